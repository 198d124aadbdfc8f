#!/usr/bin/python3
"""End to end on ../shared/scenes: the harness writes each room's scene file (camera, back wall
and light outlines from its truth), inlay-cli renders it, the harness scores the composite the
way the acceptance checks do. Each scene's object RMSE must beat the paper's baseline (a flat,
uniformly shaded object of the dataset's mean true colour). Prints a table and writes
scenes.csv in the working folder. Exit 77 (skipped) without ../shared.

usage: cli_scenes_test.py INLAY_CLI [--seconds S] [--out DIR]
"""
import csv, json, os, subprocess, sys, time

SKIP = 77


def main():
    cli = os.path.abspath(sys.argv[1])
    args = sys.argv[2:]
    seconds = float(args[args.index("--seconds") + 1]) if "--seconds" in args else 12.0
    out = os.path.abspath(args[args.index("--out") + 1]) if "--out" in args else os.path.abspath("cli_scenes")
    shared = os.environ.get("INLAY_SHARED_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "shared"))
    scenes_dir = os.path.join(shared, "scenes")
    harness = os.path.join(shared, "tools", "harness.py")
    if not (os.path.isdir(scenes_dir) and os.path.isfile(harness)):
        print("skipped: ../shared/scenes not present")
        return SKIP
    os.makedirs(out, exist_ok=True)
    py = sys.executable
    base = {}
    for line in subprocess.run([py, harness, "baselines", scenes_dir], capture_output=True, text=True, check=True).stdout.splitlines():
        r = json.loads(line)
        base[r["scene"]] = r
    rows, failures = [], []
    for name in sorted(os.listdir(scenes_dir)):
        sd = os.path.join(scenes_dir, name)
        if not os.path.isfile(os.path.join(sd, "truth.json")):
            continue
        sf = os.path.join(out, name + ".json")
        comp = os.path.join(out, name + ".png")
        subprocess.run([py, harness, "scene", sd, sf, "--seconds", str(seconds)], check=True)
        if os.path.exists(comp):
            os.remove(comp)
        t0 = time.time()
        p = subprocess.run([cli, "render", sf, "-o", comp, "--quiet", "--progress-csv", os.path.join(out, name + "_progress.csv")],
                           capture_output=True, text=True, timeout=seconds * 4 + 180)
        wall = time.time() - t0
        if p.returncode != 0:
            failures.append("%s: inlay-cli exited %d: %s" % (name, p.returncode, p.stderr.strip()[-300:]))
            continue
        s = json.loads(subprocess.run([py, harness, "score", sd, comp], capture_output=True, text=True, check=True).stdout)
        spp = 0
        with open(os.path.join(out, name + "_progress.csv")) as f:
            lines = f.read().strip().splitlines()
            if len(lines) > 1:
                spp = int(lines[-1].split(",")[1])
        row = {"scene": name, "object_rmse": round(s["object_rmse"], 4),
               "object_rmse_adjusted": round(s["object_rmse_adjusted"], 4),
               "uniform_baseline_rmse": round(base[name]["uniform_dataset_mean_rmse"], 4),
               "around_rmse": round(s["around_rmse"], 4), "around_rmse_do_nothing": round(s["around_rmse_do_nothing"], 4),
               "outside_rmse": round(s["outside_rmse"], 4), "wall_s": round(wall, 1), "spp": spp}
        rows.append(row)
        if not s["object_rmse"] < base[name]["uniform_dataset_mean_rmse"]:
            failures.append("%s: object RMSE %.4f is not below the uniform baseline %.4f" % (name, s["object_rmse"], base[name]["uniform_dataset_mean_rmse"]))
    if rows:
        with open(os.path.join(out, "scenes.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        print("%-22s %8s %8s %8s %8s %8s %7s %5s" % ("scene", "obj", "obj_adj", "uniform", "around", "nothing", "wall_s", "spp"))
        for r in rows:
            print("%-22s %8.4f %8.4f %8.4f %8.4f %8.4f %7.1f %5d" % (r["scene"], r["object_rmse"], r["object_rmse_adjusted"],
                  r["uniform_baseline_rmse"], r["around_rmse"], r["around_rmse_do_nothing"], r["wall_s"], r["spp"]))
    for f in failures:
        print("FAIL", f)
    print("%d passed, %d failed" % (len(rows) - sum(1 for f in failures if "baseline" in f), len(failures)))
    return 1 if failures or not rows else 0


if __name__ == "__main__":
    sys.exit(main())
