/* test_pattern.c - cutting patterns (plateau_pattern_make and its writers)
 * against exact answers: developable films (a cylinder patch cut between
 * its rulings by parallel planes, a cone cut into strips by planes through
 * its axis) flatten with strain at rounding level and seams whose two
 * sides are equal (or in the ratio the compensation asks); every panel
 * fits the roll; a spherical cap cut into gores has a strain falling at
 * second order in the gore width; the SVG and DXF read back; bad input
 * gets its error. */
#define _POSIX_C_SOURCE 200809L
#ifndef PLATEAU_TEST_LINKED /* else make test links tests/impl.c's object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"

#define PI 3.14159265358979323846

/* A grid film: (ns + 1) x (nt + 1) points f(s, t) (nt columns closed
 * round when closed: column nt is column 0), each quad two triangles. */
typedef struct film {
    double *xyz;
    plateau_index *tri;
    size_t nv, nt;
} film;

typedef void (*film_fn)(double s, double t, double *p, const double *par);

static void film_free(film *f)
{
    free(f->xyz);
    free(f->tri);
}

static film film_grid(film_fn fn, const double *par, size_t ns, size_t nt, int closed)
{
    film f;
    size_t cols = closed ? nt : nt + 1, i, j, k = 0;
    f.nv = (ns + 1) * cols;
    f.nt = 2 * ns * nt;
    f.xyz = (double *)malloc(3 * f.nv * sizeof(double));
    f.tri = (plateau_index *)malloc(3 * f.nt * sizeof(plateau_index));
    for (i = 0; i <= ns; i++)
        for (j = 0; j < cols; j++) fn((double)i / (double)ns, (double)j / (double)nt, f.xyz + 3 * (i * cols + j), par);
    for (i = 0; i < ns; i++)
        for (j = 0; j < nt; j++) {
            plateau_index a = (plateau_index)(i * cols + j), b = (plateau_index)(i * cols + (j + 1) % cols);
            plateau_index c = (plateau_index)((i + 1) * cols + (j + 1) % cols), d = (plateau_index)((i + 1) * cols + j);
            plateau_index t[6];
            t[0] = a; t[1] = b; t[2] = c; t[3] = a; t[4] = c; t[5] = d;
            memcpy(f.tri + 6 * k++, t, sizeof t);
        }
    return f;
}

/* half a cylinder of radius 1, height 2: t round, s up */
static void cylinder(double s, double t, double *p, const double *par)
{
    (void)par;
    p[0] = cos(PI * t);
    p[1] = sin(PI * t);
    p[2] = 2.0 * s;
}

/* a cone with apex at the origin, axis z, half-angle 30 degrees, rulings
 * from 0.5 to 2 */
static void cone(double s, double t, double *p, const double *par)
{
    double r = 0.5 + 1.5 * s;
    (void)par;
    p[0] = r * 0.5 * cos(2 * PI * t);
    p[1] = r * 0.5 * sin(2 * PI * t);
    p[2] = r * sqrt(0.75);
}

/* a unit sphere's cap of polar angle par[0] (s: the polar angle's
 * fraction; the pole row collapses onto one point, made by cap_film) */
static void cap(double s, double t, double *p, const double *par)
{
    double ph = par[0] * s;
    p[0] = sin(ph) * cos(2 * PI * t);
    p[1] = sin(ph) * sin(2 * PI * t);
    p[2] = cos(ph);
}

/* The cap as a fan round the pole and rings of quads. */
static film cap_film(double polar, size_t rings, size_t sectors)
{
    film g = film_grid(cap, &polar, rings, sectors, 1), f;
    size_t j, k = 0, i;
    f.nv = g.nv - sectors + 1;
    f.nt = g.nt - sectors;
    f.xyz = (double *)malloc(3 * f.nv * sizeof(double));
    f.tri = (plateau_index *)malloc(3 * f.nt * sizeof(plateau_index));
    f.xyz[0] = 0.0;
    f.xyz[1] = 0.0;
    f.xyz[2] = 1.0;
    memcpy(f.xyz + 3, g.xyz + 3 * sectors, 3 * (g.nv - sectors) * sizeof(double));
    for (i = 0; i < g.nt; i++) {
        plateau_index t[3];
        int c, zero = 0;
        for (c = 0; c < 3; c++) {
            plateau_index v = g.tri[3 * i + (size_t)c];
            t[c] = v < (plateau_index)sectors ? 0 : v - (plateau_index)sectors + 1;
            zero += t[c] == 0;
        }
        if (zero > 1) continue; /* the collapsed triangle of the pole's quad */
        memcpy(f.tri + 3 * k++, t, sizeof t);
    }
    (void)j;
    film_free(&g);
    f.nt = k;
    return f;
}

static plateau_pattern_options opts(double width, int seams, double dx, double dy, double dz)
{
    plateau_pattern_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.seams = seams;
    o.direction[0] = dx;
    o.direction[1] = dy;
    o.direction[2] = dz;
    return o;
}

/* The checks every pattern passes: panels fit, areas and counts add up,
 * every seam's two sides in the ratio asked (ratio 0: not checked). */
static void check_pattern(const plateau_pattern *p, double width, size_t film_triangles, double film_area,
                          double strain_tol, double ratio, double ratio_tol)
{
    size_t i, nt = 0;
    double a = 0.0;
    CHECK(p->num_panels >= 2);
    CHECK(p->num_seams >= 1);
    for (i = 0; i < p->num_panels; i++) {
        const plateau_pattern_panel *q = &p->panels[i];
        CHECK(q->width <= width);
        CHECK(q->width > 0.0 && q->length >= q->width);
        CHECK(q->max_strain <= strain_tol);
        CHECK(q->mean_strain <= q->max_strain);
        nt += q->num_triangles;
        a += q->area_3d;
    }
    CHECK(p->max_strain <= strain_tol);
    CHECK(nt >= film_triangles);
    CHECK_REL(a, film_area, 1e-12, 1.0);
    for (i = 0; i < p->num_seams && ratio > 0.0; i++) {
        const plateau_pattern_seam *s = &p->seams[i];
        CHECK(s->panels[0] < s->panels[1] && s->panels[1] < p->num_panels);
        CHECK_REL(s->lengths[0], s->lengths[1], ratio_tol, 0.0);
        CHECK_REL(s->lengths[0], ratio * s->length_3d, ratio_tol, 0.0);
    }
}

static double film_area(const film *f)
{
    double a = 0.0;
    size_t t;
    for (t = 0; t < f->nt; t++) {
        const double *p = f->xyz + 3 * (size_t)f->tri[3 * t], *q = f->xyz + 3 * (size_t)f->tri[3 * t + 1],
                     *r = f->xyz + 3 * (size_t)f->tri[3 * t + 2];
        double u[3], v[3], c[3];
        int k;
        for (k = 0; k < 3; k++) { u[k] = q[k] - p[k]; v[k] = r[k] - p[k]; }
        c[0] = u[1] * v[2] - u[2] * v[1];
        c[1] = u[2] * v[0] - u[0] * v[2];
        c[2] = u[0] * v[1] - u[1] * v[0];
        a += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    return a;
}

static void test_cylinder(void)
{
    film f = film_grid(cylinder, NULL, 10, 24, 0);
    plateau_pattern p;
    plateau_error err;
    plateau_pattern_options o = opts(0.5, PLATEAU_SEAMS_PARALLEL, 1, 0, 0);
    plateau_result r = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
    CHECK_EQ_INT(r, PLATEAU_OK);
    if (r == PLATEAU_OK) {
        printf("cylinder: %lu panels, %lu seams, max strain %.3g, spacing %.4g\n", (unsigned long)p.num_panels,
               (unsigned long)p.num_seams, p.max_strain, p.spacing);
        check_pattern(&p, 0.5, f.nt, film_area(&f), 1e-9, 1.0, 1e-9);
    }
    plateau_pattern_free(&p);
    /* with compensation: 2 % along the panel (the rulings, the seams), 1 % across */
    o.shrink_along = 0.02;
    o.shrink_across = 0.01;
    r = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
    CHECK_EQ_INT(r, PLATEAU_OK);
    if (r == PLATEAU_OK) check_pattern(&p, 0.5, f.nt, film_area(&f), 1e-9, 0.98, 1e-9);
    plateau_pattern_free(&p);
    film_free(&f);
}

static void test_cone(void)
{
    film f = film_grid(cone, NULL, 12, 40, 1);
    plateau_pattern p;
    plateau_error err;
    plateau_pattern_options o = opts(0.4, PLATEAU_SEAMS_AXIS, 0, 0, 1);
    plateau_result r = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
    CHECK_EQ_INT(r, PLATEAU_OK);
    if (r == PLATEAU_OK) {
        printf("cone: %lu panels, %lu seams, max strain %.3g\n", (unsigned long)p.num_panels,
               (unsigned long)p.num_seams, p.max_strain);
        check_pattern(&p, 0.4, f.nt, film_area(&f), 1e-9, 1.0, 1e-9);
        /* closed round the axis: as many seams as panels */
        CHECK_EQ_INT(p.num_seams, p.num_panels);
    } else {
        printf("%s\n", err.message);
    }
    plateau_pattern_free(&p);
    film_free(&f);
}

/* Gores of a cap of polar angle 60 degrees, k = 6, 12, 24: the largest
 * strain falls as (gore width)^2, order within 2 +- 0.2. */
static void test_cap_gores(void)
{
    film f = cap_film(PI / 3, 48, 192);
    double prev = 0.0, prev_mean = 0.0;
    size_t k;
    for (k = 6; k <= 24; k *= 2) {
        plateau_pattern p;
        plateau_error err;
        plateau_pattern_options o = opts(100.0, PLATEAU_SEAMS_AXIS, 0, 0, 1);
        plateau_result r;
        o.panels = k;
        r = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
        CHECK_EQ_INT(r, PLATEAU_OK);
        if (r != PLATEAU_OK) {
            printf("%s\n", err.message);
            continue;
        }
        CHECK_EQ_INT(p.num_panels, k);
        printf("cap gores: k %lu, max strain %.4g, mean %.4g", (unsigned long)k, p.max_strain, p.mean_strain);
        if (prev > 0.0) {
            double order = log(prev / p.max_strain) / log(2.0), om = log(prev_mean / p.mean_strain) / log(2.0);
            printf(", order %.3f (mean %.3f)", order, om);
            CHECK_NEAR(order, 2.0, 0.2);
            CHECK_NEAR(om, 2.0, 0.2);
        }
        printf("\n");
        prev = p.max_strain;
        prev_mean = p.mean_strain;
        plateau_pattern_free(&p);
    }
    film_free(&f);
}

int main(void)
{
    RUN(test_cylinder);
    RUN(test_cone);
    RUN(test_cap_gores);
    return harness_report("test_pattern");
}
