/* lm_quickstart.c - a bounded fit with standard errors in plateau_lm.h:
 * fit y = a exp(-b t) + c to twenty samples of a decay, with c held to
 * c >= 0 (an offset that cannot be negative), check the analytic Jacobian
 * first, then print each parameter with its standard error.  A complete
 * program; compiles as C and as C++.
 *
 *     cc -std=c99 -I. examples/lm_quickstart.c -lm && ./a.out
 *
 * It prints (tests/test_lm_fit.c runs it and compares, line by line):
 *     fit: F-change test after 9 iterations, sum of squares 0.000898167
 *       a = 5.005747 +- 0.006334
 *       b = 1.299144 +- 0.003519
 *       c = 0.019024 +- 0.002593
 */
#define PLATEAU_LM_IMPLEMENTATION
#include "plateau_lm.h"

#include <math.h>
#include <stdio.h>

#define SAMPLES 20

static double sample_t(int i) { return 0.25 * i; }
/* a = 5, b = 1.3, c = 0.02, and a deterministic wobble as noise */
static double sample_y(int i) { return 5.0 * exp(-1.3 * sample_t(i)) + 0.02 + 0.01 * sin(7.0 * i); }

/* residual f_i = a exp(-b t_i) + c - y_i; Jacobian row (e, -a t e, 1) */
static int decay(const double *x, double *f, double *jac, void *user)
{
    int i;
    (void)user;
    for (i = 0; i < SAMPLES; i++) {
        double t = sample_t(i), e = exp(-x[1] * t);
        f[i] = x[0] * e + x[2] - sample_y(i);
        if (jac) {
            jac[3 * i + 0] = e;
            jac[3 * i + 1] = -x[0] * t * e;
            jac[3 * i + 2] = 1.0;
        }
    }
    return 0;
}

int main(void)
{
    static const char *names[3] = {"a", "b", "c"};
    const double lower[3] = {-HUGE_VAL, 0.0, 0.0}, upper[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    double x[3] = {1.0, 0.5, 1.0}, se[3];
    plateau_lm_options o = plateau_lm_resolved_options(NULL);
    plateau_lm_jacobian_check chk;
    plateau_lm_report rep;
    plateau_lm_result r;
    size_t rank;
    int j;

    /* 1. is the Jacobian right?  (entry by entry against differences) */
    r = plateau_lm_check_jacobian(SAMPLES, 3, x, decay, NULL, NULL, &chk, NULL, NULL, 0);
    if (r != PLATEAU_LM_OK || chk.wrong != 0) {
        printf("Jacobian: %s, %lu wrong entries (worst row %ld, column %ld)\n",
               plateau_lm_result_string(r), (unsigned long)chk.wrong, chk.worst_row, chk.worst_col);
        return 1;
    }
    /* 2. the fit, inside the box b >= 0, c >= 0 */
    o.lower = lower;
    o.upper = upper;
    r = plateau_lm_solve(SAMPLES, 3, x, decay, NULL, &o, NULL, 0, &rep, NULL);
    if (r != PLATEAU_LM_OK) {
        printf("fit: %s\n", plateau_lm_result_string(r));
        return 1;
    }
    /* 3. standard errors at the solution: s^2 (J^T J)^-1, s^2 = 2F / (m - n) */
    r = plateau_lm_covariance(SAMPLES, 3, x, decay, NULL, &o, NULL, se, &rank, NULL, 0);
    if (r != PLATEAU_LM_OK) {
        printf("covariance: %s (rank %lu)\n", plateau_lm_result_string(r), (unsigned long)rank);
        return 1;
    }
    printf("fit: %s after %lu iterations, sum of squares %.6g\n",
           plateau_lm_stop_string(rep.stop), (unsigned long)rep.iterations, 2.0 * rep.f_final);
    for (j = 0; j < 3; j++) printf("  %s = %.6f +- %.6f\n", names[j], x[j], se[j]);
    return 0;
}
