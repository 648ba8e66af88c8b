/* The stb pattern in one unit: the declarations first (as from some other
 * header of the user's), the implementation later.  plateau.h must then
 * compile the implementations of plateau_lm.h and plateau_delaunay.h too,
 * although its include guard already skipped their inclusion. */
#include "../../plateau.h"
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
