#!/usr/bin/python3
"""The inserted object's error in the photo's codes and in linear radiance, per variant of
bench_generalization.py runs (e.g. --oracle-curve runs, where the curve is known).

The harness scores the object in 8-bit codes. A camera whose curve is steeper than sRGB's turns
the same relative error of the render into more codes, so a code RMSE that is larger under a
camera does not say whether the light fit did worse. This script decodes the composite and the
truth with the response each scene used (camera.response: a toe_shoulder member, or sRGB) and
measures, over the object's pixels with truth codes 6..249, the log of composite over truth:
its mean (the object too bright > 0, too dark < 0: the lights' and albedo's scale) and its RMS.
It also counts each photo's pixels outside the lights' outlines (dilated by 2 px, as the
pipeline's mask) at codes 245 and up, and their share of the decoded radiance: the highlights a
long shoulder decodes far above the rest.

Writes OUT/linear_error.csv (one row per variant) and OUT/linear_error.png (left: code RMSE
against the log RMS, plain photos and each camera; right: the log mean per room, plain and
cameras); prints the medians per half and camera kind.

usage: bench_linear_error.py RUN_DIR[,RUN_DIR...] [--out DIR]
"""
import json, os, statistics, sys

import numpy as np
import cv2

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response as br  # noqa: E402


def decode(codes, response):
    """Radiance of 8-bit codes under a scene's camera.response (sRGB unless a toe_shoulder)."""
    if isinstance(response, dict) and response.get("family") == "toe_shoulder":
        return br.family_inverse(codes.astype(np.float64), response.get("power", 1.0), response.get("toe", 0.0),
                                 response.get("shoulder", 0.0))
    return br.family_inverse(codes.astype(np.float64), 1.0, 0.0, 0.0)


def light_mask(scene, shape):
    mask = np.zeros(shape, np.uint8)
    for light in scene.get("lights", []):
        if light.get("kind") == "polygon_px":
            cv2.fillPoly(mask, [np.round(np.array(light["points"])).astype(np.int32)], 1)
    return cv2.dilate(mask, np.ones((5, 5), np.uint8)) > 0


def measure(run, tag):
    vdir = os.path.join(run, "variants", tag)
    scene = json.load(open(os.path.join(run, tag + ".json")))
    response = scene.get("camera", {}).get("response", "auto")
    read = lambda p: cv2.imread(p)[:, :, ::-1]
    comp, truth, photo = read(os.path.join(run, tag + ".png")), read(os.path.join(vdir, "truth.png")), \
        read(os.path.join(vdir, "photo.png"))
    m = cv2.imread(os.path.join(vdir, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    ok = (truth[m] > 5) & (truth[m] < 250)
    lr = np.log(np.maximum(decode(comp[m], response), 1e-9) / np.maximum(decode(truth[m], response), 1e-9))[ok]
    code = (comp[m].astype(float) - truth[m]) / 255
    outside = ~light_mask(scene, photo.shape[:2])
    lum = decode(photo, response).max(axis=2)
    top = outside & (photo.max(axis=2) >= 245)
    room, kind = tag.split("_")
    return {"room": room, "half": benchlib.half(room), "camera": kind,
            "response": json.dumps(response) if isinstance(response, dict) else response,
            "object_rmse": round(float(np.sqrt((code ** 2).mean())), 4), "log_mean": round(float(lr.mean()), 4),
            "log_rms": round(float(np.sqrt((lr ** 2).mean())), 4),
            "top_codes_outside_lights": int(top.sum()),
            "top_codes_radiance_share": round(float(lum[top].sum() / max(lum[outside].sum(), 1e-30)), 4)}


def plot(path, rows):
    with benchlib.figure(path, 1, 2, figsize=(13, 5)) as ax:
        if ax is None:
            return
        for i, kind in enumerate(("plain", "s1", "s2", "s3")):
            sel = [r for r in rows if r["camera"] == kind]
            ax[0].plot([r["log_rms"] for r in sel], [r["object_rmse"] for r in sel], "o", color="C%d" % i, label=kind)
            rooms = sorted({r["room"] for r in rows})
            ax[1].plot([rooms.index(r["room"]) + 0.15 * (i - 1.5) for r in sel], [r["log_mean"] for r in sel], "o",
                       color="C%d" % i, label=kind)
        ax[0].set(xlabel="object: RMS of log(composite / truth), decoded", ylabel="object RMSE (codes / 255)",
                  title="the same linear error costs more codes under a steeper curve")
        ax[0].legend(fontsize=8)
        rooms = sorted({r["room"] for r in rows})
        ax[1].axhline(0, color="grey", lw=0.8)
        ax[1].set_xticks(range(len(rooms)))
        ax[1].set_xticklabels(rooms, rotation=60, fontsize=8)
        ax[1].set(ylabel="mean log(composite / truth) on the object", title="object too bright (> 0) or too dark")
        ax[1].legend(fontsize=8)


def main():
    a = benchlib.args(__doc__)
    out = os.path.abspath(benchlib.option(a, "--out", os.path.join(HERE, "out")))
    os.makedirs(out, exist_ok=True)
    rows = []
    for run in a[0].split(","):
        for f in sorted(os.listdir(run)):
            tag = f[:-4]
            if f.endswith(".png") and tag.count("_") == 1 and os.path.exists(os.path.join(run, tag + ".json")):
                rows.append(measure(run, tag))
    if not rows:
        print("no composites in", a[0])
        return 1
    benchlib.write_csv(os.path.join(out, "linear_error.csv"), rows)
    print("| half | camera | variants | median object RMSE | median log mean | median |log mean| | median log RMS |")
    print("|---|---|---|---|---|---|---|")
    for h in ("A", "B"):
        for kind in ("plain", "cameras"):
            sel = [r for r in rows if r["half"] == h and (r["camera"] == "plain") == (kind == "plain")]
            if sel:
                med = lambda k: round(statistics.median([r[k] for r in sel]), 4)
                print("| %s | %s | %d | %s | %s | %s | %s |" % (h, kind, len(sel), med("object_rmse"), med("log_mean"),
                      round(statistics.median([abs(r["log_mean"]) for r in sel]), 4), med("log_rms")))
    plot(os.path.join(out, "linear_error.png"), rows)
    print("wrote", os.path.join(out, "linear_error.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
