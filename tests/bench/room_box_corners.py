#!/usr/bin/python3
"""The automatic box's back-wall corners on the rooms with ground truth, for two builds.

usage: room_box_corners.py INLAY_CLI_BEFORE INLAY_CLI_AFTER [--out DIR]

Runs `INLAY_CLI estimate ROOM/photo.png` for each of the six dev rooms (../shared/scenes/d*)
and the 14 training rooms (../shared/scenes-train/t*) with both builds (a build folder or the
inlay-cli binary) and measures each back-wall corner (layout.back_wall_px: TL, TR, BR, BL) against
truth.json's (room.corners ceiling/floor_front_left/right). Per room: the worst error of the
corners inside the photo, before and after, and the largest corner change. Writes
DIR/room_box_corners.csv and prints the medians per set (dev, training).
"""
import csv, glob, json, math, os, statistics, subprocess, sys, tempfile

import cv2

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ORDER = ["ceiling_front_left", "ceiling_front_right", "floor_front_right", "floor_front_left"]


def cli_path(arg):
    return os.path.join(arg, "app", "inlay-cli") if os.path.isdir(arg) else arg


def corners(cli, photo, tmp):
    out = os.path.join(tmp, "estimate.json")
    subprocess.run([cli, "estimate", photo, "-o", out, "--quiet"], check=True, timeout=300)
    return json.load(open(out))["layout"]["back_wall_px"]


def main():
    a = benchlib.args(__doc__, 2)
    before, after = cli_path(os.path.abspath(a[0])), cli_path(os.path.abspath(a[1]))
    out = os.path.abspath(a[a.index("--out") + 1]) if "--out" in a else os.path.join(benchlib.HERE, "out")
    os.makedirs(out, exist_ok=True)
    shared = os.environ.get("INLAY_SHARED_DIR", os.path.join(benchlib.HERE, "..", "..", "..", "shared"))
    rooms = sorted(glob.glob(os.path.join(shared, "scenes", "d*"))) + sorted(
        glob.glob(os.path.join(shared, "scenes-train", "t*")))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for room in rooms:
            truth = json.load(open(os.path.join(room, "truth.json")))
            h, w = cv2.imread(os.path.join(room, "photo.png")).shape[:2]
            g = [truth["room"]["corners"][n]["pixel"] for n in ORDER]
            inside = [0 <= p[0] <= w and 0 <= p[1] <= h for p in g]
            got = [corners(c, os.path.join(room, "photo.png"), tmp) for c in (before, after)]
            worst = [max((math.dist(p, q) for p, q, i in zip(b, g, inside) if i), default=float("nan"))
                     for b in got]
            change = max(math.dist(p, q) for p, q in zip(*got))
            rows.append({"room": os.path.basename(room), "set": "dev" if "/scenes/" in room else "train",
                         "worst_inside_before_px": "%.2f" % worst[0], "worst_inside_after_px": "%.2f" % worst[1],
                         "largest_change_px": "%.2f" % change})
            print("%-22s worst corner inside the photo %7.2f -> %7.2f px (largest change %.2f px)" %
                  (rows[-1]["room"], worst[0], worst[1], change))
    with open(os.path.join(out, "room_box_corners.csv"), "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=list(rows[0]), lineterminator="\n")
        wr.writeheader()
        wr.writerows(rows)
    for s in ("dev", "train"):
        part = [r for r in rows if r["set"] == s]
        med = [statistics.median(float(r[k]) for r in part) for k in ("worst_inside_before_px", "worst_inside_after_px")]
        print("%s: median worst corner %.2f -> %.2f px" % (s, med[0], med[1]))


if __name__ == "__main__":
    main()
