"""inlay-cli batch against the same renders run one by one, and a resumed run after a kill.

  /usr/bin/python3 tests/bench/bench_batch.py build/app/inlay-cli [--scenes d1,d3,d5]
      [--models spot.obj,teapot.obj,stanford-bunny.obj,suzanne.obj] [--spp 16] [--jobs 1]
      [--kill-after 5] [--out DIR]

Photos: ground-truth rooms made into scene files by ../shared/tools/harness.py (assisted);
models: ../shared/models, each placed where the room's object stands, 0.5 m high, diffuse.
One render per (photo, model), all at --spp samples per pixel with no noise target (the same
work in every run). Three runs, one after another:
  one-by-one  `inlay-cli render` of a scene file per line (each prepares its room again)
  batch       `inlay-cli batch` of the manifest (each room prepared once)
  resumed     batch killed (SIGKILL) once --kill-after outputs exist, then run again: the
              second run renders only the missing lines
Writes bench_batch.csv (one row per run: wall seconds, renders done, preparations) and
bench_batch.png (wall time per run) under DIR (default tests/bench/out).
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import benchlib


def make_scenes(harness, sdir, rooms, work):
    scenes = {}
    for room in rooms:
        path = os.path.join(work, room + ".json")
        subprocess.run([sys.executable, harness, "scene", os.path.join(sdir, room), path],
                       check=True, capture_output=True)
        scenes[room] = path
    return scenes


def manifest_lines(scenes, models, out_dir):
    lines = []
    for room, scene in scenes.items():
        for model in models:
            name = os.path.splitext(os.path.basename(model))[0]
            lines.append({"scene": scene, "output": os.path.join(out_dir, f"{room}_{name}.png"),
                          "objects": [{"mesh": model, "height_m": 0.5,
                                       "material": {"preset": "diffuse", "albedo": [0.7, 0.6, 0.5]}}]})
    return lines


def write_manifest(path, lines):
    with open(path, "w") as f:
        for line in lines:
            f.write(json.dumps(line) + "\n")


def one_by_one(cli, lines, work, render_args):
    """Each line as its own scene file and `inlay-cli render` (what a script without batch does)."""
    start = time.monotonic()
    for i, line in enumerate(lines):
        with open(line["scene"]) as f:
            scene = json.load(f)
        scene["objects"][0].update(line["objects"][0])
        path = os.path.join(work, f"single_{i}.json")
        with open(path, "w") as f:
            json.dump(scene, f)
        subprocess.run([cli, "render", path, "-o", line["output"], "--quiet"] + render_args,
                       check=True)
    return time.monotonic() - start


def batch(cli, manifest, render_args, jobs):
    start = time.monotonic()
    r = subprocess.run([cli, "batch", manifest, "--jobs", str(jobs)] + render_args,
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("bench_batch: batch failed:\n" + r.stderr)
    return time.monotonic() - start, r.stderr


def killed_batch(cli, manifest, render_args, jobs, outputs, kill_after):
    """Starts batch, SIGKILLs it once `kill_after` outputs exist; returns (seconds, done)."""
    start = time.monotonic()
    p = subprocess.Popen([cli, "batch", manifest, "--jobs", str(jobs), "--quiet"] + render_args,
                         stderr=subprocess.DEVNULL)
    while p.poll() is None and sum(os.path.exists(o) for o in outputs) < kill_after:
        time.sleep(0.2)
    p.send_signal(signal.SIGKILL)
    p.wait()
    return time.monotonic() - start, sum(os.path.exists(o) for o in outputs)


def count(stderr, word):
    return stderr.count(word)


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    sdir, harness, rooms = benchlib.scene_rooms(opt("--scenes", "d1,d3,d5"), out)
    models_dir = os.path.join(benchlib.shared_dir(), "models")
    models = [os.path.join(models_dir, m) for m in
              opt("--models", "spot.obj,teapot.obj,stanford-bunny.obj,suzanne.obj").split(",")]
    render_args = ["--spp", opt("--spp", "16"), "--noise", "0", "--seconds", "0", "--seed", "1"]
    jobs = int(opt("--jobs", "1"))
    work = os.path.join(out, "batch_work")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scenes = make_scenes(harness, sdir, rooms, work)
    rows = []

    single_lines = manifest_lines(scenes, models, os.path.join(work, "single"))
    os.makedirs(os.path.join(work, "single"))
    seconds = one_by_one(cli, single_lines, work, render_args)
    rows.append({"run": "one-by-one", "seconds": round(seconds, 1), "renders": len(single_lines),
                 "preparations": len(single_lines)})
    print(rows[-1], flush=True)

    lines = manifest_lines(scenes, models, os.path.join(work, "batch"))
    manifest = os.path.join(work, "manifest.jsonl")
    write_manifest(manifest, lines)
    seconds, stderr = batch(cli, manifest, render_args, jobs)
    rows.append({"run": "batch", "seconds": round(seconds, 1), "renders": len(lines),
                 "preparations": count(stderr, "prepared ")})
    print(rows[-1], flush=True)

    lines = manifest_lines(scenes, models, os.path.join(work, "resumed"))
    write_manifest(manifest, lines)
    outputs = [l["output"] for l in lines]
    seconds, done = killed_batch(cli, manifest, render_args, jobs, outputs,
                                 int(opt("--kill-after", "5")))
    rows.append({"run": "batch, killed", "seconds": round(seconds, 1), "renders": done,
                 "preparations": ""})
    print(rows[-1], flush=True)
    seconds, stderr = batch(cli, manifest, render_args, jobs)
    rendered = int(stderr.split(" rendered")[0].rsplit(" ", 1)[-1]) if " rendered" in stderr else -1
    rows.append({"run": "batch, resumed", "seconds": round(seconds, 1), "renders": rendered,
                 "preparations": count(stderr, "prepared ")})
    print(rows[-1], flush=True)

    benchlib.write_csv(os.path.join(out, "bench_batch.csv"), rows, table="batch")
    with benchlib.figure(os.path.join(out, "bench_batch.png"), figsize=(6, 3)) as ax:
        if ax is not None:
            ax.barh([r["run"] for r in rows], [r["seconds"] for r in rows], color="#4a7fb0")
            for i, r in enumerate(rows):
                ax.text(r["seconds"], i, f" {r['renders']} renders", va="center", fontsize=8)
            ax.invert_yaxis()
            ax.set_xlabel("wall seconds")
            ax.set_title(f"{len(scenes)} photos x {len(models)} models, {render_args[1]} spp")
    print("wrote", os.path.join(out, "bench_batch.csv"))


if __name__ == "__main__":
    main()
