/* plateau_delaunay.h - robust incremental constrained Delaunay triangulation
 * in the plane (steps 3 and 4 of the Plateau-Mesh method, numbered as in
 * plateau.h: the quality seeding's refinement and the constrained
 * triangulation of the boundary and the interior points).
 * Part of plateau; stands alone: needs no other header of the project.
 * Version 0.1.0.  MIT licence (see the end of the file).
 *
 * DO THIS in exactly one C or C++ file:
 *     #define PLATEAU_DELAUNAY_IMPLEMENTATION
 *     #include "plateau_delaunay.h"
 * (PLATEAU_IMPLEMENTATION also switches it on.)  Other files just include it.
 * Define PLATEAU_STATIC first to give every function internal linkage.
 *
 * WHAT IT DOES
 *   Given points (x, y) and constraint segments (pairs of point indices), it
 *   returns the constrained Delaunay triangulation: triangles as counter-
 *   clockwise index triples, the neighbour across each edge, and which edges
 *   lie on segments.  Closed loops of segments bound a domain (an outer
 *   boundary and any number of holes, islands in holes, ...): triangles
 *   outside it are dropped, or the whole convex hull is kept on request.
 *   Exact predicates make it safe on collinear, co-circular, duplicate,
 *   tiny (1e-300) and huge (1e300) input; a fixed tie-breaking rule makes
 *   the result the same on every run and for every order of the input.
 *   It is a drop-in for the triangulation part of Shewchuk's Triangle.
 *
 * EXAMPLE (complete: a square with a square hole and a point inside)
 *     #define PLATEAU_DELAUNAY_IMPLEMENTATION
 *     #include "plateau_delaunay.h"
 *     #include <stdio.h>
 *     #include <string.h>
 *     int main(void)
 *     {
 *         double pts[] = {0, 0, 4, 0, 4, 4, 0, 4,   1, 1, 1, 2, 2, 2, 2, 1,   3, 3};
 *         plateau_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0,   4, 5, 5, 6, 6, 7, 7, 4};
 *         plateau_dt_input in;
 *         plateau_dt_mesh mesh;
 *         plateau_dt_error err;
 *         plateau_dt_result r;
 *         size_t t;
 *         memset(&in, 0, sizeof in); // every field zero (C++ warns at = {0})
 *         in.points = pts;   in.num_points = 9;
 *         in.segments = seg; in.num_segments = 8;
 *         r = plateau_dt_triangulate(&in, NULL, &mesh, &err);
 *         if (r != PLATEAU_DT_OK) {
 *             printf("%s: %s\n", plateau_dt_result_string(r), err.message);
 *             return 1;
 *         }
 *         for (t = 0; t < mesh.num_triangles; t++)
 *             printf("%d %d %d\n", (int)mesh.triangles[3 * t], (int)mesh.triangles[3 * t + 1],
 *                    (int)mesh.triangles[3 * t + 2]);
 *         plateau_dt_free(&mesh);
 *         return 0;
 *     }
 *   (examples/delaunay_quickstart.c is this program.)
 *
 * CONFIGURATION (define before including the implementation)
 *     macro                            default          meaning
 *     PLATEAU_DELAUNAY_IMPLEMENTATION  -                compile the implementation here
 *     PLATEAU_IMPLEMENTATION           -                same, for every plateau header
 *     PLATEAU_STATIC                   -                every function static
 *     PLATEAU_DT_DEF                   extern           linkage of the API (e.g. DLL export)
 *     PLATEAU_MALLOC(size, ctx)        malloc(size)     allocation; define both or neither;
 *     PLATEAU_FREE(ptr, ctx)           free(ptr)        ctx = options.allocator.user_data
 *     PLATEAU_ASSERT(x)                assert(x)        internal invariants only
 *     PLATEAU_FABS, PLATEAU_SQRT,      fabs, sqrt,      the libm calls used here (sqrt and
 *     PLATEAU_SIN                      sin              sin by the refinement only)
 *     PLATEAU_ATAN2, PLATEAU_COS       atan2, cos       (by plateau.h; required freestanding)
 *     PLATEAU_SNPRINTF                 snprintf         formats the report's message
 *                                                       (%s, %.Ns, %ld, %g); never prints
 *     PLATEAU_FREESTANDING             -                no C library header but the
 *                                                       freestanding ones: the macros
 *                                                       above must be defined, and
 *                                                       memcpy, memmove, memset linked
 *     PLATEAU_INDEX_TYPE               int32_t          index type (plateau_index)
 *     PLATEAU_DT_NO_STEINER            -                leave out what adds points: the
 *                                                       refinement (phase 6) and split
 *                                                       crossings; min_angle, max_area,
 *                                                       max_area_fn or
 *                                                       split_crossing_segments set is
 *                                                       PLATEAU_DT_ERR_ARGUMENT naming the
 *                                                       macro; plateau.h's
 *                                                       PLATEAU_NO_QUALITY_SEEDING defines it
 *   Run time: plateau_dt_options, all-zero = these defaults (see them with
 *   plateau_dt_resolved_options()):
 *     keep_convex_hull 0         0: keep the triangles inside the closed
 *                                segment loops (no segments: the hull);
 *                                1: keep every triangle of the convex hull
 *     allocator                  PLATEAU_MALLOC / PLATEAU_FREE; or set both
 *                                alloc_fn and free_fn (user_data is passed)
 *     seed 0                     0 = a fixed seed; the insertion order only
 *     split_crossing_segments 0  0: crossing segments are an error; 1: both
 *                                are split at a new vertex at the crossing
 *                                (or routed through an endpoint or an
 *                                earlier crossing vertex within 2^-40 of
 *                                it, and a third segment passing within
 *                                2^-40 of a new crossing vertex is routed
 *                                through it too: crossings that coincide
 *                                to rounding become one vertex)
 *   Refinement (all zero: none; see phase 6 below):
 *     min_angle 0                degrees; no triangle of the result has a
 *                                smaller angle, except inside input angles
 *                                below 1.5 min_angle (clamped to 34)
 *     max_area 0                 no triangle is larger (0: no limit)
 *     max_area_fn NULL           limit as a function of the centroid,
 *     max_area_user NULL         called with max_area_user (<= 0: none)
 *     max_added_points 0         budget; 0 = 10 n + 4194304
 *     keep_segments 0            1: never split a segment (or hull edge)
 *     progress NULL              int (*)(size_t vertices, void *user),
 *     progress_user NULL         called as the refinement starts and
 *                                every 1024 refinement vertices;
 *                                non-zero stops (refine_stop CANCELLED)
 *     inner_segments 0           the last inner_segments segments are
 *                                constraints inside the domain that the
 *                                others bound: they may end freely or
 *                                close, and bound nothing (ridges)
 *
 * API INDEX (every public function, one entry each: its signature with the
 * parameter names of its declaration, then what it does; the full comment
 * is at the declaration.  tests/test_api_index.c checks this list against
 * the declarations)
 *   Triangulation
 *     plateau_dt_result plateau_dt_triangulate(input, options, mesh, err)
 *         the constrained Delaunay triangulation (and optional refinement)
 *     void plateau_dt_free(mesh)
 *         frees a mesh's arrays and zeroes it
 *     plateau_dt_options plateau_dt_resolved_options(options)
 *         the options with every default filled in
 *     const char *plateau_dt_result_string(result)
 *         the sentence for a result code
 *     const char *plateau_dt_refine_stop_string(stop)
 *         the sentence for a refinement's stop reason
 *   Exact predicates
 *     int plateau_dt_orient(a, b, c)
 *         +1, -1 or 0: a, b, c counter-clockwise, clockwise or collinear
 *     int plateau_dt_incircle(a, b, c, d)
 *         +1, -1 or 0: d inside, outside or on the circle through a, b, c
 *
 * OUTPUT
 *   mesh.points holds the input points (unchanged, at their input indices)
 *   followed by the vertices added at segment crossings.  A point equal to
 *   an earlier one (exactly) is a duplicate: it appears in no triangle and
 *   duplicate_of[i] names the smallest index with the same coordinates
 *   (duplicate_of[i] = i for the kept ones).  triangles[3t..3t+2] are
 *   counter-clockwise; neighbors[3t+k] is the triangle across the edge from
 *   triangles[3t+k] to triangles[3t+(k+1)%3] (-1 on the boundary of the
 *   result) and constrained[3t+k] is 1 when that edge lies on a segment.
 *   Segments are split wherever input points lie exactly on them.
 *   segment_of[v] is the input segment an added vertex lies on (-1 for
 *   input points and interior refinement vertices).  After a refinement,
 *   refine_stop says why it ended (PLATEAU_DT_REFINE_DONE; _BUDGET when
 *   max_added_points ran out; _CANCELLED when the progress callback asked
 *   to stop; plateau_dt_refine_stop_string names them) and num_unrefined
 *   counts the triangles left beyond a bound (inside small input angles,
 *   or next to a segment that keep_segments protects).  Vertices added on a segment are rounded
 *   points: they lie on it to within an ulp, not exactly.
 *
 * THE ALGORITHM, in six phases (numbered apart from the steps of the
 *   Plateau-Mesh method)
 *   1. Validation; the coordinates are multiplied by one power of two (an
 *      exact operation, or the input is refused: see ROBUSTNESS) so that
 *      the largest is just below 2^200.
 *   2. Insertion order: a biased randomised insertion order (BRIO: Amenta,
 *      Choi and Rote, "Incremental constructions con BRIO", SoCG 2003):
 *      each point joins round r with probability 2^-(R-r+1) (seeded
 *      generator), and inside a round the points follow a Hilbert curve, so
 *      consecutive points are close and the walk below is short.
 *   3. Incremental insertion (Lawson, "Software for C1 surface
 *      interpolation", 1977; Guibas and Stolfi 1985): locate the new point
 *      by a remembering stochastic walk from the last triangle (Devillers,
 *      Pion and Teillaud, "Walking in a triangulation", 2002; bounded, with
 *      an exhaustive exact scan as the fallback), split the triangle (or the
 *      edge it lies on) and flip edges until every edge is locally Delaunay.
 *      The outside of the hull is covered by "ghost" triangles joined to a
 *      vertex at infinity, whose circumcircle is the open half-plane beyond
 *      their hull edge: no numeric super-triangle, no magic coordinates.
 *   4. Segments, in input order: walk from one end towards the other;
 *      points exactly on the segment split it; the edges crossing each piece
 *      are flipped away (Sloan, "A fast algorithm for generating constrained
 *      Delaunay triangulations", Computers & Structures 47, 1993) and the
 *      new edges are flipped back to constrained Delaunay (Lawson flips that
 *      never flip a constrained edge).  A crossed constrained edge is an
 *      error, or both segments are split at the rounded crossing point.
 *   5. Domain: a flood fill from the ghost triangles counts the segments
 *      crossed (fewest); odd counts are inside (outer boundary 1, hole 2,
 *      island in a hole 3, ...), so loops may be given in either direction.
 *   6. Refinement, when asked for (Ruppert, "A Delaunay refinement
 *      algorithm for quality 2-dimensional mesh generation", J. Algorithms
 *      18, 1995; Shewchuk, "Delaunay refinement algorithms for triangular
 *      mesh generation", Comput. Geom. 22, 2002; Miller, Pav and Walkington,
 *      "An incremental Delaunay meshing algorithm", CMU 02-CNA-023, 2002):
 *      subsegments encroached upon (a vertex inside their diametral circle)
 *      are split first, at the midpoint or, next to an input vertex, on a
 *      power-of-two "concentric shell" around it (so that small input
 *      angles do not cause endless splitting); then each bad triangle (an
 *      angle below min_angle, or too large) gets its circumcentre, unless
 *      the circumcentre lies beyond a segment or would encroach upon one,
 *      in which case those subsegments are split instead.  Triangles whose
 *      small angle is an input angle between two segments are exempt.
 *      Inside an input angle p below 1.5 min_angle (two segments, or a
 *      segment and a hull edge) a skinny triangle is left as it is when
 *      its fix would split a subsegment closer to an end than the
 *      triangle's circumradius (Shewchuk's "Terminator", 2002, section 6):
 *      this is what stops the cascade of ever shorter edges towards the
 *      apex of a small angle.  Such triangles have angles of at least
 *      arctan(sin p / (2 - cos p)) (p = 10 degrees: 9.7; p = 1: 1.0);
 *      they and the exempt ones are counted in num_unrefined.  With
 *      keep_segments a too-large triangle that cannot get its circumcentre
 *      gets its centroid.  Ruppert proved termination for bounds up to
 *      20.7 degrees and Miller, Pav and Walkington up to 26.45 (input
 *      angles of 60 degrees or more); with the rule above, bounds up to 30
 *      degrees ended (refine_stop DONE) at every input angle tested, and
 *      34 degrees usually works but can run into the budget at very small
 *      input angles, which ends every run (the experiment:
 *      examples/NOTES.md, "Measurements behind the solver's choices").
 *      Each insertion is a Lawson insertion as in phase 3, so the result
 *      stays constrained Delaunay.
 *   The result is the constrained Delaunay triangulation (Chew 1989): every
 *   edge that is not on a segment passes the exact empty-circle test.  The
 *   paper this library serves cites Miller, Pav and Walkington for its
 *   step 3; phases 2-3 are the incremental construction, phase 6 its
 *   meshing.
 *
 * ROBUSTNESS
 *   Orientation and in-circle tests are exact: a floating-point evaluation
 *   with Shewchuk's error bound decides when it can, and otherwise the
 *   determinant is evaluated exactly with floating-point expansions
 *   (Shewchuk, "Adaptive precision floating-point arithmetic and fast
 *   robust geometric predicates", Discrete Comput. Geom. 18, 1997:
 *   Two-Sum, Two-Product, Scale-Expansion, Expansion-Sum, written here from
 *   the paper).  This needs IEEE-754 binary64 arithmetic rounded to nearest,
 *   so the header refuses -ffast-math and x87 extended precision; with a
 *   hardware fused multiply-add, Two-Product uses fma() so that compiler
 *   contraction cannot break it.
 *   Scaling by a power of two keeps every product in range, so inputs from
 *   1e-300 to 1e300 work and give exactly the triangles of the same points
 *   scaled by any power of two.  The exact evaluation also shifts the
 *   coordinate differences of each test by a power of two chosen from their
 *   own top and bottom bits, so that no product of the expansions under- or
 *   overflows; when one test mixes magnitudes too far apart for that (more
 *   than 2^520 in an in-circle test, 2^1045 in an orientation test: a
 *   cluster of 1e-150 points inside a 1e150 square) it is evaluated with
 *   integers instead (every double is an integer multiple of 2^-1074).
 *   So both predicates are exact for every accepted input, whatever the
 *   mixture.  ERR_RANGE remains for one input class, a limit of the scaled
 *   working copy rather than of the predicates: phase 1's scaling must be
 *   exact, and it is unless the largest |coordinate| is 2^200 (1.6e60) or
 *   more and another nonzero one is smaller by a factor beyond 2^1221
 *   (1e367: e.g. 5e-324 next to 1e61, or 1e-300 next to 1e68); its last
 *   bits would then be lost and distinct points could become one, so such
 *   input is refused with PLATEAU_DT_ERR_RANGE, the report naming the
 *   point.  (Keeping those bits would need coordinates near 2^1000, where
 *   the circumcentres and crossing points of phases 4 and 6 overflow.)
 *   Ties are broken by symbolic perturbation ("simulation of simplicity",
 *   Edelsbrunner and Muecke 1990) of the lifting map: each point's height
 *   x^2 + y^2 is raised by an infinitesimal that is larger for
 *   lexicographically larger points.  Co-circular points (a square grid)
 *   therefore get one fixed triangulation that depends on the coordinates
 *   only: the same triangle set for every input order and seed.  Exactly
 *   collinear points are handled by exact tests (no zero-area triangle).
 *   Every loop has a bound; exceeding one returns PLATEAU_DT_ERR_INTERNAL.
 *
 * ERRORS
 *   plateau_dt_result (0 = OK, negative = error; plateau_dt_result_string
 *   gives the sentence) and, in the optional report, the offending point or
 *   segment and a message.  On error the mesh is all zero.
 *
 * THREAD SAFETY
 *   No global or static mutable state: calls on different meshes can run
 *   in parallel.  The in-circle fallback uses about 40 KB of stack (its
 *   integer path about 13 KB more).
 *
 * PERFORMANCE
 *   Expected O(n log n) for n points in the BRIO order (the walk between
 *   consecutive points is short); exactly co-circular grid cells are
 *   recognised without expansion arithmetic when the coordinate
 *   differences are small integers times a power of two (the floating-
 *   point value is then exact); the arrays of the triangulation become the
 *   output in place, and the working arrays are lent, freed or never
 *   allocated where a phase does not need them.  make bench-cgal compares
 *   it with CGAL on the same points (bench/bench_delaunay.c); the
 *   measurements, time and memory per point against CGAL's, and where the
 *   time goes: examples/NOTES.md, "Measurements behind the solver's
 *   choices".
 */
#ifndef PLATEAU_DELAUNAY_H
#define PLATEAU_DELAUNAY_H

#define PLATEAU_DELAUNAY_VERSION "0.1.0"
#define PLATEAU_DELAUNAY_VERSION_NUM 100 /* major * 10000 + minor * 100 + patch */

/* ---- Shared by every plateau header (identical copies, guarded) -------- */
#ifndef PLATEAU_COMMON_DECLARED
#define PLATEAU_COMMON_DECLARED
#include <stddef.h>
#include <stdint.h>

/* Vertex and triangle indices: a 32-bit signed type, -1 meaning "none".
 * Counts and byte sizes are size_t. */
#ifndef PLATEAU_INDEX_TYPE
#define PLATEAU_INDEX_TYPE int32_t
#define PLATEAU_INDEX_MAX INT32_MAX
#elif !defined(PLATEAU_INDEX_MAX)
#error "plateau: define PLATEAU_INDEX_MAX (the type's largest value) with PLATEAU_INDEX_TYPE"
#endif
typedef PLATEAU_INDEX_TYPE plateau_index;

/* A run-time allocator.  All-zero means: use PLATEAU_MALLOC / PLATEAU_FREE
 * (malloc and free unless you defined them), with user_data as their context.
 * Set both functions or neither. */
typedef struct plateau_allocator {
    void *(*alloc_fn)(size_t size, void *user_data);
    void (*free_fn)(void *ptr, void *user_data);
    void *user_data;
} plateau_allocator;
#endif /* PLATEAU_COMMON_DECLARED */

#ifndef PLATEAU_DT_DEF
#ifdef PLATEAU_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_DT_DEF static __attribute__((unused))
#else
#define PLATEAU_DT_DEF static
#endif
#else
#define PLATEAU_DT_DEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Result codes: one X-macro list gives the enum and the messages ---- */
#define PLATEAU_DT_RESULT_LIST(X)                                                          \
    X(PLATEAU_DT_OK, 0, "ok")                                                              \
    X(PLATEAU_DT_ERR_ARGUMENT, -1,                                                         \
      "invalid argument (NULL input, mesh or points, an allocator with one function, "     \
      "or a negative or NaN refinement bound)")                                            \
    X(PLATEAU_DT_ERR_OUT_OF_MEMORY, -2, "out of memory")                                       \
    X(PLATEAU_DT_ERR_OVERFLOW, -3, "too many points or segments for plateau_index")        \
    X(PLATEAU_DT_ERR_NOT_FINITE, -4, "a coordinate is NaN or infinite")                    \
    X(PLATEAU_DT_ERR_TOO_FEW_POINTS, -5, "fewer than 3 distinct points")                   \
    X(PLATEAU_DT_ERR_COLLINEAR, -6, "all points are collinear")                            \
    X(PLATEAU_DT_ERR_SEGMENT_INDEX, -7, "a segment endpoint index is out of range")        \
    X(PLATEAU_DT_ERR_DEGENERATE_SEGMENT, -8,                                               \
      "a segment joins a point to itself or to a duplicate of itself")                     \
    X(PLATEAU_DT_ERR_CROSSING_SEGMENTS, -9, "two segments cross")                          \
    X(PLATEAU_DT_ERR_OPEN_BOUNDARY, -10,                                                   \
      "the segments do not form closed loops, so they bound no domain")                    \
    X(PLATEAU_DT_ERR_INTERNAL, -11, "internal error: a consistency bound was exceeded")   \
    X(PLATEAU_DT_ERR_RANGE, -12,                                                           \
      "a nonzero coordinate is too small next to the largest one (by a factor beyond "     \
      "2^1221, the largest being 2^200 or more) to be kept exactly")

typedef enum plateau_dt_result {
#define PLATEAU__DT_ENUM(name, value, text) name = value,
#define PLATEAU__DT_COUNT(name, value, text) +1
    PLATEAU_DT_RESULT_LIST(PLATEAU__DT_ENUM)
    /* end marker: the number of codes, counted from the list */
    PLATEAU_DT_RESULT_COUNT = 0 PLATEAU_DT_RESULT_LIST(PLATEAU__DT_COUNT)
#undef PLATEAU__DT_COUNT
#undef PLATEAU__DT_ENUM
} plateau_dt_result;

typedef struct plateau_dt_input {
    const double *points;          /* 2 * num_points: x0, y0, x1, y1, ... */
    size_t num_points;
    const plateau_index *segments; /* 2 * num_segments: constraint edges */
    size_t num_segments;
} plateau_dt_input;

typedef struct plateau_dt_options {
    /* all-zero means the documented defaults */
    int keep_convex_hull; /* 0: keep only triangles inside the closed
                             constraint loops (outer boundary minus holes);
                             when there are no segments, the hull is kept */
    plateau_allocator allocator;
    uint64_t seed;        /* seed of the internal generator that randomises
                             the insertion order; 0 means the fixed default.
                             The triangle SET never depends on it (ties are
                             broken symbolically); the output order does. */
    int split_crossing_segments; /* 0: crossing segments are an error
                             (PLATEAU_DT_ERR_CROSSING_SEGMENTS); non-zero:
                             both are split at a new vertex placed at their
                             (rounded) crossing point, or routed through an
                             endpoint or earlier crossing vertex within 2^-40
                             (relative) of it; crossings that coincide to
                             rounding become one vertex */
    /* Delaunay refinement (quality meshing), off when all are zero: */
    double min_angle;     /* degrees: refine until no triangle has a smaller
                             angle (except at small input angles); 0: none.
                             Proven to terminate up to 26.45 (Miller, Pav and
                             Walkington) when no input angle is below 60
                             degrees; up to about 33 usually works; larger
                             values are clamped to 34 */
    double max_area;      /* refine until no triangle is larger; 0: none */
    double (*max_area_fn)(double x, double y, void *user); /* optional: the
                             area limit at a triangle's centroid (<= 0: no
                             limit there); both limits apply */
    void *max_area_user;  /* passed to max_area_fn */
    size_t max_added_points; /* budget of refinement vertices; 0: the
                             default 10 n + 4194304.  Reaching it ends the
                             refinement with refine_stop = ..._BUDGET */
    int keep_segments;    /* non-zero: refinement never splits a segment
                             (nor, in hull mode, a hull edge): the boundary
                             stays as given; triangles whose fix would
                             need a split are left as they are */
    int (*progress)(size_t vertices, void *user); /* optional: called as the
                             refinement starts (after the triangulation)
                             and every 1024 added vertices, with the
                             current vertex count; a non-zero return ends
                             the refinement at once, with refine_stop =
                             PLATEAU_DT_REFINE_CANCELLED (the result is
                             PLATEAU_DT_OK and the mesh is a valid CDT,
                             refined so far) */
    void *progress_user;  /* passed to progress */
    size_t inner_segments; /* the last inner_segments of the input's
                             segments are constraints inside the domain
                             (keep_convex_hull 0) that the others bound:
                             they may end freely (no
                             PLATEAU_DT_ERR_OPEN_BOUNDARY) or close, and
                             bound nothing (the triangles on both sides
                             are kept alike); more than num_segments:
                             PLATEAU_DT_ERR_ARGUMENT */
} plateau_dt_options;

/* Why the refinement ended (plateau_dt_mesh.refine_stop): one X-macro list
 * gives the enum and plateau_dt_refine_stop_string. */
#define PLATEAU_DT_REFINE_STOP_LIST(X)                                                     \
    X(PLATEAU_DT_REFINE_NONE, 0, "no refinement was asked for")                            \
    X(PLATEAU_DT_REFINE_DONE, 1,                                                           \
      "every triangle meets the bounds, except those counted in num_unrefined")            \
    X(PLATEAU_DT_REFINE_BUDGET, 2, "max_added_points vertices were added")                 \
    X(PLATEAU_DT_REFINE_CANCELLED, 3,                                                      \
      "the progress callback returned non-zero; the mesh is valid, refined so far")

typedef enum plateau_dt_refine_stop {
#define PLATEAU__DT_ENUM(name, value, text) name = value,
    PLATEAU_DT_REFINE_STOP_LIST(PLATEAU__DT_ENUM)
#undef PLATEAU__DT_ENUM
    PLATEAU__DT_REFINE_STOP_END = 4
} plateau_dt_refine_stop;

/* The output.  Vertex i < num_input_points is input point i (a duplicate
 * input point appears in no triangle; duplicate_of[i] names the one kept,
 * = i otherwise).  Points the library adds follow the input points. */
typedef struct plateau_dt_mesh {
    size_t num_points;
    double *points;               /* 2 * num_points */
    size_t num_input_points;
    plateau_index *duplicate_of;  /* num_input_points */
    size_t num_triangles;
    plateau_index *triangles;     /* 3 * num_triangles, counter-clockwise */
    plateau_index *neighbors;     /* 3 * num_triangles: neighbors[3t+k] is the
                                     triangle across edge (v_k, v_(k+1)%3)
                                     of triangle t, -1 if none */
    unsigned char *constrained;   /* 3 * num_triangles: 1 if that edge is a
                                     (piece of a) constraint segment */
    plateau_allocator allocator;  /* the one that allocated the arrays */
    plateau_index *segment_of;    /* num_points: for an added vertex, the
                                     input segment it lies on (-1: none, an
                                     interior refinement vertex); -1 for
                                     input points */
    plateau_dt_refine_stop refine_stop; /* why the refinement ended */
    size_t num_unrefined;         /* triangles left beyond the bounds: at
                                     small input angles, or (keep_segments)
                                     where a segment would need a split */
} plateau_dt_mesh;

/* Detail for a failed plateau_dt_triangulate, the same shape as plateau.h's
 * plateau_error and plateau_lm.h's plateau_lm_error. */
typedef struct plateau_dt_error {
    plateau_dt_result code; /* the result returned (PLATEAU_DT_OK on success) */
    long index;          /* the offending point or segment, -1 if none */
    long index2;         /* a second one where an error names two; -1 (the
                            same layout as plateau.h's plateau_error) */
    char message[160];   /* a sentence saying what was wrong */
} plateau_dt_error;

/* plateau_dt_triangulate: the constrained Delaunay triangulation of
 * input->points with input->segments as constraints.
 *   input    in: points and segments (segments may be NULL when
 *                num_segments is 0).
 *   options  in, may be NULL (= all-zero = defaults).
 *   mesh     out: filled on success; on error it is left empty (all zero)
 *                and plateau_dt_free accepts it.  Free it with
 *                plateau_dt_free.
 *   err      out, may be NULL: the code, and on error which point or
 *                segment and why (index -1 and message "" on success).
 * Returns PLATEAU_DT_OK or a negative plateau_dt_result.
 * Thread safety: reentrant; no global or static state.  Calls with
 * different meshes may run at the same time. */
PLATEAU_DT_DEF plateau_dt_result plateau_dt_triangulate(const plateau_dt_input *input,
                                                        const plateau_dt_options *options,
                                                        plateau_dt_mesh *mesh,
                                                        plateau_dt_error *err);
/* Frees the arrays of a mesh (through mesh->allocator) and zeroes it.
 * Accepts NULL and an all-zero mesh. */
PLATEAU_DT_DEF void plateau_dt_free(plateau_dt_mesh *mesh);
/* A static English sentence for a result code ("unknown result" otherwise). */
PLATEAU_DT_DEF const char *plateau_dt_result_string(plateau_dt_result result);
/* A static English sentence for a refine_stop value ("unknown stop"
 * otherwise). */
PLATEAU_DT_DEF const char *plateau_dt_refine_stop_string(plateau_dt_refine_stop stop);
/* The options with every default filled in (options may be NULL). */
PLATEAU_DT_DEF plateau_dt_options plateau_dt_resolved_options(const plateau_dt_options *options);

/* The exact predicates the triangulator uses, for callers and tests.
 * a, b, c, d point to (x, y) pairs of finite doubles.
 * plateau_dt_orient: +1 if a, b, c turn counter-clockwise, -1 if clockwise,
 *   0 if they are collinear (exactly).
 * plateau_dt_incircle: for a, b, c counter-clockwise, +1 if d lies inside
 *   their circumcircle, -1 outside, 0 on it (exactly; the sign flips when
 *   a, b, c are clockwise).
 * Each call rescales its points by a power of two (exact), or uses integer
 * arithmetic when that would lose bits: the answer is exact for every
 * finite input, subnormal and near DBL_MAX included (see ROBUSTNESS). */
PLATEAU_DT_DEF int plateau_dt_orient(const double *a, const double *b, const double *c);
PLATEAU_DT_DEF int plateau_dt_incircle(const double *a, const double *b, const double *c,
                                       const double *d);

#ifdef __cplusplus
}
#endif
#endif /* PLATEAU_DELAUNAY_H */

/* ======================================================================== */
#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_DELAUNAY_IMPLEMENTATION)
#define PLATEAU_DELAUNAY_IMPLEMENTATION
#endif
/* plateau.h without its quality seeding refines no triangulation */
#if defined(PLATEAU_NO_QUALITY_SEEDING) && !defined(PLATEAU_DT_NO_STEINER)
#define PLATEAU_DT_NO_STEINER
#endif
#if defined(PLATEAU_DELAUNAY_IMPLEMENTATION) && !defined(PLATEAU_DELAUNAY_IMPLEMENTED)
#define PLATEAU_DELAUNAY_IMPLEMENTED

/* ---- Shared by every plateau header (identical copies, guarded) -------- */
#ifndef PLATEAU_COMMON_IMPLEMENTED
#define PLATEAU_COMMON_IMPLEMENTED
#if defined(__FAST_MATH__)
#error "plateau needs IEEE-754 double arithmetic: do not compile it with -ffast-math"
#endif
#if (defined(PLATEAU_MALLOC) && !defined(PLATEAU_FREE)) || \
    (!defined(PLATEAU_MALLOC) && defined(PLATEAU_FREE))
#error "plateau: define both PLATEAU_MALLOC and PLATEAU_FREE, or neither"
#endif
#ifdef PLATEAU_FREESTANDING
/* No header of the C library beyond the freestanding ones (<stddef.h>,
 * <stdint.h>, <float.h>, <limits.h>): the user supplies the allocator, the
 * libm wrappers and (plateau_delaunay.h) PLATEAU_SNPRINTF, (plateau.h)
 * PLATEAU_QSORT, and links memcpy, memmove and memset, the functions C
 * compilers expect of every environment, freestanding ones included. */
#if !defined(PLATEAU_MALLOC) || !defined(PLATEAU_SQRT) || !defined(PLATEAU_FABS) || \
    !defined(PLATEAU_ATAN2) || !defined(PLATEAU_COS) || !defined(PLATEAU_SIN)
#error "plateau: PLATEAU_FREESTANDING needs PLATEAU_MALLOC, PLATEAU_FREE, PLATEAU_SQRT, PLATEAU_FABS, PLATEAU_ATAN2, PLATEAU_COS and PLATEAU_SIN"
#endif
#ifdef __cplusplus
extern "C" {
#endif
void *memcpy(void *dst, const void *src, size_t size);
void *memmove(void *dst, const void *src, size_t size);
void *memset(void *dst, int value, size_t size);
#ifdef __cplusplus
}
#endif
#ifndef PLATEAU_ASSERT
#define PLATEAU_ASSERT(x) ((void)0)
#endif
#endif /* PLATEAU_FREESTANDING */
#ifndef PLATEAU_MALLOC
#include <stdlib.h>
#define PLATEAU_MALLOC(size, ctx) ((void)(ctx), malloc(size))
#define PLATEAU_FREE(ptr, ctx) ((void)(ctx), free(ptr))
#endif
#ifndef PLATEAU_ASSERT
#include <assert.h>
#define PLATEAU_ASSERT(x) assert(x) /* internal invariants only, never input */
#endif
#ifndef PLATEAU_FREESTANDING
#include <math.h>
#endif
#ifndef PLATEAU_SQRT
#define PLATEAU_SQRT(x) sqrt(x)
#endif
#ifndef PLATEAU_FABS
#define PLATEAU_FABS(x) fabs(x)
#endif
#ifndef PLATEAU_ATAN2
#define PLATEAU_ATAN2(y, x) atan2(y, x)
#endif
#ifndef PLATEAU_COS
#define PLATEAU_COS(x) cos(x)
#endif
#ifndef PLATEAU_SIN
#define PLATEAU_SIN(x) sin(x)
#endif

/* Kept out of line (PLATEAU__NOINLINE): a small function called from
 * many places, whose inlined copies would add code and no speed. */
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU__NOINLINE __attribute__((noinline))
#else
#define PLATEAU__NOINLINE
#endif
/* PLATEAU__COLD: an error path (a message, a refusal), an exact-arithmetic
 * fallback that runs only when the fast test cannot decide, or code run
 * once (validation, setup, readers, writers): compiled for size, out of
 * the hot code.  gcc takes a function that always reaches a cold call for
 * never executed, and then the functions only it calls: never on a
 * function called unconditionally on the way to hot code; after adding
 * one, check with -ffunction-sections that no hot function moved to
 * .text.unlikely (examples/NOTES.md, section 25). */
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU__COLD __attribute__((cold))
#else
#define PLATEAU__COLD
#endif
/* Allocation through the run-time allocator if it has functions, else the
 * PLATEAU_MALLOC / PLATEAU_FREE macros with the allocator's user_data (out
 * of line: hundreds of calls, none in an inner loop). */
static PLATEAU__NOINLINE void *plateau__alloc(const plateau_allocator *a, size_t size)
{
    if (size == 0) size = 1;
    if (a && a->alloc_fn) return a->alloc_fn(size, a->user_data);
    return PLATEAU_MALLOC(size, a ? a->user_data : NULL);
}
static PLATEAU__NOINLINE void plateau__free(const plateau_allocator *a, void *ptr)
{
    if (!ptr) return;
    if (a && a->free_fn) { a->free_fn(ptr, a->user_data); return; }
    PLATEAU_FREE(ptr, a ? a->user_data : NULL);
}
/* count * size in bytes, or 0 on overflow (callers treat 0 as failure). */
static inline size_t plateau__bytes(size_t count, size_t size)
{
    if (size != 0 && count > (size_t)-1 / size) return 0;
    return count * size;
}
/* 1 when the allocator has both functions or neither (the only valid forms). */
static inline int plateau__allocator_valid(const plateau_allocator *a)
{
    return !a || ((a->alloc_fn == NULL) == (a->free_fn == NULL));
}
/* A 64-bit constant from its two 32-bit halves: C++98 has no long long
 * literal (g++ -std=c++98 -pedantic warns at 0x...ull). */
#define PLATEAU__U64(hi, lo) (((uint64_t)(hi) << 32) | (uint64_t)(lo))
#endif /* PLATEAU_COMMON_IMPLEMENTED */

/* ======================================================================
 * Implementation of plateau_delaunay.h
 * ====================================================================== */
#include <float.h>
/* PLATEAU_SNPRINTF(buffer, size, format, ...) writes the report's messages
 * (formats %s, %.Ns, %ld, %g); it never prints. */
#ifndef PLATEAU_SNPRINTF
#ifdef PLATEAU_FREESTANDING
#error "plateau: PLATEAU_FREESTANDING needs PLATEAU_SNPRINTF (an snprintf with %s, %ld and %g)"
#endif
#include <stdio.h>
#define PLATEAU_SNPRINTF snprintf
#endif
#ifndef PLATEAU_FREESTANDING
#include <string.h> /* memcpy, memset */
#endif

#if defined(FLT_EVAL_METHOD) && (FLT_EVAL_METHOD == 1 || FLT_EVAL_METHOD == 2)
#error "plateau_delaunay.h needs double arithmetic rounded to binary64 (x87 extended precision breaks the exact predicates): compile with -msse2 -mfpmath=sse"
#endif

/* Two-product needs the exact error of a product.  With a hardware fused
 * multiply-add it is fma(a, b, -a*b), which no compiler contraction can
 * disturb; without one it is Dekker's splitting, and then no compiler can
 * contract anything into an FMA either. */
#if defined(__FMA__) || defined(FP_FAST_FMA) || defined(__FP_FAST_FMA) || \
    defined(__ARM_FEATURE_FMA)
#define PLATEAU__DT_HAVE_FMA 1
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU__DT_FMA(a, b, c) __builtin_fma(a, b, c)
#else
#define PLATEAU__DT_FMA(a, b, c) fma(a, b, c)
#endif
#else
#define PLATEAU__DT_HAVE_FMA 0
#endif

#define PLATEAU__DT_GHOST 0 /* internal id of the vertex at infinity */
/* next and previous half-edge of the same triangle, in arithmetic rather
 * than a branch on e mod 3 (which is random: mispredicted a third of the
 * time on the hot paths) */
#define PLATEAU__DT_NEXT(e) ((e) + 1 - 3 * ((e) % 3 == 2))
#define PLATEAU__DT_PREV(e) ((e) - 1 + 3 * ((e) % 3 == 0))
/* (k + 1) mod 3 and (k + 2) mod 3 for a corner k, by look-up: compilers
 * turn the arithmetic form into a switch on k where k is a loop variable */
static const signed char plateau__dt_k_next[3] = {1, 2, 0};
static const signed char plateau__dt_k_prev[3] = {2, 0, 1};
/* scaled coordinates lie below 2^PLATEAU__DT_SCALE_EXP in magnitude */
#define PLATEAU__DT_SCALE_EXP 200

/* ---- Powers of two, built from their bits (no libm) ------------------- */
static double plateau__dt_pow2(int k) /* -1022 <= k <= 1023 */
{
    uint64_t bits = (uint64_t)(k + 1023) << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* The binary exponent e with 2^(e-1) <= x < 2^e, for finite x > 0 (out of
 * line: the scaling and the exact slow paths call it, never the filters). */
static PLATEAU__NOINLINE int plateau__dt_exponent(double x)
{
    uint64_t bits;
    int e;
    memcpy(&bits, &x, sizeof bits);
    e = (int)((bits >> 52) & 0x7ff);
    if (e == 0) { /* subnormal: count from the top set bit */
        uint64_t m = bits & ((((uint64_t)1) << 52) - 1);
        e = -1022 - 52;
        while (m) { m >>= 1; e++; }
        return e + 1;
    }
    return e - 1022;
}

/* x * 2^s exactly (barring underflow), for |s| up to about 2200. */
static double plateau__dt_ldexp(double x, int s)
{
    int h = s / 2;
    return x * plateau__dt_pow2(h) * plateau__dt_pow2(s - h);
}

/* The shift s that brings max |coordinate| m (> 0) just below
 * 2^PLATEAU__DT_SCALE_EXP. */
static int plateau__dt_shift_for(double m)
{
    return PLATEAU__DT_SCALE_EXP - plateau__dt_exponent(m);
}

/* ---- Exact arithmetic (Shewchuk 1997, sections 2-3) --------------------
 * An expansion is an array of doubles, non-overlapping and increasing in
 * magnitude, whose exact sum is the value; its sign is the sign of its last
 * (largest) component.  Zero components are dropped; zero is [0]. */

/* Two-Sum (Knuth): x + y = a + b exactly, x = fl(a + b). */
static inline void plateau__dt_two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bv = s - a;
    double av = s - bv;
    *x = s;
    *y = (a - av) + (b - bv);
}

/* Two-Diff: x + y = a - b exactly. */
static inline void plateau__dt_two_diff(double a, double b, double *x, double *y)
{
    double s = a - b;
    double bv = a - s;
    double av = s + bv;
    *x = s;
    *y = (a - av) + (bv - b);
}

/* Dekker's splitter 2^27 + 1 (Shewchuk 1997, Split). */
#define PLATEAU__DT_SPLITTER 134217729.0

/* Two-Product: x + y = a * b exactly (no overflow or underflow assumed). */
static inline void plateau__dt_two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
#if PLATEAU__DT_HAVE_FMA
    *y = PLATEAU__DT_FMA(a, b, -p);
#else
    /* Dekker's split: a = ahi + alo with both halves of at most 26 bits,
     * so every partial product below is exact. */
    double c, big, ahi, alo, bhi, blo;
    c = PLATEAU__DT_SPLITTER * a;
    big = c - a;
    ahi = c - big;
    alo = a - ahi;
    c = PLATEAU__DT_SPLITTER * b;
    big = c - b;
    bhi = c - big;
    blo = b - bhi;
    *y = alo * blo - (((p - ahi * bhi) - alo * bhi) - ahi * blo);
#endif
    *x = p;
}

/* The exact difference a - b as an expansion of 1 or 2 components. */
static int plateau__dt_diff_expansion(double a, double b, double *e)
{
    double x, y;
    plateau__dt_two_diff(a, b, &x, &y);
    if (y == 0.0) { e[0] = x; return 1; }
    e[0] = y;
    e[1] = x;
    return 2;
}

/* h = e + f (Shewchuk's Fast-Expansion-Sum with zero elimination, using
 * Two-Sum at every step).  h has room for elen + flen components. */
static int plateau__dt_sum(int elen, const double *e, int flen, const double *f, double *h)
{
    int ei = 0, fi = 0, hn = 0;
    double q, g, hh;
    /* merge by increasing magnitude, adding as we go */
    if (PLATEAU_FABS(e[0]) < PLATEAU_FABS(f[0])) q = e[ei++];
    else q = f[fi++];
    while (ei < elen || fi < flen) {
        if (fi >= flen || (ei < elen && PLATEAU_FABS(e[ei]) < PLATEAU_FABS(f[fi])))
            g = e[ei++];
        else
            g = f[fi++];
        plateau__dt_two_sum(q, g, &q, &hh);
        if (hh != 0.0) h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0) h[hn++] = q;
    return hn;
}

/* h = e * b (Scale-Expansion with zero elimination); room for 2 * elen. */
static int plateau__dt_scale(int elen, const double *e, double b, double *h)
{
    int i, hn = 0;
    double q, hh, p1, p0, s;
    plateau__dt_two_product(e[0], b, &q, &hh);
    if (hh != 0.0) h[hn++] = hh;
    for (i = 1; i < elen; i++) {
        plateau__dt_two_product(e[i], b, &p1, &p0);
        plateau__dt_two_sum(q, p0, &s, &hh);
        if (hh != 0.0) h[hn++] = hh;
        plateau__dt_two_sum(p1, s, &q, &hh);
        if (hh != 0.0) h[hn++] = hh;
    }
    if (q != 0.0 || hn == 0) h[hn++] = q;
    return hn;
}

/* h = e * f.  h and work have room for 2 * elen * flen, s for 2 * elen. */
static int plateau__dt_mul(int elen, const double *e, int flen, const double *f, double *h,
                           double *work, double *s)
{
    int j, hn, sn;
    double *acc = (flen & 1) ? h : work, *other = (flen & 1) ? work : h, *tmp;
    /* accumulate in the two buffers alternately, ending in h */
    hn = plateau__dt_scale(elen, e, f[0], acc);
    for (j = 1; j < flen; j++) {
        sn = plateau__dt_scale(elen, e, f[j], s);
        hn = plateau__dt_sum(hn, acc, sn, s, other);
        tmp = acc;
        acc = other;
        other = tmp;
    }
    return hn;
}

static void plateau__dt_negate(int n, double *e)
{
    int i;
    for (i = 0; i < n; i++) e[i] = -e[i];
}

/* ---- Exact evaluation at any magnitude ---------------------------------
 * The predicates are homogeneous in the coordinate differences (degree 2
 * and 4), so their sign does not change when every difference is
 * multiplied by one power of two 2^s.  Every component of the exact
 * differences is an integer multiple of 2^lo and below 2^hi in magnitude
 * (lo, hi from the actual operands); every product of k of them is then a
 * multiple of 2^(k lo) below 2^(k hi), and Two-Sum / Two-Product are exact
 * as long as those stay inside the binary64 range (Shewchuk 1997, section
 * 2, assumes neither underflow nor overflow).  For a degree-k predicate the
 * expansions are used with s chosen so that k (lo + s) >= -1074 (the
 * smallest subnormal: no product loses a bit) and k (hi + s) + 2k < 1023
 * (no sum overflows; Dekker's split stays below 2^996), which is possible
 * when hi - lo <= 1045 (orient) or 520 (in-circle).  Wider mixtures
 * (a 1e-150 cluster and a 1e150 point in one in-circle test) are
 * evaluated with integers: every double is an integer multiple of 2^-1074,
 * so the determinant of the coordinates divided by their smallest power of
 * two is an exact integer computation. */

/* A finite nonzero double as |x| = m 2^e with m odd (m < 2^53): the
 * fields of the binary64 encoding, the trailing zeros shifted out (at most
 * 52 steps). */
static void plateau__dt_odd_mantissa(double x, uint64_t *m, int *e)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    *e = (int)((bits >> 52) & 0x7ff);
    *m = bits & ((((uint64_t)1) << 52) - 1);
    if (*e) {
        *m |= ((uint64_t)1) << 52;
        *e -= 1075;
    } else {
        *e = -1074;
    }
    while (!(*m & 1)) { *m >>= 1; (*e)++; }
}

/* Top and bottom bit of a finite nonzero double: 2^(top-1) <= |x| < 2^top
 * and x is an odd multiple of 2^low. */
static void plateau__dt_bits(double x, int *top, int *low)
{
    uint64_t m;
    plateau__dt_odd_mantissa(x, &m, low);
    *top = plateau__dt_exponent(PLATEAU_FABS(x));
}

/* The shift s that brings n expansion components into the safe window of
 * a degree-`degree` predicate; 0 with *ok = 1 when all are zero; *ok = 0
 * when no shift fits (then the integer path is needed). */
static int plateau__dt_window_shift(const double *e, int n, int degree, int *ok)
{
    int i, hi = -100000, lo = 100000, slo, shi;
    for (i = 0; i < n; i++) {
        int t, l;
        if (e[i] == 0) continue;
        plateau__dt_bits(e[i], &t, &l);
        if (t > hi) hi = t;
        if (l < lo) lo = l;
    }
    *ok = 1;
    if (hi < lo) return 0;
    if (degree == 2) { slo = -537 - lo; shi = 508 - hi; }
    else { slo = -268 - lo; shi = 252 - hi; }
    if (slo > shi) { *ok = 0; return 0; }
    return slo + (shi - slo) / 2;
}

/* Signed big integers (sign and magnitude, 32-bit limbs): enough for the
 * in-circle determinant of any finite doubles (coordinates span at most
 * 2098 bits over 2^-1074, so the determinant has at most 8400 bits). */
/* Out of line (PLATEAU__NOINLINE): the slow paths below, and helpers
 * called from many places on them. */
#define PLATEAU__DT_BIG_LIMBS 272
typedef struct plateau__dt_big {
    int n;   /* limbs used, no leading zero limb; 0 for zero */
    int neg; /* 1 if negative */
    uint32_t d[PLATEAU__DT_BIG_LIMBS];
} plateau__dt_big;

/* r = x / 2^low exactly (x must be a multiple of 2^low). */
static PLATEAU__NOINLINE void plateau__dt_big_from(double x, int low, plateau__dt_big *r)
{
    uint64_t m, part;
    int e, sh, w, i;
    r->n = 0;
    r->neg = x < 0;
    if (x == 0) return;
    plateau__dt_odd_mantissa(x, &m, &e); /* |x| = m 2^e with m odd, so e >= low */
    sh = e - low;
    w = sh / 32;
    sh %= 32;
    for (i = 0; i < w; i++) r->d[i] = 0;
    part = m << sh; /* the low 64 bits of m 2^sh; m < 2^53, sh < 32 */
    r->d[w] = (uint32_t)part;
    r->d[w + 1] = (uint32_t)(part >> 32);
    r->d[w + 2] = sh ? (uint32_t)(m >> (64 - sh)) : 0;
    r->n = w + 3;
    while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
}

static int plateau__dt_big_cmp_mag(const plateau__dt_big *a, const plateau__dt_big *b)
{
    int i;
    if (a->n != b->n) return a->n < b->n ? -1 : 1;
    for (i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* r = a + b (r may be a or b); bsign = 1 adds b, -1 subtracts it. */
static void plateau__dt_big_add(const plateau__dt_big *a, const plateau__dt_big *b, int bsign,
                                plateau__dt_big *r)
{
    int bneg = b->neg ^ (bsign < 0), i, n;
    if (b->n == 0) { if (r != a) *r = *a; return; }
    if (a->n == 0) { if (r != b) *r = *b; r->neg = bneg; return; }
    if (a->neg == bneg) { /* magnitudes add */
        uint64_t c = 0;
        n = a->n > b->n ? a->n : b->n;
        for (i = 0; i < n; i++) {
            c += (uint64_t)(i < a->n ? a->d[i] : 0) + (uint64_t)(i < b->n ? b->d[i] : 0);
            r->d[i] = (uint32_t)c;
            c >>= 32;
        }
        r->n = n;
        if (c) r->d[r->n++] = (uint32_t)c;
        r->neg = bneg;
    } else { /* magnitudes subtract, larger minus smaller */
        const plateau__dt_big *x = a, *y = b;
        int neg = a->neg, cmp = plateau__dt_big_cmp_mag(a, b);
        int64_t brw = 0;
        if (cmp == 0) { r->n = 0; r->neg = 0; return; }
        if (cmp < 0) { x = b; y = a; neg = bneg; }
        n = x->n;
        for (i = 0; i < n; i++) {
            int64_t t = (int64_t)x->d[i] - (int64_t)(i < y->n ? y->d[i] : 0) - brw;
            brw = t < 0;
            r->d[i] = (uint32_t)(t + (brw ? ((int64_t)1 << 32) : 0));
        }
        r->n = n;
        r->neg = neg;
        while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
    }
}

/* r = a * b (r distinct from a and b). */
static void plateau__dt_big_mul(const plateau__dt_big *a, const plateau__dt_big *b,
                                plateau__dt_big *r)
{
    int i, j;
    r->neg = a->neg ^ b->neg;
    if (a->n == 0 || b->n == 0) { r->n = 0; r->neg = 0; return; }
    r->n = a->n + b->n;
    PLATEAU_ASSERT(r->n <= PLATEAU__DT_BIG_LIMBS);
    for (i = 0; i < r->n; i++) r->d[i] = 0;
    for (i = 0; i < a->n; i++) {
        uint64_t c = 0;
        for (j = 0; j < b->n; j++) {
            c += (uint64_t)a->d[i] * b->d[j] + r->d[i + j];
            r->d[i + j] = (uint32_t)c;
            c >>= 32;
        }
        r->d[i + b->n] = (uint32_t)c;
    }
    while (r->n > 0 && r->d[r->n - 1] == 0) r->n--;
}

/* The smallest bit among n points' coordinates (0 if all are zero). */
static int plateau__dt_low_bit(const double *const *p, int n)
{
    int i, k, low = 100000;
    for (i = 0; i < n; i++)
        for (k = 0; k < 2; k++)
            if (p[i][k] != 0) {
                int t, l;
                plateau__dt_bits(p[i][k], &t, &l);
                if (l < low) low = l;
            }
    return low == 100000 ? 0 : low;
}

/* Sign of the orientation determinant of any finite doubles, in integers. */
static int plateau__dt_orient_big(const double *a, const double *b, const double *c)
{
    const double *p[3];
    plateau__dt_big u, v, w, l, r;
    int low;
    p[0] = a; p[1] = b; p[2] = c;
    low = plateau__dt_low_bit(p, 3);
    plateau__dt_big_from(a[0], low, &u);
    plateau__dt_big_from(c[0], low, &w);
    plateau__dt_big_add(&u, &w, -1, &u); /* ax - cx */
    plateau__dt_big_from(b[1], low, &v);
    plateau__dt_big_from(c[1], low, &w);
    plateau__dt_big_add(&v, &w, -1, &v); /* by - cy */
    plateau__dt_big_mul(&u, &v, &l);
    plateau__dt_big_from(a[1], low, &u);
    plateau__dt_big_add(&u, &w, -1, &u); /* ay - cy */
    plateau__dt_big_from(b[0], low, &v);
    plateau__dt_big_from(c[0], low, &w);
    plateau__dt_big_add(&v, &w, -1, &v); /* bx - cx */
    plateau__dt_big_mul(&u, &v, &r);
    plateau__dt_big_add(&l, &r, -1, &l);
    return l.n == 0 ? 0 : (l.neg ? -1 : 1);
}

/* Sign of the lifted in-circle determinant of any finite doubles, in
 * integers (about 13 KB of stack). */
static int plateau__dt_incircle_big(const double *a, const double *b, const double *c,
                                    const double *d)
{
    const double *p[4];
    plateau__dt_big dx[3], dy[3], q, t1, t2, lift, cross, det;
    int low, i;
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    low = plateau__dt_low_bit(p, 4);
    for (i = 0; i < 3; i++) {
        plateau__dt_big_from(p[i][0], low, &dx[i]);
        plateau__dt_big_from(d[0], low, &q);
        plateau__dt_big_add(&dx[i], &q, -1, &dx[i]);
        plateau__dt_big_from(p[i][1], low, &dy[i]);
        plateau__dt_big_from(d[1], low, &q);
        plateau__dt_big_add(&dy[i], &q, -1, &dy[i]);
    }
    det.n = 0;
    det.neg = 0;
    for (i = 0; i < 3; i++) { /* lift_i * (dx_j dy_k - dx_k dy_j), (i, j, k) cyclic */
        int j = (i + 1) % 3, k = (i + 2) % 3;
        plateau__dt_big_mul(&dx[i], &dx[i], &t1);
        plateau__dt_big_mul(&dy[i], &dy[i], &t2);
        plateau__dt_big_add(&t1, &t2, 1, &lift);
        plateau__dt_big_mul(&dx[j], &dy[k], &t1);
        plateau__dt_big_mul(&dx[k], &dy[j], &t2);
        plateau__dt_big_add(&t1, &t2, -1, &cross);
        plateau__dt_big_mul(&lift, &cross, &t1);
        plateau__dt_big_add(&det, &t1, 1, &det);
    }
    return det.n == 0 ? 0 : (det.neg ? -1 : 1);
}

static void plateau__dt_shift_all(double *e, int n, int s)
{
    int i;
    if (s == 0) return;
    for (i = 0; i < n; i++) e[i] = plateau__dt_ldexp(e[i], s);
}

/* (ax - cx)(by - cy) - (ay - cy)(bx - cx) exactly; returns a double of the
 * right sign (the largest component of the exact expansion). */
static double plateau__dt_orient_exact(const double *a, const double *b, const double *c)
{
    double df[8], *acx = df, *bcy = df + 2, *acy = df + 4, *bcx = df + 6;
    double p1[8], p2[8], w[8], s[4], det[16];
    int nacx, nbcy, nacy, nbcx, n1, n2, n, ok, sh;
    memset(df, 0, sizeof df);
    nacx = plateau__dt_diff_expansion(a[0], c[0], acx);
    nbcy = plateau__dt_diff_expansion(b[1], c[1], bcy);
    nacy = plateau__dt_diff_expansion(a[1], c[1], acy);
    nbcx = plateau__dt_diff_expansion(b[0], c[0], bcx);
    sh = plateau__dt_window_shift(df, 8, 2, &ok);
    if (!ok) return (double)plateau__dt_orient_big(a, b, c);
    plateau__dt_shift_all(df, 8, sh);
    n1 = plateau__dt_mul(nacx, acx, nbcy, bcy, p1, w, s);
    n2 = plateau__dt_mul(nacy, acy, nbcx, bcx, p2, w, s);
    plateau__dt_negate(n2, p2);
    n = plateau__dt_sum(n1, p1, n2, p2, det);
    return det[n - 1];
}

/* The lifted in-circle determinant exactly (about 33 KB of stack). */
static double plateau__dt_incircle_exact(const double *a, const double *b, const double *c,
                                         const double *d)
{
    double dx[3][2], dy[3][2], df[12];
    int nx[3], ny[3];
    double p1[8], p2[8], cross[16], l1[8], l2[8], lift[16];
    double term[512], acc[1536], acc2[1536], w[512], s[32];
    const double *pt[3];
    int i, n1, n2, ncross, nlift, nterm, nacc = 0, ok, sh;
    pt[0] = a; pt[1] = b; pt[2] = c;
    memset(dx, 0, sizeof dx);
    memset(dy, 0, sizeof dy);
    for (i = 0; i < 3; i++) {
        nx[i] = plateau__dt_diff_expansion(pt[i][0], d[0], dx[i]);
        ny[i] = plateau__dt_diff_expansion(pt[i][1], d[1], dy[i]);
    }
    for (i = 0; i < 3; i++) { /* shift all twelve components together */
        df[4 * i] = dx[i][0]; df[4 * i + 1] = dx[i][1];
        df[4 * i + 2] = dy[i][0]; df[4 * i + 3] = dy[i][1];
    }
    sh = plateau__dt_window_shift(df, 12, 4, &ok);
    if (!ok) return (double)plateau__dt_incircle_big(a, b, c, d);
    plateau__dt_shift_all(df, 12, sh);
    for (i = 0; i < 3; i++) {
        dx[i][0] = df[4 * i]; dx[i][1] = df[4 * i + 1];
        dy[i][0] = df[4 * i + 2]; dy[i][1] = df[4 * i + 3];
    }
    /* det = sum over i of lift_i * (dx_j dy_k - dx_k dy_j), (i, j, k) cyclic */
    for (i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        n1 = plateau__dt_mul(nx[j], dx[j], ny[k], dy[k], p1, w, s);
        n2 = plateau__dt_mul(nx[k], dx[k], ny[j], dy[j], p2, w, s);
        plateau__dt_negate(n2, p2);
        ncross = plateau__dt_sum(n1, p1, n2, p2, cross);
        n1 = plateau__dt_mul(nx[i], dx[i], nx[i], dx[i], l1, w, s);
        n2 = plateau__dt_mul(ny[i], dy[i], ny[i], dy[i], l2, w, s);
        nlift = plateau__dt_sum(n1, l1, n2, l2, lift);
        nterm = plateau__dt_mul(nlift, lift, ncross, cross, term, w, s);
        if (nacc == 0) {
            memcpy(acc, term, (size_t)nterm * sizeof(double));
            nacc = nterm;
        } else {
            nacc = plateau__dt_sum(nacc, acc, nterm, term, acc2);
            memcpy(acc, acc2, (size_t)nacc * sizeof(double));
        }
    }
    return acc[nacc - 1];
}

/* Error-bound constants of the floating-point filters (Shewchuk 1997,
 * section 4.3, with epsilon = 2^-53), and absolute slacks that cover the
 * rounding of products that underflow: each rounding adds at most 2^-1075
 * besides its relative error, and with coordinates below 2^200 (phase 1)
 * the in-circle formula multiplies such an error by at most 2^404, so its
 * slack is 1e-180 (about 2^-597) rather than the orientation's 1e-300. */
#define PLATEAU__DT_EPS 1.1102230246251565404e-16
#define PLATEAU__DT_CCW_BOUND ((3.0 + 16.0 * PLATEAU__DT_EPS) * PLATEAU__DT_EPS)
#define PLATEAU__DT_ICC_BOUND ((10.0 + 96.0 * PLATEAU__DT_EPS) * PLATEAU__DT_EPS)
#define PLATEAU__DT_TINY 1e-300
#define PLATEAU__DT_ICC_TINY 1e-180

/* A fast exact case (square grids, integer coordinates): when every
 * coordinate difference is exact and all of them are integer multiples of
 * 2^lo smaller than 2^hi with (hi - lo) small enough, every product and sum
 * of the floating-point formula is an integer below 2^53 (times a power of
 * two): the filter's value is then exact, zero included.  `degree` is 2 or
 * 4; n differences in dv, their rounding errors in tail. */
static int plateau__dt_exact_small(const double *dv, const double *tail, int n, int degree)
{
    int i, lo = 100000, hi = -100000;
    for (i = 0; i < n; i++) {
        uint64_t bits, m;
        int e, l, h;
        if (tail[i] != 0) return 0;
        if (dv[i] == 0) continue;
        memcpy(&bits, &dv[i], sizeof bits);
        e = (int)((bits >> 52) & 0x7ff);
        m = bits & ((((uint64_t)1) << 52) - 1);
        if (e) {
            m |= ((uint64_t)1) << 52;
            e -= 1075;
        } else {
            e = -1074;
        }
#if defined(__GNUC__) || defined(__clang__)
        l = e + __builtin_ctzll(m);
        h = e + 64 - __builtin_clzll(m);
#else
        l = e;
        h = e;
        while (!(m & 1)) { m >>= 1; l++; }
        while (m) { m >>= 1; h++; }
        h += l - e;
#endif
        if (l < lo) lo = l;
        if (h > hi) hi = h;
    }
    if (hi < lo) return 1; /* all zero */
    return degree * (hi - lo) + degree <= 53 && degree * lo >= -1000;
}

/* the rounding error of x = a - b */
static inline double plateau__dt_diff_tail(double a, double b, double x)
{
    double bv = a - x, av = x + bv;
    return (a - av) + (bv - b);
}

/* The slow paths, out of line so that the filters stay small where they
 * are inlined: the small-integer case, else the expansions.  `det` is the
 * filter's floating-point value. */
static PLATEAU__COLD PLATEAU__NOINLINE double plateau__dt_orient_slow(const double *a, const double *b,
                                                          const double *c, double det)
{
    double dv[4], tl[4];
    dv[0] = a[0] - c[0]; dv[1] = b[1] - c[1]; dv[2] = a[1] - c[1]; dv[3] = b[0] - c[0];
    tl[0] = plateau__dt_diff_tail(a[0], c[0], dv[0]);
    tl[1] = plateau__dt_diff_tail(b[1], c[1], dv[1]);
    tl[2] = plateau__dt_diff_tail(a[1], c[1], dv[2]);
    tl[3] = plateau__dt_diff_tail(b[0], c[0], dv[3]);
    if (plateau__dt_exact_small(dv, tl, 4, 2)) return det;
    return plateau__dt_orient_exact(a, b, c);
}

static PLATEAU__COLD PLATEAU__NOINLINE double plateau__dt_incircle_slow(const double *a, const double *b,
                                                            const double *c, const double *d,
                                                            double det)
{
    double dv[6], tl[6];
    dv[0] = a[0] - d[0]; dv[1] = a[1] - d[1]; dv[2] = b[0] - d[0];
    dv[3] = b[1] - d[1]; dv[4] = c[0] - d[0]; dv[5] = c[1] - d[1];
    tl[0] = plateau__dt_diff_tail(a[0], d[0], dv[0]);
    tl[1] = plateau__dt_diff_tail(a[1], d[1], dv[1]);
    tl[2] = plateau__dt_diff_tail(b[0], d[0], dv[2]);
    tl[3] = plateau__dt_diff_tail(b[1], d[1], dv[3]);
    tl[4] = plateau__dt_diff_tail(c[0], d[0], dv[4]);
    tl[5] = plateau__dt_diff_tail(c[1], d[1], dv[5]);
    if (plateau__dt_exact_small(dv, tl, 6, 4)) return det;
    return plateau__dt_incircle_exact(a, b, c, d);
}

/* orient2d: > 0 if a, b, c are counter-clockwise, < 0 clockwise, 0 if
 * collinear.  The floating-point value is returned when its sign is
 * certain; otherwise the exact expansion decides. */
static inline double plateau__dt_orient2d(const double *a, const double *b, const double *c)
{
    double detl = (a[0] - c[0]) * (b[1] - c[1]);
    double detr = (a[1] - c[1]) * (b[0] - c[0]);
    double det = detl - detr;
    double bound = PLATEAU__DT_CCW_BOUND * (PLATEAU_FABS(detl) + PLATEAU_FABS(detr)) +
                   PLATEAU__DT_TINY;
    /* one test of |det| (almost always true: well predicted) rather than
     * two of det's sign, which the caller tests again */
    if (PLATEAU_FABS(det) > bound) return det;
    return plateau__dt_orient_slow(a, b, c, det);
}

/* incircle: > 0 if d is inside the circle through a, b, c (counter-
 * clockwise), < 0 outside, 0 on it. */
static inline double plateau__dt_incircle(const double *a, const double *b, const double *c,
                                          const double *d)
{
    double adx = a[0] - d[0], ady = a[1] - d[1];
    double bdx = b[0] - d[0], bdy = b[1] - d[1];
    double cdx = c[0] - d[0], cdy = c[1] - d[1];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double alift = adx * adx + ady * ady;
    double blift = bdx * bdx + bdy * bdy;
    double clift = cdx * cdx + cdy * cdy;
    double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                 clift * (adxbdy - bdxady);
    double perm = (PLATEAU_FABS(bdxcdy) + PLATEAU_FABS(cdxbdy)) * alift +
                  (PLATEAU_FABS(cdxady) + PLATEAU_FABS(adxcdy)) * blift +
                  (PLATEAU_FABS(adxbdy) + PLATEAU_FABS(bdxady)) * clift;
    double bound = PLATEAU__DT_ICC_BOUND * perm + PLATEAU__DT_ICC_TINY;
    if (PLATEAU_FABS(det) > bound) return det;
    return plateau__dt_incircle_slow(a, b, c, d, det);
}

/* ---- The triangulation -------------------------------------------------
 * Triangles t = 0..nt-1 hold vertex ids tv[3t+k] in counter-clockwise
 * order.  Half-edge 3t+k runs from tv[3t+k] to tv[3t+(k+1)%3]; ta[3t+k] is
 * its twin (the same edge in the neighbouring triangle) and tc[3t+k] its
 * constraint flag.  Vertex id 0 is the ghost vertex at infinity: a hull edge
 * (a, b) has a ghost triangle (b, a, 0) on its outer side, so every edge has
 * two triangles and no numeric "super triangle" is needed (the ghost is
 * never given coordinates).  Real vertices have ids 1..nv-1 in insertion
 * order. */
typedef struct plateau__dt {
    plateau_allocator al;
    double *xy;           /* 2 per vertex id (scaled coordinates) */
    plateau_index *vt;    /* a half-edge leaving each vertex, -1 if none */
    plateau_index *outid; /* vertex id -> output vertex index */
    plateau_index nv, cap_v;
    plateau_index *tv, *ta;
    unsigned char *tc;
    plateau_index nt, cap_t;
    plateau_index last;   /* a triangle next to the last insertion */
    plateau_index *stack; /* work list of the flip passes */
    size_t nstack, cap_stack;
    uint32_t walk_rng;
    int shift;            /* coordinates were multiplied by 2^shift */
    int split_crossing;   /* option split_crossing_segments */
    int cons;             /* constraint phase: flags and vt are maintained */
    unsigned char *tin;   /* refinement: 1 for triangles of the domain */
    plateau_index *ts;    /* 3 per triangle: input segment of a constrained
                             half-edge, -1 otherwise (when segments exist) */
    plateau_index *vseg;  /* per vertex: input segment of an added vertex */
    plateau_index ninput; /* vertex ids 1..ninput are input points */
    size_t steiner_left;  /* budget of vertices added at crossings */
    plateau_index *pend;  /* pending segment pieces, pairs */
    plateau_index *estack; /* edges (vertex pairs) to re-test */
    long cur_seg;         /* the input segment being inserted */
    size_t cap_estack;
    size_t npend, cap_pend;
    plateau_dt_error *report;
} plateau__dt;

#define PLATEAU__DT_P(d, v) ((d)->xy + 2 * (size_t)(v))

static PLATEAU__COLD void plateau__dt_set_error(plateau_dt_error *r, long index, const char *msg)
{
    if (!r) return;
    r->index = index;
    PLATEAU_SNPRINTF(r->message, sizeof r->message, "%s", msg);
}

/* Grow an array to hold at least `need` elements (doubling). */
static int plateau__dt_grow(const plateau_allocator *al, void **ptr, size_t *cap, size_t elem,
                            size_t need)
{
    size_t ncap = *cap ? *cap : 16, bytes;
    void *p;
    if (need <= *cap) return 1;
    while (ncap < need) {
        if (ncap > ((size_t)-1) / 4) return 0;
        ncap *= 2;
    }
    bytes = plateau__bytes(ncap, elem);
    if (!bytes) return 0;
    p = plateau__alloc(al, bytes);
    if (!p) return 0;
    if (*ptr && *cap) memcpy(p, *ptr, *cap * elem);
    plateau__free(al, *ptr);
    *ptr = p;
    *cap = ncap;
    return 1;
}

/* Reallocate an array to `cap` elements, keeping the first `keep`. */
static void *plateau__dt_realloc(const plateau_allocator *al, void *old, size_t keep, size_t cap,
                                 size_t elem)
{
    size_t bytes = plateau__bytes(cap, elem);
    void *p = bytes ? plateau__alloc(al, bytes) : NULL;
    if (!p) return NULL;
    if (old && keep) memcpy(p, old, keep * elem);
    plateau__free(al, old);
    return p;
}

/* Room for `more` new triangles. */
static plateau_dt_result plateau__dt_reserve_triangles(plateau__dt *d, plateau_index more)
{
    size_t need = (size_t)d->nt + (size_t)more, keep = 3 * (size_t)d->nt;
    void *p;
    if (need <= (size_t)d->cap_t) return PLATEAU_DT_OK;
    /* the first request is exact (2n + 8 covers every insertion: a
     * triangulation of n points and the ghost vertex has 2n - 2 triangles
     * with the ghost ones), later ones grow by half */
    if (d->cap_t) need = need + need / 2 + 16;
    if (need > (size_t)PLATEAU_INDEX_MAX / 3) return PLATEAU_DT_ERR_OVERFLOW;
    p = plateau__dt_realloc(&d->al, d->tv, keep, 3 * need, sizeof(plateau_index));
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->tv = (plateau_index *)p;
    p = plateau__dt_realloc(&d->al, d->ta, keep, 3 * need, sizeof(plateau_index));
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->ta = (plateau_index *)p;
    p = plateau__dt_realloc(&d->al, d->tc, keep, 3 * need, 1);
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->tc = (unsigned char *)p;
    if (d->tin) {
        p = plateau__dt_realloc(&d->al, d->tin, keep / 3, need, 1);
        if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        d->tin = (unsigned char *)p;
    }
    if (d->ts) {
        p = plateau__dt_realloc(&d->al, d->ts, keep, 3 * need, sizeof(plateau_index));
        if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        d->ts = (plateau_index *)p;
    }
    d->cap_t = (plateau_index)need;
    return PLATEAU_DT_OK;
}

/* Room for `more` new vertices. */
static plateau_dt_result plateau__dt_reserve_vertices(plateau__dt *d, plateau_index more)
{
    size_t need = (size_t)d->nv + (size_t)more, keep = (size_t)d->nv;
    void *p;
    if (need <= (size_t)d->cap_v) return PLATEAU_DT_OK;
    need = need + need / 2 + 16;
    if (need > (size_t)PLATEAU_INDEX_MAX / 2) return PLATEAU_DT_ERR_OVERFLOW;
    p = plateau__dt_realloc(&d->al, d->xy, 2 * keep, 2 * need, sizeof(double));
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->xy = (double *)p;
    p = plateau__dt_realloc(&d->al, d->vt, keep, need, sizeof(plateau_index));
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->vt = (plateau_index *)p;
    p = plateau__dt_realloc(&d->al, d->outid, keep, need, sizeof(plateau_index));
    if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->outid = (plateau_index *)p;
    if (d->vseg) {
        p = plateau__dt_realloc(&d->al, d->vseg, keep, need, sizeof(plateau_index));
        if (!p) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        d->vseg = (plateau_index *)p;
    }
    d->cap_v = (plateau_index)need;
    return PLATEAU_DT_OK;
}

static int plateau__dt_push(plateau__dt *d, plateau_index t)
{
    if (d->nstack == d->cap_stack &&
        !plateau__dt_grow(&d->al, (void **)&d->stack, &d->cap_stack, sizeof(plateau_index),
                          d->nstack + 1))
        return 0;
    d->stack[d->nstack++] = t;
    return 1;
}

static int plateau__dt_is_ghost(const plateau__dt *d, plateau_index t)
{
    const plateau_index *v = d->tv + 3 * (size_t)t;
    return v[0] == PLATEAU__DT_GHOST || v[1] == PLATEAU__DT_GHOST || v[2] == PLATEAU__DT_GHOST;
}

static void plateau__dt_set_tri(plateau__dt *d, plateau_index t, plateau_index a, plateau_index b,
                                plateau_index c)
{
    plateau_index *v = d->tv + 3 * (size_t)t;
    v[0] = a;
    v[1] = b;
    v[2] = c;
}

static void plateau__dt_link(plateau__dt *d, plateau_index e, plateau_index f)
{
    d->ta[e] = f;
    d->ta[f] = e;
}

/* Lexicographic order of two distinct points: 1 if a > b. */
static int plateau__dt_lex_greater(const double *a, const double *b)
{
    return a[0] > b[0] || (a[0] == b[0] && a[1] > b[1]);
}

/* In-circle test with symbolic perturbation ("simulation of simplicity"
 * on the lifting map): each point's height x^2 + y^2 is raised by an
 * infinitesimal, larger for lexicographically larger points.  Exactly
 * co-circular configurations (a square grid) are then decided by a fixed
 * rule that depends on coordinates only, so the triangulation is unique:
 * the same triangle set for every insertion order.  For a, b, c counter-
 * clockwise: 1 if d is (perturbed) inside, -1 if outside.  Cold: only
 * exact ties (det == 0) reach it. */
static PLATEAU__COLD int plateau__dt_incircle_tie(const plateau__dt *d, plateau_index a, plateau_index b,
                                                  plateau_index c, plateau_index e)
{
    const double *pa = PLATEAU__DT_P(d, a), *pb = PLATEAU__DT_P(d, b);
    const double *pc = PLATEAU__DT_P(d, c), *pe = PLATEAU__DT_P(d, e);
    const double *pt[4];
    int order[4], i, j;
    /* d det / d height_i is + orient(b,c,e), - orient(a,c,e), + orient(a,b,e),
     * - orient(a,b,c) for i = a, b, c, e; the most perturbed point whose
     * cofactor is non-zero decides. */
    pt[0] = pa; pt[1] = pb; pt[2] = pc; pt[3] = pe;
    for (i = 0; i < 4; i++) order[i] = i;
    for (i = 1; i < 4; i++) { /* insertion sort, largest first */
        int k = order[i];
        for (j = i; j > 0 && plateau__dt_lex_greater(pt[k], pt[order[j - 1]]); j--)
            order[j] = order[j - 1];
        order[j] = k;
    }
    for (i = 0; i < 4; i++) {
        double o;
        switch (order[i]) {
        case 0: o = plateau__dt_orient2d(pb, pc, pe); break;
        case 1: o = -plateau__dt_orient2d(pa, pc, pe); break;
        case 2: o = plateau__dt_orient2d(pa, pb, pe); break;
        default: o = -plateau__dt_orient2d(pa, pb, pc); break;
        }
        if (o > 0) return 1;
        if (o < 0) return -1;
    }
    return -1; /* four collinear points: not reachable from a real triangle */
}

static int plateau__dt_incircle_sos(const plateau__dt *d, plateau_index a, plateau_index b,
                                    plateau_index c, plateau_index e)
{
    double det = plateau__dt_incircle(PLATEAU__DT_P(d, a), PLATEAU__DT_P(d, b),
                                      PLATEAU__DT_P(d, c), PLATEAU__DT_P(d, e));
    if (det > 0) return 1;
    if (det < 0) return -1;
    return plateau__dt_incircle_tie(d, a, b, c, e);
}

/* ---- Local operations -------------------------------------------------
 * While the points are inserted (d->cons == 0) no edge is constrained and
 * nobody needs a half-edge per vertex, so the flags and d->vt are left
 * alone there; they are set up before the segments are inserted. */

static int plateau__dt_push2(plateau__dt *d, plateau_index t1, plateau_index t2)
{
    if (d->nstack + 2 > d->cap_stack &&
        !plateau__dt_grow(&d->al, (void **)&d->stack, &d->cap_stack, sizeof(plateau_index),
                          d->nstack + 2))
        return 0;
    d->stack[d->nstack++] = t1;
    d->stack[d->nstack++] = t2;
    return 1;
}

/* Split triangle t = (a, b, c) at the new vertex p into (p, a, b),
 * (p, b, c), (p, c, a); the first reuses t.  Each new triangle has p at
 * corner 0 and is pushed for the flip pass. */
static int plateau__dt_split_triangle(plateau__dt *d, plateau_index t, plateau_index p)
{
    plateau_index *tv = d->tv, *ta = d->ta;
    plateau_index t1 = t, t2 = d->nt, t3 = d->nt + 1;
    plateau_index a = tv[3 * t], b = tv[3 * t + 1], c = tv[3 * t + 2];
    plateau_index A0 = ta[3 * t], A1 = ta[3 * t + 1], A2 = ta[3 * t + 2];
    d->nt += 2;
    tv[3 * t1] = p; tv[3 * t1 + 1] = a; tv[3 * t1 + 2] = b;
    tv[3 * t2] = p; tv[3 * t2 + 1] = b; tv[3 * t2 + 2] = c;
    tv[3 * t3] = p; tv[3 * t3 + 1] = c; tv[3 * t3 + 2] = a;
    ta[3 * t1] = 3 * t3 + 2; ta[3 * t3 + 2] = 3 * t1;
    ta[3 * t1 + 2] = 3 * t2; ta[3 * t2] = 3 * t1 + 2;
    ta[3 * t2 + 2] = 3 * t3; ta[3 * t3] = 3 * t2 + 2;
    ta[3 * t1 + 1] = A0; ta[A0] = 3 * t1 + 1;
    ta[3 * t2 + 1] = A1; ta[A1] = 3 * t2 + 1;
    ta[3 * t3 + 1] = A2; ta[A2] = 3 * t3 + 1;
    if (d->cons) {
        unsigned char *tc = d->tc;
        unsigned char C0 = tc[3 * t], C1 = tc[3 * t + 1], C2 = tc[3 * t + 2];
        memset(tc + 3 * (size_t)t1, 0, 3);
        memset(tc + 3 * (size_t)t2, 0, 3);
        memset(tc + 3 * (size_t)t3, 0, 3);
        tc[3 * t1 + 1] = C0;
        tc[3 * t2 + 1] = C1;
        tc[3 * t3 + 1] = C2;
        if (d->ts) {
            plateau_index *ts = d->ts, S0 = ts[3 * t], S1 = ts[3 * t + 1], S2 = ts[3 * t + 2];
            int k;
            for (k = 0; k < 3; k++) ts[3 * t1 + k] = ts[3 * t2 + k] = ts[3 * t3 + k] = -1;
            ts[3 * t1 + 1] = S0;
            ts[3 * t2 + 1] = S1;
            ts[3 * t3 + 1] = S2;
        }
        if (d->tin) d->tin[t2] = d->tin[t3] = d->tin[t1];
        d->vt[p] = 3 * t1;
        d->vt[a] = 3 * t1 + 1;
        d->vt[b] = 3 * t2 + 1;
        d->vt[c] = 3 * t3 + 1;
    }
    d->nstack = 0;
    return plateau__dt_push2(d, t1, t2) && plateau__dt_push(d, t3);
}

/* Split the edge e = (a, b) of triangle t = (a, b, c), whose twin lies in
 * n = (b, a, dd), at the new vertex p lying on it: four triangles
 * (p, b, c), (p, c, a), (p, a, dd), (p, dd, b), p at corner 0.  A
 * constrained edge stays constrained in both halves. */
static int plateau__dt_split_edge(plateau__dt *d, plateau_index e, plateau_index p)
{
    plateau_index *tv = d->tv, *ta = d->ta;
    plateau_index t = e / 3, h = ta[e], n = h / 3;
    plateau_index eb = PLATEAU__DT_NEXT(e), ec = PLATEAU__DT_PREV(e);
    plateau_index hb = PLATEAU__DT_NEXT(h), hd = PLATEAU__DT_PREV(h);
    plateau_index a = tv[e], b = tv[eb], c = tv[ec], dd = tv[hd];
    plateau_index Tbc = ta[eb], Tca = ta[ec], Tad = ta[hb], Tdb = ta[hd];
    plateau_index t1 = t, t2 = d->nt, t3 = n, t4 = d->nt + 1;
    unsigned char Cab = 0, Cbc = 0, Cca = 0, Cad = 0, Cdb = 0;
    plateau_index Sab = -1, Sbc = -1, Sca = -1, Sad = -1, Sdb = -1;
    if (d->cons) {
        unsigned char *tc = d->tc;
        Cab = tc[e]; Cbc = tc[eb]; Cca = tc[ec]; Cad = tc[hb]; Cdb = tc[hd];
        if (d->ts) {
            Sab = d->ts[e]; Sbc = d->ts[eb]; Sca = d->ts[ec]; Sad = d->ts[hb]; Sdb = d->ts[hd];
        }
    }
    d->nt += 2;
    plateau__dt_set_tri(d, t1, p, b, c);
    plateau__dt_set_tri(d, t2, p, c, a);
    plateau__dt_set_tri(d, t3, p, a, dd);
    plateau__dt_set_tri(d, t4, p, dd, b);
    plateau__dt_link(d, 3 * t1, 3 * t4 + 2);
    plateau__dt_link(d, 3 * t1 + 2, 3 * t2);
    plateau__dt_link(d, 3 * t2 + 2, 3 * t3);
    plateau__dt_link(d, 3 * t3 + 2, 3 * t4);
    plateau__dt_link(d, 3 * t1 + 1, Tbc);
    plateau__dt_link(d, 3 * t2 + 1, Tca);
    plateau__dt_link(d, 3 * t3 + 1, Tad);
    plateau__dt_link(d, 3 * t4 + 1, Tdb);
    if (d->cons) {
        unsigned char *tc = d->tc;
        tc[3 * t1] = Cab; tc[3 * t1 + 1] = Cbc; tc[3 * t1 + 2] = 0;
        tc[3 * t2] = 0;   tc[3 * t2 + 1] = Cca; tc[3 * t2 + 2] = Cab;
        tc[3 * t3] = Cab; tc[3 * t3 + 1] = Cad; tc[3 * t3 + 2] = 0;
        tc[3 * t4] = 0;   tc[3 * t4 + 1] = Cdb; tc[3 * t4 + 2] = Cab;
        if (d->ts) {
            plateau_index *ts = d->ts;
            ts[3 * t1] = Sab; ts[3 * t1 + 1] = Sbc; ts[3 * t1 + 2] = -1;
            ts[3 * t2] = -1;  ts[3 * t2 + 1] = Sca; ts[3 * t2 + 2] = Sab;
            ts[3 * t3] = Sab; ts[3 * t3 + 1] = Sad; ts[3 * t3 + 2] = -1;
            ts[3 * t4] = -1;  ts[3 * t4 + 1] = Sdb; ts[3 * t4 + 2] = Sab;
        }
        if (d->tin) {
            d->tin[t2] = d->tin[t1];
            d->tin[t4] = d->tin[t3];
        }
        d->vt[p] = 3 * t1;
        d->vt[b] = 3 * t1 + 1;
        d->vt[c] = 3 * t2 + 1;
        d->vt[a] = 3 * t3 + 1;
        d->vt[dd] = 3 * t4 + 1;
    }
    d->nstack = 0;
    return plateau__dt_push2(d, t1, t2) && plateau__dt_push2(d, t3, t4);
}

/* Flip the edge e = (a, b) of t = (a, b, c) whose twin lies in n = (b, a, dd):
 * afterwards t = (c, a, dd) and n = (c, dd, b), with c at corner 0 of both
 * and the new edge (c, dd) as half-edges 3t+2 and 3n. */
static void plateau__dt_flip(plateau__dt *d, plateau_index e)
{
    plateau_index *tv = d->tv, *ta = d->ta;
    plateau_index t = e / 3, h = ta[e], n = h / 3;
    plateau_index eb = PLATEAU__DT_NEXT(e), ec = PLATEAU__DT_PREV(e);
    plateau_index hb = PLATEAU__DT_NEXT(h), hd = PLATEAU__DT_PREV(h);
    plateau_index a = tv[e], b = tv[eb], c = tv[ec], dd = tv[hd];
    plateau_index Tca = ta[ec], Tbc = ta[eb], Tad = ta[hb], Tdb = ta[hd];
    unsigned char Cca = 0, Cbc = 0, Cad = 0, Cdb = 0;
    plateau_index Sca = -1, Sbc = -1, Sad = -1, Sdb = -1;
    if (d->cons) {
        unsigned char *tc = d->tc;
        Cca = tc[ec]; Cbc = tc[eb]; Cad = tc[hb]; Cdb = tc[hd];
        if (d->ts) {
            Sca = d->ts[ec]; Sbc = d->ts[eb]; Sad = d->ts[hb]; Sdb = d->ts[hd];
        }
    }
    tv[3 * t] = c; tv[3 * t + 1] = a; tv[3 * t + 2] = dd;
    tv[3 * n] = c; tv[3 * n + 1] = dd; tv[3 * n + 2] = b;
    ta[3 * t] = Tca; ta[Tca] = 3 * t;
    ta[3 * t + 1] = Tad; ta[Tad] = 3 * t + 1;
    ta[3 * t + 2] = 3 * n; ta[3 * n] = 3 * t + 2;
    ta[3 * n + 1] = Tdb; ta[Tdb] = 3 * n + 1;
    ta[3 * n + 2] = Tbc; ta[Tbc] = 3 * n + 2;
    if (d->cons) {
        unsigned char *tc = d->tc;
        tc[3 * t] = Cca; tc[3 * t + 1] = Cad; tc[3 * t + 2] = 0;
        tc[3 * n] = 0;   tc[3 * n + 1] = Cdb; tc[3 * n + 2] = Cbc;
        if (d->ts) {
            plateau_index *ts = d->ts;
            ts[3 * t] = Sca; ts[3 * t + 1] = Sad; ts[3 * t + 2] = -1;
            ts[3 * n] = -1;  ts[3 * n + 1] = Sdb; ts[3 * n + 2] = Sbc;
        }
        d->vt[c] = 3 * t;
        d->vt[a] = 3 * t + 1;
        d->vt[dd] = 3 * t + 2;
        d->vt[b] = 3 * n + 2;
    }
}

/* plateau__dt_flip for e = 3t + 1 while the points are inserted (no flags,
 * no vertex map): t = (p, u, v) with twin n = (v, u, q) becomes
 * t = (p, u, q), n = (p, q, v).  The edge p -> u of t is unchanged. */
static inline void plateau__dt_flip_insert(plateau_index *tv, plateau_index *ta, plateau_index t,
                                           plateau_index h)
{
    plateau_index n = h / 3, j = h - 3 * n;
    plateau_index hb = 3 * n + plateau__dt_k_next[j], hd = 3 * n + plateau__dt_k_prev[j];
    plateau_index p = tv[3 * t], v = tv[3 * t + 2], q = tv[hd];
    plateau_index Tbc = ta[3 * t + 2], Tad = ta[hb], Tdb = ta[hd];
    tv[3 * t + 2] = q;
    tv[3 * n] = p; tv[3 * n + 1] = q; tv[3 * n + 2] = v;
    ta[3 * t + 1] = Tad; ta[Tad] = 3 * t + 1;
    ta[3 * t + 2] = 3 * n; ta[3 * n] = 3 * t + 2;
    ta[3 * n + 1] = Tdb; ta[Tdb] = 3 * n + 1;
    ta[3 * n + 2] = Tbc; ta[Tbc] = 3 * n + 2;
}

/* Lawson's flip pass after an insertion (Lawson 1977; de Berg et al.,
 * "Computational Geometry", section 9.3, LegalizeEdge): every triangle on
 * the stack has the new vertex p at corner 0; its edge 1, opposite p, is
 * flipped when p lies inside the circumcircle of the triangle beyond it.
 * For a ghost neighbour the "circle" is the open half-plane beyond its hull
 * edge, so the hull grows by the same flips. */
static plateau_dt_result plateau__dt_legalize(plateau__dt *d)
{
    size_t guard = 0, limit = 4 * (size_t)d->nt + 64;
    /* local copies: no flip moves these arrays or changes these flags */
    const double *xy = d->xy;
    plateau_index *tv = d->tv, *ta = d->ta;
    const unsigned char *tc = d->cons ? d->tc : NULL;
    int fixed_hull = d->tin != NULL;
    while (d->nstack) {
        plateau_index t = d->stack[--d->nstack], e = 3 * t + 1, h, p, u, v, q, n;
        int flip;
        if (++guard > limit) return PLATEAU_DT_ERR_INTERNAL;
        if (tc && tc[e]) continue;
        h = ta[e];
        p = tv[3 * t];
        u = tv[3 * t + 1];
        v = tv[3 * t + 2];
        q = tv[PLATEAU__DT_PREV(h)];
        if (q == PLATEAU__DT_GHOST)
            flip = 0;
        else if (fixed_hull && (u == PLATEAU__DT_GHOST || v == PLATEAU__DT_GHOST))
            flip = 0; /* refinement: the boundary is fixed */
        else if (u == PLATEAU__DT_GHOST) /* n = (v, ghost, q): hull edge q -> v */
            flip = plateau__dt_orient2d(xy + 2 * q, xy + 2 * v, xy + 2 * p) > 0;
        else if (v == PLATEAU__DT_GHOST) /* n = (ghost, u, q): hull edge u -> q */
            flip = plateau__dt_orient2d(xy + 2 * u, xy + 2 * q, xy + 2 * p) > 0;
        else {
            double det = plateau__dt_incircle(xy + 2 * v, xy + 2 * u, xy + 2 * q, xy + 2 * p);
            flip = det > 0 || (det == 0 && plateau__dt_incircle_tie(d, v, u, q, p) > 0);
        }
        if (!flip) continue;
        n = h / 3;
        if (tc) plateau__dt_flip(d, e);
        else plateau__dt_flip_insert(tv, ta, t, h);
        /* now t = (p, u, q) and n = (p, q, v) */
        if (!plateau__dt_push2(d, t, n)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    }
    return PLATEAU_DT_OK;
}

/* The flip pass above while the points are inserted (no constraint flags,
 * no fixed boundary): the same tests and flips, with the work list in
 * locals and the new vertex p (corner 0 of every triangle on the list)
 * and its coordinates held once; this loop is about half of the
 * triangulation's time. */
static plateau_dt_result plateau__dt_legalize_insert(plateau__dt *d, plateau_index p)
{
    size_t guard = 0, limit = 4 * (size_t)d->nt + 64, ns = d->nstack;
    const double *xy = d->xy;
    plateau_index *tv = d->tv, *ta = d->ta, *stk = d->stack;
    double pp[2];
    pp[0] = xy[2 * (size_t)p];
    pp[1] = xy[2 * (size_t)p + 1];
    while (ns) {
        plateau_index t = stk[--ns], h, u, v, q;
        int flip;
        if (++guard > limit) return PLATEAU_DT_ERR_INTERNAL;
        h = ta[3 * t + 1];
        u = tv[3 * t + 1];
        v = tv[3 * t + 2];
        q = tv[PLATEAU__DT_PREV(h)];
        if (q == PLATEAU__DT_GHOST)
            flip = 0;
        else if (u == PLATEAU__DT_GHOST) /* n = (v, ghost, q): hull edge q -> v */
            flip = plateau__dt_orient2d(xy + 2 * q, xy + 2 * v, pp) > 0;
        else if (v == PLATEAU__DT_GHOST) /* n = (ghost, u, q): hull edge u -> q */
            flip = plateau__dt_orient2d(xy + 2 * u, xy + 2 * q, pp) > 0;
        else {
            double det = plateau__dt_incircle(xy + 2 * v, xy + 2 * u, xy + 2 * q, pp);
            flip = det > 0 || (det == 0 && plateau__dt_incircle_tie(d, v, u, q, p) > 0);
        }
        if (!flip) continue;
        plateau__dt_flip_insert(tv, ta, t, h);
        if (ns + 2 > d->cap_stack) {
            d->nstack = ns;
            if (!plateau__dt_grow(&d->al, (void **)&d->stack, &d->cap_stack,
                                  sizeof(plateau_index), ns + 2))
                return PLATEAU_DT_ERR_OUT_OF_MEMORY;
            stk = d->stack;
        }
        stk[ns++] = t;
        stk[ns++] = h / 3;
    }
    d->nstack = 0;
    return PLATEAU_DT_OK;
}

/* Where a point lies relative to a triangle. */
#define PLATEAU__DT_IN_TRIANGLE 3
#define PLATEAU__DT_IN_GHOST 4
#define PLATEAU__DT_ON_VERTEX 5 /* + corner */
/* 0, 1, 2: on edge k (strictly between its endpoints) */

/* Classify p against a real triangle t: -1 if p is strictly outside an
 * edge, else a location code. */
static int plateau__dt_classify(const plateau__dt *d, plateau_index t, const double *p)
{
    const plateau_index *v = d->tv + 3 * (size_t)t;
    double o[3];
    int k, zeros = 0, zk = -1;
    for (k = 0; k < 3; k++) {
        o[k] = plateau__dt_orient2d(PLATEAU__DT_P(d, v[k]), PLATEAU__DT_P(d, v[(k + 1) % 3]), p);
        if (o[k] < 0) return -1;
        if (o[k] == 0) { zeros++; zk = k; }
    }
    if (zeros == 0) return PLATEAU__DT_IN_TRIANGLE;
    if (zeros == 1) return zk;
    for (k = 0; k < 3; k++)
        if (o[k] == 0 && o[(k + 1) % 3] == 0) return PLATEAU__DT_ON_VERTEX + (k + 1) % 3;
    return -1;
}

/* Point location by a remembering stochastic walk (Devillers, Pion and
 * Teillaud, "Walking in a triangulation", 2002) from the last triangle,
 * with exact orientation tests.  The walk is bounded; past the bound an
 * exhaustive exact scan decides.  On success *where is a location code
 * and *tri the triangle (a ghost for a point outside the hull, entered
 * across a hull edge that has p strictly outside). */
static plateau_dt_result plateau__dt_locate(plateau__dt *d, const double *p, plateau_index *tri,
                                            int *where)
{
    plateau_index t = d->last, from = -1;
    size_t steps, limit = 2 * (size_t)d->nt + 64;
    int k, c, fk = -1;
    uint32_t rng = d->walk_rng; /* kept in a register, stored on return */
    const plateau_index *tv = d->tv;
    const double *xy = d->xy;
    if (plateau__dt_is_ghost(d, t)) {
        for (k = 0; k < 3; k++)
            if (d->tv[3 * t + k] == PLATEAU__DT_GHOST) break;
        t = d->ta[3 * t + (k + 1) % 3] / 3;
    }
    (void)from;
    for (steps = 0; steps < limit; steps++) {
        const plateau_index *v = tv + 3 * (size_t)t;
        double o[3] = {1, 1, 1}; /* set before read; initialised for -Wmaybe-uninitialized */
        int i, zeros = 0, zk = -1;
        if (v[0] == PLATEAU__DT_GHOST || v[1] == PLATEAU__DT_GHOST || v[2] == PLATEAU__DT_GHOST) {
            d->walk_rng = rng;
            *tri = t;
            *where = PLATEAU__DT_IN_GHOST;
            return PLATEAU_DT_OK;
        }
        /* the edge we came through has p strictly inside; the other two
         * are tried in a random order (one bit of a xorshift generator) */
        rng ^= rng << 13;
        rng ^= rng >> 17;
        rng ^= rng << 5;
        if (fk < 0) {
            for (k = 0; k < 3; k++) {
                o[k] = plateau__dt_orient2d(xy + 2 * v[k], xy + 2 * v[plateau__dt_k_next[k]], p);
                if (o[k] < 0) break;
            }
            if (k < 3) {
                plateau_index h = d->ta[3 * t + k];
                t = h / 3;
                fk = (int)(h - 3 * t);
                continue;
            }
        } else {
            /* branch-free order: the random bit is unpredictable by design */
            int ka = plateau__dt_k_next[fk], kb = plateau__dt_k_prev[fk];
            int x = (ka ^ kb) & -(int)(rng & 1u);
            double oa, ob;
            ka ^= x;
            kb ^= x;
            oa = plateau__dt_orient2d(xy + 2 * v[ka], xy + 2 * v[plateau__dt_k_next[ka]], p);
            k = ka;
            if (oa >= 0) {
                ob = plateau__dt_orient2d(xy + 2 * v[kb], xy + 2 * v[plateau__dt_k_next[kb]], p);
                k = kb;
                if (ob >= 0) {
                    if (oa > 0 && ob > 0) { /* the common case: strictly inside */
                        d->walk_rng = rng;
                        *tri = t;
                        *where = PLATEAU__DT_IN_TRIANGLE;
                        return PLATEAU_DT_OK;
                    }
                    o[fk] = 1;
                    o[ka] = oa;
                    o[kb] = ob;
                    k = -1;
                }
            }
            if (k >= 0) {
                plateau_index h = d->ta[3 * t + k];
                t = h / 3;
                fk = (int)(h - 3 * t);
                continue;
            }
        }
        d->walk_rng = rng;
        for (i = 0; i < 3; i++)
            if (o[i] == 0) { zeros++; zk = i; }
        *tri = t;
        if (zeros == 0) *where = PLATEAU__DT_IN_TRIANGLE;
        else if (zeros == 1) *where = zk;
        else {
            for (k = 0; k < 3; k++)
                if (o[k] == 0 && o[(k + 1) % 3] == 0) break;
            *where = PLATEAU__DT_ON_VERTEX + (k + 1) % 3;
        }
        return PLATEAU_DT_OK;
    }
    d->walk_rng = rng;
    /* exhaustive scan: real triangles first, then ghosts */
    for (t = 0; t < d->nt; t++) {
        if (plateau__dt_is_ghost(d, t)) continue;
        c = plateau__dt_classify(d, t, p);
        if (c >= 0) {
            *tri = t;
            *where = c;
            return PLATEAU_DT_OK;
        }
    }
    for (t = 0; t < d->nt; t++) {
        const plateau_index *v = d->tv + 3 * (size_t)t;
        if (!plateau__dt_is_ghost(d, t)) continue;
        for (k = 0; k < 3; k++)
            if (v[k] == PLATEAU__DT_GHOST) break;
        if (plateau__dt_orient2d(PLATEAU__DT_P(d, v[(k + 1) % 3]), PLATEAU__DT_P(d, v[(k + 2) % 3]),
                                 p) > 0) {
            *tri = t;
            *where = PLATEAU__DT_IN_GHOST;
            return PLATEAU_DT_OK;
        }
    }
    return PLATEAU_DT_ERR_INTERNAL;
}

/* Insert vertex p (coordinates already in d->xy) into the triangulation.
 * *dup receives the existing vertex p coincides with (p is then not
 * inserted), else 0. */
static plateau_dt_result plateau__dt_insert(plateau__dt *d, plateau_index p, plateau_index *dup)
{
    plateau_index t;
    int where;
    plateau_dt_result r;
    *dup = 0;
    r = plateau__dt_reserve_triangles(d, 2);
    if (r != PLATEAU_DT_OK) return r;
    r = plateau__dt_locate(d, PLATEAU__DT_P(d, p), &t, &where);
    if (r != PLATEAU_DT_OK) return r;
    if (where >= PLATEAU__DT_ON_VERTEX) {
        *dup = d->tv[3 * t + (where - PLATEAU__DT_ON_VERTEX)];
        return PLATEAU_DT_OK;
    }
    d->last = t; /* its slot keeps a triangle of p through the flips */
    if (where == PLATEAU__DT_IN_TRIANGLE || where == PLATEAU__DT_IN_GHOST) {
        if (!plateau__dt_split_triangle(d, t, p)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    } else {
        if (!plateau__dt_split_edge(d, 3 * t + where, p)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    }
    return d->cons ? plateau__dt_legalize(d) : plateau__dt_legalize_insert(d, p);
}

/* ---- Insertion order: biased randomised insertion order (Amenta, Choi
 * and Rote 2003) with a Hilbert curve order inside each round ---------- */

static uint64_t plateau__dt_splitmix(uint64_t *state)
{
    uint64_t z = (*state += PLATEAU__U64(0x9E3779B9u, 0x7F4A7C15u));
    z = (z ^ (z >> 30)) * PLATEAU__U64(0xBF58476Du, 0x1CE4E5B9u);
    z = (z ^ (z >> 27)) * PLATEAU__U64(0x94D049BBu, 0x133111EBu);
    return z ^ (z >> 31);
}

/* One level of the Hilbert curve (Hilbert 1891; the table-free form of
 * Butz's algorithm): the quadrant bits (bx, by) of a cell give 2 bits of
 * its index along the curve.  The state is the transformation the finer
 * levels see: a swap of x and y (sw) and/or a complement of both (inv),
 * updated without data-dependent branches (they would be mispredicted
 * about half of the time). */
static uint32_t plateau__dt_hilbert_step(uint32_t bx, uint32_t by, uint32_t *sw, uint32_t *inv)
{
    uint32_t rx, ry, low;
    bx ^= *inv;
    by ^= *inv;
    rx = bx ^ ((bx ^ by) & *sw);
    ry = by ^ ((bx ^ by) & *sw);
    low = ry ^ 1u; /* the lower-left or lower-right quadrant */
    *inv ^= rx & low;
    *sw ^= low;
    return (3u * rx) ^ ry;
}

/* The step above for three levels at once: entry 64 s + 8 bx + by (s =
 * 2 sw + inv, bx and by three bits each) holds the 6 index bits and, in
 * its top 2 bits, the state after them. */
static void plateau__dt_hilbert_table(unsigned char *tab)
{
    uint32_t s, xy3;
    for (s = 0; s < 4; s++)
        for (xy3 = 0; xy3 < 64; xy3++) {
            uint32_t sw = s >> 1, inv = s & 1u, d = 0;
            int l;
            for (l = 2; l >= 0; l--)
                d = (d << 2) | plateau__dt_hilbert_step((xy3 >> (3 + l)) & 1u, (xy3 >> l) & 1u,
                                                        &sw, &inv);
            tab[64 * s + xy3] = (unsigned char)(d | ((2u * sw + inv) << 6));
        }
}

/* Index of the cell (x, y) of a 2^levels x 2^levels grid along the Hilbert
 * curve: single steps for the top (levels mod 3) levels, then three levels
 * per table look-up. */
static uint32_t plateau__dt_hilbert(uint32_t x, uint32_t y, int levels, const unsigned char *tab)
{
    uint32_t d = 0, sw = 0, inv = 0, s;
    int i = levels - 1;
    for (; (i + 1) % 3 != 0; i--)
        d = (d << 2) | plateau__dt_hilbert_step((x >> i) & 1u, (y >> i) & 1u, &sw, &inv);
    s = 2u * sw + inv;
    for (; i >= 2; i -= 3) {
        uint32_t e = tab[64 * s + (((x >> (i - 2)) & 7u) << 3) + ((y >> (i - 2)) & 7u)];
        d = (d << 6) | (e & 63u);
        s = e >> 6;
    }
    return d;
}

/* order[0..n-1]: the input indices in insertion order.  Each point gets a
 * round (round r holds about half of the points of round r + 1; the last
 * round half of all) and, inside its round, its Hilbert index on a grid of
 * about 4n cells; one stable radix sort of (round, Hilbert index, input
 * index) packed in 64 bits gives the order, ties by input index.  The
 * keys live in key and key2, n each: the caller lends the triangle arrays,
 * not yet used, so that their pages serve the sort and then the
 * triangulation instead of being allocated twice. */
static PLATEAU__COLD void plateau__dt_brio(const plateau__dt *d, const double *xy, size_t n, uint64_t seed,
                             plateau_index *order, uint64_t *key, uint64_t *key2)
{
    /* the coordinates are scaled on the fly, as in d->xy later */
    double f1 = plateau__dt_pow2(d->shift / 2), f2 = plateau__dt_pow2(d->shift - d->shift / 2);
    uint64_t rng = seed;
    size_t i;
    double minx = xy[0] * f1 * f2, maxx = minx, miny = xy[1] * f1 * f2, maxy = miny, sx, sy;
    int maxr = 0, levels = 1, bits, shift;
    size_t cnt[2048];
    unsigned char htab[256];
    plateau__dt_hilbert_table(htab);
    while (maxr < 24 && ((size_t)1 << (maxr + 3)) < n) maxr++;     /* rounds: 5 bits */
    while (levels < 13 && ((size_t)1 << (2 * levels)) < 4 * n) levels++; /* grid 2^levels */
    bits = 5 + 2 * levels;
    for (i = 0; i < n; i++) {
        double x = xy[2 * i] * f1 * f2, y = xy[2 * i + 1] * f1 * f2;
        if (x < minx) minx = x;
        if (x > maxx) maxx = x;
        if (y < miny) miny = y;
        if (y > maxy) maxy = y;
    }
    /* scaled coordinates are below 2^200, so these spans cannot overflow */
    {
        double cells = (double)(1u << levels) - 1.0;
        sx = maxx > minx ? cells / (maxx - minx) : 0.0;
        sy = maxy > miny ? cells / (maxy - miny) : 0.0;
    }
    for (i = 0; i < n; i++) {
        double fx = (xy[2 * i] * f1 * f2 - minx) * sx, fy = (xy[2 * i + 1] * f1 * f2 - miny) * sy;
        uint32_t top = (1u << levels) - 1u;
        uint32_t qx = fx > (double)top ? top : (fx > 0.0 ? (uint32_t)fx : 0u);
        uint32_t qy = fy > (double)top ? top : (fy > 0.0 ? (uint32_t)fy : 0u);
        uint64_t r = plateau__dt_splitmix(&rng), k;
        int level = 0; /* rounds from the last: P(level >= j) = 2^-j */
#if defined(__GNUC__) || defined(__clang__)
        level = ~r ? __builtin_ctzll(~r) : 64; /* the trailing one bits */
        if (level > maxr) level = maxr;
#else
        while (level < maxr && (r & 1u)) {
            level++;
            r >>= 1;
        }
#endif
        k = ((uint64_t)(maxr - level) << (2 * levels)) |
            plateau__dt_hilbert(qx, qy, levels, htab);
        key[i] = (k << 32) | (uint64_t)i;
    }
    /* LSD radix sort on bits 32 .. 32 + bits, 11 bits per pass */
    for (shift = 32; shift < 32 + bits; shift += 11) {
        size_t sum = 0, c;
        uint64_t *t;
        memset(cnt, 0, sizeof cnt);
        for (i = 0; i < n; i++) cnt[(key[i] >> shift) & 2047u]++;
        if (cnt[(key[0] >> shift) & 2047u] == n) continue; /* one bucket */
        for (c = 0; c < 2048; c++) {
            size_t k = cnt[c];
            cnt[c] = sum;
            sum += k;
        }
        for (i = 0; i < n; i++) key2[cnt[(key[i] >> shift) & 2047u]++] = key[i];
        t = key;
        key = key2;
        key2 = t;
    }
    for (i = 0; i < n; i++) order[i] = (plateau_index)(key[i] & 0xffffffffu);
}

/* ---- Constraint segments ----------------------------------------------- */

/* The half-edge from u to v, or -1 (rotating around u); -2 when the ring
 * of triangles around u does not close within the bound (a broken
 * structure: the callers return PLATEAU_DT_ERR_INTERNAL). */
#define PLATEAU__DT_RING_BROKEN (-2)
static plateau_index plateau__dt_find_edge(const plateau__dt *d, plateau_index u, plateau_index v)
{
    plateau_index h0 = d->vt[u], h = h0;
    plateau_index guard = 0;
    if (h0 < 0) return -1;
    do {
        if (d->tv[PLATEAU__DT_NEXT(h)] == v) return h;
        h = d->ta[PLATEAU__DT_PREV(h)];
        if (++guard > d->nt) return PLATEAU__DT_RING_BROKEN;
    } while (h != h0);
    return -1;
}

/* 1 when b - a and c - a point the same way, for collinear a, b, c. */
static int plateau__dt_same_direction(const double *a, const double *b, const double *c)
{
    return ((b[0] > a[0]) == (c[0] > a[0])) && ((b[0] < a[0]) == (c[0] < a[0])) &&
           ((b[1] > a[1]) == (c[1] > a[1])) && ((b[1] < a[1]) == (c[1] < a[1]));
}

static void plateau__dt_mark(plateau__dt *d, plateau_index e, long seg)
{
    d->tc[e] = 1;
    d->tc[d->ta[e]] = 1;
    if (d->ts) d->ts[e] = d->ts[d->ta[e]] = (plateau_index)seg;
}

static int plateau__dt_crosses(const plateau__dt *d, plateau_index a, plateau_index w,
                               plateau_index u, plateau_index v)
{
    double ou = plateau__dt_orient2d(PLATEAU__DT_P(d, a), PLATEAU__DT_P(d, w), PLATEAU__DT_P(d, u));
    double ov = plateau__dt_orient2d(PLATEAU__DT_P(d, a), PLATEAU__DT_P(d, w), PLATEAU__DT_P(d, v));
    return (ou > 0 && ov < 0) || (ou < 0 && ov > 0);
}

/* Make the edge (a, w) exist, given the edges crossing it (pairs in
 * `edges`, 2 * k entries), by Sloan's flip algorithm (Sloan, "A fast
 * algorithm for generating constrained Delaunay triangulations", 1993):
 * flip a crossing edge whenever its quadrilateral is strictly convex,
 * queueing the result again if it still crosses; then restore the
 * Delaunay property among the new edges with Lawson flips that never flip
 * a constrained edge.  `edges` is used as a circular queue; the new edges
 * are collected in `fresh` (room for k pairs). */
static plateau_dt_result plateau__dt_recover(plateau__dt *d, plateau_index a, plateau_index w,
                                             plateau_index *edges, size_t k, plateau_index *fresh)
{
    size_t head = 0, count = k, nfresh = 0, guard = 0, limit = 8 * (k + 2) * (k + 2) + 64;
    plateau_index e;
    int changed;
    while (count) {
        plateau_index u = edges[2 * head], v = edges[2 * head + 1], c, dd, h;
        head = (head + 1) % k;
        count--;
        if (++guard > limit) return PLATEAU_DT_ERR_INTERNAL;
        e = plateau__dt_find_edge(d, u, v);
        if (e < 0) return PLATEAU_DT_ERR_INTERNAL;
        h = d->ta[e];
        c = d->tv[PLATEAU__DT_PREV(e)];
        dd = d->tv[PLATEAU__DT_PREV(h)];
        if (c == PLATEAU__DT_GHOST || dd == PLATEAU__DT_GHOST) return PLATEAU_DT_ERR_INTERNAL;
        if (plateau__dt_orient2d(PLATEAU__DT_P(d, c), PLATEAU__DT_P(d, u), PLATEAU__DT_P(d, dd)) > 0 &&
            plateau__dt_orient2d(PLATEAU__DT_P(d, c), PLATEAU__DT_P(d, dd), PLATEAU__DT_P(d, v)) > 0) {
            size_t tail = (head + count) % k;
            plateau__dt_flip(d, e);
            if (plateau__dt_crosses(d, a, w, c, dd)) {
                edges[2 * tail] = c;
                edges[2 * tail + 1] = dd;
                count++;
            } else {
                fresh[2 * nfresh] = c;
                fresh[2 * nfresh + 1] = dd;
                nfresh++;
            }
        } else {
            size_t tail = (head + count) % k;
            edges[2 * tail] = u;
            edges[2 * tail + 1] = v;
            count++;
        }
    }
    e = plateau__dt_find_edge(d, a, w);
    if (e < 0) return PLATEAU_DT_ERR_INTERNAL;
    plateau__dt_mark(d, e, d->cur_seg);
    /* Lawson flips among the new edges until all are locally Delaunay */
    guard = 0;
    do {
        size_t i;
        changed = 0;
        for (i = 0; i < nfresh; i++) {
            plateau_index u = fresh[2 * i], v = fresh[2 * i + 1], c, dd;
            e = plateau__dt_find_edge(d, u, v);
            if (e < 0) return PLATEAU_DT_ERR_INTERNAL;
            if (d->tc[e]) continue;
            c = d->tv[PLATEAU__DT_PREV(e)];
            dd = d->tv[PLATEAU__DT_PREV(d->ta[e])];
            if (c == PLATEAU__DT_GHOST || dd == PLATEAU__DT_GHOST) continue;
            if (plateau__dt_incircle_sos(d, u, v, c, dd) > 0) {
                if (++guard > limit) return PLATEAU_DT_ERR_INTERNAL;
                plateau__dt_flip(d, e);
                fresh[2 * i] = c;
                fresh[2 * i + 1] = dd;
                changed = 1;
            }
        }
    } while (changed);
    return PLATEAU_DT_OK;
}

#ifndef PLATEAU_DT_NO_STEINER
/* Restore the constrained Delaunay property after the edge (u, v) lost its
 * constraint flag: it is the only edge that can fail the local test, so
 * Lawson's flips spreading from it suffice (each flip queues the four
 * edges around the new one). */
static plateau_dt_result plateau__dt_restore_from(plateau__dt *d, plateau_index u, plateau_index v)
{
    size_t n = 0, guard = 0, limit = 8 * (size_t)d->nt + 64;
    if (!plateau__dt_grow(&d->al, (void **)&d->estack, &d->cap_estack, sizeof(plateau_index), 2))
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->estack[n++] = u;
    d->estack[n++] = v;
    while (n) {
        plateau_index b = d->estack[--n], a = d->estack[--n], e, c, dd;
        if (++guard > limit) return PLATEAU_DT_ERR_INTERNAL;
        e = plateau__dt_find_edge(d, a, b);
        if (e == PLATEAU__DT_RING_BROKEN) return PLATEAU_DT_ERR_INTERNAL;
        if (e < 0 || d->tc[e]) continue;
        c = d->tv[PLATEAU__DT_PREV(e)];
        dd = d->tv[PLATEAU__DT_PREV(d->ta[e])];
        if (a == PLATEAU__DT_GHOST || b == PLATEAU__DT_GHOST || c == PLATEAU__DT_GHOST ||
            dd == PLATEAU__DT_GHOST)
            continue;
        if (plateau__dt_incircle_sos(d, a, b, c, dd) <= 0) continue;
        plateau__dt_flip(d, e);
        if (!plateau__dt_grow(&d->al, (void **)&d->estack, &d->cap_estack, sizeof(plateau_index),
                              n + 8))
            return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        d->estack[n++] = c; d->estack[n++] = a;
        d->estack[n++] = a; d->estack[n++] = dd;
        d->estack[n++] = dd; d->estack[n++] = b;
        d->estack[n++] = b; d->estack[n++] = c;
    }
    return PLATEAU_DT_OK;
}

/* The segment (a, b) crosses the constrained edge e = (u, v).  Both are
 * split at a vertex x near their crossing point, and the pieces (u, x),
 * (x, v), (a, x), (x, b) go on the pending list (the last one first, so
 * the crossed segment is restored before the walk goes on).  x is a new
 * vertex at the rounded crossing point (it need not lie exactly on either
 * line), except when the crossing is within 2^-40 (relative) of one of the
 * four endpoints: then x is that endpoint.  The snapping stops the cascade
 * of ever closer crossings that several segments through one point would
 * otherwise start. */
/* max(|b - a|, |v - u|) in the max norm */
static double plateau__dt_len_inf(const double *a, const double *b, const double *u,
                                  const double *v)
{
    double m = PLATEAU_FABS(b[0] - a[0]), z;
    z = PLATEAU_FABS(b[1] - a[1]); if (z > m) m = z;
    z = PLATEAU_FABS(v[0] - u[0]); if (z > m) m = z;
    z = PLATEAU_FABS(v[1] - u[1]); if (z > m) m = z;
    return m;
}

/* The vertex nearest to (px, py) among a, b and the apexes of the two
 * triangles of edge e, if it lies within tol (max norm); else -1.  (The
 * ends of e are left to the caller's rule, which prefers a and b.) */
static plateau_index plateau__dt_near_vertex(const plateau__dt *d, plateau_index e, plateau_index a,
                                             plateau_index b, double px, double py, double tol)
{
    plateau_index c[4], best = -1;
    double bd = tol;
    int i;
    c[0] = a; c[1] = b;
    c[2] = d->tv[PLATEAU__DT_PREV(e)];
    c[3] = d->tv[PLATEAU__DT_PREV(d->ta[e])];
    for (i = 0; i < 4; i++) {
        const double *q;
        double dist, dy;
        if (c[i] == PLATEAU__DT_GHOST) continue;
        q = PLATEAU__DT_P(d, c[i]);
        dist = PLATEAU_FABS(q[0] - px);
        dy = PLATEAU_FABS(q[1] - py);
        if (dy > dist) dist = dy;
        if (dist <= bd) { bd = dist; best = c[i]; }
    }
    return best;
}

/* Queue the pieces (p, x) and (x, q) of segment seg. */
static plateau_dt_result plateau__dt_pend_pieces(plateau__dt *d, plateau_index p, plateau_index x,
                                                 plateau_index q, plateau_index seg)
{
    if (!plateau__dt_grow(&d->al, (void **)&d->pend, &d->cap_pend, sizeof(plateau_index),
                          d->npend + 6))
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->pend[d->npend++] = p; d->pend[d->npend++] = x; d->pend[d->npend++] = seg;
    d->pend[d->npend++] = x; d->pend[d->npend++] = q; d->pend[d->npend++] = seg;
    return PLATEAU_DT_OK;
}

/* A new crossing vertex x can lie within rounding of a third segment (one
 * nearly through the same point, e.g. two nearly parallel segments from one
 * endpoint crossed by another).  Left alone, x would sit on the wrong side
 * of it by an ulp and the pieces through x would cross it again next to x,
 * leaving a cluster of crossing vertices joined by tiny constrained
 * triangles.  Such a segment (an edge of x's star, whose interior passes
 * within tol of x) is routed through x instead. */
static plateau_dt_result plateau__dt_absorb_near_segments(plateau__dt *d, plateau_index x, double tol)
{
    plateau_index found[8][3], h0 = d->vt[x], h = h0, guard = 0;
    int nf = 0, i;
    const double *px = PLATEAU__DT_P(d, x);
    plateau_dt_result r;
    if (h0 < 0) return PLATEAU_DT_OK;
    do { /* collect first: the flips below change the star */
        plateau_index opp = PLATEAU__DT_NEXT(h);
        plateau_index p = d->tv[opp], q = d->tv[PLATEAU__DT_NEXT(opp)];
        if (d->tc[opp] && p != PLATEAU__DT_GHOST && q != PLATEAU__DT_GHOST && nf < 8) {
            const double *pp = PLATEAU__DT_P(d, p), *pq = PLATEAU__DT_P(d, q);
            double ex = pq[0] - pp[0], ey = pq[1] - pp[1];
            double len = PLATEAU_SQRT(ex * ex + ey * ey);
            double along = (px[0] - pp[0]) * ex + (px[1] - pp[1]) * ey;
            double off = PLATEAU_FABS(plateau__dt_orient2d(pp, pq, px));
            if (len > 0 && off <= tol * len && along > 0 && along < len * len) {
                found[nf][0] = p;
                found[nf][1] = q;
                found[nf][2] = d->ts ? d->ts[opp] : -1;
                nf++;
            }
        }
        h = d->ta[PLATEAU__DT_PREV(h)];
        if (++guard > d->nt) return PLATEAU_DT_ERR_INTERNAL; /* a broken vertex ring */
    } while (h != h0);
    for (i = 0; i < nf; i++) {
        plateau_index e = plateau__dt_find_edge(d, found[i][0], found[i][1]);
        if (e == PLATEAU__DT_RING_BROKEN) return PLATEAU_DT_ERR_INTERNAL;
        if (e < 0 || !d->tc[e]) continue;
        d->tc[e] = 0;
        d->tc[d->ta[e]] = 0;
        if (d->ts) d->ts[e] = d->ts[d->ta[e]] = -1;
        r = plateau__dt_restore_from(d, found[i][0], found[i][1]);
        if (r != PLATEAU_DT_OK) return r;
        r = plateau__dt_pend_pieces(d, found[i][0], x, found[i][1], found[i][2]);
        if (r != PLATEAU_DT_OK) return r;
    }
    return PLATEAU_DT_OK;
}

static plateau_dt_result plateau__dt_split_crossing(plateau__dt *d, plateau_index e,
                                                    plateau_index a, plateau_index b)
{
    const double snap = 9.094947017729282e-13; /* 2^-40 */
    plateau_index u = d->tv[e], v = d->tv[PLATEAU__DT_NEXT(e)], x = -1, dup, k;
    plateau_index piece[8], seg_uv = d->ts ? d->ts[e] : -1;
    const double *pu = PLATEAU__DT_P(d, u), *pv = PLATEAU__DT_P(d, v);
    const double *pa = PLATEAU__DT_P(d, a), *pb = PLATEAU__DT_P(d, b);
    double oa = plateau__dt_orient2d(pu, pv, pa), ob = plateau__dt_orient2d(pu, pv, pb);
    double ou = plateau__dt_orient2d(pa, pb, pu), ov = plateau__dt_orient2d(pa, pb, pv);
    double t = oa / (oa - ob), sv = ou / (ou - ov), px = 0, py = 0;
    double tol = snap * plateau__dt_len_inf(pa, pb, pu, pv); /* (before d->xy moves) */
    int split_uv = 1;
    plateau_dt_result r;
    if (!(t > 0)) t = 0; /* also NaN */
    if (t > 1) t = 1;
    if (!(sv > 0)) sv = 0;
    if (sv > 1) sv = 1;
    if (d->steiner_left == 0) {
        plateau__dt_set_error(d->report, -1,
                               "segments cross too often near one point to be split there "
                               "(more than 2 n^2 + 64 splits for n segments)");
        return PLATEAU_DT_ERR_CROSSING_SEGMENTS;
    }
    d->steiner_left--;
    /* the crossed segment is routed through a or b in preference: a piece
     * of (a, b) routed back through u or v could re-create an edge that
     * was split a moment ago, and the two would alternate */
    if (t <= snap) x = a;
    else if (t >= 1 - snap) x = b;
    else if (sv <= snap) { x = u; split_uv = 0; }
    else if (sv >= 1 - snap) { x = v; split_uv = 0; }
    if (x < 0) {
        px = pa[0] + t * (pb[0] - pa[0]);
        py = pa[1] + t * (pb[1] - pa[1]);
        /* crossings that coincide to rounding are one vertex: an earlier
         * crossing vertex (an apex next to (u, v)) or an end of (a, b)
         * within 2^-40 of the longer segment's length of the rounded point
         * takes the crossing (else nearly parallel segments through one
         * point leave a tiny all-constrained triangle) */
        x = plateau__dt_near_vertex(d, e, a, b, px, py, tol);
    }
    if (split_uv) {
        d->tc[e] = 0;
        d->tc[d->ta[e]] = 0;
        if (d->ts) d->ts[e] = d->ts[d->ta[e]] = -1;
        r = plateau__dt_restore_from(d, u, v);
        if (r != PLATEAU_DT_OK) return r;
    }
    if (x < 0) {
        r = plateau__dt_reserve_vertices(d, 1);
        if (r != PLATEAU_DT_OK) return r;
        x = d->nv;
        d->xy[2 * (size_t)x] = px;
        d->xy[2 * (size_t)x + 1] = py;
        d->vt[x] = -1;
        d->outid[x] = x - 1;
        if (d->vseg) d->vseg[x] = (plateau_index)d->cur_seg;
        d->last = d->vt[u] / 3;
        r = plateau__dt_insert(d, x, &dup);
        if (r != PLATEAU_DT_OK) return r;
        if (dup) {
            x = dup; /* the rounded point is an existing vertex */
        } else {
            d->nv++;
            r = plateau__dt_absorb_near_segments(d, x, tol);
            if (r != PLATEAU_DT_OK) return r;
        }
    }
    piece[0] = x; piece[1] = b;
    piece[2] = a; piece[3] = x;
    piece[4] = x; piece[5] = v;
    piece[6] = u; piece[7] = x;
    for (k = 0; k < 4; k++) {
        if (piece[2 * k] == piece[2 * k + 1]) continue;
        if (!split_uv && k >= 2) continue; /* (u, v) stays as it is */
        if (!plateau__dt_grow(&d->al, (void **)&d->pend, &d->cap_pend, sizeof(plateau_index),
                              d->npend + 3))
            return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        d->pend[d->npend++] = piece[2 * k];
        d->pend[d->npend++] = piece[2 * k + 1];
        d->pend[d->npend++] = k < 2 ? (plateau_index)d->cur_seg : seg_uv;
    }
    return PLATEAU_DT_OK;
}

#endif /* PLATEAU_DT_NO_STEINER */

/* Insert the constraint segment (a, b), both vertices of the
 * triangulation: walk from a towards b; vertices lying exactly on the
 * segment split it; each stretch between them is recovered by flips.  A
 * crossed constraint is an error, or (option) both are split at their
 * crossing and the pieces go through the same steps. */
static plateau_dt_result plateau__dt_insert_segment(plateau__dt *d, plateau_index a0,
                                                    plateau_index b0, long segidx,
                                                    plateau_index **work, size_t *work_cap)
{
    d->npend = 0;
    if (!plateau__dt_grow(&d->al, (void **)&d->pend, &d->cap_pend, sizeof(plateau_index), 3))
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    d->pend[d->npend++] = a0;
    d->pend[d->npend++] = b0;
    d->pend[d->npend++] = (plateau_index)segidx;
    while (d->npend) {
        plateau_index sg = d->pend[--d->npend], b = d->pend[--d->npend], a = d->pend[--d->npend];
        plateau_index guard = 0;
        while (a != b) {
            const double *pa = PLATEAU__DT_P(d, a), *pb = PLATEAU__DT_P(d, b);
            plateau_index h0 = d->vt[a], h = h0, w = -1, e = -1, turns = 0;
            size_t k = 0;
            int split = 0;
            if (++guard > d->nv) return PLATEAU_DT_ERR_INTERNAL;
            /* rotate around a to find the edge along the segment, or the
             * triangle whose opposite edge the segment crosses */
            do {
                plateau_index v1 = d->tv[PLATEAU__DT_NEXT(h)], v2 = d->tv[PLATEAU__DT_PREV(h)];
                if (v1 != PLATEAU__DT_GHOST) {
                    double o1 = plateau__dt_orient2d(pa, pb, PLATEAU__DT_P(d, v1));
                    if (o1 == 0 && plateau__dt_same_direction(pa, PLATEAU__DT_P(d, v1), pb)) {
                        w = v1;
                        e = h;
                        break;
                    }
                    if (o1 < 0 && v2 != PLATEAU__DT_GHOST &&
                        plateau__dt_orient2d(pa, pb, PLATEAU__DT_P(d, v2)) > 0) {
                        e = PLATEAU__DT_NEXT(h);
                        break;
                    }
                }
                h = d->ta[PLATEAU__DT_PREV(h)];
                if (++turns > d->nt) return PLATEAU_DT_ERR_INTERNAL;
            } while (h != h0);
            if (e < 0) return PLATEAU_DT_ERR_INTERNAL;
            if (w >= 0) { /* the edge (a, w) lies along the segment */
                plateau__dt_mark(d, e, sg);
                a = w;
                continue;
            }
            /* walk across the triangles the segment passes through,
             * recording the crossed edges (each from its right to its left
             * endpoint) */
            for (;;) {
                plateau_index g, x;
                double o;
                if (d->tc[e]) {
#ifndef PLATEAU_DT_NO_STEINER /* else plateau__dt_check_args refused splits */
                    if (d->split_crossing) {
                        plateau_dt_result r;
                        d->cur_seg = sg;
                        r = plateau__dt_split_crossing(d, e, a, b);
                        if (r != PLATEAU_DT_OK) return r;
                        split = 1;
                        break;
                    }
#endif
                    if (d->report) {
                        d->report->index = segidx;
                        PLATEAU_SNPRINTF(d->report->message, sizeof d->report->message,
                                 "segment %ld crosses another segment (the one through points "
                                 "%ld and %ld)",
                                 segidx, (long)d->outid[d->tv[e]],
                                 (long)d->outid[d->tv[PLATEAU__DT_NEXT(e)]]);
                    }
                    return PLATEAU_DT_ERR_CROSSING_SEGMENTS;
                }
                if (!plateau__dt_grow(&d->al, (void **)work, work_cap, sizeof(plateau_index),
                                      4 * (k + 1)))
                    return PLATEAU_DT_ERR_OUT_OF_MEMORY;
                (*work)[2 * k] = d->tv[e];
                (*work)[2 * k + 1] = d->tv[PLATEAU__DT_NEXT(e)];
                k++;
                if (k > (size_t)d->nt) return PLATEAU_DT_ERR_INTERNAL;
                g = d->ta[e];
                x = d->tv[PLATEAU__DT_PREV(g)];
                if (x == b) { w = b; break; }
                if (x == PLATEAU__DT_GHOST) return PLATEAU_DT_ERR_INTERNAL;
                o = plateau__dt_orient2d(pa, pb, PLATEAU__DT_P(d, x));
                if (o == 0) { w = x; break; } /* a vertex on the segment */
                e = o > 0 ? PLATEAU__DT_NEXT(g) : PLATEAU__DT_PREV(g);
            }
            if (split) break; /* the pieces are on the pending list */
            d->cur_seg = sg;
            {
                plateau_dt_result r = plateau__dt_recover(d, a, w, *work, k, *work + 2 * k);
                if (r != PLATEAU_DT_OK) return r;
            }
            a = w;
        }
    }
    return PLATEAU_DT_OK;
}

/* The largest angle bound the refinement takes (degrees; larger min_angle
 * values are clamped to it): above about 33 the refinement often does not
 * terminate, and 34 still leaves room above the proven 26.45. */
#define PLATEAU__DT_MAX_MIN_ANGLE 34

#ifndef PLATEAU_DT_NO_STEINER
/* ---- Delaunay refinement ------------------------------------------------
 * Ruppert's algorithm ("A Delaunay refinement algorithm for quality 2-
 * dimensional mesh generation", J. Algorithms 18, 1995) in the form of
 * Shewchuk's Triangle and of the incremental Delaunay meshing of Miller,
 * Pav and Walkington (CMU 02-CNA-023, 2002): split encroached subsegments
 * first (at the midpoint, or on concentric shells of power-of-two radius
 * around an input vertex, which keeps small input angles from causing
 * endless splitting); otherwise take a bad triangle (an angle below the
 * bound, or an area above the limit) and insert its circumcentre, unless
 * the circumcentre lies beyond a segment or would encroach upon one: then
 * those subsegments are split instead.  Triangles whose smallest angle is
 * an input angle between two segments are exempt. */

typedef struct plateau__dt_refiner {
    double sin2;          /* sin^2 of the angle bound, 0 if none */
    double max_area;      /* scaled units, 0 if none */
    double (*area_fn)(double, double, void *);
    void *area_user;
    double unscale;       /* 2^-shift */
    int keep_segments;
    size_t budget;
    plateau_index *tq;    /* queue of triangles to test */
    size_t tq_head, tq_n, tq_cap;
    plateau_index *sq;    /* stack of subsegments (vertex pairs) to split */
    size_t sq_n, sq_cap;
    plateau_index *cav;   /* cavity work list */
    size_t cav_cap;
    size_t unrefined;
    plateau_index *cluster; /* per segment id, two slots of 3 vertex ids
                               (apex, u, w): the segment meets another (or
                               a hull edge) at apex, at the angle u-apex-w
                               (counter-clockwise) below the cluster angle
                               (1.5 min_angle); -1 */
    plateau_index nseg;   /* segment ids (input segments, then hull edges) */
    double cos2_cluster;  /* cos^2 of the largest angle that makes a cluster */
} plateau__dt_refiner;

static int plateau__dt_rq_push_tri(plateau__dt *d, plateau__dt_refiner *q, plateau_index t)
{
    if (q->tq_head > 0 && q->tq_head == q->tq_n) q->tq_head = q->tq_n = 0;
    if (q->tq_n == q->tq_cap && q->tq_head > q->tq_cap / 2) { /* compact */
        memmove(q->tq, q->tq + q->tq_head, (q->tq_n - q->tq_head) * sizeof(plateau_index));
        q->tq_n -= q->tq_head;
        q->tq_head = 0;
    }
    if (!plateau__dt_grow(&d->al, (void **)&q->tq, &q->tq_cap, sizeof(plateau_index), q->tq_n + 1))
        return 0;
    q->tq[q->tq_n++] = t;
    return 1;
}

/* forced: split even when no vertex encroaches (a circumcentre would) */
static int plateau__dt_rq_push_seg(plateau__dt *d, plateau__dt_refiner *q, plateau_index a,
                                   plateau_index b, int forced)
{
    if (!plateau__dt_grow(&d->al, (void **)&q->sq, &q->sq_cap, sizeof(plateau_index), q->sq_n + 3))
        return 0;
    q->sq[q->sq_n++] = a;
    q->sq[q->sq_n++] = b;
    q->sq[q->sq_n++] = forced;
    return 1;
}

/* 1 if the point p lies strictly inside the diametral circle of (a, b). */
static int plateau__dt_in_diametral(const double *a, const double *b, const double *p)
{
    return (a[0] - p[0]) * (b[0] - p[0]) + (a[1] - p[1]) * (b[1] - p[1]) < 0;
}

/* 1 if the constrained edge e is encroached upon by the apex of one of its
 * triangles inside the domain. */
static int plateau__dt_encroached(const plateau__dt *d, plateau_index e)
{
    plateau_index h = d->ta[e], k;
    const double *a = PLATEAU__DT_P(d, d->tv[e]), *b = PLATEAU__DT_P(d, d->tv[h]);
    for (k = 0; k < 2; k++) {
        plateau_index f = k ? h : e, apex = d->tv[PLATEAU__DT_PREV(f)];
        if (apex == PLATEAU__DT_GHOST || !d->tin[f / 3]) continue;
        if (plateau__dt_in_diametral(a, b, PLATEAU__DT_P(d, apex))) return 1;
    }
    return 0;
}

/* Push the triangles around vertex x and queue the constrained edges
 * opposite x that x encroaches upon. */
static plateau_dt_result plateau__dt_after_insert(plateau__dt *d, plateau__dt_refiner *q,
                                                  plateau_index x)
{
    plateau_index h0 = d->vt[x], h = h0, guard = 0;
    do {
        plateau_index t = h / 3, opp = PLATEAU__DT_NEXT(h);
        if (d->tin[t]) {
            if (!plateau__dt_rq_push_tri(d, q, t)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
            if (d->tc[opp] && plateau__dt_in_diametral(PLATEAU__DT_P(d, d->tv[opp]),
                                                       PLATEAU__DT_P(d, d->tv[PLATEAU__DT_NEXT(opp)]),
                                                       PLATEAU__DT_P(d, x)) &&
                !plateau__dt_rq_push_seg(d, q, d->tv[opp], d->tv[PLATEAU__DT_NEXT(opp)], 0))
                return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        }
        h = d->ta[PLATEAU__DT_PREV(h)];
        if (++guard > d->nt) return PLATEAU_DT_ERR_INTERNAL; /* a broken vertex ring */
    } while (h != h0);
    return PLATEAU_DT_OK;
}

/* Split the subsegment (a, b) (if it still exists): at its midpoint, or,
 * when exactly one end is an input vertex, at the power of two distance
 * from that end that lies between a third and two thirds of the length
 * (Ruppert's concentric shells). */
static int plateau__dt_split_point(const plateau__dt *d, plateau_index e, double *pp)
{
    plateau_index a = d->tv[e], b = d->tv[PLATEAU__DT_NEXT(e)], h = d->ta[e], k;
    const double *pa = PLATEAU__DT_P(d, a), *pb = PLATEAU__DT_P(d, b);
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1], len = PLATEAU_SQRT(dx * dx + dy * dy), f = 0.5;
    if ((a <= d->ninput) != (b <= d->ninput) && len > 0) {
        double s = plateau__dt_pow2(plateau__dt_exponent(len * (2.0 / 3.0)) - 1);
        f = s / len;
        if (b <= d->ninput) f = 1 - f;
    }
    pp[0] = pa[0] + f * dx;
    pp[1] = pa[1] + f * dy;
    /* the rounded point must leave all four new triangles positive */
    for (k = 0; k < 2; k++) {
        plateau_index g = k ? h : e;
        plateau_index u = d->tv[g], v = d->tv[PLATEAU__DT_NEXT(g)], w = d->tv[PLATEAU__DT_PREV(g)];
        if (w == PLATEAU__DT_GHOST) continue;
        if (plateau__dt_orient2d(pp, PLATEAU__DT_P(d, v), PLATEAU__DT_P(d, w)) <= 0 ||
            plateau__dt_orient2d(pp, PLATEAU__DT_P(d, w), PLATEAU__DT_P(d, u)) <= 0)
            return 0;
    }
    return 1;
}

static plateau_dt_result plateau__dt_split_subsegment(plateau__dt *d, plateau__dt_refiner *q,
                                                      plateau_index a, plateau_index b)
{
    plateau_index e = plateau__dt_find_edge(d, a, b), x;
    double pp[2], px, py;
    plateau_dt_result r;
    if (e == PLATEAU__DT_RING_BROKEN) return PLATEAU_DT_ERR_INTERNAL;
    if (e < 0 || !d->tc[e]) return PLATEAU_DT_OK; /* already split */
    if (q->budget == 0) return PLATEAU_DT_OK;
    if (!plateau__dt_split_point(d, e, pp)) return PLATEAU_DT_OK; /* a sliver is in the way */
    q->budget--;
    px = pp[0];
    py = pp[1];
    r = plateau__dt_reserve_vertices(d, 1);
    if (r != PLATEAU_DT_OK) return r;
    r = plateau__dt_reserve_triangles(d, 2);
    if (r != PLATEAU_DT_OK) return r;
    x = d->nv++;
    d->xy[2 * (size_t)x] = px;
    d->xy[2 * (size_t)x + 1] = py;
    d->outid[x] = x - 1;
    d->vseg[x] = d->ts ? d->ts[e] : -1;
    if (!plateau__dt_split_edge(d, e, x)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    r = plateau__dt_legalize(d);
    if (r != PLATEAU_DT_OK) return r;
    {
        /* x is the rounded split point, off the segment by up to an ulp:
         * the edges at x are tested too (when features are near the ulp
         * scale, x can fall outside a neighbouring circumcircle) */
        plateau_index h0 = d->vt[x], h = h0, guard = 0, nn = 0, i;
        do { /* the neighbours of x, in q->cav (free here) */
            if (!plateau__dt_grow(&d->al, (void **)&q->cav, &q->cav_cap, sizeof(plateau_index),
                                  (size_t)nn + 1))
                return PLATEAU_DT_ERR_OUT_OF_MEMORY;
            q->cav[nn++] = d->tv[PLATEAU__DT_NEXT(h)];
            h = d->ta[PLATEAU__DT_PREV(h)];
            if (++guard > d->nt) return PLATEAU_DT_ERR_INTERNAL; /* a broken vertex ring */
        } while (h != h0);
        for (i = 0; i < nn; i++) {
            r = plateau__dt_restore_from(d, x, q->cav[i]);
            if (r != PLATEAU_DT_OK) return r;
        }
    }
    if (!plateau__dt_rq_push_seg(d, q, a, x, 0) || !plateau__dt_rq_push_seg(d, q, x, b, 0))
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    return plateau__dt_after_insert(d, q, x);
}

/* Two lengths within this fraction of their sum are equal: the shortest
 * edge of a triangle between two concentric shells. */
#define PLATEAU__DT_SHELL_TIE 1e-6

/* Which bounds triangle t violates: bit 0 an area limit, bit 1 the angle
 * bound, bit 2 the angle bound at an input angle between two segments
 * (exempt); 0 if it is fine. */
static int plateau__dt_bad_triangle(const plateau__dt *d, const plateau__dt_refiner *q,
                                    plateau_index t)
{
    const plateau_index *v = d->tv + 3 * (size_t)t;
    const double *p[3];
    double l[3], area2;
    int k, m;
    for (k = 0; k < 3; k++) p[k] = PLATEAU__DT_P(d, v[k]);
    for (k = 0; k < 3; k++) { /* l[k]: squared length of the edge opposite corner k */
        const double *a = p[(k + 1) % 3], *b = p[(k + 2) % 3];
        l[k] = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
    }
    area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    if (q->max_area > 0 && 0.5 * area2 > q->max_area) return 1;
    if (q->area_fn) {
        double cx = (p[0][0] + p[1][0] + p[2][0]) / 3 * q->unscale;
        double cy = (p[0][1] + p[1][1] + p[2][1]) / 3 * q->unscale;
        double lim = q->area_fn(cx, cy, q->area_user);
        if (lim > 0 && 0.5 * area2 * q->unscale * q->unscale > lim) return 1;
    }
    if (q->sin2 <= 0) return 0;
    /* (the area test comes first: an area violation is always fixable) */
    m = 0; /* the corner with the smallest angle: opposite the shortest edge */
    for (k = 1; k < 3; k++)
        if (l[k] < l[m]) m = k;
    /* sin^2 of the smallest angle = area2^2 / (product of its two sides) */
    if (area2 * area2 >= q->sin2 * l[(m + 1) % 3] * l[(m + 2) % 3]) return 0;
    /* exempt: both sides of the angle lie on segments or, in hull mode, on
     * hull edges (tc 2: they bound the refinement like segments), so it is
     * an input angle; or the shortest edge joins two points at the same
     * distance from an input vertex on two segments through it (concentric
     * shells) */
    if (d->tc[3 * t + m] != 0 && d->tc[3 * t + (m + 2) % 3] != 0) return 4;
    {
        plateau_index a = v[(m + 1) % 3], b = v[(m + 2) % 3], o = v[m];
        if (d->vseg[a] >= 0 && d->vseg[b] >= 0 && d->vseg[a] != d->vseg[b] && o <= d->ninput) {
            double la = l[(m + 2) % 3], lb = l[(m + 1) % 3];
            if (PLATEAU_FABS(la - lb) <= PLATEAU__DT_SHELL_TIE * (la + lb)) return 4;
        }
    }
    return 2;
}

/* Insert vertex (px, py), which lies in triangle cur of the domain. */
static plateau_dt_result plateau__dt_refine_insert(plateau__dt *d, plateau__dt_refiner *q,
                                                   plateau_index cur, double px, double py)
{
    plateau_index x, dup;
    plateau_dt_result r;
    if (q->budget == 0) return PLATEAU_DT_OK;
    q->budget--;
    r = plateau__dt_reserve_vertices(d, 1);
    if (r != PLATEAU_DT_OK) return r;
    x = d->nv;
    d->xy[2 * (size_t)x] = px;
    d->xy[2 * (size_t)x + 1] = py;
    d->outid[x] = x - 1;
    d->vseg[x] = -1;
    d->last = cur;
    r = plateau__dt_insert(d, x, &dup);
    if (r != PLATEAU_DT_OK || dup) return r;
    d->nv++;
    return plateau__dt_after_insert(d, q, x);
}

/* Shewchuk's "Terminator" (Delaunay refinement algorithms for triangular
 * mesh generation, Comput. Geom. 22, 2002, section 6), in this form: a
 * skinny triangle inside a small input angle (two segments, or a segment
 * and a hull edge, meeting at less than 1.5 min_angle), whose circumcentre
 * would split a subsegment of one of them, is left as it is when the new
 * vertex would lie closer to an end of that subsegment than the triangle's
 * circumradius (the insertion radius of the circumcentre).  Splitting there
 * is what makes refinement at a small angle cascade towards its apex: each
 * split would create shorter edges than the ones it was meant to fix.
 * Triangles outside small angles are refined as usual; the ones left are
 * counted in num_unrefined.  Their smallest angle is at least
 * arctan(sin p / (2 - cos p)), p the input angle they lie in (Shewchuk's
 * bound, reached by the triangle between the first two concentric shells;
 * the tests check it for p = 1..29 degrees). */
static int plateau__dt_terminator(const plateau__dt *d, const plateau__dt_refiner *q,
                                  plateau_index t, plateau_index e, const double *pp)
{
    plateau_index sid = d->ts ? d->ts[e] : -1;
    const plateau_index *v = d->tv + 3 * (size_t)t;
    const double *a = PLATEAU__DT_P(d, d->tv[e]), *b = PLATEAU__DT_P(d, d->tv[PLATEAU__DT_NEXT(e)]);
    const double *p0 = PLATEAU__DT_P(d, v[0]), *p1 = PLATEAU__DT_P(d, v[1]), *p2 = PLATEAU__DT_P(d, v[2]);
    double l0, l1, l2, area2, r2, ra, rb;
    if (sid < 0 || sid >= q->nseg) return 0;
    {
        /* only triangles inside a small angle of the segment's cluster */
        double cen[2];
        int slot, inside = 0;
        cen[0] = (p0[0] + p1[0] + p2[0]) / 3;
        cen[1] = (p0[1] + p1[1] + p2[1]) / 3;
        for (slot = 0; slot < 2 && !inside; slot++) {
            const plateau_index *w = q->cluster + 6 * (size_t)sid + 3 * slot;
            if (w[0] < 0) continue;
            inside = plateau__dt_orient2d(PLATEAU__DT_P(d, w[0]), PLATEAU__DT_P(d, w[1]), cen) >= 0 &&
                     plateau__dt_orient2d(PLATEAU__DT_P(d, w[0]), cen, PLATEAU__DT_P(d, w[2])) >= 0;
        }
        if (!inside) return 0;
    }
    l0 = (p1[0] - p2[0]) * (p1[0] - p2[0]) + (p1[1] - p2[1]) * (p1[1] - p2[1]);
    l1 = (p2[0] - p0[0]) * (p2[0] - p0[0]) + (p2[1] - p0[1]) * (p2[1] - p0[1]);
    l2 = (p0[0] - p1[0]) * (p0[0] - p1[0]) + (p0[1] - p1[1]) * (p0[1] - p1[1]);
    area2 = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
    if (!(area2 != 0)) return 1;
    r2 = l0 * l1 * l2 / (4 * area2 * area2); /* circumradius^2 = (abc / 4A)^2 */
    ra = (pp[0] - a[0]) * (pp[0] - a[0]) + (pp[1] - a[1]) * (pp[1] - a[1]);
    rb = (pp[0] - b[0]) * (pp[0] - b[0]) + (pp[1] - b[1]) * (pp[1] - b[1]);
    return (ra < rb ? ra : rb) < r2;
}

/* Fix the bad triangle t: insert its circumcentre; or, when a segment is in
 * the way or the circumcentre would encroach upon subsegments, queue those
 * for splitting (and t again).  When no split is possible (keep_segments,
 * or a sliver next to the segment), a triangle that is too large gets its
 * centroid instead, and a triangle that is only too thin is left. */
static plateau_dt_result plateau__dt_fix_triangle(plateau__dt *d, plateau__dt_refiner *q,
                                                  plateau_index t, int area_bad)
{
    const plateau_index *v = d->tv + 3 * (size_t)t;
    const double *a = PLATEAU__DT_P(d, v[0]), *b = PLATEAU__DT_P(d, v[1]), *c = PLATEAU__DT_P(d, v[2]);
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double den = 2 * (bx * cy - by * cx), bl = bx * bx + by * by, cl = cx * cx + cy * cy;
    double cc[2], pp[2];
    plateau_index cur = t, guard = 0, ncav = 0, i;
    int blocked = 0, queued = 0;
    if (!(den != 0)) return PLATEAU_DT_OK;
    cc[0] = a[0] + (cy * bl - by * cl) / den; /* the circumcentre */
    cc[1] = a[1] + (bx * cl - cx * bl) / den;
    /* walk from t towards the circumcentre; a segment in the way is split */
    for (;;) {
        const plateau_index *w = d->tv + 3 * (size_t)cur;
        int k, moved = 0;
        if (++guard > d->nt) return PLATEAU_DT_ERR_INTERNAL; /* the walk cycled */
        for (k = 0; k < 3 && !moved && !blocked; k++) {
            plateau_index e = 3 * cur + k;
            if (plateau__dt_orient2d(PLATEAU__DT_P(d, w[k]), PLATEAU__DT_P(d, w[(k + 1) % 3]), cc) >= 0)
                continue;
            if (d->tc[e]) {
                blocked = 1;
                if (!q->keep_segments && plateau__dt_split_point(d, e, pp) &&
                    (area_bad || !plateau__dt_terminator(d, q, t, e, pp))) {
                    if (!plateau__dt_rq_push_seg(d, q, w[k], w[(k + 1) % 3], 1))
                        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
                    queued = 1;
                }
            } else {
                cur = d->ta[e] / 3;
                moved = 1;
            }
        }
        if (blocked || !moved) break;
        if (!(d->tin[cur] & 1) || plateau__dt_is_ghost(d, cur)) return PLATEAU_DT_OK;
    }
    if (!blocked) {
        /* the cavity (triangles whose circumcircle holds cc, not across
         * segments): a subsegment on its boundary that cc would encroach
         * upon is split instead of inserting cc */
        if (!plateau__dt_grow(&d->al, (void **)&q->cav, &q->cav_cap, sizeof(plateau_index), 1))
            return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        q->cav[ncav++] = cur;
        d->tin[cur] |= 2; /* bit 1: in the cavity */
        for (i = 0; i < ncav; i++) {
            plateau_index u = q->cav[i];
            int k;
            for (k = 0; k < 3; k++) {
                plateau_index e = 3 * u + k, nb = d->ta[e] / 3;
                const double *p0 = PLATEAU__DT_P(d, d->tv[e]);
                const double *p1 = PLATEAU__DT_P(d, d->tv[PLATEAU__DT_NEXT(e)]);
                if (d->tc[e]) {
                    if (plateau__dt_in_diametral(p0, p1, cc)) {
                        blocked = 1;
                        if (!q->keep_segments && plateau__dt_split_point(d, e, pp) &&
                            (area_bad || !plateau__dt_terminator(d, q, t, e, pp))) {
                            if (!plateau__dt_rq_push_seg(d, q, d->tv[e], d->tv[PLATEAU__DT_NEXT(e)], 1))
                                return PLATEAU_DT_ERR_OUT_OF_MEMORY;
                            queued = 1;
                        }
                    }
                    continue;
                }
                if ((d->tin[nb] & 2) || !(d->tin[nb] & 1) || plateau__dt_is_ghost(d, nb)) continue;
                if (plateau__dt_incircle(PLATEAU__DT_P(d, d->tv[3 * nb]), PLATEAU__DT_P(d, d->tv[3 * nb + 1]),
                                         PLATEAU__DT_P(d, d->tv[3 * nb + 2]), cc) > 0) {
                    if (!plateau__dt_grow(&d->al, (void **)&q->cav, &q->cav_cap, sizeof(plateau_index),
                                          (size_t)ncav + 1))
                        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
                    q->cav[ncav++] = nb;
                    d->tin[nb] |= 2;
                }
            }
        }
        for (i = 0; i < ncav; i++) d->tin[q->cav[i]] &= 1;
    }
    if (queued) return plateau__dt_rq_push_tri(d, q, t) ? PLATEAU_DT_OK : PLATEAU_DT_ERR_OUT_OF_MEMORY;
    if (blocked) {
        if (!area_bad) return PLATEAU_DT_OK; /* left as it is */
        return plateau__dt_refine_insert(d, q, t, (a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3);
    }
    return plateau__dt_refine_insert(d, q, cur, cc[0], cc[1]);
}

/* pi, for degrees; segments meeting at less than PLATEAU__DT_CLUSTER times
 * the angle bound form a cluster (the input angles phase 6 exempts). */
#define PLATEAU__DT_PI 3.14159265358979323846
#define PLATEAU__DT_CLUSTER 1.5
/* Records the angle between the half-edges e and f leaving v in the
 * cluster slots of their segments when it is below the cluster angle. */
static void plateau__dt_mark_small(const plateau__dt *d, plateau__dt_refiner *q, plateau_index v,
                                   plateau_index e, plateau_index f)
{
    const double *o = PLATEAU__DT_P(d, v);
    const double *a = PLATEAU__DT_P(d, d->tv[PLATEAU__DT_NEXT(e)]);
    const double *b = PLATEAU__DT_P(d, d->tv[PLATEAU__DT_NEXT(f)]);
    double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
    double dot = ux * wx + uy * wy;
    if (d->tv[PLATEAU__DT_NEXT(e)] == PLATEAU__DT_GHOST || d->tv[PLATEAU__DT_NEXT(f)] == PLATEAU__DT_GHOST)
        return;
    if (dot > 0 && dot * dot > q->cos2_cluster * (ux * ux + uy * uy) * (wx * wx + wy * wy)) {
        plateau_index u = d->tv[PLATEAU__DT_NEXT(e)], w = d->tv[PLATEAU__DT_NEXT(f)], k;
        if (ux * wy - uy * wx < 0) { k = u; u = w; w = k; } /* counter-clockwise */
        for (k = 0; k < 2; k++) {
            plateau_index sid = d->ts[k ? f : e], *c;
            if (sid < 0 || sid >= q->nseg) continue;
            c = q->cluster + 6 * (size_t)sid;
            if (c[0] >= 0) c += 3; /* the first slot is taken: the other end */
            c[0] = v; c[1] = u; c[2] = w;
        }
    }
}

/* Segment clusters for the Terminator: every constrained edge gets a
 * segment id (hull edges that bound the refinement get fresh ones), and a
 * segment is in a cluster when, at one of its vertices, it and the next
 * constrained edge around that vertex make an angle below the cluster
 * angle. */
static plateau_dt_result plateau__dt_clusters(plateau__dt *d, plateau__dt_refiner *q)
{
    plateau_index t, v, nid = 0;
    if (!d->ts) return PLATEAU_DT_OK;
    for (t = 0; t < 3 * d->nt; t++)
        if (d->ts[t] >= nid) nid = d->ts[t] + 1;
    for (t = 0; t < 3 * d->nt; t++)
        if (d->tc[t] && d->ts[t] < 0) {
            if (nid == PLATEAU_INDEX_MAX) return PLATEAU_DT_ERR_OVERFLOW;
            d->ts[t] = d->ts[d->ta[t]] = nid++;
        }
    q->nseg = nid;
    q->cluster = (plateau_index *)plateau__alloc(
        &d->al, plateau__bytes(6 * ((size_t)nid + 1), sizeof(plateau_index)));
    if (!q->cluster) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    for (t = 0; t < 6 * (nid + 1); t++) q->cluster[t] = -1;
    for (v = 1; v < d->nv; v++) {
        plateau_index h0 = d->vt[v], h, first = -1, prev = -1, guard = 0;
        if (h0 < 0) continue;
        h = h0;
        do { /* constrained edges leaving v, in rotation order */
            if (d->tc[h]) {
                if (prev >= 0) plateau__dt_mark_small(d, q, v, prev, h);
                else first = h;
                prev = h;
            }
            h = d->ta[PLATEAU__DT_PREV(h)];
            if (++guard > d->nt) return PLATEAU_DT_ERR_INTERNAL; /* a broken vertex ring */
        } while (h != h0);
        if (first >= 0 && prev != first) plateau__dt_mark_small(d, q, v, prev, first);
    }
    return PLATEAU_DT_OK;
}

static plateau_dt_result plateau__dt_refine(plateau__dt *d, const plateau_dt_options *opt,
                                            plateau_dt_refine_stop *stop, size_t *unrefined)
{
    plateau__dt_refiner q;
    plateau_dt_result r = PLATEAU_DT_OK;
    plateau_index t;
    size_t guard = 0, limit, budget0, next_report;
    int cancelled = 0;
    double ang = opt->min_angle;
    memset(&q, 0, sizeof q);
    if (ang > PLATEAU__DT_MAX_MIN_ANGLE) ang = PLATEAU__DT_MAX_MIN_ANGLE;
    if (ang > 0) {
        double s = PLATEAU_SIN(ang * PLATEAU__DT_PI / 180);
        q.sin2 = s * s;
    }
    q.unscale = plateau__dt_pow2(-d->shift / 2) * plateau__dt_pow2(-d->shift - (-d->shift / 2));
    q.max_area = opt->max_area > 0 ? opt->max_area / q.unscale / q.unscale : 0;
    q.area_fn = opt->max_area_fn;
    q.area_user = opt->max_area_user;
    q.keep_segments = opt->keep_segments != 0;
    q.budget = opt->max_added_points ? opt->max_added_points
                                     : 10 * (size_t)d->ninput + (size_t)4194304;
    limit = 64 * (q.budget + (size_t)d->nt) + 1024;
    {
        /* clusters: segments meeting at less than 1.5 min_angle (at most
         * 51 degrees); wider input angles are refined as usual (Ruppert's
         * splitting on concentric shells handles them) */
        double c = PLATEAU_COS(PLATEAU__DT_CLUSTER * ang * PLATEAU__DT_PI / 180);
        q.cos2_cluster = ang > 0 ? c * c : 2; /* 2: no cluster */
    }
    r = plateau__dt_clusters(d, &q);
    if (r != PLATEAU_DT_OK) goto out;
    /* start: every triangle of the domain, every encroached subsegment */
    for (t = 0; t < d->nt; t++) {
        int k;
        if (!(d->tin[t] & 1)) continue;
        if (!plateau__dt_rq_push_tri(d, &q, t)) { r = PLATEAU_DT_ERR_OUT_OF_MEMORY; goto out; }
        for (k = 0; k < 3; k++) {
            plateau_index e = 3 * t + k;
            if (d->tc[e] && plateau__dt_encroached(d, e) && !q.keep_segments &&
                !plateau__dt_rq_push_seg(d, &q, d->tv[e], d->tv[PLATEAU__DT_NEXT(e)], 0)) {
                r = PLATEAU_DT_ERR_OUT_OF_MEMORY;
                goto out;
            }
        }
    }
    budget0 = q.budget;
    next_report = 0; /* progress: once as the refinement starts, then every 1024 vertices */
    while ((q.sq_n || q.tq_head < q.tq_n) && q.budget > 0) {
        if (++guard > limit) { r = PLATEAU_DT_ERR_INTERNAL; goto out; }
        if (opt->progress && budget0 - q.budget >= next_report) {
            next_report = budget0 - q.budget + 1024;
            if (opt->progress((size_t)d->nv - 1, opt->progress_user)) {
                cancelled = 1;
                break;
            }
        }
        if (q.sq_n) { /* encroached subsegments first */
            plateau_index forced = q.sq[--q.sq_n], b = q.sq[--q.sq_n], a = q.sq[--q.sq_n];
            plateau_index e = plateau__dt_find_edge(d, a, b);
            if (e == PLATEAU__DT_RING_BROKEN) { r = PLATEAU_DT_ERR_INTERNAL; goto out; }
            if (e < 0 || !d->tc[e] || q.keep_segments) continue;
            if (!forced && !plateau__dt_encroached(d, e)) continue;
            r = plateau__dt_split_subsegment(d, &q, a, b);
            if (r != PLATEAU_DT_OK) goto out;
            continue;
        }
        t = q.tq[q.tq_head++];
        if (t >= d->nt || !(d->tin[t] & 1) || plateau__dt_is_ghost(d, t)) continue;
        {
            int bad = plateau__dt_bad_triangle(d, &q, t);
            if (bad & 3) r = plateau__dt_fix_triangle(d, &q, t, bad & 1);
            if (r != PLATEAU_DT_OK) goto out;
        }
    }
    *stop = cancelled ? PLATEAU_DT_REFINE_CANCELLED
            : (q.sq_n || q.tq_head < q.tq_n) && q.budget == 0 ? PLATEAU_DT_REFINE_BUDGET
                                                              : PLATEAU_DT_REFINE_DONE;
    /* count what is left beyond the bounds */
    for (t = 0; t < d->nt; t++)
        if ((d->tin[t] & 1) && !plateau__dt_is_ghost(d, t) && plateau__dt_bad_triangle(d, &q, t))
            q.unrefined++;
    *unrefined = q.unrefined;
out:
    plateau__free(&d->al, q.tq);
    plateau__free(&d->al, q.sq);
    plateau__free(&d->al, q.cav);
    plateau__free(&d->al, q.cluster);
    return r;
}

#endif /* PLATEAU_DT_NO_STEINER */

/* ---- Public functions ------------------------------------------------- */

PLATEAU_DT_DEF PLATEAU__COLD const char *plateau_dt_result_string(plateau_dt_result result)
{
    switch (result) {
#define PLATEAU__DT_CASE(name, value, text) \
    case name: return text;
        PLATEAU_DT_RESULT_LIST(PLATEAU__DT_CASE)
#undef PLATEAU__DT_CASE
    default: break;
    }
    return "unknown result";
}

PLATEAU_DT_DEF PLATEAU__COLD const char *plateau_dt_refine_stop_string(plateau_dt_refine_stop stop)
{
    switch (stop) {
#define PLATEAU__DT_CASE(name, value, text) \
    case name: return text;
        PLATEAU_DT_REFINE_STOP_LIST(PLATEAU__DT_CASE)
#undef PLATEAU__DT_CASE
    default: break;
    }
    return "unknown stop";
}

#define PLATEAU__DT_DEFAULT_SEED PLATEAU__U64(0x706C6174u, 0x65617531u)
/* The start of the walk's xorshift32 generator (Marsaglia 2003: the state
 * of his example; any non-zero state works). */
#define PLATEAU__DT_WALK_SEED 2463534242u

PLATEAU_DT_DEF PLATEAU__COLD plateau_dt_options plateau_dt_resolved_options(const plateau_dt_options *options)
{
    plateau_dt_options o;
    if (options) o = *options;
    else memset(&o, 0, sizeof o);
    if (o.seed == 0) o.seed = (uint64_t)PLATEAU__DT_DEFAULT_SEED;
    o.keep_convex_hull = o.keep_convex_hull != 0;
    o.split_crossing_segments = o.split_crossing_segments != 0;
    o.keep_segments = o.keep_segments != 0;
    if (o.min_angle > PLATEAU__DT_MAX_MIN_ANGLE) o.min_angle = PLATEAU__DT_MAX_MIN_ANGLE;
    /* max_added_points 0 stays 0: its default (10 n + 4194304) needs n */
    return o;
}

PLATEAU_DT_DEF void plateau_dt_free(plateau_dt_mesh *mesh)
{
    plateau_allocator al;
    if (!mesh) return;
    al = mesh->allocator;
    plateau__free(&al, mesh->points);
    plateau__free(&al, mesh->duplicate_of);
    plateau__free(&al, mesh->triangles);
    plateau__free(&al, mesh->neighbors);
    plateau__free(&al, mesh->constrained);
    plateau__free(&al, mesh->segment_of);
    memset(mesh, 0, sizeof *mesh);
}

/* Scale 3 or 4 points by one power of two so that the largest coordinate
 * is near 2^200, as the triangulator does.  Returns 0 for a non-finite
 * coordinate, 2 when the scaling would lose bits of a tiny coordinate next
 * to a huge one (the caller then uses the integer path on the originals),
 * 1 otherwise. */
static int plateau__dt_scale_points(const double *const *in, int n, double (*out)[2])
{
    double m = 0;
    int i, k, s;
    for (i = 0; i < n; i++) {
        double ax = PLATEAU_FABS(in[i][0]), ay = PLATEAU_FABS(in[i][1]);
        if (!(ax <= DBL_MAX) || !(ay <= DBL_MAX)) return 0;
        if (ax > m) m = ax;
        if (ay > m) m = ay;
    }
    s = m > 0 ? plateau__dt_shift_for(m) : 0;
    for (i = 0; i < n; i++)
        for (k = 0; k < 2; k++) {
            out[i][k] = plateau__dt_ldexp(in[i][k], s);
            if (plateau__dt_ldexp(out[i][k], -s) != in[i][k]) return 2;
        }
    return 1;
}

PLATEAU_DT_DEF int plateau_dt_orient(const double *a, const double *b, const double *c)
{
    const double *in[3];
    double p[3][2], o;
    int sc;
    in[0] = a; in[1] = b; in[2] = c;
    if (!a || !b || !c) return 0;
    sc = plateau__dt_scale_points(in, 3, p);
    if (sc == 0) return 0;
    if (sc == 2) return plateau__dt_orient_big(a, b, c);
    o = plateau__dt_orient2d(p[0], p[1], p[2]);
    return o > 0 ? 1 : (o < 0 ? -1 : 0);
}

PLATEAU_DT_DEF int plateau_dt_incircle(const double *a, const double *b, const double *c,
                                       const double *d)
{
    const double *in[4];
    double p[4][2], o;
    int sc;
    in[0] = a; in[1] = b; in[2] = c; in[3] = d;
    if (!a || !b || !c || !d) return 0;
    sc = plateau__dt_scale_points(in, 4, p);
    if (sc == 0) return 0;
    if (sc == 2) return plateau__dt_incircle_big(a, b, c, d);
    o = plateau__dt_incircle(p[0], p[1], p[2], p[3]);
    return o > 0 ? 1 : (o < 0 ? -1 : 0);
}

/* Frees the triangulator's arrays (out of line: one call per exit path). */
static PLATEAU__NOINLINE void plateau__dt_release(plateau__dt *d)
{
    plateau__free(&d->al, d->xy);
    plateau__free(&d->al, d->vt);
    plateau__free(&d->al, d->outid);
    plateau__free(&d->al, d->tv);
    plateau__free(&d->al, d->ta);
    plateau__free(&d->al, d->tc);
    plateau__free(&d->al, d->tin);
    plateau__free(&d->al, d->ts);
    plateau__free(&d->al, d->vseg);
    plateau__free(&d->al, d->stack);
    plateau__free(&d->al, d->pend);
    plateau__free(&d->al, d->estack);
}

/* Remove the triangles outside the domain: flood fill from the ghost
 * triangles, counting the constrained edges crossed (the fewest); a
 * triangle is inside when that count is odd (outer boundary: 1, hole: 2,
 * island in a hole: 3, ...).  keep[t] = 1 for kept real triangles. */
static plateau_dt_result plateau__dt_domain(plateau__dt *d, unsigned char *keep, plateau_index bounding)
{
    plateau_index *depth, *cur, *next;
    size_t ncur = 0, nnext = 0, bytes = plateau__bytes((size_t)d->nt, sizeof(plateau_index));
    plateau_index t, level = 0;
    depth = (plateau_index *)plateau__alloc(&d->al, bytes);
    cur = (plateau_index *)plateau__alloc(&d->al, bytes);
    next = (plateau_index *)plateau__alloc(&d->al, bytes);
    if (!depth || !cur || !next) {
        plateau__free(&d->al, depth);
        plateau__free(&d->al, cur);
        plateau__free(&d->al, next);
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    }
    for (t = 0; t < d->nt; t++) {
        depth[t] = -1;
        if (plateau__dt_is_ghost(d, t)) {
            depth[t] = 0;
            cur[ncur++] = t;
        }
    }
    /* level by level: a depth-first fill across unconstrained edges; a
     * constrained edge leads to the next level (-2 marks "pending") */
    while (ncur) {
        while (ncur) {
            plateau_index u = cur[--ncur];
            int k;
            for (k = 0; k < 3; k++) {
                plateau_index x = d->ta[3 * u + k] / 3;
                if (depth[x] >= 0) continue;
                if (d->tc[3 * u + k] && d->ts[3 * u + k] < bounding) {
                    if (depth[x] == -1) {
                        depth[x] = -2;
                        next[nnext++] = x;
                    }
                } else {
                    depth[x] = level;
                    cur[ncur++] = x;
                }
            }
        }
        level++;
        while (nnext) {
            plateau_index x = next[--nnext];
            if (depth[x] == -2) {
                depth[x] = level;
                cur[ncur++] = x;
            }
        }
    }
    for (t = 0; t < d->nt; t++) keep[t] = (unsigned char)(depth[t] >= 0 && (depth[t] & 1));
    plateau__free(&d->al, depth);
    plateau__free(&d->al, cur);
    plateau__free(&d->al, next);
    return PLATEAU_DT_OK;
}

/* Report helpers (the report may be NULL). */
static PLATEAU__COLD void plateau__dt_error_seg(plateau_dt_error *r, size_t seg, const char *what, long a,
                                   long b)
{
    if (!r) return;
    r->index = (long)seg;
    PLATEAU_SNPRINTF(r->message, sizeof r->message, "segment %ld %s %ld and %ld", (long)seg, what, a, b);
}

/* The first triangle: vertex 1, the next vertex distinct from it, the next
 * one not collinear with them; three ghost triangles close it. */
static plateau_dt_result plateau__dt_first_triangle(plateau__dt *d, plateau_index n,
                                                    plateau_index *seeds)
{
    plateau_index a = 1, b, c, s1, s2;
    for (s1 = 2; s1 <= n; s1++)
        if (d->xy[2 * s1] != d->xy[2] || d->xy[2 * s1 + 1] != d->xy[3]) break;
    if (s1 > n) {
        plateau__dt_set_error(d->report, -1, "all points coincide");
        return PLATEAU_DT_ERR_TOO_FEW_POINTS;
    }
    for (s2 = s1 + 1; s2 <= n; s2++)
        if (plateau__dt_orient2d(PLATEAU__DT_P(d, a), PLATEAU__DT_P(d, s1), PLATEAU__DT_P(d, s2)) != 0)
            break;
    if (s2 > n) {
        plateau_index k;
        for (k = s1 + 1; k <= n; k++) /* a third distinct point? */
            if ((d->xy[2 * k] != d->xy[2] || d->xy[2 * k + 1] != d->xy[3]) &&
                (d->xy[2 * k] != d->xy[2 * s1] || d->xy[2 * k + 1] != d->xy[2 * s1 + 1]))
                break;
        if (k > n) {
            plateau__dt_set_error(d->report, -1, "only 2 distinct points");
            return PLATEAU_DT_ERR_TOO_FEW_POINTS;
        }
        plateau__dt_set_error(d->report, -1, "all points lie on one line");
        return PLATEAU_DT_ERR_COLLINEAR;
    }
    seeds[0] = a;
    seeds[1] = s1;
    seeds[2] = s2;
    b = s1;
    c = s2;
    if (plateau__dt_orient2d(PLATEAU__DT_P(d, a), PLATEAU__DT_P(d, b), PLATEAU__DT_P(d, c)) < 0) {
        b = s2;
        c = s1;
    }
    /* real triangle 0 = (a, b, c); ghosts 1 = (b, a, G), 2 = (c, b, G),
     * 3 = (a, c, G) */
    plateau__dt_set_tri(d, 0, a, b, c);
    plateau__dt_set_tri(d, 1, b, a, PLATEAU__DT_GHOST);
    plateau__dt_set_tri(d, 2, c, b, PLATEAU__DT_GHOST);
    plateau__dt_set_tri(d, 3, a, c, PLATEAU__DT_GHOST);
    plateau__dt_link(d, 0, 3);  /* a->b, b->a */
    plateau__dt_link(d, 1, 6);  /* b->c, c->b */
    plateau__dt_link(d, 2, 9);  /* c->a, a->c */
    plateau__dt_link(d, 4, 11); /* a->G, G->a */
    plateau__dt_link(d, 5, 7);  /* G->b, b->G */
    plateau__dt_link(d, 8, 10); /* G->c, c->G */
    memset(d->tc, 0, 12);
    d->nt = 4;
    d->vt[a] = 0;
    d->vt[b] = 1;
    d->vt[c] = 2;
    d->vt[PLATEAU__DT_GHOST] = 5;
    d->last = 0;
    return PLATEAU_DT_OK;
}

/* Validation of the input: finite coordinates and segment indices. */
static plateau_dt_result plateau__dt_validate(const plateau_dt_input *in, plateau_dt_error *rep,
                                              double *maxabs)
{
    size_t i, n = in->num_points;
    *maxabs = 0;
    for (i = 0; i < 2 * n; i++) {
        double a = PLATEAU_FABS(in->points[i]);
        if (!(a <= DBL_MAX)) {
            if (rep) {
                rep->index = (long)(i / 2);
                PLATEAU_SNPRINTF(rep->message, sizeof rep->message,
                         "point %ld has a NaN or infinite coordinate", (long)(i / 2));
            }
            return PLATEAU_DT_ERR_NOT_FINITE;
        }
        if (a > *maxabs) *maxabs = a;
    }
    if (*maxabs > 0) { /* phase 1's scaling must keep every coordinate exact */
        int s = plateau__dt_shift_for(*maxabs);
        for (i = 0; i < 2 * n; i++) {
            double x = in->points[i];
            if (plateau__dt_ldexp(plateau__dt_ldexp(x, s), -s) != x) {
                if (rep) {
                    rep->index = (long)(i / 2);
                    PLATEAU_SNPRINTF(rep->message, sizeof rep->message,
                             "point %ld has a coordinate (%g) too small next to the largest "
                             "(%g) to be kept exactly when scaled",
                             (long)(i / 2), x, *maxabs);
                }
                return PLATEAU_DT_ERR_RANGE;
            }
        }
    }
    for (i = 0; i < in->num_segments; i++) {
        plateau_index a = in->segments[2 * i], b = in->segments[2 * i + 1];
        if (a < 0 || b < 0 || (size_t)a >= n || (size_t)b >= n) {
            plateau__dt_error_seg(rep, i, "has an endpoint out of range: points", (long)a, (long)b);
            return PLATEAU_DT_ERR_SEGMENT_INDEX;
        }
        if (a == b) {
            plateau__dt_error_seg(rep, i, "is degenerate: it joins points", (long)a, (long)b);
            return PLATEAU_DT_ERR_DEGENERATE_SEGMENT;
        }
    }
    if (n < 3) {
        plateau__dt_set_error(rep, -1, "fewer than 3 points");
        return PLATEAU_DT_ERR_TOO_FEW_POINTS;
    }
    return PLATEAU_DT_OK;
}

/* Fill the output mesh from the triangulation; keep[t] selects triangles;
 * dupv[v] is the vertex id a duplicate input point coincided with (0 if it
 * was inserted).  To keep the peak low the triangle arrays become the
 * output in place: kept triangle t is written to slot j <= t in the same
 * arrays (a forward pass reads each slot before any later write can reach
 * it), so the vertex, neighbour and flag arrays are handed to the mesh
 * instead of copied, and so is the coordinate array.  The new index of a
 * kept triangle is its rank among the kept ones, held in keep itself (bit
 * 7: kept; bits 0-6: the kept ones before it in its block of 128) and a
 * count per block: a byte per triangle instead of a 32-bit map. */
static plateau_dt_result plateau__dt_output(plateau__dt *d, const plateau_dt_input *in,
                                            unsigned char *keep, const plateau_index *dupv,
                                            plateau_dt_mesh *mesh)
{
    size_t n = in->num_points, np = (size_t)d->nv - 1, nkept = 0, i, j, nw, ndup = 0;
    size_t nt = (size_t)d->nt;
    plateau_index t, v, *outid = d->outid, *tv = d->tv, *ta = d->ta;
    unsigned char *tc = d->tc;
    plateau_index *rank;
    nw = nt / 128 + 1;
    rank = (plateau_index *)plateau__alloc(&d->al, plateau__bytes(nw, sizeof(plateau_index)));
    if (!rank) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    for (i = 0; i < nt; i++) {
        if (!(i & 127)) rank[i >> 7] = (plateau_index)nkept;
        if (keep[i]) {
            keep[i] = (unsigned char)(128u | ((size_t)nkept - (size_t)rank[i >> 7]));
            nkept++;
        }
    }
    mesh->num_points = np;
    mesh->num_input_points = n;
    mesh->num_triangles = nkept;
    mesh->duplicate_of =
        (plateau_index *)plateau__alloc(&d->al, plateau__bytes(n, sizeof(plateau_index)));
    mesh->segment_of =
        (plateau_index *)plateau__alloc(&d->al, plateau__bytes(np, sizeof(plateau_index)));
    if (!mesh->duplicate_of || !mesh->segment_of) {
        plateau__free(&d->al, rank);
        return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    }
    for (i = 0; i < np; i++)
        mesh->segment_of[i] = (i >= n && d->vseg && d->vseg[i + 1] >= 0 &&
                               (size_t)d->vseg[i + 1] < in->num_segments)
                                  ? d->vseg[i + 1]
                                  : -1; /* hull edges have internal ids beyond */
    /* The points, in place too (room for nv > np pairs): the added vertices
     * move down one slot, scaled back (exact; ascending, so each slot is
     * read before it is written), then the input points fill the front. */
    for (i = n; i < np; i++) {
        d->xy[2 * i] = plateau__dt_ldexp(d->xy[2 * (i + 1)], -d->shift);
        d->xy[2 * i + 1] = plateau__dt_ldexp(d->xy[2 * (i + 1) + 1], -d->shift);
    }
    memcpy(d->xy, in->points, 2 * n * sizeof(double));
    mesh->points = d->xy;
    d->xy = NULL;
    /* An inserted vertex is output as the smallest input index among the
     * points that coincide with it: duplicate_of holds that index, and
     * outid becomes the output index of each vertex id. */
    for (i = 0; i < n; i++) mesh->duplicate_of[i] = (plateau_index)i;
    for (v = 1; v <= (plateau_index)n; v++) ndup += dupv[v] != 0;
    if (ndup) { /* without duplicates outid already is the output index */
        for (v = 1; v <= (plateau_index)n; v++)
            if (dupv[v] && outid[v] < mesh->duplicate_of[outid[dupv[v]]])
                mesh->duplicate_of[outid[dupv[v]]] = outid[v];
        for (v = 1; v <= (plateau_index)n; v++)
            if (dupv[v]) mesh->duplicate_of[outid[v]] = mesh->duplicate_of[outid[dupv[v]]];
        for (v = 1; v < d->nv; v++)
            outid[v] = v <= (plateau_index)n ? mesh->duplicate_of[outid[v]] : v - 1;
    }
    outid[0] = -1;
    for (t = 0, j = 0; t < d->nt; t++) {
        int k;
        if (!keep[t]) continue;
        for (k = 0; k < 3; k++) {
            size_t nb = (size_t)ta[3 * t + k] / 3;
            tv[3 * j + (size_t)k] = outid[tv[3 * t + k]];
            tc[3 * j + (size_t)k] = (unsigned char)(tc[3 * t + k] == 1);
            ta[3 * j + (size_t)k] = keep[nb] ? rank[nb >> 7] + (plateau_index)(keep[nb] & 127u) : -1;
        }
        j++;
    }
    plateau__free(&d->al, rank);
    mesh->triangles = tv;
    mesh->neighbors = ta;
    mesh->constrained = tc;
    d->tv = d->ta = NULL;
    d->tc = NULL;
    return PLATEAU_DT_OK;
}

/* The arguments of plateau_dt_triangulate, before the points themselves
 * (plateau__dt_validate). */
static plateau_dt_result plateau__dt_check_args(const plateau_dt_input *input, const plateau_dt_options *opt,
                                                const plateau_dt_mesh *mesh, plateau_dt_error *report)
{
    if (!input || !mesh || (!input->points && input->num_points) ||
        (!input->segments && input->num_segments) || !plateau__allocator_valid(&opt->allocator)) {
        plateau__dt_set_error(report, -1,
                               "a required pointer is NULL, or the allocator sets only one "
                               "of alloc_fn and free_fn");
        return PLATEAU_DT_ERR_ARGUMENT;
    }
    if (!(opt->min_angle >= 0) || !(opt->max_area >= 0)) { /* also NaN */
        plateau__dt_set_error(report, -1, "min_angle and max_area must be zero or positive");
        return PLATEAU_DT_ERR_ARGUMENT;
    }
#ifdef PLATEAU_DT_NO_STEINER
    if (opt->min_angle > 0 || opt->max_area > 0 || opt->max_area_fn || opt->split_crossing_segments) {
        plateau__dt_set_error(report, -1,
                               "min_angle, max_area, max_area_fn and split_crossing_segments add "
                               "points, compiled out by PLATEAU_DT_NO_STEINER");
        return PLATEAU_DT_ERR_ARGUMENT;
    }
#endif
    if (opt->inner_segments > input->num_segments) {
        plateau__dt_set_error(report, -1, "inner_segments is more than num_segments");
        return PLATEAU_DT_ERR_ARGUMENT;
    }
    if (input->num_points > (size_t)PLATEAU_INDEX_MAX / 8 ||
        input->num_segments > (size_t)PLATEAU_INDEX_MAX / 4) {
        plateau__dt_set_error(report, -1, "too many points or segments for plateau_index");
        return PLATEAU_DT_ERR_OVERFLOW;
    }
    return PLATEAU_DT_OK;
}

/* Phases 1-3: the points scaled by a power of two (exact) so that the
 * largest coordinate is just below 2^200, where the predicates neither
 * overflow nor underflow (ROBUSTNESS at the top); put in the BRIO
 * insertion order; inserted one by one (Lawson's algorithm with a ghost
 * vertex).  *dupv[v] is the vertex a duplicate point v merged into (0:
 * none); *inv (with segments only) maps an input index to its vertex. */
static plateau_dt_result plateau__dt_insert_points(plateau__dt *d, const plateau_dt_input *input,
                                                   uint64_t seed, double maxabs,
                                                   plateau_index **dupv, plateau_index **inv)
{
    size_t n = input->num_points, i;
    double f1, f2;
    plateau_index seeds[3], v;
    plateau_dt_result r;
    d->shift = maxabs > 0 ? plateau__dt_shift_for(maxabs) : 0;
    r = plateau__dt_reserve_vertices(d, (plateau_index)n + 1);
    if (r != PLATEAU_DT_OK) return r;
    r = plateau__dt_reserve_triangles(d, (plateau_index)(2 * n + 8));
    if (r != PLATEAU_DT_OK) return r;
    *dupv = (plateau_index *)plateau__alloc(&d->al, plateau__bytes(n + 1, sizeof(plateau_index)));
    if (input->num_segments) /* input index -> vertex id, for the segments */
        *inv = (plateau_index *)plateau__alloc(&d->al, plateau__bytes(n, sizeof(plateau_index)));
    if (!*dupv || (input->num_segments && !*inv)) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    /* the insertion order, written straight into the map from vertex id
     * (1 + position in the order; id 0 is the ghost) to input index */
    PLATEAU_ASSERT(3 * (size_t)d->cap_t * sizeof(plateau_index) >= n * sizeof(uint64_t));
    plateau__dt_brio(d, input->points, n, seed, d->outid + 1, (uint64_t *)(void *)d->tv,
                     (uint64_t *)(void *)d->ta);
    f1 = plateau__dt_pow2(d->shift / 2);
    f2 = plateau__dt_pow2(d->shift - d->shift / 2);
    for (i = 0; i < n; i++) {
        plateau_index src = d->outid[i + 1];
        d->xy[2 * (i + 1)] = input->points[2 * (size_t)src] * f1 * f2;
        d->xy[2 * (i + 1) + 1] = input->points[2 * (size_t)src + 1] * f1 * f2;
        (*dupv)[i + 1] = 0;
    }
    if (*inv)
        for (i = 0; i < n; i++) (*inv)[d->outid[i + 1]] = (plateau_index)(i + 1);
    d->xy[0] = d->xy[1] = 0;
    d->outid[0] = -1;
    d->vt[0] = -1;
    (*dupv)[0] = 0;
    d->nv = (plateau_index)n + 1;
    r = plateau__dt_first_triangle(d, (plateau_index)n, seeds);
    if (r != PLATEAU_DT_OK) return r;
    for (v = 1; v <= (plateau_index)n; v++) {
        if (v == seeds[0] || v == seeds[1] || v == seeds[2]) continue;
        r = plateau__dt_insert(d, v, &(*dupv)[v]);
        if (r != PLATEAU_DT_OK) return r;
    }
    return PLATEAU_DT_OK;
}

/* After the insertion: the constraint flags, and (when segments or a
 * refinement need them) a half-edge per vertex and the segment of each
 * constrained edge and vertex. */
static plateau_dt_result plateau__dt_start_constraints(plateau__dt *d, int need)
{
    plateau_index v, t;
    memset(d->tc, 0, 3 * (size_t)d->nt);
    if (need) {
        for (v = 0; v < d->nv; v++) d->vt[v] = -1;
        for (t = 0; t < 3 * d->nt; t++) d->vt[d->tv[t]] = t;
    }
    d->cons = 1;
    if (!need) return PLATEAU_DT_OK;
    d->ts = (plateau_index *)plateau__alloc(&d->al, plateau__bytes(3 * (size_t)d->cap_t, sizeof(plateau_index)));
    d->vseg = (plateau_index *)plateau__alloc(&d->al, plateau__bytes((size_t)d->cap_v, sizeof(plateau_index)));
    if (!d->ts || !d->vseg) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    for (t = 0; t < 3 * d->nt; t++) d->ts[t] = -1;
    for (v = 0; v < d->cap_v; v++) d->vseg[v] = -1;
    return PLATEAU_DT_OK;
}

/* Phase 4: the constraint segments, in input order. */
static plateau_dt_result plateau__dt_segments(plateau__dt *d, const plateau_dt_input *input,
                                              const plateau_index *inv, const plateau_index *dupv,
                                              plateau_index **work, size_t *work_cap)
{
    size_t i;
    for (i = 0; i < input->num_segments; i++) {
        plateau_index a = inv[input->segments[2 * i]], b = inv[input->segments[2 * i + 1]];
        plateau_dt_result r;
        if (dupv[a]) a = dupv[a];
        if (dupv[b]) b = dupv[b];
        if (a == b) {
            plateau__dt_error_seg(d->report, i, "is degenerate: it joins the coincident points",
                                   (long)input->segments[2 * i], (long)input->segments[2 * i + 1]);
            return PLATEAU_DT_ERR_DEGENERATE_SEGMENT;
        }
        r = plateau__dt_insert_segment(d, a, b, (long)i, work, work_cap);
        if (r != PLATEAU_DT_OK) return r;
    }
    return PLATEAU_DT_OK;
}

/* Phase 5: the domain, d->tin[t] = 1 for the triangles kept: inside the
 * closed segment loops (no segment may end freely: a vertex met by exactly
 * one constrained edge ends an open chain; *deg, the caller frees it, holds
 * the counts; the last opt->inner_segments segments neither bound nor
 * count), or the whole hull, whose edges then bound a refinement
 * (flag 2: not output; a segment on the hull keeps its own flag 1). */
static plateau_dt_result plateau__dt_keep(plateau__dt *d, const plateau_dt_input *input,
                                          const plateau_dt_options *opt, int refine,
                                          plateau_index **deg)
{
    plateau_dt_error *report = d->report;
    plateau_index v, t;
    /* the segments that bound the domain: the first ones */
    plateau_index bounding = (plateau_index)(input->num_segments - opt->inner_segments);
    d->tin = (unsigned char *)plateau__alloc(&d->al, (size_t)d->cap_t);
    if (!d->tin) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
    if (!opt->keep_convex_hull && input->num_segments) {
        *deg = (plateau_index *)plateau__alloc(&d->al, plateau__bytes((size_t)d->nv, sizeof(plateau_index)));
        if (!*deg) return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        for (v = 0; v < d->nv; v++) (*deg)[v] = 0;
        for (t = 0; t < 3 * d->nt; t++)
            if (d->tc[t] && d->ts[t] < bounding) (*deg)[d->tv[t]]++;
        for (v = 1; v < d->nv; v++)
            if ((*deg)[v] == 1) {
                if (report) {
                    report->index = (long)d->outid[v];
                    PLATEAU_SNPRINTF(report->message, sizeof report->message,
                             "point %ld ends an open chain of segments, so they bound no "
                             "domain (set keep_convex_hull to keep the whole hull)",
                             (long)d->outid[v]);
                }
                return PLATEAU_DT_ERR_OPEN_BOUNDARY;
            }
        return plateau__dt_domain(d, d->tin, bounding);
    }
    for (t = 0; t < d->nt; t++) d->tin[t] = (unsigned char)!plateau__dt_is_ghost(d, t);
    if (refine)
        for (t = 0; t < 3 * d->nt; t++)
            if (d->tc[t] == 0 && d->tv[PLATEAU__DT_PREV(d->ta[t])] == PLATEAU__DT_GHOST &&
                d->tv[t] != PLATEAU__DT_GHOST && d->tv[PLATEAU__DT_NEXT(t)] != PLATEAU__DT_GHOST)
                d->tc[t] = d->tc[d->ta[t]] = 2;
    return PLATEAU_DT_OK;
}

/* The crossing budget: at most one vertex per pair of segments in exact
 * arithmetic, twice that and a margin for re-crossings caused by the
 * rounding of the points; below PLATEAU__DT_CROSSING_SQUARE_MAX segments
 * the square fits a 32-bit size_t, above it the index range bounds it. */
#define PLATEAU__DT_CROSSING_SQUARE_MAX 40000
#define PLATEAU__DT_CROSSING_MARGIN 64

/* The phases in order (THE ALGORITHM at the top), then the output. */
static plateau_dt_result plateau__dt_triangulate(const plateau_dt_input *input,
                                                 const plateau_dt_options *options,
                                                 plateau_dt_mesh *mesh, plateau_dt_error *report)
{
    plateau__dt dt, *d = &dt;
    plateau_dt_options opt;
    plateau_dt_result r;
    plateau_index *inv = NULL, *dupv = NULL, *work = NULL, *deg = NULL;
    size_t work_cap = 0;
    double maxabs;
    int refine;

    if (report) {
        report->index = -1;
        report->index2 = -1;
        report->message[0] = '\0';
    }
    if (mesh) memset(mesh, 0, sizeof *mesh);
    if (options) opt = *options;
    else memset(&opt, 0, sizeof opt);
    r = plateau__dt_check_args(input, &opt, mesh, report);
    if (r != PLATEAU_DT_OK) return r;
    r = plateau__dt_validate(input, report, &maxabs);
    if (r != PLATEAU_DT_OK) return r;
    memset(d, 0, sizeof *d);
    d->al = opt.allocator;
    d->report = report;
    d->walk_rng = PLATEAU__DT_WALK_SEED;
    d->split_crossing = opt.split_crossing_segments != 0;
    refine = opt.min_angle > 0 || opt.max_area > 0 || opt.max_area_fn != NULL;
    d->steiner_left = input->num_segments < PLATEAU__DT_CROSSING_SQUARE_MAX
                          ? 2 * input->num_segments * input->num_segments + PLATEAU__DT_CROSSING_MARGIN
                          : (size_t)PLATEAU_INDEX_MAX;
    mesh->allocator = opt.allocator;
    r = plateau__dt_insert_points(d, input, opt.seed ? (uint64_t)opt.seed : (uint64_t)PLATEAU__DT_DEFAULT_SEED,
                                  maxabs, &dupv, &inv);
    if (r == PLATEAU_DT_OK) {
        r = plateau__dt_start_constraints(d, input->num_segments || refine);
        d->ninput = (plateau_index)input->num_points;
    }
    if (r == PLATEAU_DT_OK) r = plateau__dt_segments(d, input, inv, dupv, &work, &work_cap);
    if (r == PLATEAU_DT_OK) r = plateau__dt_keep(d, input, &opt, refine, &deg);
#ifndef PLATEAU_DT_NO_STEINER /* else plateau__dt_check_args refused it */
    if (r == PLATEAU_DT_OK && refine) /* phase 6 */
        r = plateau__dt_refine(d, &opt, &mesh->refine_stop, &mesh->num_unrefined);
#endif
    if (r == PLATEAU_DT_OK) {
        /* The inverse of the insertion order, the half-edge per vertex and
         * the segment of each half-edge are not needed any more: freed
         * before the output is allocated (8 bytes per point less at the
         * peak, and 12 per triangle more, with segments or refinement). */
        plateau__free(&d->al, inv);
        plateau__free(&d->al, d->vt);
        plateau__free(&d->al, d->ts);
        inv = d->vt = d->ts = NULL;
        r = plateau__dt_output(d, input, d->tin, dupv, mesh);
    }
    if (r != PLATEAU_DT_OK) {
        plateau_dt_free(mesh);
        if (r == PLATEAU_DT_ERR_OUT_OF_MEMORY)
            plateau__dt_set_error(report, -1, "out of memory");
        else if (r == PLATEAU_DT_ERR_OVERFLOW)
            plateau__dt_set_error(report, -1, "too many points for plateau_index");
        else if (r == PLATEAU_DT_ERR_INTERNAL)
            plateau__dt_set_error(report, -1,
                                   "internal error: a walk or flip loop exceeded its bound");
    }
    plateau__free(&d->al, inv);
    plateau__free(&d->al, dupv);
    plateau__free(&d->al, work);
    plateau__free(&d->al, deg);
    plateau__dt_release(d); /* frees d->tin */
    return r;
}

PLATEAU_DT_DEF plateau_dt_result plateau_dt_triangulate(const plateau_dt_input *input,
                                                        const plateau_dt_options *options,
                                                        plateau_dt_mesh *mesh,
                                                        plateau_dt_error *err)
{
    plateau_dt_result r = plateau__dt_triangulate(input, options, mesh, err);
    if (err) err->code = r;
    return r;
}

#endif /* PLATEAU_DELAUNAY_IMPLEMENTATION */

/* HISTORY
 *   0.1.0  first release: exact adaptive predicates, BRIO + Hilbert order,
 *          ghost vertex, Lawson flips, Sloan's segment recovery, symbolic
 *          tie-breaking, domains by parity, crossing segments split on
 *          request, Delaunay refinement (angle, area, area callback).
 *
 * LICENCE (MIT)
 *   Copyright (c) 2026 the plateau authors.
 *   Permission is hereby granted, free of charge, to any person obtaining a
 *   copy of this software and associated documentation files (the
 *   "Software"), to deal in the Software without restriction, including
 *   without limitation the rights to use, copy, modify, merge, publish,
 *   distribute, sublicense, and/or sell copies of the Software, and to permit
 *   persons to whom the Software is furnished to do so, subject to the
 *   following conditions: The above copyright notice and this permission
 *   notice shall be included in all copies or substantial portions of the
 *   Software.  THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY
 *   KIND, EXPRESS OR IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF
 *   MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN
 *   NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM,
 *   DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR
 *   OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE
 *   USE OR OTHER DEALINGS IN THE SOFTWARE.
 */
