/* PLATEAU_STATIC: every function gets internal linkage.  Built with -Werror,
 * so no unused-function warning may appear even though nothing is called. */
#define PLATEAU_STATIC
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
int plateau_check_static_dummy;
