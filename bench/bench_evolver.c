/* bench_evolver.c - time against excess: plateau's methods area and paper
 * with their defaults (coarse to fine from PLATEAU_COARSE_TO_FINE_POINTS)
 * and with coarse_to_fine OFF (the rounds at full size), and Surface
 * Evolver (Brakke) with a lean and a full script, on the same polygons in
 * the same run (built by `make bench`; Evolver is an optional peer: without an
 * `evolver` on PATH its rows say "skipped").
 *
 * Polygons (examples/surfaces.h, each side of the parameter rectangle
 * sampled uniformly in its parameter):
 *   helicoid  b = 1.9, u in [-1.5, 1.5], v in [-pi/2, pi/2], 4 segments on
 *             each straight ruling and 10 on each helix (28 vertices: the
 *             counts round(m L_k / sum L) of examples/NOTES.md for this
 *             range; bench_scale keeps the demo's 5 and 9, another polygon)
 *   catenoid  the demo's: b = 2.05, u in [pi/4, 3pi/4], v in [-0.5, 0.5],
 *             8 segments on each arc, 4 on each catenary (24 vertices)
 * excess = area / A* - 1 with A* the polygon's optimum: helicoid
 * 19.4364269, catenoid 7.1571190, each from three uniformly refined levels
 * (h halving; area error c h^2 + d h^3, solved for A*) of Evolver's lean
 * script (levels 4-6: 10^4 to 1.6 10^5 interior vertices) and, the same to
 * 1e-7, of one run's levels of the coarse-to-fine prototype that preceded
 * the library's path; two levels and the h^2 term alone
 * move them by 2e-7 (helicoid) and 5e-7 (catenoid).  The run prints its
 * own extrapolations from Evolver's levels next to the pinned figures.
 *
 * Surface Evolver: the datafile (written at run time to out/evolver/) is a
 * grid spanning the polygon: the (nu + 1) x (nv + 1) points of the Coons
 * patch of the polygon's four sides (bilinear blend of the sides minus the
 * corners' bilinear term; it uses only the polygon's vertices), each cell
 * cut along its shorter diagonal; polygon vertices and edges fixed, so the
 * refinement `r` puts the new boundary vertices on the polygon's straight
 * edges (the same polygon at every level).  Scripts, per level (the first
 * level refines the grid once and is not reported; levels 2.. are):
 *   lean  r; g 5; u; V; u; then hessian_seek (with hessian_normal: one
 *         unknown per vertex, along its normal) until one lowers the area
 *         by less than 1e-10 of it
 *   full  the lean level, then cycles of g 20 (gradient steps, which also
 *         move vertices along the surface) and hessian_seek until a cycle
 *         lowers the area by less than 1e-9 of it, at most
 *         EVOLVER_FULL_CYCLES cycles per level, to level EVOLVER_FULL_LEVELS
 * One Evolver process per script runs all levels and prints, after each,
 * its interior vertex count, area and Evolver's own process CPU clock; a
 * level's CPU is that clock plus what the child's rusage has beyond the
 * last clock (loading, exit), so the last level's CPU is the rusage.
 *
 * plateau: plateau_solve on the polygon with quality seeding and
 * refine_boundary (the issue's `--seeding quality --refine-boundary`),
 * defaults otherwise (so coarse to fine from PLATEAU_COARSE_TO_FINE_POINTS
 * points), n interior points asked; the "rounds" series the same with
 * coarse_to_fine OFF.  Each run is a child process, CPU = its rusage (user + system), peak = its ru_maxrss;
 * runs under 1 s are repeated 3 times (median CPU).
 *
 * The table: every point; then, for every point of Evolver's curves, the
 * CPU each plateau series needs for no more excess (interpolated in
 * log-log along its curve) over Evolver's: the target is at most
 * 0.5.  The SVG plot (out/bench_evolver.svg) has one panel per polygon,
 * CPU seconds against excess, both logarithmic.
 * Arguments: none (the rounds to 10^5, coarse to fine to 2 10^5, Evolver
 * lean to level 6 and full to level 5: about 11 minutes of CPU on the
 * 2-core machine), "quick" (to 10^4, Evolver to level 4), "evolver"
 * (Evolver only) or "c2f" (the coarse-to-fine series and Evolver, without
 * the rounds: about 5 minutes of CPU); "nostab" adds options.stability
 * OFF to every plateau run (the solve without its stability report);
 * "equal" (with or without "quick") the CPU at equal true error, below.
 */
#define _DEFAULT_SOURCE
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "examples/surfaces.h"
#include "bench/bench_common.h"

#include <fcntl.h>
#include <sys/stat.h>

#define EVOLVER_LEVELS 6
#define EVOLVER_FULL_CYCLES 20
#define EVOLVER_FULL_LEVELS 5 /* the full script's cycles cost minutes per level beyond */
#define MAX_POINTS 16

typedef struct series {
    const char *name;
    double accuracy;       /* plateau: options.accuracy of every point (0: the library's rule) */
    int n;                 /* points */
    int skipped;           /* 1: not run (Evolver missing) */
    double cpu[MAX_POINTS], excess[MAX_POINTS], area[MAX_POINTS], peak_mb[MAX_POINTS];
    size_t interior[MAX_POINTS];
    unsigned defects[MAX_POINTS];
} series;

typedef struct surface {
    const char *name;
    demo_case c;
    double astar; /* pinned optimum of the polygon */
    double polygon[3 * DEMO_MAX_BOUNDARY];
    size_t m;
} surface;

/* ---------------------------------------------------------------- plateau */
typedef struct solve_arg {
    const surface *s;
    plateau_method method;
    size_t n;             /* interior points; 0 with accuracy > 0 */
    double accuracy;      /* options.accuracy (0: the library's rule) */
    plateau_switch c2f; /* options.coarse_to_fine */
    plateau_switch stability; /* options.stability */
} solve_arg;

typedef struct solve_out {
    int rc;
    double area;
    size_t interior, iterations, rounds, levels;
    unsigned defects;
} solve_out;

static void solve_fn(void *arg, void *out)
{
    const solve_arg *a = (const solve_arg *)arg;
    solve_out *o = (solve_out *)out;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    memset(&opt, 0, sizeof opt);
    memset(&rep, 0, sizeof rep);
    opt.method = a->method;
    opt.interior_points = a->n;
    opt.accuracy = a->accuracy;
    opt.seeding = PLATEAU_SEEDING_QUALITY;
    opt.refine_boundary = PLATEAU_ON;
    opt.coarse_to_fine = a->c2f;
    opt.stability = a->stability;
    o->rc = plateau_solve(a->s->polygon, a->s->m, &opt, &mesh, &rep, NULL);
    o->area = rep.area;
    o->interior = rep.interior_points;
    o->iterations = rep.iterations + rep.presolve_iterations;
    o->rounds = rep.rounds;
    o->levels = rep.levels;
    o->defects = rep.defects;
    plateau_mesh_free(&mesh);
}

/* one point of a plateau series: repeated while the runs are short */
static void plateau_point(const surface *s, plateau_method method, plateau_switch c2f, plateau_switch stability,
                          size_t n, series *se)
{
    solve_arg a;
    solve_out o;
    double cpu[3];
    int r, reps = 1;
    long peak = 0;
    memset(&a, 0, sizeof a);
    a.s = s;
    a.method = method;
    a.n = n;
    a.accuracy = se->accuracy;
    a.c2f = c2f;
    a.stability = stability;
    for (r = 0; r < reps; r++) {
        struct rusage ru;
        memset(&o, 0, sizeof o);
        if (!bench_run_child(solve_fn, &a, &o, sizeof o, &ru) || o.rc != PLATEAU_OK) {
            printf("%-9s %-14s n = %lu failed (%s)\n", s->name, se->name, (unsigned long)n,
                   plateau_result_string((plateau_result)o.rc));
            return;
        }
        cpu[r] = bench_cpu_of(&ru);
        if (ru.ru_maxrss > peak) peak = ru.ru_maxrss;
        if (r == 0 && cpu[0] < 1.0) reps = 3;
    }
    se->cpu[se->n] = bench_median(cpu, (size_t)reps);
    se->area[se->n] = o.area;
    se->excess[se->n] = o.area / s->astar - 1.0;
    se->interior[se->n] = o.interior;
    se->peak_mb[se->n] = (double)peak / 1024.0;
    se->defects[se->n] = o.defects;
    se->n++;
}

/* ---------------------------------------------------------------- Evolver */
static int evolver_on_path(void)
{
    const char *path = getenv("PATH");
    char buf[4096];
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t len = end ? (size_t)(end - path) : strlen(path);
        if (len > 0 && len + 9 < sizeof buf) {
            memcpy(buf, path, len);
            memcpy(buf + len, "/evolver", 9);
            if (access(buf, X_OK) == 0) return 1;
        }
        path = end ? end + 1 : NULL;
    }
    return 0;
}

/* The polygon vertex at grid point (i, j) of the boundary, in the order
 * of demo_boundary: side 0 along u at v0, side 1 along v at u1, side 2
 * back along u at v1, side 3 back along v at u0. */
static size_t grid_boundary_index(int i, int j, int nu, int nv)
{
    if (j == 0) return (size_t)i;
    if (i == nu) return (size_t)(nu + j);
    if (j == nv) return (size_t)(nu + nv + (nu - i));
    return (size_t)((2 * nu + nv + (nv - j)) % (2 * nu + 2 * nv));
}

/* Grid point (i, j): the polygon vertex on the boundary, else the Coons
 * patch of the four sides. */
static void grid_point(const surface *s, int i, int j, double *p)
{
    int nu = s->c.nu, nv = s->c.nv, k;
    const double *P = s->polygon;
    double a = (double)i / nu, b = (double)j / nv;
    if (i == 0 || i == nu || j == 0 || j == nv) {
        memcpy(p, P + 3 * grid_boundary_index(i, j, nu, nv), 3 * sizeof(double));
        return;
    }
    for (k = 0; k < 3; k++) {
        double c0 = P[3 * grid_boundary_index(i, 0, nu, nv) + k];
        double c1 = P[3 * grid_boundary_index(i, nv, nu, nv) + k];
        double d0 = P[3 * grid_boundary_index(0, j, nu, nv) + k];
        double d1 = P[3 * grid_boundary_index(nu, j, nu, nv) + k];
        double q00 = P[3 * grid_boundary_index(0, 0, nu, nv) + k];
        double q10 = P[3 * grid_boundary_index(nu, 0, nu, nv) + k];
        double q01 = P[3 * grid_boundary_index(0, nv, nu, nv) + k];
        double q11 = P[3 * grid_boundary_index(nu, nv, nu, nv) + k];
        p[k] = (1 - b) * c0 + b * c1 + (1 - a) * d0 + a * d1 -
               ((1 - a) * (1 - b) * q00 + a * (1 - b) * q10 + (1 - a) * b * q01 + a * b * q11);
    }
}

static const char *evolver_lean_level =
    "  r; g 5; u; V; u;\n"
    "  seeks := 0;\n"
    "  do { a0 := total_area; hessian_seek; seeks := seeks + 1; }\n"
    "  while a0 - total_area > 1e-10 * total_area && seeks < 100;\n";

/* The datafile: the grid, then the script after `read`. */
static int write_evolver_file(const char *path, const surface *s, int full, int levels)
{
    int nu = s->c.nu, nv = s->c.nv, i, j, e = 0;
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fprintf(f, "// %s polygon (%lu vertices), a %d x %d grid spanning it; written by bench_evolver\n",
            s->name, (unsigned long)s->m, nu, nv);
    fprintf(f, "vertices\n");
    for (j = 0; j <= nv; j++)
        for (i = 0; i <= nu; i++) {
            double p[3];
            int bd = i == 0 || i == nu || j == 0 || j == nv;
            grid_point(s, i, j, p);
            fprintf(f, "%d %.17g %.17g %.17g%s\n", j * (nu + 1) + i + 1, p[0], p[1], p[2],
                    bd ? " fixed" : "");
        }
    /* edges: horizontal (i, j)-(i+1, j), vertical (i, j)-(i, j+1), and one
     * diagonal per cell; ids in that order */
    fprintf(f, "\nedges\n");
    for (j = 0; j <= nv; j++)
        for (i = 0; i < nu; i++)
            fprintf(f, "%d %d %d%s\n", ++e, j * (nu + 1) + i + 1, j * (nu + 1) + i + 2,
                    j == 0 || j == nv ? " fixed" : "");
    for (j = 0; j < nv; j++)
        for (i = 0; i <= nu; i++)
            fprintf(f, "%d %d %d%s\n", ++e, j * (nu + 1) + i + 1, (j + 1) * (nu + 1) + i + 1,
                    i == 0 || i == nu ? " fixed" : "");
    {
        int hcount = (nv + 1) * nu, vcount = nv * (nu + 1), t = 0;
        int *diag = (int *)malloc(sizeof(int) * (size_t)(nu * nv));
        if (!diag) {
            fclose(f);
            return 0;
        }
        for (j = 0; j < nv; j++)
            for (i = 0; i < nu; i++) {
                double p00[3], p10[3], p11[3], p01[3], d1 = 0, d2 = 0;
                int k;
                grid_point(s, i, j, p00);
                grid_point(s, i + 1, j, p10);
                grid_point(s, i + 1, j + 1, p11);
                grid_point(s, i, j + 1, p01);
                for (k = 0; k < 3; k++) {
                    d1 += (p11[k] - p00[k]) * (p11[k] - p00[k]);
                    d2 += (p01[k] - p10[k]) * (p01[k] - p10[k]);
                }
                diag[j * nu + i] = d1 <= d2; /* 1: (i,j)-(i+1,j+1), 0: (i+1,j)-(i,j+1) */
                if (diag[j * nu + i])
                    fprintf(f, "%d %d %d\n", ++e, j * (nu + 1) + i + 1, (j + 1) * (nu + 1) + i + 2);
                else
                    fprintf(f, "%d %d %d\n", ++e, j * (nu + 1) + i + 2, (j + 1) * (nu + 1) + i + 1);
            }
        /* faces: oriented edge loops (counter-clockwise in (i, j)) */
        fprintf(f, "\nfaces\n");
        for (j = 0; j < nv; j++)
            for (i = 0; i < nu; i++) {
                int bottom = j * nu + i + 1, top = (j + 1) * nu + i + 1;
                int left = hcount + j * (nu + 1) + i + 1, right = left + 1;
                int dg = hcount + vcount + j * nu + i + 1;
                if (diag[j * nu + i]) { /* (i,j) -> (i+1,j) -> (i+1,j+1), and back to (i,j+1) */
                    fprintf(f, "%d %d %d %d\n", ++t, bottom, right, -dg);
                    fprintf(f, "%d %d %d %d\n", ++t, dg, -top, -left);
                } else { /* (i,j) -> (i+1,j) -> (i,j+1); (i+1,j) -> (i+1,j+1) -> (i,j+1) */
                    fprintf(f, "%d %d %d %d\n", ++t, bottom, dg, -left);
                    fprintf(f, "%d %d %d %d\n", ++t, right, -top, -dg);
                }
            }
        free(diag);
    }
    fprintf(f, "\nread\n\nquiet on\nhessian_normal on\nlev := 0\nseeks := 0\ncycles := 0\n"
               "a0 := 0\na1 := 0\n");
    fprintf(f, "procedure one_level() {\n%s", evolver_lean_level);
    if (full)
        fprintf(f, "  cycles := 0;\n"
                   "  do { a1 := total_area; g 20; hessian_seek; cycles := cycles + 1; }\n"
                   "  while a1 - total_area > 1e-9 * total_area && cycles < %d;\n",
                EVOLVER_FULL_CYCLES);
    fprintf(f, "  printf \"level %%d interior %%d area %%.15g seeks %%d cycles %%d clock %%.4f\\n\",\n"
               "         lev, sum(vertex where not fixed, 1), total_area, seeks, cycles, clock;\n}\n");
    fprintf(f, "for ( lev := 1; lev <= %d; lev += 1 ) one_level();\nquit\n", levels);
    return fclose(f) == 0;
}

/* Runs one script to `levels` levels; fills the series. */
static void evolver_series(const surface *s, int full, int levels, series *se)
{
    char path[256], line[512];
    int fd[2], status = 0, got = 0, i;
    double clk[MAX_POINTS], last = 0.0, total;
    pid_t pid;
    struct rusage ru;
    FILE *in;
    sprintf(path, "out/evolver/%s_%s.fe", s->name, full ? "full" : "lean");
    if (!write_evolver_file(path, s, full, levels) || pipe(fd) != 0) {
        printf("%-9s %-14s could not write %s\n", s->name, se->name, path);
        return;
    }
    fflush(stdout);
    pid = fork();
    if (pid < 0) return;
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0) dup2(devnull, 0);
        dup2(fd[1], 1);
        close(fd[0]);
        close(fd[1]);
        execlp("evolver", "evolver", "-x", path, (char *)NULL);
        _exit(127);
    }
    close(fd[1]);
    in = fdopen(fd[0], "r");
    while (in && fgets(line, sizeof line, in)) {
        int lev, seeks, cycles;
        long interior;
        double area, c;
        if (sscanf(line, "level %d interior %ld area %lf seeks %d cycles %d clock %lf", &lev, &interior,
                   &area, &seeks, &cycles, &c) == 6 && lev >= 2 && got < MAX_POINTS) {
            se->interior[got] = (size_t)interior;
            se->area[got] = area;
            se->excess[got] = area / s->astar - 1.0;
            se->defects[got] = 0;
            clk[got] = c;
            last = c;
            got++;
        }
    }
    if (in) fclose(in);
    if (wait4(pid, &status, 0, &ru) != pid || got == 0 || (WIFEXITED(status) && WEXITSTATUS(status) != 0)) {
        printf("%-9s %-14s Evolver failed (status %d, %d levels read)\n", s->name, se->name, status, got);
        se->n = 0;
        return;
    }
    /* Evolver 2.70 (Debian) dies by SIGSEGV in `quit` after the last level
     * of some runs (the catenoid at level 6); the levels were printed, and
     * the rusage still counts the whole process */
    if (WIFSIGNALED(status))
        printf("%-9s %-14s note: Evolver ended by signal %d after its last level\n", s->name, se->name,
               WTERMSIG(status));
    total = bench_cpu_of(&ru);
    for (i = 0; i < got; i++) {
        se->cpu[i] = clk[i] + (total - last);
        se->peak_mb[i] = i == got - 1 ? (double)ru.ru_maxrss / 1024.0 : 0.0; /* only the whole run's */
    }
    se->n = got;
}

/* ---------------------------------------------------------------- comparison */
/* The CPU a series needs for an excess of at most e: the least over its
 * points with excess <= e and over the crossings of e between consecutive
 * points (interpolated in log-log; the points are in order of n, and a
 * larger n can take less CPU: another coarse level); *bound = 1 when the
 * least is a point and the point before it (if any) already had less
 * excess than e or none crossing is cheaper (the figure is then an upper
 * bound).  -1 when no point reaches e. */
static double cpu_for_excess(const series *se, double e, int *bound)
{
    double best = -1.0;
    int i;
    *bound = 0;
    for (i = 0; i < se->n; i++) {
        if (!(se->excess[i] <= e) || se->defects[i]) continue;
        if (best < 0.0 || se->cpu[i] < best) {
            best = se->cpu[i];
            *bound = 1;
        }
        if (i > 0 && se->excess[i - 1] > e && se->excess[i] > 0.0 && !se->defects[i - 1]) {
            double l0 = log(se->excess[i - 1]), l1 = log(se->excess[i]), w = (log(e) - l0) / (l1 - l0);
            double t = exp(log(se->cpu[i - 1]) + w * (log(se->cpu[i]) - log(se->cpu[i - 1])));
            if (t < best) {
                best = t;
                *bound = 0;
            }
        }
    }
    return best;
}

static void print_series(FILE *f, const surface *s, const series *se)
{
    int i;
    if (se->skipped) {
        fprintf(f, "| %s | %s | skipped: no evolver on PATH (Debian: apt-get install evolver) | | | | |\n", s->name,
                se->name);
        return;
    }
    for (i = 0; i < se->n; i++) {
        char peak[32];
        if (se->peak_mb[i] > 0.0) sprintf(peak, "%.0f", se->peak_mb[i]);
        else strcpy(peak, "-");
        fprintf(f, "| %s | %s | %lu | %.3f | %s | %.10f | %.3e%s |\n", s->name, se->name,
                (unsigned long)se->interior[i], se->cpu[i], peak, se->area[i], se->excess[i],
                se->defects[i] ? " (defects)" : "");
    }
}

/* ---------------------------------------------------------------- SVG plot */
#define PLOT_W 460.0
#define PLOT_H 360.0
static const char *series_colour[] = {"#1f5fbf", "#2a9d3f", "#17becf", "#9acd32", "#d62728", "#7b3fa0",
                                      "#e08a1e", "#444444"};

static void plot_panel(FILE *f, double x0, const surface *s, series *const *all, int ns)
{
    double lx0 = 1e300, lx1 = -1e300, ly0 = 1e300, ly1 = -1e300, px, py;
    int k, i, d;
    for (k = 0; k < ns; k++)
        for (i = 0; i < all[k]->n; i++) {
            double lx = log10(all[k]->cpu[i]), ly = log10(all[k]->excess[i] > 1e-12 ? all[k]->excess[i] : 1e-12);
            lx0 = lx < lx0 ? lx : lx0;
            lx1 = lx > lx1 ? lx : lx1;
            ly0 = ly < ly0 ? ly : ly0;
            ly1 = ly > ly1 ? ly : ly1;
        }
    if (lx0 > lx1) return;
    lx0 = floor(lx0);
    lx1 = ceil(lx1);
    ly0 = floor(ly0);
    ly1 = ceil(ly1);
    if (lx1 <= lx0) lx1 = lx0 + 1;
    if (ly1 <= ly0) ly1 = ly0 + 1;
#define PX(lx) (x0 + 60.0 + ((lx) - lx0) / (lx1 - lx0) * (PLOT_W - 80.0))
#define PY(ly) (30.0 + (ly1 - (ly)) / (ly1 - ly0) * (PLOT_H - 80.0))
    fprintf(f, "<text x=\"%.1f\" y=\"18\" font-size=\"14\" text-anchor=\"middle\">%s (%lu-vertex polygon)</text>\n",
            x0 + PLOT_W / 2, s->name, (unsigned long)s->m);
    fprintf(f, "<rect x=\"%.1f\" y=\"30\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#888\"/>\n",
            x0 + 60.0, PLOT_W - 80.0, PLOT_H - 80.0);
    for (d = (int)lx0; d <= (int)lx1; d++) {
        px = PX((double)d);
        fprintf(f, "<line x1=\"%.1f\" y1=\"30\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", px, px, PLOT_H - 50.0);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\">1e%d</text>\n", px,
                PLOT_H - 36.0, d);
    }
    for (d = (int)ly0; d <= (int)ly1; d++) {
        py = PY((double)d);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x0 + 60.0, py,
                x0 + PLOT_W - 20.0, py);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"end\">1e%d</text>\n", x0 + 56.0,
                py + 4.0, d);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">CPU seconds</text>\n",
            x0 + PLOT_W / 2 + 20.0, PLOT_H - 18.0);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">"
               "excess = area / A* - 1</text>\n", x0 + 16.0, PLOT_H / 2, x0 + 16.0, PLOT_H / 2);
    for (k = 0; k < ns; k++) {
        const series *se = all[k];
        const char *col = series_colour[k % 8];
        if (se->n == 0) continue;
        fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
        for (i = 0; i < se->n; i++)
            fprintf(f, "%.1f,%.1f ", PX(log10(se->cpu[i])), PY(log10(se->excess[i] > 1e-12 ? se->excess[i] : 1e-12)));
        fprintf(f, "\"/>\n");
        for (i = 0; i < se->n; i++)
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"><title>%s n=%lu: %.3g s, %.3g</title></circle>\n",
                    PX(log10(se->cpu[i])), PY(log10(se->excess[i] > 1e-12 ? se->excess[i] : 1e-12)), col, se->name,
                    (unsigned long)se->interior[i], se->cpu[i], se->excess[i]);
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"%s\"/>"
                   "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">%s</text>\n",
                x0 + PLOT_W - 170.0, 40.0 + 15.0 * k, col, x0 + PLOT_W - 155.0, 49.0 + 15.0 * k, se->name);
    }
#undef PX
#undef PY
}

/* ---------------------------------------------------------------- equal true error */
/* Mode "equal": the CPU each solver needs for true relative errors
 * (excess) 1e-3, 1e-4 and 1e-5, on the helicoid and catenoid above, the
 * demo's Scherk polygon (b = 1, [-1, 1]^2, 32 vertices) and the
 * four-corner tent (a 4 m square, two opposite corners raised 2.5 m; the
 * Evolver grid is its one cell).  plateau: the series over n (quality
 * seeding, refine_boundary, coarse to fine; medians of 3 below 1 s) with
 * the CPU at each excess interpolated as above, and one run of
 * options.accuracy at the target itself (its true error printed: the
 * accuracy is a request on the estimate, not on the true error); Evolver:
 * the lean script, its levels' CPU the medians of 3 runs when the whole
 * run takes under EQUAL_EVOLVER_REPEAT seconds. */
#define NUM_TARGETS 3
#define EQUAL_SURFACES 4
#define EQUAL_EVOLVER_REPEAT 20.0
static const double equal_targets[NUM_TARGETS] = {1e-3, 1e-4, 1e-5};

/* Evolver's lean series of s, the median CPU per level over up to 3 runs. */
static void evolver_median_series(const surface *s, int levels, series *se)
{
    static series runs[3];
    int r, i, k, count = 1;
    evolver_series(s, 0, levels, &runs[0]);
    if (runs[0].n > 0 && runs[0].cpu[runs[0].n - 1] < EQUAL_EVOLVER_REPEAT) {
        for (r = 1; r < 3; r++) {
            runs[r].name = se->name;
            evolver_series(s, 0, levels, &runs[r]);
            if (runs[r].n == runs[0].n) count++;
        }
    }
    runs[0].name = se->name;
    *se = runs[0];
    for (i = 0; i < se->n; i++) {
        double c[3];
        for (k = 0, r = 0; r < 3 && k < count; r++)
            if (runs[r].n == se->n) c[k++] = runs[r].cpu[i];
        se->cpu[i] = bench_median(c, (size_t)k);
    }
}

/* The surfaces of mode "equal"; the helicoid and catenoid of main. */
static void equal_surfaces(surface *surf, const surface *main_surf)
{
    static const double tent[12] = {0, 0, 0, 4, 0, 2.5, 4, 4, 0, 0, 4, 2.5};
    surf[0] = main_surf[0];
    surf[1] = main_surf[1];
    surf[2].name = "scherk";
    surf[2].c = *demo_find("scherk-b1-m");
    surf[2].m = demo_boundary(&surf[2].c, surf[2].polygon);
    /* the polygon's optimum, converged here: Richardson in 1 / n
     * (plateau's error falls as 1 / n) from plateau_solve at 2 10^5 and
     * 4 10^5 interior points (refine_boundary ON, accuracy -1):
     * 5.64885833; from 10^5 and 2 10^5: 5.64885839 */
    surf[2].astar = 5.6488583;
    surf[3].name = "tent";
    memset(&surf[3].c, 0, sizeof surf[3].c);
    surf[3].c.nu = surf[3].c.nv = 1;
    memcpy(surf[3].polygon, tent, sizeof tent);
    surf[3].m = 4;
    surf[3].astar = 17.92240029; /* tests/test_accuracy.c's TENT_AREA */
}

/* Mode "equal" (the arguments' quick: to 3 10^4 points and Evolver level 4
 * on the grids, 6 on the tent). */
static int equal_main(const surface *main_surf, int quick, int have_evolver)
{
    static const size_t sizes[] = {300, 1000, 3000, 10000, 30000, 100000, 200000};
    static const int levels_full[EQUAL_SURFACES] = {6, 6, 5, 8};
    static surface surf[EQUAL_SURFACES];
    static series pl[EQUAL_SURFACES], ev[EQUAL_SURFACES], acc[EQUAL_SURFACES];
    int si, i, t, nsizes = quick ? 5 : 7;
    equal_surfaces(surf, main_surf);
    printf("CPU for a true relative error (excess = area / A* - 1) of 1e-3, 1e-4, 1e-5: plateau (its\n"
           "defaults at n, interpolated; and --accuracy at the target) and Surface Evolver's lean script\n");
    for (si = 0; si < EQUAL_SURFACES; si++) {
        const surface *s = &surf[si];
        pl[si].name = "plateau n";
        for (i = 0; i < nsizes; i++) plateau_point(s, PLATEAU_METHOD_AREA, PLATEAU_AUTO, PLATEAU_AUTO, sizes[i], &pl[si]);
        acc[si].name = "plateau accuracy";
        for (t = 0; t < NUM_TARGETS; t++) {
            acc[si].accuracy = equal_targets[t];
            plateau_point(s, PLATEAU_METHOD_AREA, PLATEAU_AUTO, PLATEAU_AUTO, 0, &acc[si]);
        }
        ev[si].name = "Evolver lean";
        if (!have_evolver) ev[si].skipped = 1;
        else evolver_median_series(s, quick ? (si == 3 ? 6 : 4) : levels_full[si], &ev[si]);
    }
    printf("\n| polygon | solver | interior | CPU s | peak MB | area | excess |\n|---|---|---|---|---|---|---|\n");
    for (si = 0; si < EQUAL_SURFACES; si++) {
        print_series(stdout, &surf[si], &pl[si]);
        print_series(stdout, &surf[si], &acc[si]);
        print_series(stdout, &surf[si], &ev[si]);
    }
    printf("\n| polygon | excess | plateau n: CPU s | Evolver lean: CPU s | plateau / Evolver | "
           "--accuracy at it: CPU s | its excess | its interior |\n|---|---|---|---|---|---|---|---|\n");
    for (si = 0; si < EQUAL_SURFACES; si++)
        for (t = 0; t < NUM_TARGETS; t++) {
            int b0, b1;
            double p = cpu_for_excess(&pl[si], equal_targets[t], &b0);
            double e = ev[si].skipped ? -1.0 : cpu_for_excess(&ev[si], equal_targets[t], &b1);
            printf("| %s | %.0e | ", surf[si].name, equal_targets[t]);
            if (p < 0.0) printf("not reached | ");
            else printf("%s%.3f | ", b0 ? "<= " : "", p);
            if (ev[si].skipped) printf("skipped (no evolver) | - ");
            else if (e < 0.0) printf("not reached | - ");
            else if (p < 0.0) printf("%s%.3f | - ", b1 ? "<= " : "", e);
            else printf("%s%.3f | %.2f ", b1 ? "<= " : "", e, p / e);
            if (t < acc[si].n)
                printf(" | %.3f | %.2e | %lu |\n", acc[si].cpu[t], acc[si].excess[t], (unsigned long)acc[si].interior[t]);
            else
                printf(" | failed | | |\n");
        }
    printf("\n('<=': a measured point with less excess, no crossing of the target measured.)  This run's\n"
           "Richardson extrapolations in 1 / n from plateau's two largest runs (A* pinned above):\n");
    for (si = 0; si < EQUAL_SURFACES; si++) {
        const series *a = &pl[si];
        if (a->n >= 2) {
            double n1 = (double)a->interior[a->n - 2], n2 = (double)a->interior[a->n - 1];
            printf("  %-9s %.8f (pinned %.8f)\n", surf[si].name,
                   (n2 * a->area[a->n - 1] - n1 * a->area[a->n - 2]) / (n2 - n1), surf[si].astar);
        }
    }
    return 0;
}

/* ---------------------------------------------------------------- main */
#define NUM_PLATEAU 4
#define NUM_SERIES (NUM_PLATEAU + 2)

int main(int argc, char **argv)
{
    /* 450 and 2 000 next to Evolver's smallest levels (465 to 585, 1 953 to
     * 2 449 interior vertices), so that the CPU for their excess is
     * interpolated between near points rather than bounded by a far one */
    static const size_t sizes[] = {300, 450, 600, 1000, 2000, 3000, 10000, 30000, 100000, 200000};
    static const plateau_method methods[NUM_PLATEAU] = {PLATEAU_METHOD_AREA, PLATEAU_METHOD_PAPER,
                                                        PLATEAU_METHOD_AREA, PLATEAU_METHOD_PAPER};
    static const plateau_switch c2f[NUM_PLATEAU] = {PLATEAU_AUTO, PLATEAU_AUTO, PLATEAU_OFF, PLATEAU_OFF};
    /* sizes per series (the full run): the defaults (coarse to fine) to
     * 2 10^5, to reach Evolver's finest level; the rounds to 10^5 (method
     * paper's square system: 1.1 GB there) */
    static const int max_sizes[NUM_PLATEAU] = {10, 10, 9, 9};
    static const char *plateau_names[NUM_PLATEAU] = {"plateau area", "plateau paper", "rounds area",
                                                     "rounds paper"};
    int quick = 0, only = 0, equal = 0, a; /* only: 1 Evolver, 2 the coarse-to-fine series and Evolver */
    plateau_switch stability = PLATEAU_AUTO; /* "nostab": options.stability OFF */
    int nsizes, levels, have_evolver = evolver_on_path();
    surface surf[2];
    static series ser[2][NUM_SERIES];
    int si, k, i;
    FILE *md, *svg;
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "quick") == 0) quick = 1;
        else if (strcmp(argv[a], "evolver") == 0) only = 1;
        else if (strcmp(argv[a], "c2f") == 0) only = 2;
        else if (strcmp(argv[a], "nostab") == 0) stability = PLATEAU_OFF;
        else if (strcmp(argv[a], "equal") == 0) equal = 1;
        else {
            fprintf(stderr, "usage: bench_evolver [quick] [evolver | c2f | equal] [nostab]\n");
            return 2;
        }
    }
    nsizes = quick ? 7 : 10;
    levels = quick ? 4 : EVOLVER_LEVELS;
    memset(surf, 0, sizeof surf);
    surf[0].name = "helicoid";
    surf[0].c = *demo_find("helicoid");
    surf[0].c.u0 = -1.5;
    surf[0].c.u1 = 1.5;
    surf[0].c.v0 = -M_PI / 2;
    surf[0].c.v1 = M_PI / 2;
    surf[0].c.nu = 4;
    surf[0].c.nv = 10;
    surf[0].astar = 19.4364269;
    surf[1].name = "catenoid";
    surf[1].c = *demo_find("catenoid");
    surf[1].astar = 7.1571190;
    for (si = 0; si < 2; si++) surf[si].m = demo_boundary(&surf[si].c, surf[si].polygon);
    mkdir("out", 0777);
    mkdir("out/evolver", 0777);
    if (equal) return equal_main(surf, quick, have_evolver); /* "evolver" and "c2f" do not apply */
    printf("time against excess: plateau (quality seeding, refine_boundary) and Surface Evolver (lean, full);\n"
           "CPU = the child process's rusage; excess = area / A* - 1%s\n",
           stability == PLATEAU_OFF ? "; plateau with options.stability OFF" : "");
    for (si = 0; si < 2; si++) {
        surface *s = &surf[si];
        for (k = 0; k < NUM_PLATEAU; k++) {
            series *se = &ser[si][k];
            se->name = plateau_names[k];
            if (only == 1 || (only == 2 && c2f[k] == PLATEAU_OFF)) continue;
            for (i = 0; i < nsizes && i < max_sizes[k]; i++) plateau_point(s, methods[k], c2f[k], stability, sizes[i], se);
        }
        ser[si][NUM_PLATEAU].name = "Evolver lean";
        ser[si][NUM_PLATEAU + 1].name = "Evolver full";
        for (k = 0; k < 2; k++) {
            series *se = &ser[si][NUM_PLATEAU + k];
            if (!have_evolver) se->skipped = 1;
            else evolver_series(s, k, k && levels > EVOLVER_FULL_LEVELS ? EVOLVER_FULL_LEVELS : levels, se);
        }
    }
    md = fopen("out/bench_evolver.md", "w");
    for (k = 0; k < 2; k++) {
        FILE *f = k == 0 ? stdout : md;
        if (!f) continue;
        fprintf(f, "\n| polygon | solver | interior | CPU s | peak MB | area | excess |\n|---|---|---|---|---|---|---|\n");
        for (si = 0; si < 2; si++)
            for (i = 0; i < NUM_SERIES; i++) print_series(f, &surf[si], &ser[si][i]);
        fprintf(f, "\nA* (pinned): helicoid %.7f, catenoid %.7f.  This run's extrapolations:\n", surf[0].astar,
                surf[1].astar);
        for (si = 0; si < 2; si++) {
            const series *a = &ser[si][0], *lean = &ser[si][NUM_PLATEAU];
            if (a->n >= 2) {
                double n1 = (double)a->interior[a->n - 2], n2 = (double)a->interior[a->n - 1];
                fprintf(f, "  %s: plateau area, last two n, Richardson in 1/n: %.7f\n", surf[si].name,
                        (n2 * a->area[a->n - 1] - n1 * a->area[a->n - 2]) / (n2 - n1));
            }
            if (lean->n >= 3) {
                /* three uniform levels, error c h^2 + d h^3 with h halving:
                 * e1 = A1 - A2, e2 = A2 - A3, C = 8 e2 - e1 (the h^2 part of e1),
                 * D = e1 - C, and A* = A3 - (C / 0.75) / 16 - (D / 0.875) / 64 */
                const double *A = lean->area + lean->n - 3;
                double e1 = A[0] - A[1], e2 = A[1] - A[2], C = 8.0 * e2 - e1, D = e1 - C;
                fprintf(f, "  %s: Evolver lean, last three levels (h^2 and h^3 terms): %.7f; last two (h^2): %.7f\n",
                        surf[si].name, A[2] - C / 0.75 / 16.0 - D / 0.875 / 64.0, (4.0 * A[2] - A[1]) / 3.0);
            }
        }
        fprintf(f, "\nplateau's CPU for no more excess than each Evolver point, over Evolver's CPU "
                   "(target <= 0.5; '<=': a point with less excess, no crossing of it measured):\n\n"
                   "| polygon | Evolver point | interior | CPU s | excess |");
        for (i = 0; i < NUM_PLATEAU; i++) fprintf(f, " %s |", ser[0][i].name);
        fprintf(f, "\n|---|---|---|---|---|");
        for (i = 0; i < NUM_PLATEAU; i++) fprintf(f, "---|");
        fprintf(f, "\n");
        for (si = 0; si < 2; si++) {
            int e;
            for (e = NUM_PLATEAU; e < NUM_SERIES; e++) {
                const series *ev = &ser[si][e];
                int p;
                for (p = 0; p < ev->n; p++) {
                    fprintf(f, "| %s | %s | %lu | %.3f | %.3e |", surf[si].name, ev->name,
                            (unsigned long)ev->interior[p], ev->cpu[p], ev->excess[p]);
                    for (i = 0; i < NUM_PLATEAU; i++) {
                        int bound;
                        double t = cpu_for_excess(&ser[si][i], ev->excess[p], &bound);
                        if (t < 0) fprintf(f, " not reached |");
                        else fprintf(f, " %s%.2f |", bound ? "<= " : "", t / ev->cpu[p]);
                    }
                    fprintf(f, "\n");
                }
            }
        }
    }
    if (md) fclose(md);
    svg = fopen("out/bench_evolver.svg", "w");
    if (svg) {
        fprintf(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" font-family=\"sans-serif\">\n"
                     "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", 2 * PLOT_W, PLOT_H);
        for (si = 0; si < 2; si++) {
            series *all[NUM_SERIES];
            for (i = 0; i < NUM_SERIES; i++) all[i] = &ser[si][i];
            plot_panel(svg, si * PLOT_W, &surf[si], all, NUM_SERIES);
        }
        fprintf(svg, "</svg>\n");
        fclose(svg);
    }
    printf("\nwrote out/bench_evolver.md, out/bench_evolver.svg%s\n",
           have_evolver ? ", out/evolver/*.fe" : "; Evolver: skipped (optional peer: apt-get install evolver)");
    return 0;
}
