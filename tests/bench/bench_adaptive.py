#!/usr/bin/python3
"""Adaptive sampling against time: what each way of spending the render's samples gives on the
rooms of ../shared/scenes, scored as the acceptance check scores (../shared/tools/harness.py).

Per room the harness writes the assisted scene file; inlay-cli renders it for each time budget
(--seconds B, no sample cap) with
  uniform    every pixel sampled equally (--noise 0 --no-focus)
  focus      pixels the object has not changed revisited every 4th wave only (--noise 0)
  adaptive   the default: each pixel sampled until its composite's estimated standard error is
             below --noise (default 0.004), worst pixels first (render/session.h)
and the harness scores each composite: object RMSE and mean-adjusted RMSE against the true
photo-with-object, the object's surroundings ('around') and the rest of the frame ('outside':
where the composite should be the photo). From the --layers EXR: the object's mean samples per
pixel and its estimated noise (RMS of the per-pixel standard error), the share of all samples
spent on the object. Render seconds are the renderer's own (the last frame's time), CPU seconds
the whole process's (preparation included; the machine's load changes the first, not the second).

Writes OUT/adaptive.csv and OUT/adaptive.png (object RMSE and estimated object noise against
render time, per room and way).

usage: bench_adaptive.py INLAY_CLI [--out DIR] [--scenes d1,d6] [--budgets 8,24] [--ways uniform,focus,adaptive] [--noise 0.004]
"""
import csv, json, os, resource, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

WAYS = {"uniform": ["--noise", "0", "--no-focus"], "focus": ["--noise", "0"], "adaptive": []}


def layers(path, scene):
    """(object mean spp, object estimated noise RMS, object share of samples) from --layers."""
    import OpenImageIO as oiio
    import cv2
    buf = oiio.ImageBuf(path)
    spec = buf.spec()
    names = list(spec.channelnames)
    a = buf.get_pixels(oiio.FLOAT).reshape(spec.height, spec.width, -1)
    n, e = a[..., names.index("samples.Y")], a[..., names.index("noise.Y")]
    m = cv2.imread(os.path.join(scene, "object_mask.png"), cv2.IMREAD_GRAYSCALE) >= 128
    return float(n[m].mean()), float(np.sqrt(np.mean(e[m] ** 2))), float(n[m].sum() / max(1.0, n.sum()))


def cpu_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    budgets = [float(b) for b in opt("--budgets", "8,24").split(",")]
    ways = opt("--ways", ",".join(WAYS)).split(",")
    noise = opt("--noise", "0.004")
    sdir, harness, names = benchlib.scene_rooms(opt("--scenes", "d1,d6"), out)
    py = sys.executable
    rows = []
    for name in names:
        sd = os.path.join(sdir, name)
        sf = os.path.join(out, "%s_adaptive_scene.json" % name)
        subprocess.run([py, harness, "scene", sd, sf], check=True)
        for way in ways:
            for b in budgets:
                stem = os.path.join(out, "%s_%s_%g" % (name, way, b))
                cmd = [cli, "render", sf, "-o", stem + ".png", "--quiet", "--seconds", str(b), "--spp", "100000",
                       "--layers", stem + ".exr", "--progress-csv", stem + ".csv"]
                if way == "adaptive":
                    cmd += ["--noise", noise]
                cmd += WAYS[way]
                cpu0 = cpu_of_children()
                p = subprocess.run(cmd, capture_output=True, text=True)
                cpu = cpu_of_children() - cpu0
                if p.returncode != 0:
                    print(name, way, b, "failed:", p.stderr.strip()[-300:], flush=True)
                    continue
                last = list(csv.DictReader(open(stem + ".csv")))[-1]
                s = json.loads(subprocess.run([py, harness, "score", sd, stem + ".png"], capture_output=True,
                                              text=True, check=True).stdout)
                spp, est, share = layers(stem + ".exr", sd)
                row = {"scene": name, "way": way, "budget_s": b, "render_s": round(float(last["seconds"]), 2),
                       "cpu_s": round(cpu, 1), "max_spp": int(last["spp"]), "object_spp": round(spp, 1),
                       "object_sample_share": round(share, 3), "object_noise_estimated": round(est, 4),
                       "object_rmse": round(s["object_rmse"], 4), "object_rmse_adjusted": round(s["object_rmse_adjusted"], 4),
                       "around_rmse": round(s["around_rmse"], 4), "outside_rmse": round(s["outside_rmse"], 4)}
                rows.append(row)
                print(json.dumps(row), flush=True)
    if not rows:
        return 1
    csvp = os.path.join(out, "adaptive.csv")
    benchlib.write_csv(csvp, rows, table="adaptive")
    with benchlib.figure(os.path.join(out, "adaptive.png"), 1, 2, figsize=(12, 4.2)) as ax:
        if ax is not None:
            for name in names:
                for way in ways:
                    pts = sorted((r["render_s"], r["object_rmse"], r["object_noise_estimated"]) for r in rows
                                 if r["scene"] == name and r["way"] == way)
                    if pts:
                        lab = "%s %s" % (name.split("_")[0], way)
                        ax[0].plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=lab)
                        ax[1].plot([p[0] for p in pts], [p[2] for p in pts], "o-", label=lab)
            ax[0].set(xlabel="render seconds", ylabel="object RMSE vs truth (sRGB)", title="harness score against time")
            ax[1].set(xlabel="render seconds", ylabel="estimated object noise (sRGB)", yscale="log",
                      title="render noise on the object against time")
            ax[0].legend(fontsize=7)
            ax[1].legend(fontsize=7)
    print("wrote", csvp)
    return 0


if __name__ == "__main__":
    sys.exit(main())
