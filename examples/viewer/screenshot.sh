#!/bin/sh
# SPDX-License-Identifier: MIT
# The viewer's picture for the docs, title bar and all: the viewer in a
# virtual X display with a window manager (twm draws the title), the screen
# captured (ImageMagick's import) and cut to the window's frame.
# Usage: examples/viewer/screenshot.sh VIEWER SCENE OUT.png [WxH [SECONDS [VIEWER OPTIONS]]]
set -eu
V=$1 SCENE=$2 OUT=$3 SIZE=${4:-400x300} WAIT=${5:-20}
shift $(($# < 5 ? $# : 5))
OPTIONS="$*"
W=${SIZE%x*} H=${SIZE#*x}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
[ -n "${KEEP:-}" ] && trap - EXIT
# twm places windows itself (no click to place), at the top left, no icons
printf 'RandomPlacement\nNoGrabServer\nIconManagerDontShow\n' > "$T/twmrc"
for f in TitleFont MenuFont IconFont ResizeFont IconManagerFont; do
    echo "$f \"fixed\"" >> "$T/twmrc" # the server's built-in font: no font packages needed
done
cat > "$T/run.sh" << SCRIPT
twm -f "$T/twmrc" > /dev/null 2>&1 &
wm=\$!
sleep 1
"$V" "$SCENE" --size $SIZE $OPTIONS > "$T/viewer.txt" 2>&1 &
viewer=\$!
sleep $WAIT
import -window root "$T/screen.png"
kill \$viewer \$wm
SCRIPT
xvfb-run -a -s "-screen 0 $((W + 200))x$((H + 200))x24 -wr" sh "$T/run.sh"
# the window and its frame: what is not the white root window
convert "$T/screen.png" -trim +repage "$OUT"
echo "wrote $OUT"
