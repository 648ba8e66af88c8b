/* lm_fit.c - quick start for plateau_lm.h: fit y = a exp(-b t) + c to twenty
 * noisy samples of a decay, once with an analytic Jacobian and once with
 * finite differences, and print the fitted parameters.
 *
 *     make demo        (or: cc -std=c99 -I. examples/lm_fit.c -lm)
 */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_LM_IMPLEMENTATION
#endif
#include "plateau_lm.h"

#include <math.h>
#include <stdio.h>

#define N_SAMPLES 20

typedef struct samples {
    double t[N_SAMPLES], y[N_SAMPLES];
} samples;

/* residual f_i = a exp(-b t_i) + c - y_i; Jacobian row (e, -a t e, 1) */
static int decay(const double *x, double *f, double *jac, void *user)
{
    const samples *s = (const samples *)user;
    int i;
    for (i = 0; i < N_SAMPLES; i++) {
        double e = exp(-x[1] * s->t[i]);
        f[i] = x[0] * e + x[2] - s->y[i];
        if (jac) {
            jac[3 * i + 0] = e;
            jac[3 * i + 1] = -x[0] * s->t[i] * e;
            jac[3 * i + 2] = 1.0;
        }
    }
    return 0;
}

int main(void)
{
    samples s;
    double x[3];
    plateau_lm_options opt = {0};
    plateau_lm_report rep;
    plateau_lm_result r;
    unsigned state = 12345u;
    int i, pass, failures = 0;

    /* data: a = 5, b = 0.7, c = 1, plus a small deterministic "noise" */
    for (i = 0; i < N_SAMPLES; i++) {
        state = state * 1103515245u + 12345u;
        s.t[i] = 0.25 * i;
        s.y[i] = 5.0 * exp(-0.7 * s.t[i]) + 1.0 + 0.02 * ((double)(state >> 16 & 0x7fff) / 32767.0 - 0.5);
    }
    printf("fit y = a exp(-b t) + c to %d samples (true a = 5, b = 0.7, c = 1)\n", N_SAMPLES);
    for (pass = 0; pass < 2; pass++) {
        x[0] = 1.0; x[1] = 0.1; x[2] = 0.0; /* a poor start */
        opt.numeric_jacobian = pass;
        r = plateau_lm_solve(N_SAMPLES, 3, x, decay, &s, &opt, NULL, 0, &rep, NULL);
        printf("  %-20s a = %.4f  b = %.4f  c = %.4f  F = %.3e  %zu iterations, %zu f + %zu J evaluations (%s)\n",
               pass ? "finite differences:" : "analytic Jacobian:", x[0], x[1], x[2], rep.f_final,
               rep.iterations, rep.residual_evaluations, rep.jacobian_evaluations,
               r == PLATEAU_LM_OK ? plateau_lm_stop_string((plateau_lm_stop)rep.stop)
                                  : plateau_lm_result_string(r));
        if (r != PLATEAU_LM_OK || fabs(x[0] - 5.0) > 0.1 || fabs(x[1] - 0.7) > 0.05 ||
            fabs(x[2] - 1.0) > 0.05)
            failures++;
    }
    return failures == 0 ? 0 : 1;
}
