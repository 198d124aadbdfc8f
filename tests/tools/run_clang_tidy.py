#!/usr/bin/env python3
"""Runs clang-tidy (the checks in .clang-tidy) over the project's own translation units.

The units are the tracked sources in a build tree's compile_commands.json (every configure writes
it): not Qt's generated moc/rcc units, not third-party code. Each finding in our files is listed
once (a header's finding shows up in every unit that includes it); the exit status is 1 if there
is any, 2 if the tool or the build tree is missing.

Units run in parallel (-j). A unit that comes out clean is remembered in BUILD_DIR/clang-tidy-cache
under a hash of everything its result depends on: every .clang-tidy of the repository, the
unit's flags, the clang-tidy version and its input, which is either
  - the source and every header it includes, as the build's last compile of the unit listed them
    (ninja -t deps), when that object is newer than each of those files (nothing changed since,
    so the list is the unit's); reading them costs next to nothing; or otherwise
  - the unit preprocessed by clang with its own flags and comments kept (every NOLINT in it),
    which costs a few seconds a unit; the files it read are listed (a manifest), and the next
    run keys the unit by their contents, preprocessing it only if one of them changed.
A rerun only checks what changed.

usage: tests/tools/run_clang_tidy.py [-j N] [--no-cache] [BUILD_DIR] [REGEX...]
  REGEX: only the units whose path matches (e.g. 'modeling/src/mesh'); default all of ours.
Run it at low priority on a shared machine: nice -n 15 tests/tools/run_clang_tidy.sh ...
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

FINDING = re.compile(r"^(/[^:]+):(\d+):(\d+): (warning|error): (.*) \[([\w.,-]+)\]$")
# GCC-only warning flags in the compile commands (-Wshadow=local) would warn as unknown.
EXTRA_ARGS = ["-Wno-unknown-warning-option"]


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("build", nargs="?", default="build", help="build tree (default build)")
    p.add_argument("patterns", nargs="*", help="only the units whose path matches one of these")
    p.add_argument("-j", "--jobs", type=int, default=int(os.environ.get("JOBS", os.cpu_count() or 1)),
                   help="units checked at once (default: JOBS or the number of cores)")
    p.add_argument("--no-cache", action="store_true", help="check every unit, cached or not")
    p.add_argument("--tidy", default=os.environ.get("CLANG_TIDY", "clang-tidy-14"))
    p.add_argument("--clang", default=os.environ.get("CLANG", "clang++-14"),
                   help="the compiler that preprocesses a unit for its cache key")
    return p.parse_args()


def git_files(root, *patterns):
    out = subprocess.run(["git", "ls-files", *patterns], cwd=root, capture_output=True, text=True,
                         check=True).stdout
    return set(out.split())


def our_units(db_path, root, patterns):
    """[(relative path, compile_commands entry)] of the tracked sources the build compiles."""
    tracked = git_files(root, "*.cpp", "*.cc")
    units, seen = [], set()
    for e in json.load(open(db_path)):
        f = os.path.relpath(os.path.join(e["directory"], e["file"]), root)
        if f in tracked and f not in seen and (not patterns or any(re.search(p, f) for p in patterns)):
            seen.add(f)
            units.append((f, e))
    return units


def compile_args(entry):
    return entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])


def preprocess_args(entry, clang):
    """The unit's compile command turned into 'clang -E -C' to stdout (same defines, includes)."""
    args, out, skip = compile_args(entry), [clang], False
    for a in args[1:]:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a not in ("-c",) and not a.startswith("-o"):
            out.append(a)
    if os.path.basename(args[0]) in ("ccache", "sccache"):  # a launcher in front of the compiler
        out.pop(1)
    return out + EXTRA_ARGS + ["-E", "-C"]


def config_digest(root, tidy):
    h = hashlib.sha256()
    h.update(subprocess.run([tidy, "--version"], capture_output=True, text=True).stdout.encode())
    for f in sorted(git_files(root, "*.clang-tidy")):
        h.update(f.encode())
        with open(os.path.join(root, f), "rb") as fh:
            h.update(fh.read())
    h.update(" ".join(EXTRA_ARGS).encode())
    return h.hexdigest()


def ninja_deps(build):
    """{object file (as ninja names it): [its source and headers]} of the build's last compiles;
    empty when the build tree is not ninja's."""
    r = subprocess.run(["ninja", "-C", build, "-t", "deps"], capture_output=True, text=True)
    deps, current = {}, None
    for line in r.stdout.splitlines() if r.returncode == 0 else []:
        if line and not line.startswith(" "):
            current = line.split(": #deps")[0] if line.endswith("(VALID)") else None
            if current:
                deps[current] = []
        elif line.strip() and current:
            deps[current].append(line.strip())
    return deps


def object_of(entry):
    args = compile_args(entry)
    for i, a in enumerate(args):
        if a == "-o" and i + 1 < len(args):
            return args[i + 1]
        if a.startswith("-o") and len(a) > 2:
            return a[2:]
    return None


class FileDigests:
    """sha256 of files' contents, each file read once per run."""

    def __init__(self):
        self.known = {}

    def __call__(self, path):
        if path not in self.known:
            with open(path, "rb") as f:
                self.known[path] = hashlib.sha256(f.read()).hexdigest()
        return self.known[path]


def files_key(entry, paths, digests, base_digest, kind):
    """The hash of the configuration, the unit's flags and the contents of `paths`."""
    h = hashlib.sha256(base_digest.encode())
    h.update(" ".join(compile_args(entry)).encode())
    for p in paths:
        h.update(f"{p} {digests(p)}\n".encode())
    return kind + h.hexdigest()


def deps_key(entry, deps, digests, base_digest):
    """The key of the unit's source and headers as the build lists them; None when the build has
    no object of the unit newer than each of them (the list may be out of date)."""
    obj = object_of(entry)
    files = deps.get(obj) if obj else None
    if not files:
        return None
    directory = entry["directory"]
    try:
        built = os.stat(os.path.join(directory, obj)).st_mtime_ns
        paths = [os.path.join(directory, f) for f in files]
        if any(os.stat(p).st_mtime_ns > built for p in paths):
            return None
        return files_key(entry, paths, digests, base_digest, "d")
    except OSError:
        return None


LINE_MARKER = re.compile(rb'^# \d+ "([^"<][^"]*)"', re.MULTILINE)


def preprocessed_key(entry, clang, base_digest):
    """The key of the unit's preprocessed text (comments kept), flags and configuration, and the
    files the text came from (its line markers); (None, []) if it does not preprocess (then
    clang-tidy runs and says why)."""
    r = subprocess.run(preprocess_args(entry, clang), cwd=entry["directory"], capture_output=True)
    if r.returncode != 0:
        return None, []
    h = hashlib.sha256(base_digest.encode())
    h.update(" ".join(compile_args(entry)).encode())
    h.update(r.stdout)
    files = dict.fromkeys(os.path.join(entry["directory"], m.decode(errors="replace"))
                          for m in LINE_MARKER.findall(r.stdout))
    return "p" + h.hexdigest(), [f for f in files if os.path.isfile(f)]


def manifest_path(cache_dir, entry):
    """Where the files of the unit's last preprocessing are listed (one path a line)."""
    name = hashlib.sha256((entry["file"] + " ".join(compile_args(entry))).encode()).hexdigest()
    return os.path.join(cache_dir, "manifests", name)


def unit_keys(args, entry, key, digests, base_digest, cache_dir):
    """The unit's cache keys: the build's dependency list's (`key`) when it holds; else the key of
    the files its last preprocessing read (the manifest) when that one is cached (none of them
    has changed since: as ccache's direct mode); else its preprocessed text's and its files'
    (the manifest written anew)."""
    if key is not None:
        return [key]
    manifest = manifest_path(cache_dir, entry)
    try:
        with open(manifest) as f:
            listed = f.read().splitlines()
        mkey = files_key(entry, listed, digests, base_digest, "m")
        if os.path.exists(os.path.join(cache_dir, mkey)):
            return [mkey]
    except OSError:
        pass
    pkey, files = preprocessed_key(entry, args.clang, base_digest)
    if pkey is None:
        return []
    os.makedirs(os.path.dirname(manifest), exist_ok=True)
    with open(manifest, "w") as f:
        f.write("".join(p + "\n" for p in files))
    try:
        return [pkey, files_key(entry, files, digests, base_digest, "m")]
    except OSError:
        return [pkey]


def unit_size(entry, deps):
    """About how much the unit parses: the bytes of its source and headers when the build lists
    them, else of its source alone."""
    directory = entry["directory"]
    try:
        files = deps.get(object_of(entry)) or [entry["file"]]
        return sum(os.path.getsize(os.path.join(directory, f)) for f in files)
    except OSError:
        return 0


def findings_in(text, root, tracked):
    found = {}
    for line in text.splitlines():
        m = FINDING.match(line)
        if m:
            f = os.path.relpath(m.group(1), root)
            if f in tracked:
                found[(f, int(m.group(2)), int(m.group(3)), m.group(6))] = m.group(5)
    return found


def run_tidy(tidy, build, unit):
    start = time.monotonic()
    r = subprocess.run([tidy, "-p", build, "--quiet", *[f"--extra-arg={a}" for a in EXTRA_ARGS],
                        unit], capture_output=True, text=True, errors="replace")
    return r.returncode, r.stdout + r.stderr, time.monotonic() - start


def check_unit(args, build, entry, key, digests, base_digest, cache_dir):
    """(the unit's keys, cached?, clang-tidy's exit status, output, seconds)."""
    keys = unit_keys(args, entry, key, digests, base_digest, cache_dir)
    if not args.no_cache and any(os.path.exists(os.path.join(cache_dir, k)) for k in keys):
        return keys, True, 0, "", 0.0
    return (keys, False, *run_tidy(args.tidy, build, entry["file"]))


def remember(cache_dir, keys, unit):
    """Records the unit as clean under each of its keys."""
    for key in keys:
        with open(os.path.join(cache_dir, key), "w") as f:
            f.write(unit + "\n")


def check_units(args, root, build, units, tracked, cache_dir):
    """Runs clang-tidy on each unit not cached clean, smallest first; returns (findings, units
    checked, units cached, units that failed without a finding in our files)."""
    base = config_digest(root, args.tidy)
    deps, digests = ninja_deps(build), FileDigests()
    # The product's units before the tests' and benchmarks', the smallest first: findings (a
    # header's above all) arrive soonest, and a run stopped early has covered the most units of
    # the product, each clean one cached for the next run.
    todo = sorted((unit.startswith("tests/"), unit_size(e, deps), unit, e,
                   deps_key(e, deps, digests, base)) for unit, e in units)
    preprocessed = sum(1 for t in todo if t[4] is None)
    print(f"run_clang_tidy: {len(units)} units ({len(units) - preprocessed} keyed by the build's "
          f"dependency lists, {preprocessed} by their preprocessed text), {args.jobs} jobs, "
          f"{args.tidy}", flush=True)
    found, failed, checked, cached = {}, [], 0, 0
    log = open(os.path.join(build, "clang-tidy.log"), "w")
    with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        jobs = {pool.submit(check_unit, args, build, e, key, digests, base, cache_dir): unit
                for _, _, unit, e, key in todo}
        for done in concurrent.futures.as_completed(jobs):
            unit = jobs[done]
            keys, hit, rc, text, seconds = done.result()
            if hit:  # under each key (a preprocessed unit's files key: no preprocessing next time)
                cached += 1
                remember(cache_dir, keys, unit)
                continue
            checked += 1
            log.write(f"=== {unit} (exit {rc}, {seconds:.0f} s)\n{text}\n")
            log.flush()
            mine = findings_in(text, root, tracked)
            found.update(mine)
            if rc != 0 and not mine:
                failed.append(unit)
            elif not mine:
                remember(cache_dir, keys, unit)
            status = f"{len(mine)} findings" if mine else ("FAILED" if rc != 0 else "clean")
            print(f"[{checked + cached}/{len(todo)}] {unit}: {status} ({seconds:.0f} s)", flush=True)
    return found, checked, cached, failed


def report(found, failed):
    for (f, line, col, check), msg in sorted(found.items()):
        print(f"{f}:{line}:{col}: {msg} [{check}]")
    by = {}
    for (_, _, _, check) in found:
        by[check] = by.get(check, 0) + 1
    for check, n in sorted(by.items(), key=lambda kv: -kv[1]):
        print(f"  {n:4d}  {check}")
    for unit in failed:
        print(f"run_clang_tidy: {unit}: clang-tidy failed without a finding in our files "
              "(see the log)")


def main():
    args = parse_args()
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    build = os.path.abspath(os.path.join(root, args.build) if not os.path.isabs(args.build)
                            else args.build)
    for tool, pkg in ((args.tidy, "clang-tidy-14"), (args.clang, "clang-14")):
        if not shutil.which(tool):
            print(f"run_clang_tidy: {tool} not found (apt-get install {pkg})", file=sys.stderr)
            return 2
    db = os.path.join(build, "compile_commands.json")
    if not os.path.isfile(db):
        print(f"run_clang_tidy: {db} missing: configure first (cmake -S . -B {args.build} -G Ninja "
              "...; CMAKE_EXPORT_COMPILE_COMMANDS is on)", file=sys.stderr)
        return 2
    units = our_units(db, root, args.patterns)
    if not units:
        print("run_clang_tidy: no source of ours matches", file=sys.stderr)
        return 2
    cache_dir = os.path.join(build, "clang-tidy-cache")
    os.makedirs(cache_dir, exist_ok=True)
    start = time.monotonic()
    found, checked, cached, failed = check_units(args, root, build, units, git_files(root), cache_dir)
    report(found, failed)
    minutes = (time.monotonic() - start) / 60
    print(f"run_clang_tidy: {len(units)} units: {checked} checked, {cached} cached clean; "
          f"{len(found)} findings in our files; {minutes:.1f} min wall "
          f"(raw output: {os.path.join(build, 'clang-tidy.log')})")
    return 1 if found or failed else 0


if __name__ == "__main__":
    sys.exit(main())
