/* bench_lm.c - plateau_lm.h on the Moré-Garbow-Hillstrom problems
 * (tests/lm_mgh.h): for each problem and start (1, 10, 100 x the standard
 * one), whether the published minimum was reached, the residual and
 * Jacobian evaluations, and the median CPU time per solve over 11 batches
 * (the machine is shared and noisy: medians, not means).  Then the tally,
 * with the analytic and with the forward-difference Jacobian.
 *
 * Success is judged as in the tests: the final sum of squares within
 * 1e-5 relative of MGH's published value (<= 1e-10 when that is 0);
 * "alt" marks another value MGH list (a local minimum, or a limit at
 * infinity), "low" a value below the published one. */
#define PLATEAU_LM_IMPLEMENTATION
#include "../plateau_lm.h"
#include "../tests/lm_mgh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define BATCHES 11

static int bench_callback(const double *x, double *f, double *jac, void *user)
{
    const mgh_problem *p = (const mgh_problem *)user;
    p->eval(p, x, f, jac);
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double u = *(const double *)a, v = *(const double *)b;
    return u < v ? -1 : u > v ? 1 : 0;
}

/* one solve; returns mgh_classify (3 for "below the published value") */
static int run(const mgh_problem *p, double factor, int numeric, void *work, size_t bytes,
               plateau_lm_report *rep)
{
    plateau_lm_options o;
    double x[MGH_MAX_N], s;
    plateau_lm_result r;
    int c;
    memset(&o, 0, sizeof o);
    o.numeric_jacobian = numeric;
    mgh_start(p, factor, x);
    r = plateau_lm_solve(p->m, p->n, x, bench_callback, (void *)p, &o, work, bytes, rep, NULL);
    if (r != PLATEAU_LM_OK) return -1;
    s = 2.0 * rep->f_final;
    c = mgh_classify(p, s);
    if (c == 0 && p->fstar > 0.0 && s < p->fstar) c = 3;
    return c;
}

int main(void)
{
    static const double factors[3] = {1.0, 10.0, 100.0};
    size_t bytes = plateau_lm_workspace_size(MGH_MAX_M, MGH_MAX_N, NULL);
    void *work = malloc(bytes);
    int numeric;
    if (!work) return 1;
    for (numeric = 0; numeric < 2; numeric++) {
        int reached[3] = {0, 0, 0}, alt = 0, low = 0, errors = 0;
        long nfev = 0, njev = 0, nfev_ok = 0, njev_ok = 0;
        double total_ms = 0.0;
        size_t pi;
        int s;
        printf("\n%s Jacobian\n", numeric ? "forward-difference" : "analytic");
        printf("%-30s %5s %4s %6s %5s %10s\n", "problem", "start", "", "f-ev", "J-ev",
               "median us");
        for (pi = 0; pi < MGH_COUNT; pi++) {
            const mgh_problem *p = &mgh_problems[pi];
            for (s = 0; s < 3; s++) {
                plateau_lm_report rep;
                double t[BATCHES];
                int b, c = run(p, factors[s], numeric, work, bytes, &rep), reps = 1, k;
                /* enough solves per batch for clock() to resolve the time */
                {
                    clock_t c0 = clock();
                    run(p, factors[s], numeric, work, bytes, &rep);
                    double one = (double)(clock() - c0) / CLOCKS_PER_SEC;
                    if (one < 2e-4) reps = one > 0.0 ? (int)(2e-4 / one) + 1 : 50;
                }
                for (b = 0; b < BATCHES; b++) {
                    clock_t c0 = clock();
                    for (k = 0; k < reps; k++) run(p, factors[s], numeric, work, bytes, &rep);
                    t[b] = (double)(clock() - c0) / CLOCKS_PER_SEC / reps;
                }
                qsort(t, BATCHES, sizeof t[0], cmp_double);
                total_ms += t[BATCHES / 2] * 1e3;
                nfev += rep.residual_evaluations;
                njev += rep.jacobian_evaluations;
                if (c == 1) {
                    reached[s]++;
                    nfev_ok += rep.residual_evaluations;
                    njev_ok += rep.jacobian_evaluations;
                }
                if (c == 2) alt++;
                if (c == 3) low++;
                if (c < 0) errors++;
                printf("%-30s %5g %4s %6zu %5zu %10.1f\n", p->name, factors[s],
                       c == 1 ? "ok" : c == 2 ? "alt" : c == 3 ? "low" : c < 0 ? "err" : "-",
                       rep.residual_evaluations, rep.jacobian_evaluations, t[BATCHES / 2] * 1e6);
            }
        }
        printf("tally (%s): published minimum reached from 1x %d, 10x %d, 100x %d: %d of %d;"
               " other listed minimum %d, below the published value %d, errors %d\n",
               numeric ? "differences" : "analytic", reached[0], reached[1], reached[2],
               reached[0] + reached[1] + reached[2], (int)(3 * MGH_COUNT), alt, low, errors);
        printf("evaluations (%s): all runs %ld residual + %ld Jacobian; reached runs %ld + %ld;"
               " sum of median times %.2f ms\n",
               numeric ? "differences" : "analytic", nfev, njev, nfev_ok, njev_ok, total_ms);
    }
    free(work);
    return 0;
}
