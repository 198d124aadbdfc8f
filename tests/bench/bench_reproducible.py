"""Whether a scene's preparation gives the same lights on a slow or loaded machine: each scene is
prepared (`inlay-cli render --spp 1 --noise 0 --lights-json`) three ways and its refined lights
compared with the first's, number for number:

  idle       --threads 2, nothing else started by this script;
  loaded     --threads 1, two busy processes beside it for the whole preparation;
  slow       --threads 2, the process given about 1 / SLOWDOWN of the time (SIGSTOP / SIGCONT
             duty cycle, default 100) from its "refine" stage to its next stage: a machine that
             much slower (or that loaded) while the lights are refined.

  INLAY_SHARED_DIR=../shared /usr/bin/python3 tests/bench/bench_reproducible.py build
      [--label NAME] [--scenes example,t08,P1020839] [--slowdown 100] [--out DIR] [--append]

Before the refinement's budget (a 10 s wall-clock limit), "slow" stops the solve early and its
result differs; after it it is the same, and the preparation only takes longer. Writes
DIR/bench_reproducible.csv (one row per label, scene and way: the refinement's wall seconds, its
evaluations, why it stopped, whether a time-guard warning was given, whether its solve (final
objective and evaluations) and the lights the preparation kept (--lights-json's "refined": the
first estimate's when the refinement moved them too little to refit) equal the idle run's) under DIR (default tests/bench/out); bench_refine_budget.py makes
the scene files.
"""
import json
import multiprocessing
import os
import signal
import subprocess
import tempfile
import threading
import time

import benchlib
import bench_refine_budget as budget

HERE = os.path.dirname(os.path.abspath(__file__))


def spin(stop):
    x = 1.0
    while not stop.is_set():
        x = x * 1.0000001 + 1e-9


def throttle(pid, slowdown, stop):
    """Lets `pid` run about 1 / slowdown of the time until `stop` is set (then resumes it)."""
    run = 0.002
    try:
        while not stop.is_set():
            os.kill(pid, signal.SIGSTOP)
            time.sleep(run * (slowdown - 1))
            os.kill(pid, signal.SIGCONT)
            time.sleep(run)
    except ProcessLookupError:
        pass
    finally:
        try:
            os.kill(pid, signal.SIGCONT)
        except ProcessLookupError:
            pass


def prepare(cli, scene, way, slowdown, work):
    lights, report = os.path.join(work, "lights.json"), os.path.join(work, "report.json")
    cmd = ["nice", "-n", "10", cli, "render", scene, "-o", os.path.join(work, "out.png"), "--spp", "1",
           "--noise", "0", "--threads", "1" if way == "loaded" else "2", "--lights-json", lights,
           "--report", report]
    stop_load = multiprocessing.Event()
    load = [multiprocessing.Process(target=spin, args=(stop_load,)) for _ in range(2 if way == "loaded" else 0)]
    for p in load:
        p.start()
    proc = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True)
    stop, slow = threading.Event(), None
    try:
        for line in proc.stderr:
            stage = line.strip()
            if way == "slow" and stage == "inlay-cli: refine" and slow is None:
                slow = threading.Thread(target=throttle, args=(proc.pid, slowdown, stop))
                slow.start()
            elif slow is not None and stage.startswith("inlay-cli: ") and stage != "inlay-cli: refine":
                stop.set()
    finally:
        stop.set()
        if slow is not None:
            slow.join()
        proc.wait()
        stop_load.set()
        for p in load:
            p.join()
    if proc.returncode != 0:
        raise SystemExit("%s: inlay-cli exited %d" % (scene, proc.returncode))
    lj, rep = json.load(open(lights)), json.load(open(report))
    stages = {s["name"]: s for s in rep["stages"]}
    solve = (lj["refinement"]["final_objective"], lj["refinement"]["evaluations"])
    return {"refined": lj["refined"], "solve": solve, "evaluations": lj["refinement"]["evaluations"],
            "stopped_by": lj["refinement"]["report"], "refine_seconds": stages["refine"].get("seconds", 0),
            "time_warning": int(any("time guard" in w for w in rep.get("warnings", [])))}


def main():
    benchlib.args(__doc__)
    opt, build, label, out, cli, path, rows = benchlib.labelled_run("bench_reproducible.csv")
    work = os.path.join(out, "refine_budget_scenes")
    os.makedirs(work, exist_ok=True)
    wanted = opt("--scenes", "example,t08,P1020839").split(",")
    every = budget.scenes(["example", "dev", "A", "B", "york"] if wanted != ["example"] else ["example"], work)
    slowdown = float(opt("--slowdown", "100"))
    for s, name, scene in [x for x in every if x[1] in wanted]:
        first = first_solve = None
        for way in ["idle", "loaded", "slow"]:
            with tempfile.TemporaryDirectory() as tmp:
                r = prepare(cli, scene, way, slowdown, tmp)
            first = first or r["refined"]
            first_solve = first_solve or r["solve"]
            row = {"label": label, "scene": name, "way": way, "refine_seconds": r["refine_seconds"],
                   "evaluations": r["evaluations"], "stopped_by": r["stopped_by"],
                   "time_warning": r["time_warning"], "same_lights_as_idle": int(r["refined"] == first),
                   "same_solve_as_idle": int(r["solve"] == first_solve)}
            rows.append(row)
            print("%-8s %-10s %-7s refine %6.2f s, %4d evaluations, same solve / lights as idle: %s / %s, "
                  "time warning: %d (%s)" % (label, name, way, r["refine_seconds"], r["evaluations"],
                                              row["same_solve_as_idle"] == 1, row["same_lights_as_idle"] == 1,
                                              r["time_warning"], r["stopped_by"]), flush=True)
            benchlib.write_csv(path, rows)


if __name__ == "__main__":
    main()
