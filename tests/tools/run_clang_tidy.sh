#!/usr/bin/env bash
# Runs clang-tidy (the checks in .clang-tidy) over the project's own translation units in a build
# tree's compile_commands.json, in parallel, and lists the findings in our files, each once.
# Exits 1 if there is any. A unit found clean is cached (keyed by its preprocessed text, the
# .clang-tidy files, its flags and the clang-tidy version), so a rerun checks only what changed.
#
# usage: tests/tools/run_clang_tidy.sh [-j N] [--no-cache] [BUILD_DIR (default build)] [REGEX...]
#   REGEX: only the sources whose path matches (e.g. 'modeling/src/mesh'); default all of ours.
# Environment: JOBS (default: the number of cores), CLANG_TIDY (default clang-tidy-14),
#   CLANG (default clang++-14, preprocesses a unit for its cache key).
# On a shared machine run it at low priority: nice -n 15 tests/tools/run_clang_tidy.sh -j2 build
# The raw output is kept in BUILD_DIR/clang-tidy.log, the cache in BUILD_DIR/clang-tidy-cache/.
set -euo pipefail
exec python3 "$(dirname "$0")/run_clang_tidy.py" "$@"
