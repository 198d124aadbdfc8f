#!/usr/bin/python3
"""NEE light selection against the number of lights: runs bench_light_selection (spatial rule,
power table and Auto on a room with one bright and many dim ceiling lights, 1 to 64 of them)
and plots seconds per sample and relative noise at equal samples against the light count, and
their product noise^2 x seconds (the time to a given noise, up to a constant).

Writes OUT/light_selection.csv and OUT/light_selection.png; prints a Markdown table.

usage: bench_light_selection.py BUILD_DIR [--out DIR] [--size 96x72] [--spp 16] [--repeats 3]
"""
import csv, os, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402


def main():
    build, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    w, h = opt("--size", "96x72").split("x")
    path = os.path.join(out, "light_selection.csv")
    exe = os.path.join(build, "tests", "bench", "bench_light_selection")
    subprocess.run(["nice", "-n", "10", exe, path, w, h, opt("--spp", "16"), opt("--repeats", "3")], check=True)
    rows = list(csv.DictReader(open(path)))
    benchlib.write_table("light_selection", rows, source=path)
    modes = sorted({r["mode"] for r in rows}, key=["spatial", "power", "auto"].index)
    print("| lights | " + " | ".join(f"{m} ms/spp | {m} noise" for m in modes) + " |")
    print("|---" * (1 + 2 * len(modes)) + "|")
    for n in sorted({int(r["lights"]) for r in rows}):
        cells = []
        for m in modes:
            r = next(r for r in rows if int(r["lights"]) == n and r["mode"] == m)
            cells += [f"{1e3 * float(r['seconds_per_spp']):.2f}", f"{float(r['relative_noise']):.4f}"]
        print(f"| {n} | " + " | ".join(cells) + " |")
    with benchlib.figure(os.path.join(out, "light_selection.png"), 1, 3, figsize=(13, 4)) as ax:
        if ax is None:
            return
        for m in modes:
            sel = sorted((int(r["lights"]), r) for r in rows if r["mode"] == m)
            xs = [n for n, _ in sel]
            ax[0].plot(xs, [1e3 * float(r["seconds_per_spp"]) for _, r in sel], "o-", label=m)
            ax[1].plot(xs, [float(r["relative_noise"]) for _, r in sel], "o-", label=m)
            ax[2].plot(xs, [float(r["noise2_x_seconds"]) for _, r in sel], "o-", label=m)
        for a, t in zip(ax, ["ms per sample (CPU time, 1 thread)", "relative noise at equal samples",
                             "noise² × s per sample (lower is better)"]):
            a.set_xscale("log", base=2)
            a.set_xlabel("lights (one bright, the rest dim)")
            a.set_title(t)
            a.grid(True, alpha=0.3)
            a.legend()
        ax[2].set_yscale("log")


if __name__ == "__main__":
    main()
