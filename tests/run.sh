#!/bin/sh
# tests/run.sh LOG TEST_BINARY... -- HEADER_CHECK...
#
# Runs every test binary (each prints "<name>: P checks passed, F failed"),
# counts every header check (an object that exists was built with -Werror),
# and prints the suite's closing line "N passed, N failed".  It prints one
# line per binary as it finishes (with its seconds), then the header checks'
# count.  A binary that did not build, crashed, or exited non-zero counts as
# a failure; the build log lines for it are shown.  Exits non-zero on any
# failure.
#
# TEST_JOBS binaries run at once (default 2, the CI machine's cores).  The
# builds of one test (build/gcc/test_x, build/clang/test_x, build/san/test_x)
# form one group that runs in one lane, one after another, because they
# write the same scratch files; lanes take the next group from a queue, the
# groups that took longest in the last run (build/run-times.txt) first.
log=$1; shift
jobs=${TEST_JOBS:-2}
t0=$(date +%s)
work=build/run
rm -rf "$work"
mkdir -p "$work/queue" "$work/result"

# ---- the groups: one per test name, in order of first appearance
nbins=0
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    bin=$1; shift
    nbins=$((nbins + 1))
    key=$(basename "$bin" .check)
    case "$bin" in build/quickstart/*|build/install/*|build/web/*) key=${bin#build/}; key=$(echo "$key" | tr / _) ;; esac
    [ -e "$work/group.$key" ] || echo "$key" >>"$work/order"
    printf '%s %s\n' "$nbins" "$bin" >>"$work/group.$key"
done
[ "$1" = "--" ] && shift

# slowest first: last run's seconds per group (on a fresh clone, the ones
# that were slowest when this was written), unknown groups after them in
# their given order (sort -s keeps it)
times=build/run-times.txt
if [ ! -f "$times" ]; then
    times="$work/default-times"
    printf '%s\n' "7 test_membrane" "6 test_stability" "5 test_solve_loops" "4 test_work_bounds" \
        "3 test_cli_run" "2 test_alloc_fail" "1 test_manual" >"$times"
fi
i=0
while read -r key; do
    i=$((i + 1))
    secs=$(awk -v k="$key" '$2 == k { print $1 }' "$times")
    printf '%s %05d %s\n' "${secs:-0}" "$i" "$key"
done <"$work/order" | sort -s -k1,1nr -k2,2n | {
    rank=0
    while read -r secs i key; do
        rank=$((rank + 1))
        mv "$work/group.$key" "$work/queue/$(printf '%05d' "$rank").$key"
    done
}
ngroups=$(ls "$work/queue" | wc -l | tr -d ' ')
echo "running $nbins test binaries in $ngroups groups, $jobs at a time, one line each as it finishes ..."

show_build_errors() {
    # the compiler's complaints about this target, from the -k build log
    grep -n -A12 -- "$1" "$log" 2>/dev/null | grep -E 'error|warning|Error' | head -20
}

# run_one N BIN: runs one binary, writes "P F SECONDS" to result/N and prints
# its lines in one piece (so two lanes' lines do not interleave)
run_one() {
    n=$1; bin=$2
    out_file="$work/out.$n"
    s0=$(date +%s)
    if [ ! -x "$bin" ]; then
        { echo "FAIL $bin: did not build"; show_build_errors "$bin"; } >"$out_file"
        echo "0 1 0" >"$work/result/$n"
        cat "$out_file"
        return
    fi
    out=$("./$bin" 2>&1 </dev/null)
    rc=$?
    secs=$(( $(date +%s) - s0 ))
    line=$(printf '%s\n' "$out" | grep -E '^[A-Za-z0-9_]+: [0-9]+ checks passed, [0-9]+ failed$' | tail -n 1)
    if [ -z "$line" ]; then
        { printf '%s\n' "$out" | tail -n 30; echo "FAIL $bin: exited $rc without a result line (crash?)"; } >"$out_file"
        echo "0 1 $secs" >"$work/result/$n"
        cat "$out_file"
        return
    fi
    p=$(printf '%s' "$line" | sed -E 's/.*: ([0-9]+) checks passed, ([0-9]+) failed/\1/')
    f=$(printf '%s' "$line" | sed -E 's/.*: ([0-9]+) checks passed, ([0-9]+) failed/\2/')
    : >"$out_file"
    if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then
        printf '%s\n' "$out" | grep -E '^FAIL|ERROR|runtime error|Sanitizer' | head -n 40 >>"$out_file"
        [ "$f" -eq 0 ] && f=1 && echo "FAIL $bin: exit code $rc" >>"$out_file"
    fi
    echo "  $bin: $p passed, $f failed ($secs s)" >>"$out_file"
    echo "$p $f $secs" >"$work/result/$n"
    cat "$out_file"
}

# lane: takes groups from the queue (a rename claims one; a lane that loses
# the race tries the next) until it is empty
lane() {
    while :; do
        next=$(ls "$work/queue" 2>/dev/null | head -n 1)
        [ -z "$next" ] && break
        mv "$work/queue/$next" "$work/claimed.$next" 2>/dev/null || continue
        g0=$(date +%s)
        while read -r n bin; do
            run_one "$n" "$bin"
        done <"$work/claimed.$next"
        echo "$(( $(date +%s) - g0 )) ${next#*.}" >>"$work/times.$1"
    done
}

l=1
while [ "$l" -le "$jobs" ]; do
    lane "$l" &
    l=$((l + 1))
done
wait

passed=0
failed=0
n=1
while [ "$n" -le "$nbins" ]; do
    if [ -f "$work/result/$n" ]; then
        read -r p f secs <"$work/result/$n"
    else
        p=0; f=1; echo "FAIL binary $n of $nbins: no result (the runner was interrupted?)"
    fi
    passed=$((passed + p))
    failed=$((failed + f))
    n=$((n + 1))
done
cat "$work"/times.* 2>/dev/null | sort -k1,1nr >build/run-times.txt

hp=0
for chk in "$@"; do
    if [ -e "$chk" ]; then
        hp=$((hp + 1))
        case "${chk##*/}" in *link) runs=1 ;; *) runs=0 ;; esac
        if [ "$runs" = 1 ] && ! "./$chk" >/dev/null 2>&1; then
            echo "FAIL $chk: linked program failed"; hp=$((hp - 1)); failed=$((failed + 1))
        fi
    else
        echo "FAIL $chk: header check did not compile"
        show_build_errors "$chk"
        failed=$((failed + 1))
    fi
done
[ "$hp" -gt 0 ] && echo "  header checks (C99 gcc/clang, C++ g++/clang++, static, include orders, link, strict warnings): $hp passed"
echo "ran in $(( $(date +%s) - t0 )) s"
passed=$((passed + hp))

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
