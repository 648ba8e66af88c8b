/* bench_stability.c - the cost of the stability report, next to one
 * sparse Cholesky factorisation of the same normal Hessian, in CPU
 * seconds: the paper's helicoid by method area at 10^3, 10^4 and 10^5
 * interior vertices ("quick": up to 10^4).  The report's extra cost is
 * plateau_solve with options.stability ON (2 eigenvalues) minus the same
 * solve with it OFF, the medians of 5 solves each (alternating, one run);
 * the target is extra / Cholesky <= 1 at 10^4.  Also plateau_mesh_stability
 * called alone on the result (its own analysis, 2 and 4 eigenvalues) and
 * the Cholesky's factorisation (analysis excluded), medians of 5. */
#define _DEFAULT_SOURCE
#include "bench/bench_common.h"
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "examples/surfaces.h"

/* CPU seconds of this process: on the shared machine wall time mixes in
 * the other processes' load */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Seconds of one Cholesky factorisation (analysis excluded) of the normal
 * Hessian M^-1/2 H M^-1/2 + 1e-8 I on the free vertices' pattern, as the
 * report builds it; -1 on failure. */
static double cholesky_seconds(const plateau_mesh *mesh)
{
    size_t nv = mesh->num_vertices, ne = mesh->num_edges, v, e, q = 0, k = 0, nf = 0;
    double *diag = (double *)malloc(nv * sizeof(double)), *off = (double *)malloc(ne * sizeof(double));
    double *vals = (double *)malloc((nv + 2 * ne) * sizeof(double)), *msq = (double *)malloc(nv * sizeof(double));
    plateau_index *node = (plateau_index *)malloc(nv * sizeof(plateau_index));
    plateau_index *rs = (plateau_index *)malloc((nv + 1) * sizeof(plateau_index));
    plateau_index *cols = (plateau_index *)malloc((nv + 2 * ne) * sizeof(plateau_index));
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    double t = -1.0, t0;
    if (!diag || !off || !vals || !msq || !node || !rs || !cols) goto done;
    if (plateau_mesh_area_hessian_normal(mesh, NULL, NULL, diag, off, NULL) != PLATEAU_OK) goto done;
    for (v = 0; v < nv; v++) {
        node[v] = mesh->fixed[v] ? -1 : (plateau_index)nf++;
        msq[v] = sqrt(plateau_vertex_area(mesh, v));
    }
    for (v = 0; v < nv; v++) {
        if (mesh->fixed[v]) continue;
        rs[k++] = (plateau_index)q;
        cols[q] = node[v];
        vals[q++] = diag[v] / (msq[v] * msq[v]);
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed];
            if (mesh->fixed[w]) continue;
            cols[q] = node[w];
            vals[q++] = off[ed] / (msq[v] * msq[w]);
        }
    }
    rs[k] = (plateau_index)q;
    pat.nodes = nf;
    pat.block = 1;
    pat.row_start = rs;
    pat.cols = cols;
    if (plateau_lm_sparse_analyze(&pat, NULL, NULL, &S) != PLATEAU_LM_OK) goto done;
    if (plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_CHOLESKY, NULL, 0, &F) != PLATEAU_LM_OK) goto done;
    t0 = cpu_now();
    if (plateau_lm_sparse_factorize(F, vals, 1e-8) == PLATEAU_LM_OK) t = cpu_now() - t0;
done:
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    free(diag); free(off); free(vals); free(msq); free(node); free(rs); free(cols);
    return t;
}

/* CPU seconds of one plateau_solve of the helicoid with n interior
 * points and the stability report on or off; the mesh is kept in *mesh
 * (the caller frees it); -1 on failure. */
static double solve_seconds(const demo_case *c, size_t n, int on, plateau_mesh *mesh, plateau_report *rep)
{
    double boundary[3 * DEMO_MAX_BOUNDARY], t0, t;
    size_t m = demo_boundary(c, boundary);
    plateau_options o;
    plateau_error e;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = n;
    o.stability = on ? PLATEAU_ON : PLATEAU_OFF;
    t0 = cpu_now();
    if (plateau_solve(boundary, m, &o, mesh, rep, &e) != PLATEAU_OK) {
        printf("%8lu solve failed: %s\n", (unsigned long)n, e.message);
        return -1.0;
    }
    t = cpu_now() - t0;
    return t;
}

int main(int argc, char **argv)
{
    static const size_t sizes[3] = {1000, 10000, 100000};
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0, k, r;
    const demo_case *c = demo_find("helicoid");
    printf("stability report after method area on the helicoid (CPU seconds, medians of 5)\n");
    printf("%8s %8s %8s %8s %9s %9s %9s %8s %9s %8s %6s %s\n", "n", "solve", "with rep", "extra", "cholesky",
           "extra/ch", "alone 2", "alone/ch", "alone 4", "4/ch", "index", "lowest");
    for (k = 0; k < (quick ? 2 : 3); k++) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error e;
        plateau_stability st, on_st;
        double toff[5], ton[5], tr[5], t4[5], tc[5], off_m, on_m, rm, r4, cm, t0;
        memset(&on_st, 0, sizeof on_st);
        for (r = 0; r < 5; r++) {
            plateau_mesh m2;
            plateau_report rep2;
            toff[r] = solve_seconds(c, sizes[k], 0, &m2, &rep2);
            if (toff[r] < 0.0) return 1;
            plateau_mesh_free(&m2);
            ton[r] = solve_seconds(c, sizes[k], 1, &m2, &rep2);
            if (ton[r] < 0.0) return 1;
            on_st = rep2.stability;
            plateau_mesh_free(&m2);
        }
        if (solve_seconds(c, sizes[k], 0, &mesh, &rep) < 0.0) return 1;
        for (r = 0; r < 5; r++) {
            t0 = cpu_now();
            if (plateau_mesh_stability(&mesh, 4, &st, NULL, &e) != PLATEAU_OK) {
                printf("report failed: %s\n", e.message);
                return 1;
            }
            t4[r] = cpu_now() - t0;
            t0 = cpu_now();
            if (plateau_mesh_stability(&mesh, 2, &st, NULL, &e) != PLATEAU_OK) {
                printf("report failed: %s\n", e.message);
                return 1;
            }
            tr[r] = cpu_now() - t0;
            tc[r] = cholesky_seconds(&mesh);
        }
        off_m = bench_median(toff, 5);
        on_m = bench_median(ton, 5);
        rm = bench_median(tr, 5);
        r4 = bench_median(t4, 5);
        cm = bench_median(tc, 5);
        printf("%8lu %8.3f %8.3f %8.4f %9.4f %9.2f %9.4f %8.2f %9.4f %8.2f %6lu %.4g\n",
               (unsigned long)rep.interior_points, off_m, on_m, on_m - off_m, cm, (on_m - off_m) / cm, rm, rm / cm,
               r4, r4 / cm, (unsigned long)on_st.index, on_st.num_eigenvalues ? on_st.lowest_eigenvalues[0] : 0.0);
        fflush(stdout);
        plateau_mesh_free(&mesh);
    }
    return 0;
}
