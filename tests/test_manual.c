/* test_manual.c - the manual at the top of plateau.h says what it shows:
 * its EXAMPLE, taken out of the comment, compiled with the compiler that
 * built this test and run, prints what the comment says it prints; the
 * numbers the manual and the comments give for the defaults, the memory
 * estimate, the catenoid's limits and the solver's constants are the
 * code's (the private constants are visible here because this file
 * compiles the implementation), and so is the angle bound of
 * plateau_delaunay.h's manual.  Run from the repository's root, as make
 * test does: it reads plateau.h and writes its scratch files next to this
 * binary. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "harness.h"

#include <ctype.h>
#include <math.h>

#if defined(__clang__)
#define MANUAL_CC "clang"
#else
#define MANUAL_CC "cc"
#endif

/* The whole of a file, NUL-terminated (NULL when it cannot be read). */
static char *manual_read(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    long size;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        text = (char *)malloc((size_t)size + 1);
        if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
            free(text);
            text = NULL;
        }
        if (text) text[size] = '\0';
    }
    fclose(f);
    return text;
}

/* Copies the comment lines after the line starting with `start` up to the
 * line starting with `stop` (or the first line that is not indented by
 * "prefix" when stop is NULL) into out, without their prefix " *     "
 * (a bare " *" is an empty line).  Returns the number of lines, -1 when
 * start is missing. */
static int manual_block(const char *text, const char *start, const char *stop, char *out,
                        size_t size)
{
    const char *p = strstr(text, start), *line;
    size_t used = 0;
    int lines = 0;
    if (!p) return -1;
    line = strchr(p, '\n');
    out[0] = '\0';
    while (line && *++line) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line), skip;
        if (stop && strncmp(line, stop, strlen(stop)) == 0) break;
        if (len >= 7 && strncmp(line, " *     ", 7) == 0) skip = 7;
        else if (len == 2 && strncmp(line, " *", 2) == 0 && stop) skip = 2;
        else if (stop) return -1; /* a line that is no part of the block */
        else break;
        if (used + len - skip + 2 > size) return -1;
        memcpy(out + used, line + skip, len - skip);
        used += len - skip;
        out[used++] = '\n';
        out[used] = '\0';
        lines++;
        line = end;
    }
    return lines;
}

/* The directory of this binary (argv[0]): where the example is built. */
static void manual_dir(const char *argv0, char *dir, size_t size)
{
    const char *slash = strrchr(argv0, '/');
    size_t len = slash ? (size_t)(slash - argv0) : 1;
    if (!slash) argv0 = ".";
    if (len >= size) len = size - 1;
    memcpy(dir, argv0, len);
    dir[len] = '\0';
}

static const char *manual_argv0 = "build/test_manual";

/* The EXAMPLE, compiled verbatim and run: its output is the comment's. */
static void test_example_prints_what_it_says(void)
{
    static char source[16384], expected[4096], cmd[2048], path[1024], dir[512];
    char *header = manual_read("plateau.h"), *output;
    int lines, want, rc;
    FILE *f;
    if (!CHECK_MSG(header != NULL, "plateau.h can be read (run from the repository's root)")) return;
    lines = manual_block(header, " * EXAMPLE", " *   It prints", source, sizeof source);
    want = manual_block(header, " *   It prints", NULL, expected, sizeof expected);
    free(header);
    CHECK(lines > 30);
    CHECK_EQ_INT(want, 3);
    if (lines <= 30 || want <= 0) return;
    manual_dir(manual_argv0, dir, sizeof dir);
    sprintf(path, "%s/manual_example.c", dir);
    f = fopen(path, "w");
    if (!CHECK_MSG(f != NULL, "the example's source can be written")) return;
    fputs(source, f);
    fclose(f);
    /* -O2 as a user builds it (make test-full); make test compiles it at
     * -O0, several times faster, with the same front-end warnings */
    sprintf(cmd, "%s -std=c99 -pedantic -Wall -Wextra -Werror %s -I. -o %s/manual_example %s -lm",
            MANUAL_CC, HARNESS_FULL ? "-O2" : "-O0", dir, path);
    rc = system(cmd);
    if (!CHECK_MSG(rc == 0, "the EXAMPLE compiles without a warning")) {
        printf("  failed: %s\n", cmd);
        return;
    }
    sprintf(cmd, "cd %s && ./manual_example > manual_example.out 2>&1", dir);
    rc = system(cmd);
    CHECK_MSG(rc == 0, "the EXAMPLE exits with 0");
    sprintf(path, "%s/manual_example.out", dir);
    output = manual_read(path);
    if (!CHECK(output != NULL)) return;
    if (!CHECK_MSG(strcmp(output, expected) == 0, "the EXAMPLE prints what the manual says"))
        printf("  the manual says:\n%s  it printed:\n%s", expected, output);
    else
        printf("EXAMPLE (%s): %s", MANUAL_CC, output);
    free(output);
}

/* The defaults of the run-time table (plateau_resolved_options shows them;
 * test_solve.c checks the others). */
static void test_defaults(void)
{
    plateau_options r = plateau_resolved_options(NULL, 24);
    CHECK(r.seed == 20140101u);
    CHECK(r.max_memory == (size_t)1 << 31); /* 2 GiB */
    CHECK_NEAR(r.area_tolerance, 1e-6, 0.0);
    CHECK_NEAR(r.quality_min_angle, 26.0, 0.0);
    CHECK_EQ_INT(PLATEAU_SPARSE_THRESHOLD, 200);
    CHECK_EQ_INT(PLATEAU_PAPER_SPARSE_THRESHOLD, 25);
    CHECK_EQ_INT(PLATEAU_AUTO, 0);
    CHECK(PLATEAU_ON != PLATEAU_OFF && PLATEAU_ON != PLATEAU_AUTO && PLATEAU_OFF != PLATEAU_AUTO);
    /* a fold: neighbours meeting at less than 30 degrees */
    CHECK_NEAR(180.0 - PLATEAU_FOLD_DEGREES, 30.0, 0.0);
    CHECK_NEAR(PLATEAU_DEGENERATE_DEGREES, 1e-6, 0.0);
    CHECK_NEAR(PLATEAU_PINCH_RATIO, 0.2, 0.0);
}

/* plateau_memory_estimate is the formula its comment gives. */
static void test_memory_formula(void)
{
    static const size_t ms[3] = {3, 28, 1000}, ns[4] = {0, 50, 200, 20000};
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            double m = (double)ms[i], n = (double)ns[j], lg = 0.0, x = n + 2.0, sparse;
            while (x > 1.0) { /* ceil(log2(n + 2)) */
                x *= 0.5;
                lg += 1.0;
            }
            sparse = 640.0 * n * lg + 1600.0 * (n + m) + 8192.0;
            CHECK_NEAR(plateau_memory_estimate(PLATEAU_METHOD_PAPER, ms[i], ns[j]),
                       n <= PLATEAU_PAPER_SPARSE_THRESHOLD ? 224.0 * n * n + 3200.0 * (n + m) : sparse, 0.0);
            CHECK_NEAR(plateau_memory_estimate(PLATEAU_METHOD_PAPER_LITERAL, ms[i], ns[j]),
                       48.0 * n * (n + m) + 4500.0 * (n + m), 0.0);
            CHECK_NEAR(plateau_memory_estimate(PLATEAU_METHOD_AREA, ms[i], ns[j]),
                       n <= 200 ? 1000.0 * n + 400.0 * m + 8192.0 : sparse, 0.0);
            /* coarse to fine */
            CHECK_NEAR(plateau__cfg_c2f_estimate(m, n), 64.0 * n * lg + 800.0 * n + 1600.0 * m + 8192.0, 0.0);
        }
}

/* The catenoid between coaxial rings of radius R at distance h:
 * r(z) = a cosh(z / a), R = a cosh(h / (2 a)).  h / R = 2 (a / R)
 * acosh(R / a) is largest, 1.3255, at a neck a / R = 0.5524: the manual's
 * limit of the pinch and PLATEAU_PINCH_RATIO's "waist of at least 0.55". */
static void test_catenoid_limit(void)
{
    double best = 0.0, at = 0.0, s;
    for (s = 0.3; s < 0.999; s += 1e-5) {
        double h = 2.0 * s * log(1.0 / s + sqrt(1.0 / (s * s) - 1.0));
        if (h > best) {
            best = h;
            at = s;
        }
    }
    CHECK_NEAR(best, 1.3255, 5e-5);
    CHECK_NEAR(at, 0.55, 0.005);
    CHECK(PLATEAU_PINCH_RATIO < at);
}

/* plateau_delaunay.h's manual: a skinny triangle left inside an input
 * angle p has angles of at least arctan(sin p / (2 - cos p)), 9.7 degrees
 * for p = 10 and 1.0 for p = 1. */
static void test_delaunay_bound(void)
{
    const double rad = PLATEAU__PI / 180.0;
    CHECK_NEAR(atan(sin(10.0 * rad) / (2.0 - cos(10.0 * rad))) / rad, 9.7, 0.05);
    CHECK_NEAR(atan(sin(1.0 * rad) / (2.0 - cos(1.0 * rad))) / rad, 1.0, 0.05);
    CHECK_EQ_INT(PLATEAU__DT_MAX_MIN_ANGLE, 34);
}

/* The numbers the comments give for the implementation's constants. */
static void test_constants(void)
{
    CHECK_NEAR(PLATEAU__REL_TOL, 1e-9, 0.0);
    CHECK_NEAR(PLATEAU__REL_TOL2, 1e-18, 0.0);
    CHECK_NEAR(PLATEAU__BND_COLLINEAR2, 1e-24, 0.0); /* (1e-12)^2 */
    CHECK_NEAR(PLATEAU__SQRT3_4, sqrt(3.0) / 4.0, 1e-16);
    CHECK_NEAR(PLATEAU__ONE_DEGREE, PLATEAU__PI / 180.0, 0.0);
    CHECK_NEAR(PLATEAU__DEG_PER_RAD, 180.0 / PLATEAU__PI, 1e-13);
    CHECK_NEAR(PLATEAU__DOM_GRID, ldexp(1.0, 36), 0.0);
    CHECK_NEAR(PLATEAU__SEED_TWO_POW_53, ldexp(1.0, 53), 0.0);
    CHECK_NEAR(PLATEAU__CHK_EPS, ldexp(1.0, -53), 0.0);
    /* the area stops (plateau_area_stop's comment) */
    CHECK_NEAR(PLATEAU__AREA_GTOL, 1e-10, 0.0);
    CHECK_NEAR(PLATEAU__LBFGS_SMALL_CHANGE, 1e-10, 0.0);
    CHECK_EQ_INT(PLATEAU__LBFGS_WINDOW, 20);
    CHECK_EQ_INT(PLATEAU__LBFGS_TRIES, 60);
    CHECK_EQ_INT(PLATEAU__NEWTON_WINDOW, 5);
    CHECK_NEAR(PLATEAU__NEWTON_MU_MAX, 1e12, 0.0);
    CHECK_NEAR(PLATEAU__DEFAULT_AREA_TOLERANCE, 1e-6, 0.0);
    /* the rounds end at 3e-5; the default area tolerance is 1/30 of it */
    CHECK_NEAR(PLATEAU__DRV_ROUND_DROP, 3e-5, 0.0);
    CHECK_NEAR(PLATEAU__DRV_ROUND_DROP / 30.0, PLATEAU__DEFAULT_AREA_TOLERANCE, 1e-20);
    /* refine_boundary AUTO: edges over 2 interior spacings; the grading */
    CHECK_NEAR(PLATEAU__SEED_AUTO_REFINE, 2.0, 0.0);
    CHECK_NEAR(PLATEAU__SEED_GRADING, 0.5, 0.0);
    CHECK_EQ_INT(PLATEAU__SEED_SEARCH, 20);
    /* the flips: at most 50 sweeps by default; the vertex removal's 1 degree */
    CHECK_EQ_INT(PLATEAU__RETRI_SWEEPS, 50);
    CHECK_NEAR(PLATEAU__RETRI_MAX_SLIVER_DEG, 60.0, 0.0);
    /* paper-literal: Fig. 5's eps and sqrt(eps) */
    CHECK_NEAR(PLATEAU__SOLVE_FIG5_SQRT_EPS, sqrt(PLATEAU__SOLVE_FIG5_EPS), 1e-18);
    CHECK_NEAR(PLATEAU__CHK_SOLVED_F, 1e-10, 0.0);
    /* MEMBRANES: the held volume's tolerance and its solves, the cables'
     * start half way out along their arcs */
    CHECK_NEAR(PLATEAU__MEMB_VOLUME_TOL, 1e-7, 0.0);
    CHECK_EQ_INT(PLATEAU__MEMB_VOLUME_SOLVES, 40);
    CHECK_EQ_INT(PLATEAU__MEMB_VOLUME_BACKS, 8);
    CHECK_NEAR(PLATEAU__CFG_HELD_VOLUME_TOL, 1e-13, 0.0);
    CHECK_NEAR(PLATEAU__MEMB_CABLE_BOW, 0.5, 0.0);
    CHECK_EQ_INT(PLATEAU_REPORT_CABLES, 16);
    /* COARSE TO FINE: the coarse count, the flip rounds, the reseeding,
     * the stopping rule, the steps and shifts, method paper's last level */
    CHECK_EQ_INT(PLATEAU__C2F_COARSE_MIN, 16);
    CHECK_EQ_INT(PLATEAU__C2F_COARSE_FLIP_ROUNDS, 8);
    CHECK_EQ_INT(PLATEAU__C2F_RESEEDS, 3);
    CHECK_NEAR(PLATEAU__C2F_COUNT_SLACK, 0.03, 0.0);
    CHECK_NEAR(PLATEAU__C2F_TAU, 0.01, 0.0);
    CHECK_NEAR(PLATEAU__C2F_FLOOR, 1e-13, 0.0);
    CHECK_EQ_INT(PLATEAU__C2F_MAX_STEPS, 20);
    CHECK_NEAR(PLATEAU__C2F_SHIFT0, 1e-3, 0.0);
    CHECK_EQ_INT(PLATEAU__C2F_PAPER_STEPS, 8);
    CHECK_NEAR(PLATEAU__C2F_PAPER_F, PLATEAU__CHK_SOLVED_F, 0.0);
    CHECK_EQ_INT(PLATEAU_COARSE_TO_FINE_POINTS, 200);
    /* I_L = 4^L I + B (4^L - 2^L) / 2 - (4^L - 1): I = 16, B = 12, L = 2 */
    CHECK_NEAR(plateau__c2f_coarse(16.0 * 16.0 + 12.0 * 12.0 / 2.0 - 15.0, 12.0, 2), 16.0, 1e-12);
}

/* ---- the numbers of the three manuals (each header's top comment) ----
 * Each number a manual writes with a decimal point or an exponent, or of
 * four digits or more, is checked here against the code's value and
 * printed ("manual plateau.h: 67108864 PLATEAU_DEFAULT_MAX_INPUT_BYTES"),
 * or, where no code has it (a citation's year, a published figure, an
 * input of an example), listed with its source in
 * examples/manual_check.sh, which make readme-check runs on this output. */

/* The top comment of a header: its text up to the first comment end. */
static int manual_top(const char *header, char *out, size_t size)
{
    char *text = manual_read(header), *end;
    size_t len;
    if (!text) return 0;
    end = strstr(text, "*/");
    len = end ? (size_t)(end - text) : strlen(text);
    if (len >= size) len = size - 1;
    memcpy(out, text, len);
    out[len] = '\0';
    free(text);
    return 1;
}

/* True when the manual holds text as a whole number token. */
static int manual_has(const char *manual, const char *text)
{
    const char *p = manual;
    size_t n = strlen(text);
    while ((p = strstr(p, text)) != NULL) {
        char before = p > manual ? p[-1] : ' ', after = p[n];
        if (!isalnum((unsigned char)before) && before != '.' && !isalnum((unsigned char)after) &&
            !(after == '.' && isdigit((unsigned char)p[n + 1])))
            return 1;
        p += n;
    }
    return 0;
}

/* The manual of header writes text for value: text occurs there, and
 * equals value exactly (exact) or to the digits it shows (half a unit of
 * its last digit).  Printed for examples/manual_check.sh. */
static void manual_number(const char *header, const char *manual, const char *text, double value,
                          int exact, const char *what)
{
    char *end;
    double shown = strtod(text, &end), ulp = 1.0;
    const char *dot = strchr(text, '.'), *e = strpbrk(text, "eE");
    int decimals = 0, ex = e ? atoi(e + 1) : 0;
    if (dot) decimals = (int)((e ? e : text + strlen(text)) - dot - 1);
    ulp = pow(10.0, (double)(ex - decimals));
    if (!CHECK_MSG(manual_has(manual, text), text)) printf("  %s's manual does not write %s\n", header, text);
    if (exact) {
        if (!CHECK_MSG(shown == value, what)) printf("  %s: manual %s, code %.17g\n", what, text, value);
    } else if (!CHECK_MSG(fabs(shown - value) <= 0.5 * ulp * (1.0 + 1e-9), what)) {
        printf("  %s: manual %s, code %.17g\n", what, text, value);
    }
    printf("manual %s: %s %s\n", header, text, what);
}

/* A number the test checked by other means (its CHECKs just before). */
static void manual_checked(const char *header, const char *manual, const char *text, const char *what)
{
    if (!CHECK_MSG(manual_has(manual, text), text)) printf("  %s's manual does not write %s\n", header, text);
    printf("manual %s: %s %s\n", header, text, what);
}

static void manual_version(const char *header, const char *manual, const char *version)
{
    CHECK_MSG(manual_has(manual, version), header);
    printf("manual %s: %s version\n", header, version);
}

static char manual_text[65536];

static void test_numbers_plateau(void)
{
    const char *h = "plateau.h";
    double best = 0.0, s;
    plateau_options r = plateau_resolved_options(NULL, 24), ra;
    plateau_options area;
    if (!CHECK(manual_top(h, manual_text, sizeof manual_text))) return;
    memset(&area, 0, sizeof area);
    area.method = PLATEAU_METHOD_AREA;
    ra = plateau_resolved_options(&area, 24);
    manual_version(h, manual_text, PLATEAU_VERSION);
    /* MEMBRANES: the held volume's tolerance */
    manual_number(h, manual_text, "1e-7", PLATEAU__MEMB_VOLUME_TOL, 1, "PLATEAU__MEMB_VOLUME_TOL (held volume)");
    manual_number(h, manual_text, "1e-2", PLATEAU__MEMB_CABLE_BALANCE, 1,
                  "PLATEAU__MEMB_CABLE_BALANCE (cables out of balance)");
    manual_number(h, manual_text, "1e100", PLATEAU__MEMB_PRESSURE_MAX, 1,
                  "PLATEAU__MEMB_PRESSURE_MAX (pressure times radius refused)");
    manual_number(h, manual_text, "6.283185307179586", 2.0 * PLATEAU__PI, 1, "2 pi (the examples' rings)");
    manual_number(h, manual_text, "67108864", (double)PLATEAU_DEFAULT_MAX_INPUT_BYTES, 1,
                  "PLATEAU_DEFAULT_MAX_INPUT_BYTES");
    manual_number(h, manual_text, "1e-6", PLATEAU_DEGENERATE_DEGREES, 1, "PLATEAU_DEGENERATE_DEGREES");
    manual_number(h, manual_text, "1048576", (double)PLATEAU_SEED_MAX_LEVEL_SIZE, 1, "PLATEAU_SEED_MAX_LEVEL_SIZE");
    manual_number(h, manual_text, "20140101", (double)r.seed, 1, "options.seed's default");
    manual_number(h, manual_text, "5000", (double)ra.max_iterations, 1, "max_iterations' default, method area");
    CHECK_EQ_INT(r.max_iterations, 200);
    manual_number(h, manual_text, "1e-6", r.area_tolerance, 1, "area_tolerance's default");
    manual_number(h, manual_text, "3e-5", PLATEAU__DRV_ROUND_DROP, 1, "the rounds' relative drop");
    manual_number(h, manual_text, "1e-3", PLATEAU__C2F_SHIFT0, 1, "coarse to fine: the Cholesky's first shift");
    manual_number(h, manual_text, "1e-13", PLATEAU__C2F_FLOOR, 1, "coarse to fine: the decrement's floor");
    manual_number(h, manual_text, "1e-4", PLATEAU__CFG_COARSE_TOL, 1, "coarse to fine: the coarse mesh's area tolerance");
    manual_number(h, manual_text, "1e-9", PLATEAU__REL_TOL, 1, "the boundary's contact tolerance");
    manual_number(h, manual_text, "1.3", PLATEAU__ACC_MARGIN, 1, "accuracy: the next count's margin");
    manual_number(h, manual_text, "1.5", PLATEAU__ACC_MIN_GROWTH, 1, "accuracy: the next count's least growth");
    manual_number(h, manual_text, "16", PLATEAU__ACC_MAX_GROWTH, 1, "accuracy: the next count's largest growth");
#ifndef PLATEAU_NO_PATTERNS
    manual_number(h, manual_text, "1e-7", PLATEAU__PAT_ARAP_TOL, 1, "cutting patterns: the ARAP iterations' stop");
#endif
    manual_number(h, manual_text, "1e-6", PLATEAU_LM_DEFAULT_TAU, 1, "tau of method paper's LM");
    manual_number(h, manual_text, "1e-6", PLATEAU_LM_DEFAULT_EPS, 1, "eps of method paper's LM");
    /* a unit polygon moved by 1e6: the doubles there are 2^-33 apart, about
     * 1e-10 of its size */
    CHECK(1e6 + ldexp(1.0, -33) != 1e6 && 1e6 + ldexp(1.0, -34) == 1e6);
    manual_checked(h, manual_text, "1e6", "a move the coordinates cannot represent exactly (checked above)");
    manual_number(h, manual_text, "1e-10", ldexp(1.0, -33), 0, "the spacing of the doubles at 1e6");
    /* the catenoid's limit h / R = 2 s acosh(1 / s), largest over the neck s */
    for (s = 0.3; s < 0.999; s += 1e-5) {
        double hr = 2.0 * s * log(1.0 / s + sqrt(1.0 / (s * s) - 1.0));
        if (hr > best) best = hr;
    }
    manual_number(h, manual_text, "1.3255", best, 0, "the largest h / R of a catenoid between coaxial rings");
}

static void test_numbers_lm(void)
{
    const char *h = "plateau_lm.h";
    plateau_lm_options r = plateau_lm_resolved_options(NULL);
    if (!CHECK(manual_top(h, manual_text, sizeof manual_text))) return;
    manual_version(h, manual_text, PLATEAU_LM_VERSION);
    manual_number(h, manual_text, "1e-6", r.tau, 1, "tau's default");
    manual_number(h, manual_text, "1e-6", r.eps, 1, "eps's default");
    manual_number(h, manual_text, "1e-12", r.eps_grad, 1, "eps_grad's default, eps^2");
    CHECK(r.eps_step == r.eps_grad && r.eps_f == r.eps_grad);
    manual_number(h, manual_text, "1000", (double)r.max_iterations, 1, "max_iterations' default");
    manual_number(h, manual_text, "0.75", r.geodesic_ratio, 1, "geodesic_ratio's default");
    manual_number(h, manual_text, "1e300", PLATEAU_LM_MU_LIMIT, 1, "the DAMPING stop's mu");
    manual_number(h, manual_text, "1e-10", PLATEAU_LM_REFINE_SLACK, 1, "the refinement's F slack");
    manual_number(h, manual_text, "0.01", PLATEAU_LM_REFINE_REACH, 1, "the refinement's reach");
    manual_number(h, manual_text, "1e-10", PLATEAU_LM_IRLS_TOL, 1, "the IRLS weights' tolerance");
    manual_number(h, manual_text, "0.1", PLATEAU_LM_GEODESIC_PROBE, 1, "the geodesic probe t");
    manual_number(h, manual_text, "0.5", PLATEAU_LM_GEODESIC_NONLINEAR, 1, "the geodesic nonlinearity test");
    CHECK_EQ_INT(PLATEAU_LM_REFINE_STEPS, 40);
    CHECK_EQ_INT(r.max_irls, 50);
}

static void test_numbers_delaunay(void)
{
    const char *h = "plateau_delaunay.h";
    const double rad = PLATEAU__PI / 180.0;
    if (!CHECK(manual_top(h, manual_text, sizeof manual_text))) return;
    manual_version(h, manual_text, PLATEAU_DELAUNAY_VERSION);
    manual_number(h, manual_text, "1.5", PLATEAU__DT_CLUSTER, 1, "the cluster angle factor");
    manual_number(h, manual_text, "9.7", atan(sin(10.0 * rad) / (2.0 - cos(10.0 * rad))) / rad, 0,
                  "the angle bound inside an input angle of 10 degrees");
    manual_number(h, manual_text, "1.0", atan(sin(1.0 * rad) / (2.0 - cos(1.0 * rad))) / rad, 0,
                  "the angle bound inside an input angle of 1 degree");
    manual_number(h, manual_text, "1.6e60", ldexp(1.0, PLATEAU__DT_SCALE_EXP), 0,
                  "2^PLATEAU__DT_SCALE_EXP, where the scaling stops being exact");
    manual_number(h, manual_text, "1074", -log2(nextafter(0.0, 1.0)), 1, "the smallest double, 2^-1074");
    manual_number(h, manual_text, "5e-324", nextafter(0.0, 1.0), 0, "the smallest double");
    /* 2^1221 is about 3.6e367: the examples' ratios exceed it, with 1e61
     * and 1e68 above 2^200 */
    CHECK_EQ_INT((int)floor(1221.0 * log10(2.0)), 367);
    CHECK(61.0 - log10(5e-324) > 1221.0 * log10(2.0) && 1e61 >= ldexp(1.0, 200));
    CHECK(68.0 + 300.0 > 1221.0 * log10(2.0) && 1e68 >= ldexp(1.0, 200));
    manual_checked(h, manual_text, "1e367", "2^1221 to its power of ten (beyond a double: checked above)");
    manual_checked(h, manual_text, "1e61", "an example beyond 2^200 (checked above)");
    manual_checked(h, manual_text, "1e68", "an example beyond 2^200 (checked above)");
}

int main(int argc, char **argv)
{
    (void)argc;
    if (argv && argv[0]) manual_argv0 = argv[0];
    RUN(test_example_prints_what_it_says);
    RUN(test_defaults);
    RUN(test_memory_formula);
    RUN(test_catenoid_limit);
    RUN(test_delaunay_bound);
    RUN(test_constants);
    RUN(test_numbers_plateau);
    RUN(test_numbers_lm);
    RUN(test_numbers_delaunay);
    return harness_report("test_manual");
}
