#!/bin/sh
# SPDX-License-Identifier: MIT
# Before/after check for refactors that must not change a pixel: renders
# every example scene under every profile, platform and shadow technique to
# OpenEXR (beauty and AOVs), then compares two such sets channel by channel.
#   tools/compare-renders.sh render STIN_RENDER OUT_DIR [SIZE]
#   tools/compare-renders.sh diff DIR_BEFORE DIR_AFTER [TOLERANCE]
# TOLERANCE is the largest allowed channel difference (default 1/255); the
# diff prints one line per image over it and a summary, and fails if any is.
# The image tests' own read-backs, every one hashed (tests/image/readback_log.c):
#   tools/compare-renders.sh readbacks STIN_IMAGETEST OUT_DIR [JOBS]
#   tools/compare-renders.sh diff-readbacks DIR_BEFORE DIR_AFTER
# An exact check: one differing byte in one read-back is a difference.
set -u

render() {
    bin=$1 out=$2 size=${3:-256x192}
    mkdir -p "$out"
    for scene in tests/scenes/*.json; do
        s=$(basename "$scene" .json)
        for plat in egl osmesa; do
            for prof in gl11 gl13-combine gl14-shadow gl21 gl33-core gl45-core; do
                for sh in auto volume map map-pcf off; do
                    f="$out/$s.$plat.$prof.$sh.exr"
                    "$bin" "$scene" --platform "$plat" --profile "$prof" --shadows "$sh" \
                        --size "$size" -o "$f" > /dev/null 2>&1 || rm -f "$f"
                done
            done
        done
    done
    echo "$(ls "$out" | wc -l) images in $out"
}

diff_sets() {
    a=$1 b=$2 tol=${3:-0.0039216}
    n=0 bad=0 missing=0
    for fa in "$a"/*.exr; do
        name=$(basename "$fa")
        fb="$b/$name"
        if [ ! -f "$fb" ]; then
            echo "MISSING $name"
            missing=$((missing + 1))
            continue
        fi
        n=$((n + 1))
        if ! idiff -q -fail "$tol" -failpercent 0 "$fa" "$fb" > /dev/null 2>&1; then
            bad=$((bad + 1))
            echo "DIFFERS $name: $(idiff -fail "$tol" "$fa" "$fb" 2>&1 |
                grep -E 'Max error|pixels .* > ' | tr -s ' \n' ' ')"
        fi
    done
    for fb in "$b"/*.exr; do
        [ -f "$a/$(basename "$fb")" ] || { echo "EXTRA $(basename "$fb")"; missing=$((missing + 1)); }
    done
    echo "$n compared, $bad over $tol, $missing only in one set"
    [ "$bad" -eq 0 ] && [ "$missing" -eq 0 ]
}

readbacks() {
    bin=$1 out=$2 jobs=${3:-2}
    mkdir -p "$out"
    for plat in egl osmesa; do
        for prof in gl11 gl13-combine gl14-shadow gl21 gl33-core gl45-core; do
            echo "$plat $prof"
        done
    done | xargs -P "$jobs" -L 1 sh -c 'rm -f "$1/$3.$4.log"; STIN_READBACK_LOG="$1/$3.$4.log" \
        "$2" --platform "$3" --profile "$4" tests/scenes/*.json > "$1/$3.$4.out" 2>&1' _ "$out" "$bin" \
        || true
    for plat in egl osmesa; do
        for prof in gl11 gl13-combine gl14-shadow gl21 gl33-core gl45-core; do
            printf '%s %s ' "$plat" "$prof"; sed -n '$p' "$out/$plat.$prof.out"
        done
    done
}

diff_readbacks() {
    a=$1 b=$2 bad=0 n=0
    for fa in "$a"/*.log; do
        name=$(basename "$fa")
        n=$((n + $(wc -l < "$fa")))
        if ! cmp -s "$fa" "$b/$name"; then
            bad=$((bad + 1))
            echo "DIFFERS $name: $(diff "$fa" "$b/$name" | grep -c '^[<>]') lines"
        fi
    done
    echo "$n read-backs compared, $bad logs differ"
    [ "$bad" -eq 0 ]
}

case ${1:-} in
readbacks) shift; readbacks "$@" ;;
diff-readbacks) shift; diff_readbacks "$@" ;;
render) shift; render "$@" ;;
diff) shift; diff_sets "$@" ;;
*) echo "usage: $0 render STIN_RENDER OUT_DIR [WxH] | diff DIR_BEFORE DIR_AFTER [TOL]" \
        "| readbacks STIN_IMAGETEST OUT_DIR [JOBS] | diff-readbacks DIR_BEFORE DIR_AFTER" >&2; exit 2 ;;
esac
