/* test_accuracy.c - the error estimate of every result
 * (report.area_error_estimate) and the accuracy as the request
 * (options.accuracy): the effectivity (true relative error over the
 * estimate) on films of known area at several sizes, the default
 * accuracy and --accuracy 1e-4 on a four-corner tent, a tighter accuracy
 * never worse, the membranes' estimate of their energy (the pressure's
 * and the held volume's cap, a cable-edged square) and an accuracy asked
 * of one, and an estimate that cannot be formed says why. */
#ifndef PLATEAU_TEST_LINKED /* else make test links tests/impl.c's object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "tests/harness.h"
#include "examples/surfaces.h"

#define TWO_PI 6.283185307179586

/* The tent: a 4 m square, two opposite corners raised 2.5 m.  Its film's
 * area, the polygon's own optimum, converged by coarse to fine at 10^5 to
 * 10^6 interior points (examples/NOTES.md, "The error estimate"). */
static const double TENT[12] = {0, 0, 0, 4, 0, 2.5, 4, 4, 0, 0, 4, 2.5};
#define TENT_AREA 17.92240029

/* Two coaxial rings of radius 1 at z = -h/2 and h/2, m vertices each. */
static void rings(double *xyz, int m, double h)
{
    int i, j;
    for (j = 0; j < 2; j++)
        for (i = 0; i < m; i++) {
            double t = TWO_PI * (double)i / m;
            double *p = xyz + 3 * ((size_t)j * (size_t)m + (size_t)i);
            p[0] = cos(t);
            p[1] = sin(t);
            p[2] = (j ? 0.5 : -0.5) * h;
        }
}

/* The catenoid between rings of m vertices: the smooth catenoid's area
 * scaled by the polygon's: each ring of m chords spans (m / 2pi) sin(2pi
 * / m) of the circle's perimeter, and the catenoid through the chords'
 * midpoints (radius cos(pi / m)) is the smooth one scaled by that radius;
 * the polygon's own optimum lies between the two, within O(1 / m^2) of
 * both, far below the mesh's error at the sizes tested. */
static double ring_catenoid_area(double h, int m)
{
    double c = cos(TWO_PI / (2.0 * m));
    /* the catenoid between rings of radius c at distance h: scale by c */
    return c * c * demo_catenoid_area(h / c);
}

/* One solve's outcome (err: a membrane's true relative error) */
typedef struct acc_run {
    plateau_result rc;
    double area, err, estimate, seconds;
    size_t interior, solves;
    unsigned defects;
    plateau_estimate status;
} acc_run;

/* The outcome of a solve that returned rc with report rep, begun at c0. */
static acc_run run_of(plateau_result rc, clock_t c0, const plateau_report *rep)
{
    acc_run r;
    memset(&r, 0, sizeof r);
    r.rc = rc;
    r.seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    r.area = rep->area;
    r.estimate = rep->area_error_estimate;
    r.interior = rep->interior_points;
    r.solves = rep->accuracy_solves;
    r.defects = rep->defects;
    r.status = rep->estimate;
    return r;
}

static acc_run solve_tent(size_t n, double accuracy)
{
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    acc_run r;
    clock_t c0 = clock();
    memset(&o, 0, sizeof o);
    o.interior_points = n;
    o.accuracy = accuracy;
    r = run_of(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), c0, &rep);
    plateau_mesh_free(&mesh);
    return r;
}

static acc_run solve_rings(double h, int m, size_t n, double accuracy)
{
    double *xyz = (double *)malloc(6 * (size_t)m * sizeof(double));
    size_t counts[2];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    acc_run r;
    clock_t c0 = clock();
    memset(&r, 0, sizeof r);
    r.rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (!xyz) return r;
    rings(xyz, m, h);
    counts[0] = counts[1] = (size_t)m;
    memset(&o, 0, sizeof o);
    o.interior_points = n;
    o.accuracy = accuracy;
    o.stability = PLATEAU_OFF;
    o.alternatives = PLATEAU_OFF;
    r = run_of(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, NULL), c0, &rep);
    plateau_mesh_free(&mesh);
    free(xyz);
    return r;
}

/* effectivity = true error / estimate within [0.25, 4] */
static void check_effectivity(const char *what, const acc_run *r, double exact)
{
    double err = r->area / exact - 1.0, eff = err / r->estimate;
    char msg[160];
    printf("  %-26s n %6lu  area %.8f  true %.3e  estimate %.3e  effectivity %.2f  %.3f s\n", what,
           (unsigned long)r->interior, r->area, err, r->estimate, eff, r->seconds);
    snprintf(msg, sizeof msg, "%s at n = %lu: effectivity %.3f in [0.25, 4]", what, (unsigned long)r->interior, eff);
    CHECK_EQ_INT(r->rc, PLATEAU_OK);
    CHECK_EQ_INT(r->status, PLATEAU_ESTIMATE_FORMED);
    CHECK_MSG(eff >= 0.25 && eff <= 4.0, msg);
}

static void test_effectivity_tent(void)
{
    static const size_t ns[3] = {100, 1000, 10000};
    int i;
    printf("the tent, one solve at n (accuracy -1):\n");
    for (i = 0; i < 3; i++) {
        acc_run r = solve_tent(ns[i], -1.0);
        CHECK_EQ_INT(r.solves, 1);
        check_effectivity("tent", &r, TENT_AREA);
    }
}

static void test_effectivity_catenoid(void)
{
    static const double hs[3] = {0.5, 0.9, 1.2};
    static const size_t ns[3] = {100, 1000, 10000};
    int i, j;
    printf("the catenoid between rings of 256 vertices, one solve at n:\n");
    for (j = 0; j < 3; j++)
        for (i = 0; i < (j == 1 ? 3 : 2); i++) { /* 10^4 points once: 5-10 s */
            char what[64];
            acc_run r = solve_rings(hs[j], 256, ns[i], -1.0);
            snprintf(what, sizeof what, "catenoid h = %.1f", hs[j]);
            check_effectivity(what, &r, ring_catenoid_area(hs[j], 256));
        }
}

/* Membranes (MEMBRANES at the top): the estimate is of the energy
 * E = A - p V + sum T L against the exact equilibrium, relative to
 * A + |p V| + sum T L; the true error below is relative to the same
 * scale of the exact solution. */
/* The cap of pressure p on the circle of radius r (unit tension, Laplace
 * p = 2 / R): height h = R - sqrt(R^2 - r^2), area 2 pi R h, volume
 * pi h^2 (3 R - h) / 3. */
static void cap_of_pressure(double p, double r, double *area, double *vol)
{
    double R = 2.0 / p, h = R - sqrt(R * R - r * r);
    *area = TWO_PI * R * h;
    *vol = TWO_PI * h * h * (3.0 * R - h) / 6.0;
}

/* The cap of volume v on the circle of radius r: v = pi h (3 r^2 + h^2) / 6
 * solved for h by Newton's method (increasing in h), area pi (r^2 + h^2),
 * pressure 2 / R with R = (r^2 + h^2) / (2 h). */
static void cap_of_volume(double v, double r, double *area, double *p)
{
    double h = 0.5 * r;
    int i;
    for (i = 0; i < 60; i++)
        h -= (TWO_PI * h * (3.0 * r * r + h * h) / 12.0 - v) / (TWO_PI * (r * r + h * h) / 4.0);
    *area = 0.5 * TWO_PI * (r * r + h * h);
    *p = 4.0 * h / (r * r + h * h);
}

/* The cap on the unit circle of m vertices meshed at its own spacing
 * (edge length 2 sin(pi / m) inside too), at pressure p, or holding the
 * volume v (hold).  The reference is the cap on the circle of the
 * polygon's area (radius^2 (m / 2 pi) sin(2 pi / m)): E's first variation
 * under an in-plane motion delta of the boundary is cos(alpha) times the
 * integral of delta along it (alpha the film's angle with the plane; the
 * volume's share vanishes where the film meets the plane), 0 between two
 * curves of equal area, so that circle's cap is within O(1 / m^3) of the
 * polygon's equilibrium where the unit circle's is O(1 / m^2) away, as
 * far as the mesh's own error. */
static acc_run solve_cap_membrane(plateau_method method, int m, double p, int hold, double v)
{
    double *xyz = (double *)malloc(3 * (size_t)m * sizeof(double)), r, a, vol, pe, e, sc;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    acc_run run;
    clock_t c0 = clock();
    int i;
    memset(&run, 0, sizeof run);
    run.rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (!xyz) return run;
    for (i = 0; i < m; i++) {
        xyz[3 * i] = cos(TWO_PI * i / m);
        xyz[3 * i + 1] = sin(TWO_PI * i / m);
        xyz[3 * i + 2] = 0.0;
    }
    memset(&o, 0, sizeof o);
    o.method = method;
    o.quality_edge_length = 2.0 * sin(0.5 * TWO_PI / m);
    o.interior_points = (size_t)(0.5 * TWO_PI / (0.866 * o.quality_edge_length * o.quality_edge_length));
    o.accuracy = -1.0;
    o.pressure = hold ? 0.0 : p;
    o.fix_volume = hold;
    o.volume = v;
    run = run_of(plateau_solve(xyz, (size_t)m, &o, &mesh, &rep, NULL), c0, &rep);
    r = sqrt(m / TWO_PI * sin(TWO_PI / m));
    if (hold) {
        /* the area at the volume held: E = A - p V with V = v fixed */
        cap_of_volume(v, r, &a, &pe);
        sc = a + fabs(pe * v);
        run.err = (rep.area - a) / sc;
    } else {
        cap_of_pressure(p, r, &a, &vol);
        e = a - p * vol;
        sc = a + fabs(p * vol);
        run.err = (rep.area - p * rep.volume - e) / sc;
    }
    plateau_mesh_free(&mesh);
    free(xyz);
    return run;
}

/* The flat square (+-1, +-1, 0) whose four sides are cables of tension T:
 * each an arc of radius T (T kappa = 1) over the chord 2, half-angle
 * a = asin(1 / T), length 2 T a; the film's area 4 minus four circular
 * segments T^2 (a - sin a cos a); E = A + 4 T L. */
static acc_run solve_cable_square(plateau_method method, double T, size_t n, double accuracy)
{
    double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, ts[4], a = asin(1.0 / T), e, eh;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    acc_run run;
    clock_t c0 = clock();
    int k;
    for (k = 0; k < 4; k++) ts[k] = T;
    memset(&o, 0, sizeof o);
    memset(&run, 0, sizeof run);
    o.method = method;
    o.interior_points = n;
    o.accuracy = accuracy;
    o.cable_tension = ts;
    run = run_of(plateau_solve(sq, 4, &o, &mesh, &rep, NULL), c0, &rep);
    e = 4.0 - 4.0 * T * T * (a - sin(a) * cos(a)) + 4.0 * T * (2.0 * T * a);
    eh = rep.area;
    for (k = 0; k < 4 && k < (int)rep.cables; k++) eh += T * rep.cable[k].length;
    run.err = rep.cables == 4 ? (eh - e) / e : 1.0; /* every term positive: the scale is E */
    plateau_mesh_free(&mesh);
    return run;
}

static void check_membrane(const char *what, const acc_run *r)
{
    double eff = r->err / r->estimate;
    char msg[160];
    printf("  %-26s n %6lu  true %.3e  estimate %.3e  effectivity %.2f  %.3f s\n", what, (unsigned long)r->interior,
           r->err, r->estimate, eff, r->seconds);
    snprintf(msg, sizeof msg, "%s at n = %lu: effectivity %.3f in [0.25, 4]", what, (unsigned long)r->interior, eff);
    CHECK_EQ_INT(r->rc, PLATEAU_OK);
    CHECK_EQ_INT(r->defects, 0);
    CHECK_EQ_INT(r->status, PLATEAU_ESTIMATE_FORMED);
    CHECK_MSG(eff >= 0.25 && eff <= 4.0, msg);
}

/* The cap of p = 1 (R = 2), the cable square of T = 2 and the cap holding
 * the p = 1 cap's volume, each at 10^2 to 10^3 interior points (10^4 in
 * the full tier), by method paper (the default) and method area (the
 * held volume's by method area, whose multiplier's solves run to the
 * gradient test, in the full tier up to 3 10^3). */
static void test_effectivity_membranes(void)
{
    static const size_t ns[5] = {100, 300, 1000, 3000, 10000};
    const plateau_method pa = PLATEAU_METHOD_PAPER, ar = PLATEAU_METHOD_AREA;
    double a1, v1;
    int i, sizes = HARNESS_FULL ? 5 : 3;
    cap_of_pressure(1.0, 1.0, &a1, &v1);
    CHECK_NEAR(a1, 3.367148858, 1e-9); /* test_membrane's figures */
    CHECK_NEAR(v1, 0.430966541, 1e-9);
    printf("membranes, the energy's estimate:\n");
    for (i = 0; i < sizes; i++) {
        /* the circle's vertices at the interior spacing of n points */
        int m = (int)(sqrt(7.2 * (double)ns[i]) + 0.5);
        acc_run c = solve_cap_membrane(pa, m, 1.0, 0, 0.0), h = solve_cap_membrane(pa, m, 0.0, 1, v1);
        acc_run q = solve_cable_square(pa, 2.0, ns[i], -1.0);
        acc_run ca = solve_cap_membrane(ar, m, 1.0, 0, 0.0), qa = solve_cable_square(ar, 2.0, ns[i], -1.0);
        check_membrane("cap p = 1", &c);
        check_membrane("cap, volume held", &h);
        check_membrane("cable square T = 2", &q);
        check_membrane("cap p = 1, method area", &ca);
        check_membrane("cable square, method area", &qa);
        if (HARNESS_FULL && ns[i] <= 3000) { /* 10^4: 100 s of CPU */
            acc_run ha = solve_cap_membrane(ar, m, 0.0, 1, v1);
            check_membrane("cap, volume held, area", &ha);
        }
    }
}

/* plateau_mesh_minimize at a pressure (its apex: the fixed vertices'
 * centroid, here the circle's as in plateau_solve) estimates the cap it
 * is given as plateau_solve did, within the few Newton steps it adds. */
static void test_membrane_minimize(void)
{
    double xyz[3 * 48];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report r1, r2;
    int i;
    for (i = 0; i < 48; i++) {
        xyz[3 * i] = cos(TWO_PI * i / 48);
        xyz[3 * i + 1] = sin(TWO_PI * i / 48);
        xyz[3 * i + 2] = 0.0;
    }
    memset(&o, 0, sizeof o);
    o.interior_points = 300;
    o.pressure = 1.0;
    CHECK_EQ_INT(plateau_solve(xyz, 48, &o, &mesh, &r1, NULL), PLATEAU_OK);
    memset(&o, 0, sizeof o);
    o.pressure = 1.0;
    CHECK_EQ_INT(plateau_mesh_minimize(&mesh, &o, &r2, NULL), PLATEAU_OK);
    printf("cap p = 1, 48-gon: plateau_solve estimate %.4e, plateau_mesh_minimize %.4e\n", r1.area_error_estimate,
           r2.area_error_estimate);
    CHECK_EQ_INT(r2.estimate, PLATEAU_ESTIMATE_FORMED);
    CHECK(fabs(r2.area_error_estimate / r1.area_error_estimate - 1.0) < 0.1);
    plateau_mesh_free(&mesh);
}

/* The accuracy asked of a membrane: the cable square solves again until
 * its energy's estimate meets 1e-4, and the true error is within 4 times
 * of it. */
static void test_membrane_accuracy(void)
{
    acc_run q = solve_cable_square(PLATEAU_METHOD_PAPER, 2.0, 0, 1e-4);
    printf("cable square T = 2, accuracy 1e-4: n %lu, %lu solves, true %.3e, estimate %.3e, %.3f s\n",
           (unsigned long)q.interior, (unsigned long)q.solves, q.err, q.estimate, q.seconds);
    CHECK_EQ_INT(q.rc, PLATEAU_OK);
    CHECK_EQ_INT(q.defects, 0);
    CHECK(q.solves >= 2);
    CHECK(q.estimate <= 1e-4);
    CHECK(q.err > 0.0 && q.err <= 4e-4);
}

/* The regular 40-gon in the plane z = 0. */
static void flat_disc(double *xyz)
{
    int i;
    for (i = 0; i < 40; i++) {
        xyz[3 * i] = cos(TWO_PI * i / 40);
        xyz[3 * i + 1] = sin(TWO_PI * i / 40);
        xyz[3 * i + 2] = 0.0;
    }
}

/* A plane polygon: the film is the polygon itself, every mesh of it has
 * its area, and nothing is left to gain but rounding. */
static void test_flat_disc(void)
{
    double xyz[3 * 40];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    flat_disc(xyz);
    memset(&o, 0, sizeof o);
    CHECK_EQ_INT(plateau_solve(xyz, 40, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.estimate, PLATEAU_ESTIMATE_FORMED);
    /* the rounding level, never 0 */
    CHECK(rep.area_error_estimate > 0.0 && rep.area_error_estimate < 1e-12);
    CHECK_EQ_INT(rep.accuracy_solves, 1);
    CHECK_NEAR(rep.area, 20.0 * sin(TWO_PI / 40), 1e-12);
    printf("flat disc: estimate %.3e\n", rep.area_error_estimate);
    plateau_mesh_free(&mesh);
}

/* No options: the default accuracy; --accuracy 1e-4 and 1e-5. */
static void test_default_and_asked(void)
{
    acc_run d = solve_tent(0, 0.0), a = solve_tent(0, 1e-4), b = solve_tent(0, 1e-5);
    double ed = d.area / TENT_AREA - 1.0, ea = a.area / TENT_AREA - 1.0, eb = b.area / TENT_AREA - 1.0;
    printf("tent, no options: n %lu, %lu solves, true %.3e, estimate %.3e, %.3f s\n", (unsigned long)d.interior,
           (unsigned long)d.solves, ed, d.estimate, d.seconds);
    printf("tent, accuracy 1e-4: n %lu, true %.3e, estimate %.3e; 1e-5: n %lu, true %.3e, estimate %.3e, %.3f s\n",
           (unsigned long)a.interior, ea, a.estimate, (unsigned long)b.interior, eb, b.estimate, b.seconds);
    CHECK_EQ_INT(d.rc, PLATEAU_OK);
    CHECK_EQ_INT(d.defects, 0);
    CHECK(ed >= 0.0 && ed <= 5e-4);
    CHECK(d.estimate <= PLATEAU_DEFAULT_ACCURACY);
    CHECK_EQ_INT(a.rc, PLATEAU_OK);
    CHECK(a.estimate <= 1e-4);
    CHECK(ea >= 0.0 && ea <= 4e-4);
    CHECK_EQ_INT(b.rc, PLATEAU_OK);
    CHECK(b.estimate <= 1e-5);
    CHECK(eb >= 0.0 && eb <= 4e-5);
}

/* The default on a dense polygon not used to tune its first count (the
 * pilot of plateau__acc_pilot was tuned on the curve (cos t, sin t,
 * 0.3 cos 3t)): (1.2 cos t, sin t, 0.3 sin 2t + 0.1 cos 3t), m vertices,
 * with no options and with accuracy 1e-4, against the film at 1e-5
 * corrected by its own estimate (its error's order is 1 in 1 / n:
 * Richardson's step from the estimate).  The default meets the accuracy
 * in at most 2 solves and its true error is at most 5e-4 (4e-4 asked);
 * the run at 1e-5 meets it, and the plan's first count meets each
 * accuracy in one solve.  m = 400 (make test), also 2000 in the full
 * tier, and there a second polygon of neither's making: a non-symmetric
 * loop in millimetres, tilted and off the origin, of 600 vertices
 * (examples/NOTES.md sections 23 and 26). */
static void test_dense_default(void)
{
    static const size_t ms[3] = {400, 2000, 600};
    int t, k, tiers = HARNESS_FULL ? 3 : 1;
    for (t = 0; t < tiers; t++) {
        size_t m = ms[t], i;
        double *xyz = (double *)malloc(3 * m * sizeof(double)), ref = 0.0;
        acc_run r[3];
        if (!CHECK(xyz != NULL)) return;
        for (i = 0; i < m; i++) {
            double a = TWO_PI * (double)i / (double)m;
            if (t == 2) { /* millimetres: a lopsided loop, bent, tilted about y, moved */
                double rr = 1.0 + 0.2 * cos(2.0 * a + 0.7) + 0.08 * sin(3.0 * a);
                double x = 180.0 * rr * cos(a) + 40.0, y = 110.0 * rr * sin(a) - 15.0;
                double z = 35.0 * sin(a + 0.4) + 20.0 * cos(2.0 * a) * sin(a) + 12.0 * cos(5.0 * a);
                xyz[3 * i] = 0.9 * x - 0.3 * z + 1000.0, xyz[3 * i + 1] = y, xyz[3 * i + 2] = 0.3 * x + 0.9 * z + 250.0;
                continue;
            }
            xyz[3 * i] = 1.2 * cos(a), xyz[3 * i + 1] = sin(a), xyz[3 * i + 2] = 0.3 * sin(2.0 * a) + 0.1 * cos(3.0 * a);
        }
        for (k = 2; k >= 0; k--) {
            static const double accs[3] = {0.0, 1e-4, 1e-5};
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            clock_t c0 = clock();
            memset(&o, 0, sizeof o);
            o.accuracy = accs[k];
            o.stability = PLATEAU_OFF;
            r[k] = run_of(plateau_solve(xyz, m, &o, &mesh, &rep, NULL), c0, &rep);
            plateau_mesh_free(&mesh);
            if (k == 2) ref = r[2].area * (1.0 - r[2].estimate);
            r[k].err = r[k].area / ref - 1.0;
            printf("  dense polygon m %4lu, accuracy %s: n %6lu, %lu solve(s), true %.3e, estimate %.3e, %.3f s\n",
                   (unsigned long)m, k == 2 ? "1e-5" : k ? "1e-4" : "none given", (unsigned long)r[k].interior,
                   (unsigned long)r[k].solves, r[k].err, r[k].estimate, r[k].seconds);
            CHECK_EQ_INT(r[k].rc, PLATEAU_OK);
            CHECK_EQ_INT(r[k].defects, 0);
            CHECK(r[k].estimate <= (k == 2 ? 1e-5 : 1e-4));
        }
        CHECK(r[0].solves <= 2 && r[0].err >= 0.0 && r[0].err <= 5e-4);
        CHECK(r[1].err >= 0.0 && r[1].err <= 4e-4);
        CHECK(r[0].solves == 1 && r[1].solves == 1 && r[2].solves == 1);
        free(xyz);
    }
}

/* A tighter accuracy never gives a larger true error: the tent and the
 * catenoid at h = 0.9. */
static void test_monotone(void)
{
    static const double acc[4] = {1e-3, 3e-4, 1e-4, 3e-5}; /* the catenoid to 1e-4 (1.2 10^4 points) */
    double exact = ring_catenoid_area(0.9, 256), prev_t = 1.0, prev_c = 1.0;
    int i;
    printf("monotone accuracy:\n");
    for (i = 0; i < 4; i++) {
        acc_run t = solve_tent(0, acc[i]), c = i < 3 ? solve_rings(0.9, 256, 0, acc[i]) : t;
        double et = t.area / TENT_AREA - 1.0, ec = i < 3 ? c.area / exact - 1.0 : prev_c;
        printf("  accuracy %.0e: tent n %6lu true %.3e est %.3e", acc[i], (unsigned long)t.interior, et, t.estimate);
        if (i < 3) printf("; catenoid n %6lu true %.3e est %.3e", (unsigned long)c.interior, ec, c.estimate);
        printf("\n");
        CHECK(t.estimate <= acc[i] && c.estimate <= acc[i]);
        CHECK(et <= prev_t && ec <= prev_c);
        prev_t = et;
        prev_c = ec;
    }
}

/* The per-triangle indicator (plateau_mesh_error_indicator): its estimate
 * is the report's, bit for bit; the shares are never negative and sum to
 * it within 5 % (the steps' convergence); a flat film's shares are
 * rounding; bad arguments are refused. */
static void test_indicator(void)
{
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    double *ind, est = 0.0, sum = 0.0, flat[3 * 40], big = 0.0;
    size_t t;
    memset(&o, 0, sizeof o);
    o.interior_points = 1000;
    o.accuracy = -1.0;
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), PLATEAU_OK);
    ind = (double *)malloc(mesh.num_triangles * sizeof(double));
    if (!CHECK(ind != NULL)) return;
    CHECK_EQ_INT(plateau_mesh_error_indicator(&mesh, ind, &est, &err), PLATEAU_OK);
    CHECK(est == rep.area_error_estimate);
    for (t = 0; t < mesh.num_triangles; t++) {
        sum += ind[t];
        big = ind[t] < 0.0 ? 1.0 : big;
    }
    CHECK(big == 0.0);
    printf("tent n %lu: estimate %.4e, shares sum %.4e\n", (unsigned long)rep.interior_points, est, sum);
    CHECK(fabs(sum / est - 1.0) < 0.05);
    CHECK_EQ_INT(plateau_mesh_error_indicator(&mesh, NULL, &est, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_mesh_error_indicator(NULL, ind, &est, &err), PLATEAU_ERR_ARGUMENT);
    free(ind);
    plateau_mesh_free(&mesh);
    flat_disc(flat);
    memset(&o, 0, sizeof o);
    CHECK_EQ_INT(plateau_solve(flat, 40, &o, &mesh, &rep, NULL), PLATEAU_OK);
    ind = (double *)malloc(mesh.num_triangles * sizeof(double));
    if (!CHECK(ind != NULL)) return;
    CHECK_EQ_INT(plateau_mesh_error_indicator(&mesh, ind, NULL, &err), PLATEAU_OK);
    big = 0.0;
    for (t = 0; t < mesh.num_triangles; t++) big = fabs(ind[t]) > big ? fabs(ind[t]) : big;
    CHECK(big < 1e-12);
    free(ind);
    plateau_mesh_free(&mesh);
}

/* A membrane's estimate is formed, and no accuracy is aimed at unless
 * asked (the time limit's NaN: tests/test_time_budget.c); NaN accuracy
 * is refused. */
static void test_not_formed(void)
{
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    volatile double zero = 0.0;
    memset(&o, 0, sizeof o);
    o.pressure = 0.1;
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.estimate, PLATEAU_ESTIMATE_FORMED);
    CHECK(rep.area_error_estimate > 0.0 && rep.area_error_estimate < 0.1);
    CHECK(rep.accuracy == 0.0);
    CHECK_EQ_INT(rep.accuracy_solves, 1);
    plateau_mesh_free(&mesh);
    CHECK(strcmp(plateau_estimate_string(PLATEAU_ESTIMATE_MEMBRANE), "formed") != 0);
    memset(&o, 0, sizeof o);
    o.accuracy = zero / zero; /* NaN */
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "accuracy") != NULL);
    /* the paper's fan cannot meet an accuracy: refused before solving */
    o.accuracy = 1e-4;
    o.seeding = PLATEAU_SEEDING_PAPER;
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "seeding PAPER") != NULL);
    CHECK(mesh.positions == NULL);
    CHECK(strcmp(plateau_estimate_string((plateau_estimate)99), "unknown estimate status") == 0);
}

/* Why the accuracy's solves stopped (report.accuracy_stop): met by the
 * default; the memory bound between the first solve and the finer one it
 * needs; none aimed at with -n; every reason has its own sentence. */
static void test_accuracy_stop(void)
{
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    int s, t;
    memset(&o, 0, sizeof o);
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.accuracy_stop, PLATEAU_ACCURACY_MET);
    plateau_mesh_free(&mesh);
    /* 1e-7 needs far more than 16 times the first solve's points; a memory
     * bound that admits the first (200 points, edges split to match) and
     * not 16 times as many ends the solves there, with the reason */
    o.accuracy = 1e-7;
    o.max_memory = (size_t)plateau_memory_estimate(PLATEAU_METHOD_PAPER, 4, 1000);
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), PLATEAU_OK);
    printf("tent, accuracy 1e-7 under a %lu-byte bound: %lu solve(s), n %lu, estimate %.2e: %s\n",
           (unsigned long)o.max_memory, (unsigned long)rep.accuracy_solves, (unsigned long)rep.interior_points,
           rep.area_error_estimate, plateau_accuracy_stop_string(rep.accuracy_stop));
    CHECK_EQ_INT(rep.accuracy_stop, PLATEAU_ACCURACY_MEMORY);
    CHECK(rep.area_error_estimate > 1e-7);
    plateau_mesh_free(&mesh);
    memset(&o, 0, sizeof o);
    o.interior_points = 300;
    CHECK_EQ_INT(plateau_solve(TENT, 4, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.accuracy_stop, PLATEAU_ACCURACY_NOT_ASKED);
    plateau_mesh_free(&mesh);
    for (s = 0; s < PLATEAU_ACCURACY_STOP_COUNT; s++)
        for (t = 0; t < s; t++)
            CHECK(strcmp(plateau_accuracy_stop_string((plateau_accuracy_stop)s),
                         plateau_accuracy_stop_string((plateau_accuracy_stop)t)) != 0);
    CHECK(strcmp(plateau_accuracy_stop_string((plateau_accuracy_stop)99), "unknown accuracy stop") == 0);
}

int main(void)
{
    RUN(test_effectivity_tent);
    RUN(test_effectivity_catenoid);
    RUN(test_effectivity_membranes);
    RUN(test_membrane_minimize);
    RUN(test_membrane_accuracy);
    RUN(test_flat_disc);
    RUN(test_default_and_asked);
    RUN(test_dense_default);
    RUN(test_monotone);
    RUN(test_indicator);
    RUN(test_not_formed);
    RUN(test_accuracy_stop);
    return harness_report("test_accuracy");
}
