#!/usr/bin/python3
"""The York horizon AUC's ceilings: what perfect lines would score, with and without the truth's
calibration (Debian's python3 with numpy).

usage: bench_camera_ceiling.py YORK_DIR [OUT.csv]

score_york.py's truth horizon is the line through the two horizontal vanishing points of the
database's orthogonalised directions, imaged with its calibrated focal length and principal point.
Those directions behave as the nearest rotation (SVD) to three independently fitted directions,
one per hand-labelled family. This script scores, against that truth and exactly as score_york.py
does (error at the left and right borders over the height, AUC up to 0.25), horizons built from the
hand-labelled segments alone, each under a stated calibration:
  labelled_svd_truthK      per-family fit, SVD, truth focal and principal point (reproduces truth)
  labelled_svd_centredPP   the same with the principal point at the image centre, truth focal
  labelled_svd_centredPP_len
                           the same, segments weighted by length
  labelled_vp_line         the line through the two labelled horizontal vanishing points (needs
                           no principal point or focal length)
  labelled_vertical_truthK the horizon as the polar of the labelled vertical direction
An estimator that holds the principal point at the image centre cannot beat the centred rows with
perfect lines and the exact focal length; it is the ceiling stated in README.
"""
import csv, glob, json, os, sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402


def auc(err):
    err = np.asarray(err)
    xs = np.linspace(0, 0.25, 251)
    return float(np.trapz([(err <= x).mean() for x in xs], xs) / 0.25)


def K_of(f, pp):
    return np.array([[f, 0, pp[0]], [0, -f, pp[1]], [0, 0, 1.0]])  # camera y up, pixel v down


def horizon_error(line, truth_line, W, H):
    v = lambda l, u: -(l[0] * u + l[2]) / l[1]
    return max(abs(v(line, u) - v(truth_line, u)) / H for u in (0.0, W))


def family_direction(segs, Kinv, length_power):
    """Direction minimising sum w (n . d)^2 over the segments' interpretation-plane normals."""
    a = np.c_[segs[:, 0:2], np.ones(len(segs))] @ Kinv.T
    b = np.c_[segs[:, 2:4], np.ones(len(segs))] @ Kinv.T
    n = np.cross(a, b)
    n /= np.linalg.norm(n, axis=1)[:, None]
    w = np.hypot(segs[:, 2] - segs[:, 0], segs[:, 3] - segs[:, 1]) ** length_power
    return np.linalg.eigh((n * w[:, None]).T @ n)[1][:, 0]


def nearest_rotation(dirs):
    u, _, vt = np.linalg.svd(np.asarray(dirs).T)
    return (u @ vt).T


def svd_horizon(segs, K, length_power):
    Kinv = np.linalg.inv(K)
    d = nearest_rotation([family_direction(segs[segs[:, 4] == k], Kinv, length_power) for k in (1, 2, 3)])
    vertical = d[int(np.argmax(np.abs(d[:, 1])))]
    return Kinv.T @ vertical  # image of the plane orthogonal to the vertical


def main():
    york = benchlib.args(__doc__)[0]
    rows = []
    for jf in sorted(glob.glob(os.path.join(york, "*.json"))):
        t = json.load(open(jf))
        W, H = t["width"], t["height"]
        f, pp = t["camera"]["focal_px"], np.array(t["camera"]["principal_px"])
        K = K_of(f, pp)
        dirs = np.array(t["vanishing_directions_orthogonal_camera"], float)
        vi = int(np.argmax(np.abs(dirs[:, 1])))
        hz = [K @ d for k, d in enumerate(dirs) if k != vi]
        truth = np.cross(hz[0], hz[1])
        segs = np.array(t["segments_px"], float)
        if any((segs[:, 4] == k).sum() < 2 for k in (1, 2, 3)):
            continue
        Kc = K_of(f, [W / 2, H / 2])
        raw = np.array(t["vanishing_directions_camera"], float)
        rv = int(np.argmax(np.abs(raw[:, 1])))
        vps = [K @ d for d in raw]
        row = {"image": t["image"]}
        row["labelled_svd_truthK"] = horizon_error(svd_horizon(segs, K, 0), truth, W, H)
        row["labelled_svd_centredPP"] = horizon_error(svd_horizon(segs, Kc, 0), truth, W, H)
        row["labelled_svd_centredPP_len"] = horizon_error(svd_horizon(segs, Kc, 1), truth, W, H)
        row["labelled_vp_line"] = horizon_error(np.cross(vps[(rv + 1) % 3], vps[(rv + 2) % 3]), truth, W, H)
        row["labelled_vertical_truthK"] = horizon_error(np.linalg.inv(K).T @ raw[rv], truth, W, H)
        rows.append(row)
    keys = [k for k in rows[0] if k != "image"]
    summary = {"images": len(rows)}
    summary.update({k + "_auc": round(auc([r[k] for r in rows]), 4) for k in keys})
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w") as fh:
            w = csv.DictWriter(fh, fieldnames=["image"] + keys)
            w.writeheader()
            w.writerows(rows)
    benchlib.write_table("camera_ceiling", [summary])
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
