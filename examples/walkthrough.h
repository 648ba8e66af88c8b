/* walkthrough.h - the step-by-step page of make demo (out/walkthrough.html):
 * the paper's algorithm (section II, Fig. 1) on its helicoid and catenoid,
 * one panel per step, every picture inline SVG and every number taken from
 * a report of the library.  Shared by examples/walkthrough.c (which writes
 * the page) and tests/test_walkthrough.c (which reads it back).  Not part of
 * the library.  Include it after plateau.h and surfaces.h.
 *
 *   wt_collect()     runs the steps for one case through the public API
 *   wt_write_html()  the page, to a stream
 *   wt_free()        frees what wt_collect made
 *
 * How the per-round meshes are obtained without a hook in the library:
 * plateau_solve is deterministic and its round k does not depend on
 * max_rounds, so the solve stopped at options.max_rounds = k returns the
 * mesh of round k after its LM solve, before its flips; the run stopped at
 * k + 1 has the triangulation those flips made (its solve moves vertices,
 * never edges).  The positions of the first with the triangles of the
 * second are the mesh after round k; the edges new in the second are the
 * flipped ones.  The start (steps 2 to 4) is made with the public steps
 * (demo_initial_mesh_uv), and wt_collect checks that its edges are
 * plateau_solve's.  The F curve comes from options.progress (round,
 * iteration, F), which already says all the chart needs. */
#ifndef PLATEAU_DEMO_WALKTHROUGH_H
#define PLATEAU_DEMO_WALKTHROUGH_H

#define WT_MAX_ROUNDS 16
#define WT_MAX_RECORDS 2048
#define WT_MAX_LEVELS 4
#define WT_MAX_CANDIDATES 4096

/* Everything the page shows for one case. */
typedef struct wt_case {
    const demo_case *c;
    size_t m, n;                  /* polygon vertices, interior points of the start */
    double boundary[3 * DEMO_MAX_BOUNDARY];
    double *uv;                   /* 2 (m + n): domain points of the start's vertices */
    plateau_mesh start;           /* steps 2-4: the lifted start mesh */
    double start_hmax;            /* largest |H_i| over its interior vertices */
    /* candidates (II.A) in the domain, levels 0 .. levels - 1 */
    size_t num_candidates, level_start[WT_MAX_LEVELS + 1];
    double candidates[2 * WT_MAX_CANDIDATES];
    int chosen_level;             /* K: levels 0..K hold the n draws */
    size_t candidates_upto_k;     /* inside candidates in levels 0..K */
    size_t chosen_matched;        /* chosen points found among them */
    /* method paper, all rounds; F per iteration from options.progress */
    plateau_report full;
    size_t num_records;
    int rec_round[WT_MAX_RECORDS], rec_iter[WT_MAX_RECORDS];
    double rec_f[WT_MAX_RECORDS];
    int rounds;
    plateau_mesh solved[WT_MAX_ROUNDS]; /* the solve stopped at round k + 1 */
    plateau_report solved_rep[WT_MAX_ROUNDS];
    size_t round_iterations[WT_MAX_ROUNDS], round_flips[WT_MAX_ROUNDS];
    /* the three methods from the same start */
    plateau_mesh method_mesh[3];
    plateau_report method_rep[3];
    demo_row method_row[3];
    double view[3];               /* every 3-D picture's view: wt_view of method paper's mesh */
} wt_case;

/* The options of every solve on the page: the paper's seeding (II.A's fan
 * candidates; make demo's table uses the default quality seeding), the
 * demo's seed, the case's n. */
DEMO_FN plateau_options wt_options(const demo_case *c, plateau_method method, int max_rounds)
{
    plateau_options o;
    memset(&o, 0, sizeof o);
    o.method = method;
    o.interior_points = c->n;
    o.seed = DEMO_SEED;
    o.seeding = PLATEAU_SEEDING_PAPER;
    o.max_rounds = max_rounds;
    return o;
}

static int wt_progress(int round, int iteration, double f, void *user)
{
    wt_case *w = (wt_case *)user;
    if (w->num_records < WT_MAX_RECORDS) {
        w->rec_round[w->num_records] = round;
        w->rec_iter[w->num_records] = iteration;
        w->rec_f[w->num_records] = f;
        w->num_records++;
    }
    return 0;
}

/* 1 when the undirected edge (a, b) is an edge of mesh. */
DEMO_FN int wt_has_edge(const plateau_mesh *mesh, plateau_index a, plateau_index b)
{
    size_t e;
    for (e = 0; e < mesh->num_edges; e++) {
        plateau_index p = mesh->edges[2 * e], q = mesh->edges[2 * e + 1];
        if ((p == a && q == b) || (p == b && q == a)) return 1;
    }
    return 0;
}

/* The edges of after that before lacks (vertex pairs into out, at most
 * cap pairs); returns their number. */
DEMO_FN size_t wt_new_edges(const plateau_mesh *before, const plateau_mesh *after,
                            plateau_index *out, size_t cap)
{
    size_t e, k = 0;
    for (e = 0; e < after->num_edges; e++) {
        plateau_index a = after->edges[2 * e], b = after->edges[2 * e + 1];
        if (wt_has_edge(before, a, b)) continue;
        if (k < cap) {
            out[2 * k] = a;
            out[2 * k + 1] = b;
        }
        k++;
    }
    return k;
}

/* Smallest corner angle of triangle t, degrees. */
DEMO_FN double wt_min_angle(const double *pos, const plateau_index *tri, size_t t)
{
    double best = 180.0;
    int k, j;
    for (k = 0; k < 3; k++) {
        const double *p = pos + 3 * tri[3 * t + k];
        const double *q = pos + 3 * tri[3 * t + (k + 1) % 3];
        const double *r = pos + 3 * tri[3 * t + (k + 2) % 3];
        double u[3], v[3], c[3], a;
        for (j = 0; j < 3; j++) {
            u[j] = q[j] - p[j];
            v[j] = r[j] - p[j];
        }
        demo_cross(u, v, c);
        a = atan2(sqrt(demo_dot(c, c)), demo_dot(u, v)) * 180.0 / M_PI;
        if (a < best) best = a;
    }
    return best;
}

/* The eigenvalues val and unit eigenvectors (the columns of vec) of the
 * symmetric 3 x 3 matrix a (destroyed), by cyclic Jacobi rotations. */
DEMO_FN void wt_eigen3(double a[3][3], double val[3], double vec[3][3])
{
    int i, j, k, sweep;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) vec[i][j] = i == j;
    for (sweep = 0; sweep < 50; sweep++) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        if (off <= 1e-15 * (fabs(a[0][0]) + fabs(a[1][1]) + fabs(a[2][2]))) break;
        for (i = 0; i < 2; i++)
            for (j = i + 1; j < 3; j++) {
                double th, t, c, s;
                if (a[i][j] == 0) continue;
                th = (a[j][j] - a[i][i]) / (2 * a[i][j]);
                t = (th >= 0 ? 1 : -1) / (fabs(th) + sqrt(th * th + 1));
                c = 1 / sqrt(t * t + 1);
                s = t * c;
                for (k = 0; k < 3; k++) { /* a J */
                    double aki = a[k][i], akj = a[k][j];
                    a[k][i] = c * aki - s * akj;
                    a[k][j] = s * aki + c * akj;
                }
                for (k = 0; k < 3; k++) { /* J^T a J */
                    double aik = a[i][k], ajk = a[j][k];
                    a[i][k] = c * aik - s * ajk;
                    a[j][k] = s * aik + c * ajk;
                }
                for (k = 0; k < 3; k++) {
                    double vki = vec[k][i], vkj = vec[k][j];
                    vec[k][i] = c * vki - s * vkj;
                    vec[k][j] = s * vki + c * vkj;
                }
            }
    }
    for (i = 0; i < 3; i++) val[i] = a[i][i];
}

/* The direction a picture of a surface looks in, chosen from the surface
 * (one rule for every 3-D picture of the page but the rings'):
 * M = sum over the triangles of area * n n^T (n the unit normal) has the
 * eigenvalues l1 >= l2 >= l3 (they sum to the area) and eigenvectors e1,
 * e2, e3.  Seen along e1 the surface is most face-on; sqrt(lk / l1) is how
 * far its normals spread towards ek.  The view is
 *     e1 + sqrt(l2 / l1) e2 + sqrt(l3 / l1) e3   (then unit length):
 * a flat film is seen face-on (l2 = l3 = 0), a curved one turned by its own
 * spread, so that part of it faces the eye and part is seen obliquely:
 * the helicoid's twist shows as one end face-on and the other turned away,
 * where a fixed direction saw its middle edge-on.  Each ek is signed so
 * that its first component of magnitude above 0.1, in the order z, y, x,
 * is negative: the eye above the surface and in front of it. */
DEMO_FN void wt_view(const double *pos, const plateau_index *tri, size_t nt, double view[3])
{
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, val[3], vec[3][3], e[3][3], l[3], len;
    size_t t;
    int i, j, order[3] = {0, 1, 2};
    for (t = 0; t < nt; t++) {
        const double *a = pos + 3 * tri[3 * t], *b = pos + 3 * tri[3 * t + 1], *c = pos + 3 * tri[3 * t + 2];
        double u[3], v[3], n[3], twice;
        for (i = 0; i < 3; i++) {
            u[i] = b[i] - a[i];
            v[i] = c[i] - a[i];
        }
        demo_cross(u, v, n);
        twice = sqrt(demo_dot(n, n)); /* twice the area */
        if (twice == 0) continue;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) m[i][j] += 0.5 * n[i] * n[j] / twice; /* area n n^T */
    }
    wt_eigen3(m, val, vec);
    for (i = 0; i < 3; i++) /* largest first */
        for (j = i + 1; j < 3; j++)
            if (val[order[j]] > val[order[i]]) {
                int k = order[i];
                order[i] = order[j];
                order[j] = k;
            }
    for (i = 0; i < 3; i++) {
        double s;
        l[i] = val[order[i]] > 0 ? val[order[i]] : 0;
        for (j = 0; j < 3; j++) e[i][j] = vec[j][order[i]];
        s = fabs(e[i][2]) > 0.1 ? e[i][2] : fabs(e[i][1]) > 0.1 ? e[i][1] : e[i][0];
        if (s > 0)
            for (j = 0; j < 3; j++) e[i][j] = -e[i][j];
    }
    for (j = 0; j < 3; j++)
        view[j] = e[0][j] + (l[0] > 0 ? sqrt(l[1] / l[0]) * e[1][j] + sqrt(l[2] / l[0]) * e[2][j] : 0);
    len = sqrt(demo_dot(view, view));
    for (j = 0; j < 3; j++) view[j] = len > 0 ? view[j] / len : (j == 2 ? -1 : 0);
}

/* The share of a surface's area its picture along view shows face-on:
 * sum of area * |n . view| over the area (view of unit length); 1 for a
 * flat film seen face-on, 0 edge-on.  With *low and *high (may be NULL)
 * the values of |n . view| below which lie 10 % and 90 % of the area: how
 * unevenly the surface faces the eye (a twist seen). */
DEMO_FN double wt_facing(const double *pos, const plateau_index *tri, size_t nt, const double view[3],
                         double *low, double *high)
{
    double total = 0, seen = 0, hist[101];
    size_t t;
    int i, k;
    for (k = 0; k <= 100; k++) hist[k] = 0;
    for (t = 0; t < nt; t++) {
        const double *a = pos + 3 * tri[3 * t], *b = pos + 3 * tri[3 * t + 1], *c = pos + 3 * tri[3 * t + 2];
        double u[3], v[3], n[3], twice, f;
        for (i = 0; i < 3; i++) {
            u[i] = b[i] - a[i];
            v[i] = c[i] - a[i];
        }
        demo_cross(u, v, n);
        twice = sqrt(demo_dot(n, n));
        if (twice == 0) continue;
        f = fabs(demo_dot(n, view)) / twice;
        total += 0.5 * twice;
        seen += 0.5 * twice * f;
        hist[(int)(f * 100 + 0.5)] += 0.5 * twice;
    }
    if (low || high) { /* the 10 % and 90 % points, to 0.01 */
        double sum = 0;
        int lo = -1, hi = -1;
        for (k = 0; k <= 100; k++) {
            sum += hist[k];
            if (lo < 0 && sum >= 0.1 * total) lo = k;
            if (hi < 0 && sum >= 0.9 * total) hi = k;
        }
        if (low) *low = lo / 100.0;
        if (high) *high = hi / 100.0;
    }
    return total > 0 ? seen / total : 0;
}

/* The candidate levels of II.A in the domain (the library's rule, redrawn
 * here for the picture): level 0 the centroid C of the polygon's domain
 * points, level 1 the barycentres of the closed fan (V_{j-1}, V_j, C),
 * level k + 1 those of the three pieces of each level-k triangle cut at its
 * barycentre; candidates outside the domain polygon (or within 1e-9 of its
 * size from its edges) are skipped, as plateau_seed_points does. */
DEMO_FN void wt_candidates(wt_case *w)
{
    static double tri[2][6 * WT_MAX_CANDIDATES];
    size_t m = w->m, i, count = 0, ntri = 0, level;
    double cx = 0, cy = 0, lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 }, margin;
    int cur = 0;
    for (i = 0; i < m; i++) {
        cx += w->uv[2 * i] / (double)m;
        cy += w->uv[2 * i + 1] / (double)m;
        if (w->uv[2 * i] < lo[0]) lo[0] = w->uv[2 * i];
        if (w->uv[2 * i] > hi[0]) hi[0] = w->uv[2 * i];
        if (w->uv[2 * i + 1] < lo[1]) lo[1] = w->uv[2 * i + 1];
        if (w->uv[2 * i + 1] > hi[1]) hi[1] = w->uv[2 * i + 1];
    }
    margin = 1e-9 * sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]));
    w->level_start[0] = 0;
    w->candidates[0] = cx;
    w->candidates[1] = cy;
    count = plateau_point_in_polygon(w->uv, m, w->candidates, margin) ? 1 : 0;
    w->level_start[1] = count;
    for (i = 0; i < m && ntri < WT_MAX_CANDIDATES; i++) { /* the closed fan */
        const double *a = w->uv + 2 * ((i + m - 1) % m), *b = w->uv + 2 * i;
        double *t = tri[0] + 6 * ntri++;
        t[0] = a[0]; t[1] = a[1]; t[2] = b[0]; t[3] = b[1]; t[4] = cx; t[5] = cy;
    }
    for (level = 1; level < WT_MAX_LEVELS; level++) {
        size_t next = 0, k;
        for (k = 0; k < ntri; k++) {
            const double *t = tri[cur] + 6 * k;
            double g[2];
            g[0] = (t[0] + t[2] + t[4]) / 3;
            g[1] = (t[1] + t[3] + t[5]) / 3;
            if (count < WT_MAX_CANDIDATES && plateau_point_in_polygon(w->uv, m, g, margin)) {
                w->candidates[2 * count] = g[0];
                w->candidates[2 * count + 1] = g[1];
                count++;
            }
            if (next + 3 <= WT_MAX_CANDIDATES) { /* the three pieces at g */
                int piece, j;
                for (piece = 0; piece < 3; piece++) {
                    double *u = tri[1 - cur] + 6 * next++;
                    int skip = 2 - piece; /* (a, b, g), (a, c, g), (b, c, g) */
                    int o = 0;
                    for (j = 0; j < 3; j++) {
                        if (j == skip) continue;
                        u[2 * o] = t[2 * j];
                        u[2 * o + 1] = t[2 * j + 1];
                        o++;
                    }
                    u[4] = g[0];
                    u[5] = g[1];
                }
            }
        }
        w->level_start[level + 1] = count;
        ntri = next;
        cur = 1 - cur;
    }
    w->num_candidates = count;
    /* K: the first level by which the levels hold n (PLATEAU_SEED_WHOLE_LEVELS) */
    w->chosen_level = WT_MAX_LEVELS - 1;
    for (level = 0; level < WT_MAX_LEVELS; level++)
        if (w->level_start[level + 1] >= w->n) {
            w->chosen_level = (int)level;
            break;
        }
    w->candidates_upto_k = w->level_start[w->chosen_level + 1];
    /* every chosen point must be one of them */
    w->chosen_matched = 0;
    for (i = 0; i < w->n; i++) {
        const double *p = w->uv + 2 * (m + i);
        size_t k;
        for (k = 0; k < w->candidates_upto_k; k++)
            if (fabs(p[0] - w->candidates[2 * k]) <= 1e-12 * (hi[0] - lo[0]) &&
                fabs(p[1] - w->candidates[2 * k + 1]) <= 1e-12 * (hi[0] - lo[0])) {
                w->chosen_matched++;
                break;
            }
    }
}

DEMO_FN void wt_free(wt_case *w)
{
    int k;
    free(w->uv);
    w->uv = NULL;
    plateau_mesh_free(&w->start);
    for (k = 0; k < WT_MAX_ROUNDS; k++) plateau_mesh_free(&w->solved[k]);
    for (k = 0; k < 3; k++) plateau_mesh_free(&w->method_mesh[k]);
}

/* Runs every step of the page for case c into *w (free with wt_free, also
 * after a failure).  Returns 0, or -1 with a sentence in msg (200 bytes). */
DEMO_FN int wt_collect(const demo_case *c, wt_case *w, char *msg)
{
    plateau_options o;
    plateau_error err;
    size_t i, k;
    int r;
    memset(w, 0, sizeof *w);
    w->c = c;
    w->m = demo_boundary(c, w->boundary);
    w->uv = (double *)malloc(2 * (w->m + c->n) * sizeof(double));
    if (!w->uv) {
        sprintf(msg, "%s: out of memory", c->name);
        return -1;
    }
    /* steps 2-4 with the public functions */
    if (demo_initial_mesh_uv(c, 0, &w->start, w->uv, &err) != PLATEAU_OK) {
        sprintf(msg, "%s: initial mesh: %.150s", c->name, err.message);
        return -1;
    }
    w->n = w->start.num_vertices - w->m;
    for (i = w->m; i < w->start.num_vertices; i++) {
        double h = fabs(plateau_vertex_mean_curvature(&w->start, i));
        if (h > w->start_hmax) w->start_hmax = h;
    }
    wt_candidates(w);
    /* method paper, all rounds, F per iteration */
    o = wt_options(c, PLATEAU_METHOD_PAPER, 0);
    o.progress = wt_progress;
    o.progress_user = w;
    {
        plateau_mesh full;
        memset(&full, 0, sizeof full);
        r = plateau_solve(w->boundary, w->m, &o, &full, &w->full, &err);
        plateau_mesh_free(&full);
    }
    if (r != PLATEAU_OK) {
        sprintf(msg, "%s: solve: %.150s", c->name, err.message);
        return -1;
    }
    w->rounds = (int)w->full.rounds;
    if (w->rounds < 1 || w->rounds > WT_MAX_ROUNDS || w->rounds > PLATEAU_REPORT_F_ROUNDS) {
        sprintf(msg, "%s: %d rounds do not fit the page", c->name, w->rounds);
        return -1;
    }
    for (k = 0; k < w->num_records; k++) w->round_iterations[w->rec_round[k] - 1]++;
    /* the solve stopped after each round */
    for (k = 0; k < (size_t)w->rounds; k++) {
        o = wt_options(c, PLATEAU_METHOD_PAPER, (int)k + 1);
        if (plateau_solve(w->boundary, w->m, &o, &w->solved[k], &w->solved_rep[k], &err) !=
            PLATEAU_OK) {
            sprintf(msg, "%s: solve to round %d: %.150s", c->name, (int)k + 1, err.message);
            return -1;
        }
    }
    for (k = 0; k + 1 < (size_t)w->rounds; k++)
        w->round_flips[k] = wt_new_edges(&w->solved[k], &w->solved[k + 1], NULL, 0);
    /* the start made here is plateau_solve's: the same edges (the
     * triangles may come in another order) */
    if (w->solved[0].num_triangles != w->start.num_triangles ||
        wt_new_edges(&w->start, &w->solved[0], NULL, 0) != 0 ||
        wt_new_edges(&w->solved[0], &w->start, NULL, 0) != 0) {
        sprintf(msg, "%s: the start triangulation differs from plateau_solve's", c->name);
        return -1;
    }
    for (k = 0; k < 3; k++) {
        o = wt_options(c, demo_methods[k], 0);
        if (plateau_solve(w->boundary, w->m, &o, &w->method_mesh[k], &w->method_rep[k], &err) !=
            PLATEAU_OK) {
            sprintf(msg, "%s, %s: %.150s", c->name, plateau_method_name(demo_methods[k]),
                    err.message);
            return -1;
        }
        demo_measure(c, &w->method_mesh[k], &w->method_row[k]);
    }
    /* one view for the case's pictures, from the surface it converges to */
    wt_view(w->method_mesh[0].positions, w->method_mesh[0].triangles, w->method_mesh[0].num_triangles,
            w->view);
    return 0;
}

/* ------------------------------------------------- two rings: three films */
/* The panel of the least-area question (examples/NOTES.md, section 12):
 * two coaxial rings of radius 1 at h = 1.2 (WT_RINGS_M vertices each)
 * span the stable catenoid (method area's film: a local minimum, index
 * 0), the unstable one (plateau_mesh_critical_point with index 1 from a
 * sampled catenoid whose neck is 25 % wider than the exact unstable one's:
 * a saddle, index 1) and two flat discs (least_area_topology: the least
 * area).  Each picture is coloured by its lowest mode (the eigenvector
 * of plateau_mesh_stability): the unstable catenoid's is the motion that
 * lowers its area. */
#define WT_RINGS_M 48
#define WT_RINGS_H 1.2
typedef struct wt_rings {
    plateau_mesh mesh[3];          /* stable, unstable, discs */
    plateau_stability status[3];
    double *mode[3];               /* the lowest mode per vertex */
    double area[3], exact[3];
    int converged;                 /* the saddle search converged */
} wt_rings;

/* The options of the two solves of the panel (method area). */
DEMO_FN plateau_options wt_rings_options(int discs)
{
    plateau_options o;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = (size_t)(WT_RINGS_M * WT_RINGS_M * WT_RINGS_H / (2.0 * M_PI)) + 4;
    o.least_area_topology = discs;
    return o;
}

DEMO_FN void wt_rings_free(wt_rings *r)
{
    int k;
    for (k = 0; k < 3; k++) {
        plateau_mesh_free(&r->mesh[k]);
        free(r->mode[k]);
        r->mode[k] = NULL;
    }
}

/* Fills *r (free with wt_rings_free, also after a failure).  Returns 0,
 * or -1 with a sentence in msg (200 bytes). */
DEMO_FN int wt_collect_rings(wt_rings *r, char *msg)
{
    double xyz[6 * WT_RINGS_M], au = demo_catenoid_neck_branch(WT_RINGS_H, 1);
    size_t counts[2] = {WT_RINGS_M, WT_RINGS_M};
    plateau_options o;
    plateau_report rep;
    plateau_error err;
    int k;
    memset(r, 0, sizeof *r);
    demo_rings(xyz, WT_RINGS_M, WT_RINGS_H);
    for (k = 0; k < 3; k += 2) {
        o = wt_rings_options(k == 2);
        if (plateau_solve_loops(xyz, counts, 2, &o, &r->mesh[k], &rep, &err) != PLATEAU_OK) {
            sprintf(msg, "rings: %.180s", err.message);
            return -1;
        }
    }
    if (demo_catenoid_mesh(WT_RINGS_H, 1.25 * au, WT_RINGS_M, 2 * (int)(WT_RINGS_M * WT_RINGS_H / (4.0 * M_PI)) + 3,
                           &r->mesh[1]) != PLATEAU_OK ||
        plateau_mesh_critical_point(&r->mesh[1], 1, 0, NULL, &r->converged, NULL, &err) != PLATEAU_OK) {
        sprintf(msg, "rings: the unstable catenoid");
        return -1;
    }
    for (k = 0; k < 3; k++) {
        r->mode[k] = (double *)malloc(r->mesh[k].num_vertices * sizeof(double));
        if (!r->mode[k] || plateau_mesh_stability(&r->mesh[k], 1, &r->status[k], r->mode[k], &err) != PLATEAU_OK) {
            sprintf(msg, "rings: the stability report");
            return -1;
        }
        r->area[k] = plateau_mesh_area(&r->mesh[k]);
    }
    r->exact[0] = demo_catenoid_area(WT_RINGS_H);
    r->exact[1] = demo_catenoid_area_of(WT_RINGS_H, au);
    r->exact[2] = 2.0 * M_PI;
    return 0;
}

/* ------------------------------------------------------------- the page */
/* A number the test reads back: the value exactly in data-value, shown
 * with fmt. */
DEMO_FN void wt_num(FILE *f, const char *case_name, const char *key, double value, const char *fmt)
{
    char shown[64];
    snprintf(shown, sizeof shown, fmt, value);
    fprintf(f, "<span class=\"num\" data-key=\"%s.%s\" data-value=\"%.17g\">%s</span>", case_name,
            key, value, shown);
}

/* A table cell holding the number of key "row.field" (wt_num). */
DEMO_FN void wt_cell(FILE *f, const char *case_name, const char *row, const char *field, double value,
                     const char *fmt)
{
    char key[96];
    snprintf(key, sizeof key, "%s.%s", row, field);
    fprintf(f, "<td>");
    wt_num(f, case_name, key, value, fmt);
    fprintf(f, "</td>");
}

/* A figure against its reference and their relative difference
 * |a - b| / b, the numbers of keys row.keys[0..2], with words[0] between
 * the first two and words[1] before the difference. */
DEMO_FN void wt_versus(FILE *f, const char *case_name, const char *row, const char *const keys[3], double a,
                       double b, const char *fmt, const char *const words[2], const char *diff_fmt)
{
    char key[96];
    snprintf(key, sizeof key, "%s.%s", row, keys[0]);
    wt_num(f, case_name, key, a, fmt);
    fprintf(f, "%s", words[0]);
    snprintf(key, sizeof key, "%s.%s", row, keys[1]);
    wt_num(f, case_name, key, b, fmt);
    fprintf(f, "%s", words[1]);
    snprintf(key, sizeof key, "%s.%s", row, keys[2]);
    wt_num(f, case_name, key, fabs(a - b) / b, diff_fmt);
}

/* An SVG picture written to the scratch stream tmp, inline: its
 * namespace, size attributes and XML declaration dropped (inline SVG in
 * HTML needs none; CSS sizes it), and, when scope is not NULL, the rules
 * of its <style> prefixed with "#scope " (a style in inline SVG applies to
 * the whole page).  Closes tmp. */
DEMO_FN int wt_inline_stream(FILE *out, FILE *tmp, const char *scope)
{
    char *buf, *p, *q, *gt, *style;
    long size = ftell(tmp);
    rewind(tmp);
    buf = (char *)malloc((size_t)size + 1);
    if (!buf || fread(buf, 1, (size_t)size, tmp) != (size_t)size) {
        free(buf);
        fclose(tmp);
        return -1;
    }
    buf[size] = '\0';
    fclose(tmp);
    /* "<svg ... viewBox="..." ...>" */
    p = strstr(buf, "<svg");
    gt = p ? strchr(p, '>') : NULL;
    q = p ? strstr(p, "viewBox=\"") : NULL;
    q = q && q < gt ? strchr(q + 9, '"') : NULL;
    if (!q) {
        free(buf);
        return -1;
    }
    fputs("<svg class=\"pic\" ", out);
    fwrite(strstr(p, "viewBox="), 1, (size_t)(q + 1 - strstr(p, "viewBox=")), out);
    p = gt;
    style = strstr(p, "<style>");
    if (scope && style) { /* each rule "sel{...}" as "#scope sel{...}" */
        char *end = strstr(style, "</style>"), *r = style + 7;
        fwrite(p, 1, (size_t)(r - p), out);
        while (end && r < end) {
            char *close = strchr(r, '}');
            if (!close || close > end) break;
            while (*r == ' ') r++;
            fprintf(out, "#%s ", scope);
            fwrite(r, 1, (size_t)(close + 1 - r), out);
            r = close + 1;
        }
        p = r;
    }
    fputs(p, out);
    free(buf);
    return 0;
}

/* The library's coloured picture, inline (wt_inline_stream). */
DEMO_FN int wt_inline_svg(FILE *out, const double *pos, size_t nv, const plateau_index *tri,
                          size_t nt, const plateau_svg_colors *colors)
{
    FILE *tmp = tmpfile();
    plateau_error err;
    if (!tmp) return -1;
    if (plateau_write_svg_colored_stream(tmp, pos, nv, tri, nt, colors, NULL, &err) != PLATEAU_OK) {
        fprintf(stderr, "walkthrough: %s\n", err.message);
        fclose(tmp);
        return -1;
    }
    return wt_inline_stream(out, tmp, NULL);
}

/* A 2-D frame: the box [lo, hi] fitted into 600 x 600 units with a margin,
 * y up. */
typedef struct wt_frame {
    double lo[2], s, w, h;
} wt_frame;

DEMO_FN wt_frame wt_fit(const double *xy, size_t count)
{
    wt_frame fr;
    size_t i;
    double dx, dy;
    fr.lo[0] = fr.lo[1] = 1e300;
    dx = dy = -1e300;
    for (i = 0; i < count; i++) {
        if (xy[2 * i] < fr.lo[0]) fr.lo[0] = xy[2 * i];
        if (xy[2 * i + 1] < fr.lo[1]) fr.lo[1] = xy[2 * i + 1];
        if (xy[2 * i] > dx) dx = xy[2 * i];
        if (xy[2 * i + 1] > dy) dy = xy[2 * i + 1];
    }
    dx -= fr.lo[0];
    dy -= fr.lo[1];
    fr.s = 560.0 / (dx > dy ? dx : dy);
    fr.w = dx * fr.s + 40;
    fr.h = dy * fr.s + 40;
    return fr;
}

DEMO_FN double wt_x(const wt_frame *fr, const double *p) { return 20 + (p[0] - fr->lo[0]) * fr->s; }
DEMO_FN double wt_y(const wt_frame *fr, const double *p) { return fr->h - 20 - (p[1] - fr->lo[1]) * fr->s; }

/* The polygon L in 3-D, seen along the case's view (w->view) with the
 * screen axes of the library's pictures: its vertices as dots, V_1 and the
 * walking direction marked. */
DEMO_FN void wt_svg_boundary(FILE *f, const wt_case *w)
{
    double view[3], right[3], up[3], zup[3] = { 0, 0, 1 }, xy[2 * DEMO_MAX_BOUNDARY], len;
    size_t i, m = w->m;
    wt_frame fr;
    memcpy(view, w->view, 3 * sizeof(double));
    if (fabs(view[2]) > 0.99) { /* looking along z: y up, as the library does */
        zup[1] = 1;
        zup[2] = 0;
    }
    demo_cross(view, zup, right);
    len = sqrt(demo_dot(right, right));
    for (i = 0; i < 3; i++) right[i] /= len;
    demo_cross(right, view, up);
    len = sqrt(demo_dot(up, up));
    for (i = 0; i < 3; i++) up[i] /= len;
    for (i = 0; i < m; i++) {
        xy[2 * i] = demo_dot(w->boundary + 3 * i, right);
        xy[2 * i + 1] = demo_dot(w->boundary + 3 * i, up);
    }
    fr = wt_fit(xy, m);
    fprintf(f, "<svg class=\"pic\" viewBox=\"0 0 %.0f %.0f\">\n<polygon fill=\"none\" "
               "stroke=\"#1d3557\" stroke-width=\"3\" stroke-linejoin=\"round\" points=\"",
            fr.w, fr.h);
    for (i = 0; i < m; i++) fprintf(f, "%.1f,%.1f ", wt_x(&fr, xy + 2 * i), wt_y(&fr, xy + 2 * i));
    fprintf(f, "\"/>\n<g stroke=\"#1d3557\" stroke-width=\"1.5\">");
    {
        /* the dots coloured by height z (plateau_colormap): the depth cue */
        double zlo = 1e300, zhi = -1e300;
        for (i = 0; i < m; i++) {
            if (w->boundary[3 * i + 2] < zlo) zlo = w->boundary[3 * i + 2];
            if (w->boundary[3 * i + 2] > zhi) zhi = w->boundary[3 * i + 2];
        }
        for (i = 0; i < m; i++) {
            double rgb[3];
            plateau_colormap(zhi > zlo ? (w->boundary[3 * i + 2] - zlo) / (zhi - zlo) : 0.5, rgb);
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"8\" fill=\"#%02x%02x%02x\"/>",
                    wt_x(&fr, xy + 2 * i), wt_y(&fr, xy + 2 * i), (int)(255 * rgb[0] + 0.5),
                    (int)(255 * rgb[1] + 0.5), (int)(255 * rgb[2] + 0.5));
        }
    }
    fprintf(f, "</g>\n<circle cx=\"%.1f\" cy=\"%.1f\" r=\"14\" fill=\"none\" stroke=\"#c1121f\" "
               "stroke-width=\"3\"/>\n<text x=\"%.1f\" y=\"%.1f\" font-size=\"26\" "
               "font-family=\"sans-serif\" fill=\"#c1121f\" text-anchor=\"%s\">V1</text>\n</svg>\n",
            wt_x(&fr, xy), wt_y(&fr, xy), wt_x(&fr, xy) + (wt_x(&fr, xy) > fr.w / 2 ? -18 : 18),
            wt_y(&fr, xy) - 16, wt_x(&fr, xy) > fr.w / 2 ? "end" : "start");
}

/* The domain: polygon, fan from the centroid, candidate levels 0..K+1
 * (hollow, a colour per level), the chosen points (filled); or, with cdt,
 * the constrained Delaunay triangulation of polygon and chosen points. */
DEMO_FN void wt_svg_domain(FILE *f, const wt_case *w, int cdt)
{
    size_t i, m = w->m, npts = m + w->n;
    int level, top = w->chosen_level + 1 < WT_MAX_LEVELS ? w->chosen_level + 1 : w->chosen_level;
    wt_frame fr = wt_fit(w->uv, m);
    const double *cen = w->candidates;
    fprintf(f, "<svg class=\"pic\" viewBox=\"0 0 %.0f %.0f\">\n", fr.w, fr.h);
    if (cdt) {
        fprintf(f, "<g fill=\"#f4f1de\" stroke=\"#6c757d\" stroke-width=\"1.5\" stroke-linejoin=\"round\">");
        for (i = 0; i < w->start.num_triangles; i++) {
            const plateau_index *t = w->start.triangles + 3 * i;
            fprintf(f, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\"/>",
                    wt_x(&fr, w->uv + 2 * t[0]), wt_y(&fr, w->uv + 2 * t[0]),
                    wt_x(&fr, w->uv + 2 * t[1]), wt_y(&fr, w->uv + 2 * t[1]),
                    wt_x(&fr, w->uv + 2 * t[2]), wt_y(&fr, w->uv + 2 * t[2]));
        }
        fprintf(f, "</g>\n");
    } else {
        fprintf(f, "<g stroke=\"#adb5bd\" stroke-width=\"1\">");
        for (i = 0; i < m; i++)
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>", wt_x(&fr, cen),
                    wt_y(&fr, cen), wt_x(&fr, w->uv + 2 * i), wt_y(&fr, w->uv + 2 * i));
        fprintf(f, "</g>\n");
    }
    fprintf(f, "<polygon fill=\"none\" stroke=\"#1d3557\" stroke-width=\"3\" points=\"");
    for (i = 0; i < m; i++) fprintf(f, "%.1f,%.1f ", wt_x(&fr, w->uv + 2 * i), wt_y(&fr, w->uv + 2 * i));
    fprintf(f, "\"/>\n");
    if (!cdt) {
        for (level = top; level >= 0; level--) {
            double rgb[3];
            size_t k;
            plateau_colormap(top > 0 ? 0.75 * level / top : 0.0, rgb);
            fprintf(f, "<g fill=\"none\" stroke=\"#%02x%02x%02x\" stroke-width=\"2\">",
                    (int)(255 * rgb[0] + 0.5), (int)(255 * rgb[1] + 0.5), (int)(255 * rgb[2] + 0.5));
            for (k = w->level_start[level]; k < w->level_start[level + 1]; k++)
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%d\"/>", wt_x(&fr, w->candidates + 2 * k),
                        wt_y(&fr, w->candidates + 2 * k), level > w->chosen_level ? 3 : 8);
            fprintf(f, "</g>\n");
        }
    }
    fprintf(f, "<g fill=\"#c1121f\">");
    for (i = m; i < npts; i++)
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\"/>", wt_x(&fr, w->uv + 2 * i), wt_y(&fr, w->uv + 2 * i));
    fprintf(f, "</g>\n</svg>\n");
}

/* A tick step for an axis of span units with at most max_ticks ticks:
 * 1, 2 or 5 times a power of ten. */
DEMO_FN double wt_tick_step(double span, int max_ticks)
{
    double step = 1;
    int k = 0;
    while (span / step > max_ticks && k < 60) {
        step *= (k % 3 == 1) ? 2.5 : 2; /* 1, 2, 5, 10, 20, 50, ... */
        k++;
    }
    return step;
}

/* The chart's frame: its plot box and data ranges.  Both axes come from
 * the data: x the iterations 0 .. num_records (0: the start's F), y
 * log10 F from the smallest to the largest value (F spans tens of decades:
 * quadratic convergence to rounding), each widened by WT_CHART_PAD of its
 * span on both sides, so that no point lies on the box's border. */
#define WT_CHART_PAD 0.05
typedef struct wt_chart {
    double x0, y0, pw, ph;  /* the plot box */
    double xlo, xhi, ylo, yhi; /* the data range it shows */
} wt_chart;

DEMO_FN double wt_chart_log(double fv) { return log10(fv > 1e-300 ? fv : 1e-300); }

DEMO_FN wt_chart wt_chart_frame(const wt_case *w)
{
    wt_chart ch;
    double lmin = wt_chart_log(w->full.f_initial), lmax = lmin, span;
    size_t k;
    ch.x0 = 80;
    ch.y0 = 36;
    ch.pw = 620;
    ch.ph = 300;
    for (k = 0; k < w->num_records; k++) {
        double l = wt_chart_log(w->rec_f[k]);
        if (l < lmin) lmin = l;
        if (l > lmax) lmax = l;
    }
    span = lmax > lmin ? lmax - lmin : 1;
    ch.ylo = lmin - WT_CHART_PAD * span;
    ch.yhi = lmax + WT_CHART_PAD * span;
    span = w->num_records > 0 ? (double)w->num_records : 1;
    ch.xlo = -WT_CHART_PAD * span;
    ch.xhi = (double)w->num_records + WT_CHART_PAD * span;
    return ch;
}

DEMO_FN double wt_chart_x(const wt_chart *ch, double it) { return ch->x0 + ch->pw * (it - ch->xlo) / (ch->xhi - ch->xlo); }
DEMO_FN double wt_chart_y(const wt_chart *ch, double fv) { return ch->y0 + ch->ph * (ch->yhi - wt_chart_log(fv)) / (ch->yhi - ch->ylo); }

/* F after every LM iteration, log10 scale, one colour per round: a line
 * through a dot per iteration (the start's F at iteration 0), the rounds'
 * starts marked by a dashed line, axes from the data (wt_chart_frame). */
DEMO_FN void wt_svg_fchart(FILE *f, const wt_case *w)
{
    const double W = 720, H = 380;
    wt_chart ch = wt_chart_frame(w);
    double step, d;
    size_t k;
    int round;
    fprintf(f, "<svg class=\"chart\" viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" "
               "font-size=\"13\">\n<rect x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" "
               "height=\"%.0f\" fill=\"#fbfbfb\" stroke=\"#333\"/>\n",
            W, H, ch.x0, ch.y0, ch.pw, ch.ph);
    /* y: the decades inside the range */
    step = wt_tick_step(ch.yhi - ch.ylo, 8);
    for (d = ceil(ch.ylo / step) * step; d <= ch.yhi; d += step) {
        double y = ch.y0 + ch.ph * (ch.yhi - d) / (ch.yhi - ch.ylo);
        fprintf(f, "<line x1=\"%.0f\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"#ddd\"/>"
                   "<text x=\"%.0f\" y=\"%.1f\" text-anchor=\"end\">1e%.0f</text>\n",
                ch.x0, y, ch.x0 + ch.pw, y, ch.x0 - 6, y + 4, d);
    }
    /* x: iterations */
    step = wt_tick_step(ch.xhi - ch.xlo, 10);
    for (d = 0; d <= (double)w->num_records; d += step) {
        double x = wt_chart_x(&ch, d);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.0f\" x2=\"%.1f\" y2=\"%.0f\" stroke=\"#333\"/>"
                   "<text x=\"%.1f\" y=\"%.0f\" text-anchor=\"middle\">%.0f</text>\n",
                x, ch.y0 + ch.ph, x, ch.y0 + ch.ph + 5, x, ch.y0 + ch.ph + 19, d);
    }
    fprintf(f, "<text x=\"%.0f\" y=\"%.0f\" text-anchor=\"middle\">LM iteration (all rounds; 0: the "
               "start)</text>\n<text x=\"16\" y=\"%.0f\" transform=\"rotate(-90 16 %.0f)\" "
               "text-anchor=\"middle\">F</text>\n",
            ch.x0 + ch.pw / 2, H - 6, ch.y0 + ch.ph / 2, ch.y0 + ch.ph / 2);
    for (round = 1; round <= w->rounds; round++) {
        double rgb[3], xs[WT_MAX_RECORDS + 1], ys[WT_MAX_RECORDS + 1];
        size_t first = 0, n = 0, j, np = 0;
        char hex[8];
        plateau_colormap(w->rounds > 1 ? 0.8 * (round - 1) / (w->rounds - 1) : 0.0, rgb);
        sprintf(hex, "#%02x%02x%02x", (int)(255 * rgb[0] + 0.5), (int)(255 * rgb[1] + 0.5),
                (int)(255 * rgb[2] + 0.5));
        for (k = 0; k < w->num_records; k++)
            if (w->rec_round[k] == round) {
                if (!n) first = k;
                n++;
            }
        if (round == 1) { /* F of the start (report.f_initial) at iteration 0 */
            xs[np] = wt_chart_x(&ch, 0);
            ys[np++] = wt_chart_y(&ch, w->full.f_initial);
        }
        for (j = first; j < first + n; j++) {
            xs[np] = wt_chart_x(&ch, (double)(j + 1));
            ys[np++] = wt_chart_y(&ch, w->rec_f[j]);
        }
        if (round > 1 && n) /* where the round starts */
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.0f\" x2=\"%.1f\" y2=\"%.0f\" stroke=\"%s\" "
                       "stroke-dasharray=\"4 4\"/>\n",
                    xs[0], ch.y0, xs[0], ch.y0 + ch.ph, hex);
        fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2.5\" "
                   "points=\"", hex);
        for (j = 0; j < np; j++) fprintf(f, "%.1f,%.1f ", xs[j], ys[j]);
        fprintf(f, "\"/>\n<g fill=\"%s\">", hex);
        for (j = 0; j < np; j++) fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\"/>", xs[j], ys[j]);
        fprintf(f, "</g>\n");
        if (np) /* the name over the box, above the round's iterations, clear of the lines */
            fprintf(f, "<text x=\"%.1f\" y=\"%.0f\" fill=\"%s\" text-anchor=\"middle\">round %d</text>\n",
                    0.5 * (xs[0] + xs[np - 1]), ch.y0 - 10, hex, round);
    }
    fprintf(f, "</svg>\n");
}

/* Per-triangle smallest angles of a mesh (out: num_triangles values). */
DEMO_FN void wt_angles(const double *pos, const plateau_index *tri, size_t nt, double *out)
{
    size_t t;
    for (t = 0; t < nt; t++) out[t] = wt_min_angle(pos, tri, t);
}

#define WT_MAX_MARKS 256
/* The picture of round k (0-based): the positions after its solve, the
 * triangles after its flips, each coloured by its smallest angle on
 * [0, 60] degrees, the edges the flips made marked.  vals (room for the
 * triangles), marks (2 WT_MAX_MARKS) and view are the scratch *col points
 * to; *next gets the mesh whose triangles to draw.  Returns the number of
 * flipped edges. */
DEMO_FN size_t wt_round_colors(const wt_case *w, int k, double *vals, plateau_index *marks,
                               double view[3], plateau_svg_colors *col,
                               const plateau_mesh **next)
{
    const plateau_mesh *solved = &w->solved[k];
    size_t nm;
    *next = k + 1 < w->rounds ? &w->solved[k + 1] : solved;
    nm = wt_new_edges(solved, *next, marks, WT_MAX_MARKS);
    wt_angles(solved->positions, (*next)->triangles, (*next)->num_triangles, vals);
    memset(col, 0, sizeof *col);
    col->values = vals;
    col->num_values = (*next)->num_triangles;
    col->range_min = 0;
    col->range_max = 60;
    col->title = "smallest angle, deg";
    col->marked_edges = marks;
    col->num_marked_edges = nm < WT_MAX_MARKS ? nm : WT_MAX_MARKS;
    memcpy(view, w->view, 3 * sizeof(double));
    col->view_dir = view;
    return nm;
}

/* The picture of round k as an SVG file of its own (the README's sample). */
DEMO_FN int wt_write_round_picture(const wt_case *w, int k, const char *path)
{
    const plateau_mesh *next;
    plateau_index marks[2 * WT_MAX_MARKS];
    plateau_svg_colors col;
    plateau_error err;
    double view[3], *vals;
    int status = 0;
    if (k >= w->rounds) return -1;
    vals = (double *)malloc((w->solved[k].num_triangles + 1) * sizeof(double));
    if (!vals) return -1;
    wt_round_colors(w, k, vals, marks, view, &col, &next);
    if (plateau_write_svg_colored(path, w->solved[k].positions, w->solved[k].num_vertices,
                                  next->triangles, next->num_triangles, &col, NULL,
                                  &err) != PLATEAU_OK) {
        fprintf(stderr, "%s: %s\n", path, err.message);
        status = -1;
    }
    free(vals);
    return status;
}

static const char *const wt_style =
    "body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222;"
    "line-height:1.45}\n"
    "h1{font-size:1.6em}h2{margin-top:2em;border-bottom:2px solid #1d3557}\n"
    ".panel{margin:1.2em 0;padding:0.8em 1em;border:1px solid #ccc;border-radius:6px;"
    "background:#fff}\n"
    ".panel h3{margin:0 0 0.4em 0;font-size:1.1em}\n"
    ".row{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}\n"
    ".cell{flex:1 1 300px;min-width:260px}\n"
    "svg.pic{width:100%;max-width:420px;max-height:380px;height:auto;display:block}\n"
    "svg.chart{width:100%;max-width:720px;height:auto;display:block}\n"
    "#design-flat svg.pic{max-height:760px}\n"
    ".num{font-variant-numeric:tabular-nums}\n"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:0.2em 0.6em;"
    "text-align:right}th{background:#f0f0f0}\n";


/* The membranes of panel 9 (plateau.h, MEMBRANES): which = 0 the
 * cap of p = 1 on the unit circle (48 vertices, meshed at their spacing,
 * method area), 1 the flat square with four cables of tension 2 (300
 * interior points, method area).  Fills xyz (at most 3 * 48), *m and o;
 * the page and tests/test_walkthrough.c solve the same. */
DEMO_FN void wt_membrane_options(int which, double *xyz, size_t *m, plateau_options *o)
{
    static const double tension[4] = {2.0, 2.0, 2.0, 2.0};
    size_t i;
    memset(o, 0, sizeof *o);
    o->method = PLATEAU_METHOD_AREA;
    if (which == 0) {
        *m = 48;
        for (i = 0; i < 48; i++) {
            double t = 6.283185307179586 * (double)i / 48.0;
            xyz[3 * i] = cos(t);
            xyz[3 * i + 1] = sin(t);
            xyz[3 * i + 2] = 0.0;
        }
        o->quality_edge_length = 2.0 * sin(3.141592653589793 / 48.0);
        o->interior_points = 300;
        o->pressure = 1.0;
    } else {
        static const double sq[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
        *m = 4;
        memcpy(xyz, sq, sizeof sq);
        o->interior_points = 300;
        o->cable_tension = tension;
    }
}

/* The exact figures the panel compares with: the cap of R = 2 / p = 2
 * (height 2 - sqrt 3, area 2 pi R h, volume pi h^2 (3R - h) / 3) and the
 * cable's arc of radius T = 2 over the chord 2 (half-angle asin(1 / T):
 * sag T (1 - cos a), length 2 T a, film area 4 - 4 T^2 (a - sin a cos a)). */
DEMO_FN void wt_membrane_exact(double *cap_area, double *cap_volume, double *sag, double *length,
                               double *sail_area)
{
    double R = 2.0, h = 2.0 - sqrt(3.0), T = 2.0, a = asin(1.0 / T);
    *cap_area = 2.0 * 3.141592653589793 * R * h;
    *cap_volume = 3.141592653589793 * h * h * (3.0 * R - h) / 3.0;
    *sag = T * (1.0 - cos(a));
    *length = 2.0 * T * a;
    *sail_area = 4.0 - 4.0 * T * T * (a - sin(a) * cos(a));
}

/* The number of boundary vertices of membrane which (0 the cap, 1 the
 * cables) as solved: the polygon, with the cable vertices between their
 * anchors (they come first in the mesh, in order). */
DEMO_FN size_t wt_membrane_boundary(int which, const plateau_report *rep)
{
    return which ? 4 + rep->cable_vertices : 48;
}

/* The smallest and largest H_i over membrane which's interior vertices. */
DEMO_FN void wt_membrane_h(int which, const plateau_mesh *mesh, const plateau_report *rep,
                           double *hmin, double *hmax)
{
    size_t i;
    *hmin = 1e300;
    *hmax = -1e300;
    for (i = wt_membrane_boundary(which, rep); i < mesh->num_vertices; i++) {
        double h = plateau_vertex_mean_curvature(mesh, i);
        if (h < *hmin) *hmin = h;
        if (h > *hmax) *hmax = h;
    }
}

/* The picture of membrane which, its scratch arrays given (vals: a value
 * per vertex; marks: 2 per boundary vertex; view: 3): the view by wt_view
 * (the cap seen from above at a slant, the flat film face-on).  The cap is
 * coloured by height z: H_i is nearly the same at every vertex (k1 + k2 =
 * p), so a colour by H would paint it one flat tone, where its height
 * shows the dome.  The cable film is flat (H_i = 0, its height 0), so
 * nothing on it varies: it is coloured by H_i on [-1, 1], the film at the
 * middle of the scale, and its boundary edges, the four cables, are
 * marked. */
DEMO_FN void wt_membrane_colors(int which, const plateau_mesh *mesh, const plateau_report *rep,
                                double *vals, plateau_index *marks, double view[3],
                                plateau_svg_colors *col)
{
    size_t i, nb = wt_membrane_boundary(which, rep);
    memset(col, 0, sizeof *col);
    wt_view(mesh->positions, mesh->triangles, mesh->num_triangles, view);
    col->view_dir = view;
    col->values = vals;
    col->num_values = mesh->num_vertices;
    col->per_vertex = 1;
    if (which == 0) {
        double zmax = 0;
        for (i = 0; i < mesh->num_vertices; i++) {
            vals[i] = mesh->positions[3 * i + 2];
            if (vals[i] > zmax) zmax = vals[i];
        }
        col->range_min = 0;
        col->range_max = zmax;
        col->title = "height z";
        return;
    }
    for (i = 0; i < mesh->num_vertices; i++)
        vals[i] = i < nb ? 0.0 : plateau_vertex_mean_curvature(mesh, i);
    col->range_min = -1;
    col->range_max = 1;
    col->title = "H_i (boundary 0)";
    for (i = 0; i < nb; i++) {
        marks[2 * i] = (plateau_index)i;
        marks[2 * i + 1] = (plateau_index)((i + 1) % nb);
    }
    col->marked_edges = marks;
    col->num_marked_edges = nb;
}

/* Panel 9 (after the rings' 8): a film with a pressure, and a
 * film edged by cables, against their exact solutions.  Returns 0, -1
 * when a solve or picture failed. */
DEMO_FN int wt_membrane_panel(FILE *f)
{
    double xyz[3 * 48], exact[5], view[3], *vals, hmin[2], hmax[2];
    plateau_report rep[2];
    plateau_mesh mesh[2];
    plateau_svg_colors col;
    plateau_error err;
    int k, status = 0;
    size_t m;
    wt_membrane_exact(&exact[0], &exact[1], &exact[2], &exact[3], &exact[4]);
    fprintf(f, "<h2 id=\"membrane\">Membranes: pressure and cables</h2>\n"
               "<section class=\"panel\" id=\"membrane-panel\">\n<h3>9. A film with a pressure, "
               "a film edged by cables</h3>\n<div class=\"row\">\n");
    for (k = 0; k < 2; k++) {
        plateau_options o;
        wt_membrane_options(k, xyz, &m, &o);
        if (plateau_solve(xyz, m, &o, &mesh[k], &rep[k], &err) != PLATEAU_OK) {
            fprintf(stderr, "membrane %d: %s\n", k, err.message);
            plateau_mesh_free(&mesh[k]);
            if (k == 1) plateau_mesh_free(&mesh[0]);
            return -1;
        }
        wt_membrane_h(k, &mesh[k], &rep[k], &hmin[k], &hmax[k]);
    }
    for (k = 0; k < 2; k++) {
        size_t nb = wt_membrane_boundary(k, &rep[k]);
        plateau_index *marks = (plateau_index *)malloc(2 * nb * sizeof(plateau_index));
        vals = (double *)malloc((mesh[k].num_vertices + 1) * sizeof(double));
        if (!vals || !marks) {
            free(vals);
            free(marks);
            status = -1;
            continue;
        }
        wt_membrane_colors(k, &mesh[k], &rep[k], vals, marks, view, &col);
        fprintf(f, "<div class=\"cell\" id=\"membrane-%s\">\n<p><b>%s</b></p>\n", k ? "cables" : "cap",
                k ? "four cables of tension T = 2" : "pressure p = 1");
        if (wt_inline_svg(f, mesh[k].positions, mesh[k].num_vertices, mesh[k].triangles,
                          mesh[k].num_triangles, &col))
            status = -1;
        fprintf(f, "</div>\n");
        free(vals);
        free(marks);
    }
    fprintf(f, "</div>\n<table><tr><th>film</th><th>figure</th><th>plateau</th><th>exact</th></tr>\n"
               "<tr><td>cap, p = 1</td><td>area</td><td>");
    wt_num(f, "membrane", "cap.area", rep[0].area, "%.6f");
    fprintf(f, "</td><td>");
    wt_num(f, "membrane", "cap.area_exact", exact[0], "%.6f");
    fprintf(f, "</td></tr>\n<tr><td></td><td>volume</td><td>");
    wt_num(f, "membrane", "cap.volume", rep[0].volume, "%.6f");
    fprintf(f, "</td><td>");
    wt_num(f, "membrane", "cap.volume_exact", exact[1], "%.6f");
    fprintf(f, "</td></tr>\n<tr><td>square, T = 2</td><td>film area</td><td>");
    wt_num(f, "membrane", "sail.area", rep[1].area, "%.6f");
    fprintf(f, "</td><td>");
    wt_num(f, "membrane", "sail.area_exact", exact[4], "%.6f");
    fprintf(f, "</td></tr>\n<tr><td></td><td>sag of cable 1</td><td>");
    wt_num(f, "membrane", "sail.sag", rep[1].cable[0].sag, "%.6f");
    fprintf(f, "</td><td>");
    wt_num(f, "membrane", "sail.sag_exact", exact[2], "%.6f");
    fprintf(f, "</td></tr>\n<tr><td></td><td>length of cable 1</td><td>");
    wt_num(f, "membrane", "sail.length", rep[1].cable[0].length, "%.6f");
    fprintf(f, "</td><td>");
    wt_num(f, "membrane", "sail.length_exact", exact[3], "%.6f");
    fprintf(f, "</td></tr>\n</table>\n<p>Not in the paper, whose motivation they are. Left: a "
               "film of unit tension with a pressure difference p across it minimises area "
               "&minus; p V (V the volume of the cone from the boundary's centroid), so its "
               "k<sub>1</sub> + k<sub>2</sub> is p everywhere: a spherical cap of radius 2 / p. "
               "Its colour is its height above the circle, in bands from the rim (dark) to the "
               "top (light); its discrete H<sub>i</sub> lies between ");
    wt_num(f, "membrane", "cap.h_min", hmin[0], "%.4f");
    fprintf(f, " and ");
    wt_num(f, "membrane", "cap.h_max", hmax[0], "%.4f");
    fprintf(f, " at the interior vertices, which is why H would paint it one flat tone. "
               "Right, seen face-on: every edge of the square is a cable of tension T between "
               "fixed corners (the four cables drawn in yellow); its vertices are free, and each "
               "balances the cable's pull against the film's, so the cable bends with radius T. "
               "The film stays flat: its colour is H<sub>i</sub>, the middle of its scale, the "
               "largest |H<sub>i</sub>| at the interior vertices being ");
    wt_num(f, "membrane", "sail.h_abs_max", fabs(hmin[1]) > fabs(hmax[1]) ? fabs(hmin[1]) : fabs(hmax[1]),
           "%.2g");
    fprintf(f, ". The exact figures come from those radii.</p>\n</section>\n");
    plateau_mesh_free(&mesh[0]);
    plateau_mesh_free(&mesh[1]);
    return status;
}

/* The design panel, 10: the figures it shows, from wt_design_collect
 * (tests/test_walkthrough.c solves the same). */
typedef struct wt_design {
    plateau_pattern pat;          /* the sail's panels for a roll 1.5 wide */
    double sail_area;             /* the sail's film area */
    double seam_mismatch;         /* largest |side 0 - side 1| / 3-D length of a seam */
    double free_area, supported_area, support_estimate; /* the saddle */
    double half_area, half_exact; /* the half catenoid, h = 1 */
} wt_design;

/* The four-point sail of examples/tent_design.c (a 6 x 6 square, corners
 * at heights 0 and 1.5 in turn, edges cables of tension 8, a mast head
 * ring of radius 0.8 at height 2.2), coarser (200 interior points, a ring
 * of 12), cut by planes through the mast's axis for a roll 1.5 wide. */
DEMO_FN int wt_design_sail(wt_design *d, plateau_error *err)
{
    static const double corners[12] = {-3, -3, 0, 3, -3, 1.5, 3, 3, 0, -3, 3, 1.5};
    double xyz[3 * 16], tension[16];
    size_t counts[2] = {4, 12}, i;
    plateau_options o;
    plateau_pattern_options po;
    plateau_report rep;
    plateau_mesh mesh;
    plateau_result r;
    memcpy(xyz, corners, sizeof corners);
    for (i = 0; i < 16; i++) {
        double t = 6.283185307179586 * (double)i / 12.0;
        tension[i] = i < 4 ? 8.0 : 0.0; /* the ring is rigid */
        if (i < 4) continue;
        xyz[3 * i] = 0.8 * cos(t);
        xyz[3 * i + 1] = 0.8 * sin(t);
        xyz[3 * i + 2] = 2.2;
    }
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 200;
    o.cable_tension = tension;
    r = plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, err);
    d->sail_area = rep.area;
    memset(&po, 0, sizeof po);
    po.width = 1.5;
    po.seams = PLATEAU_SEAMS_AXIS;
    po.direction[2] = 1.0;
    if (r == PLATEAU_OK)
        r = plateau_pattern_make(mesh.positions, mesh.num_vertices, mesh.triangles, mesh.num_triangles, &po,
                                 NULL, &d->pat, err);
    plateau_mesh_free(&mesh);
    d->seam_mismatch = 0;
    for (i = 0; r == PLATEAU_OK && i < d->pat.num_seams; i++) {
        const plateau_pattern_seam *s = &d->pat.seams[i];
        double e = fabs(s->lengths[0] - s->lengths[1]) / s->length_3d;
        if (e > d->seam_mismatch) d->seam_mismatch = e;
    }
    return r == PLATEAU_OK ? 0 : -1;
}

/* The saddle (x, y, x y) over the square [-1, 1]^2, 8 points a side, 128
 * interior points, method area, with (supported) or without the y axis
 * between the sides' midpoints (15 points) as an interior support: the
 * half-turn about that axis maps the film to itself, so the film contains
 * it (tests/test_supports.c). */
DEMO_FN int wt_design_saddle(int supported, plateau_report *rep, plateau_error *err)
{
    double b[3 * 32], sup[3 * 15];
    size_t counts[1] = {15}, i;
    plateau_options o;
    plateau_mesh mesh;
    plateau_result r;
    for (i = 0; i < 32; i++) { /* side s from corner s to corner s + 1 */
        static const double c[5][2] = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
        double t = (double)(i % 8) / 8.0;
        b[3 * i] = c[i / 8][0] + t * (c[i / 8 + 1][0] - c[i / 8][0]);
        b[3 * i + 1] = c[i / 8][1] + t * (c[i / 8 + 1][1] - c[i / 8][1]);
        b[3 * i + 2] = b[3 * i] * b[3 * i + 1];
    }
    for (i = 0; i < 15; i++) {
        sup[3 * i] = sup[3 * i + 2] = 0.0;
        sup[3 * i + 1] = -1.0 + 2.0 * (double)(i + 1) / 16.0;
    }
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 128;
    o.accuracy = -1.0;
    if (supported) {
        o.supports = sup;
        o.support_counts = counts;
        o.num_support_polylines = 1;
    }
    r = plateau_solve(b, 32, &o, &mesh, rep, err);
    plateau_mesh_free(&mesh);
    return r == PLATEAU_OK ? 0 : -1;
}

/* Half the catenoid between unit rings h = 1 apart: the ring at z = 1/2
 * fixed, a ring of 24 vertices on z = 0 sliding on that plane, 60
 * interior points (tests/test_sliding.c); its area, and the exact one. */
DEMO_FN int wt_design_half_catenoid(wt_design *d, plateau_error *err)
{
    double xyz[3 * 48], dir[3 * 48];
    int slide[48];
    size_t counts[2] = {24, 24}, i;
    plateau_options o;
    plateau_report rep;
    plateau_mesh mesh;
    plateau_result r;
    demo_rings(xyz, 24, 1.0);
    for (i = 0; i < 48; i++) {
        slide[i] = i < 24 ? PLATEAU_SLIDE_PLANE : 0;
        if (i < 24) xyz[3 * i + 2] = 0.0;
        dir[3 * i] = dir[3 * i + 1] = 0.0;
        dir[3 * i + 2] = 1.0;
    }
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = 60;
    o.slide = slide;
    o.slide_direction = dir;
    r = plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, err);
    plateau_mesh_free(&mesh);
    d->half_area = rep.area;
    d->half_exact = demo_catenoid_area(1.0) / 2.0;
    return r == PLATEAU_OK ? 0 : -1;
}

/* All of panel 10's figures; free d->pat with plateau_pattern_free (also
 * after an error).  Returns 0, -1 when a solve failed (message in err). */
DEMO_FN int wt_design_collect(wt_design *d, plateau_error *err)
{
    plateau_report rep[2];
    memset(d, 0, sizeof *d);
    if (wt_design_sail(d, err) || wt_design_saddle(0, &rep[0], err) || wt_design_saddle(1, &rep[1], err))
        return -1;
    d->free_area = rep[0].area;
    d->supported_area = rep[1].area;
    d->support_estimate = rep[1].area_error_estimate;
    return wt_design_half_catenoid(d, err);
}

/* The sail's film from the pattern's own vertices and triangles, each
 * triangle coloured by its panel, the seams marked. */
DEMO_FN int wt_design_sail_svg(FILE *f, const plateau_pattern *pat)
{
    double *vals = (double *)malloc((pat->num_triangles + 1) * sizeof(double)), view[3];
    plateau_index *marks = (plateau_index *)malloc((2 * pat->num_seam_edges + 1) * sizeof(plateau_index));
    plateau_svg_colors col;
    size_t p, t, e;
    int status;
    if (!vals || !marks) {
        free(vals);
        free(marks);
        return -1;
    }
    for (p = 0; p < pat->num_panels; p++)
        for (t = 0; t < pat->panels[p].num_triangles; t++) vals[pat->panels[p].first_triangle + t] = (double)p;
    for (e = 0; e < pat->num_seam_edges; e++) {
        marks[2 * e] = pat->seam_edges[4 * e];
        marks[2 * e + 1] = pat->seam_edges[4 * e + 1];
    }
    memset(&col, 0, sizeof col);
    wt_view(pat->xyz, pat->triangles, pat->num_triangles, view);
    col.view_dir = view;
    col.values = vals;
    col.num_values = pat->num_triangles;
    col.range_max = (double)(pat->num_panels > 1 ? pat->num_panels - 1 : 1);
    col.title = "panel";
    col.marked_edges = marks;
    col.num_marked_edges = pat->num_seam_edges;
    status = wt_inline_svg(f, pat->xyz, pat->num_vertices, pat->triangles, pat->num_triangles, &col);
    free(vals);
    free(marks);
    return status;
}

/* The last panel, 10 (after the membranes' 9): a sail cut into panels, a
 * support on a film, an edge that slides.  Returns 0, -1 when a solve or
 * picture failed. */
DEMO_FN int wt_design_panel(FILE *f)
{
    static const char *const support_keys[3] = {"area", "free_area", "difference"};
    static const char *const support_words[2] = {" against ", " free, a relative difference of "};
    static const char *const slide_keys[3] = {"area", "exact", "error"};
    static const char *const slide_words[2] = {" against the exact ", " (relative error "};
    wt_design d;
    plateau_error err;
    FILE *tmp;
    size_t i;
    int status = 0;
    if (wt_design_collect(&d, &err)) {
        fprintf(stderr, "design: %s\n", err.message);
        plateau_pattern_free(&d.pat);
        return -1;
    }
    fprintf(f, "<section class=\"panel\" id=\"design-panel\">\n<h3>10. Membrane design: cutting "
               "patterns, supports, sliding edges</h3>\n<div class=\"row\">\n<div class=\"cell\" "
               "id=\"design-sail\">\n");
    if (wt_design_sail_svg(f, &d.pat)) status = -1;
    fprintf(f, "</div>\n<div class=\"cell\" id=\"design-flat\">\n");
    tmp = tmpfile();
    if (!tmp || plateau_pattern_write_svg_stream(tmp, &d.pat, 0.5, &err) != PLATEAU_OK ||
        wt_inline_stream(f, tmp, "design-flat")) {
        if (tmp) fclose(tmp);
        status = -1;
    }
    fprintf(f, "</div>\n</div>\n<table><tr><th>panel</th><th>area on the film</th><th>flat area</th>"
               "<th>largest strain</th><th>width</th><th>fits the roll</th></tr>\n");
    for (i = 0; i < d.pat.num_panels; i++) {
        const plateau_pattern_panel *pp = &d.pat.panels[i];
        char row[32];
        sprintf(row, "panel%lu", (unsigned long)i);
        fprintf(f, "<tr><td>%lu</td>", (unsigned long)i);
        wt_cell(f, "design", row, "area_3d", pp->area_3d, "%.4f");
        wt_cell(f, "design", row, "area_flat", pp->area_flat, "%.4f");
        wt_cell(f, "design", row, "max_strain", pp->max_strain, "%.4f");
        wt_cell(f, "design", row, "width", pp->width, "%.3f");
        fprintf(f, "<td>%s</td></tr>\n", pp->width <= d.pat.roll_width ? "yes" : "no");
    }
    fprintf(f, "</table>\n<p>The four-point sail of examples/tent_design.c (corners 0 and 1.5 m "
               "high in turn, cables of tension 8 on its edges, lifted by a mast whose head is a "
               "ring), film area ");
    wt_num(f, "design", "sail.area", d.sail_area, "%.3f");
    fprintf(f, " m<sup>2</sup>, cut by half-planes through the mast's axis into panels that fit a "
               "roll 1.5 m wide (left: each triangle coloured by its panel, the seams marked; right: "
               "the flattened panels on their strips, seam marks every 0.5 m). Each panel is "
               "flattened by a conformal map, then a local/global strain minimisation; the two "
               "sides of every seam differ in flat length by at most ");
    wt_num(f, "design", "seam_mismatch", 100 * d.seam_mismatch, "%.2g");
    fprintf(f, " %% of it.</p>\n<p><b>Interior supports</b> (<code>options.supports</code>): "
               "the saddle z = x y over the square, with the y axis, a line the film contains by "
               "symmetry, held as a support, has area ");
    wt_versus(f, "design", "support", support_keys, d.supported_area, d.free_area, "%.6f", support_words,
              "%.2e");
    fprintf(f, " within the solve's own error estimate ");
    wt_num(f, "design", "support.estimate", d.support_estimate, "%.2e");
    fprintf(f, " (<code>report.area_error_estimate</code>).</p>\n<p><b>Sliding edges</b> "
               "(<code>options.slide</code>): a ring on z = 1/2 and a ring free to slide on the "
               "plane z = 0 give half the catenoid between rings 1 apart, the film meeting the "
               "plane at a right angle: area ");
    wt_versus(f, "design", "slide", slide_keys, d.half_area, d.half_exact, "%.5f", slide_words, "%.1e");
    fprintf(f, ", 24 vertices a ring).</p>\n</section>\n");
    plateau_pattern_free(&d.pat);
    return status;
}

/* The error estimate's panel, 11: the catenoid between rings of
 * WT_ACC_M vertices h = WT_ACC_H apart at WT_ACC_RUNS interior counts, one
 * solve each (accuracy -1), its estimate against the true error, and the
 * first mesh coloured by each triangle's share of its estimate
 * (plateau_mesh_error_indicator). */
#define WT_ACC_M 128
#define WT_ACC_H 1.0
#define WT_ACC_RUNS 3
typedef struct wt_accuracy {
    size_t interior[WT_ACC_RUNS];
    double area[WT_ACC_RUNS], estimate[WT_ACC_RUNS];
    double exact;         /* the polygon's film, from the smooth catenoid */
    plateau_mesh graded;  /* the first run's mesh (the library's grading) */
    double *indicator;    /* its triangles' shares of the estimate */
    double indicator_sum; /* their sum */
} wt_accuracy;

/* The options of run k: method area (least area, the film the estimate
 * measures against; half the time of method paper here), 400 interior
 * points, doubled each run. */
DEMO_FN plateau_options wt_accuracy_options(int k)
{
    plateau_options o;
    memset(&o, 0, sizeof o);
    o.method = PLATEAU_METHOD_AREA;
    o.interior_points = (size_t)400 << k;
    o.accuracy = -1.0;
    o.stability = PLATEAU_OFF;
    o.alternatives = PLATEAU_OFF;
    return o;
}

/* The exact area for rings of m chords: the catenoid through the chords'
 * midpoints (radius cos(pi / m)), the smooth one scaled (as in
 * tests/test_accuracy.c); the polygon's own optimum is within O(1 / m^2)
 * of it, far below the errors shown. */
DEMO_FN double wt_accuracy_exact(void)
{
    double c = cos(M_PI / WT_ACC_M);
    return c * c * demo_catenoid_area(WT_ACC_H / c);
}

DEMO_FN void wt_accuracy_free(wt_accuracy *a)
{
    plateau_mesh_free(&a->graded);
    free(a->indicator);
    a->indicator = NULL;
}

/* All of panel 11's figures (free with wt_accuracy_free, also after an
 * error).  Returns 0, -1 when a solve failed (message in err). */
DEMO_FN int wt_accuracy_collect(wt_accuracy *a, plateau_error *err)
{
    double xyz[6 * WT_ACC_M];
    size_t counts[2] = {WT_ACC_M, WT_ACC_M}, t;
    int k;
    memset(a, 0, sizeof *a);
    demo_rings(xyz, WT_ACC_M, WT_ACC_H);
    a->exact = wt_accuracy_exact();
    for (k = 0; k < WT_ACC_RUNS; k++) {
        plateau_options o = wt_accuracy_options(k);
        plateau_report rep;
        plateau_mesh mesh;
        if (plateau_solve_loops(xyz, counts, 2, &o, &mesh, &rep, err) != PLATEAU_OK) return -1;
        a->interior[k] = rep.interior_points;
        a->area[k] = rep.area;
        a->estimate[k] = rep.area_error_estimate;
        if (k == 0) a->graded = mesh;
        else plateau_mesh_free(&mesh);
    }
    a->indicator = (double *)malloc((a->graded.num_triangles + 1) * sizeof(double));
    if (!a->indicator || plateau_mesh_error_indicator(&a->graded, a->indicator, NULL, err) != PLATEAU_OK)
        return -1;
    for (t = 0; t < a->graded.num_triangles; t++) a->indicator_sum += a->indicator[t];
    return 0;
}

/* The meshes of the panel: the library's graded mesh coloured by the
 * indicator (per triangle, in units of 1e-6 of the area).  There is no
 * adaptive mesh to set beside it: examples/NOTES.md section 17 says why. */
DEMO_FN int wt_accuracy_meshes(FILE *f, const wt_accuracy *a)
{
    const plateau_mesh *g = &a->graded;
    double *vals = (double *)malloc((g->num_triangles + 1) * sizeof(double));
    plateau_svg_colors col;
    size_t t;
    int status;
    if (!vals) return -1;
    for (t = 0; t < g->num_triangles; t++) vals[t] = 1e6 * a->indicator[t];
    memset(&col, 0, sizeof col);
    col.values = vals;
    col.num_values = g->num_triangles;
    col.title = "share, 1e-6";
    col.range_min = 0.0;
    for (t = 0; t < g->num_triangles; t++)
        if (vals[t] > col.range_max) col.range_max = vals[t];
    fprintf(f, "<div class=\"cell\" id=\"accuracy-graded\">\n");
    status = wt_inline_svg(f, g->positions, g->num_vertices, g->triangles, g->num_triangles, &col);
    fprintf(f, "<p>The graded mesh, %lu interior points</p>\n</div>\n", (unsigned long)a->interior[0]);
    free(vals);
    return status;
}

/* Panel 11 (after the design's 10).  Returns 0, -1 when a solve or
 * picture failed. */
DEMO_FN int wt_accuracy_panel(FILE *f)
{
    wt_accuracy a;
    plateau_error err;
    int k, status = 0;
    if (wt_accuracy_collect(&a, &err)) {
        fprintf(stderr, "accuracy: %s\n", err.message);
        wt_accuracy_free(&a);
        return -1;
    }
    fprintf(f, "<section class=\"panel\" id=\"accuracy-panel\">\n<h3>11. The error estimate</h3>\n"
               "<div class=\"row\">\n");
    if (wt_accuracy_meshes(f, &a)) status = -1;
    fprintf(f, "</div>\n<table><tr><th>interior points</th><th>area</th><th>true error</th>"
               "<th>estimate</th><th>effectivity</th></tr>\n");
    for (k = 0; k < WT_ACC_RUNS; k++) {
        double e = a.area[k] / a.exact - 1.0;
        char row[32];
        sprintf(row, "run%d", k);
        fprintf(f, "<tr>");
        wt_cell(f, "accuracy", row, "interior", (double)a.interior[k], "%.0f");
        wt_cell(f, "accuracy", row, "area", a.area[k], "%.6f");
        wt_cell(f, "accuracy", row, "true", e, "%.2e");
        wt_cell(f, "accuracy", row, "estimate", a.estimate[k], "%.2e");
        wt_cell(f, "accuracy", row, "effectivity", e / a.estimate[k], "%.2f");
        fprintf(f, "</tr>\n");
    }
    fprintf(f, "</table>\n<p>Every result carries <code>report.area_error_estimate</code>, the "
               "estimated relative error of its area against the exact minimal surface. It is "
               "formed on a copy of the result split 1-to-4: a few conjugate-gradient steps on "
               "the area's quadratic model in the normal motions of that finer mesh give the "
               "area the finer mesh would still shed; the area's error falls as h<sup>2</sup>, "
               "so that decrease is 3/4 of the coarse mesh's error. Here the catenoid between "
               "rings of radius 1, %d vertices each, h = %.1f apart, method area (exact area ",
            WT_ACC_M, WT_ACC_H);
    wt_num(f, "accuracy", "exact", a.exact, "%.6f");
    fprintf(f, " for the rings' chords), at three interior counts: the effectivity, true error "
               "over estimate, stays near 1. The picture colours each triangle by its share of "
               "the estimate (<code>plateau_mesh_error_indicator</code>: the decrease found "
               "at its part of the split mesh); the shares sum to ");
    wt_num(f, "accuracy", "indicator_sum", a.indicator_sum, "%.3e");
    fprintf(f, ", the estimate up to the steps' convergence. The large shares lie at the "
               "neck, where the film bends most and the grading, which follows the rings, "
               "puts no extra points.</p>\n</section>\n");
    wt_accuracy_free(&a);
    return status;
}

/* The rings' panel (after the cases). Returns 0, -1 when a picture failed. */
DEMO_FN int wt_write_rings(FILE *f, const wt_rings *r)
{
    static const char *const names[3] = {"stable", "unstable", "discs"};
    static const char *const titles[3] = {"the stable catenoid", "the unstable catenoid",
                                          "two discs"};
    int k, status = 0;
    char key[64];
    fprintf(f, "<h2 id=\"rings\">Two rings: which film? (the second variation)</h2>\n"
               "<section class=\"panel\" id=\"rings-films\">\n<h3>8. Three films between the same two "
               "rings, radius 1, %d vertices each, h = %.1f apart</h3>\n<div class=\"row\">\n",
            WT_RINGS_M, WT_RINGS_H);
    for (k = 0; k < 3; k++) {
        plateau_svg_colors col;
        memset(&col, 0, sizeof col);
        col.values = r->mode[k];
        col.num_values = r->mesh[k].num_vertices;
        col.per_vertex = 1;
        col.title = "lowest mode";
        fprintf(f, "<div class=\"cell\">\n");
        if (wt_inline_svg(f, r->mesh[k].positions, r->mesh[k].num_vertices, r->mesh[k].triangles,
                          r->mesh[k].num_triangles, &col) != 0)
            status = -1;
        fprintf(f, "<p><b>%s</b>: area ", titles[k]);
        sprintf(key, "%s.area", names[k]);
        wt_num(f, "rings", key, r->area[k], "%.4f");
        fprintf(f, " (exact ");
        sprintf(key, "%s.exact", names[k]);
        wt_num(f, "rings", key, r->exact[k], "%.4f");
        fprintf(f, "), index ");
        sprintf(key, "%s.index", names[k]);
        wt_num(f, "rings", key, (double)r->status[k].index, "%.0f");
        fprintf(f, ", lowest eigenvalue ");
        sprintf(key, "%s.lowest", names[k]);
        wt_num(f, "rings", key, r->status[k].lowest_eigenvalues[0], "%.3f");
        fprintf(f, "</p>\n</div>\n");
    }
    fprintf(f, "</div>\n<p>The index is the number of independent normal motions that lower "
               "the area (the negative eigenvalues of its Hessian on normal motions, counted "
               "exactly from a sparse L D L<sup>T</sup> by Sylvester's law). The stable "
               "catenoid is a local minimum, but the two discs have less area: at this distance "
               "a soap film on the catenoid is only metastable, and a large enough disturbance "
               "takes it to the discs. The unstable catenoid is a saddle: its "
               "lowest mode (colour) narrows or widens the neck, and either way the area "
               "falls, towards the stable catenoid or towards the discs. Past h = 1.3255 no "
               "catenoid is left.</p>\n</section>\n");
    return status;
}

/* The page for the cases (and, when rings is not NULL, the rings' panel).
 * Returns 0, -1 when a picture failed. */
DEMO_FN int wt_write_html(FILE *f, wt_case *cases, size_t count, const wt_rings *rings)
{
    size_t ci;
    int status = 0;
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
               "<title>plateau: the algorithm step by step</title>\n<style>\n%s</style>\n"
               "</head>\n<body>\n<h1>Minimal triangle meshes, step by step</h1>\n"
               "<p>The algorithm of &ldquo;Constructing Minimal Triangular Mesh Based on "
               "Discrete Mean Curvature&rdquo; (section II, Fig. 1) as the library "
               "<code>plateau.h</code> runs it, on the paper's helicoid (III.A) and catenoid "
               "(III.B). Made by <code>make demo</code> (examples/walkthrough.c); every number "
               "comes from a report of the library in this build; every picture is inline SVG. "
               "The page uses the paper's own seeding (the fan candidates of II.A, "
               "<code>options.seeding = PLATEAU_SEEDING_PAPER</code>); the demo's table uses the "
               "default quality seeding, so its figures differ a little.</p>\n"
               "<p>Each picture in space (but the rings', which share one view to compare) looks "
               "along a direction chosen from its surface by one rule: with M = &Sigma; (area) n n<sup>T</sup> over the "
               "triangles (n the unit normal), eigenvalues &lambda;<sub>1</sub> &ge; "
               "&lambda;<sub>2</sub> &ge; &lambda;<sub>3</sub> and eigenvectors "
               "e<sub>1</sub>, e<sub>2</sub>, e<sub>3</sub>, the eye looks along "
               "e<sub>1</sub> + &radic;(&lambda;<sub>2</sub>/&lambda;<sub>1</sub>) e<sub>2</sub> + "
               "&radic;(&lambda;<sub>3</sub>/&lambda;<sub>1</sub>) e<sub>3</sub>: along "
               "e<sub>1</sub> the surface is most face-on, and the view turns from it as far as "
               "the surface's normals spread, so a flat film is seen face-on and a curved one "
               "shows its bend (the helicoid its twist: one end face-on, the other turned "
               "away). A case's pictures all use the view of its method-paper mesh.</p>\n",
            wt_style);
    for (ci = 0; ci < count; ci++) {
        wt_case *w = &cases[ci];
        const char *name = w->c->name;
        int helicoid = w->c->kind == DEMO_HELICOID;
        plateau_svg_colors col;
        double *vals;
        int k;
        size_t i;
        vals = (double *)malloc((w->start.num_vertices + w->start.num_triangles + 1) * sizeof(double));
        if (!vals) return -1;
        fprintf(f, "<h2 id=\"%s\">%s</h2>\n", name,
                helicoid ? "Helicoid (III.A): r(u,v) = (u cos v, u sin v, b v), b = 1.9"
                         : "Catenoid (III.B): r(u,v) = (b cos u cosh v, b v, b sin u cosh v), b = 2.05");

        /* 1. the boundary */
        fprintf(f, "<section class=\"panel\" id=\"%s-boundary\">\n<h3>1. The closed polygon L "
                   "(II.A)</h3>\n<div class=\"row\"><div class=\"cell\">\n", name);
        wt_svg_boundary(f, w);
        fprintf(f, "</div><div class=\"cell\"><p>The input of the Plateau-Mesh problem: a closed "
                   "polygon L in space with vertices V<sub>1</sub> &hellip; V<sub>m</sub>, here m = ");
        wt_num(f, name, "m", (double)w->m, "%.0f");
        fprintf(f, " points of the %s's border seen in space, walked from V1 (circled); the dots are "
                   "coloured by their height z, dark low, light high. They become the first m "
                   "vertices of every mesh below and never move. The paper asks for n = ",
                helicoid ? "helicoid" : "catenoid");
        wt_num(f, name, "n", (double)w->full.seeded_points, "%.0f");
        fprintf(f, " interior vertices.</p><p>This picture and those below look along (");
        wt_num(f, name, "view_x", w->view[0], "%.3f");
        fprintf(f, ", ");
        wt_num(f, name, "view_y", w->view[1], "%.3f");
        fprintf(f, ", ");
        wt_num(f, name, "view_z", w->view[2], "%.3f");
        fprintf(f, "), the rule above on the film of method paper (panel 7); seen so, its "
                   "triangles' projected area is ");
        wt_num(f, name, "view_facing",
               100 * wt_facing(w->method_mesh[0].positions, w->method_mesh[0].triangles,
                               w->method_mesh[0].num_triangles, w->view, NULL, NULL),
               "%.0f");
        fprintf(f, " %% of their area (100 %% only for a flat film seen face-on).</p></div></div>\n"
                   "</section>\n");

        /* 2. the domain, the fan, the candidates */
        fprintf(f, "<section class=\"panel\" id=\"%s-domain\">\n<h3>2. Candidate points in the "
                   "plane (II.A, Fig. 1)</h3>\n<div class=\"row\"><div class=\"cell\">\n", name);
        wt_svg_domain(f, w, 0);
        fprintf(f, "</div><div class=\"cell\"><p>L is laid flat on its best-fit plane (the "
                   "paper leaves this plane open). The first candidate V&prime;<sub>1</sub> is the "
                   "centroid (1/m) &Sigma; V<sub>i</sub>; the fan triangles (V<sub>j-1</sub>, "
                   "V<sub>j</sub>, V&prime;<sub>1</sub>) give V&prime;<sub>j</sub> = "
                   "(V<sub>j</sub> + V<sub>j-1</sub> + V&prime;<sub>1</sub>) / 3, and each "
                   "triangle cut at its barycentre gives the next level (large circles: levels "
                   "0 to ");
        wt_num(f, name, "level", (double)w->chosen_level, "%.0f");
        fprintf(f, ", ");
        wt_num(f, name, "candidates", (double)w->candidates_upto_k, "%.0f");
        fprintf(f, " candidates; small circles: the next level, not needed).</p><p>The n = ");
        wt_num(f, name, "chosen", (double)w->chosen_matched, "%.0f");
        fprintf(f, " red points are drawn among them with a seeded generator "
                   "(&ldquo;picking up randomly&rdquo;; the first n in order, as printed, "
                   "would crowd one side).</p></div></div>\n</section>\n");

        /* 3. the constrained Delaunay triangulation */
        fprintf(f, "<section class=\"panel\" id=\"%s-cdt\">\n<h3>3. Constrained Delaunay "
                   "triangulation (II.A)</h3>\n<div class=\"row\"><div class=\"cell\">\n", name);
        wt_svg_domain(f, w, 1);
        fprintf(f, "</div><div class=\"cell\"><p>&ldquo;Carrying out the Delaunay "
                   "triangulation with the boundary of L&rdquo; by the random incremental "
                   "method [14]: the polygon's edges are kept as constraints, so the "
                   "triangles fill exactly the domain. ");
        wt_num(f, name, "cdt_triangles", (double)w->start.num_triangles, "%.0f");
        fprintf(f, " triangles; smallest angle in the plane ");
        wt_num(f, name, "domain_min_angle", w->full.domain_min_angle_deg, "%.1f");
        fprintf(f, " degrees.</p></div></div>\n</section>\n");

        /* 4. the lifted start mesh by |H_i| */
        for (i = 0; i < w->start.num_vertices; i++)
            vals[i] = fabs(plateau_vertex_mean_curvature(&w->start, i));
        memset(&col, 0, sizeof col);
        col.values = vals;
        col.num_values = w->start.num_vertices;
        col.per_vertex = 1;
        col.range_min = 0;
        col.range_max = w->start_hmax;
        col.title = "|H_i|";
        {
            double view[3];
            memcpy(view, w->view, 3 * sizeof(double));
            col.view_dir = view;
            fprintf(f, "<section class=\"panel\" id=\"%s-start\">\n<h3>4. The start mesh in space, "
                       "coloured by |H<sub>i</sub>| (II.B, eq. (1))</h3>\n<div class=\"row\">"
                       "<div class=\"cell\">\n", name);
            if (wt_inline_svg(f, w->start.positions, w->start.num_vertices, w->start.triangles,
                              w->start.num_triangles, &col))
                status = -1;
        }
        fprintf(f, "</div><div class=\"cell\"><p>Each point keeps its barycentric combination "
                   "of the V<sub>i</sub>, so the planar triangles lift to a first mesh in space "
                   "(the paper's Fig. 6(1) and 7(1)); area ");
        wt_num(f, name, "start_area", plateau_mesh_area(&w->start), "%.5f");
        fprintf(f, ", smallest angle ");
        wt_num(f, name, "start_min_angle", w->full.initial_min_angle_deg, "%.1f");
        fprintf(f, " degrees. Colour: the discrete mean curvature H<sub>i</sub> = (1/|B|) "
                   "&Sigma; &beta;(e) |e|/2 of II.B, painted on each vertex's barycentric cell B, "
                   "from 0 to the largest interior value ");
        wt_num(f, name, "start_hmax", w->start_hmax, "%.3g");
        fprintf(f, ". The boundary cells share the scale (clamped at its top where larger), "
                   "but there H measures the polygon's corners on a one-sided cell, not the "
                   "surface, which is why method paper sums eq. (1) over the interior vertices "
                   "only. Its F = (1/2) &Sigma; |H<sub>i</sub>|<sup>2</sup> "
                   "(with two tangential rows per vertex) starts at ");
        wt_num(f, name, "start_f", w->full.f_initial, "%.3e");
        fprintf(f, ".</p></div></div>\n</section>\n");

        /* 5. F per LM iteration */
        fprintf(f, "<section class=\"panel\" id=\"%s-fchart\">\n<h3>5. F per Levenberg-Marquardt "
                   "iteration, per round (II.D, Fig. 5)</h3>\n", name);
        wt_svg_fchart(f, w);
        fprintf(f, "<p>LM minimises eq. (1) with the exact Jacobian of eq. (2) (the derivative "
                   "of &beta; in a well-conditioned form instead of eq. (3)) and the damping of "
                   "Fig. 5; the curve is what <code>options.progress</code> reports after every "
                   "iteration, in the report's units. The system is square and solved exactly, so F "
                   "falls quadratically to rounding. Each round is one solve followed by a "
                   "re-triangulation (II.A: &ldquo;repeating the last two steps&rdquo;):</p>\n"
                   "<table><tr><th>round</th><th>LM iterations</th><th>F at its end</th>"
                   "<th>edges flipped after it</th></tr>\n");
        for (k = 0; k < w->rounds; k++) {
            char key[64];
            fprintf(f, "<tr><td>%d</td><td>", k + 1);
            sprintf(key, "round%d.iterations", k + 1);
            wt_num(f, name, key, (double)w->round_iterations[k], "%.0f");
            fprintf(f, "</td><td>");
            sprintf(key, "round%d.f", k + 1);
            wt_num(f, name, key, w->full.f_rounds[k], "%.2e");
            fprintf(f, "</td><td>");
            sprintf(key, "round%d.flips", k + 1);
            wt_num(f, name, key, (double)w->round_flips[k], "%.0f");
            fprintf(f, "</td></tr>\n");
        }
        fprintf(f, "</table>\n<p>In all ");
        wt_num(f, name, "rounds", (double)w->full.rounds, "%.0f");
        fprintf(f, " rounds, ");
        wt_num(f, name, "iterations", (double)w->full.iterations, "%.0f");
        fprintf(f, " iterations and ");
        wt_num(f, name, "flips", (double)w->full.flips, "%.0f");
        fprintf(f, " flips.</p>\n</section>\n");

        /* 6. the mesh after each round */
        fprintf(f, "<section class=\"panel\" id=\"%s-rounds\">\n<h3>6. The mesh after each round, "
                   "flipped edges marked (II.A, Fig. 1's loop)</h3>\n<div class=\"row\">\n", name);
        for (k = 0; k < w->rounds; k++) {
            const plateau_mesh *solved = &w->solved[k], *next;
            plateau_index marks[2 * WT_MAX_MARKS];
            char key[64];
            double view[3];
            size_t nm = wt_round_colors(w, k, vals, marks, view, &col, &next);
            fprintf(f, "<div class=\"cell\" id=\"%s-round-%d\">\n", name, k + 1);
            if (wt_inline_svg(f, solved->positions, solved->num_vertices, next->triangles,
                              next->num_triangles, &col))
                status = -1;
            fprintf(f, "<p>Round %d: area ", k + 1);
            sprintf(key, "round%d.area", k + 1);
            wt_num(f, name, key, w->solved_rep[k].area, "%.5f");
            fprintf(f, ", smallest angle ");
            sprintf(key, "round%d.min_angle", k + 1);
            wt_num(f, name, key, w->solved_rep[k].min_angle_deg, "%.1f");
            if (nm)
                fprintf(f, " degrees after the solve; then the marked edges were flipped.</p>\n</div>\n");
            else
                fprintf(f, " degrees after the solve; the rounds end: %s.</p>\n</div>\n",
                        plateau_stop_string(w->full.stop));
        }
        fprintf(f, "</div>\n<p>After each solve the triangulation is redone: here by intrinsic "
                   "Delaunay edge flips on the surface (an edge flips when the two angles facing "
                   "it sum to more than &pi;), the new edges in yellow on black; the paper redoes "
                   "the planar Delaunay triangulation (method paper-literal below). Triangles are "
                   "coloured by their smallest angle: flips remove thin ones.</p>\n</section>\n");

        /* 7. the three methods */
        fprintf(f, "<section class=\"panel\" id=\"%s-methods\">\n<h3>7. Three methods from the "
                   "same start (III.%s)</h3>\n<div class=\"row\">\n", name, helicoid ? "A" : "B");
        for (k = 0; k < 3; k++) {
            const plateau_mesh *mm = &w->method_mesh[k];
            double view[3];
            wt_angles(mm->positions, mm->triangles, mm->num_triangles, vals);
            memset(&col, 0, sizeof col);
            col.values = vals;
            col.num_values = mm->num_triangles;
            col.range_min = 0;
            col.range_max = 60;
            col.title = "smallest angle, deg";
            memcpy(view, w->view, 3 * sizeof(double));
            col.view_dir = view;
            fprintf(f, "<div class=\"cell\" id=\"%s-method-%s\">\n<p><b>%s</b></p>\n", name,
                    plateau_method_name(demo_methods[k]), plateau_method_name(demo_methods[k]));
            if (wt_inline_svg(f, mm->positions, mm->num_vertices, mm->triangles, mm->num_triangles, &col))
                status = -1;
            fprintf(f, "</div>\n");
        }
        fprintf(f, "</div>\n<div class=\"row\">\n");
        {
            /* the same three by |H_i| on one scale: where the curvature sits after */
            double hmax = 0;
            int j;
            for (j = 0; j < 3; j++)
                for (i = w->m; i < w->method_mesh[j].num_vertices; i++) {
                    double h = fabs(plateau_vertex_mean_curvature(&w->method_mesh[j], i));
                    if (h > hmax) hmax = h;
                }
            for (j = 0; j < 3; j++) {
                const plateau_mesh *mm = &w->method_mesh[j];
                double view[3];
                for (i = 0; i < mm->num_vertices; i++)
                    vals[i] = fabs(plateau_vertex_mean_curvature(mm, i));
                memset(&col, 0, sizeof col);
                col.values = vals;
                col.num_values = mm->num_vertices;
                col.per_vertex = 1;
                col.range_min = 0;
                col.range_max = hmax;
                col.title = "|H_i|";
                memcpy(view, w->view, 3 * sizeof(double));
                col.view_dir = view;
                fprintf(f, "<div class=\"cell\" id=\"%s-curvature-%s\">\n", name,
                        plateau_method_name(demo_methods[j]));
                if (wt_inline_svg(f, mm->positions, mm->num_vertices, mm->triangles,
                                  mm->num_triangles, &col))
                    status = -1;
                fprintf(f, "</div>\n");
            }
        }
        fprintf(f, "</div>\n<p>Top row: each triangle by its smallest angle (0 to 60 degrees). "
                   "Bottom row: |H<sub>i</sub>| on one scale for the three, the largest interior "
                   "value of any at its top (boundary cells clamped): method paper drives it to "
                   "rounding at every interior vertex (compare panel 4), paper-literal trades it "
                   "against the boundary terms, area leaves a little (least area and H = 0 agree "
                   "only in the limit of fine meshes).</p>\n"
                   "<table><tr><th>method</th><th>area</th><th>F (its objective)</th>"
                   "<th>smallest angle, deg</th><th>paper's ERR</th><th>mean |H<sub>i</sub>|, "
                   "interior</th><th>iterations</th><th>rounds</th></tr>\n");
        for (k = 0; k < 3; k++) {
            const char *mn = plateau_method_name(demo_methods[k]);
            fprintf(f, "<tr><td>%s</td>", mn);
            wt_cell(f, name, mn, "area", w->method_rep[k].area, "%.5f");
            wt_cell(f, name, mn, "f", w->method_rep[k].f_final, "%.3e");
            wt_cell(f, name, mn, "min_angle", w->method_rep[k].min_angle_deg, "%.1f");
            wt_cell(f, name, mn, "err", w->method_row[k].err_mean, "%.3e");
            wt_cell(f, name, mn, "h_mean", w->method_row[k].h_mean, "%.2e");
            wt_cell(f, name, mn, "iterations", (double)w->method_rep[k].iterations, "%.0f");
            wt_cell(f, name, mn, "rounds", (double)w->method_rep[k].rounds, "%.0f");
            fprintf(f, "</tr>\n");
        }
        fprintf(f, "</table>\n<p><b>paper</b>: eq. (1) over the interior vertices, plus two "
                   "tangential rows per vertex, which make the system square (well-posed). "
                   "<b>paper-literal</b>: eq. (1) over all m + n vertices as printed, Fig. 5's LM, "
                   "planar re-triangulation; the boundary terms cannot vanish and it crushes "
                   "triangles. <b>area</b>: least area by L-BFGS, the objective of Chen et al. "
                   "[10], the paper's comparison; its F is the area. ERR is the paper's error "
                   "formula of III.%s, mean over the interior vertices; the paper published "
                   "%s (its method) and %s (Chen et al.) for ranges it does not give, so compare "
                   "the ranking, not the values.</p>\n</section>\n",
                helicoid ? "A" : "B", w->c->paper_ours, w->c->paper_chen);
        free(vals);
    }
    if (rings && wt_write_rings(f, rings) != 0) status = -1;
    if (wt_membrane_panel(f)) status = -1;
    if (wt_design_panel(f)) status = -1;
    if (wt_accuracy_panel(f)) status = -1;
    fprintf(f, "</body>\n</html>\n");
    return ferror(f) ? -1 : status;
}

#endif /* PLATEAU_DEMO_WALKTHROUGH_H */
