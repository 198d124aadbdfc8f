#!/usr/bin/python3
"""The window a sun's beam came through, against the truth's (issue #16, docs/generalization.md
"The unseen window's reveal").

Per sun room (d4, t04, t10 by default), in the plane of the truth's window:
- the truth: the window's rectangle, and the beam's section (the truth's sunlit floor patch,
  `sun.floor_patch.world_corners`, carried back against the light onto the window's wall);
- that section widened by a reveal `--depth` deep (PrepareOptions::windowRevealDepthM's rule,
  lighting/src/shaft.cpp widenByReveal), the same formula on the truth's own beam;
- where the product adds the window's sky as a light (the window out of view, no
  source_box_px: t04, t10), the product's opening at `--window-reveal 0` (the beam's section, the
  rule before) and at the default, from `inlay-cli render SCENE --spp 1 --lights-json`: its
  size, its overlap with the truth's window (intersection over union), the fitted sky's radiance
  over the truth's and its power (radiance x area) over the truth's, the sun's over the truth's
  (luminance).

Writes OUT/window_reveal.csv and OUT/window_reveal.png (per room the rectangles in the wall's
plane); prints a Markdown table. d4 shows its window (the harness gives source_box_px), so the
product adds no sky there: only the truth's rows.

usage: bench_window_reveal.py INLAY_CLI [--rooms d4,t04,t10] [--out DIR] [--depth 0.2]
"""
import json, os, subprocess, sys, tempfile
import numpy as np
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

LUM = np.array([0.2126, 0.7152, 0.0722])


def room_dir(name):
    base = "scenes-train" if name.startswith("t") else "scenes"
    root = os.path.join(benchlib.shared_dir(), base)
    return os.path.join(root, [d for d in sorted(os.listdir(root)) if d.startswith(name)][0])


def wall_frame(win):
    """The window's wall: its inward normal n and in-plane axes u (horizontal), v (up)."""
    n = np.array(win["inward_normal"], float)
    v = np.array([0.0, 1.0, 0.0])
    u = np.cross(v, n)
    return n, u / np.linalg.norm(u), v


def rect_of(points, origin, u, v):
    """[u0, u1, v0, v1] of 3D points in the wall's plane (coordinates from `origin`)."""
    a = [(np.array(p, float) - origin) @ u for p in points]
    b = [(np.array(p, float) - origin) @ v for p in points]
    return [min(a), max(a), min(b), max(b)]


def widen(rect, travel, n, u, v, depth):
    """widenByReveal's rule: each side by at most the section's extent."""
    u0, u1, v0, v1 = rect
    across = travel @ n
    if not depth > 0 or not across > 1e-6:
        return rect
    out = []
    for lo, hi, axis in ((u0, u1, u), (v0, v1, v)):
        shift = float(np.clip(depth * (travel @ axis) / across, -(hi - lo), hi - lo))
        out += [lo - shift, hi] if shift > 0 else [lo, hi - shift]
    return out


def iou(a, b):
    w = max(0.0, min(a[1], b[1]) - max(a[0], b[0]))
    h = max(0.0, min(a[3], b[3]) - max(a[2], b[2]))
    area = lambda r: (r[1] - r[0]) * (r[3] - r[2])
    return w * h / max(area(a) + area(b) - w * h, 1e-12)


def product_opening(cli, room, t, reveal, tmp):
    """The product's opening (the last refined light) and its fitted sky and sun, or None."""
    scene = os.path.join(tmp, "scene.json")
    subprocess.run(["/usr/bin/python3", os.path.join(benchlib.shared_dir(), "tools", "harness.py"), "scene",
                    room, scene], check=True, capture_output=True)
    if json.load(open(scene))["shafts"][0].get("source_box_px"):
        return None  # the window is in view: no sky is added
    lj, png = os.path.join(tmp, "lights.json"), os.path.join(tmp, "out.png")
    cmd = [cli, "render", scene, "-o", png, "--spp", "1", "--lights-json", lj, "--quiet"]
    if reveal is not None:
        cmd += ["--window-reveal", str(reveal)]
    subprocess.run(cmd, check=True, capture_output=True)
    L = json.load(open(lj))
    if not L["refined"]:
        return None
    cam = t["camera"]["position"]
    # Inlay's frame puts the camera at (0, h, 0): the truth's points shifted by its x, z.
    corners = [np.array(c, float) + np.array([cam[0], 0.0, cam[2]]) for c in L["refined"][-1]["corners"]]
    return {"corners": corners, "sky": np.array(L["refined"][-1]["rgb"], float),
            "sun": np.array(L["suns_refined"][0]["rgb"], float)}


def room_rows(name, cli, depth):
    room = room_dir(name)
    t = json.load(open(os.path.join(room, "truth.json")))
    sun, scale = t["sun"], t["exposure"]["scale"]
    win = sun["window"]
    n, u, v = wall_frame(win)
    origin = np.array(win["world_corners"][0], float)
    travel = np.array(sun["light_travel_direction"], float)
    to_sun = -travel
    window = rect_of(win["world_corners"], origin, u, v)
    # The floor patch carried back against the light onto the window's plane.
    back = []
    for p in sun["floor_patch"]["world_corners"]:
        p = np.array(p, float)
        s = ((origin - p) @ n) / (to_sun @ n)
        back.append(p + s * to_sun)
    beam = rect_of(back, origin, u, v)
    widened = widen(beam, travel, n, u, v, depth)
    sky_true = np.array(sun["sky"]["color"], float) * sun["sky"]["strength"] * scale
    sun_true = np.array(sun["color"], float) * sun["strength_W_m2"] / np.pi * scale
    area = lambda r: (r[1] - r[0]) * (r[3] - r[2])
    rows, rects = [], {"window": window, "beam (truth)": beam, "widened (truth)": widened}
    for what, r in (("truth's beam section", beam), ("truth's beam widened by %.2f m" % depth, widened)):
        rows.append({"room": name, "opening": what, "width_m": r[1] - r[0], "height_m": r[3] - r[2],
                     "iou_with_window": iou(r, window), "area_over_window": area(r) / area(window)})
    for label, reveal in (("product, --window-reveal 0", 0.0), ("product (default)", None)):
        with tempfile.TemporaryDirectory() as tmp:
            p = product_opening(cli, room, t, reveal, tmp)
        if p is None:
            continue
        r = rect_of(p["corners"], origin, u, v)
        rects[label] = r
        sky = float(p["sky"] @ LUM / (sky_true @ LUM))
        rows.append({"room": name, "opening": label, "width_m": r[1] - r[0], "height_m": r[3] - r[2],
                     "iou_with_window": iou(r, window), "area_over_window": area(r) / area(window),
                     "sky_over_true": sky, "sky_power_over_true": sky * area(r) / area(window),
                     "sun_over_true": float(p["sun"] @ LUM / (sun_true @ LUM))})
    return rows, rects


def plot(path, all_rects):
    with benchlib.figure(path, 1, len(all_rects), figsize=(4.2 * len(all_rects), 3.6), squeeze=False) as ax:
        if ax is None:
            return
        styles = {"window": ("k", "-", 2.5), "beam (truth)": ("tab:orange", "--", 1.5),
                  "widened (truth)": ("tab:green", ":", 2), "product, --window-reveal 0": ("tab:red", "-", 1.2),
                  "product (default)": ("tab:blue", "-", 1.2)}
        for i, (name, rects) in enumerate(all_rects.items()):
            a = ax[0][i]
            for label, r in rects.items():
                c, ls, lw = styles[label]
                a.plot([r[0], r[1], r[1], r[0], r[0]], [r[2], r[2], r[3], r[3], r[2]], color=c, ls=ls, lw=lw,
                       label=label)
            a.set_title("%s: the window's wall (m)" % name, fontsize=9)
            a.set_aspect("equal")
            a.legend(fontsize=6, loc="lower right")


def main():
    argv = sys.argv[1:]
    if not argv or argv[0].startswith("-"):
        raise SystemExit(__doc__)
    cli = argv[0]
    rooms = benchlib.option(argv, "--rooms", "d4,t04,t10").split(",")
    out = benchlib.option(argv, "--out", "window_reveal_out")
    depth = float(benchlib.option(argv, "--depth", "0.2"))
    os.makedirs(out, exist_ok=True)
    rows, rects = [], {}
    for r in rooms:
        rr, rects[r] = room_rows(r, cli, depth)
        rows += rr
    cols = ["room", "opening", "width_m", "height_m", "iou_with_window", "area_over_window", "sky_over_true",
            "sky_power_over_true", "sun_over_true"]
    benchlib.write_csv(os.path.join(out, "window_reveal.csv"), rows)
    plot(os.path.join(out, "window_reveal.png"), rects)
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))
    for row in rows:
        print("| " + " | ".join(benchlib.cell(row.get(c, "")) for c in cols) + " |")


if __name__ == "__main__":
    main()
