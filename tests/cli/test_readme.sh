#!/bin/sh
# SPDX-License-Identifier: MIT
# The README's quick start compiles as printed: the first C block after
# "## Quick start", with the warnings the library itself is held to.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
awk '/^## Quick start/ {q = 1} q && /^```c$/ {c = 1; next} c && /^```$/ {exit} c {print}' \
    README.md > "$dir/quick.c"
if [ ! -s "$dir/quick.c" ]; then
    echo "FAIL readme-quick-start: no C block after \"## Quick start\""
elif cc -std=c99 -Wall -Wextra -Werror -pedantic -Iinclude -c "$dir/quick.c" -o "$dir/quick.o" \
    > "$dir/log" 2>&1; then
    echo "PASS readme-quick-start: $(wc -l < "$dir/quick.c") lines compile as printed (-std=c99 -pedantic -Werror)"
else
    echo "FAIL readme-quick-start: $(grep -m 1 error "$dir/log")"
fi
