#!/usr/bin/python3
"""inlay-cli lists the preparation's stages: --verbose on stderr and --report FILE as JSON, each
stage with its seconds or the reason this scene skipped it (and --lights-json's "stages").

- The bundled example (two outlined lights, one object; no occluder, surface or shaft): the
  refinement runs; occluders, surfaces, shafts and the sun ratio are skipped with their reasons.
- Its copy with every light locked: the refinement and its refit are skipped ("every light
  locked"), and --lights-json says the refinement did not run.
- A report that cannot be written: exit 2 naming the file.
Needs nothing from ../shared.

usage: cli_stages_test.py INLAY_CLI
"""
import json, os, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
STAGES = ["photo", "response", "working copy", "camera", "layout", "occluders", "surfaces", "room", "lights",
          "shafts", "lighting", "vignetting", "sun ratio", "refine", "lighting refit", "photo size", "render scene", "objects",
          "grain"]


def render(cli, scene, out, name):
    report, lights = os.path.join(out, name + "_report.json"), os.path.join(out, name + "_lights.json")
    p = subprocess.run([cli, "render", scene, "-o", os.path.join(out, name + ".png"), "--spp", "1", "--quiet",
                        "--verbose", "--report", report, "--lights-json", lights],
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        raise SystemExit("%s: inlay-cli exited %d: %s" % (name, p.returncode, p.stderr.strip()[-400:]))
    lines = [l[len("inlay-cli: stage "):] for l in p.stderr.splitlines() if l.startswith("inlay-cli: stage ")]
    return lines, json.load(open(report)), json.load(open(lights))


def check(name, lines, report, lights, ran, skipped, failures):
    """`ran`: stages that must have run; `skipped`: stage -> its reason."""
    stages = report["stages"]
    if [s["name"] for s in stages] != STAGES:
        failures.append("%s: report stages %s" % (name, [s["name"] for s in stages]))
    if len(lines) != len(STAGES):
        failures.append("%s: --verbose printed %d stage lines, not %d: %s" % (name, len(lines), len(STAGES), lines))
    if lights["stages"] != stages:
        failures.append("%s: --lights-json's stages differ from --report's" % name)
    by_name = {s["name"]: s for s in stages}
    for s in ran:
        if not by_name[s]["ran"] or not by_name[s]["seconds"] >= 0:
            failures.append("%s: stage %s did not run: %s" % (name, s, by_name[s]))
        elif not any(l.startswith(s + ": ") and " s" in l for l in lines):
            failures.append("%s: --verbose has no time for %s" % (name, s))
    for s, reason in skipped.items():
        if by_name[s]["ran"] or by_name[s].get("skipped") != reason:
            failures.append("%s: stage %s: %s, expected skipped (%s)" % (name, s, by_name[s], reason))
        if "%s: skipped, %s" % (s, reason) not in lines:
            failures.append("%s: --verbose lacks '%s: skipped, %s'" % (name, s, reason))
    for s in stages:  # the lighting stages' steps: named, timed, inside the stage's own seconds
        if s["name"] in ("lighting", "lighting refit") and s["ran"]:
            steps = s.get("steps", [])
            if not steps or any(not (t["name"] and t["seconds"] >= 0 and t["cpu_seconds"] >= 0) for t in steps):
                failures.append("%s: stage %s has no or bad steps: %s" % (name, s["name"], steps))
            elif sum(t["cpu_seconds"] for t in steps) > s["cpu_seconds"] + 1e-9:
                failures.append("%s: stage %s: its steps' CPU seconds exceed its own" % (name, s["name"]))
            elif not any(l.startswith(s["name"] + ": ") and "; CPU s: surfaces " in l for l in lines):
                failures.append("%s: --verbose does not list the steps of %s" % (name, s["name"]))
    ran_names = [s["name"] for s in stages if s["ran"]]
    if [n for n, _ in lights["stage_seconds"]] != ran_names:
        failures.append("%s: stage_seconds %s" % (name, lights["stage_seconds"]))
    total = sum(s.get("seconds", 0) for s in stages)
    if abs(report["seconds"] - total) > 1e-9:
        failures.append("%s: report seconds %.6f is not the stages' sum %.6f" % (name, report["seconds"], total))


def main():
    cli = os.path.abspath(sys.argv[1])
    example = os.path.join(HERE, "..", "resources", "example", "scene.json")
    out = tempfile.mkdtemp(prefix="inlay_stages_")
    failures = []
    not_marked = {"occluders": "none marked", "surfaces": "none marked", "shafts": "no sun marked",
                  "vignetting": 'camera.vignetting is "none" (the default)',
                  "sun ratio": "no sun marked", "photo size": "the working copy is the photo"}
    lines, report, lights = render(cli, example, out, "example")
    check("example", lines, report, lights, ["photo", "camera", "lighting", "refine", "objects"], not_marked, failures)
    if not lights["refinement"]["ran"]:
        failures.append("example: the refinement did not run")

    scene = json.load(open(example))
    scene["photo"] = os.path.abspath(os.path.join(os.path.dirname(example), scene["photo"]))
    for light in scene["lights"]:
        light["lock"] = True
    locked = os.path.join(out, "locked.json")
    json.dump(scene, open(locked, "w"))
    lines, report, lights = render(cli, locked, out, "locked")
    skipped = dict(not_marked, **{"refine": "every light locked", "lighting refit": "the lights were not refined"})
    check("locked", lines, report, lights, ["photo", "lighting", "objects"], skipped, failures)
    if lights["refinement"]["ran"]:
        failures.append("locked: --lights-json says the refinement ran")
    if lights["refined"] != lights["initial"]:
        failures.append("locked: the lights changed without a refinement")

    bad = os.path.join(out, "no_such_folder", "report.json")
    p = subprocess.run([cli, "render", example, "-o", os.path.join(out, "bad.png"), "--spp", "1", "--quiet",
                        "--report", bad], capture_output=True, text=True, timeout=600)
    if p.returncode != 2 or bad not in p.stderr:
        failures.append("an unwritable report: exit %d, %r" % (p.returncode, p.stderr.strip()))

    for f in failures:
        print("FAIL", f)
    print("%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
