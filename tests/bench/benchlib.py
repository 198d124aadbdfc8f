"""What the benchmark scripts share: their options, the ../shared rooms and the harness's
baselines, and CSV output. Imported by the scripts beside it (run them with /usr/bin/python3)."""
import contextlib, csv, json, os, subprocess, sys

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


def harness_baselines(harness, sdir):
    """The harness's uniform-object baseline scores, by room name."""
    out = subprocess.run([sys.executable, harness, "baselines", sdir], capture_output=True, text=True,
                         check=True).stdout.splitlines()
    return {json.loads(l)["scene"]: json.loads(l) for l in out}


def write_csv(path, rows):
    """Rows (dicts) to CSV; the columns are every key in the order first seen."""
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
