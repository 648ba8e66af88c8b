/* plateau_quickstart.c - the README's quick start for plateau.h: a
 * saddle-shaped ring of 24 vertices spanned by a minimal triangle mesh with
 * about 40 interior points, reported and written to saddle.obj.
 *
 *     cc -std=c99 -O2 -I. examples/plateau_quickstart.c -o plateau_quickstart -lm
 */
#define PLATEAU_IMPLEMENTATION /* in exactly one file of a program */
#include "plateau.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    double xyz[3 * 24]; /* x, y, z of each vertex; the last joins the first */
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    plateau_result r;
    int i;

    for (i = 0; i < 24; i++) { /* a saddle-shaped ring: z = 0.4 cos 2t */
        double t = 6.283185307179586 * i / 24;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.4 * cos(2 * t);
    }
    memset(&opt, 0, sizeof opt); /* all zero: the documented defaults (method paper) */
    opt.interior_points = 40;    /* about n interior points; 0: as the accuracy needs */
    r = plateau_solve(xyz, 24, &opt, &mesh, &rep, &err);
    if (r != PLATEAU_OK) {
        fprintf(stderr, "%s: %s\n", plateau_result_string(r), err.message);
        plateau_mesh_free(&mesh); /* also after an error */
        return 1;
    }
    /* mesh.positions: the first 24 vertices are the polygon, bit for bit */
    printf("%s: %lu vertices, %lu triangles, area %.6f, smallest angle %.1f deg, %s\n",
           plateau_method_name(rep.method), (unsigned long)mesh.num_vertices,
           (unsigned long)mesh.num_triangles, rep.area, rep.min_angle_deg,
           rep.defects == 0 ? "valid" : "with defects");
    r = plateau_write_mesh("saddle.obj", mesh.positions, mesh.num_vertices, mesh.triangles,
                           mesh.num_triangles, &err);
    if (r != PLATEAU_OK) fprintf(stderr, "saddle.obj: %s\n", err.message);
    plateau_mesh_free(&mesh);
    return r == PLATEAU_OK && rep.defects == 0 ? 0 : 1;
}
