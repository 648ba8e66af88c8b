/* test_alloc_fail.c - allocation failure at every point of every public entry
 * point that allocates.
 *
 * For each entry point: run it once through the counting allocator of
 * countalloc.h and count its allocations N; then for k = 1..N refuse the k-th
 * allocation (and, in a second pass, the k-th and every later one).  Each
 * such call must return its header's out-of-memory code, leave its outputs
 * in a state its free function accepts (we call it), and give every block
 * back (the allocator's live count returns to 0; LeakSanitizer and valgrind
 * check the same from outside).  The N of each entry point is printed as
 * "alloc points: <entry point> <N>".
 *
 * The compile-time hooks are tested too: PLATEAU_MALLOC / PLATEAU_FREE are
 * defined here to the counting allocator, with the context the library
 * passes (an allocator's user_data when it has no functions), or, for a
 * call given a NULL allocator (plateau_write_svg below), the counter the
 * test points macro_target at. */
#include "plateau.h" /* the declarations, for countalloc.h */
#include "harness.h"
#define COUNTALLOC_SWEEP /* countalloc.h's out-of-memory sweep */
#include "countalloc.h"

static countalloc macro_default;                /* never refuses */
static countalloc *macro_target = &macro_default; /* where a NULL context goes */
#define PLATEAU_MALLOC(size, ctx) \
    countalloc_alloc((size), (ctx) ? (void *)(ctx) : (void *)macro_target)
#define PLATEAU_FREE(ptr, ctx) countalloc_free((ptr), (ctx) ? (void *)(ctx) : (void *)macro_target)
#define PLATEAU_IMPLEMENTATION
#include "plateau.h" /* again: now the implementations of all three headers */

/* ---------------------------------------------------------------- shapes */
/* A saddle: 12 vertices around [-1, 1]^2 with z = x y / 2. */
static void saddle(double *xyz)
{
    static const double xy[12][2] = {{-1, -1}, {-1.0 / 3, -1}, {1.0 / 3, -1}, {1, -1},
                                     {1, -1.0 / 3}, {1, 1.0 / 3}, {1, 1}, {1.0 / 3, 1},
                                     {-1.0 / 3, 1}, {-1, 1}, {-1, 1.0 / 3}, {-1, -1.0 / 3}};
    int i;
    for (i = 0; i < 12; i++) {
        xyz[3 * i] = xy[i][0];
        xyz[3 * i + 1] = xy[i][1];
        xyz[3 * i + 2] = xy[i][0] * xy[i][1] * 0.5;
    }
}

/* ======================================================================
 * plateau_lm.h: plateau_lm_solve without a workspace (Rosenbrock) */
typedef struct lm_ctx {
    double x[2];
    int numeric;
    plateau_lm_error err;
} lm_ctx;

static int rosenbrock(const double *x, double *f, double *jac, void *user)
{
    (void)user;
    f[0] = 10.0 * (x[1] - x[0] * x[0]);
    f[1] = 1.0 - x[0];
    if (jac) {
        jac[0] = -20.0 * x[0]; jac[1] = 10.0;
        jac[2] = -1.0;         jac[3] = 0.0;
    }
    return 0;
}

static int lm_call(void *vctx, const plateau_allocator *a)
{
    lm_ctx *c = (lm_ctx *)vctx;
    plateau_lm_options opt;
    memset(&opt, 0, sizeof opt);
    opt.allocator = *a;
    opt.numeric_jacobian = c->numeric;
    c->x[0] = -1.2;
    c->x[1] = 1.0;
    return plateau_lm_solve(2, 2, c->x, rosenbrock, NULL, &opt, NULL, 0, NULL, &c->err);
}

static void lm_release(void *vctx, int rc)
{
    lm_ctx *c = (lm_ctx *)vctx;
    CHECK_EQ_INT(c->err.code, rc); /* the error detail names the failure */
    if (rc == PLATEAU_LM_OK) {
        CHECK_NEAR(c->x[0], 1.0, 1e-6);
        CHECK_NEAR(c->x[1], 1.0, 1e-6);
    } else {
        CHECK(c->x[0] == -1.2 && c->x[1] == 1.0); /* untouched */
    }
}

static void test_lm(void)
{
    lm_ctx c;
    countalloc_sweep s;
    countalloc ca;
    plateau_lm_options opt;
    double work[256];
    size_t need;
    memset(&c, 0, sizeof c);
    s.name = "plateau_lm_solve (no workspace)";
    s.call = lm_call;
    s.release = lm_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_LM_OK;
    s.oom_code = PLATEAU_LM_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.numeric = 1;
    s.name = "plateau_lm_solve (no workspace, numeric Jacobian)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    /* with a caller workspace: not one allocation */
    countalloc_init(&ca, 0);
    memset(&opt, 0, sizeof opt);
    opt.allocator = countalloc_allocator(&ca);
    need = plateau_lm_workspace_size(2, 2, &opt);
    CHECK(need > 0 && need <= sizeof work);
    c.x[0] = -1.2;
    c.x[1] = 1.0;
    CHECK_EQ_INT(plateau_lm_solve(2, 2, c.x, rosenbrock, NULL, &opt, work, sizeof work, NULL, NULL),
                 PLATEAU_LM_OK);
    CHECK_EQ_INT(ca.calls, 0);
    printf("alloc points: plateau_lm_solve (caller workspace) %ld\n", ca.calls);
}

/* ======================================================================
 * plateau.h: plateau_mesh_create */
typedef struct mesh_ctx {
    double pos[3 * 9];
    plateau_index tri[3 * 8];
    plateau_mesh mesh;
    double area; /* of the first successful mesh; later ones must agree */
} mesh_ctx;

/* The test mesh: a 3 x 3 grid of vertices (a gentle saddle z = 0.1 x y),
 * 8 triangles; no mesh yet. */
static void mesh_ctx_grid(mesh_ctx *c)
{
    int i, j, t = 0;
    c->area = -1.0;
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            c->pos[3 * (3 * j + i)] = i;
            c->pos[3 * (3 * j + i) + 1] = j;
            c->pos[3 * (3 * j + i) + 2] = 0.1 * i * j;
        }
    for (j = 0; j < 2; j++)
        for (i = 0; i < 2; i++) {
            plateau_index v = (plateau_index)(3 * j + i);
            c->tri[t++] = v; c->tri[t++] = v + 1; c->tri[t++] = v + 4;
            c->tri[t++] = v; c->tri[t++] = v + 4; c->tri[t++] = v + 3;
        }
}

static int mesh_call(void *vctx, const plateau_allocator *a)
{
    mesh_ctx *c = (mesh_ctx *)vctx;
    plateau_error err;
    memset(&c->mesh, 0x5a, sizeof c->mesh);
    return plateau_mesh_create(c->pos, 9, NULL, c->tri, 8, a, &c->mesh, &err);
}

static void mesh_release(void *vctx, int rc)
{
    mesh_ctx *c = (mesh_ctx *)vctx;
    if (rc != PLATEAU_OK) {
        CHECK(c->mesh.positions == NULL && c->mesh.triangles == NULL &&
              c->mesh.neighbors == NULL && c->mesh.fixed == NULL && c->mesh.edges == NULL &&
              c->mesh.num_vertices == 0 && c->mesh.num_triangles == 0);
    } else {
        if (c->area < 0) c->area = plateau_mesh_area(&c->mesh);
        CHECK_NEAR(plateau_mesh_area(&c->mesh), c->area, 0.0);
    }
    plateau_mesh_free(&c->mesh);
}

static void test_mesh_create(void)
{
    mesh_ctx c;
    countalloc_sweep s;
    mesh_ctx_grid(&c);
    s.name = "plateau_mesh_create";
    s.call = mesh_call;
    s.release = mesh_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* plateau_mesh_create then plateau_mesh_build_adjacency on the new mesh:
 * the sweep reaches the rebuild's allocations past the creation's. */
static int mesh_rebuild_call(void *vctx, const plateau_allocator *a)
{
    mesh_ctx *c = (mesh_ctx *)vctx;
    int rc = mesh_call(vctx, a);
    if (rc != PLATEAU_OK) return rc;
    rc = plateau_mesh_build_adjacency(&c->mesh, NULL);
    if (rc != PLATEAU_OK) {
        CHECK(c->mesh.edges == NULL && c->mesh.edge_triangles == NULL &&
              c->mesh.vertex_edges == NULL && c->mesh.vertex_triangles == NULL);
        plateau_mesh_free(&c->mesh);
        memset(&c->mesh, 0, sizeof c->mesh);
    }
    return rc;
}

/* plateau_system_assemble on the grid mesh (made with a separate allocator
 * that never fails), with the tangential rows. */
typedef struct system_ctx {
    plateau_mesh mesh;
    plateau_system system;
    double weight;
} system_ctx;

static int system_call(void *vctx, const plateau_allocator *a)
{
    system_ctx *c = (system_ctx *)vctx;
    plateau_system_options opt;
    memset(&opt, 0, sizeof opt);
    opt.tangential_weight = c->weight;
    memset(&c->system, 0, sizeof c->system);
    c->mesh.allocator = *a; /* the system takes the mesh's allocator */
    return plateau_system_assemble(&c->mesh, &opt, &c->system, NULL);
}

static void system_release(void *vctx, int rc)
{
    system_ctx *c = (system_ctx *)vctx;
    (void)rc;
    plateau_system_free(&c->system);
}

static void test_mesh_rebuild_and_system(void)
{
    mesh_ctx c;
    system_ctx sc;
    countalloc_sweep s;
    countalloc keep;
    plateau_allocator ka;
    mesh_ctx_grid(&c);
    s.name = "plateau_mesh_create + plateau_mesh_build_adjacency";
    s.call = mesh_rebuild_call;
    s.release = mesh_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);

    countalloc_init(&keep, 0);
    ka = countalloc_allocator(&keep);
    memset(&sc, 0, sizeof sc);
    if (!CHECK_EQ_INT(plateau_mesh_create(c.pos, 9, NULL, c.tri, 8, &ka, &sc.mesh, NULL),
                      PLATEAU_OK))
        return;
    s.name = "plateau_system_assemble (H rows)";
    s.call = system_call;
    s.release = system_release;
    s.ctx = &sc;
    CHECK(countalloc_sweep_run(&s) >= 1);
    sc.weight = 0.5;
    s.name = "plateau_system_assemble (H and tangential rows)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    sc.mesh.allocator = ka;
    plateau_mesh_free(&sc.mesh);
    CHECK_EQ_INT(keep.live, 0);
}

/* plateau_mesh_error_indicator on the grid mesh, its border fixed (made
 * with an allocator that never fails; the estimate's split copy takes the
 * mesh's allocator, the one under test). */
typedef struct indicator_ctx {
    plateau_mesh mesh;
    double ind[8], est;
} indicator_ctx;

static int indicator_call(void *vctx, const plateau_allocator *a)
{
    indicator_ctx *c = (indicator_ctx *)vctx;
    c->mesh.allocator = *a;
    return plateau_mesh_error_indicator(&c->mesh, c->ind, &c->est, NULL);
}

static void indicator_release(void *vctx, int rc)
{
    indicator_ctx *c = (indicator_ctx *)vctx;
    if (rc == PLATEAU_OK) CHECK(c->est > 0.0);
}

static void test_error_indicator(void)
{
    static const unsigned char fixed[9] = {1, 1, 1, 1, 0, 1, 1, 1, 1};
    mesh_ctx c;
    indicator_ctx ic;
    countalloc_sweep s;
    countalloc keep;
    plateau_allocator ka;
    mesh_ctx_grid(&c);
    countalloc_init(&keep, 0);
    ka = countalloc_allocator(&keep);
    memset(&ic, 0, sizeof ic);
    if (!CHECK_EQ_INT(plateau_mesh_create(c.pos, 9, fixed, c.tri, 8, &ka, &ic.mesh, NULL), PLATEAU_OK)) return;
    s.name = "plateau_mesh_error_indicator";
    s.call = indicator_call;
    s.release = indicator_release;
    s.ctx = &ic;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
    ic.mesh.allocator = ka;
    plateau_mesh_free(&ic.mesh);
    CHECK_EQ_INT(keep.live, 0);
}

/* ======================================================================
 * plateau.h: plateau_mesh_critical_point (index 1, 6 steps at most) from
 * a coarse catenoid between two rings of 12 vertices at h = 1 (neck 0.3,
 * five rows), made with the allocator under test: the climb's Hessians,
 * flips and splits allocate (the mesh grows from 60 to 84 vertices). */
typedef struct crit_ctx {
    plateau_mesh mesh;
    int converged;
} crit_ctx;

static int crit_call(void *vctx, const plateau_allocator *a)
{
    crit_ctx *c = (crit_ctx *)vctx;
    double pos[3 * 60];
    plateau_index tri[3 * 96];
    int r, i, k = 0;
    for (r = 0; r < 5; r++) {
        double z = -0.5 + 0.25 * r, rad = r == 0 || r == 4 ? 1.0 : 0.3 * cosh(z / 0.3);
        for (i = 0; i < 12; i++) {
            double t = 6.283185307179586 * (i + 0.5 * (r % 2)) / 12;
            pos[3 * (12 * r + i)] = rad * cos(t);
            pos[3 * (12 * r + i) + 1] = rad * sin(t);
            pos[3 * (12 * r + i) + 2] = z;
        }
    }
    for (r = 0; r < 4; r++)
        for (i = 0; i < 12; i++) {
            plateau_index a0 = (plateau_index)(12 * r + i), a1 = (plateau_index)(12 * r + (i + 1) % 12);
            plateau_index b0 = (plateau_index)(12 * (r + 1) + i), b1 = (plateau_index)(12 * (r + 1) + (i + 1) % 12);
            if (r % 2 == 0) {
                tri[k++] = a0; tri[k++] = a1; tri[k++] = b0;
                tri[k++] = a1; tri[k++] = b1; tri[k++] = b0;
            } else {
                tri[k++] = a0; tri[k++] = b1; tri[k++] = b0;
                tri[k++] = a0; tri[k++] = a1; tri[k++] = b1;
            }
        }
    memset(&c->mesh, 0, sizeof c->mesh);
    c->converged = -1;
    r = plateau_mesh_create(pos, 60, NULL, tri, 96, a, &c->mesh, NULL);
    if (r != PLATEAU_OK) return r;
    return plateau_mesh_critical_point(&c->mesh, 1, 6, NULL, &c->converged, NULL, NULL);
}

static void crit_release(void *vctx, int rc)
{
    crit_ctx *c = (crit_ctx *)vctx;
    if (rc == PLATEAU_OK) CHECK(c->converged == 0 || c->converged == 1);
    plateau_mesh_free(&c->mesh);
}

static void test_critical_point(void)
{
    crit_ctx c;
    countalloc_sweep s;
    s.name = "plateau_mesh_critical_point";
    s.call = crit_call;
    s.release = crit_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* ======================================================================
 * plateau.h: plateau_boundary_domain, plateau_seed_points */
typedef struct boundary_ctx {
    double xyz[3 * 12], uv[2 * 12];
    double sxyz[3 * 40], suv[2 * 40];
    size_t n, count;
    int force_circle;
} boundary_ctx;

static int domain_call(void *vctx, const plateau_allocator *a)
{
    boundary_ctx *c = (boundary_ctx *)vctx;
    plateau_domain_kind kind;
    return plateau_boundary_domain(c->xyz, 12, c->force_circle, a, c->uv, &kind, NULL);
}

static int seed_call(void *vctx, const plateau_allocator *a)
{
    boundary_ctx *c = (boundary_ctx *)vctx;
    return plateau_seed_points(c->xyz, c->uv, 12, c->n, 7, a, c->sxyz, c->suv, &c->count, NULL);
}

static void nothing_to_release(void *vctx, int rc)
{
    (void)vctx;
    (void)rc;
}

static void test_boundary(void)
{
    boundary_ctx c;
    countalloc_sweep s;
    plateau_domain_kind kind;
    memset(&c, 0, sizeof c);
    saddle(c.xyz);
    s.release = nothing_to_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;

    /* the domain's crossing tests (in space, then in the plane) sort their
     * grid entries in scratch memory */
    s.name = "plateau_boundary_domain";
    s.call = domain_call;
    CHECK(countalloc_sweep_run(&s) >= 4);
    c.force_circle = 1;
    s.name = "plateau_boundary_domain (circle)";
    CHECK(countalloc_sweep_run(&s) >= 2);

    {
        countalloc ca;
        plateau_allocator a;
        countalloc_init(&ca, 0);
        a = countalloc_allocator(&ca);
        CHECK_EQ_INT(plateau_boundary_domain(c.xyz, 12, 0, &a, c.uv, &kind, NULL), PLATEAU_OK);
        CHECK_EQ_INT(ca.live, 0);
    }
    s.call = seed_call;
    c.n = 5;
    s.name = "plateau_seed_points (n = 5)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.n = 40;
    s.name = "plateau_seed_points (n = 40)";
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* ======================================================================
 * plateau.h: plateau_parse_boundary, plateau_read_boundary_file */
typedef struct parse_ctx {
    const char *text;
    const char *path; /* NULL: parse text */
    double *xyz;
    size_t m;
    countalloc *ca;
    plateau_allocator a;
} parse_ctx;

static int parse_call(void *vctx, const plateau_allocator *a)
{
    parse_ctx *c = (parse_ctx *)vctx;
    c->a = *a;
    c->ca = (countalloc *)a->user_data;
    c->xyz = (double *)c; /* must be overwritten */
    c->m = 99;
    if (c->path) return plateau_read_boundary_file(c->path, a, &c->xyz, &c->m, NULL);
    return plateau_parse_boundary(c->text, strlen(c->text), a, &c->xyz, &c->m, NULL);
}

static void parse_release(void *vctx, int rc)
{
    parse_ctx *c = (parse_ctx *)vctx;
    if (rc != PLATEAU_OK) {
        CHECK(c->xyz == NULL && c->m == 0); /* documented: nothing to free on error */
    } else {
        CHECK_EQ_INT(c->m, 40);
    }
    plateau_boundary_free(c->xyz, &c->a);
}

static void test_parse(void)
{
    char text[40 * 64];
    size_t len = 0;
    int i;
    parse_ctx c;
    countalloc_sweep s;
    FILE *f;
    for (i = 0; i < 40; i++)
        len += (size_t)sprintf(text + len, "%s%.17g %.17g %.17g\n", i % 7 ? "" : "# c\n",
                               cos(0.1 * i), sin(0.1 * i), 0.01 * i * i);
    memset(&c, 0, sizeof c);
    c.text = text;
    s.name = "plateau_parse_boundary (40 vertices)";
    s.call = parse_call;
    s.release = parse_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);

    f = fopen("build/test_alloc_fail_boundary.txt", "wb");
    if (!CHECK(f != NULL)) return;
    CHECK(fwrite(text, 1, len, f) == len);
    fclose(f);
    c.path = "build/test_alloc_fail_boundary.txt";
    s.name = "plateau_read_boundary_file (40 vertices)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    remove(c.path);
}

/* ======================================================================
 * plateau.h: plateau_parse_mesh, plateau_read_mesh_file (OBJ with quads),
 * plateau_write_mesh_marked (OBJ's loops, PLY's computed marks) */
typedef struct mesh_io_ctx {
    const char *text;
    const char *path;  /* read this file (NULL: parse text) */
    const char *out;   /* write this file (NULL: read) */
    double *p;
    plateau_index *t;
    long *lines;
    size_t nv, nt;
    plateau_allocator a;
} mesh_io_ctx;

static int mesh_io_call(void *vctx, const plateau_allocator *a)
{
    static const double p[27] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0.1, 2, 1, 0.2, 0, 2, 0, 1, 2, 0.2, 2, 2, 0.4};
    static const plateau_index t[24] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};
    static const unsigned char marks[9] = {1, 2, 1, 1, 0, 1, 1, 1, 1};
    mesh_io_ctx *c = (mesh_io_ctx *)vctx;
    c->a = *a;
    c->p = (double *)c; /* must be overwritten */
    c->t = (plateau_index *)c;
    c->lines = (long *)c;
    c->nv = c->nt = 99;
    if (c->out)
        return plateau_write_mesh_marked(c->out, p, 9, t, 8, strstr(c->out, ".obj") ? marks : NULL,
                                         PLATEAU_MESH_FORMAT_AUTO, a, NULL);
    if (c->path) return plateau_read_mesh_file(c->path, a, &c->p, &c->nv, &c->t, &c->nt, NULL);
    return plateau_parse_mesh(c->text, strlen(c->text), a, &c->p, &c->nv, &c->t, &c->nt, &c->lines, NULL);
}

static void mesh_io_release(void *vctx, int rc)
{
    mesh_io_ctx *c = (mesh_io_ctx *)vctx;
    FILE *f;
    if (c->out) {
        f = fopen(c->out, "rb");
        CHECK((rc == PLATEAU_OK) == (f != NULL)); /* nothing written on an error */
        if (f) fclose(f);
        remove(c->out);
        return;
    }
    if (c->path) c->lines = NULL;
    if (rc != PLATEAU_OK) {
        CHECK(c->p == NULL && c->t == NULL && c->lines == NULL && c->nv == 0 && c->nt == 0);
    } else {
        CHECK(c->nv == 40 && c->nt == 40); /* 19 quads, 2 triangles */
    }
    plateau_mesh_arrays_free(c->p, c->t, c->lines, &c->a);
}

static void test_mesh_io(void)
{
    char text[40 * 80];
    size_t len = 0;
    int i;
    mesh_io_ctx c;
    countalloc_sweep s;
    FILE *f;
    for (i = 0; i < 40; i++) len += (size_t)sprintf(text + len, "v %.17g %.17g %.17g\n", 0.1 * (i / 2), 0.1 * (i % 2), 0.01 * i);
    for (i = 0; i + 3 < 40; i += 2) len += (size_t)sprintf(text + len, "f %d %d %d %d\n", i + 1, i + 3, i + 4, i + 2);
    len += (size_t)sprintf(text + len, "f 39 40 38\nf 1 2 -38\n");
    memset(&c, 0, sizeof c);
    c.text = text;
    s.name = "plateau_parse_mesh (40 vertices)";
    s.call = mesh_io_call;
    s.release = mesh_io_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
    f = fopen("build/test_alloc_fail_mesh.obj", "wb");
    if (!CHECK(f != NULL)) return;
    CHECK(fwrite(text, 1, len, f) == len);
    fclose(f);
    c.path = "build/test_alloc_fail_mesh.obj";
    s.name = "plateau_read_mesh_file (40 vertices)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    remove(c.path);
    c.path = NULL;
    c.out = "build/test_alloc_fail_marked.obj";
    s.name = "plateau_write_mesh_marked (OBJ)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.out = "build/test_alloc_fail_marked.ply";
    s.name = "plateau_write_mesh_marked (PLY, computed marks)";
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* ======================================================================
 * plateau_delaunay.h: plateau_dt_triangulate */
typedef struct dt_ctx {
    double pts[2 * 64];
    plateau_index segs[2 * 32];
    size_t np, ns;
    int hull, split;
    double min_angle, max_area;
    plateau_dt_mesh mesh;
    plateau_dt_error err;
} dt_ctx;

static int dt_call(void *vctx, const plateau_allocator *a)
{
    dt_ctx *c = (dt_ctx *)vctx;
    plateau_dt_input in;
    plateau_dt_options opt;
    memset(&opt, 0, sizeof opt);
    opt.allocator = *a;
    opt.keep_convex_hull = c->hull;
    opt.split_crossing_segments = c->split;
    opt.min_angle = c->min_angle;
    opt.max_area = c->max_area;
    in.points = c->pts;
    in.num_points = c->np;
    in.segments = c->ns ? c->segs : NULL;
    in.num_segments = c->ns;
    memset(&c->mesh, 0x5a, sizeof c->mesh);
    return plateau_dt_triangulate(&in, &opt, &c->mesh, &c->err);
}

static void dt_release(void *vctx, int rc)
{
    dt_ctx *c = (dt_ctx *)vctx;
    CHECK_EQ_INT(c->err.code, rc); /* the error detail names the failure */
    if (rc != PLATEAU_DT_OK) {
        /* documented: on error the mesh is all zero */
        CHECK(c->mesh.num_points == 0 && c->mesh.points == NULL &&
              c->mesh.duplicate_of == NULL && c->mesh.num_triangles == 0 &&
              c->mesh.triangles == NULL && c->mesh.neighbors == NULL &&
              c->mesh.constrained == NULL);
    }
    plateau_dt_free(&c->mesh);
}

static void test_dt(void)
{
    const double pi = 3.14159265358979323846;
    dt_ctx c;
    countalloc_sweep s;
    size_t i;
    memset(&c, 0, sizeof c);
    /* a constrained 24-gon with a square hole and 20 points between */
    for (i = 0; i < 24; i++) {
        double t = 2 * pi * (double)i / 24.0;
        c.pts[2 * i] = cos(t);
        c.pts[2 * i + 1] = sin(t);
        c.segs[2 * i] = (plateau_index)i;
        c.segs[2 * i + 1] = (plateau_index)((i + 1) % 24);
    }
    for (i = 0; i < 4; i++) {
        c.pts[2 * (24 + i)] = (i == 1 || i == 2) ? 0.2 : -0.2;
        c.pts[2 * (24 + i) + 1] = (i >= 2) ? 0.2 : -0.2;
        c.segs[2 * (24 + i)] = (plateau_index)(24 + i);
        c.segs[2 * (24 + i) + 1] = (plateau_index)(24 + (i + 1) % 4);
    }
    c.np = 28;
    c.ns = 28;
    for (i = 0; i < 20; i++) {
        double t = 2 * pi * (double)i / 20.0 + 0.1, r = 0.45 + 0.3 * (double)(i % 3) / 2.0;
        c.pts[2 * c.np] = r * cos(t);
        c.pts[2 * c.np + 1] = r * sin(t);
        c.np++;
    }
    c.pts[2 * c.np] = c.pts[2 * 30]; /* a duplicate */
    c.pts[2 * c.np + 1] = c.pts[2 * 30 + 1];
    c.np++;
    s.name = "plateau_dt_triangulate (polygon with a hole, 49 points)";
    s.call = dt_call;
    s.release = dt_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_DT_OK;
    s.oom_code = PLATEAU_DT_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.min_angle = 28.0;
    s.name = "plateau_dt_triangulate (polygon with a hole, refined to 28 degrees)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.min_angle = 0.0;
    c.max_area = 0.002;
    s.name = "plateau_dt_triangulate (polygon with a hole, refined to area 0.002)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.max_area = 0.0;
    c.ns = 0;
    c.hull = 1;
    s.name = "plateau_dt_triangulate (49 points, the hull)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    /* a star of 8 segments through the centre of a 16-gon, all crossing:
     * split at the crossings */
    memset(&c, 0, sizeof c);
    for (i = 0; i < 16; i++) {
        double t = 2 * pi * (double)i / 16.0 + 0.05;
        c.pts[2 * i] = cos(t);
        c.pts[2 * i + 1] = sin(t);
    }
    c.np = 16;
    for (i = 0; i < 8; i++) {
        c.segs[2 * i] = (plateau_index)i;
        c.segs[2 * i + 1] = (plateau_index)((i + 5) % 16);
    }
    c.ns = 8;
    c.hull = 1;
    c.split = 1;
    s.name = "plateau_dt_triangulate (8 crossing segments, split)";
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* ======================================================================
 * plateau.h: plateau_solve for each method, plateau_mesh_minimize,
 * plateau_mesh_delaunay_flips */
typedef struct solve_ctx {
    double xyz[3 * 12];
    plateau_method method;
    plateau_mesh mesh;
    double area; /* of the first successful solve */
    int quality; /* 1 the quality seeding, 2 with refine_boundary */
    int linear_solver; /* method paper: a plateau_linear_solver */
    int warm_start;    /* options.area_warm_start */
    int c2f;           /* 1: coarse to fine ON, n = 450 (a coarse mesh and two levels) */
    double accuracy;   /* > 0: options.accuracy from n = 40 (two solves) */
} solve_ctx;

static int solve_call(void *vctx, const plateau_allocator *a)
{
    solve_ctx *c = (solve_ctx *)vctx;
    plateau_options opt;
    memset(&opt, 0, sizeof opt);
    opt.method = c->method;
    opt.interior_points = 6;
    opt.max_rounds = 3;
    opt.allocator = *a;
    opt.linear_solver = c->linear_solver;
    opt.area_warm_start = c->warm_start;
    if (c->quality) {
        opt.seeding = PLATEAU_SEEDING_QUALITY;
        opt.refine_boundary = c->quality == 2 ? PLATEAU_ON : PLATEAU_AUTO;
        opt.interior_points = c->quality == 2 ? 40 : 6;
    }
    if (c->c2f) {
        opt.coarse_to_fine = PLATEAU_ON;
        opt.interior_points = 450;
    }
    if (c->accuracy > 0.0) {
        opt.interior_points = 40;
        opt.accuracy = c->accuracy;
    }
    memset(&c->mesh, 0x5a, sizeof c->mesh);
    if (c->c2f || c->accuracy > 0.0) {
        plateau_report rep;
        int rc = plateau_solve(c->xyz, 12, &opt, &c->mesh, &rep, NULL);
        if (rc == PLATEAU_OK && c->c2f) CHECK_EQ_INT((int)rep.levels, 2); /* the path under test ran */
        if (rc == PLATEAU_OK && c->accuracy > 0.0) CHECK_EQ_INT((int)rep.accuracy_solves, 2);
        return rc;
    }
    return plateau_solve(c->xyz, 12, &opt, &c->mesh, NULL, NULL);
}

static void solve_release(void *vctx, int rc)
{
    solve_ctx *c = (solve_ctx *)vctx;
    if (rc == PLATEAU_OK) {
        double area = plateau_mesh_area(&c->mesh);
        if (c->area < 0) c->area = area;
        CHECK_NEAR(area, c->area, 0.0); /* bit-identical every time */
    } else {
        /* documented: free it also after an error (zero, or the last mesh) */
        CHECK((c->mesh.positions == NULL && c->mesh.num_vertices == 0 &&
               c->mesh.triangles == NULL && c->mesh.num_triangles == 0 &&
               c->mesh.fixed == NULL && c->mesh.neighbors == NULL) ||
              (c->mesh.num_vertices >= 12 && c->mesh.positions != NULL));
    }
    plateau_mesh_free(&c->mesh);
}

/* minimize and flips work on a mesh made first (through the same allocator,
 * so the sweep covers its creation too). */
static int minimize_call(void *vctx, const plateau_allocator *a)
{
    solve_ctx *c = (solve_ctx *)vctx;
    plateau_options opt;
    plateau_result rc;
    static const double pos[] = {0, 0, 0, 1, 0, 0.3, 2, 0, 0, 0, 1, 0.3, 1, 1, 0.9, 2, 1, 0.3,
                                 0, 2, 0, 1, 2, 0.3, 2, 2, 0};
    static const plateau_index tri[] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4,
                                        3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};
    memset(&c->mesh, 0, sizeof c->mesh);
    rc = plateau_mesh_create(pos, 9, NULL, tri, 8, a, &c->mesh, NULL);
    if (rc != PLATEAU_OK) return rc;
    if (c->method == (plateau_method)-1) {
        size_t flips;
        return plateau_mesh_delaunay_flips(&c->mesh, 0, &flips, NULL);
    }
    memset(&opt, 0, sizeof opt);
    opt.method = c->method;
    opt.max_rounds = 3;
    opt.allocator = *a;
    opt.linear_solver = c->linear_solver;
    return plateau_mesh_minimize(&c->mesh, &opt, NULL, NULL);
}

/* A square with a free vertex 1e-6 above its bottom side: the triangle
 * below it is a sliver, and the vertex is collapsed away. */
static int remove_call(void *vctx, const plateau_allocator *a)
{
    solve_ctx *c = (solve_ctx *)vctx;
    plateau_result rc;
    size_t removed = 0;
    static const double pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 1e-6, 0};
    static const plateau_index tri[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    memset(&c->mesh, 0, sizeof c->mesh);
    rc = plateau_mesh_create(pos, 5, NULL, tri, 4, a, &c->mesh, NULL);
    if (rc != PLATEAU_OK) return rc;
    rc = plateau_mesh_remove_degenerate(&c->mesh, 0.0, &removed, NULL);
    if (rc == PLATEAU_OK) CHECK_EQ_INT(removed, 1);
    return rc;
}

static void minimize_release(void *vctx, int rc)
{
    solve_ctx *c = (solve_ctx *)vctx;
    (void)rc;
    plateau_mesh_free(&c->mesh);
}

static void test_solve(void)
{
    static const double xy[12][2] = {{-1, -1}, {-1.0 / 3, -1}, {1.0 / 3, -1}, {1, -1},
                                     {1, -1.0 / 3}, {1, 1.0 / 3}, {1, 1}, {1.0 / 3, 1},
                                     {-1.0 / 3, 1}, {-1, 1}, {-1, 1.0 / 3}, {-1, -1.0 / 3}};
    static const char *names[3] = {"plateau_solve (paper, m = 12, n = 6)",
                                   "plateau_solve (paper-literal, m = 12, n = 6)",
                                   "plateau_solve (area, m = 12, n = 6)"};
    static const char *min_names[3] = {"plateau_mesh_create + plateau_mesh_minimize (paper)",
                                       "plateau_mesh_create + plateau_mesh_minimize (paper-literal)",
                                       "plateau_mesh_create + plateau_mesh_minimize (area)"};
    solve_ctx c;
    countalloc_sweep s;
    int i, method;
    memset(&c, 0, sizeof c);
    for (i = 0; i < 12; i++) {
        c.xyz[3 * i] = xy[i][0];
        c.xyz[3 * i + 1] = xy[i][1];
        c.xyz[3 * i + 2] = 0.5 * xy[i][0] * xy[i][1];
    }
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    for (method = 0; method < 3; method++) {
        c.method = (plateau_method)method;
        c.area = -1.0;
        s.name = names[method];
        s.call = solve_call;
        s.release = solve_release;
        CHECK(countalloc_sweep_run(&s) >= 1);
        s.name = min_names[method];
        s.call = minimize_call;
        s.release = minimize_release;
        CHECK(countalloc_sweep_run(&s) >= 1);
    }
    /* the quality seeding: the refinement's searches, the
     * mean-value mapping, and the vertices added on the boundary */
    s.call = solve_call;
    s.release = solve_release;
    for (i = 1; i <= 2; i++) {
        for (method = 0; method < 3; method += 2) {
            c.method = (plateau_method)method;
            c.quality = i;
            c.area = -1.0;
            s.name = i == 1 ? (method ? "plateau_solve (area, quality seeding, n = 6)"
                                      : "plateau_solve (paper, quality seeding, n = 6)")
                            : (method ? "plateau_solve (area, quality seeding, refine_boundary, n = 40)"
                                      : "plateau_solve (paper, quality seeding, refine_boundary, n = 40)");
            CHECK(countalloc_sweep_run(&s) >= 1);
        }
    }
    /* method paper on the sparse path (block pattern, ordering, factor,
     * the dog leg's vectors) */
    c.method = PLATEAU_METHOD_PAPER;
    c.linear_solver = PLATEAU_LINEAR_SPARSE;
    for (i = 0; i <= 2; i++) {
        c.quality = i;
        c.area = -1.0;
        s.name = i == 0 ? "plateau_solve (paper, sparse, m = 12, n = 6)"
               : i == 1 ? "plateau_solve (paper, sparse, quality seeding, n = 6)"
                        : "plateau_solve (paper, sparse, quality seeding, refine_boundary, n = 40)";
        CHECK(countalloc_sweep_run(&s) >= 1);
    }
    s.name = "plateau_mesh_create + plateau_mesh_minimize (paper, sparse)";
    s.call = minimize_call;
    s.release = minimize_release;
    CHECK(countalloc_sweep_run(&s) >= 1);
    /* method area on the sparse path (the Newton method's pattern,
     * analysis, Cholesky factor, Hessian blocks and vectors) */
    c.method = PLATEAU_METHOD_AREA;
    s.call = solve_call;
    s.release = solve_release;
    for (i = 0; i <= 2; i++) {
        c.quality = i;
        c.area = -1.0;
        s.name = i == 0 ? "plateau_solve (area, sparse, m = 12, n = 6)"
               : i == 1 ? "plateau_solve (area, sparse, quality seeding, n = 6)"
                        : "plateau_solve (area, sparse, quality seeding, refine_boundary, n = 40)";
        CHECK(countalloc_sweep_run(&s) >= 1);
    }
    /* the Pinkall-Polthier start (its pattern, analysis and Cholesky) */
    c.quality = 0;
    c.warm_start = 1;
    c.area = -1.0;
    s.name = "plateau_solve (area, sparse, Pinkall-Polthier start, m = 12, n = 6)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.warm_start = 0;
    /* coarse to fine: the coarse mesh, each subdivision, each level's
     * pattern, analysis, factor and vectors, method paper's last level */
    c.linear_solver = PLATEAU_LINEAR_AUTO;
    c.c2f = 1;
    for (method = 0; method < 3; method += 2) {
        c.method = (plateau_method)method;
        c.area = -1.0;
        s.name = method ? "plateau_solve (area, coarse to fine, n = 450)"
                        : "plateau_solve (paper, coarse to fine, n = 450)";
        CHECK(countalloc_sweep_run(&s) >= 1);
    }
    c.c2f = 0;
    /* the accuracy's second solve: the loop that keeps the better of
     * two meshes and frees the other on every failure */
    c.method = PLATEAU_METHOD_PAPER;
    c.accuracy = 1.5e-3;
    c.area = -1.0;
    s.name = "plateau_solve (paper, accuracy 1.5e-3: a second solve)";
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.accuracy = 0.0;
    c.method = PLATEAU_METHOD_AREA;
    c.linear_solver = PLATEAU_LINEAR_SPARSE;
    s.name = "plateau_mesh_create + plateau_mesh_minimize (area, sparse)";
    s.call = minimize_call;
    s.release = minimize_release;
    CHECK(countalloc_sweep_run(&s) >= 1);
    c.linear_solver = PLATEAU_LINEAR_AUTO;
    c.quality = 0;
    s.call = minimize_call;
    s.release = minimize_release;
    c.method = (plateau_method)-1;
    s.name = "plateau_mesh_create + plateau_mesh_delaunay_flips";
    CHECK(countalloc_sweep_run(&s) >= 1);
    s.name = "plateau_mesh_create + plateau_mesh_remove_degenerate";
    s.call = remove_call;
    CHECK(countalloc_sweep_run(&s) >= 1);
}

/* ======================================================================
 * plateau.h: the membranes (options.cable_tension, pressure, fix_volume)
 * through plateau_solve: cables on the square (side 2, T = 2), a pressure
 * of 1 and a held volume from a first guess above any spanning pressure
 * (2.5 on the 12-gon) on the unit circle; method area, n = 10 or 20. */
typedef struct membrane_ctx {
    int kind; /* 0 cables, 1 pressure, 2 held volume */
    plateau_mesh mesh;
    double area; /* of the first successful solve */
} membrane_ctx;

static int membrane_call(void *vctx, const plateau_allocator *a)
{
    membrane_ctx *c = (membrane_ctx *)vctx;
    static const double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    static const double tension[4] = {2, 2, 2, 2};
    double xyz[3 * 12];
    plateau_options opt;
    int i;
    memset(&opt, 0, sizeof opt);
    opt.method = PLATEAU_METHOD_AREA;
    opt.interior_points = 10;
    opt.allocator = *a;
    memset(&c->mesh, 0x5a, sizeof c->mesh);
    if (c->kind == 0) {
        opt.cable_tension = tension;
        opt.interior_points = 20;
        return plateau_solve(sq, 4, &opt, &c->mesh, NULL, NULL);
    }
    for (i = 0; i < 12; i++) {
        xyz[3 * i] = cos(6.283185307179586 * i / 12.0);
        xyz[3 * i + 1] = sin(6.283185307179586 * i / 12.0);
        xyz[3 * i + 2] = 0.0;
    }
    opt.pressure = c->kind == 1 ? 1.0 : 2.5;
    opt.fix_volume = c->kind == 2;
    opt.volume = 0.3;
    return plateau_solve(xyz, 12, &opt, &c->mesh, NULL, NULL);
}

static void membrane_release(void *vctx, int rc)
{
    membrane_ctx *c = (membrane_ctx *)vctx;
    if (rc == PLATEAU_OK) {
        double area = plateau_mesh_area(&c->mesh);
        if (c->area < 0) c->area = area;
        CHECK_NEAR(area, c->area, 0.0); /* a refused allocation is never worked around */
    }
    plateau_mesh_free(&c->mesh);
}

static void test_membranes(void)
{
    static const char *names[3] = {"plateau_solve (area, four cables, n = 20)",
                                   "plateau_solve (area, pressure 1, n = 10)",
                                   "plateau_solve (area, held volume from p = 2.5, n = 10)"};
    membrane_ctx c;
    countalloc_sweep s;
    int kind;
    for (kind = 0; kind < 3; kind++) {
        memset(&c, 0, sizeof c);
        c.kind = kind;
        c.area = -1.0;
        s.name = names[kind];
        s.call = membrane_call;
        s.release = membrane_release;
        s.ctx = &c;
        s.ok_code = PLATEAU_OK;
        s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
        CHECK(countalloc_sweep_run(&s) >= 1);
    }
}

/* ======================================================================
 * plateau_write_svg through its allocator argument; the compile-time hooks:
 * plateau_write_svg with a NULL allocator (PLATEAU_MALLOC with a NULL
 * context), and plateau_solve with an allocator that has only user_data
 * (PLATEAU_MALLOC with that context). */
static const double svg_pos[] = {0, 0, 0, 1, 0, 0.2, 1, 1, 0, 0, 1, 0.2, 0.5, 0.5, 0.5};
static const plateau_index svg_tri[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

static int svg_call(void *vctx, const plateau_allocator *a)
{
    (void)vctx;
    return plateau_write_svg("build/test_alloc_fail.svg", svg_pos, 5, svg_tri, 4, NULL, a, NULL);
}

static int svg_macro_call(void *vctx, const plateau_allocator *a)
{
    int rc;
    (void)vctx;
    macro_target = (countalloc *)a->user_data;
    rc = plateau_write_svg("build/test_alloc_fail.svg", svg_pos, 5, svg_tri, 4, NULL, NULL, NULL);
    macro_target = &macro_default;
    return rc;
}

static void svg_release(void *vctx, int rc)
{
    (void)vctx;
    (void)rc;
    remove("build/test_alloc_fail.svg");
}

static int solve_context_call(void *vctx, const plateau_allocator *a)
{
    solve_ctx *c = (solve_ctx *)vctx;
    plateau_options opt;
    memset(&opt, 0, sizeof opt);
    opt.interior_points = 6;
    opt.max_rounds = 3;
    opt.allocator.user_data = a->user_data; /* no functions: the macros, with this context */
    memset(&c->mesh, 0x5a, sizeof c->mesh);
    return plateau_solve(c->xyz, 12, &opt, &c->mesh, NULL, NULL);
}

static void test_macro_hooks(void)
{
    static const double xy[12][2] = {{-1, -1}, {-1.0 / 3, -1}, {1.0 / 3, -1}, {1, -1},
                                     {1, -1.0 / 3}, {1, 1.0 / 3}, {1, 1}, {1.0 / 3, 1},
                                     {-1.0 / 3, 1}, {-1, 1}, {-1, 1.0 / 3}, {-1, -1.0 / 3}};
    solve_ctx c;
    countalloc_sweep s;
    int i;
    memset(&c, 0, sizeof c);
    for (i = 0; i < 12; i++) {
        c.xyz[3 * i] = xy[i][0];
        c.xyz[3 * i + 1] = xy[i][1];
        c.xyz[3 * i + 2] = 0.5 * xy[i][0] * xy[i][1];
    }
    c.area = -1.0;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    s.name = "plateau_write_svg";
    s.call = svg_call;
    s.release = svg_release;
    s.ctx = &c;
    CHECK(countalloc_sweep_run(&s) >= 1);
    s.name = "plateau_write_svg (PLATEAU_MALLOC)";
    s.call = svg_macro_call;
    CHECK(countalloc_sweep_run(&s) >= 1);
    s.name = "plateau_solve (paper; PLATEAU_MALLOC with the allocator's user_data)";
    s.call = solve_context_call;
    s.release = solve_release;
    CHECK(countalloc_sweep_run(&s) >= 1);
    CHECK_EQ_INT(macro_default.live, 0);
}

/* ======================================================================
 * plateau_pattern_make (a closed cone cut by planes through its axis, the
 * spacing searched: several builds) and its writers, which allocate
 * through the pattern's allocator. */
typedef struct pattern_ctx {
    double xyz[3 * 5 * 12];
    plateau_index tri[3 * 2 * 4 * 12];
    plateau_pattern p;
} pattern_ctx;

static int pattern_call(void *vctx, const plateau_allocator *a)
{
    pattern_ctx *c = (pattern_ctx *)vctx;
    plateau_pattern_options o;
    int rc;
    memset(&o, 0, sizeof o);
    o.width = 0.6;
    o.seams = PLATEAU_SEAMS_AXIS;
    o.direction[2] = 1.0;
    o.seams = PLATEAU_SEAMS_PARALLEL; /* planes normal to x: the width function too */
    o.width = 2.0;
    o.direction[0] = 1.0;
    o.direction[2] = 0.0;
    rc = plateau_pattern_make(c->xyz, 60, c->tri, 96, &o, a, &c->p, NULL);
    plateau_pattern_free(&c->p);
    if (rc != PLATEAU_OK) return rc;
    o.seams = PLATEAU_SEAMS_AXIS;
    o.width = 0.6;
    o.direction[0] = 0.0;
    o.direction[2] = 1.0;
    rc = plateau_pattern_make(c->xyz, 60, c->tri, 96, &o, a, &c->p, NULL);
    if (rc == PLATEAU_OK) rc = plateau_pattern_write_svg("build/test_alloc_fail_pattern.svg", &c->p, 0.2, NULL);
    if (rc == PLATEAU_OK) rc = plateau_pattern_write_dxf("build/test_alloc_fail_pattern.dxf", &c->p, 0.2, NULL);
    return rc;
}

static void pattern_release(void *vctx, int rc)
{
    pattern_ctx *c = (pattern_ctx *)vctx;
    (void)rc;
    plateau_pattern_free(&c->p);
    CHECK(c->p.panels == NULL && c->p.num_panels == 0);
    remove("build/test_alloc_fail_pattern.svg");
    remove("build/test_alloc_fail_pattern.dxf");
}

static void test_pattern(void)
{
    pattern_ctx c;
    countalloc_sweep s;
    size_t i, j, k = 0;
    memset(&c, 0, sizeof c);
    for (i = 0; i < 5; i++)
        for (j = 0; j < 12; j++) {
            double r = 0.5 + 0.3 * (double)i, t = 6.283185307179586 * (double)j / 12.0;
            c.xyz[3 * (12 * i + j)] = 0.5 * r * cos(t);
            c.xyz[3 * (12 * i + j) + 1] = 0.5 * r * sin(t);
            c.xyz[3 * (12 * i + j) + 2] = 0.8660254037844386 * r;
        }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 12; j++) {
            plateau_index a = (plateau_index)(12 * i + j), b = (plateau_index)(12 * i + (j + 1) % 12);
            plateau_index d = (plateau_index)(a + 12), e = (plateau_index)(b + 12);
            plateau_index t[6];
            t[0] = a; t[1] = b; t[2] = e; t[3] = a; t[4] = e; t[5] = d;
            memcpy(c.tri + 6 * k++, t, sizeof t);
        }
    s.name = "plateau_pattern_make and its writers";
    s.call = pattern_call;
    s.release = pattern_release;
    s.ctx = &c;
    s.ok_code = PLATEAU_OK;
    s.oom_code = PLATEAU_ERR_OUT_OF_MEMORY;
    CHECK(countalloc_sweep_run(&s) >= 1);
}

int main(void)
{
    RUN(test_lm);
    RUN(test_mesh_create);
    RUN(test_mesh_rebuild_and_system);
    RUN(test_error_indicator);
    RUN(test_critical_point);
    RUN(test_membranes);
    RUN(test_boundary);
    RUN(test_parse);
    RUN(test_mesh_io);
    RUN(test_dt);
    RUN(test_solve);
    RUN(test_macro_hooks);
    RUN(test_pattern);
    CHECK_EQ_INT(countalloc_lost_context, 0);
    return harness_report("test_alloc_fail");
}
