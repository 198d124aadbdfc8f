#!/usr/bin/python3
"""What the object's error floor is made of: the error that stays when every swappable component
(lights, albedo, response) is the room's truth and the render is converged (bench_error_budget's
`all_true_long`), taken apart per room of ../shared/scenes-train with oracle renders and with
readings of the images themselves.

Per room the harness writes the assisted scene (harness.py scene, the room's own photo, response
"srgb"); every run renders it with the truth's lights (--replace-lights, truth.json's corners and
radiance in the photo's units) and the truth's albedo (--replace-albedo albedo.exr), seed 1,
exactly --spp samples (default 128), scored by harness.py score (object RMSE, sRGB [0,1]):
  floor_base     the baseline build (--baseline-cli, e.g. main's), the scene as the harness writes it
                 (bench_error_budget's all_true_long)
  floor_clean    the same without the grain the composite gives the object (--no-grain)
  floor          this build, the same scene, --no-grain
  floor_rear     this build, --no-grain, the scene with layout.rear_m = the truth's rear wall
                 distance (the true box: the harness already gives the seen walls, floor, ceiling)
  floor_clamp    floor_rear with Cycles' clamp of indirect light (--clamp-indirect: the truth's
                 render.clamp.indirect times its exposure scale, in the photo's linear units)
Readings of one image against truth.png over the object (object_mask.png >= 128), each a share
of that run's squared error E^2 (they overlap, so they do not add up to 1):
  truth_noise    the truth's own per-pixel noise (Monte Carlo, and sensor noise on a noisy room),
                 as the generator measured it on flat surfaces of the same render (truth.json
                 checks.photo_png_noise_floor): no converged render can match it, so it is floor
                 that no renderer removes. Beside it truth_dx_rms and ours_dx_rms: the RMS
                 difference of horizontal neighbours inside the eroded mask / sqrt(2) (noise plus
                 the shading's own slope: an upper bound of each image's noise on the object)
  our_noise      our render's own noise at --spp: ours_dx_rms^2 less the truth's slope
                 (truth_dx_rms^2 - truth_noise^2, when positive): what more samples remove
  edge           the pixels within one pixel of the mask's border (the truth's pixel filter is a
                 1.5 px Blackman-Harris, the object's outline mixes with the room behind it)
  bias           the object's mean colour error (what harness.py's "adjusted" removes)
  scale          ours / truth in linear light over the object's unclipped pixels (luminance,
                 sRGB decoded): a light or renderer convention that is off by a factor shows here
The grain's share of the floor is (E(floor_base)^2 - E(floor_clean)^2) / E(floor_base)^2, the
rear wall's (E(floor)^2 - E(floor_rear)^2) / E(floor_base)^2; the readings are taken on floor_clean
(without our grain, whose noise would hide the truth's) and given as shares of E(floor_base)^2.

Writes OUT/floor.csv (one row per room), OUT/floor.png (per room: RMSE of the three runs and the
shares), docs/bench/floor.md; every composite and scene stays in OUT. Each room's row is kept in
OUT/rows/ so that two processes can split the rooms; --rows-only writes the CSV and plot from
OUT/rows/ without measuring.

usage: bench_floor.py INLAY_CLI [--baseline-cli OTHER_CLI] [--out DIR] [--rooms t01,t03|A|B]
                      [--spp 128] [--runs floor_base,...] [--budget-dir DIR] [--rows-only] [--reuse]
  --runs       only these runs (the others keep their rows' earlier values)
  --budget-dir bench_error_budget.py's OUT: its all_true_long composites stand for floor_base
               (the same scene, seed and samples; rendered by the build that ran it)
"""
import json, os, shutil, subprocess, sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_error_budget as budget  # noqa: E402

PY = "/usr/bin/python3"
RUNS = ["floor_base", "floor_clean", "floor", "floor_rear", "floor_clamp"]


def true_rear_m(truth):
    """How far behind the camera the truth's rear wall stands (its room's far z minus the camera's)."""
    return float(truth["world_frame"]["room_extent"]["z"][1] - truth["camera"]["position"][2])


def scenes_of(tools, room_dir, out, room, truth):
    """The room's scene files (harness scene, response srgb; and with the true rear wall) and the
    true lights file: their paths."""
    p = lambda name: os.path.join(out, "%s_%s" % (room, name))
    subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", room_dir, p("scene.json"), "--seconds", "100000"],
                   check=True)
    s = json.load(open(p("scene.json")))
    s["camera"]["response"] = "srgb"
    json.dump(s, open(p("scene_srgb.json"), "w"), indent=1)
    s.setdefault("layout", {})["rear_m"] = round(true_rear_m(truth), 4)
    json.dump(s, open(p("scene_rear.json"), "w"), indent=1)
    json.dump({"lights": budget.true_lights(truth)}, open(p("true_lights.json"), "w"), indent=1)
    return p("scene_srgb.json"), p("scene_rear.json"), p("true_lights.json")


def srgb_to_linear(v):
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def readings(png, room_dir, truth):
    """The image readings of one composite against truth.png over the object (see the docstring)."""
    rd = lambda f: cv2.imread(f, cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.float64) / 255.0
    ours, true_png = rd(png), rd(os.path.join(room_dir, "truth.png"))
    mask = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    err = ours - true_png
    e2 = float(np.mean(err[mask] ** 2))
    inner = cv2.erode(mask.astype(np.uint8), np.ones((3, 3), np.uint8)).astype(bool)
    edge = mask & ~inner
    pair = inner[:, 1:] & inner[:, :-1]
    dx_rms = lambda im: float(np.sqrt(np.mean((im[:, 1:] - im[:, :-1])[pair] ** 2) / 2.0))
    flat = truth.get("checks", {}).get("photo_png_noise_floor", {}).get("rms_8bit_levels")
    noise = float(flat) / 255.0 if isinstance(flat, (int, float)) else float("nan")
    bias2 = float(np.sum(np.mean(err[mask], axis=0) ** 2)) / 3.0
    lum = lambda im: srgb_to_linear(im) @ np.array([0.2126, 0.7152, 0.0722])
    ok = mask & (ours.max(axis=2) < 0.99) & (true_png.max(axis=2) < 0.99)
    scale = float(lum(ours)[ok].sum() / max(lum(true_png)[ok].sum(), 1e-9)) if ok.any() else float("nan")
    share = lambda v: round(v / e2, 3) if e2 > 0 and np.isfinite(v) else ""
    return {"rmse": round(float(np.sqrt(e2)), 4), "truth_noise_rms": round(noise, 4),
            "truth_dx_rms": round(dx_rms(true_png), 4), "ours_dx_rms": round(dx_rms(ours), 4),
            "share_truth_noise": share(noise * noise),
            "share_our_noise": share(max(0.0, dx_rms(ours) ** 2 - max(0.0, dx_rms(true_png) ** 2 - noise * noise))),
            "share_edge": share(float(np.sum(err[edge] ** 2)) / 3.0 / mask.sum()),
            "share_bias": share(bias2), "linear_scale": round(scale, 3)}


def measure_room(cli, base_cli, tools, room_dir, out, spp, log, reuse, only, budget_dir):
    room = os.path.basename(room_dir)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    scene, scene_rear, lights = scenes_of(tools, room_dir, out, room, truth)
    extra = ["--replace-lights", lights, "--replace-albedo", os.path.join(room_dir, "albedo.exr")]
    row = {"room": room, "half": benchlib.half(room), "material": truth["object"]["material"]["type"],
           "lights": "+".join(L["view_status"] for L in truth["lights"]) or "sun",
           "true_rear_m": round(true_rear_m(truth), 2)}
    clamp = 10.0 * truth["exposure"]["scale"]
    if isinstance(truth.get("render", {}).get("clamp"), dict):
        clamp = float(truth["render"]["clamp"].get("indirect", 10.0)) * truth["exposure"]["scale"]
    runs = {"floor_base": (base_cli, scene, []), "floor_clean": (base_cli, scene, ["--no-grain"]),
            "floor": (cli, scene, ["--no-grain"]), "floor_rear": (cli, scene_rear, ["--no-grain"]),
            "floor_clamp": (cli, scene_rear, ["--no-grain", "--clamp-indirect", "%.6g" % clamp])}
    for name, (c, sf, more) in runs.items():
        png = os.path.join(out, "%s_%s.png" % (room, name))
        given = os.path.join(budget_dir, room + "_all_true_long.png") if budget_dir else ""
        if name == "floor_base" and os.path.exists(given):
            shutil.copyfile(given, png)
        elif c is None or name not in only:
            continue
        t = budget.render(c, sf, png, spp, extra + more, log, reuse or name == "floor_base" and os.path.exists(given))
        if t is None:
            continue
        sc = budget.score(tools, room_dir, png)
        row[name + "_rmse"] = round(sc["object_rmse"], 4)
        row[name + "_adjusted"] = round(sc["object_rmse_adjusted"], 4)
        if t > 0:
            row[name + "_s"] = round(t, 1)
        if name == "floor_clean":
            row.update({(k + "_of_clean" if k.startswith("share_") else k): v
                        for k, v in readings(png, room_dir, truth).items() if k != "rmse"})
    return row


def rear_share(row):
    """The grain's and the rear wall's shares of the floor's squared error (see the docstring)."""
    g = lambda k: row.get(k + "_rmse") if isinstance(row.get(k + "_rmse"), float) else None
    b, c, r, k = g("floor_base"), g("floor_clean"), g("floor_rear"), g("floor_clamp")
    if b and c is not None:
        row["share_grain"] = round((b * b - c * c) / (b * b), 3)
    if b and c is not None and r is not None:
        row["share_rear_wall"] = round((c * c - r * r) / (b * b), 3)
    if b and r is not None and k is not None:
        row["share_clamp"] = round((r * r - k * k) / (b * b), 3)
    if b and c:  # the readings were taken as shares of floor_clean's error
        for k in ("share_truth_noise", "share_our_noise", "share_edge", "share_bias"):
            if isinstance(row.get(k + "_of_clean"), float):
                row[k] = round(row[k + "_of_clean"] * c * c / (b * b), 3)
    return row


def plot(out, rows):
    rows = [r for r in rows if "floor_clean_rmse" in r]
    if not rows:
        return
    with benchlib.figure(os.path.join(out, "floor.png"), 1, 2, figsize=(12, 4.2)) as ax:
        if ax is None:
            return
        x = np.arange(len(rows))
        for name, mark in [("floor_base", "s"), ("floor_clean", "D"), ("floor", "o"), ("floor_rear", "^"),
                           ("floor_clamp", "v")]:
            ax[0].plot(x, [r.get(name + "_rmse", np.nan) or np.nan for r in rows], mark, label=name)
        ax[0].set_xticks(x)
        ax[0].set_xticklabels(["%s\n%s" % (r["room"], r["material"]) for r in rows], fontsize=8)
        ax[0].set_ylabel("object RMSE (sRGB), everything true, converged")
        ax[0].legend(fontsize=8)
        parts = ["share_grain", "share_rear_wall", "share_clamp", "share_our_noise", "share_truth_noise", "share_edge",
                 "share_bias"]
        w = 0.8 / len(parts)
        for k, part in enumerate(parts):
            v = [float(r.get(part) or 0) for r in rows]
            ax[1].bar(x + (k - 3) * w, v, w, label=part.replace("share_", ""))
        ax[1].axhline(0, color="k", lw=0.6)
        ax[1].set_xticks(x)
        ax[1].set_xticklabels([r["room"] for r in rows], fontsize=8)
        ax[1].set_ylabel("share of the floor's squared error")
        ax[1].legend(fontsize=8)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    base = opt("--baseline-cli", None)
    base = os.path.abspath(base) if base else None
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    rows_dir = os.path.join(out, "rows")
    os.makedirs(rows_dir, exist_ok=True)
    if "--rows-only" not in sys.argv[1:]:
        with open(os.path.join(out, "failures.log"), "a") as log:
            for room in names:
                row = measure_room(cli, base, tools, os.path.join(sdir, room), out, int(opt("--spp", "128")), log,
                                   "--reuse" in sys.argv[1:], opt("--runs", ",".join(RUNS)).split(","),
                                   opt("--budget-dir", None))
                prev_path = os.path.join(rows_dir, room + ".json")
                if os.path.exists(prev_path):  # keep what this process did not measure again
                    row = rear_share({**json.load(open(prev_path)), **row})
                json.dump(rear_share(row), open(prev_path, "w"))
                print(json.dumps(row), flush=True)
    rows = benchlib.read_rows(rows_dir)
    if not rows:
        return 1
    cols = ["room", "material", "lights", "true_rear_m"] + [n + s for n in RUNS for s in ("_rmse", "_adjusted")]
    cols += ["share_grain", "share_rear_wall", "share_clamp", "share_our_noise", "truth_noise_rms", "truth_dx_rms",
             "ours_dx_rms", "share_truth_noise", "share_edge", "share_bias", "linear_scale"]
    benchlib.write_csv(os.path.join(out, "floor.csv"), rows, table="floor", columns=cols)
    plot(out, rows)
    print("wrote", os.path.join(out, "floor.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
