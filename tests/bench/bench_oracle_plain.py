#!/usr/bin/python3
"""Oracle swaps on the generalisation benchmark's own plain scenes, at the converged sample count:
what each estimated part costs the inserted object once render noise is mostly gone.

bench_generalization.py --cameras 0 --spp 16 --long-spp 128 leaves, per room, the scene file it
rendered (GEN/ROOM_plain.json), its refined lights (GEN/ROOM_plain_lights.json) and the plain
photo's folder (GEN/variants/ROOM_plain, with the truth). Each run here renders that scene (seed 1,
exactly --spp samples, uniform) with one part swapped for the truth and scores it with
harness.py score (object RMSE, sRGB [0,1]):
  product       nothing swapped (the benchmark's --long-spp composite when --spp equals it)
  more_spp      nothing swapped, 4 x --spp samples: the render noise left at --spp
  true_rear     the room's rear wall (behind the camera) where the truth has it (layout.rear_m)
  true_power    our lights where we put them, each with its true light's power
  true_places   the true lights' rectangles, each with our light's power (our radiance x our
                area / the true area): where the lights are, their power ours
  true_lights   the truth's lights (places and radiance)
The three light swaps also take the true rear wall: our box closes 0.05 m behind the farthest
light placed behind the camera, so a true light reaching farther back would be partly hidden
(docs/generalization.md, "The floor (half A)").
  true_albedo   the room's albedo (--replace-albedo albedo.exr)
  no_grain      without the grain the render adds (--no-grain)
  place_fit     not a composite: how well the user's place and the true place of the lights
                placed in 3D (rect_m) explain the photo. The scene with the true rear wall is
                prepared twice, once as given and once with each rect_m light moved to the true
                rectangle, rendered with one sample and --lights-json: the refinement's data term
                at the start (fit_user_data, fit_true_data: its relative error against the
                decomposition's direct light, intensities solved) and the light fit's robust log
                residual (fit_user_rms_log, fit_true_rms_log). Lower explains the photo better.
and reads the noise over the object (pixels of object_mask.png >= 250 whose row neighbours are too;
the RMS second difference along rows over sqrt 6, sRGB: white noise's standard deviation, the
shading's slope removed): truth_noise (Cycles' own, which no render shares), product_noise (our
render's noise and the grain render.grain tops it up with, to the photo's measured level) and
no_grain_noise; noise_floor = sqrt(truth_noise^2 + product_noise^2), what an independent noise
of these levels alone costs, and bias = sqrt(max(0, product^2 - noise_floor^2)), the rest.
Lights pair with the truth's in order (the harness lists them as truth.json does); a room whose
light count differs from the truth's skips the light swaps.

With --dev the rooms are the six dev rooms of ../shared/scenes (their own photos, half "dev";
--rooms d1,d3 picks some): GEN is made here first, per room the harness's assisted scene
(GEN/ROOM_plain.json), its product render at --spp with its lights (GEN/ROOM_plain_long.png,
GEN/ROOM_plain_lights.json) and GEN/variants/ROOM_plain a link to the room's folder.

Writes OUT/oracle_plain.csv (one row per room: each run's RMSE and adjusted RMSE), OUT/oracle_plain.png
(per room, each run's RMSE) and docs/bench/oracle_plain.md; renders stay in OUT. Each room's row is
kept in OUT/rows/ so that processes can split the rooms (--rows-only writes the union).

usage: bench_oracle_plain.py INLAY_CLI --gen GEN_OUT [--out DIR] [--rooms t01,t07|A|B]
                             [--spp 128] [--runs product,true_power,...] [--rows-only] [--reuse]
                             [--score-only] [--dev]
  --reuse       keep the composites already in OUT (render only the missing ones)
  --score-only  render nothing: score the composites already in OUT (runs split over processes
                and folders, copied together)
"""
import json, os, subprocess, sys, time

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
from bench_error_budget import quad_area, true_lights, with_true_power  # noqa: E402
from bench_floor import true_rear_m  # noqa: E402

PY = "/usr/bin/python3"
RUNS = ["product", "true_rear", "true_power", "true_places", "true_lights", "true_albedo", "no_grain", "more_spp",
        "place_fit"]


def with_true_places(ours, truth):
    """The truth's light rectangles, each with our light's power (same order)."""
    out = []
    for o, t in zip(ours, true_lights(truth)):
        k = quad_area(o["corners"]) / max(quad_area(t["corners"]), 1e-9)
        out.append({"corners": t["corners"], "rgb": [v * k for v in o["rgb"]]})
    return out


def object_noise(room_dir, png):
    """White noise's standard deviation over the object: the RMS second difference along rows
    over sqrt 6 (sRGB; object pixels whose row neighbours are object pixels too)."""
    m = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 250
    img = cv2.imread(png, cv2.IMREAD_COLOR)
    if img is None or img.shape[:2] != m.shape:
        return ""
    t = img.astype(np.float64) / 255.0
    d = (t[:, 2:] - 2 * t[:, 1:-1] + t[:, :-2])[m[:, 2:] & m[:, 1:-1] & m[:, :-2]]
    return round(float(np.sqrt(np.mean(d ** 2) / 6)), 4) if d.size else ""


def noise_readings(row, vdir, pngs):
    """truth_noise, product_noise, no_grain_noise, noise_floor and bias (see the docstring)."""
    row["truth_noise"] = object_noise(vdir, os.path.join(vdir, "truth.png"))
    for name in ("product", "no_grain"):
        if name in pngs:
            row[name + "_noise"] = object_noise(vdir, pngs[name])
    t, o, e = row["truth_noise"], row.get("product_noise", ""), row.get("product_rmse")
    if "" not in (t, o) and e is not None:
        row["noise_floor"] = round(float(np.hypot(t, o)), 4)
        row["bias"] = round(float(np.sqrt(max(0.0, e * e - row["noise_floor"] ** 2))), 4)


def rear_scene(gen, out, room, truth):
    """The benchmark's plain scene with the truth's rear wall (layout.rear_m)."""
    s = json.load(open(os.path.join(gen, room + "_plain.json")))
    s.setdefault("layout", {})["rear_m"] = round(true_rear_m(truth), 4)
    path = os.path.join(out, room + "_rear.json")
    json.dump(s, open(path, "w"), indent=1)
    return path


def run_args(name, room, gen, out, truth, ours):
    """(scene, extra render arguments, samples factor) of one run, or None when it cannot be made."""
    scene = os.path.join(gen, room + "_plain.json")
    vdir = os.path.join(gen, "variants", room + "_plain")
    lights = {"true_power": lambda: with_true_power(ours, truth), "true_places": lambda: with_true_places(ours, truth),
              "true_lights": lambda: true_lights(truth)}
    if name in lights:
        if len(ours) != len(true_lights(truth)):
            return None
        path = os.path.join(out, "%s_%s_lights.json" % (room, name))
        json.dump({"lights": lights[name]()}, open(path, "w"), indent=1)
        return rear_scene(gen, out, room, truth), ["--replace-lights", path], 1
    if name == "true_rear":
        return rear_scene(gen, out, room, truth), [], 1
    extra, factor = {"product": ([], 1), "more_spp": ([], 4), "no_grain": (["--no-grain"], 1),
                     "true_albedo": (["--replace-albedo", os.path.join(vdir, "albedo.exr")], 1)}[name]
    return scene, extra, factor


def place_fit(cli, gen, out, room, truth, row):
    """The place_fit readings (see the docstring) into `row`."""
    rear = json.load(open(rear_scene(gen, out, room, truth)))
    placed = [i for i, L in enumerate(rear.get("lights", [])) if L.get("kind") == "rect_m"]
    tl = true_lights(truth)
    if not placed or len(rear["lights"]) != len(tl):
        return
    moved = json.loads(json.dumps(rear))
    for i in placed:
        moved["lights"][i]["corners"] = tl[i]["corners"]
    for key, doc in (("user", rear), ("true", moved)):
        scene, lights = (os.path.join(out, "%s_place_%s%s" % (room, key, ext)) for ext in (".json", "_lights.json"))
        json.dump(doc, open(scene, "w"), indent=1)
        p = subprocess.run([cli, "render", scene, "-o", os.path.join(out, "%s_place_%s.png" % (room, key)), "--quiet",
                            "--seed", "1", "--spp", "1", "--seconds", "0", "--noise", "0", "--lights-json", lights],
                           capture_output=True, text=True)
        if p.returncode != 0:
            return
        d = json.load(open(lights))
        row["fit_%s_data" % key] = round(d["refinement"]["initial_data_term"], 5)
        row["fit_%s_rms_log" % key] = round(d["fit"]["rms_log"], 5)


def measure_room(cli, tools, gen, out, room, spp, runs, reuse, score_only=False):
    vdir = os.path.join(gen, "variants", room + "_plain")
    truth = json.load(open(os.path.join(vdir, "truth.json")))
    ours = json.load(open(os.path.join(gen, room + "_plain_lights.json")))["refined"]
    row = {"room": room, "half": "dev" if room.startswith("d") else benchlib.half(room), "material": truth["object"]["material"]["type"],
           "lights": "+".join(L["view_status"] for L in truth["lights"]), "spp": spp,
           "true_rear_m": round(true_rear_m(truth), 2)}
    pngs = {}
    if "place_fit" in runs and not score_only:
        place_fit(cli, gen, out, room, truth, row)
    prev = os.path.join(out, "rows", room + ".json")
    if score_only and os.path.exists(prev):  # keep the place_fit readings of an earlier run
        row.update({k: v for k, v in json.load(open(prev)).items() if k.startswith("fit_")})
    for name in [r for r in runs if r != "place_fit"]:
        made = run_args(name, room, gen, out, truth, ours)
        if made is None:
            continue
        scene, extra, factor = made
        png = os.path.join(out, "%s_%s.png" % (room, name))
        long_png = os.path.join(gen, room + "_plain_long.png")
        if name == "product" and not os.path.exists(png) and os.path.exists(long_png) and spp == 128:
            png = long_png  # the benchmark's own --long-spp 128 composite
        if score_only and not os.path.exists(png):
            continue
        if not (reuse and os.path.exists(png)) and png != long_png and not score_only:
            t = time.monotonic()
            p = subprocess.run([cli, "render", scene, "-o", png, "--quiet", "--seed", "1", "--spp", str(spp * factor),
                                "--seconds", "0", "--noise", "0"] + extra, capture_output=True, text=True)
            if p.returncode != 0:
                sys.stderr.write("%s %s failed: %s\n" % (room, name, p.stderr[-400:]))
                continue
            row[name + "_s"] = round(time.monotonic() - t, 1)
        sc = json.loads(subprocess.run([PY, os.path.join(tools, "harness.py"), "score", vdir, png],
                                       capture_output=True, text=True, check=True).stdout)
        row[name + "_rmse"] = round(sc["object_rmse"], 4)
        row[name + "_adjusted"] = round(sc.get("object_rmse_adjusted", float("nan")), 4)
        pngs[name] = png
    noise_readings(row, vdir, pngs)
    return row


def plot(out, rows, runs):
    with benchlib.figure(os.path.join(out, "oracle_plain.png"), 1, 2, figsize=(13, 4),
                         gridspec_kw={"width_ratios": [3, 1]}) as ax:
        if ax is None:
            return
        width = 0.8 / len(runs)
        for i, name in enumerate(runs):
            v = [float(r.get(name + "_rmse") or 0) for r in rows]
            ax[0].bar([j + i * width for j in range(len(rows))], v, width, label=name)
        ax[0].set_xticks([j + 0.4 - width / 2 for j in range(len(rows))])
        ax[0].set_xticklabels([r["room"] for r in rows])
        ax[0].axhline(0.03, color="k", lw=0.6, ls=":")
        ax[0].set_ylabel("object RMSE (sRGB)")
        ax[0].legend(fontsize=7, ncol=4)
        ax[0].set_title("each run's object RMSE (dotted: the target 0.03)", fontsize=9)
        for j, r in enumerate(rows):
            f, b = float(r.get("noise_floor") or 0), float(r.get("bias") or 0)
            ax[1].bar(j, f, 0.6, color="0.7", label="noise floor" if j == 0 else None)
            ax[1].bar(j, b, 0.3, color="C3", label="bias" if j == 0 else None)
        ax[1].set_xticks(range(len(rows)))
        ax[1].set_xticklabels([r["room"] for r in rows], fontsize=7)
        ax[1].axhline(0.03, color="k", lw=0.6, ls=":")
        ax[1].legend(fontsize=7)
        ax[1].set_title("product: noise floor and the rest", fontsize=9)


def dev_rooms(only):
    """(scenes folder, tools folder, dev room names filtered by `only`, comma-separated prefixes)."""
    shared = benchlib.shared_dir()
    sdir, tools = os.path.join(shared, "scenes"), os.path.join(shared, "tools")
    names = sorted(n for n in os.listdir(sdir) if os.path.isfile(os.path.join(sdir, n, "truth.json")))
    return sdir, tools, [n for n in names if not only or only in ("A", "B")
                         or any(n.startswith(p) for p in only.split(","))]


def prepare_dev(cli, tools, sdir, gen, room, spp):
    """The benchmark's layout for a dev room (see the docstring); False when a step failed."""
    os.makedirs(os.path.join(gen, "variants"), exist_ok=True)
    link = os.path.join(gen, "variants", room + "_plain")
    if not os.path.exists(link):
        os.symlink(os.path.join(sdir, room), link)
    scene, png = os.path.join(gen, room + "_plain.json"), os.path.join(gen, room + "_plain_long.png")
    if os.path.exists(png):
        return True
    if subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", os.path.join(sdir, room), scene]).returncode != 0:
        return False
    p = subprocess.run([cli, "render", scene, "-o", png, "--quiet", "--seed", "1", "--spp", str(spp), "--seconds", "0",
                        "--noise", "0", "--lights-json", os.path.join(gen, room + "_plain_lights.json")],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write("%s: the product render failed: %s\n" % (room, p.stderr[-400:]))
    return p.returncode == 0


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    gen = os.path.abspath(opt("--gen", os.path.join(HERE, "out")))
    dev = "--dev" in sys.argv[1:]
    sdir, tools, names = (dev_rooms if dev else benchlib.train_rooms_of)(opt("--rooms", "" if dev else "A"))
    runs = opt("--runs", ",".join(RUNS)).split(",")
    unknown = [r for r in runs if r not in RUNS]
    if unknown:
        sys.stderr.write("bench_oracle_plain.py: --runs: unknown run %s (known: %s)\n" % (unknown[0], ",".join(RUNS)))
        return 2
    rows_dir = os.path.join(out, "rows")
    os.makedirs(rows_dir, exist_ok=True)
    if "--rows-only" not in sys.argv[1:]:
        for room in names:
            if dev and not prepare_dev(cli, tools, sdir, gen, room, int(opt("--spp", "128"))):
                continue
            row = measure_room(cli, tools, gen, out, room, int(opt("--spp", "128")), runs, "--reuse" in sys.argv[1:],
                               "--score-only" in sys.argv[1:])
            json.dump(row, open(os.path.join(rows_dir, room + ".json"), "w"))
            print(json.dumps(row), flush=True)
    rows = benchlib.read_rows(rows_dir)
    if not rows:
        return 1
    cols = ["room", "half", "material", "lights", "spp", "true_rear_m"] + [n + k for n in RUNS[:-1]
                                                                           for k in ("_rmse", "_adjusted")]
    cols += ["truth_noise", "product_noise", "no_grain_noise", "noise_floor", "bias"]
    cols += ["fit_user_data", "fit_true_data", "fit_user_rms_log", "fit_true_rms_log"]
    benchlib.write_csv(os.path.join(out, "oracle_plain.csv"), rows, table="oracle_plain",
                       columns=[c for c in cols if any(c in r for r in rows)])
    plot(out, rows, [n for n in RUNS[:-1] if any(n + "_rmse" in r for r in rows)])
    print("wrote", os.path.join(out, "oracle_plain.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
