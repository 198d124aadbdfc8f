#!/usr/bin/python3
"""The renderer's ray rate against a bare Embree loop casting the same rays: runs
bench_throughput on the bundled example at its full 512x384 (rays per second per thread by type,
CPU milliseconds per sample against object triangles and against the number of lights) into
OUT/throughput/LABEL/, then plots every label found there side by side (so a run before and one
after a change compare in one figure). Prints Markdown tables.

Writes OUT/throughput/LABEL/{types,triangles,lights}.csv and OUT/throughput.png.

usage: bench_throughput.py BUILD_DIR [--out DIR] [--label current] [--scene SCENE.json]
                           [--parts types,waves,triangles,lights] [--repeats 3] [--plot-only]
"""
import csv, os, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

TOP = os.path.abspath(os.path.join(benchlib.HERE, "..", ".."))


def read(path):
    return list(csv.DictReader(open(path))) if os.path.isfile(path) else []


def main():
    build, opt, out = benchlib.command_line(__doc__)
    root = os.path.join(out, "throughput")
    label = opt("--label", "current")
    if "--plot-only" not in sys.argv:
        here = os.path.join(root, label)
        os.makedirs(here, exist_ok=True)
        exe = os.path.join(build, "tests", "bench", "bench_throughput")
        scene = opt("--scene", os.path.join(TOP, "resources", "example", "scene.json"))
        subprocess.run(["nice", "-n", "10", exe, scene, here, "--parts", opt("--parts", "types,waves,triangles,lights"),
                        "--repeats", opt("--repeats", "3")], check=True)
    labels = sorted((d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d))),
                    key=lambda d: os.path.getmtime(os.path.join(root, d)))
    data = {l: {p: read(os.path.join(root, l, p + ".csv")) for p in ("types", "triangles", "lights")} for l in labels}

    if data[label]["types"]:
        benchlib.write_table("throughput", data[label]["types"], source=os.path.join(root, label, "types.csv"))
    print("| run | type | rays | renderer M rays/s/thread | bare Embree M rays/s/thread | ratio "
          "| bare, one ray at a time | ratio to it |")
    print("|---|---|---|---|---|---|---|---|")
    for l in labels:
        for r in data[l]["types"]:
            single = (f"{float(r['bare_single_per_s_per_thread']) * 1e-6:.2f} | {float(r['ratio_single']):.2f}"
                      if r.get("ratio_single") else "- | -")  # runs before the camera packets
            print(f"| {l} | {r['type']} | {r['rays']} | {float(r['renderer_per_s_per_thread']) * 1e-6:.2f} | "
                  f"{float(r['bare_per_s_per_thread']) * 1e-6:.2f} | {float(r['ratio']):.2f} | {single} |")
    for part, key in (("triangles", "triangles"), ("lights", "lights")):
        print(f"\n| run | {key} | ms/spp | bare Embree ms/spp |")
        print("|---|---|---|---|")
        for l in labels:
            for r in data[l][part]:
                print(f"| {l} | {r[key]} | {float(r['ms_per_spp']):.0f} | {float(r['bare_ms_per_spp']):.0f} |")

    with benchlib.figure(os.path.join(out, "throughput.png"), 1, 3, figsize=(15, 4.3)) as ax:
        if ax is None:
            return
        types = ["camera", "bounce", "shadow"]
        width = 0.8 / max(1, len(labels))
        single_shown = False
        for i, l in enumerate(labels):
            rows = {r["type"]: r for r in data[l]["types"]}
            xs = [k + i * width for k in range(len(types)) if types[k] in rows]
            ax[0].bar(xs, [float(rows[t]["ratio"]) for t in types if t in rows], width, label=l)
            if all(rows[t].get("ratio_single") for t in types if t in rows):  # runs since the camera packets
                ax[0].plot(xs, [float(rows[t]["ratio_single"]) for t in types if t in rows], "k_", ms=14, mew=2,
                           label="against the bare loop one ray at a time" if not single_shown else None)
                single_shown = True
        ax[0].axhline(0.6, color="k", ls="--", lw=1, label="target 0.6")
        ax[0].set_xticks([k + 0.4 - width / 2 for k in range(len(types))], types)
        ax[0].set_title("renderer / bare Embree, rays per s per thread")
        for i, l in enumerate(labels):
            for a, part, key in ((ax[1], "triangles", "triangles"), (ax[2], "lights", "lights")):
                rows = data[l][part]
                if not rows:
                    continue
                xs = [int(r[key]) for r in rows]
                line, = a.plot(xs, [float(r["ms_per_spp"]) for r in rows], "o-", label=f"{l}: renderer")
                a.plot(xs, [float(r["bare_ms_per_spp"]) for r in rows], "s:", color=line.get_color(),
                       label=f"{l}: its rays, bare Embree")
        ax[1].set_xscale("log")
        ax[1].set_xlabel("object triangles")
        ax[1].set_title("CPU ms per sample, 512x384, 1 thread")
        ax[2].set_xscale("log", base=2)
        ax[2].set_xlabel("lights (one light cut into strips)")
        ax[2].set_title("CPU ms per sample, 512x384, 1 thread")
        for a in ax:
            a.grid(True, alpha=0.3)
            a.legend(fontsize=7)
        ax[1].set_ylim(bottom=0)
        ax[2].set_ylim(bottom=0)
        if not any(data[l]["lights"] for l in labels):  # --parts without lights: say so, not an empty plot
            ax[2].clear()
            ax[2].text(0.5, 0.5, "lights: not run (--parts)", ha="center", va="center", transform=ax[2].transAxes)
            ax[2].set_axis_off()


if __name__ == "__main__":
    main()
