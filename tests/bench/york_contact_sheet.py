#!/usr/bin/python3
"""The automatic room box on every York Urban photo, as one contact sheet (Debian's python3 with
numpy, OpenCV and matplotlib).

usage: york_contact_sheet.py INLAY_CLI YORK_DIR [--out DIR] [--label NAME] [--verdicts CSV]
                             [--cols N] [--thumb W] [--small PNG] [--rejected] [--keep DIR]

Runs `INLAY_CLI estimate PHOTO -o CAMERA.json --quiet` on every photo of YORK_DIR (sorted by
name; INLAY_CLI may be a build folder, then BUILD/app/inlay-cli) and draws the box it writes on a
thumbnail of the photo: the back wall's quad (layout.back_wall_px) and the four room edges from
its corners away from the forward vanishing point to the image border (floor and ceiling
creases with the side walls). Under each thumbnail: the photo's index and name, the box's
depth (camera to back wall) and width in metres at the camera's height, and the verdict.

The box's metres are computed as the room builder does (roomFromBackWall): the bottom corners'
rays meet the floor (camera.height_m below the camera), the depth is their mean distance along
the room's -z, the width the distance between them, the ceiling where the top corners' rays
meet the back wall's plane.

--verdicts CSV: a committed file of per-photo verdicts made by looking at the sheet (columns
`image`, `scene` indoor/outdoor, and `verdict_<label>` accept/reject with `note_<label>`); the
verdicts of column `verdict_<label>` (--label, default "run") are copied into the CSV, coloured
on the sheet (green accept, red reject) and counted. Photos without a verdict show "?".

Writes DIR/york_boxes_<label>.csv (per photo: exit status, seconds, focal length, box depth,
width and ceiling in m, layout confidence, warnings, verdict) and DIR/york_boxes_<label>.png;
--small PNG also writes a 256-colour copy with half-size thumbnails (for the docs). --rejected:
the sheet shows only the rejected boxes, each captioned with its failure class (the note's
leading `[class]`), and the summary counts the classes. --keep DIR: each photo's estimate is kept
as DIR/<photo>.json (york_box_moves.py compares two such folders). Prints a JSON
summary (photos, failures, boxes refused as implausible, the accepted count per scene type and
per half A (even indices) and B (odd) when verdicts are given).
"""
import csv, json, math, os, subprocess, sys, tempfile, time

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402


def cli_path(arg):
    """INLAY_CLI itself, or BUILD/app/inlay-cli for a build folder."""
    return os.path.join(arg, "app", "inlay-cli") if os.path.isdir(arg) else arg


def estimate(cli, photo, tmp, keep=None):
    """(exit status, seconds, the estimate's JSON or None, stderr); with `keep` (a folder) the
    estimate is written there as <photo's stem>.json."""
    out = os.path.join(keep, os.path.splitext(os.path.basename(photo))[0] + ".json") if keep else \
        os.path.join(tmp, "estimate.json")
    if os.path.exists(out):
        os.remove(out)
    t0 = time.time()
    p = subprocess.run([cli, "estimate", photo, "-o", out, "--quiet"], capture_output=True, text=True,
                       timeout=300)
    dt = time.time() - t0
    est = json.load(open(out)) if p.returncode == 0 and os.path.exists(out) else None
    return p.returncode, dt, est, p.stderr.strip()


class Cam:
    """Inlay's pinhole camera (modeling/include/inlay/modeling/camera.h): world y up, floor at
    y = 0, centre (0, h, 0); camera looking down its -z, pixel y down."""

    def __init__(self, est):
        c = est["camera"]
        self.f = float(c["focal_px"])
        self.c = np.array(c["principal_px"], float)
        self.h = float(c.get("height_m", 1.6))
        self.R = np.array(est["rotation"], float)  # world from camera

    def ray(self, px):
        d = np.array([(px[0] - self.c[0]) / self.f, -(px[1] - self.c[1]) / self.f, -1.0])
        d = self.R @ d
        return d / np.linalg.norm(d)

    def vanishing_px(self, world_dir):
        """Pixel of a world direction's vanishing point; None at infinity or behind."""
        d = self.R.T @ np.asarray(world_dir, float)
        if not -d[2] > 1e-9:
            return None
        return np.array([self.c[0] + self.f * d[0] / -d[2], self.c[1] - self.f * d[1] / -d[2]])


def box_metres(cam, corners):
    """(depth, width, ceiling) in metres of the back wall's corners TL, TR, BR, BL, as
    roomFromBackWall computes them; None where a corner does not land (above the horizon)."""
    centre = np.array([0.0, cam.h, 0.0])
    floor = []
    for px in (corners[3], corners[2]):
        d = cam.ray(px)
        if not d[1] < -1e-9:
            return None, None, None
        floor.append(centre + d * (cam.h / -d[1]))
    z_back = 0.5 * (floor[0][2] + floor[1][2])
    width = floor[1][0] - floor[0][0]
    heights = []
    for px in (corners[0], corners[1]):
        d = cam.ray(px)
        if abs(d[2]) > 1e-12:
            t = z_back / d[2]  # the camera stands at z = 0
            if t > 0:
                heights.append(cam.h + t * d[1])
    ceiling = float(np.mean(heights)) if heights else None
    return float(-z_back), float(width), ceiling


def edges_px(cam, corners, W, H):
    """The box's lines in photo pixels: the back wall's four edges, then from each corner away
    from the forward vanishing point to well beyond the photo (drawing clips them)."""
    lines = [(corners[i], corners[(i + 1) % 4]) for i in range(4)]
    vz = cam.vanishing_px([0.0, 0.0, -1.0])
    if vz is None:
        return lines
    far = 4.0 * math.hypot(W, H)
    for c in corners:
        d = np.asarray(c) - vz
        n = np.linalg.norm(d)
        if n > 1e-9:
            lines.append((c, np.asarray(c) + d / n * far))
    return lines


def read_verdicts(path, label):
    """{image: (scene, verdict, note)} from the verdicts file's `verdict_<label>` column."""
    if not path or not os.path.exists(path):
        return {}
    out = {}
    for r in csv.DictReader(open(path)):
        out[r["image"]] = (r.get("scene", ""), r.get("verdict_" + label, ""), r.get("note_" + label, ""))
    return out


def run_all(cli, york, verdicts, keep=None):
    photos = sorted(f for f in os.listdir(york) if f.lower().endswith((".jpg", ".png")))
    rows, drawn = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i, name in enumerate(photos):
            code, dt, est, err = estimate(cli, os.path.join(york, name), tmp, keep)
            scene, verdict, note = verdicts.get(name, ("", "", ""))
            row = {"index": i, "image": name, "exit": code, "seconds": round(dt, 3)}
            lines = []
            if est is not None:
                cam = Cam(est)
                corners = [np.array(p, float) for p in est["layout"]["back_wall_px"]]
                depth, width, ceiling = box_metres(cam, corners)
                img = cv2.imread(os.path.join(york, name), cv2.IMREAD_COLOR)
                lines = edges_px(cam, corners, img.shape[1], img.shape[0])
                row.update({"focal_px": round(cam.f, 1), "depth_m": depth, "width_m": width, "ceiling_m": ceiling,
                            "layout_confidence": est.get("confidence", {}).get("layout"),
                            "warnings": " | ".join(w for w in est.get("warnings", []) if "box layout" in w)})
            else:
                row["error"] = err
            row.update({"scene": scene, "verdict": verdict, "note": note})
            rows.append(row)
            drawn.append((name, lines, row))
    return rows, drawn


def caption(row):
    d, w = row.get("depth_m"), row.get("width_m")
    dims = "D %.1f W %.1f m" % (d, w) if d is not None and w is not None else "no box"
    return "%d %s  %s" % (row["index"], row["image"].rsplit(".", 1)[0], dims)


def failure_class(row):
    """The failure class a rejected box's note starts with (`[class] ...`), else ""."""
    note = row.get("note") or ""
    return note[1:note.index("]")] if note.startswith("[") and "]" in note else ""


def draw_sheet(path, york, drawn, cols, thumb):
    """One grid of thumbnails with the boxes; the caption's colour is the verdict's."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = len(drawn)
    rows = (n + cols - 1) // cols
    dpi = 100
    cell_w, cell_h = thumb / dpi, thumb * 0.75 / dpi + 0.22
    fig = plt.figure(figsize=(cols * cell_w, rows * cell_h), dpi=dpi)
    colours = {"accept": "#1a7f1a", "reject": "#c01818"}
    for k, (name, lines, row) in enumerate(drawn):
        img = cv2.imread(os.path.join(york, name), cv2.IMREAD_COLOR)[:, :, ::-1]
        H, W = img.shape[:2]
        small = cv2.resize(img, (thumb, int(round(thumb * H / W))), interpolation=cv2.INTER_AREA)
        r, c = divmod(k, cols)
        ax = fig.add_axes([c / cols, 1 - (r + 1) / rows, 1 / cols, (thumb * 0.75 / dpi) / (rows * cell_h)])
        ax.imshow(small, extent=(0, W, H, 0), interpolation="nearest")
        for a, b in lines:
            ax.plot([a[0], b[0]], [a[1], b[1]], color="#ffd400", lw=1.0)
        for a, b in lines[:4]:
            ax.plot([a[0], b[0]], [a[1], b[1]], color="#ff2a2a", lw=1.2)
        ax.set_xlim(0, W)
        ax.set_ylim(H, 0)
        ax.set_axis_off()
        verdict = row.get("verdict") or "?"
        ax.set_title(caption(row) + "  " + (failure_class(row) or verdict), fontsize=6.2, pad=1.5,
                     color=colours.get(verdict, "black"))
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def small_copy(path, small_path):
    """A 256-colour copy at half size (the docs' copy)."""
    from PIL import Image
    im = Image.open(path).convert("RGB")
    im = im.resize((im.width // 2, im.height // 2), Image.LANCZOS)
    im.quantize(colors=256, method=Image.MEDIANCUT, dither=Image.NONE).save(small_path, optimize=True)


def summary(rows):
    s = {"photos": len(rows), "failed": sum(1 for r in rows if r["exit"] != 0),
         "depth_m_median": float(np.median([r["depth_m"] for r in rows if r.get("depth_m") is not None] or [math.nan])),
         "box_refused": sum(1 for r in rows if "implausible" in (r.get("warnings") or ""))}
    judged = [r for r in rows if r.get("verdict") in ("accept", "reject")]
    if judged:
        s["judged"] = len(judged)
        s["accepted"] = sum(1 for r in judged if r["verdict"] == "accept")
        # Per scene type, and per half (A: even indices in sorted order, B: odd).
        for scene in sorted({r["scene"] for r in judged}):
            for half, parity in (("", None), ("_A", 0), ("_B", 1)):
                part = [r for r in judged if r["scene"] == scene and (parity is None or r["index"] % 2 == parity)]
                s["accepted_" + scene + half] = "%d/%d" % (sum(1 for r in part if r["verdict"] == "accept"), len(part))
    return s


def main():
    a = benchlib.args(__doc__, 2)
    cli, york = cli_path(os.path.abspath(a[0])), os.path.abspath(a[1])
    out = os.path.abspath(benchlib.option(a, "--out", os.path.join(benchlib.HERE, "out", "york_boxes")))
    label = benchlib.option(a, "--label", "run")
    cols, thumb = int(benchlib.option(a, "--cols", "6")), int(benchlib.option(a, "--thumb", "240"))
    verdicts = read_verdicts(benchlib.option(a, "--verdicts", ""), label)
    if not os.path.isdir(york):
        print("skipped: no", york)
        return
    os.makedirs(out, exist_ok=True)
    keep = benchlib.option(a, "--keep", "")
    if keep:
        keep = os.path.abspath(keep)
        os.makedirs(keep, exist_ok=True)
    rows, drawn = run_all(cli, york, verdicts, keep or None)
    benchlib.write_csv(os.path.join(out, "york_boxes_%s.csv" % label), rows, table="york_boxes_%s" % label)
    png = os.path.join(out, "york_boxes_%s.png" % label)
    rejected = "--rejected" in a
    if rejected:
        drawn = [d for d in drawn if d[2].get("verdict") == "reject"]
        png = os.path.join(out, "york_boxes_%s_rejected.png" % label)
    draw_sheet(png, york, drawn, cols, thumb)
    small = benchlib.option(a, "--small", "")
    if small:
        small_copy(png, small)
    s = summary(rows)
    if rejected:
        s["rejected_by_class"] = {}
        for r in rows:
            if r.get("verdict") == "reject":
                key = "%s (%s)" % (failure_class(r) or "?", r["scene"])
                s["rejected_by_class"][key] = s["rejected_by_class"].get(key, 0) + 1
    print(json.dumps(s, indent=1))


if __name__ == "__main__":
    main()
