#!/usr/bin/python3
"""The object's surroundings (its shadow and bounce light) on the training rooms: why the
composite there can score worse than the untouched photo. For each room of ../shared/scenes-train
the harness's assisted scene is rendered with --layers at each sample count of --spp (uniform
sampling, seed 1) and once more with --denoise at the first one; in the harness's `around` region
(near the object, outside its dilated mask) it reports:
  around_rmse           harness.py score (sRGB [0,1]) next to around_rmse_do_nothing (the photo)
  effect_ratio          sum of our effect (with - without, linear) over the truth's
                        (truth_linear x exposure - photo_linear x exposure)
  effect_corr           their correlation per pixel (noise lowers it; a wrong shadow lowers it at
                        every sample count)
  change_rms            RMS of (composite - photo) in sRGB: our effect plus our render noise
  truth_change_rms      RMS of (truth - photo) in sRGB: what there is to render
A composite worse than doing nothing at few samples and better at more is render noise; one that
stays worse is a wrong shadow, bounce or caustic.

usage: bench_surroundings.py INLAY_CLI [--out DIR] [--rooms t01,t05,d4,...] [--spp 16,128]
                             [--no-denoise] [--rescore] [--baseline OTHER_OUT]
  --rooms     training rooms (t01), dev rooms by their prefix (d4: ../shared/scenes/d4_*) or room
              folders by path (a camera_variants.py variant of a room)
  --rescore   reuse the composites and layers already in OUT (only re-score)
  --baseline  another build's OUT: also writes OUT/surroundings_vs_baseline.csv/.png (around and
              object RMSE per room and sample count, baseline -> this run, and doing nothing)
Writes OUT/surroundings.csv and OUT/surroundings.png (around RMSE per room and sample count
against doing nothing); prints the table.
"""
import json, os, subprocess, sys, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"


def read_rgb(path):
    """(H x W x 3 float) of an image file; EXR through OpenImageIO."""
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise SystemExit("cannot read " + path)
    spec = inp.spec()
    px = np.asarray(inp.read_image(0, spec.nchannels, "float")).reshape(spec.height, spec.width, spec.nchannels)
    inp.close()
    return px, spec.channelnames


def layers(path):
    px, names = read_rgb(path)
    groups = {}
    for i, ch in enumerate(names):
        groups.setdefault(ch.rsplit(".", 1)[0] if "." in ch else "", []).append(i)
    return {k: px[..., v] for k, v in groups.items()}


def around_region(harness, room_dir):
    """The harness's `around` mask (its own definition, reproduced from harness.score)."""
    import cv2
    t = harness.load(room_dir)
    mask = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    x0, y0, x1, y1 = t["object"]["projected_bbox_2d"]
    w, h = x1 - x0, y1 - y0
    H, W = mask.shape
    near = np.zeros_like(mask)
    near[max(0, int(y0 - h)):min(H, int(y1 + h)), max(0, int(x0 - 1.5 * w)):min(W, int(x1 + 1.5 * w))] = True
    return near & ~cv2.dilate(mask.astype(np.uint8), np.ones((5, 5), np.uint8)).astype(bool)


def measure(cli, harness, room_dir, scene, out, spp, denoise, rescore):
    room = os.path.basename(room_dir)
    stem = os.path.join(out, "%s_%d%s" % (room, spp, "_denoised" if denoise else ""))
    row = {"room": room, "spp": spp, "denoise": denoise}
    if not (rescore and os.path.exists(stem + ".png") and os.path.exists(stem + ".exr")):
        cmd = [cli, "render", scene, "-o", stem + ".png", "--quiet", "--seed", "1", "--spp", str(spp), "--seconds",
               "0", "--noise", "0", "--layers", stem + ".exr"] + (["--denoise"] if denoise else [])
        t = time.monotonic()
        p = subprocess.run(cmd, capture_output=True, text=True)
        row["render_wall_s"] = round(time.monotonic() - t, 1)
        if p.returncode != 0:
            row["error"] = p.stderr.strip()[-300:]
            return row
    s = harness.score(room_dir, stem + ".png")
    row.update({k: round(s[k], 4) for k in ("around_rmse", "around_rmse_do_nothing", "object_rmse")})
    around = around_region(harness, room_dir)
    scale = harness.load(room_dir)["exposure"]["scale"]
    truth = read_rgb(os.path.join(room_dir, "truth_linear.exr"))[0][..., :3] * scale
    photo = read_rgb(os.path.join(room_dir, "photo_linear.exr"))[0][..., :3] * scale
    lay = layers(stem + ".exr")
    te = (truth - photo)[around]
    oe = (lay["with_objects"][..., :3] - lay["without_objects"][..., :3])[around]
    row["effect_ratio"] = round(float(oe.sum() / te.sum()), 3) if abs(te.sum()) > 1e-9 else ""
    row["effect_corr"] = round(float(np.corrcoef(oe.ravel(), te.ravel())[0, 1]), 3)
    comp8, truth8, photo8 = (harness.read8(p) for p in (stem + ".png", os.path.join(room_dir, "truth.png"),
                                                         os.path.join(room_dir, "photo.png")))
    row["change_rms"] = round(float(np.sqrt(((comp8 - photo8)[around] ** 2).mean())), 4)
    row["truth_change_rms"] = round(float(np.sqrt(((truth8 - photo8)[around] ** 2).mean())), 4)
    return row


def plot(out, rows):
    rooms = sorted({r["room"] for r in rows})
    with benchlib.figure(os.path.join(out, "surroundings.png"), 1, 1, figsize=(8, 4)) as ax:
        if ax is None:
            return
        kinds = sorted({(r["spp"], r["denoise"]) for r in rows})
        width = 0.8 / (len(kinds) + 1)
        for k, (spp, dn) in enumerate(kinds):
            v = [next((r.get("around_rmse", np.nan) for r in rows if r["room"] == room and r["spp"] == spp
                       and r["denoise"] == dn), np.nan) for room in rooms]
            ax.bar(np.arange(len(rooms)) + k * width, v, width, label="%d spp%s" % (spp, ", denoised" if dn else ""))
        nothing = [next((r.get("around_rmse_do_nothing", np.nan) for r in rows if r["room"] == room), np.nan)
                   for room in rooms]
        ax.bar(np.arange(len(rooms)) + len(kinds) * width, nothing, width, color="grey", label="do nothing")
        ax.set_xticks(np.arange(len(rooms)) + 0.4 - width / 2)
        ax.set_xticklabels(rooms)
        ax.set_ylabel("around RMSE (sRGB)")
        ax.set_title("surroundings: composite against the untouched photo")
        ax.legend(fontsize=8)


def room_directory(shared, sdir, room):
    """A training room (t04) under scenes-train, a dev room (d4) under scenes by its prefix, or a
    room folder given by its path (a camera_variants.py variant)."""
    if os.path.isdir(room):
        return os.path.abspath(room)
    if room.startswith("d"):
        dev = os.path.join(shared, "scenes")
        for name in sorted(os.listdir(dev)):
            if name.split("_")[0] == room:
                return os.path.join(dev, name)
        raise SystemExit("no dev room %s under %s" % (room, dev))
    return os.path.join(sdir, room)


def compare(out, rows, baseline_dir):
    """This run's rows against another build's surroundings.csv: a CSV and a two-panel plot."""
    base = {(r["room"], int(r["spp"]), r["denoise"] == "True"): r
            for r in benchlib.read_csv(os.path.join(baseline_dir, "surroundings.csv"))}
    table = []
    for r in rows:
        b = base.get((r["room"], int(r["spp"]), bool(r["denoise"])))
        if b is None or "around_rmse" not in r:
            continue
        table.append({"room": r["room"], "spp": r["spp"], "denoise": r["denoise"],
                      "around_baseline": float(b["around_rmse"]), "around": r["around_rmse"],
                      "around_do_nothing": r["around_rmse_do_nothing"],
                      "object_baseline": float(b["object_rmse"]), "object": r["object_rmse"],
                      "render_wall_s_baseline": b.get("render_wall_s", ""),
                      "render_wall_s": r.get("render_wall_s", "")})
    benchlib.write_csv(os.path.join(out, "surroundings_vs_baseline.csv"), table)
    with benchlib.figure(os.path.join(out, "surroundings_vs_baseline.png"), 1, 2, figsize=(11, 4)) as axes:
        if axes is None:
            return table
        labels = ["%s\n%d spp" % (t["room"].split("_")[0], t["spp"]) for t in table]
        x = np.arange(len(table))
        for ax, key, title in ((axes[0], "around", "around the object"), (axes[1], "object", "the object")):
            ax.bar(x - 0.27, [t[key + "_baseline"] for t in table], 0.27, label="baseline")
            ax.bar(x, [t[key] for t in table], 0.27, label="this build")
            if key == "around":
                ax.bar(x + 0.27, [t["around_do_nothing"] for t in table], 0.27, color="grey",
                       label="do nothing")
            ax.set_xticks(x)
            ax.set_xticklabels(labels, fontsize=8)
            ax.set_ylabel("RMSE (sRGB)")
            ax.set_title(title)
            ax.legend(fontsize=8)
    return table


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    shared = benchlib.shared_dir()
    sdir, tools = os.path.join(shared, "scenes-train"), os.path.join(shared, "tools")
    if not os.path.isdir(sdir):
        print("skipped: no ../shared/scenes-train")
        return
    sys.path.insert(0, tools)
    import harness  # noqa: E402 (../shared/tools)
    rooms = opt("--rooms", "t01,t05,t07,t13").split(",")
    spps = [int(s) for s in opt("--spp", "16,128").split(",")]
    rows = []
    for room in rooms:
        room_dir = room_directory(shared, sdir, room)
        scene = os.path.join(out, room + ".json")
        subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", room_dir, scene], check=True,
                       capture_output=True)
        runs = [(s, False) for s in spps] + ([] if "--no-denoise" in sys.argv else [(spps[0], True)])
        for spp, dn in runs:
            rows.append(measure(cli, harness, room_dir, scene, out, spp, dn, "--rescore" in sys.argv))
            print(json.dumps(rows[-1]), flush=True)
    benchlib.write_csv(os.path.join(out, "surroundings.csv"), rows)
    plot(out, rows)
    print("| room | spp | denoised | around | do nothing | effect ratio | effect corr | change rms | truth change rms |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % tuple(
            r.get(k, "") for k in ("room", "spp", "denoise", "around_rmse", "around_rmse_do_nothing", "effect_ratio",
                                   "effect_corr", "change_rms", "truth_change_rms")))
    if opt("--baseline", None):
        print("\n| room | spp | around: baseline -> this | do nothing | object: baseline -> this |")
        print("|---|---|---|---|---|")
        for t in compare(out, rows, opt("--baseline", None)):
            print("| %s | %d | %.4f -> %.4f | %.4f | %.4f -> %.4f |" % (
                t["room"], t["spp"], t["around_baseline"], t["around"], t["around_do_nothing"],
                t["object_baseline"], t["object"]))


if __name__ == "__main__":
    main()
