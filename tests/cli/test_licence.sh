#!/bin/sh
# SPDX-License-Identifier: MIT
# Every source file of the repository names its licence (an SPDX line in
# its first three lines) and the MIT text is in LICENSE. Data (scenes,
# corpus), images and documents are not source.
set -u
if [ ! -f LICENSE ] || ! grep -q '^MIT License' LICENSE; then
    echo "FAIL licence: no MIT LICENSE file"
    exit 0
fi
missing=$(git ls-files 2> /dev/null |
    grep -Ev '^(tests/fuzz/(corpus|crashes)/|tests/scenes/|docs/)|\.(md|json|png|obj|ply|dict|gitignore)$|^LICENSE$' |
    while read -r f; do
        head -n 3 "$f" | grep -q 'SPDX-License-Identifier: MIT' || echo "$f"
    done)
if [ -z "$(git ls-files 2> /dev/null | head -n 1)" ]; then
    echo "SKIP licence: not a git checkout"
elif [ -n "$missing" ]; then
    echo "FAIL licence: no SPDX line in $(echo "$missing" | tr '\n' ' ')"
else
    echo "PASS licence: LICENSE is MIT and every source file has its SPDX line"
fi
