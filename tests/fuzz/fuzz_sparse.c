/* fuzz_sparse.c - libFuzzer target for the block-sparse solver of
 * plateau_lm.h: plateau_lm_sparse_analyze, _factor_create, _factorize and
 * _solve.
 *
 * Bytes: [n] [b] [flags] [event] then the upper triangle of the node
 * graph (one bit per pair), the block values (signed byte / 8 each, the
 * diagonal blocks plus a byte / 4 on their diagonal), 2 n coordinates
 * (signed byte each) and a right-hand side (signed byte each).
 *   n, b   1 + byte modulo 12 nodes, 1 + byte modulo 4 unknowns per node
 *   flags  bit 0 drop block (event) if off-diagonal: not symmetric;
 *          bit 1 repeat node 0's last block; bit 2 drop node 0's diagonal; bit 3 pass
 *          xy; bit 4 graph ordering; bit 5 Cholesky; bit 6 shift 0.5;
 *          bit 7 refuse allocation 1 + event % 4
 * Checked: every result is a named code; a broken pattern gives
 * PLATEAU_LM_ERR_BAD_PATTERN (or out of memory when its check could not
 * get memory); a refused allocation gives
 * PLATEAU_LM_ERR_OUT_OF_MEMORY; the order is a permutation; a failed
 * pivot names a node; the same factorisation in a caller workspace solves
 * bit for bit the same; nothing leaks. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_LM_IMPLEMENTATION
#endif
#include "plateau_lm.h"
#include <math.h>
#include "countalloc.h"
#include "fuzz_common.h"

#define FZ_N 12

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes bb;
    size_t n, b, bbk, i, k, nnz = 0, N;
    uint8_t flags, ev;
    int adj[FZ_N][FZ_N];
    plateau_index rs[FZ_N + 1], cols[FZ_N * FZ_N + 1];
    double vals[(FZ_N * FZ_N + 1) * 16], xy[2 * FZ_N], rhs[FZ_N * 4], x1[FZ_N * 4], x2[FZ_N * 4];
    int broken = 0, kind;
    countalloc ca;
    plateau_lm_sparse_options o;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_symbolic *S = NULL;
    plateau_lm_sparse_factor *F = NULL, *F2 = NULL;
    plateau_lm_result r;
    bb.data = data;
    bb.size = size;
    bb.pos = 0;
    n = 1 + fuzz_u8(&bb) % FZ_N;
    b = 1 + fuzz_u8(&bb) % 4;
    bbk = b * b;
    N = n * b;
    flags = fuzz_u8(&bb);
    ev = fuzz_u8(&bb);
    memset(adj, 0, sizeof adj);
    {
        int bit = 8;
        uint8_t cur = 0;
        for (i = 0; i < n; i++)
            for (k = i + 1; k < n; k++) {
                if (bit == 8) { cur = fuzz_u8(&bb); bit = 0; }
                adj[i][k] = adj[k][i] = (cur >> bit++) & 1;
            }
    }
    rs[0] = 0;
    for (i = 0; i < n; i++) {
        for (k = 0; k < n; k++) {
            if (k == i && i == 0 && (flags & 4)) { broken = 1; continue; }
            if (k == i || adj[i][k]) cols[nnz++] = (plateau_index)k;
        }
        if (i == 0 && (flags & 2) && nnz > 0) { cols[nnz] = cols[nnz - 1]; nnz++; broken = 1; }
        rs[i + 1] = (plateau_index)nnz;
    }
    if ((flags & 1) && nnz > 0) {
        /* drop block number ev % nnz when it is off-diagonal */
        size_t drop = ev % nnz, row = 0;
        while ((size_t)rs[row + 1] <= drop) row++;
        if ((size_t)cols[drop] != row && !((flags & 2) && row == 0)) {
            for (i = drop; i + 1 < nnz; i++) cols[i] = cols[i + 1];
            nnz--;
            for (i = row + 1; i <= n; i++) rs[i]--;
            broken = 1;
        }
    }
    for (i = 0; i < nnz * bbk; i++) vals[i] = (double)(int8_t)fuzz_u8(&bb) / 8.0;
    for (i = 0; i < n; i++)
        for (k = (size_t)rs[i]; k < (size_t)rs[i + 1]; k++)
            if ((size_t)cols[k] == i) {
                size_t t;
                for (t = 0; t < b; t++) vals[k * bbk + t * b + t] += (double)fuzz_u8(&bb) / 4.0;
            }
    for (i = 0; i < 2 * n; i++) xy[i] = (double)(int8_t)fuzz_u8(&bb);
    for (i = 0; i < N; i++) rhs[i] = x1[i] = x2[i] = (double)(int8_t)fuzz_u8(&bb);

    countalloc_init(&ca, (flags & 128) ? 1 + ev % 4 : 0);
    memset(&o, 0, sizeof o);
    o.allocator = countalloc_allocator(&ca);
    o.ordering = (flags & 16) ? PLATEAU_LM_SPARSE_ORDER_GRAPH : PLATEAU_LM_SPARSE_ORDER_AUTO;
    pat.nodes = n;
    pat.block = (int)b;
    pat.row_start = rs;
    pat.cols = cols;
    kind = (flags & 32) ? PLATEAU_LM_SPARSE_CHOLESKY : PLATEAU_LM_SPARSE_LU;
    r = plateau_lm_sparse_analyze(&pat, (flags & 8) ? xy : NULL, &o, &S);
    /* the symmetry check needs the analysis' temporary block: a refused
     * first allocation may come first */
    if (broken)
        FUZZ_REQUIRE(r == PLATEAU_LM_ERR_BAD_PATTERN || (ca.refused && r == PLATEAU_LM_ERR_OUT_OF_MEMORY));
    FUZZ_REQUIRE(r == PLATEAU_LM_OK || r == PLATEAU_LM_ERR_BAD_PATTERN || r == PLATEAU_LM_ERR_OUT_OF_MEMORY);
    if (r != PLATEAU_LM_OK) {
        FUZZ_REQUIRE(S == NULL);
        FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
        return 0;
    }
    {
        const plateau_index *perm = plateau_lm_sparse_permutation(S);
        unsigned char seen[FZ_N];
        memset(seen, 0, sizeof seen);
        for (i = 0; i < n; i++) {
            FUZZ_REQUIRE(perm[i] >= 0 && (size_t)perm[i] < n && !seen[perm[i]]);
            seen[perm[i]] = 1;
        }
    }
    r = plateau_lm_sparse_factor_create(S, kind, NULL, 0, &F);
    FUZZ_REQUIRE(r == PLATEAU_LM_OK || r == PLATEAU_LM_ERR_OUT_OF_MEMORY);
    if (r == PLATEAU_LM_OK) {
        size_t need = plateau_lm_sparse_factor_size(S, kind);
        unsigned char *work = (unsigned char *)malloc(need + 1);
        double shift = (flags & 64) ? 0.5 : 0.0;
        plateau_lm_result r1 = plateau_lm_sparse_factorize(F, vals, shift), r2;
        FUZZ_REQUIRE(r1 == PLATEAU_LM_OK || r1 == PLATEAU_LM_ERR_SINGULAR_PIVOT ||
                     r1 == PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE);
        if (r1 != PLATEAU_LM_OK) {
            plateau_index bad = plateau_lm_sparse_failed_node(F);
            FUZZ_REQUIRE(bad >= 0 && (size_t)bad < n);
            FUZZ_REQUIRE(plateau_lm_sparse_solve(F, 1, x1, N) == PLATEAU_LM_ERR_NOT_FACTORED);
        } else {
            FUZZ_REQUIRE(plateau_lm_sparse_failed_node(F) == -1);
            FUZZ_REQUIRE(plateau_lm_sparse_solve(F, 1, x1, N) == PLATEAU_LM_OK);
        }
        /* the same in a caller workspace at an odd address */
        FUZZ_REQUIRE(work != NULL);
        FUZZ_REQUIRE(plateau_lm_sparse_factor_create(S, kind, work + 1, need, &F2) == PLATEAU_LM_OK);
        r2 = plateau_lm_sparse_factorize(F2, vals, shift);
        FUZZ_REQUIRE(r2 == r1);
        if (r2 == PLATEAU_LM_OK) {
            FUZZ_REQUIRE(plateau_lm_sparse_solve(F2, 1, x2, N) == PLATEAU_LM_OK);
            FUZZ_REQUIRE(memcmp(x1, x2, N * sizeof(double)) == 0);
        }
        plateau_lm_sparse_factor_free(F2);
        free(work);
    } else {
        FUZZ_REQUIRE(F == NULL);
    }
    plateau_lm_sparse_factor_free(F);
    plateau_lm_sparse_symbolic_free(S);
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    (void)rhs;
    return 0;
}
