"""What the benchmark scripts share: their options, the ../shared rooms and the harness's
baselines, CSV output and the Markdown tables of docs/bench/. Imported by the scripts beside it
(run them with /usr/bin/python3).

Run on its own it turns a benchmark's CSV into its table (for the C++ benchmarks, and for CSVs
of earlier runs); --command names what wrote the CSV, --fresh says it ran just now (the table
then gives today's date and load):
    /usr/bin/python3 tests/bench/benchlib.py table CSV NAME --command "..." [--fresh] [--columns a,b,c]
writes docs/bench/NAME.md (or under $INLAY_BENCH_TABLES)."""
import contextlib, csv, datetime, json, os, statistics, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))


def args(doc, positional=1):
    """The script's arguments; prints its docstring and exits 0 on -h/--help, and exits 2 with
    it when fewer than `positional` arguments are given."""
    a = sys.argv[1:]
    if "-h" in a or "--help" in a:
        print(doc.strip())
        sys.exit(0)
    if len(a) < positional:
        sys.stderr.write(doc.strip() + "\n")
        sys.exit(2)
    return a


def command_line(doc):
    """What most scripts start with: (their first argument as an absolute path, opt(key, default)
    for their options, the output folder given by --out, by default out/ beside them)."""
    a = args(doc)
    opt = lambda key, default: option(a, key, default)
    return os.path.abspath(a[0]), opt, os.path.abspath(opt("--out", os.path.join(HERE, "out")))


@contextlib.contextmanager
def figure(path, *grid, **kw):
    """The axes of a figure (plt.subplots(*grid, **kw)) written to `path` when the block ends;
    None, and no file, when matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no", os.path.basename(path))
        yield None
        return
    fig, ax = plt.subplots(*grid, **kw)
    yield ax
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def option(argv, key, default):
    """The value after `key` in argv, or `default`."""
    return argv[argv.index(key) + 1] if key in argv else default


def shared_dir():
    return os.environ.get("INLAY_SHARED_DIR", os.path.join(HERE, "..", "..", "..", "shared"))


def scene_rooms(only, out):
    """(scenes folder, harness.py, room names with a truth.json, filtered by the comma-separated
    prefixes in `only`), with the output folder `out` made; prints "skipped" and exits 0 when
    ../shared/scenes is absent (a user's clone)."""
    shared = shared_dir()
    sdir = os.path.join(shared, "scenes")
    harness = os.path.join(shared, "tools", "harness.py")
    if not os.path.isdir(sdir):
        print("skipped: no ../shared/scenes")
        sys.exit(0)
    os.makedirs(out, exist_ok=True)
    names = sorted(n for n in os.listdir(sdir) if os.path.isfile(os.path.join(sdir, n, "truth.json")))
    if only:
        names = [n for n in names if any(n.startswith(p) for p in only.split(","))]
    return sdir, harness, names


def train_rooms(opt, out):
    """(scenes-train folder, harness.py, the room names with a truth.json, only those named in
    the comma-separated --rooms option when given), with the output folder `out` made; prints
    "skipped" and exits 0 when ../shared/scenes-train is absent (a user's clone). For the
    scripts that re-photograph each room through random cameras (camera_variants.py)."""
    train = os.path.join(shared_dir(), "scenes-train")
    if not os.path.isdir(train):
        print("skipped: no ../shared/scenes-train")
        sys.exit(0)
    os.makedirs(out, exist_ok=True)
    harness = os.path.join(shared_dir(), "tools", "harness.py")
    rooms = sorted(d for d in os.listdir(train) if os.path.isfile(os.path.join(train, d, "truth.json")))
    if opt("--rooms", ""):
        rooms = [r for r in rooms if r in opt("--rooms", "").split(",")]
    return train, harness, rooms


PX_KEYS = {("camera", "focal_px"), ("camera", "principal_px"), ("camera", "vanishing_points_px"),
           ("layout", "back_wall_px")}


def scaled(value, k):
    """Every number in a (nested) list of pixel coordinates times k."""
    if isinstance(value, list):
        return [scaled(v, k) for v in value]
    return value * k


def scale_scene_pixels(scene, k):
    """Every pixel key of a scene file's dict (camera, layout, outlined lights, shafts, surfaces,
    occluder scribbles, objects' bases) times k, in place: the scene of its photo resized k times."""
    for section, key in PX_KEYS:
        if key in scene.get(section, {}):
            scene[section][key] = scaled(scene[section][key], k)
    for light in scene.get("lights", []):
        if light.get("kind") == "polygon_px":
            light["points"] = scaled(light["points"], k)
    for shaft in scene.get("shafts", []):
        for key in ("shaft_box_px", "source_box_px"):
            if key in shaft:
                shaft[key] = scaled(shaft[key], k)
    for surface in scene.get("surfaces", []):
        for key in ("outline_px", "height_click_px", "base_px", "profile_px"):
            if key in surface:
                surface[key] = scaled(surface[key], k)
    for occ in scene.get("occluders", []):
        for key in ("foreground_scribbles_px", "background_scribbles_px"):
            occ[key] = scaled(occ[key], k)
    for obj in scene.get("objects", []):
        obj["base_px"] = scaled(obj["base_px"], k)
    return scene


HALF_A = ["t%02d" % k for k in range(1, 15, 2)]  # scenes-train: odd rooms choose, even rooms report


def link_room_files(room_dir, out, replaced=("photo.png", "photo.jpg", "truth.png", "camera_variant.json")):
    """Symbolic links in `out` to every file of `room_dir` but the `replaced` ones (a variant of
    the room re-encodes those)."""
    os.makedirs(out, exist_ok=True)
    for name in os.listdir(room_dir):
        link = os.path.join(out, name)
        if name not in replaced and not os.path.lexists(link):
            os.symlink(os.path.abspath(os.path.join(room_dir, name)), link)


def half(room):
    """"A" (odd rooms: settings are chosen on them) or "B" (even rooms: held out)."""
    return "A" if room[:3] in HALF_A else "B"


def train_rooms_of(only):
    """(scenes-train folder, tools folder, room names with a truth.json filtered by `only`: "A",
    "B" or comma-separated name prefixes); prints "skipped" and exits 0 without ../shared."""
    shared = shared_dir()
    sdir, tools = os.path.join(shared, "scenes-train"), os.path.join(shared, "tools")
    if not os.path.isdir(sdir):
        print("skipped: no ../shared/scenes-train")
        sys.exit(0)
    names = sorted(n for n in os.listdir(sdir) if os.path.isfile(os.path.join(sdir, n, "truth.json")))
    if only in ("A", "B"):
        names = [n for n in names if half(n) == only]
    elif only:
        names = [n for n in names if any(n.startswith(p) for p in only.split(","))]
    return sdir, tools, names


def harness_baselines(harness, sdir):
    """The harness's uniform-object baseline scores, by room name."""
    out = subprocess.run([sys.executable, harness, "baselines", sdir], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    return {json.loads(l)["scene"]: json.loads(l) for l in out}


def write_csv(path, rows, table=None, columns=None):
    """Rows (dicts) to CSV; the columns are every key in the order first seen. With `table`
    (a name), the same rows also go to docs/bench/<table>.md (write_table), `columns` of them."""
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    if table:
        write_table(table, rows, columns, source=path)


def tables_dir():
    """Where the Markdown tables go: $INLAY_BENCH_TABLES, else docs/bench/ of this checkout."""
    return os.environ.get("INLAY_BENCH_TABLES", os.path.join(HERE, "..", "..", "docs", "bench"))


def cell(v):
    """A table cell: floats to 4 significant digits (whole from 10^4 on; integers as they are),
    '|' escaped."""
    if isinstance(v, str):
        try:
            v = int(v) if v.strip().lstrip("-").isdigit() else float(v)
        except ValueError:
            return v.replace("|", "\\|")
    if isinstance(v, float):
        if v != v:
            return "-"
        return "%.0f" % v if 1e4 <= abs(v) < 1e15 else "%.4g" % v
    return "" if v is None else str(v)


def write_table(name, rows, columns=None, source=None, command=None, converted=False):
    """docs/bench/<name>.md: the rows (dicts) as a Markdown table under a line saying which
    command wrote it and when, for docs/benchmarks.md to link. Replaces the previous table."""
    keys = list(columns) if columns else []
    if not keys:
        for r in rows:
            keys += [k for k in r if k not in keys]
    out = tables_dir()
    os.makedirs(out, exist_ok=True)
    root = os.path.abspath(os.path.join(HERE, "..", ".."))
    command = command or " ".join([os.path.relpath(os.path.abspath(sys.argv[0]), root)] + sys.argv[1:])
    if converted:  # a CSV written earlier: its run's machine and load are not known here
        said = "Converted on %s from `%s`, written by `%s`." % (
            datetime.date.today().isoformat(), os.path.basename(source), command)
    else:
        said = "Written by `%s` on %s (%d cores, load average %.1f)." % (
            command, datetime.date.today().isoformat(), os.cpu_count() or 0, os.getloadavg()[0])
    lines = ["<!-- written by tests/bench/benchlib.py; do not edit: run the command below again -->", said,
             "", "| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join(cell(r.get(k, "")) for k in keys) + " |" for r in rows]
    path = os.path.join(out, name + ".md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("table:", os.path.relpath(path))
    return path


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_rows(rows_dir):
    """The per-room result rows a resumable benchmark left in rows_dir (one JSON file each), by name."""
    rows = []
    for name in sorted(os.listdir(rows_dir)):
        if name.endswith(".json"):
            with open(os.path.join(rows_dir, name)) as f:
                rows.append(json.load(f))
    return rows


if __name__ == "__main__":
    a = args(__doc__, 3)
    if a[0] != "table":
        sys.stderr.write(__doc__.strip() + "\n")
        sys.exit(2)
    cols = option(a, "--columns", "")
    write_table(a[2], read_csv(a[1]), cols.split(",") if cols else None, source=a[1],
                command=option(a, "--command", "?"), converted="--fresh" not in a)


def cameras_against_plain(plain, cams, changes):
    """The columns a camera-ratio summary shares: the plain and camera medians, their ratio, and
    how many photos a rule made better or worse than the product by more than 0.005."""
    pm, cm = statistics.median(plain), statistics.median(cams)
    return {"plain_median": round(pm, 4), "cameras_median": round(cm, 4),
            "cameras_mean": round(statistics.mean(cams), 4), "ratio": round(cm / pm, 3),
            "better": sum(1 for x in changes if x < -0.005), "worse": sum(1 for x in changes if x > 0.005)}


def labelled_run(csv_name):
    """A build-labelled benchmark's start: (opt, build, label, out, cli, csv path, rows so far).
    argv[1] is the build; --label, --out and --append as every such script reads them."""
    opt = lambda k, d: option(sys.argv, k, d)  # noqa: E731
    build, label = sys.argv[1], opt("--label", "current")
    out = opt("--out", os.path.join(os.path.dirname(os.path.abspath(__file__)), "out"))
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, csv_name)
    rows = read_csv(path) if os.path.exists(path) and "--append" in sys.argv else []
    return opt, build, label, out, os.path.join(build, "app", "inlay-cli"), path, rows


def scene_with_response(scene, response, out, tag):
    """A copy of the scene file `scene` with camera.response set to `response`, written to
    OUT/TAG.json; returns its path and the path its --lights-json is to take (OUT/TAG_lights.json)."""
    j = json.load(open(scene))
    j.setdefault("camera", {})["response"] = response
    path = os.path.join(out, tag + ".json")
    json.dump(j, open(path, "w"), indent=1)
    return path, os.path.join(out, tag + "_lights.json")


def rows_of_csvs(paths):
    """The rows of several CSV files (a --from-csv list, comma-separated), one after the other."""
    rows = []
    for f in paths.split(","):
        rows += [dict(r) for r in csv.DictReader(open(f))]
    return rows


def write_rows_and_summary(out, name, rows, summ, plot):
    """OUT/NAME.csv (the rows), OUT/NAME_summary.csv (printed too) and plot(rows, summ, OUT/NAME.png)."""
    write_csv(os.path.join(out, name + ".csv"), rows)
    write_csv(os.path.join(out, name + "_summary.csv"), summ)
    for s in summ:
        print(s)
    plot(rows, summ, os.path.join(out, name + ".png"))

