#!/bin/sh
# SPDX-License-Identifier: MIT
# stin-bench on a lent GPU machine, which gets a copy of the working tree
# but none of this machine's packages (docs/benchmarks.md, "On a GPU").
#   tools/gpu-bench.sh pack        here: builds the bench without OSMesa and
#                                  OpenImageIO into build/gpu and puts it,
#                                  stripped, with the shared libraries it
#                                  needs (libc's own left out) into .gpu/,
#                                  which git ignores: carry it.
#   tools/gpu-bench.sh run PART [OPTION...]
#                                  there: one part of the to-do list, its
#                                  table into $OUT/PART.txt (each part is
#                                  sized for one 10-minute call; options are
#                                  added to the part's, --quick for a dry
#                                  run here).
# Parts: vdsm, vdsm-1280, csg, csg-readback, deep, peel, shadows.
set -eu

here=$(cd "$(dirname "$0")/.." && pwd)
carry="$here/.gpu"

pack() {
    cd "$here"
    make B=build/gpu OSMESA=no OIIO=no build/gpu/stin-bench
    rm -rf "$carry"
    mkdir -p "$carry/lib"
    strip -o "$carry/stin-bench" build/gpu/stin-bench
    # libc, libm, the loader and the vDSO come from the machine itself
    ldd build/gpu/stin-bench | awk '$3 ~ /^\// {print $3}' |
        grep -Ev '/(libc|libm|libdl|libpthread|librt|ld-linux[^/]*)\.so' |
        while read -r lib; do cp -L "$lib" "$carry/lib/"; done
    cat > "$carry/env.sh" <<'EOF'
# sourced by tools/gpu-bench.sh run (GPU_CARRY: this folder): the carried
# libraries first, then the vendor's (NVIDIA's GLVND EGL vendor file where
# it is installed)
LD_LIBRARY_PATH="$GPU_CARRY/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export LD_LIBRARY_PATH
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [ -f "$vendor" ]; then
    __EGL_VENDOR_LIBRARY_FILENAMES=$vendor
    export __EGL_VENDOR_LIBRARY_FILENAMES
fi
EOF
    du -sh "$carry"
    echo "carry: .gpu (run: tools/gpu-bench.sh run PART on the device)"
}

run() {
    part=$1
    shift
    out=${OUT:-$here/out}
    mkdir -p "$out"
    cd "$here"
    [ -x "$carry/stin-bench" ] || { echo "no $carry/stin-bench: pack it and carry .gpu" >&2; exit 2; }
    GPU_CARRY=$carry
    # shellcheck disable=SC1091
    . "$carry/env.sh"
    seed=tests/scenes/seed
    c_scenes="$seed/spheres-18k-c.json,$seed/spheres-76k-c.json,$seed/spheres-174k-c.json"
    case $part in
    vdsm) set -- --tier gl4 --vdsm --size 800x600 --scenes "$c_scenes" --vdsm-frames 10 "$@" ;;
    vdsm-1280) set -- --tier gl4 --vdsm --size 1280x720 --scenes "$c_scenes" --vdsm-frames 10 "$@" ;;
    csg) set -- --csg --csg-frames 11 "$@" ;;
    csg-readback) set -- --csg --csg-readback --csg-frames 11 "$@" ;;
    deep) set -- --deep "$@" ;;
    peel) set -- --peel "$@" ;;
    shadows) set -- --shadows --shadow-lights 1,8 "$@" ;;
    *) echo "unknown part '$part' (vdsm, vdsm-1280, csg, csg-readback, deep, peel, shadows)" >&2
       exit 2 ;;
    esac
    echo "stin-bench $*" > "$out/$part.txt"
    "$carry/stin-bench" "$@" >> "$out/$part.txt" 2>&1 || echo "exit $?" >> "$out/$part.txt"
    tail -n 40 "$out/$part.txt"
}

case ${1:-} in
pack) pack ;;
run) [ $# -ge 2 ] || { echo "usage: $0 run PART [OPTION...]" >&2; exit 2; }
    shift
    run "$@" ;;
*) sed -n '3,16p' "$0" >&2; exit 2 ;;
esac
