#!/bin/sh
# tests/quickstart_check.sh BINARY...
#
# The README's quick starts (examples/*_quickstart.c), each built by make as
# C and as C++ (BINARY is build/quickstart/<name>.<compiler>): every binary
# runs in a fresh temporary directory (the plateau quick start writes
# saddle.obj there) and exits 0, and the builds of one quick start print the
# same text.  make readme-check compares that text with the README.  Prints
# one line per check and "quickstarts: P checks passed, F failed" (the line
# tests/run.sh counts).
passed=0
failed=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/plateau-quickstart.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
top=$(pwd)

ok() { passed=$((passed + 1)); echo "  ok   $*"; }
bad() { failed=$((failed + 1)); echo "FAIL $*"; }

for bin in "$@"; do
    name=${bin##*/}
    stem=${name%.*}
    if [ ! -x "$bin" ]; then
        bad "$bin did not build (see the build log)"
        continue
    fi
    rm -rf "$tmp/run"
    mkdir "$tmp/run"
    (cd "$tmp/run" && "$top/$bin" >"$tmp/$name.out" 2>"$tmp/$name.err")
    rc=$?
    if [ "$rc" -ne 0 ]; then
        bad "$bin exited $rc: $(head -c 300 "$tmp/$name.err")"
        continue
    fi
    if [ ! -s "$tmp/$name.out" ]; then
        bad "$bin printed nothing"
        continue
    fi
    if [ "$stem" = plateau_quickstart ] && ! grep -q '^f ' "$tmp/run/saddle.obj" 2>/dev/null; then
        bad "$bin wrote no triangles to saddle.obj"
        continue
    fi
    if [ -f "$tmp/$stem.first" ]; then
        first=$(cat "$tmp/$stem.first")
        if cmp -s "$tmp/$first.out" "$tmp/$name.out"; then
            ok "$bin: exit 0, the same output as $first"
        else
            bad "$bin prints other text than $first:"
            diff "$tmp/$first.out" "$tmp/$name.out" | head -n 10
        fi
    else
        echo "$name" >"$tmp/$stem.first"
        ok "$bin: exit 0, $(wc -l <"$tmp/$name.out" | tr -d ' ') lines of output"
    fi
done

echo "quickstarts: $passed checks passed, $failed failed"
[ "$failed" -eq 0 ]
