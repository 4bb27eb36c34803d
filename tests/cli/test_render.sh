#!/bin/sh
# stin-render's command line: bad input gets exit 2, a message naming the file
# and the problem, and no output file; a forced tier above the context exits 3
# naming the missing capabilities; good runs write the image contract.
# Prints PASS/FAIL lines. Usage: test_render.sh path/to/stin-render
set -u
R=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

check() { # name, condition result (0 = pass), detail
    if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1: $3"; fi
}

# Each bad file: exit 2 in bounded time, exactly one stderr line of valid
# UTF-8 naming the file, no image.
for f in tests/scenes/bad/*.json; do
    timeout 60 "$R" "$f" -o "$T/out.png" > "$T/stdout" 2> "$T/stderr"
    rc=$?
    ok=1
    [ $rc -eq 2 ] && grep -q "$f" "$T/stderr" && [ ! -e "$T/out.png" ] &&
        [ "$(wc -l < "$T/stderr")" -eq 1 ] && iconv -f UTF-8 -t UTF-8 "$T/stderr" > /dev/null 2>&1 && ok=0
    check "bad-scene $(basename "$f")" $ok "exit $rc, stderr: $(head -c 200 "$T/stderr")"
done

"$R" tests/scenes/does-not-exist.json -o "$T/out.png" > /dev/null 2> "$T/stderr"
rc=$?
check "missing scene file" $([ $rc -eq 2 ] && grep -q does-not-exist "$T/stderr" && echo 0 || echo 1) "exit $rc"

"$R" tests/scenes/torus.json --size 0x10 > /dev/null 2>&1
check "bad --size" $([ $? -eq 2 ] && echo 0 || echo 1) "accepted --size 0x10"

"$R" tests/scenes/torus.json --tier gl9 > /dev/null 2>&1
check "unknown tier" $([ $? -eq 2 ] && echo 0 || echo 1) "accepted --tier gl9"

"$R" tests/scenes/torus.json --shadows sideways > /dev/null 2>&1
check "unknown shadow technique" $([ $? -eq 2 ] && echo 0 || echo 1) "accepted --shadows sideways"

"$R" tests/scenes/torus.json --profile gl11 --tier gl4 -o "$T/forced.png" > /dev/null 2> "$T/stderr"
rc=$?
check "forced tier above the context" \
    $([ $rc -eq 3 ] && grep -q "GLSL" "$T/stderr" && [ ! -e "$T/forced.png" ] && echo 0 || echo 1) \
    "exit $rc, stderr: $(head -c 300 "$T/stderr")"

"$R" tests/scenes/torus.json --profile gl33-core --tier gl1 > /dev/null 2> "$T/stderr"
rc=$?
check "forced GL1 on a core context" \
    $([ $rc -eq 3 ] && grep -q "compatibility" "$T/stderr" && echo 0 || echo 1) "exit $rc"

"$R" --caps --profile gl14-shadow > "$T/caps" 2>&1
rc=$?
check "--caps" $([ $rc -eq 0 ] && grep -q "^tier gl1: runs" "$T/caps" && grep -q "^tier gl2: needs" "$T/caps" && echo 0 || echo 1) "exit $rc"

"$R" tests/scenes/torus.json --size 64x48 -o "$T/t.exr" > "$T/stdout" 2>&1
rc=$?
chans=$(oiiotool --info -v "$T/t.exr" 2>/dev/null | grep -i "channel list")
ok=1
[ $rc -eq 0 ] && for c in R G B A P.X P.Y P.Z N.X N.Y N.Z Z vis.R vis.G vis.B; do
    echo "$chans" | grep -q "[ ,]$c\b" || { ok=2; break; }
done && [ $ok -eq 1 ] && ok=0
check "exr channels" $ok "exit $rc, channels: $chans"
check "prints tier, choices and time" \
    $(grep -q "^tier: " "$T/stdout" && grep -q "^lighting: " "$T/stdout" && grep -q "^frame: " "$T/stdout" && echo 0 || echo 1) \
    "$(head -c 300 "$T/stdout")"

"$R" tests/scenes/torus.json --size 64x48 -o "$T/t.png" > /dev/null 2>&1
check "png output" $([ $? -eq 0 ] && [ -s "$T/t.png" ] && echo 0 || echo 1) "no png written"
# A full disk, simulated by a file size limit (SIGXFSZ ignored, so writes
# fail with EFBIG): non-zero exit, one line, no file and no temporary left.
(trap '' XFSZ; ulimit -f 8; "$R" tests/scenes/torus.json --size 256x256 -o "$T/full.png") \
    > /dev/null 2> "$T/stderr"
rc=$?
check "png write error on a full disk" \
    $([ $rc -ne 0 ] && [ "$(wc -l < "$T/stderr")" -eq 1 ] && ! ls "$T"/full.png* > /dev/null 2>&1 &&
      echo 0 || echo 1) "exit $rc, files: $(ls "$T" | tr '\n' ' ') stderr: $(head -c 200 "$T/stderr")"
exit 0
