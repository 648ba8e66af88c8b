/* harness.h - the tiny test harness of plateau's own test suite.
 *
 * Every check counts; a failing check prints where and why, and the run goes
 * on.  At the end `harness_report()` prints one line
 *
 *     <name>: <P> checks passed, <F> failed
 *
 * which tests/run.sh sums into the suite's closing line, and returns the exit
 * code (non-zero when anything failed).  Only tests use this header; the
 * library itself has no global state.
 *
 *     static void test_something(void) {
 *         CHECK(1 + 1 == 2);
 *         CHECK_NEAR(sqrt(2.0) * sqrt(2.0), 2.0, 1e-15);
 *         CHECK_EQ_INT(f(), 3);
 *     }
 *     int main(void) { RUN(test_something); return harness_report("test_x"); }
 *
 * Set HARNESS_FILTER=substring to run only the tests whose name contains it.
 *
 * Two tiers: `make test-full` runs every test with PLATEAU_TEST_FULL=1, and
 * a slow test then runs its full sizes; `make test` leaves it unset, and
 * such a test runs smaller sizes that still check the same things (and can
 * fail the same ways).  HARNESS_FULL says which:
 *
 *     size_t n = HARNESS_FULL ? 40000 : 4000;
 */
#ifndef PLATEAU_TEST_HARNESS_H
#define PLATEAU_TEST_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static long harness_passed;
static long harness_failed;
static const char *harness_current = "";

static int harness_check(int ok, const char *file, int line, const char *what)
{
    if (ok) {
        harness_passed++;
    } else {
        harness_failed++;
        fprintf(stderr, "FAIL %s:%d [%s] %s\n", file, line, harness_current, what);
    }
    return ok;
}

/* |a - b| <= tol, and false on NaN (a NaN never passes a check). */
static int harness_near(double a, double b, double tol, const char *file, int line,
                        const char *what)
{
    int ok = (fabs(a - b) <= tol);
    if (!ok) {
        char buf[512];
        sprintf(buf, "%.200s: %.17g vs %.17g (|diff| %.3g > tol %.3g)", what, a, b,
                fabs(a - b), tol);
        return harness_check(0, file, line, buf);
    }
    return harness_check(1, file, line, what);
}

static int harness_eq_long(long a, long b, const char *file, int line, const char *what)
{
    if (a != b) {
        char buf[512];
        sprintf(buf, "%.200s: %ld vs %ld", what, a, b);
        return harness_check(0, file, line, buf);
    }
    return harness_check(1, file, line, what);
}

#define CHECK(cond) harness_check((cond) ? 1 : 0, __FILE__, __LINE__, #cond)
#define CHECK_MSG(cond, msg) harness_check((cond) ? 1 : 0, __FILE__, __LINE__, (msg))
#define CHECK_NEAR(a, b, tol) \
    harness_near((double)(a), (double)(b), (double)(tol), __FILE__, __LINE__, #a " ~ " #b)
/* relative closeness: |a - b| <= rel * max(|a|, |b|, floor) */
#define CHECK_REL(a, b, rel, floor_)                                                  \
    harness_near((double)(a), (double)(b),                                            \
                 (double)(rel) * fmax(fmax(fabs((double)(a)), fabs((double)(b))),     \
                                      (double)(floor_)),                              \
                 __FILE__, __LINE__, #a " ~rel " #b)
#define CHECK_EQ_INT(a, b) \
    harness_eq_long((long)(a), (long)(b), __FILE__, __LINE__, #a " == " #b)

#define HARNESS_FULL \
    (getenv("PLATEAU_TEST_FULL") != NULL && strcmp(getenv("PLATEAU_TEST_FULL"), "1") == 0)

/* HARNESS_TIMES set: each test's CPU seconds on stderr, to find the slow
 * ones (make test's sizes are chosen from them). */
#define RUN(fn)                                                            \
    do {                                                                   \
        const char *harness_filter_ = getenv("HARNESS_FILTER");           \
        if (!harness_filter_ || strstr(#fn, harness_filter_)) {            \
            clock_t harness_t0_ = clock();                                 \
            harness_current = #fn;                                         \
            fn();                                                          \
            if (getenv("HARNESS_TIMES"))                                   \
                fprintf(stderr, "  %s: %.2f s CPU\n", #fn,                 \
                        (double)(clock() - harness_t0_) / CLOCKS_PER_SEC); \
        }                                                                  \
    } while (0)

/* The whole file at path, NUL-terminated, its length in *len; NULL when it
 * cannot be opened or the memory is short.  The caller frees it. */
static char *harness_slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long size;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)size + 1);
    if (buf) {
        *len = fread(buf, 1, (size_t)size, f);
        buf[*len] = '\0';
    }
    fclose(f);
    return buf;
}

static int harness_report(const char *name)
{
    (void)harness_slurp; /* not every test reads files */
    printf("%s: %ld checks passed, %ld failed\n", name, harness_passed, harness_failed);
    fflush(stdout);
    return harness_failed ? 1 : 0;
}

#endif /* PLATEAU_TEST_HARNESS_H */
