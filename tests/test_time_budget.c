/* test_time_budget.c - options.max_seconds: a solve stops at its next
 * iteration or round once the budget has passed, with the mesh it has and
 * report.stop PLATEAU_STOP_TIME_LIMIT, on every solver path (dense LM,
 * sparse dog leg, L-BFGS, sparse Newton, method paper's area presolve,
 * plateau_mesh_minimize); a budget that never runs out changes nothing,
 * bit for bit; bad values are refused.  The clock is a counter
 * (options.clock_fn): one "second" per reading, so that every run is
 * exactly repeatable and nothing here depends on the machine's speed. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"

#define TB_PI 3.14159265358979323846

/* one "second" per reading */
static double tb_counter(void *user)
{
    size_t *n = (size_t *)user;
    return (double)(*n)++;
}

/* A saddle-shaped ring of m vertices (z = 0.4 cos 2t). */
static void tb_saddle(double *xyz, size_t m)
{
    size_t i;
    for (i = 0; i < m; i++) {
        double t = 2.0 * TB_PI * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.4 * cos(2.0 * t);
    }
}

/* A solve with a counter clock and budget `seconds` (0: none), the clock
 * readings it made into *readings. */
static plateau_result tb_solve(const double *xyz, size_t m, plateau_options opt, double seconds,
                               plateau_mesh *mesh, plateau_report *rep, size_t *readings)
{
    size_t n = 0;
    plateau_result r;
    if (seconds != 0.0) {
        opt.max_seconds = seconds;
        opt.clock_fn = tb_counter;
        opt.clock_user = &n;
    }
    r = plateau_solve(xyz, m, &opt, mesh, rep, NULL);
    if (readings) *readings = n;
    return r;
}

/* For one option set: the budget 1e12 gives the unbudgeted mesh bit for
 * bit; budgets cut at the first check, halfway and just before the end
 * give TIME_LIMIT, a usable mesh (the boundary unchanged, every position
 * finite, the check run), no more rounds than the whole solve, and the
 * reported area that of the mesh returned. */
static void tb_paths(const char *name, const double *xyz, size_t m, plateau_options opt)
{
    plateau_mesh full, mesh;
    plateau_report rf, rep;
    size_t readings = 0, i, k;
    double cuts[3];
    CHECK_EQ_INT(tb_solve(xyz, m, opt, 0.0, &full, &rf, NULL), PLATEAU_OK);
    CHECK(rf.stop != PLATEAU_STOP_TIME_LIMIT);
    CHECK_EQ_INT(tb_solve(xyz, m, opt, 1e12, &mesh, &rep, &readings), PLATEAU_OK);
    CHECK_EQ_INT(mesh.num_vertices, full.num_vertices);
    CHECK(mesh.num_vertices == full.num_vertices &&
          memcmp(mesh.positions, full.positions, 3 * full.num_vertices * sizeof(double)) == 0);
    CHECK(rep.area == rf.area && rep.stop == rf.stop && rep.rounds == rf.rounds);
    CHECK(readings > 4);
    plateau_mesh_free(&mesh);
    cuts[0] = 1.0;
    cuts[1] = (double)(readings / 2);
    cuts[2] = (double)(readings - 3);
    for (k = 0; k < 3; k++) {
        int finite = 1, same = 1;
        CHECK_EQ_INT(tb_solve(xyz, m, opt, cuts[k], &mesh, &rep, NULL), PLATEAU_OK);
        /* the last readings are the final check's and the error
         * estimate's: a budget that runs out at the estimate leaves the
         * solve whole and the estimate not formed */
        if (!CHECK(rep.stop == PLATEAU_STOP_TIME_LIMIT ||
                   (k == 2 && rep.estimate == PLATEAU_ESTIMATE_TIME_LIMIT && rep.stop == rf.stop &&
                    rep.area == rf.area)))
            fprintf(stderr, "  %s, budget %g of %lu readings: check_cut %d, estimate %d\n", name, cuts[k],
                    (unsigned long)readings, rep.check_cut, (int)rep.estimate);
        CHECK(rep.rounds <= rf.rounds);
        for (i = 0; i < 3 * mesh.num_vertices; i++) finite &= mesh.positions[i] - mesh.positions[i] == 0.0;
        for (i = 0; i < 3 * m; i++) same &= mesh.positions[i] == xyz[i];
        CHECK(finite);
        CHECK(same);
        CHECK_REL(rep.area, plateau_mesh_area(&mesh), 1e-12, 1e-300);
        if (k == 0) { /* at the first check: the seeded mesh, no solve */
            CHECK_EQ_INT(rep.rounds, 0);
            CHECK(rep.defects & PLATEAU_DEFECT_UNSOLVED);
            /* its smallest angle measured once, by the final check */
            CHECK(rep.initial_min_angle_deg >= 0.0 && rep.initial_min_angle_deg == rep.min_angle_deg);
        }
        plateau_mesh_free(&mesh);
    }
    printf("  %s: %lu clock readings in the whole solve (%lu rounds, stop: %s)\n", name,
           (unsigned long)readings, (unsigned long)rf.rounds, plateau_stop_string(rf.stop));
    plateau_mesh_free(&full);
}

static void test_every_path_stops_and_a_long_budget_changes_nothing(void)
{
    double xyz[3 * 48];
    plateau_options opt;
    tb_saddle(xyz, 24);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 40;
    tb_paths("paper, dense LM", xyz, 24, opt);
    opt.method = PLATEAU_METHOD_AREA;
    tb_paths("area, L-BFGS", xyz, 24, opt);
    opt.method = PLATEAU_METHOD_PAPER_LITERAL;
    tb_paths("paper-literal", xyz, 24, opt);
    opt.method = PLATEAU_METHOD_PAPER;
    opt.force_circle_domain = 1; /* method paper after method area's presolve */
    tb_paths("paper on the circle (area presolve)", xyz, 24, opt);
    opt.force_circle_domain = 0;
    tb_saddle(xyz, 48);
    opt.interior_points = 300;
    tb_paths("paper, sparse dog leg", xyz, 48, opt);
    opt.method = PLATEAU_METHOD_AREA;
    tb_paths("area, sparse Newton", xyz, 48, opt);
}

/* Two rings (plateau_solve_loops; paper-literal probes the film for a
 * pinch with a copy run through method area's rounds, which shares the
 * deadline but not the cut): stopped in the rounds, TIME_LIMIT; in the
 * probe, the rounds' own result; never a pinch invented; a long budget
 * changes nothing. */
static void test_two_loops(void)
{
    double xyz[3 * 48];
    size_t counts[2] = {24, 24}, i, n = 0, readings, stopped = 0;
    plateau_options opt;
    plateau_mesh mesh, full;
    plateau_report rep, rf;
    for (i = 0; i < 48; i++) {
        double t = 2.0 * TB_PI * (double)(i % 24) / 24.0;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < 24 ? -0.4 : 0.4;
    }
    memset(&opt, 0, sizeof opt);
    opt.method = PLATEAU_METHOD_PAPER_LITERAL;
    opt.interior_points = 60;
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &full, &rf, NULL), PLATEAU_OK);
    CHECK(rf.stop != PLATEAU_STOP_PINCHED);
    opt.clock_fn = tb_counter;
    opt.clock_user = &n;
    opt.max_seconds = 1e12;
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK(rep.area == rf.area && rep.stop == rf.stop && mesh.num_vertices == full.num_vertices &&
          memcmp(mesh.positions, full.positions, 3 * full.num_vertices * sizeof(double)) == 0);
    plateau_mesh_free(&mesh);
    readings = n;
    for (i = 0; i < 7; i++) { /* cut early in the rounds, later maybe in the probe */
        static const size_t early[3] = {2, 3, 5};
        n = 0;
        opt.max_seconds = (double)(i < 3 ? early[i] : readings * (i - 2) / 5);
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rep, NULL), PLATEAU_OK);
        CHECK(rep.stop == PLATEAU_STOP_TIME_LIMIT || rep.stop == rf.stop);
        CHECK(!(rep.defects & PLATEAU_DEFECT_PINCHED));
        stopped += rep.stop == PLATEAU_STOP_TIME_LIMIT;
        plateau_mesh_free(&mesh);
    }
    CHECK(stopped > 0);
    plateau_mesh_free(&full);
}

/* plateau_mesh_minimize takes the budget too: from the seeded mesh (a
 * budget of one reading), 3 readings stop it, a long one finishes. */
static void test_minimize(void)
{
    double xyz[3 * 24];
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    size_t n = 0;
    tb_saddle(xyz, 24);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 40;
    CHECK_EQ_INT(tb_solve(xyz, 24, opt, 1.0, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.rounds, 0);
    opt.max_seconds = 3.0;
    opt.clock_fn = tb_counter;
    opt.clock_user = &n;
    CHECK_EQ_INT(plateau_mesh_minimize(&mesh, &opt, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.stop, PLATEAU_STOP_TIME_LIMIT);
    CHECK(rep.defects & PLATEAU_DEFECT_UNSOLVED);
    n = 0;
    opt.max_seconds = 1e12;
    CHECK_EQ_INT(plateau_mesh_minimize(&mesh, &opt, &rep, NULL), PLATEAU_OK);
    CHECK(rep.stop != PLATEAU_STOP_TIME_LIMIT);
    CHECK_EQ_INT(rep.defects, 0);
    plateau_mesh_free(&mesh);
}

/* Two coaxial rings of radius 1 and m vertices each, h apart. */
static void tb_rings(double *xyz, size_t m, double h)
{
    size_t i;
    for (i = 0; i < 2 * m; i++) {
        double t = 2.0 * TB_PI * (double)(i % m) / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < m ? -0.5 * h : 0.5 * h;
    }
}

/* The saddle search of critical_index reads the clock before every
 * Newton step: a budget that runs out two readings into the search stops
 * it there (TIME_LIMIT, not converged, unsolved) instead of after all its
 * steps; a long budget changes nothing. */
static void test_critical_search_stops(void)
{
    double xyz[3 * 64];
    size_t counts[2] = {32, 32}, n = 0, before;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep, rf;
    tb_rings(xyz, 32, 1.0);
    memset(&opt, 0, sizeof opt);
    opt.alternatives = PLATEAU_OFF;
    opt.stability = PLATEAU_OFF;
    opt.clock_fn = tb_counter;
    opt.clock_user = &n;
    opt.max_seconds = 1e12;
    /* the readings of the rounds alone */
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rep, NULL), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    before = n;
    opt.critical_index = 1;
    n = 0;
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rf, NULL), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(rf.critical_converged, 1);
    CHECK(rf.critical_steps > 4);
    n = 0;
    opt.max_seconds = (double)(before + 2);
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.stop, PLATEAU_STOP_TIME_LIMIT);
    CHECK_EQ_INT(rep.critical_converged, 0);
    CHECK(!rep.solved && (rep.defects & PLATEAU_DEFECT_UNSOLVED));
    if (!CHECK(rep.critical_steps <= 2))
        fprintf(stderr, "  %lu steps after the budget ran out (%lu in the whole search)\n",
                (unsigned long)rep.critical_steps, (unsigned long)rf.critical_steps);
    CHECK_REL(rep.area, plateau_mesh_area(&mesh), 1e-12, 1e-300);
    plateau_mesh_free(&mesh);
    printf("  critical search: %lu steps whole, %lu with the budget two readings into it\n",
           (unsigned long)rf.critical_steps, (unsigned long)rep.critical_steps);
}

/* Method paper's stopping rule is a property of the mesh (F at rounding
 * level): a time-limited result is solved exactly when the mesh returned
 * meets it (the sparse dog leg, 2 rounds with flips between them).
 * Every cut from the first reading to the last: a result
 * reported solved has every free vertex's mean curvature at the solved
 * mesh's level (no flips after the solve it was measured on), and cuts
 * after the first solve give solved results. */
static void test_time_limited_solved_means_solved(void)
{
    double xyz[3 * 48], hfull = 0.0;
    plateau_options opt;
    plateau_mesh full, mesh;
    plateau_report rf, rep;
    size_t readings = 0, cut, v, solved = 0, wrong = 0;
    tb_saddle(xyz, 48);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 300;
    opt.stability = PLATEAU_OFF;
    CHECK_EQ_INT(tb_solve(xyz, 48, opt, 1e12, &full, &rf, &readings), PLATEAU_OK);
    CHECK(rf.solved && rf.rounds > 1);
    for (v = 0; v < full.num_vertices; v++)
        if (!full.fixed[v] && fabs(plateau_vertex_mean_curvature(&full, v)) > hfull)
            hfull = fabs(plateau_vertex_mean_curvature(&full, v));
    for (cut = 1; cut < readings; cut++) {
        double h = 0.0;
        CHECK_EQ_INT(tb_solve(xyz, 48, opt, (double)cut, &mesh, &rep, NULL), PLATEAU_OK);
        for (v = 0; v < mesh.num_vertices; v++)
            if (!mesh.fixed[v] && fabs(plateau_vertex_mean_curvature(&mesh, v)) > h)
                h = fabs(plateau_vertex_mean_curvature(&mesh, v));
        if (rep.solved) {
            solved++;
            if (!(h <= 100.0 * hfull + 1e-6)) {
                wrong++;
                fprintf(stderr, "  cut %lu: solved, stop %s, largest |H| %.3g (solved mesh: %.3g)\n",
                        (unsigned long)cut, plateau_stop_string(rep.stop), h, hfull);
            }
        }
        plateau_mesh_free(&mesh);
    }
    CHECK_EQ_INT(wrong, 0);
    CHECK(solved > 0);
    printf("  %lu cuts, %lu of them solved (largest |H| of the whole solve %.2e)\n",
           (unsigned long)(readings - 1), (unsigned long)solved, hfull);
    plateau_mesh_free(&full);
}

/* A budget that runs out in the seeding of a dense polygon (a circle of
 * 1 000 vertices, n = 1 500: the angle bound's grading from the polygon
 * sets a floor above n whatever the area limit, where the whole search
 * settles).  The seeding takes its share of the time left
 * (PLATEAU__SEED_TIME_SHARE), and its refinement stops at its next clock
 * reading (one as it starts, one every 1 024 vertices) once that share
 * has run out; the points made are kept when the memory bound admits
 * their count, as it does here, so a cut seeding is the seeded mesh, not
 * the polygon's triangulation (the polygon's alone only when the budget
 * ran out as the refinement started).  options.max_memory set to admit
 * n but not the floor: a cut with more than n points is replaced by one
 * refinement of at most n, in a new share of the time left (no point
 * when that share runs out as it starts: the polygon's triangulation,
 * all that the budget and the bound allow).  The result
 * says it was cut: stop TIME_LIMIT, not solved, no error estimate (the
 * mesh was never solved). */
static void test_cut_seeding_within_n(void)
{
    const size_t m = 1000, n = 1500;
    double *xyz = (double *)malloc(3 * m * sizeof(double));
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep, rf;
    size_t i, most = 0, empty = 0, over = 0, budget, cut;
    int tight;
    for (i = 0; i < m; i++) {
        double t = 2.0 * TB_PI * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.0;
    }
    memset(&opt, 0, sizeof opt);
    opt.interior_points = n;
    opt.stability = PLATEAU_OFF;
    opt.coarse_to_fine = PLATEAU_OFF;
    CHECK_EQ_INT(tb_solve(xyz, m, opt, 0.0, &mesh, &rf, NULL), PLATEAU_OK);
    CHECK(rf.seeded_points > n); /* the floor: the case the cut must handle */
    plateau_mesh_free(&mesh);
    for (tight = 0; tight < 2; tight++) {
        /* tight: the memory bound admits n interior points, not the floor */
        opt.max_memory = tight ? (size_t)plateau_memory_estimate(PLATEAU_METHOD_PAPER, m, n) : 0;
        most = empty = over = cut = 0;
        for (budget = 1; budget <= 24; budget++) {
            plateau_result r = tb_solve(xyz, m, opt, (double)budget, &mesh, &rep, NULL);
            /* tight: the whole seeding's floor may be refused by the bound */
            if (tight && r == PLATEAU_ERR_MEMORY_LIMIT) continue;
            if (!CHECK_EQ_INT(r, PLATEAU_OK)) continue;
            if (rep.seeded_points != rf.seeded_points) {
                cut++;
                if (rep.seeded_points > n) over++;
                /* budgets up to 4 readings: the seeding's share of them
                 * runs out at the refinement's first reading */
                if (rep.seeded_points == 0 && budget > 4) empty++;
                if (rep.seeded_points > most) most = rep.seeded_points;
            }
            CHECK_EQ_INT(rep.stop, PLATEAU_STOP_TIME_LIMIT);
            /* never solved, even the polygon's triangulation (no free
             * vertex) when the time left was enough to check it whole */
            if (!CHECK(!rep.solved && (rep.defects & PLATEAU_DEFECT_UNSOLVED)))
                fprintf(stderr, "  budget %lu%s: %lu points, solved %d\n", (unsigned long)budget,
                        tight ? " (memory bound at n)" : "", (unsigned long)rep.seeded_points, rep.solved);
            CHECK_EQ_INT(rep.estimate, PLATEAU_ESTIMATE_TIME_LIMIT);
            plateau_mesh_free(&mesh);
        }
        CHECK(cut > 0);
        if (tight) {
            CHECK_EQ_INT(over, 0);
        } else {
            CHECK_EQ_INT(empty, 0); /* a cut that had time for points keeps them */
            CHECK(over > 0);        /* more than n, admitted by the bound */
        }
        CHECK(most > n / 2); /* cut seedings get far */
        printf("  seeding for n = %lu%s: %lu points whole, %lu cuts, at most %lu when cut\n", (unsigned long)n,
               tight ? " (memory bound at n)" : "", (unsigned long)rf.seeded_points, (unsigned long)cut,
               (unsigned long)most);
    }
    free(xyz);
}

/* The final check reads the clock too: a budget that ran out before it
 * (here at the first reading after the start) cuts its search for
 * intersecting triangles, and the report says so (check_cut, stop
 * TIME_LIMIT, not solved); a budget that never runs out leaves the search
 * whole.  plateau_mesh_check, without a budget, always searches all. */
static void test_final_check_cut(void)
{
    double xyz[3 * 48];
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_quality q;
    tb_saddle(xyz, 48);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 400;
    opt.stability = PLATEAU_OFF;
    CHECK_EQ_INT(tb_solve(xyz, 48, opt, 1e12, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.check_cut, 0);
    CHECK_EQ_INT(rep.defects, 0);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(tb_solve(xyz, 48, opt, 1.0, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.check_cut, 1);
    CHECK_EQ_INT(rep.stop, PLATEAU_STOP_TIME_LIMIT);
    CHECK(!rep.solved && (rep.defects & PLATEAU_DEFECT_UNSOLVED));
    if (CHECK_EQ_INT(plateau_mesh_check(&mesh, &q, NULL), PLATEAU_OK)) CHECK_EQ_INT(q.intersecting_pairs, 0);
    plateau_mesh_free(&mesh);
}

/* Negative and NaN budgets are refused; an infinite one is no limit. */
static void test_bad_values(void)
{
    double xyz[3 * 24], nan = 0.0;
    plateau_options opt;
    plateau_mesh mesh, full;
    plateau_report rep, rf;
    plateau_error err;
    tb_saddle(xyz, 24);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 20;
    opt.max_seconds = -1.0;
    CHECK_EQ_INT(plateau_solve(xyz, 24, &opt, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "max_seconds") != NULL);
    nan = nan / nan;
    opt.max_seconds = nan;
    CHECK_EQ_INT(plateau_solve(xyz, 24, &opt, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    opt.max_seconds = HUGE_VAL;
    CHECK_EQ_INT(plateau_solve(xyz, 24, &opt, &mesh, &rep, &err), PLATEAU_OK);
    opt.max_seconds = 0.0;
    CHECK_EQ_INT(plateau_solve(xyz, 24, &opt, &full, &rf, &err), PLATEAU_OK);
    CHECK(mesh.num_vertices == full.num_vertices && rep.area == rf.area &&
          memcmp(mesh.positions, full.positions, 3 * full.num_vertices * sizeof(double)) == 0);
    plateau_mesh_free(&mesh);
    plateau_mesh_free(&full);
    /* the default clock (clock() of <time.h>): a generous budget runs out
     * never on a solve this small */
    opt.max_seconds = 1e6;
    CHECK_EQ_INT(plateau_solve(xyz, 24, &opt, &mesh, &rep, &err), PLATEAU_OK);
    CHECK(rep.stop != PLATEAU_STOP_TIME_LIMIT);
    CHECK(rep.area == rf.area);
    plateau_mesh_free(&mesh);
}

int main(void)
{
    RUN(test_every_path_stops_and_a_long_budget_changes_nothing);
    RUN(test_two_loops);
    RUN(test_minimize);
    RUN(test_critical_search_stops);
    RUN(test_time_limited_solved_means_solved);
    RUN(test_cut_seeding_within_n);
    RUN(test_final_check_cut);
    RUN(test_bad_values);
    return harness_report("test_time_budget");
}
