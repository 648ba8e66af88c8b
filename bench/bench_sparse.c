/* bench_sparse.c - speed and memory of the block-sparse direct solver of
 * plateau_lm.h (built by `make bench`).
 *
 * Matrices with 3 x 3 blocks (b = 3, the unknowns of a mesh vertex) on the
 * node graph of a Delaunay mesh of 10^3, 10^4 and 10^5 uniform random points
 * in the unit square and of triangulated grids of about the same sizes
 * (tests/sparse_mesh.h): an unsymmetric one for LU and a symmetric positive
 * definite one for Cholesky.  For each: analysis time (geometric nested
 * dissection + symbolic), median CPU time of several numeric factorisations,
 * the fill (blocks of L), flops and rate, factor object bytes, and the
 * relative residual of one solve.
 * When built with PLATEAU_BENCH_SUITESPARSE (the Makefile does so when
 * Debian's libsuitesparse-dev is installed: an optional peer, nothing needs
 * it) the same scalar matrices also go through UMFPACK (default ordering)
 * and CHOLMOD (default ordering), numeric factorisation timed the same way,
 * and the ratios plateau / peer are printed.
 * PLATEAU_BENCH_QUICK=1 in the environment runs only the smaller sizes.
 */
#define PLATEAU_IMPLEMENTATION
#include "plateau_lm.h"
#include "plateau_delaunay.h"
#include "tests/sparse_mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef PLATEAU_BENCH_SUITESPARSE
#include <umfpack.h>
#include <cholmod.h>
#endif

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static double median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof(double), cmp_double);
    return t[n / 2];
}

#ifdef PLATEAU_BENCH_SUITESPARSE
/* The scalar matrix in compressed columns (rows ascending); lower only when
 * lower != 0 (CHOLMOD's stype = -1 reads the lower triangle). */
static void to_csc(const sm_graph *g, size_t b, const double *v, int lower, int **Ap, int **Ai,
                   double **Ax)
{
    size_t N = g->n * b, i, p, r, c, nz = 0, bb = b * b;
    int *cnt = (int *)calloc(N + 1, sizeof(int));
    for (i = 0; i < g->n; i++)
        for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++)
            for (r = 0; r < b; r++)
                for (c = 0; c < b; c++) {
                    size_t row = i * b + r, col = (size_t)g->cols[p] * b + c;
                    if (lower && row < col) continue;
                    cnt[col + 1]++;
                    nz++;
                }
    for (i = 0; i < N; i++) cnt[i + 1] += cnt[i];
    *Ap = (int *)malloc((N + 1) * sizeof(int));
    *Ai = (int *)malloc(nz * sizeof(int));
    *Ax = (double *)malloc(nz * sizeof(double));
    memcpy(*Ap, cnt, (N + 1) * sizeof(int));
    /* rows ascending: walk block rows in order */
    for (i = 0; i < g->n; i++)
        for (r = 0; r < b; r++)
            for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++)
                for (c = 0; c < b; c++) {
                    size_t row = i * b + r, col = (size_t)g->cols[p] * b + c;
                    if (lower && row < col) continue;
                    (*Ai)[cnt[col]] = (int)row;
                    (*Ax)[cnt[col]++] = v[p * bb + r * b + c];
                }
    free(cnt);
}

static double umfpack_time(const sm_graph *g, size_t b, const double *v, int reps, double *mem,
                           double *lunz)
{
    int *Ap, *Ai, k, N = (int)(g->n * b);
    double *Ax, t[9], Control[UMFPACK_CONTROL], Info[UMFPACK_INFO];
    void *Sym = NULL, *Num = NULL;
    to_csc(g, b, v, 0, &Ap, &Ai, &Ax);
    umfpack_di_defaults(Control);
    if (umfpack_di_symbolic(N, N, Ap, Ai, Ax, &Sym, Control, Info) != UMFPACK_OK) return -1.0;
    for (k = 0; k < reps; k++) {
        double t0 = cpu();
        if (umfpack_di_numeric(Ap, Ai, Ax, Sym, &Num, Control, Info) != UMFPACK_OK) return -1.0;
        t[k] = cpu() - t0;
        if (k + 1 < reps) umfpack_di_free_numeric(&Num);
    }
    *mem = Info[UMFPACK_PEAK_MEMORY] * Info[UMFPACK_SIZE_OF_UNIT];
    *lunz = Info[UMFPACK_LNZ] + Info[UMFPACK_UNZ];
    umfpack_di_free_numeric(&Num);
    umfpack_di_free_symbolic(&Sym);
    free(Ap); free(Ai); free(Ax);
    return median(t, reps);
}

static double cholmod_time(const sm_graph *g, size_t b, const double *v, int reps, double *lnz)
{
    cholmod_common cm;
    cholmod_sparse *A;
    cholmod_factor *L;
    int *Ap, *Ai, k, N = (int)(g->n * b);
    double *Ax, t[9];
    to_csc(g, b, v, 1, &Ap, &Ai, &Ax);
    cholmod_start(&cm);
    A = cholmod_allocate_sparse((size_t)N, (size_t)N, (size_t)Ap[N], 1, 1, -1, CHOLMOD_REAL, &cm);
    memcpy(A->p, Ap, (size_t)(N + 1) * sizeof(int));
    memcpy(A->i, Ai, (size_t)Ap[N] * sizeof(int));
    memcpy(A->x, Ax, (size_t)Ap[N] * sizeof(double));
    L = cholmod_analyze(A, &cm);
    for (k = 0; k < reps; k++) {
        double t0 = cpu();
        cholmod_factorize(A, L, &cm);
        t[k] = cpu() - t0;
    }
    *lnz = cm.lnz;
    if (cm.status != CHOLMOD_OK) t[0] = t[1] = t[2] = -1.0;
    cholmod_free_factor(&L, &cm);
    cholmod_free_sparse(&A, &cm);
    cholmod_finish(&cm);
    free(Ap); free(Ai); free(Ax);
    return median(t, reps);
}
#endif

static void run(const char *name, const sm_graph *g, int reps)
{
    size_t b = 3, N = g->n * b, i;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    plateau_lm_sparse_info info;
    double *vlu = sm_values(g, b, 0, 1), *vch = sm_values(g, b, 1, 2);
    double *x = (double *)malloc(N * sizeof(double)), *r = (double *)malloc(N * sizeof(double));
    double *ax = (double *)malloc(N * sizeof(double));
    double t[9], ta, tlu = 0.0, tch = 0.0, res_lu = 0.0, res_ch = 0.0;
    unsigned long long seed = 3;
    int k, kind;
    pat.nodes = g->n;
    pat.block = (int)b;
    pat.row_start = g->rs;
    pat.cols = g->cols;
    t[0] = cpu();
    if (plateau_lm_sparse_analyze(&pat, g->xy, NULL, &S) != PLATEAU_LM_OK) {
        printf("%s: analysis failed\n", name);
        return;
    }
    ta = cpu() - t[0];
    info = plateau_lm_sparse_symbolic_info(S);
    for (kind = 1; kind <= 2; kind++) {
        const double *v = kind == 1 ? vlu : vch;
        double res = 0.0, an = sm_norm(g, b, v), xn = 0.0;
        if (plateau_lm_sparse_factor_create(S, kind, NULL, 0, &F) != PLATEAU_LM_OK) {
            printf("%s: factor object failed (out of memory?)\n", name);
            return;
        }
        for (k = 0; k < reps; k++) {
            double t0 = cpu();
            if (plateau_lm_sparse_factorize(F, v, 0.0) != PLATEAU_LM_OK) printf("factorisation failed\n");
            t[k] = cpu() - t0;
        }
        for (i = 0; i < N; i++) r[i] = x[i] = sm_rand(&seed) - 0.5;
        plateau_lm_sparse_solve(F, 1, x, N);
        sm_matvec(g, b, v, x, ax);
        for (i = 0; i < N; i++) {
            if (fabs(ax[i] - r[i]) > res) res = fabs(ax[i] - r[i]);
            if (fabs(x[i]) > xn) xn = fabs(x[i]);
        }
        if (kind == 1) { tlu = median(t, reps); res_lu = res / (an * xn); }
        else { tch = median(t, reps); res_ch = res / (an * xn); }
        plateau_lm_sparse_factor_free(F);
        F = NULL;
    }
    printf("%-14s n %7lu  N %7lu  A %8lu blk  L %9lu blk  supernodes %6lu  front %5lu  analyse %.3f s\n",
           name, (unsigned long)g->n, (unsigned long)N, (unsigned long)info.pattern_blocks,
           (unsigned long)info.factor_blocks, (unsigned long)info.supernodes,
           (unsigned long)info.largest_front, ta);
    printf("    LU       %8.3f s  %6.2f Gflop  %5.2f Gflop/s  factor object %7.1f MB  residual %.1e\n",
           tlu, info.flops_lu * 1e-9, info.flops_lu * 1e-9 / tlu,
           (double)info.factor_bytes_lu / 1048576.0, res_lu);
    printf("    Cholesky %8.3f s  %6.2f Gflop  %5.2f Gflop/s  factor object %7.1f MB  residual %.1e\n",
           tch, info.flops_cholesky * 1e-9, info.flops_cholesky * 1e-9 / tch,
           (double)info.factor_bytes_cholesky / 1048576.0, res_ch);
#ifdef PLATEAU_BENCH_SUITESPARSE
    {
        double mem = 0.0, lunz = 0.0, lnz = 0.0;
        double tu = umfpack_time(g, b, vlu, reps, &mem, &lunz);
        double tc = cholmod_time(g, b, vch, reps, &lnz);
        printf("    UMFPACK  %8.3f s  (L+U %.3g entries, peak %.1f MB)   plateau LU / UMFPACK %.2f\n", tu,
               lunz, mem / 1048576.0, tlu / tu);
        printf("    CHOLMOD  %8.3f s  (L %.3g entries)                   plateau Cholesky / CHOLMOD %.2f\n",
               tc, lnz, tch / tc);
    }
#endif
    fflush(stdout);
    plateau_lm_sparse_symbolic_free(S);
    free(vlu); free(vch); free(x); free(r); free(ax);
}

int main(void)
{
    static const size_t sizes[3] = {1000, 10000, 100000};
    static const size_t grids[3] = {32, 100, 316};
    int quick = getenv("PLATEAU_BENCH_QUICK") != NULL, s;
#ifndef PLATEAU_BENCH_SUITESPARSE
    printf("UMFPACK / CHOLMOD: skipped (optional peer: apt-get install libsuitesparse-dev)\n");
#endif
    printf("b = 3; CPU seconds, median of 5 (3 at 10^5) numeric factorisations\n");
    for (s = 0; s < (quick ? 2 : 3); s++) {
        sm_graph g;
        char name[64];
        int reps = s == 2 ? 3 : 5;
        if (!sm_delaunay(&g, sizes[s], 1)) { printf("mesh failed\n"); return 1; }
        sprintf(name, "delaunay %lu", (unsigned long)sizes[s]);
        run(name, &g, reps);
        sm_free(&g);
        if (!sm_grid(&g, grids[s])) { printf("grid failed\n"); return 1; }
        sprintf(name, "grid %lux%lu", (unsigned long)grids[s], (unsigned long)grids[s]);
        run(name, &g, reps);
        sm_free(&g);
    }
    return 0;
}
