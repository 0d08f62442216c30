#!/usr/bin/env bash
# Screenshot of the console mid-test: starts `hsmu --start CONFIG` (default paper-condition-3)
# under a virtual X server when no display exists, lets it run SECONDS (default 4) of wall
# time at real-time pacing, grabs the main window into FILE (default out/console.png) and quits.
#   scripts/screenshot.sh [FILE] [SECONDS] [CONFIG]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
hsmu="${HSMU_EXE:-${HSMU_BUILD_DIR:-$here/build}/bin/hsmu}"
file="${1:-$here/out/console.png}"
seconds="${2:-4}"
config="${3:-paper-condition-3}"
mkdir -p "$(dirname "$file")"
args=(--start "$config" --screenshot "$file" --screenshot-after "$seconds")
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  "$hsmu" "${args[@]}"
else
  xvfb-run -a -s "-screen 0 1600x1000x24" "$hsmu" "${args[@]}"
fi
echo "$file"
