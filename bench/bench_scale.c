/* bench_scale.c - methods paper and area at scale, on their sparse paths
 * (built by `make bench`).
 *
 * Two boundaries of examples/surfaces.h: the helicoid (b = 1.9, 28
 * boundary vertices) on the wider range u in [-1.5, 1.5], v in
 * [-pi/2, pi/2], and the catenoid as in the demo; quality seeding with
 * refine_boundary, n = 10^3, 10^4 and 10^5 interior points asked for, methods paper (with its default area
 * presolve on the circle domain) and area, linear_solver AUTO (the sparse
 * paths at these sizes).  Each run is a child process (fork), so that its
 * peak resident memory (getrusage ru_maxrss) is its own; wall
 * (CLOCK_MONOTONIC) and CPU (clock) time of plateau_solve, one run per row.
 * steps: method area's Newton steps (paper: its presolve's Newton steps +
 * the dog leg's iterations).  excess: (A - A*) / A*, A* the optimum
 * extrapolated from method area's series on that boundary: the area of a
 * fine mesh exceeds the surface's by about c h^2 = c' / n, so the two
 * largest n give A* = (n2 A2 - n1 A1) / (n2 - n1) (Richardson).
 * Arguments: none, or "picture FILE" (writes the README's picture of the
 * 10^4 helicoid by method area).  With the defaults these sizes run coarse
 * to fine (options.coarse_to_fine; levels: its subdivisions).
 * Measured 2026-12-03 (2-core x86-64, shared, load about 3; gcc -O3), CPU /
 * peak RSS: helicoid area 10^3 0.02 s / 2.8 MB, 10^4 0.15 s / 11.8 MB, 10^5
 * 1.46 s / 118.9 MB; paper 0.03 s, 0.22 s, 3.45 s / 155.2 MB; catenoid area
 * 0.02, 0.10, 1.45 s, paper 0.02, 0.20, 2.38 s.  Excess over A* (helicoid
 * 19.3927931484, catenoid 7.1571194834): area 3.4e-4, 4.2e-5, 4.2e-6 and
 * 1.6e-4, 2.0e-5, 2.0e-6; paper the same to 1 %.  (The rounds at full size,
 * 2026-12-02: helicoid area 10^4 3.83 s wall / 66 MB, 10^5 23.8 s / 736
 * MB; paper 10^5 87.9 s / 918 MB; examples/NOTES.md section 9.)
 */
#define _DEFAULT_SOURCE
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "examples/surfaces.h"
#include "bench/bench_common.h"

typedef struct scale_row {
    int rc;
    double wall, cpu, area;
    long maxrss_kb;
    size_t interior;
    int rounds, iterations, presolve_iterations, levels;
    unsigned defects;
} scale_row;

/* The README's picture of a large mesh: every edge once (mesh.edges) as
 * one SVG path, a thin line in an orthographic view along dir, one decimal
 * per coordinate (about 25 bytes an edge: 0.75 MB for 3 10^4 edges, where
 * plateau_write_svg's shaded triangles would take 80 bytes each). */
static int write_edges_svg(const char *path, const plateau_mesh *mesh, const double *dir)
{
    double d[3], r[3], u[3], len, lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, sc;
    size_t v, e;
    int i;
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    len = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (i = 0; i < 3; i++) d[i] = dir[i] / len;
    r[0] = d[1];
    r[1] = -d[0];
    r[2] = 0.0; /* d x z */
    len = sqrt(r[0] * r[0] + r[1] * r[1]);
    for (i = 0; i < 3; i++) r[i] /= len;
    u[0] = r[1] * d[2] - r[2] * d[1];
    u[1] = r[2] * d[0] - r[0] * d[2];
    u[2] = r[0] * d[1] - r[1] * d[0];
    for (v = 0; v < mesh->num_vertices; v++) {
        const double *p = mesh->positions + 3 * v;
        double x = p[0] * r[0] + p[1] * r[1] + p[2] * r[2], y = -(p[0] * u[0] + p[1] * u[1] + p[2] * u[2]);
        if (x < lo[0]) lo[0] = x;
        if (x > hi[0]) hi[0] = x;
        if (y < lo[1]) lo[1] = y;
        if (y > hi[1]) hi[1] = y;
    }
    sc = 900.0 / (hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1]);
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\">\n"
               "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
               "<path fill=\"none\" stroke=\"#203050\" stroke-width=\"0.25\" d=\"",
            sc * (hi[0] - lo[0]) + 20.0, sc * (hi[1] - lo[1]) + 20.0);
    for (e = 0; e < mesh->num_edges; e++) {
        for (i = 0; i < 2; i++) {
            const double *p = mesh->positions + 3 * (size_t)mesh->edges[2 * e + (size_t)i];
            double x = p[0] * r[0] + p[1] * r[1] + p[2] * r[2], y = -(p[0] * u[0] + p[1] * u[1] + p[2] * u[2]);
            fprintf(f, "%c%.1f %.1f", i ? 'L' : 'M', 10.0 + sc * (x - lo[0]), 10.0 + sc * (y - lo[1]));
        }
    }
    fprintf(f, "\"/>\n</svg>\n");
    return fclose(f) == 0;
}

static const char *picture_path; /* "picture FILE": the 10^4 helicoid by method area */

/* one solve, in this process */
static void solve_once(const char *surface, plateau_method method, size_t n, scale_row *row)
{
    demo_case c = *demo_find(surface);
    double polygon[3 * DEMO_MAX_BOUNDARY], w0;
    size_t m;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    struct rusage ru;
    clock_t c0;
    if (strcmp(surface, "helicoid") == 0) {
        c.u0 = -1.5;
        c.u1 = 1.5;
        c.v0 = -M_PI / 2;
        c.v1 = M_PI / 2;
    }
    m = demo_boundary(&c, polygon);
    memset(&o, 0, sizeof o);
    memset(&rep, 0, sizeof rep);
    o.method = method;
    o.interior_points = n;
    o.seed = DEMO_SEED;
    o.seeding = PLATEAU_SEEDING_QUALITY;
    o.refine_boundary = PLATEAU_ON;
    w0 = bench_wall_now();
    c0 = clock();
    row->rc = plateau_solve(polygon, m, &o, &mesh, &rep, NULL);
    row->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    row->wall = bench_wall_now() - w0;
    getrusage(RUSAGE_SELF, &ru);
    row->maxrss_kb = ru.ru_maxrss;
    row->area = rep.area;
    row->interior = rep.interior_points;
    row->rounds = (int)rep.rounds;
    row->iterations = (int)rep.iterations;
    row->presolve_iterations = (int)rep.presolve_iterations;
    row->levels = (int)rep.levels;
    row->defects = rep.defects;
    if (row->rc == PLATEAU_OK && picture_path) {
        static const double dir[3] = {-1.0, -0.6, -0.5};
        if (!write_edges_svg(picture_path, &mesh, dir)) row->rc = PLATEAU_ERR_IO;
    }
    plateau_mesh_free(&mesh);
}

typedef struct scale_arg {
    const char *surface;
    plateau_method method;
    size_t n;
} scale_arg;

static void solve_fn(void *arg, void *out)
{
    const scale_arg *a = (const scale_arg *)arg;
    solve_once(a->surface, a->method, a->n, (scale_row *)out);
}

/* one solve in a child process; 0 on failure to run it */
static int solve_child(const char *surface, plateau_method method, size_t n, scale_row *row)
{
    scale_arg a;
    struct rusage ru;
    a.surface = surface;
    a.method = method;
    a.n = n;
    return bench_run_child(solve_fn, &a, row, sizeof *row, &ru);
}

int main(int argc, char **argv)
{
    static const char *surfaces[2] = {"helicoid", "catenoid"};
    static const plateau_method methods[2] = {PLATEAU_METHOD_AREA, PLATEAU_METHOD_PAPER};
    static const size_t sizes[3] = {1000, 10000, 100000};
    int ns = 3, si, mi, k;
    scale_row rows[2][3];
    if (argc > 2 && strcmp(argv[1], "picture") == 0) {
        scale_row r;
        picture_path = argv[2];
        solve_once("helicoid", PLATEAU_METHOD_AREA, 10000, &r);
        printf("%s: %lu interior vertices, area %.10f, rc %d\n", argv[2], (unsigned long)r.interior, r.area, r.rc);
        return r.rc != PLATEAU_OK;
    }
    printf("helicoid b = 1.9, u in [-1.5, 1.5], v in [-pi/2, pi/2]; catenoid as in the demo;\n"
           "quality seeding + refine_boundary, linear_solver AUTO (sparse); one child process per run\n");
    printf("surface   method       n   inner   wall s   CPU s  peak MB  rounds levels  steps         "
           "area        excess  defects\n");
    for (si = 0; si < 2; si++) {
        double astar = 0.0;
        int have = 0;
        for (mi = 0; mi < 2; mi++) {
            for (k = 0; k < ns; k++) {
                scale_row *r = &rows[mi][k];
                memset(r, 0, sizeof *r);
                if (!solve_child(surfaces[si], methods[mi], sizes[k], r) || r->rc != PLATEAU_OK) {
                    printf("%-9s %-6s %7lu  failed (%s)\n", surfaces[si], plateau_method_name(methods[mi]),
                           (unsigned long)sizes[k], plateau_result_string((plateau_result)r->rc));
                    r->rc = -1;
                    continue;
                }
                if (mi == 0 && k == ns - 1 && rows[0][k - 1].rc == PLATEAU_OK) {
                    double n1 = (double)rows[0][k - 1].interior, n2 = (double)r->interior;
                    astar = (n2 * r->area - n1 * rows[0][k - 1].area) / (n2 - n1);
                    have = 1;
                }
            }
        }
        for (mi = 0; mi < 2; mi++)
            for (k = 0; k < ns; k++) {
                scale_row *r = &rows[mi][k];
                char steps[32];
                if (r->rc != PLATEAU_OK) continue;
                if (methods[mi] == PLATEAU_METHOD_PAPER)
                    sprintf(steps, "%d+%d", r->presolve_iterations, r->iterations);
                else
                    sprintf(steps, "%d", r->iterations);
                printf("%-9s %-6s %7lu %7lu %8.2f %7.2f %8.1f %7d %6d  %-9s %.10f  %8.2e  %u\n", surfaces[si],
                       plateau_method_name(methods[mi]), (unsigned long)sizes[k], (unsigned long)r->interior,
                       r->wall, r->cpu, (double)r->maxrss_kb / 1024.0, r->rounds, r->levels, steps, r->area,
                       have ? (r->area - astar) / astar : 0.0, r->defects);
            }
        if (have) printf("%-9s A* = %.10f (Richardson in 1/n, method area, the two largest n)\n", surfaces[si], astar);
    }
    return 0;
}
