/* Include order: the standalone headers first, then plateau.h. */
#define PLATEAU_LM_IMPLEMENTATION
#include "../../plateau_lm.h"
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#include "../../plateau_delaunay.h"
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
int plateau_check_order_dummy;
