// cgal_delaunay.cpp - the comparison for bench/bench_delaunay.c: CGAL's
// Delaunay_triangulation_2 with the exact-predicates-inexact-constructions
// kernel on the same points (same generator and seed), CPU time (clock),
// median of the same number of repeats.  Optional: only when libcgal-dev is
// installed; neither the library nor its tests need it.  Build and run:
//
//   g++ -O3 -DNDEBUG -o build/bench/cgal_delaunay bench/cgal_delaunay.cpp -lgmp -lmpfr
//   ./build/bench/cgal_delaunay
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> DT;

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

int main()
{
    const std::size_t sizes[3] = {10000, 100000, 1000000};
    const int reps[3] = {9, 5, 3};
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
