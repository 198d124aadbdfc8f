#!/usr/bin/python3
"""A scene's preparation is the same on any machine and under any load (issue 18): the bundled
example exported as glTF (`inlay-cli export`: the room with its albedo textures, the refined
lights, camera and objects) twice, once on two threads with nothing else running and once on
one thread beside two busy processes, gives byte-identical files. The light refinement stops at
a budget of evaluations, not at a wall clock (lighting_tests' LightRefineBudget checks that a
slow clock or a fired time guard cannot pass silently); this checks the whole preparation.
Needs nothing from ../shared.

usage: cli_reproducible_test.py INLAY_CLI
"""
import multiprocessing
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "resources", "example", "scene.json")


def spin(stop):
    x = 1.0
    while not stop.is_set():
        x = x * 1.0000001 + 1e-9


def export(cli, out, threads, busy):
    stop = multiprocessing.Event()
    load = [multiprocessing.Process(target=spin, args=(stop,)) for _ in range(busy)]
    for p in load:
        p.start()
    try:
        p = subprocess.run([cli, "export", SCENE, "-o", out, "--threads", str(threads)], capture_output=True,
                           text=True, timeout=900)
    finally:
        stop.set()
        for q in load:
            q.join()
    if p.returncode != 0:
        raise SystemExit("inlay-cli export exited %d: %s" % (p.returncode, p.stderr.strip()[-400:]))
    if "time guard" in p.stderr:
        raise SystemExit("the refinement's time guard fired on the example: %s" % p.stderr.strip()[-400:])
    return open(out, "rb").read()


def main():
    cli = sys.argv[1]
    with tempfile.TemporaryDirectory() as work:
        idle = export(cli, os.path.join(work, "idle.glb"), threads=2, busy=0)
        loaded = export(cli, os.path.join(work, "loaded.glb"), threads=1, busy=2)
    if idle != loaded:
        first = next((i for i, (a, b) in enumerate(zip(idle, loaded)) if a != b), min(len(idle), len(loaded)))
        raise SystemExit("FAIL: the example's export differs under load (%d against %d bytes, first "
                         "difference at byte %d)" % (len(idle), len(loaded), first))
    print("ok: the example's export is byte-identical idle on two threads and loaded on one (%d bytes)" % len(idle))


if __name__ == "__main__":
    main()
