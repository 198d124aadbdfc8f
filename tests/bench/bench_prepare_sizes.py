"""Preparation against photo size: dev rooms upscaled x k (the photo resized by bicubic
interpolation, every pixel coordinate of the scene file scaled by k), prepared and rendered by
inlay-cli; each stage's seconds (--report) and the object and surroundings RMSE against the
room's ground truth (../shared/tools/harness.py score) of the composite brought back to the
room's own size: its linear layer (--layers, without grain) area-averaged k x k, then encoded
to sRGB 8-bit (the dev rooms' response). Averaging the 8-bit composite instead would average
encoded noise (darker than the encoded mean) and the grain, which differ with k. The working copy (--working-mp, default 0.5 MP) makes the
image stages cost about the same at every size; the scores show what that costs in accuracy.

  INLAY_SHARED_DIR=../shared /usr/bin/python3 tests/bench/bench_prepare_sizes.py build
      [--scenes d1,d4,d6] [--scales 1,4,7] [--spp 64] [--seeds 1] [--working-mp 0.5]
      [--threads 2] [--no-focus] [--out DIR] [--append] [--plot-only]

Each room renders with about the same samples per room pixel at every scale (--spp at x1,
spp / k^2 at x k, at least 1); at x1 it renders once per seed in --seeds (the render's own
noise between seeds is the scale against which the other sizes' scores are read). Renders run
with --seconds 0 (every spp asked for, whatever the load; the harness's scene files carry a
60 s budget); --no-focus passes inlay-cli's (every pixel sampled equally).
Writes bench_prepare_sizes.csv (scene, scale, seed, width, height, megapixels, stage, seconds,
working size) and bench_prepare_sizes_scores.csv (scene, scale, seed, megapixels, prepare
seconds, object_rmse, around_rmse), and bench_prepare_sizes.png under DIR (default
tests/bench/out); --append adds to the CSVs already there (another room or scale later).
Upscaled photos live in a temporary folder and are never kept."""
import json, os, shutil, subprocess, sys, tempfile, time

import benchlib

def upscale_scene(scene, k, folder):
    """The scene file of a room photographed k times larger: the photo resized, pixel keys scaled."""
    import cv2
    photo = cv2.imread(scene["photo"], cv2.IMREAD_UNCHANGED)
    big = cv2.resize(photo, (photo.shape[1] * k, photo.shape[0] * k), interpolation=cv2.INTER_CUBIC)
    path = os.path.join(folder, "photo_x%d.png" % k)
    cv2.imwrite(path, big)
    s = json.loads(json.dumps(scene))
    s["photo"] = path
    benchlib.scale_scene_pixels(s, k)
    return s


def composite_at_room_size(layers, k, png):
    """The linear composite layer of `layers` area-averaged k x k, sRGB-encoded to 8-bit `png`."""
    import cv2
    import numpy as np
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(layers)
    lin = inp.read_image(oiio.FLOAT)[:, :, :3]  # the first part: "composite"
    inp.close()
    h, w = lin.shape[0] // k, lin.shape[1] // k
    lin = lin[:h * k, :w * k].reshape(h, k, w, k, 3).mean(axis=(1, 3))
    lin = np.clip(np.nan_to_num(lin), 0, 1)
    enc = np.where(lin <= 0.0031308, 12.92 * lin, 1.055 * np.power(lin, 1 / 2.4) - 0.055)
    cv2.imwrite(png, np.round(enc * 255)[:, :, ::-1].astype(np.uint8))


def run_one(cli, room_dir, scene, k, seed, spp, opt, work):
    """Prepares and renders one scene; its stage records and scores."""
    path = os.path.join(work, "scene.json")
    json.dump(scene, open(path, "w"), indent=1)
    comp, report = os.path.join(work, "comp.png"), os.path.join(work, "report.json")
    layers = os.path.join(work, "layers.exr")
    progress = os.path.join(work, "progress.csv")
    # --seconds 0: the samples asked for, however long they take (the harness's scene gives
    # render.seconds 60, which a loaded machine reached at x4 and x7 before their spp).
    cmd = ["nice", "-n", "10", cli, "render", path, "-o", comp, "--spp", str(spp), "--noise", "0",
           "--seconds", "0", "--seed", str(seed), "--quiet", "--threads", opt("--threads", "2"),
           "--report", report, "--working-mp", opt("--working-mp", "0.5"), "--layers", layers,
           "--progress-csv", progress]
    if "--no-focus" in sys.argv:
        cmd.append("--no-focus")
    t0 = time.time()
    subprocess.run(cmd, check=True)
    wall = time.time() - t0
    frames = benchlib.read_csv(progress)
    reached = int(frames[-1]["spp"]) if frames else 0
    if reached < spp:
        print("warning: %s reached %d of %d spp" % (path, reached, spp), flush=True)
    stages = json.load(open(report))["stages"]
    composite_at_room_size(layers, k, comp)  # scored at the room's own size
    sys.path.insert(0, os.path.join(benchlib.shared_dir(), "tools"))
    import harness
    return stages, harness.score(room_dir, comp), wall


def measure(build, opt, out):
    sdir, harness_py, rooms = benchlib.scene_rooms(opt("--scenes", "d1,d4,d6"), out)
    sys.path.insert(0, os.path.dirname(harness_py))
    import harness
    cli = os.path.join(build, "app", "inlay-cli")
    spp = int(opt("--spp", "64"))
    seeds = [int(s) for s in opt("--seeds", "1").split(",")]
    stage_rows, score_rows = [], []
    if "--append" in sys.argv and os.path.exists(os.path.join(out, "bench_prepare_sizes_scores.csv")):
        stage_rows = benchlib.read_csv(os.path.join(out, "bench_prepare_sizes.csv"))
        score_rows = benchlib.read_csv(os.path.join(out, "bench_prepare_sizes_scores.csv"))
    for room in rooms:
        base = harness.make_scene(os.path.join(sdir, room), "assisted", 60.0)
        for k in [int(v) for v in opt("--scales", "1,4,7").split(",")]:
            with tempfile.TemporaryDirectory() as work:
                scene = upscale_scene(base, k, work) if k > 1 else base
                for seed in (seeds if k == 1 else seeds[:1]):
                    stages, sc, wall = run_one(cli, os.path.join(sdir, room), scene, k, seed,
                                               max(1, spp // (k * k)), opt, work)
                    photo = next(s for s in stages if s["name"] == "photo")
                    w, h = [int(v) for v in photo["working_px"]]
                    mp = w * h / 1e6
                    for s in stages:
                        wp = s.get("working_px", [0, 0])
                        stage_rows.append({"scene": room, "scale": k, "seed": seed, "width": w, "height": h,
                                           "megapixels": round(mp, 3), "stage": s["name"],
                                           "seconds": round(s.get("seconds", 0.0), 3),
                                           "working": "%dx%d" % tuple(wp) if wp[0] else ""})
                    prep = sum(s.get("seconds", 0.0) for s in stages)
                    row = {"scene": room, "scale": k, "seed": seed, "megapixels": round(mp, 3),
                           "focus": "--no-focus" not in sys.argv,
                           "prepare_s": round(prep, 2), "wall_s": round(wall, 1),
                           "object_rmse": round(sc.get("object_rmse", float("nan")), 5),
                           "around_rmse": round(sc.get("around_rmse", float("nan")), 5),
                           "outside_rmse": round(sc.get("outside_rmse", float("nan")), 6)}
                    print(json.dumps(row), flush=True)
                    score_rows.append(row)
                    benchlib.write_csv(os.path.join(out, "bench_prepare_sizes.csv"), stage_rows)
                    benchlib.write_csv(os.path.join(out, "bench_prepare_sizes_scores.csv"), score_rows)


def plot(out):
    stages = benchlib.read_csv(os.path.join(out, "bench_prepare_sizes.csv"))
    scores = benchlib.read_csv(os.path.join(out, "bench_prepare_sizes_scores.csv"))
    with benchlib.figure(os.path.join(out, "bench_prepare_sizes.png"), 1, 2, figsize=(12, 4.5)) as ax:
        if ax is None:
            return
        import statistics
        rooms = sorted({r["scene"] for r in scores})
        for n, room in enumerate(rooms):
            rs = [r for r in scores if r["scene"] == room]
            mps = sorted({float(r["megapixels"]) for r in rs})
            med = lambda key, mp: statistics.median(float(r[key]) for r in rs if float(r["megapixels"]) == mp)
            colour = "C%d" % n
            ax[0].plot(mps, [med("prepare_s", mp) for mp in mps], "o-", color=colour, label=room)
            ax[1].plot(mps, [med("object_rmse", mp) for mp in mps], "o-", color=colour, label=room + " object")
            ax[1].plot(mps, [med("around_rmse", mp) for mp in mps], "x--", color=colour, label=room + " surroundings")
            for key, ax_i in (("prepare_s", 0), ("object_rmse", 1), ("around_rmse", 1)):  # every seed
                ax[ax_i].plot([float(r["megapixels"]) for r in rs], [float(r[key]) for r in rs], ".",
                              color=colour, alpha=0.5)
        for a in ax:
            a.set_xscale("log")
            a.set_xlabel("photo megapixels (dev room upscaled x1, x4, x7)")
        ax[0].set_ylabel("preparation seconds (sum of stages)")
        ax[0].set_title("preparation against photo size")
        ax[0].legend(fontsize=8)
        ax[1].set_ylabel("RMSE against ground truth (room's own size)")
        ax[1].set_title("accuracy against photo size")
        ax[1].legend(fontsize=7)
    del stages


def main():
    build, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    if "--plot-only" not in sys.argv:
        measure(build, opt, out)
    plot(out)


if __name__ == "__main__":
    main()
