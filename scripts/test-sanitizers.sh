#!/usr/bin/env bash
# CI stage 2 (called by scripts/test.sh; skip with HSMU_SKIP_SANITIZERS=1; runs alone too): the
# core and comms libraries, hsmu-controller and their tests built with AddressSanitizer +
# UndefinedBehaviorSanitizer (-DHSMU_SANITIZE=address,undefined, -O1 -g0) in build-address-undefined/,
# no GUI, no benchmarks, and every core and comms test run in it, except the tests labelled
# "no-sanitizers" (their purpose conflicts with the instrumentation; each label has a comment
# saying why) and, unless HSMU_SANITIZE_ALL=1, the ones labelled "sanitizers-slow" (long
# identifications on the shared records whose code the shorter tests already cover).
# HSMU_SANITIZE=thread runs scripts/test-tsan.sh instead (ThreadSanitizer, the threaded tests).
#
# Any finding fails the stage: the code is built with -fno-sanitize-recover=all and the runtime
# with halt_on_error=1, so the process that made it exits non-zero (its test fails), and every
# ASan / LSan report is also written under <build>/sanitizer-reports/, which must stay empty: a
# report from a child process (hsmu-controller started by a test) fails the stage even where the
# test tolerated the child's exit. UBSan reports ignore log_path in GCC 12's combined runtime
# (checked: they always go to stderr), so a UBSan finding in a child shows only as the child's
# exit status 1. Times of both parts go to stderr (docs/benchmarks.md, "CI stages").
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sanitize="${HSMU_SANITIZE:-address,undefined}"
if [[ "$sanitize" == *thread* ]]; then
  exec "$here/scripts/test-tsan.sh" "$@"
fi
build_dir="${HSMU_SANITIZE_BUILD_DIR:-$here/build-${sanitize//,/-}}"
jobs="$(nproc 2>/dev/null || echo 2)"

regex='^test_'
exclude='no-sanitizers'
[ "${HSMU_SANITIZE_ALL:-0}" = 1 ] || exclude='no-sanitizers|sanitizers-slow'

TIMEFORMAT="sanitizers ($sanitize): build %R s wall, %U s user + %S s sys"
time {
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DHSMU_SANITIZE="$sanitize" \
    -DHSMU_BUILD_GUI=OFF -DHSMU_BUILD_BENCHMARKS=OFF -DHSMU_BUILD_TESTS=ON >/dev/null
  cmake --build "$build_dir" -j"$jobs"
}

reports="$build_dir/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
# Leaks are findings too; scripts/lsan.supp lists the libraries' one-time allocations only.
common="halt_on_error=1:log_path=$reports/report"
export ASAN_OPTIONS="$common:detect_leaks=${HSMU_DETECT_LEAKS:-1}:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="$common:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=0"

status=0
TIMEFORMAT="sanitizers ($sanitize): tests %R s wall, %U s user + %S s sys"
time {
  (cd "$build_dir" && QT_QPA_PLATFORM=offscreen \
     ctest --output-on-failure -j"$jobs" -R "$regex" -LE "$exclude" "$@") || status=$?
}
if compgen -G "$reports/report*" >/dev/null; then
  echo "sanitizers ($sanitize): findings (each file one process):" >&2
  for f in "$reports"/report*; do
    echo "==== $f" >&2
    cat "$f" >&2
  done
  status=1
fi
exit "$status"
