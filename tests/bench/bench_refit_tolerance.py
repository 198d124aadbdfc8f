#!/usr/bin/env python3
"""The refit's tolerance (PrepareOptions::keepBetterFitTolerance): the fit residual's own spread
over the preparation's seeds.

After the light refinement the pipeline fits the lighting again and keeps that refit only when
its robust log residual against the photo (LightingEstimate::fitRmsLog) is not larger than the
first estimate's by more than the tolerance. Both residuals come from Monte Carlo gathers: this
script prepares each plain room with several preparation seeds (`inlay-cli render
--prepare-seed K`, the render cut to one sample: the lights do not depend on it), reads both
residuals from the refit stage's detail (`--report`) and both light sets (`--lights-json`:
"initial" is the first estimate's, "refined" the refit's), and writes per room and seed:

- the relative difference d = refit / first - 1 of the residuals;
- each residual's spread over the seeds (relative standard deviation);
- the lights' ratio to the truth (luminance) of the first estimate and of the refit.

The tolerance is read from half A: the median over its rooms of the seed spread of d (the
noise of the difference the rule decides on), times two (a two-sigma tie).

Usage:
  bench_refit_tolerance.py CLI --out OUT [--rooms A|B|t03,...] [--seeds 4] [--reuse]
Writes OUT/refit_tolerance.csv, OUT/refit_tolerance_summary.csv and OUT/refit_tolerance.png.
"""

import json, os, re, statistics, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_generalization as gen  # noqa: E402

PY = "/usr/bin/python3"
DETAIL = re.compile(r"log residual ([0-9.]+) against (?:the first estimate's )?([0-9.]+)")
LUMA = np.array([0.2126, 0.7152, 0.0722])


def residuals(report):
    """(first estimate's, refit's) fitRmsLog from the refit stage's detail, or None."""
    for st in json.load(open(report)).get("stages", []):
        m = DETAIL.search(st.get("detail", ""))
        if not m:
            continue
        a, b = float(m.group(1)), float(m.group(2))
        # "the first estimate fits the photo better (log residual FIRST against REFIT)";
        # "the refit is kept (log residual REFIT against the first estimate's FIRST)".
        return (a, b) if "first estimate fits" in st["detail"] else (b, a)
    return None


def ratios(lights_json, truth, key):
    """Each light's radiance over the truth's (luminance), the first estimate's or the refit's."""
    L = json.load(open(lights_json))
    s = truth["exposure"]["scale"]
    return [float(np.array(o["rgb"]) @ LUMA / (np.array(t["radiance_rgb"]) * s @ LUMA))
            for o, t in zip(L[key], truth["lights"])]


def prepare(cli, scene, out, tag, seed, reuse):
    """Runs the preparation with `seed`; (report path, lights path) or None."""
    rep, lj = os.path.join(out, "%s_s%d_report.json" % (tag, seed)), os.path.join(out, "%s_s%d_lights.json" % (tag, seed))
    if not (reuse and os.path.exists(rep) and os.path.exists(lj)):
        cmd = [cli, "render", scene, "-o", os.path.join(out, "%s_s%d.png" % (tag, seed)), "--quiet", "--spp", "1",
               "--seconds", "0", "--noise", "0", "--prepare-seed", str(seed), "--report", rep, "--lights-json", lj,
               # the refit always run and taken: "refined" holds the refit's lights, "initial" the first's
               "--keep-better-fit-tolerance", "1e9", "--refit-min-move", "0"]
        if subprocess.run(cmd, capture_output=True, text=True, timeout=1800).returncode != 0:
            return None
    return rep, lj


def measure_room(cli, tools, sdir, room, out, seeds, reuse):
    """Rows (one per seed) of a plain room; [] when it has no refit (nothing refined)."""
    vdir = gen.variant(tools, os.path.join(sdir, room), os.path.join(out, "variants", room + "_plain"), "plain")
    scene = os.path.join(out, room + "_plain.json")
    if not os.path.exists(scene):
        subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene], check=True, capture_output=True)
    truth = json.load(open(os.path.join(sdir, room, "truth.json")))
    rows = []
    for seed in range(seeds):
        got = prepare(cli, scene, out, room, seed, reuse)
        res = got and residuals(got[0])
        if not res:
            continue
        first, refit = res
        row = {"room": room, "half": benchlib.half(room), "seed": seed, "first": first, "refit": refit,
               "d": round(refit / first - 1, 6)}
        for k, (a, b) in enumerate(zip(ratios(got[1], truth, "initial"), ratios(got[1], truth, "refined"))):
            row["light%d_first_ratio" % k], row["light%d_refit_ratio" % k] = round(a, 4), round(b, 4)
        rows.append(row)
        print(json.dumps(row), flush=True)
    return rows


def summarize(rows):
    """Per room: the mean and seed spread of d and of each residual."""
    out = []
    for room in sorted({r["room"] for r in rows}):
        rs = [r for r in rows if r["room"] == room]
        if len(rs) < 2:
            continue
        d = [r["d"] for r in rs]
        rel = lambda k: statistics.stdev([r[k] for r in rs]) / statistics.mean([r[k] for r in rs])
        out.append({"room": room, "half": rs[0]["half"], "seeds": len(rs), "d_mean": round(statistics.mean(d), 5),
                    "d_sd": round(statistics.stdev(d), 5), "first_rel_sd": round(rel("first"), 5),
                    "refit_rel_sd": round(rel("refit"), 5),
                    "refit_kept_at_0": sum(x <= 0 for x in d)})
    return out


def plot(rows, summary, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    rooms = [s["room"] for s in summary]
    for i, room in enumerate(rooms):
        d = [100 * r["d"] for r in rows if r["room"] == room]
        ax[0].plot([i] * len(d), d, "o", color="C0" if summary[i]["half"] == "A" else "C1")
    ax[0].axhline(0, color="grey", ls="--")
    ax[0].set_xticks(range(len(rooms)), rooms)
    ax[0].set_ylabel("refit / first residual - 1 (%)")
    ax[0].set_title("the rule's difference, one dot per seed (A blue, B orange)")
    ax[1].bar(range(len(rooms)), [100 * s["d_sd"] for s in summary],
              color=["C0" if s["half"] == "A" else "C1" for s in summary])
    ax[1].set_xticks(range(len(rooms)), rooms)
    ax[1].set_ylabel("seed spread of the difference (sd, %)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    cli = os.path.abspath(argv[1])
    opt = lambda k, d: argv[argv.index(k) + 1] if k in argv else d
    out = os.path.abspath(opt("--out", "bench_refit_tolerance_out"))
    os.makedirs(out, exist_ok=True)
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    rows = []
    for room in names:
        rows += measure_room(cli, tools, sdir, room, out, int(opt("--seeds", "4")), "--reuse" in argv)
    summary = summarize(rows)
    benchlib.write_csv(os.path.join(out, "refit_tolerance.csv"), rows)
    benchlib.write_csv(os.path.join(out, "refit_tolerance_summary.csv"), summary)
    print("\n| room | half | seeds | d mean | d sd | first rel sd | refit rel sd | refit kept at tol 0 |\n|---|---|---|---|---|---|---|---|")
    for s in summary:
        print("| %s | %s | %d | %.4f | %.4f | %.4f | %.4f | %d |" % (s["room"], s["half"], s["seeds"], s["d_mean"], s["d_sd"],
                                                              s["first_rel_sd"], s["refit_rel_sd"], s["refit_kept_at_0"]))
    for h in ("A", "B"):
        sds = [s["d_sd"] for s in summary if s["half"] == h]
        if sds:
            print("half %s: median seed spread of d %.5f -> two-sigma tolerance %.5f" % (h, statistics.median(sds),
                                                                                       2 * statistics.median(sds)))
    if summary:
        plot(rows, summary, os.path.join(out, "refit_tolerance.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
