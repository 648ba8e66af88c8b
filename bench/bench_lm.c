/* bench_lm.c - plateau_lm.h on the Moré-Garbow-Hillstrom problems
 * (tests/lm_mgh.h): for each problem and start (1, 10, 100 x the standard
 * one), whether the published minimum was reached, the residual and
 * Jacobian evaluations, and the median CPU time per solve over 11 batches
 * (the machine is shared and noisy: medians, not means).  Then the tally,
 * with the analytic and with the forward-difference Jacobian, and the
 * analytic tally of the plain LM (geodesic acceleration NEVER).
 *
 * Success is judged as in the tests (mgh_classify in tests/lm_mgh.h): the
 * final sum of squares at most 1e-5 relative above MGH's published value
 * (<= 1e-10 when that is 0), or below it; "ok" marks the published value,
 * "low" a reached run below it, "alt" another value MGH list (a local
 * minimum, or a limit at infinity).
 *
 * Optional peer: levmar 2.6 (Lourakis), when built with
 * PLATEAU_BENCH_LEVMAR (make bench LEVMAR_DIR=/path/to/levmar-2.6, a
 * directory holding levmar.h and liblevmar.a built with its defaults;
 * levmar is not packaged in Debian and nothing needs it).  Its dlevmar_der
 * runs from the same starts with its default options (opts NULL) and at
 * most 1000 iterations; its columns give its evaluations (info[7], info[8])
 * and the tally compares the runs both reach.  m < n runs are left to
 * plateau_lm.h (levmar needs m >= n).
 *
 * Then NIST StRD's 27 nonlinear regression problems from both starts
 * (tests/lm_nist.h) for each geodesic mode: the minimum LRE of each run,
 * the evaluations, and the tally (runs with LRE >= 4, the 16 runs of
 * higher difficulty, the average minimum LRE); and the bounded and
 * linearly constrained problems of tests/lm_bounded.h. */
#define PLATEAU_LM_IMPLEMENTATION
#include "../plateau_lm.h"
#include "../tests/lm_mgh.h"
#include "../tests/lm_nist.h"
#include "../tests/lm_bounded.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef PLATEAU_BENCH_LEVMAR
#include <levmar.h>
#define LEVMAR_ITERATIONS 1000
#endif

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

/* mgh_classify of a final sum of squares s, 3 for a reached run more than
 * the tolerance below the published value */
static int classify(const mgh_problem *p, double s)
{
    int c = mgh_classify(p, s);
    if (c == 1 && p->fstar > 0.0 && s < (1.0 - 1e-5) * p->fstar) c = 3;
    return c;
}

/* classify() says the run counts as reached */
static int reached_run(int c)
{
    return c == 1 || c == 3;
}

/* one solve; returns classify(), -1 on an error */
static int run(const mgh_problem *p, double factor, int numeric, plateau_lm_geodesic geo,
               void *work, size_t bytes, plateau_lm_report *rep)
{
    plateau_lm_options o;
    double x[MGH_MAX_N];
    plateau_lm_result r;
    memset(&o, 0, sizeof o);
    o.numeric_jacobian = numeric;
    o.geodesic = geo;
    mgh_start(p, factor, x);
    r = plateau_lm_solve(p->m, p->n, x, bench_callback, (void *)p, &o, work, bytes, rep, NULL);
    if (r != PLATEAU_LM_OK) return -1;
    return classify(p, 2.0 * rep->f_final);
}

#ifdef PLATEAU_BENCH_LEVMAR
/* levmar's callbacks: hx = f(p) (its measurement vector x is 0), J of hx */
static void levmar_f(double *p, double *hx, int m, int n, void *user)
{
    const mgh_problem *pr = (const mgh_problem *)user;
    (void)m;
    (void)n;
    pr->eval(pr, p, hx, NULL);
}
static void levmar_j(double *p, double *jac, int m, int n, void *user)
{
    const mgh_problem *pr = (const mgh_problem *)user;
    double f[MGH_MAX_M];
    (void)m;
    (void)n;
    pr->eval(pr, p, f, jac);
}
/* levmar's run from the same start: classify() or -1, its evaluations */
static int run_levmar(const mgh_problem *p, double factor, long *fev, long *jev)
{
    double x[MGH_MAX_N], info[LM_INFO_SZ];
    int r;
    *fev = *jev = 0;
    if (p->m < p->n) return -2;
    mgh_start(p, factor, x);
    r = dlevmar_der(levmar_f, levmar_j, x, NULL, (int)p->n, (int)p->m, LEVMAR_ITERATIONS, NULL,
                    info, NULL, NULL, (void *)p);
    *fev = (long)info[7];
    *jev = (long)info[8];
    return r < 0 ? -1 : classify(p, info[1]);
}
#endif

static const char *verdict(int c)
{
    return c == 1 ? "ok" : c == 2 ? "alt" : c == 3 ? "low" : c == -2 ? "" : c < 0 ? "err" : "-";
}

/* the table and tally of one Jacobian kind, timed */
static void bench_mgh(int numeric, void *work, size_t bytes)
{
    static const double factors[3] = {1.0, 10.0, 100.0};
    int reached[3] = {0, 0, 0}, alt = 0, low = 0, errors = 0;
    long nfev = 0, njev = 0, nfev_ok = 0, njev_ok = 0;
    long both = 0, lv_ok = 0, both_p = 0, both_l = 0, lf_all = 0, lj_all = 0;
    double total_ms = 0.0;
    size_t pi;
    int s;
    printf("\n%s Jacobian\n", numeric ? "forward-difference" : "analytic");
    printf("%-30s %5s %4s %6s %5s %10s", "problem", "start", "", "f-ev", "J-ev", "median us");
#ifdef PLATEAU_BENCH_LEVMAR
    if (!numeric) printf(" | levmar %4s %6s %5s", "", "f-ev", "J-ev");
#endif
    printf("\n");
    for (pi = 0; pi < MGH_COUNT; pi++) {
        const mgh_problem *p = &mgh_problems[pi];
        for (s = 0; s < 3; s++) {
            plateau_lm_report rep;
            double t[BATCHES];
            int b, c = run(p, factors[s], numeric, PLATEAU_LM_GEODESIC_AUTO, work, bytes, &rep);
            int reps = 1, k;
            /* enough solves per batch for clock() to resolve the time */
            {
                clock_t c0 = clock();
                double one;
                run(p, factors[s], numeric, PLATEAU_LM_GEODESIC_AUTO, work, bytes, &rep);
                one = (double)(clock() - c0) / CLOCKS_PER_SEC;
                if (one < 2e-4) reps = one > 0.0 ? (int)(2e-4 / one) + 1 : 50;
            }
            for (b = 0; b < BATCHES; b++) {
                clock_t c0 = clock();
                for (k = 0; k < reps; k++)
                    run(p, factors[s], numeric, PLATEAU_LM_GEODESIC_AUTO, work, bytes, &rep);
                t[b] = (double)(clock() - c0) / CLOCKS_PER_SEC / reps;
            }
            qsort(t, BATCHES, sizeof t[0], cmp_double);
            total_ms += t[BATCHES / 2] * 1e3;
            nfev += (long)rep.residual_evaluations;
            njev += (long)rep.jacobian_evaluations;
            if (reached_run(c)) {
                reached[s]++;
                nfev_ok += (long)rep.residual_evaluations;
                njev_ok += (long)rep.jacobian_evaluations;
            }
            alt += c == 2;
            low += c == 3;
            errors += c < 0;
            printf("%-30s %5g %4s %6lu %5lu %10.1f", p->name, factors[s], verdict(c),
                   (unsigned long)rep.residual_evaluations, (unsigned long)rep.jacobian_evaluations,
                   t[BATCHES / 2] * 1e6);
#ifdef PLATEAU_BENCH_LEVMAR
            if (!numeric) {
                long lf, lj;
                int lc = run_levmar(p, factors[s], &lf, &lj);
                if (lc != -2) printf(" | levmar %4s %6ld %5ld", verdict(lc), lf, lj);
                if (reached_run(lc)) {
                    lv_ok++;
                    lf_all += lf;
                    lj_all += lj;
                }
                if (reached_run(lc) && reached_run(c)) {
                    both++;
                    both_p += (long)(rep.residual_evaluations + rep.jacobian_evaluations);
                    both_l += lf + lj;
                }
            }
#endif
            printf("\n");
        }
    }
    printf("tally (%s): published minimum (or a lower value) reached from 1x %d, 10x %d,"
           " 100x %d: %d of %d; of them below the published value %d; other listed minimum"
           " %d, errors %d\n",
           numeric ? "differences" : "analytic", reached[0], reached[1], reached[2],
           reached[0] + reached[1] + reached[2], (int)(3 * MGH_COUNT), low, alt, errors);
    printf("evaluations (%s): all runs %ld residual + %ld Jacobian; reached runs %ld + %ld;"
           " sum of median times %.2f ms\n",
           numeric ? "differences" : "analytic", nfev, njev, nfev_ok, njev_ok, total_ms);
#ifdef PLATEAU_BENCH_LEVMAR
    if (!numeric)
        printf("levmar 2.6 (dlevmar_der, default options, at most %d iterations): published "
               "minimum (or a lower value) reached in %ld runs (%ld + %ld evaluations); "
               "both reach it in %ld runs: plateau_lm.h %ld evaluations, levmar %ld\n",
               LEVMAR_ITERATIONS, lv_ok, lf_all, lj_all, both, both_p, both_l);
#else
    if (!numeric)
        printf("levmar 2.6: skipped (optional peer: make bench LEVMAR_DIR=<a levmar-2.6 build>)\n");
    (void)both;
    (void)lv_ok;
    (void)both_p;
    (void)both_l;
    (void)lf_all;
    (void)lj_all;
#endif
}

/* the untimed analytic tally of the plain LM (geodesic NEVER) */
static void bench_mgh_plain(void *work, size_t bytes)
{
    static const double factors[3] = {1.0, 10.0, 100.0};
    long fe = 0, je = 0;
    int reached = 0;
    size_t pi;
    int s;
    for (pi = 0; pi < MGH_COUNT; pi++)
        for (s = 0; s < 3; s++) {
            plateau_lm_report rep;
            int c = run(&mgh_problems[pi], factors[s], 0, PLATEAU_LM_GEODESIC_NEVER, work, bytes, &rep);
            if (reached_run(c)) {
                reached++;
                fe += (long)rep.residual_evaluations;
                je += (long)rep.jacobian_evaluations;
            }
        }
    printf("tally (analytic, geodesic NEVER): %d of %d; reached runs %ld + %ld evaluations\n",
           reached, (int)(3 * MGH_COUNT), fe, je);
}

static int nist_cb(const double *x, double *f, double *jac, void *user)
{
    nist_residuals((const nist_problem *)user, x, f, jac);
    return 0;
}

static void bench_nist(void)
{
    static const plateau_lm_geodesic modes[3] = {PLATEAU_LM_GEODESIC_AUTO, PLATEAU_LM_GEODESIC_NEVER,
                                                 PLATEAU_LM_GEODESIC_ALWAYS};
    static const char *const names[3] = {"AUTO (default)", "NEVER", "ALWAYS"};
    int mode;
    for (mode = 0; mode < 3; mode++) {
        size_t pi, j;
        int s, solved = 0, hard = 0;
        long fe = 0, je = 0;
        double total = 0.0;
        printf("\nNIST StRD, analytic Jacobian, geodesic %s\n", names[mode]);
        printf("%-10s %5s %8s %6s %5s %6s %6s\n", "problem", "start", "min LRE", "f-ev", "J-ev",
               "accel", "refine");
        for (pi = 0; pi < NIST_COUNT; pi++) {
            const nist_problem *p = &nist_problems[pi];
            for (s = 0; s < 2; s++) {
                plateau_lm_options o;
                plateau_lm_report rep;
                double x[NIST_MAX_N], lre = 99.0;
                memset(&o, 0, sizeof o);
                o.geodesic = modes[mode];
                memcpy(x, s ? p->start2 : p->start1, sizeof(double) * p->n);
                if (plateau_lm_solve(p->m, p->n, x, nist_cb, (void *)p, &o, NULL, 0, &rep, NULL) !=
                    PLATEAU_LM_OK)
                    lre = 0.0;
                for (j = 0; j < p->n; j++) {
                    double l = nist_lre(x[j], p->certified[j]);
                    if (l < lre) lre = l;
                }
                total += lre;
                if (lre >= 4.0) {
                    solved++;
                    hard += p->difficulty == 2;
                }
                fe += (long)rep.residual_evaluations;
                je += (long)rep.jacobian_evaluations;
                printf("%-10s %5d %8.2f %6lu %5lu %6lu %6lu\n", p->name, s + 1, lre,
                       (unsigned long)rep.residual_evaluations, (unsigned long)rep.jacobian_evaluations,
                       (unsigned long)rep.accelerated_steps, (unsigned long)rep.refinement_steps);
            }
        }
        printf("NIST tally, geodesic %s: %d of 54 runs with LRE >= 4, higher difficulty %d of 16, "
               "average minimum LRE %.2f, evaluations %ld + %ld\n",
               names[mode], solved, hard, total / 54.0, fe, je);
    }
}

static int bnd_cb(const double *x, double *f, double *jac, void *user)
{
    box_eval(((const bounded_case *)user)->id, x, f, jac);
    return 0;
}

static void bench_bounded(void)
{
    size_t c, j;
    printf("\nbounded and linearly constrained problems (tests/lm_bounded.h), analytic Jacobian\n");
    printf("%-12s %12s %12s %6s %5s %8s\n", "problem", "2F", "published", "f-ev", "J-ev", "|x-x*|");
    for (c = 0; c < BOUNDED_COUNT; c++) {
        const bounded_case *b = &bounded_cases[c];
        plateau_lm_options o;
        plateau_lm_report rep;
        double x[5], err = 0.0;
        memset(&o, 0, sizeof o);
        o.lower = b->lo;
        o.upper = b->up;
        o.constraints = b->ne;
        o.a_eq = b->a;
        o.b_eq = b->b;
        o.inequalities = b->ni;
        o.c_ineq = b->c;
        o.d_ineq = b->d;
        memcpy(x, b->x0, sizeof(double) * b->n);
        if (plateau_lm_solve(b->m, b->n, x, bnd_cb, (void *)b, &o, NULL, 0, &rep, NULL) != PLATEAU_LM_OK)
            printf("%-12s error\n", b->name);
        for (j = 0; j < b->n; j++)
            if (fabs(x[j] - b->xs[j]) > err) err = fabs(x[j] - b->xs[j]);
        printf("%-12s %12.6g %12.6g %6lu %5lu %8.1e\n", b->name, 2.0 * rep.f_final, b->fstar,
               (unsigned long)rep.residual_evaluations, (unsigned long)rep.jacobian_evaluations, err);
    }
}

int main(void)
{
    size_t bytes = plateau_lm_workspace_size(MGH_MAX_M, MGH_MAX_N, NULL);
    void *work = malloc(bytes);
    if (!work) return 1;
    bench_mgh(0, work, bytes);
    bench_mgh_plain(work, bytes);
    bench_mgh(1, work, bytes);
    free(work);
    bench_nist();
    bench_bounded();
    return 0;
}
