/* plateau_wasm.c - plateau as a freestanding WebAssembly module: no C
 * library, no WASI, no emscripten.  Built by `make web`:
 *     clang --target=wasm32 -nostdlib -ffreestanding -O2 -mbulk-memory -c
 *     wasm-ld --no-entry --export-dynamic --stack-first -z stack-size=1048576
 *     (exports: the functions marked WEB_EXPORT and the memory)
 * The library is compiled with PLATEAU_FREESTANDING; this file supplies what
 * that configuration asks for: sqrt, fabs, atan2, cos, sin, qsort and
 * snprintf (web_libc.h), memcpy / memmove / memset (WebAssembly's
 * memory.copy and memory.fill), and an allocator over the module's own
 * memory (memory.grow).  The module imports nothing: its import section is
 * empty (tests/web_check.sh verifies that), and it exports its memory and
 * the pw_* functions below.
 *
 * Use from JavaScript (examples/web/plateau_web.js):
 *     p = pw_boundary(m)          room for m vertices (x, y, z doubles) at p
 *     r = pw_solve(m, n, method)  plateau_solve with interior_points = n and
 *                                 method (0 paper, 1 paper-literal, 2 area),
 *                                 all other options at their defaults (as
 *                                 the command-line tool); 0 = PLATEAU_OK
 *     pw_area(), pw_f(), pw_iterations(), pw_rounds(), pw_defects(), ...
 *     pw_positions(), pw_num_vertices(), pw_triangles(), pw_num_triangles()
 *     pw_message()                the error message (a C string)
 * The mesh of the last solve is kept until the next solve. */
#include <stddef.h>
#include <stdint.h>

#include "web_libc.h"

/* ---- memory ------------------------------------------------------------ */
/* C compilers call these even in freestanding code (struct copies, the
 * library's copies); with -mbulk-memory the builtins are single
 * instructions, never calls back into these functions. */
void *memcpy(void *dst, const void *src, size_t size);
void *memmove(void *dst, const void *src, size_t size);
void *memset(void *dst, int value, size_t size);

void *memcpy(void *dst, const void *src, size_t size)
{
    __builtin_memcpy(dst, src, size);
    return dst;
}

void *memmove(void *dst, const void *src, size_t size)
{
    __builtin_memmove(dst, src, size);
    return dst;
}

void *memset(void *dst, int value, size_t size)
{
    __builtin_memset(dst, value, size);
    return dst;
}

/* The allocator: blocks of 2^(k+4) bytes, k = 0 .. 27, an 8-byte header
 * holding k; a freed block goes on the free list of its size and is reused
 * by the next request of that size; new blocks are cut from the top of the
 * heap, which grows by memory.grow.  No coalescing: a solve repeated at the
 * same n reuses its blocks, and the memory held is at most twice the peak
 * request.  (Module state: this is the application, not the library.) */
#define WEB_CLASSES 28
extern unsigned char __heap_base; /* wasm-ld: the first byte after data and stack */
static unsigned char *web_top, *web_end;
static void *web_free_list[WEB_CLASSES];
static size_t web_in_use, web_peak;

static void *web_malloc(size_t size)
{
    size_t cap = 16;
    int k = 0;
    unsigned char *block;
    if (size > ((size_t)1 << 31) - 8) return NULL;
    while (cap < size + 8) cap <<= 1, k++;
    if (!web_top) {
        web_top = (unsigned char *)(((uintptr_t)&__heap_base + 15) & ~(uintptr_t)15);
        web_end = (unsigned char *)(__builtin_wasm_memory_size(0) * 65536);
    }
    if (web_free_list[k]) {
        block = (unsigned char *)web_free_list[k] - 8;
        web_free_list[k] = *(void **)web_free_list[k];
    } else {
        if ((size_t)(web_end - web_top) < cap) {
            size_t pages = (cap - (size_t)(web_end - web_top) + 65535) / 65536;
            if (__builtin_wasm_memory_grow(0, pages) == (size_t)-1) return NULL;
            web_end += pages * 65536;
        }
        block = web_top;
        web_top += cap;
    }
    *(size_t *)block = (size_t)k;
    web_in_use += cap;
    if (web_in_use > web_peak) web_peak = web_in_use;
    return block + 8;
}

static void web_free(void *ptr)
{
    size_t k;
    if (!ptr) return;
    k = *(size_t *)((unsigned char *)ptr - 8);
    web_in_use -= (size_t)16 << k;
    *(void **)ptr = web_free_list[k];
    web_free_list[k] = ptr;
}

/* ---- the library, freestanding ------------------------------------------ */
#define PLATEAU_FREESTANDING
#define PLATEAU_MALLOC(size, ctx) ((void)(ctx), web_malloc(size))
#define PLATEAU_FREE(ptr, ctx) ((void)(ctx), web_free(ptr))
#define PLATEAU_SQRT(x) web_sqrt(x)
#define PLATEAU_FABS(x) web_fabs(x)
#define PLATEAU_ATAN2(y, x) web_atan2(y, x)
#define PLATEAU_COS(x) web_cos(x)
#define PLATEAU_SIN(x) web_sin(x)
#define PLATEAU_QSORT(base, count, size, compare) web_qsort(base, count, size, compare)
#define PLATEAU_SNPRINTF web_snprintf
#define PLATEAU_STATIC
#define PLATEAU_IMPLEMENTATION
#include "../../plateau.h"

/* ---- the exported interface --------------------------------------------- */
#define WEB_EXPORT(name) __attribute__((export_name(#name))) name
#define WEB_MAX_BOUNDARY 4096

static double web_boundary[3 * WEB_MAX_BOUNDARY];
static plateau_mesh web_mesh;
static int web_have_mesh;
static plateau_report web_report;
static plateau_error web_error;

/* Room for m boundary vertices (x, y, z), or NULL when m is out of range. */
double *WEB_EXPORT(pw_boundary)(int m)
{
    return m >= 3 && m <= WEB_MAX_BOUNDARY ? web_boundary : NULL;
}

/* plateau_solve on the m vertices at pw_boundary(); returns the
 * plateau_result (0: PLATEAU_OK). */
int WEB_EXPORT(pw_solve)(int m, int n, int method)
{
    plateau_options opt;
    plateau_result r;
    if (web_have_mesh) plateau_mesh_free(&web_mesh);
    web_have_mesh = 0;
    memset(&web_report, 0, sizeof web_report);
    if (m < 3 || m > WEB_MAX_BOUNDARY || n < 0 || method < 0 || method > 2) {
        web_snprintf(web_error.message, sizeof web_error.message,
                     "pw_solve: m must be 3..%d, n >= 0, method 0..2", WEB_MAX_BOUNDARY);
        return (int)PLATEAU_ERR_ARGUMENT;
    }
    memset(&opt, 0, sizeof opt);
    opt.interior_points = (size_t)n;
    opt.method = (plateau_method)method;
    r = plateau_solve(web_boundary, (size_t)m, &opt, &web_mesh, &web_report, &web_error);
    web_have_mesh = 1; /* plateau_mesh_free is safe after a failed solve too */
    return (int)r;
}

double WEB_EXPORT(pw_area)(void) { return web_report.area; }
double WEB_EXPORT(pw_f)(void) { return web_report.f_final; }
double WEB_EXPORT(pw_f_initial)(void) { return web_report.f_initial; }
double WEB_EXPORT(pw_min_angle)(void) { return web_report.min_angle_deg; }
double WEB_EXPORT(pw_max_angle)(void) { return web_report.max_angle_deg; }
int WEB_EXPORT(pw_iterations)(void) { return (int)web_report.iterations; }
int WEB_EXPORT(pw_rounds)(void) { return (int)web_report.rounds; }
int WEB_EXPORT(pw_flips)(void) { return (int)web_report.flips; }
int WEB_EXPORT(pw_defects)(void) { return (int)web_report.defects; }
int WEB_EXPORT(pw_num_vertices)(void) { return (int)web_mesh.num_vertices; }
int WEB_EXPORT(pw_num_triangles)(void) { return (int)web_mesh.num_triangles; }
double *WEB_EXPORT(pw_positions)(void) { return web_mesh.positions; }
plateau_index *WEB_EXPORT(pw_triangles)(void) { return web_mesh.triangles; }
const char *WEB_EXPORT(pw_message)(void) { return web_error.message; }
const char *WEB_EXPORT(pw_result_name)(int r) { return plateau_result_string((plateau_result)r); }
const char *WEB_EXPORT(pw_stop)(void) { return plateau_stop_string(web_report.stop); }
const char *WEB_EXPORT(pw_defects_string)(void)
{
    static char text[160];
    return plateau_defects_string(web_report.defects, text, sizeof text);
}
/* bytes of the heap in use now, and the most ever in use */
double WEB_EXPORT(pw_heap_in_use)(void) { return (double)web_in_use; }
double WEB_EXPORT(pw_heap_peak)(void) { return (double)web_peak; }
