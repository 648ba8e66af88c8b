// cgal_delaunay.cpp - the comparison for bench/bench_delaunay.c: CGAL's
// Delaunay_triangulation_2 (and Constrained_Delaunay_triangulation_2 with
// Exact_predicates_tag for the segment case) with the exact-predicates-
// inexact-constructions kernel on the same points (same generator and
// seed).  Optional: only when libcgal-dev is installed; neither the library
// nor its tests need it.  Build and run:
//
//   g++ -O3 -DNDEBUG -o build/bench/cgal_delaunay bench/cgal_delaunay.cpp -lgmp -lmpfr
//   ./build/bench/cgal_delaunay                  (its own table, repeats in one process)
//   ./build/bench/cgal_delaunay CASE N           (one run in a fresh process)
//
// One run prints "cpu_seconds peak_bytes triangles": the CPU time (clock)
// of the triangulation alone and the growth of the peak resident set
// (getrusage ru_maxrss) over the peak after the input was generated, so
// the input is not counted.  CASE is uniform (N points), grid (N = side^2)
// or cdt (N points and 200 segments); bench_delaunay's "cgal" mode runs
// these alternately with its own and prints the ratios.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> DT;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag> CDT;

static std::uint64_t state;
static double next_rand()
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static double time_it(const std::vector<K::Point_2> &pts, int reps, std::size_t *faces)
{
    std::vector<double> t;
    for (int r = 0; r < reps; r++) {
        std::clock_t c0 = std::clock();
        DT dt;
        dt.insert(pts.begin(), pts.end());
        t.push_back((double)(std::clock() - c0) / CLOCKS_PER_SEC);
        *faces = dt.number_of_faces();
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

static long peak_bytes()
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss * 1024L;
}

// One run of one case (the inputs are those of bench_delaunay.c's one_case).
static int one_case(const char *name, std::size_t n)
{
    std::vector<K::Point_2> pts;
    std::vector<std::pair<std::size_t, std::size_t> > segs;
    std::size_t faces = 0;
    long before, after;
    std::clock_t c0;
    double sec;
    state = 1;
    if (!std::strcmp(name, "uniform")) {
        pts.reserve(n);
        for (std::size_t i = 0; i < n; i++) {
            double x = next_rand();
            double y = next_rand();
            pts.push_back(K::Point_2(x, y));
        }
    } else if (!std::strcmp(name, "grid")) {
        std::size_t side = (std::size_t)std::sqrt((double)n);
        pts.reserve(side * side);
        for (std::size_t i = 0; i < side * side; i++)
            pts.push_back(K::Point_2((double)(i % side), (double)(i / side)));
    } else if (!std::strcmp(name, "cdt")) {
        pts.reserve(n + 400);
        for (std::size_t i = 0; i < n; i++) {
            double x = next_rand();
            double y = next_rand();
            pts.push_back(K::Point_2(x, y));
        }
        for (std::size_t k = 0; k < 200; k++) {
            double y = (0.25 + (double)k) / 200.0 * 0.99;
            pts.push_back(K::Point_2(0.05, y));
            pts.push_back(K::Point_2(0.95, y + 0.002));
            segs.push_back(std::make_pair(n + 2 * k, n + 2 * k + 1));
        }
    } else {
        return 1;
    }
    before = peak_bytes();
    c0 = std::clock();
    if (segs.empty()) {
        DT dt;
        dt.insert(pts.begin(), pts.end());
        sec = (double)(std::clock() - c0) / CLOCKS_PER_SEC;
        faces = dt.number_of_faces();
        after = peak_bytes();
    } else {
        CDT cdt;
        cdt.insert_constraints(pts.begin(), pts.end(), segs.begin(), segs.end());
        sec = (double)(std::clock() - c0) / CLOCKS_PER_SEC;
        faces = cdt.number_of_faces();
        after = peak_bytes();
    }
    std::printf("%.6f %ld %lu\n", sec, after - before, (unsigned long)faces);
    return 0;
}

int main(int argc, char **argv)
{
    const std::size_t sizes[3] = {10000, 100000, 1000000};
    const int reps[3] = {9, 5, 3};
    if (argc == 3) return one_case(argv[1], (std::size_t)std::strtoul(argv[2], 0, 10));
    std::printf("CGAL %s Delaunay_triangulation_2 (Epick): CPU time (clock), median of repeats\n",
                CGAL_VERSION_STR);
    for (int s = 0; s < 3; s++) {
        std::vector<K::Point_2> pts;
        state = 1;
        for (std::size_t i = 0; i < sizes[s]; i++) {
            double x = next_rand();
            double y = next_rand();
            pts.push_back(K::Point_2(x, y));
        }
        std::size_t f = 0;
        double sec = time_it(pts, reps[s], &f);
        std::printf("uniform 10^%d           %9lu points %9lu triangles  median of %2d: %8.4f s  %6.2f M points/s\n",
                    s + 4, (unsigned long)sizes[s], (unsigned long)f, reps[s], sec,
                    (double)sizes[s] / sec / 1e6);
    }
    std::vector<K::Point_2> grid;
    for (std::size_t i = 0; i < 1000000; i++) grid.push_back(K::Point_2((double)(i % 1000), (double)(i / 1000)));
    std::size_t f = 0;
    double sec = time_it(grid, 3, &f);
    std::printf("grid 1000 x 1000         1000000 points %9lu triangles  median of  3: %8.4f s  %6.2f M points/s\n",
                (unsigned long)f, sec, 1e6 / sec / 1e6);
    return 0;
}
