/* plateau - the command-line tool over plateau.h.
 *
 *   plateau [-n N] [--method paper|paper-literal|area] [--seed S]
 *           [-o mesh.obj|.ply|.off] [--svg picture.svg] [--json]
 *           [--max-input-bytes B] [--max-seconds S] boundary.txt|- [more-loops.txt ...]
 *
 * Several loops (plateau_solve_loops): blank-line separated blocks of one
 * file, or several files, in order.
 *
 * See plateau --help.  Messages go to stderr; the summary or the JSON object
 * to stdout.  Exit status 0 success, 1 bad input or failure, 2 bad usage,
 * 3 a mesh with defects (see plateau --help).
 * The work is in plateau_cli.h (arguments, loading, output) and
 * plateau_cli_run.h (one run), which tests/test_cli*.c test. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with XSI: clock_gettime, lstat, realpath */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "../plateau.h"
#ifdef PLATEAU_NO_PATTERNS /* the other switches keep the API: the tool builds with them */
#error "the command-line tool writes cutting patterns: build it without PLATEAU_NO_PATTERNS"
#endif
#include "plateau_cli.h"
#include "plateau_cli_run.h"

int main(int argc, char **argv)
{
    return plateau_cli_run(argc, argv, stdout, stderr);
}
