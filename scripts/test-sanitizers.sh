#!/usr/bin/env bash
# CI stage: the core and comms tests under AddressSanitizer + UndefinedBehaviorSanitizer
# (HSMU_SANITIZE=address,undefined), in a separate build directory without the GUI and the
# benchmarks. Called by scripts/test.sh (skip with HSMU_SKIP_SANITIZERS=1); runs alone too.
# HSMU_SANITIZE=thread selects ThreadSanitizer for the threaded tests instead.
# A finding fails the test that made it (halt_on_error), so CTest fails the stage.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sanitize="${HSMU_SANITIZE:-address,undefined}"
build_dir="${HSMU_SANITIZE_BUILD_DIR:-$here/build-${sanitize//,/-}}"
jobs="$(nproc 2>/dev/null || echo 2)"
start=$(date +%s)

# The subset that fits the CI budget: every core and comms test (the GUI is not built here;
# its tests run in the normal build). Under TSan: the tests with threads of their own.
if [[ "$sanitize" == *thread* ]]; then
  regex='^test_(comms_|record_crash|record_round_trip)'
else
  regex='^test_'
fi

cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHSMU_SANITIZE="$sanitize" \
  -DHSMU_BUILD_GUI=OFF -DHSMU_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build_dir" -j"$jobs"
built=$(date +%s)

# Leak checking is off: Qt Test, fontconfig and HDF5 keep one-time allocations until exit
# (scripts/lsan.supp lists them; turn it on with HSMU_DETECT_LEAKS=1).
export ASAN_OPTIONS="detect_leaks=${HSMU_DETECT_LEAKS:-0}:halt_on_error=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# die_after_fork=0: the tests start hsmu-controller through QProcess (a fork of a threaded
# process), which TSan otherwise refuses ("starting new threads after multi-threaded fork").
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:die_after_fork=0"
export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=0"
cd "$build_dir"
QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs" -R "$regex" --timeout 900
echo "sanitizers ($sanitize): build $((built - start)) s, tests $(( $(date +%s) - built )) s" >&2
