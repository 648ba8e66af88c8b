/* test_shared_block.c - the configuration block that plateau_lm.h and
 * plateau_delaunay.h each carry (the common declarations: plateau_index
 * and plateau_allocator; the common implementation: PLATEAU_MALLOC and the
 * other configuration macros, plateau__alloc, plateau__free, ...) is the
 * same text in both headers, so that whichever is included first defines
 * it as the other would.  Each copy starts at the marker comment
 * "Shared by every plateau header (identical copies, guarded)" and ends at
 * the #endif that closes its guard, PLATEAU_COMMON_DECLARED or
 * PLATEAU_COMMON_IMPLEMENTED.  Reads the headers from the repository's
 * root, where make test runs it. */
#include "harness.h"

#define SHARED_MARKER "/* ---- Shared by every plateau header (identical copies, guarded) -------- */"

static char *shared_read(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    long size;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        text = (char *)malloc((size_t)size + 1);
        if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
            free(text);
            text = NULL;
        }
        if (text) text[size] = '\0';
    }
    fclose(f);
    return text;
}

/* The k-th block (0: declarations, 1: implementation) of text: from its
 * marker to the end of the line of its closing #endif; *len its length.
 * NULL when there is no such block. */
static const char *shared_block(const char *text, int k, size_t *len)
{
    static const char *const ends[2] = {"#endif /* PLATEAU_COMMON_DECLARED */",
                                        "#endif /* PLATEAU_COMMON_IMPLEMENTED */"};
    const char *start = strstr(text, SHARED_MARKER), *end;
    if (start && k == 1) start = strstr(start + 1, SHARED_MARKER);
    if (!start) return NULL;
    end = strstr(start, ends[k]);
    if (!end) return NULL;
    *len = (size_t)(end - start) + strlen(ends[k]);
    return start;
}

static int shared_markers(const char *text)
{
    int n = 0;
    for (text = strstr(text, SHARED_MARKER); text; text = strstr(text + 1, SHARED_MARKER)) n++;
    return n;
}

static void test_blocks_identical(void)
{
    char *lm = shared_read("plateau_lm.h"), *dt = shared_read("plateau_delaunay.h");
    int k;
    if (!CHECK_MSG(lm && dt, "plateau_lm.h and plateau_delaunay.h can be read (run from the "
                             "repository's root)")) {
        free(lm);
        free(dt);
        return;
    }
    for (k = 0; k < 2; k++) {
        size_t la = 0, lb = 0, i, bol, line = 1;
        const char *a = shared_block(lm, k, &la), *b = shared_block(dt, k, &lb);
        if (!CHECK_MSG(a && b, k ? "both headers hold the shared implementation block"
                                 : "both headers hold the shared declaration block"))
            continue;
        /* each block is one copy, inside its own guard */
        CHECK(strstr(a, k ? "#define PLATEAU_COMMON_IMPLEMENTED" : "#define PLATEAU_COMMON_DECLARED") <
              a + la);
        CHECK(la > 400);
        CHECK_NEAR((double)la, (double)lb, 0.0); /* the same length */
        for (i = 0, bol = 0; i < la && i < lb && a[i] == b[i]; i++)
            if (a[i] == '\n') {
                line++;
                bol = i + 1;
            }
        if (!CHECK_MSG(la == lb && i == la, "the two copies are identical"))
            printf("  block %d differs at its line %lu:\n    plateau_lm.h:       %.70s\n"
                   "    plateau_delaunay.h: %.70s\n",
                   k, (unsigned long)line, a + bol, b + bol);
        else
            printf("shared block %d: %lu bytes, %lu lines, identical\n", k, (unsigned long)la,
                   (unsigned long)line);
    }
    /* two copies in each header, no third */
    CHECK_EQ_INT(shared_markers(lm), 2);
    CHECK_EQ_INT(shared_markers(dt), 2);
    free(lm);
    free(dt);
}

int main(void)
{
    RUN(test_blocks_identical);
    return harness_report("test_shared_block");
}
