/* test_boundary_domain_seeds.c - steps 1-3 of the pipeline: boundary validation, the
 * parameter domain, candidate points, and the seeded generator. */
#define PLATEAU_IMPLEMENTATION
/* every quality-seeded solve here carries its points to 3-D by the
 * harmonic map (plateau.h uses it only for many boundary vertices) */
#define PLATEAU__CDT_MVC_WORK 0.0
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

#define PI 3.14159265358979323846

/* A helicoid patch boundary r(u, v) = (u cos v, u sin v, b v) over
 * u in [u0, u1], v in [v0, v1], walked counter-clockwise in (u, v) with k
 * segments per side: 4k vertices. */
static size_t helicoid_boundary(double *xyz, int k, double b, double u0, double u1, double v0,
                                double v1)
{
    size_t n = 0;
    int side, i;
    for (side = 0; side < 4; side++) {
        for (i = 0; i < k; i++) {
            double t = (double)i / k, u, v;
            switch (side) {
            case 0: u = u0 + t * (u1 - u0); v = v0; break;
            case 1: u = u1; v = v0 + t * (v1 - v0); break;
            case 2: u = u1 - t * (u1 - u0); v = v1; break;
            default: u = u0; v = v1 - t * (v1 - v0); break;
            }
            xyz[3 * n] = u * cos(v);
            xyz[3 * n + 1] = u * sin(v);
            xyz[3 * n + 2] = b * v;
            n++;
        }
    }
    return n;
}

static double signed_area(const double *uv, size_t m)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        s += uv[2 * i] * uv[2 * j + 1] - uv[2 * j] * uv[2 * i + 1];
    }
    return 0.5 * s;
}

/* ---------------------------------------------------------------- step 1 */
static void test_check_errors(void)
{
    double tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    double bad[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    double line[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    plateau_error err;
    CHECK_EQ_INT(plateau_boundary_check(tri, 3, &err), PLATEAU_OK);
    CHECK_EQ_INT(err.code, PLATEAU_OK);
    CHECK_EQ_INT(err.index, -1);
    CHECK_EQ_INT(plateau_boundary_check(tri, 3, NULL), PLATEAU_OK);

    CHECK_EQ_INT(plateau_boundary_check(NULL, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_boundary_check(tri, 2, &err), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_boundary_check(tri, 0, &err), PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_boundary_check(NULL, 0, &err), PLATEAU_ERR_TOO_FEW_VERTICES);

    bad[7] = NAN;
    CHECK_EQ_INT(plateau_boundary_check(bad, 4, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 2);
    CHECK_EQ_INT(err.index2, -1); /* one vertex named */
    CHECK(strstr(err.message, "2") != NULL);
    bad[7] = 1.0;
    bad[11] = -INFINITY;
    CHECK_EQ_INT(plateau_boundary_check(bad, 4, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 3);
    bad[11] = 0.0;

    /* vertices 1 and 2 equal */
    bad[6] = 1.0; bad[7] = 0.0;
    CHECK_EQ_INT(plateau_boundary_check(bad, 4, &err), PLATEAU_ERR_REPEATED_VERTEX);
    CHECK_EQ_INT(err.index, 1);
    CHECK_EQ_INT(err.index2, 2);
    CHECK(strcmp(err.message, "boundary vertices 1 and 2 are equal") == 0);
    bad[6] = 1.0; bad[7] = 1.0;
    /* last equals first: the closing pair (3, 0) */
    bad[9] = 0.0; bad[10] = 0.0; bad[11] = 0.0;
    CHECK_EQ_INT(plateau_boundary_check(bad, 4, &err), PLATEAU_ERR_REPEATED_VERTEX);
    CHECK_EQ_INT(err.index, 3);
    CHECK_EQ_INT(err.index2, 0);
    CHECK(strcmp(err.message, "boundary vertices 3 and 0 are equal") == 0);
    bad[10] = 1.0;
    CHECK_EQ_INT(plateau_boundary_check(bad, 4, &err), PLATEAU_OK);

    CHECK_EQ_INT(plateau_boundary_check(line, 4, &err), PLATEAU_ERR_COLLINEAR);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_COLLINEAR);
    /* scale-aware: a tiny but genuine triangle is fine, at any scale... */
    {
        double small[9] = {0, 0, 0, 1e-200, 0, 0, 0, 1e-200, 0};
        double large[9] = {0, 0, 0, 1e200, 0, 0, 0, 1e200, 0};
        double nearly[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
        CHECK_EQ_INT(plateau_boundary_check(small, 3, &err), PLATEAU_OK);
        CHECK_EQ_INT(plateau_boundary_check(large, 3, &err), PLATEAU_OK);
        /* ...while a rounding-level wiggle off a line is still collinear */
        nearly[4] += 1e-15;
        CHECK_EQ_INT(plateau_boundary_check(nearly, 4, &err), PLATEAU_ERR_COLLINEAR);
        nearly[4] += 1e-3;
        /* not collinear any more, but out along a line and back: vertex 2
         * lies on the closing edge from vertex 3 to vertex 0 */
        CHECK_EQ_INT(plateau_boundary_check(nearly, 4, &err), PLATEAU_ERR_VERTEX_ON_EDGE);
        CHECK_EQ_INT(err.index, 2);
    }
    CHECK(strcmp(plateau_result_string(PLATEAU_ERR_COLLINEAR), "all polygon vertices are collinear") == 0);
}

/* ---------------------------------------------------------------- step 2 */
static void test_domain_plane_square(void)
{
    /* a tilted square, clockwise when seen from +z */
    double xyz[12] = {0, 0, 0, 0, 1, 0.5, 1, 1, 1, 1, 0, 0.5};
    double uv[8];
    plateau_domain_kind kind = PLATEAU_DOMAIN_CIRCLE;
    plateau_error err;
    size_t i, j;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 0, NULL, uv, &kind, &err), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
    CHECK(signed_area(uv, 4) > 0.0);
    /* a projection onto the polygon's own plane keeps every distance */
    for (i = 0; i < 4; i++) {
        for (j = i + 1; j < 4; j++) {
            double d3 = 0.0, d2;
            int k;
            for (k = 0; k < 3; k++) d3 += (xyz[3 * i + k] - xyz[3 * j + k]) * (xyz[3 * i + k] - xyz[3 * j + k]);
            d2 = (uv[2 * i] - uv[2 * j]) * (uv[2 * i] - uv[2 * j]) +
                 (uv[2 * i + 1] - uv[2 * j + 1]) * (uv[2 * i + 1] - uv[2 * j + 1]);
            CHECK_NEAR(sqrt(d2), sqrt(d3), 1e-13);
        }
    }
    /* the reversed polygon is counter-clockwise in uv too */
    {
        double rev[12];
        for (i = 0; i < 4; i++)
            for (j = 0; j < 3; j++) rev[3 * i + j] = xyz[3 * (3 - i) + j];
        CHECK_EQ_INT(plateau_boundary_domain(rev, 4, 0, NULL, uv, &kind, &err), PLATEAU_OK);
        CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
        CHECK(signed_area(uv, 4) > 0.0);
    }
    /* force_circle */
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 1, NULL, uv, &kind, &err), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_CIRCLE);
    CHECK(signed_area(uv, 4) > 0.0);
    /* errors of step 1 come through; NULL uv is an argument error */
    xyz[4] = NAN;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 0, NULL, uv, &kind, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 1);
    xyz[4] = 1.0;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 0, NULL, NULL, &kind, &err), PLATEAU_ERR_ARGUMENT);
    {
        plateau_allocator half;
        half.alloc_fn = NULL;
        half.free_fn = NULL;
        half.user_data = NULL;
        CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 0, &half, uv, &kind, &err), PLATEAU_OK);
    }
}

static void test_domain_graph_helicoid(void)
{
    /* the helicoid patch of examples/NOTES.md: a graph-like polygon over its
     * best-fit plane, 28 vertices */
    double xyz[3 * 28], uv[2 * 28];
    plateau_domain_kind kind = PLATEAU_DOMAIN_CIRCLE;
    size_t m = helicoid_boundary(xyz, 7, 1.9, -1.0, 1.0, -PI / 4, PI / 4);
    CHECK_EQ_INT(m, 28);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
    CHECK(signed_area(uv, m) > 0.0);
}

static void test_domain_helicoid_turns(void)
{
    /* one and a half turns: the projection on the best-fit plane crosses
     * itself, so the circle is used; the uv polygon is the chord-length
     * circle, counter-clockwise */
    double xyz[3 * 160], uv[2 * 160], per = 0.0, s = 0.0;
    plateau_domain_kind kind = PLATEAU_DOMAIN_PLANE;
    size_t m = helicoid_boundary(xyz, 40, 0.3, 0.4, 1.0, 0.0, 3.0 * PI), i;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_CIRCLE);
    CHECK(signed_area(uv, m) > 0.0);
    for (i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        per += sqrt((xyz[3 * j] - xyz[3 * i]) * (xyz[3 * j] - xyz[3 * i]) +
                    (xyz[3 * j + 1] - xyz[3 * i + 1]) * (xyz[3 * j + 1] - xyz[3 * i + 1]) +
                    (xyz[3 * j + 2] - xyz[3 * i + 2]) * (xyz[3 * j + 2] - xyz[3 * i + 2]));
    }
    for (i = 0; i < m; i++) {
        double r = sqrt(uv[2 * i] * uv[2 * i] + uv[2 * i + 1] * uv[2 * i + 1]);
        double ang = atan2(uv[2 * i + 1], uv[2 * i]);
        size_t j = (i + 1) % m;
        if (ang < 0) ang += 2 * PI;
        if (i == 0) ang = 0.0;
        CHECK_NEAR(r, per / (2 * PI), 1e-12 * per);
        CHECK_NEAR(ang, 2 * PI * s / per, 1e-9);
        s += sqrt((xyz[3 * j] - xyz[3 * i]) * (xyz[3 * j] - xyz[3 * i]) +
                  (xyz[3 * j + 1] - xyz[3 * i + 1]) * (xyz[3 * j + 1] - xyz[3 * i + 1]) +
                  (xyz[3 * j + 2] - xyz[3 * i + 2]) * (xyz[3 * j + 2] - xyz[3 * i + 2]));
    }
    /* half a turn is still a graph over its plane */
    m = helicoid_boundary(xyz, 10, 0.3, 0.4, 1.0, 0.0, 0.5 * PI);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
}

static void test_domain_bowtie_and_fold(void)
{
    /* a planar figure eight: crosses itself in its own plane */
    double bow[12] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0};
    /* a polygon folding back on itself along an edge (a spike) */
    double spike[15] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 0.5, 0, 2, 1, 1e-30};
    /* the same, lifted apart in space: valid (their best-fit planes tilt
     * and they project to simple polygons; the circle for projections
     * that cross is tested with the helicoids above) */
    double bow_lifted[12] = {0, 0, 0, 1, 1, 0.2, 1, 0, 0, 0, 1, -0.2};
    double spike_lifted[15] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 0.5, 0, 2, 1, 0.2};
    double uv[10];
    plateau_domain_kind kind = PLATEAU_DOMAIN_PLANE;
    /* in space they touch themselves: no embedded surface, refused */
    CHECK_EQ_INT(plateau_boundary_domain(bow, 4, 0, NULL, uv, &kind, NULL), PLATEAU_ERR_EDGES_INTERSECT);
    CHECK_EQ_INT(plateau_boundary_domain(spike, 5, 0, NULL, uv, &kind, NULL), PLATEAU_ERR_DUPLICATE_VERTEX);
    CHECK_EQ_INT(plateau_boundary_domain(bow_lifted, 4, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_boundary_domain(spike_lifted, 5, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
}

/* ---------------------------------------------------------------- step 3 */
static int in_polygon_strict(const double *uv, size_t m, const double *p)
{
    return plateau_point_in_polygon(uv, m, p, 0.0);
}

static void test_seed_square_counts(void)
{
    double xyz[12] = {0, 0, 0, 1, 0, 0.2, 1, 1, 0, 0, 1, 0.2};
    double uv[8], pts[3 * 200], q[2 * 200];
    size_t count = 0, n, i;
    plateau_error err;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 4, 0, NULL, uv, NULL, NULL), PLATEAU_OK);
    for (n = 0; n <= 200; n += (n < 20 ? 1 : 37)) {
        CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, n, 7, NULL, pts, q, &count, &err), PLATEAU_OK);
        CHECK_EQ_INT(count, n);
        for (i = 0; i < count; i++) CHECK(in_polygon_strict(uv, 4, q + 2 * i));
    }
    /* n = 1: level 0 alone, the centroid */
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, 1, 7, NULL, pts, q, &count, &err), PLATEAU_OK);
    CHECK_EQ_INT(count, 1);
    CHECK_NEAR(pts[0], 0.5, 1e-15);
    CHECK_NEAR(pts[1], 0.5, 1e-15);
    CHECK_NEAR(pts[2], 0.1, 1e-15);
    /* n = 5: the centroid and the closed fan of 4 (all of levels 0 and 1) */
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, 5, 7, NULL, pts, q, &count, &err), PLATEAU_OK);
    CHECK_EQ_INT(count, 5);
    /* fan triangle j = 1 is (V_4, V_1, C): barycentre of (0,1,.2), (0,0,0), C */
    CHECK_NEAR(pts[3], (0.0 + 0.0 + 0.5) / 3, 1e-15);
    CHECK_NEAR(pts[4], (1.0 + 0.0 + 0.5) / 3, 1e-15);
    CHECK_NEAR(pts[5], (0.2 + 0.0 + 0.1) / 3, 1e-15);
    /* argument errors */
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, 5, 7, NULL, NULL, q, &count, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, 5, 7, NULL, pts, q, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 2, 5, 7, NULL, pts, q, &count, &err),
                 PLATEAU_ERR_TOO_FEW_VERTICES);
    CHECK_EQ_INT(plateau_seed_points_rule(xyz, uv, 4, 5, 7, (plateau_seed_rule)9, NULL, pts, q,
                                          &count, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, 4, 0, 7, NULL, NULL, NULL, &count, &err), PLATEAU_OK);
    CHECK_EQ_INT(count, 0);
}

/* Every candidate is one barycentric combination of the boundary vertices,
 * the same in 3-D and in uv: the selection depends on uv only, and the 3-D
 * output is linear in xyz.  So with xyz an affine function of uv the output
 * is that function of the output uv, and outputs add up when inputs do. */
static void test_seed_same_combination(void)
{
    double xyz[3 * 28], uv[2 * 28], lift[3 * 28], sum[3 * 28];
    double p1[3 * 60], q1[2 * 60], p2[3 * 60], q2[2 * 60], p3[3 * 60], q3[2 * 60];
    size_t m = helicoid_boundary(xyz, 7, 1.9, -1.0, 1.0, -PI / 4, PI / 4), i, c1, c2, c3;
    int k;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, NULL, NULL), PLATEAU_OK);
    for (i = 0; i < m; i++) {
        lift[3 * i] = 2.0 * uv[2 * i] - uv[2 * i + 1] + 3.0;
        lift[3 * i + 1] = 0.5 * uv[2 * i + 1] - 1.0;
        lift[3 * i + 2] = uv[2 * i] + uv[2 * i + 1];
        for (k = 0; k < 3; k++) sum[3 * i + k] = xyz[3 * i + k] + lift[3 * i + k];
    }
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 60, 99, NULL, p1, q1, &c1, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_seed_points(lift, uv, m, 60, 99, NULL, p2, q2, &c2, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_seed_points(sum, uv, m, 60, 99, NULL, p3, q3, &c3, NULL), PLATEAU_OK);
    CHECK_EQ_INT(c1, 60);
    CHECK_EQ_INT(c2, 60);
    CHECK_EQ_INT(c3, 60);
    CHECK(memcmp(q1, q2, sizeof q1) == 0);
    CHECK(memcmp(q1, q3, sizeof q1) == 0);
    for (i = 0; i < 60; i++) {
        double u = q2[2 * i], v = q2[2 * i + 1];
        CHECK_NEAR(p2[3 * i], 2.0 * u - v + 3.0, 1e-13);
        CHECK_NEAR(p2[3 * i + 1], 0.5 * v - 1.0, 1e-13);
        CHECK_NEAR(p2[3 * i + 2], u + v, 1e-13);
        for (k = 0; k < 3; k++) CHECK_NEAR(p3[3 * i + k], p1[3 * i + k] + p2[3 * i + k], 1e-13);
        CHECK(in_polygon_strict(uv, m, q1 + 2 * i));
    }
}

static void test_seed_determinism(void)
{
    double xyz[3 * 28], uv[2 * 28];
    double a[3 * 50], qa[2 * 50], b[3 * 50], qb[2 * 50];
    size_t m = helicoid_boundary(xyz, 7, 1.9, -1.0, 1.0, -PI / 4, PI / 4), ca, cb;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, NULL, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 50, 12345, NULL, a, qa, &ca, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 50, 12345, NULL, b, qb, &cb, NULL), PLATEAU_OK);
    CHECK_EQ_INT(ca, 50);
    CHECK_EQ_INT(cb, 50);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK(memcmp(qa, qb, sizeof qa) == 0);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 50, 12346, NULL, b, qb, &cb, NULL), PLATEAU_OK);
    CHECK(memcmp(a, b, sizeof a) != 0);
    /* the literal rule does not use the seed */
    CHECK_EQ_INT(plateau_seed_points_rule(xyz, uv, m, 50, 1, PLATEAU_SEED_LITERAL, NULL, a, qa, &ca, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_seed_points_rule(xyz, uv, m, 50, 2, PLATEAU_SEED_LITERAL, NULL, b, qb, &cb, NULL), PLATEAU_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    /* pinned: point 37 of the default rule with seed 12345 (a regression
     * check of the generator, the level order and the draw) */
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 50, 12345, NULL, a, qa, &ca, NULL), PLATEAU_OK);
    CHECK_NEAR(a[3 * 37], 0.30304576336566325, 1e-12);
    CHECK_NEAR(a[3 * 37 + 1], 0.30304576336566319, 1e-12);
    CHECK_NEAR(a[3 * 37 + 2], 0.82903139469730647, 1e-12);
    /* the domain's u axis has the sign of plateau__dom_canonical_axis (the
     * first vertex with |u| at least half the largest gets u > 0) */
    CHECK_NEAR(qa[2 * 37], -0.82903139469730647, 1e-12);
    CHECK_NEAR(qa[2 * 37 + 1], 0.30304576336566325, 1e-12);
}

/* An L-shaped and a star-shaped domain: the centroid of the L lies outside;
 * candidates outside are skipped and every output point is inside. */
static void test_seed_nonconvex(void)
{
    double L[18] = {0, 0, 0, 2, 0, 0, 2, 0.2, 0, 0.2, 0.2, 0, 0.2, 2, 0, 0, 2, 0};
    double uv[2 * 20], pts[3 * 300], q[2 * 300], star[3 * 20];
    size_t count, i, rule;
    plateau_domain_kind kind;
    /* the centroid of the L is (0.7, 0.7), outside it */
    CHECK_EQ_INT(plateau_boundary_domain(L, 6, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
    for (rule = 0; rule < 3; rule++) {
        CHECK_EQ_INT(plateau_seed_points_rule(L, uv, 6, 300, 3, (plateau_seed_rule)rule, NULL, pts, q,
                                              &count, NULL), PLATEAU_OK);
        CHECK_EQ_INT(count, 300);
        for (i = 0; i < count; i++) {
            CHECK(in_polygon_strict(uv, 6, q + 2 * i));
            CHECK(pts[3 * i] > 0.0 && pts[3 * i + 1] > 0.0);
            CHECK(pts[3 * i] < 0.2 || pts[3 * i + 1] < 0.2);
        }
    }
    /* n = 1 in the L: the centroid is skipped, a fan barycentre comes */
    CHECK_EQ_INT(plateau_seed_points(L, uv, 6, 1, 3, NULL, pts, q, &count, NULL), PLATEAU_OK);
    CHECK_EQ_INT(count, 1);
    CHECK(pts[0] < 0.2 || pts[1] < 0.2);
    /* a ten-pointed star */
    for (i = 0; i < 20; i++) {
        double r = (i % 2) ? 0.3 : 1.0, a = 2 * PI * (double)i / 20;
        star[3 * i] = r * cos(a);
        star[3 * i + 1] = r * sin(a);
        star[3 * i + 2] = 0.1 * r;
    }
    CHECK_EQ_INT(plateau_boundary_domain(star, 20, 0, NULL, uv, &kind, NULL), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
    CHECK_EQ_INT(plateau_seed_points(star, uv, 20, 150, 5, NULL, pts, q, &count, NULL), PLATEAU_OK);
    CHECK_EQ_INT(count, 150);
    for (i = 0; i < count; i++) CHECK(in_polygon_strict(uv, 20, q + 2 * i));
}

/* A sliver: inside candidates are rare, the levels are bounded, and the
 * call says how many it found. */
static void test_seed_thin(void)
{
    /* a C-shaped polygon (a thin arc) whose fan covers mostly outside */
    double xyz[3 * 64], uv[2 * 64];
    double *pts = (double *)malloc(3 * 5000 * sizeof(double));
    double *q = (double *)malloc(2 * 5000 * sizeof(double));
    size_t count = 0, i;
    for (i = 0; i < 32; i++) {
        double a = 0.1 + 5.5 * (double)i / 31;
        xyz[3 * i] = cos(a);
        xyz[3 * i + 1] = sin(a);
        xyz[3 * i + 2] = 0.0;
        xyz[3 * (63 - i)] = 0.999 * cos(a);
        xyz[3 * (63 - i) + 1] = 0.999 * sin(a);
        xyz[3 * (63 - i) + 2] = 0.0;
    }
    CHECK_EQ_INT(plateau_boundary_domain(xyz, 64, 0, NULL, uv, NULL, NULL), PLATEAU_OK);
    CHECK(pts != NULL && q != NULL);
    if (pts && q) {
        CHECK_EQ_INT(plateau_seed_points(xyz, uv, 64, 5000, 1, NULL, pts, q, &count, NULL), PLATEAU_OK);
        CHECK(count > 0);
        CHECK(count <= 5000);
        for (i = 0; i < count; i++) CHECK(in_polygon_strict(uv, 64, q + 2 * i));
    }
    free(pts);
    free(q);
}

/* The allocator is used, and nothing is left allocated. */
typedef struct counting { long live, calls; } counting;
static void *count_alloc(size_t size, void *user)
{
    counting *c = (counting *)user;
    c->live++;
    c->calls++;
    return malloc(size);
}
static void count_free(void *ptr, void *user)
{
    ((counting *)user)->live--;
    free(ptr);
}
static void *fail_alloc(size_t size, void *user)
{
    counting *c = (counting *)user;
    if (c->calls-- <= 0) return NULL;
    c->live++;
    return malloc(size);
}

static void test_seed_allocator(void)
{
    double xyz[3 * 28], uv[2 * 28], pts[3 * 100], q[2 * 100];
    size_t m = helicoid_boundary(xyz, 7, 1.9, -1.0, 1.0, -PI / 4, PI / 4), count;
    counting c = {0, 0};
    plateau_allocator a;
    plateau_error err;
    long budget, total;
    a.alloc_fn = count_alloc;
    a.free_fn = count_free;
    a.user_data = &c;
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, &a, uv, NULL, NULL), PLATEAU_OK);
    CHECK_EQ_INT(c.live, 0);
    c.calls = 0; /* count the seeding's allocations alone */
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 100, 4, &a, pts, q, &count, NULL), PLATEAU_OK);
    CHECK(c.calls > 0);
    CHECK_EQ_INT(c.live, 0);
    total = c.calls;
    /* every allocation failing in turn: OUT_OF_MEMORY and nothing leaked */
    a.alloc_fn = fail_alloc;
    for (budget = 0; budget < total; budget++) {
        c.calls = budget;
        c.live = 0;
        CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 100, 4, &a, pts, q, &count, &err),
                     PLATEAU_ERR_OUT_OF_MEMORY);
        CHECK_EQ_INT(err.code, PLATEAU_ERR_OUT_OF_MEMORY);
        CHECK_EQ_INT(c.live, 0);
    }
    a.alloc_fn = count_alloc;
    a.free_fn = NULL;
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 100, 4, &a, pts, q, &count, NULL), PLATEAU_ERR_ARGUMENT);
}

/* ---------------------------------------------------------------- rng */
/* Polygons for the grids' tests, in the plane: a densely sampled smooth
 * closed curve (the projection of (cos t, sin t, 0.3 cos 3t)), a star
 * with long spikes, and a comb of long thin teeth (many long edges close
 * together, the grids' worst shape). */
static size_t grid_polygon(int kind, size_t m, double *uv)
{
    size_t i, n = 0;
    if (kind == 0) {
        for (i = 0; i < m; i++) {
            double t = 2 * PI * (double)i / (double)m;
            uv[2 * n] = cos(t);
            uv[2 * n + 1] = sin(t);
            n++;
        }
    } else if (kind == 1) {
        for (i = 0; i < m; i++) {
            double t = 2 * PI * (double)i / (double)m, r = i % 2 ? 0.15 : 1.0;
            uv[2 * n] = r * cos(t);
            uv[2 * n + 1] = r * sin(t);
            n++;
        }
    } else {
        size_t teeth = m / 4;
        for (i = 0; i < teeth; i++) { /* up and down each tooth, left to right */
            double x = (double)i / (double)teeth, w = 0.4 / (double)teeth;
            uv[2 * n] = x; uv[2 * n + 1] = 0.0; n++;
            uv[2 * n] = x; uv[2 * n + 1] = 1.0; n++;
            uv[2 * n] = x + w; uv[2 * n + 1] = 1.0; n++;
            uv[2 * n] = x + w; uv[2 * n + 1] = 0.0; n++;
        }
        uv[2 * n] = 1.0; uv[2 * n + 1] = -0.5; n++;
        uv[2 * n] = 0.0; uv[2 * n + 1] = -0.5; n++;
    }
    return n;
}

/* The candidates' inside test by the edge grid gives plateau_point_in_polygon's
 * answer exactly: random points, the vertices, edge midpoints, points a
 * hair off an edge, and points outside, with margin 0 and the seeding's
 * 1e-9 of the size. */
static void test_edge_grid_inside_matches_scan(void)
{
    static const size_t sizes[3] = {2000, 301, 400};
    int kind;
    for (kind = 0; kind < 3; kind++) {
        double *uv = (double *)malloc(2 * 2000 * sizeof(double)), margin;
        size_t m = grid_polygon(kind, sizes[kind], uv), i, differ = 0, inside = 0, tried = 0;
        plateau__seed_egrid g;
        plateau_rng rng;
        int k;
        CHECK(plateau__seed_egrid_build(&g, uv, m, NULL, NULL, (double)m, NULL) == PLATEAU_OK);
        margin = 1e-9 * sqrt(plateau__util_diag2(uv, m));
        CHECK(margin < 0.25 * g.h);
        plateau_rng_seed(&rng, 7);
        for (i = 0; i < 20000; i++) {
            double p[2];
            size_t e = i % m, f = (e + 1) % m;
            switch (i % 4) {
            case 0: p[0] = -1.2 + 2.4 * plateau_rng_uniform(&rng); p[1] = -1.2 + 2.4 * plateau_rng_uniform(&rng); break;
            case 1: p[0] = uv[2 * e]; p[1] = uv[2 * e + 1]; break;
            case 2: p[0] = 0.5 * (uv[2 * e] + uv[2 * f]); p[1] = 0.5 * (uv[2 * e + 1] + uv[2 * f + 1]); break;
            default: p[0] = 0.5 * (uv[2 * e] + uv[2 * f]) + 1e-9 * (plateau_rng_uniform(&rng) - 0.5);
                     p[1] = 0.5 * (uv[2 * e + 1] + uv[2 * f + 1]) + 1e-9 * (plateau_rng_uniform(&rng) - 0.5);
            }
            for (k = 0; k < 2; k++) {
                double mg = k ? margin : 0.0;
                int a = plateau__seed_egrid_inside(&g, p, mg), b = plateau_point_in_polygon(uv, m, p, mg);
                differ += a != b;
                inside += b;
                tried++;
            }
        }
        CHECK_EQ_INT(differ, 0);
        CHECK(inside > tried / 10); /* the sample reaches both answers */
        plateau__seed_egrid_free(&g, NULL);
        free(uv);
    }
}

/* The graded size limit of the quality seeding, as its definition says:
 * the scan over all edges. */
static double graded_by_scan(const plateau__seed_quality *q, double x, double y)
{
    double p[2], h = 0.0, a;
    size_t e;
    p[0] = x;
    p[1] = y;
    for (e = 0; e < q->m; e++) {
        const double *a0 = q->uv + 2 * e, *b0 = q->uv + 2 * ((e + 1) % q->m);
        double dx = b0[0] - a0[0], dy = b0[1] - a0[1];
        double v = sqrt(dx * dx + dy * dy) - q->grading * sqrt(plateau__util_seg_dist2(p, a0, b0));
        if (v > h) h = v;
    }
    a = 0.4330127018922193 * h * h;
    return a > q->amax ? a : q->amax;
}

/* The graded-size query by its grid: the scan's value bit for bit at
 * random points of the domain, for every slope the refinement tries and
 * interior sizes from coarse to fine, and its work per call (entries
 * read, counted by the structure) bounded independently of m: on the
 * dense curve of 2 000 and 20 000 vertices at most 4 squares and entries
 * per call whatever the size; on the star (many long edges meeting near
 * one point, all equally far from its centre) and the comb at most 32 on
 * average, where the scan reads all m. */
static void test_graded_size_query_bounded_work(void)
{
    static const double slopes[4] = {0.5, 2.0, 8.0, 32.0};
    static const size_t sizes[4] = {2000, 20000, 301, 400};
    static const int kinds[4] = {0, 0, 1, 2};
    int c, s, f;
    for (c = 0; c < 4; c++) {
        double *uv = (double *)malloc(2 * 20000 * sizeof(double));
        size_t m = grid_polygon(kinds[c], sizes[c], uv), i, differ = 0, worst = 0, total = 0;
        size_t npts = m > 5000 ? 200 : 2000; /* the scan it is compared with costs m */
        double area = fabs(signed_area(uv, m)), hi[2] = {uv[0], uv[1]};
        for (i = 1; i < m; i++) {
            hi[0] = uv[2 * i] > hi[0] ? uv[2 * i] : hi[0];
            hi[1] = uv[2 * i + 1] > hi[1] ? uv[2 * i + 1] : hi[1];
        }
        for (s = 0; s < 4; s++)
            for (f = 0; f < 3; f++) {
                /* the area limit of n = m / 10, m and 10 m interior points */
                double n = (double)m * (f == 0 ? 0.1 : f == 1 ? 1.0 : 10.0);
                plateau__seed_quality q;
                plateau__seed_graded gr;
                plateau_rng rng;
                memset(&q, 0, sizeof q);
                q.uv = uv;
                q.m = m;
                q.grading = slopes[s];
                q.amax = 2.0 * area / (2.0 * n + (double)m);
                CHECK(plateau__seed_graded_build(&gr, &q) == PLATEAU_OK);
                plateau_rng_seed(&rng, (uint64_t)(100 * c + 10 * s + f));
                for (i = 0; i < npts; i++) {
                    size_t e = i % m, before = gr.visits;
                    double x, y;
                    if (i % 2) {
                        x = gr.x0 + (hi[0] - gr.x0) * plateau_rng_uniform(&rng);
                        y = gr.y0 + (hi[1] - gr.y0) * plateau_rng_uniform(&rng);
                    } else { /* near an edge, where the long edges matter */
                        double t = plateau_rng_uniform(&rng);
                        x = uv[2 * e] + t * (uv[2 * ((e + 1) % m)] - uv[2 * e]) + 0.01 * (plateau_rng_uniform(&rng) - 0.5);
                        y = uv[2 * e + 1] + t * (uv[2 * ((e + 1) % m) + 1] - uv[2 * e + 1]) + 0.01 * (plateau_rng_uniform(&rng) - 0.5);
                        /* in the polygon's box, as every point the refinement asks about */
                        x = x < gr.x0 ? gr.x0 : x > hi[0] ? hi[0] : x;
                        y = y < gr.y0 ? gr.y0 : y > hi[1] ? hi[1] : y;
                    }
                    differ += plateau__seed_graded_area(x, y, &gr) != graded_by_scan(&q, x, y);
                    if (gr.visits - before > worst) worst = gr.visits - before;
                    total += gr.visits - before;
                }
                CHECK_EQ_INT(gr.calls, npts);
                plateau__seed_graded_free(&gr);
            }
        CHECK_EQ_INT(differ, 0);
        if (kinds[c] == 0) CHECK(worst <= 4);
        else CHECK(total <= 32 * 12 * npts); /* the mean per call */
        printf("  graded query, polygon %d (m = %lu): %.2f squares and entries per call, at most %lu\n",
               kinds[c], (unsigned long)m, (double)total / (12.0 * (double)npts), (unsigned long)worst);
        free(uv);
    }
}

/* The harmonic map that carries the quality seeding's points to 3-D when
 * m times the points is large: it reproduces linear functions of the
 * domain exactly (a tilted plane: every point on the plane, over its
 * domain point), and through plateau_solve a tilted flat polygon keeps the
 * refinement's angles in 3-D and ends valid with the plane's area. */
static void test_harmonic_placement(void)
{
    double xyz[3 * 40], uv[2 * 40];
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    size_t i;
    double worst = 0.0, area = 0.0;
    for (i = 0; i < 40; i++) { /* a star-shaped flat polygon in the plane z = 0.3 x - 0.2 y + 1 */
        double t = 2 * PI * (double)i / 40, r = 1.0 + 0.3 * cos(5 * t);
        xyz[3 * i] = r * cos(t);
        xyz[3 * i + 1] = r * sin(t);
        xyz[3 * i + 2] = 0.3 * xyz[3 * i] - 0.2 * xyz[3 * i + 1] + 1.0;
        uv[2 * i] = xyz[3 * i];
        uv[2 * i + 1] = xyz[3 * i + 1];
    }
    for (i = 0; i < 40; i++) {
        size_t j = (i + 1) % 40;
        area += 0.5 * (uv[2 * i] * uv[2 * j + 1] - uv[2 * j] * uv[2 * i + 1]);
    }
    area *= sqrt(1.0 + 0.09 + 0.04); /* the plane's slope */
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 150;
    opt.max_rounds = 1;
    CHECK_EQ_INT(plateau_solve(xyz, 40, &opt, &mesh, &rep, &err), PLATEAU_OK);
    CHECK(rep.seeded_points > 100);
    /* to 1e-7 degrees: the domain and the frame are each rounded to 2^-36 */
    CHECK_NEAR(rep.initial_min_angle_deg, rep.domain_min_angle_deg, 1e-7);
    CHECK_NEAR(rep.area, area, 1e-12 * area);
    CHECK_EQ_INT(rep.defects, 0);
    for (i = 40; i < mesh.num_vertices; i++) {
        const double *p = mesh.positions + 3 * i;
        double d = fabs(p[2] - (0.3 * p[0] - 0.2 * p[1] + 1.0));
        if (d > worst) worst = d;
    }
    CHECK(worst < 1e-13);
    plateau_mesh_free(&mesh);
}

/* The harmonic map on the graded mesh of a dense boundary: the circle
 * domain of the curve (cos t, sin t, 0.3 cos 3t) with m vertices, refined
 * to 26 degrees with the polygon kept (the triangles grow from the
 * boundary spacing inwards).  The map reproduces x = u and y = v exactly
 * (linear precision), z obeys the maximum principle, and the call's own
 * memory (a counting allocator's peak above what was live before it)
 * stays linear in the free vertices: its Cholesky is ordered by the
 * domain points (ordered by the not yet placed positions, all at the
 * origin, the bisection fell back to breadth-first levels that run along
 * the whole boundary band: 2122 bytes per free vertex at m = 4000 against
 * 606, and gigabytes at m = 10^5). */
static void test_harmonic_placement_dense_boundary(void)
{
    const size_t m = 4000;
    double *uv = (double *)malloc(2 * m * sizeof(double)), *pos = NULL, worst = 0.0, zlo = 1e300, zhi = -1e300;
    plateau_index *seg = (plateau_index *)malloc(2 * m * sizeof(plateau_index));
    unsigned char *fixed = NULL;
    plateau_dt_input in;
    plateau_dt_options dopt;
    plateau_dt_mesh dt;
    plateau_mesh mesh;
    plateau_error err;
    countalloc ca;
    size_t i, nfree, live0;
    if (!CHECK(uv && seg)) return;
    for (i = 0; i < m; i++) {
        double t = 2 * PI * (double)i / (double)m;
        uv[2 * i] = cos(t);
        uv[2 * i + 1] = sin(t);
        seg[2 * i] = (plateau_index)i;
        seg[2 * i + 1] = (plateau_index)((i + 1) % m);
    }
    memset(&in, 0, sizeof in);
    memset(&dopt, 0, sizeof dopt);
    in.points = uv;
    in.num_points = m;
    in.segments = seg;
    in.num_segments = m;
    dopt.min_angle = 26.0;
    dopt.keep_segments = 1;
    if (!CHECK_EQ_INT(plateau_dt_triangulate(&in, &dopt, &dt, NULL), PLATEAU_DT_OK)) return;
    pos = (double *)calloc(3 * dt.num_points, sizeof(double));
    fixed = (unsigned char *)calloc(dt.num_points, 1);
    if (!CHECK(pos && fixed)) return;
    for (i = 0; i < m; i++) {
        pos[3 * i] = uv[2 * i];
        pos[3 * i + 1] = uv[2 * i + 1];
        pos[3 * i + 2] = 0.3 * cos(3.0 * 2 * PI * (double)i / (double)m);
        fixed[i] = 1;
        if (pos[3 * i + 2] < zlo) zlo = pos[3 * i + 2];
        if (pos[3 * i + 2] > zhi) zhi = pos[3 * i + 2];
    }
    nfree = dt.num_points - m;
    CHECK(nfree > m); /* graded: more interior points than boundary ones */
    countalloc_init(&ca, 0);
    if (!CHECK_EQ_INT(plateau_mesh_create(pos, dt.num_points, fixed, dt.triangles, dt.num_triangles,
                                          NULL, &mesh, &err), PLATEAU_OK))
        return;
    mesh.allocator = countalloc_allocator(&ca);
    live0 = ca.bytes_live;
    CHECK_EQ_INT(plateau__solve_harmonic_place(&mesh, dt.points, &err), PLATEAU_OK);
    CHECK_EQ_INT(ca.live, 0);
    for (i = m; i < dt.num_points; i++) {
        const double *p = mesh.positions + 3 * i;
        double d = fabs(p[0] - dt.points[2 * i]) + fabs(p[1] - dt.points[2 * i + 1]);
        if (d > worst) worst = d;
        CHECK(p[2] >= zlo - 1e-12 && p[2] <= zhi + 1e-12);
    }
    CHECK(worst < 1e-12);
    CHECK((double)(ca.bytes_peak - live0) <= 1000.0 * (double)nfree);
    printf("  harmonic placement, m = %lu: %lu free vertices, %.0f bytes per free vertex, "
           "largest |x - u| + |y - v| %.1e\n", (unsigned long)m, (unsigned long)nfree,
           (double)(ca.bytes_peak - live0) / (double)nfree, worst);
    mesh.allocator.alloc_fn = NULL; /* freed by the default allocator that made it */
    mesh.allocator.free_fn = NULL;
    mesh.allocator.user_data = NULL;
    plateau_mesh_free(&mesh);
    plateau_dt_free(&dt);
    free(pos);
    free(fixed);
    free(uv);
    free(seg);
}

static void test_rng(void)
{
    plateau_rng a, b;
    uint64_t first[8];
    int i, differ = 0;
    double lo = 1.0, hi = 0.0, mean = 0.0;
    plateau_rng_seed(&a, 0);
    /* splitmix64's published first outputs for seed 0 */
    CHECK(plateau_rng_next(&a) == (uint64_t)0xE220A8397B1DCDAFull);
    CHECK(plateau_rng_next(&a) == (uint64_t)0x6E789E6AA1B965F4ull);
    plateau_rng_seed(&a, 42);
    plateau_rng_seed(&b, 42);
    for (i = 0; i < 8; i++) first[i] = plateau_rng_next(&a);
    for (i = 0; i < 8; i++) CHECK(plateau_rng_next(&b) == first[i]);
    plateau_rng_seed(&b, 43);
    for (i = 0; i < 8; i++) differ += plateau_rng_next(&b) != first[i];
    CHECK_EQ_INT(differ, 8);
    /* a NULL generator is refused quietly, like plateau_rng_seed(NULL) */
    plateau_rng_seed(NULL, 1);
    CHECK(plateau_rng_next(NULL) == 0);
    CHECK(plateau_rng_uniform(NULL) == 0.0);
    for (i = 0; i < 100000; i++) {
        double u = plateau_rng_uniform(&a);
        if (u < lo) lo = u;
        if (u > hi) hi = u;
        mean += u;
    }
    CHECK(lo >= 0.0 && lo < 1e-3);
    CHECK(hi < 1.0 && hi > 1.0 - 1e-3);
    CHECK_NEAR(mean / 100000, 0.5, 5e-3);
}

int main(void)
{
    RUN(test_check_errors);
    RUN(test_domain_plane_square);
    RUN(test_domain_graph_helicoid);
    RUN(test_domain_helicoid_turns);
    RUN(test_domain_bowtie_and_fold);
    RUN(test_seed_square_counts);
    RUN(test_seed_same_combination);
    RUN(test_seed_determinism);
    RUN(test_seed_nonconvex);
    RUN(test_seed_thin);
    RUN(test_seed_allocator);
    RUN(test_rng);
    RUN(test_edge_grid_inside_matches_scan);
    RUN(test_graded_size_query_bounded_work);
    RUN(test_harmonic_placement);
    RUN(test_harmonic_placement_dense_boundary);
    return harness_report("test_boundary_domain_seeds");
}
