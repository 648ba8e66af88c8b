/* test_api_index.c - each header's manual has an API INDEX: every public
 * function, one entry each, written as its return type, its name and the
 * names of its parameters in order, e.g.
 *     plateau_result plateau_read_boundary_file(path, allocator, xyz, m, err)
 * This test reads the three headers from the repository's root (where make
 * test runs it), collects the declarations (the lines that start with the
 * header's linkage macro, before its implementation) and the index entries,
 * and checks that they name the same functions with the same return types
 * and parameters in the same order: none missing, none stale, none whose
 * argument order a reader would copy wrong. */
#include "harness.h"

#include <ctype.h>

#define API_MAX 256
#define API_TEXT 512

typedef struct api_entry {
    char name[96];
    char ret[96];
    char params[API_TEXT]; /* parameter names, separated by ", " */
} api_entry;

static char *api_read(const char *path)
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

/* Copies s[0..n) into out (size API_TEXT) with every run of white space made
 * one space, none at the ends, and "* " after a type glued to the star
 * ("const char * f" and "const char *f" read the same). */
static void api_squeeze(const char *s, size_t n, char *out)
{
    size_t i, k = 0;
    int space = 0;
    for (i = 0; i < n && k + 2 < API_TEXT; i++) {
        if (isspace((unsigned char)s[i])) {
            space = k > 0;
            continue;
        }
        if (space && s[i] != '*' && !(k > 0 && out[k - 1] == '*')) out[k++] = ' ';
        if (space && s[i] == '*') out[k++] = ' ';
        space = 0;
        out[k++] = s[i];
    }
    out[k] = '\0';
}

/* The name a parameter declaration gives: the identifier inside "(*name)"
 * for a function pointer, else the last identifier before any "[...]". */
static void api_param_name(const char *p, size_t n, char *out, size_t cap)
{
    size_t i, start = 0, end = 0, k;
    const char *star = NULL;
    for (i = 0; i + 1 < n; i++)
        if (p[i] == '(' && p[i + 1] == '*') { star = p + i + 2; break; }
    if (star) {
        while (*star == ' ') star++;
        for (k = 0; k + 1 < cap && (isalnum((unsigned char)star[k]) || star[k] == '_'); k++) out[k] = star[k];
        out[k] = '\0';
        return;
    }
    for (i = 0; i < n && p[i] != '['; i++) {
        if (isalnum((unsigned char)p[i]) || p[i] == '_') {
            if (i == 0 || !(isalnum((unsigned char)p[i - 1]) || p[i - 1] == '_')) start = i;
            end = i + 1;
        }
    }
    for (k = 0; start + k < end && k + 1 < cap; k++) out[k] = p[start + k];
    out[k] = '\0';
}

/* The parameter names of a list "type a, type (*b)(int, int), type c[3]"
 * (top-level commas only), ", "-separated into out; "void" gives "". */
static void api_param_names(const char *list, char *out)
{
    size_t i = 0, start = 0, n = strlen(list), k = 0;
    int depth = 0;
    out[0] = '\0';
    if (strcmp(list, "void") == 0) return;
    for (i = 0; i <= n; i++) {
        if (list[i] == '(') depth++;
        else if (list[i] == ')') depth--;
        if (i == n || (list[i] == ',' && depth == 0)) {
            char name[96];
            api_param_name(list + start, i - start, name, sizeof name);
            if (k > 0 && k + 2 < API_TEXT) { out[k++] = ','; out[k++] = ' '; }
            if (k + strlen(name) + 1 < API_TEXT) { strcpy(out + k, name); k += strlen(name); }
            start = i + 1;
        }
    }
}

/* Splits "RET NAME(PARAMS)" (squeezed) into an entry; 0 when it is not of
 * that form. */
static int api_split(const char *sig, int names_only, api_entry *e)
{
    const char *open = strchr(sig, '('), *close = strrchr(sig, ')'), *name;
    char list[API_TEXT];
    size_t len;
    if (!open || !close || close < open) return 0;
    name = open;
    while (name > sig && (isalnum((unsigned char)name[-1]) || name[-1] == '_')) name--;
    len = (size_t)(open - name);
    if (len == 0 || len >= sizeof e->name || name == sig) return 0;
    memcpy(e->name, name, len);
    e->name[len] = '\0';
    len = (size_t)(name - sig);
    while (len > 0 && sig[len - 1] == ' ') len--;
    if (len >= sizeof e->ret) return 0;
    memcpy(e->ret, sig, len);
    e->ret[len] = '\0';
    len = (size_t)(close - open - 1);
    if (len >= sizeof list) return 0;
    memcpy(list, open + 1, len);
    list[len] = '\0';
    if (names_only) strcpy(e->params, list);
    else api_param_names(list, e->params);
    return 1;
}

/* Blanks every C comment of text (in place), keeping newlines. */
static void api_strip_comments(char *text)
{
    char *p = text;
    while ((p = strstr(p, "/*")) != NULL) {
        char *q = strstr(p + 2, "*/");
        char *end = q ? q + 2 : p + strlen(p);
        for (; p < end; p++)
            if (*p != '\n') *p = ' ';
    }
}

/* The declarations: each line of the declaration part that starts with
 * macro and a space, up to its ';'. */
static size_t api_declarations(const char *text, const char *macro, const char *impl_marker,
                               api_entry *out)
{
    char *copy;
    const char *end = strstr(text, impl_marker), *p;
    size_t n = 0, mlen = strlen(macro);
    if (!end) return 0;
    copy = (char *)malloc((size_t)(end - text) + 1);
    if (!copy) return 0;
    memcpy(copy, text, (size_t)(end - text));
    copy[end - text] = '\0';
    api_strip_comments(copy);
    for (p = copy; (p = strstr(p, macro)) != NULL; p += mlen) {
        const char *semi;
        char sig[API_TEXT];
        if ((p > copy && p[-1] != '\n') || p[mlen] != ' ') continue;
        semi = strchr(p, ';');
        if (!semi || n >= API_MAX) break;
        api_squeeze(p + mlen, (size_t)(semi - p - mlen), sig);
        if (api_split(sig, 0, &out[n])) n++;
    }
    free(copy);
    return n;
}

/* The index: from the line " * API INDEX" to the first empty comment line
 * (" *"), every line of the form " *     RET NAME(a, b, c)" (an entry: a
 * type and a name before the parenthesis, names only inside). */
static size_t api_index(const char *text, api_entry *out, int *found)
{
    const char *p = strstr(text, "\n * API INDEX");
    size_t n = 0;
    *found = p != NULL;
    if (!p) return 0;
    p = strchr(p + 1, '\n');
    while (p && n < API_MAX) {
        const char *line = p + 1, *eol = strchr(line, '\n');
        size_t len = eol ? (size_t)(eol - line) : strlen(line);
        char sig[API_TEXT];
        if (len <= 2 && strncmp(line, " *", 2) == 0) break; /* the block ends */
        if (len > 7 && strncmp(line, " *     ", 7) == 0 && line[7] != ' ' && memchr(line, '(', len)) {
            api_squeeze(line + 7, len - 7, sig);
            if (api_split(sig, 1, &out[n])) n++;
        }
        p = eol;
    }
    return n;
}

static const api_entry *api_find(const api_entry *list, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (strcmp(list[i].name, name) == 0) return &list[i];
    return NULL;
}

static void api_check_header(const char *path, const char *macro, const char *impl_marker,
                             size_t at_least)
{
    static api_entry decl[API_MAX], index[API_MAX];
    char *text = api_read(path);
    size_t nd, ni, i;
    int found = 0;
    char msg[1024];
    CHECK_MSG(text != NULL, path);
    if (!text) return;
    nd = api_declarations(text, macro, impl_marker, decl);
    ni = api_index(text, index, &found);
    sprintf(msg, "%.100s has an API INDEX", path);
    CHECK_MSG(found, msg);
    sprintf(msg, "%.100s: %lu declarations found (at least %lu)", path, (unsigned long)nd,
            (unsigned long)at_least);
    CHECK_MSG(nd >= at_least, msg);
    CHECK_NEAR((double)ni, (double)nd, 0.0); /* as many entries as declarations */
    for (i = 0; i < nd; i++) {
        const api_entry *e = api_find(index, ni, decl[i].name);
        sprintf(msg, "%.100s: %.90s is missing from the API INDEX", path, decl[i].name);
        if (!CHECK_MSG(e != NULL, msg)) continue;
        sprintf(msg, "%.100s: %.90s returns '%.90s' (the index says '%.90s')", path, decl[i].name, decl[i].ret, e->ret);
        CHECK_MSG(strcmp(e->ret, decl[i].ret) == 0, msg);
        sprintf(msg, "%.100s: %.90s(%.300s) (the index says (%.300s))", path, decl[i].name, decl[i].params, e->params);
        CHECK_MSG(strcmp(e->params, decl[i].params) == 0, msg);
    }
    for (i = 0; i < ni; i++) {
        size_t j, twice = 0;
        sprintf(msg, "%.100s: the API INDEX names %.90s, which is not declared", path, index[i].name);
        CHECK_MSG(api_find(decl, nd, index[i].name) != NULL, msg);
        for (j = 0; j < ni; j++) twice += strcmp(index[j].name, index[i].name) == 0;
        sprintf(msg, "%.100s: the API INDEX names %.90s %lu times", path, index[i].name, (unsigned long)twice);
        CHECK_MSG(twice == 1, msg);
    }
    free(text);
}

/* The checker itself, on a small text with a known answer (so that a
 * parser that finds nothing cannot pass the headers' checks vacuously). */
static void test_parser(void)
{
    static api_entry d[API_MAX], x[API_MAX];
    const char *text = "/* X - a header\n * API INDEX (test)\n *   Group\n"
                       " *     int x_f(a, cb, v)\n *         does f\n"
                       " *     const char *x_name(code)\n *         names\n *\n */\n"
                       "X_DEF int x_f(const double *a, int (*cb)(int, void *),\n"
                       "              double v[3]); /* a, b */\n"
                       "X_DEF const char * x_name(int code);\n"
                       "  X_DEF int not_at_line_start(void);\n#ifdef X_IMPL\n"
                       "X_DEF int x_hidden(void);\n";
    int found = 0;
    size_t nd = api_declarations(text, "X_DEF", "#ifdef X_IMPL", d);
    size_t ni = api_index(text, x, &found);
    CHECK_EQ_INT(nd, 2);
    CHECK_EQ_INT(ni, 2);
    CHECK(found);
    if (nd == 2 && ni == 2) {
        CHECK(strcmp(d[0].name, "x_f") == 0 && strcmp(d[0].params, "a, cb, v") == 0);
        CHECK(strcmp(d[0].ret, "int") == 0);
        CHECK(strcmp(d[1].ret, "const char *") == 0 && strcmp(d[1].params, "code") == 0);
        CHECK(strcmp(x[1].ret, "const char *") == 0 && strcmp(x[1].name, "x_name") == 0);
        CHECK(strcmp(x[0].params, "a, cb, v") == 0);
    }
}

static void test_headers(void)
{
    api_check_header("plateau_lm.h", "PLATEAU_LM_DEF",
                     "#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_LM_IMPLEMENTATION)", 20);
    api_check_header("plateau_delaunay.h", "PLATEAU_DT_DEF",
                     "#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_DELAUNAY_IMPLEMENTATION)", 7);
    api_check_header("plateau.h", "PLATEAU_DEF",
                     "#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_IMPLEMENTED)", 60);
}

int main(void)
{
    RUN(test_parser);
    RUN(test_headers);
    return harness_report("test_api_index");
}
