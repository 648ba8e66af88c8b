/* proto_c2f.c - experiments with the coarse-to-fine prototype (bench/proto/c2f.h);
 * not built by make.  Build: cc -std=c99 -O3 -I. -o build/proto/proto_c2f bench/proto/proto_c2f.c -lm
 *   proto_c2f check                  finite-difference check of c2f_assemble
 *   proto_c2f run SURFACE N [k=v...] one coarse-to-fine solve, per-level figures
 */
#define _DEFAULT_SOURCE
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "examples/surfaces.h"
#include "bench/proto/c2f.h"

static double file_poly[3 * 4096];
static size_t bench_polygon(const char *name, double *poly)
{
    demo_case c;
    if (strchr(name, '.')) { /* a boundary file */
        double *xyz = NULL;
        size_t m = 0;
        if (plateau_read_boundary_file(name, NULL, &xyz, &m, NULL) != PLATEAU_OK || m > 4096) return 0;
        memcpy(poly, xyz, 3 * m * sizeof(double));
        plateau_boundary_free(xyz, NULL);
        return m;
    }
    if (demo_find(name) && strcmp(name, "helicoid") && strcmp(name, "catenoid")) {
        c = *demo_find(name);
        return demo_boundary(&c, poly);
    }
    if (strcmp(name, "helicoid") == 0) {
        c = *demo_find("helicoid");
        c.u0 = -1.5; c.u1 = 1.5; c.v0 = -M_PI / 2; c.v1 = M_PI / 2; c.nu = 4; c.nv = 10;
    } else c = *demo_find("catenoid");
    return demo_boundary(&c, poly);
}

static double astar_of(const char *name)
{
    return strcmp(name, "helicoid") == 0 ? 19.4364269 : 7.1571190;
}

/* the derivative check of c2f.h on the helicoid */
static int check(void)
{
    double poly[3 * DEMO_MAX_BOUNDARY], r[4];
    size_t mm = bench_polygon("helicoid", poly), nfree;
    int ok = c2f_check_derivatives(poly, mm, r, &nfree);
    printf("check: %lu free vertices; gradient: largest error %.2e of largest entry %.2e; Hessian: %.2e of %.2e: %s\n",
           (unsigned long)nfree, r[0], r[1], r[2], r[3], ok ? "pass" : "FAIL");
    return !ok;
}

static int trace_progress(int round, int it, double f, void *u)
{
    (void)u;
    printf("    round %d iteration %d F %.3e cpu %.3f\n", round, it, f, c2f_cpu());
    return 0;
}

static int run(int argc, char **argv)
{
    double *poly = file_poly, c0, cpu, astar = astar_of(argv[2]);
    size_t mm = bench_polygon(argv[2], poly), n = (size_t)atol(argv[3]);
    c2f_params prm;
    c2f_stats st;
    plateau_mesh mesh;
    int a, k, rc, polish = 0;
    double polish_tol = 1e-9;
    memset(&prm, 0, sizeof prm);
    for (a = 4; a < argc; a++) {
        const char *eq = strchr(argv[a], '=');
        double val = eq ? atof(eq + 1) : 0;
        if (!eq) continue;
        if (!strncmp(argv[a], "coarse=", 7)) prm.coarse_min = (size_t)val;
        else if (!strncmp(argv[a], "tau=", 4)) prm.tau = val;
        else if (!strncmp(argv[a], "chordmid=", 9)) prm.chord_midpoints = (int)val;
        else if (!strncmp(argv[a], "levels=", 7)) prm.levels = (int)val;
        else if (!strncmp(argv[a], "tang=", 5)) prm.tangential = (int)val;
        else if (!strncmp(argv[a], "csolver=", 8)) prm.coarse_solver = (int)val;
        else if (!strncmp(argv[a], "ctol=", 5)) prm.coarse_tol = val;
        else if (!strncmp(argv[a], "crounds=", 8)) prm.coarse_rounds = (int)val;
        else if (!strncmp(argv[a], "polish=", 7)) polish = (int)val;
        else if (!strncmp(argv[a], "paper=", 6)) prm.paper = (int)val;
        else if (!strncmp(argv[a], "prounds=", 8)) prm.paper_rounds = (int)val;
        else if (!strncmp(argv[a], "pit=", 4)) prm.paper_iterations = (int)val;
        else if (!strncmp(argv[a], "nochord=", 8)) prm.no_chord = (int)val;
        else if (!strncmp(argv[a], "prounds1=", 9)) prm.plateau_rounds = (int)val;
        else if (!strncmp(argv[a], "full=", 5)) prm.full_newton = (int)val;
        else if (!strncmp(argv[a], "trace=", 6)) prm.progress = val > 0 ? trace_progress : NULL;
        else if (!strncmp(argv[a], "ptol=", 5)) polish_tol = val;
    }
    memset(&mesh, 0, sizeof mesh);
    c0 = c2f_cpu();
    rc = c2f_solve(poly, mm, n, &prm, &mesh, &st);
    cpu = c2f_cpu() - c0;
    if (rc != PLATEAU_OK) {
        printf("failed: %s\n", plateau_result_string((plateau_result)rc));
        return 1;
    }
    printf("coarse: %lu interior, %.3f s; final check %.3f s, defects %u\n", (unsigned long)st.coarse_interior,
           st.coarse_cpu, st.check_cpu, st.defects);
    for (k = 0; k < st.levels; k++) {
        c2f_level *l = &st.level[k];
        printf("level %d: %7lu interior, %2d steps, %2d factorizations, %d halvings, %.3f s, area %.10f, excess %.3e (estimate %.3e), last decrement/2 %.2e\n",
               k + 1, (unsigned long)l->interior, l->steps, l->factorizations, l->halvings, l->cpu, l->area,
               l->area / astar - 1, l->excess_estimate / l->area, l->decrement / 2 / l->area);
    }
    {
        plateau_quality q;
        plateau_mesh_quality(&mesh, &q);
        printf("total %.3f s; area %.10f excess %.3e; angles %.1f..%.1f, inverted %lu, defects %u\n", cpu,
               plateau_mesh_area(&mesh), plateau_mesh_area(&mesh) / astar - 1, q.min_angle_deg, q.max_angle_deg,
               (unsigned long)q.inverted_triangles, q.defects);
    }
    if (polish) {
        plateau_options o;
        plateau_report rep;
        double c1 = c2f_cpu();
        memset(&o, 0, sizeof o);
        memset(&rep, 0, sizeof rep);
        o.method = PLATEAU_METHOD_AREA;
        o.linear_solver = PLATEAU_LINEAR_SPARSE;
        o.area_tolerance = polish_tol;
        o.max_rounds = polish;
        o.area_warm_start = PLATEAU_OFF;
        rc = plateau_mesh_minimize(&mesh, &o, &rep, NULL);
        printf("polish (plateau_mesh_minimize, area, %d rounds, tolerance %.0e): rc %d, %.3f s, %lu steps, %lu flips, area %.10f excess %.3e, removed %lu\n",
               polish, polish_tol, rc, c2f_cpu() - c1, (unsigned long)rep.iterations, (unsigned long)rep.flips,
               rep.area, rep.area / astar - 1, (unsigned long)rep.removed_vertices);
    }
    plateau_mesh_free(&mesh);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "check") == 0) return check();
    if (argc > 3 && strcmp(argv[1], "run") == 0) return run(argc, argv);
    fprintf(stderr, "usage: proto_c2f check | run SURFACE N [coarse= tau= chordmid= levels= tang= csolver= ctol=\n"
                    "       crounds= prounds1= nochord= full= paper= prounds= pit= trace= polish= ptol=]\n");
    return 2;
}
