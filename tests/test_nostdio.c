/* test_nostdio.c - PLATEAU_NO_STDIO leaves out the functions that open
 * files (and <stdio.h> with them), and the rest still works.  plateau.h comes
 * first, before anything includes <stdio.h>. */
#define PLATEAU_NO_STDIO
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"

/* Were the file functions declared, these would be conflicting types. */
static int plateau_write_mesh(int x) { return x + 1; }
static int plateau_write_svg(int x) { return x + 2; }
static int plateau_read_boundary_file(int x) { return x + 3; }
static int plateau_pattern_write_svg(int x) { return x + 4; }
static int plateau_pattern_write_dxf(int x) { return x + 5; }

#include "harness.h"

static void test_without_stdio(void)
{
    const char *text = "0 0 0\n1 0 0\n0 1 0.5\n";
    double *xyz = NULL, uv[6], pts[3 * 4], q[2 * 4];
    size_t m = 0, count = 0;
    plateau_domain_kind kind;
    plateau_error err;
    CHECK_EQ_INT(plateau_write_mesh(1) + plateau_write_svg(1) + plateau_read_boundary_file(1), 9);
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), NULL, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 3);
    CHECK_EQ_INT(plateau_boundary_domain(xyz, m, 0, NULL, uv, &kind, &err), PLATEAU_OK);
    CHECK_EQ_INT(kind, PLATEAU_DOMAIN_PLANE);
    CHECK_EQ_INT(plateau_seed_points(xyz, uv, m, 4, 1, NULL, pts, q, &count, &err), PLATEAU_OK);
    CHECK_EQ_INT(count, 4);
    CHECK_NEAR(pts[0], 1.0 / 3.0, 1e-15);
    free(xyz);
    CHECK_EQ_INT(plateau_parse_boundary("1 2\n", 4, NULL, &xyz, &m, &err), PLATEAU_ERR_PARSE);
    CHECK(strcmp(err.message, "line 1: 2 field(s); expected three numbers \"x y z\": \"1 2\"") == 0);
    CHECK(xyz == NULL);
}

/* The cutting patterns without their writers: a square of two triangles,
 * one panel. */
static void test_pattern_without_stdio(void)
{
    static const double sq[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    static const plateau_index tri[] = {0, 1, 2, 0, 2, 3};
    plateau_pattern_options o;
    plateau_pattern p;
    CHECK_EQ_INT(plateau_pattern_write_svg(1) + plateau_pattern_write_dxf(1), 11);
    memset(&o, 0, sizeof o);
    o.width = 2.0;
    CHECK_EQ_INT(plateau_pattern_make(sq, 4, tri, 2, &o, NULL, &p, NULL), PLATEAU_OK);
    CHECK_EQ_INT(p.num_panels, 1);
    CHECK(p.max_strain <= 1e-12);
    CHECK_NEAR(p.panels[0].width, 1.0, 1e-12);
    plateau_pattern_free(&p);
}

int main(void)
{
    RUN(test_without_stdio);
    RUN(test_pattern_without_stdio);
    return harness_report("test_nostdio");
}
