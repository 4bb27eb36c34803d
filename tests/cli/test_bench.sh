#!/bin/sh
# SPDX-License-Identifier: MIT
# stin-bench smoke test: `stin-bench --quick` runs every section at a tiny
# size and must exit 0 and print its goal line, so that the bench cannot
# break silently between benchmark runs. Prints a PASS/FAIL line.
# Usage: test_bench.sh path/to/stin-bench [OUTPUT_FILE]  (stdout and stderr kept there)
set -u
BENCH=$1
LOG=${2:-$(mktemp)}
[ $# -ge 2 ] || trap 'rm -f "$LOG"' EXIT

"$BENCH" --quick > "$LOG" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q '^goal ' "$LOG"; then
    echo "PASS bench: quick smoke (exit 0, goal line printed)"
    exit 0
fi
goal=$(grep -c '^goal ' "$LOG")
echo "FAIL bench: quick smoke (exit $rc, $goal goal line(s)); the output ends:"
tail -n 15 "$LOG" | sed 's/^/    /'
exit 1
