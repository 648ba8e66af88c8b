#!/bin/sh
# tests/install_check.sh PREFIX CC
#
# What `make install PREFIX=...` left in PREFIX (make installs there before
# this runs): the three headers, the command-line tool and the pkg-config
# file, used as a user would: `pkg-config --cflags --libs plateau` gives the
# flags, the plateau quick start copied alone into a temporary directory
# (no header beside it) compiles with them and runs, and the installed tool
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
         share/pkgconfig/plateau.pc; do
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

echo "install_check: $passed checks passed, $failed failed"
[ "$failed" -eq 0 ]
