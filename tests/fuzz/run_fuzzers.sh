#!/usr/bin/env bash
# Builds the fuzz targets with clang + libFuzzer + ASan/UBSan into build-fuzz and runs each for
# a bounded time, one at a time on one job (the machine is shared). The working corpus grows in
# build-fuzz/corpus/<target> (seeded from tests/fuzz/corpus/<target>); crashes, leaks and
# timeouts land in build-fuzz/findings/<target>/. Copy a finding into tests/fuzz/corpus/<target>/
# as crash-<what> once fixed: ctest replays it from then on.
#
# usage: tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET (default 60)] [TARGET...]
# Environment: CMAKE_CXX_COMPILER_LAUNCHER (e.g. ccache), INLAY_WERROR=ON (warnings fail the build,
# as in CI's GCC trees: the Clang build is kept warning-clean with the same flags).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then targets=(scene_file mesh_obj mesh_ply mesh_gltf image); fi

cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON \
  -DBUILD_APP=OFF -DINLAY_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
  ${CMAKE_CXX_COMPILER_LAUNCHER:+-DCMAKE_CXX_COMPILER_LAUNCHER=$CMAKE_CXX_COMPILER_LAUNCHER} \
  ${INLAY_WERROR:+-DINLAY_WERROR=$INLAY_WERROR} >/dev/null
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"

summary=build-fuzz/fuzz_summary.csv
echo "target,seconds,executions,exec_per_s,coverage_edges,features,corpus_files,findings" \
  > "$summary"
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t findings=build-fuzz/findings/$t log=build-fuzz/fuzz_$t.log
  mkdir -p "$corpus" "$findings"
  # Images stay small (the seeds are a few hundred bytes; fuzz_image refuses more than 64 x 64
  # pixels), so long inputs would only be slow, not new.
  max_len=65536
  if [ "$t" = image ]; then max_len=8192; fi
  start=$(date +%s)
  # UBSan findings abort (as in the sanitizer builds); ASan's leak check runs at exit.
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  ASAN_OPTIONS=detect_leaks=1:suppressions=$PWD/tests/sanitizers/asan.supp \
  LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp \
    build-fuzz/tests/fuzz/fuzz_$t -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
      -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$findings/" \
      "$corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1 || true
  elapsed=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  files=$(ls "$corpus" | wc -l)
  found=$(ls "$findings" | wc -l)
  rate=$(( ${execs:-0} / (elapsed > 0 ? elapsed : 1) ))
  echo "$t,$elapsed,${execs:-0},$rate,${cov:-0},${ft:-0},$files,$found" | tee -a "$summary"
done
echo "summary: $summary"
