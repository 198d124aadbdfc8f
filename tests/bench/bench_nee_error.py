#!/usr/bin/env python3
"""Error against run time of two or more renderer builds (docs/benchmarks.md, "Seventh pass").

  bench_nee_error.py OUT SCENE.json[,SCENE.json...] LABEL=BUILD [LABEL=BUILD ...]
                     [--spp 8,32] [--seeds 1,2,3] [--ref-spp 512] [--repeats 5]

BUILD is a build directory (app/inlay-cli and tests/bench/bench_throughput under it). Per scene:
a reference by the first build at --ref-spp (seed 101, kept in OUT), then every build at every
--spp and seed (one thread, no noise stop, no focus, no grain), the builds alternated. Error:
the RMSE of the linear composite against the reference's, over all pixels and over the object
pixels (the reference's mask > 0.5). Time: the CPU seconds of one sample of one thread, the
median of `bench_throughput SCENE --parts types --repeats N`'s full frames (two runs per build,
alternated), times the spp. Writes OUT/nee_error.csv (every render) and OUT/nee_error.png
(object RMSE against CPU seconds, the medians over seeds).
"""
import csv, os, re, statistics, subprocess, sys

import numpy as np


def option(argv, key, default):
    return argv[argv.index(key) + 1] if key in argv else default


def composite_and_mask(path):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(path)
    names = list(buf.spec().channelnames)
    px = np.asarray(buf.get_pixels(oiio.FLOAT)).astype(np.float64)
    rgb = px[:, :, [names.index("composite." + c) for c in "RGB"]]
    return rgb, px[:, :, names.index("mask.Y")]


def render(build, scene, out, spp, seed):
    layers = out + "_L.exr"
    if not os.path.exists(layers):
        cmd = ["nice", "-n", "10", os.path.join(build, "app/inlay-cli"), "render", scene, "-o", out + ".exr",
               "--layers", layers, "--spp", str(spp), "--seconds", "100000", "--noise", "0", "--no-focus",
               "--no-grain", "--threads", "1", "--seed", str(seed)]
        subprocess.run(cmd, check=True, capture_output=True, text=True)
    return layers


def frame_seconds(build, scene, tmp, repeats):
    os.makedirs(tmp, exist_ok=True)
    cmd = ["nice", "-n", "10", os.path.join(build, "tests/bench/bench_throughput"), scene, tmp, "--parts", "types",
           "--repeats", str(repeats)]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return float(re.search(r"frame: ([0-9.]+) s CPU", text).group(1))


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    out, scenes = argv[1], argv[2].split(",")
    builds = [a.split("=", 1) for a in argv[3:] if "=" in a and not a.startswith("--")]
    spps = [int(s) for s in option(argv, "--spp", "8,32").split(",")]
    seeds = [int(s) for s in option(argv, "--seeds", "1,2,3").split(",")]
    ref_spp, repeats = int(option(argv, "--ref-spp", "512")), int(option(argv, "--repeats", "5"))
    os.makedirs(out, exist_ok=True)
    rows = []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        ref, mask = composite_and_mask(render(builds[0][1], scene, os.path.join(out, name + "_ref"), ref_spp, 101))
        obj = mask > 0.5
        per_spp = {}
        for rnd in range(2):
            for label, build in builds:
                t = frame_seconds(build, scene, os.path.join(out, "tp_" + label), repeats)
                per_spp.setdefault(label, []).append(t)
        for spp in spps:
            for seed in seeds:
                for label, build in builds:
                    img, _ = composite_and_mask(render(build, scene, os.path.join(out, f"{name}_{label}_{spp}_{seed}"),
                                                       spp, seed))
                    d2 = np.sum((img - ref) ** 2, axis=2) / 3
                    rows.append(dict(scene=name, build=label, spp=spp, seed=seed,
                                     cpu_s_per_spp=statistics.median(per_spp[label]),
                                     cpu_s=spp * statistics.median(per_spp[label]),
                                     rmse_all=float(np.sqrt(d2.mean())), rmse_object=float(np.sqrt(d2[obj].mean()))))
                    print(rows[-1], flush=True)
    with open(os.path.join(out, "nee_error.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(out, "nee_error.png"))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for label in dict.fromkeys(r["build"] for r in rows):
            pts = []
            for spp in sorted({r["spp"] for r in rows}):
                sel = [r for r in rows if r["scene"] == scene and r["build"] == label and r["spp"] == spp]
                if sel:
                    pts.append((sel[0]["cpu_s"], statistics.median(r["rmse_object"] for r in sel)))
            ax.loglog(*zip(*pts), "o-", label=label)
        ax.set_title(scene + ": object RMSE against CPU time")
        ax.set_xlabel("CPU seconds of one thread (render)")
        ax.set_ylabel("object RMSE (median over seeds)")
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


if __name__ == "__main__":
    main(sys.argv)
