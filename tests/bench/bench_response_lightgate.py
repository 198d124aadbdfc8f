#!/usr/bin/python3
"""Does the light fit's residual tell when to trust the noise cue's curve? (issue #16)

The noise cue's evidence gate keeps sRGB on most contrast (sigmoid) cameras although its
ungated curve is right on many of them (docs/camera-response.md). This script measures, through
the pipeline, a second gate: accept the ungated curve when the light fit leaves a smaller
residual with it than with sRGB. Each variant folder of a bench_generalization.py run
(--variants DIR, made by ../shared/tools/camera_variants.py) named by --photos is estimated by
`inlay-cli response PHOTO --cue noise --min-srgb-residual 0 --min-improvement 0` (the candidate:
the curve without the evidence gate and the 50 % acceptance; the shoulder rule stays) and by the
default (today's "auto"), then rendered with camera.response set explicitly to
  srgb       sRGB;
  candidate  the candidate curve (skipped, and sRGB's row reused, when the candidate is sRGB).
Renders: `inlay-cli render --spp N --seconds 0 --noise 0 --seed 1 --lights-json` (the budget of
bench_generalization.py), scored by harness.py score; the lights JSON gives the last light fit's
relative residual (LightingEstimate::fitResidualRelative). camera_variant.json is read only for
the curve's name.

Per photo, the replayed gates choose one of the two renders:
  auto        today's "auto" (the candidate when the default estimate fitted it, else sRGB);
  srgb        sRGB always;
  veto<=K     auto's curve only when its light-fit residual is at most K x sRGB's, else sRGB
              (the evidence gate stays; the light fit can only take a curve away);
  open<=K     the candidate when its light-fit residual is at most K x sRGB's (or auto fitted
              it): the light fit instead of the evidence gate;
  oracle      the better of the two renders (an upper bound no gate can beat).
Writes OUT/response_lightgate.csv (one row per photo: both renders, both residuals, the curves),
OUT/response_lightgate_summary.csv (per gate and half: photos given a curve, plain / camera
medians and their ratio, photos better / worse than auto by 0.005) and OUT/response_lightgate.png
(left: residual ratio against the object RMSE's change per photo; right: cameras / plain per gate
and half). --from-csv merges earlier runs' CSVs (no rendering).

usage: bench_response_lightgate.py INLAY_CLI --variants DIR --photos t01_s2,t03_plain,... [--out OUT]
                                   [--spp 16] [--gates veto<=1.0,open<=1.0,...] [--from-csv A.csv,B.csv]
"""
import json, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response_darkfill as brd  # noqa: E402

PY = "/usr/bin/python3"
OPEN = ["--cue", "noise", "--min-srgb-residual", "0", "--min-improvement", "0"]


def is_srgb(est):
    p = est["parameters"]
    return est["family"] == "srgb" or (p["power"] == 1 and p["toe"] == 0 and p["shoulder"] == 0)


def render(cli, tools, vdir, scene, response, tag, out, spp):
    """Object RMSE and the light fit's residual of `scene` rendered with camera.response `response`."""
    s, lj = benchlib.scene_with_response(scene, response, out, tag)
    p, secs = brd.run([cli, "render", s, "-o", os.path.join(out, tag + ".png"), "--quiet", "--seed", "1", "--spp",
                       str(spp), "--seconds", "0", "--noise", "0", "--lights-json", lj])
    if p.returncode:
        return {"error": p.stderr.strip()[-300:]}
    sc = json.loads(brd.run([PY, os.path.join(tools, "harness.py"), "score", vdir, os.path.join(out, tag + ".png")])[0].stdout)
    fit = json.load(open(lj)).get("fit", {})
    return {"rmse": round(sc["object_rmse"], 4), "residual": fit.get("residual_relative"), "s": round(secs, 1)}


def measure(cli, tools, vdir, name, out, spp):
    cam = json.load(open(os.path.join(vdir, "camera_variant.json")))
    photo = os.path.join(vdir, "photo.png")
    auto = brd.estimate(cli, photo, os.path.join(out, name + "_auto_response.json"), [])
    cand = brd.estimate(cli, photo, os.path.join(out, name + "_candidate_response.json"), OPEN)
    scene = os.path.join(out, name + "_harness.json")
    brd.run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene, "--seconds", "15"])
    row = {"photo": name, "half": benchlib.half(name[:3]), "curve": cam["curve"],
           "auto_fitted": not is_srgb(auto), "candidate": "srgb" if is_srgb(cand) else cand["description"],
           "srgb_residual_noise": round(cand["estimate"]["srgb_objective"], 4)}
    s = render(cli, tools, vdir, scene, "srgb", name + "_srgb", out, spp)
    row.update({"srgb_" + k: v for k, v in s.items()})
    if is_srgb(cand):
        row.update({"candidate_" + k: v for k, v in s.items()})
    else:
        c = render(cli, tools, vdir, scene, dict(family=cand["family"], **cand["parameters"]), name + "_candidate",
                   out, spp)
        row.update({"candidate_" + k: v for k, v in c.items()})
    print(json.dumps(row), flush=True)
    return row


def chosen(r, gate):
    """The object RMSE gate `gate` gives photo row `r`: "auto", "srgb", "oracle", "open<=K" (the
    candidate when its light-fit residual is at most K x sRGB's, or auto fitted it) or "veto<=K"
    (auto's curve only when its light-fit residual is at most K x sRGB's; else sRGB)."""
    s, c = float(r["srgb_rmse"]), float(r["candidate_rmse"])
    fitted = str(r["auto_fitted"]) == "True"
    if gate in ("auto", "srgb", "oracle"):
        return {"auto": c if fitted else s, "srgb": s, "oracle": min(s, c)}[gate]
    kind, k = gate.split("<=")
    rs, rc = float(r["srgb_residual"] or "nan"), float(r["candidate_residual"] or "nan")
    lower = rc <= float(k) * rs
    return c if (lower and (fitted or kind == "open")) or (fitted and kind == "open") else s


def summary(rows, gates):
    out = []
    for g in gates:
        for h in ("A", "B"):
            hr = [r for r in rows if r["half"] == h]
            if not any(r["curve"] == "srgb" for r in hr) or all(r["curve"] == "srgb" for r in hr):
                continue
            plain = [chosen(r, g) for r in hr if r["curve"] == "srgb"]
            cams = [chosen(r, g) for r in hr if r["curve"] != "srgb"]
            d = [chosen(r, g) - chosen(r, "auto") for r in hr]
            fitted = sum(1 for r in hr if r["candidate"] != "srgb" and chosen(r, g) == float(r["candidate_rmse"])
                         and float(r["candidate_rmse"]) != float(r["srgb_rmse"]))
            out.append({"gate": g, "half": h, "photos": len(hr), "given_curve": fitted,
                        **benchlib.cameras_against_plain(plain, cams, d)})
    return out


def plot(rows, summ, path):
    with benchlib.figure(path, 1, 2, figsize=(11, 4.5)) as ax:
        if ax is None:
            return
        for r in rows:
            if r["candidate"] == "srgb" or not r.get("candidate_residual") or not r.get("srgb_residual"):
                continue
            x = float(r["candidate_residual"]) / float(r["srgb_residual"])
            y = float(r["candidate_rmse"]) - float(r["srgb_rmse"])
            colour = ("tab:blue" if r["half"] == "A" else "tab:orange") if r["curve"] != "srgb" else "k"
            ax[0].plot(x, y, "o", color=colour)
            ax[0].annotate(r["photo"], (x, y), fontsize=6)
        ax[0].axhline(0, color="k", lw=0.5)
        ax[0].set_xlabel("light-fit residual, candidate curve / sRGB")
        ax[0].set_ylabel("object RMSE, candidate - sRGB")
        ax[0].set_title("per photo (blue A, orange B, black plain)")
        for h, colour in (("A", "tab:blue"), ("B", "tab:orange")):
            s = [x for x in summ if x["half"] == h]
            ax[1].plot(range(len(s)), [x["ratio"] for x in s], "o-", color=colour, label="half " + h)
            ax[1].set_xticks(range(len(s)), [str(x["gate"]) for x in s], fontsize=7)
        ax[1].axhline(1.25, color="k", ls=":", lw=1)
        ax[1].set_ylabel("cameras / plain median object RMSE")
        ax[1].set_title("per gate (dotted: the issue's 1.25)")
        ax[1].legend()


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    gates = ["auto", "srgb"] + opt("--gates", "veto<=0.95,veto<=1.0,open<=0.95,open<=1.0").split(",") + ["oracle"]
    rows = []
    if opt("--from-csv", ""):
        rows = benchlib.rows_of_csvs(opt("--from-csv", ""))
    else:
        if not opt("--variants", "") or not opt("--photos", ""):
            sys.stderr.write("bench_response_lightgate.py: --variants DIR and --photos NAMES are needed\n")
            return 2
        tools = os.path.join(benchlib.shared_dir(), "tools")
        for name in opt("--photos", "").split(","):
            rows.append(measure(cli, tools, os.path.join(opt("--variants", ""), name), name, out,
                                int(opt("--spp", "16"))))
    summ = summary(rows, gates)
    benchlib.write_rows_and_summary(out, "response_lightgate", rows, summ, plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
