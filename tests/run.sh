#!/bin/sh
# SPDX-License-Identifier: MIT
# The test runner of `make check`. Runs every test binary, each capability
# profile in its own process on both platforms, and ends with the line
#   N passed, N failed, N skipped
# Usage: tests/run.sh BUILD_DIR
# Environment: STIN_TEST_PLATFORMS (default "egl osmesa"),
#              STIN_TEST_PROFILES (default: every profile of docs/profiles.md).
set -u
B=${1:-build}
LOG=$B/test-log.txt
OUT=$B/test-out
mkdir -p "$OUT"
: > "$LOG"
PLATFORMS=${STIN_TEST_PLATFORMS:-egl osmesa}
PROFILES=${STIN_TEST_PROFILES:-gl11 gl13-combine gl14-shadow gl21 gl33-core gl45-core}
SCENES=$(ls tests/scenes/*.json)

# Runs one command; its PASS/FAIL/SKIP lines (or TAP lines) count. A command
# that exits non-zero without reporting a failure counts as one failure.
run() {
    name=$1
    shift
    tmp=$OUT/run.$$
    "$@" > "$tmp" 2>&1
    rc=$?
    # cmocka TAP -> PASS/FAIL lines
    sed -e "s/^ok [0-9]* - \(.*\)/PASS $name: \1/" \
        -e "s/^not ok [0-9]* - \(.*\)/FAIL $name: \1/" \
        -e "s/^ok [0-9]* # SKIP \(.*\)/SKIP $name: \1/" "$tmp" | tee -a "$LOG" | grep -E '^(PASS|FAIL|SKIP) '
    if [ $rc -ne 0 ] && ! grep -q '^\(not ok\|FAIL\) ' "$tmp"; then
        echo "FAIL $name: exited with status $rc" | tee -a "$LOG"
        tail -n 20 "$tmp" | sed 's/^/    /'
    fi
    grep -E '^(#|    )' "$tmp" | grep -iE 'error|fail|assert' | head -n 20 | sed 's/^/    /'
    rm -f "$tmp"
}

export CMOCKA_MESSAGE_OUTPUT=TAP
# Driver-internal leaks (OSMesa, EGL) are not ours; see docs/testing.md.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
for t in "$B"/tests/test_*; do
    [ -x "$t" ] || continue
    case $t in
        *test_noheap*) run "$(basename "$t")" "$t" "$B/libstin.a" ;;
        *) run "$(basename "$t")" "$t" ;;
    esac
done

for plat in $PLATFORMS; do
    for prof in $PROFILES; do
        run "image" "$B/stin-imagetest" --profile "$prof" --platform "$plat" --out "$OUT" $SCENES
    done
done

run "cli" sh tests/cli/test_render.sh "$B/stin-render"
run "install" sh tests/cli/test_install.sh
run "licence" sh tests/cli/test_licence.sh
run "readme" sh tests/cli/test_readme.sh
run "bench" sh tests/cli/test_bench.sh "$B/stin-bench" "$OUT/bench-quick.txt"

awk '/^PASS /{p++} /^FAIL /{f++} /^SKIP /{s++} END {printf "%d passed, %d failed, %d skipped\n", p, f, s; exit f > 0}' "$LOG"
