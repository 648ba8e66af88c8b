/* bench_delaunay.c - speed of plateau_delaunay.h (built by `make bench`).
 *
 * Triangulates 10^4, 10^5 and 10^6 uniform random points in the unit square
 * (fixed seed) and a 1000 x 1000 grid (every cell co-circular), a few times
 * each, and prints the median CPU time and points per second.  The points
 * are generated once per size by the same generator as bench/cgal_delaunay.cpp
 * (splitmix64, seed 1), so the two programs see identical inputs.
 * Then Delaunay refinement (30-degree bound and an area limit) of a square,
 * a disk (256-gon) and a rectangle with two holes to about 10^5 and 10^6
 * triangles: time, output size and the smallest angle.
 * PLATEAU_BENCH_QUICK=1 in the environment runs only the smaller sizes.
 *
 * "bench_delaunay cgal [full]" (make bench runs it when libcgal-dev is
 * installed and bench/cgal_delaunay.cpp is built next to this program):
 * the comparison with CGAL, each run a fresh process started by popen,
 * plateau and CGAL alternating (so that the load of a shared machine hits
 * both alike): 10^6 uniform points, the 1000 x 1000 grid, 200 segments
 * over 10^5 uniform points (CGAL's Constrained_Delaunay_triangulation_2
 * with insert_constraints) and, with "full", 10^7 uniform points.  Per
 * case: the median CPU time of each, their ratio (the median of the
 * per-pair ratios) and the peak memory per point of each (growth of the
 * peak resident set over the peak after the input was generated).
 * "bench_delaunay one CASE N" is one such run; it prints "cpu_seconds
 * peak_bytes triangles".
 */
#define _POSIX_C_SOURCE 200809L /* popen, getrusage */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "plateau_delaunay.h"

#include <math.h>
#include <string.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <sys/resource.h>

static uint64_t bench_state;
static double bench_rand(void)
{
    uint64_t z = (bench_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

/* median CPU seconds of `reps` triangulations; 0 triangles on failure */
static double time_it(const double *p, size_t n, int reps, size_t *ntri)
{
    double t[16];
    int r;
    plateau_dt_input in;
    in.points = p;
    in.num_points = n;
    in.segments = NULL;
    in.num_segments = 0;
    *ntri = 0;
    for (r = 0; r < reps; r++) {
        plateau_dt_mesh m;
        clock_t c0 = clock();
        plateau_dt_result res = plateau_dt_triangulate(&in, NULL, &m, NULL);
        t[r] = (double)(clock() - c0) / CLOCKS_PER_SEC;
        if (res != PLATEAU_DT_OK) {
            printf("  error: %s\n", plateau_dt_result_string(res));
            return 0;
        }
        *ntri = m.num_triangles;
        plateau_dt_free(&m);
    }
    qsort(t, (size_t)reps, sizeof t[0], cmp_double);
    return t[reps / 2];
}

static void report(const char *name, size_t n, int reps, double sec, size_t ntri)
{
    printf("%-22s %9lu points %9lu triangles  median of %2d: %8.4f s  %6.2f M points/s\n", name,
           (unsigned long)n, (unsigned long)ntri, reps, sec, sec > 0 ? (double)n / sec / 1e6 : 0.0);
}

/* median CPU seconds of `reps` refinements; the last mesh is kept */
static double time_refine(const double *p, size_t n, const plateau_index *seg, size_t ns,
                          double max_area, int reps, plateau_dt_mesh *out)
{
    double t[8];
    int r;
    plateau_dt_input in;
    plateau_dt_options opt;
    in.points = p;
    in.num_points = n;
    in.segments = seg;
    in.num_segments = ns;
    memset(&opt, 0, sizeof opt);
    opt.min_angle = 30;
    opt.max_area = max_area;
    for (r = 0; r < reps; r++) {
        clock_t c0 = clock();
        plateau_dt_result res;
        if (r) plateau_dt_free(out);
        res = plateau_dt_triangulate(&in, &opt, out, NULL);
        t[r] = (double)(clock() - c0) / CLOCKS_PER_SEC;
        if (res != PLATEAU_DT_OK) {
            printf("  error: %s\n", plateau_dt_result_string(res));
            return 0;
        }
    }
    qsort(t, (size_t)reps, sizeof t[0], cmp_double);
    return t[reps / 2];
}

static double smallest_angle(const plateau_dt_mesh *m)
{
    double best = 180;
    size_t t;
    int k;
    for (t = 0; t < m->num_triangles; t++)
        for (k = 0; k < 3; k++) {
            const double *a = m->points + 2 * m->triangles[3 * t + k];
            const double *b = m->points + 2 * m->triangles[3 * t + (k + 1) % 3];
            const double *c = m->points + 2 * m->triangles[3 * t + (k + 2) % 3];
            double ux = b[0] - a[0], uy = b[1] - a[1], wx = c[0] - a[0], wy = c[1] - a[1];
            double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 57.29577951308232;
            if (ang < best) best = ang;
        }
    return best;
}

static void bench_refinement(int quick)
{
    /* domains: square (area 1), disk (256-gon, area ~pi), 10 x 6 rectangle
     * with two holes (area 52) */
    static double pts[2 * 272];
    static plateau_index seg[2 * 272];
    static const char *names[3] = {"square", "disk", "holes"};
    size_t n[3], ns[3], i, start[3];
    double area[3] = {1.0, 3.14127, 52.0};
    int dom, size;
    size_t c = 0, sc = 0;
    /* square */
    start[0] = 0;
    pts[c++] = 0; pts[c++] = 0; pts[c++] = 1; pts[c++] = 0;
    pts[c++] = 1; pts[c++] = 1; pts[c++] = 0; pts[c++] = 1;
    for (i = 0; i < 4; i++) { seg[sc++] = (plateau_index)i; seg[sc++] = (plateau_index)((i + 1) % 4); }
    n[0] = 4; ns[0] = 4;
    /* disk */
    start[1] = 4;
    for (i = 0; i < 256; i++) {
        pts[c++] = cos(6.283185307179586 * (double)i / 256);
        pts[c++] = sin(6.283185307179586 * (double)i / 256);
        seg[sc++] = (plateau_index)i;
        seg[sc++] = (plateau_index)((i + 1) % 256);
    }
    n[1] = 256; ns[1] = 256;
    /* rectangle with two holes */
    start[2] = 260;
    {
        static const double hp[24] = {0, 0, 10, 0, 10, 6, 0, 6, 2, 2, 2, 4, 4, 4, 4, 2, 6, 1, 6, 5, 8, 5, 8, 1};
        static const plateau_index hs[24] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9, 9, 10, 10, 11, 11, 8};
        for (i = 0; i < 24; i++) pts[c++] = hp[i];
        for (i = 0; i < 24; i++) seg[sc++] = hs[i];
        n[2] = 12; ns[2] = 12;
    }
    printf("Delaunay refinement: 30-degree bound and an area limit, CPU time, median\n");
    for (dom = 0; dom < 3; dom++) {
        const double *p = pts + 2 * start[dom];
        const plateau_index *s = seg + 2 * (dom == 0 ? 0 : (dom == 1 ? 4 : 260));
        for (size = 5; size <= 6; size++) {
            plateau_dt_mesh m;
            double target = size == 5 ? 1e5 : 1e6, sec;
            int reps = size == 5 ? 5 : 3;
            char name[40];
            if (quick && size == 6) break;
            /* about 1.5 area / limit triangles come out */
            sec = time_refine(p, n[dom], s, ns[dom], 1.5 * area[dom] / target, reps, &m);
            snprintf(name, sizeof name, "refine %s 10^%d", names[dom], size);
            printf("%-22s %9lu points %9lu triangles  median of %2d: %8.4f s  smallest angle %.2f\n",
                   name, (unsigned long)m.num_points, (unsigned long)m.num_triangles, reps, sec,
                   smallest_angle(&m));
            plateau_dt_free(&m);
        }
    }
}

static long peak_bytes(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss * 1024L;
}

/* One run of one case, the same inputs as cgal_delaunay.cpp's one_case:
 * "uniform" n points, "grid" side x side = n points, "cdt" n uniform points
 * plus 200 disjoint, slightly slanted segments across the square (their
 * 400 endpoints appended), the whole convex hull kept. */
static int one_case(const char *name, size_t n)
{
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh m;
    plateau_dt_result res;
    plateau_index *seg = NULL;
    double *p, sec;
    size_t i, np = n, ns = 0;
    long before, after;
    clock_t c0;
    memset(&opt, 0, sizeof opt);
    bench_state = 1;
    if (!strcmp(name, "cdt")) {
        np = n + 400;
        ns = 200;
        opt.keep_convex_hull = 1;
    } else if (!strcmp(name, "grid")) {
        size_t side = (size_t)sqrt((double)n);
        np = n = side * side;
    } else if (strcmp(name, "uniform")) {
        return 1;
    }
    p = (double *)malloc(2 * np * sizeof(double));
    if (ns) seg = (plateau_index *)malloc(2 * ns * sizeof(plateau_index));
    if (!p || (ns && !seg)) return 1;
    if (!strcmp(name, "grid")) {
        size_t side = (size_t)sqrt((double)n);
        for (i = 0; i < n; i++) {
            p[2 * i] = (double)(i % side);
            p[2 * i + 1] = (double)(i / side);
        }
    } else {
        for (i = 0; i < 2 * n; i++) p[i] = bench_rand();
    }
    for (i = 0; i < ns; i++) {
        double y = (0.25 + (double)i) / 200.0 * 0.99;
        p[2 * (n + 2 * i)] = 0.05;
        p[2 * (n + 2 * i) + 1] = y;
        p[2 * (n + 2 * i + 1)] = 0.95;
        p[2 * (n + 2 * i + 1) + 1] = y + 0.002;
        seg[2 * i] = (plateau_index)(n + 2 * i);
        seg[2 * i + 1] = (plateau_index)(n + 2 * i + 1);
    }
    in.points = p;
    in.num_points = np;
    in.segments = seg;
    in.num_segments = ns;
    before = peak_bytes();
    c0 = clock();
    res = plateau_dt_triangulate(&in, &opt, &m, NULL);
    sec = (double)(clock() - c0) / CLOCKS_PER_SEC;
    after = peak_bytes();
    if (res != PLATEAU_DT_OK) {
        printf("error %s\n", plateau_dt_result_string(res));
        return 1;
    }
    printf("%.6f %ld %lu\n", sec, after - before, (unsigned long)m.num_triangles);
    plateau_dt_free(&m);
    free(p);
    free(seg);
    return 0;
}

/* Run "prog CASE N" in a fresh process and read its one line. */
static int run_child(const char *prog, const char *name, size_t n, double *sec, double *bytes,
                     unsigned long *ntri)
{
    char cmd[1200];
    FILE *f;
    long b = 0;
    int ok;
    snprintf(cmd, sizeof cmd, "%s %s %lu", prog, name, (unsigned long)n);
    f = popen(cmd, "r");
    if (!f) return 0;
    ok = fscanf(f, "%lf %ld %lu", sec, &b, ntri) == 3;
    *bytes = (double)b;
    return pclose(f) == 0 && ok;
}

/* The comparison with CGAL (see the top): alternating fresh processes. */
static int cgal_table(const char *self, int full)
{
    static const char *names[4] = {"uniform", "grid", "cdt", "uniform"};
    static const char *labels[4] = {"uniform 10^6", "grid 1000 x 1000", "200 segments, 10^5 pts",
                                    "uniform 10^7"};
    static const size_t sizes[4] = {1000000, 1000000, 100000, 10000000};
    static const int reps[4] = {5, 5, 5, 3};
    char me[1024], peer[1100], *slash;
    int c;
    snprintf(me, sizeof me, "%s", self);
    slash = strrchr(me, '/');
    if (slash) slash[1] = '\0';
    else me[0] = '\0';
    snprintf(peer, sizeof peer, "%scgal_delaunay", me);
    snprintf(me, sizeof me, "%s one", self);
    printf("plateau_delaunay.h vs CGAL 5.x (Epick), fresh process per run, alternating;\n"
           "CPU seconds (median), ratio = median of the per-pair ratios, peak bytes per point\n");
    printf("%-24s %5s %9s %9s %7s %9s %9s %9s %9s\n", "case", "runs", "plateau", "CGAL", "ratio",
           "pl tri", "CGAL tri", "pl B/pt", "CGAL B/pt");
    for (c = 0; c < (full ? 4 : 3); c++) {
        double tp[8], tc[8], rt[8], bp = 0, bc = 0, b;
        unsigned long np = 0, nc = 0;
        int r;
        for (r = 0; r < reps[c]; r++) {
            if (!run_child(me, names[c], sizes[c], &tp[r], &b, &np)) {
                printf("%-24s plateau run failed\n", labels[c]);
                return 1;
            }
            if (b > bp) bp = b;
            if (!run_child(peer, names[c], sizes[c], &tc[r], &b, &nc)) {
                printf("%-24s CGAL run failed (%s)\n", labels[c], peer);
                return 1;
            }
            if (b > bc) bc = b;
            rt[r] = tp[r] / tc[r];
        }
        qsort(tp, (size_t)reps[c], sizeof tp[0], cmp_double);
        qsort(tc, (size_t)reps[c], sizeof tc[0], cmp_double);
        qsort(rt, (size_t)reps[c], sizeof rt[0], cmp_double);
        printf("%-24s %5d %9.4f %9.4f %6.3fx %9lu %9lu %9.1f %9.1f\n", labels[c], reps[c],
               tp[reps[c] / 2], tc[reps[c] / 2], rt[reps[c] / 2], np, nc,
               bp / (double)sizes[c], bc / (double)sizes[c]);
        fflush(stdout);
    }
    return 0;
}

int main(int argc, char **argv)
{
    static const size_t sizes[3] = {10000, 100000, 1000000};
    static const int reps[3] = {9, 5, 3};
    int quick = getenv("PLATEAU_BENCH_QUICK") != NULL, s;
    size_t i, ntri;
    double *p, sec;
    if (argc == 4 && !strcmp(argv[1], "one"))
        return one_case(argv[2], (size_t)strtoul(argv[3], NULL, 10));
    if (argc >= 2 && !strcmp(argv[1], "cgal"))
        return cgal_table(argv[0], argc >= 3 && !strcmp(argv[2], "full"));
    p = (double *)malloc(2 * 1000000 * sizeof(double));
    if (!p) return 1;
    printf("plateau_delaunay.h %s: CPU time (clock), median of repeats\n",
           PLATEAU_DELAUNAY_VERSION);
    for (s = 0; s < 3; s++) {
        char name[32];
        if (quick && s == 2) break;
        bench_state = 1;
        for (i = 0; i < 2 * sizes[s]; i++) p[i] = bench_rand();
        sec = time_it(p, sizes[s], reps[s], &ntri);
        snprintf(name, sizeof name, "uniform 10^%d", s + 4);
        report(name, sizes[s], reps[s], sec, ntri);
    }
    if (!quick) {
        for (i = 0; i < 1000000; i++) {
            p[2 * i] = (double)(i % 1000);
            p[2 * i + 1] = (double)(i / 1000);
        }
        sec = time_it(p, 1000000, 3, &ntri);
        report("grid 1000 x 1000", 1000000, 3, sec, ntri);
    }
    free(p);
    bench_refinement(quick);
    return 0;
}
