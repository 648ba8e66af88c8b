/* bench_common.h - helpers shared by the benchmarks (not part of the
 * library): clocks, medians, and a function run in a child process whose
 * CPU time and peak memory are the kernel's accounting of that process
 * alone (wait4's rusage), with its result sent back through a pipe.
 *
 * Define _DEFAULT_SOURCE before any header (fork and pipe are POSIX, wait4
 * is BSD: glibc declares them under it with -std=c99).  Every function is
 * static. */
#ifndef PLATEAU_BENCH_COMMON_H
#define PLATEAU_BENCH_COMMON_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__GNUC__) || defined(__clang__)
#define BENCH_FN static __attribute__((unused))
#else
#define BENCH_FN static
#endif

BENCH_FN double bench_wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

BENCH_FN int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

/* The median of n values (sorts them in place); 0 for n = 0. */
BENCH_FN double bench_median(double *v, size_t n)
{
    if (n == 0) return 0.0;
    qsort(v, n, sizeof v[0], bench_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* User + system CPU seconds of a rusage. */
BENCH_FN double bench_cpu_of(const struct rusage *ru)
{
    return (double)ru->ru_utime.tv_sec + 1e-6 * (double)ru->ru_utime.tv_usec +
           (double)ru->ru_stime.tv_sec + 1e-6 * (double)ru->ru_stime.tv_usec;
}

/* Runs fn(arg, out) in a child process and copies its out_size bytes of
 * result back into out; *ru gets the child's own resource use (CPU time,
 * ru_maxrss its peak resident memory in KB).  Returns 1 when the child ran
 * and sent its result, 0 otherwise. */
BENCH_FN int bench_run_child(void (*fn)(void *arg, void *out), void *arg, void *out,
                             size_t out_size, struct rusage *ru)
{
    int fd[2], status = 0;
    pid_t pid;
    size_t got = 0;
    memset(ru, 0, sizeof *ru);
    if (pipe(fd) != 0) return 0;
    fflush(stdout);
    pid = fork();
    if (pid < 0) {
        close(fd[0]);
        close(fd[1]);
        return 0;
    }
    if (pid == 0) {
        char *buf = (char *)calloc(1, out_size);
        close(fd[0]);
        if (!buf) _exit(1);
        fn(arg, buf);
        if (write(fd[1], buf, out_size) != (ssize_t)out_size) _exit(1);
        _exit(0);
    }
    close(fd[1]);
    while (got < out_size) {
        ssize_t r = read(fd[0], (char *)out + got, out_size - got);
        if (r <= 0) break;
        got += (size_t)r;
    }
    close(fd[0]);
    if (wait4(pid, &status, 0, ru) != pid) return 0;
    return got == out_size && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

#endif
