/* test_io.c - the boundary parser and file reader, the mesh writers (OBJ,
 * PLY, OFF) read back exactly, and the SVG picture. */
#define _POSIX_C_SOURCE 200809L /* getpid, mkdir, rmdir: a directory of our own; fork,
                                   setrlimit, symlink, lstat: writes that fail */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "harness.h"
#include "countalloc.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

static char tmp_dir[256];

static const char *tmp_path(const char *name)
{
    static char path[512];
    sprintf(path, "%s/%s", tmp_dir, name);
    return path;
}

static plateau_result parse(const char *text, double **xyz, size_t *m, plateau_error *err)
{
    return plateau_parse_boundary(text, strlen(text), NULL, xyz, m, err);
}

/* ---------------------------------------------------------------- parser */
static void test_parse_good(void)
{
    const char *text =
        "# a square\n"
        "\n"
        "0 0 0\r\n"
        "  1\t0   0.5   # first corner on the right\r\n"
        "1 1 1e0\n"
        "   \t  \n"
        "-0.0 +1 0x1p-2\n"
        "# done";
    double *xyz = NULL;
    size_t m = 99;
    plateau_error err;
    CHECK_EQ_INT(parse(text, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(err.code, PLATEAU_OK);
    CHECK_EQ_INT(m, 4);
    CHECK(xyz != NULL);
    if (xyz && m == 4) {
        CHECK(xyz[3] == 1.0 && xyz[4] == 0.0 && xyz[5] == 0.5);
        CHECK(xyz[8] == 1.0);
        CHECK(xyz[9] == 0.0 && xyz[10] == 1.0 && xyz[11] == 0.25);
    }
    free(xyz);
    /* exactly round-tripping decimal text */
    CHECK_EQ_INT(parse("0.1 0.30000000000000004 -1.7976931348623157e308", &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 1);
    if (xyz) {
        CHECK(xyz[0] == 0.1);
        CHECK(xyz[1] == 0.1 + 0.2);
        CHECK(xyz[2] == -1.7976931348623157e308);
    }
    free(xyz);
    /* not NUL-terminated: length counts */
    CHECK_EQ_INT(plateau_parse_boundary("1 2 3\n4 5 6\n7 8 9", 11, NULL, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 2);
    free(xyz);
    /* empty and comment-only texts: no vertex, no allocation */
    CHECK_EQ_INT(plateau_parse_boundary(NULL, 0, NULL, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 0);
    CHECK(xyz == NULL);
    CHECK_EQ_INT(parse("# nothing\n\n   \n", &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 0);
    CHECK(xyz == NULL);
}

/* A closing point equal to the first is dropped (the polygon closes by
 * itself), loop by loop; each vertex's line; the loops a blank line
 * separates ('#' lines and blank lines at the ends separate nothing). */
static void test_parse_closing_and_lines(void)
{
    static const struct {
        const char *text;
        int split;
        size_t m, loops, c0, c1, dropped;
        long line0, line_last, closing0, closing1;
    } cases[] = {
        /* one loop: a closed square, with comments and a blank line */
        {"# square\n0 0 0\n1 0 0\n\n1 1 0\n0 1 0\n0 0 0\n", 0, 4, 1, 4, 0, 1, 2, 6, 7, 0},
        /* the same read as loops: the blank line splits it; the second
         * run 1 1 0 / 0 1 0 / 0 0 0 does not end on its first */
        {"# square\n0 0 0\n1 0 0\n\n1 1 0\n0 1 0\n0 0 0\n", 1, 5, 2, 2, 3, 0, 2, 7, 0, 0},
        /* a closing point equal only up to rounding stays */
        {"0 0 0\n1 0 0\n0 1 0\n0 0 1e-300\n", 0, 4, 1, 4, 0, 0, 1, 4, 0, 0},
        /* two closed loops, CRLF, comments between them */
        {"0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 0\r\n \t\r\n# ring 2\n\n0 0 1 # c\n1 0 1\n0 1 1\n0 0 1\n",
         1, 6, 2, 3, 3, 2, 1, 10, 4, 11},
        /* split rule: no vertex, blank ends, '#' lines only */
        {"\n\n0 0 0\n1 0 0\n0 1 0\n\n\n", 1, 3, 1, 3, 0, 0, 3, 5, 0, 0},
        {"0 0 0\n1 0 0\n0 1 0\n# a comment\n0 0 1\n1 0 1\n0 1 1\n", 1, 6, 1, 6, 0, 0, 1, 7, 0, 0},
        {"0 0 0\n1 0 0\n0 1 0\n\n0 0 1\n1 0 1\n0 1 1\n1 1 1", 1, 7, 2, 3, 4, 0, 1, 8, 0, 0},
        {"# only\n\n", 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    };
    size_t i, m;
    double *xyz;
    plateau_error err;
    plateau_boundary_lines info;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        memset(&info, 0, sizeof info);
        info.split_loops = cases[i].split;
        if (!CHECK_EQ_INT(plateau_parse_boundary_lines(cases[i].text, strlen(cases[i].text), NULL, &xyz,
                                                       &m, &info, &err), PLATEAU_OK))
            continue;
        CHECK_EQ_INT(m, cases[i].m);
        CHECK_EQ_INT(info.num_loops, cases[i].loops);
        CHECK_EQ_INT(info.closing_dropped, cases[i].dropped);
        if (info.num_loops > 0) {
            CHECK_EQ_INT(info.loop_counts[0], cases[i].c0);
            CHECK_EQ_INT(info.closing_lines[0], cases[i].closing0);
            CHECK_EQ_INT(info.lines[0], cases[i].line0);
            CHECK_EQ_INT(info.lines[m - 1], cases[i].line_last);
        }
        if (info.num_loops > 1) {
            CHECK_EQ_INT(info.loop_counts[1], cases[i].c1);
            CHECK_EQ_INT(info.closing_lines[1], cases[i].closing1);
        }
        /* the plain parser: one loop, the same vertices when not split */
        if (!cases[i].split) {
            double *plain;
            size_t pm;
            CHECK_EQ_INT(parse(cases[i].text, &plain, &pm, &err), PLATEAU_OK);
            CHECK_EQ_INT(pm, m);
            CHECK(pm == m && (m == 0 || memcmp(plain, xyz, 3 * m * sizeof(double)) == 0));
            free(plain);
        }
        plateau_boundary_free(xyz, NULL);
        plateau_boundary_lines_free(&info, NULL);
        CHECK(info.lines == NULL && info.loop_counts == NULL && info.num_loops == 0);
    }
    /* the kept vertices of the two closed loops, in order */
    memset(&info, 0, sizeof info);
    info.split_loops = 1;
    CHECK_EQ_INT(plateau_parse_boundary_lines(cases[3].text, strlen(cases[3].text), NULL, &xyz, &m, &info,
                                              &err), PLATEAU_OK);
    if (m == 6) {
        static const double want[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1};
        CHECK(memcmp(xyz, want, sizeof want) == 0);
        CHECK(info.lines[3] == 8 && info.lines[4] == 9 && info.lines[5] == 10);
    }
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_lines_free(&info, NULL);
    /* a closed triangle read plainly passes the boundary check */
    CHECK_EQ_INT(parse("0 0 0\n1 0 0\n0 1 0\n0 0 0\n", &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 3);
    CHECK_EQ_INT(plateau_boundary_check(xyz, m, &err), PLATEAU_OK);
    free(xyz);
    /* errors: info NULL; a parse error frees everything and names the line */
    CHECK_EQ_INT(plateau_parse_boundary_lines("0 0 0\n", 6, NULL, &xyz, &m, NULL, &err), PLATEAU_ERR_ARGUMENT);
    CHECK(xyz == NULL && m == 0);
    memset(&info, 0, sizeof info);
    CHECK_EQ_INT(plateau_parse_boundary_lines("0 0 0\n1 0 x\n", 12, NULL, &xyz, &m, &info, &err),
                 PLATEAU_ERR_PARSE);
    CHECK(xyz == NULL && m == 0 && info.lines == NULL && info.num_loops == 0);
    CHECK_EQ_INT(err.index, 2);
    CHECK_EQ_INT(err.index2, -1);
    /* out of memory at each of its allocations: the code, nothing leaked */
    {
        long k, calls;
        countalloc ca;
        plateau_allocator a;
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        memset(&info, 0, sizeof info);
        info.split_loops = 1;
        CHECK_EQ_INT(plateau_parse_boundary_lines(cases[3].text, strlen(cases[3].text), &a, &xyz, &m, &info,
                                                  &err), PLATEAU_OK);
        plateau_boundary_free(xyz, &a);
        plateau_boundary_lines_free(&info, &a);
        CHECK_EQ_INT(ca.live, 0);
        calls = ca.calls;
        CHECK(calls >= 4);
        for (k = 1; k <= calls; k++) {
            countalloc_init(&ca, k);
            a = countalloc_allocator(&ca);
            CHECK_EQ_INT(plateau_parse_boundary_lines(cases[3].text, strlen(cases[3].text), &a, &xyz, &m,
                                                      &info, &err), PLATEAU_ERR_OUT_OF_MEMORY);
            CHECK(xyz == NULL && m == 0 && info.lines == NULL && info.loop_counts == NULL);
            CHECK_EQ_INT(ca.live, 0);
            CHECK_EQ_INT(ca.bad, 0);
        }
    }
}

static void test_parse_errors(void)
{
    static const struct {
        const char *text;
        int code;
        long line;
    } cases[] = {
        {"0 0 0\n1 0 0\n1 1\n", PLATEAU_ERR_PARSE, 3},
        {"0 0 0\n1 0 0 4\n", PLATEAU_ERR_PARSE, 2},
        {"# c\n\n0 0 zero\n", PLATEAU_ERR_PARSE, 3},
        {"0 0 0\r\n1,5 0 0\r\n", PLATEAU_ERR_PARSE, 2},
        {"0 0 0\n1 0 0.5.5\n", PLATEAU_ERR_PARSE, 2},
        {"0 0 1e\n", PLATEAU_ERR_PARSE, 1},
        {"0 0 0\n\n\n\n\n\n1 0 0x\n", PLATEAU_ERR_PARSE, 7},
        {"0 0 0\n0 nan 0\n", PLATEAU_ERR_NOT_FINITE, 2},
        {"0 0 0\n1 1 1\n0 0 -inf\n", PLATEAU_ERR_NOT_FINITE, 3},
        {"0 0 1e999\n", PLATEAU_ERR_NOT_FINITE, 1},
        {"0 0 0\n1 0 0\n1 1 0\n0 1 0 # ok\n2 2\n", PLATEAU_ERR_PARSE, 5},
        {"1 2 3\n\x01 2 3\n", PLATEAU_ERR_PARSE, 2},
        {"1;2\n", PLATEAU_ERR_PARSE, 1},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double *xyz = (double *)&i;
        size_t m = 77;
        plateau_error err;
        char want[32];
        plateau_result r = parse(cases[i].text, &xyz, &m, &err);
        CHECK_EQ_INT(r, cases[i].code);
        CHECK_EQ_INT(err.code, cases[i].code);
        CHECK_EQ_INT(err.index, cases[i].line);
        sprintf(want, "line %ld:", cases[i].line);
        CHECK_MSG(strncmp(err.message, want, strlen(want)) == 0, err.message);
        CHECK(xyz == NULL);
        CHECK_EQ_INT(m, 0);
    }
    {
        /* a NUL byte inside the given length */
        static const char with_nul[] = "1 2 3\n4 \0 6\n";
        double *xyz;
        size_t m;
        plateau_error err;
        CHECK_EQ_INT(plateau_parse_boundary(with_nul, sizeof with_nul - 1, NULL, &xyz, &m, &err),
                     PLATEAU_ERR_PARSE);
        CHECK_EQ_INT(err.index, 2);
    }
    {
        double *xyz;
        size_t m;
        CHECK_EQ_INT(plateau_parse_boundary("1 2 3", 5, NULL, NULL, &m, NULL), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_parse_boundary("1 2 3", 5, NULL, &xyz, NULL, NULL), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_parse_boundary(NULL, 5, NULL, &xyz, &m, NULL), PLATEAU_ERR_ARGUMENT);
    }
}

/* CSV as spreadsheets export it: fields separated by one ',' or ';' with
 * any spaces around, and one header line naming the columns, read as the
 * same square as "x y z" lines; decimal commas, empty fields, a second
 * header and a header after a vertex are errors that quote their text. */
static void test_parse_csv(void)
{
    static const char *same[] = {
        "0 0 0\n1 0 0.5\n1 1 0\n0 1 0.5\n",
        "x,y,z\n0,0,0\n1,0,0.5\n1,1,0\n0,1,0.5\n",
        "X;Y;Z\r\n0;0;0\r\n1;0;0.5\r\n1;1;0\r\n0;1;0.5\r\n",
        "\"x\",\"y\",\"z\"\n0, 0, 0\n 1 ,0 , 0.5\n1,1,0 # a comment, with a comma\n0,1,0.5\n",
        "# exported\nx_m y_m z_m\n\n0 0 0\n1, 0, 0.5\n1;1;0\n0 1 0.5\n",
        "0,0,0\n1,0,0.5\n1,1,0\n0,1,0.5\n0,0,0\n", /* the closing point */
    };
    static const double want[12] = {0, 0, 0, 1, 0, 0.5, 1, 1, 0, 0, 1, 0.5};
    static const struct {
        const char *text;
        int code;
        long line;
        const char *quoted;
    } bad[] = {
        {"1,5;2,5;3,0\n", PLATEAU_ERR_PARSE, 1, "\"1,5\""},
        {"0,0,0\n1,,0\n", PLATEAU_ERR_PARSE, 2, "\"1,,0\""},
        {"0;0;0\n1;0;0;\n", PLATEAU_ERR_PARSE, 2, "\"1;0;0;\""},
        {"x,y,z\nx,y,z\n0,0,0\n", PLATEAU_ERR_PARSE, 2, "\"x\""},
        {"0,0,0\nx,y,z\n", PLATEAU_ERR_PARSE, 2, "\"x\""},
        {"x,y\n0,0,0\n", PLATEAU_ERR_PARSE, 1, "\"x,y\""},
        {"0,0,0\n1,0,0,4\n", PLATEAU_ERR_PARSE, 2, "\"1,0,0,4\""},
        {"0,0,0\n1,0,inf\n", PLATEAU_ERR_NOT_FINITE, 2, "\"inf\""},
        {"x,y,nan\n", PLATEAU_ERR_PARSE, 1, "\"x\""}, /* nan is no column name */
        {"0 0 0\n1 0 abcdefghijabcdefghijabcdefghijabcdefghijabcdefghijabcdefghij\n", PLATEAU_ERR_PARSE, 2,
         "\"abcdefghijabcdefghijabcdefghijabcdefghijabcdefgh...\""},
    };
    size_t i, k;
    for (i = 0; i < sizeof same / sizeof same[0]; i++) {
        double *xyz = NULL;
        size_t m = 0;
        plateau_error err;
        CHECK_EQ_INT(parse(same[i], &xyz, &m, &err), PLATEAU_OK);
        CHECK_EQ_INT(m, 4);
        if (xyz && m == 4)
            for (k = 0; k < 12; k++) CHECK_NEAR(xyz[k], want[k], 0.0);
        free(xyz);
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double *xyz = (double *)&i;
        size_t m = 77;
        plateau_error err;
        char want_line[32];
        CHECK_EQ_INT(parse(bad[i].text, &xyz, &m, &err), bad[i].code);
        CHECK_EQ_INT(err.index, bad[i].line);
        sprintf(want_line, "line %ld:", bad[i].line);
        CHECK_MSG(strncmp(err.message, want_line, strlen(want_line)) == 0, err.message);
        CHECK_MSG(strstr(err.message, bad[i].quoted) != NULL, err.message);
        CHECK(xyz == NULL && m == 0);
    }
    {
        /* cables on CSV lines, after a header: the header is no vertex line */
        char text[] = "x,y,z\n0,0,0 cable 2\n1,0,0\n1,1,0\n0,1,0\n";
        double *tension = NULL, *xyz = NULL;
        size_t count = 0, m = 0;
        plateau_boundary_lines info;
        plateau_error err;
        memset(&info, 0, sizeof info);
        CHECK_EQ_INT(plateau_parse_cables(text, strlen(text), NULL, &tension, &count, &err), PLATEAU_OK);
        CHECK_EQ_INT(count, 4);
        CHECK_EQ_INT(plateau_parse_boundary_lines(text, strlen(text), NULL, &xyz, &m, &info, &err), PLATEAU_OK);
        CHECK_EQ_INT(m, 4);
        CHECK_EQ_INT(plateau_cables_align(tension, &count, &info, &err), PLATEAU_OK);
        CHECK_EQ_INT(count, 4);
        if (tension && count == 4) {
            CHECK_NEAR(tension[0], 2.0, 0.0);
            CHECK_NEAR(tension[1], 0.0, 0.0);
        }
        free(tension);
        free(xyz);
        plateau_boundary_lines_free(&info, NULL);
    }
    {
        char text[] = "0 0 0 cable\n1 0 0\n1 1 0\n";
        double *tension = NULL;
        size_t count = 0;
        plateau_error err;
        CHECK_EQ_INT(plateau_parse_cables(text, strlen(text), NULL, &tension, &count, &err), PLATEAU_ERR_PARSE);
        CHECK_MSG(strstr(err.message, ": \"0 0 0 cable\"") != NULL, err.message);
    }
}

typedef struct counting { long live, calls; } counting;
static void *count_alloc(size_t size, void *user)
{
    counting *c = (counting *)user;
    c->live++;
    c->calls++;
    return malloc(size);
}
static void count_free(void *ptr, void *user)
{
    ((counting *)user)->live--;
    free(ptr);
}

static void test_parse_allocator(void)
{
    counting c = {0, 0};
    plateau_allocator a;
    double *xyz = NULL;
    size_t m = 0;
    const char *text = "0 0 0\n1 0 0\n1 1 0\n";
    a.alloc_fn = count_alloc;
    a.free_fn = count_free;
    a.user_data = &c;
    CHECK_EQ_INT(plateau_parse_boundary(text, strlen(text), &a, &xyz, &m, NULL), PLATEAU_OK);
    CHECK_EQ_INT(m, 3);
    CHECK_EQ_INT(c.live, 1);
    plateau_boundary_free(xyz, &a);
    CHECK_EQ_INT(c.live, 0);
    /* an error after the first vertex frees what it took */
    CHECK_EQ_INT(plateau_parse_boundary("0 0 0\nx\n", 8, &a, &xyz, &m, NULL), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(c.live, 0);
    /* read from a file through the allocator: nothing left but the result */
    {
        FILE *f = fopen(tmp_path("alloc.txt"), "wb");
        CHECK(f != NULL);
        if (f) {
            fputs(text, f);
            fclose(f);
        }
        CHECK_EQ_INT(plateau_read_boundary_file(tmp_path("alloc.txt"), &a, &xyz, &m, NULL), PLATEAU_OK);
        CHECK_EQ_INT(m, 3);
        CHECK_EQ_INT(c.live, 1);
        plateau_boundary_free(xyz, &a);
        CHECK_EQ_INT(c.live, 0);
        remove(tmp_path("alloc.txt"));
    }
}

/* ----------------------------------------------------------- mesh reader */
static plateau_result parse_mesh(const char *text, double **p, size_t *nv, plateau_index **t, size_t *nt,
                                 long **lines, plateau_error *err)
{
    return plateau_parse_mesh(text, strlen(text), NULL, p, nv, t, nt, lines, err);
}

/* 1 when triangles t (nt of them) are the 3 * nt indices want. */
static int same_triangles(const plateau_index *t, size_t nt, const int *want, size_t count)
{
    size_t i;
    if (3 * nt != count) return 0;
    for (i = 0; i < count; i++)
        if (t[i] != want[i]) return 0;
    return 1;
}

/* OBJ and OFF as meshers and the writers here write them: comments,
 * CRLF, negative and slashed corners, faces naming later vertices, the
 * statements that carry nothing plateau reads, quads and pentagons as
 * fans from their first corner, OFF's counts on the header line, and
 * colours after vertices and faces. */
static void test_parse_mesh_good(void)
{
    static const int quad[] = {0, 1, 2, 0, 2, 3}, mixed[] = {0, 1, 2, 0, 2, 3, 1, 4, 2};
    static const int pent[] = {0, 1, 2, 0, 2, 3, 0, 3, 4};
    const char *obj = "# a square and a triangle\r\n"
                      "mtllib film.mtl\r\n"
                      "o film\r\n"
                      "v 0 0 0\r\n"
                      "v 1 0 0.5   # a comment after a vertex\r\n"
                      "vt 0.5 0.5\r\n"
                      "vn 0 0 1\r\n"
                      "v 1 1 0 1\r\n"           /* with a w */
                      "v\t0 1 0.25 0.1 0.2 0.3\r\n" /* with a colour */
                      "g film\r\n"
                      "usemtl blue\r\n"
                      "s off\r\n"
                      "f 1/1/1 2/1/1 3/1/1 4/1/1\r\n"
                      "f -3//1 5 -2\r\n"      /* 5: a vertex defined below */
                      "l 1 2\r\n"
                      "v 2 0.5 0\r\n";
    const char *off = "# an OFF pentagon\n"
                      "OFF 5 1 0\n"
                      "0 0 0\n1 0 0\n1.5 1 0\n0.5 1.5 0\n-0.5 1 0\n"
                      "5 0 1 2 3 4 0.8 0.2 0.2\n";
    const char *coff = "COFF\n\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n";
    double *p = NULL;
    plateau_index *t = NULL;
    long *lines = NULL;
    size_t nv = 9, nt = 9;
    plateau_error err;
    CHECK_EQ_INT(parse_mesh(obj, &p, &nv, &t, &nt, &lines, &err), PLATEAU_OK);
    CHECK_EQ_INT(err.code, PLATEAU_OK);
    CHECK_EQ_INT(nv, 5);
    CHECK_EQ_INT(nt, 3);
    CHECK(t && same_triangles(t, nt, mixed, 9));
    CHECK(p && p[5] == 0.5 && p[11] == 0.25 && p[12] == 2.0 && p[13] == 0.5);
    CHECK(lines && lines[0] == 13 && lines[1] == 13 && lines[2] == 14);
    plateau_mesh_arrays_free(p, t, lines, NULL);
    CHECK_EQ_INT(parse_mesh(off, &p, &nv, &t, &nt, NULL, &err), PLATEAU_OK);
    CHECK_EQ_INT(nv, 5);
    CHECK(nt == 3 && t && same_triangles(t, nt, pent, 9));
    CHECK(p && p[6] == 1.5 && p[10] == 1.5);
    plateau_mesh_arrays_free(p, t, NULL, NULL);
    CHECK_EQ_INT(parse_mesh(coff, &p, &nv, &t, &nt, &lines, &err), PLATEAU_OK);
    CHECK(nv == 3 && nt == 1 && lines && lines[0] == 7);
    plateau_mesh_arrays_free(p, t, lines, NULL);
    /* the square alone, and bit for bit: %.17g reads back exactly */
    CHECK_EQ_INT(parse_mesh("v 0.1 0.30000000000000004 -1.7976931348623157e308\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                            "f 1 2 3 4\n", &p, &nv, &t, &nt, NULL, &err), PLATEAU_OK);
    CHECK(t && same_triangles(t, nt, quad, 6));
    CHECK(p && p[0] == 0.1 && p[1] == 0.30000000000000004 && p[2] == -1.7976931348623157e308);
    plateau_mesh_arrays_free(p, t, NULL, NULL);
}

/* Every refusal of the mesh parser: the code, the line in err->index, the
 * message naming the line and quoting the offending text; nothing
 * allocated (a counting allocator sees none left). */
static void test_parse_mesh_errors(void)
{
    static const struct {
        const char *text;
        plateau_result code;
        long line;
        const char *message;
    } bad[] = {
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 0\n", PLATEAU_ERR_PARSE, 4, "line 4: vertex index 0 (OBJ counts from 1): \"0\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n", PLATEAU_ERR_PARSE, 4,
         "line 4: vertex index beyond the 3 vertices of the file: \"4\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 99999999999999\n", PLATEAU_ERR_PARSE, 4,
         "line 4: vertex index beyond what plateau_index holds: \"99999999999999\""},
        {"v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 1 1 0\n", PLATEAU_ERR_PARSE, 3,
         "line 3: vertex index reaches before the first vertex (2 vertices come before the line): \"-3\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3.5\n", PLATEAU_ERR_PARSE, 4,
         "line 4: corner 3 is not a vertex index (\"a\", \"a/t\", \"a//n\" or \"a/t/n\"): \"3.5\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3/x\n", PLATEAU_ERR_PARSE, 4, "line 4: corner 3 is not a vertex index"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2\n", PLATEAU_ERR_PARSE, 4,
         "line 4: a face wants at least three corners, not 2: \"f 1 2\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 1\n", PLATEAU_ERR_PARSE, 4,
         "line 4: the face names vertex 1 twice (a degenerate triangle): \"1\""},
        {"v 0 0 0\nv 1 0 nan\nv 1 1 0\nf 1 2 3\n", PLATEAU_ERR_NOT_FINITE, 2,
         "line 2: coordinate 3 is NaN or infinite: \"nan\""},
        {"v 0 0 0\nv 1 0 1e999\nv 1 1 0\nf 1 2 3\n", PLATEAU_ERR_NOT_FINITE, 2, "line 2: coordinate 3 is NaN"},
        {"v 0 0 0\nv 1 zero 0\nv 1 1 0\nf 1 2 3\n", PLATEAU_ERR_PARSE, 2,
         "line 2: field 2 of the vertex is not a number: \"zero\""},
        {"v 0 0 0\nv 1 0\nv 1 1 0\nf 1 2 3\n", PLATEAU_ERR_PARSE, 2,
         "line 2: a vertex wants three numbers \"x y z\", not 2: \"v 1 0\""},
        {"v 0 0 0 1 2 3 4 5\n", PLATEAU_ERR_PARSE, 1, "line 1: more than 7 numbers on a vertex line: \"5\""},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nfacet 1 2 3 # no\n", PLATEAU_ERR_PARSE, 4,
         "line 4: not an OBJ statement that plateau reads (v, f): \"facet 1 2 3\""},
        {"v 0 0 0\ncstype bspline\n", PLATEAU_ERR_PARSE, 2,
         "line 2: free-form geometry (curves and surfaces) is not read: \"cstype bspline\""},
        {"ply\nformat ascii 1.0\n", PLATEAU_ERR_PARSE, 1, "line 1: a PLY file: OBJ and OFF meshes are read: \"ply\""},
        {"solid plateau\n", PLATEAU_ERR_PARSE, 1, "line 1: an ASCII STL file"},
        {"", PLATEAU_ERR_PARSE, -1, "no face"},
        {"# nothing\n\n", PLATEAU_ERR_PARSE, -1, "no face"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\n", PLATEAU_ERR_PARSE, -1, "no face"},
        {"OFF\n", PLATEAU_ERR_PARSE, 1, "line 1: the OFF text ends before its counts \"V F E\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n", PLATEAU_ERR_PARSE, 4, "line 4: the text ends after 2 of the 3 vertices"},
        {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", PLATEAU_ERR_PARSE, 6,
         "line 6: the text ends after 1 of the 2 faces"},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", PLATEAU_ERR_PARSE, 7,
         "line 7: a line after the last face (the counts say F = 1): \"3 0 1 2\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", PLATEAU_ERR_PARSE, 6,
         "line 6: vertex index beyond the 3 vertices of the file: \"3\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", PLATEAU_ERR_PARSE, 6,
         "line 6: corner 2 is not a vertex index (0-based): \"-1\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", PLATEAU_ERR_PARSE, 6,
         "line 6: a face starts with its number of corners, 3 or more: \"2\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", PLATEAU_ERR_PARSE, 6,
         "line 6: the face has 3 corners, fewer than its count: \"4 0 1 2\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n", PLATEAU_ERR_PARSE, 6,
         "line 6: the face names vertex 1 twice (a degenerate triangle): \"1\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", PLATEAU_ERR_PARSE, 6,
         "line 6: after the face's corners, a field that is not a number (a colour): \"red\""},
        {"OFF\nthree 1 0\n", PLATEAU_ERR_PARSE, 2, "line 2: count 1 is not a whole number below 2^53: \"three\""},
        {"OFF\n3\n", PLATEAU_ERR_PARSE, 2, "line 2: the counts \"V F E\" want V and F"},
        {"OFF\n3 1 0 7\n", PLATEAU_ERR_PARSE, 2, "line 2: more than the three counts \"V F E\": \"7\""},
        {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", PLATEAU_ERR_PARSE, -1, "no face: the OFF text's counts say 0 faces"}};
    size_t i;
    countalloc ca;
    plateau_allocator a;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double *p = (double *)&i;
        plateau_index *t = (plateau_index *)&i;
        long *lines = (long *)&i;
        size_t nv = 9, nt = 9;
        plateau_error err;
        char what[600];
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_parse_mesh(bad[i].text, strlen(bad[i].text), &a, &p, &nv, &t, &nt, &lines, &err),
                     bad[i].code);
        sprintf(what, "%.300s -> %.200s", bad[i].text, err.message);
        CHECK_MSG(err.code == bad[i].code && err.index == bad[i].line, what);
        CHECK_MSG(strstr(err.message, bad[i].message) == err.message, what);
        CHECK(p == NULL && t == NULL && lines == NULL && nv == 0 && nt == 0);
        CHECK(ca.live == 0 && ca.bad == 0);
    }
    {   /* a NUL byte: a binary file, not text */
        static const char nul[] = "v 0 0 0\nv 1 0\0 0\nv 1 1 0\nf 1 2 3\n";
        double *p;
        plateau_index *t;
        size_t nv, nt;
        plateau_error err;
        CHECK_EQ_INT(plateau_parse_mesh(nul, sizeof nul - 1, NULL, &p, &nv, &t, &nt, NULL, &err), PLATEAU_ERR_PARSE);
        CHECK(err.index == 2 && strstr(err.message, "line 2: a NUL byte: not a text file") == err.message);
    }
    {   /* a NULL output or a bad allocator */
        double *p;
        plateau_index *t;
        size_t nv, nt;
        plateau_allocator half = {0};
        half.alloc_fn = countalloc_alloc;
        CHECK_EQ_INT(plateau_parse_mesh("f 1 2 3", 7, NULL, NULL, &nv, &t, &nt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_parse_mesh(NULL, 7, NULL, &p, &nv, &t, &nt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
        CHECK_EQ_INT(plateau_parse_mesh("f 1 2 3", 7, &half, &p, &nv, &t, &nt, NULL, NULL), PLATEAU_ERR_ARGUMENT);
    }
}

/* Each allocation of the mesh parser and reader refused in turn: out of
 * memory, nothing left; the file reader's errors. */
static void test_read_mesh_file(void)
{
    const char *text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    countalloc ca;
    plateau_allocator a;
    double *p;
    plateau_index *t;
    long *lines;
    size_t nv, nt;
    long k;
    plateau_error err;
    FILE *f = fopen(tmp_path("quad.obj"), "wb");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    for (k = 1; k <= 4; k++) {
        countalloc_init(&ca, k);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_parse_mesh(text, strlen(text), &a, &p, &nv, &t, &nt, &lines, &err),
                     k <= 3 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_OK);
        if (k > 3) plateau_mesh_arrays_free(p, t, lines, &a);
        CHECK(ca.live == 0 && ca.bad == 0);
        countalloc_init(&ca, k);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_read_mesh_file(tmp_path("quad.obj"), &a, &p, &nv, &t, &nt, &err),
                     k <= 3 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_OK);
        if (k > 3) {
            CHECK(nv == 4 && nt == 2 && p[6] == 1.0);
            plateau_mesh_arrays_free(p, t, NULL, &a);
        }
        CHECK(ca.live == 0 && ca.bad == 0);
    }
    remove(tmp_path("quad.obj"));
    CHECK_EQ_INT(plateau_read_mesh_file(tmp_path("quad.obj"), NULL, &p, &nv, &t, &nt, &err), PLATEAU_ERR_IO);
    CHECK(strstr(err.message, "cannot open") != NULL && strstr(err.message, "quad.obj") != NULL);
    CHECK_EQ_INT(plateau_read_mesh_file(tmp_dir, NULL, &p, &nv, &t, &nt, &err), PLATEAU_ERR_IO);
    CHECK_EQ_INT(plateau_read_mesh_file(NULL, NULL, &p, &nv, &t, &nt, &err), PLATEAU_ERR_ARGUMENT);
}

/* The readers' size cap: more than max_bytes bytes is
 * PLATEAU_ERR_INPUT_TOO_LARGE, holding at most max_bytes + 1 of them; an
 * endless stream (/dev/zero) is refused, not read into memory. */
static void test_read_size_cap(void)
{
    countalloc ca;
    plateau_allocator a;
    plateau_error err;
    double *xyz = NULL;
    size_t m = 0, i;
    FILE *f = tmpfile();
    CHECK(f != NULL);
    if (!f) return;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    /* 200 vertex lines of "0.5 0.25 1\n" (11 bytes): 2200 bytes; the last
     * differs, or it would be dropped as the first's closing point */
    for (i = 0; i < 200; i++) fputs(i < 199 ? "0.5 0.25 1\n" : "0.5 0.25 2\n", f);
    fflush(f);
    rewind(f);
    CHECK_EQ_INT(plateau_read_boundary_stream(f, 2200, &a, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 200);
    plateau_boundary_free(xyz, &a);
    rewind(f);
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    CHECK_EQ_INT(plateau_read_boundary_stream(f, 2199, &a, &xyz, &m, &err),
                 PLATEAU_ERR_INPUT_TOO_LARGE);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_INPUT_TOO_LARGE);
    CHECK(strstr(err.message, "2199 bytes") != NULL);
    CHECK(xyz == NULL && m == 0);
    CHECK_EQ_INT(ca.live, 0);
    CHECK(ca.bytes_peak <= 2200 + 256);
    /* 0: the documented default, which 2200 bytes are far below */
    rewind(f);
    CHECK_EQ_INT(plateau_read_boundary_stream(f, 0, &a, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 200);
    plateau_boundary_free(xyz, &a);
    CHECK(PLATEAU_DEFAULT_MAX_INPUT_BYTES >= 1000000u);
    fclose(f);
    CHECK_EQ_INT(plateau_read_boundary_stream(NULL, 0, &a, &xyz, &m, &err), PLATEAU_ERR_ARGUMENT);
    /* an endless stream: refused after cap + 1 bytes */
    f = fopen("/dev/zero", "rb");
    if (f) {
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_read_boundary_stream(f, 100000, &a, &xyz, &m, &err),
                     PLATEAU_ERR_INPUT_TOO_LARGE);
        CHECK(ca.bytes_peak <= 100001 + 65536 + 256);
        CHECK_EQ_INT(ca.live, 0);
        fclose(f);
    }
    /* a file larger than the default cap through plateau_read_boundary_file:
     * a sparse file of cap + 1 bytes (written as one byte at its end) */
    f = fopen(tmp_path("huge.txt"), "wb");
    CHECK(f != NULL);
    if (f) {
        int ok = fseek(f, (long)PLATEAU_DEFAULT_MAX_INPUT_BYTES, SEEK_SET) == 0 && fputc('\n', f) != EOF;
        fclose(f);
        if (ok) {
            countalloc_init(&ca, 0);
            a = countalloc_allocator(&ca);
            CHECK_EQ_INT(plateau_read_boundary_file(tmp_path("huge.txt"), &a, &xyz, &m, &err),
                         PLATEAU_ERR_INPUT_TOO_LARGE);
            CHECK_EQ_INT(ca.live, 0);
        }
        remove(tmp_path("huge.txt"));
    }
}

/* The parser's vertex array is bounded by the text, not by its line count:
 * a million blank lines and one vertex allocate 24 bytes, not 24 MB. */
static void test_parse_blank_lines_bounded(void)
{
    countalloc ca;
    plateau_allocator a;
    size_t len = 1000000, m = 0;
    char *text = (char *)malloc(len + 16);
    double *xyz = NULL;
    CHECK(text != NULL);
    if (!text) return;
    memset(text, '\n', len);
    memcpy(text + len, "0 1 2", 5);
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    CHECK_EQ_INT(plateau_parse_boundary(text, len + 5, &a, &xyz, &m, NULL), PLATEAU_OK);
    CHECK_EQ_INT(m, 1);
    CHECK(ca.bytes_peak <= 4 * (len + 5) + 256);
    if (!(ca.bytes_peak <= 4 * (len + 5) + 256))
        fprintf(stderr, "  parser peak %lu bytes for %lu bytes of text\n",
                (unsigned long)ca.bytes_peak, (unsigned long)(len + 5));
    if (xyz && m == 1) CHECK(xyz[0] == 0.0 && xyz[1] == 1.0 && xyz[2] == 2.0);
    plateau_boundary_free(xyz, &a);
    CHECK_EQ_INT(ca.live, 0);
    free(text);
}

static void test_read_file(void)
{
    double *xyz = NULL;
    size_t m = 0, i;
    plateau_error err;
    FILE *f = fopen(tmp_path("boundary.txt"), "wb");
    CHECK(f != NULL);
    if (!f) return;
    /* a longer file than one read chunk */
    fputs("# a long polygon\r\n", f);
    for (i = 0; i < 5000; i++) fprintf(f, "%.17g %.17g %.17g\n", cos(i * 0.001), sin(i * 0.001), 0.25 * (double)i);
    fputs("1 2\n", f);
    fclose(f);
    CHECK_EQ_INT(plateau_read_boundary_file(tmp_path("boundary.txt"), NULL, &xyz, &m, &err), PLATEAU_ERR_PARSE);
    CHECK_EQ_INT(err.index, 5002);
    CHECK(strncmp(err.message, "line 5002:", 10) == 0);
    f = fopen(tmp_path("boundary.txt"), "ab");
    CHECK(f != NULL);
    if (!f) return;
    fclose(f);
    /* rewrite without the bad line */
    f = fopen(tmp_path("boundary.txt"), "wb");
    if (!f) return;
    for (i = 0; i < 5000; i++) fprintf(f, "%.17g %.17g %.17g\n", cos(i * 0.001), sin(i * 0.001), 0.25 * (double)i);
    fclose(f);
    CHECK_EQ_INT(plateau_read_boundary_file(tmp_path("boundary.txt"), NULL, &xyz, &m, &err), PLATEAU_OK);
    CHECK_EQ_INT(m, 5000);
    if (xyz && m == 5000) {
        int same = 1;
        for (i = 0; i < 5000; i++)
            same &= xyz[3 * i] == cos(i * 0.001) && xyz[3 * i + 1] == sin(i * 0.001) &&
                    xyz[3 * i + 2] == 0.25 * (double)i;
        CHECK(same);
        CHECK_NEAR(xyz[3 * 4999 + 2], 1249.75, 0.0);
    }
    free(xyz);
    remove(tmp_path("boundary.txt"));
    CHECK_EQ_INT(plateau_read_boundary_file(tmp_path("no-such-file.txt"), NULL, &xyz, &m, &err), PLATEAU_ERR_IO);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_IO);
    CHECK(strstr(err.message, "no-such-file.txt") != NULL);
    CHECK(xyz == NULL);
}

/* ---------------------------------------------------------------- writers */
/* A small mesh with awkward values: a tetrahedron's surface. */
static const double mesh_pos[15] = {0.1, 0.2, 0.3, 1.0 / 3.0, -2.5e-300, 7.0,
                                    -1e300, 4.0, 1.0 - 1e-16, 3.14159265358979, 2.0 / 7.0, -0.0,
                                    5.0, 5.0, 5.0};
static const plateau_index mesh_tri[12] = {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0};

/* Reads the vertices and faces back from OBJ, PLY or OFF text. */
static int read_back(const char *text, int format, double *pos, size_t *nv, long *tri, size_t *nt)
{
    const char *p = text;
    size_t v = 0, t = 0, want_v = 0, want_t = 0;
    char line[512];
    int header = format != 0;
    while (*p) {
        size_t k = 0;
        while (*p && *p != '\n' && k < sizeof line - 1) line[k++] = *p++;
        line[k] = '\0';
        if (*p == '\n') p++;
        if (format == 1 && header) {
            unsigned long n;
            if (sscanf(line, "element vertex %lu", &n) == 1) want_v = n;
            if (sscanf(line, "element face %lu", &n) == 1) want_t = n;
            if (strcmp(line, "end_header") == 0) header = 0;
            continue;
        }
        if (format == 2 && header) {
            unsigned long a, b, c;
            if (strcmp(line, "OFF") == 0) continue;
            if (sscanf(line, "%lu %lu %lu", &a, &b, &c) != 3) return 0;
            want_v = a;
            want_t = b;
            header = 0;
            continue;
        }
        if (format == 0) {
            if (line[0] == '#') continue;
            if (line[0] == 'v' && sscanf(line + 1, "%lf %lf %lf", pos + 3 * v, pos + 3 * v + 1, pos + 3 * v + 2) == 3) {
                v++;
                continue;
            }
            if (line[0] == 'f' && sscanf(line + 1, "%ld %ld %ld", tri + 3 * t, tri + 3 * t + 1, tri + 3 * t + 2) == 3) {
                tri[3 * t] -= 1;
                tri[3 * t + 1] -= 1;
                tri[3 * t + 2] -= 1;
                t++;
                continue;
            }
            return 0;
        }
        if (v < want_v) {
            if (sscanf(line, "%lf %lf %lf", pos + 3 * v, pos + 3 * v + 1, pos + 3 * v + 2) != 3) return 0;
            v++;
        } else if (t < want_t) {
            int three;
            if (sscanf(line, "%d %ld %ld %ld", &three, tri + 3 * t, tri + 3 * t + 1, tri + 3 * t + 2) != 4 || three != 3)
                return 0;
            t++;
        } else if (line[0]) {
            return 0;
        }
    }
    if (format != 0 && (v != want_v || t != want_t)) return 0;
    *nv = v;
    *nt = t;
    return 1;
}

static void test_write_formats(void)
{
    static const char *names[3] = {"mesh.obj", "mesh.PLY", "mesh.off"};
    int format;
    for (format = 0; format < 3; format++) {
        plateau_error err;
        char *text;
        size_t len = 0, nv = 0, nt = 0, i;
        double pos[15];
        long tri[12];
        const char *path = tmp_path(names[format]);
        CHECK_EQ_INT(plateau_write_mesh(path, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_OK);
        CHECK_EQ_INT(err.code, PLATEAU_OK);
        text = harness_slurp(path, &len);
        CHECK(text != NULL);
        if (!text) continue;
        CHECK(read_back(text, format, pos, &nv, tri, &nt));
        CHECK_EQ_INT(nv, 5);
        CHECK_EQ_INT(nt, 4);
        if (nv == 5 && nt == 4) {
            for (i = 0; i < 15; i++) CHECK(pos[i] == mesh_pos[i]);
            for (i = 0; i < 12; i++) CHECK_EQ_INT(tri[i], mesh_tri[i]);
        }
        if (format == 1) CHECK(strncmp(text, "ply\nformat ascii 1.0\n", 21) == 0);
        if (format == 2) CHECK(strncmp(text, "OFF\n5 4 0\n", 10) == 0);
        free(text);
        remove(path);
    }
    /* an empty mesh is a valid file */
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("empty.off"), NULL, 0, NULL, 0, NULL), PLATEAU_OK);
    remove(tmp_path("empty.off"));
}

/* A 4 x 4 grid on a saddle, 18 triangles, and one degenerate triangle
 * (a repeated corner position): STL's facets read back. */
#define STL_NV 17
#define STL_NT 19
static void stl_mesh(double *pos, plateau_index *tri)
{
    int i, j, t = 0;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++) {
            double x = 1.7 * i / 3.0, y = 0.9 * j / 3.0;
            pos[3 * (4 * j + i)] = x;
            pos[3 * (4 * j + i) + 1] = y;
            pos[3 * (4 * j + i) + 2] = 0.3 * x * y - 0.1;
        }
    pos[48] = pos[0]; /* vertex 16 where vertex 0 is */
    pos[49] = pos[1];
    pos[50] = pos[2];
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            plateau_index a = (plateau_index)(4 * j + i);
            tri[t++] = a; tri[t++] = a + 1; tri[t++] = a + 5;
            tri[t++] = a; tri[t++] = a + 5; tri[t++] = a + 4;
        }
    tri[t++] = 0; tri[t++] = 16; tri[t++] = 1;
}

/* The facet i of the mesh as STL holds it: the normal (double, to compare
 * within float rounding) and the corners as floats. */
static void stl_expect(const double *pos, const plateau_index *tri, size_t i, double n[3], float c[9])
{
    const double *a = pos + 3 * tri[3 * i], *b = pos + 3 * tri[3 * i + 1], *d = pos + 3 * tri[3 * i + 2];
    double e1[3], e2[3], len;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = d[k] - a[k];
        c[k] = (float)a[k];
        c[3 + k] = (float)b[k];
        c[6 + k] = (float)d[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (k = 0; k < 3; k++) n[k] = len > 0.0 ? n[k] / len : 0.0;
}

static float stl_le_float(const unsigned char *b)
{
    uint32_t u = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* Reads a binary STL back: 1 when every facet is the mesh's. */
static int stl_check_binary(const unsigned char *data, size_t len, const double *pos, const plateau_index *tri,
                            size_t nt)
{
    size_t i;
    int k, ok = 1;
    if (len != 84 + 50 * nt || strncmp((const char *)data, "solid", 5) == 0) return 0;
    if ((size_t)data[80] + ((size_t)data[81] << 8) + ((size_t)data[82] << 16) + ((size_t)data[83] << 24) != nt)
        return 0;
    for (i = 0; i < nt; i++) {
        const unsigned char *r = data + 84 + 50 * i;
        double n[3];
        float c[9];
        stl_expect(pos, tri, i, n, c);
        for (k = 0; k < 3; k++) ok &= fabs(stl_le_float(r + 4 * k) - n[k]) <= 1e-6;
        for (k = 0; k < 9; k++) ok &= stl_le_float(r + 12 + 4 * k) == c[k];
        ok &= r[48] == 0 && r[49] == 0;
    }
    return ok;
}

/* Reads an ASCII STL back: 1 when every facet is the mesh's, in the
 * grammar of the format. */
static int stl_check_ascii(char *text, const double *pos, const plateau_index *tri, size_t nt)
{
    static const char *const facet_words[] = {"facet", "normal", "#", "#", "#", "outer", "loop",
                                              "vertex", "#", "#", "#", "vertex", "#", "#", "#",
                                              "vertex", "#", "#", "#", "endloop", "endfacet"};
    char *tok = strtok(text, " \n");
    size_t i;
    int ok = tok && strcmp(tok, "solid") == 0;
    tok = strtok(NULL, " \n");
    ok &= tok && strcmp(tok, "plateau") == 0;
    for (i = 0; i < nt && ok; i++) {
        double n[3], v[12];
        float c[9];
        int w, nv = 0;
        stl_expect(pos, tri, i, n, c);
        for (w = 0; w < 21 && ok; w++) {
            tok = strtok(NULL, " \n");
            if (!tok) ok = 0;
            else if (facet_words[w][0] == '#') v[nv++] = strtod(tok, NULL);
            else ok &= strcmp(tok, facet_words[w]) == 0;
        }
        for (w = 0; w < 3 && ok; w++) ok &= fabs(v[w] - n[w]) <= 1e-6;
        for (w = 0; w < 9 && ok; w++) ok &= (float)v[3 + w] == c[w];
    }
    tok = strtok(NULL, " \n");
    ok &= tok && strcmp(tok, "endsolid") == 0;
    tok = strtok(NULL, " \n");
    ok &= tok && strcmp(tok, "plateau") == 0 && strtok(NULL, " \n") == NULL;
    return ok;
}

/* A tiny PLY reader (ASCII, the header's vertex properties by name): the
 * value of the vertex property named prop for each vertex into out (at
 * most max); returns the vertex count, or -1 when the header lacks the
 * element or the property. */
static long ply_vertex_property(const char *text, const char *prop, double *out, long max)
{
    char line[256], name[64], type[32];
    const char *s = text;
    long count = -1, v;
    int in_vertex = 0, nprops = 0, at = -1;
    for (;;) { /* the header, a line at a time */
        size_t n = strcspn(s, "\n");
        long c;
        if (!s[0] || n >= sizeof line) return -1;
        memcpy(line, s, n);
        line[n] = '\0';
        s += n + (s[n] == '\n');
        if (strcmp(line, "end_header") == 0) break;
        if (sscanf(line, "element %63s %ld", name, &c) == 2) {
            in_vertex = strcmp(name, "vertex") == 0;
            if (in_vertex) count = c;
        } else if (in_vertex && sscanf(line, "property %31s %63s", type, name) == 2) {
            if (strcmp(name, prop) == 0) at = nprops;
            nprops++;
        }
    }
    if (count < 0 || at < 0 || count > max) return -1;
    for (v = 0; v < count; v++) { /* the vertex lines come first */
        int k;
        for (k = 0; k < nprops; k++) {
            char *end;
            double x = strtod(s, &end);
            if (end == s) return -1;
            if (k == at) out[v] = x;
            s = end;
        }
    }
    return count;
}

/* A 3 x 3 grid of vertices in z = 0.1 x y, 8 triangles; vertex 1 on the
 * bottom edge marked as a cable's (anchors 0 and 2). */
static void grid3(double *p, plateau_index *t)
{
    int i, j, k = 0;
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            p[3 * (3 * j + i)] = i;
            p[3 * (3 * j + i) + 1] = j;
            p[3 * (3 * j + i) + 2] = 0.1 * i * j;
        }
    for (j = 0; j < 2; j++)
        for (i = 0; i < 2; i++) {
            int a = 3 * j + i;
            t[k++] = a;
            t[k++] = a + 1;
            t[k++] = a + 4;
            t[k++] = a;
            t[k++] = a + 4;
            t[k++] = a + 3;
        }
}

/* plateau_write_mesh_marked: PLY carries each vertex's mark as the vertex
 * property "boundary" (a PLY reader sees it: 0 interior, 1 boundary, 2
 * cable), computed from the triangles when no marks are given; OBJ holds
 * group "boundary" with a closed polyline over the loop and group
 * "cables" with the cable from anchor to anchor, and reads back through
 * plateau_parse_mesh as the same mesh, bit for bit; OFF and STL are the
 * files of plateau_write_mesh_format; a bad mark and every refused
 * allocation come before anything is written. */
static void test_write_marked(void)
{
    static const unsigned char marks[9] = {1, 2, 1, 1, 0, 1, 1, 1, 1};
    double p[27], got[16], *q = NULL;
    plateau_index t[24], *qt = NULL;
    unsigned char bad[9];
    size_t nv = 0, nt = 0, len, len2, i;
    char *text, *text2;
    countalloc ca;
    plateau_allocator a;
    plateau_error err;
    long k;
    grid3(p, t);
    CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("g.ply"), p, 9, t, 8, marks, PLATEAU_MESH_FORMAT_AUTO, NULL, &err),
                 PLATEAU_OK);
    text = harness_slurp(tmp_path("g.ply"), &len);
    CHECK(text && ply_vertex_property(text, "boundary", got, 16) == 9);
    for (i = 0; i < 9; i++) CHECK(got[i] == (double)marks[i]);
    CHECK(text && ply_vertex_property(text, "z", got, 16) == 9 && got[8] == 0.4);
    free(text);
    CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("h.ply"), p, 9, t, 8, NULL, PLATEAU_MESH_FORMAT_PLY, NULL, &err),
                 PLATEAU_OK);
    text = harness_slurp(tmp_path("h.ply"), &len);
    CHECK(text && ply_vertex_property(text, "boundary", got, 16) == 9);
    for (i = 0; i < 9; i++) CHECK(got[i] == (i == 4 ? 0.0 : 1.0));
    free(text);
    /* OBJ: the loop, the cable, and the same mesh read back */
    CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("g.obj"), p, 9, t, 8, marks, PLATEAU_MESH_FORMAT_AUTO, NULL, &err),
                 PLATEAU_OK);
    text = harness_slurp(tmp_path("g.obj"), &len);
    CHECK(text && strstr(text, "\ng film\nf 1 2 5\n") != NULL);
    CHECK(text && strstr(text, "\ng boundary\nl 1 2 3 6 9 8 7 4 1\ng cables\nl 1 2 3\n") != NULL);
    CHECK_EQ_INT(plateau_parse_mesh(text, len, NULL, &q, &nv, &qt, &nt, NULL, &err), PLATEAU_OK);
    CHECK(nv == 9 && nt == 8 && q && qt && memcmp(q, p, sizeof p) == 0 && memcmp(qt, t, sizeof t) == 0);
    plateau_mesh_arrays_free(q, qt, NULL, NULL);
    free(text);
    /* without marks: the loop, no cables */
    CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("h.obj"), p, 9, t, 8, NULL, PLATEAU_MESH_FORMAT_AUTO, NULL, &err),
                 PLATEAU_OK);
    text = harness_slurp(tmp_path("h.obj"), &len);
    CHECK(text && strstr(text, "\ng boundary\nl 1 2 3 6 9 8 7 4 1\n") != NULL && strstr(text, "cables") == NULL);
    free(text);
    /* a cable all round the loop but one anchor, and a loop of two rings */
    {
        static const unsigned char ring[9] = {1, 2, 2, 2, 0, 2, 2, 2, 2};
        CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("r.obj"), p, 9, t, 8, ring, PLATEAU_MESH_FORMAT_OBJ, NULL,
                                               &err), PLATEAU_OK);
        text = harness_slurp(tmp_path("r.obj"), &len);
        CHECK(text && strstr(text, "\ng cables\nl 1 2 3 6 9 8 7 4 1\n") != NULL);
        free(text);
        remove(tmp_path("r.obj"));
    }
    {   /* two loops: the annulus of a 4 x 4 grid without its middle square */
        double ap[48];
        plateau_index at[48];
        int i2, j2, n2 = 0;
        for (j2 = 0; j2 < 4; j2++)
            for (i2 = 0; i2 < 4; i2++) {
                ap[3 * (4 * j2 + i2)] = i2;
                ap[3 * (4 * j2 + i2) + 1] = j2;
                ap[3 * (4 * j2 + i2) + 2] = 0.0;
            }
        for (j2 = 0; j2 < 3; j2++)
            for (i2 = 0; i2 < 3; i2++) {
                int c = 4 * j2 + i2;
                if (i2 == 1 && j2 == 1) continue;
                at[n2++] = c, at[n2++] = c + 1, at[n2++] = c + 5;
                at[n2++] = c, at[n2++] = c + 5, at[n2++] = c + 4;
            }
        CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("a.obj"), ap, 16, at, 16, NULL, PLATEAU_MESH_FORMAT_OBJ, NULL,
                                               &err), PLATEAU_OK);
        text = harness_slurp(tmp_path("a.obj"), &len);
        CHECK_MSG(text && strstr(text, "\ng boundary\nl 1 2 3 4 8 12 16 15 14 13 9 5 1\nl 6 10 11 7 6\n") != NULL,
                  text ? text : "no file");
        free(text);
        remove(tmp_path("a.obj"));
    }
    /* OFF and STL: no place for marks, the files of plateau_write_mesh_format */
    for (k = 0; k < 2; k++) {
        const char *name = k ? "g.stl" : "g.off";
        CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path(name), p, 9, t, 8, marks, PLATEAU_MESH_FORMAT_AUTO, NULL,
                                               &err), PLATEAU_OK);
        text = harness_slurp(tmp_path(name), &len);
        CHECK_EQ_INT(plateau_write_mesh(tmp_path(name), p, 9, t, 8, &err), PLATEAU_OK);
        text2 = harness_slurp(tmp_path(name), &len2);
        CHECK(text && text2 && len == len2 && memcmp(text, text2, len) == 0);
        free(text);
        free(text2);
        remove(tmp_path(name));
    }
    /* a mark above 2: refused, nothing written */
    memcpy(bad, marks, sizeof bad);
    bad[7] = 3;
    remove(tmp_path("g.obj"));
    CHECK_EQ_INT(plateau_write_mesh_marked(tmp_path("g.obj"), p, 9, t, 8, bad, PLATEAU_MESH_FORMAT_AUTO, NULL, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK(err.index == 7 && strstr(err.message, "vertex 7 has mark 3") != NULL);
    CHECK(harness_slurp(tmp_path("g.obj"), &len) == NULL);
    /* every allocation refused in turn: out of memory, nothing written or left */
    remove(tmp_path("g.ply"));
    for (k = 1; k <= 5; k++) {
        plateau_result r;
        countalloc_init(&ca, k);
        a = countalloc_allocator(&ca);
        r = plateau_write_mesh_marked(tmp_path("g.ply"), p, 9, t, 8, NULL, PLATEAU_MESH_FORMAT_PLY, &a, &err);
        CHECK(r == (ca.refused ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_OK));
        CHECK(ca.live == 0 && ca.bad == 0);
        if (ca.refused) CHECK(harness_slurp(tmp_path("g.ply"), &len) == NULL);
        remove(tmp_path("g.ply"));
    }
    remove(tmp_path("h.ply"));
    remove(tmp_path("h.obj"));
}

/* plateau_mesh_vertex_marks: boundary edges' vertices fixed 1 or free 2
 * (a cable's), the others 0; a mesh without adjacency is refused. */
static void test_vertex_marks(void)
{
    double p[27];
    plateau_index t[24];
    unsigned char marks[9];
    plateau_mesh mesh;
    plateau_error err;
    size_t i;
    grid3(p, t);
    CHECK_EQ_INT(plateau_mesh_create(p, 9, NULL, t, 8, NULL, &mesh, &err), PLATEAU_OK);
    mesh.fixed[1] = 0;
    CHECK_EQ_INT(plateau_mesh_vertex_marks(&mesh, marks, &err), PLATEAU_OK);
    for (i = 0; i < 9; i++) CHECK_EQ_INT(marks[i], i == 4 ? 0 : i == 1 ? 2 : 1);
    CHECK_EQ_INT(plateau_mesh_vertex_marks(&mesh, NULL, &err), PLATEAU_ERR_ARGUMENT);
    plateau_mesh_free(&mesh);
    CHECK_EQ_INT(plateau_mesh_vertex_marks(&mesh, marks, &err), PLATEAU_ERR_ARGUMENT);
}

/* STL, binary (by the extension ".stl", or asked for) and ASCII: parsed
 * back, every facet is the mesh's triangle (its corners as floats, its
 * unit normal); the checks before opening; admesh, when installed, reads
 * both without an error and counts the facets. */
static void test_write_stl(void)
{
    double pos[3 * STL_NV];
    plateau_index tri[3 * STL_NT];
    plateau_error err;
    char *text;
    size_t len = 0;
    int have_admesh = system("command -v admesh >/dev/null 2>&1") == 0, form;
    stl_mesh(pos, tri);
    for (form = 0; form < 3; form++) {
        char path[600], report[600]; /* tmp_path reuses its buffer */
        strcpy(path, tmp_path(form == 0 ? "mesh.STL" : form == 1 ? "mesh.bin" : "ascii.stl"));
        strcpy(report, tmp_path("admesh.txt"));
        plateau_mesh_format f = form == 0 ? PLATEAU_MESH_FORMAT_AUTO
                                : form == 1 ? PLATEAU_MESH_FORMAT_STL : PLATEAU_MESH_FORMAT_STL_ASCII;
        CHECK_EQ_INT(plateau_write_mesh_format(path, pos, STL_NV, tri, STL_NT, f, &err), PLATEAU_OK);
        CHECK_EQ_INT(err.code, PLATEAU_OK);
        text = harness_slurp(path, &len);
        if (!CHECK(text != NULL)) continue;
        if (form < 2) CHECK(stl_check_binary((const unsigned char *)text, len, pos, tri, STL_NT));
        else CHECK(stl_check_ascii(text, pos, tri, STL_NT));
        free(text);
        if (have_admesh && form != 1) {
            char cmd[1300], *out;
            size_t olen;
            int rc;
            sprintf(cmd, "admesh -e -d -v %s > %s 2>&1", path, report);
            rc = system(cmd);
            CHECK_EQ_INT(rc, 0);
            out = harness_slurp(report, &olen);
            if (CHECK(out != NULL) &&
                CHECK_MSG(strstr(out, "Number of facets") != NULL && strstr(out, ":    19") != NULL, out) &&
                CHECK_MSG(strstr(out, "rror") == NULL, out))
                printf("admesh read %s: 19 facets, no error\n", form == 0 ? "binary STL" : "ASCII STL");
            free(out);
            remove(report);
        }
        remove(path);
    }
    if (!have_admesh) printf("admesh: skipped (not installed)\n");
    /* plateau_write_mesh takes .stl as binary STL too */
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("plain.stl"), pos, STL_NV, tri, STL_NT, &err), PLATEAU_OK);
    text = harness_slurp(tmp_path("plain.stl"), &len);
    CHECK(text && stl_check_binary((const unsigned char *)text, len, pos, tri, STL_NT));
    free(text);
    remove(tmp_path("plain.stl"));
    /* beyond the float range: refused before the file is opened */
    CHECK_EQ_INT(plateau_write_mesh_format(tmp_path("far.stl"), mesh_pos, 5, mesh_tri, 4,
                                           PLATEAU_MESH_FORMAT_STL_ASCII, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 2);
    CHECK(harness_slurp(tmp_path("far.stl"), &len) == NULL);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("far.stl"), mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(plateau_write_mesh_format(tmp_path("far.obj"), mesh_pos, 5, mesh_tri, 4,
                                           PLATEAU_MESH_FORMAT_OBJ, &err), PLATEAU_OK);
    remove(tmp_path("far.obj"));
    CHECK_EQ_INT(plateau_write_mesh_format(tmp_path("x.stl"), pos, STL_NV, tri, STL_NT,
                                           (plateau_mesh_format)6, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh_format(tmp_path("x.stl"), pos, STL_NV, tri, STL_NT,
                                           (plateau_mesh_format)-1, &err), PLATEAU_ERR_ARGUMENT);
    /* an empty mesh: a header and a zero count */
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("empty.stl"), NULL, 0, NULL, 0, &err), PLATEAU_OK);
    text = harness_slurp(tmp_path("empty.stl"), &len);
    CHECK(text && stl_check_binary((const unsigned char *)text, len, pos, tri, 0));
    free(text);
    remove(tmp_path("empty.stl"));
    /* a directory that does not exist: PLATEAU_ERR_IO */
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("no/such/dir.stl"), pos, STL_NV, tri, STL_NT, &err), PLATEAU_ERR_IO);
}

static void test_write_errors(void)
{
    plateau_error err;
    plateau_index bad[3] = {0, 1, 5};
    double nan_pos[15];
    FILE *f;
    memcpy(nan_pos, mesh_pos, sizeof nan_pos);
    nan_pos[7] = NAN;
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("x.wrl"), mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("obj"), mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("x.obj.d/mesh"), mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh(NULL, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("x.obj"), NULL, 5, mesh_tri, 4, &err), PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("x.obj"), mesh_pos, 5, bad, 1, &err), PLATEAU_ERR_INDEX_RANGE);
    CHECK_EQ_INT(err.index, 0);
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("x.obj"), nan_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_NOT_FINITE);
    CHECK_EQ_INT(err.index, 2);
    /* nothing was created by the refused calls */
    f = fopen(tmp_path("x.obj"), "rb");
    CHECK(f == NULL);
    if (f) fclose(f);
    /* unwritable: a directory that does not exist */
    CHECK_EQ_INT(plateau_write_mesh(tmp_path("no/such/dir/mesh.obj"), mesh_pos, 5, mesh_tri, 4, &err),
                 PLATEAU_ERR_IO);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_IO);
    CHECK(strstr(err.message, "mesh.obj") != NULL);
    CHECK_EQ_INT(plateau_write_svg(tmp_path("no/such/dir/mesh.svg"), mesh_pos, 5, mesh_tri, 4, NULL, NULL, &err),
                 PLATEAU_ERR_IO);
}

/* A file of the given text at path. */
static void put_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* 1 when the file at path holds exactly text. */
static int holds(const char *path, const char *text)
{
    size_t len = 0;
    char *got = harness_slurp(path, &len);
    int same = got && len == strlen(text) && memcmp(got, text, len) == 0;
    free(got);
    return same;
}

/* 1 when no temporary of path (path.tmp0 .. path.tmpf) is left */
static int no_temporary(const char *path)
{
    char name[600];
    int k;
    if (strlen(path) > 512) return 0;
    for (k = 0; k < 16; k++) {
        FILE *f;
        sprintf(name, "%.512s.tmp%c", path, k < 10 ? '0' + k : 'a' + k - 10);
        f = fopen(name, "rb");
        if (f) {
            fclose(f);
            return 0;
        }
    }
    return 1;
}

/* The writers replace a file only by a whole one.  An existing target keeps
 * its contents, and no temporary is left, when no temporary can be made
 * (all 16 names taken by directories), when a write fails (a child process
 * with a file size limit of 64 bytes: its writes fail with EFBIG), and when
 * the rename fails (the target is a directory); a good write replaces it.
 * A symbolic link given as the path is replaced by the new file, and the
 * file it pointed to keeps its contents. */
static void test_write_never_loses_a_file(void)
{
    const char *old_text = "# the file that was there\n";
    char target[520], name[600], link_target[520];
    plateau_error err;
    int k, status = -1;
    pid_t pid;
    strcpy(target, tmp_path("kept.obj"));
    /* a good write over an existing file */
    put_text(target, old_text);
    CHECK_EQ_INT(plateau_write_mesh(target, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_OK);
    CHECK(!holds(target, old_text));
    CHECK(no_temporary(target));
    /* no temporary can be made */
    put_text(target, old_text);
    for (k = 0; k < 16; k++) {
        sprintf(name, "%.512s.tmp%c", target, k < 10 ? '0' + k : 'a' + k - 10);
        mkdir(name, 0700);
    }
    CHECK_EQ_INT(plateau_write_mesh(target, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_IO);
    CHECK(strstr(err.message, "temporary") != NULL);
    CHECK_EQ_INT(plateau_write_svg(target, mesh_pos, 5, mesh_tri, 4, NULL, NULL, &err), PLATEAU_ERR_IO);
    CHECK(holds(target, old_text));
    for (k = 0; k < 16; k++) {
        sprintf(name, "%.512s.tmp%c", target, k < 10 ? '0' + k : 'a' + k - 10);
        rmdir(name);
    }
    /* a write fails: the size limit of a child process */
    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid == 0) {
        struct rlimit rl;
        plateau_result r1, r2;
        signal(SIGXFSZ, SIG_IGN);
        rl.rlim_cur = rl.rlim_max = 64;
        if (setrlimit(RLIMIT_FSIZE, &rl) != 0) _exit(3);
        r1 = plateau_write_mesh(target, mesh_pos, 5, mesh_tri, 4, NULL);
        r2 = plateau_write_svg(target, mesh_pos, 5, mesh_tri, 4, NULL, NULL, NULL);
        _exit(r1 == PLATEAU_ERR_IO && r2 == PLATEAU_ERR_IO ? 0 : 1);
    }
    if (pid > 0) waitpid(pid, &status, 0);
    CHECK(pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0);
    CHECK(holds(target, old_text));
    CHECK(no_temporary(target));
    /* the rename fails: the target is a directory (it stays one) */
    strcpy(name, tmp_path("dir.obj"));
    CHECK_EQ_INT(mkdir(name, 0700), 0);
    CHECK_EQ_INT(plateau_write_mesh(name, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_ERR_IO);
    CHECK(strstr(err.message, "left as it was") != NULL);
    CHECK(no_temporary(name));
    CHECK_EQ_INT(rmdir(name), 0);
    /* a symbolic link: replaced, its target untouched */
    strcpy(link_target, tmp_path("pointed.obj"));
    put_text(link_target, old_text);
    strcpy(name, tmp_path("link.obj"));
    if (symlink(link_target, name) == 0) {
        struct stat st;
        CHECK_EQ_INT(plateau_write_mesh(name, mesh_pos, 5, mesh_tri, 4, &err), PLATEAU_OK);
        CHECK(lstat(name, &st) == 0 && S_ISREG(st.st_mode));
        CHECK(holds(link_target, old_text));
        remove(name);
    }
    remove(link_target);
    remove(target);
}

static void test_svg(void)
{
    plateau_error err;
    char *text;
    size_t len = 0, polygons = 0;
    const char *p;
    double zero[3] = {0, 0, 0}, down[3] = {0, 0, -1};
    CHECK_EQ_INT(plateau_write_svg(tmp_path("mesh.svg"), mesh_pos, 4, mesh_tri, 4, NULL, NULL, &err), PLATEAU_OK);
    text = harness_slurp(tmp_path("mesh.svg"), &len);
    CHECK(text != NULL);
    if (text) {
        CHECK(strncmp(text, "<svg", 4) == 0);
        CHECK(strstr(text, "viewBox=\"") != NULL);
        for (p = text; (p = strstr(p, "<polygon ")) != NULL; p++) polygons++;
        CHECK_EQ_INT(polygons, 4);
        CHECK(len > 7 && strcmp(text + len - 7, "</svg>\n") == 0);
        CHECK(strstr(text, "nan") == NULL && strstr(text, "inf") == NULL);
    }
    free(text);
    /* same input, same picture; a view straight down works too */
    {
        char *again;
        size_t len2 = 0;
        CHECK_EQ_INT(plateau_write_svg(tmp_path("mesh2.svg"), mesh_pos, 4, mesh_tri, 4, NULL, NULL, &err), PLATEAU_OK);
        text = harness_slurp(tmp_path("mesh.svg"), &len);
        again = harness_slurp(tmp_path("mesh2.svg"), &len2);
        CHECK(text && again && len == len2 && memcmp(text, again, len) == 0);
        free(text);
        free(again);
        CHECK_EQ_INT(plateau_write_svg(tmp_path("mesh2.svg"), mesh_pos, 4, mesh_tri, 4, down, NULL, &err), PLATEAU_OK);
    }
    CHECK_EQ_INT(plateau_write_svg(tmp_path("mesh3.svg"), mesh_pos, 4, mesh_tri, 4, zero, NULL, &err), PLATEAU_ERR_ARGUMENT);
    remove(tmp_path("mesh.svg"));
    remove(tmp_path("mesh2.svg"));
}

/* The SVG writer allocates through the allocator it is given: a counting
 * allocator sees every block come and go, the picture is the one written
 * with the default allocator, a refused block is PLATEAU_ERR_OUT_OF_MEMORY with
 * no file left behind, and an allocator with one function is refused. */
static void test_svg_allocator(void)
{
    countalloc ca;
    plateau_allocator a;
    plateau_error err;
    char *with_default, *with_counter;
    size_t l1 = 0, l2 = 0;
    FILE *f;
    long lost = countalloc_lost_context;
    countalloc_init(&ca, 0);
    a = countalloc_allocator(&ca);
    CHECK_EQ_INT(plateau_write_svg(tmp_path("a0.svg"), mesh_pos, 4, mesh_tri, 4, NULL, NULL, &err),
                 PLATEAU_OK);
    CHECK_EQ_INT(plateau_write_svg(tmp_path("a1.svg"), mesh_pos, 4, mesh_tri, 4, NULL, &a, &err),
                 PLATEAU_OK);
    CHECK_EQ_INT(err.code, PLATEAU_OK);
    CHECK(ca.calls >= 1);          /* the depth-order array came from it */
    CHECK_EQ_INT(ca.live, 0);      /* and went back to it */
    CHECK_EQ_INT(ca.frees, ca.calls);
    CHECK_EQ_INT(ca.bad, 0);
    CHECK_EQ_INT(countalloc_lost_context, lost); /* user_data passed through */
    with_default = harness_slurp(tmp_path("a0.svg"), &l1);
    with_counter = harness_slurp(tmp_path("a1.svg"), &l2);
    CHECK(with_default && with_counter && l1 == l2 && memcmp(with_default, with_counter, l1) == 0);
    free(with_default);
    free(with_counter);
    /* the first block refused: out of memory, before the file is opened */
    countalloc_init(&ca, 1);
    CHECK_EQ_INT(plateau_write_svg(tmp_path("a2.svg"), mesh_pos, 4, mesh_tri, 4, NULL, &a, &err),
                 PLATEAU_ERR_OUT_OF_MEMORY);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_OUT_OF_MEMORY);
    CHECK_EQ_INT(ca.refused, 1);
    CHECK_EQ_INT(ca.live, 0);
    f = fopen(tmp_path("a2.svg"), "rb");
    CHECK(f == NULL);
    if (f) fclose(f);
    /* one function without the other */
    a.free_fn = NULL;
    CHECK_EQ_INT(plateau_write_svg(tmp_path("a3.svg"), mesh_pos, 4, mesh_tri, 4, NULL, &a, &err),
                 PLATEAU_ERR_ARGUMENT);
    CHECK_EQ_INT(err.code, PLATEAU_ERR_ARGUMENT);
    /* all-zero: the default allocator, like NULL */
    memset(&a, 0, sizeof a);
    CHECK_EQ_INT(plateau_write_svg(tmp_path("a3.svg"), mesh_pos, 4, mesh_tri, 4, NULL, &a, &err),
                 PLATEAU_OK);
    remove(tmp_path("a0.svg"));
    remove(tmp_path("a1.svg"));
    remove(tmp_path("a3.svg"));
}

/* Painter's order: of two stacked triangles seen from above, the upper one
 * is drawn last. */
static void test_svg_order(void)
{
    plateau_index tri[6] = {0, 1, 2, 3, 4, 5};
    double down[3] = {0, 0, -1};
    {
        /* a distinguishing case: a tilted far triangle, a flat near one */
        double pos2[18] = {0, 0, 0, 1, 0, 0.5, 0, 1, 0, 0, 0, 5, 1, 0, 5, 0, 1, 5};
        char *t1, *t2;
        size_t l1 = 0, l2 = 0;
        const char *a, *b;
        double up[3] = {0, 0, 1};
        CHECK_EQ_INT(plateau_write_svg(tmp_path("order.svg"), pos2, 6, tri, 2, down, NULL, NULL), PLATEAU_OK);
        t1 = harness_slurp(tmp_path("order.svg"), &l1);
        CHECK_EQ_INT(plateau_write_svg(tmp_path("order2.svg"), pos2, 6, tri, 2, up, NULL, NULL), PLATEAU_OK);
        t2 = harness_slurp(tmp_path("order2.svg"), &l2);
        CHECK(t1 && t2);
        if (t1 && t2) {
            /* fill colours: the tilted triangle 0 has a different shade
             * from the flat triangle 1; looking down, 0 (z <= 0.5) is far
             * and comes first; looking up, it comes last */
            const char *f1 = strstr(t1, "fill=\""), *f2 = strstr(t2, "fill=\"");
            a = f1 ? strstr(f1 + 1, "fill=\"") : NULL;
            b = f2 ? strstr(f2 + 1, "fill=\"") : NULL;
            CHECK(f1 && f2 && a && b);
            if (f1 && f2 && a && b) {
                CHECK(strncmp(f1, a, 13) != 0);
                CHECK(strncmp(f1, b, 13) == 0); /* down's first = up's last */
                CHECK(strncmp(a, f2, 13) == 0);
            }
        }
        free(t1);
        free(t2);
    }
    remove(tmp_path("order.svg"));
    remove(tmp_path("order2.svg"));
}

/* Review: the picture of a mesh scaled by a power of two is the same file.
 * At 2^1000 the edge cross products overflowed (a NaN shade went through
 * (int) into fill="#800000008000000080000000"), at 2^-1000 their squares
 * underflowed (every triangle the flat shade). */
static void test_svg_scale(void)
{
    static const double base[12] = {0, 0, 0, 1, 0, 0.2, 0.3, 1, 0.5, 0.6, 0.4, 1.1};
    static const int powers[4] = {1000, -1000, 1020, -1040};
    double pos[12];
    char *ref, *text;
    size_t len = 0, len2 = 0, i, s;
    plateau_error err;
    CHECK_EQ_INT(plateau_write_svg(tmp_path("scale0.svg"), base, 4, mesh_tri, 4, NULL, NULL, &err),
                 PLATEAU_OK);
    ref = harness_slurp(tmp_path("scale0.svg"), &len);
    CHECK(ref != NULL);
    for (s = 0; s < 4 && ref; s++) {
        for (i = 0; i < 12; i++) pos[i] = ldexp(base[i], powers[s]);
        CHECK_EQ_INT(plateau_write_svg(tmp_path("scale1.svg"), pos, 4, mesh_tri, 4, NULL, NULL, &err),
                     PLATEAU_OK);
        text = harness_slurp(tmp_path("scale1.svg"), &len2);
        if (!CHECK(text != NULL && len2 == len && memcmp(text, ref, len) == 0))
            printf("  scale 2^%d:\n%s\n", powers[s], text ? text : "(none)");
        free(text);
    }
    free(ref);
    remove(tmp_path("scale0.svg"));
    remove(tmp_path("scale1.svg"));
}

int main(void)
{
    sprintf(tmp_dir, "/tmp/plateau_test_io_%ld", (long)getpid());
    if (mkdir(tmp_dir, 0700) != 0) {
        fprintf(stderr, "cannot create %s\n", tmp_dir);
        return 1;
    }
    RUN(test_parse_good);
    RUN(test_parse_closing_and_lines);
    RUN(test_parse_errors);
    RUN(test_parse_csv);
    RUN(test_parse_allocator);
    RUN(test_read_file);
    RUN(test_read_size_cap);
    RUN(test_parse_blank_lines_bounded);
    RUN(test_parse_mesh_good);
    RUN(test_parse_mesh_errors);
    RUN(test_read_mesh_file);
    RUN(test_write_formats);
    RUN(test_write_errors);
    RUN(test_write_stl);
    RUN(test_write_marked);
    RUN(test_vertex_marks);
    RUN(test_write_never_loses_a_file);
    RUN(test_svg);
    RUN(test_svg_order);
    RUN(test_svg_allocator);
    RUN(test_svg_scale);
    rmdir(tmp_dir);
    return harness_report("test_io");
}
