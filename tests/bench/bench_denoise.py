#!/usr/bin/python3
"""The denoiser's benchmark: runs bench_denoise on a scene (default: the bundled example) and
turns its CSVs into a summary and a figure.

Times are CPU seconds per thread (process CPU time over the thread count: the wall time on idle
cores), so a loaded machine does not inflate them; convergence.csv keeps the wall time too.
Writes OUT/denoise/{convergence,timing}.csv (bench_denoise.cpp says what they hold),
OUT/denoise/summary.csv (per material and mode, raw or denoised: seconds to object RMSE 0.01,
to surroundings RMSE 0.01 and 0.005; '~' marks a time extrapolated beyond the last frame with the
Monte Carlo slope -1/2, '<=' one reached at the first frame) and OUT/denoise/convergence.png
(RMSE against seconds, log-log, object and surroundings, raw and denoised, per material);
prints Markdown tables.

usage: bench_denoise.py BUILD_DIR [--out DIR] [--scene SCENE.json] [--size 512x384]
                        [--ref-spp 512] [--max-spp 64] [--threads 2] [--materials diffuse,glass]
"""
import csv, os, subprocess, sys
from collections import defaultdict
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from bench_render import time_to  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
MATERIALS = ["diffuse", "glossy", "mirror", "glass", "glowing"]
THREADS = ["2"]


def main():
    build, opt, out = benchlib.command_line(__doc__)
    scene = os.path.abspath(opt("--scene", os.path.join(HERE, "..", "..", "resources", "example", "scene.json")))
    out = os.path.join(out, "denoise")
    os.makedirs(out, exist_ok=True)
    w, h = opt("--size", "512x384").split("x")
    THREADS[0] = opt("--threads", "2")
    subprocess.run([os.path.join(build, "tests", "bench", "bench_denoise"), scene, out, w, h, opt("--ref-spp", "512"),
                    opt("--max-spp", "64"), opt("--threads", "2"), opt("--materials", "")], check=True)
    report(out)
    return 0


def report(out):
    runs = defaultdict(list)
    for r in csv.DictReader(open(os.path.join(out, "convergence.csv"))):
        for k in ("seconds", "cpu_seconds_per_thread", "object_rmse", "surroundings_rmse"):
            r[k] = float(r[k])
        r["wall_seconds"], r["seconds"] = r["seconds"], r["cpu_seconds_per_thread"]  # load-independent time
        runs[(r["material"], r["mode"])].append(r)
    materials = [m for m in MATERIALS if (m, "raw") in runs]
    rows = []
    for m in materials:
        for mode in ("raw", "denoised", "opencv_guided"):
            pts = runs[(m, mode)]
            if not pts:
                continue
            row = {"material": m, "mode": mode}
            for key, target in (("object_rmse", 0.01), ("surroundings_rmse", 0.01), ("surroundings_rmse", 0.005)):
                t, flag = time_to([{"seconds": p["seconds"], "rmse": p[key]} for p in pts], target)
                row["s_to_%s_%g" % (key.split("_")[0], target)] = "%s%.2f" % (flag, t)
            row["object_rmse_at_1s"] = at_time(pts, 1.0, "object_rmse")
            row["surroundings_rmse_at_1s"] = at_time(pts, 1.0, "surroundings_rmse")
            rows.append(row)
    benchlib.write_csv(os.path.join(out, "summary.csv"), rows, table="denoise")
    print("| material | mode | s to object 0.01 | s to surroundings 0.01 | s to surroundings 0.005 | object RMSE at 1 s | surroundings at 1 s |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %s | %s | %s | %.4f | %.4f |" % (r["material"], r["mode"], r["s_to_object_0.01"],
              r["s_to_surroundings_0.01"], r["s_to_surroundings_0.005"], r["object_rmse_at_1s"],
              r["surroundings_rmse_at_1s"]))
    print("\n| material | size | threads | camera-ray guides ms (no longer used) | guides from the render, ms per frame | filter ms (median of 7), wall | CPU per thread | filter / baseline | reference's own error, object / surroundings |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in csv.DictReader(open(os.path.join(out, "timing.csv"))):
        print("| %s | %sx%s | %s | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f / %.4f |" % (r["material"], r["width"], r["height"], r["threads"],
              float(r["ray_guides_ms"]), float(r["buffer_guides_ms"]), float(r["filter_ms"]), float(r["filter_cpu_ms_per_thread"]),
              float(r["filter_ms"]) / max(1e-9, float(r["baseline_ms"])), float(r["reference_object_error"]),
              float(r["reference_surroundings_error"])))
    plot(out, runs, materials)


def at_time(pts, t, key):
    """RMSE of the last frame at or before t seconds (the first frame's when none is)."""
    before = [p for p in pts if p["seconds"] <= t]
    return (before[-1] if before else pts[0])[key]


def plot(out, runs, materials):
    with benchlib.figure(os.path.join(out, "convergence.png"), 1, len(materials), figsize=(3.6 * len(materials), 3.4),
                         squeeze=False) as axes:
        if axes is None:
            return
        for ax, m in zip(axes[0], materials):
            for mode, style in (("raw", "--"), ("denoised", "-"), ("opencv_guided", ":")):
                pts = runs[(m, mode)]
                if not pts:
                    continue
                for key, colour in (("object_rmse", "C0"), ("surroundings_rmse", "C1")):
                    ax.loglog([p["seconds"] for p in pts], [p[key] for p in pts], style, color=colour, marker="o", ms=2.5,
                              label="%s, %s" % (key.split("_")[0], mode))
            ax.axhline(0.01, color="gray", lw=0.7)
            ax.axhline(0.005, color="gray", lw=0.5, ls=":")
            ax.set_title(m)
            ax.set_xlabel("render seconds (CPU per thread, %s threads)" % THREADS[0])
        axes[0][0].set_ylabel("composite RMSE vs converged reference")
        axes[0][0].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
