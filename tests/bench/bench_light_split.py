#!/usr/bin/env python3
"""Why a light's fitted intensity is off: the fit's split of the photo into albedo and light,
per room surface, against the truth's passes; and the light fit with the unseen ceiling true.

The light fit explains each surface's pixels as B = rho_s (sum_j L_j E_j + Gamma), one albedo
rho_s per surface: for a given photo, a gathered light Gamma that is too low makes rho_s too high
and the lights too dark, and the reverse. Per plain room this script reads:

- per surface the camera sees (the truth's labels.png), the median of our albedo, of our gathered
  light Gamma and of our direct irradiance D / rho (`inlay-cli decompose --albedo --direct
  --gathered`), each over the truth's (albedo.exr, indirect.exr and direct.exr, scaled to the
  photo's units; the panels' own pixels left out);
- the lights' radiance over the truth's (luminance): the first estimate's, and the product's
  (refined, or the first estimate kept), from `--lights-json` with the render cut to one sample;
- on rooms whose photo shows no ceiling, the same lights with the fit's model of that ceiling set
  to the truth's colour (`--fit-unseen-ceiling`, an oracle).
- the light fit's estimate of that unseen ceiling's albedo (`--lights-json`'s "unseen_ceiling",
  luminance; empty where the CLI makes none) against the truth's, and whether the photo told it;
  with --compare-walls also the run with the fit's ceiling the walls' mean (`--unseen-ceiling
  walls`, the rule before the estimate).

Usage:
  bench_light_split.py CLI --out OUT [--rooms A|B|t03,...] [--reuse] [--compare-walls]
Writes OUT/light_split.csv (one row per room and surface), OUT/light_split_lights.csv (one row
per room, run and light) and prints both tables.
"""

import json, os, subprocess, sys

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")
import cv2  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_generalization as gen  # noqa: E402

PY = "/usr/bin/python3"
LUMA = np.array([0.2126, 0.7152, 0.0722])
SURFACES = {1: "floor", 2: "ceiling", 3: "wall_front", 4: "wall_back", 5: "wall_left", 6: "wall_right", 7: "table"}


def exr(path):
    """A linear EXR's RGB as float64 (H x W x 3)."""
    a = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    if a is None:
        raise RuntimeError("cannot read " + path)
    return a[..., :3][..., ::-1].astype(np.float64)


def run(cmd, done, reuse):
    if reuse and all(os.path.exists(p) for p in done):
        return True
    return subprocess.run(cmd, capture_output=True, text=True, timeout=3600).returncode == 0


def split_rows(room, room_dir, pre):
    """Per seen surface: ours over the truth's albedo, Gamma and direct irradiance (medians)."""
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    s = truth["exposure"]["scale"]
    lab = cv2.imread(os.path.join(room_dir, "labels.png"), cv2.IMREAD_UNCHANGED)
    lab = lab[..., 0] if lab.ndim == 3 else lab
    emitting = exr(os.path.join(room_dir, "emission.exr")).max(-1) > 0
    t_alb, t_dir, t_ind = (exr(os.path.join(room_dir, f)) for f in ("albedo.exr", "direct.exr", "indirect.exr"))
    alb, direct, gam = (exr(pre + f) for f in ("_albedo.exr", "_direct.exr", "_gathered.exr"))
    rows = []
    for label, name in SURFACES.items():
        m = (lab == label) & ~emitting
        if m.sum() < 500:
            continue
        med = lambda a: float(np.median(a[m] @ LUMA))
        ours_e = float(np.median((direct[m] @ LUMA) / np.maximum(alb[m] @ LUMA, 1e-3)))
        true_e = med(t_dir) * s
        rows.append({"room": room, "surface": name, "pixels": int(m.sum()),
                     "albedo_ratio": round(med(alb) / max(med(t_alb), 1e-6), 3),
                     "gathered_ratio": round(med(gam) / max(med(t_ind) * s, 1e-9), 3),
                     "direct_ratio": round(ours_e / true_e, 3) if true_e > 1e-3 else "",
                     "true_albedo": round(med(t_alb), 3)})
    return rows


def light_rows(room, truth, lights_json, run_name):
    L = json.load(open(lights_json))
    s = truth["exposure"]["scale"]
    ceiling = (L.get("unseen_ceiling") or {}).get("fitted")
    told = (L.get("unseen_ceiling") or {}).get("told", [])
    true_ceiling = float(np.array(truth["room"]["faces"]["ceiling"]["material"]["color"]) @ LUMA)
    out = []
    for k, t in enumerate(truth["lights"]):
        tr = np.array(t["radiance_rgb"]) * s @ LUMA
        out.append({"room": room, "run": run_name, "light": k, "view": t["view_status"],
                    "first_ratio": round(float(np.array(L["initial"][k]["rgb"]) @ LUMA / tr), 3),
                    "product_ratio": round(float(np.array(L["refined"][k]["rgb"]) @ LUMA / tr), 3),
                    "ceiling_fitted": round(float(np.array(ceiling) @ LUMA), 3) if ceiling else "",
                    "ceiling_told": "".join("1" if x else "0" for x in told) if ceiling else "",
                    "ceiling_true": round(true_ceiling, 3)})
    return out


def measure(cli, tools, sdir, room, out, reuse, compare_walls=False):
    room_dir = os.path.join(sdir, room)
    vdir = gen.variant(tools, room_dir, os.path.join(out, "variants", room + "_plain"), "plain")
    scene = os.path.join(out, room + "_plain.json")
    if not os.path.exists(scene):
        subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene], check=True, capture_output=True)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    pre = os.path.join(out, room)
    maps = [pre + f for f in ("_albedo.exr", "_direct.exr", "_gathered.exr")]
    split = []
    if run([cli, "decompose", scene, "--albedo", maps[0], "--direct", maps[1], "--gathered", maps[2], "--quiet"],
           maps, reuse):
        split = split_rows(room, room_dir, pre)
    runs = {"product": []}
    lab = cv2.imread(os.path.join(room_dir, "labels.png"), cv2.IMREAD_UNCHANGED)
    if not ((lab[..., 0] if lab.ndim == 3 else lab) == 2).any():
        colour = truth["room"]["faces"]["ceiling"]["material"]["color"]
        runs["true_ceiling_in_fit"] = ["--fit-unseen-ceiling", ",".join("%.4f" % c for c in colour)]
        if compare_walls:
            runs["walls_in_fit"] = ["--unseen-ceiling", "walls"]
    lights = []
    for name, extra in runs.items():
        lj = "%s_%s_lights.json" % (pre, name)
        if run([cli, "render", scene, "-o", "%s_%s.png" % (pre, name), "--quiet", "--spp", "1", "--seconds", "0",
                "--noise", "0", "--lights-json", lj] + extra, [lj], reuse):
            lights += light_rows(room, truth, lj, name)
    return split, lights


def table(rows, keys):
    print("\n| " + " | ".join(keys) + " |\n|" + "---|" * len(keys))
    for r in rows:
        print("| " + " | ".join(str(r.get(k, "")) for k in keys) + " |")


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    cli = os.path.abspath(argv[1])
    opt = lambda k, d: argv[argv.index(k) + 1] if k in argv else d
    out = os.path.abspath(opt("--out", "bench_light_split_out"))
    os.makedirs(out, exist_ok=True)
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    split, lights = [], []
    for room in names:
        s, l = measure(cli, tools, sdir, room, out, "--reuse" in argv, "--compare-walls" in argv)
        split += s
        lights += l
        print(json.dumps({"room": room, "split": s, "lights": l}), flush=True)
    benchlib.write_csv(os.path.join(out, "light_split.csv"), split)
    benchlib.write_csv(os.path.join(out, "light_split_lights.csv"), lights)
    table(split, ["room", "surface", "pixels", "true_albedo", "albedo_ratio", "gathered_ratio", "direct_ratio"])
    table(lights, ["room", "run", "light", "view", "first_ratio", "product_ratio", "ceiling_fitted", "ceiling_told",
                   "ceiling_true"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
