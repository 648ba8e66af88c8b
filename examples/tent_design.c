/* tent_design.c - a membrane designed from form to fabric: a four-point
 * sail (corners high and low in turn, its four edges cables of tension 8)
 * lifted in its middle by a mast whose head is a ring (the film's second
 * loop, SEVERAL LOOPS in plateau.h), found by least area with the cables
 * (MEMBRANES), then cut into radial panels by planes through the mast's
 * axis for a roll 1.5 wide (CUTTING PATTERNS), each panel flattened with
 * its strain reported.  Units: metres.  Prints the film and each panel;
 * writes out/tent_design.obj, out/tent_design-panels.dxf and the pictures
 * examples/pictures/tent-film.svg and examples/pictures/tent-panels.svg
 * (each panel on its strip of the roll, numbered, with seam marks every
 * half metre). */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define RING 16 /* vertices of the mast head's ring */

int main(void)
{
    /* the sail: a 6 x 6 square, corners at heights 0 and 1.5 in turn */
    static const double corners[12] = {-3, -3, 0, 3, -3, 1.5, 3, 3, 0, -3, 3, 1.5};
    double xyz[3 * (4 + RING)], tension[4 + RING], view[3] = {0.6, -1.0, -0.5};
    size_t counts[2] = {4, RING}, i;
    plateau_options o;
    plateau_report rep;
    plateau_mesh mesh;
    plateau_error err;
    plateau_pattern pat;
    plateau_pattern_options po;
    char defects[600];
    plateau_result r;
    int bad = 0;
    memcpy(xyz, corners, sizeof corners);
    for (i = 0; i < RING; i++) { /* the mast head: a ring of radius 0.8 at height 2.2 */
        double t = 6.283185307179586 * (double)i / RING;
        xyz[12 + 3 * i] = 0.8 * cos(t);
        xyz[12 + 3 * i + 1] = 0.8 * sin(t);
        xyz[12 + 3 * i + 2] = 2.2;
    }
    for (i = 0; i < 4 + RING; i++) tension[i] = i < 4 ? 8.0 : 0.0; /* the ring is rigid */
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 600;
    o.cable_tension = tension;
    r = plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &err);
    if (r != PLATEAU_OK) {
        printf("the film: %s\n", err.message);
        plateau_mesh_free(&mesh);
        return 1;
    }
    printf("film: %lu vertices, area %.4f m^2, %s\n", (unsigned long)mesh.num_vertices, rep.area,
           plateau_defects_string(rep.defects, defects, sizeof defects));
    for (i = 0; i < rep.cables && i < PLATEAU_REPORT_CABLES; i++)
        printf("  cable %lu: tension %.3g, length %.4f m, sag %.4f m\n", (unsigned long)i + 1, rep.cable[i].tension,
               rep.cable[i].length, rep.cable[i].sag);
    bad |= rep.defects != 0;
    if (plateau_write_mesh("out/tent_design.obj", mesh.positions, mesh.num_vertices, mesh.triangles,
                           mesh.num_triangles, &err) != PLATEAU_OK ||
        plateau_write_svg("examples/pictures/tent-film.svg", mesh.positions, mesh.num_vertices, mesh.triangles,
                          mesh.num_triangles, view, NULL, &err) != PLATEAU_OK) {
        printf("%s\n", err.message);
        bad = 1;
    }
    /* radial panels: planes through the mast's axis, a roll 1.5 wide */
    memset(&po, 0, sizeof po);
    po.width = 1.5;
    po.seams = PLATEAU_SEAMS_AXIS;
    po.direction[2] = 1.0;
    r = plateau_pattern_make(mesh.positions, mesh.num_vertices, mesh.triangles, mesh.num_triangles, &po, NULL, &pat,
                             &err);
    plateau_mesh_free(&mesh);
    if (r != PLATEAU_OK) {
        printf("the pattern: %s\n", err.message);
        return 1;
    }
    printf("pattern: %lu panels for a roll 1.5 m wide, largest strain %.4f, mean %.5f\n",
           (unsigned long)pat.num_panels, pat.max_strain, pat.mean_strain);
    for (i = 0; i < pat.num_panels; i++)
        printf("  panel %2lu: %.3f x %.3f m, area %.4f m^2, strain largest %.4f, mean %.5f\n", (unsigned long)i,
               pat.panels[i].length, pat.panels[i].width, pat.panels[i].area_3d, pat.panels[i].max_strain,
               pat.panels[i].mean_strain);
    if (plateau_pattern_write_svg("examples/pictures/tent-panels.svg", &pat, 0.5, &err) != PLATEAU_OK ||
        plateau_pattern_write_dxf("out/tent_design-panels.dxf", &pat, 0.5, &err) != PLATEAU_OK) {
        printf("%s\n", err.message);
        bad = 1;
    }
    plateau_pattern_free(&pat);
    return bad;
}
