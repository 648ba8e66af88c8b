/* whitebox.c - the implementation object of `make test`: the three headers'
 * implementation (as tests/impl.c) and, in the same unit, the tests that
 * call plateau.h's private functions with the default configuration.  Those
 * functions are static, so such a test must share a unit with the
 * implementation; here the four share one, each with its main renamed,
 * and the implementation is compiled once for all of them instead of once
 * per test.
 *
 * The tests that use only the public API (PLATEAU_TEST_LINKED) link this
 * object as they would link impl.o; each white-box test is this object
 * plus tests/whitebox_main.c, which calls plateau_test_whitebox() with the
 * test's name.  make test-full still builds every one of these tests alone
 * (gcc -O2, clang, sanitizers), as its own unit.  A test added here is
 * listed in the table below as well. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"

#include <string.h>

int plateau_test_whitebox(const char *name, int argc, char **argv);
int whitebox_kernel_main(void);
int whitebox_manual_main(int argc, char **argv);
int whitebox_solve_coarse_to_fine_main(void);
int whitebox_solve_paths_main(void);

#define main whitebox_kernel_main
#include "test_kernel.c"
#undef main

#define main whitebox_manual_main
#include "test_manual.c"
#undef main

#define main whitebox_solve_coarse_to_fine_main
#include "test_solve_coarse_to_fine.c"
#undef main

#define main whitebox_solve_paths_main
#include "test_solve_paths.c"
#undef main

/* Runs the test NAME (its file's name without .c); 2 for an unknown name. */
int plateau_test_whitebox(const char *name, int argc, char **argv)
{
    if (strcmp(name, "test_kernel") == 0) return whitebox_kernel_main();
    if (strcmp(name, "test_manual") == 0) return whitebox_manual_main(argc, argv);
    if (strcmp(name, "test_solve_coarse_to_fine") == 0) return whitebox_solve_coarse_to_fine_main();
    if (strcmp(name, "test_solve_paths") == 0) return whitebox_solve_paths_main();
    fprintf(stderr, "whitebox: no test named %s\n", name);
    return 2;
}
