#!/usr/bin/python3
"""Can the lighting model tell the camera's response? (the joint-fit cue of issue 16, probed)

The light fit has to reproduce the photo: B = rho_s (sum_j L_j E_j + Gamma) per pixel, one
albedo rho_s per surface. A response that decodes the codes to the room's true radiance should
leave the smallest residual, since the lights' fall-off E_j is fixed by the geometry and a wrong
curve bends it. This script measures whether it does, before the search is built into Inlay.

Every variant of bench_response.py's cameras (../shared/tools/camera_variants.py --seed
1000 * seed + room number) is decoded by each candidate curve into a linear EXR (code 255 -> 1;
the true curve's white taken at code 254.5), handed to `inlay-cli decompose` (harness.py's
assisted scene), and the light fit's scale- and gamma-free residual is read from its stderr
(LightingEstimate::fitResidualRelative: median |log(B / model)| over median |log B - median|).

Candidates: srgb, the camera's true curve (read from camera_variant.json, for scoring only: it is
the reference the cue should prefer), and toe_shoulder members (power, toe, shoulder) given by
--family (default: powers 0.7, 0.85, 1.2, 1.4 and a toe 0.3 and a shoulder 10 on sRGB).

Writes OUT/response_fit.csv (one row per variant and candidate: residual, the candidate's curve
error against the true curve, seconds) and OUT/response_fit_summary.csv (per half: how often the
true curve beats sRGB on the residual, how often the residual's best candidate has a smaller
curve error than sRGB), and OUT/response_fit.png (residual against curve error per variant).

usage: bench_response_fit.py INLAY_CLI [--out DIR] [--seeds 1] [--rooms t01,t03]
                             [--family 0.7/0/0,1.4/0/0]
"""
import json, os, re, statistics, subprocess, sys, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response as br  # noqa: E402
import bench_vignetting as bv  # noqa: E402

FAMILY = "0.7/0/0,0.85/0/0,1.2/0/0,1.4/0/0,1/0.3/0,1/0/10"


def candidate_table(name, cam):
    """The candidate's decode of codes 0..255 (code 255 -> 1)."""
    codes = np.arange(256.0)
    if name == "srgb":
        return bv.srgb_decode(codes / 255.0)
    if name == "true":
        if cam["curve"] == "srgb":
            return bv.srgb_decode(codes / 255.0)
        white = float(br.true_inverse(cam, np.array([254.5]))[0])
        t = br.true_inverse(cam, np.clip(codes, 0.5, 254.5)) / white
        t[0] = 0.0
        return t
    p, t, s = (float(v) for v in name.split("/"))
    return br.family_inverse(codes, p, t, s)


def curve_error(table, cam, hist):
    return br.curve_error(list(table), cam, hist)


def residual_of(cli, harness, d, table, work):
    import cv2
    os.makedirs(work, exist_ok=True)
    sf = os.path.join(work, "scene.json")
    subprocess.run([sys.executable, harness, "scene", d, sf], check=True, capture_output=True)
    codes = cv2.imread(os.path.join(d, "photo.png"), cv2.IMREAD_COLOR)[:, :, ::-1]
    exr = os.path.join(work, "photo.exr")
    bv.write_exr(exr, table[codes])
    j = json.load(open(sf))
    j["photo"] = exr
    json.dump(j, open(sf, "w"), indent=1)
    t0 = time.time()
    r = subprocess.run([cli, "decompose", sf, "--albedo", os.path.join(work, "albedo.exr")],
                       capture_output=True, text=True)
    m = re.search(r"relative residual ([0-9.eE+-]+) \(rms log ([0-9.eE+-]+)\)", r.stderr)
    if r.returncode != 0 or not m:
        sys.stderr.write(r.stderr[-400:])
        return None
    return float(m.group(1)), float(m.group(2)), time.time() - t0


def summarise(rows):
    out = []
    for half in ("A", "B"):
        variants = sorted({(r["room"], r["seed"]) for r in rows if r["half"] == half})
        true_wins, best_better, n = 0, 0, 0
        for v in variants:
            rs = {r["candidate"]: r for r in rows if (r["room"], r["seed"]) == v}
            if "srgb" not in rs or "true" not in rs:
                continue
            n += 1
            true_wins += rs["true"]["residual"] < rs["srgb"]["residual"]
            pick = min((r for k, r in rs.items() if k != "true"), key=lambda r: r["residual"])
            best_better += pick["curve_error"] < rs["srgb"]["curve_error"]
        if n:
            out.append({"half": half, "variants": n, "true_curve_lower_residual_than_srgb": true_wins,
                        "picked_curve_better_than_srgb": best_better})
    return out


def plot(path, rows):
    with benchlib.figure(path, figsize=(6, 4.5)) as ax:
        if ax is None:
            return
        for v in sorted({(r["room"], r["seed"]) for r in rows}):
            rs = [r for r in rows if (r["room"], r["seed"]) == v and r["candidate"] != "true"]
            ax.plot([r["curve_error"] for r in rs], [r["residual"] for r in rs], ".-", lw=0.6,
                    label="%s-s%s" % v)
            t = [r for r in rows if (r["room"], r["seed"]) == v and r["candidate"] == "true"]
            if t:
                ax.plot([0], [t[0]["residual"]], "k*", ms=6)
        ax.set_xlabel("candidate's curve error against the true curve")
        ax.set_ylabel("light fit's relative residual")
        ax.set_title("the joint-fit cue: * = the true curve")
        ax.legend(fontsize=6)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    train, harness, rooms = benchlib.train_rooms(opt, out)
    import cv2
    candidates = ["srgb", "true"] + opt("--family", FAMILY).split(",")
    variants = br.make_variants(train, rooms, opt("--seeds", "1").split(","), os.path.join(out, "variants"))
    rows = []
    for room, seed, d in variants:
        cam = json.load(open(os.path.join(d, "camera_variant.json")))
        hist = np.bincount(cv2.imread(os.path.join(d, "photo.png"), cv2.IMREAD_COLOR).ravel(), minlength=256)
        for name in candidates:
            table = candidate_table(name, cam)
            got = residual_of(cli, harness, d, table, os.path.join(out, "runs", "%s-s%s-%s" % (room, seed, name.replace("/", "_"))))
            if got is None:
                continue
            rows.append({"room": room, "seed": seed, "half": "A" if int(room[1:]) % 2 else "B",
                         "curve": cam["curve"], "candidate": name, "residual": round(got[0], 5),
                         "rms_log": round(got[1], 5), "curve_error": round(curve_error(table, cam, hist), 4),
                         "seconds": round(got[2], 2)})
            print(json.dumps(rows[-1]), flush=True)
            benchlib.write_csv(os.path.join(out, "response_fit.csv"), rows)
    summary = summarise(rows)
    benchlib.write_csv(os.path.join(out, "response_fit_summary.csv"), summary, table="response_fit")
    for s in summary:
        print(s)
    plot(os.path.join(out, "response_fit.png"), rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
