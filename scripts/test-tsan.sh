#!/usr/bin/env bash
# ThreadSanitizer run of the threaded tests (issue 26 item 5; docs/security.md "ThreadSanitizer").
# Not a CI stage: its cost is measured there (a weekly-style run, or before merging a change to a
# thread). Usage: scripts/test-tsan.sh [extra ctest arguments]
#
# Builds in build-thread/ (its own directory; ccache when installed) with -DHSMU_SANITIZE=thread
# (-O1 -g0, -fno-sanitize-recover=all: every report fails its test), no GUI, no benchmarks, and
# only what the threaded tests need: hsmu-controller and the test executables selected by the
# regex below. Then runs them through CTest, except the tests labelled "no-sanitizers" and
# "sanitizers-slow" (HSMU_SANITIZE_ALL=1 keeps the slow ones).
#
# The threads covered: the link thread (comms/link LinkClient: every test_comms_* test that
# connects, the TLS ones included, and hsmu-controller itself, instrumented, started by them),
# the controller's sessions and RTHS server, the updating worker (core/updating ScheduledJob,
# the robust and pinching UKFs that run their calibrations on it), the record thread
# (core/record RecordThread, RecordWriter's hand-over, the crash helper) and the test session.
# Not covered: the console worker (gui/app TestWorker on a QThread): Qt is not built with TSan,
# and Qt 6's QMutex and queued connections synchronise through futexes TSan cannot see, so every
# hand-over through a signal would be reported as a race (docs/security.md says how it is
# tested instead).
#
# Reports: every TSan report goes to <build>/sanitizer-reports/ (log_path) and fails the script,
# even one from a child process whose exit a test tolerated. Suppressions: scripts/tsan.supp
# (uninstrumented third-party code only, each line with its reason). Times go to stderr.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${HSMU_TSAN_BUILD_DIR:-$here/build-thread}"
jobs="${HSMU_TSAN_JOBS:-$(nproc 2>/dev/null || echo 2)}"

regex='^test_(comms_|record_(thread|crash|round_trip)$|updating_(scheduledjob|robustukf|pinchingukf)$|session_)'
exclude='no-sanitizers'
[ "${HSMU_SANITIZE_ALL:-0}" = 1 ] || exclude='no-sanitizers|sanitizers-slow'

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

TIMEFORMAT="tsan: build %R s wall, %U s user + %S s sys"
time {
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DHSMU_SANITIZE=thread \
    -DHSMU_BUILD_GUI=OFF -DHSMU_BUILD_BENCHMARKS=OFF -DHSMU_BUILD_PYTHON=OFF \
    -DHSMU_BUILD_TESTS=ON "${launcher[@]}" >/dev/null
  # The selected tests' executables (a CTest test here is named after its target).
  mapfile -t targets < <(cd "$build_dir" && ctest -N -R "$regex" -LE "$exclude" |
                         sed -n 's/^ *Test *#[0-9]*: *\([A-Za-z0-9_]*\)$/\1/p')
  if [ "${#targets[@]}" = 0 ]; then
    echo "tsan: no test matches $regex" >&2
    exit 1
  fi
  echo "tsan: ${#targets[@]} tests: ${targets[*]}" >&2
  cmake --build "$build_dir" -j"$jobs" --target hsmu-controller record_writer_helper "${targets[@]}"
}

reports="$build_dir/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
# die_after_fork=0: the tests start hsmu-controller through QProcess (a fork of a threaded
# process), which TSan otherwise refuses ("starting new threads after multi-threaded fork").
export TSAN_OPTIONS="halt_on_error=1:log_path=$reports/report:second_deadlock_stack=1:die_after_fork=0:suppressions=$here/scripts/tsan.supp"

status=0
TIMEFORMAT="tsan: tests %R s wall, %U s user + %S s sys"
time {
  (cd "$build_dir" && QT_QPA_PLATFORM=offscreen \
     ctest --output-on-failure -j"$jobs" -R "$regex" -LE "$exclude" "$@") || status=$?
}
if compgen -G "$reports/report*" >/dev/null; then
  echo "tsan: findings (each file one process):" >&2
  for f in "$reports"/report*; do
    echo "==== $f" >&2
    cat "$f" >&2
  done
  status=1
fi
exit "$status"
