#!/usr/bin/env bash
# Installs every build, test and tool dependency of Inlay from Debian 12's packages.
# Idempotent; run as root (or through sudo). Used by the README's two commands and by CI.
set -euo pipefail
PKGS=(
  build-essential cmake ninja-build pkg-config git
  qt6-base-dev libqt6opengl6-dev qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools qt6-translations-l10n
  libopenmesh-dev libcgal-dev libembree-dev libopencv-dev libopencv-contrib-dev libceres-dev
  libopenimageio-dev openimageio-tools libosd-dev libeigen3-dev libtbb-dev libassimp-dev
  nlohmann-json3-dev zlib1g-dev libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth
  desktop-file-utils   # desktop-file-validate: the .desktop entry (tests/install_smoke_test.sh)
  clang libclang-rt-14-dev   # tests/fuzz/run_fuzzers.sh (libFuzzer)
  clang-format-14            # tests/tools/check_format.sh (CI's format check)
  python3 python3-numpy python3-opencv python3-openimageio python3-scipy python3-matplotlib
)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
