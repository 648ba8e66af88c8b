#!/bin/sh
# examples/readme_check.sh [--update] README
#
# Checks that every number and every program text in the README is what the
# code produces now (make readme-check runs make demo and the programs
# first).  Exits non-zero, showing the difference, when one has gone stale.
#
# 1. The demo table: the lines between <!-- demo-table --> and
#    <!-- /demo-table --> are out/table.md, apart from the time column (the
#    last cell of every table line), which changes from run to run.
# 2. Blocks copied from a file: the lines between
#        <!-- file: PATH -->         (a source file, e.g. a quick start)
#        <!-- output: PATH -->       (what a program printed, under out/)
#    and the next <!-- /file --> or <!-- /output --> are PATH's contents,
#    inside a fenced code block when the first line is a ``` fence (the
#    fences are not compared).  "<!-- output: PATH (time column aside) -->"
#    compares a Markdown table without its last column.
# 3. The numbers of the prose: every number written with a decimal point or
#    an exponent (3.556042, 1e-6, 0.1.0), and every whole number from 1000
#    up, outside those blocks, must occur in one of the texts they check
#    (out/table.md and every PATH), so that it changes with them; the few
#    that come from elsewhere (the paper's own figures, which no code
#    produces) are listed in ALLOWED below with where they come from, and
#    the lines between <!-- quote: WHAT --> and <!-- /quote --> (a
#    quotation, such as the paper's reference list) are not read.
#    Whole numbers below 1000 (counts such as "three headers", inputs such
#    as n = 20) are not read.
#
# --update rewrites every block from its source (make readme-update), for
# the day the results change; the prose numbers are still checked.
update=0
if [ "$1" = "--update" ]; then update=1; shift; fi
readme=${1:-README.md}
table=out/table.md

# The paper's published figures and the fixed constants of the text that no
# program prints (each with its source).
ALLOWED='
2.941e-3 4.110e-3 9.192e-4 1.412e-3 4.786e-4 1000 10.74
'
# 2.941e-3 4.110e-3: the paper's helicoid ERR (its method, Chen et al.'s);
# 9.192e-4 1.412e-3: the same for the catenoid; 4.786e-4: its membrane's
# mean |H| (examples/NOTES.md, section 5, quotes all five).  1000:
# plateau_lm.h's default max_iterations (its manual); 10.74: the average minimum LRE of bench_lm's
# NIST StRD table (examples/NOTES.md, section 8).

tmp=$(mktemp -d "${TMPDIR:-/tmp}/readme-check.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
status=0

[ -f "$table" ] || { echo "readme-check: $table missing: run make demo"; exit 1; }
if ! grep -q '^<!-- demo-table -->' "$readme" || ! grep -q '^<!-- /demo-table -->' "$readme"; then
    echo "readme-check: $readme has no <!-- demo-table --> ... <!-- /demo-table --> block"; exit 1
fi

# the last cell of every table line removed, trailing blanks and leading
# and trailing blank lines dropped
strip_time() { sed -E -e 's/[[:space:]]+$//' -e '/^\|/ s/\|[^|]*\|$/|/'; }
trim() { sed -E -e 's/[[:space:]]+$//' | sed -e '/./,$!d' | awk '{ a[NR] = $0 } END { n = NR; while (n > 0 && a[n] == "") n--; for (i = 1; i <= n; i++) print a[i] }'; }

# ---- the blocks: one line per block, "kind<TAB>path<TAB>flags<TAB>first<TAB>last"
# (first and last: the README lines of its contents, fences excluded)
awk '
    function flush(kind, path, flags) { }
    /^<!-- demo-table -->/ { start = NR; kind = "table"; path = "'"$table"'"; flags = "time"; next }
    /^<!-- \/demo-table -->/ { if (kind == "table") print kind "\t" path "\t" flags "\t" start + 1 "\t" NR - 1; kind = ""; next }
    /^<!-- (file|output): / {
        line = $0
        sub(/^<!-- /, "", line); sub(/ -->[[:space:]]*$/, "", line)
        kind = line; sub(/:.*/, "", kind)
        path = line; sub(/^[a-z]+: /, "", path)
        flags = "-"
        if (path ~ / \(time column aside\)$/) { flags = "time"; sub(/ \(time column aside\)$/, "", path) }
        start = NR; fence = 0
        next
    }
    kind != "" && kind != "table" && !fence && NR == start + 1 && /^```/ { fence = 1; start = NR; next }
    /^<!-- quote: / { kind = "quote"; path = "-"; start = NR; fence = 0; next }
    /^<!-- \/quote -->/ { if (kind == "quote") print kind "\t" path "\t-\t" start + 1 "\t" NR - 1 "\t0"; kind = ""; next }
    /^<!-- \/(file|output) -->/ {
        last = NR - 1
        if (fence) last = NR - 2
        if (kind != "") print kind "\t" path "\t" flags "\t" start + 1 "\t" last "\t" fence
        kind = ""; next
    }
' "$readme" >"$tmp/blocks"

nblocks=0
: >"$tmp/sources"
cp "$readme" "$tmp/readme.new"
# blocks are rewritten from the last to the first, so line numbers hold
sort -t "$(printf '\t')" -k4,4nr "$tmp/blocks" >"$tmp/blocks.rev"
while IFS="$(printf '\t')" read -r kind path flags first last fence; do
    [ "$kind" = quote ] && continue
    nblocks=$((nblocks + 1))
    if [ ! -f "$path" ]; then
        echo "readme-check: $readme line $first: $path missing (make readme-check makes it)"
        status=1
        continue
    fi
    echo "$path" >>"$tmp/sources"
    if [ "$update" = 1 ]; then
        { head -n $((first - 1)) "$tmp/readme.new"; cat "$path"; tail -n +$((last + 1)) "$tmp/readme.new"; } \
            >"$tmp/readme.next" && mv "$tmp/readme.next" "$tmp/readme.new"
        continue
    fi
    sed -n "${first},${last}p" "$readme" >"$tmp/got"
    if [ "$flags" = time ]; then
        strip_time <"$tmp/got" | trim >"$tmp/a"
        strip_time <"$path" | trim >"$tmp/b"
    else
        trim <"$tmp/got" >"$tmp/a"
        trim <"$path" >"$tmp/b"
    fi
    if ! cmp -s "$tmp/a" "$tmp/b"; then
        echo "readme-check: $readme lines $first-$last differ from $path (- $path, + README):"
        diff -u "$tmp/b" "$tmp/a" | sed -n '3,30p'
        status=1
    fi
done <"$tmp/blocks.rev"
if [ "$update" = 1 ]; then
    mv "$tmp/readme.new" "$readme"
    echo "readme-update: $nblocks blocks of $readme rewritten from their sources"
    # the prose's numbers, against the rewritten README
    rm -rf "$tmp"
    exec sh "$0" "$readme"
fi

# ---- the numbers of the prose
# the README without its checked blocks and without dates (2026-12-02)
awk -v blocks="$tmp/blocks" '
    BEGIN { while ((getline l < blocks) > 0) { split(l, f, "\t"); for (i = f[4] - 1; i <= f[5] + 1; i++) skip[i] = 1 } }
    !(NR in skip) { print NR ": " $0 }
' "$readme" | sed -E 's/[0-9]{4}-[0-9]{2}-[0-9]{2}//g' >"$tmp/prose"
# every text the blocks check, as one list of number tokens
{ cat $(sort -u "$tmp/sources") 2>/dev/null; printf '%s\n' "$ALLOWED"; } |
    grep -oE '[0-9]+(\.[0-9]+)+([eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+|[0-9]+' | sort -u >"$tmp/known"
# the prose's numbers: the line number, then the token
awk '{
    line = $0; n = $1; sub(/:$/, "", n); sub(/^[0-9]+: /, "", line)
    # thin-space or blank grouped thousands ("183 701") read as one number
    while (match(line, /(^|[^0-9A-Za-z_.])[0-9]{1,3}( [0-9]{3})+([^0-9]|$)/)) {
        tok = substr(line, RSTART, RLENGTH); gsub(/[^0-9]/, "", tok)
        print n "\t" tok
        line = substr(line, 1, RSTART) "#" substr(line, RSTART + RLENGTH - 1)
    }
    while (match(line, /[0-9]+(\.[0-9]+)+([eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+|[0-9]+/)) {
        tok = substr(line, RSTART, RLENGTH)
        before = RSTART > 1 ? substr(line, RSTART - 1, 1) : ""
        after = substr(line, RSTART + RLENGTH, 1)
        line = substr(line, RSTART + RLENGTH)
        if (before ~ /[A-Za-z_]/ || after ~ /[A-Za-z_]/) continue   # C99, wasm32, x86, 3D
        if (tok ~ /^[0-9]+$/ && tok + 0 < 1000) continue
        print n "\t" tok
    }
}' "$tmp/prose" >"$tmp/numbers"
unknown=0
while IFS="$(printf '\t')" read -r n tok; do
    if ! grep -qxF "$tok" "$tmp/known"; then
        [ "$unknown" = 0 ] && echo "readme-check: numbers in $readme that no checked output contains (stale, or unchecked):"
        echo "  line $n: $tok"
        unknown=$((unknown + 1))
    fi
done <"$tmp/numbers"
[ "$unknown" -gt 0 ] && status=1
nnum=$(wc -l <"$tmp/numbers" | tr -d ' ')

if [ "$status" = 0 ] && [ "$update" = 0 ]; then
    echo "readme-check: $readme matches: $nblocks blocks (the demo table, programs and their output) and $nnum numbers of the prose"
fi
exit "$status"
