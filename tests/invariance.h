/* invariance.h - the invariance property of plateau_solve, shared by
 * tests/test_invariance.c (a small sample, in make test) and
 * bench/bench_invariance.c (50 curves, in make bench).
 *
 * A boundary and copies of it under nine transforms T: the identity; a
 * cyclic permutation of the axes; a mirror; a scaling by 2^-20; an odd
 * permutation of the axes (x and y swapped); a scaling
 * by 3.7; a translation by (1e6, -2e6, 3e6); a rotation; and a general
 * similarity (rotation, mirror, scaling by 0.37, translation).  For each
 * copy the mesh is compared with the identity's mapped by T: bit for bit
 * (positions exactly T of the reference's, triangles the same array),
 * or the same triangles (as sets of oriented triples) with the area
 * (divided by T's scale squared) within 1e-9 relative, or different
 * triangles; and whether validity (report.defects == 0) changed.  The
 * first four transforms and the swap are exact in floating point (no
 * rounding), the other four are not.  Include after plateau.h; needs <math.h>. */
#ifndef PLATEAU_TEST_INVARIANCE_H
#define PLATEAU_TEST_INVARIANCE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define INV_TRANSFORMS 9
#define INV_MAX_M 160

static const char *const inv_transform_names[INV_TRANSFORMS] = {
    "identity", "axes permuted", "mirror", "scale 2^-20",
    "scale 3.7", "moved by 1e6", "rotation", "similarity", "axes swapped"};
/* the transforms that involve no rounding */
static const int inv_exact[INV_TRANSFORMS] = {1, 1, 1, 1, 0, 0, 0, 0, 1};

typedef struct inv_rng { unsigned long long s; } inv_rng;
static double inv_uniform(inv_rng *r)
{
    r->s = r->s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

/* T(p): the transform k applied to one point */
typedef struct inv_transform {
    double a[3][3]; /* linear part, scale included */
    double t[3];    /* then moved by t */
    double scale;   /* the scale of a */
    int perm;       /* 1: the exact cyclic permutation (x, y, z) -> (z, x, y);
                       2: the odd one (x, y, z) -> (y, x, z) */
} inv_transform;

static void inv_rotation(double angle, const double *axis, double r[3][3])
{
    double n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n, c = cos(angle), s = sin(angle), C = 1 - c;
    r[0][0] = c + x * x * C;     r[0][1] = x * y * C - z * s; r[0][2] = x * z * C + y * s;
    r[1][0] = y * x * C + z * s; r[1][1] = c + y * y * C;     r[1][2] = y * z * C - x * s;
    r[2][0] = z * x * C - y * s; r[2][1] = z * y * C + x * s; r[2][2] = c + z * z * C;
}

static void inv_make(int k, inv_transform *T)
{
    static const double axis[3] = {0.3, -0.8, 0.52};
    int i, j;
    memset(T, 0, sizeof *T);
    for (i = 0; i < 3; i++) T->a[i][i] = 1.0;
    T->scale = 1.0;
    switch (k) {
    case 1: T->perm = 1; break;
    case 2: T->a[0][0] = -1.0; break;
    case 3: for (i = 0; i < 3; i++) T->a[i][i] = 9.5367431640625e-07; T->scale = 9.5367431640625e-07; break;
    case 4: for (i = 0; i < 3; i++) T->a[i][i] = 3.7; T->scale = 3.7; break;
    case 5: T->t[0] = 1e6; T->t[1] = -2e6; T->t[2] = 3e6; break;
    case 6: inv_rotation(0.7, axis, T->a); break;
    case 7:
        inv_rotation(2.1, axis, T->a);
        for (i = 0; i < 3; i++) {
            T->a[i][0] = -T->a[i][0];
            for (j = 0; j < 3; j++) T->a[i][j] *= 0.37;
        }
        T->scale = 0.37;
        T->t[0] = -5.5; T->t[1] = 12.25; T->t[2] = 0.125;
        break;
    case 8: T->perm = 2; break;
    default: break;
    }
}

static void inv_apply(const inv_transform *T, const double *p, double *q)
{
    int i;
    if (T->perm == 1) {
        q[0] = p[2]; q[1] = p[0]; q[2] = p[1];
        return;
    }
    if (T->perm == 2) {
        q[0] = p[1]; q[1] = p[0]; q[2] = p[2];
        return;
    }
    for (i = 0; i < 3; i++) q[i] = T->a[i][0] * p[0] + T->a[i][1] * p[1] + T->a[i][2] * p[2] + T->t[i];
    /* the exact transforms (a diagonal of +-1 or a power of two, t = 0) are exact here */
}

/* Boundaries: a random smooth closed curve (a sum of 3 harmonics per
 * coordinate with random amplitudes, on a ring of radius 1) and a twisted
 * unknot (a ring whose radius wobbles twice and height three times). */
static size_t inv_random_curve(inv_rng *r, double *xyz)
{
    double c[3][3][2];
    size_t m = 30 + (size_t)(inv_uniform(r) * 60.0), i;
    int k, h;
    for (k = 0; k < 3; k++)
        for (h = 0; h < 3; h++) {
            double amp = (k == 2 ? 0.5 : 0.25) / (double)(h + 1);
            c[k][h][0] = amp * (2.0 * inv_uniform(r) - 1.0);
            c[k][h][1] = amp * (2.0 * inv_uniform(r) - 1.0);
        }
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.0;
        for (k = 0; k < 3; k++)
            for (h = 0; h < 3; h++)
                xyz[3 * i + (size_t)k] += c[k][h][0] * cos((h + 2) * t) + c[k][h][1] * sin((h + 2) * t);
    }
    return m;
}

static size_t inv_twisted_unknot(double *xyz)
{
    size_t i, m = 100;
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m, r = 1.0 + 0.25 * cos(2.0 * t);
        xyz[3 * i] = r * cos(t);
        xyz[3 * i + 1] = r * sin(t);
        xyz[3 * i + 2] = 0.45 * sin(3.0 * t);
    }
    return m;
}

/* the results of one boundary over the transforms */
typedef struct inv_tally {
    int runs[INV_TRANSFORMS];      /* copies compared */
    int identical[INV_TRANSFORMS]; /* bit for bit */
    int same[INV_TRANSFORMS];      /* the same triangles, area within 1e-9 (not bit for bit) */
    int different[INV_TRANSFORMS]; /* other triangles */
    int validity[INV_TRANSFORMS];  /* valid for one, not for the other */
    int failed[INV_TRANSFORMS];    /* plateau_solve's result differed */
    double worst_area[INV_TRANSFORMS]; /* largest relative area difference */
} inv_tally;

static int inv_tri_cmp(const void *pa, const void *pb)
{
    const plateau_index *a = (const plateau_index *)pa, *b = (const plateau_index *)pb;
    int i;
    for (i = 0; i < 3; i++)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

/* the triangles as sorted oriented triples (each rotated to start at its
 * smallest index) */
static plateau_index *inv_tri_set(const plateau_mesh *mesh)
{
    size_t t, n = mesh->num_triangles;
    plateau_index *s = (plateau_index *)malloc(3 * n * sizeof(plateau_index) + 1);
    for (t = 0; t < n; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        int k = tr[0] < tr[1] ? (tr[0] < tr[2] ? 0 : 2) : (tr[1] < tr[2] ? 1 : 2);
        s[3 * t] = tr[k];
        s[3 * t + 1] = tr[(k + 1) % 3];
        s[3 * t + 2] = tr[(k + 2) % 3];
    }
    qsort(s, n, 3 * sizeof(plateau_index), inv_tri_cmp);
    return s;
}

/* Solves xyz (m vertices) and its eight copies with options o; adds to *tl. */
static void inv_run(const double *xyz, size_t m, const plateau_options *o, inv_tally *tl)
{
    plateau_mesh ref, mesh;
    plateau_report rr, rep;
    plateau_result r0, r;
    double copy[3 * INV_MAX_M];
    plateau_index *s0 = NULL, *s1;
    int k;
    size_t i;
    r0 = plateau_solve(xyz, m, o, &ref, &rr, NULL);
    if (r0 == PLATEAU_OK) s0 = inv_tri_set(&ref);
    for (k = 1; k < INV_TRANSFORMS; k++) {
        inv_transform T;
        int exact = 1;
        inv_make(k, &T);
        for (i = 0; i < m; i++) inv_apply(&T, xyz + 3 * i, copy + 3 * i);
        r = plateau_solve(copy, m, o, &mesh, &rep, NULL);
        tl->runs[k]++;
        if (r != r0) {
            tl->failed[k]++;
        } else if (r == PLATEAU_OK) {
            double ar = rep.area / (T.scale * T.scale), d = fabs(ar - rr.area) / rr.area;
            if ((rep.defects == 0) != (rr.defects == 0)) tl->validity[k]++;
            if (mesh.num_vertices == ref.num_vertices && mesh.num_triangles == ref.num_triangles &&
                memcmp(mesh.triangles, ref.triangles, 3 * ref.num_triangles * sizeof(plateau_index)) == 0) {
                for (i = 0; i < ref.num_vertices && exact; i++) {
                    double q[3];
                    inv_apply(&T, ref.positions + 3 * i, q);
                    exact = q[0] == mesh.positions[3 * i] && q[1] == mesh.positions[3 * i + 1] &&
                            q[2] == mesh.positions[3 * i + 2];
                }
            } else {
                exact = 0;
            }
            if (exact && rep.defects == rr.defects) {
                tl->identical[k]++;
            } else {
                int same = mesh.num_triangles == ref.num_triangles;
                if (same) {
                    s1 = inv_tri_set(&mesh);
                    same = memcmp(s0, s1, 3 * ref.num_triangles * sizeof(plateau_index)) == 0;
                    free(s1);
                }
                if (same && d <= 1e-9) tl->same[k]++;
                else tl->different[k]++;
            }
            if (d > tl->worst_area[k]) tl->worst_area[k] = d;
        }
        plateau_mesh_free(&mesh);
    }
    free(s0);
    plateau_mesh_free(&ref);
}

static void inv_print(const inv_tally *tl, const char *title)
{
    int k;
    printf("  %s\n  %-14s %5s %10s %9s %10s %9s %7s  %s\n", title, "transform", "runs", "bitwise",
           "same tri", "other tri", "validity", "failed", "largest area difference");
    for (k = 1; k < INV_TRANSFORMS; k++)
        printf("  %-14s %5d %10d %9d %10d %9d %7d  %.2e\n", inv_transform_names[k], tl->runs[k],
               tl->identical[k], tl->same[k], tl->different[k], tl->validity[k], tl->failed[k],
               tl->worst_area[k]);
}

#endif /* PLATEAU_TEST_INVARIANCE_H */
