#!/bin/sh
# tests/install_check.sh PREFIX CC
#
# What `make install PREFIX=...` left in PREFIX (make installs there before
# this runs): the three headers, the command-line tool, the pkg-config file
# and the CMake package, used as a user would: `pkg-config --cflags --libs
# plateau` gives the flags, the plateau quick start copied alone into a
# temporary directory (no header beside it) compiles with them and runs;
# a CMake project of that quick start finds the package with
# find_package(plateau 0.1 REQUIRED), links plateau::plateau, builds and
# runs, and find_package(plateau 9.0) is refused; and the installed tool
# reports the headers' version.  Prints one line per check and
# "install_check: P checks passed, F failed" (the line tests/run.sh counts).
prefix=$1
cc=${2:-cc}
passed=0
failed=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/plateau-install.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM

ok() { passed=$((passed + 1)); echo "  ok   $*"; }
bad() { failed=$((failed + 1)); echo "FAIL $*"; }

version=$(sed -n 's/^#define PLATEAU_VERSION "\([^"]*\)".*/\1/p' plateau.h)

for f in include/plateau.h include/plateau_lm.h include/plateau_delaunay.h bin/plateau \
         share/pkgconfig/plateau.pc share/cmake/plateau/plateau-config.cmake \
         share/cmake/plateau/plateau-config-version.cmake; do
    if [ -f "$prefix/$f" ]; then ok "$f installed"; else bad "$f missing under $prefix"; fi
done
for h in plateau.h plateau_lm.h plateau_delaunay.h; do
    cmp -s "$h" "$prefix/include/$h" || bad "include/$h differs from ./$h"
done

got=$("$prefix/bin/plateau" --version 2>&1)
if [ "$got" = "plateau $version" ]; then ok "bin/plateau --version: $got"
else bad "bin/plateau --version printed '$got', not 'plateau $version'"; fi

if ! command -v pkg-config >/dev/null 2>&1; then
    echo "  pkg-config: skipped (not installed)"
else
    PKG_CONFIG_PATH=$prefix/share/pkgconfig
    export PKG_CONFIG_PATH
    got=$(pkg-config --modversion plateau 2>&1)
    if [ "$got" = "$version" ]; then ok "pkg-config --modversion plateau: $got"
    else bad "pkg-config --modversion plateau printed '$got', not '$version'"; fi
    flags=$(pkg-config --cflags --libs plateau 2>&1)
    case "$flags" in
    *"-I$prefix/include"*-lm*) ok "pkg-config --cflags --libs plateau: $flags" ;;
    *) bad "pkg-config --cflags --libs plateau printed '$flags'" ;;
    esac
    cp examples/plateau_quickstart.c "$tmp/"
    # shellcheck disable=SC2086 # the flags are words
    if (cd "$tmp" && $cc -std=c99 -O0 plateau_quickstart.c -o quickstart $flags) >"$tmp/cc.log" 2>&1 &&
        (cd "$tmp" && ./quickstart >/dev/null 2>&1); then
        ok "the plateau quick start compiles with those flags alone and runs"
    else
        bad "the plateau quick start with the installed headers: $(head -c 400 "$tmp/cc.log")"
    fi
fi

if ! command -v cmake >/dev/null 2>&1; then
    echo "  cmake: skipped (not installed)"
else
    mkdir -p "$tmp/cmake"
    cp examples/plateau_quickstart.c "$tmp/cmake/"
    cat >"$tmp/cmake/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.5)
project(use_plateau C)
find_package(plateau 0.1 REQUIRED)
add_executable(quickstart plateau_quickstart.c)
target_link_libraries(quickstart PRIVATE plateau::plateau)
set_property(TARGET quickstart PROPERTY C_STANDARD 99)
CMAKE
    if (cd "$tmp/cmake" && cmake -S . -B build -DCMAKE_PREFIX_PATH="$prefix" &&
        cmake --build build && ./build/quickstart) >"$tmp/cmake.log" 2>&1; then
        ok "find_package(plateau 0.1 REQUIRED) and plateau::plateau: the quick start builds and runs"
    else
        bad "the CMake package: $(grep -iE 'error|warning' "$tmp/cmake.log" | head -c 400)"
    fi
    mkdir -p "$tmp/cmake9"
    printf 'cmake_minimum_required(VERSION 3.5)\nproject(p NONE)\nfind_package(plateau 9.0 REQUIRED)\n' \
        >"$tmp/cmake9/CMakeLists.txt"
    if (cd "$tmp/cmake9" && cmake -S . -B build -DCMAKE_PREFIX_PATH="$prefix") >"$tmp/cmake9.log" 2>&1; then
        bad "find_package(plateau 9.0) accepted version $version"
    else
        ok "find_package(plateau 9.0) refuses version $version"
    fi
fi

echo "install_check: $passed checks passed, $failed failed"
[ "$failed" -eq 0 ]
