#!/usr/bin/env bash
# Runs clang-tidy (the checks in .clang-tidy) over the project's own sources in a build tree's
# compile_commands.json (every configure writes it), and lists the findings in our files, each
# once (a header's finding shows up in every unit that includes it). Exits 1 if there is any.
#
# usage: tests/tools/run_clang_tidy.sh [BUILD_DIR (default build)] [REGEX...]
#   REGEX: only the sources whose path matches (e.g. 'modeling/src/mesh'); default all of ours.
# Environment: JOBS (default 2), CLANG_TIDY (default clang-tidy-14).
#
# The whole tree takes about an hour of one core (CGAL and Ceres units are slow to parse);
# it runs at nice 10. The raw output is kept in BUILD_DIR/clang-tidy.log.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
build=${1:-build}
shift || true
tidy=${CLANG_TIDY:-clang-tidy-14}
jobs=${JOBS:-2}
if ! command -v "$tidy" >/dev/null; then
  echo "run_clang_tidy: $tidy not found (apt-get install clang-tidy-14)" >&2
  exit 2
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "run_clang_tidy: $build/compile_commands.json missing: configure first" \
       "(cmake -S . -B $build -G Ninja ...; CMAKE_EXPORT_COMPILE_COMMANDS is on)" >&2
  exit 2
fi

# Our translation units: the tracked sources that the build compiles (not Qt's generated
# moc/rcc/qm units, not third-party code).
mapfile -t units < <(python3 - "$build/compile_commands.json" "$root" "$@" <<'EOF'
import json, os, re, subprocess, sys
db, root, pats = sys.argv[1], sys.argv[2], sys.argv[3:]
tracked = set(subprocess.run(["git", "ls-files", "*.cpp", "*.cc"], cwd=root, capture_output=True,
                             text=True, check=True).stdout.split())
seen = set()
for e in json.load(open(db)):
    f = os.path.relpath(os.path.join(e["directory"], e["file"]), root)
    if f in tracked and f not in seen and (not pats or any(re.search(p, f) for p in pats)):
        seen.add(f)
        print(f)
EOF
)
if [ ${#units[@]} -eq 0 ]; then
  echo "run_clang_tidy: no source of ours matches" >&2
  exit 2
fi
echo "run_clang_tidy: ${#units[@]} units, $jobs jobs, $tidy"

log=$build/clang-tidy.log
: > "$log"
# GCC-only warning flags in the compile commands (-Wshadow=local) would warn as unknown.
printf '%s\n' "${units[@]}" | nice -n 10 xargs -P "$jobs" -I{} \
  sh -c '"$0" -p "$1" --quiet --extra-arg=-Wno-unknown-warning-option "$2" > "$1/clang-tidy.$$.part" 2>&1; cat "$1/clang-tidy.$$.part"; rm -f "$1/clang-tidy.$$.part"' \
  "$tidy" "$build" {} >> "$log" || true

# The findings in tracked files (not generated headers in the build tree), once each.
python3 - "$log" "$root" <<'EOF'
import os, re, subprocess, sys
log, root = sys.argv[1], sys.argv[2]
tracked = set(subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True,
                             check=True).stdout.split())
found = {}
pat = re.compile(r"^(/[^:]+):(\d+):(\d+): (warning|error): (.*) \[([\w.,-]+)\]$")
for line in open(log, errors="replace"):
    m = pat.match(line.rstrip("\n"))
    if not m:
        continue
    f = os.path.relpath(m.group(1), root)
    if f in tracked:
        found.setdefault((f, int(m.group(2)), int(m.group(3)), m.group(6)), m.group(5))
for (f, l, c, check), msg in sorted(found.items()):
    print(f"{f}:{l}:{c}: {msg} [{check}]")
by = {}
for (_, _, _, check) in found:
    by[check] = by.get(check, 0) + 1
for check, n in sorted(by.items(), key=lambda kv: -kv[1]):
    print(f"  {n:4d}  {check}")
print(f"run_clang_tidy: {len(found)} findings in our files (raw output: {log})")
sys.exit(1 if found else 0)
EOF
