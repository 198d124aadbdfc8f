"""The preparation's stages on three dev rooms and a locked copy: each stage's seconds, or why the
scene skipped it, and the time each skip saves.

  INLAY_SHARED_DIR=../shared /usr/bin/python3 tests/bench/bench_stages.py build/app/inlay-cli
      [--repeats 3] [--threads 2] [--out DIR] [--update-doc docs/architecture.md]

Scenes (../shared/tools/harness.py, assisted):
  everything      d6_behind_table: an occluder, the table (a surface), a placed light refined
  sun             d4_sun_right: a shaft (sun ratio), no area light
  no sun/occluder d1_two_lights_tiles: two outlined lights refined, nothing else marked
  lights locked   d1_two_lights_tiles with "lock": true on every light
Each is prepared --repeats times (`inlay-cli render --spp 1 --report`, one after another);
the seconds are medians. "Saved" is what a skip saves: the stage's median seconds in the scene
that runs it (occluders, surfaces: everything; shafts, sun ratio: sun; refine, lighting refit:
no sun/occluder), and the whole preparation of no sun/occluder against lights locked.
Writes bench_stages.csv (one row per scene, stage and run), bench_stages.md (the table),
bench_stages.png (stacked seconds per scene) under DIR (default tests/bench/out); with
--update-doc, the table replaces the one between the bench_stages markers of that file.
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

import benchlib

SCENES = [("everything", "d6_behind_table", False), ("sun", "d4_sun_right", False),
          ("no sun/occluder", "d1_two_lights_tiles", False), ("lights locked", "d1_two_lights_tiles", True)]
# A skipped stage -> the scene that runs it (its seconds there are what the skip saves).
SAVED_IN = {"occluders": "everything", "surfaces": "everything", "shafts": "sun", "sun ratio": "sun",
            "refine": "no sun/occluder", "lighting refit": "no sun/occluder"}


def scene_file(harness, sdir, room, locked, work):
    path = os.path.join(work, room + ("_locked" if locked else "") + ".json")
    subprocess.run([sys.executable, harness, "scene", os.path.join(sdir, room), path], check=True, capture_output=True)
    if locked:
        scene = json.load(open(path))
        for light in scene["lights"]:
            light["lock"] = True
        json.dump(scene, open(path, "w"), indent=1)
    return path


def prepare(cli, scene, threads, work):
    """One preparation's stages (the --report's list)."""
    report = os.path.join(work, "report.json")
    subprocess.run([cli, "render", scene, "-o", os.path.join(work, "out.png"), "--spp", "1", "--noise", "0",
                    "--quiet", "--threads", str(threads), "--report", report], check=True)
    return json.load(open(report))["stages"]


def summary(runs):
    """Per stage: (ran, median seconds, reason), in the stages' order."""
    out = {}
    for stage in runs[0]:
        name = stage["name"]
        secs = [s["seconds"] for r in runs for s in r if s["name"] == name and s["ran"]]
        out[name] = (stage["ran"], statistics.median(secs) if secs else 0.0, stage.get("skipped", ""))
    return out


def markdown(results, repeats, threads):
    labels = [label for label, _, _ in SCENES]
    rows = ["| stage | " + " | ".join("%s (%s)" % (l, room[:2] + (", locked" if lk else "")) for l, room, lk in SCENES) +
            " | saved by its skip |",
            "|---|" + "---|" * (len(labels) + 1)]
    for name in results[labels[0]]:
        cells = []
        for label in labels:
            ran, secs, reason = results[label][name]
            cells.append("%.2f s" % secs if ran else "skipped: " + reason)
        saved = ""
        if name in SAVED_IN:
            ran, secs, _ = results[SAVED_IN[name]][name]
            saved = "%.2f s (%s)" % (secs, SAVED_IN[name]) if ran else ""
        rows.append("| %s | %s | %s |" % (name, " | ".join(cells), saved))
    totals = {label: sum(s for _, s, _ in results[label].values()) for label in labels}
    rows.append("| **total** | " + " | ".join("**%.1f s**" % totals[l] for l in labels) + " | %.1f s (locked against no sun/occluder) |"
                % (totals["no sun/occluder"] - totals["lights locked"]))
    return ("Medians of %d preparations per scene (`inlay-cli render --spp 1 --report`, %d threads, on a "
            "shared 2-core machine: the seconds are noisy, the skips are not).\n\n" % (repeats, threads) +
            "\n".join(rows) + "\n")


def plot(results, path):
    with benchlib.figure(path, figsize=(8, 3.6)) as ax:
        if ax is None:
            return
        labels = [label for label, _, _ in SCENES]
        stages = list(results[labels[0]])
        left = [0.0] * len(labels)
        from matplotlib import colormaps
        cmap = colormaps["tab20"]
        for k, name in enumerate(stages):
            secs = [results[l][name][1] if results[l][name][0] else 0.0 for l in labels]
            if max(secs) < 0.05:
                continue
            ax.barh(labels, secs, left=left, label=name, color=cmap(k % 20))
            left = [a + b for a, b in zip(left, secs)]
        ax.set_xlabel("preparation seconds (median)")
        ax.invert_yaxis()
        ax.legend(fontsize=7, ncol=2, loc="lower right")


def update_doc(path, table):
    text = open(path).read()
    begin, end = "<!-- bench_stages begin -->", "<!-- bench_stages end -->"
    a, b = text.index(begin) + len(begin), text.index(end)
    open(path, "w").write(text[:a] + "\n" + table + text[b:])


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    repeats, threads = int(opt("--repeats", 3)), int(opt("--threads", 2))
    sdir, harness, _ = benchlib.scene_rooms("", out)
    work = tempfile.mkdtemp(prefix="bench_stages_")
    rows, results = [], {}
    for label, room, locked in SCENES:
        scene = scene_file(harness, sdir, room, locked, work)
        runs = []
        for k in range(repeats):
            runs.append(prepare(cli, scene, threads, work))
            for s in runs[-1]:
                rows.append({"scene": label, "room": room, "locked": int(locked), "run": k, "stage": s["name"],
                             "ran": int(s["ran"]), "seconds": round(s.get("seconds", 0.0), 4),
                             "skipped": s.get("skipped", ""), "detail": s.get("detail", "")})
            print("%s run %d: %.1f s" % (label, k, sum(s.get("seconds", 0.0) for s in runs[-1])), flush=True)
        results[label] = summary(runs)
    benchlib.write_csv(os.path.join(out, "bench_stages.csv"), rows)
    benchlib.write_table("stages", [{"scene": label, "stage": name, "ran": int(ran), "median_s": round(secs, 3),
                                     "skipped": reason}
                                    for label, stages in results.items() for name, (ran, secs, reason) in stages.items()],
                         source=os.path.join(out, "bench_stages.csv"))
    table = markdown(results, repeats, threads)
    open(os.path.join(out, "bench_stages.md"), "w").write(table)
    plot(results, os.path.join(out, "bench_stages.png"))
    print(table)
    doc = opt("--update-doc", "")
    if doc:
        update_doc(doc, table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
