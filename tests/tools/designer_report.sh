#!/usr/bin/env bash
# Everything issue #17's closing note shows, from a build of a clean clone:
#   OUTDIR/guided_steps.png        the guided start's screenshots (box, light, library chair, final)
#   OUTDIR/guided/                 its screenshots, figures.csv, final.png
#   OUTDIR/designer_steps.png      the designer test's step screenshots on one contact sheet
#   OUTDIR/designer/               the screenshots themselves, figures.csv, final.png
#   OUTDIR/library_thumbnails.png  the model library's thumbnails, rendered by Inlay's renderer
#   OUTDIR/library/                the library rebuilt (the .glb files, library.json, thumbnails/)
#   OUTDIR/bench/                  bench_big_photo: open, prepare, first frame against megapixels
#   OUTDIR/timings.md              the timing table: the designer's steps and the big photos
#
#   tests/tools/designer_report.sh BUILD OUTDIR [steps] [library] [bench] [table]
#
# BUILD is a configured build tree (cmake -DBUILD_TESTING=ON); the targets needed are built
# first. Without stage names all four run, one after the other (the library's thumbnails take
# 5 to 17 minutes on a loaded two-core machine, the benchmark a few); naming stages runs only
# those (e.g. in parallel shells, then `table` alone). Environment:
#   INLAY_SHARED_DIR     the shared data (York photos, models; default: ../shared beside the repo)
#   THUMBNAIL_SPP        samples per pixel of the thumbnails (default 64, as the bundled ones)
#   BENCH_MP, BENCH_GESTURES   bench_big_photo's --mp (default 0.3,3,12) and --gestures (5)
set -euo pipefail

if [[ $# -lt 2 ]]; then
  sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
BUILD=$(cd "$1" && pwd)
mkdir -p "$2"
OUT=$(cd "$2" && pwd)
shift 2
REPO=$(cd "$(dirname "$0")/../.." && pwd)
STAGES=("$@")
[[ ${#STAGES[@]} -eq 0 ]] && STAGES=(steps library bench table)
export INLAY_SHARED_DIR=${INLAY_SHARED_DIR:-$(cd "$REPO/.." && pwd)/shared}
wants() { [[ " ${STAGES[*]} " == *" $1 "* ]]; }
say() { echo "designer_report: $*" >&2; }

if [[ ! -f "$INLAY_SHARED_DIR/york/P1020833.jpg" ]]; then
  say "$INLAY_SHARED_DIR/york/P1020833.jpg is missing: set INLAY_SHARED_DIR to the shared data"
  exit 2
fi

targets=()
wants steps && targets+=(studio_guided_test studio_designer_test)
wants library && targets+=(inlay-make-library)
wants bench && targets+=(bench_big_photo)
if [[ ${#targets[@]} -gt 0 ]]; then
  say "building ${targets[*]}"
  nice -n 5 cmake --build "$BUILD" -j2 --target "${targets[@]}" >&2
fi

# A studio test's walk, then its screenshots on one contact sheet: the guided start (the box
# accepted, a light outlined, a library chair dragged in, final, split, export) and the designer
# test's (models inserted, dropped, arranged, final, export, undo and redo all).
walk() {  # walk TEST FUNCTION NAME
  local test=$1 function=$2 name=$3 art="$BUILD/tests/${1%_test}_artifacts"
  say "running $test (a minute or more)"
  (cd "$BUILD/tests" && QT_QPA_PLATFORM=offscreen INLAY_SOURCE_DIR="$REPO" \
    ./"$test" ${function:+"$function"} > "$OUT/${name}_test.log" 2>&1) || {
    say "$test failed: see $OUT/${name}_test.log"
    exit 1
  }
  rm -rf "${OUT:?}/$name"
  mkdir -p "$OUT/$name"
  cp "$art"/[0-9][0-9]_*.png "$art/figures.csv" "$art/final.png" "$OUT/$name/"
  montage -label '%t' "$OUT/$name"/[0-9][0-9]_*.png -tile 4x -geometry 640x400+6+6 \
    -pointsize 15 -background white -depth 8 "$OUT/${name}_steps.png"
  say "wrote $OUT/${name}_steps.png"
}
if wants steps; then
  walk studio_guided_test "" guided
  walk studio_designer_test modelsInsertDropArrangeUndoRedo designer
fi

# The library rebuilt and its thumbnails rendered into the bundled example by Inlay's renderer.
if wants library; then
  say "rendering the library's thumbnails at ${THUMBNAIL_SPP:-64} spp (minutes)"
  rm -rf "$OUT/library"
  nice -n 5 "$BUILD/resources/models/generator/inlay-make-library" --out "$OUT/library" --thumbnails \
    --sheet "$OUT/library_thumbnails.png" --spp "${THUMBNAIL_SPP:-64}" > "$OUT/library.log" 2>&1 || {
    say "inlay-make-library failed: see $OUT/library.log"
    exit 1
  }
  say "wrote $OUT/library_thumbnails.png"
fi

# Open, prepare and first frame against megapixels (its Markdown table goes to OUTDIR too).
if wants bench; then
  say "running bench_big_photo (minutes)"
  INLAY_BENCH_TABLES="$OUT/bench" /usr/bin/python3 "$REPO/tests/bench/bench_big_photo.py" "$BUILD" \
    --out "$OUT/bench" --mp "${BENCH_MP:-0.3,3,12}" --gestures "${BENCH_GESTURES:-5}" \
    > "$OUT/bench.log" 2>&1 || {
    say "bench_big_photo failed: see $OUT/bench.log"
    exit 1
  }
fi

if wants table; then
  /usr/bin/python3 "$REPO/tests/tools/designer_timings.py" "$OUT" > "$OUT/timings.md"
  cat "$OUT/timings.md"
fi
