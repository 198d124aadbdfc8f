#!/usr/bin/python3
"""A clipped sun's strength against the truth as its patch clips more (the dev sun room d4).

usage: bench_sun_bounce.py CLI [CLI ...] [--labels a,b] [--out DIR] [--room DIR]
                           [--gains 1,1.5,2,3,4]

For each gain, the room (default ../shared/scenes/d4_sun_right) re-photographed G times brighter
(sun_exposure_variants.py: its plain sRGB encoding of the linear renders times G, so the sunlit
patch clips more), its assisted scene (harness.py scene), and per CLI one preparation
(`inlay-cli render --spp 1 --lights-json`): the refined sun's strength over the truth's (in the
photo's units: truth.json's exposure scale times G), by luminance and per channel, and the
warnings about the sun. Writes OUT/sun_bounce.csv and OUT/sun_bounce.png (ratio against gain per
CLI); prints the table. A CLI may carry options after it, in one argument: the bounce fit is off by
default, so `"build/app/inlay-cli --suns-from-bounce"` measures it against `build/app/inlay-cli`.
"""
import json, os, shlex, subprocess, sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402

PY = "/usr/bin/python3"
LUMA = np.array([0.2126, 0.7152, 0.0722])


def variant(room, out, gain):
    """The room at `gain`, with its assisted scene: (folder, scene file)."""
    vdir = os.path.join(out, "variants", "%s_g%s" % (os.path.basename(room), gain))
    scene = vdir + ".json"
    if not os.path.exists(scene):
        subprocess.run([PY, os.path.join(HERE, "sun_exposure_variants.py"), room, vdir, "--gain", str(gain)],
                       check=True, capture_output=True)
        subprocess.run([PY, os.path.join(benchlib.shared_dir(), "tools", "harness.py"), "scene", vdir, scene],
                       check=True, capture_output=True)
    return vdir, scene


def measure(cli, label, room, scene, gain, out):
    """One row: the CLI's refined sun against the truth at `gain`."""
    tag = "%s_g%s" % (label, gain)
    lj, report = os.path.join(out, tag + "_lights.json"), os.path.join(out, tag + "_report.json")
    command, options = shlex.split(cli)[0], shlex.split(cli)[1:]
    p = subprocess.run([command, "render", scene, "-o", os.path.join(out, tag + ".png"), "--spp", "1", "--seconds",
                        "0", "--noise", "0", "--quiet", "--lights-json", lj, "--report", report] + options,
                       capture_output=True, text=True)
    row = {"label": label, "gain": gain}
    if p.returncode != 0:
        row["error"] = p.stderr.strip()[-200:]
        return row
    truth = json.load(open(os.path.join(room, "truth.json")))
    sun = truth["sun"]
    true = np.array(sun["color"], float) * sun["strength_W_m2"] / np.pi * truth["exposure"]["scale"] * gain
    ours = np.array(json.load(open(lj))["suns_refined"][0]["rgb"], float)
    row["sun_ratio"] = round(float(ours @ LUMA / (true @ LUMA)), 3)
    for c, name in enumerate("rgb"):
        row["ratio_" + name] = round(float(ours[c] / true[c]), 3)
    row["warnings"] = " | ".join(w for w in json.load(open(report)).get("warnings", []) if w.startswith("sun "))
    return row


def main():
    a = benchlib.args(__doc__)
    opt = lambda key, default: benchlib.option(a, key, default)
    clis = [os.path.abspath(x) for x in a if not x.startswith("--") and os.access(x, os.X_OK) and os.path.isfile(x)]
    labels = opt("--labels", ",".join("cli%d" % k for k in range(len(clis)))).split(",")
    out = os.path.abspath(opt("--out", os.path.join(HERE, "out", "sun_bounce")))
    room = opt("--room", os.path.join(benchlib.shared_dir(), "scenes", "d4_sun_right"))
    gains = [float(g) for g in opt("--gains", "1,1.5,2,3,4").split(",")]
    os.makedirs(out, exist_ok=True)
    rows = []
    for gain in gains:
        vdir, scene = variant(room, out, gain)
        for cli, label in zip(clis, labels):
            rows.append(measure(cli, label, room, scene, gain, out))
            print(json.dumps(rows[-1]))
    benchlib.write_csv(os.path.join(out, "sun_bounce.csv"), rows)
    print("| gain | " + " | ".join(labels) + " |\n|---|" + "---|" * len(labels))
    for gain in gains:
        cells = [str(r.get("sun_ratio", "error")) for lab in labels for r in rows if r["gain"] == gain and r["label"] == lab]
        print("| %g | %s |" % (gain, " | ".join(cells)))
    with benchlib.figure(os.path.join(out, "sun_bounce.png"), figsize=(5.5, 3.6)) as ax:
        if ax is not None:
            for lab in labels:
                pts = [(r["gain"], r["sun_ratio"]) for r in rows if r["label"] == lab and "sun_ratio" in r]
                ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=lab)
            ax.axhline(1.0, color="grey", lw=0.8)
            ax.set_xlabel("exposure gain (the sunlit patch clips more)")
            ax.set_ylabel("sun strength / truth (luminance)")
            ax.set_title(os.path.basename(room))
            ax.legend()
    return 0


if __name__ == "__main__":
    sys.exit(main())
