/* test_solve_paths.c - method paper's two linear-algebra paths agree.
 *
 * plateau_options.linear_solver forces the dense LM (plateau_lm_solve,
 * O(n^2) Jacobian) or Powell's dog leg on the sparse block LU
 * (plateau_lm_dogleg_solve on the 1-ring pattern).  Both solve the same
 * square system (paper II.D: H_i and two tangential rows per free vertex)
 * to its root, so on the demo boundaries they must give the same mesh:
 * the same triangles (the flips between rounds see the same geometry) and
 * the same area to 1e-9 relative; the dog leg takes other steps on the
 * way, so positions agree only to the solves' tolerance.  The sparse path
 * also reaches the solved bound F <= 1e-10 when its Jacobian is large
 * against ||x|| (a large lambda here; the short edges of a densely
 * sampled boundary in bench/bench_dense_boundary.c).
 */
#define PLATEAU_IMPLEMENTATION /* the test reads private functions too */
#include "plateau.h"
#include "tests/harness.h"
#include "examples/surfaces.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static plateau_result solve_circle(const demo_case *c, size_t n, plateau_linear_solver linear_solver, int circle,
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
    o.force_circle_domain = circle;
    /* the rounds at full size, whose linear solvers these tests compare
     * (AUTO takes coarse to fine from PLATEAU_COARSE_TO_FINE_POINTS) */
    o.coarse_to_fine = PLATEAU_OFF;
    return plateau_solve(polygon, m, &o, mesh, rep, NULL);
}

static plateau_result solve_with(const demo_case *c, size_t n, plateau_linear_solver linear_solver,
                                 plateau_mesh *mesh, plateau_report *rep)
{
    return solve_circle(c, n, linear_solver, 0, mesh, rep);
}

static int same_triangles(const plateau_mesh *a, const plateau_mesh *b)
{
    return a->num_vertices == b->num_vertices && a->num_triangles == b->num_triangles &&
           memcmp(a->triangles, b->triangles, 3 * a->num_triangles * sizeof(plateau_index)) == 0;
}

/* forced dense vs forced sparse: same triangles, same area (circle: the
 * circle domain, where both start from the area presolve) */
static void compare_circle(const char *name, size_t n, int circle)
{
    const demo_case *c = demo_find(name);
    plateau_mesh md, ms;
    plateau_report rd, rs;
    char msg[128];
    if (!CHECK(c != NULL)) return;
    sprintf(msg, "%s, n = %lu%s", name, (unsigned long)n, circle ? ", circle domain" : "");
    if (CHECK_EQ_INT(solve_circle(c, n, PLATEAU_LINEAR_DENSE, circle, &md, &rd), PLATEAU_OK) &&
        CHECK_EQ_INT(solve_circle(c, n, PLATEAU_LINEAR_SPARSE, circle, &ms, &rs), PLATEAU_OK)) {
        CHECK_EQ_INT(rd.linear_solver, PLATEAU_LINEAR_DENSE);
        CHECK_EQ_INT(rs.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK_MSG(rd.solved && rs.solved, msg);
        CHECK_EQ_INT(rd.defects, 0);
        CHECK_EQ_INT(rs.defects, 0);
        CHECK_MSG(same_triangles(&md, &ms), msg);
        CHECK_MSG(fabs(rs.area - rd.area) <= 1e-9 * rd.area, msg);
        CHECK_NEAR(rs.area, rd.area, 1e-9 * rd.area);
        printf("  %-12s n = %3lu%s: rounds %zu / %zu, iterations %3zu / %3zu, area %.12f / %.12f "
               "(%.1e relative)\n",
               name, (unsigned long)rd.interior_points, circle ? " (circle)" : "", rd.rounds, rs.rounds,
               rd.iterations, rs.iterations, rd.area, rs.area, fabs(rs.area - rd.area) / rd.area);
    }
    plateau_mesh_free(&md);
    plateau_mesh_free(&ms);
}

static void compare(const char *name, size_t n) { compare_circle(name, n, 0); }

static void test_dense_vs_sparse(void)
{
    static const char *names[] = {"helicoid", "catenoid", "scherk-b1-m", "membrane"};
    static const size_t sizes[] = {25, 50, 100, 200};
    size_t i, j;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        for (j = 0; j < sizeof sizes / sizeof sizes[0]; j++) compare(names[i], sizes[j]);
    /* the circle domain: both start from the area presolve, which chooses
     * its path by size alone (at 250 the Newton method for both) */
    compare_circle("helicoid", 50, 1);
#ifndef PLATEAU_TEST_SANITIZED /* the dense LM takes 2-6 s per solve at n = 400 */
    if (HARNESS_FULL) {
        compare("helicoid", 400);
        compare_circle("helicoid", 250, 1);
    }
#endif
}

/* AUTO, method paper: dense up to PLATEAU_PAPER_SPARSE_THRESHOLD free
 * vertices (the paper's catenoid, n = 25), sparse above; a value outside
 * 0..2 is refused. */
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
        CHECK(ra.interior_points <= PLATEAU_PAPER_SPARSE_THRESHOLD);
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_DENSE);
        CHECK(memcmp(ma.positions, mf.positions, 3 * ma.num_vertices * sizeof(double)) == 0);
    }
    plateau_mesh_free(&ma);
    plateau_mesh_free(&mf);
    if (CHECK_EQ_INT(solve_with(c, 2 * PLATEAU_PAPER_SPARSE_THRESHOLD, PLATEAU_LINEAR_AUTO, &ma, &ra),
                     PLATEAU_OK) &&
        CHECK_EQ_INT(solve_with(c, 2 * PLATEAU_PAPER_SPARSE_THRESHOLD, PLATEAU_LINEAR_SPARSE, &mf, &rf),
                     PLATEAU_OK)) {
        CHECK(ra.interior_points > PLATEAU_PAPER_SPARSE_THRESHOLD);
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK(memcmp(ma.positions, mf.positions, 3 * ma.num_vertices * sizeof(double)) == 0);
        CHECK_EQ_INT(ra.iterations, rf.iterations);
        CHECK_EQ_INT(ra.evaluations, rf.evaluations);
        CHECK_EQ_INT(ra.lm_stop, rf.lm_stop);
    }
    plateau_mesh_free(&ma);
    plateau_mesh_free(&mf);
    /* method area records the sparse Newton method, and nothing for its
     * L-BFGS (no linear solver) */
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 25;
    o.linear_solver = PLATEAU_LINEAR_SPARSE;
    if (CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, NULL), PLATEAU_OK))
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_SPARSE);
    plateau_mesh_free(&ma);
    o.linear_solver = PLATEAU_LINEAR_AUTO;
    if (CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, NULL), PLATEAU_OK))
        CHECK_EQ_INT(ra.linear_solver, PLATEAU_LINEAR_AUTO);
    plateau_mesh_free(&ma);
    o.method = PLATEAU_METHOD_PAPER;
    o.linear_solver = (plateau_linear_solver)3;
    CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ma, &ra, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&ma);
    o.linear_solver = (plateau_linear_solver)-1;
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

/* m vertices of the unit circle lifted to z = amp cos(k t), t the angle */
static void wavy_circle(double *xyz, size_t m, double amp, double k)
{
    size_t i;
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = amp * cos(k * t);
    }
}

/* The sparse path solves its square system to the solved bound however
 * large its Jacobian is against ||x||.  The dog leg's step test stops once
 * a step is 1e-12 of ||x||; when J is large (the short edges along a
 * densely sampled boundary: the curve below with m = 10^5 vertices) a
 * Gauss-Newton step that short still cuts F by orders, and the solve
 * used to end above F = 1e-10, unsolved.  lambda = 1e6 makes the
 * tangential rows 10^6 times larger on a 300-vertex copy of that curve
 * (435 interior points): it ended unsolved the same way (F 3.6e-9 after
 * its last round), and now reaches the bound by the Newton tail
 * (plateau__solve_sparse_solve).  The system's solution does not depend on
 * lambda (paper II.D, square): the same triangles as lambda = 1, and the
 * same area to 1e-9. */
static plateau_result solve_curve_lambda(size_t m, double lambda, plateau_mesh *mesh, plateau_report *rep)
{
    double polygon[3 * 300];
    plateau_options o;
    wavy_circle(polygon, m, 0.3, 3.0);
    memset(&o, 0, sizeof o);
    memset(mesh, 0, sizeof *mesh);
    o.lambda = lambda;
    o.accuracy = -1.0; /* one solve at n = m */
    o.coarse_to_fine = PLATEAU_OFF;
    o.stability = PLATEAU_OFF;
    return plateau_solve(polygon, m, &o, mesh, rep, NULL);
}

static void test_solved_with_large_jacobian(void)
{
    plateau_mesh m1, m6;
    plateau_report r1, r6;
    if (CHECK_EQ_INT(solve_curve_lambda(300, 1.0, &m1, &r1), PLATEAU_OK) &&
        CHECK_EQ_INT(solve_curve_lambda(300, 1e6, &m6, &r6), PLATEAU_OK)) {
        CHECK_EQ_INT(r6.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK(r1.solved);
        CHECK(r6.solved);
        CHECK_EQ_INT(r1.defects, 0);
        CHECK_EQ_INT(r6.defects, 0);
        CHECK(same_triangles(&m1, &m6));
        CHECK_NEAR(r6.area, r1.area, 1e-9 * r1.area);
        printf("  curve m = 300, %lu interior points: lambda 1: F %.1e, area %.12f; lambda 1e6: F %.1e, "
               "area %.12f, stop %s\n",
               (unsigned long)r6.interior_points, r1.f_final, r1.area, r6.f_final, r6.area,
               plateau_lm_stop_string(r6.lm_stop));
    }
    plateau_mesh_free(&m1);
    plateau_mesh_free(&m6);
}

/* Method paper's rounds end once the area's drop from one solve to the
 * next is below 1e-6 of it, or once the drops shrink so fast that the
 * rest, continuing geometrically, adds up to less (plateau__drv_paper_done).
 * A curve whose rounds end by the second rule (4 rounds before it, 3 now):
 * going on with the rounds from its mesh (plateau_mesh_minimize) lowers
 * the area by less than that bound. */
static void test_rounds_geometric_end(void)
{
    static double xyz[3 * 400];
    double drop = 0.0;
    size_t m = 400;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep, more;
    /* the rule on its own: never before round 3; below 1e-6 ends; a
     * drop that grew, or shrank too slowly, does not */
    CHECK(!plateau__drv_paper_done(1.0, 1.0, 2, &drop));
    drop = 1e-5;
    CHECK(plateau__drv_paper_done(1.0 - 5e-7, 1.0, 3, &drop)); /* below 1e-6 */
    CHECK_NEAR(drop, 5e-7, 1e-15);
    drop = 1e-5;
    CHECK(plateau__drv_paper_done(1.0 - 2e-6, 1.0, 3, &drop)); /* q = 0.2: 5e-7 to come */
    drop = 1e-5;
    CHECK(!plateau__drv_paper_done(1.0 - 5e-6, 1.0, 3, &drop)); /* q = 0.5: 5e-6 to come */
    drop = 1e-6;
    CHECK(!plateau__drv_paper_done(1.0 - 2e-6, 1.0, 4, &drop)); /* grew */
    drop = 1e-5;
    CHECK(plateau__drv_paper_done(1.0 + 1e-7, 1.0, 3, &drop)); /* the area went up */
    wavy_circle(xyz, m, 0.5, 4.0);
    memset(&o, 0, sizeof o);
    o.interior_points = 2000;
    if (CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, NULL), PLATEAU_OK)) {
        CHECK_EQ_INT(rep.defects, 0);
        CHECK_EQ_INT(rep.rounds, 3);
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_CONVERGED);
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_PAPER;
        if (CHECK_EQ_INT(plateau_mesh_minimize(&mesh, &o, &more, NULL), PLATEAU_OK)) {
            CHECK_EQ_INT(more.defects, 0);
            CHECK(fabs(rep.area - more.area) < 1e-6 * rep.area);
            printf("  curve m = 400, n = 2000: %lu rounds, area %.12f; %lu rounds more: %.12f (%.1e)\n",
                   (unsigned long)rep.rounds, rep.area, (unsigned long)more.rounds, more.area,
                   (rep.area - more.area) / rep.area);
        }
    }
    plateau_mesh_free(&mesh);
}

/* The analytic area Hessian of method area's Newton method (3 x 3 blocks
 * on the 1-ring pattern) against central differences of the analytic
 * gradient (plateau_mesh_area_gradient), step 1e-6 on a unit-size mesh:
 * truncation ~1e-12 times the third derivative, rounding ~1e-16 / 1e-6;
 * measured max error 1.1e-10 against entries up to 4.2. */
static void test_area_hessian(void)
{
    const demo_case *c = demo_find("helicoid");
    double polygon[3 * DEMO_MAX_BOUNDARY], *hv = NULL, *lv = NULL, *gp = NULL, *gm = NULL;
    double maxerr = 0.0, maxh = 0.0, asym = 0.0;
    size_t m = demo_boundary(c, polygon), nv, nfree = 0, v, i = 0, nb;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau__solve_sparse sp;
    plateau_index *node = NULL;
    double *xy = NULL;
    void *pm = NULL;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 30;
    o.max_rounds = 1;
    o.max_iterations = 3; /* a curved mesh away from the minimum */
    if (!CHECK_EQ_INT(plateau_solve(polygon, m, &o, &mesh, &rep, NULL), PLATEAU_OK)) return;
    nv = mesh.num_vertices;
    for (v = 0; v < nv; v++) nfree += !mesh.fixed[v];
    memset(&sp, 0, sizeof sp);
    pm = plateau__solve_sparse_pattern(&mesh, nfree, &sp, &xy);
    node = (plateau_index *)malloc(nv * sizeof *node);
    gp = (double *)malloc(3 * nv * sizeof(double));
    gm = (double *)malloc(3 * nv * sizeof(double));
    if (CHECK(pm && node && gp && gm)) {
        for (v = 0; v < nv; v++) node[v] = mesh.fixed[v] ? -1 : (plateau_index)i++;
        nb = (size_t)sp.row_start[nfree];
        hv = (double *)malloc(9 * nb * sizeof(double));
        lv = (double *)malloc(9 * nb * sizeof(double));
        if (CHECK(hv && lv) && CHECK_EQ_INT(plateau__solve_area_hessian(&mesh, node, nfree, &sp, hv, lv), 0)) {
            for (v = 0; v < nv; v++) {
                int cc;
                if (mesh.fixed[v]) continue;
                for (cc = 0; cc < 3; cc++) {
                    const double step = 1e-6;
                    double save = mesh.positions[3 * v + (size_t)cc];
                    size_t q;
                    mesh.positions[3 * v + (size_t)cc] = save + step;
                    plateau_mesh_area_gradient(&mesh, gp);
                    mesh.positions[3 * v + (size_t)cc] = save - step;
                    plateau_mesh_area_gradient(&mesh, gm);
                    mesh.positions[3 * v + (size_t)cc] = save;
                    /* block (v, w), entry (cc, r) = d2A / dv_cc dw_r = d g_(w, r) / d v_cc */
                    for (q = (size_t)sp.row_start[node[v]]; q < (size_t)sp.row_start[node[v] + 1]; q++) {
                        size_t w;
                        int r;
                        for (w = 0; w < nv; w++)
                            if (node[w] == sp.cols[q]) break;
                        for (r = 0; r < 3; r++) {
                            double fd = (gp[3 * w + (size_t)r] - gm[3 * w + (size_t)r]) / (2.0 * step);
                            double an = hv[9 * q + 3 * (size_t)cc + (size_t)r];
                            if (fabs(fd - an) > maxerr) maxerr = fabs(fd - an);
                            if (fabs(an) > maxh) maxh = fabs(an);
                        }
                    }
                }
            }
            /* both triangles of the storage agree (the Cholesky reads one) */
            for (i = 0; i < nfree; i++) {
                size_t q, q2;
                for (q = (size_t)sp.row_start[i]; q < (size_t)sp.row_start[i + 1]; q++) {
                    size_t j = (size_t)sp.cols[q];
                    int r, s2;
                    for (q2 = (size_t)sp.row_start[j]; q2 < (size_t)sp.row_start[j + 1]; q2++)
                        if ((size_t)sp.cols[q2] == i) break;
                    for (r = 0; r < 3; r++)
                        for (s2 = 0; s2 < 3; s2++) {
                            double d1 = fabs(hv[9 * q + 3 * (size_t)r + (size_t)s2] - hv[9 * q2 + 3 * (size_t)s2 + (size_t)r]);
                            double d2 = fabs(lv[9 * q + 3 * (size_t)r + (size_t)s2] - lv[9 * q2 + 3 * (size_t)s2 + (size_t)r]);
                            if (d1 > asym) asym = d1;
                            if (d2 > asym) asym = d2;
                        }
                }
            }
            printf("  area Hessian: max |H - central differences| = %.2e, max |H| = %.2e, asymmetry %.1e\n",
                   maxerr, maxh, asym);
            CHECK(maxh > 0.1);
            CHECK(maxerr <= 1e-8 * maxh);
            CHECK(asym <= 1e-14 * maxh);
        }
    }
    free(hv);
    free(lv);
    free(gp);
    free(gm);
    free(node);
    plateau__free(&mesh.allocator, pm);
    plateau_mesh_free(&mesh);
}

/* Method area: the L-BFGS (DENSE) and the sparse Newton method (SPARSE)
 * minimise the same area with the same flips between the solves.  Where
 * they end on the same triangles (measured, with area_tolerance 1e-9:
 * the paper seeding at n = 25 on helicoid, catenoid and the Scherk strip,
 * and at n = 50 on the helicoid) the areas agree to 1e-9 relative at most
 * (the L-BFGS stops when its area falls by less than 1e-10 over 20 steps,
 * still creeping; the Newton method ends on the gradient test): bound
 * 2e-8.  At larger n the flips see other geometry on
 * the way and the two end on other triangulations, local minima whose
 * areas differ by up to 2.4e-4 relative (membrane, n = 200; both signs,
 * about as often each): bound 1e-3 there.  The Newton result is valid
 * (defects 0) everywhere, in at most a fifth of the L-BFGS steps (measured
 * 9 to 28 times fewer). */
static void compare_area(const char *name, size_t n, int same)
{
    const demo_case *c = demo_find(name);
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m;
    plateau_options o;
    plateau_mesh md, ms;
    plateau_report rd, rs;
    char msg[128];
    if (!CHECK(c != NULL)) return;
    m = demo_boundary(c, polygon);
    sprintf(msg, "area, %s, n = %lu", name, (unsigned long)n);
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = n;
    o.seed = DEMO_SEED;
    o.linear_solver = PLATEAU_LINEAR_DENSE;
    o.area_tolerance = 1e-9; /* the Newton solves as tight as the L-BFGS */
    o.coarse_to_fine = PLATEAU_OFF; /* the rounds at full size: their two solvers */
    memset(&md, 0, sizeof md);
    memset(&ms, 0, sizeof ms);
    if (CHECK_EQ_INT(plateau_solve(polygon, m, &o, &md, &rd, NULL), PLATEAU_OK) &&
        (o.linear_solver = PLATEAU_LINEAR_SPARSE,
         CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ms, &rs, NULL), PLATEAU_OK))) {
        double rel = fabs(rs.area - rd.area) / rd.area;
        CHECK_EQ_INT(rs.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK_MSG(rs.solved, msg);
        CHECK_EQ_INT(rs.defects, 0);
        CHECK_MSG(rel <= (same ? 2e-8 : 1e-3), msg);
        if (same) CHECK_MSG(same_triangles(&md, &ms), msg);
        CHECK_MSG(rs.iterations * 5 < rd.iterations, msg);
        printf("  area %-12s n = %4lu: iterations %5zu / %4zu, rounds %2zu / %2zu, area %.12f / %.12f "
               "(%.1e relative)\n",
               name, (unsigned long)rd.interior_points, rd.iterations, rs.iterations, rd.rounds, rs.rounds,
               rd.area, rs.area, rel);
    }
    plateau_mesh_free(&md);
    plateau_mesh_free(&ms);
}

/* One solve of the Newton method (max_rounds 1: no flips after it;
 * area_tolerance 1e-9) ends on the gradient or the area-change test, or
 * where no step lowers the area in rounding (the helicoid: mu past 1e12
 * with every gradient below 1e-8 lbar), the area gradient small (below
 * 1e-8 of the mean edge length) at all free vertices but those it held
 * (the corners of a triangle its step would turn over, left to the flips)
 * and their neighbours where it stopped on the area change: measured 2, 0,
 * 2 and 23 of 100 free vertices (helicoid, catenoid, Scherk strip,
 * membrane), bound a third. */
static void test_area_gradient(void)
{
    static const char *names[] = {"helicoid", "catenoid", "scherk-b1-m", "membrane"};
    size_t i;
    for (i = 0; i < 4; i++) {
        const demo_case *c = demo_find(names[i]);
        double polygon[3 * DEMO_MAX_BOUNDARY], *g;
        size_t m = demo_boundary(c, polygon), v, large = 0, nfree = 0;
        plateau_options o;
        plateau_mesh ms;
        plateau_report rs;
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_AREA;
        o.interior_points = 100;
        o.seed = DEMO_SEED;
        o.max_rounds = 1;
        o.linear_solver = PLATEAU_LINEAR_SPARSE;
        o.area_tolerance = 1e-9;
        if (!CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ms, &rs, NULL), PLATEAU_OK)) continue;
        CHECK_MSG(rs.area_stop == PLATEAU_AREA_STOP_GRADIENT || rs.area_stop == PLATEAU_AREA_STOP_SMALL_CHANGE ||
                      rs.area_stop == PLATEAU_AREA_STOP_LINE_SEARCH,
                  plateau_area_stop_string(rs.area_stop));
        g = (double *)malloc(3 * ms.num_vertices * sizeof(double));
        if (CHECK(g != NULL)) {
            double tol = 1e-8 * plateau_mean_edge_length(&ms);
            plateau_mesh_area_gradient(&ms, g);
            for (v = 0; v < ms.num_vertices; v++) {
                if (ms.fixed[v]) continue;
                nfree++;
                large += fabs(g[3 * v]) > tol || fabs(g[3 * v + 1]) > tol || fabs(g[3 * v + 2]) > tol;
            }
            printf("  %-12s one solve: %lu Newton steps, gradient above 1e-8 lbar at %lu of %lu free vertices\n",
                   names[i], (unsigned long)rs.iterations, (unsigned long)large, (unsigned long)nfree);
            CHECK(large * 3 <= nfree);
        }
        free(g);
        plateau_mesh_free(&ms);
    }
}

/* options.area_tolerance: the default 1e-6 stops the Newton solves
 * earlier than 1e-9 (fewer steps) and the rounds end within their own
 * 3e-5 of the tight result (measured on the helicoid at n = 400: see the
 * printed line). */
static void test_area_tolerance(void)
{
    const demo_case *c = demo_find("helicoid");
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, polygon);
    plateau_options o;
    plateau_mesh ml, mt;
    plateau_report rl, rt;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 400;
    o.seed = DEMO_SEED;
    o.coarse_to_fine = PLATEAU_OFF; /* the rounds' Newton method, which area_tolerance stops */
    memset(&ml, 0, sizeof ml);
    memset(&mt, 0, sizeof mt);
    if (CHECK_EQ_INT(plateau_solve(polygon, m, &o, &ml, &rl, NULL), PLATEAU_OK) &&
        (o.area_tolerance = 1e-9, CHECK_EQ_INT(plateau_solve(polygon, m, &o, &mt, &rt, NULL), PLATEAU_OK))) {
        double rel = (rl.area - rt.area) / rt.area;
        CHECK_EQ_INT(rl.linear_solver, PLATEAU_LINEAR_SPARSE);
        CHECK_EQ_INT(rl.defects, 0);
        CHECK_EQ_INT(rt.defects, 0);
        CHECK(rl.iterations < rt.iterations);
        CHECK(fabs(rel) < 3e-5);
        printf("  area_tolerance 1e-6 / 1e-9, helicoid n = 400: %lu / %lu Newton steps, area %.10f / %.10f "
               "(%.1e relative)\n",
               (unsigned long)rl.iterations, (unsigned long)rt.iterations, rl.area, rt.area, rel);
    }
    plateau_mesh_free(&ml);
    plateau_mesh_free(&mt);
}

static void test_area_dense_vs_sparse(void)
{
    static const char *names[] = {"helicoid", "catenoid", "scherk-b1-m"};
    size_t i;
    for (i = 0; i < 3; i++) {
        compare_area(names[i], 25, 1);
        compare_area(names[i], 50, i == 0);
        compare_area(names[i], 200, 0);
    }
    compare_area("membrane", 100, 0);
#ifndef PLATEAU_TEST_SANITIZED /* the L-BFGS takes 5-10 s at n = 1000 */
    if (HARNESS_FULL) compare_area("catenoid", 1000, 0);
#endif
}

/* ---- the time limit's predictions (options.max_seconds) ---- */

/* a clock that reads what the test set */
static double tp_clock(void *user)
{
    return *(const double *)user;
}

/* A phase that cannot end before the deadline does not start: the
 * budget's helpers, and the dog leg's iteration, predicted from the last
 * one's seconds or, before the first, from 8 residual evaluations
 * (PLATEAU__SOLVE_JAC_PER_RES); the LU's cancel says stop only once the
 * budget has run out. */
static void test_time_predictor(void)
{
    double now = 4.0;
    plateau__util_budget b, part;
    plateau__solve_ctx ctx;
    plateau__solve_sparse sp;
    memset(&b, 0, sizeof b);
    b.clock_fn = tp_clock;
    b.clock_user = &now;
    b.deadline = 10.0;
    CHECK(plateau__util_time_fits(NULL, 1e300));
    CHECK(plateau__util_time_fits(&b, 5.0));
    CHECK(!plateau__util_time_fits(&b, 7.0));
    CHECK(!b.expired && !b.interrupted); /* a refusal is not the deadline */
    CHECK_NEAR(plateau__util_time_left(&b), 6.0, 0.0);
    /* the seeding's share: 0.3 of the 6 seconds left (the figure of the
     * manual's options.max_seconds), a budget of its own */
    CHECK(PLATEAU__SEED_TIME_SHARE == 0.3);
    plateau__util_time_share(&part, &b, PLATEAU__SEED_TIME_SHARE);
    CHECK_NEAR(part.deadline, 4.0 + PLATEAU__SEED_TIME_SHARE * 6.0, 1e-15);
    CHECK(b.deadline == 10.0);
    now = 7.0;
    CHECK(plateau__util_time_up(&part) && !plateau__util_time_up(&b));
    now = 4.0;
    memset(&ctx, 0, sizeof ctx);
    ctx.budget = &b;
    sp.ctx = &ctx;
    ctx.res_seconds = 0.5; /* the first Jacobian: 8 x 0.5 = 4 <= 6 */
    CHECK(plateau__solve_jac_fits(&ctx) && !b.interrupted);
    ctx.res_seconds = 1.0; /* 8 > 6: not begun, the solve stops there */
    CHECK(!plateau__solve_jac_fits(&ctx));
    CHECK(b.interrupted && !b.expired);
    b.interrupted = 0;
    ctx.iter_seconds = 2.0; /* the last iteration's seconds rule once known */
    CHECK(plateau__solve_jac_fits(&ctx) && !b.interrupted);
    ctx.iter_seconds = 6.5;
    CHECK(!plateau__solve_jac_fits(&ctx));
    b.interrupted = 0;
    ctx.budget = NULL; /* no budget: always */
    CHECK(plateau__solve_jac_fits(&ctx));
    ctx.budget = &b;
    CHECK(!plateau__solve_sparse_cancel(&sp) && !b.interrupted);
    now = 10.0; /* the deadline: the LU stops, the solve is cut */
    CHECK(plateau__solve_sparse_cancel(&sp) && b.interrupted && b.expired);
    CHECK(!plateau__util_time_fits(&b, 0.0));
}

int main(void)
{
    RUN(test_dense_vs_sparse);
    RUN(test_auto_choice);
    RUN(test_progress_abort);
    RUN(test_solved_with_large_jacobian);
    RUN(test_rounds_geometric_end);
    RUN(test_area_hessian);
    RUN(test_area_gradient);
    RUN(test_area_tolerance);
    RUN(test_area_dense_vs_sparse);
    RUN(test_time_predictor);
    return harness_report("test_solve_paths");
}
