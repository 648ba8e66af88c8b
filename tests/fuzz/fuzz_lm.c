/* fuzz_lm.c - libFuzzer target for plateau_lm_solve.
 *
 * Bytes: [m] [n] [flags] [fail/abort] [tau] [eps] then coefficients, the
 * start, and [features] last (past the end: 0).
 *   m, n      1 + byte modulo 6 residuals and unknowns (m < n happens)
 *   flags     bit 0 numeric Jacobian; bit 1 scaling NONE; bit 2 the residual
 *             returns NaN at call (fail/abort + 1); bit 3 the residual asks
 *             to stop at that call; bit 4 refuse the (only) allocation;
 *             bits 5-7 max_iterations = 1 + 7 * value
 *   tau, eps  0 (the defaults) or 10^(-12 .. 3) / 10^(-15 .. 0)
 *   then per residual i: a constant, linear and quadratic coefficients (one
 *   signed byte each, / 8) of f_i(x) = c_i + sum_j a_ij x_j + b_i x_(i mod n)^2
 *   + d_i x_0 x_(n-1), and the start x (one signed byte each, / 4)
 *   features  bits 0-1 geodesic acceleration AUTO, ALWAYS, NEVER (3: AUTO);
 *             bit 2 the box -2 <= x_j <= 2; bit 3 the inequality
 *             x_0 - x_(n-1) >= -1; bit 4 the equality sum x_j = 0.5
 * Checked: the result is a named code; on every return x is finite; after
 * a successful solve x satisfies the box, and the inequality and the
 * equality to 1e-9 of their terms; a refused allocation gives
 * PLATEAU_LM_ERR_OUT_OF_MEMORY with x untouched; a stop request gives
 * PLATEAU_LM_ERR_ABORTED; a NaN from the start gives
 * PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL; the same solve in a caller workspace
 * gives bit for bit the same x and report; nothing leaks. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_LM_IMPLEMENTATION
#endif
#include "plateau_lm.h"
#include <math.h>
#include "countalloc.h"
#include "fuzz_common.h"

#define FUZZ_MAX_DIM 6

typedef struct problem {
    size_t m, n;
    double c[FUZZ_MAX_DIM], a[FUZZ_MAX_DIM][FUZZ_MAX_DIM], b[FUZZ_MAX_DIM], d[FUZZ_MAX_DIM];
    long calls, event_call;
    int nan_at_event, abort_at_event;
    int aborted, nan_given;
} problem;

static int residual(const double *x, double *f, double *jac, void *user)
{
    problem *p = (problem *)user;
    size_t i, j, n = p->n;
    p->calls++;
    for (i = 0; i < p->m; i++) {
        double v = p->c[i] + p->b[i] * x[i % n] * x[i % n] + p->d[i] * x[0] * x[n - 1];
        for (j = 0; j < n; j++) v += p->a[i][j] * x[j];
        f[i] = v;
        if (jac) {
            for (j = 0; j < n; j++) jac[i * n + j] = p->a[i][j];
            jac[i * n + i % n] += 2.0 * p->b[i] * x[i % n];
            jac[i * n] += p->d[i] * x[n - 1];
            jac[i * n + n - 1] += p->d[i] * x[0];
        }
    }
    if (p->calls == p->event_call) {
        if (p->abort_at_event) {
            p->aborted = 1;
            return 1;
        }
        if (p->nan_at_event) {
            f[0] = NAN;
            p->nan_given = 1;
        }
    }
    return 0;
}

static int finite_all(const double *x, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!(x[i] == x[i] && x[i] - x[i] == 0.0)) return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes bb;
    problem p, p2;
    uint8_t flags, ev, tau_b, eps_b, feat;
    static const double lo[FUZZ_MAX_DIM] = {-2, -2, -2, -2, -2, -2}, up[FUZZ_MAX_DIM] = {2, 2, 2, 2, 2, 2};
    static const double ones[FUZZ_MAX_DIM] = {1, 1, 1, 1, 1, 1}, half = 0.5, minus1 = -1.0;
    double crow[FUZZ_MAX_DIM];
    double x0[FUZZ_MAX_DIM], x[FUZZ_MAX_DIM], x2[FUZZ_MAX_DIM];
    size_t i, j, need;
    countalloc ca;
    plateau_lm_options opt;
    plateau_lm_report rep, rep2;
    plateau_lm_result rc, rc2;
    void *work;

    bb.data = data;
    bb.size = size;
    bb.pos = 0;
    memset(&p, 0, sizeof p);
    p.m = 1 + fuzz_u8(&bb) % FUZZ_MAX_DIM;
    p.n = 1 + fuzz_u8(&bb) % FUZZ_MAX_DIM;
    flags = fuzz_u8(&bb);
    ev = fuzz_u8(&bb);
    tau_b = fuzz_u8(&bb);
    eps_b = fuzz_u8(&bb);
    for (i = 0; i < p.m; i++) {
        p.c[i] = (double)(int8_t)fuzz_u8(&bb) / 8.0;
        for (j = 0; j < p.n; j++) p.a[i][j] = (double)(int8_t)fuzz_u8(&bb) / 8.0;
        p.b[i] = (double)(int8_t)fuzz_u8(&bb) / 8.0;
        p.d[i] = (double)(int8_t)fuzz_u8(&bb) / 8.0;
    }
    for (j = 0; j < p.n; j++) x0[j] = (double)(int8_t)fuzz_u8(&bb) / 4.0;
    feat = fuzz_u8(&bb);
    p.event_call = (flags & 12) ? (long)ev % 16 + 1 : 0;
    p.nan_at_event = (flags >> 2) & 1;
    p.abort_at_event = (flags >> 3) & 1;

    memset(&opt, 0, sizeof opt);
    opt.numeric_jacobian = flags & 1;
    opt.scaling = (flags & 2) ? PLATEAU_LM_SCALING_NONE : PLATEAU_LM_SCALING_ADAPTIVE;
    opt.max_iterations = 1 + 7 * (flags >> 5);
    if (tau_b & 1) opt.tau = pow(10.0, -12.0 + (double)((tau_b >> 1) % 16));
    if (eps_b & 1) opt.eps = pow(10.0, -15.0 + (double)((eps_b >> 1) % 16));
    opt.geodesic = (feat & 3) == 1 ? PLATEAU_LM_GEODESIC_ALWAYS
                   : (feat & 3) == 2 ? PLATEAU_LM_GEODESIC_NEVER : PLATEAU_LM_GEODESIC_AUTO;
    if (feat & 4) {
        opt.lower = lo;
        opt.upper = up;
    }
    for (j = 0; j < FUZZ_MAX_DIM; j++) crow[j] = 0.0;
    crow[0] += 1.0;
    crow[p.n - 1] -= 1.0;
    if (feat & 8) {
        opt.inequalities = 1;
        opt.c_ineq = crow;
        opt.d_ineq = &minus1;
    }
    if (feat & 16) {
        opt.constraints = 1;
        opt.a_eq = ones;
        opt.b_eq = &half;
    }
    countalloc_init(&ca, (flags & 16) ? 1 : 0);
    opt.allocator = countalloc_allocator(&ca);
    memcpy(x, x0, sizeof x);
    p2 = p;

    rc = plateau_lm_solve(p.m, p.n, x, residual, &p, &opt, NULL, 0, &rep, NULL);
    FUZZ_REQUIRE(plateau_lm_result_string(rc) != NULL);
    FUZZ_REQUIRE(finite_all(x, p.n));
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0 && countalloc_lost_context == 0);
    if (ca.refused) {
        FUZZ_REQUIRE(rc == PLATEAU_LM_ERR_OUT_OF_MEMORY);
        FUZZ_REQUIRE(memcmp(x, x0, p.n * sizeof(double)) == 0);
        return 0;
    }
    if (p.aborted) FUZZ_REQUIRE(rc == PLATEAU_LM_ERR_ABORTED);
    if (p.nan_given && p.event_call == 1) FUZZ_REQUIRE(rc == PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL);
    if (rc == PLATEAU_LM_OK) {
        double sum = 0.0, terms = 0.5;
        for (j = 0; j < p.n; j++) {
            if (feat & 4) FUZZ_REQUIRE(x[j] >= -2.0 && x[j] <= 2.0);
            sum += x[j];
            terms += fabs(x[j]);
        }
        /* the rows hold to rounding in the size of their terms (a
         * degenerate f, independent of the free parameters, lets noise in
         * J move x far along them) */
        if (feat & 8)
            FUZZ_REQUIRE(x[0] - x[p.n - 1] >= -1.0 - 1e-9 * (1.0 + fabs(x[0]) + fabs(x[p.n - 1])));
        if (feat & 16) FUZZ_REQUIRE(fabs(sum - 0.5) <= 1e-9 * terms);
        FUZZ_REQUIRE(rep.iterations <= (size_t)opt.max_iterations);
        /* REFINEMENT may trade a rise of F at rounding level (1e-10 F) for a
         * smaller gradient */
        FUZZ_REQUIRE(rep.f_final <= rep.f_initial * (1.0 + 1e-10));
        FUZZ_REQUIRE(rep.stop >= PLATEAU_LM_STOP_GRADIENT && rep.stop <= PLATEAU_LM_STOP_DAMPING);
    } else {
        FUZZ_REQUIRE((int)rc < 0);
    }

    /* the same solve in a caller workspace: no allocation, the same answer */
    need = plateau_lm_workspace_size(p.m, p.n, &opt);
    FUZZ_REQUIRE(need > 0);
    work = malloc(need);
    FUZZ_REQUIRE(work != NULL);
    countalloc_init(&ca, 0);
    memcpy(x2, x0, sizeof x2);
    rc2 = plateau_lm_solve(p2.m, p2.n, x2, residual, &p2, &opt, work, need, &rep2, NULL);
    free(work);
    FUZZ_REQUIRE(ca.calls == 0);
    FUZZ_REQUIRE(rc2 == rc);
    FUZZ_REQUIRE(memcmp(x, x2, p.n * sizeof(double)) == 0);
    FUZZ_REQUIRE(rep.iterations == rep2.iterations && rep.stop == rep2.stop);
    FUZZ_REQUIRE(memcmp(&rep.f_final, &rep2.f_final, sizeof(double)) == 0);
    return 0;
}
