#!/bin/sh
# SPDX-License-Identifier: MIT
# The dependency rule of docs/architecture.md on the built library
# (tools/check-layers.sh), and the check itself on a deliberately wrong-way
# call, so that a check which passes everything fails here.
# Usage: tests/cli/test_layers.sh BUILD_DIR
set -u
B=${1:-build}
root=$(pwd)
check=$root/tools/check-layers.sh

if out=$(sh "$check" "$B/lib" 2>&1); then
    echo "PASS layers: $(echo "$out" | tail -n 1 | sed 's/^check-layers: //')"
else
    echo "FAIL layers: references against the rule (tools/check-layers.sh):"
    echo "$out" | sed 's/^/    /'
fi

# base/low.c calling frame/high.c must be named; frame calling base must not.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/src/base" "$tmp/src/frame" "$tmp/obj/src/base" "$tmp/obj/src/frame"
printf 'int high(void);\nint low(void) { return high(); }\n' > "$tmp/src/base/low.c"
printf 'int low(void);\nint high(void) { return 1; }\nint top(void) { return low(); }\n' \
    > "$tmp/src/frame/high.c"
cc -c "$tmp/src/base/low.c" -o "$tmp/obj/src/base/low.o" &&
    cc -c "$tmp/src/frame/high.c" -o "$tmp/obj/src/frame/high.o" || {
    echo "FAIL layers-self-test: could not compile the probe"
    exit 0
}
out=$(cd "$tmp" && sh "$check" obj 2>/dev/null)
if [ "$out" = "src/base/low.c -> src/frame/high.c (high): base may not use frame" ]; then
    echo "PASS layers-self-test: a wrong-way call is named, the right-way one is not"
else
    echo "FAIL layers-self-test: expected exactly the base -> frame reference, got: $out"
fi

# csg including shadow's private state must be named; shadow including it must not.
mkdir -p "$tmp/src/shadow" "$tmp/src/csg"
printf 'struct stin__probe_state { int x; };\n' > "$tmp/src/shadow/probe_private.h"
printf '#include "shadow/probe_private.h"\n' > "$tmp/src/shadow/probe.c"
printf '#include "shadow/probe_private.h"\n' > "$tmp/src/csg/reader.c"
out=$(cd "$tmp" && sh "$check" obj 2>/dev/null | grep -v '^src/base/low.c')
if [ "$out" = "src/csg/reader.c includes src/shadow/probe_private.h: private to shadow" ]; then
    echo "PASS layers-private-state: another folder's include of a *_private.h is named"
else
    echo "FAIL layers-private-state: expected exactly csg's include of shadow's state, got: $out"
fi
