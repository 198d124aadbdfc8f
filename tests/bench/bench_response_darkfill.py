#!/usr/bin/python3
"""The inserted object with and without the shadows' contrast evidence of the response estimate.

`inlay-cli response --max-dark-fill D` (ResponseEstimateOptions::maxDarkFill, off by default)
lets the noise cue's curve through its evidence gate when the photo's shadows are darker than D
of its median luminance under sRGB (docs/camera-response.md). This script measures what that
does to the inserted object: each variant folder of a bench_generalization.py run (--variants
DIR, made by ../shared/tools/camera_variants.py) named by --photos is estimated twice (the
default and with --max-dark-fill D), and rendered
  auto      the harness scene as it is (camera.response "auto": the default estimate);
  darkfill  the same scene with camera.response set to the curve the option estimates (explicit
            parameters: exactly what "auto" would decode with the option on); when that curve is
            the default's, the auto render is reused and the row says so.
Renders: `inlay-cli render --spp N --seconds 0 --noise 0 --seed 1` (bench_generalization.py's
budget), scored by harness.py score. camera_variant.json is read only for the curve's name.

Writes OUT/response_darkfill.csv (one row per photo and mode: object RMSE, adjusted, the curve,
render seconds) and OUT/response_darkfill.png (object RMSE darkfill against auto per photo, and
against render seconds); --from-csv merges earlier runs' CSVs (no rendering).

usage: bench_response_darkfill.py INLAY_CLI --variants DIR --photos t02_s3,t03_s2 [--out OUT]
                                  [--max-dark-fill 0.12] [--spp 16] [--from-csv A.csv,B.csv]
"""
import csv, json, os, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"


def run(cmd, timeout=7200):
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    return p, time.time() - t0


def estimate(cli, photo, out_json, extra):
    p, _ = run([cli, "response", photo, "-o", out_json, "--quiet"] + extra)
    if p.returncode:
        raise RuntimeError("inlay-cli response failed on %s: %s" % (photo, p.stderr[-300:]))
    return json.load(open(out_json))


def render_and_score(cli, tools, vdir, scene, comp, spp):
    p, secs = run([cli, "render", scene, "-o", comp, "--quiet", "--seed", "1", "--spp", str(spp),
                   "--seconds", "0", "--noise", "0"])
    if p.returncode:
        return {"error": p.stderr.strip()[-300:]}
    s = json.loads(run([PY, os.path.join(tools, "harness.py"), "score", vdir, comp])[0].stdout)
    return {"object_rmse": round(s["object_rmse"], 4), "object_rmse_adjusted": round(s["object_rmse_adjusted"], 4),
            "render_s": round(secs, 1)}


def measure(cli, tools, vdir, name, out, o):
    """The rows of one photo: auto, then darkfill (reusing auto's render when the curve is the same)."""
    cam = json.load(open(os.path.join(vdir, "camera_variant.json")))
    photo = os.path.join(vdir, "photo.png")
    default = estimate(cli, photo, os.path.join(out, name + "_auto_response.json"), [])
    opted = estimate(cli, photo, os.path.join(out, name + "_darkfill_response.json"),
                     ["--max-dark-fill", str(o["dark"])])
    base = {"photo": name, "half": benchlib.half(name[:3]), "curve": cam["curve"],
            "dark_fill": round(opted["estimate"]["dark_fill"], 4)}
    scene = os.path.join(out, name + "_auto.json")
    run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene, "--seconds", "15"])
    auto = dict(base, mode="auto", response=default["description"])
    auto.update(render_and_score(cli, tools, vdir, scene, os.path.join(out, name + "_auto.png"), o["spp"]))
    rows = [auto]
    if opted["parameters"] == default["parameters"] and opted["family"] == default["family"]:
        rows.append(dict(auto, mode="darkfill", reused_auto=True))
    else:
        j = json.load(open(scene))
        j.setdefault("camera", {})["response"] = dict(family=opted["family"], **opted["parameters"])
        dscene = os.path.join(out, name + "_darkfill.json")
        json.dump(j, open(dscene, "w"), indent=1)
        dark = dict(base, mode="darkfill", response=opted["description"])
        dark.update(render_and_score(cli, tools, vdir, dscene, os.path.join(out, name + "_darkfill.png"), o["spp"]))
        rows.append(dark)
    for r in rows:
        print(json.dumps(r), flush=True)
    return rows


def plot(rows, path):
    by = {}
    for r in rows:
        if isinstance(r.get("object_rmse"), (int, float)):
            by.setdefault(r["photo"], {})[r["mode"]] = r
    pairs = [(p, m["auto"], m["darkfill"]) for p, m in sorted(by.items()) if "auto" in m and "darkfill" in m]
    with benchlib.figure(path, 1, 2, figsize=(11, 4.5)) as ax:
        if ax is None or not pairs:
            return
        for p, a, d in pairs:
            colour = "tab:blue" if a["half"] == "A" else "tab:orange"
            ax[0].plot(a["object_rmse"], d["object_rmse"], "o", color=colour)
            ax[0].annotate(p, (a["object_rmse"], d["object_rmse"]), fontsize=7)
            for m, mark in ((a, "o"), (d, "s")):
                ax[1].plot(float(m.get("render_s") or 0), m["object_rmse"], mark, color=colour)
        lim = max(max(a["object_rmse"], d["object_rmse"]) for _, a, d in pairs) * 1.1
        ax[0].plot([0, lim], [0, lim], "k:", lw=1)
        ax[0].set_xlabel("object RMSE, auto (default)")
        ax[0].set_ylabel("object RMSE, with --max-dark-fill")
        ax[0].set_title("per photo (blue: half A, orange: half B)")
        ax[1].set_xlabel("render wall seconds (16 spp, loaded machine)")
        ax[1].set_ylabel("object RMSE (o auto, s darkfill)")
        ax[1].set_title("error against run time")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    rows = []
    if opt("--from-csv", ""):
        for f in opt("--from-csv", "").split(","):
            rows += [dict(r) for r in csv.DictReader(open(f))]
        for r in rows:
            for k in ("object_rmse", "object_rmse_adjusted", "render_s"):
                if r.get(k) not in (None, ""):
                    r[k] = float(r[k])
    else:
        variants = opt("--variants", "")
        if not variants or not opt("--photos", ""):
            sys.stderr.write("bench_response_darkfill.py: --variants DIR and --photos NAMES are needed\n")
            return 2
        tools = os.path.join(benchlib.shared_dir(), "tools")
        o = {"dark": float(opt("--max-dark-fill", "0.12")), "spp": int(opt("--spp", "16"))}
        for name in opt("--photos", "").split(","):
            rows += measure(cli, tools, os.path.join(variants, name), name, out, o)
    benchlib.write_csv(os.path.join(out, "response_darkfill.csv"), rows)
    plot(rows, os.path.join(out, "response_darkfill.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
