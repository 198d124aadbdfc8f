#!/usr/bin/python3
"""The ~6 % darker diffuse object with everything true, taken apart: the albedo of the room
surfaces the camera does not see (issue #16).

Per room of ../shared/scenes-train, the harness's assisted scene with the truth's rear wall
(bench_floor.py's `scene_rear`), the truth's lights (--replace-lights) and the truth's albedo
(--replace-albedo albedo.exr), --no-grain, seed 1, exactly --spp samples (default 32); each run
changes one thing, the albedo the render gives the surfaces the photo does not show:
  estimate     the baseline build (--baseline-cli, e.g. main's): its --replace-albedo left those
               surfaces at the estimate's own guess (the oracle was not all true)
  walls_mean   this build, the unseen ceiling and walls at the mean of the true seen walls
               (--surface-albedo: the rule before this change)
  product      this build: the product's rule on the true albedo (an unseen ceiling at least
               kUnseenCeilingAlbedo grey, lighting/estimate.h)
  true_ceiling this build, the unseen ceiling at the truth's ceiling colour (--surface-albedo)
  true_unseen  this build, every unseen wall and the ceiling at the truth's colours
The reading is the object's mean colour in linear light, ours over the truth's (truth.png and the
composite sRGB-decoded, object_mask.png = 255, per channel and luminance): the bias that is half
of t03's floor. Beside it the harness's object RMSE.

Writes OUT/unseen.csv (one row per room and run), OUT/unseen.png (ours / true per room and run),
docs/bench/unseen.md; composites stay in OUT (--reuse keeps them).

usage: bench_unseen.py INLAY_CLI --baseline-cli MAIN_CLI [--out DIR] [--rooms A|B|t03,t09]
                       [--spp N] [--runs estimate,product,...] [--reuse]
"""
import json, os, sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_error_budget as budget  # noqa: E402
import bench_floor as floor  # noqa: E402

RUNS = ("estimate", "walls_mean", "product", "true_ceiling", "true_unseen")
WALL_LABELS = (3, 4, 5, 6)  # labels.png: wall_front, wall_back, wall_left, wall_right
SURFACE_OF_LABEL = {1: "floor", 2: "ceiling", 3: "wall_back", 4: "wall_rear", 5: "wall_left", 6: "wall_right"}


def true_wall_colour(materials):
    """The truth's wall albedo: flat walls their colour, tiles the mean of their two tile colours."""
    w = materials["walls"]
    if w.get("type") == "tiles" and "color1" in w and "color2" in w:
        return [(a + b) / 2 for a, b in zip(w["color1"], w["color2"])]
    return list(w["color"])


def unseen_surfaces(room_dir):
    """The box surfaces labels.png never shows (our names; the camera looks at wall_back)."""
    labels = cv2.imread(os.path.join(room_dir, "labels.png"), cv2.IMREAD_GRAYSCALE)
    seen = {SURFACE_OF_LABEL[int(v)] for v in np.unique(labels) if int(v) in SURFACE_OF_LABEL}
    return [s for s in ("ceiling", "wall_left", "wall_right", "wall_back", "wall_rear") if s not in seen]


def seen_walls_mean(room_dir):
    """The mean of albedo.exr over the wall pixels the camera sees (the old rule's guess)."""
    albedo = cv2.imread(os.path.join(room_dir, "albedo.exr"), cv2.IMREAD_UNCHANGED)[:, :, 2::-1]
    labels = cv2.imread(os.path.join(room_dir, "labels.png"), cv2.IMREAD_GRAYSCALE)
    walls = np.isin(labels, WALL_LABELS)
    return [float(v) for v in albedo[walls].mean(axis=0)]


def surface_files(room_dir, out, room, truth):
    """The --surface-albedo files of the walls_mean, true_ceiling and true_unseen runs."""
    unseen = unseen_surfaces(room_dir)
    mats = truth["spec"]["materials"]
    wall, mean = true_wall_colour(mats), seen_walls_mean(room_dir)
    files = {"walls_mean": {s: mean for s in unseen},
             "true_ceiling": {"ceiling": list(mats["ceiling"]["color"])} if "ceiling" in unseen else {},
             "true_unseen": {s: (list(mats["ceiling"]["color"]) if s == "ceiling" else wall) for s in unseen}}
    paths = {}
    for name, content in files.items():
        paths[name] = os.path.join(out, "%s_%s_albedo.json" % (room, name))
        with open(paths[name], "w") as f:
            json.dump(content, f, indent=1)
    return paths, unseen


def linear(png):
    return floor.srgb_to_linear(cv2.imread(png, cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.float64) / 255.0)


def ratio(png, room_dir):
    """Ours over the truth's mean linear colour over the object's full pixels: (r, g, b, lum)."""
    mask = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 255
    ours, true = linear(png)[mask].mean(axis=0), linear(os.path.join(room_dir, "truth.png"))[mask].mean(axis=0)
    lum = np.array([0.2126, 0.7152, 0.0722])
    return [round(float(v), 4) for v in list(ours / true) + [ours @ lum / (true @ lum)]]


def measure_room(cli, base_cli, tools, room_dir, out, spp, runs, reuse, log):
    room = os.path.basename(room_dir)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    _, scene_rear, lights = floor.scenes_of(tools, room_dir, out, room, truth)
    files, unseen = surface_files(room_dir, out, room, truth)
    extra = ["--replace-lights", lights, "--replace-albedo", os.path.join(room_dir, "albedo.exr"), "--no-grain"]
    rows = []
    for name in runs:
        c = base_cli if name == "estimate" else cli
        more = ["--surface-albedo", files[name]] if name in files else []
        png = os.path.join(out, "%s_%s.png" % (room, name))
        t = budget.render(c, scene_rear, png, spp, extra + more, log, reuse)
        if t is None:
            continue
        sc = budget.score(tools, room_dir, png)
        r, g, b, lum = ratio(png, room_dir)
        rows.append({"room": room, "half": benchlib.half(room), "material": truth["object"]["material"]["type"],
                     "unseen": "+".join(unseen), "run": name, "spp": spp, "ours_over_true": lum,
                     "ratio_r": r, "ratio_g": g, "ratio_b": b, "object_rmse": round(sc["object_rmse"], 4),
                     "object_rmse_adjusted": round(sc["object_rmse_adjusted"], 4), "render_s": round(t, 1)})
        print(json.dumps(rows[-1]), flush=True)
    return rows


def plot(out, rows):
    rooms = sorted({r["room"] for r in rows})
    runs = [n for n in RUNS if any(r["run"] == n for r in rows)]
    with benchlib.figure(os.path.join(out, "unseen.png"), 1, 2, figsize=(12, 4)) as ax:
        if ax is None:
            return
        w = 0.8 / max(1, len(runs))
        for k, name in enumerate(runs):
            got = {r["room"]: r for r in rows if r["run"] == name}
            xs = [i + k * w for i, room in enumerate(rooms) if room in got]
            ax[0].bar(xs, [got[room]["ours_over_true"] for room in rooms if room in got], w, label=name)
            ax[1].bar(xs, [got[room]["object_rmse"] for room in rooms if room in got], w, label=name)
        for a, title in ((ax[0], "object: ours / true, linear luminance"), (ax[1], "object RMSE (sRGB)")):
            a.set_xticks([i + 0.4 - w / 2 for i in range(len(rooms))])
            a.set_xticklabels(rooms)
            a.set_title(title)
        ax[0].axhline(1.0, color="k", lw=0.8)
        ax[0].set_ylim(0.8, 1.1)
        ax[0].legend(fontsize=7)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    base_cli = opt("--baseline-cli", None)
    runs = [r for r in opt("--runs", ",".join(RUNS)).split(",") if r]
    if any(r not in RUNS for r in runs) or ("estimate" in runs and not base_cli):
        sys.stderr.write(__doc__.strip() + "\n")
        sys.exit(2)
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    os.makedirs(out, exist_ok=True)
    rows = []
    with open(os.path.join(out, "failures.log"), "a") as log:
        for room in names:
            rows += measure_room(cli, base_cli, tools, os.path.join(sdir, room), out, int(opt("--spp", "32")), runs,
                                 "--reuse" in sys.argv, log)
    benchlib.write_csv(os.path.join(out, "unseen.csv"), rows, table="unseen")
    plot(out, rows)
    print("wrote", os.path.join(out, "unseen.csv"))


if __name__ == "__main__":
    main()
