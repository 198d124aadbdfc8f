#!/usr/bin/python3
"""Inlay's path tracer against Blender Cycles on the exported glTF of the ../shared rooms.

For each room: ../shared/tools/harness.py writes the assisted scene file; bench_cycles_ours
prepares it, exports scene.gltf and path traces the same scene in full (linear EXR with a
per-pixel region layer: room surface id or 100 for the object); Blender (headless, Debian's
`blender` package, not a CI dependency) renders the glTF with cycles_render.py at the same size
and samples. Compared: mean radiance per region (surfaces and the object, pixels seeing an
emitter left out), relative difference ours / Cycles - 1.

Writes OUT/cycles_regions.csv (scene, region, pixels, ours, cycles, rel_diff, seconds),
OUT/cycles_<scene>.png (ours | Cycles | difference) and OUT/cycles_rel_diff.png; prints a table.

usage: bench_cycles.py BUILD_DIR [--out DIR] [--scenes d1,d2,d3,d5] [--size 160x120] [--spp 256]
                       [--threads 2] [--blender blender]
"""
import json, os, subprocess, sys, time

import cv2
import numpy as np
import OpenImageIO as oiio
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.environ.get("INLAY_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))
PY = "/usr/bin/python3"
NAMES = {0: "floor", 1: "ceiling", 2: "wall_left", 3: "wall_right", 4: "wall_back", 5: "wall_rear", 100: "object"}


def run(cmd):
    t = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("failed (%d): %s\n%s\n%s" % (p.returncode, " ".join(cmd), p.stdout[-2000:], p.stderr[-2000:]))
    return time.monotonic() - t, p.stdout


def read_layers(path):
    """Channels of an EXR grouped by layer ("with_objects.R" -> "with_objects"): {name: H x W x C}."""
    inp = oiio.ImageInput.open(path)
    spec = inp.spec()
    px = inp.read_image(0, spec.nchannels, "float").reshape(spec.height, spec.width, spec.nchannels)
    inp.close()
    groups = {}
    for i, ch in enumerate(spec.channelnames):
        layer = ch.rsplit(".", 1)[0] if "." in ch else ""
        groups.setdefault(layer, []).append(i)
    return {k: px[..., v] for k, v in groups.items()}


def tonemap(x):
    return (np.clip(x / (1 + x), 0, 1) ** (1 / 2.2) * 255).astype(np.uint8)


def main():
    build, opt, out = benchlib.command_line(__doc__)
    scenes = opt("--scenes", "d1,d2,d3,d5").split(",")
    w, h = [int(v) for v in opt("--size", "160x120").split("x")]
    spp, threads, blender = int(opt("--spp", "256")), int(opt("--threads", "2")), opt("--blender", "blender")
    if not os.path.isdir(os.path.join(SHARED, "scenes")):
        print("skipped: ../shared/scenes not present")
        return 77
    os.makedirs(out, exist_ok=True)
    dirs = {d.split("_")[0]: d for d in os.listdir(os.path.join(SHARED, "scenes"))}
    rows = []
    for key in scenes:
        room = os.path.join(SHARED, "scenes", dirs[key])
        work = os.path.join(out, "cycles_" + key)
        os.makedirs(work, exist_ok=True)
        scene_json = os.path.join(work, "scene.json")
        run([PY, os.path.join(SHARED, "tools", "harness.py"), "scene", room, scene_json, "--seconds", "30"])
        _, ours_out = run([os.path.join(build, "tests", "bench", "bench_cycles_ours"), scene_json, work,
                           str(w), str(h), str(spp), str(threads)])
        ours_info = json.loads(ours_out.strip().splitlines()[-1])
        t_cycles, _ = run([blender, "-b", "--factory-startup", "-noaudio", "-P", os.path.join(HERE, "cycles_render.py"),
                           "--", os.path.join(work, "scene.gltf"), os.path.join(work, "cycles.exr"), str(w), str(h),
                           str(spp), str(threads)])
        layers = read_layers(os.path.join(work, "ours.exr"))
        ours, region = layers["with_objects"][..., :3], layers["region"][..., 0]
        cyc = list(read_layers(os.path.join(work, "cycles.exr")).values())[0][..., :3]
        # Lights seen directly, and 2 px around them (edge pixels mix emitter and room).
        emitter = cv2.dilate(((cyc.max(axis=2) > 2.0) | (ours.max(axis=2) > 2.0)).astype(np.uint8),
                             np.ones((5, 5), np.uint8)) > 0
        for r in sorted(set(np.unique(region).astype(int)) - {-1}):
            sel = (region == r) & ~emitter
            if sel.sum() < 30:
                continue
            mo, mc = float(ours[sel].mean()), float(cyc[sel].mean())
            rows.append({"scene": key, "region": NAMES.get(r, "surface_%d" % r), "pixels": int(sel.sum()),
                         "ours": mo, "cycles": mc, "rel_diff": mo / mc - 1 if mc > 0 else float("nan"),
                         "ours_seconds": ours_info["seconds"], "cycles_seconds": t_cycles})
        sel = (region >= 0) & ~emitter
        rows.append({"scene": key, "region": "all", "pixels": int(sel.sum()), "ours": float(ours[sel].mean()),
                     "cycles": float(cyc[sel].mean()), "rel_diff": float(ours[sel].mean() / cyc[sel].mean() - 1),
                     "ours_seconds": ours_info["seconds"], "cycles_seconds": t_cycles})
        diff = np.abs(ours - cyc)
        strip = np.hstack([tonemap(ours), tonemap(cyc), tonemap(4 * diff)])
        cv2.imwrite(os.path.join(out, "cycles_%s.png" % key), strip[..., ::-1])
    benchlib.write_csv(os.path.join(out, "cycles_regions.csv"), rows, table="cycles")
    print("| scene | region | pixels | ours | Cycles | ours/Cycles - 1 |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %d | %.4f | %.4f | %+.2f%% |" % (r["scene"], r["region"], r["pixels"], r["ours"], r["cycles"],
                                                        100 * r["rel_diff"]))
    with benchlib.figure(os.path.join(out, "cycles_rel_diff.png"), figsize=(10, 4)) as ax:
        if ax is not None:
            labels = ["%s %s" % (r["scene"], r["region"]) for r in rows]
            ax.bar(range(len(rows)), [100 * r["rel_diff"] for r in rows])
            ax.axhline(2, color="r", lw=0.8), ax.axhline(-2, color="r", lw=0.8)
            ax.set_xticks(range(len(rows)), labels, rotation=90, fontsize=7)
            ax.set_ylabel("mean radiance, ours / Cycles - 1 (%)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
