#!/usr/bin/python3
"""Where the error that a random camera adds to the inserted object comes from.

Every room of ../shared/scenes-train (--rooms, default half A) is photographed through the random
cameras of bench_generalization.py (../shared/tools/camera_variants.py --seed K, K = 1..--cameras:
the same camera in every room). Each variant is then inserted again with one camera component
swapped for the truth (oracle runs: only this script reads camera_variant.json):

  full         the variant as camera_variants.py writes it, camera.response "auto" (the product)
  true_curve   the same photo, camera.response = the toe_shoulder member nearest the camera's
               true tone curve (bench_response.true_family_params): a perfect curve estimate
  wb           the camera without its white balance (white_balance 1, 1, 1), photo and truth
  vignetting   the camera without vignetting
  noise        the camera without sensor noise (the room's own render noise stays)
  jpeg         the camera without JPEG (skipped when the camera writes none: same as full)
  gain         the camera without its exposure gain (gain 1)
  curve_srgb   the camera's tone curve replaced by sRGB (gain, white balance, vignetting, noise
               and JPEG kept): what the curve itself costs, estimate or not
  plain        the room's own sRGB photo (once per room): the reference of the issue's ratio

The components are switched off in both the photo and the truth (harness.py scores against the
truth photographed by the same camera), re-encoding the room's linear renders exactly as
camera_variants.py does (same seed: same camera, same noise field). Every run: harness.py's
assisted scene, `inlay-cli render --spp N --seconds 0 --noise 0 --seed 1` (the same samples in
every reading), scored by harness.py score.

Writes OUT/camera_budget.csv (one row per room, camera and reading: object RMSE, adjusted RMSE,
the response inlay used, render seconds), OUT/camera_budget_summary.csv (per reading: median
object RMSE over the cameras, its ratio to the plain median, the median of the per-variant
change against full) and OUT/camera_budget.png (per reading: the object RMSE of each variant
against full's, and the median against render seconds); prints the tables.

usage: bench_camera_budget.py INLAY_CLI [--out DIR] [--rooms A|B|t01,t03] [--cameras 3]
                              [--readings full,true_curve,...] [--spp 16] [--rescore]
                              [--from-csv F1,F2,...]
  --from-csv  measure nothing: summarise and plot the rows of these camera_budget.csv files (e.g.
              runs that split the rooms between two processes)
"""
import copy, importlib.util, json, os, statistics, subprocess, sys, time

import numpy as np
import cv2

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response as br  # noqa: E402

PY = "/usr/bin/python3"
READINGS = ["plain", "full", "true_curve", "wb", "vignetting", "noise", "jpeg", "gain", "curve_srgb"]
SWITCH = {"wb": ("white_balance", [1.0, 1.0, 1.0]), "vignetting": ("vignetting", 0.0), "noise": ("noise", 0.0),
          "jpeg": ("jpeg_quality", 0), "gain": ("gain", 1.0)}


def camera_tool():
    spec = importlib.util.spec_from_file_location(
        "camera_variants", os.path.join(benchlib.shared_dir(), "tools", "camera_variants.py"))
    cv = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(cv)
    return cv


def photograph(cv, room_dir, out, seed, reading):
    """The variant folder of `room_dir` through camera `seed` with `reading`'s component off
    (camera_variants.py's own steps, so `full` is byte for byte its output). Returns the camera."""
    rng = np.random.default_rng(seed)
    cam = cv.draw_camera(rng)
    if reading in SWITCH:
        cam[SWITCH[reading][0]] = SWITCH[reading][1]
    if os.path.isfile(os.path.join(out, "camera_variant.json")):
        return cam
    truth = json.load(open(os.path.join(room_dir, "truth.json")))
    photo = cv.read_exr(os.path.join(room_dir, "photo_linear.exr"))
    with_object = cv.read_exr(os.path.join(room_dir, "truth_linear.exr"))
    h, w = photo.shape[:2]
    yy, xx = np.mgrid[0:h, 0:w]
    r2 = ((xx + 0.5 - w / 2) ** 2 + (yy + 0.5 - h / 2) ** 2) / ((w / 2) ** 2 + (h / 2) ** 2)
    vignette = 1.0 - cam["vignetting"] * r2
    noise = rng.standard_normal(photo.shape)
    benchlib.link_room_files(room_dir, out)
    scale = truth["exposure"]["scale"]
    for image, stem in ((photo, "photo"), (with_object, "truth")):
        if reading == "curve_srgb":
            x = image * scale * cam["gain"] * np.array(cam["white_balance"]) * vignette[:, :, None]
            x = np.maximum(x + cam["noise"] * noise * np.sqrt(np.maximum(x, 1e-4)), 0)
            pixels = np.round(cv.srgb(x) * 255).astype(np.uint8)
        else:
            pixels = cv.encode(image, scale, cam, noise, vignette)
        bgr = np.ascontiguousarray(pixels[:, :, ::-1])
        if cam["jpeg_quality"]:
            ok, buf = cv2.imencode(".jpg", bgr, [cv2.IMWRITE_JPEG_QUALITY, cam["jpeg_quality"]])
            bgr = cv2.imdecode(buf, cv2.IMREAD_COLOR)
            if stem == "photo":
                open(os.path.join(out, "photo.jpg"), "wb").write(buf.tobytes())
        cv2.imwrite(os.path.join(out, stem + ".png"), bgr)
    json.dump(cam, open(os.path.join(out, "camera_variant.json"), "w"), indent=1)
    return cam


def plain_variant(room_dir, out):
    if not os.path.isfile(os.path.join(out, "camera_variant.json")):
        subprocess.run([PY, os.path.join(benchlib.shared_dir(), "tools", "camera_variants.py"), room_dir, out,
                        "--plain"], check=True, capture_output=True)
    return json.load(open(os.path.join(out, "camera_variant.json")))


def insert(cli, vdir, work, response, spp, rescore):
    """Object scores of harness.py's assisted insertion into the photo of `vdir`."""
    harness = os.path.join(benchlib.shared_dir(), "tools", "harness.py")
    os.makedirs(work, exist_ok=True)
    sf, comp = os.path.join(work, "scene.json"), os.path.join(work, "composite.png")
    row = {}
    if not (rescore and os.path.exists(comp)):
        subprocess.run([PY, harness, "scene", vdir, sf, "--seconds", "15"], check=True, capture_output=True)
        j = json.load(open(sf))
        if response is not None:
            j.setdefault("camera", {})["response"] = response
        json.dump(j, open(sf, "w"), indent=1)
        t = time.monotonic()
        r = subprocess.run([cli, "render", sf, "-o", comp, "--seed", "1", "--spp", str(spp), "--seconds", "0",
                            "--noise", "0"], capture_output=True, text=True)
        row["render_wall_s"] = round(time.monotonic() - t, 2)
        if r.returncode != 0:
            row["error"] = r.stderr.strip()[-300:]
            return row
        used = [l for l in r.stderr.splitlines() if "camera response: " in l]
        row["response_used"] = used[0].split("camera response: ")[1][:90] if used else ""
    s = json.loads(subprocess.run([PY, harness, "score", vdir, comp], capture_output=True, text=True,
                                  check=True).stdout)
    for k in ("object_rmse", "object_rmse_adjusted", "around_rmse"):
        row[k] = round(s[k], 4)
    return row


def measure(cli, cv, room_dir, seeds, readings, out, spp, rescore, progress):
    room = os.path.basename(room_dir)
    rows = []
    todo = [("plain", "plain")] if "plain" in readings else []
    todo += [("s%d" % k, r) for k in seeds for r in readings if r != "plain"]
    for kind, reading in todo:
        vname = "%s_%s_%s" % (room, kind, "full" if reading == "true_curve" else reading)
        vdir = os.path.join(out, "variants", vname)
        if reading == "plain":
            cam = plain_variant(room_dir, vdir)
        else:
            cam = photograph(cv, room_dir, vdir, int(kind[1:]), "full" if reading == "true_curve" else reading)
        if reading == "jpeg" and not cam_of(cv, int(kind[1:]))["jpeg_quality"]:
            # the camera writes no JPEG: the reading is `full` (its row, not rendered again)
            same = next((dict(r) for r in rows if r["camera"] == kind and r["reading"] == "full"), None)
            if same:
                same.update({"reading": "jpeg", "note": "no JPEG: the full camera's run"})
                rows.append(same)
            continue
        response = None
        if reading == "true_curve":
            p, t, s = br.true_family_params(cam)
            response = {"family": "toe_shoulder", "power": p, "toe": t, "shoulder": s}
        row = {"room": room, "half": benchlib.half(room), "camera": kind, "curve": cam["curve"],
               "reading": reading}
        row.update(insert(cli, vdir, os.path.join(out, "runs", "%s_%s_%s" % (room, kind, reading)), response, spp,
                          rescore))
        rows.append(row)
        print(json.dumps(row), flush=True)
        progress(rows)
    return rows


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return v


def cam_of(cv, seed):
    return cv.draw_camera(np.random.default_rng(seed))


def summarise(rows, readings):
    """Per reading: the median object RMSE over the camera variants, its ratio to the plain
    median, and the median change against `full` on the same variants."""
    full = {(r["room"], r["camera"]): r["object_rmse"] for r in rows
            if r["reading"] == "full" and isinstance(r.get("object_rmse"), float)}
    wanted = [r for r in readings if r != "plain"]
    have = {}
    for r in rows:
        if isinstance(r.get("object_rmse"), float):
            have.setdefault((r["room"], r["camera"]), set()).add(r["reading"])
    complete = {k for k, got in have.items() if k[1] != "plain" and all(w in got for w in wanted)}
    rooms = {k[0] for k in complete}
    plain = [r["object_rmse"] for r in rows if r["reading"] == "plain" and r["room"] in rooms
             and isinstance(r.get("object_rmse"), float)]
    pm = statistics.median(plain) if plain else float("nan")
    out = []
    for reading in readings:
        sel = [r for r in rows if r["reading"] == reading and isinstance(r.get("object_rmse"), float)]
        if not sel:
            continue
        vals = {(r["room"], r["camera"]): r["object_rmse"] for r in sel}
        if reading != "plain":  # only the variants every reading measured (a run may be cut short)
            vals = {k: v for k, v in vals.items() if k in complete}
        else:
            vals = {k: v for k, v in vals.items() if k[0] in rooms}
        v = list(vals.values())
        if not v:
            continue
        d = [vals[k] - full[k] for k in vals if k in full]
        s = {"reading": reading, "variants": len(v), "median_object_rmse": round(statistics.median(v), 4),
             "mean_object_rmse": round(statistics.mean(v), 4), "over_plain": round(statistics.median(v) / pm, 3),
             "median_change_vs_full": round(statistics.median(d), 4) if d else "",
             "mean_change_vs_full": round(statistics.mean(d), 4) if d else "",
             "median_render_s": round(statistics.median([r["render_wall_s"] for r in sel if "render_wall_s" in r] or [0]), 1)}
        out.append(s)
    return out


def plot(path, rows, summary):
    full = {(r["room"], r["camera"]): r["object_rmse"] for r in rows
            if r["reading"] == "full" and isinstance(r.get("object_rmse"), float)}
    with benchlib.figure(path, 1, 2, figsize=(13, 5)) as ax:
        if ax is None:
            return
        colour = {name: "C%d" % i for i, name in enumerate(READINGS)}
        for s in (x for x in summary if x["reading"] not in ("plain", "full")):
            pts = [(full[(r["room"], r["camera"])], r["object_rmse"]) for r in rows
                   if r["reading"] == s["reading"] and (r["room"], r["camera"]) in full
                   and isinstance(r.get("object_rmse"), float)]
            ax[0].plot([p[0] for p in pts], [p[1] for p in pts], "o", color=colour[s["reading"]], label=s["reading"])
        lim = max(list(full.values()) + [0.1]) * 1.05
        ax[0].plot([0, lim], [0, lim], "k--", lw=0.8)
        ax[0].set(xlabel="object RMSE, full camera (auto)", ylabel="object RMSE, component swapped for the truth",
                  title="one camera component set right (below the line: it cost that much)")
        ax[0].legend(fontsize=7)
        for s in summary:
            ax[1].plot(s["median_render_s"], s["median_object_rmse"], "o", color=colour[s["reading"]])
            ax[1].annotate(s["reading"], (s["median_render_s"], s["median_object_rmse"]), fontsize=7)
        ax[1].set(xlabel="median render wall s", ylabel="median object RMSE",
                  title="median object RMSE per reading against run time")


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    sdir, _, names = benchlib.train_rooms_of(opt("--rooms", "A"))
    order = opt("--rooms", "A").split(",")  # a list of rooms runs in its own order (fast rooms first)
    names.sort(key=lambda n: next((i for i, p in enumerate(order) if n.startswith(p)), 0))
    readings = opt("--readings", ",".join(READINGS)).split(",")
    bad = [r for r in readings if r not in READINGS]
    if bad:
        sys.stderr.write("bench_camera_budget.py: unknown reading %s (known: %s)\n" % (bad, ",".join(READINGS)))
        return 2
    seeds = range(1, int(opt("--cameras", "3")) + 1)
    os.makedirs(out, exist_ok=True)
    cv = camera_tool()
    rows = []
    if opt("--from-csv", ""):
        names = []
        for path in opt("--from-csv", "").split(","):
            rows += [{k: num(v) for k, v in r.items()} for r in benchlib.read_csv(path)]
        benchlib.write_csv(os.path.join(out, "camera_budget.csv"), rows)
    for name in names:
        rows += measure(cli, cv, os.path.join(sdir, name), seeds, readings, out, int(opt("--spp", "16")),
                        "--rescore" in sys.argv, lambda done: benchlib.write_csv(
                            os.path.join(out, "camera_budget.csv"), rows + done))
    summary = summarise(rows, readings)
    benchlib.write_csv(os.path.join(out, "camera_budget_summary.csv"), summary)
    cols = ["reading", "variants", "median_object_rmse", "mean_object_rmse", "over_plain", "median_change_vs_full",
            "mean_change_vs_full", "median_render_s"]
    print("\n| " + " | ".join(cols) + " |\n|" + "---|" * len(cols))
    for s in summary:
        print("| " + " | ".join(str(s.get(c, "")) for c in cols) + " |")
    plot(os.path.join(out, "camera_budget.png"), rows, summary)
    print("wrote", os.path.join(out, "camera_budget.csv"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
