#!/usr/bin/python3
"""Renderer benchmark on a ../shared room: runs bench_render and turns its CSVs into figures.

Writes OUT/render_<room>/{convergence,throughput,bvh}.csv (bench_render.cpp says what they hold),
OUT/render_<room>/summary.csv (per material and thread count: time to composite RMSE 0.01 in the
objects' region, correlated and independent, and the equal-time error ratio independent /
correlated at the correlated run's last time) and OUT/render_<room>/convergence.png (RMSE
against seconds, log-log); prints Markdown tables.

Also OUT/render_<room>/throughput.png: rays per second per thread by type (camera, bounce, shadow,
each over the thread time spent tracing it), 1 and 2 threads.

usage: bench_render.py BUILD_DIR [--out DIR] [--room d1] [--size 96x72] [--ref-spp 256] [--max-spp 64]
                       [--parts bvh,throughput,convergence]
"""
import csv, math, os, subprocess, sys
from collections import defaultdict
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.environ.get("INLAY_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))
PY = "/usr/bin/python3"
TARGET = 0.01


def loglog_at(points, x, key_x, key_y):
    """y at x by log-log interpolation of (x, y) points sorted by x; extrapolates the last two."""
    pts = [(math.log(p[key_x]), math.log(p[key_y])) for p in points if p[key_x] > 0 and p[key_y] > 0]
    if len(pts) < 2:
        return float("nan")
    lx = math.log(x)
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if x0 <= lx <= x1:
            return math.exp(y0 + (y1 - y0) * (lx - x0) / (x1 - x0))
    (x0, y0), (x1, y1) = (pts[0], pts[1]) if lx < pts[0][0] else (pts[-2], pts[-1])
    return math.exp(y1 + (y1 - y0) / (x1 - x0) * (lx - x1))


def time_to(points, target):
    """Seconds at which RMSE first reaches target (log-log interpolated); extrapolated beyond the
    last point with the ideal Monte Carlo slope -1/2 and marked '>'."""
    for a, b in zip(points, points[1:]):
        if a["rmse"] > target >= b["rmse"]:
            la, lb = math.log(a["rmse"]), math.log(b["rmse"])
            t = (math.log(target) - la) / (lb - la)
            return math.exp(math.log(a["seconds"]) + t * (math.log(b["seconds"]) - math.log(a["seconds"]))), ""
    if points and points[0]["rmse"] <= target:
        return points[0]["seconds"], "<="
    last = points[-1]
    return last["seconds"] * (last["rmse"] / target) ** 2, "~"


def main():
    build, opt, out = benchlib.command_line(__doc__)
    room = opt("--room", "d1")
    out = os.path.join(out, "render_" + room)
    w, h = opt("--size", "96x72").split("x")
    if not os.path.isdir(os.path.join(SHARED, "scenes")):
        print("skipped: ../shared/scenes not present")
        return 77
    os.makedirs(out, exist_ok=True)
    dirs = {d.split("_")[0]: d for d in os.listdir(os.path.join(SHARED, "scenes"))}
    scene = os.path.join(out, "scene.json")
    subprocess.run([PY, os.path.join(SHARED, "tools", "harness.py"), "scene", os.path.join(SHARED, "scenes", dirs[room]),
                    scene, "--seconds", "30"], check=True)
    parts = opt("--parts", "bvh,throughput,convergence,session")
    subprocess.run([os.path.join(build, "tests", "bench", "bench_render"), scene, out, w, h, opt("--ref-spp", "256"),
                    opt("--max-spp", "64"), parts], check=True)
    if "throughput" in parts:
        report_throughput(out)
    if "bvh" in parts:
        report_bvh(out)
    if "session" in parts:
        report_session(out)
    if "convergence" in parts:
        report_convergence(out, room)
    return 0


def report_throughput(out):
    rows = list(csv.DictReader(open(os.path.join(out, "throughput.csv"))))
    print("\n| threads | max depth | camera M rays/s/thread | bounce | shadow | all (wall) | rays camera / bounce / shadow | timing overhead |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        m = lambda k: float(r[k]) / 1e6
        print("| %s | %s | %.2f | %.2f | %.2f | %.2f | %s / %s / %s | %.2fx |" % (
            r["threads"], r["max_depth"], m("camera_per_s_per_thread"), m("bounce_per_s_per_thread"),
            m("shadow_per_s_per_thread"), m("rays_per_s_per_thread"), r["camera_rays"], r["bounce_rays"],
            r["shadow_rays"], float(r["timing_overhead"])))
    with benchlib.figure(os.path.join(out, "throughput.png"), figsize=(5, 3.5)) as ax:
        if ax is None:
            return
        full = [r for r in rows if r["max_depth"] != "0"]
        kinds = ["camera", "bounce", "shadow"]
        for k, r in enumerate(full):
            ax.bar([i + 0.38 * k for i in range(3)], [float(r[c + "_per_s_per_thread"]) / 1e6 for c in kinds], 0.36,
                   label="%s thread%s" % (r["threads"], "s" if r["threads"] != "1" else ""))
        ax.set_xticks([i + 0.19 for i in range(3)])
        ax.set_xticklabels(kinds)
        ax.set_ylabel("M rays / s / thread")
        ax.legend(fontsize=8)


def report_session(out):
    runs = defaultdict(list)
    for r in csv.DictReader(open(os.path.join(out, "session.csv"))):
        runs[int(r["start_divider"])].append(r)
    print("\n| frame | start divider | first frame after a move, median ms | min / max ms | divider | baseline 1 spp ms | median ratio |")
    print("|---|---|---|---|---|---|---|")
    for d, rs in sorted(runs.items()):
        ms = sorted(float(r["first_frame_ms"]) for r in rs)
        ratio = sorted(float(r["ratio_to_baseline"]) for r in rs)
        print("| %s | %d | %.1f | %.1f / %.1f | %s | %.1f | %.3f |" % (rs[0]["frame"], d, ms[len(ms) // 2], ms[0], ms[-1],
              rs[0]["first_frame_divider"], float(rs[0]["baseline_1spp_ms"]), ratio[len(ratio) // 2]))
    with benchlib.figure(os.path.join(out, "session.png"), figsize=(5, 3.5)) as ax:
        if ax is None:
            return
        for d, rs in sorted(runs.items()):
            ax.plot([int(r["edit"]) for r in rs], [float(r["first_frame_ms"]) for r in rs], "o-", label="start divider %d" % d)
        ax.axhline(50, color="gray", lw=0.7)
        ax.set_xlabel("move")
        ax.set_ylabel("ms to the first frame")
        ax.legend(fontsize=8)


def report_bvh(out):
    print("\n| triangles | BVH build s | instance move s (median) | tracer RSS MB | mesh MB |")
    print("|---|---|---|---|---|")
    for r in csv.DictReader(open(os.path.join(out, "bvh.csv"))):
        print("| %s | %.3f | %.2e | %.1f | %.1f |" % (r["triangles"], float(r["build_s"]), float(r["move_s"]),
                                                   float(r["tracer_rss_mb"]), float(r["mesh_mb"])))


def report_convergence(out, room):
    runs = defaultdict(list)
    for r in csv.DictReader(open(os.path.join(out, "convergence.csv"))):
        for k in ("seconds", "rmse"):
            r[k] = float(r[k])
        runs[(r["material"], int(r["threads"]), r["mode"])].append(r)
    materials = sorted({k[0] for k in runs}, key=lambda m: ["diffuse", "glossy", "mirror", "glass", "glowing"].index(m))
    rows = []
    for m in materials:
        for th in (1, 2):
            c, i = runs[(m, th, "correlated")], runs[(m, th, "independent")]
            tc, fc = time_to(c, TARGET)
            ti, fi = time_to(i, TARGET)
            t_end = c[-1]["seconds"]
            ratio = loglog_at(i, t_end, "seconds", "rmse") / c[-1]["rmse"]
            rows.append({"material": m, "threads": th, "correlated_s_to_0.01": "%s%.3f" % (fc, tc),
                         "independent_s_to_0.01": "%s%.3f" % (fi, ti), "speedup": ti / tc,
                         "equal_time_error_ratio": ratio, "final_spp": c[-1]["spp"],
                         "correlated_final_rmse": c[-1]["rmse"], "region_px": c[-1]["region_px"]})
    benchlib.write_csv(os.path.join(out, "summary.csv"), rows, table=os.path.basename(out.rstrip("/")))
    print("| material | threads | s to RMSE 0.01, correlated | independent | speed-up | equal-time error ratio |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %d | %s | %s | %.1fx | %.2f |" % (r["material"], r["threads"], r["correlated_s_to_0.01"],
                                                     r["independent_s_to_0.01"], r["speedup"], r["equal_time_error_ratio"]))
    with benchlib.figure(os.path.join(out, "convergence.png"), 1, len(materials), figsize=(4 * len(materials), 3.5),
                         squeeze=False) as axes:
        if axes is None:
            return
        for ax, m in zip(axes[0], materials):
            for (mm, th, mode), pts in sorted(runs.items()):
                if mm != m:
                    continue
                ax.loglog([p["seconds"] for p in pts], [p["rmse"] for p in pts], "o-" if mode == "correlated" else "s--",
                          label="%s, %d thread%s" % (mode, th, "s" if th > 1 else ""), ms=3)
            ax.axhline(TARGET, color="gray", lw=0.7)
            ax.set_title("%s (%s)" % (m, room))
            ax.set_xlabel("render seconds")
        axes[0][0].set_ylabel("composite RMSE, objects' region")
        axes[0][0].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
