/* catenoid_rings.c - the soap film between two coaxial rings (the catenoid
 * itself, not the paper's patch of examples/catenoid.c): two loops, radius
 * R = 1, distance h, solved by plateau_solve_loops on the annulus domain.
 * The exact film: r(z) = a cosh(z / a), the neck a the larger root of
 * R = a cosh(h / (2a)), area pi a (h + a sinh(h / a)).  Prints a table of
 * the area against the exact one as the rings get m = 12, 24, 48 vertices
 * (n ~ m^2 h / (2 pi) interior points, the ring spacing), the mean distance
 * of the interior vertices to the exact surface and the neck found; then
 * h = 1.5 R, where no catenoid exists and every method reports the pinch.
 * Writes out/catenoid-rings.md (the table), out/catenoid-rings-<m>.obj and
 * the README's picture examples/pictures/catenoid-rings.svg. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "examples/surfaces.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TWO_PI 6.283185307179586

static void rings(double *xyz, int m, double h)
{
    int i;
    for (i = 0; i < 2 * m; i++) {
        double t = TWO_PI * (i % m) / m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < m ? -0.5 * h : 0.5 * h;
    }
}

int main(void)
{
    static const int ms[3] = {12, 24, 48};
    static const double hs[2] = {0.5, 1.0};
    static const plateau_method meths[2] = {PLATEAU_METHOD_PAPER, PLATEAU_METHOD_AREA};
    FILE *md = fopen("out/catenoid-rings.md", "w");
    int ih, im, k, status = 0;
    char line[400];
    if (!md) {
        fprintf(stderr, "cannot write out/catenoid-rings.md (run from the top directory)\n");
        return 1;
    }
#define EMIT(...) do { snprintf(line, sizeof line, __VA_ARGS__); fputs(line, stdout); fputs(line, md); } while (0)
    EMIT("| h / R | method | m | n | area | exact | error | order | mean distance | neck / R (exact) | time |\n");
    EMIT("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (ih = 0; ih < 2; ih++) {
        double h = hs[ih], a = demo_catenoid_neck(h), exact = demo_catenoid_area(h);
        for (k = 0; k < 2; k++) {
            double prev = 0.0;
            for (im = 0; im < 3; im++) {
                int m = ms[im];
                size_t counts[2], v;
                double *xyz = (double *)malloc(6 * (size_t)m * sizeof(double)), err, dist = 0.0, t0;
                plateau_options o;
                plateau_mesh mesh;
                plateau_report rep;
                plateau_error e;
                counts[0] = counts[1] = (size_t)m;
                if (!xyz) return 1;
                rings(xyz, m, h);
                memset(&o, 0, sizeof o);
                o.method = meths[k];
                o.interior_points = (size_t)((double)m * (double)m * h / TWO_PI) + 4;
                t0 = (double)clock() / CLOCKS_PER_SEC;
                if (plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &e) != PLATEAU_OK) {
                    fprintf(stderr, "catenoid_rings: %s\n", e.message);
                    plateau_mesh_free(&mesh);
                    free(xyz);
                    status = 1;
                    continue;
                }
                t0 = (double)clock() / CLOCKS_PER_SEC - t0;
                for (v = 2 * (size_t)m; v < mesh.num_vertices; v++) {
                    const double *p = mesh.positions + 3 * v;
                    dist += fabs(sqrt(p[0] * p[0] + p[1] * p[1]) - a * cosh(p[2] / a)) / cosh(p[2] / a);
                }
                dist /= (double)(mesh.num_vertices - 2 * (size_t)m);
                err = rep.area - exact;
                if (im == 0) snprintf(line, sizeof line, "-");
                else snprintf(line, sizeof line, "%.1f", log(fabs(prev) / fabs(err)) / log(2.0));
                {
                    char order[16];
                    memcpy(order, line, sizeof order);
                    order[15] = '\0';
                    EMIT("| %.1f | %s | %d | %lu | %.6f | %.6f | %+.2e | %s | %.2e | %.3f (%.3f) | %.2f s |\n", h,
                         plateau_method_name(o.method), m, (unsigned long)rep.interior_points, rep.area,
                         exact, err, order, dist, rep.neck_ratio, a, t0);
                }
                if (rep.defects) status = 1;
                prev = err;
                if (h == 1.0 && k == 0) {
                    char path[64];
                    static const double view[3] = {-1.0, -0.35, -0.45};
                    sprintf(path, "out/catenoid-rings-%d.obj", m);
                    plateau_write_mesh(path, mesh.positions, mesh.num_vertices, mesh.triangles,
                                       mesh.num_triangles, NULL);
                    if (m == 24)
                        plateau_write_svg("examples/pictures/catenoid-rings.svg", mesh.positions,
                                          mesh.num_vertices, mesh.triangles, mesh.num_triangles, view,
                                          NULL, NULL);
                }
                plateau_mesh_free(&mesh);
                free(xyz);
            }
        }
    }
    fputs("\n", stdout);
    fputs("\n", md);
    {
        double xyz[6 * 24];
        size_t counts[2] = {24, 24};
        rings(xyz, 24, 1.5);
        for (k = 0; k < 3; k++) {
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)k;
            if (plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL) != PLATEAU_OK ||
                rep.stop != PLATEAU_STOP_PINCHED)
                status = 1;
            EMIT("- h = 1.5 R, %s: %s; neck %.4f of the rings, defect bit PLATEAU_DEFECT_PINCHED %s\n",
                 plateau_method_name(o.method), plateau_stop_string(rep.stop), rep.neck_ratio,
                 rep.defects & PLATEAU_DEFECT_PINCHED ? "set" : "NOT set");
            plateau_mesh_free(&mesh);
        }
    }
    fclose(md);
    return status;
}
