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

/* Where a file to be written lands, so that two outputs can be compared
 * before either exists: the file's device and inode when it exists (any
 * name, symbolic or hard link), else its directory's with its last name
 * ("x.obj", "./x.obj", "sub/../x.obj" and a path through a linked
 * directory agree).  exists -1: neither the file nor its directory could
 * be looked at (the path is then compared as text). */
typedef struct plateau_cli_place {
    int exists;
    dev_t dev;
    ino_t ino;
    const char *path, *name; /* name: the path's last component */
} plateau_cli_place;

static void plateau_cli_place_of(const char *path, plateau_cli_place *p)
{
    struct stat s;
    const char *slash = strrchr(path, '/');
    char dir[4096];
    p->path = path;
    p->name = slash ? slash + 1 : path;
    p->exists = -1;
    if (stat(path, &s) == 0) {
        p->exists = 1;
    } else {
        if (!slash) strcpy(dir, ".");
        else if (slash == path) strcpy(dir, "/");
        else if ((size_t)(slash - path) < sizeof dir) snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
        else return;
        if (stat(dir, &s) != 0) return;
        p->exists = 0;
    }
    p->dev = s.st_dev;
    p->ino = s.st_ino;
}

static int plateau_cli_same_place(const plateau_cli_place *a, const plateau_cli_place *b)
{
    if (a->exists < 0 || b->exists < 0) return strcmp(a->path, b->path) == 0;
    return a->exists == b->exists && a->dev == b->dev && a->ino == b->ino &&
           (a->exists || strcmp(a->name, b->name) == 0);
}

/* An output file of the run (-o or --svg: flag; what: "the mesh" or "the
 * picture"), checked before anything runs: naming one of the input files
 * (the boundary files, or the mesh of --minimize)
 * (the same file by any name, link or hard link: st_dev and st_ino; for
 * "-", standard input when it is a file) is refused with status 2, so
 * that an output never replaces its own input.  A symbolic link is written
 * through: *resolved (free() it) gets the path it resolves to, so the
 * library's temporary-file-and-rename replaces the file it points to, in
 * that file's directory, and the link stays (the library alone, in
 * standard C, would replace the link itself); a link to a missing file is
 * refused with status 1.  Returns 0 when the path may be written. */
static int plateau_cli_output(const char *flag, const char *what, const char *path, const plateau_cli_args *args,
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
    for (i = 0; i <= args->num_inputs; i++) { /* the boundary files, then the mesh of --minimize or --mesh */
        const char *in = i < args->num_inputs ? args->inputs[i]
                                              : args->minimize_path ? args->minimize_path : args->pattern_mesh;
        int from_stdin = in && strcmp(in, "-") == 0;
        if (!in || (from_stdin ? fstat(fileno(stdin), &si) != 0 || !S_ISREG(si.st_mode) : stat(in, &si) != 0))
            continue;
        if (so.st_dev == si.st_dev && so.st_ino == si.st_ino) {
            snprintf(msg, msg_size, "%s %.120s is the %s%s %.120s: %s would replace it", flag, path,
                     args->minimize_path || args->pattern_mesh ? "mesh file" : "boundary file",
                     from_stdin ? " on standard input," : "",
                     in, what);
            free(*resolved);
            *resolved = NULL;
            return 2;
        }
    }
    return 0;
}

/* Everything one run holds; plateau_cli_run frees it all at its one exit. */
typedef struct plateau_cli_run_state {
    plateau_cli_args args;
    double *xyz;        /* the loops of all files, one after the other */
    double *tension;    /* each vertex's cable tension (0: a rigid edge), or NULL */
    int *slide;         /* each vertex's slide mark (0: fixed), or NULL */
    double *slide_dir;  /* ... and its direction, 3 per vertex */
    double *supports;   /* --supports: the points, a closed ring's first repeated at its end */
    size_t *support_counts, support_lines;
    int slide_set;      /* slide covers the vertices read so far */
    long *lines;        /* each vertex's line in its file */
    size_t m, k;        /* vertices, loops */
    size_t counts[PLATEAU_CLI_MAX_LOOPS], file_off[PLATEAU_CLI_MAX_INPUTS + 1];
    char *mesh_file, *svg_file; /* what -o and --svg resolve to (plateau_cli_output) */
    char *pattern_svg_file, *pattern_dxf_file; /* ... --pattern-svg and --pattern-dxf */
    plateau_pattern pattern; /* --pattern */
    int capped;         /* --max-input-bytes lowered to the memory limit's share */
    plateau_mesh mesh;
    plateau_cli_result res;
    char stop_text[240]; /* why the rounds ended, in the tool's words */
    /* a failure: "plateau: MSG", after "INPUT: the solve failed: " when the
     * solve failed, then "Try 'plateau --help'." for bad usage and a hint */
    char msg[320];
    plateau_result code; /* the failure's, for --json */
    const char *failed_input;
    int usage;
    const char *hint;
} plateau_cli_run_state;

/* Reading holds the text and the vertices parsed from it (at most 4 bytes
 * per byte: plateau_parse_boundary), and the text's buffer grows by
 * doubling: about 6 bytes per byte of input at the peak; so a cap raised
 * by --max-input-bytes stays below --max-memory / 6 (the default memory
 * limit's share when --max-memory is not given). */
static void plateau_cli_cap_input(plateau_cli_run_state *st)
{
    plateau_cli_args *a = &st->args;
    size_t memory = a->have_max_memory ? (a->max_memory_mb ? (size_t)a->max_memory_mb << 20 : 0)
                                       : (size_t)PLATEAU_DEFAULT_MAX_MEMORY;
    size_t cap = a->max_input_bytes ? a->max_input_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
    if (memory && cap > memory / 6) {
        a->max_input_bytes = memory / 6 ? memory / 6 : 1;
        st->capped = 1;
    }
}

/* The output files, before anything runs: each against the inputs
 * (plateau_cli_output), then against each other (plateau_cli_same_place),
 * so that no output replaces an input or another output; the status. */
static int plateau_cli_check_outputs(plateau_cli_run_state *st)
{
    const char *const flag[4] = {"-o", "--svg", "--pattern-svg", "--pattern-dxf"};
    const char *const what[4] = {"the mesh", "the picture", "the panels' picture", "the panels' DXF"};
    const char *path[4];
    char **resolved[4];
    plateau_cli_place place[4];
    int status = 0, i, j;
    path[0] = st->args.mesh_path;
    path[1] = st->args.svg_path;
    path[2] = st->args.pattern_svg;
    path[3] = st->args.pattern_dxf;
    resolved[0] = &st->mesh_file;
    resolved[1] = &st->svg_file;
    resolved[2] = &st->pattern_svg_file;
    resolved[3] = &st->pattern_dxf_file;
    for (i = 0; i < 4 && status == 0; i++)
        if (path[i]) status = plateau_cli_output(flag[i], what[i], path[i], &st->args, resolved[i], st->msg, sizeof st->msg);
    for (i = 0; i < 4 && status == 0; i++) {
        if (!path[i]) continue;
        plateau_cli_place_of(*resolved[i] ? *resolved[i] : path[i], &place[i]);
        for (j = 0; j < i && status == 0; j++) {
            if (!path[j] || !plateau_cli_same_place(&place[j], &place[i])) continue;
            snprintf(st->msg, sizeof st->msg, "%s %.120s and %s %.120s are the same file: %s would replace %s",
                     flag[j], path[j], flag[i], path[i], what[i], what[j]);
            status = 2;
        }
    }
    if (status) st->code = status == 2 ? PLATEAU_ERR_ARGUMENT : PLATEAU_ERR_IO;
    return status;
}

/* Appends file in's loops (and cables, and each vertex's file line) to
 * st's.  Returns 0, or 1 with the reason in st->msg. */
static int plateau_cli_read_input(plateau_cli_run_state *st, int in, FILE *errout)
{
    double *fx = NULL, *all, *ft = NULL, *fd = NULL;
    int *fs = NULL;
    long *alllines;
    size_t fm = 0, fk = 0, m = st->m;
    int overflow;
    plateau_boundary_lines info;
    if (plateau_cli_load_input(st->args.inputs[in], st->args.max_input_bytes, &fx, &fm, st->counts + st->k,
                               PLATEAU_CLI_MAX_LOOPS - st->k, &fk, &info, &ft, &fs, &fd, st->msg, sizeof st->msg,
                               &st->code) != 0) {
        if (st->capped && strstr(st->msg, "larger than the limit"))
            st->hint = "that limit is the share of the memory limit reading may take "
                       "(a sixth of --max-memory, default 2048 MB): --max-memory raises it";
        return 1;
    }
    plateau_cli_closing_notes(errout, st->args.inputs[in], &info);
    overflow = m + fm > ((size_t)-1) / (3 * sizeof(double));
    all = overflow ? NULL : (double *)malloc((m + fm) * 3 * sizeof(double));
    alllines = overflow ? NULL : (long *)malloc((m + fm) * sizeof(long));
    if (all && alllines && (ft || st->tension)) { /* the cables of all files, 0 for rigid edges */
        double *nt = (double *)realloc(st->tension, (m + fm + 1) * sizeof(double));
        if (nt) {
            if (!st->tension) memset(nt, 0, m * sizeof(double));
            st->tension = nt;
            if (ft) memcpy(st->tension + m, ft, fm * sizeof(double));
            else memset(st->tension + m, 0, fm * sizeof(double));
        } else {
            free(all);
            all = NULL;
        }
    }
    plateau_boundary_free(ft, NULL);
    if (all && alllines && (fs || st->slide)) { /* the slide marks of all files, 0 for fixed vertices */
        int *ns = (int *)realloc(st->slide, (m + fm + 1) * sizeof(int));
        double *nd = ns ? (double *)realloc(st->slide_dir, (m + fm + 1) * 3 * sizeof(double)) : NULL;
        if (ns) st->slide = ns;
        if (nd) st->slide_dir = nd;
        if (ns && nd) {
            size_t i;
            for (i = 0; i < fm; i++) {
                ns[m + i] = fs ? fs[i] : 0;
                nd[3 * (m + i)] = fd ? fd[3 * i] : 0.0;
                nd[3 * (m + i) + 1] = fd ? fd[3 * i + 1] : 0.0;
                nd[3 * (m + i) + 2] = fd ? fd[3 * i + 2] : 0.0;
            }
            if (m > 0 && !st->slide_set) memset(ns, 0, m * sizeof(int)), memset(nd, 0, 3 * m * sizeof(double));
            st->slide_set = 1;
        } else {
            free(all);
            all = NULL;
        }
    }
    plateau_slides_free(fs, fd, NULL);
    if (all && alllines) {
        if (m > 0) {
            memcpy(all, st->xyz, m * 3 * sizeof(double));
            memcpy(alllines, st->lines, m * sizeof(long));
        }
        memcpy(all + 3 * m, fx, fm * 3 * sizeof(double));
        memcpy(alllines + m, info.lines, fm * sizeof(long));
        plateau_boundary_free(st->xyz, NULL);
        free(st->lines);
        st->xyz = all;
        st->lines = alllines;
        st->m = m + fm;
        st->k += fk;
        st->file_off[in + 1] = st->m;
    } else {
        free(all);
        free(alllines);
        snprintf(st->msg, sizeof st->msg, "out of memory reading the loops");
        st->code = PLATEAU_ERR_OUT_OF_MEMORY;
    }
    plateau_boundary_free(fx, NULL);
    plateau_boundary_lines_free(&info, NULL);
    return all && alllines ? 0 : 1;
}

/* The supports file of --supports (lines "x y z", a blank line between
 * polylines, plateau_parse_boundary_lines with split_loops; a polyline
 * whose last point equals its first is a closed ring, and the library
 * takes it so when that point stands at its end again).  Returns 0, or 1
 * with the reason in st->msg. */
static int plateau_cli_read_supports(plateau_cli_run_state *st)
{
    const char *path = st->args.supports_path;
    size_t limit = st->args.max_input_bytes ? st->args.max_input_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
    size_t size = 0, m = 0, j, at = 0, from = 0;
    plateau_boundary_lines info;
    plateau_error err;
    plateau_result r = PLATEAU_ERR_IO;
    double *xyz = NULL;
    char *buf = NULL;
    int e = 0;
    FILE *f = fopen(path, "rb");
    memset(&info, 0, sizeof info);
    info.split_loops = 1;
    if (f) {
        r = plateau_cli_read_text(f, limit, &buf, &size, &e);
        fclose(f);
    } else {
        e = errno;
    }
    if (r != PLATEAU_OK) {
        free(buf);
        st->code = r;
        if (r == PLATEAU_ERR_IO) plateau_cli_cannot_read(st->msg, sizeof st->msg, path, e);
        else snprintf(st->msg, sizeof st->msg, "%.120s: %s", path, plateau_result_string(r));
        return 1;
    }
    r = plateau_parse_boundary_lines(buf ? buf : "", size, NULL, &xyz, &m, &info, &err);
    free(buf);
    if (r == PLATEAU_OK && m == 0) {
        r = PLATEAU_ERR_PARSE;
        snprintf(err.message, sizeof err.message, "no support points");
    }
    if (r == PLATEAU_OK) {
        st->supports = (double *)malloc(3 * (m + info.num_loops) * sizeof(double));
        st->support_counts = (size_t *)malloc(info.num_loops * sizeof(size_t));
        if (!st->supports || !st->support_counts) r = PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (j = 0; r == PLATEAU_OK && j < info.num_loops; j++) {
        size_t c = info.loop_counts[j];
        memcpy(st->supports + 3 * at, xyz + 3 * from, 3 * c * sizeof(double));
        if (info.closing_lines[j]) { /* a ring: its closing point again */
            memcpy(st->supports + 3 * (at + c), xyz + 3 * from, 3 * sizeof(double));
            c++;
        }
        st->support_counts[j] = c;
        at += c;
        from += info.loop_counts[j];
    }
    if (r == PLATEAU_OK) st->support_lines = info.num_loops;
    plateau_boundary_free(xyz, NULL);
    plateau_boundary_lines_free(&info, NULL);
    if (r == PLATEAU_OK) return 0;
    st->code = r;
    snprintf(st->msg, sizeof st->msg, "%.120s: %s", path,
             r == PLATEAU_ERR_OUT_OF_MEMORY ? "out of memory reading the supports" : err.message);
    return 1;
}

/* The options of the solve, from the tool's. */
static void plateau_cli_solve_options(const plateau_cli_run_state *st, plateau_options *opt)
{
    const plateau_cli_args *a = &st->args;
    memset(opt, 0, sizeof *opt);
    opt->method = a->method;
    opt->interior_points = a->n;
    opt->seed = a->seed;
    opt->max_rounds = a->max_rounds;
    opt->force_circle_domain = a->circle;
    /* an edge length is the quality seeding's: asked for, it is that seeding */
    opt->seeding = a->edge_length > 0.0 && a->seeding == PLATEAU_SEEDING_AUTO ? PLATEAU_SEEDING_QUALITY
                                                                              : a->seeding;
    opt->quality_edge_length = a->edge_length;
    opt->linear_solver = a->linear_solver;
    opt->area_tolerance = a->area_tolerance;
    opt->refine_boundary = a->refine_boundary;
    opt->pressure = a->pressure;
    opt->fix_volume = a->fix_volume;
    opt->volume = a->volume;
    opt->cable_tension = st->tension;
    opt->slide = st->slide;
    opt->slide_direction = st->slide_dir;
    opt->supports = st->supports;
    opt->support_counts = st->support_counts;
    opt->num_support_polylines = st->support_lines;
    opt->coarse_to_fine = a->coarse_to_fine;
    opt->max_seconds = a->max_seconds;
    opt->accuracy = a->accuracy;
    opt->clock_fn = plateau_cli_clock;
    opt->stability = a->stability;
    opt->alternatives = a->alternatives;
    opt->least_area_topology = a->least_area;
    opt->critical_index = a->critical_index;
    if (a->have_max_memory) opt->max_memory = a->max_memory_mb ? (size_t)a->max_memory_mb << 20 : (size_t)-1;
}

/* The run's options (plateau_cli_solve_options) and its progress line:
 * on with --progress or a terminal on errout, off with --no-progress or
 * otherwise; may_presolve: whether the run may start with method area's
 * presolve (plateau_solve; plateau_mesh_minimize presolves only when
 * asked), which the line then names. */
static void plateau_cli_progress_options(plateau_cli_run_state *st, FILE *errout, int may_presolve,
                                         plateau_cli_progress *prog, plateau_options *opt)
{
    memset(prog, 0, sizeof *prog);
    prog->err = errout;
    prog->mode = st->args.progress;
    prog->tty = PLATEAU_CLI_ISATTY(errout);
    if (prog->mode == 0 && !prog->tty) prog->mode = -1;
    prog->method = st->args.method;
    prog->presolve = may_presolve && prog->mode >= 0 ? plateau_cli_presolve(&st->args, st->xyz, st->m, st->k) : 0;
    plateau_cli_solve_options(st, opt);
    if (prog->mode >= 0) {
        opt->progress = plateau_cli_progress_cb;
        opt->progress_user = prog;
    }
}

/* The solve, with the progress line; st->mesh and st->res.report.
 * Returns 0, or 1 with the reason in st->msg. */
static int plateau_cli_solve(plateau_cli_run_state *st, FILE *errout)
{
    plateau_cli_progress prog;
    plateau_options opt;
    plateau_error err;
    plateau_result r;
    plateau_cli_where where;
    double t0;
    plateau_cli_progress_options(st, errout, 1, &prog, &opt);
    memset(&err, 0, sizeof err);
    t0 = plateau_cli_now();
    prog.t0 = t0;
    if (st->k > 1) r = plateau_solve_loops(st->xyz, st->counts, st->k, &opt, &st->mesh, &st->res.report, &err);
    else r = plateau_solve(st->xyz, st->m, &opt, &st->mesh, &st->res.report, &err);
    st->res.elapsed_s = plateau_cli_now() - t0;
    plateau_cli_progress_end(&prog);
    if (r == PLATEAU_OK) return 0;
    snprintf(st->msg, sizeof st->msg, "%s", err.message[0] ? err.message : plateau_result_string(r));
    memset(&where, 0, sizeof where);
    where.lines = st->lines;
    where.m = st->m;
    where.counts = st->counts;
    where.k = st->k;
    where.files = st->args.inputs;
    where.file_off = st->file_off;
    where.num_files = st->args.num_inputs;
    /* with cables, step 1 numbers the polygon with their vertices
     * inserted: its indices are no file lines */
    if (!st->tension) plateau_cli_error_lines(st->msg, sizeof st->msg, &err, &where);
    plateau_cli_flag_names(st->msg, sizeof st->msg);
    st->code = r;
    st->failed_input = st->args.input;
    return 1;
}

/* The boundary of a mesh with its adjacency (the edges of one triangle):
 * how many vertices it has and in how many loops (each boundary edge
 * leads from a vertex to the next as its triangle runs it; a vertex where
 * two loops touch counts once).  0 loops: a closed surface.  Returns 0,
 * or 1 when out of memory. */
static int plateau_cli_mesh_boundary(const plateau_mesh *mesh, size_t *vertices, size_t *loops)
{
    size_t nv = mesh->num_vertices, e, v;
    plateau_index *next = (plateau_index *)malloc((nv ? nv : 1) * sizeof(plateau_index));
    *vertices = 0;
    *loops = 0;
    if (!next) return 1;
    for (v = 0; v < nv; v++) next[v] = -1;
    for (e = 0; e < mesh->num_edges; e++) {
        plateau_index a = mesh->edges[2 * e], b = mesh->edges[2 * e + 1];
        if (mesh->edge_triangles[2 * e + 1] >= 0) continue;
        next[a] = b; /* edge_triangles[2e] runs a -> b */
    }
    for (v = 0; v < nv; v++) *vertices += next[v] >= 0;
    for (v = 0; v < nv; v++) { /* each loop once: walk it, unlinking */
        size_t w = v, steps = 0;
        if (next[v] < 0) continue;
        while (next[w] >= 0 && steps++ <= nv) {
            size_t u = (size_t)next[w];
            next[w] = -1;
            w = u;
        }
        (*loops)++;
    }
    free(next);
    return 0;
}

/* --minimize: the mesh file (or standard input for "-"), read, checked
 * and made a mesh (plateau_mesh_create: the vertices of its boundary, the
 * edges of one triangle, fixed; a vertex in no triangle fixed too, with a
 * note).  Returns 0, or 1 with the reason in st->msg: the parser's
 * message with its line, or plateau_mesh_create's with the triangle's
 * file line; a mesh with no boundary (nothing would hold it). */
static int plateau_cli_read_mesh(plateau_cli_run_state *st, FILE *errout)
{
    const char *path = st->args.minimize_path ? st->args.minimize_path : st->args.pattern_mesh;
    size_t limit = st->args.max_input_bytes ? st->args.max_input_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
    size_t size = 0, nv = 0, nt = 0, v, lonely = 0;
    double *pos = NULL;
    plateau_index *tri = NULL;
    long *lines = NULL;
    char *buf = NULL;
    plateau_error err;
    plateau_result r = PLATEAU_ERR_IO;
    int from_stdin = strcmp(path, "-") == 0, e = 0;
    FILE *f;
    errno = 0;
    f = from_stdin ? stdin : fopen(path, "rb");
    if (!f) e = errno;
    if (from_stdin) path = "(standard input)";
    if (f) {
        r = plateau_cli_read_text(f, limit, &buf, &size, &e);
        if (!from_stdin) fclose(f);
    }
    st->code = r;
    if (r == PLATEAU_ERR_INPUT_TOO_LARGE) {
        snprintf(st->msg, sizeof st->msg, "%.120s: the input is larger than the limit of %lu bytes "
                 "(--max-input-bytes raises it)", path, (unsigned long)limit);
    } else if (r == PLATEAU_ERR_OUT_OF_MEMORY) {
        snprintf(st->msg, sizeof st->msg, "%.120s: out of memory reading the file", path);
    } else if (r != PLATEAU_OK) {
        plateau_cli_cannot_read(st->msg, sizeof st->msg, path, e);
    } else {
        r = plateau_parse_mesh(buf ? buf : "", size, NULL, &pos, &nv, &tri, &nt, &lines, &err);
        if (r == PLATEAU_OK) r = plateau_mesh_create(pos, nv, NULL, tri, nt, NULL, &st->mesh, &err);
        if (r != PLATEAU_OK) {
            snprintf(st->msg, sizeof st->msg, "%.120s: %s", path, err.message);
            /* plateau_mesh_create names a triangle: its face's line */
            if (lines && err.index >= 0 && (size_t)err.index < nt) {
                size_t len = strlen(st->msg);
                snprintf(st->msg + len, sizeof st->msg - len, " (triangle %ld, of the face on line %ld)", err.index,
                         lines[err.index]);
            }
            st->code = r;
        }
    }
    free(buf);
    plateau_mesh_arrays_free(pos, tri, lines, NULL);
    if (r != PLATEAU_OK) return 1;
    st->res.initial_area = plateau_mesh_area(&st->mesh);
    if (st->args.pattern_mesh) return 0; /* patterned as it is: a closed mesh too */
    if (plateau_cli_mesh_boundary(&st->mesh, &st->m, &st->k)) {
        snprintf(st->msg, sizeof st->msg, "%.120s: out of memory reading the mesh's boundary", path);
        st->code = PLATEAU_ERR_OUT_OF_MEMORY;
        return 1;
    }
    if (st->k == 0) {
        snprintf(st->msg, sizeof st->msg, "%.120s: the mesh has no boundary (every edge has two triangles): "
                 "nothing would hold it, and its area would shrink to nothing", path);
        st->code = PLATEAU_ERR_ARGUMENT;
        return 1;
    }
    for (v = 0; v < st->mesh.num_vertices; v++) /* a vertex in no triangle stays where it is */
        if (st->mesh.vertex_triangle_start[v + 1] == st->mesh.vertex_triangle_start[v] && !st->mesh.fixed[v]) {
            st->mesh.fixed[v] = 1;
            lonely++;
        }
    if (lonely)
        fprintf(errout, "plateau: note: %.120s: %lu vertices are in no face; they stay as they are\n", path,
                (unsigned long)lonely);
    st->res.initial_area = plateau_mesh_area(&st->mesh);
    st->code = PLATEAU_OK;
    return 0;
}

/* --minimize: plateau_mesh_minimize on st->mesh with the tool's options
 * and progress; st->res.report.  Returns 0, or 1 with the reason in st->msg. */
static int plateau_cli_minimize(plateau_cli_run_state *st, FILE *errout)
{
    plateau_cli_progress prog;
    plateau_options opt;
    plateau_error err;
    plateau_result r;
    double t0;
    plateau_cli_progress_options(st, errout, 0, &prog, &opt);
    memset(&err, 0, sizeof err);
    t0 = plateau_cli_now();
    prog.t0 = t0;
    r = plateau_mesh_minimize(&st->mesh, &opt, &st->res.report, &err);
    st->res.elapsed_s = plateau_cli_now() - t0;
    plateau_cli_progress_end(&prog);
    if (r == PLATEAU_OK) return 0;
    snprintf(st->msg, sizeof st->msg, "%s", err.message[0] ? err.message : plateau_result_string(r));
    plateau_cli_flag_names(st->msg, sizeof st->msg);
    st->code = r;
    st->failed_input = st->args.minimize_path;
    return 1;
}

/* Writes the mesh and the picture asked for; a failure is told at once
 * and makes the status 1, and the summary still follows. */
static int plateau_cli_write_outputs(plateau_cli_run_state *st, FILE *errout)
{
    const plateau_cli_args *a = &st->args;
    plateau_mesh *mesh = &st->mesh;
    plateau_error err;
    int status = 0;
    if (a->mesh_path) {
        const char *path = st->mesh_file ? st->mesh_file : a->mesh_path;
        plateau_result wr;
#ifndef PLATEAU_NO_EXTRAS
        /* the frame and the cables marked (PLY's vertex property, OBJ's
         * polylines); without memory for the marks, the frame alone */
        unsigned char *marks = (unsigned char *)malloc(mesh->num_vertices ? mesh->num_vertices : 1);
        if (marks && plateau_mesh_vertex_marks(mesh, marks, NULL) != PLATEAU_OK) {
            free(marks);
            marks = NULL;
        }
        wr = plateau_write_mesh_marked(path, mesh->positions, mesh->num_vertices, mesh->triangles,
                                       mesh->num_triangles, marks,
                                       a->stl_ascii ? PLATEAU_MESH_FORMAT_STL_ASCII : PLATEAU_MESH_FORMAT_AUTO,
                                       &mesh->allocator, &err);
        free(marks);
#else
        /* the marked writer is compiled out: the plain writer (no marks,
         * the format from the file's extension) */
        if (a->stl_ascii) {
            snprintf(err.message, sizeof err.message,
                     "--stl-ascii needs the marked writer, compiled out by PLATEAU_NO_EXTRAS");
            wr = PLATEAU_ERR_ARGUMENT;
        } else {
            wr = plateau_write_mesh(path, mesh->positions, mesh->num_vertices, mesh->triangles,
                                    mesh->num_triangles, &err);
        }
#endif
        if (wr != PLATEAU_OK) {
            plateau_cli_flag_names(err.message, sizeof err.message);
            fprintf(errout, "plateau: %s\n", err.message);
            status = 1;
        } else {
            st->res.mesh_path = a->mesh_path;
        }
    }
    if (a->svg_path) {
        if (plateau_write_svg(st->svg_file ? st->svg_file : a->svg_path, mesh->positions, mesh->num_vertices,
                              mesh->triangles, mesh->num_triangles, a->have_view ? a->view : NULL,
                              &mesh->allocator, &err) != PLATEAU_OK) {
            plateau_cli_flag_names(err.message, sizeof err.message);
            fprintf(errout, "plateau: %s\n", err.message);
            status = 1;
        } else {
            st->res.svg_path = a->svg_path;
        }
    }
    return status;
}

/* --pattern: the cutting pattern of st->mesh and its files; a failure is
 * status 1, its message in st->msg (--mesh: the run's failure) or told
 * at once on errout (after a solve, whose summary still follows). */
static int plateau_cli_pattern(plateau_cli_run_state *st, FILE *errout, int fail_in_msg)
{
    const plateau_cli_args *a = &st->args;
    plateau_pattern_options o;
    plateau_error err;
    plateau_result r;
    int status = 0;
    memset(&o, 0, sizeof o);
    o.width = a->pattern_width;
    o.seams = a->pattern_seams;
    if (a->have_pattern_direction) memcpy(o.direction, a->pattern_direction, sizeof o.direction);
    if (a->have_pattern_point) memcpy(o.point, a->pattern_point, sizeof o.point);
    o.shrink_along = a->pattern_shrink_along / 100.0;
    o.shrink_across = a->pattern_shrink_across / 100.0;
    o.panels = a->pattern_panels;
    r = plateau_pattern_make(st->mesh.positions, st->mesh.num_vertices, st->mesh.triangles, st->mesh.num_triangles,
                             &o, NULL, &st->pattern, &err);
    if (r != PLATEAU_OK) {
        plateau_cli_flag_names(err.message, sizeof err.message);
        if (!fail_in_msg) {
            fprintf(errout, "plateau: the cutting pattern failed: %s\n", err.message);
            return 1;
        }
        snprintf(st->msg, sizeof st->msg, "%.120s: the cutting pattern failed: %s", st->args.pattern_mesh,
                 err.message);
        st->code = r;
        return 1;
    }
    st->res.pattern = &st->pattern;
    if (a->pattern_svg) {
        r = plateau_pattern_write_svg(st->pattern_svg_file ? st->pattern_svg_file : a->pattern_svg, &st->pattern,
                                      a->pattern_marks, &err);
        if (r != PLATEAU_OK) fprintf(errout, "plateau: %s\n", err.message);
        else st->res.pattern_svg_path = a->pattern_svg;
        status |= r != PLATEAU_OK;
    }
    if (a->pattern_dxf) {
        r = plateau_pattern_write_dxf(st->pattern_dxf_file ? st->pattern_dxf_file : a->pattern_dxf, &st->pattern,
                                      a->pattern_marks, &err);
        if (r != PLATEAU_OK) fprintf(errout, "plateau: %s\n", err.message);
        else st->res.pattern_dxf_path = a->pattern_dxf;
        status |= r != PLATEAU_OK;
    }
    return status;
}

/* --mesh: the mesh read, patterned, reported; the status. */
static int plateau_cli_pattern_mesh(plateau_cli_run_state *st, FILE *out, FILE *errout)
{
    double t0 = plateau_cli_now();
    int status = plateau_cli_pattern(st, errout, 1);
    if (!st->res.pattern) return status;
    st->res.elapsed_s = plateau_cli_now() - t0;
    st->res.input = st->args.pattern_mesh;
    st->res.vertices = st->mesh.num_vertices;
    st->res.triangles = st->mesh.num_triangles;
    if (st->args.json) {
        plateau_cli_print_json_pattern_only(out, &st->res);
    } else {
        fprintf(out, "plateau %s: %s\n", PLATEAU_VERSION, st->res.input);
        fprintf(out, "  input      a mesh to pattern (--mesh), %lu vertices, %lu triangles, area %.10g\n",
                (unsigned long)st->res.vertices, (unsigned long)st->res.triangles, st->res.initial_area);
        plateau_cli_print_summary_pattern(out, &st->res);
        fprintf(out, "  elapsed    %.3f s\n", st->res.elapsed_s);
    }
    if (fflush(out) != 0) status = 1;
    return status;
}

/* The summary or the JSON, then the warnings; returns the run's status
 * from the status of the writes. */
static int plateau_cli_report(plateau_cli_run_state *st, FILE *out, FILE *errout, int status)
{
    plateau_cli_result *res = &st->res;
    if (st->args.json) plateau_cli_print_json(out, res);
    else plateau_cli_print_summary(out, res);
    if (fflush(out) != 0) status = 1;
    plateau_cli_count_warning(errout, res->input, &st->args, &res->report);
    if (res->report.defects) {
        plateau_cli_print_warning(errout, res->input, &res->report);
        plateau_cli_print_advice(errout, &st->args, res);
        if (status == 0) status = 3;
    }
    return status;
}

/* The length of the boundary's loops: the polygons read (st->xyz, the
 * loops st->counts, the last vertex of each joined to its first), or the
 * edges of one triangle of the mesh of --minimize. */
static double plateau_cli_boundary_length(const plateau_cli_run_state *st)
{
    double L = 0.0;
    size_t j, i, o = 0, e;
    if (st->args.minimize_path) {
        for (e = 0; e < st->mesh.num_edges; e++)
            if (st->mesh.edge_triangles[2 * e + 1] < 0) L += plateau_edge_length(&st->mesh, e);
        return L;
    }
    for (j = 0; j < (st->k ? st->k : 1); o += st->k ? st->counts[j] : st->m, j++) {
        size_t c = st->k ? st->counts[j] : st->m;
        for (i = 0; i < c; i++) {
            const double *a = st->xyz + 3 * (o + i), *b = st->xyz + 3 * (o + (i + 1) % c);
            L += sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
        }
    }
    return L;
}

/* The largest distance of a boundary vertex from the boundary's centroid
 * (the polygons read, or the vertices on the edges of one triangle of the
 * mesh of --minimize). */
static double plateau_cli_boundary_radius(const plateau_cli_run_state *st)
{
    const plateau_mesh *mesh = &st->mesh;
    double c[3] = {0.0, 0.0, 0.0}, r2 = 0.0;
    size_t v, e, count = 0, pass;
    int k;
    for (pass = 0; pass < 2; pass++) {
        if (!st->args.minimize_path) {
            for (v = 0; v < st->m; v++) {
                const double *x = st->xyz + 3 * v;
                double d2 = 0.0;
                for (k = 0; k < 3; k++) {
                    if (pass == 0) c[k] += x[k];
                    else d2 += (x[k] - c[k]) * (x[k] - c[k]);
                }
                if (d2 > r2) r2 = d2;
            }
            count = st->m;
        } else { /* each boundary edge's first vertex: each boundary vertex once on a loop */
            for (e = 0, count = 0; e < mesh->num_edges; e++) {
                const double *x;
                double d2 = 0.0;
                if (mesh->edge_triangles[2 * e + 1] >= 0) continue;
                x = mesh->positions + 3 * (size_t)mesh->edges[2 * e];
                for (k = 0; k < 3; k++) {
                    if (pass == 0) c[k] += x[k];
                    else d2 += (x[k] - c[k]) * (x[k] - c[k]);
                }
                if (d2 > r2) r2 = d2;
                count++;
            }
        }
        if (count == 0) return 0.0;
        if (pass == 0)
            for (k = 0; k < 3; k++) c[k] /= (double)count;
    }
    return sqrt(r2);
}

/* What the run produced, for the summary and the JSON. */
static void plateau_cli_fill_result(plateau_cli_run_state *st)
{
    plateau_cli_result *res = &st->res;
    res->boundary_length = plateau_cli_boundary_length(st);
    res->boundary_radius = plateau_cli_boundary_radius(st);
    if (!st->args.minimize_path && st->mesh.num_edges) { /* the polygons' longest edge */
        size_t j, i, o = 0;
        double longest = 0.0;
        for (j = 0; j < (st->k ? st->k : 1); o += st->k ? st->counts[j] : st->m, j++) {
            size_t c = st->k ? st->counts[j] : st->m;
            for (i = 0; i < c; i++) {
                const double *x = st->xyz + 3 * (o + i), *y = st->xyz + 3 * (o + (i + 1) % c);
                double d = sqrt((y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
                                (y[2] - x[2]) * (y[2] - x[2]));
                if (d > longest) longest = d;
            }
        }
        res->edge_ratio = longest / plateau_mean_edge_length(&st->mesh);
    }
    res->input = st->args.minimize_path ? st->args.minimize_path : st->args.input;
    res->minimized = st->args.minimize_path != NULL;
    res->loops = st->k;
    res->boundary_vertices = st->m;
    res->vertices = st->mesh.num_vertices;
    res->triangles = st->mesh.num_triangles;
    res->seed = st->args.seed;
    res->points_requested = st->args.n;
    res->critical_index = st->args.critical_index;
    res->stability_off = st->args.stability == PLATEAU_OFF;
    res->edge_length = st->args.edge_length;
    res->method_name = plateau_method_name(res->report.method);
    snprintf(st->stop_text, sizeof st->stop_text, "%s", plateau_stop_string(res->report.stop));
    plateau_cli_flag_names(st->stop_text, sizeof st->stop_text);
    res->stop_string = st->stop_text;
    /* a pressure given (not a held volume's) is the film's: the report
     * holds it scaled to the solver's units and back, the typed value is exact */
    if (st->args.pressure != 0.0 && !st->args.fix_volume) {
        res->report.pressure = st->args.pressure;
        res->pressure_typed = 1;
    }
    /* the seeding used: auto is quality when n >= m / 4 (plateau_solve) */
    if (!res->minimized)
        res->seeding_name = plateau_cli_quality_seeding(&st->args, st->m, st->k) ? "quality" : "paper";
}

/* Whether argv asks for --json before a "--": for a command line the
 * parser refused, its args stop at the bad option. */
static int plateau_cli_asks_json(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--json") == 0) return 1;
    return 0;
}

/* A failed run's message on errout; with --json its JSON object on out. */
static void plateau_cli_print_failure(const plateau_cli_run_state *st, int json, int status, FILE *out,
                                      FILE *errout)
{
    if (st->failed_input) fprintf(errout, "plateau: %s: the solve failed: %s\n", st->failed_input, st->msg);
    else fprintf(errout, "plateau: %s\n", st->msg);
    if (st->usage) fputs("Try 'plateau --help'.\n", errout);
    if (st->hint) fprintf(errout, "plateau: %s\n", st->hint);
    if (json) plateau_cli_print_json_error(out, st->failed_input, st->msg, st->code, status);
}

/* Returns the exit status: 0 success (a valid mesh), 1 bad input or a
 * failed solve or write, 2 bad usage, 3 a mesh with defects (written as
 * asked, with a warning on errout; report.defects).  The summary or JSON
 * goes to out, messages to errout. */
PLATEAU_CLI_FN int plateau_cli_run(int argc, char **argv, FILE *out, FILE *errout)
{
    plateau_cli_run_state st;
    int status, in;
    memset(&st, 0, sizeof st);
    if (plateau_cli_parse(argc, argv, &st.args, st.msg, sizeof st.msg) != 0) {
        st.usage = 1;
        st.code = PLATEAU_ERR_ARGUMENT;
        status = 2;
        goto done;
    }
    /* --help and --version: status 1 when the text could not be written
     * (stdout closed or full), as for every other output */
    if (st.args.help || st.args.version) {
        if (st.args.help) plateau_cli_usage(out);
        else fprintf(out, "plateau %s\n", PLATEAU_VERSION);
        status = fflush(out) != 0 || ferror(out) ? 1 : 0;
        goto done;
    }
    plateau_cli_cap_input(&st);
    if ((status = plateau_cli_check_outputs(&st)) != 0) goto done;
    if ((st.args.minimize_path || st.args.pattern_mesh) && (status = plateau_cli_read_mesh(&st, errout)) != 0)
        goto done;
    for (in = 0; in < st.args.num_inputs; in++)
        if ((status = plateau_cli_read_input(&st, in, errout)) != 0) goto done;
    if (st.args.supports_path && (status = plateau_cli_read_supports(&st)) != 0) goto done;
    /* the output files, before a long solve */
    if ((st.args.mesh_path &&
         plateau_cli_check_writable(st.args.mesh_path, "the mesh file", st.msg, sizeof st.msg)) ||
        (st.args.svg_path && plateau_cli_check_writable(st.args.svg_path, "the picture", st.msg, sizeof st.msg)) ||
        (st.args.pattern_svg &&
         plateau_cli_check_writable(st.args.pattern_svg, "the panels' picture", st.msg, sizeof st.msg)) ||
        (st.args.pattern_dxf &&
         plateau_cli_check_writable(st.args.pattern_dxf, "the panels' DXF", st.msg, sizeof st.msg))) {
        st.code = PLATEAU_ERR_IO;
        status = 1;
        goto done;
    }
    if (st.args.pattern_mesh) {
        status = plateau_cli_pattern_mesh(&st, out, errout);
        goto done;
    }
    if (st.args.minimize_path) {
        if ((status = plateau_cli_minimize(&st, errout)) != 0) goto done;
    } else {
        plateau_cli_seed_warning(errout, &st.args, st.m, st.k);
        if ((status = plateau_cli_solve(&st, errout)) != 0) goto done;
    }
    plateau_cli_fill_result(&st);
    status = plateau_cli_write_outputs(&st, errout);
    if (st.args.pattern_width > 0.0 && plateau_cli_pattern(&st, errout, 0) != 0) status = 1;
    status = plateau_cli_report(&st, out, errout, status);
done:
    if (st.msg[0])
        plateau_cli_print_failure(&st, st.args.json || (st.usage && plateau_cli_asks_json(argc, argv)), status, out,
                                  errout);
    plateau_mesh_free(&st.mesh);
    plateau_boundary_free(st.xyz, NULL);
    free(st.tension);
    free(st.slide);
    free(st.slide_dir);
    free(st.supports);
    free(st.support_counts);
    free(st.lines);
    free(st.mesh_file);
    free(st.svg_file);
    free(st.pattern_svg_file);
    free(st.pattern_dxf_file);
    plateau_pattern_free(&st.pattern);
    return status;
}

#endif /* PLATEAU_CLI_RUN_H */
