#!/usr/bin/python3
"""Does the inserted object carry the photo's grain? Grain on against off, on rooms photographed
through random cameras (shot noise, tone curve, JPEG) and on the dark, noisy JPEG room t09.

Per room of ../shared/scenes-train and camera seed, camera_variants.py re-photographs the room
(OUT/variants/<room>_s<seed>; t09 is also run as it is, its own noisy JPEG). The harness writes
the assisted scene file; inlay-cli renders it once with --layers: the PNG is the composite with
grain (the default), the layers' composite is the same render without grain (the layers stay
clean), encoded to 8-bit sRGB here as inlay-cli encodes a PNG (its half floats can move a value
by one code at most). So on and off share their render and its Monte-Carlo noise: what differs
is the grain alone. Per composite:
  hf_object      the high-frequency noise of the composite inside the object's mask (eroded 2 px):
                 Immerkaer's 3 x 3 second difference, RMS over the 90 % smallest responses as a
                 Gaussian's standard deviation, sRGB [0,1], mean over R, G, B;
  hf_truth       the same of truth.png (the true photo with the object, which shares the
                 photo's noise field);
  hf_ratio       hf_object / hf_truth: 1 is grain like the photo's, below 1 an object cleaner
                 than the photo around it; the render's own noise counts in it (spp, converged:
                 the render's samples per pixel on average, and whether every pixel met the noise
                 target);
  object_rmse, around_rmse, around_rmse_do_nothing   the harness's scores.
Halves: A = odd rooms (where any setting would be chosen), B = even rooms (reported). The
summary prints the median hf_ratio and around_rmse per half, grain on and off.

Writes OUT/grain.csv, OUT/grain.png.

usage: bench_grain.py INLAY_CLI [--out DIR] [--rooms t03,t07,t11,t06,t08,t14] [--seeds 1,2]
                      [--jobs t03:2,t08:5]
                      [--seconds 60] [--no-t09] [--rerender] [--plot-only]
--jobs: these room:seed pairs instead of every room with every seed (camera_variants.py draws
its camera from the seed alone, so seed 1 is the same camera, a nearly noise-free one, for every
room). A room's render is kept in OUT/grain/<room>_s<seed>/ and reused unless --rerender (the
row's budget_s is the one it was rendered with).
"""
import json, os, re, statistics, subprocess, sys, time

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
    """The noise's standard deviation inside `mask` (boolean, H x W; eroded 2 px) from Immerkaer's
    3 x 3 second difference, mean over the channels: the RMS response over the 90 % of pixels
    with the smallest response (edges and silhouettes left out), as a Gaussian's (a Gaussian
    truncated at its 90 % quantile keeps 0.623 of its variance). RMS, not the median: 8-bit
    values make the median response jump between whole code values when the noise is below one."""
    k = np.array([[1, -2, 1], [-2, 4, -2], [1, -2, 1]], np.float64)
    inner = cv2.erode(mask.astype(np.uint8), np.ones((5, 5), np.uint8)).astype(bool)
    sig = []
    for c in range(3):
        r = np.abs(cv2.filter2D(image[:, :, c], -1, k, borderType=cv2.BORDER_REFLECT)[inner])
        if r.size == 0:
            return float("nan"), 0
        kept = r[r <= np.quantile(r, 0.9)]
        sig.append(np.sqrt(np.mean(kept ** 2) / 0.623) / 6)
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


def srgb8(linear):
    """inlay-cli's PNG encoding of a linear image: sRGB, clamped, rounded to 8 bits, in [0,1]."""
    x = np.clip(linear, 0, 1)
    v = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    return np.round(v * 255) / 255


def clean_composite(layers_exr):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(layers_exr)
    names = list(buf.spec().channelnames)
    pixels = np.asarray(buf.get_pixels(oiio.FLOAT))
    try:
        idx = [names.index("composite." + c) for c in "RGB"]
    except ValueError:
        raise SystemExit("no composite layer in " + layers_exr)
    return srgb8(pixels[:, :, idx].astype(np.float64))


def scores_of(image, comp_path, scene_dir, harness, mask, hf_truth):
    score = json.loads(subprocess.run([sys.executable, harness, "score", scene_dir, comp_path],
                                      capture_output=True, text=True, check=True).stdout)
    hf_obj, n = hf_noise(image, mask)
    return {"hf_object": round(hf_obj, 5), "hf_truth": round(hf_truth, 5),
            "hf_ratio": round(hf_obj / hf_truth, 3) if hf_truth > 0 else float("nan"),
            "object_pixels_inner": n, "object_rmse": round(score["object_rmse"], 4),
            "around_rmse": round(score["around_rmse"], 5),
            "around_rmse_do_nothing": round(score["around_rmse_do_nothing"], 5)}


def render_and_score(cli, harness, scene_dir, work, seconds):
    """One render of the harness's assisted scene; its scores with grain (on) and without (off)."""
    sf, on, exr = (os.path.join(work, n) for n in ("scene.json", "composite_on.png", "layers.exr"))
    log = os.path.join(work, "render.log")
    if "--rerender" in sys.argv or not all(os.path.isfile(f) for f in (sf, log, exr, on)):
        subprocess.run([sys.executable, harness, "scene", scene_dir, sf, "--seconds", str(seconds)], check=True)
        t0 = time.time()
        p = subprocess.run([cli, "render", sf, "-o", on, "--layers", exr], capture_output=True, text=True)
        if p.returncode != 0:
            print(os.path.basename(scene_dir), "failed:", p.stderr.strip()[-300:])
            return None
        open(log, "w").write("wall %.1f\n" % (time.time() - t0) + p.stderr)
    text = open(log).read()
    wall = float(text.split()[1])
    last = [l for l in text.splitlines() if "wrote" in l][-1]
    m = re.search(r"([0-9.]+) on average", last)
    budget = json.load(open(sf)).get("render", {}).get("seconds")
    common = {"budget_s": budget, "wall_s": round(wall, 1), "spp": float(m.group(1)) if m else float("nan"),
              "converged": "converged" in last}
    off = os.path.join(work, "composite_off.png")
    off_image = clean_composite(exr)
    cv2.imwrite(off, np.round(off_image[:, :, ::-1] * 255).astype(np.uint8))
    mask = cv2.imread(os.path.join(scene_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    hf_truth, _ = hf_noise(read8(os.path.join(scene_dir, "truth.png")), mask)
    res = {}
    for grain, image, path in (("on", read8(on), on), ("off", off_image, off)):
        res[grain] = dict(common, **scores_of(image, path, scene_dir, harness, mask, hf_truth))
    return res


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
    ax[0].set_yscale("log")
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
    if "--plot-only" in sys.argv:  # the figure again from OUT/grain.csv
        import csv
        rows = [dict(r, hf_ratio=float(r["hf_ratio"]), around_rmse=float(r["around_rmse"]))
                for r in csv.DictReader(open(os.path.join(out, "grain.csv")))]
        with benchlib.figure(os.path.join(out, "grain.png"), 1, 2, figsize=(11, 4)) as ax:
            if ax is not None:
                plot(ax, rows)
        return 0
    shared = benchlib.shared_dir()
    if not os.path.isdir(os.path.join(shared, "scenes-train")):
        print("skipped: no ../shared/scenes-train")
        return 0
    os.makedirs(out, exist_ok=True)
    harness = os.path.join(shared, "tools", "harness.py")
    rooms = opt("--rooms", "t03,t07,t11,t06,t08,t14").split(",")
    seeds = [int(s) for s in opt("--seeds", "1,2").split(",")]
    seconds = float(opt("--seconds", "60"))
    jobs = [(r, s) for r in rooms for s in seeds]
    if opt("--jobs", ""):  # room:seed pairs instead of every room with every seed
        jobs = [(j.split(":")[0], int(j.split(":")[1])) for j in opt("--jobs", "").split(",")]
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
        res = render_and_score(cli, harness, scene_dir, work, seconds)
        for grain in ("on", "off"):
            if res is None:
                continue
            row = {"scene": name, "half": half, "grain": grain,
                   "camera_noise": round(cam.get("noise", float("nan")), 4), "jpeg_quality": cam.get("jpeg_quality", "")}
            row.update(res[grain])
            rows.append(row)
            print(json.dumps(row), flush=True)
    if not rows:
        return 1
    benchlib.write_csv(os.path.join(out, "grain.csv"), rows)
    summ = summary(rows)
    benchlib.write_csv(os.path.join(out, "grain_summary.csv"), summ, table="grain")
    for s in summ:
        print(json.dumps(s))
    with benchlib.figure(os.path.join(out, "grain.png"), 1, 2, figsize=(11, 4)) as ax:
        if ax is not None:
            plot(ax, rows)
    print("wrote", os.path.join(out, "grain.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
