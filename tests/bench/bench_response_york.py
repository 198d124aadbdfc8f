#!/usr/bin/python3
"""Are the estimated camera responses of real photos plausible? (../shared/york: no true curve.)

`inlay-cli response PHOTO -o R.json` on every York photo, for each build given. Per photo and
build: the curve's family and parameters, the decision, the fit's CPU seconds, and two numbers
that say how far the curve is from sRGB where it matters to the light fit:
  mid_vs_srgb    the curve's decode of code 128 over sRGB's (both decode 255 to 1): below 1 the
                 photo's mid-tones are read darker relative to its highlights
  stops_128_254  log2(decode(254) / decode(128)): the dynamic range the top half of the codes
                 spans (sRGB 2.2 stops; a long shoulder tens of stops)
A curve is flagged implausible when stops_128_254 exceeds --max-stops (default 6: about 64 times
the radiance in the top half of the codes; a real camera's shoulder compresses about two to
three stops there) or mid_vs_srgb lies outside [1/4, 4].

Writes OUT/response_york.csv, OUT/response_york.png (every estimated curve per build, sRGB
dashed; and stops_128_254 per photo) and prints the counts.

usage: bench_response_york.py INLAY_CLI[,LABEL[,ARGS]] [INLAY_CLI2[,LABEL2[,ARGS2]] ...] [--out DIR]
                              [--york DIR] [--max-stops 6] [--photos P1030004,P1040814]
ARGS: extra `inlay-cli response` arguments joined by '+' (e.g. --cue+noise-colour+--edge-weight+10),
so one build can be run with several settings.
"""
import glob, json, math, os, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

SRGB_128 = ((128 / 255 + 0.055) / 1.055) ** 2.4


def one(cli, photo, out_json, extra=()):
    """The response of one photo as `inlay-cli response` writes it (None when it failed)."""
    if os.path.exists(out_json):
        os.remove(out_json)
    r = subprocess.run([cli, "response", photo, "-o", out_json, "--quiet"] + list(extra), capture_output=True,
                       text=True, timeout=300)
    if r.returncode != 0 or not os.path.exists(out_json):
        return None, r.stderr.strip()[-200:]
    return json.load(open(out_json)), ""


def row_of(label, photo, j, err, max_stops):
    row = {"build": label, "photo": os.path.basename(photo)}
    if j is None:
        row["error"] = err
        return row
    t = np.array(j["table"], float)
    t = t.mean(axis=1) if t.ndim == 2 else t
    p = j.get("parameters", {})
    est = j.get("estimate", {})
    row.update({"family": j.get("family", ""), "power": p.get("power", ""), "toe": p.get("toe", ""),
                "shoulder": p.get("shoulder", ""), "mid_vs_srgb": round(float(t[128] / SRGB_128), 4),
                "stops_128_254": round(math.log2(max(t[254], 1e-30) / max(t[128], 1e-30)), 3),
                "finite_monotone": bool(np.all(np.isfinite(t)) and np.all(np.diff(t) > 0)),
                "decision": est.get("decision", j.get("source", ""))[:120],
                "cpu_s": est.get("cpu_seconds", ""), "warnings": len(j.get("warnings", []))})
    row["plausible"] = (row["finite_monotone"] and row["stops_128_254"] <= max_stops
                        and 0.25 <= row["mid_vs_srgb"] <= 4)
    row["table"] = t
    return row


def plot(path, rows, labels):
    with benchlib.figure(path, 1, 2, figsize=(13, 5)) as ax:
        if ax is None:
            return
        codes = np.arange(256)
        ax[0].plot(codes, [((c / 255 + 0.055) / 1.055) ** 2.4 if c > 10 else c / 255 / 12.92 for c in codes], "k--",
                   label="sRGB")
        for i, label in enumerate(labels):
            for r in rows:
                if r["build"] == label and "table" in r and r["family"] != "srgb":
                    ax[0].plot(codes, r["table"], color="C%d" % i, alpha=0.6, lw=1)
            ax[0].plot([], [], color="C%d" % i, label=label + " (curves other than sRGB)")
            sel = [r for r in rows if r["build"] == label and "stops_128_254" in r]
            ax[1].plot(range(len(sel)), [r["stops_128_254"] for r in sel], "o", color="C%d" % i, label=label)
        ax[0].set(xlabel="code", ylabel="linear radiance", title="York: estimated curves", yscale="log", ylim=(1e-4, 1.1))
        ax[0].legend(fontsize=7)
        ax[1].axhline(math.log2(1 / SRGB_128), ls="--", color="grey")
        ax[1].set(xlabel="photo (sorted by name)", ylabel="stops between codes 128 and 254",
                  title="York: range of the top half of the codes (sRGB dashed)")
        ax[1].legend(fontsize=7)


def main():
    argv = benchlib.args(__doc__)
    opt = lambda k, d: benchlib.option(argv, k, d)
    out = os.path.abspath(opt("--out", os.path.join(HERE, "out")))
    york = opt("--york", os.path.join(benchlib.shared_dir(), "york"))
    if not os.path.isdir(york):
        print("skipped: no", york)
        return 0
    os.makedirs(out, exist_ok=True)
    builds = []
    for a in argv:
        if a.startswith("--"):
            break
        cli, _, rest = a.partition(",")
        label, _, extra = rest.partition(",")
        builds.append((os.path.abspath(cli), label or os.path.basename(os.path.dirname(os.path.abspath(cli))),
                       extra.split("+") if extra else []))
    photos = sorted(glob.glob(os.path.join(york, "*.jpg")))
    only = opt("--photos", "")
    if only:
        photos = [p for p in photos if any(os.path.basename(p).startswith(o) for o in only.split(","))]
    max_stops = float(opt("--max-stops", "6"))
    rows = []
    for cli, label, extra in builds:
        for p in photos:
            j, err = one(cli, p, os.path.join(out, "york_response.json"), extra)
            rows.append(row_of(label, p, j, err, max_stops))
            print(json.dumps({k: v for k, v in rows[-1].items() if k != "table"}), flush=True)
    benchlib.write_csv(os.path.join(out, "response_york.csv"), [{k: v for k, v in r.items() if k != "table"}
                                                               for r in rows])
    plot(os.path.join(out, "response_york.png"), rows, [b[1] for b in builds])
    for _, label, _ in builds:
        sel = [r for r in rows if r["build"] == label]
        fitted = [r for r in sel if r.get("family") == "toe_shoulder"]
        cpu = sorted(r["cpu_s"] for r in sel if isinstance(r.get("cpu_s"), float))
        print("%s: %d photos, %d given a curve other than sRGB, %d implausible (%s), %d failed; fit CPU s median %s max %s"
              % (label, len(sel), len(fitted), sum(1 for r in sel if r.get("plausible") is False),
                 ",".join(r["photo"] for r in sel if r.get("plausible") is False), sum(1 for r in sel if "error" in r),
                 cpu[len(cpu) // 2] if cpu else "-", cpu[-1] if cpu else "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
