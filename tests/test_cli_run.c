/* test_cli_run.c - the whole command-line tool, run as a function
 * (cli/plateau_cli_run.h) on good and bad input: exit codes, messages,
 * the JSON object, the files written, and determinism. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with XSI: getpid, clock_gettime, link, symlink, lstat, mkdir, realpath */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "cli/plateau_cli.h"
#include "cli/plateau_cli_run.h"
#include "harness.h"

#include <errno.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[128];
static char out_text[65536], err_text[4096];

static const char *tmp(const char *name)
{
    static char paths[8][256];
    static int next;
    char *p = paths[next++ % 8];
    sprintf(p, "%s_%s", dir, name);
    return p;
}

static void slurp_into(FILE *f, char *buf, size_t size)
{
    size_t n;
    rewind(f);
    n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
}

/* Runs the tool on a command line split at spaces; returns its status. */
static int run(const char *line)
{
    static char buf[1024];
    char *argv[32];
    int argc = 0, status;
    char *p;
    FILE *out = fopen(tmp("out"), "w+b"), *errout = fopen(tmp("err"), "w+b");
    if (!out || !errout) {
        if (out) fclose(out);
        if (errout) fclose(errout);
        return -1;
    }
    strcpy(buf, line);
    argv[argc++] = (char *)"plateau";
    for (p = strtok(buf, " "); p && argc < 31; p = strtok(NULL, " ")) argv[argc++] = p;
    argv[argc] = NULL;
    status = plateau_cli_run(argc, argv, out, errout);
    slurp_into(out, out_text, sizeof out_text);
    slurp_into(errout, err_text, sizeof err_text);
    fclose(out);
    fclose(errout);
    remove(tmp("out"));
    remove(tmp("err"));
    return status;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static void test_bad_input(void)
{
    char line[512];
    CHECK_EQ_INT(run("--method fast cli/samples/helicoid.txt"), 2);
    CHECK(strstr(err_text, "unknown method 'fast'") != NULL);
    CHECK_EQ_INT(out_text[0], '\0');
    CHECK_EQ_INT(run(""), 2);
    CHECK(strstr(err_text, "no boundary file") != NULL);
    sprintf(line, "%s", tmp("missing.txt"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot read the file") != NULL);
    write_text(tmp("bad.txt"), "0 0 0\n1 0 0\n\n# x\n1 1 one\n");
    sprintf(line, "%s", tmp("bad.txt"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "line 5: field 3 is not a number") != NULL);
    write_text(tmp("bad.txt"), "0 0 0\n1 0 0\n");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "needs at least 3") != NULL);
    write_text(tmp("bad.txt"), "0 0 0\n1 0 0\n1 NaN 0\n");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "line 3") != NULL && strstr(err_text, "NaN") != NULL);
    remove(tmp("bad.txt"));
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "usage: plateau") != NULL);
    CHECK_EQ_INT(run("--version"), 0);
    CHECK(strstr(out_text, PLATEAU_VERSION) != NULL);
}

/* A small JSON reader: 1 when s is one JSON value (RFC 8259) followed
 * only by white space; every object key it meets is passed to key (NULL:
 * none) with its length, as written between the quotes, and its depth (0:
 * a key of the outermost object). */
typedef void (*json_key_fn)(const char *key, size_t len, int depth, void *user);
static const char *json_value(const char *s, json_key_fn key, void *user, int depth);

static const char *json_space(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') s++;
    return s;
}

static const char *json_text(const char *s)
{
    if (*s++ != '"') return NULL;
    for (; *s != '"'; s++) {
        if ((unsigned char)*s < 0x20) return NULL;
        if (*s == '\\') {
            s++;
            if (*s == 'u') {
                int i;
                for (i = 1; i <= 4; i++)
                    if (!strchr("0123456789abcdefABCDEF", s[i]) || !s[i]) return NULL;
                s += 4;
            } else if (!*s || !strchr("\"\\/bfnrt", *s)) {
                return NULL;
            }
        }
    }
    return s + 1;
}

static const char *json_number_end(const char *s)
{
    const char *start = s;
    if (*s == '-') s++;
    if (*s == '0') s++;
    else if (*s >= '1' && *s <= '9') while (*s >= '0' && *s <= '9') s++;
    else return NULL;
    if (*s == '.') {
        if (!(*++s >= '0' && *s <= '9')) return NULL;
        while (*s >= '0' && *s <= '9') s++;
    }
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-') s++;
        if (!(*s >= '0' && *s <= '9')) return NULL;
        while (*s >= '0' && *s <= '9') s++;
    }
    return s > start ? s : NULL;
}

static const char *json_value(const char *s, json_key_fn key, void *user, int depth)
{
    s = json_space(s);
    if (depth > 16) return NULL;
    if (*s == '{' || *s == '[') {
        char close = *s == '{' ? '}' : ']';
        s = json_space(s + 1);
        if (*s == close) return s + 1;
        for (;;) {
            if (close == '}') {
                const char *k = s, *e = json_text(s);
                if (!e) return NULL;
                if (key) key(k + 1, (size_t)(e - k - 2), depth, user);
                s = json_space(e);
                if (*s++ != ':') return NULL;
            }
            s = json_value(s, key, user, depth + 1);
            if (!s) return NULL;
            s = json_space(s);
            if (*s == close) return s + 1;
            if (*s++ != ',') return NULL;
            s = json_space(s);
        }
    }
    if (*s == '"') return json_text(s);
    if (strncmp(s, "true", 4) == 0 || strncmp(s, "null", 4) == 0) return s + 4;
    if (strncmp(s, "false", 5) == 0) return s + 5;
    return json_number_end(s);
}

static int json_valid(const char *s, json_key_fn key, void *user)
{
    s = json_value(s, key, user, 0);
    return s && *json_space(s) == '\0';
}

static const char *json_field(const char *json, const char *key)
{
    static char pat[64];
    const char *p;
    sprintf(pat, "\"%s\": ", key);
    p = strstr(json, pat);
    return p ? p + strlen(pat) : NULL;
}

/* The stability report and the discs in --json and the summary: two rings
 * at h = R carry a stable catenoid (index 0, less area than the discs);
 * --critical-index 1 reports whether its search converged; --no-stability and --no-alternatives leave the fields out. */
static void test_stability_fields(void)
{
    const char *f;
    CHECK_EQ_INT(run("--json --method area -n 200 cli/samples/two-rings.txt"), 0);
    f = json_field(out_text, "stability_index");
    CHECK(f && atol(f) == 0);
    f = json_field(out_text, "lowest_eigenvalues");
    CHECK(f && f[0] == '[' && atof(f + 1) > 0.0);
    CHECK(json_field(out_text, "area_gradient_norm") != NULL);
    CHECK(strstr(out_text, "\"alternatives\": [{\"topology\": \"discs\", \"area\": ") != NULL);
    CHECK(strstr(out_text, "\"least_area_topology\": \"film\"") != NULL);
    CHECK_EQ_INT(run("--method area -n 200 cli/samples/two-rings.txt"), 0);
    CHECK(strstr(out_text, "stability  index 0") != NULL);
    CHECK(strstr(out_text, "the film has the least area") != NULL);
    /* the climb from this coarse film (24 a ring) reaches the saddle: the
     * search splits edges round the narrowing neck */
    CHECK_EQ_INT(run("--json --method area -n 200 --critical-index 1 cli/samples/two-rings.txt"), 0);
    CHECK(strstr(out_text, "\"critical_converged\": true") != NULL);
    CHECK(strstr(out_text, "\"solved\": true") != NULL);
    f = json_field(out_text, "stability_index");
    CHECK(f && atol(f) == 1);
    CHECK_EQ_INT(run("--json --no-stability --no-alternatives cli/samples/two-rings.txt"), 0);
    CHECK(json_field(out_text, "stability_index") == NULL);
    CHECK(json_field(out_text, "alternatives") == NULL);
}

/* Two coaxial rings of radius 1 and m vertices each, h apart, into path;
 * the upper ring turned by turn steps (0.5: half a step). */
static void write_rings_of(const char *path, int m, double h, double turn)
{
    FILE *f = fopen(path, "w");
    int j, i;
    if (!f) return;
    for (j = 0; j < 2; j++) {
        for (i = 0; i < m; i++) {
            double t = 6.283185307179586 * (i + (j ? turn : 0.0)) / m;
            fprintf(f, "%.17g %.17g %.17g\n", cos(t), sin(t), j ? 0.5 * h : -0.5 * h);
        }
        fputs("\n", f);
    }
    fclose(f);
}

/* What was not computed says so: rings twice their radius apart pinch
 * during method paper's area presolve, so no solve of method paper ran
 * (F null with a note, not 0) and the film is no equilibrium (area
 * gradient 4.9): no stability index (null and why, not "0, no normal
 * motion lowers the area"); --critical-index always reports
 * critical_converged; --no-stability leaves the fields out. */
static void test_reports_not_computed(void)
{
    char line[400];
    const char *f;
    write_rings_of(tmp("far-rings.txt"), 48, 2.0, 0.0);
    sprintf(line, "--json %s", tmp("far-rings.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(out_text, "\"pinched\": true") != NULL);
    f = json_field(out_text, "F");
    CHECK(f && strncmp(f, "null", 4) == 0);
    CHECK(json_field(out_text, "F_note") != NULL);
    f = json_field(out_text, "stability_index");
    CHECK(f && strncmp(f, "null", 4) == 0);
    f = json_field(out_text, "stability_note");
    CHECK(f && strstr(f, "not an equilibrium") == f + 1);
    sprintf(line, "%s", tmp("far-rings.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(out_text, "no normal motion lowers the area") == NULL);
    CHECK(strstr(out_text, "  stability  not an equilibrium") != NULL);
    CHECK(strstr(out_text, "  F          not computed") != NULL);
    sprintf(line, "--json --critical-index 1 %s", tmp("far-rings.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(out_text, "\"critical_converged\": false") != NULL);
    sprintf(line, "--json --no-stability %s", tmp("far-rings.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(json_field(out_text, "stability_index") == NULL);
    remove(tmp("far-rings.txt"));
}

/* Rings of 20 vertices at h = 0.4: the search at the default n, 2 m,
 * does not converge, runs again at 4 m and converges (count_solves 2).
 * Rings of 16 vertices at h = 0.3 (the unstable neck 0.038), the upper
 * ring turned by half a step or not, and -n 200: found at the first run.
 * At h = 0.2 (the neck 0.019) it fails at all four: the tool says that
 * no critical point of that index was found, in the last of 4 runs, and
 * advises a finer mesh, not another method.  At h = 0.5 the default n
 * finds it at the first run. */
static void test_failed_critical_search_says_so(void)
{
    char line[400];
    const char *f;
    write_rings_of(tmp("rings16.txt"), 16, 0.5, 0.0);
    sprintf(line, "--json --critical-index 1 %s", tmp("rings16.txt"));
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "count_solves");
    CHECK(f && atol(f) == 1);
    write_rings_of(tmp("rings16.txt"), 20, 0.4, 0.0);
    sprintf(line, "--critical-index 1 %s", tmp("rings16.txt")); /* exit 0: converged */
    CHECK_EQ_INT(run(line), 0);
    CHECK_MSG(strstr(out_text, "\n  runs       2 (the saddle search ran again at twice the points") != NULL, out_text);
    write_rings_of(tmp("rings16.txt"), 16, 0.3, 0.0);
    sprintf(line, "--json --critical-index 1 %s", tmp("rings16.txt"));
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "count_solves");
    CHECK(f && atol(f) == 1);
    sprintf(line, "-n 200 --critical-index 1 %s", tmp("rings16.txt"));
    CHECK_EQ_INT(run(line), 0);
    write_rings_of(tmp("rings16.txt"), 16, 0.3, 0.5);
    sprintf(line, "--json --critical-index 1 %s", tmp("rings16.txt"));
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "count_solves");
    CHECK(f && atol(f) == 1);
    CHECK(strstr(out_text, "\"critical_converged\": true") != NULL);
    write_rings_of(tmp("rings16.txt"), 16, 0.2, 0.0);
    sprintf(line, "--critical-index 1 %s", tmp("rings16.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK_MSG(strstr(err_text, "no critical point of index 1 was found") != NULL, err_text);
    CHECK_MSG(strstr(err_text, "in the last of 4 runs, each at twice the points of the one before, up to 512)") !=
                  NULL, err_text);
    CHECK_MSG(strstr(err_text, "-n 1024 (a finer mesh)") != NULL, err_text);
    CHECK(strstr(err_text, "--method area") == NULL);
    remove(tmp("rings16.txt"));
}

/* A strip 100 long and 1 wide (200 vertices, unit spacing): the lowest
 * eigenvalues of its flat film, pi^2 (1 + (k / 100)^2), lie within 1e-3 of
 * each other and none passes the Lanczos convergence test; the summary
 * says so rather than end the line at "lowest eigenvalues". */
static void test_stability_none_converged(void)
{
    static char text[8192];
    char *p = text;
    const char *line;
    int i;
    for (i = 0; i < 100; i++) p += sprintf(p, "%d 0 0\n", i);
    for (i = 100; i > 0; i--) p += sprintf(p, "%d 1 0\n", i);
    write_text(tmp("strip.txt"), text);
    CHECK_EQ_INT(run(tmp("strip.txt")), 0);
    line = strstr(out_text, "lowest eigenvalues");
    CHECK(line != NULL);
    if (line) {
        line += strlen("lowest eigenvalues");
        CHECK(line[0] == ' ' && line[1] != '\n');
    }
    remove(tmp("strip.txt"));
}

/* The stability values do not depend on the unit: a saddle ring in
 * metres and the same ring in millimetres print the same scale-free line
 * (the eigenvalues times L^2, the gradient over L, L the boundary's
 * length, whose value alone differs) and the same scaled JSON values,
 * while the raw eigenvalues differ by 10^6. */
static void test_stability_units(void)
{
    static const double scale[2] = {1.0, 1000.0};
    char line[512], stab[2][512], text[4096];
    double raw[2] = {0.0, 0.0}, scaled[2] = {0.0, 0.0}, L[2] = {0.0, 0.0};
    int u, i;
    for (u = 0; u < 2; u++) {
        const char *f, *s;
        char *p = text;
        for (i = 0; i < 24; i++) {
            double t = 6.283185307179586 * i / 24;
            p += sprintf(p, "%.17g %.17g %.17g\n", scale[u] * cos(t), scale[u] * sin(t), scale[u] * 0.3 * cos(2 * t));
        }
        write_text(tmp("ring.txt"), text);
        sprintf(line, "%s", tmp("ring.txt"));
        CHECK_EQ_INT(run(line), 0);
        s = strstr(out_text, "  stability  ");
        stab[u][0] = '\0';
        if (CHECK(s != NULL && strstr(s, " (L = ") != NULL))
            sprintf(stab[u], "%.*s", (int)(strstr(s, " (L = ") - s), s);
        CHECK(strstr(out_text, u ? "(L = 6787.31, the boundary's length)\n" : "(L = 6.78731, the boundary's length)\n") !=
              NULL);
        sprintf(line, "--json %s", tmp("ring.txt"));
        CHECK_EQ_INT(run(line), 0);
        f = json_field(out_text, "lowest_eigenvalues");
        raw[u] = f ? atof(f + 1) : 0.0;
        f = json_field(out_text, "lowest_eigenvalues_scaled");
        scaled[u] = f ? atof(f + 1) : 0.0;
        f = json_field(out_text, "boundary_length");
        L[u] = f ? atof(f) : 0.0;
    }
    remove(tmp("ring.txt"));
    if (!CHECK(stab[0][0] && strcmp(stab[0], stab[1]) == 0)) fprintf(stderr, "  m:  %s\n  mm: %s\n", stab[0], stab[1]);
    CHECK(strstr(stab[0], " / L^2") != NULL && strstr(stab[0], " L, lowest eigenvalues ") != NULL);
    CHECK_REL(L[1], 1000.0 * L[0], 1e-12, 0.0);
    CHECK_REL(raw[0], 1e6 * raw[1], 1e-6, 0.0);
    CHECK(scaled[0] > 10.0);
    CHECK_REL(scaled[1], scaled[0], 1e-9, 0.0);
    CHECK_REL(scaled[0], raw[0] * L[0] * L[0], 1e-12, 0.0);
}

/* Two coaxial rings of radius 1 (64 vertices each)
 * at h = 0.8, default options and --critical-index 1: the unstable
 * catenoid, exit status 0, index 1, area within 0.5 % of the exact
 * 6.601304 (a = 0.157962). */
static void test_critical_index_rings(void)
{
    const double pi = 3.14159265358979323846, exact = 6.601304;
    char line[512];
    const char *f;
    FILE *file = fopen(tmp("rings08.txt"), "wb");
    int ring, i;
    if (!CHECK(file != NULL)) return;
    for (ring = 0; ring < 2; ring++) {
        if (ring) fprintf(file, "\n");
        for (i = 0; i < 64; i++)
            fprintf(file, "%.17g %.17g %.17g\n", cos(2.0 * pi * i / 64), sin(2.0 * pi * i / 64), ring ? 0.4 : -0.4);
    }
    fclose(file);
    sprintf(line, "--json --critical-index 1 %s", tmp("rings08.txt"));
    CHECK_EQ_INT(run(line), 0);
    CHECK(strstr(out_text, "\"critical_converged\": true") != NULL);
    CHECK(strstr(out_text, "\"valid\": true") != NULL);
    f = json_field(out_text, "stability_index");
    CHECK(f && atol(f) == 1);
    f = json_field(out_text, "area");
    CHECK(f && fabs(atof(f) - exact) < 0.005 * exact);
    remove(tmp("rings08.txt"));
}

static void test_solve_and_write(void)
{
    char line[512], first[65536];
    const char *keys[] = {"vertices", "triangles", "area", "F", "rounds", "iterations",
                          "min_angle_deg", "max_angle_deg", "method", "domain", "stop"};
    size_t i;
    long nv, nt;
    sprintf(line, "-n 12 --seeding paper --seed 3 --json -o %s --svg %s cli/samples/helicoid.txt", tmp("m.obj"),
            tmp("m.svg"));
    CHECK_EQ_INT(run(line), 0);
    CHECK_MSG(err_text[0] == '\0', err_text);
    for (i = 0; i < sizeof keys / sizeof keys[0]; i++) CHECK_MSG(json_field(out_text, keys[i]) != NULL, keys[i]);
    CHECK(strstr(out_text, "\"domain\": \"plane\"") != NULL);
    CHECK(strstr(out_text, "\"method\": \"paper\"") != NULL);
    nv = json_field(out_text, "vertices") ? atol(json_field(out_text, "vertices")) : -1;
    nt = json_field(out_text, "triangles") ? atol(json_field(out_text, "triangles")) : -1;
    CHECK_EQ_INT(nv, 28 + 12);
    CHECK(nt > 0);
    /* a sane area: within 5 % of 6.21699, the optimum of the length-sampled
     * helicoid polygon of examples/NOTES.md (this uniformly sampled one's is
     * a little lower: area minimisation reaches 6.20684) */
    CHECK_NEAR(json_field(out_text, "area") ? atof(json_field(out_text, "area")) : 0.0, 6.21699,
               0.05 * 6.21699);
    {
        /* the OBJ holds what the JSON says */
        FILE *f = fopen(tmp("m.obj"), "rb");
        char l[256];
        long v = 0, t = 0;
        CHECK(f != NULL);
        if (f) {
            while (fgets(l, sizeof l, f)) {
                v += l[0] == 'v';
                t += l[0] == 'f';
            }
            fclose(f);
        }
        CHECK_EQ_INT(v, nv);
        CHECK_EQ_INT(t, nt);
    }
    {
        FILE *f = fopen(tmp("m.svg"), "rb");
        char head[5] = {0};
        CHECK(f != NULL);
        if (f) {
            CHECK(fread(head, 1, 4, f) == 4);
            fclose(f);
        }
        CHECK(strcmp(head, "<svg") == 0);
    }
    /* the same run again gives the same JSON but for the elapsed time */
    strcpy(first, out_text);
    CHECK_EQ_INT(run(line), 0);
    {
        const char *a = strstr(first, "\"elapsed_s\""), *b = strstr(out_text, "\"elapsed_s\"");
        CHECK(a && b && (a - first) == (b - out_text) && strncmp(first, out_text, (size_t)(a - first)) == 0);
    }
    remove(tmp("m.obj"));
    remove(tmp("m.svg"));
    /* the summary; the area method; the circle domain */
    CHECK_EQ_INT(run("-n 12 --seeding paper --method area cli/samples/helicoid.txt"), 0);
    CHECK(strstr(out_text, "method     area") != NULL);
    CHECK(strstr(out_text, "40 vertices") != NULL);
    CHECK_EQ_INT(run("-n 20 --json cli/samples/helicoid-turns.txt"), 0);
    CHECK(strstr(out_text, "\"domain\": \"circle\"") != NULL);
    /* an unwritable output is refused before the solve: status 1, the
     * path and the reason, and no summary (nothing was solved) */
    sprintf(line, "-n 8 -o %s/no/such/dir/m.off cli/samples/catenoid.txt", dir);
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot write the mesh file '") != NULL);
    CHECK(strstr(err_text, "/no/such/dir/m.off': ") != NULL);
    CHECK(strstr(err_text, "nothing was solved") != NULL);
    CHECK_EQ_INT(out_text[0], '\0');
    sprintf(line, "-n 8 --svg %s/no/such/dir/m.svg cli/samples/catenoid.txt", dir);
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot write the picture '") != NULL);
    CHECK_EQ_INT(out_text[0], '\0');
    /* a good -o with a bad --svg: neither is written */
    sprintf(line, "-n 8 -o %s --svg /tmp cli/samples/catenoid.txt", tmp("kept.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot write the picture '/tmp'") != NULL);
    {
        FILE *f = fopen(tmp("kept.obj"), "rb");
        CHECK(f == NULL);
        if (f) fclose(f);
    }
}

/* The warnings of a run that succeeds: --seed with the seeding that uses
 * no seed; an interior count more than 10 % from -n (the count in the
 * message is the mesh's own). */
static void test_warnings(void)
{
    char text[16384], *p = text, line[512], want[128];
    long got;
    int i;
    CHECK_EQ_INT(run("--seed 7 -n 20 cli/samples/helicoid.txt"), 0);
    CHECK(strstr(err_text, "plateau: warning: --seed 7 has no effect") == err_text);
    CHECK(strstr(out_text, "check      valid") != NULL);
    CHECK_EQ_INT(run("--seed 7 -n 20 --seeding paper cli/samples/helicoid.txt"), 0);
    CHECK(strstr(err_text, "--seed") == NULL);
    /* a 100-vertex ring, n = 100: the refinement places more than 110 */
    for (i = 0; i < 100; i++) {
        double t = 6.283185307179586 * i / 100;
        p += sprintf(p, "%.17g %.17g %.17g\n", cos(t), sin(t), 0.2 * cos(2 * t));
    }
    write_text(tmp("ring.txt"), text);
    sprintf(line, "--json -n 100 %s", tmp("ring.txt"));
    CHECK_EQ_INT(run(line), 0);
    got = json_field(out_text, "interior_points") ? atol(json_field(out_text, "interior_points")) : -1;
    CHECK(got > 110);
    sprintf(want, "the mesh has %ld interior points, %.0f %% more than the 100 asked (-n)", got,
            (double)(got - 100));
    CHECK_MSG(strstr(err_text, want) != NULL, want);
    CHECK(strstr(err_text, "--seeding paper draws exactly n") != NULL);
    /* the fan seeding draws exactly n: no warning */
    sprintf(line, "--json -n 100 --seeding paper %s", tmp("ring.txt"));
    CHECK_EQ_INT(run(line), 0);
    got = json_field(out_text, "interior_points") ? atol(json_field(out_text, "interior_points")) : -1;
    CHECK_EQ_INT(got, 100);
    CHECK(strstr(err_text, "interior points") == NULL);
    remove(tmp("ring.txt"));
}

/* --progress: one line per stage at least (stage, round, iteration, F or
 * area, elapsed time); the area presolve of method paper on the circle
 * domain, then method paper; nothing without --progress off a terminal. */
static void test_progress(void)
{
    CHECK_EQ_INT(run("--progress -n 20 cli/samples/helicoid.txt"), 0);
    CHECK(strstr(err_text, "plateau: method paper, round 1, iteration 1, F ") == err_text);
    CHECK(strstr(err_text, " s\n") != NULL);
    CHECK(strstr(err_text, "presolve") == NULL); /* the plane domain: no presolve */
    CHECK_EQ_INT(run("--progress --method area -n 20 cli/samples/helicoid.txt"), 0);
    CHECK(strstr(err_text, "plateau: method area, round 1, iteration 1, area ") == err_text);
    CHECK_EQ_INT(run("--progress --accuracy 1e-3 cli/samples/helicoid-turns.txt"), 0); /* one solve */
    CHECK(strstr(err_text, "plateau: area presolve, round 1, iteration 1, area ") == err_text);
    CHECK(strstr(err_text, "\nplateau: method paper, round 1, iteration 1, F ") != NULL);
    CHECK_EQ_INT(run("--progress --json two-rings-absent.txt"), 1); /* no solve, no line */
    CHECK(strstr(err_text, "round") == NULL);
    CHECK_EQ_INT(run("-n 20 cli/samples/helicoid.txt"), 0);
    CHECK_EQ_INT(err_text[0], '\0');
    CHECK_EQ_INT(run("--no-progress -n 20 cli/samples/helicoid.txt"), 0);
    CHECK_EQ_INT(err_text[0], '\0');
}

/* "-" reads the boundary from standard input; --max-input-bytes caps what
 * is read, so an endless input is refused, not read into memory. */
static void test_stdin_and_size_cap(void)
{
    char from_file[65536];
    const char *a, *b;
    CHECK_EQ_INT(run("-n 20 --json cli/samples/helicoid.txt"), 0);
    strcpy(from_file, out_text);
    CHECK(freopen("cli/samples/helicoid.txt", "rb", stdin) != NULL);
    CHECK_EQ_INT(run("-n 20 --json -"), 0);
    CHECK_MSG(err_text[0] == '\0', err_text);
    /* the same mesh: the JSON from "vertices" up to the elapsed time agrees */
    a = strstr(from_file, "\"vertices\"");
    b = strstr(out_text, "\"vertices\"");
    CHECK(a && b);
    if (a && b) {
        const char *ea = strstr(a, "\"elapsed_s\""), *eb = strstr(b, "\"elapsed_s\"");
        CHECK(ea && eb && ea - a == eb - b && strncmp(a, b, (size_t)(ea - a)) == 0);
    }
    CHECK(strstr(out_text, "\"boundary_vertices\": 28") != NULL);
    /* an oversize input: refused with the limit named, status 1 */
    CHECK_EQ_INT(run("--max-input-bytes 100 cli/samples/helicoid.txt"), 1);
    CHECK(strstr(err_text, "larger than the limit of 100 bytes") != NULL);
    CHECK_EQ_INT(out_text[0], '\0');
    CHECK_EQ_INT(run("--max-input-bytes 4096 /dev/zero"), 1);
    CHECK(strstr(err_text, "/dev/zero: the input is larger than the limit of 4096 bytes") != NULL);
    CHECK_EQ_INT(run("--max-input-bytes 0 cli/samples/helicoid.txt"), 2);
    CHECK_EQ_INT(run("--max-input-bytes lots cli/samples/helicoid.txt"), 2);
    /* the help says what n defaults to, and how to read standard input */
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "as many as the accuracy") != NULL && strstr(out_text, "--accuracy TOL") != NULL);
    CHECK(strstr(out_text, "standard input") != NULL);
    CHECK(strstr(out_text, "--max-input-bytes") != NULL);
    CHECK(strstr(out_text, "the library's") == NULL);
}

/* A mesh with defects is written and summarised as asked, with a warning
 * in words on stderr and exit status 3; --json carries the counts and
 * "valid".  A trefoil knot bounds no embedded disk (its mesh crosses
 * itself); helicoid-turns with the paper's fan seeding folds (2 inverted
 * triangles, |dihedral| 178.9 deg), with the default seeding it is valid. */
static void test_defects_status(void)
{
    char text[8192], *p = text, line[512];
    int i;
    for (i = 0; i < 60; i++) {
        double t = 6.283185307179586 * i / 60;
        p += sprintf(p, "%.17g %.17g %.17g\n", sin(t) + 2 * sin(2 * t), cos(t) - 2 * cos(2 * t),
                     -sin(3 * t));
    }
    write_text(tmp("trefoil.txt"), text);
    sprintf(line, "-n 60 -o %s %s", tmp("t.obj"), tmp("trefoil.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(err_text, "warning") != NULL);
    CHECK(strstr(err_text, "triangles intersecting each other") != NULL);
    CHECK(strstr(out_text, "check      DEFECTS") != NULL);
    CHECK(strstr(out_text, "converged") == NULL);
    /* what to try: another method, more points, and the knot (the
     * polygon's edges are no longer than the mesh's: nothing to split) */
    CHECK(strstr(err_text, "plateau: what to try: --method area") != NULL);
    CHECK(strstr(err_text, "; -n 120 (a finer mesh)") != NULL);
    CHECK(strstr(err_text, "--refine-boundary") == NULL);
    CHECK(strstr(err_text, "knotted") != NULL);
    {
        FILE *f = fopen(tmp("t.obj"), "rb"); /* the mesh is still written */
        CHECK(f != NULL);
        if (f) fclose(f);
    }
    remove(tmp("t.obj"));
    sprintf(line, "--json %s", tmp("trefoil.txt"));
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(out_text, "\"valid\": false") != NULL);
    CHECK(strstr(out_text, "\"defects\": 8") != NULL);
    CHECK(strstr(out_text, "\"intersecting_pairs\": 0") == NULL);
    remove(tmp("trefoil.txt"));
    /* n = m = 56: the paper's fan seeding folds (the default accuracy's
     * finer mesh is valid) */
    CHECK_EQ_INT(run("-n 56 --seeding paper cli/samples/helicoid-turns.txt"), 3);
    CHECK(strstr(err_text, "inverted triangles") != NULL);
    CHECK(strstr(err_text, "plateau: what to try: --method area") != NULL);
    CHECK_EQ_INT(run("--method paper-literal cli/samples/helicoid-turns.txt"), 3);
    CHECK(strstr(err_text, "plateau: what to try: --method paper or --method area") != NULL);
    CHECK_EQ_INT(run("--json -n 56 --seeding paper cli/samples/helicoid-turns.txt"), 3);
    CHECK(strstr(out_text, "\"valid\": false") != NULL);
    /* the statuses are documented */
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "3  a mesh was produced") != NULL);
}

/* Every shipped sample gives a valid mesh with the defaults, by methods
 * paper and area (status 0, "valid": true, no warning); the default
 * seeding uses no seed, so --seed changes nothing. */
static void test_samples_valid(void)
{
    /* helicoid-turns at --accuracy 1e-3 (its estimate at the first count
     * is below that): the mesh the default returns, without the default's
     * further solve at a finer count, which takes seconds */
    static const char *const samples[] = {"cli/samples/helicoid.txt", "cli/samples/catenoid.txt",
                                          "--accuracy 1e-3 cli/samples/helicoid-turns.txt"};
    static const char *const methods[] = {"paper", "area"};
    char line[256];
    size_t i, k;
    for (i = 0; i < sizeof samples / sizeof samples[0]; i++)
        for (k = 0; k < 2; k++) {
            sprintf(line, "--json --method %s %s", methods[k], samples[i]);
            CHECK_MSG(run(line) == 0, line);
            CHECK_MSG(strstr(out_text, "\"valid\": true") != NULL, line);
            CHECK_MSG(strstr(out_text, "\"defects\": 0") != NULL, line);
            CHECK_MSG(err_text[0] == '\0', err_text);
        }
    CHECK_EQ_INT(run("--seed 3 --accuracy 1e-3 cli/samples/helicoid-turns.txt"), 0);
    CHECK(strstr(out_text, "check      valid") != NULL);
}


/* Membranes from the command line: cable lines ("x y z cable T"), the
 * JSON's "cables", "pressure" and "volume", and bad values by name. */
static void test_membranes(void)
{
    char path[256];
    double sag;
    const char *f;
    strcpy(path, tmp("sail.txt")); /* tmp's buffers rotate */
    write_text(path, "-1 -1 0 cable 2\n1 -1 0 cable 2 # the south edge\n1 1 0\n-1 1 0 cable 2\n");
    CHECK_EQ_INT(run("--json --method area -n 200 /tmp/x"), 1); /* no such file */
    {
        char line[512];
        sprintf(line, "--json --method area -n 200 %s", path);
        CHECK_EQ_INT(run(line), 0);
    }
    CHECK(strstr(out_text, "\"cables\": [{\"tension\": 2, \"length\": ") != NULL);
    f = strstr(out_text, "\"sag\": ");
    sag = f ? atof(f + 7) : 0.0;
    CHECK(sag > 0.2 && sag < 0.3); /* the arc of radius 2 over the chord 2: 0.268 */
    CHECK(strstr(out_text, "\"valid\": true") != NULL);
    CHECK_MSG(err_text[0] == '\0', err_text);
    {
        char line[512];
        write_text(path, "-1 -1 0 cable 0.5\n1 -1 0\n1 1 0\n-1 1 0\n");
        sprintf(line, "--method area %s", path);
        CHECK_EQ_INT(run(line), 1);
        CHECK(strstr(err_text, "half its chord") != NULL);
        write_text(path, "-1 -1 0 cable\n1 -1 0\n1 1 0\n-1 1 0\n");
        CHECK_EQ_INT(run(line), 1);
        CHECK(strstr(err_text, "line 1") != NULL);
        remove(path);
    }
    CHECK_EQ_INT(run("--json --method paper --pressure 1 cli/samples/helicoid.txt"), 0);
    CHECK(strstr(out_text, "\"pressure\": 1,") != NULL);
    CHECK(json_field(out_text, "volume") != NULL);
    CHECK_EQ_INT(run("--pressure abc cli/samples/helicoid.txt"), 2);
    CHECK_EQ_INT(run("--method paper-literal --volume 1 cli/samples/helicoid.txt"), 2);
}

/* Membranes against what is of the area alone: no stability report (the
 * JSON's stability_index null with its note, the summary's line), coarse to
 * fine on refused naming both; a cable on a closing point that is
 * dropped is refused by its line, and "cable T" on the line before it
 * makes the closing edge a cable; cables from two files, each kept with
 * its loop. */
static void test_membranes_merged(void)
{
    char path[256], path2[256], line[700];
    const char *f;
    CHECK_EQ_INT(run("--json --method paper --pressure 1 cli/samples/helicoid.txt"), 0);
    f = json_field(out_text, "stability_index");
    CHECK(f && strncmp(f, "null", 4) == 0);
    CHECK(json_field(out_text, "stability_note") != NULL);
    CHECK(json_field(out_text, "lowest_eigenvalues") == NULL);
    CHECK_EQ_INT(run("--method area -n 200 cli/samples/sail-square.txt"), 0);
    CHECK(strstr(out_text, "stability  not computed for a membrane") != NULL);
    CHECK_EQ_INT(run("--json --method area -n 200 cli/samples/helicoid.txt"), 0);
    f = json_field(out_text, "stability_index");
    CHECK(f && atol(f) == 0);
    CHECK(json_field(out_text, "stability_note") == NULL);
    CHECK_EQ_INT(run("--coarse-to-fine on --pressure 1 cli/samples/helicoid.txt"), 2);
    CHECK_MSG(strstr(err_text, "not the membrane energy's") != NULL, err_text);
    CHECK_EQ_INT(run("--critical-index 1 --pressure 1 cli/samples/helicoid.txt"), 2);
    CHECK_MSG(strstr(err_text, "a membrane's energy is not its area") != NULL, err_text);
    /* a membrane by its cables (the boundary file): the library refuses */
    CHECK_EQ_INT(run("--coarse-to-fine on cli/samples/sail-square.txt"), 1);
    CHECK_MSG(strstr(err_text, "--coarse-to-fine on and a membrane") != NULL, err_text);
    strcpy(path, tmp("closed-sail.txt"));
    strcpy(path2, tmp("closed-sail2.txt"));
    /* the closing point (line 6) carries the cable: refused by its line */
    write_text(path, "# a sail\n-1 -1 0 cable 2\n1 -1 0 cable 2\n1 1 0 cable 2\n-1 1 0\n-1 -1 0 cable 2\n");
    sprintf(line, "--method area -n 200 %s", path);
    CHECK_EQ_INT(run(line), 1);
    CHECK_MSG(strstr(err_text, "line 6: a cable on a closing point") != NULL, err_text);
    /* on the line before it: the closing edge is a cable, the point is dropped with a note */
    write_text(path, "# a sail\n-1 -1 0 cable 2\n1 -1 0 cable 2\n1 1 0 cable 2\n-1 1 0 cable 2\n-1 -1 0\n");
    sprintf(line, "--json --method area -n 200 %s", path);
    CHECK_EQ_INT(run(line), 0);
    CHECK_MSG(strstr(err_text, "line 6 repeats the first vertex") != NULL, err_text);
    CHECK(strstr(out_text, "\"boundary_vertices\": 4,") != NULL);
    f = strstr(out_text, "\"cables\": [");
    CHECK(f && strstr(f, "}, {\"tension\": 2, ") && strstr(strstr(f, "}, {") + 4, "}, {") &&
          strstr(strstr(strstr(f, "}, {") + 4, "}, {") + 4, "}, {"));
    /* two files: the second's cables stay with its loop (rings of radius 1
     * and 2 at heights 0 and 0.5: chords below 2 T) */
    {
        char text[2048], *p = text;
        int i;
        for (i = 0; i < 12; i++)
            p += sprintf(p, "%.17g %.17g 0\n", cos(6.283185307179586 * i / 12), sin(6.283185307179586 * i / 12));
        write_text(path, text);
        p = text;
        for (i = 0; i < 12; i++)
            p += sprintf(p, "%.17g %.17g 0.5%s\n", 2.0 * cos(6.283185307179586 * i / 12),
                         2.0 * sin(6.283185307179586 * i / 12), i == 3 ? " cable 3" : "");
        write_text(path2, text);
        sprintf(line, "--json --method area -n 100 %s %s", path, path2);
        run(line);
        f = strstr(out_text, "\"cables\": [{\"tension\": 3, ");
        CHECK_MSG(f != NULL && strstr(f, "}, {") == NULL, out_text);
    }
    remove(path);
    remove(path2);
}

/* A ring of n vertices (radius 1, height z), the first repeated at the end
 * when closed, after a comment line; returns the text's end. */
static char *ring_text(char *p, int n, double z, int closed)
{
    int i;
    p += sprintf(p, "# a ring at height %g\n", z);
    for (i = 0; i <= n; i++) {
        double t = 6.283185307179586 * (i % n) / n;
        if (i == n && !closed) break;
        p += sprintf(p, "%.17g %.17g %.17g\n", cos(t), sin(t), z);
    }
    return p;
}

/* The first whole number after "label ... :" in admesh's report; -1 if none. */
static long admesh_value(const char *out, const char *label)
{
    const char *p = strstr(out, label);
    long v = -1;
    if (p) p = strchr(p, ':');
    if (!p || sscanf(p + 1, "%ld", &v) != 1) return -1;
    return v;
}

/* The little-endian uint32 at p. */
static unsigned long stl_count(const unsigned char *p)
{
    return (unsigned long)p[0] | (unsigned long)p[1] << 8 | (unsigned long)p[2] << 16 |
           (unsigned long)p[3] << 24;
}

/* -o FILE.stl writes binary STL, --stl-ascii ASCII STL: as many facets as
 * the JSON's triangles (each facet's corners are the mesh's: test_io).
 * admesh, when installed, checks both (no repair): no error, the facet
 * count, one part, no facet to reverse, no normal to fix, and the 24
 * boundary edges of the catenoid sample as its only open edges. */
static void test_stl(void)
{
    char line[1024], bin[256], asc[256], report[256], cmd[1024];
    long nt;
    FILE *f;
    unsigned char head[84];
    size_t got = 0;
    char *p, *q;
    long facets = 0, vertices = 0;
    strcpy(bin, tmp("m.stl"));
    strcpy(asc, tmp("a.stl"));
    strcpy(report, tmp("admesh.txt"));
    sprintf(line, "-n 30 --json -o %s cli/samples/catenoid.txt", bin);
    CHECK_EQ_INT(run(line), 0);
    nt = json_field(out_text, "triangles") ? atol(json_field(out_text, "triangles")) : -1;
    CHECK(nt > 0);
    f = fopen(bin, "rb");
    if (CHECK(f != NULL)) {
        got = fread(head, 1, 84, f);
        fseek(f, 0, SEEK_END);
        CHECK_EQ_INT(ftell(f), 84 + 50 * nt);
        fclose(f);
    }
    CHECK(got == 84 && (long)stl_count(head + 80) == nt && strncmp((char *)head, "solid", 5) != 0);
    sprintf(line, "-n 30 --json --stl-ascii -o %s cli/samples/catenoid.txt", asc);
    CHECK_EQ_INT(run(line), 0);
    f = fopen(asc, "rb");
    if (CHECK(f != NULL)) {
        static char text[1 << 20];
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = '\0';
        fclose(f);
        CHECK(strncmp(text, "solid plateau\n", 14) == 0);
        for (p = text; (q = strstr(p, "facet normal")) != NULL; p = q + 1) facets++;
        for (p = text; (q = strstr(p, "vertex ")) != NULL; p = q + 1) vertices++;
        CHECK_EQ_INT(facets, nt);
        CHECK_EQ_INT(vertices, 3 * nt);
        CHECK(n > 18 && strcmp(text + n - 17, "endsolid plateau\n") == 0);
    }
    if (system("command -v admesh >/dev/null 2>&1") == 0) {
        int k;
        for (k = 0; k < 2; k++) {
            static char out[16384];
            char want[64];
            /* check only (no repair): exact edges, normal directions and values */
            sprintf(cmd, "admesh -e -d -v %s > %s 2>&1", k == 0 ? bin : asc, report);
            CHECK_EQ_INT(system(cmd), 0);
            f = fopen(report, "rb");
            if (!CHECK(f != NULL)) continue;
            out[fread(out, 1, sizeof out - 1, f)] = '\0';
            fclose(f);
            CHECK_MSG(strstr(out, k == 0 ? "Binary STL file" : "ASCII STL file") != NULL, out);
            CHECK_MSG(strstr(out, "rror") == NULL, out);
            CHECK_EQ_INT(admesh_value(out, "Number of facets"), nt);
            CHECK_EQ_INT(admesh_value(out, "Number of parts"), 1);
            CHECK_EQ_INT(admesh_value(out, "Facets reversed"), 0); /* oriented consistently */
            CHECK_EQ_INT(admesh_value(out, "Backwards edges"), 0);
            CHECK_EQ_INT(admesh_value(out, "Normals fixed"), 0);   /* the normals are right */
            CHECK_EQ_INT(admesh_value(out, "Degenerate facets"), 0);
            /* an open film: its boundary edges are the "disconnected" ones */
            CHECK_EQ_INT(admesh_value(out, "Facets with 1 disconnected edge") +
                             2 * admesh_value(out, "Facets with 2 disconnected edges"), 24);
            sprintf(want, "admesh -e -d -v on the %s STL: %ld facets", k == 0 ? "binary" : "ASCII", nt);
            printf("%s\n", want);
            remove(report);
        }
    } else {
        printf("admesh: skipped (not installed)\n");
    }
    remove(bin);
    remove(asc);
}

/* A closing point equal to the first is dropped with a note, for one loop
 * and for each loop of a file of several; geometric errors name the file
 * lines of the vertices they name, in one file and across files. */
static void test_closing_point_and_lines(void)
{
    char text[8192], *p, line[1024], want[1024], path[256], path2[256];
    strcpy(path, tmp("closed.txt")); /* tmp() reuses its buffers */
    strcpy(path2, tmp("ring2.txt"));
    /* one loop: a closed skew quadrilateral */
    write_text(path, "# a saddle\n0 0 0\n1 0 1\n1 1 0\n0 1 1\n0 0 0\n");
    sprintf(line, "--json -n 5 %s", path);
    CHECK_EQ_INT(run(line), 0);
    sprintf(want, "plateau: note: %s: line 6 repeats the first vertex of the polygon (line 2); dropped", path);
    CHECK_MSG(strstr(err_text, want) == err_text, err_text);
    CHECK(json_field(out_text, "boundary_vertices") && atol(json_field(out_text, "boundary_vertices")) == 4);
    /* two loops in one file, each closed: one note each */
    p = ring_text(text, 16, 0.0, 1);
    p += sprintf(p, "\n");
    ring_text(p, 16, 1.0, 1);
    write_text(path, text);
    sprintf(line, "--json -n 40 %s", path);
    CHECK_EQ_INT(run(line), 0);
    sprintf(want, "%s: line 18 repeats the first vertex of its loop (line 2); dropped", path);
    CHECK_MSG(strstr(err_text, want) != NULL, err_text);
    sprintf(want, "%s: line 37 repeats the first vertex of its loop (line 21); dropped", path);
    CHECK_MSG(strstr(err_text, want) != NULL, err_text);
    CHECK(json_field(out_text, "boundary_vertices") && atol(json_field(out_text, "boundary_vertices")) == 32);
    /* a repeated vertex on file lines 5 and 6 (vertices 1 and 2) */
    write_text(path, "# c\n# c\n0 0 0\n# c\n1 0 0\n1 0 0\n0 1 0\n");
    CHECK_EQ_INT(run(path), 1);
    sprintf(want, "plateau: %s: boundary vertices 1 and 2 are equal (file lines 5 and 6)\n", path);
    CHECK_MSG(strcmp(err_text, want) == 0, err_text);
    /* not neighbours (vertices 0 and 2), a vertex on an edge, crossing edges */
    write_text(path, "# c\n0 0 0\n1 0 0\n0 0 0\n0 1 0\n");
    CHECK_EQ_INT(run(path), 1);
    CHECK_MSG(strstr(err_text, "boundary vertices 0 and 2 coincide (they are not neighbours) (file lines 2 and 4)") != NULL,
              err_text);
    write_text(path, "0 0 0\n2 0 0\n2 2 0\n# c\n1 0 0\n0 2 0\n");
    CHECK_EQ_INT(run(path), 1);
    CHECK_MSG(strstr(err_text, "boundary vertex 3 lies on edge 0 (from vertex 0 to vertex 1) "
                               "(file lines: vertex 5, edge 1-2)") != NULL, err_text);
    write_text(path, "0 0 0\n1 1 0\n# c\n1 0 0\n0 1 0\n");
    CHECK_EQ_INT(run(path), 1);
    CHECK_MSG(strstr(err_text, "(file lines: edges 1-2 and 4-5)") != NULL, err_text);
    /* two files, loops sharing a vertex: vertex 4 of the second ring moved
     * onto vertex 4 of the first (file lines 6 and 6) */
    ring_text(text, 16, 0.0, 0);
    write_text(path, text);
    ring_text(text, 16, 1.0, 0);
    p = strstr(text, "\n");
    {
        int i;
        for (i = 0; i < 4 && p; i++) p = strstr(p + 1, "\n");
        if (p) {
            char rest[8192], *q = strstr(p + 1, "\n");
            strcpy(rest, q ? q : "");
            sprintf(p + 1, "%.17g %.17g %.17g%s", cos(6.283185307179586 * 4 / 16),
                    sin(6.283185307179586 * 4 / 16), 0.0, rest);
        }
    }
    write_text(path2, text);
    sprintf(line, "-n 20 %s %s", path, path2);
    CHECK_EQ_INT(run(line), 1);
    sprintf(want, "vertex 4 of loop 0 and vertex 4 of loop 1 coincide (lines %s:6 and %s:6)", path, path2);
    CHECK_MSG(strstr(err_text, want) != NULL, err_text);
    remove(path);
    remove(path2);
}

/* The output files: -o naming the boundary file (by its name, a hard link
 * or a symbolic link to it) is refused before anything runs, status 2, and
 * the boundary keeps its contents; -o as a symbolic link to another file
 * replaces that file and the link stays a link; a link to a missing file is
 * refused, status 1; an existing -o file that cannot be replaced (a
 * directory) stays as it was. */
static void test_output_files(void)
{
    char line[512], *before;
    size_t len = 0;
    struct stat st;
    FILE *f;
    long size;
    f = fopen("cli/samples/helicoid.txt", "rb");
    CHECK(f != NULL);
    if (!f) return;
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    rewind(f);
    before = (char *)malloc((size_t)size + 1);
    len = fread(before, 1, (size_t)size, f);
    fclose(f);
    CHECK_EQ_INT((long)len, size);
    /* the boundary, copied to boundary.obj (a name -o accepts) */
    f = fopen(tmp("boundary.obj"), "wb");
    if (f) {
        fwrite(before, 1, len, f);
        fclose(f);
    }
    sprintf(line, "-n 8 -o %s %s", tmp("boundary.obj"), tmp("boundary.obj"));
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "is the boundary file") != NULL);
    CHECK_EQ_INT(out_text[0], '\0');
    if (link(tmp("boundary.obj"), tmp("hard.obj")) == 0) {
        sprintf(line, "-n 8 -o %s %s", tmp("hard.obj"), tmp("boundary.obj"));
        CHECK_EQ_INT(run(line), 2);
        remove(tmp("hard.obj"));
    }
    if (symlink(tmp("boundary.obj"), tmp("soft.obj")) == 0) {
        sprintf(line, "-n 8 -o %s %s", tmp("soft.obj"), tmp("boundary.obj"));
        CHECK_EQ_INT(run(line), 2);
        remove(tmp("soft.obj"));
    }
    {   /* the boundary is as it was */
        char *now = (char *)malloc(len + 1);
        f = fopen(tmp("boundary.obj"), "rb");
        CHECK(f && fread(now, 1, len + 1, f) == len && memcmp(now, before, len) == 0);
        if (f) fclose(f);
        free(now);
    }
    /* through a link to another file: that file replaced, the link kept */
    write_text(tmp("target.obj"), "# old\n");
    if (symlink(tmp("target.obj"), tmp("link.obj")) == 0) {
        sprintf(line, "-n 8 -o %s cli/samples/helicoid.txt", tmp("link.obj"));
        CHECK_EQ_INT(run(line), 0);
        CHECK(lstat(tmp("link.obj"), &st) == 0 && S_ISLNK(st.st_mode));
        CHECK(stat(tmp("target.obj"), &st) == 0 && st.st_size > 100);
        remove(tmp("link.obj"));
    }
    remove(tmp("target.obj"));
    if (symlink(tmp("missing.obj"), tmp("dangling.obj")) == 0) {
        sprintf(line, "-n 8 -o %s cli/samples/helicoid.txt", tmp("dangling.obj"));
        CHECK_EQ_INT(run(line), 1);
        CHECK(strstr(err_text, "symbolic link") != NULL);
        CHECK(lstat(tmp("dangling.obj"), &st) == 0 && S_ISLNK(st.st_mode));
        remove(tmp("dangling.obj"));
    }
    /* -o an existing directory: the write fails, status 1, it stays */
    CHECK_EQ_INT(mkdir(tmp("dir.obj"), 0700), 0);
    sprintf(line, "-n 8 -o %s cli/samples/helicoid.txt", tmp("dir.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(stat(tmp("dir.obj"), &st) == 0 && S_ISDIR(st.st_mode));
    rmdir(tmp("dir.obj"));
    remove(tmp("boundary.obj"));
    free(before);
}

/* 1 when the file at path holds exactly text. */
static int file_is(const char *path, const char *text)
{
    static char now[65536];
    FILE *f = fopen(path, "rb");
    size_t n;
    if (!f) return 0;
    n = fread(now, 1, sizeof now - 1, f);
    fclose(f);
    now[n] = '\0';
    return strcmp(now, text) == 0;
}

/* Every output path is checked against the inputs and against the other
 * outputs before anything is solved, as -o is against the boundary: the
 * same file by any spelling ("./x", "sub/../x"), through a symbolic or a
 * hard link, or a boundary read from standard input, is bad usage (status
 * 2, nothing written, the boundary as it was); distinct outputs are
 * written. */
static void test_output_paths(void)
{
    static const char *const same[] = {
        "-o %s/x.obj --svg %s/x.obj", "-o %s/x.obj --svg %s/./x.obj", "--svg %s/x.obj -o %s/sub/../x.obj",
        "-o %s/sub/../x.obj --svg %s/x.obj --json"};
    const char *frame = "-1 -1 0\n1 -1 0.5\n1 1 0\n-1 1 0.5\n";
    char d[256], line[1024];
    struct stat st;
    size_t i;
    sprintf(d, "%s", tmp("paths"));
    CHECK_EQ_INT(mkdir(d, 0700), 0);
    sprintf(line, "%s/sub", d);
    CHECK_EQ_INT(mkdir(line, 0700), 0);
    sprintf(line, "%s/frame.txt", d);
    write_text(line, frame);
    /* --svg onto the boundary, by its name, another spelling, a link */
    sprintf(line, "-n 8 --svg %s/frame.txt %s/frame.txt", d, d);
    CHECK_EQ_INT(run(line), 2);
    CHECK_MSG(strstr(err_text, "frame.txt is the boundary file ") != NULL &&
                  strstr(err_text, ": the picture would replace it") != NULL, err_text);
    sprintf(line, "-n 8 --svg %s/sub/../frame.txt %s/frame.txt", d, d);
    CHECK_EQ_INT(run(line), 2);
    sprintf(line, "%s/frame.txt", d);
    sprintf(d + strlen(d), "/link.svg");
    if (symlink(line, d) == 0) {
        char svg[300];
        strcpy(svg, d);
        sprintf(line, "-n 8 --svg %s %s/frame.txt", svg, tmp("paths"));
        CHECK_EQ_INT(run(line), 2);
        remove(svg);
    }
    sprintf(d, "%s", tmp("paths"));
    /* a boundary on standard input that is the --svg file */
    sprintf(line, "%s/frame.txt", d);
    CHECK(freopen(line, "rb", stdin) != NULL);
    sprintf(line, "-n 8 --svg %s/frame.txt -", d);
    CHECK_EQ_INT(run(line), 2);
    CHECK_MSG(strstr(err_text, "is the boundary file on standard input, -: the picture would replace it") != NULL,
              err_text);
    sprintf(line, "%s/frame.txt", d);
    CHECK(file_is(line, frame));
    /* -o and --svg naming one file: refused, nothing written, whether or
     * not it exists already */
    for (i = 0; i < sizeof same / sizeof same[0]; i++) {
        char args[600];
        sprintf(args, same[i], d, d);
        sprintf(line, "-n 8 %s %s/frame.txt", args, d);
        CHECK_EQ_INT(run(line), 2);
        if (!CHECK(strstr(err_text, "are the same file: ") != NULL)) fprintf(stderr, "  %s: %s", args, err_text);
        sprintf(line, "%s/x.obj", d);
        CHECK(stat(line, &st) != 0);
    }
    CHECK(strstr(out_text, "{\"error\": \"-o ") == out_text && strstr(out_text, "\"exit\": 2}") != NULL);
    sprintf(line, "%s/x.obj", d);
    write_text(line, "# kept\n");
    sprintf(line, "-n 8 -o %s/x.obj --svg %s/sub/../x.obj %s/frame.txt", d, d, d);
    CHECK_EQ_INT(run(line), 2);
    CHECK_MSG(strstr(err_text, "the picture would replace the mesh") != NULL, err_text);
    sprintf(line, "%s/x.obj", d);
    CHECK(file_is(line, "# kept\n"));
    sprintf(line, "%s/hard.svg", d);
    {
        char x[300];
        sprintf(x, "%s/x.obj", d);
        if (link(x, line) == 0) {
            sprintf(line, "-n 8 -o %s/x.obj --svg %s/hard.svg %s/frame.txt", d, d, d);
            CHECK_EQ_INT(run(line), 2);
            sprintf(line, "%s/hard.svg", d);
            remove(line);
        }
        remove(x);
    }
    /* distinct outputs: both written */
    sprintf(line, "-n 8 -o %s/x.obj --svg %s/x.svg %s/frame.txt", d, d, d);
    CHECK_EQ_INT(run(line), 0);
    sprintf(line, "%s/x.obj", d);
    CHECK(stat(line, &st) == 0 && st.st_size > 0);
    remove(line);
    sprintf(line, "%s/x.svg", d);
    CHECK(stat(line, &st) == 0 && st.st_size > 0);
    remove(line);
    sprintf(line, "%s/frame.txt", d);
    remove(line);
    sprintf(line, "%s/sub", d);
    rmdir(line);
    rmdir(d);
}

/* --help and --version with a standard output that cannot be written:
 * status 1, not 0; a boundary file larger than the share of --max-memory
 * that reading may take (a sixth) is refused even when --max-input-bytes
 * is raised above it, and the message names --max-memory; a small one is
 * read. */
static void test_unwritable_output_and_read_cap(void)
{
    static char text[600000];
    char *argv[4], arg1[32], line[512], *p = text;
    FILE *ro = fopen("cli/samples/helicoid.txt", "rb"), *errout = fopen(tmp("err2"), "w+b");
    int i;
    CHECK(ro != NULL && errout != NULL);
    if (ro && errout) {
        argv[0] = (char *)"plateau";
        strcpy(arg1, "--help");
        argv[1] = arg1;
        argv[2] = NULL;
        CHECK_EQ_INT(plateau_cli_run(2, argv, ro, errout), 1);
        strcpy(arg1, "--version");
        CHECK_EQ_INT(plateau_cli_run(2, argv, ro, errout), 1);
    }
    if (ro) fclose(ro);
    if (errout) fclose(errout);
    remove(tmp("err2"));
    /* a 2000-vertex boundary of about 190 kB against --max-memory 1 (MB):
     * a cap of 174 762 bytes */
    for (i = 0; i < 2000; i++) {
        double t = 6.283185307179586 * i / 2000;
        p += sprintf(p, "%.17g %.17g %.17g   # a vertex of the big ring\n", cos(t), sin(t), 0.3 * cos(3 * t));
    }
    write_text(tmp("big.txt"), text);
    sprintf(line, "--max-input-bytes 100000000 --max-memory 1 -n 5 %s", tmp("big.txt"));
    CHECK(strlen(text) > 174762);
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "larger than the limit of 174762 bytes") != NULL);
    CHECK(strstr(err_text, "--max-memory raises it") != NULL);
    remove(tmp("big.txt"));
    CHECK_EQ_INT(run("--max-input-bytes 100000000 --max-memory 1 -n 5 cli/samples/helicoid.txt"), 0);
}

/* The limits a run hit are named with the option that moves them: a
 * solve refused by its memory estimate names --max-memory; a mesh cut
 * short by --max-seconds (a microsecond: the seeding alone takes longer)
 * is advised no limit (or a larger one), not another method. */
static void test_limits_advice(void)
{
    CHECK_EQ_INT(run("--max-memory 1000 -n 1000000 cli/samples/helicoid.txt"), 1);
    CHECK(strstr(err_text, "options.max_memory") == NULL);
    if (!CHECK(strstr(err_text, "--max-memory") != NULL)) fprintf(stderr, "  %s", err_text);
    CHECK_EQ_INT(run("--max-seconds 0.000001 cli/samples/helicoid.txt"), 3);
    CHECK(strstr(err_text, "time limit") != NULL || strstr(out_text, "time limit") != NULL);
    if (!CHECK(strstr(err_text, "what to try: --max-seconds 0 (no time limit; or one above 1e-06)\n") != NULL &&
               strstr(err_text, "--method") == NULL))
        fprintf(stderr, "  %s", err_text);
}

/* A boundary file that cannot be read: the message says why, in the
 * system's words (strerror), for a missing file and for a directory. */
static void test_unreadable_reason(void)
{
    char line[512], want[256];
    sprintf(line, "%s", tmp("missing.txt"));
    CHECK_EQ_INT(run(line), 1);
    sprintf(want, "missing.txt: cannot read the file: %s\n", strerror(ENOENT));
    if (!CHECK(strstr(err_text, want) != NULL)) fprintf(stderr, "  %s", err_text);
    CHECK_EQ_INT(run("cli"), 1);
    sprintf(want, "plateau: cli: cannot read the file: %s\n", strerror(EISDIR));
    if (!CHECK(strcmp(err_text, want) == 0)) fprintf(stderr, "  %s", err_text);
    sprintf(line, "cli/samples/helicoid.txt %s", tmp("missing.txt"));
    CHECK_EQ_INT(run(line), 1);
    sprintf(want, "missing.txt: cannot read the file: %s\n", strerror(ENOENT));
    CHECK(strstr(err_text, want) != NULL);
}

/* A number the tool echoes from its options prints as typed, the
 * shortest text that reads back as the same double: the pressure given
 * by --pressure, in the JSON and in the summary (the library's report
 * holds it scaled there and back: 0.9000000000000001). */
static void test_echoed_numbers(void)
{
    CHECK_EQ_INT(run("--pressure 0.9 --json cli/samples/sail-square.txt"), 0);
    if (!CHECK(strstr(out_text, "\"pressure\": 0.9,") != NULL)) fprintf(stderr, "  %.300s\n", out_text);
    CHECK_EQ_INT(run("--pressure 0.9 cli/samples/sail-square.txt"), 0);
    CHECK(strstr(out_text, "membrane   pressure 0.9, volume ") != NULL);
    CHECK_EQ_INT(run("--pressure 0.123456789012 cli/samples/sail-square.txt"), 0);
    if (!CHECK(strstr(out_text, "membrane   pressure 0.123456789012, volume ") != NULL))
        fprintf(stderr, "  %s", out_text);
    /* a held volume's pressure is the solve's, not an echo: 10 digits */
    CHECK_EQ_INT(run("--volume 0.1 cli/samples/helicoid.txt"), 0);
    CHECK(strstr(out_text, "membrane   pressure 0.07343888199, volume ") != NULL);
}

/* The tool's messages name its flags, not the library's option fields:
 * the stop of a run cut short by --max-seconds, and the refusals that
 * depend on the boundary (cables make a membrane; two loops). */
static void test_messages_name_flags(void)
{
    CHECK_EQ_INT(run("--max-seconds 0.000001 cli/samples/helicoid.txt"), 3);
    if (!CHECK(strstr(out_text, "  stop       time limit: --max-seconds ran out;") != NULL))
        fprintf(stderr, "  %s", out_text);
    CHECK(strstr(out_text, "options.") == NULL);
    CHECK_EQ_INT(run("--max-seconds 0.000001 --json cli/samples/helicoid.txt"), 3);
    CHECK(strstr(out_text, "\"stop\": \"time limit: --max-seconds ran out;") != NULL);
    CHECK_EQ_INT(run("--critical-index 1 cli/samples/sail-square.txt"), 1);
    if (!CHECK(strstr(err_text, "--critical-index and --least-area are of the area alone, not of a membrane "
                                "(--pressure, --volume or cables in the boundary file)") != NULL))
        fprintf(stderr, "  %s", err_text);
    CHECK(strstr(err_text, "critical_index") == NULL && strstr(err_text, "cable_tension") == NULL);
    CHECK_EQ_INT(run("--coarse-to-fine on cli/samples/two-rings.txt"), 1);
    if (!CHECK(strstr(err_text, "the solve failed: --coarse-to-fine on takes one polygon, not several loops") != NULL))
        fprintf(stderr, "  %s", err_text);
    CHECK_EQ_INT(run("--max-memory 1000 -n 1000000 cli/samples/helicoid.txt"), 1);
    CHECK(strstr(err_text, "(--max-memory raises it; 0: no limit)") != NULL);
}

/* Options that cannot go together are bad usage (status 2, before any
 * file is read), each pair named as typed: a membrane (--pressure not 0,
 * or --volume) with what is of the area alone, method paper-literal with
 * a membrane, and --coarse-to-fine on with what it cannot start from. */
static void test_conflicting_options(void)
{
    static const char *const pairs[][2] = {
        {"--pressure 0.5 --critical-index 1", "--pressure 0.5 and --critical-index 1 cannot go together"},
        {"--critical-index 2 --volume 0.1", "--volume 0.1 and --critical-index 2 cannot go together"},
        {"--pressure -0.2 --least-area", "--pressure -0.2 and --least-area cannot go together"},
        {"--volume 0 --least-area", "--volume 0 and --least-area cannot go together"},
        {"--coarse-to-fine on --pressure 1", "--pressure 1 and --coarse-to-fine on cannot go together"},
        {"--method paper-literal --pressure 1.6", "--method paper-literal and --pressure 1.6 cannot go together"},
        {"--volume 2 --method paper-literal", "--method paper-literal and --volume 2 cannot go together"},
        {"--coarse-to-fine on --method paper-literal",
         "--coarse-to-fine on and --method paper-literal cannot go together"},
        {"--seeding paper --coarse-to-fine on", "--coarse-to-fine on and --seeding paper cannot go together"},
        {"--coarse-to-fine on --keep-boundary", "--coarse-to-fine on and --keep-boundary cannot go together"}};
    char line[512];
    size_t i;
    for (i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        /* a missing boundary file: refused before it is read */
        sprintf(line, "%s %s", pairs[i][0], tmp("missing.txt"));
        CHECK_EQ_INT(run(line), 2);
        if (!CHECK(strstr(err_text, pairs[i][1]) != NULL && strstr(err_text, "Try 'plateau --help'.") != NULL))
            fprintf(stderr, "  %s: %s", pairs[i][0], err_text);
        CHECK_EQ_INT(out_text[0], '\0');
    }
    /* what is not a membrane, no saddle search or no coarse to fine goes */
    CHECK_EQ_INT(run("--pressure 0 --critical-index 1 --method paper-literal cli/samples/helicoid.txt"), 3);
    CHECK_EQ_INT(run("--pressure 0.5 --critical-index 0 --coarse-to-fine off cli/samples/helicoid.txt"), 0);
    CHECK_EQ_INT(run("--coarse-to-fine auto --seeding paper --keep-boundary cli/samples/helicoid.txt"), 0);
}

/* --edge-length L: the library's quality_edge_length, the quality
 * seeding with interior edges about L long instead of about n points (a
 * shorter L, more points); echoed as typed; a length above 0; not with
 * -n, --seeding paper or --coarse-to-fine on; in --help. */
static void test_edge_length(void)
{
    static const char *const bad[] = {"0", "-0.1", "abc", "inf", "nan", "0.2x", ""};
    const char *f;
    long fine, coarse;
    char line[256];
    size_t i;
    CHECK_EQ_INT(run("--edge-length 0.4 --json cli/samples/helicoid.txt"), 0);
    CHECK(strstr(out_text, "\"edge_length\": 0.4,") != NULL);
    CHECK(strstr(out_text, "\"seeding\": \"quality\"") != NULL);
    f = json_field(out_text, "interior_points");
    coarse = f ? atol(f) : -1;
    CHECK_EQ_INT(run("--edge-length 0.2 --json cli/samples/helicoid.txt"), 0);
    f = json_field(out_text, "interior_points");
    fine = f ? atol(f) : -1;
    if (!CHECK(coarse > 0 && fine > 3 * coarse)) fprintf(stderr, "  interior points %ld (L 0.4), %ld (L 0.2)\n", coarse, fine);
    CHECK_EQ_INT(run("--edge-length=0.2 cli/samples/helicoid.txt"), 0);
    if (!CHECK(strstr(out_text, "  method     paper, seed 0, edge length 0.2 asked\n") != NULL))
        fprintf(stderr, "  %s", out_text);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        sprintf(line, "--edge-length=%s cli/samples/helicoid.txt", bad[i]);
        CHECK_EQ_INT(run(line), 2);
        CHECK_MSG(strstr(err_text, "--edge-length wants a length above 0") != NULL, err_text);
    }
    CHECK_EQ_INT(run("--edge-length 0.2 -n 30 cli/samples/helicoid.txt"), 2);
    CHECK_MSG(strstr(err_text, "-n 30 and --edge-length 0.2 cannot go together") != NULL, err_text);
    CHECK_EQ_INT(run("--edge-length 0.2 --seeding paper cli/samples/helicoid.txt"), 2);
    CHECK_MSG(strstr(err_text, "--edge-length 0.2 and --seeding paper cannot go together") != NULL, err_text);
    CHECK_EQ_INT(run("--edge-length 0.2 --coarse-to-fine on cli/samples/helicoid.txt"), 2);
    CHECK_MSG(strstr(err_text, "--coarse-to-fine on and --edge-length 0.2 cannot go together") != NULL, err_text);
    /* the seed has no effect: the edge length asks for the quality seeding */
    CHECK_EQ_INT(run("--edge-length 0.3 --seed 4 cli/samples/helicoid.txt"), 0);
    CHECK_MSG(strstr(err_text, "--seed 4 has no effect: the seeding here is the Delaunay refinement "
                               "(--edge-length)") != NULL, err_text);
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "  --edge-length L ") != NULL);
}

/* --json on a failure prints one JSON object on stdout instead of
 * nothing: {"error": the message, "code": the plateau_result's name,
 * "exit": the status}, its strings escaped; the message still goes to
 * stderr. */
static void test_json_errors(void)
{
    char line[512], want[512];
    CHECK_EQ_INT(run("--json --bogus cli/samples/helicoid.txt"), 2);
    if (!CHECK(strcmp(out_text, "{\"error\": \"unknown option '--bogus'\", \"code\": \"PLATEAU_ERR_ARGUMENT\", "
                                "\"exit\": 2}\n") == 0))
        fprintf(stderr, "  %s", out_text);
    CHECK(strstr(err_text, "plateau: unknown option '--bogus'\nTry 'plateau --help'.\n") != NULL);
    CHECK_EQ_INT(run("--bogus --json cli/samples/helicoid.txt"), 2); /* --json after the bad option */
    CHECK(json_valid(out_text, NULL, NULL) && strstr(out_text, "\"exit\": 2") != NULL);
    CHECK_EQ_INT(run("--json --pressure 1 --least-area cli/samples/two-rings.txt"), 2);
    CHECK(json_valid(out_text, NULL, NULL) && strstr(out_text, "cannot go together") != NULL);
    CHECK_EQ_INT(run("--json"), 2);
    CHECK(strstr(out_text, "{\"error\": \"no boundary file given\"") == out_text);
    /* a name with a quote and a backslash: escaped */
    sprintf(line, "--json %s", tmp("q\"uo\\te.txt"));
    CHECK_EQ_INT(run(line), 1);
    if (!CHECK(json_valid(out_text, NULL, NULL))) fprintf(stderr, "  %s", out_text);
    sprintf(want, "q\\\"uo\\\\te.txt: cannot read the file: %s\", \"code\": \"PLATEAU_ERR_IO\", \"exit\": 1}\n",
            strerror(ENOENT));
    if (!CHECK(strstr(out_text, want) != NULL)) fprintf(stderr, "  %s  want ...%s", out_text, want);
    write_text(tmp("bad.txt"), "0 0 0\n1 0 0\n1 1 one\n");
    sprintf(line, "--json %s", tmp("bad.txt"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(json_valid(out_text, NULL, NULL) && strstr(out_text, "line 3: field 3 is not a number: \\\"one\\\"\", "
                                                                "\"code\": \"PLATEAU_ERR_PARSE\"") != NULL);
    remove(tmp("bad.txt"));
    CHECK_EQ_INT(run("--json --max-memory 1000 -n 1000000 cli/samples/helicoid.txt"), 1);
    CHECK(json_valid(out_text, NULL, NULL));
    if (!CHECK(strstr(out_text, "{\"error\": \"cli/samples/helicoid.txt: the solve failed: the solve would need "
                                "about ") == out_text &&
               strstr(out_text, "(--max-memory raises it; 0: no limit)\", \"code\": \"PLATEAU_ERR_MEMORY_LIMIT\", "
                                "\"exit\": 1}\n") != NULL))
        fprintf(stderr, "  %s", out_text);
    sprintf(line, "--json -o %s cli/samples/helicoid.txt", tmp("nodir/m.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(json_valid(out_text, NULL, NULL) && strstr(out_text, "\"code\": \"PLATEAU_ERR_IO\"") != NULL);
    /* no --json: nothing on stdout */
    CHECK_EQ_INT(run("--bogus cli/samples/helicoid.txt"), 2);
    CHECK_EQ_INT(out_text[0], '\0');
}

/* A 7 x 7 grid over [-1, 1]^2 on the saddle z = x y with a bump
 * 0.3 (1 - x^2)(1 - y^2) inside, as quads (OBJ) or their triangles (OFF):
 * its rim is the saddle's straight-edged frame. */
static void write_saddle_mesh(const char *path, int off)
{
    const int n = 7;
    FILE *f = fopen(path, "wb");
    int i, j;
    if (!f) return;
    if (off) fprintf(f, "OFF\n%d %d 0\n", n * n, 2 * (n - 1) * (n - 1));
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            double x = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
            fprintf(f, "%s%.17g %.17g %.17g\n", off ? "" : "v ", x, y, x * y + 0.3 * (1 - x * x) * (1 - y * y));
        }
    for (j = 0; j < n - 1; j++)
        for (i = 0; i < n - 1; i++) {
            int a = j * n + i;
            if (off) fprintf(f, "3 %d %d %d\n3 %d %d %d\n", a, a + 1, a + 1 + n, a, a + 1 + n, a + n);
            else fprintf(f, "f %d %d %d %d\n", a + 1, a + 2, a + 2 + n, a + 1 + n);
        }
    fclose(f);
}

/* --minimize FILE: a saddle mesh (OBJ, OFF; methods paper and area) keeps
 * its rim bit for bit while its area falls and it becomes valid; the
 * summary and the JSON say so; a mesh that is no surface with a boundary
 * (an edge of three triangles, a closed surface) or a bad file is refused
 * with status 1 and the reason (the file line); options that seed are bad
 * usage with it, and so are boundary files and an output naming it. */
static void test_minimize(void)
{
    static const char *const runs[] = {"--json --minimize %s -o %s", "--json --method area --minimize %s -o %s",
                                       "--json --minimize %s -o %s"};
    char line[1024], in[256], out[256];
    size_t r;
    for (r = 0; r < sizeof runs / sizeof runs[0]; r++) {
        double *p = NULL, *q = NULL, area, before;
        plateau_index *t = NULL, *qt = NULL;
        size_t nv = 0, nt = 0, qv = 0, qn = 0, v, moved = 0, rim = 0;
        const char *f;
        strcpy(in, tmp(r == 2 ? "saddle.off" : "saddle.obj"));
        strcpy(out, tmp("minimized.obj"));
        write_saddle_mesh(in, r == 2);
        sprintf(line, runs[r], in, out);
        CHECK_EQ_INT(run(line), 0);
        CHECK_MSG(strstr(out_text, "\"minimize\": true, \"initial_area\": ") != NULL, line);
        f = json_field(out_text, "area");
        area = f ? atof(f) : -1.0;
        f = json_field(out_text, "initial_area");
        before = f ? atof(f) : -1.0;
        if (!CHECK(area > 0.0 && area < before - 0.05)) fprintf(stderr, "  %s: area %g, before %g\n", line, area, before);
        CHECK(strstr(out_text, "\"boundary_vertices\": 24, \"boundary_length\": 11.31") != NULL);
        CHECK(strstr(out_text, "\"vertices\": 49, \"triangles\": 72") != NULL);
        CHECK(strstr(out_text, "\"loops\": 1,") != NULL && strstr(out_text, "\"valid\": true") != NULL);
        CHECK(strstr(out_text, "\"removed_vertices\": 0") != NULL);
        CHECK(json_field(out_text, "domain") == NULL && json_field(out_text, "seeding") == NULL);
        CHECK(plateau_read_mesh_file(in, NULL, &p, &nv, &t, &nt, NULL) == PLATEAU_OK);
        CHECK(plateau_read_mesh_file(out, NULL, &q, &qv, &qt, &qn, NULL) == PLATEAU_OK);
        if (CHECK(p && q && nv == 49 && qv == 49)) {
            for (v = 0; v < nv; v++) {
                int on_rim = v % 7 == 0 || v % 7 == 6 || v / 7 == 0 || v / 7 == 6;
                int same = memcmp(p + 3 * v, q + 3 * v, 3 * sizeof(double)) == 0;
                rim += on_rim && same;
                moved += !on_rim && !same;
            }
            CHECK_EQ_INT(rim, 24);  /* the boundary, bit for bit */
            CHECK_EQ_INT(moved, 25); /* every interior vertex moved */
        }
        plateau_mesh_arrays_free(p, t, NULL, NULL);
        plateau_mesh_arrays_free(q, qt, NULL, NULL);
        remove(in);
        remove(out);
    }
    write_saddle_mesh(tmp("saddle.obj"), 0);
    sprintf(line, "--minimize %s", tmp("saddle.obj"));
    CHECK_EQ_INT(run(line), 0);
    CHECK(strstr(out_text, "  input      a mesh to minimise (--minimize), area 5.337302791\n"
                           "  boundary   24 vertices in 1 loop (its edges of one triangle), kept\n"
                           "  method     paper\n") != NULL);
    CHECK(strstr(out_text, "seeding") == NULL && strstr(out_text, "check      valid") != NULL);
    /* refusals: the reason, with the file line */
    write_text(tmp("nm.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\n# a third\nf 1 2 5\n");
    sprintf(line, "--minimize %s", tmp("nm.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK_MSG(strstr(err_text, "nm.obj: an edge has more than two triangles (triangle 2, of the face on line 9)\n") !=
                  NULL, err_text);
    write_text(tmp("nm.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n");
    sprintf(line, "--json --minimize %s", tmp("nm.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK_MSG(strstr(out_text, "nm.obj: line 4: vertex index reaches before the first vertex (3 vertices come "
                               "before the line): \\\"-9\\\"\", \"code\": \"PLATEAU_ERR_PARSE\", \"exit\": 1}") != NULL,
              out_text);
    write_text(tmp("nm.obj"), "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(out_text, "PLATEAU_ERR_NOT_FINITE") != NULL);
    write_text(tmp("nm.obj"), "");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(out_text, "no face") != NULL);
    remove(tmp("nm.obj"));
    write_text(tmp("tet.off"), "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    sprintf(line, "--minimize %s", tmp("tet.off"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "tet.off: the mesh has no boundary (every edge has two triangles)") != NULL);
    remove(tmp("tet.off"));
    /* bad usage */
    sprintf(line, "--minimize %s -n 8", tmp("saddle.obj"));
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "saddle.obj and -n 8 cannot go together: the mesh's vertices are the points") != NULL);
    sprintf(line, "--minimize %s --circle", tmp("saddle.obj"));
    CHECK_EQ_INT(run(line), 2);
    sprintf(line, "--minimize %s cli/samples/helicoid.txt", tmp("saddle.obj"));
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "takes a mesh in place of boundary files") != NULL);
    sprintf(line, "--minimize %s -o %s", tmp("saddle.obj"), tmp("saddle.obj"));
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "is the mesh file ") != NULL);
    remove(tmp("saddle.obj"));
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "--minimize FILE") != NULL);
}

/* ---- advice that is followed (plateau_cli_print_advice) ---- */

#define ADVICE_TRIES 8
/* The tries of a run's advice ("plateau: what to try: A; B or C; ..."):
 * each alternative as the options it names, with their values, outside
 * parentheses (the why). */
typedef struct advice {
    char line[1024];                 /* the advice line, "" when none */
    char opts[ADVICE_TRIES][256];
    int count;
    int bare;                        /* alternatives that name no option */
} advice;

/* What a run of the tool came to: the status, the failure's signature
 * (the mesh's counts and area, the defect bits) and the advice. */
typedef struct outcome {
    int status;
    char sig[256];
    advice adv;
} outcome;

/* Appends the options named in [s, s + len) (text in parentheses left
 * out) to out; returns how many. */
static int advice_options(const char *s, size_t len, char *out, size_t size)
{
    char buf[512], *tok, *save = NULL;
    size_t i, k = 0;
    int depth = 0, found = 0, want_value = 0;
    for (i = 0; i < len && k + 1 < sizeof buf; i++) {
        if (s[i] == '(') depth++;
        else if (s[i] == ')') depth -= depth > 0;
        else if (depth == 0) buf[k++] = s[i];
    }
    buf[k] = '\0';
    out[0] = '\0';
    for (tok = strtok_r(buf, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
        size_t n = strlen(tok);
        while (n > 0 && (tok[n - 1] == ',' || tok[n - 1] == ';')) tok[--n] = '\0';
        if (want_value) {
            if (strlen(out) + n + 2 < size) strcat(strcat(out, " "), tok);
            want_value = 0;
            continue;
        }
        if (tok[0] == '-' && plateau_cli_find_option(tok)) {
            const plateau_cli_option *o = plateau_cli_find_option(tok);
            if (strlen(out) + n + 2 < size) strcat(strcat(out, out[0] ? " " : ""), tok);
            want_value = o->kind != PLATEAU_CLI_FLAG;
            found++;
        }
    }
    return found;
}

static void advice_parse(const char *err, advice *a)
{
    const char *s = strstr(err, "plateau: what to try: "), *end, *p;
    memset(a, 0, sizeof *a);
    if (!s) return;
    end = strchr(s, '\n');
    if (!end) end = s + strlen(s);
    sprintf(a->line, "%.*s", (int)(end - s < 1000 ? end - s : 1000), s);
    p = s + strlen("plateau: what to try: ");
    while (p < end && a->count < ADVICE_TRIES) {
        /* one try: up to "; " outside parentheses; its alternatives split at " or " */
        const char *q = p, *alt = p;
        int depth = 0;
        for (; q < end && !(depth == 0 && q[0] == ';'); q++) {
            if (*q == '(') depth++;
            else if (*q == ')') depth -= depth > 0;
            if (depth == 0 && strncmp(q, " or ", 4) == 0) {
                if (a->count < ADVICE_TRIES && advice_options(alt, (size_t)(q - alt), a->opts[a->count], 256))
                    a->count++;
                else a->bare++;
                alt = q + 4;
            }
        }
        if (a->count < ADVICE_TRIES && advice_options(alt, (size_t)(q - alt), a->opts[a->count], 256)) a->count++;
        else a->bare++;
        p = q < end ? q + 2 : end;
    }
}

/* cmd with the options of opts: each replaces the options of cmd that
 * set the same field (-n replaces -n, --method --method, --refine-boundary
 * --keep-boundary), then it is appended. */
static void advice_apply(const char *cmd, const char *opts, char *out, size_t size)
{
    char c[1024], o[512], *tok, *save = NULL, *tokens[64];
    int n = 0, i;
    snprintf(c, sizeof c, "%s", cmd);
    snprintf(o, sizeof o, "%s", opts);
    for (tok = strtok_r(c, " ", &save); tok && n < 64; tok = strtok_r(NULL, " ", &save)) tokens[n++] = tok;
    out[0] = '\0';
    for (i = 0; i < n; i++) {
        const plateau_cli_option *ot = tokens[i][0] == '-' ? plateau_cli_find_option(tokens[i]) : NULL;
        char *t2, *save2 = NULL, o2[512];
        int replaced = 0;
        if (ot) {
            snprintf(o2, sizeof o2, "%s", opts);
            for (t2 = strtok_r(o2, " ", &save2); t2; t2 = strtok_r(NULL, " ", &save2)) {
                const plateau_cli_option *oa = t2[0] == '-' ? plateau_cli_find_option(t2) : NULL;
                if (oa && oa->offset == ot->offset) replaced = 1;
            }
        }
        if (replaced) {
            if (ot->kind != PLATEAU_CLI_FLAG) i++; /* its value too */
            continue;
        }
        if (strlen(out) + strlen(tokens[i]) + 2 < size) strcat(strcat(out, out[0] ? " " : ""), tokens[i]);
    }
    if (strlen(out) + strlen(o) + 2 < size) strcat(strcat(out, " "), o);
}

static void outcome_of(const char *cmd, outcome *o)
{
    static const char *const keys[] = {"vertices", "triangles", "area", "defects"};
    size_t k;
    o->status = run(cmd);
    sprintf(o->sig, "status %d", o->status);
    for (k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        const char *f = json_field(out_text, keys[k]);
        size_t len = f ? strcspn(f, ",}") : 0;
        sprintf(o->sig + strlen(o->sig), ", %s %.*s", keys[k], (int)(len < 40 ? len : 40), f ? f : "-");
    }
    advice_parse(err_text, &o->adv);
}

/* Runs every piece of the advice of cmd (whose outcome is o), and of what
 * that advises in turn, depth levels deep: each must end valid (status 0)
 * or fail otherwise: another mesh or defects than every run before it on
 * the chain (no loop, no same failure), and other advice than its
 * parent's; and every alternative must name an option to run.  runs
 * counts the runs. */
static void advice_follow(const char *cmd, const outcome *o, int depth, char chain[][256], int nchain, int *runs)
{
    int t, j;
    if (!CHECK_MSG(o->adv.bare == 0, o->adv.line)) fprintf(stderr, "  advice with a try that names no option\n");
    for (t = 0; t < o->adv.count; t++) {
        char next[1024];
        outcome *n = (outcome *)malloc(sizeof *n);
        int loop = -1;
        if (!n) return;
        advice_apply(cmd, o->adv.opts[t], next, sizeof next);
        outcome_of(next, n);
        (*runs)++;
        for (j = 0; j < nchain && n->status != 0; j++)
            if (strcmp(chain[j], n->sig) == 0) loop = j;
        if (!CHECK(n->status == 0 || (n->status == 3 && loop < 0 && strcmp(n->adv.line, o->adv.line) != 0))) {
            fprintf(stderr, "  %s\n    (%s)\n    %s\n  advised: %s\n    (%s)\n    %s\n", cmd, o->sig, o->adv.line, next,
                    n->sig, n->adv.line[0] ? n->adv.line : err_text);
            if (loop >= 0) fprintf(stderr, "    the same failure as %d runs before\n", nchain - loop);
        }
        if (n->status == 3 && depth > 1 && nchain < 8) {
            strcpy(chain[nchain], n->sig);
            advice_follow(next, n, depth - 1, chain, nchain + 1, runs);
        }
        free(n);
    }
}

/* 4 vertices of a skew quadrilateral, z = 0, 2, 0, 2: -n 1 gives one
 * interior point and an inverted fan. */
static void write_saddle4(const char *path)
{
    write_text(path, "-1 -1 0\n1 -1 2\n1 1 0\n-1 1 2\n");
}

/* Two coaxial rings of radius 1, 24 vertices each, h apart. */
static void write_rings(const char *path, double h)
{
    char text[4096], *p = text;
    int ring, i;
    for (ring = 0; ring < 2; ring++) {
        if (ring) p += sprintf(p, "\n");
        for (i = 0; i < 24; i++)
            p += sprintf(p, "%.17g %.17g %.17g\n", cos(6.283185307179586 * i / 24), sin(6.283185307179586 * i / 24),
                         ring ? h / 2 : -h / 2);
    }
    write_text(path, text);
}

/* Every piece of advice the tool prints is run: on a set of failing
 * inputs, one or more for each branch of plateau_cli_print_advice, each
 * advised command line (and what that one advises, a level deeper) gives
 * a valid mesh or another failure with other advice, never the same
 * failure and never a loop back: --pressure 5 on a 2 x 2 square (methods
 * paper and area; they advised each other before), a pinched two-ring
 * film (it never named --least-area), a failed --critical-index 1 (it
 * advised another method where a finer -n works), -n 1 on a 4-point
 * saddle (it advised -n 2, which gives the same mesh), paper-literal, the
 * paper's fan, a knot, a held volume, --edge-length, a time limit and a
 * minimised mesh. */
static void test_advice_followed(void)
{
    char square[256], saddle4[256], pinch[256], rings[256], knot[256], coarse[256], mesh[256], chain[8][256];
    char cmds[24][512], text[8192], *p = text, l[600];
    static char lines[24][1024];
    int depth[24];
    size_t c, ncmds = 0;
    int runs = 0, i;
    FILE *f;
    strcpy(square, tmp("square.txt"));
    strcpy(saddle4, tmp("saddle4.txt"));
    strcpy(pinch, tmp("pinch.txt"));
    strcpy(rings, tmp("rings02.txt"));
    strcpy(knot, tmp("trefoil.txt"));
    strcpy(mesh, tmp("fold.obj"));
    write_text(square, "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n");
    write_saddle4(saddle4);
    write_rings(pinch, 1.5);
    write_rings_of(rings, 16, 0.2, 0.0); /* its thin neck: 16 vertices a ring are too few at 4 m */
    for (i = 0; i < 60; i++) {
        double t = 6.283185307179586 * i / 60;
        p += sprintf(p, "%.17g %.17g %.17g\n", sin(t) + 2 * sin(2 * t), cos(t) - 2 * cos(2 * t), -sin(3 * t));
    }
    write_text(knot, text);
    /* every 4th vertex of the twisted helicoid: 14 vertices, long edges */
    strcpy(coarse, tmp("turns14.txt"));
    f = fopen("cli/samples/helicoid-turns.txt", "rb");
    p = text;
    for (i = 0; f && fgets(l, sizeof l, f);)
        if (l[0] != '#' && l[0] != '\n' && i++ % 4 == 0) p += sprintf(p, "%s", l);
    if (f) fclose(f);
    write_text(coarse, text);
    /* a folded mesh to minimise: paper-literal's on it */
    sprintf(l, "--method paper-literal -n 20 -o %s %s", mesh, coarse);
    CHECK_EQ_INT(run(l), 3);
    /* make test-full follows the advice of the advice too; make test once */
    for (c = 0; c < 24; c++) depth[c] = HARNESS_FULL ? 2 : 1;
    sprintf(cmds[ncmds++], "--json --pressure 5 %s", square);
    sprintf(cmds[ncmds++], "--json --pressure 5 --method area %s", square);
    sprintf(cmds[ncmds++], "--json --pressure -3 %s", square);
    sprintf(cmds[ncmds++], "--json --volume 2 %s", square);
    sprintf(cmds[ncmds++], "--json %s", pinch);
    sprintf(cmds[ncmds++], "--json --method area %s", pinch);
    /* -n 64, the first count of the default (which runs again at 4 m, 8 m, 16 m) */
    sprintf(cmds[ncmds++], "--json --critical-index 1 -n 64 %s", rings);
    sprintf(cmds[ncmds++], "--json --critical-index 1 --method area -n 64 %s", rings);
    sprintf(cmds[ncmds++], "--json -n 1 %s", saddle4);
    sprintf(cmds[ncmds++], "--json -n 1 --method area %s", saddle4);
    sprintf(cmds[ncmds++], "--json -n 2 %s", saddle4);
    /* -n 56 (paper-literal's count, m): the advised --method paper and
     * area then solve once at it, not at the default accuracy's counts */
    sprintf(cmds[ncmds++], "--json --method paper-literal -n 56 cli/samples/helicoid-turns.txt");
    sprintf(cmds[ncmds++], "--json -n 56 --seeding paper cli/samples/helicoid-turns.txt");
    sprintf(cmds[ncmds++], "--json %s", knot);
    sprintf(cmds[ncmds++], "--json --max-seconds 0.000001 cli/samples/helicoid.txt");
    sprintf(cmds[ncmds++], "--json --method paper-literal -n 40 %s", coarse);
    sprintf(cmds[ncmds++], "--json -n 20 %s", coarse);
    depth[ncmds] = 1; /* --edge-length 0.25 would take seconds */
    sprintf(cmds[ncmds++], "--json --method paper-literal --edge-length 1 %s", coarse);
    sprintf(cmds[ncmds++], "--json --method paper-literal --minimize %s", mesh);
    for (c = 0; c < ncmds; c++) {
        outcome *o = (outcome *)malloc(sizeof *o);
        if (!o) return;
        outcome_of(cmds[c], o);
        runs++;
        if (!CHECK_MSG(o->status == 3 && o->adv.count > 0, cmds[c])) fprintf(stderr, "  %s", err_text);
        sprintf(lines[c], "%.1000s", o->adv.line);
        strcpy(chain[0], o->sig);
        advice_follow(cmds[c], o, depth[c], chain, 1, &runs);
        free(o);
    }
    printf("advice: %lu failing runs, %d runs in all\n", (unsigned long)ncmds, runs);
    /* the advice of the issues' cases, and each branch of the advice */
    CHECK_MSG(strstr(lines[0], "what to try: --pressure 1.41 (no film of pressure 5 spans this frame; one does "
                               "for a pressure up to 2 / R = 1.414") != NULL && strstr(lines[0], "--method") == NULL,
              lines[0]);
    CHECK_MSG(strstr(lines[1], "what to try: --pressure 1.41 (no film of pressure 5 spans") != NULL, lines[1]);
    CHECK_MSG(strstr(lines[2], "what to try: --pressure -1.41 (") != NULL, lines[2]);
    CHECK_MSG(strstr(lines[3], "--volume 1 (a smaller volume") != NULL, lines[3]);
    CHECK_MSG(strstr(lines[4], "what to try: --least-area (") != NULL, lines[4]);
    CHECK_MSG(strstr(lines[6], "what to try: -n 472 (a finer mesh)") != NULL && strstr(lines[6], "--method") == NULL,
              lines[6]);
    CHECK_MSG(strstr(lines[8], "what to try: -n 4 (a finer mesh)") != NULL, lines[8]);
    CHECK_MSG(strstr(lines[10], "what to try: -n 4 (a finer mesh)") != NULL, lines[10]); /* -n 2 placed one point */
    CHECK_MSG(strstr(lines[11], "what to try: --method paper or --method area (") != NULL, lines[11]);
    CHECK_MSG(strstr(lines[13], "what to try: --method area (") != NULL, lines[13]);
    CHECK_MSG(strstr(lines[14], "what to try: --max-seconds 0 (") != NULL, lines[14]);
    CHECK_MSG(strstr(lines[15], "--refine-boundary (") != NULL, lines[15]);
    CHECK_MSG(strstr(lines[17], "--edge-length 0.5 (a finer mesh)") != NULL, lines[17]);
    CHECK_MSG(strstr(lines[18], "what to try: --method paper or --method area (") != NULL &&
              strstr(lines[18], "-n ") == NULL, lines[18]);
    remove(square);
    remove(saddle4);
    remove(pinch);
    remove(rings);
    remove(knot);
    remove(coarse);
    remove(mesh);
}

/* The whole of the file at path (static; "" when it cannot be read). */
static const char *file_text(const char *path, size_t *len)
{
    static char text[1 << 20];
    FILE *f = fopen(path, "rb");
    size_t n = 0;
    if (f) {
        n = fread(text, 1, sizeof text - 1, f);
        fclose(f);
    }
    text[n] = '\0';
    if (len) *len = n;
    return text;
}

/* -o marks the frame and the cables: a PLY's vertex property "boundary"
 * (read by a small PLY reader: 1 at the 4 anchors of the cable sail, 2 at
 * the vertices the solve put on its cables, 0 inside), an OBJ's groups
 * "boundary" (one closed polyline over the loop) and "cables" (one
 * polyline per cable, anchor to anchor), and the OBJ reads back through
 * plateau_parse_mesh as the mesh the JSON describes. */
static void test_marked_output(void)
{
    char line[512];
    const char *text, *p;
    size_t len, nv = 0, nt = 0;
    long vertices, triangles, count[3] = {0, 0, 0}, polylines = 0;
    double *q = NULL;
    plateau_index *qt = NULL;
    sprintf(line, "--json -o %s cli/samples/sail-square.txt", tmp("sail.ply"));
    CHECK_EQ_INT(run(line), 0);
    vertices = json_field(out_text, "vertices") ? atol(json_field(out_text, "vertices")) : -1;
    triangles = json_field(out_text, "triangles") ? atol(json_field(out_text, "triangles")) : -1;
    text = file_text(tmp("sail.ply"), NULL);
    CHECK(strstr(text, "property double z\nproperty uchar boundary\n") != NULL);
    p = strstr(text, "end_header\n");
    if (CHECK(p != NULL)) {
        long v;
        p += strlen("end_header\n");
        for (v = 0; v < vertices; v++) { /* x y z mark, a line each */
            unsigned mark = 9;
            if (sscanf(p, "%*s %*s %*s %u", &mark) != 1 || mark > 2) break;
            count[mark]++;
            p = strchr(p, '\n') + 1;
        }
        CHECK_EQ_INT(v, vertices);
    }
    if (!CHECK(count[1] == 4 && count[2] >= 4 && count[0] > 0))
        fprintf(stderr, "  marks: %ld interior, %ld boundary, %ld cable\n", count[0], count[1], count[2]);
    remove(tmp("sail.ply"));
    sprintf(line, "--json -o %s cli/samples/sail-square.txt", tmp("sail.obj"));
    CHECK_EQ_INT(run(line), 0);
    text = file_text(tmp("sail.obj"), &len);
    p = strstr(text, "\ng boundary\nl 1 ");
    CHECK(p != NULL && strstr(text, "\ng film\nf ") != NULL);
    for (p = p ? strstr(p, "\ng cables\n") : NULL; p && (p = strstr(p + 1, "\nl ")) != NULL;) polylines++;
    CHECK_EQ_INT(polylines, 4);
    CHECK_EQ_INT(plateau_parse_mesh(text, len, NULL, &q, &nv, &qt, &nt, NULL, NULL), PLATEAU_OK);
    CHECK((long)nv == vertices && (long)nt == triangles);
    plateau_mesh_arrays_free(q, qt, NULL, NULL);
    remove(tmp("sail.obj"));
}

/* A boundary exported from a spreadsheet as CSV ("x,y,z" or "x;y;z"
 * lines after one header line of column names) is read as the same
 * polygon as its "x y z" lines; --help says the tool reads it. */
static void test_csv_boundary(void)
{
    static const char *const texts[] = {"-1 -1 0\n1 -1 0.5\n1 1 0\n-1 1 0.5\n",
                                        "x,y,z\n-1,-1,0\n1,-1,0.5\n1,1,0\n-1,1,0.5\n",
                                        "\"x\";\"y\";\"z\"\r\n-1; -1; 0\r\n1;-1;0.5\r\n1;1;0\r\n-1;1;0.5\r\n"};
    char line[512], first[65536];
    size_t i;
    for (i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        write_text(tmp("frame.csv"), texts[i]);
        sprintf(line, "--json -n 12 %s", tmp("frame.csv"));
        CHECK_EQ_INT(run(line), 0);
        CHECK(strstr(out_text, "\"boundary_vertices\": 4,") != NULL);
        if (i == 0) {
            strcpy(first, strstr(out_text, "\"vertices\"") ? strstr(out_text, "\"vertices\"") : "");
            if (strstr(first, "\"elapsed_s\"")) *strstr(first, "\"elapsed_s\"") = '\0';
        } else {
            const char *v = strstr(out_text, "\"vertices\"");
            CHECK_MSG(v && first[0] && strncmp(v, first, strlen(first)) == 0, texts[i]); /* the same mesh */
        }
    }
    remove(tmp("frame.csv"));
    CHECK_EQ_INT(run("--help"), 0);
    CHECK(strstr(out_text, "CSV") != NULL && strstr(out_text, "\"x;y;z\"") != NULL &&
          strstr(out_text, "header line") != NULL);
}

/* --pattern: the tool's own result and a mesh given with --mesh cut into
 * panels that fit the roll, the JSON's pattern object, the SVG and DXF
 * written; the options refused without --pattern or with what --mesh does
 * not do; the pattern's files checked against the inputs and the other
 * outputs; a film no spacing fits fails with its reason. */
static void test_pattern(void)
{
    char line[1024], svg[256], dxf[256], mesh[256];
    const char *p;
    int panels = 0;
    FILE *f;
    strcpy(svg, tmp("pat.svg"));
    strcpy(dxf, tmp("pat.dxf"));
    strcpy(mesh, tmp("pat-saddle.obj"));
    write_saddle_mesh(mesh, 0);
    sprintf(line, "--json -n 60 --pattern 0.6 --pattern-marks 0.25 --pattern-svg %s --pattern-dxf %s "
                  "cli/samples/helicoid.txt", svg, dxf);
    CHECK_EQ_INT(run(line), 0);
    CHECK(json_valid(out_text, NULL, NULL));
    CHECK((p = strstr(out_text, "\"pattern\": {\"roll_width\": 0.6, \"panels\": [")) != NULL);
    for (p = out_text; (p = strstr(p, "\"area_3d\"")) != NULL; p++) panels++;
    CHECK(panels >= 2);
    for (p = out_text; (p = strstr(p, "\"width\": ")) != NULL; p++) CHECK(atof(p + 9) <= 0.6);
    CHECK(strstr(out_text, "\"pattern_svg_file\": ") != NULL && strstr(out_text, "\"pattern_dxf_file\": ") != NULL);
    f = fopen(svg, "rb");
    CHECK(f != NULL);
    if (f) fclose(f);
    f = fopen(dxf, "rb");
    CHECK(f != NULL);
    if (f) {
        char tail[16] = "";
        fseek(f, -6, SEEK_END);
        CHECK(fread(tail, 1, 6, f) == 6);
        CHECK(strncmp(tail, "0\nEOF\n", 6) == 0);
        fclose(f);
    }
    remove(svg);
    remove(dxf);
    /* the summary: a line per panel */
    CHECK_EQ_INT(run("-n 60 --pattern 0.6 --pattern-seams axis --pattern-direction 0,0,1 --pattern-point 0,0,0 "
                     "cli/samples/helicoid.txt"), 0);
    CHECK(strstr(out_text, "  pattern    ") != NULL && strstr(out_text, "  panel 0 ") != NULL);
    /* a mesh given with --mesh: nothing solved */
    sprintf(line, "--json --pattern 1 --mesh %s", mesh);
    CHECK_EQ_INT(run(line), 0);
    CHECK(json_valid(out_text, NULL, NULL));
    CHECK(strstr(out_text, "\"pattern\": {") != NULL && strstr(out_text, "\"method\"") == NULL);
    sprintf(line, "--pattern 1 --pattern-shrink-along 2 --pattern-shrink-across 1 --mesh %s", mesh);
    CHECK_EQ_INT(run(line), 0);
    CHECK(strstr(out_text, "a mesh to pattern (--mesh)") != NULL);
    /* usage */
    CHECK_EQ_INT(run("--pattern 0 cli/samples/helicoid.txt"), 2);
    CHECK(strstr(err_text, "--pattern wants the roll width") != NULL);
    CHECK_EQ_INT(run("--pattern -1 cli/samples/helicoid.txt"), 2);
    sprintf(line, "--mesh %s", mesh);
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "--mesh needs --pattern W") != NULL);
    sprintf(line, "--pattern-svg %s cli/samples/helicoid.txt", svg);
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "--pattern-svg needs --pattern W") != NULL);
    sprintf(line, "--pattern 1 --mesh %s cli/samples/helicoid.txt", mesh);
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "takes a mesh in place of boundary files") != NULL);
    sprintf(line, "--pattern 1 --mesh %s -n 5", mesh);
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "cannot go together") != NULL);
    CHECK_EQ_INT(run("--pattern 1 --pattern-point 0,0,0 cli/samples/helicoid.txt"), 2);
    CHECK(strstr(err_text, "--pattern-seams axis") != NULL);
    CHECK_EQ_INT(run("--pattern 1 --pattern-seams radial cli/samples/helicoid.txt"), 2);
    CHECK_EQ_INT(run("--pattern 1 --pattern-shrink-along 50 cli/samples/helicoid.txt"), 2);
    /* the outputs: onto the mesh read, onto each other */
    sprintf(line, "--pattern 1 --pattern-dxf %s --mesh %s", mesh, mesh);
    CHECK_EQ_INT(run(line), 2);
    CHECK_MSG(strstr(err_text, "is the mesh file ") != NULL && strstr(err_text, "would replace it") != NULL,
              err_text);
    sprintf(line, "--pattern 1 --pattern-svg %s --pattern-dxf %s --mesh %s", svg, svg, mesh);
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "are the same file") != NULL);
    sprintf(line, "-n 8 -o %s --pattern 1 --pattern-svg %s cli/samples/helicoid.txt", tmp("same.obj"),
            tmp("same.obj"));
    CHECK_EQ_INT(run(line), 2);
    CHECK(strstr(err_text, "are the same file") != NULL);
    sprintf(line, "--pattern 1 --pattern-svg %s/no/such/dir/x.svg --mesh %s", dir, mesh);
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot write the panels' picture") != NULL);
    /* no spacing fits: planes normal to z cannot cut a flat square */
    write_text(tmp("pat-flat.obj"), "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    write_text(tmp("pat-flat.txt"), "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n");
    sprintf(line, "--json --pattern 0.5 --pattern-direction 0,0,1 --mesh %s", tmp("pat-flat.obj"));
    CHECK_EQ_INT(run(line), 1);
    CHECK_MSG(strstr(err_text, "the cutting pattern failed: no spacing") != NULL, err_text);
    CHECK(strstr(out_text, "\"code\": \"PLATEAU_ERR_PATTERN\"") != NULL);
    /* after a solve: the summary still comes, the status is 1 */
    sprintf(line, "-n 30 --pattern 0.5 --pattern-direction 0,0,1 %s", tmp("pat-flat.txt"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "the cutting pattern failed") != NULL && strstr(out_text, "  check      valid") != NULL);
    remove(tmp("pat-flat.obj"));
    remove(tmp("pat-flat.txt"));
    remove(mesh);
}

/* The keys of README.md's JSON list (between <!-- json-keys --> and
 * <!-- /json-keys -->, one "- `key`: ..." a line) and what the tool
 * printed of them. */
#define DOC_KEYS 100
typedef struct doc_keys {
    char name[DOC_KEYS][32];
    int seen[DOC_KEYS], count, last; /* last: the list position of the
                                        previous top-level key printed */
    int unknown, out_of_order;
} doc_keys;

static int doc_key_index(const doc_keys *d, const char *key, size_t len)
{
    int i;
    for (i = 0; i < d->count; i++)
        if (strlen(d->name[i]) == len && strncmp(d->name[i], key, len) == 0) return i;
    return -1;
}

static void doc_key_seen(const char *key, size_t len, int depth, void *user)
{
    doc_keys *d = (doc_keys *)user;
    int i = doc_key_index(d, key, len);
    if (i < 0) {
        d->unknown++;
        fprintf(stderr, "  printed, not in README.md's list: %.*s\n", (int)len, key);
        return;
    }
    d->seen[i] = 1;
    if (depth > 0) return;
    if (i < d->last) {
        d->out_of_order++;
        fprintf(stderr, "  printed after %s, listed before it: %s\n", d->name[d->last], d->name[i]);
    }
    d->last = i;
}

/* A unit circle of m vertices whose every other edge is a cable of
 * tension 1: m / 2 cables. */
static void write_cable_circle(const char *path, int m)
{
    FILE *f = fopen(path, "w");
    int i;
    if (!f) return;
    for (i = 0; i < m; i++)
        fprintf(f, "%.17g %.17g 0%s\n", cos(6.283185307179586 * i / m), sin(6.283185307179586 * i / m),
                i % 2 == 0 ? " cable 1" : "");
    fclose(f);
}

/* The JSON's cable list against the cables: 32 cables give 16 listed,
 * cables_total 32 and a note saying why; 8 give all 8 and no note. */
static void test_cable_list_says_when_cut(void)
{
    char line[400];
    const char *f;
    int listed = 0;
    write_cable_circle(tmp("cables32.txt"), 64);
    sprintf(line, "--json -n 60 %s", tmp("cables32.txt"));
    CHECK_EQ_INT(run(line), 0);
    for (f = strstr(out_text, "{\"tension\": "); f; f = strstr(f + 1, "{\"tension\": ")) listed++;
    CHECK_EQ_INT(listed, PLATEAU_REPORT_CABLES);
    f = json_field(out_text, "cables_total");
    CHECK(f && atol(f) == 32);
    f = json_field(out_text, "cables_note");
    CHECK(f && strstr(f, "the first 16 of 32 cables") != NULL);
    write_cable_circle(tmp("cables32.txt"), 16);
    CHECK_EQ_INT(run(line), 0);
    for (listed = 0, f = strstr(out_text, "{\"tension\": "); f; f = strstr(f + 1, "{\"tension\": ")) listed++;
    CHECK_EQ_INT(listed, 8);
    f = json_field(out_text, "cables_total");
    CHECK(f && atol(f) == 8);
    CHECK(json_field(out_text, "cables_note") == NULL);
    remove(tmp("cables32.txt"));
}

/* The skew quadrilateral (+-1, +-1, x y), two points per side. */
#define SKEW_QUAD "1 -1 -1\n1 0 0\n1 1 1\n0 1 0\n-1 1 -1\n-1 0 0\n-1 -1 1\n0 -1 0\n"

/* --supports FILE: the points are fixed vertices of the mesh written,
 * the summary and --json count them; a ring closes; a file that cannot
 * be read, a point the film cannot reach and bad text fail with exit 1. */
static void test_supports_file(void)
{
    char line[512];
    const char *f;
    double x, y, z;
    int found = 0;
    FILE *in;
    write_text(tmp("sq.txt"), SKEW_QUAD);
    write_text(tmp("sup.txt"), "0 -0.5 0.25\n0 0 0.25\n0 0.5 0.25\n\n0.5 0 0\n");
    sprintf(line, "-n 60 --supports %s -o %s %s", tmp("sup.txt"), tmp("sup.obj"), tmp("sq.txt"));
    CHECK_EQ_INT(run(line), 0);
    CHECK(strstr(out_text, "supports   4 fixed points") != NULL);
    in = fopen(tmp("sup.obj"), "rb");
    if (CHECK(in != NULL)) {
        char text[256];
        while (fgets(text, sizeof text, in))
            if (sscanf(text, "v %lf %lf %lf", &x, &y, &z) == 3 && x == 0.0 && y == 0.0 && z == 0.25) found++;
        fclose(in);
    }
    CHECK_EQ_INT(found, 1);
    sprintf(line, "--json -n 60 --supports %s %s", tmp("sup.txt"), tmp("sq.txt"));
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "support_points");
    CHECK(f && atol(f) == 4);
    /* a closed ring: its repeated point is its first vertex again */
    write_text(tmp("sup.txt"), "0.3 0 0\n0 0.3 0\n-0.3 0 0\n0 -0.3 0\n0.3 0 0\n");
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "support_points");
    CHECK(f && atol(f) == 4);
    write_text(tmp("sup.txt"), "5 0 0\n");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "support point 0 has no place inside the film") != NULL);
    write_text(tmp("sup.txt"), "0 0 zero\n");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, tmp("sup.txt")) != NULL);
    remove(tmp("sup.txt"));
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(err_text, "cannot read") != NULL);
    remove(tmp("sq.txt"));
    remove(tmp("sup.obj"));
}

/* A unit ring at height h and a ring of 24 vertices on z = 0 marked
 * "slide-plane 0 0 1" (the last one's mark replaced by tail). */
static void write_sliding_rings(const char *path, double h, const char *tail)
{
    FILE *f = fopen(path, "wb");
    int i;
    if (!f) return;
    for (i = 0; i < 24; i++) fprintf(f, "%.17g %.17g %g\n", cos(i * 3.14159265358979323846 / 12), sin(i * 3.14159265358979323846 / 12), h);
    fputc('\n', f);
    for (i = 0; i < 24; i++)
        fprintf(f, "%.17g %.17g 0 %s\n", cos(i * 3.14159265358979323846 / 12), sin(i * 3.14159265358979323846 / 12), i < 23 ? "slide-plane 0 0 1" : tail);
    fclose(f);
}

/* Slide marks: the half catenoid solves (exit 0), the summary and --json
 * count the sliding vertices, which stay on their plane; beyond the
 * catenoid's limit the film pinches (exit 3); a bad mark is a parse
 * error naming its line (exit 1). */
static void test_slide_marks(void)
{
    char line[512];
    const char *f;
    write_sliding_rings(tmp("slide.txt"), 0.5, "slide-line 0 1 0");
    sprintf(line, "-n 60 --method area %s", tmp("slide.txt"));
    CHECK_EQ_INT(run(line), 0);
    CHECK(strstr(out_text, "sliding    24 boundary vertices") != NULL);
    sprintf(line, "--json -n 60 --method area %s", tmp("slide.txt"));
    CHECK_EQ_INT(run(line), 0);
    f = json_field(out_text, "sliding_vertices");
    CHECK(f && atol(f) == 24);
    f = json_field(out_text, "area");
    CHECK(f && fabs(atof(f) - 2.9958985) < 0.02);
    write_sliding_rings(tmp("slide.txt"), 0.7, "slide-plane 0 0 1");
    CHECK_EQ_INT(run(line), 3);
    CHECK(strstr(out_text, "\"pinched\": true") != NULL);
    write_sliding_rings(tmp("slide.txt"), 0.5, "slide-plane 0 0");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(out_text, "line 49") != NULL);
    write_sliding_rings(tmp("slide.txt"), 0.5, "slide-plane 0 0 0");
    CHECK_EQ_INT(run(line), 1);
    CHECK(strstr(out_text, "zero") != NULL);
    remove(tmp("slide.txt"));
}

/* Every key --json prints is in README.md's list, the top-level ones in
 * its order, and every key of the list is printed by one of these runs: a
 * plain film (with -o, --svg and --edge-length), a membrane (cables), two
 * loops, two loops with --critical-index 1, a mesh minimised, and a
 * failure. */
static void test_json_keys_documented(void)
{
    static const char *const runs[] = {
        "--json --edge-length 0.4 -o %s --svg %s cli/samples/helicoid.txt",
        "--json cli/samples/sail-square.txt", "--json --volume 0.1 cli/samples/helicoid.txt",
        "--json cli/samples/two-rings.txt", "--json --critical-index 1 cli/samples/two-rings.txt",
        "--json --minimize %s", "--json %s",
        "--json -n 40 --pattern 0.6 --pattern-svg %s --pattern-dxf %s cli/samples/helicoid.txt",
        "--json --pattern 1 --mesh %s", "--json --max-seconds 1e-9 cli/samples/helicoid.txt"};
    static doc_keys d;
    FILE *f = fopen("README.md", "rb");
    char text[256], line[512];
    int in = 0, i;
    size_t r;
    memset(&d, 0, sizeof d);
    if (!CHECK(f != NULL)) return;
    write_saddle_mesh(tmp("keys-saddle.obj"), 0);
    while (fgets(text, sizeof text, f)) {
        if (strncmp(text, "<!-- json-keys -->", 18) == 0) in = 1;
        else if (strncmp(text, "<!-- /json-keys -->", 19) == 0) in = 0;
        else if (in && strncmp(text, "- `", 3) == 0 && d.count < DOC_KEYS && strchr(text + 3, '`'))
            sprintf(d.name[d.count++], "%.*s", (int)(strchr(text + 3, '`') - text - 3), text + 3);
    }
    fclose(f);
    if (!CHECK_MSG(d.count > 50, "README.md lists the JSON keys between <!-- json-keys --> and <!-- /json-keys -->"))
        return;
    for (r = 0; r < sizeof runs / sizeof runs[0]; r++) {
        if (r == 0) sprintf(line, runs[r], tmp("keys.obj"), tmp("keys.svg"));
        else if (strstr(runs[r], "--pattern-svg")) sprintf(line, runs[r], tmp("keys-pat.svg"), tmp("keys-pat.dxf"));
        else if (strstr(runs[r], "--minimize") || strstr(runs[r], "--mesh"))
            sprintf(line, runs[r], tmp("keys-saddle.obj"));
        else sprintf(line, runs[r], tmp("missing.txt"));
        run(line);
        d.last = 0;
        if (!CHECK_MSG(json_valid(out_text, doc_key_seen, &d), line)) fprintf(stderr, "  %s", out_text);
    }
    /* 32 cables, one every other edge of a circle: more than the report lists */
    write_cable_circle(tmp("keys-cables.txt"), 64);
    sprintf(line, "--json -n 60 %s", tmp("keys-cables.txt"));
    run(line);
    d.last = 0;
    if (!CHECK_MSG(json_valid(out_text, doc_key_seen, &d), line)) fprintf(stderr, "  %s", out_text);
    remove(tmp("keys-cables.txt"));
    /* interior supports: support_points */
    write_text(tmp("keys-quad.txt"), SKEW_QUAD);
    write_text(tmp("keys-sup.txt"), "0 0 0\n");
    sprintf(line, "--json -n 60 --supports %s %s", tmp("keys-sup.txt"), tmp("keys-quad.txt"));
    run(line);
    d.last = 0;
    if (!CHECK_MSG(json_valid(out_text, doc_key_seen, &d), line)) fprintf(stderr, "  %s", out_text);
    remove(tmp("keys-quad.txt"));
    remove(tmp("keys-sup.txt"));
    /* sliding vertices: sliding_vertices */
    write_sliding_rings(tmp("keys-slide.txt"), 0.5, "slide-plane 0 0 1");
    sprintf(line, "--json -n 60 %s", tmp("keys-slide.txt"));
    run(line);
    d.last = 0;
    if (!CHECK_MSG(json_valid(out_text, doc_key_seen, &d), line)) fprintf(stderr, "  %s", out_text);
    remove(tmp("keys-slide.txt"));
    remove(tmp("keys.obj"));
    remove(tmp("keys.svg"));
    remove(tmp("keys-pat.svg"));
    remove(tmp("keys-pat.dxf"));
    remove(tmp("keys-saddle.obj"));
    CHECK_EQ_INT(d.unknown, 0);
    CHECK_EQ_INT(d.out_of_order, 0);
    for (i = 0; i < d.count; i++) {
        sprintf(line, "README.md lists %s, which none of the runs printed", d.name[i]);
        CHECK_MSG(d.seen[i], line);
    }
}

int main(void)
{
    sprintf(dir, "/tmp/plateau_test_cli_run_%ld", (long)getpid());
    RUN(test_bad_input);
    RUN(test_solve_and_write);
    RUN(test_stability_fields);
    RUN(test_reports_not_computed);
    RUN(test_failed_critical_search_says_so);
    RUN(test_cable_list_says_when_cut);
    RUN(test_supports_file);
    RUN(test_slide_marks);
    RUN(test_stability_none_converged);
    RUN(test_stability_units);
    RUN(test_critical_index_rings);
    RUN(test_stdin_and_size_cap);
    RUN(test_defects_status);
    RUN(test_samples_valid);
    RUN(test_warnings);
    RUN(test_progress);
    RUN(test_closing_point_and_lines);
    RUN(test_stl);
    RUN(test_output_files);
    RUN(test_output_paths);
    RUN(test_unwritable_output_and_read_cap);
    RUN(test_limits_advice);
    RUN(test_membranes);
    RUN(test_membranes_merged);
    RUN(test_unreadable_reason);
    RUN(test_echoed_numbers);
    RUN(test_messages_name_flags);
    RUN(test_conflicting_options);
    RUN(test_edge_length);
    RUN(test_json_errors);
    RUN(test_pattern);
    RUN(test_json_keys_documented);
    RUN(test_csv_boundary);
    RUN(test_marked_output);
    RUN(test_minimize);
    RUN(test_advice_followed);
    return harness_report("test_cli_run");
}
