#!/bin/sh
# examples/readme_outputs.sh
#
# Runs the commands whose output the README shows, typed as a user types
# them (the README's compile lines included), and writes each session to
# out/readme/NAME.txt: every command as "$ command", then what it printed
# (standard output, then standard error), then "[exit status N]" when N is
# not 0.  They run in a scratch copy of the files they read
# (out/readme/run/), so that nothing lands in the top directory.
# examples/readme_check.sh compares the README's blocks with these files.
# Needs build/plateau and build/gcc/test_lm_fit (make readme-check builds
# them).
out=out/readme
run=$out/run
rm -rf "$out"
mkdir -p "$run/examples" "$run/cli/samples" "$run/build" || exit 1
cp plateau.h plateau_lm.h plateau_delaunay.h "$run/" &&
    cp examples/*_quickstart.c "$run/examples/" &&
    cp cli/samples/*.txt "$run/cli/samples/" &&
    cp build/plateau build/gcc/test_lm_fit "$run/build/" || exit 1

status=0
file=

# session NAME: the file the next commands go to
session() { file=$out/$1.txt; : >"$file"; }

# cmd COMMAND...: one command, run in the scratch directory
cmd() {
    printf '$ %s\n' "$*" >>"$file"
    (cd "$run" && "$@") >"$out/.stdout" 2>"$out/.stderr"
    rc=$?
    # the one line that changes from run to run: the elapsed time
    grep -v '^  elapsed ' "$out/.stdout" >>"$file"
    cat "$out/.stderr" >>"$file"
    [ "$rc" -ne 0 ] && echo "[exit status $rc]" >>"$file"
    rm -f "$out/.stdout" "$out/.stderr"
    return 0
}

# must COMMAND...: as cmd, and the check fails unless it exits 0
must() {
    cmd "$@"
    if tail -n 1 "$file" | grep -q '^\[exit status'; then
        echo "readme-outputs: '$*' failed (see $file)"
        status=1
    fi
}

for q in plateau lm delaunay; do
    session ${q}_quickstart
    must cc -std=c99 -O2 -I. examples/${q}_quickstart.c -o ${q}_quickstart -lm
    must c++ -x c++ -O2 -I. examples/${q}_quickstart.c -o ${q}_quickstart_cxx -lm
    must ./${q}_quickstart
done

session lm-nist
must env HARNESS_FILTER=test_nist_accuracy build/test_lm_fit

session cli-helicoid
must build/plateau cli/samples/helicoid.txt -n 20 -o helicoid.obj --svg helicoid.svg

session cli-help
must build/plateau --version
must build/plateau --help

session cli-pattern
must build/plateau cli/samples/sail-hypar.txt -n 300 --pattern 0.4 --pattern-marks 0.2 --pattern-svg sail-panels.svg --pattern-dxf sail-panels.dxf

session cli-turns
cmd build/plateau cli/samples/helicoid-turns.txt --method paper-literal -o turns.obj

exit "$status"
