/* plateau_cli.h - the command-line tool's argument parsing and output
 * formatting, kept apart from main() so tests/test_cli.c can test them.
 * Include after plateau.h (and <stdio.h>).  Not part of the library. */
#ifndef PLATEAU_CLI_H
#define PLATEAU_CLI_H

#include <errno.h>
#include <float.h> /* DBL_MAX: the range of a finite number */
#include <math.h> /* log10: the JSON's area_log10 */
#include <stddef.h> /* offsetof: where an option's value goes */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_CLI_FN static __attribute__((unused))
#else
#define PLATEAU_CLI_FN static
#endif

#define PLATEAU_CLI_MAX_POINTS 1000000ul /* -n at most; -n's refusal spells it out */
/* Boundary files on one command line, and loops in all of them. */
#define PLATEAU_CLI_MAX_INPUTS 16
#define PLATEAU_CLI_MAX_LOOPS 64

typedef struct plateau_cli_args {
    size_t n;            /* 0: the library's default, n = m */
    plateau_method method;
    uint64_t seed;       /* 0: the library's default */
    int have_seed;       /* --seed given (a warning when it has no effect) */
    int progress;        /* --progress 1, --no-progress -1, else 0: progress
                            when stderr is a terminal and the run takes
                            more than a second */
    int max_rounds;      /* 0: the library's default */
    int circle;          /* --circle: force the circle domain */
    plateau_seeding seeding; /* --seeding auto|quality|paper (0: auto) */
    double edge_length;  /* --edge-length L: the quality seeding's interior
                            edge length (options.quality_edge_length); 0:
                            aim at n points */
    plateau_switch refine_boundary; /* --refine-boundary ON, --keep-boundary OFF, else AUTO */
    plateau_switch coarse_to_fine; /* --coarse-to-fine on|off|auto (AUTO) */
    plateau_linear_solver linear_solver; /* --linear-solver auto|dense|sparse */
    double area_tolerance; /* --area-tolerance T: 0 = the library's default */
    double max_seconds;  /* --max-seconds S: 0 = no limit */
    double accuracy;     /* --accuracy TOL: 0 = the library's default */
    plateau_switch stability; /* --no-stability OFF, else AUTO */
    plateau_switch alternatives; /* --no-alternatives OFF, else AUTO */
    int least_area;      /* --least-area: return the discs of two loops when smaller */
    int critical_index;  /* --critical-index K: 0 .. 7 */
    size_t max_input_bytes; /* --max-input-bytes: 0 = PLATEAU_DEFAULT_MAX_INPUT_BYTES */
    int have_max_memory; /* --max-memory MB given */
    unsigned long long max_memory_mb; /* its value; 0: no limit */
    double pressure;     /* --pressure P: 0 none */
    int fix_volume;      /* --volume V given */
    double volume;
    int json;
    int stl_ascii;       /* --stl-ascii: the .stl mesh file in ASCII */
    int help;
    int version;
    int have_view;
    double view[3];      /* --view X,Y,Z for the SVG */
    const char *mesh_path;
    const char *svg_path;
    const char *minimize_path; /* --minimize FILE: a mesh to minimise, in
                            place of boundary files */
    double pattern_width; /* --pattern W: the roll width (0: no pattern) */
    const char *pattern_svg, *pattern_dxf; /* --pattern-svg, --pattern-dxf */
    const char *pattern_mesh; /* --mesh FILE: pattern this mesh, nothing solved */
    const char *supports_path; /* --supports FILE: interior supports */
    int pattern_seams;   /* --pattern-seams parallel|axis */
    int have_pattern_direction, have_pattern_point;
    double pattern_direction[3], pattern_point[3]; /* --pattern-direction, --pattern-point */
    double pattern_shrink_along, pattern_shrink_across; /* --pattern-shrink-along/-across, percent */
    size_t pattern_panels; /* --pattern-panels N (0: the fewest that fit) */
    double pattern_marks; /* --pattern-marks L: seam marks every L (0: the ends) */
    const char *input;   /* the first boundary file */
    const char *inputs[PLATEAU_CLI_MAX_INPUTS]; /* all of them, in order */
    int num_inputs;
} plateau_cli_args;

PLATEAU_CLI_FN void plateau_cli_usage(FILE *out)
{
    fprintf(out,
            "usage: plateau [options] boundary.txt [more-loops.txt ...]\n"
            "       plateau [options] --minimize mesh.obj|mesh.off\n"
            "       plateau --pattern W [pattern options] --mesh mesh.obj|mesh.off\n"
            "\n"
            "Builds a minimal triangle mesh spanning the closed polygon in boundary.txt\n"
            "(one vertex \"x y z\" per line, '#' comments; the last vertex joins the\n"
            "first; a last vertex equal to the first is dropped, with a note).  CSV\n"
            "reads too: \"x,y,z\" or \"x;y;z\" lines (a '.' decimal point), after at\n"
            "most one header line of three column names such as \"x,y,z\".  A\n"
            "boundary file named - is read from standard input.  Errors about the\n"
            "polygon name its vertices (from 0) and their file lines.\n"
            "Several loops (the film between two rings, a frame with holes): separate\n"
            "them by a blank line in one file (blank lines before the first vertex,\n"
            "after the last and '#' lines separate nothing), or give one file per loop\n"
            "or group of loops; the loops keep their order (see plateau_solve_loops).\n"
            "Two loops that are too far apart for a connected minimal film (coaxial\n"
            "rings farther apart than 1.3255 times their radius) end \"pinched\".\n"
            "\n"
            "  --minimize FILE     instead of a boundary, a mesh (OBJ or OFF; polygons as\n"
            "                      fans): keep its boundary (the edges of one triangle)\n"
            "                      and minimise its area or the method's energy over\n"
            "                      its other vertices; no seeding options then\n"
            "  -n N                interior points (default: as many as the accuracy\n"
            "                      needs; with --accuracy the first count tried)\n"
            "  --accuracy TOL      solve again with more points until the estimated\n"
            "                      relative error of the area (a membrane's energy)\n"
            "                      is at most TOL (default 1e-4 for one loop of a\n"
            "                      soap film without -n, --edge-length or --seeding\n"
            "                      paper; not with --seeding paper)\n"
            "  --method M          paper (default), paper-literal or area\n"
            "  --seed S            seed of the candidate draw (0: the default seed)\n"
            "  --max-rounds R      bound on solve / re-triangulate rounds\n"
            "  --circle            map the boundary on a circle even if the plane works\n"
            "  --seeding S         auto (default: quality when N >= m / 4, else paper),\n"
            "                      quality (Delaunay refinement of the domain, about N\n"
            "                      interior points; no seed) or paper (the paper's fan\n"
            "                      candidates, drawn with the seed)\n"
            "  --edge-length L     quality seeding with interior edges about L long (in\n"
            "                      the boundary's units) instead of about N points;\n"
            "                      not with -n, --seeding paper or --coarse-to-fine on\n"
            "  --refine-boundary   quality seeding may add vertices on the polygon's edges\n"
            "  --keep-boundary     ... never (default: methods area and paper add them\n"
            "                      where the polygon's edges are over 2 interior\n"
            "                      spacings long)\n"
            "  --linear-solver L   auto (default: sparse above 25 interior points for\n"
            "                      paper, above 200 for area), dense (paper: dense\n"
            "                      LM; area: L-BFGS) or sparse\n"
            "                      (paper: sparse dog leg; area: sparse Newton)\n"
            "  --coarse-to-fine C  auto (default: methods area and paper from %d points\n"
            "                      when the polygon's edges may be split; never for a\n"
            "                      membrane), on or off: solve a coarse mesh, then\n"
            "                      subdivide it level by level with Newton steps along\n"
            "                      the vertex normals\n"
            "  --area-tolerance T  method area, sparse Newton: a solve ends when 5 steps\n"
            "                      lower the area by less than T of it (default 1e-6;\n"
            "                      above 0, at most 0.01)\n"
            "  --max-memory MB     refuse a solve whose estimated peak memory exceeds MB\n"
            "                      megabytes (default 2048; 0: no limit)\n"
            "  --max-seconds S     stop the solve once S seconds (wall clock) have passed,\n"
            "                      with the mesh it has reached (stop \"time limit\"; a\n"
            "                      solve cut short counts as a defect; 0: no limit)\n",
            PLATEAU_COARSE_TO_FINE_POINTS);
    /* two calls: C99 promises string literals of 4095 characters, no more */
    fprintf(out,
            "  --no-stability      skip the stability report (index, lowest eigenvalues\n"
            "                      of the area's Hessian on normal motions; a membrane\n"
            "                      has none, nor the discs or --critical-index)\n"
            "  --no-alternatives   two loops: do not also solve one disc per loop\n"
            "  --least-area        two loops: return the discs when their area is less\n"
            "  --critical-index K  then look for a critical point of the area of index K\n"
            "                      near the result (1: the unstable catenoid between\n"
            "                      two rings; 0: the default, the method's result)\n"
            "  -o FILE             write the mesh: .obj, .ply, .off or .stl (binary STL)\n"
            "  --stl-ascii         write the .stl mesh file as ASCII STL\n"
            "  --svg FILE          write a shaded picture of the mesh\n"
            "  --view X,Y,Z        the picture's viewing direction (default -1,-1,-1)\n"
            "  --json              print one JSON object instead of the summary; on a\n"
            "                      failure {\"error\": ..., \"code\": ..., \"exit\": ...}\n"
            "  --pressure P        a membrane: pressure P across the film (unit tension):\n"
            "                      least area - P V; method paper solves H_i = P\n"
            "  --volume V          hold the volume V (the pressure is reported)\n"
            "                      (a vertex line \"x y z cable T\" makes its edge to the\n"
            "                      next vertex a cable of tension T)\n"
            "                      (a vertex line \"x y z slide-plane nx ny nz\" or\n"
            "                      \"x y z slide-line dx dy dz\" lets the vertex move on\n"
            "                      that plane or line: an edge on the ground or a rod)\n"
            "  --supports FILE     interior supports: points (\"x y z\" lines) the film\n"
            "                      passes through, fixed vertices of the mesh; a blank\n"
            "                      line between polylines, whose consecutive points are\n"
            "                      joined by edges (one repeating its first point at\n"
            "                      its end is a closed ring)\n"
            "  --progress          show the solve's progress on stderr (stage, round,\n"
            "                      iteration, F or area, elapsed time); the default\n"
            "                      when stderr is a terminal and the run takes over\n"
            "                      a second\n"
            "  --no-progress       never show it\n"
            "  --max-input-bytes B refuse a boundary file of more than B bytes\n"
            "                      (default %lu; at most a sixth of --max-memory:\n"
            "                      reading takes about 6 bytes per byte)\n"
            "  --version, --help\n"
            "\n"
            "Cutting patterns (CUTTING PATTERNS in plateau.h), of the result or of --mesh:\n"
            "  --pattern W         cut the film into panels that fit a roll of width W,\n"
            "                      flatten them and report each panel and seam\n"
            "  --mesh FILE         pattern this mesh (OBJ or OFF) instead of solving\n"
            "  --pattern-seams S   parallel (default: planes normal to the direction) or\n"
            "                      axis (planes through the axis)\n"
            "  --pattern-direction X,Y,Z  the planes' normal, or the axis's direction\n"
            "                      (default: the film's longest coordinate axis, or its\n"
            "                      vector area)\n"
            "  --pattern-point X,Y,Z  a point of the axis (default: the area centroid)\n"
            "  --pattern-panels N  exactly N panels between the planes (default: the\n"
            "                      fewest that fit W)\n"
            "  --pattern-shrink-along P, --pattern-shrink-across P\n"
            "                      compensation: shrink the panels by P percent along\n"
            "                      and across (0 <= P < 50)\n"
            "  --pattern-marks L   seam marks every L of seam (default: its ends)\n"
            "  --pattern-svg FILE  write the panels as SVG\n"
            "  --pattern-dxf FILE  write them as DXF R12 (cutting plotters)\n"
            "\n"
            "Exit status:\n"
            "  0  success: a valid mesh\n"
            "  1  bad input, or a failed solve or write\n"
            "  2  bad usage\n"
            "  3  a mesh was produced (and written) but it has defects: inverted,\n"
            "     folded, degenerate or intersecting triangles, or the solver did not\n"
            "     reach its stopping rule, or the film between two loops pinched\n"
            "     (a warning on stderr names them)\n",
            (unsigned long)PLATEAU_DEFAULT_MAX_INPUT_BYTES);
}

/* digits only, no sign, no overflow, at most max */
static int plateau_cli_unsigned(const char *s, unsigned long long max, unsigned long long *out)
{
    unsigned long long v = 0;
    if (!s || !*s) return 0;
    for (; *s; s++) {
        unsigned d;
        if (*s < '0' || *s > '9') return 0;
        d = (unsigned)(*s - '0');
        if (d > max || v > (max - d) / 10) return 0;
        v = 10 * v + d;
    }
    *out = v;
    return 1;
}

static int plateau_cli_xyz(const char *s, double v[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        char *end = NULL;
        v[k] = strtod(s, &end);
        if (end == s || !(v[k] == v[k]) || v[k] - v[k] != 0.0) return 0;
        s = end;
        if (k < 2) {
            if (*s != ',') return 0;
            s++;
        }
    }
    return *s == '\0';
}

static int plateau_cli_view(const char *s, double v[3])
{
    return plateau_cli_xyz(s, v) && (v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0);
}

static int plateau_cli_has_ext(const char *path, const char *ext)
{
    size_t lp = strlen(path), le = strlen(ext), i;
    if (lp <= le) return 0;
    for (i = 0; i < le; i++) {
        char c = path[lp - le + i];
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != ext[i]) return 0;
    }
    return 1;
}

/* The size of plateau_cli_number's text: "-2.2250738585072014e-308" and more */
#define PLATEAU_CLI_NUMBER_SIZE 32

/* v as the shortest of %.15g, %.16g and %.17g that strtod reads back as v,
 * into buf: every number the tool echoes from what was typed prints as it
 * was typed (0.2, not 0.20000000000000001; 1.6, not 1.6000000000000001),
 * and every other exactly.  Returns buf. */
static const char *plateau_cli_number(double v, char buf[PLATEAU_CLI_NUMBER_SIZE])
{
    int digits;
    for (digits = 15; digits < 17; digits++) {
        snprintf(buf, PLATEAU_CLI_NUMBER_SIZE, "%.*g", digits, v);
        if (strtod(buf, NULL) == v) return buf;
    }
    snprintf(buf, PLATEAU_CLI_NUMBER_SIZE, "%.17g", v);
    return buf;
}

/* The library's messages name its options' fields; the tool's name the
 * flags a user types.  Each library phrase and the tool's words for it,
 * tried in this order at each place of a message (a longer phrase before
 * the field name it holds). */
static const char *const plateau_cli_flag_words[][2] = {
    {"(options.max_memory)", "(--max-memory raises it; 0: no limit)"},
    {"options.max_memory", "--max-memory"},
    {"options.max_seconds", "--max-seconds"},
    {"stability ON, alternatives ON, critical_index and least_area_topology are",
     "--critical-index and --least-area are"},
    {"(pressure, fix_volume or cable_tension)", "(--pressure, --volume or cables in the boundary file)"},
    {"stability ON and critical_index need", "--critical-index needs"},
    {"linear_solver SPARSE or area_warm_start ON needs", "--linear-solver sparse needs"},
    {"coarse_to_fine ON", "--coarse-to-fine on"},
    {"refine_boundary not OFF", "no --keep-boundary"},
    {"seeding not PAPER", "no --seeding paper"},
    {"quality_edge_length 0", "no --edge-length"},
    {"quality_edge_length", "--edge-length"},
    {"interior_points", "-n"},
    {"max_rounds", "--max-rounds"},
    {"max_seconds", "--max-seconds"},
    {"accuracy", "--accuracy"},
    {"max_memory", "--max-memory"},
    {"area_tolerance", "--area-tolerance"},
    {"critical_index", "--critical-index"},
    {"least_area_topology", "--least-area"},
    {"linear_solver", "--linear-solver"},
    {"fix_volume", "--volume"},
    {"coarse_to_fine", "--coarse-to-fine"},
    {"options.direction", "--pattern-direction"},
    {"the number of panels asked", "--pattern-panels"}};

/* A message of the library (msg, of at most size bytes with its NUL) with
 * its option fields put as the tool's flags (plateau_cli_flag_words), in
 * place; cut to size. */
static void plateau_cli_flag_names(char *msg, size_t size)
{
    const size_t words = sizeof plateau_cli_flag_words / sizeof plateau_cli_flag_words[0];
    char out[640];
    size_t i = 0, o = 0, w, len;
    while (msg[i] && o + 1 < sizeof out) {
        for (w = 0; w < words; w++)
            if (strncmp(msg + i, plateau_cli_flag_words[w][0], strlen(plateau_cli_flag_words[w][0])) == 0) break;
        if (w == words) {
            out[o++] = msg[i++];
            continue;
        }
        len = strlen(plateau_cli_flag_words[w][1]);
        if (len > sizeof out - 1 - o) len = sizeof out - 1 - o;
        memcpy(out + o, plateau_cli_flag_words[w][1], len);
        o += len;
        i += strlen(plateau_cli_flag_words[w][0]);
    }
    for (i = 0; i < o && i + 1 < size; i++) msg[i] = out[i];
    if (size > 0) msg[i] = '\0';
}

/* The type of the field of plateau_cli_args an option's value goes to. */
typedef enum plateau_cli_field {
    PLATEAU_CLI_INT,     /* int */
    PLATEAU_CLI_SIZE,    /* size_t */
    PLATEAU_CLI_U64,     /* uint64_t */
    PLATEAU_CLI_ULL,     /* unsigned long long */
    PLATEAU_CLI_DOUBLE,  /* double */
    PLATEAU_CLI_STRING,  /* const char * */
    PLATEAU_CLI_XYZ,     /* double[3] */
    PLATEAU_CLI_METHOD,  /* plateau_method */
    PLATEAU_CLI_SEEDING, /* plateau_seeding */
    PLATEAU_CLI_SOLVER,  /* plateau_linear_solver */
    PLATEAU_CLI_SWITCH   /* plateau_switch */
} plateau_cli_field;

/* What an option takes after its name. */
typedef enum plateau_cli_kind {
    PLATEAU_CLI_FLAG,    /* nothing: the option stores .set */
    PLATEAU_CLI_WORD,    /* one of .words, which stores its value */
    PLATEAU_CLI_WHOLE,   /* digits only (no sign), from .min to .max */
    PLATEAU_CLI_NUMBER,  /* a number strtod reads whole, in .lo .. .hi (.open) */
    PLATEAU_CLI_MESH,    /* a file name ending in .obj, .ply, .off or .stl */
    PLATEAU_CLI_NAME,    /* a file name, not empty */
    PLATEAU_CLI_VIEW,    /* X,Y,Z: three finite numbers, not all zero */
    PLATEAU_CLI_POINT    /* X,Y,Z: three finite numbers */
} plateau_cli_kind;

/* .open of a PLATEAU_CLI_NUMBER: the ends of its range that are excluded */
#define PLATEAU_CLI_ABOVE_LO 1
#define PLATEAU_CLI_BELOW_HI 2

typedef struct plateau_cli_word {
    const char *word;
    int value;
} plateau_cli_word;

/* One option: its names, what it takes, where it goes, and the sentence
 * that refuses a bad value (a printf format of the value as typed). */
typedef struct plateau_cli_option {
    const char *name, *alias; /* alias: another name, or NULL */
    plateau_cli_kind kind;
    plateau_cli_field field;
    size_t offset;            /* offsetof(plateau_cli_args, the field) */
    size_t given;             /* offsetof an int field set to 1 when the
                                 option is given; 0: none (offset 0 is n,
                                 never such a field) */
    int set;                  /* FLAG: the value stored */
    const plateau_cli_word *words; /* WORD */
    unsigned long long min, max;   /* WHOLE */
    double lo, hi;            /* NUMBER */
    int open;                 /* NUMBER: PLATEAU_CLI_ABOVE_LO | PLATEAU_CLI_BELOW_HI */
    const char *bad;
} plateau_cli_option;

static const plateau_cli_word plateau_cli_methods[] = {
    {"paper", PLATEAU_METHOD_PAPER}, {"paper-literal", PLATEAU_METHOD_PAPER_LITERAL},
    {"area", PLATEAU_METHOD_AREA}, {NULL, 0}};
static const plateau_cli_word plateau_cli_seedings[] = {
    {"paper", PLATEAU_SEEDING_PAPER}, {"quality", PLATEAU_SEEDING_QUALITY},
    {"auto", PLATEAU_SEEDING_AUTO}, {NULL, 0}};
static const plateau_cli_word plateau_cli_solvers[] = {
    {"auto", PLATEAU_LINEAR_AUTO}, {"dense", PLATEAU_LINEAR_DENSE},
    {"sparse", PLATEAU_LINEAR_SPARSE}, {NULL, 0}};
static const plateau_cli_word plateau_cli_seam_families[] = {
    {"parallel", PLATEAU_SEAMS_PARALLEL}, {"axis", PLATEAU_SEAMS_AXIS}, {NULL, 0}};
static const plateau_cli_word plateau_cli_switches[] = {
    {"on", PLATEAU_ON}, {"off", PLATEAU_OFF}, {"auto", PLATEAU_AUTO}, {NULL, 0}};

#define PLATEAU_CLI_AT(field) offsetof(plateau_cli_args, field)

/* Every option of the tool (plateau --help says what each does). */
#define PLATEAU_CLI_FLAG_(n, f, v) .name = n, .kind = PLATEAU_CLI_FLAG, .field = f, .set = v
static const plateau_cli_option plateau_cli_options[] = {
    {PLATEAU_CLI_FLAG_("-h", PLATEAU_CLI_INT, 1), .alias = "--help", .offset = PLATEAU_CLI_AT(help)},
    {PLATEAU_CLI_FLAG_("--version", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(version)},
    {PLATEAU_CLI_FLAG_("--json", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(json)},
    {PLATEAU_CLI_FLAG_("--stl-ascii", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(stl_ascii)},
    {PLATEAU_CLI_FLAG_("--progress", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(progress)},
    {PLATEAU_CLI_FLAG_("--no-progress", PLATEAU_CLI_INT, -1), .offset = PLATEAU_CLI_AT(progress)},
    {PLATEAU_CLI_FLAG_("--circle", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(circle)},
    {PLATEAU_CLI_FLAG_("--no-stability", PLATEAU_CLI_SWITCH, PLATEAU_OFF), .offset = PLATEAU_CLI_AT(stability)},
    {PLATEAU_CLI_FLAG_("--no-alternatives", PLATEAU_CLI_SWITCH, PLATEAU_OFF),
     .offset = PLATEAU_CLI_AT(alternatives)},
    {PLATEAU_CLI_FLAG_("--least-area", PLATEAU_CLI_INT, 1), .offset = PLATEAU_CLI_AT(least_area)},
    {PLATEAU_CLI_FLAG_("--refine-boundary", PLATEAU_CLI_SWITCH, PLATEAU_ON),
     .offset = PLATEAU_CLI_AT(refine_boundary)},
    {PLATEAU_CLI_FLAG_("--keep-boundary", PLATEAU_CLI_SWITCH, PLATEAU_OFF),
     .offset = PLATEAU_CLI_AT(refine_boundary)},
    {.name = "--method", .kind = PLATEAU_CLI_WORD, .field = PLATEAU_CLI_METHOD, .offset = PLATEAU_CLI_AT(method),
     .words = plateau_cli_methods, .bad = "unknown method '%.40s' (use paper, paper-literal or area)"},
    {.name = "--seeding", .kind = PLATEAU_CLI_WORD, .field = PLATEAU_CLI_SEEDING,
     .offset = PLATEAU_CLI_AT(seeding), .words = plateau_cli_seedings,
     .bad = "unknown seeding '%.40s' (use auto, paper or quality)"},
    {.name = "--linear-solver", .kind = PLATEAU_CLI_WORD, .field = PLATEAU_CLI_SOLVER,
     .offset = PLATEAU_CLI_AT(linear_solver), .words = plateau_cli_solvers,
     .bad = "unknown linear solver '%.40s' (use auto, dense or sparse)"},
    {.name = "--coarse-to-fine", .kind = PLATEAU_CLI_WORD, .field = PLATEAU_CLI_SWITCH,
     .offset = PLATEAU_CLI_AT(coarse_to_fine), .words = plateau_cli_switches,
     .bad = "unknown --coarse-to-fine '%.40s' (use on, off or auto)"},
    {.name = "-n", .alias = "--points", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_SIZE,
     .offset = PLATEAU_CLI_AT(n), .min = 1, .max = PLATEAU_CLI_MAX_POINTS,
     .bad = "-n wants a whole number from 1 to 1000000, not '%.40s'"},
    {.name = "--max-input-bytes", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_SIZE,
     .offset = PLATEAU_CLI_AT(max_input_bytes), .min = 1, .max = (size_t)-1 - 1,
     .bad = "--max-input-bytes wants a whole number of bytes, at least 1, not '%.40s'"},
    {.name = "--seed", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_U64, .offset = PLATEAU_CLI_AT(seed),
     .given = PLATEAU_CLI_AT(have_seed), .max = 18446744073709551615ull,
     .bad = "--seed wants a whole number from 0 to 2^64-1, not '%.40s'"},
    {.name = "--max-memory", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_ULL,
     .offset = PLATEAU_CLI_AT(max_memory_mb), .given = PLATEAU_CLI_AT(have_max_memory),
     .max = (size_t)-1 >> 20, .bad = "--max-memory wants a whole number of megabytes, not '%.40s'"},
    {.name = "--max-rounds", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_INT,
     .offset = PLATEAU_CLI_AT(max_rounds), .min = 1, .max = 100000,
     .bad = "--max-rounds wants a whole number from 1 to 100000, not '%.40s'"},
    {.name = "--critical-index", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_INT,
     .offset = PLATEAU_CLI_AT(critical_index), .max = 7,
     .bad = "--critical-index wants a whole number from 0 to 7, not '%.40s'"},
    {.name = "--pressure", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(pressure), .lo = -DBL_MAX, .hi = DBL_MAX,
     .bad = "--pressure wants a finite number, not '%.40s'"},
    {.name = "--volume", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE, .offset = PLATEAU_CLI_AT(volume),
     .given = PLATEAU_CLI_AT(fix_volume), .lo = -DBL_MAX, .hi = DBL_MAX,
     .bad = "--volume wants a finite number, not '%.40s'"},
    {.name = "--area-tolerance", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(area_tolerance), .lo = 0.0, .hi = 1e-2, .open = PLATEAU_CLI_ABOVE_LO,
     .bad = "--area-tolerance wants a number above 0, at most 0.01, not '%.40s'"},
    {.name = "--edge-length", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(edge_length), .lo = 0.0, .hi = DBL_MAX, .open = PLATEAU_CLI_ABOVE_LO,
     .bad = "--edge-length wants a length above 0 (in the boundary's units), not '%.40s'"},
    {.name = "--accuracy", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(accuracy), .lo = 0.0, .hi = 0.1, .open = PLATEAU_CLI_ABOVE_LO,
     .bad = "--accuracy wants a relative error above 0, at most 0.1, not '%.40s'"},
    {.name = "--max-seconds", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(max_seconds), .lo = 0.0, .hi = 1e15, .open = PLATEAU_CLI_BELOW_HI,
     .bad = "--max-seconds wants a number of seconds, 0 or more, not '%.40s'"},
    {.name = "-o", .alias = "--output", .kind = PLATEAU_CLI_MESH, .field = PLATEAU_CLI_STRING,
     .offset = PLATEAU_CLI_AT(mesh_path), .bad = "the mesh file '%.60s' must end in .obj, .ply, .off or .stl"},
    {.name = "--svg", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING, .offset = PLATEAU_CLI_AT(svg_path),
     .bad = "--svg needs a file name"},
    {.name = "--minimize", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING,
     .offset = PLATEAU_CLI_AT(minimize_path), .bad = "--minimize needs the name of a mesh file"},
    {.name = "--pattern", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(pattern_width), .lo = 0.0, .hi = DBL_MAX, .open = PLATEAU_CLI_ABOVE_LO,
     .bad = "--pattern wants the roll width, a finite number above 0, not '%.40s'"},
    {.name = "--pattern-svg", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING,
     .offset = PLATEAU_CLI_AT(pattern_svg), .bad = "--pattern-svg needs a file name"},
    {.name = "--pattern-dxf", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING,
     .offset = PLATEAU_CLI_AT(pattern_dxf), .bad = "--pattern-dxf needs a file name"},
    {.name = "--supports", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING,
     .offset = PLATEAU_CLI_AT(supports_path), .bad = "--supports needs a file name"},
    {.name = "--mesh", .kind = PLATEAU_CLI_NAME, .field = PLATEAU_CLI_STRING, .offset = PLATEAU_CLI_AT(pattern_mesh),
     .bad = "--mesh needs the name of a mesh file"},
    {.name = "--pattern-seams", .kind = PLATEAU_CLI_WORD, .field = PLATEAU_CLI_INT,
     .offset = PLATEAU_CLI_AT(pattern_seams), .words = plateau_cli_seam_families,
     .bad = "unknown --pattern-seams '%.40s' (use parallel or axis)"},
    {.name = "--pattern-direction", .kind = PLATEAU_CLI_VIEW, .field = PLATEAU_CLI_XYZ,
     .offset = PLATEAU_CLI_AT(pattern_direction), .given = PLATEAU_CLI_AT(have_pattern_direction),
     .bad = "--pattern-direction wants three numbers X,Y,Z, not all zero, not '%.40s'"},
    {.name = "--pattern-point", .kind = PLATEAU_CLI_POINT, .field = PLATEAU_CLI_XYZ,
     .offset = PLATEAU_CLI_AT(pattern_point), .given = PLATEAU_CLI_AT(have_pattern_point),
     .bad = "--pattern-point wants three numbers X,Y,Z, not '%.40s'"},
    {.name = "--pattern-panels", .kind = PLATEAU_CLI_WHOLE, .field = PLATEAU_CLI_SIZE,
     .offset = PLATEAU_CLI_AT(pattern_panels), .min = 1, .max = 100000,
     .bad = "--pattern-panels wants a whole number from 1 to 100000, not '%.40s'"},
    {.name = "--pattern-shrink-along", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(pattern_shrink_along), .lo = 0.0, .hi = 50.0, .open = PLATEAU_CLI_BELOW_HI,
     .bad = "--pattern-shrink-along wants a percentage from 0 to below 50, not '%.40s'"},
    {.name = "--pattern-shrink-across", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(pattern_shrink_across), .lo = 0.0, .hi = 50.0, .open = PLATEAU_CLI_BELOW_HI,
     .bad = "--pattern-shrink-across wants a percentage from 0 to below 50, not '%.40s'"},
    {.name = "--pattern-marks", .kind = PLATEAU_CLI_NUMBER, .field = PLATEAU_CLI_DOUBLE,
     .offset = PLATEAU_CLI_AT(pattern_marks), .lo = 0.0, .hi = DBL_MAX, .open = PLATEAU_CLI_ABOVE_LO,
     .bad = "--pattern-marks wants a length above 0, not '%.40s'"},
    {.name = "--view", .kind = PLATEAU_CLI_VIEW, .field = PLATEAU_CLI_XYZ, .offset = PLATEAU_CLI_AT(view),
     .given = PLATEAU_CLI_AT(have_view), .bad = "--view wants three numbers X,Y,Z, not all zero, not '%.40s'"}};
#undef PLATEAU_CLI_FLAG_

/* The option named name (its name or its alias), or NULL. */
static const plateau_cli_option *plateau_cli_find_option(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof plateau_cli_options / sizeof plateau_cli_options[0]; i++) {
        const plateau_cli_option *o = &plateau_cli_options[i];
        if (strcmp(name, o->name) == 0 || (o->alias && strcmp(name, o->alias) == 0)) return o;
    }
    return NULL;
}

/* Checks value (NULL for a FLAG) against o and stores it into args.
 * Returns 0 when the value is refused (args then as it was). */
static int plateau_cli_store(const plateau_cli_option *o, const char *value, plateau_cli_args *args)
{
    char *at = (char *)args + o->offset, *end = NULL;
    unsigned long long whole = 0;
    double x = 0.0;
    int v = o->set;
    const plateau_cli_word *w;
    switch (o->kind) {
    case PLATEAU_CLI_FLAG:
        break;
    case PLATEAU_CLI_WORD:
        for (w = o->words; w->word && strcmp(w->word, value) != 0; w++) continue;
        if (!w->word) return 0;
        v = w->value;
        break;
    case PLATEAU_CLI_WHOLE:
        if (!plateau_cli_unsigned(value, o->max, &whole) || whole < o->min) return 0;
        break;
    case PLATEAU_CLI_NUMBER:
        x = strtod(value, &end);
        if (end == value || *end != '\0' || !(o->open & PLATEAU_CLI_ABOVE_LO ? x > o->lo : x >= o->lo) ||
            !(o->open & PLATEAU_CLI_BELOW_HI ? x < o->hi : x <= o->hi))
            return 0;
        break;
    case PLATEAU_CLI_MESH:
        if (!plateau_cli_has_ext(value, ".obj") && !plateau_cli_has_ext(value, ".ply") &&
            !plateau_cli_has_ext(value, ".off") && !plateau_cli_has_ext(value, ".stl"))
            return 0;
        break;
    case PLATEAU_CLI_NAME:
        if (!*value) return 0;
        break;
    case PLATEAU_CLI_VIEW:
    case PLATEAU_CLI_POINT: {
        double xyz[3];
        if (!(o->kind == PLATEAU_CLI_VIEW ? plateau_cli_view(value, xyz) : plateau_cli_xyz(value, xyz))) return 0;
        memcpy(at, xyz, sizeof xyz);
        break;
    }
    }
    switch (o->field) {
    case PLATEAU_CLI_INT: *(int *)(void *)at = o->kind == PLATEAU_CLI_WHOLE ? (int)whole : v; break;
    case PLATEAU_CLI_SIZE: *(size_t *)(void *)at = (size_t)whole; break;
    case PLATEAU_CLI_U64: *(uint64_t *)(void *)at = (uint64_t)whole; break;
    case PLATEAU_CLI_ULL: *(unsigned long long *)(void *)at = whole; break;
    case PLATEAU_CLI_DOUBLE: *(double *)(void *)at = x; break;
    case PLATEAU_CLI_STRING: *(const char **)(void *)at = value; break;
    case PLATEAU_CLI_XYZ: break; /* stored above */
    case PLATEAU_CLI_METHOD: *(plateau_method *)(void *)at = (plateau_method)v; break;
    case PLATEAU_CLI_SEEDING: *(plateau_seeding *)(void *)at = (plateau_seeding)v; break;
    case PLATEAU_CLI_SOLVER: *(plateau_linear_solver *)(void *)at = (plateau_linear_solver)v; break;
    case PLATEAU_CLI_SWITCH: *(plateau_switch *)(void *)at = (plateau_switch)v; break;
    }
    if (o->given) *(int *)(void *)((char *)args + o->given) = 1;
    return 1;
}

/* Settings that some others cannot go with (plateau_cli_conflicts). */
#define PLATEAU_CLI_MEMBRANE 1u /* --pressure P (not 0) or --volume V */
#define PLATEAU_CLI_SADDLE 2u   /* --critical-index K above 0 */
#define PLATEAU_CLI_DISCS 4u    /* --least-area */
#define PLATEAU_CLI_C2F 8u      /* --coarse-to-fine on */
#define PLATEAU_CLI_LITERAL 16u /* --method paper-literal */
#define PLATEAU_CLI_FAN 32u     /* --seeding paper */
#define PLATEAU_CLI_KEEP 64u    /* --keep-boundary */
#define PLATEAU_CLI_EDGE 128u   /* --edge-length L */
#define PLATEAU_CLI_POINTS 256u /* -n N */
#define PLATEAU_CLI_MESH_IN 512u /* --minimize FILE */
#define PLATEAU_CLI_SEED 1024u   /* --seed S */
#define PLATEAU_CLI_CIRCLE 2048u /* --circle */
#define PLATEAU_CLI_REFINE 4096u /* --refine-boundary */
#define PLATEAU_CLI_QUALITY 8192u /* --seeding quality */
#define PLATEAU_CLI_PATTERN_MESH 16384u /* --mesh FILE: a mesh patterned, nothing solved */

/* The pairs of settings that cannot go together, and why: the library
 * refuses the first eight; in the others one setting would be ignored
 * (--minimize: the mesh given is the start, nothing is seeded). */
static const struct plateau_cli_conflict {
    unsigned a, b;
    const char *why;
} plateau_cli_conflicts[] = {
    {PLATEAU_CLI_MEMBRANE, PLATEAU_CLI_SADDLE,
     "the saddle search is of the area alone, and a membrane's energy is not its area"},
    {PLATEAU_CLI_MEMBRANE, PLATEAU_CLI_DISCS,
     "the discs of two loops are compared by area alone, and a membrane's energy is not its area"},
    {PLATEAU_CLI_MEMBRANE, PLATEAU_CLI_C2F, "coarse to fine's Newton steps are the area's, not the membrane energy's"},
    {PLATEAU_CLI_LITERAL, PLATEAU_CLI_MEMBRANE, "method paper-literal takes no pressure or volume (methods paper "
                                                "and area do)"},
    {PLATEAU_CLI_C2F, PLATEAU_CLI_LITERAL, "coarse to fine takes methods paper and area"},
    {PLATEAU_CLI_C2F, PLATEAU_CLI_FAN, "coarse to fine starts from the quality seeding"},
    {PLATEAU_CLI_C2F, PLATEAU_CLI_KEEP, "coarse to fine splits the polygon's edges at every level"},
    {PLATEAU_CLI_C2F, PLATEAU_CLI_EDGE, "coarse to fine sets the spacing of its levels itself"},
    {PLATEAU_CLI_POINTS, PLATEAU_CLI_EDGE, "each sets how many interior points the seeding makes"},
    {PLATEAU_CLI_EDGE, PLATEAU_CLI_FAN, "the edge length is the quality seeding's; the paper's fan draws -n "
                                        "points"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_POINTS, "the mesh's vertices are the points: nothing is seeded"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_EDGE, "the mesh's vertices are the points: nothing is seeded"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_FAN, "the mesh's vertices are the points: nothing is seeded"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_QUALITY, "the mesh's vertices are the points: nothing is seeded"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_SEED, "the mesh's vertices are the points: nothing is seeded"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_CIRCLE, "the mesh is the start: no parameter domain is made"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_REFINE, "the mesh's boundary is kept as it is"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_KEEP, "the mesh's boundary is kept as it is"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_C2F, "coarse to fine builds its own meshes"},
    {PLATEAU_CLI_MESH_IN, PLATEAU_CLI_DISCS, "the discs of two loops are solved from boundary files"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_MESH_IN, "--mesh patterns a mesh as it is, --minimize solves one"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_MEMBRANE, "--mesh patterns the mesh as it is: nothing is solved"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_SADDLE, "--mesh patterns the mesh as it is: nothing is solved"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_DISCS, "--mesh patterns the mesh as it is: nothing is solved"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_C2F, "--mesh patterns the mesh as it is: nothing is solved"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_LITERAL, "--mesh patterns the mesh as it is: nothing is solved"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_POINTS, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_EDGE, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_FAN, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_QUALITY, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_SEED, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_CIRCLE, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_REFINE, "--mesh patterns the mesh as it is: nothing is seeded"},
    {PLATEAU_CLI_PATTERN_MESH, PLATEAU_CLI_KEEP, "--mesh patterns the mesh as it is: nothing is seeded"}};

/* The settings of args among PLATEAU_CLI_MEMBRANE ... */
static unsigned plateau_cli_settings(const plateau_cli_args *a)
{
    return (a->pressure != 0.0 || a->fix_volume ? PLATEAU_CLI_MEMBRANE : 0u) |
           (a->critical_index > 0 ? PLATEAU_CLI_SADDLE : 0u) | (a->least_area ? PLATEAU_CLI_DISCS : 0u) |
           (a->coarse_to_fine == PLATEAU_ON ? PLATEAU_CLI_C2F : 0u) |
           (a->method == PLATEAU_METHOD_PAPER_LITERAL ? PLATEAU_CLI_LITERAL : 0u) |
           (a->seeding == PLATEAU_SEEDING_PAPER ? PLATEAU_CLI_FAN : 0u) |
           (a->refine_boundary == PLATEAU_OFF ? PLATEAU_CLI_KEEP : 0u) |
           (a->edge_length > 0.0 ? PLATEAU_CLI_EDGE : 0u) | (a->n ? PLATEAU_CLI_POINTS : 0u) |
           (a->minimize_path ? PLATEAU_CLI_MESH_IN : 0u) | (a->have_seed ? PLATEAU_CLI_SEED : 0u) |
           (a->circle ? PLATEAU_CLI_CIRCLE : 0u) | (a->refine_boundary == PLATEAU_ON ? PLATEAU_CLI_REFINE : 0u) |
           (a->seeding == PLATEAU_SEEDING_QUALITY ? PLATEAU_CLI_QUALITY : 0u) |
           (a->pattern_mesh ? PLATEAU_CLI_PATTERN_MESH : 0u);
}

/* Setting one of args as typed ("--pressure 0.2") into buf. */
static const char *plateau_cli_setting(const plateau_cli_args *a, unsigned setting, char *buf, size_t size)
{
    char num[PLATEAU_CLI_NUMBER_SIZE];
    if (setting == PLATEAU_CLI_MEMBRANE)
        snprintf(buf, size, "%s %s", a->fix_volume ? "--volume" : "--pressure",
                 plateau_cli_number(a->fix_volume ? a->volume : a->pressure, num));
    else if (setting == PLATEAU_CLI_SADDLE)
        snprintf(buf, size, "--critical-index %d", a->critical_index);
    else if (setting == PLATEAU_CLI_EDGE)
        snprintf(buf, size, "--edge-length %s", plateau_cli_number(a->edge_length, num));
    else if (setting == PLATEAU_CLI_POINTS)
        snprintf(buf, size, "-n %lu", (unsigned long)a->n);
    else if (setting == PLATEAU_CLI_MESH_IN)
        snprintf(buf, size, "--minimize %.60s", a->minimize_path);
    else if (setting == PLATEAU_CLI_PATTERN_MESH)
        snprintf(buf, size, "--mesh %.60s", a->pattern_mesh);
    else if (setting == PLATEAU_CLI_SEED)
        snprintf(buf, size, "--seed %llu", (unsigned long long)a->seed);
    else
        snprintf(buf, size, "%s", setting == PLATEAU_CLI_DISCS ? "--least-area"
                                  : setting == PLATEAU_CLI_C2F ? "--coarse-to-fine on"
                                  : setting == PLATEAU_CLI_LITERAL ? "--method paper-literal"
                                  : setting == PLATEAU_CLI_FAN ? "--seeding paper"
                                  : setting == PLATEAU_CLI_CIRCLE ? "--circle"
                                  : setting == PLATEAU_CLI_REFINE ? "--refine-boundary"
                                  : setting == PLATEAU_CLI_QUALITY ? "--seeding quality" : "--keep-boundary");
    return buf;
}

/* 1 with a sentence in msg when args holds two settings that cannot go
 * together (plateau_cli_conflicts), else 0. */
static int plateau_cli_conflict(const plateau_cli_args *args, char *msg, size_t msg_size)
{
    unsigned have = plateau_cli_settings(args);
    size_t i;
    char a[80], b[80];
    for (i = 0; i < sizeof plateau_cli_conflicts / sizeof plateau_cli_conflicts[0]; i++) {
        const struct plateau_cli_conflict *c = &plateau_cli_conflicts[i];
        if ((have & c->a) && (have & c->b)) {
            snprintf(msg, msg_size, "%s and %s cannot go together: %s", plateau_cli_setting(args, c->a, a, sizeof a),
                     plateau_cli_setting(args, c->b, b, sizeof b), c->why);
            return 1;
        }
    }
    return 0;
}

/* Fills args from argv.  Returns 0 when fine; otherwise writes a sentence
 * into msg and returns 2 (bad usage).  "--opt value" and "--opt=value" both
 * work; "--" ends the options. */
PLATEAU_CLI_FN int plateau_cli_parse(int argc, char **argv, plateau_cli_args *args, char *msg,
                                     size_t msg_size)
{
    int i, options_done = 0;
    memset(args, 0, sizeof *args);
    args->method = PLATEAU_METHOD_PAPER;
    msg[0] = '\0';
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *value = NULL, *eq;
        const plateau_cli_option *o;
        char name[32];
        size_t nlen;
        if (options_done || a[0] != '-' || a[1] == '\0') {
            if (args->num_inputs == PLATEAU_CLI_MAX_INPUTS) {
                snprintf(msg, msg_size, "more than %d boundary files (from '%.40s')",
                         PLATEAU_CLI_MAX_INPUTS, a);
                return 2;
            }
            if (!args->input) args->input = a;
            args->inputs[args->num_inputs++] = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            options_done = 1;
            continue;
        }
        eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
        nlen = eq ? (size_t)(eq - a) : strlen(a);
        if (nlen >= sizeof name) nlen = sizeof name - 1;
        memcpy(name, a, nlen);
        name[nlen] = '\0';
        o = plateau_cli_find_option(name);
        if (o && o->kind != PLATEAU_CLI_FLAG) {
            if (eq) {
                value = eq + 1;
            } else if (i + 1 < argc) {
                value = argv[++i];
            } else {
                snprintf(msg, msg_size, "option %.30s needs a value", name);
                return 2;
            }
        } else if (eq) {
            snprintf(msg, msg_size, "option %.30s takes no value", name);
            return 2;
        }
        if (!o) {
            snprintf(msg, msg_size, "unknown option '%.40s'", a);
            return 2;
        }
        if (!plateau_cli_store(o, value, args)) {
            snprintf(msg, msg_size, o->bad, value);
            return 2;
        }
    }
    if (!args->input && !args->minimize_path && !args->pattern_mesh && !args->help && !args->version) {
        snprintf(msg, msg_size, "no boundary file given");
        return 2;
    }
    if (args->input && args->minimize_path) {
        snprintf(msg, msg_size, "--minimize %.60s takes a mesh in place of boundary files, not with '%.60s'",
                 args->minimize_path, args->input);
        return 2;
    }
    if (args->input && args->pattern_mesh) {
        snprintf(msg, msg_size, "--mesh %.60s takes a mesh in place of boundary files, not with '%.60s'",
                 args->pattern_mesh, args->input);
        return 2;
    }
    if (args->pattern_width == 0.0 &&
        (args->pattern_mesh || args->pattern_svg || args->pattern_dxf || args->pattern_seams ||
         args->have_pattern_direction || args->have_pattern_point || args->pattern_panels ||
         args->pattern_shrink_along > 0.0 || args->pattern_shrink_across > 0.0 || args->pattern_marks > 0.0)) {
        snprintf(msg, msg_size, "%s needs --pattern W (the roll width)",
                 args->pattern_mesh ? "--mesh" : args->pattern_svg ? "--pattern-svg"
                 : args->pattern_dxf ? "--pattern-dxf" : "a --pattern-... option");
        return 2;
    }
    if (args->have_pattern_point && (args->pattern_seams != PLATEAU_SEAMS_AXIS || !args->have_pattern_direction)) {
        snprintf(msg, msg_size, "--pattern-point is a point of the axis: it needs --pattern-seams axis and "
                                "--pattern-direction");
        return 2;
    }
    if (args->stl_ascii && !(args->mesh_path && plateau_cli_has_ext(args->mesh_path, ".stl"))) {
        snprintf(msg, msg_size, "--stl-ascii needs a mesh file ending in .stl (-o FILE.stl)");
        return 2;
    }
    return plateau_cli_conflict(args, msg, msg_size) ? 2 : 0;
}

/* "FILE: cannot read the file", and why when errno said (e non-zero). */
static void plateau_cli_cannot_read(char *msg, size_t msg_size, const char *path, int e)
{
    snprintf(msg, msg_size, "%.120s: cannot read the file%s%s", path, e ? ": " : "", e ? strerror(e) : "");
}

/* Reads and validates the boundary file; "-" is standard input.  At most
 * max_bytes bytes are read (0: PLATEAU_DEFAULT_MAX_INPUT_BYTES): a larger
 * input is refused.  Returns 0 with *xyz (plateau_boundary_free(*xyz, NULL))
 * and *m filled, or 1 with a message "FILE: what is wrong" in msg (a parse
 * error names its line: "FILE: line 7: field 2 is not a number"). */
PLATEAU_CLI_FN int plateau_cli_load_capped(const char *path, size_t max_bytes, double **xyz,
                                           size_t *m, char *msg, size_t msg_size)
{
    plateau_error err;
    plateau_result r = PLATEAU_ERR_IO;
    int from_stdin = strcmp(path, "-") == 0, e;
    FILE *f;
    errno = 0;
    f = from_stdin ? stdin : fopen(path, "rb");
    e = errno;
    *xyz = NULL;
    *m = 0;
    if (from_stdin) path = "(standard input)";
    if (f) {
        errno = 0;
        r = plateau_read_boundary_stream(f, max_bytes, NULL, xyz, m, &err);
        e = errno;
        if (!from_stdin) fclose(f);
    }
    if (r == PLATEAU_OK) {
        r = plateau_boundary_check(*xyz, *m, &err);
        if (r != PLATEAU_OK) {
            plateau_boundary_free(*xyz, NULL);
            *xyz = NULL;
            *m = 0;
        }
    }
    if (r == PLATEAU_OK) return 0;
    if (r == PLATEAU_ERR_IO)
        plateau_cli_cannot_read(msg, msg_size, path, e);
    else if (r == PLATEAU_ERR_INPUT_TOO_LARGE)
        snprintf(msg, msg_size, "%.120s: %s (--max-input-bytes raises it)", path, err.message);
    else if (r == PLATEAU_ERR_TOO_FEW_VERTICES && *m == 0 && err.index == 0)
        snprintf(msg, msg_size, "%.120s: no vertices (a polygon needs at least 3)", path);
    else
        snprintf(msg, msg_size, "%.120s: %s", path, err.message);
    return 1;
}

/* Where the vertices of a run came from, for messages that name file
 * lines: vertex v of the whole boundary (all files' loops one after the
 * other) is on line lines[v] of file files[f], f the file with
 * file_off[f] <= v < file_off[f + 1]; the loops have counts[0 .. k - 1]
 * vertices. */
typedef struct plateau_cli_where {
    const long *lines;
    size_t m;
    const size_t *counts;
    size_t k;
    const char *const *files;
    const size_t *file_off;
    int num_files;
} plateau_cli_where;

/* "5" (one file) or "ring.txt:5" (several) for vertex v, into buf. */
static void plateau_cli_line_of(const plateau_cli_where *w, long v, char *buf, size_t size)
{
    int f = 0;
    if (w->num_files > 1) {
        while (f + 1 < w->num_files && (size_t)v >= w->file_off[f + 1]) f++;
        snprintf(buf, size, "%.72s:%ld", w->files[f], w->lines[v]);
    } else {
        snprintf(buf, size, "%ld", w->lines[v]);
    }
}

/* The vertex after v in its loop (edge v joins v to it). */
static long plateau_cli_next_vertex(const plateau_cli_where *w, long v)
{
    size_t j, o = 0;
    for (j = 0; j < w->k; o += w->counts[j], j++)
        if ((size_t)v < o + w->counts[j]) return (long)(o + ((size_t)v - o + 1) % w->counts[j]);
    return v;
}

/* Appends to msg (a NUL-terminated message of at most size bytes) the file
 * lines of the vertices a geometric error names (plateau_error.index and
 * .index2): " (file lines 5 and 6)" for two vertices, " (file lines:
 * vertex 9, edge 2-3)" for a vertex on an edge, " (file lines: edges 2-3
 * and 7-8)" for two edges; with several files each line is "file:line".
 * Other errors, or indices outside the boundary, add nothing. */
PLATEAU_CLI_FN void plateau_cli_error_lines(char *msg, size_t size, const plateau_error *err,
                                            const plateau_cli_where *w)
{
    char a[96], b[96], c[96], d[96], add[512];
    const char *what = w->num_files > 1 ? "lines" : "file lines";
    size_t len = strlen(msg), q;
    long i = err->index, j = err->index2;
    if (!w->lines || i < 0 || j < 0 || (size_t)i >= w->m || (size_t)j >= w->m) return;
    plateau_cli_line_of(w, i, a, sizeof a);
    plateau_cli_line_of(w, j, b, sizeof b);
    add[0] = '\0';
    switch (err->code) {
    case PLATEAU_ERR_REPEATED_VERTEX:
    case PLATEAU_ERR_DUPLICATE_VERTEX:
    case PLATEAU_ERR_LOOPS_SHARE_VERTEX:
        snprintf(add, sizeof add, " (%s %s and %s)", what, a, b);
        break;
    case PLATEAU_ERR_VERTEX_ON_EDGE:
        plateau_cli_line_of(w, plateau_cli_next_vertex(w, j), c, sizeof c);
        snprintf(add, sizeof add, " (%s: vertex %s, edge %s-%s)", what, a, b, c);
        break;
    case PLATEAU_ERR_EDGES_INTERSECT:
    case PLATEAU_ERR_LOOPS_INTERSECT:
        plateau_cli_line_of(w, plateau_cli_next_vertex(w, i), c, sizeof c);
        plateau_cli_line_of(w, plateau_cli_next_vertex(w, j), d, sizeof d);
        snprintf(add, sizeof add, " (%s: edges %s-%s and %s-%s)", what, a, c, b, d);
        break;
    default:
        break;
    }
    for (q = 0; add[q] && len + 1 < size; q++) msg[len++] = add[q];
    if (len < size) msg[len] = '\0';
}

/* The notes for the closing points plateau_parse_boundary_lines dropped:
 * one line on errout per loop that had one. */
PLATEAU_CLI_FN void plateau_cli_closing_notes(FILE *errout, const char *path,
                                              const plateau_boundary_lines *info)
{
    size_t j, o = 0;
    if (strcmp(path, "-") == 0) path = "(standard input)";
    for (j = 0; j < info->num_loops; o += info->loop_counts[j], j++) {
        if (info->closing_lines[j] == 0) continue;
        fprintf(errout, "plateau: note: %.120s: line %ld repeats the first vertex of %s (line %ld); "
                        "dropped, as the polygon closes by itself\n",
                path, info->closing_lines[j], info->num_loops > 1 ? "its loop" : "the polygon",
                info->loop_counts[j] > 0 ? info->lines[o] : 0L);
    }
}

/* The whole text of f, at most limit bytes (one more proves it too
 * large), into *buf (free() it, also on failure; NULL when f is empty) and
 * *size.  Returns PLATEAU_OK, PLATEAU_ERR_INPUT_TOO_LARGE,
 * PLATEAU_ERR_OUT_OF_MEMORY or PLATEAU_ERR_IO (*e: errno then, or 0). */
static plateau_result plateau_cli_read_text(FILE *f, size_t limit, char **buf, size_t *size, int *e)
{
    size_t cap = 0;
    *buf = NULL;
    *size = 0;
    *e = 0;
    for (;;) {
        size_t got;
        if (*size == cap) {
            size_t ncap = cap ? 2 * cap : 65536;
            char *nbuf;
            if (limit < (size_t)-1 && ncap > limit + 1) ncap = limit + 1;
            if (ncap <= cap) return PLATEAU_ERR_INPUT_TOO_LARGE;
            nbuf = (char *)realloc(*buf, ncap);
            if (!nbuf) return PLATEAU_ERR_OUT_OF_MEMORY;
            *buf = nbuf;
            cap = ncap;
        }
        errno = 0;
        got = fread(*buf + *size, 1, cap - *size, f);
        *size += got;
        if (*size > limit) return PLATEAU_ERR_INPUT_TOO_LARGE;
        if (got == 0) {
            if (!ferror(f)) return PLATEAU_OK;
            *e = errno;
            return PLATEAU_ERR_IO;
        }
    }
}

/* Reads a boundary file of one or more loops (runs of vertex lines
 * separated by a blank line, plateau_parse_boundary_lines with
 * split_loops; "-" is standard input; at most max_bytes bytes, 0: the
 * library's default).  A closing point equal to its loop's first vertex
 * is dropped (info->closing_lines says where; plateau_cli_closing_notes
 * prints it).  With tension non-NULL, the cables of the text ("x y z
 * cable T", plateau_parse_cables): *tension one per vertex kept, or NULL
 * when there are none (free it with plateau_boundary_free); a "cable" on
 * a closing point that is dropped is refused, naming its line
 * (plateau_cables_align).  With slide non-NULL, the sliding vertices
 * ("x y z slide-plane nx ny nz", "x y z slide-line dx dy dz",
 * plateau_parse_slides): *slide and *slide_dir one entry (three) per
 * vertex kept, or NULL when none slides (plateau_slides_free(*slide,
 * *slide_dir, NULL)).  Returns 0 with *xyz
 * (plateau_boundary_free(*xyz, NULL)), *m, the loops' counts (*k of them,
 * at most max_loops) and *info (plateau_boundary_lines_free(info, NULL):
 * each vertex's line), or 1 with a message as plateau_cli_load_capped and
 * its plateau_result in *code (nothing to free).  A file of one loop is
 * checked as plateau_cli_load_capped checks it, its message naming file
 * lines (plateau_cli_error_lines); several loops are checked by
 * plateau_solve_loops. */
PLATEAU_CLI_FN int plateau_cli_load_input(const char *path, size_t max_bytes, double **xyz, size_t *m,
                                          size_t *counts, size_t max_loops, size_t *k,
                                          plateau_boundary_lines *info, double **tension, int **slide,
                                          double **slide_dir, char *msg, size_t msg_size, plateau_result *code)
{
    size_t nt = 0, ns = 0, size = 0, limit = max_bytes ? max_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
    plateau_error err;
    plateau_result r = PLATEAU_ERR_IO;
    int from_stdin = strcmp(path, "-") == 0, e, done = 0; /* done: msg written */
    FILE *f;
    char *buf = NULL;
    *xyz = NULL;
    *m = 0;
    *k = 0;
    if (tension) *tension = NULL;
    if (slide) *slide = NULL, *slide_dir = NULL;
    memset(info, 0, sizeof *info);
    info->split_loops = 1;
    errno = 0;
    f = from_stdin ? stdin : fopen(path, "rb");
    e = errno;
    if (from_stdin) path = "(standard input)";
    if (f) {
        r = plateau_cli_read_text(f, limit, &buf, &size, &e);
        if (!from_stdin) fclose(f);
    }
    if (r != PLATEAU_OK) {
        free(buf);
        *code = r;
        if (r == PLATEAU_ERR_INPUT_TOO_LARGE)
            snprintf(msg, msg_size, "%.120s: the input is larger than the limit of %lu bytes "
                     "(--max-input-bytes raises it)", path, (unsigned long)limit);
        else if (r == PLATEAU_ERR_OUT_OF_MEMORY)
            snprintf(msg, msg_size, "%.120s: out of memory reading the file", path);
        else
            plateau_cli_cannot_read(msg, msg_size, path, e);
        return 1;
    }
    if (slide && buf) r = plateau_parse_slides(buf, size, NULL, slide, slide_dir, &ns, &err);
    if (r == PLATEAU_OK && tension && buf) r = plateau_parse_cables(buf, size, NULL, tension, &nt, &err);
    if (r == PLATEAU_OK) r = plateau_parse_boundary_lines(buf ? buf : "", size, NULL, xyz, m, info, &err);
    free(buf);
    if (r == PLATEAU_OK && tension && *tension) r = plateau_cables_align(*tension, &nt, info, &err);
    if (r == PLATEAU_OK && slide && *slide) r = plateau_slides_align(*slide, *slide_dir, &ns, info, &err);
    if (r == PLATEAU_OK && info->num_loops > max_loops) {
        snprintf(msg, msg_size, "%.120s: more than %lu loops", path, (unsigned long)max_loops);
        r = PLATEAU_ERR_ARGUMENT;
        done = 1;
    } else if (r == PLATEAU_OK) {
        size_t j;
        *k = info->num_loops;
        for (j = 0; j < *k; j++) counts[j] = info->loop_counts[j];
        if (*k <= 1) {
            r = plateau_boundary_check(*xyz, *m, &err);
            if (r == PLATEAU_ERR_TOO_FEW_VERTICES && *m == 0) {
                snprintf(msg, msg_size, "%.120s: no vertices (a polygon needs at least 3)", path);
                done = 1;
            } else if (r != PLATEAU_OK) {
                plateau_cli_where w; /* one loop: its count is *m */
                memset(&w, 0, sizeof w);
                w.lines = info->lines;
                w.m = *m;
                w.counts = m;
                w.k = 1;
                snprintf(msg, msg_size, "%.120s: %s", path, err.message);
                plateau_cli_error_lines(msg, msg_size, &err, &w);
                done = 1;
            }
        }
    }
    if (r == PLATEAU_OK) return 0;
    *code = r;
    if (tension) {
        plateau_boundary_free(*tension, NULL);
        *tension = NULL;
    }
    if (slide) {
        plateau_slides_free(*slide, *slide_dir, NULL);
        *slide = NULL, *slide_dir = NULL;
    }
    plateau_boundary_free(*xyz, NULL);
    plateau_boundary_lines_free(info, NULL);
    *xyz = NULL;
    *m = 0;
    *k = 0;
    if (done) return 1;
    if (r == PLATEAU_ERR_IO) plateau_cli_cannot_read(msg, msg_size, path, 0);
    else snprintf(msg, msg_size, "%.120s: %s", path, err.message);
    return 1;
}

/* plateau_cli_load_input without the result code. */
PLATEAU_CLI_FN int plateau_cli_load_loops_cables(const char *path, size_t max_bytes, double **xyz, size_t *m,
                                                 size_t *counts, size_t max_loops, size_t *k,
                                                 plateau_boundary_lines *info, double **tension,
                                                 char *msg, size_t msg_size)
{
    plateau_result code;
    return plateau_cli_load_input(path, max_bytes, xyz, m, counts, max_loops, k, info, tension, NULL, NULL, msg, msg_size,
                                  &code);
}

/* plateau_cli_load_input without cables or the result code. */
PLATEAU_CLI_FN int plateau_cli_load_loops(const char *path, size_t max_bytes, double **xyz, size_t *m,
                                          size_t *counts, size_t max_loops, size_t *k,
                                          plateau_boundary_lines *info, char *msg, size_t msg_size)
{
    return plateau_cli_load_loops_cables(path, max_bytes, xyz, m, counts, max_loops, k, info, NULL, msg, msg_size);
}

/* plateau_cli_load_capped with the default cap. */
PLATEAU_CLI_FN int plateau_cli_load(const char *path, double **xyz, size_t *m, char *msg,
                                    size_t msg_size)
{
    return plateau_cli_load_capped(path, 0, xyz, m, msg, msg_size);
}

/* What one run produced, for the summary and the JSON. */
typedef struct plateau_cli_result {
    const char *input;
    size_t boundary_vertices;
    size_t vertices, triangles;
    uint64_t seed;
    size_t points_requested; /* 0: the library's default */
    double elapsed_s;
    plateau_report report;
    const char *seeding_name; /* "paper" or "quality" (NULL: not shown) */
    const char *method_name;  /* plateau_method_name(report.method) */
    const char *stop_string;  /* plateau_stop_string(report.stop) */
    const char *mesh_path, *svg_path;
    int pressure_typed;       /* report.pressure is --pressure's value as typed */
    double edge_length;       /* --edge-length (0: not given) */
    int minimized;            /* --minimize: the input was a mesh, its
                                 boundary kept; then boundary_vertices and
                                 loops are its boundary's */
    size_t loops;             /* the boundary's loops */
    double initial_area;      /* --minimize: the area of the mesh read */
    double boundary_length;   /* L, the length of all the boundary's loops:
                                 the stability values times a power of L
                                 are the same in any unit */
    double boundary_radius;   /* the largest distance of a boundary vertex
                                 from their centroid (the pressure that a
                                 film is known to exist for) */
    double edge_ratio;        /* the polygon's longest edge over the mesh's
                                 mean edge length (0: not known): how far
                                 the seeding could split the polygon */
    int critical_index;       /* --critical-index K (0: no saddle search) */
    int stability_off;        /* --no-stability */
    const plateau_pattern *pattern; /* --pattern: the cutting pattern, or NULL */
    const char *pattern_svg_path, *pattern_dxf_path; /* the pattern files written */
} plateau_cli_result;

/* Why report.stability holds no status of the mesh, or NULL when it does:
 * not asked, not computed (a membrane, the time limit, no Hessian), or
 * computed on a mesh that is no equilibrium (unsolved or pinched: its area
 * gradient is not 0, so the index says nothing about stability). */
static const char *plateau_cli_stability_note(const plateau_cli_result *r)
{
    const plateau_report *p = &r->report;
    if (p->stability.computed && p->solved && p->stop != PLATEAU_STOP_PINCHED) return NULL;
    if (p->stability.computed)
        return "not an equilibrium (unsolved or pinched): its area gradient is not 0, so the index of the "
               "Hessian says nothing about its stability";
    if (p->membrane) return "not computed for a membrane: the area's Hessian is not the Hessian of its energy";
    if (r->stability_off) return NULL; /* not asked: the fields are left out */
    if (p->stop == PLATEAU_STOP_TIME_LIMIT) return "not computed: the time limit ran out first";
    return "not computed: no free vertex, or a zero-area triangle (no Hessian)";
}

/* 1 when report.f_final is the method's F of a solve that ran: 0 for a
 * mesh no solve of the method reached (no round, a seeding the time limit
 * cut before any point, or method paper stopped by the pinch of its area
 * presolve). */
static int plateau_cli_f_known(const plateau_report *p)
{
    if (p->interior_points == 0) return p->stop != PLATEAU_STOP_TIME_LIMIT;
    if (p->rounds == 0 && p->levels == 0) return 0;
    return !(p->stop == PLATEAU_STOP_PINCHED && p->iterations == 0 && p->f_final == 0.0 && p->f_initial == 0.0);
}

static const char *plateau_cli_domain_name(plateau_domain_kind kind)
{
    return kind == PLATEAU_DOMAIN_CIRCLE ? "circle" : (kind == PLATEAU_DOMAIN_ANNULUS ? "annulus" : "plane");
}

/* The length of the well-formed UTF-8 sequence at s (RFC 3629: no
 * overlong forms, no surrogates, nothing above U+10FFFF), or 0. */
static size_t plateau_cli_utf8_length(const unsigned char *s)
{
    unsigned c = s[0];
    size_t n, k;
    unsigned lo = 0x80, hi = 0xbf;
    if (c < 0x80) return 1;
    if (c >= 0xc2 && c <= 0xdf) n = 2;
    else if (c >= 0xe0 && c <= 0xef) n = 3;
    else if (c >= 0xf0 && c <= 0xf4) n = 4;
    else return 0;
    if (c == 0xe0) lo = 0xa0;      /* overlong */
    if (c == 0xed) hi = 0x9f;      /* surrogates */
    if (c == 0xf0) lo = 0x90;      /* overlong */
    if (c == 0xf4) hi = 0x8f;      /* above U+10FFFF */
    for (k = 1; k < n; k++) {
        if (s[k] < (k == 1 ? lo : 0x80) || s[k] > (k == 1 ? hi : 0xbf)) return 0;
    }
    return n;
}

/* The characters of s inside a JSON string: quotes, backslashes and
 * control characters escaped, well-formed UTF-8 as it is, and every byte
 * that is not part of one (a file name in another encoding) as the escape
 * of the code point of that byte's value (\u0080 .. \u00ff, its Latin-1
 * reading), so that the output is valid UTF-8 whatever the bytes. */
static void plateau_cli_json_chars(FILE *out, const char *s)
{
    const unsigned char *u = (const unsigned char *)s;
    while (u && *u) {
        unsigned char c = *u;
        size_t n = plateau_cli_utf8_length(u);
        if (n > 1) {
            fwrite(u, 1, n, out);
            u += n;
            continue;
        }
        if (c == '"' || c == '\\') fprintf(out, "\\%c", c);
        else if (c == '\n') fputs("\\n", out);
        else if (c == '\t') fputs("\\t", out);
        else if (c < 0x20 || c >= 0x7f) fprintf(out, "\\u%04x", c);
        else fputc(c, out);
        u++;
    }
}

/* A JSON string of s (plateau_cli_json_chars). */
static void plateau_cli_json_string(FILE *out, const char *s)
{
    fputc('"', out);
    plateau_cli_json_chars(out, s);
    fputc('"', out);
}

/* The name of a plateau_result as its enum spells it ("PLATEAU_ERR_IO"). */
static const char *plateau_cli_result_name(plateau_result r)
{
    switch (r) {
#define PLATEAU_CLI_RESULT_NAME_(name, value, text) \
    case name:                                      \
        return #name;
        PLATEAU_RESULT_LIST(PLATEAU_CLI_RESULT_NAME_)
#undef PLATEAU_CLI_RESULT_NAME_
    default:
        break;
    }
    return "PLATEAU_ERR_UNKNOWN";
}

/* What --json prints for a run that failed: {"error": the message (after
 * "INPUT: the solve failed: " when failed_input is not NULL), "code": the
 * name of its plateau_result (PLATEAU_ERR_ARGUMENT for bad usage), "exit":
 * the exit status}. */
PLATEAU_CLI_FN void plateau_cli_print_json_error(FILE *out, const char *failed_input, const char *msg,
                                                 plateau_result code, int status)
{
    fputs("{\"error\": \"", out);
    if (failed_input) {
        plateau_cli_json_chars(out, failed_input);
        fputs(": the solve failed: ", out);
    }
    plateau_cli_json_chars(out, msg);
    fprintf(out, "\", \"code\": \"%s\", \"exit\": %d}\n", plateau_cli_result_name(code), status);
}

/* A JSON number: plateau_cli_number; null for NaN and infinities, which
 * JSON cannot hold. */
static void plateau_cli_json_number(FILE *out, double v)
{
    char buf[PLATEAU_CLI_NUMBER_SIZE];
    fputs(v == v && v - v == 0.0 ? plateau_cli_number(v, buf) : "null", out);
}

/* report.range in words ("" when 0). */
static const char *plateau_cli_range_words(unsigned range, char *buf, size_t size)
{
    buf[0] = '\0';
    if (range & PLATEAU_RANGE_AREA_OVERFLOW) strncat(buf, "area above the largest double; ", size - strlen(buf) - 1);
    if (range & PLATEAU_RANGE_AREA_UNDERFLOW) strncat(buf, "area below the smallest normal double; ", size - strlen(buf) - 1);
    if (range & PLATEAU_RANGE_F_OVERFLOW) strncat(buf, "F above the largest double; ", size - strlen(buf) - 1);
    if (range & PLATEAU_RANGE_F_UNDERFLOW) strncat(buf, "F below the smallest normal double; ", size - strlen(buf) - 1);
    if (range & PLATEAU_RANGE_VOLUME_OVERFLOW) strncat(buf, "volume above the largest double; ", size - strlen(buf) - 1);
    if (range & PLATEAU_RANGE_VOLUME_UNDERFLOW)
        strncat(buf, "volume below the smallest normal double; ", size - strlen(buf) - 1);
    if (buf[0]) buf[strlen(buf) - 2] = '\0';
    return buf;
}

/* The area at any scale: "area_significand", "area_exponent" (exact:
 * area = significand * 2^exponent), "area_log10" (finite whenever the
 * area is not 0), and "range" in words. */
static void plateau_cli_print_json_range(FILE *out, const plateau_report *p)
{
    char words[200];
    fputs(", \"area_significand\": ", out);
    plateau_cli_json_number(out, p->area_significand);
    fprintf(out, ", \"area_exponent\": %d, \"area_log10\": ", p->area_exponent);
    if (p->area_significand > 0.0)
        plateau_cli_json_number(out, log10(p->area_significand) + 0.30102999566398120 * p->area_exponent);
    else
        fputs("null", out);
    fputs(", \"range\": ", out);
    plateau_cli_json_string(out, plateau_cli_range_words(p->range, words, sizeof words));
}

/* The final check's fields: the counts, "solved", the defect bits and
 * their words, and "valid" (defects == 0). */
static void plateau_cli_print_json_check(FILE *out, const plateau_report *p)
{
    char words[320];
    fprintf(out, ", \"folded_edges\": %lu, \"degenerate_triangles\": %lu, \"intersecting_pairs\": %lu",
            (unsigned long)p->folded_edges, (unsigned long)p->degenerate_triangles,
            (unsigned long)p->intersecting_pairs);
    fprintf(out, ", \"check_cut\": %s", p->check_cut ? "true" : "false");
    fprintf(out, ", \"solved\": %s, \"defects\": %u, \"defects_string\": ", p->solved ? "true" : "false",
            p->defects);
    plateau_cli_json_string(out, plateau_defects_string(p->defects, words, sizeof words));
    fprintf(out, ", \"valid\": %s", p->defects ? "false" : "true");
}

/* The second-order status and the alternatives of two loops; L: the
 * boundary's length, for the values that do not depend on the unit. */
static void plateau_cli_print_json_status(FILE *out, const plateau_cli_result *r, double L)
{
    const plateau_report *p = &r->report;
    const char *note = plateau_cli_stability_note(r);
    size_t q;
    if (r->critical_index > 0 || p->critical_steps || p->critical_converged)
        fprintf(out, ", \"critical_converged\": %s, \"critical_steps\": %lu",
                p->critical_converged ? "true" : "false", (unsigned long)p->critical_steps);
    if (note) {
        fputs(", \"stability_index\": null, \"stability_note\": ", out);
        plateau_cli_json_string(out, note);
    }
    if (p->stability.computed) {
        if (!note) fprintf(out, ", \"stability_index\": %lu", (unsigned long)p->stability.index);
        fputs(", \"lowest_eigenvalues\": [", out);
        for (q = 0; q < p->stability.num_eigenvalues; q++) {
            if (q) fputs(", ", out);
            plateau_cli_json_number(out, p->stability.lowest_eigenvalues[q]);
        }
        fputs("], \"area_gradient_norm\": ", out);
        plateau_cli_json_number(out, p->stability.area_gradient_norm);
        fputs(", \"lowest_eigenvalues_scaled\": [", out);
        for (q = 0; q < p->stability.num_eigenvalues; q++) {
            if (q) fputs(", ", out);
            plateau_cli_json_number(out, p->stability.lowest_eigenvalues[q] * L * L);
        }
        fputs("], \"area_gradient_norm_scaled\": ", out);
        plateau_cli_json_number(out, L > 0.0 ? p->stability.area_gradient_norm / L : 0.0);
    }
    if (p->alternative_area > 0.0) {
        fputs(", \"alternatives\": [{\"topology\": \"discs\", \"area\": ", out);
        plateau_cli_json_number(out, p->alternative_area);
        fputs("}], \"film_area\": ", out);
        plateau_cli_json_number(out, p->film_area);
        fprintf(out, ", \"least_area_topology\": \"%s\", \"returned_topology\": \"%s\"",
                p->film_not_least ? "discs" : "film", p->discs_returned ? "discs" : "film");
    }
}

/* --pattern's part of the JSON: ", \"pattern\": {...}" and the files. */
static void plateau_cli_print_json_pattern(FILE *out, const plateau_cli_result *r)
{
    const plateau_pattern *p = r->pattern;
    size_t i;
    if (!p) return;
    fputs(", \"pattern\": {\"roll_width\": ", out);
    plateau_cli_json_number(out, p->roll_width);
    fputs(", \"panels\": [", out);
    for (i = 0; i < p->num_panels; i++) {
        const plateau_pattern_panel *q = &p->panels[i];
        fputs(i ? ", {\"area_3d\": " : "{\"area_3d\": ", out);
        plateau_cli_json_number(out, q->area_3d);
        fputs(", \"area_flat\": ", out);
        plateau_cli_json_number(out, q->area_flat);
        fputs(", \"max_strain\": ", out);
        plateau_cli_json_number(out, q->max_strain);
        fputs(", \"mean_strain\": ", out);
        plateau_cli_json_number(out, q->mean_strain);
        fputs(", \"width\": ", out);
        plateau_cli_json_number(out, q->width);
        fputs(", \"panel_length\": ", out);
        plateau_cli_json_number(out, q->length);
        fputs("}", out);
    }
    fputs("], \"seams\": [", out);
    for (i = 0; i < p->num_seams; i++) {
        const plateau_pattern_seam *q = &p->seams[i];
        fprintf(out, "%s{\"panels\": [%lu, %lu], \"lengths\": [", i ? ", " : "", (unsigned long)q->panels[0],
                (unsigned long)q->panels[1]);
        plateau_cli_json_number(out, q->lengths[0]);
        fputs(", ", out);
        plateau_cli_json_number(out, q->lengths[1]);
        fputs("], \"length_3d\": ", out);
        plateau_cli_json_number(out, q->length_3d);
        fputs("}", out);
    }
    fputs("], \"max_strain\": ", out);
    plateau_cli_json_number(out, p->max_strain);
    fputs(", \"mean_strain\": ", out);
    plateau_cli_json_number(out, p->mean_strain);
    fputs("}", out);
    if (r->pattern_svg_path) {
        fputs(", \"pattern_svg_file\": ", out);
        plateau_cli_json_string(out, r->pattern_svg_path);
    }
    if (r->pattern_dxf_path) {
        fputs(", \"pattern_dxf_file\": ", out);
        plateau_cli_json_string(out, r->pattern_dxf_path);
    }
}

/* --mesh: the input mesh and its pattern, nothing solved. */
PLATEAU_CLI_FN void plateau_cli_print_json_pattern_only(FILE *out, const plateau_cli_result *r)
{
    fputs("{\"input\": ", out);
    plateau_cli_json_string(out, r->input);
    fprintf(out, ", \"vertices\": %lu, \"triangles\": %lu", (unsigned long)r->vertices,
            (unsigned long)r->triangles);
    fputs(", \"area\": ", out);
    plateau_cli_json_number(out, r->initial_area);
    fputs(", \"elapsed_s\": ", out);
    plateau_cli_json_number(out, r->elapsed_s);
    plateau_cli_print_json_pattern(out, r);
    fputs("}\n", out);
}

/* --pattern's lines of the summary. */
PLATEAU_CLI_FN void plateau_cli_print_summary_pattern(FILE *out, const plateau_cli_result *r)
{
    const plateau_pattern *p = r->pattern;
    size_t i;
    double worst = 0.0;
    if (!p) return;
    for (i = 0; i < p->num_seams; i++) {
        const plateau_pattern_seam *q = &p->seams[i];
        double d = fabs(q->lengths[0] - q->lengths[1]) / (q->length_3d > 0.0 ? q->length_3d : 1.0);
        if (d > worst) worst = d;
    }
    fprintf(out, "  pattern    %lu panels, %lu seams for a roll %.6g wide; strain largest %.3g, mean %.3g; "
                 "seam sides differ by %.3g of their length at most\n",
            (unsigned long)p->num_panels, (unsigned long)p->num_seams, p->roll_width, p->max_strain, p->mean_strain,
            worst);
    for (i = 0; i < p->num_panels; i++)
        fprintf(out, "  panel %-4lu %.6g x %.6g, area %.6g (flat %.6g), strain largest %.3g, mean %.3g\n",
                (unsigned long)i, p->panels[i].length, p->panels[i].width, p->panels[i].area_3d,
                p->panels[i].area_flat, p->panels[i].max_strain, p->panels[i].mean_strain);
    if (r->pattern_svg_path) fprintf(out, "  panels svg %s\n", r->pattern_svg_path);
    if (r->pattern_dxf_path) fprintf(out, "  panels dxf %s\n", r->pattern_dxf_path);
}

PLATEAU_CLI_FN void plateau_cli_print_json(FILE *out, const plateau_cli_result *r)
{
    const plateau_report *p = &r->report;
    fputs("{\"input\": ", out);
    plateau_cli_json_string(out, r->input);
    if (r->minimized) {
        fputs(", \"minimize\": true, \"initial_area\": ", out);
        plateau_cli_json_number(out, r->initial_area);
    }
    fprintf(out, ", \"boundary_vertices\": %lu", (unsigned long)r->boundary_vertices);
    fputs(", \"boundary_length\": ", out);
    plateau_cli_json_number(out, r->boundary_length);
    fprintf(out, ", \"vertices\": %lu, \"triangles\": %lu", (unsigned long)r->vertices,
            (unsigned long)r->triangles);
    fputs(", \"method\": ", out);
    plateau_cli_json_string(out, r->method_name);
    if (!r->minimized) { /* a mesh given has no parameter domain */
        fputs(", \"domain\": ", out);
        plateau_cli_json_string(out, plateau_cli_domain_name(p->domain));
    }
    fprintf(out, ", \"loops\": %lu", (unsigned long)(r->loops ? r->loops : 1));
    if (p->loops == 2) {
        fputs(", \"neck_ratio\": ", out);
        plateau_cli_json_number(out, p->neck_ratio);
    }
    fprintf(out, ", \"pinched\": %s", p->stop == PLATEAU_STOP_PINCHED ? "true" : "false");
    if (!r->minimized) fprintf(out, ", \"seed\": %llu", (unsigned long long)r->seed);
    if (r->edge_length > 0.0) {
        fputs(", \"edge_length\": ", out);
        plateau_cli_json_number(out, r->edge_length);
    }
    fputs(", \"area\": ", out);
    plateau_cli_json_number(out, p->area);
    fputs(", \"area_error_estimate\": ", out);
    if (p->estimate == PLATEAU_ESTIMATE_FORMED && p->area_error_estimate == p->area_error_estimate)
        plateau_cli_json_number(out, p->area_error_estimate);
    else
        fputs("null", out);
    fputs(", \"estimate\": ", out);
    plateau_cli_json_string(out, plateau_estimate_string(p->estimate));
    fputs(", \"accuracy\": ", out);
    plateau_cli_json_number(out, p->accuracy);
    fprintf(out, ", \"accuracy_solves\": %lu", (unsigned long)p->accuracy_solves);
    fputs(", \"accuracy_stop\": ", out);
    plateau_cli_json_string(out, plateau_accuracy_stop_string(p->accuracy_stop));
    plateau_cli_print_json_range(out, p);
    if (plateau_cli_f_known(p)) {
        fputs(", \"F\": ", out);
        plateau_cli_json_number(out, p->f_final);
        fputs(", \"F_initial\": ", out);
        plateau_cli_json_number(out, p->f_initial);
    } else {
        fputs(", \"F\": null, \"F_initial\": null, \"F_note\": \"no solve of the method ran on this mesh\"", out);
    }
    fprintf(out, ", \"rounds\": %zu, \"iterations\": %zu, \"evaluations\": %zu, \"flips\": %zu",
            p->rounds, p->iterations, p->evaluations, p->flips);
    if (!r->minimized) fprintf(out, ", \"levels\": %zu", p->levels);
    fputs(", \"min_angle_deg\": ", out);
    plateau_cli_json_number(out, p->min_angle_deg);
    fputs(", \"max_angle_deg\": ", out);
    plateau_cli_json_number(out, p->max_angle_deg);
    fputs(", \"quality_floor_deg\": ", out);
    plateau_cli_json_number(out, p->quality_floor_deg);
    fprintf(out, ", \"below_floor_triangles\": %lu, \"floor_cause\": ", (unsigned long)p->below_floor_triangles);
    plateau_cli_json_string(out, plateau_floor_string(p->floor_cause));
    fputs(", \"max_abs_beta_deg\": ", out);
    plateau_cli_json_number(out, p->max_abs_beta_deg);
    fprintf(out, ", \"inverted_triangles\": %zu, \"removed_vertices\": %lu",
            p->inverted_triangles, (unsigned long)p->removed_vertices);
    if (!r->minimized) {
        fputs(", \"seeding\": ", out);
        plateau_cli_json_string(out, r->seeding_name ? r->seeding_name : "paper");
    }
    fprintf(out, ", \"interior_points\": %lu, \"cable_vertices\": %lu, \"count_solves\": %lu",
            (unsigned long)p->interior_points, (unsigned long)p->cable_vertices, (unsigned long)p->count_solves);
    if (!r->minimized) { /* what the seeding made */
        fprintf(out, ", \"boundary_points_added\": %lu", (unsigned long)p->boundary_points_added);
        if (p->support_points) fprintf(out, ", \"support_points\": %lu", (unsigned long)p->support_points);
        if (p->sliding_vertices) fprintf(out, ", \"sliding_vertices\": %lu", (unsigned long)p->sliding_vertices);
        fputs(", \"initial_min_angle_deg\": ", out);
        plateau_cli_json_number(out, p->initial_min_angle_deg);
    }
    fputs(", \"stop\": ", out);
    plateau_cli_json_string(out, r->stop_string);
    plateau_cli_print_json_check(out, p);
    fprintf(out, ", \"pressure\": ");
    plateau_cli_json_number(out, p->pressure);
    fprintf(out, ", \"volume\": ");
    plateau_cli_json_number(out, p->volume);
    fputs(", \"volume_significand\": ", out);
    plateau_cli_json_number(out, p->volume_significand);
    fprintf(out, ", \"volume_exponent\": %d", p->volume_exponent);
    if (!r->minimized) { /* cables come from a boundary file */
        size_t c;
        fprintf(out, ", \"cables\": [");
        for (c = 0; c < p->cables && c < PLATEAU_REPORT_CABLES; c++) {
            fprintf(out, "%s{\"tension\": ", c ? ", " : "");
            plateau_cli_json_number(out, p->cable[c].tension);
            fprintf(out, ", \"length\": ");
            plateau_cli_json_number(out, p->cable[c].length);
            fprintf(out, ", \"sag\": ");
            plateau_cli_json_number(out, p->cable[c].sag);
            fprintf(out, "}");
        }
        fprintf(out, "], \"cables_total\": %lu", (unsigned long)p->cables);
        if (p->cables > PLATEAU_REPORT_CABLES)
            fprintf(out, ", \"cables_note\": \"the first %d of %lu cables: the library's report holds "
                         "PLATEAU_REPORT_CABLES\"", PLATEAU_REPORT_CABLES, (unsigned long)p->cables);
    }
    plateau_cli_print_json_status(out, r, r->boundary_length);
    fputs(", \"elapsed_s\": ", out);
    plateau_cli_json_number(out, r->elapsed_s);
    if (r->mesh_path) {
        fputs(", \"mesh_file\": ", out);
        plateau_cli_json_string(out, r->mesh_path);
    }
    if (r->svg_path) {
        fputs(", \"svg_file\": ", out);
        plateau_cli_json_string(out, r->svg_path);
    }
    plateau_cli_print_json_pattern(out, r);
    fputs("}\n", out);
}

/* The summary's line of the final check: "valid", or the counts. */
static void plateau_cli_print_check(FILE *out, const plateau_report *p)
{
    if (!p->defects) {
        fprintf(out, "  check      valid\n");
        return;
    }
    fprintf(out, "  check      DEFECTS: %zu inverted, %lu folded edges, %lu degenerate, "
                 "%lu intersecting pairs%s, solver %s\n",
            p->inverted_triangles, (unsigned long)p->folded_edges,
            (unsigned long)p->degenerate_triangles, (unsigned long)p->intersecting_pairs,
            p->check_cut ? " (search cut by the time limit)" : "", p->solved ? "at its stopping rule" : "short of its stopping rule");
}

/* The warning for a mesh with defects (exit status 3), in words. */
PLATEAU_CLI_FN void plateau_cli_print_warning(FILE *errout, const char *input, const plateau_report *p)
{
    char words[320];
    fprintf(errout, "plateau: warning: %s: the mesh is not valid: %s\n", input ? input : "",
            plateau_defects_string(p->defects, words, sizeof words));
    if (p->stop == PLATEAU_STOP_PINCHED)
        fprintf(errout, "plateau: %s: the film between the two loops pinched: its neck shrank to "
                        "%.3f of the shorter loop, so no connected minimal surface spans them "
                        "(two coaxial rings farther apart than 1.3255 radii carry no catenoid; "
                        "the least area is one disk in each loop)\n",
                input ? input : "", p->neck_ratio);
}

/* 1 when the run seeds by Delaunay refinement, which draws nothing at
 * random: several loops always; one loop with --seeding quality or
 * --edge-length, or by default (PLATEAU_SEEDING_AUTO) when n >= m / 4 (n
 * defaults to m).  The
 * library's automatic choice falls back to the fan where the refinement
 * gives fewer than n / 2 points; the report does not say so, so this rule
 * does not see that case. */
PLATEAU_CLI_FN int plateau_cli_quality_seeding(const plateau_cli_args *a, size_t m, size_t loops)
{
    size_t n = a->n ? a->n : m;
    return loops > 1 || a->seeding == PLATEAU_SEEDING_QUALITY || a->edge_length > 0.0 ||
           (a->seeding == PLATEAU_SEEDING_AUTO && n >= m / 4);
}

/* The warning for a --seed that changes nothing (only the paper's fan
 * seeding draws at random).  Returns 1 when it printed it. */
PLATEAU_CLI_FN int plateau_cli_seed_warning(FILE *errout, const plateau_cli_args *a, size_t m,
                                            size_t loops)
{
    if (!a->have_seed || !plateau_cli_quality_seeding(a, m, loops)) return 0;
    fprintf(errout, "plateau: warning: --seed %llu has no effect: the seeding here is the Delaunay "
                    "refinement (%s), which draws nothing at random; the seed drives only the "
                    "paper's fan seeding (--seeding paper)\n",
            (unsigned long long)a->seed,
            loops > 1                                 ? "always, for several loops"
            : a->seeding == PLATEAU_SEEDING_QUALITY ? "--seeding quality"
            : a->edge_length > 0.0                    ? "--edge-length"
                                                      : "the default when n >= m / 4");
    return 1;
}

/* The warning when the mesh's interior count is more than 3 % away from
 * the n asked with -n (10 % below n = 100, where one point is 1 %), with
 * the reason: the saddle search's splits (which resolve the neck it
 * narrows whatever -n asks, and whether it converged), the seeding's count, or
 * vertices removed as degenerate during the rounds (the library has
 * already run again at a scaled count when that came closer:
 * report.count_solves).  Cable vertices are not counted (the JSON's
 * interior_points counts them, and cable_vertices says how many).
 * Returns 1 when it printed it. */
PLATEAU_CLI_FN int plateau_cli_count_warning(FILE *errout, const char *input, const plateau_cli_args *a,
                                             const plateau_report *p)
{
    /* cable vertices are free but not interior points */
    double n = (double)a->n, got = (double)(p->interior_points - p->cable_vertices);
    double seeded = (double)p->seeded_points, slack = a->n >= 100 ? 0.03 : 0.1;
    if (a->n == 0 || (got >= (1.0 - slack) * n && got <= (1.0 + slack) * n)) return 0;
    fprintf(errout, "plateau: warning: %s: the mesh has %lu interior points, %.0f %% %s than the %lu "
                    "asked (-n)",
            input ? input : "", (unsigned long)(p->interior_points - p->cable_vertices),
            100.0 * (got > n ? got - n : n - got) / n, got > n ? "more" : "fewer", (unsigned long)a->n);
    if (p->cable_vertices)
        fprintf(errout, " (not counting the %lu cable vertices)", (unsigned long)p->cable_vertices);
    if (a->critical_index > 0 && got > 1.1 * seeded)
        fprintf(errout, ": the saddle search split edges where the film bends (its neck), from %lu seeded "
                        "points, %s",
                (unsigned long)p->seeded_points,
                p->critical_converged ? "to resolve it: -n sets the seeding, not these splits"
                                      : "and did not converge");
    else if (p->levels)
        fprintf(errout, ": coarse to fine made it by %lu subdivisions of %lu seeded points "
                        "(--coarse-to-fine off seeds all n at once)",
                (unsigned long)p->levels, (unsigned long)p->seeded_points);
    else if ((double)p->seed_floor > n && seeded > n)
        fprintf(errout, ": the Delaunay refinement's angle bound places %lu along the polygon at the "
                        "spacing -n asks for; -n %lu or more is honoured (--seeding paper draws exactly n, "
                        "with thinner starting triangles)",
                (unsigned long)p->seeded_points, (unsigned long)p->seed_floor);
    else if (seeded < 0.9 * n || seeded > 1.1 * n)
        fprintf(errout, ": the seeding placed %lu; the Delaunay refinement places about n points as "
                        "its angle bound and the polygon's edges allow (--seeding paper draws "
                        "exactly n, with thinner starting triangles)",
                (unsigned long)p->seeded_points);
    if (p->removed_vertices)
        fprintf(errout, "%s %lu were removed as degenerate during the rounds",
                seeded < 0.9 * n || seeded > 1.1 * n ? ";" : ":", (unsigned long)p->removed_vertices);
    fputc('\n', errout);
    return 1;
}

/* The polygon's longest edge over the mesh's mean edge length above which
 * --refine-boundary is advised: below it the quality seeding splits no
 * edge of the polygon, and the advice would give the same mesh. */
#define PLATEAU_CLI_LONG_EDGE 2.0

/* A finer mesh than the run's, as -n: twice the points asked (n, m by
 * default) and twice the points the mesh has (the seeding may place fewer
 * than asked: with a 4-vertex polygon -n 2 places 1), at least m (a
 * polygon's own vertex count gives every method room), at most
 * PLATEAU_CLI_MAX_POINTS; 0 when nothing finer can be asked. */
static size_t plateau_cli_finer(size_t n, size_t got, size_t m)
{
    size_t more = 2 * n > 2 * got ? 2 * n : 2 * got;
    if (more < m) more = m;
    if (more > PLATEAU_CLI_MAX_POINTS) more = PLATEAU_CLI_MAX_POINTS;
    return more > n ? more : 0;
}

/* x to 3 significant digits, rounded towards 0 ("1.41" for 1.41421),
 * into buf. */
static const char *plateau_cli_round_down(double x, char buf[PLATEAU_CLI_NUMBER_SIZE])
{
    double a = x < 0.0 ? -x : x, unit;
    if (!(a > 0.0) || a - a != 0.0) return plateau_cli_number(0.0, buf);
    unit = pow(10.0, floor(log10(a)) - 2.0);
    snprintf(buf, PLATEAU_CLI_NUMBER_SIZE, "%.3g", (x < 0.0 ? -1.0 : 1.0) * floor(a / unit) * unit);
    return buf;
}

/* After a mesh with defects (exit status 3): what to try, on one line
 * "plateau: what to try: A; B; C", each try options with their values
 * (and, in parentheses, why) that can be added to the command line as
 * they are: the advice never repeats what the run used, never names an
 * option that cannot go with the run's (plateau_cli_conflicts), and never
 * leads back to a run that fails the same way (tests/test_cli_run.c,
 * test_advice_followed, runs every piece of it).  What no option does
 * (move the loops, a finer input mesh) is a note in parentheses after it.
 * In order:
 *   pinched: --least-area (the discs are the least-area answer);
 *   a time limit: --max-seconds 0;
 *   a saddle search that did not converge: a finer mesh (-n, or a
 *     shorter --edge-length), not another method (the same coarse mesh
 *     fails the same way);
 *   a pressure above the one a film is known to exist for: that pressure,
 *     2 / R with R the radius of a ball about the boundary's centroid that
 *     holds the boundary (Hildebrandt 1970: a film of mean curvature H
 *     spans a curve inside a ball of radius R when |H| R <= 1; p = 2 H);
 *   else another method, one way only so that advice never loops
 *     (paper-literal: paper or area; paper: area; area: none) unless the
 *     mesh has fewer than 4 interior points (every method gives such a
 *     mesh alike), a finer mesh, and the polygon's edges split
 *     (--refine-boundary, one loop, the quality seeding). */
PLATEAU_CLI_FN void plateau_cli_print_advice(FILE *errout, const plateau_cli_args *a, const plateau_cli_result *r)
{
    const plateau_report *p = &r->report;
    size_t m = r->boundary_vertices, n = a->n, got = p->interior_points - p->cable_vertices, more;
    unsigned geometric = p->defects & ~(unsigned)(PLATEAU_DEFECT_UNSOLVED | PLATEAU_DEFECT_PINCHED);
    char finer[96], num[PLATEAU_CLI_NUMBER_SIZE], num2[PLATEAU_CLI_NUMBER_SIZE], text[400];
    const char *tries[4], *note = NULL;
    int k = 0, i;
    double bound = r->boundary_radius > 0.0 ? 2.0 / r->boundary_radius : 0.0;
    if (n == 0) { /* the library's default count (2 m for the saddle search) */
        plateau_options d;
        memset(&d, 0, sizeof d);
        d.critical_index = a->critical_index;
        n = plateau_resolved_options(&d, m).interior_points;
        /* the saddle search ran again at twice the count each time */
        for (i = 1; a->critical_index > 0 && i < (int)p->count_solves && n < PLATEAU_CLI_MAX_POINTS; i++) n *= 2;
    }
    more = plateau_cli_finer(n, got, m);
    finer[0] = '\0';
    if (a->edge_length > 0.0)
        snprintf(finer, sizeof finer, "--edge-length %s (a finer mesh)", plateau_cli_number(a->edge_length / 2, num));
    else if (more && !r->minimized)
        snprintf(finer, sizeof finer, "-n %lu (a finer mesh)", (unsigned long)more);
    if (p->stop == PLATEAU_STOP_PINCHED) {
        if (!p->membrane && !p->sliding_vertices) /* both refuse --least-area */
            tries[k++] = "--least-area (the two discs, one in each loop, have less area: they are the "
                         "least-area surface)";
        note = "(or loops closer together: coaxial rings at most 1.3255 radii apart carry a connected film)";
    } else if (p->stop == PLATEAU_STOP_TIME_LIMIT) { /* the mesh is unfinished, not wrong */
        snprintf(text, sizeof text, "--max-seconds 0 (no time limit; or one above %s)",
                 plateau_cli_number(a->max_seconds, num));
        tries[k++] = text;
    } else if (a->critical_index > 0 && !p->critical_converged) {
        fprintf(errout, "plateau: no critical point of index %d was found: the saddle search stopped after %lu "
                        "steps without converging", a->critical_index, (unsigned long)p->critical_steps);
        if (a->n == 0 && p->count_solves > 1)
            fprintf(errout, " (in the last of %lu runs, each at twice the points of the one before, up to %lu)",
                    (unsigned long)p->count_solves, (unsigned long)n);
        fputc('\n', errout);
        if (finer[0]) tries[k++] = finer;
        note = r->minimized ? "(the saddle search needs a finer mesh than the one given: its neck narrows)"
                            : "(the saddle search needs more points than the minimum: its neck narrows)";
    } else if (a->pressure != 0.0 && !a->fix_volume && bound > 0.0 && (a->pressure > bound || a->pressure < -bound)) {
        snprintf(text, sizeof text, "--pressure %s (%s film of pressure %s %s this frame; one does for a pressure "
                 "up to 2 / R = %.4g, R = %.4g the largest distance of a boundary vertex from their centroid; or hold "
                 "a volume with --volume)",
                 plateau_cli_round_down(a->pressure > 0.0 ? bound : -bound, num),
                 p->defects & PLATEAU_DEFECT_NO_EQUILIBRIUM ? "no" : "a", plateau_cli_number(a->pressure, num2),
                 p->defects & PLATEAU_DEFECT_NO_EQUILIBRIUM ? "spans" : "may not span", bound,
                 r->boundary_radius);
        tries[k++] = text;
    } else {
        if (got >= 4 || r->minimized) {
            if (a->method == PLATEAU_METHOD_PAPER_LITERAL)
                tries[k++] = "--method paper or --method area (paper-literal is the paper as printed, with no remedy "
                             "for its slivers and folds)";
            else if (a->method == PLATEAU_METHOD_PAPER)
                tries[k++] = "--method area (least area: its flips only ever lower the area)";
        }
        if (finer[0]) tries[k++] = finer;
        /* not when the default already split the boundary: ON splits the same edges */
        if (geometric && a->refine_boundary != PLATEAU_ON && !p->boundary_points_added && r->loops <= 1 &&
            !r->minimized && plateau_cli_quality_seeding(a, m, r->loops) && r->edge_ratio > PLATEAU_CLI_LONG_EDGE)
            tries[k++] = "--refine-boundary (the seeding may split the polygon's long edges, which method area "
                         "does by itself only where they are over 2 interior spacings)";
        if (a->fix_volume && (p->defects & (PLATEAU_DEFECT_NO_EQUILIBRIUM | PLATEAU_DEFECT_VOLUME)) &&
            a->volume != 0.0) {
            snprintf(text, sizeof text, "--volume %s (a smaller volume: the pressure that holds it is lower)",
                     plateau_cli_number(a->volume / 2, num));
            tries[k++] = text;
        }
        if (r->minimized && geometric) note = "(a finer mesh given may have no defects)";
        else if ((p->defects & PLATEAU_DEFECT_NO_EQUILIBRIUM) && p->cables)
            note = "(cables out of balance: higher tensions in the boundary file)";
    }
    if (k) {
        fputs("plateau: what to try:", errout);
        for (i = 0; i < k; i++) fprintf(errout, "%s %s", i ? ";" : "", tries[i]);
        fputs("\n", errout);
    }
    if (note) fprintf(errout, "plateau: %s\n", note);
    if (p->intersecting_pairs && r->loops <= 1 && !p->membrane && !r->minimized)
        fputs("plateau: (a knotted polygon bounds no embedded film: if yours is knotted, intersecting triangles "
              "cannot be avoided)\n", errout);
}

/* 0 when path can be written, checked before a long solve: an existing
 * file is opened for appending (its contents stay as they are), a new one
 * is created and removed again.  Else 1 with a sentence in msg. */
PLATEAU_CLI_FN int plateau_cli_check_writable(const char *path, const char *what, char *msg,
                                              size_t msg_size)
{
    FILE *f = fopen(path, "rb");
    int existed = f != NULL, e;
    if (f) fclose(f);
    errno = 0;
    f = fopen(path, existed ? "ab" : "wb");
    e = errno;
    if (!f) {
        snprintf(msg, msg_size, "cannot write %s '%.200s'%s%s (nothing was solved)", what, path,
                 e ? ": " : "", e ? strerror(e) : "");
        return 1;
    }
    fclose(f);
    if (!existed) remove(path);
    return 0;
}

/* The summary's line of the error estimate: "area 17.9238 +- 0.0014
 * (estimated, 8.1e-05 relative)", the digits the estimate leaves (a
 * membrane's: of its energy, relative), or why there is none; and the
 * accuracy aimed at. */
static void plateau_cli_print_estimate(FILE *out, const plateau_report *p)
{
    double e = p->area_error_estimate, abs_e = e * p->area;
    int digits = 1;
    if (p->estimate != PLATEAU_ESTIMATE_FORMED || e != e) {
        fprintf(out, "  error      not estimated: %s\n", plateau_estimate_string(p->estimate));
        return;
    }
    if (p->membrane) {
        /* a membrane's is of its energy, relative to the sum of its terms' sizes */
        fprintf(out, "  error      energy A - pV + sum T L: %.1e relative to A + |pV| + sum T L (estimated)", e);
    } else {
        /* the area to the decimal of the estimate's first digit */
        if (abs_e > 0.0 && p->area > 0.0) digits = (int)ceil(-log10(abs_e)) + 1;
        if (digits < 1) digits = 1;
        if (digits > 15) digits = 15;
        fprintf(out, "  error      area %.*f +- %.*f (estimated, %.1e relative)", digits, p->area, digits, abs_e, e);
    }
    if (p->accuracy > 0.0)
        fprintf(out, "; accuracy %.1e asked, %lu solve%s", p->accuracy, (unsigned long)p->accuracy_solves,
                p->accuracy_solves == 1 ? "" : "s");
    /* the refinement stops short only for the reasons the manual's
     * ACCURACY names: say so rather than leave the numbers to disagree */
    if (p->accuracy > 0.0 && e > p->accuracy)
        fprintf(out, "; not reached: %s", plateau_accuracy_stop_string(p->accuracy_stop));
    fputc('\n', out);
}

PLATEAU_CLI_FN void plateau_cli_print_summary(FILE *out, const plateau_cli_result *r)
{
    const plateau_report *p = &r->report;
    fprintf(out, "plateau %s: %s\n", PLATEAU_VERSION, r->input ? r->input : "");
    if (r->minimized) {
        fprintf(out, "  input      a mesh to minimise (--minimize), area %.10g\n", r->initial_area);
        fprintf(out, "  boundary   %lu vertices in %lu loop%s (its edges of one triangle), kept\n",
                (unsigned long)r->boundary_vertices, (unsigned long)r->loops, r->loops == 1 ? "" : "s");
    } else if (p->loops > 1)
        fprintf(out, "  boundary   %lu vertices in %lu loops, %s domain\n",
                (unsigned long)r->boundary_vertices, (unsigned long)p->loops,
                plateau_cli_domain_name(p->domain));
    else
        fprintf(out, "  boundary   %lu vertices, %s domain\n", (unsigned long)r->boundary_vertices,
                plateau_cli_domain_name(p->domain));
    fprintf(out, "  method     %s", r->method_name ? r->method_name : "?");
    if (!r->minimized) fprintf(out, ", seed %llu", (unsigned long long)r->seed);
    if (r->points_requested) fprintf(out, ", %lu interior points asked", (unsigned long)r->points_requested);
    if (r->edge_length > 0.0) {
        char typed[PLATEAU_CLI_NUMBER_SIZE];
        fprintf(out, ", edge length %s asked", plateau_cli_number(r->edge_length, typed));
    }
    fprintf(out, "\n  mesh       %lu vertices, %lu triangles\n", (unsigned long)r->vertices,
            (unsigned long)r->triangles);
    if (r->seeding_name)
        fprintf(out, "  seeding    %s: %lu interior points, %lu added on the boundary, initial "
                     "smallest angle %.2f deg\n",
                r->seeding_name, (unsigned long)p->seeded_points,
                (unsigned long)p->boundary_points_added, p->initial_min_angle_deg);
    if (r->critical_index > 0 && !r->points_requested && p->count_solves > 1)
        fprintf(out, "  runs       %lu (the saddle search ran again at twice the points while it did not "
                     "converge)\n", (unsigned long)p->count_solves);
    if (p->support_points)
        fprintf(out, "  supports   %lu fixed point%s (mesh vertices after the boundary's)\n",
                (unsigned long)p->support_points, p->support_points == 1 ? "" : "s");
    if (p->sliding_vertices)
        fprintf(out, "  sliding    %lu boundary vert%s on planes or lines\n", (unsigned long)p->sliding_vertices,
                p->sliding_vertices == 1 ? "ex" : "ices");
    fprintf(out, "  area       %.10g", p->area);
    if (p->range & (PLATEAU_RANGE_AREA_OVERFLOW | PLATEAU_RANGE_AREA_UNDERFLOW))
        fprintf(out, " (beyond a double: %.10g x 2^%d)", p->area_significand, p->area_exponent);
    fputc('\n', out);
    plateau_cli_print_estimate(out, p);
    if (plateau_cli_f_known(p)) fprintf(out, "  F          %.3e (initial %.3e)\n", p->f_final, p->f_initial);
    else fprintf(out, "  F          not computed: no solve of the method ran on this mesh\n");
    fprintf(out, "  work       %zu rounds, %zu iterations, %zu evaluations, %zu flips\n", p->rounds,
            p->iterations, p->evaluations, p->flips);
    if (p->levels)
        fprintf(out, "  levels     coarse to fine: %zu subdivisions of a coarse mesh of %zu interior points\n",
                p->levels, p->seeded_points);
    fprintf(out, "  angles     smallest %.2f deg, largest %.2f deg", p->min_angle_deg, p->max_angle_deg);
    if (p->below_floor_triangles)
        fprintf(out, "; %lu triangles below the quality floor %.2f deg: %s",
                (unsigned long)p->below_floor_triangles, p->quality_floor_deg, plateau_floor_string(p->floor_cause));
    fputc('\n', out);
    fprintf(out, "  folds      largest |dihedral| %.2f deg, %zu inverted triangles\n",
            p->max_abs_beta_deg, p->inverted_triangles);
    fprintf(out, "  stop       %s\n", r->stop_string ? r->stop_string : "?");
    if (p->pressure != 0.0 || p->volume != 0.0) {
        char typed[PLATEAU_CLI_NUMBER_SIZE];
        if (r->pressure_typed) plateau_cli_number(p->pressure, typed);
        else snprintf(typed, sizeof typed, "%.10g", p->pressure);
        fprintf(out, "  membrane   pressure %s, volume %.10g", typed, p->volume);
        if (p->range & (PLATEAU_RANGE_VOLUME_OVERFLOW | PLATEAU_RANGE_VOLUME_UNDERFLOW))
            fprintf(out, " (beyond a double: %.10g x 2^%d)", p->volume_significand, p->volume_exponent);
        fputc('\n', out);
    }
    {
        size_t c;
        for (c = 0; c < p->cables && c < PLATEAU_REPORT_CABLES; c++)
            fprintf(out, "  cable %-4lu tension %.6g, length %.10g, sag %.10g\n", (unsigned long)c + 1,
                    p->cable[c].tension, p->cable[c].length, p->cable[c].sag);
    }
    if (p->loops == 2)
        fprintf(out, "  neck       %.4f of the shorter loop%s\n", p->neck_ratio,
                p->stop == PLATEAU_STOP_PINCHED ? ": PINCHED, no connected minimal film spans the loops" : "");
    if (plateau_cli_stability_note(r)) {
        fprintf(out, "  stability  %s", plateau_cli_stability_note(r));
        if (p->stability.computed && r->boundary_length > 0.0)
            fprintf(out, " (area gradient %.3e L)", p->stability.area_gradient_norm / r->boundary_length);
        fputc('\n', out);
    } else if (p->stability.computed) {
        /* scale-free: the gradient (a length) over L, the eigenvalues
         * (1 / length^2) times L^2, so that a film in millimetres reads as
         * the same film in metres */
        size_t q;
        double L = r->boundary_length;
        fprintf(out, "  stability  index %lu (%s), area gradient %.3e L, lowest eigenvalues",
                (unsigned long)p->stability.index,
                p->stability.index ? "a saddle of the area: it falls along that many normal motions"
                                   : "no normal motion lowers the area",
                L > 0.0 ? p->stability.area_gradient_norm / L : 0.0);
        for (q = 0; q < p->stability.num_eigenvalues; q++)
            fprintf(out, " %.4g", p->stability.lowest_eigenvalues[q] * L * L);
        /* a clustered spectrum (a long strip) can leave every Ritz value short of the test */
        if (p->stability.num_eigenvalues == 0) fputs(" none converged", out);
        else fputs(" / L^2", out);
        fprintf(out, " (L = %.6g, the boundary's length)\n", L);
    }
    if (p->alternative_area > 0.0)
        fprintf(out, "  topology   film %.10g, two discs %.10g: %s\n", p->film_area, p->alternative_area,
                p->discs_returned ? "the discs have less area and are returned"
                : p->film_not_least && p->stability.computed && p->stability.index > 0
                    ? "the film returned is a saddle of the area; the two discs have less area"
                : p->film_not_least ? "the film returned is only a local minimum; the two discs have less area"
                : p->film_area > p->alternative_area
                    ? "the rounds' film has less area than the discs; the film returned (the critical point "
                      "asked for) has more"
                                    : "the film has the least area");
    plateau_cli_print_check(out, p);
    fprintf(out, "  elapsed    %.3f s\n", r->elapsed_s);
    if (r->mesh_path) fprintf(out, "  mesh file  %s\n", r->mesh_path);
    if (r->svg_path) fprintf(out, "  picture    %s\n", r->svg_path);
    plateau_cli_print_summary_pattern(out, r);
}

#endif /* PLATEAU_CLI_H */
