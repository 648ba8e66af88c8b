/* test_threads.c - determinism and thread safety.
 *
 * The same input gives bit-identical output: two sequential runs agree, and
 * four threads running at once (all on the same input, then each on its
 * own, then the coarse-to-fine path) agree bit for bit with the sequential
 * run.  The library needs no
 * threads and has no global state; only this test uses pthreads.  Each
 * thread gets its own counting allocator (its context comes from the call),
 * and one pass uses the default allocator. */
#define _POSIX_C_SOURCE 200809L
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

#include <pthread.h>

#define NUM_THREADS 4
#define REPEATS 3

/* ---------------------------------------------------------------- inputs */
/* A small deterministic generator for the test inputs (not the library's). */
static uint64_t lcg_state;
static double lcg_uniform(void)
{
    lcg_state = lcg_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(lcg_state >> 11) * (1.0 / 9007199254740992.0);
}

#define NUM_POLYGONS 6
#define MAX_M 40
typedef struct polygon {
    const char *name;
    double xyz[3 * MAX_M];
    size_t m;
    plateau_method method;
    size_t n;
    plateau_switch c2f; /* options.coarse_to_fine */
} polygon;
static polygon polygons[NUM_POLYGONS];

static void make_polygons(void)
{
    size_t i;
    polygon *p;
    const double pi = 3.14159265358979323846;
    /* a saddle over the square, 12 vertices */
    p = &polygons[0];
    p->name = "saddle";
    p->m = 12;
    for (i = 0; i < 12; i++) {
        double t = (double)i / 3.0, x, y;
        int side = (int)(i / 3);
        double f = t - side;
        x = side == 0 ? -1 + 2 * f : side == 1 ? 1 : side == 2 ? 1 - 2 * f : -1;
        y = side == 0 ? -1 : side == 1 ? -1 + 2 * f : side == 2 ? 1 : 1 - 2 * f;
        p->xyz[3 * i] = x;
        p->xyz[3 * i + 1] = y;
        p->xyz[3 * i + 2] = 0.5 * x * y;
    }
    p->method = PLATEAU_METHOD_PAPER;
    p->n = 10;
    /* a wavy circle: a regular polygon with z = 0.3 sin(3 t) */
    p = &polygons[1];
    p->name = "wavy circle";
    p->m = 24;
    for (i = 0; i < p->m; i++) {
        double t = 2 * pi * (double)i / (double)p->m;
        p->xyz[3 * i] = cos(t);
        p->xyz[3 * i + 1] = sin(t);
        p->xyz[3 * i + 2] = 0.3 * sin(3 * t);
    }
    p->method = PLATEAU_METHOD_AREA;
    p->n = 16;
    /* a helicoid boundary: two rulings and two helix arcs */
    p = &polygons[2];
    p->name = "helicoid";
    p->m = 28;
    {
        size_t k = 0;
        int j;
        const double b = 1.9;
        for (j = 0; j < 7; j++) { /* u from -1 to 1 at v = -pi/4 */
            double u = -1 + 2.0 * j / 7, v = -pi / 4;
            p->xyz[3 * k] = u * cos(v); p->xyz[3 * k + 1] = u * sin(v); p->xyz[3 * k + 2] = b * v; k++;
        }
        for (j = 0; j < 7; j++) { /* v from -pi/4 to pi/4 at u = 1 */
            double u = 1, v = -pi / 4 + (pi / 2) * j / 7;
            p->xyz[3 * k] = u * cos(v); p->xyz[3 * k + 1] = u * sin(v); p->xyz[3 * k + 2] = b * v; k++;
        }
        for (j = 0; j < 7; j++) { /* u from 1 to -1 at v = pi/4 */
            double u = 1 - 2.0 * j / 7, v = pi / 4;
            p->xyz[3 * k] = u * cos(v); p->xyz[3 * k + 1] = u * sin(v); p->xyz[3 * k + 2] = b * v; k++;
        }
        for (j = 0; j < 7; j++) { /* v from pi/4 to -pi/4 at u = -1 */
            double u = -1, v = pi / 4 - (pi / 2) * j / 7;
            p->xyz[3 * k] = u * cos(v); p->xyz[3 * k + 1] = u * sin(v); p->xyz[3 * k + 2] = b * v; k++;
        }
    }
    p->method = PLATEAU_METHOD_PAPER;
    p->n = 20;
    /* a random star-shaped polygon, the literal method */
    p = &polygons[3];
    p->name = "random star";
    p->m = 15;
    lcg_state = 42;
    for (i = 0; i < p->m; i++) {
        double t = 2 * pi * (double)i / (double)p->m, r = 0.7 + 0.5 * lcg_uniform();
        p->xyz[3 * i] = r * cos(t);
        p->xyz[3 * i + 1] = r * sin(t);
        p->xyz[3 * i + 2] = 0.4 * (lcg_uniform() - 0.5);
    }
    p->method = PLATEAU_METHOD_PAPER_LITERAL;
    p->n = 8;
    /* the helicoid coarse to fine, methods area and paper (the coarse
     * mesh, two levels of subdivision and Newton steps) */
    for (i = 4; i < 6; i++) {
        p = &polygons[i];
        *p = polygons[2];
        p->name = i == 4 ? "helicoid, coarse to fine, area" : "helicoid, coarse to fine, paper";
        p->method = i == 4 ? PLATEAU_METHOD_AREA : PLATEAU_METHOD_PAPER;
        p->n = 1500;
        p->c2f = PLATEAU_ON;
    }
}

#define NUM_POINT_SETS 5
#define MAX_POINTS 2000
typedef struct point_set {
    const char *name;
    double pts[2 * MAX_POINTS];
    size_t np;
    plateau_index segs[2 * 64];
    size_t ns;
    double min_angle; /* > 0: Delaunay refinement */
} point_set;
static point_set point_sets[NUM_POINT_SETS];

static void make_point_sets(void)
{
    size_t i, j;
    point_set *s;
    const double pi = 3.14159265358979323846;
    /* uniform random points, the convex hull */
    s = &point_sets[0];
    s->name = "random";
    lcg_state = 7;
    s->np = MAX_POINTS;
    for (i = 0; i < 2 * s->np; i++) s->pts[i] = lcg_uniform();
    s->ns = 0;
    /* a grid (co-circular everywhere: the tie-breaking rule decides) */
    s = &point_sets[1];
    s->name = "grid";
    s->np = 0;
    for (j = 0; j < 30; j++)
        for (i = 0; i < 30; i++) {
            s->pts[2 * s->np] = (double)i;
            s->pts[2 * s->np + 1] = (double)j;
            s->np++;
        }
    s->ns = 0;
    /* a constrained circle with random points inside */
    s = &point_sets[2];
    s->name = "circle with inside points";
    s->np = 0;
    for (i = 0; i < 64; i++) {
        double t = 2 * pi * (double)i / 64.0;
        s->pts[2 * s->np] = cos(t);
        s->pts[2 * s->np + 1] = sin(t);
        s->segs[2 * i] = (plateau_index)i;
        s->segs[2 * i + 1] = (plateau_index)((i + 1) % 64);
        s->np++;
    }
    s->ns = 64;
    lcg_state = 99;
    while (s->np < 600) {
        double x = 2 * lcg_uniform() - 1, y = 2 * lcg_uniform() - 1;
        if (x * x + y * y < 0.95) {
            s->pts[2 * s->np] = x;
            s->pts[2 * s->np + 1] = y;
            s->np++;
        }
    }
    /* duplicates and collinear runs */
    s = &point_sets[3];
    s->name = "duplicates and collinear";
    s->np = 0;
    for (i = 0; i < 300; i++) {
        s->pts[2 * s->np] = (double)(i % 50);
        s->pts[2 * s->np + 1] = (double)((i * 7) % 3) * ((i % 50) == 0 ? 1.0 : 0.0);
        s->np++;
    }
    s->pts[2 * s->np] = 25;
    s->pts[2 * s->np + 1] = 10;
    s->np++;
    s->ns = 0;
    /* the constrained circle again, refined to 30 degrees */
    point_sets[4] = point_sets[2];
    point_sets[4].name = "circle refined to 30 degrees";
    point_sets[4].min_angle = 30.0;
}

/* ---------------------------------------------------------------- results */
typedef struct solve_result {
    int rc;
    plateau_mesh mesh;
    plateau_report report;
} solve_result;

typedef struct dt_result {
    int rc;
    plateau_dt_mesh mesh;
} dt_result;

static void run_solve(const polygon *p, const plateau_allocator *a, solve_result *out)
{
    plateau_options opt;
    memset(&opt, 0, sizeof opt);
    opt.method = p->method;
    opt.interior_points = p->n;
    opt.coarse_to_fine = p->c2f;
    if (a) opt.allocator = *a;
    memset(&out->mesh, 0, sizeof out->mesh);
    memset(&out->report, 0, sizeof out->report);
    out->rc = plateau_solve(p->xyz, p->m, &opt, &out->mesh, &out->report, NULL);
}

static void run_dt(const point_set *s, const plateau_allocator *a, dt_result *out)
{
    plateau_dt_input in;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    if (a) opt.allocator = *a;
    opt.min_angle = s->min_angle;
    in.points = s->pts;
    in.num_points = s->np;
    in.segments = s->ns ? s->segs : NULL;
    in.num_segments = s->ns;
    memset(&out->mesh, 0, sizeof out->mesh);
    out->rc = plateau_dt_triangulate(&in, &opt, &out->mesh, NULL);
}

#define SAME_ARRAY(a, b, count) \
    ((count) == 0 || ((a) && (b) && memcmp((a), (b), (count) * sizeof *(a)) == 0))

static int same_solve(const solve_result *x, const solve_result *y)
{
    const plateau_mesh *a = &x->mesh, *b = &y->mesh;
    const plateau_report *r = &x->report, *s = &y->report;
    return x->rc == y->rc && a->num_vertices == b->num_vertices &&
           a->num_triangles == b->num_triangles &&
           SAME_ARRAY(a->positions, b->positions, 3 * a->num_vertices) &&
           SAME_ARRAY(a->fixed, b->fixed, a->num_vertices) &&
           SAME_ARRAY(a->triangles, b->triangles, 3 * a->num_triangles) &&
           SAME_ARRAY(a->neighbors, b->neighbors, 3 * a->num_triangles) &&
           r->rounds == s->rounds && r->iterations == s->iterations &&
           r->evaluations == s->evaluations && r->flips == s->flips && r->stop == s->stop &&
           memcmp(&r->f_final, &s->f_final, sizeof(double)) == 0 &&
           memcmp(&r->area, &s->area, sizeof(double)) == 0 &&
           memcmp(&r->min_angle_deg, &s->min_angle_deg, sizeof(double)) == 0;
}

static int same_dt(const dt_result *x, const dt_result *y)
{
    const plateau_dt_mesh *a = &x->mesh, *b = &y->mesh;
    return x->rc == y->rc && a->num_points == b->num_points &&
           a->num_input_points == b->num_input_points &&
           a->num_triangles == b->num_triangles &&
           SAME_ARRAY(a->points, b->points, 2 * a->num_points) &&
           SAME_ARRAY(a->duplicate_of, b->duplicate_of, a->num_input_points) &&
           SAME_ARRAY(a->triangles, b->triangles, 3 * a->num_triangles) &&
           SAME_ARRAY(a->neighbors, b->neighbors, 3 * a->num_triangles) &&
           SAME_ARRAY(a->constrained, b->constrained, 3 * a->num_triangles);
}

/* ---------------------------------------------------------------- threads */
static solve_result solve_ref[NUM_POLYGONS];
static dt_result dt_ref[NUM_POINT_SETS];

typedef struct job {
    int kind;         /* 0: plateau_solve, 1: plateau_dt_triangulate */
    int input;        /* -1: input (thread id) modulo the count; else that input */
    int use_counting; /* per-thread counting allocator, else the default */
    int id;
    pthread_barrier_t *barrier;
    int mismatches, leaks, failures;
} job;

static void *worker(void *arg)
{
    job *j = (job *)arg;
    int r;
    countalloc ca;
    plateau_allocator a;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    pthread_barrier_wait(j->barrier);
    for (r = 0; r < REPEATS; r++) {
        if (j->kind == 0) {
            int i = j->input >= 0 ? j->input : j->id % NUM_POLYGONS;
            solve_result res;
            run_solve(&polygons[i], j->use_counting ? &a : NULL, &res);
            if (res.rc != PLATEAU_OK) j->failures++;
            if (!same_solve(&res, &solve_ref[i])) j->mismatches++;
            plateau_mesh_free(&res.mesh);
        } else {
            int i = j->input >= 0 ? j->input : j->id % NUM_POINT_SETS;
            dt_result res;
            run_dt(&point_sets[i], j->use_counting ? &a : NULL, &res);
            if (res.rc != PLATEAU_DT_OK) j->failures++;
            if (!same_dt(&res, &dt_ref[i])) j->mismatches++;
            plateau_dt_free(&res.mesh);
        }
        if (ca.live != 0 || ca.bad != 0) j->leaks++;
    }
    return NULL;
}

static void run_threads(int kind, int input, int use_counting, const char *what)
{
    pthread_t th[NUM_THREADS];
    job jobs[NUM_THREADS];
    pthread_barrier_t barrier;
    int i, mismatches = 0, leaks = 0, failures = 0;
    pthread_barrier_init(&barrier, NULL, NUM_THREADS);
    for (i = 0; i < NUM_THREADS; i++) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].kind = kind;
        jobs[i].input = input;
        jobs[i].use_counting = use_counting;
        jobs[i].id = i;
        jobs[i].barrier = &barrier;
        CHECK(pthread_create(&th[i], NULL, worker, &jobs[i]) == 0);
    }
    for (i = 0; i < NUM_THREADS; i++) {
        pthread_join(th[i], NULL);
        mismatches += jobs[i].mismatches;
        leaks += jobs[i].leaks;
        failures += jobs[i].failures;
    }
    pthread_barrier_destroy(&barrier);
    if (!CHECK_EQ_INT(mismatches, 0)) fprintf(stderr, "  %s: results differ\n", what);
    if (!CHECK_EQ_INT(leaks, 0)) fprintf(stderr, "  %s: blocks leaked\n", what);
    if (!CHECK_EQ_INT(failures, 0)) fprintf(stderr, "  %s: calls failed\n", what);
}

/* ---------------------------------------------------------------- tests */
static void test_solve_sequential(void)
{
    int i;
    for (i = 0; i < NUM_POLYGONS; i++) {
        solve_result again;
        countalloc ca;
        plateau_allocator a;
        run_solve(&polygons[i], NULL, &solve_ref[i]);
        if (!CHECK_EQ_INT(solve_ref[i].rc, PLATEAU_OK))
            fprintf(stderr, "  polygon %s: %s\n", polygons[i].name,
                    plateau_result_string((plateau_result)solve_ref[i].rc));
        CHECK(solve_ref[i].mesh.num_vertices > polygons[i].m);
        CHECK(polygons[i].c2f != PLATEAU_ON || solve_ref[i].report.levels > 0);
        run_solve(&polygons[i], NULL, &again);
        CHECK_MSG(same_solve(&again, &solve_ref[i]), "two sequential runs are bit-identical");
        plateau_mesh_free(&again.mesh);
        /* the allocator does not change the result */
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        run_solve(&polygons[i], &a, &again);
        CHECK_MSG(same_solve(&again, &solve_ref[i]), "the allocator does not change the mesh");
        plateau_mesh_free(&again.mesh);
        CHECK_EQ_INT(ca.live, 0);
        CHECK_NEAR(again.report.area, solve_ref[i].report.area, 0.0);
    }
}

static void test_solve_threads(void)
{
    int i;
    run_threads(0, 0, 1, "plateau_solve, 4 threads, the same input");
    run_threads(0, 2, 0, "plateau_solve, 4 threads, the same input, default allocator");
    run_threads(0, -1, 1, "plateau_solve, 4 threads, different inputs");
    run_threads(0, -1, 0, "plateau_solve, 4 threads, different inputs, default allocator");
    run_threads(0, 4, 1, "plateau_solve, 4 threads, coarse to fine, area");
    run_threads(0, 5, 0, "plateau_solve, 4 threads, coarse to fine, paper, default allocator");
    for (i = 0; i < NUM_POLYGONS; i++) plateau_mesh_free(&solve_ref[i].mesh);
}

static void test_dt_sequential(void)
{
    int i;
    for (i = 0; i < NUM_POINT_SETS; i++) {
        dt_result again;
        run_dt(&point_sets[i], NULL, &dt_ref[i]);
        if (!CHECK_EQ_INT(dt_ref[i].rc, PLATEAU_DT_OK))
            fprintf(stderr, "  point set %s: %s\n", point_sets[i].name,
                    plateau_dt_result_string((plateau_dt_result)dt_ref[i].rc));
        CHECK(dt_ref[i].mesh.num_triangles > 0);
        run_dt(&point_sets[i], NULL, &again);
        CHECK_MSG(same_dt(&again, &dt_ref[i]), "two sequential runs are bit-identical");
        plateau_dt_free(&again.mesh);
    }
}

static void test_dt_threads(void)
{
    int i;
    run_threads(1, 1, 1, "plateau_dt_triangulate, 4 threads, the same input");
    run_threads(1, 0, 0, "plateau_dt_triangulate, 4 threads, the same input, default allocator");
    run_threads(1, 4, 1, "plateau_dt_triangulate, 4 threads, the same refined input");
    run_threads(1, -1, 1, "plateau_dt_triangulate, 4 threads, different inputs");
    for (i = 0; i < NUM_POINT_SETS; i++) plateau_dt_free(&dt_ref[i].mesh);
}

int main(void)
{
    make_polygons();
    make_point_sets();
    RUN(test_dt_sequential);
    RUN(test_dt_threads);
    RUN(test_solve_sequential);
    RUN(test_solve_threads);
    CHECK_EQ_INT(countalloc_lost_context, 0);
    return harness_report("test_threads");
}
