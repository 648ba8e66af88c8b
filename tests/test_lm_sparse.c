/* test_lm_sparse.c - the block-sparse direct solver of plateau_lm.h: orderings
 * are permutations, nested dissection beats the natural order on a grid,
 * LU and Cholesky solve random block systems on grids and Delaunay meshes to
 * a residual near rounding and agree with a dense solve, several
 * right-hand sides, reuse of an analysis, every error code, caller
 * workspaces, and allocation failure at every allocation; Powell's dog
 * leg on Rosenbrock and a nonlinear block system on a grid, against the
 * dense LM; the LDL^T's inertia against Jacobi eigenvalues and the grid
 * Laplacian's known spectrum, its solve, its breakdown on a zero pivot. */
#include "plateau.h" /* the declarations, for countalloc.h */
#include "harness.h"
#include "countalloc.h"
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h" /* and plateau_lm.h, plateau_delaunay.h */
#include "sparse_mesh.h"

#include <float.h>

#ifdef PLATEAU_TEST_SANITIZED
#define BIG_GRID 24
#define BIG_DELAUNAY 800
#else
#define BIG_GRID 60
#define BIG_DELAUNAY 5000
#endif

static int all_finite_vec(const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!(v[i] - v[i] == 0.0)) return 0;
    return 1;
}

static plateau_lm_sparse_pattern pattern_of(const sm_graph *g, int b)
{
    plateau_lm_sparse_pattern p;
    p.nodes = g->n;
    p.block = b;
    p.row_start = g->rs;
    p.cols = g->cols;
    return p;
}

static int is_permutation(const plateau_index *perm, size_t n)
{
    size_t i;
    int ok = 1;
    unsigned char *seen = (unsigned char *)calloc(n + 1, 1);
    if (!seen || !perm) { free(seen); return 0; }
    for (i = 0; i < n && ok; i++) {
        if (perm[i] < 0 || (size_t)perm[i] >= n || seen[perm[i]]) ok = 0;
        else seen[perm[i]] = 1;
    }
    free(seen);
    return ok;
}

/* ||A x - r||_inf / (||A||_inf ||x||_inf) for the solution x of A x = r */
static double rel_residual(const sm_graph *g, size_t b, const double *v, const double *x,
                           const double *r)
{
    size_t N = g->n * b, i;
    double *ax = (double *)malloc(N * sizeof(double)), res = 0.0, xn = 0.0;
    if (!ax) return 1.0;
    sm_matvec(g, b, v, x, ax);
    for (i = 0; i < N; i++) {
        if (fabs(ax[i] - r[i]) > res || ax[i] - r[i] != ax[i] - r[i]) res = fabs(ax[i] - r[i]);
        if (fabs(x[i]) > xn) xn = fabs(x[i]);
    }
    free(ax);
    return res / (sm_norm(g, b, v) * xn);
}

/* Analyse, factor, solve one random right-hand side; returns the relative
 * residual (1 on any failure, which is also checked). */
static double solve_case(const sm_graph *g, int b, int kind, int spd, int ordering, int use_xy,
                         unsigned long long seed, plateau_lm_sparse_info *info_out)
{
    plateau_lm_sparse_pattern pat = pattern_of(g, b);
    plateau_lm_sparse_options o;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    size_t N = g->n * (size_t)b, i;
    double *v = sm_values(g, (size_t)b, spd, seed), *r = (double *)malloc(N * sizeof(double)),
           *x = (double *)malloc(N * sizeof(double)), res = 1.0;
    memset(&o, 0, sizeof o);
    o.ordering = ordering;
    if (!v || !r || !x) goto done;
    for (i = 0; i < N; i++) r[i] = x[i] = 2.0 * sm_rand(&seed) - 1.0;
    if (!CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, use_xy ? g->xy : NULL, &o, &S), PLATEAU_LM_OK)) goto done;
    CHECK(is_permutation(plateau_lm_sparse_permutation(S), g->n));
    if (info_out) *info_out = plateau_lm_sparse_symbolic_info(S);
    if (!CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, kind, NULL, 0, &F), PLATEAU_LM_OK)) goto done;
    if (!CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK)) goto done;
    if (!CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, N), PLATEAU_LM_OK)) goto done;
    res = rel_residual(g, (size_t)b, v, x, r);
done:
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    free(v);
    free(r);
    free(x);
    return res;
}

/* ------------------------------------------------------------ tests */

static void test_orderings_are_permutations(void)
{
    sm_graph g;
    int ord;
    if (!CHECK(sm_delaunay(&g, 700, 11))) return;
    for (ord = 0; ord <= 3; ord++) {
        plateau_lm_sparse_pattern pat = pattern_of(&g, 1);
        plateau_lm_sparse_options o;
        plateau_lm_sparse_symbolic *S = NULL;
        memset(&o, 0, sizeof o);
        o.ordering = ord;
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, ord == 2 ? NULL : g.xy, &o, &S), PLATEAU_LM_OK);
        CHECK(is_permutation(plateau_lm_sparse_permutation(S), g.n));
        plateau_lm_sparse_symbolic_free(S);
    }
    sm_free(&g);
}

static void test_nested_dissection_fill(void)
{
    sm_graph g;
    plateau_lm_sparse_info nat, geo, gra;
    if (!CHECK(sm_grid(&g, 40))) return;
    CHECK(solve_case(&g, 1, PLATEAU_LM_SPARSE_CHOLESKY, 1, 3, 0, 1, &nat) < 1e-13);
    CHECK(solve_case(&g, 1, PLATEAU_LM_SPARSE_CHOLESKY, 1, 1, 1, 1, &geo) < 1e-13);
    CHECK(solve_case(&g, 1, PLATEAU_LM_SPARSE_CHOLESKY, 1, 2, 0, 1, &gra) < 1e-13);
    /* natural order on a k x k grid: band k, fill ~ k^3 = 64000 blocks and
     * ~ k^4 flops; nested dissection: O(k^2 log k) fill, O(k^3) flops (the
     * fill gap only opens at larger k, the flop gap already here) */
    printf("fill on a 40 x 40 grid (blocks of L): natural %lu, geometric ND %lu, graph ND %lu; "
           "Cholesky Mflop %.1f, %.1f, %.1f\n",
           (unsigned long)nat.factor_blocks, (unsigned long)geo.factor_blocks,
           (unsigned long)gra.factor_blocks, nat.flops_cholesky * 1e-6, geo.flops_cholesky * 1e-6,
           gra.flops_cholesky * 1e-6);
    CHECK(geo.factor_blocks < 0.6 * (double)nat.factor_blocks);
    CHECK(gra.factor_blocks < 0.6 * (double)nat.factor_blocks);
    CHECK(geo.flops_cholesky < 0.5 * nat.flops_cholesky);
    CHECK(gra.flops_cholesky < 0.5 * nat.flops_cholesky);
    sm_free(&g);
}

static void test_residuals(void)
{
    sm_graph g, d;
    int b, kind;
    if (!CHECK(sm_grid(&g, 17)) || !CHECK(sm_delaunay(&d, 600, 5))) return;
    for (b = 1; b <= 4; b++)
        for (kind = 1; kind <= 2; kind++) {
            int spd = kind == PLATEAU_LM_SPARSE_CHOLESKY;
            CHECK(solve_case(&g, b, kind, spd, 0, 1, 100 + (unsigned)b, NULL) < 1e-14);
            CHECK(solve_case(&g, b, kind, spd, 2, 0, 200 + (unsigned)b, NULL) < 1e-14);
            CHECK(solve_case(&d, b, kind, spd, 0, 1, 300 + (unsigned)b, NULL) < 1e-14);
            CHECK(solve_case(&d, b, kind, spd, 3, 0, 400 + (unsigned)b, NULL) < 1e-14);
        }
    /* LU of a symmetric positive definite matrix too */
    CHECK(solve_case(&d, 3, PLATEAU_LM_SPARSE_LU, 1, 0, 1, 7, NULL) < 1e-14);
    sm_free(&g);
    sm_free(&d);
}

static void test_large(void)
{
    sm_graph g, d;
    plateau_lm_sparse_info info;
    double r;
    if (!CHECK(sm_grid(&g, BIG_GRID)) || !CHECK(sm_delaunay(&d, BIG_DELAUNAY, 9))) return;
    r = solve_case(&g, 3, PLATEAU_LM_SPARSE_LU, 0, 0, 1, 1, &info);
    CHECK(r < 1e-14);
    CHECK(info.supernodes < info.nodes);
    CHECK(solve_case(&d, 3, PLATEAU_LM_SPARSE_LU, 0, 0, 1, 2, NULL) < 1e-14);
    CHECK(solve_case(&d, 3, PLATEAU_LM_SPARSE_CHOLESKY, 1, 0, 1, 3, NULL) < 1e-14);
    CHECK(solve_case(&d, 3, PLATEAU_LM_SPARSE_LU, 0, 2, 0, 4, NULL) < 1e-14);
    sm_free(&g);
    sm_free(&d);
}

/* Dense Gaussian elimination with partial pivoting: A (N x N row-major) x = r */
static int dense_solve(double *A, double *x, size_t N)
{
    size_t i, j, k;
    for (k = 0; k < N; k++) {
        size_t pr = k;
        for (i = k + 1; i < N; i++)
            if (fabs(A[i * N + k]) > fabs(A[pr * N + k])) pr = i;
        if (A[pr * N + k] == 0.0) return 0;
        if (pr != k) {
            for (j = 0; j < N; j++) { double t = A[k * N + j]; A[k * N + j] = A[pr * N + j]; A[pr * N + j] = t; }
            { double t = x[k]; x[k] = x[pr]; x[pr] = t; }
        }
        for (i = k + 1; i < N; i++) {
            double f = A[i * N + k] / A[k * N + k];
            for (j = k; j < N; j++) A[i * N + j] -= f * A[k * N + j];
            x[i] -= f * x[k];
        }
    }
    for (k = N; k-- > 0;) {
        double s = x[k];
        for (j = k + 1; j < N; j++) s -= A[k * N + j] * x[j];
        x[k] = s / A[k * N + k];
    }
    return 1;
}

static void test_dense_agreement(void)
{
    sm_graph g;
    int kind;
    if (!CHECK(sm_delaunay(&g, 40, 3))) return;
    for (kind = 1; kind <= 2; kind++) {
        size_t b = 3, N = g.n * b, i, p, r, c, nrhs = 3, ld = N + 5;
        int spd = kind == PLATEAU_LM_SPARSE_CHOLESKY;
        unsigned long long seed = 77;
        double *v = sm_values(&g, b, spd, 1234 + (unsigned)kind);
        double *A = (double *)calloc(N * N, sizeof(double));
        double *rhs = (double *)malloc(ld * nrhs * sizeof(double));
        double *xd = (double *)malloc(N * sizeof(double)), maxdiff = 0.0, xmax = 0.0;
        plateau_lm_sparse_pattern pat = pattern_of(&g, (int)b);
        plateau_lm_sparse_symbolic *S = NULL;
        plateau_lm_sparse_factor *F = NULL;
        size_t col;
        if (!v || !A || !rhs || !xd) return;
        for (i = 0; i < g.n; i++)
            for (p = (size_t)g.rs[i]; p < (size_t)g.rs[i + 1]; p++)
                for (r = 0; r < b; r++)
                    for (c = 0; c < b; c++)
                        A[(i * b + r) * N + (size_t)g.cols[p] * b + c] = v[p * b * b + r * b + c];
        /* a shift moves the diagonal: compare against A + 0.5 I */
        for (i = 0; i < N; i++) A[i * N + i] += 0.5;
        for (i = 0; i < ld * nrhs; i++) rhs[i] = 2.0 * sm_rand(&seed) - 1.0;
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, NULL, &S), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, kind, NULL, 0, &F), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.5), PLATEAU_LM_OK);
        for (col = 0; col < nrhs; col++) {
            double *Ac = (double *)malloc(N * N * sizeof(double));
            if (!Ac) break;
            memcpy(Ac, A, N * N * sizeof(double));
            memcpy(xd, rhs + col * ld, N * sizeof(double));
            CHECK(dense_solve(Ac, xd, N));
            free(Ac);
            if (col == 0) continue;
            /* columns 1, 2 are solved together below; column 0 alone */
        }
        {
            double *one = (double *)malloc(N * sizeof(double));
            double *pad = rhs + N; /* the padding of column 0 must stay as it is */
            double pad0 = pad[0];
            memcpy(one, rhs, N * sizeof(double));
            CHECK_EQ_INT(plateau_lm_sparse_solve(F, nrhs, rhs, ld), PLATEAU_LM_OK);
            CHECK(pad[0] == pad0);
            memcpy(xd, one, N * sizeof(double));
            {
                double *Ac = (double *)malloc(N * N * sizeof(double));
                memcpy(Ac, A, N * N * sizeof(double));
                CHECK(dense_solve(Ac, xd, N));
                free(Ac);
            }
            for (i = 0; i < N; i++) {
                if (fabs(rhs[i] - xd[i]) > maxdiff) maxdiff = fabs(rhs[i] - xd[i]);
                if (fabs(xd[i]) > xmax) xmax = fabs(xd[i]);
            }
            CHECK(maxdiff <= 1e-12 * xmax);
            free(one);
        }
        plateau_lm_sparse_factor_free(F);
        plateau_lm_sparse_symbolic_free(S);
        free(v); free(A); free(rhs); free(xd);
    }
    sm_free(&g);
}

/* Several right-hand sides at once equal one at a time, bit for bit, for
 * each kind (Cholesky and L D L^T solve them in pairs, reading L once for
 * two columns: four columns are two pairs, three a pair and a single one);
 * the padding between columns stays as it was; a second factorisation
 * with other values reuses the analysis. */
static void test_multi_rhs_and_reuse(void)
{
    sm_graph g;
    size_t b = 2, N, i, ld, j;
    int kind;
    plateau_lm_sparse_pattern pat;
    if (!CHECK(sm_delaunay(&g, 300, 8))) return;
    N = g.n * b;
    ld = N + 3;
    pat = pattern_of(&g, (int)b);
    for (kind = PLATEAU_LM_SPARSE_LU; kind <= PLATEAU_LM_SPARSE_LDLT; kind++) {
        size_t nrhs = kind == PLATEAU_LM_SPARSE_LU ? 4 : (size_t)kind + 1;
        int spd = kind != PLATEAU_LM_SPARSE_LU;
        plateau_lm_sparse_symbolic *S = NULL;
        plateau_lm_sparse_factor *F = NULL;
        double *v1 = sm_values(&g, b, spd, 1), *v2 = sm_values(&g, b, spd, 2), maxd = 0.0, res = 0.0;
        double *B = (double *)malloc(4 * ld * sizeof(double)), *X = (double *)malloc(4 * ld * sizeof(double));
        unsigned long long seed = 5;
        for (i = 0; i < 4 * ld; i++) B[i] = X[i] = sm_rand(&seed) - 0.5;
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, kind, NULL, 0, &F), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v1, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v2, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_solve(F, nrhs, X, ld), PLATEAU_LM_OK);
        for (j = 0; j < nrhs; j++) {
            double *one = (double *)malloc(N * sizeof(double)), r;
            memcpy(one, B + j * ld, N * sizeof(double));
            CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, one, 0), PLATEAU_LM_OK);
            for (i = 0; i < N; i++)
                if (fabs(one[i] - X[j * ld + i]) > maxd) maxd = fabs(one[i] - X[j * ld + i]);
            for (i = N; i < ld && j + 1 < 4; i++) CHECK(X[j * ld + i] == B[j * ld + i]);
            r = rel_residual(&g, b, v2, X + j * ld, B + j * ld);
            if (r > res) res = r;
            free(one);
        }
        for (i = nrhs * ld; i < 4 * ld; i++) CHECK(X[i] == B[i]); /* columns beyond nrhs untouched */
        CHECK(maxd == 0.0);
        CHECK(res < 1e-14);
        printf("  %s, %lu right-hand sides at once: largest relative residual %.1e, largest difference to one at a time %g\n",
               kind == PLATEAU_LM_SPARSE_LU ? "LU" : kind == PLATEAU_LM_SPARSE_CHOLESKY ? "Cholesky" : "L D L^T",
               (unsigned long)nrhs, res, maxd);
        plateau_lm_sparse_factor_free(F);
        plateau_lm_sparse_symbolic_free(S);
        free(v1); free(v2); free(B); free(X);
    }
    sm_free(&g);
}

static void test_errors(void)
{
    /* a 3-node path 0 - 1 - 2 */
    plateau_index rs[4] = {0, 2, 5, 7}, cols[7] = {0, 1, 0, 1, 2, 1, 2};
    plateau_index cols_asym[7] = {0, 1, 0, 1, 2, 2, 2}; /* (2,1) replaced by a repeat */
    plateau_index rs_nodiag[4] = {0, 1, 3, 4}, cols_nodiag[4] = {1, 0, 2, 1};
    plateau_index cols_oor[7] = {0, 1, 0, 1, 3, 1, 2};
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_options o;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    double v[7] = {4, -1, -1, 4, -1, -1, 4}, x[3] = {1, 2, 3};
    double xy[6] = {0, 0, 1, 0, 2, 0};
    unsigned char buf[1 << 16];
    size_t need;
    pat.nodes = 3; pat.block = 1; pat.row_start = rs; pat.cols = cols;
    memset(&o, 0, sizeof o);

    CHECK_EQ_INT(plateau_lm_sparse_analyze(NULL, NULL, NULL, &S), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, NULL), PLATEAU_LM_ERR_ARGUMENT);
    pat.nodes = 0;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_EMPTY);
    pat.nodes = 3; pat.block = 5;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_ARGUMENT);
    pat.block = 0;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_ARGUMENT);
    pat.block = 1;
    o.ordering = PLATEAU_LM_SPARSE_ORDER_GEOMETRIC;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, &o, &S), PLATEAU_LM_ERR_ARGUMENT);
    o.ordering = 9;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, xy, &o, &S), PLATEAU_LM_ERR_ARGUMENT);
    o.ordering = 0; o.pivot_tol = -1.0;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, xy, &o, &S), PLATEAU_LM_ERR_ARGUMENT);
    o.pivot_tol = 0.0;
    xy[3] = HUGE_VAL;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, xy, &o, &S), PLATEAU_LM_ERR_ARGUMENT);
    xy[3] = 0.0;
    pat.cols = cols_asym;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_BAD_PATTERN);
    pat.cols = cols_oor;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_BAD_PATTERN);
    pat.row_start = rs_nodiag; pat.cols = cols_nodiag;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_ERR_BAD_PATTERN);
    CHECK(S == NULL);
    pat.row_start = rs; pat.cols = cols;

    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, xy, NULL, &S), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, 7, NULL, 0, &F), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_factor_size(S, 7), 0);
    need = plateau_lm_sparse_factor_size(S, PLATEAU_LM_SPARSE_LU);
    CHECK(need > 0 && need < sizeof buf - 8);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, buf + 3, need - 1, &F),
                 PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL);
    /* a caller workspace of the exact size at an odd address */
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, buf + 3, need, &F), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 3), PLATEAU_LM_ERR_NOT_FACTORED);
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, NULL, 0.0), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, -1.0), PLATEAU_LM_ERR_ARGUMENT);
    v[3] = 0.0; /* the middle diagonal block singular */
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_ERR_SINGULAR_PIVOT);
    CHECK_EQ_INT(plateau_lm_sparse_failed_node(F), 1);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 3), PLATEAU_LM_ERR_NOT_FACTORED);
    /* a shift damps it: A + 2 I is fine */
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 2.0), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_failed_node(F), -1);
    /* (A + 2 I) x = [[6,-1,0],[-1,2,-1],[0,-1,6]] x = (1,2,3) */
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 3), PLATEAU_LM_OK);
    CHECK_NEAR(6 * x[0] - x[1], 1.0, 1e-14);
    CHECK_NEAR(-x[0] + 2 * x[1] - x[2], 2.0, 1e-14);
    CHECK_NEAR(-x[1] + 6 * x[2], 3.0, 1e-14);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 2, x, 2), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 0, NULL, 0), PLATEAU_LM_OK);
    /* a zero pivot after elimination: [[1,1],[1,1]] block structure in scalars */
    v[3] = 4.0;
    v[0] = 1.0; v[1] = 1.0; v[2] = 1.0; v[3] = 1.0;
    {
        plateau_lm_result rr = plateau_lm_sparse_factorize(F, v, 0.0);
        CHECK_EQ_INT(rr, PLATEAU_LM_ERR_SINGULAR_PIVOT);
        CHECK(plateau_lm_sparse_failed_node(F) == 0 || plateau_lm_sparse_failed_node(F) == 1);
    }
    v[0] = 4.0; v[1] = -1.0; v[2] = -1.0; v[3] = 4.0;
    v[4] = NAN;
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_ERR_NOT_FINITE_MATRIX);
    v[4] = -1.0;
    plateau_lm_sparse_factor_free(F); /* a caller workspace: nothing to free */
    F = NULL;
    /* Cholesky of an indefinite matrix */
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_CHOLESKY, NULL, 0, &F), PLATEAU_LM_OK);
    v[6] = -4.0;
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE);
    CHECK(plateau_lm_sparse_failed_node(F) >= 0);
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 9.0), PLATEAU_LM_OK);
    v[6] = 4.0;
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    plateau_lm_sparse_factor_free(NULL);
    plateau_lm_sparse_symbolic_free(NULL);
    CHECK(plateau_lm_sparse_permutation(NULL) == NULL);
    CHECK_EQ_INT(plateau_lm_sparse_symbolic_info(NULL).nodes, 0);
    CHECK_EQ_INT(plateau_lm_sparse_failed_node(NULL), -1);
    CHECK(strcmp(plateau_lm_result_string(PLATEAU_LM_ERR_NOT_FACTORED), "unknown plateau_lm_result") != 0);
}

/* Disconnected graphs and a single node. */
static void test_forest(void)
{
    sm_graph g, h;
    size_t i;
    plateau_index *e;
    if (!CHECK(sm_grid(&g, 10))) return;
    /* two copies of the grid side by side, no edge between them */
    e = (plateau_index *)calloc(4 * g.nnz, sizeof(plateau_index)); /* zeroed: gcc 12 -O2 warns on malloc */
    {
        size_t ne = 0, v, p;
        for (v = 0; v < g.n; v++)
            for (p = (size_t)g.rs[v]; p < (size_t)g.rs[v + 1]; p++)
                if ((size_t)g.cols[p] > v) {
                    e[2 * ne] = (plateau_index)v; e[2 * ne + 1] = g.cols[p]; ne++;
                    e[2 * ne] = (plateau_index)(v + g.n); e[2 * ne + 1] = (plateau_index)((size_t)g.cols[p] + g.n); ne++;
                }
        memset(&h, 0, sizeof h);
        CHECK(sm_from_edges(&h, 2 * g.n, e, ne));
        h.xy = (double *)malloc(4 * g.n * sizeof(double));
        for (i = 0; i < 2 * g.n; i++) {
            h.xy[2 * i] = g.xy[2 * (i % g.n)] + (i >= g.n ? 0.25 : 0.0);
            h.xy[2 * i + 1] = g.xy[2 * (i % g.n) + 1];
        }
    }
    CHECK(solve_case(&h, 3, PLATEAU_LM_SPARSE_LU, 0, 0, 1, 1, NULL) < 1e-14);
    CHECK(solve_case(&h, 3, PLATEAU_LM_SPARSE_CHOLESKY, 1, 2, 0, 1, NULL) < 1e-14);
    free(e);
    sm_free(&h);
    {
        plateau_index rs[2] = {0, 1}, cols[1] = {0};
        double v[4] = {2, 1, 1, 3}, x[2] = {3, 4};
        plateau_lm_sparse_pattern pat;
        plateau_lm_sparse_symbolic *S = NULL;
        plateau_lm_sparse_factor *F = NULL;
        pat.nodes = 1; pat.block = 2; pat.row_start = rs; pat.cols = cols;
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, NULL, &S), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, NULL, 0, &F), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 2), PLATEAU_LM_OK);
        CHECK_NEAR(x[0], 1.0, 1e-15);
        CHECK_NEAR(x[1], 1.0, 1e-15);
        plateau_lm_sparse_factor_free(F);
        plateau_lm_sparse_symbolic_free(S);
    }
    sm_free(&g);
}

/* Every allocation of analyse + factor object refused in turn (and, in a
 * second pass, every later one too): the out-of-memory code, nothing leaked. */
static int alloc_run(const sm_graph *g, countalloc *ca, int *rc)
{
    plateau_lm_sparse_pattern pat = pattern_of(g, 3);
    plateau_lm_sparse_options o;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    memset(&o, 0, sizeof o);
    o.allocator = countalloc_allocator(ca);
    *rc = plateau_lm_sparse_analyze(&pat, g->xy, &o, &S);
    if (*rc == PLATEAU_LM_OK) {
        *rc = plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, NULL, 0, &F);
        if (*rc != PLATEAU_LM_OK && F) return 0;
    } else if (S) {
        return 0;
    }
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    return 1;
}

static void test_alloc_failure(void)
{
    sm_graph g;
    countalloc ca;
    long n, k;
    int rc, pass, bad = 0;
    if (!CHECK(sm_delaunay(&g, 200, 4))) return;
    countalloc_init(&ca, 0);
    CHECK(alloc_run(&g, &ca, &rc));
    CHECK_EQ_INT(rc, PLATEAU_LM_OK);
    n = ca.calls;
    CHECK_EQ_INT(n, 3);
    CHECK_EQ_INT(ca.live, 0);
    printf("alloc points: plateau_lm_sparse_analyze + factor_create %ld\n", n);
    for (pass = 0; pass < 2; pass++)
        for (k = 1; k <= n; k++) {
            countalloc_init(&ca, k);
            if (pass) ca.fail_from = k;
            if (!alloc_run(&g, &ca, &rc)) bad++;
            if (rc != PLATEAU_LM_ERR_OUT_OF_MEMORY) bad++;
            if (ca.live != 0 || ca.bad != 0) bad++;
        }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(countalloc_lost_context, 0);
    sm_free(&g);
}


/* ---- The square system of plateau.h (paper II.D): H_v and the two
 * tangential rows of every free vertex, 3 unknowns per free vertex ---- */

static void test_paper_jacobian(void)
{
    const int nu = 12;
    size_t nvert = (size_t)(nu + 1) * (size_t)(nu + 1), ntri = 2 * (size_t)nu * (size_t)nu, t = 0;
    double *pos = (double *)malloc(3 * nvert * sizeof(double));
    plateau_index *tri = (plateau_index *)malloc(3 * ntri * sizeof(plateau_index));
    unsigned char *fixed = (unsigned char *)calloc(nvert, 1);
    unsigned long long seed = 17;
    plateau_mesh mesh;
    plateau_system sys;
    plateau_system_options so;
    int i, j;
    memset(&mesh, 0, sizeof mesh);
    memset(&sys, 0, sizeof sys);
    /* a jittered grid on the saddle z = 0.3 (x^2 - y^2) + 0.1 sin(3 x), boundary fixed */
    for (j = 0; j <= nu; j++)
        for (i = 0; i <= nu; i++) {
            size_t v = (size_t)(j * (nu + 1) + i);
            double x = -1.0 + 2.0 * i / nu, y = -1.0 + 2.0 * j / nu;
            if (i > 0 && i < nu && j > 0 && j < nu) {
                x += 0.4 / nu * (sm_rand(&seed) - 0.5);
                y += 0.4 / nu * (sm_rand(&seed) - 0.5);
            } else {
                fixed[v] = 1;
            }
            pos[3 * v] = x;
            pos[3 * v + 1] = y;
            pos[3 * v + 2] = 0.3 * (x * x - y * y) + 0.1 * sin(3.0 * x);
        }
    for (j = 0; j < nu; j++)
        for (i = 0; i < nu; i++) {
            plateau_index a = (plateau_index)(j * (nu + 1) + i), b = a + 1, c = a + (plateau_index)(nu + 1), d = c + 1;
            tri[3 * t] = a; tri[3 * t + 1] = b; tri[3 * t + 2] = d; t++;
            tri[3 * t] = a; tri[3 * t + 1] = d; tri[3 * t + 2] = c; t++;
        }
    if (!CHECK_EQ_INT(plateau_mesh_create(pos, nvert, fixed, tri, ntri, NULL, &mesh, NULL), PLATEAU_OK)) return;
    memset(&so, 0, sizeof so);
    so.tangential_weight = 1.0;
    if (!CHECK_EQ_INT(plateau_system_assemble(&mesh, &so, &sys, NULL), PLATEAU_OK)) return;
    CHECK_EQ_INT(sys.num_rows, sys.num_columns);
    {
        /* block CSR over the free vertices: the union of the three rows'
         * blocks, symmetrised (a missing transposed block is a stored zero) */
        size_t n = sys.num_columns / 3, N = sys.num_columns, r, p, q, k, nnz;
        plateau_index *e = (plateau_index *)malloc(2 * (sys.num_blocks + 1) * sizeof(plateau_index));
        size_t ne = 0;
        sm_graph g;
        double *vals, *Jd = (double *)malloc(N * N * sizeof(double)), *rhs, *x, *xd, res = 0.0, jn = 0.0,
               xn = 0.0, maxd = 0.0;
        plateau_lm_sparse_pattern pat;
        plateau_lm_sparse_symbolic *S = NULL;
        plateau_lm_sparse_factor *F = NULL;
        memset(&g, 0, sizeof g);
        for (r = 0; r < sys.num_rows; r++)
            for (p = sys.row_start[r]; p < sys.row_start[r + 1]; p++) {
                plateau_index cv = sys.block_vertex[p];
                e[2 * ne] = (plateau_index)(r / 3);
                e[2 * ne + 1] = (plateau_index)(sys.column_of_vertex[cv] / 3);
                if (e[2 * ne] != e[2 * ne + 1]) ne++;
            }
        CHECK(sm_from_edges(&g, n, e, ne));
        nnz = g.nnz;
        vals = (double *)calloc(9 * nnz, sizeof(double));
        g.xy = (double *)malloc(2 * n * sizeof(double));
        for (k = 0; k < nvert; k++)
            if (sys.column_of_vertex[k] >= 0) {
                size_t node = (size_t)sys.column_of_vertex[k] / 3;
                g.xy[2 * node] = mesh.positions[3 * k];
                g.xy[2 * node + 1] = mesh.positions[3 * k + 1];
            }
        for (r = 0; r < sys.num_rows; r++)
            for (p = sys.row_start[r]; p < sys.row_start[r + 1]; p++) {
                size_t cnode = (size_t)sys.column_of_vertex[sys.block_vertex[p]] / 3;
                q = sm_find(&g, r / 3, cnode);
                for (k = 0; k < 3; k++) vals[9 * q + 3 * (r % 3) + k] += sys.block_value[3 * p + k];
            }
        plateau_system_dense(&sys, Jd);
        rhs = (double *)malloc(N * sizeof(double));
        x = (double *)malloc(N * sizeof(double));
        xd = (double *)malloc(N * sizeof(double));
        for (r = 0; r < N; r++) x[r] = xd[r] = rhs[r] = -sys.residual[r];
        pat = pattern_of(&g, 3);
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, NULL, &S), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, NULL, 0, &F), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, vals, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, N), PLATEAU_LM_OK);
        /* ||J h + f|| / (||J|| ||h||) with the dense J of plateau_system_dense */
        for (r = 0; r < N; r++) {
            double s = -rhs[r], rs = 0.0;
            for (k = 0; k < N; k++) {
                s += Jd[r * N + k] * x[k];
                rs += fabs(Jd[r * N + k]);
            }
            if (fabs(s) > res) res = fabs(s);
            if (rs > jn) jn = rs;
            if (fabs(x[r]) > xn) xn = fabs(x[r]);
        }
        CHECK(res <= 1e-13 * jn * xn);
        CHECK(dense_solve(Jd, xd, N));
        for (r = 0; r < N; r++)
            if (fabs(x[r] - xd[r]) > maxd) maxd = fabs(x[r] - xd[r]);
        CHECK(maxd <= 1e-10 * xn);
        printf("paper system, %lu free vertices: Newton step residual %.1e, vs dense %.1e (|h| %.2g)\n",
               (unsigned long)n, res / (jn * xn), maxd / xn, xn);
        plateau_lm_sparse_factor_free(F);
        plateau_lm_sparse_symbolic_free(S);
        free(e); free(vals); free(Jd); free(rhs); free(x); free(xd);
        sm_free(&g);
    }
    plateau_system_free(&sys);
    plateau_mesh_free(&mesh);
    free(pos); free(tri); free(fixed);
}

/* ---- Powell's dog leg against the dense LM ------------------------------ */

/* A nonlinear system on a k x k grid, b = 3: per node
 * f_i[r] = x_i[r] + 0.5 x_i[r+1] + 0.2 x_i[r]^3 + 0.3 sum_j (x_i[r] - sin x_j[r]) - c_i[r]
 * (r + 1 modulo 3): a full 3 x 3 diagonal block, diagonal off-diagonal blocks. */
typedef struct dl_problem {
    const sm_graph *g;
    double *c;
    int calls, fail_at; /* abort on call number fail_at (0: never) */
    int jcalls;         /* calls that asked for the Jacobian */
    double *last_jx;    /* NULL, or 3 n: the x of the last of those */
} dl_problem;

static int dl_func(const double *x, double *f, double *jac, void *user)
{
    dl_problem *P = (dl_problem *)user;
    const sm_graph *g = P->g;
    size_t i, p, r;
    P->calls++;
    if (P->fail_at && P->calls == P->fail_at) return 1;
    if (jac) {
        P->jcalls++;
        if (P->last_jx) memcpy(P->last_jx, x, 3 * g->n * sizeof(double));
    }
    for (i = 0; i < g->n; i++)
        for (r = 0; r < 3; r++) {
            double xi = x[3 * i + r], s = xi + 0.5 * x[3 * i + (r + 1) % 3] + 0.2 * xi * xi * xi - P->c[3 * i + r];
            for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++) {
                size_t k = (size_t)g->cols[p];
                if (k != i) s += 0.3 * (xi - sin(x[3 * k + r]));
            }
            f[3 * i + r] = s;
        }
    if (jac) {
        for (i = 0; i < g->n; i++) {
            double deg = (double)(g->rs[i + 1] - g->rs[i] - 1);
            for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++) {
                size_t k = (size_t)g->cols[p];
                double *blk = jac + 9 * p;
                for (r = 0; r < 9; r++) blk[r] = 0.0;
                for (r = 0; r < 3; r++) {
                    if (k == i) {
                        blk[r * 3 + r] = 1.0 + 0.6 * x[3 * i + r] * x[3 * i + r] + 0.3 * deg;
                        blk[r * 3 + (r + 1) % 3] = 0.5;
                    } else {
                        blk[r * 3 + r] = -0.3 * cos(x[3 * k + r]);
                    }
                }
            }
        }
    }
    return 0;
}

/* the same through plateau_lm_solve's dense callback */
static int dl_dense(const double *x, double *f, double *jac, void *user)
{
    dl_problem *P = (dl_problem *)user;
    const sm_graph *g = P->g;
    size_t N = 3 * g->n, i, p, r, c;
    double *blocks = NULL;
    if (jac) {
        blocks = (double *)malloc(9 * g->nnz * sizeof(double));
        if (!blocks) return 1;
    }
    dl_func(x, f, blocks, user);
    if (jac) {
        for (i = 0; i < N * N; i++) jac[i] = 0.0;
        for (i = 0; i < g->n; i++)
            for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++)
                for (r = 0; r < 3; r++)
                    for (c = 0; c < 3; c++)
                        jac[(3 * i + r) * N + 3 * (size_t)g->cols[p] + c] = blocks[9 * p + 3 * r + c];
        free(blocks);
    }
    return 0;
}

/* Rosenbrock as a square system: f = (10 (x2 - x1^2), 1 - x1), one node, b = 2 */
static int rosen(const double *x, double *f, double *jac, void *user)
{
    (void)user;
    f[0] = 10.0 * (x[1] - x[0] * x[0]);
    f[1] = 1.0 - x[0];
    if (jac) {
        jac[0] = -20.0 * x[0]; jac[1] = 10.0;
        jac[2] = -1.0; jac[3] = 0.0;
    }
    return 0;
}

/* Rosenbrock with both residuals times dl_scale: the weights dl_scale^2 */
static double dl_scale = 1.0;
static int rosen_scaled(const double *x, double *f, double *jac, void *user)
{
    int r = rosen(x, f, jac, user), k;
    for (k = 0; k < 2; k++) f[k] *= dl_scale;
    if (jac)
        for (k = 0; k < 4; k++) jac[k] *= dl_scale;
    return r;
}

/* finite (F = 12.5) at the start (3, 4) only, NaN at every other point */
static int dl_nan_around_start(const double *x, double *f, double *jac, void *user)
{
    int start = x[0] == 3.0 && x[1] == 4.0;
    (void)user;
    f[0] = start ? x[0] : NAN;
    f[1] = start ? x[1] : NAN;
    if (jac) { jac[0] = 1.0; jac[1] = 0.0; jac[2] = 0.0; jac[3] = 1.0; }
    return 0;
}

/* The dog leg has no absolute scale: residuals times 1e50 .. 1e150 (the
 * uniform weights 1e100 .. 1e300) take the steps of residuals of 1, to
 * the same minimiser (||g||^2 and ||J g||^2 of the Cauchy step overflowed
 * from 1e100 on, and the run stopped at the start on the step test).  A
 * residual NaN at every trial point is an error, x left at the start, as
 * in plateau_lm_solve.  Options it does not implement are refused. */
static void test_dogleg_scale_and_nan(void)
{
    static const double scale[] = {1.0, 1e50, 1e100, 1e125, 1e150};
    plateau_index rs[2] = {0, 1}, cols[1] = {0};
    plateau_lm_sparse_pattern pat;
    plateau_lm_report rep;
    plateau_lm_options o;
    size_t k, iters = 0;
    double w[2] = {1.0, 1.0}, lo[2] = {-5.0, -5.0};
    pat.nodes = 1; pat.block = 2; pat.row_start = rs; pat.cols = cols;
    for (k = 0; k < sizeof scale / sizeof scale[0]; k++) {
        double x[2] = {-1.2, 1.0};
        dl_scale = scale[k];
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, rosen_scaled, NULL, NULL, &rep), PLATEAU_LM_OK);
        if (!CHECK(rep.stop == PLATEAU_LM_STOP_SMALL_F || rep.stop == PLATEAU_LM_STOP_GRADIENT))
            fprintf(stderr, "  scale %g: %s after %d\n", scale[k], plateau_lm_stop_string(rep.stop),
                    (int)rep.iterations);
        CHECK_NEAR(x[0], 1.0, 1e-10);
        CHECK_NEAR(x[1], 1.0, 1e-10);
        if (k == 0) iters = rep.iterations;
        CHECK_EQ_INT(rep.iterations, iters);
    }
    dl_scale = 1.0;
    {
        double x[2] = {3.0, 4.0};
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, dl_nan_around_start, NULL, NULL, &rep),
                     PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
        CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ERROR);
        CHECK(x[0] == 3.0 && x[1] == 4.0);
        CHECK(rep.iterations >= 1 && rep.residual_evaluations >= 2);
        CHECK_NEAR(rep.f_final, 12.5, 0.0);
    }
    {
        double x[2] = {-1.2, 1.0};
        memset(&o, 0, sizeof o);
        o.weights = w;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, rosen, NULL, &o, &rep), PLATEAU_LM_ERR_ARGUMENT);
        memset(&o, 0, sizeof o);
        o.loss = PLATEAU_LM_LOSS_HUBER;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, rosen, NULL, &o, &rep), PLATEAU_LM_ERR_ARGUMENT);
        memset(&o, 0, sizeof o);
        o.lower = lo;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, rosen, NULL, &o, &rep), PLATEAU_LM_ERR_ARGUMENT);
        CHECK(x[0] == -1.2 && x[1] == 1.0);
    }
}

static void test_dogleg(void)
{
    sm_graph g;
    dl_problem P;
    size_t N, i;
    double *x, *xd, maxd = 0.0;
    unsigned long long seed = 42;
    plateau_lm_report rep, drep;
    plateau_lm_sparse_pattern pat;
    int scale;
    {   /* Rosenbrock from the standard start */
        plateau_index rs[2] = {0, 1}, cols[1] = {0};
        double xr[2] = {-1.2, 1.0}, xl[2] = {-1.2, 1.0};
        pat.nodes = 1; pat.block = 2; pat.row_start = rs; pat.cols = cols;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, xr, rosen, NULL, NULL, &rep), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_solve(2, 2, xl, (plateau_lm_func)rosen, NULL, NULL, NULL, 0, &drep, NULL), PLATEAU_LM_OK);
        CHECK_NEAR(xr[0], 1.0, 1e-10);
        CHECK_NEAR(xr[1], 1.0, 1e-10);
        CHECK_NEAR(xr[0], xl[0], 1e-10);
        CHECK(rep.f_final <= 1e-20);
        CHECK(rep.stop == PLATEAU_LM_STOP_SMALL_F || rep.stop == PLATEAU_LM_STOP_GRADIENT);
        printf("dog leg, Rosenbrock: %zu iterations, %zu + %zu evaluations (dense LM: %zu, %zu + %zu)\n",
               rep.iterations, rep.residual_evaluations, rep.jacobian_evaluations, drep.iterations,
               drep.residual_evaluations, drep.jacobian_evaluations);
    }
    if (!CHECK(sm_grid(&g, 6))) return;
    N = 3 * g.n;
    P.g = &g;
    P.calls = P.fail_at = P.jcalls = 0;
    P.last_jx = NULL;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    xd = (double *)malloc(N * sizeof(double));
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    pat = pattern_of(&g, 3);
    for (scale = 1; scale <= 100; scale *= 10) {
        double F0;
        for (i = 0; i < N; i++) x[i] = xd[i] = (double)scale * (sm_rand(&seed) - 0.5);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, NULL, &rep), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_solve(N, N, xd, dl_dense, &P, NULL, NULL, 0, &drep, NULL), PLATEAU_LM_OK);
        F0 = rep.f_initial;
        CHECK(rep.f_final <= 1e-24 * (F0 > 1.0 ? F0 : 1.0) + 1e-28);
        CHECK(drep.f_final <= 1e-20 * (F0 > 1.0 ? F0 : 1.0) + 1e-24);
        maxd = 0.0;
        for (i = 0; i < N; i++)
            if (fabs(x[i] - xd[i]) > maxd) maxd = fabs(x[i] - xd[i]);
        CHECK(maxd <= 1e-9);
        printf("dog leg, 6 x 6 grid, b = 3, start %dx: %zu iterations, %zu + %zu evaluations, F %.1e "
               "(dense LM: %zu, %zu + %zu, F %.1e); max |x - x_dense| %.1e\n",
               scale, rep.iterations, rep.residual_evaluations, rep.jacobian_evaluations, rep.f_final,
               drep.iterations, drep.residual_evaluations, drep.jacobian_evaluations, drep.f_final, maxd);
    }
    /* errors */
    {
        plateau_lm_options o;
        memset(&o, 0, sizeof o);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(NULL, NULL, x, dl_func, &P, NULL, &rep), PLATEAU_LM_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, NULL, dl_func, &P, NULL, &rep), PLATEAU_LM_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, NULL, &P, NULL, &rep), PLATEAU_LM_ERR_ARGUMENT);
        o.numeric_jacobian = 1;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, dl_func, &P, &o, &rep), PLATEAU_LM_ERR_ARGUMENT);
        o.numeric_jacobian = 0;
        o.max_iterations = 2;
        for (i = 0; i < N; i++) x[i] = 50.0 * (sm_rand(&seed) - 0.5);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
        CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_MAX_ITERATIONS);
        CHECK_EQ_INT(rep.iterations, 2);
        o.max_iterations = 0;
        P.calls = 0;
        P.fail_at = 3;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, dl_func, &P, &o, &rep), PLATEAU_LM_ERR_ABORTED);
        CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ABORTED);
        CHECK(all_finite_vec(x, N));
        P.fail_at = 0;
        x[5] = NAN;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, NULL, x, dl_func, &P, &o, &rep), PLATEAU_LM_ERR_NOT_FINITE_X0);
        x[5] = 0.0;
        {   /* allocation failure at each of its allocations */
            countalloc ca;
            long n, k;
            int bad = 0, pass;
            countalloc_init(&ca, 0);
            o.allocator = countalloc_allocator(&ca);
            CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
            n = ca.calls;
            CHECK_EQ_INT(n, 4);
            CHECK_EQ_INT(ca.live, 0);
            for (pass = 0; pass < 2; pass++)
                for (k = 1; k <= n; k++) {
                    countalloc_init(&ca, k);
                    if (pass) ca.fail_from = k;
                    if (plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o, &rep) != PLATEAU_LM_ERR_OUT_OF_MEMORY) bad++;
                    if (ca.live != 0 || ca.bad != 0) bad++;
                }
            CHECK_EQ_INT(bad, 0);
        }
    }
    free(P.c); free(x); free(xd);
    sm_free(&g);
}

/* The dog leg's tail (options tail_f_stop, tail_iterations): one run that
 * stops on a coarse step test (eps_step 1e-3) above tail_f_stop and goes
 * on from there gives, bit for bit, the x, F and stop of that run followed
 * by a second run from its point (eps_step DBL_EPSILON, f_stop the tail's,
 * at most tail_iterations steps), with one residual and one Jacobian fewer
 * (the analysis, f and J at the point kept).  A SMALL_F stop forms no
 * Jacobian at its final point. */
static void test_dogleg_tail(void)
{
    sm_graph g;
    dl_problem P;
    size_t N, i;
    double *x, *x2, *jx;
    unsigned long long seed = 7;
    plateau_lm_report rep, r1, r2;
    plateau_lm_options o, o1, o2;
    plateau_lm_sparse_pattern pat;
    int start, tails = 0, reused = 0, one_step = 0, as_two = 0, r1_spent;
    if (!CHECK(sm_grid(&g, 8))) return;
    N = 3 * g.n;
    P.g = &g;
    P.calls = P.fail_at = P.jcalls = 0;
    P.last_jx = NULL;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    x2 = (double *)malloc(N * sizeof(double));
    jx = (double *)malloc(N * sizeof(double));
    if (!CHECK(P.c && x && x2 && jx)) return;
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    pat = pattern_of(&g, 3);
    for (start = 0; start < 6; start++) {
        int calls, jcalls;
        double scale = start < 3 ? 1.0 : 30.0;
        for (i = 0; i < N; i++) x[i] = x2[i] = scale * (sm_rand(&seed) - 0.5);
        memset(&o, 0, sizeof o);
        o.eps_step = 1e-3;
        o.tail_f_stop = 1e-26;
        o.tail_iterations = 1 + start % 3;
        P.calls = P.jcalls = 0;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
        calls = P.calls;
        jcalls = P.jcalls;
        /* the same by two runs */
        o1 = o;
        o1.tail_f_stop = 0.0;
        P.calls = P.jcalls = 0;
        P.last_jx = jx;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o1, &r1), PLATEAU_LM_OK);
        /* r1 ended by the spent test (test_dogleg_spent), without the
         * Jacobian at its point, which the tail forms */
        r1_spent = memcmp(x2, jx, N * sizeof(double)) != 0;
        if (r1.stop == PLATEAU_LM_STOP_STEP && r1.f_final > o.tail_f_stop) {
            tails++;
            o2 = o1;
            o2.eps_step = DBL_EPSILON;
            o2.f_stop = o.tail_f_stop;
            o2.max_iterations = o.tail_iterations;
            CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o2, &r2), PLATEAU_LM_OK);
            CHECK_EQ_INT(rep.iterations, r1.iterations + r2.iterations);
            CHECK_EQ_INT(rep.stop, r2.stop);
            CHECK(rep.f_final == r2.f_final);
            CHECK_EQ_INT(calls, P.calls - 2 + r1_spent);
            CHECK_EQ_INT(jcalls, P.jcalls - 1 + r1_spent);
            CHECK(rep.iterations > r1.iterations);
        } else {
            CHECK(rep.f_final == r1.f_final);
        }
        CHECK(memcmp(x, x2, N * sizeof(double)) == 0);
    }
    CHECK(tails >= 4);
    /* A step-test stop on a step from GMRES on the kept LU whose relative
     * residual rr has rr^2 F at most tail_f_stop: the tail tries that step
     * first, on the kept LU, where a second run would take a new LU, and
     * ends below tail_f_stop (mostly by that one step, no more Jacobians;
     * never with more Jacobians than the two runs); other stops go on as a
     * second run would, bit for bit. */
    for (start = 0; start < 12; start++) {
        double ts = start % 3 == 0 ? 1e-8 : start % 3 == 1 ? 1e-12 : 1e-16;
        for (i = 0; i < N; i++) x[i] = x2[i] = (start < 6 ? 1.0 : 30.0) * (sm_rand(&seed) - 0.5);
        memset(&o, 0, sizeof o);
        o.eps_step = 1e-3;
        o.tail_f_stop = ts;
        o.tail_iterations = 5;
        P.calls = P.jcalls = 0;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
        o1 = o;
        o1.tail_f_stop = 0.0;
        P.last_jx = jx;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o1, &r1), PLATEAU_LM_OK);
        r1_spent = memcmp(x2, jx, N * sizeof(double)) != 0;
        if (r1.stop != PLATEAU_LM_STOP_STEP || !(r1.f_final > ts)) continue;
        o2 = o1;
        o2.eps_step = DBL_EPSILON;
        o2.f_stop = ts;
        o2.max_iterations = o.tail_iterations;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o2, &r2), PLATEAU_LM_OK);
        if (memcmp(x, x2, N * sizeof(double)) == 0 && rep.f_final == r2.f_final) {
            as_two++;
            continue;
        }
        reused++;
        CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_SMALL_F);
        CHECK(rep.f_final <= ts);
        CHECK(rep.jacobian_evaluations + 1 <= r1.jacobian_evaluations + r2.jacobian_evaluations + (size_t)r1_spent);
        if (rep.iterations == r1.iterations + 1 &&
            rep.jacobian_evaluations == r1.jacobian_evaluations + (size_t)r1_spent)
            one_step++;
        CHECK(r2.f_final <= ts);
    }
    CHECK(reused >= 3 && 2 * one_step >= reused);
    printf("dog leg tail from a GMRES step: %d runs tried it first (%d ended by it alone), %d as two runs\n",
           reused, one_step, as_two);
    /* SMALL_F: every Jacobian formed was used by a step; none at the end */
    for (i = 0; i < N; i++) x[i] = 10.0 * (sm_rand(&seed) - 0.5);
    memset(&o, 0, sizeof o);
    o.f_stop = 1e-12;
    P.calls = P.jcalls = 0;
    P.last_jx = jx;
    CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
    CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_SMALL_F);
    CHECK_EQ_INT(P.jcalls, rep.jacobian_evaluations);
    CHECK(P.jcalls >= 1 && (size_t)P.jcalls <= rep.iterations);
    CHECK(memcmp(x, jx, N * sizeof(double)) != 0);
    CHECK(rep.grad_inf > 0.0);
    printf("dog leg tail: %d of 6 runs went on from a step-test stop, as two runs would\n", tails);
    free(P.c); free(x); free(x2); free(jx);
    sm_free(&g);
}

/* The dog leg's spent test: a solve that converges to the rounding level
 * (f_stop 0 -> about 1e-32 F0: a step-test stop) ends, where the step at
 * the last point is predicted below the step test by the chord step on the
 * LU at hand, without the Jacobian there (the last Jacobian was taken at an
 * earlier point); a second solve from that point, which forms the
 * Jacobian, confirms it: its first step is refused by the step test, x
 * unchanged. */
static void test_dogleg_spent(void)
{
    sm_graph g;
    dl_problem P;
    size_t N, i;
    double *x, *x2, *jx;
    unsigned long long seed = 11;
    plateau_lm_report rep, r2;
    plateau_lm_sparse_pattern pat;
    int start, spent = 0;
    if (!CHECK(sm_grid(&g, 8))) return;
    N = 3 * g.n;
    P.g = &g;
    P.calls = P.fail_at = P.jcalls = 0;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    x2 = (double *)malloc(N * sizeof(double));
    jx = (double *)malloc(N * sizeof(double));
    if (!CHECK(P.c && x && x2 && jx)) return;
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    pat = pattern_of(&g, 3);
    for (start = 0; start < 8; start++) {
        for (i = 0; i < N; i++) x[i] = (start < 4 ? 1.0 : 20.0) * (sm_rand(&seed) - 0.5);
        P.jcalls = 0;
        P.last_jx = jx;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, NULL, &rep), PLATEAU_LM_OK);
        CHECK_EQ_INT(P.jcalls, rep.jacobian_evaluations);
        if (rep.stop != PLATEAU_LM_STOP_STEP || memcmp(x, jx, N * sizeof(double)) == 0) continue;
        spent++;
        CHECK(rep.jacobian_evaluations < rep.iterations);
        memcpy(x2, x, N * sizeof(double));
        P.last_jx = NULL;
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, NULL, &r2), PLATEAU_LM_OK);
        CHECK_EQ_INT(r2.stop, PLATEAU_LM_STOP_STEP);
        CHECK_EQ_INT(r2.iterations, 1);
        CHECK_EQ_INT(r2.jacobian_evaluations, 1);
        CHECK(memcmp(x, x2, N * sizeof(double)) == 0);
    }
    CHECK(spent >= 4);
    printf("dog leg: %d of 8 solves ended on a predicted step-test stop, no Jacobian at the end\n", spent);
    free(P.c); free(x); free(x2); free(jx);
    sm_free(&g);
}

/* options.chord = -1: a new LU at every Jacobian, no GMRES steps (each
 * accepted Gauss-Newton step a full Newton step, converging quadratically):
 * the same solutions as with the kept LU, in fewer iterations (the kept
 * LU's GMRES steps converge linearly).  The first solve passes no
 * options: their defaults must say chord 0 (an unset field made it
 * follow the stack's contents, 48 or 51 iterations run to run). */
static void test_dogleg_no_chord(void)
{
    sm_graph g;
    dl_problem P;
    size_t N, i, it0 = 0, it1 = 0;
    double *x, *x2, maxd = 0.0;
    unsigned long long seed = 5;
    plateau_lm_report r0, r1;
    plateau_lm_options o;
    plateau_lm_sparse_pattern pat;
    int start;
    if (!CHECK(sm_grid(&g, 8))) return;
    N = 3 * g.n;
    P.g = &g;
    P.calls = P.fail_at = P.jcalls = 0;
    P.last_jx = NULL;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    x2 = (double *)malloc(N * sizeof(double));
    if (!CHECK(P.c && x && x2)) return;
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    pat = pattern_of(&g, 3);
    memset(&o, 0, sizeof o);
    o.chord = -1;
    for (start = 0; start < 6; start++) {
        for (i = 0; i < N; i++) x[i] = x2[i] = (start < 3 ? 1.0 : 20.0) * (sm_rand(&seed) - 0.5);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, NULL, &r0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o, &r1), PLATEAU_LM_OK);
        CHECK(r1.f_final <= 1e-24 * (r1.f_initial > 1.0 ? r1.f_initial : 1.0) + 1e-28);
        for (i = 0; i < N; i++)
            if (fabs(x[i] - x2[i]) > maxd) maxd = fabs(x[i] - x2[i]);
        it0 += r0.iterations;
        it1 += r1.iterations;
    }
    CHECK(maxd <= 1e-9);
    CHECK(it1 < it0);
    printf("dog leg, a new LU at every Jacobian: %zu iterations in 6 solves against %zu with the kept LU; "
           "max |x difference| %.1e\n", it1, it0, maxd);
    free(P.c); free(x); free(x2);
    sm_free(&g);
}

/* options.chord = 1: a new LU at every Jacobian and, after a Newton step
 * that cut F 1000-fold, chord steps on its LU without a Jacobian: the same
 * solutions as chord = -1 (to the rounding level), with fewer Jacobians and
 * LUs, more iterations than Jacobians (the chord steps), every callback
 * call counted in the report, and F never rising along the accepted steps
 * (a chord step that does not lower F is refused).  With a tail
 * (eps_step 1e-3, tail_f_stop 1e-26, as in test_dogleg_tail) the chord
 * steps go on under the tail's bound and end below tail_f_stop. */
static int chord_F_rose;
static double chord_last_F;
static int chord_progress(int k, double F, double grad_inf, double delta, int accepted, void *user)
{
    (void)k, (void)grad_inf, (void)delta, (void)user;
    if (accepted) {
        if (F > chord_last_F) chord_F_rose = 1;
        chord_last_F = F;
    }
    return 0;
}

static void test_dogleg_chord_steps(void)
{
    sm_graph g;
    dl_problem P;
    size_t N, i, j0 = 0, j1 = 0, it1 = 0;
    double *x, *x2, maxd = 0.0;
    unsigned long long seed = 13;
    plateau_lm_report r0, r1;
    plateau_lm_options o0, o1;
    plateau_lm_sparse_pattern pat;
    int start, tail;
    if (!CHECK(sm_grid(&g, 8))) return;
    N = 3 * g.n;
    P.g = &g;
    P.calls = P.fail_at = P.jcalls = 0;
    P.last_jx = NULL;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    x2 = (double *)malloc(N * sizeof(double));
    if (!CHECK(P.c && x && x2)) return;
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    pat = pattern_of(&g, 3);
    for (tail = 0; tail < 2; tail++)
        for (start = 0; start < 6; start++) {
            for (i = 0; i < N; i++) x[i] = x2[i] = (start < 3 ? 1.0 : 20.0) * (sm_rand(&seed) - 0.5);
            memset(&o0, 0, sizeof o0);
            o0.chord = -1;
            if (tail) {
                o0.eps_step = 1e-3;
                o0.tail_f_stop = 1e-26;
            }
            o1 = o0;
            o1.chord = 1;
            o1.progress = chord_progress;
            CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &o0, &r0), PLATEAU_LM_OK);
            P.calls = P.jcalls = 0;
            chord_F_rose = 0;
            chord_last_F = HUGE_VAL;
            CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x2, dl_func, &P, &o1, &r1), PLATEAU_LM_OK);
            CHECK(!chord_F_rose);
            CHECK_EQ_INT(P.jcalls, r1.jacobian_evaluations);
            CHECK_EQ_INT(P.calls, r1.jacobian_evaluations + r1.residual_evaluations);
            if (tail) CHECK(r1.f_final <= 1e-26);
            else CHECK(r1.f_final <= 1e-24 * (r1.f_initial > 1.0 ? r1.f_initial : 1.0) + 1e-28);
            CHECK(r1.jacobian_evaluations <= r0.jacobian_evaluations);
            for (i = 0; i < N; i++)
                if (fabs(x[i] - x2[i]) > maxd) maxd = fabs(x[i] - x2[i]);
            j0 += r0.jacobian_evaluations;
            j1 += r1.jacobian_evaluations;
            it1 += r1.iterations;
        }
    CHECK(maxd <= 1e-9);
    CHECK(j1 < j0);
    CHECK(it1 > j1);
    printf("dog leg with chord steps: %zu Jacobians (and LUs) in 12 solves against %zu, %zu iterations; "
           "max |x difference| %.1e\n", j1, j0, it1, maxd);
    free(P.c); free(x); free(x2);
    sm_free(&g);
}

/* One dog-leg solve with and without a keep (plateau_lm_dogleg_solve_kept)
 * from the same start: the same x, F, stop and counts, bit for bit; 1 when
 * they agree.  xk, xp: the two copies of the start. */
static int keep_agrees(const plateau_lm_sparse_pattern *pat, const double *xy, dl_problem *P, double *xk,
                       double *xp, size_t N, const plateau_lm_options *o, plateau_lm_dogleg_keep **keep)
{
    plateau_lm_report rk, rp;
    plateau_lm_result ck, cp = plateau_lm_dogleg_solve(pat, xy, xp, dl_func, P, o, &rp);
    ck = plateau_lm_dogleg_solve_kept(pat, xy, xk, dl_func, P, o, &rk, keep);
    return ck == PLATEAU_LM_OK && cp == PLATEAU_LM_OK && memcmp(xk, xp, N * sizeof(double)) == 0 &&
           rk.f_final == rp.f_final && rk.stop == rp.stop && rk.iterations == rp.iterations &&
           rk.jacobian_evaluations == rp.jacobian_evaluations;
}

/* The keep: a sequence of solves on two Delaunay graphs of the same nodes
 * (the patterns of a mesh before and after edge flips) and a larger one,
 * each kept solve the plain solve bit for bit, in blocks filled by the
 * solve before (the second solve on a pattern allocates only its
 * analysis); another allocator refused; allocation failure at each of the
 * kept solves' allocations, the keep still usable afterwards and nothing
 * leaked once it is freed. */
static void test_dogleg_keep(void)
{
    sm_graph g[3];
    plateau_lm_sparse_pattern pat[3];
    dl_problem P;
    plateau_lm_dogleg_keep *keep = NULL;
    plateau_lm_options o;
    plateau_lm_report rep;
    countalloc ca, other;
    unsigned long long seed = 11;
    size_t N, Nmax, i, grown;
    double *xk, *xp, *x0;
    long plain, kept, k;
    int s, agree = 0, bad = 0;
    const int seq[5] = {0, 1, 0, 2, 1};
    if (!CHECK(sm_delaunay(&g[0], 150, 1) && sm_delaunay(&g[1], 150, 2) && sm_delaunay(&g[2], 220, 3))) return;
    Nmax = 3 * g[2].n;
    P.calls = P.fail_at = P.jcalls = 0;
    P.last_jx = NULL;
    P.c = (double *)malloc(Nmax * sizeof(double));
    xk = (double *)malloc(Nmax * sizeof(double));
    xp = (double *)malloc(Nmax * sizeof(double));
    x0 = (double *)malloc(Nmax * sizeof(double));
    if (!CHECK(P.c && xk && xp && x0)) return;
    for (i = 0; i < Nmax; i++) {
        P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
        x0[i] = 3.0 * (sm_rand(&seed) - 0.5);
    }
    for (s = 0; s < 3; s++) pat[s] = pattern_of(&g[s], 3);
    countalloc_init(&ca, 0);
    memset(&o, 0, sizeof o);
    o.allocator = countalloc_allocator(&ca);
    for (s = 0; s < 5; s++) {
        P.g = &g[seq[s]];
        N = 3 * P.g->n;
        memcpy(xk, x0, N * sizeof(double));
        memcpy(xp, x0, N * sizeof(double));
        agree += keep_agrees(&pat[seq[s]], P.g->xy, &P, xk, xp, N, &o, &keep);
    }
    CHECK_EQ_INT(agree, 5);
    grown = plateau_lm_dogleg_keep_bytes(keep);
    CHECK(grown > 0);
    /* allocations: the plain solve's, and the kept one's on a pattern the
     * blocks hold (its analysis only: two fewer) */
    P.g = &g[0];
    N = 3 * g[0].n;
    memcpy(xp, x0, N * sizeof(double));
    countalloc_init(&ca, 0);
    CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat[0], g[0].xy, xp, dl_func, &P, &o, &rep), PLATEAU_LM_OK);
    plain = ca.calls;
    memcpy(xk, x0, N * sizeof(double));
    countalloc_init(&ca, 0);
    CHECK_EQ_INT(plateau_lm_dogleg_solve_kept(&pat[0], g[0].xy, xk, dl_func, &P, &o, &rep, &keep), PLATEAU_LM_OK);
    kept = ca.calls;
    CHECK_EQ_INT(kept, plain - 2);
    CHECK_EQ_INT(plateau_lm_dogleg_keep_bytes(keep), grown);
    CHECK(memcmp(xk, xp, N * sizeof(double)) == 0);
    /* another allocator than the keep's */
    countalloc_init(&other, 0);
    o.allocator = countalloc_allocator(&other);
    CHECK_EQ_INT(plateau_lm_dogleg_solve_kept(&pat[0], g[0].xy, xk, dl_func, &P, &o, &rep, &keep),
                 PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(other.calls, 0);
    plateau_lm_dogleg_keep_free(keep);
    keep = NULL;
    /* allocation failure: at each allocation of a first kept solve (the keep
     * made), then of a second on a larger pattern (the blocks grown); after
     * each failure the keep gives the plain solve's bits */
    o.allocator = countalloc_allocator(&ca);
    for (s = 0; s < 2; s++) {
        long n;
        int sp = s == 0 ? 0 : 2;
        countalloc_init(&ca, 0);
        for (k = 1;; k++) {
            plateau_lm_result r;
            if (s == 1) { /* a keep sized by the smaller pattern first */
                P.g = &g[0];
                memcpy(xk, x0, 3 * g[0].n * sizeof(double));
                if (plateau_lm_dogleg_solve_kept(&pat[0], g[0].xy, xk, dl_func, &P, &o, &rep, &keep) !=
                    PLATEAU_LM_OK)
                    bad++;
            }
            ca.fail_at = ca.calls + k;
            P.g = &g[sp];
            N = 3 * g[sp].n;
            memcpy(xk, x0, N * sizeof(double));
            r = plateau_lm_dogleg_solve_kept(&pat[sp], g[sp].xy, xk, dl_func, &P, &o, &rep, &keep);
            ca.fail_at = 0;
            if (r == PLATEAU_LM_OK) {
                plateau_lm_dogleg_keep_free(keep);
                keep = NULL;
                break;
            }
            if (r != PLATEAU_LM_ERR_OUT_OF_MEMORY) bad++;
            memcpy(xk, x0, N * sizeof(double));
            memcpy(xp, x0, N * sizeof(double));
            if (!keep_agrees(&pat[sp], g[sp].xy, &P, xk, xp, N, &o, &keep)) bad++;
            plateau_lm_dogleg_keep_free(keep);
            keep = NULL;
            if (ca.live != 0 || ca.bad != 0) bad++;
        }
        n = k - 1;
        CHECK(n >= (s == 0 ? 4 : 2));
        printf("dog-leg keep, %s: %ld allocations failed one at a time, each cleanly\n",
               s == 0 ? "first solve" : "grown blocks", n);
    }
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(ca.live, 0);
    printf("dog-leg keep: 5 solves on 3 patterns as the plain solve, bit for bit; %ld allocations "
           "a solve on kept blocks against %ld\n", kept, plain);
    free(P.c); free(xk); free(xp); free(x0);
    for (s = 0; s < 3; s++) sm_free(&g[s]);
}

/* ---- LDL^T and its inertia -------------------------------------------- */


/* ---- options.cancel: a time limit inside one factorisation -------------- */

/* counts its calls; non-zero from call number stop_at on (0: never) */
typedef struct cancel_count {
    int calls, stop_at;
} cancel_count;

static int cancel_after(void *user)
{
    cancel_count *c = (cancel_count *)user;
    c->calls++;
    return c->stop_at && c->calls >= c->stop_at;
}

/* plateau_lm_sparse_options.cancel is asked during a factorisation whose
 * fronts hold more than PLATEAU_LM_CANCEL_FLOPS multiply-adds (an 80 x 80
 * grid, b = 3: about 5 10^8 flops), and one that says stop ends it at once
 * (ABORTED, nothing solved from it: NOT_FACTORED); the object stays
 * usable, and a cancel that never says stop changes no bit of the factor
 * (the same solution). */
static void test_factorize_cancel(void)
{
    sm_graph g;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_options o;
    plateau_lm_sparse_symbolic *S = NULL, *S2 = NULL;
    plateau_lm_sparse_factor *F = NULL, *F2 = NULL;
    cancel_count cc = {0, 0};
    double *v, *x, *x2;
    size_t N, i;
    unsigned long long seed = 5;
    int same = 1;
    if (!CHECK(sm_grid(&g, 80))) return;
    N = 3 * g.n;
    pat = pattern_of(&g, 3);
    v = sm_values(&g, 3, 0, 9);
    x = (double *)malloc(N * sizeof(double));
    x2 = (double *)malloc(N * sizeof(double));
    if (!CHECK(v && x && x2)) goto done;
    for (i = 0; i < N; i++) x[i] = x2[i] = 2.0 * sm_rand(&seed) - 1.0;
    memset(&o, 0, sizeof o);
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, &o, &S2), PLATEAU_LM_OK); /* no cancel */
    o.cancel = cancel_after;
    o.cancel_user = &cc;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, &o, &S), PLATEAU_LM_OK);
    if (!S || !S2) goto done;
    CHECK(plateau_lm_sparse_symbolic_info(S).flops_lu > 4.0 * PLATEAU_LM_CANCEL_FLOPS);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LU, NULL, 0, &F), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S2, PLATEAU_LM_SPARSE_LU, NULL, 0, &F2), PLATEAU_LM_OK);
    if (!F || !F2) goto done;
    /* never stop: asked a few times, the same factor as without */
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK);
    CHECK(cc.calls >= 2);
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F2, v, 0.0), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, N), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F2, 1, x2, N), PLATEAU_LM_OK);
    for (i = 0; i < N; i++) same &= x[i] == x2[i];
    CHECK(same);
    printf("cancel: asked %d times in one LU of %lu unknowns (%.2g flops)\n", cc.calls, (unsigned long)N,
           plateau_lm_sparse_symbolic_info(S).flops_lu);
    /* stop at the first question: ABORTED there, nothing to solve with */
    cc.calls = 0;
    cc.stop_at = 1;
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_ERR_ABORTED);
    CHECK_EQ_INT(cc.calls, 1);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, N), PLATEAU_LM_ERR_NOT_FACTORED);
    /* the object stays valid: a factorisation that is let run holds */
    cc.calls = cc.stop_at = 0;
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK);
done:
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_factor_free(F2);
    plateau_lm_sparse_symbolic_free(S);
    plateau_lm_sparse_symbolic_free(S2);
    free(v);
    free(x);
    free(x2);
    sm_free(&g);
}

/* plateau_lm_options.cancel reaches the dog leg's LU with the solve's
 * user pointer: a cancel that stops at its first question ends the solve
 * with ABORTED and x at its last accepted point (here the start: the
 * first LU is cut); one that never stops gives the solve without it, bit
 * for bit. */
static dl_problem *dl_cancel_problem;
static cancel_count dl_cancel_count;
static int dl_cancel(void *user)
{
    CHECK(user == (void *)dl_cancel_problem);
    return cancel_after(&dl_cancel_count);
}

static void test_dogleg_cancel(void)
{
    sm_graph g;
    dl_problem P;
    plateau_lm_sparse_pattern pat;
    plateau_lm_options lo;
    plateau_lm_report rep, r0;
    size_t N, i;
    double *x, *x0, *xr;
    unsigned long long seed = 7;
    int same = 1, start = 1;
    if (!CHECK(sm_grid(&g, 60))) return; /* LUs of about 2 10^8 flops: cancel is asked */
    N = 3 * g.n;
    memset(&P, 0, sizeof P);
    P.g = &g;
    P.c = (double *)malloc(N * sizeof(double));
    x = (double *)malloc(N * sizeof(double));
    x0 = (double *)malloc(N * sizeof(double));
    xr = (double *)malloc(N * sizeof(double));
    if (!CHECK(P.c && x && x0 && xr)) goto done;
    for (i = 0; i < N; i++) P.c[i] = 4.0 * sm_rand(&seed) - 2.0;
    for (i = 0; i < N; i++) x[i] = x0[i] = xr[i] = sm_rand(&seed) - 0.5;
    pat = pattern_of(&g, 3);
    CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, xr, dl_func, &P, NULL, &r0), PLATEAU_LM_OK);
    memset(&lo, 0, sizeof lo);
    lo.cancel = dl_cancel;
    dl_cancel_problem = &P;
    dl_cancel_count.calls = dl_cancel_count.stop_at = 0;
    CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &lo, &rep), PLATEAU_LM_OK);
    CHECK(dl_cancel_count.calls > 0);
    for (i = 0; i < N; i++) same &= x[i] == xr[i];
    CHECK(same && rep.iterations == r0.iterations && rep.f_final == r0.f_final);
    for (i = 0; i < N; i++) x[i] = x0[i];
    dl_cancel_count.calls = 0;
    dl_cancel_count.stop_at = 1;
    CHECK_EQ_INT(plateau_lm_dogleg_solve(&pat, g.xy, x, dl_func, &P, &lo, &rep), PLATEAU_LM_ERR_ABORTED);
    CHECK_EQ_INT(rep.stop, PLATEAU_LM_STOP_ABORTED);
    CHECK_EQ_INT(rep.iterations, 0);
    for (i = 0; i < N; i++) start &= x[i] == x0[i];
    CHECK(start);
done:
    free(P.c);
    free(x);
    free(x0);
    free(xr);
    sm_free(&g);
}

/* Eigenvalues of the dense symmetric N x N matrix A (destroyed) by cyclic
 * Jacobi rotations: an independent count for the inertia tests. */
static void jacobi_eigenvalues(double *A, size_t N, double *ev)
{
    size_t sweep, p, q, k;
    for (sweep = 0; sweep < 60; sweep++) {
        double off = 0.0;
        for (p = 0; p < N; p++)
            for (q = p + 1; q < N; q++) off += A[p * N + q] * A[p * N + q];
        if (off < 1e-30) break;
        for (p = 0; p < N; p++)
            for (q = p + 1; q < N; q++) {
                double apq = A[p * N + q], th, t, c, sn;
                if (fabs(apq) < 1e-300) continue;
                th = (A[q * N + q] - A[p * N + p]) / (2.0 * apq);
                t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
                c = 1.0 / sqrt(t * t + 1.0);
                sn = t * c;
                for (k = 0; k < N; k++) { /* columns p, q */
                    double akp = A[k * N + p], akq = A[k * N + q];
                    A[k * N + p] = c * akp - sn * akq;
                    A[k * N + q] = sn * akp + c * akq;
                }
                for (k = 0; k < N; k++) { /* rows p, q */
                    double apk = A[p * N + k], aqk = A[q * N + k];
                    A[p * N + k] = c * apk - sn * aqk;
                    A[q * N + k] = sn * apk + c * aqk;
                }
            }
    }
    for (p = 0; p < N; p++) ev[p] = A[p * N + p];
}

/* Random symmetric blocks on a Delaunay graph, moved down by c on the
 * diagonal so that about half the eigenvalues are negative: the inertia of
 * the LDL^T equals the count of the Jacobi eigenvalues below 0 (and below
 * -shift with a shift), and its solve agrees with the dense solve. */
static void test_ldlt_inertia_dense(void)
{
    sm_graph g;
    size_t b;
    if (!CHECK(sm_delaunay(&g, 40, 11))) return;
    for (b = 1; b <= 3; b += 2) {
        size_t N = g.n * b, bb = b * b, i, p, r, c, neg = 0, pos = 0, want, want_s;
        double *v = sm_values(&g, b, 1, 900 + b), *A = (double *)calloc(N * N, sizeof(double));
        double *A2 = (double *)malloc(N * N * sizeof(double)), *ev = (double *)malloc(N * sizeof(double));
        double *x = (double *)malloc(N * sizeof(double)), *xd = (double *)malloc(N * sizeof(double));
        double cshift = 0.0, maxdiff = 0.0, xmax = 0.0, sh = 0.25;
        unsigned long long seed = 5;
        plateau_lm_sparse_pattern pat = pattern_of(&g, (int)b);
        plateau_lm_sparse_symbolic *S = NULL;
        plateau_lm_sparse_factor *F = NULL;
        if (!v || !A || !A2 || !ev || !x || !xd) return;
        /* the diagonal entries are b (deg + 1); the middle of the spectrum is near them */
        for (i = 0; i < g.n; i++) {
            size_t d = sm_find(&g, i, i);
            cshift += v[d * bb] / (double)g.n;
        }
        for (i = 0; i < g.n; i++) {
            size_t d = sm_find(&g, i, i);
            for (r = 0; r < b; r++) v[d * bb + r * b + r] -= cshift + 0.1 * (double)r;
        }
        for (i = 0; i < g.n; i++)
            for (p = (size_t)g.rs[i]; p < (size_t)g.rs[i + 1]; p++)
                for (r = 0; r < b; r++)
                    for (c = 0; c < b; c++)
                        A[(i * b + r) * N + (size_t)g.cols[p] * b + c] = v[p * bb + r * b + c];
        memcpy(A2, A, N * N * sizeof(double));
        jacobi_eigenvalues(A2, N, ev);
        want = want_s = 0;
        for (i = 0; i < N; i++) {
            want += ev[i] < 0.0;
            want_s += ev[i] < -sh;
        }
        CHECK(want > N / 5 && want < 4 * N / 5); /* really indefinite */
        CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, NULL, &S), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LDLT, NULL, 0, &F), PLATEAU_LM_OK);
        if (!F) break;
        CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_ERR_NOT_FACTORED);
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_OK);
        CHECK_EQ_INT(neg, want);
        CHECK_EQ_INT(neg + pos, N);
        for (i = 0; i < N; i++) x[i] = xd[i] = 2.0 * sm_rand(&seed) - 1.0;
        CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, N), PLATEAU_LM_OK);
        memcpy(A2, A, N * N * sizeof(double));
        CHECK(dense_solve(A2, xd, N));
        for (i = 0; i < N; i++) {
            if (fabs(x[i] - xd[i]) > maxdiff) maxdiff = fabs(x[i] - xd[i]);
            if (fabs(xd[i]) > xmax) xmax = fabs(xd[i]);
        }
        CHECK(maxdiff <= 1e-9 * xmax);
        /* A + sh I: the eigenvalues below -sh */
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, sh), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_OK);
        CHECK_EQ_INT(neg, want_s);
        plateau_lm_sparse_factor_free(F);
        plateau_lm_sparse_symbolic_free(S);
        free(v); free(A); free(A2); free(ev); free(x); free(xd);
    }
    sm_free(&g);
}

/* The 5-point Laplacian of a k x k grid (the grid's diagonal couplings set
 * to 0) minus c I: its eigenvalues 4 - 2 cos(pi i/(k+1)) - 2 cos(pi j/(k+1))
 * are known, so the inertia has an exact count at a size where a dense
 * check is out of reach; the Cholesky of the SPD case agrees (no negative). */
static void test_ldlt_inertia_grid(void)
{
    sm_graph g;
    size_t k = BIG_GRID, i, j, p, neg = 0, pos = 0, want;
    double cs[3] = {0.5, 2.7, 6.1};
    int t;
    double *v;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL;
    if (!CHECK(sm_grid(&g, k))) return;
    v = (double *)malloc(g.nnz * sizeof(double));
    pat = pattern_of(&g, 1);
    if (!v) return;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, g.xy, NULL, &S), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LDLT, NULL, 0, &F), PLATEAU_LM_OK);
    if (!F) return;
    for (t = 0; t < 3; t++) {
        const double pi = 3.14159265358979323846;
        double c = cs[t];
        for (i = 0; i < g.n; i++)
            for (p = (size_t)g.rs[i]; p < (size_t)g.rs[i + 1]; p++) {
                size_t q = (size_t)g.cols[p], lo = q < i ? q : i, hi = q < i ? i : q;
                if (q == i) v[p] = 4.0 - c;
                else if (hi - lo == 1 || hi - lo == k) v[p] = -1.0;
                else v[p] = 0.0;
            }
        want = 0;
        for (i = 1; i <= k; i++)
            for (j = 1; j <= k; j++)
                want += 4.0 - 2.0 * cos(pi * (double)i / (double)(k + 1)) -
                            2.0 * cos(pi * (double)j / (double)(k + 1)) < c;
        CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_OK);
        CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_OK);
        CHECK_EQ_INT(neg, want);
        CHECK_EQ_INT(pos, g.n - want);
    }
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    free(v);
    sm_free(&g);
}

/* A zero pivot in elimination order is a breakdown (SINGULAR_PIVOT, the
 * node named), a shift gets past it; the other kinds have no inertia. */
static void test_ldlt_breakdown(void)
{
    /* the 2 x 2 [0 1; 1 0]: eigenvalues -1 and 1, first pivot 0 */
    plateau_index rs[3] = {0, 2, 4}, cols[4] = {0, 1, 0, 1};
    double v[4] = {0, 1, 1, 0}, x[2] = {1, 2};
    size_t neg = 9, pos = 9;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL, *C = NULL;
    plateau_lm_sparse_options o;
    memset(&o, 0, sizeof o);
    o.ordering = PLATEAU_LM_SPARSE_ORDER_NATURAL;
    pat.nodes = 2; pat.block = 1; pat.row_start = rs; pat.cols = cols;
    CHECK_EQ_INT(plateau_lm_sparse_analyze(&pat, NULL, &o, &S), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_LDLT, NULL, 0, &F), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_factor_create(S, PLATEAU_LM_SPARSE_CHOLESKY, NULL, 0, &C), PLATEAU_LM_OK);
    CHECK(plateau_lm_sparse_factor_size(S, PLATEAU_LM_SPARSE_LDLT) > 0);
    CHECK(plateau_lm_sparse_factor_size(S, 4) == 0);
    if (!F || !C) return;
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.0), PLATEAU_LM_ERR_SINGULAR_PIVOT);
    CHECK(plateau_lm_sparse_failed_node(F) == 0);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_ERR_NOT_FACTORED);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 2), PLATEAU_LM_ERR_NOT_FACTORED);
    /* + 0.5 I: eigenvalues -0.5 and 1.5; the solve agrees with the exact inverse */
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 0.5), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_OK);
    CHECK_EQ_INT(neg, 1);
    CHECK_EQ_INT(pos, 1);
    CHECK_EQ_INT(plateau_lm_sparse_solve(F, 1, x, 2), PLATEAU_LM_OK);
    /* [0.5 1; 1 0.5]^-1 = [0.5 -1; -1 0.5] / (0.25 - 1) */
    CHECK_NEAR(x[0], (0.5 * 1 - 1 * 2) / (0.25 - 1.0), 1e-14);
    CHECK_NEAR(x[1], (0.5 * 2 - 1 * 1) / (0.25 - 1.0), 1e-14);
    /* + 1.5 I: positive definite; the Cholesky agrees that it is */
    CHECK_EQ_INT(plateau_lm_sparse_factorize(F, v, 1.5), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(F, &neg, &pos), PLATEAU_LM_OK);
    CHECK_EQ_INT(neg, 0);
    CHECK_EQ_INT(plateau_lm_sparse_factorize(C, v, 1.5), PLATEAU_LM_OK);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(C, &neg, &pos), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(NULL, &neg, &pos), PLATEAU_LM_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_lm_sparse_inertia(F, NULL, &pos), PLATEAU_LM_ERR_ARGUMENT);
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_factor_free(C);
    plateau_lm_sparse_symbolic_free(S);
}

int main(void)
{
    RUN(test_orderings_are_permutations);
    RUN(test_nested_dissection_fill);
    RUN(test_residuals);
    RUN(test_dense_agreement);
    RUN(test_multi_rhs_and_reuse);
    RUN(test_errors);
    RUN(test_forest);
    RUN(test_large);
    RUN(test_alloc_failure);
    RUN(test_dogleg);
    RUN(test_dogleg_scale_and_nan);
    RUN(test_factorize_cancel);
    RUN(test_dogleg_cancel);
    RUN(test_dogleg_tail);
    RUN(test_dogleg_spent);
    RUN(test_dogleg_no_chord);
    RUN(test_dogleg_chord_steps);
    RUN(test_dogleg_keep);
    RUN(test_paper_jacobian);
    RUN(test_ldlt_inertia_dense);
    RUN(test_ldlt_inertia_grid);
    RUN(test_ldlt_breakdown);
    return harness_report("test_lm_sparse");
}
