/* delaunay_quickstart.c - the README's quick start for plateau_delaunay.h
 * and the example at the top of that header: a square with a square hole
 * and one free point, triangulated as a domain; prints the triangles as
 * counter-clockwise index triples.
 *
 *     cc -std=c99 -O2 -I. examples/delaunay_quickstart.c -o delaunay_quickstart -lm
 */
#define PLATEAU_DELAUNAY_IMPLEMENTATION /* in exactly one file of a program */
#include "plateau_delaunay.h"

#include <stdio.h>
#include <string.h>

int main(void)
{
    double pts[] = {0, 0, 4, 0, 4, 4, 0, 4,   1, 1, 1, 2, 2, 2, 2, 1,   3, 3}; /* x, y */
    plateau_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0,   4, 5, 5, 6, 6, 7, 7, 4}; /* point pairs */
    plateau_dt_input in;
    plateau_dt_mesh mesh;
    plateau_dt_error err;
    plateau_dt_result r;
    size_t t;

    memset(&in, 0, sizeof in); /* every field zero first */
    in.points = pts;   in.num_points = 9;
    in.segments = seg; in.num_segments = 8; /* the outer loop, then the hole's */
    r = plateau_dt_triangulate(&in, NULL, &mesh, &err);
    if (r != PLATEAU_DT_OK) {
        fprintf(stderr, "%s: %s\n", plateau_dt_result_string(r), err.message);
        return 1;
    }
    for (t = 0; t < mesh.num_triangles; t++)
        printf("%d %d %d\n", (int)mesh.triangles[3 * t], (int)mesh.triangles[3 * t + 1],
               (int)mesh.triangles[3 * t + 2]);
    plateau_dt_free(&mesh);
    return 0;
}
