/* cable_membranes.c - membranes beyond a film on a rigid frame (MEMBRANES
 * in plateau.h): a four-point sail, its corners those of a hypar (high and
 * low in turn), whose four edges are cables of tension T, and a pneumatic
 * cushion on a square frame held by an internal pressure p = 1.5 (then
 * by its volume: the pressure that holds it comes back, 1.500000 as
 * printed).  Prints a table of each
 * cable's length and sag and each film's area, volume and pressure;
 * writes out/membranes.md (the table), out/sail.obj, out/cushion.obj and
 * the pictures examples/pictures/membrane-sail.svg and
 * examples/pictures/membrane-cushion.svg. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include <stdio.h>
#include <string.h>

static int run(const char *name, const double *xyz, size_t m, const plateau_options *o, FILE *md,
               const double *view, plateau_report *rep)
{
    plateau_mesh mesh;
    plateau_error err;
    char path[128], defects[600];
    size_t c;
    plateau_result r = plateau_solve(xyz, m, o, &mesh, rep, &err);
    if (r != PLATEAU_OK) {
        printf("%s: %s\n", name, err.message);
        plateau_mesh_free(&mesh);
        return 1;
    }
    printf("%-8s %5lu vertices  area %.6f  volume %+.6f  pressure %.6f  %s\n", name,
           (unsigned long)mesh.num_vertices, rep->area, rep->volume, rep->pressure,
           plateau_defects_string(rep->defects, defects, sizeof defects));
    fprintf(md, "| %s | %lu | %.6f | %+.6f | %.6f | %s |\n", name, (unsigned long)mesh.num_vertices, rep->area,
            rep->volume, rep->pressure, defects);
    for (c = 0; c < rep->cables && c < PLATEAU_REPORT_CABLES; c++)
        printf("         cable %lu: tension %.3g, %lu vertices, length %.6f, sag %.6f\n", (unsigned long)c + 1,
               rep->cable[c].tension, (unsigned long)rep->cable[c].vertices, rep->cable[c].length,
               rep->cable[c].sag);
    sprintf(path, "out/%s.obj", name);
    if (plateau_write_mesh(path, mesh.positions, mesh.num_vertices, mesh.triangles, mesh.num_triangles, &err) !=
        PLATEAU_OK)
        printf("%s\n", err.message);
    sprintf(path, "examples/pictures/membrane-%s.svg", name);
    if (plateau_write_svg(path, mesh.positions, mesh.num_vertices, mesh.triangles, mesh.num_triangles, view, NULL,
                          &err) != PLATEAU_OK)
        printf("%s\n", err.message);
    plateau_mesh_free(&mesh);
    return rep->defects != 0;
}

int main(void)
{
    /* the sail: a 4 x 4 square, corners at heights +-1 in turn (a hypar),
     * every edge a cable of tension 4 (half its chord is 2) */
    static const double sail[12] = {-2, -2, 1, 2, -2, -1, 2, 2, 1, -2, 2, -1};
    static const double tension[4] = {4.0, 4.0, 4.0, 4.0};
    /* the cushion: a 2 x 2 square frame in z = 0 (rigid), 12 vertices a side */
    double frame[3 * 48];
    int i;
    double view[3] = {0.6, -1.0, 0.7};
    plateau_options o;
    plateau_report rep;
    int bad = 0;
    FILE *md = fopen("out/membranes.md", "w");
    if (!md) {
        printf("cannot write out/membranes.md (run from the repository root: make demo)\n");
        return 1;
    }
    for (i = 0; i < 48; i++) {
        double t = -1.0 + (i % 12) / 6.0; /* along the side, -1 .. 1 - 1/6 */
        int side = i / 12;
        frame[3 * i] = side == 0 ? t : side == 1 ? 1.0 : side == 2 ? -t : -1.0;
        frame[3 * i + 1] = side == 0 ? -1.0 : side == 1 ? t : side == 2 ? 1.0 : -t;
        frame[3 * i + 2] = 0.0;
    }
    fprintf(md, "| film | vertices | area | volume | pressure | check |\n|---|---|---|---|---|---|\n");
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 600;
    o.cable_tension = tension;
    bad |= run("sail", sail, 4, &o, md, view, &rep);
    /* method paper (H_i = p with its tangential rows): least area - p V
     * on this frame lets vertex pairs near the frame slide together
     * (examples/NOTES.md, section 13, "Membranes") */
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_PAPER;
    o.interior_points = 400;
    o.pressure = 1.5;
    bad |= run("cushion", frame, 48, &o, md, view, &rep);
    /* the same cushion by its volume: the multiplier is the pressure 1.5 */
    o.pressure = 0.0;
    o.fix_volume = 1;
    o.volume = rep.volume;
    bad |= run("cushion-volume", frame, 48, &o, md, view, &rep);
    fclose(md);
    return bad;
}
