/* fuzz_solve.c - libFuzzer target for plateau_solve (the whole pipeline) on
 * small polygons, and for plateau_solve_loops on two or three loops.
 *
 * Bytes: [method] [n] [flags] [fail_at] [abort_at] [seed] vertices...
 *   method   modulo 12: that modulo 3 the method (paper, paper-literal, area);
 *            / 3 odd: the quality seeding; / 6: refine_boundary;
 *            / 12 odd: several loops (plateau_solve_loops): 2 + (seed
 *            modulo 2) loops sharing the vertices evenly, the first loop
 *            taking the remainder, loop 0's count lowered by seed / 2
 *            modulo 4 for the next one (counts below 3 are errors too)
 *   n        interior points: 1 + the byte modulo 8
 *   flags    bit 0 force_circle_domain; bit 1 refuse allocation fail_at + 1;
 *            bit 2 the progress callback asks to stop at call abort_at + 1;
 *            bit 3 coordinate byte -128 means NaN; bit 4 coordinates are one
 *            signed byte / 8 (else / 2); bits 5-6 linear_solver; bit 7
 *            refine_boundary PLATEAU_OFF (kept), area_warm_start PLATEAU_ON and
 *            area_tolerance 1e-9 (else the automatic 0s)
 *   vertices three signed bytes each (x, y, z), at most 12 vertices
 * The time budget: options.max_seconds 2 + (fail_at xor abort_at) modulo
 * 16 on a clock that counts its readings (a cheap clock, and a bound on
 * the work of one input: about 1 000 inputs a second under the
 * sanitizers instead of 50).
 * Checked: on success the first m vertices are the boundary bit for bit and
 * fixed, the rest free, every position finite, triangles in range with
 * distinct corners and mutual neighbours; a refused allocation gives
 * PLATEAU_ERR_OUT_OF_MEMORY, a stop request PLATEAU_ERR_ABORTED; after
 * plateau_mesh_free the mesh is zero and every block is back. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include <math.h>
#include "countalloc.h"
#include "fuzz_common.h"

#define FUZZ_MAX_VERTICES 12

typedef struct progress_state {
    long calls;
    long abort_at; /* 0: never */
    int aborted;
} progress_state;

static int progress(int round, int iteration, double f, void *user)
{
    progress_state *ps = (progress_state *)user;
    (void)round;
    (void)iteration;
    (void)f;
    ps->calls++;
    if (ps->abort_at > 0 && ps->calls >= ps->abort_at) {
        ps->aborted = 1;
        return 1;
    }
    return 0;
}

/* options.clock_fn: one "second" per reading, so that max_seconds caps the
 * checks a run makes (every solver iteration, round, seeding refinement
 * and saddle step reads it once): a bounded, repeatable amount of work
 * per input, and the time-limit paths fuzzed too */
static double counter_clock(void *user)
{
    return (double)(*(unsigned long *)user)++;
}

static int is_finite(double x)
{
    return x == x && x - x == 0.0;
}

/* nfixed: m plus the vertices the quality seeding added on the polygon's
 * edges (refine_boundary), which follow it */
static void check_mesh(const plateau_mesh *mesh, const double *xyz, size_t m, size_t nfixed)
{
    size_t i, t;
    int k;
    FUZZ_REQUIRE(mesh->num_vertices >= m);
    FUZZ_REQUIRE(mesh->positions != NULL && mesh->fixed != NULL);
    FUZZ_REQUIRE(mesh->num_triangles >= 1 && mesh->triangles != NULL);
    for (i = 0; i < 3 * m; i++) FUZZ_REQUIRE(mesh->positions[i] == xyz[i]);
    for (i = 0; i < mesh->num_vertices; i++) {
        FUZZ_REQUIRE(mesh->fixed[i] == (i < nfixed ? 1 : 0));
        for (k = 0; k < 3; k++) FUZZ_REQUIRE(is_finite(mesh->positions[3 * i + k]));
    }
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *v = mesh->triangles + 3 * t;
        FUZZ_REQUIRE(v[0] != v[1] && v[1] != v[2] && v[0] != v[2]);
        for (k = 0; k < 3; k++) {
            plateau_index a = v[k], b = v[(k + 1) % 3];
            FUZZ_REQUIRE(a >= 0 && (size_t)a < mesh->num_vertices);
            if (mesh->neighbors) {
                plateau_index u = mesh->neighbors[3 * t + k];
                if (u >= 0) {
                    int j, back = -1;
                    FUZZ_REQUIRE((size_t)u < mesh->num_triangles);
                    for (j = 0; j < 3; j++)
                        if (mesh->triangles[3 * u + j] == b &&
                            mesh->triangles[3 * u + (j + 1) % 3] == a)
                            back = j;
                    FUZZ_REQUIRE(back >= 0 && mesh->neighbors[3 * u + back] == (plateau_index)t);
                } else {
                    FUZZ_REQUIRE(u == -1);
                }
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    double xyz[3 * FUZZ_MAX_VERTICES];
    fuzz_bytes b;
    uint8_t method, flags, fail_byte, abort_byte, raw;
    size_t m, i, counts[3], k = 1;
    int loops;
    countalloc ca;
    progress_state ps;
    unsigned long readings = 0;
    plateau_options opt;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    plateau_result rc;

    b.data = data;
    b.size = size;
    b.pos = 0;
    raw = fuzz_u8(&b);
    method = raw % 12; /* method, seeding, refine_boundary */
    loops = (raw / 12) % 2;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 1 + fuzz_u8(&b) % 8;
    flags = fuzz_u8(&b);
    fail_byte = fuzz_u8(&b);
    abort_byte = fuzz_u8(&b);
    opt.seed = fuzz_u8(&b);
    m = fuzz_left(&b) / 3;
    if (m > FUZZ_MAX_VERTICES) m = FUZZ_MAX_VERTICES;
    for (i = 0; i < 3 * m; i++) {
        int8_t c = (int8_t)fuzz_u8(&b);
        if (c == -128 && (flags & 8)) {
            xyz[i] = NAN;
        } else {
            xyz[i] = (double)c / ((flags & 16) ? 8.0 : 2.0);
        }
    }

    countalloc_init(&ca, (flags & 2) ? (long)fail_byte + 1 : 0);
    ps.calls = 0;
    ps.abort_at = (flags & 4) ? (long)abort_byte + 1 : 0;
    ps.aborted = 0;
    opt.method = (plateau_method)(method % 3);
    opt.seeding = (method / 3) % 2 ? PLATEAU_SEEDING_QUALITY : PLATEAU_SEEDING_PAPER;
    opt.refine_boundary = (flags & 128) ? PLATEAU_OFF : method / 6 ? PLATEAU_ON : PLATEAU_AUTO;
    opt.area_warm_start = (flags & 128) ? PLATEAU_ON : PLATEAU_AUTO;
    opt.area_tolerance = (flags & 128) ? 1e-9 : 0.0;
    opt.max_rounds = 2;
    opt.force_circle_domain = flags & 1;
    /* method paper's linear solver: auto, dense, sparse dog leg, or out of range */
    opt.linear_solver = (plateau_linear_solver)((flags >> 5) & 3);
    opt.progress = progress;
    opt.progress_user = &ps;
    /* a budget of 2 to 17 clock readings */
    opt.clock_fn = counter_clock;
    opt.clock_user = &readings;
    opt.max_seconds = 2.0 + (double)((fail_byte ^ abort_byte) % 16);
    opt.allocator = countalloc_allocator(&ca);
    memset(&mesh, 0, sizeof mesh);
    memset(&err, 0, sizeof err);

    if (loops) {
        size_t shift;
        k = 2 + (size_t)(opt.seed % 2);
        for (i = 0; i < k; i++) counts[i] = m / k;
        counts[0] += m % k;
        shift = (size_t)(opt.seed / 2) % 4;
        if (shift > counts[0]) shift = counts[0];
        counts[0] -= shift;
        counts[1] += shift;
        rc = plateau_solve_loops(m ? xyz : NULL, counts, k, &opt, &mesh, &rep, &err);
    } else {
        rc = plateau_solve(m ? xyz : NULL, m, &opt, &mesh, &rep, &err);
    }
    FUZZ_REQUIRE(plateau_result_string(rc) != NULL);
    if (ca.refused > 0) {
        FUZZ_REQUIRE(rc == PLATEAU_ERR_OUT_OF_MEMORY);
    } else if (ps.aborted) {
        FUZZ_REQUIRE(rc == PLATEAU_ERR_ABORTED);
    }
    if (rc == PLATEAU_OK) {
        check_mesh(&mesh, xyz, m, m + rep.boundary_points_added);
        /* 0 is automatic (method area may split long edges), -1 keeps them */
        FUZZ_REQUIRE(opt.refine_boundary != PLATEAU_OFF || rep.boundary_points_added == 0);
        FUZZ_REQUIRE(rep.loops == k);
        FUZZ_REQUIRE(k == 1 || rep.boundary_points_added == 0);
        if (k == 2) FUZZ_REQUIRE(rep.neck_ratio >= 0.0 && is_finite(rep.neck_ratio));
        FUZZ_REQUIRE(is_finite(rep.area) && rep.area >= 0);
    } else {
        FUZZ_REQUIRE((int)rc < 0);
        FUZZ_REQUIRE(fuzz_terminated(err.message, sizeof err.message));
    }
    plateau_mesh_free(&mesh);
    FUZZ_REQUIRE(mesh.num_vertices == 0 && mesh.positions == NULL && mesh.fixed == NULL);
    FUZZ_REQUIRE(mesh.num_triangles == 0 && mesh.triangles == NULL && mesh.neighbors == NULL);
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    FUZZ_REQUIRE(countalloc_lost_context == 0);
    return 0;
}
