#!/usr/bin/python3
"""Plots for bench_camera's CSV (Debian's python3 with numpy and matplotlib).

usage: bench_camera_plot.py OUT_DIR   (reads OUT_DIR/camera_bench.csv and camera_bench_summary.json,
                                        writes OUT_DIR/camera_*.png)
"""
import csv, json, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

out = benchlib.args(__doc__)[0]
rows = list(csv.DictReader(open(os.path.join(out, "camera_bench.csv"))))
summary = json.load(open(os.path.join(out, "camera_bench_summary.json")))
default = summary["default_budget"]
benchlib.write_table("camera", [
    {"set": set_, "budget": budget, "images": s["images"], "focal_rel_err_median": s["focal_rel_err_median"],
     "vp_angle_deg_max_median": s["vp_angle_deg_max_median"], "horizon_auc": s["horizon_auc"],
     "corner_err_px_max_median": s.get("corner_err_px_max_median", float("nan")), "ms_median": s["ms_median"]}
    for set_ in ("york", "scenes") for budget, s in sorted(summary.get(set_, {}).items(), key=lambda kv: int(kv[0]))],
    source=os.path.join(out, "camera_bench_summary.json"))


def col(set_, budget, key):
    v = [float(r[key]) for r in rows if r["set"] == set_ and int(r["budget"]) == budget]
    return np.array(v)


def auc(h):
    xs = np.linspace(0, 0.25, 251)
    return float(np.trapz([(h <= x).mean() for x in xs], xs) / 0.25)


for set_ in ("york", "scenes"):
    budgets = sorted({int(r["budget"]) for r in rows if r["set"] == set_})
    if not budgets:
        continue
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    h = col(set_, default, "horizon_err")
    xs = np.linspace(0, 0.25, 251)
    ax[0].plot(xs, [(h <= x).mean() for x in xs])
    ax[0].set_xlabel("horizon error / image height")
    ax[0].set_ylabel("fraction of images")
    ax[0].set_title(f"{set_}: horizon AUC(0.25) = {auc(h):.3f} (budget {default})")
    ax[0].grid(alpha=0.3)
    a = col(set_, default, "vp_angle_deg_max")
    ax[1].hist(np.clip(a, 0, 10), bins=40)
    ax[1].set_xlabel("worst vanishing-direction error (deg, clipped at 10)")
    ax[1].set_title(f"median {np.median(a):.2f} deg")
    f = col(set_, default, "focal_rel_err")
    ax[2].hist(np.clip(f, 0, 0.5), bins=40)
    ax[2].set_xlabel("relative focal error (clipped at 0.5)")
    ax[2].set_title(f"median {np.median(f):.3f}")
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"camera_{set_}_errors.png"), dpi=110)
    plt.close(fig)

    # Error against run time as the search budget varies: CPU time (one idle core's cost) when
    # the CSV has it, wall time on a shared machine counts the waits for a core too.
    tkey = "cpu_ms" if "cpu_ms" in rows[0] else "ms"
    ms = [np.median(col(set_, b, tkey)) for b in budgets]
    ang = [np.median(col(set_, b, "vp_angle_deg_max")) for b in budgets]
    foc = [np.median(col(set_, b, "focal_rel_err")) for b in budgets]
    aucs = [auc(col(set_, b, "horizon_err")) for b in budgets]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for k, (y, lab) in enumerate([(ang, "median worst-direction error (deg)"),
                                  (foc, "median relative focal error"),
                                  (aucs, "horizon AUC(0.25)")]):
        ax[k].plot(ms, y, "o-")
        for b, x_, y_ in zip(budgets, ms, y):
            ax[k].annotate(str(b), (x_, y_), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax[k].set_xlabel(f"median {'CPU ' if tkey == 'cpu_ms' else ''}ms per photo (one core)")
        ax[k].set_ylabel(lab)
        ax[k].grid(alpha=0.3)
    fig.suptitle(f"{set_}: error against run time (labels: hypotheses per focal rung)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"camera_{set_}_budget.png"), dpi=110)
    plt.close(fig)

    # The same per photo: one line per image through its budgets (a budget that helps one photo
    # and hurts another shows here, not in the medians).
    keys = [("vp_angle_deg_max", "worst-direction error (deg)"), ("horizon_err", "horizon error / height")]
    if set_ == "scenes":
        keys.append(("corner_err_px_max", "back-wall corner error, max (px)"))
    fig, ax = plt.subplots(1, len(keys), figsize=(5 * len(keys), 4.2))
    for name in sorted({r["image"] for r in rows if r["set"] == set_}):
        rr = sorted((r for r in rows if r["set"] == set_ and r["image"] == name), key=lambda r: int(r["budget"]))
        for k, (key, lab) in enumerate(keys):
            ax[k].plot([float(r[tkey]) for r in rr], [max(1e-4, float(r[key])) for r in rr], "-",
                       lw=0.8, alpha=0.6, label=name if set_ == "scenes" else None)
    for k, (key, lab) in enumerate(keys):
        ax[k].set(xscale="log", yscale="log", xlabel=f"{tkey} per photo (one core)", ylabel=lab)
        ax[k].grid(alpha=0.3)
    if set_ == "scenes":
        ax[0].legend(fontsize=7)
    fig.suptitle(f"{set_}: error against run time per photo (budgets {budgets})")
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"camera_{set_}_budget_per_image.png"), dpi=110)
    plt.close(fig)

scene = [r for r in rows if r["set"] == "scenes" and int(r["budget"]) == default]
if scene:
    fig, ax = plt.subplots(figsize=(8, 4))
    names = [r["image"] for r in scene]
    ax.bar(np.arange(len(scene)) - 0.2, [float(r["corner_err_px_max"]) for r in scene], 0.4, label="max")
    ax.bar(np.arange(len(scene)) + 0.2, [float(r["corner_err_px_mean"]) for r in scene], 0.4, label="mean")
    ax.set_xticks(np.arange(len(scene)))
    ax.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
    ax.set_ylabel("back-wall corner error (px)")
    ax.set_yscale("log")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "camera_scenes_corners.png"), dpi=110)
    plt.close(fig)
print("plots in", out)
