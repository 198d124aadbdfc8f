#!/usr/bin/python3
"""Extra geometry against the ground truth: table tops and occluder mattes.

For each room with a table (d3_table_cube, d6_behind_table, ...) the harness writes the assisted
scene file (table outline and height click; occluder scribbles where the object stands behind the
table); build/tests/bench/bench_modeling times the extrusion (best of N) and the matting and
reports the table top and the matte; this script compares them with truth.json and labels.png
(== 7, the table) and writes OUT/bench_modeling.csv and OUT/bench_modeling.png (error against
run time). Where an occluder's matte shows a top drawn without a thickness open below, the
slab thickness it gives (slabFromMatte) is listed against the truth's top_thickness. With --render INLAY_CLI_DIR it also renders
each scene with `harness.py run` and adds the harness's scores plus the composite's RMSE in a
band of 4 px around the table's outline inside the object's neighbourhood (the occlusion edge).

usage: bench_modeling.py BUILD_DIR [--out DIR] [--repeat N] [--render] [--seconds S]
"""
import glob, json, os, subprocess, sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def main():
    build, opt, out = benchlib.command_line(__doc__)
    repeat = opt("--repeat", "50")
    seconds = opt("--seconds", "40")
    shared = os.environ.get("INLAY_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))
    sdir = os.path.join(shared, "scenes")
    harness = os.path.join(shared, "tools", "harness.py")
    if not os.path.isdir(sdir):
        print("skipped: no ../shared/scenes")
        return 0
    os.makedirs(out, exist_ok=True)
    tool = os.path.join(build, "tests", "bench", "bench_modeling")
    rows = []
    for name in sorted(os.listdir(sdir)):
        tpath = os.path.join(sdir, name, "truth.json")
        if not os.path.isfile(tpath):
            continue
        t = json.load(open(tpath))
        if not t.get("table"):
            continue
        scene = os.path.join(sdir, name)
        sj = os.path.join(out, name + ".json")
        subprocess.run([sys.executable, harness, "scene", scene, sj, "--mode", "assisted"], check=True)
        work = os.path.join(out, name)
        os.makedirs(work, exist_ok=True)
        lines = subprocess.run([tool, sj, work, repeat], check=True, capture_output=True, text=True).stdout
        cam = t["camera"]
        pos = np.array([cam["position"][0], 0.0, cam["position"][2]])
        tb = t["table"]
        for line in lines.splitlines():
            r = json.loads(line)
            row = {"scene": name, "what": r["what"], "index": r["index"], "ms": round(r["ms"], 4)}
            if "error" in r:
                row["error"] = r["error"]
            elif r["what"] == "surface" and r["index"] < 0:
                row.update({"kind": r["kind"], "height_m": round(r["height_m"], 4),
                            "up_triangles": r["up_triangles"]})
            elif r["what"] == "surface":
                h = r["height_m"]
                row["height_m"] = round(h, 4)
                row["height_true_m"] = tb["top_height"]
                row["height_rel_err"] = round(abs(h / tb["top_height"] - 1), 5)
                truth_floor = [np.array(b["pixel"]) for b in tb["bbox_corners"] if b["world"][1] == 0.0]
                truth_top = [np.array(c["world"]) - pos for c in tb["top_surface"]["corners"]]
                px = [min(np.linalg.norm(np.array(p) - q) for q in truth_floor) for p in r["floor_corners_px"]]
                wm = [min(np.linalg.norm(np.array(p) - q) for q in truth_top) for p in r["top_world"]]
                row["floor_corner_px_err_max"] = round(max(px), 3)
                row["top_corner_m_err_max"] = round(max(wm), 4)
            elif r["what"] == "slab":
                row.update({"occluder": r["occluder"], "covered": r["covered"], "open_points": r["open_points"],
                            "open": r["open"], "thickness_m": round(r["thickness_m"], 4),
                            "thickness_true_m": tb.get("top_thickness")})
            else:
                alpha = cv2.imread(r["alpha_pgm"], cv2.IMREAD_UNCHANGED).astype(np.float64) / 255.0
                lab = cv2.imread(os.path.join(scene, "labels.png"), cv2.IMREAD_GRAYSCALE) == 7
                p = alpha >= 0.5
                band = cv2.dilate(lab.astype(np.uint8), np.ones((9, 9), np.uint8)) != \
                    cv2.erode(lab.astype(np.uint8), np.ones((9, 9), np.uint8))
                row.update({"segment_ms": round(r["segment_ms"], 1), "matte_ms": round(r["matte_ms"], 1),
                            "iou": round(float((p & lab).sum() / max(1, (p | lab).sum())), 4),
                            "recall": round(float((p & lab).sum() / max(1, lab.sum())), 4),
                            "alpha_mae": round(float(np.abs(alpha - lab).mean()), 5),
                            "alpha_mae_edge_band": round(float(np.abs(alpha - lab)[band].mean()), 4),
                            "lowest_px_y": round(r["lowest_px"][1], 2),
                            "table_lowest_px_y": int(np.nonzero(lab)[0].max()) + 1})
            rows.append(row)
        sd = json.load(open(sj))
        if sd.get("surfaces"):
            # A user's clicks are off by a pixel or so: the outline and the click jittered
            # uniformly in [-J, J] px (default 1), `trials` times (default 20).
            jit = float(opt("--jitter", "1.0"))
            rng = np.random.default_rng(7)
            herr, perr = [], []
            truth_floor = [np.array(b["pixel"]) for b in tb["bbox_corners"] if b["world"][1] == 0.0]
            for k in range(int(opt("--trials", "20"))):
                sdj = dict(sd, occluders=[], surfaces=[dict(x) for x in sd["surfaces"]])
                s0 = sdj["surfaces"][0]
                s0["outline_px"] = [[p[0] + rng.uniform(-jit, jit), p[1] + rng.uniform(-jit, jit)] for p in s0["outline_px"]]
                s0["height_click_px"] = [s0["height_click_px"][0] + rng.uniform(-jit, jit),
                                         s0["height_click_px"][1] + rng.uniform(-jit, jit)]
                sjj = os.path.join(work, "jitter.json")
                json.dump(sdj, open(sjj, "w"))
                for line in subprocess.run([tool, sjj, work, "1"], check=True, capture_output=True, text=True).stdout.splitlines():
                    r = json.loads(line)
                    if r["what"] == "surface" and r["index"] == 0 and "height_m" in r:
                        herr.append(abs(r["height_m"] / tb["top_height"] - 1))
                        perr.append(max(min(np.linalg.norm(np.array(p) - q) for q in truth_floor) for p in r["floor_corners_px"]))
            if herr:
                rows.append({"scene": name, "what": "surface_jitter_%gpx" % jit, "index": 0, "trials": len(herr),
                             "height_rel_err": round(float(np.mean(herr)), 5), "height_rel_err_max": round(float(np.max(herr)), 5),
                             "floor_corner_px_err_max": round(float(np.max(perr)), 3),
                             "floor_corner_px_err_mean_of_max": round(float(np.mean(perr)), 3)})
        if sd.get("occluders"):
            # The matting time at 640 x 480: the photo and the strokes scaled to that size.
            ph = cv2.imread(sd["photo"], cv2.IMREAD_COLOR)
            sx, sy = 640.0 / ph.shape[1], 480.0 / ph.shape[0]
            big = os.path.join(work, "photo_640x480.png")
            cv2.imwrite(big, cv2.resize(ph, (640, 480), interpolation=cv2.INTER_LINEAR))
            scale = lambda strokes: [[[p[0] * sx, p[1] * sy] for p in st] for st in strokes]
            sd640 = dict(sd, photo=big, surfaces=[], objects=[])
            sd640["camera"] = dict(sd["camera"], focal_px=sd["camera"]["focal_px"] * sx,
                                   principal_px=[sd["camera"]["principal_px"][0] * sx, sd["camera"]["principal_px"][1] * sy],
                                   vanishing_points_px=[[v[0] * sx, v[1] * sy] for v in sd["camera"]["vanishing_points_px"]])
            sd640.pop("layout", None)
            sd640["lights"] = []
            sd640["occluders"] = [{"foreground_scribbles_px": scale(o["foreground_scribbles_px"]),
                                   "background_scribbles_px": scale(o["background_scribbles_px"])} for o in sd["occluders"]]
            sj640 = os.path.join(work, "scene_640x480.json")
            json.dump(sd640, open(sj640, "w"))
            w640 = os.path.join(work, "640x480")
            os.makedirs(w640, exist_ok=True)
            for line in subprocess.run([tool, sj640, w640, "1"], check=True, capture_output=True, text=True).stdout.splitlines():
                r = json.loads(line)
                if r["what"] == "occluder":
                    rows.append({"scene": name + "@640x480", "what": "occluder", "index": r["index"],
                                 "ms": round(r["ms"], 1), "cpu_ms": round(r.get("cpu_ms", -1), 1),
                                 "load_avg_1min": round(os.getloadavg()[0], 1),
                                 "segment_ms": round(r.get("segment_ms", -1), 1),
                                 "matte_ms": round(r.get("matte_ms", -1), 1), "error": r.get("error", "")})
        if "--render" in sys.argv[1:]:
            rdir = os.path.join(out, name + "_render")
            res = subprocess.run([sys.executable, harness, "run", scene, os.path.join(build, "app"), rdir,
                                  "--mode", "assisted", "--seconds", seconds], capture_output=True, text=True)
            row = {"scene": name, "what": "render", "index": 0, "render_s": float(seconds)}
            try:
                row.update(json.loads(res.stdout))
            except ValueError:
                row["error"] = (res.stdout + res.stderr)[-300:]
            comps = sorted(glob.glob(os.path.join(rdir, "*.png")), key=os.path.getmtime)
            if comps:
                comp = cv2.imread(comps[-1]).astype(np.float64) / 255
                truth = cv2.imread(os.path.join(scene, "truth.png")).astype(np.float64) / 255
                photo = cv2.imread(os.path.join(scene, "photo.png")).astype(np.float64) / 255
                lab = (cv2.imread(os.path.join(scene, "labels.png"), cv2.IMREAD_GRAYSCALE) == 7).astype(np.uint8)
                obj = cv2.imread(os.path.join(scene, "object_mask.png"), cv2.IMREAD_GRAYSCALE) > 0
                near = cv2.dilate(obj.astype(np.uint8), np.ones((31, 31), np.uint8)) > 0
                edge = (cv2.dilate(lab, np.ones((9, 9), np.uint8)) != cv2.erode(lab, np.ones((9, 9), np.uint8))) & near
                if edge.sum():
                    row["edge_pixels"] = int(edge.sum())
                    row["edge_rmse"] = round(float(np.sqrt(((comp - truth)[edge] ** 2).mean())), 5)
                    row["edge_rmse_do_nothing"] = round(float(np.sqrt(((photo - truth)[edge] ** 2).mean())), 5)
            rows.append(row)
    path = os.path.join(out, "bench_modeling.csv")
    benchlib.write_csv(path, rows, table="modeling")
    for r in rows:
        print(json.dumps(r))
    print("wrote", path)
    plot(rows, os.path.join(out, "bench_modeling.png"))
    return 0


def plot(rows, path):
    """Error against run time: table tops (height error vs extrusion ms), mattes (alpha MAE vs
    matting ms), renders (object RMSE vs the render's seconds)."""
    with benchlib.figure(path, 1, 3, figsize=(13, 4)) as ax:
        if ax is not None:
            scatter_panels(ax, rows)
            print("wrote", path)


def scatter_panels(ax, rows):
    panels = [(ax[0], lambda r: r["what"] == "surface" and "height_rel_err" in r, "ms", "height_rel_err",
               "extrusion (ms, best of N)", "table height, relative error"),
              (ax[1], lambda r: r["what"] == "occluder" and "alpha_mae" in r, "matte_ms", "alpha_mae",
               "grabCut + alphamat (ms)", "matte MAE vs true mask"),
              (ax[2], lambda r: r["what"] == "render" and "object_rmse" in r, "render_s", "object_rmse",
               "render budget (s)", "object RMSE (sRGB)")]
    for a, keep, xk, yk, xl, yl in panels:
        for r in rows:
            if keep(r) and xk in r and yk in r:
                a.scatter([r[xk]], [r[yk]])
                a.annotate(r["scene"], (r[xk], r[yk]), fontsize=7)
        a.set_xlabel(xl)
        a.set_ylabel(yl)
        a.grid(alpha=0.3)


if __name__ == "__main__":
    sys.exit(main())
