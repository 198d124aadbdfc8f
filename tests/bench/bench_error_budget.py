#!/usr/bin/python3
"""What the inserted object's error is made of, per room of ../shared/scenes-train: swap one
estimated component at a time for the room's truth and see how much of the error goes.

Per room the harness writes the assisted scene file (harness.py scene, the room's own sRGB photo)
and inlay-cli renders it with the same seed and exactly --spp samples (uniform, default 16, the
generalisation benchmark's budget), scored by harness.py score (object RMSE, sRGB [0,1]):
  estimated       everything as Inlay estimates it (the benchmark's number)
  estimated_long  the same at --long-spp samples (default 128): the product's error without
                  most of the benchmark's render noise
  no_grain        the same without the photo's grain on the object (--no-grain; the truth has a
                  grain of its own, independent of ours, so ours adds to the error)
  true_intensity  our lights where we put them, each with its true light's power (the truth's
                  radiance x its area / our light's area, in the photo's units)
  true_lights     the true lights (truth.json's corners and radiance): true places and power
  true_albedo     our lights, the true albedo of the room (albedo.exr)
  true_response   camera.response "srgb" (the plain photo's true curve); not rendered (same as
                  estimated) when the estimate already says sRGB
  all_true        true lights, true albedo and true response at --spp
  all_true_long   the same at --long-spp samples (default 128)
A room with a sun whose window is out of view (its sky is a light Inlay adds after the scene
file's, and one of the truth's lights here: the window's rectangle at the sky's radiance) also:
  true_sky        our lights, the window's light at the truth's sky radiance (its place ours)
  true_window     our lights, the window's light replaced by the truth's window and sky
  true_patch      where the photo clips, the render's bounces read the truth's radiance
                  (photo_linear.exr in the photo's units, --replace-radiance) instead of the
                  light model's albedo x fitted sun: the sun's strength and colour as the
                  sunlit patch bounces them
  true_ceiling    the unseen ceiling's albedo the truth's (--surface-albedo)
  sun_all_true    true_window, true_patch and true_ceiling together
  fit_true_ceiling the light fit's model of the unseen ceiling the truth's colour
                  (--fit-unseen-ceiling; the render's unseen ceiling stays the product's): the
                  sky's and the sun's fitted strength as the ceiling sets them (its lights:
                  OUT/ROOM_fit_true_ceiling_lights.json, ours: OUT/ROOM_lights.json)
  floor_no_grain  all_true_long without our grain (--no-grain): what stays with every input
                  true, less the grain we add independently of the truth's
Geometry (the box, the table, the object's place) comes from the harness's assisted inputs (the
truth's own vanishing points, corners and outlines) and cannot be swapped; its error is measured:
the box's size against the truth's (the preparation's report) and the object mask's IoU against
object_mask.png (--layers).

The error budget, as shares of the estimated squared error E0^2 (RMSE^2 over the object):
  intensity   E0^2 - E(true_intensity)^2
  places      E(true_intensity)^2 - E(true_lights)^2     (the lights' places once their power
                                                           is right: swapped in that order)
  albedo      E0^2 - E(true_albedo)^2
  response    E0^2 - E(true_response)^2
  noise       E0^2 - E(estimated_long)^2                 (our render's noise at --spp)
  grain       E0^2 - E(no_grain)^2                       (the grain render.grain adds)
  floor       E(all_true_long)^2  (what stays with every swappable component true and the render
                                   converged: geometry, the renderer against Cycles, the truth's
                                   own Monte-Carlo noise, JPEG)
  interaction E0^2 minus all of the above (components that cancel or add up; may be negative)
  sky, window, patch, ceiling, sun_all, fit_ceiling: E0^2 - E(true_sky)^2 and so on, each
              on its own, not part of the sum (sun rooms only)
The column noise_rms is the RMS difference of all_true and all_true_long over the object (the
noise itself, not its share of the error); truth_noise_rms the truth's own noise there (adjacent
pixels' difference over sqrt 2), which no render shares; on sun rooms patch_clipped_share,
patch_true_rgb and patch_ours_rgb: the sunlit patch's clipped share per channel and its median
radiance, the truth's and our render's. A light the truth puts beyond our rear wall (the box
closes 0.5 m behind the camera) is partly hidden by it: `places` is then negative.

Writes OUT/error_budget.csv (one row per room), OUT/error_budget.png (per room: each
component's share), OUT/error_budget_sun.png (sun rooms: the object's RMSE of each run), docs/bench/error_budget.md; every composite, scene file and lights file
stays in OUT. Rooms run in the order given; each room's row is kept in OUT/rows/ so that two
processes can split the rooms and the last to finish writes the union (--rows-only: write the
CSV and plot from OUT/rows/ without measuring).

usage: bench_error_budget.py INLAY_CLI [--out DIR] [--rooms t01,t03|A|B] [--spp 16]
                             [--long-spp 128] [--rows-only] [--reuse]
  --reuse      keep the composites already in OUT (render only the missing ones)
"""
import json, os, subprocess, sys, time

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"
COMPONENTS = ["intensity", "places", "albedo", "response", "noise", "grain", "floor", "interaction"]
SUN_RUNS = ["true_sky", "true_window", "true_patch", "true_ceiling", "sun_all_true", "fit_true_ceiling"]


def quad_area(corners):
    c = np.array(corners, float)
    return 0.5 * float(np.linalg.norm(np.cross(c[2] - c[0], c[3] - c[1])))


def to_ours(truth, corners):
    """World corners in Inlay's frame (camera at (0, h, 0))."""
    cam = truth["camera"]["position"]
    return [[p[0] - cam[0], p[1], p[2] - cam[2]] for p in corners]


def sky_window(truth):
    """The sky through a sun's window out of view as the truth has it (the window's rectangle,
    emitting into the room at the sky's radiance, photo units), or None."""
    sun = truth.get("sun") or {}
    win, sky = sun.get("window", {}), sun.get("sky") or (truth.get("spec", {}).get("sun") or {}).get("sky")
    if win.get("view_status") != "out_of_view" or not sky:
        return None
    c = np.array(to_ours(truth, win["world_corners"]), float)
    if np.dot(np.cross(c[1] - c[0], c[3] - c[0]), win["inward_normal"]) < 0:
        c = c[::-1]  # emit into the room (AreaLight's normal: (c1 - c0) x (c3 - c0))
    rgb = np.array(sky["color"], float) * sky["strength"] * truth["exposure"]["scale"]
    return {"corners": c.tolist(), "rgb": rgb.tolist()}


def true_lights(truth):
    """The truth's area lights in Inlay's frame and the photo's units; a sun's window out of view
    last (Inlay adds its sky as a light after the scene file's)."""
    scale = truth["exposure"]["scale"]
    out = [{"corners": to_ours(truth, L["world_corners"]), "rgb": [v * scale for v in L["radiance_rgb"]]}
           for L in truth["lights"]]
    return out + [w for w in [sky_window(truth)] if w]


def with_true_power(ours, truth):
    """Our lights (same order as the truth's) where we put them, each with its true light's power."""
    out = []
    for o, t in zip(ours, true_lights(truth)):
        k = quad_area(t["corners"]) / max(quad_area(o["corners"]), 1e-9)
        out.append({"corners": o["corners"], "rgb": [v * k for v in t["rgb"]]})
    return out + [{"corners": o["corners"], "rgb": o["rgb"]} for o in ours[len(out):]]


def sun_runs(truth, room_dir, ours, p, scene, spp, long_spp):
    """The sun room's swaps (see the docstring): {} unless a sun's window is out of view and we
    added its light (the last of ours, after the truth's other lights)."""
    win = sky_window(truth)
    if not win or len(ours) <= len(truth["lights"]):
        return {}
    import OpenImageIO as oiio
    keep = [{"corners": o["corners"], "rgb": o["rgb"]} for o in ours[:-1]]
    json.dump({"lights": keep + [{"corners": ours[-1]["corners"], "rgb": win["rgb"]}]},
              open(p("true_sky.json"), "w"), indent=1)
    json.dump({"lights": keep + [win]}, open(p("true_window.json"), "w"), indent=1)
    hdr = oiio.ImageBuf(os.path.join(room_dir, "photo_linear.exr"))
    px = np.asarray(hdr.get_pixels(oiio.FLOAT))[..., :3] * truth["exposure"]["scale"]
    oiio.ImageBuf(np.ascontiguousarray(px, np.float32)).write(p("true_radiance.exr"))
    json.dump({"ceiling": truth["spec"]["materials"]["ceiling"]["color"]}, open(p("true_ceiling.json"), "w"))
    patch, ceiling = ["--replace-radiance", p("true_radiance.exr")], ["--surface-albedo", p("true_ceiling.json")]
    fit_ceiling = ["--fit-unseen-ceiling", ",".join("%.4f" % v for v in truth["spec"]["materials"]["ceiling"]["color"])]
    srgb, alb = p("scene_srgb.json"), os.path.join(room_dir, "albedo.exr")
    return {"true_sky": (scene, spp, ["--replace-lights", p("true_sky.json")]),
            "true_window": (scene, spp, ["--replace-lights", p("true_window.json")]),
            "true_patch": (scene, spp, patch), "true_ceiling": (scene, spp, ceiling),
            "sun_all_true": (scene, spp, ["--replace-lights", p("true_window.json")] + patch + ceiling),
            "fit_true_ceiling": (scene, spp, fit_ceiling + ["--lights-json", p("fit_true_ceiling_lights.json")]),
            "floor_no_grain": (srgb, long_spp, ["--no-grain", "--replace-lights", p("true_lights.json"), "--replace-albedo",
                                                alb])}


def render(cli, scene, png, spp, extra, log, reuse=False):
    """inlay-cli render with exactly `spp` samples, seed 1; the wall seconds (0 when `reuse` kept
    an existing composite), or None on failure."""
    if reuse and os.path.exists(png):
        return 0.0
    t = time.monotonic()
    cmd = [cli, "render", scene, "-o", png, "--quiet", "--seed", "1", "--spp", str(spp), "--seconds", "0",
           "--noise", "0"] + extra
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        log.write("failed: %s\n%s\n" % (" ".join(cmd), p.stderr[-500:]))
        return None
    return time.monotonic() - t


def score(tools, room_dir, png):
    p = subprocess.run([PY, os.path.join(tools, "harness.py"), "score", room_dir, png], capture_output=True,
                       text=True, check=True)
    return json.loads(p.stdout)


def mask_iou(layers_exr, room_dir):
    """IoU of our object mask (the --layers file's `mask` layer) with the truth's object_mask.png."""
    import OpenImageIO as oiio
    truth = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    inp = oiio.ImageInput.open(layers_exr)
    if inp is None:
        return ""
    spec = inp.spec()
    px = np.asarray(inp.read_image(0, spec.nchannels, "float")).reshape(spec.height, spec.width, spec.nchannels)
    inp.close()
    idx = [i for i, ch in enumerate(spec.channelnames) if ch.startswith("mask")]
    if not idx:
        return ""
    ours = px[..., idx[0]] >= 0.5
    union = np.logical_or(ours, truth).sum()
    return round(float(np.logical_and(ours, truth).sum() / max(union, 1)), 4)


def box_error(report, truth):
    """The layout stage's 'W x D m, H m high' against the truth room's size (m)."""
    try:
        detail = next(s["detail"] for s in json.load(open(report))["stages"] if s["name"] == "layout")
        w, rest = detail.split(" x ")
        d, rest = rest.split(" m, ")
        h = rest.split(" m")[0]
        r = truth["room"]
        return {"box_width_err_m": round(float(w) - r["width"], 3), "box_depth_err_m": round(float(d) - r["depth"], 3),
                "box_height_err_m": round(float(h) - r["height"], 3)}
    except (StopIteration, ValueError, KeyError, OSError):
        return {}


def measure_room(cli, tools, room_dir, out, spp, long_spp, log, reuse):
    """One room's renders and scores: {config: object RMSE}, plus the geometry measures."""
    room = os.path.basename(room_dir)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    p = lambda name: os.path.join(out, "%s_%s" % (room, name))
    scene = p("scene.json")
    subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", room_dir, scene, "--seconds", "100000"], check=True)
    s = json.load(open(scene))
    s["camera"]["response"] = "srgb"
    json.dump(s, open(p("scene_srgb.json"), "w"), indent=1)
    json.dump({"lights": true_lights(truth)}, open(p("true_lights.json"), "w"), indent=1)
    resp = subprocess.run([cli, "response", scene, "-o", p("response.json"), "--quiet"], capture_output=True, text=True)
    family = json.load(open(p("response.json"))).get("description", "?") if resp.returncode == 0 else "?"
    row = {"room": room, "half": benchlib.half(room), "material": truth["object"]["material"]["type"],
           "lights": "+".join(L["view_status"] for L in truth["lights"]), "table": bool(truth.get("table")),
           "response_estimated": family}
    seconds = {}
    t = render(cli, scene, p("estimated.png"), spp, ["--lights-json", p("lights.json"), "--report", p("report.json"),
                                                    "--layers", p("layers.exr")], log, reuse)
    if t is None:
        return row
    seconds["estimated"] = t
    ours = json.load(open(p("lights.json")))["refined"]
    json.dump({"lights": with_true_power(ours, truth)}, open(p("true_power.json"), "w"), indent=1)
    alb = os.path.join(room_dir, "albedo.exr")
    runs = {"estimated_long": (scene, long_spp, []),
            "no_grain": (scene, spp, ["--no-grain"]),
            "true_intensity": (scene, spp, ["--replace-lights", p("true_power.json")]),
            "true_lights": (scene, spp, ["--replace-lights", p("true_lights.json")]),
            "true_albedo": (scene, spp, ["--replace-albedo", alb]),
            "true_response": (p("scene_srgb.json"), spp, []),
            "all_true": (p("scene_srgb.json"), spp, ["--replace-lights", p("true_lights.json"), "--replace-albedo", alb]),
            "all_true_long": (p("scene_srgb.json"), long_spp,
                              ["--replace-lights", p("true_lights.json"), "--replace-albedo", alb])}
    runs.update(sun_runs(truth, room_dir, ours, p, scene, spp, long_spp))
    if family == "srgb":
        del runs["true_response"]  # the same scene as estimated: nothing to swap
    for name, (sf, n, extra) in runs.items():
        t = render(cli, sf, p(name + ".png"), n, extra, log, reuse)
        if t is not None:
            seconds[name] = t
    prev_path = os.path.join(out, "rows", room + ".json")
    prev = json.load(open(prev_path)) if os.path.exists(prev_path) else {}
    for name in seconds:
        sc = score(tools, room_dir, p(name + ".png"))
        row[name + "_rmse"] = round(sc["object_rmse"], 4)
        row[name + "_s"] = round(seconds[name], 1) if seconds[name] > 0 else prev.get(name + "_s", "")
    if "true_response_rmse" not in row and "estimated_rmse" in row:
        row["true_response_rmse"] = row["estimated_rmse"]
    row["noise_rms"] = noise_rms(p("all_true.png"), p("all_true_long.png"), room_dir)
    row["object_mask_iou"] = mask_iou(p("layers.exr"), room_dir)
    row["truth_noise_rms"] = truth_noise(room_dir)
    row.update(sun_patch(room_dir, truth, p("layers.exr")))
    row.update(box_error(p("report.json"), truth))
    row.update(budget(row))
    return row


def truth_noise(room_dir):
    """The truth's own noise on the object: the RMS difference of horizontally adjacent object
    pixels (coverage >= 250/255 for both) over sqrt 2, sRGB (an upper bound: edges add to it)."""
    m = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 250
    t = cv2.imread(os.path.join(room_dir, "truth.png"), cv2.IMREAD_COLOR).astype(np.float64) / 255.0
    dx = (t[:, 1:] - t[:, :-1])[m[:, :-1] & m[:, 1:]]
    return round(float(np.sqrt(np.mean(dx ** 2)) / np.sqrt(2)), 4) if dx.size else ""


def sun_patch(room_dir, truth, layers_exr):
    """The sunlit floor patch (the truth's polygon, eroded 2 px): the share of its pixels the
    photo clips per channel, and the median radiance there of the truth (photo units) and of our
    render's room without objects (--layers), per channel."""
    import OpenImageIO as oiio
    poly = (truth.get("sun") or {}).get("floor_patch", {}).get("image_polygon")
    if not poly or not os.path.exists(layers_exr):
        return {}
    m = np.zeros((truth["image"]["height"], truth["image"]["width"]), np.uint8)
    cv2.fillPoly(m, [np.round(np.array(poly)).astype(np.int32)], 1)
    m = cv2.erode(m, np.ones((5, 5), np.uint8)) > 0
    photo = cv2.imread(os.path.join(room_dir, "photo.png"), cv2.IMREAD_COLOR)[..., ::-1]
    hdr = np.asarray(oiio.ImageBuf(os.path.join(room_dir, "photo_linear.exr")).get_pixels(oiio.FLOAT))[..., :3]
    lay = oiio.ImageBuf(layers_exr)
    names = list(lay.spec().channelnames)
    ours = np.asarray(lay.get_pixels(oiio.FLOAT))[..., [names.index("without_objects." + c) for c in "RGB"]]
    fmt = lambda v: " ".join("%.3g" % x for x in v)
    return {"patch_clipped_share": fmt((photo[m] >= 250).mean(0)),
            "patch_true_rgb": fmt(np.median(hdr[m], 0) * truth["exposure"]["scale"]),
            "patch_ours_rgb": fmt(np.median(ours[m], 0))}


def noise_rms(a_png, b_png, room_dir):
    """RMS difference of two renders over the object (the render noise at the lower count)."""
    if not (os.path.exists(a_png) and os.path.exists(b_png)):
        return ""
    rd = lambda f: cv2.imread(f, cv2.IMREAD_COLOR).astype(np.float64) / 255.0
    m = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    return round(float(np.sqrt(np.mean((rd(a_png)[m] - rd(b_png)[m]) ** 2))), 4)


def budget(row):
    """Each component's share of the estimated squared error (see the docstring)."""
    e = lambda k: row.get(k + "_rmse")
    if any(not isinstance(e(k), float) for k in ("estimated", "estimated_long", "true_intensity", "true_lights", "true_albedo",
                                                   "true_response", "all_true", "all_true_long", "no_grain")):
        return {}
    e0 = e("estimated") ** 2
    parts = {"intensity": e0 - e("true_intensity") ** 2, "places": e("true_intensity") ** 2 - e("true_lights") ** 2,
             "albedo": e0 - e("true_albedo") ** 2, "response": e0 - e("true_response") ** 2,
             "noise": e0 - e("estimated_long") ** 2, "grain": e0 - e("no_grain") ** 2, "floor": e("all_true_long") ** 2}
    parts["interaction"] = e0 - sum(parts.values())
    for run in SUN_RUNS:  # sun rooms: each swap on its own, not part of the sum
        if isinstance(e(run), float):
            parts[run.replace("true_", "").replace("_true", "")] = e0 - e(run) ** 2
    return {"share_" + k: round(v / e0, 3) for k, v in parts.items()}


def plot(out, rows):
    rows = [r for r in rows if all("share_" + c in r for c in COMPONENTS)]
    if not rows:
        return
    cols = min(4, len(rows))
    nrow = (len(rows) + cols - 1) // cols
    with benchlib.figure(os.path.join(out, "error_budget.png"), nrow, cols, figsize=(4.2 * cols, 3.4 * nrow),
                         squeeze=False) as ax:
        if ax is None:
            return
        for k, r in enumerate(rows):
            a = ax[k // cols][k % cols]
            v = [r["share_" + c] for c in COMPONENTS]
            a.barh(range(len(v)), v, color=["C%d" % i for i in range(len(v))])
            a.set_yticks(range(len(v)))
            a.set_yticklabels(COMPONENTS, fontsize=8)
            a.invert_yaxis()
            a.axvline(0, color="k", lw=0.6)
            a.set_xlim(min(-0.3, min(v) - 0.05), max(1.0, max(v) + 0.05))
            a.set_title("%s (%s, %s): RMSE %.3f" % (r["room"], r["material"], r["lights"].replace("_", " "),
                                                   r["estimated_rmse"]), fontsize=8)
            a.set_xlabel("share of the object's squared error", fontsize=8)
        for k in range(len(rows), nrow * cols):
            ax[k // cols][k % cols].axis("off")


def plot_sun(out, rows):
    """Sun rooms: the object's RMSE of each run, estimated to everything true."""
    runs = ["estimated", "no_grain", "estimated_long"] + SUN_RUNS + ["true_albedo", "all_true_long", "floor_no_grain"]
    rows = [r for r in rows if isinstance(r.get("true_patch_rmse"), float)]
    if not rows:
        return
    with benchlib.figure(os.path.join(out, "error_budget_sun.png"), 1, len(rows), figsize=(4.6 * len(rows), 3.6),
                         squeeze=False) as ax:
        if ax is None:
            return
        for k, r in enumerate(rows):
            a = ax[0][k]
            v = [r.get(n + "_rmse") if isinstance(r.get(n + "_rmse"), float) else 0 for n in runs]
            a.barh(range(len(v)), v, color=["C0"] * 3 + ["C1"] * len(SUN_RUNS) + ["C2"] * 3)
            a.axvline(r["estimated_rmse"], color="k", lw=0.6)
            a.set_yticks(range(len(v)))
            a.set_yticklabels(runs, fontsize=8)
            a.invert_yaxis()
            a.set_title("%s: object RMSE per swap (16 spp; long: 128)" % r["room"], fontsize=8)
            a.set_xlabel("object RMSE (sRGB)", fontsize=8)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    rows_dir = os.path.join(out, "rows")
    os.makedirs(rows_dir, exist_ok=True)
    if "--rows-only" not in sys.argv[1:]:
        with open(os.path.join(out, "failures.log"), "a") as log:
            for room in names:
                row = measure_room(cli, tools, os.path.join(sdir, room), out, int(opt("--spp", "16")),
                                   int(opt("--long-spp", "128")), log, "--reuse" in sys.argv[1:])
                json.dump(row, open(os.path.join(rows_dir, room + ".json"), "w"))
                print(json.dumps(row), flush=True)
    rows = benchlib.read_rows(rows_dir)
    if not rows:
        return 1
    cols = ["room", "material", "lights", "estimated_rmse", "estimated_long_rmse", "no_grain_rmse", "true_intensity_rmse", "true_lights_rmse",
            "true_albedo_rmse", "true_response_rmse", "all_true_rmse", "all_true_long_rmse", "noise_rms"]
    cols += ["share_" + c for c in COMPONENTS] + ["object_mask_iou", "box_depth_err_m"]
    if any(r.get("true_patch_rmse") not in (None, "") for r in rows):
        cols += ["truth_noise_rms", "patch_clipped_share", "patch_true_rgb", "patch_ours_rgb"]
        cols += [k + "_rmse" for k in SUN_RUNS + ["floor_no_grain"]] + ["share_" + k.replace("true_", "").replace("_true", "")
                                                  for k in SUN_RUNS]
    benchlib.write_csv(os.path.join(out, "error_budget.csv"), rows, table="error_budget", columns=cols)
    plot(out, rows)
    plot_sun(out, rows)
    print("wrote", os.path.join(out, "error_budget.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
