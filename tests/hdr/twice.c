/* Every header twice, implementation switched on both times: the include
 * guards and the implementation guards must keep everything compiled once. */
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
#include "../../plateau_lm.h"
#include "../../plateau_delaunay.h"
#include "../../plateau.h"
#include "../../plateau_lm.h"
#include "../../plateau_delaunay.h"
int plateau_check_twice_dummy;
