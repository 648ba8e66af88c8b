/* scherk.c - the paper's example III.C (Fig. 8): Scherk's surface
 * z = (1/b) ln(cos(b y) / cos(b x)) for b = 0.4, 1 and 4.9, three sizes each
 * (nine cases, each with its own n and polygon).  For one size the three
 * polygons are scaled copies of each other, so the mesh areas scale by
 * 1/b^2 while the paper's ERR, absolute below |z| = 1 and relative above,
 * does not.  Cases: examples/surfaces.h; the API itself: examples/helicoid.c. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "surfaces.h"

int main(void)
{
    return demo_run_group("scherk");
}
