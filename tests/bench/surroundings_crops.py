#!/usr/bin/python3
"""Side-by-side crops around the object of bench_surroundings.py composites (one row per room):
each OUT folder's composite at the given sample count, then the room's truth.

usage: surroundings_crops.py OUT.png --rooms d4,t04 --spp 16 DIR1 [DIR2 ...]
  DIRk     bench_surroundings.py --out folders (their ROOM_SPP.png composites)
  --rooms  training rooms (t04), dev rooms by prefix (d4) or room folders, as bench_surroundings.py
"""
import os, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
from bench_surroundings import room_directory  # noqa: E402


def crop_box(room_dir, shape):
    """The object's projected box widened by its width either side and half its height."""
    import json
    with open(os.path.join(room_dir, "truth.json")) as f:
        x0, y0, x1, y1 = [int(v) for v in json.load(f)["object"]["projected_bbox_2d"]]
    w, h = x1 - x0, y1 - y0
    return max(0, y0 - h // 2), min(shape[0], y1 + h // 2), max(0, x0 - w), min(shape[1], x1 + w)


def main():
    import cv2
    argv = sys.argv[1:]
    out = argv[0]
    rooms = benchlib.option(argv, "--rooms", "d4").split(",")
    spp = benchlib.option(argv, "--spp", "16")
    dirs = [a for i, a in enumerate(argv[1:], 1) if not a.startswith("--") and argv[i - 1] not in ("--rooms", "--spp")]
    shared = benchlib.shared_dir()
    rows = []
    for room in rooms:
        room_dir = room_directory(shared, os.path.join(shared, "scenes-train"), room)
        truth = cv2.imread(os.path.join(room_dir, "truth.png"))
        y0, y1, x0, x1 = crop_box(room_dir, truth.shape)
        tiles = [cv2.imread(os.path.join(d, "%s_%s.png" % (os.path.basename(room_dir), spp)))[y0:y1, x0:x1]
                 for d in dirs] + [truth[y0:y1, x0:x1]]
        row = np.hstack(tiles)
        scale = 240.0 / row.shape[0]
        rows.append(cv2.resize(row, None, fx=scale, fy=scale, interpolation=cv2.INTER_NEAREST))
    width = max(r.shape[1] for r in rows)
    rows = [np.pad(r, ((0, 4), (0, width - r.shape[1]), (0, 0)), constant_values=255) for r in rows]
    cv2.imwrite(out, np.vstack(rows))
    print("wrote", out)


if __name__ == "__main__":
    main()
