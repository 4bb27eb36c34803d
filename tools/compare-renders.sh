#!/bin/sh
# SPDX-License-Identifier: MIT
# Before/after check for refactors that must not change a pixel: renders
# every example scene under every profile, platform and shadow technique to
# OpenEXR (beauty and AOVs), then compares two such sets channel by channel.
#   tools/compare-renders.sh render STIN_RENDER OUT_DIR [SIZE]
#   tools/compare-renders.sh diff DIR_BEFORE DIR_AFTER [TOLERANCE]
# TOLERANCE is the largest allowed channel difference (default 1/255); the
# diff prints one line per image over it and a summary, and fails if any is.
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

case ${1:-} in
render) shift; render "$@" ;;
diff) shift; diff_sets "$@" ;;
*) echo "usage: $0 render STIN_RENDER OUT_DIR [WxH] | diff DIR_BEFORE DIR_AFTER [TOL]" >&2; exit 2 ;;
esac
