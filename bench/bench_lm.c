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
 * infinity), "low" a value below the published one.
 *
 * Then NIST StRD's 27 nonlinear regression problems from both starts
 * (tests/lm_nist.h), without and with geodesic acceleration: the minimum
 * LRE of each run, the evaluations, and the tally (runs with LRE >= 4,
 * the 16 runs of higher difficulty, the average minimum LRE); and the
 * bounded problems of tests/lm_bounded.h. */
#define PLATEAU_LM_IMPLEMENTATION
#include "../plateau_lm.h"
#include "../tests/lm_mgh.h"
#include "../tests/lm_nist.h"
#include "../tests/lm_bounded.h"

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

static int nist_cb(const double *x, double *f, double *jac, void *user)
{
    nist_residuals((const nist_problem *)user, x, f, jac);
    return 0;
}

static void bench_nist(void)
{
    int geo;
    for (geo = 0; geo < 2; geo++) {
        size_t pi, j;
        int s, solved = 0, hard = 0;
        long fe = 0, je = 0;
        double total = 0.0;
        printf("\nNIST StRD, analytic Jacobian%s\n", geo ? ", geodesic acceleration" : "");
        printf("%-10s %5s %8s %6s %5s %5s\n", "problem", "start", "min LRE", "f-ev", "J-ev", "refine");
        for (pi = 0; pi < NIST_COUNT; pi++) {
            const nist_problem *p = &nist_problems[pi];
            for (s = 0; s < 2; s++) {
                plateau_lm_options o;
                plateau_lm_report rep;
                double x[NIST_MAX_N], lre = 99.0;
                memset(&o, 0, sizeof o);
                o.geodesic = geo;
                memcpy(x, s ? p->start2 : p->start1, sizeof(double) * p->n);
                if (plateau_lm_solve(p->m, p->n, x, nist_cb, (void *)p, &o, NULL, 0, &rep, NULL) != PLATEAU_LM_OK)
                    lre = 0.0;
                for (j = 0; j < p->n; j++) {
                    double l = nist_lre(x[j], p->certified[j]);
                    if (l < lre) lre = l;
                }
                total += lre;
                if (lre >= 4.0) { solved++; hard += p->difficulty == 2; }
                fe += (long)rep.residual_evaluations;
                je += (long)rep.jacobian_evaluations;
                printf("%-10s %5d %8.2f %6zu %5zu %5zu\n", p->name, s + 1, lre, rep.residual_evaluations,
                       rep.jacobian_evaluations, rep.refinement_steps);
            }
        }
        printf("NIST tally%s: %d of 54 runs with LRE >= 4, higher difficulty %d of 16, average minimum "
               "LRE %.2f, evaluations %ld + %ld\n", geo ? " (geodesic)" : "", solved, hard, total / 54.0, fe, je);
    }
}

static int bnd_cb(const double *x, double *f, double *jac, void *user)
{
    box_eval(*(const int *)user, x, f, jac);
    return 0;
}

static void bench_bounded(void)
{
    size_t c, j;
    printf("\nbounded problems (tests/lm_bounded.h), analytic Jacobian\n");
    printf("%-6s %12s %12s %6s %5s %6s\n", "id", "2F", "published", "f-ev", "J-ev", "|x-x*|");
    for (c = 0; c < BOUNDED_COUNT; c++) {
        const bounded_case *b = &bounded_cases[c];
        plateau_lm_options o;
        plateau_lm_report rep;
        double x[5], err = 0.0;
        memset(&o, 0, sizeof o);
        o.lower = b->lo;
        o.upper = b->up;
        memcpy(x, b->x0, sizeof(double) * b->n);
        plateau_lm_solve(b->n, b->n, x, bnd_cb, (void *)&b->id, &o, NULL, 0, &rep, NULL);
        for (j = 0; j < b->n; j++)
            if (fabs(x[j] - b->xs[j]) > err) err = fabs(x[j] - b->xs[j]);
        printf("%-6d %12.6g %12.6g %6zu %5zu %6.1e\n", b->id, 2.0 * rep.f_final, b->fstar,
               rep.residual_evaluations, rep.jacobian_evaluations, err);
    }
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
    bench_nist();
    bench_bounded();
    return 0;
}
