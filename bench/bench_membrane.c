/* bench_membrane.c - membranes at scale (built by `make bench`): the
 * spherical cap of p = 1 on the unit circle (method area, least area - p V)
 * and the flat square (+-1, +-1, 0) with four cables of tension 2 (method
 * area), each at n = 10^3 and 10^4 interior points asked for (the sparse
 * Newton path), one run per row in a child process (bench_common.h): wall
 * and CPU time of plateau_solve, peak resident memory, Newton steps, and
 * the error against the exact solution (the cap's area 2 pi R h with R = 2,
 * h = 2 - sqrt 3; the cable's sag T (1 - cos asin(1 / T))).  The cap's
 * circle has m = 2 sqrt(pi n) vertices, so that its spacing matches the
 * interior's.  Measurements: examples/NOTES.md, "Membranes". */
#define _DEFAULT_SOURCE
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "bench/bench_common.h"
#include <math.h>

#define PI 3.141592653589793

typedef struct job {
    int cable;
    size_t n;
} job;

typedef struct outcome {
    int ok;
    double wall, value, exact;
    size_t steps, vertices;
    unsigned defects;
} outcome;

static void run(void *arg, void *out)
{
    const job *jb = (const job *)arg;
    outcome *r = (outcome *)out;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    double t0;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = jb->n;
    if (jb->cable) {
        static const double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
        static const double tension[4] = {2.0, 2.0, 2.0, 2.0};
        o.cable_tension = tension;
        t0 = bench_wall_now();
        r->ok = plateau_solve(sq, 4, &o, &mesh, &rep, &err) == PLATEAU_OK;
        r->wall = bench_wall_now() - t0;
        r->value = rep.cables ? rep.cable[0].sag : 0.0;
        r->exact = 2.0 * (1.0 - cos(asin(0.5)));
    } else {
        size_t m = (size_t)(2.0 * sqrt(PI * (double)jb->n)), i;
        double *xyz = (double *)malloc(3 * m * sizeof(double)), h = 2.0 - sqrt(3.0);
        for (i = 0; i < m; i++) {
            xyz[3 * i] = cos(2.0 * PI * (double)i / (double)m);
            xyz[3 * i + 1] = sin(2.0 * PI * (double)i / (double)m);
            xyz[3 * i + 2] = 0.0;
        }
        o.pressure = 1.0;
        t0 = bench_wall_now();
        r->ok = plateau_solve(xyz, m, &o, &mesh, &rep, &err) == PLATEAU_OK;
        r->wall = bench_wall_now() - t0;
        r->value = rep.area;
        r->exact = 2.0 * PI * 2.0 * h;
        free(xyz);
    }
    r->steps = rep.iterations;
    r->vertices = mesh.num_vertices;
    r->defects = rep.defects;
    plateau_mesh_free(&mesh);
}

int main(void)
{
    static const size_t sizes[2] = {1000, 10000};
    int c, k;
    printf("membranes on the sparse path (method area; one run per row, each in its own process)\n");
    printf("%-28s %8s %9s %9s %9s %6s %12s %9s %s\n", "case", "n asked", "vertices", "wall s", "CPU s",
           "steps", "value", "error", "check");
    for (c = 0; c < 2; c++)
        for (k = 0; k < 2; k++) {
            job jb;
            outcome r;
            struct rusage ru;
            jb.cable = c;
            jb.n = sizes[k];
            memset(&r, 0, sizeof r);
            if (!bench_run_child(run, &jb, &r, sizeof r, &ru) || !r.ok) {
                printf("%-28s %8lu  failed\n", c ? "cable square T = 2 (sag)" : "cap p = 1 (area)",
                       (unsigned long)jb.n);
                continue;
            }
            printf("%-28s %8lu %9lu %9.2f %9.2f %6lu %12.9f %9.2e %s, %.0f MB\n",
                   c ? "cable square T = 2 (sag)" : "cap p = 1 (area)", (unsigned long)jb.n,
                   (unsigned long)r.vertices, r.wall, bench_cpu_of(&ru), (unsigned long)r.steps, r.value,
                   (r.value - r.exact) / r.exact, r.defects ? "DEFECTS" : "valid", (double)ru.ru_maxrss / 1024.0);
        }
    return 0;
}
