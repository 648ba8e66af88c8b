#!/bin/sh
# tests/progress.sh build LOG SECONDS TARGET... -- COMMAND...
#   Runs COMMAND with its output into LOG and, every SECONDS while it runs,
#   prints how many of the TARGETs exist ("  built 57 of 112 (1 min 20 s)"),
#   so that a long build is never silent.  Exits with COMMAND's status.
#
# tests/progress.sh pass SECONDS -- COMMAND...
#   Runs COMMAND with its output passed through and prints
#   "  ... still running (T s)" whenever SECONDS pass without a line from it.
#   Exits with COMMAND's status.
#
# make test runs its build and its test binaries through this.
mode=$1
shift
t0=$(date +%s)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/plateau-progress.XXXXXX") || exit 1
ticker=
cleanup() {
    [ -n "$ticker" ] && kill "$ticker" 2>/dev/null
    rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

elapsed() {
    s=$(( $(date +%s) - t0 ))
    if [ "$s" -ge 60 ]; then echo "$((s / 60)) min $((s % 60)) s"; else echo "$s s"; fi
}

case "$mode" in
build)
    log=$1
    secs=$2
    shift 2
    : >"$tmp/targets"
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do
        echo "$1" >>"$tmp/targets"
        shift
    done
    shift
    total=$(wc -l <"$tmp/targets" | tr -d ' ')
    (
        # one-second sleeps, so that none outlives the ticker by more
        n=0
        while sleep 1; do
            n=$((n + 1))
            [ "$n" -lt "$secs" ] && continue
            n=0
            built=0
            while read -r t; do [ -e "$t" ] && built=$((built + 1)); done <"$tmp/targets"
            echo "  built $built of $total ($(elapsed))"
        done
    ) &
    ticker=$!
    "$@" >"$log" 2>&1
    status=$?
    ;;
pass)
    secs=$1
    shift 2
    date +%s >"$tmp/last"
    (
        while sleep 1; do
            now=$(date +%s)
            last=$(cat "$tmp/last" 2>/dev/null || echo "$now")
            if [ $((now - last)) -ge "$secs" ]; then
                echo "  ... still running ($(elapsed))"
                echo "$now" >"$tmp/last"
            fi
        done
    ) &
    ticker=$!
    { "$@"; echo $? >"$tmp/status"; } 2>&1 | while IFS= read -r line; do
        printf '%s\n' "$line"
        date +%s >"$tmp/last"
    done
    status=$(cat "$tmp/status" 2>/dev/null || echo 1)
    ;;
*)
    echo "usage: tests/progress.sh build LOG SECONDS TARGET... -- COMMAND... | pass SECONDS -- COMMAND..." >&2
    exit 2
    ;;
esac
kill "$ticker" 2>/dev/null
wait "$ticker" 2>/dev/null
ticker=
exit "$status"
