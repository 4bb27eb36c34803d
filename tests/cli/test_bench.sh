#!/bin/sh
# SPDX-License-Identifier: MIT
# stin-bench smoke test: `stin-bench --quick` runs every section at a tiny
# size and must exit 0 and print its goal line, so that the bench cannot
# break silently between benchmark runs; and --vdsm-goal must print the
# full chain's and the volumes' rows only. Prints a PASS/FAIL line each.
# Usage: test_bench.sh path/to/stin-bench [OUTPUT_FILE]  (stdout and stderr kept there)
set -u
BENCH=$1
LOG=${2:-$(mktemp)}
[ $# -ge 2 ] || trap 'rm -f "$LOG"' EXIT

fails=0
"$BENCH" --quick > "$LOG" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q '^goal ' "$LOG"; then
    echo "PASS bench: quick smoke (exit 0, goal line printed)"
else
    goal=$(grep -c '^goal ' "$LOG")
    echo "FAIL bench: quick smoke (exit $rc, $goal goal line(s)); the output ends:"
    tail -n 15 "$LOG" | sed 's/^/    /'
    fails=1
fi

# appended to the same file, checked on its own
out=$("$BENCH" --vdsm --vdsm-goal --quick --tier gl4 2>&1)
rc=$?
printf '\n%s\n' "$out" >> "$LOG"
rows=$(printf '%s\n' "$out" | grep -c '^| ')
if printf '%s\n' "$out" | grep -q 'SKIP (the context lacks'; then
    echo "SKIP bench: --vdsm-goal (no gl4 here)"
elif [ $rc -eq 0 ] && printf '%s\n' "$out" | grep -q '^| SP+EP+SM+DC+DT | [0-9]' &&
     printf '%s\n' "$out" | grep -q '^| volume |' &&
     [ "$rows" -eq 3 ]; then
    echo "PASS bench: --vdsm-goal prints the full chain and the volumes only"
else
    echo "FAIL bench: --vdsm-goal (exit $rc, $rows table lines, want 3: the header and two rows)"
    printf '%s\n' "$out" | tail -n 15 | sed 's/^/    /'
    fails=1
fi
exit $fails
