#!/usr/bin/python3
"""The decomposition's default solver before and after issue #16: objective gap and albedo error
against CPU time, on the bundled example and the rooms.

For each scene, after one preparation per command (`inlay-cli decompose SCENE --solver S
--iterations N --progress-csv F`: the solver re-run from the lighting's start, its CPU seconds
printed by the CLI):
  old        BASELINE --solver scalar --iterations 30 (the default before: one scalar step, cap 30)
  new        CLI --solver default (DecomposeOptions' defaults: diagonal steps, coarse start, the
             pixels outside the data terms held, stopped at gapTolerance)
  old_min    BASELINE --solver diagonal --iterations CAP: the old objective's minimum (no pixel
             held; the baseline's lighting gives its own start)
  new_min    CLI --solver diagonal+hold --iterations CAP: the new objective's minimum
Each run's albedo (its room pixels; the lighting's own elsewhere) is scored by
../shared/tools/score_albedo.py against the room's true reflectance (not for the example). The
objective gap is per pixel and channel (the unit of gapTolerance) to the lowest objective any run
of that objective reached. The history's times are wall seconds; CPU seconds at each sample are
the run's CPU seconds times its share of the run's wall time.

BASELINE defaults to CLI (then "old" is the old solver on this build's kernels and start); for
the product before issue #16 give that build with the CPU print around its re-run ("re-run: X s
of CPU" or "XCPU X"; docs/benchmarks.md says how it was built), else its CPU is NaN.

Writes OUT/decompose_default.csv (scene, run, cpu_seconds, iterations, converged, mae, gap per
value), OUT/decompose_default_history.csv (scene, run, cpu_seconds, iteration, objective, gap) and
OUT/decompose_default.png (objective gap per value against CPU seconds; albedo MAE against CPU
seconds, old and new); prints a Markdown table.

usage: bench_decompose_default.py INLAY_CLI [--baseline OLD_CLI] [--scenes example,t01,...]
                                  [--cap 1000] [--out DIR]
"""
import csv, json, os, re, subprocess, sys, tempfile
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from bench_decompose_convergence import scene_file  # noqa: E402

RUNS = ("old", "new", "old_min", "new_min")


def run(cli, scene, solver, cap, tmp):
    hist, albedo = os.path.join(tmp, "history.csv"), os.path.join(tmp, "albedo.exr")
    cmd = [cli, "decompose", scene, "--albedo", albedo, "--solver", solver, "--progress-csv", hist]
    if cap:
        cmd += ["--iterations", str(cap)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("failed: %s\n%s" % (" ".join(cmd), p.stderr))
    cpu = re.search(r"(?:re-run: |XCPU )([\d.]+)", p.stderr)
    report = [l for l in p.stderr.splitlines() if "decomposition" in l and "re-run" not in l]
    with open(hist) as f:
        h = list(csv.DictReader(f))
    return {"cpu": float(cpu.group(1)) if cpu else float("nan"), "history": h,
            "report": report[-1] if report else "", "albedo": albedo}


def score(room_dir, albedo):
    if room_dir is None:
        return float("nan")
    p = subprocess.run(["/usr/bin/python3", os.path.join(benchlib.shared_dir(), "tools",
                                                         "score_albedo.py"), room_dir, albedo],
                       capture_output=True, text=True, check=True)
    return json.loads(p.stdout)["mae"]


def room_dir(name):
    if name == "example":
        return None
    base = "scenes-train" if name.startswith("t") else "scenes"
    root = os.path.join(benchlib.shared_dir(), base)
    return os.path.join(root, [d for d in os.listdir(root) if d.startswith(name)][0])


def scene_rows(name, cli, baseline, cap, tmp):
    scene = scene_file(name, tmp)
    plan = {"old": (baseline, "scalar", 30), "new": (cli, "default", 0),
            "old_min": (baseline, "diagonal", cap), "new_min": (cli, "diagonal+hold", cap)}
    runs = {}
    for key, (exe, solver, c) in plan.items():
        runs[key] = run(exe, scene, solver, c, tmp)
        runs[key]["mae"] = score(room_dir(name), runs[key]["albedo"])
    values = None
    summary, history = [], []
    for key in RUNS:
        objective = "old" if key.startswith("old") else "new"
        best = min(float(r["objective"]) for k in RUNS if k.startswith(objective)
                   for r in runs[k]["history"])
        r = runs[key]
        wall = max(float(r["history"][-1]["seconds"]), 1e-9)
        if values is None:
            values = pixel_values(scene)
        for h in r["history"]:
            history.append({"scene": name, "run": key,
                            "cpu_seconds": r["cpu"] * float(h["seconds"]) / wall,
                            "iteration": int(h["iteration"]), "objective": float(h["objective"]),
                            "gap": (float(h["objective"]) - best) / values})
        summary.append({"scene": name, "run": key, "cpu_seconds": r["cpu"],
                        "iterations": int(r["history"][-1]["iteration"]),
                        "converged": "not converged" not in r["report"], "mae": r["mae"],
                        "gap": history[-1]["gap"],
                        "report": r["report"].split("decomposition ", 1)[-1]})
        print("%s %s: %.3f s CPU, MAE %.4f, gap %.2e: %s" % (
            name, key, r["cpu"], r["mae"], history[-1]["gap"], summary[-1]["report"]), flush=True)
    return summary, history


def pixel_values(scene):
    """3 x the photo's pixels (the solver's values per objective unit of gapTolerance)."""
    import cv2
    with open(scene) as f:
        photo = json.load(f)["photo"]
    path = photo if isinstance(photo, str) else photo.get("path", photo.get("file"))
    img = cv2.imread(os.path.join(os.path.dirname(scene), path), cv2.IMREAD_UNCHANGED)
    return 3.0 * img.shape[0] * img.shape[1]


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    baseline = opt("--baseline", cli)
    cap = int(opt("--cap", "1000"))
    os.makedirs(out, exist_ok=True)
    summary, history = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in opt("--scenes", "example").split(","):
            s, h = scene_rows(name, cli, baseline, cap, tmp)
            summary += s
            history += h
            # after each scene: a long run cut short keeps what it measured
            benchlib.write_csv(os.path.join(out, "decompose_default.csv"), summary)
            benchlib.write_csv(os.path.join(out, "decompose_default_history.csv"), history)
    table(summary)
    plot(out, summary, history)
    return 0


def table(summary):
    print("| scene | old CPU s | old MAE | old gap | new CPU s | new iterations | converged | "
          "new MAE | new gap |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in dict.fromkeys(r["scene"] for r in summary):
        o, n = [[r for r in summary if r["scene"] == name and r["run"] == k][0]
                for k in ("old", "new")]
        print("| %s | %.3f | %.4f | %.1e | %.3f | %d | %s | %.4f | %.1e |" % (
            name, o["cpu_seconds"], o["mae"], o["gap"], n["cpu_seconds"], n["iterations"],
            "yes" if n["converged"] else "no", n["mae"], n["gap"]))


def plot(out, summary, history):
    with benchlib.figure(os.path.join(out, "decompose_default.png"), 1, 2,
                         figsize=(11, 4)) as ax:
        if ax is None:
            return
        scenes = list(dict.fromkeys(r["scene"] for r in summary))
        for k, s in enumerate(scenes):
            for run_name, style in (("old", "--"), ("new", "-")):
                pts = [r for r in history if r["scene"] == s and r["run"] == run_name]
                ax[0].semilogy([r["cpu_seconds"] for r in pts], [max(r["gap"], 1e-6) for r in pts],
                               style, color="C%d" % (k % 10), lw=0.8,
                               label=s if run_name == "new" else None)
        ax[0].axhline(1e-3, color="gray", lw=0.5)
        ax[0].set(xlabel="solver CPU seconds (dashed: old, 30 scalar iterations; solid: new)",
                  ylabel="objective gap per pixel and channel (tolerance 1e-3)")
        ax[0].legend(fontsize=6, ncol=2)
        for run_name, marker in (("old", "x"), ("new", "o")):
            pts = [r for r in summary if r["run"] == run_name and r["mae"] == r["mae"]]
            ax[1].scatter([r["cpu_seconds"] for r in pts], [r["mae"] for r in pts], marker=marker,
                          label=run_name)
        for s in scenes:
            pair = [r for r in summary if r["scene"] == s and r["run"] in ("old", "new")]
            if all(r["mae"] == r["mae"] for r in pair):
                ax[1].plot([r["cpu_seconds"] for r in pair], [r["mae"] for r in pair], color="gray",
                           lw=0.5)
        ax[1].set(xlabel="solver CPU seconds", ylabel="albedo MAE (room pixels)")
        ax[1].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
