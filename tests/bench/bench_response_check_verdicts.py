#!/usr/bin/python3
"""Does the response check's quick comparison (ResponseQuickCheck: the curve and sRGB on small
copies first) keep the verdicts of the full check? (issue #16: the response fit adds under 1 s)

  run     renders each photo once with one build and extra flags, and writes one row per photo
          to OUT/verdicts_LABEL.csv (appends; photos already there are skipped):
            inlay-cli render SCENE -o X.png --spp 1 --seconds 0 --noise 0 --threads 2 --quiet
                      --report R.json [ARGS]
          From the report: the response stage's CPU seconds, and when the estimate fitted a curve
          the "response check" record: the response kept, both residuals the verdict rests on,
          the copies' residuals and log ratio (when the build has them) and the check's CPU
          seconds (all of it, and the copies' steps alone).
  report  merges three runs: BASE (a build before the copies: the full check's verdict), FULL
          (this build with --response-quick-margin inf: the copies' and the full check's
          residuals on every photo) and PRODUCT (this build as shipped), and writes
          OUT/response_check_verdicts.csv (per photo: the three verdicts, the full and the copies'
          log ratio, the check's CPU seconds before and after), prints the disagreements and the
          widest copies' ratio that disagrees with the full check per half, and draws
          OUT/response_check_verdicts.png (the copies' log ratio against the full check's, the
          margin as a band; right: the check's CPU seconds before and after per photo). --open:
          runs with the evidence gate open (run ... --args "--response-quick-margin inf
          --min-srgb-residual 0 --min-improvement 0"), more photos for the margin: drawn hollow,
          counted apart, written to OUT/response_check_verdicts_open.csv. --copies LABEL (and
          LABEL:COPIES in --open): the copies' log ratio from another run, one with
          --response-quick-margin 0 (the copies always decide), e.g. with other copy settings
          (--response-quick-copy); the full check's ratio stays FULL's.

Photos: camera variants ROOM_sK / ROOM_plain as bench_response_check_cost.py makes them (cached
under OUT/variants), and York photos PNNNNNNN (a scene of the photo alone, camera estimated; --york
DIR). Half A: odd rooms; half B: even rooms; York: its own group.

usage: bench_response_check_verdicts.py run INLAY_CLI LABEL --photos t01_s1,...,P1020177 [--args "..."]
                                        [--york DIR] [--out DIR]
       bench_response_check_verdicts.py report --base LABEL --full LABEL --product LABEL
                                        [--copies LABEL] [--open LABEL[:COPIES],...] [--margin 0.1] [--out DIR]
"""
import csv, json, math, os, re, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402
import bench_response_check_cost as cost  # noqa: E402

COLUMNS = ["photo", "status", "kept", "curve_res", "srgb_res", "q_curve", "q_srgb", "q_log", "q_decided",
           "response_cpu", "check_cpu", "copies_cpu"]
NUMBER = r"(-?[0-9.]+|nan|-?inf)"


def scene_of(name, folder, york):
    return cost.york_scene(name, folder, york) if name.startswith("P") else cost.native_variant(name, folder)


def parse_check(stages):
    """The response check's figures from a report's stages ({} when it did not run)."""
    check = [s for s in stages if s["name"] == "response check" and s.get("ran")]
    if not check:
        return {"kept": "-"}
    d = check[0]["detail"]
    steps = check[0].get("steps", [])
    # Since resp21 the two copies run side by side: each copy's records then count the process's
    # CPU while they ran, the other copy's included; the step "both copies, ..." times them together.
    both = [s for s in steps if s["name"].startswith("both copies, ")]
    copies = both[0]["cpu_seconds"] if both else sum(s["cpu_seconds"] for s in steps if s["name"].startswith("copy"))
    row = {"kept": "curve" if d.startswith("the curve kept") else "srgb",
           "check_cpu": round(check[0]["cpu_seconds"], 3), "copies_cpu": round(copies, 3)}
    m = re.search(r"is %s, with sRGB %s" % (NUMBER, NUMBER), d)
    if m:
        row["curve_res"], row["srgb_res"] = m.group(1), m.group(2)
    m = re.search(r"copies %s against %s, log ratio %s (beyond|within)" % (NUMBER, NUMBER, NUMBER), d)
    if m:
        row["q_curve"], row["q_srgb"], row["q_log"], row["q_decided"] = m.groups()
    return row


def run(a, out):
    cli, label = os.path.abspath(a[1]), a[2]
    opt = lambda key, default: benchlib.option(a, key, default)
    folder = os.path.join(out, "variants")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(out, "verdicts_%s.csv" % label)
    rows = benchlib.read_csv(path) if os.path.exists(path) else []
    done = {r["photo"] for r in rows}
    york = opt("--york", os.path.join(benchlib.shared_dir(), "york"))
    for name in [p for p in opt("--photos", "").split(",") if p and p not in done]:
        report = os.path.join(out, "report_%s.json" % label)
        cmd = ["nice", "-n", "10", cli, "render", scene_of(name, folder, york), "-o",
               os.path.join(out, "composite_%s.png" % label), "--spp", "1", "--seconds", "0", "--noise", "0",
               "--threads", "2", "--quiet", "--report", report] + opt("--args", "").split()
        p = subprocess.run(cmd, capture_output=True, text=True)
        row = {"photo": name, "status": p.returncode}
        if p.returncode == 0:
            stages = json.load(open(report))["stages"]
            row["response_cpu"] = round([s for s in stages if s["name"] == "response"][0]["cpu_seconds"], 3)
            row.update(parse_check(stages))
        else:
            row["kept"] = "error: " + p.stderr.strip()[-200:]
        print(json.dumps(row), flush=True)
        rows.append(row)
        benchlib.write_csv(path, rows, columns=COLUMNS)
    return 0


def group(name):
    return "York" if name.startswith("P") else benchlib.half(name.split("_")[0])


def log_ratio(curve, srgb):
    try:
        c, s = float(curve), float(srgb)
        return math.log(c / s) if c > 0 and s > 0 else float("nan")
    except (TypeError, ValueError):
        return float("nan")


def load(out, label):
    return {r["photo"]: r for r in benchlib.read_csv(os.path.join(out, "verdicts_%s.csv" % label))}


def merged(out, base, full, product, copies):
    b, f, p = load(out, base), load(out, full), load(out, product)
    c = load(out, copies) if copies else f
    rows = []
    for name in b:
        rb, rf, rp, rc = b[name], f.get(name, {}), p.get(name, {}), c.get(name, {})
        rows.append({"photo": name, "group": group(name), "kept_before": rb.get("kept", ""),
                     "kept_full": rf.get("kept", ""), "kept_after": rp.get("kept", ""),
                     "full_log_ratio": round(log_ratio(rf.get("curve_res"), rf.get("srgb_res")), 4),
                     "copies_log_ratio": rc.get("q_log", ""), "decided_by_copies": rp.get("q_decided", "") == "beyond",
                     "check_cpu_before": rb.get("check_cpu", ""), "check_cpu_after": rp.get("check_cpu", ""),
                     "response_cpu_after": rp.get("response_cpu", "")})
    return rows


def open_rows(out, labels):
    """Runs with the evidence gate open (--open): per photo the full and the copies' log ratio."""
    rows = []
    for pair in [x for x in labels.split(",") if x]:
        label, copies = (pair.split(":", 1) + [""])[:2]
        c = load(out, copies) if copies else {}
        for r in benchlib.read_csv(os.path.join(out, "verdicts_%s.csv" % label)):
            q = c.get(r["photo"], r) if copies else r
            if r.get("q_log") not in ("", None) and q.get("q_log") not in ("", None):
                rows.append({"photo": r["photo"], "group": group(r["photo"]), "run": pair,
                             "full_log_ratio": round(log_ratio(r["curve_res"], r["srgb_res"]), 4),
                             "copies_log_ratio": q["q_log"]})
    return rows


def disagreements(rows):
    """The copies' |log ratio| on the photos where its sign is not the full check's."""
    return [abs(float(r["copies_log_ratio"])) for r in rows
            if float(r["copies_log_ratio"]) * float(r["full_log_ratio"]) < 0]


def plot(rows, margin, path, opened=()):
    checked = [r for r in rows if r["copies_log_ratio"] not in ("", None)]
    with benchlib.figure(path, 1, 2, figsize=(12, 4.6)) as ax:
        if ax is None:
            return
        colours = {"A": "tab:blue", "B": "tab:orange", "York": "tab:green"}
        for g, colour in colours.items():
            sel = [r for r in checked if r["group"] == g]
            ax[0].scatter([float(r["full_log_ratio"]) for r in sel], [float(r["copies_log_ratio"]) for r in sel],
                          s=18, c=colour, label="half " + g if g != "York" else g)
        lim = max([0.3] + [abs(float(r[k])) for r in checked for k in ("full_log_ratio", "copies_log_ratio")
                           if math.isfinite(float(r[k]))]) * 1.05
        for g, colour in colours.items():
            sel = [r for r in opened if r["group"] == g]
            if sel:
                ax[0].scatter([float(r["full_log_ratio"]) for r in sel], [float(r["copies_log_ratio"]) for r in sel],
                              s=22, facecolors="none", edgecolors=colour, label="half %s, gate open" % g)
        ax[0].axhspan(-margin, margin, color="grey", alpha=0.2, label="margin: the full check runs")
        ax[0].axhline(0, color="k", lw=0.5)
        ax[0].axvline(0, color="k", lw=0.5)
        ax[0].set_xlim(-lim, lim)
        ax[0].set_ylim(-lim, lim)
        ax[0].set_xlabel("full check: log(curve residual / sRGB residual)")
        ax[0].set_ylabel("160 x 120 copies: log ratio")
        ax[0].set_title("a verdict differs only in the upper-left or lower-right quadrant")
        ax[0].legend(fontsize=7)
        timed = [r for r in checked if r["check_cpu_before"] not in ("", None) and r["check_cpu_after"] not in ("", None)]
        xs = range(len(timed))
        ax[1].bar([x - 0.2 for x in xs], [float(r["check_cpu_before"]) for r in timed], 0.4, label="before")
        ax[1].bar([x + 0.2 for x in xs], [float(r["check_cpu_after"]) for r in timed], 0.4, label="after")
        ax[1].set_xticks(list(xs), [r["photo"] for r in timed], rotation=90, fontsize=6)
        ax[1].set_ylabel("response check CPU s (one run)")
        ax[1].set_title("the check's cost per photo that gets a curve")
        ax[1].legend(fontsize=7)


def report(a, out):
    opt = lambda key, default: benchlib.option(a, key, default)
    margin = float(opt("--margin", "0.1"))
    rows = merged(out, opt("--base", "base"), opt("--full", "full"), opt("--product", "product"), opt("--copies", ""))
    benchlib.write_csv(os.path.join(out, "response_check_verdicts.csv"), rows)
    opened = open_rows(out, opt("--open", ""))
    if opened:
        benchlib.write_csv(os.path.join(out, "response_check_verdicts_open.csv"), opened)
    plot(rows, margin, os.path.join(out, "response_check_verdicts.png"), opened)
    for g in ("A", "B", "York"):
        sel = [r for r in rows if r["group"] == g and r["copies_log_ratio"] not in ("", None)]
        wrong = disagreements(sel)
        print(json.dumps({"group": g, "checked": len(sel), "copies_decide": sum(r["decided_by_copies"] for r in sel),
                          "sign_disagreements": len(wrong), "widest_disagreeing_copies_ratio": max(wrong or [0])}))
        sel = [r for r in opened if r["group"] == g]
        if sel:
            wrong = disagreements(sel)
            print(json.dumps({"group": g, "gate_open": len(sel), "beyond_margin": sum(
                abs(float(r["copies_log_ratio"])) > margin for r in sel), "sign_disagreements": len(wrong),
                "widest_disagreeing_copies_ratio": max(wrong or [0])}))
    missing = [r["photo"] for r in rows if not r["kept_after"]]
    if missing:
        print("not run by the product build:", ",".join(missing))
    for r in rows:
        if r["kept_after"] and r["kept_before"] != r["kept_after"]:
            print("verdict differs:", json.dumps(r))
    return 0


def main():
    a = benchlib.args(__doc__, 1)
    out = os.path.abspath(benchlib.option(a, "--out", os.path.join(HERE, "out")))
    os.makedirs(out, exist_ok=True)
    if a[0] == "run" and len(a) >= 3:
        return run(a, out)
    if a[0] == "report":
        return report(a, out)
    sys.stderr.write(__doc__.strip() + "\n")
    return 2


if __name__ == "__main__":
    sys.exit(main())
