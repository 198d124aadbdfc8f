#!/usr/bin/python3
"""Does the light fit's residual, with the noise cue's, see the camera curve's power? (issue #16)

The noise cue cannot see a pure power change of the curve (a power maps a quadratic noise
variance onto a nearly quadratic one), and "auto" keeps the power of sRGB or of the noise cue's
curve. The light fit's model is additive (the lights' irradiance plus the gathered light, times
one albedo per surface), and a power change of the decoded radiance is not: so its residual
might see the power where the noise cannot (docs/camera-response.md, tenth round). This script
measures it through the pipeline, per photo of a bench_generalization.py variant folder:

  auto     `inlay-cli render` with camera.response "auto" (today's product); the curve it used is
           read from the CLI's `camera response:` line;
  xM       the same curve with its power multiplied by M (--scan, default 0.6,0.8,1.25; clamped
           to the family's [0.4, 2.5]), as an explicit camera.response (so no estimate and no
           light-fit check run).

Every render: `inlay-cli render --spp N --seconds 0 --noise 0 --seed 1 --lights-json`, scored by
harness.py score (object RMSE); the lights JSON gives the last light fit's relative residual
(LightingEstimate::fitResidualRelative); `inlay-cli response --cue noise --evaluate-at P,T,S`
gives the noise cue's objective at each curve. camera_variant.json is read for the curve's name
only.

The replayed rules choose one render per photo:
  auto              today's "auto";
  light<=K          the scanned power whose light-fit residual is lowest, when it is at most K x
                    auto's, else auto;
  joint:W<=K        the lowest  residual / auto's residual + W x (noise objective - auto's), when
                    it is at most K, else auto (the noise cue's likelihood as the power's prior);
  oracle            the best render of the scan (no rule can beat it).
Writes OUT/response_power_scan.csv (a row per photo), OUT/response_power_scan_summary.csv (per
rule and half: plain and camera medians, their ratio, photos better / worse than auto by 0.005,
photos whose power moved) and OUT/response_power_scan.png (left: per photo, the residual ratio
of each scanned power against its object RMSE change; right: cameras / plain per rule and half).
--from-csv merges earlier runs' CSVs (no rendering).

--york P1020177,P1080015 instead scans York photos (a scene of the photo alone, as
bench_response_check_cost.py makes it; no truth, so no object RMSE): per photo and power the light
fit's residual, the noise objective and whether the curve is plausible by bench_response_york.py's
rule (at most 6 stops between codes 128 and 254, code 128 within 1/4-4 of sRGB's value); writes
OUT/response_power_scan_york.csv and prints, per rule, the power it picks and that curve's
plausibility.

usage: bench_response_power_scan.py INLAY_CLI --variants DIR --photos t01_s1,t01_plain,... [--out OUT]
                                    [--spp 8] [--scan 0.6,0.8,1.25] [--rules light<=1.0,joint:0.1<=0.95]
                                    [--from-csv A.csv,B.csv]
       bench_response_power_scan.py INLAY_CLI --york P1020177,... [--spp 1] [--scan ...] [--out OUT]
"""
import json, math, os, re, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"
CURVE = re.compile(r"camera response: toe_shoulder \(power ([0-9.]+), toe ([0-9.]+), shoulder ([0-9.e+]+)\)")
DEFAULT_RULES = "light<=1.0,light<=0.95,joint:0.1<=1.0,joint:0.1<=0.95,joint:0.3<=0.95,joint:1<=0.95"


def run(cmd, timeout=7200):
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    return p, time.time() - t0


def used_curve(stderr):
    """(power, toe, shoulder) of the curve the CLI's render used; sRGB is (1, 0, 0)."""
    m = CURVE.search(stderr)
    return (float(m.group(1)), float(m.group(2)), float(m.group(3))) if m else (1.0, 0.0, 0.0)


def noise_objective(cli, photo, curve, out_json):
    """The noise cue's objective at `curve` (inlay-cli response --evaluate-at); NaN when undetermined."""
    p, _ = run([cli, "response", photo, "-o", out_json, "--quiet", "--cue", "noise", "--evaluate-at",
                "%.6g,%.6g,%.6g" % curve])
    if p.returncode:
        return float("nan")
    e = json.load(open(out_json)).get("estimate", {})
    v = e.get("objective")
    return float(v) if v is not None else float("nan")


def render(cli, tools, vdir, scene, response, tag, out, spp):
    """Object RMSE, the light fit's residual and the used curve of `scene` rendered with `response`."""
    s, lj = benchlib.scene_with_response(scene, response, out, tag)
    comp = os.path.join(out, tag + ".png")
    p, secs = run([cli, "render", s, "-o", comp, "--seed", "1", "--spp", str(spp), "--seconds", "0", "--noise", "0",
                   "--lights-json", lj])
    if p.returncode:
        return {"error": p.stderr.strip()[-300:]}
    sc = json.loads(run([PY, os.path.join(tools, "harness.py"), "score", vdir, comp])[0].stdout)
    fit = json.load(open(lj)).get("fit", {})
    return {"rmse": round(sc["object_rmse"], 4), "residual": fit.get("residual_relative"), "s": round(secs, 1),
            "curve": used_curve(p.stderr)}


def measure(cli, tools, vdir, name, out, spp, scan):
    cam = json.load(open(os.path.join(vdir, "camera_variant.json")))
    photo = os.path.join(vdir, "photo.png")
    scene = os.path.join(out, name + "_harness.json")
    run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene, "--seconds", "15"])
    a = render(cli, tools, vdir, scene, "auto", name + "_auto", out, spp)
    if "error" in a:
        print(name, a["error"], file=sys.stderr)
        return None
    p0, t0, s0 = a["curve"]
    row = {"photo": name, "half": benchlib.half(name[:3]), "curve": cam["curve"], "auto_power": p0, "auto_toe": t0,
           "auto_shoulder": s0, "rmse_x1": a["rmse"], "residual_x1": a["residual"], "s_x1": a["s"],
           "noise_x1": round(noise_objective(cli, photo, a["curve"], os.path.join(out, name + "_n1.json")), 5)}
    for m in scan:
        c = (min(2.5, max(0.4, p0 * m)), t0, s0)
        r = render(cli, tools, vdir, scene, {"family": "toe_shoulder", "power": c[0], "toe": t0, "shoulder": s0},
                   "%s_x%g" % (name, m), out, spp)
        k = "x%g" % m
        row.update({"rmse_" + k: r.get("rmse"), "residual_" + k: r.get("residual"), "s_" + k: r.get("s"),
                    "noise_" + k: round(noise_objective(cli, photo, c, os.path.join(out, name + "_n.json")), 5)})
    print(json.dumps(row), flush=True)
    return row


def plausible(cli, scene, curve, out_json):
    """(stops between codes 128 and 254, code 128 over sRGB's, plausible) of `curve` as
    bench_response_york.py judges it, from `inlay-cli response` with the curve set explicitly."""
    j = json.load(open(scene))
    j.setdefault("camera", {})["response"] = {"family": "toe_shoulder", "power": curve[0], "toe": curve[1],
                                              "shoulder": curve[2]}
    s = out_json[:-5] + "_scene.json"
    json.dump(j, open(s, "w"))
    run([cli, "response", s, "-o", out_json, "--quiet"])
    t = json.load(open(out_json))["table"]
    t = [sum(v) / len(v) if isinstance(v, list) else v for v in t]
    srgb128 = ((128 / 255 + 0.055) / 1.055) ** 2.4
    stops, mid = math.log2(max(t[254], 1e-30) / max(t[128], 1e-30)), t[128] / srgb128
    return round(stops, 3), round(mid, 4), stops <= 6 and 0.25 <= mid <= 4


def measure_york(cli, york, name, out, spp, scan):
    """The power scan of York photo `name`: residuals, noise objectives and plausibility, no score."""
    scene = os.path.join(out, name + "_scene.json")
    photo = os.path.join(york, name + ".jpg")
    json.dump({"format": "inlay-scene", "version": 1, "photo": photo}, open(scene, "w"))
    row = {"photo": name, "half": "York", "curve": "unknown"}
    for m in [1.0] + scan:
        k = "x%g" % m
        if m == 1.0:
            p, secs = run([cli, "render", scene, "-o", os.path.join(out, name + "_x1.png"), "--seed", "1", "--spp",
                           str(spp), "--seconds", "0", "--noise", "0", "--lights-json", os.path.join(out, name + "_l.json")])
            if p.returncode:
                print(name, p.stderr.strip()[-300:], file=sys.stderr)
                return None
            c0 = used_curve(p.stderr)
            row.update({"auto_power": c0[0], "auto_toe": c0[1], "auto_shoulder": c0[2]})
            c, resp = c0, "auto"
        else:
            c = (min(2.5, max(0.4, c0[0] * m)), c0[1], c0[2])
            resp = {"family": "toe_shoulder", "power": c[0], "toe": c[1], "shoulder": c[2]}
            j = {"format": "inlay-scene", "version": 1, "photo": photo, "camera": {"response": resp}}
            sc = os.path.join(out, "%s_%s.json" % (name, k))
            json.dump(j, open(sc, "w"))
            p, secs = run([cli, "render", sc, "-o", os.path.join(out, "%s_%s.png" % (name, k)), "--seed", "1",
                           "--spp", str(spp), "--seconds", "0", "--noise", "0", "--lights-json",
                           os.path.join(out, name + "_l.json")])
        fit = json.load(open(os.path.join(out, name + "_l.json"))).get("fit", {}) if not p.returncode else {}
        stops, mid, ok = plausible(cli, scene, c, os.path.join(out, "%s_%s_resp.json" % (name, k)))
        row.update({"residual_" + k: fit.get("residual_relative"), "s_" + k: round(secs, 1),
                    "noise_" + k: round(noise_objective(cli, photo, c, os.path.join(out, name + "_n.json")), 5),
                    "stops_" + k: stops, "mid_" + k: mid, "plausible_" + k: ok, "rmse_" + k: ""})
    print(json.dumps(row), flush=True)
    return row


def york_choices(rows, rules):
    """Per York photo and rule: the power picked and whether its curve is plausible."""
    out = []
    for r in rows:
        for rule in rules:
            if rule == "oracle":
                continue
            k = choice(r, rule)
            out.append({"photo": r["photo"], "rule": rule, "picked": k, "plausible": r["plausible_" + k]})
    return out


def keys_of(r):
    return sorted({k[len("residual_"):] for k in r if k.startswith("residual_") and r[k] not in (None, "")},
                  key=lambda k: float(k[1:]))


def num(v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return float("nan")
    return x


def choice(r, rule):
    """The scan key (x1 = auto) rule `rule` picks for photo row `r`."""
    keys = keys_of(r)
    if rule == "auto":
        return "x1"
    if rule == "oracle":
        return min(keys, key=lambda k: num(r["rmse_" + k]))
    kind, k = rule.split("<=")
    w = float(kind.split(":")[1]) if kind.startswith("joint") else 0.0
    r1, n1 = num(r["residual_x1"]), num(r["noise_x1"])
    if not math.isfinite(r1) or r1 <= 0:
        return "x1"

    def score(key):
        s = num(r["residual_" + key]) / r1
        if w:
            dn = num(r["noise_" + key]) - n1
            s += w * (dn if math.isfinite(dn) else 0.0)
        return s if math.isfinite(s) else float("inf")

    best = min(keys, key=score)
    return best if score(best) <= float(k) else "x1"


def summary(rows, rules):
    out = []
    for rule in rules:
        for h in ("A", "B"):
            hr = [r for r in rows if r["half"] == h]
            plain = [num(r["rmse_" + choice(r, rule)]) for r in hr if r["curve"] == "srgb"]
            cams = [num(r["rmse_" + choice(r, rule)]) for r in hr if r["curve"] != "srgb"]
            if not plain or not cams:
                continue
            d = [num(r["rmse_" + choice(r, rule)]) - num(r["rmse_x1"]) for r in hr]
            out.append({"rule": rule, "half": h, "photos": len(hr),
                        "power_moved": sum(1 for r in hr if choice(r, rule) != "x1"),
                        "plain_moved": sum(1 for r in hr if r["curve"] == "srgb" and choice(r, rule) != "x1"),
                        **benchlib.cameras_against_plain(plain, cams, d)})
    return out


def plot(rows, summ, path):
    with benchlib.figure(path, 1, 2, figsize=(11, 4.5)) as ax:
        if ax is None:
            return
        colours = {"srgb": "k", "reinhard": "tab:green", "sigmoid": "tab:red", "gamma": "tab:purple"}
        for r in rows:
            r1 = num(r["residual_x1"])
            for k in keys_of(r):
                if k == "x1":
                    continue
                x, y = num(r["residual_" + k]) / r1, num(r["rmse_" + k]) - num(r["rmse_x1"])
                ax[0].plot(x, y, "o" if r["half"] == "A" else "s", color=colours.get(r["curve"], "tab:blue"), ms=4)
        ax[0].axhline(0, color="k", lw=0.5)
        ax[0].axvline(1, color="k", lw=0.5)
        ax[0].set_xlabel("light-fit residual, scanned power / auto's")
        ax[0].set_ylabel("object RMSE, scanned power - auto")
        ax[0].set_title("per photo and power (o A, s B; black plain, green Reinhard, red sigmoid)", fontsize=8)
        for h, colour in (("A", "tab:blue"), ("B", "tab:orange")):
            s = [x for x in summ if x["half"] == h]
            ax[1].plot(range(len(s)), [x["ratio"] for x in s], "o-", color=colour, label="half " + h)
            ax[1].set_xticks(range(len(s)), [str(x["rule"]) for x in s], fontsize=6, rotation=30)
        ax[1].axhline(1.25, color="k", ls=":", lw=1)
        ax[1].set_ylabel("cameras / plain median object RMSE")
        ax[1].set_title("per rule (dotted: the issue's 1.25)")
        ax[1].legend()


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    rules = ["auto"] + opt("--rules", DEFAULT_RULES).split(",") + ["oracle"]
    rows = []
    if opt("--york", ""):
        york = os.path.join(benchlib.shared_dir(), "york")
        scan = [float(x) for x in opt("--scan", "0.6,0.8,1.25").split(",")]
        for name in opt("--york", "").split(","):
            r = measure_york(cli, york, name, out, int(opt("--spp", "1")), scan)
            if r:
                rows.append({k: str(v) for k, v in r.items()})
        benchlib.write_csv(os.path.join(out, "response_power_scan_york.csv"), rows)
        for c in york_choices(rows, rules):
            print(c)
        return 0
    if opt("--from-csv", ""):
        rows = benchlib.rows_of_csvs(opt("--from-csv", ""))
    else:
        if not opt("--variants", "") or not opt("--photos", ""):
            sys.stderr.write("bench_response_power_scan.py: --variants DIR and --photos NAMES are needed\n")
            return 2
        tools = os.path.join(benchlib.shared_dir(), "tools")
        scan = [float(x) for x in opt("--scan", "0.6,0.8,1.25").split(",")]
        for name in opt("--photos", "").split(","):
            r = measure(cli, tools, os.path.join(opt("--variants", ""), name), name, out, int(opt("--spp", "8")), scan)
            if r:
                rows.append(r)
    summ = summary(rows, rules)
    benchlib.write_rows_and_summary(out, "response_power_scan", rows, summ, plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
