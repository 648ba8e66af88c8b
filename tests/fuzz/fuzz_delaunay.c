/* fuzz_delaunay.c - libFuzzer target for plateau_dt_triangulate.
 *
 * Bytes: [flags] [fail_at] [point count] points... segments...
 *   flags bit 0     keep_convex_hull
 *   flags bits 1-2  coordinates: 0 one signed byte / 4 (a small grid: many
 *                   duplicates, collinear and co-circular points), 1 two
 *                   signed bytes, 2 raw IEEE doubles (NaN and Inf kept, finite
 *                   values folded into 1e-150 .. 1e150, see in_range),
 *                   3 one signed byte times 1e-150 or 1e150 (flags bit 3)
 *   flags bit 4     refuse allocation number fail_at (1..256); when clear,
 *                   fail_at selects a refinement: bits 0-1 none, min_angle,
 *                   max_area or both; bits 2-5 the angle (20 + 0..15
 *                   degrees); bit 6 keep_segments; bit 7 the area bound
 *                   (1/50 or 1/400 of the bounding box), at most 2000 added
 *                   points
 *   flags bit 5     split_crossing_segments
 *   flags bits 6-7  the insertion-order seed (0..3)
 *   segments        pairs of bytes: an index modulo (count + 1), so one past
 *                   the end occurs; byte 255 gives -1 and 254 INDEX_MAX
 * Checked: on success the mesh is well formed (indices in range, distinct
 * corners, mutual neighbours, constrained flags agreeing across an edge,
 * input points kept bit for bit, counter-clockwise triangles where the grid
 * makes the orientation exact, the same triangle set whatever the seed,
 * after a completed refinement no angle below the bound and no area above
 * it); on
 * error the mesh is empty; a refused allocation gives
 * PLATEAU_DT_ERR_OUT_OF_MEMORY; nothing leaks. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#endif
#include "plateau_delaunay.h"
#include <math.h>
#include "countalloc.h"
#include "fuzz_common.h"

#define FUZZ_MAX_POINTS 96
#define FUZZ_MAX_SEGMENTS 64

/* Raw doubles keep NaN, Inf and zero; finite values get their binary
 * exponent folded into -497 .. 498, about the documented range 1e-150 ..
 * 1e150, mixed freely within one input. */
#define FUZZ_EXP_MIN (-497)
#define FUZZ_EXP_SPAN 996

/* A finite x with its binary exponent folded into that range. */
static double in_range(double x)
{
    int e;
    double m;
    if (x != x || x - x != 0.0 || x == 0.0) return x; /* NaN, Inf, zero */
    m = frexp(x, &e);
    return ldexp(m, FUZZ_EXP_MIN + (e + 1074) % FUZZ_EXP_SPAN);
}

static void check_mesh(const plateau_dt_mesh *mesh, const double *pts, size_t np,
                       int exact_orientation)
{
    size_t t, i;
    int k;
    FUZZ_REQUIRE(mesh->num_input_points == np);
    FUZZ_REQUIRE(mesh->num_points >= np);
    FUZZ_REQUIRE(mesh->points != NULL);
    FUZZ_REQUIRE(np == 0 || mesh->duplicate_of != NULL);
    for (i = 0; i < np; i++) {
        plateau_index d = mesh->duplicate_of[i];
        FUZZ_REQUIRE(mesh->points[2 * i] == pts[2 * i]);
        FUZZ_REQUIRE(mesh->points[2 * i + 1] == pts[2 * i + 1]);
        FUZZ_REQUIRE(d >= 0 && (size_t)d < np);
        FUZZ_REQUIRE(mesh->duplicate_of[d] == d);
        FUZZ_REQUIRE(pts[2 * d] == pts[2 * i] && pts[2 * d + 1] == pts[2 * i + 1]);
    }
    for (i = np; i < mesh->num_points; i++) {
        FUZZ_REQUIRE(mesh->points[2 * i] == mesh->points[2 * i]);         /* not NaN */
        FUZZ_REQUIRE(mesh->points[2 * i + 1] == mesh->points[2 * i + 1]); /* not NaN */
    }
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *v = mesh->triangles + 3 * t;
        for (k = 0; k < 3; k++) {
            plateau_index a = v[k], b = v[(k + 1) % 3];
            plateau_index u = mesh->neighbors[3 * t + k];
            FUZZ_REQUIRE(a >= 0 && (size_t)a < mesh->num_points);
            FUZZ_REQUIRE((size_t)a >= np || mesh->duplicate_of[a] == a);
            FUZZ_REQUIRE(a != b);
            FUZZ_REQUIRE(mesh->constrained[3 * t + k] <= 1);
            if (u >= 0) {
                int j, back = -1;
                FUZZ_REQUIRE((size_t)u < mesh->num_triangles && (size_t)u != t);
                for (j = 0; j < 3; j++)
                    if (mesh->neighbors[3 * u + j] == (plateau_index)t) back = j;
                FUZZ_REQUIRE(back >= 0);
                FUZZ_REQUIRE(mesh->triangles[3 * u + back] == b);
                FUZZ_REQUIRE(mesh->triangles[3 * u + (back + 1) % 3] == a);
                FUZZ_REQUIRE(mesh->constrained[3 * u + back] == mesh->constrained[3 * t + k]);
            } else {
                FUZZ_REQUIRE(u == -1);
            }
        }
        if (exact_orientation && (size_t)v[0] < np && (size_t)v[1] < np && (size_t)v[2] < np) {
            /* small integers (times 1/4): the products below are exact */
            const double *a = pts + 2 * v[0], *b = pts + 2 * v[1], *c = pts + 2 * v[2];
            double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            FUZZ_REQUIRE(det > 0);
        }
    }
}

static void check_empty(const plateau_dt_mesh *mesh)
{
    FUZZ_REQUIRE(mesh->num_points == 0 && mesh->points == NULL);
    FUZZ_REQUIRE(mesh->num_input_points == 0 && mesh->duplicate_of == NULL);
    FUZZ_REQUIRE(mesh->num_triangles == 0 && mesh->triangles == NULL);
    FUZZ_REQUIRE(mesh->neighbors == NULL && mesh->constrained == NULL);
}

/* Triangles as canonical triples (rotated so the smallest index is first,
 * which keeps the orientation), sorted: the triangle set. */
static int triple_cmp(const void *x, const void *y)
{
    const plateau_index *a = (const plateau_index *)x, *b = (const plateau_index *)y;
    int k;
    for (k = 0; k < 3; k++)
        if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
    return 0;
}

static plateau_index *triangle_set(const plateau_dt_mesh *mesh)
{
    size_t t, n = mesh->num_triangles;
    plateau_index *s = (plateau_index *)malloc(3 * (n ? n : 1) * sizeof(plateau_index));
    FUZZ_REQUIRE(s != NULL);
    for (t = 0; t < n; t++) {
        const plateau_index *v = mesh->triangles + 3 * t;
        int r = (v[1] < v[0] && v[1] < v[2]) ? 1 : (v[2] < v[0] && v[2] < v[1]) ? 2 : 0;
        s[3 * t] = v[r];
        s[3 * t + 1] = v[(r + 1) % 3];
        s[3 * t + 2] = v[(r + 2) % 3];
    }
    qsort(s, n, 3 * sizeof(plateau_index), triple_cmp);
    return s;
}

/* The documented promise: the seed changes the order, never the set. */
static void check_seed_independent(const plateau_dt_input *in, const plateau_dt_options *opt,
                                   const plateau_dt_mesh *mesh)
{
    plateau_dt_options o2 = *opt;
    plateau_dt_mesh other;
    plateau_index *a, *b;
    o2.seed = opt->seed + 12345;
    memset(&o2.allocator, 0, sizeof o2.allocator);
    FUZZ_REQUIRE(plateau_dt_triangulate(in, &o2, &other, NULL) == PLATEAU_DT_OK);
    FUZZ_REQUIRE(other.num_triangles == mesh->num_triangles);
    a = triangle_set(mesh);
    b = triangle_set(&other);
    FUZZ_REQUIRE(memcmp(a, b, 3 * mesh->num_triangles * sizeof(plateau_index)) == 0);
    free(a);
    free(b);
    plateau_dt_free(&other);
}

/* After a refinement that ended with every triangle within the bounds
 * (refine_stop DONE, num_unrefined 0): no area above max_area and no angle
 * below min_angle (clamped to 34 degrees), up to rounding.  (A small input
 * angle, of a segment corner or of the hull in hull mode, is counted in
 * num_unrefined: test_dt_refine_spirals_into_small_hull_corner.) */
static void check_refined(const plateau_dt_mesh *mesh, double min_angle, double max_area)
{
    size_t t;
    double bound = min_angle > 34.0 ? 34.0 : min_angle;
    double sin_bound = sin(bound * 3.14159265358979323846 / 180.0);
    if (mesh->refine_stop != PLATEAU_DT_REFINE_DONE || mesh->num_unrefined != 0) return;
    for (t = 0; t < mesh->num_triangles; t++) {
        const double *p[3];
        double area2;
        int k;
        for (k = 0; k < 3; k++) p[k] = mesh->points + 2 * mesh->triangles[3 * t + k];
        area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        if (max_area > 0) FUZZ_REQUIRE(0.5 * area2 <= max_area * (1 + 1e-6));
        /* unit edge vectors first, so tiny triangles do not underflow */
        for (k = 0; bound > 0 && k < 3; k++) {
            const double *a = p[k], *b1 = p[(k + 1) % 3], *c = p[(k + 2) % 3];
            double ux = b1[0] - a[0], uy = b1[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
            double lu = hypot(ux, uy), lv = hypot(vx, vy);
            double cross = (ux / lu) * (vy / lv) - (uy / lu) * (vx / lv);
            double dot = (ux / lu) * (vx / lv) + (uy / lu) * (vy / lv);
            /* angle at a >= bound: sin above sin(bound) or the angle obtuse */
            FUZZ_REQUIRE(dot <= 0 || fabs(cross) >= sin_bound - 1e-6);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static double pts[2 * FUZZ_MAX_POINTS];
    static plateau_index segs[2 * FUZZ_MAX_SEGMENTS];
    fuzz_bytes b;
    uint8_t flags, fail_byte;
    int mode;
    size_t np, ns, i;
    countalloc ca;
    plateau_dt_input in;
    plateau_dt_options opt;
    plateau_dt_mesh mesh;
    plateau_dt_error rep;
    plateau_dt_result rc;

    b.data = data;
    b.size = size;
    b.pos = 0;
    flags = fuzz_u8(&b);
    fail_byte = fuzz_u8(&b);
    np = fuzz_u8(&b) % (FUZZ_MAX_POINTS + 1);
    mode = (flags >> 1) & 3;
    for (i = 0; i < 2 * np; i++) {
        double c;
        switch (mode) {
        case 0: c = (double)(int8_t)fuzz_u8(&b) / 4.0; break;
        case 1: {
            int hi = (int8_t)fuzz_u8(&b);
            c = (double)(hi * 256 + fuzz_u8(&b));
            break;
        }
        case 2: c = in_range(fuzz_raw_double(&b)); break;
        default: c = (double)(int8_t)fuzz_u8(&b) * ((flags & 8) ? 1e150 : 1e-150); break;
        }
        pts[i] = c;
    }
    ns = fuzz_left(&b) / 2;
    if (ns > FUZZ_MAX_SEGMENTS) ns = FUZZ_MAX_SEGMENTS;
    for (i = 0; i < 2 * ns; i++) {
        uint8_t s = fuzz_u8(&b);
        if (s == 255) segs[i] = -1;
        else if (s == 254) segs[i] = PLATEAU_INDEX_MAX;
        else segs[i] = (plateau_index)(s % (np + 1));
    }

    countalloc_init(&ca, (flags & 16) ? (long)fail_byte + 1 : 0);
    memset(&opt, 0, sizeof opt);
    opt.keep_convex_hull = flags & 1;
    opt.split_crossing_segments = (flags >> 5) & 1;
    opt.seed = (unsigned long)(flags >> 6);
    if (!(flags & 16) && (fail_byte & 3) && np >= 3 && (mode == 0 || mode == 1)) {
        double lo[2] = {pts[0], pts[1]}, hi[2] = {pts[0], pts[1]};
        for (i = 1; i < np; i++) {
            int k;
            for (k = 0; k < 2; k++) {
                if (pts[2 * i + k] < lo[k]) lo[k] = pts[2 * i + k];
                if (pts[2 * i + k] > hi[k]) hi[k] = pts[2 * i + k];
            }
        }
        if (fail_byte & 1) opt.min_angle = 20.0 + (double)((fail_byte >> 2) & 15);
        if (fail_byte & 2)
            opt.max_area = (hi[0] - lo[0]) * (hi[1] - lo[1]) / ((fail_byte & 128) ? 400.0 : 50.0);
        opt.keep_segments = (fail_byte >> 6) & 1;
        opt.max_added_points = 2000;
    }
    opt.allocator = countalloc_allocator(&ca);
    in.points = pts;
    in.num_points = np;
    in.segments = ns ? segs : NULL;
    in.num_segments = ns;
    memset(&mesh, 0x5a, sizeof mesh); /* the call must not rely on a zeroed mesh */
    rep.index = -7;
    memset(rep.message, 'x', sizeof rep.message);

    rc = plateau_dt_triangulate(&in, &opt, &mesh, &rep);
    FUZZ_REQUIRE(plateau_dt_result_string(rc) != NULL);
    if (rc == PLATEAU_DT_OK) {
        check_mesh(&mesh, pts, np, mode == 0 || mode == 1);
        if (opt.min_angle > 0 || opt.max_area > 0)
            check_refined(&mesh, opt.keep_segments ? 0.0 : opt.min_angle,
                          opt.keep_segments ? 0.0 : opt.max_area);
        if (mesh.num_points == np) check_seed_independent(&in, &opt, &mesh);
    } else {
        FUZZ_REQUIRE((int)rc < 0);
        FUZZ_REQUIRE(fuzz_terminated(rep.message, sizeof rep.message));
        check_empty(&mesh);
    }
    if (ca.refused > 0) FUZZ_REQUIRE(rc == PLATEAU_DT_ERR_OUT_OF_MEMORY);
    plateau_dt_free(&mesh);
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    FUZZ_REQUIRE(countalloc_lost_context == 0);
    return 0;
}
