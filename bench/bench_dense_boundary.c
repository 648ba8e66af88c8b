/* bench_dense_boundary.c - dense boundaries with the default options
 * (built by `make bench`).
 *
 * The smooth closed curve (cos t, sin t, 0.3 cos 3t) sampled with m
 * vertices, t = 2 pi i / m (a scan or a CAD export gives such curves),
 * solved by plateau_solve with all-zero options (method paper, n = m, the
 * quality seeding), m = 10^3, 3 10^3 and 10^4 (with the argument "full"
 * also 3 10^4 and 10^5, the latter once with the default max_memory and
 * once without a limit); and the 20 000-vertex curve with n = 10 (the fan
 * seeding: ten interior vertices of valence about 2000).  Each run is a
 * child process (fork), so that its peak resident memory (getrusage
 * ru_maxrss) is its own; wall (CLOCK_MONOTONIC) and CPU (clock) time of
 * plateau_solve, one run per row, and the memory estimate plateau_solve
 * compares with max_memory once the seeding has made its points
 * (plateau_memory_estimate for the seeded count) with its ratio to that
 * peak (above 1: an upper bound).  The targets (this machine, defaults):
 * m = 10^4 under 10 s, m = 10^5 under 30 s (the accuracy work's; the
 * reliability work's was 120 s), the 20 000-vertex curve with n = 10
 * under 2 s; each row says whether it met its target (CPU time below it,
 * and a valid, solved mesh).
 * Then the time limit (options.max_seconds on the wall clock): m = 10^4
 * with budgets 0.3, 1, 2 and 5 s (with "full" also m = 10^5, budgets 0.3
 * to 30 s); each row gives the wall and CPU time of plateau_solve and
 * whether the wall time stayed within 1.1 budget + 0.5 s (the overshoot
 * allowed; on a loaded machine the wall time may pass it while the CPU
 * time shows the solve was starved, not late).
 * Measurements and their history: examples/NOTES.md.
 */
#define _POSIX_C_SOURCE 200809L
#define PLATEAU_IMPLEMENTATION
#include "plateau.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct dense_row {
    int rc;
    double wall, cpu, area, estimate;
    long maxrss_kb;
    size_t interior, rounds;
    plateau_stop stop;
    unsigned defects;
    char message[160]; /* the refusal's sentence (it names the estimate) */
} dense_row;

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* options.clock_fn: wall-clock seconds */
static double wall_clock(void *user)
{
    (void)user;
    return wall_now();
}

/* seconds > 0: options.max_seconds on the wall clock */
static void solve_once(size_t m, size_t n, int unlimited, double seconds, dense_row *row)
{
    double *xyz = (double *)malloc(3 * m * sizeof(double)), w0;
    plateau_options o;
    plateau_mesh mesh;
    plateau_report rep;
    plateau_error err;
    struct rusage ru;
    clock_t c0;
    size_t i;
    if (!xyz) {
        row->rc = PLATEAU_ERR_OUT_OF_MEMORY;
        return;
    }
    for (i = 0; i < m; i++) {
        double t = 6.283185307179586 * (double)i / (double)m;
        xyz[3 * i] = cos(t);
        xyz[3 * i + 1] = sin(t);
        xyz[3 * i + 2] = 0.3 * cos(3.0 * t);
    }
    memset(&o, 0, sizeof o);
    memset(&rep, 0, sizeof rep);
    o.interior_points = n;
    if (unlimited) o.max_memory = (size_t)-1;
    if (seconds > 0.0) {
        o.max_seconds = seconds;
        o.clock_fn = wall_clock;
    }
    w0 = wall_now();
    c0 = clock();
    row->rc = plateau_solve(xyz, m, &o, &mesh, &rep, &err);
    row->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    row->wall = wall_now() - w0;
    getrusage(RUSAGE_SELF, &ru);
    row->maxrss_kb = ru.ru_maxrss;
    row->area = rep.area;
    row->interior = rep.interior_points;
    /* the bound plateau_solve checks once the seeding has made its points */
    row->estimate = plateau_memory_estimate(o.method, m, rep.seeded_points);
    row->rounds = rep.rounds;
    row->stop = rep.stop;
    row->defects = rep.defects;
    if (row->rc != PLATEAU_OK) memcpy(row->message, err.message, sizeof row->message);
    plateau_mesh_free(&mesh);
    free(xyz);
}

/* one solve in a child process; 0 on failure to run it */
static int solve_child(size_t m, size_t n, int unlimited, double seconds, dense_row *row)
{
    int fd[2], status;
    pid_t pid;
    ssize_t got;
    if (pipe(fd) != 0) return 0;
    fflush(stdout);
    pid = fork();
    if (pid < 0) return 0;
    if (pid == 0) {
        dense_row r;
        memset(&r, 0, sizeof r);
        close(fd[0]);
        solve_once(m, n, unlimited, seconds, &r);
        if (write(fd[1], &r, sizeof r) != (ssize_t)sizeof r) _exit(1);
        _exit(0);
    }
    close(fd[1]);
    got = read(fd[0], row, sizeof *row);
    close(fd[0]);
    waitpid(pid, &status, 0);
    return got == (ssize_t)sizeof *row && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* The time limit: each budget once per size, in a child process. */
static void budget_sweep(int full)
{
    static const double budgets[] = {0.3, 1.0, 2.0, 5.0, 10.0, 30.0};
    static const size_t sizes[] = {10000, 100000};
    size_t s, b;
    printf("\ntime limit (options.max_seconds, wall clock), default options otherwise\n");
    printf("       m  budget s   wall s    CPU s  interior  rounds  stop                 within 1.1 B + 0.5 s\n");
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (b = 0; b < sizeof budgets / sizeof budgets[0]; b++) {
            dense_row r;
            double B = budgets[b];
            if (!full && (sizes[s] > 10000 || B > 5.0)) continue;
            memset(&r, 0, sizeof r);
            if (!solve_child(sizes[s], 0, 0, B, &r)) {
                printf("%8lu %9.1f  the child process failed\n", (unsigned long)sizes[s], B);
                continue;
            }
            if (r.rc != PLATEAU_OK) {
                r.message[sizeof r.message - 1] = '\0';
                printf("%8lu %9.1f  refused after %.2f s: %s\n", (unsigned long)sizes[s], B, r.wall, r.message);
                continue;
            }
            printf("%8lu %9.1f %8.2f %8.2f %9lu %7lu  %-20.20s %s\n", (unsigned long)sizes[s], B, r.wall, r.cpu,
                   (unsigned long)r.interior, (unsigned long)r.rounds, plateau_stop_string(r.stop),
                   r.wall <= 1.1 * B + 0.5 ? "yes" : r.cpu <= 1.1 * B + 0.5 ? "no (wall), CPU within" : "NO");
        }
}

int main(int argc, char **argv)
{
    static const struct {
        size_t m, n;
        int unlimited, full;
        double target; /* CPU seconds; 0: none */
    } runs[] = {
        {1000, 0, 0, 0, 0.0},      {3000, 0, 0, 0, 0.0},       {10000, 0, 0, 0, 10.0},
        {20000, 10, 0, 0, 2.0},    {30000, 0, 0, 1, 0.0},      {100000, 0, 0, 1, 30.0},
        {100000, 0, 1, 1, 30.0},
    };
    int full = argc > 1 && strcmp(argv[1], "full") == 0;
    size_t k;
    printf("curve (cos t, sin t, 0.3 cos 3t), m vertices; default options (n = m unless given);\n"
           "one child process per run\n");
    printf("       m      n   interior   wall s    CPU s  peak MB  est. MB  est/peak  rounds  stop          area  "
           "defects  target\n");
    for (k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        dense_row r;
        char n[16], target[40];
        if (runs[k].full && !full) continue;
        memset(&r, 0, sizeof r);
        sprintf(n, runs[k].n ? "%lu" : "m", (unsigned long)runs[k].n);
        if (!solve_child(runs[k].m, runs[k].n, runs[k].unlimited, 0.0, &r)) {
            printf("%8lu %6s  the child process failed\n", (unsigned long)runs[k].m, n);
            continue;
        }
        if (runs[k].target > 0.0)
            sprintf(target, "%s %.0f s", r.rc == PLATEAU_OK && r.defects == 0 && r.cpu < runs[k].target ? "met, <" : "MISSED, <",
                    runs[k].target);
        else
            target[0] = '\0';
        if (r.rc != PLATEAU_OK) {
            r.message[sizeof r.message - 1] = '\0';
            printf("%8lu %6s  refused after %.2f s: %s%s  %s\n          %s\n", (unsigned long)runs[k].m, n, r.wall,
                   plateau_result_string((plateau_result)r.rc),
                   runs[k].unlimited ? "" : " (default max_memory)", target, r.message);
            continue;
        }
        printf("%8lu %6s %10lu %8.2f %8.2f %8.1f %8.1f %9.2f %7lu  %-9.9s %.8f  %7u  %s%s\n", (unsigned long)runs[k].m,
               n, (unsigned long)r.interior, r.wall, r.cpu, (double)r.maxrss_kb / 1024.0, r.estimate / 1048576.0,
               r.estimate / (1024.0 * (double)r.maxrss_kb), (unsigned long)r.rounds, plateau_stop_string(r.stop), r.area, r.defects, target,
               runs[k].unlimited ? " (max_memory: no limit)" : "");
    }
    budget_sweep(full);
    return 0;
}
