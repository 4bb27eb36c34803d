#!/bin/sh
# SPDX-License-Identifier: MIT
# The test runner of `make check`. Runs every test binary, each capability
# profile in its own process on both platforms, STIN_TEST_JOBS suites at a
# time (default: the number of cores), prints each suite's lines in a fixed
# order once all are done, the ten slowest suites, and ends with the line
#   N passed, N failed, N skipped
# Usage: tests/run.sh BUILD_DIR
# Environment: STIN_TEST_PLATFORMS (default "egl osmesa"),
#              STIN_TEST_PROFILES (default: every desktop profile of docs/profiles.md),
#              STIN_TEST_ES_PROFILES (default "es30 es32 es20-ext es20 es31"; egl only, the scenes below),
#              STIN_TEST_QUICK=1 leaves out the install, licence, readme,
#              bench, viewer and browser (web) suites (make check-quick), STIN_TEST_JOBS,
#              STIN_READBACK_DIR: every image suite hashes its read-backs into
#              DIR/PLATFORM.PROFILE.log (tools/compare-renders.sh diff-readbacks),
#              STIN_TEST_REFERENCE_CACHE=0: no reference cache, every image
#              suite computes its own references (default: the suites share
#              them in BUILD_DIR/test-out/reference-cache, emptied before and
#              after the run).
set -u
# One suite (xargs runs this script again with --suite): its output, exit
# status, wall and CPU seconds into SUITES/NNN.*. Dispatched before the set-up
# below, which would take "--suite" for the build directory: its redirection
# into a directory that does not exist ends the shell (dash, bash --posix).
run_suite() {
    dir=$1 num=$2
    shift 2
    shift # the name
    start=$(date +%s.%N)
    "$@" > "$dir/$num.out" 2>&1
    echo $? > "$dir/$num.rc"
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.1f\n", $2 - $1 }' > "$dir/$num.seconds"
    # CPU seconds (user + system of the suite's processes: a loaded machine
    # stretches the wall seconds, hardly these): times' second line, the
    # children's, written by this shell itself (a pipeline's subshell has
    # no children of its own)
    times > "$dir/$num.times"
    sed -n 2p "$dir/$num.times" | tr 'ms' '  ' |
        awk '{ printf "%.1f\n", 60 * $1 + $2 + 60 * $3 + $4 }' > "$dir/$num.cpu"
}
if [ "${1:-}" = --suite ]; then
    shift
    run_suite "$@"
    exit 0
fi

B=${1:-build}
LOG=$B/test-log.txt
OUT=$B/test-out
SUITES=$OUT/suites
rm -rf "$SUITES"
mkdir -p "$OUT" "$SUITES"
: > "$LOG"
PLATFORMS=${STIN_TEST_PLATFORMS:-egl osmesa}
PROFILES=${STIN_TEST_PROFILES:-gl11 gl13-combine gl14-shadow gl21 gl33-core gl45-core}
# OpenGL ES (egl only: OSMesa has no ES), on the scenes that prove the path:
# lighting, volumes and vdsm on four-lights; on es30 also map-pcf on
# spheres-18k-sun (es32 has no timer queries for its vdsm/volumes choice
# tests there), depth peeling with its any-samples early stop and coloured
# maps on glass-panes (10 s), scs and goldfeather with their GLSL ES 3.00
# depth write-back on csg (42 s), displacement by vertex textures on
# displace-plate (2 s), normal/parallax/pom on stone-wall (5 s); on es32
# dual peeling and deep maps on glass-panes and interval CSG on csg (both
# its tiers run), tessellated displacement on displace-tess (3 s), area
# lights on shadow-soft (soft vdsm by image atomics: 8 s).
# es20-ext (GLSL ES 1.00) runs es30's scenes, csg by the GPU resolve alone
# (35 s); es20 (no derivatives, depth textures or 32-bit indices) volumes
# and map-pcf's packed maps on spheres-18k-spot (6 s), and csg by the packed
# GPU resolve (its result packed into RGBA8: 30 s more). es31 (GLSL ES
# 3.10; es30's choices) lighting, volumes, map-pcf and the application's
# visibility map on four-lights (19 s).
ES_PROFILES=${STIN_TEST_ES_PROFILES:-es30 es32 es20-ext es20 es31}
ES_SCENES="tests/scenes/four-lights.json"
JOBS=${STIN_TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
SCENES=$(ls tests/scenes/*.json)

# The image suites share whole-image reference results (Embree) through
# files keyed by everything that determines them (docs/testing.md, "The
# reference cache"); emptied here so no result outlives this run's build.
CACHE=
if [ "${STIN_TEST_REFERENCE_CACHE:-1}" != 0 ]; then
    CACHE=$OUT/reference-cache
    rm -rf "$CACHE"
    mkdir -p "$CACHE"
fi
export STIN_REFERENCE_CACHE="$CACHE"

export CMOCKA_MESSAGE_OUTPUT=TAP
# With a suite per core already, llvmpipe's own rasteriser threads only add
# hand-offs: rasterising in each suite's thread took 9% less CPU on the CSG
# scene (the same pixels: tiles are rasterised alike either way).
if [ "$JOBS" -ge "$(nproc 2>/dev/null || echo 1)" ]; then
    export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
fi
# llvmpipe allocates every texture and framebuffer of a stin context anew
# (a 2048-texel deep map is over 32 MB), and glibc serves such blocks by
# mmap: every context then paid page faults and the kernel's zeroing of
# fresh pages. Served from the heap and kept there, a freed block is reused
# as it is: on gl45-core (EGL) system time fell from 22.0 to 4.6 s on the
# terminator scenes, from 11.3 to 5.0 s on four-lights and glass-panes, with
# identical lines (docs/testing.md, "Where make check's time goes").
# hugetlb=1 asks for transparent huge pages on that heap: the first touch of
# fresh heap faults in 2 MB at a time instead of 4 KB, and a fork (a scene's
# model or image import runs in a child) copies one entry per 2 MB; system
# time fell from 17.1 to 7.9 s on gl45-core (EGL), 10.8 to 4.9 on gl21
# (OSMesa), the same lines.
# AddressSanitizer's allocator (the unit tests) ignores these settings.
export GLIBC_TUNABLES=${GLIBC_TUNABLES:-glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967296:glibc.malloc.top_pad=67108864:glibc.malloc.hugetlb=1}
# Driver-internal leaks (OSMesa, EGL) are not ours; see docs/testing.md.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}

# The suites, one a line: "NAME COMMAND...", in the order their lines are
# printed. Arguments hold no spaces.
{
    for plat in $PLATFORMS; do
        for prof in $PROFILES; do
            hashes=
            if [ -n "${STIN_READBACK_DIR:-}" ]; then
                rm -f "$STIN_READBACK_DIR/$plat.$prof.log"
                hashes="env STIN_READBACK_LOG=$STIN_READBACK_DIR/$plat.$prof.log"
            fi
            echo "image:$plat:$prof $hashes $B/stin-imagetest --profile $prof --platform $plat --out $OUT" $SCENES
        done
        [ "$plat" = egl ] || continue
        for prof in $ES_PROFILES; do
            case $prof in
                es30) more="tests/scenes/spheres-18k-sun.json tests/scenes/glass-panes.json tests/scenes/csg.json tests/scenes/displace-plate.json tests/scenes/stone-wall.json" ;;
                es32) more="tests/scenes/glass-panes.json tests/scenes/csg.json tests/scenes/displace-tess.json
                             tests/scenes/shadow-soft.json" ;;
                es20-ext) more="tests/scenes/spheres-18k-sun.json tests/scenes/glass-panes.json
                                tests/scenes/stone-wall.json tests/scenes/displace-plate.json
                                tests/scenes/csg.json" ;;
                es20) more="tests/scenes/spheres-18k-spot.json tests/scenes/csg.json" ;;
                *) more= ;;
            esac
            tiers=
            if [ "$prof" = es30 ]; then
                # ES 3.0's own GL4 tier on every scene; its GL2 tier (the
                # gl2 sources as GLSL ES 3.00) where that differs most
                tiers="--tiers gl1,gl4"
                echo "image:$plat:$prof-gl2 $B/stin-imagetest --profile $prof --platform $plat --out $OUT --tiers gl2" \
                     $ES_SCENES tests/scenes/glass-panes.json tests/scenes/stone-wall.json
            fi
            echo "image:$plat:$prof $B/stin-imagetest --profile $prof --platform $plat --out $OUT $tiers" $ES_SCENES $more
        done
    done
    for t in "$B"/tests/test_*; do
        [ -x "$t" ] || continue
        case $t in
            *test_noheap*) echo "$(basename "$t") $t $B/libstin.a" ;;
            *) echo "$(basename "$t") $t" ;;
        esac
    done
    echo "cli sh tests/cli/test_render.sh $B/stin-render"
    case " $PLATFORMS " in *" egl "*) echo "cli-es sh tests/cli/test_es_render.sh $B/stin-render"
                                      echo "bench-es sh tests/cli/test_bench_es.sh $B/stin-bench" ;; esac
    echo "layers sh tests/cli/test_layers.sh $B"
    if [ "${STIN_TEST_QUICK:-0}" != 1 ]; then
        echo "install sh tests/cli/test_install.sh"
        echo "licence sh tests/cli/test_licence.sh"
        echo "readme sh tests/cli/test_readme.sh"
        echo "bench sh tests/cli/test_bench.sh $B/stin-bench $OUT/bench-quick.txt"
        echo "viewer sh tests/cli/test_viewer.sh $B/examples/viewer $B/stin-render"
        echo "web sh tests/web/run.sh $B"
    fi
} | awk '{ printf "%03d %s\n", NR, $0 }' > "$SUITES/list"

# Started longest first (measured: gl45-core, gl33-core and gl21 take most
# of the run; the command-line, bench, install and viewer checks and the
# es30 and es32 suites, 50-80 s each, next), so that the
# parallel run ends together. gl45-core and gl33-core of the first platform
# go before the second's: two suites that run the same scenes side by side
# would both compute every reference the cache could have shared.
first=${PLATFORMS%% *}
awk -v first="image:$first:" '{ w = 1 }
     $2 ~ /:gl45-core$/ { w = 6 } $2 ~ /:gl33-core$/ { w = 5 } $2 ~ /:gl21$/ { w = 4 }
     w >= 5 && index($2, first) == 1 { w += 10 }
     $2 == "cli" || $2 == "cli-es" || $2 == "bench" || $2 == "bench-es" || $2 == "install" || $2 == "viewer" || $2 == "web" { w = 3 }
     $2 ~ /:es(3[02]|20-ext)$/ { w = 3 } $2 ~ /^image:/ && w == 1 { w = 2 }
     { print w, $0 }' "$SUITES/list" | sort -s -k1,1nr | cut -d" " -f2- > "$SUITES/schedule"
xargs -P "$JOBS" -L 1 sh "$0" --suite "$SUITES" < "$SUITES/schedule"

# In list order: cmocka TAP -> PASS/FAIL lines; a suite that exits non-zero
# without reporting a failure counts as one failure.
while read -r num name _; do
    tmp=$SUITES/$num.out
    rc=$(cat "$SUITES/$num.rc" 2>/dev/null || echo 127)
    label=${name%%:*}
    sed -e "s/^ok [0-9]* - \(.*\)/PASS $label: \1/" \
        -e "s/^not ok [0-9]* - \(.*\)/FAIL $label: \1/" \
        -e "s/^ok [0-9]* # SKIP \(.*\)/SKIP $label: \1/" "$tmp" | tee -a "$LOG" | grep -E '^(PASS|FAIL|SKIP) '
    if [ "$rc" -ne 0 ] && ! grep -q '^\(not ok\|FAIL\) ' "$tmp"; then
        echo "FAIL $name: exited with status $rc" | tee -a "$LOG"
        tail -n 20 "$tmp" | sed 's/^/    /'
    fi
    grep -E '^(#|    )' "$tmp" | grep -iE 'error|fail|assert' | head -n 20 | sed 's/^/    /'
done < "$SUITES/list"

echo "slowest suites (wall seconds, $JOBS at a time; CPU seconds, user + system):"
while read -r num name _; do
    echo "$(cat "$SUITES/$num.seconds" 2>/dev/null || echo 0) (cpu $(cat "$SUITES/$num.cpu" 2>/dev/null || echo 0)) $name"
done < "$SUITES/list" | sort -rn | head -n 10 | sed 's/^/  /'

if [ -n "$CACHE" ]; then
    rm -rf "$CACHE"
fi

awk '/^PASS /{p++} /^FAIL /{f++} /^SKIP /{s++} END {printf "%d passed, %d failed, %d skipped\n", p, f, s; exit f > 0}' "$LOG"
