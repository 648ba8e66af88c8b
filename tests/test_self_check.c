/* test_self_check.c - plateau_mesh_self_check, and PLATEAU_SELF_CHECK, which runs
 * it after every adjacency build.  Every invariant it tests is broken once
 * on a copy of a solved mesh and must be reported with its code and index;
 * solves of every method and both seedings pass it at every stage. */
#define PLATEAU_SELF_CHECK
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "harness.h"

#include <math.h>

/* A saddle-shaped ring of m vertices: z = 0.4 cos 2t. */
static void sc_ring(double *xyz, size_t m)
{
    size_t i;
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.4 * cos(2.0 * t);
    }
}

/* Every method and both seedings: the solve's every adjacency build ran the
 * check (PLATEAU_SELF_CHECK), and the result passes it again. */
static void test_solves_pass(void)
{
    double xyz[3 * 20];
    int method, seeding;
    sc_ring(xyz, 20);
    for (method = 0; method < 3; method++)
        for (seeding = 0; seeding < 2; seeding++) {
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            plateau_error err;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)method;
            o.seeding = (plateau_seeding)seeding;
            o.interior_points = 15;
            CHECK_EQ_INT(plateau_solve(xyz, 20, &o, &mesh, &rep, &err), PLATEAU_OK);
            CHECK_EQ_INT(plateau_mesh_self_check(&mesh, &err), PLATEAU_OK);
            CHECK_EQ_INT(err.code, PLATEAU_OK);
            CHECK(rep.rounds >= 1);
            CHECK_NEAR(rep.area, plateau_mesh_area(&mesh), 1e-9 * rep.area);
            plateau_mesh_free(&mesh);
        }
}

/* A fresh copy of a solved mesh (its own arrays), to break. */
static int sc_copy(const plateau_mesh *src, plateau_mesh *dst)
{
    return plateau_mesh_create(src->positions, src->num_vertices, src->fixed, src->triangles,
                               src->num_triangles, NULL, dst, NULL) == PLATEAU_OK;
}

static void test_broken_meshes_fail(void)
{
    double xyz[3 * 16];
    plateau_mesh good, bad;
    plateau_error err;
    plateau_options o;
    size_t t, e;
    plateau_index keep;
    sc_ring(xyz, 16);
    memset(&o, 0, sizeof o);
    o.interior_points = 10;
    CHECK_EQ_INT(plateau_solve(xyz, 16, &o, &good, NULL, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_self_check(&good, &err), PLATEAU_OK);
    CHECK_EQ_INT(err.index, -1);
    /* an interior triangle: all three neighbours present */
    for (t = 0; t < good.num_triangles; t++)
        if (good.neighbors[3 * t] >= 0 && good.neighbors[3 * t + 1] >= 0 &&
            good.neighbors[3 * t + 2] >= 0)
            break;
    CHECK(t < good.num_triangles);
    if (t == good.num_triangles) t = 0;

    /* no mesh, no adjacency */
    CHECK_EQ_INT(plateau_mesh_self_check(NULL, &err), PLATEAU_ERR_ARGUMENT);
    /* a NaN coordinate */
    if (sc_copy(&good, &bad)) {
        bad.positions[3 * 20 + 1] = NAN;
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_NOT_FINITE);
        CHECK_EQ_INT(err.index, 20);
        plateau_mesh_free(&bad);
    }
    /* a vertex out of range */
    if (sc_copy(&good, &bad)) {
        bad.triangles[3 * t + 1] = (plateau_index)bad.num_vertices;
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_INDEX_RANGE);
        CHECK_EQ_INT(err.index, (long)t);
        plateau_mesh_free(&bad);
    }
    /* a repeated vertex */
    if (sc_copy(&good, &bad)) {
        bad.triangles[3 * t + 2] = bad.triangles[3 * t];
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_DEGENERATE_TRIANGLE);
        CHECK_EQ_INT(err.index, (long)t);
        plateau_mesh_free(&bad);
    }
    /* a triangle turned over (its adjacency not rebuilt): its edge records
     * no longer match, or its neighbours run their edges its way */
    if (sc_copy(&good, &bad)) {
        keep = bad.triangles[3 * t + 1];
        bad.triangles[3 * t + 1] = bad.triangles[3 * t + 2];
        bad.triangles[3 * t + 2] = keep;
        CHECK(plateau_mesh_self_check(&bad, &err) != PLATEAU_OK);
        CHECK(err.code == PLATEAU_ERR_ARGUMENT || err.code == PLATEAU_ERR_ORIENTATION);
        plateau_mesh_free(&bad);
    }
    /* a neighbour that does not name the triangle back */
    if (sc_copy(&good, &bad)) {
        plateau_index u = bad.neighbors[3 * t];
        size_t q;
        for (q = 0; q < 3; q++)
            if (bad.neighbors[3 * (size_t)u + q] == (plateau_index)t) bad.neighbors[3 * (size_t)u + q] = -1;
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_ARGUMENT);
        plateau_mesh_free(&bad);
    }
    /* a missing neighbour across an interior edge */
    if (sc_copy(&good, &bad)) {
        bad.neighbors[3 * t + 1] = -1;
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(err.index, (long)t);
        plateau_mesh_free(&bad);
    }
    /* an edge with no triangle */
    if (sc_copy(&good, &bad)) {
        e = (size_t)bad.triangle_edges[3 * t];
        bad.edge_triangles[2 * e] = bad.edge_triangles[2 * e + 1] = -1;
        CHECK(plateau_mesh_self_check(&bad, &err) == PLATEAU_ERR_ARGUMENT);
        plateau_mesh_free(&bad);
    }
    /* a vertex that lists a triangle it is not in */
    if (sc_copy(&good, &bad)) {
        size_t v = 20, j = bad.vertex_triangle_start[v];
        size_t w;
        for (w = 0; w < bad.num_triangles; w++) {
            const plateau_index *tr = bad.triangles + 3 * w;
            if (tr[0] != (plateau_index)v && tr[1] != (plateau_index)v && tr[2] != (plateau_index)v)
                break;
        }
        bad.vertex_triangles[j] = (plateau_index)w;
        CHECK_EQ_INT(plateau_mesh_self_check(&bad, &err), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(err.index, 20);
        plateau_mesh_free(&bad);
    }
    /* with PLATEAU_SELF_CHECK, an adjacency build reports a bad mesh too:
     * a NaN position is not among plateau_mesh_build_adjacency's own checks */
    if (sc_copy(&good, &bad)) {
        bad.positions[3 * 20] = HUGE_VAL;
        CHECK_EQ_INT(plateau_mesh_build_adjacency(&bad, &err), PLATEAU_ERR_NOT_FINITE);
        CHECK_EQ_INT(err.index, 20);
        plateau_mesh_free(&bad);
    }
    plateau_mesh_free(&good);
}

int main(void)
{
    RUN(test_solves_pass);
    RUN(test_broken_meshes_fail);
    return harness_report("test_self_check");
}
