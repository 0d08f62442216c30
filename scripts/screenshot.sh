#!/usr/bin/env bash
# Screenshots of the console, for a look before a release (issue 6). Writes into OUTDIR
# (default out/screenshots):
#   console-builtin.png  the main window mid-test, built-in virtual controller
#   console-tcp.png      the main window mid-test over the native TCP link to a real
#                        hsmu-controller (started here on a free port, stopped afterwards)
#   replay.png           the replay window playing the record of a short headless run
# Each window runs SECONDS (default 5) of wall time at real-time pacing before the grab.
# Without a display the windows run under a virtual X server (xvfb-run).
#   scripts/screenshot.sh [OUTDIR] [SECONDS] [CONFIG]      (CONFIG default paper-condition-3)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${HSMU_BUILD_DIR:-$here/build}/bin"
hsmu="${HSMU_EXE:-$bin/hsmu}"
controller_exe="${HSMU_CONTROLLER_EXE:-$bin/hsmu-controller}"
outdir="${1:-$here/out/screenshots}"
seconds="${2:-5}"
config="${3:-paper-condition-3}"
mkdir -p "$outdir"
outdir="$(cd "$outdir" && pwd)"

# hsmu-controller takes a configuration file: a preset name becomes its file.
config_file="$config"
[ -f "$config_file" ] || config_file="$here/resources/presets/$config.json"

gui() { # run a GUI command, under xvfb-run when there is no display
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    "$@"
  else
    xvfb-run -a -s "-screen 0 1600x1000x24" "$@"
  fi
}

# 1. The console with the built-in controller.
gui "$hsmu" --start "$config" --screenshot "$outdir/console-builtin.png" \
  --screenshot-after "$seconds"

# 2. The console over TCP to a real hsmu-controller on a free port.
log="$(mktemp)"
"$controller_exe" --config "$config_file" --port 0 >"$log" 2>&1 &
controller_pid=$!
trap 'kill "$controller_pid" 2>/dev/null || true; rm -f "$log"' EXIT
port=""
for _ in $(seq 1 100); do
  port="$(sed -n 's/.*listening on [0-9.]*:\([0-9]*\).*/\1/p' "$log" | head -n 1)"
  [ -n "$port" ] && break
  kill -0 "$controller_pid" 2>/dev/null || { cat "$log" >&2; exit 1; }
  sleep 0.1
done
[ -n "$port" ] || { echo "screenshot.sh: hsmu-controller did not report its port" >&2; exit 1; }
gui "$hsmu" --start "$config" --controller "tcp://127.0.0.1:$port" \
  --screenshot "$outdir/console-tcp.png" --screenshot-after "$seconds"
kill "$controller_pid" 2>/dev/null || true
wait "$controller_pid" 2>/dev/null || true

# 3. The replay window on the record of a short headless run.
run_dir="$(mktemp -d)"
"$hsmu" run "$config" --duration 12 --out "$run_dir" >/dev/null 2>&1
gui "$hsmu" replay "$run_dir/record.h5" --play --speed 2 \
  --screenshot "$outdir/replay.png" --screenshot-after "$seconds"
rm -rf "$run_dir"

ls -1 "$outdir"/console-builtin.png "$outdir"/console-tcp.png "$outdir"/replay.png
