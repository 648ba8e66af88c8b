/* The implementation of the three headers in one object, built once per
 * compiler by make test and linked into every test that marks itself
 * PLATEAU_TEST_LINKED (those that use only the public API and the default
 * configuration), instead of compiling 13 000 lines into each of them. */
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
