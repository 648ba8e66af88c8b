/* plateau_lm.h - dense Levenberg-Marquardt nonlinear least squares, after
 * Madsen, Nielsen and Tingleff, "Methods for non-linear least squares
 * problems" (IMM, DTU, 2004), as used in step 3 of the Plateau-Mesh method.
 * Part of plateau; stands alone: needs no other header of the project.
 * Version 0.1.0.  MIT licence (see the end of the file).
 *
 * DO THIS in exactly one C or C++ file:
 *     #define PLATEAU_LM_IMPLEMENTATION
 *     #include "plateau_lm.h"
 * (PLATEAU_IMPLEMENTATION also switches it on.)  Other files just include it.
 * Define PLATEAU_STATIC first to give every function internal linkage.
 *
 * WHAT IT DOES
 *   Minimises F(x) = 1/2 ||f(x)||^2 for f: R^n -> R^m, any m and n (also
 *   m < n, which levmar and MINPACK refuse).  You give a callback computing f
 *   and, when asked, the Jacobian J (m x n, row-major); or set
 *   numeric_jacobian and the solver builds J by forward differences.
 *
 * EXAMPLE (complete: fits y = a exp(-b t) to four points)
 *     #define PLATEAU_LM_IMPLEMENTATION
 *     #include "plateau_lm.h"
 *     #include <math.h>
 *     #include <stdio.h>
 *     static const double T[4] = {0, 1, 2, 3}, Y[4] = {5.0, 3.0, 1.8, 1.1};
 *     static int decay(const double *x, double *f, double *jac, void *user)
 *     {
 *         int i;
 *         (void)user;
 *         for (i = 0; i < 4; i++) {
 *             double e = exp(-x[1] * T[i]);
 *             f[i] = x[0] * e - Y[i];
 *             if (jac) { jac[2 * i] = e; jac[2 * i + 1] = -x[0] * T[i] * e; }
 *         }
 *         return 0;
 *     }
 *     int main(void)
 *     {
 *         double x[2] = {1.0, 0.1};
 *         plateau_lm_report rep;
 *         plateau_lm_result r = plateau_lm_solve(4, 2, x, decay, NULL, NULL, NULL, 0, &rep, NULL);
 *         printf("%s: a = %g, b = %g, F = %g (%s)\n", plateau_lm_result_string(r), x[0],
 *                x[1], rep.f_final, plateau_lm_stop_string((plateau_lm_stop)rep.stop));
 *         return r == PLATEAU_LM_OK ? 0 : 1;
 *     }
 *
 * CONFIGURATION (define before including the implementation)
 *     macro                      default              meaning
 *     PLATEAU_LM_IMPLEMENTATION  -                    compile the implementation here
 *     PLATEAU_IMPLEMENTATION     -                    same, for every plateau header
 *     PLATEAU_STATIC             -                    every function static
 *     PLATEAU_LM_DEF             extern               linkage of the API (e.g. DLL export)
 *     PLATEAU_MALLOC(size, ctx)  malloc(size)         allocation; define both or neither;
 *     PLATEAU_FREE(ptr, ctx)     free(ptr)            ctx = options.allocator.user_data
 *     PLATEAU_ASSERT(x)          assert(x)            internal invariants only
 *     PLATEAU_SQRT, PLATEAU_FABS sqrt, fabs           the libm calls used here
 *   Run time: plateau_lm_options, all-zero = these defaults (see them with
 *   plateau_lm_resolved_options()):
 *     tau 1e-6               mu0 = tau max diag(J^T J) (the paper), see below
 *     eps 1e-6               the three tolerances default to eps^2 = 1e-12:
 *     eps_grad, eps_step, eps_f
 *     f_stop                 DBL_EPSILON^2 min(F0, 1); negative: off
 *     max_iterations 1000    every solve of the damped system counts
 *     numeric_jacobian 0     non-zero: forward differences, step fd_step |x_j|
 *     fd_step                sqrt(DBL_EPSILON) (fd_step itself when x_j = 0)
 *     scaling NONE           mu I; ADAPTIVE: mu D^2 as MINPACK (see below)
 *     allocator              PLATEAU_MALLOC / PLATEAU_FREE
 *     progress NULL          per-iteration callback (k, F, ||g||_inf, mu, accepted)
 *
 * THE ALGORITHM: Madsen-Nielsen-Tingleff Algorithm 3.16 (the paper's Fig. 5)
 *   F(x) = 1/2 ||f(x)||^2,  J = f'(x),  g = J^T f,  A = J^T J.
 *   Model: L(h) = F(x) + h^T g + 1/2 h^T A h.
 *   Step:  (A + mu I) h = -g, by Cholesky on the n x n matrix when m >= n,
 *          and as h = -J^T (J J^T + mu I)^-1 f on the m x m matrix when
 *          m < n (the same step: (J^T J + mu I)^-1 J^T = J^T (J J^T + mu I)^-1).
 *          If the matrix is not positive definite in floating point:
 *          mu := mu nu, nu := 2 nu, solve again.
 *   Gain:  rho = (F(x) - F(x + h)) / (L(0) - L(h)),  L(0) - L(h) = 1/2 h^T (mu h - g).
 *   rho > 0: accept, x := x + h, new J; mu := mu max(1/3, 1 - (2 rho - 1)^3),
 *            nu := 2, but mu := mu / 10 when rho > 3/4.
 *   else:    reject, mu := mu nu, nu := 2 nu.
 *   What differs from Fig. 5, and why (measured on the 45 MGH variants of
 *   tests/lm_mgh.h from 1, 10 and 100 x the standard start):
 *   - mu0 = max(tau max a_ii, ||g|| / (10 max(||x0||, 1))).  ||h|| <= ||g|| / mu,
 *     so the first step is at most ten times the size of the start: from a
 *     far start, Fig. 5's mu0 = 1e-6 max a_ii gives a wild Gauss-Newton step
 *     and a long run of rejections.  (Without it: 112 reached instead of
 *     116, with 9145 + 7112 evaluations instead of 7361 + 5743.)
 *   - mu / 10 after a very good step (Nielsen's rule divides by at most 3):
 *     like MINPACK doubling its trust radius, it reaches Gauss-Newton speed
 *     sooner.  (Nielsen's 1/3: 115 reached with 8419 + 7187 evaluations;
 *     1/5: 113; 1/20: 110; 1/10: 116 with 7361 + 5743.)
 *   - No scaling by default.  MINPACK's D (d_j = largest ||column j|| seen)
 *     is available as PLATEAU_LM_SCALING_ADAPTIVE, then mu I becomes mu D^2;
 *     it wins on badly scaled problems but, never shrinking, it crawls once
 *     a far start has inflated the column norms (106 vs 116 reached).
 *   No per-problem settings: every run uses the all-zero options.
 *
 * STOPPING RULES (any one stops, result PLATEAU_LM_OK; report->stop says which)
 *   - SMALL_F: F <= f_stop, at x0 and after each accepted step.  The default
 *     f_stop = DBL_EPSILON^2 min(F0, 1) says "the residual is at rounding
 *     level"; it ends the slow (linear) tail of zero-residual problems with
 *     a singular Jacobian at the solution (Powell singular).
 *   - GRADIENT: g = 0, or after an accepted step the largest cosine between f
 *     and a column of J, max_j |g_j| / (||J_j|| ||f||), is <= eps_grad
 *     (MINPACK's gtol test: scale-free, unlike Fig. 5's
 *     ||g||_inf < eps^(1/3) (1 + F), which stops far from the minimum).
 *   - STEP, before trying the step: ||h|| <= eps_step (||x|| + floor),
 *     floor = eps_step min(||x0||, 1) (MNT's floor is eps_step, which
 *     stops a problem at the scale of 1e-150 before its first step; Fig. 5
 *     prints ||h|| < sqrt(eps) (1 + ||h||) with h on both sides), trusted only right after a rejection or when mu <= min_j a_jj:
 *     a step made tiny by heavy damping alone is not convergence (it stopped
 *     Meyer and Powell badly scaled from far starts).  x is not moved.
 *     With scaling ADAPTIVE a step made small by heavy damping (mu > min_j
 *     a_jj) is trusted only when the gradient measure of GRADIENT is <=
 *     sqrt(eps_grad) or F has fallen to F0 / 2: at a point with a large
 *     gradient and no progress the run goes on (it stopped Chebyquad n = 9,
 *     10 untouched at 10 x0).  The same holds for F_CHANGE.
 *   - F_CHANGE, on accepted steps only (Fig. 5 tests rejected steps too,
 *     where F(x) - F(x_new) < 0 always passes): the actual reduction and the
 *     predicted one L(0) - L(h) are both <= eps_f F_old, for a step taken
 *     with mu <= min_j a_jj or for 3 such accepted steps in a row.
 *   - MAX_ITERATIONS: k = max_iterations.
 *   - DAMPING: mu > 1e300: no step lowers F in floating point.
 *   (With scaling ADAPTIVE the norms and a_jj are those of the scaled
 *   problem: ||D h||, ||D x||, diag(D^-1 A D^-1).)
 *
 * NON-FINITE VALUES
 *   NaN or Inf in x0: PLATEAU_LM_ERR_NOT_FINITE_X0 (x untouched).  In the
 *   residual at x0 (or F overflowing): PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL.  At
 *   a trial point x + h the step counts as failed (rho < 0: mu grows, the
 *   step shrinks): a trial point may leave the domain of f (a log, a square
 *   root) and a shorter step is the sound answer.  In the Jacobian (analytic,
 *   or a difference whose forward and backward residuals are both
 *   non-finite): PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN.  After any error or abort
 *   x holds the start or the last accepted point: no NaN or Inf is ever
 *   written to x, and report->f_final is F at that x.
 *
 * MEMORY
 *   plateau_lm_workspace_size(m, n, options) bytes, about
 *   8 (m n + 2 k^2 + 2 m + 5 n + k), k = min(m, n): with a caller workspace (any
 *   alignment) the solver allocates nothing; with work = NULL it makes one
 *   allocation through options.allocator (or PLATEAU_MALLOC) and frees it
 *   before returning.  Every size product is overflow-checked.
 *
 * THREAD SAFETY
 *   No global or static mutable state.  Concurrent solves are safe when each
 *   has its own x, workspace and callback data.
 *
 * DETERMINISM
 *   Same x0, options and residuals give the same iterates bit for bit.
 *   Across builds that needs the same arithmetic: no contraction of a*b + c
 *   into a fused multiply-add.  gcc: an ISO mode (-std=c99) or
 *   -ffp-contract=off (its GNU modes contract where the target has FMA);
 *   clang: the implementation sets #pragma STDC FP_CONTRACT OFF, which
 *   clang honours unless -ffp-contract=fast is passed.
 *
 * EVIDENCE (make bench; tests/test_lm.c)
 *   45 MGH variants x 3 starts: the published minimum is reached in 116 of
 *   135 runs (1x 43, 10x 41, 100x 32) with 7361 residual + 5743 Jacobian
 *   evaluations in all; MINPACK's lmder (default tolerances, run on the same
 *   problems and starts) reaches 97, with 9028 + 7758.
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
#elif !defined(PLATEAU_INDEX_MAX)
#error "plateau: define PLATEAU_INDEX_MAX (the type's largest value) with PLATEAU_INDEX_TYPE"
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

/* ---- Result codes: 0 = OK, negative = error --------------------------------
 * One X-macro list gives the enum and plateau_lm_result_string(), so the two
 * never drift.  X(name, value, message). */
#define PLATEAU_LM_RESULT_LIST(X)                                                   \
    X(PLATEAU_LM_OK, 0, "ok")                                                       \
    X(PLATEAU_LM_ERR_ARGUMENT, -1,                                                  \
      "invalid argument (x or func NULL, an option negative or NaN, an unknown "    \
      "scaling, or an allocator with only one function)")                          \
    X(PLATEAU_LM_ERR_OUT_OF_MEMORY, -2, "out of memory")                            \
    X(PLATEAU_LM_ERR_OVERFLOW, -3, "m and n are so large that the workspace size overflows size_t") \
    X(PLATEAU_LM_ERR_NOT_FINITE_X0, -4, "the start x holds a NaN or an infinity")   \
    X(PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL, -5,                                       \
      "the residual at the start holds a NaN or an infinity, or F overflows")       \
    X(PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN, -6,                                       \
      "the Jacobian (analytic, or forward and backward differences) holds a NaN or an infinity") \
    X(PLATEAU_LM_ERR_EMPTY, -7, "m or n is zero")                                   \
    X(PLATEAU_LM_ERR_ABORTED, -8, "a callback (residual or progress) returned non-zero") \
    X(PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL, -9,                                       \
      "work_bytes is smaller than plateau_lm_workspace_size()")

/* The enum of a list, and its end marker: <PREFIX>_COUNT, the number of
 * entries, counted from the list (so no value is typed twice). */
#define PLATEAU_LM_ENUM_ENTRY(name, value, text) name = value,
#define PLATEAU_LM_COUNT_ENTRY(name, value, text) +1
typedef enum plateau_lm_result {
    PLATEAU_LM_RESULT_LIST(PLATEAU_LM_ENUM_ENTRY)
    PLATEAU_LM_RESULT_COUNT = 0 PLATEAU_LM_RESULT_LIST(PLATEAU_LM_COUNT_ENTRY)
} plateau_lm_result;

/* ---- Why the iteration stopped (report->stop); separate from the result ---- */
#define PLATEAU_LM_STOP_LIST(X)                                                     \
    X(PLATEAU_LM_STOP_NONE, 0, "not stopped")                                       \
    X(PLATEAU_LM_STOP_GRADIENT, 1, "gradient test")                                 \
    X(PLATEAU_LM_STOP_STEP, 2, "step test")                                         \
    X(PLATEAU_LM_STOP_F_CHANGE, 3, "F-change test")                                 \
    X(PLATEAU_LM_STOP_SMALL_F, 4, "F below f_stop")                                 \
    X(PLATEAU_LM_STOP_MAX_ITERATIONS, 5, "max_iterations reached")                  \
    X(PLATEAU_LM_STOP_DAMPING, 6, "damping limit: no step lowers F")                \
    X(PLATEAU_LM_STOP_ABORTED, 7, "aborted by a callback")                          \
    X(PLATEAU_LM_STOP_ERROR, 8, "error (see the result code)")
/* The tests behind each reason: see STOPPING RULES at the top of the file. */

typedef enum plateau_lm_stop {
    PLATEAU_LM_STOP_LIST(PLATEAU_LM_ENUM_ENTRY)
    PLATEAU_LM_STOP_COUNT = 0 PLATEAU_LM_STOP_LIST(PLATEAU_LM_COUNT_ENTRY)
} plateau_lm_stop;

/* Scaling of the damping term (options.scaling). */
typedef enum plateau_lm_scaling {
    PLATEAU_LM_SCALING_NONE = 0,    /* default: mu I, as MNT / the paper's Fig. 5 */
    PLATEAU_LM_SCALING_ADAPTIVE = 1 /* mu D^2, D_j = running max of ||J_j|| (MINPACK) */
} plateau_lm_scaling;

/* Residual callback: evaluate f(x) (m values) into f; if jac is not NULL,
 * also the Jacobian, row-major m x n: jac[i * n + j] = d f_i / d x_j.
 * Return 0 to go on, non-zero to abort the solve (PLATEAU_LM_ERR_ABORTED).
 * It may return NaN or Inf residuals at trial points: see "Non-finite values". */
typedef int (*plateau_lm_func)(const double *x, double *f, double *jac, void *user);

/* Per-iteration callback: k (1, 2, ...), F at the current (accepted) point,
 * ||J^T f||_inf there, the damping mu for the next iteration, and whether this
 * iteration's step was accepted.  user is the solve's user pointer.  Return
 * non-zero to abort (PLATEAU_LM_ERR_ABORTED; x keeps the last accepted point). */
typedef int (*plateau_lm_progress)(int k, double F, double grad_inf, double mu, int accepted,
                                   void *user);

typedef struct plateau_lm_options {
    /* all-zero means the documented defaults; see plateau_lm_resolved_options() */
    double tau;        /* mu0 = tau * max diag(J^T J), raised if needed to keep the
                          first step <= 10 max(||x0||, 1); 0 -> 1e-6 (the paper) */
    double eps;        /* 0 -> 1e-6 (the paper's epsilon); the three tests below
                          default to eps^2 */
    int max_iterations;/* 0 -> 1000; each solve of the damped system counts */
    int numeric_jacobian; /* non-zero: the callback never gets jac; forward differences */
    plateau_allocator allocator;
    /* the stopping tests and further settings */
    double eps_grad;   /* gradient (cosine) test; 0 -> eps^2 */
    double eps_step;   /* step test; 0 -> eps^2 */
    double eps_f;      /* F-change test; 0 -> eps^2 */
    double f_stop;     /* stop once F <= f_stop; 0 -> DBL_EPSILON^2 min(F0, 1);
                          negative: never */
    double fd_step;    /* relative forward-difference step; 0 -> sqrt(DBL_EPSILON) */
    plateau_lm_scaling scaling; /* 0 -> PLATEAU_LM_SCALING_NONE */
    plateau_lm_progress progress; /* NULL -> none */
} plateau_lm_options;

typedef struct plateau_lm_report {
    int iterations;            /* damped systems solved */
    int residual_evaluations;  /* callback calls for f alone (finite differences included) */
    int jacobian_evaluations;  /* Jacobians formed (analytic calls, or difference sweeps) */
    double f_initial, f_final; /* F = 1/2 ||f||^2 */
    double grad_inf;           /* ||J^T f||_inf at the end */
    double mu_final;
    plateau_lm_stop stop;      /* why the iteration ended */
} plateau_lm_report;

/* Detail for a failed plateau_lm_solve, the same shape as plateau.h's
 * plateau_error and plateau_delaunay.h's plateau_dt_error. */
typedef struct plateau_lm_error {
    plateau_lm_result code;
    long index;        /* the offending entry of x (NOT_FINITE_X0); -1 if none */
    char message[160]; /* one sentence: the result's message */
} plateau_lm_error;

/* Minimise F(x) = 1/2 ||f(x)||^2, f: R^n -> R^m (m < n allowed).  x (n
 * values) is the start on entry and the solution on return.  options and
 * report may be NULL.  work/work_bytes: a caller-owned workspace of at least
 * plateau_lm_workspace_size(m, n, options) bytes (any alignment), or NULL to
 * allocate through options->allocator.
 * Returns PLATEAU_LM_OK when the iteration ran to one of its stopping rules
 * (report->stop says which, including max_iterations), else an error code.
 * On every return x holds finite values: the start, or the last accepted point.
 * err (may be NULL) gets the code, the offending entry of x and the message
 * on error, and is reset (PLATEAU_LM_OK, -1, "") on success.
 * Thread safety: re-entrant; concurrent calls need distinct x and work. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_solve(size_t m, size_t n, double *x,
                                                  plateau_lm_func func, void *user,
                                                  const plateau_lm_options *options,
                                                  void *work, size_t work_bytes,
                                                  plateau_lm_report *report,
                                                  plateau_lm_error *err);
/* Bytes of workspace plateau_lm_solve needs: 8 (m n + 2 k^2 + 2 m + 5 n + k), k = min(m, n),
 * plus alignment slack.  0 when m or n is 0 or the size overflows size_t. */
PLATEAU_LM_DEF size_t plateau_lm_workspace_size(size_t m, size_t n,
                                                const plateau_lm_options *options);
/* The message for a result code ("ok", ...); never NULL. */
PLATEAU_LM_DEF const char *plateau_lm_result_string(plateau_lm_result result);
/* What a stop reason means; never NULL. */
PLATEAU_LM_DEF const char *plateau_lm_stop_string(plateau_lm_stop stop);
/* The options with every zero field replaced by its default (options may be
 * NULL: all defaults). */
PLATEAU_LM_DEF plateau_lm_options plateau_lm_resolved_options(const plateau_lm_options *options);

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

/* ---- plateau_lm implementation ------------------------------------------ */
#include <float.h>

/* No contraction of a*b + c into FMA in this implementation: the same build
 * flags under gcc -std=c99 and clang then give the same iterates (see
 * DETERMINISM).  gcc ignores the pragma with a warning, so only clang. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#define PLATEAU_LM_DEFAULT_TAU 1e-6
#define PLATEAU_LM_DEFAULT_EPS 1e-6
#define PLATEAU_LM_DEFAULT_MAX_ITERATIONS 1000
/* mu beyond this means no step of any length lowers F (in floating point) */
#define PLATEAU_LM_MU_LIMIT 1e300
/* the first step is at most this many times max(||D x0||, 1) */
#define PLATEAU_LM_FIRST_STEP 10.0
/* mu is multiplied by this after a step with gain ratio rho > 3/4 */
#define PLATEAU_LM_GOOD_STEP_FACTOR 0.1
/* this many accepted steps in a row with a tiny F change stop the iteration
 * even while the damping dominates (a flat valley, a local minimum at which
 * some columns of J vanish) */
#define PLATEAU_LM_SMALL_CHANGES 3

#define PLATEAU_LM_STRING_CASE(name, value, text) \
    case name:                                    \
        return text;

PLATEAU_LM_DEF const char *plateau_lm_result_string(plateau_lm_result result)
{
    switch (result) {
        PLATEAU_LM_RESULT_LIST(PLATEAU_LM_STRING_CASE)
    default:
        break;
    }
    return "unknown plateau_lm_result";
}

PLATEAU_LM_DEF const char *plateau_lm_stop_string(plateau_lm_stop stop)
{
    switch (stop) {
        PLATEAU_LM_STOP_LIST(PLATEAU_LM_STRING_CASE)
    default:
        break;
    }
    return "unknown plateau_lm_stop";
}

/* v is neither NaN nor infinite (NaN - NaN and inf - inf are NaN). */
static int plateau__lm_finite(double v)
{
    return v - v == 0.0;
}

/* a + b, or 0 on overflow */
static size_t plateau__lm_add(size_t a, size_t b)
{
    if (a == 0 || b > (size_t)-1 - a) return 0;
    return a + b;
}

/* Number of doubles in the workspace, or 0 when it overflows size_t.
 * Layout: f, fnew (m each); J (m n); A, its factor (k k each, k = min(m, n));
 * g, h, xnew, d, column norms (n each); y (k). */
static size_t plateau__lm_doubles(size_t m, size_t n)
{
    size_t k = m < n ? m : n;
    size_t mn = plateau__bytes(m, n), kk = plateau__bytes(k, k), total;
    size_t twom = plateau__bytes(m, 2), twokk = plateau__bytes(kk, 2), fiven = plateau__bytes(n, 5);
    if (mn == 0 || kk == 0 || twom == 0 || twokk == 0 || fiven == 0) return 0;
    total = plateau__lm_add(twom, mn);
    total = plateau__lm_add(total, twokk);
    total = plateau__lm_add(total, fiven);
    total = plateau__lm_add(total, k);
    return total;
}

PLATEAU_LM_DEF size_t plateau_lm_workspace_size(size_t m, size_t n,
                                                const plateau_lm_options *options)
{
    size_t count, bytes;
    (void)options; /* no option changes the size today; kept for the future */
    if (m == 0 || n == 0) return 0;
    count = plateau__lm_doubles(m, n);
    if (count == 0) return 0;
    bytes = plateau__bytes(count, sizeof(double));
    if (bytes == 0) return 0;
    /* slack to align a caller's buffer to a double boundary */
    return plateau__lm_add(bytes, sizeof(double));
}

/* 1 when v is a valid non-negative option value (NaN is invalid). */
static int plateau__lm_nonneg(double v)
{
    return v >= 0.0 && plateau__lm_finite(v);
}

PLATEAU_LM_DEF plateau_lm_options plateau_lm_resolved_options(const plateau_lm_options *options)
{
    plateau_lm_options o;
    double eps2;
    if (options) {
        o = *options;
    } else {
        o.tau = o.eps = o.eps_grad = o.eps_step = o.eps_f = o.f_stop = o.fd_step = 0.0;
        o.max_iterations = 0;
        o.numeric_jacobian = 0;
        o.scaling = PLATEAU_LM_SCALING_NONE;
        o.allocator.alloc_fn = NULL;
        o.allocator.free_fn = NULL;
        o.allocator.user_data = NULL;
        o.progress = NULL;
    }
    if (o.tau == 0.0) o.tau = PLATEAU_LM_DEFAULT_TAU;
    if (o.eps == 0.0) o.eps = PLATEAU_LM_DEFAULT_EPS;
    eps2 = o.eps * o.eps;
    if (o.eps_grad == 0.0) o.eps_grad = eps2;
    if (o.eps_step == 0.0) o.eps_step = eps2;
    if (o.eps_f == 0.0) o.eps_f = eps2;
    if (o.fd_step == 0.0) o.fd_step = 1.4901161193847656e-08; /* sqrt(DBL_EPSILON) */
    if (o.max_iterations == 0) o.max_iterations = PLATEAU_LM_DEFAULT_MAX_ITERATIONS;
    return o;
}

static int plateau__lm_options_valid(const plateau_lm_options *o)
{
    return plateau__lm_nonneg(o->tau) && plateau__lm_nonneg(o->eps) &&
           plateau__lm_nonneg(o->eps_grad) && plateau__lm_nonneg(o->eps_step) &&
           plateau__lm_nonneg(o->eps_f) && plateau__lm_finite(o->f_stop) &&
           plateau__lm_nonneg(o->fd_step) && o->max_iterations >= 0 &&
           (o->scaling == PLATEAU_LM_SCALING_NONE || o->scaling == PLATEAU_LM_SCALING_ADAPTIVE) &&
           plateau__allocator_valid(&o->allocator);
}

/* Everything one solve needs, so the helpers take one pointer. */
typedef struct plateau__lm_state {
    size_t m, n, k;  /* k = min(m, n): order of the normal matrix */
    double *x;       /* the caller's x: always the last accepted point */
    plateau_lm_func func;
    void *user;
    const plateau_lm_options *o;
    double *f, *fnew, *jac, *a, *fac, *g, *h, *xnew, *d, *cn, *y;
    int residual_evaluations, jacobian_evaluations;
} plateau__lm_state;

/* 1/2 ||v||^2, or an infinity / NaN when v is not finite or the sum overflows. */
static double plateau__lm_half_sumsq(const double *v, size_t len)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < len; i++) s += v[i] * v[i];
    return 0.5 * s;
}

static int plateau__lm_all_finite(const double *v, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++)
        if (!plateau__lm_finite(v[i])) return 0;
    return 1;
}

/* The Jacobian at s->x, whose residual s->f is already known.  Analytic: one
 * call with jac (its residual output goes to scratch).  Numeric (forward
 * differences, one call per column): step h_j = fd_step * |x_j| (fd_step when
 * x_j = 0), rounded so that x_j + h_j is exact; if the residual at x_j + h_j is
 * not finite, the backward difference at x_j - h_j is used instead. */
static plateau_lm_result plateau__lm_jacobian(plateau__lm_state *s)
{
    size_t m = s->m, n = s->n, i, j;
    s->jacobian_evaluations++;
    if (!s->o->numeric_jacobian) {
        if (s->func(s->x, s->fnew, s->jac, s->user) != 0) return PLATEAU_LM_ERR_ABORTED;
        if (!plateau__lm_all_finite(s->jac, m * n)) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
        return PLATEAU_LM_OK;
    }
    for (j = 0; j < n; j++) s->xnew[j] = s->x[j];
    for (j = 0; j < n; j++) {
        double xj = s->x[j], step = s->o->fd_step * PLATEAU_FABS(xj), t;
        int side;
        if (step == 0.0) step = s->o->fd_step;
        for (side = 0; side < 2; side++) {
            double hj = side == 0 ? step : -step;
            t = xj + hj;
            hj = t - xj; /* the step actually taken */
            s->xnew[j] = t;
            s->residual_evaluations++;
            if (s->func(s->xnew, s->fnew, NULL, s->user) != 0) {
                s->xnew[j] = xj;
                return PLATEAU_LM_ERR_ABORTED;
            }
            if (hj != 0.0 && plateau__lm_all_finite(s->fnew, m)) {
                for (i = 0; i < m; i++) s->jac[i * n + j] = (s->fnew[i] - s->f[i]) / hj;
                break;
            }
        }
        s->xnew[j] = xj;
        if (side == 2) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
    }
    if (!plateau__lm_all_finite(s->jac, m * n)) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
    return PLATEAU_LM_OK;
}

/* After a new Jacobian: g = J^T f, column norms cn, the scaling d (MINPACK's
 * rule: d_j = max(d_j, ||J_j||), first d_j = ||J_j|| or 1 for a zero column),
 * and the scaled normal matrix A' (lower triangle): D^-1 J^T J D^-1 (n x n)
 * when m >= n, J D^-2 J^T (m x m) when m < n.  Returns ||g||_inf. */
/* min and max over the non-zero columns of diag(J'^T J')_j = (||J_j|| / d_j)^2 */
static void plateau__lm_diag_range(const plateau__lm_state *s, double *amin, double *amax)
{
    size_t j;
    double lo = HUGE_VAL, hi = 0.0;
    for (j = 0; j < s->n; j++) {
        double q = s->cn[j] / s->d[j];
        if (q > 0.0) {
            if (q * q < lo) lo = q * q;
            if (q * q > hi) hi = q * q;
        }
    }
    *amin = hi > 0.0 ? lo : 0.0;
    *amax = hi;
}

static double plateau__lm_prepare(plateau__lm_state *s, int first)
{
    size_t m = s->m, n = s->n, k = s->k, i, j, r;
    const double *J = s->jac;
    double ginf = 0.0;
    for (j = 0; j < n; j++) {
        s->g[j] = 0.0;
        s->cn[j] = 0.0;
    }
    for (r = 0; r < m; r++) {
        const double *row = J + r * n;
        double fr = s->f[r];
        for (j = 0; j < n; j++) {
            s->g[j] += row[j] * fr;
            s->cn[j] += row[j] * row[j];
        }
    }
    for (j = 0; j < n; j++) {
        double c = PLATEAU_SQRT(s->cn[j]);
        s->cn[j] = c;
        if (PLATEAU_FABS(s->g[j]) > ginf) ginf = PLATEAU_FABS(s->g[j]);
        if (s->o->scaling == PLATEAU_LM_SCALING_NONE) {
            s->d[j] = 1.0;

        } else if (first) {
            s->d[j] = c > 0.0 ? c : 1.0;
        } else if (c > s->d[j]) {
            s->d[j] = c;
        }
    }
    for (i = 0; i < k * k; i++) s->a[i] = 0.0;
    if (m >= n) {
        for (r = 0; r < m; r++) {
            const double *row = J + r * n;
            for (i = 0; i < n; i++) {
                double ri = row[i];
                double *ai = s->a + i * n;
                if (ri == 0.0) continue;
                for (j = 0; j <= i; j++) ai[j] += ri * row[j];
            }
        }
        for (i = 0; i < n; i++)
            for (j = 0; j <= i; j++) s->a[i * n + j] /= s->d[i] * s->d[j];
    } else {
        for (i = 0; i < m; i++) {
            const double *ri = J + i * n;
            for (r = 0; r <= i; r++) {
                const double *rr = J + r * n;
                double sum = 0.0;
                for (j = 0; j < n; j++) sum += (ri[j] / s->d[j]) * (rr[j] / s->d[j]);
                s->a[i * m + r] = sum;
            }
        }
    }
    return ginf;
}

/* In-place Cholesky factorisation L L^T of the lower triangle of the k x k
 * row-major matrix a.  Returns 0 when a pivot is not positive (or not finite):
 * the matrix is not positive definite in floating point. */
static int plateau__lm_cholesky(double *a, size_t k)
{
    size_t i, j, p;
    for (j = 0; j < k; j++) {
        double *aj = a + j * k, s = aj[j], ljj;
        for (p = 0; p < j; p++) s -= aj[p] * aj[p];
        if (!(s > 0.0) || !plateau__lm_finite(s)) return 0;
        ljj = PLATEAU_SQRT(s);
        aj[j] = ljj;
        for (i = j + 1; i < k; i++) {
            double *ai = a + i * k, t = ai[j];
            for (p = 0; p < j; p++) t -= ai[p] * aj[p];
            ai[j] = t / ljj;
        }
    }
    return 1;
}

/* Solve L L^T v = v in place with the factor from plateau__lm_cholesky. */
static void plateau__lm_cholesky_solve(const double *l, size_t k, double *v)
{
    size_t i, p;
    for (i = 0; i < k; i++) {
        double t = v[i];
        for (p = 0; p < i; p++) t -= l[i * k + p] * v[p];
        v[i] = t / l[i * k + i];
    }
    for (i = k; i-- > 0;) {
        double t = v[i];
        for (p = i + 1; p < k; p++) t -= l[p * k + i] * v[p];
        v[i] = t / l[i * k + i];
    }
}

/* The damped Gauss-Newton step in the scaled variables: h' solves
 * (A' + mu I) h' = -g' with g' = D^-1 g (m >= n), or equivalently
 * h' = -J'^T (J' J'^T + mu I)^-1 f with J' = J D^-1 (m < n: the m x m
 * system, since (J'^T J' + mu I)^-1 J'^T = J'^T (J' J'^T + mu I)^-1).
 * Returns 0 when the damped matrix is not positive definite in floating point. */
static int plateau__lm_step(plateau__lm_state *s, double mu)
{
    size_t m = s->m, n = s->n, k = s->k, i, j;
    for (i = 0; i < k; i++) {
        for (j = 0; j <= i; j++) s->fac[i * k + j] = s->a[i * k + j];
        s->fac[i * k + i] += mu;
    }
    if (!plateau__lm_cholesky(s->fac, k)) return 0;
    if (m >= n) {
        for (j = 0; j < n; j++) s->h[j] = -s->g[j] / s->d[j];
        plateau__lm_cholesky_solve(s->fac, n, s->h);
    } else {
        for (i = 0; i < m; i++) s->y[i] = -s->f[i];
        plateau__lm_cholesky_solve(s->fac, m, s->y);
        for (j = 0; j < n; j++) s->h[j] = 0.0;
        for (i = 0; i < m; i++) {
            const double *row = s->jac + i * n;
            double yi = s->y[i];
            for (j = 0; j < n; j++) s->h[j] += row[j] * yi;
        }
        for (j = 0; j < n; j++) s->h[j] /= s->d[j];
    }
    return plateau__lm_all_finite(s->h, n);
}

/* The scale-free gradient measure of the gradient test (MINPACK's gtol):
 * the largest cosine between f and a column of J, max_j |g_j| / (||J_j|| ||f||),
 * for F = 1/2 ||f||^2 at the point where g and the column norms were formed. */
static double plateau__lm_grad_cosine(const plateau__lm_state *s, double F)
{
    double fnorm = PLATEAU_SQRT(2.0 * F), cmax = 0.0;
    size_t j;
    for (j = 0; j < s->n; j++)
        if (s->cn[j] > 0.0) {
            double c = PLATEAU_FABS(s->g[j]) / (s->cn[j] * fnorm);
            if (c > cmax) cmax = c;
        }
    return cmax;
}

/* The step and F-change tests say "converged" from small steps or small
 * changes of F.  With scaling ADAPTIVE the norms are ||D .||, and ||D x|| is
 * dominated by the columns of largest norm (they can differ by 1e13), so a
 * step that is large in a column of small norm still looks small.  There a
 * small step is evidence of convergence when it is Gauss-Newton-like
 * (gauss_newton: mu <= min_j a'_jj), when the gradient measure is at most
 * sqrt(eps_grad), or when the run has made progress (F at most half of F0);
 * a small damped step at a point with a large gradient and no progress
 * means a poor model, not convergence, and the run goes on until a step
 * succeeds or the damping limit or max_iterations stops it (MGH Chebyquad
 * n = 9 and 10 from 10 x0 stopped untouched, F = 1.2e25 and 1.4e28).
 * Without scaling the tests keep their plain form. */
static int plateau__lm_may_claim(const plateau_lm_options *o, int gauss_newton, double cosine,
                                 double F, double F0)
{
    if (o->scaling != PLATEAU_LM_SCALING_ADAPTIVE) return 1;
    return gauss_newton || cosine <= PLATEAU_SQRT(o->eps_grad) || F <= 0.5 * F0;
}

static plateau_lm_result plateau__lm_solve(size_t m, size_t n, double *x,
                                           plateau_lm_func func, void *user,
                                           const plateau_lm_options *options,
                                           void *work, size_t work_bytes,
                                           plateau_lm_report *report)
{
    plateau_lm_options o;
    plateau__lm_state s;
    plateau_lm_result res = PLATEAU_LM_OK;
    plateau_lm_stop stop = PLATEAU_LM_STOP_NONE;
    void *owned = NULL;
    unsigned char *base;
    size_t need, j, k;
    double F = 0.0, F0 = 0.0, mu = 0.0, nu = 2.0, ginf = 0.0, amin = 0.0, amax = 0.0;
    double step_floor = 0.0; /* the absolute term of the step test, see below */
    double f_stop = 0.0, *p;
    int iter = 0, rejected = 0, small_changes = 0;
    double cosine = 0.0; /* the gradient measure at x, see plateau__lm_may_claim */

    if (report) {
        report->iterations = report->residual_evaluations = report->jacobian_evaluations = 0;
        report->f_initial = report->f_final = report->grad_inf = report->mu_final = 0.0;
        report->stop = PLATEAU_LM_STOP_ERROR;
    }
    s.residual_evaluations = s.jacobian_evaluations = 0;
    if (!x || !func) return PLATEAU_LM_ERR_ARGUMENT;
    if (m == 0 || n == 0) return PLATEAU_LM_ERR_EMPTY;
    o = plateau_lm_resolved_options(options);
    if (!plateau__lm_options_valid(&o)) return PLATEAU_LM_ERR_ARGUMENT;
    need = plateau_lm_workspace_size(m, n, &o);
    if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
    if (!plateau__lm_all_finite(x, n)) return PLATEAU_LM_ERR_NOT_FINITE_X0;
    if (work) {
        if (work_bytes < need) return PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL;
        base = (unsigned char *)work;
    } else {
        owned = plateau__alloc(&o.allocator, need);
        if (!owned) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        base = (unsigned char *)owned;
    }
    {   /* align to a double boundary (the size has the slack for it) */
        size_t mis = (size_t)((uintptr_t)base % sizeof(double));
        if (mis) base += sizeof(double) - mis;
    }
    k = m < n ? m : n;
    p = (double *)(void *)base;
    s.m = m; s.n = n; s.k = k; s.x = x; s.func = func; s.user = user; s.o = &o;
    s.f = p; p += m;
    s.fnew = p; p += m;
    s.jac = p; p += m * n;
    s.a = p; p += k * k;
    s.fac = p; p += k * k;
    s.g = p; p += n;
    s.h = p; p += n;
    s.xnew = p; p += n;
    s.d = p; p += n;
    s.cn = p; p += n;
    s.y = p; p += k;
    PLATEAU_ASSERT((size_t)(p - (double *)(void *)base) == plateau__lm_doubles(m, n));

    /* MNT Alg. 3.16 / Fig. 5, initialisation: x := x0; A := J^T J; g := J^T f;
     * found := gradient test; mu := tau * max a_ii; nu := 2. */
    s.residual_evaluations++;
    if (func(x, s.f, NULL, user) != 0) { res = PLATEAU_LM_ERR_ABORTED; goto finish; }
    F = F0 = plateau__lm_half_sumsq(s.f, m);
    if (!plateau__lm_finite(F)) { res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL; goto finish; }
    /* f_stop = 0: the residual is at rounding level, F <= DBL_EPSILON^2 min(F0, 1);
     * f_stop < 0: never. */
    f_stop = o.f_stop != 0.0 ? o.f_stop : DBL_EPSILON * DBL_EPSILON * (F0 < 1.0 ? F0 : 1.0);
    res = plateau__lm_jacobian(&s);
    if (res != PLATEAU_LM_OK) goto finish;
    ginf = plateau__lm_prepare(&s, 1);
    plateau__lm_diag_range(&s, &amin, &amax);
    /* mu0 = tau max a_ii (Fig. 5), raised if needed so that the first step,
     * whose length is at most ||g'|| / mu, is at most 10 max(||D x0||, 1): a
     * far start then begins with a bounded gradient step instead of a wild
     * Gauss-Newton step and a long series of rejections. */
    mu = o.tau * amax;
    {
        double gn = 0.0, xn = 0.0, lim;
        for (j = 0; j < n; j++) {
            gn += (s.g[j] / s.d[j]) * (s.g[j] / s.d[j]);
            xn += (s.d[j] * x[j]) * (s.d[j] * x[j]);
        }
        xn = PLATEAU_SQRT(xn);
        /* MNT's step test ||h|| <= eps2 (||x|| + eps2) has an absolute
         * floor eps2, which stops at once a problem living at the scale of
         * 1e-150; the floor is eps2^2 min(||D x0||, 1) instead: the same for
         * starts of norm 1 or more, scale-free below. */
        step_floor = o.eps_step * o.eps_step * (xn < 1.0 ? xn : 1.0);
        lim = PLATEAU_SQRT(gn) / (PLATEAU_LM_FIRST_STEP * (xn > 1.0 ? xn : 1.0));
        if (lim > mu) mu = lim;
    }
    if (!(mu > 0.0)) mu = o.tau;
    if (F <= f_stop) stop = PLATEAU_LM_STOP_SMALL_F;
    else if (ginf == 0.0) stop = PLATEAU_LM_STOP_GRADIENT;
    else cosine = plateau__lm_grad_cosine(&s, F);

    /* MNT / Fig. 5 main loop: while (not found) and (k < k_max) */
    while (stop == PLATEAU_LM_STOP_NONE) {
        double Fnew, pred, rho, hnorm = 0.0, xnorm = 0.0;
        int accepted = 0;
        if (iter >= o.max_iterations) { stop = PLATEAU_LM_STOP_MAX_ITERATIONS; break; }
        iter++;
        /* k := k + 1; solve (A + mu I) delta = -g, here (A' + mu I) h' = -g' in
         * the scaled variables.  Not positive definite in floating point: raise
         * mu as after a failed step and solve again (bounded by k_max and by
         * PLATEAU_LM_MU_LIMIT). */
        if (!plateau__lm_step(&s, mu)) {
            double floor_mu = DBL_EPSILON * amax > DBL_MIN ? DBL_EPSILON * amax : DBL_MIN;
            mu *= nu;
            if (mu < floor_mu) mu = floor_mu;
            nu *= 2.0;
            rejected = 1;
            if (!(mu <= PLATEAU_LM_MU_LIMIT)) { stop = PLATEAU_LM_STOP_DAMPING; break; }
            if (o.progress && o.progress(iter, F, ginf, mu, 0, user) != 0) {
                res = PLATEAU_LM_ERR_ABORTED;
                goto finish;
            }
            continue;
        }
        /* Step test (MNT, corrected from Fig. 5): ||delta|| <= eps2 (||x|| + eps2 min(||x0||, 1)),
         * in the scaled norm ||D .||, trusted only when the step is not a mere
         * artefact of heavy damping: after a rejection (stagnation), or when
         * mu <= min_j a'_jj (the step is close to the Gauss-Newton step),
         * and only when plateau__lm_may_claim allows a claim of convergence. */
        for (j = 0; j < n; j++) {
            hnorm += s.h[j] * s.h[j];
            xnorm += (s.d[j] * x[j]) * (s.d[j] * x[j]);
        }
        hnorm = PLATEAU_SQRT(hnorm);
        xnorm = PLATEAU_SQRT(xnorm);
        if (hnorm <= o.eps_step * xnorm + step_floor && (rejected || mu <= amin) &&
            plateau__lm_may_claim(&o, mu <= amin, cosine, F, F0)) {
            stop = PLATEAU_LM_STOP_STEP;
            break;
        }
        /* else: x_new := x + delta;  rho := (F(x) - F(x_new)) / (L(0) - L(delta))
         * with L(0) - L(delta) = 1/2 h'^T (mu h' - g') (MNT eq. 3.14, scaled). */
        for (j = 0; j < n; j++) s.xnew[j] = x[j] + s.h[j] / s.d[j];
        pred = 0.0;
        for (j = 0; j < n; j++) pred += s.h[j] * (mu * s.h[j] - s.g[j] / s.d[j]);
        pred *= 0.5;
        Fnew = HUGE_VAL;
        if (plateau__lm_all_finite(s.xnew, n)) {
            s.residual_evaluations++;
            if (func(s.xnew, s.fnew, NULL, user) != 0) { res = PLATEAU_LM_ERR_ABORTED; goto finish; }
            Fnew = plateau__lm_half_sumsq(s.fnew, m);
        }
        /* A NaN or infinite residual at the trial point is a failed step: the
         * step left the domain of f; a shorter one is tried next. */
        rho = (plateau__lm_finite(Fnew) && pred > 0.0) ? (F - Fnew) / pred : -1.0;
        if (rho > 0.0) {
            /* if rho > 0: x := x_new; A := J^T J; g := J^T f; found := tests */
            double Fold = F, mu_step, amin_step, *t;
            accepted = 1;
            for (j = 0; j < n; j++) x[j] = s.xnew[j];
            t = s.f; s.f = s.fnew; s.fnew = t;
            F = Fnew;
            res = plateau__lm_jacobian(&s);
            if (res != PLATEAU_LM_OK) goto finish;
            mu_step = mu;
            amin_step = amin;
            ginf = plateau__lm_prepare(&s, 0);
            plateau__lm_diag_range(&s, &amin, &amax);
            rejected = 0;
            /* mu := mu * max(1/3, 1 - (2 rho - 1)^3); nu := 2 (Nielsen), except
             * that a very good step (rho > 3/4) divides mu by 10 */
            {
                double q = 2.0 * rho - 1.0, factor = 1.0 - q * q * q;
                if (factor < 1.0 / 3.0) factor = 1.0 / 3.0;
                if (rho > 0.75) factor = PLATEAU_LM_GOOD_STEP_FACTOR;
                mu *= factor;
                if (mu < DBL_MIN) mu = DBL_MIN;
                nu = 2.0;
            }
            if (F <= f_stop) {
                stop = PLATEAU_LM_STOP_SMALL_F;
            } else {
                /* gradient test, scale-free: the largest cosine between f and a
                 * column of J, |g_j| / (||J_j|| ||f||) <= eps_grad */
                double cmax = plateau__lm_grad_cosine(&s, F);
                cosine = cmax;
                if (ginf == 0.0 || cmax <= o.eps_grad) stop = PLATEAU_LM_STOP_GRADIENT;
                /* F-change test, on accepted steps only (examples/NOTES.md): the actual and
                 * the predicted reduction are both below eps_f * F, for a
                 * Gauss-Newton-like step (mu <= min a'_jj when it was taken) or
                 * for PLATEAU_LM_SMALL_CHANGES accepted steps in a row. */
                else if (Fold - F <= o.eps_f * Fold && pred <= o.eps_f * Fold) {
                    small_changes++;
                    if ((mu_step <= amin_step || small_changes >= PLATEAU_LM_SMALL_CHANGES) &&
                        plateau__lm_may_claim(&o, mu_step <= amin_step, cmax, F, F0))
                        stop = PLATEAU_LM_STOP_F_CHANGE;
                } else {
                    small_changes = 0;
                }
            }
        } else {
            /* else: mu := mu * nu; nu := 2 nu */
            mu *= nu;
            nu *= 2.0;
            rejected = 1;
            if (!(mu <= PLATEAU_LM_MU_LIMIT)) stop = PLATEAU_LM_STOP_DAMPING;
        }
        if (o.progress && o.progress(iter, F, ginf, mu, accepted, user) != 0) {
            res = PLATEAU_LM_ERR_ABORTED;
            goto finish;
        }
    }

finish:
    if (report) {
        report->iterations = iter;
        report->residual_evaluations = s.residual_evaluations;
        report->jacobian_evaluations = s.jacobian_evaluations;
        report->f_initial = F0;
        report->f_final = F;
        report->grad_inf = ginf;
        report->mu_final = mu;
        report->stop = res == PLATEAU_LM_OK ? stop
                       : res == PLATEAU_LM_ERR_ABORTED ? PLATEAU_LM_STOP_ABORTED
                                                       : PLATEAU_LM_STOP_ERROR;
    }
    plateau__free(&o.allocator, owned);
    return res;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_solve(size_t m, size_t n, double *x,
                                                  plateau_lm_func func, void *user,
                                                  const plateau_lm_options *options,
                                                  void *work, size_t work_bytes,
                                                  plateau_lm_report *report,
                                                  plateau_lm_error *err)
{
    plateau_lm_result res = plateau__lm_solve(m, n, x, func, user, options, work, work_bytes,
                                              report);
    if (err) {
        const char *text = res == PLATEAU_LM_OK ? "" : plateau_lm_result_string(res);
        size_t i = 0, j;
        err->code = res;
        err->index = -1;
        if (res == PLATEAU_LM_ERR_NOT_FINITE_X0) /* x is untouched: name the entry */
            for (j = 0; j < n && err->index < 0; j++)
                if (!plateau__lm_finite(x[j])) err->index = (long)j;
        while (text[i] && i + 1 < sizeof err->message) {
            err->message[i] = text[i];
            i++;
        }
        err->message[i] = '\0';
    }
    return res;
}

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#endif
#endif /* PLATEAU_LM_IMPLEMENTATION */

/* HISTORY
 *   0.1.0  first release: MNT Algorithm 3.16 with MINPACK-style scaling, the
 *          m < n normal equations, finite differences, caller workspace.
 *
 * LICENCE (MIT)
 *   Copyright (c) 2026 the plateau authors.
 *   Permission is hereby granted, free of charge, to any person obtaining a
 *   copy of this software and associated documentation files (the
 *   "Software"), to deal in the Software without restriction, including
 *   without limitation the rights to use, copy, modify, merge, publish,
 *   distribute, sublicense, and/or sell copies of the Software, and to permit
 *   persons to whom the Software is furnished to do so, subject to the
 *   following conditions: The above copyright notice and this permission
 *   notice shall be included in all copies or substantial portions of the
 *   Software.  THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY
 *   KIND, EXPRESS OR IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF
 *   MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN
 *   NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM,
 *   DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR
 *   OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE
 *   USE OR OTHER DEALINGS IN THE SOFTWARE.
 */
