#!/usr/bin/env bash
# Quick start, command 2: set up, build and run every test through CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh"
cd "$build_dir"
QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "$@"

# Stage 2 (opt-in until its CI time is measured): core and comms tests under ASan + UBSan
# (scripts/test-sanitizers.sh).
if [ "${HSMU_SANITIZERS:-0}" = 1 ]; then
  "$here/scripts/test-sanitizers.sh"
fi
