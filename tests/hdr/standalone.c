/* Compiles one header, with its implementation, alone in a translation unit.
 * The Makefile sets PLATEAU_CHECK_HEADER to the header and defines the
 * header's *_IMPLEMENTATION macro; it builds this file as C99 under gcc and
 * clang and as C++ under g++ and clang++, all with -Werror. */
#include PLATEAU_CHECK_HEADER
int plateau_check_standalone_dummy;
