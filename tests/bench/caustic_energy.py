"""The caustic's energy on the support around a glass object: per render, the light its composite
adds to the photo and the light it removes (shadow), summed over a region of the photo outside
the truth's object mask, in the photo's linear units (luminance); the truth's own image first.

    /usr/bin/python3 tests/bench/caustic_energy.py ROOM_DIR --region Y0,Y1,X0,X1 NAME=LAYERS.exr ...

LAYERS.exr: inlay-cli render --layers (its composite layer). ROOM_DIR: a ../shared/scenes-train
room (truth_linear.exr, photo_linear.exr, object_mask.png, truth.json's exposure scale). Prints a
Markdown table: render, light added, light removed, brightest pixel."""
import json, os, sys

import cv2
import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def read(path, channels=3):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        sys.exit("cannot read %s" % path)
    s = inp.spec()
    px = np.asarray(inp.read_image(0, s.nchannels, "float")).reshape(s.height, s.width, s.nchannels)
    inp.close()
    return px[..., :channels]


def main():
    a = benchlib.args(__doc__, 3)
    room = a[0]
    y0, y1, x0, x1 = (int(v) for v in benchlib.option(a, "--region", "0,0,0,0").split(","))
    scale = json.load(open(os.path.join(room, "truth.json")))["exposure"]["scale"]
    photo = read(os.path.join(room, "photo_linear.exr")) * scale
    region = np.zeros(photo.shape[:2], bool)
    region[y0:y1, x0:x1] = True
    region &= cv2.imread(os.path.join(room, "object_mask.png"), cv2.IMREAD_GRAYSCALE) < 128
    renders = [("truth", os.path.join(room, "truth_linear.exr"))]
    renders += [tuple(r.split("=", 1)) for r in a[1:] if "=" in r]
    print("| render | light added | light removed | brightest pixel |\n|---|---|---|---|")
    for name, path in renders:
        image = read(path) * (scale if name == "truth" else 1.0)
        d = (image.mean(-1) - photo.mean(-1))[region]
        print("| %s | %+.1f | %.1f | %.2f |" % (name, d[d > 0].sum(), d[d < 0].sum(), d.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
