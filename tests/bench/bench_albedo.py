#!/usr/bin/python3
"""Albedo against the true reflectance on every room of ../shared/scenes, ours and Retinex.

For each room the harness writes the assisted scene file; `inlay-cli decompose` writes the albedo
with --method ours and --method retinex; ../shared/tools/score_albedo.py scores it (MAE, RMSE
over room pixels, and after the best single scale) and per known surface (labels.png). Then ours
again with a series of iteration caps (--iterations) for the error against the solver's run time,
with the solver's objective and residuals (--progress-csv).

Writes OUT/albedo_scenes.csv (scene, method, mae, rmse, mae_scaled, scale, wall seconds),
OUT/albedo_surfaces.csv (scene, method, surface, pixels, mae, rmse),
OUT/albedo_error_vs_time.csv (scene, budget, solver seconds, iterations, mae, rmse),
OUT/albedo_history_<scene>.csv (the solver's history at the largest budget) and
OUT/albedo_error_vs_time.png; prints a Markdown table.

usage: bench_albedo.py INLAY_CLI [--out DIR] [--budgets 1,10,30,100,200,400]
                       [--scenes d1,d3]
"""
import csv, json, os, subprocess, sys, time
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PY = "/usr/bin/python3"


def run(cmd):
    t = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("failed (%d): %s\n%s" % (p.returncode, " ".join(cmd), p.stderr))
    return time.monotonic() - t, p.stdout, p.stderr


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    budgets = [int(x) for x in opt("--budgets", "1,10,30,100,200,400").split(",")]
    shared = os.environ.get("INLAY_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))
    sdir = os.path.join(shared, "scenes")
    tools = os.path.join(shared, "tools")
    if not os.path.isdir(sdir):
        print("skipped: no ../shared/scenes")
        return 0
    only = [s for s in opt("--scenes", "").split(",") if s]
    names = sorted(n for n in os.listdir(sdir) if os.path.isfile(os.path.join(sdir, n, "truth.json")))
    if only:
        names = [n for n in names if any(n.startswith(o) for o in only)]
    os.makedirs(out, exist_ok=True)
    score = lambda s, exr: json.loads(run([PY, os.path.join(tools, "score_albedo.py"),
                                           os.path.join(sdir, s), exr])[1])
    rows, curve, surfaces, failed = [], [], [], []
    for s in list(names):
        try:
            measure(s, cli, out, sdir, tools, budgets, score, rows, curve, surfaces)
        except SystemExit as e:
            print("FAILED %s: %s" % (s, e), flush=True)
            failed.append(s)
            names.remove(s)
    if not names:
        print("every scene failed")
        return 1
    write(out, names, rows, curve, surfaces, failed)
    return 0


SURFACES = {1: "floor", 2: "ceiling", 3: "wall_front", 4: "wall_back", 5: "wall_left",
            6: "wall_right", 7: "table"}


def per_surface(scene_dir, exr, s, m):
    """MAE and RMSE over each known surface (labels.png), visible emitters left out as the
    scorer does."""
    import numpy as np, cv2, OpenImageIO as oiio
    read = lambda p: oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:, :, :3]
    t, e = read(os.path.join(scene_dir, "albedo.exr")), read(exr)
    labels = cv2.imread(os.path.join(scene_dir, "labels.png"), cv2.IMREAD_GRAYSCALE)
    emit = read(os.path.join(scene_dir, "emission.exr")).max(2)
    out = []
    for k, name in SURFACES.items():
        msk = (labels == k) & (emit <= 1e-6) & np.isfinite(e).all(2)
        if msk.sum() < 100:
            continue
        d = e[msk] - t[msk]
        out.append(dict(scene=s, method=m, surface=name, pixels=int(msk.sum()),
                        mae=float(np.abs(d).mean()), rmse=float(np.sqrt((d * d).mean()))))
    return out


def measure(s, cli, out, sdir, tools, budgets, score, rows, curve, surfaces):
    scene = os.path.join(out, s + ".json")
    run([PY, os.path.join(tools, "harness.py"), "scene", os.path.join(sdir, s), scene])
    for m in ("ours", "retinex"):
        exr = os.path.join(out, "%s_%s.exr" % (s, m))
        secs, _, _ = run([cli, "decompose", scene, "--albedo", exr, "--method", m, "--quiet"])
        r = score(s, exr)
        surfaces.extend(per_surface(os.path.join(sdir, s), exr, s, m))
        rows.append(dict(scene=s, method=m, mae=r["mae"], rmse=r["rmse"],
                         mae_scaled=r["mae_scaled"], scale=r["scale"], seconds=secs))
        print("%s %-7s mae %.4f rmse %.4f mae_scaled %.4f scale %.3f (%.1f s)"
              % (s, m, r["mae"], r["rmse"], r["mae_scaled"], r["scale"], secs), flush=True)
    for b in budgets:
        exr = os.path.join(out, "%s_ours_%d.exr" % (s, b))
        hist = os.path.join(out, "albedo_history_%s.csv" % s)
        run([cli, "decompose", scene, "--albedo", exr, "--iterations", str(b), "--progress-csv",
             hist, "--quiet"])
        with open(hist) as f:
            h = list(csv.DictReader(f))
        r = score(s, exr)
        curve.append(dict(scene=s, budget=b, solver_seconds=float(h[-1]["seconds"]),
                          iterations=int(h[-1]["iteration"]), mae=r["mae"], rmse=r["rmse"]))
        os.remove(exr)


def write(out, names, rows, curve, surfaces, failed):
    with open(os.path.join(out, "albedo_surfaces.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(surfaces[0]))
        w.writeheader()
        w.writerows(surfaces)
    print("\n| scene | surface | pixels | ours MAE | ours RMSE | Retinex MAE | Retinex RMSE |")
    print("|---|---|---|---|---|---|---|")
    for r in surfaces:
        if r["method"] != "ours":
            continue
        t = next(x for x in surfaces if x["method"] == "retinex" and x["scene"] == r["scene"]
                 and x["surface"] == r["surface"])
        print("| %s | %s | %d | %.4f | %.4f | %.4f | %.4f |" % (
            r["scene"], r["surface"], r["pixels"], r["mae"], r["rmse"], t["mae"], t["rmse"]))
    benchlib.write_csv(os.path.join(out, "albedo_scenes.csv"), rows, table="albedo")
    with open(os.path.join(out, "albedo_error_vs_time.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(curve[0]))
        w.writeheader()
        w.writerows(curve)

    print("\n| scene | ours MAE | ours RMSE | Retinex MAE | Retinex RMSE | ours MAE scaled | ours s |")
    print("|---|---|---|---|---|---|---|")
    mean = lambda m, k: sum(r[k] for r in rows if r["method"] == m) / len(names)
    for s in names:
        o = next(r for r in rows if r["scene"] == s and r["method"] == "ours")
        t = next(r for r in rows if r["scene"] == s and r["method"] == "retinex")
        print("| %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.1f |" % (
            s, o["mae"], o["rmse"], t["mae"], t["rmse"], o["mae_scaled"], o["seconds"]))
    print("| mean | %.4f | %.4f | %.4f | %.4f | %.4f | |" % (
        mean("ours", "mae"), mean("ours", "rmse"), mean("retinex", "mae"), mean("retinex", "rmse"),
        mean("ours", "mae_scaled")))
    if failed:
        print("failed (not in the table): " + ", ".join(failed))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: plots skipped")
        return 0
    fig, ax = plt.subplots(1, 3, figsize=(17, 4.5))
    for i, s in enumerate(names):
        col = "C%d" % i
        c = [r for r in curve if r["scene"] == s]
        ax[0].plot([max(r["solver_seconds"], 1e-3) for r in c], [r["mae"] for r in c], "o-",
                   color=col, label=s)
        with open(os.path.join(out, "albedo_history_%s.csv" % s)) as f:
            h = list(csv.DictReader(f))
        t = [float(r["seconds"]) for r in h]
        f0 = float(h[0]["objective"])
        ax[1].plot(t, [float(r["objective"]) / f0 for r in h], color=col, label=s)
        ax[2].semilogy(t, [float(r["primal_residual"]) for r in h], "-", color=col, label=s + " primal")
        ax[2].semilogy(t, [float(r["dual_residual"]) for r in h], "--", color=col, label=s + " dual")
    ax[0].set_xscale("log")
    ax[0].set_xlabel("solver seconds (2 threads)")
    ax[0].set_ylabel("albedo MAE vs albedo.exr")
    ax[0].set_title("error against solver time (ours, iteration caps)")
    ax[0].legend(fontsize=7)
    ax[1].set_xlabel("seconds")
    ax[1].set_ylabel("objective / first recorded")
    ax[1].set_title("objective")
    ax[1].legend(fontsize=7)
    ax[2].set_xlabel("seconds")
    ax[2].set_ylabel("RMS residual (x step)")
    ax[2].set_title("primal (solid) and dual (dashed) residuals")
    ax[2].legend(fontsize=5, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "albedo_error_vs_time.png"), dpi=110)
    print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
