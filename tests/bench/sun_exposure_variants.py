#!/usr/bin/python3
"""A room re-photographed at a brighter exposure, so its sunlit patch clips more.

  sun_exposure_variants.py ROOM_DIR OUT_DIR --gain G

The room's plain sRGB encoding (camera_variants.py --plain) of its linear renders times G: photo
and truth alike; camera_variant.json records the gain (the benchmarks read it to bring the truth's
light into the photo's units; Inlay never reads it). Every other file is linked.
"""
import json, os, sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("INLAY_SHARED_DIR", "/work/shared"), "tools"))
import camera_variants as cv  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402


def main(args):
    if len(args) < 4 or "--gain" not in args:
        print(__doc__)
        return 2
    room, out, gain = args[0], args[1], float(args[args.index("--gain") + 1])
    truth = json.load(open(os.path.join(room, "truth.json")))
    scale = truth["exposure"]["scale"] * gain
    benchlib.link_room_files(room, out)
    for exr, stem in (("photo_linear.exr", "photo"), ("truth_linear.exr", "truth")):
        pixels = np.round(cv.srgb(cv.read_exr(os.path.join(room, exr)) * scale) * 255).astype(np.uint8)
        cv.cv2.imwrite(os.path.join(out, stem + ".png"), np.ascontiguousarray(pixels[:, :, ::-1]))
    cam = {"curve": "srgb", "gain": gain, "white_balance": [1, 1, 1], "vignetting": 0.0, "noise": 0.0,
           "jpeg_quality": 0}
    json.dump(cam, open(os.path.join(out, "camera_variant.json"), "w"), indent=1)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
