/* The switches of CONFIGURATION (PLATEAU_NO_STABILITY, _NO_MEMBRANES,
 * _NO_LOOPS, _NO_COARSE_TO_FINE, _NO_SVG, _NO_PLY_OFF_STL, _NO_PARSERS,
 * _NO_SUPPORTS, _NO_SLIDING, _NO_ACCURACY, _NO_QUALITY_SEEDING,
 * PLATEAU_LM_NO_SPARSE,
 * PLATEAU_LM_NO_CONSTRAINTS, PLATEAU_LM_NO_EXTRAS, PLATEAU_NO_EXTRAS),
 * each alone and all together: the Makefile builds this file with the
 * implementation once per configuration (C99 under gcc, C++ under g++) and
 * runs it.  It solves a small plain film with the default options, and
 * with the paper's fan seeding, checks the mesh (valid, the boundary kept
 * bit for bit) and prints its digest, which the Makefile compares with the
 * full library's: a switch removes code, never changes a plain film
 * (without the quality seeding the default seeding is the fan, so there
 * only the fan's film is compared).  Then every request for a feature
 * compiled out must be refused with PLATEAU_ERR_ARGUMENT and a message
 * naming the macro.  Prints "switches: P checks passed, F failed". */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int passed, failed;

static void check(int ok, const char *what)
{
    if (ok) {
        passed++;
    } else {
        failed++;
        printf("FAILED: %s\n", what);
    }
}

/* rc is PLATEAU_ERR_ARGUMENT and the message names the macro */
static void refused(plateau_result rc, const plateau_error *err, const char *macro, const char *what)
{
    char line[256];
    snprintf(line, sizeof line, "%s: PLATEAU_ERR_ARGUMENT naming %s (got %d: %s)", what, macro, (int)rc,
             err->message);
    check(rc == PLATEAU_ERR_ARGUMENT && err->code == PLATEAU_ERR_ARGUMENT && strstr(err->message, macro) != NULL,
          line);
}

/* FNV-1a over the bytes of the mesh's positions and triangles */
static unsigned long digest(const plateau_mesh *mesh)
{
    const unsigned char *p = (const unsigned char *)mesh->positions;
    size_t i, n = 3 * mesh->num_vertices * sizeof(double);
    unsigned long h = 2166136261ul;
    for (i = 0; i < n; i++) h = ((h ^ p[i]) * 16777619ul) & 0xfffffffful;
    p = (const unsigned char *)mesh->triangles;
    n = 3 * mesh->num_triangles * sizeof(plateau_index);
    for (i = 0; i < n; i++) h = ((h ^ p[i]) * 16777619ul) & 0xfffffffful;
    return h;
}

#define M 20
static double ring[3 * 2 * M];

#if defined(PLATEAU_LM_NO_CONSTRAINTS) || defined(PLATEAU_LM_NO_EXTRAS)
/* f_i = a t_i + b - y_i at (0, 1) and (1, 3) */
static int line_residuals(const double *x, double *f, double *jac, void *user)
{
    (void)user;
    f[0] = x[1] - 1.0;
    f[1] = x[0] + x[1] - 3.0;
    if (jac) {
        jac[0] = 0.0, jac[1] = 1.0;
        jac[2] = 1.0, jac[3] = 1.0;
    }
    return 0;
}
#endif

/* a saddle-shaped ring (z = 0.3 cos 2t) of M vertices; the second loop of
 * the two-loop request is the same ring lifted by 1 */
static void make_rings(void)
{
    int i;
    for (i = 0; i < M; i++) {
        double t = 6.283185307179586 * i / M;
        ring[3 * i] = cos(t);
        ring[3 * i + 1] = sin(t);
        ring[3 * i + 2] = 0.3 * cos(2 * t);
        ring[3 * (M + i)] = cos(t);
        ring[3 * (M + i) + 1] = -sin(t);
        ring[3 * (M + i) + 2] = 1.0;
    }
}

/* the plain film by method (the paper's pipeline: methods paper,
 * paper-literal and area), the mesh checked and its digest printed */
static void plain_film(plateau_method method, plateau_seeding seeding)
{
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    plateau_result rc;
    /* the digest line the Makefile compares: "mesh"; without the quality
     * seeding the default one is the fan's, another mesh */
#ifdef PLATEAU_NO_QUALITY_SEEDING
    const char *tag = seeding == PLATEAU_SEEDING_AUTO ? "fan-by-default" : "mesh";
#else
    const char *tag = "mesh";
#endif
    memset(&opt, 0, sizeof opt);
    opt.method = method;
    opt.seeding = seeding;
    opt.interior_points = 20; /* dense LM: at most PLATEAU_PAPER_SPARSE_THRESHOLD free */
    rc = plateau_solve(ring, M, &opt, &mesh, &rep, &err);
    check(rc == PLATEAU_OK, "the plain film solves");
    if (rc != PLATEAU_OK) {
        printf("  %s\n", err.message);
        return;
    }
    check(rep.defects == 0, "the plain film has no defect");
    {
        plateau_quality q;
        check(plateau_mesh_check(&mesh, &q, &err) == PLATEAU_OK && q.defects == 0 && q.intersecting_pairs == 0,
              "plateau_mesh_check finds no defect");
    }
    check(mesh.num_vertices > M && memcmp(mesh.positions, ring, sizeof(double) * 3 * M) == 0,
          "the boundary comes back bit for bit");
    printf("%s %s%s: %lu vertices %lu triangles digest %08lx\n", tag, plateau_method_name(method),
           seeding == PLATEAU_SEEDING_PAPER ? " fan" : "",
           (unsigned long)mesh.num_vertices, (unsigned long)mesh.num_triangles, digest(&mesh));
#ifdef PLATEAU_NO_STABILITY
    {
        plateau_stability st;
        rc = plateau_mesh_stability(&mesh, 2, &st, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_STABILITY", "plateau_mesh_stability");
        rc = plateau_mesh_critical_point(&mesh, 1, 0, NULL, NULL, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_STABILITY", "plateau_mesh_critical_point");
    }
#endif
#ifdef PLATEAU_NO_ACCURACY
    check(rep.estimate == PLATEAU_ESTIMATE_COMPILED_OUT && rep.area_error_estimate != rep.area_error_estimate,
          "no error estimate: NaN, PLATEAU_ESTIMATE_COMPILED_OUT");
    check(strstr(plateau_estimate_string(rep.estimate), "PLATEAU_NO_ACCURACY") != NULL,
          "the estimate's status names PLATEAU_NO_ACCURACY");
#else
    if (seeding == PLATEAU_SEEDING_AUTO)
        check(rep.estimate == PLATEAU_ESTIMATE_FORMED && rep.area_error_estimate > 0.0,
              "the error estimate is formed");
#endif
    {
        double *ind = (double *)malloc(sizeof(double) * mesh.num_triangles), est = 0.0;
        rc = ind ? plateau_mesh_error_indicator(&mesh, ind, &est, &err) : PLATEAU_ERR_OUT_OF_MEMORY;
#ifdef PLATEAU_NO_ACCURACY
        refused(rc, &err, "PLATEAU_NO_ACCURACY", "plateau_mesh_error_indicator");
#else
        if (seeding == PLATEAU_SEEDING_AUTO)
            check(rc == PLATEAU_OK && est == rep.area_error_estimate, "the indicator's estimate is the report's");
#endif
        free(ind);
    }
#ifdef PLATEAU_NO_EXTRAS
    { /* the public functions the pipeline never calls refuse, naming the macro */
        plateau_index verts[64];
        double grad[3 * 64], k[3] = {0.0, 0.0, 0.0}, *g = (double *)malloc(sizeof(double) * mesh.num_vertices);
        size_t count = 0;
        FILE *f;
        rc = plateau_mesh_self_check(&mesh, &err);
        refused(rc, &err, "PLATEAU_NO_EXTRAS", "plateau_mesh_self_check");
        rc = plateau_mesh_minimize(&mesh, NULL, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_EXTRAS", "plateau_mesh_minimize");
        rc = plateau_write_mesh_marked("switches-never-written.obj", mesh.positions, mesh.num_vertices,
                                       mesh.triangles, mesh.num_triangles, NULL, PLATEAU_MESH_FORMAT_AUTO, NULL,
                                       &err);
        refused(rc, &err, "PLATEAU_NO_EXTRAS", "plateau_write_mesh_marked");
        f = fopen("switches-never-written.obj", "r");
        check(f == NULL, "plateau_write_mesh_marked writes no file");
        if (f) fclose(f);
        check(plateau_vertex_mean_curvature_vector(&mesh, M, k) != plateau_vertex_mean_curvature_vector(&mesh, M, k) &&
                  k[0] != k[0] && k[1] != k[1] && k[2] != k[2],
              "plateau_vertex_mean_curvature_vector: NaN");
        rc = g ? plateau_mesh_area_hessian_normal(&mesh, NULL, g, NULL, NULL, &err) : PLATEAU_ERR_OUT_OF_MEMORY;
#if defined(PLATEAU_NO_STABILITY) && defined(PLATEAU_NO_COARSE_TO_FINE) && defined(PLATEAU_NO_ACCURACY)
        refused(rc, &err, "PLATEAU_NO_EXTRAS", "plateau_mesh_area_hessian_normal");
#else
        check(rc == PLATEAU_OK, "plateau_mesh_area_hessian_normal stays (a compiled feature calls it)");
#endif
        rc = plateau_vertex_mean_curvature_gradient(&mesh, M, 64, verts, grad, &count, NULL);
#ifdef PLATEAU_NO_COARSE_TO_FINE
        check(rc == PLATEAU_ERR_ARGUMENT, "plateau_vertex_mean_curvature_gradient: PLATEAU_ERR_ARGUMENT");
#else
        check(rc == PLATEAU_OK && count > 1, "plateau_vertex_mean_curvature_gradient stays (coarse to fine calls it)");
#endif
        free(g);
    }
#else
    check(plateau_mesh_self_check(&mesh, &err) == PLATEAU_OK, "plateau_mesh_self_check passes");
#endif
#ifdef PLATEAU_NO_SVG
    rc = plateau_write_svg("switches-never-written.svg", mesh.positions, mesh.num_vertices, mesh.triangles,
                           mesh.num_triangles, NULL, NULL, &err);
    refused(rc, &err, "PLATEAU_NO_SVG", "plateau_write_svg");
    {
        FILE *f = fopen("switches-never-written.svg", "r");
        check(f == NULL, "plateau_write_svg writes no file");
        if (f) fclose(f);
    }
#endif
#ifdef PLATEAU_NO_PLY_OFF_STL
    { /* PLY, OFF and STL refused (by extension and by format), OBJ written */
        static const char *const paths[] = {"switches-never-written.ply", "switches-never-written.off",
                                            "switches-never-written.stl"};
        size_t k;
        FILE *f;
        for (k = 0; k < 3; k++) {
            rc = plateau_write_mesh(paths[k], mesh.positions, mesh.num_vertices, mesh.triangles, mesh.num_triangles,
                                    &err);
            refused(rc, &err, "PLATEAU_NO_PLY_OFF_STL", paths[k]);
            f = fopen(paths[k], "r");
            check(f == NULL, "a refused format writes no file");
            if (f) fclose(f);
        }
        rc = plateau_write_mesh_format("switches-never-written.obj", mesh.positions, mesh.num_vertices,
                                       mesh.triangles, mesh.num_triangles, PLATEAU_MESH_FORMAT_STL_ASCII, &err);
        refused(rc, &err, "PLATEAU_NO_PLY_OFF_STL", "plateau_write_mesh_format STL_ASCII");
        rc = plateau_write_mesh_marked("switches-never-written.ply", mesh.positions, mesh.num_vertices,
                                       mesh.triangles, mesh.num_triangles, NULL, PLATEAU_MESH_FORMAT_AUTO, NULL,
                                       &err);
#ifndef PLATEAU_NO_EXTRAS /* else the marked writer refuses naming PLATEAU_NO_EXTRAS (above) */
        refused(rc, &err, "PLATEAU_NO_PLY_OFF_STL", "plateau_write_mesh_marked PLY");
#endif
        rc = plateau_write_mesh("switches-written.obj", mesh.positions, mesh.num_vertices, mesh.triangles,
                                mesh.num_triangles, &err);
        check(rc == PLATEAU_OK, "the OBJ writer stays");
        remove("switches-written.obj");
    }
#endif
    plateau_mesh_free(&mesh);
}

/* one solve with one option changed from the defaults, refused */
static void refused_option(const plateau_options *opt, const char *macro, const char *what)
{
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    plateau_result rc = plateau_solve(ring, M, opt, &mesh, &rep, &err);
    refused(rc, &err, macro, what);
    check(mesh.num_vertices == 0 && mesh.positions == NULL, "a refused solve returns no mesh");
    plateau_mesh_free(&mesh);
}

static void compiled_out(void)
{
    plateau_options opt;
    plateau_error err;
    plateau_result rc;
    (void)rc;
    (void)err;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 30;
    (void)refused_option;
#ifdef PLATEAU_NO_STABILITY
    opt.stability = PLATEAU_ON;
    refused_option(&opt, "PLATEAU_NO_STABILITY", "stability ON");
    opt.stability = PLATEAU_AUTO;
    opt.critical_index = 1;
    refused_option(&opt, "PLATEAU_NO_STABILITY", "critical_index 1");
    opt.critical_index = 0;
#endif
#ifdef PLATEAU_NO_MEMBRANES
    opt.pressure = 0.5;
    refused_option(&opt, "PLATEAU_NO_MEMBRANES", "a pressure");
    opt.pressure = 0.0;
    opt.fix_volume = 1;
    refused_option(&opt, "PLATEAU_NO_MEMBRANES", "a held volume");
    opt.fix_volume = 0;
#endif
#ifdef PLATEAU_NO_COARSE_TO_FINE
    opt.coarse_to_fine = PLATEAU_ON;
    refused_option(&opt, "PLATEAU_NO_COARSE_TO_FINE", "coarse_to_fine ON");
    opt.coarse_to_fine = PLATEAU_AUTO;
#endif
#ifdef PLATEAU_LM_NO_SPARSE
    opt.linear_solver = PLATEAU_LINEAR_SPARSE;
    refused_option(&opt, "PLATEAU_LM_NO_SPARSE", "linear_solver SPARSE");
    opt.linear_solver = PLATEAU_LINEAR_AUTO;
    opt.area_warm_start = PLATEAU_ON;
    opt.method = PLATEAU_METHOD_AREA;
    refused_option(&opt, "PLATEAU_LM_NO_SPARSE", "area_warm_start ON");
    opt.area_warm_start = PLATEAU_AUTO;
    opt.method = PLATEAU_METHOD_PAPER;
    {
        plateau_lm_sparse_symbolic *sym = NULL;
        plateau_lm_sparse_pattern pat;
        plateau_index rs[2] = {0, 1}, cols[1] = {0};
        memset(&pat, 0, sizeof pat);
        pat.nodes = 1;
        pat.block = 1;
        pat.row_start = rs;
        pat.cols = cols;
        check(plateau_lm_sparse_analyze(&pat, NULL, NULL, &sym) == PLATEAU_LM_ERR_ARGUMENT && sym == NULL,
              "plateau_lm_sparse_analyze: PLATEAU_LM_ERR_ARGUMENT");
    }
#endif
#ifdef PLATEAU_LM_NO_CONSTRAINTS
    {
        /* the line y = a t + b through (0, 1) and (1, 3), with a = b + 1 */
        double x[2] = {0.0, 0.0}, a_eq[2] = {1.0, -1.0}, b_eq[1] = {1.0}, lb[2] = {-10.0, -10.0};
        plateau_lm_options lo;
        plateau_lm_error lerr;
        memset(&lo, 0, sizeof lo);
        lo.constraints = 1;
        lo.a_eq = a_eq;
        lo.b_eq = b_eq;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_CONSTRAINTS") != NULL,
              "plateau_lm_solve with a constraint: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_CONSTRAINTS");
        lo.constraints = 0;
        lo.lower = lb; /* a bound: refused with the constraints */
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_CONSTRAINTS") != NULL,
              "plateau_lm_solve with a bound: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_CONSTRAINTS");
        lo.lower = NULL;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) == PLATEAU_LM_OK &&
                  fabs(x[0] - 2.0) < 1e-9 && fabs(x[1] - 1.0) < 1e-9,
              "plateau_lm_solve without constraints fits the line");
    }
#endif
#ifdef PLATEAU_NO_LOOPS
    {
        size_t counts[2] = {M, M};
        plateau_mesh mesh;
        rc = plateau_solve_loops(ring, counts, 2, &opt, &mesh, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_LOOPS", "two loops");
        plateau_mesh_free(&mesh);
    }
#endif
#ifdef PLATEAU_NO_SUPPORTS
    {
        double point[3] = {0.0, 0.0, 0.1};
        size_t one = 1;
        plateau_options so = opt;
        plateau_mesh mesh;
        so.supports = point;
        so.support_counts = &one;
        so.num_support_polylines = 1;
        rc = plateau_solve(ring, M, &so, &mesh, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_SUPPORTS", "a support point");
        plateau_mesh_free(&mesh);
    }
#endif
#ifdef PLATEAU_NO_SLIDING
    {
        int slide[M];
        double dir[3 * M];
        plateau_options so = opt;
        plateau_mesh mesh;
        memset(slide, 0, sizeof slide);
        memset(dir, 0, sizeof dir);
        slide[0] = PLATEAU_SLIDE_LINE;
        dir[2] = 1.0;
        so.slide = slide;
        so.slide_direction = dir;
        rc = plateau_solve(ring, M, &so, &mesh, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_SLIDING", "a sliding vertex");
        plateau_mesh_free(&mesh);
    }
#endif
#ifdef PLATEAU_NO_ACCURACY
    opt.accuracy = 1e-3;
    refused_option(&opt, "PLATEAU_NO_ACCURACY", "accuracy 1e-3");
    opt.accuracy = 0.0;
    {
        /* the default accuracy means none: one solve at n = m */
        plateau_mesh mesh;
        plateau_report rep;
        opt.interior_points = 0;
        rc = plateau_solve(ring, M, &opt, &mesh, &rep, &err);
        check(rc == PLATEAU_OK && rep.accuracy_solves == 1 && rep.accuracy == 0.0,
              "the default options: one solve, no accuracy aimed at");
        plateau_mesh_free(&mesh);
        opt.interior_points = 30;
    }
#endif
#ifdef PLATEAU_NO_PARSERS
    {
        static const char text[] = "0 0 0\n1 0 0\n0 1 0\n";
        double *xyz = NULL;
        size_t m = 7;
        rc = plateau_parse_boundary(text, sizeof text - 1, NULL, &xyz, &m, &err);
        refused(rc, &err, "PLATEAU_NO_PARSERS", "plateau_parse_boundary");
        check(xyz == NULL && m == 0, "plateau_parse_boundary returns nothing");
        rc = plateau_read_boundary_file("cli/samples/helicoid.txt", NULL, &xyz, &m, &err);
        refused(rc, &err, "PLATEAU_NO_PARSERS", "plateau_read_boundary_file");
    }
#endif
}

/* the switches of the paper's pipeline: the quality seeding (and
 * plateau_delaunay.h's Steiner points), the LM's extras */
static void compiled_out_pipeline(void)
{
    plateau_options opt;
    plateau_error err;
    plateau_result rc;
    (void)rc;
    (void)err;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 30;
#ifdef PLATEAU_NO_QUALITY_SEEDING
    opt.seeding = PLATEAU_SEEDING_QUALITY;
    refused_option(&opt, "PLATEAU_NO_QUALITY_SEEDING", "seeding QUALITY");
    opt.seeding = PLATEAU_SEEDING_AUTO;
    opt.coarse_to_fine = PLATEAU_ON;
    refused_option(&opt, "PLATEAU_NO_QUALITY_SEEDING", "coarse_to_fine ON (implied switch)");
    opt.coarse_to_fine = PLATEAU_AUTO;
    {
        size_t counts[2] = {M, M};
        plateau_mesh mesh;
        rc = plateau_solve_loops(ring, counts, 2, &opt, &mesh, NULL, &err);
        refused(rc, &err, "PLATEAU_NO_QUALITY_SEEDING", "two loops (implied switch)");
        plateau_mesh_free(&mesh);
    }
    {
        /* plateau_delaunay.h adds no point: PLATEAU_DT_NO_STEINER */
        double pts[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        plateau_dt_input in;
        plateau_dt_options dopt;
        plateau_dt_mesh dm;
        plateau_dt_error derr;
        memset(&in, 0, sizeof in);
        memset(&dopt, 0, sizeof dopt);
        in.points = pts;
        in.num_points = 4;
        dopt.min_angle = 20.0;
        check(plateau_dt_triangulate(&in, &dopt, &dm, &derr) == PLATEAU_DT_ERR_ARGUMENT &&
                  strstr(derr.message, "PLATEAU_DT_NO_STEINER") != NULL,
              "plateau_dt_triangulate with min_angle: PLATEAU_DT_ERR_ARGUMENT naming PLATEAU_DT_NO_STEINER");
        dopt.min_angle = 0.0;
        check(plateau_dt_triangulate(&in, &dopt, &dm, &derr) == PLATEAU_DT_OK && dm.num_triangles == 2,
              "plateau_dt_triangulate without refinement: two triangles");
        plateau_dt_free(&dm);
    }
#endif
#ifdef PLATEAU_LM_NO_EXTRAS
    {
        double x[2] = {0.0, 0.0}, cov[4];
        plateau_lm_options lo;
        plateau_lm_error lerr;
        memset(&lo, 0, sizeof lo);
        lo.loss = PLATEAU_LM_LOSS_HUBER;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_EXTRAS") != NULL,
              "plateau_lm_solve with a Huber loss: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_EXTRAS");
        lo.loss = PLATEAU_LM_LOSS_SQUARED;
        lo.geodesic = PLATEAU_LM_GEODESIC_ALWAYS;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_EXTRAS") != NULL,
              "plateau_lm_solve with geodesic ALWAYS: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_EXTRAS");
        lo.geodesic = PLATEAU_LM_GEODESIC_AUTO;
        lo.numeric_jacobian = 1;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_EXTRAS") != NULL,
              "plateau_lm_solve with numeric_jacobian: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_EXTRAS");
        lo.numeric_jacobian = 0;
        lo.weights = x; /* two weights, any values: refused before they are read */
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) ==
                      PLATEAU_LM_ERR_ARGUMENT &&
                  strstr(lerr.message, "PLATEAU_LM_NO_EXTRAS") != NULL,
              "plateau_lm_solve with weights: PLATEAU_LM_ERR_ARGUMENT naming PLATEAU_LM_NO_EXTRAS");
        lo.weights = NULL;
        check(plateau_lm_solve(2, 2, x, line_residuals, NULL, &lo, NULL, 0, NULL, &lerr) == PLATEAU_LM_OK &&
                  fabs(x[0] - 2.0) < 1e-9 && fabs(x[1] - 1.0) < 1e-9,
              "plateau_lm_solve with the squared loss fits the line");
        check(plateau_lm_covariance(2, 2, x, line_residuals, NULL, &lo, cov, NULL, NULL, NULL, 0) ==
                  PLATEAU_LM_ERR_ARGUMENT,
              "plateau_lm_covariance: PLATEAU_LM_ERR_ARGUMENT");
        check(plateau_lm_check_jacobian(2, 2, x, line_residuals, NULL, &lo, NULL, NULL, NULL, 0) ==
                  PLATEAU_LM_ERR_ARGUMENT,
              "plateau_lm_check_jacobian: PLATEAU_LM_ERR_ARGUMENT");
    }
#endif
}

int main(void)
{
    make_rings();
    plain_film(PLATEAU_METHOD_PAPER, PLATEAU_SEEDING_AUTO);
    plain_film(PLATEAU_METHOD_PAPER_LITERAL, PLATEAU_SEEDING_AUTO);
    plain_film(PLATEAU_METHOD_AREA, PLATEAU_SEEDING_AUTO);
    plain_film(PLATEAU_METHOD_PAPER, PLATEAU_SEEDING_PAPER);
    plain_film(PLATEAU_METHOD_AREA, PLATEAU_SEEDING_PAPER);
    compiled_out();
    compiled_out_pipeline();
    printf("switches: %d checks passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
