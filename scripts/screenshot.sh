#!/usr/bin/env bash
# Screenshots of the console, for a look before a release (issues 6, 16). Writes into OUTDIR
# (default out/screenshots), for each language LANG of HSMU_SCREENSHOT_LANGS (default
# "en es zh_CN"):
#   console-builtin-LANG.png  the main window mid-test, built-in virtual controller
#   console-tcp-LANG.png      the main window mid-test over the native TCP link to a real
#                             hsmu-controller (started here on a free port, stopped afterwards)
#   replay-LANG.png           the replay window playing the record of a short headless run
# Each window is HSMU_SCREENSHOT_SIZE (default 1280x720, the smallest size the layout is
# designed for) and runs SECONDS (default 5) of wall time at real-time pacing before the grab.
# The windows run with fresh settings (a temporary home: the language is LANG's, nothing of
# the user's settings or record folder is touched). Without a display they run under a
# virtual X server (xvfb-run) of that size.
#   scripts/screenshot.sh [OUTDIR] [SECONDS] [CONFIG]      (CONFIG default paper-condition-3)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${HSMU_BUILD_DIR:-$here/build}/bin"
hsmu="${HSMU_EXE:-$bin/hsmu}"
controller_exe="${HSMU_CONTROLLER_EXE:-$bin/hsmu-controller}"
outdir="${1:-$here/out/screenshots}"
seconds="${2:-5}"
config="${3:-paper-condition-3}"
size="${HSMU_SCREENSHOT_SIZE:-1280x720}"
langs="${HSMU_SCREENSHOT_LANGS:-en es zh_CN}"
mkdir -p "$outdir"
outdir="$(cd "$outdir" && pwd)"
home="$(mktemp -d)" # fresh settings, record folder and state for the windows
export XDG_CONFIG_HOME="$home/config" XDG_DATA_HOME="$home/data" XDG_STATE_HOME="$home/state"

# hsmu-controller takes a configuration file: a preset name becomes its file.
config_file="$config"
[ -f "$config_file" ] || config_file="$here/resources/presets/$config.json"

gui() { # run a GUI command in language $lang, under xvfb-run when there is no display
  local locale="$lang.UTF-8"
  [ "$lang" = en ] && locale=en_US.UTF-8
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    LC_ALL="$locale" LANG="$locale" "$@" -geometry "$size+0+0"
  else
    LC_ALL="$locale" LANG="$locale" xvfb-run -a -s "-screen 0 ${size}x24" "$@" \
      -geometry "$size+0+0"
  fi
}
shots=()

# 1. The console with the built-in controller.
for lang in $langs; do
  gui "$hsmu" --start "$config" --screenshot "$outdir/console-builtin-$lang.png" \
    --screenshot-after "$seconds"
  shots+=("$outdir/console-builtin-$lang.png")
done

# 2. The console over TCP to a real hsmu-controller on a free port (a fresh controller for
#    each language, so each window starts from a virgin specimen).
log="$(mktemp)"
controller_pid=""
trap 'kill "$controller_pid" 2>/dev/null || true; rm -rf "$log" "$home"' EXIT
for lang in $langs; do
  "$controller_exe" --config "$config_file" --port 0 --no-state-file >"$log" 2>&1 &
  controller_pid=$!
  port=""
  for _ in $(seq 1 100); do
    port="$(sed -n 's/.*listening on [0-9.]*:\([0-9]*\).*/\1/p' "$log" | head -n 1)"
    [ -n "$port" ] && break
    kill -0 "$controller_pid" 2>/dev/null || { cat "$log" >&2; exit 1; }
    sleep 0.1
  done
  [ -n "$port" ] || { echo "screenshot.sh: hsmu-controller did not report its port" >&2; exit 1; }
  gui "$hsmu" --start "$config" --controller "tcp://127.0.0.1:$port" \
    --screenshot "$outdir/console-tcp-$lang.png" --screenshot-after "$seconds"
  shots+=("$outdir/console-tcp-$lang.png")
  kill "$controller_pid" 2>/dev/null || true
  wait "$controller_pid" 2>/dev/null || true
done

# 3. The replay window on the record of a short headless run.
run_dir="$(mktemp -d)"
"$hsmu" run "$config" --duration 12 --out "$run_dir" >/dev/null 2>&1
for lang in $langs; do
  gui "$hsmu" replay "$run_dir/record.h5" --play --speed 2 \
    --screenshot "$outdir/replay-$lang.png" --screenshot-after "$seconds"
  shots+=("$outdir/replay-$lang.png")
done
rm -rf "$run_dir"

ls -1 "${shots[@]}"
