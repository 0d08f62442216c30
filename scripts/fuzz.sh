#!/bin/sh
# One libFuzzer target over its committed seeds (tests/fuzz/corpus/NAME), new inputs kept in
# WORK/corpus and findings (crash-*, oom-*, timeout-*) in WORK/findings. CTest runs it with
# -runs=100000 per target (tests/fuzz/CMakeLists.txt); a long run, e.g. an hour on 2 cores:
#   scripts/fuzz.sh build/tests/fuzz/project/fuzz_config_text tests/fuzz/corpus/config_text \
#       /tmp/fuzz-config -max_total_time=3600 -jobs=2 -workers=2
# A finding: fix it, then copy the file from WORK/findings into tests/fuzz/corpus/NAME.
# usage: scripts/fuzz.sh FUZZER SEEDS WORK [libFuzzer options...]
set -eu
if [ $# -lt 3 ]; then
    sed -n 's/^# \{0,1\}//p' "$0" | sed -n '/^usage/p' >&2
    exit 2
fi
bin=$1
seeds=$2
work=$3
shift 3
mkdir -p "$work/corpus" "$work/findings"
exec "$bin" -artifact_prefix="$work/findings/" -max_len=20000 -rss_limit_mb=2048 \
    -print_final_stats=1 "$@" "$work/corpus" "$seeds"
