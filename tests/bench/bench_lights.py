#!/usr/bin/python3
"""Lights from the photo, on every room of ../shared/scenes: what the refinement buys and what
limits the error.

Per room the harness writes the assisted scene file; inlay-cli renders it (same budget, same
seed) with
  refined       the refined lights (the default)
  initial       the lights before refinement (--initial-lights)
  true_lights   the room's true area lights (truth.json, in the photo's units) with our albedo
  true_albedo   our refined lights with the true albedo (albedo.exr)
  true_both     true lights and true albedo (what is left: geometry, gathered light, noise)
and the harness scores each composite (object RMSE, mean-adjusted RMSE, sRGB [0,1]) next to
the paper's uniform baseline. Every run renders the same number of samples with the same seed
(--spp, default 32: the machine's load does not change the noise, and the runs share their
noise pattern), uniformly (--noise 0) unless --noise E asks for the CLI's adaptive sampling to
that noise target (then --spp is each pixel's cap: give a large one to converge). The `_bias` columns are the object RMSE after a Gaussian blur (sigma 2 px,
normalised inside the object's mask) of both images: the render noise mostly gone, the
lighting's bias left; they are what attributes the error. Light position error: distance of each light's centre to its true
light's (same order as truth.json), initial and refined; intensity error: relative error of the
RGB radiance (suns: of their RGB strength against the truth's, in the photo's units). The
refinement's objective against time goes to lights_objective.csv. --seeds 1,2,3 renders every
run once per render seed: the RMSE columns are then the means, `_sd` their standard deviation
over seeds (the measurement's Monte-Carlo noise), and `refined_minus_initial` (mean, `_sd`) the
paired difference of the object RMSE, refined minus initial, seed by seed. --refine-size sets
"refine_size": true on every light of the scene files (the refinement also fits the lights'
edge lengths).

Writes OUT/lights.csv, OUT/lights_objective.csv, OUT/lights.png.

usage: bench_lights.py INLAY_CLI [--out DIR] [--spp N] [--noise E] [--scenes d1,d3] [--runs refined,initial,...]
                       [--seeds 1,2,3] [--refine-size]
"""
import csv, json, os, statistics, subprocess, sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
RUNS = ["refined", "initial", "true_lights", "true_albedo", "true_both"]


def true_lights(truth):
    """The truth's area lights in Inlay's frame (camera at (0, h, 0)) and the photo's units."""
    cam = truth["camera"]["position"]
    scale = truth["exposure"]["scale"]
    out = []
    for L in truth["lights"]:
        corners = [[p[0] - cam[0], p[1], p[2] - cam[2]] for p in L["world_corners"]]
        out.append({"corners": corners, "rgb": [v * scale for v in L["radiance_rgb"]]})
    return out


def smoothed_rmse(scene, comp_path, sigma=2.0):
    """Object RMSE of blurred images (blur normalised inside the mask, scored on its interior)."""
    rd = lambda p: cv2.imread(p, cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.float64) / 255.0
    truth, comp = rd(os.path.join(scene, "truth.png")), rd(comp_path)
    m = (cv2.imread(os.path.join(scene, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128).astype(np.float64)
    blur = lambda im: cv2.GaussianBlur(im, (0, 0), sigma)
    w = blur(m)[..., None] + 1e-9
    a, b = blur(truth * m[..., None]) / w, blur(comp * m[..., None]) / w
    inner = cv2.erode(m.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)
    return float(np.sqrt(np.mean((a[inner] - b[inner]) ** 2)))


def centre(corners):
    return np.mean(np.array(corners, float), axis=0)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    spp = int(opt("--spp", "32"))
    noise = opt("--noise", "0")
    runs = opt("--runs", ",".join(RUNS)).split(",")
    seeds = [int(v) for v in opt("--seeds", "1").split(",")]
    sdir, harness, names = benchlib.scene_rooms(opt("--scenes", ""), out)
    py = sys.executable
    base = benchlib.harness_baselines(harness, sdir)
    rows, objective_rows = [], []
    for name in names:
        sd = os.path.join(sdir, name)
        truth = json.load(open(os.path.join(sd, "truth.json")))
        sf = os.path.join(out, "%s.json" % name)
        subprocess.run([py, harness, "scene", sd, sf, "--seconds", "100000"], check=True)
        if "--refine-size" in sys.argv[1:]:
            scene = json.load(open(sf))
            for light in scene["lights"]:
                light["refine_size"] = True
            json.dump(scene, open(sf, "w"), indent=1)
        tl = os.path.join(out, "%s_true_lights.json" % name)
        json.dump({"lights": true_lights(truth)}, open(tl, "w"))
        lj = os.path.join(out, "%s_lights.json" % name)
        row = {"scene": name, "material": truth["object"]["material"]["type"],
               "uniform_baseline": round(base[name]["uniform_dataset_mean_rmse"], 4),
               "uniform_adjusted": round(base[name]["uniform_adjusted_rmse"], 4)}
        per_seed = {}
        for run in runs:
            for seed in seeds:
                comp = os.path.join(out, "%s_%s.png" % (name, run) if seed == seeds[0] else "%s_%s_s%d.png" % (name, run, seed))
                cmd = [cli, "render", sf, "-o", comp, "--quiet", "--spp", str(spp), "--noise", noise, "--seed", str(seed)]
                if run == "refined":
                    cmd += ["--lights-json", lj]
                if run == "initial":
                    cmd += ["--initial-lights"]
                if run in ("true_lights", "true_both"):
                    if not truth["lights"]:
                        continue  # only a sun: no area light to replace
                    cmd += ["--replace-lights", tl]
                if run in ("true_albedo", "true_both"):
                    cmd += ["--replace-albedo", os.path.join(sd, "albedo.exr")]
                p = subprocess.run(cmd, capture_output=True, text=True)
                if p.returncode != 0:
                    print(name, run, "failed:", p.stderr.strip()[-300:], flush=True)
                    continue
                s = json.loads(subprocess.run([py, harness, "score", sd, comp], capture_output=True, text=True, check=True).stdout)
                per_seed.setdefault(run, []).append((seed, s["object_rmse"], s["object_rmse_adjusted"], smoothed_rmse(sd, comp)))
        for run, vals in per_seed.items():
            for k, key in ((1, "_rmse"), (2, "_adjusted"), (3, "_bias")):
                row[run + key] = round(statistics.mean(v[k] for v in vals), 4)
                if len(vals) > 1:
                    row[run + key + "_sd"] = round(statistics.stdev(v[k] for v in vals), 4)
        if "refined" in per_seed and "initial" in per_seed:
            ini = {v[0]: v[1] for v in per_seed["initial"]}
            diff = [v[1] - ini[v[0]] for v in per_seed["refined"] if v[0] in ini]
            if diff:
                row["refined_minus_initial"] = round(statistics.mean(diff), 5)
                if len(diff) > 1:
                    row["refined_minus_initial_sd"] = round(statistics.stdev(diff), 5)
        if os.path.exists(lj):
            L = json.load(open(lj))
            tls = true_lights(truth)
            for which in ("initial", "refined"):
                pos, inten = [], []
                for ours, t in zip(L[which], tls):
                    pos.append(float(np.linalg.norm(np.array(ours["centre"]) - centre(t["corners"]))))
                    inten.append(float(np.linalg.norm(np.array(ours["rgb"]) - t["rgb"]) / np.linalg.norm(t["rgb"])))
                row[which + "_position_error_m"] = round(max(pos), 4) if pos else ""
                row[which + "_intensity_error"] = round(max(inten), 4) if inten else ""
            ts = truth.get("sun")
            if ts and L.get("suns_initial"):
                t_rgb = np.array(ts["color"]) * ts["strength_W_m2"] / np.pi * truth["exposure"]["scale"]
                for which in ("initial", "refined"):
                    ours = np.array(L["suns_" + which][0]["rgb"])
                    row["sun_" + which + "_rgb"] = " ".join("%.3f" % v for v in ours)
                    row["sun_" + which + "_error"] = round(float(np.linalg.norm(ours - t_rgb) / np.linalg.norm(t_rgb)), 4)
                row["sun_true_rgb"] = " ".join("%.3f" % v for v in t_rgb)
            r = L["refinement"]
            row["refine_s"] = round(r["seconds"], 3)
            row["objective_initial"] = round(r["initial_objective"], 6)
            row["objective_refined"] = round(r["final_objective"], 6)
            for t, obj in r["history"]:
                objective_rows.append({"scene": name, "seconds": round(t, 4), "objective": obj})
        rows.append(row)
        print(json.dumps(row), flush=True)
    if not rows:
        return 1
    csvp = os.path.join(out, "lights.csv")
    benchlib.write_csv(csvp, rows, table="lights")
    with open(os.path.join(out, "lights_objective.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["scene", "seconds", "objective"])
        w.writeheader()
        w.writerows(objective_rows)
    for run in runs:
        vals = [r[run + "_rmse"] for r in rows if run + "_rmse" in r]
        adj = [r[run + "_adjusted"] for r in rows if run + "_adjusted" in r]
        bias = [r[run + "_bias"] for r in rows if run + "_bias" in r]
        if vals:
            print("%-12s median RMSE %.4f  median adjusted %.4f  median bias %.4f  (%d rooms)" %
                  (run, statistics.median(vals), statistics.median(adj), statistics.median(bias), len(vals)))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(12, 4.2))
        x = np.arange(len(rows))
        shown = runs + ["uniform_baseline"]
        for k, run in enumerate(shown):
            key = run if run == "uniform_baseline" else run + "_rmse"
            ax[0].bar(x + (k - len(shown) / 2) * 0.13, [r.get(key, 0) for r in rows], 0.13, label=run)
        ax[0].set_xticks(x)
        ax[0].set_xticklabels([r["scene"].split("_")[0] for r in rows])
        ax[0].set(ylabel="object RMSE vs truth (sRGB)", title="lights: initial, refined, truth swaps")
        ax[0].legend(fontsize=7)
        for name in names:
            pts = [(o["seconds"], o["objective"]) for o in objective_rows if o["scene"] == name]
            if pts:
                ax[1].plot([p[0] for p in pts], [p[1] / pts[0][1] for p in pts], "o-", label=name)
        ax[1].set(xlabel="refinement seconds", ylabel="objective / initial", title="refinement objective against time")
        ax[1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "lights.png"), dpi=110)
    except ImportError:
        print("matplotlib missing: no plot")
    print("wrote", csvp)
    return 0


if __name__ == "__main__":
    sys.exit(main())
