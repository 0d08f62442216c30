#!/usr/bin/env bash
# Quick start, command 1: set up, build and run the main job: the paper's frame, test
# condition 3, on the built-in virtual specimen. In a window when a display exists, otherwise
# headless, printing the summary and writing PNG plots to ./out/paper-condition-3.
# The El Centro 1940 record is used when ../shared/data holds it, else the built-in record.
# Only what it runs is built (hsmu, hsmu-cli, hsmu-console, hsmu-controller and their libraries): the
# tests and the benchmarks are scripts/test.sh's.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh" hsmu hsmu-cli hsmu-console hsmu-controller

hsmu="$build_dir/bin/hsmu"
gm_args=()
elcentro="$here/../shared/data/elcentro/elCentro_Peknold_NS_0.02s.AT2"
if [ -f "$elcentro" ]; then
  gm_args=(--ground-motion "$elcentro")
fi

if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$hsmu" --start paper-condition-3 "${gm_args[@]}" "$@"
fi
out="$here/out/paper-condition-3"
"$hsmu" run paper-condition-3 --out "$out" --plots "${gm_args[@]}" "$@"
echo "plots and records: $out" >&2
ls -1 "$out" >&2
