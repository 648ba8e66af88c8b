/* test_no_patterns.c - PLATEAU_NO_PATTERNS leaves out the cutting patterns
 * (CUTTING PATTERNS in plateau.h): none of their functions or types is
 * declared, and the rest of the library still works. */
#define PLATEAU_NO_PATTERNS
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
/* Were the pattern functions and types declared, these would conflict. */
static int plateau_pattern_make(int x) { return x + 1; }
static int plateau_pattern_free(int x) { return x + 2; }
static int plateau_pattern_write_svg(int x) { return x + 3; }
typedef int plateau_pattern;
typedef int plateau_pattern_options;
#include "harness.h"

static void test_without_patterns(void)
{
    static const double quad[] = {-1, -1, 0, 1, -1, 0.5, 1, 1, 0, -1, 1, 0.5};
    plateau_pattern p = 1;
    plateau_pattern_options o = 2;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_options opt;
    CHECK_EQ_INT(plateau_pattern_make(p) + plateau_pattern_free(o) + plateau_pattern_write_svg(0), 9);
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 8;
    CHECK_EQ_INT(plateau_solve(quad, 4, &opt, &mesh, &rep, NULL), PLATEAU_OK);
    CHECK(mesh.num_vertices >= 12);
    CHECK_NEAR(rep.area, plateau_mesh_area(&mesh), 1e-12 * rep.area);
    plateau_mesh_free(&mesh);
}

int main(void)
{
    RUN(test_without_patterns);
    return harness_report("test_no_patterns");
}
