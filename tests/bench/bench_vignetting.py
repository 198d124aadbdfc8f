#!/usr/bin/python3
"""Does the camera's vignetting (and its tone curve) matter for the inserted object's error?

Every room of ../shared/scenes-train (or --rooms) is re-photographed through --seeds random
cameras (../shared/tools/camera_variants.py --seed 1000 * seed + room number, the cameras of
bench_response.py), and each variant is inserted by `inlay-cli render` (harness.py's assisted
scene, --seconds S, or --spp N samples per pixel whatever the time: the same samples for every
reading) under these readings of the photo:

  srgb              photo.png read as sRGB (camera.response "srgb", what "auto" keeps on these
                    rooms); its 8-bit composite is scored as written.
  srgb_exr          the same radiance handed to Inlay as a linear EXR (sRGB-decoded codes), the
                    composite layer encoded back with sRGB here: the control for the rows below,
                    which go through the same path (an EXR photo gets no grain).
  srgb_devignetted  the sRGB-decoded codes divided by the camera's true vignetting V(x, y) (an
                    oracle: camera_variant.json, read here only), the composite multiplied by V
                    before the sRGB encoding: out = f(V (f^-1(photo) / V + with - without)).
  true_curve        the codes decoded by the camera's true curve (normalised so code 254.5 is
                    1.0), the composite encoded back by it: the right response, vignetting left.
  true_devignetted  the true curve and the true vignetting: both corrected (the oracle's best).

So srgb_devignetted against srgb_exr says what correcting the vignetting would gain at most, and
true_curve / true_devignetted what a right response would gain with and without it.

Rows go to OUT/vignetting.csv (object RMSE, adjusted, surroundings, the camera's curve and
vignetting, render seconds), medians per half and reading to OUT/vignetting_summary.csv, and
OUT/vignetting.png plots the object RMSE of each reading against srgb_exr per variant (left)
and against the camera's vignetting (right). Half A = odd rooms, half B = even rooms.

--estimate (instead of the readings): `inlay-cli decompose` on each variant's photo (read as
sRGB) prints the vignetting its light fit's residual shows (LightingEstimate::vignetting); rows
with the camera's true vignetting go to OUT/vignetting_estimate.csv, the plot (estimate against
truth) to OUT/vignetting_estimate.png.

usage: bench_vignetting.py INLAY_CLI [--out DIR] [--seeds 1] [--rooms t01,t03]
                           [--readings srgb,srgb_exr,...] [--seconds 10 | --spp N] [--estimate]
"""
import json, os, statistics, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response as br  # noqa: E402

READINGS = ["srgb", "srgb_exr", "srgb_devignetted", "true_curve", "true_devignetted"]


def srgb_decode(y):
    return np.where(y <= 0.04045, y / 12.92, ((y + 0.055) / 1.055) ** 2.4)


def srgb_encode(x):
    x = np.clip(x, 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def vignette(cam, h, w):
    """camera_variants.py's vignetting: 1 - v r^2, r^2 over the corner's."""
    yy, xx = np.mgrid[0:h, 0:w]
    r2 = ((xx + 0.5 - w / 2) ** 2 + (yy + 0.5 - h / 2) ** 2) / ((w / 2) ** 2 + (h / 2) ** 2)
    return 1.0 - cam.get("vignetting", 0.0) * r2


def codecs(cam, reading):
    """(decode: codes -> linear, encode: linear -> [0,1]) of a reading."""
    if reading.startswith("true") and cam["curve"] != "srgb":
        white = float(br.true_inverse(cam, np.array([254.5]))[0])
        table = br.true_inverse(cam, np.clip(np.arange(256.0), 0.5, 254.5)) / white
        table[0] = 0.0
        return (lambda codes: table[codes]), (lambda x: br.tone(np.maximum(x, 0) * white, cam))
    return (lambda codes: srgb_decode(codes / 255.0)), srgb_encode


def write_exr(path, rgb):
    import OpenImageIO as oiio
    spec = oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, oiio.FLOAT)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), np.ascontiguousarray(rgb.astype(np.float32)))
    if not buf.write(path):
        raise RuntimeError(buf.geterror())


def read_layer(path, name):
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(path)
    try:
        for sub in range(64):
            if not inp.seek_subimage(sub, 0):
                break
            spec = inp.spec()
            if spec.getattribute("name") == name or any(c.startswith(name + ".") for c in spec.channelnames):
                px = inp.read_image(oiio.FLOAT)
                return np.asarray(px)[:, :, :3].astype(np.float64)
    finally:
        inp.close()
    raise RuntimeError("no layer %s in %s" % (name, path))


def run_one(cli, harness, d, cam, reading, seconds, spp, work):
    import cv2
    os.makedirs(work, exist_ok=True)
    sf = os.path.join(work, "scene.json")
    subprocess.run([sys.executable, harness, "scene", d, sf, "--seconds", str(seconds)], check=True)
    j = json.load(open(sf))
    if spp:  # a fixed sample count: the readings differ by their photo, not by the machine's load
        j["render"].update({"spp": spp, "seconds": 1e6, "noise": 0})
    comp = os.path.join(work, "composite.png")
    if reading == "srgb":
        j["camera"]["response"] = "srgb"
        json.dump(j, open(sf, "w"), indent=1)
        r = subprocess.run([cli, "render", sf, "-o", comp, "--quiet"], capture_output=True, text=True)
    else:
        codes = cv2.imread(os.path.join(d, "photo.png"), cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.int64)
        h, w = codes.shape[:2]
        decode, encode = codecs(cam, reading)
        V = vignette(cam, h, w) if reading.endswith("devignetted") else np.ones((h, w))
        exr = os.path.join(work, "photo.exr")
        write_exr(exr, decode(codes) / V[:, :, None])
        j["photo"] = exr
        json.dump(j, open(sf, "w"), indent=1)
        layers = os.path.join(work, "layers.exr")
        r = subprocess.run([cli, "render", sf, "-o", os.path.join(work, "raw.png"), "--layers", layers,
                            "--quiet"], capture_output=True, text=True)
        if r.returncode == 0:
            out = encode(read_layer(layers, "composite") * V[:, :, None])
            cv2.imwrite(comp, np.round(np.clip(out, 0, 1) * 255).astype(np.uint8)[:, :, ::-1])
    if r.returncode != 0:
        sys.stderr.write(r.stderr[-400:])
        return None
    return json.loads(subprocess.run([sys.executable, harness, "score", d, comp], capture_output=True,
                                     text=True, check=True).stdout)


def estimate_rows(cli, harness, variants, out):
    """The vignetting the light fit's residual shows, against the camera's."""
    import re
    rows = []
    for room, seed, d in variants:
        cam = json.load(open(os.path.join(d, "camera_variant.json")))
        work = os.path.join(out, "estimate", "%s-s%s" % (room, seed))
        os.makedirs(work, exist_ok=True)
        sf = os.path.join(work, "scene.json")
        subprocess.run([sys.executable, harness, "scene", d, sf], check=True, capture_output=True)
        j = json.load(open(sf))
        j["camera"]["response"] = "srgb"
        json.dump(j, open(sf, "w"), indent=1)
        r = subprocess.run([cli, "decompose", sf, "--albedo", os.path.join(work, "albedo.exr")],
                           capture_output=True, text=True)
        m = re.search(r"vignetting as the residual shows it ([0-9.]+) \(residual x ([0-9.]+)\)", r.stderr)
        if r.returncode != 0 or not m:
            sys.stderr.write(r.stderr[-400:])
            continue
        rows.append({"room": room, "seed": seed, "half": "A" if int(room[1:]) % 2 else "B",
                     "curve": cam["curve"], "true_vignetting": round(cam.get("vignetting", 0.0), 3),
                     "estimated_vignetting": float(m.group(1)), "residual_ratio": float(m.group(2))})
        print(json.dumps(rows[-1]), flush=True)
        benchlib.write_csv(os.path.join(out, "vignetting_estimate.csv"), rows)
    with benchlib.figure(os.path.join(out, "vignetting_estimate.png"), figsize=(5, 4.5)) as ax:
        if ax is not None and rows:
            for half in ("A", "B"):
                h = [r for r in rows if r["half"] == half]
                ax.scatter([r["true_vignetting"] for r in h], [r["estimated_vignetting"] for r in h],
                           label="half " + half, s=20)
            ax.plot([0, 0.6], [0, 0.6], "k:", lw=0.8)
            ax.set_xlabel("camera's vignetting (camera_variant.json)")
            ax.set_ylabel("estimated from the light fit's residual")
            ax.legend()
    return rows


def summarise(rows, readings):
    out = []
    for half in ("A", "B"):
        for reading in readings:
            v = [r["object_rmse"] for r in rows if r["half"] == half and r["reading"] == reading]
            if v:
                out.append({"half": half, "reading": reading, "n": len(v),
                            "object_rmse_median": round(statistics.median(v), 4),
                            "object_rmse_mean": round(statistics.mean(v), 4)})
    return out


def plot(path, rows, readings):
    with benchlib.figure(path, 1, 2, figsize=(11, 4.5)) as ax:
        if ax is None:
            return
        base = {(r["room"], r["seed"]): r["object_rmse"] for r in rows if r["reading"] == "srgb_exr"}
        for reading in readings:
            pts = [(base[(r["room"], r["seed"])], r["object_rmse"], r["vignetting"]) for r in rows
                   if r["reading"] == reading and (r["room"], r["seed"]) in base]
            if not pts:
                continue
            ax[0].scatter([p[0] for p in pts], [p[1] for p in pts], label=reading, s=18)
            ax[1].scatter([p[2] for p in pts], [p[1] for p in pts], label=reading, s=18)
        lim = max([r["object_rmse"] for r in rows] + [0.01])
        ax[0].plot([0, lim], [0, lim], "k:", lw=0.8)
        ax[0].set_xlabel("object RMSE, srgb_exr (control)")
        ax[0].set_ylabel("object RMSE")
        ax[1].set_xlabel("camera vignetting (light lost at the corners)")
        ax[1].set_ylabel("object RMSE")
        ax[0].legend(fontsize=7)
        ax[0].set_title("each reading against the control")
        ax[1].set_title("against the camera's vignetting")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    train, harness, rooms = benchlib.train_rooms(opt, out)
    seeds = opt("--seeds", "1").split(",")
    readings = opt("--readings", ",".join(READINGS)).split(",")
    seconds = float(opt("--seconds", "10"))
    spp = int(opt("--spp", "0"))
    variants = br.make_variants(train, rooms, seeds, os.path.join(out, "variants"))
    if "--estimate" in sys.argv:
        estimate_rows(cli, harness, variants, out)
        return 0
    rows = []
    csv_path = os.path.join(out, "vignetting.csv")
    for room, seed, d in variants:
        cam = json.load(open(os.path.join(d, "camera_variant.json")))
        half = "A" if int(room[1:]) % 2 == 1 else "B"
        for reading in readings:
            work = os.path.join(out, "runs", "%s-s%s-%s" % (room, seed, reading))
            score = run_one(cli, harness, d, cam, reading, seconds, spp, work)
            if score is None:
                continue
            rows.append({"room": room, "seed": seed, "half": half, "curve": cam["curve"],
                         "vignetting": round(cam.get("vignetting", 0.0), 3), "reading": reading,
                         "object_rmse": round(score["object_rmse"], 4),
                         "object_rmse_adjusted": round(score["object_rmse_adjusted"], 4),
                         "around_rmse": round(score["around_rmse"], 4),
                         "around_rmse_do_nothing": round(score["around_rmse_do_nothing"], 4)})
            print(json.dumps(rows[-1]), flush=True)
            benchlib.write_csv(csv_path, rows)
    summary = summarise(rows, readings)
    benchlib.write_csv(os.path.join(out, "vignetting_summary.csv"), summary, table="vignetting")
    for s in summary:
        print(s)
    plot(os.path.join(out, "vignetting.png"), rows, readings)
    return 0


if __name__ == "__main__":
    sys.exit(main())
