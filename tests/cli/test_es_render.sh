#!/bin/sh
# SPDX-License-Identifier: MIT
# stin-render on the OpenGL ES profiles (egl): every repository scene
# (tests/scenes/*.json, not bad/) renders with exit 0 on every ES profile
# (es20's derivative-free paths included), each profile in one process
# (stin-render takes several scenes with --no-output) at 24x16, and
# --verbose names the context's version string.
# Prints PASS/FAIL lines. Usage: test_es_render.sh path/to/stin-render
set -u
R=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
SCENES=$(ls tests/scenes/*.json)
COUNT=$(echo "$SCENES" | wc -l)

check() { # name, condition result (0 = pass), detail
    if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1: $3"; fi
}

for p in ${STIN_ES_RENDER_PROFILES:-es20 es20-ext es30 es31 es32}; do
    ver=$(echo "$p" | sed -n 's/^es\([0-9]\)\([0-9]\).*/\1.\2/p')
    # shellcheck disable=SC2086
    LP_NUM_THREADS=${LP_NUM_THREADS:-0} "$R" $SCENES --profile "$p" --size 24x16 --no-output \
        --verbose > "$T/$p.txt" 2>&1
    rc=$?
    ok=$(grep -c '^scene .*: exit 0$' "$T/$p.txt")
    bad=$(grep '^scene .*: exit [1-9]' "$T/$p.txt" | sed 's/^scene //' | tr '\n' ' ')
    check "es-render $p: all $COUNT scenes exit 0" $([ $rc -eq 0 ] && [ "$ok" -eq "$COUNT" ] &&
        echo 0 || echo 1) "exit $rc, $ok of $COUNT: not $bad$(tail -n 2 "$T/$p.txt" | tr '\n' ' ')"
    check "es-render $p: --verbose names \"OpenGL ES $ver Mesa\"" \
        $(grep -q "\"OpenGL ES $ver Mesa" "$T/$p.txt" && echo 0 || echo 1) \
        "no version string in the info lines"
done
