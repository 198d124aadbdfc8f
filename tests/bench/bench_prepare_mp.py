"""The preparation's stages at 0.3, 3 and 12 MP: a scene's photo resized to each size (bicubic,
written as a JPEG of quality 95 like a phone's; every pixel key of the scene file scaled), then
`inlay-cli render --spp 1 --noise 0 --report --progress-csv` --repeats times at nice -n 10:
each stage's seconds (the report), the preparation's sum, the first frame (the first row of
the progress CSV: one sample in every pixel, at the photo's size) and the run's wall time.

  /usr/bin/python3 tests/bench/bench_prepare_mp.py build [--scene FILE] [--mp 0.3,3,12]
      [--repeats 3] [--threads 2] [--working-mp 0.5] [--initial-lights] [--label NAME] [--out DIR]
      [--append] [--plot-only]

--initial-lights passes inlay-cli's (the refinement and the refit skipped: the working copy's
lighting, which the photo's size does not change, once instead of twice; halves a run).
--scene defaults to the bundled example (resources/example/scene.json: two outlined lights,
a sphere). --label names the run (e.g. "before", "after"): runs of other labels already in
the CSV are kept, so one figure and one table compare them. Writes bench_prepare_mp.csv (one
row per label, size, run and stage), bench_prepare_mp_summary.csv (medians per label, size and
stage, wall and CPU seconds (all threads); the table docs/bench/prepare_mp.md) and bench_prepare_mp.png under DIR (default
tests/bench/out). Resized photos live in a temporary folder and are never kept.
The lighting stage and its refit also get a row per step of theirs (the report's "steps":
"lighting: gather", "lighting refit: light fit", ...; not in the preparation's sum).
--append keeps the label's earlier runs (numbered on): two builds' runs alternate on a loaded
machine by calling each in turn with --repeats 1 --append, into one DIR."""
import csv, json, math, os, statistics, subprocess, sys, tempfile, time

import benchlib

HERE = os.path.dirname(os.path.abspath(__file__))
def resized_scene(scene_path, mp, folder):
    """The scene file of its photo resized to about `mp` megapixels (aspect kept), pixel keys scaled."""
    import cv2
    scene = json.load(open(scene_path))
    photo_path = os.path.join(os.path.dirname(os.path.abspath(scene_path)), scene["photo"])
    photo = cv2.imread(photo_path, cv2.IMREAD_COLOR)
    h0, w0 = photo.shape[:2]
    k = math.sqrt(mp * 1e6 / (w0 * h0))
    w, h = int(round(w0 * k)), int(round(h0 * k))
    k = w / w0
    big = cv2.resize(photo, (w, h), interpolation=cv2.INTER_CUBIC)
    path = os.path.join(folder, "photo_%gmp.jpg" % mp)
    cv2.imwrite(path, big, [cv2.IMWRITE_JPEG_QUALITY, 95])
    scene["photo"] = path
    benchlib.scale_scene_pixels(scene, k)
    out = os.path.join(folder, "scene_%gmp.json" % mp)
    json.dump(scene, open(out, "w"), indent=1)
    return out, w, h


def run_once(cli, scene, opt, work):
    """One preparation and first frame: [(stage, seconds, CPU seconds)], the first frame's seconds,
    wall seconds."""
    report, progress = os.path.join(work, "report.json"), os.path.join(work, "progress.csv")
    cmd = ["nice", "-n", "10", cli, "render", scene, "-o", os.path.join(work, "comp.png"), "--spp", "1",
           "--noise", "0", "--quiet", "--threads", opt("--threads", "2"), "--report", report,
           "--progress-csv", progress, "--working-mp", opt("--working-mp", "0.5")]
    if "--initial-lights" in sys.argv:  # no refine and refit (lighting-bound, on the working copy)
        cmd.append("--initial-lights")
    t0 = time.time()
    subprocess.run(cmd, check=True)
    wall = time.time() - t0
    ran = [s for s in json.load(open(report))["stages"] if s.get("ran")]
    stages = [(s["name"], s["seconds"], s.get("cpu_seconds", float("nan"))) for s in ran]
    steps = [("%s: %s" % (s["name"], t["name"]), t.get("seconds", float("nan")), t.get("cpu_seconds", float("nan")))
             for s in ran for t in s.get("steps", [])]
    rows = benchlib.read_csv(progress)
    first = float(rows[0]["seconds"]) if rows else float("nan")
    return stages, steps, first, wall


def measure(build, opt, out, label):
    cli = os.path.join(build, "app", "inlay-cli")
    scene = opt("--scene", os.path.join(HERE, "..", "..", "resources", "example", "scene.json"))
    path = os.path.join(out, "bench_prepare_mp.csv")
    rows = benchlib.read_csv(path) if os.path.exists(path) else []
    if "--append" not in sys.argv:
        rows = [r for r in rows if r["label"] != label]
    for mp in [float(v) for v in opt("--mp", "0.3,3,12").split(",")]:
        with tempfile.TemporaryDirectory() as work:
            sfile, w, h = resized_scene(scene, mp, work)
            done = len({r["run"] for r in rows if r["label"] == label and float(r["megapixels"]) == mp})
            for run in range(done, done + int(opt("--repeats", "3"))):
                stages, steps, first, wall = run_once(cli, sfile, opt, work)
                base = {"label": label, "megapixels": mp, "width": w, "height": h, "run": run}
                for name, s, cpu in stages + steps:
                    rows.append(dict(base, stage=name, seconds=round(s, 4), cpu_seconds=round(cpu, 4)))
                prep, prep_cpu = sum(s[1] for s in stages), sum(s[2] for s in stages)
                rows.append(dict(base, stage="prepare (sum)", seconds=round(prep, 4), cpu_seconds=round(prep_cpu, 4)))
                rows.append(dict(base, stage="first frame", seconds=round(first, 4), cpu_seconds=""))
                rows.append(dict(base, stage="wall", seconds=round(wall, 3), cpu_seconds=""))
                print(label, mp, "MP run", run, "prepare %.2f s (CPU %.2f s)" % (prep, prep_cpu),
                      "first frame %.2f s" % first, "wall %.1f s" % wall, "load %.1f" % os.getloadavg()[0],
                      flush=True)
                benchlib.write_csv(path, rows)


def summarize(out):
    """Medians per label, size and stage, as one row per (label, stage) with a column per size."""
    rows = benchlib.read_csv(os.path.join(out, "bench_prepare_mp.csv"))
    labels = list(dict.fromkeys(r["label"] for r in rows))
    mps = sorted({float(r["megapixels"]) for r in rows})
    stages = list(dict.fromkeys(r["stage"] for r in rows))
    table = []
    for label in labels:
        for stage in stages:
            row = {"label": label, "stage": stage}
            for mp in mps:
                for key, col in (("seconds", "%g MP (s)"), ("cpu_seconds", "%g MP CPU (s)")):
                    v = [float(r[key]) for r in rows if r["label"] == label and r["stage"] == stage
                         and float(r["megapixels"]) == mp and r.get(key, "") not in ("", "nan")]
                    row[col % mp] = round(statistics.median(v), 3) if v else float("nan")
            if any(not math.isnan(row["%g MP (s)" % mp]) for mp in mps):
                table.append(row)
    benchlib.write_csv(os.path.join(out, "bench_prepare_mp_summary.csv"), table, table="prepare_mp")
    return table, labels, mps


def plot(out, table, labels, mps):
    with benchlib.figure(os.path.join(out, "bench_prepare_mp.png"), 1, 2, figsize=(12, 4.5)) as ax:
        if ax is None:
            return
        for n, label in enumerate(labels):
            get = lambda stage: [next((r["%g MP (s)" % mp] for r in table
                                       if r["label"] == label and r["stage"] == stage), float("nan")) for mp in mps]
            ax[0].plot(mps, get("prepare (sum)"), "o-", color="C%d" % n, label=label + ": prepare")
            cpu = [next((r["%g MP CPU (s)" % mp] for r in table
                         if r["label"] == label and r["stage"] == "prepare (sum)"), float("nan")) for mp in mps]
            ax[0].plot(mps, cpu, "s:", color="C%d" % n, label=label + ": prepare, CPU")
            ax[0].plot(mps, get("first frame"), "x--", color="C%d" % n, label=label + ": first frame")
        ax[0].axhline(5, color="gray", linestyle=":", label="5 s target")
        ax[0].set_xscale("log")
        ax[0].set_yscale("log")
        ax[0].set_xlabel("photo megapixels")
        ax[0].set_ylabel("seconds (median)")
        ax[0].legend(fontsize=8)
        ax[0].set_title("preparation and first frame against photo size")
        big = mps[-1]
        skip = {"prepare (sum)", "wall", "first frame"}
        stages = [s for s in dict.fromkeys(r["stage"] for r in table) if s not in skip and ": " not in s]
        width = 0.8 / max(1, len(labels))
        for n, label in enumerate(labels):
            vals = [next((r["%g MP CPU (s)" % big] for r in table if r["label"] == label and r["stage"] == s), 0)
                    for s in stages]
            ax[1].barh([i + n * width for i in range(len(stages))], vals, width, color="C%d" % n, label=label)
        ax[1].set_yticks([i + 0.4 - width / 2 for i in range(len(stages))])
        ax[1].set_yticklabels(stages, fontsize=8)
        ax[1].invert_yaxis()
        ax[1].set_xscale("symlog", linthresh=0.01)
        ax[1].set_xlabel("CPU seconds at %g MP (median, all threads)" % big)
        ax[1].set_title("each stage at %g MP" % big)
        ax[1].legend(fontsize=8)


def main():
    build, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    if "--plot-only" not in sys.argv:
        measure(build, opt, out, opt("--label", "run"))
    table, labels, mps = summarize(out)
    with open(os.path.join(out, "bench_prepare_mp_summary.csv")) as f:
        print(f.read())
    plot(out, table, labels, mps)


if __name__ == "__main__":
    main()
