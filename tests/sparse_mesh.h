/* sparse_mesh.h - block-sparse test matrices on planar meshes, shared by
 * tests/test_lm_sparse.c and bench/bench_sparse.c: grids and Delaunay meshes of
 * random points as node graphs (CSR with the diagonal), and random values
 * (unsymmetric and diagonally dominant, or symmetric positive definite).
 * Needs plateau_lm.h and plateau_delaunay.h declared before it. */
#ifndef PLATEAU_TEST_SPARSE_MESH_H
#define PLATEAU_TEST_SPARSE_MESH_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct sm_graph {
    size_t n, nnz;
    plateau_index *rs, *cols; /* CSR with the diagonal, columns ascending */
    double *xy;               /* 2 n */
} sm_graph;

static void sm_free(sm_graph *g)
{
    free(g->rs);
    free(g->cols);
    free(g->xy);
    memset(g, 0, sizeof *g);
}

/* a 64-bit linear congruential generator, uniform in [0, 1) */
static double sm_rand(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

static int sm_cmp_index(const void *a, const void *b)
{
    plateau_index x = *(const plateau_index *)a, y = *(const plateau_index *)b;
    return x < y ? -1 : x > y;
}

/* CSR from an undirected edge list (both directions added, duplicates
 * removed, the diagonal added). */
static int sm_from_edges(sm_graph *g, size_t n, const plateau_index *e, size_t ne)
{
    size_t i, k, *cnt = (size_t *)calloc(n + 1, sizeof(size_t));
    plateau_index *tmp;
    if (!cnt) return 0;
    for (i = 0; i < ne; i++) {
        cnt[e[2 * i] + 1]++;
        cnt[e[2 * i + 1] + 1]++;
    }
    for (i = 0; i < n; i++) cnt[i + 1] += cnt[i] + 1;
    tmp = (plateau_index *)malloc((cnt[n] + 1) * sizeof(plateau_index));
    g->rs = (plateau_index *)malloc((n + 1) * sizeof(plateau_index));
    if (!tmp || !g->rs) { free(cnt); free(tmp); return 0; }
    {
        size_t *pos = (size_t *)malloc((n + 1) * sizeof(size_t));
        if (!pos) { free(cnt); free(tmp); return 0; }
        for (i = 0; i < n; i++) { pos[i] = cnt[i]; tmp[pos[i]++] = (plateau_index)i; }
        for (i = 0; i < ne; i++) {
            tmp[pos[e[2 * i]]++] = e[2 * i + 1];
            tmp[pos[e[2 * i + 1]]++] = e[2 * i];
        }
        free(pos);
    }
    /* sort each row, drop duplicates */
    k = 0;
    g->rs[0] = 0;
    for (i = 0; i < n; i++) {
        size_t a = cnt[i], b = cnt[i + 1], j;
        qsort(tmp + a, b - a, sizeof(plateau_index), sm_cmp_index);
        for (j = a; j < b; j++)
            if (j == a || tmp[j] != tmp[j - 1]) tmp[k++] = tmp[j];
        g->rs[i + 1] = (plateau_index)k;
    }
    g->cols = tmp;
    g->n = n;
    g->nnz = k;
    free(cnt);
    return 1;
}

/* k x k grid of nodes, triangulated (right, up and up-right neighbours:
 * the graph of a regular triangle mesh), coordinates (i, j). */
static int sm_grid(sm_graph *g, size_t k)
{
    size_t n = k * k, i, j, ne = 0;
    plateau_index *e = (plateau_index *)malloc(6 * n * sizeof(plateau_index) + 1);
    memset(g, 0, sizeof *g);
    g->xy = (double *)malloc(2 * n * sizeof(double));
    if (!e || !g->xy) { free(e); return 0; }
    for (j = 0; j < k; j++)
        for (i = 0; i < k; i++) {
            size_t v = j * k + i;
            g->xy[2 * v] = (double)i;
            g->xy[2 * v + 1] = (double)j;
            if (i + 1 < k) { e[2 * ne] = (plateau_index)v; e[2 * ne + 1] = (plateau_index)(v + 1); ne++; }
            if (j + 1 < k) { e[2 * ne] = (plateau_index)v; e[2 * ne + 1] = (plateau_index)(v + k); ne++; }
            if (i + 1 < k && j + 1 < k) {
                e[2 * ne] = (plateau_index)v; e[2 * ne + 1] = (plateau_index)(v + k + 1); ne++;
            }
        }
    i = (size_t)sm_from_edges(g, n, e, ne);
    free(e);
    return (int)i;
}

/* Delaunay triangulation of n random points in the unit square. */
static int sm_delaunay(sm_graph *g, size_t n, unsigned long long seed)
{
    plateau_dt_input in;
    plateau_dt_mesh mesh;
    plateau_index *e;
    size_t i, t;
    int ok;
    memset(g, 0, sizeof *g);
    memset(&in, 0, sizeof in);
    g->xy = (double *)malloc(2 * n * sizeof(double));
    if (!g->xy) return 0;
    for (i = 0; i < 2 * n; i++) g->xy[i] = sm_rand(&seed);
    in.points = g->xy;
    in.num_points = n;
    if (plateau_dt_triangulate(&in, NULL, &mesh, NULL) != PLATEAU_DT_OK) return 0;
    e = (plateau_index *)malloc(6 * mesh.num_triangles * sizeof(plateau_index) + 1);
    if (!e) { plateau_dt_free(&mesh); return 0; }
    for (t = 0; t < mesh.num_triangles; t++)
        for (i = 0; i < 3; i++) {
            e[6 * t + 2 * i] = mesh.triangles[3 * t + i];
            e[6 * t + 2 * i + 1] = mesh.triangles[3 * t + (i + 1) % 3];
        }
    ok = sm_from_edges(g, n, e, 3 * mesh.num_triangles);
    free(e);
    plateau_dt_free(&mesh);
    return ok;
}

/* Position of block (k, i) for every block (i, k) of g (columns ascending). */
static size_t sm_find(const sm_graph *g, size_t i, size_t k)
{
    size_t lo = (size_t)g->rs[i], hi = (size_t)g->rs[i + 1];
    while (lo < hi) {
        size_t m = lo + (hi - lo) / 2;
        if ((size_t)g->cols[m] < k) lo = m + 1; else hi = m;
    }
    return lo;
}

/* Values, b x b blocks.  spd = 0: unsymmetric, each diagonal block a random
 * well-conditioned (not diagonal) block times a random scale, off-diagonal
 * blocks random and smaller in total (block diagonally dominant after
 * scaling by the diagonal blocks' inverses).  spd = 1: symmetric, strictly
 * diagonally dominant with a positive diagonal: positive definite. */
static double *sm_values(const sm_graph *g, size_t b, int spd, unsigned long long seed)
{
    size_t bb = b * b, i, p, r, c;
    double *v = (double *)malloc(g->nnz * bb * sizeof(double) + 1);
    if (!v) return NULL;
    for (i = 0; i < g->n; i++)
        for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++) {
            size_t k = (size_t)g->cols[p];
            if (spd && k < i) continue;
            for (r = 0; r < bb; r++) v[p * bb + r] = 2.0 * sm_rand(&seed) - 1.0;
            if (spd && k > i) {
                size_t q = sm_find(g, k, i);
                for (r = 0; r < b; r++)
                    for (c = 0; c < b; c++) v[q * bb + c * b + r] = v[p * bb + r * b + c];
            }
        }
    for (i = 0; i < g->n; i++) {
        size_t d = sm_find(g, i, i);
        double deg = (double)(g->rs[i + 1] - g->rs[i]);
        if (spd) {
            for (r = 0; r < b; r++)
                for (c = 0; c < r; c++) v[d * bb + c * b + r] = v[d * bb + r * b + c];
            for (r = 0; r < b; r++) v[d * bb + r * b + r] = (double)b * (deg + 1.0);
        } else {
            double scale = 0.1 + 10.0 * sm_rand(&seed);
            for (r = 0; r < b; r++) v[d * bb + r * b + r] += (double)b * deg;
            for (r = 0; r < bb; r++) v[d * bb + r] *= scale;
        }
    }
    return v;
}

/* y = A x */
static void sm_matvec(const sm_graph *g, size_t b, const double *v, const double *x, double *y)
{
    size_t i, p, r, c, bb = b * b;
    for (i = 0; i < g->n * b; i++) y[i] = 0.0;
    for (i = 0; i < g->n; i++)
        for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++) {
            size_t k = (size_t)g->cols[p];
            for (r = 0; r < b; r++)
                for (c = 0; c < b; c++) y[i * b + r] += v[p * bb + r * b + c] * x[k * b + c];
        }
}

/* ||A||_inf */
static double sm_norm(const sm_graph *g, size_t b, const double *v)
{
    size_t i, p, r, c, bb = b * b;
    double best = 0.0;
    for (i = 0; i < g->n; i++)
        for (r = 0; r < b; r++) {
            double s = 0.0;
            for (p = (size_t)g->rs[i]; p < (size_t)g->rs[i + 1]; p++)
                for (c = 0; c < b; c++) s += fabs(v[p * bb + r * b + c]);
            if (s > best) best = s;
        }
    return best;
}

#endif /* PLATEAU_TEST_SPARSE_MESH_H */
