#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the Debian packages stin needs to build and test, if any are
# missing. Quiet when everything is there. As root it runs apt-get; otherwise
# it names the packages and the command, and fails.
set -u

# clang + libclang-rt-dev (libFuzzer's runtime, which clang only recommends):
# make fuzz. cmake: the install test builds an application with find_package.
# libopencsg-dev + libglew-dev: stin-bench --csg times OpenCSG beside stin
# (built without them, the section times stin alone).
# libopenscenegraph-dev: stin-bench --peers times osgShadow's techniques beside
# stin's on the same scenes (built without it, the section has stin's rows alone);
# assimp-testmodels: three of its scenes' models (without it they are skipped).
# libglfw3-dev: examples/viewer, the interactive viewer (built when present);
# xvfb + xauth: its test runs it on a virtual display (xvfb-run);
# imagemagick + twm: the viewer's screenshot with its title bar (import -window root).
# emscripten: make web, libstin and its browser front end in WebAssembly;
# chromium: the browser image tests (headless, WebGL 2 on SwiftShader) and
# the demo page's screenshot (docs/web.md); nodejs runs emscripten and the
# tests' local server.
PACKAGES="build-essential pkg-config libegl-dev libgl-dev libosmesa6-dev \
libegl-mesa0 libgl1-mesa-dri libembree-dev libopenimageio-dev openimageio-tools \
libassimp-dev libcjson-dev libcmocka-dev clang libclang-rt-dev cmake \
libopencsg-dev libglew-dev libopenscenegraph-dev assimp-testmodels \
libglfw3-dev xvfb xauth imagemagick twm emscripten nodejs chromium"

if ! command -v dpkg >/dev/null 2>&1; then
    echo "install-deps: dpkg not found; install these (Debian names) by hand: $PACKAGES" >&2
    exit 1
fi

# One dpkg-query for every package (make check runs this first: a dpkg -s
# per package took 0.55 CPU s). Removed-but-configured packages are listed
# too, so the state must be "installed".
# shellcheck disable=SC2086 # one word per package, on purpose
installed=" $(dpkg-query -W -f='${db:Status-Status} ${Package}\n' $PACKAGES 2>/dev/null |
    awk '$1 == "installed" { printf "%s ", $2 }')"
missing=""
for pkg in $PACKAGES; do
    case $installed in
        *" $pkg "*) ;;
        *) missing="$missing $pkg" ;;
    esac
done
missing=${missing# }

if [ -z "$missing" ]; then
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    echo "install-deps: installing $missing"
    apt-get update || exit 1
    # shellcheck disable=SC2086 # one word per package, on purpose
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing || exit 1
    exit 0
fi

echo "install-deps: missing Debian packages: $missing" >&2
echo "install-deps: run as root:" >&2
echo "  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing" >&2
exit 1
