#!/usr/bin/python3
"""Glass and mirror objects: the inserted object's error on the rooms of ../shared/scenes-train
whose object is glass or a mirror, two builds side by side, with the oracles that take the
error apart.

Per room the harness writes the assisted scene (harness.py scene, the room's own sRGB photo) and
each run renders it with seed 1 and exactly the given samples (uniform), scored by harness.py
score (object RMSE, adjusted RMSE and the RMSE around the object, sRGB [0,1]):
  base            the baseline build (--baseline-cli), everything estimated, --spp samples
  estimated       this build, everything estimated, --spp samples (the benchmark's number),
                  with --estimated-args "ARGS" appended if given (e.g. "--caustic-radius 0.1")
  caustic         estimated with the caustic photon pass on (--caustic-photons 200000, or
                  --caustic-args "ARGS" instead, e.g. "--caustic-photons 800000")
  estimated_long  this build, everything estimated, --long-spp samples, --no-grain: the product's
                  error without most of the render noise
  all_true_long   this build with the truth's lights (--replace-lights) and albedo
                  (--replace-albedo), the truth's rear wall (layout.rear_m), --no-grain,
                  --long-spp samples, the product's clamp of indirect light
  cycles_clamp    all_true_long with the truth's own clamp (Cycles' clamp indirect x exposure)
The budget, as shares of estimated's squared error E^2: noise E^2 - E(estimated_long)^2, the
lights and albedo E(estimated_long)^2 - E(all_true_long)^2, the floor E(all_true_long)^2 (the
renderer against Cycles with everything swappable true: its clamp, its caustics, the room the
object shows), of which clamp E(all_true_long)^2 - E(cycles_clamp)^2.

Writes OUT/glass.csv (a row per room), OUT/glass.png (object RMSE per room and run),
OUT/glass_crops.png (per room, around the object: the truth, then each run at --spp, and below
each its difference to the truth x4) and keeps every composite in OUT (--reuse keeps those
already there).

usage: bench_glass.py INLAY_CLI [--baseline-cli OTHER_CLI] [--out DIR] [--rooms t05,t13,t02,t12]
                      [--spp 16] [--long-spp 128] [--runs base,estimated,...] [--reuse]
                      [--estimated-args "ARGS"] [--caustic-args "ARGS"]
"""
import json, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_error_budget as budget  # noqa: E402
import bench_floor as floor  # noqa: E402

PY = "/usr/bin/python3"
RUNS = ["base", "estimated", "caustic", "estimated_long", "all_true_long", "cycles_clamp"]


def scenes_of(tools, room_dir, out, room, truth):
    """The room's assisted scene, the same with the truth's rear wall, and the true lights file."""
    p = lambda name: os.path.join(out, "%s_%s" % (room, name))
    subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", room_dir, p("scene.json"), "--seconds", "100000"],
                   check=True)
    s = json.load(open(p("scene.json")))
    s.setdefault("layout", {})["rear_m"] = round(floor.true_rear_m(truth), 4)
    json.dump(s, open(p("scene_rear.json"), "w"), indent=1)
    json.dump({"lights": budget.true_lights(truth)}, open(p("true_lights.json"), "w"), indent=1)
    return p("scene.json"), p("scene_rear.json"), p("true_lights.json")


def measure_room(cli, base_cli, tools, room_dir, out, o, log):
    room = os.path.basename(room_dir)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    scene, scene_rear, lights = scenes_of(tools, room_dir, out, room, truth)
    oracle = ["--replace-lights", lights, "--replace-albedo", os.path.join(room_dir, "albedo.exr"), "--no-grain"]
    clamp = float(truth.get("render", {}).get("clamp", {}).get("indirect", 10.0)) * truth["exposure"]["scale"]
    runs = {"base": (base_cli, scene, o["spp"], []), "estimated": (cli, scene, o["spp"], o["estimated_args"]),
            "caustic": (cli, scene, o["spp"], o["caustic_args"]),
            "estimated_long": (cli, scene, o["long_spp"], ["--no-grain"]),
            "all_true_long": (cli, scene_rear, o["long_spp"], oracle),
            "cycles_clamp": (cli, scene_rear, o["long_spp"], oracle + ["--clamp-indirect", "%.6g" % clamp])}
    row = {"room": room, "half": benchlib.half(room), "material": truth["object"]["material"]["type"],
           "object": truth["object"]["type"], "support": truth["object"]["support"]}
    for name, (c, sf, spp, extra) in runs.items():
        if c is None or name not in o["runs"]:
            continue
        png = os.path.join(out, "%s_%s.png" % (room, name))
        t = budget.render(c, sf, png, spp, extra, log, o["reuse"])
        if t is None:
            continue
        sc = budget.score(tools, room_dir, png)
        row[name + "_rmse"] = round(sc["object_rmse"], 4)
        row[name + "_adjusted"] = round(sc["object_rmse_adjusted"], 4)
        row[name + "_around"] = round(sc["around_rmse"], 4)
        row["around_do_nothing"] = round(sc["around_rmse_do_nothing"], 4)
        if t > 0:
            row[name + "_s"] = round(t, 1)
    return shares(row)


def shares(row):
    """The budget's shares of estimated's squared error (see the docstring)."""
    g = lambda k: row.get(k + "_rmse")
    e, lg, tr, cc = g("estimated"), g("estimated_long"), g("all_true_long"), g("cycles_clamp")
    if e and lg is not None:
        row["share_noise"] = round((e * e - lg * lg) / (e * e), 3)
    if e and lg is not None and tr is not None:
        row["share_lights_albedo"] = round((lg * lg - tr * tr) / (e * e), 3)
    if e and tr is not None:
        row["share_floor"] = round(tr * tr / (e * e), 3)
    if e and tr is not None and cc is not None:
        row["share_clamp"] = round((tr * tr - cc * cc) / (e * e), 3)
    return row


def plot(out, rows, runs):
    with benchlib.figure(os.path.join(out, "glass.png"), 1, 1, figsize=(8, 4)) as ax:
        if ax is None:
            return
        w = 0.8 / max(1, len(runs))
        for k, run in enumerate(runs):
            v = [r.get(run + "_rmse") or 0 for r in rows]
            ax.bar([i + (k - (len(runs) - 1) / 2) * w for i in range(len(rows))], v, w, label=run)
        ax.set_xticks(range(len(rows)))
        ax.set_xticklabels(["%s (%s) %s %s" % (r["room"], r["half"], r["material"], r["object"]) for r in rows],
                           fontsize=8)
        ax.set_ylabel("object RMSE (sRGB)")
        ax.legend(fontsize=8)


def crops(out, sdir, names, runs):
    """Per room: the truth and each run's composite around the object (its projected box grown by
    half its size), and below each the difference to the truth x4 (grey: none)."""
    import numpy as np
    from PIL import Image
    with benchlib.figure(os.path.join(out, "glass_crops.png"), 2 * len(names), 1 + len(runs),
                         figsize=(2.2 * (1 + len(runs)), 2.0 * 2 * len(names)), squeeze=False) as ax:
        if ax is None:
            return
        for i, room in enumerate(names):
            truth_json = json.load(open(os.path.join(sdir, room, "truth.json")))
            x0, y0, x1, y1 = truth_json["object"]["projected_bbox_2d"]
            gx, gy = 0.5 * (x1 - x0), 0.5 * (y1 - y0)
            truth = np.asarray(Image.open(os.path.join(sdir, room, "truth.png")).convert("RGB"), float) / 255
            h, w = truth.shape[:2]
            box = (max(0, int(x0 - gx)), max(0, int(y0 - gy)), min(w, int(x1 + gx)), min(h, int(y1 + gy)))
            cut = lambda im: im[box[1]:box[3], box[0]:box[2]]
            images = [("truth", truth)]
            for run in runs:
                png = os.path.join(out, "%s_%s.png" % (room, run))
                if os.path.exists(png):
                    images.append((run, np.asarray(Image.open(png).convert("RGB"), float) / 255))
            for k in range(1 + len(runs)):
                for a in (ax[2 * i][k], ax[2 * i + 1][k]):
                    a.axis("off")
                if k >= len(images):
                    continue
                name, im = images[k]
                ax[2 * i][k].imshow(np.clip(cut(im), 0, 1))
                ax[2 * i][k].set_title("%s %s" % (room, name), fontsize=8)
                if k > 0:
                    ax[2 * i + 1][k].imshow(np.clip(0.5 + 4 * (cut(im) - cut(truth)), 0, 1))


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    base = opt("--baseline-cli", None)
    o = {"spp": int(opt("--spp", "16")), "long_spp": int(opt("--long-spp", "128")),
         "runs": opt("--runs", ",".join(RUNS)).split(","), "reuse": "--reuse" in sys.argv[1:],
         "estimated_args": opt("--estimated-args", "").split(),
         "caustic_args": opt("--caustic-args", "--caustic-photons 200000").split()}
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "t05,t13,t02,t12"))
    rows = []
    with open(os.path.join(out, "failures.log"), "a") as log:
        for room in names:
            rows.append(measure_room(os.path.abspath(cli), base and os.path.abspath(base), tools,
                                     os.path.join(sdir, room), out, o, log))
            print(json.dumps(rows[-1]), flush=True)
            benchlib.write_csv(os.path.join(out, "glass.csv"), rows)
    plot(out, rows, [r for r in RUNS if r in o["runs"]])
    crops(out, sdir, names, [r for r in ["base", "estimated", "caustic"] if r in o["runs"]])
    print("wrote", os.path.join(out, "glass.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
