/* fuzz_parse.c - libFuzzer target for plateau_parse_boundary and
 * plateau_parse_boundary_lines, the command-line tool's input parser, and for the boundary steps that follow it
 * (plateau_boundary_check, plateau_boundary_domain, plateau_seed_points).
 *
 * Bytes: the text itself (not NUL-terminated: the parser must keep to the
 * length).  When the first byte is 0x01, the second picks an allocation to
 * refuse (1..8) and the text starts after them.
 * Checked: the parser stays inside the buffer (AddressSanitizer), an error
 * leaves no array behind, the message is terminated, a refused allocation
 * gives PLATEAU_ERR_OUT_OF_MEMORY; a parsed boundary that passes the check gets a
 * finite domain and finite seed points; nothing leaks. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "countalloc.h"
#include "fuzz_common.h"

#define FUZZ_SEED_POINTS 6
#define FUZZ_MAX_BOUNDARY 64

static int is_finite(double x)
{
    return x == x && x - x == 0.0;
}

static void boundary_steps(const double *xyz, size_t m, const plateau_allocator *a)
{
    static double uv[2 * FUZZ_MAX_BOUNDARY];
    double sxyz[3 * FUZZ_SEED_POINTS], suv[2 * FUZZ_SEED_POINTS];
    plateau_domain_kind kind = PLATEAU_DOMAIN_PLANE;
    plateau_error err;
    plateau_result rc;
    size_t i, count = 0;
    int force;

    rc = plateau_boundary_check(xyz, m, &err);
    if (rc != PLATEAU_OK) {
        FUZZ_REQUIRE((int)rc < 0 && fuzz_terminated(err.message, sizeof err.message));
        return;
    }
    for (force = 0; force < 2; force++) {
        rc = plateau_boundary_domain(xyz, m, force, a, uv, &kind, &err);
        if (rc == PLATEAU_ERR_OUT_OF_MEMORY) return;
        FUZZ_REQUIRE(rc == PLATEAU_OK);
        FUZZ_REQUIRE(kind == PLATEAU_DOMAIN_PLANE || kind == PLATEAU_DOMAIN_CIRCLE);
        if (force) FUZZ_REQUIRE(kind == PLATEAU_DOMAIN_CIRCLE);
        for (i = 0; i < 2 * m; i++) FUZZ_REQUIRE(is_finite(uv[i]));
        rc = plateau_seed_points(xyz, uv, m, FUZZ_SEED_POINTS, 1, a, sxyz, suv, &count, &err);
        if (rc == PLATEAU_ERR_OUT_OF_MEMORY) return;
        FUZZ_REQUIRE(rc == PLATEAU_OK);
        FUZZ_REQUIRE(count <= FUZZ_SEED_POINTS);
        for (i = 0; i < 3 * count; i++) FUZZ_REQUIRE(is_finite(sxyz[i]));
        for (i = 0; i < 2 * count; i++) FUZZ_REQUIRE(is_finite(suv[i]));
    }
}

/* plateau_parse_boundary_lines on the same text, as one loop and as
 * blank-line separated loops: the same result code as the plain parser,
 * as one loop the same vertex count; the loops' counts sum to m, the lines
 * rise, each dropped closing point's line lies after its loop's last kept
 * vertex; nothing leaks. */
static void lines_checks(const uint8_t *data, size_t size, long fail_at, plateau_result plain_rc,
                         size_t plain_m)
{
    int split;
    for (split = 0; split < 2; split++) {
        countalloc ca;
        plateau_allocator a;
        plateau_boundary_lines info;
        plateau_error err;
        plateau_result rc;
        double *xyz = NULL;
        size_t m = 0, i, sum = 0, o = 0;
        countalloc_init(&ca, fail_at);
        a = countalloc_allocator(&ca);
        memset(&info, 0, sizeof info);
        info.split_loops = split;
        rc = plateau_parse_boundary_lines((const char *)data, size, &a, &xyz, &m, &info, &err);
        if (ca.refused > 0) FUZZ_REQUIRE(rc == PLATEAU_ERR_OUT_OF_MEMORY);
        else FUZZ_REQUIRE(rc == plain_rc);
        if (rc == PLATEAU_OK) {
            if (!split) FUZZ_REQUIRE(m == plain_m);
            FUZZ_REQUIRE((m == 0) == (info.num_loops == 0));
            for (i = 1; i < m; i++) FUZZ_REQUIRE(info.lines[i] > info.lines[i - 1]);
            for (i = 0; i < info.num_loops; i++) {
                sum += info.loop_counts[i];
                if (info.closing_lines[i] != 0)
                    FUZZ_REQUIRE(info.closing_lines[i] > info.lines[o + info.loop_counts[i] - 1]);
                o += info.loop_counts[i];
            }
            FUZZ_REQUIRE(sum == m);
        } else {
            FUZZ_REQUIRE(xyz == NULL && m == 0 && info.lines == NULL && info.num_loops == 0);
        }
        plateau_boundary_free(xyz, &a);
        plateau_boundary_lines_free(&info, &a);
        FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    countalloc ca;
    plateau_allocator a;
    plateau_error err;
    plateau_result rc;
    double *xyz = (double *)&ca; /* must be overwritten */
    size_t m = 12345;
    long fail_at = 0;

    if (size >= 2 && data[0] == 1) {
        fail_at = 1 + data[1] % 8;
        data += 2;
        size -= 2;
    }
    countalloc_init(&ca, fail_at);
    a = countalloc_allocator(&ca);
    memset(&err, 0, sizeof err);

    rc = plateau_parse_boundary((const char *)data, size, &a, &xyz, &m, &err);
    FUZZ_REQUIRE(plateau_result_string(rc) != NULL);
    if (ca.refused > 0) FUZZ_REQUIRE(rc == PLATEAU_ERR_OUT_OF_MEMORY);
    if (rc == PLATEAU_OK) {
        FUZZ_REQUIRE(m == 0 || xyz != NULL);
        if (m > 0 && m <= FUZZ_MAX_BOUNDARY) boundary_steps(xyz, m, &a);
        a.free_fn(xyz, a.user_data);
    } else {
        FUZZ_REQUIRE((int)rc < 0);
        FUZZ_REQUIRE(xyz == NULL);
        FUZZ_REQUIRE(fuzz_terminated(err.message, sizeof err.message));
    }
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    lines_checks(data, size, fail_at, rc, m);
    FUZZ_REQUIRE(countalloc_lost_context == 0);
    return 0;
}
