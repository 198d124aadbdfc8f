#!/usr/bin/python3
"""Generalisation to unseen rooms: every room of ../shared/scenes-train, plain and through random
cameras, scored per room and per half (A = odd rooms t01, t03, ..., B = even rooms).

For each room, one variant folder per camera (../shared/tools/camera_variants.py; `plain` is the
room's own sRGB encoding, `sK` the random camera of seed K), cached under OUT/variants/ (delete a
folder to redraw it). For each variant the harness writes the assisted scene file and
  render     inlay-cli render (--seconds S, seed 1) scored by harness.py score: object RMSE,
             adjusted RMSE, around_rmse next to around_rmse_do_nothing (the untouched photo);
             --lights-json gives the lights and the pipeline's seconds per stage
  lights     each area light's intensity against truth.json's (same order; the truth in the
             variant photo's linear units: radiance x exposure scale x the camera's gain and
             white balance): relative RGB error, and the ratio ours / true of the luminance
             (> 1: too bright); suns likewise
  albedo     inlay-cli decompose --method ours and --method retinex, scored by score_albedo.py
  response   inlay-cli response SCENE -o R.json when the CLI has that command (else n/a): its
             256-entry code -> linear table against the variant's true curve (from
             camera_variant.json, read for scoring only), RMSE over codes 8..247 after the best
             single scale, relative to the true curve's mean
Times: the wall seconds of each command and the pipeline's stages (stage_<name>_s).

Writes OUT/generalization.csv (one row per room and camera), OUT/generalization_summary.csv
(medians per half and camera kind), OUT/generalization.png (object RMSE per room, plain against
cameras; light intensity ratio; albedo ours against Retinex), OUT/generalization_time.png (error
against run time: object RMSE against render wall seconds, albedo MAE against decompose seconds,
response error against its seconds); prints Markdown tables per half.

usage: bench_generalization.py INLAY_CLI [--out DIR] [--rooms t01,t03|A|B] [--cameras N]
                               [--seconds S] [--spp N [--long-spp M]] [--product [CAP]] [--no-albedo]
                               [--no-plain] [--rescore]
                               [--variants ROOM_CAMERA,...] [--oracle-curve] [--vignetting V]
  --cameras N   random cameras per room, seeds 1..N (default 3; 0: plain only)
  --seconds S   render seconds per composite (default 15)
  --spp N       render exactly N samples per pixel instead (no clock, uniform sampling): the
                fair comparison of two builds on a loaded machine (the clock gives fewer samples
                when other jobs run); both runs share seed 1 and so their noise pattern
  --long-spp M  with --spp: also render each variant at M samples (same seed, uniform) and score
                it: object_rmse_long, object_rmse_adjusted_long, around_rmse_long (and their
                medians). At 16 samples render noise is half or more of the object's squared
                error where the object is glossy or lit from behind the camera (t01, t07;
                bench_error_budget.py), not on glass: the _long columns are the product's
                error with little of the benchmark's noise
  --product [CAP]  also render each variant as `inlay-cli render` does for a user by default: the
                scene without render.spp and render.seconds (so the CLI's defaults: at most 256
                samples, adaptive sampling until every pixel's estimated error is below
                render.noise 0.004, no clock), seed 1, with only --seconds CAP (default 1800) as a
                guard; scored: object_rmse_product, object_rmse_adjusted_product,
                around_rmse_product, and what it took: product_spp (the samples per pixel it
                stopped at), product_render_s (the render's own seconds), render_product_wall_s
                (the command, preparation included), product_estimated_error (its final noise
                estimate). With --spp the 16-sample columns are kept for comparison
  --variants t03_s1,t11_s2  measure only these room_camera variants (e.g. the photos where two
                builds choose different responses; merge with the other build's rows by --from-csv)
  --oracle-curve  an oracle run (benchmark only): each scene's camera.response is the toe_shoulder
                member nearest the variant's true curve (bench_response.true_family_params, from
                camera_variant.json), "srgb" for the plain photos: the pipeline as if the curve
                estimate were perfect
  --vignetting V  set every scene's camera.vignetting: "none" (the product's default), "auto" (the
                light fit's residual estimate), a number, or "true": the oracle, the variant's
                true strength from camera_variant.json (0 for the plain photos)
  --rescore     reuse the composites, albedo and lights files already in OUT (only re-score)
  --from-csv F1,F2,...  measure nothing: read the rows of these generalization.csv files (later
                files win for the same room and camera; e.g. two runs that split the rooms) and
                write the tables, summary and plots of their union to OUT
  --clamp-grid 0,1,2,4,8  measure the clamp of indirect light (render.clamp_indirect, times white)
                instead: each variant is prepared once by `inlay-cli batch` and rendered at every
                value of the grid (0: off; same --spp, seed 1, uniform), each composite scored.
                Writes OUT/clamp_grid.csv (one row per variant and clamp: object RMSE, adjusted,
                around, render_s), OUT/clamp_grid_summary.csv (median and worst per half, camera
                kind and clamp) and OUT/clamp_grid.png (object RMSE against the clamp and against
                render seconds, per half); needs --spp. With --dev: the six dev rooms of
                ../shared/scenes instead (their own photos, half "dev"; --rooms d1,d5 picks some)
  --baseline D  also compare with another build's run in folder D (its generalization.csv):
                prints both halves' medians side by side, writes OUT/generalization_vs_baseline.csv
                and OUT/generalization_vs_baseline.png (per room, baseline against this run)
"""
import json, os, re, statistics, subprocess, sys, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"


def run(cmd, timeout=None):
    """(exit status, wall seconds, stdout, stderr) of a command."""
    t = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return 124, time.monotonic() - t, "", "timed out"
    return p.returncode, time.monotonic() - t, p.stdout, p.stderr


def variant(tools, room_dir, vdir, kind):
    """The cached variant folder `vdir` of the room (made when missing)."""
    if not os.path.isfile(os.path.join(vdir, "camera_variant.json")):
        extra = ["--plain"] if kind == "plain" else ["--seed", kind[1:]]
        rc, _, _, err = run([PY, os.path.join(tools, "camera_variants.py"), room_dir, vdir] + extra)
        if rc != 0:
            raise RuntimeError("camera_variants.py failed: " + err[-300:])
    return vdir


def photo_units(truth, cam):
    """Per channel factor from truth.json's radiance to the variant photo's linear units."""
    return truth["exposure"]["scale"] * cam.get("gain", 1.0) * np.array(cam.get("white_balance", [1, 1, 1]), float)


LUMA = np.array([0.2126, 0.7152, 0.0722])


def light_errors(lights_json, truth, cam):
    """Intensity errors of the refined area lights and suns against the truth."""
    L = json.load(open(lights_json))
    units = photo_units(truth, cam)
    row, rel, ratio = {}, [], []
    for k, (ours, t) in enumerate(zip(L["refined"], truth["lights"])):
        tr = np.array(t["radiance_rgb"], float) * units
        o = np.array(ours["rgb"], float)
        rel.append(float(np.linalg.norm(o - tr) / np.linalg.norm(tr)))
        ratio.append(float(o @ LUMA / max(tr @ LUMA, 1e-12)))
        row["light%d_%s_ratio" % (k, t["view_status"])] = round(ratio[-1], 3)
    ts = truth.get("sun")
    if ts and L.get("suns_refined"):
        tr = np.array(ts["color"], float) * ts["strength_W_m2"] / np.pi * units
        o = np.array(L["suns_refined"][0]["rgb"], float)
        rel.append(float(np.linalg.norm(o - tr) / np.linalg.norm(tr)))
        ratio.append(float(o @ LUMA / max(tr @ LUMA, 1e-12)))
        row["sun_ratio"] = round(ratio[-1], 3)
        # The sky through a window the photo does not show: Inlay adds it as a light after the
        # scene file's (one per such shaft); ours / the truth's sky radiance, by luminance.
        sky = ts.get("sky")
        extra = L["refined"][len(truth["lights"]):]
        if sky and ts.get("window", {}).get("view_status") == "out_of_view" and extra:
            tr = np.array(sky["color"], float) * sky["strength"] * units
            row["sky_ratio"] = round(float(np.array(extra[-1]["rgb"], float) @ LUMA / max(tr @ LUMA, 1e-12)), 3)
    if rel:
        row["light_intensity_error"] = round(max(rel), 4)
        worst = max(ratio, key=lambda r: abs(np.log(max(r, 1e-9))))
        row["light_worst_ratio"] = round(worst, 3)
    for stage, secs in L.get("stage_seconds", []):
        row["stage_%s_s" % re.sub(r"\W+", "_", stage)] = round(secs, 3)
    if "refinement" in L:
        row["refine_s"] = round(L["refinement"].get("seconds", 0.0), 3)
    return row


def true_response(cam):
    """The variant's code -> linear table (256 entries, grey: white balance and gain are scale),
    inverted numerically from the forward curve of camera_variants.py."""
    x = np.geomspace(1e-6, 64.0, 200000)
    if cam["curve"] == "srgb":
        y = np.clip(x, 0, 1)
        y = np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1 / 2.4) - 0.055)
    elif cam["curve"] == "gamma":
        y = np.clip(x, 0, 1) ** (1 / cam["gamma"])
    elif cam["curve"] == "reinhard":
        w2 = cam["white"] ** 2
        y = np.clip(x * (1 + x / w2) / (1 + x), 0, 1) ** (1 / cam["gamma"])
    else:
        lx = np.log2(x / 0.18)
        y = (1 / (1 + np.exp(-cam["contrast"] * lx * 0.7))) ** (2.2 / cam["gamma"])
    y, first = np.unique(np.clip(y, 0, 1), return_index=True)
    return np.interp(np.arange(256) / 255.0, y, x[first])


def find_table(j):
    """The first list of 256 numbers (or 256 RGB triples, averaged) anywhere in a JSON value."""
    if isinstance(j, list) and len(j) == 256:
        a = np.array(j, float)
        return a.mean(axis=1) if a.ndim == 2 else a
    items = j.values() if isinstance(j, dict) else j if isinstance(j, list) else []
    for v in items:
        t = find_table(v)
        if t is not None:
            return t
    return None


def response_error(cli, has_response, scene, out_json, cam, rescore):
    """Response fit error and seconds, or n/a when the CLI has no `response` command."""
    if not has_response:
        return {"response_error": "n/a"}
    secs = 0.0
    if not (rescore and os.path.exists(out_json)):
        rc, secs, _, err = run([cli, "response", scene, "-o", out_json, "--quiet"], timeout=600)
        if rc != 0:
            return {"response_error": "failed", "response_stderr": err.strip()[-200:]}
    est = find_table(json.load(open(out_json)))
    if est is None:
        return {"response_error": "no 256-entry table"}
    ref = true_response(cam)
    codes = slice(8, 248)
    e, r = est[codes], ref[codes]
    s = float((e * r).sum() / max((e * e).sum(), 1e-30))
    err = float(np.sqrt(np.mean((s * e - r) ** 2)) / max(r.mean(), 1e-12))
    return {"response_error": round(err, 4), "response_s": round(secs, 3)}


def albedo_scores(cli, tools, vdir, scene, out, tag, rescore):
    row = {}
    for m in ("ours", "retinex"):
        exr = os.path.join(out, "%s_albedo_%s.exr" % (tag, m))
        if not (rescore and os.path.exists(exr)):
            rc, secs, _, err = run([cli, "decompose", scene, "--albedo", exr, "--method", m, "--quiet"], timeout=900)
            if rc != 0:
                row["albedo_%s_mae" % m] = "failed"
                print(tag, m, "decompose failed:", err.strip()[-300:], flush=True)
                continue
            row["decompose_%s_s" % m] = round(secs, 2)
        rc, _, so, err = run([PY, os.path.join(tools, "score_albedo.py"), vdir, exr])
        if rc == 0:
            r = json.loads(so)
            row["albedo_%s_mae" % m] = round(r["mae"], 4)
            row["albedo_%s_mae_scaled" % m] = round(r["mae_scaled"], 4)
    return row


def measure(cli, tools, room_dir, vdir, kind, out, o):
    """One row: the room `room_dir` through camera `kind`, in variant folder `vdir`."""
    room = os.path.basename(room_dir)
    tag = "%s_%s" % (room, kind)
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    cam = json.load(open(os.path.join(vdir, "camera_variant.json")))
    row = {"room": room, "half": benchlib.half(room), "camera": kind, "curve": cam["curve"],
           "lights": "+".join(sorted({l["view_status"] for l in truth["lights"]} | ({"sun"} if truth.get("sun") else set()))),
           "material": truth["object"]["material"]["type"], "support": truth["object"]["support"],
           "table": bool(truth.get("table"))}
    scene = os.path.join(out, tag + ".json")
    run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene, "--seconds", str(o["seconds"])])
    if o.get("oracle_curve"):
        set_true_curve(scene, cam)
    if o.get("vignetting"):
        set_vignetting(scene, cam, o["vignetting"])
    comp, lj = os.path.join(out, tag + ".png"), os.path.join(out, tag + "_lights.json")
    budget = (["--spp", str(o["spp"]), "--seconds", "0", "--noise", "0"] if o["spp"]
              else ["--spp", "100000", "--seconds", str(o["seconds"])])
    row.update(render_scored(cli, tools, scene, vdir, comp, ["--lights-json", lj] + budget, o["seconds"] * 4 + 1800,
                             ("object_rmse", "object_rmse_adjusted", "around_rmse", "around_rmse_do_nothing"),
                             o["rescore"], "", also_stale=(lj,)))
    if "error" in row:
        return row
    if o["spp"] and o["long_spp"]:
        row.update(long_render(cli, tools, scene, vdir, os.path.join(out, tag + "_long.png"), o))
    if o["product"]:
        row.update(product_render(cli, tools, scene, vdir, os.path.join(out, tag + "_product"), o))
    if os.path.exists(lj):
        row.update(light_errors(lj, truth, cam))
    if o["albedo"]:
        row.update(albedo_scores(cli, tools, vdir, scene, out, tag, o["rescore"]))
    row.update(response_error(cli, o["has_response"], scene, os.path.join(out, tag + "_response.json"),
                              cam, o["rescore"]))
    return row


def set_true_curve(scene, cam):
    """The oracle: the scene's camera.response set to the family member nearest the true curve."""
    import bench_response
    j = json.load(open(scene))
    if cam["curve"] == "srgb":
        response = "srgb"
    else:
        p, t, s = bench_response.true_family_params(cam)
        response = {"family": "toe_shoulder", "power": p, "toe": t, "shoulder": s}
    j.setdefault("camera", {})["response"] = response
    json.dump(j, open(scene, "w"), indent=1)


def set_vignetting(scene, cam, value):
    """--vignetting: the scene's camera.vignetting ("true": the camera's own strength, an oracle)."""
    j = json.load(open(scene))
    if value == "true":
        v = float(cam.get("vignetting", 0.0))
    else:
        v = value if value in ("auto", "none") else float(value)
    j.setdefault("camera", {})["vignetting"] = v
    json.dump(j, open(scene, "w"), indent=1)


def clamp_label(c):
    return "off" if c == 0 else "%g" % c


def measure_clamp_grid(cli, tools, room_dir, vdir, kind, out, o, grid):
    """Rows of one variant at every clamp of `grid`: one `inlay-cli batch` (the scene prepared
    once), a line per clamp, each composite scored by the harness. render_s: a line's seconds
    (the gap between outputs; the first line's excludes the preparation batch reports)."""
    room = os.path.basename(room_dir)
    tag = "%s_%s" % (room, kind)
    scene = os.path.join(out, tag + ".json")
    run([PY, os.path.join(tools, "harness.py"), "scene", vdir, scene, "--seconds", str(o["seconds"])])
    comps = [os.path.join(out, "%s_clamp_%s.png" % (tag, clamp_label(c))) for c in grid]
    manifest = os.path.join(out, tag + "_clamp.jsonl")
    with open(manifest, "w") as f:
        for c, comp in zip(grid, comps):
            f.write(json.dumps({"scene": scene, "output": comp, "render": {"clamp_indirect": c}}) + "\n")
    if not o["rescore"]:
        for comp in comps:
            if os.path.exists(comp):
                os.remove(comp)
    start = time.time()
    rc, secs, _, err = run([cli, "batch", manifest, "--spp", str(o["spp"]), "--seconds", "0", "--noise", "0",
                            "--seed", "1"], timeout=7200)
    m = re.search(r"prepared .*\(([0-9.]+) s,", err)
    prev = start + (float(m.group(1)) if m else 0.0)
    rows = []
    for c, comp in zip(grid, comps):
        half = "dev" if room.startswith("d") else benchlib.half(room)
        row = {"room": room, "half": half, "camera": kind, "clamp": c, "batch_wall_s": round(secs, 2)}
        if not os.path.exists(comp):
            row["error"] = (err.strip() or "batch exit %d" % rc)[-300:]
            rows.append(row)
            continue
        t = os.path.getmtime(comp)
        row["render_s"] = round(t - prev, 2)
        prev = t
        _, _, so, _ = run([PY, os.path.join(tools, "harness.py"), "score", vdir, comp])
        sc = json.loads(so)
        for k in ("object_rmse", "object_rmse_adjusted", "around_rmse", "around_rmse_do_nothing"):
            row[k] = round(sc[k], 4)
        rows.append(row)
    return rows


def summarise_clamp_grid(rows):
    """Median and worst per half, camera kind (plain, cameras, all) and clamp."""
    out = []
    for h in ("A", "B", "dev"):
        for kind in ("plain", "cameras", "all"):
            for c in sorted({r["clamp"] for r in rows}):
                sel = [r for r in rows if r["half"] == h and r["clamp"] == c and
                       (kind == "all" or (r["camera"] == "plain") == (kind == "plain"))]
                if not numbers(sel, "object_rmse"):
                    continue
                s = {"half": h, "camera": kind, "clamp": c, "runs": len(numbers(sel, "object_rmse"))}
                for k in ("object_rmse", "object_rmse_adjusted", "around_rmse", "render_s"):
                    s["median_" + k] = med(sel, k)
                s["max_object_rmse"] = max(numbers(sel, "object_rmse"))
                s["max_around_rmse"] = max(numbers(sel, "around_rmse"))
                out.append(s)
    return out


def plot_clamp_grid(out, summary):
    """Object RMSE (median and worst) against the clamp and against render seconds, per half."""
    with benchlib.figure(os.path.join(out, "clamp_grid.png"), 1, 2, figsize=(12, 4.5)) as ax:
        if ax is None:
            return
        for h, col in (("A", "C0"), ("B", "C1"), ("dev", "C2")):
            for kind, mk in (("plain", "s"), ("cameras", "o")):
                sel = sorted((s for s in summary if s["half"] == h and s["camera"] == kind),
                             key=lambda s: s["clamp"] if s["clamp"] > 0 else 32)
                if not sel:
                    continue
                xs = [s["clamp"] if s["clamp"] > 0 else 32 for s in sel]  # off drawn at 32
                lab = "half %s %s" % (h, kind)
                ax[0].plot(xs, [s["median_object_rmse"] for s in sel], mk + "-", color=col, label=lab + " median")
                ax[0].plot(xs, [s["max_object_rmse"] for s in sel], mk + ":", color=col, alpha=0.6, label=lab + " worst")
                ax[1].plot([s["median_render_s"] for s in sel], [s["median_object_rmse"] for s in sel], mk, color=col,
                           label=lab)
                for s in sel:
                    ax[1].annotate(clamp_label(s["clamp"]), (s["median_render_s"], s["median_object_rmse"]), fontsize=7)
        ax[0].set(xscale="log", xlabel="clamp of indirect light (times white; 'off' drawn at 32)",
                  ylabel="object RMSE (sRGB)", title="object RMSE against the clamp")
        ax[1].set(xlabel="median render seconds per composite", ylabel="median object RMSE",
                  title="object RMSE against render time (labels: clamp)")
        for a in ax:
            if a.get_legend_handles_labels()[0]:
                a.legend(fontsize=7)


def print_clamp_pivot(rows):
    """Markdown per half: a row per variant, a column per clamp (object RMSE / around RMSE)."""
    clamps = sorted({r["clamp"] for r in rows})
    for h in ("A", "B", "dev"):
        sel = [r for r in rows if r["half"] == h]
        if not sel:
            continue
        print("\n### Half %s: object RMSE / around RMSE per clamp\n" % h)
        print("| variant | " + " | ".join(clamp_label(c) for c in clamps) + " |\n|---|" + "---|" * len(clamps))
        for v in sorted({(r["room"], r["camera"]) for r in sel}):
            cells = []
            for c in clamps:
                r = next((x for x in sel if (x["room"], x["camera"]) == v and x["clamp"] == c), {})
                cells.append("%s / %s" % (r.get("object_rmse", "-"), r.get("around_rmse", "-")))
            print("| %s_%s | %s |" % (v[0], v[1], " | ".join(cells)))


def room_variants(tools, sdir, names, kinds, out, only=(), dev=False):
    """(room, camera kind, the variant's folder) for every room and kind, in order; the variant
    drawn (or reused) under OUT/variants. only: "room_kind" names to keep (empty: all). dev: the
    rooms' own folders (the dev rooms' photos, no variant drawn)."""
    for name in names:
        for kind in kinds:
            if only and "%s_%s" % (name, kind) not in only:
                continue
            yield name, kind, (os.path.join(sdir, name) if dev else variant(
                tools, os.path.join(sdir, name), os.path.join(out, "variants", "%s_%s" % (name, kind)), kind))


def run_clamp_grid(cli, tools, sdir, names, kinds, out, o, grid, dev=False):
    """The --clamp-grid run over rooms x cameras (dev: the dev rooms' own photos, plain only)."""
    rows = []
    for name, kind, vdir in room_variants(tools, sdir, names, ["plain"] if dev else kinds, out, dev=dev):
        for row in measure_clamp_grid(cli, tools, os.path.join(sdir, name), vdir, kind, out, o, grid):
            rows.append(row)
            print(json.dumps(row), flush=True)
        benchlib.write_csv(os.path.join(out, "clamp_grid.csv"), rows)
    if not rows:
        print("no rooms")
        return 1
    summary = summarise_clamp_grid(rows)
    benchlib.write_csv(os.path.join(out, "clamp_grid_summary.csv"), summary)
    keys = list(summary[0]) if summary else []
    print("\n| %s |\n|%s" % (" | ".join(keys), "---|" * len(keys)))
    for s in summary:
        print("| " + " | ".join(str(s.get(k, "")) for k in keys) + " |")
    print_clamp_pivot(rows)
    plot_clamp_grid(out, summary)
    print("wrote", os.path.join(out, "clamp_grid.csv"))
    return 0


def long_render(cli, tools, scene, vdir, comp, o):
    """The `_long` columns: the variant rendered at --long-spp samples (seed 1, uniform), scored."""
    return render_scored(cli, tools, scene, vdir, comp, ["--spp", str(o["long_spp"]), "--seconds", "0", "--noise", "0"],
                         7200, ("object_rmse", "object_rmse_adjusted", "around_rmse"), o["rescore"], "_long")


def product_render(cli, tools, scene, vdir, base, o):
    """The `_product` columns: the variant rendered with the CLI's default stop rule (the scene
    without render.spp and render.seconds; --seconds o["product"] only as a guard), scored, with
    the samples and seconds it took (from its --progress-csv)."""
    doc = json.load(open(scene))
    for k in ("spp", "seconds"):
        doc.get("render", {}).pop(k, None)
    user_scene, progress = base + ".json", base + "_progress.csv"
    with open(user_scene, "w") as f:
        json.dump(doc, f, indent=1)
    row = render_scored(cli, tools, user_scene, vdir, base + ".png",
                        ["--seconds", "%g" % o["product"], "--progress-csv", progress], o["product"] * 2 + 600,
                        ("object_rmse", "object_rmse_adjusted", "around_rmse"), o["rescore"], "_product",
                        also_stale=(progress,))
    if os.path.exists(progress):
        import csv
        last = list(csv.DictReader(open(progress)))[-1:]
        if last:
            row["product_spp"] = int(float(last[0]["spp"]))
            row["product_render_s"] = round(float(last[0]["seconds"]), 2)
            row["product_estimated_error"] = round(float(last[0]["estimated_error"]), 5)
    return row


def render_scored(cli, tools, scene, vdir, comp, render_args, timeout, keys, rescore, suffix, also_stale=()):
    """Renders `scene` to `comp` (seed 1; kept when rescoring and it exists) and scores it with the
    harness: `keys` + suffix, the render's wall seconds as render<suffix>_wall_s, or error<suffix>."""
    row = {}
    if not (rescore and os.path.exists(comp)):
        for f in (comp,) + tuple(also_stale):
            if os.path.exists(f):
                os.remove(f)
        rc, secs, _, err = run([cli, "render", scene, "-o", comp, "--quiet", "--seed", "1"] + render_args,
                               timeout=timeout)
        row["render%s_wall_s" % suffix] = round(secs, 2)
        if rc != 0:
            row["error" + suffix] = err.strip()[-300:]
            return row
    rc, _, so, _ = run([PY, os.path.join(tools, "harness.py"), "score", vdir, comp])
    s = json.loads(so)
    for k in keys:
        row[k + suffix] = round(s[k], 4)
    return row


def numbers(rows, key):
    return [r[key] for r in rows if isinstance(r.get(key), (int, float)) and not isinstance(r.get(key), bool)]


def med(rows, key):
    v = numbers(rows, key)
    return round(statistics.median(v), 4) if v else ""


def summarise(rows):
    """Medians per half and camera kind (plain, cameras), with the issue's ratios."""
    out = []
    for h in ("A", "B"):
        for kind in ("plain", "cameras"):
            sel = [r for r in rows if r["half"] == h and (r["camera"] == "plain") == (kind == "plain")]
            if not sel:
                continue
            s = {"half": h, "camera": kind, "runs": len(sel)}
            for k in ("object_rmse", "object_rmse_adjusted", "around_rmse", "around_rmse_do_nothing",
                      "object_rmse_long", "object_rmse_adjusted_long", "around_rmse_long", "light_intensity_error", "albedo_ours_mae", "albedo_retinex_mae", "response_error",
                      "render_wall_s", "decompose_ours_s", "object_rmse_product", "object_rmse_adjusted_product",
                      "around_rmse_product", "product_spp", "product_render_s"):
                s["median_" + k] = med(sel, k)
            s["max_object_rmse"] = max(numbers(sel, "object_rmse"), default="")
            s["max_object_rmse_long"] = max(numbers(sel, "object_rmse_long"), default="")
            s["max_object_rmse_product"] = max(numbers(sel, "object_rmse_product"), default="")
            ours, ret = numbers(sel, "albedo_ours_mae"), numbers(sel, "albedo_retinex_mae")
            if ours:
                s["mean_albedo_ours_mae"] = round(statistics.mean(ours), 4)
                s["albedo_ours_wins"] = "%d/%d" % (sum(1 for r in sel if isinstance(r.get("albedo_ours_mae"), float)
                                                       and isinstance(r.get("albedo_retinex_mae"), float)
                                                       and r["albedo_ours_mae"] < r["albedo_retinex_mae"]), len(ours))
            out.append(s)
    for s in out:
        plain = next((p for p in out if p["half"] == s["half"] and p["camera"] == "plain"), None)
        if s["camera"] == "cameras" and plain and plain["median_object_rmse"]:
            s["cameras_over_plain"] = round(s["median_object_rmse"] / plain["median_object_rmse"], 3)
    return out


def print_tables(rows, summary):
    cols = ["room", "camera", "curve", "lights", "object_rmse", "object_rmse_adjusted", "object_rmse_long",
            "object_rmse_adjusted_long", "around_rmse",
            "around_rmse_do_nothing", "light_intensity_error", "light_worst_ratio", "albedo_ours_mae",
            "albedo_retinex_mae", "response_error", "render_wall_s"]
    if any("object_rmse_product" in r for r in rows):
        cols += ["object_rmse_product", "object_rmse_adjusted_product", "around_rmse_product", "product_spp",
                 "product_render_s"]
    for h in ("A", "B"):
        sel = [r for r in rows if r["half"] == h]
        if not sel:
            continue
        print("\n### Half %s\n\n| %s |\n|%s" % (h, " | ".join(cols), "---|" * len(cols)))
        for r in sel:
            print("| " + " | ".join(str(r.get(c, "")) for c in cols) + " |")
    keys = list(summary[0]) if summary else []
    for s in summary:
        keys += [k for k in s if k not in keys]
    print("\n### Medians\n\n| %s |\n|%s" % (" | ".join(keys), "---|" * len(keys)))
    for s in summary:
        print("| " + " | ".join(str(s.get(k, "")) for k in keys) + " |")


def plot(out, rows):
    rooms = sorted({r["room"] for r in rows})
    x = np.arange(len(rooms))
    with benchlib.figure(os.path.join(out, "generalization.png"), 1, 3, figsize=(17, 4.5)) as ax:
        if ax is not None:
            for room_i, room in enumerate(rooms):
                sel = [r for r in rows if r["room"] == room]
                for r in sel:
                    plain = r["camera"] == "plain"
                    if isinstance(r.get("object_rmse"), float):
                        ax[0].plot(room_i, r["object_rmse"], "s" if plain else "o", color="C0" if plain else "C1", alpha=1 if plain else 0.6)
                    if isinstance(r.get("object_rmse_long"), float):  # --long-spp: the same at more samples
                        ax[0].plot(room_i, r["object_rmse_long"], "x", color="C2" if plain else "C3", ms=8)
                    if isinstance(r.get("light_worst_ratio"), float):
                        ax[1].plot(room_i, r["light_worst_ratio"], "s" if plain else "o", color="C0" if plain else "C1", alpha=1 if plain else 0.6)
                    for m, c, dx in (("ours", "C2", -0.15), ("retinex", "C3", 0.15)):
                        if isinstance(r.get("albedo_%s_mae" % m), float):
                            ax[2].plot(room_i + dx, r["albedo_%s_mae" % m], "s" if plain else "o", color=c, alpha=1 if plain else 0.5)
            ax[0].axhline(0.03, ls="--", color="grey")
            ax[0].set(ylabel="object RMSE (sRGB)",
                      title="object RMSE: plain (squares), random cameras (dots), --long-spp (crosses)")
            ax[1].axhline(1.0, ls="--", color="grey")
            ax[1].set(yscale="log", ylabel="ours / true luminance (worst light)", title="light intensity")
            ax[2].axhline(0.05, ls="--", color="grey")
            ax[2].set(ylabel="albedo MAE", title="albedo: ours (green) against Retinex (red)")
            for a in ax:
                a.set_xticks(x)
                a.set_xticklabels(["%s%s" % (r, benchlib.half(r)) for r in rooms], fontsize=7)
    with benchlib.figure(os.path.join(out, "generalization_time.png"), 1, 3, figsize=(17, 4.5)) as ax:
        if ax is not None:
            for pane, (tk, ek, title) in enumerate((("render_wall_s", "object_rmse", "object RMSE against render wall s"),
                                                    ("decompose_ours_s", "albedo_ours_mae", "albedo MAE against decompose s"),
                                                    ("response_s", "response_error", "response error against its s"))):
                for h, c in (("A", "C0"), ("B", "C1")):
                    pts = [(r[tk], r[ek]) for r in rows if r["half"] == h and isinstance(r.get(tk), float)
                           and isinstance(r.get(ek), float)]
                    if pts:
                        ax[pane].plot([p[0] for p in pts], [p[1] for p in pts], "o", color=c, label="half " + h)
                ax[pane].set(xlabel="seconds", ylabel=ek, title=title)
                if ax[pane].get_legend_handles_labels()[0]:
                    ax[pane].legend(fontsize=7)


def plot_samples(out, rows):
    """With --long-spp (and --product): OUT/generalization_samples.png, per plain photo the object
    RMSE at --spp, --long-spp and the CLI's default stop rule, and the same against the render
    command's wall seconds (one line per room, preparation included in each)."""
    runs = (("", "s", "--spp"), ("_long", "x", "--long-spp"), ("_product", "^", "default stop"))
    sel = [r for r in rows if r["camera"] == "plain" and isinstance(r.get("object_rmse_long"), float)]
    if not sel:
        return
    rooms = sorted({r["room"] for r in sel})
    with benchlib.figure(os.path.join(out, "generalization_samples.png"), 1, 2, figsize=(14, 4.8)) as ax:
        if ax is None:
            return
        labelled = set()
        for i, room in enumerate(rooms):
            r = next(r for r in sel if r["room"] == room)
            c = "C0" if r["half"] == "A" else "C1"
            pts = []
            for suffix, marker, label in runs:
                e, t = r.get("object_rmse" + suffix), r.get("render%s_wall_s" % suffix)
                if isinstance(e, float):
                    ax[0].plot(i, e, marker, color="grey" if label not in labelled else c, ms=7,
                               label=None if label in labelled else label)
                    ax[0].plot(i, e, marker, color=c, ms=7)
                    labelled.add(label)
                    if isinstance(t, float):
                        pts.append((t, e, marker))
            ax[1].plot([p[0] for p in pts], [p[1] for p in pts], "-", color=c, alpha=0.5)
            for t, e, marker in pts:
                ax[1].plot(t, e, marker, color=c, ms=7)
            if pts:
                ax[1].annotate(room, (pts[-1][0], pts[-1][1]), fontsize=7, xytext=(3, 3), textcoords="offset points")
        for a in ax:
            a.axhline(0.03, ls="--", color="grey")
            a.axhline(0.08, ls=":", color="grey")
        ax[0].set_xticks(np.arange(len(rooms)))
        ax[0].set_xticklabels(["%s%s" % (r, benchlib.half(r)) for r in rooms], fontsize=7)
        ax[0].set(ylabel="object RMSE (sRGB)", title="object RMSE per room (half A blue, B orange; target 0.03, worst 0.08)")
        ax[0].legend(fontsize=7)
        ax[1].set(xscale="log", xlabel="render command wall seconds (preparation included)", ylabel="object RMSE",
                  title="error against run time: square --spp, cross --long-spp, triangle default stop")


def product_cap(argv):
    """--product [CAP]: the guard in seconds (default 1800); 0 without --product."""
    if "--product" not in argv:
        return 0.0
    i = argv.index("--product")
    nxt = argv[i + 1] if i + 1 < len(argv) else ""
    return float(nxt) if re.fullmatch(r"[0-9.]+", nxt) else 1800.0


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    argv = sys.argv[1:]
    sdir, tools, names = benchlib.train_rooms_of(opt("--rooms", ""))
    os.makedirs(os.path.join(out, "variants"), exist_ok=True)
    kinds = ([] if "--no-plain" in argv else ["plain"]) + ["s%d" % k for k in range(1, int(opt("--cameras", "3")) + 1)]
    rc, _, help_text, help_err = run([cli, "--help"])
    o = {"seconds": float(opt("--seconds", "15")), "spp": int(opt("--spp", "0")), "long_spp": int(opt("--long-spp", "0")),
         "product": product_cap(argv), "albedo": "--no-albedo" not in argv, "rescore": "--rescore" in argv,
         "has_response": "inlay-cli response" in help_text + help_err, "oracle_curve": "--oracle-curve" in argv,
         "vignetting": opt("--vignetting", "")}
    print("response command:", "yes" if o["has_response"] else "no (n/a)", flush=True)
    if opt("--clamp-grid", ""):
        if not o["spp"]:
            print("--clamp-grid needs --spp")
            return 2
        grid = [float(c) if c != "off" else 0.0 for c in opt("--clamp-grid", "").split(",")]
        if "--dev" in argv:
            sdir, _, names = benchlib.scene_rooms(opt("--rooms", ""), out)
            return run_clamp_grid(cli, tools, sdir, names, kinds, out, o, grid, dev=True)
        return run_clamp_grid(cli, tools, sdir, names, kinds, out, o, grid)
    rows = []
    if opt("--from-csv", ""):
        merged = {}
        for path in opt("--from-csv", "").split(","):
            for r in read_rows(path):
                r["table"] = r.get("table") in (True, "True", 1.0)
                merged[(r["room"], r["camera"])] = r
        rows = [merged[k] for k in sorted(merged)]
        benchlib.write_csv(os.path.join(out, "generalization.csv"), rows)
        names = []
    only = set(filter(None, opt("--variants", "").split(",")))
    for name, kind, vdir in room_variants(tools, sdir, names, kinds, out, only):
        row = measure(cli, tools, os.path.join(sdir, name), vdir, kind, out, o)
        rows.append(row)
        print(json.dumps(row), flush=True)
        benchlib.write_csv(os.path.join(out, "generalization.csv"), rows)
    if not rows:
        print("no rooms")
        return 1
    summary = summarise(rows)
    benchlib.write_csv(os.path.join(out, "generalization_summary.csv"), summary, table="generalization")
    print_tables(rows, summary)
    plot(out, rows)
    plot_samples(out, rows)
    if opt("--baseline", ""):
        compare(out, rows, os.path.abspath(opt("--baseline", "")))
    print("wrote", os.path.join(out, "generalization.csv"))
    return 0


def read_rows(path):
    """Rows of a generalization.csv, numbers as floats."""
    import csv
    rows = []
    for r in csv.DictReader(open(path)):
        for k, v in r.items():
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
        rows.append(r)
    return rows


COMPARED = ["object_rmse", "object_rmse_adjusted", "object_rmse_long", "around_rmse", "light_intensity_error", "light_worst_ratio",
            "albedo_ours_mae", "albedo_retinex_mae"]


def compare(out, rows, baseline_dir):
    """This run against another build's on the rooms and cameras both measured."""
    base = {(r["room"], r["camera"]): r for r in read_rows(os.path.join(baseline_dir, "generalization.csv"))}
    pairs = [(base[(r["room"], r["camera"])], r) for r in rows if (r["room"], r["camera"]) in base]
    table = []
    for b, a in pairs:
        t = {"room": a["room"], "half": a["half"], "camera": a["camera"]}
        for k in COMPARED:
            t[k + "_baseline"], t[k] = b.get(k, ""), a.get(k, "")
        table.append(t)
    benchlib.write_csv(os.path.join(out, "generalization_vs_baseline.csv"), table, table="generalization_vs_baseline")
    print("\n### Against the baseline (%s)\n" % baseline_dir)
    print("| half | camera | rooms | " + " | ".join("%s base -> now" % k for k in COMPARED) + " | albedo wins base -> now |")
    print("|" + "---|" * (len(COMPARED) + 4))
    for h in ("A", "B"):
        for kind in ("plain", "cameras"):
            sel = [t for t in table if t["half"] == h and (t["camera"] == "plain") == (kind == "plain")]
            if not sel:
                continue
            cells = []
            for k in COMPARED:
                cells.append("%s -> %s" % (med([{"v": t[k + "_baseline"]} for t in sel], "v"),
                                           med([{"v": t[k]} for t in sel], "v")))
            wins = lambda suffix: sum(1 for t in sel if isinstance(t.get("albedo_ours_mae" + suffix), float)
                                      and isinstance(t.get("albedo_retinex_mae" + suffix), float)
                                      and t["albedo_ours_mae" + suffix] < t["albedo_retinex_mae" + suffix])
            print("| %s | %s | %d | %s | %d -> %d |" % (h, kind, len(sel), " | ".join(cells), wins("_baseline"), wins("")))
    with benchlib.figure(os.path.join(out, "generalization_vs_baseline.png"), 1, 3, figsize=(17, 4.5)) as ax:
        if ax is None:
            return
        x = np.arange(len(table))
        for pane, (k, title) in enumerate((("object_rmse", "object RMSE"), ("light_worst_ratio", "ours / true light (worst)"),
                                           ("albedo_ours_mae", "albedo MAE (ours)"))):
            vals = lambda key: [t[key] if isinstance(t[key], float) else np.nan for t in table]
            ax[pane].bar(x - 0.2, vals(k + "_baseline"), 0.4, label="baseline")
            ax[pane].bar(x + 0.2, vals(k), 0.4, label="this run")
            if k == "albedo_ours_mae":
                ax[pane].plot(x, vals("albedo_retinex_mae"), "k_", ms=12, label="Retinex (this run)")
            if k == "light_worst_ratio":
                ax[pane].axhline(1.0, ls="--", color="grey")
                ax[pane].set_yscale("log")
            ax[pane].set_xticks(x)
            ax[pane].set_xticklabels(["%s%s %s" % (t["room"], t["half"], t["camera"]) for t in table], rotation=60, fontsize=7)
            ax[pane].set(title=title)
            ax[pane].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
