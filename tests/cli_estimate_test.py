#!/usr/bin/python3
"""inlay-cli estimate on the bundled example photo: the output's keys (../shared/spec/cli.md),
finite numbers, what each vanishing point rests on, the fitted box against the example's own
marked back wall, and bad input (exit 2, file named, nothing written). Needs nothing from
../shared.

usage: cli_estimate_test.py INLAY_CLI
"""
import json, math, os, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "resources", "example")
from checks import check, summary  # noqa: E402


def finite(x):
    if isinstance(x, list):
        return all(finite(v) for v in x)
    return isinstance(x, (int, float)) and math.isfinite(x)


def main():
    cli = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="inlay_estimate_")
    photo = os.path.join(EXAMPLE, "photo.png")
    out = os.path.join(tmp, "camera.json")
    p = subprocess.run([cli, "estimate", photo, "-o", out, "--quiet"], capture_output=True, text=True, timeout=300)
    check("exit 0", p.returncode == 0, p.stderr)
    e = json.load(open(out))
    for k in ("camera", "layout", "rotation", "confidence", "focal_interval_px", "warnings", "timings_ms",
              "vanishing_point_support", "principal_sigma_px", "principal_from_prior"):
        check("key " + k, k in e)
    cam = e["camera"]
    check("focal finite", finite(cam["focal_px"]) and cam["focal_px"] > 0)
    check("focal in its interval", e["focal_interval_px"][0] <= cam["focal_px"] <= e["focal_interval_px"][1],
          str(e["focal_interval_px"]))
    check("vanishing points finite", finite(cam["vanishing_points_px"]))
    check("rotation finite", finite(e["rotation"]))
    check("principal sigma finite, >= 0", finite(e["principal_sigma_px"]) and min(e["principal_sigma_px"]) >= 0,
          str(e["principal_sigma_px"]))
    sup = e["vanishing_point_support"]
    check("three supports", len(sup) == 3)
    for k, v in enumerate(sup):
        check("support %d finite" % k, finite([v["support_length_px"], v["rms_residual_px"], v["angular_sigma_deg"],
                                               v["confidence"]] + v["homogeneous_px"]), str(v))
        check("support %d confidence matches" % k, abs(v["confidence"] - e["confidence"]["vanishing_points"][k]) < 1e-12)
    # The example room's floor tiles run along x and z; its two back-wall corners are vertical.
    n = [v["segments"] for v in sup]
    check("every axis supported", n[0] >= 10 and n[1] >= 1 and n[2] >= 10, str(n))
    check("manhattan", e["confidence"]["manhattan"] is True)
    # Its scene file marks the back wall: the estimate lands within a few pixels of it.
    marked = json.load(open(os.path.join(EXAMPLE, "scene.json")))["layout"]["back_wall_px"]
    worst = max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(marked, e["layout"]["back_wall_px"]))
    check("back wall near the marked one", worst < 6.0, "worst corner %.1f px" % worst)

    # Bad input: a corrupt photo is named, exit 2, the output left alone.
    bad = os.path.join(tmp, "bad.png")
    open(bad, "wb").write(b"\x89PNG\r\n\x1a\nnot really")
    keep = os.path.join(tmp, "keep.json")
    open(keep, "w").write("{}")
    p = subprocess.run([cli, "estimate", bad, "-o", keep, "--quiet"], capture_output=True, text=True, timeout=60)
    check("corrupt photo exit 2", p.returncode == 2, str(p.returncode))
    check("corrupt photo named", "bad.png" in p.stderr, p.stderr)
    check("output untouched", open(keep).read() == "{}")
    p = subprocess.run([cli, "estimate", photo, "--quiet"], capture_output=True, text=True, timeout=60)
    check("missing -o exit 2", p.returncode == 2, p.stderr)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
