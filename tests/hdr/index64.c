/* A 64-bit index type: PLATEAU_INDEX_TYPE with its PLATEAU_INDEX_MAX (the
 * headers refuse the type without the maximum).  Every header's
 * implementation must compile warning-free with it. */
#define PLATEAU_INDEX_TYPE int64_t
#define PLATEAU_INDEX_MAX INT64_MAX
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
int plateau_check_index64_dummy;
