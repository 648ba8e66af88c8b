/* bench_invariance.c - the invariance property over many boundaries
 * (built by `make bench`; tests/test_invariance.c runs a small sample in
 * make test): 50 random smooth closed curves (tests/invariance.h: 30 to 89
 * vertices, three harmonics per coordinate on a ring), each solved with
 * the default options as given and under 8 transforms (axes permuted
 * cyclically, mirror, scale 2^-20, axes swapped: exact in floating point;
 * scale 3.7, moved by 1e6,
 * a rotation, a general similarity: not), then the twisted unknot and the
 * far saddle of the test.  Prints per transform how many copies gave the
 * reference's mesh bit for bit, the same triangles with the area within
 * 1e-9, other triangles, a change of validity, and the largest relative
 * area difference.  "full" runs 200 curves. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "tests/invariance.h"

/* a saddle moved far from the origin (its coordinates rounded there) */
static size_t inv_far_saddle(double *xyz)
{
    size_t i, m = 40;
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m;
        xyz[3 * i] = 1e6 + cos(t);
        xyz[3 * i + 1] = 1e6 + sin(t);
        xyz[3 * i + 2] = 1e6 + 0.4 * cos(2.0 * t);
    }
    return m;
}

int main(int argc, char **argv)
{
    int curves = argc > 1 && strcmp(argv[1], "full") == 0 ? 200 : 50, c;
    inv_tally tl;
    inv_rng rng = {20240601ull};
    double xyz[3 * INV_MAX_M];
    plateau_options o;
    size_t m;
    memset(&tl, 0, sizeof tl);
    memset(&o, 0, sizeof o);
    for (c = 0; c < curves; c++) {
        m = inv_random_curve(&rng, xyz);
        if (plateau_boundary_check(xyz, m, NULL) != PLATEAU_OK) {
            c--; /* a curve that touches itself: draw another */
            continue;
        }
        inv_run(xyz, m, &o, &tl);
    }
    {
        char title[80];
        sprintf(title, "%d random smooth curves, default options", curves);
        inv_print(&tl, title);
    }
    memset(&tl, 0, sizeof tl);
    m = inv_twisted_unknot(xyz);
    inv_run(xyz, m, &o, &tl);
    inv_print(&tl, "the twisted unknot (100 vertices)");
    memset(&tl, 0, sizeof tl);
    m = inv_far_saddle(xyz);
    inv_run(xyz, m, &o, &tl);
    inv_print(&tl, "the saddle at (1e6, 1e6, 1e6)");
    return 0;
}
