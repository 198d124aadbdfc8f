"""Big photos in the studio: runs bench_big_photo (a York photo, or the example, upscaled at run
time to each size; never kept) and plots open, prepare and first frame against megapixels, and
the time from an arranging gesture to its first frame on screen with the paint time (the
issue's target: <= 33 ms at 512 x 384, the bundled example).

  /usr/bin/python3 tests/bench/bench_big_photo.py build [--out DIR] [--mp 0.3,3,12]
      [--gestures 15] [--plot-only]

Writes bench_big_photo.csv (from the binary), bench_big_photo_summary.csv (medians) and
bench_big_photo.png into DIR (default tests/bench/out)."""
import collections, csv, os, statistics, subprocess, sys

import benchlib


def run(build, out, mp, gestures):
    exe = os.path.join(build, "tests", "bench", "bench_big_photo")
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    env.setdefault("INLAY_SHARED_DIR", benchlib.shared_dir())
    cmd = ["nice", "-n", "10", exe, "--out", out, "--mp", mp, "--gestures", str(gestures)]
    print(" ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, env=env)


def medians(path):
    """{(megapixels, figure): median} and {megapixels: (width, height)} of the binary's CSV."""
    samples = collections.defaultdict(list)
    sizes = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            mp = float(row["megapixels"])
            samples[(mp, row["figure"])].append(float(row["value"]))
            sizes[mp] = (int(row["width"]), int(row["height"]))
    return {k: statistics.median(v) for k, v in samples.items()}, sizes


def main():
    build, opt, out = benchlib.command_line(__doc__)
    os.makedirs(out, exist_ok=True)
    if "--plot-only" not in sys.argv:
        run(build, out, opt("--mp", "0.3,3,12"), int(opt("--gestures", "15")))
    med, sizes = medians(os.path.join(out, "bench_big_photo.csv"))
    figures = ["open_ms", "prepare_ms", "first_frame_ms", "paint_ms", "gesture_frame_ms", "gesture_frame_cpu_ms",
               "preview_megapixels"]
    with open(os.path.join(out, "bench_big_photo_summary.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["photo", "width", "height", "megapixels_actual"] + figures)
        for mp in sorted(sizes):
            wd, ht = sizes[mp]
            w.writerow(["example" if mp == 0 else "%gMP" % mp, wd, ht, "%.2f" % (wd * ht / 1e6)]
                       + ["%.1f" % med.get((mp, k), float("nan")) if k != "preview_megapixels"
                          else "%.2f" % med.get((mp, k), float("nan")) for k in figures])
    with open(os.path.join(out, "bench_big_photo_summary.csv")) as f:
        print(f.read())
    summary_csv = os.path.join(out, "bench_big_photo_summary.csv")
    benchlib.write_table("big_photo", list(csv.DictReader(open(summary_csv))), source=summary_csv)
    mps = [mp for mp in sorted(sizes) if mp > 0]
    actual = [sizes[mp][0] * sizes[mp][1] / 1e6 for mp in mps]
    with benchlib.figure(os.path.join(out, "bench_big_photo.png"), 1, 2, figsize=(11, 4.2)) as ax:
        if ax is None:
            return
        for key, label in [("open_ms", "open (photo shown)"), ("prepare_ms", "prepare"),
                           ("first_frame_ms", "first frame after prepare")]:
            ax[0].plot(actual, [med[(mp, key)] / 1000 for mp in mps], "o-", label=label)
        ax[0].set_xscale("log")
        ax[0].set_yscale("log")
        ax[0].set_xlabel("photo megapixels")
        ax[0].set_ylabel("seconds (median)")
        ax[0].set_title("opening a photo")
        ax[0].legend()
        for key, label in [("gesture_frame_ms", "gesture to first frame"),
                           ("gesture_frame_cpu_ms", "its CPU time (all threads)"), ("paint_ms", "viewport paint")]:
            ys = [med.get((mp, key)) for mp in mps]
            if all(y is not None for y in ys):
                ax[1].plot(actual, ys, "o-", label=label)
        if (0.0, "gesture_frame_ms") in med:
            ex = sizes[0.0][0] * sizes[0.0][1] / 1e6
            ax[1].plot([ex], [med[(0.0, "gesture_frame_ms")]], "k*", markersize=12,
                       label="gesture, example 512x384")
            if (0.0, "gesture_frame_cpu_ms") in med:
                ax[1].plot([ex], [med[(0.0, "gesture_frame_cpu_ms")]], "r*", markersize=12,
                           label="its CPU time, example")
        ax[1].axhline(33, color="gray", linestyle="--", label="33 ms target")
        ax[1].set_xscale("log")
        ax[1].set_xlabel("photo megapixels")
        ax[1].set_ylabel("milliseconds (median)")
        ax[1].set_title("arranging (preview <= %.1f MP)" % 1.0)
        ax[1].legend()


if __name__ == "__main__":
    main()
