"""What the light refinement spends on real scenes: its Ceres iterations, its direct-light
evaluations (the unit of its deterministic budget, LightRefineOptions::maxEvaluations), its wall
and CPU seconds and why it stopped, per scene. The budget is chosen from these figures.

  INLAY_SHARED_DIR=../shared /usr/bin/python3 tests/bench/bench_refine_budget.py build
      [--label NAME] [--sets example,dev,A,B,york] [--threads 2] [--out DIR] [--append] [--plot-only]

Scenes: the bundled example; the dev rooms (../shared/scenes, harness.py scene: assisted);
scenes-train half A (odd rooms: the budget is chosen on them) and half B (even rooms: reported);
two York photos with a ceiling panel outlined (P1020833, the studio_own_photo_test's panel, and
P1020839), camera and box estimated. Each is prepared once per call (`inlay-cli render --spp 1
--noise 0 --lights-json --report`, at nice -n 10); two builds are compared by calling each in
turn with --append into one DIR (alternated runs). Writes DIR/bench_refine_budget.csv (one row
per label, scene and run) and DIR/bench_refine_budget_summary.csv (per label and set: the
largest evaluations, iterations and CPU seconds, the CPU seconds per evaluation) under DIR
(default tests/bench/out), and bench_refine_budget.png (per scene, the first label's evaluations
and CPU seconds against the budget and the old 10 s limit; --plot-only redraws it). Each row also has the preparation's wall and CPU seconds (its stages' sums), for the
stage times before and after a change (alternated runs; medians from the CSV).
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

import benchlib

HERE = os.path.dirname(os.path.abspath(__file__))
# Ceiling panels outlined by hand on two York photos (640 x 480): the lights the refinement moves.
YORK_PANELS = {"P1020833": [[324, 49], [398, 47], [411, 92], [339, 93]],
               "P1020839": [[329, 132], [465, 125], [475, 135], [337, 140]]}


def york_scene(name, work):
    path = os.path.join(work, name + ".json")
    scene = {"format": "inlay-scene", "version": 1,
             "photo": os.path.join(benchlib.shared_dir(), "york", name + ".jpg"),
             "lights": [{"kind": "polygon_px", "points": YORK_PANELS[name]}]}
    json.dump(scene, open(path, "w"), indent=1)
    return path


def harness_scene(room_dir, work):
    path = os.path.join(work, os.path.basename(room_dir) + ".json")
    if not os.path.exists(path):
        harness = os.path.join(benchlib.shared_dir(), "tools", "harness.py")
        subprocess.run(["/usr/bin/python3", harness, "scene", room_dir, path], check=True, capture_output=True)
    return path


def scenes(sets, work):
    """[(set, name, scene file)] of the sets asked for."""
    out = []
    if "example" in sets:
        out.append(("example", "example", os.path.join(HERE, "..", "..", "resources", "example", "scene.json")))
    shared = benchlib.shared_dir()
    if "dev" in sets:
        sdir = os.path.join(shared, "scenes")
        for n in sorted(os.listdir(sdir)):
            if os.path.isfile(os.path.join(sdir, n, "truth.json")):
                out.append(("dev", n, harness_scene(os.path.join(sdir, n), work)))
    for h in ("A", "B"):
        if h in sets:
            tdir, _, rooms = benchlib.train_rooms_of(h)
            out += [(h, r, harness_scene(os.path.join(tdir, r), work)) for r in rooms]
    if "york" in sets:
        out += [("york", n, york_scene(n, work)) for n in sorted(YORK_PANELS)]
    return out


def run_once(cli, scene, threads, work):
    """The refinement's figures of one preparation, or None when the scene refined nothing."""
    lights, report = os.path.join(work, "lights.json"), os.path.join(work, "report.json")
    cmd = ["nice", "-n", "10", cli, "render", scene, "-o", os.path.join(work, "out.png"), "--spp", "1",
           "--noise", "0", "--quiet", "--threads", str(threads), "--lights-json", lights, "--report", report]
    subprocess.run(cmd, check=True)
    ref = json.load(open(lights))["refinement"]
    stages = {s["name"]: s for s in json.load(open(report))["stages"]}
    refine = stages.get("refine", {})
    if not ref.get("ran"):
        return None
    m = re.search(r"\((\d+) iterations\)", ref.get("report", ""))
    warnings = json.load(open(report)).get("warnings", [])
    return {"iterations": int(m.group(1)) if m else -1, "evaluations": ref["evaluations"],
            "pixels": ref["pixels"], "seconds": refine.get("seconds", ref["seconds"]),
            "cpu_seconds": refine.get("cpu_seconds", float("nan")),
            "stopped_by": ref["report"].split(".")[0].split(" (")[0],
            "time_warning": int(any("time guard" in w for w in warnings)),
            "lights": len(json.load(open(lights)).get("refined", [])),
            "prepare_seconds": sum(s.get("seconds", 0) for s in stages.values() if s.get("ran")),
            "prepare_cpu_seconds": sum(s.get("cpu_seconds", 0) for s in stages.values() if s.get("ran"))}


def summarise(rows):
    out = []
    for label in sorted({r["label"] for r in rows}):
        for s in ["example", "dev", "A", "B", "york"]:
            rs = [r for r in rows if r["label"] == label and r["set"] == s]
            if not rs:
                continue
            ev = [int(r["evaluations"]) for r in rs]
            per = [float(r["cpu_seconds"]) / max(1, int(r["evaluations"])) for r in rs]
            out.append({"label": label, "set": s, "runs": len(rs), "max_evaluations": max(ev),
                        "median_evaluations": statistics.median(ev),
                        "max_iterations": max(int(r["iterations"]) for r in rs),
                        "max_cpu_seconds": max(float(r["cpu_seconds"]) for r in rs),
                        "median_cpu_ms_per_evaluation": 1000 * statistics.median(per),
                        "max_wall_seconds": max(float(r["seconds"]) for r in rs)})
    return out


BUDGET = 2000  # LightRefineOptions::maxEvaluations


def plot(rows, path):
    """Per scene (the first label's first run): the evaluations the solve used and its CPU
    seconds, against the budget and the 10 s the wall-clock limit allowed before."""
    label = rows[0]["label"]
    first = {}
    for r in rows:
        if r["label"] == label:
            first.setdefault(r["scene"], r)
    names = list(first)
    with benchlib.figure(path, 1, 2, figsize=(12, 4.5)) as ax:
        if ax is None:
            return
        x = range(len(names))
        colours = {"example": "C0", "dev": "C1", "A": "C2", "B": "C3", "york": "C4"}
        c = [colours.get(first[n]["set"], "C7") for n in names]
        ax[0].bar(x, [int(first[n]["evaluations"]) for n in names], color=c)
        ax[0].axhline(BUDGET, color="k", ls="--", label="budget (maxEvaluations %d)" % BUDGET)
        ax[0].set_yscale("log")
        ax[0].set_ylabel("direct-light evaluations used")
        ax[0].legend(loc="center right")
        ax[1].bar(x, [float(first[n]["cpu_seconds"]) for n in names], color=c)
        ax[1].axhline(10, color="k", ls=":", label="the 10 s wall-clock limit before")
        ax[1].set_yscale("log")
        ax[1].set_ylabel("refine stage CPU seconds")
        ax[1].legend(loc="center right")
        for a in ax:
            a.set_xticks(list(x))
            a.set_xticklabels(names, rotation=70, fontsize=7)
        ax[0].set_title("colour: example, dev, half A, half B, York")


def main():
    benchlib.args(__doc__)
    opt, build, label, out, cli, path, rows = benchlib.labelled_run("bench_refine_budget.csv")
    if "--plot-only" in sys.argv:
        plot(benchlib.read_csv(path), os.path.join(out, "bench_refine_budget.png"))
        return
    work = os.path.join(out, "refine_budget_scenes")
    os.makedirs(work, exist_ok=True)
    for s, name, scene in scenes(opt("--sets", "example,dev,A,B,york").split(","), work):
        run = sum(1 for r in rows if r["label"] == label and r["scene"] == name)
        with tempfile.TemporaryDirectory() as tmp:
            r = run_once(cli, scene, opt("--threads", "2"), tmp)
        if r is None:
            print("%-8s %-22s no light refined" % (s, name), flush=True)
            continue
        r.update({"label": label, "set": s, "scene": name, "run": run})
        rows.append(r)
        print("%-8s %-22s %2d lights %3d iterations %4d evaluations %6.2f s (CPU %.2f) %s" %
              (s, name, r["lights"], r["iterations"], r["evaluations"], r["seconds"], r["cpu_seconds"],
               r["stopped_by"]), flush=True)
        benchlib.write_csv(path, rows)
    plot(rows, os.path.join(out, "bench_refine_budget.png"))
    summ = summarise(rows)
    benchlib.write_csv(os.path.join(out, "bench_refine_budget_summary.csv"), summ)
    for r in summ:
        print(r)


if __name__ == "__main__":
    main()
