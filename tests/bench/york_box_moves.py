#!/usr/bin/python3
"""Which automatic boxes moved between two runs of the York contact sheet, drawn side by side
(Debian's python3 with numpy and OpenCV).

usage: york_box_moves.py BEFORE_DIR AFTER_DIR YORK_DIR [--half A|B] [--verdicts CSV --label NAME]
                         [--out PNG]

BEFORE_DIR and AFTER_DIR hold one estimate per photo (<stem>.json), as
`york_contact_sheet.py ... --keep DIR` writes them. A box moves when its depth, width or ceiling
(york_contact_sheet.box_metres: at the camera's height) changes by more than 5 % or the box's
refusal ("implausible" in a box warning) flips, the criterion of the earlier York rounds. Prints
one line per moved box (index in sorted order, half, photo, the verdict of column
`verdict_<label>` when given, the sizes before -> after; "R": refused) and a count per half.
--half A (even indices: the odd-numbered photos) or B (odd indices) lists only that half, so that
settings can be chosen on one half without looking at the other. --out PNG draws the moved boxes
at full size, two per row: the back wall's quad before in red, after in green, the room's edges
lighter.
"""
import csv, json, os, sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
import york_contact_sheet as sheet  # noqa: E402

COLOURS = [(40, 40, 255), (40, 200, 40)]  # BGR: before red, after green


def box_of(folder, stem):
    """(camera, corners, (depth, width, ceiling), refused) of one kept estimate."""
    est = json.load(open(os.path.join(folder, stem + ".json")))
    cam = sheet.Cam(est)
    corners = [np.array(p, float) for p in est["layout"]["back_wall_px"]]
    refused = any("implausible" in w for w in est.get("warnings", []) if "box layout" in w)
    return cam, corners, sheet.box_metres(cam, corners), refused


def moved(a, b):
    """Whether the box moved: a size by more than 5 % (or defined in one run only), or the refusal."""
    for p, q in zip(a[2], b[2]):
        if (p is None) != (q is None) or (p is not None and abs(p - q) > 0.05 * abs(p)):
            return True
    return a[3] != b[3]


def sizes(box):
    d, w, c = (v if v is not None else float("nan") for v in box[2])
    return "D %.1f W %.1f C %.1f%s" % (d, w, c, " R" if box[3] else "")


def draw(york, stem, boxes):
    img = cv2.imread(os.path.join(york, stem + ".jpg"), cv2.IMREAD_COLOR)
    H, W = img.shape[:2]
    for k, (cam, corners, _, _) in enumerate(boxes):
        light = tuple(int(0.5 * v + 120) for v in COLOURS[k])
        for i, (p, q) in enumerate(sheet.edges_px(cam, corners, W, H)):
            cv2.line(img, tuple(int(round(v)) for v in p), tuple(int(round(v)) for v in q),
                     COLOURS[k] if i < 4 else light, 2 if i < 4 else 1, cv2.LINE_AA)
    for k, box in enumerate(boxes):
        text = ("before " if k == 0 else "after ") + sizes(box)
        for colour, width in (((0, 0, 0), 3), (COLOURS[k], 1)):
            cv2.putText(img, text, (6, 18 + 18 * k), cv2.FONT_HERSHEY_SIMPLEX, 0.5, colour, width, cv2.LINE_AA)
    cv2.putText(img, stem, (6, H - 8), cv2.FONT_HERSHEY_SIMPLEX, 0.6, (255, 255, 255), 2, cv2.LINE_AA)
    return cv2.resize(img, (640, int(round(640 * H / W))), interpolation=cv2.INTER_AREA)


def main():
    a = benchlib.args(__doc__, 3)
    before, after, york = (os.path.abspath(x) for x in a[:3])
    half = benchlib.option(a, "--half", "")
    if half not in ("", "A", "B"):
        sys.stderr.write("york_box_moves.py: --half must be A or B, not %r\n" % half)
        sys.exit(2)
    label = benchlib.option(a, "--label", "")
    verdicts = sheet.read_verdicts(benchlib.option(a, "--verdicts", ""), label) if label else {}
    stems = sorted(f[:-5] for f in os.listdir(before) if f.endswith(".json"))
    missing = [s for s in stems if not os.path.exists(os.path.join(after, s + ".json"))]
    if not stems or missing:
        sys.stderr.write("york_box_moves.py: %s: no estimates, or missing in %s: %s\n"
                         % (before, after, ", ".join(missing[:5])))
        sys.exit(2)
    counts, tiles = {"A": 0, "B": 0}, []
    for i, stem in enumerate(stems):
        h = "A" if i % 2 == 0 else "B"
        if half and h != half:
            continue
        boxes = [box_of(before, stem), box_of(after, stem)]
        if not moved(*boxes):
            continue
        counts[h] += 1
        verdict = verdicts.get(stem + ".jpg", ("", "", ""))[1]
        print("%2d %s %s %-7s %s -> %s" % (i, h, stem, verdict, sizes(boxes[0]), sizes(boxes[1])))
        if "--out" in a:
            tiles.append(draw(york, stem, boxes))
    print(json.dumps({"moved_A": counts["A"], "moved_B": counts["B"], "half": half or "both"}))
    out = benchlib.option(a, "--out", "")
    if out and tiles:
        h = max(t.shape[0] for t in tiles)
        tiles = [cv2.copyMakeBorder(t, 0, h - t.shape[0], 0, 0, cv2.BORDER_CONSTANT) for t in tiles]
        if len(tiles) % 2:
            tiles.append(np.zeros_like(tiles[0]))
        cv2.imwrite(out, np.vstack([np.hstack(tiles[k:k + 2]) for k in range(0, len(tiles), 2)]))


if __name__ == "__main__":
    main()
