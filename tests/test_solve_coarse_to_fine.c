/* test_solve_coarse_to_fine.c - plateau_solve's coarse-to-fine path
 * (options.coarse_to_fine): the subdivision keeps the polygon bit for bit
 * and puts the new boundary vertices on its straight edges; a plane polygon
 * gives its own plane region; on the demo's helicoid and catenoid polygons
 * the area converges as h^2 (order 1 in 1/n) to the extrapolated optimum;
 * the stopping rule's answer is within 1 % of the discrete optimum's excess
 * (against a much tighter solve of the same mesh); the interior count is
 * honoured within 10 %; method paper's last level solves H_i = 0; the
 * option's errors, the automatic choice and options.max_seconds.  The
 * implementation is compiled here so that the tighter solve can call the
 * level's Newton method. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"
#include "examples/surfaces.h"

#ifdef PLATEAU_TEST_SANITIZED
#define C2F_HEAVY 0
#else
#define C2F_HEAVY HARNESS_FULL /* make test: the sanitizers' sizes */
#endif

static size_t c2f_polygon(const char *name, double *xyz)
{
    const demo_case *c = demo_find(name);
    return c ? demo_boundary(c, xyz) : 0;
}

static plateau_result c2f_solve(const double *xyz, size_t m, plateau_method method, size_t n,
                                plateau_switch c2f, plateau_mesh *mesh, plateau_report *rep)
{
    plateau_options o;
    memset(&o, 0, sizeof o);
    o.method = method;
    o.interior_points = n;
    o.coarse_to_fine = c2f;
    return plateau_solve(xyz, m, &o, mesh, rep, NULL);
}

/* Distance of p from the segment ab over |ab|. */
static double c2f_off_segment(const double *p, const double *a, const double *b)
{
    double d[3], e[3], t, len2 = 0.0, dist2 = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        d[k] = b[k] - a[k];
        e[k] = p[k] - a[k];
        len2 += d[k] * d[k];
    }
    t = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / len2;
    if (t < 0.0 || t > 1.0) return 1.0;
    for (k = 0; k < 3; k++) dist2 += (e[k] - t * d[k]) * (e[k] - t * d[k]);
    return sqrt(dist2 / len2);
}

/* The polygon bit for bit as the first m vertices, then exactly
 * boundary_points_added fixed vertices, each on a polygon edge, then the
 * free ones; also for the polygon scaled and moved. */
static void test_boundary_bit_for_bit(void)
{
    double xyz[3 * DEMO_MAX_BOUNDARY], moved[3 * DEMO_MAX_BOUNDARY];
    size_t m = c2f_polygon("helicoid", xyz), i, v;
    int method, pass;
    for (i = 0; i < 3 * m; i++) moved[i] = 1e6 * xyz[i] + (double)(i % 3) * 3.5e6;
    for (pass = 0; pass < 2; pass++) {
        const double *poly = pass ? moved : xyz;
        for (method = 0; method < 3; method += 2) {
            plateau_mesh mesh;
            plateau_report rep;
            double worst = 0.0;
            size_t nfixed = 0;
            if (!CHECK_EQ_INT(c2f_solve(poly, m, (plateau_method)method, 3000, PLATEAU_ON, &mesh, &rep),
                              PLATEAU_OK))
                continue;
            CHECK(rep.levels >= 2);
            CHECK_EQ_INT((int)rep.defects, 0);
            CHECK(memcmp(mesh.positions, poly, 3 * m * sizeof(double)) == 0);
            for (v = 0; v < mesh.num_vertices; v++) nfixed += mesh.fixed[v] != 0;
            CHECK_EQ_INT((long)nfixed, (long)(m + rep.boundary_points_added));
            for (v = 0; v < m + rep.boundary_points_added; v++) CHECK(mesh.fixed[v]);
            for (v = m; v < m + rep.boundary_points_added; v++) {
                double best = 1.0;
                for (i = 0; i < m; i++) {
                    double off = c2f_off_segment(mesh.positions + 3 * v, poly + 3 * i, poly + 3 * ((i + 1) % m));
                    if (off < best) best = off;
                }
                if (best > worst) worst = best;
            }
            CHECK(worst < 1e-14); /* the midpoint of two doubles, rounded */
            if (pass == 0)
                printf("boundary, %s: %lu polygon vertices bit for bit, %lu added on its edges "
                       "(largest distance from the edge %.1e of its length), %lu levels\n",
                       plateau_method_name((plateau_method)method), (unsigned long)m,
                       (unsigned long)rep.boundary_points_added, worst, (unsigned long)rep.levels);
            plateau_mesh_free(&mesh);
        }
    }
}

/* A plane polygon spans its own plane region: the shoelace area, every
 * vertex on the plane. */
static void test_plane_region(void)
{
    double xyz[3 * 40], exact = 0.0, n[3] = {0.36, -0.48, 0.8};
    size_t m = 40, i, v;
    plateau_mesh mesh;
    plateau_report rep;
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m, r = 1.0 + 0.25 * cos(3.0 * t);
        double x = r * cos(t), y = r * sin(t);
        /* the plane through the origin with normal n: basis (0.8, 0.6, 0), n x that */
        double e1[3] = {0.8, 0.6, 0.0}, e2[3];
        e2[0] = n[1] * e1[2] - n[2] * e1[1];
        e2[1] = n[2] * e1[0] - n[0] * e1[2];
        e2[2] = n[0] * e1[1] - n[1] * e1[0];
        xyz[3 * i] = x * e1[0] + y * e2[0];
        xyz[3 * i + 1] = x * e1[1] + y * e2[1];
        xyz[3 * i + 2] = x * e1[2] + y * e2[2];
    }
    for (i = 0; i < m; i++) {
        /* shoelace in the plane's own coordinates */
        const double *a = xyz + 3 * i, *b = xyz + 3 * ((i + 1) % m);
        double c[3];
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
        exact += 0.5 * (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]);
    }
    exact = fabs(exact);
    if (CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, 2000, PLATEAU_ON, &mesh, &rep), PLATEAU_OK)) {
        double off = 0.0;
        for (v = 0; v < mesh.num_vertices; v++) {
            const double *p = mesh.positions + 3 * v;
            off = fmax(off, fabs(p[0] * n[0] + p[1] * n[1] + p[2] * n[2]));
        }
        CHECK(rep.levels > 0);
        CHECK_NEAR(rep.area, exact, 1e-12 * exact);
        CHECK(off < 1e-12);
        CHECK_EQ_INT((int)rep.defects, 0);
        printf("plane polygon: area %.15f, exact %.15f, largest distance from the plane %.1e\n",
               rep.area, exact, off);
        plateau_mesh_free(&mesh);
    }
}

/* Convergence: A(n) = A* + C n^-p; three runs at n, 4n, 16n give
 * p = log4((A1 - A2) / (A2 - A3)) and A*.  Order 2 in h is p = 1. */
static void test_convergence(void)
{
    static const char *names[2] = {"helicoid", "catenoid"};
    int s;
    for (s = 0; s < 2; s++) {
        double xyz[3 * DEMO_MAX_BOUNDARY], a[3], p, astar;
        size_t m = c2f_polygon(names[s], xyz), n0 = C2F_HEAVY ? 1500 : 600;
        int k, ok = 1;
        for (k = 0; k < 3 && ok; k++) {
            plateau_mesh mesh;
            plateau_report rep;
            size_t n = n0 << (2 * k);
            ok = CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, n, PLATEAU_ON, &mesh, &rep), PLATEAU_OK);
            if (!ok) break;
            CHECK_EQ_INT((int)rep.defects, 0);
            CHECK_EQ_INT(rep.area_stop, PLATEAU_AREA_STOP_DECREMENT);
            a[k] = rep.area;
            plateau_mesh_free(&mesh);
        }
        if (!ok) continue;
        CHECK(a[0] > a[1] && a[1] > a[2]);
        p = log((a[0] - a[1]) / (a[1] - a[2])) / log(4.0);
        astar = a[2] - (a[1] - a[2]) / (pow(4.0, p) - 1.0);
        printf("convergence, %s: areas %.9f %.9f %.9f at n = %lu, %lu, %lu: order %.2f in 1/n "
               "(%.2f in h), extrapolated %.9f\n",
               names[s], a[0], a[1], a[2], (unsigned long)n0, (unsigned long)(4 * n0),
               (unsigned long)(16 * n0), p, 2.0 * p, astar);
        CHECK(p > 0.8 && p < 1.25);
        CHECK(astar < a[2]);
    }
}

/* The stopping rule: the answer's excess over the discrete optimum of the
 * same mesh (Newton on normal motions run to its end: tolerance 0) is at
 * most 1 % of that optimum's excess over the polygon's, A* extrapolated
 * from the levels of two tighter runs; the same for a helicoid. */
static void test_stopping_rule(void)
{
    static const char *names[2] = {"helicoid", "catenoid"};
    int s;
    for (s = 0; s < 2; s++) {
        double xyz[3 * DEMO_MAX_BOUNDARY], a_big[2], astar, a_tight;
        size_t m = c2f_polygon(names[s], xyz), n = C2F_HEAVY ? 4000 : 1200, k;
        plateau_mesh mesh, big;
        plateau_report rep, brep, trep;
        plateau__cfg cfg;
        plateau__cfg_run run;
        int ok = 1;
        /* A* from 4n and 16n (order 2 in h) */
        for (k = 0; k < 2 && ok; k++) {
            ok = CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, n << (2 * (k + 1)), PLATEAU_ON, &big,
                                        &brep), PLATEAU_OK);
            if (ok) a_big[k] = brep.area;
            plateau_mesh_free(&big);
        }
        if (!ok || !CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, n, PLATEAU_ON, &mesh, &rep), PLATEAU_OK))
            continue;
        astar = a_big[1] - (a_big[0] - a_big[1]) / 3.0;
        CHECK_EQ_INT(plateau__cfg_resolve(NULL, m, &cfg, NULL), PLATEAU_OK);
        plateau__cfg_run_start(&cfg, &run);
        memset(&trep, 0, sizeof trep);
        /* prev_area = the area itself: tolerance 0, the steps run to the end */
        CHECK_EQ_INT(plateau__c2f_normal_newton(&mesh, &cfg, &run, 1, rep.area, &trep, NULL), PLATEAU_OK);
        a_tight = trep.f_final;
        printf("stopping rule, %s, n = %lu: area %.10f, tighter solve %.10f (%lu more steps), "
               "A* %.10f: the answer's excess is %.4f of the discrete optimum's, above it by "
               "%.2e of it\n",
               names[s], (unsigned long)rep.interior_points, rep.area, a_tight,
               (unsigned long)trep.iterations, astar, (rep.area - astar) / (a_tight - astar),
               (rep.area - a_tight) / (a_tight - astar));
        /* no step taken: the same mesh, its area summed twice (the
         * report's in the caller's units), equal to rounding */
        CHECK(a_tight <= rep.area * (1.0 + PLATEAU__C2F_FLOOR));
        CHECK(a_tight > astar);
        CHECK(rep.area - a_tight <= 0.01 * (a_tight - astar));
        plateau_mesh_free(&mesh);
    }
}

/* interior_points honoured within 10 % over a range of n; method paper's
 * last level solves its H_i = 0 (F at the final check's bound) with an area
 * close to method area's. */
static void test_counts_and_paper(void)
{
    static const char *names[2] = {"helicoid", "catenoid"};
    static const size_t ns[5] = {1000, 2500, 7000, 20000, 60000};
    int s, k, count = C2F_HEAVY ? 5 : 3;
    for (s = 0; s < 2; s++) {
        double xyz[3 * DEMO_MAX_BOUNDARY];
        size_t m = c2f_polygon(names[s], xyz);
        for (k = 0; k < count; k++) {
            plateau_mesh ma, mp;
            plateau_report ra, rp;
            double off;
            if (!CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, ns[k], PLATEAU_AUTO, &ma, &ra), PLATEAU_OK))
                continue;
            off = (double)ra.interior_points / (double)ns[k] - 1.0;
            CHECK(ra.levels > 0);
            CHECK(fabs(off) <= 0.10);
            CHECK_EQ_INT((int)ra.defects, 0);
            if (k < 3 && CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_PAPER, ns[k], PLATEAU_AUTO, &mp, &rp),
                                      PLATEAU_OK)) {
                CHECK(rp.levels == ra.levels);
                CHECK(rp.f_final <= 1e-10);
                CHECK_EQ_INT((int)rp.defects, 0);
                CHECK_EQ_INT((long)rp.interior_points, (long)ra.interior_points);
                CHECK(fabs(rp.area - ra.area) <= 1e-6 * ra.area);
                printf("  %s n = %5lu: %5lu interior (%+.1f %%), %lu levels; area %.9f, paper %.9f "
                       "(F %.1e)\n",
                       names[s], (unsigned long)ns[k], (unsigned long)ra.interior_points, 100.0 * off,
                       (unsigned long)ra.levels, ra.area, rp.area, rp.f_final);
                plateau_mesh_free(&mp);
            }
            plateau_mesh_free(&ma);
        }
    }
}

/* The option: OFF and below PLATEAU_COARSE_TO_FINE_POINTS the rounds at
 * full size; ON with a conflicting option PLATEAU_ERR_ARGUMENT; the report
 * and the resolved options. */
static void test_option(void)
{
    double xyz[3 * DEMO_MAX_BOUNDARY], rings[3 * 32];
    size_t m = c2f_polygon("helicoid", xyz), counts[2] = {16, 16}, i;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, 1500, PLATEAU_OFF, &mesh, &rep), PLATEAU_OK);
    CHECK_EQ_INT((int)rep.levels, 0);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_AREA, PLATEAU_COARSE_TO_FINE_POINTS - 1, PLATEAU_AUTO, &mesh,
                           &rep), PLATEAU_OK);
    CHECK_EQ_INT((int)rep.levels, 0);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(c2f_solve(xyz, m, PLATEAU_METHOD_PAPER_LITERAL, 1500, PLATEAU_ON, &mesh, &rep),
                 PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    memset(&o, 0, sizeof o);
    o.interior_points = 1500;
    o.coarse_to_fine = PLATEAU_ON;
    o.refine_boundary = PLATEAU_OFF;
    CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "coarse_to_fine") != NULL);
    plateau_mesh_free(&mesh);
    o.refine_boundary = PLATEAU_AUTO;
    o.seeding = PLATEAU_SEEDING_PAPER;
    CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    o.seeding = PLATEAU_SEEDING_AUTO;
    o.coarse_to_fine = (plateau_switch)2;
    CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(plateau_resolved_options(&o, m).coarse_to_fine, 2);
    /* several loops: ON refused, AUTO the rounds */
    for (i = 0; i < 32; i++) {
        double t = 6.283185307179586 * (double)(i % 16) / 16.0;
        rings[3 * i] = cos(t);
        rings[3 * i + 1] = sin(t);
        rings[3 * i + 2] = i < 16 ? -0.4 : 0.4;
    }
    o.coarse_to_fine = PLATEAU_ON;
    o.interior_points = 1200;
    CHECK_EQ_INT(plateau_solve_loops(rings, counts, 2, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    CHECK(strcmp(plateau_area_stop_string(PLATEAU_AREA_STOP_DECREMENT), "Newton decrement test") == 0);
    /* options.max_seconds: a budget that has run out at the first level
     * gives the mesh reached, stopped by the time limit, not solved */
    memset(&o, 0, sizeof o);
    o.interior_points = 3000;
    o.method = PLATEAU_METHOD_AREA;
    o.coarse_to_fine = PLATEAU_ON;
    o.max_seconds = 1e-300;
    if (CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_OK)) {
        CHECK_EQ_INT(rep.stop, PLATEAU_STOP_TIME_LIMIT);
        CHECK(rep.defects & PLATEAU_DEFECT_UNSOLVED);
        CHECK(memcmp(mesh.positions, xyz, 3 * m * sizeof(double)) == 0);
    }
    plateau_mesh_free(&mesh);
}

/* The memory bound of the path (plateau_memory_estimate's comment) holds
 * for the peak of a counting allocator, within 1.3 times it (a bound far
 * above the peak refuses solves that fit: 1.7 times, and n = 10^6 refused
 * by the 2 GiB default, with 800 bytes more per point), and a limit below
 * the rounds' own bound but above this one lets the solve run (the error
 * estimate after it runs when its own bound, plateau__acc_memory, fits
 * too, and then the peak is the larger of the two bounds). */
static void test_memory(void)
{
    double xyz[3 * DEMO_MAX_BOUNDARY];
    size_t m = c2f_polygon("helicoid", xyz), ns[2] = {10000, 40000}, k;
    int method, count = C2F_HEAVY ? 2 : 1;
    for (k = 0; k < (size_t)count; k++)
        for (method = 0; method < 3; method += 2) {
            countalloc ca;
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            double bound, rounds, acc;
            size_t n = ns[k];
            memset(&o, 0, sizeof o);
            countalloc_init(&ca, 0);
            o.method = (plateau_method)method;
            o.interior_points = n;
            o.allocator = countalloc_allocator(&ca);
            bound = plateau__cfg_c2f_estimate((double)m, (double)n);
            rounds = plateau_memory_estimate(o.method, m, n);
            o.max_memory = (size_t)(0.5 * (bound + rounds));
            if (!CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, NULL), PLATEAU_OK)) continue;
            CHECK(rep.levels > 0);
            /* the error estimate after the solve, when its own bound fits */
            acc = plateau__acc_memory(&mesh);
            CHECK_EQ_INT(rep.estimate, acc > (double)o.max_memory ? PLATEAU_ESTIMATE_MEMORY : PLATEAU_ESTIMATE_FORMED);
            if (rep.estimate == PLATEAU_ESTIMATE_FORMED && acc > bound) bound = acc;
            CHECK((double)ca.bytes_peak <= bound);
            CHECK(bound <= 1.3 * (double)ca.bytes_peak);
            CHECK(bound < rounds);
            printf("memory, %s n = %lu: peak %.1f MB, bound %.1f MB (the rounds' bound %.1f MB)\n",
                   plateau_method_name(o.method), (unsigned long)n, (double)ca.bytes_peak / 1048576.0,
                   bound / 1048576.0, rounds / 1048576.0);
            plateau_mesh_free(&mesh);
            CHECK_EQ_INT(ca.live, 0);
        }
}

/* The error estimate's memory bound (plateau__acc_memory: the result's
 * arrays and PLATEAU__ACC_BYTES_PER_VERTEX per vertex of the subdivided
 * mesh) holds for the peak of a counting allocator while it runs on a
 * result of 10^3, 10^4 (and 10^5) interior points, within 1.3 times it. */
static void test_estimate_memory(void)
{
    double xyz[3 * DEMO_MAX_BOUNDARY];
    size_t m = c2f_polygon("helicoid", xyz), ns[3] = {1000, 10000, 100000}, k;
    for (k = 0; k < (C2F_HEAVY ? 3u : 2u); k++) {
        countalloc ca;
        plateau_allocator al;
        plateau_options o;
        plateau_mesh mesh, copy;
        plateau_report rep, est;
        plateau__cfg cfg;
        double bound;
        memset(&o, 0, sizeof o);
        o.interior_points = ns[k];
        o.stability = PLATEAU_OFF;
        if (!CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, NULL), PLATEAU_OK)) continue;
        countalloc_init(&ca, 0);
        al = countalloc_allocator(&ca);
        if (CHECK_EQ_INT(plateau_mesh_create(mesh.positions, mesh.num_vertices, mesh.fixed, mesh.triangles,
                                             mesh.num_triangles, &al, &copy, NULL), PLATEAU_OK)) {
            memset(&cfg, 0, sizeof cfg);
            cfg.max_memory = (size_t)-1;
            memset(&est, 0, sizeof est);
            CHECK_EQ_INT(plateau__acc_report(&copy, &cfg, NULL, NULL, &est, NULL), PLATEAU_OK);
            CHECK_EQ_INT(est.estimate, PLATEAU_ESTIMATE_FORMED);
            bound = plateau__acc_memory(&copy);
            printf("estimate memory, n = %lu: peak %.2f MB (%.0f bytes per subdivided vertex, the result included), bound %.2f MB\n",
                   (unsigned long)ns[k], (double)ca.bytes_peak / 1048576.0,
                   (double)ca.bytes_peak / (double)(copy.num_vertices + copy.num_edges), bound / 1048576.0);
            CHECK((double)ca.bytes_peak <= bound);
            CHECK(bound <= 1.3 * (double)ca.bytes_peak);
            plateau_mesh_free(&copy);
            CHECK_EQ_INT(ca.live, 0);
        }
        plateau_mesh_free(&mesh);
    }
}

int main(void)
{
    RUN(test_boundary_bit_for_bit);
    RUN(test_plane_region);
    RUN(test_convergence);
    RUN(test_stopping_rule);
    RUN(test_counts_and_paper);
    RUN(test_option);
    RUN(test_memory);
    RUN(test_estimate_memory);
    return harness_report("test_solve_coarse_to_fine");
}
