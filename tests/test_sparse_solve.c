/* test_sparse_solve.c - method paper's two linear-algebra paths agree.
 *
 * plateau_options.linear_solver forces the dense LM (plateau_lm_solve,
 * O(n^2) Jacobian) or Powell's dog leg on the sparse block LU
 * (plateau_lm_dogleg_solve on the 1-ring pattern).  Both solve the same
 * square system (paper II.D: H_i and two tangential rows per free vertex)
 * to its root, so on the demo boundaries they must give the same mesh:
 * the same triangles (the flips between rounds see the same geometry) and
 * the same area to 1e-9 relative; the dog leg takes other steps on the
 * way, so positions agree only to the solves' tolerance.
 */
#ifndef PLATEAU_TEST_LINKED /* else make test links tests/impl.c's object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "tests/harness.h"
#include "examples/surfaces.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static plateau_result solve_with(const demo_case *c, size_t n, int linear_solver,
                                 plateau_mesh *mesh, plateau_report *rep)
{
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, polygon);
    plateau_options o;
    memset(&o, 0, sizeof o);
    memset(mesh, 0, sizeof *mesh);
    o.method = PLATEAU_METHOD_PAPER;
    o.interior_points = n;
    o.seed = DEMO_SEED;
    o.linear_solver = linear_solver;
    return plateau_solve(polygon, m, &o, mesh, rep, NULL);
}

static int same_triangles(const plateau_mesh *a, const plateau_mesh *b)
{
    return a->num_vertices == b->num_vertices && a->num_triangles == b->num_triangles &&
           memcmp(a->triangles, b->triangles, 3 * a->num_triangles * sizeof(plateau_index)) == 0;
}

/* forced dense vs forced sparse: same triangles, same area */
static void compare(const char *name, size_t n)
{
    const demo_case *c = demo_find(name);
    plateau_mesh md, ms;
    plateau_report rd, rs;
    char msg[128];
    if (!CHECK(c != NULL)) return;
    sprintf(msg, "%s, n = %lu", name, (unsigned long)n);
    if (CHECK_EQ_INT(solve_with(c, n, PLATEAU_LINEAR_DENSE, &md, &rd), PLATEAU_OK) &&
        CHECK_EQ_INT(solve_with(c, n, PLATEAU_LINEAR_SPARSE, &ms, &rs), PLATEAU_OK)) {
        CHECK_EQ_INT(rd.linear_solver, PLATEAU_LINEAR_DENSE);
        CHECK_EQ_INT(rs.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK_MSG(rd.solved && rs.solved, msg);
        CHECK_EQ_INT(rd.defects, 0);
        CHECK_EQ_INT(rs.defects, 0);
        CHECK_MSG(same_triangles(&md, &ms), msg);
        CHECK_MSG(fabs(rs.area - rd.area) <= 1e-9 * rd.area, msg);
        CHECK_NEAR(rs.area, rd.area, 1e-9 * rd.area);
        printf("  %-12s n = %3lu: rounds %zu / %zu, iterations %3zu / %3zu, area %.12f / %.12f "
               "(%.1e relative)\n",
               name, (unsigned long)rd.interior_points, rd.rounds, rs.rounds, rd.iterations,
               rs.iterations, rd.area, rs.area, fabs(rs.area - rd.area) / rd.area);
    }
    plateau_mesh_free(&md);
    plateau_mesh_free(&ms);
}

static void test_dense_vs_sparse(void)
{
    static const char *names[] = {"helicoid", "catenoid", "scherk-b1-m", "membrane"};
    static const size_t sizes[] = {25, 50, 100, 200};
    size_t i, j;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        for (j = 0; j < sizeof sizes / sizeof sizes[0]; j++) compare(names[i], sizes[j]);
#ifndef PLATEAU_TEST_SANITIZED /* the dense LM takes 2-6 s per solve at n = 400 */
    compare("helicoid", 400);
#endif
}

/* AUTO: dense up to PLATEAU_SPARSE_THRESHOLD free vertices (the demo
 * tables unchanged), sparse above; a value outside 0..2 is refused. */
static void test_auto_choice(void)
{
    const demo_case *c = demo_find("catenoid");
    plateau_mesh ma, mf;
    plateau_report ra, rf;
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, polygon);
    plateau_options o;
    plateau_error err;
    if (CHECK_EQ_INT(solve_with(c, 25, PLATEAU_LINEAR_AUTO, &ma, &ra), PLATEAU_OK) &&
        CHECK_EQ_INT(solve_with(c, 25, PLATEAU_LINEAR_DENSE, &mf, &rf), PLATEAU_OK)) {
        CHECK(ra.interior_points <= PLATEAU_SPARSE_THRESHOLD);
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_DENSE);
        CHECK(memcmp(ma.positions, mf.positions, 3 * ma.num_vertices * sizeof(double)) == 0);
    }
    plateau_mesh_free(&ma);
    plateau_mesh_free(&mf);
    if (CHECK_EQ_INT(solve_with(c, 2 * PLATEAU_SPARSE_THRESHOLD, PLATEAU_LINEAR_AUTO, &ma, &ra),
                     PLATEAU_OK) &&
        CHECK_EQ_INT(solve_with(c, 2 * PLATEAU_SPARSE_THRESHOLD, PLATEAU_LINEAR_SPARSE, &mf, &rf),
                     PLATEAU_OK)) {
        CHECK(ra.interior_points > PLATEAU_SPARSE_THRESHOLD);
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK(memcmp(ma.positions, mf.positions, 3 * ma.num_vertices * sizeof(double)) == 0);
        CHECK_EQ_INT(ra.iterations, rf.iterations);
        CHECK_EQ_INT(ra.evaluations, rf.evaluations);
        CHECK_EQ_INT(ra.lm_stop, rf.lm_stop);
    }
    plateau_mesh_free(&ma);
    plateau_mesh_free(&mf);
    /* method area records no linear solver */
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 25;
    o.linear_solver = PLATEAU_LINEAR_SPARSE;
    if (CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, NULL), PLATEAU_OK))
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_AUTO);
    plateau_mesh_free(&ma);
    o.method = PLATEAU_METHOD_PAPER;
    o.linear_solver = 3;
    CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&ma);
    o.linear_solver = -1;
    CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, NULL), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&ma);
}

/* The progress callback sees the dog leg's iterations and can stop it. */
static int stop_at_3(int round, int iteration, double f, void *user)
{
    int *calls = (int *)user;
    (void)round;
    (void)f;
    ++*calls;
    return iteration >= 3;
}

static void test_progress_abort(void)
{
    const demo_case *c = demo_find("helicoid");
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, polygon);
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    int calls = 0;
    memset(&o, 0, sizeof o);
    o.interior_points = 100;
    o.linear_solver = PLATEAU_LINEAR_SPARSE;
    o.progress = stop_at_3;
    o.progress_user = &calls;
    CHECK_EQ_INT(plateau_solve(polygon, m, &o, &mesh, &rep, &err), PLATEAU_ERR_ABORTED);
    CHECK_EQ_INT(calls, 3);
    CHECK_EQ_INT(rep.lm_stop, PLATEAU_LM_STOP_ABORTED);
    plateau_mesh_free(&mesh);
}

int main(void)
{
    RUN(test_dense_vs_sparse);
    RUN(test_auto_choice);
    RUN(test_progress_abort);
    return harness_report("test_sparse_solve");
}
