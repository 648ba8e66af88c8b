/* test_membrane.c - membranes (options.pressure, fix_volume, cable_tension):
 * the spherical cap on the unit circle and the cable-edged flat square
 * against their exact solutions, their convergence under refinement, the
 * membrane energy's gradient against central differences, and the named
 * errors and defects of bad values. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "tests/harness.h"

#define PI 3.141592653589793

/* The cap of a sphere of radius R = 2 / p on the unit circle (unit
 * tension: k1 + k2 = p): height, area 2 pi R h, volume pi h^2 (3R - h) / 3. */
static void cap_exact(double p, double *h, double *area, double *vol)
{
    double R = 2.0 / p;
    *h = R - sqrt(R * R - 1.0);
    *area = 2.0 * PI * R * *h;
    *vol = PI * *h * *h * (3.0 * R - *h) / 3.0;
}

/* The unit circle in the plane z = 0 as m vertices, vertex i at angle
 * 2 pi i / m. */
static void unit_circle(double *xyz, int m)
{
    int i;
    for (i = 0; i < m; i++) {
        double t = 2.0 * PI * i / m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.0;
    }
}

/* The flat square (+-1, +-1, 0) with cables of tension T: each an arc of
 * radius T over the chord 2, half-angle a = asin(1 / T): sag T (1 - cos a),
 * length 2 T a, film area 4 minus four circular segments T^2 (a - sin a cos a). */
static void square_exact(double T, double *sag, double *len, double *area)
{
    double a = asin(1.0 / T);
    *sag = T * (1.0 - cos(a));
    *len = 2.0 * T * a;
    *area = 4.0 - 4.0 * T * T * (a - sin(a) * cos(a));
}

/* The unit circle as m vertices, meshed at its own spacing (edge length
 * 2 sin(pi / m) inside too: uniform refinement when m doubles). */
typedef struct cap_run {
    double area, vol, height, pressure;
    unsigned defects;
    plateau_result rc;
} cap_run;

static cap_run solve_cap(int m, plateau_method method, double p, int fix, double v0)
{
    double *xyz = (double *)malloc(3 * sizeof(double) * (size_t)m);
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    cap_run r;
    size_t v;
    unit_circle(xyz, m);
    memset(&o, 0, sizeof o);
    o.method = method;
    o.quality_edge_length = 2.0 * sin(PI / m);
    o.interior_points = (size_t)(PI / (0.866 * o.quality_edge_length * o.quality_edge_length));
    o.pressure = p;
    o.fix_volume = fix;
    o.volume = v0;
    r.rc = plateau_solve(xyz, (size_t)m, &o, &mesh, &rep, &err);
    r.area = rep.area;
    r.vol = rep.volume;
    r.pressure = rep.pressure;
    r.defects = rep.defects;
    r.height = 0.0;
    for (v = 0; v < mesh.num_vertices; v++)
        if (mesh.positions[3 * v + 2] > r.height) r.height = mesh.positions[3 * v + 2];
    if (r.rc != PLATEAU_OK) fprintf(stderr, "  cap m %d: %s\n", m, err.message);
    plateau_mesh_free(&mesh);
    free(xyz);
    return r;
}

static double order(double e0, double e1) { return log(fabs(e0) / fabs(e1)) / log(2.0); }

/* p = 1: R = 2, h = 2 - sqrt 3.  Method area (least area - p V) and method
 * paper (H_i = p) within 0.5 % at m = 96; method area's errors fall at
 * second order from m = 24 to 96. */
static void test_cap_pressure(void)
{
    double h, a, v;
    cap_run r[3], q;
    int k;
    cap_exact(1.0, &h, &a, &v);
    CHECK_NEAR(h, 0.267949192, 1e-9);
    CHECK_NEAR(a, 3.367148858, 1e-9);
    CHECK_NEAR(v, 0.430966541, 1e-9);
    for (k = 0; k < 3; k++) r[k] = solve_cap(24 << k, PLATEAU_METHOD_AREA, 1.0, 0, 0.0);
    for (k = 0; k < 3; k++) {
        CHECK_EQ_INT(r[k].rc, PLATEAU_OK);
        CHECK_EQ_INT((long)r[k].defects, 0);
        CHECK_NEAR(r[k].pressure, 1.0, 1e-15);
    }
    CHECK_NEAR(r[2].area / a, 1.0, 5e-3);
    CHECK_NEAR(r[2].vol / v, 1.0, 5e-3);
    CHECK_NEAR(r[2].height / h, 1.0, 5e-3);
    printf("  cap p = 1, method area, m = 24/48/96: area %.9f %.9f %.9f, volume %.9f %.9f %.9f, "
           "height %.9f %.9f %.9f\n", r[0].area, r[1].area, r[2].area, r[0].vol, r[1].vol, r[2].vol,
           r[0].height, r[1].height, r[2].height);
    printf("  orders: area %.2f %.2f, volume %.2f %.2f\n", order(r[0].area - a, r[1].area - a),
           order(r[1].area - a, r[2].area - a), order(r[0].vol - v, r[1].vol - v), order(r[1].vol - v, r[2].vol - v));
    CHECK(order(r[0].area - a, r[1].area - a) > 1.7 && order(r[1].area - a, r[2].area - a) > 1.7);
    CHECK(order(r[0].vol - v, r[1].vol - v) > 1.7 && order(r[1].vol - v, r[2].vol - v) > 1.7);
    q = solve_cap(96, PLATEAU_METHOD_PAPER, 1.0, 0, 0.0);
    CHECK_EQ_INT(q.rc, PLATEAU_OK);
    CHECK_EQ_INT((long)q.defects, 0);
    CHECK_NEAR(q.area / a, 1.0, 5e-3);
    CHECK_NEAR(q.vol / v, 1.0, 5e-3);
    CHECK_NEAR(q.height / h, 1.0, 5e-3);
    printf("  cap p = 1, method paper, m = 96: area %.9f volume %.9f height %.9f\n", q.area, q.vol, q.height);
    /* the sign: p < 0 bulges against the normals, the mirror image */
    q = solve_cap(48, PLATEAU_METHOD_AREA, -1.0, 0, 0.0);
    CHECK_NEAR(q.vol, -r[1].vol, 1e-6);
}

/* A pressure no film carries, so large that the solver's Newton system
 * would overflow at the flat start and the film would not move at all
 * (from about |p| R = 1e154 that came back as a valid flat film): above
 * |p| R = 1e100 it is PLATEAU_ERR_PRESSURE, in any units; at 1e99 the
 * film runs away and is NO_EQUILIBRIUM. */
static void test_pressure_too_large(void)
{
    static const double p[4] = {1e101, -1e300, 1e160, 1e99};
    static const double scale[4] = {1.0, 1.0, 1e-50, 1.0};
    double xyz[3 * 12];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    int k, i;
    for (k = 0; k < 4; k++) {
        plateau_result rc;
        unit_circle(xyz, 12);
        for (i = 0; i < 36; i++) xyz[i] *= scale[k];
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_AREA;
        o.pressure = p[k];
        memset(&mesh, 0, sizeof mesh);
        rc = plateau_solve(xyz, 12, &o, &mesh, &rep, &err);
        if (k < 3) {
            CHECK_EQ_INT(rc, PLATEAU_ERR_PRESSURE);
            CHECK(strstr(err.message, "1e100") != NULL);
        } else {
            CHECK_EQ_INT(rc, PLATEAU_OK);
            CHECK((rep.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM) != 0);
        }
        plateau_mesh_free(&mesh);
    }
    /* the same p R as a refused one is taken at another scale: 1e160 on a
     * polygon of radius 1e-70 is p R = 1e90 */
    unit_circle(xyz, 12);
    for (i = 0; i < 36; i++) xyz[i] *= 1e-70;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.pressure = 1e160;
    CHECK_EQ_INT(plateau_solve(xyz, 12, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK((rep.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM) != 0);
    plateau_mesh_free(&mesh);
}

/* V = 0.430966541 held: the same cap, the multiplier reported is the
 * pressure 1 (within 0.5 % at m = 96, converging at second order). */
static void test_cap_volume(void)
{
    double h, a, v;
    cap_run r[3], q;
    int k;
    cap_exact(1.0, &h, &a, &v);
    for (k = 0; k < 3; k++) r[k] = solve_cap(24 << k, PLATEAU_METHOD_AREA, 0.0, 1, v);
    for (k = 0; k < 3; k++) {
        CHECK_EQ_INT(r[k].rc, PLATEAU_OK);
        CHECK_EQ_INT((long)r[k].defects, 0);
        CHECK_NEAR(r[k].vol / v, 1.0, 1e-6);
    }
    CHECK_NEAR(r[2].pressure, 1.0, 5e-3);
    CHECK_NEAR(r[2].area / a, 1.0, 5e-3);
    printf("  volume held, method area, m = 24/48/96: pressure %.9f %.9f %.9f (orders %.2f %.2f)\n",
           r[0].pressure, r[1].pressure, r[2].pressure, order(r[0].pressure - 1.0, r[1].pressure - 1.0),
           order(r[1].pressure - 1.0, r[2].pressure - 1.0));
    CHECK(order(r[0].pressure - 1.0, r[1].pressure - 1.0) > 1.5 && order(r[1].pressure - 1.0, r[2].pressure - 1.0) > 1.5);
    {
        /* the default density (n = 300 on 48 vertices: the Newton path),
         * where the Newton method's own stop left V 1.3e-5 short and the
         * multiplier's solves ran out */
        double circle[3 * 48];
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        unit_circle(circle, 48);
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_AREA;
        o.interior_points = 300;
        o.fix_volume = 1;
        o.volume = 0.4;
        CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)rep.defects, 0);
        CHECK_NEAR(rep.volume, 0.4, 1e-6);
        plateau_mesh_free(&mesh);
    }
    q = solve_cap(96, PLATEAU_METHOD_PAPER, 0.0, 1, v);
    CHECK_EQ_INT(q.rc, PLATEAU_OK);
    CHECK_EQ_INT((long)q.defects, 0);
    CHECK_NEAR(q.pressure, 1.0, 5e-3);
    printf("  volume held, method paper, m = 96: pressure %.9f\n", q.pressure);
}

typedef struct square_run {
    double area, len[4], sag[4];
    size_t cables;
    unsigned defects;
    plateau_result rc;
} square_run;

static square_run solve_square(double T, size_t n, plateau_method method)
{
    double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, ts[4];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    square_run r;
    int k;
    for (k = 0; k < 4; k++) ts[k] = T;
    memset(&o, 0, sizeof o);
    memset(&r, 0, sizeof r);
    o.method = method;
    o.interior_points = n;
    o.cable_tension = ts;
    r.rc = plateau_solve(sq, 4, &o, &mesh, &rep, &err);
    if (r.rc != PLATEAU_OK) fprintf(stderr, "  square: %s\n", err.message);
    r.area = rep.area;
    r.cables = rep.cables;
    r.defects = rep.defects;
    for (k = 0; k < 4 && k < (int)rep.cables; k++) {
        r.len[k] = rep.cable[k].length;
        r.sag[k] = rep.cable[k].sag;
    }
    /* the anchors stay bit for bit */
    if (r.rc == PLATEAU_OK)
        for (k = 0; k < 4; k++)
            CHECK(memcmp(mesh.positions + 3 * rep.cable[k].anchor, sq + 3 * k, 3 * sizeof(double)) == 0);
    plateau_mesh_free(&mesh);
    return r;
}

/* Cables of tension 2 and 1.5 on the flat square: arcs of radius T; each
 * cable's sag and length and the film's area within 0.5 % at n = 800,
 * and at second order from n = 200 to 3200 (T = 2). */
static void test_square_cables(void)
{
    static const double tensions[2] = {2.0, 1.5};
    int i, k;
    for (i = 0; i < 2; i++) {
        double sag, len, area;
        square_run r = solve_square(tensions[i], 800, PLATEAU_METHOD_AREA);
        square_exact(tensions[i], &sag, &len, &area);
        CHECK_EQ_INT(r.rc, PLATEAU_OK);
        CHECK_EQ_INT((long)r.defects, 0);
        CHECK_EQ_INT((long)r.cables, 4);
        CHECK_NEAR(r.area / area, 1.0, 5e-3);
        for (k = 0; k < 4; k++) {
            CHECK_NEAR(r.len[k] / len, 1.0, 5e-3);
            CHECK_NEAR(r.sag[k] / sag, 1.0, 5e-3);
        }
        printf("  square T = %g, n = 800: area %.9f (exact %.9f), length %.9f (%.9f), sag %.9f (%.9f)\n",
               tensions[i], r.area, area, r.len[0], len, r.sag[0], sag);
    }
    {
        double sag, len, area;
        square_run r[3];
        square_exact(2.0, &sag, &len, &area);
        CHECK_NEAR(sag, 0.267949192, 1e-9);
        CHECK_NEAR(len, 2.094395102, 1e-9);
        CHECK_NEAR(area, 2.550622821, 1e-9);
        square_exact(1.5, &sag, &len, &area);
        CHECK_NEAR(sag, 0.381966011, 1e-9);
        CHECK_NEAR(len, 2.189182969, 1e-9);
        CHECK_NEAR(area, 1.904587049, 1e-9);
        square_exact(2.0, &sag, &len, &area);
        for (k = 0; k < 3; k++) r[k] = solve_square(2.0, (size_t)200 << (2 * k), PLATEAU_METHOD_AREA);
        printf("  square T = 2, n = 200/800/3200: area %.9f %.9f %.9f (orders %.2f %.2f), sag %.9f %.9f %.9f "
               "(orders %.2f %.2f)\n", r[0].area, r[1].area, r[2].area, order(r[0].area - area, r[1].area - area),
               order(r[1].area - area, r[2].area - area), r[0].sag[0], r[1].sag[0], r[2].sag[0],
               order(r[0].sag[0] - sag, r[1].sag[0] - sag), order(r[1].sag[0] - sag, r[2].sag[0] - sag));
        CHECK(order(r[0].area - area, r[2].area - area) > 2.0 * 1.6);
        CHECK(order(r[0].sag[0] - sag, r[2].sag[0] - sag) > 2.0 * 1.6);
    }
    {
        /* method paper: the area presolve places the cables, LM solves H_i = 0 */
        double sag, len, area;
        square_run r = solve_square(2.0, 800, PLATEAU_METHOD_PAPER);
        square_exact(2.0, &sag, &len, &area);
        CHECK_EQ_INT(r.rc, PLATEAU_OK);
        CHECK_NEAR(r.sag[0] / sag, 1.0, 5e-3);
        CHECK_NEAR(r.area / area, 1.0, 5e-3);
    }
}

/* plateau_membrane_energy's gradient against central differences on a
 * bumpy mesh with a pressure and two cable segments. */
static void test_energy_gradient(void)
{
    double pos[3 * 7], g[3 * 7], apex[3] = {0.1, -0.2, -0.3}, tens[2] = {1.7, 0.6};
    plateau_index tri[3 * 6], seg[4] = {1, 2, 2, 3};
    unsigned char fixed[7] = {0, 0, 0, 0, 0, 0, 0};
    plateau_mesh mesh;
    plateau_error err;
    int i, k;
    pos[0] = 0.05; pos[1] = -0.03; pos[2] = 0.4;
    for (i = 0; i < 6; i++) {
        double t = 2.0 * PI * i / 6 + 0.1 * i * i;
        pos[3 * (i + 1)] = cos(t);
        pos[3 * (i + 1) + 1] = sin(t) * (1.0 + 0.1 * i);
        pos[3 * (i + 1) + 2] = 0.2 * cos(3.0 * t) + 0.05 * i;
        tri[3 * i] = 0;
        tri[3 * i + 1] = (plateau_index)(i + 1);
        tri[3 * i + 2] = (plateau_index)((i + 1) % 6 + 1);
    }
    CHECK_EQ_INT(plateau_mesh_create(pos, 7, fixed, tri, 6, NULL, &mesh, &err), PLATEAU_OK);
    plateau_membrane_energy(&mesh, 1.3, apex, seg, tens, 2, g);
    for (i = 0; i < 7; i++)
        for (k = 0; k < 3; k++) {
            double x = mesh.positions[3 * i + k], h = 1e-6, ep, em;
            mesh.positions[3 * i + k] = x + h;
            ep = plateau_membrane_energy(&mesh, 1.3, apex, seg, tens, 2, NULL);
            mesh.positions[3 * i + k] = x - h;
            em = plateau_membrane_energy(&mesh, 1.3, apex, seg, tens, 2, NULL);
            mesh.positions[3 * i + k] = x;
            CHECK_NEAR(g[3 * i + k], (ep - em) / (2.0 * h), 1e-8);
        }
    /* the volume: a closed tetrahedron's, whatever the apex */
    plateau_mesh_free(&mesh);
    {
        double tp[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, a2[3] = {3.0, -1.0, 2.0};
        plateau_index tt[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        unsigned char fx[4] = {1, 1, 1, 1};
        CHECK_EQ_INT(plateau_mesh_create(tp, 4, fx, tt, 4, NULL, &mesh, &err), PLATEAU_OK);
        CHECK_NEAR(plateau_mesh_volume(&mesh, NULL, NULL), 1.0 / 6.0, 1e-15);
        CHECK_NEAR(plateau_mesh_volume(&mesh, a2, NULL), 1.0 / 6.0, 1e-14);
        plateau_mesh_free(&mesh);
    }
}

/* Bad values: named errors before any work, or an honest defect. */
static void test_bad_values(void)
{
    double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, ts[4] = {2, 2, 2, 2};
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    cap_run r;
    memset(&o, 0, sizeof o);
    o.cable_tension = ts;
    ts[2] = -1.0;
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_CABLE);
    CHECK_EQ_INT(err.index, 2);
    plateau_mesh_free(&mesh);
    ts[2] = 0.999; /* half the chord 2 is 1 */
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_CABLE);
    CHECK(strstr(err.message, "half its chord") != NULL);
    plateau_mesh_free(&mesh);
    ts[2] = 1.0; /* a half circle: allowed */
    ts[0] = ts[1] = ts[3] = 0.0;
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)rep.cables, 1);
    plateau_mesh_free(&mesh);
    memset(&o, 0, sizeof o);
    o.pressure = NAN;
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_PRESSURE);
    plateau_mesh_free(&mesh);
    o.pressure = 1.0;
    o.method = PLATEAU_METHOD_PAPER_LITERAL;
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_PRESSURE);
    plateau_mesh_free(&mesh);
    /* p = 3 > 2 on the unit circle: no cap spans it; the film runs away */
    r = solve_cap(24, PLATEAU_METHOD_AREA, 3.0, 0, 0.0);
    CHECK_EQ_INT(r.rc, PLATEAU_OK);
    CHECK(r.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM);
    /* a volume beyond the hemisphere's needs p > 2 on the way: not reached */
    r = solve_cap(24, PLATEAU_METHOD_AREA, 0.0, 1, 3.0 * PI);
    CHECK_EQ_INT(r.rc, PLATEAU_OK);
    CHECK(r.defects & (PLATEAU_DEFECT_VOLUME | PLATEAU_DEFECT_NO_EQUILIBRIUM));
    printf("  volume 3 pi on the unit circle: defects %u, volume reached %.6f, pressure %.6f\n", r.defects,
           r.vol, r.pressure);
}


/* Two cables facing each other across the 2 x 1 rectangle (+-1, +-0.5, 0),
 * rigid short sides.  T = 1.3: each an arc of radius 1.3 over the chord 2,
 * sag 1.3 (1 - cos asin(1 / 1.3)) = 0.469; they stay 0.06 apart, and the
 * film is in equilibrium.  T = 1.05: the arcs would sag 0.72 each and
 * cross; the film pinches between them, the solver stops there with the
 * cables out of balance, and the result must say so (NO_EQUILIBRIUM), for
 * both methods, never "converged". */
static void test_cables_pinch(void)
{
    static const double rect[12] = {-1, -0.5, 0, 1, -0.5, 0, 1, 0.5, 0, -1, 0.5, 0};
    plateau_method me;
    for (me = PLATEAU_METHOD_PAPER; me <= PLATEAU_METHOD_AREA; me = (plateau_method)(me + 1)) {
        int k;
        for (k = 0; k < 2; k++) {
            double T = k == 0 ? 1.3 : 1.05, ten[4], sag = T * (1.0 - cos(asin(1.0 / T)));
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            plateau_error err;
            if (me == PLATEAU_METHOD_PAPER_LITERAL) continue;
            ten[0] = ten[2] = T;
            ten[1] = ten[3] = 0.0;
            memset(&o, 0, sizeof o);
            o.method = me;
            o.interior_points = 600;
            o.cable_tension = ten;
            if (!CHECK_EQ_INT(plateau_solve(rect, 4, &o, &mesh, &rep, &err), PLATEAU_OK)) continue;
            CHECK_EQ_INT((long)rep.cables, 2);
            if (k == 0) {
                CHECK_EQ_INT(rep.defects, 0);
                CHECK_EQ_INT(rep.stop, PLATEAU_STOP_CONVERGED);
                CHECK_REL(rep.cable[0].sag, sag, 0.005, 0.0);
                CHECK_REL(rep.cable[1].sag, sag, 0.005, 0.0);
            } else {
                CHECK(rep.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM);
                CHECK(rep.stop != PLATEAU_STOP_CONVERGED);
                CHECK(rep.cable[0].sag + rep.cable[1].sag <= 1.0); /* pinched, not crossed */
            }
            printf("  rectangle, cables T = %.2f, %s: sags %.6f %.6f (arc %.6f), defects %u\n", T,
                   plateau_method_name(me), rep.cable[0].sag, rep.cable[1].sag, sag, rep.defects);
            plateau_mesh_free(&mesh);
        }
    }
}

/* The "cable T" syntax: its own parsing step, which blanks the two fields
 * so that plateau_parse_boundary reads the vertex lines as before. */
static void test_parse_cables(void)
{
    char text[] = "# a sail\n-1 -1 0 cable 2\n\n1 -1 0   cable 1.5e0 # south\n1 1 0\r\n-1 1 0 cable 3\n";
    char bad[] = "0 0 0 cable\n1 0 0\n0 1 0\n";
    char none[] = "0 0 0\n1 0 0\n0 1 0\n";
    double *t = NULL, *xyz = NULL;
    size_t n = 0, m = 0;
    plateau_error err;
    CHECK_EQ_INT(plateau_parse_cables(text, strlen(text), NULL, &t, &n, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)n, 4);
    if (t && n == 4) {
        CHECK(t[0] == 2.0 && t[1] == 1.5 && t[2] == 0.0 && t[3] == 3.0);
    }
    CHECK(strstr(text, "cable") == NULL);
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), NULL, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)m, 4);
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_free(t, NULL);
    CHECK_EQ_INT(plateau_parse_cables(bad, strlen(bad), NULL, &t, &n, &err), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(err.index, 1);
    CHECK(t == NULL);
    CHECK_EQ_INT(plateau_parse_cables(none, strlen(none), NULL, &t, &n, &err), PLATEAU_OK);
    CHECK(t == NULL);
}

/* The cables matched to the vertices plateau_parse_boundary_lines keeps:
 * two loops, each closed by a repeat of its first vertex; "cable T" on
 * the line before a closing point makes the closing edge a cable, and on
 * the closing point itself it is refused by its line. */
static void test_cables_align(void)
{
    char text[] = "0 0 0 cable 1\n1 0 0\n0 1 0 cable 2\n0 0 0\n\n5 0 0\n6 0 0 cable 3\n5 1 0\n5 0 0\n";
    char bad[] = "0 0 0\n1 0 0\n0 1 0\n0 0 0 cable 2\n";
    double *t = NULL, *xyz = NULL;
    size_t n = 0, m = 0;
    plateau_boundary_lines info;
    plateau_error err;
    memset(&info, 0, sizeof info);
    info.split_loops = 1;
    CHECK_EQ_INT(plateau_parse_cables(text, strlen(text), NULL, &t, &n, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)n, 8);
    CHECK_EQ_INT(plateau_parse_boundary_lines(text, strlen(text), NULL, &xyz, &m, &info, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)m, 6);
    CHECK_EQ_INT((long)info.closing_dropped, 2);
    if (t && n == 8 && m == 6) {
        size_t c = n - 1; /* a count of another text */
        CHECK_EQ_INT(plateau_cables_align(t, &c, &info, &err), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_cables_align(t, &n, &info, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)n, 6);
        CHECK(t[0] == 1.0 && t[1] == 0.0 && t[2] == 2.0 && t[3] == 0.0 && t[4] == 3.0 && t[5] == 0.0);
    }
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_free(t, NULL);
    plateau_boundary_lines_free(&info, NULL);
    info.split_loops = 1;
    CHECK_EQ_INT(plateau_parse_cables(bad, strlen(bad), NULL, &t, &n, &err), PLATEAU_OK);
    CHECK_EQ_INT(plateau_parse_boundary_lines(bad, strlen(bad), NULL, &xyz, &m, &info, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)m, 3);
    CHECK_EQ_INT(plateau_cables_align(t, &n, &info, &err), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(err.index, 4);
    CHECK(strstr(err.message, "line 4: a cable on a closing point") != NULL);
    CHECK_EQ_INT((long)n, 4); /* nothing moved */
    CHECK_EQ_INT(plateau_cables_align(NULL, &n, &info, &err), PLATEAU_ERR_ARGUMENT);
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_free(t, NULL);
    plateau_boundary_lines_free(&info, NULL);
}

/* A held volume whose secant step overshoots into a film that breaks
 * down: the cushion of examples/cable_membranes.c (square frame of 48
 * vertices, method paper, n = 400) at p = 1.5, then by its volume.  The
 * first step (the flat disc's dV/dp) asks for p = 1.88 in the caller's
 * units, where method paper's film folds; that solve is undone and the
 * pressure comes back as 1.5. */
static void test_volume_overshoot(void)
{
    double frame[3 * 48];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    double v;
    int i;
    for (i = 0; i < 48; i++) {
        double t = -1.0 + (i % 12) / 6.0;
        int side = i / 12;
        frame[3 * i] = side == 0 ? t : side == 1 ? 1.0 : side == 2 ? -t : -1.0;
        frame[3 * i + 1] = side == 0 ? -1.0 : side == 1 ? t : side == 2 ? 1.0 : -t;
        frame[3 * i + 2] = 0.0;
    }
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_PAPER;
    o.interior_points = 400;
    o.pressure = 1.5;
    CHECK_EQ_INT(plateau_solve(frame, 48, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)rep.defects, 0);
    v = rep.volume;
    plateau_mesh_free(&mesh);
    o.pressure = 0.0;
    o.fix_volume = 1;
    o.volume = v;
    CHECK_EQ_INT(plateau_solve(frame, 48, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK_EQ_INT((long)rep.defects, 0);
    CHECK_NEAR(rep.pressure, 1.5, 1e-3);
    CHECK_NEAR(rep.volume, v, 1e-6);
    printf("  cushion p = 1.5: volume %.9f; held: pressure %.9f, volume %.9f\n", v, rep.pressure, rep.volume);
    plateau_mesh_free(&mesh);
}

/* What is of the area alone is off for a membrane: AUTO resolves to OFF
 * (plateau_resolved_options), asking for it is PLATEAU_ERR_ARGUMENT
 * naming it, and the cap of p = 1 at 1200 interior points, where a plain
 * film takes coarse to fine and gets its stability report, takes the
 * rounds and has neither, and is the cap. */
static void test_area_alone(void)
{
    double circle[3 * 48], h, a, vol, ts[48];
    plateau_options o, r;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    int i;
    unit_circle(circle, 48);
    for (i = 0; i < 48; i++) ts[i] = i == 0 ? 1.0 : 0.0;
    memset(&o, 0, sizeof o);
    r = plateau_resolved_options(&o, 48);
    CHECK(r.coarse_to_fine == PLATEAU_AUTO && r.stability == PLATEAU_AUTO && r.alternatives == PLATEAU_AUTO);
    o.pressure = 1.0;
    r = plateau_resolved_options(&o, 48);
    CHECK(r.coarse_to_fine == PLATEAU_OFF && r.stability == PLATEAU_OFF && r.alternatives == PLATEAU_OFF);
    o.pressure = 0.0;
    o.cable_tension = ts;
    r = plateau_resolved_options(&o, 48);
    CHECK(r.coarse_to_fine == PLATEAU_OFF && r.stability == PLATEAU_OFF && r.alternatives == PLATEAU_OFF);
    o.cable_tension = NULL;
    o.fix_volume = 1;
    o.stability = PLATEAU_ON; /* ON stays ON, and is refused below */
    r = plateau_resolved_options(&o, 48);
    CHECK(r.coarse_to_fine == PLATEAU_OFF && r.stability == PLATEAU_ON && r.alternatives == PLATEAU_OFF);
    /* asked for explicitly: refused, naming what was asked */
    CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "stability ON") != NULL && strstr(err.message, "membrane") != NULL);
    plateau_mesh_free(&mesh);
    memset(&o, 0, sizeof o);
    o.pressure = 1.0;
    o.coarse_to_fine = PLATEAU_ON;
    CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "coarse_to_fine ON") != NULL && strstr(err.message, "membrane") != NULL);
    plateau_mesh_free(&mesh);
    o.coarse_to_fine = PLATEAU_AUTO;
    o.critical_index = 1;
    CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    o.critical_index = 0;
    o.least_area_topology = 1;
    CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    o.least_area_topology = 0;
    o.pressure = 0.0;
    o.cable_tension = ts;
    o.alternatives = PLATEAU_ON;
    CHECK_EQ_INT(plateau_solve(circle, 48, &o, &mesh, &rep, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    /* AUTO at 1200 interior points on a 16-gon (edges long enough for the
     * refinement rule): the plain film takes coarse to fine and has its
     * stability report; the membrane neither, and is bit for bit the
     * membrane with coarse_to_fine and stability OFF */
    unit_circle(circle, 16);
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 1200;
    CHECK_EQ_INT(plateau_solve(circle, 16, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK(rep.levels > 0 && rep.stability.computed == 1 && rep.membrane == 0);
    plateau_mesh_free(&mesh);
    o.pressure = 1.0;
    CHECK_EQ_INT(plateau_solve(circle, 16, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK(rep.levels == 0 && rep.stability.computed == 0 && rep.membrane == 1);
    CHECK_EQ_INT((long)rep.defects, 0);
    a = rep.area;
    vol = rep.volume;
    plateau_mesh_free(&mesh);
    o.coarse_to_fine = PLATEAU_OFF;
    o.stability = PLATEAU_OFF;
    CHECK_EQ_INT(plateau_solve(circle, 16, &o, &mesh, &rep, &err), PLATEAU_OK);
    CHECK(rep.area == a && rep.volume == vol);
    /* a cap of p = 1 over the 16-gon: between the caps over its inscribed
     * circle (radius cos(pi / 16)) and its circumscribed one (radius 1) */
    cap_exact(1.0, &h, &a, &vol);
    CHECK(rep.volume < vol && rep.area < a);
    printf("  cap p = 1 over the 16-gon, n = 1200, AUTO: levels %lu, area %.9f, volume %.9f\n",
           (unsigned long)rep.levels, rep.area, rep.volume);
    plateau_mesh_free(&mesh);
}

/* Pressure with several loops (two coaxial rings: the film bulges, V
 * follows the sign of p) and with method paper on the annulus (its area
 * presolve, then H_i = p). */
static void test_combinations(void)
{
    double xyz[3 * 64];
    size_t counts[2] = {32, 32};
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    double v[2] = {0.0, 0.0};
    int i, s;
    for (i = 0; i < 64; i++) {
        double t = 2.0 * PI * (i % 32) / 32;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = i < 32 ? -0.4 : 0.4;
    }
    for (s = 0; s < 2; s++) {
        memset(&o, 0, sizeof o);
        o.method = s ? PLATEAU_METHOD_PAPER : PLATEAU_METHOD_AREA;
        o.interior_points = 300;
        o.pressure = 0.5;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)rep.defects, 0);
        CHECK_NEAR(rep.pressure, 0.5, 1e-15);
        /* of the area alone, so not for a membrane: the stability report, the discs */
        CHECK(rep.membrane == 1 && rep.stability.computed == 0 && rep.alternative_area == 0.0);
        v[s] = rep.volume;
        plateau_mesh_free(&mesh);
    }
    /* both methods give the same film to the discretisation's accuracy */
    CHECK(v[0] != 0.0 && fabs(v[0] - v[1]) < 0.02 * fabs(v[0]));
    o.pressure = -0.5;
    o.method = PLATEAU_METHOD_AREA;
    CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &err), PLATEAU_OK);
    /* V is the cone volume from the centroid over the film, which the
     * catenoid (p = 0) already has: -p bulges the other way */
    CHECK_EQ_INT((long)rep.defects, 0);
    CHECK(rep.volume < v[0]);
    printf("  two rings at distance 0.8: V(p = 0.5) area %.6f paper %.6f, V(p = -0.5) %.6f\n", v[0], v[1],
           rep.volume);
    plateau_mesh_free(&mesh);
    {
        /* cables on two loops, each on the edge that closes its loop (from
         * its last vertex back to its first): the anchors found across the
         * wrap, the loops' own vertices fixed and bit for bit */
        double ts[64];
        size_t c, v, f = 0;
        for (i = 0; i < 64; i++) ts[i] = 0.0;
        ts[31] = ts[63] = 0.5;
        memset(&o, 0, sizeof o);
        o.method = PLATEAU_METHOD_AREA;
        o.interior_points = 400;
        o.cable_tension = ts;
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)rep.defects, 0);
        CHECK_EQ_INT((long)rep.cables, 2);
        for (c = 0; c < rep.cables && c < 2; c++) {
            double chord = 2.0 * sin(PI / 32);
            CHECK(rep.cable[c].vertices >= 1);
            CHECK(rep.cable[c].length > chord && rep.cable[c].sag > 0.0);
            /* an arc of radius at least T through the anchors: sag at most T (1 - cos a) */
            CHECK(rep.cable[c].sag <= 0.5 * (1.0 - cos(asin(chord / 1.0))) + 1e-9);
        }
        for (v = 0; v < mesh.num_vertices && f < 64; v++)
            if (mesh.fixed[v]) {
                CHECK(memcmp(mesh.positions + 3 * v, xyz + 3 * f, 3 * sizeof(double)) == 0);
                f++;
            }
        CHECK_EQ_INT((long)f, 64);
        plateau_mesh_free(&mesh);
    }
    {
        /* plateau_mesh_minimize takes a pressure too (apex: the centroid of
         * the fixed vertices), but no cables */
        double circle[3 * 48], h, a, vol, ts[48];
        plateau_mesh flat;
        plateau_report r2;
        unit_circle(circle, 48);
        for (i = 0; i < 48; i++) ts[i] = 0.0;
        memset(&o, 0, sizeof o);
        o.quality_edge_length = 2.0 * sin(PI / 48);
        o.interior_points = 300;
        CHECK_EQ_INT(plateau_solve(circle, 48, &o, &flat, &r2, &err), PLATEAU_OK);
        o.method = PLATEAU_METHOD_AREA;
        o.pressure = 1.0;
        CHECK_EQ_INT(plateau_mesh_minimize(&flat, &o, &r2, &err), PLATEAU_OK);
        cap_exact(1.0, &h, &a, &vol);
        CHECK_EQ_INT((long)r2.defects, 0);
        CHECK_NEAR(r2.volume / vol, 1.0, 0.02);
        CHECK_NEAR(r2.pressure, 1.0, 1e-15);
        CHECK(r2.membrane == 1 && r2.stability.computed == 0);
        o.cable_tension = ts;
        CHECK_EQ_INT(plateau_mesh_minimize(&flat, &o, &r2, &err), PLATEAU_ERR_CABLE);
        plateau_mesh_free(&flat);
    }
}

/* A first guess of the multiplier above every pressure the boundary can
 * carry (p = 2.5 > 2 on the unit circle: no cap spans it) still reaches
 * the held volume: the same film as from p = 0, the cap of p = 1. */
static void test_volume_first_guess(void)
{
    double h, a, v;
    cap_run r0, r1;
    cap_exact(1.0, &h, &a, &v);
    r0 = solve_cap(48, PLATEAU_METHOD_AREA, 0.0, 1, v);
    r1 = solve_cap(48, PLATEAU_METHOD_AREA, 2.5, 1, v);
    CHECK_EQ_INT(r1.rc, PLATEAU_OK);
    CHECK_EQ_INT((long)r1.defects, 0);
    CHECK_NEAR(r1.vol / v, 1.0, 1e-6);
    CHECK_NEAR(r1.pressure, r0.pressure, 1e-4);
    CHECK_NEAR(r1.pressure, 1.0, 2e-2);
    printf("  volume held from p = 2.5: pressure %.9f (from p = 0: %.9f), defects %u\n", r1.pressure,
           r0.pressure, r1.defects);
}

/* The cable-edged square in units of 1e100, 1e-100, 1e150 and 1e-150
 * (tensions in the same units: T = 2): the film of units 1 scaled, its
 * area, cable lengths and sags to 1e-6 (areas of 1e300 and 1e-300 are
 * finite, and the vertex count per cable follows the polygon, not the
 * units). */
static void test_cables_units(void)
{
    static const double scales[4] = {1e100, 1e-100, 1e150, 1e-150};
    double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, ts[4];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report ref, rep;
    plateau_error err;
    long nv;
    int i, k;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 100;
    o.cable_tension = ts;
    for (k = 0; k < 4; k++) ts[k] = 2.0;
    CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &ref, &err), PLATEAU_OK);
    nv = (long)mesh.num_vertices;
    plateau_mesh_free(&mesh);
    for (i = 0; i < 4; i++) {
        double s = scales[i], xyz[12];
        for (k = 0; k < 12; k++) xyz[k] = sq[k] * s;
        for (k = 0; k < 4; k++) ts[k] = 2.0 * s;
        CHECK_EQ_INT(plateau_solve(xyz, 4, &o, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)rep.defects, 0);
        CHECK_EQ_INT((long)rep.cables, 4);
        CHECK_EQ_INT((long)mesh.num_vertices, nv);
        CHECK_NEAR(rep.area / s / s / ref.area, 1.0, 1e-6);
        for (k = 0; k < 4 && k < (int)rep.cables; k++) {
            CHECK_NEAR(rep.cable[k].length / s / ref.cable[k].length, 1.0, 1e-6);
            CHECK_NEAR(rep.cable[k].sag / s / ref.cable[k].sag, 1.0, 1e-6);
        }
        printf("  square in units of %g: area %.9f, sag %.9f (units 1: %.9f, %.9f)\n", s, rep.area / s / s,
               rep.cable[0].sag / s, ref.area, ref.cable[0].sag);
        plateau_mesh_free(&mesh);
    }
}

/* Cables far stiffer than the film (T = 1e200 and 1e300 on the square of
 * side 2, whose T^2 overflows): the straight square, area 4, sag 0, and
 * not an error about the polygon's coordinates. */
static void test_cables_stiff(void)
{
    static const double tensions[2] = {1e200, 1e300};
    int i, k;
    for (i = 0; i < 2; i++) {
        square_run r = solve_square(tensions[i], 100, PLATEAU_METHOD_AREA);
        CHECK_EQ_INT(r.rc, PLATEAU_OK);
        CHECK_EQ_INT((long)r.cables, 4);
        CHECK_NEAR(r.area, 4.0, 1e-9);
        for (k = 0; k < 4; k++) {
            CHECK_NEAR(r.len[k], 2.0, 1e-9);
            CHECK_NEAR(r.sag[k], 0.0, 1e-9);
        }
    }
}

/* A volume beyond a double's range is given as the area is: a circle of
 * radius 1e120 at pressure 1e-150 (the unit circle's film at 1e-30,
 * scaled by 1e120) has V = V_1 1e360: report.volume is HUGE_VAL with
 * PLATEAU_RANGE_VOLUME_OVERFLOW, volume_significand * 2^volume_exponent
 * is V_1 1e360 to 1e-6, and the mesh is valid (it printed "volume -nan",
 * valid, before). */
static void test_volume_beyond_double(void)
{
    const size_t m = 48;
    double xyz[3 * 48], big[3 * 48], l2, want;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report r1, rb;
    size_t i;
    for (i = 0; i < m; i++) {
        double t = 2.0 * PI * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.0;
        big[3 * i] = 1e120 * xyz[3 * i];
        big[3 * i + 1] = 1e120 * xyz[3 * i + 1];
        big[3 * i + 2] = 0.0;
    }
    memset(&o, 0, sizeof o);
    o.pressure = 1e-30;
    CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &r1, NULL), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    CHECK(r1.volume > 0.0 && r1.range == 0);
    CHECK_REL(ldexp(r1.volume_significand, r1.volume_exponent), r1.volume, 1e-15, 0.0);
    o.pressure = 1e-150;
    CHECK_EQ_INT(plateau_solve(big, m, &o, &mesh, &rb, NULL), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(rb.defects, 0);
    CHECK(rb.range & PLATEAU_RANGE_VOLUME_OVERFLOW);
    CHECK(rb.volume == HUGE_VAL);
    CHECK(rb.volume_significand >= 0.5 && rb.volume_significand < 1.0);
    l2 = log2(rb.volume_significand) + rb.volume_exponent;
    want = log2(r1.volume) + 360.0 * log2(10.0);
    CHECK_REL(l2, want, 1e-9, 0.0);
    printf("  volume at radius 1e120, pressure 1e-150: %.10g x 2^%d (unit circle at 1e-30: %.10g)\n",
           rb.volume_significand, rb.volume_exponent, r1.volume);
}

/* A pressure above what any film on the boundary carries (the unit
 * circle of 48 vertices: |p| |A| <= L allows p up to 2 / cos(pi / 48),
 * about 2.004) is PLATEAU_DEFECT_NO_EQUILIBRIUM under method paper too,
 * whose H_i = p stalls short of a root instead of running away (it gave
 * UNSOLVED alone); method area still says so; p = 1.5 is a valid cap, in
 * both orientations, and a circle of radius 1e-3 carries p = 1500 but not
 * 2500 (scale-free). */
static void test_pressure_without_film(void)
{
    static const double ps[3] = {2.5, -2.5, 1.5};
    static const int meths[2] = {PLATEAU_METHOD_PAPER, PLATEAU_METHOD_AREA};
    double xyz[3 * 48];
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    int k, j;
    size_t i;
    for (j = 0; j < 2; j++)
        for (k = 0; k < 3; k++) {
            unit_circle(xyz, 48);
            memset(&o, 0, sizeof o);
            o.method = (plateau_method)meths[j];
            o.pressure = ps[k];
            CHECK_EQ_INT(plateau_solve(xyz, 48, &o, &mesh, &rep, NULL), PLATEAU_OK);
            if (k < 2) {
                if (!CHECK((rep.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM) != 0))
                    fprintf(stderr, "  method %d, pressure %g: defects %#x\n", meths[j], ps[k], rep.defects);
            } else {
                CHECK_EQ_INT(rep.defects, 0);
            }
            plateau_mesh_free(&mesh);
        }
    unit_circle(xyz, 48);
    for (i = 0; i < 3 * 48; i++) xyz[i] *= 1e-3;
    memset(&o, 0, sizeof o);
    o.pressure = 1500.0;
    CHECK_EQ_INT(plateau_solve(xyz, 48, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK_EQ_INT(rep.defects, 0);
    plateau_mesh_free(&mesh);
    o.pressure = 2500.0;
    CHECK_EQ_INT(plateau_solve(xyz, 48, &o, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK((rep.defects & PLATEAU_DEFECT_NO_EQUILIBRIUM) != 0);
    plateau_mesh_free(&mesh);
}

/* The corner condition: cables whose arcs (radius T, leaving a corner at
 * asin(c / 2 T) from the chord c) would cross at a corner are
 * PLATEAU_ERR_CABLE naming the corner at every n, before any solve: the
 * unit equilateral triangle needs T > 1 (its 60 degree corners), the
 * square of side 2 T >= sqrt 2 (its right angles).  Tensions that meet
 * the condition give valid films at every n. */
static void test_cables_corner(void)
{
    static const double tri[9] = {0, 0, 0, 1, 0, 0, 0.5, 0.8660254037844386, 0};
    static const double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    static const double bad_sq[2] = {1.01, 1.3}, good_sq[2] = {1.4142135623730951, 1.5};
    static const size_t ns[3] = {0, 200, 1000};
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    double ts[4];
    int i, k, j, nn = HARNESS_FULL ? 3 : 2;
    for (j = 0; j < nn; j++) {
        memset(&o, 0, sizeof o);
        o.interior_points = ns[j];
        o.cable_tension = ts;
        for (k = 0; k < 3; k++) ts[k] = 0.6;
        CHECK_EQ_INT(plateau_solve(tri, 3, &o, &mesh, &rep, &err), PLATEAU_ERR_CABLE);
        CHECK(strstr(err.message, "corner") != NULL);
        CHECK(err.index >= 0 && err.index < 3);
        plateau_mesh_free(&mesh);
        for (k = 0; k < 3; k++) ts[k] = 1.05;
        CHECK_EQ_INT(plateau_solve(tri, 3, &o, &mesh, &rep, &err), PLATEAU_OK);
        CHECK_EQ_INT((long)rep.defects, 0);
        plateau_mesh_free(&mesh);
        for (i = 0; i < 2; i++) {
            for (k = 0; k < 4; k++) ts[k] = bad_sq[i];
            CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_ERR_CABLE);
            CHECK(strstr(err.message, "corner") != NULL);
            plateau_mesh_free(&mesh);
            for (k = 0; k < 4; k++) ts[k] = good_sq[i];
            CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_OK);
            CHECK_EQ_INT((long)rep.defects, 0);
            CHECK_EQ_INT((long)rep.inverted_triangles, 0);
            plateau_mesh_free(&mesh);
        }
        /* one weak cable between rigid edges: asin(1 / 1.05) = 72 degrees
         * against the right angle: allowed */
        ts[0] = ts[1] = ts[3] = 0.0;
        ts[2] = 1.05;
        CHECK_EQ_INT(plateau_solve(sq, 4, &o, &mesh, &rep, &err), PLATEAU_OK);
        plateau_mesh_free(&mesh);
    }
}

/* Similar copies of a membrane give the same film: the square with cables
 * T = 1.5 at pressure 0.3 against its copies scaled by 1e-3 and 3.7
 * (pressure over the scale, tension times it): the same triangles, the
 * area over the scale squared within 1e-9 (INVARIANCE; the frame's
 * pressure and tensions are rounded as its coordinates are). */
static void test_membrane_similarity(void)
{
    static const double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, scales[2] = {1e-3, 3.7};
    static const size_t ns[3] = {0, 100, 400};
    static const plateau_method methods[2] = {PLATEAU_METHOD_PAPER, PLATEAU_METHOD_AREA};
    int j, mi, nn = HARNESS_FULL ? 3 : 2;
    for (mi = 0; mi < 2; mi++)
        for (j = 0; j < nn; j++) {
            plateau_method me = methods[mi];
            double ts[4], xyz[12];
            plateau_options o;
            plateau_mesh ref, mesh;
            plateau_report rr, rep;
            plateau_error err;
            int i, k;
            memset(&o, 0, sizeof o);
            o.method = me;
            o.interior_points = ns[j];
            o.cable_tension = ts;
            o.pressure = 0.3;
            for (k = 0; k < 4; k++) ts[k] = 1.5;
            CHECK_EQ_INT(plateau_solve(sq, 4, &o, &ref, &rr, &err), PLATEAU_OK);
            for (i = 0; i < 2; i++) {
                double s = scales[i];
                for (k = 0; k < 12; k++) xyz[k] = sq[k] * s;
                for (k = 0; k < 4; k++) ts[k] = 1.5 * s;
                o.pressure = 0.3 / s;
                CHECK_EQ_INT(plateau_solve(xyz, 4, &o, &mesh, &rep, &err), PLATEAU_OK);
                CHECK_EQ_INT((long)mesh.num_triangles, (long)ref.num_triangles);
                CHECK(mesh.num_triangles == ref.num_triangles &&
                      memcmp(mesh.triangles, ref.triangles, 3 * ref.num_triangles * sizeof(plateau_index)) == 0);
                CHECK_NEAR(rep.area / (s * s) / rr.area, 1.0, 1e-9);
                CHECK_NEAR(rep.volume / (s * s * s) / rr.volume, 1.0, 1e-9);
                CHECK_EQ_INT((long)rep.defects, (long)rr.defects);
                printf("  method %d, n %lu, scale %g: relative area difference %.2e\n", (int)me,
                       (unsigned long)ns[j], s, fabs(rep.area / (s * s) / rr.area - 1.0));
                plateau_mesh_free(&mesh);
            }
            plateau_mesh_free(&ref);
        }
}

/* Nearly rigid cables on a saddle (cli/samples/sail-hypar.txt: corners
 * (+-1, +-1) at heights +-0.5 in turn, four cables of T = 3): a valid
 * mesh at every n, never one called valid with an inverted or
 * intersecting triangle (the final check counts both on the film
 * returned).  make test: n = 200 and 1000 by method paper; the full tier
 * also 2000 and method area. */
static void test_cables_stiff_saddle(void)
{
    static const double sail[12] = {-1, -1, 0.5, 1, -1, -0.5, 1, 1, 0.5, -1, 1, -0.5};
    static const size_t ns[3] = {200, 1000, 2000};
    static const plateau_method methods[2] = {PLATEAU_METHOD_PAPER, PLATEAU_METHOD_AREA};
    int j, mi, k;
    for (mi = 0; mi < (HARNESS_FULL ? 2 : 1); mi++)
        for (j = 0; j < (HARNESS_FULL ? 3 : 2); j++) {
            double ts[4];
            plateau_options o;
            plateau_mesh mesh;
            plateau_report rep;
            plateau_quality q;
            plateau_error err;
            for (k = 0; k < 4; k++) ts[k] = 3.0;
            memset(&o, 0, sizeof o);
            o.method = methods[mi];
            o.interior_points = ns[j];
            o.cable_tension = ts;
            if (CHECK_EQ_INT(plateau_solve(sail, 4, &o, &mesh, &rep, &err), PLATEAU_OK)) {
                plateau_mesh_quality(&mesh, &q);
                CHECK_EQ_INT((long)rep.defects, 0);
                CHECK_EQ_INT((long)q.inverted_triangles, 0);
                CHECK_EQ_INT((long)rep.intersecting_pairs, 0);
                CHECK_EQ_INT((long)rep.cables, 4);
                printf("  sail-hypar, T = 3, method %d, n %lu: defects %u, smallest angle %.2f deg\n", (int)o.method,
                       (unsigned long)ns[j], rep.defects, rep.min_angle_deg);
            }
            plateau_mesh_free(&mesh);
        }
}

int main(void)
{
    RUN(test_energy_gradient);
    RUN(test_bad_values);
    RUN(test_parse_cables);
    RUN(test_cables_align);
    RUN(test_area_alone);
    RUN(test_volume_overshoot);
    RUN(test_volume_first_guess);
    RUN(test_cables_units);
    RUN(test_cables_stiff);
    RUN(test_combinations);
    RUN(test_cap_pressure);
    RUN(test_pressure_too_large);
    RUN(test_cap_volume);
    RUN(test_square_cables);
    RUN(test_cables_pinch);
    RUN(test_volume_beyond_double);
    RUN(test_pressure_without_film);
    RUN(test_cables_corner);
    RUN(test_membrane_similarity);
    RUN(test_cables_stiff_saddle);
    return harness_report("test_membrane");
}
