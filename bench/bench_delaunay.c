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
 */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "plateau_delaunay.h"

#include <math.h>
#include <string.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

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

int main(void)
{
    static const size_t sizes[3] = {10000, 100000, 1000000};
    static const int reps[3] = {9, 5, 3};
    int quick = getenv("PLATEAU_BENCH_QUICK") != NULL, s;
    size_t i, ntri;
    double *p = (double *)malloc(2 * 1000000 * sizeof(double)), sec;
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
