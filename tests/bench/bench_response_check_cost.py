#!/usr/bin/python3
"""The response check's cost (issue #18; the camera photos of issue #16): the preparation's CPU
seconds on camera photos whose "auto" response is a fitted curve, for which the light fit's
check (PrepareOptions::checkResponseByLightFit) prepares the photo a second time with sRGB.
Builds are alternated (their order reversed every round), each run at nice -n 10:

  inlay-cli render SCENE -o X.png --spp 1 --seconds 0 --noise 0 --threads T --quiet --report R.json

From the report: the preparation's wall and CPU seconds (the sums over its stage records, the
response check's included), the response check's own (its record), the response it kept (the
check's detail); and the process's CPU seconds (user + system, the 1-sample frame included: the
measure to compare builds by, since a build before resp17c recorded, when sRGB was kept, the
sRGB preparation's stages and then the same again as the check, and never the curve's).

Photos are camera variants named ROOM_sK (../shared/tools/camera_variants.py, room ROOM of
../shared/scenes-train, seed K) or ROOM_plain, with harness.py's assisted scene, or York photos
PNNNNNNN (../shared/york, 640 x 480, the photo alone: camera estimated; always at their own size). --mp M (0: the
room's own size, 512 x 384) makes the variant at about M megapixels: the room's linear render
resized (bicubic) and put through the same random camera (camera_variants.py's draw_camera and
encode; its noise per pixel k times the camera's, k the linear scale: the same sensor area
in k^2 times as many pixels, so the same noise at the room's own size), the scene's pixel keys
scaled.

usage: bench_response_check_cost.py --builds LABEL=BUILD_DIR,LABEL=BUILD_DIR --photos t02_s2,t04_s1,...
           [--mp 0,12] [--rounds 3] [--threads 2] [--out DIR] [--append] [--plot-only]
           [--reference LABEL]

A build may carry extra flags after its directory, each after a "+": LABEL=BUILD_DIR+--no-response-check
(resp20: the curve kept without the check, to measure what the check adds). --reference LABEL:
the summary gives each build's median process wall and CPU seconds minus LABEL's on the same
photo (added_wall_s, added_cpu_s): what the check adds to the run, whatever its stage records
say (resp20 prepares the check's two candidates side by side, so the records overlap), and
OUT/response_check_added.png draws them per photo and build.

Writes OUT/response_check_cost.csv (one row per build, round, size and photo; --append keeps the
rows already there), OUT/response_check_cost_summary.csv (medians per build, size and photo, and
each build's ratio to the first) and OUT/response_check_cost.png (median process CPU per
photo and build), OUT/response_check_cost_size.png (the response stage plus the check, median
CPU seconds, against megapixels: the issue's budget is 1 s at 640 x 480, --mp 0.3072). Rows
also give the response stage's CPU seconds and whether the check's copies decided
(ResponseQuickCheck; "full": the full check ran). Variants and scenes are cached under
OUT/variants.
"""
import csv, importlib.util, json, math, os, resource, statistics, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"


def tools_dir():
    return os.path.join(benchlib.shared_dir(), "tools")


def camera_variants():
    spec = importlib.util.spec_from_file_location("camera_variants", os.path.join(tools_dir(), "camera_variants.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def native_variant(name, folder):
    """The variant folder and assisted scene of photo `name` at the room's own size."""
    room, kind = name.split("_", 1)
    vdir, scene = os.path.join(folder, name), os.path.join(folder, name + ".json")
    if not os.path.exists(scene):
        extra = ["--plain"] if kind == "plain" else ["--seed", kind[1:]]
        subprocess.run([PY, os.path.join(tools_dir(), "camera_variants.py"),
                        os.path.join(benchlib.shared_dir(), "scenes-train", room), vdir] + extra,
                       check=True, capture_output=True)
        subprocess.run([PY, os.path.join(tools_dir(), "harness.py"), "scene", vdir, scene, "--seconds", "15"],
                       check=True, capture_output=True)
    return scene


def york_scene(name, folder, york=None):
    """The scene of York photo `name` (PNNNNNNN, 640 x 480): the photo alone, camera estimated."""
    path = os.path.join(folder, name + ".json")
    if not os.path.exists(path):
        photo = os.path.join(york or os.path.join(benchlib.shared_dir(), "york"), name + ".jpg")
        json.dump({"format": "inlay-scene", "version": 1, "photo": photo}, open(path, "w"))
    return path


def scene_of(name, mp, folder):
    """A York photo at its own size, or a camera variant at `mp` megapixels (0: the room's size)."""
    if name.startswith("P"):
        return york_scene(name, folder)
    return resized_variant(name, mp, folder) if mp > 0 else native_variant(name, folder)


def resized_variant(name, mp, folder):
    """The scene of photo `name` (a camera variant, not plain) at about `mp` megapixels."""
    import cv2
    import numpy as np
    scene_path = native_variant(name, folder)
    out = os.path.join(folder, "%s_%gmp.json" % (name, mp))
    if os.path.exists(out):
        return out
    cv = camera_variants()
    room, kind = name.split("_", 1)
    room_dir = os.path.join(benchlib.shared_dir(), "scenes-train", room)
    linear = cv.read_exr(os.path.join(room_dir, "photo_linear.exr"))
    h0, w0 = linear.shape[:2]
    k = math.sqrt(mp * 1e6 / (w0 * h0))
    w, h = int(round(w0 * k)), int(round(h0 * k))
    linear = np.maximum(cv2.resize(linear, (w, h), interpolation=cv2.INTER_CUBIC), 0)
    rng = np.random.default_rng(int(kind[1:]))  # the camera of camera_variants.py --seed K
    cam = cv.draw_camera(rng)
    cam["noise"] *= w / w0  # the same sensor in smaller pixels: the noise per pixel grows with k
    yy, xx = np.mgrid[0:h, 0:w]
    r2 = ((xx + 0.5 - w / 2) ** 2 + (yy + 0.5 - h / 2) ** 2) / ((w / 2) ** 2 + (h / 2) ** 2)
    scale = json.load(open(os.path.join(room_dir, "truth.json")))["exposure"]["scale"]
    pixels = cv.encode(linear, scale, cam, rng.standard_normal(linear.shape), 1.0 - cam["vignetting"] * r2)
    bgr = np.ascontiguousarray(pixels[:, :, ::-1])
    if cam["jpeg_quality"]:
        bgr = cv2.imdecode(cv2.imencode(".jpg", bgr, [cv2.IMWRITE_JPEG_QUALITY, cam["jpeg_quality"]])[1],
                           cv2.IMREAD_COLOR)
    photo = os.path.join(folder, "%s_%gmp.png" % (name, mp))
    cv2.imwrite(photo, bgr)
    scene = json.load(open(scene_path))
    scene["photo"] = photo
    benchlib.scale_scene_pixels(scene, w / w0)
    json.dump(scene, open(out, "w"), indent=1)
    return out


def run_once(cli, scene, threads, work, extra=()):
    """The report's figures for one render of `scene` (`extra`: more flags)."""
    report = os.path.join(work, "report.json")
    cmd = ["nice", "-n", "10", cli, "render", scene, "-o", os.path.join(work, "comp.png"), "--spp", "1",
           "--seconds", "0", "--noise", "0", "--threads", str(threads), "--quiet", "--report", report] + list(extra)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    subprocess.run(cmd, check=True)
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    stages = json.load(open(report))["stages"]
    ran = [s for s in stages if s.get("ran")]
    check = [s for s in ran if s["name"] == "response check"]
    kept = "-" if not check else ("curve" if check[0]["detail"].startswith("the curve kept") else "srgb")
    response = [s for s in ran if s["name"] == "response"]
    decided = "-" if not check else ("copies" if " beyond " in check[0]["detail"] else "full")
    return {"prepare_s": round(sum(s["seconds"] for s in ran), 3),
            "prepare_cpu_s": round(sum(s["cpu_seconds"] for s in ran), 3),
            "check_cpu_s": round(check[0]["cpu_seconds"], 3) if check else 0.0,
            "check_s": round(check[0]["seconds"], 3) if check else 0.0,
            "response_cpu_s": round(response[0]["cpu_seconds"], 3) if response else 0.0,
            "decided_by": decided,
            "kept": kept, "process_cpu_s": round(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 3),
            "wall_s": round(wall, 3), "load": round(os.getloadavg()[0], 2)}


def added_by_the_check(out, reference):
    """Each summary row's process wall and CPU medians minus the reference build's (same size and
    photo): added_wall_s, added_cpu_s."""
    for s in out:
        ref = [r for r in out if r["build"] == reference and (r["mp"], r["photo"]) == (s["mp"], s["photo"])]
        if ref:
            s["added_wall_s"] = round(s["wall_s"] - ref[0]["wall_s"], 3)
            s["added_cpu_s"] = round(s["process_cpu_s"] - ref[0]["process_cpu_s"], 3)


def plot_added(summ, reference, path):
    """What the check adds (process medians minus the reference build's), wall and CPU, per photo."""
    labels = []
    for s in summ:
        if s["build"] not in labels and s["build"] != reference and "added_wall_s" in s:
            labels.append(s["build"])
    cases = []
    for s in summ:
        if (s["mp"], s["photo"]) not in cases and "added_wall_s" in s:
            cases.append((s["mp"], s["photo"]))
    with benchlib.figure(path, 1, 2, figsize=(max(10, 1.6 * len(cases) + 2), 4)) as ax:
        if ax is None:
            return
        width = 0.8 / max(1, len(labels))
        for a, key, title in ((ax[0], "added_wall_s", "wall s"), (ax[1], "added_cpu_s", "CPU s")):
            for i, label in enumerate(labels):
                xs, ys = [], []
                for j, case in enumerate(cases):
                    sel = [x for x in summ if x["build"] == label and (x["mp"], x["photo"]) == case]
                    if sel and "added_wall_s" in sel[0]:
                        xs.append(j + i * width)
                        ys.append(float(sel[0][key]))
                a.bar(xs, ys, width, label=label)
            a.axhline(1.0, color="grey", lw=0.8)
            a.set_xticks([j + 0.4 - width / 2 for j in range(len(cases))],
                         ["%s\n%s" % (p, "own size" if float(m) == 0 else m + " MP") for m, p in cases], fontsize=7)
            a.set_ylabel("added by the check, %s (median run - %s)" % (title, reference))
            a.set_title("what the response check adds: " + title)
            a.legend(fontsize=7)


def summary(rows):
    out, first = [], None
    keys = []
    for r in rows:
        if (r["mp"], r["photo"]) not in keys:
            keys.append((r["mp"], r["photo"]))
    labels = []
    for r in rows:
        if r["build"] not in labels:
            labels.append(r["build"])
    for mp, photo in keys:
        base = None
        for label in labels:
            sel = [r for r in rows if r["build"] == label and r["mp"] == mp and r["photo"] == photo]
            if not sel:
                continue
            for r in sel:  # rows of CSVs written before the response stage was recorded: 0
                r["response_plus_check_cpu_s"] = float(r.get("response_cpu_s") or 0) + float(r["check_cpu_s"])
            med = {k: statistics.median(float(r[k]) for r in sel)
                   for k in ("prepare_s", "prepare_cpu_s", "check_cpu_s", "response_plus_check_cpu_s",
                             "process_cpu_s", "wall_s")}
            base = base or med
            out.append({"build": label, "mp": mp, "photo": photo, "runs": len(sel), "kept": sel[0]["kept"],
                        "decided_by": sel[0].get("decided_by", ""),
                        **{k: round(v, 3) for k, v in med.items()},
                        "prepare_cpu_ratio": round(med["prepare_cpu_s"] / base["prepare_cpu_s"], 3),
                        "process_cpu_ratio": round(med["process_cpu_s"] / base["process_cpu_s"], 3)})
    return out


def plot(summ, path):
    labels = []
    for s in summ:
        if s["build"] not in labels:
            labels.append(s["build"])
    cases = []
    for s in summ:
        if (s["mp"], s["photo"]) not in cases:
            cases.append((s["mp"], s["photo"]))
    panels = (("process_cpu_s", "process CPU s (median)", "the preparation and a 1-sample frame"),
              ("check_cpu_s", "response check CPU s (median)", "the check's own record"))
    with benchlib.figure(path, 1, 2, figsize=(max(10, 2.4 * len(cases) + 2), 4)) as ax:
        if ax is None:
            return
        width = 0.8 / max(1, len(labels))
        for a, (key, ylabel, title) in zip(ax, panels):
            for i, label in enumerate(labels):
                xs, ys = [], []
                for j, case in enumerate(cases):
                    s = [x for x in summ if x["build"] == label and (x["mp"], x["photo"]) == case]
                    if s:
                        xs.append(j + i * width)
                        ys.append(float(s[0][key]))
                a.bar(xs, ys, width, label=label)
            a.set_xticks([j + 0.4 - width / 2 for j in range(len(cases))],
                         ["%s\n%s" % (p, "own size" if float(m) == 0 else m + " MP") for m, p in cases], fontsize=7)
            a.set_ylabel(ylabel)
            a.set_title(title)
            a.legend()


def plot_against_size(summ, path):
    """The response stage plus the check, median CPU seconds, against the photo's megapixels
    (0: the room's own size, 0.2 MP), one line per build and photo."""
    with benchlib.figure(path, 1, 1, figsize=(6.5, 4.2)) as ax:
        if ax is None:
            return
        series = {}
        for s in summ:
            if s["kept"] == "-":
                continue
            mp = float(s["mp"]) or 0.197
            series.setdefault((s["build"], s["photo"]), []).append((mp, float(s["response_plus_check_cpu_s"])))
        styles = {}
        for (build, photo), pts in sorted(series.items()):
            pts.sort()
            style = styles.setdefault(build, "-o" if not styles else "--s")
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, label="%s %s" % (build, photo))
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("photo megapixels")
        ax.set_ylabel("response + response check, CPU s (median)")
        ax.set_title("the response fit and its check against photo size")
        ax.legend(fontsize=6)


def main():
    a = benchlib.args(__doc__, 0)
    opt = lambda key, default: benchlib.option(a, key, default)
    out = os.path.abspath(opt("--out", os.path.join(HERE, "out")))
    os.makedirs(out, exist_ok=True)
    csv_path = os.path.join(out, "response_check_cost.csv")
    rows = benchlib.read_csv(csv_path) if ("--append" in a or "--plot-only" in a) and os.path.exists(csv_path) else []
    if "--plot-only" not in a:
        builds = [b.split("=", 1) for b in opt("--builds", "").split(",") if b]
        builds = [(label, spec.split("+")[0], spec.split("+")[1:]) for label, spec in builds]
        if not builds or not opt("--photos", ""):
            sys.stderr.write(__doc__.strip() + "\n")
            return 2
        folder = os.path.join(out, "variants")
        os.makedirs(folder, exist_ok=True)
        scenes = []
        for mp in [float(m) for m in opt("--mp", "0").split(",")]:
            for name in opt("--photos", "").split(","):
                scenes.append((mp, name, scene_of(name, mp, folder)))
        start = 1 + max([int(r["round"]) for r in rows] or [0])
        for rnd in range(start, start + int(opt("--rounds", "3"))):
            order = builds if rnd % 2 else builds[::-1]
            for mp, name, scene in scenes:
                for label, build, extra in order:
                    r = run_once(os.path.join(os.path.abspath(build), "app", "inlay-cli"), scene,
                                 opt("--threads", "2"), out, extra)
                    row = {"build": label, "round": rnd, "mp": "%g" % mp, "photo": name, **r}
                    print(json.dumps(row), flush=True)
                    rows.append(row)
                    benchlib.write_csv(csv_path, rows)
    summ = summary(rows)
    reference = opt("--reference", "")
    if reference:
        added_by_the_check(summ, reference)
        plot_added(summ, reference, os.path.join(out, "response_check_added.png"))
    benchlib.write_csv(os.path.join(out, "response_check_cost_summary.csv"), summ)
    plot(summ, os.path.join(out, "response_check_cost.png"))
    plot_against_size(summ, os.path.join(out, "response_check_cost_size.png"))
    for s in summ:
        print(json.dumps(s))
    return 0


if __name__ == "__main__":
    sys.exit(main())
