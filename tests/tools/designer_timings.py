"""The timing table of issue #17's closing note, in Markdown, from what designer_report.sh
collected in OUTDIR: the guided start's and the designer test's steps (guided/figures.csv,
designer/figures.csv) and bench_big_photo's medians (bench/bench_big_photo_summary.csv).

  /usr/bin/python3 tests/tools/designer_timings.py OUTDIR > OUTDIR/timings.md"""
import csv, os, sys

GESTURES = [
    ("insert_gltf_ms", "Insert Model… (a glTF file) until it is in the scene"),
    ("drop_obj_ms", "an OBJ dropped on the floor until it stands there"),
    ("turn_and_scale_ms", "turn and height in Properties (two edits)"),
    ("turn_handle_to_frame_ms", "turn handle drag to the current frame"),
    ("height_handle_to_frame_ms", "height handle drag to the current frame"),
    ("snap_drag_to_frame_ms", "drag to the wall (snapped) to the current frame"),
    ("render_final_ms", "Render Final Image (denoised; 8 spp in the guided start, 2 in the walk) until written and shown"),
    ("accept_box_and_light_prepared_ms", "the box accepted and a light outlined until prepared"),
    ("library_chair_drop_ms", "a library chair dragged in until it stands there"),
    ("undo_all_ms", "undo everything"),
    ("redo_all_ms", "redo everything"),
]


def read_figures(path):
    with open(path) as f:
        return {r["figure"]: float(r["value"]) for r in csv.DictReader(f)}


def walk_table(path, title):
    fig = read_figures(path)
    lines = ["### %s, a York photo, 640 × 480" % title, "",
             "| step | seconds since the photo was opened |", "|---|---|"]
    for key, value in fig.items():
        if key.startswith("step_seconds_"):
            lines.append("| %s | %.1f |" % (key[len("step_seconds_"):].replace("_", " "), value))
    lines += ["", "| gesture | ms |", "|---|---|"]
    for key, what in GESTURES:
        if key in fig:
            lines.append("| %s | %.0f |" % (what, fig[key]))
    return lines


def seconds(ms):
    return "-" if ms in ("", "nan") else "%.2f s" % (float(ms) / 1000)


def millis(ms):
    return "-" if ms in ("", "nan") else "%.0f ms" % float(ms)


def bench_table(path):
    lines = ["### Open, prepare and first frame against megapixels (`bench_big_photo`, medians)", "",
             "| photo | size | MP | open | prepare | first frame | paint | gesture to frame (CPU) |",
             "|---|---|---|---|---|---|---|---|"]
    with open(path) as f:
        for r in csv.DictReader(f):
            name = "the example" if r["photo"] == "example" else "York photo at " + r["photo"]
            gesture = "-" if r["gesture_frame_ms"] == "nan" else "%s (%s)" % (
                millis(r["gesture_frame_ms"]), millis(r["gesture_frame_cpu_ms"]))
            lines.append("| %s | %s × %s | %s | %s | %s | %s | %s | %s |" % (
                name, r["width"], r["height"], r["megapixels_actual"], seconds(r["open_ms"]),
                seconds(r["prepare_ms"]), seconds(r["first_frame_ms"]), millis(r["paint_ms"]), gesture))
    return lines


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    lines = []
    guided = lambda path: walk_table(path, "The guided start (`studio_guided_test`)")
    designer = lambda path: walk_table(path, "The designer test's walk (`studio_designer_test`)")
    for name, table in [(os.path.join(out, "guided", "figures.csv"), guided),
                        (os.path.join(out, "designer", "figures.csv"), designer),
                        (os.path.join(out, "bench", "bench_big_photo_summary.csv"), bench_table)]:
        if os.path.exists(name):
            lines += table(name) + [""]
        else:
            lines += ["(%s is missing: run its stage of designer_report.sh)" % name, ""]
    try:
        load = "%.1f" % os.getloadavg()[0]
    except OSError:
        load = "?"
    lines.append("(%d cores, load average %s when the table was written.)" % (os.cpu_count() or 0, load))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
