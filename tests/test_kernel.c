/* test_kernel.c - the triangle-mesh geometry kernel of plateau.h:
 * adjacency and its errors, areas, the signed dihedral angle, the
 * Cohen-Steiner-Morvan mean curvature H_i, the Meyer et al. mean curvature
 * vector, the tangential residual, the area gradient, the area Hessian on
 * normal motions and the assembled Jacobian.  Every derivative is checked
 * against central differences; H_i is checked on exact surfaces (plane, sphere, cylinder, catenoid,
 * helicoid, Enneper, Scherk) and its measured convergence is printed. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

#ifdef PLATEAU_TEST_SANITIZED
#define GEO_HEAVY 0
#else
#define GEO_HEAVY 1
#endif

static const double geo_pi = 3.14159265358979323846;

/* ---- a small deterministic generator for the tests ---- */
typedef struct geo_rng { uint64_t s; } geo_rng;
static double geo_uniform(geo_rng *r)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

/* ---- mesh builders ---- */
typedef void (*geo_surface)(double u, double v, const double *param, double *xyz);

/* (nu + 1) x (nv + 1) grid over [u0, u1] x [v0, v1], triangles
 * counter-clockwise in (u, v), diagonals alternating (or all parallel when
 * geo_parallel_diagonals is set); interior (u, v) jittered by
 * jitter * cell size.  Border vertices are fixed. */
static int geo_parallel_diagonals;
static int geo_grid(plateau_mesh *mesh, geo_surface f, const double *param, double u0,
                    double u1, double v0, double v1, int nu, int nv, double jitter,
                    geo_rng *rng)
{
    size_t nvert = (size_t)(nu + 1) * (size_t)(nv + 1), ntri = 2 * (size_t)nu * (size_t)nv;
    double *pos = (double *)malloc(3 * nvert * sizeof(double));
    plateau_index *tri = (plateau_index *)malloc(3 * ntri * sizeof(plateau_index));
    size_t t = 0;
    int i, j, rc;
    for (j = 0; j <= nv; j++) {
        for (i = 0; i <= nu; i++) {
            double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv;
            if (jitter > 0.0 && i > 0 && i < nu && j > 0 && j < nv) {
                u += jitter * (u1 - u0) / nu * (geo_uniform(rng) - 0.5);
                v += jitter * (v1 - v0) / nv * (geo_uniform(rng) - 0.5);
            }
            f(u, v, param, pos + 3 * (size_t)(j * (nu + 1) + i));
        }
    }
    for (j = 0; j < nv; j++) {
        for (i = 0; i < nu; i++) {
            plateau_index a = (plateau_index)(j * (nu + 1) + i), b = a + 1;
            plateau_index c = a + (plateau_index)(nu + 1), d = c + 1;
            if (geo_parallel_diagonals || (i + j) % 2 == 0) {
                tri[3 * t] = a; tri[3 * t + 1] = b; tri[3 * t + 2] = d; t++;
                tri[3 * t] = a; tri[3 * t + 1] = d; tri[3 * t + 2] = c; t++;
            } else {
                tri[3 * t] = a; tri[3 * t + 1] = b; tri[3 * t + 2] = c; t++;
                tri[3 * t] = b; tri[3 * t + 1] = d; tri[3 * t + 2] = c; t++;
            }
        }
    }
    rc = plateau_mesh_create(pos, nvert, NULL, tri, ntri, NULL, mesh, NULL);
    free(pos);
    free(tri);
    return rc;
}

static void geo_plane(double u, double v, const double *p, double *x)
{
    (void)p;
    /* a tilted plane */
    x[0] = u; x[1] = v; x[2] = 0.3 * u - 0.7 * v + 0.1;
}
static void geo_bumpy(double u, double v, const double *p, double *x)
{
    x[0] = u; x[1] = v; x[2] = p[0] * (sin(2.1 * u + 0.3) * cos(1.7 * v) + 0.5 * u * v);
}
static void geo_cylinder(double u, double v, const double *p, double *x)
{
    x[0] = p[0] * cos(u); x[1] = v; x[2] = p[0] * sin(u);
}
static void geo_catenoid(double u, double v, const double *p, double *x)
{
    x[0] = p[0] * cos(u) * cosh(v); x[1] = p[0] * v; x[2] = p[0] * sin(u) * cosh(v);
}
static void geo_helicoid(double u, double v, const double *p, double *x)
{
    x[0] = u * cos(v); x[1] = u * sin(v); x[2] = p[0] * v;
}
/* the helicoid on a sheared grid, so that no grid line is a ruling */
static void geo_helicoid_sheared(double u, double v, const double *p, double *x)
{
    geo_helicoid(u + 0.6 * v, v, p, x);
}
static void geo_enneper(double u, double v, const double *p, double *x)
{
    (void)p;
    x[0] = u - u * u * u / 3.0 + u * v * v;
    x[1] = v - v * v * v / 3.0 + v * u * u;
    x[2] = u * u - v * v;
}
static void geo_scherk(double u, double v, const double *p, double *x)
{
    x[0] = u; x[1] = v; x[2] = log(cos(p[0] * v) / cos(p[0] * u)) / p[0];
}

/* Icosphere of radius r: the icosahedron subdivided `level` times (each
 * triangle into four, new vertices pushed onto the sphere). */
static int geo_icosphere(plateau_mesh *out, int level, double r)
{
    static const plateau_index ico[60] = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11,
                                          1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                                          3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9,
                                          4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    double g = (1.0 + sqrt(5.0)) / 2.0;
    double base[36] = {-1, 0, 0, 1, 0, 0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0,
                       0, -1, 0, 0, 1, 0, 0, 0, -1, 0, 0, 1, 0, 0, -1, 0, 0, 1};
    plateau_mesh cur;
    int l, k, rc;
    size_t i;
    for (i = 0; i < 12; i++) {
        double *p = base + 3 * i;
        double s;
        /* (-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), then cyclic */
        if (i < 4) { p[1] = (i < 2) ? g : -g; }
        else if (i < 8) { p[2] = (i < 6) ? g : -g; }
        else { p[0] = (i < 10) ? g : -g; }
        s = r / sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        p[0] *= s; p[1] *= s; p[2] *= s;
    }
    rc = plateau_mesh_create(base, 12, NULL, ico, 20, NULL, &cur, NULL);
    if (rc != PLATEAU_OK) return rc;
    for (l = 0; l < level; l++) {
        size_t nv = cur.num_vertices + cur.num_edges, nt = 4 * cur.num_triangles;
        double *pos = (double *)malloc(3 * nv * sizeof(double));
        plateau_index *tri = (plateau_index *)malloc(3 * nt * sizeof(plateau_index));
        plateau_mesh next;
        memcpy(pos, cur.positions, 3 * cur.num_vertices * sizeof(double));
        for (i = 0; i < cur.num_edges; i++) {
            const double *a = cur.positions + 3 * cur.edges[2 * i];
            const double *b = cur.positions + 3 * cur.edges[2 * i + 1];
            double *m = pos + 3 * (cur.num_vertices + i), s;
            for (k = 0; k < 3; k++) m[k] = 0.5 * (a[k] + b[k]);
            s = r / sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            for (k = 0; k < 3; k++) m[k] *= s;
        }
        for (i = 0; i < cur.num_triangles; i++) {
            const plateau_index *t = cur.triangles + 3 * i;
            plateau_index m0 = (plateau_index)cur.num_vertices + cur.triangle_edges[3 * i];
            plateau_index m1 = (plateau_index)cur.num_vertices + cur.triangle_edges[3 * i + 1];
            plateau_index m2 = (plateau_index)cur.num_vertices + cur.triangle_edges[3 * i + 2];
            plateau_index q[12];
            q[0] = t[0]; q[1] = m0; q[2] = m2;
            q[3] = t[1]; q[4] = m1; q[5] = m0;
            q[6] = t[2]; q[7] = m2; q[8] = m1;
            q[9] = m0; q[10] = m1; q[11] = m2;
            memcpy(tri + 12 * i, q, sizeof q);
        }
        rc = plateau_mesh_create(pos, nv, NULL, tri, nt, NULL, &next, NULL);
        free(pos);
        free(tri);
        plateau_mesh_free(&cur);
        if (rc != PLATEAU_OK) return rc;
        cur = next;
    }
    *out = cur;
    return PLATEAU_OK;
}

/* ---- adjacency ---- */
static void test_adjacency(void)
{
    plateau_mesh m;
    double p = 0.3;
    size_t t, e, v, boundary_edges = 0, nfixed = 0;
    CHECK_EQ_INT(geo_grid(&m, geo_bumpy, &p, -1, 1, -1, 1, 5, 4, 0.0, NULL), PLATEAU_OK);
    CHECK_EQ_INT(m.num_vertices, 30);
    CHECK_EQ_INT(m.num_triangles, 40);
    /* Euler characteristic of a disk: V - E + F = 1 */
    CHECK_EQ_INT((long)m.num_vertices - (long)m.num_edges + (long)m.num_triangles, 1);
    for (t = 0; t < m.num_triangles; t++) {
        int k;
        for (k = 0; k < 3; k++) {
            plateau_index a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3];
            plateau_index nb = m.neighbors[3 * t + k];
            plateau_index ed = m.triangle_edges[3 * t + k];
            CHECK((m.edges[2 * ed] == a && m.edges[2 * ed + 1] == b) ||
                  (m.edges[2 * ed] == b && m.edges[2 * ed + 1] == a));
            if (nb >= 0) {
                int j, found = 0;
                for (j = 0; j < 3; j++)
                    if (m.triangles[3 * nb + j] == b && m.triangles[3 * nb + (j + 1) % 3] == a &&
                        m.neighbors[3 * nb + j] == (plateau_index)t)
                        found = 1;
                CHECK(found);
            }
        }
    }
    for (e = 0; e < m.num_edges; e++) {
        plateau_index t0 = m.edge_triangles[2 * e], t1 = m.edge_triangles[2 * e + 1];
        int k, ok = 0;
        for (k = 0; k < 3; k++)
            if (m.triangles[3 * t0 + k] == m.edges[2 * e] &&
                m.triangles[3 * t0 + (k + 1) % 3] == m.edges[2 * e + 1])
                ok = 1;
        CHECK(ok);
        if (t1 < 0) boundary_edges++;
    }
    CHECK_EQ_INT(boundary_edges, 18);
    for (v = 0; v < m.num_vertices; v++) nfixed += m.fixed[v];
    CHECK_EQ_INT(nfixed, 18);
    CHECK_EQ_INT(m.vertex_edge_start[m.num_vertices], 2 * m.num_edges);
    CHECK_EQ_INT(m.vertex_triangle_start[m.num_vertices], 3 * m.num_triangles);
    /* rebuilding gives the same adjacency */
    {
        plateau_index e0 = m.edges[0], e1 = m.edges[1];
        size_t ne = m.num_edges;
        CHECK_EQ_INT(plateau_mesh_build_adjacency(&m, NULL), PLATEAU_OK);
        CHECK_EQ_INT(m.num_edges, ne);
        CHECK(m.edges[0] == e0 && m.edges[1] == e1);
    }
    plateau_mesh_free(&m);
    CHECK(m.positions == NULL && m.edges == NULL && m.num_vertices == 0);
    plateau_mesh_free(&m); /* an all-zero mesh is accepted */
    plateau_mesh_free(NULL);
}

/* ---- every error code of mesh creation ---- */
static void test_errors(void)
{
    /* a square split in two, plus a spare vertex */
    double pos[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 2, 0};
    plateau_index ok_tri[6] = {0, 1, 2, 0, 2, 3};
    plateau_index range[6] = {0, 1, 2, 0, 2, 5};
    plateau_index neg[6] = {0, 1, 2, -1, 2, 3};
    plateau_index rep[6] = {0, 1, 2, 0, 3, 3};
    plateau_index orient[6] = {0, 1, 2, 0, 3, 2};
    plateau_index nonman[9] = {0, 1, 2, 0, 2, 3, 2, 0, 4};
    plateau_mesh m;
    plateau_error err;
    plateau_allocator half = {countalloc_alloc, NULL, NULL};
    double bad[15];

    memset(&m, 0xff, sizeof m); /* garbage in: must be zeroed on error */
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, range, 2, NULL, &m, &err), PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(err.index, 1);
    CHECK(m.positions == NULL && m.num_vertices == 0);
    CHECK(strlen(err.message) > 0);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, neg, 2, NULL, &m, &err), PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(err.index, 1);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, rep, 2, NULL, &m, &err),
                 PLATEAU_ERR_DEGENERATE_TRIANGLE);
    CHECK_EQ_INT(err.index, 1);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, orient, 2, NULL, &m, &err),
                 PLATEAU_ERR_ORIENTATION);
    CHECK_EQ_INT(err.index, 1);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, nonman, 3, NULL, &m, &err),
                 PLATEAU_ERR_NON_MANIFOLD);
    CHECK_EQ_INT(err.index, 2);
    memcpy(bad, pos, sizeof bad);
    bad[7] = NAN;
    CHECK_EQ_INT(plateau_mesh_create(bad, 5, NULL, ok_tri, 2, NULL, &m, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 2);
    bad[7] = INFINITY;
    CHECK_EQ_INT(plateau_mesh_create(bad, 5, NULL, ok_tri, 2, NULL, &m, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(plateau_mesh_create(NULL, 5, NULL, ok_tri, 2, NULL, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, NULL, 2, NULL, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, 2, NULL, ok_tri, 2, NULL, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, 0, NULL, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, 2, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, 2, &half, &m, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_create(pos, (size_t)PLATEAU_INDEX_MAX + 1, NULL, ok_tri, 2, NULL, &m, &err),
                 PLATEAU_ERR_OVERFLOW);
    CHECK_EQ_INT(plateau_mesh_create(pos, (size_t)-1 / 8, NULL, ok_tri, 2, NULL, &m, &err),
                 PLATEAU_ERR_OVERFLOW);
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, (size_t)PLATEAU_INDEX_MAX, NULL, &m, &err),
                 PLATEAU_ERR_OVERFLOW);
    /* err may be NULL */
    CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, orient, 2, NULL, &m, NULL), PLATEAU_ERR_ORIENTATION);
    /* success, with explicit fixed flags and the unused vertex 4 */
    {
        unsigned char fx[5] = {1, 0, 1, 0, 7};
        CHECK_EQ_INT(plateau_mesh_create(pos, 5, fx, ok_tri, 2, NULL, &m, &err), PLATEAU_OK);
        CHECK_EQ_INT(err.code, PLATEAU_OK);
        CHECK(m.fixed[0] == 1 && m.fixed[1] == 0 && m.fixed[4] == 1);
        CHECK_NEAR(plateau_mesh_area(&m), 1.0, 1e-15);
        CHECK_NEAR(plateau_vertex_area(&m, 0), 1.0 / 3.0, 1e-15);
        CHECK_NEAR(plateau_vertex_area(&m, 4), 0.0, 0.0);
        CHECK_NEAR(plateau_vertex_mean_curvature(&m, 4), 0.0, 0.0);
        CHECK_EQ_INT(plateau_vertex_stencil_size(&m, 4), 1);
        /* capacity errors of the sparse rows say how much is needed */
        {
            plateau_index vv[2];
            double gg[12];
            size_t cnt = 0;
            CHECK_EQ_INT(plateau_vertex_mean_curvature_gradient(&m, 0, 2, vv, gg, &cnt, NULL),
                         PLATEAU_ERR_ARGUMENT);
            CHECK_EQ_INT(cnt, 4);
            CHECK_EQ_INT(plateau_vertex_tangential_gradient(&m, 0, 1.0, 2, vv, gg, &cnt, NULL),
                         PLATEAU_ERR_ARGUMENT);
            CHECK_EQ_INT(plateau_vertex_mean_curvature_gradient(&m, 9, 2, vv, gg, &cnt, NULL),
                         PLATEAU_ERR_ARGUMENT);
        }
        /* an orientation error while rebuilding frees the adjacency */
        m.triangles[4] = 3;
        m.triangles[5] = 2;
        CHECK_EQ_INT(plateau_mesh_build_adjacency(&m, &err), PLATEAU_ERR_ORIENTATION);
        CHECK(m.edges == NULL && m.num_edges == 0);
        plateau_mesh_free(&m);
    }
    CHECK_EQ_INT(plateau_mesh_build_adjacency(NULL, &err), PLATEAU_ERR_ARGUMENT);
    /* every allocation failure: OUT_OF_MEMORY, nothing leaked, context kept */
    {
        long k, total;
        countalloc ca;
        plateau_allocator a;
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, 2, &a, &m, &err), PLATEAU_OK);
        plateau_mesh_free(&m);
        total = ca.calls;
        CHECK(total > 5);
        CHECK_EQ_INT(ca.live, 0);
        for (k = 1; k <= total; k++) {
            countalloc_init(&ca, k);
            a = countalloc_allocator(&ca);
            CHECK_EQ_INT(plateau_mesh_create(pos, 5, NULL, ok_tri, 2, &a, &m, &err),
                         PLATEAU_ERR_OUT_OF_MEMORY);
            CHECK_EQ_INT(ca.live, 0);
            CHECK_EQ_INT(ca.bad, 0);
        }
        CHECK_EQ_INT(countalloc_lost_context, 0);
    }
}

/* ---- finite-difference checks ---- */
/* largest |analytic - central difference| / max(largest |analytic| of the
 * row, floor) over everything checked; printed at the end */
static double geo_worst_beta, geo_worst_h, geo_worst_tan, geo_worst_area, geo_worst_jac;
static double geo_worst_beta_flat, geo_worst_h_flat;

static double geo_rel(double a, double b, double scale)
{
    return fabs(a - b) / scale;
}

/* random bumpy or nearly flat patch, with jittered vertices moved off the surface */
static void geo_random_mesh(plateau_mesh *m, geo_rng *rng, double amplitude, int n)
{
    double p = amplitude;
    size_t v;
    CHECK_EQ_INT(geo_grid(m, geo_bumpy, &p, -1, 1, -1, 1, n, n, 0.6, rng), PLATEAU_OK);
    for (v = 0; v < m->num_vertices; v++)
        if (!m->fixed[v]) m->positions[3 * v + 2] += amplitude * 0.2 * (geo_uniform(rng) - 0.5);
}

static void geo_fd_mesh(plateau_mesh *m, double *worst_beta, double *worst_h, double *worst_tan,
                        double *worst_area, double *worst_jac)
{
    const double step = 1e-6;
    size_t e, v, k;
    int q, c;
    plateau_index vv[64];
    double gg[6 * 64];
    /* dihedral angle */
    for (e = 0; e < m->num_edges; e++) {
        plateau_index ev[4];
        double g[12], scale = 0.0, beta;
        beta = plateau_edge_dihedral_gradient(m, e, ev, g);
        CHECK_NEAR(beta, plateau_edge_dihedral(m, e), 0.0);
        if (ev[2] < 0) {
            for (k = 0; k < 12; k++) CHECK(g[k] == 0.0);
            continue;
        }
        for (k = 0; k < 12; k++) scale = fmax(scale, fabs(g[k]));
        for (q = 0; q < 4; q++) {
            for (c = 0; c < 3; c++) {
                double *x = m->positions + 3 * (size_t)ev[q] + c, x0 = *x, fp, fm, r;
                *x = x0 + step; fp = plateau_edge_dihedral(m, e);
                *x = x0 - step; fm = plateau_edge_dihedral(m, e);
                *x = x0;
                r = geo_rel(g[3 * q + c], (fp - fm) / (2 * step), scale);
                if (r > *worst_beta) *worst_beta = r;
            }
        }
    }
    /* H_i and the tangential residual at every vertex */
    for (v = 0; v < m->num_vertices; v++) {
        size_t cnt;
        double h, scale = 0.0;
        CHECK_EQ_INT(plateau_vertex_mean_curvature_gradient(m, v, 64, vv, gg, &cnt, &h), PLATEAU_OK);
        CHECK_NEAR(h, plateau_vertex_mean_curvature(m, v), 1e-12 * (1 + fabs(h)));
        for (k = 0; k < 3 * cnt; k++) scale = fmax(scale, fabs(gg[k]));
        for (k = 0; k < cnt; k++) {
            for (c = 0; c < 3; c++) {
                double *x = m->positions + 3 * (size_t)vv[k] + c, x0 = *x, fp, fm, r;
                *x = x0 + step; fp = plateau_vertex_mean_curvature(m, v);
                *x = x0 - step; fm = plateau_vertex_mean_curvature(m, v);
                *x = x0;
                r = geo_rel(gg[3 * k + c], (fp - fm) / (2 * step), scale);
                if (r > *worst_h) *worst_h = r;
            }
        }
        if (worst_tan) {
            double rr[2], r2[2];
            CHECK_EQ_INT(plateau_vertex_tangential_gradient(m, v, 0.7, 64, vv, gg, &cnt, rr), PLATEAU_OK);
            plateau_vertex_tangential(m, v, 0.7, r2);
            CHECK(rr[0] == r2[0] && rr[1] == r2[1]);
            scale = 0.0;
            for (k = 0; k < 6 * cnt; k++) scale = fmax(scale, fabs(gg[k]));
            for (k = 0; k < cnt; k++) {
                for (c = 0; c < 3; c++) {
                    double *x = m->positions + 3 * (size_t)vv[k] + c, x0 = *x, fp[2], fm[2], r;
                    *x = x0 + step; plateau_vertex_tangential(m, v, 0.7, fp);
                    *x = x0 - step; plateau_vertex_tangential(m, v, 0.7, fm);
                    *x = x0;
                    for (q = 0; q < 2; q++) {
                        r = geo_rel(gg[6 * k + 3 * (size_t)q + c], (fp[q] - fm[q]) / (2 * step), scale);
                        if (r > *worst_tan) *worst_tan = r;
                    }
                }
            }
        }
    }
    /* area gradient */
    if (worst_area) {
        double *g = (double *)malloc(3 * m->num_vertices * sizeof(double)), scale = 0.0;
        plateau_mesh_area_gradient(m, g);
        for (k = 0; k < 3 * m->num_vertices; k++) scale = fmax(scale, fabs(g[k]));
        for (k = 0; k < 3 * m->num_vertices; k++) {
            double *x = m->positions + k, x0 = *x, fp, fm, r;
            *x = x0 + step; fp = plateau_mesh_area(m);
            *x = x0 - step; fm = plateau_mesh_area(m);
            *x = x0;
            r = geo_rel(g[k], (fp - fm) / (2 * step), scale);
            if (r > *worst_area) *worst_area = r;
        }
        free(g);
    }
    /* assembled system (interior rows, tangential rows) vs differences of
     * the residual vector, column by column */
    if (worst_jac) {
        plateau_system s, sp, sm;
        plateau_system_options o;
        double *jac, scale = 0.0;
        size_t col;
        memset(&s, 0, sizeof s); memset(&sp, 0, sizeof sp); memset(&sm, 0, sizeof sm);
        memset(&o, 0, sizeof o);
        o.tangential_weight = 0.5;
        CHECK_EQ_INT(plateau_system_assemble(m, &o, &s, NULL), PLATEAU_OK);
        jac = (double *)malloc(s.num_rows * s.num_columns * sizeof(double));
        plateau_system_dense(&s, jac);
        for (k = 0; k < s.num_rows * s.num_columns; k++) scale = fmax(scale, fabs(jac[k]));
        o.residual_only = 1;
        for (col = 0; col < s.num_columns; col++) {
            size_t vert = 0, r;
            double *x, x0;
            for (v = 0; v < m->num_vertices; v++)
                if (s.column_of_vertex[v] >= 0 && (size_t)s.column_of_vertex[v] == col - col % 3) vert = v;
            x = m->positions + 3 * vert + col % 3;
            x0 = *x;
            *x = x0 + step; plateau_system_assemble(m, &o, &sp, NULL);
            *x = x0 - step; plateau_system_assemble(m, &o, &sm, NULL);
            *x = x0;
            for (r = 0; r < s.num_rows; r++) {
                double d = geo_rel(jac[r * s.num_columns + col],
                                   (sp.residual[r] - sm.residual[r]) / (2 * step), scale);
                if (d > *worst_jac) *worst_jac = d;
            }
        }
        free(jac);
        plateau_system_free(&s);
        plateau_system_free(&sp);
        plateau_system_free(&sm);
    }
}

static void test_derivatives(void)
{
    geo_rng rng = {0x9e3779b97f4a7c15ull};
    int trial, trials = GEO_HEAVY ? 6 : 2;
    geo_worst_beta = geo_worst_h = geo_worst_tan = geo_worst_area = geo_worst_jac = 0.0;
    geo_worst_beta_flat = geo_worst_h_flat = 0.0;
    for (trial = 0; trial < trials; trial++) {
        plateau_mesh m;
        geo_random_mesh(&m, &rng, 0.3 + 0.2 * trial, 5 + trial % 3);
        geo_fd_mesh(&m, &geo_worst_beta, &geo_worst_h, &geo_worst_tan, &geo_worst_area,
                    &geo_worst_jac);
        plateau_mesh_free(&m);
    }
    /* nearly flat: |beta| about 1e-8, where the paper's formula (3) is 0/0 */
    for (trial = 0; trial < trials; trial++) {
        plateau_mesh m;
        double mb = 0.0;
        size_t e;
        geo_random_mesh(&m, &rng, 1e-8, 5);
        for (e = 0; e < m.num_edges; e++) mb = fmax(mb, fabs(plateau_edge_dihedral(&m, e)));
        CHECK(mb > 1e-10 && mb < 1e-7);
        geo_fd_mesh(&m, &geo_worst_beta_flat, &geo_worst_h_flat, NULL, NULL, NULL);
        plateau_mesh_free(&m);
    }
    printf("finite differences (largest relative error): beta %.2e, H %.2e, tangential %.2e, "
           "area %.2e, assembled Jacobian %.2e; nearly flat (|beta| ~ 1e-8): beta %.2e, H %.2e\n",
           geo_worst_beta, geo_worst_h, geo_worst_tan, geo_worst_area, geo_worst_jac,
           geo_worst_beta_flat, geo_worst_h_flat);
    CHECK(geo_worst_beta < 1e-6);
    CHECK(geo_worst_h < 1e-6);
    CHECK(geo_worst_tan < 1e-6);
    CHECK(geo_worst_area < 1e-6);
    CHECK(geo_worst_jac < 1e-6);
    CHECK(geo_worst_beta_flat < 1e-6);
    CHECK(geo_worst_h_flat < 1e-6);
}

/* plateau_mesh_area_hessian_normal against central differences: the
 * gradient against the area's differences along m_j, the Hessian's column j
 * against the differences of the exact area gradient (plateau_mesh_area_gradient)
 * projected on every m_i; entries outside the vertex adjacency must be 0 */
static double geo_hessian_normal_fd(plateau_mesh *m, const double *dir)
{
    const double step = 1e-6;
    size_t nv = m->num_vertices, ne = m->num_edges, v, j, e;
    double *g = (double *)malloc(nv * sizeof(double)), *dg = (double *)malloc(nv * sizeof(double));
    double *off = (double *)malloc(ne * sizeof(double)), *full = (double *)malloc(nv * nv * sizeof(double));
    double *gp = (double *)malloc(3 * nv * sizeof(double)), *gm = (double *)malloc(3 * nv * sizeof(double));
    double *md = (double *)malloc(3 * nv * sizeof(double)), worst = 0.0, gscale = 0.0, hscale = 0.0;
    double gworst = 0.0;
    CHECK_EQ_INT(plateau_mesh_area_hessian_normal(m, dir, g, dg, off, NULL), PLATEAU_OK);
    for (v = 0; v < nv; v++) {
        if (dir) memcpy(md + 3 * v, dir + 3 * v, 3 * sizeof(double));
        else plateau_vertex_normal(m, v, md + 3 * v);
    }
    /* the dense Hessian from the adjacency layout */
    memset(full, 0, nv * nv * sizeof(double));
    for (v = 0; v < nv; v++) full[v * nv + v] = dg[v];
    for (e = 0; e < ne; e++) {
        size_t a = (size_t)m->edges[2 * e], b = (size_t)m->edges[2 * e + 1];
        full[a * nv + b] = full[b * nv + a] = off[e];
    }
    for (v = 0; v < nv * nv; v++) hscale = fmax(hscale, fabs(full[v]));
    for (v = 0; v < nv; v++) gscale = fmax(gscale, fabs(g[v]));
    for (j = 0; j < nv; j++) {
        double *x = m->positions + 3 * j, x0[3], ap, am;
        size_t i;
        int c;
        memcpy(x0, x, sizeof x0);
        for (c = 0; c < 3; c++) x[c] = x0[c] + step * md[3 * j + c];
        ap = plateau_mesh_area(m);
        plateau_mesh_area_gradient(m, gp);
        for (c = 0; c < 3; c++) x[c] = x0[c] - step * md[3 * j + c];
        am = plateau_mesh_area(m);
        plateau_mesh_area_gradient(m, gm);
        memcpy(x, x0, sizeof x0);
        gworst = fmax(gworst, fabs((ap - am) / (2.0 * step) - g[j]) / gscale);
        for (i = 0; i < nv; i++) {
            double fd = 0.0;
            for (c = 0; c < 3; c++) fd += (gp[3 * i + c] - gm[3 * i + c]) * md[3 * i + c];
            fd /= 2.0 * step;
            worst = fmax(worst, fabs(fd - full[i * nv + j]) / hscale);
        }
    }
    CHECK(gworst < 1e-6);
    CHECK(hscale > 0.0 && gscale > 0.0);
    free(g); free(dg); free(off); free(full); free(gp); free(gm); free(md);
    return fmax(worst, gworst);
}

static void test_area_hessian_normal(void)
{
    geo_rng rng = {0x2545f4914f6cdd1dull};
    int trial, trials = GEO_HEAVY ? 4 : 2;
    double worst = 0.0, g[4], dg[4], off[8];
    plateau_error err;
    for (trial = 0; trial < trials; trial++) {
        plateau_mesh m;
        double *dir;
        size_t v;
        geo_random_mesh(&m, &rng, 0.3 + 0.2 * trial, 4 + trial % 2);
        /* vertex normals (NULL), then random unit directions */
        worst = fmax(worst, geo_hessian_normal_fd(&m, NULL));
        dir = (double *)malloc(3 * m.num_vertices * sizeof(double));
        for (v = 0; v < m.num_vertices; v++) {
            double *d = dir + 3 * v, len;
            d[0] = geo_uniform(&rng) - 0.5;
            d[1] = geo_uniform(&rng) - 0.5;
            d[2] = geo_uniform(&rng) + 0.2;
            len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            d[0] /= len; d[1] /= len; d[2] /= len;
        }
        worst = fmax(worst, geo_hessian_normal_fd(&m, dir));
        free(dir);
        plateau_mesh_free(&m);
    }
    printf("area Hessian on normal motions against finite differences: largest relative "
           "error %.2e\n", worst);
    CHECK(worst < 1e-6);
    /* a plane moved along its normal keeps its area to second order in a
     * uniform motion: the Hessian's row sums vanish, its gradient too */
    {
        plateau_mesh m;
        double *hg, *hd, *ho, rs = 0.0, gs = 0.0;
        size_t v, e;
        CHECK_EQ_INT(geo_grid(&m, geo_plane, NULL, -1, 1, -1, 1, 4, 4, 0.5, &rng), PLATEAU_OK);
        hg = (double *)malloc(m.num_vertices * sizeof(double));
        hd = (double *)malloc(m.num_vertices * sizeof(double));
        ho = (double *)malloc(m.num_edges * sizeof(double));
        CHECK_EQ_INT(plateau_mesh_area_hessian_normal(&m, NULL, hg, hd, ho, NULL), PLATEAU_OK);
        for (v = 0; v < m.num_vertices; v++) {
            rs += hd[v];
            gs = fmax(gs, fabs(hg[v]));
        }
        for (e = 0; e < m.num_edges; e++) rs += 2.0 * ho[e];
        CHECK(fabs(rs) < 1e-12);
        CHECK(gs < 1e-12);
        free(hg); free(hd); free(ho);
        plateau_mesh_free(&m);
    }
    /* errors: no mesh, one Hessian array alone, a zero-area triangle */
    {
        static const double pos[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0};
        static const plateau_index tri[6] = {0, 1, 2, 1, 3, 2};
        plateau_mesh m;
        CHECK_EQ_INT(plateau_mesh_area_hessian_normal(NULL, NULL, g, dg, off, &err),
                     PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_mesh_create(pos, 4, NULL, tri, 2, NULL, &m, NULL), PLATEAU_OK);
        CHECK_EQ_INT(plateau_mesh_area_hessian_normal(&m, NULL, g, dg, NULL, &err),
                     PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_mesh_area_hessian_normal(&m, NULL, g, NULL, NULL, &err), PLATEAU_OK);
        m.positions[9] = 0.5;
        m.positions[10] = 0.5; /* vertex 3 on the edge (1, 2): triangle 1 is flat */
        CHECK_EQ_INT(plateau_mesh_area_hessian_normal(&m, NULL, g, dg, off, &err),
                     PLATEAU_ERR_DEGENERATE_TRIANGLE);
        CHECK_EQ_INT((int)err.index, 1);
        plateau_mesh_free(&m);
    }
}

/* the four gradients of beta sum to zero; beta is accurate near 0 and near pi */
static void test_dihedral_values(void)
{
    /* a hinge: T1 = (a, b, c) in z = 0, T2 = (b, a, d) folded down by angle phi */
    double phis[5] = {1e-9, 1e-4, 0.5, 3.0, 3.14159};
    int i, k;
    for (i = 0; i < 5; i++) {
        double phi = phis[i];
        double pos[12] = {0, 0, 0, 1, 0, 0, 0.3, 1, 0, 0.6, 0, 0};
        plateau_index tri[6] = {0, 1, 2, 1, 0, 3};
        plateau_mesh m;
        plateau_index ev[4];
        double g[12], beta, s;
        pos[10] = -cos(phi);
        pos[11] = -sin(phi);
        CHECK_EQ_INT(plateau_mesh_create(pos, 4, NULL, tri, 2, NULL, &m, NULL), PLATEAU_OK);
        /* the interior edge is the only one with two triangles */
        for (k = 0; k < (int)m.num_edges; k++)
            if (m.edge_triangles[2 * k + 1] >= 0) break;
        beta = plateau_edge_dihedral_gradient(&m, (size_t)k, ev, g);
        /* normals point to +z for T1; folding T2 down below is convex seen from +z */
        CHECK_REL(beta, phi, 1e-9, 1e-300);
        for (k = 0; k < 3; k++) {
            s = g[k] + g[3 + k] + g[6 + k] + g[9 + k];
            CHECK_NEAR(s, 0.0, 1e-12);
        }
        plateau_mesh_free(&m);
    }
}

/* ---- H on exact surfaces ---- */
static double geo_mean_interior_h(const plateau_mesh *m, double *mean_abs, double *max_abs,
                                  double *mean_vec)
{
    double s = 0.0, sa = 0.0, mx = 0.0, sv = 0.0;
    size_t v, n = 0;
    for (v = 0; v < m->num_vertices; v++) {
        double h;
        if (m->fixed[v]) continue;
        h = plateau_vertex_mean_curvature(m, v);
        s += h;
        sa += fabs(h);
        sv += plateau_vertex_mean_curvature_vector(m, v, NULL);
        if (fabs(h) > mx) mx = fabs(h);
        n++;
    }
    if (mean_abs) *mean_abs = sa / (double)n;
    if (max_abs) *max_abs = mx;
    if (mean_vec) *mean_vec = sv / (double)n;
    return s / (double)n;
}

static void test_plane(void)
{
    plateau_mesh m;
    geo_rng rng = {12345};
    double mean_abs, max_abs, kv;
    size_t e, v;
    CHECK_EQ_INT(geo_grid(&m, geo_plane, NULL, -1, 1, -2, 1, 9, 7, 0.8, &rng), PLATEAU_OK);
    geo_mean_interior_h(&m, &mean_abs, &max_abs, NULL);
    CHECK(max_abs < 1e-12);
    for (e = 0; e < m.num_edges; e++) CHECK(fabs(plateau_edge_dihedral(&m, e)) < 1e-14);
    for (v = 0; v < m.num_vertices; v++) {
        double k[3];
        if (m.fixed[v]) continue;
        kv = plateau_vertex_mean_curvature_vector(&m, v, k);
        CHECK(fabs(kv) < 1e-12 && fabs(k[0]) + fabs(k[1]) + fabs(k[2]) < 1e-12);
    }
    printf("plane: largest |H| at interior vertices %.1e\n", max_abs);
    plateau_mesh_free(&m);
}

static void test_sphere(void)
{
    const double r = 2.5;
    const double expect[4] = {1.057, 1.015, 1.004, 1.0009};
    int level, top = GEO_HEAVY ? 4 : 3;
    printf("icosphere, radius %.1f: level, vertices, mean H r/2, |error|, mean (K . n) r/2 (Meyer et al.)\n", r);
    for (level = 1; level <= top; level++) {
        plateau_mesh m;
        double s = 0.0, sk = 0.0, mn = 1e300, mx = 0.0, mean;
        size_t v;
        CHECK_EQ_INT(geo_icosphere(&m, level, r), PLATEAU_OK);
        CHECK_EQ_INT((long)m.num_vertices - (long)m.num_edges + (long)m.num_triangles, 2);
        CHECK_EQ_INT(m.num_vertices, 10 * (1L << (2 * level)) + 2);
        for (v = 0; v < m.num_vertices; v++) {
            double h = plateau_vertex_mean_curvature(&m, v);
            CHECK(!m.fixed[v]);
            s += h;
            sk += plateau_vertex_mean_curvature_vector(&m, v, NULL);
            mn = fmin(mn, h);
            mx = fmax(mx, h);
        }
        mean = s / (double)m.num_vertices * r / 2.0;
        printf("  %d  %6lu  %.5f  %.1e  %.5f\n", level, (unsigned long)m.num_vertices, mean,
               fabs(mean - 1.0), sk / (double)m.num_vertices * r / 2.0);
        CHECK_NEAR(mean, expect[level - 1], level == 4 ? 2e-4 : 1e-3);
        CHECK(mn > 0.0); /* outward orientation: convex, positive */
        plateau_mesh_free(&m);
    }
}

/* On a cylinder H_i is exact in the mean over regions (the normal-cycle
 * theory), not pointwise: with alternating diagonals the 4- and 8-valent
 * vertices get different values.  With parallel diagonals every interior
 * vertex sees the same star and H_i r converges to 1. */
static void test_cylinder(void)
{
    const double r = 1.5;
    int n, pattern;
    printf("cylinder, radius %.1f: cells around, |H| r averaged over interior vertices, "
           "area-weighted, largest |(|H| r) - 1|\n", r);
    for (pattern = 1; pattern >= 0; pattern--) {
        printf("  %s diagonals\n", pattern ? "parallel" : "alternating");
        geo_parallel_diagonals = pattern;
        for (n = 8; n <= (GEO_HEAVY ? 64 : 32); n *= 2) {
            plateau_mesh m;
            double mean, mx = 0.0, sw = 0.0, sa = 0.0;
            size_t v;
            /* a half cylinder (open patch), u over [0, pi], y over [0, 2]: r_u x r_v
             * points to the axis, so H is negative; compare |H| */
            CHECK_EQ_INT(geo_grid(&m, geo_cylinder, &r, 0, geo_pi, 0, 2, n, n / 2, 0.0, NULL),
                         PLATEAU_OK);
            mean = geo_mean_interior_h(&m, NULL, NULL, NULL);
            CHECK(mean < 0.0);
            for (v = 0; v < m.num_vertices; v++) {
                double h, b;
                if (m.fixed[v]) continue;
                h = plateau_vertex_mean_curvature(&m, v);
                b = plateau_vertex_area(&m, v);
                mx = fmax(mx, fabs(fabs(h) * r - 1.0));
                sw += h * b;
                sa += b;
            }
            printf("    %3d  %.6f  %.6f  %.2e\n", n, fabs(mean) * r, fabs(sw / sa) * r, mx);
            if (pattern) {
                CHECK_NEAR(fabs(mean) * r, 1.0, n >= 32 ? 1e-3 : 2e-2);
            } else {
                CHECK_NEAR(fabs(sw / sa) * r, 1.0, n >= 32 ? 1e-2 : 5e-2);
            }
            plateau_mesh_free(&m);
        }
    }
    geo_parallel_diagonals = 0;
}

typedef struct geo_surface_case {
    const char *name;
    geo_surface f;
    double param;
    double u0, u1, v0, v1;
    int parallel;  /* parallel diagonals (else alternating) */
    int expect;    /* 2: pointwise O(h^2); 1: only the area-weighted mean converges; 0: exact */
} geo_surface_case;

/* H_i converges pointwise where the vertex stars are symmetric enough
 * (conformal grids with square cells: catenoid, Enneper; Scherk's graph
 * grid; any grid with parallel diagonals, whose stars are centrally
 * symmetric).  On the sheared helicoid grid with alternating diagonals the
 * vertex values do not converge at all (the 4- and 8-valent stars disagree),
 * while their area-weighted mean does: the normal-cycle theory promises
 * convergence over regions only. */
static void test_minimal_surfaces(void)
{
    const double q = 3.14159265358979323846 / 4.0;
    const geo_surface_case cases[6] = {
        {"catenoid b=2.05", geo_catenoid, 2.05, q, 3 * q, -0.5, 0.5, 0, 2},
        {"helicoid b=1.9 (grid lines are rulings)", geo_helicoid, 1.9, -1.0, 1.0, -q, q, 0, 0},
        {"helicoid b=1.9, sheared grid, parallel diagonals", geo_helicoid_sheared, 1.9, -1.0, 1.0, -q, q, 1, 2},
        {"helicoid b=1.9, sheared grid, alternating diagonals", geo_helicoid_sheared, 1.9, -1.0, 1.0, -q, q, 0, 1},
        {"Enneper", geo_enneper, 0.0, -0.8, 0.8, -0.8, 0.8, 0, 2},
        {"Scherk b=1", geo_scherk, 1.0, -1.0, 1.0, -1.0, 1.0, 0, 2}};
    int c;
    printf("minimal surfaces, parameter grids: cells per side, mean |H_i|, largest |H_i|, "
           "|area-weighted mean of H_i| (all times the patch diameter), observed orders\n");
    for (c = 0; c < 6; c++) {
        int n, top = GEO_HEAVY ? 64 : 32;
        double prev_mean = 0.0, prev_max = 0.0, prev_w = 0.0;
        printf("  %s\n", cases[c].name);
        geo_parallel_diagonals = cases[c].parallel;
        for (n = 8; n <= top; n *= 2) {
            plateau_mesh m;
            double mean_abs, max_abs, diam, wmean, sw = 0.0, sa = 0.0;
            double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
            size_t v;
            int k;
            CHECK_EQ_INT(geo_grid(&m, cases[c].f, &cases[c].param, cases[c].u0, cases[c].u1,
                                  cases[c].v0, cases[c].v1, n, n, 0.0, NULL), PLATEAU_OK);
            for (v = 0; v < m.num_vertices; v++) {
                for (k = 0; k < 3; k++) {
                    lo[k] = fmin(lo[k], m.positions[3 * v + k]);
                    hi[k] = fmax(hi[k], m.positions[3 * v + k]);
                }
                if (!m.fixed[v]) {
                    double b = plateau_vertex_area(&m, v);
                    sw += plateau_vertex_mean_curvature(&m, v) * b;
                    sa += b;
                }
            }
            diam = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                        (hi[2] - lo[2]) * (hi[2] - lo[2]));
            geo_mean_interior_h(&m, &mean_abs, &max_abs, NULL);
            mean_abs *= diam;
            max_abs *= diam;
            wmean = fabs(sw / sa) * diam;
            if (cases[c].expect == 0 || n == 8) {
                printf("    %3d  %.3e  %.3e  %.3e\n", n, mean_abs, max_abs, wmean);
            } else {
                printf("    %3d  %.3e  %.3e  %.3e  orders %.2f %.2f %.2f\n", n, mean_abs, max_abs,
                       wmean, log(prev_mean / mean_abs) / log(2.0), log(prev_max / max_abs) / log(2.0),
                       log(prev_w / wmean) / log(2.0));
            }
            if (cases[c].expect == 0) {
                /* each star is symmetric under the helicoid's half-turns about
                 * its rulings: H vanishes to rounding */
                CHECK(max_abs < 1e-10);
            } else if (n > 8 && cases[c].expect == 2) {
                CHECK(log(prev_mean / mean_abs) / log(2.0) > 1.5);
                CHECK(log(prev_max / max_abs) / log(2.0) > 1.5);
                CHECK(mean_abs < 0.05);
            } else if (n > 8) {
                CHECK(mean_abs > 0.5); /* no pointwise convergence */
                CHECK(log(prev_w / wmean) / log(2.0) > 0.9);
            }
            prev_mean = mean_abs;
            prev_max = max_abs;
            prev_w = wmean;
            plateau_mesh_free(&m);
        }
    }
    geo_parallel_diagonals = 0;
}

/* flipping every triangle flips every H_i and beta */
static void test_orientation_flip(void)
{
    geo_rng rng = {777};
    plateau_mesh m, f;
    plateau_index *tri;
    size_t t, v, e;
    geo_random_mesh(&m, &rng, 0.4, 6);
    tri = (plateau_index *)malloc(3 * m.num_triangles * sizeof(plateau_index));
    for (t = 0; t < m.num_triangles; t++) {
        tri[3 * t] = m.triangles[3 * t];
        tri[3 * t + 1] = m.triangles[3 * t + 2];
        tri[3 * t + 2] = m.triangles[3 * t + 1];
    }
    CHECK_EQ_INT(plateau_mesh_create(m.positions, m.num_vertices, m.fixed, tri, m.num_triangles, NULL,
                                     &f, NULL), PLATEAU_OK);
    for (v = 0; v < m.num_vertices; v++) {
        double h = plateau_vertex_mean_curvature(&m, v);
        CHECK_NEAR(plateau_vertex_mean_curvature(&f, v), -h, 1e-13 * (1 + fabs(h)));
        CHECK_NEAR(plateau_vertex_mean_curvature_vector(&f, v, NULL),
                   -plateau_vertex_mean_curvature_vector(&m, v, NULL), 1e-12);
    }
    for (e = 0; e < m.num_edges; e++) {
        plateau_index a = m.edges[2 * e], b = m.edges[2 * e + 1];
        size_t j;
        int found = 0;
        for (j = f.vertex_edge_start[a]; j < f.vertex_edge_start[a + 1]; j++) {
            size_t g = (size_t)f.vertex_edges[j];
            if ((f.edges[2 * g] == a && f.edges[2 * g + 1] == b) ||
                (f.edges[2 * g] == b && f.edges[2 * g + 1] == a)) {
                double be = plateau_edge_dihedral(&m, e);
                CHECK_NEAR(plateau_edge_dihedral(&f, g), -be, 1e-14);
                found = 1;
            }
        }
        CHECK(found);
    }
    free(tri);
    plateau_mesh_free(&m);
    plateau_mesh_free(&f);
}

/* the degeneration check: a clean patch, then a folded one */
static void test_quality(void)
{
    plateau_mesh m;
    plateau_quality q;
    double p = 0.0;
    size_t v;
    CHECK_EQ_INT(geo_grid(&m, geo_bumpy, &p, 0, 1, 0, 1, 4, 4, 0.0, NULL), PLATEAU_OK);
    plateau_mesh_quality(&m, &q);
    CHECK_NEAR(q.min_angle_deg, 45.0, 1e-9);
    CHECK_NEAR(q.max_angle_deg, 90.0, 1e-9);
    CHECK_NEAR(q.max_abs_beta_deg, 0.0, 1e-9);
    CHECK_EQ_INT(q.inverted_triangles, 0);
    CHECK_NEAR(q.area, 1.0, 1e-14);
    /* push the centre vertex through its neighbours' plane: a fold */
    for (v = 0; v < m.num_vertices; v++)
        if (fabs(m.positions[3 * v] - 0.5) < 1e-12 && fabs(m.positions[3 * v + 1] - 0.5) < 1e-12)
            m.positions[3 * v] = 0.5 + 0.6;
    plateau_mesh_quality(&m, &q);
    CHECK(q.inverted_triangles > 0);
    CHECK(q.max_abs_beta_deg > 170.0);
    plateau_mesh_free(&m);
}

/* A mesh of the given triangles over the given points, every vertex free;
 * plateau_mesh_check's intersecting pairs (-1 when the mesh is refused). */
static long geo_pairs(const double *pos, size_t nv, const plateau_index *tri, size_t nt,
                      unsigned *defects)
{
    plateau_mesh m;
    plateau_quality q;
    long r;
    if (plateau_mesh_create(pos, nv, NULL, tri, nt, NULL, &m, NULL) != PLATEAU_OK) return -1;
    r = plateau_mesh_check(&m, &q, NULL) == PLATEAU_OK ? (long)q.intersecting_pairs : -2;
    if (defects) *defects = q.defects;
    plateau_mesh_free(&m);
    return r;
}

/* The final check's counts: zero on clean grids (flat, tilted plane: every
 * orient3d at rounding level, and curved), and each defect found on a mesh
 * built to have just that one; the grid search gives the all-pairs count. */
static void test_mesh_check(void)
{
    static const double base[3 * 3] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    double pos[3 * 6];
    plateau_index two[6] = {0, 1, 2, 3, 4, 5}, fan[6] = {0, 1, 2, 0, 3, 4};
    plateau_mesh m;
    plateau_quality q;
    unsigned d = 99;
    double p = 0.4, zero = 0.0;
    char buf[256];
    size_t t, u, brute = 0, v;
    /* clean grids: no defect of any kind */
    geo_rng rng = {7};
    CHECK_EQ_INT(geo_grid(&m, geo_plane, &p, 0, 1, 0, 1, 12, 9, 0.3, &rng), PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    CHECK_EQ_INT(q.intersecting_pairs, 0);
    CHECK_EQ_INT(q.defects, 0);
    plateau_mesh_free(&m);
    CHECK_EQ_INT(geo_grid(&m, geo_bumpy, &zero, 0, 1, 0, 1, 10, 10, 0.0, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    CHECK_EQ_INT(q.defects, 0);
    plateau_mesh_free(&m);
    CHECK_EQ_INT(geo_grid(&m, geo_helicoid, &p, -1, 1, -1, 1, 14, 14, 0.0, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    CHECK_EQ_INT(q.defects, 0);
    /* wrap the helicoid's u = 1 column through the middle of the sheet: the
     * grid search and the test of all pairs find the same crossings */
    for (v = 0; v < m.num_vertices; v++)
        if (m.positions[3 * v] > 0.99) m.positions[3 * v] = -0.3;
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    for (t = 0; t < m.num_triangles; t++)
        for (u = t + 1; u < m.num_triangles; u++) brute += (size_t)plateau__chk_pair(&m, t, u);
    CHECK(brute > 0);
    CHECK_EQ_INT(q.intersecting_pairs, brute);
    CHECK(q.defects & PLATEAU_DEFECT_INTERSECTION);
    plateau_mesh_free(&m);
    /* two triangles, no common vertex: one pierces the other, then apart,
     * then touching (a vertex on the other's edge counts) */
    memcpy(pos, base, sizeof base);
    pos[9] = 0.25; pos[10] = 0.25; pos[11] = -1;
    pos[12] = 0.25; pos[13] = 0.25; pos[14] = 1;
    pos[15] = 2; pos[16] = 2; pos[17] = 0;
    CHECK_EQ_INT(geo_pairs(pos, 6, two, 2, &d), 1);
    CHECK_EQ_INT(d, PLATEAU_DEFECT_INTERSECTION);
    pos[9] = pos[12] = 5.25;
    pos[15] = 7;
    CHECK_EQ_INT(geo_pairs(pos, 6, two, 2, &d), 0);
    CHECK_EQ_INT(d, 0);
    pos[9] = 0.5; pos[10] = 0.5; pos[11] = 0; /* on the edge x + y = 1 */
    pos[12] = 0.5; pos[13] = 2; pos[14] = 0.5;
    pos[15] = 2; pos[16] = 0.5; pos[17] = -0.5;
    CHECK_EQ_INT(geo_pairs(pos, 6, two, 2, NULL), 1);
    /* one common vertex: touching only there is fine; overlapping beyond
     * it is not, off the plane and in it */
    memcpy(pos, base, sizeof base);
    pos[9] = -1; pos[10] = 0; pos[11] = 1;
    pos[12] = 0; pos[13] = -1; pos[14] = 1;
    CHECK_EQ_INT(geo_pairs(pos, 5, fan, 2, &d), 0);
    CHECK_EQ_INT(d, 0);
    pos[9] = 0.5; pos[10] = 0.5; pos[11] = 1;
    pos[12] = 0.5; pos[13] = 0.5; pos[14] = -1;
    CHECK_EQ_INT(geo_pairs(pos, 5, fan, 2, NULL), 1);
    pos[9] = 0.2; pos[10] = 0.1; pos[11] = 0; /* inside the first, same plane */
    pos[12] = 0.1; pos[13] = 0.2; pos[14] = 0;
    CHECK_EQ_INT(geo_pairs(pos, 5, fan, 2, NULL), 1);
    pos[9] = -1; pos[10] = -0.1; pos[11] = 0; /* beside it, same plane */
    pos[12] = -0.1; pos[13] = -1; pos[14] = 0;
    CHECK_EQ_INT(geo_pairs(pos, 5, fan, 2, NULL), 0);
    /* a degenerate triangle: a corner angle of 2e-12 rad */
    memcpy(pos, base, sizeof base);
    pos[6] = 0.5; pos[7] = 1e-12;
    CHECK_EQ_INT(plateau_mesh_create(pos, 3, NULL, two, 1, NULL, &m, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    CHECK_EQ_INT(q.degenerate_triangles, 1);
    CHECK_EQ_INT(q.defects, PLATEAU_DEFECT_DEGENERATE);
    plateau_mesh_free(&m);
    /* a fold: the bumpy patch's centre pushed through its neighbours */
    CHECK_EQ_INT(geo_grid(&m, geo_bumpy, &zero, 0, 1, 0, 1, 4, 4, 0.0, NULL), PLATEAU_OK);
    for (v = 0; v < m.num_vertices; v++)
        if (fabs(m.positions[3 * v] - 0.5) < 1e-12 && fabs(m.positions[3 * v + 1] - 0.5) < 1e-12)
            m.positions[3 * v] = 0.5 + 0.6;
    CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
    CHECK(q.folded_edges > 0);
    CHECK(q.defects & PLATEAU_DEFECT_FOLD);
    CHECK(q.defects & PLATEAU_DEFECT_INVERTED);
    plateau_mesh_free(&m);
    /* the words */
    CHECK(strcmp(plateau_defects_string(0, buf, sizeof buf), "valid") == 0);
    CHECK(strcmp(plateau_defects_string(PLATEAU_DEFECT_INVERTED | PLATEAU_DEFECT_INTERSECTION, buf,
                                        sizeof buf),
                 "inverted triangles; triangles intersecting each other") == 0);
    CHECK(strlen(plateau_defects_string(31u, buf, sizeof buf)) < 200);
    CHECK(strstr(buf, "stopping rule") != NULL);
    CHECK(strcmp(plateau_defects_string(PLATEAU_DEFECT_INVERTED, buf, 9), "inverted") == 0);
    CHECK(strcmp(plateau_defects_string(512u, buf, sizeof buf), "an unknown defect") == 0);
    CHECK_EQ_INT(plateau_mesh_check(NULL, &q, NULL), PLATEAU_ERR_ARGUMENT);
}

/* plateau_mesh_check's pair search against the test of all pairs with
 * plateau__chk_pair: a soup of 300 separate random triangles (a third of
 * them in one plane, so that coplanar overlaps occur), a fan of 600
 * long thin triangles around one vertex (the shape of the fan seeding with
 * few interior points) with some rim vertices pushed through it, and a
 * crowd of 400 small triangles in a box of side 0.2 pierced by 40 long
 * ones in random directions (many triangles to a grid cell, of widths
 * 0.03 to 1: the cells' sweep and its bound by the widest box). */
static void test_mesh_check_matches_all_pairs(void)
{
    enum { NS = 300, NF = 600, NC = 400, NL = 40 };
    double *pos = (double *)malloc(3 * 3 * (NC + NL) * sizeof(double));
    plateau_index *tri = (plateau_index *)malloc(3 * (NC + NL > NF ? NC + NL : NF) * sizeof(plateau_index));
    plateau_mesh m;
    plateau_quality q;
    geo_rng rng = {12345};
    size_t i, t, u, brute;
    int k, round;
    for (round = 0; round < 3; round++) {
        size_t nv, nt;
        if (round == 2) {
            for (t = 0; t < NC + NL; t++) {
                double c[3], d[3], len = t < NC ? 0.03 : 1.0;
                for (k = 0; k < 3; k++) {
                    c[k] = 0.5 + 0.2 * (geo_uniform(&rng) - 0.5);
                    d[k] = geo_uniform(&rng) - 0.5;
                }
                for (k = 0; k < 3; k++) {
                    double *p = pos + 9 * t + 3 * k;
                    int j;
                    /* from c - len d / 2 to c + len d / 2, the third
                     * vertex within 0.01 of the second */
                    for (j = 0; j < 3; j++)
                        p[j] = c[j] + (k == 0 ? -0.5 : 0.5) * len * d[j] +
                               (k == 2 ? 0.01 * (geo_uniform(&rng) - 0.5) : 0.0);
                    tri[3 * t + (size_t)k] = (plateau_index)(3 * t + (size_t)k);
                }
            }
            nv = 3 * (NC + NL);
            nt = NC + NL;
        } else if (round == 0) {
            for (t = 0; t < NS; t++) {
                double cx = geo_uniform(&rng), cy = geo_uniform(&rng), cz = geo_uniform(&rng);
                for (k = 0; k < 3; k++) {
                    double *p = pos + 9 * t + 3 * k;
                    p[0] = cx + 0.15 * (geo_uniform(&rng) - 0.5);
                    p[1] = cy + 0.15 * (geo_uniform(&rng) - 0.5);
                    p[2] = t % 3 == 0 ? 0.5 : cz + 0.15 * (geo_uniform(&rng) - 0.5);
                    tri[3 * t + (size_t)k] = (plateau_index)(3 * t + (size_t)k);
                }
            }
            nv = 3 * NS;
            nt = NS;
        } else {
            /* the hub 0 at the origin, rim vertices 1 .. NF on a wavy circle */
            pos[0] = pos[1] = pos[2] = 0.0;
            for (i = 0; i < NF; i++) {
                double a = 6.283185307179586 * (double)i / NF;
                pos[3 * (i + 1)] = cos(a);
                pos[3 * (i + 1) + 1] = sin(a);
                pos[3 * (i + 1) + 2] = 0.3 * cos(3 * a) + (i % 97 == 0 ? -0.9 : 0.0);
                if (i % 97 == 0) { pos[3 * (i + 1)] *= -0.2; pos[3 * (i + 1) + 1] *= -0.2; }
                tri[3 * i] = 0;
                tri[3 * i + 1] = (plateau_index)(i + 1);
                tri[3 * i + 2] = (plateau_index)((i + 1) % NF + 1);
            }
            nv = NF + 1;
            nt = NF;
        }
        CHECK_EQ_INT(plateau_mesh_create(pos, nv, NULL, tri, nt, NULL, &m, NULL), PLATEAU_OK);
        CHECK_EQ_INT(plateau_mesh_check(&m, &q, NULL), PLATEAU_OK);
        brute = 0;
        for (t = 0; t < m.num_triangles; t++)
            for (u = t + 1; u < m.num_triangles; u++) brute += (size_t)plateau__chk_pair(&m, t, u);
        CHECK(brute > 10);
        CHECK_EQ_INT(q.intersecting_pairs, brute);
        printf("  mesh check, %s: %lu intersecting pairs, as the test of all pairs\n",
               round == 0 ? "soup of 300" : round == 1 ? "fan of 600" : "crowd of 400 pierced by 40",
               (unsigned long)brute);
        plateau_mesh_free(&m);
    }
    free(pos);
    free(tri);
}

/* the system: rows, columns, row selection, zero-weight tangential */
static void test_system_layout(void)
{
    plateau_mesh m;
    plateau_system s;
    plateau_system_options o;
    geo_rng rng = {99};
    unsigned char *sel;
    size_t v, nfree = 0, r;
    geo_random_mesh(&m, &rng, 0.3, 4);
    for (v = 0; v < m.num_vertices; v++) nfree += !m.fixed[v];
    memset(&s, 0, sizeof s);
    CHECK_EQ_INT(plateau_system_assemble(&m, NULL, &s, NULL), PLATEAU_OK);
    CHECK_EQ_INT(s.num_rows, nfree);
    CHECK_EQ_INT(s.num_columns, 3 * nfree);
    for (r = 0; r < s.num_rows; r++)
        CHECK_NEAR(s.residual[r], plateau_vertex_mean_curvature(&m, (size_t)s.row_vertex[r]), 1e-12);
    memset(&o, 0, sizeof o);
    o.tangential_weight = 1.0;
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &s, NULL), PLATEAU_OK);
    CHECK_EQ_INT(s.num_rows, 3 * nfree); /* square */
    /* all vertices as rows (the paper's F over m + n vertices) */
    sel = (unsigned char *)malloc(m.num_vertices);
    memset(sel, 1, m.num_vertices);
    o.row_vertices = sel;
    o.tangential_weight = 0.0;
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &s, NULL), PLATEAU_OK);
    CHECK_EQ_INT(s.num_rows, m.num_vertices);
    for (r = 0; r < s.num_rows; r++) CHECK_EQ_INT(s.row_vertex[r], r);
    CHECK_EQ_INT(plateau_system_assemble(NULL, &o, &s, NULL), PLATEAU_ERR_ARGUMENT);
    CHECK(s.residual == NULL);
    free(sel);
    plateau_system_free(&s);
    plateau_system_free(&s);
    /* allocation failures */
    {
        countalloc ca;
        plateau_allocator a;
        plateau_mesh cm;
        long k;
        memset(&o, 0, sizeof o);
        o.tangential_weight = 1.0;
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_mesh_create(m.positions, m.num_vertices, NULL, m.triangles,
                                         m.num_triangles, &a, &cm, NULL), PLATEAU_OK);
        for (k = 1; k <= 8; k++) {
            long before = ca.live;
            ca.fail_at = ca.calls + k;
            CHECK_EQ_INT(plateau_system_assemble(&cm, &o, &s, NULL), PLATEAU_ERR_OUT_OF_MEMORY);
            CHECK_EQ_INT(ca.live, before);
        }
        plateau_mesh_free(&cm);
        CHECK_EQ_INT(ca.live, 0);
        CHECK_EQ_INT(ca.bad, 0);
    }
    plateau_mesh_free(&m);
}

/* 1 when two assembled systems hold the same rows and blocks, bit for bit */
static int system_same(const plateau_system *a, const plateau_system *b, size_t nv)
{
    return a->num_rows == b->num_rows && a->num_columns == b->num_columns && a->num_blocks == b->num_blocks &&
           memcmp(a->residual, b->residual, a->num_rows * sizeof(double)) == 0 &&
           memcmp(a->row_vertex, b->row_vertex, a->num_rows * sizeof(plateau_index)) == 0 &&
           memcmp(a->row_start, b->row_start, (a->num_rows + 1) * sizeof(size_t)) == 0 &&
           memcmp(a->block_vertex, b->block_vertex, a->num_blocks * sizeof(plateau_index)) == 0 &&
           memcmp(a->block_value, b->block_value, 3 * a->num_blocks * sizeof(double)) == 0 &&
           memcmp(a->column_of_vertex, b->column_of_vertex, nv * sizeof(plateau_index)) == 0;
}

/* A system assembled again (as every evaluation of an LM solve does)
 * keeps its arrays when they suffice, also after a residual-only
 * assembly, and holds what a fresh system gets, bit for bit; a larger
 * mesh, or another allocator, gets new arrays. */
static void test_system_reuse(void)
{
    plateau_mesh m, big;
    plateau_system fresh, s;
    plateau_system_options o, ro;
    geo_rng rng = {7};
    double *bv;
    size_t *rsp;
    countalloc ca;
    plateau_allocator a;
    long calls;
    size_t v;
    geo_random_mesh(&m, &rng, 0.3, 5);
    geo_random_mesh(&big, &rng, 0.3, 7);
    memset(&o, 0, sizeof o);
    o.tangential_weight = 0.7;
    ro = o;
    ro.residual_only = 1;
    memset(&fresh, 0, sizeof fresh);
    memset(&s, 0, sizeof s);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &fresh, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_system_assemble(&m, &ro, &s, NULL), PLATEAU_OK);
    CHECK_EQ_INT(s.num_blocks, 0);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &s, NULL), PLATEAU_OK); /* grows */
    CHECK(system_same(&fresh, &s, m.num_vertices));
    bv = s.block_value;
    rsp = s.row_start;
    for (v = 0; m.fixed[v]; v++) continue;
    m.positions[3 * v + 2] += 0.01; /* an interior vertex moved */
    plateau_system_free(&fresh);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &fresh, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_system_assemble(&m, &ro, &s, NULL), PLATEAU_OK);
    CHECK(s.block_value == bv && s.row_start == rsp);
    CHECK(memcmp(s.residual, fresh.residual, s.num_rows * sizeof(double)) == 0);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &s, NULL), PLATEAU_OK);
    CHECK(s.block_value == bv && s.row_start == rsp);
    CHECK(system_same(&fresh, &s, m.num_vertices));
    /* a larger mesh: new arrays, the right system */
    plateau_system_free(&fresh);
    CHECK_EQ_INT(plateau_system_assemble(&big, &o, &fresh, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_system_assemble(&big, &o, &s, NULL), PLATEAU_OK);
    CHECK(system_same(&fresh, &s, big.num_vertices));
    /* back to the smaller one: the larger arrays serve */
    bv = s.block_value;
    plateau_system_free(&fresh);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &fresh, NULL), PLATEAU_OK);
    CHECK_EQ_INT(plateau_system_assemble(&m, &o, &s, NULL), PLATEAU_OK);
    CHECK(s.block_value == bv);
    CHECK(system_same(&fresh, &s, m.num_vertices));
    /* another allocator (a mesh made with it): the old arrays go back to
     * theirs, the new ones come from it, and reuse allocates only scratch */
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    {
        plateau_mesh cm;
        CHECK_EQ_INT(plateau_mesh_create(m.positions, m.num_vertices, m.fixed, m.triangles, m.num_triangles, &a,
                                         &cm, NULL), PLATEAU_OK);
        CHECK_EQ_INT(plateau_system_assemble(&cm, &o, &s, NULL), PLATEAU_OK);
        CHECK(system_same(&fresh, &s, m.num_vertices));
        calls = ca.calls;
        CHECK_EQ_INT(plateau_system_assemble(&cm, &o, &s, NULL), PLATEAU_OK);
        /* the stencil scratch, the slot map, the H rows' map, the edges'
         * block offsets and the triangles' cross products */
        CHECK_EQ_INT(ca.calls - calls, 6);
        CHECK(system_same(&fresh, &s, m.num_vertices));
        plateau_system_free(&s);
        plateau_mesh_free(&cm);
    }
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
    plateau_system_free(&fresh);
    plateau_mesh_free(&m);
    plateau_mesh_free(&big);
}

/* The membranes' final check of cables (PLATEAU_DEFECT_CABLE): a cable
 * segment through a triangle that shares no vertex with it is found;
 * beside the triangle, or ending at one of its vertices, it is not. */
static void test_cable_crosses(void)
{
    double pos[18] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5, 0.5, -1, 0.5, 0.5, 1, 3, 3, 1};
    plateau_index tri[3] = {0, 1, 2}, seg[2] = {3, 4};
    unsigned char fixed[6] = {1, 1, 1, 0, 0, 0};
    plateau_mesh m;
    plateau__cfg_run c;
    memset(&c, 0, sizeof c);
    if (!CHECK_EQ_INT(plateau_mesh_create(pos, 6, fixed, tri, 1, NULL, &m, NULL), PLATEAU_OK)) return;
    c.cable_seg = seg;
    c.cable_nseg = 1;
    CHECK_EQ_INT(plateau__memb_cable_crosses(&m, &c), 1);
    seg[1] = 5; /* from below the triangle to beside it, over (3, 3): apart */
    CHECK_EQ_INT(plateau__memb_cable_crosses(&m, &c), 0);
    seg[0] = 0; /* ending at a vertex of the triangle: shares it, not tested */
    seg[1] = 4;
    CHECK_EQ_INT(plateau__memb_cable_crosses(&m, &c), 0);
    plateau_mesh_free(&m);
}

int main(void)
{
    RUN(test_adjacency);
    RUN(test_errors);
    RUN(test_dihedral_values);
    RUN(test_derivatives);
    RUN(test_area_hessian_normal);
    RUN(test_plane);
    RUN(test_sphere);
    RUN(test_cylinder);
    RUN(test_minimal_surfaces);
    RUN(test_orientation_flip);
    RUN(test_quality);
    RUN(test_mesh_check);
    RUN(test_mesh_check_matches_all_pairs);
    RUN(test_cable_crosses);
    RUN(test_system_layout);
    RUN(test_system_reuse);
    return harness_report("test_kernel");
}
