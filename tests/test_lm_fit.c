/* test_lm_fit.c - tests of plateau_lm.h as a least-squares fitting library:
 * NIST StRD nonlinear regression (tests/lm_nist.h: the certified
 * parameters and their standard deviations), box bounds, linear equality
 * constraints, weights and robust losses, the Jacobian check and geodesic
 * acceleration. */
#define PLATEAU_LM_IMPLEMENTATION
#include "../plateau_lm.h"
#include "harness.h"
#include "lm_nist.h"
#include "lm_bounded.h"

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

/* The 54 runs with the default options and analytic Jacobians.  NIST's
 * rule: 4 correct digits (LRE >= 4) on every parameter.  Measured: 52 of
 * 54, the average of the per-run minimum LRE 10.32, 14 of the 16 runs of
 * higher difficulty (MGH10 from start 1 crawls to max_iterations along a
 * valley to infinity; Thurber from start 2 stops at 2F = 7682 against the
 * certified 5643).  With geodesic acceleration: 53 of 54, 16 of 16, 10.53
 * (Hahn1 from start 2 goes astray).  The floors leave a margin for
 * compilers. */
static void test_nist_accuracy(void)
{
    int geo;
    for (geo = 0; geo < 2; geo++) {
        size_t pi;
        int s, solved = 0, hard = 0;
        double total = 0.0;
        for (pi = 0; pi < NIST_COUNT; pi++) {
            const nist_problem *p = &nist_problems[pi];
            for (s = 0; s < 2; s++) {
                plateau_lm_options o = zero_options();
                plateau_lm_report rep;
                double x[NIST_MAX_N], lre;
                o.geodesic = geo;
                memcpy(x, s == 0 ? p->start1 : p->start2, p->n * sizeof(double));
                CHECK_EQ_INT(plateau_lm_solve(p->m, p->n, x, nist_callback, (void *)p, &o, NULL, 0,
                                              &rep, NULL),
                             PLATEAU_LM_OK);
                lre = min_lre(p, x);
                total += lre;
                if (lre >= 4.0) {
                    solved++;
                    hard += p->difficulty == 2;
                }
            }
        }
        printf("  NIST StRD%s: %d of 54 runs with LRE >= 4 (%d of 16 of higher difficulty), "
               "average minimum LRE %.2f\n", geo ? " with geodesic acceleration" : "", solved, hard,
               total / 54.0);
        CHECK(solved >= (geo ? 53 : 52));
        CHECK(hard >= (geo ? 16 : 14));
        CHECK(total / 54.0 >= (geo ? 10.3 : 10.0));
    }
}

/* MGH10 from NIST's start 1 (b = 2, 4e5, 2.5e4) reaches the certified
 * answer with geodesic acceleration, the steps carrying it accepted. */
static void test_geodesic_acceleration_solves_mgh10(void)
{
    const nist_problem *p = NULL;
    plateau_lm_options o = zero_options();
    plateau_lm_report rep;
    double x[NIST_MAX_N];
    size_t pi;
    for (pi = 0; pi < NIST_COUNT; pi++)
        if (strcmp(nist_problems[pi].name, "MGH10") == 0) p = &nist_problems[pi];
    CHECK(p != NULL);
    if (!p) return;
    o.geodesic = 1;
    memcpy(x, p->start1, sizeof(double) * p->n);
    CHECK_EQ_INT(plateau_lm_solve(p->m, p->n, x, nist_callback, (void *)p, &o, NULL, 0, &rep, NULL),
                 PLATEAU_LM_OK);
    CHECK(min_lre(p, x) >= 9.0);
    CHECK(rep.accelerated_steps > 0);
    CHECK(rep.accelerated_steps <= rep.iterations);
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

/* The bounded problems of tests/lm_bounded.h; every evaluated point is
 * checked against the box. */
typedef struct boxed {
    int id;
    const double *lo, *up;
    int outside;     /* evaluations outside the box */
} boxed;

static int box_callback(const double *x, double *f, double *jac, void *user)
{
    boxed *b = (boxed *)user;
    size_t n = b->id == 1 || b->id == 21 ? 2 : b->id == 5 ? 5 : 4, j;
    for (j = 0; j < n; j++)
        if ((b->lo && x[j] < b->lo[j]) || (b->up && x[j] > b->up[j])) b->outside++;
    box_eval(b->id, x, f, jac);
    return 0;
}

/* Each bounded problem reaches its published solution with every iterate,
 * trial point and difference point inside the box: HS01 (1, 1), f = 0;
 * HS21 (2, 0), f = 0.04 (x1 held at its lower bound); Hatfield B
 * (0.947214, 0.8, 0.64, 0.4096), f = 5.57281e-3 (x2 at 0.8); Hatfield C
 * (1, 1, 1, 1), f = 0; the combustion equilibrium f = 0 inside x >= 1e-4
 * (x = (0.0031141, 34.598, 0.065042, 0.85938, 0.036951)). */
static void test_bounded_problems(void)
{
    size_t c, j;
    int numeric;
    for (numeric = 0; numeric < 2; numeric++)
        for (c = 0; c < BOUNDED_COUNT; c++) {
            plateau_lm_options o = zero_options();
            plateau_lm_report rep;
            boxed b;
            double x[5];
            size_t m = bounded_cases[c].n;
            b.id = bounded_cases[c].id;
            b.lo = bounded_cases[c].lo;
            b.up = bounded_cases[c].up;
            b.outside = 0;
            o.lower = bounded_cases[c].lo;
            o.upper = bounded_cases[c].up;
            o.numeric_jacobian = numeric;
            memcpy(x, bounded_cases[c].x0, sizeof(double) * bounded_cases[c].n);
            CHECK_EQ_INT(plateau_lm_solve(m, bounded_cases[c].n, x, box_callback, &b, &o, NULL, 0, &rep, NULL),
                         PLATEAU_LM_OK);
            CHECK_EQ_INT(b.outside, 0);
            if (bounded_cases[c].fstar == 0.0) CHECK(2.0 * rep.f_final < 1e-20);
            else CHECK_REL(2.0 * rep.f_final, bounded_cases[c].fstar, 1e-5, 0.0);
            for (j = 0; j < bounded_cases[c].n; j++)
                CHECK_NEAR(x[j], bounded_cases[c].xs[j], 1e-4 * fabs(bounded_cases[c].xs[j]) + 1e-6);
            if (b.id == 21 || b.id == 2) CHECK_EQ_INT(rep.active_bounds, 1);
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
    double x[2] = {0.5, 0.5}, nanb[2], infb[2] = {HUGE_VAL, 0.0};
    b.id = 1; b.lo = b.up = NULL; b.outside = 0;
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
 * acceleration; constraints in a second solve) a caller workspace of
 * plateau_lm_workspace_size() bytes means no allocation, and the same
 * iterates as an allocating solve. */
static void test_workspace_with_features(void)
{
    static const double lo[2] = {-10.0, 1.0}, up[2] = {10.0, 1.9};
    static const double A[2] = {1.0, 1.0}, b[1] = {3.0};
    double w[LINE_M];
    size_t i, need;
    int pass;
    for (i = 0; i < LINE_M; i++) w[i] = 1.0 + (double)(i % 2);
    for (pass = 0; pass < 2; pass++) {
        plateau_lm_options o = zero_options();
        double x[2] = {0.0, 1.5}, x2[2] = {0.0, 1.5};
        unsigned char *buf;
        o.allocator.alloc_fn = count_alloc;
        o.allocator.free_fn = count_free;
        o.weights = w;
        o.loss = PLATEAU_LM_LOSS_HUBER;
        o.geodesic = 1;
        if (pass == 0) { o.lower = lo; o.upper = up; }
        else { o.constraints = 1; o.a_eq = A; o.b_eq = b; }
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
        free(buf);
    }
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
        for (pass = 0; pass < 5; pass++) {
            plateau_lm_options o = zero_options();
            plateau_lm_jacobian_check chk;
            double x[2] = {0.5, 1.5}, se[2];
            size_t rank;
            plateau_lm_result r;
            o.allocator.alloc_fn = alloc_ok ? live_alloc : fail_alloc;
            o.allocator.free_fn = live_free;
            if (pass == 0) { o.lower = lo; o.upper = up; o.geodesic = 1; }
            if (pass == 1) { o.constraints = 1; o.a_eq = A; o.b_eq = b; }
            if (pass == 2) o.loss = PLATEAU_LM_LOSS_CAUCHY;
            if (pass < 3) r = plateau_lm_solve(LINE_M, 2, x, line_residual, NULL, &o, NULL, 0, NULL, NULL);
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
    RUN(test_robust_losses);
    RUN(test_workspace_with_features);
    RUN(test_allocation_failure_new_paths);
    return harness_report("test_lm_fit");
}
