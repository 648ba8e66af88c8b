/* test_io_svg.c - the colour map (luminance rises with the value, no
 * channel clipped) and the coloured SVG writer: the fill of a known triangle
 * and of a known vertex's cells, the legend's numbers, the marked edges,
 * the stream and file forms agreeing byte for byte, and every bad argument
 * refused with its code before anything is written. */
#define _POSIX_C_SOURCE 200809L /* getpid, mkdir, rmdir: a directory of our own */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"

#include <sys/stat.h>
#include <unistd.h>

static char tmp_dir[256];

static const char *tmp_path(const char *name)
{
    static char path[512];
    sprintf(path, "%s/%s", tmp_dir, name);
    return path;
}

/* "#rrggbb" of plateau_colormap(t), rounded as the writer documents. */
static void expect_hex(double t, char hex[8])
{
    double rgb[3];
    plateau_colormap(t, rgb);
    sprintf(hex, "#%02x%02x%02x", (int)(rgb[0] * 255.0 + 0.5), (int)(rgb[1] * 255.0 + 0.5),
            (int)(rgb[2] * 255.0 + 0.5));
}

/* The value of data-value="..." in the element whose class is cls, and the
 * text the element shows; 0 when absent. */
static int legend_value(const char *svg, const char *cls, double *value, char *shown, size_t cap)
{
    char key[96];
    const char *p, *q;
    size_t k = 0;
    sprintf(key, "class=\"%s\" data-value=\"", cls);
    p = strstr(svg, key);
    if (!p) return 0;
    *value = strtod(p + strlen(key), NULL);
    q = strchr(p, '>');
    if (!q) return 0;
    for (q++; *q && *q != '<' && k + 1 < cap; q++) shown[k++] = *q;
    shown[k] = '\0';
    return 1;
}

/* Counts non-overlapping occurrences of needle. */
static size_t count_of(const char *s, const char *needle)
{
    size_t n = 0, len = strlen(needle);
    while ((s = strstr(s, needle)) != NULL) {
        n++;
        s += len;
    }
    return n;
}

/* The fill of the k-th <polygon (0-based), into hex (8 bytes); 0 if none. */
static int polygon_fill(const char *svg, size_t k, char hex[8])
{
    const char *p = svg, *f;
    size_t i;
    for (i = 0; i <= k; i++) {
        p = strstr(p, "<polygon");
        if (!p) return 0;
        p += 8;
    }
    f = strstr(p, "fill=\"");
    if (!f) return 0;
    memcpy(hex, f + 6, 7);
    hex[7] = '\0';
    return 1;
}

static void test_colormap(void)
{
    double prev = -1.0, rgb[3], lum, worst = 0.0;
    int i, monotone = 1, inside = 1;
    for (i = 0; i <= 1000; i++) {
        double t = i / 1000.0;
        plateau_colormap(t, rgb);
        lum = 0.30 * rgb[0] + 0.59 * rgb[1] + 0.11 * rgb[2];
        if (fabs(lum - (0.15 + 0.75 * t)) > worst) worst = fabs(lum - (0.15 + 0.75 * t));
        if (!(lum > prev)) monotone = 0;
        if (rgb[0] < 0 || rgb[0] > 1 || rgb[1] < 0 || rgb[1] > 1 || rgb[2] < 0 || rgb[2] > 1)
            inside = 0;
        prev = lum;
    }
    CHECK(monotone);
    CHECK(inside);
    CHECK_NEAR(worst, 0.0, 1e-5); /* luminance is the grey level 0.15 + 0.75 t */
    /* the 8-bit colours the writer uses keep the order too, in steps of 1/64 */
    prev = -1.0;
    monotone = 1;
    for (i = 0; i <= 64; i++) {
        char hex[8];
        unsigned r, g, b;
        expect_hex(i / 64.0, hex);
        sscanf(hex + 1, "%2x%2x%2x", &r, &g, &b);
        lum = 0.30 * r + 0.59 * g + 0.11 * b;
        if (!(lum > prev)) monotone = 0;
        prev = lum;
    }
    CHECK(monotone);
    /* clamped ends; NaN as 0 */
    {
        double a[3], b[3];
        plateau_colormap(-3.0, a);
        plateau_colormap(0.0, b);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
        plateau_colormap(NAN, a);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
        plateau_colormap(7.0, a);
        plateau_colormap(1.0, b);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
        /* dark blue at 0, pale at 1 */
        plateau_colormap(0.0, a);
        CHECK(a[2] > a[0] && a[2] > a[1]);
        plateau_colormap(1.0, a);
        CHECK(a[0] > 0.8 && a[1] > 0.9 && a[2] > 0.9);
    }
}

static const double tri_pos[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
static const plateau_index tri_one[3] = { 0, 1, 2 };

static void test_triangle_color(void)
{
    plateau_svg_colors c;
    plateau_error err;
    double value = 3.0, lo = 0, hi = 0;
    char *svg, hex[8], want[8], shown[64];
    size_t len;
    memset(&c, 0, sizeof c);
    c.values = &value;
    c.num_values = 1;
    c.range_min = 1.0;
    c.range_max = 5.0;
    c.title = "|H| <& \"x\"";
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("t.svg"), tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_OK);
    CHECK_EQ_INT(err.code, PLATEAU_OK);
    svg = harness_slurp(tmp_path("t.svg"), &len);
    CHECK(svg != NULL);
    if (!svg) return;
    CHECK(strncmp(svg, "<svg", 4) == 0);
    CHECK(len > 7 && strcmp(svg + len - 7, "</svg>\n") == 0);
    /* 3 on [1, 5] is the middle of the map */
    expect_hex(0.5, want);
    CHECK(polygon_fill(svg, 0, hex));
    CHECK(strcmp(hex, want) == 0);
    CHECK_EQ_INT(count_of(svg, "<polygon"), 1);
    /* the legend: 64 steps, the given range, the title escaped */
    CHECK_EQ_INT(count_of(svg, "<rect"), 65);
    CHECK(legend_value(svg, "plateau-legend-max", &hi, shown, sizeof shown));
    CHECK(hi == 5.0 && strcmp(shown, "5") == 0);
    CHECK(legend_value(svg, "plateau-legend-min", &lo, shown, sizeof shown));
    CHECK(lo == 1.0 && strcmp(shown, "1") == 0);
    CHECK(strstr(svg, ">|H| &lt;&amp; &quot;x&quot;</text>") != NULL);
    /* the top step is the top of the map, the bottom one its bottom */
    {
        const char *r = strstr(svg, "<rect"), *f;
        char top[8], bottom[8];
        f = r ? strstr(r, "fill=\"") : NULL;
        CHECK(f != NULL);
        if (f) {
            memcpy(hex, f + 6, 7);
            hex[7] = '\0';
            expect_hex(1.0 - 0.5 / 64.0, top);
            CHECK(strcmp(hex, top) == 0);
        }
        expect_hex(0.5 / 64.0, bottom);
        CHECK(strstr(svg, bottom) != NULL);
    }
    CHECK(strstr(svg, "font-family=\"sans-serif\"") != NULL);
    free(svg);
    remove(tmp_path("t.svg"));
    /* out of range values are clamped to the ends */
    value = 9.0;
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("t.svg"), tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_OK);
    svg = harness_slurp(tmp_path("t.svg"), &len);
    expect_hex(1.0, want);
    CHECK(svg && polygon_fill(svg, 0, hex) && strcmp(hex, want) == 0);
    free(svg);
    remove(tmp_path("t.svg"));
}

/* Per vertex: the three cells of the triangle, in corner order, in the
 * colours of the three vertex values over their own range (0 .. 2). */
static void test_vertex_color(void)
{
    plateau_svg_colors c;
    double values[3] = { 0.0, 1.0, 2.0 }, lo = -1, hi = -1;
    char *svg, hex[8], want[8], shown[64];
    size_t len, k;
    memset(&c, 0, sizeof c);
    c.values = values;
    c.num_values = 3;
    c.per_vertex = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("v.svg"), tri_pos, 3, tri_one, 1, &c, NULL, NULL),
                 PLATEAU_OK);
    svg = harness_slurp(tmp_path("v.svg"), &len);
    CHECK(svg != NULL);
    if (!svg) return;
    CHECK_EQ_INT(count_of(svg, "<polygon"), 4); /* three cells and the outline */
    for (k = 0; k < 3; k++) {
        expect_hex(values[k] / 2.0, want);
        CHECK(polygon_fill(svg, k, hex));
        CHECK_MSG(strcmp(hex, want) == 0, "the cell of vertex k has vertex k's colour");
    }
    CHECK(polygon_fill(svg, 3, hex) && strncmp(hex, "none", 4) == 0);
    CHECK(legend_value(svg, "plateau-legend-max", &hi, shown, sizeof shown));
    CHECK(hi == 2.0 && strcmp(shown, "2") == 0);
    CHECK(legend_value(svg, "plateau-legend-min", &lo, shown, sizeof shown));
    CHECK(lo == 0.0 && strcmp(shown, "0") == 0);
    CHECK(strstr(svg, "plateau-legend-title") == NULL); /* no title asked for */
    free(svg);
    /* the cell of vertex 0 is the quadrilateral corner, edge midpoints,
     * centroid: its four points are the corner's screen point and the
     * averages, so the midpoint lies halfway between corner 0 and 1 */
    remove(tmp_path("v.svg"));
}

/* The tetrahedron: every triangle's colour appears once; marked edges are
 * drawn twice (black, then yellow); no legend on request; the stream form
 * writes the same bytes as the file form. */
static void test_mesh_and_stream(void)
{
    static const double pos[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    static const plateau_index tri[12] = { 0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3 };
    static const plateau_index marks[4] = { 0, 1, 2, 3 };
    double values[4] = { 10, 20, 30, 40 };
    double view[3] = { -1, -0.7, -0.4 };
    plateau_svg_colors c;
    plateau_error err;
    char *a, *b, want[8];
    size_t la = 0, lb = 0, k;
    FILE *f;
    memset(&c, 0, sizeof c);
    c.values = values;
    c.num_values = 4;
    c.view_dir = view;
    c.marked_edges = marks;
    c.num_marked_edges = 2;
    c.no_legend = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("m.svg"), pos, 4, tri, 4, &c, NULL, &err), PLATEAU_OK);
    f = fopen(tmp_path("m2.svg"), "wb");
    CHECK(f != NULL);
    if (!f) return;
    CHECK_EQ_INT(plateau_write_svg_colored_stream(f, pos, 4, tri, 4, &c, NULL, &err), PLATEAU_OK);
    fclose(f);
    a = harness_slurp(tmp_path("m.svg"), &la);
    b = harness_slurp(tmp_path("m2.svg"), &lb);
    CHECK(a && b && la == lb && memcmp(a, b, la) == 0);
    if (a) {
        for (k = 0; k < 4; k++) {
            expect_hex((values[k] - 10) / 30, want);
            CHECK_EQ_INT(count_of(a, want), 1);
        }
        CHECK_EQ_INT(count_of(a, "<polygon"), 4);
        CHECK_EQ_INT(count_of(a, "<line"), 4);
        CHECK(strstr(a, "stroke=\"#ffd21f\"") != NULL);
        CHECK(strstr(a, "plateau-legend") == NULL);
        CHECK(strstr(a, "<rect") == NULL);
    }
    free(a);
    free(b);
    /* all equal values: every fill is the middle of the map */
    values[0] = values[1] = values[2] = values[3] = 7.5;
    c.num_marked_edges = 0;
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("m.svg"), pos, 4, tri, 4, &c, NULL, &err), PLATEAU_OK);
    a = harness_slurp(tmp_path("m.svg"), &la);
    expect_hex(0.5, want);
    CHECK(a && count_of(a, want) == 4);
    free(a);
    remove(tmp_path("m.svg"));
    remove(tmp_path("m2.svg"));
}

static void test_errors(void)
{
    plateau_svg_colors c;
    plateau_error err;
    double values[3] = { 1, 2, 3 };
    plateau_index bad_marks[2] = { 0, 3 };
    const char *path = tmp_path("e.svg");
    FILE *f;
    memset(&c, 0, sizeof c);
    c.values = values;
    c.num_values = 1;
    remove(path);
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, NULL, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.values = NULL;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.values = values;
    CHECK_EQ_INT(plateau_write_svg_colored(NULL, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_svg_colored(path, NULL, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_svg_colored_stream(NULL, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    /* length mismatch: 1 value for 3 vertices; 3 for 1 triangle */
    c.per_vertex = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.index, 1);
    CHECK(strstr(err.message, "1 values for 3 vertices") != NULL);
    c.per_vertex = 0;
    c.num_values = 3;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK(strstr(err.message, "3 values for 1 triangles") != NULL);
    /* NaN and infinite values, with their index */
    c.per_vertex = 1;
    values[2] = NAN;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 2);
    values[2] = 3;
    values[1] = -HUGE_VAL;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 1);
    values[1] = 2;
    /* the range */
    c.range_min = 2;
    c.range_max = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.range_min = NAN;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.range_min = 0;
    c.range_max = HUGE_VAL;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.range_max = 0;
    /* marked edges */
    c.num_marked_edges = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    c.marked_edges = bad_marks;
    CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                 PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(err.index, 0);
    c.num_marked_edges = 0;
    /* the view and the mesh checks of plateau_write_svg */
    {
        double zero[3] = { 0, 0, 0 };
        plateau_index out_of_range[3] = { 0, 1, 5 };
        c.view_dir = zero;
        CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                     PLATEAU_ERR_ARGUMENT);
        c.view_dir = NULL;
        CHECK_EQ_INT(plateau_write_svg_colored(path, tri_pos, 3, out_of_range, 1, &c, NULL, &err),
                     PLATEAU_ERR_INDEX_RANGE);
    }
    /* nothing was written by any of these */
    f = fopen(path, "rb");
    CHECK(f == NULL);
    if (f) fclose(f);
    /* and a stream gets nothing either */
    f = fopen(path, "wb");
    if (f) {
        long pos;
        values[0] = NAN;
        CHECK_EQ_INT(plateau_write_svg_colored_stream(f, tri_pos, 3, tri_one, 1, &c, NULL, &err),
                     PLATEAU_ERR_NOT_FINITE);
        pos = ftell(f);
        CHECK_EQ_INT(pos, 0);
        fclose(f);
    }
    remove(path);
    /* an unwritable path */
    values[0] = 1;
    CHECK_EQ_INT(plateau_write_svg_colored(tmp_path("no/such/dir/e.svg"), tri_pos, 3, tri_one, 1, &c,
                                           NULL, &err),
                 PLATEAU_ERR_IO);
}

int main(void)
{
    sprintf(tmp_dir, "/tmp/plateau_test_svg_colored_%ld", (long)getpid());
    if (mkdir(tmp_dir, 0700) != 0) {
        fprintf(stderr, "cannot create %s\n", tmp_dir);
        return 1;
    }
    RUN(test_colormap);
    RUN(test_triangle_color);
    RUN(test_vertex_color);
    RUN(test_mesh_and_stream);
    RUN(test_errors);
    rmdir(tmp_dir);
    return harness_report("test_io_svg");
}
