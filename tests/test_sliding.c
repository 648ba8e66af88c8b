/* test_sliding.c - edges that slide (options.slide) against exact
 * answers. */
#define _POSIX_C_SOURCE 200809L
#ifndef PLATEAU_TEST_LINKED /* else make test links tests/impl.c's object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The catenoid between coaxial unit rings at distance h: its waist a
 * (a cosh(h / (2 a)) = 1, the larger root: the stable film) by bisection,
 * and its area pi a (h + a sinh(h / a)). */
static double catenoid_area(double h, double *waist)
{
    double lo = 0.0, hi = 1.0, a = 1.0;
    int it;
    /* f(a) = a cosh(h / (2a)) - 1 rises on the stable branch: from its
     * minimum (at h / (2a) = 1.19968) to a = 1 */
    lo = h / (2.0 * 1.19967864025773);
    for (it = 0; it < 200; it++) {
        a = 0.5 * (lo + hi);
        if (a * cosh(h / (2.0 * a)) > 1.0) hi = a;
        else lo = a;
    }
    if (waist) *waist = a;
    return PI * a * (h + a * sinh(h / a));
}

/* Ring R = 1 at z = h / 2 (fixed) and a ring of q vertices on z = 0 that
 * slides on that plane; n interior points. */
static plateau_result half_catenoid(double h, size_t q, size_t n, plateau_method method, plateau_mesh *mesh,
                                    plateau_report *rep, plateau_error *err)
{
    double *xyz = (double *)malloc(6 * q * sizeof(double)), *dir = (double *)malloc(6 * q * sizeof(double));
    int *slide = (int *)malloc(2 * q * sizeof(int));
    size_t counts[2], i;
    plateau_options opt;
    plateau_result r;
    for (i = 0; i < 2 * q; i++) {
        double t = 2.0 * PI * (double)(i % q) / (double)q;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < q ? 0.5 * h : 0.0;
        slide[i] = i < q ? 0 : PLATEAU_SLIDE_PLANE;
        dir[3 * i] = dir[3 * i + 1] = 0.0;
        dir[3 * i + 2] = 1.0;
    }
    counts[0] = counts[1] = q;
    memset(&opt, 0, sizeof opt);
    opt.method = method;
    opt.interior_points = n;
    opt.slide = slide;
    opt.slide_direction = dir;
    r = plateau_solve_loops(xyz, counts, 2, &opt, mesh, rep, err);
    free(xyz);
    free(dir);
    free(slide);
    return r;
}

static void experiment(void)
{
    double a, ex = catenoid_area(1.0, &a) / 2.0;
    size_t k;
    printf("exact half %.7f waist %.6f\n", ex, a);
    for (k = 1; k <= 8; k *= 2) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        size_t q = 24 * k, i;
        double rmin = 10, rmax = 0, zmax = 0;
        plateau_result r = half_catenoid(1.0, q, 60 * k * k, PLATEAU_METHOD_AREA, &mesh, &rep, &err);
        for (i = q; r == PLATEAU_OK && i < 2 * q; i++) {
            double *p = mesh.positions + 3 * i, rr = sqrt(p[0] * p[0] + p[1] * p[1]);
            if (rr < rmin) rmin = rr;
            if (rr > rmax) rmax = rr;
            if (fabs(p[2]) > zmax) zmax = fabs(p[2]);
        }
        printf("k %lu: %d %s area %.7f err %.3e defects %u stop %d neck %.3f r %.5f..%.5f z %.1e nv %lu\n",
               (unsigned long)k, r, err.message, rep.area, rep.area - ex, rep.defects, rep.stop, rep.neck_ratio,
               rmin, rmax, zmax, (unsigned long)mesh.num_vertices);
        plateau_mesh_free(&mesh);
    }
}

static void experiment2(void)
{
    size_t j;
    double hs[3] = {1.0, 1.3, 1.4};
    for (j = 0; j < 3; j++) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        double a, ex = catenoid_area(hs[j] > 1.3255 ? 1.3255 : hs[j], &a) / 2.0;
        plateau_result r = half_catenoid(hs[j], 48, 240, PLATEAU_METHOD_PAPER, &mesh, &rep, &err);
        printf("paper h %.2f: %d %s area %.7f exact %.7f defects %u stop %d neck %.3f\n", hs[j], r, err.message,
               rep.area, ex, rep.defects, rep.stop, rep.neck_ratio);
        plateau_mesh_free(&mesh);
        r = half_catenoid(hs[j], 48, 240, PLATEAU_METHOD_AREA, &mesh, &rep, &err);
        printf("area  h %.2f: %d %s area %.7f exact %.7f defects %u stop %d neck %.3f\n", hs[j], r, err.message,
               rep.area, ex, rep.defects, rep.stop, rep.neck_ratio);
        plateau_mesh_free(&mesh);
    }
}

int main(void)
{
    RUN(experiment2);
    RUN(experiment);
    return harness_report("test_sliding");
}
