/* surfaces.h - the cases of the paper's Section III, shared by the example
 * programs (examples/helicoid.c, catenoid.c, scherk.c, membrane.c) and by
 * tests/test_examples.c.  Not part of the library: a helper of the demo.
 *
 * One place for each thing:
 *   demo_cases[]        every case: surface, parameter ranges, polygon
 *                       sampling, n, the paper's published figures
 *   demo_boundary()     the closed polygon L of a case
 *   demo_err()          the paper's error formulas (III.A to III.C)
 *   demo_distance()     distance of a point to the exact surface (Newton)
 *   demo_patch_area()   area of the continuous patch (Gauss-Legendre)
 *   demo_solve()        the library call: polygon in, mesh out
 *   demo_measure()      one table row from a solved mesh
 *   demo_optimum()      the polygon's own minimal area (examples/NOTES.md or pinned here)
 *   demo_extrapolate()  that area from fine area-minimising meshes
 *   demo_format_row()   the Markdown table, written to out/table.md
 *
 * Include it after plateau.h.  Every function is static: each program that
 * includes it gets its own copy. */
#ifndef PLATEAU_DEMO_SURFACES_H
#define PLATEAU_DEMO_SURFACES_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Every helper is static; a program uses only some of them. */
#if defined(__GNUC__) || defined(__clang__)
#define DEMO_FN static __attribute__((unused))
#else
#define DEMO_FN static
#endif

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef enum demo_kind {
    DEMO_HELICOID, /* r(u,v) = (u cos v, u sin v, b v)                      */
    DEMO_CATENOID, /* r(u,v) = (b cos u cosh v, b v, b sin u cosh v)        */
    DEMO_SCHERK,   /* r(u,v) = (u, v, (1/b) ln(cos(b v) / cos(b u)))        */
    DEMO_MEMBRANE  /* a designed sail: polygon only, no exact surface       */
} demo_kind;

#define DEMO_MAX_BOUNDARY 64

typedef struct demo_case {
    const char *name;   /* file stem in out/ and key of the table row */
    const char *group;  /* the example program that runs it */
    demo_kind kind;
    double b;
    double u0, u1, v0, v1; /* parameter rectangle (Scherk: x and y) */
    int nu, nv;            /* polygon: segments on each side along which u varies
                              (v = v0 and v = v1), and along which v varies */
    size_t n;              /* interior points */
    double optimum;        /* the polygon's own minimal area (demo_optimum) */
    int optimum_notes;     /* 1: the figure of examples/NOTES.md; 0: extrapolated here */
    int reference_of;      /* Scherk b != 1: index of the b = 1 case of the same shape,
                              whose optimum / b^2 is this one's (optimum is 0) */
    const char *paper_ours;  /* published figure of the paper's method */
    const char *paper_chen;  /* published figure of Chen et al.'s area method */
} demo_case;

/* ---------------------------------------------------------------- cases
 * The paper gives no parameter ranges.  Helicoid and catenoid use the ranges
 * of examples/NOTES.md, and their polygons give the optima given there to
 * 0.01 % (checked by extrapolating fine meshes here): the sides get segments
 * roughly in proportion to their lengths, 5 on each straight ruling and 9 on
 * each helix of the helicoid, 8 on each circular arc and 4 on each catenary
 * of the catenoid (the same 28 and 24 vertices).  The Scherk surfaces
 * for b = 0.4, 1, 4.9 are the same shape scaled by 1/b when the domain is
 * [-c/b, c/b]^2; three sizes c = 0.5, 1.0, 1.3 (|b x| <= c < pi/2), each
 * with its own resolution: 16, 32 or 48 polygon vertices and 9, 25 or 49
 * interior points ("different n and different numbers of vertices", Fig. 8).
 * Polygons: nu segments on the sides v = v0 and v = v1, nv on u = u0 and
 * u = u1, uniform in the parameter, walked
 * (u0,v0) -> (u1,v0) -> (u1,v1) -> (u0,v1). */
#define DEMO_SCHERK_CASE(bname, bval, sname, c, k, nn, opt, notes, ref)               \
    { "scherk-b" bname "-" sname, "scherk", DEMO_SCHERK, bval, -(c) / (bval),        \
      (c) / (bval), -(c) / (bval), (c) / (bval), k, k, nn, opt, notes, ref, "Fig. 8",  \
      "Fig. 8" }

static const demo_case demo_cases[] = {
    { "helicoid", "helicoid", DEMO_HELICOID, 1.9, -1.0, 1.0, -M_PI / 4, M_PI / 4, 5, 9, 20,
      6.21699, 1, -1, "2.941e-3", "4.110e-3" },
    { "catenoid", "catenoid", DEMO_CATENOID, 2.05, M_PI / 4, 3 * M_PI / 4, -0.5, 0.5, 8, 4, 25,
      7.15719, 1, -1, "9.192e-4", "1.412e-3" },
    DEMO_SCHERK_CASE("0.4", 0.4, "s", 0.5, 4, 9, 0.0, 0, 5),
    DEMO_SCHERK_CASE("0.4", 0.4, "m", 1.0, 8, 25, 0.0, 0, 6),
    DEMO_SCHERK_CASE("0.4", 0.4, "l", 1.3, 12, 49, 0.0, 0, 7),
    DEMO_SCHERK_CASE("1", 1.0, "s", 0.5, 4, 9, 1.07745, 0, -1),
    DEMO_SCHERK_CASE("1", 1.0, "m", 1.0, 8, 25, 5.64889, 1, -1),
    DEMO_SCHERK_CASE("1", 1.0, "l", 1.3, 12, 49, 13.2650, 0, -1),
    DEMO_SCHERK_CASE("4.9", 4.9, "s", 0.5, 4, 9, 0.0, 0, 5),
    DEMO_SCHERK_CASE("4.9", 4.9, "m", 1.0, 8, 25, 0.0, 0, 6),
    DEMO_SCHERK_CASE("4.9", 4.9, "l", 1.3, 12, 49, 0.0, 0, 7),
    { "membrane", "membrane", DEMO_MEMBRANE, 0.0, 0, 0, 0, 0, 0, 0, 4, 29.4905, 0, -1,
      "mean |H| 4.786e-4", "-" }
};
#define DEMO_NUM_CASES (sizeof demo_cases / sizeof demo_cases[0])

/* The membrane of III.D (the paper gives no coordinates): a four-point
 * shade sail in front of a house, metres.  Two fixings on the house wall
 * (y = 0) and two posts; heights alternate high, low, high, low, which twists
 * the cloth into a hypar.  The edges are cables: between the corners the
 * polygon follows a parabolic sag of 8 % of the edge's plan length towards
 * the middle of the sail, heights linear along the edge.  The long wall edge
 * gets two intermediate vertices, the three others one each: 9 vertices. */
static const double demo_sail_corners[4][3] = {
    { 0.0, 0.0, 3.6 }, /* wall, high */
    { 8.0, 0.0, 2.6 }, /* wall, low */
    { 6.5, 5.5, 3.8 }, /* tall post */
    { 1.0, 5.0, 2.2 }  /* short post */
};
static const int demo_sail_intermediate[4] = { 2, 1, 1, 1 };
#define DEMO_SAIL_SAG 0.08

DEMO_FN const demo_case *demo_find(const char *name)
{
    size_t i;
    for (i = 0; i < DEMO_NUM_CASES; i++)
        if (strcmp(demo_cases[i].name, name) == 0) return &demo_cases[i];
    return NULL;
}

/* ---------------------------------------------------------------- surfaces */
/* r(u,v) and its first and second derivatives (any output may be NULL). */
DEMO_FN void demo_eval(const demo_case *c, double u, double v, double r[3], double ru[3],
                      double rv[3], double ruu[3], double ruv[3], double rvv[3])
{
    double t[6][3];
    double b = c->b;
    int k;
    memset(t, 0, sizeof t);
    if (c->kind == DEMO_HELICOID) {
        double cv = cos(v), sv = sin(v);
        t[0][0] = u * cv; t[0][1] = u * sv; t[0][2] = b * v;
        t[1][0] = cv; t[1][1] = sv;
        t[2][0] = -u * sv; t[2][1] = u * cv; t[2][2] = b;
        t[4][0] = -sv; t[4][1] = cv;
        t[5][0] = -u * cv; t[5][1] = -u * sv;
    } else if (c->kind == DEMO_CATENOID) {
        double cu = cos(u), su = sin(u), ch = cosh(v), sh = sinh(v);
        t[0][0] = b * cu * ch; t[0][1] = b * v; t[0][2] = b * su * ch;
        t[1][0] = -b * su * ch; t[1][2] = b * cu * ch;
        t[2][0] = b * cu * sh; t[2][1] = b; t[2][2] = b * su * sh;
        t[3][0] = -b * cu * ch; t[3][2] = -b * su * ch;
        t[4][0] = -b * su * sh; t[4][2] = b * cu * sh;
        t[5][0] = b * cu * ch; t[5][2] = b * su * ch;
    } else if (c->kind == DEMO_SCHERK) {
        double tu = tan(b * u), tv = tan(b * v);
        t[0][0] = u; t[0][1] = v; t[0][2] = (log(cos(b * v)) - log(cos(b * u))) / b;
        t[1][0] = 1; t[1][2] = tu;
        t[2][1] = 1; t[2][2] = -tv;
        t[3][2] = b * (1 + tu * tu);
        t[5][2] = -b * (1 + tv * tv);
    }
    for (k = 0; k < 3; k++) {
        if (r) r[k] = t[0][k];
        if (ru) ru[k] = t[1][k];
        if (rv) rv[k] = t[2][k];
        if (ruu) ruu[k] = t[3][k];
        if (ruv) ruv[k] = t[4][k];
        if (rvv) rvv[k] = t[5][k];
    }
}

DEMO_FN double demo_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

DEMO_FN void demo_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The closed polygon L of a case into xyz (room for DEMO_MAX_BOUNDARY
 * vertices); returns m. */
DEMO_FN size_t demo_boundary(const demo_case *c, double *xyz)
{
    size_t m = 0;
    int side, j;
    if (c->kind == DEMO_MEMBRANE) {
        double cx = 0, cy = 0;
        for (side = 0; side < 4; side++) {
            cx += demo_sail_corners[side][0] / 4;
            cy += demo_sail_corners[side][1] / 4;
        }
        for (side = 0; side < 4; side++) {
            const double *p = demo_sail_corners[side], *q = demo_sail_corners[(side + 1) % 4];
            int k = demo_sail_intermediate[side];
            double dx = q[0] - p[0], dy = q[1] - p[1], len = sqrt(dx * dx + dy * dy);
            /* unit normal in plan, turned towards the middle of the sail */
            double nx = -dy / len, ny = dx / len;
            if (nx * (cx - p[0]) + ny * (cy - p[1]) < 0) { nx = -nx; ny = -ny; }
            for (j = 0; j <= k; j++) {
                double t = (double)j / (k + 1);
                double sag = 4 * DEMO_SAIL_SAG * len * t * (1 - t);
                xyz[3 * m + 0] = p[0] + t * dx + sag * nx;
                xyz[3 * m + 1] = p[1] + t * dy + sag * ny;
                xyz[3 * m + 2] = p[2] + t * (q[2] - p[2]);
                m++;
            }
        }
        return m;
    }
    for (side = 0; side < 4; side++) {
        int k = side % 2 ? c->nv : c->nu;
        for (j = 0; j < k; j++) {
            double t = (double)j / k, u, v;
            switch (side) {
            case 0: u = c->u0 + t * (c->u1 - c->u0); v = c->v0; break;
            case 1: u = c->u1; v = c->v0 + t * (c->v1 - c->v0); break;
            case 2: u = c->u1 - t * (c->u1 - c->u0); v = c->v1; break;
            default: u = c->u0; v = c->v1 - t * (c->v1 - c->v0); break;
            }
            demo_eval(c, u, v, xyz + 3 * m, NULL, NULL, NULL, NULL, NULL);
            m++;
        }
    }
    return m;
}

/* The paper's ERR of one point (III.A helicoid, III.B catenoid, III.C
 * Scherk): absolute below 1, relative to |y| (helicoid) or |z| above. */
DEMO_FN double demo_err(const demo_case *c, const double p[3])
{
    double x = p[0], y = p[1], z = p[2], b = c->b, e;
    if (c->kind == DEMO_HELICOID) {
        e = fabs(y - x * tan(z / b));
        return fabs(y) > 1 ? e / fabs(y) : e;
    }
    if (c->kind == DEMO_CATENOID) {
        double ch = cosh(y / b), s = b * b * ch * ch - x * x;
        e = fabs(z - sqrt(s > 0 ? s : 0));
    } else if (c->kind == DEMO_SCHERK) {
        e = fabs(z - log(cos(b * y) / cos(b * x)) / b);
    } else {
        return 0;
    }
    return fabs(z) < 1 ? e : e / fabs(z);
}

/* Distance from p to the exact surface: Newton's method on
 * (1/2)|r(u,v) - p|^2 over the parameters, from the point's own parameters
 * (inverted analytically), falling back to Gauss-Newton when the Hessian is
 * not positive definite.  The surface is the whole analytic sheet, not only
 * the patch.  uv (may be NULL) gets the foot point's parameters. */
DEMO_FN double demo_distance(const demo_case *c, const double p[3], double uv[2])
{
    double u, v, r[3], d[3];
    int it, k;
    if (c->kind == DEMO_HELICOID) {
        v = p[2] / c->b;
        u = p[0] * cos(v) + p[1] * sin(v);
    } else if (c->kind == DEMO_CATENOID) {
        v = p[1] / c->b;
        u = atan2(p[2], p[0]);
    } else {
        u = p[0];
        v = p[1];
    }
    for (it = 0; it < 60; it++) {
        double ru[3], rv[3], ruu[3], ruv[3], rvv[3], g0, g1, h00, h01, h11, det, du, dv;
        demo_eval(c, u, v, r, ru, rv, ruu, ruv, rvv);
        for (k = 0; k < 3; k++) d[k] = r[k] - p[k];
        g0 = demo_dot(ru, d);
        g1 = demo_dot(rv, d);
        h00 = demo_dot(ru, ru) + demo_dot(ruu, d);
        h01 = demo_dot(ru, rv) + demo_dot(ruv, d);
        h11 = demo_dot(rv, rv) + demo_dot(rvv, d);
        det = h00 * h11 - h01 * h01;
        if (!(h00 > 0 && det > 0)) {
            h00 = demo_dot(ru, ru);
            h01 = demo_dot(ru, rv);
            h11 = demo_dot(rv, rv);
            det = h00 * h11 - h01 * h01;
        }
        du = -(h11 * g0 - h01 * g1) / det;
        dv = -(h00 * g1 - h01 * g0) / det;
        if (c->kind == DEMO_SCHERK) { /* stay inside |b x|, |b y| < pi/2 */
            double lim = 0.5 * M_PI / c->b * (1 - 1e-9);
            while (fabs(u + du) >= lim || fabs(v + dv) >= lim) { du *= 0.5; dv *= 0.5; }
        }
        u += du;
        v += dv;
        if (fabs(du) + fabs(dv) < 1e-15 * (1 + fabs(u) + fabs(v))) break;
    }
    demo_eval(c, u, v, r, NULL, NULL, NULL, NULL, NULL);
    for (k = 0; k < 3; k++) d[k] = r[k] - p[k];
    if (uv) { uv[0] = u; uv[1] = v; }
    return sqrt(demo_dot(d, d));
}

/* Area of the continuous patch over the parameter rectangle: composite
 * 5-point Gauss-Legendre on 48 x 48 panels of |r_u x r_v|. */
DEMO_FN double demo_patch_area(const demo_case *c)
{
    static const double gx[5] = { -0.9061798459386640, -0.5384693101056831, 0.0,
                                  0.5384693101056831, 0.9061798459386640 };
    static const double gw[5] = { 0.2369268850561891, 0.4786286704993665,
                                  0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891 };
    const int panels = 48;
    double hu = (c->u1 - c->u0) / panels, hv = (c->v1 - c->v0) / panels, sum = 0;
    int i, j, a, q;
    if (c->kind == DEMO_MEMBRANE) return 0;
    for (i = 0; i < panels; i++)
        for (j = 0; j < panels; j++)
            for (a = 0; a < 5; a++)
                for (q = 0; q < 5; q++) {
                    double u = c->u0 + hu * (i + 0.5 + 0.5 * gx[a]);
                    double v = c->v0 + hv * (j + 0.5 + 0.5 * gx[q]);
                    double ru[3], rv[3], nrm[3];
                    demo_eval(c, u, v, NULL, ru, rv, NULL, NULL, NULL);
                    demo_cross(ru, rv, nrm);
                    sum += gw[a] * gw[q] * sqrt(demo_dot(nrm, nrm));
                }
    return sum * hu * hv / 4;
}


/* ---------------------------------------------------------------- solving */
#define DEMO_SEED 20260101u /* one fixed seed for every run: same input, same mesh */
static const plateau_method demo_methods[3] = { PLATEAU_METHOD_PAPER,
                                                PLATEAU_METHOD_PAPER_LITERAL,
                                                PLATEAU_METHOD_AREA };

/* CPU seconds, for the time column only (never compared). */
DEMO_FN double demo_seconds(void)
{
    return (double)clock() / CLOCKS_PER_SEC;
}

/* The library call of the demo: the closed polygon L of a case in, the
 * minimal mesh out (its first m vertices are L).  n = 0 means the case's n.
 * *seconds (may be NULL) gets the CPU time of plateau_solve. */
DEMO_FN plateau_result demo_solve(const demo_case *c, plateau_method method, size_t n,
                                  plateau_mesh *mesh, plateau_report *report,
                                  double *seconds, plateau_error *err)
{
    double boundary[3 * DEMO_MAX_BOUNDARY], t0;
    size_t m = demo_boundary(c, boundary);
    plateau_options options;
    plateau_result result;
    memset(&options, 0, sizeof options); /* all zero: the documented defaults */
    options.method = method;
    options.interior_points = n ? n : c->n;
    options.seed = DEMO_SEED;
    t0 = demo_seconds();
    result = plateau_solve(boundary, m, &options, mesh, report, err);
    if (seconds) *seconds = demo_seconds() - t0;
    return result;
}

/* The paper's initial mesh: steps 1 to 3 of the pipeline (parameter
 * domain, the fan's seeded interior points, constrained Delaunay
 * triangulation of the domain) done with the library's public functions
 * and the same seed as demo_solve: what the optimisation starts from with
 * options.seeding = PLATEAU_SEEDING_PAPER (the default quality seeding
 * starts from a refined triangulation that plateau_solve builds inside). */
DEMO_FN plateau_result demo_initial_mesh_uv(const demo_case *c, size_t n, plateau_mesh *mesh,
                                            double *uv_out, plateau_error *err);
DEMO_FN plateau_result demo_initial_mesh(const demo_case *c, size_t n, plateau_mesh *mesh,
                                         plateau_error *err)
{
    return demo_initial_mesh_uv(c, n, mesh, NULL, err);
}

/* The same, and uv_out (may be NULL; room for 2 (m + n) values) gets the
 * domain points of the mesh's vertices: the polygon's domain (step 2),
 * then the chosen candidates (step 3). */
DEMO_FN plateau_result demo_initial_mesh_uv(const demo_case *c, size_t n, plateau_mesh *mesh,
                                            double *uv_out, plateau_error *err)
{
    double boundary[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, boundary), count = 0, i;
    double *xyz = NULL, *uv = NULL;
    plateau_index *segments = NULL;
    plateau_domain_kind kind;
    plateau_dt_input input;
    plateau_dt_mesh dt;
    plateau_result result = PLATEAU_ERR_OUT_OF_MEMORY;
    memset(&dt, 0, sizeof dt);
    if (!n) n = c->n;
    xyz = (double *)malloc(3 * (m + n) * sizeof(double));
    uv = (double *)malloc(2 * (m + n) * sizeof(double));
    segments = (plateau_index *)malloc(2 * m * sizeof(plateau_index));
    if (!xyz || !uv || !segments) goto done;
    memcpy(xyz, boundary, 3 * m * sizeof(double));
    result = plateau_boundary_domain(xyz, m, 0, NULL, uv, &kind, err);
    if (result != PLATEAU_OK) goto done;
    result = plateau_seed_points(xyz, uv, m, n, DEMO_SEED, NULL, xyz + 3 * m, uv + 2 * m,
                                 &count, err);
    if (result != PLATEAU_OK) goto done;
    for (i = 0; i < m; i++) {
        segments[2 * i] = (plateau_index)i;
        segments[2 * i + 1] = (plateau_index)((i + 1) % m);
    }
    input.points = uv;
    input.num_points = m + count;
    input.segments = segments;
    input.num_segments = m;
    result = PLATEAU_ERR_TRIANGULATION;
    if (plateau_dt_triangulate(&input, NULL, &dt, NULL) != PLATEAU_DT_OK ||
        dt.num_points != m + count)
        goto done;
    result = plateau_mesh_create(xyz, m + count, NULL, dt.triangles, dt.num_triangles, NULL,
                                 mesh, err);
    if (result == PLATEAU_OK && uv_out) memcpy(uv_out, uv, 2 * (m + count) * sizeof(double));
done:
    plateau_dt_free(&dt);
    free(xyz);
    free(uv);
    free(segments);
    return result;
}

/* One row of the table. */
typedef struct demo_row {
    const demo_case *c;
    plateau_method method;
    int initial;                /* the start (steps 1 to 3), not a method's result */
    size_t m, n;
    double err_mean;            /* paper's ERR, mean over interior vertices */
    double dist_mean, dist_max; /* distance to the exact surface, interior vertices */
    double h_mean;              /* mean |H_i| over interior vertices */
    double area, patch, optimum;
    double min_angle;
    int iterations;
    double seconds;
} demo_row;

/* Fills a row from a mesh whose first m vertices are the case's polygon. */
DEMO_FN void demo_measure(const demo_case *c, const plateau_mesh *mesh, demo_row *row)
{
    double boundary[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, boundary), i;
    plateau_quality quality;
    row->c = c;
    row->m = m;
    row->n = mesh->num_vertices - m;
    row->err_mean = row->dist_mean = row->dist_max = row->h_mean = 0;
    for (i = m; i < mesh->num_vertices; i++) {
        const double *p = mesh->positions + 3 * i;
        row->h_mean += fabs(plateau_vertex_mean_curvature(mesh, i));
        if (c->kind != DEMO_MEMBRANE) {
            double d = demo_distance(c, p, NULL);
            row->err_mean += demo_err(c, p);
            row->dist_mean += d;
            if (d > row->dist_max) row->dist_max = d;
        }
    }
    if (row->n) {
        row->err_mean /= (double)row->n;
        row->dist_mean /= (double)row->n;
        row->h_mean /= (double)row->n;
    }
    plateau_mesh_quality(mesh, &quality);
    row->area = quality.area;
    row->min_angle = quality.min_angle_deg;
    row->patch = demo_patch_area(c);
}

/* ------------------------------------------------------ the polygon optimum
 * The area of the minimal surface spanning the polygon itself (the smooth
 * patch is not it: the polygon's chords cut the curve's corners).  Where the
 * ranges match, examples/NOTES.md gives it; a Scherk polygon for b != 1 is the
 * b = 1 polygon scaled by 1/b, so its optimum is that one divided by b^2;
 * the other polygons' figures were extrapolated here (demo_extrapolate) and
 * are pinned in demo_cases, so that the table does not move with the
 * reference's own noise (about 1e-5 relative, from the seeding of the fine
 * meshes); the demo recomputes them and says so if one has drifted. */
#define DEMO_PINNED_N 400 /* the pinned figures: meshes with 400 and 1600 points */
#ifndef DEMO_REFERENCE_N
#define DEMO_REFERENCE_N 200 /* the check: 200 and 800 points, 4x cheaper */
#endif

DEMO_FN double demo_reference_area(const demo_case *c, size_t n)
{
    double boundary[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, boundary);
    plateau_options options;
    plateau_mesh mesh;
    plateau_report report;
    plateau_error err;
    double area = -1;
    memset(&mesh, 0, sizeof mesh);
    /* the paper's fan seeding: its points fill the polygon up to its edges,
     * so the mesh size shrinks everywhere as n grows (the quality seeding
     * keeps the polygon's edges whole, and the triangles on them stay
     * large: A(n) then does not follow A* + K/n) */
    memset(&options, 0, sizeof options);
    options.method = PLATEAU_METHOD_AREA;
    options.interior_points = n;
    options.seed = DEMO_SEED;
    options.seeding = PLATEAU_SEEDING_PAPER;
    if (plateau_solve(boundary, m, &options, &mesh, &report, &err) == PLATEAU_OK)
        area = plateau_mesh_area(&mesh);
    else
        fprintf(stderr, "%s: reference with n = %lu failed: %s\n", c->name,
                (unsigned long)n, err.message);
    plateau_mesh_free(&mesh);
    return area;
}

/* The optimum of a case's polygon (0 if unknown); *source (may be NULL)
 * gets "examples/NOTES.md", "extrapolated" or "scaled". */
DEMO_FN double demo_optimum(const demo_case *c, const char **source)
{
    if (c->reference_of >= 0) {
        if (source) *source = "scaled";
        return demo_cases[c->reference_of].optimum / (c->b * c->b);
    }
    if (source) *source = c->optimum_notes ? "examples/NOTES.md" : "extrapolated";
    return c->optimum;
}

/* Extrapolates the polygon's optimum from area-minimising meshes with n and
 * 4n interior points, A(n) = A* + K/n (mesh size squared ~ 1/n), and caches
 * it in out/optimum-<case>.txt.  recompute = 0 takes the cache when it is
 * still right (its A(n) is what the library gives now: a changed library
 * invalidates it).  Returns A*, or 0 on failure. */
DEMO_FN double demo_extrapolate(const demo_case *c, int recompute)
{
    char path[256], key[128], line[512];
    double value = 0, cached_a1 = 0, a1, a4;
    FILE *f;
    sprintf(path, "out/optimum-%s.txt", c->name);
    sprintf(key, "%s n=%d,%d", c->name, DEMO_REFERENCE_N, 4 * DEMO_REFERENCE_N);
    f = recompute ? NULL : fopen(path, "r");
    if (f) {
        size_t len = strlen(key);
        if (fgets(line, sizeof line, f) && strncmp(line, key, len) == 0 && line[len] == ' ') {
            char *end;
            value = strtod(line + len + 1, &end);
            cached_a1 = strtod(end, NULL);
        }
        fclose(f);
    }
    a1 = demo_reference_area(c, DEMO_REFERENCE_N);
    if (value > 0 && a1 == cached_a1) return value;
    a4 = demo_reference_area(c, 4 * DEMO_REFERENCE_N);
    if (a1 <= 0 || a4 <= 0) return 0;
    value = (4 * a4 - a1) / 3;
    f = fopen(path, "w");
    if (f) {
        fprintf(f, "%s %.17g %.17g %.17g\n# optimum, A(%d), A(%d): extrapolated "
                   "(4 A(4n) - A(n)) / 3\n",
                key, value, a1, a4, DEMO_REFERENCE_N, 4 * DEMO_REFERENCE_N);
        fclose(f);
    }
    return value;
}

/* ------------------------------------------------------------- the table */
#define DEMO_TABLE_HEADER                                                                  \
    "| case | method | m | n | ERR | paper's ERR | dist mean | dist max | mean \\|H\\| | "   \
    "area | patch | optimum | excess | min angle | iters | time s |\n"                       \
    "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n"

static const char *const demo_groups[] = { "helicoid", "catenoid", "scherk", "membrane" };

/* The paper's published figure for a case and method. */
DEMO_FN const char *demo_paper_figure(const demo_case *c, plateau_method method)
{
    if (c->kind == DEMO_MEMBRANE)
        return method == PLATEAU_METHOD_AREA ? "-" : "mean \\|H\\| 4.786e-4";
    if (c->kind == DEMO_SCHERK) return "Fig. 8 only";
    return method == PLATEAU_METHOD_AREA ? c->paper_chen : c->paper_ours;
}

/* One Markdown row; the time is the last cell (left out when comparing). */
DEMO_FN void demo_format_row(const demo_row *r, char *buf, size_t cap)
{
    char err[32], dmean[32], dmax[32], patch[32], opt[32], excess[32], h[32];
    if (r->c->kind == DEMO_MEMBRANE) {
        strcpy(err, "-"); strcpy(dmean, "-"); strcpy(dmax, "-"); strcpy(patch, "-");
    } else {
        sprintf(err, "%.3e", r->err_mean);
        sprintf(dmean, "%.2e", r->dist_mean);
        sprintf(dmax, "%.2e", r->dist_max);
        sprintf(patch, "%.5g", r->patch);
    }
    /* H_i = 0 solved to rounding: its last digits would differ with any change */
    if (r->h_mean < 1e-10)
        strcpy(h, "< 1e-10");
    else
        sprintf(h, "%.2e", r->h_mean);
    if (r->optimum > 0) {
        sprintf(opt, "%.6g", r->optimum);
        sprintf(excess, "%+.2f%%", 100 * (r->area - r->optimum) / r->optimum);
    } else {
        strcpy(opt, "-"); strcpy(excess, "-");
    }
    snprintf(buf, cap,
             "| %s | %s | %lu | %lu | %s | %s | %s | %s | %s | %.6g | %s | %s | %s | %.1f | %d | %.3f |\n",
             r->c->name, r->initial ? "initial" : plateau_method_name(r->method),
             (unsigned long)r->m, (unsigned long)r->n, err,
             r->initial ? "" : demo_paper_figure(r->c, r->method), dmean, dmax,
             h, r->area, patch, opt, excess, r->min_angle, r->iterations, r->seconds);
}

/* The notes under the table: where every number comes from. */
DEMO_FN void demo_write_notes(FILE *f)
{
    size_t i;
    fprintf(f, "\nCases (the paper gives no parameter ranges: these are chosen here; each "
               "polygon samples the sides of the parameter rectangle uniformly in the "
               "parameter):\n\n");
    for (i = 0; i < DEMO_NUM_CASES; i++) {
        const demo_case *c = &demo_cases[i];
        if (c->kind == DEMO_HELICOID)
            fprintf(f, "- `%s`: r(u,v) = (u cos v, u sin v, b v), b = %g, u in [%g, %g], "
                       "v in [%.6g, %.6g] (+-pi/4); %d segments on each straight side (v "
                       "fixed), %d on each helix (u fixed)\n",
                    c->name, c->b, c->u0, c->u1, c->v0, c->v1, c->nu, c->nv);
        else if (c->kind == DEMO_CATENOID)
            fprintf(f, "- `%s`: r(u,v) = (b cos u cosh v, b v, b sin u cosh v), b = %g, "
                       "u in [%.6g, %.6g] (pi/4 to 3pi/4), v in [%g, %g]; %d segments on "
                       "each circular arc (v fixed), %d on each catenary (u fixed)\n",
                    c->name, c->b, c->u0, c->u1, c->v0, c->v1, c->nu, c->nv);
        else if (c->kind == DEMO_SCHERK)
            fprintf(f, "- `%s`: z = (1/b) ln(cos(b y)/cos(b x)), b = %g, x, y in [%.6g, %.6g] "
                       "(|b x| <= %g), %d segments per side\n",
                    c->name, c->b, c->u0, c->u1, c->u1 * c->b, c->nu);
        else
            fprintf(f, "- `%s`: a four-point shade sail (examples/surfaces.h): corners "
                       "(0, 0, 3.6), (8, 0, 2.6), (6.5, 5.5, 3.8), (1, 5, 2.2) m, cable "
                       "edges sagging %g %% in plan, 2 + 1 + 1 + 1 edge vertices\n",
                    c->name, 100 * DEMO_SAIL_SAG);
    }
    fprintf(f,
            "\nERR: the paper's formulas (III.A to III.C), mean over the interior vertices "
            "(the polygon's vertices lie on the surface); on these ranges the helicoid's is "
            "always the absolute one (|y| <= 0.71) and the catenoid's the relative one "
            "(z >= 1.45). dist: distance from the interior "
            "vertices to the exact analytic surface, by Newton's method on the "
            "parametrisation. mean |H|: the paper's discrete mean curvature (which "
            "approximates k1 + k2) at the interior vertices. patch: area of the smooth "
            "patch; optimum: the polygon's own minimal area (helicoid, catenoid and "
            "`scherk-b1-m`: examples/NOTES.md; the other b = 1 Scherk polygons and the "
            "membrane: area minimisation with %d and %d interior points extrapolated as "
            "A* + K/n, pinned in examples/surfaces.h and rechecked by the demo with %d and "
            "%d (this extrapolation gives the examples/NOTES.md figures to 0.01 %%); "
            "b = 0.4 and 4.9: the b = 1 figure divided by b^2, the polygons being "
            "scaled copies); excess: (area - optimum) / optimum. min angle in degrees; "
            "iters: LM or quasi-Newton iterations over all rounds; time: CPU seconds of "
            "plateau_solve.\n\n"
            "paper's ERR: the figures published for the paper's method and for Chen et "
            "al.'s area method. The paper does not give its parameter ranges, and ERR "
            "depends on them strongly (measured: 11x to 50x across plausible ranges), so "
            "these are not like-for-like with the ERR column.\n",
            DEMO_PINNED_N, 4 * DEMO_PINNED_N, DEMO_REFERENCE_N, 4 * DEMO_REFERENCE_N);
}

/* Writes out/rows-<group>.md, then out/table.md from the row files of every
 * group present (so each example can run alone). */
DEMO_FN int demo_write_table(const char *group, const demo_row *rows, size_t count)
{
    char path[256], buf[1024];
    size_t i, g;
    FILE *f, *in;
    sprintf(path, "out/rows-%s.md", group);
    f = fopen(path, "w");
    if (!f) return -1;
    for (i = 0; i < count; i++) {
        demo_format_row(&rows[i], buf, sizeof buf);
        fputs(buf, f);
    }
    fclose(f);
    f = fopen("out/table.md", "w");
    if (!f) return -1;
    fputs(DEMO_TABLE_HEADER, f);
    for (g = 0; g < sizeof demo_groups / sizeof demo_groups[0]; g++) {
        sprintf(path, "out/rows-%s.md", demo_groups[g]);
        in = fopen(path, "r");
        if (!in) continue;
        while (fgets(buf, sizeof buf, in)) fputs(buf, f);
        fclose(in);
    }
    demo_write_notes(f);
    fclose(f);
    return 0;
}

/* The table without its last (time) column, for comparing two tables:
 * every line starting with '|' loses its last cell. */
DEMO_FN void demo_strip_time(const char *line, char *out, size_t cap)
{
    size_t len = strlen(line);
    const char *p;
    while (len && (line[len - 1] == '\n' || line[len - 1] == '\r' || line[len - 1] == ' '))
        len--;
    if (len >= cap) len = cap - 1;
    memcpy(out, line, len);
    out[len] = 0;
    if (out[0] != '|' || len < 2) return;
    out[len - 1] = 0; /* the closing '|' */
    p = strrchr(out, '|');
    if (p) out[p - out + 1] = 0;
}

/* ------------------------------------------------------------ the examples */
/* The direction the eye looks in, per case, for the SVG pictures. */
DEMO_FN void demo_view(const demo_case *c, double view[3])
{
    view[0] = -1; view[1] = -1; view[2] = -1; /* the library's default */
    if (c->kind == DEMO_HELICOID) { view[0] = -1.0; view[1] = -0.35; view[2] = -0.45; }
    if (c->kind == DEMO_CATENOID) { view[0] = -0.35; view[1] = -1.0; view[2] = -0.9; }
    if (c->kind == DEMO_MEMBRANE) { view[0] = 0.6; view[1] = 0.8; view[2] = -0.9; }
}

/* Writes <stem>.obj and <stem>.svg; also a copy of the SVG under
 * examples/pictures/ when picture is non-zero (the README's pictures). */
DEMO_FN int demo_write_files(const demo_case *c, const plateau_mesh *mesh, const char *what,
                             int picture)
{
    char path[256];
    double view[3];
    plateau_error err;
    demo_view(c, view);
    sprintf(path, "out/%s-%s.obj", c->name, what);
    if (plateau_write_mesh(path, mesh->positions, mesh->num_vertices, mesh->triangles,
                           mesh->num_triangles, &err) != PLATEAU_OK)
        goto fail;
    sprintf(path, "out/%s-%s.svg", c->name, what);
    if (plateau_write_svg(path, mesh->positions, mesh->num_vertices, mesh->triangles,
                          mesh->num_triangles, view, &mesh->allocator, &err) != PLATEAU_OK)
        goto fail;
    if (!picture) return 0;
    sprintf(path, "examples/pictures/%s-%s.svg", c->name, what);
    if (plateau_write_svg(path, mesh->positions, mesh->num_vertices, mesh->triangles,
                          mesh->num_triangles, view, &mesh->allocator, &err) == PLATEAU_OK)
        return 0;
fail:
    fprintf(stderr, "%s: %s\n", path, err.message);
    return -1;
}

/* Prints a row, time included. */
DEMO_FN void demo_print_row(const demo_row *row)
{
    char buf[1024];
    demo_format_row(row, buf, sizeof buf);
    fputs(buf, stdout);
}

/* Runs every case of a group (the example programs call this): for each
 * case the initial Delaunay mesh and the three methods, one table row per
 * method, OBJ and SVG files in out/, then out/table.md.  Returns the exit
 * code. */
DEMO_FN int demo_run_group(const char *group)
{
    demo_row rows[3 * DEMO_NUM_CASES];
    size_t count = 0, i;
    int k, status = 0;
    for (i = 0; i < DEMO_NUM_CASES; i++) {
        const demo_case *c = &demo_cases[i];
        int picture = c->kind == DEMO_HELICOID || c->kind == DEMO_CATENOID;
        const char *source = "";
        double optimum;
        plateau_mesh mesh;
        plateau_report report;
        plateau_error err;
        demo_row row;
        if (strcmp(c->group, group) != 0) continue;
        optimum = demo_optimum(c, &source);
        if (c->kind == DEMO_MEMBRANE)
            printf("\n%s: the designed sail, n = %lu, polygon optimum %.6g (%s)\n", c->name,
                   (unsigned long)c->n, optimum, source);
        else
            printf("\n%s: b = %g, parameters [%.6g, %.6g] x [%.6g, %.6g], n = %lu, "
                   "polygon optimum %.6g (%s)\n",
                   c->name, c->b, c->u0, c->u1, c->v0, c->v1, (unsigned long)c->n, optimum,
                   source);
        if (c->reference_of < 0 && !c->optimum_notes) { /* check the pinned figure */
            double today = demo_extrapolate(c, 0);
            printf("  extrapolated today: %.6g (%+.1e relative)%s\n", today,
                   (today - optimum) / optimum,
                   fabs(today - optimum) > 3e-4 * optimum
                       ? ": the pinned figure in examples/surfaces.h has drifted"
                       : "");
        }
        printf(DEMO_TABLE_HEADER);
        /* the start: steps 1 to 3 only, before any optimisation */
        memset(&mesh, 0, sizeof mesh);
        if (demo_initial_mesh(c, 0, &mesh, &err) == PLATEAU_OK) {
            memset(&row, 0, sizeof row);
            demo_measure(c, &mesh, &row);
            row.initial = 1;
            row.optimum = optimum;
            demo_print_row(&row);
            if (demo_write_files(c, &mesh, "initial", picture)) status = 1;
        } else {
            fprintf(stderr, "%s: initial mesh: %s\n", c->name, err.message);
            status = 1;
        }
        plateau_mesh_free(&mesh);
        for (k = 0; k < 3; k++) {
            double seconds = 0;
            plateau_result r;
            memset(&mesh, 0, sizeof mesh);
            memset(&row, 0, sizeof row);
            r = demo_solve(c, demo_methods[k], 0, &mesh, &report, &seconds, &err);
            if (r != PLATEAU_OK) {
                fprintf(stderr, "%s, %s: %s (%s)\n", c->name, plateau_method_name(demo_methods[k]),
                        plateau_result_string(r), err.message);
                plateau_mesh_free(&mesh);
                status = 1;
                continue;
            }
            demo_measure(c, &mesh, &row);
            row.method = demo_methods[k];
            row.optimum = optimum;
            row.iterations = report.iterations;
            row.seconds = seconds;
            demo_print_row(&row);
            if (report.inverted_triangles)
                printf("  (warning: %zu inverted triangles, largest |beta| %.1f deg)\n",
                       report.inverted_triangles, report.max_abs_beta_deg);
            if (demo_write_files(c, &mesh, plateau_method_name(demo_methods[k]),
                                 picture && demo_methods[k] != PLATEAU_METHOD_PAPER_LITERAL))
                status = 1;
            rows[count++] = row;
            plateau_mesh_free(&mesh);
        }
    }
    if (demo_write_table(group, rows, count)) {
        fprintf(stderr, "cannot write out/table.md (run from the top directory)\n");
        status = 1;
    }
    return status;
}

/* The films between two coaxial rings of radius 1 at separation h (the
 * catenoids r(z) = a cosh(z / a)): the neck a solves a cosh(h / (2a)) = 1,
 * whose two roots lie either side of the fold x tanh x = 1, x = h / (2a)
 * (x = 1.19967864, so no root past h = 1.3255): the larger root is the
 * stable catenoid, the smaller the unstable one (index 1); both by
 * bisection.  Area pi a (h + a sinh(h / a)).  Used by
 * examples/catenoid_rings.c, tests/test_solve_loops.c and
 * tests/test_stability.c. */
DEMO_FN double demo_catenoid_neck_branch(double h, int unstable)
{
    double fold = h / (2.0 * 1.19967864025773), lo = unstable ? h / 60.0 : fold, hi = unstable ? fold : 1.0;
    int it;
    for (it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi), f = mid * cosh(h / (2.0 * mid)) - 1.0;
        /* f falls from +inf to its minimum at the fold, then rises */
        if ((f > 0.0) == (unstable != 0)) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

DEMO_FN double demo_catenoid_area_of(double h, double a)
{
    return 3.141592653589793 * a * (h + a * sinh(h / a));
}

DEMO_FN double demo_catenoid_neck(double h)
{
    return demo_catenoid_neck_branch(h, 0);
}

DEMO_FN double demo_catenoid_area(double h)
{
    return demo_catenoid_area_of(h, demo_catenoid_neck(h));
}

/* Two coaxial rings of radius 1 at z = -h/2 and h/2, m vertices each. */
DEMO_FN void demo_rings(double *xyz, int m, double h)
{
    int i, j;
    for (j = 0; j < 2; j++)
        for (i = 0; i < m; i++) {
            double t = (2.0 * M_PI) * i / m;
            xyz[3 * (j * m + i)] = cos(t);
            xyz[3 * (j * m + i) + 1] = sin(t);
            xyz[3 * (j * m + i) + 2] = (j ? 0.5 : -0.5) * h;
        }
}

/* The catenoid r = a cosh(z / a) between those rings (either branch, or
 * any neck a for a start), sampled: rows of m
 * vertices at k (odd) equally spaced heights between them, every other
 * row turned by half a step, triangulated as strips; the rings are
 * vertices 0 .. 2m-1. */
DEMO_FN plateau_result demo_catenoid_mesh(double h, double a, int m, int k, plateau_mesh *mesh)
{
    size_t nv = (size_t)m * (size_t)(k + 2);
    int i, j, t = 0, next = 2 * m;
    double *p = (double *)malloc(3 * nv * sizeof(double));
    plateau_index *tri = (plateau_index *)malloc(6 * (size_t)m * (size_t)(k + 1) * sizeof(plateau_index));
    int *id = (int *)malloc(nv * sizeof(int));
    plateau_result r = PLATEAU_ERR_OUT_OF_MEMORY;
    if (p && tri && id) {
        for (j = 0; j < k + 2; j++)
            for (i = 0; i < m; i++) {
                int ring_row = j == 0 || j == k + 1, v = j == 0 ? i : j == k + 1 ? m + i : next++;
                double z = -0.5 * h + h * j / (k + 1), th = (2.0 * M_PI) * (i + 0.5 * (j % 2)) / m;
                double rr = ring_row ? 1.0 : a * cosh(z / a);
                if (ring_row) z = (j ? 0.5 : -0.5) * h;
                id[j * m + i] = v;
                p[3 * v] = rr * cos(th);
                p[3 * v + 1] = rr * sin(th);
                p[3 * v + 2] = z;
            }
        for (j = 0; j <= k; j++)
            for (i = 0; i < m; i++) {
                int a0 = id[j * m + i], a1 = id[j * m + (i + 1) % m];
                int b0 = id[(j + 1) * m + i], b1 = id[(j + 1) * m + (i + 1) % m];
                if (j % 2 == 0) { /* row j + 1 is half a step ahead */
                    tri[3 * t] = a0; tri[3 * t + 1] = a1; tri[3 * t + 2] = b0; t++;
                    tri[3 * t] = a1; tri[3 * t + 1] = b1; tri[3 * t + 2] = b0; t++;
                } else {
                    tri[3 * t] = a0; tri[3 * t + 1] = a1; tri[3 * t + 2] = b1; t++;
                    tri[3 * t] = a0; tri[3 * t + 1] = b1; tri[3 * t + 2] = b0; t++;
                }
            }
        r = plateau_mesh_create(p, nv, NULL, tri, (size_t)t, NULL, mesh, NULL);
    }
    free(p);
    free(tri);
    free(id);
    return r;
}

#endif /* PLATEAU_DEMO_SURFACES_H */
