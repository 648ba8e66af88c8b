/* plateau.h - minimal triangle meshes spanning a closed 3-D polygon (the
 * Plateau-Mesh problem), after "Constructing Minimal Triangular Mesh Based on
 * Discrete Mean Curvature" (see README.md for the paper and our notes).
 *
 * DO THIS in exactly one C or C++ file:
 *     #define PLATEAU_IMPLEMENTATION
 *     #include "plateau.h"
 * That one define switches on the implementations of plateau.h,
 * plateau_lm.h and plateau_delaunay.h (which plateau.h includes).  Other files
 * just include plateau.h.
 *
 * [documentation, example and configuration table: issues 4 and 5]
 */
#ifndef PLATEAU_H
#define PLATEAU_H

#define PLATEAU_VERSION "0.1.0"
#define PLATEAU_VERSION_NUM 100 /* major * 10000 + minor * 100 + patch */

#include "plateau_lm.h"
#include "plateau_delaunay.h"

#if PLATEAU_LM_VERSION_NUM != PLATEAU_VERSION_NUM
#error "plateau.h and plateau_lm.h are from different versions"
#endif
#if PLATEAU_DELAUNAY_VERSION_NUM != PLATEAU_VERSION_NUM
#error "plateau.h and plateau_delaunay.h are from different versions"
#endif

#ifndef PLATEAU_DEF
#ifdef PLATEAU_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_DEF static __attribute__((unused))
#else
#define PLATEAU_DEF static
#endif
#else
#define PLATEAU_DEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Result codes: one X-macro list gives the enum and the messages ---- */
#define PLATEAU_RESULT_LIST(X)                                                        \
    X(PLATEAU_OK, 0, "success")                                                       \
    X(PLATEAU_ERR_ARGUMENT, -1, "invalid argument (NULL pointer, zero count or bad option)") \
    X(PLATEAU_ERR_NO_MEMORY, -2, "out of memory")                                      \
    X(PLATEAU_ERR_OVERFLOW, -3, "a size computation overflowed")                       \
    X(PLATEAU_ERR_NOT_FINITE, -4, "a coordinate is NaN or infinite")                   \
    X(PLATEAU_ERR_TOO_FEW_VERTICES, -5, "the polygon has fewer than 3 vertices")       \
    X(PLATEAU_ERR_REPEATED_VERTEX, -6, "two consecutive polygon vertices are equal")   \
    X(PLATEAU_ERR_COLLINEAR, -7, "all polygon vertices are collinear")                 \
    X(PLATEAU_ERR_INDEX_RANGE, -8, "a vertex index is out of range")                   \
    X(PLATEAU_ERR_DEGENERATE_TRIANGLE, -9, "a triangle repeats a vertex")               \
    X(PLATEAU_ERR_NON_MANIFOLD, -10, "an edge has more than two triangles")            \
    X(PLATEAU_ERR_ORIENTATION, -11, "neighbouring triangles are oriented inconsistently") \
    X(PLATEAU_ERR_TRIANGULATION, -12, "the planar triangulation failed")               \
    X(PLATEAU_ERR_SOLVER, -13, "the optimiser failed")                                \
    X(PLATEAU_ERR_ABORTED, -14, "a callback asked to stop")                            \
    X(PLATEAU_ERR_IO, -15, "a file could not be written or read")                     \
    X(PLATEAU_ERR_PARSE, -16, "a line of the input could not be parsed")

typedef enum plateau_result {
#define PLATEAU__ENUM(name, value, text) name = value,
    PLATEAU_RESULT_LIST(PLATEAU__ENUM)
#undef PLATEAU__ENUM
    PLATEAU__RESULT_END = 1
} plateau_result;

/* Detail for a failed call, written by the calls that take one (may be NULL). */
typedef struct plateau_error {
    plateau_result code;
    long index;        /* the offending vertex, triangle or line; -1 if none */
    char message[160]; /* one sentence, e.g. "boundary vertices 3 and 4 are equal" */
} plateau_error;

PLATEAU_DEF const char *plateau_result_string(plateau_result result);

/* ======== SECTION: mesh and geometry kernel (issue 4) ======================
 * A triangle mesh owning its arrays.  The pinned fields below are what the
 * rest of the library reads; the kernel may add adjacency fields after them. */
typedef struct plateau_mesh {
    size_t num_vertices;
    double *positions;        /* 3 * num_vertices: x, y, z */
    unsigned char *fixed;     /* num_vertices: 1 = fixed (boundary), 0 = free */
    size_t num_triangles;
    plateau_index *triangles; /* 3 * num_triangles, consistently oriented */
    plateau_index *neighbors; /* 3 * num_triangles: across edge (v_k, v_(k+1)%3), -1 = boundary */
    plateau_allocator allocator;
    /* [adjacency added by issue 4] */
} plateau_mesh;
/* Pinned: frees every array of the mesh and zeroes it; accepts an all-zero mesh. */
PLATEAU_DEF void plateau_mesh_free(plateau_mesh *mesh);
/* [kernel declarations: issue 4] */
/* ======== END SECTION: mesh and geometry kernel ======================== */

/* ======== SECTION: boundary, parameter domain and seeding (issue 5, part A) */
/* Pinned contract (part A implements, part B calls):
 *
 * A seeded generator of our own (never rand()): same seed, same sequence. */
typedef struct plateau_rng { uint64_t state; } plateau_rng;
PLATEAU_DEF void plateau_rng_seed(plateau_rng *rng, uint64_t seed);
PLATEAU_DEF uint64_t plateau_rng_next(plateau_rng *rng);
PLATEAU_DEF double plateau_rng_uniform(plateau_rng *rng); /* in [0, 1) */

typedef enum plateau_domain_kind {
    PLATEAU_DOMAIN_PLANE = 0, /* projection on the best-fit plane (simple) */
    PLATEAU_DOMAIN_CIRCLE = 1 /* boundary mapped on a circle by chord length */
} plateau_domain_kind;

/* Step 1: m >= 3 vertices, all finite, no two consecutive equal, not all
 * collinear (the polygon closes implicitly).  err may be NULL. */
PLATEAU_DEF plateau_result plateau_boundary_check(const double *xyz, size_t m,
                                                  plateau_error *err);
/* Step 2: planar parameter domain; uv gets 2 * m values.  force_circle != 0
 * skips the plane.  allocator may be NULL. */
PLATEAU_DEF plateau_result plateau_boundary_domain(const double *xyz, size_t m,
                                                   int force_circle,
                                                   const plateau_allocator *allocator,
                                                   double *uv, plateau_domain_kind *kind,
                                                   plateau_error *err);
/* Step 3: n interior candidate points (paper section II.A), in 3-D (xyz_out,
 * 3 * n) and in the domain (uv_out, 2 * n); *count gets how many were
 * produced (n unless the polygon is too thin to hold them). */
PLATEAU_DEF plateau_result plateau_seed_points(const double *xyz, const double *uv, size_t m,
                                               size_t n, uint64_t seed,
                                               const plateau_allocator *allocator,
                                               double *xyz_out, double *uv_out,
                                               size_t *count, plateau_error *err);
/* ======== END SECTION: boundary, parameter domain and seeding =========== */

/* ======== SECTION: solver pipeline (issue 5, part B) ====================== */
/* Pinned contract (part B implements; the CLI and examples call it; part B
 * may add fields after the pinned ones). */
typedef enum plateau_method {
    PLATEAU_METHOD_PAPER = 0,         /* interior H_i + tangential condition, 3-D flips */
    PLATEAU_METHOD_PAPER_LITERAL = 1, /* the paper as printed, for teaching */
    PLATEAU_METHOD_AREA = 2           /* area minimisation (Chen, Cai and Zheng) */
} plateau_method;

typedef struct plateau_options {
    /* all-zero means the documented defaults */
    plateau_method method;
    size_t interior_points; /* n; 0 -> documented default */
    uint64_t seed;          /* 0 -> fixed default seed */
    int max_rounds;         /* 0 -> documented default */
    int force_circle_domain;
    /* progress: called per LM / quasi-Newton iteration; non-zero aborts */
    int (*progress)(int round, int iteration, double f, void *user);
    void *progress_user;
    plateau_allocator allocator;
} plateau_options;

typedef struct plateau_report {
    plateau_method method;
    plateau_domain_kind domain;
    int rounds;
    int iterations;   /* LM or quasi-Newton iterations, all rounds */
    int evaluations;  /* residual (or area) evaluations, all rounds */
    double f_initial, f_final; /* the method's objective */
    double area;
    double min_angle_deg, max_angle_deg;
    double max_abs_beta_deg; /* largest |dihedral angle|: fold check */
    int inverted_triangles;
    int flips;
    int stop;             /* why the rounds ended; see plateau_stop_string */
} plateau_report;

/* Closed polygon (m vertices, xyz) in, minimal mesh out.  The mesh's first m
 * vertices are the boundary, unchanged and fixed.  options, report, err may
 * be NULL.  Free the mesh with plateau_mesh_free (also after an error). */
PLATEAU_DEF plateau_result plateau_solve(const double *boundary, size_t m,
                                         const plateau_options *options,
                                         plateau_mesh *mesh, plateau_report *report,
                                         plateau_error *err);
PLATEAU_DEF const char *plateau_method_name(plateau_method method);
PLATEAU_DEF const char *plateau_stop_string(int stop);
/* ======== END SECTION: solver pipeline =================================== */

/* ======== SECTION: mesh input and output (issue 5, part A) =============== */
/* Pinned contract (part A).  Writers take plain arrays so any mesh works. */
/* OBJ, PLY (ASCII) or OFF, chosen by the path's extension. */
PLATEAU_DEF plateau_result plateau_write_mesh(const char *path, const double *positions,
                                              size_t num_vertices,
                                              const plateau_index *triangles,
                                              size_t num_triangles, plateau_error *err);
/* Boundary text: one vertex per line "x y z", '#' comments, blank lines.
 * *xyz is allocated through allocator (may be NULL); free with the same. */
PLATEAU_DEF plateau_result plateau_parse_boundary(const char *text, size_t length,
                                                  const plateau_allocator *allocator,
                                                  double **xyz, size_t *m,
                                                  plateau_error *err);
/* ======== END SECTION: mesh input and output ============================ */

#ifdef __cplusplus
}
#endif
#endif /* PLATEAU_H */

/* ======================================================================== */
#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_IMPLEMENTED)
#define PLATEAU_IMPLEMENTED

/* ---- Shared by every plateau header (identical copies, guarded) -------- */
#ifndef PLATEAU_COMMON_IMPLEMENTED
#define PLATEAU_COMMON_IMPLEMENTED
#if defined(__FAST_MATH__)
#error "plateau needs IEEE-754 double arithmetic: do not compile it with -ffast-math"
#endif
#if (defined(PLATEAU_MALLOC) && !defined(PLATEAU_FREE)) || \
    (!defined(PLATEAU_MALLOC) && defined(PLATEAU_FREE))
#error "plateau: define both PLATEAU_MALLOC and PLATEAU_FREE, or neither"
#endif
#ifndef PLATEAU_MALLOC
#include <stdlib.h>
#define PLATEAU_MALLOC(size, ctx) ((void)(ctx), malloc(size))
#define PLATEAU_FREE(ptr, ctx) ((void)(ctx), free(ptr))
#endif
#ifndef PLATEAU_ASSERT
#include <assert.h>
#define PLATEAU_ASSERT(x) assert(x) /* internal invariants only, never input */
#endif
#include <math.h>
#ifndef PLATEAU_SQRT
#define PLATEAU_SQRT(x) sqrt(x)
#endif
#ifndef PLATEAU_FABS
#define PLATEAU_FABS(x) fabs(x)
#endif
#ifndef PLATEAU_ATAN2
#define PLATEAU_ATAN2(y, x) atan2(y, x)
#endif
#ifndef PLATEAU_COS
#define PLATEAU_COS(x) cos(x)
#endif
#ifndef PLATEAU_SIN
#define PLATEAU_SIN(x) sin(x)
#endif
#ifndef PLATEAU_LOG
#define PLATEAU_LOG(x) log(x)
#endif

/* Allocation through the run-time allocator if it has functions, else the
 * PLATEAU_MALLOC / PLATEAU_FREE macros with the allocator's user_data. */
static inline void *plateau__alloc(const plateau_allocator *a, size_t size)
{
    if (size == 0) size = 1;
    if (a && a->alloc_fn) return a->alloc_fn(size, a->user_data);
    return PLATEAU_MALLOC(size, a ? a->user_data : NULL);
}
static inline void plateau__free(const plateau_allocator *a, void *ptr)
{
    if (!ptr) return;
    if (a && a->free_fn) { a->free_fn(ptr, a->user_data); return; }
    PLATEAU_FREE(ptr, a ? a->user_data : NULL);
}
/* count * size in bytes, or 0 on overflow (callers treat 0 as failure). */
static inline size_t plateau__bytes(size_t count, size_t size)
{
    if (size != 0 && count > (size_t)-1 / size) return 0;
    return count * size;
}
/* 1 when the allocator has both functions or neither (the only valid forms). */
static inline int plateau__allocator_valid(const plateau_allocator *a)
{
    return !a || ((a->alloc_fn == NULL) == (a->free_fn == NULL));
}
#endif /* PLATEAU_COMMON_IMPLEMENTED */

PLATEAU_DEF const char *plateau_result_string(plateau_result result)
{
    switch (result) {
#define PLATEAU__CASE(name, value, text) case name: return text;
        PLATEAU_RESULT_LIST(PLATEAU__CASE)
#undef PLATEAU__CASE
    default: break;
    }
    return "unknown plateau result code";
}

/* ======== SECTION: mesh and geometry kernel (issue 4) implementation ===== */
/* ======== END SECTION: mesh and geometry kernel implementation ========== */

/* ======== SECTION: boundary, parameter domain and seeding implementation */
/* ======== END SECTION: boundary, parameter domain and seeding impl ====== */

/* ======== SECTION: solver pipeline implementation ======================== */
/* ======== END SECTION: solver pipeline implementation =================== */

/* ======== SECTION: mesh input and output implementation ================== */
/* ======== END SECTION: mesh input and output implementation ============= */

#endif /* PLATEAU_IMPLEMENTATION */
