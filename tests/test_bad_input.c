/* test_bad_input.c - every public entry point of the three headers, fed bad
 * input, returns the exact error code its header names (never an assert, a
 * crash, an endless loop or a print), leaves its outputs freeable, and
 * leaks nothing; and the extreme-but-valid inputs (coordinates at 1e-150 and
 * 1e150) succeed.
 *
 * Every call goes through the counting allocator of countalloc.h, so a leak
 * on an error path fails a check here (and LeakSanitizer / valgrind agree). */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

#include <ctype.h>
#include <float.h>
#include <math.h>

static const double NaN_ = NAN;
static const double Inf_ = HUGE_VAL;

/* An allocator with only one of its two functions: always an argument error. */
static plateau_allocator half_allocator(int keep_alloc)
{
    plateau_allocator a;
    memset(&a, 0, sizeof a);
    if (keep_alloc) a.alloc_fn = countalloc_alloc;
    else a.free_fn = countalloc_free;
    return a;
}

/* The message of a per-call report must be a terminated sentence. */
static int message_ok(const char *msg, size_t cap)
{
    return memchr(msg, 0, cap) != NULL && msg[0] != 0;
}

/* ---------------------------------------------------------------- shapes */
/* A saddle: 12 vertices around [-1, 1]^2 with z = x y / 2. */
static void saddle(double *xyz, double scale)
{
    static const double xy[12][2] = {{-1, -1}, {-1.0 / 3, -1}, {1.0 / 3, -1}, {1, -1},
                                     {1, -1.0 / 3}, {1, 1.0 / 3}, {1, 1}, {1.0 / 3, 1},
                                     {-1.0 / 3, 1}, {-1, 1}, {-1, 1.0 / 3}, {-1, -1.0 / 3}};
    int i;
    for (i = 0; i < 12; i++) {
        xyz[3 * i] = xy[i][0] * scale;
        xyz[3 * i + 1] = xy[i][1] * scale;
        xyz[3 * i + 2] = xy[i][0] * xy[i][1] * 0.5 * scale;
    }
}

/* ======================================================================
 * plateau_lm.h */

/* f_i = x_i - target_i (i < n), and a coupling row when m > n: a linear
 * problem whose minimum is x = target. */
typedef struct lm_problem {
    double target[4];
    long calls;
    long fail_call;      /* this call (1-based) returns...            */
    int fail_how;        /* 1: NaN residual, 2: Inf residual, 3: abort,
                            4: NaN Jacobian, 5: huge residual (F overflows),
                            6: NaN residual when x[0] > 0.5 (a domain edge) */
} lm_problem;

static int lm_func(const double *x, double *f, double *jac, void *user)
{
    lm_problem *p = (lm_problem *)user;
    int i, j;
    p->calls++;
    for (i = 0; i < 2; i++) f[i] = x[i] - p->target[i];
    if (jac)
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) jac[2 * i + j] = i == j ? 1.0 : 0.0;
    if (p->fail_how == 6 && x[0] > 0.5) f[0] = NaN_;
    if (p->calls >= p->fail_call) {
        switch (p->fail_how) {
        case 1: f[1] = NaN_; break;
        case 2: f[0] = -Inf_; break;
        case 3: return 1;
        case 4: if (jac) jac[1] = NaN_; break;
        case 5: f[0] = f[1] = 1e200; break;
        default: break;
        }
    }
    return 0;
}

static plateau_lm_result lm_run(lm_problem *p, double *x, const plateau_lm_options *opt,
                                plateau_lm_report *rep)
{
    p->calls = 0;
    return plateau_lm_solve(2, 2, x, lm_func, p, opt, NULL, 0, rep, NULL);
}

static void lm_problem_init(lm_problem *p, int how, long call)
{
    memset(p, 0, sizeof *p);
    p->target[0] = 1.0;
    p->target[1] = -2.0;
    p->fail_how = how;
    p->fail_call = call ? call : 1000000;
}

static void test_lm_arguments(void)
{
    lm_problem p;
    double x[2] = {0, 0}, work[64];
    plateau_lm_options opt;
    plateau_lm_report rep;
    const size_t huge = (size_t)1 << (sizeof(size_t) * 4);
    lm_problem_init(&p, 0, 0);
    memset(&opt, 0, sizeof opt);

    CHECK_EQ_INT(plateau_lm_solve(2, 2, NULL, lm_func, &p, NULL, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ERROR);
    CHECK_EQ_INT(plateau_lm_solve(2, 2, x, NULL, &p, NULL, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_solve(0, 2, x, lm_func, &p, NULL, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_EMPTY);
    CHECK_EQ_INT(plateau_lm_solve(2, 0, x, lm_func, &p, NULL, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_EMPTY);
    CHECK_EQ_INT(plateau_lm_workspace_size(0, 2, NULL), 0);
    /* m n overflows size_t */
    CHECK_EQ_INT(plateau_lm_solve(huge, huge, x, lm_func, &p, NULL, NULL, 0, &rep, NULL),
                 PLATEAU_LM_ERR_OVERFLOW);
    CHECK_EQ_INT(plateau_lm_workspace_size(huge, huge, NULL), 0);
    CHECK_EQ_INT(plateau_lm_workspace_size((size_t)-1, 1, NULL), 0);
    CHECK_EQ_INT(p.calls, 0);
    /* options */
    opt.tau = -1.0;
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.tau = NaN_;
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.tau = 0;
    opt.eps = -1e-3;
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.eps = 0;
    opt.max_iterations = -5;
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.max_iterations = 0;
    opt.scaling = 99;
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.scaling = 0;
    opt.allocator = half_allocator(1);
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    opt.allocator = half_allocator(0);
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ARGUMENT);
    memset(&opt.allocator, 0, sizeof opt.allocator);
    /* a workspace one byte too small, then exactly large enough */
    {
        size_t need = plateau_lm_workspace_size(2, 2, NULL);
        CHECK(need > 0 && need <= sizeof work);
        CHECK_EQ_INT(plateau_lm_solve(2, 2, x, lm_func, &p, NULL, work, need - 1, &rep, NULL),
                     PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL);
        CHECK_EQ_INT(plateau_lm_solve(2, 2, x, lm_func, &p, NULL, (char *)work + 1, need, &rep, NULL),
                     PLATEAU_LM_OK); /* any alignment */
        CHECK_NEAR(x[0], 1.0, 1e-12);
        CHECK_NEAR(x[1], -2.0, 1e-12);
    }
    CHECK_EQ_INT(p.calls > 0, 1);
    CHECK(strcmp(plateau_lm_result_string((plateau_lm_result)-12345), "") != 0);
    CHECK(plateau_lm_stop_string((plateau_lm_stop)77) != NULL);
}

static void test_lm_nonfinite(void)
{
    lm_problem p;
    double x[2];
    plateau_lm_options opt;
    plateau_lm_report rep;
    memset(&opt, 0, sizeof opt);

    /* NaN and Inf in the start: x untouched, the callback never called */
    lm_problem_init(&p, 0, 0);
    x[0] = NaN_;
    x[1] = 0;
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_X0);
    CHECK(isnan(x[0]) && x[1] == 0);
    CHECK_EQ_INT(p.calls, 0);
    x[0] = 0;
    x[1] = -Inf_;
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_X0);
    /* a NaN, an Inf, an overflowing F at the start */
    lm_problem_init(&p, 1, 1);
    x[0] = x[1] = 0;
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
    CHECK(x[0] == 0 && x[1] == 0);
    lm_problem_init(&p, 2, 1);
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
    lm_problem_init(&p, 5, 1);
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
    opt.numeric_jacobian = 1;
    lm_problem_init(&p, 1, 1);
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
    opt.numeric_jacobian = 0;
    /* NaN at trial points beyond a domain edge: a shorter step, success */
    lm_problem_init(&p, 6, 0);
    x[0] = x[1] = 0;
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_OK);
    CHECK(isfinite(x[0]) && isfinite(x[1]) && x[0] <= 0.5);
    /* NaN later, at every call from the third on: x stays finite */
    lm_problem_init(&p, 1, 3);
    x[0] = x[1] = 0;
    {
        plateau_lm_result rc = lm_run(&p, x, NULL, &rep);
        CHECK(rc == PLATEAU_LM_OK || rc == PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL ||
              rc == PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN);
        CHECK(isfinite(x[0]) && isfinite(x[1]));
    }
    /* a NaN in the analytic Jacobian */
    lm_problem_init(&p, 4, 1);
    x[0] = x[1] = 0;
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN);
    CHECK(x[0] == 0 && x[1] == 0);
}

static int progress_stop_at_2(int k, double F, double g, double mu, int accepted, void *user)
{
    (void)F;
    (void)g;
    (void)mu;
    (void)accepted;
    (void)user;
    return k >= 2;
}

static void test_lm_abort(void)
{
    lm_problem p;
    double x[2] = {0, 0};
    plateau_lm_options opt;
    plateau_lm_report rep;
    countalloc ca;
    /* the residual callback asks to stop at once, then later */
    lm_problem_init(&p, 3, 1);
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_ABORTED);
    CHECK(x[0] == 0 && x[1] == 0);
    CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ABORTED);
    lm_problem_init(&p, 3, 2);
    CHECK_EQ_INT(lm_run(&p, x, NULL, &rep), PLATEAU_LM_ERR_ABORTED);
    CHECK(isfinite(x[0]) && isfinite(x[1]));
    /* the progress callback asks to stop, with the counting allocator */
    lm_problem_init(&p, 0, 0);
    memset(&opt, 0, sizeof opt);
    opt.progress = progress_stop_at_2;
    countalloc_init(&ca, 0);
    opt.allocator = countalloc_allocator(&ca);
    x[0] = 30;
    x[1] = 40;
    opt.scaling = PLATEAU_LM_SCALING_NONE;
    opt.tau = 1e3; /* slow start: several iterations */
    CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_ERR_ABORTED);
    CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ABORTED);
    CHECK(isfinite(x[0]) && isfinite(x[1]));
    CHECK_EQ_INT(ca.live, 0);
}

/* A problem whose values are all of the order of 1e-150 (or 1e150), started
 * at that scale too, is the same problem in other units: same answer. */
static void test_lm_extreme_scales(void)
{
    static const double scales[] = {1e-150, 1e150};
    size_t s;
    for (s = 0; s < 2; s++) {
        lm_problem p;
        double x[2];
        plateau_lm_options opt;
        plateau_lm_report rep;
        lm_problem_init(&p, 0, 0);
        p.target[0] *= scales[s];
        p.target[1] *= scales[s];
        memset(&opt, 0, sizeof opt);
        x[0] = 3 * scales[s];
        x[1] = 5 * scales[s];
        /* regression (plateau_lm.h): at 1e-150 the step test's absolute
         * floor, ||D h|| <= eps_step (||D x|| + eps_step), stopped the first
         * iteration (STOP_STEP, PLATEAU_LM_OK) with x still at the start */
        CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_OK);
        CHECK_MSG(fabs(x[0] - p.target[0]) <= 1e-12 * fabs(p.target[0]) &&
                    fabs(x[1] - p.target[1]) <= 1e-12 * fabs(p.target[1]),
                "lm_solve reaches the minimum of a problem scaled by 1e-150 / 1e150");
        x[0] = 3 * scales[s];
        x[1] = 5 * scales[s];
        opt.numeric_jacobian = 1;
        CHECK_EQ_INT(lm_run(&p, x, &opt, &rep), PLATEAU_LM_OK);
        CHECK_MSG(fabs(x[0] - p.target[0]) <= 1e-6 * fabs(p.target[0]) &&
                    fabs(x[1] - p.target[1]) <= 1e-6 * fabs(p.target[1]),
                "lm_solve (numeric Jacobian) reaches the minimum at scale 1e-150 / 1e150");
        if (fabs(x[0] - p.target[0]) > 1e-6 * fabs(p.target[0]))
            printf("  scale %g: x = (%g, %g), stop %s\n", scales[s], x[0], x[1],
                   plateau_lm_stop_string((plateau_lm_stop)rep.stop));
    }
}

/* ======================================================================
 * plateau_delaunay.h */
static int dt_mesh_zero(const plateau_dt_mesh *m)
{
    return m->num_points == 0 && m->points == NULL && m->num_input_points == 0 &&
           m->duplicate_of == NULL && m->num_triangles == 0 && m->triangles == NULL &&
           m->neighbors == NULL && m->constrained == NULL;
}

/* One triangulation through the counting allocator.  On error: the mesh is
 * all zero, the report names a sentence; always: nothing leaks.  *ntri gets
 * the triangle count, *index the report's index. */
static plateau_dt_result dt(const double *pts, size_t np, const plateau_index *segs, size_t ns,
                            int hull, int split, size_t *ntri, long *index)
{
    countalloc ca;
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    plateau_dt_error rep;
    plateau_dt_result rc;
    countalloc_init(&ca, 0);
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = hull;
    opt.split_crossing_segments = split;
    opt.allocator = countalloc_allocator(&ca);
    in.points = pts;
    in.num_points = np;
    in.segments = segs;
    in.num_segments = ns;
    memset(&mesh, 0x5a, sizeof mesh); /* an output: its old content must not matter */
    rep.index = -99;
    rc = plateau_dt_triangulate(&in, &opt, &mesh, &rep);
    if (ntri) *ntri = rc == PLATEAU_DT_OK ? mesh.num_triangles : 0;
    if (index) *index = rep.index;
    if (rc != PLATEAU_DT_OK) {
        CHECK(dt_mesh_zero(&mesh));
        CHECK(message_ok(rep.message, sizeof rep.message));
    }
    plateau_dt_free(&mesh);
    CHECK(dt_mesh_zero(&mesh));
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
    return rc;
}

static void test_dt_arguments(void)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const plateau_index loop[] = {0, 1, 1, 2, 2, 3, 3, 0};
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    plateau_dt_error rep;
    memset(&in, 0, sizeof in);
    memset(&mesh, 0, sizeof mesh);
    in.points = sq;
    in.num_points = 4;
    CHECK_EQ_INT(plateau_dt_triangulate(NULL, NULL, &mesh, &rep), PLATEAU_DT_ERR_ARGUMENT);
    CHECK(dt_mesh_zero(&mesh));
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, NULL, &rep), PLATEAU_DT_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &mesh, NULL), PLATEAU_DT_OK);
    plateau_dt_free(&mesh);
    CHECK_EQ_INT(dt(NULL, 4, NULL, 0, 0, 0, NULL, NULL), PLATEAU_DT_ERR_ARGUMENT);
    CHECK_EQ_INT(dt(sq, 4, NULL, 4, 0, 0, NULL, NULL), PLATEAU_DT_ERR_ARGUMENT);
    CHECK_EQ_INT(dt(sq, 4, loop, 4, 0, 0, NULL, NULL), PLATEAU_DT_OK);
    /* an allocator with one function */
    memset(&opt, 0, sizeof opt);
    opt.allocator = half_allocator(1);
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, &rep), PLATEAU_DT_ERR_ARGUMENT);
    CHECK(dt_mesh_zero(&mesh));
    opt.allocator = half_allocator(0);
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, &rep), PLATEAU_DT_ERR_ARGUMENT);
    CHECK(dt_mesh_zero(&mesh));
    /* sizes beyond plateau_index */
    in.num_points = (size_t)PLATEAU_INDEX_MAX + 2;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &mesh, &rep), PLATEAU_DT_ERR_OVERFLOW);
    CHECK(dt_mesh_zero(&mesh));
    /* free accepts NULL and an all-zero mesh, twice */
    plateau_dt_free(NULL);
    plateau_dt_free(&mesh);
    plateau_dt_free(&mesh);
    CHECK(strcmp(plateau_dt_result_string((plateau_dt_result)-999), "") != 0);
}

static void test_dt_points_bad(void)
{
    double p[12] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 0.25, 0.75};
    static const double line[] = {0, 0, 1, 1, 2, 2, 3, 3, -7, -7};
    static const double dup3[] = {0, 0, 1, 0, 0, 0};
    static const double dupall[] = {2, 3, 2, 3, 2, 3, 2, 3};
    long index;
    CHECK_EQ_INT(dt(p, 0, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    CHECK_EQ_INT(dt(p, 1, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    CHECK_EQ_INT(dt(p, 2, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    /* two distinct points among three (COLLINEAR until 4d58443) */
    CHECK_EQ_INT(dt(dup3, 3, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    CHECK_EQ_INT(dt(dupall, 4, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    CHECK_EQ_INT(dt(line, 5, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_COLLINEAR);
    CHECK_EQ_INT(dt(line, 3, NULL, 0, 1, 0, NULL, NULL), PLATEAU_DT_ERR_COLLINEAR);
    p[2 * 4 + 1] = NaN_;
    CHECK_EQ_INT(dt(p, 6, NULL, 0, 1, 0, NULL, &index), PLATEAU_DT_ERR_NOT_FINITE);
    CHECK_EQ_INT(index, 4);
    p[2 * 4 + 1] = 0.5;
    p[2 * 5] = Inf_;
    CHECK_EQ_INT(dt(p, 6, NULL, 0, 1, 0, NULL, &index), PLATEAU_DT_ERR_NOT_FINITE);
    CHECK_EQ_INT(index, 5);
    p[2 * 5] = -Inf_;
    CHECK_EQ_INT(dt(p, 6, NULL, 0, 1, 0, NULL, &index), PLATEAU_DT_ERR_NOT_FINITE);
}

static void test_dt_duplicates_mapped(void)
{
    /* a square, its centre, and copies of points 1 and 4 */
    static const double p[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 1, 0, 0.5, 0.5};
    plateau_dt_input in;
    plateau_dt_mesh mesh;
    size_t t;
    int k, uses_dup = 0;
    in.points = p;
    in.num_points = 7;
    in.segments = NULL;
    in.num_segments = 0;
    if (!CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &mesh, NULL), PLATEAU_DT_OK)) return;
    CHECK_EQ_INT(mesh.num_input_points, 7);
    CHECK_EQ_INT(mesh.num_triangles, 4);
    CHECK_EQ_INT(mesh.duplicate_of[5], 1);
    CHECK_EQ_INT(mesh.duplicate_of[6], 4);
    for (k = 0; k < 5; k++) CHECK_EQ_INT(mesh.duplicate_of[k], k);
    for (t = 0; t < mesh.num_triangles; t++)
        for (k = 0; k < 3; k++) uses_dup |= mesh.triangles[3 * t + k] >= 5;
    CHECK(!uses_dup);
    plateau_dt_free(&mesh);
}

static void test_dt_segments_bad(void)
{
    /* a square with an inner point; point 5 duplicates point 2 */
    static const double p[] = {0, 0, 4, 0, 4, 4, 0, 4, 2, 1, 4, 4};
    plateau_index s[10] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 0};
    static const plateau_index cross[] = {0, 2, 1, 3};
    static const plateau_index open_chain[] = {0, 1, 1, 2, 2, 3};
    size_t ntri;
    long index;
    s[2 * 2 + 1] = 6; /* segment 2 = (2, 6): one past the end */
    CHECK_EQ_INT(dt(p, 6, s, 4, 0, 0, NULL, &index), PLATEAU_DT_ERR_SEGMENT_INDEX);
    CHECK_EQ_INT(index, 2);
    s[2 * 2 + 1] = -1;
    CHECK_EQ_INT(dt(p, 6, s, 4, 0, 0, NULL, &index), PLATEAU_DT_ERR_SEGMENT_INDEX);
    CHECK_EQ_INT(index, 2);
    s[2 * 2 + 1] = PLATEAU_INDEX_MAX;
    CHECK_EQ_INT(dt(p, 6, s, 4, 1, 0, NULL, &index), PLATEAU_DT_ERR_SEGMENT_INDEX);
    s[2 * 2 + 1] = 3;
    /* a segment from a point to itself, and to its duplicate */
    s[8] = 4;
    s[9] = 4;
    CHECK_EQ_INT(dt(p, 6, s, 5, 0, 0, NULL, &index), PLATEAU_DT_ERR_DEGENERATE_SEGMENT);
    CHECK_EQ_INT(index, 4);
    s[8] = 2;
    s[9] = 5;
    CHECK_EQ_INT(dt(p, 6, s, 5, 1, 0, NULL, &index), PLATEAU_DT_ERR_DEGENERATE_SEGMENT);
    CHECK_EQ_INT(index, 4);
    /* crossing diagonals: an error, or split at the crossing on request */
    CHECK_EQ_INT(dt(p, 5, cross, 2, 1, 0, NULL, &index), PLATEAU_DT_ERR_CROSSING_SEGMENTS);
    CHECK(index == 0 || index == 1);
    /* split: the crossing (2, 2) is a sixth vertex, 4 of 6 on the hull */
    CHECK_EQ_INT(dt(p, 5, cross, 2, 1, 1, &ntri, NULL), PLATEAU_DT_OK);
    CHECK_EQ_INT(ntri, 2 * 6 - 4 - 2);
    /* an open chain bounds no domain; with the hull kept it is fine */
    CHECK_EQ_INT(dt(p, 5, open_chain, 3, 0, 0, NULL, NULL), PLATEAU_DT_ERR_OPEN_BOUNDARY);
    CHECK_EQ_INT(dt(p, 5, open_chain, 3, 1, 0, &ntri, NULL), PLATEAU_DT_OK);
    CHECK_EQ_INT(ntri, 4);
    /* the closed square with the inner point: 4 triangles */
    CHECK_EQ_INT(dt(p, 5, s, 4, 0, 0, &ntri, NULL), PLATEAU_DT_OK);
    CHECK_EQ_INT(ntri, 4);
}

/* Refinement options: nonsense values are an argument error; the clamp and
 * the budget are honoured. */
static plateau_dt_result dt_refine(double min_angle, double max_area, size_t budget,
                                   plateau_dt_mesh *mesh)
{
    static const double p[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.3, 0.4};
    static const plateau_index loop[] = {0, 1, 1, 2, 2, 3, 3, 0};
    plateau_dt_input in;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    opt.min_angle = min_angle;
    opt.max_area = max_area;
    opt.max_added_points = budget;
    in.points = p;
    in.num_points = 5;
    in.segments = loop;
    in.num_segments = 4;
    return plateau_dt_triangulate(&in, &opt, mesh, NULL);
}

static void test_dt_refine_options(void)
{
    plateau_dt_mesh mesh;
    static const double bad[] = {-5.0, -1e-300, NAN};
    size_t i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        /* (silently "no refinement" until 4d58443) */
        CHECK_EQ_INT(dt_refine(bad[i], 0, 0, &mesh), PLATEAU_DT_ERR_ARGUMENT);
        plateau_dt_free(&mesh);
        CHECK_EQ_INT(dt_refine(0, bad[i], 0, &mesh), PLATEAU_DT_ERR_ARGUMENT);
        plateau_dt_free(&mesh);
    }
    /* a min_angle beyond 34 degrees is clamped and the refinement ends */
    CHECK_EQ_INT(dt_refine(90.0, 0, 0, &mesh), PLATEAU_DT_OK);
    CHECK_EQ_INT(mesh.refine_stop, PLATEAU_DT_REFINE_DONE);
    plateau_dt_free(&mesh);
    /* an area bound that cannot be met stops on the budget, named */
    CHECK_EQ_INT(dt_refine(0, 1e-300, 500, &mesh), PLATEAU_DT_OK);
    CHECK_EQ_INT(mesh.refine_stop, PLATEAU_DT_REFINE_BUDGET);
    CHECK(mesh.num_unrefined > 0);
    CHECK(mesh.num_points <= 5 + 500);
    plateau_dt_free(&mesh);
}

/* A zero-area loop: out along a line and back (the closing segment runs
 * over the middle point).  It encloses nothing: the named error. */
static void test_dt_zero_area_loop(void)
{
    static const double p[] = {0, 0, 1, 0, 2, 0, 1, 1};
    static const plateau_index loop[] = {0, 1, 1, 2, 2, 0};
    size_t ntri = 99;
    CHECK_EQ_INT(dt(p, 4, loop, 3, 0, 0, &ntri, NULL), PLATEAU_DT_ERR_OPEN_BOUNDARY);
    /* with the hull kept it is an ordinary triangulation */
    CHECK_EQ_INT(dt(p, 4, loop, 3, 1, 0, &ntri, NULL), PLATEAU_DT_OK);
    CHECK_EQ_INT(ntri, 2);
}

/* Coordinates at 1e-150 and at 1e150 work, alone and together in one
 * input (exact predicates whose plain products would underflow or
 * overflow). */
static void test_dt_extreme_scales(void)
{
    static const double scales[] = {1e-150, 1e150, 1e-300, 1e300};
    double p[2 * 9];
    static const double base[] = {0, 0, 3, 0, 3, 3, 0, 3, 1, 1, 2, 1, 1.5, 2.5, 0.5, 2, 2.5, 0.5};
    static const plateau_index loop[] = {0, 1, 1, 2, 2, 3, 3, 0};
    size_t s, i, ntri;
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        plateau_dt_result rc;
        int hull;
        for (i = 0; i < 18; i++) p[i] = base[i] * scales[s];
        for (hull = 0; hull < 2; hull++) {
            rc = dt(p, 9, hull ? NULL : loop, hull ? 0 : 4, hull, 0, &ntri, NULL);
            if (s < 2) {
                if (!CHECK_EQ_INT(rc, PLATEAU_DT_OK)) fprintf(stderr, "  scale %g\n", scales[s]);
            } else {
                /* beyond the documented range an error is acceptable */
                CHECK(strcmp(plateau_dt_result_string(rc), "unknown result") != 0);
                printf("Delaunay at scale %g: %s\n", scales[s], plateau_dt_result_string(rc));
            }
            if (rc == PLATEAU_DT_OK) CHECK_EQ_INT(ntri, 2 * 9 - 4 - 2);
        }
    }
    /* both extremes in one input: a huge square, and a tiny cluster at its
     * centre (the exact predicates must not overflow) */
    {
        double q[2 * 8] = {-1e150, -1e150, 1e150, -1e150, 1e150, 1e150, -1e150, 1e150,
                           0, 0, 1e-150, 0, 0, 1e-150, 1e-150, 1e-150};
        plateau_dt_result rc = dt(q, 8, loop, 4, 0, 0, &ntri, NULL);
        /* until 4d58443, point 7 (1e-150, 1e-150) came back as a duplicate
         * of point 4 (0, 0): 8 triangles instead of 10 */
        CHECK_EQ_INT(rc, PLATEAU_DT_OK);
        CHECK_EQ_INT(ntri, 2 * 8 - 4 - 2);
    }
}

/* ======================================================================
 * plateau.h: boundary check, domain, seeding */
static void test_boundary_check_bad(void)
{
    double xyz[3 * 12];
    plateau_error err;
    saddle(xyz, 1.0);

    CHECK_EQ_INT(plateau_boundary_check(NULL, 12, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    CHECK(message_ok(err.message, sizeof err.message));
    CHECK_EQ_INT(plateau_boundary_check(NULL, 0, &err), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 0, &err), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 2, &err), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, NULL), PLATEAU_OK); /* err may be NULL */

    xyz[3 * 4 + 1] = NaN_;
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 4);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, NULL), PLATEAU_ERR_NOT_FINITE);
    saddle(xyz, 1.0);
    xyz[3 * 7 + 2] = Inf_;
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 7);
    xyz[3 * 7 + 2] = -Inf_;
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_ERR_NOT_FINITE);

    /* repeated consecutive vertices: 5 == 6, and the closing pair 11 == 0 */
    saddle(xyz, 1.0);
    memcpy(xyz + 3 * 6, xyz + 3 * 5, 3 * sizeof(double));
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_ERR_REPEATED_VERTEX);
    CHECK_EQ_INT(err.index, 5);
    saddle(xyz, 1.0);
    memcpy(xyz + 3 * 11, xyz, 3 * sizeof(double));
    CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_ERR_REPEATED_VERTEX);
    CHECK_EQ_INT(err.index, 11);
    /* a repeat that is not consecutive touches itself: no embedded disk
     * spans it (it was accepted before, and meshed with folds) */
    {
        static const double touch[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 1, 0.5, 0, 2, 0, 1, 1, 0.5};
        CHECK_EQ_INT(plateau_boundary_check(touch, 6, &err), PLATEAU_ERR_DUPLICATE_VERTEX);
        CHECK_EQ_INT(err.index, 3);
    }
}

#define TWO_PI_ 6.283185307179586476925286766559

/* Writes vertex i of a polygon. */
static void put3(double *xyz, size_t i, double x, double y, double z)
{
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = z;
}

/* A 40-vertex planar figure eight (the lemniscate of Gerono, x = sin t,
 * y = sin t cos t, sampled between the crossing): edges 19 and 39 cross at
 * the origin.  lift > 0 raises one lobe (z = lift cos t): then nothing
 * touches. */
static void figure_eight(double *xyz, double lift)
{
    size_t i;
    for (i = 0; i < 40; i++) {
        double t = TWO_PI_ * ((double)i + 0.5) / 40.0;
        put3(xyz, i, sin(t), sin(t) * cos(t), lift * cos(t));
    }
}

/* Three turns of a helix of radius 1 and height 0.6 (16 vertices a turn,
 * 49 vertices), closed by straight edges back to the start.  beside = 0:
 * the closing edge runs down the line x = 1, y = 0 through the helix's
 * vertices 16 and 32 (to rounding: sin(2 pi) is 2.4e-16, not 0);
 * beside > 0: two more vertices take the return along x = 1 + beside. */
static size_t helix_closed(double *xyz, double beside)
{
    size_t i, m = 49;
    for (i = 0; i < 49; i++) {
        double t = TWO_PI_ * (double)i / 16.0;
        put3(xyz, i, cos(t), sin(t), 0.2 * (double)i / 16.0);
    }
    if (beside > 0.0) {
        put3(xyz, m++, 1.0 + beside, 0.0, 0.6);
        put3(xyz, m++, 1.0 + beside, 0.0, 0.0);
    }
    return m;
}

/* Does message contain the decimal number v as a whole word? */
static int message_has(const char *msg, long v)
{
    char num[32];
    const char *p = msg;
    size_t len;
    sprintf(num, "%ld", v);
    len = strlen(num);
    while ((p = strstr(p, num)) != NULL) {
        int before = p == msg || !isdigit((unsigned char)p[-1]);
        int after = !isdigit((unsigned char)p[len]);
        if (before && after) return 1;
        p += len;
    }
    return 0;
}

static plateau_result solve(const double *xyz, size_t m, plateau_options *opt, long *index,
                            int *finite);

/* Polygons that bound no embedded surface are refused with a named code
 * and the indices; moved apart so that nothing touches, they are valid. */
static void test_boundary_not_embedded(void)
{
    static const double repeat[] = {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0};
    static const double on_edge[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 0, 0, 0, 2, 0};
    static const double on_edge_off[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 0.1, 0, 0, 2, 0};
    static const double bowtie[] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0};
    static const double bowtie_off[] = {0, 0, 0, 1, 1, 0.2, 1, 0, 0, 0, 1, -0.2};
    /* vertex 3 folds back onto edge 1 (a spike) */
    static const double spike[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 2, 1, 0, 0, 2, 0};
    double xyz[3 * 51], uv[2 * 51];
    plateau_error err;
    plateau_domain_kind kind;
    plateau_options opt;
    size_t m;

    CHECK_EQ_INT(plateau_boundary_check(repeat, 4, &err), PLATEAU_ERR_DUPLICATE_VERTEX);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_DUPLICATE_VERTEX);
    CHECK_EQ_INT(err.index, 0);
    CHECK_EQ_INT(err.index2, 2);
    CHECK(message_has(err.message, 0) && message_has(err.message, 2));

    CHECK_EQ_INT(plateau_boundary_check(on_edge, 5, &err), PLATEAU_ERR_VERTEX_ON_EDGE);
    CHECK_EQ_INT(err.index, 3);
    CHECK_EQ_INT(err.index2, 0); /* the edge from vertex 0 to vertex 1 */
    CHECK(message_has(err.message, 3) && message_has(err.message, 0) && message_has(err.message, 1));
    CHECK_EQ_INT(plateau_boundary_check(on_edge_off, 5, &err), PLATEAU_OK);

    CHECK_EQ_INT(plateau_boundary_check(spike, 5, &err), PLATEAU_ERR_VERTEX_ON_EDGE);
    CHECK_EQ_INT(err.index, 3);

    CHECK_EQ_INT(plateau_boundary_check(bowtie, 4, &err), PLATEAU_ERR_EDGES_INTERSECT);
    CHECK_EQ_INT(err.index, 0);
    CHECK_EQ_INT(err.index2, 2); /* edges 0-1 and 2-3 */
    CHECK(message_has(err.message, 0) && message_has(err.message, 2));
    CHECK_EQ_INT(plateau_boundary_check(bowtie_off, 4, &err), PLATEAU_OK);

    figure_eight(xyz, 0.0);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 40, &err), PLATEAU_ERR_EDGES_INTERSECT);
    CHECK_EQ_INT(err.index, 19);
    CHECK_EQ_INT(err.index2, 39);
    CHECK(message_has(err.message, 19) && message_has(err.message, 39));
    figure_eight(xyz, 0.3);
    CHECK_EQ_INT(plateau_boundary_check(xyz, 40, &err), PLATEAU_OK);
    CHECK_EQ_INT(err.index2, -1);

    m = helix_closed(xyz, 0.0);
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_ERR_VERTEX_ON_EDGE);
    CHECK_EQ_INT(err.index, 16);
    CHECK_EQ_INT(err.index2, 48);
    CHECK(message_has(err.message, 16) && message_has(err.message, 48));
    m = helix_closed(xyz, 0.3);
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_OK);

    /* the domain and the solve refuse the same, leaking nothing; the helix
     * whose return passes beside it solves */
    CHECK_EQ_INT(plateau_boundary_domain(bowtie, 4, 0, NULL, uv, &kind, &err),
                 PLATEAU_ERR_EDGES_INTERSECT);
    CHECK_EQ_INT(solve(repeat, 4, NULL, NULL, NULL), PLATEAU_ERR_DUPLICATE_VERTEX);
    CHECK_EQ_INT(solve(on_edge, 5, NULL, NULL, NULL), PLATEAU_ERR_VERTEX_ON_EDGE);
    CHECK_EQ_INT(solve(bowtie, 4, NULL, NULL, NULL), PLATEAU_ERR_EDGES_INTERSECT);
    m = helix_closed(xyz, 0.0);
    CHECK_EQ_INT(solve(xyz, m, NULL, NULL, NULL), PLATEAU_ERR_VERTEX_ON_EDGE);
    m = helix_closed(xyz, 0.3);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 20;
    CHECK_EQ_INT(solve(xyz, m, &opt, NULL, NULL), PLATEAU_OK);
}

/* The crossing test finds one near miss among many edges (it sorts a grid
 * of edge pieces instead of comparing all pairs): a 20 000-vertex circle is
 * valid; with one vertex moved onto the opposite edge it is not. */
static void test_boundary_large_circle(void)
{
    size_t m = 20000, i;
    double *xyz = (double *)malloc(3 * m * sizeof(double));
    plateau_error err;
    if (!CHECK(xyz != NULL)) return;
    for (i = 0; i < m; i++) {
        double t = TWO_PI_ * (double)i / (double)m;
        put3(xyz, i, cos(t), sin(t), 0.0);
    }
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_OK);
    /* vertex 7 onto the middle of edge 10000 (from vertex 10000 to 10001) */
    for (i = 0; i < 3; i++) xyz[3 * 7 + i] = 0.5 * (xyz[3 * 10000 + i] + xyz[3 * 10001 + i]);
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_ERR_VERTEX_ON_EDGE);
    CHECK_EQ_INT(err.index, 7);
    CHECK(message_has(err.message, 10000));
    /* vertex 5000 (at the top) pulled below the bottom: its two edges
     * cross the circle's far side */
    for (i = 0; i < m; i++) {
        double t = TWO_PI_ * (double)i / (double)m;
        put3(xyz, i, cos(t), sin(t), 0.0);
    }
    put3(xyz, 5000, 0.0, -1.5, 0.0); /* edges 4999 and 5000 cross the circle's far side */
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_ERR_EDGES_INTERSECT);
    free(xyz);
}

static void test_boundary_check_collinear(void)
{
    static const double line[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 5, 5, 5};
    /* zero area: out along a line and back */
    static const double back[] = {0, 0, 0, 1, 2, 3, 2, 4, 6, 1, 2, 3};
    static const double three[] = {0, 0, 0, 1e-3, 0, 0, 2e-3, 0, 0};
    plateau_error err;
    CHECK_EQ_INT(plateau_boundary_check(line, 5, &err), PLATEAU_ERR_COLLINEAR);
    CHECK(message_ok(err.message, sizeof err.message));
    CHECK_EQ_INT(plateau_boundary_check(back, 4, &err), PLATEAU_ERR_COLLINEAR);
    CHECK_EQ_INT(plateau_boundary_check(three, 3, &err), PLATEAU_ERR_COLLINEAR);
}

/* 1e-150 and 1e150 must work; at 1e-300 and 1e300 squares leave the double
 * range, and an error is acceptable there but an OK with NaN output is not. */
static void test_boundary_extreme_scales(void)
{
    double xyz[3 * 12], uv[2 * 12];
    double sxyz[3 * 8], suv[2 * 8];
    static const double scales[] = {1e-150, 1e150, 1e-300, 1e300};
    plateau_error err;
    plateau_domain_kind kind;
    plateau_result rc;
    size_t s, i, count;
    int force;
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        int must = s < 2;
        saddle(xyz, scales[s]);
        CHECK_EQ_INT(plateau_boundary_check(xyz, 12, &err), PLATEAU_OK);
        for (force = 0; force < 2; force++) {
            int finite = 1;
            rc = plateau_boundary_domain(xyz, 12, force, NULL, uv, &kind, &err);
            if (must) CHECK_EQ_INT(rc, PLATEAU_OK);
            if (rc != PLATEAU_OK) continue;
            if (force) CHECK_EQ_INT(kind, PLATEAU_DOMAIN_CIRCLE);
            for (i = 0; i < 24; i++) finite &= isfinite(uv[i]) ? 1 : 0;
            /* at 1e+-300 it was OK with NaN uv (squares under- and
             * overflowed); fixed: the domain works in a power-of-two unit */
            if (!CHECK_MSG(finite, "boundary_domain: OK but the domain has NaN or Inf"))
                printf("  scale %g, force_circle %d\n", scales[s], force);
            if (!finite) continue;
            /* uv is in the units of xyz: its extent over the scale stays near 2 */
            {
                double lo = uv[0], hi = uv[0];
                for (i = 0; i < 24; i += 2) {
                    if (uv[i] < lo) lo = uv[i];
                    if (uv[i] > hi) hi = uv[i];
                }
                CHECK_NEAR((hi - lo) / scales[s], 2.0, 1.5);
            }
            count = 99;
            rc = plateau_seed_points(xyz, uv, 12, 8, 1, NULL, sxyz, suv, &count, &err);
            if (must) CHECK_EQ_INT(rc, PLATEAU_OK);
            if (rc != PLATEAU_OK) continue;
            if (must) CHECK_EQ_INT(count, 8);
            for (i = 0; i < 3 * count; i++) finite &= isfinite(sxyz[i]) ? 1 : 0;
            for (i = 0; i < 2 * count; i++) finite &= isfinite(suv[i]) ? 1 : 0;
            CHECK_MSG(finite, "seed_points: OK but a point has NaN or Inf");
        }
    }
}

static void test_domain_bad(void)
{
    double xyz[3 * 12], uv[2 * 12];
    plateau_error err;
    plateau_domain_kind kind;
    plateau_allocator half;
    saddle(xyz, 1.0);
    CHECK_EQ_INT(plateau_boundary_domain(NULL, 12, 0, NULL, uv, &kind, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 0, NULL, NULL, &kind, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 2, 0, NULL, uv, &kind, &err),
                 PLATEAU_ERR_TOO_FEW_VERTICES);
    half = half_allocator(1);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 0, &half, uv, &kind, &err),
                 PLATEAU_ERR_ARGUMENT);
    half = half_allocator(0);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 0, &half, uv, &kind, &err),
                 PLATEAU_ERR_ARGUMENT);
    xyz[5] = NaN_;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 0, NULL, uv, &kind, &err),
                 PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 1);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 1, NULL, uv, &kind, &err),
                 PLATEAU_ERR_NOT_FINITE);
}

static void test_seed_bad(void)
{
    double xyz[3 * 12], uv[2 * 12], sxyz[3 * 8], suv[2 * 8];
    plateau_error err;
    plateau_domain_kind kind;
    plateau_allocator half;
    countalloc ca;
    plateau_allocator a;
    size_t count;
    saddle(xyz, 1.0);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 12, 0, NULL, uv, &kind, &err), PLATEAU_OK);
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    CHECK_EQ_INT(plateau_seed_points(NULL, uv, 12, 8, 1, &a, sxyz, suv, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, NULL, 12, 8, 1, &a, sxyz, suv, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &a, NULL, suv, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &a, sxyz, NULL, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &a, sxyz, suv, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 2, 8, 1, &a, sxyz, suv, &count, &err),
                 PLATEAU_ERR_TOO_FEW_VERTICES);
    half = half_allocator(1);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &half, sxyz, suv, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    half = half_allocator(0);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &half, sxyz, suv, &count, &err),
                 PLATEAU_ERR_ARGUMENT);
    /* n = 0 is valid and gives no point */
    count = 7;
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 0, 1, &a, sxyz, suv, &count, &err),
                 PLATEAU_OK);
    CHECK_EQ_INT(count, 0);
    /* a NaN domain coordinate */
    uv[3] = NaN_;
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 12, 8, 1, &a, sxyz, suv, &count, &err),
                 PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
}

/* ======================================================================
 * plateau.h: the boundary parser and the mesh writer */
static plateau_result parse(const char *text, countalloc *ca, double **xyz, size_t *m,
                            plateau_error *err)
{
    plateau_allocator a = countalloc_allocator(ca);
    *xyz = (double *)ca; /* must be overwritten */
    *m = 777;
    return plateau_parse_boundary(text, strlen(text), &a, xyz, m, err);
}

static void parse_release(countalloc *ca, double *xyz)
{
    countalloc_free(xyz, ca);
}

static void test_parse_bad(void)
{
    /* Each case: its text, the code, and the line err->index names (1-based
     * line numbers as an editor shows them; -1 when no line is to blame). */
    static const struct {
        const char *text;
        plateau_result code;
        long line;
    } cases[] = {
        {"1 2\n", PLATEAU_ERR_PARSE, 1},
        {"0 0 0\n1 0 0\n1 x 0\n", PLATEAU_ERR_PARSE, 3},
        {"0 0 0\n1 0 0 4\n0 1 0\n", PLATEAU_ERR_PARSE, 2},
        {"# c\n\n0 0 0\n1,,0\n0 1 0\n", PLATEAU_ERR_PARSE, 4}, /* an empty CSV field */
        {"0 0 0\n1,5;0;0\n0 1 0\n", PLATEAU_ERR_PARSE, 2},    /* a decimal comma */
        {"0 0 0\n1 0 0\n0 1 0z\n", PLATEAU_ERR_PARSE, 3},
        {"0 0 0\n1 0 0\nnan 1 0\n", PLATEAU_ERR_NOT_FINITE, 3},
        {"0 0 0\n1 0 inf\n0 1 0\n", PLATEAU_ERR_NOT_FINITE, 2},
        {"0 0 0\n1 0 1e999\n0 1 0\n", PLATEAU_ERR_NOT_FINITE, 2},
        {"0 0 0\n1 0 -inf\n", PLATEAU_ERR_NOT_FINITE, 2},
        {"0 0 0\n\n\n1 0\n", PLATEAU_ERR_PARSE, 4},
        {"0 0 0\r\n1 0 0 # ok\r\n1 1\r\n", PLATEAU_ERR_PARSE, 3},
        {"1 2 3e\n", PLATEAU_ERR_PARSE, 1},
        {"--1 2 3\n", PLATEAU_ERR_PARSE, 1},
    };
    size_t i;
    countalloc ca;
    double *xyz;
    size_t m;
    plateau_error err;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        plateau_result rc;
        countalloc_init(&ca, 0);
        rc = parse(cases[i].text, &ca, &xyz, &m, &err);
        if (!CHECK_EQ_INT(rc, cases[i].code)) fprintf(stderr, "  text: %s", cases[i].text);
        CHECK_EQ_INT(err.index, cases[i].line);
        CHECK(message_ok(err.message, sizeof err.message));
        CHECK(xyz == NULL);
        CHECK_EQ_INT(m, 0);
        if (rc == PLATEAU_OK) parse_release(&ca, xyz);
        CHECK_EQ_INT(ca.live, 0);
    }
}

static void test_parse_edges(void)
{
    countalloc ca;
    double *xyz;
    size_t m;
    plateau_error err;
    plateau_allocator half;
    const char *text = "0 0 0\n1 0 0\n0 1 0\n";
    /* arguments */
    half = half_allocator(1);
    xyz = NULL;
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), &half, &xyz, &m, &err),
                 PLATEAU_ERR_ARGUMENT);
    half = half_allocator(0);
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), &half, &xyz, &m, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_parse_boundary(NULL, 5, NULL, &xyz, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), NULL, NULL, &m, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), NULL, &xyz, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    /* the length is honoured: the text stops in the middle of line 3 */
    countalloc_init(&ca, 0);
    {
        plateau_allocator a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_parse_boundary("0 0 0\n1 0 0\n0 1 0 9 9 9", 17, &a, &xyz, &m,
                                            &err),
                     PLATEAU_OK);
        CHECK_EQ_INT(m, 3);
        if (m == 3) CHECK(xyz[6] == 0 && xyz[7] == 1 && xyz[8] == 0);
        parse_release(&ca, xyz);
    }
    CHECK_EQ_INT(ca.live, 0);
    /* comments, blank lines, CRLF, tabs, no final newline */
    countalloc_init(&ca, 0);
    CHECK_EQ_INT(parse("# a comment\r\n\r\n 0\t0 0 # tail\r\n1 0 0\n\n0 1 1e-150", &ca, &xyz,
                       &m, &err),
                 PLATEAU_OK);
    CHECK_EQ_INT(m, 3);
    if (m == 3) CHECK(xyz[8] == 1e-150);
    parse_release(&ca, xyz);
    CHECK_EQ_INT(ca.live, 0);
    /* a NUL byte inside the given length is a parse error */
    countalloc_init(&ca, 0);
    {
        plateau_allocator a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_parse_boundary("0 0 0\n1 0\0 0\n0 1 0\n", 18, &a, &xyz, &m, &err),
                     PLATEAU_ERR_PARSE);
        CHECK_EQ_INT(err.index, 2);
        CHECK(xyz == NULL);
    }
    CHECK_EQ_INT(ca.live, 0);
    /* no vertex at all is not a parse error: the boundary check judges it */
    countalloc_init(&ca, 0);
    CHECK_EQ_INT(parse("# nothing\n\n", &ca, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 0);
    parse_release(&ca, xyz);
    CHECK_EQ_INT(ca.live, 0);
}

static void test_write_mesh_bad(void)
{
    static const double pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const plateau_index tri[] = {0, 1, 2};
    static const plateau_index bad_tri[] = {0, 1, 3};
    static const plateau_index neg_tri[] = {0, -1, 2};
    plateau_error err;
    CHECK_EQ_INT(plateau_write_mesh(NULL, pos, 3, tri, 1, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.obj", NULL, 3, tri, 1, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.obj", pos, 3, NULL, 1, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.xyz", pos, 3, tri, 1, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.obj", pos, 3, bad_tri, 1, &err),
                 PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.off", pos, 3, neg_tri, 1, &err),
                 PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(plateau_write_mesh("build/no/such/dir/x.obj", pos, 3, tri, 1, &err),
                 PLATEAU_ERR_IO);
    CHECK(message_ok(err.message, sizeof err.message));
    CHECK_EQ_INT(plateau_write_mesh("build/bad_input.ply", pos, 3, tri, 1, &err), PLATEAU_OK);
    remove("build/bad_input.ply");
    {
        double nanpos[9];
        static const double zero_view[3] = {0, 0, 0};
        memcpy(nanpos, pos, sizeof nanpos);
        nanpos[4] = NaN_;
        CHECK_EQ_INT(plateau_write_mesh("build/bad_input.obj", nanpos, 3, tri, 1, &err),
                     PLATEAU_ERR_NOT_FINITE);
        CHECK_EQ_INT(err.index, 1);
        CHECK_EQ_INT(plateau_write_svg("build/bad_input.svg", nanpos, 3, tri, 1, NULL, NULL, &err),
                     PLATEAU_ERR_NOT_FINITE);
        CHECK_EQ_INT(plateau_write_svg("build/bad_input.svg", pos, 3, tri, 1, zero_view, NULL, &err),
                     PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_write_svg("build/bad_input.svg", pos, 3, bad_tri, 1, NULL, NULL, &err),
                     PLATEAU_ERR_INDEX_RANGE);
        CHECK_EQ_INT(plateau_write_svg(NULL, pos, 3, tri, 1, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
        {
            plateau_allocator half = half_allocator(1);
            CHECK_EQ_INT(plateau_write_svg("build/bad_input.svg", pos, 3, tri, 1, NULL, &half, &err),
                         PLATEAU_ERR_ARGUMENT);
            half = half_allocator(0);
            CHECK_EQ_INT(plateau_write_svg("build/bad_input.svg", pos, 3, tri, 1, NULL, &half, &err),
                         PLATEAU_ERR_ARGUMENT);
            CHECK_EQ_INT(plateau_read_boundary_file("build/bad_input.svg", &half, NULL, NULL, &err),
                         PLATEAU_ERR_ARGUMENT);
        }
        CHECK_EQ_INT(plateau_write_svg("build/no/such/dir/x.svg", pos, 3, tri, 1, NULL, NULL, &err),
                     PLATEAU_ERR_IO);
    }
}

static void test_read_file_bad(void)
{
    countalloc ca;
    plateau_allocator a;
    double *xyz = (double *)&ca;
    size_t m = 5;
    plateau_error err;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    CHECK_EQ_INT(plateau_read_boundary_file("build/no/such/file.txt", &a, &xyz, &m, &err),
                 PLATEAU_ERR_IO);
    CHECK(xyz == NULL);
    CHECK_EQ_INT(m, 0);
    CHECK(message_ok(err.message, sizeof err.message));
    CHECK_EQ_INT(plateau_read_boundary_file(NULL, &a, &xyz, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(ca.live, 0);
}

/* ======================================================================
 * plateau.h: the mesh kernel */
static int mesh_is_zero(const plateau_mesh *mesh)
{
    return mesh->num_vertices == 0 && mesh->positions == NULL && mesh->fixed == NULL &&
           mesh->num_triangles == 0 && mesh->triangles == NULL && mesh->neighbors == NULL &&
           mesh->num_edges == 0 && mesh->edges == NULL && mesh->edge_triangles == NULL &&
           mesh->triangle_edges == NULL && mesh->vertex_edge_start == NULL &&
           mesh->vertex_edges == NULL && mesh->vertex_triangle_start == NULL &&
           mesh->vertex_triangles == NULL;
}

static plateau_result create(const double *pos, size_t nv, const plateau_index *tri, size_t nt,
                             long *index)
{
    countalloc ca;
    plateau_allocator a;
    plateau_mesh mesh;
    plateau_error err;
    plateau_result rc;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    memset(&mesh, 0x5a, sizeof mesh); /* an output: its old content must not matter */
    err.index = -99;
    rc = plateau_mesh_create(pos, nv, NULL, tri, nt, &a, &mesh, &err);
    *index = err.index;
    if (rc != PLATEAU_OK) {
        CHECK(mesh_is_zero(&mesh));
        CHECK_EQ_INT(err.code, rc);
        CHECK(message_ok(err.message, sizeof err.message));
    }
    plateau_mesh_free(&mesh);
    CHECK(mesh_is_zero(&mesh));
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
    return rc;
}

static void test_mesh_create_bad(void)
{
    /* a square of four triangles around vertex 4 */
    static const double pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0.2};
    static const plateau_index fan[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    static const plateau_index range[] = {0, 1, 4, 1, 2, 5};
    static const plateau_index neg[] = {0, 1, 4, 1, -1, 4};
    static const plateau_index degenerate[] = {0, 1, 4, 2, 2, 4};
    static const plateau_index three_faces[] = {0, 1, 4, 1, 0, 2, 0, 1, 3};
    static const plateau_index flipped[] = {0, 1, 4, 1, 2, 4, 2, 4, 3, 3, 0, 4};
    double nanpos[15];
    plateau_mesh mesh;
    plateau_error err;
    plateau_allocator half;
    long index;

    CHECK_EQ_INT(create(pos, 5, fan, 4, &index), PLATEAU_OK);
    CHECK_EQ_INT(create(NULL, 5, fan, 4, &index), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(create(pos, 5, NULL, 4, &index), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(create(pos, 5, range, 2, &index), PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(index, 1);
    CHECK_EQ_INT(create(pos, 5, neg, 2, &index), PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(index, 1);
    CHECK_EQ_INT(create(pos, 5, degenerate, 2, &index), PLATEAU_ERR_DEGENERATE_TRIANGLE);
    CHECK_EQ_INT(index, 1);
    CHECK_EQ_INT(create(pos, 5, three_faces, 3, &index), PLATEAU_ERR_NON_MANIFOLD);
    CHECK_EQ_INT(index, 2);
    CHECK_EQ_INT(create(pos, 5, flipped, 4, &index), PLATEAU_ERR_ORIENTATION);
    memcpy(nanpos, pos, sizeof nanpos);
    nanpos[3 * 2 + 1] = NaN_;
    CHECK_EQ_INT(create(nanpos, 5, fan, 4, &index), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(index, 2);
    nanpos[3 * 2 + 1] = -Inf_;
    CHECK_EQ_INT(create(nanpos, 5, fan, 4, &index), PLATEAU_ERR_NOT_FINITE);
    /* a NULL mesh, and an allocator with one function */
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, fan, 4, NULL, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    half = half_allocator(1);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, fan, 4, &half, &mesh, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK(mesh_is_zero(&mesh));
    half = half_allocator(0);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, fan, 4, &half, &mesh, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK(mesh_is_zero(&mesh));
    /* sizes that overflow */
    CHECK_EQ_INT(plateau_mesh_create(pos, (size_t)-1 / 2, NULL, fan, 4, NULL, &mesh, &err),
                 PLATEAU_ERR_OVERFLOW);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, fan, (size_t)-1 / 2, NULL, &mesh, &err),
                 PLATEAU_ERR_OVERFLOW);
    /* free accepts an all-zero mesh, twice */
    memset(&mesh, 0, sizeof mesh);
    plateau_mesh_free(&mesh);
    plateau_mesh_free(&mesh);
    plateau_mesh_free(NULL);
    CHECK(mesh_is_zero(&mesh));
}

/* ======================================================================
 * plateau.h: plateau_solve */
static int solve_mesh_zero(const plateau_mesh *mesh)
{
    return mesh->num_vertices == 0 && mesh->positions == NULL && mesh->fixed == NULL &&
           mesh->num_triangles == 0 && mesh->triangles == NULL && mesh->neighbors == NULL;
}

/* plateau_solve through the counting allocator: returns the code, checks the
 * error report, that the mesh is freeable and that nothing leaks. */
static plateau_result solve(const double *xyz, size_t m, plateau_options *opt, long *index,
                            int *finite)
{
    countalloc ca;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    plateau_result rc;
    plateau_options local;
    size_t i;
    if (!opt) {
        memset(&local, 0, sizeof local);
        opt = &local;
    }
    countalloc_init(&ca, 0);
    opt->allocator = countalloc_allocator(&ca);
    if (opt->interior_points == 0) opt->interior_points = 6;
    memset(&mesh, 0x5a, sizeof mesh); /* an output: its old content must not matter */
    err.index = -99;
    rc = plateau_solve(xyz, m, opt, &mesh, &rep, &err);
    if (index) *index = err.index;
    if (finite) {
        *finite = 1;
        if (rc == PLATEAU_OK)
            for (i = 0; i < 3 * mesh.num_vertices; i++)
                *finite &= isfinite(mesh.positions[i]) ? 1 : 0;
    }
    if (rc != PLATEAU_OK) {
        CHECK_EQ_INT(err.code, rc);
        CHECK(message_ok(err.message, sizeof err.message));
        /* documented: free the mesh also after an error; it is either all
         * zero or (after an abort or a failed solve) the last mesh */
        CHECK(solve_mesh_zero(&mesh) ||
              (mesh.num_vertices >= m && mesh.positions != NULL && mesh.triangles != NULL));
    }
    plateau_mesh_free(&mesh);
    CHECK(solve_mesh_zero(&mesh));
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
    return rc;
}

static int stop_at_once(int round, int iteration, double f, void *user)
{
    (void)round;
    (void)iteration;
    (void)f;
    ++*(int *)user;
    return 1;
}

/* Each refused option is named in the message, so a caller can tell which
 * of its settings to change; a memory limit below a megabyte is given in
 * bytes, not as "0 MB". */
static void test_solve_option_named(void)
{
    double xyz[3 * 12];
    plateau_options opt;
    plateau_mesh mesh;
    plateau_error err;
    int i;
    static const char *names[6] = {"method", "max_rounds", "max_iterations", "lambda", "lambda", "alloc_fn"};
    saddle(xyz, 1.0);
    for (i = 0; i < 6; i++) {
        memset(&opt, 0, sizeof opt);
        if (i == 0) opt.method = (plateau_method)17;
        if (i == 1) opt.max_rounds = -1;
        if (i == 2) opt.max_iterations = -1;
        if (i == 3) opt.lambda = NaN_;
        if (i == 4) opt.lambda = -1.0;
        if (i == 5) opt.allocator = half_allocator(1);
        memset(&mesh, 0, sizeof mesh);
        CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_ARGUMENT);
        if (!CHECK(strstr(err.message, names[i]) != NULL)) fprintf(stderr, "  %s: %s\n", names[i], err.message);
        plateau_mesh_free(&mesh);
    }
    memset(&opt, 0, sizeof opt);
    opt.max_memory = 1000;
    memset(&mesh, 0, sizeof mesh);
    CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_MEMORY_LIMIT);
    if (!CHECK(strstr(err.message, "limit of 1000 bytes") != NULL && strstr(err.message, " 0 ") == NULL))
        fprintf(stderr, "  max_memory 1000: %s\n", err.message);
    plateau_mesh_free(&mesh);
    /* an interior count too large to print is "at least" the largest the
     * message prints, never a smaller count given as the one asked for */
    for (i = 0; i < 2; i++) {
        memset(&opt, 0, sizeof opt);
        opt.interior_points = i == 0 ? (size_t)-1 : (size_t)3 << 30; /* 3.2e9 */
        memset(&mesh, 0, sizeof mesh);
        CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_MEMORY_LIMIT);
        if (!CHECK(strstr(err.message, "at least 2000000000 interior") != NULL))
            fprintf(stderr, "  interior_points %d: %s\n", i, err.message);
        plateau_mesh_free(&mesh);
    }
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 100000;
    opt.max_memory = (size_t)1 << 20;
    memset(&mesh, 0, sizeof mesh);
    CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_MEMORY_LIMIT);
    if (!CHECK(strstr(err.message, "about ") != NULL && strstr(err.message, "(100000 interior") != NULL))
        fprintf(stderr, "  interior_points 100000: %s\n", err.message);
    plateau_mesh_free(&mesh);
}

static void test_solve_bad(void)
{
    double xyz[3 * 12];
    plateau_options opt;
    plateau_mesh mesh;
    plateau_error err;
    long index;
    int calls = 0;
    static const double line[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    static const double back[] = {0, 0, 0, 1, 2, 3, 2, 4, 6, 1, 2, 3};
    saddle(xyz, 1.0);

    CHECK_EQ_INT(solve(xyz, 12, NULL, NULL, NULL), PLATEAU_OK);
    CHECK_EQ_INT(solve(NULL, 12, NULL, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(solve(xyz, 0, NULL, NULL, NULL), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(solve(xyz, 2, NULL, NULL, NULL), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_solve(xyz, 12, NULL, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
    /* NaN and Inf, a repeated vertex, collinear and zero-area polygons */
    xyz[3 * 3 + 1] = NaN_;
    CHECK_EQ_INT(solve(xyz, 12, NULL, &index, NULL), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(index, 3);
    xyz[3 * 3 + 1] = Inf_;
    CHECK_EQ_INT(solve(xyz, 12, NULL, &index, NULL), PLATEAU_ERR_NOT_FINITE);
    saddle(xyz, 1.0);
    memcpy(xyz + 3 * 9, xyz + 3 * 8, 3 * sizeof(double));
    CHECK_EQ_INT(solve(xyz, 12, NULL, &index, NULL), PLATEAU_ERR_REPEATED_VERTEX);
    CHECK_EQ_INT(index, 8);
    CHECK_EQ_INT(solve(line, 4, NULL, NULL, NULL), PLATEAU_ERR_COLLINEAR);
    CHECK_EQ_INT(solve(back, 4, NULL, NULL, NULL), PLATEAU_ERR_COLLINEAR);
    /* bad options */
    saddle(xyz, 1.0);
    memset(&opt, 0, sizeof opt);
    opt.method = (plateau_method)17;
    CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    memset(&opt, 0, sizeof opt);
    opt.max_rounds = -1;
    CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    /* lambda: an infinite or NaN weight is refused here, not by the solver */
    memset(&opt, 0, sizeof opt);
    opt.lambda = Inf_;
    memset(&mesh, 0, sizeof mesh);
    CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "out of range") != NULL);
    CHECK(solve_mesh_zero(&mesh));
    opt.lambda = NaN_;
    CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    opt.lambda = -1.0;
    CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    opt.lambda = 2.0;
    CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_OK);
    memset(&opt, 0, sizeof opt);
    opt.allocator = half_allocator(1);
    memset(&mesh, 0, sizeof mesh);
    CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(solve_mesh_zero(&mesh));
    opt.allocator = half_allocator(0);
    CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(solve_mesh_zero(&mesh));
    /* a progress callback that asks to stop, for each method */
    {
        int method;
        for (method = 0; method < 3; method++) {
            memset(&opt, 0, sizeof opt);
            opt.method = (plateau_method)method;
            opt.progress = stop_at_once;
            opt.progress_user = &calls;
            calls = 0;
            CHECK_EQ_INT(solve(xyz, 12, &opt, NULL, NULL), PLATEAU_ERR_ABORTED);
            CHECK_EQ_INT(calls, 1);
        }
    }
    /* the steps after the pipeline, on no mesh */
    CHECK_EQ_INT(plateau_mesh_minimize(NULL, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_delaunay_flips(NULL, 0, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_remove_degenerate(NULL, 0.0, NULL, &err), PLATEAU_ERR_ARGUMENT);
    {
        static const double pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0.1};
        static const plateau_index tri[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
        static const double bad_angles[] = {-1.0, 60.0, 400.0, NAN};
        size_t k, removed;
        if (CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, tri, 4, NULL, &mesh, &err), PLATEAU_OK)) {
            for (k = 0; k < sizeof bad_angles / sizeof bad_angles[0]; k++)
                CHECK_EQ_INT(plateau_mesh_remove_degenerate(&mesh, bad_angles[k], &removed, &err),
                             PLATEAU_ERR_ARGUMENT);
            CHECK_EQ_INT(plateau_mesh_remove_degenerate(&mesh, 0.0, &removed, &err), PLATEAU_OK);
            CHECK_EQ_INT(removed, 0);
            plateau_mesh_free(&mesh);
        }
    }
    {
        plateau_method mm;
        CHECK_EQ_INT(plateau_method_from_name("no such method", &mm), -1);
        CHECK_EQ_INT(plateau_method_from_name(NULL, &mm), -1);
    }
    CHECK(strcmp(plateau_result_string((plateau_result)-999), "") != 0);
    CHECK(plateau_method_name((plateau_method)99) != NULL);
    CHECK(plateau_stop_string(-5) != NULL);
}

/* A polygon folded onto itself (it goes out and comes back by another path)
 * and tiny and huge copies of the saddle: the same problem in other units,
 * so the same mesh up to the scale.  The paper seeding at any scale; the
 * quality seeding (the default) at powers of two: its refinement makes
 * discrete choices (the area-limit search, Ruppert's insertions on the
 * symmetric saddle's ties) that the rounding of other scales can flip
 * (areas 0.1 % to 8 % apart at 1e-150 .. 1e150; the frame only divides by
 * a power of two), so there every run must succeed, finite, and no more. */
static void test_solve_extreme(void)
{
    double xyz[3 * 12];
    static const double scales[] = {1e-150, 1e-50, 1e50, 1e150, 0x1p-500, 0x1p-100, 0x1p100, 0x1p500};
    /* out along two sides of a square and back by its apex */
    static const double folded[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.5, 0.5, 0, 1, 0,
                                    0.5, 0.5, 0.5, 1, 1, 0, 1, 0, 0};
    size_t s;
    int method, finite;
    plateau_options opt;
    plateau_result rc;
    for (method = 0; method < 6; method++) {
        plateau_mesh mesh;
        plateau_report rep, ref;
        int quality = method >= 3;
        memset(&opt, 0, sizeof opt);
        opt.method = (plateau_method)(method % 3);
        opt.seeding = quality ? PLATEAU_SEEDING_QUALITY : PLATEAU_SEEDING_PAPER;
        opt.interior_points = 6;
        saddle(xyz, 1.0);
        memset(&mesh, 0, sizeof mesh);
        if (!CHECK_EQ_INT(plateau_solve(xyz, 12, &opt, &mesh, &ref, NULL), PLATEAU_OK)) continue;
        plateau_mesh_free(&mesh);
        for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
            size_t i;
            double ratio;
            saddle(xyz, scales[s]);
            memset(&mesh, 0, sizeof mesh);
            rc = plateau_solve(xyz, 12, &opt, &mesh, &rep, NULL);
            finite = 1;
            for (i = 0; i < 3 * mesh.num_vertices; i++)
                finite &= isfinite(mesh.positions[i]) ? 1 : 0;
            CHECK(strcmp(plateau_result_string(rc), "unknown plateau result code") != 0);
            CHECK(finite);
            ratio = rep.area / scales[s] / scales[s] / ref.area;
            /* every scale gives the area at scale 1 over the scale squared
             * (the solve runs in the polygon's own frame: INVARIANCE) */
            CHECK_EQ_INT(rc, PLATEAU_OK);
            if (!CHECK(fabs(ratio - 1.0) <= (s >= 4 ? 1e-14 : 1e-9)))
                fprintf(stderr, "  scale %g, method %s: area / scale^2 = %.17g (%.17g at scale 1)\n",
                        scales[s], plateau_method_name((plateau_method)(method % 3)),
                        rep.area / scales[s] / scales[s], ref.area);
            plateau_mesh_free(&mesh);
        }
    }
    for (method = 0; method < 3; method++) {
        memset(&opt, 0, sizeof opt);
        opt.method = (plateau_method)method;
        rc = solve(folded, 8, &opt, NULL, &finite);
        /* any named outcome, but never OK with a NaN */
        CHECK(strcmp(plateau_result_string(rc), "unknown plateau result code") != 0);
        CHECK(rc != PLATEAU_OK || finite);
        printf("folded polygon, method %s: %s\n", plateau_method_name((plateau_method)method),
               plateau_result_string(rc));
    }
}

/* Sizes beyond a double's squares, and far from the origin:
 * - a unit square at z = 1e308 is accepted and solved (area 1): the checks
 *   and the frame work on the polygon moved to its own centre, where
 *   dividing by its largest coordinate flushed it below the smallest double
 *   (it was refused as 'vertices 0 and 1 closer than 1e-9 of the size');
 * - a unit triangle with a spike to z = 1e308 is refused as lying within
 *   1e-12 of its size of one line, which is what the test measures, not as
 *   lying on one line;
 * - the 12-vertex saddle at sizes 1e200 and 1e-200: an area of 1e400 or
 *   1e-400 is no double, so report.area is HUGE_VAL or 0 with
 *   PLATEAU_RANGE_AREA_OVERFLOW or _UNDERFLOW, and area_significand *
 *   2^area_exponent is the true area (the area at size 1 times the size
 *   squared, to 1e-9 in its logarithm); method paper's F (length^-2)
 *   leaves the range the other way and says so; at 1e150 the area fits
 *   and no area flag is set. */
static void test_solve_huge_and_far(void)
{
    static const double square[] = {0, 0, 1e308, 1, 0, 1e308, 1, 1, 1e308, 0, 1, 1e308};
    static const double spike[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1e308};
    static const double sizes[3] = {1e200, 1e-200, 1e150};
    double xyz[3 * 12];
    plateau_mesh mesh;
    plateau_report rep, ref;
    plateau_error err;
    int k;
    memset(&mesh, 0, sizeof mesh);
    CHECK_EQ_INT(plateau_boundary_check(square, 4, &err), PLATEAU_OK);
    CHECK_EQ_INT(plateau_solve(square, 4, NULL, &mesh, &rep, &err), PLATEAU_OK);
    CHECK_NEAR(rep.area, 1.0, 1e-12);
    CHECK_EQ_INT(rep.defects, 0);
    CHECK_EQ_INT(rep.range, 0);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(plateau_boundary_check(spike, 4, &err), PLATEAU_ERR_COLLINEAR);
    CHECK(strstr(err.message, "within 1e-12 of the polygon's size of one line") != NULL);
    saddle(xyz, 1.0);
    CHECK_EQ_INT(plateau_solve(xyz, 12, NULL, &mesh, &ref, NULL), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(ref.range, 0);
    for (k = 0; k < 3; k++) {
        double want;
        saddle(xyz, sizes[k]);
        CHECK_EQ_INT(plateau_solve(xyz, 12, NULL, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT(rep.defects, 0);
        /* log2 of the true area: the reference's, plus twice log2 of the size */
        want = log2(ref.area) + 2.0 * log2(sizes[k]);
        CHECK(rep.area_significand >= 0.5 && rep.area_significand < 1.0);
        CHECK_NEAR(log2(rep.area_significand) + rep.area_exponent, want, 1e-9 * fabs(want) + 1e-12);
        if (k == 0) {
            CHECK(rep.area == HUGE_VAL);
            CHECK(rep.range & PLATEAU_RANGE_AREA_OVERFLOW);
            CHECK(rep.range & PLATEAU_RANGE_F_UNDERFLOW);
        } else if (k == 1) {
            CHECK(rep.area < 2.2250738585072014e-308);
            CHECK(rep.range & PLATEAU_RANGE_AREA_UNDERFLOW);
            CHECK(rep.range & PLATEAU_RANGE_F_OVERFLOW);
        } else {
            CHECK(!(rep.range & (PLATEAU_RANGE_AREA_OVERFLOW | PLATEAU_RANGE_AREA_UNDERFLOW)));
            CHECK_NEAR(rep.area / 1e300, ref.area, 1e-9 * ref.area);
        }
        plateau_mesh_free(&mesh);
    }
}

static void test_kernel_calls_bad(void)
{
    static const double pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0.2};
    static const plateau_index fan[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    countalloc ca;
    plateau_allocator a;
    plateau_mesh mesh;
    plateau_error err;
    plateau_system sys;
    plateau_index verts[2];
    double grad[6], h;
    size_t count = 0;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    if (!CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, fan, 4, &a, &mesh, &err), PLATEAU_OK))
        return;
    /* a sparse row into too small a buffer: an argument error saying the size */
    CHECK_EQ_INT(plateau_vertex_mean_curvature_gradient(&mesh, 4, 2, verts, grad, &count, &h),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(count, plateau_vertex_stencil_size(&mesh, 4));
    /* the system: NULL mesh or output */
    memset(&sys, 0, sizeof sys);
    CHECK_EQ_INT(plateau_system_assemble(NULL, NULL, &sys, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_system_assemble(&mesh, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
    plateau_system_free(&sys);
    /* triangles edited into a bad state, then the adjacency rebuilt: the
     * named error, the adjacency freed, the mesh still freeable */
    mesh.triangles[3 * 2 + 1] = 2; /* triangle 2 = (2, 2, 4) */
    CHECK_EQ_INT(plateau_mesh_build_adjacency(&mesh, &err), PLATEAU_ERR_DEGENERATE_TRIANGLE);
    CHECK_EQ_INT(err.index, 2);
    CHECK(mesh.edges == NULL && mesh.vertex_edges == NULL && mesh.edge_triangles == NULL);
    mesh.triangles[3 * 2 + 1] = 7;
    CHECK_EQ_INT(plateau_mesh_build_adjacency(&mesh, &err), PLATEAU_ERR_INDEX_RANGE);
    mesh.triangles[3 * 2 + 1] = 4; /* triangle 2 = (2, 4, 3): (2, 3, 4) reversed */
    mesh.triangles[3 * 2 + 2] = 3;
    CHECK_EQ_INT(plateau_mesh_build_adjacency(&mesh, &err), PLATEAU_ERR_ORIENTATION);
    CHECK_EQ_INT(plateau_mesh_build_adjacency(NULL, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
}

int main(void)
{
    RUN(test_lm_arguments);
    RUN(test_lm_nonfinite);
    RUN(test_lm_abort);
    RUN(test_lm_extreme_scales);
    RUN(test_dt_arguments);
    RUN(test_dt_points_bad);
    RUN(test_dt_duplicates_mapped);
    RUN(test_dt_segments_bad);
    RUN(test_dt_zero_area_loop);
    RUN(test_dt_refine_options);
    RUN(test_dt_extreme_scales);
    RUN(test_boundary_check_bad);
    RUN(test_boundary_check_collinear);
    RUN(test_boundary_not_embedded);
    RUN(test_boundary_large_circle);
    RUN(test_boundary_extreme_scales);
    RUN(test_domain_bad);
    RUN(test_seed_bad);
    RUN(test_parse_bad);
    RUN(test_parse_edges);
    RUN(test_write_mesh_bad);
    RUN(test_read_file_bad);
    RUN(test_mesh_create_bad);
    RUN(test_kernel_calls_bad);
    RUN(test_solve_bad);
    RUN(test_solve_option_named);
    RUN(test_solve_extreme);
    RUN(test_solve_huge_and_far);
    CHECK_EQ_INT(countalloc_lost_context, 0);
    return harness_report("test_bad_input");
}
