#!/bin/sh
# SPDX-License-Identifier: MIT
# make fuzz: each libFuzzer target for SECONDS, seeded from the committed
# corpus and the example and bad scenes; new inputs go to BUILD/fuzz/corpus-*,
# crashes to BUILD/fuzz/crashes/ (copy each into tests/fuzz/crashes/TARGET/
# once fixed: make check replays it from then on). Ends with one summary line
# per target: executions, coverage (cov/ft) and crashes.
# Usage: tests/fuzz/run.sh BUILD_DIR SECONDS
set -u
B=${1:-build}
SECONDS_EACH=${2:-60}
mkdir -p "$B/fuzz/corpus-scene" "$B/fuzz/corpus-files" "$B/fuzz/crashes"
status=0
for target in scene files; do
    case $target in
        scene) seeds="tests/fuzz/corpus/scene tests/fuzz/crashes/scene tests/scenes tests/scenes/bad"
               extra="-dict=tests/fuzz/scene.dict -max_len=8192" ;;
        files) seeds="tests/fuzz/corpus/files tests/fuzz/crashes/files"
               extra="-max_len=16384" ;;
    esac
    existing=""
    for d in $seeds; do [ -d "$d" ] && existing="$existing $d"; done
    log=$B/fuzz/$target.log
    before=$(ls "$B/fuzz/crashes" | wc -l)
    # shellcheck disable=SC2086 # one word per directory and flag
    "$B/fuzz/fuzz_$target" -max_total_time="$SECONDS_EACH" -timeout=30 -rss_limit_mb=4096 \
        -print_final_stats=1 -artifact_prefix="$B/fuzz/crashes/$target-" $extra \
        "$B/fuzz/corpus-$target" $existing > "$log" 2>&1
    rc=$?
    crashes=$(( $(ls "$B/fuzz/crashes" | wc -l) - before ))
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
    cov=$(grep -E '^#[0-9]+' "$log" | tail -n 1 | grep -oE 'cov: [0-9]+ ft: [0-9]+')
    echo "fuzz_$target: ${runs:-?} executions in ${SECONDS_EACH} s, ${cov:-cov: ?}, $crashes crash(es) (log: $log)"
    [ $rc -ne 0 ] || [ "$crashes" -ne 0 ] && status=1
done
exit $status
