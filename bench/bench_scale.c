/* bench_scale.c - method paper at scale, dense LM vs sparse dog leg (built
 * by `make bench`).
 *
 * The helicoid of examples/surfaces.h (b = 1.9, 28 boundary vertices) on
 * the wider range u in [-1.5, 1.5], v in [-pi/2, pi/2], quality seeding
 * with refine_boundary, n = 1000, 3000 and 10^4 interior points asked for.
 * Each run is a child process (fork), so that its peak resident memory
 * (getrusage ru_maxrss) is its own; wall (CLOCK_MONOTONIC) and CPU
 * (clock) time of plateau_solve, the median of up to 3 runs; the dense LM
 * only where it is feasible (n = 1000: its J^T J alone is 72 n^2 bytes).
 * Method paper starts, on a circle domain, from the result of method area
 * (paper_presolve 0, an L-BFGS solve that dominates the time at this
 * size); the second group of rows asks for no presolve (paper_presolve 1),
 * timing the square solves alone.
 * Arguments: none, "quick" (one run per row, no dense row) or "full" (also
 * the dense LM without the presolve: 195 s at n = 1000).
 * Measured (2-core x86-64 shared, load about 3, gcc -O3): n = 1000 dense
 * 94 s wall and 185 MB, sparse 1.7 s and 7.3 MB, the same area
 * 19.40027085; n = 10^4 sparse 23.7 s (of which the area presolve's 9515
 * L-BFGS steps most) and 74 MB; without the presolve 4.75 s and 82 MB.
 */
#define _POSIX_C_SOURCE 200809L
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"
#include "examples/surfaces.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct scale_row {
    int rc;
    double wall, cpu, area, f_final;
    long maxrss_kb;
    size_t interior;
    int rounds, iterations, evaluations, lm_stop, linear_solver, presolve_iterations;
    unsigned defects;
} scale_row;

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* one solve, in this process */
static void solve_once(size_t n, int linear_solver, int presolve, scale_row *row)
{
    demo_case c = *demo_find("helicoid");
    double polygon[3 * DEMO_MAX_BOUNDARY], w0;
    size_t m;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    struct rusage ru;
    clock_t c0;
    c.u0 = -1.5;
    c.u1 = 1.5;
    c.v0 = -M_PI / 2;
    c.v1 = M_PI / 2;
    m = demo_boundary(&c, polygon);
    memset(&o, 0, sizeof o);
    memset(&rep, 0, sizeof rep);
    o.method = PLATEAU_METHOD_PAPER;
    o.interior_points = n;
    o.seed = DEMO_SEED;
    o.seeding = PLATEAU_SEEDING_QUALITY;
    o.refine_boundary = 1;
    o.linear_solver = linear_solver;
    o.paper_presolve = presolve;
    w0 = wall_now();
    c0 = clock();
    row->rc = plateau_solve(polygon, m, &o, &mesh, &rep, NULL);
    row->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    row->wall = wall_now() - w0;
    getrusage(RUSAGE_SELF, &ru);
    row->maxrss_kb = ru.ru_maxrss;
    row->area = rep.area;
    row->f_final = rep.f_final;
    row->interior = rep.interior_points;
    row->rounds = rep.rounds;
    row->iterations = rep.iterations;
    row->evaluations = rep.evaluations;
    row->lm_stop = (int)rep.lm_stop;
    row->linear_solver = (int)rep.linear_solver;
    row->defects = rep.defects;
    row->presolve_iterations = rep.presolve_iterations;
    plateau_mesh_free(&mesh);
}

/* one solve in a child process; 0 on failure to run it */
static int solve_child(size_t n, int linear_solver, int presolve, scale_row *row)
{
    int fd[2], status;
    pid_t pid;
    ssize_t got;
    if (pipe(fd) != 0) return 0;
    fflush(stdout);
    pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        scale_row r;
        memset(&r, 0, sizeof r);
        close(fd[0]);
        solve_once(n, linear_solver, presolve, &r);
        if (write(fd[1], &r, sizeof r) != (ssize_t)sizeof r) _exit(1);
        _exit(0);
    }
    close(fd[1]);
    got = read(fd[0], row, sizeof *row);
    close(fd[0]);
    waitpid(pid, &status, 0);
    return got == (ssize_t)sizeof *row && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

static void run(size_t n, int linear_solver, int presolve, int reps)
{
    double wall[3], cpu[3];
    long rss = 0;
    scale_row row;
    int r;
    memset(&row, 0, sizeof row);
    for (r = 0; r < reps; r++) {
        if (!solve_child(n, linear_solver, presolve, &row) || row.rc != PLATEAU_OK) {
            printf("%6lu  %-6s  failed (%s)\n", (unsigned long)n,
                   linear_solver == PLATEAU_LINEAR_DENSE ? "dense" : "sparse",
                   plateau_result_string((plateau_result)row.rc));
            return;
        }
        wall[r] = row.wall;
        cpu[r] = row.cpu;
        if (row.maxrss_kb > rss) rss = row.maxrss_kb;
    }
    qsort(wall, (size_t)reps, sizeof wall[0], cmp_double);
    qsort(cpu, (size_t)reps, sizeof cpu[0], cmp_double);
    printf("%6lu  %6lu  %-6s  %8d  %3d  %8.2f  %8.2f  %7.1f  %6d  %5d  %5d  %-9s  %.2e  %.8f  %u\n",
           (unsigned long)n, (unsigned long)row.interior,
           row.linear_solver == PLATEAU_LINEAR_DENSE ? "dense" : "sparse", row.presolve_iterations,
           reps, wall[reps / 2],
           cpu[reps / 2], (double)rss / 1024.0, row.rounds, row.iterations, row.evaluations,
           plateau_lm_stop_string((plateau_lm_stop)row.lm_stop), row.f_final, row.area,
           row.defects);
}

int main(int argc, char **argv)
{
    int quick = argc > 1 && strcmp(argv[1], "quick") == 0;
    int full = argc > 1 && strcmp(argv[1], "full") == 0;
    printf("method paper, helicoid b = 1.9, u in [-1.5, 1.5], v in [-pi/2, pi/2], 28 boundary "
           "vertices,\nquality seeding + refine_boundary; one child process per run, median of "
           "the runs\n");
    printf("presolve: L-BFGS steps of the default area presolve (the domain is the circle);\n"
           "the rows with presolve 0 ask for none (paper_presolve = 1): the LM / dog leg alone\n");
    printf("     n   inner  path    presolve  runs  wall s  CPU s  peak MB  rounds  iters  evals  "
           "lm_stop    F          area        defects\n");
    if (!quick) run(1000, PLATEAU_LINEAR_DENSE, 0, 1);
    run(1000, PLATEAU_LINEAR_SPARSE, 0, quick ? 1 : 3);
    run(3000, PLATEAU_LINEAR_SPARSE, 0, quick ? 1 : 3);
    run(10000, PLATEAU_LINEAR_SPARSE, 0, 1);
    if (full) run(1000, PLATEAU_LINEAR_DENSE, 1, 1);
    run(1000, PLATEAU_LINEAR_SPARSE, 1, quick ? 1 : 3);
    run(3000, PLATEAU_LINEAR_SPARSE, 1, quick ? 1 : 3);
    run(10000, PLATEAU_LINEAR_SPARSE, 1, quick ? 1 : 3);
    return 0;
}
