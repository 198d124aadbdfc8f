#!/usr/bin/python3
"""The principal point's prior strength, chosen on one half of York and scored on the other
(Debian's python3 with numpy; matplotlib for the plot).

usage: bench_camera_principal.py BUILD_DIR YORK_DIR [--out DIR] [--sigmas 0,0.01,...]

Runs BUILD_DIR/tests/bench/bench_camera on YORK_DIR (default search budget) once per prior
1-sigma S (EstimateOptions::principalSigma, a fraction of half the long side; 0 holds the point
at the image centre) and once with the truth's principal point (--known-principal: what a
perfect principal point would give with our lines, a diagnosis). The photos, sorted by name, are
split into alternate halves A and B; per half the horizon AUC exactly as score_york.py computes
it. The S with the best AUC on A is scored on B and vice versa (held out: no figure is chosen on
the images it reports). Also per S over all photos: focal and worst-direction medians, and the
estimated principal points' mean distance to the truth's.
Writes DIR/camera_principal.csv and camera_principal.png (AUC per half against S); prints JSON.
"""
import csv, json, os, subprocess, sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402


def auc(err):
    xs = np.linspace(0, 0.25, 251)
    err = np.asarray(err)
    return float(np.trapz([(err <= x).mean() for x in xs], xs) / 0.25)


def run(bench, york, out, extra):
    os.makedirs(out, exist_ok=True)
    subprocess.run([bench, "--york", york, "--budgets", "120", "--default-budget", "120", "--reps", "1",
                    "--out", out] + extra, check=True, capture_output=True)
    rows = [r for r in csv.DictReader(open(os.path.join(out, "camera_bench.csv"))) if r["set"] == "york"]
    return sorted(rows, key=lambda r: r["image"])


def summarise(label, sigma, rows, truth_pp):
    h = np.array([float(r["horizon_err"]) if r["horizon_err"] else 1.0 for r in rows])
    pp = np.array([[float(r["principal_x"]), float(r["principal_y"])] for r in rows])
    return {"run": label, "sigma": sigma, "auc_all": auc(h), "auc_A": auc(h[0::2]), "auc_B": auc(h[1::2]),
            "focal_rel_err_median": float(np.median([float(r["focal_rel_err"]) for r in rows])),
            "vp_angle_deg_max_median": float(np.median([float(r["vp_angle_deg_max"]) for r in rows])),
            "pp_to_truth_px_mean": float(np.mean(np.linalg.norm(pp - truth_pp, axis=1)))}


def main():
    a = benchlib.args(__doc__, 2)
    build, york = a[0], a[1]
    out = benchlib.option(a, "--out", os.path.join(benchlib.HERE, "out", "camera_principal"))
    sigmas = [float(s) for s in benchlib.option(a, "--sigmas", "0,0.01,0.02,0.04,0.08,0.16,0.32").split(",")]
    bench = os.path.join(build, "tests", "bench", "bench_camera")
    first = sorted(f for f in os.listdir(york) if f.endswith(".json"))[0]
    truth_pp = np.array(json.load(open(os.path.join(york, first)))["camera"]["principal_px"], float)
    results = []
    for s in sigmas:
        rows = run(bench, york, os.path.join(out, "s%g" % s), ["--principal-sigma", str(s)])
        results.append(summarise("sigma", s, rows, truth_pp))
    known = summarise("known_principal", float("nan"),
                      run(bench, york, os.path.join(out, "known"), ["--known-principal"]), truth_pp)
    benchlib.write_csv(os.path.join(out, "camera_principal.csv"), results + [known], table="camera_principal")
    best_a = max(results, key=lambda r: r["auc_A"])
    best_b = max(results, key=lambda r: r["auc_B"])
    summary = {"chosen_on_A": best_a["sigma"], "held_out_auc_B": best_a["auc_B"],
               "chosen_on_B": best_b["sigma"], "held_out_auc_A": best_b["auc_A"],
               "known_principal_auc_A": known["auc_A"], "known_principal_auc_B": known["auc_B"],
               "runs": results + [known]}
    with benchlib.figure(os.path.join(out, "camera_principal.png"), 1, 1, figsize=(6, 4)) as ax:
        if ax is not None:
            xs = [max(r["sigma"], 0.005) for r in results]
            for half, style in (("A", "o-"), ("B", "s-")):
                ax.plot(xs, [r["auc_" + half] for r in results], style, label="half " + half)
                ax.axhline(known["auc_" + half], ls=":", color="gray")
            ax.set_xscale("log")
            ax.set_xlabel("principal point prior 1-sigma / half long side (0 plotted at 0.005)")
            ax.set_ylabel("horizon AUC")
            ax.set_title("York, alternate halves (dotted: truth's principal point)")
            ax.legend()
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
