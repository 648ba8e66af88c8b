/* test_lm_fit.c - tests of plateau_lm.h as a least-squares fitting library:
 * NIST StRD nonlinear regression (tests/lm_nist.h: the certified
 * parameters and their standard deviations), box bounds, linear equality
 * and inequality constraints, weights and robust losses, the Jacobian
 * check, geodesic acceleration, the workspace formulas of the manual, and
 * the quick start's printed output (examples/lm_quickstart.c, run here,
 * against its comment and the README). */
#define _POSIX_C_SOURCE 200809L /* dup, dup2, fileno: the quick start's output */
#define PLATEAU_LM_IMPLEMENTATION
#include "../plateau_lm.h"
#include "harness.h"
#include "lm_nist.h"
#include "lm_bounded.h"

#include <unistd.h>

/* the quick start, its main renamed */
#define main lm_quickstart_main
#include "../examples/lm_quickstart.c"
#undef main

#include <float.h>
#include <stdlib.h>

static plateau_lm_options zero_options(void)
{
    plateau_lm_options o;
    memset(&o, 0, sizeof o);
    return o;
}

static int nist_callback(const double *x, double *f, double *jac, void *user)
{
    nist_residuals((const nist_problem *)user, x, f, jac);
    return 0;
}

/* the smallest LRE over the parameters of x against the certified values */
static double min_lre(const nist_problem *p, const double *x)
{
    double lo = 99.0;
    size_t j;
    for (j = 0; j < p->n; j++) {
        double l = nist_lre(x[j], p->certified[j]);
        if (l < lo) lo = l;
    }
    return lo;
}

/* ------------------------------------------------------------ the data */

/* The copy of NIST's files: at the certified parameters every problem gives
 * its certified residual sum of squares to 9 digits or more (Lanczos1's,
 * 1.4e-25, is the rounding of 11-digit parameters: there the sum must
 * stay below 1e-20), and every analytic Jacobian passes the Jacobian check
 * at both starts and at the certified point. */
static void test_nist_data_and_jacobians(void)
{
    size_t pi, i;
    int s;
    for (pi = 0; pi < NIST_COUNT; pi++) {
        const nist_problem *p = &nist_problems[pi];
        double f[NIST_MAX_M], ss = 0.0;
        nist_residuals(p, p->certified, f, NULL);
        for (i = 0; i < p->m; i++) ss += f[i] * f[i];
        if (p->rss < 1e-20) CHECK_MSG(ss < 1e-20, p->name);
        else CHECK_MSG(nist_lre(ss, p->rss) >= 9.0, p->name);
        for (s = 0; s < 3; s++) {
            const double *x = s == 0 ? p->start1 : s == 1 ? p->start2 : p->certified;
            plateau_lm_jacobian_check chk;
            CHECK_EQ_INT(plateau_lm_check_jacobian(p->m, p->n, x, nist_callback, (void *)p, NULL,
                                                   &chk, NULL, NULL, 0),
                         PLATEAU_LM_OK);
            CHECK_MSG(chk.wrong == 0, p->name);
            if (chk.wrong)
                fprintf(stderr, "  %s point %d: J(%ld, %ld) = %g, differences %g\n", p->name, s,
                        chk.worst_row, chk.worst_col, chk.worst_analytic, chk.worst_difference);
        }
    }
}

/* ------------------------------------------------------------ accuracy */

/* The 54 runs with analytic Jacobians.  NIST's rule: 4 correct digits
 * (LRE >= 4) on every parameter.  The default options (geodesic
 * acceleration AUTO) reach all 54, the 16 runs of higher difficulty among
 * them, with an average minimum LRE of 10.74 (measured; Ceres reports 9.4
 * over the same 54 runs).  The plain LM (NEVER) reaches 52 (MGH10 from start 1
 * crawls to max_iterations along a valley; Thurber from start 2 stops at a
 * local minimum, 2F = 7682 against the certified 5643), 14 of the 16,
 * 10.32; ALWAYS 54, 16, 10.73.  The floors leave a margin for compilers
 * except for the default's 54. */
static void test_nist_accuracy(void)
{
    static const plateau_lm_geodesic modes[3] = {PLATEAU_LM_GEODESIC_AUTO, PLATEAU_LM_GEODESIC_NEVER,
                                                 PLATEAU_LM_GEODESIC_ALWAYS};
    static const char *const names[3] = {"default (AUTO)", "NEVER", "ALWAYS"};
    static const int floor_solved[3] = {54, 52, 53}, floor_hard[3] = {16, 14, 15};
    static const double floor_lre[3] = {10.5, 10.0, 10.3};
    int mode;
    for (mode = 0; mode < 3; mode++) {
        size_t pi;
        int s, solved = 0, hard = 0;
        long evals = 0;
        double total = 0.0;
        for (pi = 0; pi < NIST_COUNT; pi++) {
            const nist_problem *p = &nist_problems[pi];
            for (s = 0; s < 2; s++) {
                plateau_lm_options o = zero_options();
                plateau_lm_report rep;
                double x[NIST_MAX_N], lre;
                o.geodesic = modes[mode];
                memcpy(x, s == 0 ? p->start1 : p->start2, p->n * sizeof(double));
                CHECK_EQ_INT(plateau_lm_solve(p->m, p->n, x, nist_callback, (void *)p, &o, NULL, 0,
                                              &rep, NULL),
                             PLATEAU_LM_OK);
                lre = min_lre(p, x);
                total += lre;
                evals += (long)(rep.residual_evaluations + rep.jacobian_evaluations);
                CHECK(rep.refinement_steps <= 40); /* REFINEMENT's bound */
                if (lre >= 4.0) {
                    solved++;
                    hard += p->difficulty == 2;
                } else if (mode == 0) {
                    fprintf(stderr, "  %s start %d: minimum LRE %.2f\n", p->name, s + 1, lre);
                }
            }
        }
        printf("  NIST StRD, geodesic %s: %d of 54 runs with LRE >= 4 (%d of 16 of higher "
               "difficulty), average minimum LRE %.2f, %ld evaluations\n", names[mode], solved, hard,
               total / 54.0, evals);
        CHECK(solved >= floor_solved[mode]);
        CHECK(hard >= floor_hard[mode]);
        CHECK(total / 54.0 >= floor_lre[mode]);
        if (mode == 0) CHECK_NEAR(total / 54.0, 10.74, 0.005); /* README.md's figure */
    }
}

/* MGH10 from NIST's start 1 (b = 2, 4e5, 2.5e4) reaches the certified
 * answer with geodesic acceleration, AUTO (the default) and ALWAYS, the
 * steps carrying it accepted; the plain step (NEVER) is still crawling
 * along the valley at max_iterations (1000), as the manual says. */
static void test_geodesic_acceleration_solves_mgh10(void)
{
    static const plateau_lm_geodesic modes[3] = {PLATEAU_LM_GEODESIC_AUTO, PLATEAU_LM_GEODESIC_ALWAYS,
                                                 PLATEAU_LM_GEODESIC_NEVER};
    const nist_problem *p = NULL;
    size_t pi;
    int mode;
    for (pi = 0; pi < NIST_COUNT; pi++)
        if (strcmp(nist_problems[pi].name, "MGH10") == 0) p = &nist_problems[pi];
    CHECK(p != NULL);
    if (!p) return;
    for (mode = 0; mode < 3; mode++) {
        plateau_lm_options o = zero_options();
        plateau_lm_report rep;
        double x[NIST_MAX_N];
        o.geodesic = modes[mode];
        memcpy(x, p->start1, sizeof(double) * p->n);
        CHECK_EQ_INT(plateau_lm_solve(p->m, p->n, x, nist_callback, (void *)p, &o, NULL, 0, &rep, NULL),
                     PLATEAU_LM_OK);
        if (mode < 2) {
            CHECK(min_lre(p, x) >= 9.0);
            CHECK(rep.accelerated_steps > 0);
            CHECK(rep.accelerated_steps <= rep.iterations);
        } else {
            CHECK(min_lre(p, x) < 4.0);
            CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_MAX_ITERATIONS);
            CHECK_EQ_INT(rep.iterations, 1000);
            CHECK_EQ_INT(rep.accelerated_steps, 0);
        }
    }
}

/* ------------------------------------------------------------ covariance */

/* NIST certifies the standard deviation of every parameter: wherever the
 * estimates reach LRE >= 4 (start 2, default options), the standard errors
 * of plateau_lm_covariance match them with LRE >= 4, on all 27 problems;
 * and the covariance matrix is symmetric with sd_j^2 on its diagonal. */
static void test_nist_standard_deviations(void)
{
    size_t pi, j;
    int compared = 0;
    for (pi = 0; pi < NIST_COUNT; pi++) {
        const nist_problem *p = &nist_problems[pi];
        double x[NIST_MAX_N], cov[NIST_MAX_N * NIST_MAX_N], se[NIST_MAX_N];
        size_t rank = 0;
        memcpy(x, p->start2, sizeof(double) * p->n);
        CHECK_EQ_INT(plateau_lm_solve(p->m, p->n, x, nist_callback, (void *)p, NULL, NULL, 0, NULL,
                                      NULL),
                     PLATEAU_LM_OK);
        /* Lanczos1's residuals (RSS 1.4e-25) are the rounding of its data:
         * their sum in double, which s^2 needs, has only 3 correct digits */
        if (min_lre(p, x) < 4.0 || p->rss < 1e-20) continue;
        CHECK_EQ_INT(plateau_lm_covariance(p->m, p->n, x, nist_callback, (void *)p, NULL, cov, se,
                                           &rank, NULL, 0),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(rank, p->n);
        compared++;
        for (j = 0; j < p->n; j++) {
            double l = nist_lre(se[j], p->sd[j]);
            CHECK_MSG(l >= 4.0, p->name);
            if (l < 4.0) fprintf(stderr, "  %s sd %zu: %.10g certified %.10g\n", p->name, j, se[j], p->sd[j]);
            CHECK_REL(cov[j * p->n + j], se[j] * se[j], 1e-12, 0.0);
            CHECK(cov[j * p->n + (j + 1) % p->n] == cov[((j + 1) % p->n) * p->n + j]);
        }
    }
    CHECK(compared >= 25);
}

static int dup_residual(const double *x, double *f, double *jac, void *user)
{
    int i;
    (void)user;
    for (i = 0; i < 5; i++) {
        double t = (double)i;
        f[i] = (x[0] + x[1]) * t - 2.0 * t - 0.01 * (double)(i % 2);
        if (jac) { jac[2 * i] = t; jac[2 * i + 1] = t; }
    }
    return 0;
}

/* y = (a + b) t: only a + b is determined.  The covariance says so
 * (RANK_DEFICIENT, rank 1, zeroed output); with as many residuals as
 * parameters s^2 is undefined (NO_DEGREES_OF_FREEDOM). */
static void test_covariance_refuses_garbage(void)
{
    double x[2] = {1.0, 1.0}, cov[4] = {7, 7, 7, 7}, se[2] = {7, 7};
    size_t rank = 9;
    CHECK_EQ_INT(plateau_lm_covariance(5, 2, x, dup_residual, NULL, NULL, cov, se, &rank, NULL, 0),
                 PLATEAU_LM_ERR_RANK_DEFICIENT);
    CHECK_EQ_INT(rank, 1);
    CHECK(cov[0] == 0.0 && cov[3] == 0.0 && se[0] == 0.0 && se[1] == 0.0);
    CHECK_EQ_INT(plateau_lm_covariance(2, 2, x, dup_residual, NULL, NULL, cov, se, &rank, NULL, 0),
                 PLATEAU_LM_ERR_NO_DEGREES_OF_FREEDOM);
    CHECK_EQ_INT(plateau_lm_covariance(5, 2, NULL, dup_residual, NULL, NULL, cov, se, &rank, NULL, 0),
                 PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_covariance(5, 2, x, dup_residual, NULL, NULL, cov, se, &rank, cov, 1),
                 PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL);
}

/* ------------------------------------------------------------ Jacobian check */

typedef struct seeded {
    const nist_problem *p;
    size_t row, col;
    double factor, add;
} seeded;

static int seeded_callback(const double *x, double *f, double *jac, void *user)
{
    const seeded *s = (const seeded *)user;
    nist_residuals(s->p, x, f, jac);
    if (jac) jac[s->row * s->p->n + s->col] = jac[s->row * s->p->n + s->col] * s->factor + s->add;
    return 0;
}

/* A seeded error in one entry of a correct Jacobian is found and named:
 * a relative error of 1e-3, a flipped sign, and an entry set to zero, each
 * in a different problem; every other entry is judged correct. */
static void test_jacobian_check_finds_seeded_error(void)
{
    static const struct { int problem; size_t row, col; double factor, add; } cases[] = {
        {0, 5, 1, 1.001, 0.0},  /* Misra1a */
        {20, 30, 4, -1.0, 0.0}, /* Thurber: a sign */
        {11, 7, 3, 0.0, 0.0},   /* MGH17: a zero */
    };
    size_t c;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        seeded s;
        plateau_lm_jacobian_check chk;
        unsigned char verdicts[NIST_MAX_M * NIST_MAX_N];
        size_t i, bad = 0;
        s.p = &nist_problems[cases[c].problem];
        s.row = cases[c].row;
        s.col = cases[c].col;
        s.factor = cases[c].factor;
        s.add = cases[c].add;
        CHECK_EQ_INT(plateau_lm_check_jacobian(s.p->m, s.p->n, s.p->start2, seeded_callback, &s,
                                               NULL, &chk, verdicts, NULL, 0),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(chk.wrong, 1);
        CHECK_EQ_INT(chk.worst_row, (long)s.row);
        CHECK_EQ_INT(chk.worst_col, (long)s.col);
        CHECK(chk.worst_ratio > 1.0);
        for (i = 0; i < s.p->m * s.p->n; i++) bad += verdicts[i] == PLATEAU_LM_JACOBIAN_WRONG;
        CHECK_EQ_INT(bad, 1);
        CHECK_EQ_INT(verdicts[s.row * s.p->n + s.col], PLATEAU_LM_JACOBIAN_WRONG);
    }
}

/* ------------------------------------------------------------ bounds */

/* The problems of tests/lm_bounded.h; every evaluated point is checked
 * against the box and the inequalities (to rounding: 1e-12 of the row's
 * terms). */
typedef struct boxed {
    const bounded_case *c;
    int outside;     /* evaluations outside the box or an inequality */
} boxed;

static int box_callback(const double *x, double *f, double *jac, void *user)
{
    boxed *b = (boxed *)user;
    const bounded_case *c = b->c;
    size_t i, j;
    for (j = 0; j < c->n; j++)
        if ((c->lo && x[j] < c->lo[j]) || (c->up && x[j] > c->up[j])) b->outside++;
    for (i = 0; i < c->ni; i++) {
        double t = -c->d[i], scale = fabs(c->d[i]);
        for (j = 0; j < c->n; j++) {
            t += c->c[i * c->n + j] * x[j];
            scale += fabs(c->c[i * c->n + j] * x[j]);
        }
        if (t < -1e-12 * scale) b->outside++;
    }
    box_eval(c->id, x, f, jac);
    return 0;
}

/* the options of a case: its box and its linear constraints */
static plateau_lm_options case_options(const bounded_case *c)
{
    plateau_lm_options o = zero_options();
    o.lower = c->lo;
    o.upper = c->up;
    o.constraints = c->ne;
    o.a_eq = c->a;
    o.b_eq = c->b;
    o.inequalities = c->ni;
    o.c_ineq = c->c;
    o.d_ineq = c->d;
    return o;
}

/* Each problem reaches its published solution, with analytic and with
 * difference Jacobians, every evaluated point inside the box and the
 * inequalities, and the equalities holding at the end: HS01 (1, 1), f = 0;
 * HS21 (2, 0), f = 0.04 (x1 held at its lower bound); Hatfield B
 * (0.947214, 0.8, 0.64, 0.4096), f = 5.57281e-3 (x2 at 0.8); Hatfield C
 * (1, 1, 1, 1), f = 0; the combustion equilibrium f = 0 inside x >= 1e-4
 * (x = (0.0031141, 34.598, 0.065042, 0.85938, 0.036951)); modified HS235
 * (-1.725, 2.9, 0.725) from a start outside the box (x2 = 3 > 2.9);
 * modified BT7 (0.7, 0.49, 0.19, 1.19, -0.2); modified HS52 #1 (-0.09,
 * 0.03, 0.25, -0.19, 0.03) with x1 and x3 on their bounds; modified HS52
 * #2 (0.5, 2, 0, 1, 1), f = 0, inside its inequalities.  The starts are
 * levmar's (lmdemo.c). */
static void test_bounded_problems(void)
{
    size_t c, i, j;
    int numeric;
    for (numeric = 0; numeric < 2; numeric++)
        for (c = 0; c < BOUNDED_COUNT; c++) {
            const bounded_case *bc = &bounded_cases[c];
            plateau_lm_options o = case_options(bc);
            plateau_lm_report rep;
            boxed b;
            double x[5];
            char msg[96];
            sprintf(msg, "%s (%s)", bc->name, numeric ? "differences" : "analytic");
            b.c = bc;
            b.outside = 0;
            o.numeric_jacobian = numeric;
            memcpy(x, bc->x0, sizeof(double) * bc->n);
            CHECK_EQ_INT(plateau_lm_solve(bc->m, bc->n, x, box_callback, &b, &o, NULL, 0, &rep, NULL),
                         PLATEAU_LM_OK);
            CHECK_MSG(b.outside == 0, msg);
            /* differences: 1e-15 (HS52 #2 ends with x3 ~ 1e-8, where the
             * difference step fd_step |x3| is too small to be accurate) */
            if (bc->fstar == 0.0) CHECK_MSG(2.0 * rep.f_final < (numeric ? 1e-15 : 1e-20), msg);
            else CHECK_REL(2.0 * rep.f_final, bc->fstar, 1e-5, 0.0);
            for (j = 0; j < bc->n; j++)
                CHECK_NEAR(x[j], bc->xs[j], 1e-4 * fabs(bc->xs[j]) + 1e-6);
            for (i = 0; i < bc->ne; i++) {
                double t = -bc->b[i];
                for (j = 0; j < bc->n; j++) t += bc->a[i * bc->n + j] * x[j];
                CHECK_NEAR(t, 0.0, 1e-12);
            }
            if (bc->id == 21 || bc->id == 2) CHECK_EQ_INT(rep.active_bounds, 1);
            CHECK_EQ_INT(rep.free_parameters, bc->n - bc->ne);
        }
}

/* Bad boxes get named errors, x untouched: lower > upper, a NaN bound, a
 * lower bound of +inf; a start outside the box (err->index names it). */
static void test_bad_bounds(void)
{
    static const double lo[2] = {0.0, 0.0}, up[2] = {1.0, -1.0}, upok[2] = {1.0, 1.0};
    plateau_lm_options o = zero_options();
    plateau_lm_error err;
    boxed b;
    bounded_case hs1 = bounded_cases[0]; /* HS01, its box not checked by the callback */
    double x[2] = {0.5, 0.5}, nanb[2], infb[2] = {HUGE_VAL, 0.0};
    hs1.lo = hs1.up = NULL;
    b.c = &hs1;
    b.outside = 0;
    nanb[0] = 0.0;
    nanb[1] = nan("");
    o.lower = lo;
    o.upper = up;
    CHECK_EQ_INT(plateau_lm_solve(2, 2, x, box_callback, &b, &o, NULL, 0, NULL, &err),
                 PLATEAU_LM_ERR_BAD_BOUNDS);
    CHECK_EQ_INT(err.index, 1);
    o.upper = NULL;
    o.lower = nanb;
    CHECK_EQ_INT(plateau_lm_solve(2, 2, x, box_callback, &b, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_BAD_BOUNDS);
    o.lower = infb;
    CHECK_EQ_INT(plateau_lm_solve(2, 2, x, box_callback, &b, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_BAD_BOUNDS);
    o.lower = lo;
    o.upper = upok;
    x[1] = 1.5;
    CHECK_EQ_INT(plateau_lm_solve(2, 2, x, box_callback, &b, &o, NULL, 0, NULL, &err),
                 PLATEAU_LM_ERR_X0_OUTSIDE_BOUNDS);
    CHECK_EQ_INT(err.index, 1);
    CHECK(x[0] == 0.5 && x[1] == 1.5);
    CHECK_EQ_INT(b.outside, 0);
}

/* ------------------------------------------------------------ constraints */

static int hs52_residual(const double *x, double *f, double *jac, void *user)
{
    size_t i;
    (void)user;
    f[0] = 4.0 * x[0] - x[1];
    f[1] = x[1] + x[2] - 2.0;
    f[2] = x[3] - 1.0;
    f[3] = x[4] - 1.0;
    if (jac) {
        for (i = 0; i < 20; i++) jac[i] = 0.0;
        jac[0] = 4.0; jac[1] = -1.0;
        jac[6] = 1.0; jac[7] = 1.0;
        jac[13] = 1.0;
        jac[19] = 1.0;
    }
    return 0;
}

/* HS52 (Hock and Schittkowski): min (4 x1 - x2)^2 + (x2 + x3 - 2)^2 +
 * (x4 - 1)^2 + (x5 - 1)^2 subject to x1 + 3 x2 = 0, x3 + x4 - 2 x5 = 0,
 * x2 - x5 = 0: x* = (-33, 11, 180, -158, 11) / 349, f* = 1859 / 349, from
 * the start (2, 2, 2, 2, 2) (infeasible: it is projected) and with a
 * fourth, redundant row (the sum of the first two).  Inconsistent rows
 * give INCONSISTENT_CONSTRAINTS. */
static void test_linear_constraints_hs52(void)
{
    static const double A[20] = {1, 3, 0, 0, 0, 0, 0, 1, 1, -2, 0, 1, 0, 0, -1, 1, 3, 1, 1, -2};
    static const double b[4] = {0, 0, 0, 0}, bbad[4] = {0, 0, 0, 1};
    static const double xs[5] = {-33.0 / 349, 11.0 / 349, 180.0 / 349, -158.0 / 349, 11.0 / 349};
    size_t rows, j;
    for (rows = 3; rows <= 4; rows++) {
        plateau_lm_options o = zero_options();
        plateau_lm_report rep;
        double x[5] = {2, 2, 2, 2, 2}, cov[25], se[5];
        size_t rank = 0;
        o.constraints = rows;
        o.a_eq = A;
        o.b_eq = b;
        CHECK_EQ_INT(plateau_lm_solve(4, 5, x, hs52_residual, NULL, &o, NULL, 0, &rep, NULL),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(rep.free_parameters, 2);
        CHECK_REL(2.0 * rep.f_final, 1859.0 / 349.0, 1e-12, 0.0);
        for (j = 0; j < 5; j++) CHECK_NEAR(x[j], xs[j], 1e-12);
        CHECK_NEAR(x[0] + 3.0 * x[1], 0.0, 1e-14);
        CHECK_NEAR(x[2] + x[3] - 2.0 * x[4], 0.0, 1e-14);
        /* two free parameters, four residuals: two degrees of freedom */
        CHECK_EQ_INT(plateau_lm_covariance(4, 5, x, hs52_residual, NULL, &o, cov, se, &rank, NULL, 0),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(rank, 2);
        /* the covariance lives in the null space: A cov = 0 */
        for (j = 0; j < 5; j++) CHECK_NEAR(cov[0 * 5 + j] + 3.0 * cov[1 * 5 + j], 0.0, 1e-12);
    }
    {
        plateau_lm_options o = zero_options();
        double x[5] = {2, 2, 2, 2, 2};
        o.constraints = 4;
        o.a_eq = A;
        o.b_eq = bbad;
        CHECK_EQ_INT(plateau_lm_solve(4, 5, x, hs52_residual, NULL, &o, NULL, 0, NULL, NULL),
                     PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS);
        o.b_eq = NULL;
        CHECK_EQ_INT(plateau_lm_solve(4, 5, x, hs52_residual, NULL, &o, NULL, 0, NULL, NULL),
                     PLATEAU_LM_ERR_ARGUMENT);
    }
}

/* ------------------------------------------------------------ weights, losses */

#define LINE_M 12
static const double line_t[LINE_M] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
/* y = 1 + 2 t with small deterministic noise, and two outliers (rows 3, 8) */
static double line_y(size_t i)
{
    double noise = 0.01 * (double)((i * 7) % 5) - 0.02;
    return 1.0 + 2.0 * line_t[i] + noise + (i == 3 ? 30.0 : i == 8 ? -25.0 : 0.0);
}
static int line_residual(const double *x, double *f, double *jac, void *user)
{
    size_t i;
    (void)user;
    for (i = 0; i < LINE_M; i++) {
        f[i] = x[0] + x[1] * line_t[i] - line_y(i);
        if (jac) { jac[2 * i] = 1.0; jac[2 * i + 1] = line_t[i]; }
    }
    return 0;
}

/* Weighted least squares: the answer of the weighted normal equations
 * (sum w [1 t; t t^2]) x = sum w y [1; t], solved here in closed form; a
 * zero weight removes a row; a negative weight is refused. */
static void test_weights(void)
{
    double w[LINE_M], x[2] = {0.0, 0.0}, s0 = 0, s1 = 0, s2 = 0, r0 = 0, r1 = 0, det;
    plateau_lm_options o = zero_options();
    plateau_lm_report rep;
    size_t i;
    for (i = 0; i < LINE_M; i++) {
        w[i] = i == 3 || i == 8 ? 0.0 : 1.0 + 0.5 * (double)(i % 3);
        s0 += w[i];
        s1 += w[i] * line_t[i];
        s2 += w[i] * line_t[i] * line_t[i];
        r0 += w[i] * line_y(i);
        r1 += w[i] * line_y(i) * line_t[i];
    }
    det = s0 * s2 - s1 * s1;
    o.weights = w;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                 PLATEAU_LM_OK);
    CHECK_NEAR(x[0], (s2 * r0 - s1 * r1) / det, 1e-12);
    CHECK_NEAR(x[1], (s0 * r1 - s1 * r0) / det, 1e-12);
    w[5] = -1.0;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_ARGUMENT);
}

static int rosenbrock_residual(const double *x, double *f, double *jac, void *user)
{
    (void)user;
    f[0] = 10.0 * (x[1] - x[0] * x[0]);
    f[1] = 1.0 - x[0];
    if (jac) { jac[0] = -20.0 * x[0]; jac[1] = 10.0; jac[2] = -1.0; jac[3] = 0.0; }
    return 0;
}

/* Uniform weights scale F and J^T J alone: the minimiser is that of weight
 * 1, for weights up to 1e300 (J^T J near 1e303).  The first step's bound
 * and the damping limit are relative to that scale (an absolute limit
 * stopped weights >= 1e200 at the start, "damping"). */
static void test_weights_of_any_scale(void)
{
    static const double scale[] = {1.0, 1e100, 1e200, 1e250, 1e300};
    double ref[2] = {0.0, 0.0};
    size_t k, i;
    for (k = 0; k < sizeof scale / sizeof scale[0]; k++) {
        double w[LINE_M], x[2] = {0.0, 0.0}, y[2] = {-1.2, 1.0};
        plateau_lm_options o = zero_options();
        plateau_lm_report rep;
        for (i = 0; i < LINE_M; i++) w[i] = scale[k];
        o.weights = w;
        CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                     PLATEAU_LM_OK);
        if (!CHECK(rep.stop != PLATEAU_LM_STOP_DAMPING && rep.iterations > 1))
            fprintf(stderr, "  line, weights %g: %s after %d\n", scale[k],
                    plateau_lm_stop_string(rep.stop), (int)rep.iterations);
        if (k == 0) { ref[0] = x[0]; ref[1] = x[1]; }
        CHECK_NEAR(x[0], ref[0], 1e-12);
        CHECK_NEAR(x[1], ref[1], 1e-12);
        CHECK_EQ_INT(plateau_lm_solve(2, 2, y, rosenbrock_residual, NULL, &o, NULL, 0, &rep, NULL),
                     PLATEAU_LM_OK);
        if (!CHECK(rep.stop != PLATEAU_LM_STOP_DAMPING))
            fprintf(stderr, "  Rosenbrock, weights %g: %s after %d\n", scale[k],
                    plateau_lm_stop_string(rep.stop), (int)rep.iterations);
        CHECK_NEAR(y[0], 1.0, 1e-8);
        CHECK_NEAR(y[1], 1.0, 1e-8);
    }
}

/* A robust loss by IRLS: the answer is a stationary point of the robust
 * objective sum rho(f_i) (its gradient sum rho'(f_i) df_i/dx, formed here,
 * vanishes), and the two outliers move the line far less than they move
 * the least-squares line. */
static void test_robust_losses(void)
{
    int loss;
    double xls[2] = {0.0, 0.0};
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, xls, line_residual, NULL, NULL, NULL, 0, NULL, NULL),
                 PLATEAU_LM_OK);
    for (loss = 1; loss <= 2; loss++) {
        plateau_lm_options o = zero_options();
        plateau_lm_report rep;
        double x[2] = {0.0, 0.0}, f[LINE_M], g0 = 0.0, g1 = 0.0, c = 0.5;
        size_t i;
        o.loss = (plateau_lm_loss)loss;
        o.loss_scale = c;
        CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                     PLATEAU_LM_OK);
        CHECK(rep.irls_rounds >= 2);
        line_residual(x, f, NULL, NULL);
        for (i = 0; i < LINE_M; i++) {
            double psi = loss == 1 ? (fabs(f[i]) <= c ? f[i] : c * (f[i] > 0 ? 1.0 : -1.0))
                                   : f[i] / (1.0 + (f[i] / c) * (f[i] / c));
            g0 += psi;
            g1 += psi * line_t[i];
        }
        CHECK_NEAR(g0, 0.0, 1e-8);
        CHECK_NEAR(g1, 0.0, 1e-7);
        CHECK(fabs(x[1] - 2.0) < 0.2 * fabs(xls[1] - 2.0));
        CHECK(fabs(x[1] - 2.0) < 0.02);
    }
}

/* ------------------------------------------------------------ workspace */

static int counting_allocs;
static void *count_alloc(size_t size, void *user) { (void)user; counting_allocs++; return malloc(size); }
static void count_free(void *p, void *user) { (void)user; free(p); }

/* With every feature on (bounds, weights, a robust loss, geodesic
 * acceleration; constraints in a second solve; bounds, an equality and an
 * inequality in a third) a caller workspace of
 * plateau_lm_workspace_size() bytes means no allocation, and the same
 * iterates as an allocating solve. */
static void test_workspace_with_features(void)
{
    static const double lo[2] = {-10.0, 1.0}, up[2] = {10.0, 1.9};
    static const double A[2] = {1.0, 1.0}, b[1] = {3.0}, C[2] = {-1.0, 1.0}, d[1] = {-1.4};
    double w[LINE_M];
    size_t i, need;
    int pass;
    for (i = 0; i < LINE_M; i++) w[i] = 1.0 + (double)(i % 2);
    for (pass = 0; pass < 3; pass++) {
        plateau_lm_options o = zero_options();
        double x[2] = {0.0, 1.5}, x2[2] = {0.0, 1.5};
        unsigned char *buf;
        o.allocator.alloc_fn = count_alloc;
        o.allocator.free_fn = count_free;
        o.weights = w;
        o.loss = PLATEAU_LM_LOSS_HUBER;
        o.geodesic = PLATEAU_LM_GEODESIC_ALWAYS;
        if (pass == 0) { o.lower = lo; o.upper = up; }
        else { o.constraints = 1; o.a_eq = A; o.b_eq = b; }
        if (pass == 2) { o.lower = lo; o.upper = up; o.inequalities = 1; o.c_ineq = C; o.d_ineq = d; }
        need = plateau_lm_workspace_size(LINE_M, 2, &o);
        CHECK(need > plateau_lm_workspace_size(LINE_M, 2, NULL));
        buf = (unsigned char *)malloc(need + 1);
        counting_allocs = 0;
        CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, buf + 1, need, NULL, NULL),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(counting_allocs, 0);
        CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x2, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                     PLATEAU_LM_OK);
        CHECK_EQ_INT(counting_allocs, 1);
        CHECK(x[0] == x2[0] && x[1] == x2[1]);
        if (pass == 0) CHECK(x[1] == 1.9);
        else CHECK_NEAR(x[0] + x[1], 3.0, 1e-14);
        if (pass == 2) CHECK(x[1] - x[0] >= -1.4 - 1e-14 && x[1] <= 1.9);
        free(buf);
    }
}

/* A linear fit y = x1 + x2 t (the line data) under x1 + 5 x2 <= 8, which
 * the unconstrained fit breaks: the constrained least-squares solution is
 * beta_u - M^-1 a (a^T beta_u - c) / (a^T M^-1 a), M = X^T X, a = (1, 5),
 * c = 8 (the Lagrange condition of the one active row), computed here in
 * closed form; the start (0, 3) breaks the row and is moved onto it.
 * Then the errors: rows without a common point (x1 >= 1, x1 <= 0), a box
 * that misses A x = b, a NaN in C (INCONSISTENT_CONSTRAINTS, x untouched),
 * inequalities without C (ARGUMENT), and an unknown geodesic mode. */
static void test_linear_inequalities(void)
{
    static const double C[2] = {-1.0, -5.0}, d[1] = {-8.0};
    static const double Cbad[4] = {1.0, 0.0, -1.0, 0.0}, dbad[2] = {1.0, 0.0};
    static const double lo[2] = {0.0, 0.0}, up[2] = {1.0, 1.0}, A[2] = {1.0, 1.0}, b[1] = {3.0};
    plateau_lm_options o = zero_options();
    plateau_lm_report rep;
    double x[2] = {0.0, 3.0}, m00 = 0, m01 = 0, m11 = 0, r0 = 0, r1 = 0, det, bu0, bu1, i00, i01, i11;
    double q0, q1, lam, Cnan[2];
    size_t i;
    for (i = 0; i < LINE_M; i++) {
        m00 += 1.0; m01 += line_t[i]; m11 += line_t[i] * line_t[i];
        r0 += line_y(i); r1 += line_t[i] * line_y(i);
    }
    det = m00 * m11 - m01 * m01;
    i00 = m11 / det; i01 = -m01 / det; i11 = m00 / det;
    bu0 = i00 * r0 + i01 * r1;
    bu1 = i01 * r0 + i11 * r1;
    CHECK(bu0 + 5.0 * bu1 > 8.0); /* the row is active at the solution */
    q0 = i00 * 1.0 + i01 * 5.0;   /* M^-1 a */
    q1 = i01 * 1.0 + i11 * 5.0;
    lam = (bu0 + 5.0 * bu1 - 8.0) / (q0 + 5.0 * q1);
    o.inequalities = 1;
    o.c_ineq = C;
    o.d_ineq = d;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                 PLATEAU_LM_OK);
    CHECK_NEAR(x[0], bu0 - lam * q0, 1e-10);
    CHECK_NEAR(x[1], bu1 - lam * q1, 1e-10);
    CHECK_NEAR(x[0] + 5.0 * x[1], 8.0, 1e-12);
    CHECK_EQ_INT(rep.free_parameters, 2);
    /* the errors */
    x[0] = 0.5; x[1] = 0.25;
    o.c_ineq = Cbad;
    o.d_ineq = dbad;
    o.inequalities = 2;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS);
    CHECK(x[0] == 0.5 && x[1] == 0.25);
    o = zero_options();
    o.lower = lo;
    o.upper = up;
    o.constraints = 1;
    o.a_eq = A;
    o.b_eq = b;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS);
    CHECK(x[0] == 0.5 && x[1] == 0.25);
    o = zero_options();
    Cnan[0] = 1.0;
    Cnan[1] = nan("");
    o.inequalities = 1;
    o.c_ineq = Cnan;
    o.d_ineq = d;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS);
    o.c_ineq = NULL;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_ARGUMENT);
    o = zero_options();
    o.geodesic = (plateau_lm_geodesic)2;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL),
                 PLATEAU_LM_ERR_ARGUMENT);
    CHECK(x[0] == 0.5 && x[1] == 0.25);
}

/* plateau_lm_workspace_size against the formulas of MEMORY in the manual:
 * 8 (W + 1) bytes, W doubles = m n + 2 k^2 + 2 m + 5 n + k (k = min(m, n),
 * or n with rows) plus each feature's part. */
static size_t manual_doubles(size_t m, size_t n, int weights, int box, int geo, int refine,
                             size_t rows)
{
    size_t k = rows > 0 ? n : (m < n ? m : n);
    size_t w = m * n + 2 * k * k + 2 * m + 5 * n + k;
    if (refine && m > n) w += m * n + m + 3 * n;
    if (weights) w += m;
    if (box) w += n;
    if (geo) w += m + n;
    if (rows > 0) w += 2 * rows * n + 3 * rows + n * n + 10 * n;
    return w;
}

static void test_workspace_formulas(void)
{
    static const size_t dims[3][2] = {{10, 3}, {3, 10}, {6, 6}};
    static const double lo[10] = {0}, A[20] = {1, 1}, C[30] = {1};
    size_t di, m, n, ke, big, w;
    int mask;
    for (di = 0; di < 3; di++) {
        m = dims[di][0];
        n = dims[di][1];
        for (mask = 0; mask < 16; mask++) {
            plateau_lm_options o = zero_options();
            int weights = mask & 1, box = (mask >> 1) & 1, geo = !((mask >> 2) & 1), refine = !(mask >> 3);
            if (weights) o.loss = PLATEAU_LM_LOSS_HUBER;
            if (box) o.lower = lo;
            if (!geo) o.geodesic = PLATEAU_LM_GEODESIC_NEVER;
            if (!refine) o.refine = -1;
            w = manual_doubles(m, n, weights, box, geo, refine, 0);
            CHECK_EQ_INT(plateau_lm_workspace_size(m, n, &o), 8 * (w + 1));
            /* two equalities: the solve in y without the box (with the box,
             * rows: n of them), then the map back */
            o.constraints = ke = 2;
            o.a_eq = A;
            o.b_eq = A;
            big = n > ke ? n : ke;
            w = manual_doubles(m, n, weights, 0, geo && !box, refine, box ? n : 0);
            if (refine) w += m * n + m + 3 * n;
            w += n * n + m * n + n * ke + 3 * big + 4 * n;
            CHECK_EQ_INT(plateau_lm_workspace_size(m, n, &o), 8 * (w + 1));
            /* three inequalities besides */
            o.inequalities = 3;
            o.c_ineq = C;
            o.d_ineq = C;
            w = manual_doubles(m, n, weights, 0, 0, refine, (box ? n : 0) + 3);
            if (refine) w += m * n + m + 3 * n;
            w += n * n + m * n + n * ke + 3 * big + 4 * n;
            CHECK_EQ_INT(plateau_lm_workspace_size(m, n, &o), 8 * (w + 1));
        }
    }
}

/* ------------------------------------------------------------ the quick start */

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    buf = (char *)malloc((size_t)n + 1);
    if (buf) buf[fread(buf, 1, (size_t)n, f)] = '\0';
    fclose(f);
    return buf;
}

/* the lines after the first `marker` in text: those starting with prefix
 * (stripped), up to the first that does not (or up to `end` when prefix
 * is ""), into out, each ending in a newline */
static void claimed_lines(const char *text, const char *marker, const char *prefix,
                          const char *end, char *out, size_t size)
{
    const char *p = text ? strstr(text, marker) : NULL;
    size_t used = 0, lp = strlen(prefix);
    out[0] = '\0';
    if (!p) return;
    p = strchr(p, '\n');
    while (p && *++p) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        if (*end ? strncmp(p, end, strlen(end)) == 0 : strncmp(p, prefix, lp) != 0) break;
        if (len >= lp && used + len - lp + 2 < size) {
            memcpy(out + used, p + lp, len - lp);
            used += len - lp;
            out[used++] = '\n';
            out[used] = '\0';
        }
        p = eol;
    }
}

/* The README shows the session as typed: the "$ " command lines (the
 * compile lines and the run) go, what the program printed stays. */
static void drop_command_lines(char *text)
{
    char *in = text, *out = text;
    while (*in) {
        char *end = strchr(in, '\n');
        size_t len = end ? (size_t)(end - in) + 1 : strlen(in);
        if (strncmp(in, "$ ", 2) != 0) {
            memmove(out, in, len);
            out += len;
        }
        in += len;
    }
    *out = '\0';
}

/* The quick start exits 0 and prints what its comment and the README say it
 * prints, line for line. */
static void test_quickstart_output(void)
{
    char got[1024], said[1024], *text;
    FILE *tmp = tmpfile();
    int saved, status;
    size_t len;
    if (!CHECK(tmp != NULL)) return;
    fflush(stdout);
    saved = dup(1);
    dup2(fileno(tmp), 1);
    status = lm_quickstart_main();
    fflush(stdout);
    dup2(saved, 1);
    close(saved);
    rewind(tmp);
    len = fread(got, 1, sizeof got - 1, tmp);
    got[len] = '\0';
    fclose(tmp);
    CHECK_EQ_INT(status, 0);
    text = read_file("examples/lm_quickstart.c");
    claimed_lines(text, "It prints", " *     ", "", said, sizeof said);
    CHECK(said[0] != '\0');
    CHECK_MSG(strcmp(got, said) == 0, "examples/lm_quickstart.c's comment");
    if (strcmp(got, said) != 0) fprintf(stderr, "  prints:\n%s  says:\n%s", got, said);
    free(text);
    text = read_file("README.md");
    claimed_lines(text ? strstr(text, "## Quick start: `plateau_lm.h`") : NULL, "```text", "", "```",
                  said, sizeof said);
    drop_command_lines(said);
    CHECK(said[0] != '\0');
    CHECK_MSG(strcmp(got, said) == 0, "README.md's plateau_lm.h quick start");
    if (strcmp(got, said) != 0) fprintf(stderr, "  prints:\n%s  README says:\n%s", got, said);
    free(text);
}

/* f(x) = (x1 + x2 + x3 - 3, 0.5) with x1 + x2 + x3 = 1 fixed by the
 * constraint: the free parameters do not move f, so J Z is rounding noise
 * (or 0); with MINPACK's scaling the steps once followed that noise to
 * |x| ~ 1e18, where x_p + Z y no longer holds the constraint.  x must stay
 * put (the projection of x0), the constraint hold, and the refinement
 * take no step. */
static int flat_residual(const double *x, double *f, double *jac, void *user)
{
    (void)user;
    f[0] = -3.0 + 1.0 * x[0] + 1.0 * x[1] + 1.0 * x[2];
    f[1] = 0.5;
    f[2] = 0.25 * x[0] + 0.25 * x[1] + 0.25 * x[2];
    if (jac) {
        jac[0] = jac[1] = jac[2] = 1.0;
        jac[3] = jac[4] = jac[5] = 0.0;
        jac[6] = jac[7] = jac[8] = 0.25;
    }
    return 0;
}

static void test_free_parameters_that_do_not_matter(void)
{
    static const double A[3] = {1.0, 1.0, 1.0}, b[1] = {1.0};
    int scaling, numeric;
    for (scaling = 0; scaling < 2; scaling++)
        for (numeric = 0; numeric < 2; numeric++) {
            plateau_lm_options o = zero_options();
            plateau_lm_report rep;
            double x[3] = {0.7, -0.2, 0.1};
            o.constraints = 1;
            o.a_eq = A;
            o.b_eq = b;
            o.scaling = scaling ? PLATEAU_LM_SCALING_ADAPTIVE : PLATEAU_LM_SCALING_NONE;
            o.numeric_jacobian = numeric;
            CHECK_EQ_INT(plateau_lm_solve(3, 3, x, flat_residual, NULL, &o, NULL, 0, &rep, NULL),
                         PLATEAU_LM_OK);
            CHECK_NEAR(x[0] + x[1] + x[2], 1.0, 1e-12);
            CHECK(fabs(x[0]) + fabs(x[1]) + fabs(x[2]) < 10.0);
            CHECK_EQ_INT(rep.refinement_steps, 0);
        }
}

/* GEODESIC ACCELERATION's gate: on a linear problem f is linear along every
 * step, so AUTO spends its probe on the first step only (at most one
 * accelerated step); ALWAYS probes every iteration (one more residual per
 * iteration). */
static void test_geodesic_auto_gate(void)
{
    plateau_lm_options o = zero_options();
    plateau_lm_report rep, rep2;
    double x[2] = {0.0, 0.0}, x2[2] = {0.0, 0.0};
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, &rep, NULL),
                 PLATEAU_LM_OK);
    CHECK(rep.accelerated_steps <= 1);
    o.geodesic = PLATEAU_LM_GEODESIC_ALWAYS;
    CHECK_EQ_INT(plateau_lm_solve(LINE_M, 2, x2, line_residual, NULL, &o, NULL, 0, &rep2, NULL),
                 PLATEAU_LM_OK);
    CHECK(rep2.residual_evaluations >= rep2.iterations + rep2.refinement_steps);
    CHECK(rep.residual_evaluations < rep2.residual_evaluations);
    CHECK_NEAR(x[0], x2[0], 1e-9);
    CHECK_NEAR(x[1], x2[1], 1e-9);
}

static int fail_live;
static void *fail_alloc(size_t size, void *user) { (void)size; (void)user; return NULL; }
static void *live_alloc(size_t size, void *user) { (void)user; fail_live++; return malloc(size); }
static void live_free(void *p, void *user) { (void)user; fail_live--; free(p); }

/* Allocation failure on every new path (each makes one allocation):
 * OUT_OF_MEMORY, x untouched; and with a working allocator nothing leaks. */
static void test_allocation_failure_new_paths(void)
{
    static const double lo[2] = {-10.0, 1.0}, up[2] = {10.0, 1.9};
    static const double A[2] = {1.0, 1.0}, b[1] = {3.0};
    int pass, alloc_ok;
    for (alloc_ok = 0; alloc_ok < 2; alloc_ok++)
        for (pass = 0; pass < 6; pass++) {
            plateau_lm_options o = zero_options();
            plateau_lm_jacobian_check chk;
            double x[2] = {0.5, 1.5}, se[2];
            size_t rank;
            plateau_lm_result r;
            o.allocator.alloc_fn = alloc_ok ? live_alloc : fail_alloc;
            o.allocator.free_fn = live_free;
            if (pass == 0) { o.lower = lo; o.upper = up; o.geodesic = PLATEAU_LM_GEODESIC_ALWAYS; }
            if (pass == 1) { o.constraints = 1; o.a_eq = A; o.b_eq = b; }
            if (pass == 2) o.loss = PLATEAU_LM_LOSS_CAUCHY;
            if (pass == 5) { o.lower = lo; o.upper = up; o.inequalities = 1; o.c_ineq = A; o.d_ineq = b; }
            if (pass < 3 || pass == 5)
                r = plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL);
            else if (pass == 3) r = plateau_lm_covariance(LINE_M, 2, x, line_residual, NULL, &o, NULL, se, &rank, NULL, 0);
            else r = plateau_lm_check_jacobian(LINE_M, 2, x, line_residual, NULL, &o, &chk, NULL, NULL, 0);
            CHECK_EQ_INT(r, alloc_ok ? PLATEAU_LM_OK : PLATEAU_LM_ERR_OUT_OF_MEMORY);
            if (!alloc_ok) CHECK(x[0] == 0.5 && x[1] == 1.5);
            CHECK_EQ_INT(fail_live, 0);
        }
}

int main(void)
{
    RUN(test_nist_data_and_jacobians);
    RUN(test_nist_accuracy);
    RUN(test_geodesic_acceleration_solves_mgh10);
    RUN(test_nist_standard_deviations);
    RUN(test_covariance_refuses_garbage);
    RUN(test_jacobian_check_finds_seeded_error);
    RUN(test_bounded_problems);
    RUN(test_bad_bounds);
    RUN(test_linear_constraints_hs52);
    RUN(test_weights);
    RUN(test_weights_of_any_scale);
    RUN(test_robust_losses);
    RUN(test_workspace_with_features);
    RUN(test_linear_inequalities);
    RUN(test_workspace_formulas);
    RUN(test_quickstart_output);
    RUN(test_free_parameters_that_do_not_matter);
    RUN(test_geodesic_auto_gate);
    RUN(test_allocation_failure_new_paths);
    return harness_report("test_lm_fit");
}
