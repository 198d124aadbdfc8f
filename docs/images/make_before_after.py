#!/usr/bin/python3
"""Makes docs/images/before_after.png, the README's picture: the bundled example's photo beside
what `inlay-cli demo` renders into it.

    /usr/bin/python3 docs/images/make_before_after.py build/app/inlay-cli [OUT.png]

The photo is read from resources/example/ (what `demo` renders); the render uses more samples
than the demo's default (64 per pixel) so the picture shows the result, not its noise. The PNG is
quantized to 256 colours (Pillow, fast octree: no visible banding) to stay small.
"""
import os
import subprocess
import sys
import tempfile

import cv2
import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PHOTO = os.path.join(ROOT, "resources", "example", "photo.png")
SPP, NOISE, SEED = 1024, 0.002, 1
LABEL_H, GAP = 28, 6


def render_demo(cli, out_png):
    subprocess.run([cli, "demo", "-o", out_png, "--spp", str(SPP), "--noise", str(NOISE),
                    "--seed", str(SEED), "--quiet"], check=True)
    img = cv2.imread(out_png, cv2.IMREAD_COLOR)
    if img is None:
        sys.exit(f"make_before_after: {out_png} was not written")
    return img


def labelled(img, text):
    bar = np.full((LABEL_H, img.shape[1], 3), 255, np.uint8)
    cv2.putText(bar, text, (8, LABEL_H - 9), cv2.FONT_HERSHEY_SIMPLEX, 0.6, (40, 40, 40), 1,
                cv2.LINE_AA)
    return np.vstack([bar, img])


def side_by_side(before, after):
    gap = np.full((before.shape[0], GAP, 3), 255, np.uint8)
    return np.hstack([before, gap, after])


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cli = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "images",
                                                              "before_after.png")
    photo = cv2.imread(PHOTO, cv2.IMREAD_COLOR)
    with tempfile.TemporaryDirectory() as tmp:
        after = render_demo(cli, os.path.join(tmp, "demo.png"))
    if photo is None or photo.shape != after.shape:
        sys.exit("make_before_after: the photo and the render differ in size")
    pair = side_by_side(labelled(photo, "Before: the photo"),
                        labelled(after, "After: inlay-cli demo (a sphere inserted)"))
    rgb = Image.fromarray(cv2.cvtColor(pair, cv2.COLOR_BGR2RGB))
    rgb.quantize(colors=256, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.FLOYDSTEINBERG) \
       .save(out, optimize=True)
    print(f"make_before_after: wrote {out} ({os.path.getsize(out) // 1024} KB)")


if __name__ == "__main__":
    main()
