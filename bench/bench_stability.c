/* bench_stability.c - the cost of the stability report (plateau_mesh_stability:
 * one analysis, the L D L^T, the Lanczos solves, two vectors at a time)
 * with the 2 lowest eigenvalues plateau_solve asks for and with 4, next
 * to the solve it follows and to one sparse Cholesky factorisation of the
 * same normal Hessian, in CPU seconds: the paper's helicoid by method area
 * at 10^3, 10^4 and 10^5 interior vertices ("quick": up to 10^4).  Medians
 * of 5 runs of the reports and of the factorisation; the solve is run
 * once. */
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

int main(int argc, char **argv)
{
    static const size_t sizes[3] = {1000, 10000, 100000};
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0, k, r;
    const demo_case *c = demo_find("helicoid");
    printf("stability report after method area on the helicoid (CPU seconds; reports and factorisation: medians of 5)\n");
    printf("%8s %8s %9s %9s %9s %8s %8s %6s %s\n", "n", "solve", "report 2", "report 4", "cholesky", "2 / chol",
           "4 / chol", "index", "lowest");
    for (k = 0; k < (quick ? 2 : 3); k++) {
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error e;
        plateau_options o;
        double boundary[3 * DEMO_MAX_BOUNDARY], t0, ts, tr[5], t4[5], tc[5], rm, r4, cm;
        size_t m = demo_boundary(c, boundary);
        plateau_stability st;
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_AREA;
        o.interior_points = sizes[k];
        o.stability = PLATEAU_OFF;
        t0 = cpu_now();
        if (plateau_solve(boundary, m, &o, &mesh, &rep, &e) != PLATEAU_OK) {
            printf("%8lu solve failed: %s\n", (unsigned long)sizes[k], e.message);
            return 1;
        }
        ts = cpu_now() - t0;
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
        rm = bench_median(tr, 5);
        r4 = bench_median(t4, 5);
        cm = bench_median(tc, 5);
        printf("%8lu %8.3f %9.4f %9.4f %9.4f %8.2f %8.2f %6lu %.4g\n", (unsigned long)rep.interior_points, ts, rm, r4,
               cm, rm / cm, r4 / cm, (unsigned long)st.index, st.num_eigenvalues ? st.lowest_eigenvalues[0] : 0.0);
        fflush(stdout);
        plateau_mesh_free(&mesh);
    }
    return 0;
}
