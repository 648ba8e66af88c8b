/* test_walkthrough.c - the page make demo writes (out/walkthrough.html,
 * examples/walkthrough.h), rendered here and read back: every panel of both
 * cases is present with its picture and its paper reference; nothing in it
 * refers outside the file; and every number it shows (data-value) equals
 * the figure recomputed here from solves of our own (reports, progress
 * callback, meshes), shown rounded to the digits it prints.  The candidate
 * levels drawn are checked against the library's literal seeding rule.
 * The pictures are checked for what their captions say: each case's mesh
 * drawn along the view its rule picks, which shows most of the surface and
 * its bend (the helicoid's twist); the F charts' points inside their plot
 * boxes; the pressure cap in many tones, the cable film not dark and its
 * cables marked. */
#ifndef PLATEAU_TEST_LINKED /* else the suite links a shared implementation object */
#define PLATEAU_IMPLEMENTATION
#endif
#include "plateau.h"
#include "tests/harness.h"
#include "examples/surfaces.h"
#include "examples/walkthrough.h"

#define MAX_NUMS 256

typedef struct num_entry {
    char key[96];
    double value;
    char shown[64];
    int seen;
} num_entry;

static num_entry nums[MAX_NUMS];
static size_t num_count;

/* Every <span class="num" data-key=... data-value=...>shown</span>. */
static void parse_numbers(const char *html)
{
    const char *p = html;
    num_count = 0;
    while ((p = strstr(p, "data-key=\"")) != NULL && num_count < MAX_NUMS) {
        num_entry *e = &nums[num_count++];
        const char *q = p + 10, *v;
        size_t k = 0;
        while (*q && *q != '"' && k + 1 < sizeof e->key) e->key[k++] = *q++;
        e->key[k] = '\0';
        v = strstr(q, "data-value=\"");
        e->value = v ? strtod(v + 12, NULL) : NAN;
        q = v ? strchr(v, '>') : NULL;
        k = 0;
        if (q)
            for (q++; *q && *q != '<' && k + 1 < sizeof e->shown; q++) e->shown[k++] = *q;
        e->shown[k] = '\0';
        e->seen = 0;
        p = q ? q : p + 10;
    }
}

/* The text is the value rounded to the digits it shows: within half a unit
 * of its last digit (and a hair for the binary value). */
static int shown_matches(const char *shown, double value)
{
    const char *dot = strchr(shown, '.'), *e = strpbrk(shown, "eE");
    int frac = 0, ex = 0;
    double t = strtod(shown, NULL), unit;
    if (dot) {
        const char *q;
        for (q = dot + 1; *q >= '0' && *q <= '9'; q++) frac++;
    }
    if (e) ex = atoi(e + 1);
    unit = pow(10.0, (double)(ex - frac));
    return fabs(t - value) <= 0.5 * unit * (1 + 1e-9) + 1e-15 * fabs(value);
}

/* The number of the page for key: present once, equal to want, shown
 * rounded from it. */
static void check_num(const char *case_name, const char *key, double want)
{
    char full[128];
    size_t i, found = 0;
    sprintf(full, "%s.%s", case_name, key);
    for (i = 0; i < num_count; i++) {
        if (strcmp(nums[i].key, full) != 0) continue;
        found++;
        nums[i].seen++;
        if (!CHECK_MSG(nums[i].value == want, full))
            fprintf(stderr, "  %s: page %.17g, recomputed %.17g\n", full, nums[i].value, want);
        if (!CHECK_MSG(shown_matches(nums[i].shown, nums[i].value), full))
            fprintf(stderr, "  %s: shows \"%s\" for %.17g\n", full, nums[i].shown, nums[i].value);
    }
    if (!CHECK_MSG(found == 1, full)) fprintf(stderr, "  %s: %lu times on the page\n", full, (unsigned long)found);
}

/* The text of the element with id, up to its closing tag name. */
static const char *find_id(const char *html, const char *id)
{
    char key[160];
    snprintf(key, sizeof key, "id=\"%s\"", id);
    return strstr(html, key);
}

typedef struct progress_log {
    int round[WT_MAX_RECORDS];
    double f[WT_MAX_RECORDS];
    size_t count;
} progress_log;

static int log_progress(int round, int iteration, double f, void *user)
{
    progress_log *l = (progress_log *)user;
    (void)iteration;
    if (l->count < WT_MAX_RECORDS) {
        l->round[l->count] = round;
        l->f[l->count] = f;
        l->count++;
    }
    return 0;
}

/* ------------------------------------------------ what the pictures show */
/* The part of html from the element with id to the end of that element's
 * block: the next "</div>" (a cell) or "</section>" (a panel), whichever
 * the caller names; NULL when absent.  *len gets its length. */
static const char *block(const char *html, const char *id, const char *end_tag, size_t *len)
{
    const char *p = find_id(html, id), *e;
    if (!p) return NULL;
    e = strstr(p, end_tag);
    if (!e) return NULL;
    *len = (size_t)(e - p);
    return p;
}

/* The picture wt_inline_svg writes for these arrays, as a string (free it). */
static char *render(const double *pos, size_t nv, const plateau_index *tri, size_t nt,
                    const plateau_svg_colors *col)
{
    FILE *f = tmpfile();
    long size;
    char *buf = NULL;
    if (!f) return NULL;
    if (wt_inline_svg(f, pos, nv, tri, nt, col) == 0 && (size = ftell(f)) > 0) {
        rewind(f);
        buf = (char *)malloc((size_t)size + 1);
        if (buf && fread(buf, 1, (size_t)size, f) == (size_t)size) buf[size] = '\0';
        else {
            free(buf);
            buf = NULL;
        }
    }
    fclose(f);
    return buf;
}

/* 1 when the picture svg (a string) is inside html's element with id, up
 * to end_tag: the page drew exactly that picture there. */
static int drawn_in(const char *html, const char *id, const char *end_tag, const char *svg)
{
    size_t len;
    const char *p = block(html, id, end_tag, &len), *q;
    if (!p || !svg) return 0;
    q = strstr(p, svg);
    return q != NULL && q + strlen(svg) <= p + len;
}

/* The fills of the <polygon>s in a block (the mesh's triangles or cells; the
 * legend's bar is <rect>s): how many distinct colours, and the smallest and
 * largest luminance (0.2126 R + 0.7152 G + 0.0722 B, on 0..1). */
static void fills(const char *p, size_t len, size_t *distinct, double *lum_lo, double *lum_hi)
{
    static unsigned seen[4096];
    size_t ns = 0, k;
    const char *q = p, *end = p + len;
    *lum_lo = 1;
    *lum_hi = 0;
    while ((q = strstr(q, "<polygon ")) != NULL && q < end) {
        const char *fl = strstr(q, "fill=\"#"), *gt = strchr(q, '>');
        unsigned rgb;
        if (fl && gt && fl < gt && sscanf(fl + 7, "%6x", &rgb) == 1) {
            double lum = (0.2126 * (rgb >> 16) + 0.7152 * ((rgb >> 8) & 255) + 0.0722 * (rgb & 255)) / 255;
            if (lum < *lum_lo) *lum_lo = lum;
            if (lum > *lum_hi) *lum_hi = lum;
            for (k = 0; k < ns && seen[k] != rgb; k++) continue;
            if (k == ns && ns < sizeof seen / sizeof seen[0]) seen[ns++] = rgb;
        }
        q++;
    }
    *distinct = ns;
}

/* How many times s occurs in the block p (len characters). */
static size_t count_in(const char *p, size_t len, const char *s)
{
    size_t n = 0;
    const char *q = p, *end = p + len;
    while ((q = strstr(q, s)) != NULL && q < end) {
        n++;
        q++;
    }
    return n;
}

/* The F chart of a case: every point drawn (the polylines' vertices and
 * the dots) lies inside the plot box, clear of its border by 2 % of its
 * side, there is one dot per iteration and one for the start, and the
 * points fill most of the box each way (the axes come from the data). */
static void check_fchart(const char *html, const wt_case *w)
{
    char id[64];
    size_t len, dots = 0, points = 0;
    const char *p, *q, *end;
    double bx = 0, by = 0, bw = 0, bh = 0, xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
    int inside = 1;
    sprintf(id, "%s-fchart", w->c->name);
    p = block(html, id, "</section>", &len);
    CHECK_MSG(p != NULL, id);
    if (!p) return;
    end = p + len;
    q = strstr(p, "<rect "); /* the first: the plot box */
    q = q ? strstr(q, " x=\"") : NULL;
    CHECK_MSG(q != NULL && q < end &&
                  sscanf(q, " x=\"%lf\" y=\"%lf\" width=\"%lf\" height=\"%lf\"", &bx, &by, &bw, &bh) == 4 &&
                  bw > 0 && bh > 0,
              "the F chart's plot box");
    for (q = p; (q = strstr(q, "<polyline ")) != NULL && q < end; q++) {
        const char *pts = strstr(q, "points=\""), *stop;
        double x, y;
        int used;
        if (!pts) break;
        pts += 8;
        stop = strchr(pts, '"');
        while (pts < stop && sscanf(pts, "%lf,%lf%n", &x, &y, &used) == 2) {
            points++;
            if (x < bx + 0.02 * bw || x > bx + 0.98 * bw || y < by + 0.02 * bh || y > by + 0.98 * bh) inside = 0;
            if (x < xlo) xlo = x;
            if (x > xhi) xhi = x;
            if (y < ylo) ylo = y;
            if (y > yhi) yhi = y;
            pts += used;
            while (*pts == ' ') pts++;
        }
    }
    for (q = p; (q = strstr(q, "<circle cx=\"")) != NULL && q < end; q++) {
        double x, y;
        if (sscanf(q, "<circle cx=\"%lf\" cy=\"%lf\"", &x, &y) != 2) continue;
        dots++;
        if (x < bx + 0.02 * bw || x > bx + 0.98 * bw || y < by + 0.02 * bh || y > by + 0.98 * bh) inside = 0;
    }
    if (!CHECK_MSG(inside, "every point of the F chart inside its plot box, clear of the border"))
        fprintf(stderr, "  %s: box x %g..%g y %g..%g, points x %g..%g y %g..%g\n", id, bx, bx + bw, by,
                by + bh, xlo, xhi, ylo, yhi);
    CHECK_EQ_INT(points, w->num_records + 1);
    CHECK_EQ_INT(dots, w->num_records + 1);
    CHECK_MSG(xhi - xlo >= 0.8 * bw && yhi - ylo >= 0.8 * bh, "the F chart's axes fitted to its points");
}

/* How a case's pictures are seen: the view is the rule's (wt_view) on the
 * mesh of method paper, and the page draws that mesh along it; seen so,
 * most of the surface faces the eye (projected area over area at least
 * 0.6, where the old fixed view of the helicoid had 0.38, its middle
 * edge-on), no part is nearly edge-on (the 10 % point of |n . view| at
 * least 0.25) and the facing varies across it (the 90 % point at least
 * 0.4 above the 10 %: the helicoid's twist seen; face-on its rulings all
 * looked alike, 0.28). */
static void check_view(const char *html, const demo_case *c, const plateau_mesh *paper)
{
    double view[3], facing, low, high, *vals;
    plateau_svg_colors col;
    char id[64], *svg;
    wt_view(paper->positions, paper->triangles, paper->num_triangles, view);
    check_num(c->name, "view_x", view[0]);
    check_num(c->name, "view_y", view[1]);
    check_num(c->name, "view_z", view[2]);
    facing = wt_facing(paper->positions, paper->triangles, paper->num_triangles, view, &low, &high);
    check_num(c->name, "view_facing", 100 * facing);
    if (!CHECK_MSG(facing >= 0.6 && low >= 0.25 && high - low >= 0.4, c->name))
        fprintf(stderr, "  %s: facing %.3f, 10 %% point %.2f, 90 %% point %.2f\n", c->name, facing, low, high);
    /* the page's picture of method paper (triangles by their smallest
     * angle) is this mesh along this view */
    vals = (double *)malloc((paper->num_triangles + 1) * sizeof(double));
    CHECK(vals != NULL);
    if (!vals) return;
    wt_angles(paper->positions, paper->triangles, paper->num_triangles, vals);
    memset(&col, 0, sizeof col);
    col.values = vals;
    col.num_values = paper->num_triangles;
    col.range_min = 0;
    col.range_max = 60;
    col.title = "smallest angle, deg";
    col.view_dir = view;
    sprintf(id, "%s-method-paper", c->name);
    svg = render(paper->positions, paper->num_vertices, paper->triangles, paper->num_triangles, &col);
    CHECK_MSG(drawn_in(html, id, "</div>", svg), "the page draws method paper's mesh along the view");
    free(svg);
    free(vals);
}

/* Recomputes every figure of one case's panels and checks the page's. */
static void check_case(const char *html, const wt_case *w)
{
    const demo_case *c = w->c;
    const char *name = c->name;
    double boundary[3 * DEMO_MAX_BOUNDARY];
    size_t m = demo_boundary(c, boundary), i;
    plateau_options o;
    plateau_report full, rep;
    plateau_mesh mesh, prev, start;
    plateau_error err;
    static progress_log log;
    char id[128], key[64];
    int k, rounds;
    static const char *const panels[] = { "boundary", "domain", "cdt", "start", "fchart",
                                          "rounds", "methods" };
    /* the panels, each with a picture and the paper's step */
    for (i = 0; i < sizeof panels / sizeof panels[0]; i++) {
        const char *p, *end;
        sprintf(id, "%s-%s", name, panels[i]);
        p = find_id(html, id);
        CHECK_MSG(p != NULL, id);
        if (!p) continue;
        end = strstr(p, "</section>");
        CHECK_MSG(end != NULL, id);
        if (!end) continue;
        {
            const char *svg = strstr(p, "<svg"), *ref = strstr(p, "II.");
            const char *ref3 = strstr(p, "III.");
            CHECK_MSG(svg != NULL && svg < end, id);
            CHECK_MSG((ref != NULL && ref < end) || (ref3 != NULL && ref3 < end), id);
        }
    }
    /* the whole solve by method paper, with the F of every iteration */
    memset(&mesh, 0, sizeof mesh);
    memset(&log, 0, sizeof log);
    o = wt_options(c, PLATEAU_METHOD_PAPER, 0);
    o.progress = log_progress;
    o.progress_user = &log;
    CHECK_EQ_INT(plateau_solve(boundary, m, &o, &mesh, &full, &err), PLATEAU_OK);
    plateau_mesh_free(&mesh);
    rounds = (int)full.rounds;
    CHECK(rounds >= 1 && rounds <= WT_MAX_ROUNDS);
    memset(&rep, 0, sizeof rep);
    check_num(name, "m", (double)m);
    check_num(name, "n", (double)full.seeded_points);
    check_num(name, "chosen", (double)full.seeded_points);
    check_num(name, "domain_min_angle", full.domain_min_angle_deg);
    check_num(name, "start_min_angle", full.initial_min_angle_deg);
    check_num(name, "start_f", full.f_initial);
    check_num(name, "rounds", (double)full.rounds);
    check_num(name, "iterations", (double)full.iterations);
    check_num(name, "flips", (double)full.flips);
    /* the candidate levels drawn: the library's literal rule takes the
     * first candidates in generation order, level by level, so asked for
     * as many as the page draws in levels 0..K it returns those points */
    {
        size_t want = w->candidates_upto_k, got = 0, same = 1;
        double uv[2 * DEMO_MAX_BOUNDARY], *xyz_out, *uv_out;
        plateau_domain_kind kind;
        xyz_out = (double *)malloc(3 * want * sizeof(double));
        uv_out = (double *)malloc(2 * want * sizeof(double));
        CHECK(xyz_out && uv_out);
        CHECK_EQ_INT(plateau_boundary_domain(boundary, m, 0, NULL, uv, &kind, &err), PLATEAU_OK);
        if (xyz_out && uv_out &&
            plateau_seed_points_rule(boundary, uv, m, want, DEMO_SEED, PLATEAU_SEED_LITERAL, NULL,
                                     xyz_out, uv_out, &got, &err) == PLATEAU_OK) {
            CHECK_EQ_INT(got, want);
            for (i = 0; i < got && i < want; i++)
                if (fabs(uv_out[2 * i] - w->candidates[2 * i]) > 1e-12 ||
                    fabs(uv_out[2 * i + 1] - w->candidates[2 * i + 1]) > 1e-12)
                    same = 0;
            CHECK_MSG(same, "the candidates drawn are the library's, in its order");
        } else {
            CHECK_MSG(0, "plateau_seed_points_rule");
        }
        free(xyz_out);
        free(uv_out);
        CHECK(want >= full.seeded_points);
        check_num(name, "candidates", (double)want);
        check_num(name, "level", (double)w->chosen_level);
        /* K is the first level by which the levels hold n */
        CHECK(w->chosen_level == 0 || w->level_start[w->chosen_level] < full.seeded_points);
    }
    /* the start */
    memset(&start, 0, sizeof start);
    CHECK_EQ_INT(demo_initial_mesh(c, 0, &start, &err), PLATEAU_OK);
    {
        double hmax = 0;
        for (i = m; i < start.num_vertices; i++) {
            double h = fabs(plateau_vertex_mean_curvature(&start, i));
            if (h > hmax) hmax = h;
        }
        check_num(name, "start_hmax", hmax);
        check_num(name, "start_area", plateau_mesh_area(&start));
        /* the legend of the start picture carries the same maximum */
        {
            const char *p;
            char cid[64];
            sprintf(cid, "%s-start", name);
            p = find_id(html, cid);
            p = p ? strstr(p, "plateau-legend-max\" data-value=\"") : NULL;
            CHECK(p != NULL && strtod(p + 32, NULL) == hmax);
        }
    }
    /* round by round: the solve stopped at round k */
    memset(&prev, 0, sizeof prev);
    {
        size_t flips_total = 0;
        for (k = 1; k <= rounds; k++) {
            size_t iters = 0, last = 0, flips;
            memset(&mesh, 0, sizeof mesh);
            o = wt_options(c, PLATEAU_METHOD_PAPER, k);
            CHECK_EQ_INT(plateau_solve(boundary, m, &o, &mesh, &rep, &err), PLATEAU_OK);
            if (k == 1) {
                /* the start drawn is plateau_solve's: same edges */
                check_num(name, "cdt_triangles", (double)mesh.num_triangles);
                CHECK_EQ_INT(wt_new_edges(&start, &mesh, NULL, 0), 0);
                CHECK_EQ_INT(wt_new_edges(&mesh, &start, NULL, 0), 0);
            } else {
                flips = wt_new_edges(&prev, &mesh, NULL, 0);
                flips_total += flips;
                sprintf(key, "round%d.flips", k - 1);
                check_num(name, key, (double)flips);
            }
            for (i = 0; i < log.count; i++)
                if (log.round[i] == k) {
                    iters++;
                    last = i;
                }
            sprintf(key, "round%d.iterations", k);
            check_num(name, key, (double)iters);
            sprintf(key, "round%d.f", k);
            check_num(name, key, full.f_rounds[k - 1]);
            /* the callback's last F of round k, in the report's units, is
             * the report's F of round k, to the bit */
            CHECK(iters > 0 && log.f[last] == full.f_rounds[k - 1]);
            CHECK(rep.f_final == full.f_rounds[k - 1]);              /* round k, any max_rounds */
            sprintf(key, "round%d.area", k);
            check_num(name, key, rep.area);
            sprintf(key, "round%d.min_angle", k);
            check_num(name, key, rep.min_angle_deg);
            sprintf(id, "%s-round-%d", name, k);
            CHECK_MSG(find_id(html, id) != NULL, id);
            plateau_mesh_free(&prev);
            prev = mesh;
        }
        sprintf(key, "round%d.flips", rounds);
        check_num(name, key, 0.0);
        CHECK_EQ_INT(flips_total, full.flips);
        CHECK_NEAR(rep.area, full.area, 0.0); /* the last round is the whole solve */
        sprintf(id, "%s-round-%d", name, rounds + 1);
        CHECK(find_id(html, id) == NULL);
    }
    plateau_mesh_free(&prev);
    plateau_mesh_free(&start);
    /* the three methods */
    for (k = 0; k < 3; k++) {
        const char *mn = plateau_method_name(demo_methods[k]);
        demo_row row;
        memset(&mesh, 0, sizeof mesh);
        o = wt_options(c, demo_methods[k], 0);
        CHECK_EQ_INT(plateau_solve(boundary, m, &o, &mesh, &rep, &err), PLATEAU_OK);
        memset(&row, 0, sizeof row);
        demo_measure(c, &mesh, &row);
        sprintf(key, "%s.area", mn);
        check_num(name, key, rep.area);
        sprintf(key, "%s.f", mn);
        check_num(name, key, rep.f_final);
        sprintf(key, "%s.min_angle", mn);
        check_num(name, key, rep.min_angle_deg);
        sprintf(key, "%s.err", mn);
        check_num(name, key, row.err_mean);
        sprintf(key, "%s.h_mean", mn);
        check_num(name, key, row.h_mean);
        sprintf(key, "%s.iterations", mn);
        check_num(name, key, (double)rep.iterations);
        sprintf(key, "%s.rounds", mn);
        check_num(name, key, (double)rep.rounds);
        sprintf(id, "%s-method-%s", name, mn);
        CHECK_MSG(find_id(html, id) != NULL, id);
        sprintf(id, "%s-curvature-%s", name, mn);
        CHECK_MSG(find_id(html, id) != NULL, id);
        if (k == 0) check_view(html, c, &mesh);
        plateau_mesh_free(&mesh);
    }
    check_fchart(html, w);
}

/* The rings' panel: every figure recomputed from solves of our own (the
 * same options), the stable film a minimum that is not the least area,
 * the unstable one a saddle of index 1, the discs the least area. */
static void check_rings(const char *html)
{
    double xyz[6 * WT_RINGS_M], au = demo_catenoid_neck_branch(WT_RINGS_H, 1);
    size_t counts[2] = {WT_RINGS_M, WT_RINGS_M};
    static const char *const names[3] = {"stable", "unstable", "discs"};
    plateau_options o;
    plateau_mesh mesh[3];
    plateau_report rep;
    plateau_stability st;
    char key[64];
    int k, conv = 0;
    CHECK(find_id(html, "rings-films") != NULL);
    memset(mesh, 0, sizeof mesh);
    demo_rings(xyz, WT_RINGS_M, WT_RINGS_H);
    for (k = 0; k < 3; k += 2) {
        o = wt_rings_options(k == 2);
        CHECK_EQ_INT(plateau_solve_loops(xyz, counts, 2, &o, &mesh[k], &rep, NULL), PLATEAU_OK);
        CHECK_EQ_INT(rep.discs_returned, k == 2);
        CHECK(rep.film_not_least);
    }
    CHECK_EQ_INT(demo_catenoid_mesh(WT_RINGS_H, 1.25 * au, WT_RINGS_M,
                                    2 * (int)(WT_RINGS_M * WT_RINGS_H / (4.0 * M_PI)) + 3, &mesh[1]),
                 PLATEAU_OK);
    CHECK_EQ_INT(plateau_mesh_critical_point(&mesh[1], 1, 0, NULL, &conv, NULL, NULL), PLATEAU_OK);
    CHECK(conv);
    for (k = 0; k < 3; k++) {
        /* with the mode, as the page asks for it: with modes the Lanczos
           run converges to a residual test, without them to an error
           bound, and the two differ in the last digits */
        double *mode = (double *)malloc(mesh[k].num_vertices * sizeof(double));
        CHECK_EQ_INT(plateau_mesh_stability(&mesh[k], 1, &st, mode, NULL), PLATEAU_OK);
        free(mode);
        CHECK_EQ_INT(st.index, k == 1);
        sprintf(key, "%s.area", names[k]);
        check_num("rings", key, plateau_mesh_area(&mesh[k]));
        sprintf(key, "%s.index", names[k]);
        check_num("rings", key, (double)st.index);
        sprintf(key, "%s.lowest", names[k]);
        check_num("rings", key, st.lowest_eigenvalues[0]);
        plateau_mesh_free(&mesh[k]);
    }
    check_num("rings", "stable.exact", demo_catenoid_area(WT_RINGS_H));
    check_num("rings", "unstable.exact", demo_catenoid_area_of(WT_RINGS_H, au));
    check_num("rings", "discs.exact", 2.0 * M_PI);
}

/* A membrane's picture (which 0 the cap, 1 the cable film): the page draws
 * this mesh with wt_membrane_colors.  The cap must read as a dome, not a
 * flat disc of one tone (coloured by H, nearly the same everywhere, it
 * had 2 fills): at least 16 distinct fills spanning half the luminance
 * scale.  The cable film, flat, is seen face-on, with no dark fill (it was
 * an all-dark silhouette at the bottom of an H scale) and its boundary's
 * edges, the cables, marked: each drawn twice (black under yellow). */
static void check_membrane_picture(const char *html, int which, const plateau_mesh *mesh,
                                   const plateau_report *rep)
{
    const char *id = which ? "membrane-cables" : "membrane-cap", *p;
    size_t nb = wt_membrane_boundary(which, rep), len, distinct;
    double *vals = (double *)malloc((mesh->num_vertices + 1) * sizeof(double)), view[3], lo, hi;
    plateau_index *marks = (plateau_index *)malloc(2 * nb * sizeof(plateau_index));
    plateau_svg_colors col;
    char *svg;
    CHECK(vals && marks);
    if (!vals || !marks) {
        free(vals);
        free(marks);
        return;
    }
    wt_membrane_colors(which, mesh, rep, vals, marks, view, &col);
    svg = render(mesh->positions, mesh->num_vertices, mesh->triangles, mesh->num_triangles, &col);
    CHECK_MSG(drawn_in(html, id, "</div>", svg), id);
    free(svg);
    p = block(html, id, "</div>", &len);
    CHECK_MSG(p != NULL, id);
    if (p) {
        fills(p, len, &distinct, &lo, &hi);
        if (which == 0) {
            if (!CHECK_MSG(distinct >= 16 && hi - lo >= 0.5, "the cap's picture shows its height"))
                fprintf(stderr, "  cap: %lu fills, luminance %.2f .. %.2f\n", (unsigned long)distinct, lo, hi);
        } else {
            if (!CHECK_MSG(distinct >= 1 && lo >= 0.25, "the cable film's picture is not a dark silhouette"))
                fprintf(stderr, "  cables: %lu fills, luminance %.2f .. %.2f\n", (unsigned long)distinct, lo, hi);
            CHECK_EQ_INT(count_in(p, len, "<line "), 2 * nb);
            CHECK(fabs(fabs(view[2]) - 1.0) < 1e-12); /* face-on: the film lies in z = 0 */
        }
    }
    free(vals);
    free(marks);
}

/* The error estimate's panel: the same solves; effectivity within
 * [0.25, 4], the error falling with n, the shares summing to the estimate
 * and largest at the neck. */
static void check_accuracy_panel(const char *html)
{
    wt_accuracy a;
    plateau_error err;
    char key[64];
    double neck = 0.0, ring = 0.0, neck_area = 0.0, ring_area = 0.0;
    size_t t;
    int k;
    CHECK(find_id(html, "accuracy-panel") != NULL && find_id(html, "accuracy-graded") != NULL);
    CHECK_EQ_INT(wt_accuracy_collect(&a, &err), 0);
    check_num("accuracy", "exact", a.exact);
    for (k = 0; k < WT_ACC_RUNS; k++) {
        double e = a.area[k] / a.exact - 1.0;
        printf("  accuracy panel: n %lu, true %.3e, estimate %.3e, effectivity %.2f\n",
               (unsigned long)a.interior[k], e, a.estimate[k], e / a.estimate[k]);
        sprintf(key, "run%d.interior", k);
        check_num("accuracy", key, (double)a.interior[k]);
        sprintf(key, "run%d.area", k);
        check_num("accuracy", key, a.area[k]);
        sprintf(key, "run%d.true", k);
        check_num("accuracy", key, e);
        sprintf(key, "run%d.estimate", k);
        check_num("accuracy", key, a.estimate[k]);
        sprintf(key, "run%d.effectivity", k);
        check_num("accuracy", key, e / a.estimate[k]);
        CHECK(e / a.estimate[k] >= 0.25 && e / a.estimate[k] <= 4.0);
        CHECK(k == 0 || (e < a.area[k - 1] / a.exact - 1.0 && a.estimate[k] < a.estimate[k - 1]));
    }
    check_num("accuracy", "indicator_sum", a.indicator_sum);
    CHECK(fabs(a.indicator_sum / a.estimate[0] - 1.0) < 0.05);
    for (t = 0; t < a.graded.num_triangles; t++) { /* share per area: the neck's half against the rest */
        const plateau_index *tr = a.graded.triangles + 3 * t;
        double z = (a.graded.positions[3 * tr[0] + 2] + a.graded.positions[3 * tr[1] + 2] +
                    a.graded.positions[3 * tr[2] + 2]) / 3.0;
        double ta = plateau_triangle_area(&a.graded, t);
        if (fabs(z) < 0.25 * WT_ACC_H) neck += a.indicator[t], neck_area += ta;
        else ring += a.indicator[t], ring_area += ta;
    }
    printf("  indicator per area: neck %.3e, near the rings %.3e\n", neck / neck_area, ring / ring_area);
    CHECK(neck / neck_area > ring / ring_area);
    wt_accuracy_free(&a);
}

static void test_page(void)
{
    static wt_case cases[2];
    static wt_rings rings;
    const char *names[2] = { "helicoid", "catenoid" };
    char msg[256], *html = NULL;
    FILE *f;
    long size;
    size_t i;
    int k;
    for (k = 0; k < 2; k++) {
        int ok = wt_collect(demo_find(names[k]), &cases[k], msg) == 0;
        if (!CHECK_MSG(ok, names[k])) fprintf(stderr, "  %s\n", msg);
    }
    {
        int ok = wt_collect_rings(&rings, msg) == 0;
        if (!CHECK_MSG(ok, "rings")) fprintf(stderr, "  %s\n", msg);
    }
    f = tmpfile();
    CHECK(f != NULL);
    if (!f) return;
    CHECK_EQ_INT(wt_write_html(f, cases, 2, &rings), 0);
    size = ftell(f);
    rewind(f);
    html = (char *)malloc((size_t)size + 1);
    CHECK(html && fread(html, 1, (size_t)size, f) == (size_t)size);
    fclose(f);
    if (!html) return;
    html[size] = '\0';
    /* one self-contained document */
    CHECK(strncmp(html, "<!DOCTYPE html>", 15) == 0);
    CHECK(size > 8 && strcmp(html + size - 8, "</html>\n") == 0);
    CHECK(strstr(html, "http:") == NULL);
    CHECK(strstr(html, "https:") == NULL);
    CHECK(strstr(html, "<script") == NULL);
    CHECK(strstr(html, "<link") == NULL);
    CHECK(strstr(html, "<img") == NULL);
    CHECK(strstr(html, "@import") == NULL);
    CHECK(strstr(html, "url(") == NULL);
    CHECK(strstr(html, "src=") == NULL);
    CHECK(strstr(html, "href=") == NULL);
    CHECK(strstr(html, "xlink") == NULL);
    parse_numbers(html);
    CHECK(num_count > 0 && num_count < MAX_NUMS);
    for (k = 0; k < 2; k++)
        if (cases[k].c) check_case(html, &cases[k]);
    check_rings(html);
    {
        /* the membranes' panel: the same solves, the same exact figures */
        double xyz[3 * 48], ex[5];
        plateau_options o;
        plateau_mesh mesh;
        plateau_report rep;
        plateau_error err;
        size_t m;
        CHECK(find_id(html, "membrane-panel") != NULL);
        wt_membrane_exact(&ex[0], &ex[1], &ex[2], &ex[3], &ex[4]);
        check_num("membrane", "cap.area_exact", ex[0]);
        check_num("membrane", "cap.volume_exact", ex[1]);
        check_num("membrane", "sail.sag_exact", ex[2]);
        check_num("membrane", "sail.length_exact", ex[3]);
        check_num("membrane", "sail.area_exact", ex[4]);
        wt_membrane_options(0, xyz, &m, &o);
        CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_OK);
        check_num("membrane", "cap.area", rep.area);
        check_num("membrane", "cap.volume", rep.volume);
        CHECK(fabs(rep.area / ex[0] - 1.0) < 0.01 && fabs(rep.volume / ex[1] - 1.0) < 0.01);
        {
            double hmin, hmax;
            wt_membrane_h(0, &mesh, &rep, &hmin, &hmax);
            check_num("membrane", "cap.h_min", hmin);
            check_num("membrane", "cap.h_max", hmax);
            CHECK(fabs(hmin - 1.0) < 0.01 && fabs(hmax - 1.0) < 0.01); /* H_i = p */
        }
        check_membrane_picture(html, 0, &mesh, &rep);
        plateau_mesh_free(&mesh);
        wt_membrane_options(1, xyz, &m, &o);
        CHECK_EQ_INT(plateau_solve(xyz, m, &o, &mesh, &rep, &err), PLATEAU_OK);
        check_num("membrane", "sail.area", rep.area);
        check_num("membrane", "sail.sag", rep.cable[0].sag);
        check_num("membrane", "sail.length", rep.cable[0].length);
        CHECK(fabs(rep.cable[0].sag / ex[2] - 1.0) < 0.02);
        {
            double hmin, hmax;
            wt_membrane_h(1, &mesh, &rep, &hmin, &hmax);
            check_num("membrane", "sail.h_abs_max", fabs(hmin) > fabs(hmax) ? fabs(hmin) : fabs(hmax));
            CHECK(fabs(hmin) < 1e-6 && fabs(hmax) < 1e-6); /* flat */
        }
        check_membrane_picture(html, 1, &mesh, &rep);
        plateau_mesh_free(&mesh);
    }
    {
        /* the design panel: the same solves; strain small, seams' sides
         * equal, every panel within the roll, the support within the
         * estimate, the half catenoid near the exact one */
        wt_design d;
        plateau_error err;
        char key[64];
        CHECK(find_id(html, "design-panel") != NULL && find_id(html, "design-flat") != NULL);
        CHECK_EQ_INT(wt_design_collect(&d, &err), 0);
        CHECK(d.pat.num_panels >= 4);
        for (i = 0; i < d.pat.num_panels; i++) {
            const plateau_pattern_panel *pp = &d.pat.panels[i];
            sprintf(key, "panel%lu.area_3d", (unsigned long)i);
            check_num("design", key, pp->area_3d);
            sprintf(key, "panel%lu.area_flat", (unsigned long)i);
            check_num("design", key, pp->area_flat);
            sprintf(key, "panel%lu.max_strain", (unsigned long)i);
            check_num("design", key, pp->max_strain);
            sprintf(key, "panel%lu.width", (unsigned long)i);
            check_num("design", key, pp->width);
            CHECK(pp->max_strain < 0.15 && fabs(pp->area_flat / pp->area_3d - 1.0) < 0.01);
            CHECK(pp->width <= 1.5);
        }
        check_num("design", "sail.area", d.sail_area);
        check_num("design", "seam_mismatch", 100 * d.seam_mismatch);
        CHECK(d.seam_mismatch < 0.02);
        check_num("design", "support.area", d.supported_area);
        check_num("design", "support.free_area", d.free_area);
        check_num("design", "support.difference", fabs(d.supported_area - d.free_area) / d.free_area);
        check_num("design", "support.estimate", d.support_estimate);
        CHECK(d.support_estimate > 0.0 && fabs(d.supported_area - d.free_area) <= d.support_estimate * d.free_area);
        check_num("design", "slide.area", d.half_area);
        check_num("design", "slide.exact", d.half_exact);
        check_num("design", "slide.error", fabs(d.half_area - d.half_exact) / d.half_exact);
        CHECK(fabs(2.0 * d.half_exact - 5.991797) < 5e-7);
        CHECK(fabs(d.half_area - d.half_exact) / d.half_exact < 0.01);
        plateau_pattern_free(&d.pat);
    }
    check_accuracy_panel(html);
    /* the panels after the cases, numbered in order: the rings', the membranes', the design's */
    CHECK(strstr(html, "<h3>8. Three films") != NULL && strstr(html, "<h3>9. A film with a pressure") != NULL &&
          strstr(html, "<h3>8. Three films") < strstr(html, "<h3>9. A film with a pressure"));
    CHECK(strstr(html, "<h3>10. Membrane design") != NULL &&
          strstr(html, "<h3>9. A film with a pressure") < strstr(html, "<h3>10. Membrane design"));
    CHECK(strstr(html, "<h3>11. The error estimate") != NULL &&
          strstr(html, "<h3>10. Membrane design") < strstr(html, "<h3>11. The error estimate"));
    /* every number on the page was recomputed above */
    for (i = 0; i < num_count; i++)
        if (!CHECK_MSG(nums[i].seen == 1, nums[i].key)) fprintf(stderr, "  unchecked: %s\n", nums[i].key);
    free(html);
    for (k = 0; k < 2; k++) wt_free(&cases[k]);
    wt_rings_free(&rings);
}

int main(void)
{
    RUN(test_page);
    return harness_report("test_walkthrough");
}
