/* Include order: plateau_delaunay.h, then plateau_lm.h, then plateau.h, with
 * PLATEAU_IMPLEMENTATION alone switching on all three implementations. */
#define PLATEAU_IMPLEMENTATION
#include "../../plateau_delaunay.h"
#include "../../plateau_lm.h"
#include "../../plateau.h"
int plateau_check_order_dummy;
