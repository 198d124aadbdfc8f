#!/usr/bin/env python3
"""Runs clang-tidy (the checks in .clang-tidy) over the project's own translation units.

The units are the tracked sources in a build tree's compile_commands.json (every configure writes
it): not Qt's generated moc/rcc units, not third-party code. Each finding in our files is listed
once (a header's finding shows up in every unit that includes it); the exit status is 1 if there
is any, 2 if the tool or the build tree is missing.

Units run in parallel (-j). A unit that comes out clean is remembered in BUILD_DIR/clang-tidy-cache
under a hash of everything its result depends on: the unit preprocessed with its own flags and
comments kept (so every header it includes, and every NOLINT, is in it), every .clang-tidy of the
repository, the flags and the clang-tidy version. A rerun only checks what changed.

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


def cache_key(entry, clang, base_digest):
    """The hash of the unit's preprocessed text (comments kept), flags and configuration; None if
    it does not preprocess (then clang-tidy runs and reports why)."""
    r = subprocess.run(preprocess_args(entry, clang), cwd=entry["directory"], capture_output=True)
    if r.returncode != 0:
        return None, 0
    h = hashlib.sha256(base_digest.encode())
    h.update(" ".join(compile_args(entry)).encode())
    h.update(r.stdout)
    return h.hexdigest(), len(r.stdout)


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


def check_units(args, root, build, units, tracked, cache_dir):
    """Preprocesses and hashes every unit, then runs clang-tidy on the ones not cached clean,
    largest first; returns (findings, checked, cached, failed units)."""
    base = config_digest(root, args.tidy)
    with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        keys = list(pool.map(lambda u: cache_key(u[1], args.clang, base), units))
    todo, cached = [], 0
    for (unit, _), (key, size) in zip(units, keys):
        if key and not args.no_cache and os.path.exists(os.path.join(cache_dir, key)):
            cached += 1
        else:
            todo.append((size, unit, key))
    # The smallest units first: findings (a header's above all) arrive soonest, and a run stopped
    # early has covered the most units, each clean one cached for the next run.
    todo.sort()
    print(f"run_clang_tidy: {len(units)} units, {cached} cached clean, {len(todo)} to check, "
          f"{args.jobs} jobs, {args.tidy}", flush=True)
    found, failed, log = {}, [], open(os.path.join(build, "clang-tidy.log"), "w")
    with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        jobs = {pool.submit(run_tidy, args.tidy, build, unit): (unit, key) for _, unit, key in todo}
        for n, done in enumerate(concurrent.futures.as_completed(jobs), 1):
            unit, key = jobs[done]
            rc, text, seconds = done.result()
            log.write(f"=== {unit} (exit {rc}, {seconds:.0f} s)\n{text}\n")
            log.flush()
            mine = findings_in(text, root, tracked)
            found.update(mine)
            if rc != 0 and not mine:
                failed.append(unit)
            elif not mine and key:
                open(os.path.join(cache_dir, key), "w").write(unit + "\n")
            status = f"{len(mine)} findings" if mine else ("FAILED" if rc != 0 else "clean")
            print(f"[{n}/{len(todo)}] {unit}: {status} ({seconds:.0f} s)", flush=True)
    return found, len(todo), cached, failed


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
