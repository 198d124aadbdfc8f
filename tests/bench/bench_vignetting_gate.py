#!/usr/bin/python3
"""camera.vignetting "auto" against "none" on the random cameras, and which photos a gate lets it
touch (issue #16, vignetting round).

Reads two sets of bench_generalization.py runs of the same variants with the same build and
--spp: one with --vignetting none, one with the product's "auto" (in any number of folders each,
e.g. one per half). A variant whose "auto" run applied nothing (lights JSON `vignetting.applied`
0) renders exactly as "none" does. A gate is a rule on what the pipeline sees before it applies
anything (the first light fit's estimate v and residual ratio, the response "auto" chose): its
object RMSE per photo is the "auto" run's where the gate lets the estimate through, else the
"none" run's, so every gate is measured without rendering again.

Gates:
  none             never devignette (the pipeline before this round)
  auto             the product: the estimate when 0.05 <= v < 0.6 (engine vignettingToApply)
  curve            as auto, and only where the response estimate chose a curve other than sRGB
  residual<=R      as auto, and only where the fit's residual with v over without is <= R (the
                   "none" run's last fit's ratio: the first fit's is not reported)

Writes OUT/vignetting_gate.csv (one row per photo: the camera's true curve and v, the estimate,
the residual ratio, the response family, object RMSE none / auto), OUT/vignetting_gate_summary.csv
(per half and gate: plain median, cameras median, cameras / plain, photos touched) and
OUT/vignetting_gate.png (object RMSE "none" against "auto" per photo; the ratio per gate and half).

With --oracle DIRS (runs with --vignetting true: the camera's own strength, read from
camera_variant.json) the rows get object_rmse_true_v and the summary an "oracle" row (every camera
photo devignetted by its true v; the plain photos as "none").

usage: bench_vignetting_gate.py --none DIR[,DIR...] --auto DIR[,DIR...] --out OUT [--residual 0.9,0.95]
                                [--oracle DIR[,DIR...]]
"""
import csv, json, os, statistics, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def arg(name, default=None):
    a = sys.argv[1:]
    return a[a.index(name) + 1] if name in a and a.index(name) + 1 < len(a) else default


def load(dirs):
    """(room, camera) -> the generalization.csv row plus its lights and response files."""
    out = {}
    for d in dirs.split(","):
        for r in csv.DictReader(open(os.path.join(d, "generalization.csv"))):
            if not r.get("object_rmse"):
                continue
            tag = "%s_%s" % (r["room"], r["camera"])
            lights = json.load(open(os.path.join(d, tag + "_lights.json"))).get("vignetting", {})
            resp_path = os.path.join(d, tag + "_response.json")
            family = json.load(open(resp_path)).get("family", "") if os.path.exists(resp_path) else ""
            cam = json.load(open(os.path.join(d, "variants", tag, "camera_variant.json")))
            out[(r["room"], r["camera"])] = dict(r, lights=lights, family=family, cam=cam)
    return out


def rows_of(none, auto, oracle):
    rows = []
    for key in sorted(set(none) & set(auto)):
        n, a = none[key], auto[key]
        rows.append({"room": key[0], "half": n["half"], "camera": key[1], "true_curve": n["cam"]["curve"],
                     "true_v": round(float(n["cam"].get("vignetting", 0.0)), 3),
                     # the estimate "auto" decided on (its first light fit), and the residual ratio of
                     # "none"'s last fit (the refit's; the first fit's is not reported)
                     "estimated_v": a["lights"].get("estimated_before_devignetting", n["lights"].get("v")),
                     "residual_ratio_refit": round(n["lights"].get("residual_ratio", 1), 3),
                     "response_family": n["family"], "applied_v": a["lights"].get("applied", 0.0),
                     "object_rmse_none": float(n["object_rmse"]), "object_rmse_auto": float(a["object_rmse"])})
        if key in oracle:
            rows[-1]["object_rmse_true_v"] = float(oracle[key]["object_rmse"])
    return rows


def gates(residuals, oracle):
    """Gate name -> for a photo row, the column it reads: "auto"'s render where the gate lets the
    estimate through, else "none"'s (the oracle: the true strength's render on the cameras)."""
    def through(ok):
        return lambda r: "object_rmse_auto" if r["applied_v"] > 0 and ok(r) else "object_rmse_none"
    g = {"none": lambda r: "object_rmse_none", "auto": through(lambda r: True),
         "curve": through(lambda r: r["response_family"] not in ("srgb", ""))}
    for t in residuals:
        g["residual<=%g" % t] = through(lambda r, t=t: r["residual_ratio_refit"] <= t)
    if oracle:
        g["oracle"] = lambda r: "object_rmse_true_v" if "object_rmse_true_v" in r else "object_rmse_none"
    return g


def summarise(rows, gate_fns):
    out = []
    for half in ("A", "B"):
        hr = [r for r in rows if r["half"] == half]
        plain = [r["object_rmse_none"] for r in hr if r["camera"] == "plain"]
        cams = [r for r in hr if r["camera"] != "plain"]
        for name, fn in gate_fns.items():
            vals = [r[fn(r)] for r in cams]
            pm = statistics.median(plain) if plain else float("nan")
            cm = statistics.median(vals) if vals else float("nan")
            out.append({"half": half, "gate": name, "plain_photos": len(plain), "camera_photos": len(cams),
                        "touched": sum(1 for r in cams if fn(r) != "object_rmse_none"),
                        "touched_plain": sum(1 for r in hr if r["camera"] == "plain" and fn(r) != "object_rmse_none"),
                        "plain_median": round(pm, 4), "cameras_median": round(cm, 4),
                        "cameras_mean": round(statistics.mean(vals), 4) if vals else "",
                        "cameras_over_plain": round(cm / pm, 3) if pm > 0 else ""})
    return out


def plot(out, rows, summary):
    with benchlib.figure(os.path.join(out, "vignetting_gate.png"), 1, 2, figsize=(12, 5)) as ax:
        if ax is None:
            return
        marks = {"reinhard": "o", "sigmoid": "^", "gamma": "s", "srgb": "x"}
        for half, colour in (("A", "tab:blue"), ("B", "tab:orange")):
            for curve, m in marks.items():
                pts = [r for r in rows if r["half"] == half and r["true_curve"] == curve]
                if pts:
                    ax[0].scatter([r["object_rmse_none"] for r in pts], [r["object_rmse_auto"] for r in pts],
                                  marker=m, color=colour, label="%s %s" % (half, curve))
        hi = max([r["object_rmse_none"] for r in rows] + [r["object_rmse_auto"] for r in rows] + [0.1])
        ax[0].plot([0, hi], [0, hi], "k:", lw=0.8)
        ax[0].set(xlabel='object RMSE, camera.vignetting "none"', ylabel='object RMSE, "auto"',
                  title="per photo (below the diagonal: auto better)")
        ax[0].legend(fontsize=7)
        names = list(dict.fromkeys(s["gate"] for s in summary))
        for k, half in enumerate(("A", "B")):
            vals = [next(s["cameras_over_plain"] for s in summary if s["half"] == half and s["gate"] == g)
                    for g in names]
            ax[1].bar([i + 0.4 * k for i in range(len(names))], vals, width=0.4, label="half " + half)
        ax[1].axhline(1.25, ls="--", color="grey")
        ax[1].set_xticks([i + 0.2 for i in range(len(names))])
        ax[1].set_xticklabels(names, fontsize=7, rotation=20)
        ax[1].set(ylabel="cameras median / plain median", title="per gate (target 1.25)")
        ax[1].legend(fontsize=8)


def main():
    none, auto, out = arg("--none"), arg("--auto"), arg("--out")
    if not (none and auto and out):
        print(__doc__)
        return 2
    os.makedirs(out, exist_ok=True)
    oracle = arg("--oracle")
    rows = rows_of(load(none), load(auto), load(oracle) if oracle else {})
    gate_fns = gates([float(t) for t in arg("--residual", "0.9,0.95").split(",")], bool(oracle))
    summary = summarise(rows, gate_fns)
    benchlib.write_csv(os.path.join(out, "vignetting_gate.csv"), rows)
    benchlib.write_csv(os.path.join(out, "vignetting_gate_summary.csv"), summary)
    plot(out, rows, summary)
    keys = list(summary[0])
    print("| %s |\n|%s" % (" | ".join(keys), "---|" * len(keys)))
    for s in summary:
        print("| " + " | ".join(str(s[k]) for k in keys) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
