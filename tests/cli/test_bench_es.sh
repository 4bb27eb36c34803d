#!/bin/sh
# SPDX-License-Identifier: MIT
# stin-bench on OpenGL ES: `--raw --quick --profile es30` (and es32) must run
# the raw loop's programs as GLSL ES and pass the bench's agreement check (one
# stin frame and one raw frame within 2/255), which is what makes its ratios
# mean anything; and with a raw lit.frag that draws something else, the same
# run must fail on that check, so the check is known to bite. Prints a
# PASS/FAIL (or SKIP) line each; es30 and es32 run two tiers each. Run from the repository root.
# Usage: test_bench_es.sh path/to/stin-bench
set -u
BENCH=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0

# $1 profile, $2 the tier rows wanted (table lines of spheres-18k)
agree() {
    out=$("$BENCH" --raw --quick --profile "$1" 2>&1)
    rc=$?
    rows=$(printf '%s\n' "$out" | grep -c '^| spheres-18k | [0-9]')
    es=$(printf '%s\n' "$out" | grep -c '^### gl[24] (.*as GLSL ES')
    if printf '%s\n' "$out" | grep -q 'no GL context'; then
        echo "SKIP bench-es: $1 (no OpenGL ES context here)"
    elif [ $rc -eq 0 ] && [ "$rows" -eq "$2" ] && [ "$es" -eq "$2" ] &&
         printf '%s\n' "$out" | grep -q '^goal stin / raw'; then
        echo "PASS bench-es: $1 raw loop agrees with stin ($rows tier(s) as GLSL ES)"
    else
        echo "FAIL bench-es: $1 raw (exit $rc, $rows row(s) and $es GLSL ES table(s), want $2)"
        printf '%s\n' "$out" | tail -n 10 | sed 's/^/    /'
        fails=1
    fi
}

agree es30 2 # GL4 (its default) and GL2
agree es32 2

# The raw loop reads its GLSL from --shaders: a copy whose lit.frag halves
# the colour must make the agreement check fail the run.
mkdir -p "$TMP/shaders"
cp -R shaders/gl2 shaders/gl4 "$TMP/shaders/"
sed 's/gl_FragColor = vec4(clamp(color, 0.0, 1.0)/gl_FragColor = vec4(0.5 * clamp(color, 0.0, 1.0)/' \
    shaders/gl2/lit.frag > "$TMP/shaders/gl2/lit.frag"
if cmp -s shaders/gl2/lit.frag "$TMP/shaders/gl2/lit.frag"; then
    echo "FAIL bench-es: could not alter gl2/lit.frag's output line (has it changed?)"
    fails=1
else
    out=$("$BENCH" --raw --quick --profile es30 --shaders "$TMP/shaders" 2>&1)
    rc=$?
    if printf '%s\n' "$out" | grep -q 'no GL context'; then
        echo "SKIP bench-es: the agreement check on es30 (no OpenGL ES context here)"
    elif [ $rc -eq 1 ] && printf '%s\n' "$out" | grep -q 'it does not draw the same thing'; then
        echo "PASS bench-es: es30 fails when the raw frame differs from stin's"
    else
        echo "FAIL bench-es: es30 with a raw lit.frag that halves the colour (exit $rc, want 1 and the agreement message)"
        printf '%s\n' "$out" | tail -n 10 | sed 's/^/    /'
        fails=1
    fi
fi
exit $fails
