#!/bin/sh
# examples/readme_check.sh README TABLE
#
# Checks that the README's demo table (the lines between the marker comments
# <!-- demo-table --> and <!-- /demo-table -->) is the table `make demo`
# wrote to out/table.md, apart from the time column (the last cell of every
# table line), which changes from run to run.  Exits non-zero on a mismatch
# and shows the difference.
#
# examples/readme_check.sh --update README TABLE
#
# Replaces the block's contents with TABLE (make readme-table), for the day
# the library's results change.
update=0
if [ "$1" = "--update" ]; then update=1; shift; fi
readme=${1:-README.md}
table=${2:-out/table.md}
[ -f "$table" ] || { echo "readme-check: $table missing: run make demo"; exit 1; }
if ! grep -q '^<!-- demo-table -->' "$readme" || ! grep -q '^<!-- /demo-table -->' "$readme"; then
    echo "readme-check: $readme has no <!-- demo-table --> ... <!-- /demo-table --> block"; exit 1
fi
if [ "$update" = 1 ]; then
    awk -v table="$table" '
        /^<!-- demo-table -->/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
        /^<!-- \/demo-table -->/ { skip = 0 }
        !skip { print }' "$readme" >"$readme.tmp" && mv "$readme.tmp" "$readme"
    echo "readme-table: $readme now holds $table"
    exit 0
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
