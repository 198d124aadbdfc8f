#!/usr/bin/python3
"""Where on the object its error sits: its outline or its inside; and what the object's shape and
the camera's pixel filter do to it, per room of ../shared/scenes-train.

Per room the harness writes the assisted scene file (harness.py scene, the room's own photo) and
inlay-cli renders it, seed 1, exactly --spp samples (uniform), once per run:
  box           --pixel-filter 0: the box of the pixel (the product's render before the filter)
  bh            --pixel-filter 1.5: Cycles' Blackman-Harris window of 1.5 px (the truth's filter,
                now the default)
  subdivided    the scene's mesh objects (a file, not builtin:) with "subdivide": --levels
                (default 2): the truth renders its meshes as a subdivision surface of the file's
                cage (below)
  subdivided_bh both
--runs picks some (default all; the subdivided runs only on rooms whose object is a mesh file).
Each composite is scored by harness.py score (object RMSE, sRGB [0,1]) and over two parts of the
object: its outline (object_mask.png's coverage between 0.5 and 0.98, or inside but next to a
pixel outside: edge_rmse, edge_share of the squared error) and the rest (inside_rmse).

The object's shape in the truth: truth.json gives the object's axis-aligned box after its yaw
(the box of the turned local box's corners), so the local box's width, depth and height follow
from two linear equations; shape_wd_over_h are those ratios, cage_wd_over_h the mesh file's,
catmull_clark_wd_over_h those of its Catmull-Clark subdivision at 1..4 levels (this script's own
subdivision, boundaries as B-spline curves), for a mesh file only.

Writes OUT/object_shape.csv (one row per room), OUT/object_shape.png (object RMSE per run and
room; edge and inside parts), OUT/object_shape_crops.png (mesh rooms: the truth, the product and
the subdivided render with the filter, and their differences), docs/bench/object_shape.md;
composites stay in OUT.

usage: bench_object_shape.py INLAY_CLI [--out DIR] [--rooms t01,t03|A|B] [--spp 64]
                             [--runs box,bh,...] [--levels 2] [--reuse]
"""
import json, math, os, subprocess, sys
from collections import defaultdict

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"
RUNS = ["box", "bh", "subdivided", "subdivided_bh"]


def read_obj(path):
    v, f = [], []
    for line in open(path):
        if line.startswith("v "):
            v.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("f "):
            f.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return np.array(v), f


def catmull_clark(v, faces):
    """One level of Catmull-Clark (open borders as cubic B-spline curves)."""
    ef = defaultdict(list)
    for fi, f in enumerate(faces):
        for a, b in zip(f, f[1:] + f[:1]):
            ef[(min(a, b), max(a, b))].append(fi)
    fp = np.array([v[f].mean(0) for f in faces])
    ep, border = {}, defaultdict(list)
    for (a, b), fs in ef.items():
        if len(fs) == 2:
            ep[(a, b)] = (v[a] + v[b] + fp[fs[0]] + fp[fs[1]]) / 4
        else:
            ep[(a, b)] = (v[a] + v[b]) / 2
            border[a].append(b), border[b].append(a)
    vf, ve = defaultdict(list), defaultdict(list)
    for fi, f in enumerate(faces):
        for x in f:
            vf[x].append(fi)
    for k in ef:
        ve[k[0]].append(k), ve[k[1]].append(k)
    nv = np.array(v)
    for x in range(len(v)):
        if x in border:
            nb = border[x]
            nv[x] = 0.75 * v[x] + 0.125 * (v[nb[0]] + v[nb[1]]) if len(nb) == 2 else v[x]
        elif vf[x]:
            n = len(vf[x])
            mid = np.mean([(v[a] + v[b]) / 2 for a, b in ve[x]], 0)
            nv[x] = (fp[vf[x]].mean(0) + 2 * mid + (n - 3) * v[x]) / n
    pts, eidx = list(nv), {}
    for k, p in ep.items():
        eidx[k] = len(pts)
        pts.append(p)
    fidx = list(range(len(pts), len(pts) + len(fp)))
    pts += list(fp)
    e = lambda a, b: eidx[(min(a, b), max(a, b))]
    out = [[f[i], e(f[i], f[(i + 1) % len(f)]), fidx[fi], e(f[i - 1], f[i])] for fi, f in enumerate(faces)
           for i in range(len(f))]
    return np.array(pts), out


def ratios(v):
    s = v.max(0) - v.min(0)
    return "%.4f %.4f" % (s[0] / s[1], s[2] / s[1])


def truth_shape(o):
    """The object's local box, width and depth over height, from the yawed box truth.json gives."""
    c, s = math.cos(math.radians(o["rotation_y_deg"])), abs(math.sin(math.radians(o["rotation_y_deg"])))
    bw, bh, bd = (np.array(o["bbox_max"]) - np.array(o["bbox_min"])).tolist()
    det = c * c - s * s
    if abs(det) < 1e-6:
        return ""
    w, d = (bw * c - bd * s) / det, (bd * c - bw * s) / det
    return "%.4f %.4f" % (w / bh, d / bh)


def shape_row(truth, scene):
    row = {"object": truth["object"]["type"], "shape_wd_over_h": truth_shape(truth["object"])}
    mesh = scene["objects"][0]["mesh"]
    if mesh.startswith("builtin:") or not mesh.endswith(".obj"):
        return row
    v, f = read_obj(mesh)
    row["cage_wd_over_h"] = ratios(v)
    cc = []
    for _ in range(4):
        v, f = catmull_clark(v, f)
        cc.append(ratios(v).replace(" ", "/"))
    row["catmull_clark_wd_over_h"] = " ".join(cc)
    return row


def parts(comp_png, room_dir):
    """Object RMSE over the outline and the inside, and the outline's share of the squared error."""
    cov = cv2.imread(os.path.join(room_dir, "object_mask.png"), cv2.IMREAD_GRAYSCALE)
    t = cv2.imread(os.path.join(room_dir, "truth.png"), cv2.IMREAD_COLOR).astype(np.float64) / 255
    o = cv2.imread(comp_png, cv2.IMREAD_COLOR).astype(np.float64) / 255
    mask, full = cov >= 128, cov >= 250
    inside = cv2.erode(full.astype(np.uint8), np.ones((3, 3), np.uint8)) > 0
    edge = mask & ~inside
    e2 = ((o - t) ** 2).mean(2)
    rm = lambda m: round(float(np.sqrt(e2[m].mean())), 4) if m.any() else ""
    return {"edge_rmse": rm(edge), "inside_rmse": rm(mask & inside), "edge_pixels": int(edge.sum()),
            "edge_share": round(float(e2[edge].sum() / max(e2[mask].sum(), 1e-12)), 3)}


def measure_room(cli, tools, room_dir, out, spp, runs, levels, reuse):
    room = os.path.basename(room_dir)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    p = lambda name: os.path.join(out, "%s_%s" % (room, name))
    subprocess.run([PY, os.path.join(tools, "harness.py"), "scene", room_dir, p("scene.json"), "--seconds", "100000"],
                   check=True)
    scene = json.load(open(p("scene.json")))
    row = {"room": room, "half": benchlib.half(room)}
    row.update(shape_row(truth, scene))
    meshes = [o for o in scene["objects"] if not o["mesh"].startswith("builtin:")]
    for o in meshes:
        o["subdivide"] = levels
    json.dump(scene, open(p("scene_subdivided.json"), "w"), indent=1)
    for run in runs:
        if run.startswith("subdivided") and not meshes:
            continue
        sf = p("scene_subdivided.json") if run.startswith("subdivided") else p("scene.json")
        extra = ["--pixel-filter", "1.5" if run.endswith("bh") else "0"]
        png = p(run + ".png")
        if not (reuse and os.path.exists(png)):
            cmd = [cli, "render", sf, "-o", png, "--quiet", "--seed", "1", "--spp", str(spp), "--seconds", "0",
                   "--noise", "0"] + extra
            if subprocess.run(cmd, capture_output=True, text=True).returncode != 0:
                continue
        sc = json.loads(subprocess.run([PY, os.path.join(tools, "harness.py"), "score", room_dir, png],
                                       capture_output=True, text=True, check=True).stdout)
        row[run + "_rmse"] = round(sc["object_rmse"], 4)
        row[run + "_adjusted"] = round(sc["object_rmse_adjusted"], 4)
        row.update({run + "_" + k: v for k, v in parts(png, room_dir).items()})
    return row


def plot(out, rows):
    with benchlib.figure(os.path.join(out, "object_shape.png"), 1, 2, figsize=(12, 3.8)) as ax:
        if ax is None:
            return
        x = np.arange(len(rows))
        for k, run in enumerate(RUNS):
            v = [r.get(run + "_rmse") if isinstance(r.get(run + "_rmse"), float) else np.nan for r in rows]
            ax[0].bar(x + 0.2 * k - 0.3, v, 0.2, label=run)
            e = [r.get(run + "_edge_rmse") if isinstance(r.get(run + "_edge_rmse"), float) else np.nan for r in rows]
            i = [r.get(run + "_inside_rmse") if isinstance(r.get(run + "_inside_rmse"), float) else np.nan
                 for r in rows]
            ax[1].plot(x + 0.2 * k - 0.3, e, "^", color="C%d" % k, label=run + " outline")
            ax[1].plot(x + 0.2 * k - 0.3, i, "o", color="C%d" % k, mfc="none", label=run + " inside")
        for a, title in zip(ax, ["object RMSE per run", "outline (triangles) and inside (circles)"]):
            a.set_xticks(x)
            a.set_xticklabels(["%s\n%s" % (r["room"], r.get("object", "")) for r in rows], fontsize=8)
            a.set_ylabel("RMSE (sRGB)")
            a.set_title(title, fontsize=9)
        ax[0].legend(fontsize=7)


def plot_crops(out, sdir, rows):
    """Rooms whose object is a mesh file: the truth, the product's render and the subdivided one
    with Cycles' filter around the object, and each one's difference to the truth (x3)."""
    rows = [r for r in rows if isinstance(r.get("subdivided_bh_rmse"), float)]
    runs = [("box", "product (the file's cage, box filter)"), ("subdivided_bh", "subdivided, 1.5 px filter")]
    with benchlib.figure(os.path.join(out, "object_shape_crops.png"), len(rows), 5, figsize=(13, 2.8 * len(rows)),
                         squeeze=False) as ax:
        if ax is None:
            return
        for k, r in enumerate(rows):
            room_dir = os.path.join(sdir, r["room"])
            x0, y0, x1, y1 = json.load(open(os.path.join(room_dir, "truth.json")))["object"]["projected_bbox_2d"]
            m = 8
            box = (slice(max(int(y0) - m, 0), int(y1) + m), slice(max(int(x0) - m, 0), int(x1) + m))
            rd = lambda f: cv2.imread(f, cv2.IMREAD_COLOR)[..., ::-1].astype(np.float64)[box] / 255
            t = rd(os.path.join(room_dir, "truth.png"))
            panels = [(t, "%s truth" % r["room"])]
            for run, name in runs:
                o = rd(os.path.join(out, "%s_%s.png" % (r["room"], run)))
                panels += [(o, "%s: %.4f" % (name, r[run + "_rmse"])), (np.clip(0.5 + 3 * (o - t), 0, 1), "x3 difference")]
            for a, (im, title) in zip(ax[k], panels):
                a.imshow(im, interpolation="nearest")
                a.set_title(title, fontsize=7)
                a.axis("off")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    runs = opt("--runs", ",".join(RUNS)).split(",")
    rows_dir = os.path.join(out, "rows")
    os.makedirs(rows_dir, exist_ok=True)
    for room in names:
        row = measure_room(cli, tools, os.path.join(sdir, room), out, int(opt("--spp", "64")), runs,
                           int(opt("--levels", "2")), "--reuse" in sys.argv[1:])
        json.dump(row, open(os.path.join(rows_dir, room + ".json"), "w"))
        print(json.dumps(row), flush=True)
    rows = sorted(benchlib.read_rows(rows_dir), key=lambda r: r["room"])
    cols = ["room", "object", "shape_wd_over_h", "cage_wd_over_h"] + [r + s for r in RUNS for s in ("_rmse", "_edge_rmse",
                                                                                               "_inside_rmse")]
    benchlib.write_csv(os.path.join(out, "object_shape.csv"), rows, table="object_shape", columns=cols)
    plot(out, rows)
    plot_crops(out, sdir, rows)
    print("wrote", os.path.join(out, "object_shape.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
