#!/bin/sh
# SPDX-License-Identifier: MIT
# The browser image tests (docs/testing.md, "In a real browser"), after
# `make web`: a local server on 127.0.0.1 (tests/web/server.js) serves
# BUILD/web; headless Chromium (WebGL 2 on SwiftShader) renders the scenes
# with each case of tests/web/test.js and posts the read-backs; stin-imagetest
# --browser compares them with the Embree reference under the native es30
# rows' bounds. PASS/FAIL/SKIP lines, then "N passed, N failed, N skipped".
# Usage: tests/web/run.sh [BUILD_DIR]
# Environment: STIN_WEB_SCENES (default all: every scene pack of
# BUILD/web/scenes), STIN_WEB_CASES (default every case but parallax-limit,
# open: docs/web.md; a compared case
# runs on its own scene alone, tests/web/test.js; "sweep" draws every scene
# with stin's own choice at STIN_WEB_SWEEP_SIZE, default 128x96, not
# compared: drawn, or the fall-backs named), STIN_WEB_TIMEOUT (seconds,
# default 240: make check runs it beside other suites), STIN_WEB_OUT (where
# the read-backs go; default BUILD/test-out/web).
set -u
B=${1:-build}
SCENES=${STIN_WEB_SCENES:-all}
CASES=${STIN_WEB_CASES:-lighting,volume,map-pcf-1024-k3,coloured,deep,lighting-gl4,volume-gl4,pom-gl4,depth-peel,normal,pom,parallax-down,parallax-down-normal,displace,scs-carved,scs-both,scs-common,goldfeather-carved,goldfeather-both,goldfeather-common,skip-dual-peel,skip-vdsm,skip-displace-tess,skip-interval,webgl1,sweep}
SWEEP=${STIN_WEB_SWEEP_SIZE:-128x96}
LIMIT=${STIN_WEB_TIMEOUT:-240}
OUT=${STIN_WEB_OUT:-$B/test-out/web}
SIZE=256x192
fail() { echo "FAIL browser: $*"; echo "0 passed, 1 failed, 0 skipped"; exit 1; }
for f in "$B/web/stin.js" "$B/web/test.html" "$B/web/scenes/list.txt" "$B/stin-imagetest"; do
    [ -f "$f" ] || fail "$f is missing (make web tests)"
done
[ "$SCENES" != all ] || SCENES=$(paste -sd, "$B/web/scenes/list.txt")
BROWSER=$(command -v chromium || command -v chromium-browser) || fail "no chromium (platform/install-deps.sh installs it)"
command -v node >/dev/null || fail "no node"
rm -rf "$OUT"
mkdir -p "$OUT/result" "$OUT/profile"

node tests/web/server.js --root "$B/web" --out "$OUT/result" --port 0 --timeout "$LIMIT" \
    > "$OUT/server.log" 2>&1 &
server=$!
i=0
while ! grep -q '^listening on' "$OUT/server.log" 2>/dev/null; do
    i=$((i + 1))
    [ $i -lt 100 ] || { kill "$server" 2>/dev/null; fail "the server did not start: $(cat "$OUT/server.log")"; }
    sleep 0.1
done
url=$(sed -n 's/^listening on //p' "$OUT/server.log" | head -n 1)
# WebGL 2 in software: ANGLE on SwiftShader (no GPU needed; Chromium
# refuses the software fallback without the unsafe switch). No sandbox as
# root; a fresh profile and nothing that reaches for the network.
# In a session of its own (setsid): its renderer and GPU processes are
# counted and ended with it. tests/run.sh's malloc settings are for the
# image suites' llvmpipe, not for a browser's many processes.
env -u GLIBC_TUNABLES setsid timeout "$LIMIT" "$BROWSER" --headless --no-sandbox --use-angle=swiftshader \
    --enable-unsafe-swiftshader --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --disable-quic --disable-extensions \
    --disable-crash-reporter --enable-logging=stderr --v=0 \
    --user-data-dir="$OUT/profile" "${url}test.html?size=$SIZE&sweep=$SWEEP&scenes=$SCENES&cases=$CASES" \
    > "$OUT/browser.log" 2>&1 &
browser=$!
wait "$server"
status=$?
# the browser's CPU seconds, every process of its session, before it ends
cpu=$(ps -s "$browser" -o times= 2>/dev/null | awk '{ s += $1 } END { print s + 0 }')
kill -- -"$browser" 2>/dev/null
wait "$browser" 2>/dev/null
echo "# browser: $cpu CPU seconds"
grep '^browser:' "$OUT/server.log"
[ "$status" -eq 0 ] || fail "no result within $LIMIT s (server status $status; $OUT/browser.log)"

scene_files=
for s in $(echo "$SCENES" | tr , ' '); do
    scene_files="$scene_files tests/scenes/$s.json"
done
# shellcheck disable=SC2086 # one word per scene
"$B/stin-imagetest" --browser "$OUT/result" --cases "$CASES" --size "$SIZE" --out "$OUT" $scene_files \
    | tee "$OUT/lines.txt"
awk '/^PASS /{p++} /^FAIL /{f++} /^SKIP /{s++} END {printf "%d passed, %d failed, %d skipped\n", p, f, s; exit f > 0 || p == 0}' "$OUT/lines.txt"
