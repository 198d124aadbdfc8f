#!/usr/bin/python3
"""Issue #17's "first updated frame after any arranging gesture <= 33 ms at 512x384": runs
bench_gestures (the studio offscreen on the bundled example: move, yaw, height, duplicate, delete,
hide, material, insert of a library chair and undo, each --reps times, denoised preview off and on)
into OUT/gestures/LABEL/gestures.csv, then plots every label found there side by side (a run
before a change and one after compare in one figure): median and 90th percentile wall time from
the edit to the repainted frame per gesture, and the process's CPU time over the same span (on a
shared machine the wall time grows with the load, the CPU time much less). Prints a Markdown
table and writes docs/bench/gestures.md for LABEL.

Writes OUT/gestures/LABEL/gestures.csv, OUT/gestures/LABEL/summary.csv and OUT/gestures.png.

usage: bench_gestures.py BUILD_DIR [--out DIR] [--label current] [--reps 20] [--plot-only]
"""
import collections, csv, os, statistics, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

GESTURES = ["move", "yaw", "height", "duplicate", "delete", "hide", "material", "insert", "undo"]
GOAL_MS = 33


def quantile(v, q):
    v = sorted(v)
    return v[min(len(v) - 1, int(q * (len(v) - 1) + 0.5))] if v else float("nan")


def summary(path):
    """[{gesture, denoise, n, median_ms, p90_ms, median_cpu_ms}] of one run's CSV."""
    by = collections.defaultdict(list)
    for r in benchlib.read_csv(path):
        by[(r["gesture"], r["denoise"])].append((float(r["ms"]), float(r["cpu_ms"])))
    rows = []
    for g in GESTURES:
        for d in ("off", "on"):
            s = by.get((g, d))
            if not s:
                continue
            ms = [a for a, _ in s]
            rows.append({"gesture": g, "denoise": d, "n": len(s), "median_ms": statistics.median(ms),
                         "p90_ms": quantile(ms, 0.9), "median_cpu_ms": statistics.median(b for _, b in s)})
    return rows


def main():
    build, opt, out = benchlib.command_line(__doc__)
    root = os.path.join(out, "gestures")
    label = opt("--label", "current")
    here = os.path.join(root, label)
    if "--plot-only" not in sys.argv:
        os.makedirs(here, exist_ok=True)
        exe = os.path.join(build, "tests", "bench", "bench_gestures")
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
        subprocess.run(["nice", "-n", "10", exe, "--out", here, "--reps", opt("--reps", "20")], check=True, env=env)
    labels = sorted((d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "gestures.csv"))),
                    key=lambda d: os.path.getmtime(os.path.join(root, d, "gestures.csv")))
    data = {l: summary(os.path.join(root, l, "gestures.csv")) for l in labels}
    if label in data:
        benchlib.write_csv(os.path.join(here, "summary.csv"), data[label], table="gestures")
    print("| run | gesture | denoise | median ms | p90 ms | median CPU ms |")
    print("|---|---|---|---|---|---|")
    for l in labels:
        for r in data[l]:
            print(f"| {l} | {r['gesture']} | {r['denoise']} | {r['median_ms']:.0f} | {r['p90_ms']:.0f} | "
                  f"{r['median_cpu_ms']:.0f} |")

    with benchlib.figure(os.path.join(out, "gestures.png"), 1, 2, figsize=(15, 4.8)) as ax:
        if ax is None:
            return
        series = [(l, d) for l in labels for d in ("off", "on")]
        width = 0.8 / max(1, len(series))
        for i, (l, d) in enumerate(series):
            rows = {r["gesture"]: r for r in data[l] if r["denoise"] == d}
            xs = [k + i * width for k, g in enumerate(GESTURES) if g in rows]
            med = [rows[g]["median_ms"] for g in GESTURES if g in rows]
            p90 = [rows[g]["p90_ms"] for g in GESTURES if g in rows]
            cpu = [rows[g]["median_cpu_ms"] for g in GESTURES if g in rows]
            bars = ax[0].bar(xs, med, width, label=f"{l}, denoiser {d}")
            ax[0].plot(xs, p90, "v", color=bars.patches[0].get_facecolor() if bars.patches else None, ms=5)
            ax[1].bar(xs, cpu, width, label=f"{l}, denoiser {d}")
        for a, title in ((ax[0], "edit to repainted frame, wall ms (bar: median, v: p90)"),
                         (ax[1], "process CPU ms over the same span (median)")):
            a.axhline(GOAL_MS, color="k", ls="--", lw=1, label=f"goal {GOAL_MS} ms")
            a.set_xticks([k + 0.4 - width / 2 for k in range(len(GESTURES))], GESTURES, rotation=20)
            a.set_title(title + ", 512x384")
            a.grid(True, axis="y", alpha=0.3)
            a.legend(fontsize=7)


if __name__ == "__main__":
    main()
