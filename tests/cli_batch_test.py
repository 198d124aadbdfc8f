"""inlay-cli batch: one render per manifest line, each scene prepared once.

    python3 cli_batch_test.py path/to/inlay-cli

On the bundled example (no ../shared needed), with builtin meshes:
- a line's composite is bit for bit what `inlay-cli render` gives for the scene file with the
  same objects (so the shared preparation changes nothing), and --jobs 1 and --jobs 2 agree;
- a bad line fails alone: exit 2, the line listed, the other outputs written, no file for it;
- resumable: an existing output is skipped; a scene whose outputs all exist is not prepared;
- Ctrl-C stops it with exit 1 and no partial file;
- bad manifests (not JSON, an unknown key, two lines writing one file, a bad --shard) exit 2
  with one line naming the manifest line and key; --shard splits by scene.
"""
import json
import os
import signal
import subprocess
import sys
import tempfile

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, summary  # noqa: E402

CLI = os.path.abspath(sys.argv[1])
SOURCE = os.environ.get("INLAY_SOURCE_DIR",
                        os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(SOURCE, "resources", "example", "scene.json")
RENDER = ["--spp", "4", "--noise", "0", "--seed", "3"]

CUBE = {"mesh": "builtin:cube", "material": {"preset": "glossy", "albedo": [0.2, 0.4, 0.8],
                                             "roughness": 0.3}}
MOVED = {"base_px": [300, 330], "height_m": 0.4}


def run(args, cwd):
    return subprocess.run([CLI] + args, cwd=cwd, capture_output=True, text=True, timeout=900)


def write_manifest(path, lines):
    with open(path, "w") as f:
        for line in lines:
            f.write((line if isinstance(line, str) else json.dumps(line)) + "\n")


def same_pixels(a, b):
    ia, ib = cv2.imread(a, cv2.IMREAD_UNCHANGED), cv2.imread(b, cv2.IMREAD_UNCHANGED)
    return ia is not None and ib is not None and ia.shape == ib.shape and np.array_equal(ia, ib)


def scene_with_object(tmp, override):
    """The example's scene file with its object merged with `override` (what a line asks)."""
    with open(EXAMPLE) as f:
        scene = json.load(f)
    scene["objects"][0].update(override)
    scene["photo"] = os.path.join(os.path.dirname(EXAMPLE), scene["photo"])
    path = os.path.join(tmp, "cube_scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def check_batch_and_equivalence(tmp):
    manifest = os.path.join(tmp, "m.jsonl")
    write_manifest(manifest, [
        {"scene": EXAMPLE, "output": "out/cube.png", "objects": [CUBE]},
        {"scene": EXAMPLE, "output": "out/moved.png", "objects": [MOVED]},
        "",
        {"scene": EXAMPLE, "output": "out/bad.png", "objects": [{"height_m": -1}]},
    ])
    r = run(["batch", manifest, "--jobs", "2"] + RENDER, tmp)
    out = os.path.join(tmp, "out")
    check("a bad line: exit 2", r.returncode == 2, "exit %d: %s" % (r.returncode, r.stderr))
    check("the bad line is listed with its key", "line 4 failed" in r.stderr and
          "objects[0].height_m" in r.stderr and "failed lines of" in r.stderr, r.stderr)
    check("the good lines are written", os.path.isfile(os.path.join(out, "cube.png")) and
          os.path.isfile(os.path.join(out, "moved.png")), str(os.listdir(tmp)))
    check("no file for the bad line", not os.path.exists(os.path.join(out, "bad.png")))
    check("one preparation for the scene", r.stderr.count("prepared ") == 1, r.stderr)

    # The same as `inlay-cli render` of a scene file holding that object.
    single = os.path.join(tmp, "single.png")
    r = run(["render", scene_with_object(tmp, CUBE), "-o", single, "--quiet"] + RENDER, tmp)
    check("render of the equivalent scene", r.returncode == 0, r.stderr)
    check("batch line == render, bit for bit", same_pixels(single, os.path.join(out, "cube.png")))

    # --jobs 1 gives the same files.
    manifest1 = os.path.join(tmp, "m1.jsonl")
    write_manifest(manifest1, [
        {"scene": EXAMPLE, "output": "out1/cube.png", "objects": [CUBE]},
        {"scene": EXAMPLE, "output": "out1/moved.png", "objects": [MOVED]},
    ])
    r = run(["batch", manifest1, "--jobs", "1", "--quiet"] + RENDER, tmp)
    check("--jobs 1: exit 0", r.returncode == 0, r.stderr)
    for name in ("cube.png", "moved.png"):
        check("--jobs 1 == --jobs 2: " + name,
              same_pixels(os.path.join(tmp, "out1", name), os.path.join(out, name)))
    return manifest1


def check_resume(tmp, manifest1):
    out1 = os.path.join(tmp, "out1")
    kept = os.path.join(out1, "cube.png")
    before = os.stat(kept).st_mtime_ns
    os.remove(os.path.join(out1, "moved.png"))
    r = run(["batch", manifest1] + RENDER, tmp)
    check("resume: exit 0", r.returncode == 0, r.stderr)
    check("resume: only the missing line rendered", "1 rendered, 1 already there" in r.stderr,
          r.stderr)
    check("resume: the existing output untouched", os.stat(kept).st_mtime_ns == before)
    r = run(["batch", manifest1] + RENDER, tmp)
    check("all done: exit 0, nothing prepared", r.returncode == 0 and "prepared" not in r.stderr
          and "0 rendered, 2 already there" in r.stderr, r.stderr)


def check_bad_manifests(tmp):
    cases = {
        "not JSON": (["{scene"], "m.jsonl:1"),
        "unknown key": ([{"scene": EXAMPLE, "output": "x.png", "mesh": "a.obj"}], "mesh"),
        "no output": ([{"scene": EXAMPLE}], "output"),
        "one output twice": ([{"scene": EXAMPLE, "output": "x.png"},
                              {"scene": EXAMPLE, "output": "x.png"}], "the same file as line 1"),
        "objects not a list": ([{"scene": EXAMPLE, "output": "x.png", "objects": {}}], "objects"),
    }
    for name, (lines, expected) in cases.items():
        manifest = os.path.join(tmp, "m.jsonl")
        write_manifest(manifest, lines)
        r = run(["batch", manifest], tmp)
        check("bad manifest (%s): exit 2 naming %s" % (name, expected),
              r.returncode == 2 and expected in r.stderr and r.stderr.count("\n") <= 2,
              "exit %d: %s" % (r.returncode, r.stderr))
    r = run(["batch", os.path.join(tmp, "missing.jsonl")], tmp)
    check("missing manifest: exit 2", r.returncode == 2 and "missing.jsonl" in r.stderr, r.stderr)
    for bad in ("2/2", "1", "a/3", "-1/2"):
        r = run(["batch", os.path.join(tmp, "m.jsonl"), "--shard", bad], tmp)
        check("--shard %s refused" % bad, r.returncode == 2 and "--shard" in r.stderr, r.stderr)


def check_shards(tmp):
    """Two scenes, two shards: each shard renders only its scene's lines."""
    other = os.path.join(tmp, "other")
    os.makedirs(other)
    with open(EXAMPLE) as f:
        scene = json.load(f)
    scene["photo"] = os.path.join(os.path.dirname(EXAMPLE), scene["photo"])
    with open(os.path.join(other, "scene.json"), "w") as f:
        json.dump(scene, f)
    manifest = os.path.join(tmp, "shards.jsonl")
    write_manifest(manifest, [
        {"scene": EXAMPLE, "output": "s/a.png", "objects": [CUBE]},
        {"scene": "other/scene.json", "output": "s/b.png"},
        {"scene": EXAMPLE, "output": "s/c.png", "objects": [MOVED]},
    ])
    r = run(["batch", manifest, "--shard", "1/2"] + RENDER, tmp)
    written = sorted(os.listdir(os.path.join(tmp, "s"))) if os.path.isdir(os.path.join(tmp, "s")) else []
    check("--shard 1/2 renders the second scene's line only", r.returncode == 0 and
          written == ["b.png"], "%s %s" % (written, r.stderr))


def check_interrupt(tmp):
    """Ctrl-C while a line renders: exit 1, no file (whole or partial) for the unfinished lines."""
    manifest = os.path.join(tmp, "int.jsonl")
    write_manifest(manifest, [{"scene": EXAMPLE, "output": "int/a.png", "objects": [CUBE]},
                              {"scene": EXAMPLE, "output": "int/b.png", "objects": [MOVED]}])
    p = subprocess.Popen([CLI, "batch", manifest, "--spp", "100000", "--noise", "0"], cwd=tmp,
                         stderr=subprocess.PIPE, text=True)
    for line in p.stderr:   # the scene is prepared: the first line is rendering
        if "prepared " in line:
            break
    p.send_signal(signal.SIGINT)
    try:
        rest = p.communicate(timeout=60)[1]
    except subprocess.TimeoutExpired:
        p.kill()
        rest = p.communicate()[1]
    out = os.path.join(tmp, "int")
    left = os.listdir(out) if os.path.isdir(out) else []
    check("Ctrl-C: exit 1 within a minute, says interrupted", p.returncode == 1 and
          "interrupted" in rest, "exit %s: %s" % (p.returncode, rest))
    check("Ctrl-C: no file left behind", left == [], str(left))


def main():
    if not os.path.isfile(EXAMPLE):
        print("skipped: no bundled example at", EXAMPLE)
        return 77
    with tempfile.TemporaryDirectory(prefix="inlay-batch-") as tmp:
        manifest1 = check_batch_and_equivalence(tmp)
        check_resume(tmp, manifest1)
        check_bad_manifests(tmp)
        check_shards(tmp)
        check_interrupt(tmp)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
