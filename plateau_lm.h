/* plateau_lm.h - nonlinear least squares: Levenberg-Marquardt after Madsen,
 * Nielsen and Tingleff ("Methods for non-linear least squares problems",
 * IMM, DTU, 2004) with box bounds, linear equality and inequality
 * constraints, weights, robust losses, geodesic acceleration, covariance
 * and a Jacobian check;
 * and a block-sparse direct solver (nested dissection, supernodal
 * multifrontal LU and Cholesky) with Powell's dog leg for large square
 * systems.  In plateau.h's pipeline it serves step 5, the solve.
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
 *   numeric_jacobian and the solver builds J by forward differences (not
 *   with PLATEAU_LM_NO_EXTRAS).
 *   Second part, LARGE SPARSE SYSTEMS: a direct solver for block-sparse
 *   matrices on a mesh's vertex graph (nested dissection, supernodal
 *   symbolic analysis, multifrontal LU with static block pivoting and
 *   Cholesky with a shift, and L D L^T with its inertia for symmetric
 *   indefinite matrices): plateau_lm_sparse_analyze / _factor_create /
 *   _factorize / _solve, documented where they are declared.
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
 *     PLATEAU_LM_NO_CONSTRAINTS  -                    leave out LINEAR CONSTRAINTS
 *                                                     (equalities and inequalities)
 *                                                     and BOUNDS (lower, upper):
 *                                                     plateau_lm_solve and
 *                                                     plateau_lm_covariance refuse them
 *                                                     (PLATEAU_LM_ERR_ARGUMENT; the
 *                                                     solve's message names the macro)
 *     PLATEAU_LM_NO_SPARSE       -                    leave out the sparse solvers (the
 *                                                     block-sparse direct solver and the
 *                                                     dog leg): their functions stay
 *                                                     declared and return
 *                                                     PLATEAU_LM_ERR_ARGUMENT (NULL
 *                                                     objects, zero sizes); the dense
 *                                                     LM is whole
 *     PLATEAU_LM_NO_EXTRAS       -                    leave out plateau_lm_covariance,
 *                                                     plateau_lm_check_jacobian (they
 *                                                     stay declared and return
 *                                                     PLATEAU_LM_ERR_ARGUMENT), the
 *                                                     robust losses, the weights, the
 *                                                     numeric Jacobian and geodesic
 *                                                     ALWAYS (plateau_lm_solve refuses
 *                                                     them, its message naming the
 *                                                     macro),
 *                                                     the REFINEMENT and the geodesic
 *                                                     acceleration (options.refine and
 *                                                     geodesic AUTO then mean never)
 *     PLATEAU_FREESTANDING       -                    no C library header but the
 *                                                     freestanding ones: the macros
 *                                                     above (and plateau_delaunay.h's
 *                                                     libm ones) must be defined, and
 *                                                     memcpy, memmove, memset linked
 *   Run time: plateau_lm_options, all-zero = these defaults (see them with
 *   plateau_lm_resolved_options()):
 *     tau 1e-6               mu0 = tau max diag(J^T J) (the paper), see below
 *     eps 1e-6               the three tolerances default to eps^2 = 1e-12:
 *     eps_grad, eps_step, eps_f
 *     f_stop                 DBL_EPSILON^2 min(F0, 1); negative: off
 *     max_iterations 1000    every solve of the damped system counts
 *     numeric_jacobian 0     non-zero: forward differences, step fd_step |x_j|
 *     fd_step                sqrt(DBL_EPSILON) (fd_step itself when x_j = 0); a
 *                            difference within 4 DBL_EPSILON (|f_i(x+h)| + |f_i(x)|)
 *                            is rounding and gives the entry 0
 *     scaling NONE           mu I; ADAPTIVE: mu D^2 as MINPACK (see below)
 *     geodesic AUTO          see GEODESIC ACCELERATION; geodesic_ratio 0.75
 *     refine 0               see REFINEMENT (m > n)
 *     lower, upper, weights  NULL: none (see BOUNDS, WEIGHTS AND ROBUST LOSSES)
 *     constraints, inequalities  0: none (see LINEAR CONSTRAINTS)
 *     loss SQUARED           loss_scale 1, max_irls 50
 *     allocator              PLATEAU_MALLOC / PLATEAU_FREE
 *     progress NULL          per-iteration callback (k, F, ||g||_inf, mu, accepted)
 *     tail_f_stop 0          plateau_lm_dogleg_solve: a step-test stop above it
 *                            goes on (tail_iterations 5 steps at most)
 *     chord 0                plateau_lm_dogleg_solve: the LU kept while steps
 *                            on it cut F 4-fold; negative: a new one each time;
 *                            positive: a new one each time, and chord steps
 *
 * API INDEX (every public function, one entry each: its signature with the
 * parameter names of its declaration, then what it does; the full comment
 * is at the declaration.  tests/test_api_index.c checks this list against
 * the declarations)
 *   Dense least squares (Levenberg-Marquardt)
 *     plateau_lm_result plateau_lm_solve(m, n, x, func, user, options, work, work_bytes, report, err)
 *         minimise 1/2 ||f(x)||^2 from the start x; the solution in x
 *     size_t plateau_lm_workspace_size(m, n, options)
 *         bytes of workspace plateau_lm_solve needs (0: overflow)
 *     plateau_lm_options plateau_lm_resolved_options(options)
 *         the options with every zero field replaced by its default
 *     const char *plateau_lm_result_string(result)
 *         the sentence for a result code
 *     const char *plateau_lm_stop_string(stop)
 *         what a stop reason means
 *   After a fit
 *     plateau_lm_result plateau_lm_covariance(m, n, x, func, user, options, cov, std_error, rank, work, work_bytes)
 *         covariance and standard errors of the parameters at a solution
 *     size_t plateau_lm_covariance_workspace_size(m, n, options)
 *         bytes of workspace plateau_lm_covariance needs
 *     plateau_lm_result plateau_lm_check_jacobian(m, n, x, func, user, options, check, verdicts, work, work_bytes)
 *         compares the callback's Jacobian with central differences
 *     size_t plateau_lm_check_workspace_size(m, n)
 *         bytes of workspace plateau_lm_check_jacobian needs
 *   Block-sparse direct solver (LARGE SPARSE SYSTEMS)
 *     plateau_lm_result plateau_lm_sparse_analyze(pattern, xy, options, symbolic)
 *         ordering and symbolic analysis of a block pattern
 *     void plateau_lm_sparse_symbolic_free(symbolic)
 *         frees an analysis
 *     plateau_lm_sparse_info plateau_lm_sparse_symbolic_info(symbolic)
 *         figures of an analysis (fill, flops, largest front)
 *     const plateau_index *plateau_lm_sparse_permutation(symbolic)
 *         the elimination order of an analysis
 *     size_t plateau_lm_sparse_factor_size(symbolic, kind)
 *         bytes of a factor object of a kind (LU, Cholesky, L D L^T)
 *     plateau_lm_result plateau_lm_sparse_factor_create(symbolic, kind, work, work_bytes, factor)
 *         a factor object, in the caller's workspace or allocated
 *     void plateau_lm_sparse_factor_free(factor)
 *         frees an allocated factor object
 *     plateau_lm_result plateau_lm_sparse_factorize(factor, values, shift)
 *         factorises A + shift I
 *     plateau_index plateau_lm_sparse_failed_node(factor)
 *         the node whose pivot failed in the last factorisation, or -1
 *     plateau_lm_result plateau_lm_sparse_inertia(factor, negative, positive)
 *         the numbers of negative and positive pivots of an L D L^T factor
 *     plateau_lm_result plateau_lm_sparse_solve(factor, nrhs, b, ldb)
 *         solves (A + shift I) X = B in place
 *     plateau_lm_result plateau_lm_dogleg_solve(pattern, xy, x, func, user, options, report)
 *         Powell's dog leg for a square sparse system f(x) = 0
 *     plateau_lm_result plateau_lm_dogleg_solve_kept(pattern, xy, x, func, user, options, report, keep)
 *         the same, its LU object and vectors kept in *keep for the next solve
 *     size_t plateau_lm_dogleg_keep_bytes(keep)
 *         the bytes a keep holds
 *     void plateau_lm_dogleg_keep_free(keep)
 *         frees a keep
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
 *   What differs from Fig. 5, and why (the measurements on the 45 MGH
 *   variants of tests/lm_mgh.h: examples/NOTES.md, "plateau_lm.h"):
 *   - mu0 = max(tau max a_ii, ||g|| / (10 max(||x0||, 1))).  ||h|| <= ||g|| / mu,
 *     so the first step is at most ten times the size of the start: from a
 *     far start, Fig. 5's mu0 = 1e-6 max a_ii gives a wild Gauss-Newton step
 *     and a long run of rejections.
 *   - mu / 10 after a very good step (Nielsen's rule divides by at most 3):
 *     like MINPACK doubling its trust radius, it reaches Gauss-Newton speed
 *     sooner.
 *   - No scaling by default.  MINPACK's D (d_j = largest ||column j|| seen)
 *     is available as PLATEAU_LM_SCALING_ADAPTIVE, then mu I becomes mu D^2;
 *     it wins on badly scaled problems but, never shrinking, it crawls once
 *     a far start has inflated the column norms.
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
 *   - DAMPING: mu > 1e300 max(max_j a_jj, 1): no step lowers F in floating
 *     point (relative to J^T J's scale: uniform weights 1e200 or 1e300 run
 *     as weights 1 do).
 *   (With scaling ADAPTIVE the norms and a_jj are those of the scaled
 *   problem: ||D h||, ||D x||, diag(D^-1 A D^-1).)
 *
 * NON-FINITE VALUES
 *   NaN or Inf in x0: PLATEAU_LM_ERR_NOT_FINITE_X0 (x untouched).  In the
 *   residual at x0 (or F overflowing): PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL.  At
 *   a trial point x + h the step counts as failed (rho < 0: mu grows, the
 *   step shrinks): a trial point may leave the domain of f (a log, a square
 *   root) and a shorter step is the sound answer; but a run that ends on the
 *   step or damping test having met no finite residual at any trial point
 *   is PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL (x0 is the only point where f was
 *   finite, not a minimum).  In the Jacobian (analytic,
 *   or a difference whose forward and backward residuals are both
 *   non-finite): PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN.  After any error or abort
 *   x holds the start or the last accepted point: no NaN or Inf is ever
 *   written to x, and report->f_final is F at that x.
 *
 * MEMORY
 *   plateau_lm_workspace_size(m, n, options) bytes: 8 (W + 1) with W doubles,
 *   W = m n + 2 k^2 + 2 m + 5 n + k, k = min(m, n), plus m n + m + 3 n for
 *   the refinement (m > n, refine >= 0), m for weights or a loss, n for
 *   bounds and m + n for the geodesic acceleration (unless NEVER).  With
 *   linear constraints: W of the solve in y (computed for n parameters,
 *   without the box), plus m n + m + 3 n (refine >= 0), plus the map back
 *   n n + m n + n k + 3 max(n, k) + 4 n for k equalities; with p inequality
 *   rows (p = k' + n for each side of the box given) the solve in y has
 *   k = n, no geodesic part, and 2 p n + 3 p + n^2 + 10 n more for the
 *   quadratic programs.  (tests/test_lm_fit.c checks these formulas.)  With a caller
 *   workspace (any alignment) the solver allocates nothing; with work =
 *   NULL it makes one allocation through options.allocator (or
 *   PLATEAU_MALLOC) and frees it before returning.  Every size product is
 *   overflow-checked.
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
 * REFINEMENT (m > n, options.refine = 0; negative: off)
 *   The damped steps solve the normal equations, whose condition number is
 *   that of J squared: on an ill-conditioned fit they stop moving while x is
 *   still far from the least-squares solution in its last digits.  After the
 *   main loop stops on STEP, F_CHANGE or GRADIENT, up to 40 Gauss-Newton
 *   steps h = argmin ||J h + f|| from a Householder QR with column pivoting
 *   of J itself polish x; a step is kept when F falls, or when the gradient
 *   measure of GRADIENT falls while F grows by no more than 1e-10 F
 *   (rounding); a step longer than 0.01 sqrt(||x||^2 + 1) is not tried (no
 *   polish: where f does not depend on a parameter, its column of J is
 *   rounding noise and so is the step).  Each costs one residual and one
 *   Jacobian.
 *   report->refinement_steps counts them.  Square and underdetermined
 *   systems (plateau.h's) are not refined.  With inequality rows (LINEAR
 *   CONSTRAINTS) the Gauss-Newton step is the quadratic program's with
 *   mu = DBL_EPSILON max_j a'_jj (keeping to the rows), kept by the same rule.
 *
 * BOUNDS (options.lower, options.upper: n values each, or NULL)
 *   Every iterate, trial point and difference point stays in the box
 *   (numeric differences step inwards).  A parameter on its bound whose
 *   gradient points out of the box is held there (the binding set of
 *   Bertsekas' projected Newton method): its row and column leave the
 *   damped system and its gradient entry is 0, so the gradient test is on
 *   the projected gradient.  A trial point is projected onto the box and,
 *   if the projection moved it, judged against the Gauss-Newton model of the
 *   projected step.  -inf / +inf leave a side open.  Errors: BAD_BOUNDS
 *   (NaN, lower > upper, lower = +inf or upper = -inf), X0_OUTSIDE_BOUNDS
 *   (bounds alone).  Bounds together with linear constraints: see LINEAR
 *   CONSTRAINTS.  PLATEAU_LM_NO_CONSTRAINTS leaves bounds out with the
 *   constraints (PLATEAU_LM_ERR_ARGUMENT).
 *
 * LINEAR CONSTRAINTS (options.constraints = k rows of A x = b, a_eq: k x n,
 *   b_eq; options.inequalities = k' rows of C x >= d, c_ineq: k' x n, d_ineq)
 *   Equalities: x = x_p + Z y with Z an orthonormal basis of the null space
 *   of A (from a QR with column pivoting of A^T; redundant rows are fine)
 *   and x_p the minimum-norm solution; the solve runs on y with the
 *   Jacobian J Z, from the projection of x0.  report->free_parameters = n -
 *   rank A.
 *   Inequalities, and bounds together with equalities, become rows
 *   G y >= e on y (a bound l_j: the row j of Z; a row c of C: c Z), and
 *   every step solves the damped model as a small quadratic program:
 *       min g'^T h + 1/2 h^T (A' + mu I) h   subject to  G D^-1 h >= e - G y
 *   by Goldfarb and Idnani's dual active-set method, so every trial point
 *   satisfies every row; rho is judged on the Gauss-Newton model of the
 *   step, and the gradient test on the gradient projected onto the cone of
 *   feasible directions (0 at a constrained stationary point).  The start
 *   is moved first to the nearest point of {A x = b, C x >= d, lower <= x <=
 *   upper} (the same kind of program, with H = I): there x0 may lie outside
 *   the box.  No geodesic acceleration there (its step ignores the rows);
 *   REFINEMENT's steps are the programs of the undamped model.  Rows with
 *   no common point, or A, b, C, d holding a NaN or an infinity:
 *   INCONSISTENT_CONSTRAINTS.
 *
 * WEIGHTS AND ROBUST LOSSES (PLATEAU_LM_NO_EXTRAS leaves both out)
 *   options.weights w_i >= 0: F = 1/2 sum w_i f_i^2 (rows scaled by sqrt(w_i)).
 *   options.loss HUBER or CAUCHY with scale c = loss_scale: minimises
 *   sum rho(sqrt(w_i) f_i) by iteratively reweighted least squares (each
 *   round a weighted solve with omega_i = rho'(t_i) / t_i from the last
 *   point) until no omega moves by more than 1e-10 or max_irls rounds;
 *   report->f_initial / f_final are then sum rho.
 *
 * GEODESIC ACCELERATION (options.geodesic, PLATEAU_LM_GEODESIC_AUTO by default)
 *   Transtrum and Sethna's second-order correction: with the LM step v and
 *   f_vv ~ (2 / t) ((f(x + t v) - f(x)) / t - J v), t = 0.1, the step
 *   becomes v + a / 2, a the damped solution for f_vv, when 2 ||a|| <=
 *   geodesic_ratio ||v|| (0.75); otherwise the step is rejected untried
 *   and mu raised (the second-order term says the model does not hold that
 *   far, as in GSL).  One more residual per accelerated iteration.  AUTO
 *   accelerates the first step and every step after a trial step h on
 *   which f proved nonlinear, ||f(x + h) - f(x) - J h|| >= 0.5 ||J h||: along
 *   a curved valley (NIST's MGH10 from its first start, which the plain
 *   step does not finish in 1000 iterations) it follows the curve; where f
 *   is nearly linear the probe would be a wasted evaluation.  ALWAYS:
 *   every iteration; NEVER: the plain step of Algorithm 3.16 (plateau.h's
 *   mesh solves use it).  The figures with and without, on the MGH and
 *   NIST sets: examples/NOTES.md, "plateau_lm.h".
 *
 * EVIDENCE (make bench; tests/test_lm.c, tests/test_lm_fit.c,
 *   tests/test_lm_sparse.c): the Moré-Garbow-Hillstrom set from 1, 10 and
 *   100 x the standard start, NIST StRD's 27 nonlinear regression problems
 *   from both starts (certified parameters and standard deviations), the
 *   bounded problems of Hock and Schittkowski and CUTE and the linearly
 *   constrained ones of levmar's demo (HS235, BT7, HS52 #1 and #2); the
 *   counts are in the tests and in examples/NOTES.md.
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
    X(PLATEAU_LM_ERR_ABORTED, -8, "a callback (residual, progress or cancel) returned non-zero") \
    X(PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL, -9,                                       \
      "work_bytes is smaller than plateau_lm_workspace_size()")                     \
    X(PLATEAU_LM_ERR_BAD_PATTERN, -10,                                              \
      "the sparse pattern has an offset or column out of range, a repeated block, "  \
      "no diagonal block, or is not structurally symmetric")                        \
    X(PLATEAU_LM_ERR_SINGULAR_PIVOT, -11,                                           \
      "sparse LU: a diagonal block is singular or a pivot of the block-scaled matrix is tiny") \
    X(PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE, -12,                                    \
      "sparse Cholesky: a pivot is not positive (the matrix plus shift is not positive definite)") \
    X(PLATEAU_LM_ERR_NOT_FACTORED, -13, "the sparse factor object holds no valid factorisation") \
    X(PLATEAU_LM_ERR_NOT_FINITE_MATRIX, -14, "the sparse matrix values hold a NaN or an infinity") \
    X(PLATEAU_LM_ERR_BAD_BOUNDS, -15,                                               \
      "a bound is NaN, a lower bound is above its upper bound, or one is +inf (lower) or -inf (upper)") \
    X(PLATEAU_LM_ERR_X0_OUTSIDE_BOUNDS, -16, "the start x lies outside the box [lower, upper]") \
    X(PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS, -17,                                 \
      "the linear constraints (A x = b, C x >= d and the bounds with them) have no common "  \
      "solution, or A, b, C or d holds a NaN or an infinity")                       \
    X(PLATEAU_LM_ERR_RANK_DEFICIENT, -18,                                           \
      "covariance: the Jacobian has rank below n, so some parameters are not determined") \
    X(PLATEAU_LM_ERR_NO_DEGREES_OF_FREEDOM, -19,                                    \
      "covariance: m is not larger than the number of free parameters, s^2 = 2F / (m - n) is undefined")

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

/* Geodesic acceleration (options.geodesic; see GEODESIC ACCELERATION at the
 * top).  Tri-state like options.refine: 0 automatic, positive always,
 * negative never. */
typedef enum plateau_lm_geodesic {
    PLATEAU_LM_GEODESIC_AUTO = 0,   /* default: after a trial step on which f proved nonlinear */
    PLATEAU_LM_GEODESIC_ALWAYS = 1, /* every iteration (as GSL's multifit_nlinear offers it) */
    PLATEAU_LM_GEODESIC_NEVER = -1  /* the plain LM step of MNT Algorithm 3.16 */
} plateau_lm_geodesic;

/* Robust loss of the residuals (options.loss), applied by iteratively
 * reweighted least squares: rho(r) replaces r^2 / 2 with scale c = loss_scale. */
typedef enum plateau_lm_loss {
    PLATEAU_LM_LOSS_SQUARED = 0, /* default: rho = r^2 / 2, plain least squares */
    PLATEAU_LM_LOSS_HUBER = 1,   /* rho = r^2 / 2 for |r| <= c, c |r| - c^2 / 2 beyond */
    PLATEAU_LM_LOSS_CAUCHY = 2   /* rho = c^2 / 2 log(1 + (r / c)^2) */
} plateau_lm_loss;

/* Residual callback: evaluate f(x) (m values) into f; if jac is not NULL,
 * also the Jacobian, row-major m x n: jac[i * n + j] = d f_i / d x_j.
 * Return 0 to go on, non-zero to abort the solve (PLATEAU_LM_ERR_ABORTED).
 * It may return NaN or Inf residuals at trial points: see "Non-finite values". */
typedef int (*plateau_lm_func)(const double *x, double *f, double *jac, void *user);

/* Per-iteration callback: k (1, 2, ...), F at the current (accepted) point,
 * ||J^T f||_inf there, the damping mu for the next iteration, and whether this
 * iteration's step was accepted.  Not called for an iteration that ends the
 * solve by the step test (it takes no step), nor for REFINEMENT's steps.
 * user is the solve's user pointer.  Return non-zero to abort
 * (PLATEAU_LM_ERR_ABORTED; x keeps the last accepted point). */
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
    /* ---- fitting fields (all-zero: as without them, except refine) ---- */
    const double *lower, *upper; /* n box bounds each, or NULL (unbounded); -inf /
                                    +inf entries leave a side open (see BOUNDS) */
    const double *weights;     /* m weights w_i >= 0: F = 1/2 sum w_i f_i^2; NULL -> 1 */
    plateau_lm_loss loss;      /* robust loss by IRLS; 0 -> PLATEAU_LM_LOSS_SQUARED */
    double loss_scale;         /* residual size where the loss turns robust; 0 -> 1 */
    int max_irls;              /* IRLS rounds for a robust loss; 0 -> 50 */
    plateau_lm_geodesic geodesic; /* Transtrum-Sethna's second-order correction;
                                     0 -> PLATEAU_LM_GEODESIC_AUTO */
    double geodesic_ratio;     /* largest 2 ||a|| / ||v|| accepted; 0 -> 0.75 */
    size_t constraints;        /* k rows of A x = b; 0 -> none */
    const double *a_eq;        /* k x n row-major A (with constraints) */
    const double *b_eq;        /* k values b (with constraints) */
    int refine;                /* 0: refine least-squares fits (m > n, see
                                  REFINEMENT); negative: never */
    size_t inequalities;       /* k' rows of C x >= d; 0 -> none */
    const double *c_ineq;      /* k' x n row-major C (with inequalities) */
    const double *d_ineq;      /* k' values d (with inequalities) */
    /* ---- a time limit ---- */
    int (*cancel)(void *user); /* NULL: none; plateau_lm_dogleg_solve passes it (with
                                  the solve's user pointer) to its sparse
                                  factorisations (plateau_lm_sparse_options.cancel):
                                  non-zero abandons the solve as a callback does
                                  (PLATEAU_LM_ERR_ABORTED, x the last accepted
                                  point); plateau_lm_solve does not use it */
    /* ---- plateau_lm_dogleg_solve only (see there) ---- */
    double tail_f_stop;        /* > 0: a STEP stop above it goes on as a tail; 0 -> none */
    int tail_iterations;       /* the tail's steps at most; 0 -> 5 */
    int chord;                 /* 0: keep an LU as GMRES's preconditioner
                                  (see plateau_lm_dogleg_solve); negative: a
                                  new LU at every Jacobian; positive: a new LU
                                  at every Jacobian, and plain chord steps on
                                  it in the quadratic regime */
} plateau_lm_options;

typedef struct plateau_lm_report {
    size_t iterations;            /* damped systems solved */
    size_t residual_evaluations;  /* callback calls for f alone (finite differences included) */
    size_t jacobian_evaluations;  /* Jacobians formed (analytic calls, or difference sweeps) */
    double f_initial, f_final; /* F = 1/2 ||f||^2 */
    double grad_inf;           /* ||J^T f||_inf at the end */
    double mu_final;
    plateau_lm_stop stop;      /* why the iteration ended */
    /* ---- fitting fields ---- */
    size_t refinement_steps;   /* accepted Gauss-Newton steps of REFINEMENT */
    size_t accelerated_steps;  /* accepted steps that carried a geodesic acceleration */
    size_t irls_rounds;        /* weighted solves of a robust loss (0 without one) */
    size_t active_bounds;      /* parameters at a bound at the end */
    size_t free_parameters;    /* n less the rank of the constraints */
} plateau_lm_report;

/* Detail for a failed plateau_lm_solve, the same shape as plateau.h's
 * plateau_error and plateau_delaunay.h's plateau_dt_error. */
typedef struct plateau_lm_error {
    plateau_lm_result code;
    long index;        /* the offending entry of x (NOT_FINITE_X0); -1 if none */
    long index2;       /* a second one where an error names two; -1 (the same
                          layout as plateau.h's plateau_error) */
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
/* Bytes of workspace plateau_lm_solve needs with these options (see MEMORY),
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

/* ---- Covariance and standard errors ----------------------------------------
 * At a solution x of plateau_lm_solve: the Jacobian J there (analytic, or
 * differences with options->numeric_jacobian; rows scaled by sqrt(w_i) with
 * options->weights), its Householder QR with column pivoting J P = Q R
 * (Businger-Golub: rank-revealing), and
 *     cov = s^2 (J^T J)^-1 = s^2 P R^-1 R^-T P^T,   s^2 = 2F / (m - n),
 * std_error_j = sqrt(cov_jj).  With constraints A x = b (options) the
 * parameters move in the null space Z of A: cov = s^2 Z (Z^T J^T J Z)^-1 Z^T
 * and m - n becomes m - (n - rank A).  Bounds and inequalities are ignored
 * (the estimate is that of the fit without them at x).  The rank: columns whose pivot
 * |r_kk| falls below 1e-12 |r_11| after scaling each column of J to unit
 * length; rank < n gives PLATEAU_LM_ERR_RANK_DEFICIENT (with *rank set)
 * rather than a covariance that rounding decides.  cov (n x n row-major)
 * and std_error (n) may each be NULL; on error both are zeroed.
 * work: plateau_lm_covariance_workspace_size() bytes, or NULL to allocate
 * through options->allocator.  rank may be NULL.
 * Errors: ARGUMENT, EMPTY, OVERFLOW, OUT_OF_MEMORY, WORKSPACE_TOO_SMALL,
 * NOT_FINITE_X0, NOT_FINITE_RESIDUAL, NOT_FINITE_JACOBIAN, ABORTED,
 * INCONSISTENT_CONSTRAINTS, NO_DEGREES_OF_FREEDOM, RANK_DEFICIENT. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_covariance(size_t m, size_t n, const double *x,
                                                       plateau_lm_func func, void *user,
                                                       const plateau_lm_options *options,
                                                       double *cov, double *std_error,
                                                       size_t *rank, void *work,
                                                       size_t work_bytes);
PLATEAU_LM_DEF size_t plateau_lm_covariance_workspace_size(size_t m, size_t n,
                                                           const plateau_lm_options *options);

/* ---- Jacobian check -------------------------------------------------------------
 * Compares an analytic Jacobian with central differences at x, entry by
 * entry (MINPACK's chkder, made explicit).  Column j: step
 * h_j = cbrt(DBL_EPSILON) max(|x_j|, 1), difference quotients D(h) and
 * D(2h); the difference's error is estimated from their gap (truncation,
 * Richardson: |D(h) - D(2h)| / 3) plus the rounding of f (4 eps (|f(x+h)| +
 * |f(x-h)|) / h).  Entry (i, j) is WRONG when
 *     |J_ij - D_ij| > tolerance max(|J_ij|, |D_ij|) + 10 (estimated error),
 * tolerance = options->eps_grad if set, else 1e-6.  verdicts (m x n
 * row-major, may be NULL) gets PLATEAU_LM_JACOBIAN_OK or _WRONG per entry.
 * Costs 4 n residual calls and one Jacobian call.  Returns OK when the check
 * ran (check->wrong says whether J is wrong); errors as plateau_lm_solve's. */
typedef enum plateau_lm_jacobian_verdict {
    PLATEAU_LM_JACOBIAN_OK = 0,
    PLATEAU_LM_JACOBIAN_WRONG = 1
} plateau_lm_jacobian_verdict;
typedef struct plateau_lm_jacobian_check {
    size_t wrong;          /* entries judged wrong */
    long worst_row, worst_col; /* the entry of largest error over its allowance; -1 if none */
    double worst_ratio;    /* that entry's |J_ij - D_ij| / allowance (> 1: wrong) */
    double worst_analytic, worst_difference; /* J_ij and D_ij there */
} plateau_lm_jacobian_check;
PLATEAU_LM_DEF plateau_lm_result plateau_lm_check_jacobian(size_t m, size_t n, const double *x,
                                                           plateau_lm_func func, void *user,
                                                           const plateau_lm_options *options,
                                                           plateau_lm_jacobian_check *check,
                                                           unsigned char *verdicts,
                                                           void *work, size_t work_bytes);
PLATEAU_LM_DEF size_t plateau_lm_check_workspace_size(size_t m, size_t n);

/* ==== Large sparse systems: a block-sparse direct solver ====================
 * For the square and the symmetric positive definite systems of a mesh
 * (unknowns per vertex, couplings along edges): A is n x n in blocks of
 * b x b (b = 1..4), its block pattern structurally symmetric (block (i, k)
 * is stored exactly when block (k, i) is) and every diagonal block stored.
 *
 *   plateau_lm_sparse_analyze       ordering + symbolic analysis, once per pattern
 *   plateau_lm_sparse_factor_create the numeric object (one allocation, or yours)
 *   plateau_lm_sparse_factorize     LU or Cholesky of A + shift I, any number
 *                                   of times on the same pattern
 *   plateau_lm_sparse_solve         x = A^-1 b for one or several right-hand sides
 *
 *   ORDERING (fill reduction; George's nested dissection): the node graph is
 *   split recursively into two halves and the vertex separator between them,
 *   numbered last.  With node coordinates (xy: 2 per node, e.g. a mesh's
 *   planar domain) each split is a median cut across the longer side of the
 *   bounding box; without, the halves are the levels of a breadth-first
 *   search from a pseudo-peripheral node (Gibbs-Poole-Stockmeyer) before and
 *   from the median level on.  The separator is a minimum vertex cover of
 *   the edges between the halves (Konig's theorem on a maximum matching),
 *   then thinned (a node without a neighbour on one side joins that side,
 *   which keeps the sides apart).  Parts of at most leaf_nodes nodes are not
 *   split further.
 *   SYMBOLIC ANALYSIS (Liu; Davis, "Direct methods for sparse linear
 *   systems", ch. 4): elimination tree, its postorder (same fill, contiguous
 *   subtrees), column counts by row subtrees, fundamental supernodes then
 *   relaxed amalgamation (a child joins its parent when few explicit zeros
 *   are added: at most 4 nodes always, up to 16 with <= 80 %, up to 48 with
 *   <= 10 %, any size with <= 5 % zeros), the row structure of each
 *   supernode, and a simulation of the multifrontal stack that sizes it.
 *   NUMERIC FACTORISATION (multifrontal; Duff and Reid, Liu 1992): for each
 *   supernode in postorder, a dense frontal matrix gathers the supernode's
 *   columns (and, for LU, rows) of A and the update matrices of its children
 *   (extend-add), is factored on its pivot columns by a blocked LU or
 *   Cholesky (panels of 32 columns factored left-looking with rank-4 column
 *   updates; the trailing update a packed, register-blocked matrix
 *   product), and leaves its Schur complement on the stack.
 *   LU: no pivoting.  Each node's b rows are first multiplied by the inverse
 *   of its b x b diagonal block (static block pivoting: the scaled matrix
 *   has identity diagonal blocks); a pivot |u_kk| < pivot_tol (default
 *   1e-10) in the scaled matrix, a singular diagonal block or a non-finite
 *   value ends it with PLATEAU_LM_ERR_SINGULAR_PIVOT and the node
 *   (plateau_lm_sparse_failed_node), so the caller can damp (shift) and retry.
 *   Cholesky: A + shift I = L L^T, reading the symmetric A from the blocks
 *   at or below the diagonal in elimination order (both halves must agree);
 *   a pivot <= 0 or not finite gives PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE.
 *   LDL^T: A + shift I = L D L^T with L unit lower triangular and D
 *   diagonal, from the same lower half, no pivoting (1x1 pivots in
 *   elimination order; the trailing update is L21 (D L21^T), with D L21^T
 *   kept in the front's unused upper half).  By Sylvester's law of inertia
 *   the signs of D count the eigenvalues of A + shift I below, at and above
 *   zero (plateau_lm_sparse_inertia): the stability index of a Hessian.  A
 *   pivot with |d| < pivot_tol max_i |a_ii + shift| or not finite ends it
 *   with PLATEAU_LM_ERR_SINGULAR_PIVOT and the node: the inertia is then
 *   unknown, and the caller retries with another shift.  Without pivoting
 *   the factors can grow on a strongly indefinite matrix; near-definite
 *   matrices (a Hessian near a minimum or a saddle of low index) are what
 *   it is for.
 *
 *   MEMORY: the analysis allocates a temporary block (about 215 n + 20 nnz
 *   bytes, nnz = stored blocks) and the symbolic object; the factor object is
 *   one block of plateau_lm_sparse_factor_size() bytes (factor, stack of
 *   update matrices, the largest front, scratch) that you may provide.
 *   Every size is overflow-checked (PLATEAU_LM_ERR_OVERFLOW); allocation
 *   failure returns PLATEAU_LM_ERR_OUT_OF_MEMORY with nothing leaked.
 *   THREADS: no global state; a factor object serves one solve at a time
 *   (its scratch vector), a symbolic object any number of factor objects.
 *   EVIDENCE: make bench (bench/bench_sparse.c) against UMFPACK and CHOLMOD;
 *   the measurements are in examples/NOTES.md. */

typedef struct plateau_lm_sparse_pattern {
    size_t nodes;                   /* n: block rows = block columns */
    int block;                      /* b: unknowns per node, 1..4 */
    const plateau_index *row_start; /* n + 1 offsets into cols, row_start[0] = 0 */
    const plateau_index *cols;      /* the block columns of each block row, any
                                       order, each once, the diagonal included */
} plateau_lm_sparse_pattern;
/* The values of A are given to plateau_lm_sparse_factorize as row_start[n]
 * blocks of b x b doubles, row-major, in the order of cols: entry (r, c) of
 * block p is values[p b^2 + r b + c]; unknown t of node i is i b + t. */

typedef enum plateau_lm_sparse_ordering {
    PLATEAU_LM_SPARSE_ORDER_AUTO = 0,      /* nested dissection: geometric when xy is given */
    PLATEAU_LM_SPARSE_ORDER_GEOMETRIC = 1, /* nested dissection by coordinates (needs xy) */
    PLATEAU_LM_SPARSE_ORDER_GRAPH = 2,     /* nested dissection by BFS levels */
    PLATEAU_LM_SPARSE_ORDER_NATURAL = 3    /* the given order (for comparison) */
} plateau_lm_sparse_ordering;

typedef enum plateau_lm_sparse_kind {
    PLATEAU_LM_SPARSE_LU = 1,      /* square, structurally symmetric */
    PLATEAU_LM_SPARSE_CHOLESKY = 2, /* symmetric positive definite */
    PLATEAU_LM_SPARSE_LDLT = 3      /* symmetric, maybe indefinite: L D L^T, 1x1 pivots */
} plateau_lm_sparse_kind;

/* The front work (multiply-adds) between two questions to
 * plateau_lm_sparse_options.cancel: about 0.05 s at 1 to 2 Gflop/s, and a
 * clock reading per question costs nothing beside it. */
#define PLATEAU_LM_CANCEL_FLOPS 67108864.0

typedef struct plateau_lm_sparse_options {
    /* all-zero means the documented defaults */
    int ordering;        /* a plateau_lm_sparse_ordering; 0 -> AUTO */
    size_t leaf_nodes;   /* dissection stops at parts this small; 0 -> 8 */
    double pivot_tol;    /* LU: smallest |pivot| of the block-scaled matrix; LDL^T: of
                            |d| / max |a_ii + shift|; 0 -> 1e-10 */
    plateau_allocator allocator; /* for the analysis and every factor object */
    int (*cancel)(void *user); /* NULL: none; else asked by plateau_lm_sparse_factorize
                            about every PLATEAU_LM_CANCEL_FLOPS of front work (a time
                            limit: one factorisation can take seconds); non-zero
                            abandons it with PLATEAU_LM_ERR_ABORTED */
    void *cancel_user;   /* passed to cancel */
} plateau_lm_sparse_options;

/* What an analysis found (plateau_lm_sparse_symbolic_info). */
typedef struct plateau_lm_sparse_info {
    size_t nodes, block, unknowns;  /* n, b, n b */
    size_t pattern_blocks;          /* stored blocks of A */
    size_t factor_blocks;           /* blocks of L, diagonal included (the fill, before
                                       amalgamation); U has the same pattern transposed */
    size_t supernodes, largest_front; /* largest front: unknowns */
    double flops_cholesky, flops_lu; /* multiply-adds counted as 2 flops */
    size_t factor_bytes_lu, factor_bytes_cholesky; /* plateau_lm_sparse_factor_size */
} plateau_lm_sparse_info;

typedef struct plateau_lm_sparse_symbolic plateau_lm_sparse_symbolic;
typedef struct plateau_lm_sparse_factor plateau_lm_sparse_factor;

/* Ordering and symbolic analysis of a pattern (copied: the caller's arrays
 * may go away).  xy: 2 n node coordinates or NULL.  options may be NULL.
 * On success *symbolic is a new object (free it with
 * plateau_lm_sparse_symbolic_free); on error it is NULL.  Errors: EMPTY (no nodes),
 * ARGUMENT (a NULL pointer, block not 1..4, unknown
 * ordering, GEOMETRIC without xy, a non-finite coordinate, pivot_tol
 * negative, a half allocator), BAD_PATTERN, OVERFLOW, OUT_OF_MEMORY. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_analyze(const plateau_lm_sparse_pattern *pattern,
                                                           const double *xy,
                                                           const plateau_lm_sparse_options *options,
                                                           plateau_lm_sparse_symbolic **symbolic);
PLATEAU_LM_DEF void plateau_lm_sparse_symbolic_free(plateau_lm_sparse_symbolic *symbolic);
/* Figures of the analysis (zeros for NULL). */
PLATEAU_LM_DEF plateau_lm_sparse_info plateau_lm_sparse_symbolic_info(const plateau_lm_sparse_symbolic *symbolic);
/* The elimination order: position k eliminates node permutation[k] (n values);
 * NULL for NULL. */
PLATEAU_LM_DEF const plateau_index *plateau_lm_sparse_permutation(const plateau_lm_sparse_symbolic *symbolic);

/* Bytes of a factor object of this kind (alignment slack included); 0 for a
 * NULL symbolic, an unknown kind or an overflow. */
PLATEAU_LM_DEF size_t plateau_lm_sparse_factor_size(const plateau_lm_sparse_symbolic *symbolic,
                                                    int kind);
/* A factor object of the given kind for this analysis (which must outlive
 * it), in work (work_bytes >= plateau_lm_sparse_factor_size(), any
 * alignment; nothing is allocated) or, with work = NULL, in one allocation
 * through the analysis' allocator.  *factor is NULL on error. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factor_create(const plateau_lm_sparse_symbolic *symbolic,
                                                                 int kind, void *work,
                                                                 size_t work_bytes,
                                                                 plateau_lm_sparse_factor **factor);
/* Frees an allocated factor object (a caller workspace is left alone); NULL is fine. */
PLATEAU_LM_DEF void plateau_lm_sparse_factor_free(plateau_lm_sparse_factor *factor);
/* Factorises A + shift I (values: see plateau_lm_sparse_pattern; shift >= 0
 * finite, 0 for A itself).  Errors: ARGUMENT (a NULL pointer, or the shift),
 * SINGULAR_PIVOT (LU, LDL^T), NOT_POSITIVE_DEFINITE (Cholesky), ABORTED (the
 * analysis' options.cancel returned non-zero); after an error the
 * object stays valid for another plateau_lm_sparse_factorize, and
 * plateau_lm_sparse_solve refuses it (NOT_FACTORED). */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factorize(plateau_lm_sparse_factor *factor,
                                                             const double *values, double shift);
/* The node whose pivot failed in the last factorisation, or -1. */
PLATEAU_LM_DEF plateau_index plateau_lm_sparse_failed_node(const plateau_lm_sparse_factor *factor);
/* The inertia of A + shift I from the last successful LDL^T factorisation:
 * the numbers of negative and positive pivots of D (Sylvester's law: the
 * eigenvalues below and above zero; none is zero, else the factorisation
 * failed).  Errors: ARGUMENT (a NULL pointer, or a factor of another kind),
 * NOT_FACTORED. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_inertia(const plateau_lm_sparse_factor *factor,
                                                           size_t *negative, size_t *positive);
/* Solves (A + shift I) X = B in place: b holds nrhs columns of n b values,
 * column j at b + j ldb (ldb >= n b; unused when nrhs is 1).  Cholesky and
 * L D L^T take the columns in pairs, reading L once for two (the result is
 * that of one column at a time, bit for bit).  Errors:
 * ARGUMENT (a NULL pointer, or ldb), NOT_FACTORED. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_solve(plateau_lm_sparse_factor *factor,
                                                         size_t nrhs, double *b, size_t ldb);

/* ---- Powell's dog leg for square sparse systems ----------------------------
 * Solves f(x) = 0 (or minimises F = 1/2 ||f||^2) for f: R^N -> R^N whose
 * Jacobian has the block pattern of a plateau_lm_sparse_pattern (N = n b):
 * Madsen-Nielsen-Tingleff Algorithm 3.21, the Gauss-Newton step h_gn from
 * the sparse LU of J (analysed once), the steepest-descent step h_sd = -alpha g
 * with alpha = ||g||^2 / ||J g||^2, g = J^T f, and the trust region radius
 * Delta:
 *   ||h_gn|| <= Delta:          h = h_gn
 *   ||alpha g|| >= Delta:       h = -(Delta / ||g||) g
 *   else                        h = alpha h_sd + beta (h_gn - alpha h_sd), ||h|| = Delta.
 *   rho = (F(x) - F(x + h)) / (L(0) - L(h)); rho > 0: accept;
 *   rho > 3/4: Delta := max(Delta, 3 ||h||); rho < 1/4: Delta := Delta / 2.
 * Delta0 = max(||x0||, 1).  When the LU fails (a singular pivot) the step
 * is the steepest-descent one, clipped to Delta.
 * Factorisation reuse: after a full Gauss-Newton step with rho > 3/4 that
 * cut F at least 4-fold, the next iterations keep the LU of that earlier
 * Jacobian J_old and get h_gn from GMRES(8) on J h = -f with the current J,
 * right-preconditioned by J_old^-1 (an inexact Newton step: relative
 * residual 1e-4; when 8 Krylov vectors leave it above 0.5 the LU is taken
 * anew at once, above 0.1 the step is tried and the LU taken anew at the
 * next iteration); the model decrease L(0) - L(h) is then evaluated with
 * the current J.  The LU is kept while each such step cuts F 4-fold with
 * rho >= 1/4; otherwise it is taken anew (at once, Delta unchanged, when
 * the step is rejected); the F-change test counts only steps from a fresh
 * LU (the time per step with and without: examples/NOTES.md).  The kept
 * LU is a preconditioner only: its L and U are rounded to float in place
 * (half the bytes for each of GMRES's sparse solves, which memory bounds).
 * options.chord < 0: no reuse, a new LU at every Jacobian.
 * options.chord > 0 (plateau.h's choice: there a GMRES step costs as much
 * as an LU): a new LU at every Jacobian, and after a full Newton step from
 * it that cut F to at most 1e-3 F (the quadratic regime) chord steps
 * h = -M^-1 f(x) on that LU M, with no Jacobian (Kelley's chord method in
 * Shamanskii's manner): each a trial (an iteration, a residual, the
 * progress callback) accepted when it lowers F within the trust radius,
 * going on while each cuts F to at most 1e-2 F; the step test applies to
 * them (a tail due starts there, and they go on under its bound; in a tail
 * they do not count against tail_iterations, only max_iterations).
 * Stopping rules and report fields are those of plateau_lm_solve (SMALL_F,
 * GRADIENT by the cosine test, STEP when ||h|| or Delta falls to
 * eps_step (||x|| + floor), F_CHANGE on accepted steps, MAX_ITERATIONS),
 * with report->mu_final holding the final Delta; the SMALL_F stop forms no
 * Jacobian at the final point, so report->grad_inf is then that of the
 * last Jacobian formed (0 when F0 met f_stop); a run that ends on the
 * step test having met no finite residual at any trial point is
 * PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL, as there.  When the step after an
 * accepted one is predicted below the step test (||h|| (F / F_before)^(1/2)
 * is) and the chord step -M^-1 f on the LU M at hand is below an eighth
 * of its bound, the run ends on STEP without the Jacobian there (counted
 * as an iteration; not where a tail would follow).
 * The tail (options->tail_f_stop > 0): a STEP stop with F above
 * tail_f_stop, within max_iterations, goes on from its point as a second
 * run from there would (f_stop := tail_f_stop, eps_step := DBL_EPSILON,
 * Delta := max(||x||, 1), at most tail_iterations more steps, a new LU
 * first) but keeps the analysis, the residual and the Jacobian at that
 * point, and the LU when it is of that Jacobian: the same steps, without
 * their set-up; and when the step the step test refused came from GMRES
 * on the kept LU with a relative residual rr such that rr^2 F is at most
 * tail_f_stop (an inexact Newton step that should end the tail by itself)
 * that step is tried first, on the kept LU, instead of a new LU
 * (the step test is scale-bound: on a Jacobian as large as
 * 1 / l^2 against ||x|| a step at 12 digits of ||x|| may still cut F by
 * orders).  The report adds up both; the progress callback's k runs on.  No step is bounded by an
 * absolute scale: residuals up to about 1e150 (uniform weights 1e300 put
 * into f) run as residuals of 1 do.  Options: tau, numeric_jacobian and
 * scaling are not used (numeric_jacobian or an ADAPTIVE scaling give
 * ARGUMENT); weights, a robust loss, bounds and equality constraints
 * give ARGUMENT; xy, if not NULL, guides the ordering; options.cancel is
 * asked during every LU (PLATEAU_LM_ERR_ABORTED when it says stop, x the
 * last accepted point).
 * Memory: the analysis, one factor object and one vector block (18 N
 * doubles and the Jacobian's blocks), all through options->allocator and
 * freed before returning. */
typedef int (*plateau_lm_sparse_func)(const double *x, double *f, double *jac, void *user);
/* f: N values at x; jac, when not NULL: the Jacobian's blocks in the order
 * of the pattern (the layout of plateau_lm_sparse_factorize's values). */

PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve(const plateau_lm_sparse_pattern *pattern,
                                                         const double *xy, double *x,
                                                         plateau_lm_sparse_func func, void *user,
                                                         const plateau_lm_options *options,
                                                         plateau_lm_report *report);

/* Storage that a sequence of dog-leg solves shares: the LU object's block
 * and the vector block (the Jacobian's blocks among them), kept from one
 * solve to the next so that a solve on a pattern like the last one (a
 * mesh after some edge flips: the same nodes, a fill within a few per
 * cent) fills memory it already has instead of fresh pages, which the
 * kernel zeroes on first touch (at 10^5 nodes a block is hundreds of MB).
 * A block that is too small is freed and allocated again, 1/32 larger than
 * the solve needs, so that a slightly larger fill next time fits. */
typedef struct plateau_lm_dogleg_keep plateau_lm_dogleg_keep;
/* plateau_lm_dogleg_solve with its LU object and vector block in *keep:
 * *keep NULL on the first call, made then through options->allocator
 * (every solve that shares it passes the same allocator, else ARGUMENT);
 * the blocks stay in it on return, errors included, until
 * plateau_lm_dogleg_keep_free.  The result is that of
 * plateau_lm_dogleg_solve, bit for bit (no value is read from a kept
 * block before the solve writes it); keep NULL: plateau_lm_dogleg_solve. */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve_kept(const plateau_lm_sparse_pattern *pattern,
                                                              const double *xy, double *x,
                                                              plateau_lm_sparse_func func, void *user,
                                                              const plateau_lm_options *options,
                                                              plateau_lm_report *report,
                                                              plateau_lm_dogleg_keep **keep);
/* Bytes held by the keep's blocks (0 for NULL). */
PLATEAU_LM_DEF size_t plateau_lm_dogleg_keep_bytes(const plateau_lm_dogleg_keep *keep);
/* Frees the keep and its blocks; NULL is fine. */
PLATEAU_LM_DEF void plateau_lm_dogleg_keep_free(plateau_lm_dogleg_keep *keep);

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
#ifdef PLATEAU_FREESTANDING
/* No header of the C library beyond the freestanding ones (<stddef.h>,
 * <stdint.h>, <float.h>, <limits.h>): the user supplies the allocator, the
 * libm wrappers and (plateau_delaunay.h) PLATEAU_SNPRINTF, (plateau.h)
 * PLATEAU_QSORT, and links memcpy, memmove and memset, the functions C
 * compilers expect of every environment, freestanding ones included. */
#if !defined(PLATEAU_MALLOC) || !defined(PLATEAU_SQRT) || !defined(PLATEAU_FABS) || \
    !defined(PLATEAU_ATAN2) || !defined(PLATEAU_COS) || !defined(PLATEAU_SIN)
#error "plateau: PLATEAU_FREESTANDING needs PLATEAU_MALLOC, PLATEAU_FREE, PLATEAU_SQRT, PLATEAU_FABS, PLATEAU_ATAN2, PLATEAU_COS and PLATEAU_SIN"
#endif
#ifdef __cplusplus
extern "C" {
#endif
void *memcpy(void *dst, const void *src, size_t size);
void *memmove(void *dst, const void *src, size_t size);
void *memset(void *dst, int value, size_t size);
#ifdef __cplusplus
}
#endif
#ifndef PLATEAU_ASSERT
#define PLATEAU_ASSERT(x) ((void)0)
#endif
#endif /* PLATEAU_FREESTANDING */
#ifndef PLATEAU_MALLOC
#include <stdlib.h>
#define PLATEAU_MALLOC(size, ctx) ((void)(ctx), malloc(size))
#define PLATEAU_FREE(ptr, ctx) ((void)(ctx), free(ptr))
#endif
#ifndef PLATEAU_ASSERT
#include <assert.h>
#define PLATEAU_ASSERT(x) assert(x) /* internal invariants only, never input */
#endif
#ifndef PLATEAU_FREESTANDING
#include <math.h>
#endif
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

/* Kept out of line (PLATEAU__NOINLINE): a small function called from
 * many places, whose inlined copies would add code and no speed. */
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU__NOINLINE __attribute__((noinline))
#else
#define PLATEAU__NOINLINE
#endif
/* PLATEAU__COLD: an error path (a message, a refusal), an exact-arithmetic
 * fallback that runs only when the fast test cannot decide, or code run
 * once (validation, setup, readers, writers): compiled for size, out of
 * the hot code.  gcc takes a function that always reaches a cold call for
 * never executed, and then the functions only it calls: never on a
 * function called unconditionally on the way to hot code; after adding
 * one, check with -ffunction-sections that no hot function moved to
 * .text.unlikely (examples/NOTES.md, section 25). */
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU__COLD __attribute__((cold))
#else
#define PLATEAU__COLD
#endif
/* Allocation through the run-time allocator if it has functions, else the
 * PLATEAU_MALLOC / PLATEAU_FREE macros with the allocator's user_data (out
 * of line: hundreds of calls, none in an inner loop). */
static PLATEAU__NOINLINE void *plateau__alloc(const plateau_allocator *a, size_t size)
{
    if (size == 0) size = 1;
    if (a && a->alloc_fn) return a->alloc_fn(size, a->user_data);
    return PLATEAU_MALLOC(size, a ? a->user_data : NULL);
}
static PLATEAU__NOINLINE void plateau__free(const plateau_allocator *a, void *ptr)
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
/* A 64-bit constant from its two 32-bit halves: C++98 has no long long
 * literal (g++ -std=c++98 -pedantic warns at 0x...ull). */
#define PLATEAU__U64(hi, lo) (((uint64_t)(hi) << 32) | (uint64_t)(lo))
#endif /* PLATEAU_COMMON_IMPLEMENTED */

/* ---- plateau_lm implementation ------------------------------------------ */
#include <float.h>

/* PLATEAU_LM_NO_CONSTRAINTS (CONFIGURATION): options with linear
 * constraints or bounds are refused, and their code (the elimination onto
 * the null space, the inequality rows and their quadratic program, the
 * box's binding set and clipping) is dead code the compiler drops. */
#ifdef PLATEAU_LM_NO_CONSTRAINTS
#define PLATEAU__LM_HAVE_CONSTRAINTS 0
#else
#define PLATEAU__LM_HAVE_CONSTRAINTS 1
#endif
/* The bounds go with them (plateau.h uses neither): their binding set
 * s->free_ is read through PLATEAU__LM_FREE, a NULL constant when they are
 * compiled out, so that every branch of the box folds away. */
#define PLATEAU__LM_FREE(s) (PLATEAU__LM_HAVE_CONSTRAINTS ? (s)->free_ : NULL)

/* PLATEAU_LM_NO_EXTRAS (CONFIGURATION): a robust loss, weights, the
 * numeric Jacobian and geodesic ALWAYS are refused (plateau.h uses none:
 * their branches fold away), the covariance and the Jacobian check return
 * PLATEAU_LM_ERR_ARGUMENT, and the refinement and the geodesic
 * acceleration never run (their code is dead code the compiler drops). */
#ifdef PLATEAU_LM_NO_EXTRAS
#define PLATEAU__LM_HAVE_EXTRAS 0
#else
#define PLATEAU__LM_HAVE_EXTRAS 1
#endif

/* +infinity: <math.h>'s HUGE_VAL, or without <math.h> (PLATEAU_FREESTANDING)
 * the IEEE-754 overflow of 2 DBL_MAX, which rounds to +infinity. */
#ifdef PLATEAU_FREESTANDING
#define PLATEAU__LM_HUGE (2.0 * DBL_MAX)
#else
#define PLATEAU__LM_HUGE HUGE_VAL
#endif

/* No contraction of a*b + c into FMA in this implementation: the same build
 * flags under gcc -std=c99 and clang then give the same iterates (see
 * DETERMINISM).  gcc ignores the pragma with a warning, so only clang. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#define PLATEAU_LM_DEFAULT_TAU 1e-6
#define PLATEAU_LM_DEFAULT_EPS 1e-6
#define PLATEAU_LM_DEFAULT_MAX_ITERATIONS 1000
/* mu beyond this times max(max_j a'_jj, 1) means no step of any length
 * lowers F (in floating point): relative, so that a problem whose J^T J is
 * of the order 1e200 (weights 1e200) has the same room as one of order 1 */
#define PLATEAU_LM_MU_LIMIT 1e300
/* the first step is at most this many times max(||D x0||, 1) */
#define PLATEAU_LM_FIRST_STEP 10.0
/* mu is multiplied by this after a step with gain ratio rho > 3/4 */
#define PLATEAU_LM_GOOD_STEP_FACTOR 0.1
/* this many accepted steps in a row with a tiny F change stop the iteration
 * even while the damping dominates (a flat valley, a local minimum at which
 * some columns of J vanish) */
#define PLATEAU_LM_SMALL_CHANGES 3
/* a gain ratio above this is a very good step (MNT: rho > 3/4) */
#define PLATEAU_LM_VERY_GOOD 0.75
/* with scaling ADAPTIVE, F at most this fraction of F0 counts as progress */
#define PLATEAU_LM_PROGRESS 0.5
/* the forward-difference step: sqrt(DBL_EPSILON) */
#define PLATEAU_LM_DEFAULT_FD_STEP 1.4901161193847656e-08
/* a difference f_i(x + h) - f_i(x) within this many DBL_EPSILON of
 * |f_i(x + h)| + |f_i(x)| is rounding: its quotient is taken as 0 */
#define PLATEAU_LM_FD_NOISE 4.0
/* robust loss: the scale c (in residual units) and the IRLS rounds */
#define PLATEAU_LM_DEFAULT_LOSS_SCALE 1.0
#define PLATEAU_LM_DEFAULT_MAX_IRLS 50
/* IRLS stops once no weight rho'(t) / t moves by more than this */
#define PLATEAU_LM_IRLS_TOL 1e-10
/* geodesic acceleration: the largest 2 ||a|| / ||v|| accepted (Transtrum
 * and Sethna's alpha), and the probe t of the second derivative */
#define PLATEAU_LM_DEFAULT_GEODESIC_RATIO 0.75
/* the dog leg's tail: its steps at most */
#define PLATEAU_LM_DEFAULT_TAIL_ITERATIONS 5
#define PLATEAU_LM_GEODESIC_PROBE 0.1
/* GEODESIC_AUTO accelerates the next step when the last trial step h showed
 * a second-order part ||f(x + h) - f(x) - J h|| of at least this times its
 * first-order part ||J h|| */
#define PLATEAU_LM_GEODESIC_NONLINEAR 0.5
/* refinement: at most this many Gauss-Newton steps, and the growth of F
 * (relative, rounding level) a step may bring when it lowers the gradient */
#define PLATEAU_LM_REFINE_STEPS 40
#define PLATEAU_LM_REFINE_SLACK 1e-10
/* a refinement step longer than this times sqrt(||x||^2 + 1) is no polish:
 * where J's columns are rounding noise (f independent of some parameter)
 * the Gauss-Newton step is noise over noise */
#define PLATEAU_LM_REFINE_REACH 0.01
/* inequality rows: a row is violated when its slack G_i h - r_i is below
 * -PLATEAU_LM_QP_TOL times its rounding scale |r_i| + sum |G_ij h_j|, and
 * active at x (for the projected gradient) when it is below
 * PLATEAU_LM_ACTIVE_TOL times that scale */
#define PLATEAU_LM_QP_TOL 1e-12
#define PLATEAU_LM_ACTIVE_TOL 1e-10
/* a row whose normal keeps less than this fraction of its squared length
 * (in H's metric) outside the span of the active normals depends on them */
#define PLATEAU_LM_QP_DEPENDENT 1e-20
/* the quadratic program's scratch: k k doubles and this many vectors of k */
#define PLATEAU__LM_QP_VECTORS 9
/* QR with column pivoting (columns of unit length): a pivot below this
 * times the first one ends the rank */
#define PLATEAU_LM_RANK_TOL 1e-12
/* A x = b is consistent when each row holds to this relative to its terms */
#define PLATEAU_LM_CONSTRAINT_TOL 1e-10
/* Jacobian check: the central-difference step cbrt(DBL_EPSILON) max(|x_j|, 1),
 * the default relative tolerance, and the margin over the estimated error */
#define PLATEAU_LM_CHECK_STEP 6.0554544523933395e-06
#define PLATEAU_LM_CHECK_TOL 1e-6
#define PLATEAU_LM_CHECK_MARGIN 10.0
#define PLATEAU_LM_CHECK_LEVELS 5

#define PLATEAU_LM_STRING_CASE(name, value, text) \
    case name:                                    \
        return text;

PLATEAU_LM_DEF PLATEAU__COLD const char *plateau_lm_result_string(plateau_lm_result result)
{
    switch (result) {
        PLATEAU_LM_RESULT_LIST(PLATEAU_LM_STRING_CASE)
    default:
        break;
    }
    return "unknown plateau_lm_result";
}

PLATEAU_LM_DEF PLATEAU__COLD const char *plateau_lm_stop_string(plateau_lm_stop stop)
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

/* ---- Workspace ---------------------------------------------------------------
 * One block of doubles, carved in this order (the parts after y only when
 * their feature is on):
 *   f, fnew (m each); J (m n); A, its factor (k k each, k = min(m, n));
 *   g, h, xnew, d, column norms (n each); y (k);
 *   weights: sw (m, square roots of the weights in use);
 *   bounds: free (n, 1 for a free parameter, 0 for one held at a bound);
 *   geodesic acceleration: fvv (m), acc (n);
 *   refinement (m > n): a copy of J for its QR (m n), fr (m), tau, column
 *   norms, permutation (n each).
 * plateau__lm_layout counts it and, given a state and a base, carves it. */
typedef struct plateau__lm_state plateau__lm_state;

/* the features that add to the workspace, from the resolved options */
static int plateau__lm_has_weights(const plateau_lm_options *o)
{
    return PLATEAU__LM_HAVE_EXTRAS && (o->weights != NULL || o->loss != PLATEAU_LM_LOSS_SQUARED);
}
static int plateau__lm_has_refine(const plateau_lm_options *o, size_t m, size_t n)
{
    return PLATEAU__LM_HAVE_EXTRAS && o->refine >= 0 && m > n;
}

/* count doubles of len into *total (0 on overflow); carve them from *p when p
 * (out of line: 36 calls in the layout of the workspace, run once per solve) */
static PLATEAU__NOINLINE double *plateau__lm_part(size_t *total, size_t len, double **p)
{
    double *r = NULL;
    if (*total != 0) *total = plateau__lm_add(*total, len);
    if (p) {
        r = *p;
        *p += len;
    }
    return r;
}

/* Number of doubles in the workspace, or 0 when it overflows size_t; with
 * s and base, also carves the arrays of s.  rows: inequality rows G y >= e
 * (0 for none); with them the normal matrix is n x n whatever m. */
static size_t plateau__lm_layout(size_t m, size_t n, const plateau_lm_options *o, size_t rows,
                                 plateau__lm_state *s, double *base);

/* Inequality rows make the solve a sequence of small quadratic programs
 * (see LINEAR CONSTRAINTS): given with C x >= d, or bounds together with
 * A x = b (the box alone keeps the projection of BOUNDS). */
static int plateau__lm_has_qp(const plateau_lm_options *o)
{
    return o->inequalities > 0 || (o->constraints > 0 && (o->lower || o->upper));
}

/* At most this many rows of G: every bound finite, and C */
static size_t plateau__lm_qp_rows(const plateau_lm_options *o, size_t n)
{
    size_t rows = o->inequalities;
    if (!plateau__lm_has_qp(o)) return 0;
    if (n > (size_t)-1 / 4 || rows > (size_t)-1 / 2) return 0;
    return rows + (o->lower ? n : 0) + (o->upper ? n : 0);
}

/* The options of the solve in y on the constrained path: no bounds or
 * constraints of its own (they are the map and the rows of G), and with
 * inequality rows no geodesic acceleration (its step ignores G). */
static plateau_lm_options plateau__lm_inner_options(const plateau_lm_options *o)
{
    plateau_lm_options io = *o;
    io.constraints = io.inequalities = 0;
    io.lower = io.upper = NULL;
    if (plateau__lm_has_qp(o)) io.geodesic = PLATEAU_LM_GEODESIC_NEVER;
    return io;
}

/* Doubles of the constrained path: the solve in y (at most n free
 * parameters; refinement arrays also when n >= m but the free ones are
 * fewer), then the map back: Z (n n), x_p, y, the full x (n each), the full
 * J (m n), the QR of A^T (n k) and its factors (3 max(n, k)).  *inner: the
 * first part. */
static size_t plateau__lm_constrained_doubles(size_t m, size_t n, const plateau_lm_options *o,
                                              size_t *inner)
{
    plateau_lm_options io = plateau__lm_inner_options(o);
    size_t k = o->constraints, big = n > k ? n : k, rows = plateau__lm_qp_rows(o, n);
    size_t nn = plateau__bytes(n, n), qa = plateau__bytes(n, k), mn = plateau__bytes(m, n);
    size_t count;
    if (nn == 0 || (k > 0 && qa == 0) || mn == 0 || big > (size_t)-1 / 8 || m > (size_t)-1 / 2 ||
        (plateau__lm_has_qp(o) && rows == 0))
        return 0;
    count = plateau__lm_layout(m, n, &io, rows, NULL, NULL);
    if (io.refine >= 0) count = plateau__lm_add(count, plateau__lm_add(mn, m + 3 * n));
    *inner = count;
    count = plateau__lm_add(count, plateau__lm_add(nn, mn));
    if (k > 0) count = plateau__lm_add(count, qa);
    return plateau__lm_add(count, 3 * big + 4 * n);
}

PLATEAU_LM_DEF size_t plateau_lm_workspace_size(size_t m, size_t n,
                                                const plateau_lm_options *options)
{
    size_t count, bytes, inner;
    plateau_lm_options o;
    if (m == 0 || n == 0) return 0;
    o = plateau_lm_resolved_options(options);
    if (o.constraints > 0 || plateau__lm_has_qp(&o))
        count = plateau__lm_constrained_doubles(m, n, &o, &inner);
    else
        count = plateau__lm_layout(m, n, &o, 0, NULL, NULL);
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
        o.lower = o.upper = o.weights = o.a_eq = o.b_eq = NULL;
        o.loss = PLATEAU_LM_LOSS_SQUARED;
        o.loss_scale = o.geodesic_ratio = 0.0;
        o.max_irls = o.refine = 0;
        o.geodesic = PLATEAU_LM_GEODESIC_AUTO;
        o.constraints = o.inequalities = 0;
        o.c_ineq = o.d_ineq = NULL;
        o.cancel = NULL;
        o.tail_f_stop = 0.0;
        o.tail_iterations = 0;
        o.chord = 0;
    }
    if (o.tau == 0.0) o.tau = PLATEAU_LM_DEFAULT_TAU;
    if (o.eps == 0.0) o.eps = PLATEAU_LM_DEFAULT_EPS;
    eps2 = o.eps * o.eps;
    if (o.eps_grad == 0.0) o.eps_grad = eps2;
    if (o.eps_step == 0.0) o.eps_step = eps2;
    if (o.eps_f == 0.0) o.eps_f = eps2;
    if (o.fd_step == 0.0) o.fd_step = PLATEAU_LM_DEFAULT_FD_STEP;
    if (o.max_iterations == 0) o.max_iterations = PLATEAU_LM_DEFAULT_MAX_ITERATIONS;
    if (o.loss_scale == 0.0) o.loss_scale = PLATEAU_LM_DEFAULT_LOSS_SCALE;
    if (o.max_irls == 0) o.max_irls = PLATEAU_LM_DEFAULT_MAX_IRLS;
    if (o.geodesic_ratio == 0.0) o.geodesic_ratio = PLATEAU_LM_DEFAULT_GEODESIC_RATIO;
    if (o.tail_iterations == 0) o.tail_iterations = PLATEAU_LM_DEFAULT_TAIL_ITERATIONS;
    return o;
}

static int plateau__lm_options_valid(const plateau_lm_options *o)
{
    return plateau__lm_nonneg(o->tau) && plateau__lm_nonneg(o->eps) &&
           plateau__lm_nonneg(o->eps_grad) && plateau__lm_nonneg(o->eps_step) &&
           plateau__lm_nonneg(o->eps_f) && plateau__lm_finite(o->f_stop) &&
           plateau__lm_nonneg(o->fd_step) && o->max_iterations >= 0 &&
           plateau__lm_nonneg(o->tail_f_stop) && o->tail_iterations >= 0 &&
           (o->scaling == PLATEAU_LM_SCALING_NONE || o->scaling == PLATEAU_LM_SCALING_ADAPTIVE) &&
           plateau__allocator_valid(&o->allocator) &&
           (o->loss == PLATEAU_LM_LOSS_SQUARED ||
            (PLATEAU__LM_HAVE_EXTRAS && (o->loss == PLATEAU_LM_LOSS_HUBER || o->loss == PLATEAU_LM_LOSS_CAUCHY))) &&
           plateau__lm_nonneg(o->loss_scale) && o->loss_scale > 0.0 && o->max_irls >= 0 &&
           plateau__lm_nonneg(o->geodesic_ratio) &&
           (o->geodesic == PLATEAU_LM_GEODESIC_AUTO || o->geodesic == PLATEAU_LM_GEODESIC_NEVER ||
            (PLATEAU__LM_HAVE_EXTRAS && o->geodesic == PLATEAU_LM_GEODESIC_ALWAYS)) &&
           (o->constraints == 0 || (o->a_eq != NULL && o->b_eq != NULL)) &&
           (o->inequalities == 0 || (o->c_ineq != NULL && o->d_ineq != NULL)) &&
           (PLATEAU__LM_HAVE_CONSTRAINTS ||
            (o->constraints == 0 && o->inequalities == 0 && !o->lower && !o->upper)) &&
           (PLATEAU__LM_HAVE_EXTRAS || (!o->weights && !o->numeric_jacobian));
}

/* Everything one solve needs, so the helpers take one pointer. */
struct plateau__lm_state {
    size_t m, n, k;  /* k: order of the normal matrix, n (J^T J) or m (J J^T, wide) */
    int wide;        /* m < n without inequality rows: the m x m system */
    double *x;       /* the caller's x: always the last accepted point */
    plateau_lm_func func;
    void *user;
    const plateau_lm_options *o;
    double *f, *fnew, *jac, *a, *fac, *g, *h, *xnew, *d, *cn, *y;
    double *sw;                 /* square roots of the weights, or NULL */
    double *free_;              /* bounds: 1 free, 0 held at a bound; or NULL */
    double *fvv, *acc;          /* geodesic acceleration, or NULL */
    double *qr, *fr, *tau, *qcn, *perm; /* refinement, or NULL */
    /* inequality rows G x >= e (p of them; see LINEAR CONSTRAINTS), or G
     * NULL: G scaled by D^-1, the step's multipliers, the gradient projected
     * onto the cone of feasible directions, the QP solver's scratch */
    size_t p;
    double *G, *e, *Gs, *rq, *u, *gp, *qpw;
    size_t residual_evaluations, jacobian_evaluations;
    size_t accelerated, refined;
    /* the iteration */
    double F, F0, mu, nu, ginf, amin, amax, step_floor, f_stop, cosine;
    double nonlinearity; /* ||f(x + h) - f(x) - J h|| / ||J h|| of the last trial */
    int iter, rejected, small_changes;
    /* trial points whose F was finite, and those whose F was not */
    size_t finite_trials, nonfinite_trials;
    plateau_lm_stop stop;
};

/* the steps and gradient of a solve with inequality rows, and whether a
 * point satisfies them (defined with the quadratic program below) */
static int plateau__lm_qp_step(plateau__lm_state *s);
static double plateau__lm_project_gradient(plateau__lm_state *s);
static int plateau__lm_rows_hold(const plateau__lm_state *s, const double *x);

static size_t plateau__lm_layout(size_t m, size_t n, const plateau_lm_options *o, size_t rows,
                                 plateau__lm_state *s, double *base)
{
    size_t k = m < n && rows == 0 ? m : n, total = 1;
    size_t mn = plateau__bytes(m, n), kk = plateau__bytes(k, k), pn = plateau__bytes(rows, n);
    double *p = base, **pp = s && base ? &p : NULL;
    double *dummy = NULL;
    if (mn == 0 || kk == 0 || (rows > 0 && (pn == 0 || k > (size_t)-1 / 16))) return 0;
#define PLATEAU__LM_PART(field, len) \
    *(s && base ? &s->field : &dummy) = plateau__lm_part(&total, len, pp)
    PLATEAU__LM_PART(f, m);
    PLATEAU__LM_PART(fnew, m);
    PLATEAU__LM_PART(jac, mn);
    PLATEAU__LM_PART(a, kk);
    PLATEAU__LM_PART(fac, kk);
    PLATEAU__LM_PART(g, n);
    PLATEAU__LM_PART(h, n);
    PLATEAU__LM_PART(xnew, n);
    PLATEAU__LM_PART(d, n);
    PLATEAU__LM_PART(cn, n);
    PLATEAU__LM_PART(y, k);
    if (s && base) s->sw = s->free_ = s->fvv = s->acc = s->qr = s->fr = s->tau = s->qcn = s->perm = NULL;
    if (plateau__lm_has_weights(o)) PLATEAU__LM_PART(sw, m);
    if (PLATEAU__LM_HAVE_CONSTRAINTS && (o->lower || o->upper)) PLATEAU__LM_PART(free_, n);
    if (PLATEAU__LM_HAVE_EXTRAS && o->geodesic != PLATEAU_LM_GEODESIC_NEVER) {
        PLATEAU__LM_PART(fvv, m);
        PLATEAU__LM_PART(acc, n);
    }
    if (plateau__lm_has_refine(o, m, n)) {
        PLATEAU__LM_PART(qr, mn);
        PLATEAU__LM_PART(fr, m);
        PLATEAU__LM_PART(tau, n);
        PLATEAU__LM_PART(qcn, n);
        PLATEAU__LM_PART(perm, n);
    }
    if (s && base) {
        s->G = s->e = s->Gs = s->rq = s->u = s->gp = s->qpw = NULL;
        s->p = rows;
        s->k = k;
        s->wide = k < n;
    }
    if (rows > 0) {
        PLATEAU__LM_PART(G, pn);
        PLATEAU__LM_PART(e, rows);
        PLATEAU__LM_PART(Gs, pn);
        PLATEAU__LM_PART(rq, rows);
        PLATEAU__LM_PART(u, rows);
        PLATEAU__LM_PART(gp, n);
        PLATEAU__LM_PART(qpw, plateau__lm_add(kk, PLATEAU__LM_QP_VECTORS * n));
    }
#undef PLATEAU__LM_PART
    (void)dummy;
    return total == 0 ? 0 : total - 1;
}

/* 1/2 ||v||^2, or an infinity / NaN when v is not finite or the sum overflows. */
static double plateau__lm_half_sumsq(const double *v, size_t len)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < len; i++) s += v[i] * v[i];
    return 0.5 * s;
}

/* 1 when no value is NaN or infinite (out of line: 29 calls, each before
 * O(len) work of its own) */
static PLATEAU__NOINLINE int plateau__lm_all_finite(const double *v, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++)
        if (!plateau__lm_finite(v[i])) return 0;
    return 1;
}

/* The user's residuals (and Jacobian) at x, rows scaled by sqrt(w_i) when
 * weights are in use.  Returns non-zero when the callback asks to stop. */
static int plateau__lm_call(plateau__lm_state *s, const double *x, double *f, double *jac)
{
    size_t i, j;
    if (s->func(x, f, jac, s->user) != 0) return 1;
    if (PLATEAU__LM_HAVE_EXTRAS && s->sw)
        for (i = 0; i < s->m; i++) {
            double w = s->sw[i];
            f[i] *= w;
            if (jac)
                for (j = 0; j < s->n; j++) jac[i * s->n + j] *= w;
        }
    return 0;
}

/* The Jacobian at x, whose residual f is already known, into jac.
 * Analytic: one call with jac (its residual output goes to scratch fnew).
 * Numeric (forward differences, one call per column): step h_j = fd_step
 * |x_j| (fd_step when x_j = 0), rounded so that x_j + h_j is exact; if the
 * residual at x_j + h_j is not finite, the backward difference at x_j - h_j
 * is used instead; a difference at the rounding level of f gives 0
 * (PLATEAU_LM_FD_NOISE).  Scratch: xnew, fnew. */
static plateau_lm_result plateau__lm_jacobian_at(plateau__lm_state *s, const double *x,
                                                 const double *f, double *jac)
{
    size_t m = s->m, n = s->n, i, j;
    s->jacobian_evaluations++;
    if (!PLATEAU__LM_HAVE_EXTRAS || !s->o->numeric_jacobian) {
        if (plateau__lm_call(s, x, s->fnew, jac) != 0) return PLATEAU_LM_ERR_ABORTED;
        if (!plateau__lm_all_finite(jac, m * n)) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
        return PLATEAU_LM_OK;
    }
    for (j = 0; j < n; j++) s->xnew[j] = x[j];
    for (j = 0; j < n; j++) {
        double xj = x[j], step = s->o->fd_step * PLATEAU_FABS(xj), t;
        int side;
        if (step == 0.0) step = s->o->fd_step;
        /* with bounds, difference towards the inside of the box */
        if (PLATEAU__LM_FREE(s) && s->o->upper && xj + step > s->o->upper[j]) step = -step;
        for (side = 0; side < 2; side++) {
            double hj = side == 0 ? step : -step;
            t = xj + hj;
            if (PLATEAU__LM_FREE(s) &&
                ((s->o->lower && t < s->o->lower[j]) || (s->o->upper && t > s->o->upper[j])))
                continue;
            hj = t - xj; /* the step actually taken */
            s->xnew[j] = t;
            /* with inequality rows, the other side when this one leaves them */
            if (side == 0 && s->G && !plateau__lm_rows_hold(s, s->xnew)) {
                s->xnew[j] = xj;
                continue;
            }
            s->residual_evaluations++;
            if (plateau__lm_call(s, s->xnew, s->fnew, NULL) != 0) {
                s->xnew[j] = xj;
                return PLATEAU_LM_ERR_ABORTED;
            }
            if (hj != 0.0 && plateau__lm_all_finite(s->fnew, m)) {
                /* a difference at the rounding level of f says nothing: 0 */
                for (i = 0; i < m; i++) {
                    double df = s->fnew[i] - f[i];
                    jac[i * n + j] = PLATEAU_FABS(df) <= PLATEAU_LM_FD_NOISE * DBL_EPSILON *
                                                             (PLATEAU_FABS(s->fnew[i]) + PLATEAU_FABS(f[i]))
                                         ? 0.0
                                         : df / hj;
                }
                break;
            }
        }
        s->xnew[j] = xj;
        if (side == 2) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
    }
    if (!plateau__lm_all_finite(jac, m * n)) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
    return PLATEAU_LM_OK;
}

/* min and max over the non-zero columns of diag(J'^T J')_j = (||J_j|| / d_j)^2 */
static void plateau__lm_diag_range(const plateau__lm_state *s, double *amin, double *amax)
{
    size_t j;
    double lo = PLATEAU__LM_HUGE, hi = 0.0;
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

/* Bounds: a parameter at its lower bound with g_j > 0, or at its upper
 * bound with g_j < 0, is held there (the descent direction -g leaves the
 * box): free_j = 0 and g_j = 0, so the damped system leaves it alone and
 * the gradient tests see the projected gradient (Bertsekas' projected
 * Newton method, the binding set). */
static void plateau__lm_binding(plateau__lm_state *s)
{
    const double *lo = s->o->lower, *up = s->o->upper;
    size_t j;
    for (j = 0; j < s->n; j++) {
        int held = (lo && s->x[j] <= lo[j] && s->g[j] > 0.0) ||
                   (up && s->x[j] >= up[j] && s->g[j] < 0.0);
        s->free_[j] = held ? 0.0 : 1.0;
        if (held) s->g[j] = 0.0;
    }
}

/* After a new Jacobian: g = J^T f, column norms cn, the scaling d (MINPACK's
 * rule: d_j = max(d_j, ||J_j||), first d_j = ||J_j|| or 1 for a zero column),
 * the binding set of the bounds, and the scaled normal matrix A' (lower
 * triangle): D^-1 J^T J D^-1 (n x n) when m >= n, J D^-2 J^T (m x m) when
 * m < n, without the columns held at a bound.  Returns ||g||_inf. */
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
    if (PLATEAU__LM_FREE(s)) plateau__lm_binding(s);
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
    if (PLATEAU__LM_FREE(s))
        for (j = 0; j < n; j++) s->cn[j] *= PLATEAU__LM_FREE(s)[j];
    if (PLATEAU__LM_HAVE_CONSTRAINTS && s->G) ginf = plateau__lm_project_gradient(s);
    for (i = 0; i < k * k; i++) s->a[i] = 0.0;
    if (!s->wide) {
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
        if (PLATEAU__LM_FREE(s))
            for (i = 0; i < n; i++)
                for (j = 0; j <= i; j++) s->a[i * n + j] *= PLATEAU__LM_FREE(s)[i] * PLATEAU__LM_FREE(s)[j];
    } else {
        for (i = 0; i < m; i++) {
            const double *ri = J + i * n;
            for (r = 0; r <= i; r++) {
                const double *rr = J + r * n;
                double sum = 0.0;
                if (PLATEAU__LM_FREE(s)) {
                    for (j = 0; j < n; j++)
                        sum += (ri[j] / s->d[j]) * (rr[j] / s->d[j]) * PLATEAU__LM_FREE(s)[j];
                } else {
                    for (j = 0; j < n; j++) sum += (ri[j] / s->d[j]) * (rr[j] / s->d[j]);
                }
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

/* out = -(A' + mu I)^-1 D^-1 J^T r (m >= n) or -D^-1 J^T (J' J'^T + mu I)^-1 r
 * (m < n) with the factor in fac: the damped step for the residual r.
 * Held parameters get 0. */
static void plateau__lm_damped_solve(plateau__lm_state *s, const double *r, double *out)
{
    size_t m = s->m, n = s->n, i, j;
    if (!s->wide) {
        for (j = 0; j < n; j++) out[j] = 0.0;
        for (i = 0; i < m; i++) {
            const double *row = s->jac + i * n;
            for (j = 0; j < n; j++) out[j] += row[j] * r[i];
        }
        for (j = 0; j < n; j++)
            out[j] = -out[j] / s->d[j] * (PLATEAU__LM_FREE(s) ? PLATEAU__LM_FREE(s)[j] : 1.0);
        plateau__lm_cholesky_solve(s->fac, n, out);
    } else {
        for (i = 0; i < m; i++) s->y[i] = -r[i];
        plateau__lm_cholesky_solve(s->fac, m, s->y);
        for (j = 0; j < n; j++) out[j] = 0.0;
        for (i = 0; i < m; i++) {
            const double *row = s->jac + i * n;
            double yi = s->y[i];
            for (j = 0; j < n; j++) out[j] += row[j] * yi;
        }
        for (j = 0; j < n; j++)
            out[j] = out[j] / s->d[j] * (PLATEAU__LM_FREE(s) ? PLATEAU__LM_FREE(s)[j] : 1.0);
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
    if (PLATEAU__LM_HAVE_CONSTRAINTS && s->G) return plateau__lm_qp_step(s);
    if (!s->wide) {
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
        if (PLATEAU__LM_FREE(s))
            for (j = 0; j < n; j++) s->h[j] *= PLATEAU__LM_FREE(s)[j];
    }
    return plateau__lm_all_finite(s->h, n);
}

/* The scale-free gradient measure of the gradient test (MINPACK's gtol):
 * the largest cosine between f and a column of J, max_j |g_j| / (||J_j|| ||f||),
 * for F = 1/2 ||f||^2 at the point where g and the column norms were formed. */
static double plateau__lm_cosine(const double *g, const double *cn, size_t n, double F)
{
    double fnorm = PLATEAU_SQRT(2.0 * F), cmax = 0.0;
    size_t j;
    for (j = 0; j < n; j++)
        if (cn[j] > 0.0) {
            double c = PLATEAU_FABS(g[j]) / (cn[j] * fnorm);
            if (c > cmax) cmax = c;
        }
    return cmax;
}
static double plateau__lm_grad_cosine(const plateau__lm_state *s, double F)
{
    return plateau__lm_cosine(s->G ? s->gp : s->g, s->cn, s->n, F);
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
 * n = 9 and 10 from 10 x0 stopped untouched).  Without scaling the tests
 * keep their plain form. */
static int plateau__lm_may_claim(const plateau_lm_options *o, int gauss_newton, double cosine,
                                 double F, double F0)
{
    if (o->scaling != PLATEAU_LM_SCALING_ADAPTIVE) return 1;
    return gauss_newton || cosine <= PLATEAU_SQRT(o->eps_grad) || F <= PLATEAU_LM_PROGRESS * F0;
}

/* MNT Alg. 3.16 / Fig. 5, initialisation: x := x0; A := J^T J; g := J^T f;
 * found := gradient test; mu := tau * max a_ii; nu := 2. */
static plateau_lm_result plateau__lm_start(plateau__lm_state *s)
{
    const plateau_lm_options *o = s->o;
    plateau_lm_result res;
    double gn = 0.0, xn = 0.0, gmax = 0.0, lim;
    size_t j;
    s->residual_evaluations++;
    if (plateau__lm_call(s, s->x, s->f, NULL) != 0) return PLATEAU_LM_ERR_ABORTED;
    s->F = s->F0 = plateau__lm_half_sumsq(s->f, s->m);
    if (!plateau__lm_finite(s->F)) return PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    /* f_stop = 0: the residual is at rounding level, F <= DBL_EPSILON^2 min(F0, 1);
     * f_stop < 0: never. */
    s->f_stop = o->f_stop != 0.0 ? o->f_stop
                                 : DBL_EPSILON * DBL_EPSILON * (s->F0 < 1.0 ? s->F0 : 1.0);
    res = plateau__lm_jacobian_at(s, s->x, s->f, s->jac);
    if (res != PLATEAU_LM_OK) return res;
    s->ginf = plateau__lm_prepare(s, 1);
    plateau__lm_diag_range(s, &s->amin, &s->amax);
    /* mu0 = tau max a_ii (Fig. 5), raised if needed so that the first step,
     * whose length is at most ||g'|| / mu, is at most 10 max(||D x0||, 1): a
     * far start then begins with a bounded gradient step instead of a wild
     * Gauss-Newton step and a long series of rejections. */
    s->mu = o->tau * s->amax;
    for (j = 0; j < s->n; j++) {
        gn += (s->g[j] / s->d[j]) * (s->g[j] / s->d[j]);
        xn += (s->d[j] * s->x[j]) * (s->d[j] * s->x[j]);
        if (PLATEAU_FABS(s->g[j] / s->d[j]) > gmax) gmax = PLATEAU_FABS(s->g[j] / s->d[j]);
    }
    xn = PLATEAU_SQRT(xn);
    gn = PLATEAU_SQRT(gn);
    if (!plateau__lm_finite(gn)) {
        /* g of order 1e200 (large weights) squares beyond double range:
         * ||g'|| in units of its largest entry */
        for (gn = 0.0, j = 0; j < s->n; j++) gn += (s->g[j] / s->d[j] / gmax) * (s->g[j] / s->d[j] / gmax);
        gn = gmax * PLATEAU_SQRT(gn);
    }
    /* MNT's step test ||h|| <= eps2 (||x|| + eps2) has an absolute floor
     * eps2, which stops at once a problem living at the scale of 1e-150;
     * the floor is eps2^2 min(||D x0||, 1) instead: the same for starts of
     * norm 1 or more, scale-free below. */
    s->step_floor = o->eps_step * o->eps_step * (xn < 1.0 ? xn : 1.0);
    lim = gn / (PLATEAU_LM_FIRST_STEP * (xn > 1.0 ? xn : 1.0));
    if (lim > s->mu) s->mu = lim;
    if (!(s->mu > 0.0)) s->mu = o->tau;
    s->nu = 2.0;
    if (s->F <= s->f_stop) s->stop = PLATEAU_LM_STOP_SMALL_F;
    else if (s->ginf == 0.0) s->stop = PLATEAU_LM_STOP_GRADIENT;
    else s->cosine = plateau__lm_grad_cosine(s, s->F);
    return PLATEAU_LM_OK;
}

/* The trial point x + h (unscaled: h_j / d_j) in xnew, projected onto the
 * box; *pred: the model's decrease.  For an unprojected step it is MNT's
 * L(0) - L(h) = 1/2 h'^T (mu h' - g') (eq. 3.14, scaled); for a projected
 * step p = P(x + h) - x, and for the step of a quadratic program (which
 * does not solve the damped system), the Gauss-Newton model's
 * -g^T p - 1/2 ||J p||^2. */
static void plateau__lm_trial(plateau__lm_state *s, double *pred)
{
    size_t n = s->n, i, j;
    int clipped = 0;
    for (j = 0; j < n; j++) s->xnew[j] = s->x[j] + s->h[j] / s->d[j];
    if (PLATEAU__LM_FREE(s))
        for (j = 0; j < n; j++) {
            double v = s->xnew[j];
            if (s->o->lower && v < s->o->lower[j]) { v = s->o->lower[j]; clipped = 1; }
            if (s->o->upper && v > s->o->upper[j]) { v = s->o->upper[j]; clipped = 1; }
            s->xnew[j] = v;
        }
    if (!clipped && !s->G) return; /* G: the step of a QP, not of the damped system */
    *pred = 0.0;
    for (j = 0; j < n; j++) *pred -= s->g[j] * (s->xnew[j] - s->x[j]);
    for (i = 0; i < s->m; i++) {
        const double *row = s->jac + i * n;
        double t = 0.0;
        for (j = 0; j < n; j++) t += row[j] * (s->xnew[j] - s->x[j]);
        *pred -= 0.5 * t * t;
    }
}

/* Geodesic acceleration (Transtrum and Sethna, "Improvements to the
 * Levenberg-Marquardt algorithm for nonlinear least-squares minimization",
 * 2012): with the velocity v = h (the LM step), the second directional
 * derivative f_vv ~ (2 / t) ((f(x + t v) - f(x)) / t - J v), t = 0.1, and the
 * acceleration a solving the same damped system for f_vv; the step becomes
 * v + a / 2 when 2 ||a|| <= geodesic_ratio ||v||, and is rejected otherwise
 * (the second-order term is too large for the model: a shorter step is
 * tried, as GSL does).  One residual evaluation.  Returns 1 (accelerated),
 * 0 (plain step: the probe point left the box or f there is not finite),
 * 2 (reject the step) or -1 (the callback aborted). */
static int plateau__lm_accelerate(plateau__lm_state *s)
{
    size_t m = s->m, n = s->n, i, j;
    const double t = PLATEAU_LM_GEODESIC_PROBE;
    double vn = 0.0, an = 0.0;
    for (j = 0; j < n; j++) s->xnew[j] = s->x[j] + t * s->h[j] / s->d[j];
    for (j = 0; j < n && PLATEAU__LM_FREE(s); j++)
        if ((s->o->lower && s->xnew[j] < s->o->lower[j]) ||
            (s->o->upper && s->xnew[j] > s->o->upper[j]))
            return 0; /* the probe would leave the box, where f may not exist */
    if (!plateau__lm_all_finite(s->xnew, n)) return 0;
    s->residual_evaluations++;
    if (plateau__lm_call(s, s->xnew, s->fvv, NULL) != 0) return -1;
    if (!plateau__lm_all_finite(s->fvv, m)) return 0;
    for (i = 0; i < m; i++) {
        const double *row = s->jac + i * n;
        double jv = 0.0;
        for (j = 0; j < n; j++) jv += row[j] * (s->h[j] / s->d[j]);
        s->fvv[i] = 2.0 / t * ((s->fvv[i] - s->f[i]) / t - jv);
    }
    plateau__lm_damped_solve(s, s->fvv, s->acc);
    for (j = 0; j < n; j++) {
        vn += s->h[j] * s->h[j];
        an += s->acc[j] * s->acc[j];
    }
    if (!plateau__lm_all_finite(s->acc, n) || !(2.0 * PLATEAU_SQRT(an) <= s->o->geodesic_ratio * PLATEAU_SQRT(vn)))
        return 2;
    for (j = 0; j < n; j++) s->h[j] += 0.5 * s->acc[j];
    return 1;
}

/* How nonlinear f proved along the trial step p = x_new - x (before x
 * moves): ||f(x_new) - f(x) - J p|| / ||J p||, the second-order part of the
 * change against the first-order one (0 when J p = 0); HUGE when F(x_new)
 * is not finite.  GEODESIC_AUTO accelerates the next step when it is at
 * least PLATEAU_LM_GEODESIC_NONLINEAR: where f is nearly linear along the
 * steps the acceleration is negligible and its probe a wasted evaluation. */
static double plateau__lm_nonlinearity(const plateau__lm_state *s, double Fnew)
{
    size_t n = s->n, i, j;
    double r2 = 0.0, l2 = 0.0;
    if (!plateau__lm_finite(Fnew)) return PLATEAU__LM_HUGE;
    for (i = 0; i < s->m; i++) {
        const double *row = s->jac + i * n;
        double lin = 0.0, r;
        for (j = 0; j < n; j++) lin += row[j] * (s->xnew[j] - s->x[j]);
        r = s->fnew[i] - s->f[i] - lin;
        r2 += r * r;
        l2 += lin * lin;
    }
    return l2 > 0.0 ? PLATEAU_SQRT(r2 / l2) : 0.0;
}

/* After an accepted step (x, f and F already moved): the new Jacobian, mu
 * updated by Nielsen's rule and the gradient and F-change tests.  Fold, pred:
 * F before the step and the model's decrease; mu_step, amin_step: the mu and
 * min_j a'_jj the step was taken with. */
static plateau_lm_result plateau__lm_accepted(plateau__lm_state *s, double Fold, double pred,
                                              double rho)
{
    const plateau_lm_options *o = s->o;
    double mu_step = s->mu, amin_step = s->amin, q, factor, cmax;
    plateau_lm_result res = plateau__lm_jacobian_at(s, s->x, s->f, s->jac);
    if (res != PLATEAU_LM_OK) return res;
    s->ginf = plateau__lm_prepare(s, 0);
    plateau__lm_diag_range(s, &s->amin, &s->amax);
    s->rejected = 0;
    /* mu := mu * max(1/3, 1 - (2 rho - 1)^3); nu := 2 (Nielsen), except that
     * a very good step (rho > 3/4) divides mu by 10 */
    q = 2.0 * rho - 1.0;
    factor = 1.0 - q * q * q;
    if (factor < 1.0 / 3.0) factor = 1.0 / 3.0;
    if (rho > PLATEAU_LM_VERY_GOOD) factor = PLATEAU_LM_GOOD_STEP_FACTOR;
    s->mu *= factor;
    if (s->mu < DBL_MIN) s->mu = DBL_MIN;
    s->nu = 2.0;
    if (s->F <= s->f_stop) {
        s->stop = PLATEAU_LM_STOP_SMALL_F;
        return PLATEAU_LM_OK;
    }
    /* gradient test, scale-free: the largest cosine between f and a column
     * of J, |g_j| / (||J_j|| ||f||) <= eps_grad */
    cmax = plateau__lm_grad_cosine(s, s->F);
    s->cosine = cmax;
    if (s->ginf == 0.0 || cmax <= o->eps_grad) {
        s->stop = PLATEAU_LM_STOP_GRADIENT;
    } else if (Fold - s->F <= o->eps_f * Fold && pred <= o->eps_f * Fold) {
        /* F-change test, on accepted steps only (examples/NOTES.md): the
         * actual and the predicted reduction are both below eps_f F, for a
         * Gauss-Newton-like step (mu <= min a'_jj when it was taken) or for
         * PLATEAU_LM_SMALL_CHANGES accepted steps in a row. */
        s->small_changes++;
        if ((mu_step <= amin_step || s->small_changes >= PLATEAU_LM_SMALL_CHANGES) &&
            plateau__lm_may_claim(o, mu_step <= amin_step, cmax, s->F, s->F0))
            s->stop = PLATEAU_LM_STOP_F_CHANGE;
    } else {
        s->small_changes = 0;
    }
    return PLATEAU_LM_OK;
}

/* The damping limit (DAMPING): mu beyond PLATEAU_LM_MU_LIMIT times the
 * problem's scale max(max_j a'_jj, 1); a NaN mu is beyond it too. */
static int plateau__lm_damping_exhausted(const plateau__lm_state *s)
{
    return !(s->mu / (s->amax > 1.0 ? s->amax : 1.0) <= PLATEAU_LM_MU_LIMIT);
}

/* One iteration of MNT Alg. 3.16 (the paper's Fig. 5): k := k + 1; solve
 * (A + mu I) h = -g (here (A' + mu I) h' = -g' in the scaled variables);
 * the step test; x_new := x + h; rho; accept (rho > 0) or raise mu. */
static plateau_lm_result plateau__lm_iteration(plateau__lm_state *s)
{
    const plateau_lm_options *o = s->o;
    size_t n = s->n, j;
    double Fnew, pred, rho, hnorm = 0.0, xnorm = 0.0;
    int accepted = 0, accel = 0;
    s->iter++;
    /* not positive definite in floating point: raise mu as after a failed
     * step and solve again (bounded by k_max and by PLATEAU_LM_MU_LIMIT) */
    if (!plateau__lm_step(s, s->mu)) {
        double floor_mu = DBL_EPSILON * s->amax > DBL_MIN ? DBL_EPSILON * s->amax : DBL_MIN;
        s->mu *= s->nu;
        if (s->mu < floor_mu) s->mu = floor_mu;
        s->nu *= 2.0;
        s->rejected = 1;
        if (plateau__lm_damping_exhausted(s)) { s->stop = PLATEAU_LM_STOP_DAMPING; return PLATEAU_LM_OK; }
        if (o->progress && o->progress(s->iter, s->F, s->ginf, s->mu, 0, s->user) != 0)
            return PLATEAU_LM_ERR_ABORTED;
        return PLATEAU_LM_OK;
    }
    /* Step test (MNT, corrected from Fig. 5): ||h|| <= eps2 (||x|| + floor)
     * in the scaled norm ||D .||, trusted only when the step is not a mere
     * artefact of heavy damping: after a rejection (stagnation), or when
     * mu <= min_j a'_jj (close to the Gauss-Newton step), and only when
     * plateau__lm_may_claim allows a claim of convergence. */
    for (j = 0; j < n; j++) {
        hnorm += s->h[j] * s->h[j];
        xnorm += (s->d[j] * s->x[j]) * (s->d[j] * s->x[j]);
    }
    hnorm = PLATEAU_SQRT(hnorm);
    xnorm = PLATEAU_SQRT(xnorm);
    if (hnorm <= o->eps_step * xnorm + s->step_floor && (s->rejected || s->mu <= s->amin) &&
        plateau__lm_may_claim(o, s->mu <= s->amin, s->cosine, s->F, s->F0)) {
        s->stop = PLATEAU_LM_STOP_STEP;
        return PLATEAU_LM_OK;
    }
    /* rho := (F(x) - F(x_new)) / (L(0) - L(h)), L(0) - L(h) = 1/2 h'^T (mu h' - g') */
    pred = 0.0;
    for (j = 0; j < n; j++) pred += s->h[j] * (s->mu * s->h[j] - s->g[j] / s->d[j]);
    pred *= 0.5;
    if (PLATEAU__LM_HAVE_EXTRAS && s->fvv && (o->geodesic == PLATEAU_LM_GEODESIC_ALWAYS ||
                   s->nonlinearity >= PLATEAU_LM_GEODESIC_NONLINEAR)) {
        accel = plateau__lm_accelerate(s);
        if (accel < 0) return PLATEAU_LM_ERR_ABORTED;
    }
    Fnew = PLATEAU__LM_HUGE;
    if (accel != 2) { /* 2: the acceleration rejected the step unevaluated */
        plateau__lm_trial(s, &pred);
        if (plateau__lm_all_finite(s->xnew, n)) {
            s->residual_evaluations++;
            if (plateau__lm_call(s, s->xnew, s->fnew, NULL) != 0) return PLATEAU_LM_ERR_ABORTED;
            Fnew = plateau__lm_half_sumsq(s->fnew, s->m);
            if (plateau__lm_finite(Fnew)) s->finite_trials++;
            else s->nonfinite_trials++;
        }
        if (s->fvv) s->nonlinearity = plateau__lm_nonlinearity(s, Fnew);
    }
    /* A NaN or infinite residual at the trial point is a failed step: the
     * step left the domain of f; a shorter one is tried next. */
    rho = (plateau__lm_finite(Fnew) && pred > 0.0) ? (s->F - Fnew) / pred : -1.0;
    if (rho > 0.0) {
        double Fold = s->F, *t;
        plateau_lm_result res;
        accepted = 1;
        s->accelerated += accel == 1;
        for (j = 0; j < n; j++) s->x[j] = s->xnew[j];
        t = s->f; s->f = s->fnew; s->fnew = t;
        s->F = Fnew;
        res = plateau__lm_accepted(s, Fold, pred, rho);
        if (res != PLATEAU_LM_OK) return res;
    } else {
        /* mu := mu * nu; nu := 2 nu */
        s->mu *= s->nu;
        s->nu *= 2.0;
        s->rejected = 1;
        if (plateau__lm_damping_exhausted(s)) s->stop = PLATEAU_LM_STOP_DAMPING;
    }
    if (o->progress && o->progress(s->iter, s->F, s->ginf, s->mu, accepted, s->user) != 0)
        return PLATEAU_LM_ERR_ABORTED;
    return PLATEAU_LM_OK;
}

/* ---- Householder QR with column pivoting (Businger and Golub; Golub and
 * Van Loan, "Matrix computations", 5.4.2) of a rows x cols row-major matrix
 * with leading dimension ld, in place: R on and above the diagonal, the
 * Householder vectors v (v_k = 1 implied) below it, H_k = I - tau_k v v^T.
 * perm[k] (as a double) is the original column of column k.  Stops at the
 * first column whose remaining norm is <= tol |r_11|: returns the rank. */
static size_t plateau__lm_qrp(double *a, size_t rows, size_t cols, size_t ld, double *tau,
                              double *cn, double *perm, double tol)
{
    size_t i, j, k, rank = 0, lim = rows < cols ? rows : cols;
    double r11 = 0.0;
    for (j = 0; j < cols; j++) {
        double t = 0.0;
        for (i = 0; i < rows; i++) t += a[i * ld + j] * a[i * ld + j];
        cn[j] = t;
        perm[j] = (double)j;
        tau[j] = 0.0;
    }
    for (k = 0; k < lim; k++) {
        size_t p = k;
        double norm = 0.0, alpha, v0;
        for (j = k + 1; j < cols; j++)
            if (cn[j] > cn[p]) p = j;
        if (p != k) {
            double t;
            for (i = 0; i < rows; i++) {
                t = a[i * ld + k]; a[i * ld + k] = a[i * ld + p]; a[i * ld + p] = t;
            }
            t = cn[k]; cn[k] = cn[p]; cn[p] = t;
            t = perm[k]; perm[k] = perm[p]; perm[p] = t;
        }
        for (i = k; i < rows; i++) norm += a[i * ld + k] * a[i * ld + k];
        norm = PLATEAU_SQRT(norm);
        if (k == 0) r11 = norm;
        if (!(norm > tol * r11) || !plateau__lm_finite(norm)) break;
        alpha = a[k * ld + k] > 0.0 ? -norm : norm;
        v0 = a[k * ld + k] - alpha;
        for (i = k + 1; i < rows; i++) a[i * ld + k] /= v0;
        tau[k] = -v0 / alpha;
        a[k * ld + k] = alpha;
        for (j = k + 1; j < cols; j++) {
            double s = a[k * ld + j], t = 0.0;
            for (i = k + 1; i < rows; i++) s += a[i * ld + k] * a[i * ld + j];
            s *= tau[k];
            a[k * ld + j] -= s;
            for (i = k + 1; i < rows; i++) {
                a[i * ld + j] -= s * a[i * ld + k];
                t += a[i * ld + j] * a[i * ld + j];
            }
            cn[j] = t; /* recomputed, not downdated: no cancellation */
        }
        rank++;
    }
    return rank;
}

/* v := Q^T v (transpose = 1) or Q v (transpose = 0) for the first `rank`
 * reflectors of plateau__lm_qrp; v has rows values. */
static void plateau__lm_qr_apply(const double *a, size_t rows, size_t ld, const double *tau,
                                 size_t rank, double *v, int transpose)
{
    size_t i, q;
    for (q = 0; q < rank; q++) {
        size_t k = transpose ? q : rank - 1 - q;
        double s = v[k];
        for (i = k + 1; i < rows; i++) s += a[i * ld + k] * v[i];
        s *= tau[k];
        v[k] -= s;
        for (i = k + 1; i < rows; i++) v[i] -= s * a[i * ld + k];
    }
}

/* ---- A small strictly convex quadratic program ------------------------------
 * min 1/2 h^T H h + c^T h subject to G_i h >= r_i (rows i of G, row-major
 * rows x k; r NULL: all 0), with H = L L^T from plateau__lm_cholesky (L
 * NULL: H = I), by the dual active-set method of Goldfarb and Idnani ("A
 * numerically stable dual method for solving strictly convex quadratic
 * programs", Math. Programming 27, 1983).  Start: the unconstrained minimum
 * h = -H^-1 c, no active rows.  Step 1: the most violated row p (slack over
 * its norm); none: optimal.  Step 2, with N the active normals and
 * B = L^-1 N: the primal direction z = L^-T (I - Q Q^T) L^-1 n_p (B = Q R),
 * the dual one r = (B^T B)^-1 B^T L^-1 n_p; the full step t2 = -s_p / n_p^T z
 * makes p active, the partial step t1 = min over r_l > 0 of u_l / r_l drops
 * row l first; h += t z, u -= t r, u_p += t.  No step at all: the rows
 * have no common point.  u (rows) gets the multipliers, 0 for inactive
 * rows.  work: k k + PLATEAU__LM_QP_VECTORS k doubles.  Returns 1 when h is
 * optimal, 0 when the rows are infeasible, the bound of 3 (rows + k) + 10
 * steps is reached, or the result misses a row by more than
 * PLATEAU_LM_ACTIVE_TOL of its scale (rounding in an ill-conditioned H; the
 * LM then raises mu, which conditions H). */

/* the slack G_i h - r_i of row i and its rounding scale |r_i| + sum |G_ij h_j| */
static double plateau__lm_slack(const double *gi, double ri, const double *h, size_t k,
                                double *scale)
{
    double sl = -ri, sc = PLATEAU_FABS(ri);
    size_t j;
    for (j = 0; j < k; j++) {
        double t = gi[j] * h[j];
        sl += t;
        sc += PLATEAU_FABS(t);
    }
    *scale = sc;
    return sl;
}

/* v := L^-1 v and v := L^-T v for the Cholesky factor of plateau__lm_cholesky */
static void plateau__lm_forward(const double *l, size_t k, double *v)
{
    size_t i, q;
    for (i = 0; i < k; i++) {
        double t = v[i];
        for (q = 0; q < i; q++) t -= l[i * k + q] * v[q];
        v[i] = t / l[i * k + i];
    }
}
static void plateau__lm_backward(const double *l, size_t k, double *v)
{
    size_t i, q;
    for (i = k; i-- > 0;) {
        double t = v[i];
        for (q = i + 1; q < k; q++) t -= l[q * k + i] * v[q];
        v[i] = t / l[i * k + i];
    }
}

/* Goldfarb-Idnani's step 2 directions for the active rows act[0..q) and row
 * p: z (primal, H^-1-projected) and rd (dual); returns n_p^T z, 0 when n_p
 * lies in the span of the active normals (to PLATEAU_LM_QP_DEPENDENT of
 * ||L^-1 n_p||^2), or -1 when the active normals are dependent. */
static double plateau__lm_qp_directions(const double *L, size_t k, const double *G,
                                        const double *act, size_t q, size_t p, double *w,
                                        double *z, double *rd)
{
    double *B = w, *tau = w + k * k, *cn = tau + k, *perm = cn + k, *v = perm + k, zn = 0.0, vn = 0.0;
    size_t j, l, rank;
    for (j = 0; j < k; j++) v[j] = G[p * k + j];
    if (L) plateau__lm_forward(L, k, v);
    for (j = 0; j < k; j++) vn += v[j] * v[j];
    for (l = 0; l < q; l++) {
        const double *gl = G + (size_t)act[l] * k;
        for (j = 0; j < k; j++) z[j] = gl[j];
        if (L) plateau__lm_forward(L, k, z);
        for (j = 0; j < k; j++) B[j * k + l] = z[j];
    }
    rank = plateau__lm_qrp(B, k, q, k, tau, cn, perm, 0.0);
    if (rank < q) return -1.0;
    for (j = 0; j < k; j++) z[j] = v[j];
    plateau__lm_qr_apply(B, k, k, tau, q, z, 1);
    for (l = q; l-- > 0;) { /* R^-1 Q^T v, then unpermuted */
        double t = z[l];
        for (j = l + 1; j < q; j++) t -= B[l * k + j] * v[j];
        v[l] = t / B[l * k + l];
    }
    for (l = 0; l < q; l++) rd[(size_t)perm[l]] = v[l];
    for (l = 0; l < q; l++) z[l] = 0.0;
    plateau__lm_qr_apply(B, k, k, tau, q, z, 0);
    for (j = 0; j < k; j++) zn += z[j] * z[j];
    if (L) plateau__lm_backward(L, k, z);
    return zn > PLATEAU_LM_QP_DEPENDENT * vn ? zn : 0.0;
}

/* The active rows act[0..q) hold with equality in exact arithmetic; with
 * an ill-conditioned H (mu tiny, J rank-deficient) the projections leave
 * them off by up to cond(H) eps.  h += N w, the least change that restores
 * N^T h = r_A (w from a QR of N: N^T N w = r_A - N^T h). */
static void plateau__lm_qp_restore(size_t k, const double *G, const double *r, const double *act,
                                   size_t q, double *h, double *work)
{
    double *B = work, *tau = work + k * k, *cn = tau + k, *perm = cn + k, *v = perm + k;
    size_t j, l, i, rank;
    for (l = 0; l < q; l++)
        for (j = 0; j < k; j++) B[j * k + l] = G[(size_t)act[l] * k + j];
    rank = plateau__lm_qrp(B, k, q, k, tau, cn, perm, 0.0);
    if (rank < q) return;
    for (j = 0; j < k; j++) v[j] = 0.0;
    for (l = 0; l < q; l++) { /* R^T t = P^T (r_A - N^T h), forward */
        size_t row = (size_t)act[(size_t)perm[l]];
        double scale, t = -plateau__lm_slack(G + row * k, r ? r[row] : 0.0, h, k, &scale);
        for (i = 0; i < l; i++) t -= B[i * k + l] * v[i];
        v[l] = t / B[l * k + l];
    }
    plateau__lm_qr_apply(B, k, k, tau, q, v, 0);
    for (j = 0; j < k; j++) h[j] += v[j];
}

static int plateau__lm_qp(const double *L, size_t k, const double *c, const double *G,
                          const double *r, size_t rows, double *h, double *u, double *work)
{
    double *act = work + k * k + 5 * k, *ua = act + k, *z = ua + k, *rd = z + k;
    size_t q = 0, i, j, l, it = 0, limit = 3 * (rows + k) + 10;
    for (j = 0; j < k; j++) h[j] = -c[j];
    if (L) plateau__lm_cholesky_solve(L, k, h);
    for (i = 0; i < rows; i++) u[i] = 0.0;
    while (it < limit) {
        size_t pv = rows;
        double worst = 0.0, up = 0.0;
        for (i = 0; i < rows; i++) { /* step 1 */
            double scale, gn = 0.0, sl = plateau__lm_slack(G + i * k, r ? r[i] : 0.0, h, k, &scale);
            int active = 0;
            for (l = 0; l < q; l++) active |= (size_t)act[l] == i;
            for (j = 0; j < k; j++) gn += G[i * k + j] * G[i * k + j];
            if (!active && sl < -PLATEAU_LM_QP_TOL * scale && gn > 0.0 &&
                sl / PLATEAU_SQRT(gn) < worst) {
                worst = sl / PLATEAU_SQRT(gn);
                pv = i;
            }
        }
        if (pv == rows) {
            for (l = 0; l < q; l++) u[(size_t)act[l]] = ua[l];
            if (q > 0) plateau__lm_qp_restore(k, G, r, act, q, h, work);
            /* every row, active ones included, holds to rounding: else the
             * projections have lost too many digits (H ill-conditioned) */
            for (i = 0; i < rows; i++) {
                double scale, sl = plateau__lm_slack(G + i * k, r ? r[i] : 0.0, h, k, &scale);
                if (sl < -PLATEAU_LM_ACTIVE_TOL * scale) return 0;
            }
            return plateau__lm_all_finite(h, k);
        }
        for (;;) { /* step 2: until row pv is active */
            double t1 = PLATEAU__LM_HUGE, t2 = PLATEAU__LM_HUGE, t, scale, zn, sp;
            size_t drop = q;
            if (++it > limit) return 0;
            zn = plateau__lm_qp_directions(L, k, G, act, q, pv, work, z, rd);
            if (zn < 0.0) return 0;
            for (l = 0; l < q; l++)
                if (rd[l] > 0.0 && ua[l] / rd[l] < t1) {
                    t1 = ua[l] / rd[l];
                    drop = l;
                }
            sp = plateau__lm_slack(G + pv * k, r ? r[pv] : 0.0, h, k, &scale);
            if (zn > 0.0) t2 = -sp / zn;
            if (!(t1 < PLATEAU__LM_HUGE) && !(t2 < PLATEAU__LM_HUGE)) return 0; /* infeasible */
            t = t2 < t1 ? t2 : t1;
            if (t2 < PLATEAU__LM_HUGE)
                for (j = 0; j < k; j++) h[j] += t * z[j];
            for (l = 0; l < q; l++) ua[l] -= t * rd[l];
            up += t;
            if (t2 <= t1) {
                if (q == k) return 0;
                act[q] = (double)pv;
                ua[q++] = up;
                break;
            }
            for (l = drop; l + 1 < q; l++) {
                act[l] = act[l + 1];
                ua[l] = ua[l + 1];
            }
            q--;
        }
    }
    return 0;
}

/* The damped step with inequality rows: h' minimises g'^T h' + 1/2 h'^T
 * (A' + mu I) h' subject to G D^-1 h' >= e - G x, so that the trial point
 * x + D^-1 h' satisfies every row (the factor of A' + mu I is in fac).
 * Scratch: xnew (g'), Gs, rq. */
static int plateau__lm_qp_step(plateau__lm_state *s)
{
    size_t n = s->n, i, j;
    for (j = 0; j < n; j++) s->xnew[j] = s->g[j] / s->d[j];
    for (i = 0; i < s->p; i++) {
        double t = s->e[i];
        for (j = 0; j < n; j++) {
            s->Gs[i * n + j] = s->G[i * n + j] / s->d[j];
            t -= s->G[i * n + j] * s->x[j];
        }
        s->rq[i] = t;
    }
    if (!plateau__lm_qp(s->fac, n, s->xnew, s->Gs, s->rq, s->p, s->h, s->u, s->qpw)) return 0;
    return plateau__lm_all_finite(s->h, n);
}

/* 1 when x satisfies every row G_i x >= e_i up to PLATEAU_LM_QP_TOL */
static int plateau__lm_rows_hold(const plateau__lm_state *s, const double *x)
{
    size_t i;
    for (i = 0; i < s->p; i++) {
        double scale, sl = plateau__lm_slack(s->G + i * s->n, s->e[i], x, s->n, &scale);
        if (sl < -PLATEAU_LM_QP_TOL * scale) return 0;
    }
    return 1;
}

/* With inequality rows, the gradient tests see gp = -P(-g), the steepest
 * descent direction projected onto the cone of feasible directions at x
 * (rows with slack <= PLATEAU_LM_ACTIVE_TOL of their scale are active): gp
 * is 0 at a constrained stationary point, as the binding set's g is for
 * BOUNDS.  Returns ||gp||_inf. */
static double plateau__lm_project_gradient(plateau__lm_state *s)
{
    size_t n = s->n, q = 0, i, j;
    double ginf = 0.0;
    for (i = 0; i < s->p; i++) {
        double scale, sl = plateau__lm_slack(s->G + i * n, s->e[i], s->x, n, &scale);
        if (sl > PLATEAU_LM_ACTIVE_TOL * scale) continue;
        for (j = 0; j < n; j++) s->Gs[q * n + j] = s->G[i * n + j];
        q++;
    }
    if (plateau__lm_qp(NULL, n, s->g, s->Gs, NULL, q, s->gp, s->u, s->qpw)) {
        for (j = 0; j < n; j++) s->gp[j] = -s->gp[j];
    } else {
        for (j = 0; j < n; j++) s->gp[j] = s->g[j];
    }
    for (j = 0; j < n; j++)
        if (PLATEAU_FABS(s->gp[j]) > ginf) ginf = PLATEAU_FABS(s->gp[j]);
    return ginf;
}

/* The columns of J scaled to unit length (scale[j] = 1 / ||J_j||, 0 for a
 * zero or held column, which is left out) into q (m x n), then QR with
 * column pivoting; returns the rank. */
static size_t plateau__lm_jacobian_qr(plateau__lm_state *s, const double *jac, double *scale)
{
    size_t m = s->m, n = s->n, i, j;
    for (j = 0; j < n; j++) {
        double c = 0.0;
        for (i = 0; i < m; i++) c += jac[i * n + j] * jac[i * n + j];
        c = PLATEAU_SQRT(c);
        scale[j] = c > 0.0 && (!PLATEAU__LM_FREE(s) || PLATEAU__LM_FREE(s)[j] > 0.0) ? 1.0 / c : 0.0;
    }
    for (i = 0; i < m; i++)
        for (j = 0; j < n; j++) s->qr[i * n + j] = jac[i * n + j] * scale[j];
    return plateau__lm_qrp(s->qr, m, n, n, s->tau, s->qcn, s->perm, PLATEAU_LM_RANK_TOL);
}

/* The Gauss-Newton step h minimising ||J h + f|| by the QR of
 * plateau__lm_jacobian_qr (rank columns; the others get 0); r: scratch m. */
static void plateau__lm_qr_step(plateau__lm_state *s, size_t rank, const double *scale,
                                double *r, double *h)
{
    size_t m = s->m, n = s->n, i, j, k;
    for (i = 0; i < m; i++) r[i] = -s->f[i];
    plateau__lm_qr_apply(s->qr, m, n, s->tau, rank, r, 1);
    for (j = 0; j < n; j++) h[j] = 0.0;
    for (k = rank; k-- > 0;) {
        double t = r[k];
        for (j = k + 1; j < rank; j++) t -= s->qr[k * n + j] * r[j];
        r[k] = t / s->qr[k * n + k];
    }
    for (k = 0; k < rank; k++) {
        size_t c = (size_t)s->perm[k];
        h[c] = r[k] * scale[c];
    }
}

/* REFINEMENT (m > n).  The damped steps come from the normal equations,
 * whose condition number is that of J squared: on an ill-conditioned fit
 * they stop moving while x is still 1e-7 off (NIST StRD MGH09, Thurber).
 * After the main loop converges (STEP, F_CHANGE or GRADIENT), Gauss-Newton
 * steps h = argmin ||J h + f|| from the QR of J itself (columns scaled to
 * unit length, pivoted) polish x: a step is kept when F falls, or
 * when the gradient measure (the cosine of the gradient test, which stays
 * accurate where F is flat to rounding) falls and F grows by no more than
 * PLATEAU_LM_REFINE_SLACK F; at most PLATEAU_LM_REFINE_STEPS steps, each
 * one residual and one Jacobian evaluation.  Scratch: qr (the trial J),
 * fr (the trial f), xnew and tau (the trial g and column norms), h (the
 * trial x). */
static plateau_lm_result plateau__lm_refine(plateau__lm_state *s)
{
    size_t m = s->m, n = s->n, i, j, r;
    for (r = 0; r < PLATEAU_LM_REFINE_STEPS; r++) {
        size_t rank = plateau__lm_jacobian_qr(s, s->jac, s->xnew);
        double hn = 0.0, xn = 0.0, Ft, ct, *t;
        plateau_lm_result res;
        if (rank == 0) break;
        plateau__lm_qr_step(s, rank, s->xnew, s->fr, s->h);
        for (j = 0; j < n; j++) {
            hn += s->h[j] * s->h[j];
            xn += s->x[j] * s->x[j];
            s->h[j] += s->x[j];
            if (s->o->lower && s->h[j] < s->o->lower[j]) s->h[j] = s->o->lower[j];
            if (s->o->upper && s->h[j] > s->o->upper[j]) s->h[j] = s->o->upper[j];
        }
        if (!(hn > DBL_EPSILON * DBL_EPSILON * xn) || !plateau__lm_all_finite(s->h, n)) break;
        if (!(hn <= PLATEAU_LM_REFINE_REACH * PLATEAU_LM_REFINE_REACH * (xn + 1.0))) break;
        s->residual_evaluations++;
        if (plateau__lm_call(s, s->h, s->fr, NULL) != 0) return PLATEAU_LM_ERR_ABORTED;
        Ft = plateau__lm_half_sumsq(s->fr, m);
        if (!plateau__lm_finite(Ft) || Ft > s->F * (1.0 + PLATEAU_LM_REFINE_SLACK)) break;
        res = plateau__lm_jacobian_at(s, s->h, s->fr, s->qr);
        if (res == PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN) break;
        if (res != PLATEAU_LM_OK) return res;
        /* the trial's gradient measure (free columns: at the trial point a
         * parameter on a bound with g pointing out counts as held) */
        for (j = 0; j < n; j++) s->xnew[j] = s->tau[j] = 0.0;
        for (i = 0; i < m; i++)
            for (j = 0; j < n; j++) {
                double q = s->qr[i * n + j];
                s->xnew[j] += q * s->fr[i];
                s->tau[j] += q * q;
            }
        for (j = 0; j < n; j++) {
            int held = (s->o->lower && s->h[j] <= s->o->lower[j] && s->xnew[j] > 0.0) ||
                       (s->o->upper && s->h[j] >= s->o->upper[j] && s->xnew[j] < 0.0);
            s->tau[j] = held ? 0.0 : PLATEAU_SQRT(s->tau[j]);
        }
        ct = plateau__lm_cosine(s->xnew, s->tau, n, Ft);
        if (!(Ft < s->F || ct < s->cosine)) break;
        for (j = 0; j < n; j++) s->x[j] = s->h[j];
        t = s->f; s->f = s->fr; s->fr = t;
        t = s->jac; s->jac = s->qr; s->qr = t;
        s->F = Ft;
        s->ginf = plateau__lm_prepare(s, 0);
        plateau__lm_diag_range(s, &s->amin, &s->amax);
        s->cosine = plateau__lm_grad_cosine(s, s->F);
        s->refined++;
        if (s->F <= s->f_stop || s->ginf == 0.0) break;
    }
    return PLATEAU_LM_OK;
}

/* REFINEMENT with inequality rows: Gauss-Newton steps that keep to the
 * rows, h' from the quadratic program of the undamped model (mu =
 * DBL_EPSILON max_j a'_jj only keeps the factor positive definite), each
 * kept by plateau__lm_refine's rule (F falls, or the gradient
 * measure, here of the projected gradient, falls while F grows by at most
 * PLATEAU_LM_REFINE_SLACK F); at most PLATEAU_LM_REFINE_STEPS, one residual
 * and one Jacobian each.  A step is judged after the state has moved to the
 * trial point (x kept in xnew) and moved back when it fails.  Scratch: qr
 * (the trial J), fr (the trial f), h (the trial x). */
static plateau_lm_result plateau__lm_refine_rows(plateau__lm_state *s)
{
    size_t n = s->n, j, r;
    for (r = 0; r < PLATEAU_LM_REFINE_STEPS; r++) {
        double pred = 0.0, hn = 0.0, xn = 0.0, Ft, Fold = s->F, cold = s->cosine, *t;
        plateau_lm_result res;
        if (!plateau__lm_step(s, DBL_EPSILON * s->amax)) break;
        for (j = 0; j < n; j++) {
            hn += (s->h[j] / s->d[j]) * (s->h[j] / s->d[j]);
            xn += s->x[j] * s->x[j];
        }
        if (!(hn > DBL_EPSILON * DBL_EPSILON * xn)) break;
        if (!(hn <= PLATEAU_LM_REFINE_REACH * PLATEAU_LM_REFINE_REACH * (xn + 1.0))) break;
        plateau__lm_trial(s, &pred);
        for (j = 0; j < n; j++) s->h[j] = s->xnew[j];
        if (!plateau__lm_all_finite(s->h, n)) break;
        s->residual_evaluations++;
        if (plateau__lm_call(s, s->h, s->fr, NULL) != 0) return PLATEAU_LM_ERR_ABORTED;
        Ft = plateau__lm_half_sumsq(s->fr, s->m);
        if (!plateau__lm_finite(Ft) || Ft > Fold * (1.0 + PLATEAU_LM_REFINE_SLACK)) break;
        res = plateau__lm_jacobian_at(s, s->h, s->fr, s->qr);
        if (res == PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN) break;
        if (res != PLATEAU_LM_OK) return res;
        for (j = 0; j < n; j++) {
            s->xnew[j] = s->x[j];
            s->x[j] = s->h[j];
        }
        t = s->f; s->f = s->fr; s->fr = t;
        t = s->jac; s->jac = s->qr; s->qr = t;
        s->F = Ft;
        s->ginf = plateau__lm_prepare(s, 0);
        s->cosine = plateau__lm_grad_cosine(s, s->F);
        if (!(Ft < Fold || s->cosine < cold)) { /* back to the point before */
            for (j = 0; j < n; j++) s->x[j] = s->xnew[j];
            t = s->f; s->f = s->fr; s->fr = t;
            t = s->jac; s->jac = s->qr; s->qr = t;
            s->F = Fold;
            s->ginf = plateau__lm_prepare(s, 0);
            s->cosine = cold;
            break;
        }
        plateau__lm_diag_range(s, &s->amin, &s->amax);
        s->refined++;
        if (s->F <= s->f_stop || s->ginf == 0.0) break;
    }
    return PLATEAU_LM_OK;
}

/* One least-squares solve with the weights in s->sw (if any): the start,
 * the main loop, the refinement. */
static plateau_lm_result plateau__lm_core(plateau__lm_state *s)
{
    plateau_lm_result res;
    s->iter = s->rejected = s->small_changes = 0;
    s->finite_trials = s->nonfinite_trials = 0;
    s->stop = PLATEAU_LM_STOP_NONE;
    s->cosine = 0.0;
    s->nonlinearity = PLATEAU__LM_HUGE; /* GEODESIC_AUTO: accelerate the first step */
    res = plateau__lm_start(s);
    /* MNT / Fig. 5 main loop: while (not found) and (k < k_max) */
    while (res == PLATEAU_LM_OK && s->stop == PLATEAU_LM_STOP_NONE) {
        if (s->iter >= s->o->max_iterations) {
            s->stop = PLATEAU_LM_STOP_MAX_ITERATIONS;
            break;
        }
        res = plateau__lm_iteration(s);
    }
    /* f not finite at any trial point tried (the start is the only finite
     * point seen): the step and damping tests then say nothing about a
     * minimum, the residual is broken around x0 */
    if (res == PLATEAU_LM_OK && s->finite_trials == 0 && s->nonfinite_trials > 0 &&
        (s->stop == PLATEAU_LM_STOP_STEP || s->stop == PLATEAU_LM_STOP_DAMPING))
        res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    if (PLATEAU__LM_HAVE_EXTRAS && res == PLATEAU_LM_OK && s->qr &&
        (s->stop == PLATEAU_LM_STOP_STEP || s->stop == PLATEAU_LM_STOP_F_CHANGE ||
         s->stop == PLATEAU_LM_STOP_GRADIENT))
        res = s->G ? plateau__lm_refine_rows(s) : plateau__lm_refine(s);
    return res;
}

#ifndef PLATEAU_LM_NO_EXTRAS
/* log(1 + q) for q >= 0 from square roots and a series (no libm log):
 * u = 1 + q halved in exponent by k square roots until u < 1.5, then
 * log u = 2 atanh(z) = 2 (z + z^3 / 3 + ...), z = (u - 1) / (u + 1) < 0.2,
 * and log(1 + q) = 2^k log u. */
static double plateau__lm_log1p(double q)
{
    double u = 1.0 + q, z, z2, term, sum, scale = 1.0;
    int i;
    if (!plateau__lm_finite(u)) return u;
    while (u >= 1.5) {
        u = PLATEAU_SQRT(u);
        scale *= 2.0;
    }
    z = q < 0.5 && scale == 1.0 ? q / (2.0 + q) : (u - 1.0) / (u + 1.0);
    z2 = z * z;
    term = z;
    sum = 0.0;
    for (i = 1; i < 60; i += 2) {
        sum += term / (double)i;
        term *= z2;
    }
    return 2.0 * scale * sum;
}

/* The robust loss: rho(t) and the IRLS weight rho'(t) / t (Huber; Cauchy). */
static double plateau__lm_loss(const plateau_lm_options *o, double t, double *weight)
{
    double c = o->loss_scale, at = PLATEAU_FABS(t), q;
    if (o->loss == PLATEAU_LM_LOSS_HUBER) {
        if (at <= c) { *weight = 1.0; return 0.5 * t * t; }
        *weight = c / at;
        return c * at - 0.5 * c * c;
    }
    if (o->loss == PLATEAU_LM_LOSS_CAUCHY) {
        q = (t / c) * (t / c);
        *weight = 1.0 / (1.0 + q);
        return 0.5 * c * c * plateau__lm_log1p(q);
    }
    *weight = 1.0;
    return 0.5 * t * t;
}

/* IRLS weights at x from the unweighted-by-loss residuals: sw_i =
 * sqrt(w_i omega_i), omega_i = rho'(t_i) / t_i, t_i = sqrt(w_i) f_i.  Returns
 * the robust objective sum rho(t_i) and in *change the largest change of an
 * omega_i; 0 in *ok when the callback aborted (-1) or f is not finite. */
static double plateau__lm_irls_weights(plateau__lm_state *s, double *change, int *ok)
{
    size_t i;
    double total = 0.0;
    *change = 0.0;
    s->residual_evaluations++;
    if (s->func(s->x, s->fnew, NULL, s->user) != 0) { *ok = -1; return 0.0; }
    for (i = 0; i < s->m; i++) {
        double w = s->o->weights ? PLATEAU_SQRT(s->o->weights[i]) : 1.0, om, old;
        old = s->sw[i] > 0.0 && w > 0.0 ? (s->sw[i] / w) * (s->sw[i] / w) : 0.0;
        total += plateau__lm_loss(s->o, w * s->fnew[i], &om);
        s->sw[i] = w * PLATEAU_SQRT(om);
        if (PLATEAU_FABS(om - old) > *change) *change = PLATEAU_FABS(om - old);
    }
    *ok = plateau__lm_finite(total) ? 1 : 0;
    return total;
}

/* A robust loss by iteratively reweighted least squares (Holland and
 * Welsch 1977): weighted solves with the weights of the last point, until
 * no weight moves by more than PLATEAU_LM_IRLS_TOL or max_irls rounds.
 * F reported: the robust objective sum rho(t_i). */
static plateau_lm_result plateau__lm_irls(plateau__lm_state *s, size_t *rounds)
{
    double change, obj, obj0;
    int ok, r;
    size_t i;
    plateau_lm_result res = PLATEAU_LM_OK;
    for (i = 0; i < s->m; i++) s->sw[i] = 0.0;
    obj = plateau__lm_irls_weights(s, &change, &ok);
    if (ok < 0) return PLATEAU_LM_ERR_ABORTED;
    if (!ok) return PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    obj0 = obj;
    for (r = 0; r < s->o->max_irls; r++) {
        res = plateau__lm_core(s);
        (*rounds)++;
        if (res != PLATEAU_LM_OK) break;
        obj = plateau__lm_irls_weights(s, &change, &ok);
        if (ok < 0) return PLATEAU_LM_ERR_ABORTED;
        if (!ok || change <= PLATEAU_LM_IRLS_TOL) break;
    }
    s->F0 = obj0;
    s->F = obj;
    return res;
}
#endif /* PLATEAU_LM_NO_EXTRAS */

/* ---- Linear equality constraints A x = b: elimination onto the null space.
 * A^T P = Q [R11 R12; 0 0] (QR with column pivoting of A^T, n x k; r = rank
 * R11).  With c = Q^T x, the constraints read R11^T c_1 = (P^T b)_1 and
 * R12^T c_1 = (P^T b)_2: c_1 is fixed, the particular solution is
 * x_p = Q [c_1; 0], and x = x_p + Z y with Z = Q[:, r:n] (orthonormal), y
 * free (Nocedal and Wright, "Numerical optimization", 15.3).  The reduced
 * problem in y has the Jacobian J Z. */
typedef struct plateau__lm_lec {
    plateau_lm_func func;
    void *user;
    size_t m, n, nr;       /* residuals, parameters, free parameters n - r */
    const double *z, *xp;  /* Z (n x nr row-major), x_p */
    const double *lo, *up; /* the bounds: x is clipped into them (rounding) */
    double *xf, *jf;       /* scratch: the full x, the full J */
} plateau__lm_lec;

static void plateau__lm_lec_x(const plateau__lm_lec *L, const double *y, double *x)
{
    size_t i, j;
    for (i = 0; i < L->n; i++) {
        double t = L->xp[i];
        for (j = 0; j < L->nr; j++) t += L->z[i * L->nr + j] * y[j];
        if (L->lo && t < L->lo[i]) t = L->lo[i];
        if (L->up && t > L->up[i]) t = L->up[i];
        x[i] = t;
    }
}

/* (J Z)_ij, 0 when it is within rounding of 0: where f depends on x only
 * through A x, which the constraints fix, the sum cancels to noise of the
 * order eps sum |J_iq Z_qj|, and the damped steps (MINPACK's scaling
 * above all) would follow that noise */
static double plateau__lm_jz(const double *jrow, const double *z, size_t n, size_t nr, size_t j)
{
    double t = 0.0, a = 0.0;
    size_t q;
    for (q = 0; q < n; q++) {
        double v = jrow[q] * z[q * nr + j];
        t += v;
        a += PLATEAU_FABS(v);
    }
    return PLATEAU_FABS(t) <= (double)n * DBL_EPSILON * a ? 0.0 : t;
}

/* the reduced residual callback: f(x_p + Z y), J Z */
static int plateau__lm_lec_func(const double *y, double *f, double *jac, void *user)
{
    const plateau__lm_lec *L = (const plateau__lm_lec *)user;
    size_t i, j;
    plateau__lm_lec_x(L, y, L->xf);
    if (L->func(L->xf, f, jac ? L->jf : NULL, L->user) != 0) return 1;
    if (jac)
        for (i = 0; i < L->m; i++)
            for (j = 0; j < L->nr; j++)
                jac[i * L->nr + j] = plateau__lm_jz(L->jf + i * L->n, L->z, L->n, L->nr, j);
    return 0;
}

/* Z and x_p for A x = b (k rows): qa (n x k scratch), tau, cn, perm (k
 * each, at least), z (n x n room), xp (n).  Returns the number of free
 * parameters n - r, or (size_t)-1 when A x = b has no solution. */
static PLATEAU__COLD size_t plateau__lm_lec_setup(size_t n, size_t k, const double *A, const double *b,
                                    double *qa, double *tau, double *cn, double *perm,
                                    double *z, double *xp)
{
    size_t i, j, r, nr;
    double *c = cn; /* reused once the factorisation is done */
    if (!plateau__lm_all_finite(A, n * k) || !plateau__lm_all_finite(b, k)) return (size_t)-1;
    for (i = 0; i < n; i++)
        for (j = 0; j < k; j++) qa[i * k + j] = A[j * n + i];
    r = plateau__lm_qrp(qa, n, k, k, tau, cn, perm, PLATEAU_LM_RANK_TOL);
    /* R11^T c_1 = (P^T b)_1: forward substitution; then x_p = Q [c_1; 0] */
    for (i = 0; i < n; i++) xp[i] = 0.0;
    for (i = 0; i < r; i++) {
        double t = b[(size_t)perm[i]];
        for (j = 0; j < i; j++) t -= qa[j * k + i] * xp[j];
        xp[i] = t / qa[i * k + i];
    }
    plateau__lm_qr_apply(qa, n, k, tau, r, xp, 0);
    /* consistency: every row of A x_p = b to rounding */
    for (j = 0; j < k; j++) {
        double t = -b[j], scale = PLATEAU_FABS(b[j]);
        for (i = 0; i < n; i++) {
            t += A[j * n + i] * xp[i];
            scale += PLATEAU_FABS(A[j * n + i] * xp[i]);
        }
        if (!(PLATEAU_FABS(t) <= PLATEAU_LM_CONSTRAINT_TOL * scale)) return (size_t)-1;
    }
    /* Z = Q e_j, j = r .. n-1 */
    nr = n - r;
    for (j = 0; j < nr; j++) {
        for (i = 0; i < n; i++) c[i] = i == r + j ? 1.0 : 0.0;
        plateau__lm_qr_apply(qa, n, k, tau, r, c, 0);
        for (i = 0; i < n; i++) z[i * nr + j] = c[i];
    }
    return nr;
}

/* The rows G y >= e of the bounds and of C x >= d on x = x_p + Z y: a
 * finite lower bound l_j gives Z_j y >= l_j - x_pj (Z_j: row j of Z), an
 * upper bound u_j gives -Z_j y >= x_pj - u_j, a row c of C gives c Z y >=
 * d - c x_p.  A row that vanishes (norm below PLATEAU_LM_CONSTRAINT_TOL of
 * the original row's: the equalities fix that combination) must hold at
 * x_p and is left out.  Returns the number of rows, or (size_t)-1 when such
 * a row fails or C or d holds a NaN or an infinity. */
static size_t plateau__lm_rows_build(const plateau_lm_options *o, size_t n, size_t nr,
                                     const double *z, const double *xp, double *G, double *e)
{
    size_t rows = 0, i, j, q, cand = 2 * n + o->inequalities;
    for (i = 0; i < cand; i++) {
        double *g = G + rows * nr, ei, scale, norm = 0.0, norm0 = 1.0;
        if (i < 2 * n) { /* bound i / 2, lower (even i) or upper (odd i) */
            size_t v = i / 2;
            const double *bnd = i % 2 ? o->upper : o->lower;
            double sign = i % 2 ? -1.0 : 1.0;
            if (!bnd || !plateau__lm_finite(bnd[v])) continue;
            for (j = 0; j < nr; j++) g[j] = sign * z[v * nr + j];
            ei = sign * (bnd[v] - xp[v]);
            scale = PLATEAU_FABS(bnd[v]) + PLATEAU_FABS(xp[v]);
        } else {
            const double *c = o->c_ineq + (i - 2 * n) * n;
            ei = o->d_ineq[i - 2 * n];
            if (!plateau__lm_finite(ei) || !plateau__lm_all_finite(c, n)) return (size_t)-1;
            scale = PLATEAU_FABS(ei);
            norm0 = 0.0;
            for (q = 0; q < n; q++) {
                ei -= c[q] * xp[q];
                scale += PLATEAU_FABS(c[q] * xp[q]);
                norm0 += c[q] * c[q];
            }
            for (j = 0; j < nr; j++) {
                double t = 0.0;
                for (q = 0; q < n; q++) t += c[q] * z[q * nr + j];
                g[j] = t;
            }
        }
        for (j = 0; j < nr; j++) norm += g[j] * g[j];
        if (!(norm > PLATEAU_LM_CONSTRAINT_TOL * PLATEAU_LM_CONSTRAINT_TOL * norm0)) {
            if (!(ei <= PLATEAU_LM_CONSTRAINT_TOL * scale)) return (size_t)-1;
            continue;
        }
        e[rows++] = ei;
    }
    return rows;
}

/* The checks of the fitting options against x: bounds (BAD_BOUNDS,
 * X0_OUTSIDE_BOUNDS, when the box is the only constraint: otherwise the
 * start is moved into the feasible set) and weights (ARGUMENT). */
static plateau_lm_result plateau__lm_check_inputs(size_t m, size_t n, const double *x,
                                                  const plateau_lm_options *o)
{
    size_t i;
    for (i = 0; PLATEAU__LM_HAVE_CONSTRAINTS && i < n; i++) { /* else no bounds */
        double lo = o->lower ? o->lower[i] : -PLATEAU__LM_HUGE;
        double up = o->upper ? o->upper[i] : PLATEAU__LM_HUGE;
        if (lo != lo || up != up || lo > up || lo == PLATEAU__LM_HUGE || up == -PLATEAU__LM_HUGE)
            return PLATEAU_LM_ERR_BAD_BOUNDS;
    }
    for (i = 0; PLATEAU__LM_HAVE_CONSTRAINTS && i < n && !plateau__lm_has_qp(o); i++)
        if ((o->lower && x[i] < o->lower[i]) || (o->upper && x[i] > o->upper[i]))
            return PLATEAU_LM_ERR_X0_OUTSIDE_BOUNDS;
    if (PLATEAU__LM_HAVE_EXTRAS && o->weights)
        for (i = 0; i < m; i++)
            if (!plateau__lm_nonneg(o->weights[i])) return PLATEAU_LM_ERR_ARGUMENT;
    return PLATEAU_LM_OK;
}

/* Runs a solve on the carved state s: with a robust loss by IRLS, else
 * one weighted (or plain) solve. */
static plateau_lm_result plateau__lm_run(plateau__lm_state *s, plateau_lm_report *report)
{
    plateau_lm_result res;
    size_t j, rounds = 0;
    if (PLATEAU__LM_HAVE_EXTRAS && s->sw && s->o->loss == PLATEAU_LM_LOSS_SQUARED)
        for (j = 0; j < s->m; j++) s->sw[j] = PLATEAU_SQRT(s->o->weights[j]);
#ifndef PLATEAU_LM_NO_EXTRAS /* else plateau__lm_options_valid refused a loss */
    if (s->sw && s->o->loss != PLATEAU_LM_LOSS_SQUARED) res = plateau__lm_irls(s, &rounds);
    else
#endif
        res = plateau__lm_core(s);
    if (report) {
        report->irls_rounds = rounds;
        report->active_bounds = 0;
        for (j = 0; PLATEAU__LM_HAVE_CONSTRAINTS && j < s->n; j++)
            report->active_bounds += (s->o->lower && s->x[j] == s->o->lower[j]) ||
                                     (s->o->upper && s->x[j] == s->o->upper[j]);
    }
    return res;
}

/* A solve with constraints: the null-space map in the workspace after the
 * inner solve's part (sized for n free parameters), the reduced solve on y,
 * and x = x_p + Z y at the end (also after an error: y is its last
 * accepted point).  With inequality rows G y >= e (LINEAR CONSTRAINTS) the
 * start y0 = Z^T (x0 - x_p) is first moved to the nearest point that
 * satisfies them (a quadratic program with H = I). */
static plateau_lm_result plateau__lm_run_constrained(plateau__lm_state *s, double *base,
                                                     plateau_lm_report *report)
{
    const plateau_lm_options *o = s->o;
    size_t m = s->m, n = s->n, k = o->constraints, inner = 0, nk = n > k ? n : k, i, j, rows = 0;
    size_t most = plateau__lm_qp_rows(o, n);
    plateau__lm_lec L;
    plateau_lm_options io = plateau__lm_inner_options(o);
    double *p, *qa, *tau, *cn, *perm, *z, *xp, *y, *x = s->x;
    plateau_lm_result res;
    (void)plateau__lm_constrained_doubles(m, n, o, &inner);
    p = base + inner;
    qa = p; p += n * k;
    tau = p; p += nk;
    cn = p; p += nk;
    perm = p; p += nk;
    z = p; p += n * n;
    xp = p; p += n;
    y = p; p += n;
    L.xf = p; p += n;
    L.jf = p;
    /* f and sw for the case nr = 0, G to check the rows */
    (void)plateau__lm_layout(m, n, &io, most, s, base);
    L.nr = plateau__lm_lec_setup(n, k, o->a_eq, o->b_eq, qa, tau, cn, perm, z, xp);
    if (L.nr == (size_t)-1) return PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS;
    if (s->G) {
        rows = plateau__lm_rows_build(o, n, L.nr, z, xp, s->G, s->e);
        if (rows == (size_t)-1) return PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS;
    }
    if (report) report->free_parameters = L.nr;
    /* y0 = Z^T (x0 - x_p): x0 projected onto the constraints */
    for (j = 0; j < L.nr; j++) {
        double t = 0.0;
        for (i = 0; i < n; i++) t += z[i * L.nr + j] * (x[i] - xp[i]);
        y[j] = t;
    }
    L.func = s->func;
    L.user = s->user;
    L.m = m;
    L.n = n;
    L.z = z;
    L.xp = xp;
    L.lo = o->lower;
    L.up = o->upper;
    if (L.nr == 0) {
        /* the constraints fix x: its residual is the answer */
        plateau__lm_lec_x(&L, y, x);
        if (PLATEAU__LM_HAVE_EXTRAS && s->sw)
            for (i = 0; i < m; i++) s->sw[i] = o->weights ? PLATEAU_SQRT(o->weights[i]) : 1.0;
        s->residual_evaluations++;
        if (plateau__lm_call(s, x, s->f, NULL) != 0) return PLATEAU_LM_ERR_ABORTED;
        s->F = s->F0 = plateau__lm_half_sumsq(s->f, m);
        s->stop = PLATEAU_LM_STOP_STEP;
        return plateau__lm_finite(s->F) ? PLATEAU_LM_OK : PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    }
    (void)plateau__lm_layout(m, L.nr, &io, most, s, base);
    if (s->G) {
        /* the rows again, where this layout keeps them; y0 moved onto them */
        (void)plateau__lm_rows_build(o, n, L.nr, z, xp, s->G, s->e);
        s->p = rows;
        for (j = 0; j < L.nr; j++) s->g[j] = -y[j];
        if (!plateau__lm_qp(NULL, L.nr, s->g, s->G, s->e, rows, s->h, s->u, s->qpw))
            return PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS;
        for (j = 0; j < L.nr; j++) y[j] = s->h[j];
    }
    s->n = L.nr;
    s->x = y;
    s->func = plateau__lm_lec_func;
    s->user = &L;
    s->o = &io;
    res = plateau__lm_run(s, report);
    plateau__lm_lec_x(&L, y, x);
    s->o = o;
    s->x = x;
    s->n = n;
    if (report) {
        report->active_bounds = 0;
        for (j = 0; j < n; j++)
            report->active_bounds += (o->lower && x[j] == o->lower[j]) || (o->upper && x[j] == o->upper[j]);
    }
    return res;
}

static plateau_lm_result plateau__lm_solve(size_t m, size_t n, double *x,
                                           plateau_lm_func func, void *user,
                                           const plateau_lm_options *options,
                                           void *work, size_t work_bytes,
                                           plateau_lm_report *report)
{
    plateau_lm_options o;
    plateau__lm_state s;
    plateau_lm_result res;
    void *owned = NULL;
    unsigned char *base;
    size_t need;

    if (report) {
        report->iterations = report->residual_evaluations = report->jacobian_evaluations = 0;
        report->f_initial = report->f_final = report->grad_inf = report->mu_final = 0.0;
        report->stop = PLATEAU_LM_STOP_ERROR;
        report->refinement_steps = report->accelerated_steps = report->irls_rounds = 0;
        report->active_bounds = 0;
        report->free_parameters = n;
    }
    if (!x || !func) return PLATEAU_LM_ERR_ARGUMENT;
    if (m == 0 || n == 0) return PLATEAU_LM_ERR_EMPTY;
    o = plateau_lm_resolved_options(options);
    if (!plateau__lm_options_valid(&o)) return PLATEAU_LM_ERR_ARGUMENT;
    need = plateau_lm_workspace_size(m, n, &o);
    if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
    if (!plateau__lm_all_finite(x, n)) return PLATEAU_LM_ERR_NOT_FINITE_X0;
    res = plateau__lm_check_inputs(m, n, x, &o);
    if (res != PLATEAU_LM_OK) return res;
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
    s.m = m; s.n = n; s.x = x; s.func = func; s.user = user; s.o = &o;
    s.residual_evaluations = s.jacobian_evaluations = s.accelerated = s.refined = 0;
    s.F = s.F0 = s.mu = s.ginf = 0.0;
    s.iter = 0;
    s.stop = PLATEAU_LM_STOP_NONE;
    if (PLATEAU__LM_HAVE_CONSTRAINTS && (o.constraints > 0 || plateau__lm_has_qp(&o))) {
        res = plateau__lm_run_constrained(&s, (double *)(void *)base, report);
    } else {
        (void)plateau__lm_layout(m, n, &o, 0, &s, (double *)(void *)base);
        res = plateau__lm_run(&s, report);
    }
    if (report) {
        report->iterations = (size_t)s.iter;
        report->residual_evaluations = s.residual_evaluations;
        report->jacobian_evaluations = s.jacobian_evaluations;
        report->f_initial = s.F0;
        report->f_final = s.F;
        report->grad_inf = s.ginf;
        report->mu_final = s.mu;
        report->refinement_steps = s.refined;
        report->accelerated_steps = s.accelerated;
        report->stop = res == PLATEAU_LM_OK ? s.stop
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
#ifdef PLATEAU_LM_NO_CONSTRAINTS
        if (res == PLATEAU_LM_ERR_ARGUMENT && options &&
            (options->constraints > 0 || options->inequalities > 0 || options->lower || options->upper))
            text = "linear constraints and bounds are compiled out by PLATEAU_LM_NO_CONSTRAINTS";
#endif
#ifdef PLATEAU_LM_NO_EXTRAS
        if (res == PLATEAU_LM_ERR_ARGUMENT && options &&
            (options->loss != PLATEAU_LM_LOSS_SQUARED || options->geodesic == PLATEAU_LM_GEODESIC_ALWAYS ||
             options->weights || options->numeric_jacobian))
            text = "robust losses, weights, numeric Jacobians and geodesic ALWAYS are compiled out by "
                   "PLATEAU_LM_NO_EXTRAS";
#endif
        err->code = res;
        err->index = -1;
        err->index2 = -1;
        if (res == PLATEAU_LM_ERR_NOT_FINITE_X0) /* x is untouched: name the entry */
            for (j = 0; j < n && err->index < 0; j++)
                if (!plateau__lm_finite(x[j])) err->index = (long)j;
        if (res == PLATEAU_LM_ERR_X0_OUTSIDE_BOUNDS || res == PLATEAU_LM_ERR_BAD_BOUNDS)
            for (j = 0; j < n && err->index < 0; j++) {
                double lo = options->lower ? options->lower[j] : -PLATEAU__LM_HUGE;
                double up = options->upper ? options->upper[j] : PLATEAU__LM_HUGE;
                if (!(lo <= x[j] && x[j] <= up) || !(lo <= up)) err->index = (long)j;
            }
        while (text[i] && i + 1 < sizeof err->message) {
            err->message[i] = text[i];
            i++;
        }
        err->message[i] = '\0';
    }
    return res;
}

#ifndef PLATEAU_LM_NO_EXTRAS
/* ---- Covariance ---------------------------------------------------------------
 * Workspace (doubles): f (m), J (m n), the QR copy (m n), tau, column norms,
 * permutation, column scales (n each), R^-1 (n n), xnew (n), fnew (m); with
 * constraints also Z (n n), x_p, the reduced J (m n) and the QR of A^T
 * (n k, and 3 max(n, k)). */
static size_t plateau__lm_cov_doubles(size_t m, size_t n, size_t k)
{
    size_t mn = plateau__bytes(m, n), nn = plateau__bytes(n, n), nk = plateau__bytes(n, k);
    size_t t, big = n > k ? n : k;
    if (mn == 0 || nn == 0 || (k > 0 && nk == 0) || big > (size_t)-1 / 8) return 0;
    if (m > (size_t)-1 / 4 || n > (size_t)-1 / 8) return 0;
    t = plateau__lm_add(plateau__lm_add(mn, mn), plateau__lm_add(plateau__lm_add(nn, nn), 3 * m));
    t = plateau__lm_add(t, 6 * n);
    if (k > 0) {
        t = plateau__lm_add(t, plateau__lm_add(nn, mn));
        t = plateau__lm_add(t, plateau__lm_add(nk, 3 * big + n));
    }
    return t;
}

PLATEAU_LM_DEF size_t plateau_lm_covariance_workspace_size(size_t m, size_t n,
                                                           const plateau_lm_options *options)
{
    size_t k = options ? options->constraints : 0, d, bytes;
    if (m == 0 || n == 0) return 0;
    d = plateau__lm_cov_doubles(m, n, k);
    bytes = d ? plateau__bytes(d, sizeof(double)) : 0;
    return bytes ? plateau__lm_add(bytes, sizeof(double)) : 0;
}

/* cov = s^2 Z P S R^-1 R^-T S P^T Z^T for the QR of the scaled J (S: the
 * column scales; Z = I without constraints) into cov (n x n) and the
 * standard errors; ri: n' x n' scratch for R^-1. */
static void plateau__lm_cov_assemble(const plateau__lm_state *s, size_t nr, const double *z,
                                     double s2, const double *scale, double *ri, double *cov,
                                     double *se, size_t n)
{
    size_t i, j, q;
    /* R^-1, upper triangular, column by column */
    for (j = 0; j < nr; j++)
        for (i = j + 1; i-- > 0;) {
            double t = i == j ? 1.0 : 0.0;
            for (q = i + 1; q <= j; q++) t -= s->qr[i * nr + q] * ri[q * nr + j];
            ri[i * nr + j] = t / s->qr[i * nr + i];
        }
    /* C = S P R^-1 R^-T P^T S: the reduced covariance, unpivoted, in s->a */
    for (i = 0; i < nr; i++)
        for (j = 0; j <= i; j++) {
            double t = 0.0;
            size_t pi = (size_t)s->perm[i], pj = (size_t)s->perm[j];
            for (q = (i > j ? i : j); q < nr; q++) t += ri[i * nr + q] * ri[j * nr + q];
            t *= s2 * scale[pi] * scale[pj];
            s->a[pi * nr + pj] = t;
            s->a[pj * nr + pi] = t;
        }
    /* back to the n parameters: Z C Z^T (Z = I without constraints) */
    for (i = 0; i < n; i++)
        for (j = 0; j <= i; j++) {
            double t = 0.0;
            size_t a, b;
            if (!z) {
                t = s->a[i * nr + j];
            } else {
                for (a = 0; a < nr; a++)
                    for (b = 0; b < nr; b++) t += z[i * nr + a] * s->a[a * nr + b] * z[j * nr + b];
            }
            if (cov) cov[i * n + j] = cov[j * n + i] = t;
            if (se && i == j) se[i] = PLATEAU_SQRT(t > 0.0 ? t : 0.0);
        }
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_covariance(size_t m, size_t n, const double *x,
                                                       plateau_lm_func func, void *user,
                                                       const plateau_lm_options *options,
                                                       double *cov, double *std_error,
                                                       size_t *rank, void *work,
                                                       size_t work_bytes)
{
    plateau_lm_options o;
    plateau__lm_state s;
    plateau_lm_result res = PLATEAU_LM_OK;
    size_t need, k, nr, r, i, big;
    void *owned = NULL;
    double *p, *ri, *scale, *z = NULL, *jz = NULL, F;
    unsigned char *base;
    if (rank) *rank = 0;
    if (cov && n && n <= (size_t)-1 / n) for (i = 0; i < n * n; i++) cov[i] = 0.0;
    if (std_error) for (i = 0; i < n; i++) std_error[i] = 0.0;
    if (!x || !func) return PLATEAU_LM_ERR_ARGUMENT;
    if (m == 0 || n == 0) return PLATEAU_LM_ERR_EMPTY;
    o = plateau_lm_resolved_options(options);
    if (!plateau__lm_options_valid(&o)) return PLATEAU_LM_ERR_ARGUMENT;
    if (!plateau__lm_all_finite(x, n)) return PLATEAU_LM_ERR_NOT_FINITE_X0;
    k = PLATEAU__LM_HAVE_CONSTRAINTS ? o.constraints : 0;
    need = plateau_lm_covariance_workspace_size(m, n, &o);
    if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
    if (o.weights)
        for (i = 0; i < m; i++)
            if (!plateau__lm_nonneg(o.weights[i])) return PLATEAU_LM_ERR_ARGUMENT;
    if (work) {
        if (work_bytes < need) return PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL;
        base = (unsigned char *)work;
    } else {
        owned = plateau__alloc(&o.allocator, need);
        if (!owned) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        base = (unsigned char *)owned;
    }
    if ((uintptr_t)base % sizeof(double)) base += sizeof(double) - (uintptr_t)base % sizeof(double);
    p = (double *)(void *)base;
    big = n > k ? n : k;
    s.m = m; s.n = n; s.k = n; s.x = (double *)(void *)p; p += n;
    s.func = func; s.user = user; s.o = &o;
    s.residual_evaluations = s.jacobian_evaluations = 0;
    s.free_ = NULL;
    s.wide = 0;
    s.p = 0;
    s.G = s.e = s.Gs = s.rq = s.u = s.gp = s.qpw = NULL;
    s.f = p; p += m;
    s.fnew = p; p += m;
    s.jac = p; p += m * n;
    s.qr = p; p += m * n;
    s.tau = p; p += n;
    s.qcn = p; p += n;
    s.perm = p; p += n;
    s.xnew = p; p += n;
    scale = p; p += n;
    s.sw = p; p += m;
    ri = p; p += n * n;
    s.a = p; p += n * n;
    for (i = 0; i < n; i++) s.x[i] = x[i];
    nr = n;
    if (k > 0) {
        double *qa = p, *tau = qa + n * k, *cn = tau + big, *perm = cn + big, *xp;
        z = perm + big;
        xp = z + n * n;
        jz = xp + n;
        nr = plateau__lm_lec_setup(n, k, o.a_eq, o.b_eq, qa, tau, cn, perm, z, xp);
        if (nr == (size_t)-1) { res = PLATEAU_LM_ERR_INCONSISTENT_CONSTRAINTS; goto done; }
    }
    if (m <= nr) { res = PLATEAU_LM_ERR_NO_DEGREES_OF_FREEDOM; goto done; }
    /* f and J at x, weighted */
    s.residual_evaluations++;
    if (func(x, s.f, NULL, user) != 0) { res = PLATEAU_LM_ERR_ABORTED; goto done; }
    for (i = 0; i < m && o.weights; i++) s.f[i] *= PLATEAU_SQRT(o.weights[i]);
    F = plateau__lm_half_sumsq(s.f, m);
    if (!plateau__lm_finite(F)) { res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL; goto done; }
    if (o.weights) {
        for (i = 0; i < m; i++) s.sw[i] = PLATEAU_SQRT(o.weights[i]);
    } else {
        s.sw = NULL;
    }
    res = plateau__lm_jacobian_at(&s, s.x, s.f, s.jac);
    if (res != PLATEAU_LM_OK) goto done;
    if (k > 0) {
        /* the reduced Jacobian J Z (m x nr) in place of J */
        size_t a, b;
        for (a = 0; a < m; a++)
            for (b = 0; b < nr; b++) jz[a * nr + b] = plateau__lm_jz(s.jac + a * n, z, n, nr, b);
        for (a = 0; a < m * nr; a++) s.jac[a] = jz[a];
        s.n = nr;
    }
    r = plateau__lm_jacobian_qr(&s, s.jac, scale);
    if (rank) *rank = r;
    if (r < nr) { res = PLATEAU_LM_ERR_RANK_DEFICIENT; goto done; }
    plateau__lm_cov_assemble(&s, nr, z, 2.0 * F / (double)(m - nr), scale, ri, cov, std_error, n);
done:
    if (res != PLATEAU_LM_OK) {
        if (cov) for (i = 0; i < n * n; i++) cov[i] = 0.0;
        if (std_error) for (i = 0; i < n; i++) std_error[i] = 0.0;
    }
    plateau__free(&o.allocator, owned);
    return res;
}

/* ---- Jacobian check ------------------------------------------------------------
 * Workspace (doubles): J (m n), f at x, f(x + h), f(x - h), the previous
 * level's quotients, the best quotient and its error estimate (m each),
 * the moved x (n). */
PLATEAU_LM_DEF size_t plateau_lm_check_workspace_size(size_t m, size_t n)
{
    size_t mn = plateau__bytes(m, n), t, bytes;
    if (m == 0 || n == 0 || mn == 0 || m > (size_t)-1 / 8) return 0;
    t = plateau__lm_add(plateau__lm_add(mn, 7 * m), n);
    bytes = t ? plateau__bytes(t, sizeof(double)) : 0;
    return bytes ? plateau__lm_add(bytes, sizeof(double)) : 0;
}

/* Column j: central differences D_k = (f(x + h_k) - f(x - h_k)) / (2 h_k) at
 * h_k = h_0 / 4^k, k = 0 .. PLATEAU_LM_CHECK_LEVELS - 1, h_0 =
 * cbrt(DBL_EPSILON) |x_j| (cbrt(DBL_EPSILON) for x_j = 0).  Per entry, the
 * error of D_k is estimated as its truncation |D_k - D_(k-1)| / 15 (the
 * h^2 term shrinks 16-fold from one level to the next) plus the rounding
 * of f_i, 4 eps size_i / h_k, where size_i = |f_i(x + h)| + |f_i(x - h)| +
 * 2 sum_j |J_ij x_j| also counts the terms a residual is the difference
 * of (model - data); the level of least estimate wins: d[i], e[i].  Returns 0 when the callback aborted (*aborted = 1) or no
 * level gave finite residuals. */
static int plateau__lm_check_column(plateau_lm_func func, void *user, size_t m, double *xt,
                                    size_t j, double *fp, double *fm, double *prev, double *d,
                                    double *e, const double *size, int *aborted)
{
    double xj = xt[j], h0 = PLATEAU_LM_CHECK_STEP * (xj != 0.0 ? PLATEAU_FABS(xj) : 1.0);
    size_t i;
    int k, have = 0, found = 0;
    for (i = 0; i < m; i++) e[i] = PLATEAU__LM_HUGE;
    for (k = 0; k < PLATEAU_LM_CHECK_LEVELS; k++, h0 *= 0.25) {
        double h = (xj + h0) - xj; /* a step exact in floating point */
        int ok;
        xt[j] = xj + h;
        ok = func(xt, fp, NULL, user) == 0;
        xt[j] = xj - h;
        ok = ok && func(xt, fm, NULL, user) == 0;
        xt[j] = xj;
        if (!ok) { *aborted = 1; return 0; }
        if (h == 0.0 || !plateau__lm_all_finite(fp, m) || !plateau__lm_all_finite(fm, m)) {
            have = 0;
            continue;
        }
        for (i = 0; i < m; i++) {
            double q = (fp[i] - fm[i]) / (2.0 * h);
            double round = 4.0 * DBL_EPSILON * (PLATEAU_FABS(fp[i]) + PLATEAU_FABS(fm[i]) + size[i]) / h;
            if (have) {
                double est = PLATEAU_FABS(q - prev[i]) / 15.0 + round;
                if (est < e[i]) { e[i] = est; d[i] = q; }
            }
            prev[i] = q;
        }
        if (have) found = 1;
        have = 1;
    }
    return found;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_check_jacobian(size_t m, size_t n, const double *x,
                                                           plateau_lm_func func, void *user,
                                                           const plateau_lm_options *options,
                                                           plateau_lm_jacobian_check *check,
                                                           unsigned char *verdicts,
                                                           void *work, size_t work_bytes)
{
    plateau_lm_options o;
    plateau_lm_result res = PLATEAU_LM_OK;
    size_t need, i, j;
    void *owned = NULL;
    unsigned char *base;
    double *J, *f, *fp, *fm, *prev, *d, *e, *size, *xt, tol;
    int aborted = 0;
    if (check) {
        check->wrong = 0;
        check->worst_row = check->worst_col = -1;
        check->worst_ratio = check->worst_analytic = check->worst_difference = 0.0;
    }
    if (!x || !func || !check) return PLATEAU_LM_ERR_ARGUMENT;
    if (m == 0 || n == 0) return PLATEAU_LM_ERR_EMPTY;
    o = plateau_lm_resolved_options(options);
    if (!plateau__lm_options_valid(&o)) return PLATEAU_LM_ERR_ARGUMENT;
    if (!plateau__lm_all_finite(x, n)) return PLATEAU_LM_ERR_NOT_FINITE_X0;
    tol = options && options->eps_grad > 0.0 ? options->eps_grad : PLATEAU_LM_CHECK_TOL;
    need = plateau_lm_check_workspace_size(m, n);
    if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
    if (work) {
        if (work_bytes < need) return PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL;
        base = (unsigned char *)work;
    } else {
        owned = plateau__alloc(&o.allocator, need);
        if (!owned) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        base = (unsigned char *)owned;
    }
    if ((uintptr_t)base % sizeof(double)) base += sizeof(double) - (uintptr_t)base % sizeof(double);
    J = (double *)(void *)base;
    f = J + m * n; fp = f + m; fm = fp + m; prev = fm + m; d = prev + m; e = d + m;
    size = e + m; xt = size + m;
    for (j = 0; j < n; j++) xt[j] = x[j];
    if (func(xt, f, J, user) != 0) { res = PLATEAU_LM_ERR_ABORTED; goto done; }
    if (!plateau__lm_all_finite(f, m)) { res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL; goto done; }
    if (!plateau__lm_all_finite(J, m * n)) { res = PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN; goto done; }
    for (i = 0; i < m; i++) {
        size[i] = 0.0;
        for (j = 0; j < n; j++) size[i] += 2.0 * PLATEAU_FABS(J[i * n + j] * x[j]);
    }
    for (j = 0; j < n; j++) {
        if (!plateau__lm_check_column(func, user, m, xt, j, fp, fm, prev, d, e, size, &aborted)) {
            res = aborted ? PLATEAU_LM_ERR_ABORTED : PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
            goto done;
        }
        for (i = 0; i < m; i++) {
            /* WRONG: |J_ij - D_ij| > tol max(|J_ij|, |D_ij|) + margin (estimate) */
            double a = J[i * n + j], big, allow, err, ratio;
            big = PLATEAU_FABS(a) > PLATEAU_FABS(d[i]) ? PLATEAU_FABS(a) : PLATEAU_FABS(d[i]);
            allow = tol * big + PLATEAU_LM_CHECK_MARGIN * e[i];
            err = PLATEAU_FABS(a - d[i]);
            ratio = allow > 0.0 ? err / allow : (err > 0.0 ? PLATEAU__LM_HUGE : 0.0);
            if (verdicts)
                verdicts[i * n + j] = (unsigned char)(ratio > 1.0 ? PLATEAU_LM_JACOBIAN_WRONG
                                                                : PLATEAU_LM_JACOBIAN_OK);
            if (ratio > 1.0) check->wrong++;
            if (ratio > check->worst_ratio || check->worst_row < 0) {
                check->worst_ratio = ratio;
                check->worst_row = (long)i;
                check->worst_col = (long)j;
                check->worst_analytic = a;
                check->worst_difference = d[i];
            }
        }
    }
done:
    plateau__free(&o.allocator, owned);
    return res;
}

#else /* PLATEAU_LM_NO_EXTRAS: the covariance and the Jacobian check refuse */
PLATEAU_LM_DEF size_t plateau_lm_covariance_workspace_size(size_t m, size_t n,
                                                           const plateau_lm_options *options)
{
    (void)m, (void)n, (void)options;
    return 0;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_covariance(size_t m, size_t n, const double *x,
                                                       plateau_lm_func func, void *user,
                                                       const plateau_lm_options *options,
                                                       double *cov, double *std_error,
                                                       size_t *rank, void *work,
                                                       size_t work_bytes)
{
    (void)m, (void)n, (void)x, (void)func, (void)user, (void)options;
    (void)cov, (void)std_error, (void)rank, (void)work, (void)work_bytes;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF size_t plateau_lm_check_workspace_size(size_t m, size_t n)
{
    (void)m, (void)n;
    return 0;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_check_jacobian(size_t m, size_t n, const double *x,
                                                           plateau_lm_func func, void *user,
                                                           const plateau_lm_options *options,
                                                           plateau_lm_jacobian_check *check,
                                                           unsigned char *verdicts,
                                                           void *work, size_t work_bytes)
{
    (void)m, (void)n, (void)x, (void)func, (void)user, (void)options;
    (void)check, (void)verdicts, (void)work, (void)work_bytes;
    return PLATEAU_LM_ERR_ARGUMENT;
}
#endif /* PLATEAU_LM_NO_EXTRAS */

#ifndef PLATEAU_LM_NO_SPARSE
/* ==== Large sparse systems: implementation ================================ */

#define PLATEAU_LM_SPARSE_DEFAULT_LEAF 8
#define PLATEAU_LM_SPARSE_DEFAULT_PIVOT_TOL 1e-10
/* blocking of the dense kernels: panel width of the partial factorisations,
 * and the packed product's k, m and n blocks (a 4 x 4 register tile) */
#define PLATEAU__LM_NB 32
#define PLATEAU__LM_KC 256
#define PLATEAU__LM_MC 64
#define PLATEAU__LM_NC 1024

struct plateau_lm_sparse_symbolic {
    plateau_allocator alloc;
    size_t n, b, nnz, ns;
    size_t *rs;           /* n + 1: row starts (a copy of the pattern) */
    plateau_index *cols;  /* nnz */
    size_t *tpos;         /* nnz: position of block (k, i) for block (i, k) */
    plateau_index *perm;  /* n: elimination position -> node */
    plateau_index *pinv;  /* n: node -> elimination position */
    size_t *sfirst;       /* ns + 1: first position of each supernode */
    size_t *srp;          /* ns + 1: starts in srows */
    plateau_index *srows; /* off-diagonal block rows (positions) of each supernode, ascending */
    size_t *scp;          /* ns + 1: starts in schild */
    size_t *schild;       /* children of each supernode, ascending */
    size_t *lpos, *upos;  /* ns + 1: offsets (doubles) of L and U of each supernode */
    size_t stack_peak;    /* doubles */
    size_t front_max;     /* largest front order (unknowns) */
    plateau_lm_sparse_info info;
    double pivot_tol;
    int (*cancel)(void *user); /* plateau_lm_sparse_options.cancel */
    void *cancel_user;
    void *base;           /* the allocation holding this object */
};

struct plateau_lm_sparse_factor {
    const plateau_lm_sparse_symbolic *sym;
    void *owned;          /* the allocation, or NULL inside a caller workspace */
    int kind, factored;
    int single;           /* LU: L and U rounded to float in place (plateau__lm_lu_to_single) */
    plateau_index failed;
    size_t negative, positive; /* LDL^T: the signs of D */
    double *L, *U, *dinv, *stack, *front, *y, *pa, *pb;
    plateau_index *map;   /* unknown (elimination numbering) -> front position */
    plateau_index *rel;   /* a child's rows in its parent's front */
};

/* Byte layout helper: *total += count * size rounded up to 16 bytes.
 * Returns 0 on overflow. */
static int plateau__lm_lay(size_t *total, size_t count, size_t size)
{
    size_t bytes;
    if (count != 0 && size != 0 && count > (size_t)-1 / size) return 0;
    bytes = count * size;
    if (bytes > (size_t)-1 - 15) return 0;
    bytes = (bytes + 15) & ~(size_t)15;
    if (bytes > (size_t)-1 - *total) return 0;
    *total += bytes;
    return 1;
}
/* Carves count * size bytes (rounded to 16) from *p. */
static void *plateau__lm_take(unsigned char **p, size_t count, size_t size)
{
    void *r = (void *)*p;
    *p += (count * size + 15) & ~(size_t)15;
    return r;
}
/* a * b, or 0 with *ok = 0 on overflow */
static size_t plateau__lm_mul(size_t a, size_t b, int *ok)
{
    if (a != 0 && b > (size_t)-1 / a) { *ok = 0; return 0; }
    return a * b;
}
static size_t plateau__lm_sum(size_t a, size_t b, int *ok)
{
    if (b > (size_t)-1 - a) { *ok = 0; return 0; }
    return a + b;
}
static unsigned char *plateau__lm_align16(void *p)
{
    unsigned char *c = (unsigned char *)p;
    size_t mis = (size_t)((uintptr_t)c % 16);
    return mis ? c + (16 - mis) : c;
}

/* Ascending sort of a short index list (Shell's increments 1, 4, 13, ...). */
static void plateau__lm_sort_index(plateau_index *a, size_t len)
{
    size_t h = 1, i, j;
    while (h < len / 3) h = 3 * h + 1;
    for (; h > 0; h /= 3)
        for (i = h; i < len; i++) {
            plateau_index v = a[i];
            for (j = i; j >= h && a[j - h] > v; j -= h) a[j] = a[j - h];
            a[j] = v;
        }
}

/* ---- Nested dissection ----------------------------------------------------
 * Working state: the graph (pattern without the diagonal), the node order
 * being built in place (each part is a contiguous range of ord), tags
 * naming each node's side of the current split, a BFS queue and levels. */
typedef struct plateau__lm_nd {
    size_t n;
    const size_t *rs;
    const plateau_index *cols;
    const double *xy;
    plateau_index *ord, *queue, *level, *tmp;
    size_t *tag, *seen, *pos, counter;
} plateau__lm_nd;

/* Breadth-first level structure of the nodes tagged `member` reachable from
 * `start`; returns the number reached (queue holds them in BFS order,
 * level[] their levels, seen[] = stamp). */
static size_t plateau__lm_bfs(plateau__lm_nd *d, plateau_index start, size_t member, size_t stamp)
{
    size_t head = 0, tail = 0, p;
    d->queue[tail++] = start;
    d->seen[start] = stamp;
    d->level[start] = 0;
    while (head < tail) {
        plateau_index v = d->queue[head++];
        for (p = d->rs[v]; p < d->rs[v + 1]; p++) {
            plateau_index w = d->cols[p];
            if (d->tag[w] != member || d->seen[w] == stamp) continue;
            d->seen[w] = stamp;
            d->level[w] = d->level[v] + 1;
            d->queue[tail++] = w;
        }
    }
    return tail;
}

/* Rearranges ord[lo, hi) as [side A | side B | separator] by tags tA, tB
 * (anything else = separator); returns the sizes of A and B. */
static void plateau__lm_nd_arrange(plateau__lm_nd *d, size_t lo, size_t hi, size_t tA, size_t tB,
                                   size_t *na, size_t *nb)
{
    size_t i, k = 0, pass;
    *na = *nb = 0;
    for (pass = 0; pass < 3; pass++)
        for (i = lo; i < hi; i++) {
            size_t t = d->tag[d->ord[i]];
            int want = pass == 0 ? t == tA : pass == 1 ? t == tB : (t != tA && t != tB);
            if (!want) continue;
            d->tmp[k++] = d->ord[i];
            if (pass == 0) (*na)++;
            if (pass == 1) (*nb)++;
        }
    for (i = 0; i < k; i++) d->ord[lo + i] = d->tmp[i];
}

/* Places the k-th smallest (by coordinate axis) of ord[lo, hi) at lo + k,
 * smaller ones before it, larger after (Hoare's FIND in Wirth's form: the
 * pivot is the current candidate, each pass shrinks [l, r]). */
static void plateau__lm_select(plateau__lm_nd *d, size_t lo, size_t hi, size_t k, int axis)
{
    const double *xy = d->xy;
    ptrdiff_t l = (ptrdiff_t)lo, r = (ptrdiff_t)hi - 1, t = (ptrdiff_t)(lo + k);
    while (l < r) {
        double x = xy[2 * d->ord[t] + axis];
        ptrdiff_t i = l, j = r;
        do {
            while (xy[2 * d->ord[i] + axis] < x) i++;
            while (x < xy[2 * d->ord[j] + axis]) j--;
            if (i <= j) {
                plateau_index s = d->ord[i];
                d->ord[i] = d->ord[j];
                d->ord[j] = s;
                i++;
                j--;
            }
        } while (i <= j);
        if (j < t) l = i;
        if (t < i) r = j;
    }
}

/* Thins a vertex separator (tag tS) between sides tA and tB of ord[lo, hi):
 * a separator node with no neighbour in B joins A, then one with no
 * neighbour in A joins B; each move keeps A and B without a common edge. */
static void plateau__lm_nd_thin(plateau__lm_nd *d, size_t lo, size_t hi, size_t tA, size_t tB,
                                size_t tS)
{
    size_t i, p, pass;
    for (pass = 0; pass < 2; pass++) {
        size_t other = pass == 0 ? tB : tA, mine = pass == 0 ? tA : tB;
        for (i = lo; i < hi; i++) {
            plateau_index v = d->ord[i];
            if (d->tag[v] != tS) continue;
            for (p = d->rs[v]; p < d->rs[v + 1]; p++)
                if (d->tag[d->cols[p]] == other) break;
            if (p == d->rs[v + 1]) d->tag[v] = mine;
        }
    }
}

/* The smallest vertex separator made of endpoints of the edges between
 * sides tA and tB of ord[lo, hi): a minimum vertex cover of that bipartite
 * graph (Konig: from a maximum matching, grown by Kuhn's augmenting paths,
 * the matched A nodes not reachable by alternating paths from unmatched A
 * nodes, and the reachable B nodes).  Cover nodes get tag tS. */
static void plateau__lm_nd_cover(plateau__lm_nd *d, size_t lo, size_t hi, size_t tA, size_t tB,
                                 size_t tS)
{
    plateau_index *mate = d->level, *via = d->tmp, *stk = d->queue;
    size_t i, head, tail, zs;
    for (i = lo; i < hi; i++) mate[d->ord[i]] = -1;
    for (i = lo; i < hi; i++) {
        plateau_index u0 = d->ord[i];
        size_t sp = 0, stamp;
        if (d->tag[u0] != tA) continue;
        stamp = ++d->counter;
        stk[sp++] = u0;
        d->seen[u0] = stamp;
        d->pos[u0] = d->rs[u0];
        /* depth-first search for an augmenting path; every node is pushed
         * at most once per search */
        while (sp > 0) {
            plateau_index u = stk[sp - 1], w = -1;
            while (d->pos[u] < d->rs[u + 1]) {
                plateau_index c = d->cols[d->pos[u]++];
                if (d->tag[c] == tB && d->seen[c] != stamp) { w = c; break; }
            }
            if (w < 0) { sp--; continue; }
            d->seen[w] = stamp;
            if (mate[w] == -1) {
                /* flip the path u0 -> ... -> u -> w */
                size_t q = sp;
                while (q-- > 0) {
                    plateau_index a = stk[q], nextw = q > 0 ? via[a] : -1;
                    mate[w] = a;
                    mate[a] = w;
                    w = nextw;
                }
                break;
            } else {
                plateau_index u2 = mate[w];
                if (d->seen[u2] != stamp) {
                    d->seen[u2] = stamp;
                    via[u2] = w;
                    d->pos[u2] = d->rs[u2];
                    stk[sp++] = u2;
                }
            }
        }
    }
    /* alternating reachability from the unmatched A nodes */
    zs = ++d->counter;
    head = tail = 0;
    for (i = lo; i < hi; i++) {
        plateau_index v = d->ord[i];
        if (d->tag[v] == tA && mate[v] == -1) {
            d->seen[v] = zs;
            stk[tail++] = v;
        }
    }
    while (head < tail) {
        plateau_index u = stk[head++];
        size_t p;
        for (p = d->rs[u]; p < d->rs[u + 1]; p++) {
            plateau_index c = d->cols[p];
            if (d->tag[c] != tB || d->seen[c] == zs) continue;
            d->seen[c] = zs;
            if (mate[c] != -1 && d->seen[mate[c]] != zs) {
                d->seen[mate[c]] = zs;
                stk[tail++] = mate[c];
            }
        }
    }
    for (i = lo; i < hi; i++) {
        plateau_index v = d->ord[i];
        if ((d->tag[v] == tA && mate[v] != -1 && d->seen[v] != zs) ||
            (d->tag[v] == tB && d->seen[v] == zs))
            d->tag[v] = tS;
    }
}

/* Splits ord[lo, hi) by BFS levels from a pseudo-peripheral node: A = levels
 * before the median level, separator = the median level, B = the rest (and
 * whatever the search did not reach).  Returns 0 when no split is possible. */
static int plateau__lm_nd_graph_split(plateau__lm_nd *d, size_t lo, size_t hi, size_t *na, size_t *nb)
{
    size_t len = hi - lo, i, reached, member = ++d->counter, tA, tB, tS, round, lm, acc;
    plateau_index start = d->ord[lo], maxlev = 0;
    for (i = lo; i < hi; i++) d->tag[d->ord[i]] = member;
    reached = plateau__lm_bfs(d, start, member, ++d->counter);
    /* pseudo-peripheral node (Gibbs, Poole and Stockmeyer): restart from a
     * node of least degree in the last level while the depth grows */
    for (round = 0; round < 4; round++) {
        plateau_index last = d->level[d->queue[reached - 1]], best = d->queue[reached - 1];
        size_t bestdeg = (size_t)-1, j;
        for (j = reached; j-- > 0 && d->level[d->queue[j]] == last;) {
            plateau_index v = d->queue[j];
            size_t deg = d->rs[v + 1] - d->rs[v];
            if (deg < bestdeg) { bestdeg = deg; best = v; }
        }
        if (round > 0 && last <= maxlev) break;
        maxlev = last;
        start = best;
        reached = plateau__lm_bfs(d, start, member, ++d->counter);
    }
    maxlev = d->level[d->queue[reached - 1]];
    tA = ++d->counter;
    tB = ++d->counter;
    tS = ++d->counter;
    if (reached <= len / 2 || maxlev == 0) {
        /* a small component: it is one side, the rest the other, no separator */
        if (reached == len) return 0;
        for (i = 0; i < reached; i++) d->tag[d->queue[i]] = tA;
        for (i = lo; i < hi; i++)
            if (d->tag[d->ord[i]] == member) d->tag[d->ord[i]] = tB;
    } else {
        lm = 0;
        acc = 0;
        for (i = 0; i < reached; i++) {
            if (acc >= reached / 2) break;
            lm = (size_t)d->level[d->queue[i]];
            acc++;
        }
        if (lm == 0) lm = 1;
        for (i = 0; i < reached; i++) {
            plateau_index v = d->queue[i];
            size_t l = (size_t)d->level[v];
            d->tag[v] = l < lm ? tA : tB;
        }
        for (i = lo; i < hi; i++)
            if (d->tag[d->ord[i]] == member) d->tag[d->ord[i]] = tB;
        plateau__lm_nd_cover(d, lo, hi, tA, tB, tS);
        plateau__lm_nd_thin(d, lo, hi, tA, tB, tS);
    }
    plateau__lm_nd_arrange(d, lo, hi, tA, tB, na, nb);
    return *na + *nb < len || (*na > 0 && *nb > 0);
}

/* Splits ord[lo, hi) at the median coordinate across the longer side of
 * its bounding box; the separator is the smaller one-sided boundary of the
 * cut (the nodes of one side with a neighbour on the other).  Returns 0
 * when the points do not spread (then the graph split is used). */
static int plateau__lm_nd_geo_split(plateau__lm_nd *d, size_t lo, size_t hi, size_t *na, size_t *nb)
{
    size_t len = hi - lo, i, half = len / 2, tA, tB, tS;
    double lo0 = PLATEAU__LM_HUGE, hi0 = -PLATEAU__LM_HUGE;
    double lo1 = PLATEAU__LM_HUGE, hi1 = -PLATEAU__LM_HUGE;
    int axis;
    for (i = lo; i < hi; i++) {
        const double *q = d->xy + 2 * d->ord[i];
        if (q[0] < lo0) lo0 = q[0];
        if (q[0] > hi0) hi0 = q[0];
        if (q[1] < lo1) lo1 = q[1];
        if (q[1] > hi1) hi1 = q[1];
    }
    if (!(hi0 > lo0) && !(hi1 > lo1)) return 0;
    axis = (hi0 - lo0) >= (hi1 - lo1) ? 0 : 1;
    plateau__lm_select(d, lo, hi, half, axis);
    tA = ++d->counter;
    tB = ++d->counter;
    tS = ++d->counter;
    for (i = lo; i < hi; i++) d->tag[d->ord[i]] = i < lo + half ? tA : tB;
    plateau__lm_nd_cover(d, lo, hi, tA, tB, tS);
    plateau__lm_nd_thin(d, lo, hi, tA, tB, tS);
    plateau__lm_nd_arrange(d, lo, hi, tA, tB, na, nb);
    return 1;
}

/* Nested dissection of the whole graph into d->ord (elimination order).
 * segs: room for 2 (n + 1) range ends.  geometric: use d->xy. */
static void plateau__lm_nd_order(plateau__lm_nd *d, size_t leaf, int geometric, size_t *segs)
{
    size_t top = 0, i;
    for (i = 0; i < d->n; i++) d->ord[i] = (plateau_index)i;
    segs[top++] = 0;
    segs[top++] = d->n;
    /* every part pushed is smaller than the one popped: the loop ends */
    while (top > 0) {
        size_t hi = segs[--top], lo = segs[--top], na = 0, nb = 0;
        int ok;
        if (hi - lo <= leaf) continue;
        ok = geometric && plateau__lm_nd_geo_split(d, lo, hi, &na, &nb);
        if (!ok) ok = plateau__lm_nd_graph_split(d, lo, hi, &na, &nb);
        if (!ok || na == hi - lo || nb == hi - lo) continue;
        if (na > 1) { segs[top++] = lo; segs[top++] = lo + na; }
        if (nb > 1) { segs[top++] = lo + na; segs[top++] = lo + na + nb; }
    }
}

/* ---- Symbolic analysis ------------------------------------------------------ */

PLATEAU_LM_DEF void plateau_lm_sparse_symbolic_free(plateau_lm_sparse_symbolic *symbolic)
{
    plateau_allocator a;
    if (!symbolic) return;
    a = symbolic->alloc;
    plateau__free(&a, symbolic->base);
}

PLATEAU_LM_DEF plateau_lm_sparse_info plateau_lm_sparse_symbolic_info(const plateau_lm_sparse_symbolic *symbolic)
{
    plateau_lm_sparse_info z;
    if (symbolic) return symbolic->info;
    z.nodes = z.block = z.unknowns = z.pattern_blocks = z.factor_blocks = 0;
    z.supernodes = z.largest_front = z.factor_bytes_lu = z.factor_bytes_cholesky = 0;
    z.flops_cholesky = z.flops_lu = 0.0;
    return z;
}

PLATEAU_LM_DEF const plateau_index *plateau_lm_sparse_permutation(const plateau_lm_sparse_symbolic *symbolic)
{
    return symbolic ? symbolic->perm : NULL;
}

/* The state of one symbolic analysis: the input, the temporaries (one
 * block), the figures, and the object being built; each phase of
 * plateau_lm_sparse_analyze is a function of it. */
typedef struct plateau__lm_an {
    const plateau_lm_sparse_pattern *pattern;
    const double *xy;
    plateau_lm_sparse_options o;
    plateau_lm_sparse_symbolic *S;
    plateau__lm_nd nd;
    size_t n, b, nnz, sbytes, nsf, ns, leaf, rtot, ltot, utot, top, peak, fmax;
    int ok;
    void *tmp;
    size_t *tcnt, *tsrc, *stamp, *where, *tagv, *seenv, *segs, *cc, *sf, *spar, *snn, *snr,
        *rep, *newid, *childsum, *tposv, *sof;
    plateau_index *trow, *ordv, *queue, *level, *tmpv, *parent, *anc, *post, *head, *nxt, *stk,
        *flag, *pinv, *perm2, *par2;
    double *zeros, flops_c, flops_lu;
    unsigned char *alive;
} plateau__lm_an;

/* The temporaries of the analysis in one block (tmp); 0 on overflow
 * (ok = 0) or when the allocation fails (tmp = NULL). */
static int plateau__lm_an_temporaries(plateau__lm_an *A)
{
    size_t tbytes = 0;
    size_t i;
    unsigned char *c;
    /* one temporary block */
    A->ok &= plateau__lm_lay(&tbytes, A->n + 1, sizeof(size_t));      /* tcnt */
    A->ok &= plateau__lm_lay(&tbytes, A->nnz, sizeof(size_t));        /* tsrc */
    A->ok &= plateau__lm_lay(&tbytes, A->nnz, sizeof(size_t));        /* tposv */
    A->ok &= plateau__lm_lay(&tbytes, A->nnz, sizeof(plateau_index)); /* trow */
    for (i = 0; i < 14; i++) A->ok &= plateau__lm_lay(&tbytes, A->n, sizeof(size_t));
    A->ok &= plateau__lm_lay(&tbytes, 2 * (A->n + 1), sizeof(size_t)); /* segs */
    A->ok &= plateau__lm_lay(&tbytes, A->n + 1, sizeof(size_t));        /* sf */
    for (i = 0; i < 15; i++) A->ok &= plateau__lm_lay(&tbytes, A->n, sizeof(plateau_index));
    A->ok &= plateau__lm_lay(&tbytes, A->n, sizeof(double));
    A->ok &= plateau__lm_lay(&tbytes, A->n, 1);
    A->ok &= plateau__lm_lay(&tbytes, 16, 1);
    if (!A->ok) return 0;
    A->tmp = plateau__alloc(&A->o.allocator, tbytes);
    if (!A->tmp) return 0;
    c = plateau__lm_align16(A->tmp);
    A->tcnt = (size_t *)plateau__lm_take(&c, A->n + 1, sizeof(size_t));
    A->tsrc = (size_t *)plateau__lm_take(&c, A->nnz, sizeof(size_t));
    A->tposv = (size_t *)plateau__lm_take(&c, A->nnz, sizeof(size_t));
    A->trow = (plateau_index *)plateau__lm_take(&c, A->nnz, sizeof(plateau_index));
    A->stamp = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->where = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->tagv = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->seenv = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->cc = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->spar = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->snn = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->snr = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->rep = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->newid = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->childsum = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->sof = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->nd.pos = (size_t *)plateau__lm_take(&c, A->n, sizeof(size_t));
    (void)plateau__lm_take(&c, A->n, sizeof(size_t));
    A->segs = (size_t *)plateau__lm_take(&c, 2 * (A->n + 1), sizeof(size_t));
    A->sf = (size_t *)plateau__lm_take(&c, A->n + 1, sizeof(size_t));
    A->ordv = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->queue = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->level = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->tmpv = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->parent = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->anc = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->post = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->head = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->nxt = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->stk = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->flag = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->pinv = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->perm2 = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->par2 = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    (void)plateau__lm_take(&c, A->n, sizeof(plateau_index));
    A->zeros = (double *)plateau__lm_take(&c, A->n, sizeof(double));
    A->alive = (unsigned char *)plateau__lm_take(&c, A->n, 1);

    return 1;
}

/* The symbolic object in one allocation; 0 on overflow (ok = 0) or
 * when the allocation fails. */
static int plateau__lm_an_allocate(plateau__lm_an *A)
{
    size_t i;
    unsigned char *c;
    if (A->ok) {
        A->sbytes = 0;
        A->ok &= plateau__lm_lay(&A->sbytes, 1, sizeof(plateau_lm_sparse_symbolic));
        A->ok &= plateau__lm_lay(&A->sbytes, A->n + 1, sizeof(size_t));
        A->ok &= plateau__lm_lay(&A->sbytes, A->nnz, sizeof(plateau_index));
        A->ok &= plateau__lm_lay(&A->sbytes, A->nnz, sizeof(size_t));
        A->ok &= plateau__lm_lay(&A->sbytes, A->n, sizeof(plateau_index));
        A->ok &= plateau__lm_lay(&A->sbytes, A->n, sizeof(plateau_index));
        for (i = 0; i < 5; i++) A->ok &= plateau__lm_lay(&A->sbytes, A->ns + 1, sizeof(size_t));
        A->ok &= plateau__lm_lay(&A->sbytes, A->ns, sizeof(size_t));
        A->ok &= plateau__lm_lay(&A->sbytes, A->rtot, sizeof(plateau_index));
        A->ok &= plateau__lm_lay(&A->sbytes, 16, 1);
    }
    if (!A->ok) return 0;
    {
        void *mem = plateau__alloc(&A->o.allocator, A->sbytes);
        if (!mem) return 0;
        c = plateau__lm_align16(mem);
        A->S = (plateau_lm_sparse_symbolic *)plateau__lm_take(&c, 1, sizeof(plateau_lm_sparse_symbolic));
        /* the allocation's own address is recovered through alloc_base below */
        A->S->rs = (size_t *)plateau__lm_take(&c, A->n + 1, sizeof(size_t));
        A->S->cols = (plateau_index *)plateau__lm_take(&c, A->nnz, sizeof(plateau_index));
        A->S->tpos = (size_t *)plateau__lm_take(&c, A->nnz, sizeof(size_t));
        A->S->perm = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
        A->S->pinv = (plateau_index *)plateau__lm_take(&c, A->n, sizeof(plateau_index));
        A->S->sfirst = (size_t *)plateau__lm_take(&c, A->ns + 1, sizeof(size_t));
        A->S->srp = (size_t *)plateau__lm_take(&c, A->ns + 1, sizeof(size_t));
        A->S->scp = (size_t *)plateau__lm_take(&c, A->ns + 1, sizeof(size_t));
        A->S->lpos = (size_t *)plateau__lm_take(&c, A->ns + 1, sizeof(size_t));
        A->S->upos = (size_t *)plateau__lm_take(&c, A->ns + 1, sizeof(size_t));
        A->S->schild = (size_t *)plateau__lm_take(&c, A->ns, sizeof(size_t));
        A->S->srows = (plateau_index *)plateau__lm_take(&c, A->rtot, sizeof(plateau_index));
        A->S->base = mem;
    }
    return 1;
}

/* Structural symmetry (phase 1 of the analysis, after the pattern checks):
 * the transposed pattern; returns 0 for a bad pattern. */
static int plateau__lm_an_transpose(plateau__lm_an *A)
{
    size_t i, k, p, q;
    /* Structural symmetry: the transposed pattern (tcnt, tsrc, trow) must
     * hold, for every row k, exactly row k's columns; tposv links each block
     * (i, k) to (k, i).  Repeated columns and a missing diagonal are refused. */
    for (i = 0; i <= A->n; i++) A->tcnt[i] = 0;
    for (p = 0; p < A->nnz; p++) A->tcnt[A->pattern->cols[p] + 1]++;
    for (i = 0; i < A->n; i++) A->tcnt[i + 1] += A->tcnt[i];
    for (i = 0; i < A->n; i++) A->where[i] = A->tcnt[i];
    for (i = 0; i < A->n; i++)
        for (p = (size_t)A->pattern->row_start[i]; p < (size_t)A->pattern->row_start[i + 1]; p++) {
            size_t col = (size_t)A->pattern->cols[p];
            A->tsrc[A->where[col]] = p;
            A->trow[A->where[col]++] = (plateau_index)i;
        }
    for (i = 0; i < A->n; i++) A->stamp[i] = 0;
    for (k = 0; k < A->n; k++) {
        size_t r0 = (size_t)A->pattern->row_start[k], r1 = (size_t)A->pattern->row_start[k + 1];
        for (q = r0; q < r1; q++) {
            size_t col = (size_t)A->pattern->cols[q];
            if (A->stamp[col] == k + 1) return 0;
            A->stamp[col] = k + 1;
            A->where[col] = q;
        }
        if (A->stamp[k] != k + 1 || A->tcnt[k + 1] - A->tcnt[k] != r1 - r0) return 0;
        for (q = A->tcnt[k]; q < A->tcnt[k + 1]; q++) {
            size_t row = (size_t)A->trow[q];
            if (A->stamp[row] != k + 1) return 0;
            A->tposv[A->tsrc[q]] = A->where[row];
        }
    }

    return 1;
}

/* Phase 2: the fill-reducing order (nested dissection, or the natural one)
 * and its inverse. */
static void plateau__lm_an_order(plateau__lm_an *A)
{
    size_t i, k;
    /* Fill-reducing order (nested dissection), or the natural one. */
    {
        size_t *rsv = A->tcnt; /* row starts as size_t: reuse tcnt after the check */
        for (i = 0; i <= A->n; i++) rsv[i] = (size_t)A->pattern->row_start[i];
        A->nd.n = A->n;
        A->nd.rs = rsv;
        A->nd.cols = A->pattern->cols;
        A->nd.xy = A->xy;
        A->nd.ord = A->ordv;
        A->nd.queue = A->queue;
        A->nd.level = A->level;
        A->nd.tmp = A->tmpv;
        A->nd.tag = A->tagv;
        A->nd.seen = A->seenv;
        A->nd.counter = 0;
        for (i = 0; i < A->n; i++) A->tagv[i] = A->seenv[i] = 0;
        if (A->o.ordering == PLATEAU_LM_SPARSE_ORDER_NATURAL) {
            for (i = 0; i < A->n; i++) A->ordv[i] = (plateau_index)i;
        } else {
            int geo = A->xy != NULL && A->o.ordering != PLATEAU_LM_SPARSE_ORDER_GRAPH;
            plateau__lm_nd_order(&A->nd, A->leaf, geo, A->segs);
        }
    }
    for (k = 0; k < A->n; k++) A->pinv[A->ordv[k]] = (plateau_index)k;

}

/* Phase 3: the elimination tree. */
static void plateau__lm_an_etree(plateau__lm_an *A)
{
    size_t k, p;
    /* Elimination tree (Liu's algorithm with path compression: for each row
     * k, climb from every earlier neighbour to the root of its current
     * subtree and hang that root under k). */
    for (k = 0; k < A->n; k++) {
        size_t old = (size_t)A->ordv[k];
        A->parent[k] = A->anc[k] = -1;
        for (p = A->tcnt[old]; p < A->tcnt[old + 1]; p++) {
            plateau_index r = A->pinv[A->pattern->cols[p]];
            while (r != -1 && (size_t)r < k) {
                plateau_index up = A->anc[r];
                A->anc[r] = (plateau_index)k;
                if (up == -1) A->parent[r] = (plateau_index)k;
                r = up;
            }
        }
    }
}

/* Phase 4: the postorder of the tree, applied to the order and the tree. */
static void plateau__lm_an_postorder(plateau__lm_an *A)
{
    size_t j, k;
    /* Postorder of the tree (children in increasing order): subtrees become
     * contiguous ranges, the fill is unchanged. */
    for (k = 0; k < A->n; k++) A->head[k] = -1;
    for (k = A->n; k-- > 0;)
        if (A->parent[k] != -1) {
            A->nxt[k] = A->head[A->parent[k]];
            A->head[A->parent[k]] = (plateau_index)k;
        }
    j = 0;
    for (k = 0; k < A->n; k++) {
        size_t sp = 0;
        if (A->parent[k] != -1) continue;
        A->stk[sp++] = (plateau_index)k;
        while (sp > 0) {
            plateau_index t = A->stk[sp - 1], ch = A->head[t];
            if (ch == -1) {
                sp--;
                A->post[j++] = t;
            } else {
                A->head[t] = A->nxt[ch];
                A->stk[sp++] = ch;
            }
        }
    }
    PLATEAU_ASSERT(j == A->n);
    for (k = 0; k < A->n; k++) A->anc[A->post[k]] = (plateau_index)k; /* anc: inverse of post */
    for (k = 0; k < A->n; k++) {
        A->perm2[k] = A->ordv[A->post[k]];
        A->par2[k] = A->parent[A->post[k]] == -1 ? -1 : A->anc[A->parent[A->post[k]]];
    }
    for (k = 0; k < A->n; k++) {
        A->ordv[k] = A->perm2[k];
        A->parent[k] = A->par2[k];
        A->pinv[A->ordv[k]] = (plateau_index)k;
    }

}

/* Phase 5: the column counts of L. */
static void plateau__lm_an_colcounts(plateau__lm_an *A)
{
    size_t k, p;
    /* Column counts of L (in blocks, diagonal included) by row subtrees: row
     * k of L holds the nodes on the tree paths from k's earlier neighbours
     * up to k. */
    for (k = 0; k < A->n; k++) {
        size_t old = (size_t)A->ordv[k];
        A->flag[k] = (plateau_index)k;
        A->cc[k] = 1;
        for (p = A->tcnt[old]; p < A->tcnt[old + 1]; p++) {
            plateau_index r = A->pinv[A->pattern->cols[p]];
            if ((size_t)r >= k) continue;
            while (A->flag[r] != (plateau_index)k) {
                A->cc[r]++;
                A->flag[r] = (plateau_index)k;
                r = A->parent[r];
            }
        }
    }

}

/* Phases 6 and 7: fundamental supernodes and their relaxed amalgamation. */
static void plateau__lm_an_supernodes(plateau__lm_an *A)
{
    size_t i, k;
    /* Fundamental supernodes: j joins j - 1 when j is its parent, its only
     * child, and column j - 1 is column j plus the diagonal. */
    for (k = 0; k < A->n; k++) A->head[k] = 0; /* child counts */
    for (k = 0; k < A->n; k++)
        if (A->parent[k] != -1) A->head[A->parent[k]]++;
    A->nsf = 0;
    for (k = 0; k < A->n; k++) {
        if (k == 0 || !(A->parent[k - 1] == (plateau_index)k && A->cc[k - 1] == A->cc[k] + 1 && A->head[k] == 1))
            A->sf[A->nsf++] = k;
        A->sof[k] = A->nsf - 1;
    }
    A->sf[A->nsf] = A->n;
    for (i = 0; i < A->nsf; i++) {
        size_t last = A->sf[i + 1] - 1;
        A->snn[i] = A->sf[i + 1] - A->sf[i];
        A->snr[i] = A->cc[last] - 1;
        A->spar[i] = A->parent[last] == -1 ? (size_t)-1 : A->sof[A->parent[last]];
        A->zeros[i] = 0.0;
        A->alive[i] = 1;
    }
    /* Relaxed amalgamation: a supernode whose last node precedes its
     * parent's first joins the parent when the merged block (in nodes) is
     * small or adds few explicit zeros (the rows of the parent, minus its
     * own, in its columns). */
    for (i = 0; i < A->nsf; i++) {
        size_t pp = A->spar[i], nnm;
        double tot, z;
        if (pp == (size_t)-1 || A->sf[i] + A->snn[i] != A->sf[pp]) continue;
        nnm = A->snn[i] + A->snn[pp];
        tot = 0.5 * (double)nnm * (double)(nnm + 1) + (double)nnm * (double)A->snr[pp];
        z = A->zeros[i] + A->zeros[pp] + (double)A->snn[i] * ((double)A->snn[pp] + (double)A->snr[pp] - (double)A->snr[i]);
        if (nnm <= 4 || (nnm <= 16 && z <= 0.8 * tot) || (nnm <= 48 && z <= 0.1 * tot) ||
            z <= 0.05 * tot) {
            A->alive[i] = 0;
            A->sf[pp] = A->sf[i];
            A->snn[pp] = nnm;
            A->zeros[pp] = z;
        }
    }
    A->ns = 0;
    for (i = A->nsf; i-- > 0;) A->rep[i] = A->alive[i] ? i : A->rep[A->spar[i]];
    for (i = 0; i < A->nsf; i++)
        if (A->alive[i]) A->newid[i] = A->ns++;

}

/* Phase 8: the sizes of the factor and a simulation of the multifrontal
 * stack (its peak), with the flop counts. */
static void plateau__lm_an_sizes(plateau__lm_an *A)
{
    size_t i;
    /* Sizes: per supernode nc = b nodes columns, nr = b rows below, front
     * f = nc + nr; L holds f nc, U nc nr, the update matrix nr^2.  The stack
     * simulation follows the postorder: a supernode pops its children's
     * updates (the top of the stack) and pushes its own. */
    A->rtot = A->ltot = A->utot = 0;
    A->top = A->peak = A->fmax = 0;
    for (i = 0; i < A->nsf; i++) A->childsum[i] = 0;
    for (i = 0; i < A->nsf; i++) {
        size_t ncs, nrs, f, upd;
        double dk;
        if (!A->alive[i]) continue;
        ncs = plateau__lm_mul(A->b, A->snn[i], &A->ok);
        nrs = plateau__lm_mul(A->b, A->snr[i], &A->ok);
        f = plateau__lm_sum(ncs, nrs, &A->ok);
        A->rtot = plateau__lm_sum(A->rtot, A->snr[i], &A->ok);
        A->ltot = plateau__lm_sum(A->ltot, plateau__lm_mul(f, ncs, &A->ok), &A->ok);
        A->utot = plateau__lm_sum(A->utot, plateau__lm_mul(ncs, nrs, &A->ok), &A->ok);
        upd = plateau__lm_mul(nrs, nrs, &A->ok);
        (void)plateau__lm_mul(f, f, &A->ok);
        if (!A->ok) break;
        if (f > A->fmax) A->fmax = f;
        A->top -= A->childsum[A->newid[i]];
        A->top += upd;
        if (A->top > A->peak) A->peak = A->top;
        if (A->spar[i] != (size_t)-1) A->childsum[A->newid[A->rep[A->spar[i]]]] += upd;
        for (dk = 0.0; dk < (double)ncs; dk += 1.0) {
            double cnt = (double)f - dk - 1.0;
            A->flops_c += cnt + cnt * (cnt + 1.0);
            A->flops_lu += cnt + 2.0 * cnt * cnt;
        }
    }
}

/* Phase 9: the symbolic object's tables: the pattern, the order, the
 * supernodes in the compacted numbering and their children. */
static void plateau__lm_an_tables(plateau__lm_an *A)
{
    size_t i, j, k, p;
    A->S->alloc = A->o.allocator;
    A->S->n = A->n;
    A->S->b = A->b;
    A->S->nnz = A->nnz;
    A->S->ns = A->ns;
    A->S->pivot_tol = A->o.pivot_tol != 0.0 ? A->o.pivot_tol : PLATEAU_LM_SPARSE_DEFAULT_PIVOT_TOL;
    A->S->cancel = A->o.cancel;
    A->S->cancel_user = A->o.cancel_user;
    for (i = 0; i <= A->n; i++) A->S->rs[i] = A->tcnt[i];
    for (p = 0; p < A->nnz; p++) {
        A->S->cols[p] = A->pattern->cols[p];
        A->S->tpos[p] = A->tposv[p];
    }
    for (k = 0; k < A->n; k++) {
        A->S->perm[k] = A->ordv[k];
        A->S->pinv[k] = A->pinv[k];
    }
    /* supernode tables in the compacted numbering */
    j = 0;
    A->S->lpos[0] = A->S->upos[0] = A->S->srp[0] = 0;
    for (i = 0; i < A->nsf; i++) {
        size_t t, ncs, f;
        if (!A->alive[i]) continue;
        t = A->newid[i];
        A->S->sfirst[t] = A->sf[i];
        A->S->srp[t + 1] = A->S->srp[t] + A->snr[i];
        ncs = A->b * A->snn[i];
        f = ncs + A->b * A->snr[i];
        A->S->lpos[t + 1] = A->S->lpos[t] + f * ncs;
        A->S->upos[t + 1] = A->S->upos[t] + ncs * A->b * A->snr[i];
        A->rep[t] = A->spar[i] == (size_t)-1 ? (size_t)-1 : A->newid[A->rep[A->spar[i]]]; /* rep: parent now */
        j++;
    }
    A->S->sfirst[A->ns] = A->n;
    /* children lists, ascending */
    for (i = 0; i <= A->ns; i++) A->S->scp[i] = 0;
    for (i = 0; i < A->ns; i++)
        if (A->rep[i] != (size_t)-1) A->S->scp[A->rep[i] + 1]++;
    for (i = 0; i < A->ns; i++) A->S->scp[i + 1] += A->S->scp[i];
    for (i = 0; i < A->ns; i++) A->where[i] = A->S->scp[i];
    for (i = 0; i < A->ns; i++)
        if (A->rep[i] != (size_t)-1) A->S->schild[A->where[A->rep[i]]++] = i;
}

/* Phase 10: the row structure of each supernode, and the figures. */
static void plateau__lm_an_rows(plateau__lm_an *A)
{
    size_t i, k, p, q;
    /* Row structure of each supernode: the union of its nodes' later
     * neighbours and of its children's rows, beyond its last node. */
    for (i = 0; i < A->n; i++) A->stamp[i] = 0;
    for (i = 0; i < A->ns; i++) {
        size_t last = A->S->sfirst[i + 1] - 1, cnt = 0, mark = i + 1;
        plateau_index *rows = A->S->srows + A->S->srp[i];
        for (k = A->S->sfirst[i]; k <= last; k++) {
            size_t old = (size_t)A->S->perm[k];
            for (p = A->S->rs[old]; p < A->S->rs[old + 1]; p++) {
                size_t r = (size_t)A->S->pinv[A->S->cols[p]];
                if (r > last && A->stamp[r] != mark) {
                    A->stamp[r] = mark;
                    rows[cnt++] = (plateau_index)r;
                }
            }
        }
        for (q = A->S->scp[i]; q < A->S->scp[i + 1]; q++) {
            size_t ch = A->S->schild[q], e;
            for (e = A->S->srp[ch]; e < A->S->srp[ch + 1]; e++) {
                size_t r = (size_t)A->S->srows[e];
                if (r > last && A->stamp[r] != mark) {
                    A->stamp[r] = mark;
                    rows[cnt++] = (plateau_index)r;
                }
            }
        }
        PLATEAU_ASSERT(cnt == A->S->srp[i + 1] - A->S->srp[i]);
        plateau__lm_sort_index(rows, cnt);
    }
    A->S->stack_peak = A->peak;
    A->S->front_max = A->fmax;
    A->S->info.nodes = A->n;
    A->S->info.block = A->b;
    A->S->info.unknowns = A->n * A->b;
    A->S->info.pattern_blocks = A->nnz;
    A->S->info.factor_blocks = 0;
    for (k = 0; k < A->n; k++) A->S->info.factor_blocks += A->cc[k];
    A->S->info.supernodes = A->ns;
    A->S->info.largest_front = A->fmax;
    A->S->info.flops_cholesky = A->flops_c;
    A->S->info.flops_lu = A->flops_lu;
    A->S->info.factor_bytes_lu = 0;
    A->S->info.factor_bytes_cholesky = 0;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_analyze(const plateau_lm_sparse_pattern *pattern,
                                                           const double *xy,
                                                           const plateau_lm_sparse_options *options,
                                                           plateau_lm_sparse_symbolic **symbolic)
{
    plateau__lm_an an, *A = &an;
    size_t i, p;

    if (symbolic) *symbolic = NULL;
    if (!pattern || !symbolic || !pattern->row_start || !pattern->cols)
        return PLATEAU_LM_ERR_ARGUMENT;
    A->n = pattern->nodes;
    if (A->n == 0) return PLATEAU_LM_ERR_EMPTY;
    if (options) {
        A->o = *options;
    } else {
        A->o.ordering = 0;
        A->o.leaf_nodes = 0;
        A->o.pivot_tol = 0.0;
        A->o.allocator.alloc_fn = NULL;
        A->o.allocator.free_fn = NULL;
        A->o.allocator.user_data = NULL;
        A->o.cancel = NULL;
        A->o.cancel_user = NULL;
    }
    if (pattern->block < 1 || pattern->block > 4 || A->o.ordering < 0 || A->o.ordering > 3 ||
        (A->o.ordering == PLATEAU_LM_SPARSE_ORDER_GEOMETRIC && !xy) ||
        !plateau__lm_nonneg(A->o.pivot_tol) || !plateau__allocator_valid(&A->o.allocator))
        return PLATEAU_LM_ERR_ARGUMENT;
    if (xy && A->o.ordering != PLATEAU_LM_SPARSE_ORDER_GRAPH &&
        A->o.ordering != PLATEAU_LM_SPARSE_ORDER_NATURAL) {
        if (A->n > (size_t)-1 / 2) return PLATEAU_LM_ERR_OVERFLOW;
        if (!plateau__lm_all_finite(xy, 2 * A->n)) return PLATEAU_LM_ERR_ARGUMENT;
    }
    A->b = (size_t)pattern->block;
    /* every unknown's front position fits in a plateau_index */
    if (A->n >= (size_t)PLATEAU_INDEX_MAX / A->b) return PLATEAU_LM_ERR_OVERFLOW;
    A->leaf = A->o.leaf_nodes ? A->o.leaf_nodes : PLATEAU_LM_SPARSE_DEFAULT_LEAF;
    /* the pattern: offsets non-decreasing from 0, columns in range */
    if (pattern->row_start[0] != 0) return PLATEAU_LM_ERR_BAD_PATTERN;
    for (i = 0; i < A->n; i++)
        if (pattern->row_start[i + 1] < pattern->row_start[i]) return PLATEAU_LM_ERR_BAD_PATTERN;
    A->nnz = (size_t)pattern->row_start[A->n];
    for (p = 0; p < A->nnz; p++)
        if (pattern->cols[p] < 0 || (size_t)pattern->cols[p] >= A->n) return PLATEAU_LM_ERR_BAD_PATTERN;

    A->pattern = pattern;
    A->xy = xy;
    A->ok = 1;
    A->tmp = NULL;
    A->S = NULL;
    A->sbytes = 0;
    A->flops_c = A->flops_lu = 0.0;
    if (!plateau__lm_an_temporaries(A)) return A->ok ? PLATEAU_LM_ERR_OUT_OF_MEMORY : PLATEAU_LM_ERR_OVERFLOW;
    if (!plateau__lm_an_transpose(A)) {
        plateau__free(&A->o.allocator, A->tmp);
        return PLATEAU_LM_ERR_BAD_PATTERN;
    }
    plateau__lm_an_order(A);
    plateau__lm_an_etree(A);
    plateau__lm_an_postorder(A);
    plateau__lm_an_colcounts(A);
    plateau__lm_an_supernodes(A);
    plateau__lm_an_sizes(A);
    if (!plateau__lm_an_allocate(A)) {
        plateau__free(&A->o.allocator, A->tmp);
        return A->ok ? PLATEAU_LM_ERR_OUT_OF_MEMORY : PLATEAU_LM_ERR_OVERFLOW;
    }
    plateau__lm_an_tables(A);
    plateau__lm_an_rows(A);
    plateau__free(&A->o.allocator, A->tmp);
    A->S->info.factor_bytes_lu = plateau_lm_sparse_factor_size(A->S, PLATEAU_LM_SPARSE_LU);
    A->S->info.factor_bytes_cholesky = plateau_lm_sparse_factor_size(A->S, PLATEAU_LM_SPARSE_CHOLESKY);
    *symbolic = A->S;
    return PLATEAU_LM_OK;
}

/* ---- Dense kernels on frontal matrices (column-major, leading dimension ld) */

/* C(0:mr, 0:nr) -= A B for one 4 x 4 register tile: a and b are packed
 * panels (4 values per k), C is column-major with leading dimension ldc. */
static void plateau__lm_tile(size_t kc, const double *a, const double *b, double *C, size_t ldc,
                             size_t mr, size_t nr)
{
    double c00 = 0, c10 = 0, c20 = 0, c30 = 0, c01 = 0, c11 = 0, c21 = 0, c31 = 0;
    double c02 = 0, c12 = 0, c22 = 0, c32 = 0, c03 = 0, c13 = 0, c23 = 0, c33 = 0;
    size_t p, i, j;
    for (p = 0; p < kc; p++) {
        double a0 = a[4 * p], a1 = a[4 * p + 1], a2 = a[4 * p + 2], a3 = a[4 * p + 3];
        double b0 = b[4 * p], b1 = b[4 * p + 1], b2 = b[4 * p + 2], b3 = b[4 * p + 3];
        c00 += a0 * b0; c10 += a1 * b0; c20 += a2 * b0; c30 += a3 * b0;
        c01 += a0 * b1; c11 += a1 * b1; c21 += a2 * b1; c31 += a3 * b1;
        c02 += a0 * b2; c12 += a1 * b2; c22 += a2 * b2; c32 += a3 * b2;
        c03 += a0 * b3; c13 += a1 * b3; c23 += a2 * b3; c33 += a3 * b3;
    }
    if (mr == 4 && nr == 4) {
        double *q = C;
        q[0] -= c00; q[1] -= c10; q[2] -= c20; q[3] -= c30; q += ldc;
        q[0] -= c01; q[1] -= c11; q[2] -= c21; q[3] -= c31; q += ldc;
        q[0] -= c02; q[1] -= c12; q[2] -= c22; q[3] -= c32; q += ldc;
        q[0] -= c03; q[1] -= c13; q[2] -= c23; q[3] -= c33;
    } else {
        double t[16];
        t[0] = c00; t[1] = c10; t[2] = c20; t[3] = c30;
        t[4] = c01; t[5] = c11; t[6] = c21; t[7] = c31;
        t[8] = c02; t[9] = c12; t[10] = c22; t[11] = c32;
        t[12] = c03; t[13] = c13; t[14] = c23; t[15] = c33;
        for (j = 0; j < nr; j++)
            for (i = 0; i < mr; i++) C[j * ldc + i] -= t[4 * j + i];
    }
}

/* C -= A B with C m x n (ldc), A m x k (lda), B(p, j) = B[p bp + j bj]:
 * B is packed in 4-column panels of KC rows, A in 4-row panels of MC x KC
 * (Goto's blocking), and 4 x 4 tiles accumulate in registers. */
static void plateau__lm_gemm(size_t m, size_t n, size_t k, const double *A, size_t lda,
                             const double *B, size_t bp, size_t bj, double *C, size_t ldc,
                             double *pa, double *pb)
{
    size_t j0, p0, i0, jj, ii, p, r;
    for (j0 = 0; j0 < n; j0 += PLATEAU__LM_NC) {
        size_t ncb = n - j0 < PLATEAU__LM_NC ? n - j0 : PLATEAU__LM_NC;
        for (p0 = 0; p0 < k; p0 += PLATEAU__LM_KC) {
            size_t kc = k - p0 < PLATEAU__LM_KC ? k - p0 : PLATEAU__LM_KC;
            for (jj = 0; jj < ncb; jj += 4) {
                double *dst = pb + jj * kc;
                for (p = 0; p < kc; p++)
                    for (r = 0; r < 4; r++)
                        dst[4 * p + r] = jj + r < ncb ? B[(p0 + p) * bp + (j0 + jj + r) * bj] : 0.0;
            }
            for (i0 = 0; i0 < m; i0 += PLATEAU__LM_MC) {
                size_t mc = m - i0 < PLATEAU__LM_MC ? m - i0 : PLATEAU__LM_MC;
                for (ii = 0; ii < mc; ii += 4) {
                    double *dst = pa + ii * kc;
                    for (p = 0; p < kc; p++) {
                        const double *src = A + (p0 + p) * lda + i0 + ii;
                        for (r = 0; r < 4; r++) dst[4 * p + r] = ii + r < mc ? src[r] : 0.0;
                    }
                }
                for (jj = 0; jj < ncb; jj += 4)
                    for (ii = 0; ii < mc; ii += 4)
                        plateau__lm_tile(kc, pa + ii * kc, pb + jj * kc,
                                         C + (j0 + jj) * ldc + i0 + ii, ldc,
                                         mc - ii < 4 ? mc - ii : 4, ncb - jj < 4 ? ncb - jj : 4);
            }
        }
    }
}

/* y -= x0 u0 + x1 u1 + x2 u2 + x3 u3 over n entries (a rank-4 update of
 * one column: y is read and written once for four columns of x). */
static void plateau__lm_axpy4(size_t n, double *y, const double *x0, const double *x1,
                              const double *x2, const double *x3, double u0, double u1,
                              double u2, double u3)
{
    size_t i;
    for (i = 0; i + 2 <= n; i += 2) {
        double y0 = y[i], y1 = y[i + 1];
        y0 -= x0[i] * u0 + x1[i] * u1 + x2[i] * u2 + x3[i] * u3;
        y1 -= x0[i + 1] * u0 + x1[i + 1] * u1 + x2[i + 1] * u2 + x3[i + 1] * u3;
        y[i] = y0;
        y[i + 1] = y1;
    }
    if (i < n) y[i] -= x0[i] * u0 + x1[i] * u1 + x2[i] * u2 + x3[i] * u3;
}

/* Partial LU without pivoting of the f x f front F on its first nc columns
 * (blocked Doolittle: left-looking within a panel of NB columns, right-
 * looking between panels): afterwards F = [L11\U11, U12; L21, S] with
 * S = F22 - L21 U12 the Schur complement.  Returns 0 (and the column in
 * *bad) when a pivot has |u_kk| < tol or is not finite. */
static int plateau__lm_lu_partial(double *F, size_t f, size_t nc, double tol, size_t *bad,
                                  double *pa, double *pb)
{
    size_t k0, k, i, j;
    for (k0 = 0; k0 < nc; k0 += PLATEAU__LM_NB) {
        size_t kw = nc - k0 < PLATEAU__LM_NB ? nc - k0 : PLATEAU__LM_NB, ke = k0 + kw;
        /* the panel: columns k0..ke-1, all rows below the diagonal; column
         * j takes the updates of the panel's earlier columns (rows above j:
         * the unit lower triangular solve giving U; rows from j on: four
         * columns at a time), then its pivot */
        for (j = k0; j < ke; j++) {
            double *cj = F + j * f, piv, inv;
            for (k = k0; k < j; k++) {
                const double *ck = F + k * f;
                double u = cj[k];
                if (u != 0.0)
                    for (i = k + 1; i < j; i++) cj[i] -= ck[i] * u;
            }
            for (k = k0; k + 4 <= j; k += 4) {
                const double *ck = F + k * f;
                plateau__lm_axpy4(f - j, cj + j, ck + j, ck + f + j, ck + 2 * f + j, ck + 3 * f + j,
                                  cj[k], cj[k + 1], cj[k + 2], cj[k + 3]);
            }
            for (; k < j; k++) {
                const double *ck = F + k * f;
                double u = cj[k];
                if (u != 0.0)
                    for (i = j; i < f; i++) cj[i] -= ck[i] * u;
            }
            piv = cj[j];
            if (!(PLATEAU_FABS(piv) >= tol) || !plateau__lm_finite(piv)) {
                *bad = j;
                return 0;
            }
            inv = 1.0 / piv;
            for (i = j + 1; i < f; i++) cj[i] *= inv;
        }
        if (ke == f) break;
        /* U12 of the panel rows: L11^-1 (unit lower) times the columns right
         * of it, four columns at a time (one load of L11 for four) */
        for (j = ke; j < f; j += 4) {
            size_t jw = f - j < 4 ? f - j : 4, t;
            if (jw < 4) {
                for (t = 0; t < jw; t++) {
                    double *cj = F + (j + t) * f;
                    for (k = k0; k < ke; k++) {
                        const double *ck = F + k * f;
                        double u = cj[k];
                        if (u != 0.0)
                            for (i = k + 1; i < ke; i++) cj[i] -= ck[i] * u;
                    }
                }
                break;
            }
            {
                double *c0 = F + j * f, *c1 = c0 + f, *c2 = c1 + f, *c3 = c2 + f;
                for (k = k0; k < ke; k++) {
                    const double *ck = F + k * f;
                    double u0 = c0[k], u1 = c1[k], u2 = c2[k], u3 = c3[k];
                    for (i = k + 1; i < ke; i++) {
                        double l = ck[i];
                        c0[i] -= l * u0;
                        c1[i] -= l * u1;
                        c2[i] -= l * u2;
                        c3[i] -= l * u3;
                    }
                }
            }
        }
        /* trailing update F22 -= L21 U12 */
        plateau__lm_gemm(f - ke, f - ke, kw, F + k0 * f + ke, f, F + ke * f + k0, 1, f,
                         F + ke * f + ke, f, pa, pb);
    }
    return 1;
}

/* Partial Cholesky of the lower triangle of the f x f front F on its first
 * nc columns (blocked: left-looking within a panel of NB columns, four
 * columns at a time, right-looking between panels): F = [L11, -; L21, S],
 * S = F22 - L21 L21^T (lower triangle; the upper one is scratch).  Returns
 * 0 (and the column in *bad) when a pivot is not positive or not finite. */
static int plateau__lm_chol_partial(double *F, size_t f, size_t nc, size_t *bad, double *pa,
                                    double *pb)
{
    size_t k0, k, i, j, j0;
    for (k0 = 0; k0 < nc; k0 += PLATEAU__LM_NB) {
        size_t kw = nc - k0 < PLATEAU__LM_NB ? nc - k0 : PLATEAU__LM_NB, ke = k0 + kw;
        for (j = k0; j < ke; j++) {
            double *cj = F + j * f, d, l, inv;
            for (k = k0; k + 4 <= j; k += 4) {
                const double *ck = F + k * f;
                plateau__lm_axpy4(f - j, cj + j, ck + j, ck + f + j, ck + 2 * f + j, ck + 3 * f + j,
                                  ck[j], ck[f + j], ck[2 * f + j], ck[3 * f + j]);
            }
            for (; k < j; k++) {
                const double *ck = F + k * f;
                double ljk = ck[j];
                if (ljk != 0.0)
                    for (i = j; i < f; i++) cj[i] -= ck[i] * ljk;
            }
            d = cj[j];
            if (!(d > 0.0) || !plateau__lm_finite(d)) {
                *bad = j;
                return 0;
            }
            l = PLATEAU_SQRT(d);
            cj[j] = l;
            inv = 1.0 / l;
            for (i = j + 1; i < f; i++) cj[i] *= inv;
        }
        /* trailing lower triangle, in column blocks: F22 -= L21 L21^T */
        for (j0 = ke; j0 < f; j0 += 2 * PLATEAU__LM_NB) {
            size_t jw = f - j0 < 2 * PLATEAU__LM_NB ? f - j0 : 2 * PLATEAU__LM_NB;
            plateau__lm_gemm(f - j0, jw, kw, F + k0 * f + j0, f, F + k0 * f + j0, f, 1,
                             F + j0 * f + j0, f, pa, pb);
        }
    }
    return 1;
}

/* Partial L D L^T of the lower triangle of the f x f front F on its first
 * nc columns, blocked as plateau__lm_chol_partial: column j of L21 is
 * first formed unscaled (l_ij d_j), copied into row j of the upper half
 * (which the Cholesky leaves as scratch) and then divided by d_j, so the
 * trailing update F22 -= L21 (D L21^T) reads D L21^T from the upper half.
 * Afterwards F = [L11 with D on its diagonal, -; L21, S].  Returns 0 (and
 * the column in *bad) when |d_j| < tol or d_j is not finite. */
static int plateau__lm_ldlt_partial(double *F, size_t f, size_t nc, double tol, size_t *bad,
                                    double *pa, double *pb)
{
    size_t k0, k, i, j, j0;
    for (k0 = 0; k0 < nc; k0 += PLATEAU__LM_NB) {
        size_t kw = nc - k0 < PLATEAU__LM_NB ? nc - k0 : PLATEAU__LM_NB, ke = k0 + kw;
        for (j = k0; j < ke; j++) {
            double *cj = F + j * f, d, inv;
            /* column j -= sum over the panel's earlier k of L(:, k) (l_jk d_k),
             * l_jk d_k being entry (k, j) of the upper half */
            for (k = k0; k + 4 <= j; k += 4) {
                const double *ck = F + k * f;
                plateau__lm_axpy4(f - j, cj + j, ck + j, ck + f + j, ck + 2 * f + j, ck + 3 * f + j,
                                  cj[k], cj[k + 1], cj[k + 2], cj[k + 3]);
            }
            for (; k < j; k++) {
                const double *ck = F + k * f;
                double u = cj[k];
                if (u != 0.0)
                    for (i = j; i < f; i++) cj[i] -= ck[i] * u;
            }
            d = cj[j];
            if (!(PLATEAU_FABS(d) >= tol) || !plateau__lm_finite(d)) {
                *bad = j;
                return 0;
            }
            inv = 1.0 / d;
            for (i = j + 1; i < f; i++) {
                F[i * f + j] = cj[i]; /* (j, i): l_ij d_j */
                cj[i] *= inv;
            }
        }
        /* trailing lower triangle, in column blocks: F22 -= L21 (D L21^T) */
        for (j0 = ke; j0 < f; j0 += 2 * PLATEAU__LM_NB) {
            size_t jw = f - j0 < 2 * PLATEAU__LM_NB ? f - j0 : 2 * PLATEAU__LM_NB;
            plateau__lm_gemm(f - j0, jw, kw, F + k0 * f + j0, f, F + j0 * f + k0, 1, f,
                             F + j0 * f + j0, f, pa, pb);
        }
    }
    return 1;
}

/* Inverse of the b x b row-major block a + shift I by Gauss-Jordan with
 * partial pivoting.  Returns 0 when a pivot is below 16 eps ||a||_inf or
 * anything is not finite. */
static int plateau__lm_block_inverse(const double *a, size_t b, double shift, double *inv)
{
    double m[16], norm = 0.0;
    size_t i, j, col;
    for (i = 0; i < b; i++) {
        double rs = 0.0;
        for (j = 0; j < b; j++) {
            m[i * b + j] = a[i * b + j] + (i == j ? shift : 0.0);
            inv[i * b + j] = i == j ? 1.0 : 0.0;
            rs += PLATEAU_FABS(m[i * b + j]);
        }
        if (!(rs <= norm)) norm = rs; /* NaN propagates into norm */
    }
    if (!plateau__lm_finite(norm) || norm == 0.0) return 0;
    for (col = 0; col < b; col++) {
        size_t pr = col;
        double piv, t;
        for (i = col + 1; i < b; i++)
            if (PLATEAU_FABS(m[i * b + col]) > PLATEAU_FABS(m[pr * b + col])) pr = i;
        if (!(PLATEAU_FABS(m[pr * b + col]) > 16.0 * DBL_EPSILON * norm)) return 0;
        if (pr != col)
            for (j = 0; j < b; j++) {
                t = m[pr * b + j]; m[pr * b + j] = m[col * b + j]; m[col * b + j] = t;
                t = inv[pr * b + j]; inv[pr * b + j] = inv[col * b + j]; inv[col * b + j] = t;
            }
        piv = 1.0 / m[col * b + col];
        for (j = 0; j < b; j++) {
            m[col * b + j] *= piv;
            inv[col * b + j] *= piv;
        }
        for (i = 0; i < b; i++) {
            double fct = m[i * b + col];
            if (i == col || fct == 0.0) continue;
            for (j = 0; j < b; j++) {
                m[i * b + j] -= fct * m[col * b + j];
                inv[i * b + j] -= fct * inv[col * b + j];
            }
        }
    }
    return plateau__lm_all_finite(inv, b * b);
}

/* ---- Factor objects --------------------------------------------------------- */

/* Lays out (base != NULL: carves) a factor object; returns the bytes needed
 * without the alignment slack, 0 on overflow. */
static size_t plateau__lm_factor_layout(const plateau_lm_sparse_symbolic *S, int kind,
                                        plateau_lm_sparse_factor *F, unsigned char *base)
{
    size_t total = 0, N = S->n * S->b, ff;
    int ok = 1, lu = kind == PLATEAU_LM_SPARSE_LU;
    size_t cnt[9];
    size_t i;
    ff = plateau__lm_mul(S->front_max, S->front_max, &ok);
    cnt[0] = S->lpos[S->ns];
    cnt[1] = lu ? S->upos[S->ns] : 0;
    cnt[2] = lu ? plateau__lm_mul(S->n, S->b * S->b, &ok) : 0;
    cnt[3] = S->stack_peak;
    cnt[4] = ff;
    cnt[5] = N;
    {   /* the packed panels of the matrix product, no larger than the largest front needs */
        size_t fm = S->front_max, kc = fm < PLATEAU__LM_KC ? fm : PLATEAU__LM_KC;
        size_t mc = fm < PLATEAU__LM_MC ? fm : PLATEAU__LM_MC, nc = fm < PLATEAU__LM_NC ? fm : PLATEAU__LM_NC;
        cnt[6] = kc * ((mc + 3) & ~(size_t)3);
        cnt[7] = kc * ((nc + 3) & ~(size_t)3);
    }
    if (!ok) return 0;
    ok &= plateau__lm_lay(&total, 1, sizeof(plateau_lm_sparse_factor));
    for (i = 0; i < 8; i++) ok &= plateau__lm_lay(&total, cnt[i], sizeof(double));
    ok &= plateau__lm_lay(&total, N, sizeof(plateau_index));
    ok &= plateau__lm_lay(&total, S->front_max, sizeof(plateau_index));
    if (!ok) return 0;
    if (F && base) {
        unsigned char *c = base;
        (void)plateau__lm_take(&c, 1, sizeof(plateau_lm_sparse_factor));
        F->L = (double *)plateau__lm_take(&c, cnt[0], sizeof(double));
        F->U = (double *)plateau__lm_take(&c, cnt[1], sizeof(double));
        F->dinv = (double *)plateau__lm_take(&c, cnt[2], sizeof(double));
        F->stack = (double *)plateau__lm_take(&c, cnt[3], sizeof(double));
        F->front = (double *)plateau__lm_take(&c, cnt[4], sizeof(double));
        F->y = (double *)plateau__lm_take(&c, cnt[5], sizeof(double));
        F->pa = (double *)plateau__lm_take(&c, cnt[6], sizeof(double));
        F->pb = (double *)plateau__lm_take(&c, cnt[7], sizeof(double));
        F->map = (plateau_index *)plateau__lm_take(&c, N, sizeof(plateau_index));
        F->rel = (plateau_index *)plateau__lm_take(&c, S->front_max, sizeof(plateau_index));
    }
    return total;
}

PLATEAU_LM_DEF size_t plateau_lm_sparse_factor_size(const plateau_lm_sparse_symbolic *symbolic,
                                                    int kind)
{
    size_t t;
    if (!symbolic || (kind != PLATEAU_LM_SPARSE_LU && kind != PLATEAU_LM_SPARSE_CHOLESKY &&
                      kind != PLATEAU_LM_SPARSE_LDLT))
        return 0;
    t = plateau__lm_factor_layout(symbolic, kind, NULL, NULL);
    if (t == 0 || t > (size_t)-1 - 16) return 0;
    return t + 16;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factor_create(const plateau_lm_sparse_symbolic *symbolic,
                                                                 int kind, void *work,
                                                                 size_t work_bytes,
                                                                 plateau_lm_sparse_factor **factor)
{
    size_t need;
    void *owned = NULL;
    unsigned char *base;
    plateau_lm_sparse_factor *F;
    if (factor) *factor = NULL;
    if (!symbolic || !factor) return PLATEAU_LM_ERR_ARGUMENT;
    if (kind != PLATEAU_LM_SPARSE_LU && kind != PLATEAU_LM_SPARSE_CHOLESKY &&
        kind != PLATEAU_LM_SPARSE_LDLT)
        return PLATEAU_LM_ERR_ARGUMENT;
    need = plateau_lm_sparse_factor_size(symbolic, kind);
    if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
    if (work) {
        if (work_bytes < need) return PLATEAU_LM_ERR_WORKSPACE_TOO_SMALL;
        base = (unsigned char *)work;
    } else {
        owned = plateau__alloc(&symbolic->alloc, need);
        if (!owned) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        base = (unsigned char *)owned;
    }
    base = plateau__lm_align16(base);
    F = (plateau_lm_sparse_factor *)(void *)base;
    (void)plateau__lm_factor_layout(symbolic, kind, F, base);
    F->sym = symbolic;
    F->owned = owned;
    F->kind = kind;
    F->factored = 0;
    F->single = 0;
    F->failed = -1;
    F->negative = F->positive = 0;
    *factor = F;
    return PLATEAU_LM_OK;
}

PLATEAU_LM_DEF void plateau_lm_sparse_factor_free(plateau_lm_sparse_factor *factor)
{
    if (factor && factor->owned) plateau__free(&factor->sym->alloc, factor->owned);
}

PLATEAU_LM_DEF plateau_index plateau_lm_sparse_failed_node(const plateau_lm_sparse_factor *factor)
{
    return factor ? factor->failed : -1;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_inertia(const plateau_lm_sparse_factor *factor,
                                                           size_t *negative, size_t *positive)
{
    if (!factor || !negative || !positive || factor->kind != PLATEAU_LM_SPARSE_LDLT)
        return PLATEAU_LM_ERR_ARGUMENT;
    if (!factor->factored) return PLATEAU_LM_ERR_NOT_FACTORED;
    *negative = factor->negative;
    *positive = factor->positive;
    return PLATEAU_LM_OK;
}

/* ---- Numeric factorisation (multifrontal) ----------------------------------- */

/* Adds the b x b block s (row-major; scaled by the b x b row-major d when d is
 * not NULL, plus shift on the diagonal when diag) into the front at rows of
 * node position r, columns of node position k. */
static void plateau__lm_assemble_block(plateau_lm_sparse_factor *F, size_t f, size_t b,
                                       const double *s, const double *d, double shift, int diag,
                                       size_t r, size_t k)
{
    double blk[16];
    size_t i, j, t;
    for (i = 0; i < b; i++)
        for (j = 0; j < b; j++) blk[i * b + j] = s[i * b + j] + (diag && i == j ? shift : 0.0);
    if (d) {
        double sc[16];
        for (i = 0; i < b; i++)
            for (j = 0; j < b; j++) {
                double acc = 0.0;
                for (t = 0; t < b; t++) acc += d[i * b + t] * blk[t * b + j];
                sc[i * b + j] = acc;
            }
        for (i = 0; i < b * b; i++) blk[i] = sc[i];
    }
    for (j = 0; j < b; j++) {
        double *col = F->front + (size_t)F->map[k * b + j] * f;
        for (i = 0; i < b; i++) col[F->map[r * b + i]] += blk[i * b + j];
    }
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factorize(plateau_lm_sparse_factor *factor,
                                                             const double *values, double shift)
{
    const plateau_lm_sparse_symbolic *S;
    size_t b, bb, n, t, top = 0, i, p, q;
    int lu, ldlt;
    double dtol = 0.0, work = 0.0;
    if (!factor || !values) return PLATEAU_LM_ERR_ARGUMENT;
    S = factor->sym;
    factor->factored = 0;
    factor->single = 0;
    factor->failed = -1;
    factor->negative = factor->positive = 0;
    if (!(shift >= 0.0) || !plateau__lm_finite(shift)) return PLATEAU_LM_ERR_ARGUMENT;
    b = S->b;
    bb = b * b;
    n = S->n;
    lu = factor->kind == PLATEAU_LM_SPARSE_LU;
    ldlt = factor->kind == PLATEAU_LM_SPARSE_LDLT;
    for (i = 0; i < n; i++)
        for (p = S->rs[i]; p < S->rs[i + 1]; p++) {
            if (!plateau__lm_all_finite(values + p * bb, bb)) {
                factor->failed = (plateau_index)i;
                return PLATEAU_LM_ERR_NOT_FINITE_MATRIX;
            }
            if (ldlt && (size_t)S->cols[p] == i)
                for (q = 0; q < b; q++) {
                    double a = PLATEAU_FABS(values[p * bb + q * b + q] + shift);
                    if (a > dtol) dtol = a;
                }
        }
    /* LDL^T: a pivot below pivot_tol times the largest diagonal entry is a breakdown */
    dtol *= S->pivot_tol;
    if (ldlt && !(dtol > 0.0)) dtol = DBL_MIN;
    /* LU: static block pivoting, D_i^-1 with D_i = A_ii + shift I */
    if (lu)
        for (i = 0; i < n; i++) {
            for (p = S->rs[i]; p < S->rs[i + 1]; p++)
                if ((size_t)S->cols[p] == i) break;
            if (!plateau__lm_block_inverse(values + p * bb, b, shift, factor->dinv + i * bb)) {
                factor->failed = (plateau_index)i;
                return PLATEAU_LM_ERR_SINGULAR_PIVOT;
            }
        }
    for (t = 0; t < S->ns; t++) {
        size_t f0 = S->sfirst[t], nn = S->sfirst[t + 1] - f0, nc = b * nn;
        const plateau_index *rows = S->srows + S->srp[t];
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr, j, base, off, bad = 0;
        double *Fr = factor->front;
        int ok;
        /* a time limit (options.cancel): asked once the fronts since the
         * last question hold PLATEAU_LM_CANCEL_FLOPS multiply-adds (a
         * front's partial factorisation: about f^2 nc) */
        work += (double)f * (double)f * (double)nc;
        if (S->cancel && work >= PLATEAU_LM_CANCEL_FLOPS) {
            work = 0.0;
            if (S->cancel(S->cancel_user)) return PLATEAU_LM_ERR_ABORTED;
        }
        /* front positions: the supernode's unknowns, then its rows below */
        for (j = 0; j < nc; j++) factor->map[f0 * b + j] = (plateau_index)j;
        for (q = 0; q < nrn; q++)
            for (j = 0; j < b; j++) factor->map[(size_t)rows[q] * b + j] = (plateau_index)(nc + q * b + j);
        for (j = 0; j < f * f; j++) Fr[j] = 0.0;
        /* assembly of A's entries: for each pivot node j, row j from column j
         * on (U part) and column j from row j on (L part) */
        for (j = f0; j < f0 + nn; j++) {
            size_t old = (size_t)S->perm[j];
            for (p = S->rs[old]; p < S->rs[old + 1]; p++) {
                size_t kold = (size_t)S->cols[p], k = (size_t)S->pinv[kold];
                const double *tb = values + S->tpos[p] * bb;
                if (k < j) continue;
                if (lu) {
                    plateau__lm_assemble_block(factor, f, b, values + p * bb, factor->dinv + old * bb,
                                               shift, k == j, j, k);
                    if (k != j)
                        plateau__lm_assemble_block(factor, f, b, tb, factor->dinv + kold * bb, 0.0, 0,
                                                   k, j);
                } else {
                    plateau__lm_assemble_block(factor, f, b, tb, NULL, shift, k == j, k, j);
                }
            }
        }
        /* extend-add of the children's update matrices (the top of the stack) */
        off = 0;
        for (q = S->scp[t]; q < S->scp[t + 1]; q++) {
            size_t ch = S->schild[q], nrc = b * (S->srp[ch + 1] - S->srp[ch]);
            off += nrc * nrc;
        }
        PLATEAU_ASSERT(off <= top);
        base = top - off;
        off = base;
        for (q = S->scp[t]; q < S->scp[t + 1]; q++) {
            size_t ch = S->schild[q], nrcn = S->srp[ch + 1] - S->srp[ch], nrc = b * nrcn, jj, ii;
            const plateau_index *rc = S->srows + S->srp[ch];
            const double *upd = factor->stack + off;
            for (jj = 0; jj < nrcn; jj++)
                for (ii = 0; ii < b; ii++)
                    factor->rel[jj * b + ii] = factor->map[(size_t)rc[jj] * b + ii];
            for (jj = 0; jj < nrc; jj++) {
                double *col = Fr + (size_t)factor->rel[jj] * f;
                const double *ucol = upd + jj * nrc;
                for (ii = lu ? 0 : jj; ii < nrc; ii++) col[factor->rel[ii]] += ucol[ii];
            }
            off += nrc * nrc;
        }
        top = base;
        ok = lu     ? plateau__lm_lu_partial(Fr, f, nc, S->pivot_tol, &bad, factor->pa, factor->pb)
             : ldlt ? plateau__lm_ldlt_partial(Fr, f, nc, dtol, &bad, factor->pa, factor->pb)
                    : plateau__lm_chol_partial(Fr, f, nc, &bad, factor->pa, factor->pb);
        if (!ok) {
            factor->failed = S->perm[f0 + bad / b];
            factor->negative = factor->positive = 0;
            return lu || ldlt ? PLATEAU_LM_ERR_SINGULAR_PIVOT : PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE;
        }
        if (ldlt)
            for (j = 0; j < nc; j++) {
                if (Fr[j * f + j] < 0.0) factor->negative++;
                else factor->positive++;
            }
        /* keep [L11\U11; L21] (the first nc columns) and U12; push the Schur
         * complement */
        {
            double *L = factor->L + S->lpos[t];
            for (j = 0; j < f * nc; j++) L[j] = Fr[j];
            if (lu) {
                double *U = factor->U + S->upos[t];
                for (j = 0; j < nr; j++)
                    for (i = 0; i < nc; i++) U[j * nc + i] = Fr[(nc + j) * f + i];
            }
            for (j = 0; j < nr; j++) {
                double *dst = factor->stack + top + j * nr;
                const double *src = Fr + (nc + j) * f + nc;
                for (i = lu ? 0 : j; i < nr; i++) dst[i] = src[i];
            }
            top += nr * nr;
            PLATEAU_ASSERT(top <= S->stack_peak);
        }
    }
    factor->factored = 1;
    return PLATEAU_LM_OK;
}

/* ---- Solve -------------------------------------------------------------------- */

/* Gathers (scatter = 0) the entries of y at the unknowns of the b-node rows
 * into w, or adds w into them (scatter = 1). */
static void plateau__lm_rows_move(const plateau_index *rows, size_t nrn, size_t b, double *y,
                                  double *w, int scatter)
{
    size_t q, i;
    for (q = 0; q < nrn; q++) {
        double *yq = y + (size_t)rows[q] * b, *wq = w + q * b;
        if (scatter)
            for (i = 0; i < b; i++) yq[i] += wq[i];
        else
            for (i = 0; i < b; i++) wq[i] = yq[i];
    }
}

/* One right-hand side, in the elimination numbering, in place in y; w is
 * scratch of front_max values (the off-diagonal rows of a supernode, kept
 * contiguous so that the updates are plain dense loops). */
static void plateau__lm_sparse_substitute(const plateau_lm_sparse_factor *F, double *y, double *w)
{
    const plateau_lm_sparse_symbolic *S = F->sym;
    size_t b = S->b, t, k, i, q;
    int lu = F->kind == PLATEAU_LM_SPARSE_LU, chol = F->kind == PLATEAU_LM_SPARSE_CHOLESKY;
    /* forward: L y = r, supernode by supernode; the rows below the
     * supernode collect their updates in w, added to y once */
    for (t = 0; t < S->ns; t++) {
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const plateau_index *rows = S->srows + S->srp[t];
        const double *L = F->L + S->lpos[t];
        double *ys = y + f0 * b;
        for (q = 0; q < nr; q++) w[q] = 0.0;
        for (k = 0; k < nc; k++) {
            const double *lk = L + k * f, *lr = lk + nc;
            double v;
            if (chol) ys[k] /= lk[k];
            v = ys[k];
            if (v == 0.0) continue;
            for (i = k + 1; i < nc; i++) ys[i] -= lk[i] * v;
            for (q = 0; q < nr; q++) w[q] -= lr[q] * v;
        }
        plateau__lm_rows_move(rows, nrn, b, y, w, 1);
    }
    /* backward: U x = y (LU), L^T x = y (Cholesky) or L^T x = D^-1 y
     * (LDL^T, L unit lower); the rows below the
     * supernode (already solved) gathered into w */
    for (t = S->ns; t-- > 0;) {
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const plateau_index *rows = S->srows + S->srp[t];
        const double *L = F->L + S->lpos[t];
        double *ys = y + f0 * b;
        plateau__lm_rows_move(rows, nrn, b, y, w, 0);
        if (lu) {
            const double *U = F->U + S->upos[t];
            for (q = 0; q < nr; q++) {
                double v = w[q];
                const double *uq = U + q * nc;
                if (v == 0.0) continue;
                for (k = 0; k < nc; k++) ys[k] -= uq[k] * v;
            }
            for (k = nc; k-- > 0;) {
                const double *lk = L + k * f;
                double v = ys[k] / lk[k];
                ys[k] = v;
                for (i = 0; i < k; i++) ys[i] -= lk[i] * v;
            }
        } else {
            for (k = nc; k-- > 0;) {
                const double *lk = L + k * f, *lr = lk + nc;
                double v = chol ? ys[k] : ys[k] / lk[k];
                for (i = k + 1; i < nc; i++) v -= lk[i] * ys[i];
                for (q = 0; q < nr; q++) v -= lr[q] * w[q];
                ys[k] = chol ? v / lk[k] : v;
            }
        }
    }
}

/* Two right-hand sides of a Cholesky or L D L^T factor at once, in the
 * elimination numbering, in place in y0 and y1; w is scratch of 2 nr
 * values for the largest nr (the front's front_max^2 values have room:
 * nr < front_max).  Each column sees the operations of
 * plateau__lm_sparse_substitute in the same order (the same result, bit
 * for bit), but every entry of L is loaded once for both and the two
 * back-substitution sums are independent chains the processor overlaps. */
static void plateau__lm_sparse_substitute2(const plateau_lm_sparse_factor *F, double *y0, double *y1,
                                           double *w)
{
    const plateau_lm_sparse_symbolic *S = F->sym;
    size_t b = S->b, t, k, i, q;
    int chol = F->kind == PLATEAU_LM_SPARSE_CHOLESKY;
    for (t = 0; t < S->ns; t++) {
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const plateau_index *rows = S->srows + S->srp[t];
        const double *L = F->L + S->lpos[t];
        double *a = y0 + f0 * b, *c = y1 + f0 * b, *w1 = w + nr;
        for (q = 0; q < nr; q++) w[q] = w1[q] = 0.0;
        for (k = 0; k < nc; k += 2) {
            /* columns k and k + 1 together: each entry below takes column
             * k's update, then column k + 1's, as one column at a time
             * would (the same bits), with one pass over it */
            const double *l0 = L + k * f, *l1 = k + 1 < nc ? l0 + f : l0, *r0 = l0 + nc, *r1 = l1 + nc;
            double u0, v0, u1 = 0.0, v1 = 0.0;
            int z0, z1 = 1;
            if (chol) {
                a[k] /= l0[k];
                c[k] /= l0[k];
            }
            u0 = a[k];
            v0 = c[k];
            z0 = u0 == 0.0 && v0 == 0.0;
            if (k + 1 < nc) {
                if (!z0) {
                    a[k + 1] -= l0[k + 1] * u0;
                    c[k + 1] -= l0[k + 1] * v0;
                }
                if (chol) {
                    a[k + 1] /= l1[k + 1];
                    c[k + 1] /= l1[k + 1];
                }
                u1 = a[k + 1];
                v1 = c[k + 1];
                z1 = u1 == 0.0 && v1 == 0.0;
            }
            if (z0 && z1) continue;
            if (z0 || z1) { /* one column: the other is zero, or k is the last */
                const double *lk = z0 ? l1 : l0, *lr = z0 ? r1 : r0;
                double u = z0 ? u1 : u0, v = z0 ? v1 : v0;
                for (i = k + 1 + (k + 1 < nc); i < nc; i++) {
                    a[i] -= lk[i] * u;
                    c[i] -= lk[i] * v;
                }
                for (q = 0; q < nr; q++) {
                    w[q] -= lr[q] * u;
                    w1[q] -= lr[q] * v;
                }
                continue;
            }
            for (i = k + 2; i < nc; i++) {
                a[i] = a[i] - l0[i] * u0 - l1[i] * u1;
                c[i] = c[i] - l0[i] * v0 - l1[i] * v1;
            }
            for (q = 0; q < nr; q++) {
                w[q] = w[q] - r0[q] * u0 - r1[q] * u1;
                w1[q] = w1[q] - r0[q] * v0 - r1[q] * v1;
            }
        }
        plateau__lm_rows_move(rows, nrn, b, y0, w, 1);
        plateau__lm_rows_move(rows, nrn, b, y1, w1, 1);
    }
    for (t = S->ns; t-- > 0;) {
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const plateau_index *rows = S->srows + S->srp[t];
        const double *L = F->L + S->lpos[t];
        double *a = y0 + f0 * b, *c = y1 + f0 * b, *w1 = w + nr;
        plateau__lm_rows_move(rows, nrn, b, y0, w, 0);
        plateau__lm_rows_move(rows, nrn, b, y1, w1, 0);
        for (k = nc; k-- > 0;) {
            const double *lk = L + k * f, *lr = lk + nc;
            double u = chol ? a[k] : a[k] / lk[k], v = chol ? c[k] : c[k] / lk[k];
            for (i = k + 1; i < nc; i++) {
                u -= lk[i] * a[i];
                v -= lk[i] * c[i];
            }
            for (q = 0; q < nr; q++) {
                u -= lr[q] * w[q];
                v -= lr[q] * w1[q];
            }
            a[k] = chol ? u / lk[k] : u;
            c[k] = chol ? v / lk[k] : v;
        }
    }
}

/* An LU factor kept as a preconditioner only (the dog leg's GMRES on an
 * earlier Jacobian): L and U rounded to float, in place (float j over the
 * bytes of double j / 2, written in ascending j after double j was read),
 * so that each substitution reads half the bytes: its sparse solves are
 * bound by memory (at 10^4 nodes one reads some 75 MB of L and U for 2
 * flops a value).  The rounding, 6e-8 relative, lies far below what such a
 * preconditioner leaves (GMRES's relative residuals 1e-3 to 0.15 after 8
 * vectors; Higham, "Accuracy and stability of numerical algorithms",
 * section 12.2: a factorisation in lower precision as a preconditioner);
 * a new factorisation writes doubles again. */
static void plateau__lm_lu_to_single(plateau_lm_sparse_factor *F)
{
    const plateau_lm_sparse_symbolic *S = F->sym;
    size_t j, nl = S->lpos[S->ns], nu = S->upos[S->ns];
    unsigned char *ls = (unsigned char *)(void *)F->L, *us = (unsigned char *)(void *)F->U;
    float v;
    const unsigned char *vc = (const unsigned char *)&v;
    size_t i;
    if (F->single || F->kind != PLATEAU_LM_SPARSE_LU || !F->factored) return;
    /* copied as characters: the bytes take the type float (C99 6.5p6), and
     * every store stays after the loads of the doubles it overwrites */
    for (j = 0; j < nl; j++) {
        v = (float)F->L[j];
        for (i = 0; i < sizeof v; i++) ls[j * sizeof v + i] = vc[i];
    }
    for (j = 0; j < nu; j++) {
        v = (float)F->U[j];
        for (i = 0; i < sizeof v; i++) us[j * sizeof v + i] = vc[i];
    }
    F->single = 1;
}

/* plateau__lm_sparse_substitute for an LU factor in float
 * (plateau__lm_lu_to_single): the same steps, the sums in double. */
static void plateau__lm_sparse_substitute_single(const plateau_lm_sparse_factor *F, double *y, double *w)
{
    const plateau_lm_sparse_symbolic *S = F->sym;
    const float *Ls = (const float *)(const void *)F->L, *Us = (const float *)(const void *)F->U;
    size_t b = S->b, t, k, i, q;
    for (t = 0; t < S->ns; t++) { /* forward: L y = r (unit diagonal) */
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const float *L = Ls + S->lpos[t];
        double *ys = y + f0 * b;
        for (q = 0; q < nr; q++) w[q] = 0.0;
        for (k = 0; k < nc; k++) {
            const float *lk = L + k * f, *lr = lk + nc;
            double v = ys[k];
            if (v == 0.0) continue;
            for (i = k + 1; i < nc; i++) ys[i] -= (double)lk[i] * v;
            for (q = 0; q < nr; q++) w[q] -= (double)lr[q] * v;
        }
        plateau__lm_rows_move(S->srows + S->srp[t], nrn, b, y, w, 1);
    }
    for (t = S->ns; t-- > 0;) { /* backward: U x = y */
        size_t f0 = S->sfirst[t], nc = b * (S->sfirst[t + 1] - f0);
        size_t nrn = S->srp[t + 1] - S->srp[t], nr = b * nrn, f = nc + nr;
        const float *L = Ls + S->lpos[t], *U = Us + S->upos[t];
        double *ys = y + f0 * b;
        plateau__lm_rows_move(S->srows + S->srp[t], nrn, b, y, w, 0);
        for (q = 0; q < nr; q++) {
            double v = w[q];
            const float *uq = U + q * nc;
            if (v == 0.0) continue;
            for (k = 0; k < nc; k++) ys[k] -= (double)uq[k] * v;
        }
        for (k = nc; k-- > 0;) {
            const float *lk = L + k * f;
            double v = ys[k] / (double)lk[k];
            ys[k] = v;
            for (i = 0; i < k; i++) ys[i] -= (double)lk[i] * v;
        }
    }
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_solve(plateau_lm_sparse_factor *factor,
                                                         size_t nrhs, double *b, size_t ldb)
{
    const plateau_lm_sparse_symbolic *S;
    size_t bs, n, N, r, k, i, j;
    if (!factor || (!b && nrhs > 0)) return PLATEAU_LM_ERR_ARGUMENT;
    if (!factor->factored) return PLATEAU_LM_ERR_NOT_FACTORED;
    S = factor->sym;
    bs = S->b;
    n = S->n;
    N = n * bs;
    if (nrhs > 1 && ldb < N) return PLATEAU_LM_ERR_ARGUMENT;
    r = 0;
    if (factor->kind != PLATEAU_LM_SPARSE_LU)
        for (; r + 2 <= nrhs; r += 2) {
            /* a pair: y = P c0, then c0 = P c1 (c0 is in y), both solved,
             * then c1 = P^T c0 and c0 = P^T y */
            double *c0 = b + r * ldb, *c1 = c0 + ldb, *y = factor->y;
            for (k = 0; k < n; k++)
                for (i = 0; i < bs; i++) y[k * bs + i] = c0[(size_t)S->perm[k] * bs + i];
            for (k = 0; k < n; k++)
                for (i = 0; i < bs; i++) c0[k * bs + i] = c1[(size_t)S->perm[k] * bs + i];
            plateau__lm_sparse_substitute2(factor, y, c0, factor->front);
            for (k = 0; k < n; k++)
                for (i = 0; i < bs; i++) c1[(size_t)S->perm[k] * bs + i] = c0[k * bs + i];
            for (k = 0; k < n; k++)
                for (i = 0; i < bs; i++) c0[(size_t)S->perm[k] * bs + i] = y[k * bs + i];
        }
    for (; r < nrhs; r++) {
        double *col = b + r * ldb, *y = factor->y;
        /* y = P D^-1 b (D^-1 only for LU), x = P^T y */
        for (k = 0; k < n; k++) {
            size_t old = (size_t)S->perm[k];
            const double *src = col + old * bs;
            if (factor->kind == PLATEAU_LM_SPARSE_LU) {
                const double *d = factor->dinv + old * bs * bs;
                for (i = 0; i < bs; i++) {
                    double acc = 0.0;
                    for (j = 0; j < bs; j++) acc += d[i * bs + j] * src[j];
                    y[k * bs + i] = acc;
                }
            } else {
                for (i = 0; i < bs; i++) y[k * bs + i] = src[i];
            }
        }
        if (factor->single) plateau__lm_sparse_substitute_single(factor, y, factor->front);
        else plateau__lm_sparse_substitute(factor, y, factor->front);
        for (k = 0; k < n; k++) {
            size_t old = (size_t)S->perm[k];
            for (i = 0; i < bs; i++) col[old * bs + i] = y[k * bs + i];
        }
    }
    return PLATEAU_LM_OK;
}


/* ---- Powell's dog leg (MNT Algorithm 3.21) ----------------------------------- */

/* The LU of an earlier Jacobian is kept while each step on it cuts F at
 * least this much (a rate of 1/2 in ||f||; the cost of a refactorisation
 * against a step on the kept LU: examples/NOTES.md). */
#define PLATEAU__LM_CHORD_RATE 0.25

/* options.chord > 0 (plain chord steps on a fresh LU, see
 * plateau__lm_dl_chords): a full Newton step from a fresh LU that cut F
 * to at most CHORD_START F starts them (the quadratic regime), and they go
 * on while each cuts F to at most CHORD_KEEP F. */
#define PLATEAU__LM_CHORD_START 1e-3
#define PLATEAU__LM_CHORD_KEEP 1e-2

/* y = J v (trans = 0) or J^T v (trans = 1) for block values jac on pattern S */
static void plateau__lm_bmatvec(const plateau_lm_sparse_symbolic *S, const double *jac,
                                const double *v, double *y, int trans)
{
    size_t b = S->b, bb = b * b, i, p, r, c;
    for (i = 0; i < S->n * b; i++) y[i] = 0.0;
    for (i = 0; i < S->n; i++)
        for (p = S->rs[i]; p < S->rs[i + 1]; p++) {
            size_t k = (size_t)S->cols[p];
            const double *blk = jac + p * bb;
            for (r = 0; r < b; r++)
                for (c = 0; c < b; c++) {
                    if (trans) y[k * b + c] += blk[r * b + c] * v[i * b + r];
                    else y[i * b + r] += blk[r * b + c] * v[k * b + c];
                }
        }
}

static double plateau__lm_dot(const double *a, const double *b, size_t n)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

/* With a kept LU the Gauss-Newton step J h = -f is solved by GMRES with
 * that LU as the preconditioner: at most this many Krylov vectors (one
 * sparse solve and one product with J each), stopping once the residual
 * is below PLATEAU__LM_KRYLOV_TOL ||f||; above PLATEAU__LM_KRYLOV_GIVEUP
 * ||f|| the LU is taken anew instead. */
#define PLATEAU__LM_KRYLOV_DIM 8
#define PLATEAU__LM_KRYLOV_TOL 1e-4
#define PLATEAU__LM_KRYLOV_GIVEUP 0.1
/* ... unless the step is still worth trying (below this): then it is, and
 * the LU is taken anew at the next iteration */
#define PLATEAU__LM_KRYLOV_POOR 0.5

/* GMRES(m) with right preconditioning by the LU in Fac (Saad, "Iterative
 * methods for sparse linear systems", Algorithm 9.5; modified Gram-Schmidt,
 * Givens rotations), from h = 0, for J h = -f with J the block values jac:
 * h = M^-1 V y minimises ||f + J h|| over the Krylov space of J M^-1 and f.
 * V: (m + 1) N scratch, w: N scratch, hs: (m + 1) (m + 4) scratch.
 * Returns ||f + J h|| / ||f|| as the recurrence tracks it. */
static double plateau__lm_gmres(const plateau_lm_sparse_symbolic *S, plateau_lm_sparse_factor *Fac,
                                const double *jac, const double *f, double *h, double *V,
                                double *w, double *hs, size_t m)
{
    size_t N = S->n * S->b, ld = m + 1, i, j, k = 0, l;
    double *H = hs, *cs = hs + ld * m, *sn = cs + ld, *gv = sn + ld, beta, *v0 = V;
    beta = PLATEAU_SQRT(plateau__lm_dot(f, f, N));
    for (i = 0; i < N; i++) h[i] = 0.0;
    if (!(beta > 0.0)) return 0.0;
    for (i = 0; i < N; i++) v0[i] = -f[i] / beta;
    gv[0] = beta;
    for (j = 0; j < m; j++) {
        double *vj = V + j * N, *vn = V + (j + 1) * N, hn, r, t;
        double *Hj = H + j * ld;
        for (i = 0; i < N; i++) w[i] = vj[i];
        (void)plateau_lm_sparse_solve(Fac, 1, w, N);
        plateau__lm_bmatvec(S, jac, w, vn, 0);
        for (l = 0; l <= j; l++) {
            const double *vl = V + l * N;
            double hl = plateau__lm_dot(vn, vl, N);
            Hj[l] = hl;
            for (i = 0; i < N; i++) vn[i] -= hl * vl[i];
        }
        hn = PLATEAU_SQRT(plateau__lm_dot(vn, vn, N));
        Hj[j + 1] = hn;
        if (hn > 0.0)
            for (i = 0; i < N; i++) vn[i] /= hn;
        for (l = 0; l < j; l++) {
            t = cs[l] * Hj[l] + sn[l] * Hj[l + 1];
            Hj[l + 1] = -sn[l] * Hj[l] + cs[l] * Hj[l + 1];
            Hj[l] = t;
        }
        r = PLATEAU_SQRT(Hj[j] * Hj[j] + hn * hn);
        if (!(r > 0.0) || !plateau__lm_finite(r)) break;
        cs[j] = Hj[j] / r;
        sn[j] = hn / r;
        Hj[j] = r;
        Hj[j + 1] = 0.0;
        gv[j + 1] = -sn[j] * gv[j];
        gv[j] = cs[j] * gv[j];
        k = j + 1;
        if (PLATEAU_FABS(gv[j + 1]) <= PLATEAU__LM_KRYLOV_TOL * beta || hn == 0.0) break;
    }
    if (k == 0) return 1.0;
    /* y = R^-1 g (back substitution), h = M^-1 V y */
    for (j = k; j-- > 0;) {
        double acc = gv[j];
        for (l = j + 1; l < k; l++) acc -= H[l * ld + j] * gv[l];
        gv[j] = acc / H[j * ld + j];
    }
    for (i = 0; i < N; i++) w[i] = 0.0;
    for (j = 0; j < k; j++) {
        const double *vj = V + j * N;
        double y = gv[j];
        for (i = 0; i < N; i++) w[i] += y * vj[i];
    }
    (void)plateau_lm_sparse_solve(Fac, 1, w, N);
    for (i = 0; i < N; i++) h[i] = w[i];
    /* the true relative residual, ||f + J h|| / ||f|| */
    plateau__lm_bmatvec(S, jac, h, w, 0);
    for (i = 0; i < N; i++) w[i] += f[i];
    return PLATEAU_SQRT(plateau__lm_dot(w, w, N)) / beta;
}

/* The blocks consecutive dog-leg solves share (plateau_lm_dogleg_solve_kept):
 * block[0] the LU object, block[1] the vectors. */
struct plateau_lm_dogleg_keep {
    plateau_allocator alloc;
    void *block[2];
    size_t bytes[2];
};

/* Block i of the keep, at least need bytes: the one it holds when large
 * enough, else a new one of need + need / 32 bytes (the old one freed
 * first, so that the two are never held together); NULL when out of
 * memory (the keep then holds no block i). */
static void *plateau__lm_keep_block(plateau_lm_dogleg_keep *k, int i, size_t need)
{
    size_t want = need + need / 32;
    if (k->bytes[i] >= need) return k->block[i];
    plateau__free(&k->alloc, k->block[i]);
    k->block[i] = NULL;
    k->bytes[i] = 0;
    if (want < need) want = need;
    k->block[i] = plateau__alloc(&k->alloc, want);
    if (k->block[i]) k->bytes[i] = want;
    return k->block[i];
}

PLATEAU_LM_DEF size_t plateau_lm_dogleg_keep_bytes(const plateau_lm_dogleg_keep *keep)
{
    return keep ? keep->bytes[0] + keep->bytes[1] : 0;
}

PLATEAU_LM_DEF void plateau_lm_dogleg_keep_free(plateau_lm_dogleg_keep *keep)
{
    plateau_allocator a;
    if (!keep) return;
    a = keep->alloc;
    plateau__free(&a, keep->block[0]);
    plateau__free(&a, keep->block[1]);
    plateau__free(&a, keep);
}

/* The state of one dog-leg solve, so that its phases are functions of one
 * pointer.  The LU in Fac is of the Jacobian at the current x (fresh), or
 * of an earlier one kept as GMRES's preconditioner (see
 * plateau__lm_dl_gauss_newton); refactor: take a new one at the next
 * Jacobian. */
typedef struct plateau__lm_dl {
    plateau_lm_options o;
    plateau_lm_sparse_symbolic *S;
    plateau_lm_sparse_factor *Fac;
    plateau_lm_dogleg_keep *keep; /* the blocks' keeper, or NULL: the solve's own */
    plateau_lm_sparse_func func;
    void *user;
    double *x, *mem;
    /* f, fnew, g = J^T f, h_gn, h, x + h, J g, column norms, J h (N each),
     * the Krylov vectors, the Jacobian's blocks, GMRES's small matrix */
    double *f, *fnew, *g, *hgn, *h, *xnew, *jg, *cn, *jh, *kv, *jac, *khs;
    double F, F0, Fold, f_stop, ginf, delta, step_floor, xn, hn; /* Fold: F before the last accepted step */
    double krylov_rr; /* GMRES's relative residual for h_gn at x (HUGE: h_gn from a fresh LU) */
    size_t N, nv, bb;
    int iter, revals, jevals, gn_ok, small_changes, fresh, refactor;
    int chord_ready; /* options.chord > 0: the last accepted step was a full Newton
                        step from a fresh LU that cut F to at most CHORD_START F */
    int tailing, max_user; /* in the tail; the caller's max_iterations */
    int cancelled; /* a factorisation was abandoned (options.cancel) */
    size_t finite_trials, nonfinite_trials; /* trial points x + h evaluated */
    plateau_lm_stop stop;
} plateau__lm_dl;

/* Options, the analysis of the pattern, the LU object and one block for the
 * vectors. */
static plateau_lm_result plateau__lm_dl_setup(plateau__lm_dl *dl,
                                              const plateau_lm_sparse_pattern *pattern,
                                              const double *xy,
                                              const plateau_lm_options *options)
{
    plateau_lm_sparse_options so;
    plateau_lm_result res;
    size_t bytes = 0, N;
    int ok = 1;
    dl->o = plateau_lm_resolved_options(options);
    /* what the dog leg does not implement is refused, never ignored */
    if (!plateau__lm_options_valid(&dl->o) || dl->o.numeric_jacobian ||
        dl->o.scaling != PLATEAU_LM_SCALING_NONE || plateau__lm_has_weights(&dl->o) || dl->o.lower ||
        dl->o.upper || dl->o.a_eq)
        return PLATEAU_LM_ERR_ARGUMENT;
    so.ordering = 0;
    so.leaf_nodes = 0;
    so.pivot_tol = 0.0;
    so.allocator = dl->o.allocator;
    so.cancel = dl->o.cancel;
    so.cancel_user = dl->user;
    res = plateau_lm_sparse_analyze(pattern, xy, &so, &dl->S);
    if (res != PLATEAU_LM_OK) return res;
    N = dl->N = dl->S->n * dl->S->b;
    dl->bb = dl->S->b * dl->S->b;
    if (!plateau__lm_all_finite(dl->x, N)) return PLATEAU_LM_ERR_NOT_FINITE_X0;
    if (dl->keep) { /* the LU object in the kept block */
        size_t need = plateau_lm_sparse_factor_size(dl->S, PLATEAU_LM_SPARSE_LU);
        void *blk;
        if (need == 0) return PLATEAU_LM_ERR_OVERFLOW;
        blk = plateau__lm_keep_block(dl->keep, 0, need);
        if (!blk) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        res = plateau_lm_sparse_factor_create(dl->S, PLATEAU_LM_SPARSE_LU, blk, dl->keep->bytes[0], &dl->Fac);
    } else {
        res = plateau_lm_sparse_factor_create(dl->S, PLATEAU_LM_SPARSE_LU, NULL, 0, &dl->Fac);
    }
    if (res != PLATEAU_LM_OK) return res;
    /* vectors: f, fnew, g, hgn, h, xnew, jg, cn, jh (N each), the Krylov
     * vectors (m + 1 of N) and the Jacobian's blocks, then the small
     * Hessenberg matrix and rotations */
    dl->nv = dl->S->nnz;
    ok &= plateau__lm_lay(&bytes, plateau__lm_mul(N, 10 + PLATEAU__LM_KRYLOV_DIM, &ok), sizeof(double));
    ok &= plateau__lm_lay(&bytes, plateau__lm_mul(dl->nv, dl->bb, &ok), sizeof(double));
    ok &= plateau__lm_lay(&bytes, (PLATEAU__LM_KRYLOV_DIM + 1) * (PLATEAU__LM_KRYLOV_DIM + 4), sizeof(double));
    if (!ok) return PLATEAU_LM_ERR_OVERFLOW;
    dl->mem = (double *)(dl->keep ? plateau__lm_keep_block(dl->keep, 1, bytes)
                                  : plateau__alloc(&dl->o.allocator, bytes));
    if (!dl->mem) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
    dl->f = dl->mem; dl->fnew = dl->f + N; dl->g = dl->fnew + N; dl->hgn = dl->g + N;
    dl->h = dl->hgn + N; dl->xnew = dl->h + N; dl->jg = dl->xnew + N; dl->cn = dl->jg + N;
    dl->jh = dl->cn + N; dl->kv = dl->jh + N;
    dl->jac = dl->kv + (PLATEAU__LM_KRYLOV_DIM + 1) * N;
    dl->khs = dl->jac + dl->nv * dl->bb;
    return PLATEAU_LM_OK;
}

/* MNT 3.21's tests at a new point: SMALL_F (before the Jacobian, which
 * the stop does not need: on method paper's meshes forming it costs as
 * much as a sparse LU); else the Jacobian there, g = J^T f, the column
 * norms, and the gradient test in the dense LM's cosine form (the largest
 * |g_j| / (||J_j|| ||f||) at most eps_grad) set dl->stop. */
static plateau_lm_result plateau__lm_dl_jacobian(plateau__lm_dl *dl)
{
    const plateau_lm_sparse_symbolic *S = dl->S;
    size_t N = dl->N, bb = dl->bb, i, j, k;
    double fnorm, cmax = 0.0;
    if (dl->F <= dl->f_stop) { /* no step follows: no Jacobian either */
        dl->stop = PLATEAU_LM_STOP_SMALL_F;
        return PLATEAU_LM_OK;
    }
    dl->jevals++;
    if (dl->func(dl->x, dl->fnew, dl->jac, dl->user) != 0) return PLATEAU_LM_ERR_ABORTED;
    if (!plateau__lm_all_finite(dl->jac, dl->nv * bb)) return PLATEAU_LM_ERR_NOT_FINITE_JACOBIAN;
    plateau__lm_bmatvec(S, dl->jac, dl->f, dl->g, 1);
    for (j = 0; j < N; j++) dl->cn[j] = 0.0;
    for (i = 0; i < S->n; i++)
        for (k = S->rs[i]; k < S->rs[i + 1]; k++) {
            size_t col = (size_t)S->cols[k], r, c;
            const double *blk = dl->jac + k * bb;
            for (r = 0; r < S->b; r++)
                for (c = 0; c < S->b; c++) dl->cn[col * S->b + c] += blk[r * S->b + c] * blk[r * S->b + c];
        }
    dl->ginf = 0.0;
    for (j = 0; j < N; j++) {
        dl->cn[j] = PLATEAU_SQRT(dl->cn[j]);
        if (PLATEAU_FABS(dl->g[j]) > dl->ginf) dl->ginf = PLATEAU_FABS(dl->g[j]);
    }
    fnorm = PLATEAU_SQRT(2.0 * dl->F);
    for (j = 0; j < N; j++)
        if (dl->cn[j] > 0.0) {
            double cs = PLATEAU_FABS(dl->g[j]) / (dl->cn[j] * fnorm);
            if (cs > cmax) cmax = cs;
        }
    if (dl->ginf == 0.0 || cmax <= dl->o.eps_grad) dl->stop = PLATEAU_LM_STOP_GRADIENT;
    return PLATEAU_LM_OK;
}

/* The LU of the Jacobian at x: 1 when it holds; 0 when a pivot fails, or
 * when options.cancel abandoned it (dl->cancelled: the solve ends). */
static int plateau__lm_dl_factor(plateau__lm_dl *dl)
{
    plateau_lm_result r = plateau_lm_sparse_factorize(dl->Fac, dl->jac, 0.0);
    if (r == PLATEAU_LM_ERR_ABORTED) dl->cancelled = 1;
    return r == PLATEAU_LM_OK;
}

/* The LU of the Jacobian at x and h_gn = -J^-1 f from it (dl->gn_ok = 0
 * when a pivot fails or h_gn is not finite). */
static void plateau__lm_dl_fresh_lu(plateau__lm_dl *dl)
{
    size_t j;
    dl->gn_ok = plateau__lm_dl_factor(dl);
    dl->fresh = 1;
    if (!dl->gn_ok) return;
    for (j = 0; j < dl->N; j++) dl->hgn[j] = -dl->f[j];
    (void)plateau_lm_sparse_solve(dl->Fac, 1, dl->hgn, dl->N);
    dl->gn_ok = plateau__lm_all_finite(dl->hgn, dl->N);
}

/* The Gauss-Newton step h_gn at a new point: from a new LU (refactor, or
 * no usable LU), or by GMRES(8) preconditioned with the kept LU (Kelley's
 * Newton-GMRES: an inexact Newton step).  GMRES leaving the relative
 * residual above PLATEAU__LM_KRYLOV_POOR: a new LU at once; above
 * PLATEAU__LM_KRYLOV_GIVEUP: the step is tried, and a new LU next time.
 * Then J g for the Cauchy step. */
static void plateau__lm_dl_gauss_newton(plateau__lm_dl *dl)
{
    size_t N = dl->N, j;
    int kept = 0;
    if (dl->refactor || !dl->gn_ok) {
        dl->gn_ok = plateau__lm_dl_factor(dl);
        dl->fresh = 1;
    } else {
        dl->fresh = 0;
        kept = 1;
    }
    dl->refactor = 0;
    dl->krylov_rr = PLATEAU__LM_HUGE;
    if (dl->gn_ok && kept) {
        double rr;
        plateau__lm_lu_to_single(dl->Fac); /* a preconditioner from now on */
        rr = plateau__lm_gmres(dl->S, dl->Fac, dl->jac, dl->f, dl->hgn, dl->kv, dl->h,
                                      dl->khs, PLATEAU__LM_KRYLOV_DIM);
        dl->krylov_rr = rr;
        if (!(rr <= PLATEAU__LM_KRYLOV_POOR)) {
            /* the kept LU no longer preconditions J: a new one */
            dl->gn_ok = plateau__lm_dl_factor(dl);
            dl->fresh = 1;
        } else if (!(rr <= PLATEAU__LM_KRYLOV_GIVEUP)) {
            /* a poor but usable step (it may end the solve by the step
             * test, and the dog leg checks it); a new LU next time */
            dl->refactor = 1;
        }
    }
    if (dl->gn_ok && dl->fresh) {
        for (j = 0; j < N; j++) dl->hgn[j] = -dl->f[j];
        (void)plateau_lm_sparse_solve(dl->Fac, 1, dl->hgn, N);
    }
    if (dl->gn_ok) dl->gn_ok = plateau__lm_all_finite(dl->hgn, N);
    /* J g of g / ||g||_inf (h is free here): ||g||^2 and ||J g||^2 overflow
     * for residuals near 1e150 (uniform weights 1e300), their ratio does not */
    for (j = 0; j < N; j++) dl->h[j] = dl->ginf > 0.0 ? dl->g[j] / dl->ginf : dl->g[j];
    plateau__lm_bmatvec(dl->S, dl->jac, dl->h, dl->jg, 0);
}

/* MNT 3.21's step for the radius Delta into dl->h, its length into dl->hn;
 * returns the model's decrease L(0) - L(h).  With alpha = ||g||^2 /
 * ||J g||^2 (formed from g / ||g||_inf, and ||g||^2 as ||g|| times ||g||,
 * so that no square of the residual's scale is formed): h_gn when ||h_gn|| <= Delta (*gn_step = 1); the Cauchy step
 * -alpha g, or -Delta g / ||g|| when that is shorter, when h_gn is not
 * usable or ||alpha g|| >= Delta; else the dog leg a + beta (h_gn - a),
 * a = -alpha g, with beta such that ||h|| = Delta.  A step that uses an
 * h_gn from the kept LU (*chord = 1) solves J h = -f only approximately,
 * so its decrease is evaluated: -h^T g - 1/2 ||J h||^2 (MNT eq. 3.7b). */
static double plateau__lm_dl_dogleg(plateau__lm_dl *dl, int *gn_step, int *chord)
{
    size_t N = dl->N, j;
    const double *g = dl->g, *hgn = dl->hgn;
    double *h = dl->h, delta = dl->delta, F = dl->F;
    double gs = dl->ginf > 0.0 ? dl->ginf : 1.0, u2 = 0.0, jg2 = plateau__lm_dot(dl->jg, dl->jg, N);
    double alpha, gnorm, pred, hgn2;
    for (j = 0; j < N; j++) u2 += (g[j] / gs) * (g[j] / gs);
    alpha = u2 / jg2; /* ||g||^2 / ||J g||^2: the factors gs^2 cancel */
    gnorm = gs * PLATEAU_SQRT(u2);
    *gn_step = 0;
    hgn2 = dl->gn_ok ? plateau__lm_dot(hgn, hgn, N) : PLATEAU__LM_HUGE;
    if (dl->gn_ok && PLATEAU_SQRT(hgn2) <= delta) {
        for (j = 0; j < N; j++) h[j] = hgn[j];
        pred = F;
        *gn_step = 1;
    } else if (!dl->gn_ok || alpha * gnorm >= delta) {
        /* the steepest-descent step, to the Cauchy point or the boundary */
        double t = alpha * gnorm <= delta ? alpha : delta / gnorm;
        for (j = 0; j < N; j++) h[j] = -t * g[j];
        pred = t == alpha ? 0.5 * (alpha * gnorm) * gnorm : delta * (2.0 * alpha * gnorm - delta) / (2.0 * alpha);
    } else {
        /* a = -alpha g, b = h_gn, h = a + beta (b - a) with ||h|| = Delta */
        double a2 = (alpha * gnorm) * (alpha * gnorm), c = 0.0, bma2 = 0.0, d2 = delta * delta, beta, disc;
        for (j = 0; j < N; j++) {
            double aj = -alpha * g[j], dj = hgn[j] - aj;
            c += aj * dj;
            bma2 += dj * dj;
        }
        disc = PLATEAU_SQRT(c * c + bma2 * (d2 - a2));
        beta = c <= 0.0 ? (disc - c) / bma2 : (d2 - a2) / (c + disc);
        for (j = 0; j < N; j++) h[j] = -alpha * g[j] + beta * (hgn[j] + alpha * g[j]);
        pred = 0.5 * (alpha * gnorm) * gnorm * (1.0 - beta) * (1.0 - beta) + beta * (2.0 - beta) * F;
    }
    *chord = dl->gn_ok && !dl->fresh && (*gn_step || alpha * gnorm < delta);
    if (*chord) {
        plateau__lm_bmatvec(dl->S, dl->jac, h, dl->jh, 0);
        pred = -plateau__lm_dot(h, g, N) - 0.5 * plateau__lm_dot(dl->jh, dl->jh, N);
    }
    dl->hn = PLATEAU_SQRT(plateau__lm_dot(h, h, N));
    dl->xn = PLATEAU_SQRT(plateau__lm_dot(dl->x, dl->x, N));
    return pred;
}

/* After the trial point x + h with F(x + h) = Fnew and gain ratio rho: the
 * trust-region update (rho > 3/4: Delta := max(Delta, 3 ||h||); rho < 1/4:
 * Delta := Delta / 2), acceptance (rho > 0) with the F-change test, and
 * the kept LU's bookkeeping.  Factorisation reuse (Kelley, "Solving
 * nonlinear equations with Newton's method": the chord method,
 * Newton-GMRES): after a full Gauss-Newton step with rho > 3/4 that cut F
 * to at most PLATEAU__LM_CHORD_RATE F, the next iterations keep the LU as
 * GMRES's preconditioner.  A step on it that the model does not predict
 * well (rho < 1/4), or that cuts F by less, marks the LU stale: Delta is
 * left alone (the direction was at fault, not the radius), and the LU is
 * taken anew, at once if the step is rejected.  The F-change test counts
 * only steps from a fresh LU.  Returns 1 when the step was accepted. */
static int plateau__lm_dl_update(plateau__lm_dl *dl, double Fnew, double pred, double rho,
                                 int gn_step, int chord)
{
    const plateau_lm_options *o = &dl->o;
    double F = dl->F, hn = dl->hn;
    if (chord && !(rho >= 0.25 && Fnew <= PLATEAU__LM_CHORD_RATE * F)) {
        dl->refactor = 1;
    } else if (rho > 0.75) {
        if (3.0 * hn > dl->delta) dl->delta = 3.0 * hn;
    } else if (rho < 0.25) {
        dl->delta *= 0.5;
    }
    if (!chord && !(gn_step && rho > 0.75 && Fnew <= PLATEAU__LM_CHORD_RATE * F && o->chord == 0))
        dl->refactor = 1;
    dl->chord_ready = o->chord > 0 && rho > 0.0 && gn_step && dl->fresh && !chord &&
                      Fnew <= PLATEAU__LM_CHORD_START * F;
    if (rho > 0.0) {
        double Fold = F, *t;
        size_t j;
        for (j = 0; j < dl->N; j++) dl->x[j] = dl->xnew[j];
        t = dl->f; dl->f = dl->fnew; dl->fnew = t;
        dl->Fold = F;
        dl->F = Fnew;
        /* F-change test on accepted steps (as the dense LM) */
        if (Fold - Fnew <= o->eps_f * Fold && pred <= o->eps_f * Fold) {
            if (chord) {
                dl->refactor = 1;
            } else {
                dl->small_changes++;
                if (gn_step || dl->small_changes >= PLATEAU_LM_SMALL_CHANGES)
                    dl->stop = PLATEAU_LM_STOP_F_CHANGE;
            }
        } else {
            dl->small_changes = 0;
        }
        return 1;
    }
    if (chord) {
        /* rejected step on the kept LU: the LU of the Jacobian at x, h_gn anew */
        plateau__lm_dl_fresh_lu(dl);
        dl->refactor = 0;
    } else if (dl->delta <= o->eps_step * dl->xn + dl->step_floor) {
        dl->stop = PLATEAU_LM_STOP_STEP;
    }
    return 0;
}

/* The tail (options->tail_f_stop): at a STEP stop above it, within
 * max_iterations, the state a second run from x would reach before its
 * first step (see plateau_lm_dogleg_solve), and 1; else 0.  f, the
 * Jacobian, g and J g are those at x already; the LU too when fresh,
 * else it is taken anew as that run's first one would be. */
static int plateau__lm_dl_tail_due(const plateau__lm_dl *dl)
{
    return dl->o.tail_f_stop > 0.0 && dl->stop == PLATEAU_LM_STOP_STEP && dl->F > dl->o.tail_f_stop &&
           dl->o.max_iterations - dl->iter > 0 && !(dl->finite_trials == 0 && dl->nonfinite_trials > 0);
}

/* The tail's options and state (see plateau_lm_dogleg_solve), once
 * plateau__lm_dl_tail_due holds. */
static void plateau__lm_dl_tail_start(plateau__lm_dl *dl)
{
    double xn, ts = dl->o.tail_f_stop;
    int left = dl->o.max_iterations - dl->iter;
    dl->o.tail_f_stop = 0.0; /* one tail */
    dl->tailing = 1;
    dl->o.max_iterations = dl->iter + (left < dl->o.tail_iterations ? left : dl->o.tail_iterations);
    dl->o.eps_step = DBL_EPSILON;
    dl->f_stop = dl->o.f_stop = ts;
    xn = PLATEAU_SQRT(plateau__lm_dot(dl->x, dl->x, dl->N));
    dl->delta = xn > 1.0 ? xn : 1.0;
    dl->step_floor = dl->o.eps_step * dl->o.eps_step * (xn < 1.0 ? xn : 1.0);
    dl->small_changes = 0;
    dl->finite_trials = dl->nonfinite_trials = 0;
    dl->stop = PLATEAU_LM_STOP_NONE;
}

static int plateau__lm_dl_tail(plateau__lm_dl *dl)
{
    double ts = dl->o.tail_f_stop;
    if (!plateau__lm_dl_tail_due(dl)) return 0;
    plateau__lm_dl_tail_start(dl);
    /* a new LU first, unless the step the step test refused is an inexact
     * Newton step that should end the tail by itself: GMRES on the kept LU
     * left the relative residual rr with rr^2 F at most tail_f_stop (to
     * first order F(x + h) = rr^2 F: Kelley's Newton-GMRES; at 10^5 nodes
     * an LU costs 2 s); it is tried first, checked by the dog leg as every
     * step on the kept LU is */
    if (!dl->fresh && !(dl->gn_ok && dl->krylov_rr * dl->krylov_rr * dl->F <= ts)) {
        dl->refactor = 1;
        plateau__lm_dl_gauss_newton(dl);
    }
    dl->refactor = 0;
    return 1;
}

/* After an accepted step, 1 when the next iteration's step would be
 * refused by the step test and no tail would follow, known without the
 * Jacobian there (at 10^5 nodes a Jacobian and GMRES take seconds, and
 * every round of plateau's rounds used to end so): at quadratic
 * convergence ||h_next|| is about ||h|| (F / Fold)^(1/2) (the
 * Gauss-Newton step scales with f); when that is below the step test's
 * bound, the chord step -M^-1 f with the LU M at hand (Kelley's chord
 * method; the Jacobian at x differs from M's by O(||h||)) measures
 * ||h_next||, and a chord step below an eighth of the bound ends the
 * solve as that iteration would: iter counted, x and F unchanged, STEP
 * (every step the dog leg takes is at most ||h_gn|| long). */
static int plateau__lm_dl_spent(plateau__lm_dl *dl)
{
    size_t N = dl->N, j;
    double bound, hc;
    if (dl->iter == 0 || !dl->gn_ok || dl->iter >= dl->o.max_iterations || !(dl->F > dl->f_stop) ||
        (dl->o.tail_f_stop > 0.0 && dl->F > dl->o.tail_f_stop) || !(dl->Fold > 0.0))
        return 0;
    dl->xn = PLATEAU_SQRT(plateau__lm_dot(dl->x, dl->x, N));
    bound = dl->o.eps_step * dl->xn + dl->step_floor;
    if (!(dl->hn * PLATEAU_SQRT(dl->F / dl->Fold) <= bound)) return 0;
    for (j = 0; j < N; j++) dl->h[j] = -dl->f[j];
    (void)plateau_lm_sparse_solve(dl->Fac, 1, dl->h, N);
    hc = PLATEAU_SQRT(plateau__lm_dot(dl->h, dl->h, N));
    if (!(hc <= 0.125 * bound)) return 0;
    dl->iter++;
    dl->hn = hc;
    dl->stop = PLATEAU_LM_STOP_STEP;
    return 1;
}

/* The trial point x + h of a step (dog leg or chord): its residual into
 * dl->fnew and *Fnew = F(x + h), or PLATEAU__LM_HUGE when x + h is not
 * finite (no evaluation); nonzero when the user's function aborts. */
static int plateau__lm_dl_trial(plateau__lm_dl *dl, double *Fnew)
{
    size_t N = dl->N, j;
    for (j = 0; j < N; j++) dl->xnew[j] = dl->x[j] + dl->h[j];
    *Fnew = PLATEAU__LM_HUGE;
    if (!plateau__lm_all_finite(dl->xnew, N)) return 0;
    dl->revals++;
    if (dl->func(dl->xnew, dl->fnew, NULL, dl->user) != 0) return 1;
    *Fnew = plateau__lm_half_sumsq(dl->fnew, N);
    if (plateau__lm_finite(*Fnew)) dl->finite_trials++;
    else dl->nonfinite_trials++;
    return 0;
}

/* options.chord > 0: Kelley's chord method in Shamanskii's manner ("Solving
 * nonlinear equations with Newton's method", 1.8 and 5.4) after a Newton
 * step in the quadratic regime (dl->chord_ready): steps h = -M^-1 f(x) on
 * the LU M of the last Jacobian, with no Jacobian at x (at 10^5 nodes a
 * Jacobian and its LU cost as much as six such steps).  Near a root a
 * chord step cuts ||f|| by about K ||x - x_M|| (x_M: M's point), the
 * factor by which the Newton step from x_M cut it, so each chord step cuts
 * F about as much as that Newton step did.  Each is a trial as the dog
 * leg's are (an iteration, a residual, the progress callback), within the
 * trust radius; accepted when it lowers F, and they go on while each cuts
 * F to at most CHORD_KEEP F.  The step test applies to the chord step:
 * one no longer than eps_step ||x|| + floor ends the solve on STEP, or,
 * when a tail is due (plateau__lm_dl_tail_due), starts the tail and the
 * chord steps go on under its bound.  Then the dog leg goes on from the
 * point reached with a new Jacobian and LU. */
static plateau_lm_result plateau__lm_dl_chords(plateau__lm_dl *dl)
{
    size_t N = dl->N, j;
    int have = 0;
    if (!dl->chord_ready) return PLATEAU_LM_OK;
    dl->chord_ready = 0;
    while (dl->gn_ok && dl->F > dl->f_stop && dl->iter < dl->o.max_iterations) {
        double F = dl->F, Fnew = PLATEAU__LM_HUGE;
        int accepted;
        if (!have) {
            for (j = 0; j < N; j++) dl->h[j] = -dl->f[j];
            (void)plateau_lm_sparse_solve(dl->Fac, 1, dl->h, N);
            dl->hn = PLATEAU_SQRT(plateau__lm_dot(dl->h, dl->h, N));
            dl->xn = PLATEAU_SQRT(plateau__lm_dot(dl->x, dl->x, N));
            have = 1;
        }
        if (!plateau__lm_finite(dl->hn) || dl->hn > dl->delta) return PLATEAU_LM_OK;
        if (dl->hn <= dl->o.eps_step * dl->xn + dl->step_floor) {
            dl->iter++;
            dl->stop = PLATEAU_LM_STOP_STEP;
            if (!plateau__lm_dl_tail_due(dl)) return PLATEAU_LM_OK;
            plateau__lm_dl_tail_start(dl); /* the same step, under the tail's bound */
            continue;
        }
        have = 0;
        dl->iter++;
        /* in the tail, tail_iterations bounds its dog-leg steps; chord
         * steps, each cutting F 100-fold or ending the run, only the
         * caller's max_iterations */
        if (dl->tailing && dl->o.max_iterations < dl->max_user) dl->o.max_iterations++;
        if (plateau__lm_dl_trial(dl, &Fnew) != 0) return PLATEAU_LM_ERR_ABORTED;
        accepted = plateau__lm_finite(Fnew) && Fnew < F;
        if (accepted) {
            double *t = dl->f;
            for (j = 0; j < N; j++) dl->x[j] = dl->xnew[j];
            dl->f = dl->fnew;
            dl->fnew = t;
            dl->Fold = F;
            dl->F = Fnew;
        }
        if (dl->o.progress &&
            dl->o.progress(dl->iter, dl->F, dl->ginf, dl->delta, accepted, dl->user) != 0)
            return PLATEAU_LM_ERR_ABORTED;
        if (!accepted || !(Fnew <= PLATEAU__LM_CHORD_KEEP * F)) return PLATEAU_LM_OK;
    }
    return PLATEAU_LM_OK;
}

/* MNT 3.21's inner loop at one Jacobian: steps until one is accepted or a
 * stopping rule fires (MAX_ITERATIONS, or STEP when ||h|| <= eps_step
 * (||x|| + floor)). */
static plateau_lm_result plateau__lm_dl_steps(plateau__lm_dl *dl)
{
    for (;;) {
        double pred, Fnew, rho;
        int gn_step, chord, accepted;
        if (dl->iter >= dl->o.max_iterations) {
            dl->stop = PLATEAU_LM_STOP_MAX_ITERATIONS;
            return PLATEAU_LM_OK;
        }
        dl->iter++;
        pred = plateau__lm_dl_dogleg(dl, &gn_step, &chord);
        if (dl->hn <= dl->o.eps_step * dl->xn + dl->step_floor) {
            dl->stop = PLATEAU_LM_STOP_STEP;
            return PLATEAU_LM_OK;
        }
        if (plateau__lm_dl_trial(dl, &Fnew) != 0) return PLATEAU_LM_ERR_ABORTED;
        rho = (plateau__lm_finite(Fnew) && pred > 0.0) ? (dl->F - Fnew) / pred : -1.0;
        accepted = plateau__lm_dl_update(dl, Fnew, pred, rho, gn_step, chord);
        if (dl->cancelled) return PLATEAU_LM_ERR_ABORTED;
        if (dl->o.progress &&
            dl->o.progress(dl->iter, dl->F, dl->ginf, dl->delta, accepted, dl->user) != 0)
            return PLATEAU_LM_ERR_ABORTED;
        if (accepted || dl->stop != PLATEAU_LM_STOP_NONE) return PLATEAU_LM_OK;
    }
}

/* The keep for a solve with the resolved allocator a: *keep, made when
 * NULL; ARGUMENT when it was made with another allocator. */
static plateau_lm_result plateau__lm_keep_open(plateau_lm_dogleg_keep **keep, const plateau_allocator *a,
                                               plateau_lm_dogleg_keep **out)
{
    plateau_lm_dogleg_keep *k = *keep;
    *out = NULL;
    if (!k) {
        k = (plateau_lm_dogleg_keep *)plateau__alloc(a, sizeof *k);
        if (!k) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
        k->alloc = *a;
        k->block[0] = k->block[1] = NULL;
        k->bytes[0] = k->bytes[1] = 0;
        *keep = k;
    } else if (k->alloc.alloc_fn != a->alloc_fn || k->alloc.free_fn != a->free_fn ||
               k->alloc.user_data != a->user_data) {
        return PLATEAU_LM_ERR_ARGUMENT;
    }
    *out = k;
    return PLATEAU_LM_OK;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve(const plateau_lm_sparse_pattern *pattern,
                                                         const double *xy, double *x,
                                                         plateau_lm_sparse_func func, void *user,
                                                         const plateau_lm_options *options,
                                                         plateau_lm_report *report)
{
    return plateau_lm_dogleg_solve_kept(pattern, xy, x, func, user, options, report, NULL);
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve_kept(const plateau_lm_sparse_pattern *pattern,
                                                              const double *xy, double *x,
                                                              plateau_lm_sparse_func func, void *user,
                                                              const plateau_lm_options *options,
                                                              plateau_lm_report *report,
                                                              plateau_lm_dogleg_keep **keep)
{
    plateau__lm_dl dl;
    plateau_lm_result res;
    double xn;
    dl.S = NULL;
    dl.Fac = NULL;
    dl.keep = NULL;
    dl.mem = NULL;
    dl.x = x;
    dl.func = func;
    dl.user = user;
    dl.o = plateau_lm_resolved_options(NULL);
    dl.F = dl.F0 = dl.Fold = dl.ginf = dl.delta = 0.0;
    dl.iter = dl.revals = dl.jevals = dl.gn_ok = dl.small_changes = dl.fresh = dl.cancelled = 0;
    dl.chord_ready = dl.tailing = dl.max_user = 0;
    dl.finite_trials = dl.nonfinite_trials = 0;
    dl.refactor = 1;
    dl.krylov_rr = PLATEAU__LM_HUGE;
    dl.stop = PLATEAU_LM_STOP_NONE;
    if (report) {
        report->iterations = report->residual_evaluations = report->jacobian_evaluations = 0;
        report->f_initial = report->f_final = report->grad_inf = report->mu_final = 0.0;
        report->stop = PLATEAU_LM_STOP_ERROR;
    }
    if (!pattern || !x || !func) return PLATEAU_LM_ERR_ARGUMENT;
    if (keep) {
        plateau_lm_options ro = plateau_lm_resolved_options(options);
        res = plateau__lm_keep_open(keep, &ro.allocator, &dl.keep);
        if (res != PLATEAU_LM_OK) return res;
    }
    res = plateau__lm_dl_setup(&dl, pattern, xy, options);
    if (res != PLATEAU_LM_OK) goto finish;
    dl.max_user = dl.o.max_iterations;
    /* MNT 3.21, initialisation: x := x0; Delta := Delta0 = max(||x0||, 1);
     * g := J^T f; found := tests */
    dl.revals++;
    if (func(x, dl.f, NULL, user) != 0) { res = PLATEAU_LM_ERR_ABORTED; goto finish; }
    dl.F = dl.F0 = plateau__lm_half_sumsq(dl.f, dl.N);
    if (!plateau__lm_finite(dl.F)) { res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL; goto finish; }
    dl.f_stop = dl.o.f_stop != 0.0 ? dl.o.f_stop
                                   : DBL_EPSILON * DBL_EPSILON * (dl.F0 < 1.0 ? dl.F0 : 1.0);
    xn = PLATEAU_SQRT(plateau__lm_dot(x, x, dl.N));
    dl.delta = xn > 1.0 ? xn : 1.0;
    dl.step_floor = dl.o.eps_step * dl.o.eps_step * (xn < 1.0 ? xn : 1.0);
    while (res == PLATEAU_LM_OK && dl.stop == PLATEAU_LM_STOP_NONE) {
        res = plateau__lm_dl_chords(&dl);
        if (res != PLATEAU_LM_OK || dl.stop != PLATEAU_LM_STOP_NONE) break;
        if (plateau__lm_dl_spent(&dl)) break;
        res = plateau__lm_dl_jacobian(&dl);
        if (res != PLATEAU_LM_OK || dl.stop != PLATEAU_LM_STOP_NONE) break;
        plateau__lm_dl_gauss_newton(&dl);
        if (dl.cancelled) { /* options.cancel: x is the last accepted point */
            res = PLATEAU_LM_ERR_ABORTED;
            break;
        }
        res = plateau__lm_dl_steps(&dl);
        while (res == PLATEAU_LM_OK && plateau__lm_dl_tail(&dl))
            res = dl.cancelled ? PLATEAU_LM_ERR_ABORTED : plateau__lm_dl_steps(&dl);
    }
    if (dl.stop == PLATEAU_LM_STOP_F_CHANGE && dl.F <= dl.f_stop) dl.stop = PLATEAU_LM_STOP_SMALL_F;
    /* f not finite at any trial point tried, as in plateau_lm_solve: the
     * step test says nothing about a minimum, the residual is broken
     * around x0 */
    if (res == PLATEAU_LM_OK && dl.stop == PLATEAU_LM_STOP_STEP && dl.finite_trials == 0 && dl.nonfinite_trials > 0)
        res = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
finish:
    if (report) {
        report->iterations = (size_t)dl.iter;
        report->residual_evaluations = (size_t)dl.revals;
        report->jacobian_evaluations = (size_t)dl.jevals;
        report->f_initial = dl.F0;
        report->f_final = dl.F;
        report->grad_inf = dl.ginf;
        report->mu_final = res == PLATEAU_LM_OK ? dl.delta : 0.0;
        report->stop = res == PLATEAU_LM_OK ? dl.stop
                       : res == PLATEAU_LM_ERR_ABORTED ? PLATEAU_LM_STOP_ABORTED
                                                       : PLATEAU_LM_STOP_ERROR;
    }
    if (!dl.keep) plateau__free(&dl.o.allocator, dl.mem); /* a kept block stays */
    plateau_lm_sparse_factor_free(dl.Fac);
    plateau_lm_sparse_symbolic_free(dl.S);
    return res;
}

#else /* PLATEAU_LM_NO_SPARSE: the sparse calls refuse (PLATEAU_LM_ERR_ARGUMENT) */
PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_analyze(const plateau_lm_sparse_pattern *pattern,
                                                           const double *xy,
                                                           const plateau_lm_sparse_options *options,
                                                           plateau_lm_sparse_symbolic **symbolic)
{
    (void)pattern, (void)xy, (void)options;
    if (symbolic) *symbolic = NULL;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF void plateau_lm_sparse_symbolic_free(plateau_lm_sparse_symbolic *symbolic)
{
    (void)symbolic;
}

PLATEAU_LM_DEF plateau_lm_sparse_info plateau_lm_sparse_symbolic_info(const plateau_lm_sparse_symbolic *symbolic)
{
    plateau_lm_sparse_info info;
    unsigned char *b = (unsigned char *)&info;
    size_t i;
    (void)symbolic;
    for (i = 0; i < sizeof info; i++) b[i] = 0; /* all counts 0: nothing analysed */
    return info;
}

PLATEAU_LM_DEF const plateau_index *plateau_lm_sparse_permutation(const plateau_lm_sparse_symbolic *symbolic)
{
    (void)symbolic;
    return NULL;
}

PLATEAU_LM_DEF size_t plateau_lm_sparse_factor_size(const plateau_lm_sparse_symbolic *symbolic, int kind)
{
    (void)symbolic, (void)kind;
    return 0;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factor_create(const plateau_lm_sparse_symbolic *symbolic,
                                                                 int kind, void *work, size_t work_bytes,
                                                                 plateau_lm_sparse_factor **factor)
{
    (void)symbolic, (void)kind, (void)work, (void)work_bytes;
    if (factor) *factor = NULL;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF void plateau_lm_sparse_factor_free(plateau_lm_sparse_factor *factor)
{
    (void)factor;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_factorize(plateau_lm_sparse_factor *factor,
                                                             const double *values, double shift)
{
    (void)factor, (void)values, (void)shift;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF plateau_index plateau_lm_sparse_failed_node(const plateau_lm_sparse_factor *factor)
{
    (void)factor;
    return -1;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_inertia(const plateau_lm_sparse_factor *factor,
                                                           size_t *negative, size_t *positive)
{
    (void)factor;
    if (negative) *negative = 0;
    if (positive) *positive = 0;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_sparse_solve(plateau_lm_sparse_factor *factor,
                                                         size_t nrhs, double *b, size_t ldb)
{
    (void)factor, (void)nrhs, (void)b, (void)ldb;
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve(const plateau_lm_sparse_pattern *pattern,
                                                         const double *xy, double *x,
                                                         plateau_lm_sparse_func func, void *user,
                                                         const plateau_lm_options *options,
                                                         plateau_lm_report *report)
{
    (void)pattern, (void)xy, (void)x, (void)func, (void)user, (void)options;
    if (report) {
        report->iterations = report->residual_evaluations = report->jacobian_evaluations = 0;
        report->f_initial = report->f_final = report->grad_inf = report->mu_final = 0.0;
        report->stop = PLATEAU_LM_STOP_ERROR;
    }
    return PLATEAU_LM_ERR_ARGUMENT;
}

PLATEAU_LM_DEF plateau_lm_result plateau_lm_dogleg_solve_kept(const plateau_lm_sparse_pattern *pattern,
                                                              const double *xy, double *x,
                                                              plateau_lm_sparse_func func, void *user,
                                                              const plateau_lm_options *options,
                                                              plateau_lm_report *report,
                                                              plateau_lm_dogleg_keep **keep)
{
    (void)keep;
    return plateau_lm_dogleg_solve(pattern, xy, x, func, user, options, report);
}

PLATEAU_LM_DEF size_t plateau_lm_dogleg_keep_bytes(const plateau_lm_dogleg_keep *keep)
{
    (void)keep;
    return 0;
}

PLATEAU_LM_DEF void plateau_lm_dogleg_keep_free(plateau_lm_dogleg_keep *keep)
{
    (void)keep;
}
#endif /* PLATEAU_LM_NO_SPARSE */

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
