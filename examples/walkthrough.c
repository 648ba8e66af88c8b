/* walkthrough.c - writes out/walkthrough.html, the algorithm step by step
 * on the paper's helicoid (III.A) and catenoid (III.B): the polygon, the
 * candidate points and the fan in the plane (II.A, Fig. 1), the constrained
 * Delaunay triangulation, the start mesh coloured by |H_i| (II.B), F per
 * Levenberg-Marquardt iteration per round (II.D), the mesh after each round
 * with its flipped edges, and the three methods side by side; after the
 * cases, films between two rings, membranes, membrane design, and the
 * error estimate (each triangle's share, against the true error).  One
 * self-contained file: inline SVG and CSS, no script, nothing fetched.
 * Also writes examples/pictures/walkthrough-helicoid-round-1.svg, the
 * README's sample panel.  The page's logic is examples/walkthrough.h,
 * shared with tests/test_walkthrough.c. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "surfaces.h"
#include "walkthrough.h"

int main(void)
{
    static wt_case cases[2];
    static wt_rings rings;
    const char *names[2] = { "helicoid", "catenoid" };
    char msg[256];
    int k, status = 0;
    FILE *f;
    for (k = 0; k < 2; k++) {
        if (wt_collect(demo_find(names[k]), &cases[k], msg) != 0) {
            fprintf(stderr, "walkthrough: %s\n", msg);
            status = 1;
        }
    }
    if (status == 0 && wt_collect_rings(&rings, msg) != 0) {
        fprintf(stderr, "walkthrough: %s\n", msg);
        status = 1;
    }
    if (status == 0) {
        f = fopen("out/walkthrough.html", "w");
        if (!f || wt_write_html(f, cases, 2, &rings) != 0) {
            fprintf(stderr, "walkthrough: cannot write out/walkthrough.html\n");
            status = 1;
        }
        if (f && fclose(f) != 0) status = 1;
    }
    if (status == 0 && wt_write_round_picture(&cases[0], 0,
                                              "examples/pictures/walkthrough-helicoid-round-1.svg"))
        status = 1;
    if (status == 0)
        printf("out/walkthrough.html: helicoid %d rounds, %lu iterations; catenoid %d rounds, "
               "%lu iterations\n",
               cases[0].rounds, (unsigned long)cases[0].full.iterations, cases[1].rounds,
               (unsigned long)cases[1].full.iterations);
    for (k = 0; k < 2; k++) wt_free(&cases[k]);
    wt_rings_free(&rings);
    return status;
}
