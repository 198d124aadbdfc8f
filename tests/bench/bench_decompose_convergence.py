#!/usr/bin/python3
"""The decomposition's convergence against its run time: the scalar-step solver (the product's),
the diagonal steps with the coarse-to-fine start, and those with the pixels outside the data terms
held at their start, side by side.

For each scene, `inlay-cli decompose SCENE --iterations CAP --solver scalar|diagonal|diagonal+hold
--progress-csv` (the solver re-run from its start after one preparation per solver, its objective
and residuals every 10 iterations against seconds). The objective's gap is taken to the lowest
objective the scalar and diagonal solvers reached on that scene (they solve the same objective
from the same start); diagonal+hold solves it with more constraints, its gap to its own minimum. Rooms are named as for harness.py (t02, d4): their
assisted scene is written first; `example` is the bundled example.

Writes OUT/decompose_convergence.csv (scene, solver, seconds, iteration, objective, gap, primal,
dual), OUT/decompose_convergence_summary.csv (scene, solver, iterations, converged, seconds,
report) and OUT/decompose_convergence.png (relative objective gap and dual residual against
seconds).

usage: bench_decompose_convergence.py INLAY_CLI [--scenes example,t02] [--cap 2000] [--out DIR]
"""
import csv, os, subprocess, sys, tempfile
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOLVERS = ("scalar", "diagonal", "diagonal+hold")
ROOT = os.path.dirname(os.path.dirname(HERE))


def scene_file(name, tmp):
    if name == "example":
        return os.path.join(ROOT, "resources", "example", "scene.json")
    shared = os.environ.get("INLAY_SHARED_DIR", os.path.join(ROOT, "..", "shared"))
    base = "scenes-train" if name.startswith("t") else "scenes"
    room = [d for d in os.listdir(os.path.join(shared, base)) if d.startswith(name)][0]
    out = os.path.join(tmp, name + ".json")
    subprocess.run(["/usr/bin/python3", os.path.join(shared, "tools", "harness.py"), "scene",
                    os.path.join(shared, base, room), out], check=True, capture_output=True)
    return out


def run(cli, solver, scene, cap, tmp):
    hist = os.path.join(tmp, "history.csv")
    p = subprocess.run([cli, "decompose", scene, "--albedo", os.path.join(tmp, "albedo.exr"),
                        "--iterations", str(cap), "--solver", solver, "--progress-csv", hist],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("failed: %s %s\n%s" % (cli, scene, p.stderr))
    report = [l for l in p.stderr.splitlines() if "decomposition" in l]
    with open(hist) as f:
        return list(csv.DictReader(f)), (report[-1] if report else "")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    cap = int(opt("--cap", "2000"))
    os.makedirs(out, exist_ok=True)
    rows, summary = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in opt("--scenes", "example").split(","):
            scene = scene_file(name, tmp)
            runs = {b: run(cli, b, scene, cap, tmp) for b in SOLVERS}
            lowest = lambda names: min(float(r["objective"]) for b in names for r in runs[b][0])
            for b, (hist, report) in runs.items():
                best = lowest([b] if b == "diagonal+hold" else ["scalar", "diagonal"])
                for r in hist:
                    f = float(r["objective"])
                    rows.append({"scene": name, "solver": b, "seconds": float(r["seconds"]),
                                 "iteration": int(r["iteration"]), "objective": f,
                                 "gap": (f - best) / abs(best),
                                 "primal": float(r["primal_residual"]),
                                 "dual": float(r["dual_residual"])})
                last = hist[-1]
                summary.append({"scene": name, "solver": b, "iterations": int(last["iteration"]),
                                "converged": "not converged" not in report,
                                "seconds": float(last["seconds"]),
                                "report": report.split("decomposition ", 1)[-1]})
                print("%s %s: %s" % (name, b, summary[-1]["report"]), flush=True)
    benchlib.write_csv(os.path.join(out, "decompose_convergence.csv"), rows)
    benchlib.write_csv(os.path.join(out, "decompose_convergence_summary.csv"), summary)
    plot(out, rows)
    return 0


def plot(out, rows):
    with benchlib.figure(os.path.join(out, "decompose_convergence.png"), 1, 2,
                         figsize=(11, 4)) as ax:
        if ax is None:
            return
        scenes = sorted({r["scene"] for r in rows})
        for k, s in enumerate(scenes):
            for b, style in zip(SOLVERS, ("--", "-", ":")):
                pts = [r for r in rows if r["scene"] == s and r["solver"] == b]
                t = [r["seconds"] for r in pts]
                ax[0].semilogy(t, [max(r["gap"], 1e-9) for r in pts], style, color="C%d" % k,
                               label="%s %s" % (s, b))
                ax[1].semilogy(t, [r["dual"] for r in pts], style, color="C%d" % k)
        ax[0].set(xlabel="solver seconds", ylabel="objective gap (relative)")
        ax[1].axhline(1e-4, color="gray", lw=0.5)
        ax[1].set(xlabel="solver seconds", ylabel="dual residual (tolerance 1e-4)")
        ax[0].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
