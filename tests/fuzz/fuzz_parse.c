/* fuzz_parse.c - libFuzzer target for plateau_parse_boundary, the command-line
 * tool's input parser, and for the boundary steps that follow it
 * (plateau_boundary_check, plateau_boundary_domain, plateau_seed_points).
 *
 * Bytes: the text itself (not NUL-terminated: the parser must keep to the
 * length).  When the first byte is 0x01, the second picks an allocation to
 * refuse (1..8) and the text starts after them.
 * Checked: the parser stays inside the buffer (AddressSanitizer), an error
 * leaves no array behind, the message is terminated, a refused allocation
 * gives PLATEAU_ERR_OUT_OF_MEMORY; a parsed boundary that passes the check gets a
 * finite domain and finite seed points; nothing leaks. */
#define PLATEAU_IMPLEMENTATION
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
    FUZZ_REQUIRE(countalloc_lost_context == 0);
    return 0;
}
