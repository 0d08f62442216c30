#!/usr/bin/env bash
# Quick start, command 2 (and CI, .ci/run): set up, build and run every test through CTest, then
# stage 2, the core and comms tests under ASan + UBSan (scripts/test-sanitizers.sh; skip it with
# HSMU_SKIP_SANITIZERS=1). Each stage prints its wall and CPU time to stderr.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_BUILD_DIR:-$here/build}"

TIMEFORMAT="setup and build: %R s wall, %U s user + %S s sys"
time "$here/scripts/setup.sh"

TIMEFORMAT="tests: %R s wall, %U s user + %S s sys"
time (cd "$build_dir" &&
      QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "$@")

if [ "${HSMU_SKIP_SANITIZERS:-0}" != 1 ]; then
  "$here/scripts/test-sanitizers.sh"
fi
