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
        /* planes spaced evenly in the arc across them: the fewest strips
         * of width 0.5 on the half circle of length pi */
        CHECK_EQ_INT(p.num_panels, (size_t)ceil(PI / 0.5));
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

/* Gores of a cap of polar angle 60 degrees, k = 6 .. 96 planes through
 * its axis, the mesh refined with the gores (4 sectors across a gore, k / 2
 * rings): the largest and the mean strain fall at order 2 in the gore
 * width.  The order measured between k and 2k approaches 2 from below as
 * 2 - O(1 / k) (a gore is not slender at k = 6: its width at the rim is
 * 0.9 of its length, and the strain of a panel is set by its smaller
 * extent only once it is thin), so the check is on the last pair and on
 * the extrapolation 2 p_k - p_(k/2) of the orders. */
static void test_cap_gores(void)
{
    double prev = 0.0, prev_mean = 0.0, order = 0.0, om = 0.0, last = 0.0, last_m = 0.0;
    size_t k;
    for (k = 6; k <= 96; k *= 2) {
        film f = cap_film(PI / 3, k / 2, 4 * k);
        plateau_pattern p;
        plateau_error err;
        plateau_pattern_options o = opts(100.0, PLATEAU_SEAMS_AXIS, 0, 0, 1);
        plateau_result r;
        o.panels = k;
        r = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
        film_free(&f);
        CHECK_EQ_INT(r, PLATEAU_OK);
        if (r != PLATEAU_OK) return;
        CHECK_EQ_INT(p.num_panels, k);
        CHECK_EQ_INT(p.num_seams, k);
        printf("cap gores: k %2lu, max strain %.4e, mean %.4e", (unsigned long)k, p.max_strain, p.mean_strain);
        if (prev > 0.0) {
            last = order;
            last_m = om;
            order = log(prev / p.max_strain) / log(2.0);
            om = log(prev_mean / p.mean_strain) / log(2.0);
            printf(", orders %.3f, %.3f", order, om);
            CHECK(order > last && om > last_m); /* rising towards 2 */
        }
        printf("\n");
        prev = p.max_strain;
        prev_mean = p.mean_strain;
        plateau_pattern_free(&p);
    }
    printf("cap gores: extrapolated orders %.3f, %.3f\n", 2.0 * order - last, 2.0 * om - last_m);
    CHECK_NEAR(order, 2.0, 0.15);
    CHECK_NEAR(om, 2.0, 0.15);
    CHECK_NEAR(2.0 * order - last, 2.0, 0.05);
    CHECK_NEAR(2.0 * om - last_m, 2.0, 0.05);
}

/* The outline edges of a pattern: the panel edges no other triangle of the
 * panel shares, counted directly. */
static size_t outline_edges(const plateau_pattern *p)
{
    size_t n = 0, t, u;
    int k, l;
    for (t = 0; t < p->num_triangles; t++)
        for (k = 0; k < 3; k++) {
            plateau_index a = p->triangles[3 * t + (size_t)k], b = p->triangles[3 * t + (size_t)(k + 1) % 3];
            int twin = 0;
            for (u = 0; u < p->num_triangles && !twin; u++)
                for (l = 0; l < 3; l++)
                    twin |= p->triangles[3 * u + (size_t)l] == b && p->triangles[3 * u + (size_t)(l + 1) % 3] == a;
            n += !twin;
        }
    return n;
}

static size_t count(const char *text, const char *what)
{
    size_t n = 0;
    const char *q = text;
    while ((q = strstr(q, what)) != NULL) {
        n++;
        q += strlen(what);
    }
    return n;
}

/* The DXF read back as group code / value pairs: every entity a LINE or
 * TEXT, the LINEs by layer, each coordinate within the roll's strips, the
 * TEXTs the panel numbers; ends with EOF. */
static void check_dxf(const char *text, const plateau_pattern *p, size_t marks)
{
    const char *q = text;
    char layer[32] = "", value[128];
    int code, in_entities = 0, eof = 0, kind = 0;
    size_t lines_outline = 0, lines_marks = 0, texts = 0, bad = 0, numbers = 0;
    double top = 1.1 * p->roll_width * (double)p->num_panels, len = 0.0;
    size_t i;
    unsigned long seen = 0;
    for (i = 0; i < p->num_panels; i++) len = p->panels[i].length > len ? p->panels[i].length : len;
    while (sscanf(q, "%d\n%127[^\n]\n", &code, value) == 2) {
        q = strchr(q, '\n') + 1;
        q = strchr(q, '\n') + 1;
        if (code == 0) {
            if (kind == 1 && strcmp(layer, "OUTLINE") == 0) lines_outline++;
            if (kind == 1 && strcmp(layer, "MARKS") == 0) lines_marks++;
            kind = strcmp(value, "LINE") == 0 ? 1 : strcmp(value, "TEXT") == 0 ? 2 : 0;
            texts += kind == 2;
            if (in_entities && kind == 0 && strcmp(value, "ENDSEC") != 0 && strcmp(value, "EOF") != 0) bad++;
            eof |= strcmp(value, "EOF") == 0;
        } else if (code == 2 && strcmp(value, "ENTITIES") == 0) {
            in_entities = 1;
        } else if (code == 8) {
            strcpy(layer, value);
        } else if (kind && (code == 10 || code == 11 || code == 20 || code == 21)) {
            double x = atof(value), lo = -0.1 * p->roll_width, hi = code < 20 ? len + 0.1 * p->roll_width : top;
            bad += !(x >= lo && x <= hi);
        } else if (kind == 2 && code == 1) {
            unsigned long n = strtoul(value, NULL, 10);
            numbers += n < p->num_panels && !(seen & (1ul << (n % 64)));
            seen |= 1ul << (n % 64);
        }
    }
    CHECK(eof);
    CHECK_EQ_INT(bad, 0);
    CHECK_EQ_INT(lines_outline, outline_edges(p));
    CHECK_EQ_INT(lines_marks, 2 * marks);
    CHECK_EQ_INT(texts, p->num_panels);
    CHECK_EQ_INT(numbers, p->num_panels);
}

/* Marks, SVG and DXF of the cylinder's pattern: the marks of a seam pair
 * up (the same film point on both sides, at the spacing along the seam),
 * and the files read back with every outline edge, mark and number. */
static void test_writers(void)
{
    film f = film_grid(cylinder, NULL, 10, 24, 0);
    plateau_pattern p;
    plateau_error err;
    plateau_pattern_options o = opts(0.8, PLATEAU_SEAMS_PARALLEL, 1, 0, 0);
    size_t s, n, total = 0, len, len2;
    double m[4 * 64];
    char *svg, *dxf, *svg2;
    FILE *fs;
    CHECK_EQ_INT(plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err), PLATEAU_OK);
    film_free(&f);
    for (s = 0; s < p.num_seams; s++) {
        size_t k;
        CHECK_EQ_INT(plateau_pattern_seam_marks(&p, s, 0.25, NULL, 0, &n, &err), PLATEAU_OK);
        CHECK_EQ_INT(n, 9); /* a straight seam of length 2: 0, 0.25, ..., 2 */
        CHECK_EQ_INT(plateau_pattern_seam_marks(&p, s, 0.25, m, 64, &n, &err), PLATEAU_OK);
        for (k = 1; k < n; k++) { /* on both sides a quarter apart */
            CHECK_NEAR(hypot(m[4 * k] - m[4 * k - 4], m[4 * k + 1] - m[4 * k - 3]), 0.25, 1e-9);
            CHECK_NEAR(hypot(m[4 * k + 2] - m[4 * k - 2], m[4 * k + 3] - m[4 * k - 1]), 0.25, 1e-9);
        }
        total += n;
    }
    CHECK_EQ_INT(plateau_pattern_seam_marks(&p, p.num_seams, 0.25, m, 64, &n, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_pattern_seam_marks(&p, 0, 0.0, m, 64, &n, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_pattern_seam_marks(&p, 0, 1e-9, m, 64, &n, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_pattern_write_svg("build/test_pattern.svg", &p, 1e-9, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "ten million marks") != NULL);
    CHECK_EQ_INT(plateau_pattern_write_dxf("build/test_pattern.dxf", &p, 0.25, &err), PLATEAU_OK);
    CHECK_EQ_INT(plateau_pattern_write_svg("build/test_pattern.svg", &p, 0.25, &err), PLATEAU_OK);
    dxf = harness_slurp("build/test_pattern.dxf", &len);
    svg = harness_slurp("build/test_pattern.svg", &len2);
    CHECK(dxf && svg);
    if (dxf) check_dxf(dxf, &p, total);
    if (svg) {
        CHECK_EQ_INT(count(svg, "<line class=\"outline\""), outline_edges(&p));
        CHECK_EQ_INT(count(svg, "<line class=\"marks\""), 2 * total);
        CHECK_EQ_INT(count(svg, "<text class=\"number\""), p.num_panels);
        CHECK(strstr(svg, "</svg>") != NULL);
    }
    fs = fopen("build/test_pattern2.svg", "wb");
    CHECK_EQ_INT(plateau_pattern_write_svg_stream(fs, &p, 0.25, &err), PLATEAU_OK);
    fclose(fs);
    svg2 = harness_slurp("build/test_pattern2.svg", &len);
    CHECK(svg2 && svg && len == len2 && memcmp(svg, svg2, len) == 0);
    CHECK_EQ_INT(plateau_pattern_write_dxf("build/no/such/dir/x.dxf", &p, 0.25, &err), PLATEAU_ERR_IO);
    CHECK_EQ_INT(plateau_pattern_write_svg(NULL, &p, 0.25, &err), PLATEAU_ERR_ARGUMENT);
    free(dxf);
    free(svg);
    free(svg2);
    remove("build/test_pattern.dxf");
    remove("build/test_pattern.svg");
    remove("build/test_pattern2.svg");
    plateau_pattern_free(&p);
    CHECK_EQ_INT(plateau_pattern_write_svg("build/test_pattern.svg", &p, 0.25, &err), PLATEAU_ERR_ARGUMENT);
}

/* Bad input: each refused with its code and a sentence, the pattern left
 * all zero. */
static void test_bad_input(void)
{
    static const double sq[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    static const plateau_index sqt[] = {0, 1, 2, 0, 2, 3};
    static const plateau_index bad_orient[] = {0, 1, 2, 0, 3, 2};
    film tube = film_grid(cone, NULL, 4, 16, 1);
    plateau_pattern p;
    plateau_error err;
    plateau_pattern_options o = opts(1.0, PLATEAU_SEAMS_PARALLEL, 0, 0, 0);
    o.width = 0.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "roll width") != NULL);
    CHECK(p.num_panels == 0 && p.panels == NULL);
    o.width = -1.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    o.width = NAN;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    o.width = 1.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 0, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "empty") != NULL);
    CHECK_EQ_INT(plateau_pattern_make(NULL, 0, NULL, 0, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, NULL, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, NULL, &err), PLATEAU_ERR_ARGUMENT);
    o.shrink_along = 0.5;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    o.shrink_along = 0.0;
    o.seams = 7;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    o.seams = PLATEAU_SEAMS_PARALLEL;
    o.direction[1] = INFINITY;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_ARGUMENT);
    o.direction[1] = 0.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, bad_orient, 2, &o, NULL, &p, &err), PLATEAU_ERR_ORIENTATION);
    /* a film wider than the roll across planes that cannot cut it: the
     * square lies in a plane normal to the planes' normal */
    o.direction[2] = 1.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_ERR_PATTERN);
    CHECK(strstr(err.message, "wider than the roll") != NULL);
    CHECK(p.num_panels == 0 && p.panels == NULL);
    /* it fits as one panel when the roll is wide enough: 2.0 across */
    o.width = 2.0 + 1e-12;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, sqt, 2, &o, NULL, &p, &err), PLATEAU_OK);
    CHECK_EQ_INT(p.num_panels, 1);
    CHECK_EQ_INT(p.num_seams, 0);
    plateau_pattern_free(&p);
    /* the cone cut by planes normal to its axis: bands, no discs */
    o.width = 10.0;
    o.panels = 2;
    CHECK_EQ_INT(plateau_pattern_make(tube.xyz, tube.nv, tube.tri, tube.nt, &o, NULL, &p, &err), PLATEAU_ERR_PATTERN);
    CHECK(strstr(err.message, "no disc") != NULL);
    /* a panel count whose panels do not fit */
    o = opts(0.1, PLATEAU_SEAMS_AXIS, 0, 0, 1);
    o.panels = 4;
    CHECK_EQ_INT(plateau_pattern_make(tube.xyz, tube.nv, tube.tri, tube.nt, &o, NULL, &p, &err), PLATEAU_ERR_PATTERN);
    CHECK(strstr(err.message, "number of panels asked") != NULL);
    film_free(&tube);
    CHECK(strcmp(plateau_result_string(PLATEAU_ERR_PATTERN), "unknown plateau result code") != 0);
}

int main(void)
{
    RUN(test_cylinder);
    RUN(test_cone);
    RUN(test_cap_gores);
    RUN(test_writers);
    RUN(test_bad_input);
    return harness_report("test_pattern");
}
