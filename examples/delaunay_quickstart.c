/* delaunay_quickstart.c - the example at the top of plateau_delaunay.h: a
 * square with a square hole and one free point, triangulated as a domain;
 * prints the triangles as counter-clockwise index triples. */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "plateau_delaunay.h"
#include <stdio.h>
int main(void)
{
    double pts[] = {0, 0, 4, 0, 4, 4, 0, 4,   1, 1, 1, 2, 2, 2, 2, 1,   3, 3};
    plateau_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0,   4, 5, 5, 6, 6, 7, 7, 4};
    plateau_dt_input in = {0};
    plateau_dt_mesh mesh;
    plateau_dt_error rep;
    plateau_dt_result r;
    size_t t;
    in.points = pts;   in.num_points = 9;
    in.segments = seg; in.num_segments = 8;
    r = plateau_dt_triangulate(&in, NULL, &mesh, &rep);
    if (r != PLATEAU_DT_OK) {
        printf("%s: %s\n", plateau_dt_result_string(r), rep.message);
        return 1;
    }
    for (t = 0; t < mesh.num_triangles; t++)
        printf("%d %d %d\n", (int)mesh.triangles[3 * t], (int)mesh.triangles[3 * t + 1],
               (int)mesh.triangles[3 * t + 2]);
    plateau_dt_free(&mesh);
    return 0;
}
