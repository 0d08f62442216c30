#!/usr/bin/env bash
# Quick start, command 2: set up, build and run every test through CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh"
cd "$build_dir"
QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "$@"
