/* countalloc.h - a counting, optionally failing allocator for plateau's tests
 * and fuzz targets, plugged in through plateau_allocator.
 *
 *     countalloc ca;
 *     plateau_allocator a;
 *     countalloc_init(&ca, 3);          refuse the 3rd allocation (0: never)
 *     a = countalloc_allocator(&ca);
 *     ... call the library with a ...
 *     ca.calls    allocations asked for
 *     ca.live     blocks handed out and not freed yet
 *     ca.bad      frees of a pointer this allocator did not hand out, or
 *                 double frees
 *     countalloc_lost_context   calls that came without our user_data
 *
 * With COUNTALLOC_SWEEP defined (after harness.h) it also gives
 * countalloc_sweep_run, the out-of-memory sweep of one entry point.
 *
 * Each block carries a small header (its size and a tag) so the allocator can
 * tell its own blocks from foreign ones; the state lives in the user_data,
 * which also checks that the library passes the context through.  Only the
 * k-th call fails, later calls succeed again: a caller that goes on after a
 * failure is caught because it cannot return the out-of-memory code then. */
#ifndef PLATEAU_TEST_COUNTALLOC_H
#define PLATEAU_TEST_COUNTALLOC_H

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* COUNTALLOC_SITES (a measurement build only, glibc): every allocation
 * that no refusal is set for (fail_at 0) appends the return addresses of
 * its callers to the file named by the environment variable
 * COUNTALLOC_SITES, one line per call, for tests/alloc_sites.sh, which
 * turns them into the set of distinct allocation call sites a sweep
 * reaches (a sweep refuses each call of its full run once, so the sites
 * of that run are the sites it fails). */
#ifdef COUNTALLOC_SITES
#include <execinfo.h>
#include <stdio.h>
static void countalloc_site(void)
{
    void *frames[8];
    const char *path = getenv("COUNTALLOC_SITES");
    FILE *f;
    int n, i;
    if (!path || !(f = fopen(path, "a"))) return;
    n = backtrace(frames, 8);
    for (i = 1; i < n; i++) fprintf(f, "%s%p", i > 1 ? " " : "", frames[i]);
    fputc('\n', f);
    fclose(f);
}
#define COUNTALLOC_SITE(ca) ((ca)->fail_at == 0 && (ca)->fail_from == 0 ? countalloc_site() : (void)0)
#else
#define COUNTALLOC_SITE(ca) ((void)0)
#endif

#define COUNTALLOC_MAGIC 0x5ca1ab1eu

/* Calls that arrived without our user_data (the library lost the context). */
static long countalloc_lost_context;

typedef struct countalloc {
    unsigned magic;
    long calls;       /* allocation calls so far */
    long fail_at;     /* the call number (1-based) that returns NULL; 0: none */
    long fail_from;   /* when non-zero: every call from this number on fails */
    long refused;     /* how many calls returned NULL */
    long live;        /* blocks allocated and not yet freed */
    long frees;
    long bad;         /* foreign pointers, double frees, wrong user_data */
    size_t bytes_live;
    size_t bytes_peak;
} countalloc;

/* The block header: keeps the user's pointer aligned like malloc's. */
typedef union countalloc_head {
    struct {
        size_t size;
        unsigned tag;
    } h;
    double align_d;
    void *align_p;
    long double align_ld;
} countalloc_head;

#define COUNTALLOC_TAG_LIVE 0x600dcafeu
#define COUNTALLOC_TAG_DEAD 0xdeadbeefu

static void countalloc_init(countalloc *ca, long fail_at)
{
    memset(ca, 0, sizeof *ca);
    ca->magic = COUNTALLOC_MAGIC;
    ca->fail_at = fail_at;
}

static void *countalloc_alloc(size_t size, void *user_data)
{
    countalloc *ca = (countalloc *)user_data;
    countalloc_head *head;
    if (!ca || ca->magic != COUNTALLOC_MAGIC) {
        countalloc_lost_context++;
        return NULL;
    }
    ca->calls++;
    COUNTALLOC_SITE(ca);
    if (ca->calls == ca->fail_at || (ca->fail_from > 0 && ca->calls >= ca->fail_from)) {
        ca->refused++;
        return NULL;
    }
    if (size > (size_t)-1 - sizeof(countalloc_head)) {
        ca->refused++;
        return NULL;
    }
    head = (countalloc_head *)malloc(sizeof(countalloc_head) + size);
    if (!head) {
        ca->refused++;
        return NULL;
    }
    head->h.size = size;
    head->h.tag = COUNTALLOC_TAG_LIVE;
    ca->live++;
    ca->bytes_live += size;
    if (ca->bytes_live > ca->bytes_peak) ca->bytes_peak = ca->bytes_live;
    return (void *)(head + 1);
}

static void countalloc_free(void *ptr, void *user_data)
{
    countalloc *ca = (countalloc *)user_data;
    countalloc_head *head;
    if (!ptr) return; /* free(NULL) is allowed */
    if (!ca || ca->magic != COUNTALLOC_MAGIC) {
        countalloc_lost_context++;
        return;
    }
    head = (countalloc_head *)ptr - 1;
    if (head->h.tag != COUNTALLOC_TAG_LIVE) {
        ca->bad++; /* double free, or a block from another allocator */
        return;
    }
    head->h.tag = COUNTALLOC_TAG_DEAD;
    ca->live--;
    ca->frees++;
    ca->bytes_live -= head->h.size;
    free(head);
}

static plateau_allocator countalloc_allocator(countalloc *ca)
{
    plateau_allocator a;
    a.alloc_fn = countalloc_alloc;
    a.free_fn = countalloc_free;
    a.user_data = ca;
    return a;
}

#if defined(PLATEAU_TEST_HARNESS_H) && defined(COUNTALLOC_SWEEP) /* asked for; checks with harness.h's CHECK */
/* ---- the out-of-memory sweep of one entry point ----
 * Runs it once through the counting allocator and counts its allocations
 * N (twice: the count is deterministic); then for k = 1..N (make test:
 * every third) refuses the k-th allocation, and in a second pass the k-th
 * and every later one: each call must return oom_code and give every
 * block back, with no foreign or double free.  Prints "alloc points:
 * <name> <N>" and returns N (-1 when the unconstrained call failed). */
/* One entry point under test: call() runs it with the allocator and returns
 * its result code; release() frees whatever outputs it left (through the
 * entry point's own free function) and checks their state. */
typedef struct countalloc_sweep {
    const char *name;
    int (*call)(void *ctx, const plateau_allocator *a);
    void (*release)(void *ctx, int rc);
    void *ctx;
    int ok_code, oom_code;
} countalloc_sweep;

static long countalloc_run_once(const countalloc_sweep *s, countalloc *ca, int *rc)
{
    plateau_allocator a = countalloc_allocator(ca);
    *rc = s->call(s->ctx, &a);
    s->release(s->ctx, *rc);
    return ca->calls;
}

static long countalloc_sweep_run(const countalloc_sweep *s)
{
    countalloc ca;
    long n, k, step, bad_code = 0, leaks = 0, bad_frees = 0;
    int rc, pass;

    countalloc_init(&ca, 0);
    n = countalloc_run_once(s, &ca, &rc);
    if (!CHECK_EQ_INT(rc, s->ok_code)) {
        fprintf(stderr, "  %s: the unconstrained call failed\n", s->name);
        return -1;
    }
    CHECK_EQ_INT(ca.live, 0);
    CHECK_EQ_INT(ca.bad, 0);
    /* the count is deterministic: a second run makes the same calls */
    countalloc_init(&ca, 0);
    CHECK_EQ_INT(countalloc_run_once(s, &ca, &rc), n);

    /* make test-full refuses every allocation in each pass; make test every
     * third, the two passes at different offsets (a sweep costs the square
     * of the run's allocations) */
    step = HARNESS_FULL ? 1 : 3;
    for (pass = 0; pass < 2; pass++) {
        for (k = 1 + pass % step; k <= n; k += step) {
            countalloc_init(&ca, k);
            if (pass) ca.fail_from = k;
            countalloc_run_once(s, &ca, &rc);
            if (rc != s->oom_code) {
                if (bad_code++ < 5)
                    fprintf(stderr, "FAIL %s: allocation %ld of %ld refused%s: returned %d (%s), "
                                    "expected %d\n",
                            s->name, k, n, pass ? " (and all later)" : "", rc,
                            s->oom_code == PLATEAU_ERR_OUT_OF_MEMORY
                                ? plateau_result_string((plateau_result)rc)
                                : "", s->oom_code);
            }
            if (ca.live != 0 && leaks++ < 5)
                fprintf(stderr, "FAIL %s: allocation %ld of %ld refused: %ld blocks leaked\n",
                        s->name, k, n, ca.live);
            if (ca.bad != 0 && bad_frees++ < 5)
                fprintf(stderr, "FAIL %s: allocation %ld of %ld refused: %ld bad frees\n",
                        s->name, k, n, ca.bad);
        }
    }
    CHECK_MSG(bad_code == 0, "every refused allocation gives the out-of-memory code");
    CHECK_MSG(leaks == 0, "no block leaks after a refused allocation");
    CHECK_MSG(bad_frees == 0, "no foreign or double free after a refused allocation");
    printf("alloc points: %s %ld\n", s->name, n);
    return n;
}

#endif /* PLATEAU_TEST_HARNESS_H */

#endif /* PLATEAU_TEST_COUNTALLOC_H */
