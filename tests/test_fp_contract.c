/* test_fp_contract.c - the meshes stay valid when the compiler fuses a*b+c
 * into one fused multiply-add.
 *
 * gcc's default GNU mode (-std=gnu99, and no -std at all) contracts a*b + c
 * into an FMA (-ffp-contract=fast) wherever the target has one; so does
 * clang with -ffp-contract=fast.  Fused and unfused arithmetic round
 * differently, so the same input can give another mesh (the DETERMINISM
 * section of plateau.h): cli/samples/helicoid-turns.txt came out with area
 * 4.2967 under -std=c99 and 4.3361 under -std=gnu99 -mfma.  What must not
 * change is validity.  `make test-full` runs this file as every test (gcc, clang,
 * sanitizers) and once more as build/fma/test_fp_contract, compiled with
 * -std=gnu99 -ffp-contract=fast -O2 (plus -mfma on an x86-64 that has FMA,
 * which defines PLATEAU_TEST_EXPECT_FMA: the build must then really fuse).
 *
 * On every demo polygon (examples/surfaces.h: helicoid, catenoid, the nine
 * Scherk polygons, the membrane) with methods paper and area, and on the CLI
 * samples, it checks: the solve succeeds, no triangle is inverted, the
 * largest |dihedral| stays below 120 degrees, the smallest angle (measured
 * here, not taken from the report) is above MIN_ANGLE_FLOOR_DEG, and the
 * first m vertices are the boundary bit for bit. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#include "../examples/surfaces.h"

/* The floor for the smallest angle: the demo's smallest for paper and area
 * is 6.6 degrees (area on the largest Scherk polygons). */
#define MIN_ANGLE_FLOOR_DEG 5.0
#define MAX_ABS_DIHEDRAL_DEG 120.0

/* 1 when this build fuses x*y + z: with x = 1 + 2^-30, y = 1 - 2^-30 the
 * product 1 - 2^-60 rounds to 1, so x*y - 1 is 0 unless it is fused. */
static int build_fuses(void)
{
    volatile double vx = 1.0 + 1.0 / 1073741824.0, vy = 1.0 - 1.0 / 1073741824.0, vz = -1.0;
    double x = vx, y = vy, z = vz;
    return x * y + z != 0.0;
}

static double smallest_angle_deg(const plateau_mesh *mesh)
{
    double best = 180.0;
    size_t t;
    int k;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tri = mesh->triangles + 3 * t;
        for (k = 0; k < 3; k++) {
            const double *p = mesh->positions + 3 * tri[k];
            const double *q = mesh->positions + 3 * tri[(k + 1) % 3];
            const double *r = mesh->positions + 3 * tri[(k + 2) % 3];
            double a[3], b[3], c[3], dot, cr, ang;
            int i;
            for (i = 0; i < 3; i++) {
                a[i] = q[i] - p[i];
                b[i] = r[i] - p[i];
            }
            demo_cross(a, b, c);
            dot = demo_dot(a, b);
            cr = sqrt(demo_dot(c, c));
            ang = atan2(cr, dot) * 180.0 / M_PI;
            if (ang < best) best = ang;
        }
    }
    return best;
}

/* One solve of the loops of boundary (counts[0..k), m vertices in all). */
static void check_loops(const char *what, const double *boundary, const size_t *counts, size_t k,
                        const plateau_options *opt)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    char msg[200];
    size_t i;
    int same = 1;
    double angle;
    size_t m = 0;
    for (i = 0; i < k; i++) m += counts[i];
    memset(&mesh, 0, sizeof mesh);
    if (plateau_solve_loops(boundary, counts, k, opt, &mesh, &rep, &err) != PLATEAU_OK) {
        sprintf(msg, "%s: the solve failed: %.100s", what, err.message);
        CHECK_MSG(0, msg);
        plateau_mesh_free(&mesh);
        return;
    }
    for (i = 0; i < 3 * m; i++) same &= mesh.positions[i] == boundary[i];
    angle = smallest_angle_deg(&mesh);
    sprintf(msg, "%s: boundary unchanged", what);
    CHECK_MSG(same, msg);
    sprintf(msg, "%s: %zu inverted triangles", what, rep.inverted_triangles);
    CHECK_MSG(rep.inverted_triangles == 0, msg);
    sprintf(msg, "%s: largest |dihedral| %.2f deg", what, rep.max_abs_beta_deg);
    CHECK_MSG(rep.max_abs_beta_deg < MAX_ABS_DIHEDRAL_DEG, msg);
    sprintf(msg, "%s: smallest angle %.2f deg", what, angle);
    CHECK_MSG(angle > MIN_ANGLE_FLOOR_DEG, msg);
    CHECK_NEAR(rep.min_angle_deg, angle, 1e-6); /* the report measures the same */
    sprintf(msg, "%s: defects %u", what, rep.defects);
    CHECK_MSG(rep.defects == 0, msg);
    plateau_mesh_free(&mesh);
}

static void check_mesh(const char *what, const double *boundary, size_t m,
                       const plateau_options *opt)
{
    check_loops(what, boundary, &m, 1, opt);
}

static void test_demo_polygons(void)
{
    static const plateau_method methods[2] = {PLATEAU_METHOD_PAPER, PLATEAU_METHOD_AREA};
    size_t ci;
    int k;
    for (ci = 0; ci < DEMO_NUM_CASES; ci++) {
        const demo_case *c = &demo_cases[ci];
        double boundary[3 * DEMO_MAX_BOUNDARY];
        size_t m = demo_boundary(c, boundary);
        for (k = 0; k < 2; k++) {
            plateau_options opt;
            char what[80];
            memset(&opt, 0, sizeof opt);
            opt.method = methods[k];
            opt.interior_points = c->n;
            opt.seed = DEMO_SEED;
            sprintf(what, "%s, %s", c->name, plateau_method_name(methods[k]));
            check_mesh(what, boundary, m, &opt);
        }
    }
}

/* The CLI samples.  helicoid-turns folds with the default seeding (2
 * inverted triangles under any build): it is checked with the quality
 * seeding, which solves it cleanly, at accuracy 1e-3 (one solve; the
 * default 1e-4 adds a solve at a finer count that takes seconds). */
static void test_cli_samples(void)
{
    static const struct {
        const char *path;
        plateau_seeding seeding;
        double accuracy;
    } samples[] = {
        {"cli/samples/helicoid.txt", PLATEAU_SEEDING_PAPER, 0.0},
        {"cli/samples/catenoid.txt", PLATEAU_SEEDING_PAPER, 0.0},
        {"cli/samples/helicoid-turns.txt", PLATEAU_SEEDING_QUALITY, 1e-3},
    };
    size_t i;
    for (i = 0; i < sizeof samples / sizeof samples[0]; i++) {
        double *xyz = NULL;
        size_t m = 0;
        plateau_options opt;
        CHECK_EQ_INT(plateau_read_boundary_file(samples[i].path, NULL, &xyz, &m, NULL), PLATEAU_OK);
        if (!xyz) continue;
        memset(&opt, 0, sizeof opt);
        opt.seeding = samples[i].seeding;
        opt.accuracy = samples[i].accuracy;
        check_mesh(samples[i].path, xyz, m, &opt);
        free(xyz);
    }
}

/* Two loops: the rings of cli/samples/two-rings.txt (radius 1, z = -0.5
 * and 0.5, 24 vertices each), an annulus domain, methods paper and area
 * as for the demo polygons (paper-literal, the ill-posed teaching method,
 * reaches 0.24 degrees here under either build). */
static void test_two_rings(void)
{
    double xyz[3 * 48];
    size_t counts[2] = {24, 24}, i;
    int method;
    for (i = 0; i < 48; i++) {
        double t = 2.0 * M_PI * (double)(i % 24) / 24.0;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < 24 ? -0.5 : 0.5;
    }
    for (method = 0; method < 2; method++) {
        plateau_options opt;
        char what[80];
        memset(&opt, 0, sizeof opt);
        opt.method = method ? PLATEAU_METHOD_AREA : PLATEAU_METHOD_PAPER;
        opt.interior_points = 95;
        sprintf(what, "two rings, %s", plateau_method_name(opt.method));
        check_loops(what, xyz, counts, 2, &opt);
    }
}

static void test_this_build(void)
{
    printf("  this build %s a*b + c\n", build_fuses() ? "fuses" : "does not fuse");
#ifdef PLATEAU_TEST_EXPECT_FMA
    CHECK_MSG(build_fuses(), "built to contract into FMA, yet a*b + c is not fused");
#endif
}

int main(void)
{
    RUN(test_this_build);
    RUN(test_demo_polygons);
    RUN(test_cli_samples);
    RUN(test_two_rings);
    return harness_report("test_fp_contract");
}
