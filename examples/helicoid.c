/* helicoid.c - the paper's example III.A, and a first tour of the API.
 *
 *     make demo            (or: make build/examples/helicoid && ./build/examples/helicoid)
 *
 * Part 1 is the whole API in a few lines: a closed polygon in, a minimal
 * triangle mesh out.  Part 2 runs the paper's comparison for this case
 * (every method, error against the exact helicoid) with the shared helpers
 * of examples/surfaces.h, which also hold the parameter ranges. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION /* in exactly one file of a program */
#endif
#include "plateau.h"
#include "surfaces.h"

int main(void)
{
    /* ---- Part 1: the API -------------------------------------------- */
    const demo_case *helicoid = demo_find("helicoid");
    double polygon[3 * DEMO_MAX_BOUNDARY]; /* x, y, z of each vertex, closed implicitly */
    size_t m = demo_boundary(helicoid, polygon); /* 28 vertices on the patch's edges */
    plateau_options options;
    plateau_mesh mesh;
    plateau_report report;
    plateau_error err;

    memset(&options, 0, sizeof options); /* all zero = the documented defaults */
    options.method = PLATEAU_METHOD_PAPER;
    options.interior_points = 20;           /* the paper's n */
    memset(&mesh, 0, sizeof mesh);
    if (plateau_solve(polygon, m, &options, &mesh, &report, &err) != PLATEAU_OK) {
        fprintf(stderr, "plateau_solve: %s\n", err.message);
        plateau_mesh_free(&mesh);
        return 1;
    }
    /* The mesh's first m vertices are the polygon, the others interior. */
    printf("helicoid: %lu vertices, %lu triangles, area %.6f, smallest angle %.1f deg, "
           "%zu iterations (%s)\n",
           (unsigned long)mesh.num_vertices, (unsigned long)mesh.num_triangles, report.area,
           report.min_angle_deg, report.iterations, plateau_stop_string(report.stop));
    if (plateau_write_mesh("out/helicoid.obj", mesh.positions, mesh.num_vertices,
                           mesh.triangles, mesh.num_triangles, &err) != PLATEAU_OK)
        fprintf(stderr, "out/helicoid.obj: %s\n", err.message);
    plateau_mesh_free(&mesh);

    /* ---- Part 2: the paper's comparison ----------------------------- */
    return demo_run_group("helicoid");
}
