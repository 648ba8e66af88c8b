/* membrane.c - the paper's example III.D: a tensile membrane spanning 9
 * boundary vertices with n = 4 interior points.  The paper gives no
 * coordinates, so the polygon is a designed four-point shade sail: two
 * fixings on a house wall and two posts, heights alternating high and low
 * (a hypar), cable edges with an 8 % sag (examples/surfaces.h).  There is no
 * exact surface: the table gives the mean |H| (the paper's figure for its
 * sail: 4.786e-4) and the area against the polygon's own optimum. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "surfaces.h"

int main(void)
{
    return demo_run_group("membrane");
}
