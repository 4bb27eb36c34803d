#!/bin/sh
# SPDX-License-Identifier: MIT
# The interactive viewer (examples/viewer) under a virtual X display: a few
# scripted frames of a scene, the window's read-back compared with
# stin-render's image of the same scene, camera, size and technique. They
# must agree: at most 0.01% of the pixels (one at 160 x 120) may differ by
# more than 2/255 in any of R G B A. Measured: none differs at all (the
# same llvmpipe behind GLX and EGL); the one pixel is room for a window
# system that rounds an edge otherwise, no more, so that a camera 0.1
# degrees off fails (measured: 7 pixels, 0.036%, turned about the up axis;
# 92, 0.48%, tilted), or the comparison would prove nothing.
# Prints PASS/FAIL/SKIP lines. Usage: test_viewer.sh VIEWER STIN_RENDER
set -u
V=$1
R=$2
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
SCENE=tests/scenes/torus.json
SIZE=160x120
BOUND=0.01      # percent of the pixels
THRESH=0.00785  # 2/255

if [ ! -x "$V" ]; then
    echo "SKIP viewer: not built (GLFW missing: libglfw3-dev, see platform/install-deps.sh)"
    exit 0
fi
if ! command -v xvfb-run > /dev/null 2>&1; then
    echo "SKIP viewer: no xvfb-run (xvfb, see platform/install-deps.sh)"
    exit 0
fi

# The settings: stin's own choice (gl4 here: vdsm), and the fixed-function
# tier with stencil volumes reached by keys as a user would: T (tier gl1),
# S (vdsm: refused at gl1, the context kept), S (volume). Each: the
# reference, then the viewer's frames.
run() { # name, options...
    name=$1
    shift
    "$R" "$SCENE" --size $SIZE "$@" -o "$T/$name.ref.exr" > "$T/$name.ref.txt" 2>&1 ||
        echo "stin-render failed: $(tail -n 1 "$T/$name.ref.txt")" > "$T/$name.ref.fail"
}
run auto
run gl1-volume --tier gl1 --shadows volume
# One X server for every viewer run (starting one is the costly part).
cat > "$T/viewer.sh" << EOF
"$V" "$SCENE" --size $SIZE --frames 2 --screenshot "$T/auto.exr" > "$T/auto.txt" 2>&1
echo \$? > "$T/auto.rc"
"$V" "$SCENE" --size $SIZE --frames 4 --keys TSS --screenshot "$T/gl1-volume.exr" > "$T/gl1-volume.txt" 2>&1
echo \$? > "$T/gl1-volume.rc"
"$V" "$SCENE" --size $SIZE --frames 2 --keys G --screenshot "$T/srgb.exr" > "$T/srgb.txt" 2>&1
echo \$? > "$T/srgb.rc"
"$V" "$SCENE" --size $SIZE --frames 2 --orbit 0.1,0 --screenshot "$T/nudged.exr" > "$T/nudged.txt" 2>&1
echo \$? > "$T/nudged.rc"
"$V" "$SCENE" --size $SIZE --frames 2 --keys O --screenshot "$T/overlay.exr" > "$T/overlay.txt" 2>&1
echo \$? > "$T/overlay.rc"
EOF
timeout 120 xvfb-run -a -s "-screen 0 640x480x24" sh "$T/viewer.sh" > "$T/xvfb.txt" 2>&1
if [ "$(cat "$T/auto.rc" 2>/dev/null)" = 4 ] || [ ! -e "$T/auto.rc" ]; then
    echo "SKIP viewer: no display could be opened: $(tail -n 1 "$T/auto.txt" 2>/dev/null || tail -n 1 "$T/xvfb.txt")"
    exit 0
fi

# The share of pixels over THRESH in R G B A (percent), or "" if oiiotool could not tell.
over() { # reference, viewer
    out=$(oiiotool --fail $THRESH --warn $THRESH "$1" --ch R,G,B,A "$2" --diff 2>&1)
    if echo "$out" | grep -q '^PASS'; then
        echo 0
    else
        echo "$out" | sed -n 's/.*pixels (\([0-9.e+-]*\)%) over.*/\1/p' | head -n 1
    fi
}

for name in auto gl1-volume; do
    if [ -e "$T/$name.ref.fail" ]; then
        echo "FAIL viewer: $name: $(cat "$T/$name.ref.fail")"
        continue
    fi
    rc=$(cat "$T/$name.rc")
    if [ "$rc" -ne 0 ] || [ ! -s "$T/$name.exr" ]; then
        echo "FAIL viewer: $name: exit $rc, $(tail -n 1 "$T/$name.txt")"
        continue
    fi
    p=$(over "$T/$name.ref.exr" "$T/$name.exr")
    tech=$(grep "^shadows:" "$T/$name.txt" | tail -n 1 | cut -d" " -f2)
    if [ -n "$p" ] && awk -v p="$p" -v b=$BOUND 'BEGIN { exit !(p <= b) }'; then
        echo "PASS viewer: $name ($tech) agrees with stin-render: $p% of pixels over 2/255"
    else
        echo "FAIL viewer: $name ($tech): $p% of pixels over 2/255 (bound $BOUND%)"
    fi
done

# G (sRGB on): stin lights in linear space and the framebuffer encodes;
# the read-back decoded must agree with the linear reference within the
# same bound (an 8-bit sRGB step is at most 2.3/255 in linear terms, so
# rounding stays under 2/255). Measured: no pixel over 2/255.
if grep -q "sRGB: unavailable" "$T/srgb.txt"; then
    echo "SKIP viewer: srgb: the display has no sRGB-capable framebuffer"
elif [ "$(cat "$T/srgb.rc")" -ne 0 ] || ! grep -q "sRGB: on" "$T/srgb.txt"; then
    echo "FAIL viewer: srgb: exit $(cat "$T/srgb.rc"), $(grep sRGB "$T/srgb.txt" | tail -n 1)"
else
    p=$(over "$T/auto.ref.exr" "$T/srgb.exr")
    if [ -n "$p" ] && awk -v p="$p" -v b=$BOUND 'BEGIN { exit !(p <= b) }'; then
        echo "PASS viewer: srgb (G) decoded agrees with stin-render: $p% of pixels over 2/255"
    else
        echo "FAIL viewer: srgb (G): $p% of pixels over 2/255 (bound $BOUND%)"
    fi
fi

# The title: tier, the techniques, the frame's stage times (gl4 has timer
# queries) and why; the keys' refusal said in stin's words.
title=$(sed -n 's/^title: //p' "$T/auto.txt")
if echo "$title" | grep -q "^stin gl4 | vdsm | .* ms \[.*shadow [0-9.]* .*\] | shadows: " &&
    grep -q "^refused: .*shadows technique vdsm needs tier gl4" "$T/gl1-volume.txt"; then
    echo "PASS viewer: the title shows tier, techniques, stage times and why"
else
    echo "FAIL viewer: title '$title'; refusal: $(grep '^refused' "$T/gl1-volume.txt")"
fi

# The same frame with the camera turned 0.1 degrees must not pass.
p=$(over "$T/auto.ref.exr" "$T/nudged.exr")
if [ "$(cat "$T/nudged.rc")" -eq 0 ] && [ -n "$p" ] && awk -v p="$p" -v b=$BOUND 'BEGIN { exit !(p > b) }'; then
    echo "PASS viewer: a camera 0.1 degrees off is caught: $p% of pixels over 2/255"
else
    echo "FAIL viewer: a camera 0.1 degrees off passed: ${p:-?}% of pixels over 2/255 (bound $BOUND%)"
fi

# O (the status overlay; off in a script until pressed, so the comparisons
# above are stin's frame alone): the panel it reports at the top left must
# differ from stin-render's frame on at least half its pixels (a dark panel
# with light text), and the rows below it agree by the bound above.
# Measured at 160x120: a 160x112 panel, 93.3% of the frame's pixels over
# 2/255 (all of the panel's), the 8 rows below: none.
W=${SIZE%x*}
H=${SIZE#*x}
panel=$(sed -n 's/^overlay: \([0-9]*x[0-9]*\) at the top left$/\1/p' "$T/overlay.txt")
pw=${panel%x*}
ph=${panel#*x}
p=$(over "$T/auto.ref.exr" "$T/overlay.exr")
below=0
if [ -n "$panel" ] && [ "$ph" -lt "$H" ]; then
    out=$(oiiotool --fail $THRESH --warn $THRESH "$T/auto.ref.exr" --ch R,G,B,A \
        --cut "${W}x$((H - ph))+0+$ph" "$T/overlay.exr" --cut "${W}x$((H - ph))+0+$ph" --diff 2>&1)
    echo "$out" | grep -q '^PASS' || below=$(echo "$out" | sed -n 's/.*pixels (\([0-9.e+-]*\)%) over.*/\1/p' | head -n 1)
fi
if [ "$(cat "$T/overlay.rc")" -eq 0 ] && [ -n "$panel" ] && [ -n "$p" ] &&
    awk -v p="$p" -v a="$((pw * ph))" -v n="$((W * H))" -v b="${below:-100}" -v bound=$BOUND \
        'BEGIN { exit !(p * n / 100 >= a / 2 && b <= bound) }'; then
    echo "PASS viewer: the overlay (O) draws its ${panel} panel: $p% of pixels over 2/255, below it $below%"
else
    echo "FAIL viewer: overlay (O): exit $(cat "$T/overlay.rc"), panel '${panel}', $p% of pixels over 2/255, below it ${below:-?}%"
fi
