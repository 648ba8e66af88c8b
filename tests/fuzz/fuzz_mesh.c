/* fuzz_mesh.c - libFuzzer target for plateau_parse_mesh, the reader of the
 * command-line tool's --minimize (OBJ and OFF), and for the mesh that
 * plateau_mesh_create makes of what it reads.
 *
 * Bytes: the text itself (not NUL-terminated: the parser must keep to the
 * length).  When the first byte is 0x01, the second picks an allocation to
 * refuse (1..8) and the text starts after them.
 * Checked: the parser stays inside the buffer (AddressSanitizer); an error
 * leaves no array behind and a terminated message, a parse error names a
 * line within the text; a refused allocation gives
 * PLATEAU_ERR_OUT_OF_MEMORY; a mesh read has every triangle's three
 * corners in range and distinct, finite coordinates and each triangle's
 * line within the text, rising; plateau_mesh_create either takes it or
 * names a triangle; nothing leaks. */
#ifndef PLATEAU_TEST_LINKED /* else the Makefile links one shared object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "countalloc.h"
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    countalloc ca;
    plateau_allocator a;
    plateau_error err;
    plateau_result rc;
    double *p = (double *)&ca; /* must be overwritten */
    plateau_index *t = (plateau_index *)&ca;
    long *lines = (long *)&ca, nlines = 1;
    size_t nv = 12345, nt = 12345, i;
    long fail_at = 0;

    if (size >= 2 && data[0] == 1) {
        fail_at = 1 + data[1] % 8;
        data += 2;
        size -= 2;
    }
    for (i = 0; i < size; i++) nlines += data[i] == '\n';
    countalloc_init(&ca, fail_at);
    a = countalloc_allocator(&ca);
    memset(&err, 0, sizeof err);
    rc = plateau_parse_mesh((const char *)data, size, &a, &p, &nv, &t, &nt, &lines, &err);
    FUZZ_REQUIRE(plateau_result_string(rc) != NULL);
    if (ca.refused > 0) FUZZ_REQUIRE(rc == PLATEAU_ERR_OUT_OF_MEMORY);
    if (rc == PLATEAU_OK) {
        plateau_mesh mesh;
        FUZZ_REQUIRE(nt > 0 && p != NULL && t != NULL && lines != NULL);
        for (i = 0; i < 3 * nv; i++) FUZZ_REQUIRE(p[i] == p[i] && p[i] - p[i] == 0.0);
        for (i = 0; i < nt; i++) {
            const plateau_index *c = t + 3 * i;
            FUZZ_REQUIRE(c[0] >= 0 && c[1] >= 0 && c[2] >= 0);
            FUZZ_REQUIRE((size_t)c[0] < nv && (size_t)c[1] < nv && (size_t)c[2] < nv);
            FUZZ_REQUIRE(c[0] != c[1] && c[1] != c[2] && c[2] != c[0]);
            FUZZ_REQUIRE(lines[i] >= 1 && lines[i] <= nlines && (i == 0 || lines[i] >= lines[i - 1]));
        }
        memset(&mesh, 0, sizeof mesh);
        rc = plateau_mesh_create(p, nv, NULL, t, nt, &a, &mesh, &err);
        if (rc == PLATEAU_OK) {
            unsigned char *marks = (unsigned char *)malloc(nv);
            FUZZ_REQUIRE(marks != NULL);
            FUZZ_REQUIRE(plateau_mesh_vertex_marks(&mesh, marks, &err) == PLATEAU_OK);
            for (i = 0; i < nv; i++) FUZZ_REQUIRE(marks[i] <= PLATEAU_MARK_CABLE);
            free(marks);
        } else if (rc != PLATEAU_ERR_OUT_OF_MEMORY) {
            FUZZ_REQUIRE(rc == PLATEAU_ERR_NON_MANIFOLD || rc == PLATEAU_ERR_ORIENTATION);
            FUZZ_REQUIRE(err.index >= 0 && (size_t)err.index < nt);
        }
        plateau_mesh_free(&mesh);
        plateau_mesh_arrays_free(p, t, lines, &a);
    } else {
        FUZZ_REQUIRE((int)rc < 0);
        FUZZ_REQUIRE(p == NULL && t == NULL && lines == NULL && nv == 0 && nt == 0);
        FUZZ_REQUIRE(fuzz_terminated(err.message, sizeof err.message));
        if (rc == PLATEAU_ERR_PARSE || rc == PLATEAU_ERR_NOT_FINITE)
            FUZZ_REQUIRE(err.index == -1 || (err.index >= 1 && err.index <= nlines));
    }
    FUZZ_REQUIRE(ca.live == 0 && ca.bad == 0);
    FUZZ_REQUIRE(countalloc_lost_context == 0);
    return 0;
}
