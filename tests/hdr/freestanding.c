/* PLATEAU_FREESTANDING: the three implementations compile with no header of
 * the C library beyond the freestanding ones.  The Makefile compiles this
 * with clang -ffreestanding -nostdlibinc (only the compiler's own <stddef.h>,
 * <stdint.h>, <float.h>, <limits.h> on the include path; C and C++) and with
 * gcc -ffreestanding; examples/web links the same configuration into a
 * WebAssembly module that imports nothing.  The object's undefined symbols
 * are the ones named below plus memcpy, memmove and memset. */
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
double check_sqrt(double x);
double check_fabs(double x);
double check_atan2(double y, double x);
double check_cos(double x);
double check_sin(double x);
void *check_malloc(size_t size);
void check_free(void *ptr);
int check_snprintf(char *buffer, size_t size, const char *format, ...);
void check_qsort(void *base, size_t count, size_t size,
                 int (*compare)(const void *a, const void *b));
#ifdef __cplusplus
}
#endif
#define PLATEAU_FREESTANDING
#define PLATEAU_MALLOC(size, ctx) ((void)(ctx), check_malloc(size))
#define PLATEAU_FREE(ptr, ctx) ((void)(ctx), check_free(ptr))
#define PLATEAU_SQRT(x) check_sqrt(x)
#define PLATEAU_FABS(x) check_fabs(x)
#define PLATEAU_ATAN2(y, x) check_atan2(y, x)
#define PLATEAU_COS(x) check_cos(x)
#define PLATEAU_SIN(x) check_sin(x)
#define PLATEAU_SNPRINTF check_snprintf
#define PLATEAU_QSORT(base, count, size, compare) check_qsort(base, count, size, compare)
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"
int plateau_check_freestanding_dummy;
