#!/bin/sh
# tests/alloc_sites.sh TEST.c FILTER [CFLAGS...]
#   The distinct allocation call sites the tests of TEST.c whose names
#   contain FILTER reach in their full (never refused) runs, one per line
#   as "function file:line", sorted: the library's line that called
#   plateau__alloc.  An out-of-memory sweep refuses each call of such a
#   run once, so these are the sites it fails.  Compiles TEST.c with the
#   implementation in it, -O0 and no inlining (so every call keeps its
#   frame) and countalloc.h's COUNTALLOC_SITES (glibc's backtrace), runs
#   it with HARNESS_FILTER=FILTER, and maps the return addresses with
#   addr2line.  Used to show that a smaller sweep fails the same sites:
#     sh tests/alloc_sites.sh tests/test_solve_loops.c alloc_fail >after.txt
src=$1; filter=$2; shift 2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/plateau-sites.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
${CC:-cc} -std=c99 -O0 -g -fno-inline -no-pie -DCOUNTALLOC_SITES -D_GNU_SOURCE -I. "$@" \
    -o "$tmp/t" "$src" -lm -pthread || exit 1
COUNTALLOC_SITES="$tmp/raw" HARNESS_FILTER="$filter" "$tmp/t" >"$tmp/out" 2>&1 || { cat "$tmp/out" >&2; exit 1; }
# every distinct return address, then each mapped to "function file:line"
# (the address less 1: the call instruction, not the one after it)
tr ' ' '\n' <"$tmp/raw" | sort -u >"$tmp/addrs"
while read -r a; do printf '%x\n' $((a - 1)); done <"$tmp/addrs" >"$tmp/calls"
addr2line -f -e "$tmp/t" <"$tmp/calls" | paste - - | awk '{ sub(/ \(discriminator.*/, ""); print }' >"$tmp/names"
paste "$tmp/addrs" "$tmp/names" | awk '{ print $1, $2, $3 }' >"$tmp/map"
# per call: the first frame above plateau__alloc (the allocation site),
# and with ALLOC_SITES_DEPTH=N the N frames from it (the call path)
awk -v depth="${ALLOC_SITES_DEPTH:-1}" 'NR == FNR { sub(/.*\//, "", $3); name[$1] = $2; where[$1] = $3; next }
     { for (i = 1; i <= NF; i++) if (name[$i] == "plateau__alloc" && i < NF) {
           s = ""
           for (j = i + 1; j <= NF && j <= i + depth; j++) s = s (j > i + 1 ? " < " : "") name[$j] " " where[$j]
           print s; break } }' "$tmp/map" "$tmp/raw" | sort -u
