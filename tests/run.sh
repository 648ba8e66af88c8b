#!/bin/sh
# tests/run.sh LOG TEST_BINARY... -- HEADER_CHECK...
#
# Runs every test binary (each prints "<name>: P checks passed, F failed"),
# counts every header check (an object that exists was built with -Werror),
# and prints the suite's closing line "N passed, N failed".  It prints one
# line per stage as it goes: each binary's result when it finishes, a line
# before the fuzz runs, the header checks' count.  A binary that did
# not build, crashed, or exited non-zero counts as a failure; the build log
# lines for it are shown.  Exits non-zero on any failure.
log=$1; shift
passed=0
failed=0
t0=$(date +%s)
nbins=0
nfuzz=0
for a in "$@"; do
    [ "$a" = "--" ] && break
    case "$a" in *.check) nfuzz=$((nfuzz + 1)) ;; *) nbins=$((nbins + 1)) ;; esac
done
echo "running $nbins test binaries, one line each as it finishes ..."
fuzz_announced=0

show_build_errors() {
    # the compiler's complaints about this target, from the -k build log
    grep -n -A12 -- "$1" "$log" 2>/dev/null | grep -E 'error|warning|Error' | head -20
}

while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    bin=$1; shift
    case "$bin" in
    *.check)
        if [ "$fuzz_announced" = 0 ]; then
            echo "fuzzing: $nfuzz libFuzzer targets, a short run each ($(( $(date +%s) - t0 )) s so far) ..."
            fuzz_announced=1
        fi ;;
    esac
    if [ ! -x "$bin" ]; then
        echo "FAIL $bin: did not build"
        show_build_errors "$bin"
        failed=$((failed + 1))
        continue
    fi
    out=$("./$bin" 2>&1)
    rc=$?
    line=$(printf '%s\n' "$out" | grep -E '^[A-Za-z0-9_]+: [0-9]+ checks passed, [0-9]+ failed$' | tail -n 1)
    if [ -z "$line" ]; then
        printf '%s\n' "$out" | tail -n 30
        echo "FAIL $bin: exited $rc without a result line (crash?)"
        failed=$((failed + 1))
        continue
    fi
    p=$(printf '%s' "$line" | sed -E 's/.*: ([0-9]+) checks passed, ([0-9]+) failed/\1/')
    f=$(printf '%s' "$line" | sed -E 's/.*: ([0-9]+) checks passed, ([0-9]+) failed/\2/')
    if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then
        printf '%s\n' "$out" | grep -E '^FAIL|ERROR|runtime error|Sanitizer' | head -n 40
        [ "$f" -eq 0 ] && f=1 && echo "FAIL $bin: exit code $rc"
    fi
    echo "  $bin: $p passed, $f failed"
    passed=$((passed + p))
    failed=$((failed + f))
done
[ "$1" = "--" ] && shift

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
[ "$hp" -gt 0 ] && echo "  header checks (C99 gcc/clang, C++ g++/clang++, static, include orders, link): $hp passed"
echo "ran in $(( $(date +%s) - t0 )) s"
passed=$((passed + hp))

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
