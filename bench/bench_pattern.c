/* bench_pattern.c - cutting patterns at scale: plateau_pattern_make on
 * films of about 10^5 vertices, wall and CPU time and peak resident
 * memory (each run in a child process, bench_common.h), with the panels,
 * the spacing tries and the strain, and the SVG and DXF writers' time.
 *   a saddle z = (x^2 - y^2) / 2 over [-1, 1]^2 (a hypar sail), parallel
 *     seams through its straight lines x - y = c, roll width 0.25;
 *   a spherical cap of polar angle 60 degrees, gores through its axis,
 *     roll width 0.2 (a dome);
 * Usage: bench_pattern [quick] (quick: about 10^4 vertices). */
#define _DEFAULT_SOURCE
#include "bench_common.h"
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"

#include <math.h>

typedef struct film {
    double *xyz;
    plateau_index *tri;
    size_t nv, nt;
} film;

/* A (k + 1) x (k + 1) grid over [-1, 1]^2 lifted to the saddle, or the
 * cap of polar angle 60 degrees in k rings of 4 k sectors round its pole. */
static film make_film(int kind, size_t k)
{
    film f;
    size_t i, j, t = 0;
    if (kind == 0) {
        f.nv = (k + 1) * (k + 1);
        f.nt = 2 * k * k;
    } else {
        f.nv = 1 + k * 4 * k;
        f.nt = 4 * k + 2 * (k - 1) * 4 * k;
    }
    f.xyz = (double *)malloc(3 * f.nv * sizeof(double));
    f.tri = (plateau_index *)malloc(3 * f.nt * sizeof(plateau_index));
    if (kind == 0) {
        for (i = 0; i <= k; i++)
            for (j = 0; j <= k; j++) {
                double x = -1.0 + 2.0 * (double)j / (double)k, y = -1.0 + 2.0 * (double)i / (double)k;
                double *p = f.xyz + 3 * (i * (k + 1) + j);
                p[0] = x;
                p[1] = y;
                p[2] = 0.5 * (x * x - y * y);
            }
        for (i = 0; i < k; i++)
            for (j = 0; j < k; j++) {
                plateau_index a = (plateau_index)(i * (k + 1) + j), b = a + 1, c = b + (plateau_index)(k + 1),
                              d = a + (plateau_index)(k + 1);
                plateau_index q[6];
                q[0] = a; q[1] = b; q[2] = c; q[3] = a; q[4] = c; q[5] = d;
                memcpy(f.tri + 6 * t++, q, sizeof q);
            }
        return f;
    }
    {
        size_t s = 4 * k;
        f.xyz[0] = 0.0;
        f.xyz[1] = 0.0;
        f.xyz[2] = 1.0;
        for (i = 1; i <= k; i++)
            for (j = 0; j < s; j++) {
                double ph = 1.0471975511965976 * (double)i / (double)k, th = 6.283185307179586 * (double)j / (double)s;
                double *p = f.xyz + 3 * (1 + (i - 1) * s + j);
                p[0] = sin(ph) * cos(th);
                p[1] = sin(ph) * sin(th);
                p[2] = cos(ph);
            }
        for (j = 0; j < s; j++) {
            f.tri[3 * t] = 0;
            f.tri[3 * t + 1] = (plateau_index)(1 + j);
            f.tri[3 * t + 2] = (plateau_index)(1 + (j + 1) % s);
            t++;
        }
        for (i = 1; i < k; i++)
            for (j = 0; j < s; j++) {
                plateau_index a = (plateau_index)(1 + (i - 1) * s + j), b = (plateau_index)(1 + (i - 1) * s + (j + 1) % s);
                plateau_index c = b + (plateau_index)s, d = a + (plateau_index)s;
                plateau_index q[6];
                q[0] = a; q[1] = d; q[2] = c; q[3] = a; q[4] = c; q[5] = b;
                memcpy(f.tri + 3 * t, q, sizeof q);
                t += 2;
            }
    }
    return f;
}

typedef struct job {
    int kind;
    size_t k;
} job;

typedef struct result {
    int rc;
    size_t nv, panels, seams;
    double wall, write_wall, max_strain, mean_strain, widest, seam_rel;
} result;

static void run(void *arg, void *out)
{
    const job *jb = (const job *)arg;
    result *r = (result *)out;
    film f = make_film(jb->kind, jb->k);
    plateau_pattern p;
    plateau_pattern_options o;
    plateau_error err;
    double t0;
    size_t i;
    memset(&o, 0, sizeof o);
    if (jb->kind == 0) {
        o.width = 0.25; /* planes through the rulings x - y = c: straight strips */
        o.direction[0] = 1.0;
        o.direction[1] = -1.0;
    } else {
        o.width = 0.2;
        o.seams = PLATEAU_SEAMS_AXIS;
        o.direction[2] = 1.0;
    }
    r->nv = f.nv;
    t0 = bench_wall_now();
    r->rc = plateau_pattern_make(f.xyz, f.nv, f.tri, f.nt, &o, NULL, &p, &err);
    r->wall = bench_wall_now() - t0;
    if (r->rc == PLATEAU_OK) {
        r->panels = p.num_panels;
        r->seams = p.num_seams;
        r->max_strain = p.max_strain;
        r->mean_strain = p.mean_strain;
        for (i = 0; i < p.num_panels; i++) r->widest = p.panels[i].width > r->widest ? p.panels[i].width : r->widest;
        for (i = 0; i < p.num_seams; i++) {
            double d = fabs(p.seams[i].lengths[0] - p.seams[i].lengths[1]) / p.seams[i].length_3d;
            r->seam_rel = d > r->seam_rel ? d : r->seam_rel;
        }
        t0 = bench_wall_now();
        plateau_pattern_write_svg("/dev/null", &p, 0.1, NULL);
        plateau_pattern_write_dxf("/dev/null", &p, 0.1, NULL);
        r->write_wall = bench_wall_now() - t0;
    } else {
        fprintf(stderr, "bench_pattern: %s\n", err.message);
    }
    plateau_pattern_free(&p);
    free(f.xyz);
    free(f.tri);
}

int main(int argc, char **argv)
{
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0, kind, fails = 0;
    static const char *const names[2] = {"hypar, parallel seams, W 0.25", "cap, gores, W 0.2"};
    printf("cutting patterns: plateau_pattern_make (each run a child process)\n");
    printf("%-32s %8s %7s %6s %9s %9s %9s %10s %9s %8s\n", "film", "vertices", "panels", "seams", "widest",
           "max strain", "mean", "seam sides", "time s", "peak MB");
    for (kind = 0; kind < 2; kind++) {
        job jb;
        result r;
        struct rusage ru;
        jb.kind = kind;
        jb.k = kind == 0 ? (quick ? 100 : 316) : (quick ? 50 : 158);
        memset(&r, 0, sizeof r);
        if (!bench_run_child(run, &jb, &r, sizeof r, &ru) || r.rc != PLATEAU_OK) {
            printf("%-32s failed\n", names[kind]);
            fails++;
            continue;
        }
        printf("%-32s %8lu %7lu %6lu %9.4f %9.3g %9.3g %10.3g %9.2f %8.1f\n", names[kind], (unsigned long)r.nv,
               (unsigned long)r.panels, (unsigned long)r.seams, r.widest, r.max_strain, r.mean_strain, r.seam_rel,
               r.wall, (double)ru.ru_maxrss / 1024.0);
        printf("%-32s writing the SVG and the DXF: %.2f s; CPU in all %.2f s\n", "", r.write_wall, bench_cpu_of(&ru));
    }
    return fails ? 1 : 0;
}
