#!/usr/bin/python3
"""The response estimate's settings on bench_generalization.py's photos: curve error and fit time.

Every variant folder of a bench_generalization.py run (OUT/variants/<room>_<camera>, made by
../shared/tools/camera_variants.py; --variants DIR) and the dev rooms' plain renders
(../shared/scenes/d*/photo.png, truth sRGB) are estimated by `inlay-cli response` for each
setting. Curve error as bench_generalization.py's response_error (the camera_variant.json truth
is read here for scoring only). Settings (NAME=ARGS, ARGS split at '+'):
  colour      --cue colour                    (the edge cue, main's "auto")
  ungated     --cue noise --min-srgb-residual 0
  gate0.3     --cue noise --min-srgb-residual 0.3 --min-improvement 0.2
  gate0.5     --cue noise                     (the noise cue's defaults)
Half A (odd rooms) chooses, half B reports; the dev rooms show false curves on sRGB photos.

Writes OUT/response_gate.csv (one row per photo and setting), OUT/response_gate_summary.csv
(per setting and half: median and mean curve error, photos worse / better than sRGB by 0.01,
median CPU seconds) and OUT/response_gate.png (mean curve error against median fit CPU seconds
per setting and half).

usage: bench_response_gate.py INLAY_CLI --variants DIR [--out OUT] [--settings NAME=ARGS,...]
"""
import glob, json, os, statistics, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_generalization as bg  # noqa: E402

DEFAULT_SETTINGS = ("colour=--cue+colour,ungated=--cue+noise+--min-srgb-residual+0,"
                    "gate0.3=--cue+noise+--min-srgb-residual+0.3+--min-improvement+0.2,gate0.5=--cue+noise")


def curve_error(table, cam):
    ref, est = bg.true_response(cam)[8:248], np.asarray(table, float)[8:248]
    s = float((est * ref).sum() / max((est * est).sum(), 1e-30))
    return float(np.sqrt(np.mean((s * est - ref) ** 2)) / max(ref.mean(), 1e-12))


def photos(variants):
    """(name, half, photo path, camera dict) of every variant and dev room."""
    out = []
    for cj in sorted(glob.glob(os.path.join(variants, "t*_*", "camera_variant.json"))):
        d = os.path.dirname(cj)
        name = os.path.basename(d)
        photo = next(os.path.join(d, f) for f in ("photo.jpg", "photo.png") if os.path.exists(os.path.join(d, f)))
        out.append((name, "A" if int(name[1:3]) % 2 else "B", photo, json.load(open(cj))))
    for p in sorted(glob.glob(os.path.join(benchlib.shared_dir(), "scenes", "d*", "photo.png"))):
        out.append((os.path.basename(os.path.dirname(p))[:2], "dev", p, {"curve": "srgb"}))
    return out


def summarise(rows, settings):
    out = []
    for name, _ in settings:
        for h in ("A", "B", "dev"):
            sel = [r for r in rows if r["setting"] == name and r["half"] == h]
            if sel:
                out.append({"setting": name, "half": h, "photos": len(sel),
                            "median_error": round(statistics.median(r["error"] for r in sel), 4),
                            "mean_error": round(statistics.mean(r["error"] for r in sel), 4),
                            "worse": sum(r["error"] > r["srgb_error"] + 0.01 for r in sel),
                            "better": sum(r["error"] < r["srgb_error"] - 0.01 for r in sel),
                            "median_cpu_s": round(statistics.median(r["cpu_s"] for r in sel), 4)})
    return out


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    variants = opt("--variants", "")
    if not os.path.isdir(variants):
        sys.stderr.write("bench_response_gate.py: --variants DIR (a bench_generalization.py OUT/variants) is required\n")
        return 2
    os.makedirs(out, exist_ok=True)
    settings = [(s.split("=")[0], s.split("=", 1)[1].split("+")) for s in opt("--settings", DEFAULT_SETTINGS).split(",")]
    rows, rj = [], os.path.join(out, "R.json")
    for name, half, photo, cam in photos(variants):
        srgb_error = curve_error(bg.true_response({"curve": "srgb"}), cam)
        for sname, extra in settings:
            p = subprocess.run([cli, "response", photo, "-o", rj, "--quiet"] + extra, capture_output=True, text=True)
            if p.returncode != 0:
                print(name, sname, "failed:", p.stderr.strip()[-200:])
                continue
            j = json.load(open(rj))
            e = j.get("estimate", {})
            rows.append({"photo": name, "half": half, "curve": cam["curve"], "setting": sname,
                         "error": round(curve_error(j["table"], cam), 4), "srgb_error": round(srgb_error, 4),
                         "response": j["description"], "srgb_residual": round(e.get("srgb_objective", 0), 4),
                         "decision": e.get("decision", ""), "cpu_s": round(e.get("cpu_seconds", 0), 4)})
            print(json.dumps(rows[-1]), flush=True)
    benchlib.write_csv(os.path.join(out, "response_gate.csv"), rows)
    summary = summarise(rows, settings)
    benchlib.write_csv(os.path.join(out, "response_gate_summary.csv"), summary)
    for s in summary:
        print(s)
    with benchlib.figure(os.path.join(out, "response_gate.png"), 1, 1, figsize=(7, 4.5)) as ax:
        if ax is not None:
            for h, mk in (("A", "o"), ("B", "s"), ("dev", "^")):
                for k, s in enumerate(x for x in summary if x["half"] == h):
                    ax.plot(s["median_cpu_s"], s["mean_error"], mk, color="C%d" % k,
                            label="%s (%s)" % (s["setting"], h))
            ax.set(xlabel="fit CPU seconds (median per photo)", ylabel="mean curve error",
                   title="response estimate: curve error against fit time")
            ax.legend(fontsize=7, ncol=3)
    return 0


if __name__ == "__main__":
    sys.exit(main())
