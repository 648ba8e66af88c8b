#!/bin/sh
# examples/readme_check.sh README TABLE
#
# Checks that the README's demo table (the lines between the marker comments
# <!-- demo-table --> and <!-- /demo-table -->) is the table `make demo`
# wrote to out/table.md, apart from the time column (the last cell of every
# table line), which changes from run to run.  Exits non-zero on a mismatch
# and shows the difference.
readme=${1:-README.md}
table=${2:-out/table.md}
[ -f "$table" ] || { echo "readme-check: $table missing: run make demo"; exit 1; }
if ! grep -q '^<!-- demo-table -->' "$readme"; then
    echo "readme-check: $readme has no <!-- demo-table --> block"; exit 1
fi
tmp=${TMPDIR:-/tmp}/readme-check.$$
trap 'rm -f "$tmp.a" "$tmp.b"' EXIT
strip() { sed -E -e 's/[[:space:]]+$//' -e '/^\|/ s/\|[^|]*\|$/|/'; }
sed -n '/^<!-- demo-table -->/,/^<!-- \/demo-table -->/p' "$readme" \
    | sed -e '1d' -e '$d' | strip | sed -e '/./,$!d' >"$tmp.a"
strip <"$table" | sed -e '/./,$!d' >"$tmp.b"
# trailing blank lines do not count
printf '%s\n' "$(cat "$tmp.a")" >"$tmp.a"
printf '%s\n' "$(cat "$tmp.b")" >"$tmp.b"
if diff -u "$tmp.b" "$tmp.a" >/dev/null; then
    echo "readme-check: the README table matches $table (time column aside)"
else
    echo "readme-check: the README table differs from $table (- demo, + README):"
    diff -u "$tmp.b" "$tmp.a" | sed -n '3,40p'
    exit 1
fi
