/* catenoid.c - the paper's example III.B: a catenoid patch
 * r(u,v) = (b cos u cosh v, b v, b sin u cosh v), b = 2.05, a polygon of 24
 * vertices, n = 25.  The paper's error formula
 * z = sqrt(b^2 cosh^2(y/b) - x^2) is the same surface (y = b v), its upper
 * half z > 0, where this patch lies.  Ranges and polygon: examples/surfaces.h;
 * the API itself: examples/helicoid.c. */
#ifndef PLATEAU_IMPL_LINKED /* else make links the one shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "surfaces.h"

int main(void)
{
    return demo_run_group("catenoid");
}
