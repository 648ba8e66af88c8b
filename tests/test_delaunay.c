/* test_delaunay.c - tests of plateau_delaunay.h.
 *
 * Every triangulation produced here goes through check_mesh(), which
 * verifies: counter-clockwise, non-degenerate triangles (exact orientation
 * > 0), mutual neighbour links and matching constraint flags, the exact
 * empty-circle test on every unconstrained interior edge (with the
 * library's predicate and, for small meshes, with an independent big-
 * integer evaluation), every segment present as a chain of constrained
 * edges, the Euler characteristic of the domain, and (hull mode) that the
 * boundary is convex and every distinct point is used.
 */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "plateau_delaunay.h"
#include "harness.h"

#include <float.h>
#include <limits.h>
#include <stdint.h>

#ifdef PLATEAU_TEST_SANITIZED
#define BIG_N 3000
#else
#define BIG_N 40000
#endif

/* ---------------------------------------------------------------- random */
static uint64_t rng_state = 12345;
static uint64_t rnd_u64(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rnd01(void) { return (double)(rnd_u64() >> 11) * (1.0 / 9007199254740992.0); }

/* ------------------------------------------- independent exact arithmetic
 * Signed big integers (32-bit limbs), enough for the predicates on any
 * finite doubles: coordinates are integer multiples of a common power of
 * two within 2098 bits of each other, the in-circle determinant has at
 * most 4 * 2099 + 4 bits. */
#define BIG_LIMBS 300
typedef struct big {
    int sign; /* -1, 0, 1 */
    int n;    /* limbs used */
    uint32_t d[BIG_LIMBS];
} big;

static void big_norm(big *a)
{
    while (a->n > 0 && a->d[a->n - 1] == 0) a->n--;
    if (a->n == 0) a->sign = 0;
}
static int big_cmp_mag(const big *a, const big *b)
{
    int i;
    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    for (i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}
static void big_add_mag(const big *a, const big *b, big *r)
{
    int i, n = a->n > b->n ? a->n : b->n;
    uint64_t c = 0;
    for (i = 0; i < n; i++) {
        c += (uint64_t)(i < a->n ? a->d[i] : 0) + (uint64_t)(i < b->n ? b->d[i] : 0);
        r->d[i] = (uint32_t)c;
        c >>= 32;
    }
    r->n = n;
    if (c && n < BIG_LIMBS) r->d[r->n++] = (uint32_t)c;
}
static void big_sub_mag(const big *a, const big *b, big *r) /* |a| >= |b| */
{
    int i;
    int64_t c = 0;
    for (i = 0; i < a->n; i++) {
        c += (int64_t)a->d[i] - (int64_t)(i < b->n ? b->d[i] : 0);
        r->d[i] = (uint32_t)(c & 0xffffffff);
        c = c < 0 ? -1 : 0;
    }
    r->n = a->n;
}
static big big_add(const big *a, const big *b)
{
    big r;
    r.sign = 0;
    r.n = 0;
    if (a->sign == 0) return *b;
    if (b->sign == 0) return *a;
    if (a->sign == b->sign) {
        big_add_mag(a, b, &r);
        r.sign = a->sign;
    } else if (big_cmp_mag(a, b) >= 0) {
        big_sub_mag(a, b, &r);
        r.sign = a->sign;
    } else {
        big_sub_mag(b, a, &r);
        r.sign = b->sign;
    }
    big_norm(&r);
    return r;
}
static big big_neg(big a)
{
    a.sign = -a.sign;
    return a;
}
static big big_sub(const big *a, const big *b)
{
    big nb = big_neg(*b);
    return big_add(a, &nb);
}
static big big_mul(const big *a, const big *b)
{
    big r;
    int i, j;
    r.n = a->n + b->n;
    r.sign = a->sign * b->sign;
    if (r.n > BIG_LIMBS) r.n = BIG_LIMBS;
    for (i = 0; i < r.n; i++) r.d[i] = 0;
    for (i = 0; i < a->n; i++) {
        uint64_t c = 0;
        for (j = 0; j < b->n && i + j < BIG_LIMBS; j++) {
            c += (uint64_t)a->d[i] * b->d[j] + r.d[i + j];
            r.d[i + j] = (uint32_t)c;
            c >>= 32;
        }
        if (i + j < BIG_LIMBS) r.d[i + j] = (uint32_t)c;
    }
    big_norm(&r);
    return r;
}
/* x = mant * 2^exp with an odd or zero integer mant (|mant| < 2^53) */
static void split_double(double x, int64_t *mant, int *exp)
{
    int e;
    double m = frexp(x, &e);
    int64_t M = (int64_t)ldexp(m, 53);
    e -= 53;
    while (M != 0 && (M & 1) == 0) {
        M /= 2;
        e++;
    }
    *mant = M;
    *exp = e;
}
/* x / 2^emin as a big integer (x must be a multiple of 2^emin) */
static big big_from(double x, int emin)
{
    big r;
    int64_t M;
    int e, shift, i;
    uint64_t mag;
    r.n = 0;
    r.sign = 0;
    split_double(x, &M, &e);
    if (M == 0) return r;
    shift = e - emin;
    mag = (uint64_t)(M < 0 ? -M : M);
    for (i = 0; i < shift / 32 + 3; i++) r.d[i] = 0;
    r.d[shift / 32] = (uint32_t)(mag << (shift % 32));
    if (shift % 32) {
        r.d[shift / 32 + 1] = (uint32_t)(mag >> (32 - shift % 32));
        r.d[shift / 32 + 2] = (uint32_t)(mag >> (64 - shift % 32));
    } else {
        r.d[shift / 32 + 1] = (uint32_t)(mag >> 32);
    }
    r.n = shift / 32 + 3;
    r.sign = M < 0 ? -1 : 1;
    big_norm(&r);
    return r;
}
/* the common exponent of k points; 0 (and *ok = 0) if out of reach */
static int common_exp(const double *const *p, int k, int *ok)
{
    int i, j, emin = INT_MAX, emax = INT_MIN;
    for (i = 0; i < k; i++)
        for (j = 0; j < 2; j++) {
            int64_t M;
            int e;
            split_double(p[i][j], &M, &e);
            if (M == 0) continue;
            if (e < emin) emin = e;
            if (e + 53 > emax) emax = e + 53;
        }
    *ok = emin == INT_MAX || (emax - emin) * 4 + 64 < 32 * (BIG_LIMBS - 8);
    return emin == INT_MAX ? 0 : emin;
}
static int slow_orient(const double *a, const double *b, const double *c, int *ok)
{
    const double *p[3];
    int e;
    big ax, ay, bx, by, cx, cy, t1, t2, l, r, det;
    p[0] = a; p[1] = b; p[2] = c;
    e = common_exp(p, 3, ok);
    if (!*ok) return 0;
    ax = big_from(a[0], e); ay = big_from(a[1], e);
    bx = big_from(b[0], e); by = big_from(b[1], e);
    cx = big_from(c[0], e); cy = big_from(c[1], e);
    t1 = big_sub(&ax, &cx); t2 = big_sub(&by, &cy); l = big_mul(&t1, &t2);
    t1 = big_sub(&ay, &cy); t2 = big_sub(&bx, &cx); r = big_mul(&t1, &t2);
    det = big_sub(&l, &r);
    return det.sign;
}
static int slow_incircle(const double *a, const double *b, const double *c, const double *d,
                         int *ok)
{
    const double *p[4];
    big dx[3], dy[3], px, py, qx, qy, lift, cross, t1, t2, term, det;
    int e, i;
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    e = common_exp(p, 4, ok);
    if (!*ok) return 0;
    qx = big_from(d[0], e);
    qy = big_from(d[1], e);
    for (i = 0; i < 3; i++) {
        px = big_from(p[i][0], e);
        py = big_from(p[i][1], e);
        dx[i] = big_sub(&px, &qx);
        dy[i] = big_sub(&py, &qy);
    }
    det.sign = 0;
    det.n = 0;
    for (i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        t1 = big_mul(&dx[i], &dx[i]);
        t2 = big_mul(&dy[i], &dy[i]);
        lift = big_add(&t1, &t2);
        t1 = big_mul(&dx[j], &dy[k]);
        t2 = big_mul(&dx[k], &dy[j]);
        cross = big_sub(&t1, &t2);
        term = big_mul(&lift, &cross);
        det = big_add(&det, &term);
    }
    return det.sign;
}

/* ------------------------------------------------------------ mesh checks */
typedef struct edge_rec {
    plateau_index lo, hi;
    long tk; /* 3t + k */
} edge_rec;
static int edge_cmp(const void *a, const void *b)
{
    const edge_rec *x = (const edge_rec *)a, *y = (const edge_rec *)b;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
    return x->tk < y->tk ? -1 : (x->tk > y->tk);
}
static long find_edge(const edge_rec *e, size_t ne, plateau_index a, plateau_index b)
{
    edge_rec key;
    size_t lo = 0, hi = ne;
    key.lo = a < b ? a : b;
    key.hi = a < b ? b : a;
    key.tk = -1;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (edge_cmp(&e[mid], &key) < 0) lo = mid + 1;
        else hi = mid;
    }
    if (lo < ne && e[lo].lo == key.lo && e[lo].hi == key.hi) return (long)lo;
    return -1;
}

typedef struct along_rec {
    double t;
    plateau_index v;
} along_rec;
static int along_cmp(const void *a, const void *b)
{
    const along_rec *x = (const along_rec *)a, *y = (const along_rec *)b;
    return x->t < y->t ? -1 : (x->t > y->t);
}

#define NO_EULER (-1000)
/* hull: 1 if the whole convex hull is expected; euler: expected V - E + F
 * (NO_EULER to skip) */
static void check_mesh(const plateau_dt_input *in, const plateau_dt_mesh *m, int hull, int euler)
{
    size_t nt = m->num_triangles, t, ne = 3 * nt, i;
    edge_rec *e = (edge_rec *)malloc((ne + 1) * sizeof *e);
    unsigned char *used = (unsigned char *)calloc(m->num_points + 1, 1);
    long bad_ccw = 0, bad_nb = 0, bad_del = 0, bad_slow = 0, bad_flag = 0, bad_idx = 0;
    long V = 0, E = 0, slow_checked = 0, fast_checked = 0;
    int slow = m->num_points <= 3000;
    const double *P = m->points;
    CHECK(m->num_input_points == in->num_points);
    CHECK(m->num_points >= in->num_points);
    for (t = 0; t < nt; t++) {
        const plateau_index *v = m->triangles + 3 * t;
        int k;
        for (k = 0; k < 3; k++) {
            if (v[k] < 0 || (size_t)v[k] >= m->num_points) { bad_idx++; continue; }
            if ((size_t)v[k] < m->num_input_points && m->duplicate_of[v[k]] != v[k]) bad_idx++;
            used[v[k]] = 1;
            e[3 * t + k].lo = v[k] < v[(k + 1) % 3] ? v[k] : v[(k + 1) % 3];
            e[3 * t + k].hi = v[k] < v[(k + 1) % 3] ? v[(k + 1) % 3] : v[k];
            e[3 * t + k].tk = (long)(3 * t + k);
        }
        if (plateau_dt_orient(P + 2 * v[0], P + 2 * v[1], P + 2 * v[2]) != 1) bad_ccw++;
    }
    CHECK_EQ_INT(bad_idx, 0);
    if (bad_idx) goto out;
    CHECK_EQ_INT(bad_ccw, 0);
    qsort(e, ne, sizeof *e, edge_cmp);
    /* each undirected edge: once (boundary, neighbour -1) or twice, in
     * opposite directions, linked to each other */
    for (i = 0; i < ne;) {
        size_t j = i;
        while (j < ne && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        E++;
        if (j - i == 1) {
            if (m->neighbors[e[i].tk] != -1) bad_nb++;
        } else if (j - i == 2) {
            long a = e[i].tk, b = e[i + 1].tk;
            long ta = a / 3, tb = b / 3;
            plateau_index a0 = m->triangles[a], b0 = m->triangles[b];
            if (m->neighbors[a] != tb || m->neighbors[b] != ta || a0 == b0) bad_nb++;
            if (m->constrained[a] != m->constrained[b]) bad_flag++;
            if (!m->constrained[a]) {
                /* the exact empty-circle test across the edge */
                const plateau_index *va = m->triangles + 3 * ta;
                plateau_index opp = m->triangles[3 * tb + (b % 3 + 2) % 3];
                fast_checked++;
                if (plateau_dt_incircle(P + 2 * va[0], P + 2 * va[1], P + 2 * va[2], P + 2 * opp) > 0)
                    bad_del++;
                if (slow) {
                    int ok;
                    int s = slow_incircle(P + 2 * va[0], P + 2 * va[1], P + 2 * va[2], P + 2 * opp, &ok);
                    if (ok) {
                        slow_checked++;
                        if (s > 0) bad_slow++;
                    }
                }
            }
        } else {
            bad_nb++;
        }
        i = j;
    }
    CHECK_EQ_INT(bad_nb, 0);
    CHECK_EQ_INT(bad_flag, 0);
    CHECK_EQ_INT(bad_del, 0);
    CHECK_EQ_INT(bad_slow, 0);
    if (slow) CHECK_EQ_INT(slow_checked, fast_checked);
    for (i = 0; i < m->num_points; i++) V += used[i];
    if (euler != NO_EULER) CHECK_EQ_INT(V - E + (long)nt, euler);
    /* duplicates: coincide with the kept point, which is the smallest index */
    {
        long bad_dup = 0;
        for (i = 0; i < m->num_input_points; i++) {
            plateau_index k = m->duplicate_of[i];
            if (k < 0 || (size_t)k > i || m->duplicate_of[k] != k) { bad_dup++; continue; }
            if (P[2 * i] != P[2 * k] || P[2 * i + 1] != P[2 * k + 1]) bad_dup++;
            if ((size_t)k != i && used[i]) bad_dup++;
            if (hull && (size_t)k == i && !used[i]) bad_dup++; /* every point used */
        }
        CHECK_EQ_INT(bad_dup, 0);
    }
    /* hull mode: every boundary edge has no point strictly on its right */
    if (hull && m->num_points <= 6000) {
        long bad_hull = 0;
        for (i = 0; i < 3 * nt; i++) {
            size_t j;
            const plateau_index *v;
            if (m->neighbors[i] != -1) continue;
            v = m->triangles + 3 * (i / 3);
            for (j = 0; j < m->num_points; j++)
                if (plateau_dt_orient(P + 2 * v[i % 3], P + 2 * v[(i % 3 + 1) % 3], P + 2 * j) < 0)
                    bad_hull++;
        }
        CHECK_EQ_INT(bad_hull, 0);
    }
    /* every segment is a chain of constrained edges through the points
     * lying exactly on it */
    if (in->num_segments && m->num_points <= 20000) {
        long bad_seg = 0;
        along_rec *al = (along_rec *)malloc((m->num_points + 1) * sizeof *al);
        for (i = 0; i < in->num_segments; i++) {
            plateau_index a = m->duplicate_of[in->segments[2 * i]];
            plateau_index b = m->duplicate_of[in->segments[2 * i + 1]];
            const double *pa = P + 2 * a, *pb = P + 2 * b;
            size_t j, na = 0;
            double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
            for (j = 0; j < m->num_points; j++) {
                const double *q = P + 2 * j;
                if (j < m->num_input_points && (size_t)m->duplicate_of[j] != j) continue;
                if (plateau_dt_orient(pa, pb, q) != 0) continue;
                if (q[0] < fmin(pa[0], pb[0]) || q[0] > fmax(pa[0], pb[0]) ||
                    q[1] < fmin(pa[1], pb[1]) || q[1] > fmax(pa[1], pb[1]))
                    continue;
                /* along a line, one coordinate orders the points exactly */
                al[na].t = dx != 0 ? (dx > 0 ? q[0] : -q[0]) : (dy > 0 ? q[1] : -q[1]);
                al[na].v = (plateau_index)j;
                na++;
            }
            qsort(al, na, sizeof *al, along_cmp);
            if (na < 2 || al[0].v != a || al[na - 1].v != b) bad_seg++;
            for (j = 0; j + 1 < na; j++) {
                long k = find_edge(e, ne, al[j].v, al[j + 1].v);
                if (k < 0 || !m->constrained[e[k].tk]) bad_seg++;
            }
        }
        free(al);
        CHECK_EQ_INT(bad_seg, 0);
    }
out:
    free(e);
    free(used);
}

/* The triangle set as sorted coordinate triples (rotation-normalised). */
typedef struct tri_key {
    double c[6];
} tri_key;
static int tri_key_cmp(const void *a, const void *b)
{
    const tri_key *x = (const tri_key *)a, *y = (const tri_key *)b;
    int i;
    for (i = 0; i < 6; i++)
        if (x->c[i] != y->c[i]) return x->c[i] < y->c[i] ? -1 : 1;
    return 0;
}
static tri_key *triangle_set(const plateau_dt_mesh *m)
{
    tri_key *k = (tri_key *)malloc((m->num_triangles + 1) * sizeof *k);
    size_t t;
    for (t = 0; t < m->num_triangles; t++) {
        const plateau_index *v = m->triangles + 3 * t;
        int r = 0, i;
        for (i = 1; i < 3; i++) {
            const double *p = m->points + 2 * v[i], *q = m->points + 2 * v[r];
            if (p[0] < q[0] || (p[0] == q[0] && p[1] < q[1])) r = i;
        }
        for (i = 0; i < 3; i++) {
            k[t].c[2 * i] = m->points[2 * v[(r + i) % 3]];
            k[t].c[2 * i + 1] = m->points[2 * v[(r + i) % 3] + 1];
        }
    }
    qsort(k, m->num_triangles, sizeof *k, tri_key_cmp);
    return k;
}
static int same_triangle_set(const plateau_dt_mesh *a, const plateau_dt_mesh *b)
{
    tri_key *x, *y;
    int same;
    if (a->num_triangles != b->num_triangles) return 0;
    x = triangle_set(a);
    y = triangle_set(b);
    same = memcmp(x, y, a->num_triangles * sizeof *x) == 0;
    free(x);
    free(y);
    return same;
}
static int same_mesh(const plateau_dt_mesh *a, const plateau_dt_mesh *b)
{
    size_t n3 = 3 * a->num_triangles;
    return a->num_triangles == b->num_triangles && a->num_points == b->num_points &&
           memcmp(a->triangles, b->triangles, n3 * sizeof(plateau_index)) == 0 &&
           memcmp(a->neighbors, b->neighbors, n3 * sizeof(plateau_index)) == 0 &&
           memcmp(a->constrained, b->constrained, n3) == 0 &&
           memcmp(a->points, b->points, 2 * a->num_points * sizeof(double)) == 0;
}

static plateau_dt_result run(const double *pts, size_t n, const plateau_index *seg, size_t ns,
                             const plateau_dt_options *opt, plateau_dt_mesh *m)
{
    plateau_dt_input in;
    plateau_dt_error rep;
    plateau_dt_result r;
    in.points = pts;
    in.num_points = n;
    in.segments = seg;
    in.num_segments = ns;
    r = plateau_dt_triangulate(&in, opt, m, &rep);
    CHECK_EQ_INT(rep.code, r); /* the error detail carries the code */
    if (r != PLATEAU_DT_OK) CHECK(rep.message[0] != '\0');
    else CHECK(rep.index == -1 && rep.message[0] == '\0');
    if (r != PLATEAU_DT_OK && getenv("TEST_DELAUNAY_VERBOSE"))
        fprintf(stderr, "  triangulate: %d %s: %s\n", r, plateau_dt_result_string(r), rep.message);
    return r;
}
/* run and check; returns the result */
static plateau_dt_result run_check(const double *pts, size_t n, const plateau_index *seg,
                                   size_t ns, const plateau_dt_options *opt, plateau_dt_mesh *m,
                                   int hull, int euler)
{
    plateau_dt_input in;
    plateau_dt_result r = run(pts, n, seg, ns, opt, m);
    CHECK_EQ_INT(r, PLATEAU_DT_OK);
    in.points = pts;
    in.num_points = n;
    in.segments = seg;
    in.num_segments = ns;
    if (r == PLATEAU_DT_OK) check_mesh(&in, m, hull, euler);
    return r;
}

/* ================================================================ tests */

static void test_predicates_against_bigint(void)
{
    /* points a few ulps off a line and off a circle: the plain floating-
     * point formula is wrong for some of them, the predicates never */
    int i, naive_wrong = 0, mism = 0, checked = 0;
    for (i = 0; i < 3000; i++) {
        double a[2], b[2], c[2], d[2];
        double s = rnd01() * 10 + 0.5;
        int k, ok, want, got;
        a[0] = rnd01(); a[1] = a[0];
        b[0] = a[0] + s; b[1] = b[0];
        c[0] = a[0] + rnd01() * s * 3; c[1] = c[0];
        for (k = (int)(rnd_u64() % 4); k > 0; k--) c[1] = nextafter(c[1], (rnd_u64() & 1) ? 10 : -10);
        want = slow_orient(a, b, c, &ok);
        if (!ok) continue;
        checked++;
        got = plateau_dt_orient(a, b, c);
        if (got != want) mism++;
        {
            double naive = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
            int ns = naive > 0 ? 1 : (naive < 0 ? -1 : 0);
            if (ns != want) naive_wrong++;
        }
        /* a point near the unit circle through a, b, c on it */
        {
            double t0 = rnd01() * 6.283, t1 = t0 + 1 + rnd01(), t2 = t1 + 1 + rnd01(), t3 = rnd01() * 6.283;
            double A[2], B[2], C[2];
            A[0] = cos(t0); A[1] = sin(t0);
            B[0] = cos(t1); B[1] = sin(t1);
            C[0] = cos(t2); C[1] = sin(t2);
            d[0] = cos(t3); d[1] = sin(t3);
            for (k = (int)(rnd_u64() % 3); k > 0; k--) d[0] = nextafter(d[0], 0);
            want = slow_incircle(A, B, C, d, &ok);
            if (ok) {
                double adx = A[0] - d[0], ady = A[1] - d[1], bdx = B[0] - d[0], bdy = B[1] - d[1];
                double cdx = C[0] - d[0], cdy = C[1] - d[1];
                double naive = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                               (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                               (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
                int ns = naive > 0 ? 1 : (naive < 0 ? -1 : 0);
                checked++;
                if (plateau_dt_incircle(A, B, C, d) != want) mism++;
                if (ns != want) naive_wrong++;
            }
        }
    }
    CHECK(checked > 5000);
    CHECK_EQ_INT(mism, 0);
    CHECK(naive_wrong > 0); /* the inputs really are beyond plain floating point */
    /* small integers times powers of two (the predicates' exact shortcut)
     * and just past its limit, many of them degenerate */
    mism = 0;
    for (i = 0; i < 4000; i++) {
        double q[4][2];
        int k, ok, bits = 2 + (int)(rnd_u64() % 14), e = (int)(rnd_u64() % 200) - 100;
        for (k = 0; k < 8; k++)
            q[k / 2][k % 2] = ldexp((double)(rnd_u64() % ((uint64_t)1 << bits)), e);
        if (plateau_dt_orient(q[0], q[1], q[2]) != slow_orient(q[0], q[1], q[2], &ok) && ok) mism++;
        if (plateau_dt_incircle(q[0], q[1], q[2], q[3]) != slow_incircle(q[0], q[1], q[2], q[3], &ok) &&
            ok)
            mism++;
    }
    CHECK_EQ_INT(mism, 0);
    /* exact zeros */
    {
        double a[2] = {0.1, 0.1}, b[2] = {0.3, 0.3}, c[2] = {0.7, 0.7};
        double p[2] = {1, 0}, q[2] = {0, 1}, r[2] = {-1, 0}, s[2] = {0, -1};
        double u[2] = {3, 4}, v[2] = {-5, 0}, w[2] = {4, -3}, z[2] = {0, 5};
        CHECK_EQ_INT(plateau_dt_orient(a, b, c), 0);
        CHECK_EQ_INT(plateau_dt_incircle(p, q, r, s), 0);
        CHECK_EQ_INT(plateau_dt_incircle(u, z, v, w), 0);
        CHECK_EQ_INT(plateau_dt_orient(p, q, r), 1);
        CHECK_EQ_INT(plateau_dt_orient(p, r, q), -1);
    }
}

/* A random double of magnitude 10^e, e uniform in [lo, hi] (a random sign). */
static double rnd_mag(int lo, int hi)
{
    double m = 1 + rnd01() * 9;
    int e = lo + (int)(rnd_u64() % (uint64_t)(hi - lo + 1));
    return ((rnd_u64() & 1) ? -1 : 1) * m * pow(10.0, e);
}

/* Random points at mixed magnitudes (1e-300 .. 1e300 in one test, tiny
 * clusters inside huge squares, nearly collinear and nearly co-circular
 * points in such clusters), each test compared with the big integers. */
static void test_predicates_mixed_magnitudes(void)
{
    int i, k, mism = 0, checked = 0, nonzero_icc = 0, ok;
    uint64_t saved = rng_state; /* the later tests keep their inputs */
    for (i = 0; i < 6000; i++) {
        double p[4][2];
        int kind = i % 6;
        if (kind == 0) { /* every coordinate anywhere in 1e-300 .. 1e300 */
            for (k = 0; k < 8; k++) p[k / 2][k % 2] = rnd_mag(-300, 300);
        } else if (kind == 1) { /* a 1e-150 cluster and a 1e150 point */
            for (k = 0; k < 6; k++) p[k / 2][k % 2] = rnd_mag(-152, -150);
            p[3][0] = rnd_mag(150, 150);
            p[3][1] = rnd_mag(150, 150);
        } else if (kind == 2) { /* three huge corners, one tiny point */
            for (k = 0; k < 6; k++) p[k / 2][k % 2] = rnd_mag(140, 160);
            p[3][0] = rnd_mag(-160, -140);
            p[3][1] = rnd_mag(-160, -140);
        } else if (kind == 3) { /* a tiny triangle and a point nearly on its circle's far side */
            double cx, cy, r, t;
            int e = -(int)(rnd_u64() % 290);
            for (k = 0; k < 3; k++) {
                t = rnd01() * 6.283;
                p[k][0] = cos(t) * pow(10.0, e);
                p[k][1] = sin(t) * pow(10.0, e);
            }
            cx = 0; cy = 0; r = pow(10.0, e);
            t = rnd01() * 6.283;
            p[3][0] = cx + r * cos(t);
            p[3][1] = cy + r * sin(t);
            if (rnd_u64() & 1) { /* and a huge offset point in the same test */
                p[(int)(rnd_u64() % 4)][0] = rnd_mag(100, 300);
            }
        } else if (kind == 4) { /* nearly collinear points straddling magnitudes */
            double t = rnd01();
            p[0][0] = rnd_mag(-300, -100); p[0][1] = rnd_mag(-300, -100);
            p[1][0] = rnd_mag(100, 300); p[1][1] = rnd_mag(100, 300);
            p[2][0] = p[0][0] + (p[1][0] - p[0][0]) * t;
            p[2][1] = p[0][1] + (p[1][1] - p[0][1]) * t;
            p[3][0] = p[2][0] * 1e-200;
            p[3][1] = nextafter(p[2][1], 0) * 1e-200;
        } else { /* subnormals with normal numbers and huge ones */
            for (k = 0; k < 8; k++) {
                uint64_t r = rnd_u64() % 3;
                p[k / 2][k % 2] = r == 0 ? ldexp((double)(rnd_u64() % 1000) - 500, -1074)
                                         : (r == 1 ? rnd_mag(-20, 20) : rnd_mag(250, 307));
            }
        }
        {
            int w = slow_orient(p[0], p[1], p[2], &ok);
            if (ok) {
                checked++;
                if (plateau_dt_orient(p[0], p[1], p[2]) != w)
                    mism++;
            }
            w = slow_orient(p[3], p[1], p[0], &ok);
            if (ok) {
                checked++;
                if (plateau_dt_orient(p[3], p[1], p[0]) != w)
                    mism++;
            }
            w = slow_incircle(p[0], p[1], p[2], p[3], &ok);
            if (ok) {
                checked++;
                if (w != 0) nonzero_icc++;
                if (plateau_dt_incircle(p[0], p[1], p[2], p[3]) != w)
                    mism++;
            }
        }
    }
    rng_state = saved;
    CHECK(checked >= 17000);
    CHECK(nonzero_icc > 5000);
    CHECK_EQ_INT(mism, 0);
    /* three points near 1e-151 and one at 1e150: not co-circular */
    {
        double a[2] = {1.3e-151, -0.7e-151}, b[2] = {2.1e-151, 1.9e-151}, c[2] = {-1.2e-151, 0.4e-151};
        double d[2] = {1e150, 0.5e150};
        int w = slow_incircle(a, b, c, d, &ok);
        CHECK(ok && w == -1);
        CHECK_EQ_INT(plateau_dt_incircle(a, b, c, d), w);
        CHECK_EQ_INT(plateau_dt_incircle(d, a, b, c), -w);
    }
}

/* 55 points in [-1e-150, 1e-150]^2 and two at (+-1e150, 1e150): every
 * edge must pass the exact empty-circle test of the big integers (point 17
 * lay inside the circle through 33, 56 and 47 when products of the small
 * differences underflowed inside the expansions). */
static void test_mixed_magnitude_cluster(void)
{
    static const double pts[2 * 57] = {
        1.9817199371914617e-151, -6.9694662812738479e-151, -4.2719223501178581e-151, -5.4410958689600465e-151,
        -3.7108955980082549e-151, 4.1647454534021567e-151, -4.3105770945842158e-151, -4.4820583233912207e-151,
        -2.7951544646378924e-151, -1.9076825480687455e-152, -8.4803629587788217e-151, -5.1256773249083218e-151,
        2.6209784221983546e-151, 5.1162738038660229e-151, 7.382766509548628e-151, -1.6904935063912774e-151,
        6.975849503958347e-151, 3.497210803703481e-151, -9.6139819517270867e-151, 1.8350893332973484e-151,
        8.5293887597808387e-151, 9.0345365012071331e-151, -3.5047226066722502e-152, 1.4436593928689724e-151,
        5.6483649980908443e-151, -8.4095494525271319e-151, -9.1825896556722662e-151, -7.5581579075621822e-151,
        -9.635881194756175e-151, 7.478243857546278e-151, 9.6262148757797354e-151, 3.0763553467897164e-151,
        -5.9447788492359208e-152, -7.8562438596726608e-151, -2.3091215425737753e-151, 8.5794096329072251e-151,
        4.6409804715925905e-151, 9.8568578528811429e-151, 3.335751310192656e-151, -8.6914086328137013e-152,
        -8.6316219057268778e-151, -6.3670961051271964e-151, -9.0601174112421206e-151, 7.6076542036883124e-151,
        4.0574237827135519e-151, -2.2837489262209077e-151, -3.5068482265429316e-151, -3.506209994053002e-151,
        8.7622025452986991e-151, -3.1700935686639566e-151, 2.2057777749433604e-151, -2.2759439730163633e-151,
        -2.4137726403318283e-151, -6.1106680938650432e-151, -7.0993171221027479e-151, 3.3083839121184488e-151,
        -5.3038742801949069e-151, -1.5952808755552584e-151, -4.680783395370087e-151, -3.4799246463430133e-152,
        4.0712689620576682e-151, -2.0630855255959691e-151, 1.5970142047053694e-151, -3.8458169961843921e-151,
        8.2443084344507357e-151, 8.3728121733821489e-151, -3.272194978119969e-151, 7.5662444772557122e-151,
        -8.4454378285973663e-151, -6.3747192964102255e-151, -7.1555127013103384e-151, 7.0117775672171586e-153,
        3.3749612362632851e-152, 9.0135635730972827e-152, 6.0525186022973523e-151, -9.9065483026320406e-151,
        1.0769064877542234e-151, 8.6369498048159302e-151, -5.9971552147778898e-151, -7.7016845277934381e-151,
        9.8124369324722395e-151, -1.9402171575576555e-152, -5.6920385511467564e-151, -3.8398493778901986e-151,
        8.5589929413183892e-151, -1.9256514021999481e-151, -6.453704967036744e-152, 8.6827183627012711e-151,
        5.3931297575031031e-151, -6.6303292786652388e-151, -1.1983963313788592e-153, 7.8104400954204275e-151,
        7.3120971187995386e-151, -2.6259423824655248e-151, -4.6177657927166106e-151, 8.1450343393227209e-151,
        6.6157473485997226e-151, 8.3003241695734805e-151, -7.9760866563259556e-151, -9.0215086047575215e-151,
        7.6525978471925971e-151, -4.1616375470811874e-152, 4.6391391563562626e-151, -7.2821648540796485e-151,
        -8.6606816214818989e-151, -1.9899079808347531e-151, 9.6251165222181961e-151, 5.3368209992593155e-151,
        -1.1784531400896236e-151, 6.8969345283739875e-151, 9.9999999999999998e+149, 9.9999999999999998e+149,
        -9.9999999999999998e+149, 9.9999999999999998e+149,
    };
    plateau_dt_mesh m;
    int ok;
    CHECK_EQ_INT(slow_incircle(pts + 2 * 33, pts + 2 * 56, pts + 2 * 47, pts + 2 * 17, &ok) *
                     slow_orient(pts + 2 * 33, pts + 2 * 56, pts + 2 * 47, &ok), 1);
    CHECK_EQ_INT(plateau_dt_incircle(pts + 2 * 33, pts + 2 * 56, pts + 2 * 47, pts + 2 * 17) *
                     plateau_dt_orient(pts + 2 * 33, pts + 2 * 56, pts + 2 * 47), 1);
    run_check(pts, 57, NULL, 0, NULL, &m, 1, 1); /* every edge, exactly */
    CHECK_EQ_INT(m.num_points, 57);
    plateau_dt_free(&m);
}

static void test_predicates_extreme_scales(void)
{
    /* the same configuration at 2^-1000, 1e-150, 1e150, 2^1000: the exact
     * answers must not change (powers of two are exact scalings) */
    double sc[5];
    int i, k, bad = 0;
    sc[0] = 1.0;
    sc[1] = ldexp(1.0, -1000);
    sc[2] = ldexp(1.0, -500);
    sc[3] = ldexp(1.0, 500);
    sc[4] = ldexp(1.0, 1000);
    for (i = 0; i < 500; i++) {
        double a[2], b[2], c[2], d[2], base_o, base_i;
        a[0] = rnd01(); a[1] = rnd01();
        b[0] = rnd01(); b[1] = rnd01();
        c[0] = a[0] + (b[0] - a[0]) * 0.5; c[1] = a[1] + (b[1] - a[1]) * 0.5; /* near the line */
        d[0] = rnd01(); d[1] = rnd01();
        base_o = plateau_dt_orient(a, b, c);
        base_i = plateau_dt_incircle(a, b, d, c);
        for (k = 1; k < 5; k++) {
            double A[2], B[2], C[2], D[2];
            A[0] = a[0] * sc[k]; A[1] = a[1] * sc[k];
            B[0] = b[0] * sc[k]; B[1] = b[1] * sc[k];
            C[0] = c[0] * sc[k]; C[1] = c[1] * sc[k];
            D[0] = d[0] * sc[k]; D[1] = d[1] * sc[k];
            if (plateau_dt_orient(A, B, C) != base_o) bad++;
            if (plateau_dt_incircle(A, B, D, C) != base_i) bad++;
        }
    }
    CHECK_EQ_INT(bad, 0);
    {
        double a[2] = {1e-150, 1e-150}, b[2] = {3e-150, 1e-150}, c[2] = {1e-150, 3e-150};
        double d[2] = {3e-150, 3e-150}, e[2] = {2e150, 0}, f[2] = {0, 2e150}, g[2] = {-2e150, 0};
        double h[2] = {0, -2e150};
        CHECK_EQ_INT(plateau_dt_orient(a, b, c), 1);
        CHECK_EQ_INT(plateau_dt_incircle(a, b, d, c), 0);
        CHECK_EQ_INT(plateau_dt_incircle(e, f, g, h), 0);
        CHECK_EQ_INT(plateau_dt_orient(e, f, g), 1);
    }
}

static void test_random_points(void)
{
    size_t n = BIG_N, i;
    double *p = (double *)malloc(2 * n * sizeof(double));
    plateau_dt_mesh m;
    for (i = 0; i < 2 * n; i++) p[i] = rnd01();
    run_check(p, n, NULL, 0, NULL, &m, 1, 1);
    CHECK(m.num_triangles > n); /* 2n - 2 - h */
    plateau_dt_free(&m);
    /* small sets, many of them, each with the slow exact check */
    for (i = 0; i < 40; i++) {
        size_t k = 3 + (size_t)(rnd_u64() % 60), j;
        for (j = 0; j < 2 * k; j++) p[j] = rnd01();
        if (run_check(p, k, NULL, 0, NULL, &m, 1, 1) == PLATEAU_DT_OK)
            CHECK(m.num_triangles >= k - 2);
        plateau_dt_free(&m);
    }
    free(p);
}

static void test_grid(void)
{
    /* a square grid: every cell's four corners are co-circular */
    int s = 30, i, j;
    size_t n = (size_t)(s * s);
    double *p = (double *)malloc(2 * n * sizeof(double)), *q;
    plateau_dt_mesh m, m2;
    for (j = 0; j < s; j++)
        for (i = 0; i < s; i++) {
            p[2 * (j * s + i)] = i;
            p[2 * (j * s + i) + 1] = j;
        }
    run_check(p, n, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, 2 * (s - 1) * (s - 1));
    /* reversed order: same triangle set */
    q = (double *)malloc(2 * n * sizeof(double));
    for (i = 0; i < (int)n; i++) {
        q[2 * i] = p[2 * (n - 1 - (size_t)i)];
        q[2 * i + 1] = p[2 * (n - 1 - (size_t)i) + 1];
    }
    run_check(q, n, NULL, 0, NULL, &m2, 1, 1);
    CHECK(same_triangle_set(&m, &m2));
    plateau_dt_free(&m);
    plateau_dt_free(&m2);
    free(p);
    free(q);
}

static void test_circle(void)
{
    /* lattice points exactly on x^2 + y^2 = 1105^2 (many representations),
     * with and without the centre; then points on a circle by cos/sin */
    double p[2 * 1200];
    size_t n = 0, i;
    long x, r = 1105;
    plateau_dt_mesh m, m2;
    for (x = -r; x <= r; x++) {
        long y2 = r * r - x * x, y = (long)floor(sqrt((double)y2) + 0.5);
        if (y * y == y2) {
            p[2 * n] = (double)x;
            p[2 * n + 1] = (double)y;
            n++;
            if (y) {
                p[2 * n] = (double)x;
                p[2 * n + 1] = (double)-y;
                n++;
            }
        }
    }
    CHECK(n >= 20);
    run_check(p, n, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, n - 2);
    /* rotated listing: same triangles */
    {
        double q[2 * 1200];
        for (i = 0; i < n; i++) {
            q[2 * i] = p[2 * ((i + 7) % n)];
            q[2 * i + 1] = p[2 * ((i + 7) % n) + 1];
        }
        run_check(q, n, NULL, 0, NULL, &m2, 1, 1);
        CHECK(same_triangle_set(&m, &m2));
        plateau_dt_free(&m2);
    }
    plateau_dt_free(&m);
    p[2 * n] = 0;
    p[2 * n + 1] = 0;
    run_check(p, n + 1, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, n);
    plateau_dt_free(&m);
    for (i = 0; i < 1000; i++) {
        p[2 * i] = cos(6.283185307179586 * (double)i / 1000.0);
        p[2 * i + 1] = sin(6.283185307179586 * (double)i / 1000.0);
    }
    run_check(p, 1000, NULL, 0, NULL, &m, 1, 1);
    plateau_dt_free(&m);
}

static void test_collinear(void)
{
    double p[2 * 60];
    size_t i;
    plateau_dt_mesh m;
    plateau_dt_input in;
    plateau_dt_error rep;
    for (i = 0; i < 50; i++) {
        p[2 * i] = (double)i;
        p[2 * i + 1] = 3.0 * (double)i - 7.0;
    }
    in.points = p;
    in.num_points = 50;
    in.segments = NULL;
    in.num_segments = 0;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_COLLINEAR);
    CHECK(m.num_triangles == 0 && m.triangles == NULL);
    plateau_dt_free(&m);
    /* collinear plus one point off the line: a fan of 49 triangles */
    p[100] = 10;
    p[101] = 50;
    run_check(p, 51, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, 49);
    plateau_dt_free(&m);
    /* two parallel lines of collinear points */
    for (i = 0; i < 30; i++) {
        p[2 * i] = (double)i * 0.5;
        p[2 * i + 1] = 0;
    }
    for (i = 0; i < 30; i++) {
        p[2 * (30 + i)] = (double)i * 0.5 + 0.25;
        p[2 * (30 + i) + 1] = 1;
    }
    run_check(p, 60, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, 58);
    plateau_dt_free(&m);
}

/* A square polygon of side 1 with k vertices per side (4k in all, long
 * straight sides) plus interior points; its boundary as segments. */
static void square_polygon(size_t k, size_t interior, double *p, plateau_index *seg)
{
    size_t i, n = 4 * k;
    for (i = 0; i < k; i++) {
        double t = (double)i / (double)k;
        p[2 * i] = t;            p[2 * i + 1] = 0;
        p[2 * (k + i)] = 1;      p[2 * (k + i) + 1] = t;
        p[2 * (2 * k + i)] = 1 - t; p[2 * (2 * k + i) + 1] = 1;
        p[2 * (3 * k + i)] = 0;  p[2 * (3 * k + i) + 1] = 1 - t;
    }
    for (i = 0; i < n; i++) {
        seg[2 * i] = (plateau_index)i;
        seg[2 * i + 1] = (plateau_index)((i + 1) % n);
    }
    for (i = 0; i < interior; i++) {
        p[2 * (n + i)] = 0.001 + 0.998 * rnd01();
        p[2 * (n + i) + 1] = 0.001 + 0.998 * rnd01();
    }
}

static void test_long_straight_sides(void)
{
    size_t k = 100, ni = 300, n = 4 * k + ni;
    double *p = (double *)malloc(2 * n * sizeof(double));
    plateau_index *seg = (plateau_index *)malloc(2 * 4 * k * sizeof(plateau_index));
    plateau_dt_mesh m;
    plateau_dt_options opt;
    square_polygon(k, ni, p, seg);
    run_check(p, n, seg, 4 * k, NULL, &m, 0, 1);
    CHECK_EQ_INT(m.num_triangles, 2 * n - 2 - 4 * k); /* no point lost, no sliver */
    plateau_dt_free(&m);
    /* only the 4 corners as segments: the collinear side vertices split them */
    {
        plateau_index corners[8];
        corners[0] = 0; corners[1] = (plateau_index)k;
        corners[2] = (plateau_index)k; corners[3] = (plateau_index)(2 * k);
        corners[4] = (plateau_index)(2 * k); corners[5] = (plateau_index)(3 * k);
        corners[6] = (plateau_index)(3 * k); corners[7] = 0;
        run_check(p, n, corners, 4, NULL, &m, 0, 1);
        CHECK_EQ_INT(m.num_triangles, 2 * n - 2 - 4 * k);
        plateau_dt_free(&m);
    }
    /* a non-convex polygon (an L) with collinear sides: triangles of the
     * notch are removed */
    {
        double L[2 * 64];
        plateau_index ls[2 * 64];
        size_t c = 0, i;
        for (i = 0; i < 10; i++) { L[2 * c] = 0.2 * (double)i; L[2 * c + 1] = 0; c++; }   /* bottom 0..1.8 */
        for (i = 0; i < 5; i++) { L[2 * c] = 2; L[2 * c + 1] = 0.2 * (double)i; c++; }    /* right 0..0.8 */
        for (i = 0; i < 5; i++) { L[2 * c] = 2 - 0.2 * (double)i; L[2 * c + 1] = 1; c++; }/* top of foot */
        for (i = 0; i < 5; i++) { L[2 * c] = 1; L[2 * c + 1] = 1 + 0.2 * (double)i; c++; }/* inner side */
        for (i = 0; i < 5; i++) { L[2 * c] = 1 - 0.2 * (double)i; L[2 * c + 1] = 2; c++; }/* top */
        for (i = 0; i < 10; i++) { L[2 * c] = 0; L[2 * c + 1] = 2 - 0.2 * (double)i; c++; }/* left */
        for (i = 0; i < c; i++) {
            ls[2 * i] = (plateau_index)i;
            ls[2 * i + 1] = (plateau_index)((i + 1) % c);
        }
        run_check(L, c, ls, c, NULL, &m, 0, 1);
        CHECK_EQ_INT(m.num_triangles, c - 2);
        {
            size_t t;
            long outside = 0;
            for (t = 0; t < m.num_triangles; t++) {
                const plateau_index *v = m.triangles + 3 * t;
                double cx = (L[2 * v[0]] + L[2 * v[1]] + L[2 * v[2]]) / 3;
                double cy = (L[2 * v[0] + 1] + L[2 * v[1] + 1] + L[2 * v[2] + 1]) / 3;
                if (cx > 1 && cy > 1) outside++;
            }
            CHECK_EQ_INT(outside, 0);
        }
        plateau_dt_free(&m);
        memset(&opt, 0, sizeof opt);
        opt.keep_convex_hull = 1;
        run_check(L, c, ls, c, &opt, &m, 1, 1);
        plateau_dt_free(&m);
    }
    free(p);
    free(seg);
}

static void test_duplicates(void)
{
    double p[2 * 200];
    size_t i, n = 120;
    plateau_dt_mesh m;
    for (i = 0; i < 80; i++) {
        p[2 * i] = rnd01();
        p[2 * i + 1] = rnd01();
    }
    /* a copy placed before its original: the smaller index is kept */
    p[2 * 0] = p[2 * 79];
    p[2 * 0 + 1] = p[2 * 79 + 1];
    for (i = 80; i < n; i++) { /* copies of earlier points */
        size_t k = (size_t)(rnd_u64() % 80);
        p[2 * i] = p[2 * k];
        p[2 * i + 1] = p[2 * k + 1];
    }
    run_check(p, n, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.duplicate_of[79], 0);
    CHECK_EQ_INT(m.duplicate_of[0], 0);
    {
        long dups = 0;
        for (i = 0; i < n; i++) dups += m.duplicate_of[i] != (plateau_index)i;
        CHECK_EQ_INT(dups, 41);
    }
    plateau_dt_free(&m);
    /* all points equal but three */
    for (i = 0; i < 50; i++) {
        p[2 * i] = 0.5;
        p[2 * i + 1] = 0.5;
    }
    p[2 * 10] = 1; p[2 * 20 + 1] = 1; p[2 * 30] = 0;
    run_check(p, 50, NULL, 0, NULL, &m, 1, 1);
    CHECK_EQ_INT(m.num_triangles, 2); /* (1,.5), (.5,1), (0,.5); (.5,.5) on the hull */
    CHECK_EQ_INT(m.duplicate_of[49], 0);
    plateau_dt_free(&m);
    /* a segment given between duplicates of its endpoints */
    {
        double q[2 * 6] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 1, 0, 0};
        plateau_index s[8] = {5, 1, 1, 4, 2, 3, 3, 0};
        run_check(q, 6, s, 4, NULL, &m, 0, 1);
        CHECK_EQ_INT(m.num_triangles, 2);
        CHECK_EQ_INT(m.duplicate_of[4], 2);
        CHECK_EQ_INT(m.duplicate_of[5], 0);
        plateau_dt_free(&m);
    }
}

static void test_tiny_and_huge(void)
{
    /* the same point set at several scales: powers of two give exactly the
     * same triangles; 1e-150 and 1e150 give a valid triangulation */
    double scales[5];
    size_t n = 400, i, s;
    double *p = (double *)malloc(2 * n * sizeof(double)), *q = (double *)malloc(2 * n * sizeof(double));
    plateau_dt_mesh m, m2;
    scales[0] = ldexp(1.0, -1000);
    scales[1] = 1e-150;
    scales[2] = 1e150;
    scales[3] = ldexp(1.0, 1000);
    scales[4] = ldexp(1.0, -199);
    for (i = 0; i < n; i++) { /* a grid (co-circular) and random points */
        if (i < 100) {
            p[2 * i] = (double)(i % 10);
            p[2 * i + 1] = (double)(i / 10);
        } else {
            p[2 * i] = rnd01() * 9;
            p[2 * i + 1] = rnd01() * 9;
        }
    }
    run_check(p, n, NULL, 0, NULL, &m, 1, 1);
    for (s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        for (i = 0; i < 2 * n; i++) q[i] = p[i] * scales[s];
        run_check(q, n, NULL, 0, NULL, &m2, 1, 1);
        if (scales[s] != 1e-150 && scales[s] != 1e150) {
            CHECK_EQ_INT(m2.num_triangles, m.num_triangles);
            CHECK(m2.num_triangles == m.num_triangles &&
                  memcmp(m.triangles, m2.triangles, 3 * m.num_triangles * sizeof(plateau_index)) == 0);
        }
        plateau_dt_free(&m2);
    }
    /* subnormal coordinates: integers times 2^-1070 */
    for (i = 0; i < 100; i++) {
        q[2 * i] = ldexp(p[2 * i], -1066); /* subnormal, exact */
        q[2 * i + 1] = ldexp(p[2 * i + 1], -1066);
    }
    {
        plateau_dt_mesh g;
        run_check(p, 100, NULL, 0, NULL, &g, 1, 1);
        run_check(q, 100, NULL, 0, NULL, &m2, 1, 1);
        CHECK(m2.num_triangles == g.num_triangles &&
              memcmp(g.triangles, m2.triangles, 3 * g.num_triangles * sizeof(plateau_index)) == 0);
        plateau_dt_free(&g);
        plateau_dt_free(&m2);
    }
    /* both extremes in one input: a 1e150 quadrilateral with a 1e-150
     * cluster inside; the cluster stays a set of distinct points (the exact
     * predicates rescale coordinate differences locally, or use integers) */
    {
        double c[2 * 9] = {-1e150, -1e150, 1e150, -1e150, 1e150, 1e150, -1e150, 1e150,
                           0, 0, 1e-150, 0, 0, 1e-150, 1e-150, 1e-150, 3e-151, 7e-151};
        plateau_index sq[8] = {0, 1, 1, 2, 2, 3, 3, 0};
        run_check(c, 9, sq, 4, NULL, &m2, 0, 1); /* the square centred on the cluster */
        CHECK_EQ_INT(m2.num_triangles, 2 * 9 - 2 - 4);
        plateau_dt_free(&m2);
    }
    {
        double c[2 * 9] = {-1e150, -0.7e150, 1.1e150, -1e150, 0.9e150, 1.2e150, -1.05e150, 0.8e150,
                           0, 0, 1e-150, 0, 0, 1e-150, 1e-150, 1e-150, 3e-151, 7e-151};
        plateau_index sq[8] = {0, 1, 1, 2, 2, 3, 3, 0};
        run_check(c, 9, sq, 4, NULL, &m2, 0, 1);
        CHECK_EQ_INT(m2.num_triangles, 2 * 9 - 2 - 4);
        plateau_dt_free(&m2);
    }
    /* a domain at 1e-150 and at 1e150 */
    {
        size_t k = 20, ni = 50, nn = 4 * k + ni;
        double *pp = (double *)malloc(2 * nn * sizeof(double));
        plateau_index *seg = (plateau_index *)malloc(2 * 4 * k * sizeof(plateau_index));
        square_polygon(k, ni, pp, seg);
        for (i = 0; i < 2 * nn; i++) pp[i] *= 1e-150;
        run_check(pp, nn, seg, 4 * k, NULL, &m2, 0, 1);
        plateau_dt_free(&m2);
        for (i = 0; i < 2 * nn; i++) pp[i] *= 1e300;
        run_check(pp, nn, seg, 4 * k, NULL, &m2, 0, 1);
        plateau_dt_free(&m2);
        free(pp);
        free(seg);
    }
    plateau_dt_free(&m);
    free(p);
    free(q);
}

/* outer square [0,10]^2 (4 vertices per side), holes [2,4]^2 and [6,8]x[2,8]
 * given clockwise or counter-clockwise, an island [6.5,7.5]x[4,6] inside
 * the second hole, and random points everywhere */
static void test_holes(void)
{
    double p[2 * 600];
    plateau_index s[2 * 64];
    size_t n = 0, ns = 0, i, loop0;
    plateau_dt_mesh m;
    static const double boxes[4][4] = {{0, 0, 10, 10}, {2, 2, 4, 4}, {6, 2, 8, 8}, {6.5, 4, 7.5, 6}};
    int b;
    for (b = 0; b < 4; b++) {
        double x0 = boxes[b][0], y0 = boxes[b][1], x1 = boxes[b][2], y1 = boxes[b][3];
        double cx[4], cy[4];
        int c;
        loop0 = n;
        cx[0] = x0; cy[0] = y0; cx[1] = x1; cy[1] = y0; cx[2] = x1; cy[2] = y1; cx[3] = x0; cy[3] = y1;
        for (c = 0; c < 4; c++) {
            int j;
            for (j = 0; j < 4; j++) {
                int cc = (b == 1) ? 3 - c : c; /* hole 1 clockwise */
                int nc = (b == 1) ? (cc + 3) % 4 : (cc + 1) % 4;
                p[2 * n] = cx[cc] + (cx[nc] - cx[cc]) * j / 4.0;
                p[2 * n + 1] = cy[cc] + (cy[nc] - cy[cc]) * j / 4.0;
                n++;
            }
        }
        for (i = loop0; i < n; i++) {
            s[2 * ns] = (plateau_index)i;
            s[2 * ns + 1] = (plateau_index)(i + 1 < n ? i + 1 : loop0);
            ns++;
        }
    }
    for (i = 0; i < 300; i++) {
        p[2 * n] = 0.01 + 9.98 * rnd01();
        p[2 * n + 1] = 0.01 + 9.98 * rnd01();
        n++;
    }
    /* domain: square minus two holes (chi = -1) plus the island (chi = 1) */
    run_check(p, n, s, ns, NULL, &m, 0, 0);
    {
        size_t t;
        long wrong = 0;
        double area = 0;
        for (t = 0; t < m.num_triangles; t++) {
            const plateau_index *v = m.triangles + 3 * t;
            const double *a = p + 2 * v[0], *bb = p + 2 * v[1], *c = p + 2 * v[2];
            double gx = (a[0] + bb[0] + c[0]) / 3, gy = (a[1] + bb[1] + c[1]) / 3;
            int in_h1 = gx > 2 && gx < 4 && gy > 2 && gy < 4;
            int in_h2 = gx > 6 && gx < 8 && gy > 2 && gy < 8;
            int in_isl = gx > 6.5 && gx < 7.5 && gy > 4 && gy < 6;
            if (in_h1 || (in_h2 && !in_isl)) wrong++;
            area += 0.5 * ((bb[0] - a[0]) * (c[1] - a[1]) - (bb[1] - a[1]) * (c[0] - a[0]));
        }
        CHECK_EQ_INT(wrong, 0);
        CHECK_NEAR(area, 100 - 4 - 12 + 2, 1e-9);
    }
    plateau_dt_free(&m);
    /* without the island: chi = 1 - 2 */
    run_check(p, n, s, ns - 16, NULL, &m, 0, -1);
    plateau_dt_free(&m);
}

static void test_points_on_segments(void)
{
    /* points exactly on a segment split it; overlapping collinear segments */
    double p[2 * 9] = {0, 0, 10, 0, 10, 5, 0, 5, 3, 0, 7, 0, 5, 5, 5, 2, 1, 1};
    plateau_index s[2 * 6] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7};
    plateau_dt_mesh m;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1; /* (6, 7) dangles: an open chain */
    run_check(p, 9, s, 6, &opt, &m, 1, 1);
    {
        size_t t;
        int k, found = 0;
        for (t = 0; t < m.num_triangles; t++)
            for (k = 0; k < 3; k++) {
                plateau_index a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3];
                if (!m.constrained[3 * t + k]) continue;
                if ((a == 0 && b == 4) || (a == 4 && b == 5) || (a == 5 && b == 1) ||
                    (a == 2 && b == 6) || (a == 6 && b == 3) || (a == 6 && b == 7))
                    found++;
            }
        CHECK_EQ_INT(found, 6); /* each sub-edge once, from the inner side */
    }
    plateau_dt_free(&m);
    opt.keep_convex_hull = 0;
    CHECK_EQ_INT(run(p, 9, s, 6, &opt, &m), PLATEAU_DT_ERR_OPEN_BOUNDARY);
    run_check(p, 9, s, 4, &opt, &m, 0, 1); /* the rectangle alone */
    CHECK_EQ_INT(m.num_triangles, 2 * 9 - 2 - 7);
    plateau_dt_free(&m);
}

/* Inner segments (options.inner_segments): an open polyline and a
 * closed ring inside a square bound nothing: the whole square is kept
 * (its area), every inner edge is a constrained edge of the result, also
 * after a refinement that keeps segments whole; without the option the
 * open chain is refused, and more inner segments than segments too. */
static void test_inner_segments(void)
{
    static const double p[2 * 11] = {0, 0, 10, 0, 10, 10, 0, 10, 2, 5, 5, 5, 8, 5, 6, 7, 7, 7, 7, 8, 6, 8};
    static const plateau_index s[2 * 10] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 7, 8, 8, 9, 9, 10, 10, 7};
    plateau_dt_options opt;
    plateau_dt_mesh m;
    int pass;
    memset(&opt, 0, sizeof opt);
    CHECK_EQ_INT(run(p, 11, s, 10, &opt, &m), PLATEAU_DT_ERR_OPEN_BOUNDARY);
    opt.inner_segments = 11;
    CHECK_EQ_INT(run(p, 11, s, 10, &opt, &m), PLATEAU_DT_ERR_ARGUMENT);
    opt.inner_segments = 6;
    for (pass = 0; pass < 2; pass++) {
        size_t t, k, i;
        double area = 0.0;
        if (pass) {
            opt.min_angle = 25.0;
            opt.max_area = 2.0;
            opt.keep_segments = 1;
        }
        CHECK_EQ_INT(run(p, 11, s, 10, &opt, &m), PLATEAU_DT_OK);
        for (t = 0; t < m.num_triangles; t++) {
            const double *a = m.points + 2 * m.triangles[3 * t], *b = m.points + 2 * m.triangles[3 * t + 1],
                         *c = m.points + 2 * m.triangles[3 * t + 2];
            area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        }
        CHECK_NEAR(area, 100.0, 1e-9);
        for (i = 4; i < 10; i++) {
            int found = 0;
            for (t = 0; t < m.num_triangles; t++)
                for (k = 0; k < 3; k++) {
                    plateau_index a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3];
                    if (m.constrained[3 * t + k] && ((a == s[2 * i] && b == s[2 * i + 1]) ||
                                                     (b == s[2 * i] && a == s[2 * i + 1])))
                        found++;
                }
            CHECK_EQ_INT(found, 2); /* the edge from both sides: inside the domain */
        }
        if (pass) CHECK(m.num_points > 11);
        plateau_dt_free(&m);
    }
}

static void test_long_segment_many_flips(void)
{
    /* one segment across many random points (keep the hull) and a zigzag
     * of segments: recovered by flips, constrained Delaunay afterwards */
    size_t n = 2000, i;
    double *p = (double *)malloc(2 * (n + 8) * sizeof(double));
    plateau_index s[2 * 8];
    plateau_dt_mesh m;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    for (i = 0; i < n; i++) {
        p[2 * i] = rnd01();
        p[2 * i + 1] = rnd01();
    }
    p[2 * n] = -0.1; p[2 * n + 1] = 0.5;
    p[2 * n + 2] = 1.1; p[2 * n + 3] = 0.51;
    p[2 * n + 4] = 0.5; p[2 * n + 5] = -0.1;
    p[2 * n + 6] = 0.52; p[2 * n + 7] = 1.1;
    s[0] = (plateau_index)n; s[1] = (plateau_index)n + 1;
    run_check(p, n + 2, s, 1, &opt, &m, 1, 1);
    plateau_dt_free(&m);
    s[2] = (plateau_index)n + 2; s[3] = (plateau_index)n + 3;
    CHECK_EQ_INT(run(p, n + 4, s, 2, &opt, &m), PLATEAU_DT_ERR_CROSSING_SEGMENTS);
    plateau_dt_free(&m);
    free(p);
}

static void test_determinism(void)
{
    size_t k = 30, ni = 500, n = 4 * k + ni, i;
    double *p = (double *)malloc(2 * n * sizeof(double)), *q = (double *)malloc(2 * n * sizeof(double));
    plateau_index *seg = (plateau_index *)malloc(2 * 4 * k * sizeof(plateau_index));
    plateau_index *perm = (plateau_index *)malloc(n * sizeof(plateau_index)), *inv;
    plateau_index *seg2 = (plateau_index *)malloc(2 * 4 * k * sizeof(plateau_index));
    plateau_dt_mesh a, b;
    plateau_dt_options opt;
    square_polygon(k, ni, p, seg);
    for (i = 0; i < 60; i++) { /* some grid points too (co-circular ties) */
        p[2 * (4 * k + i)] = 0.1 + 0.1 * (double)(i % 8);
        p[2 * (4 * k + i) + 1] = 0.1 + 0.1 * (double)(i / 8);
    }
    run_check(p, n, seg, 4 * k, NULL, &a, 0, 1);
    run_check(p, n, seg, 4 * k, NULL, &b, 0, 1);
    CHECK(same_mesh(&a, &b));
    plateau_dt_free(&b);
    /* a different seed: same set */
    memset(&opt, 0, sizeof opt);
    opt.seed = 987654321ul;
    run_check(p, n, seg, 4 * k, &opt, &b, 0, 1);
    CHECK(same_triangle_set(&a, &b));
    plateau_dt_free(&b);
    /* a permuted input: same set */
    for (i = 0; i < n; i++) perm[i] = (plateau_index)i;
    for (i = n - 1; i > 0; i--) {
        size_t j = (size_t)(rnd_u64() % (i + 1));
        plateau_index t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    inv = (plateau_index *)malloc(n * sizeof(plateau_index));
    for (i = 0; i < n; i++) {
        q[2 * i] = p[2 * perm[i]];
        q[2 * i + 1] = p[2 * perm[i] + 1];
        inv[perm[i]] = (plateau_index)i;
    }
    for (i = 0; i < 4 * k; i++) { /* segments renumbered and in reverse order */
        seg2[2 * i] = inv[seg[2 * (4 * k - 1 - i) + 1]];
        seg2[2 * i + 1] = inv[seg[2 * (4 * k - 1 - i)]];
    }
    run_check(q, n, seg2, 4 * k, NULL, &b, 0, 1);
    CHECK(same_triangle_set(&a, &b));
    plateau_dt_free(&a);
    plateau_dt_free(&b);
    free(p); free(q); free(seg); free(seg2); free(perm); free(inv);
}

/* split_crossing_segments: random segments that cross each other are split
 * at new vertices; every crossing gives one vertex where four constrained
 * edges meet, close to both segments */
/* Two nearly parallel segments from one point crossed by a third, nearly
 * parallel too, near that point: the crossings coincide to rounding, so at
 * most two vertices are added and no triangle has three constrained edges
 * (the rounded crossing vertices used to cascade into clusters of up to 9
 * vertices joined by tiny all-constrained triangles). */
static void test_split_crossing_coinciding(void)
{
    int trial, too_many = 0, closed = 0, failed = 0, one = 0;
    uint64_t saved = rng_state;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    opt.split_crossing_segments = 1;
    for (trial = 0; trial < 3000; trial++) {
        double ang = rnd01() * 6.28, eps = pow(10, -16 + 6 * rnd01()), dd = pow(10, -13 + 13 * rnd01());
        double len3 = pow(10, -3 + 3 * rnd01()), ox = rnd01(), oy = rnd01(), len = 1 + rnd01();
        double cang = ang + (rnd01() - 0.5) * 0.05, px = ox + dd * cos(ang), py = oy + dd * sin(ang);
        double pts[18];
        plateau_index seg[6] = {0, 1, 0, 2, 3, 4};
        plateau_dt_mesh m;
        size_t t;
        pts[0] = ox; pts[1] = oy;
        pts[2] = ox + len * cos(ang); pts[3] = oy + len * sin(ang);
        pts[4] = ox + len * cos(ang + eps); pts[5] = oy + len * sin(ang + eps);
        pts[6] = px - len3 * cos(cang); pts[7] = py - len3 * sin(cang);
        pts[8] = px + len3 * cos(cang); pts[9] = py + len3 * sin(cang);
        pts[10] = -2; pts[11] = -2; pts[12] = 3; pts[13] = -2;
        pts[14] = 3; pts[15] = 3; pts[16] = -2; pts[17] = 3;
        if (run(pts, 9, seg, 3, &opt, &m) != PLATEAU_DT_OK) { failed++; continue; }
        if (m.num_points > 11) too_many++;
        if (m.num_points == 10) one++;
        for (t = 0; t < m.num_triangles; t++)
            if (m.constrained[3 * t] && m.constrained[3 * t + 1] && m.constrained[3 * t + 2]) {
                /* a genuine triangle between three segments has a vertex
                 * at least 1e-10 (the rounding tolerance being 2e-12) away */
                const plateau_index *v = m.triangles + 3 * t;
                double l = 0;
                int k;
                for (k = 0; k < 3; k++) {
                    const double *a = m.points + 2 * v[k], *b = m.points + 2 * v[(k + 1) % 3];
                    double dl = fabs(a[0] - b[0]) + fabs(a[1] - b[1]);
                    if (dl > l) l = dl;
                }
                if (l < 1e-10) closed++;
            }
        plateau_dt_free(&m);
    }
    rng_state = saved;
    CHECK_EQ_INT(failed, 0);
    CHECK_EQ_INT(too_many, 0);
    CHECK_EQ_INT(closed, 0);
    CHECK(one > 1000); /* most crossings pairs coincide to rounding */
}

static void test_split_crossing(void)
{
    size_t ns = 25, n = 2 * ns + 200, i, j, crossings = 0;
    double *p = (double *)malloc(2 * n * sizeof(double));
    plateau_index *s = (plateau_index *)malloc(2 * ns * sizeof(plateau_index));
    plateau_dt_mesh m;
    plateau_dt_options opt;
    plateau_dt_input in;
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    opt.split_crossing_segments = 1;
    for (i = 0; i < 2 * n; i++) p[i] = rnd01();
    for (i = 0; i < ns; i++) {
        s[2 * i] = (plateau_index)(2 * i);
        s[2 * i + 1] = (plateau_index)(2 * i + 1);
    }
    for (i = 0; i < ns; i++)
        for (j = i + 1; j < ns; j++) {
            const double *a = p + 4 * i, *b = p + 4 * i + 2, *c = p + 4 * j, *d = p + 4 * j + 2;
            if (plateau_dt_orient(a, b, c) * plateau_dt_orient(a, b, d) < 0 &&
                plateau_dt_orient(c, d, a) * plateau_dt_orient(c, d, b) < 0)
                crossings++;
        }
    CHECK(crossings > 10);
    in.points = p; in.num_points = n; in.segments = s; in.num_segments = ns;
    CHECK_EQ_INT(run(p, n, s, ns, &opt, &m), PLATEAU_DT_OK);
    CHECK_EQ_INT(m.num_points, n + crossings);
    {
        plateau_dt_input in0 = in;
        in0.num_segments = 0; /* the chains are not straight: checked below */
        check_mesh(&in0, &m, 0, 1);
    }
    {
        long *deg = (long *)calloc(m.num_points, sizeof(long));
        long cedges = 0, bad = 0;
        size_t t;
        int k;
        for (t = 0; t < m.num_triangles; t++)
            for (k = 0; k < 3; k++) {
                plateau_index u = m.neighbors[3 * t + k];
                if (!m.constrained[3 * t + k]) continue;
                if (u >= 0 && (size_t)u < t) continue; /* count each edge once */
                cedges++;
                deg[m.triangles[3 * t + k]]++;
                deg[m.triangles[3 * t + (k + 1) % 3]]++;
            }
        CHECK_EQ_INT(cedges, (long)(ns + 2 * crossings));
        for (i = n; i < m.num_points; i++) {
            /* near two of the segments */
            int near = 0;
            for (j = 0; j < ns; j++) {
                const double *a = p + 4 * j, *b = p + 4 * j + 2, *x = m.points + 2 * i;
                double cr = (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]);
                if (fabs(cr) < 1e-12) near++;
            }
            if (deg[i] != 4 || near != 2) bad++;
        }
        CHECK_EQ_INT(bad, 0);
        free(deg);
    }
    plateau_dt_free(&m);
    /* as a domain: a square with both diagonals is four triangles' worth */
    {
        double q[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        plateau_index sq[12] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
        opt.keep_convex_hull = 0;
        CHECK_EQ_INT(run(q, 4, sq, 6, &opt, &m), PLATEAU_DT_OK);
        CHECK_EQ_INT(m.num_triangles, 4);
        CHECK_EQ_INT(m.num_points, 5);
        CHECK(m.points[8] == 0.5 && m.points[9] == 0.5);
        plateau_dt_free(&m);
    }
    free(p);
    free(s);
}

/* random small inputs: snapped to a coarse grid (many collinear, co-circular
 * and duplicate points), random segments (some crossing, some through
 * points, some repeated), all option combinations: the result is OK or the
 * expected named error, and every OK result passes check_mesh */
static void test_fuzz(void)
{
    int iter, bad_code = 0, ok_runs = 0, split_gave_up = 0;
    double p[2 * 64];
    plateau_index s[2 * 24];
#if defined(TEST_DELAUNAY_FUZZ_ITERS)
    int iters = TEST_DELAUNAY_FUZZ_ITERS; /* long runs by hand */
#elif defined(PLATEAU_TEST_SANITIZED)
    int iters = 150;
#else
    int iters = 1500;
#endif
    for (iter = 0; iter < iters; iter++) {
        size_t n = 3 + (size_t)(rnd_u64() % 40), ns = (size_t)(rnd_u64() % 12), i;
        int grid = 2 + (int)(rnd_u64() % 6), mode = (int)(rnd_u64() % 4);
        plateau_dt_options opt;
        plateau_dt_mesh m;
        plateau_dt_input in;
        plateau_dt_error rep;
        plateau_dt_result r;
        double scale = (rnd_u64() & 1) ? 1.0 : ldexp(1.0, (int)(rnd_u64() % 400) - 200);
        for (i = 0; i < 2 * n; i++) {
            p[i] = (double)(rnd_u64() % (uint64_t)grid) * scale;
            /* a few ulps off the grid (not at 0: a subnormal next to 1 is
             * beyond the documented 2^400 range of exactness) */
            if ((iter & 3) == 3 && p[i] != 0 && (rnd_u64() & 1))
                p[i] = nextafter(nextafter(p[i], 1e300), (rnd_u64() & 1) ? 1e300 : -1e300);
        }
        for (i = 0; i < ns; i++) {
            s[2 * i] = (plateau_index)(rnd_u64() % n);
            s[2 * i + 1] = (plateau_index)(rnd_u64() % n);
            if (s[2 * i] == s[2 * i + 1]) s[2 * i + 1] = (plateau_index)((s[2 * i] + 1) % n);
        }
        memset(&opt, 0, sizeof opt);
        opt.keep_convex_hull = mode & 1;
        opt.split_crossing_segments = (mode >> 1) & 1;
        if (iter % 5 == 4) { /* refinement too, on a budget */
            opt.min_angle = 20 + (double)(rnd_u64() % 14);
            opt.max_area = (rnd_u64() & 1) ? 0.0 : 0.01 * (double)grid * (double)grid * scale * scale;
            opt.max_added_points = 800;
            opt.keep_segments = (int)(rnd_u64() & 1);
        }
        in.points = p; in.num_points = n; in.segments = s; in.num_segments = ns;
        r = plateau_dt_triangulate(&in, &opt, &m, &rep);
        if (r == PLATEAU_DT_OK) {
            plateau_dt_input in0 = in;
            ok_runs++;
            /* chains bent through added or snapped vertices, and segments
             * outside the domain (one joining two loops from outside), are
             * not straight chains of the output: checked elsewhere */
            int refined = opt.min_angle > 0;
            if (opt.split_crossing_segments || !opt.keep_convex_hull || refined) in0.num_segments = 0;
            check_mesh(&in0, &m, (opt.keep_convex_hull || ns == 0) && !refined, NO_EULER);
        } else if (!(r == PLATEAU_DT_ERR_TOO_FEW_POINTS || r == PLATEAU_DT_ERR_COLLINEAR ||
                     r == PLATEAU_DT_ERR_DEGENERATE_SEGMENT ||
                     r == PLATEAU_DT_ERR_CROSSING_SEGMENTS ||
                     (r == PLATEAU_DT_ERR_OPEN_BOUNDARY && !opt.keep_convex_hull))) {
            bad_code++;
            fprintf(stderr, "fuzz %d: %s (%s)\n", iter, plateau_dt_result_string(r), rep.message);
        }
        if (r == PLATEAU_DT_ERR_CROSSING_SEGMENTS && opt.split_crossing_segments) split_gave_up++;
        if (r != PLATEAU_DT_OK) CHECK(m.triangles == NULL && rep.message[0] != '\0');
        plateau_dt_free(&m);
    }
    CHECK_EQ_INT(bad_code, 0);
    CHECK(ok_runs > iters / 4);
    CHECK(split_gave_up <= iters / 1000); /* splitting gives up only in rare cascades */
}

static double area_limit_fn(double x, double y, void *user)
{
    (void)y;
    (void)user;
    return 1e-4 + 0.01 * x * x;
}
/* ------------------------------------------------------------ refinement */
static double tri_min_angle(const plateau_dt_mesh *m, size_t t)
{
    const plateau_index *v = m->triangles + 3 * t;
    double best = 180;
    int k;
    for (k = 0; k < 3; k++) {
        const double *a = m->points + 2 * v[k], *b = m->points + 2 * v[(k + 1) % 3];
        const double *c = m->points + 2 * v[(k + 2) % 3];
        double ux = b[0] - a[0], uy = b[1] - a[1], wx = c[0] - a[0], wy = c[1] - a[1];
        double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 57.29577951308232;
        if (ang < best) best = ang;
    }
    return best;
}
static double tri_area(const plateau_dt_mesh *m, size_t t)
{
    const plateau_index *v = m->triangles + 3 * t;
    const double *a = m->points + 2 * v[0], *b = m->points + 2 * v[1], *c = m->points + 2 * v[2];
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

/* every input segment is the union of its sub-edges: its end points, the
 * input points on it and the added points with segment_of == s, in order,
 * joined by constrained edges */
static long check_segments_split(const plateau_dt_input *in, const plateau_dt_mesh *m)
{
    size_t ne = 3 * m->num_triangles, t, i, j;
    edge_rec *e = (edge_rec *)malloc((ne + 1) * sizeof *e);
    along_rec *al = (along_rec *)malloc((m->num_points + 1) * sizeof *al);
    long bad = 0;
    for (t = 0; t < ne; t++) {
        plateau_index a = m->triangles[t], b = m->triangles[t - t % 3 + (t % 3 + 1) % 3];
        e[t].lo = a < b ? a : b;
        e[t].hi = a < b ? b : a;
        e[t].tk = (long)t;
    }
    qsort(e, ne, sizeof *e, edge_cmp);
    for (i = 0; i < in->num_segments; i++) {
        plateau_index a = m->duplicate_of[in->segments[2 * i]], b = m->duplicate_of[in->segments[2 * i + 1]];
        const double *pa = m->points + 2 * a, *pb = m->points + 2 * b;
        double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
        size_t na = 0;
        for (j = 0; j < m->num_points; j++) {
            const double *q = m->points + 2 * j;
            int on;
            if (j < m->num_input_points) {
                if ((size_t)m->duplicate_of[j] != j || plateau_dt_orient(pa, pb, q) != 0) continue;
                on = q[0] >= fmin(pa[0], pb[0]) && q[0] <= fmax(pa[0], pb[0]) &&
                     q[1] >= fmin(pa[1], pb[1]) && q[1] <= fmax(pa[1], pb[1]);
            } else {
                on = m->segment_of[j] == (plateau_index)i;
            }
            if (!on) continue;
            al[na].t = (q[0] - pa[0]) * dx + (q[1] - pa[1]) * dy;
            al[na].v = (plateau_index)j;
            na++;
        }
        qsort(al, na, sizeof *al, along_cmp);
        if (na < 2 || al[0].v != a || al[na - 1].v != b) bad++;
        for (j = 0; j + 1 < na; j++) {
            long k = find_edge(e, ne, al[j].v, al[j + 1].v);
            if (k < 0 || !m->constrained[e[k].tk]) bad++;
        }
    }
    free(e);
    free(al);
    return bad;
}

/* refine, then check: valid constrained Delaunay mesh, Euler, the angle
 * bound everywhere but in num_unrefined triangles, the area bound, and the
 * segments as unions of sub-edges */
static void refine_check(const double *p, size_t n, const plateau_index *seg, size_t ns,
                         const plateau_dt_options *opt, int euler, plateau_dt_mesh *m)
{
    plateau_dt_input in;
    size_t t;
    long below = 0, big = 0;
    CHECK_EQ_INT(run(p, n, seg, ns, opt, m), PLATEAU_DT_OK);
    in.points = p; in.num_points = n; in.segments = NULL; in.num_segments = 0;
    /* (not checked as a hull: rounded split points on hull edges may make
     * the boundary non-convex by an ulp) */
    check_mesh(&in, m, 0, euler);
    CHECK_EQ_INT(m->refine_stop, PLATEAU_DT_REFINE_DONE);
    for (t = 0; t < m->num_triangles; t++) {
        if (opt->min_angle > 0 && tri_min_angle(m, t) < opt->min_angle - 1e-7) below++;
        if (opt->max_area > 0 && tri_area(m, t) > opt->max_area * (1 + 1e-9)) big++;
    }
    CHECK(below + big <= (long)m->num_unrefined);
    in.segments = seg;
    in.num_segments = ns;
    CHECK_EQ_INT(check_segments_split(&in, m), 0);
}

static void test_refine_quality(void)
{
    plateau_dt_options opt;
    plateau_dt_mesh m, m2;
    size_t i;
    memset(&opt, 0, sizeof opt);
    /* a square with a triangular hole: 30 degrees and an area limit */
    {
        double p[14] = {0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.4, 0.6, 0.4, 0.5, 0.6};
        plateau_index s[14] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4};
        double area = 0;
        opt.min_angle = 30;
        opt.max_area = 1e-3;
        refine_check(p, 7, s, 7, &opt, 0, &m);
        CHECK_EQ_INT(m.num_unrefined, 0);
        CHECK(m.num_triangles > 980);
        for (i = 0; i < m.num_triangles; i++) area += tri_area(&m, i);
        CHECK_NEAR(area, 0.98, 1e-12);
        /* deterministic */
        refine_check(p, 7, s, 7, &opt, 0, &m2);
        CHECK(same_mesh(&m, &m2));
        plateau_dt_free(&m2);
        plateau_dt_free(&m);
        /* 33 degrees, angle only */
        opt.max_area = 0;
        opt.min_angle = 33;
        refine_check(p, 7, s, 7, &opt, 0, &m);
        CHECK_EQ_INT(m.num_unrefined, 0);
        plateau_dt_free(&m);
    }
    /* a disk (96-gon) and a polygon with two holes */
    {
        double p[2 * 200];
        plateau_index s[2 * 200];
        size_t n = 96, ns = 96;
        for (i = 0; i < n; i++) {
            p[2 * i] = cos(6.283185307179586 * (double)i / (double)n);
            p[2 * i + 1] = sin(6.283185307179586 * (double)i / (double)n);
            s[2 * i] = (plateau_index)i;
            s[2 * i + 1] = (plateau_index)((i + 1) % n);
        }
        opt.min_angle = 32;
        opt.max_area = 0.002;
        refine_check(p, n, s, ns, &opt, 1, &m);
        CHECK_EQ_INT(m.num_unrefined, 0);
        plateau_dt_free(&m);
    }
    {
        double p[2 * 12] = {0, 0, 10, 0, 10, 6, 0, 6, 2, 2, 2, 4, 4, 4, 4, 2, 6, 1, 6, 5, 8, 5, 8, 1};
        plateau_index s[2 * 12] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9, 9, 10, 10, 11, 11, 8};
        opt.min_angle = 28;
        opt.max_area = 0.05;
        refine_check(p, 12, s, 12, &opt, -1, &m);
        CHECK_EQ_INT(m.num_unrefined, 0);
        plateau_dt_free(&m);
    }
}

/* The square [0,10]^2 (sides as segments, hull kept) with two segments
 * from (5,5): to (9,5) and to (5,5) + 4 (cos a, sin a).  For every input
 * angle a = 1..29 degrees and min_angle 20, 25, 30 the refinement ends
 * (DONE), with a vertex count within 8 times that of a = 20 (the shells
 * down to the apex grow like log(1 / sin a): at most 112 vertices against
 * 17 at 30 degrees), and every triangle below min_angle lies inside the
 * small angle (centroid in the sector of angle a and radius 4 at (5,5))
 * with all its angles at least arctan(sin a / (2 - cos a)).  Before the
 * Terminator rule, a = 5, 10, 12, 14 at 30 degrees ran into the budget
 * (4 194 381 vertices). */
/* White box: a vertex ring that never closes (a corrupted triangulation)
 * makes the refinement's ring walk return PLATEAU_DT_ERR_INTERNAL, as the
 * manual promises for every loop bound (it used to stop silently). */
static void test_broken_ring_is_internal_error(void)
{
    plateau__dt d;
    plateau__dt_refiner q;
    plateau_index tv[6] = {1, 2, 3, 1, 3, 4}, ta[6] = {-1, -1, 3, 2, -1, 3}, vt[5] = {-1, 0, -1, -1, -1};
    unsigned char tc[6] = {0, 0, 0, 0, 0, 0}, tin[2] = {0, 0};
    memset(&d, 0, sizeof d);
    memset(&q, 0, sizeof q);
    d.tv = tv;
    d.ta = ta;
    d.tc = tc;
    d.tin = tin;
    d.vt = vt;
    d.nt = 2;
    d.nv = 5;
    /* from half-edge 0 the walk goes to 3 and then stays there */
    CHECK_EQ_INT(plateau__dt_after_insert(&d, &q, 1), PLATEAU_DT_ERR_INTERNAL);
}

static void test_refine_input_angles(void)
{
    static const double mas[3] = {20, 25, 30};
    plateau_index seg[12] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 4, 6};
    int mi, ai;
    for (mi = 0; mi < 3; mi++) {
        long not_done = 0, outside = 0, below_bound = 0, too_many = 0, max_nv = 0, nv20 = 0;
        long nv[30];
        plateau_dt_options opt;
        memset(&opt, 0, sizeof opt);
        opt.keep_convex_hull = 1;
        opt.min_angle = mas[mi];
        opt.max_added_points = 100000;
        for (ai = 1; ai <= 29; ai++) {
            double a = ai * 0.017453292519943295;
            double p[14] = {0, 0, 10, 0, 10, 10, 0, 10, 5, 5, 9, 5, 0, 0};
            double bound = atan(sin(a) / (2 - cos(a))) * 57.29577951308232;
            plateau_dt_mesh m;
            size_t t;
            p[12] = 5 + 4 * cos(a);
            p[13] = 5 + 4 * sin(a);
            if (!CHECK_EQ_INT(run(p, 7, seg, 6, &opt, &m), PLATEAU_DT_OK)) continue;
            if (m.refine_stop != PLATEAU_DT_REFINE_DONE) not_done++;
            nv[ai] = (long)m.num_points;
            if (nv[ai] > max_nv) max_nv = nv[ai];
            for (t = 0; t < m.num_triangles; t++) {
                const plateau_index *v = m.triangles + 3 * t;
                double ang = tri_min_angle(&m, t), cx = -5, cy = -5, th;
                int k;
                if (ang >= opt.min_angle) continue;
                for (k = 0; k < 3; k++) {
                    cx += m.points[2 * v[k]] / 3;
                    cy += m.points[2 * v[k] + 1] / 3;
                }
                th = atan2(cy, cx);
                if (!(th >= -1e-9 && th <= a + 1e-9 && hypot(cx, cy) <= 4)) outside++;
                if (ang < bound * (1 - 1e-9)) below_bound++;
            }
            if (ai <= 3 || ai == 20) {
                plateau_dt_input in;
                in.points = p; in.num_points = 7; in.segments = NULL; in.num_segments = 0;
                check_mesh(&in, &m, 0, 1);
                in.segments = seg;
                in.num_segments = 6;
                CHECK_EQ_INT(check_segments_split(&in, &m), 0);
            }
            plateau_dt_free(&m);
        }
        nv20 = nv[20];
        for (ai = 1; ai <= 29; ai++)
            if (nv[ai] > 8 * nv20) too_many++;
        if (getenv("PLATEAU_TEST_VERBOSE"))
            printf("  min_angle %g: a = 1: %ld vertices, a = 20: %ld, max %ld\n", opt.min_angle, nv[1],
                   nv20, max_nv);
        CHECK_EQ_INT(not_done, 0);
        CHECK_EQ_INT(outside, 0);
        CHECK_EQ_INT(below_bound, 0);
        CHECK_EQ_INT(too_many, 0);
        CHECK(nv20 <= 20);
    }
}

/* 20 horizontal and 20 vertical segments with random free ends, turned by
 * 0.01 rad, crossing each other (split mode), hull kept, 30 degrees: it
 * ran into a 300 000-vertex budget (smallest angle 4.4 degrees) and ends
 * now with about 2 500 vertices. */
static void test_refine_crossing_grid(void)
{
    double p[2 * 80];
    plateau_index seg[2 * 40];
    plateau_dt_options opt;
    plateau_dt_mesh m;
    plateau_dt_input in;
    int i, k;
    for (i = 0; i < 20; i++) {
        unsigned s1 = (unsigned)i * 2654435761u + 6u * 97u;
        double th = 0.01;
        p[8 * i] = -1 + (s1 % 1000) / 1000.0 * 1.2;
        p[8 * i + 1] = i;
        p[8 * i + 2] = 20 - ((s1 / 1000) % 1000) / 1000.0 * 1.2;
        p[8 * i + 3] = i;
        p[8 * i + 4] = i;
        p[8 * i + 5] = -1 + ((s1 / 7) % 1000) / 1000.0 * 1.2;
        p[8 * i + 6] = i;
        p[8 * i + 7] = 20 - ((s1 / 13) % 1000) / 1000.0 * 1.2;
        for (k = 0; k < 4; k++) {
            double x = p[8 * i + 2 * k], y = p[8 * i + 2 * k + 1];
            p[8 * i + 2 * k] = x * cos(th) - y * sin(th);
            p[8 * i + 2 * k + 1] = x * sin(th) + y * cos(th);
        }
        seg[4 * i] = 4 * i; seg[4 * i + 1] = 4 * i + 1;
        seg[4 * i + 2] = 4 * i + 2; seg[4 * i + 3] = 4 * i + 3;
    }
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = 1;
    opt.split_crossing_segments = 1;
    opt.min_angle = 30;
    opt.max_added_points = 300000;
    if (!CHECK_EQ_INT(run(p, 80, seg, 40, &opt, &m), PLATEAU_DT_OK)) return;
    CHECK_EQ_INT(m.refine_stop, PLATEAU_DT_REFINE_DONE);
    CHECK(m.num_points < 4000);
    CHECK(m.num_points > 400 + 80); /* the 400 crossings and some refinement */
    in.points = p; in.num_points = 80; in.segments = NULL; in.num_segments = 0;
    check_mesh(&in, &m, 0, 1);
    plateau_dt_free(&m);
}

static int progress_calls;
static size_t progress_last;
static int progress_stop_after_three(size_t vertices, void *user)
{
    progress_calls++;
    CHECK(vertices > progress_last);
    progress_last = vertices;
    CHECK(user == (void *)&progress_calls);
    return progress_calls >= 3;
}

/* The progress callback sees the vertex count every 1024 refinement
 * vertices; non-zero ends the refinement with refine_stop CANCELLED and a
 * valid mesh.  refine_stop values have names. */
static void test_refine_progress_and_stop_names(void)
{
    double p[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    plateau_index s[8] = {0, 1, 1, 2, 2, 3, 3, 0};
    plateau_dt_options opt;
    plateau_dt_mesh m;
    plateau_dt_input in;
    memset(&opt, 0, sizeof opt);
    opt.min_angle = 30;
    opt.max_area = 1e-6; /* about a million triangles if not stopped */
    opt.progress = progress_stop_after_three;
    opt.progress_user = &progress_calls;
    progress_calls = 0;
    progress_last = 0;
    if (CHECK_EQ_INT(run(p, 4, s, 4, &opt, &m), PLATEAU_DT_OK)) {
        CHECK_EQ_INT(progress_calls, 3);
        CHECK_EQ_INT(m.refine_stop, PLATEAU_DT_REFINE_CANCELLED);
        CHECK(m.num_points >= 3 * 1024 && m.num_points < 4 * 1024 + 64);
        in.points = p; in.num_points = 4; in.segments = NULL; in.num_segments = 0;
        check_mesh(&in, &m, 0, 1);
        plateau_dt_free(&m);
    }
    /* a callback that never stops: called, refinement ends DONE */
    opt.max_area = 1e-4;
    opt.progress_user = &progress_calls;
    progress_calls = -1000000;
    progress_last = 0;
    if (CHECK_EQ_INT(run(p, 4, s, 4, &opt, &m), PLATEAU_DT_OK)) {
        CHECK(progress_calls > -1000000);
        CHECK_EQ_INT(m.refine_stop, PLATEAU_DT_REFINE_DONE);
        plateau_dt_free(&m);
    }
    CHECK(strcmp(plateau_dt_refine_stop_string(PLATEAU_DT_REFINE_NONE), "no refinement was asked for") == 0);
    CHECK(strstr(plateau_dt_refine_stop_string(PLATEAU_DT_REFINE_DONE), "num_unrefined") != NULL);
    CHECK(strstr(plateau_dt_refine_stop_string(PLATEAU_DT_REFINE_BUDGET), "max_added_points") != NULL);
    CHECK(strstr(plateau_dt_refine_stop_string(PLATEAU_DT_REFINE_CANCELLED), "progress") != NULL);
    CHECK(strcmp(plateau_dt_refine_stop_string((plateau_dt_refine_stop)99), "unknown stop") == 0);
}

static void test_refine_small_angles_and_options(void)
{
    plateau_dt_options opt;
    plateau_dt_mesh m;
    size_t i;
    long on_boundary = 0;
    memset(&opt, 0, sizeof opt);
    /* a 5-degree wedge, and a polygon with a 2-degree spike: refinement
     * terminates; the small input angles are left (and counted) */
    {
        double p[2 * 5] = {0, 0, 1, 0, 0, 0, 0.5, 0.8, -0.5, 0.75};
        plateau_index s[2 * 5] = {0, 1, 1, 2, 2, 0, 0, 0, 0, 0};
        plateau_index s2[2 * 5] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 0};
        p[4] = cos(5 * 0.017453292519943295);
        p[5] = sin(5 * 0.017453292519943295);
        opt.min_angle = 30;
        refine_check(p, 3, s, 3, &opt, 1, &m);
        CHECK(m.num_unrefined >= 1);
        CHECK(m.num_points < 5000);
        plateau_dt_free(&m);
        /* A (0,0), B (2,0), C (2,1), D (1,1), P at 2 degrees from A */
        p[2] = 2; p[3] = 0; p[4] = 2; p[5] = 1; p[6] = 1; p[7] = 1;
        p[8] = 1.5;
        p[9] = 1.5 * tan(2 * 0.017453292519943295);
        refine_check(p, 5, s2, 5, &opt, 1, &m);
        CHECK(m.num_unrefined >= 1);
        CHECK(m.num_points < 5000);
        plateau_dt_free(&m);
    }
    /* keep_segments: the boundary stays as given */
    {
        double p[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        plateau_index s[8] = {0, 1, 1, 2, 2, 3, 3, 0};
        opt.min_angle = 25;
        opt.max_area = 0.001;
        opt.keep_segments = 1;
        CHECK_EQ_INT(run(p, 4, s, 4, &opt, &m), PLATEAU_DT_OK);
        {
            plateau_dt_input in;
            in.points = p; in.num_points = 4; in.segments = s; in.num_segments = 4;
            check_mesh(&in, &m, 0, 1); /* the segments are still straight chains */
        }
        for (i = 4; i < m.num_points; i++) {
            const double *q = m.points + 2 * i;
            if (q[0] <= 0 || q[0] >= 1 || q[1] <= 0 || q[1] >= 1) on_boundary++;
            CHECK(m.segment_of[i] == -1);
        }
        CHECK_EQ_INT(on_boundary, 0);
        CHECK(m.num_points > 100);
        plateau_dt_free(&m);
        opt.keep_segments = 0;
    }
    /* hull mode (no segments): hull edges bound the refinement, and are
     * not reported as constrained */
    {
        double p[2 * 30];
        long flagged = 0;
        for (i = 0; i < 60; i++) p[i] = rnd01();
        opt.min_angle = 25;
        opt.max_area = 0;
        refine_check(p, 30, NULL, 0, &opt, 1, &m);
        for (i = 0; i < 3 * m.num_triangles; i++) flagged += m.constrained[i];
        CHECK_EQ_INT(flagged, 0);
        CHECK_EQ_INT(m.num_unrefined, 0);
        plateau_dt_free(&m);
    }
    /* an area limit through a callback: small near x = 0 */
    {
        double p[8] = {0, 0, 1, 0, 1, 1, 0, 1};
        plateau_index s[8] = {0, 1, 1, 2, 2, 3, 3, 0};
        long big = 0;
        opt.min_angle = 20;
        opt.max_area_fn = area_limit_fn;
        opt.max_area_user = NULL;
        refine_check(p, 4, s, 4, &opt, 1, &m);
        for (i = 0; i < m.num_triangles; i++) {
            const plateau_index *v = m.triangles + 3 * i;
            double cx = (m.points[2 * v[0]] + m.points[2 * v[1]] + m.points[2 * v[2]]) / 3;
            double cy = (m.points[2 * v[0] + 1] + m.points[2 * v[1] + 1] + m.points[2 * v[2] + 1]) / 3;
            if (tri_area(&m, i) > area_limit_fn(cx, cy, NULL) * (1 + 1e-9)) big++;
        }
        CHECK_EQ_INT(big, 0);
        plateau_dt_free(&m);
        opt.max_area_fn = NULL;
        /* the budget: stops with its reason */
        opt.max_area = 1e-6;
        opt.max_added_points = 50;
        CHECK_EQ_INT(run(p, 4, s, 4, &opt, &m), PLATEAU_DT_OK);
        CHECK_EQ_INT(m.refine_stop, PLATEAU_DT_REFINE_BUDGET);
        CHECK(m.num_points <= 4 + 50);
        plateau_dt_free(&m);
        /* no refinement asked: no stop reason */
        memset(&opt, 0, sizeof opt);
        CHECK_EQ_INT(run(p, 4, s, 4, &opt, &m), PLATEAU_DT_OK);
        CHECK_EQ_INT(m.refine_stop, PLATEAU_DT_REFINE_NONE);
        plateau_dt_free(&m);
    }
}

/* allocators: every byte freed; failures at every allocation reported */
typedef struct alloc_ctx {
    long live, calls, fail_at;
} alloc_ctx;
static void *ctx_alloc(size_t size, void *user)
{
    alloc_ctx *c = (alloc_ctx *)user;
    void *p;
    if (c->fail_at >= 0 && c->calls == c->fail_at) {
        c->calls++;
        return NULL;
    }
    c->calls++;
    p = malloc(size);
    if (p) c->live++;
    return p;
}
static void ctx_free(void *ptr, void *user)
{
    alloc_ctx *c = (alloc_ctx *)user;
    if (ptr) c->live--;
    free(ptr);
}

static void test_errors(void)
{
    double p[2 * 8] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 2, 2, 0, 0, 3, 3};
    plateau_index s[2 * 8];
    plateau_dt_input in;
    plateau_dt_mesh m;
    plateau_dt_error rep;
    plateau_dt_options opt;
    int code;
    memset(&opt, 0, sizeof opt);
    in.points = p; in.num_points = 5; in.segments = NULL; in.num_segments = 0;
    CHECK_EQ_INT(plateau_dt_triangulate(NULL, NULL, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    CHECK(rep.message[0] != '\0');
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, NULL, &rep), PLATEAU_DT_ERR_ARGUMENT);
    in.points = NULL;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    in.points = p;
    in.num_segments = 1;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    in.num_segments = 0;
    opt.allocator.user_data = NULL;
    opt.allocator.free_fn = ctx_free;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    opt.allocator.free_fn = NULL;
    /* NaN and Inf, with the point named */
    p[2 * 3 + 1] = NAN;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_NOT_FINITE);
    CHECK_EQ_INT(rep.index, 3);
    p[2 * 3 + 1] = -INFINITY;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_NOT_FINITE);
    CHECK_EQ_INT(rep.index, 3);
    CHECK(m.triangles == NULL && m.num_triangles == 0 && m.points == NULL);
    p[2 * 3 + 1] = 1;
    /* too few */
    in.num_points = 2;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    in.num_points = 0;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_TOO_FEW_POINTS);
    {
        double same[8] = {1, 2, 1, 2, 1, 2, 1, 2};
        in.points = same;
        in.num_points = 4;
        CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_TOO_FEW_POINTS);
        same[2] = 3; /* two distinct points: still too few */
        CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_TOO_FEW_POINTS);
        same[4] = 5; /* three distinct collinear points */
        CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_COLLINEAR);
        in.points = p;
    }
    in.num_points = 5;
    /* refinement bounds: negative or NaN */
    opt.min_angle = -1;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    opt.min_angle = NAN;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    opt.min_angle = 0;
    opt.max_area = -1e-300;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_ERR_ARGUMENT);
    opt.max_area = 0;
    /* segment indices */
    in.segments = s;
    in.num_segments = 1;
    s[0] = 0; s[1] = 5;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_SEGMENT_INDEX);
    CHECK_EQ_INT(rep.index, 0);
    s[0] = -1; s[1] = 2;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_SEGMENT_INDEX);
    /* degenerate segments: (a, a), and between coincident points */
    s[0] = 2; s[1] = 2;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_DEGENERATE_SEGMENT);
    in.num_points = 7; /* point 6 = point 0 */
    s[0] = 6; s[1] = 0;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_DEGENERATE_SEGMENT);
    /* crossing: the two diagonals of the square */
    in.num_points = 4;
    s[0] = 0; s[1] = 2; s[2] = 1; s[3] = 3;
    in.num_segments = 2;
    opt.keep_convex_hull = 1;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_ERR_CROSSING_SEGMENTS);
    CHECK_EQ_INT(rep.index, 1);
    CHECK(m.triangles == NULL);
    /* meeting at a point that lies on both is no crossing: both are split */
    in.num_points = 5;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_OK);
    check_mesh(&in, &m, 1, 1);
    plateau_dt_free(&m);
    /* open chain when a domain is asked for; fine when the hull is kept */
    s[0] = 0; s[1] = 1; s[2] = 1; s[3] = 2; s[4] = 2; s[5] = 3;
    in.num_segments = 3;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_ERR_OPEN_BOUNDARY);
    CHECK(rep.index == 0 || rep.index == 3);
    CHECK_EQ_INT(plateau_dt_triangulate(&in, &opt, &m, &rep), PLATEAU_DT_OK);
    check_mesh(&in, &m, 1, 1);
    plateau_dt_free(&m);
    s[6] = 3; s[7] = 0;
    in.num_segments = 4;
    CHECK_EQ_INT(plateau_dt_triangulate(&in, NULL, &m, &rep), PLATEAU_DT_OK);
    check_mesh(&in, &m, 0, 1);
    CHECK_EQ_INT(m.num_triangles, 4);
    plateau_dt_free(&m);
    plateau_dt_free(NULL);
    plateau_dt_free(&m); /* twice: harmless */
    /* messages */
    for (code = 0; code >= -12; code--) {
        const char *t = plateau_dt_result_string((plateau_dt_result)code);
        CHECK(t != NULL && strcmp(t, "unknown result") != 0);
    }
    CHECK(strcmp(plateau_dt_result_string((plateau_dt_result)-99), "unknown result") == 0);
    /* resolved options: the defaults made visible */
    {
        plateau_dt_options ro = plateau_dt_resolved_options(NULL);
        CHECK(ro.seed != 0);
        CHECK_EQ_INT(ro.keep_convex_hull, 0);
        CHECK_EQ_INT(ro.split_crossing_segments, 0);
        CHECK(ro.allocator.alloc_fn == NULL && ro.min_angle == 0 && ro.max_area == 0);
        opt.keep_convex_hull = 5;
        opt.seed = 7;
        ro = plateau_dt_resolved_options(&opt);
        CHECK_EQ_INT(ro.keep_convex_hull, 1);
        CHECK_EQ_INT((long)ro.seed, 7);
    }
    CHECK(strcmp(plateau_dt_result_string(PLATEAU_DT_ERR_CROSSING_SEGMENTS),
                 plateau_dt_result_string(PLATEAU_DT_ERR_OPEN_BOUNDARY)) != 0);
}

static void test_allocator(void)
{
    size_t k = 10, ni = 200, n = 4 * k + ni;
    double *p = (double *)malloc(2 * n * sizeof(double));
    plateau_index *seg = (plateau_index *)malloc(2 * 4 * k * sizeof(plateau_index));
    plateau_dt_options opt;
    plateau_dt_mesh m;
    alloc_ctx c;
    long total, f, bad = 0;
    square_polygon(k, ni, p, seg);
    memset(&opt, 0, sizeof opt);
    c.live = 0; c.calls = 0; c.fail_at = -1;
    opt.allocator.alloc_fn = ctx_alloc;
    opt.allocator.free_fn = ctx_free;
    opt.allocator.user_data = &c;
    CHECK_EQ_INT(run(p, n, seg, 4 * k, &opt, &m), PLATEAU_DT_OK);
    CHECK(c.live == 6);
    CHECK(m.allocator.user_data == &c);
    plateau_dt_free(&m);
    CHECK_EQ_INT(c.live, 0);
    total = c.calls;
    for (f = 0; f < total; f++) {
        plateau_dt_input in;
        plateau_dt_error rep;
        plateau_dt_result r;
        c.live = 0; c.calls = 0; c.fail_at = f;
        in.points = p; in.num_points = n; in.segments = seg; in.num_segments = 4 * k;
        r = plateau_dt_triangulate(&in, &opt, &m, &rep);
        if (r != PLATEAU_DT_ERR_OUT_OF_MEMORY || c.live != 0 || m.triangles != NULL) bad++;
        plateau_dt_free(&m);
    }
    CHECK(total > 5);
    CHECK_EQ_INT(bad, 0);
    free(p);
    free(seg);
}

int main(void)
{
    RUN(test_predicates_against_bigint);
    RUN(test_predicates_extreme_scales);
    RUN(test_predicates_mixed_magnitudes);
    RUN(test_mixed_magnitude_cluster);
    RUN(test_random_points);
    RUN(test_grid);
    RUN(test_circle);
    RUN(test_collinear);
    RUN(test_long_straight_sides);
    RUN(test_duplicates);
    RUN(test_tiny_and_huge);
    RUN(test_holes);
    RUN(test_points_on_segments);
    RUN(test_inner_segments);
    RUN(test_long_segment_many_flips);
    RUN(test_determinism);
    RUN(test_split_crossing);
    RUN(test_split_crossing_coinciding);
    RUN(test_refine_quality);
    RUN(test_refine_small_angles_and_options);
    RUN(test_refine_input_angles);
    RUN(test_broken_ring_is_internal_error);
    RUN(test_refine_crossing_grid);
    RUN(test_refine_progress_and_stop_names);
    RUN(test_fuzz);
    RUN(test_errors);
    RUN(test_allocator);
    return harness_report("test_delaunay");
}
