/* bench_solver.c - speed of plateau_solve (built by `make bench`).
 *
 * The paper's helicoid (b = 1.9, u in [-1, 1], v in [-pi/4, pi/4], 28
 * boundary vertices, n = 20) and catenoid (b = 2.05, u in [pi/4, 3pi/4],
 * v in [-0.5, 0.5], 24 boundary vertices, n = 25), and a finer helicoid
 * (56 boundary vertices, n = 120): each method a few times, median CPU time,
 * the ratio to method paper, and the area's excess over the polygon optimum
 * of examples/NOTES.md where it applies.
 */
#define _DEFAULT_SOURCE
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "bench/bench_common.h"

#include <math.h>

#define BENCH_PI 3.14159265358979323846

/* per_side uniform steps along each side of the parameter rectangle */
static size_t polygon(int helicoid, double b, double u0, double u1, double v0, double v1,
                      int per_side, double *xyz)
{
    size_t m = 0;
    int s, k;
    for (s = 0; s < 4; s++)
        for (k = 0; k < per_side; k++) {
            double t = (double)k / per_side, u, v, *x = xyz + 3 * m++;
            if (s == 0) { u = u0 + (u1 - u0) * t; v = v0; }
            else if (s == 1) { u = u1; v = v0 + (v1 - v0) * t; }
            else if (s == 2) { u = u1 - (u1 - u0) * t; v = v1; }
            else { u = u0; v = v1 - (v1 - v0) * t; }
            if (helicoid) { x[0] = u * cos(v); x[1] = u * sin(v); x[2] = b * v; }
            else { x[0] = b * cos(u) * cosh(v); x[1] = b * v; x[2] = b * sin(u) * cosh(v); }
        }
    return m;
}

static void run(const char *name, const double *xyz, size_t m, size_t n, double optimum)
{
    double base = 0.0;
    int method;
    for (method = 0; method < 3; method++) {
        double t[7];
        int r, reps = 7;
        plateau_report rep;
        memset(&rep, 0, sizeof rep);
        for (r = 0; r < reps; r++) {
            plateau_options o;
            plateau_mesh mesh;
            clock_t c0;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)method;
            o.interior_points = n;
            c0 = clock();
            if (plateau_solve(xyz, m, &o, &mesh, &rep, NULL) != PLATEAU_OK) {
                printf("%s %s: failed\n", name, plateau_method_name(o.method));
                plateau_mesh_free(&mesh);
                return;
            }
            t[r] = (double)(clock() - c0) / CLOCKS_PER_SEC;
            plateau_mesh_free(&mesh);
        }
        bench_median(t, (size_t)reps);
        if (method == 0) base = t[reps / 2];
        printf("%-18s %-14s %8.2f ms  x%5.2f  area %.5f", name,
               plateau_method_name((plateau_method)method), 1e3 * t[reps / 2],
               base > 0 ? t[reps / 2] / base : 1.0, rep.area);
        if (optimum > 0) printf(" (+%.3f%%)", 100.0 * (rep.area / optimum - 1.0));
        printf("  min angle %.1f  rounds %zu  iterations %zu\n", rep.min_angle_deg, rep.rounds,
               rep.iterations);
    }
}

int main(void)
{
    double xyz[3 * 64];
    size_t m;
    m = polygon(1, 1.9, -1.0, 1.0, -BENCH_PI / 4, BENCH_PI / 4, 7, xyz);
    run("helicoid (paper)", xyz, m, 20, 6.21699);
    m = polygon(0, 2.05, BENCH_PI / 4, 3 * BENCH_PI / 4, -0.5, 0.5, 6, xyz);
    run("catenoid (paper)", xyz, m, 25, 7.15719);
    m = polygon(1, 1.9, -1.0, 1.0, -BENCH_PI / 4, BENCH_PI / 4, 14, xyz);
    run("helicoid, n = 120", xyz, m, 120, 0.0);
    return 0;
}
