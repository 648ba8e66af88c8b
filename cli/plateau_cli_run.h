/* plateau_cli_run.h - one run of the command-line tool, as a function:
 * plateau_cli_run(argc, argv, out, errout) is main() with its streams
 * passed in, so tests can drive the whole tool.  Include after plateau.h
 * (with its implementation) and plateau_cli.h.  Not part of the library. */
#ifndef PLATEAU_CLI_RUN_H
#define PLATEAU_CLI_RUN_H

#include <time.h>
#include <stdlib.h>    /* realpath (POSIX) */
#include <sys/stat.h>  /* stat, lstat (POSIX) */

/* Whether a stream is a terminal: POSIX isatty where the program asked for
 * POSIX (cli/plateau.c does), else "no" (progress then only on request). */
#if defined(_POSIX_C_SOURCE) && _POSIX_C_SOURCE >= 200112L
#include <unistd.h>
#define PLATEAU_CLI_ISATTY(f) isatty(fileno(f))
#else
#define PLATEAU_CLI_ISATTY(f) 0
#endif

static double plateau_cli_now(void)
{
#if defined(CLOCK_MONOTONIC)
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) == 0)
        return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
#endif
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

/* The progress line: the library calls back once per iteration with the
 * round, the iteration and the objective (options.progress).  A method's
 * rounds count up from 1 and each round's iterations count up, so a call
 * that does not move forward starts a new stage: method paper after its
 * area presolve. */
typedef struct plateau_cli_progress {
    FILE *err;
    int mode;           /* 1: shown; 0: shown after the first second; -1: never */
    int tty;            /* err is a terminal: one line, rewritten in place */
    plateau_method method;
    int presolve;       /* method paper: 1 an area presolve runs first, 0 none, -1 unknown */
    double t0, last;    /* the solve's start, the last line's time */
    int stage, round, iteration;
    size_t calls, width; /* width: the length of the line on the screen */
} plateau_cli_progress;

/* The stage's name and its objective's name. */
static void plateau_cli_stage(const plateau_cli_progress *p, const char **stage, const char **value)
{
    if (p->method == PLATEAU_METHOD_AREA) {
        *stage = "method area";
        *value = "area";
    } else if (p->method == PLATEAU_METHOD_PAPER_LITERAL) {
        *stage = "method paper-literal";
        *value = "F";
    } else if (p->stage > 0 || p->presolve == 0) {
        *stage = "method paper";
        *value = "F";
    } else if (p->presolve == 1) {
        *stage = "area presolve";
        *value = "area";
    } else {
        *stage = "paper or presolve"; /* several loops: the domain is not known */
        *value = "F/area";
    }
}

static int plateau_cli_progress_cb(int round, int iteration, double f, void *user)
{
    plateau_cli_progress *p = (plateau_cli_progress *)user;
    double now = plateau_cli_now();
    const char *stage, *value;
    char line[160];
    size_t len;
    int new_stage = p->calls > 0 && (round < p->round || (round == p->round && iteration <= p->iteration));
    p->stage += new_stage;
    p->calls++;
    p->round = round;
    p->iteration = iteration;
    if (p->mode < 0 || (p->mode == 0 && now - p->t0 < 1.0)) return 0;
    /* at most ten lines a second on a terminal, one elsewhere; a new stage at once */
    if (p->width > 0 && !new_stage && now - p->last < (p->tty ? 0.1 : 1.0)) return 0;
    p->last = now;
    plateau_cli_stage(p, &stage, &value);
    snprintf(line, sizeof line, "plateau: %s, round %d, iteration %d, %s %.7g, %.1f s", stage, round,
             iteration, value, f, now - p->t0);
    len = strlen(line);
    if (p->tty) {
        fprintf(p->err, "\r%s%*s", line, p->width > len ? (int)(p->width - len) : 0, "");
        p->width = len;
    } else {
        fprintf(p->err, "%s\n", line);
        p->width = 1;
    }
    fflush(p->err);
    return 0;
}

/* After the solve: the terminal's progress line blanked, so the summary
 * and the warnings start on a clean line. */
static void plateau_cli_progress_end(plateau_cli_progress *p)
{
    if (p->tty && p->width > 0) {
        fprintf(p->err, "\r%*s\r", (int)p->width, "");
        fflush(p->err);
    }
    p->width = 0;
}

/* Method paper starts from an area presolve on the circle domain (and on
 * the annulus of two loops): for one loop, ask the domain step itself;
 * for several loops the domain is not known before the solve. */
static int plateau_cli_presolve(const plateau_cli_args *a, const double *xyz, size_t m, size_t loops)
{
    plateau_domain_kind kind = PLATEAU_DOMAIN_PLANE;
    double *uv;
    int known;
    if (a->method != PLATEAU_METHOD_PAPER) return 0;
    if (loops > 1 || m > ((size_t)-1) / (2 * sizeof(double))) return -1;
    uv = (double *)malloc(2 * m * sizeof(double));
    if (!uv) return -1;
    known = plateau_boundary_domain(xyz, m, a->circle, NULL, uv, &kind, NULL) == PLATEAU_OK;
    free(uv);
    return known ? kind == PLATEAU_DOMAIN_CIRCLE : -1;
}

/* options.clock_fn: --max-seconds counts wall-clock seconds */
static double plateau_cli_clock(void *user)
{
    (void)user;
    return plateau_cli_now();
}

/* An output file of the run (-o or --svg), checked before anything runs:
 * naming one of the boundary files (the same file by any name, link or
 * hard link: st_dev and st_ino) is refused with status 2, so that a mesh
 * never replaces its own boundary.  A symbolic link is written through:
 * *resolved (free() it) gets the path it resolves to, so the library's
 * temporary-file-and-rename replaces the file it points to, in that file's
 * directory, and the link stays (the library alone, in standard C, would
 * replace the link itself); a link to a missing file is refused with
 * status 1.  Returns 0 when the path may be written. */
static int plateau_cli_output(const char *flag, const char *path, const plateau_cli_args *args,
                              char **resolved, char *msg, size_t msg_size)
{
    struct stat so, si;
    int i;
    *resolved = NULL;
    if (lstat(path, &so) == 0 && S_ISLNK(so.st_mode)) {
        *resolved = realpath(path, NULL);
        if (!*resolved) {
            snprintf(msg, msg_size, "%s %.120s is a symbolic link to a file that does not exist "
                     "(give the path of the file to write)", flag, path);
            return 1;
        }
    }
    if (stat(path, &so) != 0) return 0; /* a new file */
    for (i = 0; i < args->num_inputs; i++) {
        if (strcmp(args->inputs[i], "-") == 0 || stat(args->inputs[i], &si) != 0) continue;
        if (so.st_dev == si.st_dev && so.st_ino == si.st_ino) {
            snprintf(msg, msg_size, "%s %.120s is the boundary file %.120s: the mesh would replace it",
                     flag, path, args->inputs[i]);
            free(*resolved);
            *resolved = NULL;
            return 2;
        }
    }
    return 0;
}

/* Returns the exit status: 0 success (a valid mesh), 1 bad input or a
 * failed solve or write, 2 bad usage, 3 a mesh with defects (written as
 * asked, with a warning on errout; report.defects).  The summary or JSON
 * goes to out, messages to errout. */
PLATEAU_CLI_FN int plateau_cli_run(int argc, char **argv, FILE *out, FILE *errout)
{
    plateau_cli_args args;
    plateau_cli_result res;
    plateau_cli_progress prog;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_error err;
    plateau_result r;
    double *xyz = NULL, *tension = NULL, t0;
    long *lines = NULL; /* each vertex's line in its file */
    size_t m = 0, counts[PLATEAU_CLI_MAX_LOOPS], k = 0, file_off[PLATEAU_CLI_MAX_INPUTS + 1];
    plateau_cli_where where;
    int in;
    char msg[320], *mesh_file = NULL, *svg_file = NULL;
    int status = 0, capped = 0;

    if (plateau_cli_parse(argc, argv, &args, msg, sizeof msg) != 0) {
        fprintf(errout, "plateau: %s\nTry 'plateau --help'.\n", msg);
        return 2;
    }
    /* --help and --version: status 1 when the text could not be written
     * (stdout closed or full), as for every other output */
    if (args.help) {
        plateau_cli_usage(out);
        return fflush(out) != 0 || ferror(out) ? 1 : 0;
    }
    if (args.version) {
        fprintf(out, "plateau %s\n", PLATEAU_VERSION);
        return fflush(out) != 0 || ferror(out) ? 1 : 0;
    }
    /* reading holds the text and the vertices parsed from it (at most 4
     * bytes per byte: plateau_parse_boundary), and the text's buffer grows
     * by doubling: about 6 bytes per byte of input at the peak; so a cap
     * raised by --max-input-bytes stays below --max-memory / 6 (the
     * default memory limit's share when --max-memory is not given) */
    {
        size_t memory = args.have_max_memory ? (args.max_memory_mb ? (size_t)args.max_memory_mb << 20 : 0)
                                             : (size_t)PLATEAU_DEFAULT_MAX_MEMORY;
        size_t cap = args.max_input_bytes ? args.max_input_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
        if (memory && cap > memory / 6) {
            args.max_input_bytes = memory / 6 ? memory / 6 : 1;
            capped = 1;
        }
    }
    /* the output files, before anything runs */
    if (args.mesh_path && (status = plateau_cli_output("-o", args.mesh_path, &args, &mesh_file, msg,
                                                       sizeof msg)) == 0 &&
        args.svg_path)
        status = plateau_cli_output("--svg", args.svg_path, &args, &svg_file, msg, sizeof msg);
    if (status != 0) {
        fprintf(errout, "plateau: %s\n", msg);
        free(mesh_file);
        return status;
    }
    /* every file's loops, one after the other, and each vertex's file line */
    file_off[0] = 0;
    for (in = 0; in < args.num_inputs; in++) {
        double *fx = NULL, *all, *ft = NULL;
        long *alllines;
        size_t fm = 0, fk = 0;
        int overflow;
        plateau_boundary_lines info;
        if (plateau_cli_load_loops_cables(args.inputs[in], args.max_input_bytes, &fx, &fm, counts + k,
                                          PLATEAU_CLI_MAX_LOOPS - k, &fk, &info, &ft, msg, sizeof msg) != 0) {
            fprintf(errout, "plateau: %s\n", msg);
            if (capped && strstr(msg, "larger than the limit"))
                fprintf(errout, "plateau: that limit is the share of the memory limit reading may take "
                                "(a sixth of --max-memory, default 2048 MB): --max-memory raises it\n");
            plateau_boundary_free(xyz, NULL);
            free(tension);
            free(lines);
            free(mesh_file);
            free(svg_file);
            return 1;
        }
        plateau_cli_closing_notes(errout, args.inputs[in], &info);
        overflow = m + fm > ((size_t)-1) / (3 * sizeof(double));
        all = overflow ? NULL : (double *)malloc((m + fm) * 3 * sizeof(double));
        alllines = overflow ? NULL : (long *)malloc((m + fm) * sizeof(long));
        if (all && alllines && (ft || tension)) { /* the cables of all files, 0 for rigid edges */
            double *nt = (double *)realloc(tension, (m + fm + 1) * sizeof(double));
            if (nt) {
                if (!tension) memset(nt, 0, m * sizeof(double));
                tension = nt;
                if (ft) memcpy(tension + m, ft, fm * sizeof(double));
                else memset(tension + m, 0, fm * sizeof(double));
            } else {
                free(all);
                all = NULL;
            }
        }
        plateau_boundary_free(ft, NULL);
        if (!all || !alllines) {
            fprintf(errout, "plateau: out of memory reading the loops\n");
            free(all);
            free(alllines);
            plateau_boundary_free(fx, NULL);
            plateau_boundary_lines_free(&info, NULL);
            plateau_boundary_free(xyz, NULL);
            free(tension);
            free(lines);
            free(mesh_file);
            free(svg_file);
            return 1;
        }
        if (m > 0) {
            memcpy(all, xyz, m * 3 * sizeof(double));
            memcpy(alllines, lines, m * sizeof(long));
        }
        memcpy(all + 3 * m, fx, fm * 3 * sizeof(double));
        memcpy(alllines + m, info.lines, fm * sizeof(long));
        plateau_boundary_free(fx, NULL);
        plateau_boundary_lines_free(&info, NULL);
        plateau_boundary_free(xyz, NULL);
        free(lines);
        xyz = all;
        lines = alllines;
        m += fm;
        k += fk;
        file_off[in + 1] = m;
    }
    memset(&where, 0, sizeof where);
    where.lines = lines;
    where.m = m;
    where.counts = counts;
    where.k = k;
    where.files = args.inputs;
    where.file_off = file_off;
    where.num_files = args.num_inputs;

    /* the output files, before a long solve */
    if ((args.mesh_path && plateau_cli_check_writable(args.mesh_path, "the mesh file", msg, sizeof msg)) ||
        (args.svg_path && plateau_cli_check_writable(args.svg_path, "the picture", msg, sizeof msg))) {
        fprintf(errout, "plateau: %s\n", msg);
        plateau_boundary_free(xyz, NULL);
        free(tension);
        free(lines);
        free(mesh_file);
        free(svg_file);
        return 1;
    }
    plateau_cli_seed_warning(errout, &args, m, k);

    memset(&prog, 0, sizeof prog);
    prog.err = errout;
    prog.mode = args.progress;
    prog.tty = PLATEAU_CLI_ISATTY(errout);
    if (prog.mode == 0 && !prog.tty) prog.mode = -1;
    prog.method = args.method;
    prog.presolve = prog.mode >= 0 ? plateau_cli_presolve(&args, xyz, m, k) : 0;
    memset(&opt, 0, sizeof opt);
    opt.method = args.method;
    opt.interior_points = args.n;
    opt.seed = args.seed;
    opt.max_rounds = args.max_rounds;
    opt.force_circle_domain = args.circle;
    opt.seeding = args.seeding;
    opt.linear_solver = args.linear_solver;
    opt.area_tolerance = args.area_tolerance;
    opt.refine_boundary = args.refine_boundary;
    opt.pressure = args.pressure;
    opt.fix_volume = args.fix_volume;
    opt.volume = args.volume;
    opt.cable_tension = tension;
    opt.coarse_to_fine = args.coarse_to_fine;
    opt.max_seconds = args.max_seconds;
    opt.clock_fn = plateau_cli_clock;
    opt.stability = args.stability;
    opt.alternatives = args.alternatives;
    opt.least_area_topology = args.least_area;
    opt.critical_index = args.critical_index;
    if (args.have_max_memory)
        opt.max_memory = args.max_memory_mb ? (size_t)args.max_memory_mb << 20 : (size_t)-1;
    memset(&mesh, 0, sizeof mesh);
    memset(&res, 0, sizeof res);
    memset(&err, 0, sizeof err);
    if (prog.mode >= 0) {
        opt.progress = plateau_cli_progress_cb;
        opt.progress_user = &prog;
    }
    t0 = plateau_cli_now();
    prog.t0 = t0;
    if (k > 1) r = plateau_solve_loops(xyz, counts, k, &opt, &mesh, &res.report, &err);
    else r = plateau_solve(xyz, m, &opt, &mesh, &res.report, &err);
    res.elapsed_s = plateau_cli_now() - t0;
    plateau_cli_progress_end(&prog);
    if (r != PLATEAU_OK) {
        snprintf(msg, sizeof msg, "%s", err.message[0] ? err.message : plateau_result_string(r));
        /* with cables, step 1 numbers the polygon with their vertices
         * inserted: its indices are no file lines */
        if (!tension) plateau_cli_error_lines(msg, sizeof msg, &err, &where);
        if (r == PLATEAU_ERR_MEMORY_LIMIT) { /* the library's option is the tool's --max-memory */
            char *o = strstr(msg, "(options.max_memory)");
            if (o) snprintf(o, sizeof msg - (size_t)(o - msg), "(--max-memory raises it; 0: no limit)");
        }
        fprintf(errout, "plateau: %s: the solve failed: %s\n", args.input, msg);
        free(lines);
        plateau_mesh_free(&mesh);
        plateau_boundary_free(xyz, NULL);
        free(tension);
        free(mesh_file);
        free(svg_file);
        return 1;
    }
    res.input = args.input;
    res.boundary_vertices = m;
    res.vertices = mesh.num_vertices;
    res.triangles = mesh.num_triangles;
    res.seed = args.seed;
    res.points_requested = args.n;
    res.method_name = plateau_method_name(res.report.method);
    res.stop_string = plateau_stop_string(res.report.stop);
    /* the seeding used: auto is quality when n >= m / 4 (plateau_solve) */
    res.seeding_name = plateau_cli_quality_seeding(&args, m, k) ? "quality" : "paper";

    if (args.mesh_path) {
        r = plateau_write_mesh_format(mesh_file ? mesh_file : args.mesh_path, mesh.positions,
                                      mesh.num_vertices, mesh.triangles, mesh.num_triangles,
                                      args.stl_ascii ? PLATEAU_MESH_FORMAT_STL_ASCII : PLATEAU_MESH_FORMAT_AUTO,
                                      &err);
        if (r != PLATEAU_OK) {
            fprintf(errout, "plateau: %s\n", err.message);
            status = 1;
        } else {
            res.mesh_path = args.mesh_path;
        }
    }
    if (args.svg_path) {
        r = plateau_write_svg(svg_file ? svg_file : args.svg_path, mesh.positions, mesh.num_vertices, mesh.triangles,
                              mesh.num_triangles, args.have_view ? args.view : NULL,
                              &mesh.allocator, &err);
        if (r != PLATEAU_OK) {
            fprintf(errout, "plateau: %s\n", err.message);
            status = 1;
        } else {
            res.svg_path = args.svg_path;
        }
    }
    if (args.json) plateau_cli_print_json(out, &res);
    else plateau_cli_print_summary(out, &res);
    if (fflush(out) != 0) status = 1;
    plateau_cli_count_warning(errout, args.input, &args, &res.report);
    if (res.report.defects) {
        plateau_cli_print_warning(errout, args.input, &res.report);
        plateau_cli_print_advice(errout, &args, m, &res.report);
        if (status == 0) status = 3;
    }
    plateau_mesh_free(&mesh);
    plateau_boundary_free(xyz, NULL);
    free(tension);
    free(lines);
    free(mesh_file);
    free(svg_file);
    return status;
}

#endif /* PLATEAU_CLI_RUN_H */
