/* test_supports.c - interior supports (options.supports): a support on
 * the film the boundary takes anyway (the two lines of symmetry of the
 * film spanning a skew quadrilateral) leaves the area within the result's
 * own error estimate; a support lifted out of it raises the area, and a
 * lifted ring's area converges at second order; the support points are
 * fixed vertices, bit for bit, joined by edges; bad supports get their
 * errors. */
#define _POSIX_C_SOURCE 200809L
#ifndef PLATEAU_TEST_LINKED /* else make test links tests/impl.c's object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#define COUNTALLOC_SWEEP /* countalloc.h's out-of-memory sweep */
#include "tests/countalloc.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The skew quadrilateral (+-1, +-1, x y) with k points per side: its
 * minimal film is symmetric under the half-turns about the x and y axes,
 * so it contains both axes' segments between the sides' midpoints. */
static size_t skew_quad(size_t k, double *xyz)
{
    static const double c[4][2] = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    size_t s, i, n = 0;
    for (s = 0; s < 4; s++)
        for (i = 0; i < k; i++) {
            double t = (double)i / (double)k;
            double x = c[s][0] + t * (c[(s + 1) % 4][0] - c[s][0]);
            double y = c[s][1] + t * (c[(s + 1) % 4][1] - c[s][1]);
            xyz[3 * n] = x;
            xyz[3 * n + 1] = y;
            xyz[3 * n + 2] = x * y;
            n++;
        }
    return n;
}

/* The support line along the y axis (x = 0, z = 0) between the sides'
 * midpoints, p interior points. */
static size_t axis_line(size_t p, int axis, double *xyz)
{
    size_t i;
    for (i = 0; i < p; i++) {
        double t = -1.0 + 2.0 * (double)(i + 1) / (double)(p + 1);
        xyz[3 * i] = axis ? 0.0 : t;
        xyz[3 * i + 1] = axis ? t : 0.0;
        xyz[3 * i + 2] = 0.0;
    }
    return p;
}

static plateau_result solve(const double *b, size_t m, const double *sup, const size_t *counts, size_t lines,
                            size_t n, plateau_mesh *mesh, plateau_report *rep, plateau_error *err)
{
    plateau_options opt;
    memset(&opt, 0, sizeof opt);
    opt.method = PLATEAU_METHOD_AREA;
    opt.interior_points = n;
    opt.accuracy = -1.0;
    opt.supports = sup;
    opt.support_counts = counts;
    opt.num_support_polylines = lines;
    return plateau_solve(b, m, &opt, mesh, rep, err);
}

/* 1 when the mesh has an edge between vertices a and b. */
static int has_edge(const plateau_mesh *mesh, size_t a, size_t b)
{
    size_t e;
    for (e = 0; e < mesh->num_edges; e++)
        if (((size_t)mesh->edges[2 * e] == a && (size_t)mesh->edges[2 * e + 1] == b) ||
            ((size_t)mesh->edges[2 * e] == b && (size_t)mesh->edges[2 * e + 1] == a))
            return 1;
    return 0;
}

/* The y axis as one polyline (through the centre) and the x axis as two
 * (either side of it), all on the film: the area stays within the
 * result's own error estimate of the free film's; the supports are fixed
 * vertices after the polygon's, bit for bit, and consecutive points are
 * joined by edges. */
static void test_supports_on_film(void)
{
    double b[3 * 64], sup[3 * 64];
    size_t k = 16, m = skew_quad(k, b), p = 2 * k - 1, cnt[3], i, j, v;
    plateau_mesh a, s;
    plateau_report ra, rs;
    plateau_error e;
    axis_line(p, 1, sup);                     /* y axis, through (0, 0, 0) */
    axis_line(p, 0, sup + 3 * p);             /* x axis ... */
    memmove(sup + 3 * (p + k - 1), sup + 3 * (p + k), 3 * (k - 1) * sizeof(double)); /* ... less (0, 0, 0) */
    cnt[0] = p;
    cnt[1] = k - 1;
    cnt[2] = k - 1;
    CHECK_EQ_INT(solve(b, m, NULL, NULL, 0, m * m / 8, &a, &ra, &e), PLATEAU_OK);
    CHECK_EQ_INT(solve(b, m, sup, cnt, 3, m * m / 8, &s, &rs, &e), PLATEAU_OK);
    CHECK_EQ_INT(rs.defects, 0);
    CHECK_EQ_INT(rs.support_points, p + 2 * (k - 1));
    CHECK(rs.area_error_estimate > 0.0 && ra.area_error_estimate > 0.0);
    CHECK(fabs(rs.area - ra.area) <= rs.area_error_estimate * rs.area);
    printf("  on the film: area %.9f, supported %.9f, difference %.2e relative, estimate %.2e\n", ra.area,
           rs.area, fabs(rs.area - ra.area) / ra.area, rs.area_error_estimate);
    for (i = 0; i < rs.support_points; i++) {
        v = m + rs.boundary_points_added + i;
        CHECK(s.fixed[v] == 1);
        CHECK(memcmp(s.positions + 3 * v, sup + 3 * i, 3 * sizeof(double)) == 0);
    }
    for (j = 0, i = 0; j < 3; i += cnt[j], j++) {
        size_t q;
        for (q = 1; q < cnt[j]; q++) CHECK(has_edge(&s, m + i + q - 1, m + i + q));
    }
    plateau_mesh_free(&a);
    plateau_mesh_free(&s);
}

/* The y axis lifted by up to 0.2 out of the film raises the area beyond
 * the estimate, the centre point lifted by 0.05 raises it too; the default method (paper) takes supports too and keeps them fixed. */
static void test_supports_lifted_line(void)
{
    double b[3 * 64], sup[3 * 64];
    size_t k = 16, m = skew_quad(k, b), p = axis_line(2 * k - 1, 1, sup), i;
    plateau_mesh a, s;
    plateau_report ra, rs;
    plateau_error e;
    plateau_options opt;
    CHECK_EQ_INT(solve(b, m, NULL, NULL, 0, m * m / 8, &a, &ra, &e), PLATEAU_OK);
    for (i = 0; i < p; i++) sup[3 * i + 2] = 0.2 * (1.0 - sup[3 * i + 1] * sup[3 * i + 1]);
    CHECK_EQ_INT(solve(b, m, sup, &p, 1, m * m / 8, &s, &rs, &e), PLATEAU_OK);
    CHECK_EQ_INT(rs.defects, 0);
    CHECK(rs.area > ra.area * (1.0 + 3.0 * rs.area_error_estimate));
    printf("  lifted line: area %.9f against %.9f\n", rs.area, ra.area);
    plateau_mesh_free(&s);
    {   /* one point, the film's centre lifted by 0.05: the area rises, by
         * less than the line's (a point carries no film in the limit: the
         * rise falls with the mesh's spacing) */
        double point[3] = {0.0, 0.0, 0.05};
        size_t one = 1;
        CHECK_EQ_INT(solve(b, m, point, &one, 1, m * m / 8, &s, &rs, &e), PLATEAU_OK);
        CHECK_EQ_INT(rs.defects, 0);
        CHECK(rs.area > ra.area);
        CHECK(memcmp(s.positions + 3 * m, point, sizeof point) == 0);
        printf("  lifted point: area %.9f against %.9f\n", rs.area, ra.area);
        plateau_mesh_free(&s);
    }
    memset(&opt, 0, sizeof opt);
    opt.supports = sup;
    opt.support_counts = &p;
    opt.num_support_polylines = 1;
    opt.interior_points = 200;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_OK);
    CHECK_EQ_INT(rs.method, PLATEAU_METHOD_PAPER);
    CHECK_EQ_INT(rs.defects, 0);
    CHECK_EQ_INT(rs.support_points, p);
    CHECK(rs.area > ra.area * (1.0 + 3.0 * ra.area_error_estimate));
    for (i = 0; i < p; i++)
        CHECK(memcmp(s.positions + 3 * (m + rs.boundary_points_added + i), sup + 3 * i, 3 * sizeof(double)) == 0);
    plateau_mesh_free(&a);
    plateau_mesh_free(&s);
}
/* The exact film: a flat unit circle at z = 0 and a ring of radius r at
 * height h as its support: the disc of the ring and, between the two, the
 * catenoid rho(z) = a cosh((z - z0) / a) through both circles whose neck
 * lies above the ring (z0 > h: a radial graph, least area), a by
 * bisection; its area pi a [t + a sinh(2 t / a) / 2] from t = -z0 to
 * h - z0, plus pi r^2. */
static double ring_exact(double r, double h)
{
    double lo = 0.05, hi = 1.0, a = 0.5, z0, t0, t1;
    int it;
    for (it = 0; it < 200; it++) {
        double f;
        a = 0.5 * (lo + hi);
        z0 = a * acosh(1.0 / a);
        f = a * cosh((h - z0) / a) - r;
        if (f > 0.0) hi = a;
        else lo = a;
    }
    z0 = a * acosh(1.0 / a);
    t0 = -z0;
    t1 = h - z0;
    return PI * a * ((t1 + 0.5 * a * sinh(2.0 * t1 / a)) - (t0 + 0.5 * a * sinh(2.0 * t0 / a))) + PI * r * r;
}

static size_t ring_case(size_t k, double r, double h, double *b, double *sup, size_t *cnt)
{
    size_t i, m = 16 * k;
    for (i = 0; i < m; i++) {
        double t = 2.0 * PI * (double)i / (double)m;
        b[3 * i] = cos(t);
        b[3 * i + 1] = sin(t);
        b[3 * i + 2] = 0.0;
    }
    *cnt = 8 * k + 1;
    for (i = 0; i < 8 * k; i++) {
        double t = 2.0 * PI * (double)i / (double)(8 * k);
        sup[3 * i] = r * cos(t);
        sup[3 * i + 1] = r * sin(t);
        sup[3 * i + 2] = h;
    }
    memcpy(sup + 3 * 8 * k, sup, 3 * sizeof(double)); /* closed */
    return m;
}

/* A lifted ring (radius 0.5, height 0.2, closed: its last point repeats
 * the first) over a flat unit circle: the exact film is a catenoid piece
 * and the ring's disc; the area converges to it at second order, and lies
 * above the flat disc's pi. */
static void test_supports_ring_order(void)
{
    double b[3 * 256], sup[3 * 128], ex = ring_exact(0.5, 0.2), err[3];
    size_t k, j = 0;
    for (k = 2; k <= 8; k *= 2, j++) {
        size_t cnt, m = ring_case(k, 0.5, 0.2, b, sup, &cnt);
        plateau_mesh s;
        plateau_report rs;
        plateau_error e;
        CHECK_EQ_INT(solve(b, m, sup, &cnt, 1, 40 * k * k, &s, &rs, &e), PLATEAU_OK);
        CHECK_EQ_INT(rs.defects, 0);
        CHECK_EQ_INT(rs.support_points, cnt - 1);
        CHECK(rs.area > PI);
        CHECK_NEAR(rs.area, ex, 0.05);
        err[j] = rs.area - ex;
        printf("  ring k = %lu: area %.9f, exact %.9f, error %.3e\n", (unsigned long)k, rs.area, ex, err[j]);
        plateau_mesh_free(&s);
    }
    for (j = 0; j < 2; j++) {
        double order = log(fabs(err[j] / err[j + 1])) / log(2.0);
        printf("  order %.3f\n", order);
        CHECK(order > 1.8 && order < 2.2);
    }
    CHECK(fabs(err[2]) < 5e-4 * ex);
}

/* Bad supports: each gets its error, and no mesh. */
static void test_supports_bad(void)
{
    double b[3 * 64], sup[3 * 8] = {0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 5.0, 0.0, 0.0};
    size_t m = skew_quad(4, b), cnt[2] = {1, 0};
    plateau_options opt;
    plateau_mesh s;
    plateau_report rs;
    plateau_error e;
    memset(&opt, 0, sizeof opt);
    opt.num_support_polylines = 1;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(s.num_vertices == 0 && s.positions == NULL);
    opt.supports = sup;
    opt.support_counts = cnt + 1; /* a polyline of no point */
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(e.message, "no point") != NULL);
    sup[4] = NAN;
    cnt[0] = 2;
    opt.support_counts = cnt;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(e.index, 1);
    sup[4] = 0.0;
    opt.coarse_to_fine = PLATEAU_ON;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_ARGUMENT);
    opt.coarse_to_fine = PLATEAU_AUTO;
    /* a point twice */
    cnt[0] = 3;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(e.message, "falls on the domain point") != NULL);
    CHECK(s.num_vertices == 0);
    /* a point far outside: the film comes nearest it at the boundary */
    opt.supports = sup + 9;
    cnt[0] = 1;
    CHECK_EQ_INT(plateau_solve(b, m, &opt, &s, &rs, &e), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(e.message, "no place inside the film") != NULL);
    CHECK_EQ_INT(e.index, 0);
    CHECK(s.num_vertices == 0);
}

/* Out of memory at each allocation of a supported solve
 * (countalloc_sweep_run): PLATEAU_ERR_OUT_OF_MEMORY, nothing leaked, no
 * foreign free. */
typedef struct supports_ctx {
    double b[3 * 16], sup[3 * 3];
    size_t m, p;
    plateau_mesh mesh;
} supports_ctx;

static int supports_call(void *ctx, const plateau_allocator *a)
{
    supports_ctx *c = (supports_ctx *)ctx;
    plateau_options opt;
    plateau_report rep;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 20;
    opt.supports = c->sup;
    opt.support_counts = &c->p;
    opt.num_support_polylines = 1;
    opt.allocator = *a;
    return (int)plateau_solve(c->b, c->m, &opt, &c->mesh, &rep, NULL);
}

static void supports_release(void *ctx, int rc)
{
    (void)rc;
    plateau_mesh_free(&((supports_ctx *)ctx)->mesh);
}

static void test_supports_alloc_fail(void)
{
    supports_ctx c;
    countalloc_sweep s;
    memset(&c, 0, sizeof c);
    c.m = skew_quad(4, c.b);
    c.p = axis_line(3, 1, c.sup);
    s.name = "a supported solve";
    s.call = supports_call;
    s.release = supports_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) > 10);
}

int main(void)
{
    RUN(test_supports_alloc_fail);
    RUN(test_supports_on_film);
    RUN(test_supports_lifted_line);
    RUN(test_supports_ring_order);
    RUN(test_supports_bad);
    return harness_report("test_supports");
}
