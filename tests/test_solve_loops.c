/* test_solve_loops.c - several boundary loops (plateau_solve_loops): the
 * catenoid between two coaxial rings against its exact area and surface,
 * the pinch past h = 1.3255 R, frames with holes, tilted rings, three
 * loops, one loop bit for bit as plateau_solve, and the new errors. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "tests/harness.h"
#include "tests/countalloc.h"
#include "examples/surfaces.h"

#define TWO_PI 6.283185307179586

/* A ring of m vertices: centre c, radius r, in the plane spanned by the
 * unit vectors e1, e2 (t from e1 towards e2); reverse walks it backwards. */
static void ring(double *xyz, int m, const double *c, double r, const double *e1, const double *e2,
                 int reverse)
{
    int i, k;
    for (i = 0; i < m; i++) {
        double t = TWO_PI * (reverse ? (double)(m - i) : (double)i) / m;
        for (k = 0; k < 3; k++) xyz[3 * i + k] = c[k] + r * (cos(t) * e1[k] + sin(t) * e2[k]);
    }
}

static const double EX[3] = {1.0, 0.0, 0.0}, EY[3] = {0.0, 1.0, 0.0}, EZ[3] = {0.0, 0.0, 1.0};

/* Two coaxial rings of radius 1 at z = -h/2 and h/2, m vertices each. */
static void rings(double *xyz, int m, double h)
{
    double c0[3] = {0.0, 0.0, 0.0}, c1[3] = {0.0, 0.0, 0.0};
    c0[2] = -0.5 * h;
    c1[2] = 0.5 * h;
    ring(xyz, m, c0, 1.0, EX, EY, 0);
    ring(xyz + 3 * m, m, c1, 1.0, EX, EY, 0);
}

/* The checks every multi-loop result must pass: return OK, no defects,
 * the M boundary vertices first, fixed and bit for bit, the rest free;
 * the triangles a manifold with one consistent orientation (a fresh
 * plateau_mesh_create accepts them), every boundary edge a loop edge and
 * every loop edge a boundary edge, and V - E + T = chi. */
static void check_valid(const plateau_mesh *mesh, const plateau_report *rep, const double *xyz,
                        const size_t *counts, size_t k, long chi, const char *what)
{
    size_t M = 0, j, e, v, nb = 0, off = 0;
    plateau_mesh copy;
    int ok = 1;
    for (j = 0; j < k; j++) M += counts[j];
    if (!CHECK_EQ_INT(rep->defects, 0)) fprintf(stderr, "  %s: defects %u\n", what, rep->defects);
    CHECK(rep->stop == PLATEAU_STOP_CONVERGED || rep->stop == PLATEAU_STOP_ROUND_LIMIT);
    CHECK_EQ_INT(rep->loops, k);
    if (!CHECK(mesh->num_vertices > M)) return;
    CHECK(memcmp(mesh->positions, xyz, 3 * M * sizeof(double)) == 0);
    for (v = 0; v < mesh->num_vertices; v++) ok &= (mesh->fixed[v] != 0) == (v < M);
    CHECK(ok);
    CHECK_EQ_INT((long)mesh->num_vertices - (long)mesh->num_edges + (long)mesh->num_triangles, chi);
    CHECK_EQ_INT(plateau_mesh_create(mesh->positions, mesh->num_vertices, mesh->fixed, mesh->triangles,
                                     mesh->num_triangles, NULL, &copy, NULL),
                 PLATEAU_OK);
    plateau_mesh_free(&copy);
    /* boundary edges = loop edges */
    ok = 1;
    for (e = 0; e < mesh->num_edges; e++) {
        size_t a = (size_t)mesh->edges[2 * e], b = (size_t)mesh->edges[2 * e + 1];
        int boundary = mesh->edge_triangles[2 * e] < 0 || mesh->edge_triangles[2 * e + 1] < 0;
        nb += boundary;
        if (boundary) ok &= a < M && b < M;
    }
    CHECK(ok);
    CHECK_EQ_INT(nb, M);
    for (j = 0; j < k; j++) {
        size_t i;
        ok = 1;
        for (i = 0; i < counts[j]; i++) {
            size_t a = off + i, b = off + (i + 1) % counts[j], s;
            int found = 0;
            for (s = mesh->vertex_edge_start[a]; s < mesh->vertex_edge_start[a + 1]; s++) {
                size_t ed = (size_t)mesh->vertex_edges[s];
                if ((size_t)mesh->edges[2 * ed] + (size_t)mesh->edges[2 * ed + 1] == a + b &&
                    ((size_t)mesh->edges[2 * ed] == b || (size_t)mesh->edges[2 * ed + 1] == b) &&
                    (mesh->edge_triangles[2 * ed] < 0 || mesh->edge_triangles[2 * ed + 1] < 0))
                    found = 1;
            }
            ok &= found;
        }
        CHECK(ok);
        off += counts[j];
    }
}

/* One loop: plateau_solve_loops with k = 1 is plateau_solve, bit for bit. */
static void test_one_loop_same(void)
{
    double xyz[3 * 24];
    size_t count = 24;
    int i, meth;
    for (i = 0; i < 24; i++) {
        double t = TWO_PI * i / 24;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.4 * cos(2 * t);
    }
    for (meth = 0; meth < 3; meth++) {
        plateau_options o;
        plateau_mesh a, b;
        plateau_report ra, rb;
        memset(&o, 0, sizeof o);
        o.method = (plateau_method)meth;
        o.interior_points = 30;
        CHECK_EQ_INT(plateau_solve(xyz, 24, &o, &a, &ra, NULL), PLATEAU_OK);
        CHECK_EQ_INT(plateau_solve_loops(xyz, &count, 1, &o, &b, &rb, NULL), PLATEAU_OK);
        if (CHECK(a.num_vertices == b.num_vertices && a.num_triangles == b.num_triangles)) {
            CHECK(memcmp(a.positions, b.positions, 3 * a.num_vertices * sizeof(double)) == 0);
            CHECK(memcmp(a.triangles, b.triangles, 3 * a.num_triangles * sizeof(plateau_index)) == 0);
        }
        CHECK(ra.area == rb.area && ra.loops == 1 && rb.loops == 1);
        plateau_mesh_free(&a);
        plateau_mesh_free(&b);
    }
}

/* The catenoid between coaxial rings of radius 1 at h = 0.5 and 1: as m
 * (and n ~ m^2) grow, the area approaches pi a (h + a sinh(h / a)) and the
 * interior vertices approach the surface r = a cosh(z / a); the measured
 * orders are printed (area error and distance both O(m^-2): the polygon's
 * chords and the triangles' flatness). */
static void test_catenoid(void)
{
    static const double hs[2] = {0.5, 1.0};
    static const int ms[3] = {12, 24, 48};
    int ih, meth, im;
    printf("  catenoid between rings of radius 1 (exact: a = neck, A = pi a (h + a sinh(h/a)))\n");
    printf("  h    method         m   n     area       exact      error     order  mean dist  neck\n");
    for (ih = 0; ih < 2; ih++) {
        double h = hs[ih], a = demo_catenoid_neck(h), exact = demo_catenoid_area(h);
        for (meth = 0; meth < 3; meth++) {
            double prev_err = 0.0, prev_dist = 0.0, first_err = 0.0;
            int nm = meth == PLATEAU_METHOD_PAPER_LITERAL ? 2 : 3;
            for (im = 0; im < nm; im++) {
                int m = ms[im];
                size_t counts[2], v;
                double *xyz = (double *)malloc(6 * (size_t)m * sizeof(double)), err, dist = 0.0;
                plateau_options o;
                plateau_mesh mesh;
                plateau_report rep;
                plateau_error e;
                counts[0] = counts[1] = (size_t)m;
                rings(xyz, m, h);
                memset(&o, 0, sizeof o);
                o.method = (plateau_method)meth;
                /* interior spacing near the ring spacing: the annulus
                 * between the rings holds about (h / (2 pi / m)) rows */
                o.interior_points = (size_t)((double)m * (double)m * h / TWO_PI) + 4;
                if (!CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &e), PLATEAU_OK)) {
                    fprintf(stderr, "  %s\n", e.message);
                    free(xyz);
                    continue;
                }
                check_valid(&mesh, &rep, xyz, counts, 2, 0, "catenoid");
                CHECK_EQ_INT(rep.domain, PLATEAU_DOMAIN_ANNULUS);
                for (v = 2 * (size_t)m; v < mesh.num_vertices; v++) {
                    const double *p = mesh.positions + 3 * v;
                    double r = sqrt(p[0] * p[0] + p[1] * p[1]);
                    dist += fabs(r - a * cosh(p[2] / a)) / cosh(p[2] / a);
                }
                dist /= (double)(mesh.num_vertices - 2 * (size_t)m);
                err = fabs(rep.area - exact);
                printf("  %.1f  %-13s %3d %4lu  %.6f  %.6f  %.2e  %5.2f  %.2e   %.3f\n", h,
                       plateau_method_name(o.method), m, (unsigned long)rep.interior_points, rep.area,
                       exact, err, im > 0 ? log(prev_err / err) / log(2.0) : 0.0, dist, rep.neck_ratio);
                /* the interior vertices approach the surface (every method) */
                if (im > 0) CHECK(dist < 0.6 * prev_dist);
                if (meth == PLATEAU_METHOD_AREA && im > 0) CHECK(err < 0.3 * prev_err);
                if (meth == PLATEAU_METHOD_PAPER && im == 0) first_err = err;
                /* method paper's area crosses the exact one (H = 0 is not
                 * least area): its error falls over the whole range */
                if (meth == PLATEAU_METHOD_PAPER && im == nm - 1) CHECK(err < 0.1 * first_err);
                if (meth != PLATEAU_METHOD_PAPER_LITERAL) {
                    /* the waist approaches 2 pi a: the neck ratio approaches a */
                    CHECK(fabs(rep.neck_ratio - a) < 0.05);
                    CHECK(rep.min_angle_deg > 15.0);
                }
                prev_err = err;
                prev_dist = dist;
                plateau_mesh_free(&mesh);
                free(xyz);
            }
        }
    }
}

/* The example of plateau.h's SEVERAL LOOPS note: two coaxial 32-gon rings
 * of radius 1 at distance 1, 170 interior points: area 5.99151 by method
 * paper, 5.98822 by method area, both valid (the exact catenoid on the
 * circles has 5.99180). */
static void test_header_example(void)
{
    double xyz[3 * 64];
    size_t counts[2] = {32, 32}, i;
    static const double want[3] = {5.99151, 0.0, 5.98822};
    int meth;
    for (meth = 0; meth < 3; meth += 2) {
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        for (i = 0; i < 64; i++) {
            double t = TWO_PI * (double)(i % 32) / 32.0;
            xyz[3 * i] = cos(t);
            xyz[3 * i + 1] = sin(t);
            xyz[3 * i + 2] = i < 32 ? -0.5 : 0.5;
        }
        memset(&o, 0, sizeof o);
        o.interior_points = 170;
        o.method = (plateau_method)meth;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), PLATEAU_OK);
        CHECK_NEAR(rep.area, want[meth], 5e-6);
        CHECK_EQ_INT(rep.interior_points, 170);
        CHECK_EQ_INT(rep.defects, 0);
        plateau_mesh_free(&mesh);
    }
    CHECK_NEAR(demo_catenoid_area(1.0), 5.99180, 5e-6);
}

/* The loops' direction and starting vertex are the library's business: the
 * second ring walked backwards and started a third of the way round (and
 * options.seeding, not read for several loops, set to the fan) gives the
 * same catenoid: a valid untwisted annulus whose area and neck agree with
 * the plain rings' to the discretisation. */
static void test_orientation(void)
{
    double xyz[6 * 24], alt[6 * 24];
    size_t counts[2] = {24, 24};
    int i, k, meth;
    rings(xyz, 24, 1.0);
    memcpy(alt, xyz, sizeof xyz);
    for (i = 0; i < 24; i++)
        for (k = 0; k < 3; k++) alt[72 + 3 * i + k] = xyz[72 + 3 * ((24 - i + 8) % 24) + k];
    for (meth = 0; meth < 3; meth += 2) {
        plateau_options o;
        plateau_mesh a, b;
        plateau_report ra, rb;
        memset(&o, 0, sizeof o);
        o.method = (plateau_method)meth;
        o.interior_points = 95;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &a, &ra, NULL), PLATEAU_OK);
        o.seeding = PLATEAU_SEEDING_PAPER;
        CHECK_EQ_INT(plateau_solve_loops(alt, counts, 2, &o, &b, &rb, NULL), PLATEAU_OK);
        check_valid(&a, &ra, xyz, counts, 2, 0, "rings");
        check_valid(&b, &rb, alt, counts, 2, 0, "rings, the second reversed and turned");
        CHECK_NEAR(rb.area, ra.area, 2e-3 * ra.area);
        CHECK_NEAR(rb.neck_ratio, ra.neck_ratio, 0.02);
        printf("  rings as given / second reversed and turned, %s: area %.6f / %.6f, neck %.4f / %.4f\n",
               plateau_method_name(o.method), ra.area, rb.area, ra.neck_ratio, rb.neck_ratio);
        plateau_mesh_free(&a);
        plateau_mesh_free(&b);
    }
}

/* Past h = 1.3255 R there is no catenoid: every method reports the pinch
 * (a named stop and a defect, not a valid mesh). */
static void test_pinch(void)
{
    double xyz[6 * 24];
    size_t counts[2] = {24, 24};
    int meth;
    char buf[300];
    rings(xyz, 24, 1.5);
    for (meth = 0; meth < 3; meth++) {
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        memset(&o, 0, sizeof o);
        o.method = (plateau_method)meth;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), PLATEAU_OK);
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_PINCHED);
        CHECK(rep.defects & PLATEAU_DEFECT_PINCHED);
        CHECK(rep.neck_ratio < PLATEAU_PINCH_RATIO);
        CHECK(memcmp(mesh.positions, xyz, sizeof xyz) == 0);
        printf("  h = 1.5 R, %s: %s (neck %.3f of the rings, area %.4f; 2 pi R^2 = 6.2832)\n",
               plateau_method_name(o.method), plateau_defects_string(rep.defects, buf, sizeof buf),
               rep.neck_ratio, rep.area);
        plateau_mesh_free(&mesh);
    }
    CHECK(strstr(plateau_stop_string(PLATEAU_STOP_PINCHED), "pinched") != NULL);
    /* just inside the limit (h = 1.25 R; the catenoid's neck is 0.70 R)
     * nothing pinches: the test does not fire on a thin but real neck */
    rings(xyz, 24, 1.25);
    for (meth = 0; meth < 3; meth++) {
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        memset(&o, 0, sizeof o);
        o.method = (plateau_method)meth;
        o.interior_points = 115;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), PLATEAU_OK);
        CHECK(rep.stop != PLATEAU_STOP_PINCHED && !(rep.defects & PLATEAU_DEFECT_PINCHED));
        CHECK(rep.neck_ratio > 0.55 && rep.neck_ratio < 0.8);
        if (meth != PLATEAU_METHOD_PAPER_LITERAL) check_valid(&mesh, &rep, xyz, counts, 2, 0, "h = 1.25 R");
        printf("  h = 1.25 R, %s: %s, neck %.3f (exact %.3f), area %.5f\n", plateau_method_name(o.method),
               plateau_stop_string(rep.stop), rep.neck_ratio, demo_catenoid_neck(1.25), rep.area);
        plateau_mesh_free(&mesh);
    }
}

/* Shapes that are no catenoid: a non-planar frame with a planar hole, two
 * tilted non-coaxial rings, a planar outer loop with two holes; the inner
 * loops given either way round. */
static void test_shapes(void)
{
    int meth, rev;
    for (rev = 0; rev < 2; rev++) {
        /* a saddle frame of radius 2 around a flat hole of radius 0.6 */
        double xyz[3 * (32 + 16)], c[3] = {0.0, 0.0, 0.0};
        size_t counts[2] = {32, 16};
        int i;
        for (i = 0; i < 32; i++) {
            double t = TWO_PI * i / 32;
            xyz[3 * i] = 2.0 * cos(t);
            xyz[3 * i + 1] = 2.0 * sin(t);
            xyz[3 * i + 2] = 0.5 * cos(2.0 * t);
        }
        ring(xyz + 96, 16, c, 0.6, EX, EY, rev);
        for (meth = 0; meth < 3; meth++) {
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)meth;
            o.interior_points = 80;
            if (CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), PLATEAU_OK)) {
                check_valid(&mesh, &rep, xyz, counts, 2, 0, "frame with a hole");
                CHECK_EQ_INT(rep.domain, PLATEAU_DOMAIN_PLANE);
                if (meth != PLATEAU_METHOD_PAPER_LITERAL) {
                    /* the annulus, forced, spans the same frame */
                    plateau_mesh m2;
                    plateau_report r2;
                    o.force_circle_domain = 1;
                    if (CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &m2, &r2, NULL), PLATEAU_OK)) {
                        check_valid(&m2, &r2, xyz, counts, 2, 0, "frame with a hole, annulus");
                        CHECK_EQ_INT(r2.domain, PLATEAU_DOMAIN_ANNULUS);
                        CHECK_NEAR(r2.area, rep.area, 3e-3 * rep.area);
                        if (rev == 0)
                            printf("  saddle frame with a hole, %s, annulus forced: area %.5f\n",
                                   plateau_method_name(o.method), r2.area);
                    }
                    plateau_mesh_free(&m2);
                }
                CHECK(rep.neck_ratio > 1.0); /* the hole is the shorter loop */
                if (rev == 0)
                    printf("  saddle frame with a hole, %s: area %.5f, %lu interior, angles %.1f..%.1f\n",
                           plateau_method_name(o.method), rep.area, (unsigned long)rep.interior_points,
                           rep.min_angle_deg, rep.max_angle_deg);
            }
            plateau_mesh_free(&mesh);
        }
    }
    for (rev = 0; rev < 2; rev++) {
        /* two rings tilted by 20 degrees the opposite ways, axes apart */
        double xyz[6 * 20], c0[3] = {0.0, 0.0, -0.4}, c1[3] = {0.3, 0.1, 0.4}, e0[3], e1[3];
        double s = sin(20.0 / 57.29577951308232), co = cos(20.0 / 57.29577951308232);
        size_t counts[2] = {20, 20};
        e0[0] = co; e0[1] = 0.0; e0[2] = s;
        e1[0] = co; e1[1] = 0.0; e1[2] = -s;
        ring(xyz, 20, c0, 1.0, e0, EY, 0);
        ring(xyz + 60, 20, c1, 0.9, e1, EY, rev);
        for (meth = 0; meth < 3; meth++) {
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)meth;
            o.interior_points = 60;
            if (CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), PLATEAU_OK)) {
                char buf[300];
                /* paper-literal (the paper as printed: F over the boundary
                 * vertices too) folds this film: its defects are reported */
                if (meth != PLATEAU_METHOD_PAPER_LITERAL) {
                    check_valid(&mesh, &rep, xyz, counts, 2, 0, "tilted rings");
                    CHECK(rep.neck_ratio > 0.5);
                } else {
                    CHECK(memcmp(mesh.positions, xyz, sizeof xyz) == 0);
                    CHECK(rep.defects != 0 || rep.neck_ratio > 0.5);
                }
                if (rev == 0)
                    printf("  tilted rings, %s: area %.5f, domain %d, neck %.3f, angles %.1f..%.1f, %s\n",
                           plateau_method_name(o.method), rep.area, (int)rep.domain, rep.neck_ratio,
                           rep.min_angle_deg, rep.max_angle_deg,
                           plateau_defects_string(rep.defects, buf, sizeof buf));
            }
            plateau_mesh_free(&mesh);
        }
    }
    for (rev = 0; rev < 2; rev++) {
        /* three loops in one plane: a circle of radius 3 and two holes;
         * the minimal surface is the flat region */
        double xyz[3 * (40 + 12 + 12)], c[3] = {0.0, 0.0, 0.0}, flat;
        size_t counts[3] = {40, 12, 12};
        ring(xyz, 40, c, 3.0, EX, EY, 0);
        c[0] = -1.3;
        ring(xyz + 120, 12, c, 0.6, EX, EY, rev);
        c[0] = 1.2;
        c[1] = 0.4;
        ring(xyz + 156, 12, c, 0.5, EX, EY, 0);
        /* polygon areas: n/2 r^2 sin(2 pi / n) */
        flat = 20.0 * 9.0 * sin(TWO_PI / 40) - 6.0 * 0.36 * sin(TWO_PI / 12) - 6.0 * 0.25 * sin(TWO_PI / 12);
        for (meth = 0; meth < 3; meth++) {
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)meth;
            o.interior_points = 60;
            if (CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 3, &o, &mesh, &rep, NULL), PLATEAU_OK)) {
                size_t v;
                double zmax = 0.0;
                check_valid(&mesh, &rep, xyz, counts, 3, -1, "three loops");
                CHECK_EQ_INT(rep.domain, PLATEAU_DOMAIN_PLANE);
                CHECK_NEAR(rep.area, flat, 1e-9 * flat);
                for (v = 0; v < mesh.num_vertices; v++)
                    if (fabs(mesh.positions[3 * v + 2]) > zmax) zmax = fabs(mesh.positions[3 * v + 2]);
                CHECK(zmax < 1e-9);
                if (rev == 0)
                    printf("  three loops in a plane, %s: area %.9f (flat %.9f), angles %.1f..%.1f\n",
                           plateau_method_name(o.method), rep.area, flat, rep.min_angle_deg,
                           rep.max_angle_deg);
            }
            plateau_mesh_free(&mesh);
        }
    }
}

static void expect_error2(const double *xyz, const size_t *counts, size_t k, plateau_result want,
                          const char *words, long index, long index2)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error e;
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, k, NULL, &mesh, &rep, &e), want);
    if (!CHECK(strstr(e.message, words) != NULL)) fprintf(stderr, "  message: %s\n", e.message);
    CHECK_EQ_INT(e.index, index);
    CHECK_EQ_INT(e.index2, index2);
    plateau_mesh_free(&mesh);
}

static void expect_error(const double *xyz, const size_t *counts, size_t k, plateau_result want,
                         const char *words, long index)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error e;
    plateau_result r = plateau_solve_loops(xyz, counts, k, NULL, &mesh, &rep, &e);
    if (!CHECK_EQ_INT(r, want)) fprintf(stderr, "  got %s: %s\n", plateau_result_string(r), e.message);
    CHECK_EQ_INT(e.code, want);
    if (!CHECK(strstr(e.message, words) != NULL)) fprintf(stderr, "  message: %s\n", e.message);
    if (index != -2) CHECK_EQ_INT(e.index, index);
    CHECK(mesh.num_vertices == 0 && mesh.positions == NULL);
    CHECK(strncmp(plateau_result_string(r), "unknown", 7) != 0);
}

static void test_bad_input(void)
{
    double xyz[3 * 72], c[3] = {0.0, 0.0, 0.0};
    size_t counts[3] = {24, 24, 24};
    plateau_mesh mesh;
    /* arguments */
    rings(xyz, 24, 1.0);
    CHECK_EQ_INT(plateau_solve_loops(xyz, NULL, 2, NULL, &mesh, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 0, NULL, &mesh, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, NULL, NULL, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_solve_loops(NULL, counts, 2, NULL, &mesh, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    /* each loop as plateau_solve, named */
    counts[1] = 2;
    expect_error(xyz, counts, 2, PLATEAU_ERR_TOO_FEW_VERTICES, "loop 1: ", -2);
    counts[1] = 24;
    xyz[3 * 30] = xyz[3 * 31];
    xyz[3 * 30 + 1] = xyz[3 * 31 + 1];
    expect_error(xyz, counts, 2, PLATEAU_ERR_REPEATED_VERTEX, "loop 1: boundary vertices 6 and 7", 30);
    /* index and index2 in the whole array's numbering */
    expect_error2(xyz, counts, 2, PLATEAU_ERR_REPEATED_VERTEX, "loop 1: boundary vertices 6 and 7", 30, 31);
    rings(xyz, 24, 1.0);
    xyz[3 * 40 + 2] = HUGE_VAL;
    expect_error(xyz, counts, 2, PLATEAU_ERR_NOT_FINITE, "loop 1: boundary vertex 16", 40);
    /* two loops sharing a vertex: the second ring through vertex 6 of the first */
    rings(xyz, 24, 1.0);
    ring(xyz + 72, 24, c, 1.0, EX, EY, 0);
    {
        int i;
        for (i = 0; i < 24; i++) xyz[72 + 3 * i + 2] = 0.3 * sin(TWO_PI * i / 24);
        for (i = 0; i < 24; i++) xyz[3 * i + 2] = -0.5;
        xyz[72 + 3 * 6 + 2] = -0.5; /* vertex 6 of loop 1 on vertex 6 of loop 0 */
    }
    expect_error(xyz, counts, 2, PLATEAU_ERR_LOOPS_SHARE_VERTEX, "vertex 6 of loop 0 and vertex 6 of loop 1", 6);
    expect_error2(xyz, counts, 2, PLATEAU_ERR_LOOPS_SHARE_VERTEX, "vertex 6 of loop 0", 6, 30);
    /* an edge of loop 1 through the middle of edge 0 of loop 0 */
    {
        double mid[3], t = TWO_PI / 24;
        rings(xyz, 24, 1.0);
        mid[0] = 0.5 * (1.0 + cos(t));
        mid[1] = 0.5 * sin(t);
        mid[2] = -0.5;
        counts[1] = 3;
        xyz[72] = mid[0]; xyz[73] = mid[1]; xyz[74] = mid[2] + 0.3;
        xyz[75] = mid[0]; xyz[76] = mid[1]; xyz[77] = mid[2] - 0.3;
        xyz[78] = mid[0] + 0.5; xyz[79] = mid[1]; xyz[80] = mid[2];
        expect_error(xyz, counts, 2, PLATEAU_ERR_LOOPS_INTERSECT, "edge 0 of loop 0 (to vertex 1) and edge 0 of loop 1", 0);
        expect_error2(xyz, counts, 2, PLATEAU_ERR_LOOPS_INTERSECT, "edge 0 of loop 1", 0, 24);
        counts[1] = 24;
    }
    /* a vertex of loop 1 on edge 5 of loop 0 */
    {
        double t0 = TWO_PI * 5 / 24, t1 = TWO_PI * 6 / 24;
        rings(xyz, 24, 1.0);
        counts[1] = 3;
        xyz[72] = 0.5 * (cos(t0) + cos(t1)); xyz[73] = 0.5 * (sin(t0) + sin(t1)); xyz[74] = -0.5;
        xyz[75] = 2.0; xyz[76] = 2.0; xyz[77] = 0.5;
        xyz[78] = 2.5; xyz[79] = 1.0; xyz[80] = 0.0;
        expect_error(xyz, counts, 2, PLATEAU_ERR_LOOPS_INTERSECT, "edge 5 of loop 0 (to vertex 6) and edge 0 of loop 1", 5);
        counts[1] = 24;
    }
    /* two loops side by side in one plane */
    c[0] = -1.5;
    ring(xyz, 24, c, 1.0, EX, EY, 0);
    c[0] = 1.5;
    ring(xyz + 72, 24, c, 1.0, EX, EY, 0);
    expect_error(xyz, counts, 2, PLATEAU_ERR_LOOPS_NESTING, "side by side", -2);
    /* a loop inside a hole, all in one plane */
    c[0] = 0.0;
    ring(xyz, 24, c, 3.0, EX, EY, 0);
    ring(xyz + 72, 24, c, 2.0, EX, EY, 0);
    ring(xyz + 144, 24, c, 1.0, EX, EY, 0);
    expect_error(xyz, counts, 3, PLATEAU_ERR_LOOPS_NESTING, "loop 2 lies inside a hole", 48);
    /* three coaxial rings in space: no plane domain, no annulus */
    c[2] = -1.0;
    ring(xyz, 24, c, 1.0, EX, EY, 0);
    c[2] = 0.0;
    ring(xyz + 72, 24, c, 1.0, EX, EY, 0);
    c[2] = 1.0;
    ring(xyz + 144, 24, c, 1.0, EX, EY, 0);
    expect_error(xyz, counts, 3, PLATEAU_ERR_LOOPS_DOMAIN, "more than two loops", -2);
    (void)EZ;
}

/* Out of memory at every allocation of a multi-loop solve (the annulus,
 * the plane with holes, the pinch and its probe): PLATEAU_ERR_OUT_OF_MEMORY,
 * nothing leaked, no foreign free.  A sweep refuses each allocation of
 * the full solve once, so its cost grows with the square of the solve's
 * allocations: the four cases run without the stability report and the
 * discs alternative (which roughly double a solve's allocations), and a
 * fifth, the pinch probe with both ON, fails theirs.  Together the five
 * reach every allocation call path (three frames deep) the four with both
 * ON reach (counted with tests/alloc_sites.sh). */
static void test_alloc_fail(void)
{
    double xyz[3 * 24], c[3] = {0.0, 0.0, 0.0};
    size_t counts[2] = {8, 8};
    int cas;
    for (cas = 0; cas < 5; cas++) {
        plateau_options o;
        long total = 0, k, bad = 0, leaked = 0, wrong = 0;
        memset(&o, 0, sizeof o);
        o.interior_points = 10;
        o.stability = cas == 4 ? PLATEAU_ON : PLATEAU_OFF;
        o.alternatives = cas == 4 ? PLATEAU_ON : PLATEAU_OFF;
        if (cas == 0) rings(xyz, 8, 0.8);                   /* annulus, paper (presolve) */
        if (cas == 1 || cas == 4) { rings(xyz, 8, 1.6); o.method = PLATEAU_METHOD_PAPER_LITERAL; } /* pinch probe */
        if (cas == 2) { rings(xyz, 8, 1.6); o.method = PLATEAU_METHOD_AREA; }
        if (cas == 3) {                                     /* plane with a hole */
            ring(xyz, 8, c, 2.0, EX, EY, 0);
            ring(xyz + 24, 8, c, 0.5, EX, EY, 1);
        }
        /* make test-full refuses each allocation; make test every third */
        for (k = 0; k <= total; k += (k == 0 || HARNESS_FULL) ? 1 : 3) {
            countalloc ca;
            plateau_mesh mesh;
            plateau_result r;
            plateau_report rep;
            countalloc_init(&ca, k);
            o.allocator = countalloc_allocator(&ca);
            r = plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL);
            plateau_mesh_free(&mesh);
            if (k == 0) {
                CHECK_EQ_INT(r, PLATEAU_OK);
                /* the report and the alternative ran exactly in case 4 */
                CHECK_EQ_INT(rep.stability.computed != 0, cas == 4);
                CHECK_EQ_INT(rep.alternative_area > 0.0, cas == 4);
                total = ca.calls;
            } else {
                wrong += r != PLATEAU_ERR_OUT_OF_MEMORY;
            }
            leaked += ca.live != 0;
            bad += ca.bad != 0;
        }
        CHECK_EQ_INT(wrong, 0);
        CHECK_EQ_INT(leaked, 0);
        CHECK_EQ_INT(bad, 0);
        printf("  out of memory at %s of %ld allocations (case %d): handled\n",
               HARNESS_FULL ? "each" : "every third", total, cas);
    }
}

int main(void)
{
    RUN(test_one_loop_same);
    RUN(test_catenoid);
    RUN(test_header_example);
    RUN(test_orientation);
    RUN(test_pinch);
    RUN(test_shapes);
    RUN(test_bad_input);
    RUN(test_alloc_fail);
    return harness_report("test_solve_loops");
}
