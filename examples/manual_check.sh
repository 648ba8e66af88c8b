#!/bin/sh
# examples/manual_check.sh NUMBERS
#
# Checks the numbers of the three manuals (the top comment of plateau.h,
# plateau_lm.h and plateau_delaunay.h) as examples/readme_check.sh checks
# the README's prose: every number written with a decimal point or an
# exponent (3.556042, 1e-6, 0.1.0), and every whole number from 1000 up,
# must occur in NUMBERS, the output of tests/test_manual.c (make
# readme-check writes it to out/readme/manual-numbers.txt), which checks
# each against the code's value (a default, a constant, a formula) and
# prints it, or the EXAMPLE's output it compares; the few that no code
# has are listed below, per header, with where they come from.  Dates
# (2026-12-02) are not read.  Exits non-zero, naming header, line and
# number, when one is neither.
numbers=${1:-out/readme/manual-numbers.txt}
[ -f "$numbers" ] || { echo "manual-check: $numbers missing (make readme-check writes it)"; exit 1; }

# The numbers no code has, with their sources.
ALLOWED_plateau_h='
0.4 0.5 2003 2007 2006 1e-150 1e150 1e-12 1e-10 1.5 2002 2008
'
# 0.4: the EXAMPLE's input (z = 0.4 cos 2t; test_manual compiles and runs
#   it); 0.5: the several-loops example's ring heights (an input);
# 2003, 2007, 2006: the years of the citations (Floater; Bobenko and
#   Springborn; Hormann and Floater); 2002, 2008: those of CUTTING
#   PATTERNS (Levy et al. and Desbrun et al.; Liu et al.);
# 1e-150, 1e150: tests/test_bad_input.c solves boundaries at those scales;
# 1e-12, 1e-10: the tolerances of tests/test_solve.c's invariance test
#   (method paper, method area), which the sentence names;
# 1.5: tests/test_solve_loops.c's rings at h = 1.5 R, which pinch.
ALLOWED_plateau_lm_h='
2004 5.0 3.0 1.8 1.1 1.0 0.1 3.16 1e-150
'
# 2004: the year of the citation (Madsen, Nielsen and Tingleff);
# 5.0 3.0 1.8 1.1 1.0 0.1: the EXAMPLE's data and start (inputs);
# 3.16: the number of the cited book's algorithm;
# 1e-150: tests/test_bad_input.c's problem at that scale.
ALLOWED_plateau_delaunay_h='
2003 1977 1985 2002 1993 1995 1989 1997 1990 1e-300 1e300 1e-150 1e150
4194304 1024 20.7 26.45 1045 1221 1000
'
# 2003 ... 1990: the years of the citations;
# 1e-300, 1e300, 1e-150, 1e150: tests/test_delaunay.c's points at mixed
#   magnitudes and tests/test_regressions.c;
# 4194304: max_added_points' default (10 n + 4194304) and 1024: the
#   progress interval, literals of the refinement's code;
# 20.7, 26.45: Ruppert's and Miller, Pav and Walkington's published
#   angle bounds (degrees);
# 1045, 1221: the exponents the exact predicates' range argument derives
#   (2^1045 an orientation test's spread, 2^1221 the scaling's, which
#   PLATEAU_DT_ERR_RANGE's message gives too); 1000: "near 2^1000", an
#   order of magnitude.

tmp=$(mktemp -d "${TMPDIR:-/tmp}/manual-check.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
status=0
total=0
for header in plateau.h plateau_lm.h plateau_delaunay.h; do
    var=ALLOWED_$(echo "$header" | tr '.' '_')
    eval "allowed=\$$var"
    { cat "$numbers"; printf '%s\n' "$allowed"; } |
        grep -oE '[0-9]+(\.[0-9]+)+([eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+|[0-9]+' | sort -u >"$tmp/known"
    # the manual: the lines up to the first comment end, dates removed
    awk '{ print NR ": " $0 } /\*\// { exit }' "$header" | sed -E 's/[0-9]{4}-[0-9]{2}-[0-9]{2}//g' |
    awk '{
        line = $0; n = $1; sub(/:$/, "", n); sub(/^[0-9]+: /, "", line)
        while (match(line, /[0-9]+(\.[0-9]+)+([eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+|[0-9]+/)) {
            tok = substr(line, RSTART, RLENGTH)
            before = RSTART > 1 ? substr(line, RSTART - 1, 1) : ""
            after = substr(line, RSTART + RLENGTH, 1)
            line = substr(line, RSTART + RLENGTH)
            if (before ~ /[A-Za-z_]/ || after ~ /[A-Za-z_]/) continue   # C99, int32_t, 3D
            if (tok ~ /^[0-9]+$/ && tok + 0 < 1000) continue
            print n "\t" tok
        }
    }' >"$tmp/numbers"
    while IFS="$(printf '\t')" read -r n tok; do
        total=$((total + 1))
        if ! grep -qxF "$tok" "$tmp/known"; then
            echo "manual-check: $header line $n: $tok is in no output of tests/test_manual.c and not listed in examples/manual_check.sh"
            status=1
        fi
    done <"$tmp/numbers"
done
[ "$status" = 0 ] && echo "manual-check: the $total numbers of the three manuals are checked by tests/test_manual.c or listed with their sources"
exit "$status"
