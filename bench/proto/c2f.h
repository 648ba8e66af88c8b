/* c2f.h - a prototype, not part of the library: method area coarse to fine,
 * with Newton's method on normal motions, built on plateau's public API
 * (plateau_solve and plateau_mesh_minimize for the coarsest level, the mesh
 * kernel's adjacency, plateau_lm.h's sparse Cholesky and LU).  Used by
 * bench/bench_evolver.c (its "c2f" series) and bench/proto/proto_c2f.c (the
 * experiments); the design it measures is meant for plateau.h's method area.
 *
 * The algorithm (c2f_solve, all-zero c2f_params):
 *   0. Levels.  The coarse count I_0 solves I_L = n for
 *      I_L = 4^L I_0 + B (4^L - 2^L) / 2 - (4^L - 1), B = m (a disk of I
 *      interior and B boundary vertices subdivided once has 4 I + B - 3
 *      interior and 2 B boundary vertices, by Euler's formula); L is the
 *      largest number of 1-to-4 subdivisions that leaves I_0 >= 16
 *      (C2F_COARSE_MIN), so I_0 is 16 to about 70.
 *   1. Coarse level: plateau_solve(method area, quality seeding,
 *      refine_boundary, the sparse Newton method) with one round, then
 *      rounds of plain area-lowering flips (c2f_area_flips) and a re-solve
 *      (plateau_mesh_minimize, one round) until no flip is left (at most 8).
 *   2. Subdivide 1-to-4 (c2f_subdivide): a vertex on every edge; on a
 *      boundary edge (one triangle) at its midpoint, fixed (the polygon's
 *      edges are straight: the polygon does not change); on an interior
 *      edge (a, b) the midpoint of the cubic through a and b whose tangents
 *      lie in the tangent planes of a and b (unit vertex normals n_a, n_b),
 *          p = (a + b) / 2 - ((b - a).n_a n_a + (a - b).n_b n_b) / 8
 *      (the cubic Bezier edge of "PN triangles", Vlachos et al. 2001), O(h^3)
 *      off a smooth surface where the chord's midpoint is O(h^2) off.
 *   3. Newton's method on normal motions (c2f_normal_newton): one unknown t_i
 *      per free vertex, x_i(t) = x_i + t_i m_i, m_i its unit area-weighted
 *      normal, frozen during the step.  For a triangle (p_0, p_1, p_2) with
 *      e_i = p_(i+1) - p_(i+2), N = (p_1 - p_0) x (p_2 - p_0), n = N / |N|,
 *      a_i = m_i x e_i (0 for a fixed corner), since dN = sum_i d_i x e_i
 *      and N is bilinear in the corners:
 *          dA/dt_i       = n.a_i / 2
 *          d2A/dt_i dt_j = (a_i.a_j - (n.a_i)(n.a_j)) / (2 |N|) + s_ij n.(m_i x m_j) / 2
 *      with s_ij = +1 for j = i + 1, -1 for j = i + 2 (mod 3), 0 for j = i
 *      (c2f_assemble; c2f_check_derivatives compares both with central
 *      differences).  The step solves H t = -g by the sparse Cholesky
 *      (scalar nodes, the free vertices' 1-ring pattern, analysed once per
 *      level); if H is not positive definite, H + mu mean(diag H) I with mu
 *      = 1e-3, x10 per failure; the step is halved while it raises the area
 *      or turns a triangle against its old normal.
 *   4. Stopping rule: the Newton decrement delta = -g.t = t.H t is twice
 *      the decrease the quadratic model still promises; a level ends when
 *      delta / 2 <= tau E, tau = 0.01 (C2F_TAU), E the level's excess
 *      estimated from the levels themselves: one subdivision halves h and
 *      the area's error falls as h^2, so A_(k-1) - A* ~ 4 (A_k - A*) and
 *      E = (A_(k-1) - A) / 3, A the current area.  After a step the
 *      decrement is first computed with the old factor (a chord solve, one
 *      substitution); only when that one is too large is H factorised anew.
 *      At most C2F_MAX_STEPS steps per level.
 *   5. The final check plateau_solve makes (plateau_mesh_check).
 * Options for the measurements: the coarse level by plateau_solve's own
 * rounds, chord midpoints, a new factorisation for every decrement,
 * tangential relaxation sweeps (c2f_tangential), and three forms of method
 * paper (c2f_params.paper).  Memory: the mesh, one scalar factor, vectors.
 */
#ifndef PLATEAU_C2F_H
#define PLATEAU_C2F_H

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef C2F_COARSE_MIN
#define C2F_COARSE_MIN 16
#endif
#ifndef C2F_TAU
#define C2F_TAU 0.01
#endif
#define C2F_MAX_STEPS 20

#if defined(__GNUC__) || defined(__clang__)
#define C2F_FN static __attribute__((unused))
#else
#define C2F_FN static
#endif

typedef struct c2f_params {
    /* all-zero: the design measured by bench_evolver */
    size_t coarse_min;   /* 0 -> C2F_COARSE_MIN */
    double tau;          /* 0 -> C2F_TAU; negative: a fixed step count (-tau steps) */
    int chord_midpoints; /* 1: new interior edge vertices at the chord's midpoint
                            (0: the cubic of step 1) */
    int plateau_rounds;  /* 1: the coarse level by plateau_solve's own rounds (0: one
                            solve, then rounds of c2f_area_flips and a re-solve) */
    int coarse_solver;   /* plateau_options.linear_solver of the coarse solve;
                            0 -> PLATEAU_LINEAR_SPARSE (the Newton method) */
    double coarse_tol;   /* plateau_options.area_tolerance of the coarse solve */
    int coarse_rounds;   /* plateau_options.max_rounds of the coarse solve (plateau_rounds) */
    int no_chord;        /* 1: every decrement from a new factorisation */
    int tangential;      /* sweeps of tangential relaxation per level (0: none) */
    int full_newton;     /* > 0: instead of step 3, this many steps of plateau's own
                            Newton method on all 3 coordinates (plateau_mesh_minimize,
                            method area, one round) per level */
    int levels;          /* > 0: force this many subdivisions */
    int paper;           /* method paper: 1 its square system at every level
                            (plateau_mesh_minimize), 2 the area levels, then its
                            system at the finest level only, 3 the area levels, then
                            H_i = 0 on normal motions (c2f_paper_normal) */
    int paper_rounds;    /* max_rounds of the paper solves (0: 1) */
    int paper_iterations; /* max_iterations of those solves (0: the default; 3 steps
                            for paper 3) */
    int (*progress)(int round, int iteration, double f, void *user); /* of those solves */
} c2f_params;

typedef struct c2f_level {
    size_t interior;
    int steps, factorizations, halvings;
    double area, decrement, excess_estimate, cpu, tangential_gain;
} c2f_level;

typedef struct c2f_stats {
    int levels;
    unsigned defects;     /* plateau_mesh_check of the result */
    double check_cpu;
    c2f_level level[12];
    double coarse_cpu;
    size_t coarse_interior;
} c2f_stats;

/* ---------------------------------------------------------------- helpers */
C2F_FN void c2f_sub(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}
C2F_FN void c2f_cross(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}
C2F_FN double c2f_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Unit area-weighted normals of all vertices (zero where undefined). */
C2F_FN void c2f_vertex_normals(const plateau_mesh *mesh, double *m)
{
    size_t t, v;
    memset(m, 0, 3 * mesh->num_vertices * sizeof(double));
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double e1[3], e2[3], nn[3];
        int c;
        c2f_sub(mesh->positions + 3 * (size_t)tr[1], mesh->positions + 3 * (size_t)tr[0], e1);
        c2f_sub(mesh->positions + 3 * (size_t)tr[2], mesh->positions + 3 * (size_t)tr[0], e2);
        c2f_cross(e1, e2, nn);
        for (c = 0; c < 3; c++) {
            double *mv = m + 3 * (size_t)tr[c];
            mv[0] += nn[0];
            mv[1] += nn[1];
            mv[2] += nn[2];
        }
    }
    for (v = 0; v < mesh->num_vertices; v++) {
        double *mv = m + 3 * v, len = sqrt(c2f_dot(mv, mv));
        if (len > 0) {
            mv[0] /= len;
            mv[1] /= len;
            mv[2] /= len;
        }
    }
}

/* ---------------------------------------------------------------- 1. subdivision */
/* 1-to-4 subdivision of mesh into *out (created with plateau_mesh_create):
 * vertices keep their indices, edge e gets vertex num_vertices + e;
 * triangle (a, b, c) with edge vertices ab, bc, ca becomes (a, ab, ca),
 * (ab, b, bc), (ca, bc, c), (ab, bc, ca).  Returns a plateau_result. */
C2F_FN int c2f_subdivide(const plateau_mesh *mesh, int place, plateau_mesh *out)
{
    size_t nv = mesh->num_vertices, ne = mesh->num_edges, nt = mesh->num_triangles, e, t;
    double *pos = (double *)malloc(3 * (nv + ne) * sizeof(double));
    double *nrm = (double *)malloc(3 * nv * sizeof(double));
    unsigned char *fixed = (unsigned char *)malloc(nv + ne);
    plateau_index *tri = (plateau_index *)malloc(12 * nt * sizeof(plateau_index));
    int rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (!pos || !nrm || !fixed || !tri) goto done;
    memcpy(pos, mesh->positions, 3 * nv * sizeof(double));
    memcpy(fixed, mesh->fixed, nv);
    c2f_vertex_normals(mesh, nrm);
    for (e = 0; e < ne; e++) {
        size_t a = (size_t)mesh->edges[2 * e], b = (size_t)mesh->edges[2 * e + 1];
        const double *pa = pos + 3 * a, *pb = pos + 3 * b;
        double *p = pos + 3 * (nv + e);
        int boundary = mesh->edge_triangles[2 * e] < 0 || mesh->edge_triangles[2 * e + 1] < 0, k;
        for (k = 0; k < 3; k++) p[k] = 0.5 * (pa[k] + pb[k]);
        fixed[nv + e] = (unsigned char)boundary;
        if (!boundary && place) {
            double d[3], wa, wb;
            c2f_sub(pb, pa, d);
            wa = c2f_dot(d, nrm + 3 * a);
            wb = -c2f_dot(d, nrm + 3 * b);
            for (k = 0; k < 3; k++) p[k] -= (wa * nrm[3 * a + k] + wb * nrm[3 * b + k]) / 8.0;
        }
    }
    for (t = 0; t < nt; t++) {
        const plateau_index *v = mesh->triangles + 3 * t;
        plateau_index m[3], *o = tri + 12 * t;
        int k;
        for (k = 0; k < 3; k++) m[k] = (plateau_index)(nv + (size_t)mesh->triangle_edges[3 * t + (size_t)k]);
        /* m[k] lies on edge (v_k, v_(k+1)) */
        o[0] = v[0]; o[1] = m[0]; o[2] = m[2];
        o[3] = m[0]; o[4] = v[1]; o[5] = m[1];
        o[6] = m[2]; o[7] = m[1]; o[8] = v[2];
        o[9] = m[0]; o[10] = m[1]; o[11] = m[2];
    }
    rc = plateau_mesh_create(pos, nv + ne, fixed, tri, 4 * nt, NULL, out, NULL);
done:
    free(pos);
    free(nrm);
    free(fixed);
    free(tri);
    return rc;
}

/* ---------------------------------------------------------------- 2. normal Newton */
typedef struct c2f_system {
    size_t nfree, nnz;
    plateau_index *node;      /* vertex -> free index or -1 */
    plateau_index *row_start; /* nfree + 1 */
    plateau_index *cols;      /* nnz: the diagonal first, then free neighbours */
    double *xy;               /* 2 nfree: the nodes projected on the mean plane (ordering) */
    plateau_lm_sparse_symbolic *sym;
    plateau_lm_sparse_factor *fac;
} c2f_system;

C2F_FN void c2f_system_free(c2f_system *s)
{
    plateau_lm_sparse_factor_free(s->fac);
    plateau_lm_sparse_symbolic_free(s->sym);
    free(s->node);
    free(s->row_start);
    free(s->cols);
    free(s->xy);
    memset(s, 0, sizeof *s);
}

/* The scalar 1-ring pattern of the free vertices and its analysis. */
C2F_FN int c2f_system_new(const plateau_mesh *mesh, c2f_system *s)
{
    size_t nv = mesh->num_vertices, v, k = 0, q = 0, t;
    double nn[3] = {0, 0, 0}, a[3] = {0, 0, 0}, b[3], len;
    plateau_lm_sparse_pattern pat;
    int ax;
    memset(s, 0, sizeof *s);
    s->node = (plateau_index *)malloc(nv * sizeof(plateau_index));
    if (!s->node) return 0;
    for (v = 0; v < nv; v++) s->node[v] = mesh->fixed[v] ? -1 : (plateau_index)s->nfree++;
    s->row_start = (plateau_index *)malloc((s->nfree + 1) * sizeof(plateau_index));
    s->cols = (plateau_index *)malloc((s->nfree + 2 * mesh->num_edges) * sizeof(plateau_index));
    s->xy = (double *)malloc(2 * s->nfree * sizeof(double) + 1);
    if (!s->row_start || !s->cols || !s->xy) return 0;
    for (v = 0; v < nv; v++) {
        size_t e;
        if (mesh->fixed[v]) continue;
        s->row_start[k++] = (plateau_index)q;
        s->cols[q++] = s->node[v];
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed];
            if (!mesh->fixed[w]) s->cols[q++] = s->node[w];
        }
    }
    s->row_start[k] = (plateau_index)q;
    s->nnz = q;
    for (t = 0; t < mesh->num_triangles; t++) {
        double tn[3];
        plateau_triangle_normal(mesh, t, tn);
        nn[0] += tn[0];
        nn[1] += tn[1];
        nn[2] += tn[2];
    }
    len = sqrt(c2f_dot(nn, nn));
    if (len > 0) {
        nn[0] /= len;
        nn[1] /= len;
        nn[2] /= len;
    }
    ax = fabs(nn[0]) <= fabs(nn[1]) ? (fabs(nn[0]) <= fabs(nn[2]) ? 0 : 2) : (fabs(nn[1]) <= fabs(nn[2]) ? 1 : 2);
    a[ax] = 1.0;
    len = c2f_dot(a, nn);
    a[0] -= len * nn[0];
    a[1] -= len * nn[1];
    a[2] -= len * nn[2];
    len = sqrt(c2f_dot(a, a));
    a[0] /= len;
    a[1] /= len;
    a[2] /= len;
    c2f_cross(nn, a, b);
    for (v = 0; v < nv; v++)
        if (s->node[v] >= 0) {
            s->xy[2 * (size_t)s->node[v]] = c2f_dot(mesh->positions + 3 * v, a);
            s->xy[2 * (size_t)s->node[v] + 1] = c2f_dot(mesh->positions + 3 * v, b);
        }
    pat.nodes = s->nfree;
    pat.block = 1;
    pat.row_start = s->row_start;
    pat.cols = s->cols;
    if (plateau_lm_sparse_analyze(&pat, s->xy, NULL, &s->sym) != PLATEAU_LM_OK) return 0;
    return plateau_lm_sparse_factor_create(s->sym, PLATEAU_LM_SPARSE_CHOLESKY, NULL, 0, &s->fac) == PLATEAU_LM_OK;
}

C2F_FN size_t c2f_slot(const c2f_system *s, plateau_index i, plateau_index j)
{
    size_t q;
    for (q = (size_t)s->row_start[i]; q < (size_t)s->row_start[i + 1]; q++)
        if (s->cols[q] == j) return q;
    return (size_t)-1;
}

/* Gradient g (nfree) and Hessian values hv (nnz, in the pattern's order) of
 * the area in the normal coordinates t at t = 0, directions m (unit vertex
 * normals, 3 per vertex).  Returns 0 for a degenerate triangle. */
C2F_FN int c2f_assemble(const plateau_mesh *mesh, const c2f_system *s, const double *m, double *g, double *hv)
{
    size_t t;
    memset(g, 0, s->nfree * sizeof(double));
    memset(hv, 0, s->nnz * sizeof(double));
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        const double *p[3];
        double e1[3], e2[3], N[3], n[3], len, a[3][3], na[3];
        plateau_index id[3];
        int i, j;
        for (i = 0; i < 3; i++) {
            p[i] = mesh->positions + 3 * (size_t)tr[i];
            id[i] = s->node[tr[i]];
        }
        if (id[0] < 0 && id[1] < 0 && id[2] < 0) continue;
        c2f_sub(p[1], p[0], e1);
        c2f_sub(p[2], p[0], e2);
        c2f_cross(e1, e2, N);
        len = sqrt(c2f_dot(N, N));
        if (!(len > 0)) return 0;
        n[0] = N[0] / len;
        n[1] = N[1] / len;
        n[2] = N[2] / len;
        for (i = 0; i < 3; i++) {
            double e[3];
            if (id[i] < 0) {
                a[i][0] = a[i][1] = a[i][2] = na[i] = 0.0;
                continue;
            }
            c2f_sub(p[(i + 1) % 3], p[(i + 2) % 3], e);
            c2f_cross(m + 3 * (size_t)tr[i], e, a[i]);
            na[i] = c2f_dot(n, a[i]);
            g[id[i]] += 0.5 * na[i];
        }
        for (i = 0; i < 3; i++) {
            if (id[i] < 0) continue;
            for (j = 0; j < 3; j++) {
                double h;
                size_t q;
                if (id[j] < 0) continue;
                h = (c2f_dot(a[i], a[j]) - na[i] * na[j]) / (2.0 * len);
                if (j != i) {
                    double mm[3], sij = j == (i + 1) % 3 ? 1.0 : -1.0;
                    c2f_cross(m + 3 * (size_t)tr[i], m + 3 * (size_t)tr[j], mm);
                    h += 0.5 * sij * c2f_dot(n, mm);
                }
                q = c2f_slot(s, id[i], id[j]);
                if (q == (size_t)-1) return 0;
                hv[q] += h;
            }
        }
    }
    return 1;
}

/* Every triangle's unnormalised normal, for the turn test. */
C2F_FN void c2f_tri_normals(const plateau_mesh *mesh, double *tn)
{
    size_t t;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double e1[3], e2[3];
        c2f_sub(mesh->positions + 3 * (size_t)tr[1], mesh->positions + 3 * (size_t)tr[0], e1);
        c2f_sub(mesh->positions + 3 * (size_t)tr[2], mesh->positions + 3 * (size_t)tr[0], e2);
        c2f_cross(e1, e2, tn + 3 * t);
    }
}

C2F_FN int c2f_turned(const plateau_mesh *mesh, const double *tn)
{
    size_t t;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double e1[3], e2[3], c[3];
        c2f_sub(mesh->positions + 3 * (size_t)tr[1], mesh->positions + 3 * (size_t)tr[0], e1);
        c2f_sub(mesh->positions + 3 * (size_t)tr[2], mesh->positions + 3 * (size_t)tr[0], e2);
        c2f_cross(e1, e2, c);
        if (!(c2f_dot(c, tn + 3 * t) > 0)) return 1;
    }
    return 0;
}

/* Newton steps on normal motions until delta / 2 <= tol (absolute area), or
 * fixed_steps steps when fixed_steps > 0.  prev_area > 0: the previous
 * level's area, for tol = tau (prev_area - A) / 3.  Fills lev. */
C2F_FN int c2f_normal_newton(plateau_mesh *mesh, double prev_area, double tau, int fixed_steps, int chord,
                             c2f_level *lev)
{
    c2f_system s;
    size_t nv = mesh->num_vertices, v, i;
    double *m = NULL, *g = NULL, *hv = NULL, *t = NULL, *x0 = NULL, *tn = NULL, area;
    int ok = 0, step, factored = 0;
    memset(lev, 0, sizeof *lev);
    if (!c2f_system_new(mesh, &s)) goto done;
    m = (double *)malloc(3 * nv * sizeof(double));
    x0 = (double *)malloc(3 * nv * sizeof(double));
    tn = (double *)malloc(3 * mesh->num_triangles * sizeof(double));
    g = (double *)malloc((s.nfree + 1) * sizeof(double));
    t = (double *)malloc((s.nfree + 1) * sizeof(double));
    hv = (double *)malloc((s.nnz + 1) * sizeof(double));
    if (!m || !x0 || !tn || !g || !t || !hv) goto done;
    area = plateau_mesh_area(mesh);
    for (step = 0; step < C2F_MAX_STEPS; step++) {
        double mu = 0.0, delta = 0.0, st = 1.0, a1 = area, diag_mean = 0.0, tol;
        int tries;
        c2f_vertex_normals(mesh, m);
        if (!c2f_assemble(mesh, &s, m, g, hv)) break;
        tol = prev_area > 0 ? tau * (prev_area - area) / 3.0 : 0.0;
        if (chord && factored && fixed_steps <= 0) {
            /* the decrement with the last factor (a chord solve): near the
             * solution H changes little, and a small chord decrement ends the
             * level without a new factorisation */
            delta = 0.0;
            for (i = 0; i < s.nfree; i++) t[i] = -g[i];
            if (plateau_lm_sparse_solve(s.fac, 1, t, s.nfree) != PLATEAU_LM_OK) break;
            for (i = 0; i < s.nfree; i++) delta -= g[i] * t[i];
            lev->decrement = delta;
            if (delta / 2.0 <= tol) break;
            delta = 0.0;
        }
        for (i = 0; i < s.nfree; i++) diag_mean += hv[s.row_start[i]];
        diag_mean /= (double)(s.nfree ? s.nfree : 1);
        for (tries = 0; tries < 12; tries++) {
            int rc = plateau_lm_sparse_factorize(s.fac, hv, mu * diag_mean);
            lev->factorizations++;
            if (rc == PLATEAU_LM_OK) break;
            mu = mu == 0.0 ? 1e-3 : 10.0 * mu;
        }
        if (tries == 12) break;
        factored = mu == 0.0;
        for (i = 0; i < s.nfree; i++) t[i] = -g[i];
        if (plateau_lm_sparse_solve(s.fac, 1, t, s.nfree) != PLATEAU_LM_OK) break;
        for (i = 0; i < s.nfree; i++) delta -= g[i] * t[i];
        lev->decrement = delta;
        if (fixed_steps <= 0 && delta / 2.0 <= tol) break;
        /* the step, halved while it raises the area or turns a triangle */
        memcpy(x0, mesh->positions, 3 * nv * sizeof(double));
        c2f_tri_normals(mesh, tn);
        for (tries = 0; tries < 20; tries++) {
            for (v = 0; v < nv; v++)
                if (s.node[v] >= 0) {
                    double tv = st * t[s.node[v]];
                    mesh->positions[3 * v] = x0[3 * v] + tv * m[3 * v];
                    mesh->positions[3 * v + 1] = x0[3 * v + 1] + tv * m[3 * v + 1];
                    mesh->positions[3 * v + 2] = x0[3 * v + 2] + tv * m[3 * v + 2];
                }
            a1 = plateau_mesh_area(mesh);
            if (a1 <= area && !c2f_turned(mesh, tn)) break;
            st *= 0.5;
            lev->halvings++;
        }
        if (tries == 20) {
            memcpy(mesh->positions, x0, 3 * nv * sizeof(double));
            break;
        }
        area = a1;
        lev->steps++;
        if (fixed_steps > 0 && lev->steps >= fixed_steps) break;
    }
    lev->area = area;
    lev->excess_estimate = prev_area > 0 ? (prev_area - area) / 3.0 : 0.0;
    lev->interior = s.nfree;
    ok = 1;
done:
    c2f_system_free(&s);
    free(m);
    free(g);
    free(hv);
    free(t);
    free(x0);
    free(tn);
    return ok;
}

/* ---------------------------------------------------------------- derivative check */
/* c2f_assemble against central differences (step 1e-6) on a 60-point mesh
 * of the polygon after 3 Newton steps of method area, moved off the
 * surface by 0.05 sin(7 v) in z (a general point): g_i against the area's
 * differences along m_i, H's column i against g's differences.  r[0..3] =
 * largest gradient error, largest |g_i|, largest Hessian error, largest
 * |H_ij|; *nfree the free vertices.  Returns 1 when the gradient agrees to
 * 1e-7 and the Hessian to 1e-6 of their largest entries. */
C2F_FN int c2f_check_derivatives(const double *polygon, size_t mm, double r[4], size_t *nfree)
{
    double *m, *g, *hv, *hv2, *g1, *g2, *x0, h = 1e-6;
    size_t v, i, j;
    plateau_options o;
    plateau_mesh mesh;
    c2f_system s;
    int ok = 0;
    r[0] = r[1] = r[2] = r[3] = 0.0;
    *nfree = 0;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 60;
    o.max_rounds = 1;
    o.max_iterations = 3;
    if (plateau_solve(polygon, mm, &o, &mesh, NULL, NULL) != PLATEAU_OK) return 0;
    for (v = 0; v < mesh.num_vertices; v++)
        if (!mesh.fixed[v]) mesh.positions[3 * v + 2] += 0.05 * sin(7.0 * (double)v);
    if (!c2f_system_new(&mesh, &s)) {
        c2f_system_free(&s);
        plateau_mesh_free(&mesh);
        return 0;
    }
    *nfree = s.nfree;
    m = (double *)malloc(3 * mesh.num_vertices * sizeof(double));
    x0 = (double *)malloc(3 * mesh.num_vertices * sizeof(double));
    g = (double *)malloc(s.nfree * sizeof(double));
    g1 = (double *)malloc(s.nfree * sizeof(double));
    g2 = (double *)malloc(s.nfree * sizeof(double));
    hv = (double *)malloc(s.nnz * sizeof(double));
    hv2 = (double *)malloc(s.nnz * sizeof(double));
    if (m && x0 && g && g1 && g2 && hv && hv2) {
        c2f_vertex_normals(&mesh, m);
        ok = c2f_assemble(&mesh, &s, m, g, hv);
        memcpy(x0, mesh.positions, 3 * mesh.num_vertices * sizeof(double));
        for (v = 0; v < mesh.num_vertices && ok; v++) {
            double ap, am, fd;
            int k;
            if (s.node[v] < 0) continue;
            i = (size_t)s.node[v];
            for (k = 0; k < 3; k++) mesh.positions[3 * v + k] = x0[3 * v + k] + h * m[3 * v + k];
            ap = plateau_mesh_area(&mesh);
            ok = c2f_assemble(&mesh, &s, m, g1, hv2);
            for (k = 0; k < 3; k++) mesh.positions[3 * v + k] = x0[3 * v + k] - h * m[3 * v + k];
            am = plateau_mesh_area(&mesh);
            ok = ok && c2f_assemble(&mesh, &s, m, g2, hv2);
            for (k = 0; k < 3; k++) mesh.positions[3 * v + k] = x0[3 * v + k];
            fd = (ap - am) / (2 * h);
            if (fabs(fd - g[i]) > r[0]) r[0] = fabs(fd - g[i]);
            if (fabs(g[i]) > r[1]) r[1] = fabs(g[i]);
            for (j = 0; j < s.nfree; j++) {
                size_t q = c2f_slot(&s, (plateau_index)j, (plateau_index)i);
                double hfd = (g1[j] - g2[j]) / (2 * h), ha = q == (size_t)-1 ? 0.0 : hv[q];
                if (fabs(hfd - ha) > r[2]) r[2] = fabs(hfd - ha);
                if (fabs(ha) > r[3]) r[3] = fabs(ha);
            }
        }
    }
    c2f_system_free(&s);
    plateau_mesh_free(&mesh);
    free(m);
    free(x0);
    free(g);
    free(g1);
    free(g2);
    free(hv);
    free(hv2);
    return ok && r[0] < 1e-7 * r[1] && r[2] < 1e-6 * r[3];
}

/* ---------------------------------------------------------------- method paper on normal motions */
/* Newton's method for the paper's residuals H_i(x + t m) = 0 at the free
 * vertices (Cohen-Steiner-Morvan mean curvature, plateau_vertex_mean_curvature)
 * in the normal coordinates t, the tangential positions kept: n equations in
 * n unknowns, J_ij = (dH_i / dx_j) . m_j from
 * plateau_vertex_mean_curvature_gradient, on the same 1-ring pattern, by the
 * sparse LU.  A step is halved while it does not lower ||H|| or turns a
 * triangle.  At most `steps` steps; returns the final ||H||_2 in *hnorm. */
C2F_FN int c2f_paper_normal(plateau_mesh *mesh, int steps, double *hnorm, int *taken)
{
    c2f_system s;
    plateau_lm_sparse_factor *lu = NULL;
    size_t nv = mesh->num_vertices, v, i, cap = 0;
    double *m = NULL, *f = NULL, *jv = NULL, *t = NULL, *x0 = NULL, *tn = NULL, *grad = NULL, fn;
    plateau_index *verts = NULL;
    int ok = 0, step;
    *taken = 0;
    if (!c2f_system_new(mesh, &s)) goto done;
    if (plateau_lm_sparse_factor_create(s.sym, PLATEAU_LM_SPARSE_LU, NULL, 0, &lu) != PLATEAU_LM_OK) goto done;
    for (v = 0; v < nv; v++) {
        size_t c = plateau_vertex_stencil_size(mesh, v);
        if (c > cap) cap = c;
    }
    m = (double *)malloc(3 * nv * sizeof(double));
    x0 = (double *)malloc(3 * nv * sizeof(double));
    tn = (double *)malloc(3 * mesh->num_triangles * sizeof(double));
    f = (double *)malloc((s.nfree + 1) * sizeof(double));
    t = (double *)malloc((s.nfree + 1) * sizeof(double));
    jv = (double *)malloc((s.nnz + 1) * sizeof(double));
    grad = (double *)malloc(3 * cap * sizeof(double));
    verts = (plateau_index *)malloc(cap * sizeof(plateau_index));
    if (!m || !x0 || !tn || !f || !t || !jv || !grad || !verts) goto done;
    fn = 0.0;
    for (v = 0; v < nv; v++)
        if (s.node[v] >= 0) {
            double h = plateau_vertex_mean_curvature(mesh, v);
            fn += h * h;
        }
    for (step = 0; step < steps; step++) {
        double st = 1.0, fn1 = fn;
        int tries;
        c2f_vertex_normals(mesh, m);
        memset(jv, 0, s.nnz * sizeof(double));
        for (v = 0; v < nv; v++) {
            size_t count, k;
            double h;
            plateau_index r = s.node[v];
            if (r < 0) continue;
            if (plateau_vertex_mean_curvature_gradient(mesh, v, cap, verts, grad, &count, &h) != PLATEAU_OK) goto done;
            f[r] = h;
            for (k = 0; k < count; k++) {
                plateau_index c = s.node[verts[k]];
                size_t q;
                if (c < 0) continue;
                q = c2f_slot(&s, r, c);
                if (q == (size_t)-1) continue; /* outside the 1-ring: not in the pattern */
                jv[q] += c2f_dot(grad + 3 * k, m + 3 * (size_t)verts[k]);
            }
        }
        if (plateau_lm_sparse_factorize(lu, jv, 0.0) != PLATEAU_LM_OK) break;
        for (i = 0; i < s.nfree; i++) t[i] = -f[i];
        if (plateau_lm_sparse_solve(lu, 1, t, s.nfree) != PLATEAU_LM_OK) break;
        memcpy(x0, mesh->positions, 3 * nv * sizeof(double));
        c2f_tri_normals(mesh, tn);
        for (tries = 0; tries < 20; tries++) {
            for (v = 0; v < nv; v++)
                if (s.node[v] >= 0) {
                    double tv = st * t[s.node[v]];
                    mesh->positions[3 * v] = x0[3 * v] + tv * m[3 * v];
                    mesh->positions[3 * v + 1] = x0[3 * v + 1] + tv * m[3 * v + 1];
                    mesh->positions[3 * v + 2] = x0[3 * v + 2] + tv * m[3 * v + 2];
                }
            fn1 = 0.0;
            for (v = 0; v < nv; v++)
                if (s.node[v] >= 0) {
                    double h = plateau_vertex_mean_curvature(mesh, v);
                    fn1 += h * h;
                }
            if (fn1 < fn && !c2f_turned(mesh, tn)) break;
            st *= 0.5;
        }
        if (tries == 20) {
            memcpy(mesh->positions, x0, 3 * nv * sizeof(double));
            break;
        }
        fn = fn1;
        (*taken)++;
    }
    *hnorm = sqrt(fn);
    ok = 1;
done:
    plateau_lm_sparse_factor_free(lu);
    c2f_system_free(&s);
    free(m);
    free(x0);
    free(tn);
    free(f);
    free(t);
    free(jv);
    free(grad);
    free(verts);
    return ok;
}

/* ---------------------------------------------------------------- area-lowering flips */
/* One sweep over the interior edges in index order: edge (a, b) with
 * triangles (a, b, c) and (b, a, d) becomes (a, d, c), (d, b, c) when that
 * lowers the area by more than 1e-12 of the pair's, c and d are not
 * joined, and neither new triangle faces against either old one (no fold).
 * A triangle touched by a flip is left alone for the rest of the sweep,
 * and so is an edge whose ends both got a new edge in it (the adjacency,
 * and with it the test whether c and d are joined, is rebuilt after it).  Returns the flips, or -1 when
 * the adjacency could not be rebuilt. */
C2F_FN long c2f_area_flips(plateau_mesh *mesh)
{
    size_t e, nt = mesh->num_triangles, nv = mesh->num_vertices;
    unsigned char *tt = (unsigned char *)calloc(nt + nv, 1), *tv = tt + nt;
    long flips = 0;
    if (!tt) return -1;
    for (e = 0; e < mesh->num_edges; e++) {
        plateau_index t1 = mesh->edge_triangles[2 * e], t2 = mesh->edge_triangles[2 * e + 1];
        plateau_index a = mesh->edges[2 * e], b = mesh->edges[2 * e + 1], c = -1, d = -1, *T1, *T2;
        const double *pa, *pb, *pc, *pd;
        double n1[3], n2[3], m1[3], m2[3], u[3], w[3], old, nw;
        size_t q;
        int k;
        if (t1 < 0 || t2 < 0 || tt[t1] || tt[t2]) continue;
        T1 = mesh->triangles + 3 * (size_t)t1;
        T2 = mesh->triangles + 3 * (size_t)t2;
        for (k = 0; k < 3; k++) {
            if (T1[k] != a && T1[k] != b) c = T1[k];
            if (T2[k] != a && T2[k] != b) d = T2[k];
        }
        if (c < 0 || d < 0 || c == d || (tv[c] && tv[d])) continue;
        for (q = mesh->vertex_edge_start[c]; q < mesh->vertex_edge_start[c + 1]; q++) {
            size_t ed = (size_t)mesh->vertex_edges[q];
            if (mesh->edges[2 * ed] == d || mesh->edges[2 * ed + 1] == d) break;
        }
        if (q < mesh->vertex_edge_start[c + 1]) continue;
        pa = mesh->positions + 3 * (size_t)a;
        pb = mesh->positions + 3 * (size_t)b;
        pc = mesh->positions + 3 * (size_t)c;
        pd = mesh->positions + 3 * (size_t)d;
        c2f_sub(pb, pa, u); c2f_sub(pc, pa, w); c2f_cross(u, w, n1);
        c2f_sub(pa, pb, u); c2f_sub(pd, pb, w); c2f_cross(u, w, n2);
        c2f_sub(pd, pa, u); c2f_sub(pc, pa, w); c2f_cross(u, w, m1);
        c2f_sub(pb, pd, u); c2f_sub(pc, pd, w); c2f_cross(u, w, m2);
        old = sqrt(c2f_dot(n1, n1)) + sqrt(c2f_dot(n2, n2));
        nw = sqrt(c2f_dot(m1, m1)) + sqrt(c2f_dot(m2, m2));
        if (!(nw < old * (1.0 - 1e-12))) continue;
        if (!(c2f_dot(m1, n1) > 0 && c2f_dot(m1, n2) > 0 && c2f_dot(m2, n1) > 0 && c2f_dot(m2, n2) > 0)) continue;
        /* a triangle's winding starts anywhere: write the new ones whole */
        T1[0] = a; T1[1] = d; T1[2] = c;
        T2[0] = d; T2[1] = b; T2[2] = c;
        tt[t1] = tt[t2] = 1;
        tv[c] = tv[d] = 1;
        flips++;
    }
    free(tt);
    if (flips > 0 && plateau_mesh_build_adjacency(mesh, NULL) != PLATEAU_OK) return -1;
    return flips;
}

/* ---------------------------------------------------------------- 4. tangential relaxation */
/* sweeps of d_v = -P_v g_v / w_v for every free vertex at once (P_v the
 * projection on v's tangent plane, g_v the area gradient, w_v the diagonal
 * of the cotangent Laplacian, cotangents clipped at 0), the step halved
 * while the area rises or a triangle turns.  Returns the area. */
C2F_FN double c2f_tangential(plateau_mesh *mesh, int sweeps)
{
    size_t nv = mesh->num_vertices, nt = mesh->num_triangles, v, t;
    double *g = (double *)malloc(3 * nv * sizeof(double)), *w = (double *)malloc(nv * sizeof(double));
    double *m = (double *)malloc(3 * nv * sizeof(double)), *x0 = (double *)malloc(3 * nv * sizeof(double));
    double *tn = (double *)malloc(3 * nt * sizeof(double));
    double area = plateau_mesh_area(mesh), st = 1.0;
    int sw;
    if (!g || !w || !m || !x0 || !tn) goto done;
    for (sw = 0; sw < sweeps; sw++) {
        double a1 = area;
        int tries;
        plateau_mesh_area_gradient(mesh, g);
        c2f_vertex_normals(mesh, m);
        memset(w, 0, nv * sizeof(double));
        for (t = 0; t < nt; t++) {
            const plateau_index *tr = mesh->triangles + 3 * t;
            int i;
            for (i = 0; i < 3; i++) {
                const double *p = mesh->positions + 3 * (size_t)tr[i];
                double u[3], q[3], c[3], cot;
                c2f_sub(mesh->positions + 3 * (size_t)tr[(i + 1) % 3], p, u);
                c2f_sub(mesh->positions + 3 * (size_t)tr[(i + 2) % 3], p, q);
                c2f_cross(u, q, c);
                cot = c2f_dot(u, q) / sqrt(c2f_dot(c, c));
                if (!(cot > 0)) cot = 0;
                /* the corner i's cotangent weighs the opposite edge */
                w[tr[(i + 1) % 3]] += 0.5 * cot;
                w[tr[(i + 2) % 3]] += 0.5 * cot;
            }
        }
        memcpy(x0, mesh->positions, 3 * nv * sizeof(double));
        c2f_tri_normals(mesh, tn);
        for (tries = 0; tries < 20; tries++) {
            for (v = 0; v < nv; v++) {
                double *gv = g + 3 * v, *mv = m + 3 * v, gn, d[3];
                int k;
                if (mesh->fixed[v] || !(w[v] > 0)) continue;
                gn = c2f_dot(gv, mv);
                for (k = 0; k < 3; k++) d[k] = -(gv[k] - gn * mv[k]) / w[v];
                for (k = 0; k < 3; k++) mesh->positions[3 * v + k] = x0[3 * v + k] + st * d[k];
            }
            a1 = plateau_mesh_area(mesh);
            if (a1 < area && !c2f_turned(mesh, tn)) break;
            st *= 0.5;
        }
        if (tries == 20) {
            memcpy(mesh->positions, x0, 3 * nv * sizeof(double));
            break;
        }
        area = a1;
        if (st < 1.0) st *= 2.0;
    }
done:
    free(g);
    free(w);
    free(m);
    free(x0);
    free(tn);
    return area;
}

/* ---------------------------------------------------------------- the driver */
C2F_FN double c2f_cpu(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* The coarse interior count whose L subdivisions have n interior vertices,
 * for a boundary of m vertices (see c2f_solve). */
C2F_FN double c2f_coarse_count(size_t n, size_t m, int levels)
{
    double p4 = pow(4.0, levels), p2 = pow(2.0, levels);
    return ((double)n + (p4 - 1.0) - (double)m * (p4 - p2) / 2.0) / p4;
}

/* Coarse to fine: polygon (m vertices) to a mesh of about n interior
 * vertices.  Returns a plateau_result; *mesh is the caller's (free it with
 * plateau_mesh_free). */
C2F_FN int c2f_solve(const double *polygon, size_t m, size_t n, const c2f_params *prm, plateau_mesh *mesh,
                     c2f_stats *st)
{
    plateau_options o;
    plateau_report rep;
    size_t cmin = prm->coarse_min ? prm->coarse_min : C2F_COARSE_MIN, n0 = n;
    double tau = prm->tau != 0.0 ? prm->tau : C2F_TAU, prev, c0 = c2f_cpu();
    int levels = 0, k, rc;
    memset(st, 0, sizeof *st);
    /* L subdivisions of a disk with I interior and B boundary vertices give
     * I_L = 4^L I + B (4^L - 2^L) / 2 - (4^L - 1) interior vertices (each
     * level: I' = 4 I + B - 3, B' = 2 B, by Euler's formula); the coarse
     * count I_0(L) solves that for I_L = n with B = m (the boundary points
     * the coarse seeding adds make the result somewhat larger), and L is
     * the largest with I_0(L) >= cmin */
    if (prm->levels > 0) levels = prm->levels;
    else
        while (levels < 12 && c2f_coarse_count(n, m, levels + 1) >= (double)cmin) levels++;
    {
        double i0 = c2f_coarse_count(n, m, levels);
        n0 = i0 < 4.0 ? 4 : (size_t)(i0 + 0.5);
    }
    memset(&o, 0, sizeof o);
    o.method = prm->paper == 1 ? PLATEAU_METHOD_PAPER : PLATEAU_METHOD_AREA;
    o.interior_points = n0;
    o.seeding = PLATEAU_SEEDING_QUALITY;
    o.refine_boundary = PLATEAU_ON;
    o.linear_solver = prm->coarse_solver ? prm->coarse_solver : PLATEAU_LINEAR_SPARSE;
    o.area_tolerance = prm->coarse_tol;
    o.max_rounds = prm->plateau_rounds || o.method != PLATEAU_METHOD_AREA ? prm->coarse_rounds : 1;
    rc = plateau_solve(polygon, m, &o, mesh, &rep, NULL);
    if (rc != PLATEAU_OK) return rc;
    if (!prm->plateau_rounds && o.method == PLATEAU_METHOD_AREA) {
        /* rounds of plain area-lowering flips and a re-solve (plateau_solve
         * flips with vertex relaxation below PLATEAU_SPARSE_THRESHOLD free
         * vertices, 90 % of its time on small meshes) */
        int r;
        for (r = 0; r < 8; r++) {
            long f = c2f_area_flips(mesh);
            plateau_report rr;
            if (f < 0) return PLATEAU_ERR_OUT_OF_MEMORY;
            if (f == 0) break;
            rc = plateau_mesh_minimize(mesh, &o, &rr, NULL);
            if (rc != PLATEAU_OK) return rc;
            rep.area = rr.area;
        }
    }
    st->coarse_cpu = c2f_cpu() - c0;
    st->coarse_interior = rep.interior_points;
    prev = rep.area;
    for (k = 0; k < levels && k < 12; k++) {
        plateau_mesh fine;
        c2f_level *lev = &st->level[k];
        double c1 = c2f_cpu();
        memset(&fine, 0, sizeof fine);
        rc = c2f_subdivide(mesh, !prm->chord_midpoints, &fine);
        plateau_mesh_free(mesh);
        *mesh = fine;
        if (rc != PLATEAU_OK) return rc;
        if (prm->paper == 1 || (prm->paper == 2 && k == levels - 1)) {
            /* method paper's square system from the subdivided mesh */
            plateau_options po;
            plateau_report pr;
            memset(&po, 0, sizeof po);
            memset(&pr, 0, sizeof pr);
            po.method = PLATEAU_METHOD_PAPER;
            po.paper_presolve = PLATEAU_OFF; /* the subdivided mesh is the start */
            po.max_rounds = prm->paper_rounds > 0 ? prm->paper_rounds : 1;
            po.progress = prm->progress;
            po.linear_solver = PLATEAU_LINEAR_SPARSE;
            po.max_iterations = prm->paper_iterations;
            if (prm->paper == 2 &&
                !c2f_normal_newton(mesh, prev, tau > 0 ? tau : 0.0, tau < 0 ? (int)-tau : 0, !prm->no_chord, lev))
                return PLATEAU_ERR_SOLVER;
            rc = plateau_mesh_minimize(mesh, &po, &pr, NULL);
            if (rc != PLATEAU_OK) return rc;
            lev->steps = (int)pr.iterations;
            lev->area = pr.area;
            lev->interior = pr.interior_points;
            lev->excess_estimate = (prev - pr.area) / 3.0;
            lev->halvings = (int)pr.defects;
        } else if (prm->full_newton > 0) {
            plateau_options fo;
            plateau_report fr;
            memset(&fo, 0, sizeof fo);
            memset(&fr, 0, sizeof fr);
            fo.method = PLATEAU_METHOD_AREA;
            fo.linear_solver = PLATEAU_LINEAR_SPARSE;
            fo.max_rounds = 1;
            fo.max_iterations = prm->full_newton;
            fo.area_warm_start = PLATEAU_OFF;
            rc = plateau_mesh_minimize(mesh, &fo, &fr, NULL);
            if (rc != PLATEAU_OK) return rc;
            lev->steps = (int)fr.iterations;
            lev->area = fr.area;
            lev->interior = fr.interior_points;
            lev->excess_estimate = (prev - fr.area) / 3.0;
        } else if (!c2f_normal_newton(mesh, prev, tau > 0 ? tau : 0.0, tau < 0 ? (int)-tau : 0, !prm->no_chord, lev))
            return PLATEAU_ERR_SOLVER;
        if (prm->paper == 3 && k == levels - 1) {
            /* method paper's H_i = 0 in normal coordinates, from the area level */
            double hn;
            int taken;
            if (!c2f_paper_normal(mesh, prm->paper_iterations > 0 ? prm->paper_iterations : 3, &hn, &taken))
                return PLATEAU_ERR_SOLVER;
            lev->steps += taken;
            lev->area = plateau_mesh_area(mesh);
            lev->decrement = hn;
        }
        if (prm->tangential > 0) {
            c2f_level l2;
            double at = c2f_tangential(mesh, prm->tangential);
            lev->tangential_gain = lev->area - at;
            if (!c2f_normal_newton(mesh, prev, tau > 0 ? tau : 0.0, tau < 0 ? (int)-tau : 0, !prm->no_chord, &l2))
                return PLATEAU_ERR_SOLVER;
            lev->steps += l2.steps;
            lev->factorizations += l2.factorizations;
            lev->area = l2.area;
            lev->excess_estimate = l2.excess_estimate;
        }
        prev = lev->area;
        lev->cpu = c2f_cpu() - c1;
        st->levels = k + 1;
    }
    {
        /* the final check plateau_solve makes (step 8) */
        plateau_quality q;
        double c1 = c2f_cpu();
        rc = plateau_mesh_check(mesh, &q, NULL);
        st->defects = q.defects;
        st->check_cpu = c2f_cpu() - c1;
    }
    return rc;
}

#endif
