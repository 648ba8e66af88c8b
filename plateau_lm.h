/* plateau_lm.h - dense Levenberg-Marquardt nonlinear least squares, after
 * Madsen, Nielsen and Tingleff, "Methods for non-linear least squares
 * problems" (IMM, DTU, 2004), as used in step 3 of the Plateau-Mesh method.
 * Part of plateau; stands alone: needs no other header of the project.
 *
 * DO THIS in exactly one C or C++ file:
 *     #define PLATEAU_LM_IMPLEMENTATION
 *     #include "plateau_lm.h"
 * (PLATEAU_IMPLEMENTATION also switches it on.)  Other files just include it.
 *
 * [documentation, example and configuration table: see issue 2]
 */
#ifndef PLATEAU_LM_H
#define PLATEAU_LM_H

#define PLATEAU_LM_VERSION "0.1.0"
#define PLATEAU_LM_VERSION_NUM 100 /* major * 10000 + minor * 100 + patch */

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

#ifndef PLATEAU_LM_DEF
#ifdef PLATEAU_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_LM_DEF static __attribute__((unused))
#else
#define PLATEAU_LM_DEF static
#endif
#else
#define PLATEAU_LM_DEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- API contract (the pipeline in plateau.h is written against it) ----
 * Result codes: 0 = OK, negative = error; names and messages come from one
 * X-macro list so they never drift. */
typedef enum plateau_lm_result {
    PLATEAU_LM_OK = 0
    /* errors: see the implementation issue */
} plateau_lm_result;

/* Residual callback: evaluate f(x) (m values) into f; if jac is not NULL,
 * also the Jacobian, row-major m x n: jac[i * n + j] = d f_i / d x_j.
 * Return 0 to go on, non-zero to abort the solve. */
typedef int (*plateau_lm_func)(const double *x, double *f, double *jac, void *user);

typedef struct plateau_lm_options {
    /* all-zero means the documented defaults */
    double tau;        /* mu0 = tau * max diag(J^T J); 0 -> 1e-6 (the paper) */
    double eps;        /* 0 -> 1e-6 (the paper's epsilon) */
    int max_iterations;/* 0 -> documented default */
    int numeric_jacobian; /* non-zero: the callback never gets jac; forward differences */
    plateau_allocator allocator;
    /* per-iteration callback etc.: see the implementation issue */
} plateau_lm_options;

typedef struct plateau_lm_report {
    int iterations;
    int residual_evaluations;
    int jacobian_evaluations;
    double f_initial, f_final; /* F = 1/2 ||f||^2 */
    double grad_inf;           /* ||J^T f||_inf at the end */
    double mu_final;
    int stop;                  /* a plateau_lm_stop value */
} plateau_lm_report;

/* Minimise F(x) = 1/2 ||f(x)||^2, f: R^n -> R^m (m < n allowed).  x (n
 * values) is the start on entry and the solution on return.  options and
 * report may be NULL.  work/work_bytes: a caller-owned workspace of at least
 * plateau_lm_workspace_size(m, n, options) bytes, or NULL to allocate. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_solve(size_t m, size_t n, double *x,
                                                  plateau_lm_func func, void *user,
                                                  const plateau_lm_options *options,
                                                  void *work, size_t work_bytes,
                                                  plateau_lm_report *report);
PLATEAU_LM_DEF size_t plateau_lm_workspace_size(size_t m, size_t n,
                                                const plateau_lm_options *options);
PLATEAU_LM_DEF const char *plateau_lm_result_string(plateau_lm_result result);

#ifdef __cplusplus
}
#endif
#endif /* PLATEAU_LM_H */

/* ======================================================================== */
#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_LM_IMPLEMENTATION)
#define PLATEAU_LM_IMPLEMENTATION
#endif
#if defined(PLATEAU_LM_IMPLEMENTATION) && !defined(PLATEAU_LM_IMPLEMENTED)
#define PLATEAU_LM_IMPLEMENTED

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

/* [implementation: issue 2] */

#endif /* PLATEAU_LM_IMPLEMENTATION */
