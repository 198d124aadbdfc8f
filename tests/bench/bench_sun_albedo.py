#!/usr/bin/python3
"""Where a sun room's albedo error is: per region, per scale, and with the light fit's shading
parts swapped for the truth's (issue #16, docs/generalization.md "The sun rooms' albedo").

For each room: `inlay-cli decompose SCENE --albedo A --direct D --gathered G --physical P` on the
assisted scene (harness.py scene) and `--method retinex`; then against the room's truth files
(albedo.exr, direct.exr and indirect.exr times exposure.scale, normal.exr, labels.png), over the
pixels score_albedo.py scores (labels 1..6, no emitter):

Regions: sunlit (the truth's direct light at least half the sun's alone, n.l x strength x colour
/ pi, where the sun faces the surface), split into clipped (the photo's code 254 or more in a
channel) and not, and into the floor and the walls (the shaft on the walls); in the sun's shade:
the floor, the walls, the ceiling.
Columns per region: pixels; share of the room's absolute error; MAE of our albedo raw, after the
room's best single scale (score_albedo's mae_scaled) and after the region's own best scale;
Retinex's MAE; medians (luminance) of ours / truth, of the light fit's albedo (B over its
shading, --physical) / truth, of our gathered light / the truth's indirect (Gamma), of the light
fit's direct light (B / physical - Gamma) / the truth's direct; and the light fit's albedo's MAE
with its shading's parts swapped for the truth's, per pixel: true Gamma (B / (direct_fit +
Gamma_true)), true direct (B / (direct_true + Gamma_fit)), both true.
The decomposition's start takes its scale from the light fit's albedo (the median ratio,
lighting/src/estimate.cpp anchoredRetinex), so a global scale error of ours is the light fit's.

Writes OUT/sun_albedo.csv and OUT/sun_albedo.png (per room: the regions (floor orange, walls
green, ceiling red in the sun's shade; sunlit purple, sunlit and clipped brown, clipped pink; not
scored blue), |error|, log2 of ours /
truth, of Gamma / truth's, of the fit's direct / truth's where the truth has direct light (at least 2 %
of its direct plus indirect light; elsewhere blank)); prints a Markdown table.

A CLI without --physical (a build before it) gets NaN in the light fit's columns. --rooms takes
any rooms (a room without a sun has no sunlit regions): the "all" rows are the albedo MAE of ours
and Retinex per room, as bench_albedo.py scores them.

usage: bench_sun_albedo.py INLAY_CLI [--rooms d4,t04,t10] [--out DIR]
"""
import json, os, subprocess, sys, tempfile
import numpy as np
import OpenImageIO as oiio
import cv2
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

LUM = np.array([0.2126, 0.7152, 0.0722])


def read(path):
    b = oiio.ImageBuf(path)
    if b.has_error:
        raise SystemExit("cannot read %s: %s" % (path, b.geterror()))
    a = b.get_pixels(oiio.FLOAT)
    return a[:, :, :3] if a.shape[2] >= 3 else np.repeat(a[:, :, :1], 3, 2)


def room_dir(name):
    base = "scenes-train" if name.startswith("t") else "scenes"
    root = os.path.join(benchlib.shared_dir(), base)
    return os.path.join(root, [d for d in sorted(os.listdir(root)) if d.startswith(name)][0])


def run_cli(cli, room, tmp):
    scene = os.path.join(tmp, "scene.json")
    subprocess.run(["/usr/bin/python3", os.path.join(benchlib.shared_dir(), "tools", "harness.py"),
                    "scene", room, scene], check=True, capture_output=True)
    f = {k: os.path.join(tmp, k + ".exr") for k in ("ours", "direct", "gathered", "physical", "retinex")}
    cmd = [cli, "decompose", scene, "--albedo", f["ours"], "--direct", f["direct"], "--gathered", f["gathered"],
           "--quiet"]
    # A build before --physical (exit 2 on the option): the light fit's albedo columns are NaN.
    if subprocess.run(cmd + ["--physical", f["physical"]], capture_output=True).returncode == 2:
        subprocess.run(cmd, check=True, capture_output=True)
        f.pop("physical")
    subprocess.run([cli, "decompose", scene, "--albedo", f["retinex"], "--method", "retinex", "--quiet"],
                   check=True, capture_output=True)
    photo = json.load(open(scene))["photo"]
    est = {k: read(p) for k, p in f.items()}
    est.setdefault("physical", np.full_like(est["ours"], np.nan))
    return est, cv2.imread(photo, cv2.IMREAD_UNCHANGED)


def truth_of(room):
    t = json.load(open(os.path.join(room, "truth.json")))
    k = t["exposure"]["scale"]
    tr = {"albedo": read(os.path.join(room, "albedo.exr")), "direct": k * read(os.path.join(room, "direct.exr")),
          "indirect": k * read(os.path.join(room, "indirect.exr")), "normal": read(os.path.join(room, "normal.exr")),
          "labels": cv2.imread(os.path.join(room, "labels.png"), cv2.IMREAD_GRAYSCALE),
          "emit": read(os.path.join(room, "emission.exr")).max(2)}
    sun = t.get("sun") or {}
    l = np.array(sun.get("direction_to_sun", [0, 1, 0]))
    cos = np.clip((tr["normal"] * l).sum(2), 0, None)
    # The sun's own direct light, photo units: strength x colour x cos / pi x exposure scale.
    tr["sun"] = k * sun.get("strength_W_m2", 0) * cos[..., None] * np.array(sun.get("color", [1, 1, 1])) / np.pi
    return tr


def regions(tr, photo8, scored):
    lab = tr["labels"]
    clipped = photo8[:, :, :3].max(2) >= (254 if photo8.dtype == np.uint8 else 65278)
    sunlit = (tr["sun"] @ LUM > 1e-6) & (tr["direct"] @ LUM >= 0.5 * (tr["sun"] @ LUM))
    wall = (lab >= 3) & (lab <= 6)
    r = {"all": scored, "sunlit": scored & sunlit, "sunlit clipped": scored & sunlit & clipped,
         "sunlit unclipped": scored & sunlit & ~clipped, "sunlit floor": scored & sunlit & (lab == 1),
         "sunlit walls (shaft)": scored & sunlit & wall, "clipped, not sunlit": scored & clipped & ~sunlit,
         "shade floor": scored & ~sunlit & ~clipped & (lab == 1),
         "shade walls": scored & ~sunlit & ~clipped & wall,
         "shade ceiling": scored & ~sunlit & ~clipped & (lab == 2)}
    return r


def best_scale(e, t):
    return float((t * e).sum() / max((e * e).sum(), 1e-12))


def median_ratio(a, b, m):
    la, lb = a[m] @ LUM, b[m] @ LUM
    ok = (lb > 1e-6) & np.isfinite(la)
    return float(np.median(la[ok] / lb[ok])) if ok.any() else float("nan")


def oracles(est, tr, photo_lin):
    """The light fit's albedo with its shading's parts swapped for the truth's, per pixel."""
    with np.errstate(divide="ignore", invalid="ignore"):
        shading = np.where(est["physical"] > 1e-6, photo_lin / est["physical"], np.nan)
        fit_direct = np.clip(shading - est["gathered"], 0, None)
        swap = {"fit": shading, "fit_true_gamma": fit_direct + tr["indirect"],
                "fit_true_direct": tr["direct"] + est["gathered"], "fit_both_true": tr["direct"] + tr["indirect"]}
        out = {k: np.clip(photo_lin / s, 0, 1) for k, s in swap.items()}
    return out, fit_direct


def room_rows(name, cli):
    room = room_dir(name)
    with tempfile.TemporaryDirectory() as tmp:
        est, photo8 = run_cli(cli, room, tmp)
    tr = truth_of(room)
    photo_lin = np.where(photo8[:, :, 2::-1] / 255.0 <= 0.04045, photo8[:, :, 2::-1] / 255.0 / 12.92,
                         ((photo8[:, :, 2::-1] / 255.0 + 0.055) / 1.055) ** 2.4)
    scored = (tr["labels"] >= 1) & (tr["labels"] <= 6) & (tr["emit"] <= 1e-6) & np.isfinite(est["ours"]).all(2)
    reg = regions(tr, photo8, scored)
    t, o = tr["albedo"], est["ours"]
    s_room = best_scale(o[scored], t[scored])
    total = np.abs(o - t)[scored].sum()
    orc, fit_direct = oracles(est, tr, photo_lin)
    rows = []
    for rname, m in reg.items():
        if m.sum() < 50:
            continue
        row = {"room": name, "region": rname, "pixels": int(m.sum()),
               "error_share": float(np.abs(o - t)[m].sum() / total),
               "mae": float(np.abs(o - t)[m].mean()), "mae_room_scale": float(np.abs(s_room * o - t)[m].mean()),
               "mae_own_scale": float(np.abs(best_scale(o[m], t[m]) * o - t)[m].mean()),
               "retinex_mae": float(np.abs(est["retinex"] - t)[m].mean()), "room_scale": s_room,
               "ours_over_true": median_ratio(o, t, m), "fit_over_true": median_ratio(est["physical"], t, m),
               "gamma_over_true": median_ratio(est["gathered"], tr["indirect"], m),
               "fit_direct_over_true": median_ratio(fit_direct, tr["direct"], m)}
        for k, a in orc.items():
            ok = m & np.isfinite(a).all(2)
            row["mae_" + k] = float(np.abs(a - t)[ok].mean()) if ok.any() else float("nan")
        rows.append(row)
    return rows, {"regions": reg, "ours": o, "truth": t, "gathered": est["gathered"], "tr": tr, "fit_direct": fit_direct}


def plot(path, maps):
    # regions: floor orange, walls green, ceiling red (in shade); sunlit purple, sunlit clipped
    # brown, clipped pink; not scored blue
    names = ["regions", "|ours - truth|", "log2 ours / truth", "log2 Gamma / truth's",
             "log2 fit direct / truth's\n(blank: truth's direct < 2 % of its light)"]
    with benchlib.figure(path, len(maps), 5, figsize=(17, 2.9 * len(maps)), squeeze=False) as ax:
        if ax is None:
            return
        for i, (name, mp) in enumerate(maps.items()):
            reg, tr = mp["regions"], mp["tr"]
            code = np.zeros(reg["all"].shape)
            for k, rn in enumerate(["shade floor", "shade walls", "shade ceiling", "sunlit unclipped",
                                    "sunlit clipped", "clipped, not sunlit"]):
                code[reg[rn]] = k + 1
            # Where the truth has (almost) no direct light the ratio is noise over nothing: t10's
            # right wall holds the window, its direct light 0 in the truth, 2e-4 in the fit's model
            # (mean, against a Gamma of 0.22), which the ratio showed several times too bright.
            has_direct = (tr["direct"] @ LUM) >= 0.02 * ((tr["direct"] + tr["indirect"]) @ LUM)
            lg = lambda a, b: np.where(reg["all"], np.log2(np.maximum(a @ LUM, 1e-6) / np.maximum(b @ LUM, 1e-6)), np.nan)
            ims = [(code, "tab10", 0, 9), (np.where(reg["all"], np.abs(mp["ours"] - mp["truth"]).mean(2), np.nan), "magma", 0, 0.4),
                   (lg(mp["ours"], mp["truth"]), "coolwarm", -1.5, 1.5), (lg(mp["gathered"], tr["indirect"]), "coolwarm", -1.5, 1.5),
                   (np.where(has_direct, lg(mp["fit_direct"], tr["direct"]), np.nan), "coolwarm", -1.5, 1.5)]
            for j, (img, cm, lo, hi) in enumerate(ims):
                h = ax[i][j].imshow(img, cmap=cm, vmin=lo, vmax=hi)
                ax[i][j].set_title("%s: %s" % (name, names[j]), fontsize=8)
                ax[i][j].axis("off")
                if j:
                    ax[i][j].figure.colorbar(h, ax=ax[i][j], fraction=0.035)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    rows, maps = [], {}
    for name in opt("--rooms", "d4,t04,t10").split(","):
        r, mp = room_rows(name, cli)
        rows += r
        maps[name] = mp
    benchlib.write_csv(os.path.join(out, "sun_albedo.csv"), rows)
    plot(os.path.join(out, "sun_albedo.png"), maps)
    cols = ["room", "region", "pixels", "error_share", "mae", "mae_room_scale", "mae_own_scale", "retinex_mae",
            "ours_over_true", "fit_over_true", "gamma_over_true", "fit_direct_over_true", "mae_fit",
            "mae_fit_true_gamma", "mae_fit_true_direct", "mae_fit_both_true"]
    print("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols))
    for r in rows:
        print("| " + " | ".join(benchlib.cell(r[c]) for c in cols) + " |")


if __name__ == "__main__":
    main()
