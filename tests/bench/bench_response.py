#!/usr/bin/python3
"""The camera response estimated from the photo alone, against the true curve of random cameras.

Every room of ../shared/scenes-train is re-photographed through --seeds random cameras
(../shared/tools/camera_variants.py --seed 1000 * seed + room number, so every room and seed
has its own camera; its --plain sRGB encoding too, as seed "plain"), into
OUT/variants/<room>-s<seed> (made once, reused). `inlay-cli response` estimates each photo's
response for every setting of --cues x --priors (the cue the edges are measured with and the
weight of the pull toward sRGB); "srgb" is reading every photo as sRGB (the old behaviour).

Curve error: the estimated code -> linear table against the true camera's inverse tone curve at
the same codes (camera_variant.json, read here for scoring only; Inlay never sees it), after
the best scale (exposure and white balance are not identifiable from one photo), as an RMSE
relative to the true values' RMS, over the codes the photo uses (weighted by its histogram of
all three channels, clipped code 255 left out).

--harness N (instead of the curves): harness.py's object RMSE of the first N half-B variants
rendered (--seconds S, default 20) with camera.response "srgb", "auto" and the true curve's
nearest toe_shoulder member, and the last again on the same camera with its vignetting off
(does vignetting matter once the curve is right?), and the rooms' plain photos with "auto"
(the object RMSE a camera is compared with), to OUT/response_harness.csv; --modes picks among
plain, srgb, auto, true_curve, true_curve_no_vignetting.

The setting is chosen on half A (odd rooms t01, t03, ... t13) by the median curve error (ties: the
mean) and reported on half B (even rooms), so no setting is tuned to the rooms it is judged on. Fit time
is inlay-cli's own measurement of the estimate (seconds in RESPONSE.json).

Writes OUT/response.csv (one row per photo and setting), OUT/response_summary.csv (per setting
and half: median and mean curve error, median and 90th-percentile seconds) and
OUT/response.png (curve error against fit time per setting and half, and the chosen
setting's curves on B).

usage: bench_response.py INLAY_CLI [--out DIR] [--seeds 1,2,3] [--cues symmetry,colour,both]
                         [--priors 0.02,0.2,2] [--settings colour@0.2,symmetry@0.02] [--rooms t01,t02]
                         [--harness N --seconds S --modes plain,srgb,auto,true_curve]
"""
import json, os, statistics, subprocess, sys

import cv2
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def tone(x, cam):
    """camera_variants.py's tone curve (the truth)."""
    if cam["curve"] == "srgb":
        x = np.clip(x, 0, 1)
        return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    if cam["curve"] == "gamma":
        y = np.clip(x, 0, 1) ** (1 / cam["gamma"])
    elif cam["curve"] == "reinhard":
        w2 = cam["white"] ** 2
        y = np.clip(x * (1 + x / w2) / (1 + x), 0, 1) ** (1 / cam["gamma"])
    else:
        lx = np.log2(np.maximum(x, 1e-6) / 0.18)
        y = (1 / (1 + np.exp(-cam["contrast"] * lx * 0.7))) ** (2.2 / cam["gamma"])
    return np.clip(y, 0, 1)


def true_inverse(cam, codes):
    """Radiance x with tone(x) = code / 255 (bisection in log x)."""
    y = codes / 255.0
    lo, hi = np.full(y.shape, 1e-9), np.full(y.shape, 1e6)
    for _ in range(100):
        m = np.sqrt(lo * hi)
        below = tone(m, cam) < y
        lo, hi = np.where(below, m, lo), np.where(below, hi, m)
    return np.sqrt(lo * hi)


def curve_error(table, cam, hist):
    """Relative RMSE of the best-scaled estimated table against the truth, histogram-weighted."""
    codes = np.arange(1, 255)
    w = hist[1:255].astype(np.float64)
    t = true_inverse(cam, codes.astype(np.float64))
    e = np.asarray(table, np.float64)[1:255]
    s = np.sum(w * e * t) / max(np.sum(w * e * e), 1e-30)
    return float(np.sqrt(np.sum(w * (s * e - t) ** 2) / np.sum(w * t * t)))


def family_inverse(codes, p, t, s):
    """The toe_shoulder family's decode (response.h), for fitting it to a true curve."""
    y = np.clip(codes / 255.0, 0, 1)
    u = np.where(y <= 0.04045, y / 12.92, ((y + 0.055) / 1.055) ** 2.4)
    u = u / (1 + s - s * u)
    u = (u + np.sqrt(u * u + 4 * (1 + t) * u * t)) / (2 * (1 + t))
    return u ** (1 / p)


def true_family_params(cam):
    """The toe_shoulder parameters nearest the true curve (codes 1..250, best scale): a grid."""
    codes = np.arange(1, 251).astype(np.float64)
    truth = true_inverse(cam, codes)
    best = (1e9, (1.0, 0.0, 0.0))
    for p in np.arange(0.4, 2.5, 0.02):
        for t in (0, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0, 1.5, 2.0):
            for s in (0, 0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000):
                e = family_inverse(codes, p, t, s)
                k = np.dot(e, truth) / np.dot(e, e)
                err = np.sqrt(np.mean((k * e - truth) ** 2))
                if err < best[0]:
                    best = (err, (float(p), float(t), float(s)))
    return best[1]


def harness_runs(cli, variants, count, seconds, out, modes):
    """Object RMSE by harness.py with camera.response srgb, auto and the true curve's nearest
    family member (and that curve without the camera's vignetting), on the first `count` half-B
    variants (random cameras), and each of their rooms' plain photo with auto (mode plain)."""
    harness = os.path.join(benchlib.shared_dir(), "tools", "harness.py")
    rows = []
    picked = [v for v in variants if v[1] != "plain" and int(v[0][1:]) % 2 == 0][:count]
    if "plain" in modes:
        rooms = []
        for v in picked:
            rooms += [v[0]] if v[0] not in rooms else []
        picked = [v for r in rooms for v in variants if v[0] == r and v[1] == "plain"] + picked
    train = os.path.join(benchlib.shared_dir(), "scenes-train")
    for room, seed, d in picked:
        cam = json.load(open(os.path.join(d, "camera_variant.json")))
        todo = []
        if seed == "plain":
            todo = [("plain", "auto", d)]
        else:
            p, t, s = true_family_params(cam)
            true_curve = {"family": "toe_shoulder", "power": p, "toe": t, "shoulder": s}
            todo = [("srgb", "srgb", d), ("auto", "auto", d), ("true_curve", true_curve, d)]
            if "true_curve_no_vignetting" in modes:
                flat = without_vignetting(os.path.join(train, room), d, 1000 * int(seed) + int(room[1:]),
                                          d + "-novignette")
                todo.append(("true_curve_no_vignetting", true_curve, flat))
        for mode, response, d in [m for m in todo if m[0] in modes]:
            work = os.path.join(out, "harness", "%s-s%s-%s" % (room, seed, mode))
            os.makedirs(work, exist_ok=True)
            sf = os.path.join(work, "scene.json")
            subprocess.run([sys.executable, harness, "scene", d, sf, "--seconds", str(seconds)], check=True)
            j = json.load(open(sf))
            j["camera"]["response"] = response
            json.dump(j, open(sf, "w"), indent=1)
            comp = os.path.join(work, "composite.png")
            r = subprocess.run([cli, "render", sf, "-o", comp], capture_output=True, text=True)
            if r.returncode != 0:
                sys.stderr.write(r.stderr[-400:])
                continue
            score = json.loads(subprocess.run([sys.executable, harness, "score", d, comp], capture_output=True,
                                              text=True, check=True).stdout)
            line = [l for l in r.stderr.splitlines() if "camera response" in l]
            rows.append({"room": room, "seed": seed, "curve": cam["curve"], "response": mode,
                         "used": line[0].split("camera response: ")[1] if line else "",
                         "object_rmse": round(score["object_rmse"], 4),
                         "object_rmse_adjusted": round(score["object_rmse_adjusted"], 4),
                         "around_rmse": round(score["around_rmse"], 4),
                         "around_rmse_do_nothing": round(score["around_rmse_do_nothing"], 4)})
            print(json.dumps(rows[-1]), flush=True)
    benchlib.write_csv(os.path.join(out, "response_harness.csv"), rows)


def without_vignetting(room_dir, variant_dir, seed, out):
    """The variant's camera (same seed: same curve, noise field, JPEG) with its vignetting off."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "camera_variants", os.path.join(benchlib.shared_dir(), "tools", "camera_variants.py"))
    cv = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cv)
    rng = np.random.default_rng(seed)
    cam = cv.draw_camera(rng)
    cam["vignetting"] = 0.0
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    photo = cv.read_exr(os.path.join(room_dir, "photo_linear.exr"))
    with_object = cv.read_exr(os.path.join(room_dir, "truth_linear.exr"))
    noise = rng.standard_normal(photo.shape)
    os.makedirs(out, exist_ok=True)
    for name in os.listdir(variant_dir):
        if name not in ("photo.png", "photo.jpg", "truth.png", "camera_variant.json") and \
                not os.path.lexists(os.path.join(out, name)):
            os.symlink(os.path.realpath(os.path.join(variant_dir, name)), os.path.join(out, name))
    for image, stem in ((photo, "photo"), (with_object, "truth")):
        pixels = cv.encode(image, truth["exposure"]["scale"], cam, noise, np.ones(photo.shape[:2]))
        bgr = np.ascontiguousarray(pixels[:, :, ::-1])
        if cam["jpeg_quality"]:
            bgr = cv2.imdecode(cv2.imencode(".jpg", bgr, [cv2.IMWRITE_JPEG_QUALITY, cam["jpeg_quality"]])[1],
                               cv2.IMREAD_COLOR)
        cv2.imwrite(os.path.join(out, stem + ".png"), bgr)
    json.dump(cam, open(os.path.join(out, "camera_variant.json"), "w"), indent=1)
    return out


def make_variants(train, rooms, seeds, vdir):
    tool = os.path.join(benchlib.shared_dir(), "tools", "camera_variants.py")
    out = []
    for r in rooms:
        for s in seeds:
            d = os.path.join(vdir, "%s-s%s" % (r, s))
            if not os.path.exists(os.path.join(d, "camera_variant.json")):
                # camera_variants.py draws the camera from its seed alone: one per room and seed
                extra = ["--plain"] if s == "plain" else ["--seed", str(1000 * int(s) + int(r[1:]))]
                subprocess.run([sys.executable, tool, os.path.join(train, r), d] + extra, check=True,
                               capture_output=True)
            out.append((r, s, d))
    return out


def estimate(cli, photo, cue, prior, tmp):
    """inlay-cli response's table, seconds and JSON (None when it failed)."""
    out = os.path.join(tmp, "response.json")
    if cue == "srgb":
        return [((k / 255 + 0.055) / 1.055) ** 2.4 if k / 255 > 0.04045 else k / 255 / 12.92
                for k in range(256)], 0.0, {}
    p = subprocess.run([cli, "response", photo, "-o", out, "--cue", cue, "--prior", str(prior), "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write(p.stderr)
        return None, 0.0, {}
    j = json.load(open(out))
    return j["table"], j.get("estimate", {}).get("seconds", 0.0), j


def summarise(rows):
    out = []
    keys = sorted({(r["setting"], r["half"]) for r in rows})
    for setting, half in keys:
        sel = [r for r in rows if r["setting"] == setting and r["half"] == half]
        errs = [r["curve_error"] for r in sel]
        secs = sorted(r["seconds"] for r in sel)
        out.append({"setting": setting, "half": half, "photos": len(sel),
                    "median_curve_error": round(statistics.median(errs), 4),
                    "mean_curve_error": round(statistics.mean(errs), 4),
                    "worst_curve_error": round(max(errs), 4),
                    "undetermined": sum(1 for r in sel if not r["determined"]),
                    "median_seconds": round(statistics.median(secs), 4),
                    "p90_seconds": round(secs[int(0.9 * (len(secs) - 1))], 4)})
    return out


def plot(path, summary, rows, chosen):
    with benchlib.figure(path, 1, 2, figsize=(12, 4.8)) as ax:
        if ax is None:
            return
        for s in summary:
            mark = "o" if s["half"] == "A" else "s"
            ax[0].scatter(s["median_seconds"], s["median_curve_error"], marker=mark)
            ax[0].annotate("%s %s" % (s["setting"], s["half"]), (s["median_seconds"], s["median_curve_error"]),
                           fontsize=7)
        ax[0].set_xlabel("fit time, median s (inlay-cli response)")
        ax[0].set_ylabel("median relative curve RMSE")
        ax[0].set_yscale("log")
        ax[0].set_title("curve error against fit time (o: half A, s: half B)")
        codes = np.arange(256)
        for r in [r for r in rows if r["setting"] == chosen and r["half"] == "B"][:12]:
            cam = json.load(open(os.path.join(r["dir"], "camera_variant.json")))
            t = true_inverse(cam, np.maximum(codes, 0.5).astype(np.float64))
            e = np.asarray(r["table"])
            s = np.sum(e[1:250] * t[1:250]) / np.sum(e[1:250] ** 2)
            line, = ax[1].plot(codes[:250], t[:250], "-", lw=1)
            ax[1].plot(codes[:250], s * e[:250], "--", lw=1, color=line.get_color())
        ax[1].set_yscale("log")
        ax[1].set_xlabel("code")
        ax[1].set_ylabel("linear radiance (truth solid, estimate dashed, best scale)")
        ax[1].set_title("half B curves, setting " + chosen)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    train, _, rooms = benchlib.train_rooms(opt, out)
    seeds = opt("--seeds", "1,2,3").split(",") + ["plain"]
    cues = opt("--cues", "symmetry,colour,both").split(",")
    priors = [float(p) for p in opt("--priors", "0.02,0.2,2").split(",")]
    settings = [("srgb", 0.0)] + [(c, p) for c in cues for p in priors]
    if opt("--settings", ""):  # explicit CUE@PRIOR list instead of the product
        settings = [("srgb", 0.0)] + [(x.split("@")[0], float(x.split("@")[1])) for x in opt("--settings", "").split(",")]
    variants = make_variants(train, rooms, seeds, os.path.join(out, "variants"))
    if int(opt("--harness", "0")) > 0:
        modes = opt("--modes", "plain,srgb,auto,true_curve,true_curve_no_vignetting").split(",")
        harness_runs(cli, variants, int(opt("--harness", "0")), float(opt("--seconds", "20")), out, modes)
        return 0
    rows = []
    for room, seed, d in variants:
        cam = json.load(open(os.path.join(d, "camera_variant.json")))
        img = cv2.imread(os.path.join(d, "photo.png"), cv2.IMREAD_COLOR)
        hist = np.bincount(img.ravel(), minlength=256)
        half = "A" if int(room[1:]) % 2 == 1 else "B"
        for cue, prior in settings:
            table, sec, j = estimate(cli, os.path.join(d, "photo.png"), cue, prior, out)
            if table is None:
                continue
            name = cue if cue == "srgb" else "%s@%g" % (cue, prior)
            err = curve_error(table, cam, hist)
            est = j.get("estimate", {})
            rows.append({"room": room, "seed": seed, "half": half, "curve": cam["curve"], "setting": name,
                         "vignetting": cam.get("vignetting", 0.0), "jpeg_quality": cam.get("jpeg_quality", 0),
                         "cpu_seconds": round(est.get("cpu_seconds", 0.0), 4),
                         "curve_error": round(err, 5), "seconds": round(sec, 4),
                         "determined": est.get("determined", cue == "srgb"),
                         "edges": est.get("edges_used", 0), "family": j.get("description", "srgb"),
                         "dir": d, "table": table})
            print("%s %s/%s %-8s %-16s err %.4f %5.3f s %s" % (half, room, seed, cam["curve"], name, err, sec,
                                                            j.get("description", "")), flush=True)
    benchlib.write_csv(os.path.join(out, "response.csv"),
                       [{k: v for k, v in r.items() if k not in ("table", "dir")} for r in rows])
    summary = summarise(rows)
    a_rows = [s for s in summary if s["half"] == "A" and s["setting"] != "srgb"]
    chosen = min(a_rows, key=lambda s: (s["median_curve_error"], s["mean_curve_error"]))["setting"] if a_rows else "srgb"
    for s in summary:
        s["chosen_on_A"] = s["setting"] == chosen
    benchlib.write_csv(os.path.join(out, "response_summary.csv"), summary, table="response")
    plot(os.path.join(out, "response.png"), summary, rows, chosen)
    print("chosen on half A:", chosen)
    for s in summary:
        if s["setting"] in (chosen, "srgb"):
            print(json.dumps(s))
    return 0


if __name__ == "__main__":
    sys.exit(main())
