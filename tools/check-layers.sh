#!/bin/sh
# SPDX-License-Identifier: MIT
# The library's one dependency rule, read from the built objects' symbols
# (not the includes: a header that declares everything would hide a tangle).
#
#   base < gl < select < assets < render < features < frame
#   features: shadow csg surface translucent transparency post
#
# A file may use what its own folder and the folders below it define; feature
# folders never use each other; only frame names features. Every reference
# that breaks the rule is printed as
#   src/FROM.c -> src/TO.c (symbol): FOLDER may not use FOLDER
# A module's private state is a src/FOLDER/*_private.h header that only files of
# its folder include (read from the sources: the compiler sees no symbol for a
# struct); each other include is printed as
#   src/FROM.c includes src/FOLDER/X_private.h: private to FOLDER
# Usage: tools/check-layers.sh [OBJ_DIR (default build/lib)]
# Exits 1 when anything is printed.
set -u
OBJ=${1:-build/lib}
[ -d "$OBJ/src" ] || { echo "check-layers: no objects under $OBJ/src (build first)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# what each object defines and what it uses, "symbol src/FILE.c" a line; one
# nm call each (nm -A names the object on every line)
find "$OBJ/src" -name '*.o' | sort > "$tmp/objects"
to_source='{ f = $1; sub(/:.*/, "", f); sub("^" obj "/", "", f); sub(/\.o$/, ".c", f) }'
xargs nm -A -g --defined-only < "$tmp/objects" |
    awk -v obj="$OBJ" "$to_source"' NF == 3 { print $3, f }' > "$tmp/defs"
xargs nm -A -u < "$tmp/objects" | awk -v obj="$OBJ" "$to_source"' { print $NF, f }' > "$tmp/uses"
# an object whose source was moved or removed is left out
for list in defs uses; do
    awk '{ print $2 }' "$tmp/$list" | sort -u | while read -r f; do
        [ -f "$f" ] || echo "$f"
    done > "$tmp/gone"
    awk 'FILENAME == ARGV[1] { gone[$1] = 1; next } !($2 in gone)' "$tmp/gone" "$tmp/$list" > "$tmp/kept"
    mv "$tmp/kept" "$tmp/$list"
done
sort -o "$tmp/defs" "$tmp/defs"
sort -o "$tmp/uses" "$tmp/uses"

# "symbol from to" for every cross-file reference, judged by the rule
join "$tmp/uses" "$tmp/defs" | awk '$2 != $3' | awk '
function folder(path,  p) { split(path, p, "/"); return p[2] }
function rank(d) {
    if (d == "base") return 0; if (d == "gl") return 1; if (d == "select") return 2
    if (d == "assets") return 3; if (d == "render") return 4; if (d == "frame") return 6
    if (d == "shadow" || d == "csg" || d == "surface" || d == "translucent" ||
        d == "transparency" || d == "post") return 5
    return -1
}
{
    from = folder($2); to = folder($3)
    if (from == to) next
    if (rank(from) < 0 || rank(to) < 0) {
        printf "%s -> %s (%s): folder outside the rule\n", $2, $3, $1; next
    }
    if (rank(to) < rank(from)) next
    printf "%s -> %s (%s): %s may not use %s\n", $2, $3, $1, from, to
}' | sort > "$tmp/wrong"

# private state headers included from another folder
find src -name '*.[ch]' | sort | xargs grep -H '^#include "[a-z_]*/[a-z0-9_]*_private\.h"' |
    awk -F: '{
        split($1, f, "/"); h = $2; sub(/^#include "/, "", h); sub(/".*/, "", h)
        split(h, t, "/")
        if (f[2] != t[1]) printf "%s includes src/%s: private to %s\n", $1, h, t[1]
    }' > "$tmp/private"

if [ -s "$tmp/private" ]; then
    cat "$tmp/private"
    echo "check-layers: $(wc -l < "$tmp/private") includes of another folder's private state" >&2
fi
if [ -s "$tmp/wrong" ]; then
    cat "$tmp/wrong"
    echo "check-layers: $(awk '{ print $1, $3 }' "$tmp/wrong" | sort -u | wc -l) wrong-way file pairs" >&2
    exit 1
fi
[ -s "$tmp/private" ] && exit 1
echo "check-layers: $(cat "$tmp/defs" "$tmp/uses" | awk '{ print $2 }' | sort -u | wc -l) files, no wrong-way reference" >&2
