#!/bin/sh
# SPDX-License-Identifier: MIT
# make install into a scratch DESTDIR; an application builds and runs against
# it through pkg-config and through CMake's find_package (which refuses a
# version the install is not); make uninstall leaves no file behind.
# Run from the repository root after the build.
set -u
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
prefix=/opt/stin
root=$dir$prefix
app=tests/cli/install_consumer.c
version=$(sed -n 's/^#define STIN_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' include/stin/stin.h | paste -sd.)

if ! make -s --no-print-directory install DESTDIR="$dir" PREFIX=$prefix > "$dir/log" 2>&1; then
    echo "FAIL install: make install failed: $(tail -n 1 "$dir/log")"
    exit 0
fi

flags=$(PKG_CONFIG_PATH=$root/lib/pkgconfig PKG_CONFIG_SYSROOT_DIR=$dir pkg-config --cflags --libs stin)
if cc -std=c99 -Wall -Werror "$app" $flags -o "$dir/pc-app" > "$dir/log" 2>&1 &&
    out=$("$dir/pc-app") && [ "$out" = "stin $version" ]; then
    echo "PASS install-pkg-config: built and ran against the installed header and library ($out)"
else
    echo "FAIL install-pkg-config: $(tail -n 1 "$dir/log")"
fi

cmake_app() { # $1: the version find_package asks for; builds into $dir/cm-$1
    mkdir -p "$dir/cm-$1"
    cat > "$dir/cm-$1/CMakeLists.txt" << END
cmake_minimum_required(VERSION 3.13)
project(consumer C)
find_package(stin $1 REQUIRED)
add_executable(app $PWD/$app)
target_link_libraries(app stin::stin)
END
    cmake -S "$dir/cm-$1" -B "$dir/cm-$1/build" -DCMAKE_PREFIX_PATH="$root" > "$dir/log" 2>&1 &&
        cmake --build "$dir/cm-$1/build" >> "$dir/log" 2>&1
}
if ! command -v cmake > /dev/null 2>&1; then
    echo "SKIP install-cmake: no cmake on this machine"
elif cmake_app "${version%.*}" && out=$("$dir/cm-${version%.*}/build/app") &&
    [ "$out" = "stin $version" ]; then
    if cmake_app 9.0; then
        echo "FAIL install-cmake: find_package(stin 9.0) accepted version $version"
    else
        echo "PASS install-cmake: find_package(stin ${version%.*}) built and ran ($out); 9.0 refused"
    fi
else
    echo "FAIL install-cmake: $(tail -n 3 "$dir/log" | tr '\n' ' ')"
fi

# The examples, built against the install as their headers say, and their
# pictures checked against the exact shadow (tests/cli/example_check.c).
cc -std=c99 -D_DEFAULT_SOURCE -Wall -Wextra -Werror tests/cli/example_check.c -lm -o "$dir/check" 2> "$dir/log" ||
    echo "FAIL examples: the checker does not build: $(tail -n 1 "$dir/log")"
for ex in osmesa_shadow:-lOSMesa egl_shadow:-lEGL egl_app_shader:-lEGL skinned:-lEGL; do
    name=${ex%%:*}
    if ! cc -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -pedantic \
        "examples/${name}.c" $flags ${ex#*:} -lm -o "$dir/$name" > "$dir/log" 2>&1; then
        echo "FAIL example-$name: does not build: $(tail -n 1 "$dir/log")"
        continue
    fi
    # the EGL examples on OpenGL ES 2.0 and 3.0 too (--es; Mesa gives its
    # latest ES for any version asked, so the override pins the one asked)
    runs=-
    case $name in egl_*|skinned) runs="- 2 3" ;; esac
    for es in $runs; do
        if [ "$es" = - ]; then
            pic=$name.ppm
            set -- "$dir/$name" "$dir/$pic"
        else
            pic=$name-es$es.ppm
            set -- MESA_GLES_VERSION_OVERRIDE=$es.0 "$dir/$name" --es "$es" "$dir/$pic"
        fi
        if ! env "$@" > "$dir/log" 2>&1; then
            echo "SKIP example-$pic: no context here: $(tail -n 1 "$dir/log")"
        elif [ "$es" != - ] && ! grep -q "^context: OpenGL ES $es\.0" "$dir/log"; then
            echo "FAIL example-$pic: not an OpenGL ES $es.0 context: $(head -n 1 "$dir/log")"
        else
            "$dir/check" "$dir/$pic" | sed -e "s|$dir/||" -e 's#^\(PASS\|FAIL\) #\1 example-#'
        fi
    done
done

make -s --no-print-directory uninstall DESTDIR="$dir" PREFIX=$prefix > "$dir/log" 2>&1
left=$(find "$root" -type f 2> /dev/null | sed "s|^$root/||" | tr '\n' ' ')
if [ -z "$left" ]; then
    echo "PASS install-uninstall: make uninstall removed every installed file"
else
    echo "FAIL install-uninstall: left $left"
fi
