/* test_regressions.c - inputs that broke a header, found by the fuzz targets
 * (tests/fuzz/) or by the reliability tests, kept inline and named after
 * what broke. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

/* Triangulates the points (hull kept) and counts the input points reported
 * as duplicates of a point with other coordinates.  Also checks the basic
 * contract: indices in range, neighbours mutual, nothing leaked. */
static long false_duplicates(const double *pts, size_t np, size_t *ntri)
{
    countalloc ca;
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    long wrong = 0;
    size_t i, t;
    countalloc_init(&ca, 0);
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    opt.allocator = countalloc_allocator(&ca);
    in.points = pts;
    in.num_points = np;
    in.segments = NULL;
    in.num_segments = 0;
    *ntri = 0;
    if (!CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, NULL), PLATEAU_DT_OK)) return -1;
    for (i = 0; i < np; i++) {
        plateau_index d = mesh.duplicate_of[i];
        if (d < 0 || (size_t)d >= np || pts[2 * d] != pts[2 * i] ||
            pts[2 * d + 1] != pts[2 * i + 1]) {
            wrong++;
            printf("  point %lu (%g, %g) reported as a duplicate of point %ld\n",
                   (unsigned long)i, pts[2 * i], pts[2 * i + 1], (long)d);
        }
    }
    for (t = 0; t < 3 * mesh.num_triangles; t++) {
        CHECK(mesh.triangles[t] >= 0 && (size_t)mesh.triangles[t] < mesh.num_points);
        CHECK(mesh.neighbors[t] >= -1 && mesh.neighbors[t] < (plateau_index)mesh.num_triangles);
    }
    *ntri = mesh.num_triangles;
    plateau_dt_free(&mesh);
    CHECK_EQ_INT(ca.live, 0);
    return wrong;
}

/* fuzz_delaunay, raw-double mode: four points inside the documented range
 * 1e-150 .. 1e150 (0, 6.6e-136, -1.2e139, 2.8e-125, 5.7e-106): distinct
 * points came back as duplicates of each other. */
static void test_dt_mixed_magnitudes_merged_as_duplicates(void)
{
    static const double pts[] = {0.0, 0.0, 0x1.ec7ff00000000p-450, 0.0,
                                 -0x1.00005fb050a00p+462, 0x1.9e9f5fe020204p-446,
                                 0x1.3030004070706p-414, 0x1.5007e37e43c88p-350};
    size_t ntri;
    long wrong = false_duplicates(pts, 4, &ntri);
    /* fixed in 4d58443 (each predicate rescales its coordinate differences) */
    CHECK_EQ_INT(wrong, 0);
    CHECK_EQ_INT(ntri, 2);
}

/* test_bad_input.c: a square of side 2e150 around a cluster of four points
 * 1e-150 apart: point (1e-150, 1e-150) came back as a duplicate of (0, 0). */
static void test_dt_huge_square_tiny_cluster_merged(void)
{
    static const double pts[] = {-1e150, -1e150, 1e150, -1e150, 1e150, 1e150, -1e150, 1e150,
                                 0, 0, 1e-150, 0, 0, 1e-150, 1e-150, 1e-150};
    size_t ntri;
    long wrong = false_duplicates(pts, 8, &ntri);
    /* fixed in 4d58443 */
    CHECK_EQ_INT(wrong, 0);
    CHECK_EQ_INT(ntri, 10);
}

/* fuzz_delaunay, raw doubles before they were folded into the documented
 * range: subnormals (2e-323, 5.6e-309, 1.1e-308) and 1e293 in one input.
 * Outside 1e-150 .. 1e150, so an error code would be acceptable, but a wrong
 * duplicate map is not.  Step 1's scaling by 2^-774 flushed the subnormals
 * to zero, so distinct points became one; such input is now refused with
 * PLATEAU_DT_ERR_RANGE naming the first point that would lose bits. */
/* Segments lying on the convex hull, with keep_convex_hull and refinement:
 * the hull marking that bounds the refinement overwrote the segments' flag,
 * so a square with its four sides as segments came back with no constrained
 * edge (4 sides' worth without refinement). */
static void test_dt_hull_segments_lose_flag_when_refined(void)
{
    static const double pts[] = {0, 0, 4, 0, 4, 4, 0, 4, 1.3, 2.1};
    static const plateau_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    int pass;
    for (pass = 0; pass < 2; pass++) {
        plateau_dt_input in;
        plateau_dt_options opt;
        plateau_dt_mesh mesh;
        size_t t, constrained = 0;
        double length = 0.0;
        memset(&in, 0, sizeof in);
        memset(&opt, 0, sizeof opt);
        in.points = pts; in.num_points = 5;
        in.segments = seg; in.num_segments = 4;
        opt.keep_convex_hull = 1;
        if (pass == 1) opt.min_angle = 20.0;
        CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, NULL), PLATEAU_DT_OK);
        for (t = 0; t < 3 * mesh.num_triangles; t++)
            if (mesh.constrained[t]) {
                plateau_index a = mesh.triangles[t];
                plateau_index b = mesh.triangles[t - t % 3 + (t % 3 + 1) % 3];
                double dx = mesh.points[2 * b] - mesh.points[2 * a];
                double dy = mesh.points[2 * b + 1] - mesh.points[2 * a + 1];
                constrained++;
                length += sqrt(dx * dx + dy * dy);
            }
        CHECK_MSG(constrained >= 4, "every hull segment stays constrained");
        CHECK_NEAR(length, 16.0, 1e-12); /* the four sides, whole, once each */
        plateau_dt_free(&mesh);
    }
}

static void test_dt_subnormals_merged_as_duplicates(void)
{
    static const double pts[] = {-0x1.8fcfcfc00fc04p+976, -0x1.800f800fc0000p+961,
                                 0x0.4000804f83737p-1022, 0x1.73737373700fcp-140,
                                 0x0.0000000000004p-1022, 0x0.804f804fc0400p-1022,
                                 0x1.4040808f808fcp-959, 0x1.0080408080000p-895,
                                 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    countalloc ca;
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    plateau_dt_error rep;
    plateau_dt_result rc;
    countalloc_init(&ca, 0);
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    opt.allocator = countalloc_allocator(&ca);
    in.points = pts;
    in.num_points = 8;
    in.segments = NULL;
    in.num_segments = 0;
    rc = plateau_dt_triangulate(&in, &opt, &mesh, &rep);
    if (rc == PLATEAU_DT_OK) {
        long wrong = 0;
        size_t i;
        for (i = 0; i < 8; i++) {
            plateau_index d = mesh.duplicate_of[i];
            wrong += pts[2 * d] != pts[2 * i] || pts[2 * d + 1] != pts[2 * i + 1];
        }
        CHECK_MSG(wrong == 0, "dt_triangulate: subnormal input, an error or a true duplicate map");
    }
    CHECK_EQ_INT(rc, PLATEAU_DT_ERR_RANGE);
    CHECK_EQ_INT(rep.index, 1); /* 0x0.4000804f83737p-1022 loses its last bits */
    CHECK(strstr(rep.message, "point 1 ") != NULL);
    CHECK(strcmp(plateau_dt_result_string(rc), "unknown result") != 0);
    plateau_dt_free(&mesh);
    CHECK_EQ_INT(ca.live, 0);
    /* the same points with the largest coordinate 2^199: scaling up is exact,
     * so they are triangulated and no two distinct points merge */
    {
        double q[16];
        size_t i, ntri = 0;
        memcpy(q, pts, sizeof q);
        q[0] = -0x1p199;
        q[1] = -0x1p190;
        CHECK_EQ_INT(false_duplicates(q, 8, &ntri), 0);
        CHECK(ntri > 0);
        for (i = 0; i < 16; i++) q[i] = -q[i];
        CHECK_EQ_INT(false_duplicates(q, 8, &ntri), 0);
    }
}

/* fuzz_delaunay (whole documented range): five distinct points of mixed
 * magnitude (1e-141 .. 1e143) and 36 more copies of (0, 0).  The header
 * promises that the seed changes the triangle order, never the set; here
 * seeds 0, 12345 and 7 gave three different sets, and the set without the
 * copies was a fourth. */
static int canon_cmp(const void *x, const void *y)
{
    const plateau_index *a = (const plateau_index *)x, *b = (const plateau_index *)y;
    int k;
    for (k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* The triangle set of one run, canonical: each triple rotated to start at
 * its smallest index, the triples sorted.  Returns the count (at most 16). */
static size_t dt_set(const double *pts, size_t np, unsigned long seed, plateau_index *set)
{
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    size_t t, n = 0;
    memset(&opt, 0, sizeof opt);
    opt.seed = seed;
    in.points = pts;
    in.num_points = np;
    in.segments = NULL;
    in.num_segments = 0;
    if (!CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, NULL), PLATEAU_DT_OK)) return 0;
    for (t = 0; t < mesh.num_triangles && t < 16; t++) {
        const plateau_index *v = mesh.triangles + 3 * t;
        int r = (v[1] < v[0] && v[1] < v[2]) ? 1 : (v[2] < v[0] && v[2] < v[1]) ? 2 : 0;
        set[3 * t] = v[r];
        set[3 * t + 1] = v[(r + 1) % 3];
        set[3 * t + 2] = v[(r + 2) % 3];
        n++;
    }
    qsort(set, n, 3 * sizeof(plateau_index), canon_cmp);
    plateau_dt_free(&mesh);
    return n;
}

static void test_dt_seed_changes_triangle_set_mixed_magnitudes(void)
{
    double pts[2 * 41];
    static const double distinct[] = {0x1.ff2f2f2e0e820p-450, -0x1.000000000007fp+350,
                                      -0x1.00000000000ffp+478, -0x1.7970741f00000p-69,
                                      0x1.ffe0000000000p-467,  0x1.801bf21e00000p-464,
                                      -0x1.0759c00000000p-318, 0.0};
    static const unsigned long seeds[] = {12345, 7};
    plateau_index ref[48], other[48];
    size_t nref, n, i;
    int same = 1;
    memset(pts, 0, sizeof pts);
    memcpy(pts, distinct, sizeof distinct);
    nref = dt_set(pts, 41, 0, ref);
    for (i = 0; i < 2; i++) {
        n = dt_set(pts, 41, seeds[i], other);
        same &= n == nref && memcmp(ref, other, 3 * n * sizeof(plateau_index)) == 0;
    }
    n = dt_set(pts, 5, 0, other); /* without the copies of (0, 0) */
    same &= n == nref && memcmp(ref, other, 3 * n * sizeof(plateau_index)) == 0;
    /* fixed in 4d58443 */
    CHECK_MSG(same, "dt_triangulate: one triangle set whatever the seed and the duplicates");
}

/* fuzz_delaunay (refinement): a single triangle with a 12.9 degree corner
 * at (0, 0), refined to 20 degrees, hull mode.  The refinement splits the
 * hull edges toward the corner about 1870 times, down to 2.7e-138 from it,
 * then reports refine_stop DONE and num_unrefined 0 although the 12.9 degree
 * angle is still there (as it must be: no split can widen it).  The hull
 * edges' angle was not taken for an input angle (only segments' were); now
 * it is exempt like a segment corner: 8 vertices, num_unrefined 1. */
static void test_dt_refine_spirals_into_small_hull_corner(void)
{
    static const double pts[] = {0, 0, 1117, 256, 1024, 0};
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    double closest = 1e300, smallest = 180.0;
    size_t t, v;
    memset(&opt, 0, sizeof opt);
    opt.min_angle = 20.0;
    in.points = pts;
    in.num_points = 3;
    in.segments = NULL;
    in.num_segments = 0;
    if (!CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &mesh, NULL), PLATEAU_DT_OK)) return;
    for (v = 3; v < mesh.num_points; v++) {
        double r = hypot(mesh.points[2 * v], mesh.points[2 * v + 1]);
        if (r < closest) closest = r;
    }
    for (t = 0; t < mesh.num_triangles; t++) {
        int k;
        for (k = 0; k < 3; k++) {
            const double *a = mesh.points + 2 * mesh.triangles[3 * t + k];
            const double *b = mesh.points + 2 * mesh.triangles[3 * t + (k + 1) % 3];
            const double *c = mesh.points + 2 * mesh.triangles[3 * t + (k + 2) % 3];
            double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
            double lu = hypot(ux, uy), lv = hypot(vx, vy);
            double ang = atan2(fabs((ux / lu) * (vy / lv) - (uy / lu) * (vx / lv)),
                               (ux / lu) * (vx / lv) + (uy / lu) * (vy / lv)) *
                         (180.0 / 3.14159265358979323846);
            if (ang < smallest) smallest = ang;
        }
    }
    /* the corner stays: the smallest angle is 12.9 degrees whatever happens */
    CHECK_NEAR(smallest, 12.9084, 1e-3);
    /* the hull corner is an input angle: exempt and counted, not refined */
    if (!CHECK_MSG(mesh.num_unrefined > 0,
                   "dt_triangulate: a triangle left below min_angle is counted in num_unrefined") ||
        !CHECK_MSG(mesh.num_points < 100, "dt_triangulate: few vertices added at a small hull angle"))
        printf("  %lu triangles, %lu vertices added, the closest %g from the corner, "
               "refine_stop %d, num_unrefined %lu\n",
               (unsigned long)mesh.num_triangles, (unsigned long)(mesh.num_points - 3), closest,
               mesh.refine_stop, (unsigned long)mesh.num_unrefined);
    plateau_dt_free(&mesh);
}

/* Review: a triangle and a square with coordinates of both signs near
 * DBL_MAX.  plateau_boundary_check's coordinate differences overflowed to
 * infinity and it called them collinear (PLATEAU_ERR_COLLINEAR); then
 * plateau_solve's frame took 2^1024 = inf as its scale and found every
 * framed vertex equal (PLATEAU_ERR_REPEATED_VERTEX). */
static void test_boundary_near_dbl_max(void)
{
    static const double tri[9] = {1e308, 0, 0, -1e308, 0, 0, 0, 1e308, 0};
    static const double sq[12] = {1.7e308, 0, 0, 0, 1.7e308, 0, -1.7e308, 0, 0,
                                  0, -1.7e308, 0.5e308};
    static const double line[9] = {-1.7e308, 0, 0, 0, 0, 0, 1.7e308, 0, 0};
    plateau_error err;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    size_t i;
    CHECK_EQ_INT(plateau_boundary_check(tri, 3, &err), PLATEAU_OK);
    CHECK_EQ_INT(plateau_boundary_check(sq, 4, &err), PLATEAU_OK);
    CHECK_EQ_INT(plateau_boundary_check(line, 3, &err), PLATEAU_ERR_COLLINEAR);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 4;
    if (CHECK_EQ_INT(plateau_solve(sq, 4, &opt, &mesh, &rep, &err), PLATEAU_OK)) {
        for (i = 0; i < 12; i++) CHECK(mesh.positions[i] == sq[i]);
        for (i = 0; i < 3 * mesh.num_vertices; i++) CHECK(isfinite(mesh.positions[i]));
    }
    plateau_mesh_free(&mesh);
}

/* A trefoil knot bounds no embedded disk, yet its mesh
 * came back with stop "converged" and no warning (17 pairs of triangles
 * crossing each other with the fan seeding and its default seed, 60
 * vertices; 22 with today's default quality seeding).  The final
 * check counts the pairs; the solve still returns the mesh (PLATEAU_OK),
 * the report says what is wrong and the stop is not "converged"; the same
 * holds for plateau_mesh_minimize on that mesh. */
static void test_trefoil_mesh_intersects_itself(void)
{
    double xyz[3 * 60];
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    int i;
    for (i = 0; i < 60; i++) {
        double t = 6.283185307179586 * i / 60;
        xyz[3 * i] = sin(t) + 2 * sin(2 * t);
        xyz[3 * i + 1] = cos(t) - 2 * cos(2 * t);
        xyz[3 * i + 2] = -sin(3 * t);
    }
    if (CHECK_EQ_INT(plateau_solve(xyz, 60, NULL, &mesh, &rep, &err), PLATEAU_OK)) {
        CHECK(rep.intersecting_pairs > 0);
        CHECK(rep.defects & PLATEAU_DEFECT_INTERSECTION);
        CHECK(rep.stop != PLATEAU_STOP_CONVERGED);
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_DEFECTS);
        CHECK(strstr(plateau_stop_string(rep.stop), "converged") == NULL);
        printf("  trefoil: %lu intersecting pairs, defects %u, stop: %s\n",
               (unsigned long)rep.intersecting_pairs, rep.defects, plateau_stop_string(rep.stop));
        memset(&rep, 0, sizeof rep);
        CHECK_EQ_INT(plateau_mesh_minimize(&mesh, NULL, &rep, &err), PLATEAU_OK);
        CHECK(rep.defects & PLATEAU_DEFECT_INTERSECTION);
        CHECK(rep.stop != PLATEAU_STOP_CONVERGED);
    }
    plateau_mesh_free(&mesh);
}

/* A solve that stops short of its stopping rule is no
 * success.  One LM iteration (max_iterations 1) leaves F far above zero:
 * solved 0, PLATEAU_DEFECT_UNSOLVED, stop not "converged".  And
 * cli/samples/helicoid.txt on the circle domain with n = 300 ended at a
 * local minimum of F (F = 174, a 0.00 degree angle, stop "converged"). */
static void test_unsolved_is_not_converged(void)
{
    double *xyz = NULL;
    size_t m = 0;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    if (!CHECK_EQ_INT(plateau_read_boundary_file("cli/samples/helicoid.txt", NULL, &xyz, &m, &err),
                      PLATEAU_OK))
        return;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 20;
    opt.max_iterations = 1;
    if (CHECK_EQ_INT(plateau_solve(xyz, m, &opt, &mesh, &rep, &err), PLATEAU_OK)) {
        CHECK(rep.f_final > 1e-6);
        CHECK_EQ_INT(rep.solved, 0);
        CHECK(rep.defects & PLATEAU_DEFECT_UNSOLVED);
        CHECK(rep.stop != PLATEAU_STOP_CONVERGED);
    }
    plateau_mesh_free(&mesh);
    opt.max_iterations = 0; /* the same with the defaults: solved, valid */
    if (CHECK_EQ_INT(plateau_solve(xyz, m, &opt, &mesh, &rep, &err), PLATEAU_OK)) {
        CHECK_EQ_INT(rep.solved, 1);
        CHECK_EQ_INT(rep.defects, 0);
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_CONVERGED);
    }
    plateau_mesh_free(&mesh);
#ifndef PLATEAU_TEST_SANITIZED /* 4 s at -O2 */
    opt.interior_points = 300;
    opt.force_circle_domain = 1;
    opt.seeding = PLATEAU_SEEDING_PAPER;
    if (CHECK_EQ_INT(plateau_solve(xyz, m, &opt, &mesh, &rep, &err), PLATEAU_OK)) {
        printf("  helicoid, circle domain, n = 300: F %.3g, smallest angle %.2g deg, %lu removed, "
               "defects %u, stop: %s\n",
               rep.f_final, rep.min_angle_deg, (unsigned long)rep.removed_vertices, rep.defects,
               plateau_stop_string(rep.stop));
        if (rep.f_final > 1e-6 || rep.min_angle_deg < 1e-3) {
            CHECK(rep.defects != 0);
            CHECK(rep.stop != PLATEAU_STOP_CONVERGED);
        }
    }
    plateau_mesh_free(&mesh);
#endif
    free(xyz);
}

/* A flat 1e6 : 1 rectangle, as 4 corners and with each long side cut into
 * 50 edges: the default solve (the accuracy's runs, coarse to fine) is
 * valid, the area 1e6 to the estimate (it ended "the objective did not
 * reach its stopping rule", exit 3, where --method area was valid). */
static void test_flat_thin_rectangle_default_is_valid(void)
{
    double xyz[3 * 104];
    size_t m, i, pass;
    for (pass = 0; pass < 2; pass++) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        size_t side = pass ? 50 : 1;
        m = 0;
        for (i = 0; i <= side; i++) { /* y = 0, x rising; then y = 1, x falling */
            xyz[3 * m] = 1e6 * (double)i / (double)side, xyz[3 * m + 1] = 0.0, xyz[3 * m + 2] = 0.0, m++;
        }
        for (i = 0; i <= side; i++) {
            xyz[3 * m] = 1e6 * (double)(side - i) / (double)side, xyz[3 * m + 1] = 1.0, xyz[3 * m + 2] = 0.0, m++;
        }
        if (!CHECK_EQ_INT(plateau_solve(xyz, m, NULL, &mesh, &rep, &err), PLATEAU_OK)) {
            fprintf(stderr, "  %s\n", err.message);
            continue;
        }
        if (!CHECK_EQ_INT(rep.defects, 0))
            fprintf(stderr, "  %lu vertices: %s\n", (unsigned long)m, plateau_stop_string(rep.stop));
        if (!CHECK(fabs(rep.area - 1e6) <= 1e6 * (rep.area_error_estimate + 1e-12)))
            fprintf(stderr, "  area %.17g, estimate %g\n", rep.area, rep.area_error_estimate);
        plateau_mesh_free(&mesh);
    }
}

/* The same rectangle, 4 corners, seeded by the paper's fan at n = 10, 30
 * and 100 (slivers of 1e-5 degrees): method paper's H_i are all 0 on the
 * flat mesh, and its tangential rows are met too (F at rounding level),
 * so the result is solved and valid, the area 1e6.  The LM's mu I damping
 * took its scale from the slivers' H rows and stopped by the step test
 * where it began (n = 10: F 4.4e-12 in the caller's units, "the
 * objective did not reach its stopping rule"). */
static void test_flat_thin_rectangle_fan_is_solved(void)
{
    static const double xyz[12] = {0.0, 0.0, 0.0, 1e6, 0.0, 0.0, 1e6, 1.0, 0.0, 0.0, 1.0, 0.0};
    static const size_t ns[3] = {10, 30, 100};
    size_t k, v;
    for (k = 0; k < 3; k++) {
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        double zmax = 0.0;
        memset(&o, 0, sizeof o);
        o.seeding = PLATEAU_SEEDING_PAPER;
        o.interior_points = ns[k];
        if (!CHECK_EQ_INT(plateau_solve(xyz, 4, &o, &mesh, &rep, &err), PLATEAU_OK)) continue;
        CHECK(rep.solved);
        if (!CHECK_EQ_INT(rep.defects, 0))
            fprintf(stderr, "  n %lu: F %g, %s\n", (unsigned long)ns[k], rep.f_final, plateau_stop_string(rep.stop));
        CHECK(rep.f_final <= 1e-10);
        CHECK_EQ_INT(rep.interior_points, ns[k]);
        CHECK(fabs(rep.area - 1e6) <= 1e-9 * 1e6);
        for (v = 0; v < mesh.num_vertices; v++)
            if (fabs(mesh.positions[3 * v + 2]) > zmax) zmax = fabs(mesh.positions[3 * v + 2]);
        CHECK(zmax == 0.0);
        plateau_mesh_free(&mesh);
    }
}

int main(void)
{
    RUN(test_dt_mixed_magnitudes_merged_as_duplicates);
    RUN(test_dt_huge_square_tiny_cluster_merged);
    RUN(test_dt_subnormals_merged_as_duplicates);
    RUN(test_dt_hull_segments_lose_flag_when_refined);
    RUN(test_dt_seed_changes_triangle_set_mixed_magnitudes);
    RUN(test_dt_refine_spirals_into_small_hull_corner);
    RUN(test_boundary_near_dbl_max);
    RUN(test_trefoil_mesh_intersects_itself);
    RUN(test_unsolved_is_not_converged);
    RUN(test_flat_thin_rectangle_default_is_valid);
    RUN(test_flat_thin_rectangle_fan_is_solved);
    CHECK_NEAR(0.0, 0.0, 0.0);
    return harness_report("test_regressions");
}
