#!/usr/bin/python3
"""Does the inserted object carry the photo's grain? Grain on against off, on rooms photographed
through random cameras (shot noise, tone curve, JPEG) and on the dark, noisy JPEG room t09.

Per room of ../shared/scenes-train and camera seed, camera_variants.py re-photographs the room
(OUT/variants/<room>_s<seed>; t09 is also run as it is, its own noisy JPEG). The harness writes
the assisted scene file; inlay-cli renders it twice with the same seed and budget: as is (grain
on, the default) and with --no-grain. Per composite:
  hf_object      the high-frequency noise of the composite inside the object's mask (eroded 2 px):
                 Immerkaer's 3 x 3 second difference, median absolute response as a Gaussian's
                 standard deviation, sRGB [0,1], mean over R, G, B;
  hf_truth       the same of truth.png (the true photo with the object, which shares the
                 photo's noise field);
  hf_ratio       hf_object / hf_truth: 1 is grain like the photo's, below 1 an object cleaner
                 than the photo around it;
  object_rmse, around_rmse, around_rmse_do_nothing   the harness's scores.
Halves: A = odd rooms (where any setting would be chosen), B = even rooms (reported). The
summary prints the median hf_ratio and around_rmse per half, grain on and off.

Writes OUT/grain.csv, OUT/grain.png.

usage: bench_grain.py INLAY_CLI [--out DIR] [--rooms t03,t07,t11,t06,t08,t14] [--seeds 1,2]
                      [--seconds 20] [--no-t09]
"""
import json, os, statistics, subprocess, sys, time

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def read8(path):
    im = cv2.imread(path, cv2.IMREAD_COLOR)
    if im is None:
        raise SystemExit("cannot read " + path)
    return im[:, :, ::-1].astype(np.float64) / 255.0


def hf_noise(image, mask):
    """Immerkaer's noise estimate inside `mask` (boolean, H x W), mean over the channels."""
    k = np.array([[1, -2, 1], [-2, 4, -2], [1, -2, 1]], np.float64)
    inner = cv2.erode(mask.astype(np.uint8), np.ones((5, 5), np.uint8)).astype(bool)
    sig = []
    for c in range(3):
        r = cv2.filter2D(image[:, :, c], -1, k, borderType=cv2.BORDER_REFLECT)
        sig.append(np.median(np.abs(r[inner])) / (0.6745 * 6))
    return float(np.mean(sig)), int(inner.sum())


def variant(shared, room, seed, out):
    """The room re-photographed through camera `seed` (made once), or the room itself (seed 0)."""
    src = os.path.join(shared, "scenes-train", room)
    if seed == 0:
        return src
    dst = os.path.join(out, "variants", "%s_s%d" % (room, seed))
    if not os.path.isfile(os.path.join(dst, "truth.png")):
        subprocess.run([sys.executable, os.path.join(shared, "tools", "camera_variants.py"), src, dst,
                        "--seed", str(seed)], check=True, capture_output=True)
    return dst


def render_and_score(cli, harness, scene_dir, work, seconds, grain):
    """One render (grain on or off) of the harness's assisted scene, scored."""
    sf = os.path.join(work, "scene.json")
    comp = os.path.join(work, "composite_%s.png" % ("on" if grain else "off"))
    py = sys.executable
    subprocess.run([py, harness, "scene", scene_dir, sf, "--seconds", str(seconds)], check=True)
    t0 = time.time()
    cmd = [cli, "render", sf, "-o", comp, "--quiet"] + ([] if grain else ["--no-grain"])
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        print(os.path.basename(scene_dir), "failed:", p.stderr.strip()[-300:])
        return None
    score = json.loads(subprocess.run([py, harness, "score", scene_dir, comp], capture_output=True,
                                      text=True, check=True).stdout)
    mask = cv2.imread(os.path.join(scene_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    hf_obj, n = hf_noise(read8(comp), mask)
    hf_truth, _ = hf_noise(read8(os.path.join(scene_dir, "truth.png")), mask)
    return {"wall_s": round(wall, 1), "hf_object": round(hf_obj, 5), "hf_truth": round(hf_truth, 5),
            "hf_ratio": round(hf_obj / hf_truth, 3) if hf_truth > 0 else float("nan"),
            "object_pixels_inner": n, "object_rmse": round(score["object_rmse"], 4),
            "around_rmse": round(score["around_rmse"], 5),
            "around_rmse_do_nothing": round(score["around_rmse_do_nothing"], 5)}


def summary(rows):
    """Median hf_ratio and around_rmse per half and grain setting."""
    out = []
    for half in ("A", "B", "t09"):
        for grain in ("on", "off"):
            rr = [r for r in rows if r["half"] == half and r["grain"] == grain]
            if not rr:
                continue
            med = lambda k: round(statistics.median(r[k] for r in rr), 4)
            out.append({"half": half, "grain": grain, "n": len(rr), "median_hf_ratio": med("hf_ratio"),
                        "median_object_rmse": med("object_rmse"), "median_around_rmse": med("around_rmse")})
    return out


def plot(ax, rows):
    names = sorted({r["scene"] for r in rows}, key=lambda n: (n[1:3], n))
    x = np.arange(len(names))
    for off, grain, colour in ((-0.2, "on", "tab:orange"), (0.2, "off", "tab:blue")):
        v = [next((r["hf_ratio"] for r in rows if r["scene"] == n and r["grain"] == grain), np.nan) for n in names]
        ax[0].bar(x + off, v, 0.4, label="grain " + grain, color=colour)
    ax[0].axhline(1.0, color="k", lw=0.8)
    ax[0].set_xticks(x, names, rotation=60, fontsize=7)
    ax[0].set(ylabel="object HF noise / truth's", title="grain inside the object (1 = like the photo)")
    ax[0].legend(fontsize=7)
    on = {r["scene"]: r for r in rows if r["grain"] == "on"}
    off = {r["scene"]: r for r in rows if r["grain"] == "off"}
    both = [n for n in names if n in on and n in off]
    a = [off[n]["around_rmse"] for n in both]
    b = [on[n]["around_rmse"] for n in both]
    ax[1].scatter(a, b, s=14)
    hi = max(a + b + [1e-3]) * 1.1
    ax[1].plot([0, hi], [0, hi], "k-", lw=0.8)
    ax[1].set(xlabel="around RMSE, grain off", ylabel="around RMSE, grain on", title="surroundings (shadows, bounce)")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    shared = benchlib.shared_dir()
    if not os.path.isdir(os.path.join(shared, "scenes-train")):
        print("skipped: no ../shared/scenes-train")
        return 0
    os.makedirs(out, exist_ok=True)
    harness = os.path.join(shared, "tools", "harness.py")
    rooms = opt("--rooms", "t03,t07,t11,t06,t08,t14").split(",")
    seeds = [int(s) for s in opt("--seeds", "1,2").split(",")]
    seconds = float(opt("--seconds", "20"))
    jobs = [(r, s) for r in rooms for s in seeds]
    if "--no-t09" not in sys.argv:
        jobs.append(("t09", 0))
    rows = []
    for room, seed in jobs:
        scene_dir = variant(shared, room, seed, out)
        name = "%s_s%d" % (room, seed) if seed else room
        work = os.path.join(out, "grain", name)
        os.makedirs(work, exist_ok=True)
        cam = os.path.join(scene_dir, "camera_variant.json")
        cam = json.load(open(cam)) if os.path.isfile(cam) else {}
        half = "t09" if seed == 0 else ("A" if int(room[1:]) % 2 else "B")
        for grain in (True, False):
            res = render_and_score(cli, harness, scene_dir, work, seconds, grain)
            if res is None:
                continue
            row = {"scene": name, "half": half, "grain": "on" if grain else "off",
                   "camera_noise": round(cam.get("noise", float("nan")), 4), "jpeg_quality": cam.get("jpeg_quality", "")}
            row.update(res)
            rows.append(row)
            print(json.dumps(row), flush=True)
    if not rows:
        return 1
    benchlib.write_csv(os.path.join(out, "grain.csv"), rows)
    summ = summary(rows)
    benchlib.write_csv(os.path.join(out, "grain_summary.csv"), summ)
    for s in summ:
        print(json.dumps(s))
    with benchlib.figure(os.path.join(out, "grain.png"), 1, 2, figsize=(11, 4)) as ax:
        if ax is not None:
            plot(ax, rows)
    print("wrote", os.path.join(out, "grain.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
