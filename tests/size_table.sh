#!/bin/sh
# tests/size_table.sh [OUT]
#
# The cost of each configuration of the switches (plateau.h's SWITCHES):
# the implementation translation unit (tests/impl.c: the three headers'
# implementations) compiled by $CC (default gcc) with -std=c99 at -O2 and at
# -Os, once with no switch, once per switch alone and once with all of
# them.  Writes a Markdown table (default out/size-table.md) of the text
# bytes (`size`: code, read-only data and unwind tables) at -O2 and -Os
# and the compile's user CPU seconds at -O2, the last column; the README
# copies the table and make readme-check compares it, the seconds aside
# (they vary with the machine's load; the README says where they were
# measured).  One compile at a time, so that the seconds are the
# compiler's alone.
out=${1:-out/size-table.md}
CC=${CC:-gcc}
SIZE=${SIZE:-size}
command -v "$SIZE" >/dev/null 2>&1 || { echo "size_table.sh: $SIZE not found (binutils)"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/size-table.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM

# "name|flags" per line: none, each switch alone, all of them
ALL="-DPLATEAU_NO_STABILITY -DPLATEAU_NO_MEMBRANES -DPLATEAU_NO_LOOPS -DPLATEAU_NO_COARSE_TO_FINE"
ALL="$ALL -DPLATEAU_NO_SVG -DPLATEAU_NO_PARSERS -DPLATEAU_LM_NO_SPARSE -DPLATEAU_LM_NO_CONSTRAINTS"
ALL="$ALL -DPLATEAU_NO_PATTERNS -DPLATEAU_NO_SUPPORTS -DPLATEAU_NO_SLIDING -DPLATEAU_NO_ACCURACY"
ALL="$ALL -DPLATEAU_NO_QUALITY_SEEDING -DPLATEAU_LM_NO_EXTRAS -DPLATEAU_NO_PLY_OFF_STL -DPLATEAU_NO_EXTRAS"
configs="none (every feature)|
PLATEAU_NO_STABILITY|-DPLATEAU_NO_STABILITY
PLATEAU_NO_MEMBRANES|-DPLATEAU_NO_MEMBRANES
PLATEAU_NO_LOOPS|-DPLATEAU_NO_LOOPS
PLATEAU_NO_COARSE_TO_FINE|-DPLATEAU_NO_COARSE_TO_FINE
PLATEAU_NO_SVG|-DPLATEAU_NO_SVG
PLATEAU_NO_PLY_OFF_STL|-DPLATEAU_NO_PLY_OFF_STL
PLATEAU_NO_PARSERS|-DPLATEAU_NO_PARSERS
PLATEAU_LM_NO_SPARSE|-DPLATEAU_LM_NO_SPARSE
PLATEAU_LM_NO_CONSTRAINTS|-DPLATEAU_LM_NO_CONSTRAINTS
PLATEAU_NO_PATTERNS|-DPLATEAU_NO_PATTERNS
PLATEAU_NO_SUPPORTS|-DPLATEAU_NO_SUPPORTS
PLATEAU_NO_SLIDING|-DPLATEAU_NO_SLIDING
PLATEAU_NO_ACCURACY|-DPLATEAU_NO_ACCURACY
PLATEAU_NO_QUALITY_SEEDING|-DPLATEAU_NO_QUALITY_SEEDING
PLATEAU_LM_NO_EXTRAS|-DPLATEAU_LM_NO_EXTRAS
PLATEAU_NO_EXTRAS|-DPLATEAU_NO_EXTRAS
all sixteen|$ALL"

# text bytes of object $1
text_of() { "$SIZE" "$1" | awk 'NR == 2 { print $1 }'; }

mkdir -p "$(dirname "$out")"
{
    echo "| configuration | text at -O2 (bytes) | text at -Os (bytes) | compile at -O2 (user s) |"
    echo "|---|---:|---:|---:|"
} >"$tmp/table"
echo "$configs" | while IFS='|' read -r name flags; do
    # the user CPU seconds of the -O2 compile: the children's line of `times`
    # shellcheck disable=SC2086
    secs=$( ( $CC -std=c99 -O2 $flags -I. -c tests/impl.c -o "$tmp/o2.o" || exit 1; times ) |
            awk 'NR == 2 { t = $1; m = t; sub(/m.*/, "", m); s = t; sub(/^[0-9]+m/, "", s); sub(/s$/, "", s);
                           printf "%.1f", m * 60 + s }')
    [ -f "$tmp/o2.o" ] || { echo "size_table.sh: $name does not compile at -O2"; exit 1; }
    # shellcheck disable=SC2086
    $CC -std=c99 -Os $flags -I. -c tests/impl.c -o "$tmp/os.o" || { echo "size_table.sh: $name does not compile at -Os"; exit 1; }
    echo "| $name | $(text_of "$tmp/o2.o") | $(text_of "$tmp/os.o") | $secs |" >>"$tmp/table"
    echo "  $name: $(text_of "$tmp/o2.o") bytes at -O2, $secs s" >&2
    rm -f "$tmp/o2.o" "$tmp/os.o"
done || exit 1
cp "$tmp/table" "$out"
echo "size_table.sh: wrote $out" >&2
