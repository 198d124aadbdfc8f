#!/usr/bin/python3
"""Error against run time on every room of ../shared/scenes.

For each room the harness writes the assisted scene file; inlay-cli renders it with a series of
time budgets; the harness scores each composite (object RMSE against the true photo with the
object, sRGB [0,1]; the same after removing the mean; the surroundings). Writes
OUT/scenes_error_vs_time.csv and OUT/scenes_error_vs_time.png.

usage: bench_scenes.py INLAY_CLI [--out DIR] [--budgets 2,4,8,16] [--scenes d1,d3] [--repeat N]
                       [--mode assisted|auto]
--mode auto: the harness's automatic scene (no camera, layout or table keys: inlay-cli
estimates them); the CSV and PNG names then end in _auto.
"""
import json, os, statistics, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import benchlib  # noqa: E402


def main():
    cli, opt, out = benchlib.command_line(__doc__)
    budgets = [float(x) for x in opt("--budgets", "2,4,8,16,32").split(",")]
    repeat = int(opt("--repeat", "1"))
    mode = opt("--mode", "assisted")
    tag = "" if mode == "assisted" else "_" + mode
    sdir, harness, names = benchlib.scene_rooms(opt("--scenes", ""), out)
    py = sys.executable
    base = benchlib.harness_baselines(harness, sdir)
    rows = []
    for name in names:
        sd = os.path.join(sdir, name)
        for budget in budgets:
            scores, walls, spps = [], [], []
            for rep in range(repeat):
                sf = os.path.join(out, "%s.json" % name)
                comp = os.path.join(out, "%s_%g.png" % (name, budget))
                prog = os.path.join(out, "%s_%g.csv" % (name, budget))
                subprocess.run([py, harness, "scene", sd, sf, "--seconds", str(budget), "--mode", mode], check=True)
                t0 = time.time()
                p = subprocess.run([cli, "render", sf, "-o", comp, "--quiet", "--progress-csv", prog], capture_output=True, text=True)
                walls.append(time.time() - t0)
                if p.returncode != 0:
                    print(name, budget, "failed:", p.stderr.strip()[-200:])
                    break
                scores.append(json.loads(subprocess.run([py, harness, "score", sd, comp], capture_output=True, text=True, check=True).stdout))
                lines = open(prog).read().strip().splitlines()
                spps.append(int(lines[-1].split(",")[1]) if len(lines) > 1 else 0)
            if not scores:
                continue
            med = lambda k: statistics.median(s[k] for s in scores)
            row = {"scene": name, "budget_s": budget, "wall_s": round(statistics.median(walls), 2),
                   "spp": int(statistics.median(spps)), "object_rmse": round(med("object_rmse"), 4),
                   "object_rmse_adjusted": round(med("object_rmse_adjusted"), 4),
                   "around_rmse": round(med("around_rmse"), 4), "around_rmse_do_nothing": round(med("around_rmse_do_nothing"), 4),
                   "uniform_baseline": round(base[name]["uniform_dataset_mean_rmse"], 4)}
            rows.append(row)
            print(json.dumps(row), flush=True)
    if not rows:
        return 1
    csvp = os.path.join(out, "scenes_error_vs_time%s.csv" % tag)
    benchlib.write_csv(csvp, rows, table="scenes" + tag)
    with benchlib.figure(os.path.join(out, "scenes_error_vs_time%s.png" % tag), 1, 2, figsize=(11, 4)) as ax:
        if ax is not None:
            plot(ax, rows, names)
    print("wrote", csvp)
    return 0


def plot(ax, rows, names):
    """Object and surroundings RMSE against wall time, a line per room."""
    for name in names:
        rr = [r for r in rows if r["scene"] == name]
        if not rr:
            continue
        ax[0].plot([r["wall_s"] for r in rr], [r["object_rmse"] for r in rr], "o-", label=name)
        ax[1].plot([r["wall_s"] for r in rr], [r["around_rmse"] for r in rr], "o-", label=name)
    ax[0].set(xscale="log", xlabel="wall seconds (prepare + render)", ylabel="object RMSE vs truth (sRGB)", title="object")
    ax[1].set(xscale="log", xlabel="wall seconds", ylabel="surroundings RMSE vs truth", title="shadows and bounce")
    ax[0].legend(fontsize=7)


if __name__ == "__main__":
    sys.exit(main())
