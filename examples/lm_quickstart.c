/* lm_quickstart.c - the README's quick start for plateau_lm.h: fit
 * y = a exp(-b t) + c to eight measurements by Levenberg-Marquardt with an
 * analytic Jacobian.
 *
 *     cc -std=c99 -O2 -I. examples/lm_quickstart.c -o lm_quickstart -lm
 */
#define PLATEAU_LM_IMPLEMENTATION /* in exactly one file of a program */
#include "plateau_lm.h"

#include <math.h>
#include <stdio.h>

static const double T[8] = {0, 0.5, 1, 1.5, 2, 3, 4, 6};
static const double Y[8] = {6.00, 4.52, 3.48, 2.77, 2.24, 1.61, 1.32, 1.09};

/* The m = 8 residuals f_i = a exp(-b t_i) + c - y_i of x = (a, b, c) and,
 * when jac is not NULL, their Jacobian, row-major 8 x 3.  A non-zero return
 * stops the solve. */
static int decay(const double *x, double *f, double *jac, void *user)
{
    int i;
    (void)user;
    for (i = 0; i < 8; i++) {
        double e = exp(-x[1] * T[i]);
        f[i] = x[0] * e + x[2] - Y[i];
        if (jac) {
            jac[3 * i] = e;
            jac[3 * i + 1] = -x[0] * T[i] * e;
            jac[3 * i + 2] = 1.0;
        }
    }
    return 0;
}

int main(void)
{
    double x[3] = {1.0, 1.0, 0.0}; /* the start; the minimiser on return */
    plateau_lm_report rep;
    plateau_lm_result r = plateau_lm_solve(8, 3, x, decay, NULL, NULL, NULL, 0, &rep, NULL);
    if (r != PLATEAU_LM_OK) {
        fprintf(stderr, "%s\n", plateau_lm_result_string(r));
        return 1;
    }
    printf("a = %.4f, b = %.4f, c = %.4f, F = %.3e, %lu iterations (%s)\n", x[0], x[1], x[2],
           rep.f_final, (unsigned long)rep.iterations,
           plateau_lm_stop_string((plateau_lm_stop)rep.stop));
    return 0;
}
