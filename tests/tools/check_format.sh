#!/usr/bin/env bash
# Checks that every C++ file of the project (the .cpp/.h files git tracks) is formatted as
# .clang-format says. Lists each file that is not and exits 1; exits 0 when all are.
#
# usage: tests/tools/check_format.sh          check (CI runs this, see .ci/run)
#        tests/tools/check_format.sh --fix    format those files in place
#        tests/tools/check_format.sh --diff   show what would change
#
# Needs clang-format 14 (Debian 12: apt-get install clang-format-14); another major version
# formats a few constructs differently, so it is refused rather than trusted.
set -euo pipefail
cd "$(dirname "$0")/../.."
mode=${1:-check}

cf=""
for c in clang-format-14 clang-format; do
  if command -v "$c" >/dev/null && "$c" --version | grep -q 'version 14\.'; then cf=$c; break; fi
done
if [ -z "$cf" ]; then
  echo "check_format: clang-format 14 not found (apt-get install clang-format-14)" >&2
  exit 2
fi

mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.hpp' '*.cc')
bad=()
for f in "${files[@]}"; do
  if ! "$cf" --style=file "$f" | cmp -s - "$f"; then bad+=("$f"); fi
done

if [ ${#bad[@]} -eq 0 ]; then
  echo "check_format: all ${#files[@]} C++ files are formatted"
  exit 0
fi
case "$mode" in
  --fix)
    "$cf" --style=file -i "${bad[@]}"
    echo "check_format: formatted ${#bad[@]} files"
    exit 0 ;;
  --diff)
    for f in "${bad[@]}"; do "$cf" --style=file "$f" | diff -u --label "$f" --label "$f (formatted)" "$f" - || true; done ;;
esac
echo "check_format: ${#bad[@]} of ${#files[@]} C++ files are not formatted as .clang-format says:" >&2
printf '  %s\n' "${bad[@]}" >&2
echo "check_format: run tests/tools/check_format.sh --fix (clang-format-14), or --diff to see the changes" >&2
exit 1
