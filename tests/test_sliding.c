/* test_sliding.c - edges that slide (options.slide) against exact
 * answers: a unit ring at height h / 2 and a second loop sliding on the
 * plane z = 0 give half of the catenoid between rings at distance h (its
 * area at second order, the film meeting the plane at 90 degrees), a
 * pinched film beyond h = 1.3255; vertices sliding on radial lines give
 * the same film; the projected gradient and Newton blocks of step 5 match
 * finite differences of the area along the planes and lines; bad slides
 * get their errors.  Compiles the implementation itself (the derivative
 * check reads step 5's private functions). */
#define _POSIX_C_SOURCE 200809L
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "harness.h"
#define COUNTALLOC_SWEEP /* countalloc.h's out-of-memory sweep */
#include "tests/countalloc.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The catenoid between coaxial unit rings at distance h: its waist a
 * (a cosh(h / (2 a)) = 1, the larger root: the stable film) by bisection,
 * and its area pi a (h + a sinh(h / a)). */
static double catenoid_area(double h, double *waist)
{
    double lo = 0.0, hi = 1.0, a = 1.0;
    int it;
    /* f(a) = a cosh(h / (2a)) - 1 rises on the stable branch: from its
     * minimum (at h / (2a) = 1.19968) to a = 1 */
    lo = h / (2.0 * 1.19967864025773);
    for (it = 0; it < 200; it++) {
        a = 0.5 * (lo + hi);
        if (a * cosh(h / (2.0 * a)) > 1.0) hi = a;
        else lo = a;
    }
    if (waist) *waist = a;
    return PI * a * (h + a * sinh(h / a));
}

/* Ring R = 1 at z = h / 2 (fixed) and a ring of q vertices on z = 0 that
 * slides on that plane (or each vertex on its radial line in it); n
 * interior points. */
static plateau_result half_catenoid(double h, size_t q, size_t n, plateau_method method, int radial_lines,
                                    plateau_mesh *mesh, plateau_report *rep, plateau_error *err)
{
    double *xyz = (double *)malloc(6 * q * sizeof(double)), *dir = (double *)malloc(6 * q * sizeof(double));
    int *slide = (int *)malloc(2 * q * sizeof(int));
    size_t counts[2], i;
    plateau_options opt;
    plateau_result r;
    for (i = 0; i < 2 * q; i++) {
        double t = 2.0 * PI * (double)(i % q) / (double)q;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < q ? 0.5 * h : 0.0;
        slide[i] = i < q ? 0 : radial_lines ? PLATEAU_SLIDE_LINE : PLATEAU_SLIDE_PLANE;
        dir[3 * i] = radial_lines ? cos(t) : 0.0;
        dir[3 * i + 1] = radial_lines ? sin(t) : 0.0;
        dir[3 * i + 2] = radial_lines ? 0.0 : 1.0;
    }
    counts[0] = counts[1] = q;
    memset(&opt, 0, sizeof opt);
    opt.method = method;
    opt.interior_points = n;
    opt.slide = slide;
    opt.slide_direction = dir;
    r = plateau_solve_loops(xyz, counts, 2, &opt, mesh, rep, err);
    free(xyz);
    free(dir);
    free(slide);
    return r;
}

/* The largest deviation from 90 degrees (degrees) of the angle between
 * the plane z = 0 and the triangles on the sliding loop's edges (vertices
 * q .. 2q - 1). */
static double contact_deviation(const plateau_mesh *mesh, size_t q)
{
    size_t t;
    double worst = 0.0;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        int k, on = 0;
        double n[3], dev;
        for (k = 0; k < 3; k++) on += (size_t)tr[k] >= q && (size_t)tr[k] < 2 * q;
        if (on < 2) continue;
        plateau_triangle_normal(mesh, t, n);
        /* the normal's angle from the plane: 0 when the film stands upright */
        dev = asin(fabs(n[2]) / sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])) * 180.0 / PI;
        if (dev > worst) worst = dev;
    }
    return worst;
}

/* h = 1: the area converges to half the catenoid's (5.991797 / 2) at
 * second order, the sliding loop stays on z = 0 exactly and comes to the
 * waist, the contact angle tends to 90 degrees; the fixed ring is kept
 * bit for bit; the default method (paper) agrees. */
static void test_half_catenoid(void)
{
    double a, ex = catenoid_area(1.0, &a) / 2.0, err[3], dev[3];
    size_t j, k, kmax = HARNESS_FULL ? 8 : 4; /* make test-full: 48 to 192 vertices per loop */
    CHECK_NEAR(2.0 * ex, 5.991797, 5e-7);
    for (k = kmax / 4, j = 0; k <= kmax; k *= 2) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error e;
        size_t q = 24 * k, i;
        double rmin = 10.0, rmax = 0.0;
        int onplane = 1;
        if (!CHECK_EQ_INT(half_catenoid(1.0, q, 60 * k * k, PLATEAU_METHOD_AREA, 0, &mesh, &rep, &e), PLATEAU_OK))
            continue;
        CHECK_EQ_INT(rep.defects, 0);
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_CONVERGED);
        for (i = q; i < 2 * q; i++) {
            const double *p = mesh.positions + 3 * i;
            double r = sqrt(p[0] * p[0] + p[1] * p[1]);
            onplane &= p[2] == 0.0 && mesh.fixed[i] == 1;
            if (r < rmin) rmin = r;
            if (r > rmax) rmax = r;
        }
        CHECK(onplane);
        for (i = 0; i < q; i++) CHECK(mesh.positions[3 * i + 2] == 0.5 && mesh.fixed[i] == 1);
        CHECK(fabs(rmin - a) < 0.01 && fabs(rmax - a) < 0.01);
        if (j < 3) {
            err[j] = rep.area - ex;
            dev[j] = contact_deviation(&mesh, q);
            printf("  %lu + %lu boundary vertices: area %.7f (exact %.7f, error %.3e), waist %.5f..%.5f "
                   "(exact %.5f), contact angle 90 deg within %.2f deg\n",
                   (unsigned long)q, (unsigned long)q, rep.area, ex, err[j], rmin, rmax, a, dev[j]);
            j++;
        }
        plateau_mesh_free(&mesh);
    }
    for (k = 0; k + 1 < j; k++) {
        double order = log(fabs(err[k] / err[k + 1])) / log(2.0);
        printf("  order %.2f; contact angle deviation falls %.2f times\n", order, dev[k] / dev[k + 1]);
        CHECK(order > 1.8 && order < 2.6);
        CHECK(dev[k + 1] < dev[k]);
    }
    CHECK(fabs(err[j - 1]) < 2e-4 * ex);
    CHECK(dev[j - 1] < 10.0);
    {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error e;
        CHECK_EQ_INT(half_catenoid(1.0, 48, 240, PLATEAU_METHOD_PAPER, 0, &mesh, &rep, &e), PLATEAU_OK);
        CHECK_EQ_INT(rep.defects, 0);
        CHECK(fabs(rep.area - ex) < 2e-3 * ex);
        printf("  method paper: area %.7f\n", rep.area);
        plateau_mesh_free(&mesh);
    }
}

/* Beyond h = 1.3255 no catenoid joins the rings: the sliding loop
 * collapses (PLATEAU_STOP_PINCHED, a defect); at h = 1.3 the film stands,
 * half the catenoid's area. */
static void test_pinched(void)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error e;
    double ex = catenoid_area(1.3, NULL) / 2.0;
    CHECK_EQ_INT(half_catenoid(1.3, 48, 240, PLATEAU_METHOD_AREA, 0, &mesh, &rep, &e), PLATEAU_OK);
    CHECK_EQ_INT(rep.defects, 0);
    CHECK(rep.neck_ratio > PLATEAU_PINCH_RATIO);
    CHECK(fabs(rep.area - ex) < 1e-3 * ex);
    printf("  h = 1.3: area %.7f (exact %.7f), neck ratio %.3f\n", rep.area, ex, rep.neck_ratio);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(half_catenoid(1.4, 48, 240, PLATEAU_METHOD_AREA, 0, &mesh, &rep, &e), PLATEAU_OK);
    CHECK_EQ_INT(rep.stop, PLATEAU_STOP_PINCHED);
    CHECK((rep.defects & PLATEAU_DEFECT_PINCHED) != 0);
    CHECK(rep.neck_ratio < PLATEAU_PINCH_RATIO);
    printf("  h = 1.4: pinched, neck ratio %.3f\n", rep.neck_ratio);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(half_catenoid(1.4, 48, 240, PLATEAU_METHOD_PAPER, 0, &mesh, &rep, &e), PLATEAU_OK);
    CHECK_EQ_INT(rep.stop, PLATEAU_STOP_PINCHED);
    plateau_mesh_free(&mesh);
}

/* Each vertex of the lower loop on its radial line in z = 0: the same
 * film as on the plane (the symmetric film moves them radially only; the
 * mesh, not quite symmetric, gains a little more from the plane's
 * freedom: at most 1e-5 of the area, a fiftieth of the discretisation's
 * error), each vertex still on its line. */
static void test_radial_lines(void)
{
    plateau_mesh a, b;
    plateau_report ra, rb;
    plateau_error e;
    size_t q = 48, i;
    CHECK_EQ_INT(half_catenoid(1.0, q, 240, PLATEAU_METHOD_AREA, 0, &a, &ra, &e), PLATEAU_OK);
    CHECK_EQ_INT(half_catenoid(1.0, q, 240, PLATEAU_METHOD_AREA, 1, &b, &rb, &e), PLATEAU_OK);
    CHECK_EQ_INT(rb.defects, 0);
    CHECK(ra.area <= rb.area && rb.area - ra.area < 1e-5 * ra.area);
    printf("  plane %.9f, radial lines %.9f\n", ra.area, rb.area);
    for (i = q; i < 2 * q; i++) {
        double t = 2.0 * PI * (double)(i - q) / (double)q, *p = b.positions + 3 * i;
        CHECK(p[2] == 0.0);
        CHECK(fabs(p[0] * sin(t) - p[1] * cos(t)) < 1e-15); /* on the line through (cos t, sin t, 0) */
    }
    plateau_mesh_free(&a);
    plateau_mesh_free(&b);
}

/* Step 5's derivatives with sliding vertices: on the solved half
 * catenoid, its interior vertices and sliding ones moved off the film (the
 * sliding ones along their plane or line), the projected gradient is the
 * central difference of the area along each allowed direction (and 0
 * across), and the Newton blocks P_i H_ij P_j applied to an allowed
 * direction at a sliding vertex are the central differences of the
 * projected gradient. */
static void check_derivatives(int kind)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error e;
    plateau__cfg cfg;
    plateau__cfg_run run;
    plateau__solve_newton_state st;
    size_t q = 12, nv, v, i, dirs;
    int *slide;
    double *proj, *g, *gp, *gm, worst_g = 0.0, worst_h = 0.0, worst_n = 0.0;
    unsigned seed = 12345u;
    if (!CHECK_EQ_INT(half_catenoid(1.0, q, 30, PLATEAU_METHOD_AREA, kind == PLATEAU_SLIDE_LINE, &mesh, &rep, &e),
                      PLATEAU_OK))
        return;
    nv = mesh.num_vertices;
    slide = (int *)calloc(nv, sizeof(int));
    proj = (double *)calloc(9 * nv, sizeof(double));
    g = (double *)malloc(3 * nv * sizeof(double));
    gp = (double *)malloc(3 * nv * sizeof(double));
    gm = (double *)malloc(3 * nv * sizeof(double));
    memset(&cfg, 0, sizeof cfg);
    memset(&run, 0, sizeof run);
    for (v = q; v < 2 * q; v++) {
        double t = 2.0 * PI * (double)(v - q) / (double)q, d[3];
        d[0] = kind == PLATEAU_SLIDE_LINE ? cos(t) : 0.0;
        d[1] = kind == PLATEAU_SLIDE_LINE ? sin(t) : 0.0;
        d[2] = kind == PLATEAU_SLIDE_LINE ? 0.0 : 1.0;
        slide[v] = kind;
        plateau__slide_projector(kind, d, proj + 9 * v);
        mesh.fixed[v] = 0;
    }
    run.slide = slide;
    run.slide_p = proj;
    run.slide_m = 2 * q;
    for (v = q; v < nv; v++) { /* off the film, the sliding ones along their plane or line */
        double d[3];
        int c;
        for (c = 0; c < 3; c++) {
            seed = seed * 1103515245u + 12345u;
            d[c] = 0.05 * ((double)(seed >> 8) / 16777216.0 - 0.5);
        }
        if (v < 2 * q) plateau__slide_apply(proj + 9 * v, d, d);
        for (c = 0; c < 3; c++) mesh.positions[3 * v + c] += d[c];
    }
    plateau__solve_energy(&mesh, &cfg, &run, g);
    CHECK_EQ_INT(plateau__solve_newton_init(&mesh, &st, NULL, &e), PLATEAU_OK);
    st.cfg = &cfg;
    st.run = &run;
    CHECK_EQ_INT(plateau__solve_area_hessian(&mesh, st.node, st.nfree, &st.sp, st.hv, st.lv), 0);
    memcpy(st.mv, st.hv, 9 * (size_t)st.sp.row_start[st.nfree] * sizeof(double));
    plateau__slide_blocks(&run, st.node, st.sp.row_start, st.sp.cols, st.mv, st.lv);
    for (v = q, dirs = 0; v < 2 * q; v++) {
        double basis[3][3];
        int b, nb = kind == PLATEAU_SLIDE_LINE ? 1 : 2, c;
        /* the allowed directions, and the one across (plane: its normal) */
        if (kind == PLATEAU_SLIDE_LINE) {
            double t = 2.0 * PI * (double)(v - q) / (double)q;
            basis[0][0] = cos(t), basis[0][1] = sin(t), basis[0][2] = 0.0;
            basis[1][0] = 0.0, basis[1][1] = 0.0, basis[1][2] = 1.0;
        } else {
            basis[0][0] = 1.0, basis[0][1] = 0.0, basis[0][2] = 0.0;
            basis[1][0] = 0.0, basis[1][1] = 1.0, basis[1][2] = 0.0;
        }
        basis[2][0] = kind == PLATEAU_SLIDE_LINE ? -basis[0][1] : 0.0;
        basis[2][1] = kind == PLATEAU_SLIDE_LINE ? basis[0][0] : 0.0;
        basis[2][2] = kind == PLATEAU_SLIDE_LINE ? 0.0 : 1.0;
        for (b = 0; b < 3; b++) {
            const double *t = basis[b];
            double eps = 1e-6, fd, an = 0.0, *x = mesh.positions + 3 * v, x0[3];
            plateau_index iv = st.node[v];
            for (c = 0; c < 3; c++) an += g[3 * v + c] * t[c];
            if (b >= nb) { /* across: no derivative there */
                double m = fabs(an);
                if (m > worst_n) worst_n = m;
                continue;
            }
            memcpy(x0, x, sizeof x0);
            for (c = 0; c < 3; c++) x[c] = x0[c] + eps * t[c];
            fd = plateau_mesh_area(&mesh);
            plateau__solve_energy(&mesh, &cfg, &run, gp);
            for (c = 0; c < 3; c++) x[c] = x0[c] - eps * t[c];
            fd = (fd - plateau_mesh_area(&mesh)) / (2.0 * eps);
            plateau__solve_energy(&mesh, &cfg, &run, gm);
            memcpy(x, x0, sizeof x0);
            if (fabs(an - fd) > worst_g) worst_g = fabs(an - fd);
            /* the Newton column of (v, t): block (j, v) t at each free j */
            for (i = 0; i < nv; i++) {
                plateau_index j = st.node[i];
                size_t qq;
                if (j < 0) continue;
                for (qq = (size_t)st.sp.row_start[j]; qq < (size_t)st.sp.row_start[j + 1]; qq++) {
                    const double *blk = st.mv + 9 * qq;
                    int r;
                    if (st.sp.cols[qq] != iv) continue;
                    for (r = 0; r < 3; r++) {
                        double col = blk[3 * r] * t[0] + blk[3 * r + 1] * t[1] + blk[3 * r + 2] * t[2];
                        double d2 = (gp[3 * i + r] - gm[3 * i + r]) / (2.0 * eps);
                        if (fabs(col - d2) > worst_h) worst_h = fabs(col - d2);
                    }
                }
            }
            dirs++;
        }
    }
    printf("  %s: %lu directions, gradient against differences %.1e, Newton blocks %.1e, across %.1e\n",
           kind == PLATEAU_SLIDE_LINE ? "lines" : "plane", (unsigned long)dirs, worst_g, worst_h, worst_n);
    CHECK(dirs == (kind == PLATEAU_SLIDE_LINE ? q : 2 * q));
    CHECK(worst_g < 1e-8);
    CHECK(worst_h < 1e-5);
    CHECK(worst_n < 1e-15);
    plateau__solve_newton_free(&st);
    free(slide);
    free(proj);
    free(g);
    free(gp);
    free(gm);
    plateau_mesh_free(&mesh);
}

static void test_derivatives(void)
{
    check_derivatives(PLATEAU_SLIDE_PLANE);
    check_derivatives(PLATEAU_SLIDE_LINE);
}

/* Bad slides: each gets its error, and no mesh. */
static void test_bad_slides(void)
{
    double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, dir[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    int slide[3] = {0, PLATEAU_SLIDE_PLANE, 0};
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error e;
    memset(&opt, 0, sizeof opt);
    opt.slide = slide;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(e.message, "slide_direction") != NULL);
    CHECK(mesh.num_vertices == 0);
    opt.slide_direction = dir;
    slide[1] = 3;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(e.index, 1);
    slide[1] = PLATEAU_SLIDE_LINE;
    dir[4] = NAN;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(e.index, 1);
    dir[3] = dir[4] = dir[5] = 0.0;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(e.message, "zero") != NULL);
    dir[5] = 1.0;
    opt.method = PLATEAU_METHOD_PAPER_LITERAL;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    opt.method = PLATEAU_METHOD_AREA;
    opt.pressure = 1.0;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    opt.pressure = 0.0;
    opt.paper_presolve = PLATEAU_OFF;
    CHECK_EQ_INT(plateau_solve(xyz, 3, &opt, &mesh, &rep, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(mesh.num_vertices == 0);
}

/* The slide marks of a boundary text: kinds and directions per vertex
 * line, the marks blanked so that the boundary parser reads "x y z", the
 * closing point's entry dropped by the alignment; bad marks name their
 * line. */
static void test_parse_slides(void)
{
    char text[] = "x y z\n0 0 0 slide-plane 0 0 2\n1 0 0 # fixed\n0 1 0 slide-line 1 -1 0\n0 0 0\n";
    char bad[] = "0 0 0\n1 0 0 slide-line 1 0\n0 1 0\n", nan_text[] = "0 0 0 slide-plane nan 0 1\n";
    char closing[] = "0 0 0\n1 0 0\n0 1 0\n0 0 0 slide-plane 0 0 1\n";
    int *kind = NULL;
    double *dir = NULL, *xyz = NULL;
    size_t count = 0, m = 0;
    plateau_boundary_lines info;
    plateau_error e;
    CHECK_EQ_INT(plateau_parse_slides(text, strlen(text), NULL, &kind, &dir, &count, &e), PLATEAU_OK);
    CHECK_EQ_INT(count, 4);
    if (kind && dir) {
        CHECK(kind[0] == PLATEAU_SLIDE_PLANE && kind[1] == 0 && kind[2] == PLATEAU_SLIDE_LINE && kind[3] == 0);
        CHECK(dir[2] == 2.0 && dir[6] == 1.0 && dir[7] == -1.0 && dir[3] == 0.0);
    }
    memset(&info, 0, sizeof info);
    info.split_loops = 1;
    CHECK_EQ_INT(plateau_parse_boundary_lines(text, strlen(text), NULL, &xyz, &m, &info, &e), PLATEAU_OK);
    CHECK_EQ_INT(m, 3); /* the marks blanked; the closing point dropped */
    CHECK_EQ_INT(plateau_slides_align(kind, dir, &count, &info, &e), PLATEAU_OK);
    CHECK_EQ_INT(count, 3);
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_lines_free(&info, NULL);
    plateau_slides_free(kind, dir, NULL);
    CHECK_EQ_INT(plateau_parse_slides(bad, strlen(bad), NULL, &kind, &dir, &count, &e), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(e.index, 2);
    CHECK(kind == NULL && dir == NULL && count == 0);
    CHECK_EQ_INT(plateau_parse_slides(nan_text, strlen(nan_text), NULL, &kind, &dir, &count, &e),
                 PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(plateau_parse_slides(closing, strlen(closing), NULL, &kind, &dir, &count, &e), PLATEAU_OK);
    memset(&info, 0, sizeof info);
    info.split_loops = 1;
    CHECK_EQ_INT(plateau_parse_boundary_lines(closing, strlen(closing), NULL, &xyz, &m, &info, &e), PLATEAU_OK);
    CHECK_EQ_INT(plateau_slides_align(kind, dir, &count, &info, &e), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(e.index, 4);
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_lines_free(&info, NULL);
    plateau_slides_free(kind, dir, NULL);
    /* no mark: nothing allocated */
    CHECK_EQ_INT(plateau_parse_slides(bad, 6, NULL, &kind, &dir, &count, &e), PLATEAU_OK);
    CHECK(kind == NULL && dir == NULL && count == 0);
}

/* Out of memory at each allocation of a solve with a sliding loop
 * (countalloc_sweep_run), methods area and paper: PLATEAU_ERR_OUT_OF_MEMORY,
 * nothing leaked, no foreign free. */
typedef struct sliding_ctx {
    double xyz[3 * 16], dir[3 * 16];
    int slide[16];
    int method;
    plateau_mesh mesh;
} sliding_ctx;

static int sliding_call(void *ctx, const plateau_allocator *a)
{
    sliding_ctx *c = (sliding_ctx *)ctx;
    size_t counts[2] = {8, 8};
    plateau_options opt;
    plateau_report rep;
    memset(&opt, 0, sizeof opt);
    opt.method = c->method ? PLATEAU_METHOD_PAPER : PLATEAU_METHOD_AREA;
    opt.interior_points = 12;
    opt.slide = c->slide;
    opt.slide_direction = c->dir;
    opt.allocator = *a;
    return (int)plateau_solve_loops(c->xyz, counts, 2, &opt, &c->mesh, &rep, NULL);
}

static void sliding_release(void *ctx, int rc)
{
    (void)rc;
    plateau_mesh_free(&((sliding_ctx *)ctx)->mesh);
}

static void test_sliding_alloc_fail(void)
{
    sliding_ctx c;
    countalloc_sweep s;
    size_t i;
    memset(&c, 0, sizeof c);
    for (i = 0; i < 16; i++) {
        double t = 2.0 * PI * (double)(i % 8) / 8.0;
        c.xyz[3 * i] = cos(t), c.xyz[3 * i + 1] = sin(t), c.xyz[3 * i + 2] = i < 8 ? 0.5 : 0.0;
        c.dir[3 * i + 2] = 1.0;
        c.slide[i] = i < 8 ? 0 : PLATEAU_SLIDE_PLANE;
    }
    s.call = sliding_call;
    s.release = sliding_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    for (c.method = 0; c.method < 2; c.method++) {
        s.name = c.method ? "a sliding loop, method paper" : "a sliding loop, method area";
        CHECK(countalloc_sweep_run(&s) > 10);
    }
}

int main(void)
{
    RUN(test_sliding_alloc_fail);
    RUN(test_parse_slides);
    RUN(test_half_catenoid);
    RUN(test_pinched);
    RUN(test_radial_lines);
    RUN(test_derivatives);
    RUN(test_bad_slides);
    return harness_report("test_sliding");
}
