/* bench_delaunay.c - speed of plateau_delaunay.h (built by `make bench`).
 *
 * Triangulates 10^4, 10^5 and 10^6 uniform random points in the unit square
 * (fixed seed) and a 1000 x 1000 grid (every cell co-circular), a few times
 * each, and prints the median CPU time and points per second.  The points
 * are generated once per size by the same generator as bench/cgal_delaunay.cpp
 * (splitmix64, seed 1), so the two programs see identical inputs.
 * PLATEAU_BENCH_QUICK=1 in the environment runs only the two smaller sizes.
 */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "plateau_delaunay.h"

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
    return 0;
}
