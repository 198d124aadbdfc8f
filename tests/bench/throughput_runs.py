#!/usr/bin/env python3
"""Alternated bench_throughput runs (docs/benchmarks.md, "Seventh pass") as a CSV, medians and a plot.

  throughput_runs.py LOG CSV PNG KEY=LABEL KEY=LABEL

LOG holds the runs, each after a line "=== round R build KEY load L" and printing bench_throughput
--parts types' five last lines; KEY=LABEL names the two builds (the first is the baseline)."""
import re, csv, statistics, sys
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
log = open(sys.argv[1]).read().split("=== ")[1:]
names = dict(a.split("=", 1) for a in sys.argv[4:6])
rows = []
for block in log:
    m = re.match(r"round (\d+) build (\w+) load ([0-9.]+)", block)
    rnd, b, load = m.group(1), names[m.group(2)], m.group(3)
    fr = re.search(r"frame: ([0-9.]+) s CPU \(maxDepth 0: ([0-9.]+) s\), NEE ([0-9.]+) %.*checksum (\w+)", block)
    pr = re.search(r"with every ray timed: NEE ([0-9.]+) %, timing overhead [0-9.]+ %, ratios bounce ([0-9.]+) shadow ([0-9.]+)", block)
    for t in re.finditer(r"(\w+)\s+(\d+) rays\s+renderer\s+([0-9.]+) M/s/thread\s+bare Embree\s+([0-9.]+) M/s/thread\s+ratio ([0-9.]+)\s+\(bare one ray at a time\s+([0-9.]+), ratio ([0-9.]+)\)", block):
        typ = t.group(1)
        per_ray = {"camera": "", "bounce": pr.group(2), "shadow": pr.group(3)}[typ]
        rows.append(dict(binary=b, run=rnd, load=load, type=typ, rays=t.group(2), renderer_M_per_s_per_thread=t.group(3),
                         bare_M_per_s_per_thread=t.group(4), ratio=t.group(5), bare_single_M_per_s_per_thread=t.group(6),
                         ratio_single=t.group(7), ratio_nee_share_every_ray_timed=per_ray, frame_cpu_s=fr.group(1),
                         frame_depth0_cpu_s=fr.group(2), nee_share_percent=fr.group(3),
                         nee_share_every_ray_timed_percent=pr.group(1), checksum=fr.group(4)))
with open(sys.argv[2], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys())); w.writeheader(); w.writerows(rows)
def med(b, typ, key):
    return statistics.median(float(r[key]) for r in rows if r["binary"] == b and r["type"] == typ and r[key] != "")
def rng(b, typ, key):
    v = [float(r[key]) for r in rows if r["binary"] == b and r["type"] == typ and r[key] != ""]
    return "%.3f-%.3f" % (min(v), max(v))
for b in names.values():
    print(b)
    for typ in ["camera", "bounce", "shadow"]:
        print("  %s renderer %.2f bare %.2f ratio %.3f (%s) single %.3f  per-ray-timed ratio %s" % (
            typ, med(b, typ, "renderer_M_per_s_per_thread"), med(b, typ, "bare_M_per_s_per_thread"), med(b, typ, "ratio"),
            rng(b, typ, "ratio"), med(b, typ, "ratio_single"),
            "%.3f (%s)" % (med(b, typ, "ratio_nee_share_every_ray_timed"), rng(b, typ, "ratio_nee_share_every_ray_timed")) if typ != "camera" else "-"))
    print("  frame %.3f (%s) depth0 %.3f nee %.1f per-ray nee %.1f" % (med(b, "shadow", "frame_cpu_s"), rng(b, "shadow", "frame_cpu_s"),
          med(b, "shadow", "frame_depth0_cpu_s"), med(b, "shadow", "nee_share_percent"), med(b, "shadow", "nee_share_every_ray_timed_percent")))
fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
for ax, typ in zip(axes, ["camera", "bounce", "shadow"]):
    for k, b in enumerate(names.values()):
        v = [float(r["ratio"]) for r in rows if r["binary"] == b and r["type"] == typ]
        ax.plot([k + 0.08 * (i - 3) for i in range(len(v))], v, "o", label=b)
        if typ != "camera":
            v2 = [float(r["ratio_nee_share_every_ray_timed"]) for r in rows if r["binary"] == b and r["type"] == typ]
            ax.plot([k + 0.3 + 0.04 * (i - 3) for i in range(len(v2))], v2, "x", color="C%d" % k,
                    label=b + " (NEE share with every ray timed)")
    ax.axhline(0.6, color="grey", ls="--", lw=0.8)
    ax.set_title(typ + " rays: renderer / bare Embree")
    ax.set_xticks([0, 1]); ax.set_xticklabels([n.split()[0] for n in names.values()]); ax.set_ylim(0, 0.65)
axes[2].legend(fontsize=7, loc="lower right")
fig.suptitle("example, 512 x 384, one thread: 7 alternated runs per build (dashed: the 0.6 target)", fontsize=10); fig.tight_layout(); fig.savefig(sys.argv[3], dpi=100)
