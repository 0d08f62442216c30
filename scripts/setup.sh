#!/usr/bin/env bash
# Install every Debian package the build, the tests and the screenshots need (idempotent; as
# root or through sudo), then configure and build into ./build (or $HSMU_BUILD_DIR): every
# target, or only the targets given as arguments (scripts/run.sh: the programs it runs and
# their libraries, no test or benchmark).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_BUILD_DIR:-$here/build}"

packages=(
  build-essential cmake pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-svg-dev libqt6opengl6-dev
  libqcustomplot-dev libqcustomplot2.1-qt6
  libeigen3-dev libboost-dev libboost-system-dev libhdf5-dev hdf5-tools nlohmann-json3-dev
  libssl-dev openssl  # tls:// links (OpenSSL 3) and scripts/hsmu-certs.sh
  libbenchmark-dev xvfb xauth
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module hsmu (docs/python.md)
  fonts-wqy-microhei  # Chinese glyphs for the zh_CN console and its screenshots
  clang libclang-rt-14-dev  # the libFuzzer targets (tests/fuzz), run by ctest when present
)
# The real OpenSees 3.8 + OpenFresco 2.8 the pairing tests run (../shared/tools/opensees, present
# in CI, absent on a user's machine): its runtime libraries.
if [ -d "$here/../shared/tools/opensees" ]; then
  packages+=(tcl8.6 liblapack3 libblas3 libgfortran5 libssl3)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all Debian packages present" >&2
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do
  targets+=(--target "$t")
done
cmake --build "$build_dir" -j"$jobs" "${targets[@]}"
echo "setup: built into $build_dir" >&2
