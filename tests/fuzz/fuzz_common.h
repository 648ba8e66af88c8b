/* fuzz_common.h - shared bits of plateau's libFuzzer targets.
 *
 * Each target turns the fuzzer's bytes into a call of one public entry point,
 * through the counting allocator of tests/countalloc.h (optionally refusing
 * one allocation), then checks the entry point's contract and that every
 * block came back.  A broken contract aborts, which libFuzzer reports as a
 * crash with the input saved. */
#ifndef PLATEAU_FUZZ_COMMON_H
#define PLATEAU_FUZZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_REQUIRE(cond)                                                          \
    do {                                                                           \
        if (!(cond)) {                                                             \
            fprintf(stderr, "fuzz contract violated: %s (%s:%d)\n", #cond, __FILE__, \
                    __LINE__);                                                     \
            abort();                                                               \
        }                                                                          \
    } while (0)

/* Not every target uses every helper (libFuzzer builds are clang-only). */
#define FUZZ_HELPER static __attribute__((unused))

/* A reader over the fuzzer's bytes; past the end it yields zeros. */
typedef struct fuzz_bytes {
    const uint8_t *data;
    size_t size, pos;
} fuzz_bytes;

FUZZ_HELPER uint8_t fuzz_u8(fuzz_bytes *b)
{
    return b->pos < b->size ? b->data[b->pos++] : 0;
}

FUZZ_HELPER size_t fuzz_left(const fuzz_bytes *b)
{
    return b->size - b->pos;
}

FUZZ_HELPER double fuzz_raw_double(fuzz_bytes *b)
{
    uint64_t bits = 0;
    double d;
    int i;
    for (i = 0; i < 8; i++) bits = (bits << 8) | fuzz_u8(b);
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* 1 if s (capacity n) holds a terminating NUL. */
FUZZ_HELPER int fuzz_terminated(const char *s, size_t n)
{
    return memchr(s, 0, n) != NULL;
}

#endif /* PLATEAU_FUZZ_COMMON_H */
