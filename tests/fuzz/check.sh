#!/bin/sh
# tests/fuzz/check.sh NAME BINARY SECONDS [short]
#
# One time-bounded libFuzzer run of BINARY, printed as a test result line
# "NAME: P checks passed, F failed" (one check: the run found nothing) so that
# tests/run.sh counts it like a test binary.
#   make fuzz:  the corpus grows in build/fuzz/corpus/NAME across runs
#               (seeded from tests/fuzz/seeds/NAME).
#   short:      (make test-full) a fresh corpus from the seeds only, removed
#               afterwards: libFuzzer replays a whole corpus before it looks
#               at the clock, so a grown corpus would stretch the run.
# A crashing input is saved as build/fuzz/NAME-crash-... and its stack shown.
name=$1
bin=$2
secs=${3:-5}
seeds=tests/fuzz/seeds/$name
[ -d "$seeds" ] || seeds=
if [ "$4" = "short" ]; then
    corpus=build/fuzz/short-$name.$$
    rm -rf "$corpus"
else
    corpus=build/fuzz/corpus/$name
fi
mkdir -p "$corpus"
# fuzz_solve runs the whole pipeline: its many coverage features made the
# entropic schedule's bookkeeping (InputCorpus::UpdateFeatureFrequency) a
# third of its time, 480 inputs per CPU second against 1 280 without it;
# and its inputs say nothing past 6 + 3 * 12 bytes.
extra=
[ "$name" = fuzz_solve ] && extra="-entropic=0 -max_len=42"
out=$("./$bin" -max_total_time="$secs" -timeout=20 -print_final_stats=1 $extra \
      -artifact_prefix="build/fuzz/$name-" "$corpus" $seeds 2>&1)
rc=$?
runs=$(printf '%s\n' "$out" | sed -n 's/^stat::number_of_executed_units: *//p' | tail -n 1)
echo "$name: ${runs:-0} inputs in ${secs} s, corpus $(ls "$corpus" | wc -l) files"
[ "$4" = "short" ] && rm -rf "$corpus"
if [ "$rc" -eq 0 ]; then
    echo "$name: 1 checks passed, 0 failed"
else
    printf '%s\n' "$out" | grep -v '^#' | tail -n 40
    printf '%s\n' "$out" | grep -E 'Test unit written|artifact' | sed 's/^/FAIL /'
    echo "$name: 0 checks passed, 1 failed"
    exit 1
fi
