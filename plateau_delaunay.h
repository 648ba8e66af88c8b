/* plateau_delaunay.h - robust incremental constrained Delaunay
 * triangulation in the plane (step 2 of the Plateau-Mesh method).
 * Part of plateau; stands alone: needs no other header of the project.
 *
 * DO THIS in exactly one C or C++ file:
 *     #define PLATEAU_DELAUNAY_IMPLEMENTATION
 *     #include "plateau_delaunay.h"
 * (PLATEAU_IMPLEMENTATION also switches it on.)  Other files just include it.
 *
 * [documentation, example and configuration table: see issue 3]
 */
#ifndef PLATEAU_DELAUNAY_H
#define PLATEAU_DELAUNAY_H

#define PLATEAU_DELAUNAY_VERSION "0.1.0"
#define PLATEAU_DELAUNAY_VERSION_NUM 100 /* major * 10000 + minor * 100 + patch */

/* ---- Shared by every plateau header (identical copies, guarded) -------- */
#ifndef PLATEAU_COMMON_DECLARED
#define PLATEAU_COMMON_DECLARED
#include <stddef.h>
#include <stdint.h>

/* Vertex and triangle indices: a 32-bit signed type, -1 meaning "none".
 * Counts and byte sizes are size_t. */
#ifndef PLATEAU_INDEX_TYPE
#define PLATEAU_INDEX_TYPE int32_t
#define PLATEAU_INDEX_MAX INT32_MAX
#endif
typedef PLATEAU_INDEX_TYPE plateau_index;

/* A run-time allocator.  All-zero means: use PLATEAU_MALLOC / PLATEAU_FREE
 * (malloc and free unless you defined them), with user_data as their context.
 * Set both functions or neither. */
typedef struct plateau_allocator {
    void *(*alloc_fn)(size_t size, void *user_data);
    void (*free_fn)(void *ptr, void *user_data);
    void *user_data;
} plateau_allocator;
#endif /* PLATEAU_COMMON_DECLARED */

#ifndef PLATEAU_DT_DEF
#ifdef PLATEAU_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_DT_DEF static __attribute__((unused))
#else
#define PLATEAU_DT_DEF static
#endif
#else
#define PLATEAU_DT_DEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- API contract (the pipeline in plateau.h is written against it) ---- */
typedef enum plateau_dt_result {
    PLATEAU_DT_OK = 0
    /* errors: see the implementation issue */
} plateau_dt_result;

typedef struct plateau_dt_input {
    const double *points;          /* 2 * num_points: x0, y0, x1, y1, ... */
    size_t num_points;
    const plateau_index *segments; /* 2 * num_segments: constraint edges */
    size_t num_segments;
} plateau_dt_input;

typedef struct plateau_dt_options {
    /* all-zero means the documented defaults */
    int keep_convex_hull; /* 0: keep only triangles inside the closed
                             constraint loops (outer boundary minus holes);
                             when there are no segments, the hull is kept */
    plateau_allocator allocator;
} plateau_dt_options;

/* The output.  Vertex i < num_input_points is input point i (a duplicate
 * input point appears in no triangle; duplicate_of[i] names the one kept,
 * = i otherwise).  Points added by the library follow the input points. */
typedef struct plateau_dt_mesh {
    size_t num_points;
    double *points;               /* 2 * num_points */
    size_t num_input_points;
    plateau_index *duplicate_of;  /* num_input_points */
    size_t num_triangles;
    plateau_index *triangles;     /* 3 * num_triangles, counter-clockwise */
    plateau_index *neighbors;     /* 3 * num_triangles: neighbors[3t+k] is the
                                     triangle across edge (v_k, v_(k+1)%3)
                                     of triangle t, -1 if none */
    unsigned char *constrained;   /* 3 * num_triangles: 1 if that edge is a
                                     (piece of a) constraint segment */
    plateau_allocator allocator;  /* the one that allocated the arrays */
} plateau_dt_mesh;

typedef struct plateau_dt_report {
    long index;          /* the offending point or segment, -1 if none */
    char message[160];   /* a sentence saying what was wrong */
} plateau_dt_report;

/* options and report may be NULL.  On error the mesh is left empty (all
 * zero) and plateau_dt_free accepts it. */
PLATEAU_DT_DEF plateau_dt_result plateau_dt_triangulate(const plateau_dt_input *input,
                                                        const plateau_dt_options *options,
                                                        plateau_dt_mesh *mesh,
                                                        plateau_dt_report *report);
PLATEAU_DT_DEF void plateau_dt_free(plateau_dt_mesh *mesh);
PLATEAU_DT_DEF const char *plateau_dt_result_string(plateau_dt_result result);

#ifdef __cplusplus
}
#endif
#endif /* PLATEAU_DELAUNAY_H */

/* ======================================================================== */
#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_DELAUNAY_IMPLEMENTATION)
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#endif
#if defined(PLATEAU_DELAUNAY_IMPLEMENTATION) && !defined(PLATEAU_DELAUNAY_IMPLEMENTED)
#define PLATEAU_DELAUNAY_IMPLEMENTED

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

/* [implementation: issue 3] */

#endif /* PLATEAU_DELAUNAY_IMPLEMENTATION */
