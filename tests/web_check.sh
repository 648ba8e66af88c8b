#!/bin/sh
# tests/web_check.sh PAGE_DIR CLI [CHROMIUM]
#
# The web build checked in a real browser.  Headless Chromium opens
# PAGE_DIR/index.html from file:// with a boundary and n in the address; the
# page loads the module (base64, no fetch), solves, and shows the result; the
# DOM it dumps is read back here and its area compared with the
# command-line tool's (CLI --json) on the same boundary, to 1e-12 relative.
# Also: the module imports nothing (read from the binary, and as the page's
# WebAssembly.Module.imports shows it), every shape opens showing the
# film's front side, and its boundary text shows each vertex on one line,
# unwrapped and whole.  Prints one line per check and "web_check: P checks
# passed, F failed" (the line tests/run.sh counts).
# Every Chromium run is bounded by timeout; its profile is a temporary
# directory, removed at the end.
page=$1
cli=$2
chromium=${3:-chromium}
passed=0
failed=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/plateau-web-check.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
abs=$(cd "$page" && pwd) || exit 1

ok() { passed=$((passed + 1)); echo "  ok   $*"; }
bad() { failed=$((failed + 1)); echo "FAIL $*"; }

# run_page QUERY: the page's DOM after its scripts ran, into $tmp/dom.html
run_page() {
    timeout -k 5 60 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
        --disable-extensions --user-data-dir="$tmp/profile" --virtual-time-budget=60000 \
        --dump-dom "file://$abs/index.html?$1" >"$tmp/dom.html" 2>>"$tmp/chromium.log"
}

# field ID: the text of the element with that id in the dump
field() {
    sed -n "s/.*id=\"$1\"[^>]*>\\([^<]*\\)<.*/\\1/p" "$tmp/dom.html" | head -n 1
}

# cli_area FILE N [METHOD]: the area the command-line tool reports
cli_area() {
    "$cli" "$1" -n "$2" --method "${3:-paper}" --json 2>/dev/null |
        sed -n 's/.*"area": \([^,]*\),.*/\1/p'
}

# same_area NAME PAGE_AREA CLI_AREA
same_area() {
    if [ -n "$2" ] && [ -n "$3" ] &&
        awk -v a="$2" -v b="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; exit !(d <= 1e-12 * s) }'; then
        ok "$1: area $2 in the browser, $3 from $cli"
    else
        bad "$1: area '$2' in the browser, '$3' from $cli (more than 1e-12 apart)"
    fi
}

# points FILE: a boundary file as the page's points=x,y,z;... parameter
points() {
    grep -v '^[[:space:]]*#' "$1" | awk 'NF == 3 { printf "%s%s,%s,%s", (n++ ? ";" : ""), $1, $2, $3 }'
}

imports=$(sh tests/web_imports.sh "$page/plateau.wasm")
if [ "$imports" = none ]; then ok "plateau.wasm ($(wc -c <"$page/plateau.wasm") bytes) imports nothing"
else bad "plateau.wasm imports: $imports"; fi

# the command-line tool's own sample boundaries, passed to the page
# (name:n:method, method 0 paper, 2 area)
for case in helicoid:25:0 catenoid:400:0 catenoid:30:2; do
    name=${case%%:*}
    rest=${case#*:}
    n=${rest%%:*}
    method=${rest#*:}
    cli_method=paper
    [ "$method" = 2 ] && cli_method=area
    file=cli/samples/$name.txt
    run_page "points=$(points "$file")&n=$n&method=$method"
    status=$(field status)
    what="$name n=$n method $cli_method"
    if [ "$status" = valid ]; then ok "$what: the page solved it ($(field time), $(field iterations) iterations)"
    else bad "$what: the page shows status '$status'"; continue; fi
    same_area "$what" "$(field area)" "$(cli_area "$file" "$n" "$cli_method")"
    if [ "$name" = helicoid ]; then
        if [ "$(field imports)" = none ]; then ok "the page's WebAssembly.Module.imports is empty"
        else bad "the page lists imports '$(field imports)'"; fi
    fi
done

# a boundary the page makes (the saddle), handed to the command-line tool
run_page "shape=saddle&n=40"
awk '/id="boundary-text"/ { on = 1; sub(/.*id="boundary-text"[^>]*>/, "") }
     on { end = sub(/<\/textarea>.*/, ""); print; if (end) exit }' "$tmp/dom.html" >"$tmp/saddle.txt"
if [ "$(grep -c . "$tmp/saddle.txt")" = 24 ]; then
    same_area "saddle n=40 (the page's boundary)" "$(field area)" "$(cli_area "$tmp/saddle.txt" 40)"
else
    bad "saddle: the page's boundary text has $(grep -c . "$tmp/saddle.txt") lines, not 24"
fi

# dragging: the page moves saddle vertex 5 by (15, -25) pixels through its
# pointer handlers and solves again; the moved boundary goes to the CLI
run_page "shape=saddle&n=30&drag=5,15,-25"
awk '/id="boundary-text"/ { on = 1; sub(/.*id="boundary-text"[^>]*>/, "") }
     on { end = sub(/<\/textarea>.*/, ""); print; if (end) exit }' "$tmp/dom.html" >"$tmp/dragged.txt"
solves=$(sed -n 's/.*data-solved="\([0-9]*\)".*/\1/p' "$tmp/dom.html" | head -n 1)
moved=$(awk 'FNR == NR { a[FNR] = $0; next } a[FNR] != $0 { d++ } END { print d + 0 }' \
    "$tmp/saddle.txt" "$tmp/dragged.txt")
if [ "$solves" = 2 ] && [ "$moved" = 1 ]; then
    same_area "saddle n=30 after dragging vertex 5" "$(field area)" "$(cli_area "$tmp/dragged.txt" 30)"
else
    bad "drag: $moved boundary lines changed (1 expected), $solves solves (2 expected)"
fi

# the page opens on the film's front side: most of the picture's area blue
# (the page writes the share to <body data-front-share>), for each shape
for shape in helicoid catenoid saddle ring; do
    run_page "shape=$shape&n=25"
    share=$(sed -n 's/.*data-front-share="\([0-9.]*\)".*/\1/p' "$tmp/dom.html" | head -n 1)
    if [ -n "$share" ] && awk -v s="$share" 'BEGIN { exit !(s > 0.5) }'; then
        ok "$shape opens on the film's front side ($share of the picture's area)"
    else
        bad "$shape opens with '$share' of the picture on the front side (more than 0.5 expected)"
    fi
    # the boundary text: one vertex a line, none wrapped (wrap="off"; the
    # page reads its white-space back and measures every line as shown
    # whole: <body data-boundary-fits>)
    fits=$(sed -n 's/.*data-boundary-fits="\([01]\)".*/\1/p' "$tmp/dom.html" | head -n 1)
    if grep -q '<textarea id="boundary-text"[^>]* wrap="off"' "$tmp/dom.html" && [ "$fits" = 1 ]; then
        ok "$shape: the boundary text shows each vertex on one line, unwrapped"
    else
        bad "$shape: the boundary text wraps or is cut (wrap=\"off\" $(grep -c '<textarea id="boundary-text"[^>]* wrap="off"' "$tmp/dom.html"), fits '$fits')"
    fi
done

echo "web_check: $passed checks passed, $failed failed"
[ "$failed" -eq 0 ]
