/* plateau.h - minimal triangle meshes spanning a closed 3-D polygon (the
 * Plateau-Mesh problem), after "Constructing Minimal Triangular Mesh Based on
 * Discrete Mean Curvature" (see README.md for the paper and our notes).
 * Part of plateau; needs plateau_lm.h and plateau_delaunay.h beside it.
 * Version 0.1.0.  MIT licence (see the end of the file).
 *
 * DO THIS in exactly one C or C++ file (C99, or C++98 and later):
 *     #define PLATEAU_IMPLEMENTATION
 *     #include "plateau.h"
 * That one define switches on the implementations of plateau.h,
 * plateau_lm.h and plateau_delaunay.h (which plateau.h includes).  Other files
 * just include plateau.h.  Define PLATEAU_STATIC first to give every function
 * of the three headers internal linkage.  Link with -lm.
 *
 * WHAT IT DOES
 *   Given a closed polygon of m >= 3 vertices in space, plateau_solve returns
 *   a triangle mesh whose boundary is that polygon (its first m vertices,
 *   unchanged bit for bit) and whose n interior vertices are placed so that
 *   the mesh is a discrete minimal surface: zero discrete mean curvature at
 *   every interior vertex (the paper's objective, made well-posed) or least
 *   area.  Every stage is public as well: the mesh kernel (areas, signed
 *   dihedral angles, the discrete mean curvature and its exact derivatives,
 *   the residual system), the parameter domain and the candidate points, the
 *   3-D Delaunay flips, OBJ / PLY / OFF / STL / SVG writers (flat-shaded, or
 *   coloured by a scalar with a legend) and a boundary parser.
 *
 * EXAMPLE (complete: a saddle-shaped ring, solved, reported, written as OBJ)
 *     #define PLATEAU_IMPLEMENTATION
 *     #include "plateau.h"
 *     #include <math.h>
 *     #include <stdio.h>
 *     #include <string.h>
 *     int main(void)
 *     {
 *         double xyz[3 * 24];
 *         char defects[64];
 *         plateau_options opt;
 *         plateau_mesh mesh;
 *         plateau_report rep;
 *         plateau_error err;
 *         plateau_result r;
 *         int i;
 *         for (i = 0; i < 24; i++) { // a saddle-shaped ring: z = 0.4 cos 2t
 *             double t = 6.283185307179586 * i / 24;
 *             xyz[3 * i] = cos(t);
 *             xyz[3 * i + 1] = sin(t);
 *             xyz[3 * i + 2] = 0.4 * cos(2 * t);
 *         }
 *         memset(&opt, 0, sizeof opt); // all zero: the defaults (method paper)
 *         opt.interior_points = 40;     // n; 0: as the accuracy needs
 *         r = plateau_solve(xyz, 24, &opt, &mesh, &rep, &err);
 *         if (r != PLATEAU_OK) {
 *             printf("%s: %s\n", plateau_result_string(r), err.message);
 *             plateau_mesh_free(&mesh);
 *             return 1;
 *         }
 *         printf("%s: %lu vertices, %lu triangles, area %.6f, %s\n",
 *                plateau_method_name(rep.method), (unsigned long)mesh.num_vertices,
 *                (unsigned long)mesh.num_triangles, rep.area,
 *                plateau_defects_string(rep.defects, defects, sizeof defects));
 *         printf("%zu rounds, %zu iterations, angles %.1f..%.1f deg\n", rep.rounds,
 *                rep.iterations, rep.min_angle_deg, rep.max_angle_deg);
 *         printf("%s\n", plateau_stop_string(rep.stop));
 *         r = plateau_write_mesh("saddle.obj", mesh.positions, mesh.num_vertices,
 *                                mesh.triangles, mesh.num_triangles, &err);
 *         if (r != PLATEAU_OK) printf("%s\n", err.message);
 *         plateau_mesh_free(&mesh);
 *         return r == PLATEAU_OK ? 0 : 1;
 *     }
 *   It prints (tests/test_manual.c compiles this text and compares)
 *     paper: 64 vertices, 102 triangles, area 3.556042, valid
 *     1 rounds, 7 iterations, angles 32.6..90.3 deg
 *     converged: the triangulation stopped changing
 *   The command-line tool (make cli) does the same for a boundary file:
 *     build/plateau cli/samples/helicoid.txt -n 20 -o helicoid.obj --svg h.svg
 *
 * CONFIGURATION (define before including the implementation)
 *     macro                        default       meaning
 *     PLATEAU_IMPLEMENTATION       -             compile plateau.h, plateau_lm.h
 *                                                and plateau_delaunay.h here
 *     PLATEAU_STATIC               -             every function of the three static
 *     PLATEAU_DEF                  extern        linkage of this header's functions
 *                                                (e.g. DLL export); PLATEAU_LM_DEF
 *                                                and PLATEAU_DT_DEF for the others
 *     PLATEAU_MALLOC(size, ctx)    malloc(size)  allocation when the run-time
 *     PLATEAU_FREE(ptr, ctx)       free(ptr)     allocator is NULL or has no
 *                                                functions; ctx = its user_data
 *                                                (NULL for a NULL allocator);
 *                                                define both or neither
 *     PLATEAU_ASSERT(x)            assert(x)     internal invariants only, never
 *                                                input (used by the other two)
 *     PLATEAU_SQRT, PLATEAU_FABS   sqrt, fabs    the libm calls; define any of
 *     PLATEAU_ATAN2                atan2         them to replace it
 *     PLATEAU_COS, PLATEAU_SIN     cos, sin
 *     PLATEAU_INDEX_TYPE           int32_t       plateau_index, vertex and triangle
 *                                                indices (signed: -1 is "none");
 *                                                define PLATEAU_INDEX_MAX, its
 *                                                largest value, with it
 *     PLATEAU_NO_STDIO             -             leave out plateau_write_mesh(_format,
 *                                                _marked),
 *                                                plateau_write_svg,
 *                                                plateau_write_svg_colored(_stream),
 *                                                plateau_read_boundary_file,
 *                                                plateau_read_boundary_stream,
 *                                                plateau_read_mesh_file and
 *                                                all of <stdio.h>
 *     PLATEAU_NO_PATTERNS          -             leave out the cutting patterns
 *                                                (CUTTING PATTERNS: plateau_pattern_*)
 *   The feature switches (each compiles a section out; see SWITCHES below):
 *     PLATEAU_NO_STABILITY         -             the stability report and
 *                                                critical points
 *     PLATEAU_NO_MEMBRANES         -             pressure, held volume, cables
 *     PLATEAU_NO_LOOPS             -             several loops
 *     PLATEAU_NO_COARSE_TO_FINE    -             coarse to fine
 *     PLATEAU_NO_SVG               -             the SVG drawings (the mesh
 *                                                writers stay)
 *     PLATEAU_NO_PARSERS           -             the text parsers and readers
 *                                                (boundary, cables, meshes)
 *     PLATEAU_LM_NO_SPARSE         -             plateau_lm.h's sparse solvers
 *                                                (every solve dense; implies
 *                                                PLATEAU_NO_STABILITY and
 *                                                PLATEAU_NO_COARSE_TO_FINE)
 *     PLATEAU_LM_NO_CONSTRAINTS    -             plateau_lm.h's linear
 *                                                constraints (plateau.h uses
 *                                                none)
 *     PLATEAU_NO_ACCURACY          -             the error estimate and
 *                                                options.accuracy (ACCURACY)
 *     PLATEAU_QSORT(b, n, s, cmp)  qsort         sorting (its comparisons are total
 *                                                orders: any correct sort gives the
 *                                                same result)
 *     PLATEAU_SNPRINTF             snprintf      messages of plateau_delaunay.h's
 *                                                report (%s, %.Ns, %ld, %g)
 *     PLATEAU_FREESTANDING         -             include no C library header but the
 *                                                freestanding <stddef.h>, <stdint.h>,
 *                                                <float.h>, <limits.h>: then
 *                                                PLATEAU_MALLOC / _FREE, the five libm
 *                                                macros, PLATEAU_QSORT and
 *                                                PLATEAU_SNPRINTF must be defined
 *                                                (#error otherwise), PLATEAU_ASSERT
 *                                                defaults to nothing, memcpy,
 *                                                memmove and memset must be linked
 *                                                (C compilers call them even in
 *                                                freestanding code), PLATEAU_NO_STDIO
 *                                                follows and plateau_parse_boundary(_lines)
 *                                                (strtod) is left out.
 *                                                examples/web builds this way to
 *                                                WebAssembly
 *     PLATEAU_SELF_CHECK           -             run plateau_mesh_self_check after every
 *                                                adjacency build (debugging)
 *     PLATEAU_DEFAULT_MAX_INPUT_BYTES  67108864  the boundary readers' size cap
 *                                                (64 MiB) when max_bytes is 0;
 *                                                more: PLATEAU_ERR_INPUT_TOO_LARGE
 *     PLATEAU_FOLD_DEGREES         150           the final check: a fold is an
 *                                                edge with |dihedral| above it
 *     PLATEAU_DEGENERATE_DEGREES   1e-6          ... a degenerate triangle has
 *                                                an angle below it
 *     PLATEAU_SEED_MAX_LEVELS      16            bounds of plateau_seed_points:
 *     PLATEAU_SEED_MAX_LEVEL_SIZE  1048576       candidate levels, triangles in
 *                                                one level (read by the
 *                                                declarations: define them
 *                                                before the first inclusion)
 *   PLATEAU_LM_IMPLEMENTATION or PLATEAU_DELAUNAY_IMPLEMENTATION alone compile
 *   only that header.  The headers refuse -ffast-math, and plateau_delaunay.h
 *   x87 extended precision (#error): its exact predicates need IEEE-754
 *   binary64 rounded to nearest.  Besides libm the implementation uses
 *   <string.h>, <stdlib.h> (malloc, free, strtod, qsort), <limits.h>,
 *   <locale.h>, <time.h> (clock, for options.max_seconds) and <stdio.h>
 *   (none of them but <limits.h> under PLATEAU_FREESTANDING).
 *   Run time: plateau_options, all-zero = these defaults (see them filled in
 *   with plateau_resolved_options(options, m); the three switches take
 *   PLATEAU_AUTO = 0, PLATEAU_ON or PLATEAU_OFF):
 *     method PLATEAU_METHOD_PAPER  see METHODS below
 *     interior_points 0            n = m (the number of boundary vertices)
 *     seed 0                       a fixed seed (20140101): the candidate draw
 *     max_rounds 0                 20 rounds of solve and re-triangulate
 *     force_circle_domain 0        the best-fit plane when its projection
 *                                  is simple, else the circle (non-zero:
 *                                  always the circle)
 *     progress NULL                called per iteration (round, iteration,
 *                                  F, user), F in the caller's units as
 *                                  the report's (the area, during method
 *                                  paper's area presolve); non-zero:
 *                                  PLATEAU_ERR_ABORTED
 *     allocator {0}                PLATEAU_MALLOC / PLATEAU_FREE; or set both
 *                                  alloc_fn and free_fn (user_data is passed)
 *     lambda 0                     1: tangential rows' weight (method paper)
 *     max_iterations 0             200 per LM solve, 5000 per solve of
 *                                  method area
 *     area_warm_start AUTO         a Pinkall-Polthier start for method area
 *                                  above PLATEAU_SPARSE_THRESHOLD free
 *                                  vertices (ON: always, OFF: never)
 *     paper_presolve AUTO          method paper starts from method area's
 *                                  result where the domain is not the plane
 *                                  (ON: always, OFF: never)
 *     seeding 0                    PLATEAU_SEEDING_AUTO: QUALITY when
 *                                  n >= m / 4 and it gives >= n / 2
 *                                  points, else PAPER;
 *                                  PLATEAU_SEEDING_QUALITY: step 3 by
 *                                  Delaunay refinement of the domain;
 *                                  PLATEAU_SEEDING_PAPER: step 3's fan
 *                                  candidates (the seed is used only here)
 *     refine_boundary AUTO         quality seeding may split the polygon's
 *                                  edges for method area (and paper's area
 *                                  presolve) when the longest is over 2
 *                                  interior spacings, else keeps them whole
 *                                  (ON: may split, OFF: keep)
 *     quality_min_angle 0          26 degrees (quality seeding)
 *     quality_edge_length 0        aim at interior_points points instead
 *     max_memory 0                 PLATEAU_DEFAULT_MAX_MEMORY (2 GiB): a solve
 *                                  whose estimated peak is above it is
 *                                  refused before it starts
 *     linear_solver AUTO           up to PLATEAU_SPARSE_THRESHOLD free
 *                                  vertices method paper's dense LM and
 *                                  method area's L-BFGS, above it the sparse
 *                                  dog leg and the sparse Newton method
 *                                  (PLATEAU_LINEAR_DENSE / _SPARSE force one;
 *                                  method paper's area presolve always
 *                                  chooses by size)
 *     area_tolerance 0             1e-6: method area's Newton solves end
 *                                  when 5 steps lower the area by less
 *                                  than this fraction of it (coarse to
 *                                  fine's coarse mesh: at least 1e-4)
 *     pressure 0, fix_volume 0,    no membrane terms (MEMBRANES below)
 *     volume 0, cable_tension NULL
 *     coarse_to_fine AUTO          methods area and paper from
 *                                  PLATEAU_COARSE_TO_FINE_POINTS interior
 *                                  points, when the polygon's edges may be
 *                                  split: a coarse mesh refined level by
 *                                  level (COARSE TO FINE below; ON: from
 *                                  one level, OFF: never); never for a
 *                                  membrane (ON with one:
 *                                  PLATEAU_ERR_ARGUMENT)
 *     max_seconds 0                no time limit; > 0: the solve stops at
 *                                  its next iteration or round once that
 *                                  many seconds have passed since the
 *                                  call began, with the mesh it has
 *                                  (report.stop PLATEAU_STOP_TIME_LIMIT;
 *                                  the seeding always finishes)
 *     clock_fn NULL                the clock of max_seconds: processor
 *                                  seconds by clock() of <time.h>; or a
 *                                  function returning seconds (clock_user
 *                                  is passed); required with max_seconds
 *                                  under PLATEAU_FREESTANDING
 *     stability AUTO               report.stability, the second-order
 *                                  status of the mesh returned
 *                                  (plateau_mesh_stability: the index of
 *                                  the area's Hessian on normal motions,
 *                                  2 lowest eigenvalues, the area
 *                                  gradient's norm); AUTO: always but
 *                                  for a membrane (not computed there:
 *                                  MEMBRANES), ON: always (a membrane:
 *                                  below), OFF: never
 *     alternatives AUTO            two loops: one disc per loop solved
 *                                  too, report.alternative_area against
 *                                  report.film_area (AUTO: for two loops
 *                                  of a soap film, ON: for two loops;
 *                                  OFF: never)
 *     critical_index 0             K = 1 .. 7: from the result, a critical
 *                                  point of the area of index K nearby
 *                                  (plateau_mesh_critical_point, which
 *                                  may add vertices;
 *                                  report.critical_converged)
 *     least_area_topology 0        non-zero: two loops return the discs
 *                                  when their area is less
 *                                  (report.discs_returned)
 *   A membrane with stability ON, alternatives ON, critical_index > 0 or
 *   least_area_topology is PLATEAU_ERR_ARGUMENT (all four are of the area
 *   alone, MEMBRANES).
 *
 * THE PIPELINE (plateau_solve; the paper's Fig. 1 and section II)
 *   The three headers number the steps the same way: plateau_delaunay.h
 *   serves steps 3 (the quality seeding's refinement) and 4, plateau_lm.h
 *   serves step 5.
 *   1. Boundary check (plateau_boundary_check): at least 3 vertices, all
 *      finite, no two consecutive equal, not all on one line, and able to
 *      bound an embedded surface: no vertex twice, no vertex on another
 *      edge, no two edges that cross or touch in space.
 *   2. Parameter domain (plateau_boundary_domain): the projection on the
 *      best-fit plane when it is a simple polygon, else the boundary laid
 *      on a circle by chord length.  The paper triangulates "with the
 *      boundary of L" and leaves this step open.
 *   3. Interior points, by one of two seedings (options.seeding):
 *      the paper's (PLATEAU_SEEDING_PAPER; plateau_seed_points; II.A, the
 *      V'_j formulas): the centroid, the barycentres of the closed fan,
 *      then each triangle split at its barycentre, level by level; whole
 *      levels are generated and n points drawn with the seeded generator
 *      (the paper's literal rule, PLATEAU_SEED_LITERAL, crowds one side of
 *      the patch);
 *      the quality seeding (PLATEAU_SEEDING_QUALITY; not in the paper, which
 *      cites Miller, Pav and Walkington's quality meshing): the domain
 *      polygon is refined by plateau_dt_triangulate (min_angle, an area
 *      limit and, unless refine_boundary, keep_segments), which yields the
 *      points and step 4's triangulation at once.  Its interior points go
 *      to 3-D by mean-value coordinates of the boundary (Floater 2003),
 *      points on the polygon's edges along the straight 3-D edge.
 *      PLATEAU_SEEDING_AUTO (the default) takes the quality seeding when
 *      n >= m / 4 and the refinement delivers at least n / 2 points, else
 *      the paper's: with n far below m the kept edges force points n did
 *      not ask for, and on a coarse polygon they stop the refinement short
 *      of n.  Why the quality seeding is the default: examples/NOTES.md,
 *      "Measurements behind the solver's choices".
 *   4. Constrained Delaunay triangulation of boundary and points in the
 *      domain (plateau_dt_triangulate of plateau_delaunay.h; II.A: "the
 *      random incremental method [14]").  The 3-D mesh, the initial mesh of
 *      the rounds, takes its triangles (a point the triangulator merges as
 *      a duplicate is dropped).
 *   5. Solve (II.B-II.D): method paper minimises F = 1/2 sum of squared
 *      residuals (equation (1), restricted to interior vertices, with two
 *      tangential rows per vertex) by Levenberg-Marquardt (II.D, Fig. 5;
 *      plateau_lm.h) with the exact Jacobian: equation (2), II.C.1 for
 *      d|B|/dV, II.C.2 for d|e|/dV and a well-conditioned replacement of
 *      formula (3) for d beta/dV.  Method area minimises the total area by
 *      L-BFGS with the gradient of II.C.1, above PLATEAU_SPARSE_THRESHOLD
 *      free vertices by a damped Newton method (the exact area Hessian plus
 *      mu times the cotangent Laplacian, sparse Cholesky; report.iterations
 *      counts its accepted steps).
 *   6. Re-triangulation: intrinsic Delaunay edge flips
 *      (plateau_mesh_delaunay_flips; method area: flips that lower the
 *      area, also after moving the free vertices of the two triangles);
 *      method paper-literal re-projects to the plane domain and re-runs the
 *      constrained triangulation, as Fig. 1 does.  Where the rounds would
 *      end, method area (and method paper's area presolve) removes a free
 *      vertex left in a triangle with an angle below 1 degree, or
 *      inverted, by an edge collapse (plateau_mesh_remove_degenerate; on a
 *      thin strip least area pulls a superfluous vertex onto a boundary
 *      chord) and the rounds go on (each removal adds a round to
 *      max_rounds, at most max_rounds times); report->removed_vertices
 *      counts them.  Not in the paper.
 *   Steps 5 and 6 repeat "until any of the iterative conditions isn't
 *   satisfied" (II.A; the paper names none): until the flips after a solve
 *   find nothing to flip (PLATEAU_STOP_CONVERGED) or max_rounds solves were
 *   done (PLATEAU_STOP_ROUND_LIMIT).  The flips end by construction:
 *   methods paper and paper-literal flip on the intrinsic metric (Lawson's
 *   algorithm on a piecewise flat surface: a Delaunay energy drops with
 *   each flip; Bobenko and Springborn 2007), method area flips only to
 *   lower the area, and its rounds also end when a round lowers the area
 *   by less than 3e-5 of it; method paper's rounds end, from round 3 on,
 *   when a solve lowers the area by less than 1e-6 of it (before its
 *   flips: on a densely sampled boundary the flips drift without end).  After every solve the degeneration check
 *   (plateau_mesh_quality: smallest angle, largest |dihedral|, inverted
 *   triangles) goes into the report.
 *   The final check (plateau_mesh_check; not in the paper): inverted,
 *   folded and degenerate triangles, pairs of triangles intersecting each
 *   other, and whether the last solve reached its stopping rule, as
 *   report.defects (0: valid); with a defect the stop is
 *   PLATEAU_STOP_DEFECTS, never PLATEAU_STOP_CONVERGED.
 *   INVARIANCE.  Steps 2-6 run on the polygon in a frame of its own
 *   (plateau__frame_make): divided by a power of two, its axes
 *   ordered and signed by the polygon itself (never by the order the
 *   caller gave them in), moved to its centroid, turned to axes through
 *   two of its vertices, divided by its root mean square radius and
 *   rounded to 2^-36 of it; the domain's uv are rounded to 2^-36 of the
 *   domain's size.  What holds (tests/test_invariance.c checks it on
 *   random smooth curves and the cases named there):
 *   - a copy with its axes permuted, mirrored or scaled by a power of two
 *     (transforms without rounding) gives the same mesh bit for bit: the
 *     same triangles in the same order, every vertex the same transform
 *     of the original's, the same report (areas scaled);
 *   - any other similarity (a rotation, a scaling by another factor, a
 *     move the coordinates represent exactly) gives the same triangles
 *     with the area (over the scale squared) within 1e-9, and the same
 *     validity, unless one of the frame's coordinates lies within
 *     rounding of a half-way point of its grid or a decision of the solve
 *     within rounding of a tie;
 *   - a move the coordinates cannot represent exactly (a unit polygon
 *     moved by 1e6 loses about 1e-10 of its size) gives a slightly
 *     different polygon, whose mesh may take other triangles where the
 *     solve's decisions are that close to ties;
 *   - units do not matter: 1e-150 and 1e150 work as 1.
 *   plateau_mesh_minimize runs steps 5-6 on a mesh you made
 *   (plateau_mesh_create).  Each function's comment below gives the
 *   details and the choices where the paper is silent or wrong.
 *
 * SEVERAL LOOPS (plateau_solve_loops: the soap film between two rings, a
 *   frame with holes)
 *   The boundary may be k >= 1 closed polygons, all in one coordinate array
 *   with a count per loop; the mesh's first vertices are the loops' own, in
 *   the given order, fixed and bit for bit; the result is a manifold with
 *   Euler characteristic 2 - k (an annulus for two loops: 0).  Example: the
 *   catenoid between two coaxial rings of radius 1 at distance 1
 *       double xyz[3 * 64];
 *       size_t counts[2] = {32, 32};
 *       for (i = 0; i < 64; i++) {
 *           double t = 6.283185307179586 * (i % 32) / 32;
 *           xyz[3 * i] = cos(t);
 *           xyz[3 * i + 1] = sin(t);
 *           xyz[3 * i + 2] = i < 32 ? -0.5 : 0.5;
 *       }
 *       opt.interior_points = 170;
 *       r = plateau_solve_loops(xyz, counts, 2, &opt, &mesh, &rep, &err);
 *       if (r == PLATEAU_OK && rep.stop == PLATEAU_STOP_PINCHED) ...no film
 *   (examples/catenoid_rings.c compares such films with the exact
 *   catenoid).  k = 1 is plateau_solve.  What changes against one loop:
 *   1. Each loop is checked as by plateau_boundary_check (errors name the
 *      loop: "loop 1: boundary vertices 6 and 7 are equal"; err->index
 *      and err->index2 number the vertices in the whole array), then the
 *      loops against each other: no shared vertex
 *      (PLATEAU_ERR_LOOPS_SHARE_VERTEX, index and index2 the two vertices),
 *      no edges of two loops that cross or touch (PLATEAU_ERR_LOOPS_INTERSECT,
 *      index and index2 the two edges' first vertices),
 *      both within 1e-9 of the size, by the grid of step 1 over all edges.
 *   2. The domain: the loops' common best-fit plane when they project there
 *      as simple polygons that do not meet, one (the outer) holding the
 *      others and none of those another: the inner loops are holes.
 *      Coplanar loops in any other arrangement bound no connected plane
 *      region: PLATEAU_ERR_LOOPS_NESTING.  Otherwise two loops go on
 *      concentric circles by chord length (the annulus,
 *      PLATEAU_DOMAIN_ANNULUS; the radius ratio is the conformal one of a
 *      cylinder between them), and more than two give
 *      PLATEAU_ERR_LOOPS_DOMAIN.
 *   3-4. Always the quality seeding (options.seeding is not read; a fan
 *      around one centroid has no meaning on a domain with holes): the
 *      constrained triangulation keeps only the region between the loops,
 *      so no point falls in a hole, and the points reach 3-D by mean-value
 *      coordinates over all loops (Hormann and Floater 2006).  The loops are
 *      kept whole (refine_boundary is not read).
 *   5-6. Unchanged, every method.  On the annulus method paper starts from
 *      method area's result, as on the circle domain.  paper-literal
 *      re-triangulates by 3-D flips (its re-projection needs one polygon).
 *   Orientation: loops may be given either way round.  The mesh's normals
 *   follow the outer loop as for one polygon (the outer loop: the one
 *   holding the others in the plane, the longer one on the annulus); the
 *   other loops are walked whichever way the film needs, so that a
 *   triangle runs an inner loop's edge against the outer loop's sense.
 *   The annulus aligns each circle's start and turning sense with its
 *   loop's winding around the common axis, so reversing a loop or
 *   starting it elsewhere gives no twisted start.
 *   The pinch: two coaxial rings of radius R farther apart than 1.3255 R
 *   carry no catenoid; least area then shrinks the film's neck to nothing
 *   (the true minimum is two disks, which is not an annulus).  For two
 *   loops the neck is measured (the shortest level set of the graph
 *   distance from loop 0, report.neck_ratio, over the shorter loop) after
 *   every solve of method area, after method paper's area presolve, and
 *   for method paper-literal (and method paper where it ran no presolve:
 *   the plane domain, or paper_presolve OFF) on a copy of its result run
 *   through method area's rounds (their F vanishes or stalls on films
 *   that least area leaves).  Below PLATEAU_PINCH_RATIO the result is
 *   PLATEAU_OK with stop PLATEAU_STOP_PINCHED and defect
 *   PLATEAU_DEFECT_PINCHED: the mesh comes back, as any mesh with
 *   defects, but it is no answer (tests/test_solve_loops.c: rings at
 *   h = R keep their neck, at h = 1.5 R pinch by all three methods).
 *
 * MEMBRANES (options.pressure, fix_volume, cable_tension; the paper's
 *   motivation: "cable-membrane structures")
 *   The film has unit surface tension.  With a pressure difference p the
 *   energy is E = area - p V, V the signed volume of the cone from the
 *   given boundary's centroid over the film (plateau_mesh_volume; over a
 *   fixed boundary its variation does not depend on the apex); its
 *   critical points have k1 + k2 = p, so a sphere of radius 2 / p.  The
 *   sign: p > 0 bulges the film to the side its normals point to (the
 *   side from which the boundary turns counter-clockwise).  Method area
 *   minimises E (the same L-BFGS or sparse Newton method, with the
 *   volume's exact gradient and Hessian); method paper solves H_i = p (the
 *   Cohen-Steiner-Morvan H approximates k1 + k2) with its tangential rows.
 *   With fix_volume the film holds V = volume instead: the pressure is a
 *   Lagrange multiplier, found by the secant method on V(p), each V(p) a
 *   solve at pressure p from the last mesh, until |V - volume| <= 1e-7
 *   area^(3/2) (at most 40 solves; a solve that overshoots the volume
 *   into a film with defects is undone, the last good film back and half
 *   the step, at most 8 times, and so is a first guess whose film runs
 *   away or breaks down: the seeded mesh back and half that pressure);
 *   report.pressure gives it, the pressure of the film returned.
 *   A cable is a boundary edge between two fixed anchors with tension T
 *   (cable_tension[i] = T > 0 for the edge from vertex i to the next of its
 *   loop): plateau_solve inserts into it free vertices at the film's
 *   density, and E gains T times the cable's length, so each cable vertex
 *   balances the cable's pull against the film's (a cable in a flat film
 *   is an arc of radius T).  The mesh's first vertices are then the
 *   polygon with the cable vertices between their anchors, in order
 *   (report.cable[j].anchor, .vertices); the given vertices stay fixed and
 *   bit for bit; step 1's messages number this polygon.  Method paper
 *   places the cables by its area presolve and holds them while LM solves
 *   the film.  report.cables, .cable[] (length, sag from the chord),
 *   .pressure and .volume describe the result.  Flips: intrinsic Delaunay
 *   (E is not the area).  Bad values: a tension negative or not finite,
 *   or below half its chord (an arc of radius T spans at most 2 T: no
 *   equilibrium that stays a disc), is PLATEAU_ERR_CABLE; a pressure or
 *   volume not finite, or method paper-literal with any of them, or a
 *   pressure above 1e100 over the polygon's radius, PLATEAU_ERR_PRESSURE.  A pressure that no film spans (p > 2 on the
 *   unit circle): the line searches refuse vertices beyond 2 (R_b + 4 /
 *   |p|) from the apex, R_b the boundary's radius about it, and a film
 *   beyond R_b + 4 / |p| (where every sphere of that pressure through the
 *   boundary lies) has PLATEAU_DEFECT_NO_EQUILIBRIUM; so has, without
 *   cables or a held volume, a pressure with |p| |A| > L (A the
 *   boundary's vector area, L its length: the flux formula excludes any
 *   film; method paper stalls there), and so have cables
 *   whose vertices end out of balance (the energy gradient at a cable
 *   vertex above 1e-2 per unit of cable length, the polygon scaled to
 *   about 1: two cables that would cross, say, pinch the film between them
 *   and the solver stops there); a volume not reached,
 *   PLATEAU_DEFECT_VOLUME; a cable through a triangle, PLATEAU_DEFECT_CABLE.
 *   Known limit: least area - p V has no tangential stiffness, and on a
 *   frame with corners (a square, a hexagon) method area's solves let
 *   triangles degenerate as p grows, and step 6 then removes many interior
 *   vertices; on a smooth frame (the circle) its meshes stay good.  Method
 *   paper (the default), whose tangential rows fix the vertices, gives
 *   good meshes on both (the measurements: examples/NOTES.md section 13).
 *   Checked against exact solutions in tests/test_membrane.c: the cap of
 *   p = 1 on the unit circle (R = 2, h = 2 - sqrt 3, area 2 pi R h, volume
 *   pi h^2 (3R - h) / 3), the same cap by its volume (pressure 1), and the
 *   flat square (+-1, +-1, 0) with four cables of T = 2 and 1.5 (arcs of
 *   radius T), each within 0.5 % and converging at second order.
 *   What is of the area alone is not done for a membrane (report.membrane
 *   1): the stability report (the area's Hessian is not the Hessian of
 *   area - p V or of the cables' energy, nor does it project out a held
 *   volume: report.stability.computed stays 0 rather than give a wrong
 *   index), the discs of two loops, the saddle search and coarse to fine
 *   (its Newton steps are the area's); asking for one of them explicitly
 *   (ON, critical_index > 0, least_area_topology) is PLATEAU_ERR_ARGUMENT.
 *
 * METHODS, AND WHY THE DEFAULT IS NOT THE PAPER AS PRINTED
 *   PLATEAU_METHOD_PAPER (default): H_i = 0 at the interior vertices only,
 *     plus, per interior vertex, the tangential part of (mean of its
 *     neighbours - vertex) as two more residuals scaled by
 *     lambda / (mean edge length)^2: a square system whose solution does not
 *     depend on the start or on lambda; LM (plateau_lm.h) with the exact
 *     Jacobian (tau = eps = 1e-6, tests at eps^2, at most max_iterations
 *     per solve; above PLATEAU_SPARSE_THRESHOLD free vertices Powell's dog
 *     leg on a sparse LU of the same Jacobian instead, same stopping
 *     rules); 3-D flips.  Where the domain is not the plane (the circle,
 *     the annulus) the seeded mesh is folded in 3-D and LM from it finds
 *     folded roots: there it first runs the rounds of method area and
 *     starts from their result (options.paper_presolve).
 *   PLATEAU_METHOD_PAPER_LITERAL: the paper as printed, for comparison: F
 *     over all m + n vertices (equation (1)), no tangential rows, LM with
 *     Fig. 5's damping and its step and F-change tests where usable, and
 *     re-triangulation by re-projecting the vertices to the plane domain
 *     (the affine least-squares map of the boundary onto its domain
 *     polygon) and re-running the CDT; 3-D flips where that is unusable
 *     (circle domain, a vertex outside the polygon).
 *   PLATEAU_METHOD_AREA: least total area (Chen, Cai and Zheng's objective,
 *     the paper's comparison) by L-BFGS with its exact gradient and an
 *     Armijo line search, at most max_iterations steps per solve (above
 *     PLATEAU_SPARSE_THRESHOLD free vertices the sparse Newton method);
 *     flips that lower the area, and step 6's vertex removal.  Never LM on
 *     the gradient norm (it stalls).
 *   Why: the boundary vertices' H_i do not vanish even on the exact surface
 *   (polygon corners), so F over all vertices cannot reach 0 and drives
 *   triangles to slivers; and H_i = 0 at the interior vertices alone is n
 *   equations in 3n unknowns, whose solutions slide tangentially
 *   (examples/NOTES.md, section 2).  The tangential rows make the system
 *   square; LM solves it exactly in a few quadratic steps, and the mesh
 *   depends neither on the start nor on lambda.  The README's demo table
 *   (make readme-check compares it with make demo) gives each method's
 *   area, its excess over the polygon's optimum, its smallest angle and
 *   its iterations on the paper's examples: method area reaches the least
 *   area; method paper is the paper's curvature objective done soundly and
 *   converges in about a dozen LM iterations (area: hundreds of L-BFGS
 *   steps).  For large n only method area is affordable (MEMORY), but with
 *   n far above m least area pulls vertices onto the boundary chords:
 *   test the report's defects.
 *
 * COARSE TO FINE (options.coarse_to_fine; Surface Evolver's way of working)
 *   From PLATEAU_COARSE_TO_FINE_POINTS interior points methods area and
 *   paper do not seed and solve at full size: they solve a coarse mesh and
 *   refine it, so that each level starts next to its answer.
 *   0. Levels: L 1-to-4 subdivisions of a disk of I interior and B boundary
 *      vertices give I_L = 4^L I + B (4^L - 2^L) / 2 - (4^L - 1) interior
 *      vertices (Euler's formula); L is the largest with a coarse count
 *      I_0 >= 16 for I_L = n, B = m, so I_0 is 16 to about 61 + m points, and
 *      the coarse seeding is redone with a corrected count (at most three
 *      times) while I_L, with the B the seeding made, misses n by more
 *      than 3 %; when I_L stays more than 3 % above n (a coarse polygon
 *      whose edges the seeding splits many times: each boundary vertex
 *      adds (4^L - 2^L) / 2 interior ones), one level fewer is taken.
 *   1. Coarse mesh: steps 2-4 for I_0 points with refine_boundary ON, one
 *      round of method area's sparse Newton method, then rounds of plain
 *      area flips and a re-solve while flips happen and a round lowers the
 *      area by 3e-5 of it (at most 8); its solves end when 5 steps lower
 *      the area by less than 1e-4 of it (area_tolerance when larger: the
 *      levels redo the normal positions, and the rounds' 1e-6 bought only
 *      tangential creep there, examples/NOTES.md, section 10).  With a
 *      defect (plateau_mesh_check) one level fewer is tried, then the rounds
 *      at full size: subdivision keeps a defect.
 *   2. Each level: 1-to-4 subdivision; a boundary edge's new vertex is its
 *      midpoint, fixed, restored in the caller's units as the midpoint of
 *      its ends there (the polygon is the same, its first m vertices bit
 *      for bit, the new boundary vertices numbered after the old ones:
 *      report.boundary_points_added); an interior edge's the midpoint of
 *      the cubic through its ends tangent to their tangent planes,
 *      p = (a + b) / 2 - ((b - a).n_a n_a + (a - b).n_b n_b) / 8.
 *   3. Newton's method on normal motions: one unknown t_v per free vertex,
 *      x_v + t_v m_v with m_v the unit vertex normal frozen for the step;
 *      the gradient and Hessian of plateau_mesh_area_hessian_normal, a
 *      scalar sparse Cholesky on the 1-ring pattern (shifted by 1e-3 of the
 *      mean diagonal, x10 per failure, when not positive definite), the
 *      step halved while it raises the area or turns a triangle.  The
 *      tangential distribution is the subdivision's and the flips' of the
 *      coarse level: a decision (the tangential rows and sweeps measured
 *      in examples/NOTES.md, section 10, cost more than they gained).
 *   4. Stopping rule, per level: the Newton decrement delta = -g.t is twice
 *      the decrease the quadratic model still promises; a level ends when
 *      delta / 2 <= max(0.01 E, 1e-13 A), E = (A_prev - A) / 3 its excess
 *      extrapolated from the levels (one subdivision halves h and the
 *      area's error falls as h^2; 1e-13 A: the rounding of the area's sum), i.e. within 1 % of the discrete optimum's excess
 *      (report.area_stop PLATEAU_AREA_STOP_DECREMENT; at most 20 steps, or
 *      max_iterations, then MAX_ITERATIONS and PLATEAU_DEFECT_UNSOLVED).
 *   5. Method paper, at the finest level only: its H_i = 0 at the free
 *      vertices on normal motions, n equations in n unknowns (J_ij =
 *      dH_i/dx_j . m_j, sparse LU), from method area's result, which fixes
 *      the tangential positions.  A decision: the tangential rows of its
 *      square system are dropped, since at scale that system costs several
 *      times the rest and its answer differs from least area by little
 *      (examples/NOTES.md, section 10); F <= 1e-10 is its stopping rule as
 *      on the rounds' path, at most 8 steps.
 *   options.max_seconds is read before every level and every Newton step:
 *   when it runs out the mesh reached comes back (report.stop
 *   PLATEAU_STOP_TIME_LIMIT, not solved), with fewer points than n when a
 *   level was never reached.
 *   6. The final check, as always.  report.levels counts the subdivisions,
 *      report.rounds the coarse mesh's rounds plus the levels,
 *      report.seeded_points the coarse mesh's points, report.iterations
 *      all Newton steps.  plateau_mesh_minimize never takes this path.
 *   Not taken (AUTO) or refused (ON, PLATEAU_ERR_ARGUMENT) with
 *   refine_boundary OFF, seeding PAPER, quality_edge_length > 0, method
 *   paper-literal or several loops; AUTO also needs refine_boundary's own
 *   AUTO rule to hold at n (the polygon's longest edge over 2 interior
 *   spacings) unless refine_boundary is ON, and linear_solver AUTO (a
 *   forced linear solver asks for the rounds' solvers).
 *
 * ACCURACY (report.area_error_estimate, options.accuracy)
 *   Every result of plateau_solve, plateau_solve_loops and
 *   plateau_mesh_minimize carries report.area_error_estimate: the
 *   estimated relative error of its area against the exact minimal
 *   surface of the same polygon (not against a smooth surface the polygon
 *   may sample).  It is formed on a copy of the result: each triangle split
 *   flat into four through its edge midpoints (a new boundary vertex at its
 *   edge's midpoint, on the polygon's straight segment), then
 *   PLATEAU__ACC_CG_STEPS steps of conjugate gradients, preconditioned by
 *   the diagonal, on the area's second-order model in the normal motions of
 *   the free vertices (plateau_mesh_area_hessian_normal): D, the decrease
 *   of area that the mesh of half the edge length still offers.  The area
 *   of a second-order discretisation errs by C h^2, so the mesh of h/2
 *   gains 3/4 of the coarse mesh's error, and the estimate is
 *   (4/3) D / A.  Not formed (NaN, report.estimate says why) for a
 *   membrane, a zero-area triangle or a subdivided mesh beyond max_memory.
 *   examples/NOTES.md (section "The error estimate") has its effectivity
 *   (true error over estimate) on surfaces of known area, and where it
 *   fails.
 *   options.accuracy > 0 (and, by default, PLATEAU_DEFAULT_ACCURACY when
 *   neither interior_points nor quality_edge_length is given, for one
 *   polygon and not with seeding PAPER: several loops and the paper's
 *   fan run at n = m and aim at an accuracy only when asked) turns the
 *   estimate into the request: the solve runs at a first count
 *   (interior_points, or max(m, PLATEAU__ACC_FIRST_POINTS)), and while the
 *   estimate e is above the accuracy asked a, again at (e / a) 1.3 times
 *   the interior points (the error falls as 1 / n; at least 1.5 and at
 *   most 16 times as many, at most PLATEAU_ACCURACY_MAX_POINTS), the
 *   polygon's edges split to match the interior spacing (refine_boundary
 *   ON: the polygon's vertices bit for bit, the new ones on its
 *   segments).  report.accuracy_solves counts the solves; the last one is
 *   returned, with its estimate (above the accuracy only when the count
 *   reached its bound, a result had defects or the time ran out).
 *
 * CUTTING PATTERNS (plateau_pattern_make; the membrane's fabric: rolls of
 *   width W, flat panels sewn along seams; PLATEAU_NO_PATTERNS leaves it out)
 *   Any film (a result, a mesh read from a file) is cut along the sections
 *   of the film by a family of planes, each panel flattened, compensated
 *   and reported, and written as SVG or DXF R12 (plateau_pattern_write_svg,
 *   _dxf, and _stream forms).
 *   1. Seams: the planes are parallel (normal options.direction; default
 *      the coordinate axis of the film's largest extent), or half-planes
 *      through an axis (point, direction; default the film's vector area
 *      through its area centroid), spaced evenly over the film's extent
 *      (parallel) or its angular range about the axis (a film round the
 *      axis is cut all round, starting at a vertex's angle).  Each plane
 *      splits the triangles it crosses exactly (the new vertex on an edge
 *      by linear interpolation, shared by the edge's two triangles); a
 *      vertex within 1/100 of the mean edge length of a plane counts as on
 *      it, so the seam passes through it and no sliver is made.  Each
 *      connected set of triangles between two neighbouring planes is a
 *      panel; a panel that is no disc (planes normal to a tube's axis cut
 *      bands) is PLATEAU_ERR_PATTERN.
 *   2. Spacing: parallel planes are spaced evenly in the film's width
 *      across them (a step ds of s = d.x is ds / sin a on a triangle whose
 *      normal makes the angle a with d; the largest over the triangles at each
 *      level, integrated), planes through an axis evenly in angle.  The
 *      first try spaces them by W (that width, or the largest radius about
 *      the axis times the angle); while the widest
 *      flattened panel exceeds W the count grows by their ratio (2 % to
 *      spare).  Three tries that narrow it by less than 2 % (a film the
 *      planes cannot cut narrower) or more than 100 000 panels:
 *      PLATEAU_ERR_PATTERN.  options.panels = N fixes the count instead.
 *   3. Flattening, per panel: the least-squares conformal map (Levy,
 *      Petitjean, Ray and Maillot 2002, as E_D - A: the cotangent
 *      Dirichlet energy less the flat area, Desbrun, Meyer and Alliez
 *      2002) with the two vertices farthest apart pinned, scaled to the
 *      film's area; then the local / global iterations of Liu, Zhang, Xu,
 *      Gotsman and Gortler 2008 (ARAP: each triangle's best rotation, then
 *      one sparse Cholesky solve of the cotangent Laplacian for the flat
 *      points), until an iteration lowers the energy by less than 1e-7
 *      of it (at most options.max_iterations, default 100).  A developable
 *      panel (a cone, a cylinder: any cut of them) comes out of the
 *      conformal map isometric, with strain at rounding level
 *      (tests/test_pattern.c: <= 1e-9).
 *   4. Strain of a triangle: the largest |s - 1| over the singular values
 *      s of the map from the film triangle to the flat one; per panel the
 *      largest and the area-weighted mean.  The panel is turned so that
 *      its least width (rotating calipers on its convex hull) lies across
 *      the roll, v in [0, width], u along it, and then compensated: u
 *      times 1 - shrink_along, v times 1 - shrink_across (the prestress;
 *      the strain is the flattening's, before compensation).
 *   5. Seams: the edges shared by two panels, in chains, with their flat
 *      length on each side (equal for a developable film, both 1 -
 *      shrink_along times the film length for a seam along the panels);
 *      plateau_pattern_seam_marks gives matching marks on both sides every
 *      given film length.  The writers put each panel on its own strip of
 *      the roll, with its number and the seam marks.
 *   On a spherical cap cut into k gores by planes through its axis the
 *   strain falls at order 2 in the gore width: the order measured between
 *   k and 2k rises to 2 as 2 - O(1/k), since a gore must be slender before
 *   only its width counts (tests/test_pattern.c, k = 6 .. 96 with the mesh
 *   refined alongside, checks the last order and its extrapolation
 *   2 p_k - p_(k/2) against 2).
 *
 * THE GEOMETRY KERNEL: CONVENTIONS
 *   - plateau_mesh.triangles are consistently oriented; a triangle's normal
 *     follows the right-hand rule over (v0, v1, v2).  plateau_solve builds
 *     them counter-clockwise in the domain, so the normals lie on the side
 *     from which the boundary, walked in the given order, turns
 *     counter-clockwise.  neighbors[3t + k] is the triangle across the edge
 *     (v_k, v_(k+1)%3), -1 on the boundary.
 *   - beta(e), the signed dihedral angle of an interior edge, lies in
 *     (-pi, pi] and is positive on a convex crease when the normals point
 *     outward (paper II.B, Fig. 4); beta = 0 on a flat edge and on a
 *     boundary edge.
 *   - H_v = (1/|B_v|) sum over v's edges of beta(e) |e| / 2 with the
 *     barycentric cell |B_v| = (1/3) sum of v's triangle areas (II.B; Cohen-
 *     Steiner and Morvan).  It approximates k1 + k2, twice the mean
 *     curvature (2/r on a sphere of radius r), and has the sign of the
 *     normals.  Boundary edges contribute 0: H at a boundary vertex is no
 *     curvature estimate.  A vertex with |B_v| = 0 gets H = 0.
 *   - Derivatives are exact (checked against central differences in
 *     tests/test_kernel.c) and stay exact at beta = 0.
 *   - The queries that return a number (areas, normals, lengths, beta, H,
 *     the tangential residual, the area gradient, the quality check) trust
 *     their arguments: a mesh with its adjacency built (plateau_mesh_create,
 *     plateau_solve) and indices in range.  Input data is checked, in every
 *     build, by the functions that take it: plateau_mesh_create,
 *     plateau_solve, the boundary, seeding and I/O functions.
 *
 * ADVANCED: INTERNAL PLUMBING
 *   Public so that tests and experiments can reach them, not needed to use
 *   the library, and free to change between versions: the residual system
 *   (plateau_system_options, plateau_system, plateau_system_assemble,
 *   plateau_system_dense, plateau_system_free: the rows the LM adapter
 *   solves); the generator (plateau_rng, plateau_rng_seed, plateau_rng_next,
 *   plateau_rng_uniform); the candidate selection rule (plateau_seed_rule,
 *   plateau_seed_points_rule, to compare with the paper's literal rule);
 *   plateau_vertex_stencil_size (the capacity of the sparse gradient rows);
 *   and the configuration macros PLATEAU_SEED_MAX_LEVELS and
 *   PLATEAU_SEED_MAX_LEVEL_SIZE, which sit with the seeding declarations
 *   because those read them.
 *
 * API INDEX (every public function, one entry each: its signature with the
 * parameter names of its declaration, then what it does; the full comment
 * is at the declaration.  tests/test_api_index.c checks this list against
 * the declarations)
 *   Solving
 *     plateau_result plateau_solve(boundary, m, options, mesh, report, err)
 *         a minimal mesh spanning one closed polygon (the whole pipeline)
 *     plateau_result plateau_solve_loops(xyz, loop_counts, num_loops, options, mesh, report, err)
 *         the same for several loops (a film between rings)
 *     plateau_result plateau_mesh_minimize(mesh, options, report, err)
 *         steps 5-6 and the final check on a mesh you give
 *     plateau_options plateau_resolved_options(options, m)
 *         the options plateau_solve will use, defaults filled in
 *     double plateau_memory_estimate(method, m, n)
 *         bytes a solve of m boundary and n interior vertices needs at its peak
 *   Names and messages
 *     const char *plateau_result_string(result)
 *         the sentence for a result code
 *     const char *plateau_method_name(method)
 *         "paper", "paper-literal" or "area"
 *     int plateau_method_from_name(name, method)
 *         the method of a name; 0, or -1 for an unknown name
 *     const char *plateau_stop_string(stop)
 *         the sentence for report.stop
 *     const char *plateau_area_stop_string(stop)
 *         the sentence for report.area_stop
 *     const char *plateau_estimate_string(status)
 *         the sentence for report.estimate
 *     char *plateau_defects_string(defects, buf, size)
 *         the defect bits in words ("valid" for none) into buf
 *   The pipeline's steps (THE PIPELINE)
 *     plateau_result plateau_boundary_check(xyz, m, err)
 *         step 1: the polygon is usable (finite, simple, not collinear)
 *     plateau_result plateau_boundary_domain(xyz, m, force_circle, allocator, uv, kind, err)
 *         step 2: the polygon's planar parameter domain
 *     plateau_result plateau_seed_points(xyz, uv, m, n, seed, allocator, xyz_out, uv_out, count, err)
 *         step 3: n interior candidate points from fan barycentres
 *     plateau_result plateau_seed_points_rule(xyz, uv, m, n, seed, rule, allocator, xyz_out, uv_out, count, err)
 *         step 3 with a chosen selection rule
 *     int plateau_point_in_polygon(uv, m, p, margin)
 *         1 when p lies inside the polygon, farther than margin from its edges
 *     plateau_result plateau_mesh_delaunay_flips(mesh, max_sweeps, flips, err)
 *         step 6: intrinsic Delaunay edge flips
 *     plateau_result plateau_mesh_remove_degenerate(mesh, min_angle_deg, removed, err)
 *         step 6: removes free vertices that left degenerate triangles
 *   Meshes
 *     plateau_result plateau_mesh_create(positions, num_vertices, fixed, triangles, num_triangles, allocator, mesh, err)
 *         a mesh from your arrays (copied), with its adjacency
 *     void plateau_mesh_free(mesh)
 *         frees a mesh's arrays and zeroes it
 *     plateau_result plateau_mesh_build_adjacency(mesh, err)
 *         rebuilds the adjacency after you changed the triangles
 *     plateau_result plateau_mesh_self_check(mesh, err)
 *         checks a mesh's invariants (debugging)
 *     void plateau_mesh_quality(mesh, quality)
 *         area, angles, largest crease, inverted triangles
 *     plateau_result plateau_mesh_check(mesh, quality, err)
 *         plateau_mesh_quality plus the triangles that intersect each other
 *   The mesh kernel: geometry and curvature (paper II.B-C)
 *     double plateau_triangle_area(mesh, t)
 *         area of triangle t
 *     double plateau_triangle_normal(mesh, t, normal)
 *         unit normal of triangle t; returns its area
 *     double plateau_vertex_area(mesh, v)
 *         barycentric cell area |B_v|
 *     double plateau_mesh_area(mesh)
 *         total area
 *     double plateau_edge_length(mesh, e)
 *         length of edge e
 *     double plateau_mean_edge_length(mesh)
 *         mean length over all edges
 *     double plateau_vertex_normal(mesh, v, normal)
 *         area-weighted unit vertex normal
 *     double plateau_edge_dihedral(mesh, e)
 *         signed dihedral angle beta(e)
 *     double plateau_edge_dihedral_gradient(mesh, e, vertices, gradient)
 *         beta(e) and its exact gradient
 *     double plateau_vertex_mean_curvature(mesh, v)
 *         Cohen-Steiner-Morvan discrete mean curvature H_v
 *     size_t plateau_vertex_stencil_size(mesh, v)
 *         how many vertices H_v depends on (capacity for the rows below)
 *     plateau_result plateau_vertex_mean_curvature_gradient(mesh, v, capacity, vertices, gradient, count, h)
 *         H_v and its exact gradient as a sparse row
 *     double plateau_vertex_mean_curvature_vector(mesh, v, k)
 *         the cotangent mean curvature vector (Meyer et al.)
 *     void plateau_vertex_tangential(mesh, v, weight, r)
 *         method paper's tangential residual of a vertex
 *     plateau_result plateau_vertex_tangential_gradient(mesh, v, weight, capacity, vertices, gradient, count, r)
 *         the tangential residual and its exact Jacobian
 *     void plateau_mesh_area_gradient(mesh, gradient)
 *         gradient of the total area
 *     plateau_result plateau_mesh_area_hessian_normal(mesh, directions, gradient, diagonal, off_diagonal, err)
 *         gradient and Hessian of the area for motions along given directions
 *   The residual system (paper II.D)
 *     plateau_result plateau_system_assemble(mesh, options, system, err)
 *         the residuals f(x) and sparse Jacobian rows of selected vertices
 *     void plateau_system_dense(system, jacobian)
 *         the dense row-major Jacobian of an assembled system
 *     void plateau_system_free(system)
 *         frees a system's arrays
 *   Membranes (MEMBRANES)
 *     double plateau_mesh_volume(mesh, apex, gradient)
 *         signed volume of the cone from apex over the mesh, and its gradient
 *     double plateau_membrane_energy(mesh, pressure, apex, segments, tensions, num_segments, gradient)
 *         area - pressure V + cable tension times length, and its gradient
 *   Second order: stability and critical points
 *     plateau_result plateau_mesh_stability(mesh, num_eigenvalues, stability, modes, err)
 *         the index and lowest eigenvalues of the area's normal Hessian
 *     plateau_result plateau_mesh_critical_point(mesh, index, max_steps, status, converged, steps, err)
 *         a critical point of the area of a given index near the mesh
 *   Reading boundaries
 *     plateau_result plateau_read_boundary_file(path, allocator, xyz, m, err)
 *         reads and parses a boundary file ("x y z" lines)
 *     plateau_result plateau_read_boundary_stream(stream, max_bytes, allocator, xyz, m, err)
 *         the same from an open stream
 *     plateau_result plateau_parse_boundary(text, length, allocator, xyz, m, err)
 *         parses boundary text in memory
 *     plateau_result plateau_parse_boundary_lines(text, length, allocator, xyz, m, info, err)
 *         the same, with each vertex's line and the loops
 *     void plateau_boundary_lines_free(info, allocator)
 *         frees what plateau_parse_boundary_lines put in info
 *     void plateau_boundary_free(xyz, allocator)
 *         frees the coordinates a parser or reader returned
 *     plateau_result plateau_parse_cables(text, length, allocator, tension, count, err)
 *         the "cable T" marks of a boundary text, one per vertex line
 *     plateau_result plateau_cables_align(tension, count, info, err)
 *         matches those marks to the vertices the parser kept
 *   Reading meshes
 *     plateau_result plateau_read_mesh_file(path, allocator, positions, num_vertices, triangles, num_triangles, err)
 *         reads an OBJ or OFF mesh file (polygons as fans of triangles)
 *     plateau_result plateau_parse_mesh(text, length, allocator, positions, num_vertices, triangles, num_triangles, face_lines, err)
 *         parses OBJ or OFF text in memory, with each triangle's line
 *     void plateau_mesh_arrays_free(positions, triangles, face_lines, allocator)
 *         frees the arrays a mesh parser or reader returned
 *   Writing meshes and pictures
 *     plateau_result plateau_write_mesh(path, positions, num_vertices, triangles, num_triangles, err)
 *         OBJ, PLY, OFF or binary STL, by the path's extension
 *     plateau_result plateau_write_mesh_format(path, positions, num_vertices, triangles, num_triangles, format, err)
 *         the same with the format given
 *     plateau_result plateau_write_mesh_marked(path, positions, num_vertices, triangles, num_triangles, marks, format, allocator, err)
 *         the same with boundary and cable vertices marked (PLY, OBJ)
 *     plateau_result plateau_mesh_vertex_marks(mesh, marks, err)
 *         each vertex of a mesh as interior, boundary or cable vertex
 *     plateau_result plateau_write_svg(path, positions, num_vertices, triangles, num_triangles, view_dir, allocator, err)
 *         a flat-shaded SVG picture
 *     plateau_result plateau_write_svg_colored(path, positions, num_vertices, triangles, num_triangles, colors, allocator, err)
 *         an SVG picture coloured by a scalar, with a legend
 *     plateau_result plateau_write_svg_colored_stream(stream, positions, num_vertices, triangles, num_triangles, colors, allocator, err)
 *         the same into an open stream
 *     void plateau_colormap(t, rgb)
 *         the pictures' colour map (cubehelix) at t in [0, 1]
 *   Cutting patterns (CUTTING PATTERNS)
 *     plateau_result plateau_pattern_make(positions, num_vertices, triangles, num_triangles, options, allocator, pattern, err)
 *         cuts a film into panels that fit a roll, flattens and reports them
 *     void plateau_pattern_free(pattern)
 *         frees a pattern's arrays and zeroes it
 *     plateau_result plateau_pattern_seam_marks(pattern, s, spacing, marks, capacity, count, err)
 *         matching marks on both sides of a seam
 *     plateau_result plateau_pattern_write_svg(path, pattern, mark_spacing, err)
 *         the panels as SVG, with numbers and seam marks
 *     plateau_result plateau_pattern_write_svg_stream(stream, pattern, mark_spacing, err)
 *         the same into an open stream
 *     plateau_result plateau_pattern_write_dxf(path, pattern, mark_spacing, err)
 *         the panels as DXF R12 ASCII (cutting plotters)
 *     plateau_result plateau_pattern_write_dxf_stream(stream, pattern, mark_spacing, err)
 *         the same into an open stream
 *   Random numbers (the seeding's generator)
 *     void plateau_rng_seed(rng, seed)
 *         starts a generator at seed
 *     uint64_t plateau_rng_next(rng)
 *         the next 64 random bits
 *     double plateau_rng_uniform(rng)
 *         a double in [0, 1)
 *
 * ERRORS
 *   Functions that can fail return plateau_result: PLATEAU_OK = 0, errors
 *   negative (the list is PLATEAU_RESULT_LIST below; plateau_result_string
 *   gives the sentence).  Those that take a plateau_error *err (may be NULL)
 *   also write the detail there: the code, index (the offending vertex,
 *   triangle or 1-based input line; -1 if none), index2 (the second vertex
 *   where the error names two, an edge by its first vertex; -1 if none) and
 *   a one-sentence message such as "boundary vertices 3 and 4 are equal".
 *   A program that read the boundary from a file maps index and index2 to
 *   file lines with plateau_parse_boundary_lines (the command-line tool
 *   adds "(file lines 5 and 6)" to the message).  plateau_solve,
 *   plateau_mesh_create and the boundary, seeding and I/O functions also
 *   reset it on success (code PLATEAU_OK, index -1, message ""); the others
 *   leave it alone then: test the return value.  No global error state.  Why
 *   the solver stopped is not an error: plateau_report.stop (the rounds) and
 *   .lm_stop / .area_stop (the last LM solve, the last solve of method area) say it.  A mesh with
 *   defects is no error either (PLATEAU_OK: the caller gets the mesh), but
 *   plateau_report.defects is non-zero (one PLATEAU_DEFECT_* bit per kind:
 *   inverted, folded, degenerate or intersecting triangles, a solve short of
 *   its stopping rule; plateau_defects_string names them) and the stop is
 *   PLATEAU_STOP_DEFECTS.  Nothing here prints, exits or aborts.
 *
 * MEMORY
 *   Every allocation goes through a plateau_allocator {alloc_fn, free_fn,
 *   user_data}: options.allocator for plateau_solve, the allocator argument
 *   of the other functions.  All-zero or NULL means PLATEAU_MALLOC /
 *   PLATEAU_FREE (malloc and free unless you define them) with user_data as
 *   their context.  Who frees what:
 *     plateau_solve, plateau_mesh_create   the mesh owns its arrays and a copy
 *                                          of the allocator: plateau_mesh_free
 *                                          (also after an error; it accepts an
 *                                          all-zero mesh)
 *     plateau_system_assemble              plateau_system_free (the mesh's
 *                                          allocator)
 *     plateau_parse_boundary,              *xyz: plateau_boundary_free with the
 *     plateau_read_boundary_file,          same allocator
 *     plateau_read_boundary_stream,
 *     plateau_parse_boundary_lines         and its info: plateau_boundary_lines_free
 *     plateau_parse_mesh,                  the arrays: plateau_mesh_arrays_free
 *     plateau_read_mesh_file               with the same allocator
 *     plateau_pattern_make                 plateau_pattern_free (the pattern
 *                                          keeps a copy of the allocator)
 *   Everything else writes into arrays the caller passes, and frees its own
 *   scratch before returning (plateau_mesh_minimize and the flips use the
 *   mesh's allocator).  Every size product is overflow-checked
 *   (PLATEAU_ERR_OVERFLOW).  Out of memory at any allocation gives
 *   PLATEAU_ERR_OUT_OF_MEMORY with nothing leaked (tests/test_alloc_fail.c).
 *   Peak memory of plateau_solve: method paper on its dense path (up to
 *   PLATEAU_SPARSE_THRESHOLD free vertices, or forced) holds LM's dense
 *   3n x 3n Jacobian and normal equations, O(n^2) bytes for n interior
 *   points (paper-literal's Jacobian is (m + n) x 3n, always dense); on its
 *   sparse path it holds the block pattern, the analysis and the sparse
 *   LU, O(n log n); method area is linear on its L-BFGS path and holds a
 *   sparse Cholesky on its Newton path (above PLATEAU_SPARSE_THRESHOLD).
 *   plateau_solve and plateau_mesh_minimize estimate that peak first
 *   (plateau_memory_estimate, an upper bound of the form given there) and
 *   refuse with PLATEAU_ERR_MEMORY_LIMIT, before allocating anything, when
 *   it exceeds options.max_memory (default PLATEAU_DEFAULT_MAX_MEMORY;
 *   (size_t)-1 for none).  A solve with quality seeding checks again once
 *   it knows its points; where that bound refuses method paper's sparse
 *   path, the seeded triangulation's own symbolic analysis decides (twice
 *   the block LU's exact bytes plus a fixed amount per vertex: the
 *   formula fits uniform meshes, and the graded mesh of a densely sampled
 *   boundary fills far less).  The allocator can still cap every single
 *   allocation.  Measured peaks: examples/NOTES.md, "Measurements behind
 *   the solver's choices"; bench/bench_scale.c.
 *
 * THREAD SAFETY
 *   No global or static mutable state, no static scratch: every function is
 *   reentrant, and calls on different meshes and outputs may run at once
 *   (tests/test_threads.c).  A shared allocator must be thread-safe itself.
 *   One exception: plateau_parse_boundary (and so the file reader) reads
 *   localeconv(), so calling setlocale() in another thread at the same time
 *   is a race, as with strtod itself.
 *
 * DETERMINISM
 *   Randomness comes only from seeded generators, never rand(): the
 *   candidate draw from plateau_rng (splitmix64) seeded with options.seed,
 *   the triangulator's insertion order from its own fixed seed (its
 *   triangles do not depend on the order: ties are broken symbolically).
 *   The flips sweep in index order and never flip a tie.  The same input and
 *   options give the same mesh bit for bit, on every run and in every thread.
 *   Bit for bit across builds needs the same arithmetic: another compiler
 *   or libm can change the last bits, and so can the contraction of a*b + c
 *   into one fused multiply-add (FMA), and through a flip decision the
 *   connectivity (examples/NOTES.md has an example).  What the build needs:
 *     gcc    an ISO mode, -std=c99 (or c11, c17), which does not contract;
 *            or -ffp-contract=off.  The GNU modes (-std=gnu99, gnu11, and
 *            no -std at all) contract wherever the target has FMA (-mfma,
 *            -march=native on a recent x86-64, AArch64, POWER).  gcc
 *            ignores the pragma below.
 *     clang  the implementation sets #pragma STDC FP_CONTRACT OFF for its
 *            own code and DEFAULT after it; clang honours it under its
 *            default -ffp-contract=on, not under -ffp-contract=fast (do not
 *            pass that, or pass -ffp-contract=off).
 *     any    no -ffast-math (refused with #error); no x87 arithmetic
 *            (plateau_delaunay.h refuses it); the exact predicates use fma()
 *            explicitly, so contraction cannot break them.
 *   Contraction changes results, not validity: make test-full builds
 *   tests/test_fp_contract.c with -std=gnu99 -ffp-contract=fast -O2 (-mfma
 *   where the CPU has FMA) and checks the mesh of every demo polygon and CLI
 *   sample: no inverted triangle, smallest angle above 5 degrees, largest
 *   |dihedral| below 120 degrees, the boundary bit for bit.
 *
 * SWITCHES
 *   Each switch of CONFIGURATION leaves one feature out of the
 *   implementation, at section granularity: defined before the
 *   implementation, it shrinks the object and its compile time (the
 *   README's table gives both per configuration; tests/size_table.sh
 *   measures them).  The declarations stay the same in every
 *   configuration, so a program compiles and links against any of them;
 *   what a switch removed refuses at run time with PLATEAU_ERR_ARGUMENT
 *   and a message naming the macro ("a membrane (pressure, fix_volume or
 *   cable_tension) needs the membranes, compiled out by
 *   PLATEAU_NO_MEMBRANES"):
 *     PLATEAU_NO_STABILITY       options.stability ON, critical_index > 0,
 *                                plateau_mesh_stability,
 *                                plateau_mesh_critical_point; stability
 *                                AUTO means OFF (report.stability stays 0)
 *     PLATEAU_NO_MEMBRANES       options.pressure, fix_volume, cable_tension
 *     PLATEAU_NO_LOOPS           plateau_solve_loops with more than one loop
 *     PLATEAU_NO_COARSE_TO_FINE  coarse_to_fine ON; AUTO means OFF
 *     PLATEAU_NO_SVG             plateau_write_svg, plateau_write_svg_colored
 *                                (_stream)
 *     PLATEAU_NO_PARSERS         plateau_parse_boundary(_lines),
 *                                plateau_parse_cables, plateau_cables_align,
 *                                plateau_parse_mesh and the three readers
 *                                (file and stream)
 *     PLATEAU_LM_NO_SPARSE       linear_solver SPARSE and area_warm_start ON;
 *                                AUTO means the dense LM and the L-BFGS at
 *                                every size, without the warm start; the
 *                                sparse functions of plateau_lm.h return
 *                                PLATEAU_LM_ERR_ARGUMENT
 *     PLATEAU_LM_NO_CONSTRAINTS  plateau_lm_solve and plateau_lm_covariance
 *                                with options.constraints or inequalities
 *                                (PLATEAU_LM_ERR_ARGUMENT)
 *     PLATEAU_NO_ACCURACY        options.accuracy > 0; the default accuracy
 *                                means none (one solve at interior_points,
 *                                m when 0); report.area_error_estimate is
 *                                NaN with report.estimate
 *                                PLATEAU_ESTIMATE_COMPILED_OUT
 *   A plain film (one loop, no membrane, the defaults) gives the same mesh
 *   bit for bit in every configuration: a switch removes code, it changes
 *   no result of the code that stays, except where AUTO chose the feature
 *   (stability AUTO, coarse to fine AUTO from
 *   PLATEAU_COARSE_TO_FINE_POINTS interior points, the sparse path above
 *   PLATEAU_SPARSE_THRESHOLD free vertices, the default accuracy when
 *   interior_points is 0).  The Makefile's header checks
 *   build tests/hdr/switches.c once per switch and with all of them, run it
 *   and compare its mesh with the full library's, and build the
 *   command-line tool with all of them but PLATEAU_NO_PATTERNS (it then
 *   refuses to read a boundary file).
 *   PLATEAU_NO_STDIO, PLATEAU_NO_PATTERNS and PLATEAU_FREESTANDING are
 *   different: they leave functions and their declarations out.
 *
 * PERFORMANCE
 *   Method paper's dense LM costs O(n^3) per iteration and is the default
 *   up to PLATEAU_SPARSE_THRESHOLD free vertices; above it the sparse dog
 *   leg; method area costs O(n) per L-BFGS step, and its sparse Newton
 *   method a sparse Cholesky per step.  make bench measures them (medians
 *   and ratios in one run); examples/NOTES.md records the measurements
 *   behind the thresholds.
 *
 * HOW THE CODE IS LAID OUT
 *   After the declarations, the implementation follows this manual, one
 *   section per banner "SECTION: ... (prefix)", each with one private
 *   prefix for its functions and types: the shared infrastructure, the
 *   core in the order of THE PIPELINE, one block per optional feature in
 *   the order of this manual, then the driver and I/O:
 *     shared helpers                            plateau__util_
 *     the configuration (options resolved once) plateau__cfg_
 *     the mesh kernel                           plateau__geo_
 *     step 1: boundary check                    plateau__bnd_
 *     the scale-free frame (INVARIANCE)         plateau__frame_
 *     step 2: parameter domain                  plateau__dom_
 *     step 3: interior points                   plateau__seed_
 *     step 4: constrained Delaunay triangulation plateau__cdt_
 *     step 5: solve                             plateau__solve_
 *     step 6: re-triangulation                  plateau__retri_
 *     the final check                           plateau__chk_
 *     several loops: the discs of two loops     plateau__loops_
 *     membranes and cables                      plateau__memb_
 *     coarse to fine                            plateau__c2f_
 *     the accuracy: the error estimate          plateau__acc_
 *     second-order analysis: the stability      plateau__stab_,
 *       report and critical points              plateau__crit_
 *     the driver: the rounds, the entry points  plateau__drv_
 *     mesh input and output                     plateau__io_
 *     cutting patterns (after the I/O, whose    plateau__pat_
 *       file writing its writers share)
 *   Each step's section ends with the step as plateau_solve runs it
 *   (plateau__bnd_step ... plateau__retri_step).  plateau_solve and
 *   plateau_solve_loops are one driver (plateau__drv_solve); it resolves
 *   and validates the options once, at entry, into a plateau__cfg that is
 *   read-only from then on (nothing below reads plateau_options), and what
 *   the run decides on its way (method paper's presolve, the frame's unit,
 *   a membrane's values in the frame, the time budget) lives in a
 *   plateau__cfg_run; a further solve (the presolve, a disc of two loops)
 *   gets its configuration from plateau__cfg_derive.
 *   The allocation helpers (plateau__alloc, plateau__free, plateau__bytes)
 *   and the libm wrappers (PLATEAU_SQRT, ...) come from the configuration
 *   block that plateau_lm.h and plateau_delaunay.h share
 *   (tests/test_shared_block.c checks that the two copies are identical).
 */
#ifndef PLATEAU_H
#define PLATEAU_H

#define PLATEAU_VERSION "0.1.0"
#define PLATEAU_VERSION_NUM 100 /* major * 10000 + minor * 100 + patch */

#include "plateau_lm.h"
#include "plateau_delaunay.h"
#if defined(PLATEAU_FREESTANDING) && !defined(PLATEAU_NO_STDIO)
#define PLATEAU_NO_STDIO
#endif
/* The second-order analysis and coarse to fine factor sparse matrices:
 * PLATEAU_LM_NO_SPARSE leaves them out too (CONFIGURATION). */
#ifdef PLATEAU_NO_STABILITY
#define PLATEAU__NO_STABILITY_BY "PLATEAU_NO_STABILITY"
#elif defined(PLATEAU_LM_NO_SPARSE)
#define PLATEAU_NO_STABILITY
#define PLATEAU__NO_STABILITY_BY "PLATEAU_LM_NO_SPARSE (it implies PLATEAU_NO_STABILITY)"
#endif
#ifdef PLATEAU_NO_COARSE_TO_FINE
#define PLATEAU__NO_COARSE_TO_FINE_BY "PLATEAU_NO_COARSE_TO_FINE"
#elif defined(PLATEAU_LM_NO_SPARSE)
#define PLATEAU_NO_COARSE_TO_FINE
#define PLATEAU__NO_COARSE_TO_FINE_BY "PLATEAU_LM_NO_SPARSE (it implies PLATEAU_NO_COARSE_TO_FINE)"
#endif
#ifndef PLATEAU_NO_STDIO
#include <stdio.h> /* FILE, for plateau_read_boundary_stream */
#endif

#if PLATEAU_LM_VERSION_NUM != PLATEAU_VERSION_NUM
#error "plateau.h and plateau_lm.h are from different versions"
#endif
#if PLATEAU_DELAUNAY_VERSION_NUM != PLATEAU_VERSION_NUM
#error "plateau.h and plateau_delaunay.h are from different versions"
#endif

#ifndef PLATEAU_DEF
#ifdef PLATEAU_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define PLATEAU_DEF static __attribute__((unused))
#else
#define PLATEAU_DEF static
#endif
#else
#define PLATEAU_DEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Every enum of this header with a message per value (results, stop
 * reasons) is one X-macro list X(name, value, text): the enum, its end
 * marker <PREFIX>_COUNT (the number of entries, counted from the list) and
 * its string function all come from the list, so they never drift. */
#define PLATEAU__ENUM(name, value, text) name = value,
#define PLATEAU__COUNT(name, value, text) +1

/* ---- Result codes ---- */
#define PLATEAU_RESULT_LIST(X)                                                        \
    X(PLATEAU_OK, 0, "ok")                                                            \
    X(PLATEAU_ERR_ARGUMENT, -1, "invalid argument (NULL pointer, zero count or bad option)") \
    X(PLATEAU_ERR_OUT_OF_MEMORY, -2, "out of memory")                                      \
    X(PLATEAU_ERR_OVERFLOW, -3, "a size computation overflowed")                       \
    X(PLATEAU_ERR_NOT_FINITE, -4, "a coordinate is NaN or infinite")                   \
    X(PLATEAU_ERR_TOO_FEW_VERTICES, -5, "the polygon has fewer than 3 vertices")       \
    X(PLATEAU_ERR_REPEATED_VERTEX, -6, "two consecutive polygon vertices are equal")   \
    X(PLATEAU_ERR_COLLINEAR, -7, "all polygon vertices are collinear")                 \
    X(PLATEAU_ERR_INDEX_RANGE, -8, "a vertex index is out of range")                   \
    X(PLATEAU_ERR_DEGENERATE_TRIANGLE, -9, "a triangle repeats a vertex")               \
    X(PLATEAU_ERR_NON_MANIFOLD, -10, "an edge has more than two triangles")            \
    X(PLATEAU_ERR_ORIENTATION, -11, "neighbouring triangles are oriented inconsistently") \
    X(PLATEAU_ERR_TRIANGULATION, -12, "the planar triangulation failed")               \
    X(PLATEAU_ERR_SOLVER, -13, "the optimiser failed")                                \
    X(PLATEAU_ERR_ABORTED, -14, "a callback asked to stop")                            \
    X(PLATEAU_ERR_IO, -15, "a file could not be written or read")                     \
    X(PLATEAU_ERR_PARSE, -16, "a line of the input could not be parsed")             \
    X(PLATEAU_ERR_INPUT_TOO_LARGE, -17, "the input is larger than the size limit")   \
    X(PLATEAU_ERR_DUPLICATE_VERTEX, -18, "two polygon vertices that are not neighbours coincide") \
    X(PLATEAU_ERR_VERTEX_ON_EDGE, -19, "a polygon vertex lies on an edge it does not end") \
    X(PLATEAU_ERR_EDGES_INTERSECT, -20, "two polygon edges cross or touch")           \
    X(PLATEAU_ERR_MEMORY_LIMIT, -21, "the solve would need more memory than options.max_memory") \
    X(PLATEAU_ERR_LOOPS_SHARE_VERTEX, -22, "two boundary loops share a vertex")         \
    X(PLATEAU_ERR_LOOPS_INTERSECT, -23, "edges of two boundary loops cross or touch")   \
    X(PLATEAU_ERR_LOOPS_NESTING, -24, "the boundary loops are nested so that they bound no connected surface") \
    X(PLATEAU_ERR_LOOPS_DOMAIN, -25, "more than two loops that do not project onto one plane as an outer polygon with holes") \
    X(PLATEAU_ERR_CABLE, -26, "a cable's tension is not finite, negative, or below half its chord") \
    X(PLATEAU_ERR_PRESSURE, -27, "the pressure or volume is not finite, or the method cannot apply it") \
    X(PLATEAU_ERR_PATTERN, -28, "no cutting pattern: a panel wider than the roll, or not a disc")

typedef enum plateau_result {
    PLATEAU_RESULT_LIST(PLATEAU__ENUM)
    /* end marker: the number of codes, counted from the list */
    PLATEAU_RESULT_COUNT = 0 PLATEAU_RESULT_LIST(PLATEAU__COUNT)
} plateau_result;

/* Detail for a failed call, written by the calls that take one (may be NULL). */
typedef struct plateau_error {
    plateau_result code;
    long index;        /* the offending vertex, triangle or line; -1 if none */
    long index2;       /* the second vertex where the error names two (vertices
                          i and j, a vertex and the edge it touches, two edges:
                          an edge is its first vertex, edge i joining vertex i
                          to the next one of its loop), in index's numbering;
                          -1 if none */
    char message[160]; /* one sentence, e.g. "boundary vertices 3 and 4 are equal" */
} plateau_error;

/* The sentence for a result code (a static string, never NULL: "unknown
 * plateau result code" for a value not in the list). */
PLATEAU_DEF const char *plateau_result_string(plateau_result result);

/* ======== SECTION: steps 1-3: boundary check, parameter domain, points == */
/* A seeded generator of our own (never rand()): same seed, same sequence. */
typedef struct plateau_rng { uint64_t state; } plateau_rng;
/* out *rng: the generator started at seed (any value, 0 included). */
PLATEAU_DEF void plateau_rng_seed(plateau_rng *rng, uint64_t seed);
/* in/out *rng; returns the next 64 random bits (splitmix64, below); 0 for
 * a NULL rng. */
PLATEAU_DEF uint64_t plateau_rng_next(plateau_rng *rng);
/* in/out *rng; returns a double in [0, 1): the top 53 bits of the next draw. */
PLATEAU_DEF double plateau_rng_uniform(plateau_rng *rng);

typedef enum plateau_domain_kind {
    PLATEAU_DOMAIN_PLANE = 0, /* projection on the best-fit plane (simple) */
    PLATEAU_DOMAIN_CIRCLE = 1, /* boundary mapped on a circle by chord length */
    PLATEAU_DOMAIN_ANNULUS = 2 /* two loops on concentric circles by chord
                                  length (plateau_solve_loops) */
} plateau_domain_kind;

/* Step 1: m >= 3 vertices, all finite, no two consecutive equal, not all
 * collinear, and no self-contact: no vertex twice, no vertex on an edge it
 * does not end, no two edges that cross or touch (the polygon closes
 * implicitly; edge i joins vertex i to vertex (i + 1) % m).
 *   in  xyz (3 * m coordinates), m;  out err (may be NULL).
 * Returns PLATEAU_OK or the first failed check (details below). */
PLATEAU_DEF plateau_result plateau_boundary_check(const double *xyz, size_t m,
                                                  plateau_error *err);
/* Step 2: planar parameter domain (not in the paper, which leaves the plane
 * of its triangulation open; details below).
 *   in  xyz, m; force_circle (non-zero: skip the plane); allocator (may be
 *       NULL; O(m) scratch for the crossing tests, freed before returning);
 *   out uv (2 * m values, counter-clockwise), *kind (may be NULL), err.
 * Returns PLATEAU_OK, the errors of plateau_boundary_check,
 * PLATEAU_ERR_ARGUMENT (uv NULL, an allocator with one function) or
 * PLATEAU_ERR_OUT_OF_MEMORY. */
PLATEAU_DEF plateau_result plateau_boundary_domain(const double *xyz, size_t m,
                                                   int force_circle,
                                                   const plateau_allocator *allocator,
                                                   double *uv, plateau_domain_kind *kind,
                                                   plateau_error *err);
/* Step 3: n interior candidate points (paper section II.A), in 3-D (xyz_out,
 * 3 * n) and in the domain (uv_out, 2 * n); *count gets how many were
 * produced (n unless the polygon is too thin to hold them).
 *   in  xyz (3 * m), uv (2 * m, the domain of step 2), m, n, seed,
 *       allocator (may be NULL; scratch only, freed before returning);
 *   out xyz_out, uv_out (may be NULL when n = 0), *count, err.
 * Returns PLATEAU_OK (also when *count < n), _ARGUMENT, _TOO_FEW_VERTICES,
 * _OVERFLOW, _NOT_FINITE (a uv value), _OUT_OF_MEMORY. */
PLATEAU_DEF plateau_result plateau_seed_points(const double *xyz, const double *uv, size_t m,
                                               size_t n, uint64_t seed,
                                               const plateau_allocator *allocator,
                                               double *xyz_out, double *uv_out,
                                               size_t *count, plateau_error *err);
/*
 * Details of steps 1-3 (the quality seeding of step 3: plateau_solve).
 *
 * plateau_rng is splitmix64 (Steele, Lea and Flood, "Fast splittable
 * pseudorandom number generators", OOPSLA 2014): state += golden gamma, then
 * two xor-shift-multiply rounds.  Any seed, including 0, is valid.
 * plateau_rng_uniform gives the top 53 bits as a double in [0, 1).
 *
 * plateau_boundary_check checks, in this order: xyz != NULL when m > 0
 * (else PLATEAU_ERR_ARGUMENT; NULL with m = 0 is the next error); m >= 3 (PLATEAU_ERR_TOO_FEW_VERTICES); m fits
 * plateau_index (PLATEAU_ERR_OVERFLOW); every coordinate finite
 * (PLATEAU_ERR_NOT_FINITE, err->index = the first such vertex); no vertex
 * exactly equal to the next one, the last one's next being vertex 0
 * (PLATEAU_ERR_REPEATED_VERTEX, err->index = i and err->index2 = (i+1) % m
 * for the pair);
 * not all on one line (PLATEAU_ERR_COLLINEAR): the largest distance of a
 * vertex from the line through vertex 0 and the vertex farthest from it must
 * exceed 1e-12 times the bounding-box diagonal.  Then the polygon must be
 * able to bound an embedded surface (a polygon that touches itself bounds
 * none: its meshes fold or invert), tested with the tolerance
 * tol = 1e-9 times the bounding-box diagonal:
 *   PLATEAU_ERR_REPEATED_VERTEX  consecutive vertices i, i + 1 closer than
 *                                tol (err->index = i, index2 = i + 1);
 *   PLATEAU_ERR_DUPLICATE_VERTEX two vertices i < j that are not
 *                                neighbours within tol (index = i,
 *                                index2 = j; message
 *                                "boundary vertices 0 and 2 coincide ...");
 *   PLATEAU_ERR_VERTEX_ON_EDGE   vertex v within tol of edge e, not one of
 *                                its ends, nor within tol of them (index =
 *                                v, index2 = e; a spike, a polygon folding back on its
 *                                neighbouring edge, is such a case; message
 *                                "boundary vertex 3 lies on edge 0 (from
 *                                vertex 0 to vertex 1)");
 *   PLATEAU_ERR_EDGES_INTERSECT  edges a < b without a common vertex within
 *                                tol of each other: they cross or touch
 *                                (index = a, index2 = b; message "boundary edges 0
 *                                (vertices 0, 1) and 2 (vertices 2, 3)
 *                                cross or touch").
 * When there are several, the one reported is the first by (this order,
 * smaller index, larger index).  Why relative and why 1e-9: the answer
 * must not depend on the units, and an exact test on doubles misses
 * touches that are exact only up to rounding (a helix vertex at t = 2 pi
 * lies 2.4e-16 off the line x = 1, y = 0 of a straight return edge); 1e-9
 * is far above the rounding of coordinates computed or printed to 15-17
 * digits, far below any feature a mesh resolves, and the tolerance of the
 * plane domain's own simplicity test below, so that a planar polygon
 * accepted here has a simple plane domain.  Cost O(m log m) time and
 * O(m) scratch: each edge is cut into pieces of about the median edge
 * length, the pieces are entered into a uniform grid (sorted cells) and
 * only edges sharing a cell are compared; many short edges crowded into
 * one cell (a dense cluster far below the median length) make it
 * quadratic in that crowd.  plateau_boundary_check takes its scratch from
 * PLATEAU_MALLOC (PLATEAU_ERR_OUT_OF_MEMORY when that fails),
 * plateau_boundary_domain and plateau_solve from their allocator.
 * Indices are 0-based.
 *
 * plateau_boundary_domain calls plateau_boundary_check first.  PLANE: the
 * vertices are projected on the plane through their centroid spanned by the
 * two principal axes of largest variance of the vertex covariance (cyclic
 * Jacobi rotations on the symmetric 3x3 matrix); u along the largest axis
 * when its variance exceeds the other in-plane one by more than 1e-3 of
 * it, else (squares, regular polygons) along the in-plane direction of the
 * first vertex at least half as far from the centroid as the farthest;
 * its sign such that the first vertex with |u| at least half the largest
 * has u > 0.  So the axes are the polygon's own, not rounding's: a scaled,
 * moved or rotated copy gets the same uv up to rounding.
 * The plane is used when the projected polygon is simple: no two
 * non-adjacent edges closer than 1e-9 times the projection's bounding-box
 * diagonal (a crossing or a touch), no vertex folding back onto a
 * neighbouring edge.  Otherwise CIRCLE: vertex i goes to angle
 * 2 pi s_i / L on the circle of radius L / (2 pi), s_i the chord length
 * along the polygon from vertex 0 and L the perimeter, so uv lengths stay
 * comparable with xyz lengths.  Orientation convention: the uv polygon is
 * always counter-clockwise (positive signed area).  A mesh triangulated
 * counter-clockwise in uv therefore has facet normals on the side from
 * which the boundary, walked in the given vertex order, turns
 * counter-clockwise (the right-hand rule).  uv in the same units as xyz.
 * Scratch O(m) through allocator (PLATEAU_ERR_OUT_OF_MEMORY); cost O(m log m):
 * the planar test compares only the edge pairs the grid of step 1 finds.
 *
 * plateau_seed_points (paper section II.A, with the choices of
 * examples/NOTES.md).  Candidates: level 0 is the centroid C of the boundary vertices;
 * level 1 the barycentres of the CLOSED fan of triangles (V_{j-1}, V_j, C),
 * j = 1..m with V_0 = V_m (the paper's j = 2..m leaves out the triangle at
 * the closing edge); level k+1 the barycentres of the three triangles
 * (a, b, g), (a, c, g), (b, c, g) into which each level-k triangle (a, b, c)
 * is split at its barycentre g.  Each candidate is the same average of
 * three corners in xyz and in uv (C is the mean of the vertices in both),
 * so the 3-D point and its domain point are one barycentric combination of
 * the boundary vertices.  A candidate whose uv is outside the domain polygon
 * or within 1e-9 times the domain's bounding-box diagonal of its boundary is
 * skipped.  Which n of the candidates are taken is the rule below
 * (plateau_seed_points uses PLATEAU_SEED_WHOLE_LEVELS).  The selection
 * depends only on uv, m, n and the seed, never on xyz; the points come out
 * in generation order (level by level).  At most PLATEAU_SEED_MAX_LEVELS
 * levels and PLATEAU_SEED_MAX_LEVEL_SIZE triangles per level are generated:
 * when these hold fewer than n inside candidates, all of them are returned,
 * *count < n and the result is still PLATEAU_OK (a thin polygon).  n = 0
 * gives *count = 0.  Same input and seed, same output bit for bit.
 * Memory O(candidates) through the allocator (about 90 bytes per triangle
 * of the deepest level: some 90 MB at the default level-size bound, reached
 * only by thin polygons asked for many points); time O(candidates * m).
 *
 * Threads: none of these functions keeps state between calls; each may run
 * in several threads at once.
 */
#ifndef PLATEAU_SEED_MAX_LEVELS
#define PLATEAU_SEED_MAX_LEVELS 16
#endif
#ifndef PLATEAU_SEED_MAX_LEVEL_SIZE
#define PLATEAU_SEED_MAX_LEVEL_SIZE 1048576 /* triangles in one level */
#endif
typedef enum plateau_seed_rule {
    /* Default.  Generate whole levels 0..K, K the first with at least n
     * inside candidates in all, then draw n of them uniformly without
     * replacement with the seeded generator. */
    PLATEAU_SEED_WHOLE_LEVELS = 0,
    /* Generate levels until the last one ALONE has at least n inside
     * candidates, then draw n of that level. */
    PLATEAU_SEED_LAST_LEVEL = 1,
    /* The paper read literally: the first n inside candidates in generation
     * order (centroid, fan j = 1..m, then each triangle's three children in
     * turn).  Crowds one side of the patch when n is not a whole level;
     * the seed is not used. */
    PLATEAU_SEED_LITERAL = 2
} plateau_seed_rule;
/* plateau_seed_points with the selection rule of your choice (for
 * comparing them with the paper's); parameters, results and errors as
 * plateau_seed_points, plus PLATEAU_ERR_ARGUMENT for an unknown rule. */
PLATEAU_DEF plateau_result plateau_seed_points_rule(const double *xyz, const double *uv,
                                                    size_t m, size_t n, uint64_t seed,
                                                    plateau_seed_rule rule,
                                                    const plateau_allocator *allocator,
                                                    double *xyz_out, double *uv_out,
                                                    size_t *count, plateau_error *err);
/* 1 when p lies inside the closed polygon uv (m vertices, either
 * orientation) at a distance greater than margin from every edge; 0
 * otherwise (also for NULL arguments or m < 3).  Even-odd rule. */
PLATEAU_DEF int plateau_point_in_polygon(const double *uv, size_t m, const double p[2],
                                         double margin);
/* ======== END SECTION: boundary, parameter domain and seeding =========== */

/* ======== SECTION: mesh and geometry kernel =============================
 * A triangle mesh owning its arrays: the vertices, the triangles and their
 * neighbours, then the adjacency built from them. */
typedef struct plateau_mesh {
    size_t num_vertices;
    double *positions;        /* 3 * num_vertices: x, y, z */
    unsigned char *fixed;     /* num_vertices: 1 = fixed (boundary), 0 = free */
    size_t num_triangles;
    plateau_index *triangles; /* 3 * num_triangles, consistently oriented */
    plateau_index *neighbors; /* 3 * num_triangles: across edge (v_k, v_(k+1)%3), -1 = boundary */
    plateau_allocator allocator;
    /* Adjacency, built from the triangles by
     * plateau_mesh_create and plateau_mesh_build_adjacency in O(V + T).
     * Read-only for users; rebuild it after editing the triangles.
     * Edge e joins edges[2e] = a and edges[2e+1] = b; edge_triangles[2e] is
     * the triangle that runs a -> b, edge_triangles[2e+1] the one that runs
     * b -> a (-1 on a boundary edge).  The edges of vertex v are
     * vertex_edges[vertex_edge_start[v] .. vertex_edge_start[v+1]), in
     * increasing edge order; likewise its triangles. */
    size_t num_edges;
    plateau_index *edges;            /* 2 * num_edges */
    plateau_index *edge_triangles;   /* 2 * num_edges */
    plateau_index *triangle_edges;   /* 3 * num_triangles: edge of (v_k, v_(k+1)%3) */
    size_t *vertex_edge_start;       /* num_vertices + 1 */
    plateau_index *vertex_edges;     /* 2 * num_edges */
    size_t *vertex_triangle_start;   /* num_vertices + 1 */
    plateau_index *vertex_triangles; /* 3 * num_triangles */
} plateau_mesh;
/* Frees every array of the mesh through the mesh's allocator and zeroes it.
 *   in/out mesh: a mesh from plateau_mesh_create or plateau_solve (also after
 *       their error), or an all-zero one; NULL is ignored. */
PLATEAU_DEF void plateau_mesh_free(plateau_mesh *mesh);

/* Creates a mesh by copying positions (3 * num_vertices), triangles
 * (3 * num_triangles, one consistent orientation) and fixed (num_vertices
 * flags; NULL: the vertices on boundary edges are fixed), then builds the
 * adjacency.  allocator may be NULL (PLATEAU_MALLOC / PLATEAU_FREE); the mesh
 * keeps a copy of it.
 *   in  positions, num_vertices (>= 3), fixed (or NULL), triangles,
 *       num_triangles (>= 1), allocator (or NULL);
 *   out mesh (free with plateau_mesh_free), err (may be NULL).
 * Returns PLATEAU_OK or the error (err->index names the vertex or triangle):
 * PLATEAU_ERR_ARGUMENT, _NOT_FINITE (vertex), _INDEX_RANGE (triangle),
 * _DEGENERATE_TRIANGLE (a triangle repeats a vertex), _NON_MANIFOLD (the
 * triangle bringing a third face to an edge), _ORIENTATION (the second
 * triangle running an edge in the same direction), _OUT_OF_MEMORY, _OVERFLOW.
 * On error the mesh is all zero.  Thread safety: distinct meshes, any thread. */
PLATEAU_DEF plateau_result plateau_mesh_create(const double *positions, size_t num_vertices,
                                               const unsigned char *fixed,
                                               const plateau_index *triangles,
                                               size_t num_triangles,
                                               const plateau_allocator *allocator,
                                               plateau_mesh *mesh, plateau_error *err);
/* Rebuilds neighbors and the adjacency fields from mesh->triangles (after the
 * caller changed them), in O(V + T), with the same checks and errors as
 * plateau_mesh_create.  in/out mesh; out err (may be NULL, untouched on
 * success).  On error the adjacency arrays are freed (zero). */
PLATEAU_DEF plateau_result plateau_mesh_build_adjacency(plateau_mesh *mesh, plateau_error *err);
/* Checks the invariants of a mesh with its adjacency, for debugging (like
 * Triangle's checkmesh): finite positions; every triangle three distinct
 * vertices in range; across each edge a neighbour that runs it the other
 * way and names the triangle back (PLATEAU_ERR_ORIENTATION when it runs it
 * the same way), or -1 on a boundary edge; the edge records and the
 * per-vertex edge and triangle lists agree with the triangles.  Returns
 * PLATEAU_OK or the first failure (_ARGUMENT for an adjacency that does not
 * match, _NOT_FINITE, _INDEX_RANGE, _DEGENERATE_TRIANGLE, _ORIENTATION;
 * err->index the triangle, edge or vertex).  O(V + T).  Define
 * PLATEAU_SELF_CHECK before the implementation to run it after every
 * adjacency build (every change of connectivity in plateau_solve,
 * plateau_mesh_minimize, the flips and the vertex removal). */
PLATEAU_DEF plateau_result plateau_mesh_self_check(const plateau_mesh *mesh, plateau_error *err);

/* The queries below read a mesh with its adjacency (plateau_mesh_create,
 * plateau_solve) and do not check their indices: t < num_triangles,
 * v < num_vertices, e < num_edges.
 *
 * Triangle t: area, and its unit normal by the right-hand rule over
 * (v0, v1, v2) (zero vector for a zero-area triangle); returns the area.
 *   out normal (3 values). */
PLATEAU_DEF double plateau_triangle_area(const plateau_mesh *mesh, size_t t);
PLATEAU_DEF double plateau_triangle_normal(const plateau_mesh *mesh, size_t t, double normal[3]);
/* Barycentric cell area |B_v| = (1/3) sum of the areas of v's triangles (paper II.B). */
PLATEAU_DEF double plateau_vertex_area(const plateau_mesh *mesh, size_t v);
/* Total area, the sum of the triangle areas (method area's objective). */
PLATEAU_DEF double plateau_mesh_area(const plateau_mesh *mesh);
/* Length |e| of edge e, from edges[2e] to edges[2e + 1]. */
PLATEAU_DEF double plateau_edge_length(const plateau_mesh *mesh, size_t e);
/* Mean length over all edges (0 for a mesh without edges): the length scale
 * of the tangential rows and of the solvers' tolerances. */
PLATEAU_DEF double plateau_mean_edge_length(const plateau_mesh *mesh);
/* Area-weighted unit vertex normal (zero if undefined); returns the length of
 * the unnormalised sum N = sum over v's triangles of (p1 - p0) x (p2 - p0).
 *   out normal (3 values). */
PLATEAU_DEF double plateau_vertex_normal(const plateau_mesh *mesh, size_t v, double normal[3]);

/* Signed dihedral angle beta(e) of edge e in (-pi, pi] (paper II.B, Fig. 4):
 * with T1 = (a, b, c) and T2 = (b, a, d), unit normals n1, n2,
 * beta = atan2((n1 x n2) . (b - a) / |b - a|, n1 . n2), positive on a convex
 * crease when the normals point outward; 0 on a boundary edge and when a
 * face or the edge has zero size.  Returns beta in radians. */
PLATEAU_DEF double plateau_edge_dihedral(const plateau_mesh *mesh, size_t e);
/* beta(e) and its exact gradient.
 *   out vertices[0..3] = a, b, c, d (c, d = -1 on a boundary edge);
 *   out gradient[3k + j] = d beta / d (vertex k coordinate j) (all zero on a
 *       boundary edge).
 * This is the well-conditioned form of the paper's formula (3)
 * (examples/NOTES.md): d beta/dc = -n1/h1, d beta/dd = -n2/h2,
 * d beta/da = (1 - tc) n1/h1 + (1 - td) n2/h2, d beta/db = tc n1/h1 + td n2/h2,
 * with h1, h2 the heights of c, d over the edge and tc, td their foot
 * parameters; it stays exact at beta = 0, where formula (3) is 0/0.
 * Returns beta. */
PLATEAU_DEF double plateau_edge_dihedral_gradient(const plateau_mesh *mesh, size_t e,
                                                  plateau_index vertices[4],
                                                  double gradient[12]);

/* Cohen-Steiner-Morvan discrete mean curvature (paper II.B):
 * H_v = (1/|B_v|) sum over edges e of v of beta(e) |e| / 2; boundary edges
 * add nothing.  It approximates k1 + k2 (2/r on a sphere of radius r).
 * Returns H_v; 0 when |B_v| = 0. */
PLATEAU_DEF double plateau_vertex_mean_curvature(const plateau_mesh *mesh, size_t v);
/* Number of vertices H_v (and the tangential residual) depend on: v and its
 * one-ring, 1 + (number of edges of v).  Capacity for the sparse rows below. */
PLATEAU_DEF size_t plateau_vertex_stencil_size(const plateau_mesh *mesh, size_t v);
/* H_v and its exact gradient as a sparse row (paper formula (2) with the
 * corrected derivative of beta, II.C.1 for d|B|, II.C.2 for d|e|).
 *   in  v, capacity (>= plateau_vertex_stencil_size(mesh, v));
 *   out vertices[k] (k < *count): vertices[0] = v, then v's neighbours in
 *       edge order; gradient[3k + j] = dH_v / d(vertex k coordinate j)
 *       (3 * capacity doubles); *count; *h = H_v (h may be NULL).
 * Returns PLATEAU_OK; PLATEAU_ERR_ARGUMENT for a NULL pointer, v out of
 * range, or a capacity too small (then *count is the size needed).  Zero
 * gradient and H when |B_v| = 0. */
PLATEAU_DEF plateau_result plateau_vertex_mean_curvature_gradient(const plateau_mesh *mesh,
                                                                  size_t v, size_t capacity,
                                                                  plateau_index *vertices,
                                                                  double *gradient,
                                                                  size_t *count, double *h);
/* Mean curvature vector of Meyer, Desbrun, Schroeder and Barr (2003), the
 * paper's reference [12]: K = (1 / (2 A_mixed)) sum_j (cot alpha_j +
 * cot beta_j) (x_v - x_j), with their mixed (Voronoi / obtuse) area.  K
 * approximates (k1 + k2) n.  Writes K to k (may be NULL) and returns
 * K . (vertex normal), comparable with H_v.  0 for an isolated vertex. */
PLATEAU_DEF double plateau_vertex_mean_curvature_vector(const plateau_mesh *mesh, size_t v,
                                                        double k[3]);

/* Tangential residual (examples/NOTES.md; method paper's extra rows, not in the
 * paper): the tangential part of (mean of v's neighbours - x_v), as its two
 * components on a tangent frame (t1, t2) of the vertex normal n, times
 * weight (the solver uses lambda / (mean edge length)^2).
 * t1 = normalise(e x n) with e the coordinate axis least aligned with n,
 * t2 = n x t1.  out r (2 values; zero without neighbours or normal). */
PLATEAU_DEF void plateau_vertex_tangential(const plateau_mesh *mesh, size_t v, double weight,
                                           double r[2]);
/* The same with its exact Jacobian (the frame is differentiated too):
 * capacity, vertices and *count as for the mean curvature gradient;
 *   out gradient[6k + 3 row + j] = d r_row / d(vertex k coordinate j)
 *       (6 * capacity doubles); r (may be NULL).
 * Returns PLATEAU_OK or PLATEAU_ERR_ARGUMENT, as the mean curvature
 * gradient. */
PLATEAU_DEF plateau_result plateau_vertex_tangential_gradient(const plateau_mesh *mesh, size_t v,
                                                              double weight, size_t capacity,
                                                              plateau_index *vertices,
                                                              double *gradient, size_t *count,
                                                              double r[2]);

/* Gradient of the total area with respect to every vertex position: the sum
 * over triangles of (1/2) n x (opposite edge) (paper II.C.1); its negative
 * is the mean curvature vector times the area (Pinkall-Polthier).
 *   out gradient (3 * num_vertices values, fixed vertices included; a
 *       zero-area triangle adds nothing). */
PLATEAU_DEF void plateau_mesh_area_gradient(const plateau_mesh *mesh, double *gradient);
/* The signed volume of the cone from apex (NULL: the origin) over the
 * mesh, V = sum over triangles (a, b, c) of (a - o) . ((b - o) x (c - o)) / 6
 * with o the apex: positive where the normals point away from the apex (a
 * closed mesh with outward normals gives its enclosed volume, whatever the
 * apex).  gradient (may be NULL): 3 per vertex, dV/da = sum over a's
 * triangles of (b - o) x (c - o) / 6.  Over a fixed boundary the variation
 * of V does not depend on the apex (the cone's side does not move). */
PLATEAU_DEF double plateau_mesh_volume(const plateau_mesh *mesh, const double apex[3], double *gradient);
/* The energy of a membrane (MEMBRANES at the top): E = area - pressure V +
 * sum over the num_segments cable segments s = (segments[2s],
 * segments[2s + 1]) of tensions[s] times the segment's length; V as
 * plateau_mesh_volume from apex.  gradient (may be NULL): 3 per vertex,
 * the exact dE/dx (tests/test_membrane.c checks it against central
 * differences). */
PLATEAU_DEF double plateau_membrane_energy(const plateau_mesh *mesh, double pressure, const double apex[3],
                                           const plateau_index *segments, const double *tensions,
                                           size_t num_segments, double *gradient);

/* Gradient and Hessian of the total area in normal coordinates: every vertex
 * v moves along a fixed direction m_v, x_v(t) = x_v + t_v m_v, and the
 * derivatives are taken at t = 0 (Surface Evolver's hessian_normal; the
 * Newton step of plateau_solve's coarse-to-fine path).  Per triangle
 * (p_0, p_1, p_2) with e_i = p_(i+1) - p_(i+2), N = (p_1 - p_0) x (p_2 - p_0),
 * n = N / |N| and a_i = m_i x e_i, since dN/dt_i = a_i and
 * d2N/dt_i dt_j = s_ij m_i x m_j (s_ij = +1 for j = i + 1, -1 for j = i + 2
 * mod 3, 0 for j = i), the area A = |N| / 2 has
 *     dA/dt_i        = n.a_i / 2,
 *     d2A/dt_i dt_j  = (a_i.a_j - (n.a_i)(n.a_j)) / (2 |N|) + s_ij n.(m_i x m_j) / 2.
 * The Hessian's pattern is the vertex adjacency: its diagonal per vertex and
 * one value per edge (symmetric).  Fixed vertices are included (drop their
 * rows and columns to keep them fixed).
 *   in  mesh (with adjacency), directions (3 * num_vertices: m_v; NULL: the
 *       unit area-weighted vertex normals of plateau_vertex_normal);
 *   out gradient (num_vertices: dA/dt_v; may be NULL),
 *       diagonal (num_vertices: d2A/dt_v^2), off_diagonal (num_edges:
 *       d2A/dt_a dt_b for edge e = (edges[2e], edges[2e+1])); both may be
 *       NULL together (the gradient alone);
 *   out err (may be NULL, untouched on success).
 * Returns PLATEAU_OK, _ARGUMENT (no mesh or adjacency, or only one of the
 * two Hessian arrays) or _DEGENERATE_TRIANGLE (a triangle of zero area,
 * where the Hessian does not exist; err->index names it; the outputs are
 * then partial).  O(V + T) with directions given, no allocation; with
 * NULL each corner recomputes its vertex's normal, O(sum of the squared
 * valences) (pass the normals for meshes with fan vertices).  Thread
 * safety: any thread. */
PLATEAU_DEF plateau_result plateau_mesh_area_hessian_normal(const plateau_mesh *mesh,
                                                            const double *directions,
                                                            double *gradient, double *diagonal,
                                                            double *off_diagonal,
                                                            plateau_error *err);

/* Degeneration check of a mesh (run by the solver after every solve). */
typedef struct plateau_quality {
    double area;
    double min_angle_deg, max_angle_deg; /* over all triangle corners */
    double max_abs_beta_deg;             /* largest |dihedral| over interior edges */
    size_t inverted_triangles; /* zero area, or facing against its neighbours:
                                  sum of n_t . n_u over neighbours u < 0 */
    /* The defect counts (all zero on a valid mesh; thresholds below): */
    size_t folded_edges;         /* interior edges with |dihedral| above
                                    PLATEAU_FOLD_DEGREES */
    size_t degenerate_triangles; /* a corner angle below PLATEAU_DEGENERATE_DEGREES
                                    (zero-area triangles included) */
    size_t intersecting_pairs;   /* pairs of triangles that meet other than in
                                    their shared vertex or edge (plateau_mesh_check
                                    only; plateau_mesh_quality leaves 0) */
    unsigned defects;            /* PLATEAU_DEFECT_* bits of the counts above;
                                    0: valid */
} plateau_quality;
/* Fills *quality (out) from the mesh: the check for folds and slivers that
 * examples/NOTES.md asks for after every solve (zero H does not mean smooth:
 * large opposite creases can cancel).  Everything but intersecting_pairs
 * (O(T), no allocation). */
PLATEAU_DEF void plateau_mesh_quality(const plateau_mesh *mesh, plateau_quality *quality);

/* The defects of a mesh (plateau_quality.defects, plateau_report.defects):
 * one bit per kind, 0 for a valid mesh; plateau_defects_string names them. */
#define PLATEAU_DEFECT_INVERTED 1u     /* inverted_triangles > 0 */
#define PLATEAU_DEFECT_FOLD 2u         /* folded_edges > 0 */
#define PLATEAU_DEFECT_DEGENERATE 4u   /* degenerate_triangles > 0 */
#define PLATEAU_DEFECT_INTERSECTION 8u /* intersecting_pairs > 0 */
#define PLATEAU_DEFECT_UNSOLVED 16u    /* the solver's objective did not reach its
                                          stopping rule (plateau_report only) */
#define PLATEAU_DEFECT_PINCHED 32u     /* two loops: the film's neck collapsed
                                          (plateau_report only; PLATEAU_STOP_PINCHED) */
#define PLATEAU_DEFECT_NO_EQUILIBRIUM 64u /* a pressure: the film ran away from
                                          the boundary (no film of that pressure
                                          spans it), or cables left out of
                                          balance (no film spans the frame
                                          with those cables; plateau_report
                                          only) */
#define PLATEAU_DEFECT_VOLUME 128u     /* options.fix_volume: the volume was
                                          not reached (plateau_report only) */
#define PLATEAU_DEFECT_CABLE 256u      /* a cable crosses the film or another
                                          edge (plateau_report only) */
/* A fold: two neighbouring triangles meet at less than 30 degrees, i.e. the
 * surface turns back on itself (a minimal surface meshed at any usable
 * resolution has dihedrals of tens of degrees; the measurements behind the
 * bound: examples/NOTES.md, "Measurements behind the solver's choices"). */
#ifndef PLATEAU_FOLD_DEGREES
#define PLATEAU_FOLD_DEGREES 150.0
#endif
/* A degenerate triangle: a corner angle whose sine is below about
 * sqrt(DBL_EPSILON) (1e-6 degrees = 1.7e-8 rad), where its normal, and so
 * the dihedrals and H at its edges, keep fewer than half of their digits. */
#ifndef PLATEAU_DEGENERATE_DEGREES
#define PLATEAU_DEGENERATE_DEGREES 1e-6
#endif

/* The whole final check of a mesh: plateau_mesh_quality, and the pairs of
 * triangles that intersect each other (intersecting_pairs) found by
 * pairing edges with triangles that share no vertex with them, in a
 * uniform grid that long triangles and edges enter piece by piece (at
 * most 32 T + 1024 cell entries; O(T log T) for a mesh of even size, and
 * for fans of long thin triangles around vertices of any valence, whose
 * triangles all share the centre) and, per candidate, segment-triangle tests
 * built on the orientation predicate orient3d with Shewchuk's static error
 * bound (a sign that rounding cannot decide counts as touching: near
 * contacts are flagged, never missed).  Triangles with no common vertex
 * intersect when an edge of one meets the other (closed: touching counts);
 * triangles with one common vertex s, (s, a, b) and (s, c, d), when the
 * opposite edge ab meets (s, c, d) or cd meets (s, a, b) (their intersection
 * is convex and contains s; any other point of it is reached so), coplanar
 * overlaps included; triangles with a common edge overlap only when folded
 * flat, which the fold count reports.  Uses the mesh's allocator.
 * Returns PLATEAU_OK, _ARGUMENT (NULL mesh or quality), _OUT_OF_MEMORY or
 * _OVERFLOW (*quality then holds plateau_mesh_quality's part). */
PLATEAU_DEF plateau_result plateau_mesh_check(const plateau_mesh *mesh, plateau_quality *quality,
                                              plateau_error *err);

/* Residual vector and Jacobian for the solver, as sparse per-vertex rows.
 * For each selected vertex v in increasing order: one row H_v, then (if
 * tangential_weight > 0) its two tangential rows.  Columns: 3 per free
 * (not fixed) vertex, in vertex order; fixed vertices get no column. */
typedef struct plateau_system_options {
    const unsigned char *row_vertices; /* num_vertices flags; NULL = the free vertices */
    double tangential_weight;          /* 0: H rows only */
    int residual_only;                 /* non-zero: skip the Jacobian */
    double mean_curvature;             /* the value H rows are to reach: the
                                          residual is H_v minus it (0: zero
                                          mean curvature; a pressure p asks
                                          for H_v = p, MEMBRANES) */
} plateau_system_options;
typedef struct plateau_system {
    size_t num_rows, num_columns, num_blocks;
    double *residual;              /* num_rows */
    plateau_index *row_vertex;     /* num_rows: the vertex of each row */
    size_t *row_start;             /* num_rows + 1: row r has blocks [row_start[r], row_start[r+1]) */
    plateau_index *block_vertex;   /* num_blocks: a free vertex */
    double *block_value;           /* 3 * num_blocks: d row / d(x, y, z of that vertex) */
    plateau_index *column_of_vertex; /* num_vertices: first column, -1 if fixed */
    plateau_allocator allocator;
} plateau_system;
/* Assembles the rows of the selected vertices (paper II.D's f(x) and J).
 *   in  mesh (with adjacency), options (may be NULL: H rows of the free
 *       vertices, with the Jacobian);
 *   in/out system: all-zero on first use; earlier contents are freed; the
 *       arrays come from the mesh's allocator (free with
 *       plateau_system_free);
 *   out err (may be NULL, untouched on success).
 * Returns PLATEAU_OK, _ARGUMENT (no mesh, adjacency or system) or
 * _OUT_OF_MEMORY (also for a size that overflows). */
PLATEAU_DEF plateau_result plateau_system_assemble(const plateau_mesh *mesh,
                                                   const plateau_system_options *options,
                                                   plateau_system *system, plateau_error *err);
/* Dense row-major num_rows x num_columns Jacobian from the sparse rows (the
 * form plateau_lm.h takes).  out jacobian (num_rows * num_columns doubles;
 * all zero after a residual_only assembly). */
PLATEAU_DEF void plateau_system_dense(const plateau_system *system, double *jacobian);
/* Frees the system's arrays and zeroes it; accepts an all-zero system. */
PLATEAU_DEF void plateau_system_free(plateau_system *system);
/* ======== END SECTION: mesh and geometry kernel ======================== */

/* ======== SECTION: options, report; steps 5-6 and the final check ======= */
typedef enum plateau_method {
    PLATEAU_METHOD_PAPER = 0,         /* interior H_i + tangential condition, 3-D flips */
    PLATEAU_METHOD_PAPER_LITERAL = 1, /* the paper as printed, for teaching */
    PLATEAU_METHOD_AREA = 2           /* area minimisation (Chen, Cai and Zheng) */
} plateau_method;

/* How method paper solves its square system (plateau_options.linear_solver,
 * plateau_report.linear_solver).  DENSE: plateau_lm_solve, the LM of paper
 * II.D on the dense Jacobian (O(n^2) memory, O(n^3) time per step);
 * SPARSE: plateau_lm_dogleg_solve, Powell's dog leg with the sparse block
 * LU of the Jacobian (3 x 3 blocks on the 1-ring pattern, nested-dissection
 * order), same stopping rules, except that a dog leg ended by its step test
 * with F above the solved bound (1e-10, see plateau_report.solved) goes on
 * for at most 5 more steps with the step test at rounding level (the step
 * test is relative to ||x||, which a large Jacobian makes too coarse for
 * F: the short edges of a densely sampled boundary, or a large lambda);
 * both reach the same root where both converge.  AUTO picks SPARSE above
 * PLATEAU_SPARSE_THRESHOLD free vertices. */
typedef enum plateau_linear_solver {
    PLATEAU_LINEAR_AUTO = 0,
    PLATEAU_LINEAR_DENSE = 1,
    PLATEAU_LINEAR_SPARSE = 2
} plateau_linear_solver;
#define PLATEAU_SPARSE_THRESHOLD 200
/* From this many interior points, methods area and paper take the coarse-
 * to-fine path by default (plateau_options.coarse_to_fine AUTO). */
#ifndef PLATEAU_COARSE_TO_FINE_POINTS
#define PLATEAU_COARSE_TO_FINE_POINTS 200
#endif

/* Where the interior points come from (plateau_options.seeding). */
typedef enum plateau_seeding {
    PLATEAU_SEEDING_AUTO = 0,    /* default: quality when n >= m / 4, else paper */
    PLATEAU_SEEDING_PAPER = 1,   /* paper II.A: fan barycentres (plateau_seed_points) */
    PLATEAU_SEEDING_QUALITY = 2  /* Delaunay refinement of the domain */
} plateau_seeding;

/* The value of an option that the library decides unless the caller forces
 * it (plateau_options.area_warm_start, .paper_presolve, .refine_boundary):
 * PLATEAU_AUTO, 0 so that all-zero options are the defaults, lets the
 * library decide as the option's comment says; PLATEAU_ON and PLATEAU_OFF
 * force it.  Any other value is PLATEAU_ERR_ARGUMENT. */
typedef enum plateau_switch {
    PLATEAU_OFF = -1,
    PLATEAU_AUTO = 0,
    PLATEAU_ON = 1
} plateau_switch;

typedef struct plateau_options {
    /* all-zero means the documented defaults */
    plateau_method method;
    size_t interior_points; /* n; 0 -> documented default */
    uint64_t seed;          /* 0 -> fixed default seed */
    int max_rounds;         /* 0 -> documented default */
    int force_circle_domain; /* non-zero: step 2 lays the boundary on the
                           circle (two loops: the annulus) even where the
                           best-fit plane works; 0: the plane when the
                           polygon projects there as a simple polygon */
    /* progress: called per LM / quasi-Newton iteration; non-zero aborts */
    int (*progress)(int round, int iteration, double f, void *user);
    void *progress_user;
    plateau_allocator allocator;
    /* solver settings (all-zero still means the defaults): */
    double lambda;      /* method paper: weight of the tangential rows, scaled by
                           1 / (mean edge length)^2; 0 -> 1 (the solution does not
                           depend on it: the square system is solved exactly);
                           negative, infinite or NaN: PLATEAU_ERR_ARGUMENT */
    int max_iterations; /* per solve; 0 -> 200 (LM) or 5000 (L-BFGS) */
    plateau_switch area_warm_start; /* method area (and method paper's area
                            presolve): one Pinkall-Polthier (cotangent
                            Laplace) solve before the first round; AUTO: above
                            PLATEAU_SPARSE_THRESHOLD free vertices */
    plateau_switch paper_presolve; /* method paper: start from the result of
                            method area's rounds; AUTO: on the circle and
                            annulus domains (the seeded mesh is folded in 3-D
                            there, and LM from it finds folded roots) */
    /* quality seeding (all-zero still means the defaults): */
    plateau_seeding seeding; /* step 3 (PLATEAU_SEEDING_AUTO = 0: QUALITY
                           when n >= m / 4 and it gives >= n / 2 points, else
                           PAPER; PLATEAU_SEEDING_QUALITY: Delaunay refinement
                           of the domain, see plateau_solve;
                           PLATEAU_SEEDING_PAPER: the paper's fan candidates) */
    plateau_switch refine_boundary; /* quality seeding: ON lets the refinement
                           add vertices on the polygon's edges (fixed, on the
                           straight 3-D edges; report.boundary_points_added);
                           OFF keeps the polygon as given; AUTO: ON for method
                           area (and method paper's area presolve) when the
                           longest edge is more than 2 interior spacings long,
                           else OFF (one loop; several loops keep theirs) */
    double quality_min_angle; /* quality seeding: the refinement's angle bound in
                           degrees; 0 -> 26 (Miller-Pav-Walkington's proven 26.45);
                           at most 34 (clamped by plateau_delaunay.h) */
    double quality_edge_length; /* quality seeding: target edge length in the
                           domain, in the polygon's units; 0 -> aim at
                           interior_points interior vertices instead */
    size_t max_memory;  /* bytes a solve may need by the estimate of
                           plateau_memory_estimate; above it plateau_solve and
                           plateau_mesh_minimize refuse before they start
                           (PLATEAU_ERR_MEMORY_LIMIT); 0 ->
                           PLATEAU_DEFAULT_MAX_MEMORY, (size_t)-1: no limit */
    plateau_linear_solver linear_solver; /* methods paper and area; AUTO (0):
                           up to PLATEAU_SPARSE_THRESHOLD free vertices
                           the dense LM (paper) or the L-BFGS (area), above it
                           the sparse dog leg (paper) or the sparse Newton
                           method (area) */
    double area_tolerance; /* method area on the sparse path (the Newton
                           method): a solve ends when its last 5 steps lowered
                           the area by less than this fraction of it; 0 ->
                           1e-6 (the rounds end at 3e-5 per round); at most
                           1e-2 */
    /* membranes (MEMBRANES at the top; all zero: a soap film on a rigid
     * frame).  Methods paper and area; paper-literal refuses them. */
    double pressure;    /* p, the pressure difference across the film of unit
                           surface tension: the energy is area - p V, V the
                           signed volume of the cone from the boundary's
                           centroid over the film (positive where the film
                           bulges to the side its normals point to); method
                           paper solves H_i = p.  Finite, else
                           PLATEAU_ERR_PRESSURE */
    int fix_volume;     /* non-zero: hold V = volume instead (a Lagrange
                           multiplier, reported as report.pressure); pressure
                           is then the multiplier's first guess */
    double volume;      /* the volume held when fix_volume (finite) */
    const double *cable_tension; /* NULL, or one per boundary vertex (all loops):
                           T > 0 makes the edge from that vertex to the next
                           of its loop a cable of tension T, 0 a rigid edge;
                           negative, not finite, or below half the edge's
                           length: PLATEAU_ERR_CABLE */
    plateau_switch coarse_to_fine; /* methods area and paper, one polygon:
                           solve a coarse mesh, then subdivide it 1-to-4 level
                           by level with Newton steps on normal motions (see
                           COARSE TO FINE at the top); AUTO: from
                           PLATEAU_COARSE_TO_FINE_POINTS interior points when
                           the quality seeding may refine the polygon's edges
                           (refine_boundary not OFF and, for AUTO, its rule
                           holds at n; quality_edge_length 0; seeding not
                           PAPER; linear_solver AUTO); ON: whenever a level fits (n at least about
                           4 * 16 + m), PLATEAU_ERR_ARGUMENT with
                           refine_boundary OFF, seeding PAPER,
                           quality_edge_length > 0, method paper-literal,
                           several loops or a membrane (pressure, fix_volume
                           or cable_tension: AUTO is off for them); OFF: the
                           rounds at full size */
    /* time budget (all-zero: none): */
    double max_seconds; /* > 0: once this many seconds have passed since the
                           call began, the solve stops at its next iteration
                           or round with the mesh it has (report.stop
                           PLATEAU_STOP_TIME_LIMIT; the seeding always
                           finishes, so there is a mesh), the saddle search
                           of critical_index at its next Newton step, and
                           the stability report is not computed; 0: no
                           limit; +inf too; negative or NaN:
                           PLATEAU_ERR_ARGUMENT */
    double (*clock_fn)(void *user); /* seconds on any fixed origin, read at
                           the start and at every check; NULL: processor
                           seconds by clock() of <time.h> (under
                           PLATEAU_FREESTANDING there is no clock(): a
                           max_seconds without clock_fn is refused) */
    void *clock_user;   /* passed to clock_fn */
    plateau_switch stability; /* the second-order status of the result
                           (plateau_mesh_stability, 2 eigenvalues) into
                           report.stability; AUTO: ON (one more sparse
                           factorisation on the analysis of the solver's
                           last sparse solve, and the Lanczos solves:
                           examples/NOTES.md section 12); OFF skips it */
    plateau_switch alternatives; /* two loops: also solve one disc per loop
                           (same options, each loop alone) and report their
                           total area in report.alternative_area; AUTO: ON
                           for two loops (none other has an alternative) */
    int critical_index;  /* 0: the rounds' result (a minimum of its method);
                           K = 1 .. 7: then plateau_mesh_critical_point
                           from it, a critical point of the area of index
                           K near it (report.critical_converged; the
                           search may add vertices: report.interior_points
                           counts them) */
    int least_area_topology; /* two loops, non-zero: return the discs when
                           their total area is below the least film's found
                           (with critical_index, the rounds' film before the
                           search; the mesh then has two components;
                           report.discs_returned) */
    double accuracy;     /* the relative error of the area asked for
                           (ACCURACY at the top): > 0: solve, estimate
                           (report.area_error_estimate) and solve again
                           with more interior points, the polygon's edges
                           split to match, until the estimate is at most
                           this (interior_points, when given, is the first
                           count); 0: PLATEAU_DEFAULT_ACCURACY when
                           interior_points and quality_edge_length are 0
                           and the film is a soap film of methods paper or
                           area on one polygon (plateau_solve) without
                           critical_index or the paper's fan seeding
                           (seeding PAPER: its fan makes slivers at the
                           counts an accuracy needs), else none; < 0:
                           none (one solve at interior_points, m when 0);
                           NaN: PLATEAU_ERR_ARGUMENT */
} plateau_options;

/* The accuracy a solve aims at when neither interior_points nor
 * accuracy is given (plateau_options.accuracy): the relative error of the
 * area estimated by report.area_error_estimate. */
#ifndef PLATEAU_DEFAULT_ACCURACY
#define PLATEAU_DEFAULT_ACCURACY 1e-4
#endif
/* At most this many interior points in the solves of options.accuracy. */
#ifndef PLATEAU_ACCURACY_MAX_POINTS
#define PLATEAU_ACCURACY_MAX_POINTS 1000000
#endif
/* Whether report.area_error_estimate was formed, and why not. */
#define PLATEAU_ESTIMATE_LIST(X)                                                      \
    X(PLATEAU_ESTIMATE_FORMED, 0, "formed")                                           \
    X(PLATEAU_ESTIMATE_NO_RESULT, 1, "no result: the solve failed")                    \
    X(PLATEAU_ESTIMATE_MEMBRANE, 2, "not formed for a membrane (pressure, volume or cables)") \
    X(PLATEAU_ESTIMATE_DEGENERATE, 3, "a triangle of zero area: the area has no Hessian there") \
    X(PLATEAU_ESTIMATE_MEMORY, 4, "the subdivided mesh would exceed memory bound, options.max_memory") \
    X(PLATEAU_ESTIMATE_NO_AREA, 5, "the mesh has no area")                             \
    X(PLATEAU_ESTIMATE_COMPILED_OUT, 6, "the error estimate is compiled out by PLATEAU_NO_ACCURACY")
typedef enum plateau_estimate {
    PLATEAU_ESTIMATE_LIST(PLATEAU__ENUM)
    PLATEAU_ESTIMATE_COUNT = 0 PLATEAU_ESTIMATE_LIST(PLATEAU__COUNT)
} plateau_estimate;
/* The sentence for an estimate status (a static string, never NULL). */
PLATEAU_DEF const char *plateau_estimate_string(plateau_estimate status);

/* The pinch test of two loops (plateau_solve_loops): a neck shorter than
 * this fraction of the shorter loop is a collapsed film.  A stable
 * catenoid between coaxial rings has a waist of at least 0.55 of the
 * rings (at the limit h = 1.3255 R). */
#ifndef PLATEAU_PINCH_RATIO
#define PLATEAU_PINCH_RATIO 0.2
#endif
/* Why the rounds ended (plateau_report.stop). */
#define PLATEAU_STOP_LIST(X)                                                          \
    X(PLATEAU_STOP_CONVERGED, 0, "converged: the triangulation stopped changing")      \
    X(PLATEAU_STOP_ROUND_LIMIT, 1, "round limit reached")                               \
    X(PLATEAU_STOP_STALLED, 2, "stalled: three area solves without a smaller area (a defect)") \
    X(PLATEAU_STOP_DEFECTS, 3, "defects: the triangulation stopped changing, but the mesh is not valid") \
    X(PLATEAU_STOP_PINCHED, 4, "pinched: the film between the two loops collapsed to a thin neck; no connected minimal surface spans them") \
    X(PLATEAU_STOP_TIME_LIMIT, 5, "time limit: options.max_seconds ran out; the mesh is the last one reached")
/* CONVERGED: a solve was followed by no change of the triangulation;
 * ROUND_LIMIT: max_rounds solves were done; STALLED: an internal safety net,
 * never expected: 3 solves of method area without a smaller area (a solve
 * raised it); a defect.  DEFECTS: the triangulation stopped changing, but
 * the mesh has defects (report.defects): never "converged".  PINCHED (two
 * loops, plateau_solve_loops): the neck of the film between them fell below
 * PLATEAU_PINCH_RATIO of the shorter loop's length (report.neck_ratio):
 * the surface the solver was heading for does not exist (coaxial rings too
 * far apart carry no catenoid) and the mesh is no answer; a defect
 * (PLATEAU_DEFECT_PINCHED).  TIME_LIMIT: options.max_seconds ran out;
 * the mesh is the one the solve had reached (its last accepted iterate, or
 * the seeded mesh when no solve had begun); when a solve was cut short,
 * report.defects holds PLATEAU_DEFECT_UNSOLVED. */
typedef enum plateau_stop {
    PLATEAU_STOP_LIST(PLATEAU__ENUM)
    PLATEAU_STOP_COUNT = 0 PLATEAU_STOP_LIST(PLATEAU__COUNT)
} plateau_stop;

/* Why the last solve of method area ended (plateau_report.area_stop), by
 * either of its solvers (step 5): the L-BFGS up to PLATEAU_SPARSE_THRESHOLD
 * free vertices, the sparse Newton method above.
 *   GRADIENT        ||gradient||_inf <= 1e-10 times the mean edge length
 *                   (Newton: over the vertices it does not hold)
 *   SMALL_CHANGE    L-BFGS: the last 20 steps lowered the area by less than
 *                   1e-10 of it; Newton: the last 5 accepted steps by less
 *                   than options.area_tolerance of it
 *   LINE_SEARCH     no step lowers the area (L-BFGS: 60 halvings; Newton:
 *                   its damping mu passed 1e12, or a triangle is degenerate)
 *   MAX_ITERATIONS  max_iterations steps (Newton: accepted steps, or
 *                   4 max_iterations tries; coarse to fine: a level's
 *                   steps reached min(max_iterations, 20))
 *   DECREMENT       coarse to fine: half the Newton decrement on normal
 *                   motions fell below 1 % of the level's extrapolated
 *                   excess (see COARSE TO FINE at the top) */
#define PLATEAU_AREA_STOP_LIST(X)                                                    \
    X(PLATEAU_AREA_STOP_NONE, 0, "no solve of method area")                           \
    X(PLATEAU_AREA_STOP_GRADIENT, 1, "gradient test")                                 \
    X(PLATEAU_AREA_STOP_SMALL_CHANGE, 2, "area change test")                          \
    X(PLATEAU_AREA_STOP_LINE_SEARCH, 3, "line search: no step lowers the area")       \
    X(PLATEAU_AREA_STOP_MAX_ITERATIONS, 4, "max_iterations reached")                 \
    X(PLATEAU_AREA_STOP_DECREMENT, 5, "Newton decrement test")
typedef enum plateau_area_stop {
    PLATEAU_AREA_STOP_LIST(PLATEAU__ENUM)
    PLATEAU_AREA_STOP_COUNT = 0 PLATEAU_AREA_STOP_LIST(PLATEAU__COUNT)
} plateau_area_stop;

/* Solves whose objective plateau_report.f_rounds keeps. */
#define PLATEAU_REPORT_F_ROUNDS 8
/* Cables whose measures plateau_report.cable keeps (report.cables counts
 * them all). */
#define PLATEAU_REPORT_CABLES 16
/* One cable of the result, in the caller's units: the mesh vertex of its
 * first anchor (the cable runs from there along the boundary through
 * `vertices` free cable vertices to the next anchor), its tension, its
 * length and its sag (the largest distance of a cable vertex from the
 * chord between its anchors). */
typedef struct plateau_cable_result {
    size_t anchor, vertices;
    double tension, length, sag;
} plateau_cable_result;
/* The default of plateau_options.max_memory: 2 GiB (it fits a 32-bit
 * size_t).  Define it before the first inclusion to change it. */
#ifndef PLATEAU_DEFAULT_MAX_MEMORY
#define PLATEAU_DEFAULT_MAX_MEMORY ((size_t)1 << 31)
#endif

/* Bytes that a solve by method of m fixed (boundary) and n free
 * (interior) vertices needs at its peak, by an upper bound fitted to the
 * peaks of a counting allocator (examples/NOTES.md, "Measurements behind
 * the solver's choices"; tests/test_manual.c checks these formulas):
 *   paper          224 n^2 + 3200 (n + m)   (LM's dense 3n x 3n matrices,
 *                                            plus method area's presolve),
 *                  up to n = PLATEAU_SPARSE_THRESHOLD; above it (the sparse
 *                  path) 640 n ceil(log2(n + 2)) + 1600 (n + m) + 8192
 *   paper-literal  48 n (n + m) + 4500 (n + m)   ((m + n) x 3n Jacobian)
 *   area           1000 n + 400 m + 8192 up to n = PLATEAU_SPARSE_THRESHOLD
 *                  (L-BFGS), above it paper's sparse bound (the Newton
 *                  method's Cholesky)
 *   coarse to fine (methods area and paper, options.coarse_to_fine)
 *                  64 n ceil(log2(n + 2)) + 1600 (n + m) + 8192 (the
 *                  finest mesh and its predecessor, one scalar Cholesky
 *                  or LU factor); plateau_solve checks this one when that
 *                  path may run, and the bound above if it falls back to
 *                  the rounds at full size
 * A double, so that no size overflows; for an unknown method, paper's.
 * plateau_solve compares it with options.max_memory before it allocates
 * anything (with n = interior_points, default m), and again after steps
 * 3-4 with the interior points the seeding made (quality seeding: about
 * n, or about A / (sqrt(3) / 4 L^2) for quality_edge_length L on a domain
 * of area A, estimated before the refinement runs); where that second
 * check refuses method paper's sparse path, the factor's exact size from
 * the seeded triangulation decides instead (MEMORY in the manual). */
PLATEAU_DEF double plateau_memory_estimate(plateau_method method, size_t m, size_t n);

/* ---- the second-order status of a result (the stability report) ----
 * Whether a mesh is a minimum of the area, a saddle or neither: the area
 * Hessian with respect to the free vertices restricted to normal motions
 * (plateau_mesh_area_hessian_normal with the unit vertex normals, Surface
 * Evolver's hessian_normal: one unknown per free vertex, so that the
 * near-null tangential motions of a discrete surface do not count) is
 * taken with the lumped metric M = diag(|B_v|) (plateau_vertex_area), and
 * the generalised eigenvalues H u = lambda M u approximate those of the
 * Jacobi operator -Laplacian - |A|^2 of the smooth surface (the second
 * variation of area, int |grad u|^2 - |A|^2 u^2), independent of the
 * mesh size.  The index (negative eigenvalues) is an exact count:
 * Sylvester's law on the sparse L D L^T of M^-1/2 H M^-1/2
 * (plateau_lm_sparse_inertia); the lowest eigenvalues come from block
 * Lanczos on the shifted inverse of that factorisation (two vectors per
 * step, so that double eigenvalues show both copies, solved together;
 * full reorthogonalisation; it stops once the values asked for have
 * converged, each to an error bound of 1e-8 relative, its residual
 * squared over the gap to its neighbour, or with modes asked for to a
 * residual of 1e-8, after at most PLATEAU_STABILITY_LANCZOS vectors),
 * with a shift below the spectrum when the index is not 0.  A mesh with
 * index 0 and a small area gradient is a discrete local minimum of the
 * area; index k > 0 says the area decreases along k independent normal
 * motions.  For method paper, whose F is not the area, the gradient
 * norm is not 0 and the index says whether a nearby area minimum is a
 * minimum at all.
 * Cost: one analysis and one or two factorisations of an order-n
 * symmetric matrix on the vertex graph (as one Newton step of method
 * area; after plateau_solve, the analysis or the elimination order of
 * its last sparse solve on the same pattern is reused), plus one solve
 * per Lanczos vector (at most
 * PLATEAU_STABILITY_LANCZOS, 40 unless defined before the first
 * inclusion; fewer for fewer eigenvalues: plateau_solve asks for 2;
 * examples/NOTES.md section 12 has the measurements). */
#define PLATEAU_STABILITY_MAX_EIGENVALUES 8
#ifndef PLATEAU_STABILITY_LANCZOS
#define PLATEAU_STABILITY_LANCZOS 40
#endif
typedef struct plateau_stability {
    int computed;            /* 1: the fields below are filled; 0: not asked
                                for (options.stability OFF) or no free vertex */
    size_t index;            /* eigenvalues below -shift: the stability index */
    size_t free_vertices;    /* the order of the Hessian */
    size_t num_eigenvalues;  /* entries of lowest_eigenvalues that are filled
                                (Ritz values that passed the convergence
                                test above) */
    double lowest_eigenvalues[PLATEAU_STABILITY_MAX_EIGENVALUES]; /* ascending,
                                units 1 / length^2 */
    double area_gradient_norm; /* Euclidean norm of the area gradient over the
                                free vertices' coordinates (units: length) */
    double shift;            /* 0, or the shift sigma > 0 of H + sigma M that
                                the L D L^T needed when H itself had a
                                (near-)zero pivot: eigenvalues in (-sigma, 0]
                                are then not counted */
} plateau_stability;
/* The stability report of a mesh with adjacency.
 *   in  mesh, num_eigenvalues (how many of the lowest to compute, at most
 *       PLATEAU_STABILITY_MAX_EIGENVALUES; 0: the index and gradient only);
 *   out stability (all of it written), modes (NULL, or num_eigenvalues *
 *       num_vertices values: mode j at modes + j num_vertices, the normal
 *       displacement per vertex, 0 at fixed vertices, normalised so that
 *       sum |B_v| u_v^2 = 1 and its largest entry is positive; entries of
 *       modes beyond stability->num_eigenvalues are 0), err.
 * Returns PLATEAU_OK, _ARGUMENT (no mesh or adjacency, too many
 * eigenvalues), _OUT_OF_MEMORY, _OVERFLOW, _DEGENERATE_TRIANGLE (a
 * zero-area triangle: no Hessian), _SOLVER (no shift up to 1e4 times
 * the largest diagonal entry gave a factorisation).  Uses the mesh's
 * allocator; deterministic (a fixed Lanczos start); thread safety: any
 * thread, distinct outputs. */
PLATEAU_DEF plateau_result plateau_mesh_stability(const plateau_mesh *mesh, size_t num_eigenvalues,
                                                  plateau_stability *stability, double *modes,
                                                  plateau_error *err);
/* A critical point of the area of the given index near the mesh (a start
 * the caller gives: a mesh with the boundary wanted, e.g. a solved film,
 * or the film of a boundary just edited): Newton's method on normal
 * motions (the Hessian of plateau_mesh_stability, one unknown per free
 * vertex along its unit normal, renewed every step) with eigenvector
 * following (Cerjan and Miller 1981; Surface Evolver's saddle): along the
 * `index` lowest eigenvectors the step goes up (Newton towards the maximum
 * where the eigenvalue is negative, else a climb, in the direction along
 * which the area rises less), along the others down; every normal move is
 * capped at a tenth of the mean edge length.  While a step is capped the
 * mesh is kept fit, as Surface Evolver's users do by hand between saddle
 * steps: a tangential smoothing sweep (vertex averaging), Delaunay flips
 * on the intrinsic metric (equiangulation), and edge splits where the
 * surface turns across an edge by more than four times the boundary
 * polygon's mean turning angle (|K|^1/2 times the edge length, K the
 * angle-defect Gaussian curvature: the neck of a catenoid that narrows 4-6
 * times needs more vertices round it).  A climb that fails (the area
 * falls back by 5 % of what it gained, or doubles, or a triangle
 * collapses) starts again from the caller's mesh the other way up, with
 * the steps left.  Once converged, edges are split at half that angle
 * (twice the turning angle), flipped and converged again, until none is
 * split (at most 24 rounds).  So the number of vertices may grow (up to 16
 * times the caller's; new vertices are appended, free, the others keep
 * their indices and the fixed ones their positions bit for bit) and the
 * triangles change.  Index 0 is Newton towards a minimum.  It stops when
 * the Hessian has exactly `index` negative eigenvalues, max |dA/dt_v| /
 * |B_v| (a mean curvature) is at most 1e-9 over the caller's mean edge
 * length and no triangle is inverted, degenerate or folded (*converged
 * 1), or after max_steps Newton steps in all (0: 1000), or when a step
 * cannot be formed (*converged 0; the mesh holds the last positions).
 * Two coaxial rings of radius 1 solved with the default options give the
 * unstable catenoid with index 1 at h = 0.8, 1.0, 1.2, the area within 0.5
 * % of the exact one (tests/test_stability.c).
 *   in/out mesh (positions move; triangles and vertices may be added);
 *   in  index (0 .. 7), max_steps;
 *   out status (may be NULL: plateau_mesh_stability of the result with
 *       index + 2 eigenvalues), converged, steps (may be NULL), err.
 * Returns PLATEAU_OK (test *converged), _ARGUMENT, _OUT_OF_MEMORY,
 * _OVERFLOW.  Thread safety: distinct meshes. */
PLATEAU_DEF plateau_result plateau_mesh_critical_point(plateau_mesh *mesh, size_t index, int max_steps,
                                                       plateau_stability *status, int *converged,
                                                       size_t *steps, plateau_error *err);

typedef struct plateau_report {
    plateau_method method;
    plateau_domain_kind domain;
    size_t rounds;
    size_t iterations;   /* LM, dog-leg or quasi-Newton iterations, or the
                            accepted steps of method area's sparse Newton
                            method, all rounds */
    size_t evaluations;  /* residual (or area) evaluations, all rounds */
    double f_initial, f_final; /* the method's objective */
    double area;
    double min_angle_deg, max_angle_deg;
    double max_abs_beta_deg; /* largest |dihedral angle|: fold check */
    size_t inverted_triangles;
    size_t flips;
    plateau_stop stop;    /* why the rounds ended; see plateau_stop_string */
    /* the rounds in detail: */
    size_t interior_points;  /* free vertices of the mesh (seeded points kept;
                                with cables also their cable_vertices) */
    plateau_lm_stop lm_stop; /* why the last LM solve ended (methods paper and
                                paper-literal; PLATEAU_LM_STOP_NONE for area) */
    plateau_area_stop area_stop; /* why the last solve of method area ended,
                                L-BFGS or sparse Newton (PLATEAU_AREA_STOP_NONE
                                for the other methods) */
    size_t retriangulations;    /* paper-literal: rounds re-triangulated by
                                re-projection and CDT (the others used 3-D flips) */
    double f_rounds[PLATEAU_REPORT_F_ROUNDS]; /* the objective after each of the
                                first PLATEAU_REPORT_F_ROUNDS solves */
    int warm_started;        /* the Pinkall-Polthier start ran and its result was kept */
    size_t presolve_iterations; /* method paper: L-BFGS steps of the area presolve (0: none) */
    size_t removed_vertices; /* interior vertices removed as degenerate between
                                rounds (plateau_mesh_remove_degenerate; method
                                area, also as method paper's presolve);
                                interior_points counts those that remain */
    /* the initial mesh: */
    size_t seeded_points;    /* interior vertices of the initial mesh (step 4) */
    size_t boundary_points_added; /* quality seeding with refine_boundary: fixed
                                vertices added on the polygon's edges; they are
                                mesh vertices m .. m + boundary_points_added - 1 */
    double initial_min_angle_deg; /* smallest angle of the initial 3-D mesh */
    double domain_min_angle_deg;  /* smallest angle of the planar triangulation
                                of step 4 (in the domain) */
    /* The final check of the result (plateau_mesh_check), with
     * inverted_triangles above: */
    size_t folded_edges;          /* |dihedral| above PLATEAU_FOLD_DEGREES */
    size_t degenerate_triangles;  /* an angle below PLATEAU_DEGENERATE_DEGREES */
    size_t intersecting_pairs;    /* triangles meeting each other */
    int solved;                   /* 1: the last solve reached its stopping rule
                                     (paper: F <= 1e-10 with the polygon scaled
                                     to the unit cube, the square system solved;
                                     paper-literal: an LM stop other than
                                     max_iterations; area: an L-BFGS stop other
                                     than max_iterations) */
    unsigned defects;             /* the one field to test: 0 when the mesh is
                                     valid, else PLATEAU_DEFECT_* bits (the
                                     counts above, and _UNSOLVED when solved is
                                     0); plateau_defects_string names them */
    plateau_linear_solver linear_solver; /* method paper: how the last solve
                                     ran (DENSE or SPARSE); method area:
                                     SPARSE for the Newton method, AUTO (0)
                                     for the L-BFGS; AUTO for paper-literal */
    size_t loops;                 /* boundary loops (plateau_solve: 1;
                                     plateau_mesh_minimize: 0) */
    double neck_ratio;            /* two loops: the shortest closed curve around
                                     the film found (the neck) over the shorter
                                     loop's length; 0 otherwise */
    /* membranes (MEMBRANES at the top): */
    double pressure;              /* the pressure of the film: options.pressure,
                                     or the multiplier that holds fix_volume */
    double volume;                /* V of the result (the cone from the
                                     boundary's centroid; 0 without pressure,
                                     volume or cables); beyond a double's
                                     range HUGE_VAL, 0 or subnormal (range
                                     says so), exact in any case as: */
    double volume_significand;    /* |in [0.5, 1)|, V's sign (0 for V = 0) */
    int volume_exponent;          /* V = volume_significand * 2^volume_exponent */
    int membrane;                 /* 1: a pressure, a held volume or a cable
                                     (MEMBRANES): stability, the discs and
                                     the saddle search were not computed */
    size_t cables;                /* cables (options.cable_tension) */
    size_t cable_vertices;        /* free vertices on them, all cables */
    plateau_cable_result cable[PLATEAU_REPORT_CABLES]; /* the first cables */
    size_t levels;                /* coarse to fine: the 1-to-4 subdivisions
                                     done after the coarse mesh (0: the rounds
                                     ran at full size); seeded_points and
                                     rounds then count the coarse mesh's */
    /* Values outside a double's range: the solve runs on the polygon
     * scaled to about 1 (see INVARIANCE), and only the report is in the
     * caller's units, where an area (length^2) or method paper's F
     * (length^-2) of a polygon 1e200 or 1e-200 across is beyond DBL_MAX or
     * below DBL_MIN.  Then area or F is HUGE_VAL, or 0 or a subnormal
     * with fewer digits, and range says so; the area is exact in any case
     * as area_significand * 2^area_exponent: */
    double area_significand;      /* in [0.5, 1) (0 for a mesh of no area) */
    int area_exponent;
    unsigned range;               /* PLATEAU_RANGE_* bits; 0: every value
                                     is the double it says */
    plateau_stability stability;  /* the second-order status of the mesh
                                     returned (options.stability; computed 0
                                     when off or when the mesh has a zero-area
                                     triangle) */
    int critical_converged;       /* options.critical_index > 0: 1 when the
                                     search reached a critical point of that
                                     index (else the defect _UNSOLVED) */
    size_t critical_steps;        /* its Newton steps */
    double film_area;             /* two loops with alternatives: the area of
                                     the connected film; 0 otherwise */
    double alternative_area;      /* two loops with alternatives: the total area
                                     of one disc per loop; 0: not computed */
    int film_not_least;           /* 1: the least connected film found (the
                                     rounds', or the one returned) has more
                                     area than the discs */
    int discs_returned;           /* 1: least_area_topology returned the discs */
    /* the accuracy (ACCURACY at the top): */
    double area_error_estimate;   /* the estimated relative error of area
                                     against the exact minimal surface of
                                     the same polygon; NaN when not formed
                                     (estimate says why) */
    plateau_estimate estimate;    /* PLATEAU_ESTIMATE_FORMED, or why not */
    double accuracy;              /* the accuracy aimed at (options.accuracy
                                     or PLATEAU_DEFAULT_ACCURACY); 0: none */
    size_t accuracy_solves;       /* solves the accuracy took (1: the
                                     first met it or none was aimed at) */
} plateau_report;
#define PLATEAU_RANGE_AREA_OVERFLOW 1u  /* area is HUGE_VAL: above DBL_MAX */
#define PLATEAU_RANGE_AREA_UNDERFLOW 2u /* area is 0 or subnormal: below DBL_MIN */
#define PLATEAU_RANGE_VOLUME_OVERFLOW 16u  /* volume is +-HUGE_VAL: above DBL_MAX */
#define PLATEAU_RANGE_VOLUME_UNDERFLOW 32u /* volume is 0 or subnormal where it is not 0 */
#define PLATEAU_RANGE_F_OVERFLOW 4u     /* f_initial, f_final or f_rounds: one is HUGE_VAL */
#define PLATEAU_RANGE_F_UNDERFLOW 8u    /* ... one is 0 or subnormal where it is not 0 in
                                           the solve's units */


/* Closed polygon (m vertices, xyz) in, minimal mesh out.  The mesh's first m
 * vertices are the boundary, unchanged and fixed.  options, report, err may
 * be NULL.  Free the mesh with plateau_mesh_free (also after an error).
 *   in  boundary (3 * m coordinates, the polygon closing implicitly), m,
 *       options (NULL or all-zero: the defaults of the table at the top);
 *   out mesh (its arrays from options->allocator), report (the work done,
 *       the stop reasons and the quality of the result), err.
 * Returns PLATEAU_OK; the errors of plateau_boundary_check; _ARGUMENT (no
 * mesh, an option out of range); _OUT_OF_MEMORY; _OVERFLOW; _TRIANGULATION
 * (the planar triangulation failed, or two boundary vertices meet in the
 * domain); _SOLVER (the LM failed); _ABORTED (the progress callback);
 * _MEMORY_LIMIT (the estimated peak exceeds options.max_memory).
 * A result that is merely poor, or broken, is no error: test
 * report->defects (0: valid; the final check) and read
 * report->min_angle_deg, max_abs_beta_deg and inverted_triangles.
 *
 * It runs THE PIPELINE described at the top of this file (steps 1-6 and
 * the final check, with the methods of METHODS there); what follows is the
 * detail of the quality seeding.
 *
 * Quality seeding (options.seeding = PLATEAU_SEEDING_QUALITY, or the default
 * PLATEAU_SEEDING_AUTO when n >= m / 4) makes the points of step 3 and the
 * triangulation of step 4 at once: the domain polygon is refined by
 * plateau_dt_triangulate (Ruppert; Shewchuk; Miller, Pav and Walkington)
 * with the angle bound
 * quality_min_angle (0 -> 26 degrees, below the proven 26.45) and an area
 * limit: the equilateral area of quality_edge_length when that is set
 * (in the polygon's units, measured in the domain), else a limit searched
 * for (at most 20 refinements, starting at 2 A / (2n + m), doubling or
 * halving, then bisecting) so that about n = interior_points interior
 * points come out (the closest count; report->seeded_points says it).
 * The polygon is kept as given (keep_segments) unless refine_boundary is
 * ON, or AUTO for method area and method paper's area presolve when the
 * longest domain edge exceeds 2 h, h the side of the equilateral triangle
 * of area 2 A / (2n + m) (least area pulls interior vertices onto longer
 * kept edges, step 6 removes them, and the rounds churn); while it is
 * kept, the limit is graded near it (the larger of the limit and the
 * equilateral area of max over edges of (edge length - dist / 2)), since a
 * triangle on a long kept edge cannot be refined without splitting it.
 * That maximum is taken over the edges near the point only (a grid of the
 * long edges: plateau__seed_graded), so a densely sampled boundary costs
 * O(1) per query.
 * When that grading leaves fewer than half the points asked for (a coarse
 * polygon), the slope 1/2 steepens to 2, 8, 32, then no grading, until at
 * least half are there; quality_edge_length L counts as asking for
 * A / (sqrt(3) / 4 L^2) points.  The triangles standing on long kept edges
 * then have angles of about size / edge length.  (The counts this gives,
 * and the measurements behind these choices: examples/NOTES.md,
 * "Measurements behind the solver's choices"; tests/test_seeding_quality.c
 * checks the counts.)  The refined triangulation is the initial mesh.  An interior point goes
 * to 3-D by the mean-value coordinates of its domain point in the domain
 * polygon (Floater 2003; well defined in any simple polygon: Hormann and
 * Floater 2006), applied to the boundary's xyz: smooth, no linear solve,
 * and on the best-fit-plane domain the 3-D point projects back onto its
 * domain point (linear precision), so the refined angles carry over as far
 * as the surface is a graph over the plane.  Those cost O(m) per point:
 * above 1e7 boundary vertices times points (PLATEAU__CDT_MVC_WORK) the
 * points go to 3-D by the discrete harmonic map of the refined
 * triangulation instead (cotangent weights of its plane triangles, one
 * sparse Cholesky; also linear-precise).  With refine_boundary, a
 * vertex added on edge i (from vertex i to i + 1) is fixed, lies on the
 * straight 3-D edge at the parameter of its domain point, and is a mesh
 * vertex m .. m + k - 1 (k = report->boundary_points_added, in edge order
 * and along each edge); the interior vertices follow.  The seed is not
 * used: the refinement is deterministic.  report->domain_min_angle_deg and
 * initial_min_angle_deg give the smallest angle of the planar
 * triangulation and of the 3-D start, for either seeding.
 *
 * *mesh is output only: its contents on entry are neither read nor freed,
 * so a mesh that holds an earlier result must go through plateau_mesh_free
 * before it is solved into again (or its arrays leak); on return it holds
 * the result (free it with plateau_mesh_free, also after an error).
 *
 * Thread safety: no global state; concurrent calls need distinct meshes and
 * option allocators that are themselves thread-safe. */
PLATEAU_DEF plateau_result plateau_solve(const double *boundary, size_t m,
                                         const plateau_options *options,
                                         plateau_mesh *mesh, plateau_report *report,
                                         plateau_error *err);
/* Several boundary loops: k = num_loops closed polygons, loop j having
 * loop_counts[j] >= 3 vertices, all in one array xyz (3 * sum of the counts
 * coordinates, loop 0 first; each loop closes implicitly).  The mesh's
 * first vertices are the loops' vertices in that order, unchanged bit for
 * bit and fixed; the interior vertices follow.  For k = 1 it is
 * plateau_solve(xyz, loop_counts[0], ...): the same mesh bit for bit.
 * Options, report and errors as plateau_solve (interior_points 0: as many
 * as all loops have vertices; seeding and refine_boundary are not read:
 * the quality seeding with the loops kept whole; force_circle_domain
 * makes two loops use the annulus even where the plane works, and is not
 * read for more), plus report->loops and,
 * for two loops, report->neck_ratio.  See SEVERAL LOOPS at the top.
 * Returns PLATEAU_OK; _ARGUMENT (NULL mesh or counts, k = 0), each loop's
 * errors of plateau_boundary_check (the message starts "loop j: " and
 * numbers the loop's own vertices; err->index is the vertex's index in
 * xyz, or the loop's count for _TOO_FEW_VERTICES), _LOOPS_SHARE_VERTEX, _LOOPS_INTERSECT, _LOOPS_NESTING,
 * _LOOPS_DOMAIN (err->index: a vertex of the loop named), and the errors
 * of plateau_solve.  A pinched film is no error: report->stop
 * PLATEAU_STOP_PINCHED and report->defects PLATEAU_DEFECT_PINCHED. */
PLATEAU_DEF plateau_result plateau_solve_loops(const double *xyz, const size_t *loop_counts,
                                               size_t num_loops, const plateau_options *options,
                                               plateau_mesh *mesh, plateau_report *report,
                                               plateau_error *err);
/* The method's name, "paper", "paper-literal" or "area" (a static string;
 * "unknown" for another value). */
PLATEAU_DEF const char *plateau_method_name(plateau_method method);
/* A sentence for plateau_report.stop (PLATEAU_STOP_*; a static string,
 * "unknown stop reason" for another value). */
PLATEAU_DEF const char *plateau_stop_string(plateau_stop stop);
/* A sentence for plateau_report.area_stop (a static string, "unknown
 * area stop reason" for another value). */
PLATEAU_DEF const char *plateau_area_stop_string(plateau_area_stop stop);
/* The defects (PLATEAU_DEFECT_* bits) in words, "valid" for 0, e.g.
 * "inverted triangles; triangles intersecting each other", written into
 * buf (size bytes; cut short, always terminated when size > 0); returns
 * buf.  80 bytes hold one kind, 500 all of them. */
PLATEAU_DEF char *plateau_defects_string(unsigned defects, char *buf, size_t size);
/* The options plateau_solve will use for a polygon of m vertices: a copy of
 * *options (NULL: all zero) with every zero that means "default" replaced by
 * the default (interior_points = m, seed, max_rounds 20, max_iterations 200
 * for the LM methods or 5000 for area, lambda 1, area_tolerance 1e-6,
 * quality_min_angle 26, max_memory PLATEAU_DEFAULT_MAX_MEMORY).  This is
 * the one resolution plateau_solve, plateau_solve_loops and
 * plateau_mesh_minimize make at entry (they validate it too).  The
 * switches and seeding stay PLATEAU_AUTO, decided on the way (paper_presolve
 * AUTO: where the domain is not the plane), but for a membrane (pressure
 * non-zero, fix_volume or cable_tension: MEMBRANES) coarse_to_fine,
 * stability and alternatives AUTO become PLATEAU_OFF.  Pure; does not
 * validate. */
PLATEAU_DEF plateau_options plateau_resolved_options(const plateau_options *options, size_t m);
/* The inverse of plateau_method_name ("paper", "paper-literal", "area");
 * returns 0 and sets *method, or -1 for an unknown name. */
PLATEAU_DEF int plateau_method_from_name(const char *name, plateau_method *method);

/* Steps 5-6 and the final check on an existing mesh: optimise the positions
 * of its free vertices by options->method, re-triangulating by 3-D Delaunay
 * flips between rounds (method paper-literal re-projects only inside
 * plateau_solve, which knows the domain; here it flips too; paper_presolve
 * AUTO and OFF mean never here, ON always).  Fixed vertices never move (bit
 * for bit); scale-invariant like plateau_solve.  The counts change only
 * when method area (or method paper's area presolve) removes a degenerate
 * free vertex (step 6, plateau_mesh_remove_degenerate: one vertex and two
 * triangles each, report->removed_vertices); fixed vertices keep their
 * order.  report (may be NULL) is filled as by
 * plateau_solve except domain.  Errors: _ARGUMENT, _OUT_OF_MEMORY, _OVERFLOW,
 * _SOLVER (the LM failed), _ABORTED (the progress callback),
 * _MEMORY_LIMIT (options.max_memory, checked first), and the adjacency
 * errors.  On error the mesh holds the last positions. */
PLATEAU_DEF plateau_result plateau_mesh_minimize(plateau_mesh *mesh, const plateau_options *options,
                                                 plateau_report *report, plateau_error *err);

/* Step 6: intrinsic Delaunay edge flips.  Sweeps the triangles in index
 * order and flips an interior edge (a, b), shared by (a, b, c) and
 * (b, a, d), when the angles at c and d sum to more than pi + 1e-9 (ties
 * never flip: the result is deterministic), unless c and d are already
 * joined or either new triangle (a, d, c), (b, c, d) would be degenerate or
 * face against either old one in 3-D (a fold).  The angles are those of the
 * mesh's intrinsic metric: the edge lengths when the call starts, a flipped
 * edge getting the length of the diagonal of its two triangles unfolded
 * into the plane.  Each flip lowers a Delaunay energy of that fixed metric,
 * so the flips end by themselves (Lawson's algorithm; Bobenko and
 * Springborn 2007); the flipped edges become straight 3-D chords.
 * Boundary edges never flip.  At most max_sweeps sweeps (0 -> 50) and, as
 * a safety bound only, 10 * num_edges flips; *flips (may be NULL) gets the
 * count.  Rebuilds the adjacency.  Returns PLATEAU_OK, _ARGUMENT (no mesh,
 * max_sweeps < 0), _OUT_OF_MEMORY (3 lengths per triangle of scratch) or an
 * adjacency error. */
PLATEAU_DEF plateau_result plateau_mesh_delaunay_flips(plateau_mesh *mesh, int max_sweeps,
                                                       size_t *flips, plateau_error *err);

/* Step 6, vertex removal: removal of degenerate free vertices.  Area minimisation can pull
 * an interior vertex onto a boundary chord (a thin strip: the vertex is
 * superfluous there), leaving a triangle with a 0 degree angle that no flip
 * can remove.  Sweeps the triangles in index order; a triangle is
 * degenerate when a corner angle is below min_angle_deg (0 -> 1 degree;
 * angles make the test scale-free) or it is inverted (zero area, or facing
 * against its neighbours, as plateau_mesh_quality counts).  Its free
 * interior vertices, largest angle first (the apex of a cap, then the ends
 * of a needle's short edge), are tried for a half-edge collapse onto a
 * neighbour w (Hoppe et al. 1993): w must pass the link condition (Dey et
 * al. 1999: the mesh stays a manifold disk) and every surviving triangle
 * must keep a non-zero area facing the same side as before (no fold);
 * among those w, the largest smallest angle (ties: first in edge order).
 * One vertex goes per pass, then the adjacency is rebuilt; at most
 * num_vertices passes.  Fixed vertices and vertices on a boundary edge
 * never move or go.  Vertices after a removed one and triangles after the
 * removed two move down one place, in order (plateau_solve's boundary
 * vertices 0 .. m-1 keep their indices).  *removed (may be NULL) gets the
 * count.  Errors: _ARGUMENT (no mesh or adjacency, angle outside [0, 60)),
 * and the adjacency errors; deterministic. */
PLATEAU_DEF plateau_result plateau_mesh_remove_degenerate(plateau_mesh *mesh, double min_angle_deg,
                                                          size_t *removed, plateau_error *err);
/* ======== END SECTION: options, report; steps 5-6 and the final check === */

/* ======== SECTION: mesh input and output ================================ */
/* Writers take plain arrays so any mesh works.
 *
 * Define PLATEAU_NO_STDIO (before including the implementation) to leave out
 * the functions that open files or write streams (plateau_write_mesh(_format,
 * _marked), plateau_write_svg, plateau_write_svg_colored(_stream),
 * plateau_read_boundary_file, plateau_read_boundary_stream,
 * plateau_read_mesh_file) and with them
 * every use of <stdio.h>; the parsers of a text buffer and plateau_colormap
 * stay.  Nothing here keeps state between calls:
 * every function is safe to call from several threads at once (on different
 * files). */
#ifndef PLATEAU_NO_STDIO
/* OBJ, PLY (ASCII), OFF or binary STL, chosen by the path's extension
 * (".obj", ".ply", ".off", ".stl", any case; anything else is
 * PLATEAU_ERR_ARGUMENT; STL and ASCII STL: plateau_write_mesh_format).  Coordinates are
 * written with %.17g, so they read back bit for bit; indices are 1-based in
 * OBJ ("v x y z", "f a b c") and 0-based in PLY ("element vertex" with double
 * x y z, "element face" with "list uchar int vertex_indices") and OFF.
 * Checked before the file is opened: positions / triangles non-NULL when
 * their count is non-zero (PLATEAU_ERR_ARGUMENT), every coordinate finite
 * (PLATEAU_ERR_NOT_FINITE, err->index = the vertex), every index in range
 * (PLATEAU_ERR_INDEX_RANGE, err->index = the triangle).  The file is
 * written to a temporary file beside path ("path.tmp0", ...) and renamed
 * over path only once complete, flushed and closed: a failure (no
 * temporary can be made, a write or the rename fails: PLATEAU_ERR_IO)
 * leaves an existing file at path as it was and removes the temporary; a
 * symbolic link at path is replaced by the file, not followed (see
 * plateau__io_open).  Allocates nothing.
 *   in  path, positions (3 * num_vertices), triangles (3 * num_triangles);
 *   out the file; err (may be NULL).
 * Returns PLATEAU_OK or one of the errors above. */
PLATEAU_DEF plateau_result plateau_write_mesh(const char *path, const double *positions,
                                              size_t num_vertices,
                                              const plateau_index *triangles,
                                              size_t num_triangles, plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* The formats of plateau_write_mesh_format. */
typedef enum plateau_mesh_format {
    PLATEAU_MESH_FORMAT_AUTO = 0,      /* by the path's extension, as plateau_write_mesh */
    PLATEAU_MESH_FORMAT_OBJ = 1,
    PLATEAU_MESH_FORMAT_PLY = 2,
    PLATEAU_MESH_FORMAT_OFF = 3,
    PLATEAU_MESH_FORMAT_STL = 4,       /* binary STL */
    PLATEAU_MESH_FORMAT_STL_ASCII = 5  /* ASCII STL */
} plateau_mesh_format;
#ifndef PLATEAU_NO_STDIO
/* plateau_write_mesh with the format given (any extension then; AUTO: by
 * the extension, ".stl" being binary STL).  STL, the format 3-D printing
 * and mesh checkers such as admesh read, has no shared vertices: each
 * triangle is a facet with its unit normal ((b - a) x (c - a) normalised;
 * 0 0 0 for a degenerate triangle) and its three corners, in 32-bit floats
 * (the coordinates rounded to float: STL holds no more).  Binary: an
 * 80-byte header ("plateau VERSION binary STL", blank-padded; never
 * "solid"), the facet count as a little-endian uint32, then per facet 12
 * little-endian floats (normal, corners) and a zero uint16.  ASCII: "solid
 * plateau", per facet "facet normal nx ny nz", "outer loop", three
 * "vertex x y z", "endloop", "endfacet", then "endsolid plateau"; each
 * value the float written with %.9g, so it reads back as the same float.
 * Written as plateau_write_mesh writes (a temporary file renamed over
 * path); its checks and errors, before the file is opened,
 * and for STL a coordinate beyond the float range (PLATEAU_ERR_NOT_FINITE:
 * it would be infinite there, err->index = the vertex) and more than
 * 2^32 - 1 triangles in binary STL (PLATEAU_ERR_OVERFLOW); a format not
 * in the list is PLATEAU_ERR_ARGUMENT. */
PLATEAU_DEF plateau_result plateau_write_mesh_format(const char *path, const double *positions,
                                                     size_t num_vertices,
                                                     const plateau_index *triangles,
                                                     size_t num_triangles,
                                                     plateau_mesh_format format,
                                                     plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* The vertex marks of plateau_write_mesh_marked, one unsigned char per
 * vertex: where a vertex is, for a program that reads the file back. */
#define PLATEAU_MARK_INTERIOR 0 /* on no boundary edge */
#define PLATEAU_MARK_BOUNDARY 1 /* on a boundary edge (an edge of one
                                   triangle) and fixed: the frame */
#define PLATEAU_MARK_CABLE 2    /* on a boundary edge and free: a vertex
                                   plateau_solve put on a cable (MEMBRANES) */
/* The marks of a mesh with its adjacency (from plateau_solve,
 * plateau_solve_loops or plateau_mesh_create): PLATEAU_MARK_BOUNDARY for
 * a fixed vertex on an edge of one triangle, PLATEAU_MARK_CABLE for a free
 * one, PLATEAU_MARK_INTERIOR for every other vertex.
 *   in  mesh; out marks (mesh->num_vertices values), err (may be NULL).
 * Returns PLATEAU_OK, or PLATEAU_ERR_ARGUMENT (no mesh, no adjacency, marks
 * NULL).  Allocates nothing. */
PLATEAU_DEF plateau_result plateau_mesh_vertex_marks(const plateau_mesh *mesh, unsigned char *marks,
                                                     plateau_error *err);
#ifndef PLATEAU_NO_STDIO
/* plateau_write_mesh_format with each vertex's mark (PLATEAU_MARK_*)
 * written where the format has a place for it, so that a program reading
 * the file knows the frame and the cables from the film:
 *   PLY: a vertex property after x, y, z, "property uchar boundary", with
 *     the mark as its value (0 interior, 1 boundary, 2 cable vertex; a
 *     header comment says so).
 *   OBJ: the triangles in group "film" ("g film"), then group "boundary"
 *     with one polyline element ("l a b ... a", 1-based) per boundary loop:
 *     the edges of one triangle each, walked as their triangle runs them,
 *     a closed loop ending at its first vertex again (a chain that does not
 *     close, in a mesh that is no surface, ends where it stops), the loops
 *     in the order of their smallest first vertex; then, when a vertex of a
 *     loop is marked PLATEAU_MARK_CABLE, group "cables" with one polyline
 *     per run of such vertices along a loop, from the vertex before the run
 *     (its anchor) to the one after.  Readers keep groups and polylines (a
 *     viewer draws the frame); plateau_parse_mesh skips them and reads the
 *     same mesh back, bit for bit.  A mark of a vertex on no loop has no
 *     place in OBJ.
 *   OFF and STL: no place for marks: the file of plateau_write_mesh_format.
 *   in  path, positions, num_vertices, triangles, num_triangles, format
 *       (as plateau_write_mesh_format), marks (num_vertices values, each
 *       PLATEAU_MARK_*; NULL: PLATEAU_MARK_BOUNDARY for every vertex of an
 *       edge of one triangle, PLATEAU_MARK_INTERIOR for the others; pass
 *       plateau_mesh_vertex_marks's to tell cables), allocator (the
 *       scratch of the loops: the triangles' edges, about 50 bytes a
 *       triangle, freed before returning; NULL: PLATEAU_MALLOC; setting
 *       only one of its functions is PLATEAU_ERR_ARGUMENT);
 *   out the file; err (may be NULL).
 * Returns PLATEAU_OK or the errors of plateau_write_mesh_format, and before
 * the file is opened PLATEAU_ERR_ARGUMENT (a mark above 2, err->index the
 * vertex; a bad allocator), _OUT_OF_MEMORY or _OVERFLOW. */
PLATEAU_DEF plateau_result plateau_write_mesh_marked(const char *path, const double *positions,
                                                     size_t num_vertices, const plateau_index *triangles,
                                                     size_t num_triangles, const unsigned char *marks,
                                                     plateau_mesh_format format, const plateau_allocator *allocator,
                                                     plateau_error *err);
/* An SVG picture of the mesh: orthographic projection along view_dir (the
 * direction the eye looks in; NULL means (-1, -1, -1), an oblique view from
 * above of a z-up object), screen "up" the projection of +z (of +y when
 * looking along z).  Triangles are painted far to near by the depth of their
 * centroid, ties in triangle order; each is filled with a flat shade of its
 * facet normal against a light from behind the eye's left shoulder (two-sided:
 * |n . l|), with thin dark edges; the viewBox fits the picture with a 3 %
 * margin.  Output: "<svg ...>", one <polygon> per triangle, "</svg>".  Same
 * checks and errors as plateau_write_mesh (except the extension, which is
 * not looked at); a zero or non-finite view_dir is PLATEAU_ERR_ARGUMENT.
 *   in  path, positions (3 * num_vertices), triangles (3 * num_triangles),
 *       view_dir (3 values, or NULL);
 *   in  allocator: where the one scratch array (num_triangles depth keys,
 *       freed before returning) comes from; NULL or all-zero means
 *       PLATEAU_MALLOC / PLATEAU_FREE with the allocator's user_data as
 *       context; setting only one of alloc_fn / free_fn is
 *       PLATEAU_ERR_ARGUMENT.  Pass &mesh.allocator to draw a mesh with the
 *       allocator it was made with.
 *   out err (may be NULL).
 * Returns PLATEAU_OK or the error; PLATEAU_ERR_OUT_OF_MEMORY and
 * PLATEAU_ERR_OVERFLOW come before the file is opened (nothing written). */
PLATEAU_DEF plateau_result plateau_write_svg(const char *path, const double *positions,
                                             size_t num_vertices,
                                             const plateau_index *triangles,
                                             size_t num_triangles, const double *view_dir,
                                             const plateau_allocator *allocator,
                                             plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* Colour map of the coloured pictures: cubehelix (D. A. Green, "A colour
 * scheme for the display of astronomical intensity images", Bull. Astr.
 * Soc. India 39, 2011), computed, not tabulated: for t in [0, 1] (clamped;
 * NaN counts as 0) the grey level g = 0.15 + 0.75 t and, with
 * phi = 2 pi (0.5 / 3 - 1.5 g) and a = g (1 - g) / 2 (Green's start 0.5,
 * rotations -1.5, hue 1, gamma 1),
 *   R = g + a (-0.14861 cos phi + 1.78277 sin phi)
 *   G = g + a (-0.29227 cos phi - 0.90649 sin phi)
 *   B = g + a ( 1.97294 cos phi).
 * The added term is perpendicular to the grey axis in the luminance
 * 0.30 R + 0.59 G + 0.11 B (to 1e-6), so that luminance is g: it rises
 * monotonically with t (the map reads in grey, on paper printed black and
 * white, and for colour-blind readers), from dark blue through green and
 * rose to pale blue-white; on [0.15, 0.9] no channel leaves [0, 1], so
 * nothing is clipped.
 *   out rgb (3 values in [0, 1]). */
PLATEAU_DEF void plateau_colormap(double t, double rgb[3]);
/* What plateau_write_svg_colored draws (all-zero plus values and
 * num_values: per-triangle colours over the values' range, a legend, the
 * default view). */
typedef struct plateau_svg_colors {
    const double *values;   /* the scalar to show: per triangle (num_triangles
                               values) or, with per_vertex, per vertex
                               (num_vertices values); all finite */
    size_t num_values;      /* must equal that count */
    int per_vertex;         /* 0: each triangle filled with its value's colour;
                               1: each vertex's barycentric cell (paper II.B:
                               in every triangle the quadrilateral from the
                               corner to its two edge midpoints and the
                               centroid) filled with the vertex's colour */
    double range_min, range_max; /* the values at the ends of the colour map
                               (values outside are clamped to the ends);
                               both 0: the smallest and largest value */
    const char *title;      /* over the colour bar (XML-escaped; NULL: none) */
    int no_legend;          /* non-zero: no colour bar */
    const double *view_dir; /* as plateau_write_svg's (NULL: (-1, -1, -1)) */
    const plateau_index *marked_edges; /* 2 * num_marked_edges vertex indices:
                               segments drawn over the mesh (black under yellow),
                               e.g. the edges a flip round made; NULL if none */
    size_t num_marked_edges;
} plateau_svg_colors;
#ifndef PLATEAU_NO_STDIO
/* An SVG picture of the mesh coloured by a scalar the caller gives (|H_i|,
 * an angle, a distance to a reference surface), with a legend: the same
 * projection, painter's order and viewBox fit as plateau_write_svg (whose
 * flat shade stays the plain picture), but each triangle (or each vertex's
 * cell, per_vertex) is filled with plateau_colormap((value - range_min) /
 * (range_max - range_min)), unshaded, so that the colour is the value; the
 * edges are thin grey lines.  Order of the output: "<svg ...>", per
 * triangle far to near either one <polygon> with its fill or, per_vertex,
 * three cell <polygon>s in the order of the triangle's corners then the
 * triangle's outline (fill="none"); the marked edges as <line>s; then,
 * unless no_legend, a group class="plateau-legend" to the right of the
 * picture: the title (class="plateau-legend-title"), a vertical colour bar
 * of 64 steps (range_max at the top) and two labels, class
 * "plateau-legend-max" and "plateau-legend-min", each showing its value
 * with %.3g and carrying it exactly in data-value="%.17g".  Text uses the
 * generic font-family sans-serif: the file refers to nothing outside
 * itself.  Coordinates are written with one decimal on a picture 1000
 * units across.
 *   in  path, positions (3 * num_vertices), triangles (3 * num_triangles),
 *       colors (see plateau_svg_colors), allocator (as plateau_write_svg:
 *       one scratch array of num_triangles depth keys);
 *   out the file; err (may be NULL).
 * Errors, all before the file is opened: those of plateau_write_svg (a NULL
 * path or array, _NOT_FINITE positions, _INDEX_RANGE, a zero view_dir,
 * the allocator); PLATEAU_ERR_ARGUMENT for colors NULL, values NULL,
 * num_values not the count per_vertex asks for (err->index = num_values),
 * marked_edges NULL with a non-zero count, or a range with range_min >
 * range_max or a non-finite end; PLATEAU_ERR_NOT_FINITE for a NaN or
 * infinite value (err->index = its index); PLATEAU_ERR_INDEX_RANGE for a
 * marked edge's vertex out of range (err->index = the edge).  When every
 * value is equal (or range_min == range_max) every fill is the middle of
 * the map.  Writing failures give PLATEAU_ERR_IO (the file is removed). */
PLATEAU_DEF plateau_result plateau_write_svg_colored(const char *path, const double *positions,
                                                     size_t num_vertices,
                                                     const plateau_index *triangles,
                                                     size_t num_triangles,
                                                     const plateau_svg_colors *colors,
                                                     const plateau_allocator *allocator,
                                                     plateau_error *err);
/* The same picture written to an open stream (e.g. into an HTML page,
 * where inline SVG needs no file of its own): the stream is neither opened
 * nor closed; the same checks and errors come before anything is written;
 * a write error (ferror) gives PLATEAU_ERR_IO, with the part written left
 * in the stream. */
PLATEAU_DEF plateau_result plateau_write_svg_colored_stream(FILE *stream,
                                                            const double *positions,
                                                            size_t num_vertices,
                                                            const plateau_index *triangles,
                                                            size_t num_triangles,
                                                            const plateau_svg_colors *colors,
                                                            const plateau_allocator *allocator,
                                                            plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* Boundary text: one vertex per line "x y z", '#' comments, blank lines.
 * *xyz is allocated through allocator (may be NULL); free with the same.
 *   in  text (length bytes), allocator (may be NULL: PLATEAU_MALLOC, so
 *       free() with the default macros);
 *   out *xyz (3 * *m coordinates, or NULL), *m, err (may be NULL).
 * Returns PLATEAU_OK, _ARGUMENT, _PARSE, _NOT_FINITE, _OUT_OF_MEMORY, _OVERFLOW. */
/* More precisely: lines end with "\n", "\r\n" or the end of the buffer; a
 * '#' starts a comment to the end of the line; spaces and tabs separate
 * fields, and so does one ';' or (on a line without ';') one ',' with any
 * spaces around it, as spreadsheets export CSV: "1 2 3", "1,2,3",
 * "1, 2, 3" and "1;2;3" read alike, while two separators in a row, a
 * separator at the end of the line, or "1,5;2,5;3,0" (decimal commas) are
 * parse errors.  A line with no field is skipped.  So is one header line
 * that names three columns ("x,y,z", "X Y Z", "\"x\";\"y\";\"z\"": three
 * fields, each starting with a letter or a '"' and none a number) when it
 * comes before the first vertex.  Any other line must hold exactly
 * three numbers in C syntax (strtod: decimal or hexadecimal, with the '.'
 * point whatever the current locale), each consuming its whole field, or
 * the call fails with PLATEAU_ERR_PARSE, err->index = the 1-based line
 * number, which the message also gives, and ends by quoting the offending
 * text ("line 7: field 2 is not a number: \"abc\"").  "nan", "inf" and
 * numbers overflowing a double give PLATEAU_ERR_NOT_FINITE with the line.
 * A text with no vertex gives PLATEAU_OK with *m = 0 and *xyz = NULL; the
 * vertices are not otherwise validated (plateau_boundary_check does that),
 * except that a last vertex exactly equal to the first (the closing point
 * many tools write) is dropped, since the polygon closes by itself (edge
 * m - 1 joins the last vertex to the first): "0 0 0 / 1 0 0 / 0 1 0 /
 * 0 0 0" gives m = 3.  plateau_parse_boundary_lines says whether it did.
 * On error *xyz = NULL and *m = 0, nothing allocated.  length is the number
 * of bytes of text (which need not be NUL-terminated); a NUL byte is a
 * parse error.  Fields longer than 127 characters are parse errors.  It
 * reads localeconv() to undo a non-'.' decimal point: calling setlocale()
 * in another thread at the same time is a race, as with strtod itself.
 * Left out under PLATEAU_FREESTANDING (it needs strtod). */
#ifndef PLATEAU_FREESTANDING
PLATEAU_DEF plateau_result plateau_parse_boundary(const char *text, size_t length,
                                                  const plateau_allocator *allocator,
                                                  double **xyz, size_t *m,
                                                  plateau_error *err);
/* The cables of a boundary text (MEMBRANES), a parsing step before
 * plateau_parse_boundary: a vertex line "x y z cable T" (T a number, before
 * any '#') makes the edge from that vertex to the next of its loop a cable
 * of tension T.  The two fields are overwritten with spaces in text, so
 * that plateau_parse_boundary then reads the line as "x y z".  *tension
 * gets one value per vertex line (T, or 0 for a line without "cable"),
 * *count their number; *tension is NULL when no line has a cable (free it
 * with plateau_boundary_free and the same allocator).  Returns PLATEAU_OK,
 * _PARSE ("cable" without a number after it, err->index the 1-based
 * line), _NOT_FINITE, _ARGUMENT, _OVERFLOW, _OUT_OF_MEMORY.  The values
 * are checked by plateau_solve (PLATEAU_ERR_CABLE).  *count counts the
 * closing points the parsers then drop: plateau_cables_align matches
 * *tension to the vertices plateau_parse_boundary_lines kept (with
 * plateau_parse_boundary, one loop, a dropped closing point is the last
 * entry, which plateau_solve does not read). */
PLATEAU_DEF plateau_result plateau_parse_cables(char *text, size_t length, const plateau_allocator *allocator,
                                                double **tension, size_t *count, plateau_error *err);
/* Where plateau_parse_boundary_lines found the vertices, and the loops. */
typedef struct plateau_boundary_lines {
    int split_loops;       /* in: non-zero: a blank line (no field, no '#')
                              between two vertex lines starts a new loop
                              ('#' lines and blank lines before the first
                              vertex separate nothing), as plateau_solve_loops
                              takes them; 0: the text is one loop */
    long *lines;           /* out: the 1-based text line of each vertex kept
                              (*m entries; NULL when *m = 0) */
    size_t *loop_counts;   /* out: vertices per loop, closing points dropped
                              (num_loops entries, summing to *m) */
    long *closing_lines;   /* out: per loop, the line of its dropped closing
                              point, 0 where none was dropped */
    size_t num_loops;      /* out: 0 when *m = 0, else at least 1 */
    size_t closing_dropped; /* out: the number of loops whose closing point
                              was dropped */
} plateau_boundary_lines;
/* plateau_parse_boundary, with each vertex's line (for messages that name
 * file lines: plateau_error.index and .index2 index info->lines) and the
 * loops: a last vertex of a loop exactly equal to the loop's first is
 * dropped, loop by loop, and reported in info->closing_lines.
 *   in  text, length, allocator (as plateau_parse_boundary),
 *       info->split_loops;
 *   out *xyz, *m, the out fields of *info (its arrays allocated through
 *       allocator: plateau_boundary_lines_free with the same allocator,
 *       *xyz as ever plateau_boundary_free), err.
 * Returns the results of plateau_parse_boundary; info NULL is
 * PLATEAU_ERR_ARGUMENT.  On error nothing is allocated. */
PLATEAU_DEF plateau_result plateau_parse_boundary_lines(const char *text, size_t length,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_boundary_lines *info,
                                                        plateau_error *err);
/* Frees info's arrays (NULL and the counts 0 after); info NULL is ignored. */
PLATEAU_DEF void plateau_boundary_lines_free(plateau_boundary_lines *info,
                                             const plateau_allocator *allocator);
/* The cables of plateau_parse_cables (count entries, one per vertex line)
 * matched to the vertices plateau_parse_boundary_lines kept from the same
 * text (info): the entries of the dropped closing points go, in place,
 * and *count becomes the number kept.  A cable on a dropped closing point
 * (an edge from the point to itself) is refused: PLATEAU_ERR_PARSE,
 * err->index its 1-based line ("cable T" on the line before it makes the
 * closing edge a cable).  count other than the vertices kept plus the
 * closing points dropped, or a NULL argument: PLATEAU_ERR_ARGUMENT. */
PLATEAU_DEF plateau_result plateau_cables_align(double *tension, size_t *count,
                                                const plateau_boundary_lines *info, plateau_error *err);
#endif
/* Frees the coordinates plateau_parse_boundary or plateau_read_boundary_file
 * returned, through the allocator they were given (NULL: PLATEAU_FREE);
 * xyz NULL is ignored. */
PLATEAU_DEF void plateau_boundary_free(double *xyz, const plateau_allocator *allocator);
/* The vertex array the parser allocates is at most 4 bytes per byte of text
 * (a vertex line holds at least 6 bytes with its line end): a text of blank
 * lines does not make it allocate 24 bytes per line. */
#ifndef PLATEAU_NO_STDIO
/* The size cap of the readers below: a longer input is refused with
 * PLATEAU_ERR_INPUT_TOO_LARGE after reading at most cap + 1 bytes, so an
 * endless stream (/dev/zero, a pipe) cannot exhaust memory.  64 MiB holds
 * about two million vertices of "%.17g %.17g %.17g"; define the macro
 * (before the first inclusion) or pass max_bytes to change it. */
#ifndef PLATEAU_DEFAULT_MAX_INPUT_BYTES
#define PLATEAU_DEFAULT_MAX_INPUT_BYTES 67108864u
#endif
/* Reads the whole file at path (binary mode) and parses it as above: a file
 * that cannot be opened or read gives PLATEAU_ERR_IO, one larger than
 * PLATEAU_DEFAULT_MAX_INPUT_BYTES PLATEAU_ERR_INPUT_TOO_LARGE (nothing
 * parsed).  Parameters, results and freeing as plateau_parse_boundary, path
 * in place of the text; the file's bytes are held through allocator while
 * they are parsed. */
PLATEAU_DEF plateau_result plateau_read_boundary_file(const char *path,
                                                      const plateau_allocator *allocator,
                                                      double **xyz, size_t *m,
                                                      plateau_error *err);
/* As plateau_read_boundary_file, from an open stream (stdin, a pipe, a file
 * the caller opened) read to its end, with the size cap max_bytes (0:
 * PLATEAU_DEFAULT_MAX_INPUT_BYTES): more than max_bytes bytes give
 * PLATEAU_ERR_INPUT_TOO_LARGE, err->index -1, and the message names the
 * limit.  The stream is not closed; a read error is PLATEAU_ERR_IO. */
PLATEAU_DEF plateau_result plateau_read_boundary_stream(FILE *stream, size_t max_bytes,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* Mesh text in OBJ or OFF, for plateau_mesh_create (and so
 * plateau_mesh_minimize: a mesh whose boundary, the edges with one
 * triangle, stays where it is).  The format is the text's: OFF when its
 * first line that is not blank or a '#' comment starts with "OFF" (or
 * "COFF", "NOFF", "CNOFF": the normals and colours after a vertex's x y z,
 * and the colour after a face's indices, are read as numbers and left
 * out), OBJ otherwise.
 *   OBJ: "v x y z" (further numbers, a w or a colour, are left out), "f a b
 *   c ..." (also "fo") with each corner "a", "a/t", "a//n" or "a/t/n": a is
 *   1-based, or negative from the last vertex before the line (-1 that
 *   vertex), and may name vertices that come later in the file; the texture
 *   and normal indices are not read.  vt, vn, vp, g, o, s, mg, l, p, usemtl,
 *   mtllib and OBJ's other display statements are skipped; free-form
 *   geometry (cstype, curv, surf, ...) and any other statement are refused.
 *   OFF: the header, the counts "V F E" (on the header line or the next),
 *   V vertex lines "x y z" and F face lines "n i_0 .. i_(n-1)" with 0-based
 *   indices; nothing may follow the last face.
 * In both, '#' starts a comment (also after a statement), lines end with
 * "\n" or "\r\n", fields are separated by spaces and tabs, numbers are C
 * syntax with the '.' point (as plateau_parse_boundary reads them), and a
 * face of n > 3 corners becomes the fan of n - 2 triangles from its first
 * corner, (c_0, c_i, c_(i+1)), which keeps its orientation (right for the
 * convex and the star-shaped faces that meshers write).
 *   in  text (length bytes; need not be NUL-terminated), allocator (may be
 *       NULL: PLATEAU_MALLOC);
 *   out *positions (3 * *num_vertices), *triangles (3 * *num_triangles,
 *       0-based), *face_lines (face_lines may be NULL: not wanted; else
 *       the 1-based line of each triangle's face, for messages about a
 *       triangle, e.g. plateau_mesh_create's), all through allocator: free
 *       them with plateau_mesh_arrays_free; err (may be NULL).
 * Returns PLATEAU_OK, or on error nothing allocated and:
 *   PLATEAU_ERR_PARSE, err->index the 1-based line (-1 for a text with no
 *     face), the message naming the line and, where there is one, ending
 *     by quoting the offending text ("line 9: vertex index 0 (OBJ counts
 *     from 1): \"0\""): a field that is not a number, a vertex line of
 *     fewer than three, a face of fewer than three corners, a corner index
 *     0, out of range (the message names the count) or not a whole number,
 *     a face repeating a corner (a degenerate triangle of its fan), an
 *     unknown statement, an OFF header or counts missing, fewer or more
 *     lines than its counts, a NUL byte (a binary file), a PLY or STL text
 *     (named as such), no face;
 *   PLATEAU_ERR_NOT_FINITE (a coordinate NaN or infinite, err->index the
 *     line), _ARGUMENT (a NULL output or a bad allocator), _OVERFLOW (more
 *     vertices or triangles than plateau_index holds), _OUT_OF_MEMORY.
 * Vertices no face names are kept (plateau_mesh_create accepts them).
 * Non-manifold edges and inconsistent orientation are plateau_mesh_create's
 * to find (its err->index, a triangle, maps to a line by face_lines).  Left
 * out under PLATEAU_FREESTANDING (it needs strtod). */
#ifndef PLATEAU_FREESTANDING
PLATEAU_DEF plateau_result plateau_parse_mesh(const char *text, size_t length, const plateau_allocator *allocator,
                                              double **positions, size_t *num_vertices,
                                              plateau_index **triangles, size_t *num_triangles,
                                              long **face_lines, plateau_error *err);
#endif
/* Frees the arrays plateau_parse_mesh or plateau_read_mesh_file returned
 * (any of them may be NULL), through the allocator they were given. */
PLATEAU_DEF void plateau_mesh_arrays_free(double *positions, plateau_index *triangles, long *face_lines,
                                          const plateau_allocator *allocator);
#ifndef PLATEAU_NO_STDIO
/* Reads the whole file at path (binary mode; at most
 * PLATEAU_DEFAULT_MAX_INPUT_BYTES bytes, else PLATEAU_ERR_INPUT_TOO_LARGE)
 * and parses it as plateau_parse_mesh, without face lines: a file that
 * cannot be opened or read is PLATEAU_ERR_IO.  Free the arrays with
 * plateau_mesh_arrays_free(*positions, *triangles, NULL, allocator). */
PLATEAU_DEF plateau_result plateau_read_mesh_file(const char *path, const plateau_allocator *allocator,
                                                  double **positions, size_t *num_vertices,
                                                  plateau_index **triangles, size_t *num_triangles,
                                                  plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
/* ======== END SECTION: mesh input and output ============================ */

/* ======== SECTION: cutting patterns ====================================== */
/* Define PLATEAU_NO_PATTERNS (before including the implementation) to leave
 * out this section: the types and functions below and their code
 * (CUTTING PATTERNS in the manual). */
#ifndef PLATEAU_NO_PATTERNS
/* The family of planes whose sections of the film are the seams. */
typedef enum plateau_pattern_seams {
    PLATEAU_SEAMS_PARALLEL = 0, /* parallel planes normal to direction */
    PLATEAU_SEAMS_AXIS = 1      /* half-planes through the axis (point, direction) */
} plateau_pattern_seams;

/* What plateau_pattern_make is asked.  All-zero but width: parallel planes
 * normal to the coordinate axis along which the film is longest, no
 * compensation, 100 strain-minimising iterations at most. */
typedef struct plateau_pattern_options {
    double width;          /* W > 0: the roll width every panel must fit */
    int seams;             /* a plateau_pattern_seams */
    double direction[3];   /* parallel: the planes' normal; axis: the axis's
                              direction; all zero: the default (parallel:
                              the coordinate axis of the film's largest
                              extent; axis: the film's vector area through
                              its area centroid) */
    double point[3];       /* axis: a point of the axis (with a non-zero
                              direction) */
    double shrink_along;   /* compensation: the flat panel shrunk by this
                              fraction along its length ... */
    double shrink_across;  /* ... and this one across it, each in [0, 0.5) */
    int max_iterations;    /* strain-minimising (local/global) iterations per
                              panel; 0: 100, < 0: none (the conformal map only) */
    size_t panels;         /* 0: the fewest intervals between the planes
                              that fit W; N > 0: exactly N intervals (a
                              panel wider than W is then an error) */
} plateau_pattern_options;

/* One flat panel.  Its vertices are pattern.uv / .xyz [first_vertex,
 * first_vertex + num_vertices), its triangles pattern.triangles
 * [first_triangle, ...).  Lengths in the film's units. */
typedef struct plateau_pattern_panel {
    size_t first_vertex, num_vertices;
    size_t first_triangle, num_triangles;
    double area_3d;     /* its area on the film */
    double area_flat;   /* its flat area (after compensation) */
    double max_strain;  /* the largest per-triangle strain of the flattening */
    double mean_strain; /* the area-weighted mean strain */
    double width;       /* its extent across (the roll's width direction) */
    double length;      /* its extent along the roll */
} plateau_pattern_panel;

/* One seam: the edges shared by two panels. */
typedef struct plateau_pattern_seam {
    size_t panels[2];   /* the two panels, panels[0] < panels[1] */
    double lengths[2];  /* its flat length on each panel's side */
    double length_3d;   /* its length on the film */
    size_t first_edge, num_edges; /* pattern.seam_edges [first_edge, ...) */
} plateau_pattern_seam;

/* A cutting pattern (plateau_pattern_make; free with plateau_pattern_free).
 * Each panel lies on its own strip of the roll: u along the roll from 0 to
 * its length, v across from 0 to its width (<= W). */
typedef struct plateau_pattern {
    size_t num_panels;
    plateau_pattern_panel *panels;
    size_t num_seams;
    plateau_pattern_seam *seams;
    size_t num_vertices;       /* pattern vertices: a film vertex on a seam
                                  is one pattern vertex per panel */
    double *xyz;               /* 3 per vertex: its point on the film */
    double *uv;                /* 2 per vertex: its flat point */
    size_t num_triangles;
    plateau_index *triangles;  /* 3 per triangle, pattern vertices */
    size_t num_seam_edges;
    plateau_index *seam_edges; /* 4 per seam edge: its ends a, b on
                                  panels[0]'s side, then on panels[1]'s, each
                                  seam's edges in chains from end to end */
    double max_strain;         /* the largest panel max_strain */
    double mean_strain;        /* the area-weighted mean over all panels */
    double spacing;            /* the seam planes' mean spacing (along
                                  direction, or radians about the axis) */
    size_t iterations;         /* strain-minimising iterations, all panels */
    double roll_width;         /* W, as asked */
    plateau_allocator allocator;
} plateau_pattern;

/* Cuts a film (any mesh: a result of plateau_solve, a mesh read from a
 * file) into panels along the sections of the film by a family of planes,
 * spaced evenly and as widely as lets every flattened panel fit the roll
 * width, flattens each panel (least-squares conformal map, then local /
 * global strain minimisation), compensates it and reports it.
 *   in  positions (3 * num_vertices), triangles (3 * num_triangles, one
 *       consistent orientation, a manifold), options (width > 0),
 *       allocator (NULL: PLATEAU_MALLOC);
 *   out pattern (free with plateau_pattern_free, also after an error), err.
 * Returns PLATEAU_OK, or PLATEAU_ERR_ARGUMENT (a NULL pointer, no triangle,
 * a width not > 0 and finite, a compensation outside [0, 0.5), an unknown
 * seam family), plateau_mesh_create's errors for a bad mesh,
 * PLATEAU_ERR_PATTERN (no spacing of the chosen planes fits every panel
 * within W, or a panel is no disc: seams that cut the film into bands),
 * _OUT_OF_MEMORY, _OVERFLOW.  Deterministic. */
PLATEAU_DEF plateau_result plateau_pattern_make(const double *positions, size_t num_vertices,
                                                const plateau_index *triangles, size_t num_triangles,
                                                const plateau_pattern_options *options,
                                                const plateau_allocator *allocator,
                                                plateau_pattern *pattern, plateau_error *err);
/* Frees a pattern's arrays and zeroes it; an all-zero pattern and NULL are
 * accepted. */
PLATEAU_DEF void plateau_pattern_free(plateau_pattern *pattern);
/* Matching marks along seam s (for sewing): a mark at each end of each of
 * its chains and every `spacing` of film length between, each as its flat
 * point on both sides: marks[4k .. 4k + 3] = u, v on panels[0]'s side,
 * then on panels[1]'s.  Writes at most capacity marks; *count is the
 * number there are (call with capacity 0 to size the array).
 * PLATEAU_ERR_ARGUMENT for s out of range, spacing not > 0 or so small
 * that the seam would get more than ten million marks, or NULL pointers
 * (marks may be NULL with capacity 0). */
PLATEAU_DEF plateau_result plateau_pattern_seam_marks(const plateau_pattern *pattern, size_t s,
                                                      double spacing, double *marks, size_t capacity,
                                                      size_t *count, plateau_error *err);
#ifndef PLATEAU_NO_STDIO
/* The panels as an SVG picture (one strip of the roll per panel, its
 * outline, its number, its seam marks every mark_spacing with the seam's
 * number; mark_spacing <= 0: the ends only), in the film's units.  Written
 * to a temporary and renamed (as plateau_write_mesh).  PLATEAU_ERR_IO,
 * _ARGUMENT (also for a mark spacing that would put more than ten million
 * marks on a seam), _OUT_OF_MEMORY. */
PLATEAU_DEF plateau_result plateau_pattern_write_svg(const char *path, const plateau_pattern *pattern,
                                                     double mark_spacing, plateau_error *err);
PLATEAU_DEF plateau_result plateau_pattern_write_svg_stream(FILE *stream, const plateau_pattern *pattern,
                                                            double mark_spacing, plateau_error *err);
/* The same as DXF R12 ASCII (what cutting plotters read): LINE entities on
 * layer OUTLINE (each panel's outline) and MARKS (the seam marks, short
 * strokes into the panel), TEXT on layer TEXT (the panel numbers). */
PLATEAU_DEF plateau_result plateau_pattern_write_dxf(const char *path, const plateau_pattern *pattern,
                                                     double mark_spacing, plateau_error *err);
PLATEAU_DEF plateau_result plateau_pattern_write_dxf_stream(FILE *stream, const plateau_pattern *pattern,
                                                            double mark_spacing, plateau_error *err);
#endif /* PLATEAU_NO_STDIO */
#endif /* PLATEAU_NO_PATTERNS */
/* ======== END SECTION: cutting patterns ================================== */

#ifdef __cplusplus
}
#endif
#endif /* PLATEAU_H */

/* ======================================================================== */
#if defined(PLATEAU_IMPLEMENTATION) && !defined(PLATEAU_IMPLEMENTED)
#define PLATEAU_IMPLEMENTED

/* The implementations of the two headers plateau.h builds on.  Included
 * again here, outside plateau.h's include guard, so that the stb pattern
 * "include the declarations, later define PLATEAU_IMPLEMENTATION and include
 * again" compiles them too; their own guards compile each one once.  They
 * also bring the shared configuration block (allocator, libm wrappers) this
 * implementation uses. */
#include "plateau_lm.h"
#include "plateau_delaunay.h"

/* No contraction of a*b + c into FMA in this implementation (DETERMINISM);
 * clang honours the C99 pragma, gcc would warn that it ignores it. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

PLATEAU_DEF const char *plateau_result_string(plateau_result result)
{
    switch (result) {
#define PLATEAU__CASE(name, value, text) case name: return text;
        PLATEAU_RESULT_LIST(PLATEAU__CASE)
#undef PLATEAU__CASE
    default: break;
    }
    return "unknown plateau result code";
}

#ifndef PLATEAU_FREESTANDING
#include <string.h>
#endif
#include <limits.h> /* INT_MAX */
#ifndef PLATEAU_FREESTANDING
#include <time.h> /* clock: the default clock of options.max_seconds */
#endif
/* PLATEAU_QSORT(base, count, size, compare): qsort's contract.  Every
 * comparison given to it is a total order on the keys sorted, so any
 * correct sort gives the same result. */
#ifndef PLATEAU_QSORT
#ifdef PLATEAU_FREESTANDING
#error "plateau: PLATEAU_FREESTANDING needs PLATEAU_QSORT (qsort's arguments)"
#endif
#include <stdlib.h>
#define PLATEAU_QSORT(base, count, size, compare) qsort(base, count, size, compare)
#endif

/* ======== SECTION: shared helpers (plateau__util_) ======================== */
/* Vector, planar-polygon, number and error helpers used by several sections. */
/* ---- small vector helpers ---- */
static void plateau__util_sub(const double *p, const double *q, double *r)
{
    r[0] = p[0] - q[0]; r[1] = p[1] - q[1]; r[2] = p[2] - q[2];
}

static double plateau__util_dot(const double *p, const double *q)
{
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

static void plateau__util_cross(const double *p, const double *q, double *r)
{
    double x = p[1] * q[2] - p[2] * q[1];
    double y = p[2] * q[0] - p[0] * q[2];
    double z = p[0] * q[1] - p[1] * q[0];
    r[0] = x; r[1] = y; r[2] = z;
}

#ifndef PLATEAU_NO_STABILITY /* used by the stability report only */
/* 1 when the n indices at p and q are equal (memcmp's test, which a
 * freestanding build does not have) */
static int plateau__util_same_indices(const plateau_index *p, const plateau_index *q, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (p[i] != q[i]) return 0;
    return 1;
}
#endif

static double plateau__util_norm(const double *p)
{
    return PLATEAU_SQRT(plateau__util_dot(p, p));
}

/* (q - p) x (r - p): twice the area vector of the triangle (p, q, r). */
static void plateau__util_corner_cross(const double *p, const double *q, const double *r,
                                      double *n)
{
    double u[3], w[3];
    plateau__util_sub(q, p, u);
    plateau__util_sub(r, p, w);
    plateau__util_cross(u, w, n);
}

/* The angle at p of the triangle (p, q, r), in [0, pi] radians:
 * atan2(|u x w|, u . w) with u = q - p, w = r - p, accurate at every angle
 * (acos of the cosine is not, near 0 and pi). */
static double plateau__util_corner_angle(const double *p, const double *q, const double *r)
{
    double u[3], w[3], c[3];
    plateau__util_sub(q, p, u);
    plateau__util_sub(r, p, w);
    plateau__util_cross(u, w, c);
    return PLATEAU_ATAN2(plateau__util_norm(c), plateau__util_dot(u, w));
}

#define PLATEAU__PI 3.14159265358979323846
/* Steps 1 and 2 treat two points closer than this fraction of the
 * polygon's bounding-box diagonal as touching (why 1e-9: the comment of
 * plateau_boundary_check); PLATEAU__REL_TOL2 is its square, for squared
 * distances. */
#define PLATEAU__REL_TOL 1e-9
#define PLATEAU__REL_TOL2 1e-18
/* 180 degrees: no triangle's angle is larger (the start of a minimum). */
#define PLATEAU__HALF_TURN_DEG 180.0
/* pi / 180: one degree in radians. */
#define PLATEAU__ONE_DEGREE 0.0174532925199432958
/* sqrt(3) / 4: the area of the equilateral triangle of side 1. */
#define PLATEAU__SQRT3_4 0.4330127018922193

#define PLATEAU__DEG_PER_RAD 57.295779513082320876798154814105 /* 180 / pi */

/* exp(-t) for t >= 0, to a few ulp, by the library itself (no libm call,
 * so the same bits on every platform and in a freestanding build):
 * t = k ln 2 + r with |r| <= ln 2 / 2 (ln 2 in two parts), exp(-r) by its Taylor series (25
 * terms: the remainder is below 1e-30), then halved k times (exact until
 * the result underflows).  Only the annulus domain's radius ratio uses it. */
#define PLATEAU__UTIL_EXP_UNDERFLOW 745.0 /* exp(-t) is below the smallest double */
#define PLATEAU__UTIL_EXP_TERMS 25        /* terms of the Taylor series */
static double plateau__util_exp_neg(double t)
{
    /* ln 2 split in two (Cody and Waite): k * ln2_hi is exact for k < 2^20 */
    const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
    double k, r, term = 1.0, sum = 1.0;
    int i;
    if (!(t > 0.0)) return 1.0;
    if (t > PLATEAU__UTIL_EXP_UNDERFLOW) return 0.0;
    k = (double)(long)(t / (ln2_hi + ln2_lo) + 0.5);
    r = (t - k * ln2_hi) - k * ln2_lo;
    for (i = 1; i <= PLATEAU__UTIL_EXP_TERMS; i++) {
        term *= -r / (double)i;
        sum += term;
    }
    for (; k > 0.0; k -= 1.0) sum *= 0.5;
    return sum;
}

/* Allocates count elements of size bytes; NULL on overflow or no memory. */
static void *plateau__util_array(const plateau_allocator *a, size_t count, size_t size)
{
    size_t bytes = plateau__bytes(count, size);
    if (bytes == 0 && count != 0) return NULL;
    return plateau__alloc(a, bytes);
}

/* ---- errors: the one message formatter, and the reset ---- */

/* Error detail for every function that takes a plateau_error (err may be
 * NULL): the code, the index and the message fmt, each '@' of which takes
 * the next of v[0 .. nv - 1] in decimal. */
static void plateau__util_error_n(plateau_error *err, plateau_result code, long index,
                                  const char *fmt, const long *v, int nv)
{
    size_t k = 0;
    int used = 0;
    if (!err) return;
    err->code = code;
    err->index = index;
    err->index2 = -1;
    while (*fmt && k + 1 < sizeof err->message) {
        if (*fmt == '@' && used < nv) {
            char digits[24];
            long val = v[used++];
            unsigned long u = val < 0 ? 0ul - (unsigned long)val : (unsigned long)val;
            int d = 0;
            do { digits[d++] = (char)('0' + (int)(u % 10ul)); u /= 10ul; } while (u && d < 22);
            if (val < 0) digits[d++] = '-';
            while (d > 0 && k + 1 < sizeof err->message) err->message[k++] = digits[--d];
        } else {
            err->message[k++] = *fmt;
        }
        fmt++;
    }
    err->message[k] = '\0';
}

/* Step 1's test that the polygon can bound an embedded surface: no two
 * vertices on one point, no vertex on an edge it does not end, no two
 * edges that cross or touch, in space.  Tolerance: 1e-9 times the
 * bounding-box diagonal, relative so that the answer does not depend on
 * the units; it is the tolerance of step 2's planar test (so a planar
 * polygon accepted here has a simple plane domain), far above the
 * rounding of coordinates computed or printed to 15-17 digits (a helix
 * vertex at 2 pi lies 2.4e-16 off its axis: an exact test on doubles
 * would call that return edge disjoint from the helix) and far below any
 * feature a mesh resolves.  Consecutive vertices closer than that are
 * refused as repeated.  Works on a copy divided by the power of two at or
 * above the largest coordinate (exact; no square under- or overflows).
 * The reported defect is the first by (kind, smaller index, larger index)
 * among all found, so it does not depend on the grid. */

/* The same with at most two numbers, a and b (a fixed message passes 0, 0). */
static void plateau__util_error(plateau_error *err, plateau_result code, long index,
                                const char *fmt, long a, long b)
{
    long v[2];
    v[0] = a;
    v[1] = b;
    plateau__util_error_n(err, code, index, fmt, v, 2);
}

static plateau_result plateau__util_ok(plateau_error *err)
{
    if (err) {
        err->code = PLATEAU_OK;
        err->index = -1;
        err->index2 = -1;
        err->message[0] = '\0';
    }
    return PLATEAU_OK;
}

/* The one mapping of a failed plateau_lm.h call to plateau_result: out of
 * memory and a size overflow keep their meaning, anything else is the
 * solver's failure (PLATEAU_ERR_SOLVER); the message is the code's
 * sentence, or oom_message (when not NULL) for out of memory. */
static plateau_result plateau__util_lm_error(plateau_lm_result lrc, const char *oom_message,
                                             plateau_error *err)
{
    plateau_result rc = lrc == PLATEAU_LM_ERR_OUT_OF_MEMORY ? PLATEAU_ERR_OUT_OF_MEMORY
                      : lrc == PLATEAU_LM_ERR_OVERFLOW      ? PLATEAU_ERR_OVERFLOW
                                                            : PLATEAU_ERR_SOLVER;
    plateau__util_error(err, rc, -1,
                        rc == PLATEAU_ERR_OUT_OF_MEMORY && oom_message ? oom_message
                                                                       : plateau_lm_result_string(lrc),
                        0, 0);
    return rc;
}

/* The one mapping of a failed plateau_delaunay.h call to plateau_result:
 * out of memory and a size overflow keep their meaning (the message is the
 * code's sentence), anything else is PLATEAU_ERR_TRIANGULATION with the
 * triangulator's index and message. */
static plateau_result plateau__util_dt_error(plateau_dt_result dres, const plateau_dt_error *drep,
                                             plateau_error *err)
{
    if (dres == PLATEAU_DT_ERR_OUT_OF_MEMORY || dres == PLATEAU_DT_ERR_OVERFLOW) {
        plateau_result rc = dres == PLATEAU_DT_ERR_OUT_OF_MEMORY ? PLATEAU_ERR_OUT_OF_MEMORY
                                                                 : PLATEAU_ERR_OVERFLOW;
        plateau__util_error(err, rc, -1, plateau_dt_result_string(dres), 0, 0);
        return rc;
    }
    plateau__util_error(err, PLATEAU_ERR_TRIANGULATION, drep->index, drep->message, 0, 0);
    return PLATEAU_ERR_TRIANGULATION;
}

/* 1 when v is neither NaN nor infinite. */
static int plateau__util_finite(double v)
{
    return v == v && v - v == 0.0;
}

/* Whether a is below b by more than the fraction margin of it (of |b|: b
 * may be negative, a membrane's energy). */
static int plateau__util_lower(double a, double b, double margin)
{
    return b >= 0.0 ? a < b * (1.0 - margin) : a < b * (1.0 + margin);
}

/* Doubling or halving steps that take 1 to any positive finite double:
 * 2^-1074 .. 2^1023 is 2097 steps. */
#define PLATEAU__UTIL_POW2_STEPS 2200

/* The power of two at or above ext (> 0; 2^1023 at most, the next one
 * overflows): coordinates divided by it are exact, and their squares
 * neither underflow nor overflow. */
static double plateau__util_pow2_at_least(double ext)
{
    double s = 1.0;
    int steps;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && s < ext && plateau__util_finite(s * 2.0); steps++)
        s *= 2.0;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && s * 0.5 >= ext; steps++) s *= 0.5;
    return s;
}

/* p = the count points xyz moved to their bounding-box centre and divided
 * by the power of two at or above their largest half-extent: coordinates in
 * [-1, 1] whatever the units, and a small polygon far from the origin (a
 * unit square at z = 1e308) keeps its digits, where dividing by the largest
 * |coordinate| flushed it below the smallest double. */
static void plateau__util_unit_copy(const double *xyz, size_t count, double *p)
{
    double lo[3], hi[3], c[3], ext = 0.0, cs;
    size_t i;
    int k;
    for (k = 0; k < 3; k++) lo[k] = hi[k] = xyz[k];
    for (i = 1; i < count; i++)
        for (k = 0; k < 3; k++) {
            if (xyz[3 * i + (size_t)k] < lo[k]) lo[k] = xyz[3 * i + (size_t)k];
            if (xyz[3 * i + (size_t)k] > hi[k]) hi[k] = xyz[3 * i + (size_t)k];
        }
    for (k = 0; k < 3; k++) {
        c[k] = lo[k] * 0.5 + hi[k] * 0.5;
        if (hi[k] * 0.5 - lo[k] * 0.5 > ext) ext = hi[k] * 0.5 - lo[k] * 0.5;
    }
    cs = ext > 0.0 ? plateau__util_pow2_at_least(ext) : 1.0;
    for (i = 0; i < count; i++)
        for (k = 0; k < 3; k++) p[3 * i + (size_t)k] = (xyz[3 * i + (size_t)k] - c[k]) / cs;
}

/* The time budget of one call (options.max_seconds). */
typedef struct plateau__util_budget {
    double (*clock_fn)(void *user);
    void *clock_user;
    double deadline;  /* clock_fn's reading at which the budget ends */
    int expired;      /* it has ended: no solve starts, none goes on */
    int interrupted;  /* a solve was cut short or never ran: the mesh's
                         objective did not reach its stopping rule */
} plateau__util_budget;

#ifndef PLATEAU_FREESTANDING
static double plateau__util_cpu_seconds(void *user)
{
    (void)user;
    return (double)clock() / (double)CLOCKS_PER_SEC;
}
#endif

/* 1 once options.max_seconds have passed (and from then on); 0 without a
 * budget.  One clock reading per call: the solvers ask once per
 * iteration, the rounds once per round, the seeding once per refinement. */
static int plateau__util_time_up(plateau__util_budget *b)
{
    if (!b) return 0;
    if (!b->expired && !(b->clock_fn(b->clock_user) < b->deadline)) b->expired = 1;
    return b->expired;
}

#ifndef PLATEAU_NO_LOOPS /* used by the discs of two loops only */
/* The seconds left of budget b on its clock (one reading; at least
 * 1e-300, so that a budget that has run out stays a budget); 0 without
 * one. */
static double plateau__util_time_left(const plateau__util_budget *b)
{
    double left;
    if (!b) return 0.0;
    left = b->deadline - b->clock_fn(b->clock_user);
    return left > 0.0 ? left : 1e-300;
}
#endif

/* Squared distance from p to the segment a-b in the plane. */
static double plateau__util_seg_dist2(const double *p, const double *a, const double *b)
{
    double ex = b[0] - a[0], ey = b[1] - a[1];
    double px = p[0] - a[0], py = p[1] - a[1];
    double l2 = ex * ex + ey * ey, t = 0.0, dx, dy;
    if (l2 > 0.0) {
        t = (px * ex + py * ey) / l2;
        if (t < 0.0) t = 0.0;
        if (t > 1.0) t = 1.0;
    }
    dx = px - t * ex;
    dy = py - t * ey;
    return dx * dx + dy * dy;
}

/* Squared bounding-box diagonal of m points in the plane. */
static double plateau__util_diag2(const double *uv, size_t m)
{
    double lo[2], hi[2];
    size_t i;
    lo[0] = hi[0] = uv[0];
    lo[1] = hi[1] = uv[1];
    for (i = 1; i < m; i++) {
        if (uv[2 * i] < lo[0]) lo[0] = uv[2 * i];
        if (uv[2 * i] > hi[0]) hi[0] = uv[2 * i];
        if (uv[2 * i + 1] < lo[1]) lo[1] = uv[2 * i + 1];
        if (uv[2 * i + 1] > hi[1]) hi[1] = uv[2 * i + 1];
    }
    return (hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]);
}

/* Signed area of the closed polygon uv of m vertices (shoelace formula,
 * relative to vertex 0): positive when counter-clockwise. */
static double plateau__util_signed_area(const double *uv, size_t m)
{
    double s = 0.0;
    size_t i;
    for (i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        s += (uv[2 * i] - uv[0]) * (uv[2 * j + 1] - uv[1]) -
             (uv[2 * j] - uv[0]) * (uv[2 * i + 1] - uv[1]);
    }
    return 0.5 * s;
}
/* ======== END SECTION: shared helpers ===================================== */

/* ======== SECTION: the configuration (plateau__cfg_) ====================== */
/* The options resolved and validated once, at entry, into one plateau__cfg,
 * read-only from then on: below the entry points nothing reads the
 * caller's plateau_options.  The defaults live here and nowhere else, and
 * so does every other configuration a run uses (plateau__cfg_derive).
 * What a run decides or changes on its way lives in its run context,
 * plateau__cfg_run.  Also the memory estimate and the work area the steps
 * fill for the driver. */

/* The defaults of plateau_options (plateau_resolved_options fills them in). */
#define PLATEAU__DEFAULT_SEED 20140101u
#define PLATEAU__DEFAULT_ROUNDS 20
#define PLATEAU__DEFAULT_LM_ITERATIONS 200
#define PLATEAU__DEFAULT_LBFGS_ITERATIONS 5000
#define PLATEAU__DEFAULT_QUALITY_ANGLE 26.0
#define PLATEAU__DEFAULT_LAMBDA 1.0
#define PLATEAU__DEFAULT_AREA_TOLERANCE 1e-6
/* The largest area_tolerance accepted. */
#define PLATEAU__MAX_AREA_TOLERANCE 1e-2

/* The switches (CONFIGURATION): what a request for a feature compiled out
 * is told (PLATEAU_ERR_ARGUMENT), and whether the sparse solvers of
 * plateau_lm.h are there (without them every solve takes the dense path). */
#define PLATEAU__CFG_NO_STABILITY \
    "stability ON and critical_index need the second-order analysis, compiled out by " PLATEAU__NO_STABILITY_BY
#define PLATEAU__CFG_NO_MEMBRANES \
    "a membrane (pressure, fix_volume or cable_tension) needs the membranes, compiled out by PLATEAU_NO_MEMBRANES"
#define PLATEAU__CFG_NO_COARSE_TO_FINE \
    "coarse_to_fine ON needs coarse to fine, compiled out by " PLATEAU__NO_COARSE_TO_FINE_BY
#define PLATEAU__CFG_NO_SPARSE \
    "linear_solver SPARSE or area_warm_start ON needs the sparse solvers, compiled out by PLATEAU_LM_NO_SPARSE"
#define PLATEAU__CFG_NO_LOOPS "several loops are compiled out by PLATEAU_NO_LOOPS"
#define PLATEAU__CFG_NO_ACCURACY \
    "options.accuracy > 0 needs the error estimate, compiled out by PLATEAU_NO_ACCURACY"
#ifdef PLATEAU_LM_NO_SPARSE
#define PLATEAU__HAVE_SPARSE 0
#else
#define PLATEAU__HAVE_SPARSE 1
#endif
/* Without several loops (PLATEAU_NO_LOOPS) their branches in the steps are
 * dead code the compiler drops: plateau__drv_solve refused k > 1. */
#ifdef PLATEAU_NO_LOOPS
#define PLATEAU__HAVE_LOOPS 0
#else
#define PLATEAU__HAVE_LOOPS 1
#endif
/* Without the error estimate (PLATEAU_NO_ACCURACY) the default accuracy
 * means none: plateau_resolved_options leaves options.accuracy 0. */
#ifdef PLATEAU_NO_ACCURACY
#define PLATEAU__HAVE_ACCURACY 0
#else
#define PLATEAU__HAVE_ACCURACY 1
#endif

/* Whether methods paper and area take the sparse path for n free
 * vertices: linear_solver SPARSE, or AUTO above PLATEAU_SPARSE_THRESHOLD;
 * never without the sparse solvers (PLATEAU_LM_NO_SPARSE). */
static int plateau__cfg_sparse(plateau_linear_solver linear_solver, double n)
{
    return PLATEAU__HAVE_SPARSE &&
           (linear_solver == PLATEAU_LINEAR_SPARSE ||
            (linear_solver != PLATEAU_LINEAR_DENSE && n > (double)PLATEAU_SPARSE_THRESHOLD));
}

/* The options a switch refuses (NULL: none), for plateau__cfg_resolve. */
static const char *plateau__cfg_compiled_out(const plateau_options *r)
{
    const char *bad = NULL;
#ifdef PLATEAU_NO_STABILITY
    if (r->stability == PLATEAU_ON || r->critical_index > 0) bad = PLATEAU__CFG_NO_STABILITY;
#endif
#ifdef PLATEAU_NO_MEMBRANES
    if (r->pressure != 0.0 || r->fix_volume || r->cable_tension) bad = PLATEAU__CFG_NO_MEMBRANES;
#endif
#ifdef PLATEAU_NO_COARSE_TO_FINE
    if (r->coarse_to_fine == PLATEAU_ON) bad = PLATEAU__CFG_NO_COARSE_TO_FINE;
#endif
#ifdef PLATEAU_LM_NO_SPARSE
    if (r->linear_solver == PLATEAU_LINEAR_SPARSE || r->area_warm_start == PLATEAU_ON) bad = PLATEAU__CFG_NO_SPARSE;
#endif
#ifdef PLATEAU_NO_ACCURACY
    if (r->accuracy > 0.0) bad = PLATEAU__CFG_NO_ACCURACY;
#endif
    (void)r;
    return bad;
}

/* max_iterations 0 means this, per solve of the method. */
static int plateau__cfg_default_iterations(plateau_method method)
{
    return method == PLATEAU_METHOD_AREA ? PLATEAU__DEFAULT_LBFGS_ITERATIONS
                                         : PLATEAU__DEFAULT_LM_ITERATIONS;
}

/* What the last sparse solve of method area leaves for the stability
 * report, whose normal Hessian has the free vertices' 1-ring pattern too:
 * a coarse-to-fine level (plateau__c2f_normal_newton) its scalar
 * pattern and analysis, which the report reuses as they are when its own
 * pattern is the same; the Newton method on 3 unknowns a vertex its
 * elimination order by vertex (vertex[k] is eliminated k-th), which spares
 * the report the nested dissection.  The driver owns and frees it. */
typedef struct plateau__solve_order {
    plateau_allocator alloc; /* the driver's: everything below is allocated with it */
    plateau_index *vertex;
    size_t count, capacity;
    plateau_lm_sparse_symbolic *sym; /* the level's analysis, or NULL */
    void *pattern;                   /* its pattern (plateau__solve_sparse_pattern's block) */
    plateau_allocator pattern_alloc; /* the mesh's, which allocated pattern */
    plateau_index *row_start, *cols; /* in pattern: nfree + 1 and row_start[nfree] */
    size_t nfree;
} plateau__solve_order;

/* The one private configuration: the caller's options validated, with the
 * defaults filled in; read-only once plateau__cfg_resolve has filled it. */
typedef struct plateau__cfg {
    plateau_method method;
    size_t n;             /* interior points asked for (interior_points) */
    uint64_t seed;
    int max_rounds;
    int max_iterations;   /* per solve of the method's own solver */
    double lambda;
    plateau_switch warm_start;     /* area_warm_start */
    plateau_switch paper_presolve; /* as given; the run's presolve is the decision */
    plateau_seeding seeding;
    plateau_switch refine_boundary;
    double quality_min_angle, quality_edge_length;
    size_t max_memory;    /* bytes; (size_t)-1: no limit */
    plateau_linear_solver linear_solver;
    double area_tolerance; /* the Newton method's SMALL_CHANGE bound (step 5) */
    plateau_switch coarse_to_fine;
    int stability;        /* the stability report after the final check */
    int alternatives;     /* two loops: solve the discs too */
    int least_area;       /* two loops: return the discs when smaller */
    int critical_index;   /* > 0: the saddle search after the rounds */
    int force_circle;
    int (*progress)(int round, int iteration, double f, void *user);
    void *progress_user;
    plateau_allocator alloc;
    double max_seconds;   /* the time budget, > 0; 0: none */
    double (*clock_fn)(void *user); /* its clock (the default filled in) */
    void *clock_user;
    /* membranes, as given (the run holds them in the frame) */
    int membrane;         /* pressure, volume or cables: step 5 minimises
                             plateau_membrane_energy instead of the area */
    double pressure;      /* p */
    int fix_volume;
    double volume;        /* V0 when fix_volume */
    const double *cable_tension; /* the caller's, one per boundary vertex */
    double accuracy;      /* > 0: the relative error of the area aimed at
                             (options.accuracy, or the default); 0: none */
    int n_given;          /* options.interior_points was not 0 */
} plateau__cfg;

/* What a run decides or changes on its way, beside its read-only
 * configuration: the driver or the step that decides a value sets it,
 * the steps after read it.  A copy shares the time budget and the
 * elimination order through its pointers. */
typedef struct plateau__cfg_run {
    int presolve;         /* method paper: method area's rounds run first
                             (step 2 decides; plateau_mesh_minimize takes
                             paper_presolve ON only) */
    double unit;          /* the frame's scale s (the solves see the polygon
                             divided by s): the progress callback gets F in
                             the caller's units, an area times s^2, a sum of
                             squared curvatures over s^2 */
    int c2f_memory;       /* the memory bound of the coarse-to-fine path
                             (while that path may run) */
    size_t neck_m0, neck_m1; /* two loops of these sizes (mesh vertices 0 ..
                                m0 + m1 - 1): the pinch test; 0: none */
    /* a membrane in the frame (plateau__memb_frame divides lengths by s: a
     * pressure times s, a tension over s, a volume over s^3) */
    double pressure;      /* p (method paper: H_i = p); a held volume's
                             iteration moves it */
    double volume;        /* V0 when fix_volume */
    double apex[3];       /* the cone's apex: the given boundary's centroid */
    double escape;        /* a film vertex farther than this from the apex
                             is refused by the line searches (0: no bound) */
    double radius;        /* the given boundary's largest distance from the apex */
    double orientation;   /* -1 when the frame mirrors (plateau__frame_orientation) */
    const plateau_index *cable_seg; /* 2 per cable segment (mesh vertices) */
    const double *cable_t;          /* the segments' tensions */
    size_t cable_nseg;
    const plateau_index *cable_vtx; /* the free cable vertices */
    size_t cable_nv;
    plateau__util_budget *budget; /* options.max_seconds, or NULL: none
                                (points at budget_data of the run that
                                plateau__cfg_run_start began: copies share it) */
    plateau__util_budget budget_data;
    plateau__solve_order *order; /* where the sparse Newton solves leave their
                                    elimination order (NULL: nowhere) */
} plateau__cfg_run;

PLATEAU_DEF const char *plateau_method_name(plateau_method method)
{
    switch (method) {
    case PLATEAU_METHOD_PAPER: return "paper";
    case PLATEAU_METHOD_PAPER_LITERAL: return "paper-literal";
    case PLATEAU_METHOD_AREA: return "area";
    default: break;
    }
    return "unknown";
}

PLATEAU_DEF int plateau_method_from_name(const char *name, plateau_method *method)
{
    int k;
    if (!name || !method) return -1;
    for (k = 0; k < 3; k++) {
        const char *a = name, *b = plateau_method_name((plateau_method)k);
        while (*a && *a == *b) a++, b++;
        if (*a == *b) { /* the two strings are equal */
            *method = (plateau_method)k;
            return 0;
        }
    }
    return -1;
}

/* The defaults, filled in (the one place they are applied). */
PLATEAU_DEF plateau_options plateau_resolved_options(const plateau_options *options, size_t m)
{
    plateau_options r;
    if (options) r = *options;
    else memset(&r, 0, sizeof r);
    if (PLATEAU__HAVE_ACCURACY && r.accuracy == 0.0 && r.interior_points == 0 && r.quality_edge_length == 0.0 &&
        r.pressure == 0.0 && !r.fix_volume && !r.cable_tension && r.critical_index == 0 &&
        r.method != PLATEAU_METHOD_PAPER_LITERAL && r.seeding != PLATEAU_SEEDING_PAPER)
        r.accuracy = PLATEAU_DEFAULT_ACCURACY; /* ACCURACY at the top; several loops
                                                 aim at it only when asked */
    if (r.interior_points == 0) r.interior_points = m;
    if (r.seed == 0) r.seed = PLATEAU__DEFAULT_SEED;
    if (r.max_rounds == 0) r.max_rounds = PLATEAU__DEFAULT_ROUNDS;
    if (r.max_iterations == 0) r.max_iterations = plateau__cfg_default_iterations(r.method);
    if (r.lambda == 0.0) r.lambda = PLATEAU__DEFAULT_LAMBDA;
    if (r.area_tolerance == 0.0) r.area_tolerance = PLATEAU__DEFAULT_AREA_TOLERANCE;
    if (r.quality_min_angle == 0.0) r.quality_min_angle = PLATEAU__DEFAULT_QUALITY_ANGLE;
    if (r.max_memory == 0) r.max_memory = PLATEAU_DEFAULT_MAX_MEMORY;
    if (r.pressure != 0.0 || r.fix_volume || r.cable_tension) {
        /* a membrane: these are of the area alone (MEMBRANES) */
        if (r.coarse_to_fine == PLATEAU_AUTO) r.coarse_to_fine = PLATEAU_OFF;
        if (r.stability == PLATEAU_AUTO) r.stability = PLATEAU_OFF;
        if (r.alternatives == PLATEAU_AUTO) r.alternatives = PLATEAU_OFF;
    }
    return r;
}

static int plateau__cfg_switch_valid(plateau_switch s)
{
    return s == PLATEAU_OFF || s == PLATEAU_AUTO || s == PLATEAU_ON;
}

/* Validates the caller's options (NULL: all zero) and resolves them, for a
 * boundary of m vertices, into *cfg: the only place that reads them.
 * PLATEAU_ERR_ARGUMENT names the first option out of range. */
static plateau_result plateau__cfg_resolve(const plateau_options *options, size_t m,
                                           plateau__cfg *cfg, plateau_error *err)
{
    plateau_options r = plateau_resolved_options(options, m);
    const char *bad = NULL;
    plateau_result code = PLATEAU_ERR_ARGUMENT;
    memset(cfg, 0, sizeof *cfg);
    if ((int)r.method < 0 || (int)r.method > 2)
        bad = "method is out of range: PLATEAU_METHOD_PAPER, _PAPER_LITERAL or _AREA";
    else if (r.max_rounds < 0 || r.max_iterations < 0)
        bad = r.max_rounds < 0 ? "max_rounds is out of range: 0 (the default) or more"
                               : "max_iterations is out of range: 0 (the default) or more";
    else if (!(r.lambda >= 0.0) || !plateau__util_finite(r.lambda))
        bad = "lambda is out of range: finite, 0 (the default) or more";
    else if (!plateau__allocator_valid(&r.allocator))
        bad = "allocator: set both alloc_fn and free_fn, or neither";
    else if (!plateau__cfg_switch_valid(r.paper_presolve) ||
             !plateau__cfg_switch_valid(r.area_warm_start) ||
             !plateau__cfg_switch_valid(r.refine_boundary) || !plateau__cfg_switch_valid(r.coarse_to_fine))
        bad = "paper_presolve, area_warm_start, refine_boundary and coarse_to_fine must be PLATEAU_AUTO, PLATEAU_ON or PLATEAU_OFF";
    else if (!plateau__cfg_switch_valid(r.stability) || !plateau__cfg_switch_valid(r.alternatives))
        bad = "stability and alternatives must be PLATEAU_AUTO, PLATEAU_ON or PLATEAU_OFF";
    else if (r.critical_index < 0 || r.critical_index >= PLATEAU_STABILITY_MAX_EIGENVALUES)
        bad = "critical_index must be 0 to 7";
    else if ((int)r.linear_solver < PLATEAU_LINEAR_AUTO || (int)r.linear_solver > PLATEAU_LINEAR_SPARSE)
        bad = "linear_solver must be 0, 1 or 2";
    else if (!(r.area_tolerance >= 0.0) || !(r.area_tolerance <= PLATEAU__MAX_AREA_TOLERANCE))
        bad = "area_tolerance must be in [0, 1e-2]";
    else if (!plateau__util_finite(r.pressure) || !plateau__util_finite(r.volume))
        code = PLATEAU_ERR_PRESSURE, bad = "pressure and volume must be finite";
    else if (r.method == PLATEAU_METHOD_PAPER_LITERAL &&
             (r.pressure != 0.0 || r.fix_volume || r.cable_tension))
        code = r.cable_tension ? PLATEAU_ERR_CABLE : PLATEAU_ERR_PRESSURE,
        bad = "method paper-literal takes no pressure, volume or cables (methods paper and area do)";
    else if (((int)r.seeding != PLATEAU_SEEDING_PAPER && (int)r.seeding != PLATEAU_SEEDING_QUALITY &&
              (int)r.seeding != PLATEAU_SEEDING_AUTO) ||
             !(r.quality_min_angle >= 0.0) || !(r.quality_edge_length >= 0.0) ||
             !plateau__util_finite(r.quality_min_angle) || !plateau__util_finite(r.quality_edge_length))
        bad = "seeding, quality_min_angle or quality_edge_length is out of range";
    else if (r.coarse_to_fine == PLATEAU_ON &&
             (r.refine_boundary == PLATEAU_OFF || r.seeding == PLATEAU_SEEDING_PAPER ||
              r.quality_edge_length > 0.0 || r.method == PLATEAU_METHOD_PAPER_LITERAL))
        bad = "coarse_to_fine ON needs method area or paper, refine_boundary not OFF, seeding not PAPER and quality_edge_length 0";
    else if (!(r.max_seconds >= 0.0))
        bad = "max_seconds must be 0 (no limit) or positive";
    else if (r.accuracy != r.accuracy)
        bad = "accuracy must not be NaN (> 0: the relative error asked for; 0: the default; < 0: none)";
    else if ((r.pressure != 0.0 || r.fix_volume || r.cable_tension) &&
             (r.coarse_to_fine == PLATEAU_ON || r.stability == PLATEAU_ON || r.alternatives == PLATEAU_ON ||
              r.critical_index > 0 || r.least_area_topology))
        bad = r.coarse_to_fine == PLATEAU_ON
                  ? "coarse_to_fine ON and a membrane (pressure, fix_volume or cable_tension): its Newton steps "
                    "are the area's, not the membrane energy's"
                  : "stability ON, alternatives ON, critical_index and least_area_topology are of the area "
                    "alone, not of a membrane (pressure, fix_volume or cable_tension)";
    if (!bad && (bad = plateau__cfg_compiled_out(&r)) != NULL) code = PLATEAU_ERR_ARGUMENT;
    if (bad) {
        plateau__util_error(err, code, -1, bad, 0, 0);
        return code;
    }
    cfg->method = r.method;
    cfg->n = r.interior_points;
    cfg->seed = r.seed;
    cfg->max_rounds = r.max_rounds;
    cfg->max_iterations = r.max_iterations;
    cfg->lambda = r.lambda;
    cfg->warm_start = r.area_warm_start;
    cfg->paper_presolve = r.paper_presolve;
    cfg->seeding = r.seeding;
    cfg->refine_boundary = r.refine_boundary;
    cfg->quality_min_angle = r.quality_min_angle;
    cfg->quality_edge_length = r.quality_edge_length;
    cfg->max_memory = r.max_memory;
    cfg->linear_solver = r.linear_solver;
    cfg->area_tolerance = r.area_tolerance;
    cfg->coarse_to_fine = r.coarse_to_fine;
    cfg->force_circle = r.force_circle_domain != 0;
    /* a switch turns AUTO off (CONFIGURATION); ON was refused above */
#ifdef PLATEAU_NO_STABILITY
    r.stability = PLATEAU_OFF;
#endif
#ifdef PLATEAU_NO_COARSE_TO_FINE
    cfg->coarse_to_fine = PLATEAU_OFF;
#endif
#ifdef PLATEAU_LM_NO_SPARSE
    cfg->warm_start = PLATEAU_OFF;
#endif
    cfg->stability = r.stability != PLATEAU_OFF;
    cfg->alternatives = r.alternatives != PLATEAU_OFF;
    cfg->least_area = r.least_area_topology != 0;
    cfg->critical_index = r.critical_index;
    cfg->progress = r.progress;
    cfg->progress_user = r.progress_user;
    cfg->alloc = r.allocator;
    cfg->pressure = r.pressure;
    cfg->fix_volume = r.fix_volume != 0;
    cfg->volume = r.volume;
    cfg->cable_tension = r.cable_tension;
    cfg->membrane = r.pressure != 0.0 || cfg->fix_volume || r.cable_tension;
    cfg->accuracy = r.accuracy > 0.0 && !cfg->membrane ? r.accuracy : 0.0;
    cfg->n_given = options && options->interior_points > 0;
    /* the time budget (its clock is read when the run starts) */
    if (r.max_seconds > 0.0 && plateau__util_finite(r.max_seconds)) {
        cfg->max_seconds = r.max_seconds;
        cfg->clock_fn = r.clock_fn;
        cfg->clock_user = r.clock_user;
#ifndef PLATEAU_FREESTANDING
        if (!cfg->clock_fn) cfg->clock_fn = plateau__util_cpu_seconds;
#endif
        if (!cfg->clock_fn) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                                "max_seconds needs options.clock_fn in a freestanding build", 0, 0);
            return PLATEAU_ERR_ARGUMENT;
        }
    }
    return PLATEAU_OK;
}

/* Starts the run context of a solve configured by *cfg: nothing decided
 * yet, the unit frame, and the time budget, its clock read now (at the
 * start of the call). */
static void plateau__cfg_run_start(const plateau__cfg *cfg, plateau__cfg_run *run)
{
    memset(run, 0, sizeof *run);
    run->unit = 1.0;
    run->orientation = 1.0;
    if (cfg->max_seconds > 0.0) {
        plateau__util_budget *b = &run->budget_data;
        b->clock_fn = cfg->clock_fn;
        b->clock_user = cfg->clock_user;
        b->deadline = b->clock_fn(b->clock_user) + cfg->max_seconds;
        run->budget = b;
    }
}

/* The configurations of the further solves a run makes, each derived
 * from the resolved one (which stays as it is) by plateau__cfg_derive. */
typedef enum plateau__cfg_use {
    PLATEAU__CFG_PRESOLVE,    /* method paper's presolve by method area's rounds */
    PLATEAU__CFG_PROBE,       /* the pinch probe: method area's rounds on a copy */
    PLATEAU__CFG_COARSE,      /* coarse to fine's coarse mesh */
    PLATEAU__CFG_HELD_VOLUME, /* the solves of a held volume (fix_volume) */
    PLATEAU__CFG_DISC         /* one disc of two loops (alternatives) */
} plateau__cfg_use;

/* The coarse mesh's Newton solves end when 5 steps lower its area by less
 * than this fraction of it (SMALL_CHANGE; options.area_tolerance when
 * larger): the coarse mesh's own excess is 1e-3 to 1e-2 and the levels
 * redo its normal positions, so the 1e-6 of the rounds at full size only
 * bought tangential creep there (examples/NOTES.md, section 10). */
#define PLATEAU__CFG_COARSE_TOL 1e-4
/* A held volume's V(p) must be exact to PLATEAU__MEMB_VOLUME_TOL: the
 * Newton method's SMALL_CHANGE stop (area_tolerance) can leave V short of
 * it (tests/test_membrane.c has such a case), so its solves stop at this
 * SMALL_CHANGE bound, which leaves them to their gradient test. */
#define PLATEAU__CFG_HELD_VOLUME_TOL 1e-13

/* The configuration of a further solve (use), as a new value from *cfg:
 * method area's rounds for another method (PRESOLVE, PROBE, COARSE) take
 * method area with its own default number of iterations per solve.  n
 * and max_seconds: a disc's interior points and the seconds left of the
 * call (DISC only). */
static plateau__cfg plateau__cfg_derive(const plateau__cfg *cfg, plateau__cfg_use use, size_t n,
                                        double max_seconds)
{
    plateau__cfg d = *cfg;
    if (use == PLATEAU__CFG_PRESOLVE || use == PLATEAU__CFG_PROBE || use == PLATEAU__CFG_COARSE) {
        d.method = PLATEAU_METHOD_AREA;
        d.max_iterations = plateau__cfg_default_iterations(PLATEAU_METHOD_AREA);
    }
    if (use == PLATEAU__CFG_PRESOLVE) {
        /* the square solves that follow converge to their root from a
         * start near the surface, so the presolve's Newton method stops at
         * the default tolerance whatever area_tolerance says (examples/
         * NOTES.md, "Measurements behind the solver's choices") */
        d.area_tolerance = PLATEAU__DEFAULT_AREA_TOLERANCE;
        /* the presolve's path by size alone: linear_solver chooses how
         * method paper solves its square system, and forced dense and
         * sparse then start from the same presolved mesh */
        d.linear_solver = PLATEAU_LINEAR_AUTO;
    } else if (use == PLATEAU__CFG_PROBE) {
        d.progress = NULL; /* a look at the result, no stage of the solve */
    } else if (use == PLATEAU__CFG_COARSE) {
        /* steps 3-4 with the polygon's edges refined, one round of the
         * sparse Newton method */
        d.refine_boundary = PLATEAU_ON;
        d.linear_solver = PLATEAU_LINEAR_SPARSE;
        d.max_rounds = 1;
        if (d.area_tolerance < PLATEAU__CFG_COARSE_TOL) d.area_tolerance = PLATEAU__CFG_COARSE_TOL;
    } else if (use == PLATEAU__CFG_HELD_VOLUME) {
        d.area_tolerance = PLATEAU__CFG_HELD_VOLUME_TOL;
    } else { /* a disc: the same options, n points, the time left, and none
              * of the analyses after the final check */
        d.n = n;
        d.max_seconds = max_seconds;
        d.stability = 0;
        d.alternatives = 0;
        d.least_area = 0;
        d.critical_index = 0;
    }
    return d;
}

/* Memory estimate: counts above this are clamped (the bound stays finite
 * and its log2 loop short); numbers in a message are clamped to fit a
 * 32-bit long. */
#define PLATEAU__CFG_COUNT_CAP 1e15
#define PLATEAU__CFG_LONG_CAP 2e9
#define PLATEAU__CFG_MIB 1048576.0

/* The bound of plateau_memory_estimate's comment for a given linear solver
 * of methods paper and area (dense: LM's 3n x 3n matrices; sparse: the
 * nested-dissection LU, which fills O(n log n); how the coefficients were
 * fitted: examples/NOTES.md, "Measurements behind the solver's choices"). */
static double plateau__cfg_estimate(plateau_method method, plateau_linear_solver linear_solver,
                                    double dm, double dn)
{
    int sparse = plateau__cfg_sparse(linear_solver, dn);
    if (method == PLATEAU_METHOD_AREA && !sparse) return 1000.0 * dn + 400.0 * dm + 8192.0;
    if (method == PLATEAU_METHOD_PAPER_LITERAL) return 48.0 * dn * (dn + dm) + 4500.0 * (dn + dm);
    if (sparse) { /* method paper's LU; method area's Cholesky is smaller */
        double lg = 0.0, x = dn + 2.0; /* log2(n + 2), rounded up */
        int steps;
        for (steps = 0; steps < 64 && x > 1.0; steps++) {
            x *= 0.5;
            lg += 1.0;
        }
        return 640.0 * dn * lg + 1600.0 * (dn + dm) + 8192.0;
    }
    return 224.0 * dn * dn + 3200.0 * (dn + dm);
}

/* The bound for coarse to fine (methods area and paper): the finest mesh,
 * its predecessor while it is subdivided, and one scalar factor of the
 * normal-motion Hessian (nested dissection: O(n log n)). */
static double plateau__cfg_c2f_estimate(double dm, double dn)
{
    double lg = 0.0, x = dn + 2.0;
    int steps;
    for (steps = 0; steps < 64 && x > 1.0; steps++) {
        x *= 0.5;
        lg += 1.0;
    }
    return 64.0 * dn * lg + 1600.0 * (dn + dm) + 8192.0;
}

PLATEAU_DEF double plateau_memory_estimate(plateau_method method, size_t m, size_t n)
{
    return plateau__cfg_estimate(method, PLATEAU_LINEAR_AUTO, (double)m, (double)n);
}

/* PLATEAU_ERR_MEMORY_LIMIT when the estimate for m fixed and n free
 * vertices (doubles, so that an estimated count cannot overflow) exceeds
 * cfg->max_memory (coarse to fine's estimate while run->c2f_memory). */
static plateau_result plateau__cfg_memory_check(const plateau__cfg *cfg, const plateau__cfg_run *run,
                                                double m, double n, plateau_error *err)
{
    double limit = (double)cfg->max_memory, need, dm, dn, unit;
    long v[4];
    if (cfg->max_memory == (size_t)-1) return PLATEAU_OK;
    dm = m < PLATEAU__CFG_COUNT_CAP ? m : PLATEAU__CFG_COUNT_CAP;
    dn = n < PLATEAU__CFG_COUNT_CAP ? n : PLATEAU__CFG_COUNT_CAP;
    need = run->c2f_memory ? plateau__cfg_c2f_estimate(dm, dn)
                           : plateau__cfg_estimate(cfg->method, cfg->linear_solver, dm, dn);
    if (need <= limit) return PLATEAU_OK;
    /* a limit below a megabyte in bytes (else "about 0 MB, above 0 MB") */
    unit = limit < PLATEAU__CFG_MIB ? 1.0 : PLATEAU__CFG_MIB;
    /* rounded, or rounded down after "at least" (an interior count the
       message cannot print) */
    v[0] = (long)(need / unit < PLATEAU__CFG_LONG_CAP ? need / unit + (n < PLATEAU__CFG_LONG_CAP ? 0.5 : 0.0)
                                                     : PLATEAU__CFG_LONG_CAP);
    v[1] = (long)(n < PLATEAU__CFG_LONG_CAP ? n : PLATEAU__CFG_LONG_CAP);
    v[2] = (long)(dm < PLATEAU__CFG_LONG_CAP ? dm : PLATEAU__CFG_LONG_CAP);
    v[3] = (long)(limit / unit < PLATEAU__CFG_LONG_CAP ? limit / unit + 0.5 : PLATEAU__CFG_LONG_CAP);
    {
        /* [bytes or MB][n as asked, or above what the message can print] */
        static const char *const msg[2][2] = {
            {"the solve would need about @ MB (@ interior and @ boundary vertices), above the limit of @ MB "
             "(options.max_memory)",
             "the solve would need at least @ MB (at least @ interior and @ boundary vertices), above the "
             "limit of @ MB (options.max_memory)"},
            {"the solve would need about @ bytes (@ interior and @ boundary vertices), above the limit of @ "
             "bytes (options.max_memory)",
             "the solve would need at least @ bytes (at least @ interior and @ boundary vertices), above "
             "the limit of @ bytes (options.max_memory)"}};
        plateau__util_error_n(err, PLATEAU_ERR_MEMORY_LIMIT, -1, msg[unit == 1.0][n >= PLATEAU__CFG_LONG_CAP],
                              v, 4);
    }
    return PLATEAU_ERR_MEMORY_LIMIT;
}

/* What the driver carries from one step to the next.  All arrays come from
 * alloc and are freed by plateau__cfg_work_free. */
typedef struct plateau__cfg_work {
    plateau_allocator alloc;
    const double *boundary; /* 3 * m: the caller's polygon */
    size_t m, n;            /* boundary vertices, interior points asked for */
    double *nb;             /* 3 * m: the polygon in the frame */
    double *uv;             /* 2 * m: its parameter domain (step 2) */
    plateau_index *seg;     /* 2 * m: the domain polygon's edges */
    double *pts;            /* 3 * n: the seeded points in 3-D (fan seeding) */
    plateau_dt_mesh dt;     /* the planar triangulation (step 4) */
    size_t k;               /* fixed vertices the refinement added on the edges */
    double *orig;           /* 3 * (m + k) when k > 0: the fixed vertices in the
                               caller's units, for the bit-exact restore */
    /* several loops (plateau_solve_loops; all zero for one polygon): m counts
     * the vertices of all loops, loop j holds vertices off[j] .. off[j+1]-1 */
    size_t loops;
    size_t *off;            /* loops + 1 offsets */
    size_t *loop;           /* m: the loop of vertex i */
    size_t *next;           /* m: the vertex that ends edge i (its loop's next) */
    double *lsign;          /* loops: +1 when the loop runs with the domain on
                               its left in uv (outer counter-clockwise, holes
                               clockwise), -1 when against */
    double area;            /* the domain's area (outer minus holes) */
    /* cables (options.cable_tension; all NULL without): the polygon with
     * the free cable vertices inserted, its loop counts, and the cable
     * segments for plateau__cfg_run */
    double *cable_xyz;
    size_t *cable_counts;
    plateau_index *cable_seg, *cable_vtx, *cable_anchor;
    double *cable_t;
    size_t cables;          /* cables; cable_anchor[2 j], [2 j + 1]: the anchors
                               of cable j, its free vertices from
                               cable_anchor[2 j] + 1 in the mesh */
    struct plateau__util_budget *time_budget; /* plateau__cfg_run.budget */
} plateau__cfg_work;

static void plateau__cfg_work_free(plateau__cfg_work *s)
{
    plateau_dt_free(&s->dt);
    plateau__free(&s->alloc, s->orig);
    plateau__free(&s->alloc, s->uv);
    plateau__free(&s->alloc, s->pts);
    plateau__free(&s->alloc, s->seg);
    plateau__free(&s->alloc, s->nb);
    plateau__free(&s->alloc, s->next);
    plateau__free(&s->alloc, s->lsign);
    plateau__free(&s->alloc, s->off);
    plateau__free(&s->alloc, s->loop);
    plateau__free(&s->alloc, s->cable_xyz);
    plateau__free(&s->alloc, s->cable_counts);
    plateau__free(&s->alloc, s->cable_seg);
    plateau__free(&s->alloc, s->cable_vtx);
    plateau__free(&s->alloc, s->cable_anchor);
    plateau__free(&s->alloc, s->cable_t);
}
/* ======== END SECTION: the configuration ================================== */

/* ======== SECTION: the mesh kernel (plateau__geo_) ======================== */
/* The mesh with its adjacency, and the geometry every step uses: areas,
 * normals, dihedral angles, the discrete mean curvature and its exact
 * derivatives, the tangential residual, the residual system. */
static const double *plateau__geo_pos(const plateau_mesh *mesh, plateau_index v)
{
    return mesh->positions + 3 * (size_t)v;
}

static void plateau__geo_free_adjacency(plateau_mesh *mesh)
{
    const plateau_allocator *a = &mesh->allocator;
    plateau__free(a, mesh->edges);
    plateau__free(a, mesh->edge_triangles);
    plateau__free(a, mesh->triangle_edges);
    plateau__free(a, mesh->vertex_edge_start);
    plateau__free(a, mesh->vertex_edges);
    plateau__free(a, mesh->vertex_triangle_start);
    plateau__free(a, mesh->vertex_triangles);
    mesh->num_edges = 0;
    mesh->edges = NULL;
    mesh->edge_triangles = NULL;
    mesh->triangle_edges = NULL;
    mesh->vertex_edge_start = NULL;
    mesh->vertex_edges = NULL;
    mesh->vertex_triangle_start = NULL;
    mesh->vertex_triangles = NULL;
}

PLATEAU_DEF void plateau_mesh_free(plateau_mesh *mesh)
{
    plateau_allocator a;
    if (!mesh) return;
    plateau__geo_free_adjacency(mesh);
    a = mesh->allocator;
    plateau__free(&a, mesh->positions);
    plateau__free(&a, mesh->fixed);
    plateau__free(&a, mesh->triangles);
    plateau__free(&a, mesh->neighbors);
    memset(mesh, 0, sizeof *mesh);
}

/* The half-edges of a mesh (3t + k runs v_k -> v_(k+1)%3) paired into
 * edges: the scratch of plateau_mesh_build_adjacency. */
typedef struct plateau__geo_halfedges {
    size_t *bucket_start;    /* nv + 1 */
    plateau_index *bucket;   /* nh: the half-edges by smaller endpoint */
    plateau_index *mark;     /* nv: the bucket that last saw a vertex */
    plateau_index *first;    /* nv: the edge of that bucket and vertex */
    plateau_index *he_edge;  /* nh: the edge of each half-edge */
    plateau_index *edge_he;  /* 2 nh: the half-edges of each edge (-1: none) */
    size_t ne;               /* edges */
} plateau__geo_halfedges;

/* Pairs the half-edges in O(V + T): bucketed by their smaller endpoint
 * (counting sort), and inside a bucket a per-vertex mark pairs those with
 * the same other endpoint.  PLATEAU_ERR_NON_MANIFOLD (a third half-edge
 * on an edge) or PLATEAU_ERR_ORIENTATION (two triangles running their
 * edge the same way), *bad the triangle and *msg the message. */
static plateau_result plateau__geo_pair_edges(const plateau_mesh *mesh, plateau__geo_halfedges *he,
                                              long *bad, const char **msg)
{
    size_t nv = mesh->num_vertices, nh = 3 * mesh->num_triangles, i, e;
    const plateau_index *tri = mesh->triangles;
    for (i = 0; i <= nv; i++) he->bucket_start[i] = 0;
    for (i = 0; i < nh; i++) {
        plateau_index p = tri[i], q = tri[i - i % 3 + (i % 3 + 1) % 3];
        he->bucket_start[(size_t)(p < q ? p : q) + 1]++;
    }
    for (i = 0; i < nv; i++) he->bucket_start[i + 1] += he->bucket_start[i];
    for (i = 0; i < nv; i++) { he->mark[i] = -1; he->first[i] = -1; }
    for (i = 0; i < nh; i++) {
        plateau_index p = tri[i], q = tri[i - i % 3 + (i % 3 + 1) % 3];
        size_t lo = (size_t)(p < q ? p : q);
        he->bucket[he->bucket_start[lo]++] = (plateau_index)i;
    }
    for (i = nv; i > 0; i--) he->bucket_start[i] = he->bucket_start[i - 1];
    he->bucket_start[0] = 0;
    he->ne = 0;
    for (i = 0; i < nv; i++) {
        size_t j;
        for (j = he->bucket_start[i]; j < he->bucket_start[i + 1]; j++) {
            size_t h = (size_t)he->bucket[j];
            plateau_index p = tri[h], q = tri[h - h % 3 + (h % 3 + 1) % 3];
            plateau_index w = (p == (plateau_index)i) ? q : p;
            if (he->mark[w] != (plateau_index)i) {
                he->mark[w] = (plateau_index)i;
                he->first[w] = (plateau_index)he->ne;
                he->he_edge[h] = (plateau_index)he->ne;
                he->edge_he[2 * he->ne] = (plateau_index)h;
                he->edge_he[2 * he->ne + 1] = -1;
                he->ne++;
            } else {
                e = (size_t)he->first[w];
                he->he_edge[h] = (plateau_index)e;
                if (he->edge_he[2 * e + 1] >= 0) {
                    *bad = (long)(h / 3);
                    *msg = "an edge has more than two triangles";
                    return PLATEAU_ERR_NON_MANIFOLD;
                }
                he->edge_he[2 * e + 1] = (plateau_index)h;
            }
        }
    }
    /* consistent orientation: the two half-edges of an edge run opposite ways */
    for (e = 0; e < he->ne; e++) {
        plateau_index h0 = he->edge_he[2 * e], h1 = he->edge_he[2 * e + 1];
        if (h1 >= 0 && tri[h0] == tri[h1]) {
            long t0 = (long)(h0 / 3), t1 = (long)(h1 / 3);
            *bad = t0 > t1 ? t0 : t1;
            *msg = "two neighbouring triangles run their shared edge the same way";
            return PLATEAU_ERR_ORIENTATION;
        }
    }
    return PLATEAU_OK;
}

/* The mesh's adjacency arrays from the paired half-edges: the edges and
 * their triangles, each triangle's edges and neighbours, and the
 * per-vertex lists of edges and triangles (CSR, increasing order). */
static plateau_result plateau__geo_fill_adjacency(plateau_mesh *mesh, const plateau__geo_halfedges *he)
{
    const plateau_allocator *a = &mesh->allocator;
    size_t nv = mesh->num_vertices, nh = 3 * mesh->num_triangles, ne = he->ne, i, e;
    mesh->edges = (plateau_index *)plateau__util_array(a, 2 * ne, sizeof(plateau_index));
    mesh->edge_triangles = (plateau_index *)plateau__util_array(a, 2 * ne, sizeof(plateau_index));
    mesh->triangle_edges = (plateau_index *)plateau__util_array(a, nh, sizeof(plateau_index));
    mesh->vertex_edge_start = (size_t *)plateau__util_array(a, nv + 1, sizeof(size_t));
    mesh->vertex_edges = (plateau_index *)plateau__util_array(a, 2 * ne, sizeof(plateau_index));
    mesh->vertex_triangle_start = (size_t *)plateau__util_array(a, nv + 1, sizeof(size_t));
    mesh->vertex_triangles = (plateau_index *)plateau__util_array(a, nh, sizeof(plateau_index));
    if (!mesh->edges || !mesh->edge_triangles || !mesh->triangle_edges ||
        !mesh->vertex_edge_start || !mesh->vertex_edges || !mesh->vertex_triangle_start ||
        !mesh->vertex_triangles)
        return PLATEAU_ERR_OUT_OF_MEMORY;
    mesh->num_edges = ne;
    for (e = 0; e < ne; e++) {
        size_t h0 = (size_t)he->edge_he[2 * e];
        plateau_index h1 = he->edge_he[2 * e + 1];
        mesh->edges[2 * e] = mesh->triangles[h0];
        mesh->edges[2 * e + 1] = mesh->triangles[h0 - h0 % 3 + (h0 % 3 + 1) % 3];
        mesh->edge_triangles[2 * e] = (plateau_index)(h0 / 3);
        mesh->edge_triangles[2 * e + 1] = h1 >= 0 ? (plateau_index)(h1 / 3) : -1;
    }
    for (i = 0; i < nh; i++) {
        size_t ed = (size_t)he->he_edge[i];
        plateau_index h0 = he->edge_he[2 * ed], h1 = he->edge_he[2 * ed + 1];
        plateau_index twin = (h0 == (plateau_index)i) ? h1 : h0;
        mesh->triangle_edges[i] = (plateau_index)ed;
        mesh->neighbors[i] = twin >= 0 ? twin / 3 : -1;
    }
    for (i = 0; i <= nv; i++) { mesh->vertex_edge_start[i] = 0; mesh->vertex_triangle_start[i] = 0; }
    for (e = 0; e < ne; e++) {
        mesh->vertex_edge_start[(size_t)mesh->edges[2 * e] + 1]++;
        mesh->vertex_edge_start[(size_t)mesh->edges[2 * e + 1] + 1]++;
    }
    for (i = 0; i < nh; i++) mesh->vertex_triangle_start[(size_t)mesh->triangles[i] + 1]++;
    for (i = 0; i < nv; i++) {
        mesh->vertex_edge_start[i + 1] += mesh->vertex_edge_start[i];
        mesh->vertex_triangle_start[i + 1] += mesh->vertex_triangle_start[i];
    }
    for (e = 0; e < ne; e++) {
        int s;
        for (s = 0; s < 2; s++) {
            size_t v = (size_t)mesh->edges[2 * e + (size_t)s];
            mesh->vertex_edges[mesh->vertex_edge_start[v]++] = (plateau_index)e;
        }
    }
    for (i = 0; i < nh; i++) {
        size_t v = (size_t)mesh->triangles[i];
        mesh->vertex_triangles[mesh->vertex_triangle_start[v]++] = (plateau_index)(i / 3);
    }
    for (i = nv; i > 0; i--) {
        mesh->vertex_edge_start[i] = mesh->vertex_edge_start[i - 1];
        mesh->vertex_triangle_start[i] = mesh->vertex_triangle_start[i - 1];
    }
    mesh->vertex_edge_start[0] = 0;
    mesh->vertex_triangle_start[0] = 0;
    return PLATEAU_OK;
}

/* Adjacency in O(V + T): the triangles checked, their half-edges paired
 * (plateau__geo_pair_edges), the arrays filled (plateau__geo_fill_adjacency). */
PLATEAU_DEF plateau_result plateau_mesh_build_adjacency(plateau_mesh *mesh, plateau_error *err)
{
    const plateau_allocator *a;
    plateau__geo_halfedges he;
    size_t nv, nt, nh, i;
    plateau_result rc = PLATEAU_OK;
    long bad = -1;
    const char *msg = "out of memory while building the adjacency";

    if (!mesh || !mesh->positions || !mesh->triangles || !mesh->neighbors ||
        mesh->num_vertices == 0 || mesh->num_triangles == 0) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the mesh has no vertices or triangles", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    a = &mesh->allocator;
    plateau__geo_free_adjacency(mesh);
    nv = mesh->num_vertices;
    nt = mesh->num_triangles;
    if (nv > (size_t)PLATEAU_INDEX_MAX || nt > (size_t)PLATEAU_INDEX_MAX / 3) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many vertices or triangles for plateau_index", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    nh = 3 * nt;
    for (i = 0; i < nt; i++) {
        const plateau_index *t = mesh->triangles + 3 * i;
        int k;
        for (k = 0; k < 3; k++) {
            if (t[k] < 0 || (size_t)t[k] >= nv) {
                plateau__util_error(err, PLATEAU_ERR_INDEX_RANGE, (long)i,
                                    "a triangle names a vertex index out of range", 0, 0);
                return PLATEAU_ERR_INDEX_RANGE;
            }
        }
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
            plateau__util_error(err, PLATEAU_ERR_DEGENERATE_TRIANGLE, (long)i,
                                "a triangle repeats a vertex", 0, 0);
            return PLATEAU_ERR_DEGENERATE_TRIANGLE;
        }
    }
    he.bucket_start = (size_t *)plateau__util_array(a, nv + 1, sizeof(size_t));
    he.bucket = (plateau_index *)plateau__util_array(a, nh, sizeof(plateau_index));
    he.mark = (plateau_index *)plateau__util_array(a, nv, sizeof(plateau_index));
    he.first = (plateau_index *)plateau__util_array(a, nv, sizeof(plateau_index));
    he.he_edge = (plateau_index *)plateau__util_array(a, nh, sizeof(plateau_index));
    he.edge_he = (plateau_index *)plateau__util_array(a, 2 * nh, sizeof(plateau_index));
    if (!he.bucket_start || !he.bucket || !he.mark || !he.first || !he.he_edge || !he.edge_he)
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (rc == PLATEAU_OK) rc = plateau__geo_pair_edges(mesh, &he, &bad, &msg);
    if (rc == PLATEAU_OK) rc = plateau__geo_fill_adjacency(mesh, &he);
    plateau__free(a, he.bucket_start);
    plateau__free(a, he.bucket);
    plateau__free(a, he.mark);
    plateau__free(a, he.first);
    plateau__free(a, he.he_edge);
    plateau__free(a, he.edge_he);
    if (rc != PLATEAU_OK) {
        plateau__geo_free_adjacency(mesh);
        plateau__util_error(err, rc, bad, msg, 0, 0);
    }
#ifdef PLATEAU_SELF_CHECK
    /* every connectivity the library makes (plateau_mesh_create, the flips,
     * the vertex removal, the re-projection) passes through here */
    if (rc == PLATEAU_OK) {
        plateau_error ce;
        rc = plateau_mesh_self_check(mesh, &ce);
        if (rc != PLATEAU_OK && err) *err = ce;
    }
#endif
    return rc;
}

/* The invariants plateau_mesh_self_check tests; the first that fails is the
 * error (err->index the triangle, edge or vertex). */
PLATEAU_DEF plateau_result plateau_mesh_self_check(const plateau_mesh *mesh, plateau_error *err)
{
    size_t nv, nt, ne, t, e, v, j;
    int k;
    if (!mesh || !mesh->positions || !mesh->triangles || !mesh->neighbors ||
        !mesh->triangle_edges || !mesh->edges || !mesh->edge_triangles ||
        !mesh->vertex_edge_start || !mesh->vertex_edges || !mesh->vertex_triangle_start ||
        !mesh->vertex_triangles) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the mesh has no triangles or no adjacency", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    nv = mesh->num_vertices;
    nt = mesh->num_triangles;
    ne = mesh->num_edges;
    for (v = 0; v < 3 * nv; v++)
        if (!plateau__util_finite(mesh->positions[v])) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)(v / 3),
                               "vertex @ has a NaN or infinite coordinate", (long)(v / 3), 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    /* every triangle: three distinct vertices in range; across each edge
     * (a, b) a neighbour that runs it as (b, a) and names t back, or -1
     * and a boundary edge; its edge record joins a and b and names t on
     * the side of its direction */
    for (t = 0; t < nt; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        for (k = 0; k < 3; k++)
            if (tr[k] < 0 || (size_t)tr[k] >= nv) {
                plateau__util_error(err, PLATEAU_ERR_INDEX_RANGE, (long)t,
                                   "triangle @ has a vertex out of range", (long)t, 0);
                return PLATEAU_ERR_INDEX_RANGE;
            }
        if (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0]) {
            plateau__util_error(err, PLATEAU_ERR_DEGENERATE_TRIANGLE, (long)t,
                               "triangle @ repeats a vertex", (long)t, 0);
            return PLATEAU_ERR_DEGENERATE_TRIANGLE;
        }
        for (k = 0; k < 3; k++) {
            plateau_index a = tr[k], b = tr[(k + 1) % 3], u = mesh->neighbors[3 * t + (size_t)k];
            plateau_index te = mesh->triangle_edges[3 * t + (size_t)k];
            int q, back = 0;
            if (te < 0 || (size_t)te >= ne ||
                !((mesh->edges[2 * (size_t)te] == a && mesh->edges[2 * (size_t)te + 1] == b &&
                   mesh->edge_triangles[2 * (size_t)te] == (plateau_index)t) ||
                  (mesh->edges[2 * (size_t)te] == b && mesh->edges[2 * (size_t)te + 1] == a &&
                   mesh->edge_triangles[2 * (size_t)te + 1] == (plateau_index)t))) {
                plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)t,
                                   "the edge record of triangle @ does not match it", (long)t, 0);
                return PLATEAU_ERR_ARGUMENT;
            }
            if (u < 0) {
                if (mesh->edge_triangles[2 * (size_t)te] >= 0 &&
                    mesh->edge_triangles[2 * (size_t)te + 1] >= 0) {
                    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)t,
                                       "triangle @ has no neighbour across an interior edge", (long)t, 0);
                    return PLATEAU_ERR_ARGUMENT;
                }
                continue;
            }
            if ((size_t)u >= nt) {
                plateau__util_error(err, PLATEAU_ERR_INDEX_RANGE, (long)t,
                                   "triangle @ has a neighbour out of range", (long)t, 0);
                return PLATEAU_ERR_INDEX_RANGE;
            }
            for (q = 0; q < 3; q++) {
                const plateau_index *tu = mesh->triangles + 3 * (size_t)u;
                if (tu[q] == a && tu[(q + 1) % 3] == b) {
                    plateau__util_error(err, PLATEAU_ERR_ORIENTATION, (long)t,
                                       "triangles @ and @ run their edge the same way", (long)t, (long)u);
                    return PLATEAU_ERR_ORIENTATION;
                }
                if (tu[q] == b && tu[(q + 1) % 3] == a &&
                    mesh->neighbors[3 * (size_t)u + (size_t)q] == (plateau_index)t)
                    back = 1;
            }
            if (!back) {
                plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)t,
                                   "triangle @ and its neighbour @ do not name each other", (long)t, (long)u);
                return PLATEAU_ERR_ARGUMENT;
            }
        }
    }
    /* every edge is some triangle's; the vertex lists are ordered ranges
     * holding only incident edges and triangles */
    for (e = 0; e < ne; e++)
        if (mesh->edge_triangles[2 * e] < 0 && mesh->edge_triangles[2 * e + 1] < 0) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)e, "edge @ has no triangle", (long)e, 0);
            return PLATEAU_ERR_ARGUMENT;
        }
    if (mesh->vertex_edge_start[0] != 0 || mesh->vertex_edge_start[nv] != 2 * ne ||
        mesh->vertex_triangle_start[0] != 0 || mesh->vertex_triangle_start[nv] != 3 * nt) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the vertex lists do not cover the mesh", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (v = 0; v < nv; v++) {
        if (mesh->vertex_edge_start[v] > mesh->vertex_edge_start[v + 1] ||
            mesh->vertex_triangle_start[v] > mesh->vertex_triangle_start[v + 1]) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)v,
                               "the lists of vertex @ are out of order", (long)v, 0);
            return PLATEAU_ERR_ARGUMENT;
        }
        for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
            plateau_index ed = mesh->vertex_edges[j];
            if (ed < 0 || (size_t)ed >= ne ||
                (mesh->edges[2 * (size_t)ed] != (plateau_index)v &&
                 mesh->edges[2 * (size_t)ed + 1] != (plateau_index)v)) {
                plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)v,
                                   "vertex @ lists an edge it is not on", (long)v, 0);
                return PLATEAU_ERR_ARGUMENT;
            }
        }
        for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
            plateau_index tt = mesh->vertex_triangles[j];
            const plateau_index *tr;
            if (tt < 0 || (size_t)tt >= nt) {
                plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)v,
                                   "vertex @ lists a triangle out of range", (long)v, 0);
                return PLATEAU_ERR_ARGUMENT;
            }
            tr = mesh->triangles + 3 * (size_t)tt;
            if (tr[0] != (plateau_index)v && tr[1] != (plateau_index)v && tr[2] != (plateau_index)v) {
                plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)v,
                                   "vertex @ lists a triangle it is not in", (long)v, 0);
                return PLATEAU_ERR_ARGUMENT;
            }
        }
    }
    return plateau__util_ok(err);
}

PLATEAU_DEF plateau_result plateau_mesh_create(const double *positions, size_t num_vertices,
                                               const unsigned char *fixed,
                                               const plateau_index *triangles,
                                               size_t num_triangles,
                                               const plateau_allocator *allocator,
                                               plateau_mesh *mesh, plateau_error *err)
{
    size_t i, bp, bt;
    plateau_result rc;
    if (mesh) memset(mesh, 0, sizeof *mesh);
    if (!mesh || !positions || !triangles || num_vertices < 3 || num_triangles == 0 ||
        !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                               "plateau_mesh_create needs a mesh, >= 3 vertices, >= 1 triangle and a valid allocator", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    bp = plateau__bytes(num_vertices, 3 * sizeof(double));
    bt = plateau__bytes(num_triangles, 3 * sizeof(plateau_index));
    if (bp == 0 || bt == 0 || num_vertices > (size_t)PLATEAU_INDEX_MAX ||
        num_triangles > (size_t)PLATEAU_INDEX_MAX / 3) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many vertices or triangles", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    for (i = 0; i < 3 * num_vertices; i++) {
        double x = positions[i];
        if (!(x - x == 0.0)) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)(i / 3),
                                   "a vertex coordinate is NaN or infinite", 0, 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    }
    if (allocator) mesh->allocator = *allocator;
    mesh->num_vertices = num_vertices;
    mesh->num_triangles = num_triangles;
    mesh->positions = (double *)plateau__alloc(&mesh->allocator, bp);
    mesh->fixed = (unsigned char *)plateau__alloc(&mesh->allocator, num_vertices);
    mesh->triangles = (plateau_index *)plateau__alloc(&mesh->allocator, bt);
    mesh->neighbors = (plateau_index *)plateau__alloc(&mesh->allocator, bt);
    if (!mesh->positions || !mesh->fixed || !mesh->triangles || !mesh->neighbors) {
        plateau_mesh_free(mesh);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory while creating the mesh", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    memcpy(mesh->positions, positions, bp);
    memcpy(mesh->triangles, triangles, bt);
    rc = plateau_mesh_build_adjacency(mesh, err);
    if (rc != PLATEAU_OK) {
        plateau_mesh_free(mesh);
        return rc;
    }
    if (fixed) {
        for (i = 0; i < num_vertices; i++) mesh->fixed[i] = (unsigned char)(fixed[i] != 0);
    } else {
        for (i = 0; i < num_vertices; i++) mesh->fixed[i] = 0;
        for (i = 0; i < mesh->num_edges; i++) {
            if (mesh->edge_triangles[2 * i + 1] < 0) {
                mesh->fixed[mesh->edges[2 * i]] = 1;
                mesh->fixed[mesh->edges[2 * i + 1]] = 1;
            }
        }
    }
    plateau__util_ok(err);
    return PLATEAU_OK;
}

/* ---- areas, normals, lengths ---- */
/* Unnormalised normal (p1 - p0) x (p2 - p0) of triangle t (twice its area). */
static void plateau__geo_tri_cross(const plateau_mesh *mesh, size_t t, double *n)
{
    const plateau_index *tr = mesh->triangles + 3 * t;
    plateau__util_corner_cross(plateau__geo_pos(mesh, tr[0]), plateau__geo_pos(mesh, tr[1]),
                              plateau__geo_pos(mesh, tr[2]), n);
}

PLATEAU_DEF double plateau_triangle_area(const plateau_mesh *mesh, size_t t)
{
    double n[3];
    plateau__geo_tri_cross(mesh, t, n);
    return 0.5 * plateau__util_norm(n);
}

PLATEAU_DEF double plateau_triangle_normal(const plateau_mesh *mesh, size_t t, double normal[3])
{
    double n[3], len;
    plateau__geo_tri_cross(mesh, t, n);
    len = plateau__util_norm(n);
    if (len > 0.0) {
        normal[0] = n[0] / len; normal[1] = n[1] / len; normal[2] = n[2] / len;
    } else {
        normal[0] = normal[1] = normal[2] = 0.0;
    }
    return 0.5 * len;
}

PLATEAU_DEF double plateau_vertex_area(const plateau_mesh *mesh, size_t v)
{
    double s = 0.0;
    size_t j;
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++)
        s += plateau_triangle_area(mesh, (size_t)mesh->vertex_triangles[j]);
    return s / 3.0;
}

PLATEAU_DEF double plateau_mesh_area(const plateau_mesh *mesh)
{
    double s = 0.0;
    size_t t;
    for (t = 0; t < mesh->num_triangles; t++) s += plateau_triangle_area(mesh, t);
    return s;
}

PLATEAU_DEF double plateau_edge_length(const plateau_mesh *mesh, size_t e)
{
    double d[3];
    plateau__util_sub(plateau__geo_pos(mesh, mesh->edges[2 * e + 1]),
                     plateau__geo_pos(mesh, mesh->edges[2 * e]), d);
    return plateau__util_norm(d);
}

PLATEAU_DEF double plateau_mean_edge_length(const plateau_mesh *mesh)
{
    double s = 0.0;
    size_t e;
    if (mesh->num_edges == 0) return 0.0;
    for (e = 0; e < mesh->num_edges; e++) s += plateau_edge_length(mesh, e);
    return s / (double)mesh->num_edges;
}

/* Unnormalised vertex normal N = sum of (p1 - p0) x (p2 - p0) over v's triangles. */
static void plateau__geo_vertex_cross(const plateau_mesh *mesh, size_t v, double *n)
{
    size_t j;
    n[0] = n[1] = n[2] = 0.0;
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
        double c[3];
        plateau__geo_tri_cross(mesh, (size_t)mesh->vertex_triangles[j], c);
        n[0] += c[0]; n[1] += c[1]; n[2] += c[2];
    }
}

PLATEAU_DEF double plateau_vertex_normal(const plateau_mesh *mesh, size_t v, double normal[3])
{
    double n[3], len;
    plateau__geo_vertex_cross(mesh, v, n);
    len = plateau__util_norm(n);
    if (len > 0.0) {
        normal[0] = n[0] / len; normal[1] = n[1] / len; normal[2] = n[2] / len;
    } else {
        normal[0] = normal[1] = normal[2] = 0.0;
    }
    return len;
}

/* ---- dihedral angle (paper II.B, Fig. 4) and its derivative (examples/NOTES.md,
 * the well-conditioned replacement of the paper's formula (3)) ---- */
/* The vertex of triangle t that is not on the edge (a, b). */
static plateau_index plateau__geo_opposite(const plateau_mesh *mesh, plateau_index t,
                                           plateau_index a, plateau_index b)
{
    const plateau_index *tr = mesh->triangles + 3 * (size_t)t;
    int k;
    for (k = 0; k < 3; k++)
        if (tr[k] != a && tr[k] != b) return tr[k];
    return -1;
}

static double plateau__geo_dihedral(const plateau_mesh *mesh, size_t e, double *grad,
                                    plateau_index *verts)
{
    plateau_index a = mesh->edges[2 * e], b = mesh->edges[2 * e + 1];
    plateau_index t1 = mesh->edge_triangles[2 * e], t2 = mesh->edge_triangles[2 * e + 1];
    plateau_index c, d;
    const double *pa, *pb, *pc, *pd;
    double ab[3], ac[3], ad[3], N1[3], N2[3], n1[3], n2[3], m[3], len1, len2, l, l2;
    double h1, h2, tc, td, beta;
    int j;
    if (verts) { verts[0] = a; verts[1] = b; verts[2] = -1; verts[3] = -1; }
    if (grad) for (j = 0; j < 12; j++) grad[j] = 0.0;
    if (t2 < 0) return 0.0;
    c = plateau__geo_opposite(mesh, t1, a, b);
    d = plateau__geo_opposite(mesh, t2, a, b);
    if (verts) { verts[2] = c; verts[3] = d; }
    pa = plateau__geo_pos(mesh, a); pb = plateau__geo_pos(mesh, b);
    pc = plateau__geo_pos(mesh, c); pd = plateau__geo_pos(mesh, d);
    plateau__util_sub(pb, pa, ab);
    plateau__util_sub(pc, pa, ac);
    plateau__util_sub(pd, pa, ad);
    /* N1 = (b - a) x (c - a); N2 = (a - b) x (d - b) = (d - a) x (b - a) */
    plateau__util_cross(ab, ac, N1);
    plateau__util_cross(ad, ab, N2);
    len1 = plateau__util_norm(N1);
    len2 = plateau__util_norm(N2);
    l2 = plateau__util_dot(ab, ab);
    l = PLATEAU_SQRT(l2);
    if (!(len1 > 0.0) || !(len2 > 0.0) || !(l > 0.0)) return 0.0;
    for (j = 0; j < 3; j++) { n1[j] = N1[j] / len1; n2[j] = N2[j] / len2; }
    plateau__util_cross(n1, n2, m);
    beta = PLATEAU_ATAN2(plateau__util_dot(m, ab) / l, plateau__util_dot(n1, n2));
    if (grad) {
        h1 = len1 / l;
        h2 = len2 / l;
        tc = plateau__util_dot(ac, ab) / l2;
        td = plateau__util_dot(ad, ab) / l2;
        for (j = 0; j < 3; j++) {
            double g1 = n1[j] / h1, g2 = n2[j] / h2;
            grad[j] = (1.0 - tc) * g1 + (1.0 - td) * g2; /* a */
            grad[3 + j] = tc * g1 + td * g2;             /* b */
            grad[6 + j] = -g1;                           /* c */
            grad[9 + j] = -g2;                           /* d */
        }
    }
    return beta;
}

PLATEAU_DEF double plateau_edge_dihedral(const plateau_mesh *mesh, size_t e)
{
    return plateau__geo_dihedral(mesh, e, NULL, NULL);
}

PLATEAU_DEF double plateau_edge_dihedral_gradient(const plateau_mesh *mesh, size_t e,
                                                  plateau_index vertices[4],
                                                  double gradient[12])
{
    return plateau__geo_dihedral(mesh, e, gradient, vertices);
}

/* ---- discrete mean curvature H_v (paper II.B) and its gradient (paper
 * formula (2)) ---- */
PLATEAU_DEF double plateau_vertex_mean_curvature(const plateau_mesh *mesh, size_t v)
{
    double s = 0.0, area = plateau_vertex_area(mesh, v);
    size_t j;
    for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
        size_t e = (size_t)mesh->vertex_edges[j];
        if (mesh->edge_triangles[2 * e + 1] < 0) continue;
        s += plateau_edge_dihedral(mesh, e) * plateau_edge_length(mesh, e) * 0.5;
    }
    return area > 0.0 ? s / area : 0.0;
}

PLATEAU_DEF size_t plateau_vertex_stencil_size(const plateau_mesh *mesh, size_t v)
{
    return 1 + (mesh->vertex_edge_start[v + 1] - mesh->vertex_edge_start[v]);
}

/* Fills vertices[] with v and its neighbours (edge order); returns the count. */
static size_t plateau__geo_stencil(const plateau_mesh *mesh, size_t v, plateau_index *vertices)
{
    size_t j, n = 1;
    vertices[0] = (plateau_index)v;
    for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
        size_t e = (size_t)mesh->vertex_edges[j];
        plateau_index w = mesh->edges[2 * e] == (plateau_index)v ? mesh->edges[2 * e + 1]
                                                                  : mesh->edges[2 * e];
        vertices[n++] = w;
    }
    return n;
}

static size_t plateau__geo_slot(const plateau_index *vertices, size_t n, plateau_index w)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (vertices[k] == w) return k;
    return n; /* not in the stencil: cannot happen on a valid mesh */
}

/* The stencil slot of w, a vertex of triangle t of v (the stencil of
 * plateau__geo_stencil: v, then its neighbours in the order of v's edge
 * list), in O(log valence) instead of a scan of the stencil: the edge of t
 * joining v and w, found by binary search in v's edge list (increasing
 * edge order, as plateau_mesh_build_adjacency makes it), has the position
 * slot - 1.  So a vertex of any valence k costs O(k log k) per gradient,
 * not O(k^2).  Falls back to the scan when the lists are not as built.
 * slot_of (the system assembly's scratch, or NULL): the slot of every
 * stencil vertex, filled by plateau__geo_map_stencil. */
static size_t plateau__geo_slot_in(const plateau_mesh *mesh, size_t v, size_t t, plateau_index w,
                                   const plateau_index *vertices, size_t n, const plateau_index *slot_of)
{
    const plateau_index *tr = mesh->triangles + 3 * t;
    size_t lo = mesh->vertex_edge_start[v], hi = mesh->vertex_edge_start[v + 1], start = lo;
    plateau_index e = -1;
    int k;
    if (w == (plateau_index)v) return 0;
    if (slot_of) return (size_t)slot_of[w]; /* the system assembly's map: O(1) */
    for (k = 0; k < 3; k++) {
        plateau_index p = tr[k], q = tr[(k + 1) % 3];
        if ((p == (plateau_index)v && q == w) || (p == w && q == (plateau_index)v))
            e = mesh->triangle_edges[3 * t + (size_t)k];
    }
    while (e >= 0 && lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (mesh->vertex_edges[mid] < e) lo = mid + 1;
        else hi = mid;
    }
    if (e >= 0 && lo < mesh->vertex_edge_start[v + 1] && mesh->vertex_edges[lo] == e &&
        1 + (lo - start) < n && vertices[1 + (lo - start)] == w)
        return 1 + (lo - start);
    return plateau__geo_slot(vertices, n, w);
}

/* slot_of: NULL, or a scratch of num_vertices entries, all -1 on entry and
 * on return, that then maps each stencil vertex to its slot in O(1) (the
 * system assembly passes one). */
static void plateau__geo_map_stencil(plateau_index *slot_of, const plateau_index *vertices, size_t n,
                                     int set)
{
    size_t k;
    if (slot_of)
        for (k = 0; k < n; k++) slot_of[vertices[k]] = set ? (plateau_index)k : -1;
}

static plateau_result plateau__geo_hgrad(const plateau_mesh *mesh, size_t v, size_t capacity,
                                         plateau_index *vertices, double *gradient, size_t *count,
                                         double *h, plateau_index *slot_of);

PLATEAU_DEF plateau_result plateau_vertex_mean_curvature_gradient(const plateau_mesh *mesh,
                                                                  size_t v, size_t capacity,
                                                                  plateau_index *vertices,
                                                                  double *gradient,
                                                                  size_t *count, double *h)
{
    return plateau__geo_hgrad(mesh, v, capacity, vertices, gradient, count, h, NULL);
}

static plateau_result plateau__geo_hgrad(const plateau_mesh *mesh, size_t v, size_t capacity,
                                         plateau_index *vertices, double *gradient, size_t *count,
                                         double *h, plateau_index *slot_of)
{
    size_t need, n, j, k;
    double s = 0.0, area = 0.0, hv;
    if (!mesh || v >= mesh->num_vertices || !vertices || !gradient || !count)
        return PLATEAU_ERR_ARGUMENT;
    need = plateau_vertex_stencil_size(mesh, v);
    *count = need;
    if (capacity < need) return PLATEAU_ERR_ARGUMENT;
    n = plateau__geo_stencil(mesh, v, vertices);
    plateau__geo_map_stencil(slot_of, vertices, n, 1);
    for (k = 0; k < 3 * n; k++) gradient[k] = 0.0;
    /* dS, S = sum over interior edges of beta |e| / 2 */
    for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
        size_t e = (size_t)mesh->vertex_edges[j];
        plateau_index ev[4];
        double g[12], len, beta, dir[3];
        int q, c;
        if (mesh->edge_triangles[2 * e + 1] < 0) continue;
        size_t slots[4];
        beta = plateau__geo_dihedral(mesh, e, g, ev);
        len = plateau_edge_length(mesh, e);
        s += beta * len * 0.5;
        /* a and b: v and the neighbour of this edge; c and d: the third
         * vertices of the edge's two triangles */
        slots[0] = ev[0] == (plateau_index)v ? 0 : 1 + (j - mesh->vertex_edge_start[v]);
        slots[1] = ev[1] == (plateau_index)v ? 0 : 1 + (j - mesh->vertex_edge_start[v]);
        slots[2] = plateau__geo_slot_in(mesh, v, (size_t)mesh->edge_triangles[2 * e], ev[2], vertices, n, slot_of);
        slots[3] = plateau__geo_slot_in(mesh, v, (size_t)mesh->edge_triangles[2 * e + 1], ev[3], vertices, n, slot_of);
        for (q = 0; q < 4; q++) {
            size_t slot = slots[q];
            if (slot >= n) continue;
            for (c = 0; c < 3; c++) gradient[3 * slot + (size_t)c] += 0.5 * len * g[3 * q + c];
        }
        /* d|e|/da = (a - b)/|e|, d|e|/db = (b - a)/|e| */
        if (len > 0.0) {
            size_t sa = slots[0];
            size_t sb = slots[1];
            plateau__util_sub(plateau__geo_pos(mesh, ev[1]), plateau__geo_pos(mesh, ev[0]), dir);
            for (c = 0; c < 3; c++) {
                gradient[3 * sa + (size_t)c] -= 0.5 * beta * dir[c] / len;
                gradient[3 * sb + (size_t)c] += 0.5 * beta * dir[c] / len;
            }
        }
    }
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++)
        area += plateau_triangle_area(mesh, (size_t)mesh->vertex_triangles[j]);
    area /= 3.0;
    if (!(area > 0.0)) {
        for (k = 0; k < 3 * n; k++) gradient[k] = 0.0;
        if (h) *h = 0.0;
        plateau__geo_map_stencil(slot_of, vertices, n, 0);
        return PLATEAU_OK;
    }
    hv = s / area;
    /* dH = (dS - H d|B|) / |B|, d|B| = (1/3) sum dA_f, dA_f/dp_k = (1/2) n_f x (p_(k+2) - p_(k+1)) */
    for (k = 0; k < 3 * n; k++) gradient[k] /= area;
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
        size_t t = (size_t)mesh->vertex_triangles[j];
        const plateau_index *tr = mesh->triangles + 3 * t;
        double nf[3];
        int q, c;
        if (!(plateau_triangle_normal(mesh, t, nf) > 0.0)) continue;
        for (q = 0; q < 3; q++) {
            double opp[3], dA[3];
            size_t slot = plateau__geo_slot_in(mesh, v, t, tr[q], vertices, n, slot_of);
            plateau__util_sub(plateau__geo_pos(mesh, tr[(q + 2) % 3]),
                             plateau__geo_pos(mesh, tr[(q + 1) % 3]), opp);
            plateau__util_cross(nf, opp, dA);
            for (c = 0; c < 3; c++) gradient[3 * slot + (size_t)c] -= hv * (0.5 * dA[c] / 3.0) / area;
        }
    }
    if (h) *h = hv;
    plateau__geo_map_stencil(slot_of, vertices, n, 0);
    return PLATEAU_OK;
}

/* ---- mean curvature vector, Meyer-Desbrun-Schroeder-Barr 2003 ---- */
PLATEAU_DEF double plateau_vertex_mean_curvature_vector(const plateau_mesh *mesh, size_t v,
                                                        double k[3])
{
    double sum[3] = {0.0, 0.0, 0.0}, amix = 0.0, nv[3];
    size_t j;
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
        size_t t = (size_t)mesh->vertex_triangles[j];
        const plateau_index *tr = mesh->triangles + 3 * t;
        int q = tr[0] == (plateau_index)v ? 0 : (tr[1] == (plateau_index)v ? 1 : 2);
        const double *pi = plateau__geo_pos(mesh, tr[q]);
        const double *pj = plateau__geo_pos(mesh, tr[(q + 1) % 3]);
        const double *pk = plateau__geo_pos(mesh, tr[(q + 2) % 3]);
        double ij[3], ik[3], jk[3], cr[3], twice_area, cot_i, cot_j, cot_k, area;
        int c;
        plateau__util_sub(pj, pi, ij);
        plateau__util_sub(pk, pi, ik);
        plateau__util_sub(pk, pj, jk);
        plateau__util_cross(ij, ik, cr);
        twice_area = plateau__util_norm(cr);
        if (!(twice_area > 0.0)) continue;
        area = 0.5 * twice_area;
        cot_i = plateau__util_dot(ij, ik) / twice_area;
        cot_j = -plateau__util_dot(ij, jk) / twice_area; /* angle at j between j->i and j->k */
        cot_k = plateau__util_dot(ik, jk) / twice_area;  /* angle at k between k->i and k->j */
        /* edge (i, j) is opposite k; edge (i, k) is opposite j */
        for (c = 0; c < 3; c++) sum[c] += cot_k * (-ij[c]) + cot_j * (-ik[c]);
        if (cot_i < 0.0) {
            amix += area / 2.0; /* obtuse at v */
        } else if (cot_j < 0.0 || cot_k < 0.0) {
            amix += area / 4.0; /* obtuse elsewhere */
        } else {
            amix += (cot_k * plateau__util_dot(ij, ij) + cot_j * plateau__util_dot(ik, ik)) / 8.0;
        }
    }
    if (!(amix > 0.0)) {
        if (k) k[0] = k[1] = k[2] = 0.0;
        return 0.0;
    }
    sum[0] /= 2.0 * amix; sum[1] /= 2.0 * amix; sum[2] /= 2.0 * amix;
    if (k) { k[0] = sum[0]; k[1] = sum[1]; k[2] = sum[2]; }
    plateau_vertex_normal(mesh, v, nv);
    return plateau__util_dot(sum, nv);
}

/* ---- tangential residual (examples/NOTES.md) ---- */
/* Frame and residual: d = mean of neighbours - x_v; N the unnormalised
 * vertex normal; returns the axis index used for the frame, or -1. */
static int plateau__geo_frame(const plateau_mesh *mesh, size_t v, double *N, double *n,
                              double *t1, double *t2, double *u, double *d, size_t *ring)
{
    double len, ulen, ax[3] = {0.0, 0.0, 0.0};
    size_t j, cnt = 0;
    int axis, c;
    d[0] = d[1] = d[2] = 0.0;
    for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
        size_t e = (size_t)mesh->vertex_edges[j];
        plateau_index w = mesh->edges[2 * e] == (plateau_index)v ? mesh->edges[2 * e + 1]
                                                                  : mesh->edges[2 * e];
        const double *p = plateau__geo_pos(mesh, w);
        d[0] += p[0]; d[1] += p[1]; d[2] += p[2];
        cnt++;
    }
    *ring = cnt;
    if (cnt == 0) return -1;
    for (c = 0; c < 3; c++) d[c] = d[c] / (double)cnt - mesh->positions[3 * v + (size_t)c];
    plateau__geo_vertex_cross(mesh, v, N);
    len = plateau__util_norm(N);
    if (!(len > 0.0)) return -1;
    for (c = 0; c < 3; c++) n[c] = N[c] / len;
    axis = 0;
    if (PLATEAU_FABS(n[1]) < PLATEAU_FABS(n[axis])) axis = 1;
    if (PLATEAU_FABS(n[2]) < PLATEAU_FABS(n[axis])) axis = 2;
    ax[axis] = 1.0;
    plateau__util_cross(ax, n, u);
    ulen = plateau__util_norm(u);
    for (c = 0; c < 3; c++) t1[c] = u[c] / ulen;
    plateau__util_cross(n, t1, t2);
    return axis;
}

PLATEAU_DEF void plateau_vertex_tangential(const plateau_mesh *mesh, size_t v, double weight,
                                           double r[2])
{
    double N[3], n[3], t1[3], t2[3], u[3], d[3];
    size_t ring;
    if (plateau__geo_frame(mesh, v, N, n, t1, t2, u, d, &ring) < 0) {
        r[0] = r[1] = 0.0;
        return;
    }
    r[0] = weight * plateau__util_dot(d, t1);
    r[1] = weight * plateau__util_dot(d, t2);
}

/* Exact Jacobian: r1 = w d.t1, r2 = w d.t2 with
 * dn = (I - n n^T) dN / |N|, du = e x dn, dt1 = (I - t1 t1^T) du / |u|,
 * dt2 = dn x t1 + n x dt1, and dN/dp_k = (p_(k+2) - p_(k+1)) x (.) for each
 * triangle (p0, p1, p2) of v. */
static plateau_result plateau__geo_tgrad(const plateau_mesh *mesh, size_t v, double weight,
                                         size_t capacity, plateau_index *vertices, double *gradient,
                                         size_t *count, double r[2], plateau_index *slot_of);

PLATEAU_DEF plateau_result plateau_vertex_tangential_gradient(const plateau_mesh *mesh, size_t v,
                                                              double weight, size_t capacity,
                                                              plateau_index *vertices,
                                                              double *gradient, size_t *count,
                                                              double r[2])
{
    return plateau__geo_tgrad(mesh, v, weight, capacity, vertices, gradient, count, r, NULL);
}

/* slot_of as for plateau__geo_hgrad; with it (the system assembly, which
 * keeps only the free vertices' blocks) the slots of fixed vertices are
 * left zero: a free vertex among thousands of fixed neighbours costs O(k)
 * for its two rows, not 6 k outputs of O(1) each on top */
static plateau_result plateau__geo_tgrad(const plateau_mesh *mesh, size_t v, double weight,
                                         size_t capacity, plateau_index *vertices, double *gradient,
                                         size_t *count, double r[2], plateau_index *slot_of)
{
    double N[3], n[3], t1[3], t2[3], u[3], d[3], lenN, lenu, ax[3] = {0.0, 0.0, 0.0};
    size_t need, nst, ring, s, j;
    int axis;
    if (!mesh || v >= mesh->num_vertices || !vertices || !gradient || !count)
        return PLATEAU_ERR_ARGUMENT;
    need = plateau_vertex_stencil_size(mesh, v);
    *count = need;
    if (capacity < need) return PLATEAU_ERR_ARGUMENT;
    nst = plateau__geo_stencil(mesh, v, vertices);
    for (j = 0; j < 6 * nst; j++) gradient[j] = 0.0;
    axis = plateau__geo_frame(mesh, v, N, n, t1, t2, u, d, &ring);
    if (axis < 0) {
        if (r) r[0] = r[1] = 0.0;
        return PLATEAU_OK;
    }
    plateau__geo_map_stencil(slot_of, vertices, nst, 1);
    if (r) {
        r[0] = weight * plateau__util_dot(d, t1);
        r[1] = weight * plateau__util_dot(d, t2);
    }
    ax[axis] = 1.0;
    lenN = plateau__util_norm(N);
    lenu = plateau__util_norm(u);
    /* dN/dp_w e_c = sum over the triangles of v holding w of opp x e_c, opp
     * the edge facing w: first the sums of opp for every stencil vertex in
     * one pass over the triangles (into gradient[6 s .. 6 s + 2], read back
     * below before the slot is written), so that a vertex of valence k
     * costs O(k log k), not O(k^2) */
    for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
        size_t t = (size_t)mesh->vertex_triangles[j];
        const plateau_index *tr = mesh->triangles + 3 * t;
        int q;
        for (q = 0; q < 3; q++) {
            double opp[3];
            size_t slot = plateau__geo_slot_in(mesh, v, t, tr[q], vertices, nst, slot_of);
            if (slot >= nst || (slot_of && mesh->fixed[tr[q]])) continue;
            plateau__util_sub(plateau__geo_pos(mesh, tr[(q + 2) % 3]),
                             plateau__geo_pos(mesh, tr[(q + 1) % 3]), opp);
            gradient[6 * slot] += opp[0];
            gradient[6 * slot + 1] += opp[1];
            gradient[6 * slot + 2] += opp[2];
        }
    }
    plateau__geo_map_stencil(slot_of, vertices, nst, 0);
    for (s = 0; s < nst; s++) {
        double cd = (s == 0) ? -1.0 : 1.0 / (double)ring; /* d d / d p_w = cd I */
        double opp[3];
        int c;
        if (slot_of && mesh->fixed[vertices[s]]) continue;
        opp[0] = gradient[6 * s];
        opp[1] = gradient[6 * s + 1];
        opp[2] = gradient[6 * s + 2];
        for (c = 0; c < 3; c++) {
            double dN[3], dn[3], du[3], dt1[3], dt2[3], tmp[3], tmp2[3], ec[3];
            double a;
            int q;
            ec[0] = ec[1] = ec[2] = 0.0;
            ec[c] = 1.0;
            plateau__util_cross(opp, ec, dN);
            a = plateau__util_dot(n, dN);
            for (q = 0; q < 3; q++) dn[q] = (dN[q] - a * n[q]) / lenN;
            plateau__util_cross(ax, dn, du);
            a = plateau__util_dot(t1, du);
            for (q = 0; q < 3; q++) dt1[q] = (du[q] - a * t1[q]) / lenu;
            plateau__util_cross(dn, t1, tmp);
            plateau__util_cross(n, dt1, tmp2);
            for (q = 0; q < 3; q++) dt2[q] = tmp[q] + tmp2[q];
            gradient[6 * s + (size_t)c] = weight * (cd * t1[c] + plateau__util_dot(d, dt1));
            gradient[6 * s + 3 + (size_t)c] = weight * (cd * t2[c] + plateau__util_dot(d, dt2));
        }
    }
    return PLATEAU_OK;
}

/* ---- area gradient (paper II.C.1) ---- */
PLATEAU_DEF void plateau_mesh_area_gradient(const plateau_mesh *mesh, double *gradient)
{
    size_t t, i;
    for (i = 0; i < 3 * mesh->num_vertices; i++) gradient[i] = 0.0;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double nf[3];
        int q;
        if (!(plateau_triangle_normal(mesh, t, nf) > 0.0)) continue;
        for (q = 0; q < 3; q++) {
            double opp[3], g[3];
            plateau__util_sub(plateau__geo_pos(mesh, tr[(q + 2) % 3]),
                             plateau__geo_pos(mesh, tr[(q + 1) % 3]), opp);
            plateau__util_cross(nf, opp, g);
            gradient[3 * (size_t)tr[q]] += 0.5 * g[0];
            gradient[3 * (size_t)tr[q] + 1] += 0.5 * g[1];
            gradient[3 * (size_t)tr[q] + 2] += 0.5 * g[2];
        }
    }
}

/* ---- membranes: the cone volume and the energy area - p V + sum T |s| ---- */
/* scale times the signed volume of the cone from apex (NULL: the origin)
 * over the triangles, V = sum r_0 . (r_1 x r_2) / 6 with r_q = x_q - apex,
 * added into *sum triangle by triangle, and scale times its gradient into
 * gradient (may be NULL): dV/dr_q = r_(q+1) x r_(q+2) / 6. */
static void plateau__geo_volume_add(const plateau_mesh *mesh, const double apex[3], double scale,
                                    double *sum, double *gradient)
{
    static const double origin[3] = {0.0, 0.0, 0.0};
    const double *o = apex ? apex : origin;
    size_t t;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double r[3][3], c[3];
        int q, k;
        for (q = 0; q < 3; q++) plateau__util_sub(plateau__geo_pos(mesh, tr[q]), o, r[q]);
        plateau__util_cross(r[1], r[2], c);
        *sum += scale * plateau__util_dot(r[0], c) / 6.0;
        if (!gradient) continue;
        for (q = 0; q < 3; q++) {
            double g[3];
            plateau__util_cross(r[(q + 1) % 3], r[(q + 2) % 3], g);
            for (k = 0; k < 3; k++) gradient[3 * (size_t)tr[q] + (size_t)k] += scale * g[k] / 6.0;
        }
    }
}

PLATEAU_DEF double plateau_mesh_volume(const plateau_mesh *mesh, const double apex[3], double *gradient)
{
    double vol = 0.0;
    size_t i;
    if (gradient)
        for (i = 0; i < 3 * mesh->num_vertices; i++) gradient[i] = 0.0;
    plateau__geo_volume_add(mesh, apex, 1.0, &vol, gradient);
    return vol;
}

/* The cable term sum T_s |s| and its gradient added into gradient (may be
 * NULL): d|b - a|/db = (b - a) / |b - a|. */
static double plateau__geo_cable_energy(const plateau_mesh *mesh, const plateau_index *segments,
                                        const double *tensions, size_t num_segments, double *gradient)
{
    double e = 0.0;
    size_t s;
    for (s = 0; s < num_segments; s++) {
        plateau_index a = segments[2 * s], b = segments[2 * s + 1];
        double d[3], len;
        int k;
        plateau__util_sub(plateau__geo_pos(mesh, b), plateau__geo_pos(mesh, a), d);
        len = plateau__util_norm(d);
        e += tensions[s] * len;
        if (!gradient || !(len > 0.0)) continue;
        for (k = 0; k < 3; k++) {
            gradient[3 * (size_t)b + (size_t)k] += tensions[s] * d[k] / len;
            gradient[3 * (size_t)a + (size_t)k] -= tensions[s] * d[k] / len;
        }
    }
    return e;
}

PLATEAU_DEF double plateau_membrane_energy(const plateau_mesh *mesh, double pressure, const double apex[3],
                                           const plateau_index *segments, const double *tensions,
                                           size_t num_segments, double *gradient)
{
    double e = plateau_mesh_area(mesh);
    if (gradient) plateau_mesh_area_gradient(mesh, gradient);
    if (pressure != 0.0) plateau__geo_volume_add(mesh, apex, -pressure, &e, gradient); /* - p V */
    if (segments && tensions && num_segments > 0)
        e += plateau__geo_cable_energy(mesh, segments, tensions, num_segments, gradient);
    return e;
}

/* ---- area Hessian on normal motions (Surface Evolver's hessian_normal) ---- */

/* Direction m_v of vertex v: directions[3v..] or the unit vertex normal. */
static void plateau__geo_direction(const plateau_mesh *mesh, const double *directions, size_t v,
                                   double m[3])
{
    if (directions) {
        m[0] = directions[3 * v];
        m[1] = directions[3 * v + 1];
        m[2] = directions[3 * v + 2];
    } else {
        plateau_vertex_normal(mesh, v, m);
    }
}

PLATEAU_DEF plateau_result plateau_mesh_area_hessian_normal(const plateau_mesh *mesh,
                                                            const double *directions,
                                                            double *gradient, double *diagonal,
                                                            double *off_diagonal,
                                                            plateau_error *err)
{
    size_t t, v, e;
    if (!mesh || (mesh->num_triangles > 0 && !mesh->triangle_edges) ||
        (!diagonal) != (!off_diagonal)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "area Hessian: no mesh or adjacency, or one Hessian array alone",
                            0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (v = 0; v < mesh->num_vertices; v++) {
        if (gradient) gradient[v] = 0.0;
        if (diagonal) diagonal[v] = 0.0;
    }
    for (e = 0; off_diagonal && e < mesh->num_edges; e++) off_diagonal[e] = 0.0;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double e1[3], e2[3], nv[3], len, m[3][3], a[3][3], na[3];
        int i;
        plateau__util_sub(plateau__geo_pos(mesh, tr[1]), plateau__geo_pos(mesh, tr[0]), e1);
        plateau__util_sub(plateau__geo_pos(mesh, tr[2]), plateau__geo_pos(mesh, tr[0]), e2);
        plateau__util_cross(e1, e2, nv);
        len = plateau__util_norm(nv);
        if (!(len > 0.0)) {
            plateau__util_error(err, PLATEAU_ERR_DEGENERATE_TRIANGLE, (long)t,
                                "area Hessian: triangle @ has zero area", (long)t, 0);
            return PLATEAU_ERR_DEGENERATE_TRIANGLE;
        }
        nv[0] /= len;
        nv[1] /= len;
        nv[2] /= len;
        /* a_i = m_i x e_i = dN/dt_i, e_i the edge opposite corner i */
        for (i = 0; i < 3; i++) {
            double ei[3];
            plateau__geo_direction(mesh, directions, (size_t)tr[i], m[i]);
            plateau__util_sub(plateau__geo_pos(mesh, tr[(i + 1) % 3]),
                             plateau__geo_pos(mesh, tr[(i + 2) % 3]), ei);
            plateau__util_cross(m[i], ei, a[i]);
            na[i] = plateau__util_dot(nv, a[i]);
            if (gradient) gradient[tr[i]] += 0.5 * na[i];
        }
        if (!diagonal) continue;
        for (i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            double mm[3], hij;
            diagonal[tr[i]] += (plateau__util_dot(a[i], a[i]) - na[i] * na[i]) / (2.0 * len);
            /* the pair (i, i + 1) runs along the triangle's edge k = i, s_ij = +1 */
            plateau__util_cross(m[i], m[j], mm);
            hij = (plateau__util_dot(a[i], a[j]) - na[i] * na[j]) / (2.0 * len) +
                  0.5 * plateau__util_dot(nv, mm);
            off_diagonal[mesh->triangle_edges[3 * t + (size_t)i]] += hij;
        }
    }
    return PLATEAU_OK;
}

/* ---- degeneration check ---- */
PLATEAU_DEF void plateau_mesh_quality(const plateau_mesh *mesh, plateau_quality *quality)
{
    const double rad = PLATEAU__DEG_PER_RAD;
    double mn = PLATEAU__HALF_TURN_DEG, mx = 0.0, mb = 0.0, area = 0.0;
    size_t t, e, inv = 0, deg = 0, fold = 0;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        double nf[3], s = 0.0, a, tmin = PLATEAU__HALF_TURN_DEG;
        int q;
        a = plateau_triangle_normal(mesh, t, nf);
        area += a;
        for (q = 0; q < 3; q++) {
            double ang = plateau__util_corner_angle(plateau__geo_pos(mesh, tr[q]),
                                                   plateau__geo_pos(mesh, tr[(q + 1) % 3]),
                                                   plateau__geo_pos(mesh, tr[(q + 2) % 3])) * rad;
            if (ang < mn) mn = ang;
            if (ang > mx) mx = ang;
            if (ang < tmin) tmin = ang;
        }
        /* degenerate: an angle at rounding level (or no area at all) */
        if (!(tmin >= PLATEAU_DEGENERATE_DEGREES) || !(a > 0.0)) deg++;
        for (q = 0; q < 3; q++) {
            plateau_index nb = mesh->neighbors[3 * t + (size_t)q];
            double nn[3];
            if (nb < 0) continue;
            plateau_triangle_normal(mesh, (size_t)nb, nn);
            s += plateau__util_dot(nf, nn);
        }
        if (!(a > 0.0) || s < 0.0) inv++;
    }
    for (e = 0; e < mesh->num_edges; e++) {
        double b = PLATEAU_FABS(plateau_edge_dihedral(mesh, e)) * rad;
        if (b > mb) mb = b;
        if (b > PLATEAU_FOLD_DEGREES) fold++;
    }
    quality->area = area;
    quality->min_angle_deg = mesh->num_triangles ? mn : 0.0;
    quality->max_angle_deg = mx;
    quality->max_abs_beta_deg = mb;
    quality->inverted_triangles = inv;
    quality->folded_edges = fold;
    quality->degenerate_triangles = deg;
    quality->intersecting_pairs = 0;
    quality->defects = (inv ? PLATEAU_DEFECT_INVERTED : 0u) | (fold ? PLATEAU_DEFECT_FOLD : 0u) |
                       (deg ? PLATEAU_DEFECT_DEGENERATE : 0u);
}

/* ---- residual and Jacobian assembly ---- */
PLATEAU_DEF void plateau_system_free(plateau_system *system)
{
    plateau_allocator a;
    if (!system) return;
    a = system->allocator;
    plateau__free(&a, system->residual);
    plateau__free(&a, system->row_vertex);
    plateau__free(&a, system->row_start);
    plateau__free(&a, system->block_vertex);
    plateau__free(&a, system->block_value);
    plateau__free(&a, system->column_of_vertex);
    memset(system, 0, sizeof *system);
}

PLATEAU_DEF plateau_result plateau_system_assemble(const plateau_mesh *mesh,
                                                   const plateau_system_options *options,
                                                   plateau_system *system, plateau_error *err)
{
    plateau_system_options opt;
    size_t nv, v, rows = 0, blocks = 0, cols = 0, maxst = 1, r, b;
    int per;
    plateau_index *sv = NULL, *slot_of = NULL;
    double *sg = NULL;
    const plateau_allocator *a;
    if (system) plateau_system_free(system);
    if (!mesh || !system || !mesh->vertex_edge_start) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_system_assemble needs a mesh with adjacency and a system", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    memset(&opt, 0, sizeof opt);
    if (options) opt = *options;
    a = &mesh->allocator;
    system->allocator = mesh->allocator;
    nv = mesh->num_vertices;
    per = opt.tangential_weight > 0.0 ? 3 : 1;
    for (v = 0; v < nv; v++) {
        int sel = opt.row_vertices ? opt.row_vertices[v] != 0 : !mesh->fixed[v];
        size_t st = plateau_vertex_stencil_size(mesh, v), j;
        if (!mesh->fixed[v]) cols += 3;
        if (st > maxst) maxst = st;
        if (!sel) continue;
        rows += (size_t)per;
        if (!opt.residual_only) {
            size_t fr = 0;
            plateau_index w;
            if (!mesh->fixed[v]) fr++;
            for (j = mesh->vertex_edge_start[v]; j < mesh->vertex_edge_start[v + 1]; j++) {
                size_t e = (size_t)mesh->vertex_edges[j];
                w = mesh->edges[2 * e] == (plateau_index)v ? mesh->edges[2 * e + 1] : mesh->edges[2 * e];
                if (!mesh->fixed[w]) fr++;
            }
            blocks += (size_t)per * fr;
        }
    }
    system->residual = (double *)plateau__util_array(a, rows, sizeof(double));
    system->row_vertex = (plateau_index *)plateau__util_array(a, rows, sizeof(plateau_index));
    system->row_start = (size_t *)plateau__util_array(a, rows + 1, sizeof(size_t));
    system->block_vertex = (plateau_index *)plateau__util_array(a, blocks, sizeof(plateau_index));
    system->block_value = (double *)plateau__util_array(a, blocks, 3 * sizeof(double));
    system->column_of_vertex = (plateau_index *)plateau__util_array(a, nv, sizeof(plateau_index));
    sv = (plateau_index *)plateau__util_array(a, maxst, sizeof(plateau_index));
    sg = (double *)plateau__util_array(a, maxst, 6 * sizeof(double));
    if (!opt.residual_only) slot_of = (plateau_index *)plateau__util_array(a, nv, sizeof(plateau_index));
    if (!system->residual || !system->row_vertex || !system->row_start || !system->block_vertex ||
        !system->block_value || !system->column_of_vertex || !sv || !sg ||
        (!opt.residual_only && !slot_of)) {
        plateau__free(a, sv);
        plateau__free(a, sg);
        plateau__free(a, slot_of);
        plateau_system_free(system);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory while assembling the system", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    system->num_rows = rows;
    system->num_columns = cols;
    if (slot_of)
        for (v = 0; v < nv; v++) slot_of[v] = -1;
    cols = 0;
    for (v = 0; v < nv; v++) {
        system->column_of_vertex[v] = mesh->fixed[v] ? -1 : (plateau_index)cols;
        if (!mesh->fixed[v]) cols += 3;
    }
    r = 0;
    b = 0;
    system->row_start[0] = 0;
    for (v = 0; v < nv; v++) {
        int sel = opt.row_vertices ? opt.row_vertices[v] != 0 : !mesh->fixed[v];
        size_t cnt = 0, k;
        int q;
        double hv = 0.0, tr[2] = {0.0, 0.0};
        if (!sel) continue;
        if (opt.residual_only) {
            system->residual[r] = plateau_vertex_mean_curvature(mesh, v) - opt.mean_curvature;
            system->row_vertex[r] = (plateau_index)v;
            system->row_start[++r] = 0;
            if (per == 3) {
                plateau_vertex_tangential(mesh, v, opt.tangential_weight, tr);
                for (q = 0; q < 2; q++) {
                    system->residual[r] = tr[q];
                    system->row_vertex[r] = (plateau_index)v;
                    system->row_start[++r] = 0;
                }
            }
            continue;
        }
        plateau__geo_hgrad(mesh, v, maxst, sv, sg, &cnt, &hv, slot_of);
        system->residual[r] = hv - opt.mean_curvature;
        system->row_vertex[r] = (plateau_index)v;
        for (k = 0; k < cnt; k++) {
            if (mesh->fixed[sv[k]]) continue;
            system->block_vertex[b] = sv[k];
            system->block_value[3 * b] = sg[3 * k];
            system->block_value[3 * b + 1] = sg[3 * k + 1];
            system->block_value[3 * b + 2] = sg[3 * k + 2];
            b++;
        }
        system->row_start[++r] = b;
        if (per == 3) {
            plateau__geo_tgrad(mesh, v, opt.tangential_weight, maxst, sv, sg, &cnt, tr, slot_of);
            for (q = 0; q < 2; q++) {
                system->residual[r] = tr[q];
                system->row_vertex[r] = (plateau_index)v;
                for (k = 0; k < cnt; k++) {
                    if (mesh->fixed[sv[k]]) continue;
                    system->block_vertex[b] = sv[k];
                    system->block_value[3 * b] = sg[6 * k + 3 * (size_t)q];
                    system->block_value[3 * b + 1] = sg[6 * k + 3 * (size_t)q + 1];
                    system->block_value[3 * b + 2] = sg[6 * k + 3 * (size_t)q + 2];
                    b++;
                }
                system->row_start[++r] = b;
            }
        }
    }
    system->num_blocks = b;
    plateau__free(a, sv);
    plateau__free(a, sg);
    plateau__free(a, slot_of);
    return PLATEAU_OK;
}

PLATEAU_DEF void plateau_system_dense(const plateau_system *system, double *jacobian)
{
    size_t r, k, nc = system->num_columns;
    for (r = 0; r < system->num_rows * nc; r++) jacobian[r] = 0.0;
    for (r = 0; r < system->num_rows; r++) {
        for (k = system->row_start[r]; k < system->row_start[r + 1]; k++) {
            plateau_index col = system->column_of_vertex[system->block_vertex[k]];
            double *row = jacobian + r * nc + (size_t)col;
            row[0] += system->block_value[3 * k];
            row[1] += system->block_value[3 * k + 1];
            row[2] += system->block_value[3 * k + 2];
        }
    }
}
/* ======== END SECTION: the mesh kernel ==================================== */

/* ======== SECTION: step 1: boundary check (plateau__bnd_) ================= */
/* The polygon (or the loops) must be able to bound an embedded surface. */
/* ---- crossing and touching edges in O(m log m): a uniform grid ----------
 * Both simplicity tests (step 1 in space, step 2 in the plane) look for
 * pairs of polygon edges closer than a tolerance.  All pairs would be
 * O(m^2).  Instead each edge
 * is cut into pieces no longer than the cell size h, each piece's
 * bounding box grown by the tolerance is entered into the cells of a
 * uniform grid it meets (at most 3 per axis), the (cell, edge) entries
 * are sorted (qsort: O(E log E)), and only edges sharing a cell are
 * compared (the sort-and-grid broad phase of collision detection; Ericson,
 * "Real-Time Collision Detection", 2005, ch. 7).  h is the larger of twice
 * the median edge length and a quarter of the mean, so there are at most
 * about 5m pieces and a cell holds O(1) edges unless the polygon crowds
 * many short edges into one place (then the cost grows with the square of
 * that crowd).  Cells are named by a 64-bit hash of their integer
 * coordinates: a collision only adds comparisons. */
typedef struct plateau__bnd_entry {
    uint64_t key;
    size_t edge;
} plateau__bnd_entry;

static int plateau__bnd_entry_cmp(const void *pa, const void *pb)
{
    const plateau__bnd_entry *a = (const plateau__bnd_entry *)pa, *b = (const plateau__bnd_entry *)pb;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    if (a->edge != b->edge) return a->edge < b->edge ? -1 : 1;
    return 0;
}

static int plateau__bnd_double_cmp(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return a < b ? -1 : (a > b ? 1 : 0);
}

/* Visits a candidate pair of edges a < b; non-zero stops the enumeration. */
typedef int (*plateau__bnd_visit)(void *ctx, size_t a, size_t b);

/* Calls visit(ctx, a, b), a < b, at least once for every pair of edges
 * (edge i from vertex i to next[i], or to (i + 1) % m when next is NULL:
 * several closed loops in one array or one polygon; dim = 2 or 3 coordinates per
 * vertex in pts) whose bounding boxes grown by tol overlap, and never for
 * others.  Returns 0 when all were visited, 1 when visit stopped it,
 * -1 out of memory, -2 a size overflow. */
static int plateau__bnd_edge_pairs_next(const double *pts, int dim, size_t m, const size_t *next,
                                       double tol, const plateau_allocator *allocator,
                                       plateau__bnd_visit visit, void *ctx)
{
    double *len = NULL, lo[3] = {0.0, 0.0, 0.0}, perim = 0.0, h, median;
    plateau__bnd_entry *ent = NULL;
    size_t i, count = 0, filled = 0, bytes, run, r2;
    int k, pass, result = 0;
    bytes = plateau__bytes(m, sizeof(double));
    if (bytes == 0) return -2;
    len = (double *)plateau__alloc(allocator, bytes);
    if (!len) return -1;
    for (k = 0; k < dim; k++) lo[k] = pts[k];
    for (i = 0; i < m; i++) {
        const double *a = pts + (size_t)dim * i, *b = pts + (size_t)dim * (next ? next[i] : (i + 1) % m);
        double s = 0.0;
        for (k = 0; k < dim; k++) {
            s += (b[k] - a[k]) * (b[k] - a[k]);
            if (a[k] < lo[k]) lo[k] = a[k];
        }
        len[i] = PLATEAU_SQRT(s);
        perim += len[i];
    }
    for (k = 0; k < dim; k++) lo[k] -= 2.0 * tol;
    PLATEAU_QSORT(len, m, sizeof(double), plateau__bnd_double_cmp);
    median = len[m / 2];
    h = 2.0 * median;
    if (h < 0.25 * perim / (double)m) h = 0.25 * perim / (double)m;
    if (h < 4.0 * tol) h = 4.0 * tol;
    plateau__free(allocator, len);
    len = NULL;
    if (!(h > 0.0) || !plateau__util_finite(h)) return 0; /* no edge has a length */
    /* pass 0 counts the entries, pass 1 fills them */
    for (pass = 0; pass < 2; pass++) {
        for (i = 0; i < m; i++) {
            const double *a = pts + (size_t)dim * i, *b = pts + (size_t)dim * (next ? next[i] : (i + 1) % m);
            double s = 0.0, pieces;
            size_t np, p;
            for (k = 0; k < dim; k++) s += (b[k] - a[k]) * (b[k] - a[k]);
            pieces = PLATEAU_SQRT(s) / h;
            np = pieces < 1.0 ? 1 : (size_t)pieces + 1;
            for (p = 0; p < np; p++) {
                double t0 = (double)p / (double)np, t1 = (double)(p + 1) / (double)np;
                uint64_t c0[3] = {0, 0, 0}, c1[3] = {0, 0, 0}, x, y, z;
                for (k = 0; k < dim; k++) {
                    double u0 = a[k] + t0 * (b[k] - a[k]), u1 = a[k] + t1 * (b[k] - a[k]);
                    double mn = (u0 < u1 ? u0 : u1) - tol - lo[k], mx = (u0 < u1 ? u1 : u0) + tol - lo[k];
                    c0[k] = (uint64_t)(mn > 0.0 ? mn / h : 0.0);
                    c1[k] = (uint64_t)(mx > 0.0 ? mx / h : 0.0);
                }
                for (x = c0[0]; x <= c1[0]; x++)
                    for (y = c0[1]; y <= c1[1]; y++)
                        for (z = c0[2]; z <= c1[2]; z++) {
                            if (pass == 0) {
                                if (count == (size_t)-1) return -2;
                                count++;
                            } else if (filled < count) {
                                /* a splitmix64-style mix of the cell coordinates */
                                uint64_t key = x * PLATEAU__U64(0x9E3779B9u, 0x7F4A7C15u);
                                key = (key ^ (key >> 29) ^ y) * PLATEAU__U64(0xBF58476Du, 0x1CE4E5B9u);
                                key = (key ^ (key >> 31) ^ z) * PLATEAU__U64(0x94D049BBu, 0x133111EBu);
                                ent[filled].key = key ^ (key >> 32);
                                ent[filled].edge = i;
                                filled++;
                            }
                        }
            }
        }
        if (pass == 0) {
            bytes = plateau__bytes(count, sizeof(plateau__bnd_entry));
            if (bytes == 0) return -2;
            ent = (plateau__bnd_entry *)plateau__alloc(allocator, bytes);
            if (!ent) return -1;
        }
    }
    PLATEAU_QSORT(ent, filled, sizeof(plateau__bnd_entry), plateau__bnd_entry_cmp);
    for (run = 0; run < filled && result == 0; run = r2) {
        size_t x, y;
        for (r2 = run + 1; r2 < filled && ent[r2].key == ent[run].key; r2++) {}
        for (x = run; x < r2 && result == 0; x++) {
            if (x > run && ent[x].edge == ent[x - 1].edge) continue;
            for (y = x + 1; y < r2 && result == 0; y++) {
                size_t ea = ent[x].edge, eb = ent[y].edge;
                const double *a0, *a1, *b0, *b1;
                int apart = 0;
                if (eb == ent[y - 1].edge && y - 1 > x) continue;
                if (eb == ea) continue;
                a0 = pts + (size_t)dim * ea;
                a1 = pts + (size_t)dim * (next ? next[ea] : (ea + 1) % m);
                b0 = pts + (size_t)dim * eb;
                b1 = pts + (size_t)dim * (next ? next[eb] : (eb + 1) % m);
                for (k = 0; k < dim; k++) {
                    double amin = a0[k] < a1[k] ? a0[k] : a1[k], amax = a0[k] < a1[k] ? a1[k] : a0[k];
                    double bmin = b0[k] < b1[k] ? b0[k] : b1[k], bmax = b0[k] < b1[k] ? b1[k] : b0[k];
                    if (amin - tol > bmax + tol || bmin - tol > amax + tol) apart = 1;
                }
                if (!apart) result = visit(ctx, ea, eb);
            }
        }
    }
    plateau__free(allocator, ent);
    return result ? 1 : 0;
}

static int plateau__bnd_edge_pairs(const double *pts, int dim, size_t m, double tol,
                                  const plateau_allocator *allocator,
                                  plateau__bnd_visit visit, void *ctx)
{
    return plateau__bnd_edge_pairs_next(pts, dim, m, NULL, tol, allocator, visit, ctx);
}

/* Squared distance from p to the segment a-b in space. */
static double plateau__bnd_seg_dist2_3(const double *p, const double *a, const double *b)
{
    double e[3], q[3], l2 = 0.0, t = 0.0, d2 = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        e[k] = b[k] - a[k];
        q[k] = p[k] - a[k];
        l2 += e[k] * e[k];
        t += q[k] * e[k];
    }
    t = l2 > 0.0 ? t / l2 : 0.0;
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    for (k = 0; k < 3; k++) d2 += (q[k] - t * e[k]) * (q[k] - t * e[k]);
    return d2;
}

/* Squared distance between the segments p0-p1 and q0-q1 in space: the
 * closest points of the two lines (the 2x2 normal equations of
 * min |p0 + s d1 - q0 - t d2|^2), clamped to the segments one after the
 * other, and the four endpoint-to-segment distances, which cover parallel
 * and nearly parallel segments (the minimum over two segments lies at an
 * endpoint unless their interiors hold the closest points of the lines). */
static double plateau__bnd_segs_dist2_3(const double *p0, const double *p1, const double *q0,
                                       const double *q1)
{
    double d1[3], d2[3], r[3], a = 0.0, b = 0.0, c = 0.0, e = 0.0, f = 0.0, den, s, t, best, v;
    int k;
    for (k = 0; k < 3; k++) {
        d1[k] = p1[k] - p0[k];
        d2[k] = q1[k] - q0[k];
        r[k] = p0[k] - q0[k];
        a += d1[k] * d1[k];
        b += d1[k] * d2[k];
        c += d1[k] * r[k];
        e += d2[k] * d2[k];
        f += d2[k] * r[k];
    }
    best = plateau__bnd_seg_dist2_3(p0, q0, q1);
    v = plateau__bnd_seg_dist2_3(p1, q0, q1);
    if (v < best) best = v;
    v = plateau__bnd_seg_dist2_3(q0, p0, p1);
    if (v < best) best = v;
    v = plateau__bnd_seg_dist2_3(q1, p0, p1);
    if (v < best) best = v;
    den = a * e - b * b;
    if (a > 0.0 && e > 0.0 && den > 0.0) {
        s = (b * f - c * e) / den;
        if (s < 0.0) s = 0.0;
        if (s > 1.0) s = 1.0;
        t = (b * s + f) / e;
        if (t < 0.0) t = 0.0;
        if (t > 1.0) t = 1.0;
        s = (b * t - c) / a;
        if (s < 0.0) s = 0.0;
        if (s > 1.0) s = 1.0;
        v = 0.0;
        for (k = 0; k < 3; k++) {
            double w = r[k] + s * d1[k] - t * d2[k];
            v += w * w;
        }
        if (v < best) best = v;
    }
    return best;
}

/* Step 1's embedding test: the first defect by (kind, index, index). */
typedef struct plateau__bnd_defect {
    const double *p; /* the polygon, in units of its largest coordinate */
    size_t m;
    double tol2;
    int kind;        /* 0 none, 1 a vertex twice, 2 a vertex on an edge, 3 two edges meet */
    size_t i, j;
} plateau__bnd_defect;

static void plateau__bnd_defect_note(plateau__bnd_defect *d, int kind, size_t i, size_t j)
{
    if (d->kind == 0 || kind < d->kind || (kind == d->kind && (i < d->i || (i == d->i && j < d->j)))) {
        d->kind = kind;
        d->i = i;
        d->j = j;
    }
}

static double plateau__bnd_dist2_3(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

static int plateau__bnd_defect_visit(void *ctx, size_t ea, size_t eb)
{
    plateau__bnd_defect *d = (plateau__bnd_defect *)ctx;
    size_t m = d->m, va[2], vb[2], x, y;
    int found = 0;
    va[0] = ea; va[1] = (ea + 1) % m;
    vb[0] = eb; vb[1] = (eb + 1) % m;
    /* two vertices that are not neighbours on one point */
    for (x = 0; x < 2; x++)
        for (y = 0; y < 2; y++) {
            size_t u = va[x], w = vb[y], lo2 = u < w ? u : w, hi2 = u < w ? w : u;
            if (u == w || hi2 - lo2 == 1 || (lo2 == 0 && hi2 == m - 1)) continue;
            if (plateau__bnd_dist2_3(d->p + 3 * u, d->p + 3 * w) <= d->tol2) {
                plateau__bnd_defect_note(d, 1, lo2, hi2);
                found = 1;
            }
        }
    /* a vertex on an edge it does not end (on a neighbouring edge: the
     * polygon folds back on itself) and not on one of that edge's ends */
    for (x = 0; x < 4; x++) {
        size_t u = x < 2 ? va[x] : vb[x - 2], e = x < 2 ? eb : ea;
        const double *e0 = d->p + 3 * e, *e1 = d->p + 3 * ((e + 1) % m), *pu = d->p + 3 * u;
        if (u == e || u == (e + 1) % m) continue;
        if (plateau__bnd_seg_dist2_3(pu, e0, e1) <= d->tol2 &&
            plateau__bnd_dist2_3(pu, e0) > d->tol2 && plateau__bnd_dist2_3(pu, e1) > d->tol2) {
            plateau__bnd_defect_note(d, 2, u, e);
            found = 1;
        }
    }
    /* two edges that share no vertex and cross or touch in their interiors */
    if (!found && va[1] != eb && vb[1] != ea &&
        plateau__bnd_segs_dist2_3(d->p + 3 * va[0], d->p + 3 * va[1], d->p + 3 * vb[0],
                                 d->p + 3 * vb[1]) <= d->tol2)
        plateau__bnd_defect_note(d, 3, ea, eb);
    return 0;
}

static plateau_result plateau__bnd_embedded(const double *xyz, size_t m,
                                           const plateau_allocator *allocator,
                                           plateau_error *err)
{
    plateau__bnd_defect d;
    double *p, lo[3], hi[3], diag2 = 0.0;
    size_t i, bytes;
    int k, r;
    long v[6];
    bytes = plateau__bytes(m, 3 * sizeof(double));
    if (bytes == 0) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the polygon is too large", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    p = (double *)plateau__alloc(allocator, bytes);
    if (!p) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1,
                          "out of memory while checking the polygon for crossings", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    plateau__util_unit_copy(xyz, m, p);
    for (k = 0; k < 3; k++) lo[k] = hi[k] = p[k];
    for (i = 1; i < m; i++)
        for (k = 0; k < 3; k++) {
            if (p[3 * i + (size_t)k] < lo[k]) lo[k] = p[3 * i + (size_t)k];
            if (p[3 * i + (size_t)k] > hi[k]) hi[k] = p[3 * i + (size_t)k];
        }
    for (k = 0; k < 3; k++) diag2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    memset(&d, 0, sizeof d);
    d.p = p;
    d.m = m;
    d.tol2 = PLATEAU__REL_TOL2 * diag2;
    for (i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        if (plateau__bnd_dist2_3(p + 3 * i, p + 3 * j) <= d.tol2) {
            plateau__free(allocator, p);
            plateau__util_error(err, PLATEAU_ERR_REPEATED_VERTEX, (long)i,
                              "boundary vertices @ and @ are closer than 1e-9 times the polygon's size",
                              (long)i, (long)j);
            if (err) err->index2 = (long)j;
            return PLATEAU_ERR_REPEATED_VERTEX;
        }
    }
    r = plateau__bnd_edge_pairs(p, 3, m, PLATEAU__REL_TOL * PLATEAU_SQRT(diag2), allocator,
                               plateau__bnd_defect_visit, &d);
    plateau__free(allocator, p);
    if (r < 0) {
        plateau_result rc = r == -1 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_ERR_OVERFLOW;
        plateau__util_error(err, rc, -1,
                          r == -1 ? "out of memory while checking the polygon for crossings"
                                  : "the crossing test of the polygon overflows", 0, 0);
        return rc;
    }
    v[0] = (long)d.i;
    v[1] = (long)d.j;
    v[2] = (long)d.j;
    v[3] = (long)((d.j + 1) % m);
    if (d.kind == 1) {
        plateau__util_error_n(err, PLATEAU_ERR_DUPLICATE_VERTEX, v[0],
                            "boundary vertices @ and @ coincide (they are not neighbours)", v, 2);
        if (err) err->index2 = v[1];
        return PLATEAU_ERR_DUPLICATE_VERTEX;
    }
    if (d.kind == 2) {
        plateau__util_error_n(err, PLATEAU_ERR_VERTEX_ON_EDGE, v[0],
                            "boundary vertex @ lies on edge @ (from vertex @ to vertex @)", v, 4);
        if (err) err->index2 = v[1];
        return PLATEAU_ERR_VERTEX_ON_EDGE;
    }
    if (d.kind == 3) {
        v[1] = (long)d.i;
        v[2] = (long)((d.i + 1) % m);
        v[3] = (long)d.j;
        v[4] = (long)d.j;
        v[5] = (long)((d.j + 1) % m);
        plateau__util_error_n(err, PLATEAU_ERR_EDGES_INTERSECT, (long)d.i,
                            "boundary edges @ (vertices @, @) and @ (vertices @, @) cross or touch",
                            v, 6);
        if (err) err->index2 = v[3];
        return PLATEAU_ERR_EDGES_INTERSECT;
    }
    return plateau__util_ok(err);
}

/* ---- step 1: the boundary ------------------------------------------------ */
/* Step 1, its scratch from allocator (plateau_boundary_check: the default). */
/* Collinear: no vertex farther than 1e-12 of the bounding-box diagonal
 * from the line (the square of that fraction, for squared distances). */
#define PLATEAU__BND_COLLINEAR2 1e-24

static plateau_result plateau__bnd_check(const double *xyz, size_t m,
                                                 const plateau_allocator *allocator,
                                                 plateau_error *err)
{
    size_t i, far = 0;
    double lo[3], hi[3], diag2, best = -1.0, d[3], len2, maxdist2 = 0.0, extent, h;
    int k, off_line = 0;
    if (!xyz && m > 0) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the boundary array is NULL", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (m < 3) {
        plateau__util_error(err, PLATEAU_ERR_TOO_FEW_VERTICES, (long)m,
                          "the polygon has @ vertices; it needs at least 3", (long)m, 0);
        return PLATEAU_ERR_TOO_FEW_VERTICES;
    }
    if (m > (size_t)PLATEAU_INDEX_MAX || m > (size_t)-1 / (3 * sizeof(double))) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1,
                          "the polygon has more vertices than plateau_index can count", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    for (i = 0; i < m; i++) {
        for (k = 0; k < 3; k++) {
            if (!plateau__util_finite(xyz[3 * i + (size_t)k])) {
                plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)i,
                                  "boundary vertex @ has a NaN or infinite coordinate", (long)i, 0);
                return PLATEAU_ERR_NOT_FINITE;
            }
        }
    }
    for (i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        if (xyz[3 * i] == xyz[3 * j] && xyz[3 * i + 1] == xyz[3 * j + 1] &&
            xyz[3 * i + 2] == xyz[3 * j + 2]) {
            plateau__util_error(err, PLATEAU_ERR_REPEATED_VERTEX, (long)i,
                              "boundary vertices @ and @ are equal", (long)i, (long)j);
            if (err) err->index2 = (long)j;
            return PLATEAU_ERR_REPEATED_VERTEX;
        }
    }
    /* Collinearity, relative to the size of the polygon. */
    for (k = 0; k < 3; k++) lo[k] = hi[k] = xyz[k];
    for (i = 1; i < m; i++) {
        for (k = 0; k < 3; k++) {
            if (xyz[3 * i + (size_t)k] < lo[k]) lo[k] = xyz[3 * i + (size_t)k];
            if (xyz[3 * i + (size_t)k] > hi[k]) hi[k] = xyz[3 * i + (size_t)k];
        }
    }
    /* work in units of the largest extent, so no square under- or overflows;
     * when a coordinate difference itself overflows (coordinates of both
     * signs near DBL_MAX), on halved coordinates (h = 0.5), whose
     * differences are finite */
    h = 1.0;
    for (k = 0; k < 3; k++)
        if (!plateau__util_finite(hi[k] - lo[k])) h = 0.5;
    extent = 0.0;
    for (k = 0; k < 3; k++)
        if (hi[k] * h - lo[k] * h > extent) extent = hi[k] * h - lo[k] * h;
    if (!(extent > 0.0) || !plateau__util_finite(extent)) extent = 1.0;
    diag2 = 0.0;
    for (k = 0; k < 3; k++)
        diag2 += ((hi[k] * h - lo[k] * h) / extent) * ((hi[k] * h - lo[k] * h) / extent);
    for (i = 1; i < m; i++) {
        double s = 0.0;
        for (k = 0; k < 3; k++) {
            double e = (xyz[3 * i + (size_t)k] * h - xyz[k] * h) / extent;
            s += e * e;
        }
        if (s > best) { best = s; far = i; }
    }
    for (k = 0; k < 3; k++) d[k] = (xyz[3 * far + (size_t)k] * h - xyz[k] * h) / extent;
    len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (i = 1; i < m && len2 > 0.0; i++) {
        double e[3], c[3], dist2;
        for (k = 0; k < 3; k++) e[k] = (xyz[3 * i + (size_t)k] * h - xyz[k] * h) / extent;
        c[0] = e[1] * d[2] - e[2] * d[1];
        c[1] = e[2] * d[0] - e[0] * d[2];
        c[2] = e[0] * d[1] - e[1] * d[0];
        dist2 = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / len2;
        if (dist2 > maxdist2) maxdist2 = dist2;
        off_line |= c[0] != 0.0 || c[1] != 0.0 || c[2] != 0.0;
    }
    if (!(maxdist2 > PLATEAU__BND_COLLINEAR2 * diag2)) {
        plateau__util_error(err, PLATEAU_ERR_COLLINEAR, -1,
                          off_line ? "all @ polygon vertices lie within 1e-12 of the polygon's size of one line"
                                         : "all @ polygon vertices lie on one line",
                          (long)m, 0);
        return PLATEAU_ERR_COLLINEAR;
    }
    return plateau__bnd_embedded(xyz, m, allocator, err);
}

PLATEAU_DEF plateau_result plateau_boundary_check(const double *xyz, size_t m,
                                                  plateau_error *err)
{
    return plateau__bnd_check(xyz, m, NULL, err);
}

/* ---- step 1 for several loops -------------------------------------------- */
/* The first contact between two different loops, by (kind, smaller edge,
 * larger edge): kind 1 a vertex of one loop on a vertex of another, 2 a
 * vertex of one on an edge of another or two edges that cross or touch.
 * Pairs within one loop were checked by the loop's own test. */
typedef struct plateau__bnd_contact {
    const double *p;     /* all loops, in units of the largest coordinate */
    const size_t *next;  /* the vertex ending edge i */
    const size_t *loop;  /* the loop of vertex i */
    double tol2;
    int kind;
    size_t i, j;         /* kind 1: the two vertices; kind 2: the two edges */
} plateau__bnd_contact;

static int plateau__bnd_contact_visit(void *ctx, size_t ea, size_t eb)
{
    plateau__bnd_contact *d = (plateau__bnd_contact *)ctx;
    size_t va[2], vb[2], x, y;
    if (d->loop[ea] == d->loop[eb]) return 0;
    va[0] = ea; va[1] = d->next[ea];
    vb[0] = eb; vb[1] = d->next[eb];
    for (x = 0; x < 2; x++)
        for (y = 0; y < 2; y++)
            if (plateau__bnd_dist2_3(d->p + 3 * va[x], d->p + 3 * vb[y]) <= d->tol2) {
                size_t lo2 = va[x] < vb[y] ? va[x] : vb[y], hi2 = va[x] < vb[y] ? vb[y] : va[x];
                if (d->kind == 0 || d->kind > 1 || lo2 < d->i || (lo2 == d->i && hi2 < d->j)) {
                    d->kind = 1;
                    d->i = lo2;
                    d->j = hi2;
                }
            }
    if (plateau__bnd_segs_dist2_3(d->p + 3 * va[0], d->p + 3 * va[1], d->p + 3 * vb[0],
                                 d->p + 3 * vb[1]) <= d->tol2 &&
        (d->kind == 0 || (d->kind == 2 && (ea < d->i || (ea == d->i && eb < d->j))))) {
        d->kind = 2;
        d->i = ea;
        d->j = eb;
    }
    return 0;
}

/* Step 1 for k loops (plateau_solve_loops): each loop by
 * plateau__bnd_check (its message then starts "loop j: " and keeps
 * the loop's own vertex numbers; err->index and index2 become the vertices'
 * indices in the whole array), then no contact between loops: no vertex of one within
 * tol of a vertex of another (PLATEAU_ERR_LOOPS_SHARE_VERTEX), no edges of
 * two loops within tol of each other (PLATEAU_ERR_LOOPS_INTERSECT), tol =
 * 1e-9 times the bounding-box diagonal of all loops, by the grid of
 * plateau__bnd_edge_pairs_next over all edges (O(M log M), M vertices in
 * all).  off: k + 1 offsets; next, loop: M entries each, filled here. */
static plateau_result plateau__bnd_loops_check(const double *xyz, const size_t *off, size_t k,
                                              size_t *next, size_t *loop,
                                              const plateau_allocator *allocator,
                                              plateau_error *err)
{
    plateau__bnd_contact d;
    size_t j, i, M = off[k], bytes;
    double *p, lo[3], hi[3], diag2 = 0.0;
    plateau_result rc;
    long v[6];
    int r, c;
    for (j = 0; j < k; j++) {
        rc = plateau__bnd_check(xyz + 3 * off[j], off[j + 1] - off[j], allocator, err);
        if (rc != PLATEAU_OK) {
            if (err) {
                /* "loop j: " and the loop's own message after it */
                char own[sizeof err->message];
                size_t n, q;
                long jj = (long)j, index = err->index, index2 = err->index2;
                memcpy(own, err->message, sizeof own);
                own[sizeof own - 1] = '\0';
                plateau__util_error_n(err, rc, index, "loop @: ", &jj, 1);
                for (n = 0; err->message[n]; n++) {}
                for (q = 0; own[q] && n + 1 < sizeof err->message; q++) err->message[n++] = own[q];
                err->message[n] = '\0';
                if (index >= 0 && rc != PLATEAU_ERR_TOO_FEW_VERTICES) err->index = index + (long)off[j];
                if (index2 >= 0) err->index2 = index2 + (long)off[j];
            }
            return rc;
        }
        for (i = off[j]; i < off[j + 1]; i++) {
            next[i] = i + 1 < off[j + 1] ? i + 1 : off[j];
            loop[i] = j;
        }
    }
    bytes = plateau__bytes(M, 3 * sizeof(double));
    p = bytes ? (double *)plateau__alloc(allocator, bytes) : NULL;
    if (!p) {
        rc = bytes ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_ERR_OVERFLOW;
        plateau__util_error(err, rc, -1, "out of memory while checking the loops for contacts", 0, 0);
        return rc;
    }
    plateau__util_unit_copy(xyz, M, p);
    for (c = 0; c < 3; c++) lo[c] = hi[c] = p[c];
    for (i = 1; i < M; i++)
        for (c = 0; c < 3; c++) {
            if (p[3 * i + (size_t)c] < lo[c]) lo[c] = p[3 * i + (size_t)c];
            if (p[3 * i + (size_t)c] > hi[c]) hi[c] = p[3 * i + (size_t)c];
        }
    for (c = 0; c < 3; c++) diag2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    memset(&d, 0, sizeof d);
    d.p = p;
    d.next = next;
    d.loop = loop;
    d.tol2 = PLATEAU__REL_TOL2 * diag2;
    r = plateau__bnd_edge_pairs_next(p, 3, M, next, PLATEAU__REL_TOL * PLATEAU_SQRT(diag2), allocator,
                                    plateau__bnd_contact_visit, &d);
    plateau__free(allocator, p);
    if (r < 0) {
        rc = r == -1 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_ERR_OVERFLOW;
        plateau__util_error(err, rc, -1, "out of memory while checking the loops for contacts", 0, 0);
        return rc;
    }
    if (d.kind == 1) {
        v[0] = (long)loop[d.i];
        v[1] = (long)(d.i - off[loop[d.i]]);
        v[2] = (long)loop[d.j];
        v[3] = (long)(d.j - off[loop[d.j]]);
        {
            long w[6];
            w[0] = v[0]; w[1] = v[2]; w[2] = v[1]; w[3] = v[0]; w[4] = v[3]; w[5] = v[2];
            plateau__util_error_n(err, PLATEAU_ERR_LOOPS_SHARE_VERTEX, (long)d.i,
                                "loops @ and @ share a vertex: vertex @ of loop @ and vertex @ of loop @ coincide",
                                w, 6);
            if (err) err->index2 = (long)d.j;
        }
        return PLATEAU_ERR_LOOPS_SHARE_VERTEX;
    }
    if (d.kind == 2) {
        v[0] = (long)(d.i - off[loop[d.i]]);
        v[1] = (long)loop[d.i];
        v[2] = (long)(next[d.i] - off[loop[d.i]]);
        v[3] = (long)(d.j - off[loop[d.j]]);
        v[4] = (long)loop[d.j];
        v[5] = (long)(next[d.j] - off[loop[d.j]]);
        plateau__util_error_n(err, PLATEAU_ERR_LOOPS_INTERSECT, (long)d.i,
                            "edge @ of loop @ (to vertex @) and edge @ of loop @ (to vertex @) cross or touch",
                            v, 6);
        if (err) err->index2 = (long)d.j;
        return PLATEAU_ERR_LOOPS_INTERSECT;
    }
    return plateau__util_ok(err);
}

/* ---- the step as plateau_solve runs it ---- */

/* Step 1 and the work area for k >= 1 loops of counts[j] vertices, m in
 * all: one loop by plateau__bnd_check, several by plateau__bnd_loops_check
 * (each loop, then the contacts between loops); then the n interior points
 * must fit plateau_index beside them. */
static plateau_result plateau__bnd_step(const double *xyz, const size_t *counts, size_t k,
                                        const plateau__cfg *cfg, plateau__cfg_work *s,
                                        plateau_error *err)
{
    size_t m = s->m, n = cfg->n, j;
    plateau_result rc;
    if (k == 1 || !PLATEAU__HAVE_LOOPS) {
        rc = plateau__bnd_check(xyz, m, &s->alloc, err);
        if (rc != PLATEAU_OK) return rc;
    } else {
        s->off = (size_t *)plateau__util_array(&s->alloc, k + 1, sizeof(size_t));
        s->loop = (size_t *)plateau__util_array(&s->alloc, m, sizeof(size_t));
        s->next = (size_t *)plateau__util_array(&s->alloc, m, sizeof(size_t));
        s->lsign = (double *)plateau__util_array(&s->alloc, k, sizeof(double));
        if (!s->off || !s->loop || !s->next || !s->lsign) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_solve_loops", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        s->off[0] = 0;
        for (j = 0; j < k; j++) s->off[j + 1] = s->off[j] + counts[j];
        rc = plateau__bnd_loops_check(xyz, s->off, k, s->next, s->loop, &s->alloc, err);
        if (rc != PLATEAU_OK) return rc;
        s->loops = k;
    }
    if (m + n < m || n > (size_t)PLATEAU_INDEX_MAX - m) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many interior points", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    s->boundary = xyz;
    s->n = n;
    s->uv = (double *)plateau__util_array(&s->alloc, m, 2 * sizeof(double));
    if (k == 1) s->pts = (double *)plateau__util_array(&s->alloc, n, 3 * sizeof(double));
    s->seg = (plateau_index *)plateau__util_array(&s->alloc, m, 2 * sizeof(plateau_index));
    s->nb = (double *)plateau__util_array(&s->alloc, m, 7 * sizeof(double)); /* 4 m: the frame's scratch */
    if (!s->uv || (k == 1 && !s->pts) || !s->seg || !s->nb) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1,
                            k == 1 ? "out of memory in plateau_solve" : "out of memory in plateau_solve_loops", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    return PLATEAU_OK;
}
/* ======== END SECTION: step 1: boundary check ============================= */

/* ======== SECTION: the scale-free frame (plateau__frame_) ================= */
/* The polygon's own frame, in which steps 2-6 run (the manual's
 * INVARIANCE), and the way back to the caller's units. */
/* The solve's frame (plateau_solve, plateau_solve_loops,
 * plateau_mesh_minimize): the rounds run on canonical coordinates of the
 * polygon, the same for every copy of it under a similarity, so that the
 * copies give the same mesh.  In steps:
 *   1. move to the bounding box's centre and divide by P, the power of two
 *      at or above the largest half-extent (no square below overflows or
 *      underflows at any scale, and a small polygon far from the origin
 *      keeps its digits);
 *   2. order and sign the axes by the polygon itself, never by the order
 *      the caller gave them in: per axis, the coordinates less the middle
 *      of their range, the sign that makes the first one at least tau of
 *      the largest positive, the axes by their largest |value|, then by
 *      their signed sequences compared in vertex order (tau = 0.5772...,
 *      Euler's constant: a threshold that the symmetric polygons people
 *      draw do not sit on);
 *   3. the origin at the centroid of the vertices, and the axes e1 (to the
 *      first vertex at least tau of the farthest from the centroid), e2 (to
 *      the first at least tau of the farthest from that line, orthogonal
 *      to e1) and e3 = +-e1 x e2 (signed like e1 unless the polygon is
 *      flat to 1e-6), all from vertices, so that a rotated copy gets the
 *      same axes up to rounding (a principal-axes frame does not: near a
 *      tie of two moments its axes spin);
 *   4. divide by S, the root mean square distance of the vertices from the
 *      centroid, and round to a multiple of 2^-36 (as the domain's uv:
 *      plateau__dom_canonical).
 * Steps 1 and 2 commute exactly with those transforms (the centre of a
 * mirrored box is the mirrored centre, bit for bit; a power of two scales
 * every difference exactly), so a copy with its axes permuted, mirrored or
 * scaled by a power of two reaches step 3 with the same numbers and gets
 * the same mesh bit for bit (the caller's units restored exactly: the
 * boundary as given, the other vertices by the inverse map).  Any other
 * similarity (a rotation, a scaling by 3.7, a move) reaches step 4 with
 * the same coordinates up to rounding (1e-15 of the size), which the
 * rounding of step 4 (1.5e-11 of the size, far below the tolerance 1e-9
 * of the boundary check) makes equal bit for bit unless one of them lies
 * within rounding of a half-way point of the grid (about 1e-4 per
 * coordinate): then the copies solve boundaries 1.5e-11 apart, and their
 * meshes differ at that level (the same triangles but at near-ties). */
#define PLATEAU__FRAME_TAU 0.5772156649015329
typedef struct plateau__frame {
    int rounded;     /* 0: a degenerate point set, moved and divided by p2 only */
    double c0[3];    /* step 1: the bounding box's centre (the caller's axes) */
    double p2;       /* step 1 */
    int axis[3];     /* step 2: frame axis j is the caller's axis[j] ... */
    double sign[3];  /* ... times sign[j] */
    double g[3];     /* step 3: the centroid, in step 2's coordinates */
    double e[3][3];  /* step 3: the axes e1, e2, e3 (rows) */
    double s;        /* step 4 */
    double unit;     /* p2 s: a frame length in the caller's units */
} plateau__frame;

/* The index of the first of n values v[i * stride] whose |value| is at
 * least tau of the largest, and that largest in *mx. */
static size_t plateau__frame_first(const double *v, size_t n, size_t stride, double *mx)
{
    size_t i;
    *mx = 0.0;
    for (i = 0; i < n; i++)
        if (PLATEAU_FABS(v[i * stride]) > *mx) *mx = PLATEAU_FABS(v[i * stride]);
    for (i = 0; i < n; i++)
        if (PLATEAU_FABS(v[i * stride]) >= PLATEAU__FRAME_TAU * *mx) return i;
    return 0;
}

/* Step 2's order of the axes a and b: by the largest |value|, then by
 * the signed sequences in vertex order (d: count x 3, centred). */
static int plateau__frame_before(const double *d, size_t count, const double *mx,
                                 const double *sign, int a, int b)
{
    size_t i;
    if (mx[a] != mx[b]) return mx[a] > mx[b];
    for (i = 0; i < count; i++) {
        double x = sign[a] * d[3 * i + (size_t)a], y = sign[b] * d[3 * i + (size_t)b];
        if (x != y) return x > y;
    }
    return a < b;
}

/* Step 3's third axis: its sign from a vertex, unless the polygon is flat
 * to 1e-6 of its size (then e1 x e2: the sign would be rounding's). */
static void plateau__frame_third(plateau__frame *f, const double *w, size_t count,
                                 double dmax, double *h)
{
    size_t i, i3;
    double hm, len;
    plateau__util_cross(f->e[0], f->e[1], f->e[2]);
    len = plateau__util_norm(f->e[2]);
    for (i = 0; i < 3; i++) f->e[2][i] /= len;
    for (i = 0; i < count; i++) h[i] = plateau__util_dot(w + 3 * i, f->e[2]);
    i3 = plateau__frame_first(h, count, 1, &hm);
    if (hm > 1e-6 * dmax && h[i3] < 0.0)
        for (i = 0; i < 3; i++) f->e[2][i] = -f->e[2][i];
}

/* A degenerate point set (all on one line: only plateau_mesh_minimize
 * can meet one): the caller's axes divided by p2, not rounded. */
static int plateau__frame_plain(plateau__frame *f)
{
    int k;
    for (k = 0; k < 3; k++) {
        f->axis[k] = k;
        f->sign[k] = 1.0;
        f->g[k] = 0.0;
        f->e[k][0] = f->e[k][1] = f->e[k][2] = 0.0;
        f->e[k][k] = 1.0;
    }
    f->s = 1.0;
    f->unit = f->p2;
    f->rounded = 0;
    return -1;
}

/* Fills *f for the count points xyz (count >= 1); scratch holds 4 count
 * doubles.  Returns 0, or -1 for a degenerate set (all on one line, or
 * not finite: then plateau__frame_plain's frame). */
static int plateau__frame_make(const double *xyz, size_t count, plateau__frame *f,
                               double *scratch)
{
    double *d = scratch, *h = scratch + 3 * count, mx[3], lo[3], hi[3], big = 0.0, dmax, rmax, ss = 0.0;
    size_t i, i1, i2;
    int k, a, b;
    memset(f, 0, sizeof *f);
    for (k = 0; k < 3; k++) {
        f->axis[k] = k;
        f->sign[k] = 1.0;
        f->e[k][k] = 1.0;
    }
    f->p2 = f->s = f->unit = 1.0;
    if (count == 0) return plateau__frame_plain(f);
    for (k = 0; k < 3; k++) lo[k] = hi[k] = xyz[k]; /* step 1 */
    for (i = 1; i < count; i++)
        for (k = 0; k < 3; k++) {
            if (xyz[3 * i + (size_t)k] < lo[k]) lo[k] = xyz[3 * i + (size_t)k];
            if (xyz[3 * i + (size_t)k] > hi[k]) hi[k] = xyz[3 * i + (size_t)k];
        }
    for (k = 0; k < 3; k++) {
        f->c0[k] = lo[k] * 0.5 + hi[k] * 0.5;
        if (hi[k] * 0.5 - lo[k] * 0.5 > big) big = hi[k] * 0.5 - lo[k] * 0.5;
    }
    if (!(big > 0.0) || !plateau__util_finite(big)) return plateau__frame_plain(f);
    f->p2 = plateau__util_pow2_at_least(big);
    for (k = 0; k < 3; k++) { /* step 2 */
        for (i = 0; i < count; i++) d[3 * i + (size_t)k] = (xyz[3 * i + (size_t)k] - f->c0[k]) / f->p2;
        i1 = plateau__frame_first(d + k, count, 3, &mx[k]);
        f->sign[k] = d[3 * i1 + (size_t)k] < 0.0 ? -1.0 : 1.0;
    }
    for (a = 0; a < 3; a++) /* insertion sort of the three axes */
        for (b = a; b > 0 && plateau__frame_before(d, count, mx, f->sign, f->axis[b], f->axis[b - 1]); b--) {
            int t = f->axis[b];
            f->axis[b] = f->axis[b - 1];
            f->axis[b - 1] = t;
        }
    {
        double sg[3];
        for (k = 0; k < 3; k++) sg[k] = f->sign[f->axis[k]];
        for (k = 0; k < 3; k++) f->sign[k] = sg[k];
    }
    for (i = 0; i < count; i++) /* d: step 2's coordinates */
        for (k = 0; k < 3; k++) {
            int ax = f->axis[k];
            d[3 * i + (size_t)k] = f->sign[k] * ((xyz[3 * i + (size_t)ax] - f->c0[ax]) / f->p2);
        }
    for (k = 0; k < 3; k++) { /* step 3 */
        for (i = 0; i < count; i++) f->g[k] += d[3 * i + (size_t)k];
        f->g[k] /= (double)count;
    }
    for (i = 0; i < count; i++) {
        for (k = 0; k < 3; k++) d[3 * i + (size_t)k] -= f->g[k];
        h[i] = plateau__util_norm(d + 3 * i);
        ss += h[i] * h[i];
    }
    i1 = plateau__frame_first(h, count, 1, &dmax);
    if (!(h[i1] > 0.0)) return plateau__frame_plain(f);
    for (k = 0; k < 3; k++) f->e[0][k] = d[3 * i1 + (size_t)k] / h[i1];
    for (i = 0; i < count; i++) {
        double t = plateau__util_dot(d + 3 * i, f->e[0]), r[3];
        for (k = 0; k < 3; k++) r[k] = d[3 * i + (size_t)k] - t * f->e[0][k];
        h[i] = plateau__util_norm(r);
    }
    i2 = plateau__frame_first(h, count, 1, &rmax);
    if (!(h[i2] > 1e-12 * dmax)) return plateau__frame_plain(f);
    {
        double t = plateau__util_dot(d + 3 * i2, f->e[0]);
        for (k = 0; k < 3; k++) f->e[1][k] = (d[3 * i2 + (size_t)k] - t * f->e[0][k]) / h[i2];
    }
    plateau__frame_third(f, d, count, dmax, h);
    f->s = PLATEAU_SQRT(ss / (double)count); /* step 4 */
    f->unit = f->p2 * f->s;
    f->rounded = 1;
    return 0;
}

/* Points into the frame (in and out may be the same array), rounded to a
 * multiple of 2^-36 (step 4). */
static void plateau__frame_to(const plateau__frame *f, const double *in, size_t count,
                              double *out)
{
    size_t i;
    int k;
    for (i = 0; i < count; i++) {
        double y[3], q[3];
        for (k = 0; k < 3; k++) {
            int ax = f->axis[k];
            y[k] = f->sign[k] * ((in[3 * i + (size_t)ax] - f->c0[ax]) / f->p2) - f->g[k];
        }
        for (k = 0; k < 3; k++) {
            double t = plateau__util_dot(f->e[k], y) / f->s * 68719476736.0;
            /* |t| < 2^52: half away from zero by an exact conversion */
            if (f->rounded && PLATEAU_FABS(t) < 4503599627370496.0)
                t = (double)(int64_t)(t + (t < 0.0 ? -0.5 : 0.5));
            q[k] = t / 68719476736.0;
        }
        for (k = 0; k < 3; k++) out[3 * i + (size_t)k] = q[k];
    }
}

/* One point back to the caller's units. */
static void plateau__frame_from(const plateau__frame *f, const double *q, double *out)
{
    double y[3];
    int k;
    for (k = 0; k < 3; k++) y[k] = f->s * (f->e[0][k] * q[0] + f->e[1][k] * q[1] + f->e[2][k] * q[2]) + f->g[k];
    for (k = 0; k < 3; k++) out[f->axis[k]] = f->sign[k] * y[k] * f->p2 + f->c0[f->axis[k]];
}

/* x = m 2^e with m in [0.5, 1) (x > 0 finite, also subnormal); exact. */
static double plateau__frame_frexp(double x, int *e)
{
    int steps;
    *e = 0;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && x >= 1.0; steps++) { x *= 0.5; (*e)++; }
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && x < 0.5; steps++) { x *= 2.0; (*e)--; }
    return x;
}

/* m 2^e as a double: HUGE_VAL above DBL_MAX, 0 or a subnormal below
 * DBL_MIN (one rounding, in the last halving). */
static double plateau__frame_ldexp(double m, int e)
{
    int steps;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && e > 0 && plateau__util_finite(m); steps++, e--) m *= 2.0;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && e < 0 && m != 0.0; steps++, e++) m *= 0.5;
    return m;
}

/* v times unit^power (power +-2) in the caller's units, with the range
 * flags for F (a value that is finite and not 0 in the frame, but
 * HUGE_VAL or 0 / subnormal after). */
static double plateau__frame_units(double v, double p2, double s, int power, unsigned *range)
{
    int e2 = 0, e = 0;
    double m, t = p2;
    int steps;
    if (!(v != 0.0) || !plateau__util_finite(v)) return v;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && t > 1.0; steps++) { t *= 0.5; e2++; }
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && t < 1.0; steps++) { t *= 2.0; e2--; }
    m = plateau__frame_frexp(PLATEAU_FABS(power > 0 ? v * s * s : v / (s * s)), &e);
    m = plateau__frame_ldexp(m, e + (power > 0 ? 2 * e2 : -2 * e2));
    if (!plateau__util_finite(m)) *range |= PLATEAU_RANGE_F_OVERFLOW;
    else if (m < 2.2250738585072014e-308) *range |= PLATEAU_RANGE_F_UNDERFLOW;
    return v < 0.0 ? -m : m;
}

/* The area of mesh (in the caller's units) measured in the frame's
 * (unrounded): no square overflows or underflows at any scale. */
static double plateau__frame_area(const plateau_mesh *mesh, const plateau__frame *fr)
{
    plateau__frame plain = *fr;
    double a = 0.0;
    size_t t;
    int q;
    plain.rounded = 0;
    for (t = 0; t < mesh->num_triangles; t++) {
        double p[3][3], u[3], v[3], c[3];
        for (q = 0; q < 3; q++)
            plateau__frame_to(&plain, mesh->positions + 3 * (size_t)mesh->triangles[3 * t + (size_t)q], 1, p[q]);
        plateau__util_sub(p[1], p[0], u);
        plateau__util_sub(p[2], p[0], v);
        plateau__util_cross(u, v, c);
        a += 0.5 * plateau__util_norm(c);
    }
    return a;
}
#ifndef PLATEAU_NO_MEMBRANES /* used by the membranes only */
/* The frame's orientation: +1 when its linear part keeps the handedness,
 * -1 when it mirrors (the determinant's sign: step 2's signed axis
 * permutation times step 3's axes). */
static double plateau__frame_orientation(const plateau__frame *fr)
{
    double o = fr->sign[0] * fr->sign[1] * fr->sign[2], det;
    int a0 = fr->axis[0], a1 = fr->axis[1], a2 = fr->axis[2];
    /* the permutation's parity: even for the cyclic orders */
    if (!((a0 == 0 && a1 == 1 && a2 == 2) || (a0 == 1 && a1 == 2 && a2 == 0) || (a0 == 2 && a1 == 0 && a2 == 1)))
        o = -o;
    if (!fr->rounded) return o;
    det = fr->e[0][0] * (fr->e[1][1] * fr->e[2][2] - fr->e[1][2] * fr->e[2][1]) -
          fr->e[0][1] * (fr->e[1][0] * fr->e[2][2] - fr->e[1][2] * fr->e[2][0]) +
          fr->e[0][2] * (fr->e[1][0] * fr->e[2][1] - fr->e[1][1] * fr->e[2][0]);
    return det < 0.0 ? -o : o;
}
#endif

/* Back to the caller's units: free vertices by the inverse map of the
 * frame, fixed ones from original (3 values per fixed vertex, in vertex
 * order: a removed free vertex shifts the indices, never the order), and
 * the report's areas and objectives. */
static void plateau__frame_restore(plateau_mesh *mesh, const double *original,
                                   const plateau__frame *fr, plateau_report *rep)
{
    size_t v, f = 0;
    int k;
    for (v = 0; v < mesh->num_vertices; v++) {
        double *p = mesh->positions + 3 * v;
        if (mesh->fixed[v]) {
            for (k = 0; k < 3; k++) p[k] = original[3 * f + (size_t)k];
            f++;
        } else {
            double q[3];
            q[0] = p[0];
            q[1] = p[1];
            q[2] = p[2];
            plateau__frame_from(fr, q, p);
        }
    }
    /* the area of the mesh returned (its boundary as given, not the
     * frame's rounded one), summed in the frame and scaled once: its
     * significand and exponent exact, the double as far as it goes */
    {
        double a = plateau__frame_area(mesh, fr) * fr->s * fr->s;
        int e2 = 0, steps;
        double t = fr->p2;
        for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && t > 1.0; steps++) { t *= 0.5; e2++; }
        for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && t < 1.0; steps++) { t *= 2.0; e2--; }
        rep->area_significand = 0.0;
        rep->area_exponent = 0;
        rep->area = 0.0;
        if (a > 0.0 && plateau__util_finite(a)) {
            rep->area_significand = plateau__frame_frexp(a, &rep->area_exponent);
            rep->area_exponent += 2 * e2;
            rep->area = plateau__frame_ldexp(rep->area_significand, rep->area_exponent);
            if (!plateau__util_finite(rep->area)) rep->range |= PLATEAU_RANGE_AREA_OVERFLOW;
            else if (rep->area < 2.2250738585072014e-308) rep->range |= PLATEAU_RANGE_AREA_UNDERFLOW;
        }
    }
    {   /* method area's F is an area, method paper's 1/2 sum H^2: length^-2 */
        int power = rep->method == PLATEAU_METHOD_AREA ? 2 : -2;
        rep->f_initial = plateau__frame_units(rep->f_initial, fr->p2, fr->s, power, &rep->range);
        rep->f_final = plateau__frame_units(rep->f_final, fr->p2, fr->s, power, &rep->range);
        for (k = 0; k < PLATEAU_REPORT_F_ROUNDS; k++)
            rep->f_rounds[k] = plateau__frame_units(rep->f_rounds[k], fr->p2, fr->s, power, &rep->range);
    }
}
/* ======== END SECTION: the scale-free frame =============================== */

/* ======== SECTION: step 2: parameter domain (plateau__dom_) =============== */
/* A planar domain for the boundary: the best-fit plane, the circle, the plane
 * with holes or the annulus, then rounded to a canonical grid. */
/* ---- step 2: the parameter domain ---------------------------------------- */

/* Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations:
 * a is destroyed, w gets the eigenvalues, the columns of v the eigenvectors. */
/* Jacobi: converged when the off-diagonal squares are below
 * PLATEAU__DOM_JACOBI_DONE of the diagonal's; above PLATEAU__DOM_JACOBI_HUGE
 * the rotation's tangent is 1 / (2 theta), as theta^2 would overflow. */
#define PLATEAU__DOM_JACOBI_DONE 1e-36
#define PLATEAU__DOM_JACOBI_HUGE 1e150

static void plateau__dom_jacobi3(double a[3][3], double v[3][3], double w[3])
{
    static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    int sweep, r, c, pi;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 3; c++) v[r][c] = r == c ? 1.0 : 0.0;
    for (sweep = 0; sweep < 64; sweep++) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double dia = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off == 0.0 || off <= PLATEAU__DOM_JACOBI_DONE * dia) break;
        for (pi = 0; pi < 3; pi++) {
            int p = pairs[pi][0], q = pairs[pi][1];
            double apq = a[p][q], theta, t, cs, sn;
            if (apq == 0.0) continue;
            theta = (a[q][q] - a[p][p]) / (2.0 * apq);
            if (PLATEAU_FABS(theta) > PLATEAU__DOM_JACOBI_HUGE) {
                t = 0.5 / theta;
            } else {
                t = 1.0 / (PLATEAU_FABS(theta) + PLATEAU_SQRT(theta * theta + 1.0));
                if (theta < 0.0) t = -t;
            }
            cs = 1.0 / PLATEAU_SQRT(t * t + 1.0);
            sn = t * cs;
            a[p][p] -= t * apq;
            a[q][q] += t * apq;
            a[p][q] = a[q][p] = 0.0;
            for (r = 0; r < 3; r++) {
                double arp, arq;
                if (r == p || r == q) continue;
                arp = a[r][p];
                arq = a[r][q];
                a[r][p] = a[p][r] = cs * arp - sn * arq;
                a[r][q] = a[q][r] = sn * arp + cs * arq;
            }
            for (r = 0; r < 3; r++) {
                double vrp = v[r][p], vrq = v[r][q];
                v[r][p] = cs * vrp - sn * vrq;
                v[r][q] = sn * vrp + cs * vrq;
            }
        }
    }
    for (r = 0; r < 3; r++) w[r] = a[r][r];
}

static double plateau__dom_orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Step 2's planar test on one candidate pair: 1 (stop) when the
 * non-adjacent edges a and b cross or come within tol of each other. */
typedef struct plateau__dom_planar {
    const double *uv;
    size_t m;
    double tol2;
} plateau__dom_planar;

static int plateau__dom_planar_visit(void *ctx, size_t i, size_t j)
{
    const plateau__dom_planar *s = (const plateau__dom_planar *)ctx;
    const double *uv = s->uv;
    size_t m = s->m;
    const double *a = uv + 2 * i, *b = uv + 2 * ((i + 1) % m);
    const double *c = uv + 2 * j, *d = uv + 2 * ((j + 1) % m);
    double o1, o2, o3, o4, tol2 = s->tol2;
    if (j == i + 1 || (i == 0 && j == m - 1)) return 0; /* adjacent */
    o1 = plateau__dom_orient(a, b, c);
    o2 = plateau__dom_orient(a, b, d);
    o3 = plateau__dom_orient(c, d, a);
    o4 = plateau__dom_orient(c, d, b);
    if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
        ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
        return 1;
    if (plateau__util_seg_dist2(a, c, d) <= tol2 || plateau__util_seg_dist2(b, c, d) <= tol2 ||
        plateau__util_seg_dist2(c, a, b) <= tol2 || plateau__util_seg_dist2(d, a, b) <= tol2)
        return 1;
    return 0;
}

/* 1 when the closed polygon uv is simple with a safety distance: no two
 * non-adjacent edges within tol of each other, no vertex within tol of the
 * neighbouring edge it does not belong to (a fold or a zero-length edge);
 * 0 when not; -1 out of memory, -2 a size overflow.  The non-adjacent
 * pairs come from the grid of plateau__bnd_edge_pairs: O(m log m). */
static int plateau__dom_simple(const double *uv, size_t m, const plateau_allocator *allocator)
{
    plateau__dom_planar s;
    double tol2 = PLATEAU__REL_TOL2 * plateau__util_diag2(uv, m);
    size_t i;
    int r;
    if (!(tol2 > 0.0)) return 0;
    for (i = 0; i < m; i++) {
        const double *a = uv + 2 * ((i + m - 1) % m), *b = uv + 2 * i, *c = uv + 2 * ((i + 1) % m);
        if (plateau__util_seg_dist2(a, b, c) <= tol2 || plateau__util_seg_dist2(c, a, b) <= tol2)
            return 0;
    }
    s.uv = uv;
    s.m = m;
    s.tol2 = tol2;
    r = plateau__bnd_edge_pairs(uv, 2, m, PLATEAU_SQRT(tol2), allocator, plateau__dom_planar_visit, &s);
    return r < 0 ? r : !r;
}

/* Two in-plane variances closer than this fraction are a tie: the axis is
 * then chosen by the vertices, not by rounding. */
#define PLATEAU__DOM_AXIS_TIE 1e-3

/* The in-plane axis u of the plane domain, made canonical: a function of
 * the polygon alone, so that a scaled, moved or rotated copy gets the
 * same axis moved with it and its uv differ only by rounding (plateau_solve
 * then rounds that away).  The principal axis of largest variance when
 * that variance exceeds the other in-plane one by more than 1e-3 of it;
 * else (squares, regular polygons: equal variances, whose eigenvectors
 * rounding decides) the in-plane direction from the centroid of the first
 * vertex whose in-plane distance is at least half the largest.  Its sign:
 * the first vertex whose |u| is at least half the largest |u| gets u > 0.
 * d_i = xyz_i / cs - c; nrm is the plane's unit normal. */
static void plateau__dom_canonical_axis(const double *xyz, size_t m, double cs, const double *c,
                                       double w_big, double w_mid, const double *nrm, double *e1)
{
    size_t i;
    int k, pass;
    if (!(w_big - w_mid > PLATEAU__DOM_AXIS_TIE * w_big)) {
        double best = 0.0;
        for (pass = 0; pass < 2; pass++) {
            for (i = 0; i < m; i++) {
                double d[3], q[3], dn = 0.0, l2 = 0.0;
                for (k = 0; k < 3; k++) {
                    d[k] = xyz[3 * i + (size_t)k] / cs - c[k];
                    dn += d[k] * nrm[k];
                }
                for (k = 0; k < 3; k++) {
                    q[k] = d[k] - dn * nrm[k];
                    l2 += q[k] * q[k];
                }
                if (pass == 0) {
                    if (l2 > best) best = l2;
                } else if (l2 >= 0.25 * best && l2 > 0.0) {
                    double len = PLATEAU_SQRT(l2);
                    for (k = 0; k < 3; k++) e1[k] = q[k] / len;
                    break;
                }
            }
        }
    }
    {
        double best = 0.0;
        for (pass = 0; pass < 2; pass++) {
            for (i = 0; i < m; i++) {
                double u = 0.0;
                for (k = 0; k < 3; k++) u += (xyz[3 * i + (size_t)k] / cs - c[k]) * e1[k];
                if (pass == 0) {
                    if (PLATEAU_FABS(u) > best) best = PLATEAU_FABS(u);
                } else if (PLATEAU_FABS(u) >= 0.5 * best) {
                    if (u < 0.0)
                        for (k = 0; k < 3; k++) e1[k] = -e1[k];
                    break;
                }
            }
        }
    }
}

/* The best-fit plane of the m points xyz / cs: their centroid c, the unit
 * normal nrm along the axis of least variance of their covariance (cyclic
 * Jacobi rotations), the canonical in-plane axis e1
 * (plateau__dom_canonical_axis) and e2 = nrm x e1, so that (e1, e2, nrm)
 * is right-handed. */
static void plateau__dom_plane(const double *xyz, size_t m, double cs, double *c, double *e1,
                               double *e2, double *nrm)
{
    double cov[3][3], vec[3][3], w[3];
    size_t i;
    int k, l, big = 0, small = 0, mid;
    for (k = 0; k < 3; k++) c[k] = 0.0;
    for (i = 0; i < m; i++)
        for (k = 0; k < 3; k++) c[k] += xyz[3 * i + (size_t)k] / cs;
    for (k = 0; k < 3; k++) c[k] /= (double)m;
    memset(cov, 0, sizeof cov);
    for (i = 0; i < m; i++) {
        double d[3];
        for (k = 0; k < 3; k++) d[k] = xyz[3 * i + (size_t)k] / cs - c[k];
        for (k = 0; k < 3; k++)
            for (l = 0; l < 3; l++) cov[k][l] += d[k] * d[l];
    }
    plateau__dom_jacobi3(cov, vec, w);
    for (k = 1; k < 3; k++) {
        if (w[k] > w[big]) big = k;
        if (w[k] < w[small]) small = k;
    }
    if (big == small) small = (big + 1) % 3; /* isotropic: any axes do */
    mid = 3 - big - small;
    for (k = 0; k < 3; k++) {
        e1[k] = vec[k][big];
        nrm[k] = vec[k][small];
    }
    plateau__dom_canonical_axis(xyz, m, cs, c, w[big], w[mid], nrm, e1);
    plateau__util_cross(nrm, e1, e2);
}

PLATEAU_DEF plateau_result plateau_boundary_domain(const double *xyz, size_t m,
                                                   int force_circle,
                                                   const plateau_allocator *allocator,
                                                   double *uv, plateau_domain_kind *kind,
                                                   plateau_error *err)
{
    plateau_result r;
    size_t i;
    int k;
    double cs = 1.0;
    if (!uv || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          uv ? "the allocator sets only one of its two functions"
                             : "the uv output array is NULL", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    r = plateau__bnd_check(xyz, m, allocator, err);
    if (r != PLATEAU_OK) return r;
    /* the squares below (covariance, chord lengths) are taken on
     * coordinates divided by cs, the power of two at or above the largest
     * coordinate (2^1023 at most): exact, the same domain as unscaled
     * where nothing under- or overflows, finite at 1e+-300 */
    {
        double ext = 0.0;
        for (i = 0; i < 3 * m; i++)
            if (PLATEAU_FABS(xyz[i]) > ext) ext = PLATEAU_FABS(xyz[i]);
        cs = plateau__util_pow2_at_least(ext);
    }
    if (!force_circle) {
        double c[3], e1[3], e2[3], nrm[3];
        int simple;
        plateau__dom_plane(xyz, m, cs, c, e1, e2, nrm);
        for (i = 0; i < m; i++) {
            double d[3];
            for (k = 0; k < 3; k++) d[k] = xyz[3 * i + (size_t)k] / cs - c[k];
            uv[2 * i] = d[0] * e1[0] + d[1] * e1[1] + d[2] * e1[2];
            uv[2 * i + 1] = d[0] * e2[0] + d[1] * e2[1] + d[2] * e2[2];
        }
        simple = plateau__dom_simple(uv, m, allocator);
        if (simple < 0) {
            r = simple == -1 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_ERR_OVERFLOW;
            plateau__util_error(err, r, -1,
                              simple == -1 ? "out of memory while testing the plane domain"
                                           : "the test of the plane domain overflows", 0, 0);
            return r;
        }
        if (simple) {
            if (plateau__util_signed_area(uv, m) < 0.0)
                for (i = 0; i < m; i++) uv[2 * i + 1] = -uv[2 * i + 1];
            for (i = 0; i < 2 * m; i++) uv[i] *= cs; /* back to the units of xyz */
            if (kind) *kind = PLATEAU_DOMAIN_PLANE;
            return plateau__util_ok(err);
        }
    }
    {
        /* the circle: angle proportional to the chord length from vertex 0 */
        const double two_pi = 2.0 * PLATEAU__PI;
        double total = 0.0, s = 0.0, radius;
        for (i = 0; i < m; i++) {
            size_t j = (i + 1) % m;
            double d2 = 0.0;
            for (k = 0; k < 3; k++)
                d2 += (xyz[3 * j + (size_t)k] / cs - xyz[3 * i + (size_t)k] / cs) * (xyz[3 * j + (size_t)k] / cs - xyz[3 * i + (size_t)k] / cs);
            total += PLATEAU_SQRT(d2);
        }
        radius = total / two_pi;
        for (i = 0; i < m; i++) {
            double angle = two_pi * (s / total), d2 = 0.0;
            size_t j = (i + 1) % m;
            uv[2 * i] = radius * PLATEAU_COS(angle) * cs;
            uv[2 * i + 1] = radius * PLATEAU_SIN(angle) * cs;
            for (k = 0; k < 3; k++)
                d2 += (xyz[3 * j + (size_t)k] / cs - xyz[3 * i + (size_t)k] / cs) * (xyz[3 * j + (size_t)k] / cs - xyz[3 * i + (size_t)k] / cs);
            s += PLATEAU_SQRT(d2);
        }
        if (kind) *kind = PLATEAU_DOMAIN_CIRCLE;
    }
    return plateau__util_ok(err);
}

/* ---- step 2 for several loops ---------------------------------------------- */
/* Step 2's planar test between loops: 1 (stop) when edges of two different
 * loops cross or come within tol of each other in the plane. */
typedef struct plateau__dom_planar_loops {
    const double *uv;
    const size_t *next, *loop;
    double tol2;
} plateau__dom_planar_loops;

static int plateau__dom_planar_loops_visit(void *ctx, size_t i, size_t j)
{
    const plateau__dom_planar_loops *s = (const plateau__dom_planar_loops *)ctx;
    const double *a = s->uv + 2 * i, *b = s->uv + 2 * s->next[i];
    const double *c = s->uv + 2 * j, *d = s->uv + 2 * s->next[j];
    double o1, o2, o3, o4, tol2 = s->tol2;
    if (s->loop[i] == s->loop[j]) return 0;
    o1 = plateau__dom_orient(a, b, c);
    o2 = plateau__dom_orient(a, b, d);
    o3 = plateau__dom_orient(c, d, a);
    o4 = plateau__dom_orient(c, d, b);
    if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
        ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
        return 1;
    return plateau__util_seg_dist2(a, c, d) <= tol2 || plateau__util_seg_dist2(b, c, d) <= tol2 ||
           plateau__util_seg_dist2(c, a, b) <= tol2 || plateau__util_seg_dist2(d, a, b) <= tol2;
}

/* Step 2 for k >= 2 loops (plateau_solve_loops), on loops already checked
 * (plateau__bnd_loops_check) and moved into the unit frame.
 * PLANE WITH HOLES: the vertices of all loops are projected on their
 * common best-fit plane (the axes of plateau_boundary_domain); used when
 * every loop projects to a simple polygon, no two loops' projections come
 * within 1e-9 of the projection's diagonal of each other, and one loop
 * (the outer) holds all others while none of those holds another.  The
 * outer loop then runs counter-clockwise in uv (v is mirrored if needed);
 * each loop keeps its vertex order, and sign[j] records whether loop j
 * runs with the domain on its left (+1) or against (-1).
 * Otherwise, when all loops lie in one plane (within 1e-9 of the size)
 * they can bound only a plane region, and since it is not an outer
 * polygon with holes there is none: PLATEAU_ERR_LOOPS_NESTING (loops side
 * by side, or a loop inside a hole).  Else, for k > 2:
 * PLATEAU_ERR_LOOPS_DOMAIN.  Else (two loops in space, e.g. coaxial rings
 * whose projections coincide, or tilted rings side by side) ANNULUS: each
 * loop is laid by chord length on one of two concentric circles, the
 * longer loop outside on radius L_out / (2 pi), the other on rho times
 * that radius with
 *     rho = (L_in / L_out) exp(-2 pi d / ((L_in + L_out) / 2)),
 * d the distance between the loops' centroids: the ratio of the conformal
 * map of a cylinder of that height and mean circumference onto an annulus
 * (log r is the conformal coordinate along the cylinder), times the ratio
 * of the loops' lengths, which is the exact ratio for two concentric
 * coplanar circles.  On the catenoid between coaxial rings, whose
 * conformal ratio is exp(-h / a) (a the neck radius), it gives 0.61 for
 * 0.60 at h / R = 0.5 and 0.37 for 0.31 at h / R = 1: triangles refined
 * to be well shaped in the domain stay well shaped on the surface.  rho
 * is clamped to [0.05, 0.9].  Orientation and phase: the axis is the
 * loops' mean vector area (Newell's normal, the second turned to agree
 * with the first); each loop's angle starts at the direction of its
 * vertex 0 from its centroid around that axis and turns the way the loop
 * winds around it, so the initial mesh is neither twisted nor turned
 * inside out whichever way the loops are given.  The outer circle runs
 * counter-clockwise in uv.  area gets the domain's area.  force_annulus
 * (options.force_circle_domain) with two loops skips the plane. */
/* The vertices of all loops projected on their common best-fit plane (the
 * axes of plateau_boundary_domain): uv, the plane's unit normal nrm, the
 * largest distance of a vertex from the plane and the squared diagonal of
 * the loops' bounding box. */
static void plateau__dom_loops_project(const double *xyz, size_t M, double *uv, double *nrm,
                                       double *off_plane, double *diag2)
{
    double c[3], e1[3], e2[3], lo[3], hi[3];
    size_t i;
    int q;
    plateau__dom_plane(xyz, M, 1.0, c, e1, e2, nrm);
    *off_plane = 0.0;
    *diag2 = 0.0;
    for (q = 0; q < 3; q++) lo[q] = hi[q] = xyz[q];
    for (i = 0; i < M; i++) {
        double d[3], h;
        for (q = 0; q < 3; q++) {
            d[q] = xyz[3 * i + (size_t)q] - c[q];
            if (xyz[3 * i + (size_t)q] < lo[q]) lo[q] = xyz[3 * i + (size_t)q];
            if (xyz[3 * i + (size_t)q] > hi[q]) hi[q] = xyz[3 * i + (size_t)q];
        }
        uv[2 * i] = plateau__util_dot(d, e1);
        uv[2 * i + 1] = plateau__util_dot(d, e2);
        h = PLATEAU_FABS(plateau__util_dot(d, nrm));
        if (h > *off_plane) *off_plane = h;
    }
    for (q = 0; q < 3; q++) *diag2 += (hi[q] - lo[q]) * (hi[q] - lo[q]);
}

/* 1 when every loop projects to a simple polygon and no two loops'
 * projections come within the tolerance of each other; 0 when not; -1 out
 * of memory, -2 a size overflow. */
static int plateau__dom_loops_apart(const double *uv, const size_t *off, size_t k,
                                    const size_t *next, const size_t *loop,
                                    const plateau_allocator *allocator)
{
    plateau__dom_planar_loops s;
    size_t j, M = off[k];
    int r;
    for (j = 0; j < k; j++) {
        r = plateau__dom_simple(uv + 2 * off[j], off[j + 1] - off[j], allocator);
        if (r <= 0) return r;
    }
    s.uv = uv;
    s.next = next;
    s.loop = loop;
    s.tol2 = PLATEAU__REL_TOL2 * plateau__util_diag2(uv, M);
    r = plateau__bnd_edge_pairs_next(uv, 2, M, next, PLATEAU_SQRT(s.tol2), allocator,
                                     plateau__dom_planar_loops_visit, &s);
    return r < 0 ? r : r == 0;
}

/* The plane with holes, for loops whose projections are apart: when one
 * loop (the outer) holds all others and none of those holds another, the
 * outer loop is made counter-clockwise (v mirrored if needed), sign[j] is
 * +1 for a loop with the domain on its left, *area the domain's area, and
 * the result 1.  Otherwise 0, with *outer and *side two loops that no loop
 * holds, or *deep (< k) a loop inside a hole, for the error message.  The
 * nesting is tested at each loop's vertex 0. */
static int plateau__dom_loops_holes(double *uv, const size_t *off, size_t k, double *sign,
                                    double *area, size_t *outer, size_t *side, size_t *deep)
{
    size_t outers = 0, M = off[k], i, j;
    *outer = 0;
    *side = *deep = k;
    for (j = 0; j < k; j++) {
        size_t depth = 0, h;
        for (h = 0; h < k; h++)
            if (h != j && plateau_point_in_polygon(uv + 2 * off[h], off[h + 1] - off[h],
                                                   uv + 2 * off[j], 0.0))
                depth++;
        if (depth == 0) {
            if (outers++ == 0) *outer = j;
            else if (*side == k) *side = j;
        } else if (depth > 1 && *deep == k) {
            *deep = j;
        }
    }
    if (outers != 1 || *deep != k) return 0;
    if (plateau__util_signed_area(uv + 2 * off[*outer], off[*outer + 1] - off[*outer]) < 0.0)
        for (i = 0; i < M; i++) uv[2 * i + 1] = -uv[2 * i + 1];
    *area = 0.0;
    for (j = 0; j < k; j++) {
        double a = plateau__util_signed_area(uv + 2 * off[j], off[j + 1] - off[j]);
        sign[j] = (j == *outer) == (a > 0.0) ? 1.0 : -1.0;
        *area += j == *outer ? PLATEAU_FABS(a) : -PLATEAU_FABS(a);
    }
    return 1;
}

/* The annulus: a length below PLATEAU__DOM_TINY (the loops are in the unit
 * frame) is no direction; a cross product shorter than PLATEAU__DOM_ACROSS
 * is too short to normalise; the radius ratio is clamped to
 * [PLATEAU__DOM_RHO_MIN, PLATEAU__DOM_RHO_MAX]. */
#define PLATEAU__DOM_TINY 1e-12
#define PLATEAU__DOM_ACROSS 1e-6
#define PLATEAU__DOM_RHO_MIN 0.05
#define PLATEAU__DOM_RHO_MAX 0.9

/* The annulus of two loops (plateau__dom_loops): each laid by chord length
 * on one of two concentric circles, the longer loop outside; see there. */
static void plateau__dom_annulus(const double *xyz, const size_t *off, const size_t *next,
                                 const double *nrm, double *uv, double *sign, double *area)
{
    const double two_pi = 2.0 * PLATEAU__PI;
    double cj[2][3], nj[2][3], len[2], ax[3], e1[3], e2[3], dn, dc2 = 0.0, rho, rout, sg[2];
    size_t i, j, in, outer;
    int q;
    for (j = 0; j < 2; j++) {
        size_t m = off[j + 1] - off[j];
        for (q = 0; q < 3; q++) cj[j][q] = nj[j][q] = 0.0;
        len[j] = 0.0;
        for (i = off[j]; i < off[j + 1]; i++)
            for (q = 0; q < 3; q++) cj[j][q] += xyz[3 * i + (size_t)q] / (double)m;
        for (i = off[j]; i < off[j + 1]; i++) {
            double a[3], b[3], x[3];
            for (q = 0; q < 3; q++) {
                a[q] = xyz[3 * i + (size_t)q] - cj[j][q];
                b[q] = xyz[3 * next[i] + (size_t)q] - cj[j][q];
            }
            plateau__util_cross(a, b, x);
            for (q = 0; q < 3; q++) nj[j][q] += 0.5 * x[q];
            for (q = 0; q < 3; q++) a[q] = b[q] - a[q];
            len[j] += plateau__util_norm(a);
        }
    }
    /* the axis: the loops' mean vector area (Newell's normal, the second
     * turned to agree with the first); the plane's normal if it vanishes */
    dn = plateau__util_dot(nj[0], nj[1]) < 0.0 ? -1.0 : 1.0;
    {
        double l0 = plateau__util_norm(nj[0]), l1 = plateau__util_norm(nj[1]), la;
        for (q = 0; q < 3; q++)
            ax[q] = (l0 > 0.0 ? nj[0][q] / l0 : 0.0) + (l1 > 0.0 ? dn * nj[1][q] / l1 : 0.0);
        la = plateau__util_norm(ax);
        if (!(la > PLATEAU__DOM_TINY)) {
            for (q = 0; q < 3; q++) ax[q] = nrm[q];
        } else {
            for (q = 0; q < 3; q++) ax[q] /= la;
        }
    }
    /* e1: a unit vector across the axis (from loop 0's vertex 0) */
    {
        double d[3], t, l;
        for (q = 0; q < 3; q++) d[q] = xyz[3 * off[0] + (size_t)q] - cj[0][q];
        t = plateau__util_dot(d, ax);
        for (q = 0; q < 3; q++) e1[q] = d[q] - t * ax[q];
        l = plateau__util_norm(e1);
        if (!(l > PLATEAU__DOM_TINY)) {
            /* vertex 0 on the axis: any direction across it, (1, 1, 1) x ax
             * unless ax is along (1, 1, 1) */
            e1[0] = ax[1] - ax[2];
            e1[1] = ax[2] - ax[0];
            e1[2] = ax[0] - ax[1];
            if (plateau__util_norm(e1) < PLATEAU__DOM_ACROSS) { e1[0] = -ax[1]; e1[1] = ax[0]; e1[2] = 0.0; }
            l = plateau__util_norm(e1);
        }
        for (q = 0; q < 3; q++) e1[q] /= l;
        plateau__util_cross(ax, e1, e2);
    }
    for (j = 0; j < 2; j++) sg[j] = plateau__util_dot(nj[j], ax) < 0.0 ? -1.0 : 1.0;
    outer = len[1] > len[0] ? 1 : 0;
    in = 1 - outer;
    for (q = 0; q < 3; q++) dc2 += (cj[1][q] - cj[0][q]) * (cj[1][q] - cj[0][q]);
    rho = (len[in] / len[outer]) * plateau__util_exp_neg(two_pi * PLATEAU_SQRT(dc2) / (0.5 * (len[0] + len[1])));
    if (rho < PLATEAU__DOM_RHO_MIN) rho = PLATEAU__DOM_RHO_MIN;
    if (rho > PLATEAU__DOM_RHO_MAX) rho = PLATEAU__DOM_RHO_MAX;
    rout = len[outer] / two_pi;
    for (j = 0; j < 2; j++) {
        double d[3], phi0, s = 0.0, rad = j == outer ? rout : rho * rout;
        for (q = 0; q < 3; q++) d[q] = xyz[3 * off[j] + (size_t)q] - cj[j][q];
        phi0 = PLATEAU_ATAN2(plateau__util_dot(d, e2), plateau__util_dot(d, e1));
        for (i = off[j]; i < off[j + 1]; i++) {
            double t = sg[outer] * (phi0 + sg[j] * two_pi * (s / len[j])), e[3];
            uv[2 * i] = rad * PLATEAU_COS(t);
            uv[2 * i + 1] = rad * PLATEAU_SIN(t);
            for (q = 0; q < 3; q++) e[q] = xyz[3 * next[i] + (size_t)q] - xyz[3 * i + (size_t)q];
            s += plateau__util_norm(e);
        }
        /* the outer circle runs counter-clockwise, the inner one the way
         * its loop winds relative to the outer; the domain is on the left
         * of a clockwise hole */
        sign[j] = j == outer ? 1.0 : (sg[outer] * sg[j] < 0.0 ? 1.0 : -1.0);
    }
    *area = PLATEAU__PI * rout * rout * (1.0 - rho * rho);
}

static plateau_result plateau__dom_loops(const double *xyz, const size_t *off, size_t k,
                                         const size_t *next, const size_t *loop, int force_annulus,
                                         const plateau_allocator *allocator, double *uv,
                                         double *sign, double *area, plateau_domain_kind *kind,
                                         plateau_error *err)
{
    size_t outer, side, deep;
    double nrm[3], off_plane, diag2;
    int clean = 0, planar;
    long v[2];
    plateau__dom_loops_project(xyz, off[k], uv, nrm, &off_plane, &diag2);
    planar = off_plane <= PLATEAU__REL_TOL * PLATEAU_SQRT(diag2);
    if (!(force_annulus && k == 2)) {
        clean = plateau__dom_loops_apart(uv, off, k, next, loop, allocator);
        if (clean < 0) {
            plateau_result rc = clean == -1 ? PLATEAU_ERR_OUT_OF_MEMORY : PLATEAU_ERR_OVERFLOW;
            plateau__util_error(err, rc, -1, "out of memory while testing the plane domain of the loops", 0, 0);
            return rc;
        }
    }
    if (clean) {
        plateau_result rc = planar ? PLATEAU_ERR_LOOPS_NESTING : PLATEAU_ERR_LOOPS_DOMAIN;
        if (plateau__dom_loops_holes(uv, off, k, sign, area, &outer, &side, &deep)) {
            *kind = PLATEAU_DOMAIN_PLANE;
            return PLATEAU_OK;
        }
        if (planar || k > 2) {
            if (deep < k) {
                v[0] = (long)deep;
                plateau__util_error_n(err, rc, (long)off[deep],
                                      rc == PLATEAU_ERR_LOOPS_NESTING
                                          ? "loop @ lies inside a hole of the plane region the loops bound"
                                          : "loop @ lies inside a hole in the loops' best-fit plane; more than two loops need one outer loop with the others as holes",
                                      v, 1);
            } else {
                v[0] = (long)outer;
                v[1] = (long)side;
                plateau__util_error_n(err, rc, (long)off[side],
                                      rc == PLATEAU_ERR_LOOPS_NESTING
                                          ? "loops @ and @ lie side by side in one plane: neither holds the other"
                                          : "loops @ and @ lie side by side in the loops' best-fit plane; more than two loops need one outer loop with the others as holes",
                                      v, 2);
            }
            return rc;
        }
    } else if (k > 2) {
        plateau__util_error(err, PLATEAU_ERR_LOOPS_DOMAIN, -1,
                            "the loops' projections on their best-fit plane cross or touch; more than two loops need one outer loop with the others as holes in that plane",
                            0, 0);
        return PLATEAU_ERR_LOOPS_DOMAIN;
    } else if (planar && !(force_annulus && k == 2)) {
        plateau__util_error(err, PLATEAU_ERR_LOOPS_NESTING, -1,
                            "the two loops lie in one plane but their projections touch", 0, 0);
        return PLATEAU_ERR_LOOPS_NESTING;
    }
    plateau__dom_annulus(xyz, off, next, nrm, uv, sign, area);
    *kind = PLATEAU_DOMAIN_ANNULUS;
    return PLATEAU_OK;
}

/* The grid of the canonical domain: 2^36 steps across it. */
#define PLATEAU__DOM_GRID 68719476736.0

/* Invariance of the domain (step 2 in plateau_solve): uv divided by D, the
 * domain's bounding-box diagonal, rounded to a multiple of 2^-36, and
 * multiplied by P, the power of two at or above D.  A copy of the polygon
 * scaled by any factor, moved or rotated has, thanks to the canonical axes
 * of plateau__dom_canonical_axis, the same uv / D up to rounding; rounding
 * to 2^-36 (above that noise, far below the domain's tolerance
 * PLATEAU__REL_TOL) makes them equal bit for bit, and P makes the copies
 * differ by a power of two at most, which every later step carries
 * exactly.  So the seeding and the triangulation take the same decisions,
 * also on their exact ties (the cocircular points of a square or a regular
 * polygon), unless a value lies within rounding of a half-way point of the
 * grid (why 2^-36: examples/NOTES.md, "Measurements behind the solver's
 * choices").  Returns P / D, the factor by which domain lengths grew. */
static double plateau__dom_canonical(double *uv, size_t m)
{
    double d = PLATEAU_SQRT(plateau__util_diag2(uv, m)), p = 1.0;
    size_t i;
    int steps;
    if (!(d > 0.0) || !plateau__util_finite(d)) return 1.0;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && p < d; steps++) p *= 2.0;
    for (steps = 0; steps < PLATEAU__UTIL_POW2_STEPS && p * 0.5 >= d; steps++) p *= 0.5;
    for (i = 0; i < 2 * m; i++) {
        /* |t| <= 2^36: rounding half away from zero by an exact conversion,
         * symmetric in the sign */
        double t = uv[i] / d * PLATEAU__DOM_GRID;
        t = (double)(int64_t)(t + (t < 0.0 ? -0.5 : 0.5));
        uv[i] = t / PLATEAU__DOM_GRID * p;
    }
    return p / d;
}

/* ---- the step as plateau_solve runs it ---- */

/* Step 2 on the boundary moved into its canonical frame
 * (plateau__frame_make; *frame out): the domain of one polygon (plateau_boundary_domain) or
 * of several loops (plateau__dom_loops), made canonical, its edges in
 * s->seg; then the one decision whether method paper presolves by method
 * area (run->presolve): when forced, with cables, or automatically where
 * the domain is not the plane (the circle or the annulus: the seeded mesh
 * is folded in 3-D there). */
static plateau_result plateau__dom_step(plateau__cfg_work *s, const plateau__cfg *cfg,
                                        plateau__cfg_run *run, plateau_report *rep,
                                        plateau__frame *frame, double *dscale, plateau_error *err)
{
    size_t m = s->m, i;
    plateau_result rc;
    plateau__frame_make(s->boundary, m, frame, s->nb + 3 * m);
    plateau__frame_to(frame, s->boundary, m, s->nb);
    run->unit = frame->unit;
    if (s->loops <= 1 || !PLATEAU__HAVE_LOOPS)
        rc = plateau_boundary_domain(s->nb, m, cfg->force_circle, &s->alloc, s->uv, &rep->domain, err);
    else
        rc = plateau__dom_loops(s->nb, s->off, s->loops, s->next, s->loop, cfg->force_circle,
                                &s->alloc, s->uv, s->lsign, &s->area, &rep->domain, err);
    if (rc != PLATEAU_OK) return rc;
    run->presolve = cfg->paper_presolve == PLATEAU_ON || run->cable_nv > 0 ||
                    (cfg->paper_presolve == PLATEAU_AUTO && rep->domain != PLATEAU_DOMAIN_PLANE);
    *dscale = plateau__dom_canonical(s->uv, m);
    s->area *= *dscale * *dscale;
    for (i = 0; i < m; i++) {
        s->seg[2 * i] = (plateau_index)i;
        s->seg[2 * i + 1] = (plateau_index)(s->next ? s->next[i] : (i + 1) % m);
    }
    return PLATEAU_OK;
}
/* ======== END SECTION: step 2: parameter domain =========================== */

/* ======== SECTION: step 3: interior points (plateau__seed_) =============== */
/* The interior points: the paper's fan candidates (II.A), or the quality
 * seeding, which refines the domain with plateau_delaunay.h. */
/* ---- the generator: splitmix64 ------------------------------------------ */
PLATEAU_DEF void plateau_rng_seed(plateau_rng *rng, uint64_t seed)
{
    if (rng) rng->state = seed;
}

PLATEAU_DEF uint64_t plateau_rng_next(plateau_rng *rng)
{
    uint64_t z;
    if (!rng) return 0; /* like plateau_rng_seed(NULL): no crash, no state */
    rng->state += PLATEAU__U64(0x9E3779B9u, 0x7F4A7C15u);
    z = rng->state;
    z = (z ^ (z >> 30)) * PLATEAU__U64(0xBF58476Du, 0x1CE4E5B9u);
    z = (z ^ (z >> 27)) * PLATEAU__U64(0x94D049BBu, 0x133111EBu);
    return z ^ (z >> 31);
}

#define PLATEAU__SEED_TWO_POW_53 9007199254740992.0

PLATEAU_DEF double plateau_rng_uniform(plateau_rng *rng)
{
    return (double)(plateau_rng_next(rng) >> 11) * (1.0 / PLATEAU__SEED_TWO_POW_53);
}

/* ---- step 3: candidate points -------------------------------------------- */
PLATEAU_DEF int plateau_point_in_polygon(const double *uv, size_t m, const double p[2],
                                         double margin)
{
    size_t i;
    int inside = 0;
    double margin2;
    if (!uv || !p || m < 3) return 0;
    if (!(margin >= 0.0)) margin = 0.0;
    margin2 = margin * margin;
    for (i = 0; i < m; i++) {
        const double *a = uv + 2 * i, *b = uv + 2 * ((i + 1) % m);
        if ((a[1] > p[1]) != (b[1] > p[1])) {
            double x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if (p[0] < x) inside = !inside;
        }
        if (plateau__util_seg_dist2(p, a, b) <= margin2) return 0;
    }
    return inside;
}

/* ---- a uniform grid over the edges of the domain polygon ----
 * Cells of side h over the polygon's bounding box; each cell lists the
 * edges whose bounding box, grown by grow[e] on every side (grow NULL: 0;
 * an edge with a negative grow is left out), touches it.  Edge e runs from
 * vertex e to next[e] (next NULL: to (e + 1) % m).  h starts at the side
 * giving about `cells` cells and doubles until the lists hold at most
 * 16 (cells + m) + 64 entries (the sizing pass stops counting there), so
 * the build costs O(m + cells) time and memory whatever the edges.  Used
 * by the candidate test of step 3 and the graded size limit of 3q. */
typedef struct plateau__seed_egrid {
    double x0, y0, h; /* the lower-left corner and the cell side */
    size_t nx, ny;
    size_t *start;    /* nx * ny + 1: cell c lists item[start[c] .. start[c+1]) */
    size_t *item;     /* edge ids */
    const double *uv;
    const size_t *next;
    size_t m;
} plateau__seed_egrid;

static size_t plateau__seed_egrid_cell(double x, double origin, double h, size_t n)
{
    double d = (x - origin) / h;
    if (!(d > 0.0)) return 0; /* also NaN */
    if (d >= (double)n) return n - 1;
    return (size_t)d;
}

static size_t plateau__seed_egrid_end(const plateau__seed_egrid *g, size_t e)
{
    return g->next ? g->next[e] : (e + 1) % g->m;
}

/* The cell range [c[0], c[1]] x [c[2], c[3]] of edge e's box grown by r. */
static void plateau__seed_egrid_range(const plateau__seed_egrid *g, size_t e, double r, size_t *c)
{
    const double *a = g->uv + 2 * e, *b = g->uv + 2 * plateau__seed_egrid_end(g, e);
    c[0] = plateau__seed_egrid_cell((a[0] < b[0] ? a[0] : b[0]) - r, g->x0, g->h, g->nx);
    c[1] = plateau__seed_egrid_cell((a[0] > b[0] ? a[0] : b[0]) + r, g->x0, g->h, g->nx);
    c[2] = plateau__seed_egrid_cell((a[1] < b[1] ? a[1] : b[1]) - r, g->y0, g->h, g->ny);
    c[3] = plateau__seed_egrid_cell((a[1] > b[1] ? a[1] : b[1]) + r, g->y0, g->h, g->ny);
}

static void plateau__seed_egrid_free(plateau__seed_egrid *g, const plateau_allocator *allocator)
{
    plateau__free(allocator, g->start);
    plateau__free(allocator, g->item);
    g->start = NULL;
    g->item = NULL;
}

/* PLATEAU_OK or PLATEAU_ERR_OUT_OF_MEMORY (*g then holds nothing to free). */
static plateau_result plateau__seed_egrid_build(plateau__seed_egrid *g, const double *uv, size_t m,
                                              const size_t *next, const double *grow,
                                              double cells, const plateau_allocator *allocator)
{
    double lo[2], hi[2], w, ht, cap = 16.0 * (cells + (double)m) + 64.0, ent = 0.0;
    size_t i, e, x, y, c, ncell, r[4];
    int tries;
    memset(g, 0, sizeof *g);
    g->uv = uv;
    g->m = m;
    g->next = next;
    lo[0] = hi[0] = uv[0];
    lo[1] = hi[1] = uv[1];
    for (i = 1; i < m; i++)
        for (c = 0; c < 2; c++) {
            if (uv[2 * i + c] < lo[c]) lo[c] = uv[2 * i + c];
            if (uv[2 * i + c] > hi[c]) hi[c] = uv[2 * i + c];
        }
    g->x0 = lo[0];
    g->y0 = lo[1];
    w = hi[0] - lo[0];
    ht = hi[1] - lo[1];
    if (!(cells >= 1.0)) cells = 1.0;
    g->h = PLATEAU_SQRT(w * ht / cells);
    if (!(g->h * cells >= (w > ht ? w : ht))) g->h = (w > ht ? w : ht) / cells;
    if (!(g->h > 0.0) || !plateau__util_finite(g->h)) g->h = 1.0;
    for (tries = 0; tries < PLATEAU__UTIL_POW2_STEPS; tries++, g->h *= 2.0) {
        /* A side of more cells than the whole grid may hold (or a count
           that is not finite: extents near the double range) would fail
           the test below anyway; skip it before converting to size_t. */
        if (!(w / g->h < 4.0 * cells + 4.0 && ht / g->h < 4.0 * cells + 4.0)) continue;
        g->nx = (size_t)(w / g->h) + 1;
        g->ny = (size_t)(ht / g->h) + 1;
        ent = 0.0;
        for (e = 0; e < m && ent <= cap; e++) {
            if (grow && !(grow[e] >= 0.0)) continue;
            plateau__seed_egrid_range(g, e, grow ? grow[e] : 0.0, r);
            ent += (double)(r[1] - r[0] + 1) * (double)(r[3] - r[2] + 1);
        }
        if (ent <= cap && (double)g->nx * (double)g->ny <= 4.0 * cells + 4.0) break;
    }
    if (tries == PLATEAU__UTIL_POW2_STEPS) { /* no size fitted: one cell holds every edge */
        g->nx = g->ny = 1;
        ent = (double)m;
    }
    ncell = g->nx * g->ny;
    g->start = (size_t *)plateau__util_array(allocator, ncell + 1, sizeof(size_t));
    g->item = (size_t *)plateau__util_array(allocator, (size_t)ent + 1, sizeof(size_t));
    if (!g->start || !g->item) {
        plateau__seed_egrid_free(g, allocator);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    /* counting sort of (cell, edge): counts, prefix sums, fill */
    for (c = 0; c <= ncell; c++) g->start[c] = 0;
    for (i = 0; i < 2; i++) {
        for (e = 0; e < m; e++) {
            if (grow && !(grow[e] >= 0.0)) continue;
            plateau__seed_egrid_range(g, e, grow ? grow[e] : 0.0, r);
            for (y = r[2]; y <= r[3]; y++)
                for (x = r[0]; x <= r[1]; x++) {
                    if (i == 0) g->start[y * g->nx + x + 1]++;
                    else g->item[g->start[y * g->nx + x]++] = e;
                }
        }
        if (i == 0)
            for (c = 0; c < ncell; c++) g->start[c + 1] += g->start[c];
    }
    /* the fill moved every start one cell on */
    for (c = ncell; c > 0; c--) g->start[c] = g->start[c - 1];
    g->start[0] = 0;
    return PLATEAU_OK;
}

/* plateau_point_in_polygon(uv, m, p, margin) for the grid's one polygon
 * (built with grow NULL), the same value from the same comparisons on the
 * edges that can change it: those in the 3 x 3 cells around p for the
 * margin (margin below h / 2, so that a point within margin of p lies in
 * one of them) and those in p's row from the column left of p's on for the
 * crossings of the ray to +x (an edge wholly further left has x < p[0] at
 * the height of p; each edge counted once, in the first of its cells the
 * scan meets).  O(9 cells + one row) instead of O(m). */
static int plateau__seed_egrid_inside(const plateau__seed_egrid *g, const double p[2], double margin)
{
    size_t cx = plateau__seed_egrid_cell(p[0], g->x0, g->h, g->nx);
    size_t cy = plateau__seed_egrid_cell(p[1], g->y0, g->h, g->ny);
    size_t x, y, j, from;
    double margin2;
    int inside = 0;
    if (!(margin >= 0.0)) margin = 0.0;
    margin2 = margin * margin;
    for (y = cy > 0 ? cy - 1 : 0; y <= cy + 1 && y < g->ny; y++)
        for (x = cx > 0 ? cx - 1 : 0; x <= cx + 1 && x < g->nx; x++)
            for (j = g->start[y * g->nx + x]; j < g->start[y * g->nx + x + 1]; j++) {
                size_t e = g->item[j];
                if (plateau__util_seg_dist2(p, g->uv + 2 * e, g->uv + 2 * plateau__seed_egrid_end(g, e)) <= margin2)
                    return 0;
            }
    /* p above or below every edge: no crossing */
    if (!(p[1] >= g->y0) || !(p[1] < g->y0 + (double)g->ny * g->h)) return 0;
    from = cx > 0 ? cx - 1 : 0;
    for (x = from; x < g->nx; x++)
        for (j = g->start[cy * g->nx + x]; j < g->start[cy * g->nx + x + 1]; j++) {
            size_t e = g->item[j], r[4];
            const double *a = g->uv + 2 * e, *b = g->uv + 2 * plateau__seed_egrid_end(g, e);
            plateau__seed_egrid_range(g, e, 0.0, r);
            if (x != (r[0] > from ? r[0] : from)) continue;
            if ((a[1] > p[1]) != (b[1] > p[1])) {
                double xc = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if (p[0] < xc) inside = !inside;
            }
        }
    return inside;
}

/* A candidate's inside test: by the grid when it was built, else the scan. */
static unsigned char plateau__seed_candidate_inside(const plateau__seed_egrid *g, const double *uv,
                                                  size_t m, const double *p, double margin)
{
    return (unsigned char)(g->start ? plateau__seed_egrid_inside(g, p, margin)
                                    : plateau_point_in_polygon(uv, m, p, margin));
}

/* The point table: boundary vertices 0..m-1, the centroid m, then every
 * candidate in generation order, each as xyz (3) and uv (2). */
typedef struct plateau__seed_table {
    double *pt;          /* 5 * capacity */
    size_t count, capacity;
    unsigned char *inside; /* per point: 1 = an inside candidate */
} plateau__seed_table;

/* Makes room for need candidates in the table (doubling from 64, the
 * entries kept).  PLATEAU_OK, _OVERFLOW or _OUT_OF_MEMORY (the table is
 * unchanged then). */
static plateau_result plateau__seed_grow(plateau__seed_table *tab, size_t need,
                                       const plateau_allocator *allocator)
{
    size_t cap = tab->capacity ? tab->capacity : 64, bytes, k;
    double *pt;
    unsigned char *inside;
    if (need <= tab->capacity) return PLATEAU_OK;
    while (cap < need && cap <= (size_t)-1 / 2) cap *= 2;
    if (cap < need) return PLATEAU_ERR_OVERFLOW;
    bytes = plateau__bytes(cap, 5 * sizeof(double));
    if (bytes == 0) return PLATEAU_ERR_OVERFLOW;
    pt = (double *)plateau__alloc(allocator, bytes);
    inside = (unsigned char *)plateau__alloc(allocator, cap);
    if (!pt || !inside) {
        plateau__free(allocator, pt);
        plateau__free(allocator, inside);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (k = 0; k < 5 * tab->count; k++) pt[k] = tab->pt[k];
    for (k = 0; k < tab->count; k++) inside[k] = tab->inside[k];
    plateau__free(allocator, tab->pt);
    plateau__free(allocator, tab->inside);
    tab->pt = pt;
    tab->inside = inside;
    tab->capacity = cap;
    return PLATEAU_OK;
}

/* The argument checks of plateau_seed_points_rule. */
static plateau_result plateau__seed_args(const double *xyz, const double *uv, size_t m, size_t n,
                                         plateau_seed_rule rule, const plateau_allocator *allocator,
                                         const double *xyz_out, const double *uv_out,
                                         const size_t *count, plateau_error *err)
{
    size_t i;
    if (!xyz || !uv || !count || (n > 0 && (!xyz_out || !uv_out)) ||
        !plateau__allocator_valid(allocator) ||
        (rule != PLATEAU_SEED_WHOLE_LEVELS && rule != PLATEAU_SEED_LAST_LEVEL &&
         rule != PLATEAU_SEED_LITERAL)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_seed_points: a NULL array, a bad allocator or an unknown rule",
                            0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (m < 3) {
        plateau__util_error(err, PLATEAU_ERR_TOO_FEW_VERTICES, (long)m,
                            "the polygon has @ vertices; it needs at least 3", (long)m, 0);
        return PLATEAU_ERR_TOO_FEW_VERTICES;
    }
    if (m > (size_t)PLATEAU_INDEX_MAX) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many boundary vertices", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    for (i = 0; i < 2 * m; i++) {
        if (!plateau__util_finite(uv[i])) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)(i / 2),
                                "domain vertex @ is NaN or infinite", (long)(i / 2), 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    }
    return PLATEAU_OK;
}

/* The candidates (paper II.A): the boundary and the centroid (level 0)
 * into the table, then the barycentres of the closed fan (level 1) and of
 * every triangle's three children, level by level, until the levels hold
 * n inside candidates (the last level alone, for PLATEAU_SEED_LAST_LEVEL)
 * or the bounds PLATEAU_SEED_MAX_LEVELS / _LEVEL_SIZE stop them.  *tri (the
 * caller frees it) holds the last level's triangles; the draw chooses from
 * the candidates from *pool_begin on. */
static plateau_result plateau__seed_levels(plateau__seed_table *tab, size_t **tri, const double *xyz,
                                           const double *uv, size_t m, size_t n, plateau_seed_rule rule,
                                           const plateau__seed_egrid *grid,
                                           const plateau_allocator *allocator, size_t *pool_begin)
{
    size_t *next, ntri = 0, level_size = m, i, k, level_begin = m, found_all, found_level;
    double margin = PLATEAU__REL_TOL * PLATEAU_SQRT(plateau__util_diag2(uv, m)), *c;
    int level = 0;
    plateau_result result = plateau__seed_grow(tab, m + 1 + m, allocator);
    if (result != PLATEAU_OK) return result;
    for (i = 0; i < m; i++) {
        for (k = 0; k < 3; k++) tab->pt[5 * i + k] = xyz[3 * i + k];
        tab->pt[5 * i + 3] = uv[2 * i];
        tab->pt[5 * i + 4] = uv[2 * i + 1];
        tab->inside[i] = 0;
    }
    c = tab->pt + 5 * m; /* level 0: the centroid, as the mean in xyz and in uv */
    for (k = 0; k < 5; k++) c[k] = 0.0;
    for (i = 0; i < m; i++) {
        for (k = 0; k < 3; k++) c[k] += xyz[3 * i + k];
        c[3] += uv[2 * i];
        c[4] += uv[2 * i + 1];
    }
    for (k = 0; k < 5; k++) c[k] /= (double)m;
    tab->inside[m] = plateau__seed_candidate_inside(grid, uv, m, c + 3, margin);
    tab->count = m + 1;
    *pool_begin = m;
    found_all = found_level = tab->inside[m];
    while ((rule == PLATEAU_SEED_LAST_LEVEL ? found_level : found_all) < n) {
        size_t bytes;
        if (level + 1 > PLATEAU_SEED_MAX_LEVELS || level_size > (size_t)PLATEAU_SEED_MAX_LEVEL_SIZE) break;
        /* the triangles of level + 1: the closed fan, or the children
         * (a, b, g), (a, c, g), (b, c, g) of every triangle of the
         * previous level, g that triangle's candidate */
        bytes = plateau__bytes(level_size, 3 * sizeof(size_t));
        if (bytes == 0) return PLATEAU_ERR_OVERFLOW;
        next = (size_t *)plateau__alloc(allocator, bytes);
        if (!next) return PLATEAU_ERR_OUT_OF_MEMORY;
        for (i = 0; i < (level == 0 ? m : ntri); i++) {
            size_t *o = next + (level == 0 ? 3 * i : 9 * i);
            if (level == 0) {
                o[0] = (i + m - 1) % m; o[1] = i; o[2] = m;
            } else {
                size_t a = (*tri)[3 * i], b = (*tri)[3 * i + 1], cc = (*tri)[3 * i + 2], g = level_begin + i;
                o[0] = a; o[1] = b; o[2] = g;
                o[3] = a; o[4] = cc; o[5] = g;
                o[6] = b; o[7] = cc; o[8] = g;
            }
        }
        plateau__free(allocator, *tri);
        *tri = next;
        ntri = level_size;
        level++;
        /* their barycentres: the candidates of this level */
        if (tab->count > (size_t)-1 - ntri) return PLATEAU_ERR_OVERFLOW;
        result = plateau__seed_grow(tab, tab->count + ntri, allocator);
        if (result != PLATEAU_OK) return result;
        level_begin = tab->count;
        if (rule == PLATEAU_SEED_LAST_LEVEL) *pool_begin = level_begin;
        found_level = 0;
        for (i = 0; i < ntri; i++) {
            const double *pa = tab->pt + 5 * (*tri)[3 * i], *pb = tab->pt + 5 * (*tri)[3 * i + 1];
            const double *pc = tab->pt + 5 * (*tri)[3 * i + 2];
            double *g = tab->pt + 5 * (level_begin + i);
            for (k = 0; k < 5; k++) g[k] = (pa[k] + pb[k] + pc[k]) / 3.0;
            tab->inside[level_begin + i] = plateau__seed_candidate_inside(grid, uv, m, g + 3, margin);
            found_level += tab->inside[level_begin + i];
        }
        tab->count += ntri;
        found_all += found_level;
        if (ntri > (size_t)-1 / 3) break;
        level_size = 3 * ntri;
    }
    return PLATEAU_OK;
}

/* The selection of n of the inside candidates from pool_begin on: the
 * first n in generation order (PLATEAU_SEED_LITERAL, or all of them when
 * there are no more), else a partial Fisher-Yates draw with the seeded
 * generator, the drawn ones kept in generation order; written to xyz_out
 * and uv_out, their count to *count. */
static plateau_result plateau__seed_select(plateau__seed_table *tab, size_t pool_begin, size_t n,
                                           uint64_t seed, plateau_seed_rule rule,
                                           const plateau_allocator *allocator, double *xyz_out,
                                           double *uv_out, size_t *count)
{
    size_t avail = 0, take, i, j, k, *pool;
    for (i = pool_begin; i < tab->count; i++) avail += tab->inside[i];
    take = avail < n ? avail : n;
    if (rule == PLATEAU_SEED_LITERAL || take == avail) {
        size_t left = take;
        for (i = pool_begin; i < tab->count; i++) {
            if (tab->inside[i] && left > 0) left--;
            else tab->inside[i] = 0;
        }
    } else {
        plateau_rng rng;
        size_t bytes = plateau__bytes(avail, sizeof(size_t));
        if (bytes == 0) return PLATEAU_ERR_OVERFLOW;
        pool = (size_t *)plateau__alloc(allocator, bytes);
        if (!pool) return PLATEAU_ERR_OUT_OF_MEMORY;
        j = 0;
        for (i = pool_begin; i < tab->count; i++)
            if (tab->inside[i]) pool[j++] = i;
        plateau_rng_seed(&rng, seed);
        for (i = 0; i < take; i++) {
            size_t pick = i + (size_t)(plateau_rng_uniform(&rng) * (double)(avail - i));
            size_t t;
            if (pick >= avail) pick = avail - 1;
            t = pool[i]; pool[i] = pool[pick]; pool[pick] = t;
        }
        for (i = take; i < avail; i++) tab->inside[pool[i]] = 0;
        plateau__free(allocator, pool);
    }
    j = 0;
    for (i = pool_begin; i < tab->count; i++) {
        if (!tab->inside[i]) continue;
        for (k = 0; k < 3; k++) xyz_out[3 * j + k] = tab->pt[5 * i + k];
        uv_out[2 * j] = tab->pt[5 * i + 3];
        uv_out[2 * j + 1] = tab->pt[5 * i + 4];
        j++;
    }
    *count = j;
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_seed_points_rule(const double *xyz, const double *uv,
                                                    size_t m, size_t n, uint64_t seed,
                                                    plateau_seed_rule rule,
                                                    const plateau_allocator *allocator,
                                                    double *xyz_out, double *uv_out,
                                                    size_t *count, plateau_error *err)
{
    plateau_result result;
    plateau__seed_table tab;
    plateau__seed_egrid grid;
    size_t *tri = NULL, pool_begin = m;
    memset(&grid, 0, sizeof grid);
    tab.pt = NULL;
    tab.inside = NULL;
    tab.count = tab.capacity = 0;
    if (count) *count = 0;
    result = plateau__seed_args(xyz, uv, m, n, rule, allocator, xyz_out, uv_out, count, err);
    if (result != PLATEAU_OK) return result;
    if (n == 0) return plateau__util_ok(err);
    /* the candidates' inside test by a grid of the domain's edges: the
     * same answers as plateau_point_in_polygon in O(sqrt m) each, not O(m)
     * (the scan when the margin is not far below the cell side) */
    result = plateau__seed_egrid_build(&grid, uv, m, NULL, NULL, (double)m, allocator);
    if (result == PLATEAU_OK &&
        !(PLATEAU__REL_TOL * PLATEAU_SQRT(plateau__util_diag2(uv, m)) < 0.25 * grid.h))
        plateau__seed_egrid_free(&grid, allocator);
    if (result == PLATEAU_OK)
        result = plateau__seed_levels(&tab, &tri, xyz, uv, m, n, rule, &grid, allocator, &pool_begin);
    if (result == PLATEAU_OK)
        result = plateau__seed_select(&tab, pool_begin, n, seed, rule, allocator, xyz_out, uv_out, count);
    plateau__seed_egrid_free(&grid, allocator);
    plateau__free(allocator, tab.pt);
    plateau__free(allocator, tab.inside);
    plateau__free(allocator, tri);
    if (result == PLATEAU_ERR_OUT_OF_MEMORY) {
        plateau__util_error(err, result, -1, "out of memory while generating candidate points", 0, 0);
        return result;
    }
    if (result != PLATEAU_OK) {
        plateau__util_error(err, result, -1, "the number of candidate points overflows", 0, 0);
        return result;
    }
    return plateau__util_ok(err);
}

PLATEAU_DEF plateau_result plateau_seed_points(const double *xyz, const double *uv, size_t m,
                                               size_t n, uint64_t seed,
                                               const plateau_allocator *allocator,
                                               double *xyz_out, double *uv_out,
                                               size_t *count, plateau_error *err)
{
    return plateau_seed_points_rule(xyz, uv, m, n, seed, PLATEAU_SEED_WHOLE_LEVELS, allocator,
                                    xyz_out, uv_out, count, err);
}

/* ---- steps 3-4 with options.seeding = PLATEAU_SEEDING_QUALITY ----
 * The domain polygon of step 2 is refined by plateau_delaunay.h (its step 6:
 * Ruppert 1995, Shewchuk 2002, Miller, Pav and Walkington 2002): no angle
 * below the bound (except where keep_segments leaves a triangle at the
 * boundary as it is) and no triangle above an area limit.  The limit comes
 * from options.quality_edge_length (the area of the equilateral triangle
 * of that side) or is searched for so that the refinement adds about
 * interior_points interior vertices: a triangulation with n interior and m
 * boundary vertices has 2n + m - 2 triangles, and refined triangles end up
 * around half the limit, so the search starts at 2 A / (2n + m) (A the
 * domain's area), doubles or halves until the count is bracketed, then
 * bisects the bracket geometrically; at most 20 refinements, the closest
 * count kept (the first one on a tie).  Deterministic: no randomness. */
typedef struct plateau__seed_quality {
    plateau_allocator alloc;
    double min_angle;  /* degrees */
    int refine_boundary;
    size_t budget;     /* max_added_points of one refinement (0: the default) */
    const double *uv;  /* the domain polygon, for the graded limit */
    size_t m;
    double amax;       /* the limit away from the boundary */
    double grading;    /* the slope of the graded limit; 0: none (amax everywhere) */
    const size_t *next; /* several loops: edge e ends at vertex next[e]; NULL:
                           one polygon, edge e ends at (e + 1) % m */
    double area;       /* several loops: the domain's area (outer minus holes);
                          0: the signed area of the one polygon */
    struct plateau__util_budget *time_budget; /* no new refinement once it ran
                          out (the best one so far is kept); NULL: none */
} plateau__seed_quality;

/* The graded area limit when the polygon is kept (keep_segments): a
 * triangle on a polygon edge of length L cannot be refined below about
 * the equilateral area on L without splitting the edge, and forcing it
 * (plateau_delaunay.h then inserts centroids) gives angles of a few
 * degrees (examples/NOTES.md).  So the limit at p is
 * the larger of amax and the equilateral area on the size
 * h(p) = max over edges e of (L_e - PLATEAU__SEED_GRADING * dist(p, e)):
 * edges keep their own size nearby, and the size falls to the interior
 * one with slope PLATEAU__SEED_GRADING. */
#define PLATEAU__SEED_GRADING 0.5

#define PLATEAU__SEED_AUTO_REFINE 2.0

/* The query structure of that limit, built per refinement (amax and the
 * slope g change between them).  Only edges longer than the cut h0 (the
 * size whose equilateral area is amax, less a hair) can raise the limit
 * above amax, and only within (L_e - h0) / g of themselves: those enter a
 * grid of the domain's edges (plateau__seed_egrid) with that reach.  In a
 * square of centre c and side s, an edge's term lies in
 * [L_e - g (d(c, e) + r), L_e - g max(0, d(c, e) - r)] (r = 0.75 s, above
 * the half-diagonal); an edge whose upper bound is below another's lower
 * bound, or below h0, cannot give the maximum there and is dropped, the
 * rest sorted by upper bound, largest first, so that a query stops at the
 * first edge that cannot beat the best so far.  A grid cell with more than
 * PLATEAU__SEED_GRADED_LEAF edges left is split into four, down to 10
 * levels while the structure holds at most 32 (m + cells) + 1024 entries
 * (a quadtree: halving the square halves the bounds' gap, so near a point
 * where many long edges meet fewer of them stay candidates).  The value is
 * the scan's over all edges bit for bit (the same maximum of the same
 * terms; the bounds carry a slack of 1e-12 of the domain's size against
 * rounding).  Work per query: the levels descended and the entries read
 * (counted in visits): none on a densely sampled boundary (no edge is
 * above h0), a few on smooth polygons, at most the leaf's list. */
#define PLATEAU__SEED_GRADED_LEAF 8
typedef struct plateau__seed_graded_node {
    double x, y, s;     /* lower-left corner and side of the square */
    size_t first, count; /* its entries */
    size_t child;       /* the first of its four children (0: a leaf) */
    int depth;
} plateau__seed_graded_node;

typedef struct plateau__seed_graded {
    const plateau__seed_quality *q;
    double x0, y0, h;   /* the grid of the root squares */
    size_t nx, ny;
    plateau__seed_graded_node *node;
    size_t nodes, node_cap;
    size_t *item;       /* entries: an edge and its upper bound in its square */
    double *ub;
    size_t items, item_cap;
    double h0, slack;
    size_t calls, visits; /* work counters: queries, squares and entries read */
} plateau__seed_graded;

static double plateau__seed_graded_term(const plateau__seed_quality *q, size_t e, const double *p)
{
    const double *a0 = q->uv + 2 * e, *b0 = q->uv + 2 * (q->next ? q->next[e] : (e + 1) % q->m);
    double dx = b0[0] - a0[0], dy = b0[1] - a0[1];
    return PLATEAU_SQRT(dx * dx + dy * dy) - q->grading * PLATEAU_SQRT(plateau__util_seg_dist2(p, a0, b0));
}

typedef struct plateau__seed_graded_entry {
    double ub;
    size_t e;
} plateau__seed_graded_entry;

static int plateau__seed_graded_cmp(const void *pa, const void *pb)
{
    const plateau__seed_graded_entry *a = (const plateau__seed_graded_entry *)pa;
    const plateau__seed_graded_entry *b = (const plateau__seed_graded_entry *)pb;
    if (a->ub != b->ub) return a->ub > b->ub ? -1 : 1;
    return a->e < b->e ? -1 : a->e > b->e ? 1 : 0;
}

static void plateau__seed_graded_free(plateau__seed_graded *gr)
{
    plateau__free(&gr->q->alloc, gr->node);
    plateau__free(&gr->q->alloc, gr->item);
    plateau__free(&gr->q->alloc, gr->ub);
    gr->node = NULL;
    gr->item = NULL;
    gr->ub = NULL;
}

/* Room for one more node and for `more` more entries (capacities doubled,
 * contents kept).  0, or -1 when out of memory (gr unchanged). */
static int plateau__seed_graded_room(plateau__seed_graded *gr, size_t more)
{
    const plateau_allocator *a = &gr->q->alloc;
    if (gr->nodes == gr->node_cap) {
        size_t cap = gr->node_cap ? 2 * gr->node_cap : 64;
        plateau__seed_graded_node *n = (plateau__seed_graded_node *)plateau__util_array(a, cap, sizeof *n);
        if (!n) return -1;
        if (gr->nodes) memcpy(n, gr->node, gr->nodes * sizeof *n);
        plateau__free(a, gr->node);
        gr->node = n;
        gr->node_cap = cap;
    }
    if (gr->items + more > gr->item_cap) {
        size_t cap = gr->item_cap ? gr->item_cap : 64;
        size_t *it;
        double *ub;
        while (cap < gr->items + more) cap *= 2;
        it = (size_t *)plateau__util_array(a, cap, sizeof(size_t));
        ub = (double *)plateau__util_array(a, cap, sizeof(double));
        if (!it || !ub) {
            plateau__free(a, it);
            plateau__free(a, ub);
            return -1;
        }
        if (gr->items) {
            memcpy(it, gr->item, gr->items * sizeof(size_t));
            memcpy(ub, gr->ub, gr->items * sizeof(double));
        }
        plateau__free(a, gr->item);
        plateau__free(a, gr->ub);
        gr->item = it;
        gr->ub = ub;
        gr->item_cap = cap;
    }
    return 0;
}

/* Appends the square (x, y, s) at depth with the candidates cand[0 .. k)
 * pruned and sorted (see plateau__seed_graded); tmp holds k entries.
 * 0, or -1 when out of memory. */
static int plateau__seed_graded_square(plateau__seed_graded *gr, double x, double y, double s,
                                      int depth, const size_t *cand, size_t k,
                                      plateau__seed_graded_entry *tmp)
{
    const plateau__seed_quality *q = gr->q;
    plateau__seed_graded_node *nd;
    double c[2], r = 0.75 * s, best_lo = 0.0;
    size_t j, kept = 0;
    if (plateau__seed_graded_room(gr, k) != 0) return -1;
    c[0] = x + 0.5 * s;
    c[1] = y + 0.5 * s;
    for (j = 0; j < k; j++) {
        size_t e = cand[j];
        const double *a0 = q->uv + 2 * e, *b0 = q->uv + 2 * (q->next ? q->next[e] : (e + 1) % q->m);
        double dx = b0[0] - a0[0], dy = b0[1] - a0[1], len = PLATEAU_SQRT(dx * dx + dy * dy);
        double d = PLATEAU_SQRT(plateau__util_seg_dist2(c, a0, b0)), lo = len - q->grading * (d + r);
        tmp[j].ub = len - q->grading * (d > r ? d - r : 0.0) + gr->slack;
        tmp[j].e = e;
        if (lo > best_lo) best_lo = lo;
    }
    for (j = 0; j < k; j++)
        if (tmp[j].ub >= best_lo && tmp[j].ub >= gr->h0) tmp[kept++] = tmp[j];
    PLATEAU_QSORT(tmp, kept, sizeof *tmp, plateau__seed_graded_cmp);
    nd = gr->node + gr->nodes++;
    nd->x = x;
    nd->y = y;
    nd->s = s;
    nd->first = gr->items;
    nd->count = kept;
    nd->child = 0;
    nd->depth = depth;
    for (j = 0; j < kept; j++) {
        gr->item[gr->items] = tmp[j].e;
        gr->ub[gr->items++] = tmp[j].ub;
    }
    return 0;
}

/* Builds gr for q (q->grading > 0).  PLATEAU_OK or _OUT_OF_MEMORY. */
static plateau_result plateau__seed_graded_build(plateau__seed_graded *gr,
                                                const plateau__seed_quality *q)
{
    double *reach, diag = PLATEAU_SQRT(plateau__util_diag2(q->uv, q->m));
    plateau__seed_egrid grid;
    plateau__seed_graded_entry *tmp = NULL;
    size_t e, c, i, longest = 0, ncell, used = 0, budget, *cand = NULL;
    plateau_result rc;
    memset(gr, 0, sizeof *gr);
    gr->q = q;
    gr->slack = 1e-12 * diag;
    gr->h0 = PLATEAU_SQRT(q->amax / 0.4330127018922193) * (1.0 - 1e-9) - gr->slack;
    reach = (double *)plateau__util_array(&q->alloc, q->m, sizeof(double));
    if (!reach) return PLATEAU_ERR_OUT_OF_MEMORY;
    for (e = 0; e < q->m; e++) {
        const double *a0 = q->uv + 2 * e, *b0 = q->uv + 2 * (q->next ? q->next[e] : (e + 1) % q->m);
        double dx = b0[0] - a0[0], dy = b0[1] - a0[1], len = PLATEAU_SQRT(dx * dx + dy * dy);
        /* beyond this, len - g d < h0 - 2 slack: the term cannot lift amax */
        reach[e] = len + gr->slack > gr->h0 ? (len - gr->h0 + 2.0 * gr->slack) / q->grading : -1.0;
        used += reach[e] >= 0.0;
    }
    rc = plateau__seed_egrid_build(&grid, q->uv, q->m, q->next, reach, 4.0 * (double)used + 16.0,
                                 &q->alloc);
    plateau__free(&q->alloc, reach);
    if (rc != PLATEAU_OK) return rc;
    gr->x0 = grid.x0;
    gr->y0 = grid.y0;
    gr->h = grid.h;
    gr->nx = grid.nx;
    gr->ny = grid.ny;
    ncell = grid.nx * grid.ny;
    budget = 32 * (q->m + ncell) + 1024;
    for (c = 0; c < ncell; c++)
        if (grid.start[c + 1] - grid.start[c] > longest) longest = grid.start[c + 1] - grid.start[c];
    tmp = (plateau__seed_graded_entry *)plateau__util_array(&q->alloc, longest + 1, sizeof *tmp);
    cand = (size_t *)plateau__util_array(&q->alloc, longest + 1, sizeof(size_t));
    rc = tmp && cand ? PLATEAU_OK : PLATEAU_ERR_OUT_OF_MEMORY;
    /* the root squares: the grid's cells, in cell order */
    for (c = 0; c < ncell && rc == PLATEAU_OK; c++)
        if (plateau__seed_graded_square(gr, grid.x0 + (double)(c % grid.nx) * grid.h,
                                       grid.y0 + (double)(c / grid.nx) * grid.h, grid.h, 0,
                                       grid.item + grid.start[c], grid.start[c + 1] - grid.start[c],
                                       tmp) != 0)
            rc = PLATEAU_ERR_OUT_OF_MEMORY;
    plateau__seed_egrid_free(&grid, &q->alloc);
    /* split crowded squares, breadth first (children follow their parents) */
    for (i = 0; i < gr->nodes && rc == PLATEAU_OK; i++) {
        plateau__seed_graded_node nd = gr->node[i];
        int k;
        if (nd.count <= PLATEAU__SEED_GRADED_LEAF || nd.depth >= 10 || gr->items > budget) continue;
        memcpy(cand, gr->item + nd.first, nd.count * sizeof(size_t));
        gr->node[i].child = gr->nodes;
        for (k = 0; k < 4 && rc == PLATEAU_OK; k++)
            if (plateau__seed_graded_square(gr, nd.x + 0.5 * nd.s * (double)(k & 1),
                                           nd.y + 0.5 * nd.s * (double)(k >> 1), 0.5 * nd.s,
                                           nd.depth + 1, cand, nd.count, tmp) != 0)
                rc = PLATEAU_ERR_OUT_OF_MEMORY;
    }
    plateau__free(&q->alloc, tmp);
    plateau__free(&q->alloc, cand);
    if (rc != PLATEAU_OK) plateau__seed_graded_free(gr);
    return rc;
}

static double plateau__seed_graded_area(double x, double y, void *user)
{
    plateau__seed_graded *gr = (plateau__seed_graded *)user;
    const plateau__seed_quality *q = gr->q;
    const plateau__seed_graded_node *nd;
    double p[2], h = 0.0, a;
    size_t j;
    p[0] = x;
    p[1] = y;
    gr->calls++;
    if (!(q->grading > 0.0)) return q->amax;
    if (!(x >= gr->x0 && x <= gr->x0 + (double)gr->nx * gr->h && y >= gr->y0 &&
          y <= gr->y0 + (double)gr->ny * gr->h)) {
        size_t e; /* outside the polygon's box (the refinement never asks): the scan */
        for (e = 0; e < q->m; e++) {
            double v = plateau__seed_graded_term(q, e, p);
            gr->visits++;
            if (v > h) h = v;
        }
    } else {
        nd = gr->node + plateau__seed_egrid_cell(y, gr->y0, gr->h, gr->ny) * gr->nx +
             plateau__seed_egrid_cell(x, gr->x0, gr->h, gr->nx);
        gr->visits++;
        while (nd->child) {
            double half = 0.5 * nd->s;
            nd = gr->node + nd->child + (x >= nd->x + half ? 1 : 0) + (y >= nd->y + half ? 2 : 0);
            gr->visits++;
        }
        for (j = nd->first; j < nd->first + nd->count && gr->ub[j] > h; j++) {
            double v = plateau__seed_graded_term(q, gr->item[j], p);
            gr->visits++;
            if (v > h) h = v;
        }
    }
    a = PLATEAU__SQRT3_4 * h * h;
    return a > q->amax ? a : q->amax;
}

static plateau_dt_result plateau__seed_refine(const double *uv, size_t m, const plateau_index *seg,
                                             plateau__seed_quality *q, double amax,
                                             plateau_dt_mesh *dt, size_t *interior,
                                             plateau_dt_error *drep)
{
    plateau_dt_input in;
    plateau_dt_options o;
    plateau_dt_result r;
    plateau__seed_graded graded;
    size_t v;
    memset(&in, 0, sizeof in);
    memset(&o, 0, sizeof o);
    in.points = uv;
    in.num_points = m;
    in.segments = seg;
    in.num_segments = m;
    o.allocator = q->alloc;
    o.min_angle = q->min_angle;
    o.keep_segments = !q->refine_boundary;
    memset(&graded, 0, sizeof graded);
    if (q->refine_boundary) {
        o.max_area = amax;
    } else {
        plateau__seed_quality *qm = q;
        qm->amax = amax;
        graded.q = qm;
        if (qm->grading > 0.0 && plateau__seed_graded_build(&graded, qm) != PLATEAU_OK) {
            drep->code = PLATEAU_DT_ERR_OUT_OF_MEMORY;
            drep->index = -1;
            memcpy(drep->message, "out of memory", 14);
            return PLATEAU_DT_ERR_OUT_OF_MEMORY;
        }
        o.max_area_fn = plateau__seed_graded_area;
        o.max_area_user = &graded;
    }
    o.max_added_points = q->budget;
    *interior = 0;
    r = plateau_dt_triangulate(&in, &o, dt, drep);
    if (graded.node) plateau__seed_graded_free(&graded);
    if (r != PLATEAU_DT_OK) return r;
    for (v = dt->num_input_points; v < dt->num_points; v++) *interior += dt->segment_of[v] < 0;
    return r;
}

/* The search for the area limit: at most PLATEAU__SEED_SEARCH refinements,
 * the bracket bisected until its ends are within PLATEAU__SEED_BRACKET of
 * each other (relative). */
#define PLATEAU__SEED_SEARCH 20
#define PLATEAU__SEED_BRACKET 1e-3

/* The refined triangulation into *best (all zero on error).
 * On a coarse polygon kept whole, the graded limit above covers the whole
 * domain (on a unit square, edges of length 1 keep the size near 1
 * everywhere, and the refinement adds almost no point).  So when the
 * refinement at the gentle slope delivers less than half of the count
 * asked for (n, or A / (sqrt(3) / 4 L^2) for an edge length L, the count
 * of triangles of about half the equilateral area on A), the slope
 * steepens, 0.5, 2, 8, 32, then no grading: the refinement reaches the
 * count, and the price is paid only in the triangles that stand on the
 * long kept edges (their angles fall to about size / edge length). */
static plateau_result plateau__seed_quality_dt(const double *uv, size_t m, const plateau_index *seg,
                                              size_t n, double edge_length,
                                              const plateau__seed_quality *qc,
                                              plateau_dt_mesh *best, plateau_error *err)
{
    static const double slopes[5] = {PLATEAU__SEED_GRADING, 2.0, 8.0, 32.0, 0.0};
    plateau__seed_quality q = *qc;
    plateau_dt_mesh dt;
    plateau_dt_error drep;
    plateau_dt_result dres = PLATEAU_DT_OK;
    double area = qc->area > 0.0 ? qc->area : plateau__util_signed_area(uv, m), a, small, big, want;
    size_t best_diff, c = 0, best_count, prev;
    int it, slope;
    q.uv = uv;
    q.m = m;
    memset(best, 0, sizeof *best);
    memset(&drep, 0, sizeof drep);
    want = edge_length > 0.0 ? area / (PLATEAU__SQRT3_4 * edge_length * edge_length) : (double)n;
    for (slope = 0; slope < 5; slope++) {
        q.grading = slopes[slope];
        plateau_dt_free(best);
        best_count = 0;
        if (edge_length > 0.0) {
            /* the equilateral triangle of side edge_length */
            dres = plateau__seed_refine(uv, m, seg, &q, PLATEAU__SQRT3_4 * edge_length * edge_length,
                                       best, &c, &drep);
            best_count = c;
        } else {
            /* a search for the count: each refinement at most 8 (n + m) + 4096 points */
            q.budget = n < ((size_t)-1 - 4096) / 8 - m ? 8 * (n + m) + 4096 : 0;
            a = 2.0 * area / (2.0 * (double)n + (double)m);
            small = big = 0.0;
            best_diff = (size_t)-1;
            prev = (size_t)-1;
            for (it = 0; it < PLATEAU__SEED_SEARCH; it++) {
                size_t diff;
                int late;
                memset(&dt, 0, sizeof dt);
                dres = plateau__seed_refine(uv, m, seg, &q, a, &dt, &c, &drep);
                if (dres != PLATEAU_DT_OK) {
                    plateau_dt_free(&dt);
                    plateau_dt_free(best);
                    break;
                }
                diff = c > n ? c - n : n - c;
                late = plateau__util_time_up(q.time_budget);
                /* past the time budget the search ends at the first count
                 * within n (n is what the memory bound admitted), or once
                 * a larger limit no longer removes a tenth of the points
                 * (the angle bound's grading from a dense polygon sets a
                 * floor: on a circle of 10^5 vertices, 176 332 points
                 * whatever the limit, for n = 10^5) */
                if (diff < best_diff || (late && best_count > n && c <= n)) {
                    plateau_dt_free(best);
                    *best = dt;
                    best_diff = diff;
                    best_count = c;
                } else {
                    plateau_dt_free(&dt);
                }
                if (diff == 0 || (late && (best_count <= n || (prev != (size_t)-1 && (c >= prev || prev - c < prev / 10)))))
                    break;
                prev = c;
                if (c > n) small = a; /* too many points: a larger limit */
                else big = a;
                if (big == 0.0) {
                    if (small >= area) break; /* the angle bound alone adds more than n */
                    a = 2.0 * small;
                } else if (small == 0.0) {
                    a = 0.5 * big;
                } else {
                    if (big <= small * (1.0 + PLATEAU__SEED_BRACKET)) break;
                    a = PLATEAU_SQRT(small * big);
                }
            }
        }
        /* refine_boundary grades nothing; enough points: done */
        if (dres != PLATEAU_DT_OK || q.refine_boundary || 2.0 * (double)best_count >= want ||
            plateau__util_time_up(q.time_budget))
            break;
    }
    if (dres != PLATEAU_DT_OK) {
        plateau_dt_free(best);
        return plateau__util_dt_error(dres, &drep, err);
    }
    if (best->num_triangles == 0) {
        plateau_dt_free(best);
        plateau__util_error(err, PLATEAU_ERR_TRIANGULATION, drep.index, "the refined triangulation is empty", 0, 0);
        return PLATEAU_ERR_TRIANGULATION;
    }
    return PLATEAU_OK;
}

/* The automatic refine_boundary of one polygon for n interior points (or
 * the edge length el > 0, in the domain's units): the longest polygon edge
 * is more than PLATEAU__SEED_AUTO_REFINE times the interior spacing h, the
 * side of the equilateral triangle of area 2 A / (2 n + m). */
static int plateau__seed_refine_auto(const plateau__cfg_work *s, size_t n, double el)
{
    double lmax = 0.0, h;
    size_t e;
    for (e = 0; e < s->m; e++) {
        const double *a0 = s->uv + 2 * e, *b0 = s->uv + 2 * ((e + 1) % s->m);
        double dx = b0[0] - a0[0], dy = b0[1] - a0[1], l = PLATEAU_SQRT(dx * dx + dy * dy);
        if (l > lmax) lmax = l;
    }
    h = el > 0.0 ? el
                 : PLATEAU_SQRT(2.0 * PLATEAU_FABS(plateau__util_signed_area(s->uv, s->m)) /
                                ((2.0 * (double)n + (double)s->m) * PLATEAU__SQRT3_4));
    return lmax > PLATEAU__SEED_AUTO_REFINE * h;
}

/* Steps 3-4 with the quality seeding: the domain refined by
 * plateau_delaunay.h; the refined triangulation is s->dt.  scale is the
 * frame's over the canonical domain's factor, to bring quality_edge_length
 * into the domain's units. */
static plateau_result plateau__seed_quality_mesh(plateau__cfg_work *s, const plateau__cfg *cfg,
                                                 const plateau__cfg_run *run, double scale, int area_rounds,
                                                 plateau_error *err)
{
    plateau__seed_quality qc;
    double el = cfg->quality_edge_length / scale; /* in the domain's units */
    /* a polygon with cables keeps its edges whole: no fixed vertex on a cable */
    plateau_switch refine_boundary = s->cables ? PLATEAU_OFF : cfg->refine_boundary;
    int refine = refine_boundary == PLATEAU_ON;
    if (cfg->quality_edge_length > 0.0) {
        /* bounded memory: the count the edge length asks for, before the
         * refinement runs */
        double a = s->loops > 1 ? s->area : PLATEAU_FABS(plateau__util_signed_area(s->uv, s->m));
        plateau_result rc = plateau__cfg_memory_check(cfg, run, (double)s->m,
                                                      a / (PLATEAU__SQRT3_4 * el * el), err);
        if (rc != PLATEAU_OK) return rc;
    }
    qc.alloc = s->alloc;
    qc.min_angle = cfg->quality_min_angle;
    if (refine_boundary == PLATEAU_AUTO && area_rounds && s->loops <= 1) {
        /* automatic: least area pulls interior vertices onto a polygon
         * edge much longer than the interior spacing (the film twists
         * along the edge, and a vertex on the chord is the only way its
         * flat triangle can split), step 6's vertex removal takes them,
         * and the next ones follow (examples/NOTES.md, "Measurements
         * behind the solver's choices").  So the edges may split when the
         * longest is more than PLATEAU__SEED_AUTO_REFINE times the
         * interior spacing h, the side of the equilateral triangle of
         * area 2 A / (2 n + m) (or quality_edge_length). */
        refine = plateau__seed_refine_auto(s, s->n, el);
    }
    qc.refine_boundary = refine && s->loops <= 1;
    qc.budget = 0;
    qc.time_budget = s->time_budget;
    qc.next = s->next;
    qc.area = s->area;
    return plateau__seed_quality_dt(s->uv, s->m, s->seg, s->n, el, &qc, &s->dt, err);
}
/* ======== END SECTION: step 3: interior points ============================ */

/* ======== SECTION: step 4: constrained Delaunay triangulation (plateau__cdt_) */
/* The constrained Delaunay triangulation of the boundary and the points in
 * the domain (plateau_delaunay.h), lifted to the initial 3-D mesh. */
/* 3-D position of a domain point p strictly inside the domain polygon uv:
 * the mean-value coordinates of p (Floater, "Mean value coordinates",
 * CAGD 20, 2003; well defined inside any simple polygon, convex or not:
 * Hormann and Floater, ACM TOG 25, 2006) applied to the boundary's xyz.
 * w_i = (tan(a_(i-1)/2) + tan(a_i/2)) / r_i, r_i = |uv_i - p|, a_i the
 * signed angle at p from uv_i to uv_(i+1); tan(a/2) is taken as
 * cross / (r r' + dot) when dot >= 0 and (r r' - dot) / cross otherwise,
 * both free of cancellation.  The interpolant is smooth, reproduces the
 * boundary and is linear-precise: on the best-fit-plane domain the 3-D
 * point projects back to p exactly (to rounding), so the refined angles
 * carry over as far as the surface is a graph over the plane.  Returns 0,
 * or -1 when p is on the boundary or the weights do not sum to a positive
 * finite number. */
static int plateau__cdt_mvc_loops(const double *uv, const double *xyz, const size_t *off,
                                  size_t loops, const double *sign, const double *p, double *out);

static int plateau__cdt_mvc(const double *uv, const double *xyz, size_t m, const double *p,
                            double *out)
{
    size_t off[2];
    double sign = 1.0; /* one loop: the same sums, the same bits */
    off[0] = 0;
    off[1] = m;
    return plateau__cdt_mvc_loops(uv, xyz, off, 1, &sign, p, out);
}

/* Mean-value coordinates on a domain with holes (Hormann and Floater 2006,
 * section 4: a set of polygons): the sums of plateau__cdt_mvc over every
 * loop's vertices, each loop taken with the domain on its left (outer
 * counter-clockwise, holes clockwise; sign[j] = -1 reverses loop j, which
 * negates its weights).  Along any ray from p the boundary crossings then
 * alternate in sign with growing distance, so the weights' sum is
 * positive inside the domain, and the interpolant still reproduces the
 * boundary and is linear-precise.  Loop j holds vertices off[j] ..
 * off[j+1]-1.  Returns 0, or -1 as plateau__cdt_mvc. */
static int plateau__cdt_mvc_loops(const double *uv, const double *xyz, const size_t *off,
                                  size_t loops, const double *sign, const double *p, double *out)
{
    double wsum = 0.0, acc[3] = {0.0, 0.0, 0.0};
    size_t j, i;
    int k;
    for (i = 0; i < off[loops]; i++) {
        if (uv[2 * i] == p[0] && uv[2 * i + 1] == p[1]) {
            for (k = 0; k < 3; k++) out[k] = xyz[3 * i + (size_t)k];
            return 0;
        }
    }
    for (j = 0; j < loops; j++) {
        size_t o = off[j], m = off[j + 1] - off[j];
        double tprev = 0.0, tfirst = 0.0;
        for (i = 0; i <= m; i++) {
            size_t a = o + i % m, b = o + (i + 1) % m;
            double ax = uv[2 * a] - p[0], ay = uv[2 * a + 1] - p[1];
            double bx = uv[2 * b] - p[0], by = uv[2 * b + 1] - p[1];
            double ra = PLATEAU_SQRT(ax * ax + ay * ay), rb = PLATEAU_SQRT(bx * bx + by * by);
            double cr = ax * by - ay * bx, dt = ax * bx + ay * by, t;
            if (dt >= 0.0) {
                t = cr / (ra * rb + dt);
            } else {
                if (cr == 0.0) return -1; /* p on the edge a-b */
                t = (ra * rb - dt) / cr;
            }
            if (i == 0) {
                tfirst = t;
            } else {
                double w = sign[j] * (tprev + (i == m ? tfirst : t)) / ra;
                wsum += w;
                for (k = 0; k < 3; k++) acc[k] += w * xyz[3 * a + (size_t)k];
            }
            tprev = t;
        }
    }
    if (!(wsum > 0.0) || !plateau__util_finite(wsum)) return -1;
    for (k = 0; k < 3; k++) out[k] = acc[k] / wsum;
    for (k = 0; k < 3; k++)
        if (!plateau__util_finite(out[k])) return -1;
    return 0;
}

/* The smallest angle (degrees) of a planar triangulation's triangles. */
static double plateau__cdt_min_angle(const plateau_dt_mesh *dt)
{
    double best = PLATEAU__HALF_TURN_DEG;
    size_t t;
    int k;
    for (t = 0; t < dt->num_triangles; t++) {
        for (k = 0; k < 3; k++) {
            const double *o = dt->points + 2 * (size_t)dt->triangles[3 * t + (size_t)k];
            const double *a = dt->points + 2 * (size_t)dt->triangles[3 * t + (size_t)((k + 1) % 3)];
            const double *b = dt->points + 2 * (size_t)dt->triangles[3 * t + (size_t)((k + 2) % 3)];
            double ax = a[0] - o[0], ay = a[1] - o[1], bx = b[0] - o[0], by = b[1] - o[1];
            double ang = PLATEAU_ATAN2(PLATEAU_FABS(ax * by - ay * bx), ax * bx + ay * by);
            ang *= PLATEAU__DEG_PER_RAD;
            if (ang < best) best = ang;
        }
    }
    return best;
}

/* A vertex added on the polygon's edge s (quality seeding, refine_boundary),
 * at parameter t along it: sorted by (s, t) they follow the boundary. */
typedef struct plateau__cdt_edge_vertex {
    size_t s, v;
    double t;
} plateau__cdt_edge_vertex;

static int plateau__cdt_edge_vertex_cmp(const void *pa, const void *pb)
{
    const plateau__cdt_edge_vertex *a = (const plateau__cdt_edge_vertex *)pa;
    const plateau__cdt_edge_vertex *b = (const plateau__cdt_edge_vertex *)pb;
    if (a->s != b->s) return a->s < b->s ? -1 : 1;
    if (a->t != b->t) return a->t < b->t ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v ? 1 : 0;
}

/* Steps 3-4 with the fan seeding: the candidate points of plateau_seed_points
 * (paper II.A) and the constrained Delaunay triangulation of the boundary and
 * those points in the domain (s->dt). */
static plateau_result plateau__cdt_fan_mesh(plateau__cfg_work *s, uint64_t seed,
                                            plateau_error *err)
{
    size_t m = s->m, count = 0, i;
    double *pts2, *dpts;
    plateau_dt_input in;
    plateau_dt_options dopt;
    plateau_dt_error derr;
    plateau_dt_result dres;
    plateau_result rc;

    pts2 = (double *)plateau__util_array(&s->alloc, s->n, 2 * sizeof(double));
    dpts = (double *)plateau__util_array(&s->alloc, m + s->n, 2 * sizeof(double));
    if (!pts2 || !dpts) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in plateau_solve", 0, 0);
        goto done;
    }
    /* step 3 */
    rc = plateau_seed_points(s->nb, s->uv, m, s->n, seed, &s->alloc, s->pts, pts2, &count, err);
    if (rc != PLATEAU_OK) goto done;
    /* step 4: constrained Delaunay triangulation of boundary + points */
    for (i = 0; i < m; i++) {
        dpts[2 * i] = s->uv[2 * i];
        dpts[2 * i + 1] = s->uv[2 * i + 1];
    }
    for (i = 0; i < count; i++) {
        dpts[2 * (m + i)] = pts2[2 * i];
        dpts[2 * (m + i) + 1] = pts2[2 * i + 1];
    }
    memset(&in, 0, sizeof in);
    memset(&dopt, 0, sizeof dopt);
    memset(&derr, 0, sizeof derr);
    in.points = dpts;
    in.num_points = m + count;
    in.segments = s->seg;
    in.num_segments = m;
    dopt.allocator = s->alloc;
    dres = plateau_dt_triangulate(&in, &dopt, &s->dt, &derr);
    if (dres != PLATEAU_DT_OK) {
        rc = plateau__util_dt_error(dres, &derr, err);
    } else if (s->dt.num_triangles == 0 || s->dt.num_points != m + count) {
        rc = PLATEAU_ERR_TRIANGULATION;
        plateau__util_error(err, rc, derr.index, "the triangulator added points to the domain", 0, 0);
    }
done:
    plateau__free(&s->alloc, pts2);
    plateau__free(&s->alloc, dpts);
    return rc;
}

/* The vertices the refinement added on the polygon's edges (s->k of them):
 * on edge e from vertex e to e + 1, at the parameter t of the domain point's
 * projection on the domain edge, the same t on the straight 3-D edge, in
 * the frame (pos) and, for the bit-exact restore, in the caller's units
 * (s->orig).  They follow the polygon in edge order, then along each edge;
 * remap, fixed and *nv as in plateau__cdt_remap. */
static void plateau__cdt_edge_vertices(plateau__cfg_work *s, plateau__cdt_edge_vertex *ev,
                                       double *pos, plateau_index *remap,
                                       unsigned char *fixed, size_t *nv)
{
    const plateau_dt_mesh *dt = &s->dt;
    const double *uv = s->uv, *nb = s->nb, *boundary = s->boundary;
    size_t m = s->m, i, j = 0, c;
    for (i = m; i < dt->num_points; i++) {
        size_t s2, a2, b2;
        double ex, ey, l2, t;
        if (dt->segment_of[i] < 0) continue;
        s2 = (size_t)dt->segment_of[i];
        a2 = s2;
        b2 = (s2 + 1) % m;
        ex = uv[2 * b2] - uv[2 * a2];
        ey = uv[2 * b2 + 1] - uv[2 * a2 + 1];
        l2 = ex * ex + ey * ey;
        t = l2 > 0.0 ? ((dt->points[2 * i] - uv[2 * a2]) * ex + (dt->points[2 * i + 1] - uv[2 * a2 + 1]) * ey) / l2 : 0.5;
        if (!(t > 0.0)) t = 0.0;
        if (t > 1.0) t = 1.0;
        ev[j].s = s2;
        ev[j].v = i;
        ev[j].t = t;
        j++;
    }
    PLATEAU_QSORT(ev, s->k, sizeof *ev, plateau__cdt_edge_vertex_cmp);
    memcpy(s->orig, boundary, 3 * m * sizeof(double));
    for (j = 0; j < s->k; j++) {
        size_t a2 = ev[j].s, b2 = (ev[j].s + 1) % m;
        double t = ev[j].t;
        for (c = 0; c < 3; c++) {
            pos[3 * *nv + c] = nb[3 * a2 + c] + t * (nb[3 * b2 + c] - nb[3 * a2 + c]);
            s->orig[3 * (m + j) + c] = boundary[3 * a2 + c] + t * (boundary[3 * b2 + c] - boundary[3 * a2 + c]);
        }
        remap[ev[j].v] = (plateau_index)*nv;
        fixed[*nv] = 1;
        (*nv)++;
    }
}

/* Above this product of boundary vertices and refinement points the
 * quality seeding carries its points to 3-D by the discrete harmonic map
 * of the refined triangulation instead of the mean-value coordinates,
 * which cost O(m) per point (m = 10^5 with 1.7 10^5 points: 1.7 10^10
 * terms, minutes; m = 10^4 with 1.7 10^4 points: a third of the whole
 * solve): 10^7 of them take about 0.1 s, more than the one sparse Cholesky
 * of the harmonic map at those sizes, and all the demo's and tests'
 * polygons stay below it (a test may define it smaller). */
#ifndef PLATEAU__CDT_MVC_WORK
#define PLATEAU__CDT_MVC_WORK 1e7
#endif

/* The harmonic placement above that work (step 5's sparse Cholesky: the
 * solve section). */
static plateau_result plateau__solve_harmonic_place(plateau_mesh *mesh, const double *uvpos,
                                                    plateau_error *err);

/* The 3-D mesh from the planar triangulation (the remap): it takes the
 * triangles; interior points the triangulator dropped as duplicates are
 * left out.  Vertex order: the polygon (0 .. m-1), the vertices the
 * refinement added on its edges (fixed), the interior points (fan seeding:
 * their seeded 3-D position; quality seeding: the mean-value coordinates of
 * the domain polygon carry them to 3-D).  *nv gets the vertex count. */
static plateau_result plateau__cdt_remap(plateau__cfg_work *s, int quality, plateau_mesh *mesh,
                                         size_t *nv, plateau_error *err)
{
    const plateau_dt_mesh *dt = &s->dt;
    size_t m = s->m, np = dt->num_points, i;
    plateau_index *remap, *tri;
    double *pos, *uvpos = NULL;
    unsigned char *fixed;
    plateau__cdt_edge_vertex *ev = NULL;
    plateau_result rc = PLATEAU_OK;
    /* many boundary vertices and points: the harmonic map, not the O(m)
     * per point mean-value coordinates (PLATEAU__CDT_MVC_WORK) */
    int harmonic = quality && (double)m * (double)(np - m) > PLATEAU__CDT_MVC_WORK;

    *nv = 0;
    remap = (plateau_index *)plateau__util_array(&s->alloc, np, sizeof(plateau_index));
    pos = (double *)plateau__util_array(&s->alloc, np, 3 * sizeof(double));
    fixed = (unsigned char *)plateau__alloc(&s->alloc, np);
    tri = (plateau_index *)plateau__util_array(&s->alloc, dt->num_triangles, 3 * sizeof(plateau_index));
    if (harmonic) uvpos = (double *)plateau__util_array(&s->alloc, np, 2 * sizeof(double));
    if (!remap || !pos || !fixed || !tri || (harmonic && !uvpos)) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in plateau_solve", 0, 0);
        goto done;
    }
    if (quality)
        for (i = m; i < np; i++) s->k += dt->segment_of[i] >= 0;
    if (s->k > 0) {
        ev = (plateau__cdt_edge_vertex *)plateau__util_array(&s->alloc, s->k, sizeof(plateau__cdt_edge_vertex));
        s->orig = (double *)plateau__util_array(&s->alloc, m + s->k, 3 * sizeof(double));
        if (!ev || !s->orig) {
            rc = PLATEAU_ERR_OUT_OF_MEMORY;
            plateau__util_error(err, rc, -1, "out of memory in plateau_solve", 0, 0);
            goto done;
        }
    }
    for (i = 0; i < m; i++) {
        if (dt->duplicate_of[i] != (plateau_index)i) {
            rc = PLATEAU_ERR_TRIANGULATION;
            plateau__util_error(err, rc, (long)i, "two boundary vertices fall on one point of the domain", 0, 0);
            goto done;
        }
        remap[i] = (plateau_index)*nv;
        memcpy(pos + 3 * *nv, s->nb + 3 * i, 3 * sizeof(double));
        fixed[*nv] = 1;
        (*nv)++;
    }
    if (s->k > 0) plateau__cdt_edge_vertices(s, ev, pos, remap, fixed, nv);
    for (i = m; i < np; i++) {
        if (harmonic) {
            if (dt->segment_of[i] >= 0) continue;
            pos[3 * *nv] = pos[3 * *nv + 1] = pos[3 * *nv + 2] = 0.0; /* placed below */
        } else if (quality) {
            if (dt->segment_of[i] >= 0) continue;
            if ((PLATEAU__HAVE_LOOPS && s->loops > 1 ? plateau__cdt_mvc_loops(s->uv, s->nb, s->off, s->loops, s->lsign,
                                                       dt->points + 2 * i, pos + 3 * *nv)
                              : plateau__cdt_mvc(s->uv, s->nb, m, dt->points + 2 * i, pos + 3 * *nv)) != 0) {
                rc = PLATEAU_ERR_TRIANGULATION;
                plateau__util_error(err, rc, (long)i,
                                       "a refinement point got no mean-value coordinates", 0, 0);
                goto done;
            }
        } else {
            if (dt->duplicate_of[i] != (plateau_index)i) {
                remap[i] = -1;
                continue;
            }
            memcpy(pos + 3 * *nv, s->pts + 3 * (i - m), 3 * sizeof(double));
        }
        remap[i] = (plateau_index)*nv;
        fixed[*nv] = 0;
        (*nv)++;
    }
    for (i = 0; i < 3 * dt->num_triangles; i++) tri[i] = remap[dt->triangles[i]];
    rc = plateau_mesh_create(pos, *nv, fixed, tri, dt->num_triangles, &s->alloc, mesh, err);
    if (rc == PLATEAU_OK && harmonic) {
        for (i = 0; i < np; i++)
            if (remap[i] >= 0) memcpy(uvpos + 2 * (size_t)remap[i], dt->points + 2 * i, 2 * sizeof(double));
        rc = plateau__solve_harmonic_place(mesh, uvpos, err);
        if (rc != PLATEAU_OK) plateau_mesh_free(mesh);
    }
done:
    plateau__free(&s->alloc, uvpos);
    plateau__free(&s->alloc, ev);
    plateau__free(&s->alloc, remap);
    plateau__free(&s->alloc, pos);
    plateau__free(&s->alloc, fixed);
    plateau__free(&s->alloc, tri);
    return rc;
}

/* ---- steps 3-4 as plateau_solve runs them ---- */

/* The second memory bound of a solve the formula refuses after seeding:
 * method paper's sparse path holds the block LU of its 3 n unknowns, and
 * the symbolic analysis of the seeded triangulation's free vertices
 * (ordered by their domain points, as the solve orders by their placed
 * ones) gives that factor's bytes F exactly; the bound is
 * PLATEAU__CDT_MEM_LU F + PLATEAU__CDT_MEM_VERTEX (n + m) bytes.  The
 * formula fits uniform meshes; the graded mesh of a dense boundary has
 * smaller separators (m = 3 10^4: 2 860 bytes of LU per free vertex, the
 * formula allows 10 240), and the measured peaks stay under this bound
 * (examples/NOTES.md, section 11).  *need = 0: the bound does not apply
 * (another method, the dense path or coarse to fine). */
#define PLATEAU__CDT_MEM_LU 2.0
#define PLATEAU__CDT_MEM_VERTEX 2000.0
static plateau_result plateau__cdt_memory_graph(const plateau__cfg_work *s, const plateau__cfg *cfg,
                                                const plateau__cfg_run *run, double *need, plateau_error *err)
{
    const plateau_dt_mesh *dt = &s->dt;
    const plateau_allocator *al = &s->alloc;
    size_t np = dt->num_points, nt = dt->num_triangles, nf = 0, i, t;
    int q;
    plateau_index *node, *rs = NULL, *cols = NULL;
    double *xy = NULL;
    plateau_lm_result lrc = PLATEAU_LM_ERR_OUT_OF_MEMORY;
    *need = 0.0;
    if (cfg->method != PLATEAU_METHOD_PAPER || cfg->linear_solver == PLATEAU_LINEAR_DENSE ||
        run->c2f_memory || !dt->segment_of || !dt->neighbors)
        return PLATEAU_OK;
    node = (plateau_index *)plateau__util_array(al, np, sizeof(plateau_index));
    if (node) {
        for (i = 0; i < np; i++) node[i] = i < s->m || dt->segment_of[i] >= 0 ? -1 : (plateau_index)nf++;
        rs = (plateau_index *)plateau__util_array(al, nf + 2, sizeof(plateau_index));
        xy = (double *)plateau__util_array(al, nf + 1, 2 * sizeof(double));
    }
    if (rs && xy && PLATEAU__HAVE_SPARSE &&
        (nf > (size_t)PLATEAU_SPARSE_THRESHOLD || cfg->linear_solver == PLATEAU_LINEAR_SPARSE)) {
        /* row lengths: the diagonal, and each edge between free vertices
         * once (from the triangle of the smaller index, or the only one) */
        for (i = 0; i <= nf + 1; i++) rs[i] = 0;
        for (t = 0; t < nt; t++)
            for (i = 0; i < 3; i++) {
                plateau_index a = node[dt->triangles[3 * t + i]], b = node[dt->triangles[3 * t + (i + 1) % 3]];
                plateau_index o = dt->neighbors[3 * t + i];
                if (a < 0 || b < 0 || (o >= 0 && (size_t)o < t)) continue;
                rs[a + 2]++;
                rs[b + 2]++;
            }
        for (i = 0; i < nf; i++) rs[i + 2] += rs[i + 1] + 1;
        cols = (plateau_index *)plateau__util_array(al, (size_t)rs[nf + 1] + 1, sizeof(plateau_index));
    }
    if (cols) {
        plateau_lm_sparse_pattern pat;
        plateau_lm_sparse_options so;
        plateau_lm_sparse_symbolic *sym = NULL;
        for (i = 0; i < np; i++)
            if (node[i] >= 0) {
                cols[rs[node[i] + 1]++] = node[i];
                xy[2 * (size_t)node[i]] = dt->points[2 * i];
                xy[2 * (size_t)node[i] + 1] = dt->points[2 * i + 1];
            }
        for (t = 0; t < nt; t++)
            for (i = 0; i < 3; i++) {
                plateau_index a = node[dt->triangles[3 * t + i]], b = node[dt->triangles[3 * t + (i + 1) % 3]];
                plateau_index o = dt->neighbors[3 * t + i];
                if (a < 0 || b < 0 || (o >= 0 && (size_t)o < t)) continue;
                cols[rs[a + 1]++] = b;
                cols[rs[b + 1]++] = a;
            }
        memset(&so, 0, sizeof so);
        so.allocator = *al;
        pat.nodes = nf;
        pat.block = 3;
        pat.row_start = rs;
        pat.cols = cols;
        lrc = plateau_lm_sparse_analyze(&pat, xy, &so, &sym);
        if (lrc == PLATEAU_LM_OK)
            *need = PLATEAU__CDT_MEM_LU * (double)plateau_lm_sparse_symbolic_info(sym).factor_bytes_lu +
                    PLATEAU__CDT_MEM_VERTEX * (double)np + 8192.0;
        plateau_lm_sparse_symbolic_free(sym);
    } else if (rs && xy) {
        lrc = PLATEAU_LM_OK; /* the dense path: its formula stands */
    }
    plateau__free(al, node);
    plateau__free(al, rs);
    plateau__free(al, cols);
    plateau__free(al, xy);
    if (lrc == PLATEAU_LM_OK) return PLATEAU_OK;
    q = lrc == PLATEAU_LM_ERR_OVERFLOW ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_OUT_OF_MEMORY;
    plateau__util_error(err, (plateau_result)q, -1, "out of memory in the memory bound", 0, 0);
    return (plateau_result)q;
}

/* Steps 3-4: the interior points and the initial mesh.  The quality
 * seeding unless asked for the fan, or automatically when n < m / 4 (the
 * refinement's angle bound puts points along all m kept edges whatever n
 * asks for) or when the refinement delivers fewer than n / 2 points (a
 * coarse polygon whose kept edges stop it short); several loops always
 * take the quality seeding (a fan around one centroid means nothing on a
 * domain with holes).  The memory bound is checked again with the points
 * made.  The mesh and the report's seeding fields come out. */
static plateau_result plateau__cdt_step(plateau__cfg_work *s, const plateau__cfg *cfg,
                                        const plateau__cfg_run *run, double scale, plateau_mesh *mesh,
                                        plateau_report *rep, size_t *nv,
                                        plateau_error *err)
{
    size_t m = s->m, n = s->n;
    int automatic = s->loops <= 1 && cfg->seeding == PLATEAU_SEEDING_AUTO;
    int quality = s->loops > 1 || (cfg->seeding != PLATEAU_SEEDING_PAPER && !(automatic && n < m / 4));
    plateau_quality q0;
    plateau_result rc = PLATEAU_OK;
    if (quality) {
        /* method area's rounds run for method area and for method paper's
         * presolve: they may split long polygon edges (refine_boundary) */
        int area_rounds = cfg->method == PLATEAU_METHOD_AREA ||
                          (cfg->method == PLATEAU_METHOD_PAPER && run->presolve);
        rc = plateau__seed_quality_mesh(s, cfg, run, scale, area_rounds, err);
        if (rc != PLATEAU_OK) return rc;
        if (automatic && 2 * (s->dt.num_points - m) < n) {
            plateau_dt_free(&s->dt);
            memset(&s->dt, 0, sizeof s->dt);
            quality = 0;
        }
    }
    if (!quality) rc = plateau__cdt_fan_mesh(s, cfg->seed, err);
    if (rc != PLATEAU_OK) return rc;
    rc = plateau__cfg_memory_check(cfg, run, (double)m, (double)(s->dt.num_points - m), err);
    if (rc == PLATEAU_ERR_MEMORY_LIMIT) {
        /* the seeded triangulation's own factor size may admit it */
        plateau_error keep;
        double need = 0.0;
        memset(&keep, 0, sizeof keep);
        if (err) keep = *err;
        rc = plateau__cdt_memory_graph(s, cfg, run, &need, err);
        if (rc != PLATEAU_OK) return rc;
        if (!(need > 0.0 && need <= (double)cfg->max_memory)) {
            if (err) *err = keep;
            return PLATEAU_ERR_MEMORY_LIMIT;
        }
    }
    if (rc != PLATEAU_OK) return rc;
    rep->domain_min_angle_deg = plateau__cdt_min_angle(&s->dt);
    rc = plateau__cdt_remap(s, quality, mesh, nv, err);
    if (rc != PLATEAU_OK) return rc;
    rep->seeded_points = *nv - m - s->k;
    rep->boundary_points_added = s->k;
    plateau_mesh_quality(mesh, &q0);
    rep->initial_min_angle_deg = q0.min_angle_deg;
    return PLATEAU_OK;
}
/* ======== END SECTION: step 4: constrained Delaunay triangulation ======== */

/* ======== SECTION: step 5: solve (plateau__solve_) ======================== */
/* One solve of a round: Levenberg-Marquardt (plateau_lm.h) for method paper,
 * L-BFGS or a sparse Newton method on the area for method area. */
/* ---- the solves of one round ---- */
typedef struct plateau__solve_ctx {
    plateau_mesh *mesh;
    plateau_system system;
    plateau_system_options sysopt;
    size_t rows, cols;
    int round;
    int (*progress)(int round, int iteration, double f, void *user);
    void *progress_user;
    double unit;            /* the frame's scale (plateau__cfg_run.unit) */
    plateau_result failure; /* set when the callback stopped the solver */
    plateau__util_budget *budget; /* the time budget (plateau__cfg_run.budget) */
} plateau__solve_ctx;

static void plateau__solve_scatter(plateau_mesh *mesh, const double *x)
{
    size_t v, k = 0;
    for (v = 0; v < mesh->num_vertices; v++) {
        if (mesh->fixed[v]) continue;
        mesh->positions[3 * v] = x[k];
        mesh->positions[3 * v + 1] = x[k + 1];
        mesh->positions[3 * v + 2] = x[k + 2];
        k += 3;
    }
}

static void plateau__solve_gather(const plateau_mesh *mesh, double *x)
{
    size_t v, k = 0;
    for (v = 0; v < mesh->num_vertices; v++) {
        if (mesh->fixed[v]) continue;
        x[k] = mesh->positions[3 * v];
        x[k + 1] = mesh->positions[3 * v + 1];
        x[k + 2] = mesh->positions[3 * v + 2];
        k += 3;
    }
}

/* The LM callback: residuals f (H_i rows, and the tangential rows for
 * method paper) and, when asked, the dense Jacobian from the sparse rows.
 * A trial point with a collapsed triangle may give non-finite values:
 * plateau_lm.h treats that step as failed and shortens it. */
static int plateau__solve_lm_func(const double *x, double *f, double *jac, void *user)
{
    plateau__solve_ctx *ctx = (plateau__solve_ctx *)user;
    plateau_result rc;
    plateau__solve_scatter(ctx->mesh, x);
    ctx->sysopt.residual_only = jac == NULL;
    rc = plateau_system_assemble(ctx->mesh, &ctx->sysopt, &ctx->system, NULL);
    if (rc != PLATEAU_OK || ctx->system.num_rows != ctx->rows) {
        ctx->failure = rc != PLATEAU_OK ? rc : PLATEAU_ERR_SOLVER;
        return 1;
    }
    memcpy(f, ctx->system.residual, ctx->rows * sizeof(double));
    if (jac) plateau_system_dense(&ctx->system, jac);
    return 0;
}

static int plateau__solve_lm_progress(int k, double F, double grad_inf, double mu, int accepted,
                                    void *user)
{
    plateau__solve_ctx *ctx = (plateau__solve_ctx *)user;
    (void)grad_inf;
    (void)mu;
    (void)accepted;
    /* F = 1/2 sum of squared curvatures: length^-2, back to the caller's units */
    if (ctx->progress && ctx->progress(ctx->round, k, F / (ctx->unit * ctx->unit), ctx->progress_user)) {
        ctx->failure = PLATEAU_ERR_ABORTED;
        return 1;
    }
    if (plateau__util_time_up(ctx->budget)) { /* stop at the last accepted point */
        ctx->budget->interrupted = 1;
        return 1;
    }
    return 0;
}

/* Method paper, sparse path (for many free vertices): the square system
 * has one 3 x 3 block row per free vertex (H_v and its two tangential
 * rows) whose blocks are the free vertices of v's closed 1-ring, so its
 * block pattern is the mesh's vertex graph on the free vertices
 * (structurally symmetric, the diagonal stored).  Powell's dog leg
 * (Madsen-Nielsen-Tingleff Algorithm 3.21, plateau_lm_dogleg_solve) with
 * the sparse LU of that pattern replaces the dense LM, whose Cholesky of
 * J^T J costs O(n^3) time and O(n^2) memory. */
typedef struct plateau__solve_sparse {
    plateau__solve_ctx *ctx;
    plateau_index *row_start; /* nfree + 1 */
    plateau_index *cols;      /* the block columns of each block row */
} plateau__solve_sparse;

/* The dog leg callback: the residuals, and the Jacobian's blocks scattered
 * into the pattern's order (row r is row r % 3 of block row r / 3). */
static int plateau__solve_sparse_func(const double *x, double *f, double *jac, void *user)
{
    plateau__solve_sparse *sp = (plateau__solve_sparse *)user;
    plateau__solve_ctx *ctx = sp->ctx;
    const plateau_system *s = &ctx->system;
    plateau_result rc;
    size_t r, p, q;
    plateau__solve_scatter(ctx->mesh, x);
    ctx->sysopt.residual_only = jac == NULL;
    rc = plateau_system_assemble(ctx->mesh, &ctx->sysopt, &ctx->system, NULL);
    if (rc != PLATEAU_OK || s->num_rows != ctx->rows) {
        ctx->failure = rc != PLATEAU_OK ? rc : PLATEAU_ERR_SOLVER;
        return 1;
    }
    memcpy(f, s->residual, ctx->rows * sizeof(double));
    if (!jac) return 0;
    for (q = 0; q < 9 * (size_t)sp->row_start[ctx->rows / 3]; q++) jac[q] = 0.0;
    for (r = 0; r < s->num_rows; r++) {
        size_t node = r / 3;
        for (p = s->row_start[r]; p < s->row_start[r + 1]; p++) {
            plateau_index col = s->column_of_vertex[s->block_vertex[p]] / 3;
            double *b;
            for (q = (size_t)sp->row_start[node]; q < (size_t)sp->row_start[node + 1]; q++)
                if (sp->cols[q] == col) break;
            if (q == (size_t)sp->row_start[node + 1]) { /* a block outside the 1-ring */
                ctx->failure = PLATEAU_ERR_SOLVER;
                return 1;
            }
            b = jac + 9 * q + 3 * (r % 3);
            b[0] += s->block_value[3 * p];
            b[1] += s->block_value[3 * p + 1];
            b[2] += s->block_value[3 * p + 2];
        }
    }
    return 0;
}

static int plateau__solve_sparse_progress(int k, double F, double grad_inf, double delta,
                                        int accepted, void *user)
{
    return plateau__solve_lm_progress(k, F, grad_inf, delta, accepted,
                                    ((plateau__solve_sparse *)user)->ctx);
}

/* The block pattern from the mesh adjacency and 2-D ordering coordinates:
 * the free vertices projected on the plane normal to the mesh's vector
 * area (sum of the triangles' cross products; for a spanning surface the
 * boundary's vector area, the direction of largest projected area), used
 * by the nested dissection's geometric bisection.  One block of memory:
 * row_start, cols, then xy.  *xy_out is NULL when the vector area vanishes
 * (the ordering then bisects by graph levels). */
static void *plateau__solve_sparse_pattern(const plateau_mesh *mesh, size_t nfree,
                                         plateau__solve_sparse *sp, double **xy_out)
{
    size_t v, e, t, k = 0, q = 0, nnz = nfree, bytes, off_cols, off_xy;
    plateau_index *node;
    unsigned char *mem;
    double nrm[3] = {0.0, 0.0, 0.0}, a[3], b[3], len;
    for (v = 0; v < mesh->num_vertices; v++)
        if (!mesh->fixed[v])
            for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
                size_t ed = (size_t)mesh->vertex_edges[e];
                plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1]
                                                                          : mesh->edges[2 * ed];
                nnz += !mesh->fixed[w];
            }
    /* sizes: nfree + 1 + nnz indices, 2 nfree doubles, num_vertices indices of scratch */
    off_cols = (nfree + 1) * sizeof(plateau_index);
    off_xy = off_cols + nnz * sizeof(plateau_index);
    off_xy = (off_xy + sizeof(double) - 1) / sizeof(double) * sizeof(double);
    if (nnz > ((size_t)-1 - off_xy) / 4 || nfree > ((size_t)-1) / 64 ||
        mesh->num_vertices > ((size_t)-1) / 64)
        return NULL;
    bytes = off_xy + 2 * nfree * sizeof(double) + mesh->num_vertices * sizeof(plateau_index);
    mem = (unsigned char *)plateau__alloc(&mesh->allocator, bytes);
    if (!mem) return NULL;
    sp->row_start = (plateau_index *)(void *)mem;
    sp->cols = (plateau_index *)(void *)(mem + off_cols);
    *xy_out = (double *)(void *)(mem + off_xy);
    node = (plateau_index *)(void *)(mem + off_xy + 2 * nfree * sizeof(double));
    for (v = 0; v < mesh->num_vertices; v++) node[v] = mesh->fixed[v] ? -1 : (plateau_index)k++;
    for (v = 0, k = 0; v < mesh->num_vertices; v++) {
        if (mesh->fixed[v]) continue;
        sp->row_start[k++] = (plateau_index)q;
        sp->cols[q++] = node[v];
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1]
                                                                      : mesh->edges[2 * ed];
            if (!mesh->fixed[w]) sp->cols[q++] = node[w];
        }
    }
    sp->row_start[k] = (plateau_index)q;
    for (t = 0; t < mesh->num_triangles; t++) {
        const double *p0 = mesh->positions + 3 * (size_t)mesh->triangles[3 * t];
        const double *p1 = mesh->positions + 3 * (size_t)mesh->triangles[3 * t + 1];
        const double *p2 = mesh->positions + 3 * (size_t)mesh->triangles[3 * t + 2];
        double d1[3], d2[3];
        int i;
        for (i = 0; i < 3; i++) { d1[i] = p1[i] - p0[i]; d2[i] = p2[i] - p0[i]; }
        nrm[0] += d1[1] * d2[2] - d1[2] * d2[1];
        nrm[1] += d1[2] * d2[0] - d1[0] * d2[2];
        nrm[2] += d1[0] * d2[1] - d1[1] * d2[0];
    }
    len = PLATEAU_SQRT(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(len > 0.0) || !plateau__util_finite(len)) {
        *xy_out = NULL;
        return mem;
    }
    nrm[0] /= len; nrm[1] /= len; nrm[2] /= len;
    /* a: the coordinate axis least aligned with the normal, made orthogonal */
    k = PLATEAU_FABS(nrm[0]) <= PLATEAU_FABS(nrm[1]) ? (PLATEAU_FABS(nrm[0]) <= PLATEAU_FABS(nrm[2]) ? 0 : 2)
                                     : (PLATEAU_FABS(nrm[1]) <= PLATEAU_FABS(nrm[2]) ? 1 : 2);
    a[0] = a[1] = a[2] = 0.0;
    a[k] = 1.0;
    len = a[0] * nrm[0] + a[1] * nrm[1] + a[2] * nrm[2];
    for (t = 0; t < 3; t++) a[t] -= len * nrm[t];
    len = PLATEAU_SQRT(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (t = 0; t < 3; t++) a[t] /= len;
    b[0] = nrm[1] * a[2] - nrm[2] * a[1];
    b[1] = nrm[2] * a[0] - nrm[0] * a[2];
    b[2] = nrm[0] * a[1] - nrm[1] * a[0];
    for (v = 0, k = 0; v < mesh->num_vertices; v++) {
        const double *p = mesh->positions + 3 * v;
        if (mesh->fixed[v]) continue;
        (*xy_out)[2 * k] = p[0] * a[0] + p[1] * a[1] + p[2] * a[2];
        (*xy_out)[2 * k + 1] = p[0] * b[0] + p[1] * b[1] + p[2] * b[2];
        k++;
    }
    return mem;
}

/* Method paper's square system is solved: F at most this, in the unit
 * frame (plateau_report.solved). */
#define PLATEAU__CHK_SOLVED_F 1e-10

/* Method paper's Newton tail on the sparse path.  The dog leg's step test
 * ends a solve once a step is at most eps_step ||x|| long (eps_step 1e-12):
 * x has converged to 12 digits of its norm, which is not F's convergence
 * when J is large against ||x|| (J grows as 1 / l^2 with the shortest edges
 * l, the boundary's on a densely sampled curve; or with lambda).  A
 * Gauss-Newton step that short may still cut F by orders, to its rounding
 * level, and the solve ended above PLATEAU__CHK_SOLVED_F, unsolved
 * (examples/NOTES.md, section 15; tests/test_solve_paths.c).  A solve that
 * ends by the step test above that bound goes on from its point (a second
 * dog-leg run) with the step test at rounding level (DBL_EPSILON ||x||)
 * until F meets the bound (the dog leg's f_stop), or for at most
 * PLATEAU__SOLVE_TAIL_STEPS steps (the rounding level of F itself may lie
 * above the bound); every solve that ends at or below the bound is left as
 * it was. */
#define PLATEAU__SOLVE_TAIL_STEPS 5

/* The sparse solve of one round: same options, stopping rules and report
 * as the dense LM (the dog leg needs no damping scaling: its trust region
 * is a ball), and the Newton tail above. */
static plateau_lm_result plateau__solve_sparse_solve(plateau__solve_ctx *ctx, size_t nfree, double *x,
                                                   plateau_lm_options *lo, plateau_lm_report *lr)
{
    plateau__solve_sparse sp;
    plateau_lm_sparse_pattern pat;
    plateau_lm_result lrc;
    double *xy = NULL;
    void *mem;
    sp.ctx = ctx;
    mem = plateau__solve_sparse_pattern(ctx->mesh, nfree, &sp, &xy);
    if (!mem) return PLATEAU_LM_ERR_OUT_OF_MEMORY;
    pat.nodes = nfree;
    pat.block = 3;
    pat.row_start = sp.row_start;
    pat.cols = sp.cols;
    lo->scaling = PLATEAU_LM_SCALING_NONE;
    lo->progress = plateau__solve_sparse_progress;
    lrc = plateau_lm_dogleg_solve(&pat, xy, x, plateau__solve_sparse_func, &sp, lo, lr);
    if (lrc == PLATEAU_LM_OK && lr->stop == PLATEAU_LM_STOP_STEP && lr->f_final > PLATEAU__CHK_SOLVED_F &&
        (lo->max_iterations == 0 || (size_t)lo->max_iterations > lr->iterations)) {
        plateau_lm_options tail = *lo;
        plateau_lm_report tr;
        tail.eps_step = DBL_EPSILON;
        tail.f_stop = PLATEAU__CHK_SOLVED_F;
        tail.max_iterations = PLATEAU__SOLVE_TAIL_STEPS; /* within the caller's max_iterations: */
        if (lo->max_iterations != 0 && (size_t)lo->max_iterations - lr->iterations < (size_t)tail.max_iterations)
            tail.max_iterations = (int)((size_t)lo->max_iterations - lr->iterations);
        lrc = plateau_lm_dogleg_solve(&pat, xy, x, plateau__solve_sparse_func, &sp, &tail, &tr);
        lr->iterations += tr.iterations;
        lr->residual_evaluations += tr.residual_evaluations;
        lr->jacobian_evaluations += tr.jacobian_evaluations;
        lr->f_final = tr.f_final;
        lr->grad_inf = tr.grad_inf;
        lr->mu_final = tr.mu_final;
        lr->stop = tr.stop;
    }
    plateau__free(&ctx->mesh->allocator, mem);
    return lrc;
}

/* The analysis (nested dissection by xy) of a pattern made by
 * plateau__solve_sparse_pattern with block unknowns per node, and a Cholesky
 * factor object for it, both through al; on error both are NULL. */
static plateau_lm_result plateau__solve_cholesky_new(const plateau__solve_sparse *sp, size_t nodes,
                                                   int block, const double *xy,
                                                   const plateau_allocator *al,
                                                   plateau_lm_sparse_symbolic **sym,
                                                   plateau_lm_sparse_factor **fac)
{
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_options so;
    plateau_lm_result lrc;
    memset(&so, 0, sizeof so);
    pat.nodes = nodes;
    pat.block = block;
    pat.row_start = sp->row_start;
    pat.cols = sp->cols;
    so.allocator = *al;
    *fac = NULL;
    lrc = plateau_lm_sparse_analyze(&pat, xy, &so, sym);
    if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_factor_create(*sym, PLATEAU_LM_SPARSE_CHOLESKY, NULL, 0, fac);
    if (lrc != PLATEAU_LM_OK) {
        plateau_lm_sparse_symbolic_free(*sym);
        *sym = NULL;
    }
    return lrc;
}

/* The system L x = b of a discrete harmonic map with edge weights w (n
 * free vertices, the pattern sp of plateau__solve_sparse_pattern): row k
 * of the free vertex v holds sum_j w_vj on the diagonal and -w_vj for each
 * free neighbour j, in the pattern's order (v's edges in vertex_edges
 * order); b_v = sum of w_vj x_j over the fixed neighbours j, into x (one
 * column of n per coordinate). */
static void plateau__solve_laplacian_rows(const plateau_mesh *mesh, const plateau__solve_sparse *sp,
                                          const double *w, size_t n, double *vals, double *x)
{
    size_t i, k, e, q;
    int c;
    for (i = 0; i < 3 * n; i++) x[i] = 0.0;
    for (i = 0, k = 0; i < mesh->num_vertices; i++) {
        size_t q0;
        if (mesh->fixed[i]) continue;
        q0 = (size_t)sp->row_start[k];
        q = q0 + 1;
        vals[q0] = 0.0;
        for (e = mesh->vertex_edge_start[i]; e < mesh->vertex_edge_start[i + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index o = mesh->edges[2 * ed] == (plateau_index)i ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed];
            vals[q0] += w[ed];
            if (!mesh->fixed[o]) vals[q++] = -w[ed];
            else
                for (c = 0; c < 3; c++) x[(size_t)c * n + k] += w[ed] * mesh->positions[3 * (size_t)o + (size_t)c];
        }
        k++;
    }
}

/* The free vertices of mesh (their positions are overwritten) by the
 * discrete harmonic map of the planar triangulation uvpos (2 values per
 * mesh vertex): for every free vertex sum_j w_ij (x_i - x_j) = 0 with the
 * cotangent weights w_ij = (cot alpha_ij + cot beta_ij) / 2 of the plane
 * triangles, the fixed vertices as they are.  The weights of a
 * constrained Delaunay triangulation are >= 0 on its interior edges and
 * the map reproduces linear functions of uv exactly, so on the best-fit
 * plane domain a point projects back onto its domain point, as with the
 * mean-value coordinates (Floater 2003 derives those as an approximation
 * of this map).  One sparse Cholesky (plateau_lm.h) for the three
 * coordinates: O(n log n) memory for n free vertices.  PLATEAU_OK,
 * _OUT_OF_MEMORY, or _TRIANGULATION when the system is not positive
 * definite or gives a non-finite point. */
static plateau_result plateau__solve_harmonic_place(plateau_mesh *mesh, const double *uvpos,
                                                    plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, ne = mesh->num_edges, n = 0, e, i, k;
    double *w = NULL, *x = NULL, *vals = NULL, *xy = NULL;
    void *pmem = NULL;
    plateau__solve_sparse sp;
    plateau_lm_sparse_symbolic *sym = NULL;
    plateau_lm_sparse_factor *fac = NULL;
    plateau_lm_result lrc;
    plateau_result rc = PLATEAU_OK;
    int c;
    memset(&sp, 0, sizeof sp);
    for (i = 0; i < nv; i++) n += !mesh->fixed[i];
    if (n == 0) return PLATEAU_OK;
    w = (double *)plateau__util_array(al, ne, sizeof(double));
    x = (double *)plateau__util_array(al, n, 3 * sizeof(double));
    pmem = plateau__solve_sparse_pattern(mesh, n, &sp, &xy);
    vals = pmem ? (double *)plateau__util_array(al, (size_t)sp.row_start[n], sizeof(double)) : NULL;
    if (!w || !x || !pmem || !vals) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        goto done;
    }
    for (e = 0; e < ne; e++) {
        int s2;
        w[e] = 0.0;
        for (s2 = 0; s2 < 2; s2++) {
            plateau_index tr = mesh->edge_triangles[2 * e + (size_t)s2];
            plateau_index a = mesh->edges[2 * e], b = mesh->edges[2 * e + 1], o;
            double ux, uy, vx, vy, cr;
            if (tr < 0) continue;
            o = plateau__geo_opposite(mesh, tr, a, b);
            ux = uvpos[2 * (size_t)a] - uvpos[2 * (size_t)o];
            uy = uvpos[2 * (size_t)a + 1] - uvpos[2 * (size_t)o + 1];
            vx = uvpos[2 * (size_t)b] - uvpos[2 * (size_t)o];
            vy = uvpos[2 * (size_t)b + 1] - uvpos[2 * (size_t)o + 1];
            cr = PLATEAU_FABS(ux * vy - uy * vx);
            if (cr > 0.0) w[e] += 0.5 * (ux * vx + uy * vy) / cr;
        }
    }
    plateau__solve_laplacian_rows(mesh, &sp, w, n, vals, x);
    /* the ordering bisects the domain points: the free vertices are not
     * placed yet (all at the origin), and on equal coordinates the
     * bisection falls back to breadth-first levels, which on the graded
     * mesh of a dense boundary run along the whole boundary band (fronts
     * of thousands of vertices: m = 10^5 needed gigabytes) */
    if (xy)
        for (i = 0, k = 0; i < nv; i++)
            if (!mesh->fixed[i]) {
                xy[2 * k] = uvpos[2 * i];
                xy[2 * k + 1] = uvpos[2 * i + 1];
                k++;
            }
    lrc = plateau__solve_cholesky_new(&sp, n, 1, xy, al, &sym, &fac);
    if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_factorize(fac, vals, 0.0);
    if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_solve(fac, 3, x, n);
    if (lrc == PLATEAU_LM_ERR_OUT_OF_MEMORY) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        goto done;
    }
    for (i = 0; i < 3 * n && lrc == PLATEAU_LM_OK; i++)
        if (!plateau__util_finite(x[i])) lrc = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    if (lrc != PLATEAU_LM_OK) {
        rc = PLATEAU_ERR_TRIANGULATION;
        goto done;
    }
    for (i = 0, k = 0; i < nv; i++) {
        if (mesh->fixed[i]) continue;
        for (c = 0; c < 3; c++) mesh->positions[3 * i + (size_t)c] = x[(size_t)c * n + k];
        k++;
    }
done:
    if (rc == PLATEAU_ERR_OUT_OF_MEMORY)
        plateau__util_error(err, rc, -1, "out of memory while placing the refinement points", 0, 0);
    else if (rc != PLATEAU_OK)
        plateau__util_error(err, rc, -1, "the harmonic map of the refined triangulation failed", 0, 0);
    plateau_lm_sparse_factor_free(fac);
    plateau_lm_sparse_symbolic_free(sym);
    plateau__free(al, pmem);
    plateau__free(al, vals);
    plateau__free(al, w);
    plateau__free(al, x);
    return rc;
}

/* Fig. 5's tolerances for method paper-literal: eps (tau and the F-change
 * test) and sqrt(eps) (the step test). */
#define PLATEAU__SOLVE_FIG5_EPS 1e-6
#define PLATEAU__SOLVE_FIG5_SQRT_EPS 1e-3

/* Method paper / paper-literal: one LM solve (paper II.D) on the free
 * vertices' coordinates.  paper: rows H_i and the two tangential rows of
 * every free vertex (square); paper-literal: H_i of every vertex (the
 * paper's F over all m + n vertices, equation (1)). */
static plateau_result plateau__solve_lm(plateau_mesh *mesh, const plateau__cfg *cfg,
                                      const plateau__cfg_run *run, int round,
                                      unsigned char *all_rows, plateau_report *rep,
                                      double *f0, double *f1, plateau_error *err)
{
    plateau__solve_ctx ctx;
    plateau_lm_options lo;
    plateau_lm_report lr;
    plateau_lm_result lrc;
    size_t v, nfree = 0;
    double *x, lbar;
    memset(&ctx, 0, sizeof ctx);
    memset(&lo, 0, sizeof lo);
    memset(&lr, 0, sizeof lr);
    for (v = 0; v < mesh->num_vertices; v++) nfree += !mesh->fixed[v];
    ctx.mesh = mesh;
    ctx.round = round;
    ctx.progress = cfg->progress;
    ctx.progress_user = cfg->progress_user;
    ctx.unit = run->unit;
    ctx.budget = run->budget;
    ctx.cols = 3 * nfree;
    if (cfg->method == PLATEAU_METHOD_PAPER) {
        lbar = plateau_mean_edge_length(mesh);
        ctx.sysopt.tangential_weight = cfg->lambda / (lbar * lbar);
        ctx.sysopt.mean_curvature = run->pressure; /* H_i = p (MEMBRANES) */
        ctx.rows = 3 * nfree;
    } else {
        for (v = 0; v < mesh->num_vertices; v++) all_rows[v] = 1;
        ctx.sysopt.row_vertices = all_rows;
        ctx.rows = mesh->num_vertices;
    }
    x = (double *)plateau__util_array(&mesh->allocator, ctx.cols, sizeof(double));
    if (!x) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory before the LM solve", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    plateau__solve_gather(mesh, x);
    lo.max_iterations = cfg->max_iterations;
    lo.allocator = mesh->allocator;
    lo.progress = plateau__solve_lm_progress;
    /* plateau.h's systems are square and its F is zero at the answer:
     * no QR refinement, no geodesic acceleration (plateau_lm.h defaults
     * them on for data fitting) */
    lo.refine = -1;
    lo.geodesic = PLATEAU_LM_GEODESIC_NEVER;
    if (cfg->method == PLATEAU_METHOD_PAPER_LITERAL) {
        /* Fig. 5 as printed where it is usable: mu I damping (no scaling),
         * tau = eps = 1e-6, the step test at sqrt(eps), the F-change test at
         * eps (on accepted steps only: as printed it fires on every rejected
         * step).  The gradient test stays plateau_lm.h's scale-free cosine
         * test: the printed ||g|| < eps^(1/3) (1 + F) stops far from the
         * minimum (examples/NOTES.md). */
        lo.scaling = PLATEAU_LM_SCALING_NONE;
        lo.eps_step = PLATEAU__SOLVE_FIG5_SQRT_EPS;
        lo.eps_f = PLATEAU__SOLVE_FIG5_EPS;
    }
    if (cfg->method == PLATEAU_METHOD_PAPER && plateau__cfg_sparse(cfg->linear_solver, (double)nfree)) {
        rep->linear_solver = PLATEAU_LINEAR_SPARSE;
        lrc = plateau__solve_sparse_solve(&ctx, nfree, x, &lo, &lr);
    } else {
        if (cfg->method == PLATEAU_METHOD_PAPER) rep->linear_solver = PLATEAU_LINEAR_DENSE;
        lrc = plateau_lm_solve(ctx.rows, ctx.cols, x, plateau__solve_lm_func, &ctx, &lo, NULL, 0, &lr, NULL);
    }
    plateau__solve_scatter(mesh, x); /* the solution, not the last trial point */
    plateau__free(&mesh->allocator, x);
    plateau_system_free(&ctx.system);
    rep->iterations += lr.iterations;
    rep->evaluations += lr.residual_evaluations;
    rep->lm_stop = lr.stop;
    *f0 = lr.f_initial;
    *f1 = lr.f_final;
    if (ctx.failure != PLATEAU_OK) {
        plateau__util_error(err, ctx.failure, -1,
                               ctx.failure == PLATEAU_ERR_ABORTED ? "the progress callback asked to stop"
                                                                  : "out of memory while evaluating the residuals", 0, 0);
        return ctx.failure;
    }
    if (lrc == PLATEAU_LM_ERR_ABORTED && ctx.budget && ctx.budget->interrupted) {
        /* the time budget: x is the last accepted point; for method paper
         * it is solved when its own F meets the stopping rule (the limit
         * fell on the iteration that converged) */
        if (cfg->method == PLATEAU_METHOD_PAPER && lr.f_final <= PLATEAU__CHK_SOLVED_F)
            ctx.budget->interrupted = 0;
        return PLATEAU_OK;
    }
    if (lrc != PLATEAU_LM_OK) return plateau__util_lm_error(lrc, NULL, err);
    return PLATEAU_OK;
}

/* Method area: L-BFGS (Nocedal and Wright, "Numerical Optimization", 2nd
 * ed., algorithm 7.4, two-loop recursion with memory 8) on the total area,
 * exact gradient (paper II.C.1), backtracking Armijo line search
 * (c1 = 1e-4, halving) with the step capped at half the mean edge length;
 * a pair is kept only when s.y > 0. */
/* L-BFGS: pairs (s, y) kept (Nocedal and Wright's m, 3 to 20 typical), and
 * step halvings the Armijo line search tries before it gives up. */
#define PLATEAU__LBFGS_HISTORY 8
#define PLATEAU__LBFGS_TRIES 60
/* Armijo's sufficient decrease c1 (Nocedal and Wright, (3.4)). */
#define PLATEAU__LBFGS_ARMIJO 1e-4
/* The longest step, in mean edge lengths. */
#define PLATEAU__LBFGS_MAX_STEP 0.5
/* SMALL_CHANGE: the area fell by less than this fraction of it over the
 * last PLATEAU__LBFGS_WINDOW steps (why these values: examples/NOTES.md,
 * "Measurements behind the solver's choices"). */
#define PLATEAU__LBFGS_SMALL_CHANGE 1e-10
#define PLATEAU__LBFGS_WINDOW 20
/* GRADIENT (L-BFGS and Newton): max |g| at most this times the mean edge
 * length. */
#define PLATEAU__AREA_GTOL 1e-10

/* The objective of method area: the area, or with a pressure, a volume or
 * cables the membrane energy (plateau_membrane_energy); gradient (may be
 * NULL): 3 per vertex.  A film vertex beyond run->escape from the apex
 * gives DBL_MAX, which the line searches refuse: a film with no
 * equilibrium (too high a pressure) stops at that sphere, and the driver
 * names it (PLATEAU_DEFECT_NO_EQUILIBRIUM). */
static double plateau__solve_energy(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                    const plateau__cfg_run *run, double *gradient)
{
    if (!cfg->membrane) {
        if (gradient) plateau_mesh_area_gradient(mesh, gradient);
        return plateau_mesh_area(mesh);
    }
    if (run->escape > 0.0) {
        size_t v;
        for (v = 0; v < mesh->num_vertices; v++) {
            double d[3];
            plateau__util_sub(plateau__geo_pos(mesh, (plateau_index)v), run->apex, d);
            if (!(plateau__util_dot(d, d) <= run->escape * run->escape)) return DBL_MAX;
        }
    }
    return plateau_membrane_energy(mesh, run->pressure, run->apex, run->cable_seg, run->cable_t,
                                   run->cable_nseg, gradient);
}

static plateau_result plateau__solve_lbfgs(plateau_mesh *mesh, const plateau__cfg *cfg,
                                         const plateau__cfg_run *run, int round,
                                         plateau_report *rep, double *f0, double *f1,
                                         plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nfree = 0, n, v, i, j;
    double *x, *g, *d, *xt, *gt, *s, *y, *full, rho[PLATEAU__LBFGS_HISTORY], alpha[PLATEAU__LBFGS_HISTORY];
    double f, ft, lbar, gtol, fscale, hist_f[PLATEAU__LBFGS_WINDOW];
    int k, hist = 0, head = 0;
    plateau_area_stop stop = PLATEAU_AREA_STOP_MAX_ITERATIONS;
    int max_iter = cfg->max_iterations;
    plateau_result rc = PLATEAU_OK;
    for (v = 0; v < mesh->num_vertices; v++) nfree += !mesh->fixed[v];
    n = 3 * nfree;
    x = (double *)plateau__util_array(al, n, sizeof(double));
    g = (double *)plateau__util_array(al, n, sizeof(double));
    d = (double *)plateau__util_array(al, n, sizeof(double));
    xt = (double *)plateau__util_array(al, n, sizeof(double));
    gt = (double *)plateau__util_array(al, n, sizeof(double));
    s = (double *)plateau__util_array(al, n, PLATEAU__LBFGS_HISTORY * sizeof(double));
    y = (double *)plateau__util_array(al, n, PLATEAU__LBFGS_HISTORY * sizeof(double));
    full = (double *)plateau__util_array(al, mesh->num_vertices, 3 * sizeof(double));
    if (!x || !g || !d || !xt || !gt || !s || !y || !full) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in the area minimisation", 0, 0);
        goto done;
    }
    lbar = plateau_mean_edge_length(mesh);
    gtol = PLATEAU__AREA_GTOL * lbar;
    plateau__solve_gather(mesh, x);
    f = plateau__solve_energy(mesh, cfg, run, full);
    fscale = plateau_mesh_area(mesh); /* a membrane's energy may be negative: its
                                         SMALL_CHANGE is relative to this area */
    for (v = 0, j = 0; v < mesh->num_vertices; v++)
        if (!mesh->fixed[v]) { g[j] = full[3 * v]; g[j + 1] = full[3 * v + 1]; g[j + 2] = full[3 * v + 2]; j += 3; }
    rep->evaluations++;
    *f0 = f;
    for (k = 0; k < max_iter; k++) {
        double gmax = 0.0, dmax = 0.0, gd = 0.0, t;
        int tries, ok = 0;
        for (i = 0; i < n; i++) gmax = PLATEAU_FABS(g[i]) > gmax ? PLATEAU_FABS(g[i]) : gmax;
        if (gmax <= gtol) { stop = PLATEAU_AREA_STOP_GRADIENT; break; }
        /* two-loop recursion: d = -H g */
        for (i = 0; i < n; i++) d[i] = -g[i];
        for (j = 0; j < (size_t)hist; j++) {
            size_t slot = (size_t)((head - 1 - (int)j + 2 * PLATEAU__LBFGS_HISTORY) % PLATEAU__LBFGS_HISTORY);
            double a = 0.0;
            for (i = 0; i < n; i++) a += s[slot * n + i] * d[i];
            a *= rho[slot];
            alpha[slot] = a;
            for (i = 0; i < n; i++) d[i] -= a * y[slot * n + i];
        }
        if (hist > 0) {
            size_t last = (size_t)((head - 1 + PLATEAU__LBFGS_HISTORY) % PLATEAU__LBFGS_HISTORY);
            double sy = 0.0, yy = 0.0;
            for (i = 0; i < n; i++) { sy += s[last * n + i] * y[last * n + i]; yy += y[last * n + i] * y[last * n + i]; }
            for (i = 0; i < n; i++) d[i] *= sy / yy;
        }
        for (j = (size_t)hist; j > 0; j--) {
            size_t slot = (size_t)((head - (int)j + 2 * PLATEAU__LBFGS_HISTORY) % PLATEAU__LBFGS_HISTORY);
            double b = 0.0;
            for (i = 0; i < n; i++) b += y[slot * n + i] * d[i];
            b *= rho[slot];
            for (i = 0; i < n; i++) d[i] += (alpha[slot] - b) * s[slot * n + i];
        }
        for (i = 0; i < n; i++) gd += g[i] * d[i];
        if (!(gd < 0.0)) { /* not a descent direction: restart from steepest descent */
            hist = 0;
            gd = 0.0;
            for (i = 0; i < n; i++) { d[i] = -g[i]; gd -= g[i] * g[i]; }
        }
        for (i = 0; i < n; i++) dmax = PLATEAU_FABS(d[i]) > dmax ? PLATEAU_FABS(d[i]) : dmax;
        t = 1.0;
        if (t * dmax > PLATEAU__LBFGS_MAX_STEP * lbar) t = PLATEAU__LBFGS_MAX_STEP * lbar / dmax;
        ft = f;
        for (tries = 0; tries < PLATEAU__LBFGS_TRIES; tries++) {
            for (i = 0; i < n; i++) xt[i] = x[i] + t * d[i];
            plateau__solve_scatter(mesh, xt);
            ft = plateau__solve_energy(mesh, cfg, run, NULL);
            rep->evaluations++;
            if (ft <= f + PLATEAU__LBFGS_ARMIJO * t * gd) { ok = 1; break; }
            t *= 0.5;
        }
        if (!ok) {
            plateau__solve_scatter(mesh, x);
            stop = PLATEAU_AREA_STOP_LINE_SEARCH;
            break;
        }
        plateau__solve_energy(mesh, cfg, run, full);
        for (v = 0, j = 0; v < mesh->num_vertices; v++)
            if (!mesh->fixed[v]) { gt[j] = full[3 * v]; gt[j + 1] = full[3 * v + 1]; gt[j + 2] = full[3 * v + 2]; j += 3; }
        {
            size_t slot = (size_t)head;
            double sy = 0.0;
            for (i = 0; i < n; i++) {
                s[slot * n + i] = xt[i] - x[i];
                y[slot * n + i] = gt[i] - g[i];
                sy += s[slot * n + i] * y[slot * n + i];
            }
            if (sy > 0.0) {
                rho[slot] = 1.0 / sy;
                head = (head + 1) % PLATEAU__LBFGS_HISTORY;
                if (hist < PLATEAU__LBFGS_HISTORY) hist++;
            }
        }
        for (i = 0; i < n; i++) { x[i] = xt[i]; g[i] = gt[i]; }
        f = ft;
        rep->iterations++;
        if (cfg->progress && cfg->progress(round, k + 1, f * run->unit * run->unit, cfg->progress_user)) {
            rc = PLATEAU_ERR_ABORTED;
            plateau__util_error(err, rc, -1, "the progress callback asked to stop", 0, 0);
            break;
        }
        if (plateau__util_time_up(run->budget)) {
            run->budget->interrupted = 1;
            break;
        }
        /* SMALL_CHANGE: on a connectivity whose minimiser is degenerate (a
         * triangle collapsing) the area creeps down for thousands of steps,
         * and the flips that follow fix the connectivity */
        hist_f[k % PLATEAU__LBFGS_WINDOW] = f;
        if (k >= PLATEAU__LBFGS_WINDOW &&
            hist_f[(k + 1) % PLATEAU__LBFGS_WINDOW] - f <=
                PLATEAU__LBFGS_SMALL_CHANGE * (cfg->membrane ? fscale : f)) {
            stop = PLATEAU_AREA_STOP_SMALL_CHANGE;
            break;
        }
    }
    rep->area_stop = stop;
    *f1 = f;
done:
    plateau__free(al, x);
    plateau__free(al, g);
    plateau__free(al, d);
    plateau__free(al, xt);
    plateau__free(al, gt);
    plateau__free(al, s);
    plateau__free(al, y);
    plateau__free(al, full);
    return rc;
}

/* Method area on the sparse path: the second derivatives of the area.
 * For a triangle (p_0, p_1, p_2) with N = (p_1 - p_0) x (p_2 - p_0), A =
 * |N| / 2 and e_i = p_(i+1) - p_(i+2) (indices mod 3), a motion d_i of the
 * corners changes N by sum_i d_i x e_i, so (with n = N / |N|, [v] the cross
 * product matrix v x ., P = I - n n^T)
 *   dA/dp_i        = (e_i x n) / 2                       (paper II.C.1)
 *   d2A/dp_i dp_j  = -[e_i] P [e_j] / (2 |N|) + s_ij [n] / 2,
 * s_ij = -1 for j = i + 1, +1 for j = i + 2, 0 for j = i: the first term
 * from the change of |N| in the plane normal to n, the second from the
 * bilinear dependence of N on the corners.  Also the cotangent Laplacian
 * of Pinkall and Polthier (edge weight (cot alpha + cot beta) / 2): the
 * Hessian of the Dirichlet energy D whose gradient at the current mesh is
 * the area's, D >= A everywhere, so L - H_A is positive semi-definite;
 * here with each cotangent clipped at 0 (plateau__solve_newton says
 * why), a weighted graph Laplacian.  Both as 3 x 3 blocks in the order of the 1-ring
 * pattern (sp->row_start, sp->cols; node: vertex -> free index or -1);
 * -1 when a triangle is degenerate or a block lies outside the pattern. */
static int plateau__solve_area_hessian(const plateau_mesh *mesh, const plateau_index *node,
                                     size_t nfree, const plateau__solve_sparse *sp, double *hv,
                                     double *lv)
{
    size_t t, q, nblocks = (size_t)sp->row_start[nfree];
    for (q = 0; q < 9 * nblocks; q++) hv[q] = lv[q] = 0.0;
    for (t = 0; t < mesh->num_triangles; t++) {
        const plateau_index *tr = mesh->triangles + 3 * t;
        const double *p[3];
        double nv[3], e[3][3], c[3][9], pc[3][9], len, cot[3];
        int i, j, r, s;
        for (i = 0; i < 3; i++) p[i] = plateau__geo_pos(mesh, tr[i]);
        plateau__util_corner_cross(p[0], p[1], p[2], nv);
        len = plateau__util_norm(nv);
        if (!(len > 0.0) || !plateau__util_finite(len)) return -1;
        for (i = 0; i < 3; i++) nv[i] /= len;
        for (i = 0; i < 3; i++) {
            double u[3], w[3];
            plateau__util_sub(p[(i + 1) % 3], p[(i + 2) % 3], e[i]);
            /* [e_i] and P [e_i] */
            c[i][0] = 0.0;      c[i][1] = -e[i][2]; c[i][2] = e[i][1];
            c[i][3] = e[i][2];  c[i][4] = 0.0;      c[i][5] = -e[i][0];
            c[i][6] = -e[i][1]; c[i][7] = e[i][0];  c[i][8] = 0.0;
            for (s = 0; s < 3; s++) {
                double nc = nv[0] * c[i][s] + nv[1] * c[i][3 + s] + nv[2] * c[i][6 + s];
                for (r = 0; r < 3; r++) pc[i][3 * r + s] = c[i][3 * r + s] - nv[r] * nc;
            }
            /* cot of the corner i: u . w / |u x w| with |u x w| = |N| */
            plateau__util_sub(p[(i + 1) % 3], p[i], u);
            plateau__util_sub(p[(i + 2) % 3], p[i], w);
            cot[i] = plateau__util_dot(u, w) / len;
            if (!(cot[i] > 0.0)) cot[i] = 0.0; /* obtuse: clipped, see below */
        }
        for (i = 0; i < 3; i++) {
            plateau_index ni = node[tr[i]];
            if (ni < 0) continue;
            for (j = 0; j < 3; j++) {
                plateau_index nj = node[tr[j]];
                double *hb, *lb, sg, wl;
                if (nj < 0) continue;
                for (q = (size_t)sp->row_start[ni]; q < (size_t)sp->row_start[ni + 1]; q++)
                    if (sp->cols[q] == nj) break;
                if (q == (size_t)sp->row_start[ni + 1]) return -1;
                hb = hv + 9 * q;
                lb = lv + 9 * q;
                /* -[e_i] P [e_j] / (2 |N|) */
                for (r = 0; r < 3; r++)
                    for (s = 0; s < 3; s++)
                        hb[3 * r + s] -= 0.5 / len * (c[i][3 * r] * pc[j][s] + c[i][3 * r + 1] * pc[j][3 + s] +
                                                      c[i][3 * r + 2] * pc[j][6 + s]);
                sg = j == (i + 1) % 3 ? -0.5 : j == (i + 2) % 3 ? 0.5 : 0.0;
                hb[1] -= sg * nv[2]; hb[2] += sg * nv[1];
                hb[3] += sg * nv[2]; hb[5] -= sg * nv[0];
                hb[6] -= sg * nv[1]; hb[7] += sg * nv[0];
                /* the edge (i, k) carries cot of the third corner / 2 */
                if (i == j) wl = 0.5 * (cot[(i + 1) % 3] + cot[(i + 2) % 3]);
                else wl = -0.5 * cot[3 - i - j];
                lb[0] += wl; lb[4] += wl; lb[8] += wl;
            }
        }
    }
    return 0;
}

/* The slot of block (i, j) in the 1-ring pattern, or -1. */
static long plateau__solve_block(const plateau__solve_sparse *sp, plateau_index i, plateau_index j)
{
    size_t q;
    for (q = (size_t)sp->row_start[i]; q < (size_t)sp->row_start[i + 1]; q++)
        if (sp->cols[q] == j) return (long)q;
    return -1;
}

/* The membrane's terms of the Hessian added to the area's blocks hv: -p
 * times the volume's (for a triangle with r_q = p_q - apex, V = r_0 .
 * (r_1 x r_2) / 6, so d2V/dr_i dr_(i+1) = E(r_(i+2)) / 6 and d2V/dr_i
 * dr_(i+2) = -E(r_(i+1)) / 6 with E(c) the matrix [[0, c2, -c1], [-c2, 0,
 * c0], [c1, -c0, 0]], the diagonal blocks 0), and T times each cable
 * segment's (T (I - u u^T) / |s| on the diagonal blocks, minus it off the
 * diagonal, u the segment's direction).  -1 when a block lies outside the
 * pattern. */
static int plateau__solve_membrane_hessian(const plateau_mesh *mesh, const plateau__cfg_run *run,
                                           const plateau_index *node, const plateau__solve_sparse *sp,
                                           double *hv)
{
    size_t t, sg;
    if (run->pressure != 0.0)
        for (t = 0; t < mesh->num_triangles; t++) {
            const plateau_index *tr = mesh->triangles + 3 * t;
            double r[3][3];
            int i, d;
            for (i = 0; i < 3; i++) plateau__util_sub(plateau__geo_pos(mesh, tr[i]), run->apex, r[i]);
            for (i = 0; i < 3; i++)
                for (d = 1; d <= 2; d++) {
                    plateau_index ni = node[tr[i]], nj = node[tr[(i + d) % 3]];
                    const double *c = r[(i + 3 - d) % 3]; /* d = 1: r_(i+2); d = 2: r_(i+1) */
                    double f = (d == 1 ? 1.0 : -1.0) * -run->pressure / 6.0, *b;
                    long q;
                    if (ni < 0 || nj < 0) continue;
                    q = plateau__solve_block(sp, ni, nj);
                    if (q < 0) return -1;
                    b = hv + 9 * (size_t)q;
                    b[1] += f * c[2]; b[2] -= f * c[1];
                    b[3] -= f * c[2]; b[5] += f * c[0];
                    b[6] += f * c[1]; b[7] -= f * c[0];
                }
        }
    for (sg = 0; sg < run->cable_nseg; sg++) {
        plateau_index a = run->cable_seg[2 * sg], bb = run->cable_seg[2 * sg + 1];
        plateau_index na = node[a], nb = node[bb];
        double u[3], len, k[9];
        int r, c;
        plateau__util_sub(plateau__geo_pos(mesh, bb), plateau__geo_pos(mesh, a), u);
        len = plateau__util_norm(u);
        if (!(len > 0.0)) return -1;
        for (r = 0; r < 3; r++) u[r] /= len;
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++) k[3 * r + c] = run->cable_t[sg] * ((r == c) - u[r] * u[c]) / len;
        for (r = 0; r < 4; r++) { /* (a, a), (b, b), (a, b), (b, a) */
            plateau_index ni = r == 1 || r == 3 ? nb : na, nj = r == 1 || r == 2 ? nb : na;
            double sign = r < 2 ? 1.0 : -1.0, *b;
            long q;
            if (ni < 0 || nj < 0) continue;
            q = plateau__solve_block(sp, ni, nj);
            if (q < 0) return -1;
            b = hv + 9 * (size_t)q;
            for (c = 0; c < 9; c++) b[c] += sign * k[c];
        }
    }
    return 0;
}

/* Method area on the sparse path (many free vertices): a Levenberg-
 * Marquardt-type Newton method on the area.  The area's Hessian H is
 * indefinite away from the minimum and nearly singular at it in the
 * tangential directions (a planar mesh keeps its area under in-plane
 * motion of its interior vertices), so each step solves
 *   (H + mu L) h = -g,
 * L the cotangent Laplacian (plateau__solve_area_hessian), by the sparse
 * Cholesky of plateau_lm.h on the 1-ring pattern (analysed once per
 * round).  For large mu the step is a shortened Pinkall-Polthier step
 * (h = -L^-1 g / mu: L^-1 g is their step, the minimiser of the Dirichlet
 * energy that majorises the area), for small mu Newton's step.  L is the
 * metric of the damping as D^T D is in Madsen-Nielsen-Tingleff's (3.13),
 * with the gain ratio rho = (A(x) - A(x + h)) / (q(0) - q(h)), q(h) = g.h +
 * h.H h / 2 the quadratic model, and Nielsen's update (MNT (2.21)): a step
 * that lowers the area is accepted and mu *= max(1/10, 1 - (2 rho - 1)^3),
 * else mu *= nu, nu *= 2.  The floor is MNT's 1/3 lowered to 1/10: the
 * model is near exact here, and with 1/3 mu falls too slowly to where the
 * tangential motions start to pay.  A Cholesky failure (H + mu L not
 * positive definite), a step longer than the mean edge length or a rise
 * of the area also raise mu.  The cotangents enter L clipped at 0 (an
 * obtuse corner's negative weight would make L indefinite in rounding,
 * and the Cholesky would fail for every mu near a sliver), so L stays a
 * weighted graph Laplacian, positive definite with the boundary fixed.  mu starts at 1: H + L is between L and 2 L where the clipping is
 * idle, a step between half a Pinkall-Polthier step and a full one; the
 * solves of later rounds (after the flips, close to the minimum) start
 * from ten times the mu the last one ended with (*mu_io), at most 1.
 * Triangles: the area has a kink (|N| at N = 0) where a triangle turns
 * over, which the quadratic model does not see.  When a step would turn a
 * triangle against its old normal, the halving of the step finds the first
 * triangles that turn; their free vertices are held (their rows and
 * columns of H + mu L replaced by L's diagonal block, their gradient
 * zeroed) for the rest of this solve, and the step is solved again: the
 * rest converges while the flips after the solve mend the triangle
 * (shortening the step instead creeps).
 * Stops (report.area_stop): GRADIENT at max |g| <= PLATEAU__AREA_GTOL lbar
 * over the vertices not held (as the L-BFGS); SMALL_CHANGE when the last
 * PLATEAU__NEWTON_WINDOW accepted steps lowered the area by less than
 * options.area_tolerance of it (default 1e-6, 1/30 of the rounds'
 * PLATEAU__DRV_ROUND_DROP: a tighter bound buys mostly tangential creep
 * toward slivers); LINE_SEARCH when mu exceeds PLATEAU__NEWTON_MU_MAX or
 * a triangle is degenerate (no model); MAX_ITERATIONS when the accepted
 * steps reach max_iterations or the tries 4 max_iterations.
 * Reuse of the factorisation: after a Newton step with rho above
 * PLATEAU__NEWTON_CHORD_RHO the next step is a chord step, the new
 * gradient with the same factor (and the same H in q): a solve instead of
 * a factorisation; when it is refused the step is solved again with a new
 * factor, mu kept.  One chord step per factorisation.  The measurements
 * behind the floor, the tolerance and the chord steps: examples/NOTES.md,
 * "Measurements behind the solver's choices".
 * iterations counts accepted steps, evaluations the area evaluations. */
#define PLATEAU__NEWTON_MU_MAX 1e12  /* LINE_SEARCH above this damping */
#define PLATEAU__NEWTON_MU_FALL 0.1  /* the floor of Nielsen's factor */
#define PLATEAU__NEWTON_NU0 2.0      /* Nielsen's nu after an accepted step */
#define PLATEAU__NEWTON_WINDOW 5     /* SMALL_CHANGE: accepted steps compared */
#define PLATEAU__NEWTON_CHORD_RHO 0.5 /* a chord step follows a gain ratio above this */
#define PLATEAU__NEWTON_MU_NEXT 10.0 /* the next round starts from this times mu */

/* One solve of the Newton method: the 1-ring pattern and its Cholesky
 * factor, the blocks of H, L and H + mu L, and the vectors of the step. */
typedef struct plateau__solve_newton_state {
    plateau_mesh *mesh;
    const plateau__cfg *cfg;   /* the objective (plateau__solve_energy) ... */
    const plateau__cfg_run *run; /* ... in the run's frame */
    size_t nfree, n;           /* free vertices, unknowns (3 per vertex) */
    plateau__solve_sparse sp;  /* the pattern (its memory: pmem, with xy) */
    void *pmem;
    double *xy;
    plateau_lm_sparse_symbolic *sym;
    plateau_lm_sparse_factor *fac;
    plateau_index *node;       /* vertex -> free index, -1 if fixed */
    unsigned char *frozen;     /* free vertices held for the rest of the solve */
    double *hv, *lv, *mv;      /* 9 per block: H, L, H + mu L */
    double *x, *g, *h, *hh;    /* n: position, gradient, step, H h or trial point */
    double *full, *nrm;        /* 3 per vertex: the whole gradient; 3 per
                                  triangle: the normals at x */
} plateau__solve_newton_state;

static void plateau__solve_newton_free(plateau__solve_newton_state *st)
{
    const plateau_allocator *al = &st->mesh->allocator;
    plateau_lm_sparse_factor_free(st->fac);
    plateau_lm_sparse_symbolic_free(st->sym);
    plateau__free(al, st->pmem);
    plateau__free(al, st->node);
    plateau__free(al, st->hv);
    plateau__free(al, st->lv);
    plateau__free(al, st->mv);
    plateau__free(al, st->x);
    plateau__free(al, st->g);
    plateau__free(al, st->h);
    plateau__free(al, st->hh);
    plateau__free(al, st->full);
    plateau__free(al, st->nrm);
    plateau__free(al, st->frozen);
}

/* The pattern, the arrays and the analysis with its factor object. */
static plateau_result plateau__solve_newton_init(plateau_mesh *mesh, plateau__solve_newton_state *st,
                                                 plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, nt = mesh->num_triangles, v, i, nb;
    plateau_lm_result lrc;
    memset(st, 0, sizeof *st);
    st->mesh = mesh;
    for (v = 0; v < nv; v++) st->nfree += !mesh->fixed[v];
    st->n = 3 * st->nfree;
    st->pmem = plateau__solve_sparse_pattern(mesh, st->nfree, &st->sp, &st->xy);
    if (st->pmem) {
        nb = (size_t)st->sp.row_start[st->nfree];
        st->node = (plateau_index *)plateau__util_array(al, nv, sizeof(plateau_index));
        st->hv = (double *)plateau__util_array(al, nb, 9 * sizeof(double));
        st->lv = (double *)plateau__util_array(al, nb, 9 * sizeof(double));
        st->mv = (double *)plateau__util_array(al, nb, 9 * sizeof(double));
        st->x = (double *)plateau__util_array(al, st->n, sizeof(double));
        st->g = (double *)plateau__util_array(al, st->n, sizeof(double));
        st->h = (double *)plateau__util_array(al, st->n, sizeof(double));
        st->hh = (double *)plateau__util_array(al, st->n, sizeof(double));
        st->full = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
        st->nrm = (double *)plateau__util_array(al, nt, 3 * sizeof(double));
        st->frozen = (unsigned char *)plateau__util_array(al, st->nfree, 1);
    }
    if (!st->pmem || !st->node || !st->hv || !st->lv || !st->mv || !st->x || !st->g || !st->h ||
        !st->hh || !st->full || !st->nrm || !st->frozen) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in the area minimisation", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    memset(st->frozen, 0, st->nfree);
    for (v = 0, i = 0; v < nv; v++) st->node[v] = mesh->fixed[v] ? -1 : (plateau_index)i++;
    lrc = plateau__solve_cholesky_new(&st->sp, st->nfree, 3, st->xy, al, &st->sym, &st->fac);
    if (lrc != PLATEAU_LM_OK) return plateau__util_lm_error(lrc, "out of memory in the area minimisation", err);
    return PLATEAU_OK;
}

/* The area's gradient at the free vertices into st->g, zero at the held
 * ones; returns its largest component. */
static double plateau__solve_newton_gradient(plateau__solve_newton_state *st)
{
    const plateau_mesh *mesh = st->mesh;
    double gmax = 0.0;
    size_t v, i;
    plateau__solve_energy(mesh, st->cfg, st->run, st->full);
    for (v = 0, i = 0; v < mesh->num_vertices; v++)
        if (!mesh->fixed[v]) {
            st->g[i] = st->full[3 * v];
            st->g[i + 1] = st->full[3 * v + 1];
            st->g[i + 2] = st->full[3 * v + 2];
            i += 3;
        }
    for (i = 0; i < st->n; i++) {
        if (st->frozen[i / 3]) st->g[i] = 0.0;
        gmax = PLATEAU_FABS(st->g[i]) > gmax ? PLATEAU_FABS(st->g[i]) : gmax;
    }
    return gmax;
}

/* The step h = -(H + mu L)^-1 g, the held vertices' rows and columns
 * replaced by L's diagonal block; a chord step reuses the last factor. */
static plateau_lm_result plateau__solve_newton_direction(plateau__solve_newton_state *st, double mu,
                                                         int chord)
{
    plateau_lm_result lrc = PLATEAU_LM_OK;
    size_t i, q;
    if (!chord) {
        for (i = 0; i < st->nfree; i++)
            for (q = (size_t)st->sp.row_start[i]; q < (size_t)st->sp.row_start[i + 1]; q++) {
                size_t j = (size_t)st->sp.cols[q], r;
                int held = st->frozen[i] || st->frozen[j];
                for (r = 9 * q; r < 9 * q + 9; r++)
                    st->mv[r] = !held ? st->hv[r] + mu * st->lv[r] : i == j ? st->lv[r] : 0.0;
            }
        lrc = plateau_lm_sparse_factorize(st->fac, st->mv, 0.0);
    }
    if (lrc == PLATEAU_LM_OK) {
        for (i = 0; i < st->n; i++) st->h[i] = -st->g[i];
        lrc = plateau_lm_sparse_solve(st->fac, 1, st->h, st->n);
    }
    return lrc;
}

/* The model's terms: g.h, h.H h (H h by the blocks of H, into st->hh) and
 * the largest component of h. */
static void plateau__solve_newton_model(plateau__solve_newton_state *st, double *gh, double *hhh,
                                        double *hmax)
{
    double *hh = st->hh;
    const double *h = st->h;
    size_t i, q;
    for (i = 0; i < st->n; i++) hh[i] = 0.0;
    for (i = 0; i < st->nfree; i++)
        for (q = (size_t)st->sp.row_start[i]; q < (size_t)st->sp.row_start[i + 1]; q++) {
            const double *b = st->hv + 9 * q, *hc = h + 3 * (size_t)st->sp.cols[q];
            hh[3 * i] += b[0] * hc[0] + b[1] * hc[1] + b[2] * hc[2];
            hh[3 * i + 1] += b[3] * hc[0] + b[4] * hc[1] + b[5] * hc[2];
            hh[3 * i + 2] += b[6] * hc[0] + b[7] * hc[1] + b[8] * hc[2];
        }
    for (i = 0; i < st->n; i++) {
        *gh += st->g[i] * h[i];
        *hhh += h[i] * hh[i];
        *hmax = PLATEAU_FABS(h[i]) > *hmax ? PLATEAU_FABS(h[i]) : *hmax;
    }
}

/* Moves the free vertices to x + step h (kept in st->hh); 1 when a triangle
 * turns against its normal at x.  With hold, the free vertices of every
 * triangle that turns are held for the rest of the solve, their gradient
 * zeroed. */
static int plateau__solve_newton_turns(plateau__solve_newton_state *st, double step, int hold)
{
    plateau_mesh *mesh = st->mesh;
    size_t i, t;
    int turned = 0;
    for (i = 0; i < st->n; i++) st->hh[i] = st->x[i] + step * st->h[i];
    plateau__solve_scatter(mesh, st->hh);
    for (t = 0; t < mesh->num_triangles && (hold || !turned); t++) {
        double cn[3];
        int c;
        plateau__geo_tri_cross(mesh, t, cn);
        if (plateau__util_dot(cn, st->nrm + 3 * t) > 0.0) continue;
        turned = 1;
        for (c = 0; c < 3 && hold; c++) {
            plateau_index w = st->node[mesh->triangles[3 * t + (size_t)c]];
            if (w >= 0) {
                st->frozen[w] = 1;
                st->g[3 * (size_t)w] = st->g[3 * (size_t)w + 1] = st->g[3 * (size_t)w + 2] = 0.0;
            }
        }
    }
    return turned;
}

/* Forgets what *order holds (its vertex array stays for reuse). */
static void plateau__solve_order_clear(plateau__solve_order *order)
{
    plateau_lm_sparse_symbolic_free(order->sym);
    if (order->pattern) plateau__free(&order->pattern_alloc, order->pattern);
    order->sym = NULL;
    order->pattern = NULL;
    order->row_start = order->cols = NULL;
    order->nfree = order->count = 0;
}

/* The solve's elimination order by vertex into *order (a copy of the
 * analysis' permutation of the free vertices); 0 when out of memory (the
 * order then empty). */
static int plateau__solve_newton_keep(const plateau__solve_newton_state *st, plateau__solve_order *order)
{
    const plateau_index *perm = plateau_lm_sparse_permutation(st->sym);
    size_t v, k;
    plateau__solve_order_clear(order);
    if (!perm) return 1;
    if (order->capacity < st->nfree) { /* nfree values, then nfree of scratch */
        plateau__free(&order->alloc, order->vertex);
        order->capacity = 0;
        order->vertex = (plateau_index *)plateau__util_array(&order->alloc, st->nfree, 2 * sizeof(plateau_index));
        if (!order->vertex) return 0;
        order->capacity = st->nfree;
    }
    for (v = 0; v < st->mesh->num_vertices; v++) /* free index -> vertex */
        if (st->node[v] >= 0) order->vertex[order->capacity + (size_t)st->node[v]] = (plateau_index)v;
    for (k = 0; k < st->nfree; k++) order->vertex[k] = order->vertex[order->capacity + (size_t)perm[k]];
    order->count = st->nfree;
    return 1;
}

static plateau_result plateau__solve_newton(plateau_mesh *mesh, const plateau__cfg *cfg,
                                            const plateau__cfg_run *run, int round, double *mu_io,
                                            plateau_report *rep, double *f0, double *f1,
                                            plateau_error *err)
{
    plateau__solve_newton_state s;
    plateau_lm_result lrc;
    double f, lbar, gtol, fscale, mu = *mu_io, nu = PLATEAU__NEWTON_NU0, hist_f[PLATEAU__NEWTON_WINDOW];
    plateau_area_stop stop = PLATEAU_AREA_STOP_MAX_ITERATIONS;
    int max_iter = cfg->max_iterations, k = 0, tries, assembled = 0, chord = 0;
    plateau_result rc = plateau__solve_newton_init(mesh, &s, err);
    s.cfg = cfg;
    s.run = run;
    if (rc != PLATEAU_OK) {
        plateau__solve_newton_free(&s);
        return rc;
    }
    lbar = plateau_mean_edge_length(mesh);
    gtol = PLATEAU__AREA_GTOL * lbar;
    plateau__solve_gather(mesh, s.x);
    fscale = plateau_mesh_area(mesh); /* a membrane's SMALL_CHANGE scale (its
                                         energy may be negative) */
    f = plateau__solve_energy(mesh, cfg, run, NULL);
    rep->evaluations++;
    *f0 = f;
    for (tries = 0; tries < 4 * max_iter && k < max_iter; tries++) {
        double hmax = 0.0, pred = 0.0, gh = 0.0, hhh = 0.0, step = 1.0, ft, rho;
        int ok = 1;
        if (!assembled) {
            size_t t;
            if (plateau__solve_newton_gradient(&s) <= gtol) { stop = PLATEAU_AREA_STOP_GRADIENT; break; }
            if (!chord && (plateau__solve_area_hessian(mesh, s.node, s.nfree, &s.sp, s.hv, s.lv) != 0 ||
                           (cfg->membrane && plateau__solve_membrane_hessian(mesh, run, s.node, &s.sp, s.hv) != 0))) {
                stop = PLATEAU_AREA_STOP_LINE_SEARCH; /* a degenerate triangle: no model */
                break;
            }
            for (t = 0; t < mesh->num_triangles; t++) plateau__geo_tri_cross(mesh, t, s.nrm + 3 * t);
            assembled = 1;
        }
        lrc = plateau__solve_newton_direction(&s, mu, chord);
        if (lrc != PLATEAU_LM_OK && lrc != PLATEAU_LM_ERR_NOT_POSITIVE_DEFINITE &&
            lrc != PLATEAU_LM_ERR_NOT_FINITE_MATRIX) {
            rc = plateau__util_lm_error(lrc, NULL, err); /* factorize and solve allocate nothing */
            break;
        }
        if (lrc == PLATEAU_LM_OK) {
            /* q(0) - q(h) = -g.h - h.H h / 2 */
            plateau__solve_newton_model(&s, &gh, &hhh, &hmax);
            if (!(-gh - 0.5 * hhh > 0.0) || !(hmax <= lbar)) ok = 0;
        } else {
            ok = 0;
        }
        ft = f;
        if (ok) {
            /* halvings until no triangle turns against its old normal */
            int halvings;
            ok = 0;
            for (halvings = 0; halvings < PLATEAU__LBFGS_TRIES && !ok; halvings++) {
                if (halvings > 0) step *= 0.5;
                ok = !plateau__solve_newton_turns(&s, step, 0);
            }
            if (ok && step < 1.0) {
                /* the triangles that turn at 2 step: their free vertices
                 * are held for the rest of this solve, and the step is
                 * solved again without them */
                plateau__solve_newton_turns(&s, 2.0 * step, 1);
                plateau__solve_scatter(mesh, s.x);
                if (chord) chord = assembled = 0; /* a new matrix at x */
                continue;
            }
            if (ok) {
                ft = plateau__solve_energy(mesh, cfg, run, NULL);
                rep->evaluations++;
                pred = -step * gh - 0.5 * step * step * hhh;
                if (!(ft < f)) ok = 0;
            }
        }
        if (!ok) {
            if (lrc == PLATEAU_LM_OK) plateau__solve_scatter(mesh, s.x);
            if (chord) { /* the old factor failed: a new one at x, mu kept */
                chord = assembled = 0;
                continue;
            }
            mu *= nu;
            nu *= 2.0;
            if (!(mu <= PLATEAU__NEWTON_MU_MAX)) { stop = PLATEAU_AREA_STOP_LINE_SEARCH; break; }
            continue;
        }
        rho = (f - ft) / pred;
        if (!chord) { /* Nielsen's update (a full step: step < 1 held vertices above) */
            double c3 = 2.0 * rho - 1.0;
            c3 = 1.0 - c3 * c3 * c3;
            mu *= c3 > PLATEAU__NEWTON_MU_FALL ? c3 : PLATEAU__NEWTON_MU_FALL;
            nu = PLATEAU__NEWTON_NU0;
        }
        chord = !chord && rho > PLATEAU__NEWTON_CHORD_RHO;
        memcpy(s.x, s.hh, s.n * sizeof(double));
        assembled = 0;
        k++;
        rep->iterations++;
        if (cfg->progress && cfg->progress(round, k, ft * run->unit * run->unit, cfg->progress_user)) {
            f = ft;
            rc = PLATEAU_ERR_ABORTED;
            plateau__util_error(err, rc, -1, "the progress callback asked to stop", 0, 0);
            break;
        }
        f = ft;
        if (plateau__util_time_up(run->budget)) {
            run->budget->interrupted = 1;
            break;
        }
        hist_f[k % PLATEAU__NEWTON_WINDOW] = f;
        if (k > PLATEAU__NEWTON_WINDOW &&
            hist_f[(k + 1) % PLATEAU__NEWTON_WINDOW] - f <= cfg->area_tolerance * (cfg->membrane ? fscale : f)) {
            stop = PLATEAU_AREA_STOP_SMALL_CHANGE;
            break;
        }
    }
    rep->area_stop = stop;
    *f1 = f;
    /* the next round (after flips) starts from PLATEAU__NEWTON_MU_NEXT times this mu */
    *mu_io = PLATEAU__NEWTON_MU_NEXT * mu < 1.0 ? PLATEAU__NEWTON_MU_NEXT * mu : 1.0;
    if (run->order && rc == PLATEAU_OK && !plateau__solve_newton_keep(&s, run->order)) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in the area minimisation", 0, 0);
    }
    plateau__solve_newton_free(&s);
    return rc;
}

/* Pinkall-Polthier warm start for method area (Pinkall and Polthier,
 * "Computing discrete minimal surfaces and their conjugates", 1993): one
 * step of their iteration, the discrete harmonic map with the current
 * cotangent weights w_ij = (cot alpha_ij + cot beta_ij) / 2: for every free
 * vertex sum_j w_ij (x_i - x_j) = 0, boundary fixed.  Solved for the three
 * coordinates at once by the sparse Cholesky of plateau_lm.h (one
 * analysis, one factorisation, three right-hand sides; cheaper than
 * conjugate gradients, examples/NOTES.md).  Kept only when the
 * Laplacian was positive definite, the area went down and no triangle
 * turned against its old normal; else the positions are restored and
 * *used = 0. */
static plateau_result plateau__solve_warm_start(plateau_mesh *mesh, int *used, plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, ne = mesh->num_edges, nt = mesh->num_triangles;
    size_t n = 0, e, i, t;
    plateau_index *col = NULL;
    double *w = NULL, *x = NULL, *vals = NULL, *old = NULL, *nrm = NULL, *xy = NULL;
    void *pmem = NULL;
    plateau__solve_sparse sp;
    plateau_lm_sparse_symbolic *sym = NULL;
    plateau_lm_sparse_factor *fac = NULL;
    plateau_lm_result lrc;
    double area0, area1;
    plateau_result rc = PLATEAU_OK;
    int c, ok = 1;
    *used = 0;
    memset(&sp, 0, sizeof sp);
    col = (plateau_index *)plateau__util_array(al, nv, sizeof(plateau_index));
    if (!col) goto oom;
    for (i = 0; i < nv; i++) col[i] = mesh->fixed[i] ? -1 : (plateau_index)n++;
    if (n == 0) goto done;
    w = (double *)plateau__util_array(al, ne, sizeof(double));
    old = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
    nrm = (double *)plateau__util_array(al, nt, 3 * sizeof(double));
    x = (double *)plateau__util_array(al, n, 3 * sizeof(double));
    pmem = plateau__solve_sparse_pattern(mesh, n, &sp, &xy);
    vals = pmem ? (double *)plateau__util_array(al, (size_t)sp.row_start[n], sizeof(double)) : NULL;
    if (!w || !old || !nrm || !x || !pmem || !vals) goto oom;
    for (e = 0; e < ne; e++) {
        int s2;
        w[e] = 0.0;
        for (s2 = 0; s2 < 2; s2++) {
            plateau_index tr = mesh->edge_triangles[2 * e + (size_t)s2];
            plateau_index a = mesh->edges[2 * e], b = mesh->edges[2 * e + 1], o;
            double u[3], v2[3], cr[3], len;
            if (tr < 0) continue;
            o = plateau__geo_opposite(mesh, tr, a, b);
            plateau__util_sub(plateau__geo_pos(mesh, a), plateau__geo_pos(mesh, o), u);
            plateau__util_sub(plateau__geo_pos(mesh, b), plateau__geo_pos(mesh, o), v2);
            plateau__util_cross(u, v2, cr);
            len = plateau__util_norm(cr);
            if (!(len > 0.0)) { ok = 0; continue; }
            w[e] += 0.5 * plateau__util_dot(u, v2) / len;
        }
    }
    memcpy(old, mesh->positions, 3 * nv * sizeof(double));
    for (t = 0; t < nt; t++) plateau__geo_tri_cross(mesh, t, nrm + 3 * t);
    area0 = plateau_mesh_area(mesh);
    plateau__solve_laplacian_rows(mesh, &sp, w, n, vals, x);
    if (ok) {
        lrc = plateau__solve_cholesky_new(&sp, n, 1, xy, al, &sym, &fac);
        if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_factorize(fac, vals, 0.0);
        if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_solve(fac, 3, x, n);
        if (lrc == PLATEAU_LM_ERR_OUT_OF_MEMORY) goto oom;
        /* not positive definite (cotangent weights of obtuse pairs): no start */
        if (lrc != PLATEAU_LM_OK) ok = 0;
        for (i = 0; i < 3 * n && ok; i++)
            if (!plateau__util_finite(x[i])) ok = 0;
    }
    if (ok) {
        for (i = 0; i < nv; i++)
            if (col[i] >= 0)
                for (c = 0; c < 3; c++) mesh->positions[3 * i + (size_t)c] = x[(size_t)c * n + (size_t)col[i]];
        area1 = plateau_mesh_area(mesh);
        if (!(area1 < area0)) ok = 0;
        for (t = 0; t < nt && ok; t++) {
            double cn[3];
            plateau__geo_tri_cross(mesh, t, cn);
            if (!(plateau__util_dot(cn, nrm + 3 * t) > 0.0)) ok = 0;
        }
    }
    if (ok) *used = 1;
    else memcpy(mesh->positions, old, 3 * nv * sizeof(double));
    goto done;
oom:
    rc = PLATEAU_ERR_OUT_OF_MEMORY;
    plateau__util_error(err, rc, -1, "out of memory in the Pinkall-Polthier warm start", 0, 0);
done:
    plateau_lm_sparse_factor_free(fac);
    plateau_lm_sparse_symbolic_free(sym);
    plateau__free(al, pmem);
    plateau__free(al, vals);
    plateau__free(al, col);
    plateau__free(al, w);
    plateau__free(al, old);
    plateau__free(al, nrm);
    plateau__free(al, x);
    return rc;
}

/* ---- the step as plateau_solve runs it ---- */

/* Marks the free cable vertices fixed (hold 1) or free again (hold 0):
 * for the warm start, and for method paper, whose rows are the film's
 * H_i = p only (its area presolve places the cables). */
static void plateau__solve_hold_cables(plateau_mesh *mesh, const plateau__cfg_run *run, int hold)
{
    size_t i;
    for (i = 0; i < run->cable_nv; i++) mesh->fixed[run->cable_vtx[i]] = (unsigned char)(hold != 0);
}

/* Step 5 of one round: the method's solve (method area: the sparse Newton
 * method or the L-BFGS; else LM), its objective before and after into *f0
 * and *f1 (without free vertices: the area, or 0). */
static plateau_result plateau__solve_step(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          const plateau__cfg_run *run, int round, int newton,
                                          double *newton_mu, unsigned char *rows, size_t nfree,
                                          plateau_report *rep, double *f0, double *f1,
                                          plateau_error *err)
{
    if (nfree == 0) {
        *f0 = *f1 = cfg->method == PLATEAU_METHOD_AREA ? plateau_mesh_area(mesh) : 0.0;
        return PLATEAU_OK;
    }
    if (newton) return plateau__solve_newton(mesh, cfg, run, round, newton_mu, rep, f0, f1, err);
    if (cfg->method == PLATEAU_METHOD_AREA)
        return plateau__solve_lbfgs(mesh, cfg, run, round, rep, f0, f1, err);
    return plateau__solve_lm(mesh, cfg, run, round, rows, rep, f0, f1, err);
}

/* The Pinkall-Polthier start before the rounds of method area, automatic
 * above the threshold, where the seeded start lies many edge lengths off
 * the surface and the Newton steps, bounded by one mean edge length, are
 * slow to cross that. */
static plateau_result plateau__solve_warm_step(plateau_mesh *mesh, const plateau__cfg *cfg,
                                               const plateau__cfg_run *run, size_t nfree,
                                               plateau_report *rep, plateau_error *err)
{
    plateau_result rc;
    int used = 0;
    if (!PLATEAU__HAVE_SPARSE || cfg->method != PLATEAU_METHOD_AREA || nfree == 0 || plateau__util_time_up(run->budget) ||
        !(cfg->warm_start == PLATEAU_ON || (cfg->warm_start == PLATEAU_AUTO && nfree > PLATEAU_SPARSE_THRESHOLD)))
        return PLATEAU_OK;
    plateau__solve_hold_cables(mesh, run, 1); /* the harmonic map moves the film only */
    rc = plateau__solve_warm_start(mesh, &used, err);
    plateau__solve_hold_cables(mesh, run, 0);
    if (rc == PLATEAU_OK) rep->warm_started = used;
    return rc;
}
/* ======== END SECTION: step 5: solve ====================================== */

/* ======== SECTION: step 6: re-triangulation (plateau__retri_) ============= */
/* Between solves: 3-D Delaunay (or area) edge flips, removal of degenerate
 * free vertices, and paper-literal's re-projection. */
/* ---- step 6: 3-D Delaunay edge flips ---- */
/* (b - a) x (c - a) for mesh vertices a, b, c. */
static void plateau__retri_tri_cross(const plateau_mesh *mesh, plateau_index a, plateau_index b,
                                   plateau_index c, double *n)
{
    plateau__util_corner_cross(plateau__geo_pos(mesh, a), plateau__geo_pos(mesh, b),
                              plateau__geo_pos(mesh, c), n);
}

/* 1 if some triangle around vertex c (walking the neighbours from t0 both
 * ways) holds vertex d. */
static int plateau__retri_joined(const plateau_mesh *mesh, plateau_index t0, plateau_index c,
                               plateau_index d)
{
    int dir;
    for (dir = 0; dir < 2; dir++) {
        plateau_index t = t0;
        size_t steps;
        for (steps = 0; steps <= mesh->num_triangles; steps++) {
            const plateau_index *tr = mesh->triangles + 3 * (size_t)t;
            int k = tr[0] == c ? 0 : (tr[1] == c ? 1 : 2);
            if (tr[0] == d || tr[1] == d || tr[2] == d) return 1;
            /* dir 0 crosses edge (c, next), dir 1 edge (previous, c) */
            t = mesh->neighbors[3 * (size_t)t + (size_t)(dir == 0 ? k : (k + 2) % 3)];
            if (t < 0 || t == t0) break;
        }
    }
    return 0;
}

static void plateau__retri_set_nb(plateau_mesh *mesh, plateau_index t, plateau_index from,
                                plateau_index to)
{
    int k;
    if (t < 0) return;
    for (k = 0; k < 3; k++)
        if (mesh->neighbors[3 * (size_t)t + (size_t)k] == from)
            mesh->neighbors[3 * (size_t)t + (size_t)k] = to;
}

/* The area of a triangle with side lengths p, q, r, times 4 (Heron in
 * Kahan's form, "Miscalculating area and angles of a needle-like
 * triangle": sides sorted, no cancellation beyond the inputs' rounding). */
static double plateau__retri_heron4(double p, double q, double r)
{
    double t, s;
    if (p < q) { t = p; p = q; q = t; }
    if (q < r) { t = q; q = r; r = t; }
    if (p < q) { t = p; p = q; q = t; }
    s = (p + (q + r)) * (r - (p - q)) * (r + (p - q)) * (p + (q - r));
    return s > 0.0 ? PLATEAU_SQRT(s) : 0.0;
}

/* The angle opposite side r in a triangle with sides p, q, r (law of
 * cosines as atan2(4 area, p^2 + q^2 - r^2): accurate near 0 and pi). */
static double plateau__retri_len_angle(double p, double q, double r)
{
    return PLATEAU_ATAN2(plateau__retri_heron4(p, q, r), (p - r) * (p + r) + q * q);
}

static double plateau__retri_tri_area(const plateau_mesh *mesh, plateau_index a, plateau_index b,
                                    plateau_index c)
{
    double n[3];
    plateau__retri_tri_cross(mesh, a, b, c, n);
    return 0.5 * plateau__util_norm(n);
}

/* The smallest corner angle of the triangles (p, q, r) and (s, r, q). */
static double plateau__retri_pair_min_angle(const plateau_mesh *mesh, plateau_index p, plateau_index q,
                                          plateau_index r, plateau_index s)
{
    plateau_index tri[6];
    double m = 4.0;
    int i, k;
    tri[0] = p; tri[1] = q; tri[2] = r; tri[3] = s; tri[4] = r; tri[5] = q;
    for (i = 0; i < 2; i++)
        for (k = 0; k < 3; k++) {
            double g = plateau__util_corner_angle(plateau__geo_pos(mesh, tri[3 * i + k]), plateau__geo_pos(mesh, tri[3 * i + (k + 1) % 3]),
                                          plateau__geo_pos(mesh, tri[3 * i + (k + 2) % 3]));
            if (g < m) m = g;
        }
    return m;
}

/* Rewires the hinge of triangles t = (a, b, c) (edge k from a) and
 * u = (b, a, d) (edge j from b): t becomes (a, d, c), u becomes (b, c, d). */
static void plateau__retri_flip_edge(plateau_mesh *mesh, size_t t, int k, plateau_index u, int j)
{
    plateau_index *tt = mesh->triangles + 3 * t, *tu = mesh->triangles + 3 * (size_t)u;
    plateau_index a = tt[k], b = tt[(k + 1) % 3], c = tt[(k + 2) % 3], d = tu[(j + 2) % 3];
    plateau_index n_bc = mesh->neighbors[3 * t + (size_t)((k + 1) % 3)];
    plateau_index n_ca = mesh->neighbors[3 * t + (size_t)((k + 2) % 3)];
    plateau_index n_ad = mesh->neighbors[3 * (size_t)u + (size_t)((j + 1) % 3)];
    plateau_index n_db = mesh->neighbors[3 * (size_t)u + (size_t)((j + 2) % 3)];
    tt[0] = a; tt[1] = d; tt[2] = c;
    mesh->neighbors[3 * t] = n_ad;
    mesh->neighbors[3 * t + 1] = u;
    mesh->neighbors[3 * t + 2] = n_ca;
    tu[0] = b; tu[1] = c; tu[2] = d;
    mesh->neighbors[3 * (size_t)u] = n_bc;
    mesh->neighbors[3 * (size_t)u + 1] = (plateau_index)t;
    mesh->neighbors[3 * (size_t)u + 2] = n_db;
    plateau__retri_set_nb(mesh, n_ad, u, (plateau_index)t);
    plateau__retri_set_nb(mesh, n_bc, (plateau_index)t, u);
}

/* The triangles around vertex v, walking the neighbours from t0 (which
 * holds v) both ways; their count, or 0 when more than max. */
#define PLATEAU__RETRI_STAR_MAX 64

static size_t plateau__retri_star(const plateau_mesh *mesh, plateau_index t0, plateau_index v,
                                plateau_index *out)
{
    size_t n = 0;
    int dir;
    out[n++] = t0;
    for (dir = 0; dir < 2; dir++) {
        plateau_index t = t0;
        size_t steps;
        for (steps = 0; steps <= mesh->num_triangles; steps++) {
            const plateau_index *tr = mesh->triangles + 3 * (size_t)t;
            int k = tr[0] == v ? 0 : (tr[1] == v ? 1 : 2);
            t = mesh->neighbors[3 * (size_t)t + (size_t)(dir == 0 ? k : (k + 2) % 3)];
            if (t < 0) break;
            if (t == t0) return n; /* closed around v: one walk saw it all */
            if (n == PLATEAU__RETRI_STAR_MAX) return 0;
            out[n++] = t;
        }
    }
    return n;
}

/* Area of the triangles list[0..n), and the gradient of that area with
 * respect to vertex v (paper II.C.1: (1/2) n x e_opposite per triangle)
 * and h, the area's second derivative along the normal of a flat star
 * (sum |e_opposite|^2 / (4 area)), the step scale of the relaxation. */
static double plateau__retri_star_area(const plateau_mesh *mesh, const plateau_index *list, size_t n,
                                     plateau_index v, double *g, double *h)
{
    double area = 0.0;
    size_t i;
    if (g) { g[0] = g[1] = g[2] = 0.0; *h = 0.0; }
    for (i = 0; i < n; i++) {
        const plateau_index *tr = mesh->triangles + 3 * (size_t)list[i];
        int k = tr[0] == v ? 0 : (tr[1] == v ? 1 : 2);
        const double *x = plateau__geo_pos(mesh, v);
        const double *p = plateau__geo_pos(mesh, tr[(k + 1) % 3]), *q = plateau__geo_pos(mesh, tr[(k + 2) % 3]);
        double e1[3], e2[3], nn[3], eo[3], gn[3], len;
        plateau__util_sub(p, x, e1);
        plateau__util_sub(q, x, e2);
        plateau__util_cross(e1, e2, nn);
        len = plateau__util_norm(nn);
        area += 0.5 * len;
        if (g && len > 0.0) {
            plateau__util_sub(q, p, eo);
            nn[0] /= len; nn[1] /= len; nn[2] /= len;
            plateau__util_cross(nn, eo, gn);
            g[0] += 0.5 * gn[0]; g[1] += 0.5 * gn[1]; g[2] += 0.5 * gn[2];
            *h += plateau__util_dot(eo, eo) / (2.0 * len);
        }
    }
    return area;
}

/* The relaxation of a vertex: at most PLATEAU__RETRI_RELAX_STEPS steps of
 * at most PLATEAU__RETRI_RELAX_HALVINGS halvings each, until a step lowers
 * the star's area by no more than PLATEAU__RETRI_RELAX_STALL of it. */
#define PLATEAU__RETRI_RELAX_STEPS 20
#define PLATEAU__RETRI_RELAX_HALVINGS 30
#define PLATEAU__RETRI_RELAX_STALL 1e-14

/* Lowers the area of the star of the free vertex v (triangles list[0..n))
 * by moving v: steps -g/h, halved until the area drops (Armijo) and no
 * triangle of the star turns over or collapses. */
static void plateau__retri_relax_vertex(plateau_mesh *mesh, const plateau_index *list, size_t n,
                                      plateau_index v)
{
    double *x = mesh->positions + 3 * (size_t)v;
    int it;
    for (it = 0; it < PLATEAU__RETRI_RELAX_STEPS; it++) {
        double g[3], h, x0[3], area, step = 1.0, gg, ref[PLATEAU__RETRI_STAR_MAX][3];
        int bt, done = 0;
        size_t i;
        area = plateau__retri_star_area(mesh, list, n, v, g, &h);
        gg = plateau__util_dot(g, g);
        if (!(h > 0.0) || !(gg > 0.0)) return;
        for (i = 0; i < n; i++) {
            const plateau_index *tr = mesh->triangles + 3 * (size_t)list[i];
            plateau__retri_tri_cross(mesh, tr[0], tr[1], tr[2], ref[i]);
        }
        x0[0] = x[0]; x0[1] = x[1]; x0[2] = x[2];
        for (bt = 0; bt < PLATEAU__RETRI_RELAX_HALVINGS && !done; bt++, step *= 0.5) {
            int ok = 1;
            x[0] = x0[0] - step * g[0] / h;
            x[1] = x0[1] - step * g[1] / h;
            x[2] = x0[2] - step * g[2] / h;
            for (i = 0; i < n && ok; i++) {
                const plateau_index *tr = mesh->triangles + 3 * (size_t)list[i];
                double nn[3];
                plateau__retri_tri_cross(mesh, tr[0], tr[1], tr[2], nn);
                ok = plateau__util_dot(nn, ref[i]) > 0.0;
            }
            if (ok && plateau__retri_star_area(mesh, list, n, v, NULL, NULL) <
                          area - PLATEAU__LBFGS_ARMIJO * step * gg / h)
                done = 1;
        }
        if (!done) {
            x[0] = x0[0]; x[1] = x0[1]; x[2] = x0[2];
            return;
        }
        if (area - plateau__retri_star_area(mesh, list, n, v, NULL, NULL) <= PLATEAU__RETRI_RELAX_STALL * area)
            return;
    }
}

/* An area flip with relaxation: flips the edge of the hinge (t, k; u, j),
 * then moves its free vertices (a, b, c, d) to lower the area of their
 * stars, and keeps the result when the area of the triangles involved
 * dropped by more than drop, no triangle turned over and the new edge did
 * not exist; otherwise restores everything.  Returns 1 when kept.  A flip
 * that raises the area with the vertices where they are can lower it once
 * they move (a vertex that the old edges held in place). */
static int plateau__retri_relaxed_flip(plateau_mesh *mesh, size_t t, int k, plateau_index u, int j,
                                     double drop)
{
    plateau_index *tt = mesh->triangles + 3 * t, *tu = mesh->triangles + 3 * (size_t)u;
    plateau_index quad[4], set[4 * PLATEAU__RETRI_STAR_MAX + 2], star[PLATEAU__RETRI_STAR_MAX];
    plateau_index save_t[6], save_n[6], n_ad, n_bc;
    double save_x[12], ref[4 * PLATEAU__RETRI_STAR_MAX + 2][3], before, after, old_angle;
    size_t nset = 0, i, q, ns;
    int nfree = 0, pass, ok = 1;
    quad[0] = tt[k]; quad[1] = tt[(k + 1) % 3]; quad[2] = tt[(k + 2) % 3]; quad[3] = tu[(j + 2) % 3];
    if (quad[2] == quad[3] || plateau__retri_joined(mesh, (plateau_index)t, quad[2], quad[3])) return 0;
    set[nset++] = (plateau_index)t;
    set[nset++] = u;
    for (q = 0; q < 4; q++) {
        if (!mesh->fixed || mesh->fixed[quad[q]]) continue;
        nfree++;
        ns = plateau__retri_star(mesh, q == 3 ? u : (plateau_index)t, quad[q], star);
        if (ns == 0) return 0;
        for (i = 0; i < ns; i++) {
            size_t r;
            for (r = 0; r < nset && set[r] != star[i]; r++) {}
            if (r == nset) set[nset++] = star[i];
        }
    }
    if (nfree == 0) return 0;
    for (i = 0; i < nset; i++) {
        const plateau_index *tr = mesh->triangles + 3 * (size_t)set[i];
        plateau__retri_tri_cross(mesh, tr[0], tr[1], tr[2], ref[i]);
    }
    before = 0.0;
    for (i = 0; i < nset; i++) {
        const plateau_index *tr = mesh->triangles + 3 * (size_t)set[i];
        before += plateau__retri_tri_area(mesh, tr[0], tr[1], tr[2]);
    }
    for (q = 0; q < 3; q++) {
        save_t[q] = tt[q]; save_t[3 + q] = tu[q];
        save_n[q] = mesh->neighbors[3 * t + q]; save_n[3 + q] = mesh->neighbors[3 * (size_t)u + q];
    }
    for (q = 0; q < 4; q++) memcpy(save_x + 3 * q, plateau__geo_pos(mesh, quad[q]), 3 * sizeof(double));
    n_ad = mesh->neighbors[3 * (size_t)u + (size_t)((j + 1) % 3)];
    n_bc = mesh->neighbors[3 * t + (size_t)((k + 1) % 3)];
    old_angle = plateau__retri_pair_min_angle(mesh, quad[2], quad[0], quad[1], quad[3]);
    plateau__retri_flip_edge(mesh, t, k, u, j);
    /* t = (a, d, c) holds a, c, d; u = (b, c, d) holds b */
    for (pass = 0; pass < 3; pass++)
        for (q = 0; q < 4; q++) {
            if (mesh->fixed[quad[q]]) continue;
            ns = plateau__retri_star(mesh, q == 1 ? u : (plateau_index)t, quad[q], star);
            if (ns > 0) plateau__retri_relax_vertex(mesh, star, ns, quad[q]);
        }
    after = 0.0;
    for (i = 0; i < nset && ok; i++) {
        const plateau_index *tr = mesh->triangles + 3 * (size_t)set[i];
        double nn[3];
        plateau__retri_tri_cross(mesh, tr[0], tr[1], tr[2], nn);
        after += 0.5 * plateau__util_norm(nn);
        if (i < 2) /* the new pair faces as both old triangles did */
            ok = plateau__util_dot(nn, ref[0]) > 0.0 && plateau__util_dot(nn, ref[1]) > 0.0;
        else
            ok = plateau__util_dot(nn, ref[i]) > 0.0;
    }
    if (ok && after < before - drop) {
        /* as the plain flips: no new angle under 1 degree (the threshold
         * of the vertex removal) */
        double new_angle = plateau__retri_pair_min_angle(mesh, quad[0], quad[3], quad[2], quad[1]);
        if (!(new_angle < PLATEAU__ONE_DEGREE && new_angle < old_angle)) return 1;
    }
    for (q = 0; q < 3; q++) {
        tt[q] = save_t[q]; tu[q] = save_t[3 + q];
        mesh->neighbors[3 * t + q] = save_n[q]; mesh->neighbors[3 * (size_t)u + q] = save_n[3 + q];
    }
    plateau__retri_set_nb(mesh, n_ad, (plateau_index)t, u);
    plateau__retri_set_nb(mesh, n_bc, u, (plateau_index)t);
    for (q = 0; q < 4; q++) memcpy(mesh->positions + 3 * (size_t)quad[q], save_x + 3 * q, 3 * sizeof(double));
    return 0;
}

/* The flip rules of step 6.  Both flip an interior edge only when a measure
 * of the triangulation drops, so no triangulation comes back and the sweeps
 * end on their own.
 *   PLATEAU__RETRI_FLIP_INTRINSIC: Delaunay flips on the intrinsic metric of the
 *     mesh (the edge lengths when the flips start; a flipped edge gets the
 *     length of the diagonal of the two triangles unfolded into the plane;
 *     the vertices do not move).  This is Lawson's flip algorithm on a
 *     piecewise flat surface: each flip of an edge whose opposite angles
 *     sum to more than pi lowers the Dirichlet energy of every piecewise
 *     linear function on the vertices (Rippa 1990, whose proof is local to
 *     the two triangles), and the algorithm ends, in the unique intrinsic
 *     Delaunay triangulation (Indermitte, Liebling, Troyanov and Clemencon
 *     2001; Bobenko and Springborn 2007).  Measuring the angles on the 3-D
 *     triangles instead, after each flip, is no flip algorithm on a fixed
 *     metric (the new chord is shorter than the unfolded diagonal), and
 *     such flips cycled.
 *   PLATEAU__RETRI_FLIP_AREA, for method area, whose solves lower the area too:
 *     a flip that lowers the area of the two triangles by more than 1e-9 of
 *     it, or that does not raise it and is a Delaunay flip (angles at c
 *     and d summing to more than pi + 1e-6: quality where the area has no
 *     preference, as on a plane).  The margin is a tie-break: the area's
 *     solve fixes tangential positions only to a fraction of the size (a
 *     planar region's area does not change when its vertices slide), so a
 *     smaller margin would let rounding decide the cocircular hinges of a
 *     symmetric boundary, and a scaled or rotated copy would get other
 *     triangles.  No flip makes a triangle with an angle under 1 degree
 *     (the threshold of the vertex removal) unless the old pair had a
 *     smaller one.  So the area never rises (up to the rounding of two sums
 *     of two areas), and where it stays equal (a planar hinge) the flip is
 *     a Lawson flip.  When such sweeps find nothing, one sweep tries each
 *     edge with its free vertices moved (plateau__retri_relaxed_flip), kept
 *     only when the area drops by more than 1e-9 of the mesh's area (at
 *     most (A - A_min) / (1e-9 A) such flips), then plain sweeps again.
 *   PLATEAU__RETRI_FLIP_AREA_PLAIN, for method area above PLATEAU_SPARSE_THRESHOLD
 *     free vertices: the same flips without the sweep with relaxation, which
 *     pays on small meshes and costs more than it gains on large ones
 *     (examples/NOTES.md, "Measurements behind the solver's choices").
 * All skip a flip whose new triangles would be degenerate or face against
 * either old one in 3-D (a fold), or whose new edge exists already. */
#define PLATEAU__RETRI_FLIP_INTRINSIC 0
#define PLATEAU__RETRI_FLIP_AREA 1
#define PLATEAU__RETRI_FLIP_AREA_PLAIN 2
/* The margins of the rules above: an intrinsic flip needs the opposite
 * angles to sum to more than pi + PLATEAU__RETRI_TIE (radians; ties never
 * flip); an area flip must lower the area by more than
 * PLATEAU__RETRI_AREA_DROP of it, or keep it and sum to more than pi +
 * PLATEAU__RETRI_AREA_TIE.  At most PLATEAU__RETRI_SWEEPS sweeps when the
 * caller gives 0. */
#define PLATEAU__RETRI_TIE 1e-9
#define PLATEAU__RETRI_AREA_DROP 1e-9
#define PLATEAU__RETRI_AREA_TIE 1e-6
#define PLATEAU__RETRI_SWEEPS 50

static plateau_result plateau__retri_flip_sweeps(plateau_mesh *mesh, int rule, int max_sweeps,
                                               size_t *flips, plateau_error *err)
{
    const double pi = PLATEAU__PI;
    size_t count = 0, limit, t;
    double *len = NULL, drop = 0.0;
    int sweep, plain_done = 0;
    if (flips) *flips = 0;
    if (!mesh || !mesh->triangles || !mesh->neighbors || !mesh->positions || max_sweeps < 0) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_mesh_delaunay_flips needs a mesh", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (max_sweeps == 0) max_sweeps = PLATEAU__RETRI_SWEEPS;
    if (rule == PLATEAU__RETRI_FLIP_AREA) drop = PLATEAU__RETRI_AREA_DROP * plateau_mesh_area(mesh);
    if (rule == PLATEAU__RETRI_FLIP_AREA_PLAIN) plain_done = 2; /* never the relaxed sweep */
    if (rule == PLATEAU__RETRI_FLIP_INTRINSIC && mesh->num_triangles > 0) {
        /* len[3t + k]: the intrinsic length of edge (v_k, v_(k+1)%3) of t */
        len = (double *)plateau__util_array(&mesh->allocator, 3 * mesh->num_triangles, sizeof(double));
        if (!len) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in the flips", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        for (t = 0; t < 3 * mesh->num_triangles; t++) {
            double e[3];
            size_t t3 = t - t % 3;
            plateau__util_sub(plateau__geo_pos(mesh, mesh->triangles[t3 + (t % 3 + 1) % 3]),
                             plateau__geo_pos(mesh, mesh->triangles[t]), e);
            len[t] = plateau__util_norm(e);
        }
    }
    /* a safety bound only: each flip lowers the measure, so the sweeps end
     * by themselves long before (a sweep without a flip ends them) */
    limit = 10 * (mesh->num_edges + 1);
    for (sweep = 0; sweep < max_sweeps && count < limit; sweep++) {
        size_t before = count;
        /* rule area: sweeps of plain flips until none is left, then one
         * sweep (once per call: the next solve moves every vertex anyway)
         * that also tries the flips with relaxation, then plain sweeps */
        int relax = rule == PLATEAU__RETRI_FLIP_AREA && plain_done == 1;
        for (t = 0; t < mesh->num_triangles && count < limit; t++) {
            int k;
            for (k = 0; k < 3; k++) {
                plateau_index *tt = mesh->triangles + 3 * t, *tu;
                plateau_index u = mesh->neighbors[3 * t + (size_t)k];
                plateau_index a, b, c, d;
                double n1[3], n2[3], n3[3], n4[3];
                double l_ab = 0.0, l_bc = 0.0, l_ca = 0.0, l_ad = 0.0, l_db = 0.0, l_cd = 0.0;
                int j;
                if (u < 0 || (size_t)u < t) continue;
                a = tt[k]; b = tt[(k + 1) % 3]; c = tt[(k + 2) % 3];
                tu = mesh->triangles + 3 * (size_t)u;
                for (j = 0; j < 3; j++)
                    if (tu[j] == b && tu[(j + 1) % 3] == a) break;
                if (j == 3) continue; /* cannot happen on a consistent mesh */
                d = tu[(j + 2) % 3];
                if (rule == PLATEAU__RETRI_FLIP_INTRINSIC) {
                    double gc, gd;
                    l_ab = len[3 * t + (size_t)k];
                    l_bc = len[3 * t + (size_t)((k + 1) % 3)];
                    l_ca = len[3 * t + (size_t)((k + 2) % 3)];
                    l_ad = len[3 * (size_t)u + (size_t)((j + 1) % 3)];
                    l_db = len[3 * (size_t)u + (size_t)((j + 2) % 3)];
                    gc = plateau__retri_len_angle(l_bc, l_ca, l_ab);
                    gd = plateau__retri_len_angle(l_ad, l_db, l_ab);
                    if (!(gc + gd > pi + PLATEAU__RETRI_TIE)) continue;
                } else {
                    double old_area = plateau__retri_tri_area(mesh, a, b, c) + plateau__retri_tri_area(mesh, b, a, d);
                    double new_area = plateau__retri_tri_area(mesh, a, d, c) + plateau__retri_tri_area(mesh, b, c, d);
                    int drops = new_area < old_area * (1.0 - PLATEAU__RETRI_AREA_DROP);
                    if (!drops && new_area <= old_area)
                        drops = plateau__util_corner_angle(plateau__geo_pos(mesh, c), plateau__geo_pos(mesh, a),
                                                   plateau__geo_pos(mesh, b)) +
                                    plateau__util_corner_angle(plateau__geo_pos(mesh, d), plateau__geo_pos(mesh, a),
                                                       plateau__geo_pos(mesh, b)) >
                                pi + PLATEAU__RETRI_AREA_TIE;
                    /* no new triangle with an angle under 1 degree (the
                     * threshold of the vertex removal) unless the old pair
                     * had one */
                    if (drops) {
                        double new_min = plateau__retri_pair_min_angle(mesh, a, d, c, b);
                        if (new_min < PLATEAU__ONE_DEGREE &&
                            new_min < plateau__retri_pair_min_angle(mesh, c, a, b, d))
                            continue;
                    }
                    if (!drops) {
                        if (relax && plateau__retri_relaxed_flip(mesh, t, k, u, j, drop)) {
                            count++;
                            if (count >= limit) break;
                        }
                        continue;
                    }
                }
                plateau__retri_tri_cross(mesh, a, b, c, n1);
                plateau__retri_tri_cross(mesh, b, a, d, n2);
                plateau__retri_tri_cross(mesh, a, d, c, n3);
                plateau__retri_tri_cross(mesh, b, c, d, n4);
                if (!(plateau__util_dot(n3, n1) > 0.0) || !(plateau__util_dot(n3, n2) > 0.0) ||
                    !(plateau__util_dot(n4, n1) > 0.0) || !(plateau__util_dot(n4, n2) > 0.0))
                    continue;
                if (c == d || plateau__retri_joined(mesh, (plateau_index)t, c, d)) continue;
                if (rule == PLATEAU__RETRI_FLIP_INTRINSIC) {
                    /* the diagonal (c, d) of the hinge unfolded about (a, b):
                     * the angles at a of the two triangles add */
                    double ang = plateau__retri_len_angle(l_ab, l_ca, l_bc) + plateau__retri_len_angle(l_ab, l_ad, l_db);
                    double s = l_ca * l_ca + l_ad * l_ad - 2.0 * l_ca * l_ad * PLATEAU_COS(ang);
                    l_cd = s > 0.0 ? PLATEAU_SQRT(s) : 0.0;
                }
                plateau__retri_flip_edge(mesh, t, k, u, j);
                if (len) {
                    len[3 * t] = l_ad; len[3 * t + 1] = l_cd; len[3 * t + 2] = l_ca;
                    len[3 * (size_t)u] = l_bc; len[3 * (size_t)u + 1] = l_cd; len[3 * (size_t)u + 2] = l_db;
                }
                count++;
                if (count >= limit) break;
            }
        }
        if (count == before && (rule == PLATEAU__RETRI_FLIP_INTRINSIC || plain_done)) break;
        if (relax) plain_done = 2;
        else if (count == before) plain_done = 1;
    }
    plateau__free(&mesh->allocator, len);
    if (flips) *flips = count;
    if (count > 0) return plateau_mesh_build_adjacency(mesh, err);
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_mesh_delaunay_flips(plateau_mesh *mesh, int max_sweeps,
                                                       size_t *flips, plateau_error *err)
{
    return plateau__retri_flip_sweeps(mesh, PLATEAU__RETRI_FLIP_INTRINSIC, max_sweeps, flips, err);
}

/* ---- step 6: removal of a degenerate free vertex ----
 * A half-edge collapse (Hoppe, DeRose, Duchamp, McDonald and Stuetzle,
 * "Mesh optimization", SIGGRAPH 1993: the vertex v moves onto its
 * neighbour w, which stays; the two triangles of the edge (v, w) vanish)
 * under the link condition of Dey, Edelsbrunner, Guha and Nekhayev,
 * "Topology preserving edge contraction" (1999), which keeps a manifold
 * disk a manifold disk. */

/* 1 when triangle t is a sliver (a corner angle below tol radians) or is
 * inverted as plateau_mesh_quality counts it (zero area, or facing against
 * its neighbours). */
static int plateau__retri_degenerate(const plateau_mesh *mesh, size_t t, double tol)
{
    const plateau_index *tr = mesh->triangles + 3 * t;
    double n[3], s = 0.0;
    int q;
    for (q = 0; q < 3; q++)
        if (!(plateau__util_corner_angle(plateau__geo_pos(mesh, tr[q]), plateau__geo_pos(mesh, tr[(q + 1) % 3]),
                                 plateau__geo_pos(mesh, tr[(q + 2) % 3])) >= tol))
            return 1;
    if (!(plateau_triangle_normal(mesh, t, n) > 0.0)) return 1;
    for (q = 0; q < 3; q++) {
        plateau_index u = mesh->neighbors[3 * t + (size_t)q];
        double nu[3];
        if (u < 0) continue;
        plateau_triangle_normal(mesh, (size_t)u, nu);
        s += plateau__util_dot(n, nu);
    }
    return s < 0.0;
}

static plateau_index plateau__retri_other(const plateau_mesh *mesh, size_t e, plateau_index v)
{
    return mesh->edges[2 * e] == v ? mesh->edges[2 * e + 1] : mesh->edges[2 * e];
}

/* The neighbour w that the free vertex v collapses onto, or -1.  v must be
 * an interior vertex (each of its edges has two triangles).  A candidate w
 * passes the link condition (v and w have exactly two common neighbours,
 * the vertices opposite the edge (v, w)), and every triangle of v that
 * survives (v replaced by w) keeps a non-zero area facing the same side as
 * before (normals at less than 90 degrees: no fold; the vertex normal is
 * no reference where the star wraps around a twisted strip).  Among the
 * candidates: the largest
 * smallest corner angle of the surviving triangles, ties to the first in
 * v's edge order. */
static plateau_index plateau__retri_collapse_target(const plateau_mesh *mesh, plateau_index v)
{
    size_t e0 = mesh->vertex_edge_start[v], e1 = mesh->vertex_edge_start[v + 1];
    size_t t0 = mesh->vertex_triangle_start[v], t1 = mesh->vertex_triangle_start[v + 1];
    size_t i, j, k;
    plateau_index best = -1;
    double best_angle = -1.0;
    if (mesh->fixed[v] || e0 == e1) return -1;
    for (i = e0; i < e1; i++)
        if (mesh->edge_triangles[2 * (size_t)mesh->vertex_edges[i] + 1] < 0) return -1;
    for (i = e0; i < e1; i++) {
        plateau_index w = plateau__retri_other(mesh, (size_t)mesh->vertex_edges[i], v);
        size_t common = 0;
        double worst = 4.0;
        int ok = 1;
        for (j = e0; j < e1; j++) {
            plateau_index x = plateau__retri_other(mesh, (size_t)mesh->vertex_edges[j], v);
            if (x == w) continue;
            for (k = mesh->vertex_edge_start[w]; k < mesh->vertex_edge_start[w + 1]; k++)
                if (plateau__retri_other(mesh, (size_t)mesh->vertex_edges[k], w) == x) {
                    common++;
                    break;
                }
        }
        if (common != 2) continue;
        for (j = t0; j < t1 && ok; j++) {
            size_t t = (size_t)mesh->vertex_triangles[j];
            const plateau_index *tr = mesh->triangles + 3 * t;
            const double *p[3];
            double u[3], s[3], c[3], n0[3];
            int q;
            if (tr[0] == w || tr[1] == w || tr[2] == w) continue; /* vanishes */
            for (q = 0; q < 3; q++) p[q] = plateau__geo_pos(mesh, tr[q] == v ? w : tr[q]);
            plateau__util_sub(p[1], p[0], u);
            plateau__util_sub(p[2], p[0], s);
            plateau__util_cross(u, s, c);
            plateau__geo_tri_cross(mesh, t, n0);
            if (!(plateau__util_dot(c, n0) > 0.0)) { ok = 0; break; }
            for (q = 0; q < 3; q++) {
                double a = plateau__util_corner_angle(p[q], p[(q + 1) % 3], p[(q + 2) % 3]);
                if (a < worst) worst = a;
            }
        }
        if (ok && worst > best_angle) {
            best_angle = worst;
            best = w;
        }
    }
    return best;
}

/* Collapses v onto w and renumbers: the vertices after v and the triangles
 * after the two removed ones move down by one place, keeping their order. */
static void plateau__retri_collapse(plateau_mesh *mesh, plateau_index v, plateau_index w)
{
    size_t t, out = 0, nv = mesh->num_vertices;
    int k;
    for (t = 0; t < mesh->num_triangles; t++) {
        plateau_index tr[3];
        int hv = 0, hw = 0;
        for (k = 0; k < 3; k++) {
            tr[k] = mesh->triangles[3 * t + (size_t)k];
            hv |= tr[k] == v;
            hw |= tr[k] == w;
        }
        if (hv && hw) continue;
        for (k = 0; k < 3; k++) {
            plateau_index x = tr[k] == v ? w : tr[k];
            mesh->triangles[3 * out + (size_t)k] = x > v ? x - 1 : x;
        }
        out++;
    }
    mesh->num_triangles = out;
    memmove(mesh->positions + 3 * (size_t)v, mesh->positions + 3 * ((size_t)v + 1),
            3 * (nv - (size_t)v - 1) * sizeof(double));
    memmove(mesh->fixed + v, mesh->fixed + v + 1, nv - (size_t)v - 1);
    mesh->num_vertices = nv - 1;
}

/* A sliver's angle bound must be below 60 degrees: every triangle has an
 * angle of at least that. */
#define PLATEAU__RETRI_MAX_SLIVER_DEG 60.0

PLATEAU_DEF plateau_result plateau_mesh_remove_degenerate(plateau_mesh *mesh, double min_angle_deg,
                                                          size_t *removed, plateau_error *err)
{
    size_t count = 0, pass, limit;
    double tol;
    if (removed) *removed = 0;
    if (!mesh || !mesh->triangles || !mesh->neighbors || !mesh->positions || !mesh->fixed ||
        !mesh->vertex_edge_start || !(min_angle_deg >= 0.0) || !(min_angle_deg < PLATEAU__RETRI_MAX_SLIVER_DEG)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                               "plateau_mesh_remove_degenerate needs a mesh with adjacency and an angle in [0, 60)", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    tol = (min_angle_deg > 0.0 ? min_angle_deg : 1.0) * PLATEAU__ONE_DEGREE;
    limit = mesh->num_vertices;
    /* each pass removes one vertex or ends: at most num_vertices passes */
    for (pass = 0; pass < limit; pass++) {
        plateau_index v = -1, w = -1;
        size_t t;
        plateau_result rc;
        for (t = 0; t < mesh->num_triangles && w < 0; t++) {
            const plateau_index *tr = mesh->triangles + 3 * t;
            double ang[3];
            int order[3] = {0, 1, 2}, q, r;
            if (!plateau__retri_degenerate(mesh, t, tol)) continue;
            for (q = 0; q < 3; q++)
                ang[q] = plateau__util_corner_angle(plateau__geo_pos(mesh, tr[q]), plateau__geo_pos(mesh, tr[(q + 1) % 3]),
                                            plateau__geo_pos(mesh, tr[(q + 2) % 3]));
            /* corners by decreasing angle: the apex of a cap (a vertex on the
             * opposite edge) first, then the ends of a needle's short edge */
            for (q = 0; q < 2; q++)
                for (r = 0; r < 2 - q; r++)
                    if (ang[order[r + 1]] > ang[order[r]]) {
                        int tmp = order[r];
                        order[r] = order[r + 1];
                        order[r + 1] = tmp;
                    }
            for (r = 0; r < 3 && w < 0; r++) {
                v = tr[order[r]];
                w = plateau__retri_collapse_target(mesh, v);
            }
        }
        if (w < 0) break;
        plateau__retri_collapse(mesh, v, w);
        count++;
        if (removed) *removed = count;
        rc = plateau_mesh_build_adjacency(mesh, err);
        if (rc != PLATEAU_OK) return rc;
    }
    return PLATEAU_OK;
}

/* What plateau_solve knows about the domain, for paper-literal's re-projection. */
typedef struct plateau__retri_domain {
    const double *uv; /* 2 * m: the boundary in the domain; NULL: none */
    size_t m;
    plateau_domain_kind kind;
} plateau__retri_domain;

/* The ridge added to the normal equations of the re-projection's affine
 * map: this fraction of their trace (a flat boundary makes them singular). */
#define PLATEAU__RETRI_RIDGE 1e-12

/* paper-literal's re-triangulation (paper II.A, Fig. 1): map the vertices
 * back to the plane domain by the affine map that takes the boundary to its
 * domain polygon (least squares; exact for the best-fit-plane projection)
 * and run the constrained Delaunay triangulation again.  *used = 0 when it
 * is not usable (circle domain, a vertex outside the polygon, a duplicate or
 * an added point): the caller flips in 3-D instead.  *changed = 1 when the
 * triangles differ. */
static plateau_result plateau__retri_reproject(plateau_mesh *mesh, const plateau__retri_domain *dom,
                                             int *used, int *changed, plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, m = dom->m, i, t;
    double c[3] = {0.0, 0.0, 0.0}, cu[2] = {0.0, 0.0}, A[9], B[6], M[6], tr;
    double *uv = NULL;
    plateau_index *seg = NULL;
    plateau_dt_input in;
    plateau_dt_options dopt;
    plateau_dt_mesh dt;
    plateau_dt_result dres;
    plateau_result rc = PLATEAU_OK;
    int r, k;
    *used = 0;
    *changed = 0;
    if (!dom->uv || dom->kind != PLATEAU_DOMAIN_PLANE || m < 3 || m > nv) return PLATEAU_OK;
    for (i = 0; i < m; i++) {
        for (k = 0; k < 3; k++) c[k] += mesh->positions[3 * i + (size_t)k] / (double)m;
        cu[0] += dom->uv[2 * i] / (double)m;
        cu[1] += dom->uv[2 * i + 1] / (double)m;
    }
    /* normal equations (P^T P + ridge) M^T = P^T U, P the centred boundary */
    for (k = 0; k < 9; k++) A[k] = 0.0;
    for (k = 0; k < 6; k++) B[k] = 0.0;
    for (i = 0; i < m; i++) {
        double p[3], u[2];
        for (k = 0; k < 3; k++) p[k] = mesh->positions[3 * i + (size_t)k] - c[k];
        u[0] = dom->uv[2 * i] - cu[0];
        u[1] = dom->uv[2 * i + 1] - cu[1];
        for (r = 0; r < 3; r++) {
            for (k = 0; k < 3; k++) A[3 * r + k] += p[r] * p[k];
            B[2 * r] += p[r] * u[0];
            B[2 * r + 1] += p[r] * u[1];
        }
    }
    tr = A[0] + A[4] + A[8];
    for (r = 0; r < 3; r++) A[4 * r] += PLATEAU__RETRI_RIDGE * tr;
    /* Gaussian elimination with partial pivoting, two right-hand sides */
    for (r = 0; r < 3; r++) {
        int piv = r, q;
        for (q = r + 1; q < 3; q++)
            if (PLATEAU_FABS(A[3 * q + r]) > PLATEAU_FABS(A[3 * piv + r])) piv = q;
        if (!(PLATEAU_FABS(A[3 * piv + r]) > 0.0)) return PLATEAU_OK;
        if (piv != r) {
            for (k = 0; k < 3; k++) { double tmp = A[3 * r + k]; A[3 * r + k] = A[3 * piv + k]; A[3 * piv + k] = tmp; }
            for (k = 0; k < 2; k++) { double tmp = B[2 * r + k]; B[2 * r + k] = B[2 * piv + k]; B[2 * piv + k] = tmp; }
        }
        for (q = r + 1; q < 3; q++) {
            double fct = A[3 * q + r] / A[3 * r + r];
            for (k = r; k < 3; k++) A[3 * q + k] -= fct * A[3 * r + k];
            for (k = 0; k < 2; k++) B[2 * q + k] -= fct * B[2 * r + k];
        }
    }
    for (r = 2; r >= 0; r--) {
        for (k = 0; k < 2; k++) {
            double sum = B[2 * r + k];
            int q;
            for (q = r + 1; q < 3; q++) sum -= A[3 * r + q] * M[2 * q + k];
            M[2 * r + k] = sum / A[3 * r + r];
        }
    }
    uv = (double *)plateau__util_array(al, nv, 2 * sizeof(double));
    seg = (plateau_index *)plateau__util_array(al, m, 2 * sizeof(plateau_index));
    if (!uv || !seg) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in the re-projection", 0, 0);
        goto done;
    }
    for (i = 0; i < m; i++) {
        uv[2 * i] = dom->uv[2 * i];
        uv[2 * i + 1] = dom->uv[2 * i + 1];
        seg[2 * i] = (plateau_index)i;
        seg[2 * i + 1] = (plateau_index)((i + 1) % m);
    }
    for (i = m; i < nv; i++) {
        double p[3];
        for (k = 0; k < 3; k++) p[k] = mesh->positions[3 * i + (size_t)k] - c[k];
        uv[2 * i] = cu[0] + p[0] * M[0] + p[1] * M[2] + p[2] * M[4];
        uv[2 * i + 1] = cu[1] + p[0] * M[1] + p[1] * M[3] + p[2] * M[5];
        if (!plateau_point_in_polygon(dom->uv, m, uv + 2 * i, 0.0)) goto done;
    }
    memset(&in, 0, sizeof in);
    memset(&dopt, 0, sizeof dopt);
    memset(&dt, 0, sizeof dt);
    in.points = uv;
    in.num_points = nv;
    in.segments = seg;
    in.num_segments = m;
    dopt.allocator = mesh->allocator;
    dres = plateau_dt_triangulate(&in, &dopt, &dt, NULL);
    if (dres != PLATEAU_DT_OK) {
        plateau_dt_free(&dt);
        if (dres == PLATEAU_DT_ERR_OUT_OF_MEMORY) {
            rc = PLATEAU_ERR_OUT_OF_MEMORY;
            plateau__util_error(err, rc, -1, "out of memory in the re-triangulation", 0, 0);
        }
        goto done;
    }
    if (dt.num_points != nv || dt.num_triangles != mesh->num_triangles) {
        plateau_dt_free(&dt);
        goto done;
    }
    for (i = 0; i < nv; i++)
        if (dt.duplicate_of[i] != (plateau_index)i) break;
    if (i < nv) {
        plateau_dt_free(&dt);
        goto done;
    }
    *used = 1;
    /* the same triangulation when every new edge is an old one */
    for (t = 0; t < dt.num_triangles && !*changed; t++) {
        for (k = 0; k < 3; k++) {
            plateau_index p = dt.triangles[3 * t + (size_t)k], q = dt.triangles[3 * t + (size_t)((k + 1) % 3)];
            size_t e, found = 0;
            for (e = mesh->vertex_edge_start[p]; e < mesh->vertex_edge_start[p + 1]; e++) {
                size_t ed = (size_t)mesh->vertex_edges[e];
                if (mesh->edges[2 * ed] == q || mesh->edges[2 * ed + 1] == q) found = 1;
            }
            if (!found) { *changed = 1; break; }
        }
    }
    if (*changed) {
        memcpy(mesh->triangles, dt.triangles, 3 * dt.num_triangles * sizeof(plateau_index));
        rc = plateau_mesh_build_adjacency(mesh, err);
    }
    plateau_dt_free(&dt);
done:
    plateau__free(al, uv);
    plateau__free(al, seg);
    return rc;
}

/* ---- the step as plateau_solve runs it ---- */

/* Step 6 of one round: paper-literal re-projects to the plane domain and
 * re-runs the triangulation where it can (dom), the other methods (and
 * paper-literal elsewhere) flip: by the flip rule of the method, method
 * area above PLATEAU_SPARSE_THRESHOLD free vertices without the sweep with
 * relaxation.  *changed = 1 when the triangles changed. */
static plateau_result plateau__retri_step(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          const plateau__retri_domain *dom, int flip_rule,
                                          size_t nfree, plateau_report *rep, int *changed,
                                          plateau_error *err)
{
    plateau_result rc;
    size_t flips = 0;
    *changed = 0;
    if (cfg->method == PLATEAU_METHOD_PAPER_LITERAL && dom && dom->uv) {
        int used = 0;
        rc = plateau__retri_reproject(mesh, dom, &used, changed, err);
        if (rc != PLATEAU_OK) return rc;
        if (used) {
            rep->retriangulations++;
            if (*changed) rep->flips++;
            return PLATEAU_OK;
        }
    } else if (flip_rule == PLATEAU__RETRI_FLIP_AREA && nfree > PLATEAU_SPARSE_THRESHOLD) {
        flip_rule = PLATEAU__RETRI_FLIP_AREA_PLAIN;
    }
    rc = plateau__retri_flip_sweeps(mesh, flip_rule, 0, &flips, err);
    if (rc != PLATEAU_OK) return rc;
    *changed = flips > 0;
    rep->flips += flips;
    return PLATEAU_OK;
}
/* ======== END SECTION: step 6: re-triangulation =========================== */

/* ======== SECTION: the final check (plateau__chk_) ======================== */
/* Triangles that intersect each other, whether the last solve reached its
 * stopping rule, and the pinch test of a film between two loops. */
/* ---- the final check: triangles that intersect each other ----
 * orient3d (Shewchuk, "Adaptive precision floating-point arithmetic and
 * fast robust geometric predicates", 1997) with its static error bound
 * A = (7 + 56 eps) eps times the permanent: the sign of det[a-d; b-d; c-d]
 * when the rounded value decides it, 0 when it does not (treated as "on
 * the plane": a contact is counted rather than missed). */
/* Shewchuk's static error bounds of orient3d and orient2d, with eps the
 * unit roundoff 2^-53 of binary64. */
#define PLATEAU__CHK_EPS 1.1102230246251565e-16
#define PLATEAU__CHK_O3D_BOUND ((7.0 + 56.0 * PLATEAU__CHK_EPS) * PLATEAU__CHK_EPS)
#define PLATEAU__CHK_O2D_BOUND ((3.0 + 16.0 * PLATEAU__CHK_EPS) * PLATEAU__CHK_EPS)

static int plateau__chk_orient3d(const double *a, const double *b, const double *c, const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy, ab = adx * bdy,
           ba = bdx * ady;
    double det = adz * (bc - cb) + bdz * (ca - ac) + cdz * (ab - ba);
    double perm = (PLATEAU_FABS(bc) + PLATEAU_FABS(cb)) * PLATEAU_FABS(adz) +
                  (PLATEAU_FABS(ca) + PLATEAU_FABS(ac)) * PLATEAU_FABS(bdz) +
                  (PLATEAU_FABS(ab) + PLATEAU_FABS(ba)) * PLATEAU_FABS(cdz);
    double bound = PLATEAU__CHK_O3D_BOUND * perm;
    return det > bound ? 1 : det < -bound ? -1 : 0;
}

/* orient2d of the points projected along axis k (dropped), with the
 * static bound (3 + 16 eps) eps (Shewchuk); 0 when undecided. */
static int plateau__chk_orient2d(const double *a, const double *b, const double *c, int k)
{
    int i = (k + 1) % 3, j = (k + 2) % 3;
    double l = (a[i] - c[i]) * (b[j] - c[j]), r = (a[j] - c[j]) * (b[i] - c[i]);
    double det = l - r, bound = PLATEAU__CHK_O2D_BOUND * (PLATEAU_FABS(l) + PLATEAU_FABS(r));
    return det > bound ? 1 : det < -bound ? -1 : 0;
}

/* 1 when x lies in the closed box of p and q along both projected axes */
static int plateau__chk_between(const double *p, const double *q, const double *x, int k)
{
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return x[i] >= (p[i] < q[i] ? p[i] : q[i]) && x[i] <= (p[i] > q[i] ? p[i] : q[i]) &&
           x[j] >= (p[j] < q[j] ? p[j] : q[j]) && x[j] <= (p[j] > q[j] ? p[j] : q[j]);
}

/* Closed segments pq and uv in the plane of projection k meet? */
static int plateau__chk_seg_seg_2d(const double *p, const double *q, const double *u,
                                   const double *v, int k)
{
    int d1 = plateau__chk_orient2d(p, q, u, k), d2 = plateau__chk_orient2d(p, q, v, k);
    int d3 = plateau__chk_orient2d(u, v, p, k), d4 = plateau__chk_orient2d(u, v, q, k);
    if (d1 * d2 < 0 && d3 * d4 < 0) return 1;
    return (d1 == 0 && plateau__chk_between(p, q, u, k)) || (d2 == 0 && plateau__chk_between(p, q, v, k)) ||
           (d3 == 0 && plateau__chk_between(u, v, p, k)) || (d4 == 0 && plateau__chk_between(u, v, q, k));
}

/* Closed point x in the closed triangle abc, projected along k? */
static int plateau__chk_point_in_2d(const double *x, const double *a, const double *b,
                                    const double *c, int k)
{
    int o1 = plateau__chk_orient2d(a, b, x, k), o2 = plateau__chk_orient2d(b, c, x, k);
    int o3 = plateau__chk_orient2d(c, a, x, k);
    return !((o1 > 0 || o2 > 0 || o3 > 0) && (o1 < 0 || o2 < 0 || o3 < 0));
}

/* The closed segment pq and the closed triangle abc meet in the projection
 * that drops the largest component of the triangle's normal? */
static int plateau__chk_seg_tri_2d(const double *p, const double *q, const double *a,
                                   const double *b, const double *c)
{
    double u[3], w[3], nrm[3];
    int k = 0;
    plateau__util_sub(b, a, u);
    plateau__util_sub(c, a, w);
    plateau__util_cross(u, w, nrm);
    if (PLATEAU_FABS(nrm[1]) > PLATEAU_FABS(nrm[k])) k = 1;
    if (PLATEAU_FABS(nrm[2]) > PLATEAU_FABS(nrm[k])) k = 2;
    return plateau__chk_point_in_2d(p, a, b, c, k) || plateau__chk_point_in_2d(q, a, b, c, k) ||
           plateau__chk_seg_seg_2d(p, q, a, b, k) || plateau__chk_seg_seg_2d(p, q, b, c, k) ||
           plateau__chk_seg_seg_2d(p, q, c, a, k);
}

/* Does the closed segment pq meet the closed triangle abc?  Off the plane:
 * p and q not strictly on one side of it, and the line pq passing inside
 * the triangle (orient3d(p, q, .) of its three edges of one sign).  When
 * rounding leaves p and q both on the plane, or the line's side of an edge
 * undecided (a segment nearly in the plane: a tilted flat mesh, whose
 * rounded coordinates make every orient3d tiny), the 2-D test decides. */
static int plateau__chk_seg_tri(const double *p, const double *q, const double *a, const double *b,
                                const double *c)
{
    int sp = plateau__chk_orient3d(a, b, c, p), sq = plateau__chk_orient3d(a, b, c, q);
    int s1, s2, s3;
    if (sp * sq > 0) return 0;
    if (sp == 0 && sq == 0) return plateau__chk_seg_tri_2d(p, q, a, b, c);
    s1 = plateau__chk_orient3d(p, q, a, b);
    s2 = plateau__chk_orient3d(p, q, b, c);
    s3 = plateau__chk_orient3d(p, q, c, a);
    if ((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0)) return 0;
    if (s1 == 0 || s2 == 0 || s3 == 0) return plateau__chk_seg_tri_2d(p, q, a, b, c);
    return 1;
}

/* Do triangles t and u meet other than in what they share? */
static int plateau__chk_pair(const plateau_mesh *mesh, size_t t, size_t u)
{
    const plateau_index *a = mesh->triangles + 3 * t, *b = mesh->triangles + 3 * u;
    const double *pa[3], *pb[3];
    int i, j, shared = 0, si = -1, sj = -1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            if (a[i] == b[j]) { shared++; si = i; sj = j; }
    if (shared >= 2) return 0; /* a common edge: overlap only when folded flat */
    for (i = 0; i < 3; i++) {
        pa[i] = plateau__geo_pos(mesh, a[i]);
        pb[i] = plateau__geo_pos(mesh, b[i]);
    }
    if (shared == 1)
        return plateau__chk_seg_tri(pa[(si + 1) % 3], pa[(si + 2) % 3], pb[0], pb[1], pb[2]) ||
               plateau__chk_seg_tri(pb[(sj + 1) % 3], pb[(sj + 2) % 3], pa[0], pa[1], pa[2]);
    for (i = 0; i < 3; i++)
        if (plateau__chk_seg_tri(pa[i], pa[(i + 1) % 3], pb[0], pb[1], pb[2]) ||
            plateau__chk_seg_tri(pb[i], pb[(i + 1) % 3], pa[0], pa[1], pa[2]))
            return 1;
    return 0;
}

/* cell coordinate of x along axis k: floor((x - origin) / h), clamped */
static size_t plateau__chk_cell(double x, double origin, double h, size_t dim)
{
    double c = (x - origin) / h;
    if (!(c > 0.0)) return 0;
    if (c >= (double)dim) return dim - 1;
    return (size_t)c;
}

/* ---- the pair search of plateau_mesh_check ----
 * Two triangles meet by the rule of plateau__chk_pair exactly when an edge
 * of one that shares no vertex with the other meets the other (with no
 * common vertex any edge, with one common vertex s the edge opposite s;
 * with a common edge none).  So the search pairs edges with triangles
 * instead of triangles with triangles, and never looks at an (edge,
 * triangle) with a common vertex: the spokes and the triangles of a vertex
 * of valence k (a fan of thousands) cost O(k), not O(k^2).  Triangles and
 * edges are cut into pieces no longer than the cell side h (bisecting the
 * longest side; pieces' boxes grown by 1e-9 of the mesh's size, far above
 * the rounding of the cut), so that a long thin triangle enters the cells
 * along it, not every cell of its box.  An edge and a triangle with
 * pieces in one cell whose boxes overlap are tested with the calls
 * plateau__chk_pair makes (the edge as each of its triangles runs it), and
 * each meeting pair is counted once.  h: from 4 times the mean triangle
 * height, doubled until the pieces make at most 32 T + 1024 cell entries,
 * so time and memory are O(T log T) plus the tests in crowded cells. */
typedef struct plateau__chk_entry {
    size_t item; /* t: triangle t; T + 3 t + k: its edge (v_k, v_(k+1)), T triangles */
    double lo[3], hi[3];
} plateau__chk_entry;

/* The sort key of entry idx: its cell.  Entries are made triangles first,
 * then edges, each in item order, so sorting the keys stably by cell
 * orders each cell's entries by item, as plateau__chk_cell_tests wants,
 * while only these 16 bytes move. */
typedef struct plateau__chk_key {
    size_t cell, idx;
} plateau__chk_key;

typedef struct plateau__chk_grid {
    double origin[3], h, margin;
    size_t dim[3];
    plateau__chk_entry *e; /* NULL: count only */
    plateau__chk_key *key; /* with e */
    size_t count, cap;
} plateau__chk_grid;

/* The entries of one piece's box (grown by the margin): one per cell. */
static void plateau__chk_emit(plateau__chk_grid *g, size_t item, const double *lo, const double *hi)
{
    size_t a[3], b[3], x, y, z;
    int k;
    for (k = 0; k < 3; k++) {
        a[k] = plateau__chk_cell(lo[k] - g->margin, g->origin[k], g->h, g->dim[k]);
        b[k] = plateau__chk_cell(hi[k] + g->margin, g->origin[k], g->h, g->dim[k]);
    }
    for (x = a[0]; x <= b[0]; x++)
        for (y = a[1]; y <= b[1]; y++)
            for (z = a[2]; z <= b[2]; z++) {
                if (g->e && g->count < g->cap) {
                    plateau__chk_entry *en = g->e + g->count;
                    g->key[g->count].cell = (x * g->dim[1] + y) * g->dim[2] + z;
                    g->key[g->count].idx = g->count;
                    en->item = item;
                    for (k = 0; k < 3; k++) {
                        en->lo[k] = lo[k] - g->margin;
                        en->hi[k] = hi[k] + g->margin;
                    }
                }
                g->count++;
            }
}

/* The pieces of triangle t (bisecting the longest side until no side is
 * above h, at most 40 levels) or of its edge k (k >= 0: equal pieces no
 * longer than h); stops early once g->count passes stop. */
static void plateau__chk_pieces(const plateau_mesh *mesh, size_t t, int k, plateau__chk_grid *g,
                                size_t stop)
{
    double st[42][9];
    int depth[42], top = 0, q, i;
    const plateau_index *tr = mesh->triangles + 3 * t;
    if (k >= 0) {
        const double *p = plateau__geo_pos(mesh, tr[k]), *r = plateau__geo_pos(mesh, tr[(k + 1) % 3]);
        double d[3], len, n;
        size_t pieces, j;
        plateau__util_sub(r, p, d);
        len = plateau__util_norm(d);
        n = len / g->h;
        pieces = n < 1.0 ? 1 : n < 1e6 ? (size_t)n + 1 : 1000001;
        for (j = 0; j < pieces && g->count <= stop; j++) {
            double lo[3], hi[3], s0 = (double)j / (double)pieces, s1 = (double)(j + 1) / (double)pieces;
            for (i = 0; i < 3; i++) {
                double u = p[i] + s0 * d[i], w = j + 1 == pieces ? r[i] : p[i] + s1 * d[i];
                lo[i] = u < w ? u : w;
                hi[i] = u < w ? w : u;
            }
            plateau__chk_emit(g, mesh->num_triangles + 3 * t + (size_t)k, lo, hi);
        }
        return;
    }
    for (q = 0; q < 3; q++)
        for (i = 0; i < 3; i++) st[0][3 * q + i] = plateau__geo_pos(mesh, tr[q])[i];
    depth[0] = 0;
    top = 1;
    while (top > 0 && g->count <= stop) {
        double *c = st[--top], l2[3], lo[3], hi[3];
        int d = depth[top], longest = 0;
        for (q = 0; q < 3; q++) {
            const double *a = c + 3 * q, *b = c + 3 * ((q + 1) % 3);
            l2[q] = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]);
            if (l2[q] > l2[longest]) longest = q;
        }
        if (l2[longest] <= g->h * g->h || d >= 40 || top + 2 > 42) {
            for (i = 0; i < 3; i++) {
                lo[i] = c[i];
                hi[i] = c[i];
                for (q = 1; q < 3; q++) {
                    if (c[3 * q + i] < lo[i]) lo[i] = c[3 * q + i];
                    if (c[3 * q + i] > hi[i]) hi[i] = c[3 * q + i];
                }
            }
            plateau__chk_emit(g, t, lo, hi);
            continue;
        }
        {   /* (a, b, c) with ab longest: (a, m, c) and (m, b, c) */
            double a[3], b[3], o[3], mid[3];
            for (i = 0; i < 3; i++) {
                a[i] = c[3 * longest + i];
                b[i] = c[3 * ((longest + 1) % 3) + i];
                o[i] = c[3 * ((longest + 2) % 3) + i];
                mid[i] = 0.5 * a[i] + 0.5 * b[i];
            }
            for (i = 0; i < 3; i++) {
                st[top][i] = a[i]; st[top][3 + i] = mid[i]; st[top][6 + i] = o[i];
                st[top + 1][i] = mid[i]; st[top + 1][3 + i] = b[i]; st[top + 1][6 + i] = o[i];
            }
            depth[top] = depth[top + 1] = d + 1;
            top += 2;
        }
    }
}

/* All pieces of the mesh: its triangles, then each edge once (from the
 * triangle of smaller index, or the only one). */
static void plateau__chk_all_pieces(const plateau_mesh *mesh, plateau__chk_grid *g, size_t stop)
{
    size_t t;
    int k;
    for (t = 0; t < mesh->num_triangles && g->count <= stop; t++) plateau__chk_pieces(mesh, t, -1, g, stop);
    for (t = 0; t < mesh->num_triangles && g->count <= stop; t++) {
        for (k = 0; k < 3; k++) {
            plateau_index u = mesh->neighbors ? mesh->neighbors[3 * t + (size_t)k] : -1;
            if (u < 0 || (size_t)u > t) plateau__chk_pieces(mesh, t, k, g, stop);
        }
    }
}

/* The n keys (made in idx order) sorted by cell, stably, so by (cell,
 * idx): a least-significant-digit radix sort, a byte per pass, as many
 * passes as the largest cell has bytes; tmp holds n keys.  Returns the
 * sorted array (key or tmp). */
static plateau__chk_key *plateau__chk_sort_keys(plateau__chk_key *key, plateau__chk_key *tmp, size_t n)
{
    size_t count[256], i, top = 0;
    int shift;
    for (i = 0; i < n; i++)
        if (key[i].cell > top) top = key[i].cell;
    for (shift = 0; shift < (int)(8 * sizeof(size_t)) && (top >> shift) != 0; shift += 8) {
        size_t sum = 0, c;
        plateau__chk_key *x;
        for (i = 0; i < 256; i++) count[i] = 0;
        for (i = 0; i < n; i++) count[(key[i].cell >> shift) & 255]++;
        for (i = 0; i < 256; i++) {
            c = count[i];
            count[i] = sum;
            sum += c;
        }
        for (i = 0; i < n; i++) tmp[count[(key[i].cell >> shift) & 255]++] = key[i];
        x = key;
        key = tmp;
        tmp = x;
    }
    return key;
}

static int plateau__chk_pair_cmp(const void *pa, const void *pb)
{
    const size_t *a = (const size_t *)pa, *b = (const size_t *)pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0;
}

static int plateau__chk_size_cmp(const void *pa, const void *pb)
{
    size_t a = *(const size_t *)pa, b = *(const size_t *)pb;
    return a < b ? -1 : a > b ? 1 : 0;
}

/* The vertex in most of the triangles of the run en[0 .. n) (one whose
 * entries' items are sorted, triangles first), or -1; scratch n * 3. */
static plateau_index plateau__chk_hub(const plateau_mesh *mesh, const plateau__chk_entry *en,
                                      size_t n, size_t *scratch)
{
    size_t i, c = 0, best = 0, run = 0;
    plateau_index hub = -1;
    for (i = 0; i < n && en[i].item < mesh->num_triangles; i++) {
        const plateau_index *tr = mesh->triangles + 3 * en[i].item;
        scratch[c++] = (size_t)tr[0];
        scratch[c++] = (size_t)tr[1];
        scratch[c++] = (size_t)tr[2];
    }
    if (c < 48) return -1; /* a small cell: the plain double loop */
    PLATEAU_QSORT(scratch, c, sizeof(size_t), plateau__chk_size_cmp);
    for (i = 0; i < c; i++) {
        run = i > 0 && scratch[i] == scratch[i - 1] ? run + 1 : 1;
        if (run > best) {
            best = run;
            hub = (plateau_index)scratch[i];
        }
    }
    return hub;
}

/* The (edge, triangle) tests of one cell's run en[0 .. n) (triangles
 * first); each meeting pair goes to *hits (as 2 indices, smaller first). */
typedef struct plateau__chk_hits {
    size_t *p;
    size_t count, cap;
    int failed; /* out of memory */
} plateau__chk_hits;

static void plateau__chk_hit(const plateau_mesh *mesh, plateau__chk_hits *hits, size_t t, size_t u)
{
    if (hits->count == hits->cap) {
        size_t cap = hits->cap ? 2 * hits->cap : 64;
        size_t *p = (size_t *)plateau__util_array(&mesh->allocator, cap, 2 * sizeof(size_t));
        if (!p) {
            hits->failed = 1;
            return;
        }
        if (hits->count) memcpy(p, hits->p, 2 * hits->count * sizeof(size_t));
        plateau__free(&mesh->allocator, hits->p);
        hits->p = p;
        hits->cap = cap;
    }
    hits->p[2 * hits->count] = t < u ? t : u;
    hits->p[2 * hits->count + 1] = t < u ? u : t;
    hits->count++;
}

/* Edge item ed (its triangle t, side k) against triangle u: the calls of
 * plateau__chk_pair for the edge as each of its triangles runs it. */
static void plateau__chk_edge_tri(const plateau_mesh *mesh, size_t t, int k, size_t u,
                                  plateau__chk_hits *hits)
{
    const plateau_index *tu = mesh->triangles + 3 * u;
    const double *pu[3];
    plateau_index side[2];
    int s, q;
    for (q = 0; q < 3; q++) pu[q] = plateau__geo_pos(mesh, tu[q]);
    side[0] = (plateau_index)t;
    side[1] = mesh->neighbors ? mesh->neighbors[3 * t + (size_t)k] : -1;
    for (s = 0; s < 2; s++) {
        const plateau_index *tr;
        plateau_index a = mesh->triangles[3 * t + (size_t)k], b = mesh->triangles[3 * t + (size_t)((k + 1) % 3)];
        int shared = 0, i, j;
        if (side[s] < 0 || (size_t)side[s] == u) continue;
        tr = mesh->triangles + 3 * (size_t)side[s];
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) shared += tr[i] == tu[j];
        if (shared >= 2) continue; /* a common edge: the fold count's case */
        if (s == 1) { /* the neighbour runs the edge b -> a */
            plateau_index x = a;
            a = b;
            b = x;
        }
        if (plateau__chk_seg_tri(plateau__geo_pos(mesh, a), plateau__geo_pos(mesh, b), pu[0], pu[1], pu[2]))
            plateau__chk_hit(mesh, hits, (size_t)side[s], u);
    }
}

static void plateau__chk_cell_tests(const plateau_mesh *mesh, const plateau__chk_entry *en, size_t n,
                                    size_t *scratch, plateau__chk_hits *hits)
{
    size_t T = mesh->num_triangles, nt = 0, nrest = 0, i, j;
    plateau_index hub;
    while (nt < n && en[nt].item < T) nt++;
    if (nt == 0 || nt == n) return;
    hub = plateau__chk_hub(mesh, en, nt, scratch);
    /* the cell's triangles without the hub (scratch is free again) */
    for (j = 0; j < nt; j++) {
        const plateau_index *tu = mesh->triangles + 3 * en[j].item;
        if (tu[0] != hub && tu[1] != hub && tu[2] != hub) scratch[nrest++] = j;
    }
    for (i = nt; i < n; i++) {
        size_t t = (en[i].item - T) / 3, cnt;
        int k = (int)((en[i].item - T) % 3), c;
        plateau_index a = mesh->triangles[3 * t + (size_t)k], b = mesh->triangles[3 * t + (size_t)((k + 1) % 3)];
        /* an edge of the hub shares it with every triangle of the hub:
         * only the others are tested (the many pairs of a fan are not) */
        int on_hub = hub >= 0 && (a == hub || b == hub);
        cnt = on_hub ? nrest : nt;
        for (j = 0; j < cnt; j++) {
            const plateau__chk_entry *tj = en + (on_hub ? scratch[j] : j);
            const plateau_index *tu = mesh->triangles + 3 * tj->item;
            int apart = 0;
            if (tu[0] == a || tu[1] == a || tu[2] == a || tu[0] == b || tu[1] == b || tu[2] == b) continue;
            for (c = 0; c < 3; c++)
                if (en[i].lo[c] > tj->hi[c] || tj->lo[c] > en[i].hi[c]) apart = 1;
            if (!apart) plateau__chk_edge_tri(mesh, t, k, tj->item, hits);
        }
    }
}

/* The number of pairs of triangles that meet (see above) into *pairs.
 * PLATEAU_OK, _OUT_OF_MEMORY or _OVERFLOW. */
static plateau_result plateau__chk_pairs(const plateau_mesh *mesh, size_t *pairs)
{
    size_t T = mesh->num_triangles, t, i, j, cap = 32 * T + 1024, longest = 0, *scratch = NULL;
    double glo[3], ghi[3], h = 0.0, diag2 = 0.0;
    plateau__chk_entry *run = NULL;
    plateau__chk_key *sorted = NULL;
    plateau__chk_grid g;
    plateau__chk_hits hits;
    int k, tries;
    *pairs = 0;
    memset(&g, 0, sizeof g);
    memset(&hits, 0, sizeof hits);
    for (t = 0; t < T; t++) {
        double e[3][3], l[3], cr[3];
        int q;
        for (q = 0; q < 3; q++) {
            const double *p = plateau__geo_pos(mesh, mesh->triangles[3 * t + (size_t)q]);
            plateau__util_sub(plateau__geo_pos(mesh, mesh->triangles[3 * t + (size_t)((q + 1) % 3)]), p, e[q]);
            l[q] = plateau__util_norm(e[q]);
            for (k = 0; k < 3; k++) {
                if ((t == 0 && q == 0) || p[k] < glo[k]) glo[k] = p[k];
                if ((t == 0 && q == 0) || p[k] > ghi[k]) ghi[k] = p[k];
            }
        }
        plateau__util_cross(e[0], e[1], cr);
        q = l[0] >= l[1] && l[0] >= l[2] ? 0 : l[1] >= l[2] ? 1 : 2;
        if (l[q] > 0.0) h += 4.0 * plateau__util_norm(cr) / l[q] / (double)T; /* 4 heights */
    }
    for (k = 0; k < 3; k++) diag2 += (ghi[k] - glo[k]) * (ghi[k] - glo[k]);
    g.margin = 1e-9 * PLATEAU_SQRT(diag2);
    for (k = 0; k < 3; k++) g.origin[k] = glo[k] - 2.0 * g.margin;
    if (!(h > 0.0) || !plateau__util_finite(h)) h = PLATEAU_SQRT(diag2);
    if (!(h > 0.0) || !plateau__util_finite(h)) h = 1.0;
    for (tries = 0; tries < PLATEAU__UTIL_POW2_STEPS; tries++, h *= 2.0) {
        int fits = 1;
        g.h = h;
        for (k = 0; k < 3; k++) {
            double d = (ghi[k] - g.origin[k] + 2.0 * g.margin) / h;
            fits &= d < 1048576.0;
            g.dim[k] = fits ? (size_t)d + 1 : 1;
        }
        if (!fits) continue;
        g.count = 0;
        plateau__chk_all_pieces(mesh, &g, cap);
        if (g.count <= cap) break;
    }
    if (g.count > cap) return PLATEAU_ERR_OVERFLOW;
    g.cap = g.count;
    g.e = (plateau__chk_entry *)plateau__util_array(&mesh->allocator, g.cap + 1, sizeof(plateau__chk_entry));
    g.key = (plateau__chk_key *)plateau__util_array(&mesh->allocator, g.cap + 1, 2 * sizeof(plateau__chk_key));
    if (g.e && g.key) {
        g.count = 0;
        plateau__chk_all_pieces(mesh, &g, g.cap);
        sorted = plateau__chk_sort_keys(g.key, g.key + g.cap + 1, g.count);
        for (i = 0; i < g.count; i = j) { /* the longest cell run (before merging) */
            for (j = i; j < g.count && sorted[j].cell == sorted[i].cell; j++) {}
            if (j - i > longest) longest = j - i;
        }
        scratch = (size_t *)plateau__util_array(&mesh->allocator, longest + 1, 3 * sizeof(size_t));
        run = (plateau__chk_entry *)plateau__util_array(&mesh->allocator, longest + 1, sizeof(plateau__chk_entry));
    }
    if (!g.e || !g.key || !scratch || !run) hits.failed = 1;
    for (i = 0; i < g.count && !hits.failed; i = j) {
        size_t n = 0;
        /* the cell's entries, one per item: the union of its pieces' boxes */
        for (j = i; j < g.count && sorted[j].cell == sorted[i].cell; j++) {
            const plateau__chk_entry *en = g.e + sorted[j].idx;
            if (n > 0 && run[n - 1].item == en->item) {
                for (k = 0; k < 3; k++) {
                    if (en->lo[k] < run[n - 1].lo[k]) run[n - 1].lo[k] = en->lo[k];
                    if (en->hi[k] > run[n - 1].hi[k]) run[n - 1].hi[k] = en->hi[k];
                }
            } else {
                run[n++] = *en;
            }
        }
        plateau__chk_cell_tests(mesh, run, n, scratch, &hits);
    }
    plateau__free(&mesh->allocator, run);
    plateau__free(&mesh->allocator, g.key);
    plateau__free(&mesh->allocator, scratch);
    plateau__free(&mesh->allocator, g.e);
    if (hits.failed) {
        plateau__free(&mesh->allocator, hits.p);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    /* each pair once (plateau__chk_pair agrees: one of its calls said so) */
    if (hits.count > 1) PLATEAU_QSORT(hits.p, hits.count, 2 * sizeof(size_t), plateau__chk_pair_cmp);
    for (i = 0; i < hits.count; i++)
        if (i == 0 || hits.p[2 * i] != hits.p[2 * i - 2] || hits.p[2 * i + 1] != hits.p[2 * i - 1])
            *pairs += (size_t)plateau__chk_pair(mesh, hits.p[2 * i], hits.p[2 * i + 1]);
    plateau__free(&mesh->allocator, hits.p);
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_mesh_check(const plateau_mesh *mesh, plateau_quality *quality,
                                              plateau_error *err)
{
    size_t pairs = 0;
    plateau_result rc;
    if (!mesh || !quality) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_mesh_check needs a mesh and a quality", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    plateau_mesh_quality(mesh, quality);
    if (mesh->num_triangles < 2) return PLATEAU_OK;
    rc = plateau__chk_pairs(mesh, &pairs);
    if (rc == PLATEAU_ERR_OUT_OF_MEMORY) {
        plateau__util_error(err, rc, -1, "out of memory in plateau_mesh_check", 0, 0);
        return rc;
    }
    if (rc != PLATEAU_OK) {
        plateau__util_error(err, rc, -1, "no grid fits the mesh's triangles", 0, 0);
        return rc;
    }
    quality->intersecting_pairs = pairs;
    if (pairs) quality->defects |= PLATEAU_DEFECT_INTERSECTION;
    return PLATEAU_OK;
}

PLATEAU_DEF char *plateau_defects_string(unsigned defects, char *buf, size_t size)
{
    static const char *const names[9] = {
        "inverted triangles", "a fold (|dihedral| above PLATEAU_FOLD_DEGREES)",
        "degenerate triangles (an angle at rounding level)", "triangles intersecting each other",
        "the objective did not reach its stopping rule",
        "the film pinched (its neck between two loops collapsed)",
        "no equilibrium: the film ran away from the boundary (too high a pressure), or cables out of balance",
        "the volume was not reached", "a cable crosses the film"
    };
    size_t len = 0;
    int bit, first = 1;
    if (!buf || size == 0) return buf;
    buf[0] = '\0';
    for (bit = 0; bit < 10; bit++) {
        const char *s;
        if (bit < 9 && !(defects & (1u << bit))) continue;
        if (bit == 9 && !(defects >> 9)) continue;
        s = bit < 9 ? names[bit] : "an unknown defect";
        if (!first) {
            const char *sep = "; ";
            for (; *sep && len + 1 < size; sep++) buf[len++] = *sep;
        }
        for (; *s && len + 1 < size; s++) buf[len++] = *s;
        first = 0;
    }
    if (first) {
        const char *s = "valid";
        for (; *s && len + 1 < size; s++) buf[len++] = *s;
    }
    buf[len] = '\0';
    return buf;
}

/* The degeneration check after a solve (plateau_mesh_quality) into the
 * report: area, angles, largest |dihedral|, inverted triangles. */
static void plateau__chk_report_quality(const plateau_mesh *mesh, plateau_report *rep)
{
    plateau_quality q;
    plateau_mesh_quality(mesh, &q);
    rep->area = q.area;
    rep->min_angle_deg = q.min_angle_deg;
    rep->max_angle_deg = q.max_angle_deg;
    rep->max_abs_beta_deg = q.max_abs_beta_deg;
    rep->inverted_triangles = q.inverted_triangles;
}

/* The final check of every solve (plateau_solve, plateau_mesh_minimize):
 * plateau_mesh_check's counts, and whether the last solve reached its
 * stopping rule (runs in the unit frame of plateau__frame, so the F
 * bound of method paper is scale-free).  Method paper solves a square
 * system exactly (quadratic convergence, F at rounding level): F above
 * PLATEAU__CHK_SOLVED_F is a local minimum of F that is no solution;
 * paper-literal's F cannot vanish (boundary H_i), its stop is any LM test
 * but the iteration cap; area: any stop but the cap.  A mesh with defects
 * never reports PLATEAU_STOP_CONVERGED. */
static plateau_result plateau__chk_final(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                        const plateau__cfg_run *run, plateau_report *rep, plateau_error *err)
{
    plateau_quality q;
    plateau_result rc = plateau_mesh_check(mesh, &q, err);
    if (rc != PLATEAU_OK) return rc;
    if (rep->interior_points == 0) rep->solved = 1;
    else if (run->budget && run->budget->interrupted) rep->solved = 0; /* cut short by the time budget */
    else if (cfg->method == PLATEAU_METHOD_PAPER) rep->solved = rep->f_final <= PLATEAU__CHK_SOLVED_F;
    else if (cfg->method == PLATEAU_METHOD_AREA) rep->solved = rep->area_stop != PLATEAU_AREA_STOP_MAX_ITERATIONS;
    else rep->solved = rep->lm_stop != PLATEAU_LM_STOP_MAX_ITERATIONS;
    rep->inverted_triangles = q.inverted_triangles;
    rep->folded_edges = q.folded_edges;
    rep->degenerate_triangles = q.degenerate_triangles;
    rep->intersecting_pairs = q.intersecting_pairs;
    rep->defects = q.defects | (rep->solved ? 0u : PLATEAU_DEFECT_UNSOLVED);
    if (rep->defects && rep->stop == PLATEAU_STOP_CONVERGED) rep->stop = PLATEAU_STOP_DEFECTS;
    return PLATEAU_OK;
}

/* The pinch test of a film between two loops (plateau_solve_loops): its
 * neck, the shortest closed curve around it, against the shorter loop.
 * d(v) is the graph distance (Dijkstra on the edge lengths, a binary heap
 * with lazy deletion: O(E log E)) from loop 0 (mesh vertices 0 .. m0-1);
 * D the least d over loop 1 (vertices m0 .. m0+m1-1).  For each of
 * PLATEAU__CHK_NECK_LEVELS levels t in (0, D) the level set {d = t} of the
 * piecewise-linear interpolant separates the loops, so its length (summed
 * over the triangles it crosses) is at least the neck's; the least of
 * these lengths is the neck found.  On a catenoid the distance from one
 * ring runs along the meridians and the level sets are the parallels, so
 * the neck found is the waist 2 pi a.  Returns that over the shorter
 * loop's length, 1 when it cannot be measured (no path between the
 * loops), -1 when out of memory. */
#define PLATEAU__CHK_NECK_LEVELS 64

static double plateau__chk_neck_ratio(const plateau_mesh *mesh, size_t m0, size_t m1)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, cap = 2 * mesh->num_edges + nv + 1, hn = 0, v, t, e;
    double *dist, *hk, far = 0.0, best = -1.0, len[2] = {0.0, 0.0}, shorter;
    size_t *hv;
    int lev;
    dist = (double *)plateau__util_array(al, nv, sizeof(double));
    hk = (double *)plateau__util_array(al, cap, sizeof(double));
    hv = (size_t *)plateau__util_array(al, cap, sizeof(size_t));
    if (!dist || !hk || !hv) {
        plateau__free(al, dist);
        plateau__free(al, hk);
        plateau__free(al, hv);
        return -1.0;
    }
    for (v = 0; v < nv; v++) dist[v] = -1.0;
    /* heap push / pop of (key, vertex), a min-heap on key */
#define PLATEAU__CHK_NECK_PUSH(key, vert)                                                   \
    do {                                                                                \
        size_t c_ = hn++;                                                               \
        while (c_ > 0 && hk[(c_ - 1) / 2] > (key)) {                                    \
            hk[c_] = hk[(c_ - 1) / 2];                                                  \
            hv[c_] = hv[(c_ - 1) / 2];                                                  \
            c_ = (c_ - 1) / 2;                                                          \
        }                                                                               \
        hk[c_] = (key);                                                                 \
        hv[c_] = (vert);                                                                \
    } while (0)
    for (v = 0; v < m0; v++) PLATEAU__CHK_NECK_PUSH(0.0, v);
    while (hn > 0) {
        double key = hk[0], lk;
        size_t u = hv[0], c = 0, k2, lv;
        size_t s0, s1;
        /* pop: move the last entry down from the root */
        hn--;
        lk = hk[hn];
        lv = hv[hn];
        while ((k2 = 2 * c + 1) < hn) {
            if (k2 + 1 < hn && hk[k2 + 1] < hk[k2]) k2++;
            if (!(hk[k2] < lk)) break;
            hk[c] = hk[k2];
            hv[c] = hv[k2];
            c = k2;
        }
        hk[c] = lk;
        hv[c] = lv;
        if (dist[u] >= 0.0) continue;
        dist[u] = key;
        s0 = mesh->vertex_edge_start[u];
        s1 = mesh->vertex_edge_start[u + 1];
        for (e = s0; e < s1; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            size_t w = (size_t)mesh->edges[2 * ed] == u ? (size_t)mesh->edges[2 * ed + 1] : (size_t)mesh->edges[2 * ed];
            if (dist[w] < 0.0 && hn < cap) PLATEAU__CHK_NECK_PUSH(key + plateau_edge_length(mesh, ed), w);
        }
    }
#undef PLATEAU__CHK_NECK_PUSH
    for (v = m0; v < m0 + m1 && v < nv; v++)
        if (dist[v] >= 0.0 && (far == 0.0 || dist[v] < far)) far = dist[v];
    for (v = 0; v < m0 + m1 && v < nv; v++) {
        size_t w = v + 1 == m0 ? 0 : (v + 1 == m0 + m1 ? m0 : v + 1);
        double d[3];
        plateau__util_sub(mesh->positions + 3 * w, mesh->positions + 3 * v, d);
        len[v < m0 ? 0 : 1] += plateau__util_norm(d);
    }
    shorter = len[0] < len[1] ? len[0] : len[1];
    if (far > 0.0 && shorter > 0.0) {
        for (lev = 0; lev < PLATEAU__CHK_NECK_LEVELS; lev++) {
            double level = far * ((double)lev + 0.5) / (double)PLATEAU__CHK_NECK_LEVELS, sum = 0.0;
            for (t = 0; t < mesh->num_triangles; t++) {
                double pt[2][3];
                int k, np = 0;
                for (k = 0; k < 3 && np < 2; k++) {
                    size_t a = (size_t)mesh->triangles[3 * t + (size_t)k];
                    size_t b = (size_t)mesh->triangles[3 * t + (size_t)((k + 1) % 3)];
                    double da = dist[a], db = dist[b];
                    if (da < 0.0 || db < 0.0) break;
                    /* the edge crosses the level (half-open: each crossing once) */
                    if ((da < level) != (db < level)) {
                        double s = (level - da) / (db - da);
                        int q;
                        for (q = 0; q < 3; q++)
                            pt[np][q] = mesh->positions[3 * a + (size_t)q] +
                                        s * (mesh->positions[3 * b + (size_t)q] - mesh->positions[3 * a + (size_t)q]);
                        np++;
                    }
                }
                if (np == 2) {
                    double d[3];
                    plateau__util_sub(pt[1], pt[0], d);
                    sum += plateau__util_norm(d);
                }
            }
            if (best < 0.0 || sum < best) best = sum;
        }
    }
    plateau__free(al, dist);
    plateau__free(al, hk);
    plateau__free(al, hv);
    return best >= 0.0 ? best / shorter : 1.0;
}

/* The pinch test after a solve (run->neck_m1 > 0: two loops): the neck
 * ratio into the report; 1 in *pinched when it is below
 * PLATEAU_PINCH_RATIO. */
static plateau_result plateau__chk_pinch(const plateau_mesh *mesh, const plateau__cfg_run *run,
                                        plateau_report *rep, int *pinched, plateau_error *err)
{
    double r;
    *pinched = 0;
    if (!PLATEAU__HAVE_LOOPS) return PLATEAU_OK; /* never asked: one loop */
    r = plateau__chk_neck_ratio(mesh, run->neck_m0, run->neck_m1);
    if (r < 0.0) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in the pinch test", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    rep->neck_ratio = r;
    *pinched = r < PLATEAU_PINCH_RATIO;
    return PLATEAU_OK;
}
/* ======== END SECTION: the final check ==================================== */

/* ---- declarations: the driver's rounds and run, which the optional
 * sections below call (the driver, which calls them, comes after them) ---- */
/* A round of method area that lowers the area by less than this fraction
 * of it ends the rounds (coarse to fine's coarse mesh keeps the rule). */
#define PLATEAU__DRV_ROUND_DROP 3e-5
static plateau_result plateau__drv_rounds(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          const plateau__cfg_run *run, const plateau__retri_domain *dom,
                                          plateau_report *rep, plateau_error *err);
static plateau_result plateau__drv_rounds_of(plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, const plateau__retri_domain *dom,
                                             plateau_report *rep, plateau_error *err);
static plateau_result plateau__drv_run(const double *xyz, const size_t *counts, size_t k, size_t m,
                                       const plateau__cfg *cfg, plateau_mesh *mesh, plateau_report *report,
                                       plateau_error *err);

/* ======== SECTION: several loops: the discs of two loops (plateau__loops_) == */
/* The other topology of a film between two loops (the manual's SEVERAL
 * LOOPS; plateau_options.alternatives): one disc per loop, each solved
 * alone, its area against the film's, and the discs returned as one mesh
 * when asked for and smaller.  The rest of several loops belongs to the
 * steps: their check (step 1), their domain (step 2), the seeding and
 * triangulation between them (steps 3-4) and the pinch test (the final
 * check). */
#ifndef PLATEAU_NO_LOOPS

/* The two discs as one mesh of two components: the loops' vertices first
 * (loop 0, then loop 1, as plateau_solve_loops promises), then the other
 * vertices of disc 0 and of disc 1; the report describes it. */
static plateau_result plateau__loops_merge(const plateau_mesh *d, const plateau_report *dr,
                                           const size_t *counts, plateau_mesh *mesh,
                                           plateau_report *rep, plateau_error *err)
{
    const plateau_allocator *a = &mesh->allocator;
    size_t nv = d[0].num_vertices + d[1].num_vertices, nt = d[0].num_triangles + d[1].num_triangles;
    size_t at = counts[0] + counts[1], j, v, t, base = 0;
    double *p = (double *)plateau__util_array(a, nv, 3 * sizeof(double));
    unsigned char *fx = (unsigned char *)plateau__util_array(a, nv, 1);
    plateau_index *tri = (plateau_index *)plateau__util_array(a, nt, 3 * sizeof(plateau_index));
    plateau_index *map = (plateau_index *)plateau__util_array(a, nv, sizeof(plateau_index));
    plateau_mesh nm;
    plateau_result rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (p && fx && tri && map) {
        size_t q = 0;
        for (j = 0; j < 2; j++) {
            for (v = 0; v < d[j].num_vertices; v++) {
                size_t w = v < counts[j] ? (j ? counts[0] : 0) + v : at++;
                map[base + v] = (plateau_index)w;
                memcpy(p + 3 * w, d[j].positions + 3 * v, 3 * sizeof(double));
                fx[w] = d[j].fixed[v];
            }
            for (t = 0; t < 3 * d[j].num_triangles; t++) tri[q++] = map[base + (size_t)d[j].triangles[t]];
            base += d[j].num_vertices;
        }
        rc = plateau_mesh_create(p, nv, fx, tri, nt, a, &nm, err);
    } else {
        plateau__util_error(err, rc, -1, "out of memory while joining the discs", 0, 0);
    }
    plateau__free(a, p);
    plateau__free(a, fx);
    plateau__free(a, tri);
    plateau__free(a, map);
    if (rc != PLATEAU_OK) return rc;
    plateau_mesh_free(mesh);
    *mesh = nm;
    plateau__chk_report_quality(mesh, rep);
    rep->interior_points = dr[0].interior_points + dr[1].interior_points;
    rep->defects = dr[0].defects | dr[1].defects;
    rep->stop = dr[0].stop != PLATEAU_STOP_CONVERGED ? dr[0].stop : dr[1].stop;
    rep->solved = dr[0].solved && dr[1].solved;
    rep->folded_edges = dr[0].folded_edges + dr[1].folded_edges;
    rep->degenerate_triangles = dr[0].degenerate_triangles + dr[1].degenerate_triangles;
    rep->intersecting_pairs = dr[0].intersecting_pairs + dr[1].intersecting_pairs;
    rep->f_initial = dr[0].f_initial + dr[1].f_initial;
    rep->f_final = dr[0].f_final + dr[1].f_final;
    rep->neck_ratio = 0.0;
    rep->discs_returned = 1;
    return PLATEAU_OK;
}

/* Two loops (cfg->alternatives): the other topology, one disc per loop,
 * each loop solved alone with the same options (plateau__cfg_derive's
 * PLATEAU__CFG_DISC: the interior points shared in proportion to the
 * loops' vertices, the time left of the call), and its total area
 * against the least film found (film_least: the rounds' valid film, 0 if
 * none, or the film returned when less); with cfg->least_area the discs
 * replace the film when their area is smaller.  A disc that cannot be solved leaves no
 * alternative (alternative_area 0); running out of memory, the memory
 * limit and the progress callback's abort are errors of the solve. */
static plateau_result plateau__loops_discs(const double *xyz, const size_t *counts,
                                           const plateau__cfg *cfg, const plateau__cfg_run *run,
                                           double film_least, plateau_mesh *mesh, plateau_report *rep,
                                           plateau_error *err)
{
    double left = plateau__util_time_left(run->budget); /* each disc's budget */
    plateau_mesh d[2];
    plateau_report dr[2];
    plateau_error e;
    plateau_result rc = PLATEAU_OK;
    size_t j, m = counts[0] + counts[1];
    double area = 0.0;
    memset(d, 0, sizeof d);
    if (plateau__util_time_up(run->budget)) return PLATEAU_OK; /* options.max_seconds: none */
    for (j = 0; j < 2 && rc == PLATEAU_OK; j++) {
        double share = (double)cfg->n * (double)counts[j] / (double)m;
        const plateau__cfg disc =
            plateau__cfg_derive(cfg, PLATEAU__CFG_DISC, share < 1.0 ? 1 : (size_t)share, left);
        rc = plateau__drv_run(xyz + 3 * (j ? counts[0] : 0), counts + j, 1, counts[j], &disc, &d[j], &dr[j],
                              &e);
        area += dr[j].area;
    }
    /* the least film found: the rounds' (film_least, when a saddle search
     * then moved the mesh to a film of more area) or the one returned */
    if (!(film_least > 0.0 && film_least < rep->area)) film_least = rep->area;
    if (rc == PLATEAU_OK) {
        rep->film_area = rep->area;
        rep->alternative_area = area;
        rep->film_not_least = area < film_least;
        if (cfg->least_area && area < film_least) rc = plateau__loops_merge(d, dr, counts, mesh, rep, err);
    } else if (rc == PLATEAU_ERR_OUT_OF_MEMORY || rc == PLATEAU_ERR_OVERFLOW ||
               rc == PLATEAU_ERR_MEMORY_LIMIT || rc == PLATEAU_ERR_ABORTED) {
        if (err) *err = e;
    } else {
        rc = PLATEAU_OK;
    }
    plateau_mesh_free(&d[0]);
    plateau_mesh_free(&d[1]);
    return rc;
}
#else /* PLATEAU_NO_LOOPS */
/* plateau__drv_solve refused more than one loop: no discs to solve. */
static plateau_result plateau__loops_discs(const double *xyz, const size_t *counts,
                                           const plateau__cfg *cfg, const plateau__cfg_run *run,
                                           double film_least, plateau_mesh *mesh, plateau_report *rep,
                                           plateau_error *err)
{
    (void)xyz, (void)counts, (void)cfg, (void)run, (void)film_least, (void)mesh, (void)rep, (void)err;
    return PLATEAU_OK;
}
#endif /* PLATEAU_NO_LOOPS */
/* ======== END SECTION: several loops ====================================== */

/* ======== SECTION: membranes and cables (plateau__memb_) ================== */
/* A pressure, a held volume or cables (the manual's MEMBRANES): the
 * cable vertices inserted into the polygon before step 1, the membrane's
 * values in the frame, the rounds at a pressure or for a held volume (the
 * Lagrange multiplier by the secant method), the membrane's defects and
 * its report. */
#ifndef PLATEAU_NO_MEMBRANES

/* The parts of a cable edge of chord c at the film's spacing h: max(2,
 * round(c / h)), at most PLATEAU__MEMB_CABLE_PARTS. */
#define PLATEAU__MEMB_CABLE_PARTS 100000
static size_t plateau__memb_cable_parts(double c, double h)
{
    double q = h > 0.0 ? c / h + 0.5 : 2.0;
    if (!(q >= 2.0)) return 2;
    if (!(q <= (double)PLATEAU__MEMB_CABLE_PARTS)) return PLATEAU__MEMB_CABLE_PARTS;
    return (size_t)q;
}

/* The length of the chord from a to b divided by cs. */
static double plateau__memb_cable_chord(const double *a, const double *b, double cs)
{
    double d[3];
    int k;
    for (k = 0; k < 3; k++) d[k] = a[k] / cs - b[k] / cs;
    return plateau__util_norm(d);
}

/* Cables (options.cable_tension): checks each tension (finite, >= 0, and
 * at least half its edge's chord: a cable of tension T pulled by a film of
 * unit tension bends with radius T, and an arc of radius T spans at most
 * 2 T) and inserts into every cable edge (i, next(i)) the free vertices
 * that split it into equal parts at the film's density: the side h of the
 * equilateral triangle of area 2 A / (2 n + m) (the quality seeding's
 * area per triangle, A the largest vector area of a loop).  The polygon
 * with them (s->cable_xyz, s->cable_counts, s->m) goes through steps 1-4
 * (the seeding keeps its edges whole); the cable segments go into run.  Coordinates that are not finite leave
 * everything as it is (step 1 names them). */
static plateau_result plateau__memb_cables(const double *xyz, const size_t *counts, size_t k,
                                           const plateau__cfg *cfg, plateau__cfg_work *s,
                                           plateau__cfg_run *run, plateau_error *err)
{
    const double *T = cfg->cable_tension;
    size_t m = s->m, j, i, off, total = 0, ncab = 0, w, nseg = 0, nvx = 0, c = 0;
    double area = 0.0, h, big = 0.0, cs;
    for (i = 0; i < 3 * m; i++) {
        if (!plateau__util_finite(xyz[i])) return PLATEAU_OK;
        if (PLATEAU_FABS(xyz[i]) > big) big = PLATEAU_FABS(xyz[i]);
    }
    /* lengths and areas on the coordinates divided by the power of two cs
     * at or above the largest (exact): no square over- or underflows in
     * units of 1e100 or 1e-100, and the parts do not depend on the units */
    cs = big > 0.0 ? plateau__util_pow2_at_least(big) : 1.0;
    for (j = 0, off = 0; j < k; off += counts[j], j++) {
        double va[3] = {0.0, 0.0, 0.0};
        for (i = 0; i < counts[j]; i++) {
            double u[3], v[3], x[3];
            int d;
            for (d = 0; d < 3; d++) {
                u[d] = xyz[3 * (off + i) + (size_t)d] / cs - xyz[3 * off + (size_t)d] / cs;
                v[d] = xyz[3 * (off + (i + 1) % counts[j]) + (size_t)d] / cs - xyz[3 * off + (size_t)d] / cs;
            }
            plateau__util_cross(u, v, x);
            va[0] += 0.5 * x[0]; va[1] += 0.5 * x[1]; va[2] += 0.5 * x[2];
        }
        if (plateau__util_norm(va) > area) area = plateau__util_norm(va);
    }
    h = PLATEAU_SQRT(8.0 * area / (PLATEAU_SQRT(3.0) * (2.0 * (double)cfg->n + (double)m)));
    for (j = 0, off = 0; j < k; off += counts[j], j++)
        for (i = 0; i < counts[j]; i++) {
            double t = T[off + i], chord;
            long v[1];
            v[0] = (long)(off + i);
            if (!plateau__util_finite(t) || t < 0.0) {
                plateau__util_error_n(err, PLATEAU_ERR_CABLE, v[0],
                                      "boundary vertex @: the cable's tension is negative or not finite", v, 1);
                return PLATEAU_ERR_CABLE;
            }
            if (t == 0.0) continue;
            chord = plateau__memb_cable_chord(xyz + 3 * (off + i), xyz + 3 * (off + (i + 1) % counts[j]), cs);
            if (!(t / cs >= 0.5 * chord)) {
                plateau__util_error_n(err, PLATEAU_ERR_CABLE, v[0],
                                      "boundary vertex @: the cable's tension is below half its chord: "
                                      "no equilibrium that stays a disc", v, 1);
                return PLATEAU_ERR_CABLE;
            }
            total += plateau__memb_cable_parts(chord, h) - 1;
            ncab++;
        }
    if (ncab == 0) return PLATEAU_OK;
    if (total > (size_t)PLATEAU_INDEX_MAX - m) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many cable vertices", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    s->cable_xyz = (double *)plateau__util_array(&s->alloc, m + total, 3 * sizeof(double));
    s->cable_counts = (size_t *)plateau__util_array(&s->alloc, k, sizeof(size_t));
    s->cable_seg = (plateau_index *)plateau__util_array(&s->alloc, total + ncab, 2 * sizeof(plateau_index));
    s->cable_t = (double *)plateau__util_array(&s->alloc, total + ncab, sizeof(double));
    s->cable_vtx = (plateau_index *)plateau__util_array(&s->alloc, total, sizeof(plateau_index));
    s->cable_anchor = (plateau_index *)plateau__util_array(&s->alloc, ncab, 2 * sizeof(plateau_index));
    if (!s->cable_xyz || !s->cable_counts || !s->cable_seg || !s->cable_t || !s->cable_vtx || !s->cable_anchor) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the cables", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (j = 0, off = 0, w = 0; j < k; off += counts[j], j++) {
        size_t first = w;
        for (i = 0; i < counts[j]; i++) {
            const double *a = xyz + 3 * (off + i), *b = xyz + 3 * (off + (i + 1) % counts[j]);
            size_t parts = 1, q;
            memcpy(s->cable_xyz + 3 * w, a, 3 * sizeof(double));
            if (T[off + i] > 0.0) {
                parts = plateau__memb_cable_parts(plateau__memb_cable_chord(a, b, cs), h);
                s->cable_anchor[2 * c] = (plateau_index)w;
                /* the end anchor: the next vertex, or the loop's first */
                s->cable_anchor[2 * c + 1] =
                    (plateau_index)(i + 1 == counts[j] ? first : w + parts);
                for (q = 0; q < parts; q++) {
                    s->cable_seg[2 * nseg] = (plateau_index)(w + q);
                    s->cable_seg[2 * nseg + 1] = q + 1 < parts ? (plateau_index)(w + q + 1)
                                                               : s->cable_anchor[2 * c + 1];
                    s->cable_t[nseg++] = T[off + i];
                }
                for (q = 1; q < parts; q++) {
                    int d;
                    double f = (double)q / (double)parts;
                    for (d = 0; d < 3; d++) s->cable_xyz[3 * (w + q) + (size_t)d] = a[d] + f * (b[d] - a[d]);
                    s->cable_vtx[nvx++] = (plateau_index)(w + q);
                }
                c++;
            }
            w += parts;
        }
        s->cable_counts[j] = w - first;
    }
    s->cables = ncab;
    s->m = m + total;
    run->cable_seg = s->cable_seg;
    run->cable_t = s->cable_t;
    run->cable_nseg = nseg;
    run->cable_vtx = s->cable_vtx;
    run->cable_nv = nvx;
    return PLATEAU_OK;
}

/* The start of the cable vertices of one polygon: bow = 0 on the chord,
 * else bow times the sag of the arc of radius T (the cable in a flat film)
 * towards the polygon's centroid, across the chord: fewer of the solve's
 * steps (each at most a mean edge length) go to carrying the cable out. */
static void plateau__memb_cable_bow(plateau__cfg_work *s, double bow)
{
    double g[3] = {0.0, 0.0, 0.0};
    size_t i, j, sg = 0;
    int d;
    for (i = 0; i < s->m; i++)
        for (d = 0; d < 3; d++) g[d] += s->cable_xyz[3 * i + (size_t)d] / (double)s->m;
    for (j = 0; j < s->cables; j++) {
        size_t a = (size_t)s->cable_anchor[2 * j], b = (size_t)s->cable_anchor[2 * j + 1], parts = 1, q;
        const double *pa = s->cable_xyz + 3 * a, *pb = s->cable_xyz + 3 * b;
        double e[3], u[3], c, t = s->cable_t[sg], un, half;
        while ((size_t)s->cable_seg[2 * sg + 1] != b) sg++, parts++;
        sg++;
        plateau__util_sub(pb, pa, e);
        c = plateau__util_norm(e);
        for (d = 0; d < 3; d++) {
            e[d] /= c;
            u[d] = g[d] - 0.5 * (pa[d] + pb[d]);
        }
        un = plateau__util_dot(u, e);
        for (d = 0; d < 3; d++) u[d] -= un * e[d];
        un = plateau__util_norm(u);
        if (!(un > 0.0)) un = 1.0, bow = 0.0;
        /* the arc's height over the chord at x, sqrt(T^2 - x^2) - sqrt(T^2 - c^2 / 4),
         * as (c / 2 - x) (c / 2 + x) over the sum of the two roots, each root
         * T sqrt(1 - (x / T)^2): no square of T or c to overflow */
        half = 0.5 * c / t;
        half = t * PLATEAU_SQRT(half < 1.0 ? 1.0 - half * half : 0.0);
        for (q = 1; q < parts; q++) {
            double f = (double)q / (double)parts, x = (f - 0.5) * c, r = x / t;
            double sag = bow * (0.5 * c - x) / (t * PLATEAU_SQRT(1.0 - r * r) + half) * (0.5 * c + x);
            for (d = 0; d < 3; d++)
                s->cable_xyz[3 * (a + q) + (size_t)d] = pa[d] + f * (pb[d] - pa[d]) + sag * u[d] / un;
        }
    }
}

#define PLATEAU__MEMB_CABLE_BOW 0.5

/* Before step 1: the polygon with the cable vertices inserted
 * (plateau__memb_cables, into s); one polygon's cables start half way out
 * along their arcs, unless that makes the polygon fail step 1. */
static plateau_result plateau__memb_polygon(const double *xyz, const size_t *counts, size_t k,
                                            const plateau__cfg *cfg, plateau__cfg_work *s,
                                            plateau__cfg_run *run, plateau_error *err)
{
    plateau_result rc = plateau__memb_cables(xyz, counts, k, cfg, s, run, err);
    if (s->cable_xyz && k == 1) {
        plateau_result bc;
        plateau_error be;
        plateau__memb_cable_bow(s, PLATEAU__MEMB_CABLE_BOW);
        bc = plateau__bnd_check(s->cable_xyz, s->m, &s->alloc, &be);
        /* out of memory is an error, not a polygon that fails step 1 */
        if (bc == PLATEAU_ERR_OUT_OF_MEMORY || bc == PLATEAU_ERR_OVERFLOW) {
            rc = bc;
            if (err) *err = be;
        } else if (bc != PLATEAU_OK)
            plateau__memb_cable_bow(s, 0.0);
    }
    return rc;
}

/* The membrane's values in the frame (lengths divided by its unit), into
 * the run: the pressure times the unit, the volume over its cube, the
 * tensions cable_t over it; the apex, the centroid of the m given vertices
 * xyz (in the caller's units); run->radius, their largest distance from
 * it. */
static void plateau__memb_frame(plateau__cfg_run *run, const plateau__cfg *cfg, const double *xyz,
                                size_t m, const plateau__frame *fr, double *cable_t)
{
    size_t i;
    int d;
    /* the frame may mirror (plateau__frame_make): then the signed
     * volume, and with it the pressure, changes sign in the frame */
    double o = plateau__frame_orientation(fr), u = fr->unit;
    run->orientation = o;
    run->pressure = cfg->pressure * (o * u);
    run->volume = o * cfg->volume / u / u / u;
    for (i = 0; i < run->cable_nseg && cable_t; i++) cable_t[i] /= u;
    run->apex[0] = run->apex[1] = run->apex[2] = 0.0;
    for (i = 0; i < m; i++) {
        double q[3];
        plateau__frame_to(fr, xyz + 3 * i, 1, q);
        for (d = 0; d < 3; d++) run->apex[d] += q[d] / (double)m;
    }
    run->radius = 0.0;
    for (i = 0; i < m; i++) {
        double q[3], r;
        plateau__frame_to(fr, xyz + 3 * i, 1, q);
        r = PLATEAU_SQRT(plateau__bnd_dist2_3(q, run->apex));
        if (r > run->radius) run->radius = r;
    }
}

/* report.volume in the caller's units, computed there: the cone from the
 * centroid of xyz (m vertices: the given boundary) over the mesh.  Where
 * that leaves a double's range (a cone term above DBL_MAX: inf - inf), the
 * volume of the frame (rep->volume on entry) times unit^3, as significand
 * and exponent (the area's representation, plateau__frame_restore). */
static void plateau__memb_volume(plateau_mesh *mesh, const double *xyz, size_t m, double unit,
                                 plateau_report *rep)
{
    double apex[3] = {0.0, 0.0, 0.0}, vf = rep->volume, v, a, mu;
    size_t i;
    int d, e = 0, eu = 0, t;
    for (i = 0; i < m; i++)
        for (d = 0; d < 3; d++) apex[d] += xyz[3 * i + (size_t)d] / (double)m;
    v = plateau_mesh_volume(mesh, apex, NULL);
    rep->volume_significand = 0.0;
    rep->volume_exponent = 0;
    if (plateau__util_finite(v) && (v == 0.0 || PLATEAU_FABS(v) >= 2.2250738585072014e-308)) {
        rep->volume = v;
        if (v != 0.0) rep->volume_significand = plateau__frame_frexp(PLATEAU_FABS(v), &rep->volume_exponent);
        if (v < 0.0) rep->volume_significand = -rep->volume_significand;
    } else if (vf != 0.0 && plateau__util_finite(vf) && unit > 0.0) {
        a = plateau__frame_frexp(PLATEAU_FABS(vf), &e);
        mu = plateau__frame_frexp(unit, &eu);
        for (d = 0; d < 3; d++) { /* V = V_frame unit^3, one factor at a time */
            a = plateau__frame_frexp(a * mu, &t);
            e += t + eu;
        }
        rep->volume_significand = a;
        rep->volume_exponent = e;
        rep->volume = plateau__frame_ldexp(a, e);
        rep->range |= plateau__util_finite(rep->volume) ? PLATEAU_RANGE_VOLUME_UNDERFLOW : PLATEAU_RANGE_VOLUME_OVERFLOW;
        if (vf < 0.0) {
            rep->volume_significand = -a;
            rep->volume = -rep->volume;
        }
    } else {
        rep->volume = v;
    }
}

/* The sphere that every sphere of curvature p (radius 2 / |p|) through
 * the boundary lies in, about the apex: radius R_b + 4 / |p|; 0 for p = 0
 * (a film without pressure lies in the boundary's convex hull). */
static double plateau__memb_reach(const plateau__cfg_run *run, double p)
{
    return p != 0.0 ? run->radius + 4.0 / PLATEAU_FABS(p) : 0.0;
}

/* A cable segment that passes through a triangle that shares no vertex
 * with it: 1 (the final check's PLATEAU_DEFECT_CABLE). */
static int plateau__memb_cable_crosses(const plateau_mesh *mesh, const plateau__cfg_run *run)
{
    size_t sg, t;
    for (sg = 0; sg < run->cable_nseg; sg++) {
        plateau_index a = run->cable_seg[2 * sg], b = run->cable_seg[2 * sg + 1];
        const double *p = plateau__geo_pos(mesh, a), *q = plateau__geo_pos(mesh, b);
        for (t = 0; t < mesh->num_triangles; t++) {
            const plateau_index *tr = mesh->triangles + 3 * t;
            int d, apart = 0;
            if (tr[0] == a || tr[1] == a || tr[2] == a || tr[0] == b || tr[1] == b || tr[2] == b) continue;
            for (d = 0; d < 3 && !apart; d++) {
                double lo = p[d] < q[d] ? p[d] : q[d], hi = p[d] < q[d] ? q[d] : p[d];
                double x0 = plateau__geo_pos(mesh, tr[0])[d], x1 = plateau__geo_pos(mesh, tr[1])[d];
                double x2 = plateau__geo_pos(mesh, tr[2])[d];
                apart = (x0 < lo && x1 < lo && x2 < lo) || (x0 > hi && x1 > hi && x2 > hi);
            }
            if (!apart && plateau__chk_seg_tri(p, q, plateau__geo_pos(mesh, tr[0]),
                                               plateau__geo_pos(mesh, tr[1]), plateau__geo_pos(mesh, tr[2])))
                return 1;
        }
    }
    return 0;
}

/* A cable vertex is in equilibrium when the cable's pull T (u_a + u_b)
 * balances the film's (minus the energy gradient's film part): the
 * energy gradient at it, per unit of its cable length (half its two
 * segments), in the frame where the polygon's size is about 1.  Above
 * this the cables are left out of balance (the film between two cables
 * that would cross pinches, and the solver stops there): NO_EQUILIBRIUM.
 * Converged cables measure below 1e-6 (tests/test_membrane.c). */
#define PLATEAU__MEMB_CABLE_BALANCE 1e-2

/* The largest out-of-balance force per unit length of the free cable
 * vertices (see PLATEAU__MEMB_CABLE_BALANCE); -1 when out of memory. */
static double plateau__memb_cable_imbalance(const plateau_mesh *mesh, const plateau__cfg_run *run)
{
    double *g = (double *)plateau__util_array(&mesh->allocator, mesh->num_vertices, 4 * sizeof(double));
    double *len, worst = 0.0;
    size_t sg, v;
    if (!g) return -1.0;
    len = g + 3 * mesh->num_vertices;
    (void)plateau_membrane_energy(mesh, run->pressure, run->apex, run->cable_seg, run->cable_t,
                                  run->cable_nseg, g);
    for (v = 0; v < mesh->num_vertices; v++) len[v] = 0.0;
    for (sg = 0; sg < run->cable_nseg; sg++) {
        plateau_index a = run->cable_seg[2 * sg], b = run->cable_seg[2 * sg + 1];
        double d[3], l;
        plateau__util_sub(plateau__geo_pos(mesh, a), plateau__geo_pos(mesh, b), d);
        l = plateau__util_norm(d);
        len[a] += 0.5 * l;
        len[b] += 0.5 * l;
    }
    for (v = 0; v < mesh->num_vertices; v++)
        if (!mesh->fixed[v] && len[v] > 0.0) {
            double f = plateau__util_norm(g + 3 * v) / len[v];
            if (!(f <= worst)) worst = f; /* NaN counts as out of balance */
        }
    plateau__free(&mesh->allocator, g);
    return worst;
}

/* The film of pressure p has run away: a vertex beyond plateau__memb_reach
 * from the apex, where no film of that pressure reaches (NO_EQUILIBRIUM). */
static int plateau__memb_ran_away(const plateau_mesh *mesh, const plateau__cfg_run *run, double p)
{
    double reach = plateau__memb_reach(run, p);
    size_t i;
    for (i = 0; i < mesh->num_vertices && reach > 0.0; i++)
        if (plateau__bnd_dist2_3(plateau__geo_pos(mesh, (plateau_index)i), run->apex) > reach * reach) return 1;
    return 0;
}

/* No film of pressure p spans the mesh's boundary when |p| |A| > L, A the
 * boundary's vector area (the sum of the triangles' vector areas: that of
 * any surface on it) and L its length: the balancing (flux) formula of a
 * surface of constant mean curvature H = p / 2, the conormal's integral
 * over the boundary equal to p A, bounds |p| |A| by L (Kusner, "Global
 * geometry of extremal surfaces in three-space", 1988; for a circle of
 * radius R, Heinz's |p| R <= 2).  Method paper's H_i = p then stalls
 * short of a root rather than running away: this names why.  1 when the
 * bound excludes p (a relative margin of 1e-9 for rounding). */
static int plateau__memb_flux_excludes(const plateau_mesh *mesh, double p)
{
    double A[3] = {0.0, 0.0, 0.0}, L = 0.0, an;
    size_t t, e;
    int k;
    for (t = 0; t < mesh->num_triangles; t++) {
        double n[3];
        const plateau_index *tv = mesh->triangles + 3 * t;
        plateau__util_corner_cross(plateau__geo_pos(mesh, tv[0]), plateau__geo_pos(mesh, tv[1]),
                                   plateau__geo_pos(mesh, tv[2]), n);
        for (k = 0; k < 3; k++) A[k] += 0.5 * n[k];
    }
    for (e = 0; e < mesh->num_edges; e++)
        if (mesh->edge_triangles[2 * e] < 0 || mesh->edge_triangles[2 * e + 1] < 0)
            L += PLATEAU_SQRT(plateau__bnd_dist2_3(plateau__geo_pos(mesh, mesh->edges[2 * e]),
                                                   plateau__geo_pos(mesh, mesh->edges[2 * e + 1])));
    an = PLATEAU_SQRT(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]);
    return PLATEAU_FABS(p) * an > L * (1.0 + 1e-9);
}

/* The multiplier's iteration (options.fix_volume): at most this many
 * solves, until |V - V0| <= PLATEAU__MEMB_VOLUME_TOL times the area^(3/2). */
#define PLATEAU__MEMB_VOLUME_SOLVES 40
#define PLATEAU__MEMB_VOLUME_TOL 1e-7
/* A solve of the multiplier's iteration that ends with defects beyond V0
 * (a film run away or folded at a pressure the secant overshot to) is
 * undone, at most this many times: the last film without defects back,
 * and the pressure half way back to its. */
#define PLATEAU__MEMB_VOLUME_BACKS 8

/* The largest |pressure| times the polygon's radius (about the boundary's
 * size) that a membrane solve takes: a film spans its boundary only up to
 * about |p| R = 2 (a hemisphere; beyond, NO_EQUILIBRIUM), and from about
 * 1e154 the Newton system at the flat start overflows, so the film would
 * not move at all and look valid. */
#define PLATEAU__MEMB_PRESSURE_MAX 1e100

/* Steps 5-6 and the final check of a membrane (a plain film's are
 * plateau__drv_rounds), in the frame fr: first the membrane's values in
 * it (plateau__memb_frame, from the m given vertices xyz and the tensions
 * cable_t) and the cable vertices freed.  With a pressure, the rounds at
 * that pressure.
 * With fix_volume, the Lagrange multiplier p of V = V0 by the secant
 * method on V(p), each V(p) the rounds at pressure p from the last mesh
 * (the first step from p0 = options.pressure takes dV/dp = A^2 / (8 pi),
 * a flat disc's); a solve that overshoots V0 and ends with defects or
 * runs away is undone (the last film without them back, p half way back
 * to its; before there is such a film, the start back and p half way to
 * 0) up to PLATEAU__MEMB_VOLUME_BACKS times; report.pressure is the last p.  Then the membrane's
 * defects: the film beyond plateau__memb_reach (NO_EQUILIBRIUM: no film of
 * that pressure spans the boundary, and the line searches held it at
 * twice that distance), the volume missed (VOLUME), a cable through the
 * film (CABLE). */
static plateau_result plateau__memb_solve(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          plateau__cfg_run *run, const double *xyz, size_t m,
                                          const plateau__frame *fr, double *cable_t,
                                          const plateau__retri_domain *dom, plateau_report *rep,
                                          plateau_error *err)
{
    /* V(p) of a held volume must be exact: its solves run to their gradient
     * test (PLATEAU__CFG_HELD_VOLUME_TOL) */
    const plateau__cfg c =
        cfg->fix_volume ? plateau__cfg_derive(cfg, PLATEAU__CFG_HELD_VOLUME, 0, 0.0) : *cfg;
    plateau__cfg_run r; /* the run at the pressure of the solve */
    plateau_result rc = PLATEAU_OK;
    plateau_mesh good; /* fix_volume: the last film without defects */
    plateau_mesh start; /* fix_volume: the mesh before the first solve */
    double v = 0.0, pp = 0.0, vp = 0.0, pg = 0.0, vg = 0.0, pm = 0.0;
    int it, met = 1, backs = 0, have_good = 0, have_prev = 0;
    plateau__memb_frame(run, cfg, xyz, m, fr, cable_t);
    plateau__solve_hold_cables(mesh, run, 0); /* step 4 fixed the polygon's cable vertices: free */
    r = *run;
    if (!(PLATEAU_FABS(run->pressure) * run->radius <= PLATEAU__MEMB_PRESSURE_MAX)) {
        /* (in the frame, where the polygon's radius is about 1) */
        plateau__util_error(err, PLATEAU_ERR_PRESSURE, -1,
                            "the pressure times the polygon's radius is above 1e100: no film carries such a "
                            "pressure, and the solver's arithmetic would overflow", 0, 0);
        return PLATEAU_ERR_PRESSURE;
    }
    memset(&good, 0, sizeof good);
    memset(&start, 0, sizeof start);
    if (cfg->fix_volume) {
        rc = plateau_mesh_create(mesh->positions, mesh->num_vertices, mesh->fixed, mesh->triangles,
                                 mesh->num_triangles, &mesh->allocator, &start, err);
        if (rc != PLATEAU_OK) return rc;
    }
    for (it = 0; it < (cfg->fix_volume ? PLATEAU__MEMB_VOLUME_SOLVES : 1); it++) {
        double a, step;
        int broken;
        r.escape = 2.0 * plateau__memb_reach(&r, r.pressure);
        rc = plateau__drv_rounds(mesh, &c, &r, dom, rep, err);
        if (rc != PLATEAU_OK) break;
        v = plateau_mesh_volume(mesh, r.apex, NULL);
        pm = r.pressure;
        if (!cfg->fix_volume) break;
        a = plateau_mesh_area(mesh);
        met = PLATEAU_FABS(v - r.volume) <= PLATEAU__MEMB_VOLUME_TOL * a * PLATEAU_SQRT(a);
        if (met) break;
        broken = rep->defects || plateau__memb_ran_away(mesh, &r, r.pressure);
        if (broken && have_good && backs < PLATEAU__MEMB_VOLUME_BACKS &&
            it + 1 < PLATEAU__MEMB_VOLUME_SOLVES && (v - r.volume) * (vg - r.volume) < 0.0) {
            /* the step overshot V0 and the film broke down: undone, the
             * last good film and half the step (the secant then runs
             * from that film's p and V, pp and vp) */
            backs++;
            plateau_mesh_free(mesh);
            rc = plateau_mesh_create(good.positions, good.num_vertices, good.fixed, good.triangles,
                                     good.num_triangles, &good.allocator, mesh, err);
            if (rc != PLATEAU_OK) break;
            pm = pg;
            v = vg;
            r.pressure = 0.5 * (r.pressure + pg);
            continue;
        }
        if (broken && !have_good && r.pressure != 0.0 && backs < PLATEAU__MEMB_VOLUME_BACKS &&
            it + 1 < PLATEAU__MEMB_VOLUME_SOLVES) {
            /* no film yet, and the first guess broke it down (a pressure
             * no film of this boundary carries: p > 2 on the unit
             * circle): the start back and the pressure half way to 0,
             * where a film always spans */
            backs++;
            plateau_mesh_free(mesh);
            rc = plateau_mesh_create(start.positions, start.num_vertices, start.fixed, start.triangles,
                                     start.num_triangles, &start.allocator, mesh, err);
            if (rc != PLATEAU_OK) break;
            r.pressure *= 0.5;
            continue;
        }
        if (!broken) {
            plateau_mesh_free(&good);
            rc = plateau_mesh_create(mesh->positions, mesh->num_vertices, mesh->fixed, mesh->triangles,
                                     mesh->num_triangles, &mesh->allocator, &good, err);
            if (rc != PLATEAU_OK) break;
            have_good = 1;
            pg = r.pressure;
            vg = v;
        }
        step = have_prev && v != vp ? (r.pressure - pp) / (v - vp) : 8.0 * PLATEAU__PI / (a * a);
        pp = r.pressure;
        vp = v;
        have_prev = 1;
        r.pressure += (r.volume - v) * step;
        if (!plateau__util_finite(r.pressure)) break;
    }
    plateau_mesh_free(&good);
    plateau_mesh_free(&start);
    if (rc != PLATEAU_OK) return rc;
    /* the pressure of the film returned (not the next one the secant asked for) */
    rep->pressure = pm * run->orientation / run->unit; /* the caller's units */
    rep->volume = v; /* in the frame until plateau__memb_volume */
    if (plateau__memb_ran_away(mesh, &r, pm)) rep->defects |= PLATEAU_DEFECT_NO_EQUILIBRIUM;
    if (!cfg->fix_volume && run->cable_nseg == 0 && plateau__memb_flux_excludes(mesh, pm))
        rep->defects |= PLATEAU_DEFECT_NO_EQUILIBRIUM;
    if (run->cable_nseg > 0) {
        double imbalance;
        r.pressure = pm; /* the film's, not the next the secant asked for */
        imbalance = plateau__memb_cable_imbalance(mesh, &r);
        if (imbalance < 0.0) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in the cables' balance", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        if (!(imbalance <= PLATEAU__MEMB_CABLE_BALANCE)) rep->defects |= PLATEAU_DEFECT_NO_EQUILIBRIUM;
    }
    if (!met) rep->defects |= PLATEAU_DEFECT_VOLUME;
    if (run->cable_nseg > 0 && plateau__memb_cable_crosses(mesh, run)) rep->defects |= PLATEAU_DEFECT_CABLE;
    if (rep->defects && rep->stop == PLATEAU_STOP_CONVERGED) rep->stop = PLATEAU_STOP_DEFECTS;
    return PLATEAU_OK;
}

/* The cables' measures in the caller's units (after the frame): length,
 * and sag, the largest distance of a cable vertex from its chord. */
static void plateau__memb_cable_report(const plateau_mesh *mesh, const plateau__cfg_work *s, size_t nseg,
                                       double scale, plateau_report *rep)
{
    size_t j, sg = 0;
    rep->cables = s->cables;
    rep->cable_vertices = 0;
    for (j = 0; j < s->cables; j++) {
        plateau_index a = s->cable_anchor[2 * j], b = s->cable_anchor[2 * j + 1];
        plateau_cable_result r;
        memset(&r, 0, sizeof r);
        r.anchor = (size_t)a;
        r.tension = s->cable_t[sg] * scale;
        while (sg < nseg) {
            plateau_index u = s->cable_seg[2 * sg], w = s->cable_seg[2 * sg + 1];
            r.length += PLATEAU_SQRT(plateau__bnd_dist2_3(plateau__geo_pos(mesh, u), plateau__geo_pos(mesh, w)));
            if (u != a) {
                double d = PLATEAU_SQRT(plateau__bnd_seg_dist2_3(plateau__geo_pos(mesh, u),
                                                                 plateau__geo_pos(mesh, a),
                                                                 plateau__geo_pos(mesh, b)));
                if (d > r.sag) r.sag = d;
                r.vertices++;
            }
            sg++;
            if (w == b) break;
        }
        rep->cable_vertices += r.vertices;
        if (j < PLATEAU_REPORT_CABLES) rep->cable[j] = r;
    }
}

/* After the frame: the membrane's measures in the caller's units, the
 * volume (xyz: the m given vertices) and, with s, the cables' (nseg
 * segments, tensions back from the frame by its unit). */
static void plateau__memb_report(plateau_mesh *mesh, const double *xyz, size_t m,
                                 const plateau__cfg_work *s, size_t nseg, double unit, plateau_report *rep)
{
    plateau__memb_volume(mesh, xyz, m, unit, rep);
    if (s && s->cables) plateau__memb_cable_report(mesh, s, nseg, unit, rep);
}
#else /* PLATEAU_NO_MEMBRANES */
/* plateau__cfg_resolve refused a pressure, a volume and cables: the
 * driver never asks for a membrane. */
static plateau_result plateau__memb_polygon(const double *xyz, const size_t *counts, size_t k,
                                            const plateau__cfg *cfg, plateau__cfg_work *s,
                                            plateau__cfg_run *run, plateau_error *err)
{
    (void)xyz, (void)counts, (void)k, (void)cfg, (void)s, (void)run;
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, PLATEAU__CFG_NO_MEMBRANES, 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

static plateau_result plateau__memb_solve(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          plateau__cfg_run *run, const double *xyz, size_t m,
                                          const plateau__frame *fr, double *cable_t,
                                          const plateau__retri_domain *dom, plateau_report *rep,
                                          plateau_error *err)
{
    (void)mesh, (void)cfg, (void)run, (void)xyz, (void)m, (void)fr, (void)cable_t, (void)dom, (void)rep;
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, PLATEAU__CFG_NO_MEMBRANES, 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

static void plateau__memb_report(plateau_mesh *mesh, const double *xyz, size_t m,
                                 const plateau__cfg_work *s, size_t nseg, double unit, plateau_report *rep)
{
    (void)mesh, (void)xyz, (void)m, (void)s, (void)nseg, (void)unit, (void)rep;
}
#endif /* PLATEAU_NO_MEMBRANES */
/* ======== END SECTION: membranes and cables =============================== */

/* ======== SECTION: coarse to fine (plateau__c2f_) ========================= */
/* From PLATEAU_COARSE_TO_FINE_POINTS interior points (the manual's
 * COARSE TO FINE): a coarse mesh solved by method area's rounds, then
 * 1-to-4 subdivisions, each followed by Newton's method on normal motions,
 * and method paper's H_i = 0 at the finest level. */
#ifndef PLATEAU_NO_COARSE_TO_FINE

/* Level counts: a coarse mesh of at least PLATEAU__C2F_COARSE_MIN interior
 * points, at most PLATEAU__C2F_MAX_LEVELS subdivisions. */
#define PLATEAU__C2F_COARSE_MIN 16
#define PLATEAU__C2F_MAX_LEVELS 10
/* Rounds of plain area flips and a re-solve on the coarse mesh; they also
 * end at a round that lowers the area by less than PLATEAU__DRV_ROUND_DROP
 * of it (the rounds' own rule). */
#define PLATEAU__C2F_COARSE_FLIP_ROUNDS 8
/* The coarse seeding is redone with a corrected count at most this many
 * times while the finest level's interior count I_L would miss n by more
 * than PLATEAU__C2F_COUNT_SLACK of n. */
#define PLATEAU__C2F_RESEEDS 3
#define PLATEAU__C2F_COUNT_SLACK 0.03

/* The interior count I_0 whose L subdivisions have n interior vertices on a
 * boundary of b vertices: L 1-to-4 subdivisions of a disk of I interior and
 * B boundary vertices give I_L = 4^L I + B (4^L - 2^L) / 2 - (4^L - 1)
 * (each level I' = 4 I + B - 3, B' = 2 B, by Euler's formula), solved for I. */
static double plateau__c2f_coarse(double n, double b, int levels)
{
    double p4 = 1.0, p2 = 1.0;
    int k;
    for (k = 0; k < levels; k++) {
        p4 *= 4.0;
        p2 *= 2.0;
    }
    return (n + (p4 - 1.0) - b * (p4 - p2) / 2.0) / p4;
}

#endif /* PLATEAU_NO_COARSE_TO_FINE: the subdivision stays (the error estimate's too) */

#if !defined(PLATEAU_NO_COARSE_TO_FINE) || !defined(PLATEAU_NO_ACCURACY)

/* 1-to-4 subdivision of the mesh, in place: a vertex on every edge, on a
 * boundary edge at its midpoint (fixed: the polygon's straight edges stay
 * where they are), on an interior edge (a, b) at the midpoint of the cubic
 * through a and b whose tangents lie in their tangent planes (unit vertex
 * normals n_a, n_b; the Bezier edge of "PN triangles", Vlachos et al. 2001),
 *     p = (a + b) / 2 - ((b - a).n_a n_a + (a - b).n_b n_b) / 8,
 * O(h^3) off a smooth surface where the chord's midpoint is O(h^2) off.
 * Triangle (a, b, c) with edge vertices ab, bc, ca becomes (a, ab, ca),
 * (ab, b, bc), (ca, bc, c), (ab, bc, ca).  The new order: the fixed
 * vertices as they were, the new boundary vertices (edge order), the free
 * vertices as they were, the new interior ones, so the first vertices stay
 * the polygon.  orig (3 * nfixed: the fixed vertices in the caller's units)
 * is replaced by a new array with the new boundary vertices appended at the
 * midpoints of their edges' ends in those units (*nfixed updated).
 * flat: every new vertex at its edge's midpoint (the same surface, split
 * finer: the error estimate's mesh). */
static plateau_result plateau__c2f_subdivide(plateau_mesh *mesh, double **orig, size_t *nfixed,
                                             int own_orig, int flat, plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, ne = mesh->num_edges, nt = mesh->num_triangles, v, e, t;
    size_t nf = 0, nb = 0, kf = 0, kb, kv, ki;
    plateau_index *map = NULL, *tri = NULL;
    double *pos = NULL, *nrm = NULL, *no = NULL;
    unsigned char *fixed = NULL;
    plateau_mesh out;
    plateau_result rc = PLATEAU_ERR_OUT_OF_MEMORY;
    if (ne > (size_t)PLATEAU_INDEX_MAX - nv) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "a subdivided mesh has too many vertices", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    for (v = 0; v < nv; v++) nf += mesh->fixed[v] != 0;
    for (e = 0; e < ne; e++) nb += mesh->edge_triangles[2 * e] < 0 || mesh->edge_triangles[2 * e + 1] < 0;
    map = (plateau_index *)plateau__util_array(al, nv + ne, sizeof(plateau_index));
    pos = (double *)plateau__util_array(al, nv + ne, 3 * sizeof(double));
    nrm = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
    fixed = (unsigned char *)plateau__util_array(al, nv + ne, 1);
    tri = (plateau_index *)plateau__util_array(al, nt, 12 * sizeof(plateau_index));
    no = (double *)plateau__util_array(al, nf + nb, 3 * sizeof(double));
    if (map && pos && nrm && fixed && tri && no && nf == *nfixed) {
        /* new indices: old vertex v -> map[v], edge e -> map[nv + e] */
        kb = nf;
        kv = nf + nb;
        ki = nf + nb + (nv - nf);
        for (v = 0; v < nv; v++) map[v] = (plateau_index)(mesh->fixed[v] ? kf++ : kv++);
        memcpy(no, *orig, 3 * nf * sizeof(double));
        for (v = 0; v < nv; v++) plateau_vertex_normal(mesh, v, nrm + 3 * v);
        for (v = 0; v < nv; v++) {
            memcpy(pos + 3 * (size_t)map[v], mesh->positions + 3 * v, 3 * sizeof(double));
            fixed[map[v]] = mesh->fixed[v];
        }
        for (e = 0; e < ne; e++) {
            size_t a = (size_t)mesh->edges[2 * e], b = (size_t)mesh->edges[2 * e + 1], j;
            int boundary = mesh->edge_triangles[2 * e] < 0 || mesh->edge_triangles[2 * e + 1] < 0, c;
            const double *pa = mesh->positions + 3 * a, *pb = mesh->positions + 3 * b;
            double *p, d[3], wa, wb;
            j = boundary ? kb++ : ki++;
            map[nv + e] = (plateau_index)j;
            p = pos + 3 * j;
            fixed[j] = (unsigned char)boundary;
            for (c = 0; c < 3; c++) p[c] = 0.5 * (pa[c] + pb[c]);
            if (boundary) {
                /* in the caller's units, from the ends' own coordinates there
                 * (halved first: the sum of two coordinates near DBL_MAX
                 * would overflow; the same bits otherwise) */
                const double *oa = *orig + 3 * (size_t)map[a], *ob = *orig + 3 * (size_t)map[b];
                for (c = 0; c < 3; c++) no[3 * j + (size_t)c] = 0.5 * oa[c] + 0.5 * ob[c];
                continue;
            }
            if (flat) continue; /* the chord's midpoint: the same surface */
            plateau__util_sub(pb, pa, d);
            wa = plateau__util_dot(d, nrm + 3 * a);
            wb = -plateau__util_dot(d, nrm + 3 * b);
            for (c = 0; c < 3; c++) p[c] -= (wa * nrm[3 * a + (size_t)c] + wb * nrm[3 * b + (size_t)c]) / 8.0;
        }
        for (t = 0; t < nt; t++) {
            const plateau_index *tv = mesh->triangles + 3 * t;
            plateau_index a = map[tv[0]], b = map[tv[1]], c = map[tv[2]], q[3], *o = tri + 12 * t;
            int k;
            for (k = 0; k < 3; k++) q[k] = map[nv + (size_t)mesh->triangle_edges[3 * t + (size_t)k]];
            /* q[k] lies on the edge (v_k, v_(k+1)) */
            o[0] = a; o[1] = q[0]; o[2] = q[2];
            o[3] = q[0]; o[4] = b; o[5] = q[1];
            o[6] = q[2]; o[7] = q[1]; o[8] = c;
            o[9] = q[0]; o[10] = q[1]; o[11] = q[2];
        }
        rc = plateau_mesh_create(pos, nv + ne, fixed, tri, 4 * nt, al, &out, err);
    } else if (nf != *nfixed) {
        rc = PLATEAU_ERR_ARGUMENT; /* an internal mismatch, never expected */
    }
    if (rc == PLATEAU_OK) {
        plateau_mesh_free(mesh);
        *mesh = out;
        if (own_orig) plateau__free(al, *orig);
        *orig = no;
        *nfixed = nf + nb;
        no = NULL;
    } else if (rc == PLATEAU_ERR_OUT_OF_MEMORY || rc == PLATEAU_ERR_ARGUMENT) {
        plateau__util_error(err, rc, -1, rc == PLATEAU_ERR_ARGUMENT ? "subdivision: the fixed vertices do not match"
                                                                     : "out of memory in a subdivision", 0, 0);
    }
    plateau__free(al, map);
    plateau__free(al, pos);
    plateau__free(al, nrm);
    plateau__free(al, fixed);
    plateau__free(al, tri);
    plateau__free(al, no);
    return rc;
}
#endif /* the subdivision: coarse to fine or the error estimate */

#ifndef PLATEAU_NO_COARSE_TO_FINE
/* The number of subdivisions coarse to fine takes for this solve (0: the
 * rounds at full size) and the coarse count *n0: L the largest with I_0 >=
 * PLATEAU__C2F_COARSE_MIN for n and the m polygon vertices, I_0 rounded
 * (so that I_L is the closest to n).  Whether it applies: see
 * plateau_options.coarse_to_fine. */
static int plateau__c2f_plan(const plateau__cfg_work *s, const plateau__cfg *cfg, size_t *n0)
{
    int levels = 0;
    double i0;
    if (cfg->coarse_to_fine == PLATEAU_OFF || s->loops > 1 ||
        (cfg->method != PLATEAU_METHOD_AREA && cfg->method != PLATEAU_METHOD_PAPER) ||
        cfg->seeding == PLATEAU_SEEDING_PAPER || cfg->quality_edge_length > 0.0 ||
        cfg->refine_boundary == PLATEAU_OFF)
        return 0;
    if (cfg->coarse_to_fine == PLATEAU_AUTO &&
        (s->n < PLATEAU_COARSE_TO_FINE_POINTS || cfg->linear_solver != PLATEAU_LINEAR_AUTO ||
         (cfg->refine_boundary == PLATEAU_AUTO && !plateau__seed_refine_auto(s, s->n, 0.0))))
        return 0;
    while (levels < PLATEAU__C2F_MAX_LEVELS &&
           plateau__c2f_coarse((double)s->n, (double)s->m, levels + 1) >= (double)PLATEAU__C2F_COARSE_MIN)
        levels++;
    i0 = plateau__c2f_coarse((double)s->n, (double)s->m, levels);
    *n0 = (size_t)(i0 + 0.5);
    return levels;
}

/* Undoes steps 3-4 (the coarse mesh had defects): the triangulation, the
 * boundary vertices added, the mesh and the report. */
static void plateau__c2f_reset(plateau__cfg_work *s, plateau_mesh *mesh, plateau_report *rep)
{
    plateau_report keep = *rep;
    plateau_dt_free(&s->dt);
    memset(&s->dt, 0, sizeof s->dt);
    plateau__free(&s->alloc, s->orig);
    s->orig = NULL;
    s->k = 0;
    plateau_mesh_free(mesh);
    memset(rep, 0, sizeof *rep);
    rep->method = keep.method;
    rep->domain = keep.domain;
    rep->loops = keep.loops;
}

/* The coarse mesh: steps 3-4 for n0 points with the polygon's edges
 * refined, method area's solve (the sparse Newton method, one round, to
 * PLATEAU__CFG_COARSE_TOL), then up to PLATEAU__C2F_COARSE_FLIP_ROUNDS
 * rounds of plain area flips and a re-solve while flips happen and a
 * round lowers the area by PLATEAU__DRV_ROUND_DROP of it.  n and levels:
 * the finest level's count asked and the subdivisions to come.  *ok = 0 when the result has defects
 * (plateau_mesh_check): subdivision would keep them; also, before the
 * solve, when the finest level would have more than
 * PLATEAU__C2F_COUNT_SLACK too many points. */
static plateau_result plateau__c2f_coarse_mesh(plateau__cfg_work *s, const plateau__cfg *cfg,
                                               const plateau__cfg_run *run, size_t n, int levels,
                                               size_t n0, double scale,
                                               plateau_mesh *mesh, plateau_report *rep, int *ok,
                                               plateau_error *err)
{
    const plateau__cfg cc = plateau__cfg_derive(cfg, PLATEAU__CFG_COARSE, 0, 0.0);
    plateau_quality q;
    plateau_result rc;
    size_t nv = 0, flips = 0;
    double solved, over = 0.0;
    int r;
    *ok = 0;
    for (r = 0;; r++) {
        /* the seeding makes about n0 points and adds k boundary ones: the
         * coarse count again from the mesh's own B = m + k, at most
         * PLATEAU__C2F_RESEEDS times, while I_L misses n by more than
         * PLATEAU__C2F_COUNT_SLACK of it */
        double il, p4 = 1.0;
        int k;
        s->n = n0;
        rc = plateau__cdt_step(s, &cc, run, scale, mesh, rep, &nv, err);
        if (rc != PLATEAU_OK) return rc;
        il = plateau__c2f_coarse((double)n, (double)(s->m + s->k), levels);
        for (k = 0; k < levels; k++) p4 *= 4.0;
        il = (double)(nv - s->m - s->k) - il; /* the coarse points too many */
        over = il * p4;
        if (r == PLATEAU__C2F_RESEEDS || PLATEAU_FABS(over) <= PLATEAU__C2F_COUNT_SLACK * (double)n ||
            !(il < (double)n0 - (double)PLATEAU__C2F_COARSE_MIN))
            break;
        plateau__c2f_reset(s, mesh, rep);
        n0 = (size_t)((double)n0 - il + 0.5);
    }
    /* I_L still more than PLATEAU__C2F_COUNT_SLACK of n above it (the
     * seeding split the polygon's edges so often that even the least
     * coarse count overshoots: every boundary vertex adds (4^L - 2^L) / 2
     * interior ones): one level fewer, *ok = 0 */
    if (over > PLATEAU__C2F_COUNT_SLACK * (double)n && levels > 1) return PLATEAU_OK;
    rc = plateau__drv_rounds_of(mesh, &cc, run, NULL, rep, err);
    solved = rep->area;
    for (r = 0; r < PLATEAU__C2F_COARSE_FLIP_ROUNDS && rc == PLATEAU_OK; r++) {
        int rounds = (int)rep->rounds;
        rc = plateau__retri_flip_sweeps(mesh, PLATEAU__RETRI_FLIP_AREA_PLAIN, 0, &flips, err);
        if (rc != PLATEAU_OK || flips == 0) break;
        rep->flips += flips;
        rc = plateau__drv_rounds_of(mesh, &cc, run, NULL, rep, err);
        rep->rounds += (size_t)rounds;
        if (rc != PLATEAU_OK || !plateau__util_lower(rep->area, solved, PLATEAU__DRV_ROUND_DROP)) break;
        solved = rep->area;
    }
    if (rc != PLATEAU_OK) return rc;
    rc = plateau_mesh_check(mesh, &q, err);
    if (rc != PLATEAU_OK) return rc;
    *ok = q.defects == 0 && rep->area_stop != PLATEAU_AREA_STOP_LINE_SEARCH;
    return PLATEAU_OK;
}

/* ---- Newton's method on normal motions: the levels' solve ----
 * The levels of the coarse-to-fine path (plateau__c2f_levels) solve on a
 * mesh that is already close to the surface (the previous level's result,
 * subdivided), so only the normal position of each vertex is wrong to
 * first order: one unknown t_v per free vertex, x_v + t_v m_v with m_v its
 * unit vertex normal frozen for the step (Surface Evolver's hessian_normal),
 * and a scalar Cholesky factor of the area's Hessian on the free vertices'
 * 1-ring pattern (plateau_mesh_area_hessian_normal).  A level ends by the
 * Newton decrement delta = -g.t = t.H t, twice the decrease the quadratic
 * model still promises: when delta / 2 <= PLATEAU__C2F_TAU E, E = (A_prev -
 * A) / 3 the level's remaining excess extrapolated from the levels (one
 * subdivision halves h, the area's error falls as h^2: A_prev - A* ~ 4 (A -
 * A*)), the answer is within 1 % of the discrete optimum's excess. */
#define PLATEAU__C2F_TAU 0.01
#define PLATEAU__C2F_FLOOR 1e-13  /* the tolerance's floor, relative to the area */
#define PLATEAU__C2F_MAX_STEPS 20   /* Newton steps per level */
#define PLATEAU__C2F_HALVINGS 20    /* step halvings per Newton step */
#define PLATEAU__C2F_SHIFTS 12      /* shifted factorisations per step */
#define PLATEAU__C2F_SHIFT0 1e-3    /* first shift, of the mean diagonal; x10 per failure */
#define PLATEAU__C2F_PAPER_STEPS 8  /* method paper's normal Newton steps */
#define PLATEAU__C2F_PAPER_F 1e-10  /* its F bound: the final check's PLATEAU__CHK_SOLVED_F */

/* The work of one level: the pattern, its factor and the vectors. */
typedef struct plateau__c2f_nn {
    plateau__solve_sparse sp;
    void *pattern;            /* the pattern's one allocation (sp's arrays, xy) */
    double *xy;
    plateau_lm_sparse_symbolic *sym;
    plateau_lm_sparse_factor *fac;
    size_t nfree, nnz;
    plateau_index *node;      /* num_vertices: free index or -1 */
    double *m, *x0, *tn, *g, *dg, *off, *hv, *t;
} plateau__c2f_nn;

static void plateau__c2f_nn_free(plateau__c2f_nn *w, const plateau_allocator *al)
{
    plateau_lm_sparse_factor_free(w->fac);
    plateau_lm_sparse_symbolic_free(w->sym);
    plateau__free(al, w->pattern);
    plateau__free(al, w->node);
    plateau__free(al, w->m);
    plateau__free(al, w->x0);
    plateau__free(al, w->tn);
    plateau__free(al, w->g);
    plateau__free(al, w->dg);
    plateau__free(al, w->off);
    plateau__free(al, w->hv);
    plateau__free(al, w->t);
    memset(w, 0, sizeof *w);
}

/* The scalar pattern of the free vertices (the diagonal, then the free
 * neighbours in vertex_edges order), its analysis, a factor object of
 * kind, and the vectors.  PLATEAU_ERR_OUT_OF_MEMORY (or _OVERFLOW) on
 * failure, w then freed. */
static plateau_result plateau__c2f_nn_new(const plateau_mesh *mesh, int kind, plateau__c2f_nn *w,
                                          plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, v;
    plateau_lm_result lrc = PLATEAU_LM_ERR_OUT_OF_MEMORY;
    memset(w, 0, sizeof *w);
    for (v = 0; v < nv; v++) w->nfree += !mesh->fixed[v];
    w->pattern = plateau__solve_sparse_pattern(mesh, w->nfree, &w->sp, &w->xy);
    w->node = (plateau_index *)plateau__util_array(al, nv, sizeof(plateau_index));
    w->m = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
    w->x0 = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
    w->tn = (double *)plateau__util_array(al, mesh->num_triangles, 3 * sizeof(double));
    w->g = (double *)plateau__util_array(al, nv, sizeof(double));
    w->dg = (double *)plateau__util_array(al, nv, sizeof(double));
    w->off = (double *)plateau__util_array(al, mesh->num_edges + 1, sizeof(double));
    w->t = (double *)plateau__util_array(al, w->nfree + 1, sizeof(double));
    if (w->pattern) {
        w->nnz = (size_t)w->sp.row_start[w->nfree];
        w->hv = (double *)plateau__util_array(al, w->nnz + 1, sizeof(double));
    }
    if (w->pattern && w->node && w->m && w->x0 && w->tn && w->g && w->dg && w->off && w->t && w->hv) {
        plateau_lm_sparse_pattern pat;
        plateau_lm_sparse_options so;
        size_t k = 0;
        for (v = 0; v < nv; v++) w->node[v] = mesh->fixed[v] ? -1 : (plateau_index)k++;
        memset(&so, 0, sizeof so);
        so.allocator = *al;
        pat.nodes = w->nfree;
        pat.block = 1;
        pat.row_start = w->sp.row_start;
        pat.cols = w->sp.cols;
        lrc = plateau_lm_sparse_analyze(&pat, w->xy, &so, &w->sym);
        if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_factor_create(w->sym, kind, NULL, 0, &w->fac);
    }
    if (lrc != PLATEAU_LM_OK) {
        plateau__c2f_nn_free(w, al);
        plateau__util_error(err, lrc == PLATEAU_LM_ERR_OVERFLOW ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_OUT_OF_MEMORY,
                            -1, "out of memory in a coarse-to-fine level", 0, 0);
        return lrc == PLATEAU_LM_ERR_OVERFLOW ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_OUT_OF_MEMORY;
    }
    return PLATEAU_OK;
}

/* Unit vertex normals into w->m, the unnormalised triangle normals into
 * w->tn (the turn test) and the positions into w->x0. */
static void plateau__c2f_nn_frame(const plateau_mesh *mesh, plateau__c2f_nn *w)
{
    size_t v, t;
    for (v = 0; v < mesh->num_vertices; v++) plateau_vertex_normal(mesh, v, w->m + 3 * v);
    for (t = 0; t < mesh->num_triangles; t++) plateau__geo_tri_cross(mesh, t, w->tn + 3 * t);
    memcpy(w->x0, mesh->positions, 3 * mesh->num_vertices * sizeof(double));
}

/* The positions x0 + step t_v m_v; 1 when a triangle turns against its
 * normal at x0. */
static int plateau__c2f_nn_move(plateau_mesh *mesh, const plateau__c2f_nn *w, double step)
{
    size_t v, t;
    for (v = 0; v < mesh->num_vertices; v++) {
        double tv;
        int c;
        if (w->node[v] < 0) continue;
        tv = step * w->t[w->node[v]];
        for (c = 0; c < 3; c++) mesh->positions[3 * v + (size_t)c] = w->x0[3 * v + (size_t)c] + tv * w->m[3 * v + (size_t)c];
    }
    for (t = 0; t < mesh->num_triangles; t++) {
        double cn[3];
        plateau__geo_tri_cross(mesh, t, cn);
        if (!(plateau__util_dot(cn, w->tn + 3 * t) > 0.0)) return 1;
    }
    return 0;
}

/* The area's gradient and Hessian on normal motions, gathered into the
 * free vertices' pattern (w->t = -g, w->hv); 0 for a zero-area triangle. */
static int plateau__c2f_nn_assemble(const plateau_mesh *mesh, plateau__c2f_nn *w)
{
    size_t v, e, q = 0;
    if (plateau_mesh_area_hessian_normal(mesh, w->m, w->g, w->dg, w->off, NULL) != PLATEAU_OK) return 0;
    for (v = 0; v < mesh->num_vertices; v++) {
        if (w->node[v] < 0) continue;
        w->t[w->node[v]] = -w->g[v];
        w->hv[q++] = w->dg[v];
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index u = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed];
            if (w->node[u] >= 0) w->hv[q++] = w->off[ed];
        }
    }
    return 1;
}

/* w->t = -g on the free vertices. */
static void plateau__c2f_nn_rhs(const plateau_mesh *mesh, plateau__c2f_nn *w)
{
    size_t v;
    for (v = 0; v < mesh->num_vertices; v++)
        if (w->node[v] >= 0) w->t[w->node[v]] = -w->g[v];
}

/* The Newton decrement -g.t of the step in w->t. */
static double plateau__c2f_nn_decrement(const plateau_mesh *mesh, const plateau__c2f_nn *w)
{
    double delta = 0.0;
    size_t v;
    for (v = 0; v < mesh->num_vertices; v++)
        if (w->node[v] >= 0) delta -= w->g[v] * w->t[w->node[v]];
    return delta;
}

/* Factorises H, shifted by mu mean(diag H) I (mu from PLATEAU__C2F_SHIFT0,
 * x10 per failure) when H is not positive definite, and solves H t = -g in
 * w->t.  *exact = 1 when no shift was needed.  0 when every shift failed. */
static int plateau__c2f_nn_newton_step(plateau__c2f_nn *w, int *exact)
{
    double diag = 0.0, mu = 0.0;
    size_t i;
    int k;
    for (i = 0; i < w->nfree; i++) diag += PLATEAU_FABS(w->hv[w->sp.row_start[i]]);
    diag /= (double)(w->nfree ? w->nfree : 1);
    for (k = 0; k < PLATEAU__C2F_SHIFTS; k++) {
        if (plateau_lm_sparse_factorize(w->fac, w->hv, mu * diag) == PLATEAU_LM_OK) break;
        mu = mu == 0.0 ? PLATEAU__C2F_SHIFT0 : 10.0 * mu;
    }
    *exact = mu == 0.0;
    return k < PLATEAU__C2F_SHIFTS && plateau_lm_sparse_solve(w->fac, 1, w->t, w->nfree) == PLATEAU_LM_OK;
}

/* One level of method area's coarse to fine: Newton steps on normal
 * motions until delta / 2 <= PLATEAU__C2F_TAU (prev_area - A) / 3 (area_stop
 * PLATEAU_AREA_STOP_DECREMENT), at most min(max_iterations,
 * PLATEAU__C2F_MAX_STEPS) steps (MAX_ITERATIONS), or no step lowers the
 * area without turning a triangle (LINE_SEARCH).  After a step the
 * decrement is first computed with the last unshifted factor (a chord
 * solve): near the solution H changes little, and a small chord decrement
 * ends the level without a new factorisation.  Each step is halved while it
 * raises the area or turns a triangle. */
static plateau_result plateau__c2f_normal_newton(plateau_mesh *mesh, const plateau__cfg *cfg,
                                                 const plateau__cfg_run *run, int round, double prev_area,
                                                 plateau_report *rep, plateau_error *err)
{
    plateau__c2f_nn w;
    plateau_area_stop stop = PLATEAU_AREA_STOP_MAX_ITERATIONS;
    plateau_result rc = plateau__c2f_nn_new(mesh, PLATEAU_LM_SPARSE_CHOLESKY, &w, err);
    double area = plateau_mesh_area(mesh);
    int steps = 0, factored = 0, limit = cfg->max_iterations < PLATEAU__C2F_MAX_STEPS ? cfg->max_iterations : PLATEAU__C2F_MAX_STEPS;
    if (rc != PLATEAU_OK) return rc;
    rep->f_initial = area;
    while (w.nfree > 0) {
        double tol = PLATEAU__C2F_TAU * (prev_area - area) / 3.0, delta = 0.0, step = 1.0, a1 = area;
        /* a decrease below the rounding of the area's sum means nothing
         * (a plane polygon: A_prev - A is rounding too) */
        if (tol < PLATEAU__C2F_FLOOR * area) tol = PLATEAU__C2F_FLOOR * area;
        if (plateau__util_time_up(run->budget)) { /* options.max_seconds: the mesh as it is */
            run->budget->interrupted = 1;
            break;
        }
        int k, exact = 0;
        plateau__c2f_nn_frame(mesh, &w);
        if (!plateau__c2f_nn_assemble(mesh, &w)) { stop = PLATEAU_AREA_STOP_LINE_SEARCH; break; }
        if (factored) { /* the chord decrement, with the last factor */
            if (plateau_lm_sparse_solve(w.fac, 1, w.t, w.nfree) != PLATEAU_LM_OK) break;
            delta = plateau__c2f_nn_decrement(mesh, &w);
            if (delta / 2.0 <= tol) { stop = PLATEAU_AREA_STOP_DECREMENT; break; }
            plateau__c2f_nn_rhs(mesh, &w);
        }
        if (steps >= limit) break;
        if (!plateau__c2f_nn_newton_step(&w, &exact)) { stop = PLATEAU_AREA_STOP_LINE_SEARCH; break; }
        factored = exact;
        delta = plateau__c2f_nn_decrement(mesh, &w);
        if (exact && delta / 2.0 <= tol) { stop = PLATEAU_AREA_STOP_DECREMENT; break; }
        for (k = 0; k < PLATEAU__C2F_HALVINGS; k++, step *= 0.5) {
            if (!plateau__c2f_nn_move(mesh, &w, step) && (a1 = plateau_mesh_area(mesh)) <= area) break;
        }
        if (k == PLATEAU__C2F_HALVINGS) {
            memcpy(mesh->positions, w.x0, 3 * mesh->num_vertices * sizeof(double));
            stop = PLATEAU_AREA_STOP_LINE_SEARCH;
            break;
        }
        area = a1;
        steps++;
        rep->iterations++;
        if (cfg->progress && cfg->progress(round, steps, area * run->unit * run->unit, cfg->progress_user)) {
            rc = PLATEAU_ERR_ABORTED;
            plateau__util_error(err, rc, -1, "the progress callback asked to stop", 0, 0);
            break;
        }
    }
    if (w.nfree == 0) stop = PLATEAU_AREA_STOP_GRADIENT;
    rep->area_stop = stop;
    rep->f_final = area;
    if (run->order && w.nfree > 0) {
        /* the level's pattern and analysis go to the stability report */
        plateau__solve_order_clear(run->order);
        run->order->sym = w.sym;
        run->order->pattern = w.pattern;
        run->order->pattern_alloc = mesh->allocator;
        run->order->row_start = w.sp.row_start;
        run->order->cols = w.sp.cols;
        run->order->nfree = w.nfree;
        w.sym = NULL;
        w.pattern = NULL;
    }
    plateau__c2f_nn_free(&w, &mesh->allocator);
    return rc;
}

/* Method paper at the finest level of coarse to fine: its residuals H_i = 0
 * (paper II.B) at the free vertices, solved in the normal coordinates t
 * from method area's result, which fixes the tangential positions (so the
 * tangential rows of the square system are dropped: n equations in n
 * unknowns, J_ij = (dH_i/dx_j).m_j from plateau_vertex_mean_curvature_gradient
 * on the 1-ring pattern, by the sparse LU).  A step is halved while it does
 * not lower F = 1/2 sum H_i^2 or turns a triangle; at most
 * PLATEAU__C2F_PAPER_STEPS steps, ending at F <= PLATEAU__C2F_PAPER_F (the final check's bound).
 * rep->f_initial, f_final: F. */
static plateau_result plateau__c2f_paper_normal(plateau_mesh *mesh, const plateau__cfg *cfg,
                                                const plateau__cfg_run *run, int round,
                                                plateau_report *rep, plateau_error *err)
{
    plateau__c2f_nn w;
    const plateau_allocator *al = &mesh->allocator;
    size_t cap = 0, v, q;
    plateau_index *verts = NULL;
    double *grad = NULL, f = 0.0;
    int steps = 0;
    plateau_result rc = plateau__c2f_nn_new(mesh, PLATEAU_LM_SPARSE_LU, &w, err);
    if (rc != PLATEAU_OK) return rc;
    for (v = 0; v < mesh->num_vertices; v++) {
        size_t c = plateau_vertex_stencil_size(mesh, v);
        if (c > cap) cap = c;
    }
    verts = (plateau_index *)plateau__util_array(al, cap, sizeof(plateau_index));
    grad = (double *)plateau__util_array(al, cap, 3 * sizeof(double));
    if (!verts || !grad) {
        rc = PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__util_error(err, rc, -1, "out of memory in method paper's last level", 0, 0);
    }
    for (v = 0; v < mesh->num_vertices && rc == PLATEAU_OK; v++)
        if (w.node[v] >= 0) {
            double h = plateau_vertex_mean_curvature(mesh, v);
            f += 0.5 * h * h;
        }
    rep->f_initial = f;
    while (rc == PLATEAU_OK && f > PLATEAU__C2F_PAPER_F && steps < PLATEAU__C2F_PAPER_STEPS) {
        double step = 1.0, f1 = f;
        int k;
        if (plateau__util_time_up(run->budget)) {
            run->budget->interrupted = 1;
            break;
        }
        plateau__c2f_nn_frame(mesh, &w);
        for (q = 0; q < w.nnz; q++) w.hv[q] = 0.0;
        for (v = 0; v < mesh->num_vertices; v++) {
            size_t count = 0, j, r0;
            double h = 0.0;
            plateau_index r = w.node[v];
            if (r < 0) continue;
            plateau_vertex_mean_curvature_gradient(mesh, v, cap, verts, grad, &count, &h);
            w.t[r] = -h;
            r0 = (size_t)w.sp.row_start[r];
            for (j = 0; j < count; j++) {
                plateau_index c = w.node[verts[j]];
                if (c < 0) continue;
                for (q = r0; q < (size_t)w.sp.row_start[r + 1]; q++)
                    if (w.sp.cols[q] == c) {
                        w.hv[q] += plateau__util_dot(grad + 3 * j, w.m + 3 * (size_t)verts[j]);
                        break;
                    }
            }
        }
        if (plateau_lm_sparse_factorize(w.fac, w.hv, 0.0) != PLATEAU_LM_OK ||
            plateau_lm_sparse_solve(w.fac, 1, w.t, w.nfree) != PLATEAU_LM_OK)
            break;
        for (k = 0; k < PLATEAU__C2F_HALVINGS; k++, step *= 0.5) {
            if (plateau__c2f_nn_move(mesh, &w, step)) continue;
            f1 = 0.0;
            for (v = 0; v < mesh->num_vertices; v++)
                if (w.node[v] >= 0) {
                    double h = plateau_vertex_mean_curvature(mesh, v);
                    f1 += 0.5 * h * h;
                }
            if (f1 < f) break;
        }
        if (k == PLATEAU__C2F_HALVINGS) {
            memcpy(mesh->positions, w.x0, 3 * mesh->num_vertices * sizeof(double));
            break;
        }
        f = f1;
        steps++;
        rep->iterations++;
        if (cfg->progress && cfg->progress(round, steps, f / (run->unit * run->unit), cfg->progress_user)) {
            rc = PLATEAU_ERR_ABORTED;
            plateau__util_error(err, rc, -1, "the progress callback asked to stop", 0, 0);
        }
    }
    rep->f_final = f;
    plateau__free(al, verts);
    plateau__free(al, grad);
    plateau__c2f_nn_free(&w, al);
    return rc;
}

/* The levels: levels subdivisions of the coarse mesh, each followed by
 * method area's Newton steps on normal motions (plateau__c2f_normal_newton),
 * then for method paper its H_i = 0 on normal motions at the finest level
 * (plateau__c2f_paper_normal).  s->orig, s->k follow the fixed vertices. */
static plateau_result plateau__c2f_levels(plateau__cfg_work *s, const plateau__cfg *cfg,
                                          const plateau__cfg_run *run, int levels, plateau_mesh *mesh,
                                          plateau_report *rep, plateau_error *err)
{
    double prev = plateau_mesh_area(mesh);
    size_t nfixed = s->m + s->k, v;
    int k, round0 = (int)rep->rounds;
    plateau_result rc = PLATEAU_OK;
    for (k = 1; k <= levels && rc == PLATEAU_OK; k++) {
        plateau_report lr;
        if (plateau__util_time_up(run->budget)) { /* options.max_seconds: this level's mesh */
            run->budget->interrupted = 1;
            break;
        }
        if (!s->orig) {
            /* the first subdivision starts from the caller's polygon */
            s->orig = (double *)plateau__util_array(&s->alloc, s->m, 3 * sizeof(double));
            if (!s->orig) {
                plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in a subdivision", 0, 0);
                return PLATEAU_ERR_OUT_OF_MEMORY;
            }
            memcpy(s->orig, s->boundary, 3 * s->m * sizeof(double));
        }
        rc = plateau__c2f_subdivide(mesh, &s->orig, &nfixed, 1, 0, err);
        if (rc != PLATEAU_OK) break;
        s->k = nfixed - s->m;
        memset(&lr, 0, sizeof lr);
        rc = plateau__c2f_normal_newton(mesh, cfg, run, round0 + k, prev, &lr, err);
        rep->iterations += lr.iterations;
        rep->area_stop = lr.area_stop;
        rep->f_final = lr.f_final;
        rep->levels = (size_t)k;
        if (round0 + k <= PLATEAU_REPORT_F_ROUNDS) rep->f_rounds[round0 + k - 1] = lr.f_final;
        prev = lr.f_final;
    }
    for (v = 0, rep->interior_points = 0; v < mesh->num_vertices; v++) rep->interior_points += !mesh->fixed[v];
    rep->rounds = (size_t)(round0 + (int)rep->levels);
    rep->boundary_points_added = s->k;
    if (rc == PLATEAU_OK && cfg->method == PLATEAU_METHOD_PAPER &&
        !(run->budget && run->budget->interrupted)) {
        plateau_report pr;
        memset(&pr, 0, sizeof pr);
        rc = plateau__c2f_paper_normal(mesh, cfg, run, round0 + levels + 1, &pr, err);
        rep->iterations += pr.iterations;
        rep->f_initial = pr.f_initial;
        rep->f_final = pr.f_final;
        rep->area_stop = PLATEAU_AREA_STOP_NONE;
        rep->linear_solver = PLATEAU_LINEAR_SPARSE;
    }
    plateau__chk_report_quality(mesh, rep);
    rep->stop = run->budget && run->budget->interrupted ? PLATEAU_STOP_TIME_LIMIT : PLATEAU_STOP_CONVERGED;
    if (rc == PLATEAU_OK) rc = plateau__chk_final(mesh, cfg, run, rep, err);
    return rc;
}

/* Coarse to fine, when plateau__c2f_plan says so: the coarse mesh (with
 * one level fewer, four times as many coarse points, when it has defects
 * or its finest level would have too many points;
 * then the rounds at full size), then the levels.  *used = 0: nothing was
 * done, the caller runs steps 3-6 at full size. */
static plateau_result plateau__c2f_solve(plateau__cfg_work *s, const plateau__cfg *cfg,
                                         const plateau__cfg_run *run, double scale, plateau_mesh *mesh,
                                         plateau_report *rep, int *used, plateau_error *err)
{
    size_t n = s->n, n0 = 0;
    int levels = plateau__c2f_plan(s, cfg, &n0), ok = 0, tries;
    plateau_result rc = PLATEAU_OK;
    *used = 0;
    if (cfg->coarse_to_fine == PLATEAU_ON && s->loops > 1) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "coarse_to_fine ON takes one polygon, not several loops", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (tries = 0; tries < 2 && levels > 0 && !ok; tries++) {
        if (tries > 0) {
            plateau__c2f_reset(s, mesh, rep);
            levels--;
            n0 = (size_t)(plateau__c2f_coarse((double)n, (double)s->m, levels) + 0.5);
            if (levels == 0) break;
        }
        rc = plateau__c2f_coarse_mesh(s, cfg, run, n, levels, n0, scale, mesh, rep, &ok, err);
        if (rc != PLATEAU_OK) {
            s->n = n;
            return rc;
        }
    }
    if (!ok) {
        if (levels > 0 || tries > 0) plateau__c2f_reset(s, mesh, rep);
        s->n = n;
        return PLATEAU_OK;
    }
    s->n = n;
    *used = 1;
    return plateau__c2f_levels(s, cfg, run, levels, mesh, rep, err);
}
#else /* PLATEAU_NO_COARSE_TO_FINE */
/* plateau__cfg_resolve refused coarse_to_fine ON and turned AUTO off:
 * the rounds at full size. */
static plateau_result plateau__c2f_solve(plateau__cfg_work *s, const plateau__cfg *cfg,
                                         const plateau__cfg_run *run, double scale, plateau_mesh *mesh,
                                         plateau_report *rep, int *used, plateau_error *err)
{
    (void)s, (void)cfg, (void)run, (void)scale, (void)mesh, (void)rep, (void)err;
    *used = 0;
    return PLATEAU_OK;
}
#endif /* PLATEAU_NO_COARSE_TO_FINE */
/* ======== END SECTION: coarse to fine ===================================== */

/* ======== SECTION: the accuracy: the error estimate (plateau__acc_) ======== */
/* ACCURACY at the top: the estimate of every result
 * (report.area_error_estimate) and the counts that options.accuracy
 * solves at. */

/* Conjugate-gradient steps on the subdivided mesh's quadratic model. */
#define PLATEAU__ACC_CG_STEPS 10
/* The first interior count of options.accuracy when interior_points is 0
 * (at least m): from 200 points coarse to fine runs, and a polygon of few
 * corners gets its edges split. */
#define PLATEAU__ACC_FIRST_POINTS 200
/* The next count: the error falls as 1 / n, so (e / a) n meets a; the
 * margin covers the estimate's own scatter, the bounds keep a step useful
 * and a wrong estimate from running away. */
#define PLATEAU__ACC_MARGIN 1.3
#define PLATEAU__ACC_MIN_GROWTH 1.5
#define PLATEAU__ACC_MAX_GROWTH 16.0
#define PLATEAU__ACC_MAX_SOLVES 8
/* Bytes per vertex of the subdivided mesh (its arrays and the vectors
 * below), a bound, for options.max_memory. */
#define PLATEAU__ACC_BYTES_PER_VERTEX 700.0

PLATEAU_DEF const char *plateau_estimate_string(plateau_estimate status)
{
    switch (status) {
#define PLATEAU__CASE(name, value, text) case name: return text;
        PLATEAU_ESTIMATE_LIST(PLATEAU__CASE)
#undef PLATEAU__CASE
    default: break;
    }
    return "unknown estimate status";
}

/* A quiet NaN without <math.h>'s NAN (freestanding builds have none). */
static double plateau__acc_nan(void)
{
    volatile double z = 0.0;
    return z / z;
}

#ifndef PLATEAU_NO_ACCURACY

/* The copy of the mesh that the estimate works on, in [-1, 1]^3 (the
 * estimate is relative, and a polygon 1e200 across keeps its Hessian in
 * range), split flat 1-to-4 (plateau__c2f_subdivide: the new boundary
 * vertices on the polygon's segments, the others at their edges'
 * midpoints, so the copy has the result's area). */
static plateau_result plateau__acc_fine(const plateau_mesh *mesh, plateau_mesh *fine, plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, nf = 0, v, k = 0;
    double *pos = (double *)plateau__util_array(al, nv, 3 * sizeof(double)), *orig = NULL;
    plateau_result rc = PLATEAU_ERR_OUT_OF_MEMORY;
    memset(fine, 0, sizeof *fine);
    for (v = 0; v < nv; v++) nf += mesh->fixed[v] != 0;
    orig = (double *)plateau__util_array(al, nf + 1, 3 * sizeof(double));
    if (pos && orig) {
        plateau__util_unit_copy(mesh->positions, nv, pos);
        for (v = 0; v < nv; v++)
            if (mesh->fixed[v]) memcpy(orig + 3 * k++, pos + 3 * v, 3 * sizeof(double));
        rc = plateau_mesh_create(pos, nv, mesh->fixed, mesh->triangles, mesh->num_triangles, al, fine, err);
    } else {
        plateau__util_error(err, rc, -1, "out of memory in the error estimate", 0, 0);
    }
    plateau__free(al, pos);
    if (rc == PLATEAU_OK) rc = plateau__c2f_subdivide(fine, &orig, &nf, 1, 1, err);
    plateau__free(al, orig);
    if (rc != PLATEAU_OK) plateau_mesh_free(fine);
    return rc;
}

/* y = H p on the free vertices (H: diagonal dg, one value per edge), 0 at
 * the fixed ones. */
static void plateau__acc_hessian_times(const plateau_mesh *mesh, const double *dg, const double *off,
                                       const double *p, double *y)
{
    size_t v, e;
    for (v = 0; v < mesh->num_vertices; v++) y[v] = mesh->fixed[v] ? 0.0 : dg[v] * p[v];
    for (e = 0; e < mesh->num_edges; e++) {
        size_t a = (size_t)mesh->edges[2 * e], b = (size_t)mesh->edges[2 * e + 1];
        if (mesh->fixed[a] || mesh->fixed[b]) continue;
        y[a] += off[e] * p[b];
        y[b] += off[e] * p[a];
    }
}

/* D: the decrease of the area's second-order model q(t) = g.t + t.H t / 2
 * in the normal motions t of the free vertices of the subdivided mesh
 * (plateau_mesh_area_hessian_normal with the unit vertex normals), over
 * PLATEAU__ACC_CG_STEPS steps of conjugate gradients preconditioned by the
 * diagonal (each exact line search lowers q by (r.z)^2 / (2 p.H p)); they
 * stop at a direction of negative curvature (a saddle's result).  The
 * high-frequency motions that the new vertices add converge first, and
 * they carry the decrease the finer mesh offers. */
static plateau_result plateau__acc_decrease(const plateau_mesh *fine, double *decrease, plateau_estimate *st,
                                            plateau_error *err)
{
    const plateau_allocator *al = &fine->allocator;
    size_t nv = fine->num_vertices, v;
    double *w = (double *)plateau__util_array(al, nv, 9 * sizeof(double));
    double *off = (double *)plateau__util_array(al, fine->num_edges + 1, sizeof(double));
    double *nrm, *g, *dg, *r, *z, *p, *hp, rz = 0.0, d = 0.0;
    int k;
    *decrease = 0.0;
    *st = PLATEAU_ESTIMATE_FORMED;
    if (!w || !off) {
        plateau__free(al, w);
        plateau__free(al, off);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in the error estimate", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    nrm = w, g = w + 3 * nv, dg = g + nv, r = dg + nv, z = r + nv, p = z + nv, hp = p + nv;
    for (v = 0; v < nv; v++) plateau_vertex_normal(fine, v, nrm + 3 * v);
    if (plateau_mesh_area_hessian_normal(fine, nrm, g, dg, off, NULL) != PLATEAU_OK) {
        *st = PLATEAU_ESTIMATE_DEGENERATE;
    } else {
        for (v = 0; v < nv; v++) {
            r[v] = fine->fixed[v] ? 0.0 : -g[v];
            z[v] = r[v] / (dg[v] > 0.0 ? dg[v] : 1.0);
            p[v] = z[v];
            rz += r[v] * z[v];
        }
        for (k = 0; k < PLATEAU__ACC_CG_STEPS && rz > 0.0; k++) {
            double php = 0.0, alpha, rz1 = 0.0;
            plateau__acc_hessian_times(fine, dg, off, p, hp);
            for (v = 0; v < nv; v++) php += p[v] * hp[v];
            if (!(php > 0.0)) break;
            alpha = rz / php;
            d += 0.5 * alpha * rz;
            for (v = 0; v < nv; v++) {
                r[v] -= alpha * hp[v];
                z[v] = r[v] / (dg[v] > 0.0 ? dg[v] : 1.0);
                rz1 += r[v] * z[v];
            }
            for (v = 0; v < nv; v++) p[v] = z[v] + (rz1 / rz) * p[v];
            rz = rz1;
        }
        *decrease = d;
    }
    plateau__free(al, w);
    plateau__free(al, off);
    return PLATEAU_OK;
}

/* report.area_error_estimate of a result: (4/3) D / A (ACCURACY at the
 * top), or NaN and report.estimate saying why not.  Returns PLATEAU_OK or
 * the failure of an allocation (_OUT_OF_MEMORY, _OVERFLOW). */
static plateau_result plateau__acc_report(const plateau_mesh *mesh, const plateau__cfg *cfg, plateau_report *rep,
                                          plateau_error *err)
{
    plateau_mesh fine;
    double d = 0.0, a;
    plateau_estimate st = PLATEAU_ESTIMATE_FORMED;
    plateau_result rc;
    rep->area_error_estimate = plateau__acc_nan();
    rep->estimate = cfg->membrane ? PLATEAU_ESTIMATE_MEMBRANE
                    : !mesh->positions || mesh->num_triangles == 0 ? PLATEAU_ESTIMATE_NO_RESULT
                    : 4.0 * (double)(mesh->num_vertices + mesh->num_edges) * PLATEAU__ACC_BYTES_PER_VERTEX >
                            (double)cfg->max_memory
                        ? PLATEAU_ESTIMATE_MEMORY
                        : PLATEAU_ESTIMATE_FORMED;
    if (rep->estimate != PLATEAU_ESTIMATE_FORMED) return PLATEAU_OK;
    rc = plateau__acc_fine(mesh, &fine, err);
    if (rc == PLATEAU_ERR_DEGENERATE_TRIANGLE) { /* a triangle repeats a vertex: never from a solve */
        rep->estimate = PLATEAU_ESTIMATE_DEGENERATE;
        return plateau__util_ok(err);
    }
    if (rc != PLATEAU_OK) return rc;
    a = plateau_mesh_area(&fine);
    if (!(a > 0.0)) st = PLATEAU_ESTIMATE_NO_AREA;
    else rc = plateau__acc_decrease(&fine, &d, &st, err);
    if (rc == PLATEAU_OK && st == PLATEAU_ESTIMATE_FORMED) rep->area_error_estimate = 4.0 / 3.0 * d / a;
    rep->estimate = st;
    plateau_mesh_free(&fine);
    return rc;
}

/* The next interior count of options.accuracy after a solve whose got
 * interior points gave the estimate e above the accuracy a; 0 when none
 * may follow (the bound reached). */
static size_t plateau__acc_next(size_t got, double e, double a)
{
    double f = PLATEAU__ACC_MARGIN * e / a, n;
    if (!(f >= PLATEAU__ACC_MIN_GROWTH)) f = PLATEAU__ACC_MIN_GROWTH;
    if (f > PLATEAU__ACC_MAX_GROWTH) f = PLATEAU__ACC_MAX_GROWTH;
    n = f * (double)(got > 4 ? got : 4);
    if (n > (double)PLATEAU_ACCURACY_MAX_POINTS) n = (double)PLATEAU_ACCURACY_MAX_POINTS;
    return n > (double)got ? (size_t)n : 0;
}
#else /* PLATEAU_NO_ACCURACY */
/* No estimate: NaN, and the reason. */
static plateau_result plateau__acc_report(const plateau_mesh *mesh, const plateau__cfg *cfg, plateau_report *rep,
                                          plateau_error *err)
{
    (void)mesh, (void)cfg, (void)err;
    rep->area_error_estimate = plateau__acc_nan();
    rep->estimate = PLATEAU_ESTIMATE_COMPILED_OUT;
    return PLATEAU_OK;
}
#endif /* PLATEAU_NO_ACCURACY */
/* ======== END SECTION: the accuracy ========================================= */


/* ======== SECTION: second-order analysis (plateau__stab_, plateau__crit_) == */
/* The stability report (plateau_mesh_stability: the index and lowest
 * eigenvalues of the area's Hessian on normal motions) and the search
 * for a critical point of a chosen index (plateau_mesh_critical_point),
 * on a small numerics block: a dense symmetric eigensolver and block
 * Lanczos on the shifted inverse. */
#ifndef PLATEAU_NO_STABILITY

/* ---- numerics: the dense symmetric eigensolver and block Lanczos ---- */

/* Eigenvalues and eigenvectors of the dense symmetric k x k matrix a
 * (row-major, destroyed; its diagonal ends as the eigenvalues): Householder
 * reduction to tridiagonal form, then the implicit symmetric QR iteration
 * with Wilkinson's shift (Golub and Van Loan, algorithms 8.3.1 and 8.3.3),
 * the transformations accumulated in z (k x k, row-major), whose columns
 * end as the eigenvectors.  About 10 k^3 operations; an off-diagonal entry
 * below eps (|d_i| + |d_i+1|) splits the matrix. */
static void plateau__stab_symeig(double *a, size_t k, double *z)
{
    size_t j, i, m, lo, hi, iter;
    for (i = 0; i < k * k; i++) z[i] = 0.0;
    for (i = 0; i < k; i++) z[i * k + i] = 1.0;
    for (j = 0; j + 2 < k; j++) { /* column j below its subdiagonal to zero: A = H A H */
        double alpha = 0.0, vtv = 0.0, beta, vp = 0.0, v[PLATEAU_STABILITY_LANCZOS], p[PLATEAU_STABILITY_LANCZOS];
        for (i = j + 1; i < k; i++) alpha += a[i * k + j] * a[i * k + j];
        alpha = PLATEAU_SQRT(alpha);
        if (alpha == 0.0) continue;
        if (a[(j + 1) * k + j] > 0.0) alpha = -alpha; /* v_0 = x_0 - alpha without cancellation */
        for (i = 0; i < k; i++) v[i] = i > j ? a[i * k + j] : 0.0;
        v[j + 1] -= alpha;
        for (i = j + 1; i < k; i++) vtv += v[i] * v[i];
        if (!(vtv > 0.0)) continue;
        beta = 2.0 / vtv;
        for (i = j; i < k; i++) { /* p = beta A v */
            double s = 0.0;
            for (m = j + 1; m < k; m++) s += a[i * k + m] * v[m];
            p[i] = beta * s;
            vp += v[i] * p[i];
        }
        for (i = j; i < k; i++) p[i] -= 0.5 * beta * vp * v[i]; /* w = p - (beta v^T p / 2) v */
        for (i = j; i < k; i++)
            for (m = j; m < k; m++) a[i * k + m] -= v[i] * p[m] + p[i] * v[m];
        for (i = 0; i < k; i++) { /* Z = Z H */
            double s = 0.0;
            for (m = j + 1; m < k; m++) s += z[i * k + m] * v[m];
            s *= beta;
            for (m = j + 1; m < k; m++) z[i * k + m] -= s * v[m];
        }
    }
    /* the tridiagonal matrix: d_i on the diagonal, e_i = a(i + 1, i) kept at a(i, i + 1) */
    for (i = 0; i + 1 < k; i++) a[i * k + i + 1] = a[(i + 1) * k + i];
    hi = k > 0 ? k - 1 : 0;
    for (iter = 0; hi > 0 && iter < 30 * k; iter++) {
        double dd, ee, mu, x, y, bulge = 0.0;
        size_t p;
        if (PLATEAU_FABS(a[(hi - 1) * k + hi]) <=
            DBL_EPSILON * (PLATEAU_FABS(a[(hi - 1) * k + hi - 1]) + PLATEAU_FABS(a[hi * k + hi]))) {
            a[(hi - 1) * k + hi] = 0.0; /* a(hi, hi) has converged */
            hi--;
            continue;
        }
        for (lo = hi - 1; lo > 0; lo--) /* the unreduced block lo .. hi */
            if (PLATEAU_FABS(a[(lo - 1) * k + lo]) <=
                DBL_EPSILON * (PLATEAU_FABS(a[(lo - 1) * k + lo - 1]) + PLATEAU_FABS(a[lo * k + lo]))) {
                a[(lo - 1) * k + lo] = 0.0;
                break;
            }
        /* Wilkinson's shift: the eigenvalue of the trailing 2 x 2 nearer a(hi, hi) */
        dd = 0.5 * (a[(hi - 1) * k + hi - 1] - a[hi * k + hi]);
        ee = a[(hi - 1) * k + hi];
        mu = a[hi * k + hi] - ee * ee / (dd + (dd >= 0.0 ? 1.0 : -1.0) * PLATEAU_SQRT(dd * dd + ee * ee));
        x = a[lo * k + lo] - mu;
        y = a[lo * k + lo + 1];
        for (p = lo; p < hi; p++) { /* the bulge chased down by rotations in planes (p, p + 1) */
            double r = PLATEAU_SQRT(x * x + y * y), c = r > 0.0 ? x / r : 1.0, s = r > 0.0 ? y / r : 0.0;
            double dp = a[p * k + p], ep = a[p * k + p + 1], dq = a[(p + 1) * k + p + 1];
            if (p > lo) a[(p - 1) * k + p] = r;
            a[p * k + p] = c * c * dp + 2.0 * c * s * ep + s * s * dq;
            a[(p + 1) * k + p + 1] = s * s * dp - 2.0 * c * s * ep + c * c * dq;
            a[p * k + p + 1] = c * s * (dq - dp) + (c * c - s * s) * ep;
            if (p + 1 < hi) {
                bulge = s * a[(p + 1) * k + p + 2];
                a[(p + 1) * k + p + 2] *= c;
            }
            for (i = 0; i < k; i++) {
                double zp = z[i * k + p], zq = z[i * k + p + 1];
                z[i * k + p] = c * zp + s * zq;
                z[i * k + p + 1] = c * zq - s * zp;
            }
            x = a[p * k + p + 1];
            y = bulge;
        }
    }
}

/* The working state of plateau_mesh_stability: K = M^-1/2 H M^-1/2 on the
 * free vertices (CSR with the diagonal), its analysis and L D L^T, and the
 * Lanczos basis. */
typedef struct plateau__stab {
    plateau_allocator alloc;
    size_t nv, nf, nnz, steps;
    plateau_index *node;      /* nv: the row of a free vertex, -1 for a fixed one */
    plateau__solve_sparse sp; /* K's pattern (nf + 1 row starts, nnz columns) */
    void *pattern;            /* its memory, with xy */
    double *xy;               /* nf: ordering coordinates (NULL: graph ordering) */
    double *vals, *msq;       /* nnz values of K; nf values sqrt(|B_v|) */
    double *diag, *off, *grad; /* nv, num_edges, 3 nv: H and the area gradient */
    double *dir;              /* 3 nv: the unit vertex normals, H's directions */
    double *tri;              /* 4 per triangle (its cross product, its area),
                                 then nv barycentric cells: setup's scratch */
    double *gn;               /* nv: the area gradient on normal motions */
    double *q;                /* (steps + 1) nf: the Lanczos basis */
    double *t, *z, *e, *w;    /* steps^2 each (T, its eigenvectors, scratch); nf */
    double scale;             /* largest |K_ii| */
    int vectors;              /* 1: the Ritz vectors are used (modes, the
                                 critical-point search), 0: the values only
                                 (plateau__stab_ritz's two tests) */
    const plateau__solve_order *order; /* NULL, or an elimination order of the
                                 free vertices (plateau__stab_ordered) */
    plateau_lm_sparse_symbolic *sym;
    plateau_lm_sparse_factor *fac;
} plateau__stab;

static void plateau__stab_free(plateau__stab *st)
{
    plateau_lm_sparse_factor_free(st->fac);
    plateau_lm_sparse_symbolic_free(st->sym);
    plateau__free(&st->alloc, st->node);
    plateau__free(&st->alloc, st->pattern);
    plateau__free(&st->alloc, st->vals);
    plateau__free(&st->alloc, st->msq);
    plateau__free(&st->alloc, st->diag);
    plateau__free(&st->alloc, st->off);
    plateau__free(&st->alloc, st->grad);
    plateau__free(&st->alloc, st->dir);
    plateau__free(&st->alloc, st->tri);
    plateau__free(&st->alloc, st->gn);
    plateau__free(&st->alloc, st->q);
    plateau__free(&st->alloc, st->t);
    plateau__free(&st->alloc, st->z);
    plateau__free(&st->alloc, st->e);
    plateau__free(&st->alloc, st->w);
}

/* The dot product of two n-vectors, four partial sums (independent
 * additions the processor can overlap; a fixed order, so deterministic). */
static double plateau__stab_dot(const double *a, const double *b, size_t n)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        s0 += a[i] * b[i];
        s1 += a[i + 1] * b[i + 1];
        s2 += a[i + 2] * b[i + 2];
        s3 += a[i + 3] * b[i + 3];
    }
    for (; i < n; i++) s0 += a[i] * b[i];
    return (s0 + s1) + (s2 + s3);
}

/* The b <= 2 columns of W (n apart) minus their projections on the
 * orthonormal columns 0 .. r - 1 of q (modified Gram-Schmidt, each q_j read
 * once for both columns), a second pass only when the first removed more
 * than half of a column's length (Daniel, Gragg, Kaufman and Stewart's
 * test: once is then not enough); then W = Q' R within the block (R b x b
 * upper triangular, row-major; a column whose remaining length is at most
 * thr gets R_cc = 0, is left unscaled and makes the return value 1: the
 * Krylov space is exhausted). */
static int plateau__stab_orth(const double *q, size_t n, size_t r, double *W, size_t b, double thr,
                              double *R)
{
    size_t pass, j, i, c;
    double before[2], after[2];
    int broke = 0;
    for (c = 0; c < b; c++) before[c] = PLATEAU_SQRT(plateau__stab_dot(W + c * n, W + c * n, n));
    for (pass = 0; pass < 2 && r > 0; pass++) {
        int again = 0;
        for (j = 0; j < r; j++) {
            const double *qj = q + j * n;
            for (c = 0; c < b; c++) {
                double *w = W + c * n, d = plateau__stab_dot(qj, w, n);
                for (i = 0; i < n; i++) w[i] -= d * qj[i];
            }
        }
        for (c = 0; c < b; c++) {
            after[c] = PLATEAU_SQRT(plateau__stab_dot(W + c * n, W + c * n, n));
            if (!(after[c] > 0.5 * before[c])) again = 1;
            before[c] = after[c];
        }
        if (!again) break;
    }
    for (c = 0; c < b * b; c++) R[c] = 0.0;
    for (c = 0; c < b; c++) {
        double *w = W + c * n, len = before[c];
        for (j = 0; j < c && !broke; j++)
            for (pass = 0; pass < 2; pass++) { /* against the block's earlier columns, DGKS again */
                double d = plateau__stab_dot(W + j * n, w, n);
                for (i = 0; i < n; i++) w[i] -= d * W[j * n + i];
                R[j * b + c] += d;
                d = PLATEAU_SQRT(plateau__stab_dot(w, w, n));
                if (d > 0.5 * len) {
                    len = d;
                    break;
                }
                len = d;
            }
        if (broke || !(len > thr)) {
            broke = 1;
            continue;
        }
        R[c * b + c] = len;
        for (i = 0; i < n; i++) w[i] /= len;
    }
    return broke;
}

/* Ritz values and vectors of the L x L matrix T of the last Lanczos run
 * (stride st->steps in st->t), with the residual block R (b x b, upper
 * triangular): lam[i] = 1 / theta_i - shift; the eigenvectors of T in
 * st->z (columns, in the order of lam).  ok[i] when the residual
 * r = |R z_i(last b rows)| is at most 1e-8 of the largest |theta| (the
 * Ritz vector then converged too), or, when only the values are wanted
 * (st->vectors 0), when theta_i's error bound min(r, r^2 / gap) is at
 * most 1e-8 |theta_i|, gap the distance to the nearest other Ritz value
 * (Parlett, The Symmetric Eigenvalue Problem, 11.7: a Ritz value's
 * error is second order in its residual). */
static void plateau__stab_ritz(plateau__stab *st, size_t L, size_t b, const double *R,
                               double shift, double *lam, int *ok)
{
    size_t i, j, c;
    double tmax = 0.0;
    for (j = 0; j < L; j++)
        for (i = 0; i < L; i++) st->z[j * L + i] = st->t[j * st->steps + i];
    memcpy(st->e, st->z, L * L * sizeof(double));
    plateau__stab_symeig(st->e, L, st->z);
    for (i = 0; i < L; i++)
        if (PLATEAU_FABS(st->e[i * L + i]) > tmax) tmax = PLATEAU_FABS(st->e[i * L + i]);
    for (i = 0; i < L; i++) {
        double th = st->e[i * L + i], res = 0.0;
        for (c = 0; c < b; c++) { /* (R z_i)_c over the last block's rows */
            double rc = 0.0;
            for (j = c; j < b; j++) rc += R[c * b + j] * st->z[(L - b + j) * L + i];
            res += rc * rc;
        }
        lam[i] = th != 0.0 ? 1.0 / th - shift : 0.0;
        res = PLATEAU_SQRT(res);
        ok[i] = th != 0.0 && res <= 1e-8 * tmax;
        if (th != 0.0 && !ok[i] && !st->vectors) {
            double gap = -1.0, bound;
            for (j = 0; j < L; j++)
                if (j != i && (gap < 0.0 || PLATEAU_FABS(st->e[j * L + j] - th) < gap))
                    gap = PLATEAU_FABS(st->e[j * L + j] - th);
            bound = gap > 0.0 && res * res / gap < res ? res * res / gap : res;
            ok[i] = bound <= 1e-8 * PLATEAU_FABS(th);
        }
    }
}

/* Whether the want Ritz values of largest theta (the lowest eigenvalues
 * of K when K + shift I is positive definite) have all converged. */
static int plateau__stab_done(const double *lam, const int *ok, size_t L, size_t want)
{
    size_t i, j, below;
    for (i = 0; i < L; i++) {
        if (ok[i]) continue;
        for (j = 0, below = 0; j < L; j++) below += lam[j] < lam[i];
        if (below < want) return 0; /* an unconverged value among the lowest want */
    }
    return 1;
}

/* Block Lanczos (Golub and Van Loan 10.3.6, block size b = 2 so that the
 * double eigenvalues of a surface of revolution show both copies; b = 1
 * on a Hessian of at most PLATEAU_STABILITY_LANCZOS rows, whose Krylov
 * space the steps exhaust) on (K + shift I)^-1 from a fixed start: each
 * new block takes the three-term recurrence, then one Gram-Schmidt pass
 * against the whole basis (full reorthogonalisation; a second pass only
 * when DGKS asks for it).  T = Q^T (K + shift I)^-1 Q is
 * block tridiagonal; its Ritz values theta give eigenvalues
 * 1 / theta - shift of K (plateau__stab_ritz fills lam, ok and
 * st->z).  With want > 0 (K + shift I positive definite), the run stops
 * once the want lowest have converged; want = 0 runs every step. */
static void plateau__stab_lanczos(plateau__stab *st, double shift, size_t want, double *lam,
                                  int *ok, size_t *count)
{
    size_t n = st->nf, b = n > st->steps && st->steps >= 2 ? 2 : 1, blocks = st->steps / b, k, L = 0, i, j, c,
           check = 0;
    double R[4] = {0.0, 0.0, 0.0, 0.0}, tmax = 0.0, *q = st->q;
    plateau_rng rng;
    plateau_rng_seed(&rng, 20140101u);
    for (i = 0; i < st->steps * st->steps; i++) st->t[i] = 0.0;
    /* the start block: b random vectors, orthonormalised */
    for (i = 0; i < b * n; i++) q[i] = plateau_rng_uniform(&rng) - 0.5;
    (void)plateau__stab_orth(q, n, 0, q, b, 0.0, R);
    for (k = 0; k < blocks; k++) {
        size_t c0 = k * b, lo = c0 >= b ? c0 - b : 0;
        double *W = q + (c0 + b) * n;
        int broke;
        memcpy(W, q + c0 * n, b * n * sizeof(double));
        (void)plateau_lm_sparse_solve(st->fac, b, W, n);
        /* the diagonal block A_k = Q_k^T W */
        for (c = 0; c < b; c++)
            for (j = 0; j < b; j++)
                st->t[(c0 + c) * st->steps + c0 + j] = plateau__stab_dot(q + (c0 + c) * n, W + j * n, n);
        for (c = 0; c < b; c++)
            for (j = c + 1; j < b; j++) { /* symmetrise what rounding split */
                double m = 0.5 * (st->t[(c0 + c) * st->steps + c0 + j] + st->t[(c0 + j) * st->steps + c0 + c]);
                st->t[(c0 + c) * st->steps + c0 + j] = st->t[(c0 + j) * st->steps + c0 + c] = m;
            }
        for (c = 0; c < b; c++)
            if (PLATEAU_FABS(st->t[(c0 + c) * st->steps + c0 + c]) > tmax)
                tmax = PLATEAU_FABS(st->t[(c0 + c) * st->steps + c0 + c]);
        /* the three-term recurrence, W -= Q_k A_k + Q_{k-1} B_{k-1}^T (the
           coefficients are column c0 + j of T), then W against the whole
           basis, which now removes only rounding (one pass, as a rule),
           and W = Q_{k+1} R */
        for (j = 0; j < b; j++) {
            double *wj = W + j * n;
            for (c = lo; c < c0 + b; c++) {
                const double *qc = q + c * n;
                double tc = st->t[c * st->steps + c0 + j];
                for (i = 0; i < n; i++) wj[i] -= tc * qc[i];
            }
        }
        broke = plateau__stab_orth(q, n, c0 + b, W, b, 1e-13 * tmax, R);
        L = c0 + b;
        if (broke || k + 1 == blocks) break;
        for (c = 0; c < b; c++) /* the off-diagonal blocks: R below, R^T above */
            for (j = c; j < b; j++)
                st->t[(L + c) * st->steps + c0 + j] = st->t[(c0 + j) * st->steps + L + c] = R[c * b + j];
        if (want > 0 && L >= want + b && L >= check) {
            /* the check costs about 10 L^3, a block about 8 n L:
               checks are spaced so that they cost at most as much */
            size_t gap = 2 * L * L / n;
            plateau__stab_ritz(st, L, b, R, shift, lam, ok);
            if (plateau__stab_done(lam, ok, L, want)) break;
            check = L + b * (gap > 1 ? gap : 1);
        }
    }
    plateau__stab_ritz(st, L, b, R, shift, lam, ok);
    *count = L;
}

/* ---- the stability report (plateau_mesh_stability) ---- */

/* With st->order an elimination order of exactly the free vertices (the
 * last Newton solve's, on the same vertex graph unless flips or removals
 * followed it): st->node numbers the free vertices in that order and K's
 * pattern is built in it (rows in order, each its diagonal, then its free
 * neighbours in the order of vertex_edges), so that the analysis keeps the
 * given order (PLATEAU_LM_SPARSE_ORDER_NATURAL) instead of computing a
 * nested dissection.  0 (st->node as it was, nothing allocated) when
 * there is no such order; -1 when out of memory. */
static int plateau__stab_ordered(const plateau_mesh *mesh, plateau__stab *st)
{
    const plateau__solve_order *o = st->order;
    size_t k, e, q = 0, nnz, bytes;
    if (!o || o->count != st->nf || st->nf == 0) return 0;
    for (k = 0; k < st->nv; k++) st->node[k] = -1;
    for (k = 0; k < o->count; k++) {
        size_t v = (size_t)o->vertex[k];
        if (o->vertex[k] < 0 || v >= st->nv || mesh->fixed[v] || st->node[v] >= 0) break;
        st->node[v] = (plateau_index)k;
    }
    if (k < o->count) { /* not a permutation of the free vertices */
        for (k = 0, q = 0; k < st->nv; k++) st->node[k] = mesh->fixed[k] ? -1 : (plateau_index)q++;
        return 0;
    }
    nnz = st->nf + 2 * mesh->num_edges; /* an upper bound; the caller checked it */
    bytes = plateau__bytes(st->nf + 1 + nnz, sizeof(plateau_index));
    if (bytes == 0) return -1;
    st->pattern = plateau__alloc(&st->alloc, bytes);
    if (!st->pattern) return -1;
    st->sp.row_start = (plateau_index *)st->pattern;
    st->sp.cols = st->sp.row_start + st->nf + 1;
    for (k = 0; k < st->nf; k++) {
        size_t v = (size_t)o->vertex[k];
        st->sp.row_start[k] = (plateau_index)q;
        st->sp.cols[q++] = (plateau_index)k;
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1]
                                                                     : mesh->edges[2 * ed];
            if (!mesh->fixed[w]) st->sp.cols[q++] = st->node[w];
        }
    }
    st->sp.row_start[st->nf] = (plateau_index)q;
    st->xy = NULL;
    return 1;
}

/* Allocates the state, assembles H (normal motions along the unit vertex
 * normals), the lumped metric and K, and analyses K's pattern: the
 * solver's vertex-graph pattern, in the order of st->order
 * (plateau__stab_ordered) or else as plateau__solve_sparse_pattern
 * makes it, ordered by the same geometric nested dissection. */
static plateau_result plateau__stab_setup(const plateau_mesh *mesh, plateau__stab *st,
                                          plateau_stability *out, plateau_error *err)
{
    const plateau_allocator *a = &mesh->allocator;
    size_t v, e, k, t, q = 0, ne = mesh->num_edges, nt = mesh->num_triangles;
    plateau_lm_sparse_pattern pat;
    plateau_lm_sparse_options o;
    plateau_lm_result lr;
    plateau_result rc;
    double g2 = 0.0;
    int ordered;
    st->alloc = *a;
    st->nv = mesh->num_vertices;
    st->node = (plateau_index *)plateau__util_array(a, st->nv + 1, sizeof(plateau_index));
    st->diag = (double *)plateau__util_array(a, st->nv + 1, sizeof(double));
    st->off = (double *)plateau__util_array(a, ne + 1, sizeof(double));
    st->grad = (double *)plateau__util_array(a, st->nv + 1, 3 * sizeof(double));
    st->gn = (double *)plateau__util_array(a, st->nv + 1, sizeof(double));
    st->dir = (double *)plateau__util_array(a, st->nv + 1, 3 * sizeof(double));
    if (!st->node || !st->diag || !st->off || !st->grad || !st->gn || !st->dir) goto oom;
    for (v = 0; v < st->nv; v++) st->node[v] = mesh->fixed[v] ? -1 : (plateau_index)st->nf++;
    out->free_vertices = st->nf;
    plateau_mesh_area_gradient(mesh, st->grad);
    for (v = 0; v < st->nv; v++)
        if (!mesh->fixed[v]) g2 += plateau__util_dot(st->grad + 3 * v, st->grad + 3 * v);
    out->area_gradient_norm = PLATEAU_SQRT(g2);
    if (st->nf == 0) return PLATEAU_OK;
    /* the normals once per vertex (NULL directions would recompute a
       vertex's normal at each of its corners: the sum of the squared
       valences, 4 10^7 cross products for ten fan vertices of valence
       2000), and the cells, from one cross product per triangle: the sums
       of plateau_vertex_normal and plateau_vertex_area, in their order */
    if (nt > ((size_t)-1 - st->nv) / 4) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the stability report's pattern is too large", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    st->tri = (double *)plateau__util_array(a, 4 * nt + st->nv, sizeof(double));
    if (!st->tri) goto oom;
    for (t = 0; t < nt; t++) {
        plateau__geo_tri_cross(mesh, t, st->tri + 4 * t);
        st->tri[4 * t + 3] = 0.5 * plateau__util_norm(st->tri + 4 * t);
    }
    for (v = 0; v < st->nv; v++) {
        double n[3] = {0.0, 0.0, 0.0}, cell = 0.0, len, *d = st->dir + 3 * v;
        for (e = mesh->vertex_triangle_start[v]; e < mesh->vertex_triangle_start[v + 1]; e++) {
            const double *c = st->tri + 4 * (size_t)mesh->vertex_triangles[e];
            n[0] += c[0]; n[1] += c[1]; n[2] += c[2];
            cell += c[3];
        }
        len = plateau__util_norm(n);
        if (len > 0.0) {
            d[0] = n[0] / len; d[1] = n[1] / len; d[2] = n[2] / len;
        } else {
            d[0] = d[1] = d[2] = 0.0;
        }
        st->tri[4 * nt + v] = cell / 3.0;
    }
    rc = plateau_mesh_area_hessian_normal(mesh, st->dir, st->gn, st->diag, st->off, err);
    if (rc != PLATEAU_OK) return rc;
    st->steps = st->nf < PLATEAU_STABILITY_LANCZOS ? st->nf : PLATEAU_STABILITY_LANCZOS;
    if (ne > ((size_t)-1 - st->nf) / 2) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the stability report's pattern is too large", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    ordered = plateau__stab_ordered(mesh, st);
    if (ordered == 0) st->pattern = plateau__solve_sparse_pattern(mesh, st->nf, &st->sp, &st->xy);
    st->vals = (double *)plateau__util_array(a, st->nf + 2 * ne, sizeof(double));
    st->msq = (double *)plateau__util_array(a, st->nf, sizeof(double));
    st->q = (double *)plateau__util_array(a, st->nf, (st->steps + 2) * sizeof(double));
    st->t = (double *)plateau__util_array(a, st->steps * st->steps, sizeof(double));
    st->z = (double *)plateau__util_array(a, st->steps * st->steps, sizeof(double));
    st->e = (double *)plateau__util_array(a, st->steps * st->steps, sizeof(double));
    st->w = (double *)plateau__util_array(a, st->nf, sizeof(double));
    if (!st->pattern || !st->vals || !st->msq || !st->q || !st->t || !st->z || !st->e || !st->w)
        goto oom;
    for (v = 0; v < st->nv; v++) {
        double mv;
        if (mesh->fixed[v]) continue;
        mv = st->tri[4 * nt + v];
        if (!(mv > 0.0)) {
            plateau__util_error(err, PLATEAU_ERR_DEGENERATE_TRIANGLE, (long)v,
                                "vertex @ has no area around it: no stability report", (long)v, 0);
            return PLATEAU_ERR_DEGENERATE_TRIANGLE;
        }
        st->msq[st->node[v]] = PLATEAU_SQRT(mv);
    }
    /* K's values in the pattern's order: row by row (st->node's order),
       each its diagonal, then its free neighbours in the order of
       vertex_edges */
    for (k = 0, v = 0; k < st->nf; k++, v++) {
        double d;
        if (ordered) v = (size_t)st->order->vertex[k];
        else while (mesh->fixed[v]) v++;
        d = st->diag[v] / (st->msq[st->node[v]] * st->msq[st->node[v]]);
        st->vals[q++] = d;
        if (PLATEAU_FABS(d) > st->scale) st->scale = PLATEAU_FABS(d);
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            plateau_index w = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1]
                                                                     : mesh->edges[2 * ed];
            if (mesh->fixed[w]) continue;
            st->vals[q++] = st->off[ed] / (st->msq[st->node[v]] * st->msq[st->node[w]]);
        }
    }
    st->nnz = q;
    pat.nodes = st->nf;
    pat.block = 1;
    pat.row_start = st->sp.row_start;
    pat.cols = st->sp.cols;
    memset(&o, 0, sizeof o);
    o.allocator = *a;
    if (ordered) o.ordering = PLATEAU_LM_SPARSE_ORDER_NATURAL;
    if (!ordered && st->order && st->order->sym && st->order->nfree == st->nf &&
        plateau__util_same_indices(st->order->row_start, st->sp.row_start, st->nf + 1) &&
        plateau__util_same_indices(st->order->cols, st->sp.cols, st->nnz)) {
        /* the last coarse-to-fine level's analysis of this very pattern */
        lr = plateau_lm_sparse_factor_create(st->order->sym, PLATEAU_LM_SPARSE_LDLT, NULL, 0, &st->fac);
    } else {
        lr = plateau_lm_sparse_analyze(&pat, st->xy, &o, &st->sym);
        if (lr == PLATEAU_LM_OK)
            lr = plateau_lm_sparse_factor_create(st->sym, PLATEAU_LM_SPARSE_LDLT, NULL, 0, &st->fac);
    }
    if (lr == PLATEAU_LM_ERR_OVERFLOW) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the stability report's factor is too large", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    if (lr != PLATEAU_LM_OK) goto oom;
    return PLATEAU_OK;
oom:
    plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_stability", 0, 0);
    return PLATEAU_ERR_OUT_OF_MEMORY;
}

/* L D L^T of K + shift I; the count of negative pivots in *neg.  Returns
 * 0 on a breakdown (a pivot near zero). */
static int plateau__stab_factor(plateau__stab *st, double shift, size_t *neg)
{
    size_t pos;
    if (plateau_lm_sparse_factorize(st->fac, st->vals, shift) != PLATEAU_LM_OK) return 0;
    return plateau_lm_sparse_inertia(st->fac, neg, &pos) == PLATEAU_LM_OK;
}

/* Picks the lowest eigenvalues from the last Lanczos run into the report:
 * in ascending order, stopping at the first unconverged Ritz value, except
 * that a run at a shift inside the spectrum (below_all 0) skips its
 * unconverged values below -index_shift (they stand for eigenvalues far
 * from the shift, all of which below it are known converged).  pick gets
 * the Ritz indices. */
static size_t plateau__stab_pick(const double *lam, const int *ok, size_t count, int below_all,
                                 double index_shift, size_t want, plateau_stability *out,
                                 size_t *pick)
{
    size_t taken = 0, i, j;
    unsigned char used[PLATEAU_STABILITY_LANCZOS];
    for (i = 0; i < count; i++) used[i] = 0;
    for (i = 0; i < count && taken < want; i++) {
        size_t best = count;
        for (j = 0; j < count; j++)
            if (!used[j] && (best == count || lam[j] < lam[best])) best = j;
        used[best] = 1;
        if (!ok[best]) {
            if (!below_all && lam[best] < -index_shift) continue;
            break;
        }
        out->lowest_eigenvalues[taken] = lam[best];
        pick[taken++] = best;
    }
    return taken;
}

/* The mode of Ritz pair p of the last run: u = M^-1/2 Q z_p, its largest
 * entry positive, at modes (num_vertices values, 0 at fixed vertices). */
static void plateau__stab_mode(const plateau__stab *st, size_t L, size_t p, double *modes)
{
    size_t v, i, j;
    double big = 0.0;
    for (i = 0; i < st->nf; i++) {
        double y = 0.0;
        for (j = 0; j < L; j++) y += st->q[j * st->nf + i] * st->z[j * L + p];
        st->w[i] = y / st->msq[i];
        if (PLATEAU_FABS(st->w[i]) > PLATEAU_FABS(big)) big = st->w[i];
    }
    for (v = 0; v < st->nv; v++)
        modes[v] = st->node[v] < 0 ? 0.0 : (big < 0.0 ? -1.0 : 1.0) * st->w[st->node[v]];
}

/* plateau_mesh_stability, K's rows in the elimination order order (NULL:
 * the report orders them itself; plateau__stab_ordered). */
static plateau_result plateau__stab_compute(const plateau_mesh *mesh, size_t num_eigenvalues,
                                            const plateau__solve_order *order,
                                            plateau_stability *stability, double *modes,
                                            plateau_error *err)
{
    plateau__stab st;
    plateau_result rc;
    double lam[PLATEAU_STABILITY_LANCZOS], shift = 0.0;
    int ok[PLATEAU_STABILITY_LANCZOS], below_all = 1;
    size_t pick[PLATEAU_STABILITY_MAX_EIGENVALUES], count = 0, neg = 0, i, tries;
    if (stability) memset(stability, 0, sizeof *stability);
    if (!mesh || !stability || !mesh->positions || !mesh->vertex_edge_start ||
        num_eigenvalues > PLATEAU_STABILITY_MAX_EIGENVALUES) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_mesh_stability needs a mesh with adjacency, a report and at most 8 eigenvalues", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (modes) {
        size_t bytes = plateau__bytes(mesh->num_vertices, num_eigenvalues * sizeof(double));
        if (bytes == 0 && mesh->num_vertices != 0 && num_eigenvalues != 0) {
            plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the modes' size overflows", 0, 0);
            return PLATEAU_ERR_OVERFLOW;
        }
        if (bytes) memset(modes, 0, bytes);
    }
    memset(&st, 0, sizeof st);
    st.vectors = modes != NULL;
    st.order = order;
    rc = plateau__stab_setup(mesh, &st, stability, err);
    if (rc != PLATEAU_OK || st.nf == 0) {
        stability->computed = 0;
        plateau__stab_free(&st);
        return rc;
    }
    /* the index: Sylvester's law on K, or on K + shift I after a breakdown */
    for (tries = 0; !plateau__stab_factor(&st, shift, &neg); tries++) {
        if (tries == 15) {
            plateau__util_error(err, PLATEAU_ERR_SOLVER, -1,
                                "the stability report found no shift that factorises the Hessian", 0, 0);
            plateau__stab_free(&st);
            return PLATEAU_ERR_SOLVER;
        }
        shift = shift == 0.0 ? 1e-10 * st.scale : 10.0 * shift;
    }
    stability->index = neg;
    stability->shift = shift;
    stability->computed = 1;
    if (num_eigenvalues > 0) {
        double s = shift, low = 0.0;
        size_t found = 0;
        plateau__stab_lanczos(&st, s, neg == 0 ? num_eigenvalues : 0, lam, ok, &count);
        for (i = 0; i < count; i++)
            if (ok[i] && lam[i] < -shift) {
                found++;
                if (lam[i] < low) low = lam[i];
            }
        if (neg > 0 && found >= neg) {
            below_all = 0;
        } else if (neg > 0) {
            /* a shift below the spectrum: K + s I positive definite */
            size_t n2 = 1;
            s = low < 0.0 ? -2.0 * low : st.scale;
            for (tries = 0; tries < 20; tries++, s *= 4.0)
                if (plateau__stab_factor(&st, s, &n2) && n2 == 0) break;
            if (tries < 20) plateau__stab_lanczos(&st, s, num_eigenvalues, lam, ok, &count);
            else count = 0;
        }
        stability->num_eigenvalues =
            plateau__stab_pick(lam, ok, count, below_all, shift, num_eigenvalues, stability, pick);
        if (modes)
            for (i = 0; i < stability->num_eigenvalues; i++)
                plateau__stab_mode(&st, count, pick[i], modes + i * mesh->num_vertices);
    }
    plateau__stab_free(&st);
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_mesh_stability(const plateau_mesh *mesh, size_t num_eigenvalues,
                                                  plateau_stability *stability, double *modes,
                                                  plateau_error *err)
{
    return plateau__stab_compute(mesh, num_eigenvalues, NULL, stability, modes, err);
}

/* ---- critical points of a chosen index (plateau_mesh_critical_point) ---- */

/* The search's limits: the refinement angle (twice the mean turning
 * angle of the boundary; its range in radians), the vertices at most
 * PLATEAU__CRIT_GROWTH times the caller's, at most PLATEAU__CRIT_STAGES
 * rounds of splits after the climb, the fall of the area (a fraction of
 * what the climb has gained) and its rise (a multiple of the start's)
 * that end a climb gone astray, and the Newton steps of max_steps 0. */
#define PLATEAU__CRIT_THETA_FACTOR 2.0
#define PLATEAU__CRIT_THETA_MIN 0.01
#define PLATEAU__CRIT_THETA_MAX 0.5
#define PLATEAU__CRIT_GROWTH 16
#define PLATEAU__CRIT_STAGES 24
#define PLATEAU__CRIT_CLIMB_FALL 0.05
#define PLATEAU__CRIT_CLIMB_RISE 2.0
#define PLATEAU__CRIT_CLIMB_COARSER 2.0
#define PLATEAU__CRIT_STEPS 1000 /* max_steps 0 */

/* y = Q z_p (nf values, the Ritz vector of pair p of the last Lanczos run
 * of L steps, in the coordinates of K) into y. */
static void plateau__crit_ritz(const plateau__stab *st, size_t L, size_t p, double *y)
{
    size_t i, j;
    double big = 0.0;
    for (i = 0; i < st->nf; i++) {
        double s = 0.0;
        for (j = 0; j < L; j++) s += st->q[j * st->nf + i] * st->z[j * L + p];
        y[i] = s;
        if (PLATEAU_FABS(s) > PLATEAU_FABS(big)) big = s;
    }
    if (big < 0.0) /* the sign of a mode: its largest entry positive, as in every iteration */
        for (i = 0; i < st->nf; i++) y[i] = -y[i];
}

/* Moves every free vertex v by t[row(v)] / sqrt(|B_v|) along its unit
 * normal (the normals the Hessian used), the largest move capped at cap:
 * returns the factor applied (1 when uncapped). */
static double plateau__crit_move(plateau_mesh *mesh, const plateau__stab *st, const double *s,
                                 const double *normals, double cap)
{
    size_t v;
    double big = 0.0, f = 1.0;
    for (v = 0; v < st->nv; v++)
        if (st->node[v] >= 0) {
            double t = PLATEAU_FABS(s[st->node[v]] / st->msq[st->node[v]]);
            if (t > big) big = t;
        }
    if (big > cap) f = cap / big;
    for (v = 0; v < st->nv; v++)
        if (st->node[v] >= 0) {
            double t = f * s[st->node[v]] / st->msq[st->node[v]];
            mesh->positions[3 * v] += t * normals[3 * v];
            mesh->positions[3 * v + 1] += t * normals[3 * v + 1];
            mesh->positions[3 * v + 2] += t * normals[3 * v + 2];
        }
    return f;
}

/* One tangential smoothing sweep: every free vertex moves half way to the
 * mean of its neighbours within its tangent plane (the surface keeps its
 * shape to first order; the triangles stay shapely while the normal steps
 * are large). */
static void plateau__crit_smooth(plateau_mesh *mesh, const double *normals, double *scratch)
{
    size_t v, e;
    for (v = 0; v < mesh->num_vertices; v++) {
        double c[3] = {0.0, 0.0, 0.0}, d;
        size_t deg = mesh->vertex_edge_start[v + 1] - mesh->vertex_edge_start[v];
        scratch[3 * v] = scratch[3 * v + 1] = scratch[3 * v + 2] = 0.0;
        if (mesh->fixed[v] || deg == 0) continue;
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            size_t w = (size_t)(mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed]);
            c[0] += mesh->positions[3 * w] / (double)deg - mesh->positions[3 * v] / (double)deg;
            c[1] += mesh->positions[3 * w + 1] / (double)deg - mesh->positions[3 * v + 1] / (double)deg;
            c[2] += mesh->positions[3 * w + 2] / (double)deg - mesh->positions[3 * v + 2] / (double)deg;
        }
        d = plateau__util_dot(c, normals + 3 * v);
        scratch[3 * v] = 0.5 * (c[0] - d * normals[3 * v]);
        scratch[3 * v + 1] = 0.5 * (c[1] - d * normals[3 * v + 1]);
        scratch[3 * v + 2] = 0.5 * (c[2] - d * normals[3 * v + 2]);
    }
    for (v = 0; v < 3 * mesh->num_vertices; v++) mesh->positions[v] += scratch[v];
}

/* The area after moving every free vertex by delta y_v / sqrt(|B_v|)
 * along its normal; the positions are restored from keep. */
static double plateau__crit_trial(plateau_mesh *mesh, const plateau__stab *st, const double *y,
                                  const double *normals, double delta, double *keep)
{
    double area;
    size_t v, j;
    memcpy(keep, mesh->positions, 3 * st->nv * sizeof(double));
    for (v = 0; v < st->nv; v++)
        if (st->node[v] >= 0)
            for (j = 0; j < 3; j++)
                mesh->positions[3 * v + j] += delta * y[st->node[v]] / st->msq[st->node[v]] * normals[3 * v + j];
    area = plateau_mesh_area(mesh);
    memcpy(mesh->positions, keep, 3 * st->nv * sizeof(double));
    return area;
}

/* 1 when the mesh is one plateau_mesh_check would pass on its triangles:
 * no inverted or degenerate triangle and no folded edge (a search may
 * report a critical point only on such a mesh). */
static int plateau__crit_valid(const plateau_mesh *mesh)
{
    plateau_quality q;
    plateau_mesh_quality(mesh, &q);
    return q.inverted_triangles == 0 && q.degenerate_triangles == 0 && q.folded_edges == 0;
}

/* The angle the mesh is refined to: PLATEAU__CRIT_THETA_FACTOR times the
 * mean turning angle of the boundary polygons at their vertices (pi minus
 * the corner angle between a boundary vertex's two boundary edges; 2 pi /
 * m for a regular m-gon), kept in [PLATEAU__CRIT_THETA_MIN,
 * PLATEAU__CRIT_THETA_MAX].  An edge turns the surface by about its length
 * times the curvature, so edges no longer than theta / curvature resolve
 * the film about as finely as the polygon resolves its boundary. */
static double plateau__crit_theta(const plateau_mesh *mesh)
{
    size_t v, e, n = 0;
    double sum = 0.0, th;
    for (v = 0; v < mesh->num_vertices; v++) {
        plateau_index nb[2];
        int k = 0;
        if (!mesh->fixed[v]) continue;
        for (e = mesh->vertex_edge_start[v]; e < mesh->vertex_edge_start[v + 1] && k < 3; e++) {
            size_t ed = (size_t)mesh->vertex_edges[e];
            if (mesh->edge_triangles[2 * ed] >= 0 && mesh->edge_triangles[2 * ed + 1] >= 0) continue;
            if (k < 2) nb[k] = mesh->edges[2 * ed] == (plateau_index)v ? mesh->edges[2 * ed + 1] : mesh->edges[2 * ed];
            k++;
        }
        if (k != 2) continue;
        sum += PLATEAU__PI - plateau__util_corner_angle(plateau__geo_pos(mesh, (plateau_index)v),
                                                       plateau__geo_pos(mesh, nb[0]), plateau__geo_pos(mesh, nb[1]));
        n++;
    }
    th = n ? PLATEAU__CRIT_THETA_FACTOR * sum / (double)n : PLATEAU__CRIT_THETA_MAX;
    if (!(th >= PLATEAU__CRIT_THETA_MIN)) th = PLATEAU__CRIT_THETA_MIN;
    if (th > PLATEAU__CRIT_THETA_MAX) th = PLATEAU__CRIT_THETA_MAX;
    return th;
}

/* kappa[v] = sqrt(|K_v|), K_v = (2 pi - the angles at v) / (A_v / 3) the
 * angle defect over a third of the area of v's triangles (the discrete
 * Gaussian curvature): on a critical point of the area H = 0, so k1 = -k2
 * and sqrt(-K) is the magnitude of both principal curvatures.  0 at
 * fixed vertices (an edge takes the larger of its ends). */
static void plateau__crit_kappa(const plateau_mesh *mesh, double *kappa)
{
    size_t v, j;
    for (v = 0; v < mesh->num_vertices; v++) {
        double ang = 0.0, area = 0.0, nn[3];
        kappa[v] = 0.0;
        if (mesh->fixed[v]) continue;
        for (j = mesh->vertex_triangle_start[v]; j < mesh->vertex_triangle_start[v + 1]; j++) {
            size_t t = (size_t)mesh->vertex_triangles[j];
            const plateau_index *tv = mesh->triangles + 3 * t;
            int k = tv[0] == (plateau_index)v ? 0 : tv[1] == (plateau_index)v ? 1 : 2;
            ang += plateau__util_corner_angle(plateau__geo_pos(mesh, tv[k]), plateau__geo_pos(mesh, tv[(k + 1) % 3]),
                                              plateau__geo_pos(mesh, tv[(k + 2) % 3]));
            area += plateau_triangle_normal(mesh, t, nn);
        }
        if (area > 0.0) kappa[v] = PLATEAU_SQRT(3.0 * PLATEAU_FABS(2.0 * PLATEAU__PI - ang) / area);
    }
}

/* One pass of edge splits: every interior edge whose length times the
 * larger curvature of its ends (plateau__crit_kappa) exceeds theta is
 * split at the midpoint of the cubic through its ends tangent to their
 * tangent planes (as plateau__c2f_subdivide places it), each triangle
 * split once a pass (edges taken in order, an edge skipped when one of
 * its triangles is split already), the vertices at most max_nv.  The two
 * triangles (a, b, c), (b, a, d) of a split edge become (a, p, c),
 * (p, b, c), (b, p, d), (p, a, d).  *count: the vertices added.  The
 * mark array holds the triangle's split edge (nt entries, -1: none), then
 * each split edge's new vertex (ne entries). */
static plateau_result plateau__crit_split(plateau_mesh *mesh, double theta, size_t max_nv, size_t *count,
                                          plateau_error *err)
{
    const plateau_allocator *al = &mesh->allocator;
    size_t nv = mesh->num_vertices, nt = mesh->num_triangles, ne = mesh->num_edges, e, t, n = 0, kt = 0;
    double *kappa = (double *)plateau__util_array(al, nv + ne + 1, 4 * sizeof(double)), *pos;
    plateau_index *mark = (plateau_index *)plateau__util_array(al, nt + ne + 1, sizeof(plateau_index));
    plateau_index *tri = (plateau_index *)plateau__util_array(al, nt + 2 * ne + 1, 3 * sizeof(plateau_index));
    unsigned char *fixed = (unsigned char *)plateau__util_array(al, nv + ne + 1, 1);
    plateau_mesh out;
    plateau_result rc = PLATEAU_OK;
    *count = 0;
    if (!kappa || !mark || !tri || !fixed) {
        plateau__free(al, kappa);
        plateau__free(al, mark);
        plateau__free(al, tri);
        plateau__free(al, fixed);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_critical_point", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    pos = kappa + nv; /* nv doubles hold kappa, then 3 (nv + ne) the positions */
    plateau__crit_kappa(mesh, kappa);
    memcpy(pos, mesh->positions, 3 * nv * sizeof(double));
    memcpy(fixed, mesh->fixed, nv);
    for (t = 0; t < nt; t++) mark[t] = -1;
    for (e = 0; e < ne && nv + n < max_nv && nv + n < (size_t)PLATEAU_INDEX_MAX; e++) {
        plateau_index t1 = mesh->edge_triangles[2 * e], t2 = mesh->edge_triangles[2 * e + 1];
        size_t a = (size_t)mesh->edges[2 * e], b = (size_t)mesh->edges[2 * e + 1], p = nv + n;
        double d[3], na[3], nb[3], wa, wb, k = kappa[a] > kappa[b] ? kappa[a] : kappa[b];
        int j;
        if (t1 < 0 || t2 < 0 || mark[t1] >= 0 || mark[t2] >= 0) continue;
        plateau__util_sub(mesh->positions + 3 * b, mesh->positions + 3 * a, d);
        if (!(plateau__util_norm(d) * k > theta)) continue;
        plateau_vertex_normal(mesh, a, na);
        plateau_vertex_normal(mesh, b, nb);
        wa = plateau__util_dot(d, na);
        wb = -plateau__util_dot(d, nb);
        for (j = 0; j < 3; j++)
            pos[3 * p + (size_t)j] = 0.5 * (mesh->positions[3 * a + (size_t)j] + mesh->positions[3 * b + (size_t)j]) -
                                     (wa * na[j] + wb * nb[j]) / 8.0;
        fixed[p] = 0;
        mark[t1] = mark[t2] = (plateau_index)e;
        mark[nt + e] = (plateau_index)p;
        n++;
    }
    for (t = 0; t < nt; t++) {
        const plateau_index *tv = mesh->triangles + 3 * t;
        plateau_index *o = tri + 3 * kt, p;
        int k;
        if (mark[t] < 0) {
            memcpy(o, tv, 3 * sizeof(plateau_index));
            kt++;
            continue;
        }
        p = mark[nt + (size_t)mark[t]]; /* the new vertex of the edge split */
        for (k = 0; k < 3 && mesh->triangle_edges[3 * t + (size_t)k] != mark[t]; k++) {}
        o[0] = tv[k]; o[1] = p; o[2] = tv[(k + 2) % 3];
        o[3] = p; o[4] = tv[(k + 1) % 3]; o[5] = tv[(k + 2) % 3];
        kt += 2;
    }
    if (n > 0) rc = plateau_mesh_create(pos, nv + n, fixed, tri, kt, al, &out, err);
    if (n > 0 && rc == PLATEAU_OK) {
        plateau_mesh_free(mesh);
        *mesh = out;
        *count = n;
    }
    plateau__free(al, kappa);
    plateau__free(al, mark);
    plateau__free(al, tri);
    plateau__free(al, fixed);
    return rc;
}

/* The state of one iteration of the search. */
typedef struct plateau__crit {
    size_t index, neg;    /* the index asked for; the negative pivots of K + fshift I */
    double fshift, cap;   /* the factorisation's shift; the largest normal move */
    double theta;         /* the refinement angle (plateau__crit_theta) */
    size_t max_nv;        /* the most vertices the splits may make */
    double *gh, *s, *y;   /* nf: M^-1/2 g, the step, a Ritz vector */
    double *normals, *keep; /* 3 nv each */
    double dir[PLATEAU_STABILITY_MAX_EIGENVALUES]; /* climbing direction per mode, 0: not chosen */
    struct plateau__util_budget *budget; /* options.max_seconds of a solve, or NULL */
    int timed_out;        /* the budget ran out before the search ended */
} plateau__crit;

/* The step of one iteration in the coordinates of K (c->s) from the
 * factorisation of K + fshift I: Newton's step with its components along
 * the lowest c->index eigenvectors replaced by a step up (Cerjan and
 * Miller's eigenvector following): -gh_k / lambda_k where lambda_k < 0
 * (Newton towards the maximum along that mode), else a climb of the
 * largest move cap, in the direction along which the area rises least (a
 * trial move each way, chosen once).  When K has more negative eigenvalues
 * than the index, the rest of the step solves with K + sigma I, sigma above
 * them.  Returns 0 when too few Ritz pairs converged. */
static int plateau__crit_step(plateau_mesh *mesh, plateau__stab *st, plateau__crit *c)
{
    double lam[PLATEAU_STABILITY_LANCZOS], cv[PLATEAU_STABILITY_MAX_EIGENVALUES];
    int ok[PLATEAU_STABILITY_LANCZOS];
    size_t pick[PLATEAU_STABILITY_MAX_EIGENVALUES], count = 0, got, i, k, n = st->nf;
    plateau_stability tmp;
    memset(&tmp, 0, sizeof tmp);
    plateau__stab_lanczos(st, c->fshift, c->neg == 0 ? c->index + 1 : 0, lam, ok, &count);
    got = plateau__stab_pick(lam, ok, count, c->neg == 0, c->fshift, c->index + 1, &tmp, pick);
    if (got < c->index) return 0;
    if (c->neg > c->index) { /* shift the other negative eigenvalues away */
        double sigma = got > c->index ? -1.5 * tmp.lowest_eigenvalues[c->index] : 0.0;
        if (!(sigma > 1e-3 * st->scale)) sigma = 1e-3 * st->scale;
        if (!plateau__stab_factor(st, sigma, &k)) return 0;
    }
    memcpy(c->s, c->gh, n * sizeof(double));
    if (plateau_lm_sparse_solve(st->fac, 1, c->s, n) != PLATEAU_LM_OK) return 0;
    for (i = 0; i < n; i++) c->s[i] = -c->s[i];
    for (k = 0; k < c->index; k++) {
        double gi = 0.0, si = 0.0, want, l = tmp.lowest_eigenvalues[k], ymax = 0.0;
        plateau__crit_ritz(st, count, pick[k], c->y);
        for (i = 0; i < n; i++) {
            gi += c->y[i] * c->gh[i];
            si += c->y[i] * c->s[i];
            if (PLATEAU_FABS(c->y[i] / st->msq[i]) > ymax) ymax = PLATEAU_FABS(c->y[i] / st->msq[i]);
        }
        if (l < 0.0) {
            want = -gi / l;
        } else {
            if (c->dir[k] == 0.0) {
                double d = c->cap / ymax;
                double up = plateau__crit_trial(mesh, st, c->y, c->normals, d, c->keep);
                double down = plateau__crit_trial(mesh, st, c->y, c->normals, -d, c->keep);
                c->dir[k] = up <= down ? 1.0 : -1.0;
            }
            want = c->dir[k] * c->cap / ymax;
        }
        cv[k] = want - si;
    }
    for (k = 0; k < c->index; k++) { /* second pass: the corrections */
        plateau__crit_ritz(st, count, pick[k], c->y);
        for (i = 0; i < n; i++) c->s[i] += cv[k] * c->y[i];
    }
    return 1;
}

/* Frees the search's vectors. */
static void plateau__crit_free(const plateau_allocator *a, plateau__crit *c)
{
    plateau__free(a, c->gh);
    plateau__free(a, c->s);
    plateau__free(a, c->y);
    plateau__free(a, c->normals);
    plateau__free(a, c->keep);
    c->gh = c->s = c->y = c->normals = c->keep = NULL;
}

/* (Re)allocates the search's vectors for nv vertices; 0 when out of memory. */
static int plateau__crit_alloc(const plateau_allocator *a, plateau__crit *c, size_t nv)
{
    plateau__crit_free(a, c);
    c->gh = (double *)plateau__util_array(a, nv + 1, sizeof(double));
    c->s = (double *)plateau__util_array(a, nv + 1, sizeof(double));
    c->y = (double *)plateau__util_array(a, nv + 1, sizeof(double));
    c->normals = (double *)plateau__util_array(a, nv + 1, 3 * sizeof(double));
    c->keep = (double *)plateau__util_array(a, nv + 1, 3 * sizeof(double));
    return c->gh && c->s && c->y && c->normals && c->keep;
}

/* Keeps the mesh fit after a capped step: Delaunay flips on the intrinsic
 * metric, then one pass of splits where the surface bends across an edge
 * by more than c->theta (plateau__crit_split: the neck of a catenoid
 * narrowing 4-6 times needs more vertices round it), flipped again; the
 * search's vectors follow the vertex count and the largest normal move
 * the mean edge length. */
static plateau_result plateau__crit_fit(plateau_mesh *mesh, plateau__crit *c, plateau_error *err)
{
    size_t added = 0;
    plateau_result rc = plateau_mesh_delaunay_flips(mesh, 0, NULL, err);
    if (rc == PLATEAU_OK) rc = plateau__crit_split(mesh, c->theta, c->max_nv, &added, err);
    if (rc != PLATEAU_OK || added == 0) return rc;
    rc = plateau_mesh_delaunay_flips(mesh, 0, NULL, err);
    if (rc != PLATEAU_OK) return rc;
    if (!plateau__crit_alloc(&mesh->allocator, c, mesh->num_vertices)) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_critical_point", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    c->cap = 0.1 * plateau_mean_edge_length(mesh);
    return PLATEAU_OK;
}

/* One iteration: the Hessian, gradient and normals at the current mesh,
 * the index of K; *done when the index is the one asked for and the
 * gradient passes tol, else (unless test_only) the step is taken, and
 * while it is capped the mesh is kept fit as Surface Evolver's users keep
 * it between saddle steps: a tangential smoothing sweep (vertex
 * averaging), then Delaunay flips on the intrinsic metric (equiangulation,
 * plateau_mesh_delaunay_flips, which rebuilds the adjacency; the next
 * iteration builds the Hessian's pattern anew).  Returns PLATEAU_OK, or an
 * error of the setup or the flips; *stuck when no step could be formed. */
static plateau_result plateau__crit_iterate(plateau_mesh *mesh, plateau__crit *c, double tol, int test_only,
                                            int *done, int *stuck, plateau_error *err)
{
    plateau__stab st;
    plateau_stability tmp;
    plateau_result rc;
    size_t v, tries;
    double gmax = 0.0;
    memset(&st, 0, sizeof st);
    memset(&tmp, 0, sizeof tmp);
    st.vectors = 1; /* the step follows the Ritz vectors */
    *done = *stuck = 0;
    rc = plateau__stab_setup(mesh, &st, &tmp, err);
    if (rc == PLATEAU_OK && st.nf == 0) *done = 1;
    if (rc != PLATEAU_OK || st.nf == 0) {
        plateau__stab_free(&st);
        return rc;
    }
    for (v = 0; v < st.nv; v++) {
        (void)plateau_vertex_normal(mesh, v, c->normals + 3 * v);
        if (st.node[v] >= 0) {
            double m2 = st.msq[st.node[v]];
            c->gh[st.node[v]] = st.gn[v] / m2;
            if (PLATEAU_FABS(st.gn[v]) / (m2 * m2) > gmax) gmax = PLATEAU_FABS(st.gn[v]) / (m2 * m2);
        }
    }
    c->fshift = 0.0;
    for (tries = 0; !plateau__stab_factor(&st, c->fshift, &c->neg); tries++) {
        if (tries == 15) {
            *stuck = 1;
            plateau__stab_free(&st);
            return PLATEAU_OK;
        }
        c->fshift = c->fshift == 0.0 ? 1e-10 * st.scale : 10.0 * c->fshift;
    }
    if (c->neg == c->index && gmax <= tol) {
        *done = 1;
    } else if (test_only) {
        /* the step budget is spent: the mesh as it is */
    } else if (!plateau__crit_step(mesh, &st, c)) {
        *stuck = 1;
    } else if (plateau__crit_move(mesh, &st, c->s, c->normals, c->cap) < 1.0) {
        plateau__crit_smooth(mesh, c->normals, c->keep);
        plateau__stab_free(&st);
        return plateau__crit_fit(mesh, c, err);
    }
    plateau__stab_free(&st);
    return PLATEAU_OK;
}

/* Newton steps from the current mesh until *done, *stuck, max_steps
 * steps (*steps counts them), or, while the Hessian has fewer negative
 * eigenvalues than the index (the climb), the area falls by more than
 * PLATEAU__CRIT_CLIMB_FALL of what the climb has gained (the climb passed
 * a ridge that leads to no saddle) or rises above PLATEAU__CRIT_CLIMB_RISE
 * times the start's (a film swelling without end): *stuck.  A converged mesh with an
 * inverted, degenerate or folded triangle is not done (*stuck). */
static plateau_result plateau__crit_run(plateau_mesh *mesh, plateau__crit *c, double tol, size_t max_steps,
                                        size_t *steps, int *done, int *stuck, plateau_error *err)
{
    plateau_result rc = PLATEAU_OK;
    double first = plateau_mesh_area(mesh), start = first, top = first;
    size_t it, nv = mesh->num_vertices;
    *done = *stuck = 0;
    for (it = 0; it <= max_steps && rc == PLATEAU_OK && !*done && !*stuck; it++) {
        /* it == max_steps: the last iteration only tests convergence */
        double area;
        if (plateau__util_time_up(c->budget)) { /* options.max_seconds: the mesh as it is */
            c->timed_out = 1;
            break;
        }
        rc = plateau__crit_iterate(mesh, c, tol, it == max_steps, done, stuck, err);
        if (rc != PLATEAU_OK || *done || *stuck || it == max_steps) break;
        (*steps)++;
        area = plateau_mesh_area(mesh);
        if (c->neg >= c->index) continue;
        if (mesh->num_vertices != nv) { /* splits change the area: measure from here */
            nv = mesh->num_vertices;
            start = top = area;
        }
        if (area > top) top = area;
        else if (area < top - PLATEAU__CRIT_CLIMB_FALL * (top - start)) *stuck = 1;
        if (area > PLATEAU__CRIT_CLIMB_RISE * first) *stuck = 1;
    }
    if (rc == PLATEAU_ERR_DEGENERATE_TRIANGLE) { /* a collapsed step: not converged */
        rc = PLATEAU_OK;
        *stuck = 1;
    }
    if (*done && !plateau__crit_valid(mesh)) {
        *done = 0;
        *stuck = 1;
    }
    return rc;
}

/* A copy of the mesh (positions, flags, triangles) through its allocator. */
static plateau_result plateau__crit_copy(const plateau_mesh *mesh, plateau_mesh *copy, plateau_error *err)
{
    return plateau_mesh_create(mesh->positions, mesh->num_vertices, mesh->fixed, mesh->triangles,
                               mesh->num_triangles, &mesh->allocator, copy, err);
}

/* The climb from the caller's mesh, then the refinement: the climb goes
 * up the lowest modes in the directions the first step chose; when it
 * does not converge it starts again from the caller's mesh in the
 * opposite directions.  Once converged, the edges the surface bends
 * across by more than the boundary's turning angle are split
 * (plateau__crit_split), the mesh is made intrinsically Delaunay again
 * and Newton's steps converge anew, until no edge is split. */
static plateau_result plateau__crit_search(plateau_mesh *mesh, plateau__crit *c, double tol,
                                           size_t max_steps, size_t *steps, int *done, plateau_error *err)
{
    const plateau_allocator *a = &mesh->allocator;
    plateau_mesh start;
    plateau_result rc;
    size_t k, added = 1, stage;
    double cap = c->cap;
    int stuck = 0, turn = 0;
    c->theta = plateau__crit_theta(mesh);
    c->max_nv = PLATEAU__CRIT_GROWTH * mesh->num_vertices;
    if (c->max_nv / PLATEAU__CRIT_GROWTH != mesh->num_vertices) c->max_nv = (size_t)PLATEAU_INDEX_MAX;
    rc = plateau__crit_copy(mesh, &start, err);
    if (rc != PLATEAU_OK) return rc;
    c->theta *= PLATEAU__CRIT_CLIMB_COARSER; /* the climb's splits: only where the mesh is far too coarse */
    rc = plateau__crit_run(mesh, c, tol, max_steps / 2, steps, done, &stuck, err);
    for (k = 0; k < c->index; k++) turn |= c->dir[k] != 0.0;
    if (rc == PLATEAU_OK && !*done && turn && !c->timed_out) { /* the other way up */
        plateau_mesh again;
        rc = plateau__crit_copy(&start, &again, err);
        if (rc == PLATEAU_OK) {
            plateau_mesh_free(mesh);
            *mesh = again;
        }
        for (k = 0; k < c->index; k++) c->dir[k] = -c->dir[k];
        c->cap = cap;
        if (rc == PLATEAU_OK && !plateau__crit_alloc(a, c, mesh->num_vertices)) {
            plateau_mesh_free(&start);
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_critical_point", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        if (rc == PLATEAU_OK) rc = plateau__crit_run(mesh, c, tol, max_steps - *steps, steps, done, &stuck, err);
    }
    plateau_mesh_free(&start);
    c->theta /= PLATEAU__CRIT_CLIMB_COARSER;
    for (stage = 0; stage < PLATEAU__CRIT_STAGES && rc == PLATEAU_OK && *done && added > 0; stage++) {
        if (plateau__util_time_up(c->budget)) {
            /* options.max_seconds: converged at the last stage's vertices */
            c->timed_out = 1;
            break;
        }
        rc = plateau__crit_split(mesh, c->theta, c->max_nv, &added, err);
        if (rc != PLATEAU_OK || added == 0) break;
        rc = plateau_mesh_delaunay_flips(mesh, 0, NULL, err);
        if (rc != PLATEAU_OK) break;
        if (!plateau__crit_alloc(a, c, mesh->num_vertices)) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_critical_point", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        c->cap = 0.1 * plateau_mean_edge_length(mesh);
        rc = plateau__crit_run(mesh, c, tol, max_steps - *steps, steps, done, &stuck, err);
    }
    return rc;
}

/* plateau_mesh_critical_point within the time budget of a solve (NULL:
 * none); *timed_out (may be NULL) 1 when it ran out first. */
static plateau_result plateau__crit_point(plateau_mesh *mesh, size_t index, int max_steps,
                                          plateau__util_budget *budget, plateau_stability *status,
                                          int *converged, size_t *steps, int *timed_out,
                                          plateau_error *err)
{
    plateau__crit c;
    const plateau_allocator *a;
    plateau_result rc = PLATEAU_OK;
    size_t it = 0;
    double h, tol;
    int done = 0;
    if (converged) *converged = 0;
    if (steps) *steps = 0;
    if (!mesh || !mesh->positions || !mesh->vertex_edge_start || max_steps < 0 ||
        index >= PLATEAU_STABILITY_MAX_EIGENVALUES) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_mesh_critical_point needs a mesh with adjacency, max_steps >= 0 and an index below 8", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    a = &mesh->allocator;
    memset(&c, 0, sizeof c);
    c.index = index;
    c.budget = budget;
    h = plateau_mean_edge_length(mesh);
    c.cap = 0.1 * h;
    tol = 1e-9 / (h > 0.0 ? h : 1.0);
    if (!plateau__crit_alloc(a, &c, mesh->num_vertices)) {
        plateau__crit_free(a, &c);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_critical_point", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    if (max_steps == 0) max_steps = PLATEAU__CRIT_STEPS;
    rc = plateau__crit_search(mesh, &c, tol, (size_t)max_steps, &it, &done, err);
    plateau__crit_free(a, &c);
    if (timed_out) *timed_out = c.timed_out;
    if (steps) *steps = it;
    if (converged) *converged = done;
    if (rc == PLATEAU_OK && status) {
        plateau_error e2;
        plateau_result r2 = plateau_mesh_stability(mesh, index + 2 < PLATEAU_STABILITY_MAX_EIGENVALUES ? index + 2 : index + 1, status, NULL, &e2);
        if (r2 == PLATEAU_ERR_OUT_OF_MEMORY || r2 == PLATEAU_ERR_OVERFLOW) {
            if (err) *err = e2;
            rc = r2;
        }
    }
    return rc;
}

PLATEAU_DEF plateau_result plateau_mesh_critical_point(plateau_mesh *mesh, size_t index, int max_steps,
                                                       plateau_stability *status, int *converged,
                                                       size_t *steps, plateau_error *err)
{
    return plateau__crit_point(mesh, index, max_steps, NULL, status, converged, steps, NULL, err);
}

/* ---- after a solve: its stability report and its saddle search ---- */

/* The stability report of the mesh returned (cfg->stability): running out
 * of memory is an error of the solve; a mesh without a Hessian (a
 * zero-area triangle, a defect the report names already) leaves
 * report.stability.computed 0. */
static plateau_result plateau__stab_of_solve(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, plateau_report *rep,
                                             plateau_error *err)
{
    plateau_error scratch;
    plateau_result rc;
    if (!cfg->stability) return PLATEAU_OK;
    if (plateau__util_time_up(run->budget)) return PLATEAU_OK; /* options.max_seconds: not computed */
    rc = plateau__stab_compute(mesh, 2, run->order, &rep->stability, NULL, &scratch);
    if (rc == PLATEAU_ERR_OUT_OF_MEMORY || rc == PLATEAU_ERR_OVERFLOW) {
        if (err) *err = scratch;
        return rc;
    }
    return PLATEAU_OK;
}

/* options.critical_index K > 0: the search for a critical point of index K
 * from the rounds' result (plateau_mesh_critical_point), then the final
 * check again; a search that does not converge is the defect _UNSOLVED. */
static plateau_result plateau__crit_of_solve(plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, plateau_report *rep,
                                             plateau_error *err)
{
    int conv = 0, timed_out = 0;
    size_t v;
    plateau_result rc;
    if (cfg->critical_index <= 0) return PLATEAU_OK;
    if (plateau__util_time_up(run->budget)) { /* options.max_seconds: no search */
        rep->solved = 0;
        rep->defects |= PLATEAU_DEFECT_UNSOLVED;
        rep->stop = PLATEAU_STOP_TIME_LIMIT;
        return PLATEAU_OK;
    }
    rc = plateau__crit_point(mesh, (size_t)cfg->critical_index, 0, run->budget, NULL, &conv,
                             &rep->critical_steps, &timed_out, err);
    if (rc != PLATEAU_OK) return rc;
    rep->critical_converged = conv;
    if (timed_out && !conv) rep->stop = PLATEAU_STOP_TIME_LIMIT;
    for (v = 0, rep->interior_points = 0; v < mesh->num_vertices; v++) rep->interior_points += !mesh->fixed[v];
    plateau__chk_report_quality(mesh, rep);
    if (!conv && rep->stop == PLATEAU_STOP_CONVERGED) rep->stop = PLATEAU_STOP_DEFECTS;
    rc = plateau__chk_final(mesh, cfg, run, rep, err);
    if (rc == PLATEAU_OK && run->neck_m1 > 0) {
        /* the neck moved: measure it again; a converged critical point is
         * the film asked for however narrow its neck (the unstable
         * catenoid at h = 0.8 R has a neck of 0.158 R) */
        int pinched = 0;
        rc = plateau__chk_pinch(mesh, run, rep, &pinched, err);
        if (pinched && !conv) {
            rep->defects |= PLATEAU_DEFECT_PINCHED;
            rep->stop = PLATEAU_STOP_PINCHED;
        }
    }
    if (!conv) {
        rep->solved = 0;
        rep->defects |= PLATEAU_DEFECT_UNSOLVED;
    }
    return rc;
}
#else /* PLATEAU_NO_STABILITY: the entry points refuse, naming the macro */
PLATEAU_DEF plateau_result plateau_mesh_stability(const plateau_mesh *mesh, size_t num_eigenvalues,
                                                  plateau_stability *stability, double *modes,
                                                  plateau_error *err)
{
    (void)mesh, (void)num_eigenvalues, (void)modes;
    if (stability) memset(stability, 0, sizeof *stability);
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                        "the stability report is compiled out by " PLATEAU__NO_STABILITY_BY, 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

PLATEAU_DEF plateau_result plateau_mesh_critical_point(plateau_mesh *mesh, size_t index, int max_steps,
                                                       plateau_stability *status, int *converged,
                                                       size_t *steps, plateau_error *err)
{
    (void)mesh, (void)index, (void)max_steps;
    if (status) memset(status, 0, sizeof *status);
    if (converged) *converged = 0;
    if (steps) *steps = 0;
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                        "critical points are compiled out by " PLATEAU__NO_STABILITY_BY, 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

/* plateau__cfg_resolve refused stability ON and critical_index > 0 and
 * turned AUTO off: nothing to run after the rounds. */
static plateau_result plateau__stab_of_solve(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, plateau_report *rep,
                                             plateau_error *err)
{
    (void)mesh, (void)cfg, (void)run, (void)rep, (void)err;
    return PLATEAU_OK;
}

static plateau_result plateau__crit_of_solve(plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, plateau_report *rep,
                                             plateau_error *err)
{
    (void)mesh, (void)cfg, (void)run, (void)rep, (void)err;
    return PLATEAU_OK;
}
#endif /* PLATEAU_NO_STABILITY */
/* ======== END SECTION: second-order analysis ============================== */

/* ======== SECTION: the driver (plateau__drv_) ============================= */
/* The sequence of the steps: the rounds of solve and re-triangulation
 * (steps 5-6 repeated, the final check, the pinch test of two loops), and
 * the entry points plateau_solve, plateau_solve_loops and
 * plateau_mesh_minimize, which call the optional sections only where a
 * solve asks for them. */
PLATEAU_DEF const char *plateau_stop_string(plateau_stop stop)
{
    switch (stop) {
#define PLATEAU__CASE(name, value, text) case name: return text;
        PLATEAU_STOP_LIST(PLATEAU__CASE)
#undef PLATEAU__CASE
    default: break;
    }
    return "unknown stop reason";
}

PLATEAU_DEF const char *plateau_area_stop_string(plateau_area_stop stop)
{
    switch (stop) {
#define PLATEAU__CASE(name, value, text) case name: return text;
        PLATEAU_AREA_STOP_LIST(PLATEAU__CASE)
#undef PLATEAU__CASE
    default: break;
    }
    return "unknown area stop reason";
}

/* The pinch test of a result that did not come from lowering the area
 * (method paper-literal, or method paper without the area presolve):
 * their objectives vanish on any film with zero mean curvature, stable or
 * not, and paper-literal's F stalls on a film that is neither (coaxial
 * rings too far apart for a catenoid; examples/NOTES.md).  So method
 * area's rounds run on a copy of the result; when
 * the copy pinches, the result is taken as pinched (its neck ratio is the
 * copy's).  The result itself is left as it is. */
static plateau_result plateau__drv_pinch_probe(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                               const plateau__cfg_run *run, plateau_report *rep,
                                               int *pinched, plateau_error *err)
{
    plateau_mesh copy;
    const plateau__cfg area_cfg = plateau__cfg_derive(cfg, PLATEAU__CFG_PROBE, 0, 0.0);
    plateau__cfg_run probe_run = *run;
    plateau_report probe;
    plateau_result rc;
    *pinched = 0;
    rc = plateau_mesh_create(mesh->positions, mesh->num_vertices, mesh->fixed, mesh->triangles,
                             mesh->num_triangles, &mesh->allocator, &copy, err);
    if (rc != PLATEAU_OK) return rc;
    memset(&probe, 0, sizeof probe);
    if (run->budget) { /* the same deadline; a cut probe tells nothing */
        probe_run.budget_data = *run->budget;
        probe_run.budget_data.interrupted = 0;
        probe_run.budget = &probe_run.budget_data;
    }
    rc = plateau__drv_rounds_of(&copy, &area_cfg, &probe_run, NULL, &probe, err);
    if (rc == PLATEAU_OK && !(probe_run.budget && probe_run.budget->interrupted))
        rc = plateau__chk_pinch(&copy, run, &probe, pinched, err);
    if (rc == PLATEAU_OK && *pinched) rep->neck_ratio = probe.neck_ratio;
    plateau_mesh_free(&copy);
    return rc;
}

/* The rounds of a method; for method paper with run->presolve, first the
 * rounds of method area (their iterations go to presolve_iterations). */
static plateau_result plateau__drv_rounds(plateau_mesh *mesh, const plateau__cfg *cfg,
                                          const plateau__cfg_run *run, const plateau__retri_domain *dom,
                                          plateau_report *rep, plateau_error *err)
{
    if (cfg->method == PLATEAU_METHOD_PAPER && run->presolve) {
        const plateau__cfg area_cfg = plateau__cfg_derive(cfg, PLATEAU__CFG_PRESOLVE, 0, 0.0);
        plateau_report area_rep;
        plateau_result rc;
        memset(&area_rep, 0, sizeof area_rep);
        rc = plateau__drv_rounds_of(mesh, &area_cfg, run, dom, &area_rep, err);
        rep->presolve_iterations = area_rep.iterations;
        rep->evaluations += area_rep.evaluations;
        rep->removed_vertices += area_rep.removed_vertices;
        if (rc != PLATEAU_OK) return rc;
        if (run->neck_m1 > 0) {
            /* a film the area presolve pinched: method paper has no root
             * to find from there (no surface), so it stops here */
            int pinched = 0;
            rc = plateau__chk_pinch(mesh, run, rep, &pinched, err);
            if (rc != PLATEAU_OK) return rc;
            if (pinched) {
                rep->interior_points = area_rep.interior_points;
                rep->rounds = area_rep.rounds;
                rep->f_final = rep->f_initial = 0.0;
                plateau__chk_report_quality(mesh, rep);
                rc = plateau__chk_final(mesh, &area_cfg, run, rep, err);
                rep->solved = 0;
                rep->defects |= PLATEAU_DEFECT_UNSOLVED | PLATEAU_DEFECT_PINCHED;
                rep->stop = PLATEAU_STOP_PINCHED;
                return rc;
            }
        }
    }
    {
        plateau_result rc;
        int hold = cfg->method == PLATEAU_METHOD_PAPER && run->cable_nv > 0;
        if (hold) plateau__solve_hold_cables(mesh, run, 1);
        rc = plateau__drv_rounds_of(mesh, cfg, run, dom, rep, err);
        if (hold) plateau__solve_hold_cables(mesh, run, 0);
        if (rc != PLATEAU_OK) return rc;
    }
    {
        plateau_result rc = plateau__chk_final(mesh, cfg, run, rep, err);
        int pinched = 0;
        if (rc != PLATEAU_OK || run->neck_m1 == 0 || !PLATEAU__HAVE_LOOPS) return rc;
        rc = plateau__chk_pinch(mesh, run, rep, &pinched, err);
        if (rc == PLATEAU_OK && !pinched && cfg->method != PLATEAU_METHOD_AREA &&
            !(cfg->method == PLATEAU_METHOD_PAPER && run->presolve))
            rc = plateau__drv_pinch_probe(mesh, cfg, run, rep, &pinched, err);
        if (rc == PLATEAU_OK && pinched) {
            rep->defects |= PLATEAU_DEFECT_PINCHED;
            rep->stop = PLATEAU_STOP_PINCHED;
        }
        return rc;
    }
}

/* The rounds' bounds: a round of method area that lowers the area by less
 * than PLATEAU__DRV_ROUND_DROP of it (with the rounds' declarations, before
 * the optional sections) ends them; PLATEAU__DRV_STALL_SOLVES solves of
 * method area without an area lower by PLATEAU__DRV_BEST_MARGIN of it stop
 * them as stalled (a safety net, never expected). */

/* What method area's rounds lower: the area (given, as computed by the
 * caller), or a membrane's energy (compared by plateau__util_lower). */
static double plateau__drv_measure(const plateau_mesh *mesh, const plateau__cfg *cfg,
                                   const plateau__cfg_run *run, double area)
{
    return cfg->membrane ? plateau__solve_energy(mesh, cfg, run, NULL) : area;
}

/* Method paper: a round whose solve does not lower the area by at least
 * this fraction of it (against the previous round's solve) ends the rounds
 * before its flips.  On a densely sampled boundary the intrinsic flips
 * after every solve keep finding edges (a drift of a few 1e-7 of the area
 * per round, up or down, far below the discretisation error; with a fan of
 * 10 interior vertices on 20 000 boundary vertices the flips raised the
 * area round after round), and without this every such run went to
 * max_rounds full solves.  A membrane: its energy in place of the area
 * (plateau__util_lower, relative to |E|). */
#define PLATEAU__DRV_PAPER_DROP 1e-6
#define PLATEAU__DRV_STALL_SOLVES 3
#define PLATEAU__DRV_BEST_MARGIN 1e-12

/* The rounds of one method (steps 5 and 6, repeated "until any of the
 * iterative conditions isn't satisfied", II.A): until a solve leaves the
 * triangulation unchanged (PLATEAU_STOP_CONVERGED), max_rounds solves
 * (PLATEAU_STOP_ROUND_LIMIT), or for method area a round that lowers the
 * area by less than PLATEAU__DRV_ROUND_DROP of it.  The degeneration check
 * after every solve goes into the report; two loops are tested for a
 * pinch after every solve of method area. */
static plateau_result plateau__drv_rounds_of(plateau_mesh *mesh, const plateau__cfg *cfg,
                                             const plateau__cfg_run *run, const plateau__retri_domain *dom,
                                             plateau_report *rep, plateau_error *err)
{
    unsigned char *rows = NULL;
    plateau_result rc = PLATEAU_OK;
    double best = 0.0, flip_area = 0.0, solved_area = 0.0;
    size_t v, nfree = 0;
    int round, since_best = 0, stalled, reset_best = 0, limit = cfg->max_rounds, resolves = 0;
    /* a membrane (method area with a pressure, volume or cables): the
     * area's flips without relaxation (which would move cable vertices for
     * the area alone); its rounds measure the membrane's energy instead */
    int flip_rule = cfg->method != PLATEAU_METHOD_AREA ? PLATEAU__RETRI_FLIP_INTRINSIC
                    : cfg->membrane                     ? PLATEAU__RETRI_FLIP_AREA_PLAIN
                                                        : PLATEAU__RETRI_FLIP_AREA;
    int area_rule = flip_rule != PLATEAU__RETRI_FLIP_INTRINSIC;
    int newton; /* method area by the sparse Newton method, chosen once for the rounds */
    double newton_mu = 1.0; /* its damping, carried from round to round */
    for (v = 0; v < mesh->num_vertices; v++) nfree += !mesh->fixed[v];
    rep->interior_points = nfree;
    newton = cfg->method == PLATEAU_METHOD_AREA && plateau__cfg_sparse(cfg->linear_solver, (double)nfree);
    if (newton) rep->linear_solver = PLATEAU_LINEAR_SPARSE;
    rep->stop = PLATEAU_STOP_ROUND_LIMIT;
    if (cfg->method == PLATEAU_METHOD_PAPER_LITERAL) {
        rows = (unsigned char *)plateau__alloc(&mesh->allocator, mesh->num_vertices);
        if (!rows) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory before the rounds", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
    }
    rc = plateau__solve_warm_step(mesh, cfg, run, nfree, rep, err);
    if (rc != PLATEAU_OK) return rc;
    /* limit grows by one per round of vertex removal, at most max_rounds
     * times: at most 2 max_rounds solves */
    for (round = 1; round <= limit; round++) {
        double f0 = 0.0, f1 = 0.0;
        int changed = 0;
        if (plateau__util_time_up(run->budget)) {
            /* the time budget ran out: the mesh as it is; before any solve
             * of these rounds, or after flips no solve followed, it is not
             * the solved mesh */
            if (nfree > 0) run->budget->interrupted = 1;
            rep->stop = PLATEAU_STOP_TIME_LIMIT;
            plateau__chk_report_quality(mesh, rep);
            break;
        }
        rep->rounds = (size_t)round;
        rc = plateau__solve_step(mesh, cfg, run, round, newton, &newton_mu, rows, nfree, rep, &f0, &f1, err);
        if (rc != PLATEAU_OK) break;
        if (round == 1) rep->f_initial = f0;
        rep->f_final = f1;
        if (round <= PLATEAU_REPORT_F_ROUNDS) rep->f_rounds[round - 1] = f1;
        plateau__chk_report_quality(mesh, rep);
        if (run->budget && run->budget->interrupted) {
            rep->stop = PLATEAU_STOP_TIME_LIMIT; /* the solve was cut short */
            break;
        }
        if (run->neck_m1 > 0 && cfg->method == PLATEAU_METHOD_AREA) {
            /* two loops: least area shrinks the neck of a film that has no
             * minimal surface to reach; stop while the collapse is still a
             * neck (vertex removal would next join the loops by long
             * triangles) */
            int pinched = 0;
            rc = plateau__chk_pinch(mesh, run, rep, &pinched, err);
            if (rc != PLATEAU_OK) break;
            if (pinched) {
                rep->stop = PLATEAU_STOP_PINCHED;
                break;
            }
        }
        if (cfg->method == PLATEAU_METHOD_PAPER && nfree > 0 && round > 2 &&
            !plateau__util_lower(plateau__drv_measure(mesh, cfg, run, rep->area), solved_area,
                                 PLATEAU__DRV_PAPER_DROP)) {
            rep->stop = PLATEAU_STOP_CONVERGED; /* the solved mesh, before more flips */
            break;
        }
        solved_area = plateau__drv_measure(mesh, cfg, run, rep->area); /* a membrane: its energy */
        /* The safety net: method area's solves (descent line searches) and
         * flips only lower the area, so solves without a lower area mean a
         * solve raised it: a stop PLATEAU_STOP_STALLED, a defect. */
        stalled = 0;
        if (round == 1 || reset_best ||
            plateau__util_lower(plateau__drv_measure(mesh, cfg, run, rep->area), best, PLATEAU__DRV_BEST_MARGIN)) {
            best = plateau__drv_measure(mesh, cfg, run, rep->area);
            since_best = 0;
            reset_best = 0;
        } else if (++since_best >= PLATEAU__DRV_STALL_SOLVES && area_rule) {
            stalled = 1;
        }
        if (round == limit) {
            if (stalled) rep->stop = PLATEAU_STOP_STALLED;
            break;
        }
        /* the time budget ran out after a whole solve: the solved mesh, no flips after it */
        if (plateau__util_time_up(run->budget)) { rep->stop = PLATEAU_STOP_TIME_LIMIT; break; }
        if (!stalled) { /* step 6 (a stall goes straight to the removal) */
            rc = plateau__retri_step(mesh, cfg, dom, flip_rule, nfree, rep, &changed, err);
            if (rc != PLATEAU_OK) break;
        }
        if (area_rule && changed) {
            /* method area's solves and flips lower one measure, the area:
             * at most 1 + ln(A_1 / A_min) / PLATEAU__DRV_ROUND_DROP rounds
             * go on (A_min > 0 the least area on this boundary); the last
             * flips stay */
            double a = plateau__drv_measure(mesh, cfg, run, plateau_mesh_area(mesh));
            if (flip_area != 0.0 && !plateau__util_lower(a, flip_area, PLATEAU__DRV_ROUND_DROP)) {
                changed = 0;
                plateau__chk_report_quality(mesh, rep);
                rep->f_final = plateau__drv_measure(mesh, cfg, run, rep->area);
            }
            flip_area = a;
        }
        if (stalled || !changed) {
            /* step 6's vertex removal, only where the rounds would end (the
             * flips can mend nothing more), method area only (also method
             * paper's presolve): a free vertex the solves left degenerate
             * goes by an edge collapse and the rounds go on with a re-solve
             * (examples/NOTES.md, "Measurements behind the solver's
             * choices", says why not after every round, nor for method
             * paper) */
            size_t removed = 0;
            if (cfg->method == PLATEAU_METHOD_AREA && nfree > 0) {
                rc = plateau_mesh_remove_degenerate(mesh, 0.0, &removed, err);
                if (rc != PLATEAU_OK) break;
            }
            if (removed == 0) {
                rep->stop = stalled ? PLATEAU_STOP_STALLED : PLATEAU_STOP_CONVERGED;
                break;
            }
            nfree -= removed;
            /* the next round must lower this */
            flip_area = plateau__drv_measure(mesh, cfg, run, plateau_mesh_area(mesh));
            rep->removed_vertices += removed;
            rep->interior_points = nfree;
            reset_best = 1;
            /* the re-solve does not use up the caller's rounds, up to
             * max_rounds such re-solves: a solve that leaves a few
             * degenerate vertices every round would run a round per
             * removal */
            if (limit < INT_MAX && resolves < cfg->max_rounds) {
                limit++;
                resolves++;
            }
        }
    }
    plateau__free(&mesh->allocator, rows);
    return rc;
}

PLATEAU_DEF plateau_result plateau_mesh_minimize(plateau_mesh *mesh, const plateau_options *options,
                                                 plateau_report *report, plateau_error *err)
{
    plateau__cfg resolved;
    const plateau__cfg *cfg = &resolved;
    plateau__cfg_run run;
    plateau_report rep;
    plateau_result rc;
    plateau__frame fr;
    plateau__solve_order order;
    double *original;
    size_t v, f;
    memset(&rep, 0, sizeof rep);
    if (!mesh || !mesh->positions || !mesh->vertex_edge_start) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_mesh_minimize needs a mesh with adjacency", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    rc = plateau__cfg_resolve(options, 0, &resolved, err);
    if (rc != PLATEAU_OK) return rc;
    plateau__cfg_run_start(cfg, &run);
    if (cfg->cable_tension) {
        plateau__util_error(err, PLATEAU_ERR_CABLE, -1,
                            "plateau_mesh_minimize takes no cables (plateau_solve inserts their vertices)", 0, 0);
        return PLATEAU_ERR_CABLE;
    }
    /* no domain here: method paper presolves only when asked to */
    run.presolve = cfg->paper_presolve == PLATEAU_ON;
    rep.method = cfg->method;
    rep.membrane = cfg->membrane;
    for (v = 0, f = 0; v < mesh->num_vertices; v++) f += mesh->fixed[v] != 0;
    rc = plateau__cfg_memory_check(cfg, &run, (double)f, (double)(mesh->num_vertices - f), err);
    if (rc != PLATEAU_OK) {
        if (report) *report = rep;
        return rc;
    }
    /* the fixed vertices (3 per vertex), then the frame's scratch (4) */
    original = (double *)plateau__util_array(&mesh->allocator, mesh->num_vertices, 7 * sizeof(double));
    if (!original) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory in plateau_mesh_minimize", 0, 0);
        if (report) *report = rep;
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (v = 0, f = 0; v < mesh->num_vertices; v++)
        if (mesh->fixed[v]) memcpy(original + 3 * f++, mesh->positions + 3 * v, 3 * sizeof(double));
    plateau__frame_make(mesh->positions, mesh->num_vertices, &fr, original + 3 * mesh->num_vertices);
    run.unit = fr.unit;
    plateau__frame_to(&fr, mesh->positions, mesh->num_vertices, mesh->positions);
    memset(&order, 0, sizeof order); /* the last Newton solve's order, for the report */
    order.alloc = cfg->alloc;
    if (cfg->stability) run.order = &order;
    /* a membrane's apex: the centroid of the fixed vertices */
    if (cfg->membrane) rc = plateau__memb_solve(mesh, cfg, &run, original, f, &fr, NULL, NULL, &rep, err);
    else rc = plateau__drv_rounds(mesh, cfg, &run, NULL, &rep, err);
    plateau__frame_restore(mesh, original, &fr, &rep);
    if (cfg->membrane) plateau__memb_report(mesh, original, f, NULL, 0, fr.unit, &rep);
    plateau__free(&mesh->allocator, original);
    if (rc == PLATEAU_OK) rc = plateau__crit_of_solve(mesh, cfg, &run, &rep, err);
    if (rc == PLATEAU_OK) rc = plateau__stab_of_solve(mesh, cfg, &run, &rep, err);
    if (rc == PLATEAU_OK) rc = plateau__acc_report(mesh, cfg, &rep, err);
    else rep.area_error_estimate = plateau__acc_nan(), rep.estimate = PLATEAU_ESTIMATE_NO_RESULT;
    plateau__solve_order_clear(&order);
    plateau__free(&order.alloc, order.vertex);
    if (report) *report = rep;
    return rc;
}

/* The one run of plateau_solve and plateau_solve_loops (and of each disc
 * of two loops), configured by *cfg for the k loops of counts[j] vertices,
 * m in all: the memory bound, steps 1-4, then steps 5-6 and the final
 * check (plateau__drv_rounds, or a membrane's plateau__memb_solve) in the
 * frame, and the mesh back in the caller's units, the fixed vertices bit
 * for bit; or coarse to fine; then the analyses after the final check. */
static plateau_result plateau__drv_run(const double *xyz, const size_t *counts, size_t k, size_t m,
                                       const plateau__cfg *cfg, plateau_mesh *mesh, plateau_report *report,
                                       plateau_error *err)
{
    plateau__cfg_run run;
    plateau__cfg_work s;
    plateau__retri_domain dom, *domp;
    plateau_report rep;
    plateau_result rc;
    plateau__frame frame;
    double dscale = 1.0, film_least;
    size_t nv = 0;
    const double *bxyz = xyz;    /* the polygon of steps 1-4: with cables, */
    const size_t *bcounts = counts; /* the cable vertices inserted */
    int c2f = 0;
    plateau__solve_order order;

    plateau__cfg_run_start(cfg, &run);
    memset(&rep, 0, sizeof rep);
    memset(&s, 0, sizeof s);
    memset(&frame, 0, sizeof frame); /* set by step 2; gcc -O3 cannot see that c2f implies it */
    rep.loops = k;
    s.alloc = cfg->alloc;
    s.m = m;
    /* the memory bound of coarse to fine while that path may run (the
     * options allow it; plateau__c2f_plan decides) */
    run.c2f_memory = k == 1 && cfg->coarse_to_fine != PLATEAU_OFF &&
                     (cfg->method == PLATEAU_METHOD_AREA || cfg->method == PLATEAU_METHOD_PAPER) &&
                     cfg->seeding != PLATEAU_SEEDING_PAPER && cfg->quality_edge_length == 0.0 &&
                     cfg->refine_boundary != PLATEAU_OFF &&
                     (cfg->coarse_to_fine == PLATEAU_ON ||
                      (cfg->n >= PLATEAU_COARSE_TO_FINE_POINTS && cfg->linear_solver == PLATEAU_LINEAR_AUTO));
    s.time_budget = run.budget;
    rep.method = cfg->method;
    rep.membrane = cfg->membrane;
    /* bounded memory: the estimate for the n asked, before anything is allocated */
    rc = plateau__cfg_memory_check(cfg, &run, (double)m, (double)cfg->n, err);
    if (rc == PLATEAU_OK && k > 1 && !xyz) {
        rc = PLATEAU_ERR_ARGUMENT;
        plateau__util_error(err, rc, -1, "the boundary array is NULL", 0, 0);
    }
    if (rc == PLATEAU_OK && cfg->cable_tension && xyz) {
        rc = plateau__memb_polygon(xyz, counts, k, cfg, &s, &run, err);
        if (s.cable_xyz) {
            bxyz = s.cable_xyz;
            bcounts = s.cable_counts;
        }
    }
    if (rc == PLATEAU_OK) rc = plateau__bnd_step(bxyz, bcounts, k, cfg, &s, err);
    if (rc == PLATEAU_OK) rc = plateau__dom_step(&s, cfg, &run, &rep, &frame, &dscale, err);
    /* the last Newton solve's elimination order, for the stability report */
    memset(&order, 0, sizeof order);
    order.alloc = cfg->alloc;
    if (cfg->stability) run.order = &order;
    /* coarse to fine: never for a membrane (plateau_resolved_options) */
    if (rc == PLATEAU_OK && !cfg->membrane)
        rc = plateau__c2f_solve(&s, cfg, &run, frame.unit / dscale, mesh, &rep, &c2f, err);
    run.c2f_memory = c2f; /* the rounds at full size: their own bound */
    if (c2f) {
        /* back to the caller's units, the fixed vertices from s.orig */
        plateau__frame_restore(mesh, s.k > 0 ? s.orig : xyz, &frame, &rep);
    } else if (rc == PLATEAU_OK) {
        rc = plateau__cdt_step(&s, cfg, &run, frame.unit / dscale, mesh, &rep, &nv, err);
    }
    if (rc == PLATEAU_OK && !c2f) {
        /* paper-literal re-projects only a mesh of one polygon and its points */
        dom.uv = s.uv;
        dom.m = s.m;
        dom.kind = rep.domain;
        if (k == 2) {
            run.neck_m0 = bcounts[0];
            run.neck_m1 = bcounts[1];
        }
        domp = k == 1 && s.k == 0 && nv == s.dt.num_points ? &dom : NULL;
        if (cfg->membrane)
            rc = plateau__memb_solve(mesh, cfg, &run, xyz, m, &frame, s.cable_t, domp, &rep, err);
        else
            rc = plateau__drv_rounds(mesh, cfg, &run, domp, &rep, err);
        /* back to the caller's units: the boundary bit for bit, the
         * vertices added on its edges as computed in step 4 */
        plateau__frame_restore(mesh, s.k > 0 ? s.orig : xyz, &frame, &rep);
        if (cfg->membrane) plateau__memb_report(mesh, xyz, m, &s, run.cable_nseg, frame.unit, &rep);
    }
    /* after either path: the saddle search, the discs of two loops (against
     * the least film found: the rounds' minimum, valid, before the search),
     * the stability report (coarse to fine runs for one polygon only) */
    film_least = rep.defects ? 0.0 : rep.area;
    if (rc == PLATEAU_OK) rc = plateau__crit_of_solve(mesh, cfg, &run, &rep, err);
    if (rc == PLATEAU_OK && k == 2 && cfg->alternatives)
        rc = plateau__loops_discs(xyz, counts, cfg, &run, film_least, mesh, &rep, err);
    if (rc == PLATEAU_OK) rc = plateau__stab_of_solve(mesh, cfg, &run, &rep, err);
    if (rc == PLATEAU_OK) rc = plateau__acc_report(mesh, cfg, &rep, err);
    else rep.area_error_estimate = plateau__acc_nan(), rep.estimate = PLATEAU_ESTIMATE_NO_RESULT;
    plateau__solve_order_clear(&order);
    plateau__free(&order.alloc, order.vertex);
    plateau__cfg_work_free(&s);
    if (report) *report = rep;
    if (rc == PLATEAU_OK) plateau__util_ok(err);
    return rc;
}

#ifndef PLATEAU_NO_ACCURACY
/* options.accuracy (ACCURACY at the top): the run at the first count, and
 * again at plateau__acc_next's while the estimate is above the accuracy,
 * the polygon's edges split to match (refine_boundary AUTO taken as ON);
 * a result with defects ends the search (more points do not mend a knot);
 * a further run that has defects, or ran out of time, is dropped and ends
 * the search with the previous result; one that fails is the call's
 * failure.  The time budget covers all runs. */
static plateau_result plateau__drv_accuracy(const double *xyz, const size_t *counts, size_t k, size_t m,
                                            const plateau__cfg *cfg, plateau_mesh *mesh,
                                            plateau_report *report, plateau_error *err)
{
    plateau__cfg c = *cfg;
    plateau_report rep, trep;
    plateau_mesh trial;
    plateau_result rc;
    size_t solves = 1, next;
    double t0 = cfg->max_seconds > 0.0 ? cfg->clock_fn(cfg->clock_user) : 0.0;
    if (c.refine_boundary == PLATEAU_AUTO) c.refine_boundary = PLATEAU_ON;
    if (!cfg->n_given && c.n < PLATEAU__ACC_FIRST_POINTS) c.n = PLATEAU__ACC_FIRST_POINTS;
    rc = plateau__drv_run(xyz, counts, k, m, &c, mesh, &rep, err);
    while (rc == PLATEAU_OK && rep.estimate == PLATEAU_ESTIMATE_FORMED && rep.area_error_estimate > c.accuracy &&
           rep.defects == 0 && rep.stop != PLATEAU_STOP_TIME_LIMIT && solves < PLATEAU__ACC_MAX_SOLVES) {
        next = plateau__acc_next(rep.interior_points, rep.area_error_estimate, c.accuracy);
        if (next == 0 || plateau_memory_estimate(c.method, m, next) > (double)c.max_memory) break;
        if (cfg->max_seconds > 0.0) {
            c.max_seconds = cfg->max_seconds - (cfg->clock_fn(cfg->clock_user) - t0);
            if (!(c.max_seconds > 0.0)) break;
        }
        c.n = next;
        rc = plateau__drv_run(xyz, counts, k, m, &c, &trial, &trep, err);
        if (rc != PLATEAU_OK) { /* the caller frees the mesh it has */
            plateau_mesh_free(&trial);
            rep = trep;
            break;
        }
        if ((trep.defects & ~rep.defects) || trep.stop == PLATEAU_STOP_TIME_LIMIT) {
            plateau_mesh_free(&trial);
            break;
        }
        plateau_mesh_free(mesh);
        *mesh = trial;
        rep = trep;
        solves++;
    }
    rep.accuracy = c.accuracy;
    rep.accuracy_solves = solves;
    if (report) *report = rep;
    return rc;
}
#endif /* PLATEAU_NO_ACCURACY */

/* plateau_solve (k = 1) and plateau_solve_loops: the arguments checked,
 * the options resolved once into the read-only configuration, then the
 * run. */
static plateau_result plateau__drv_solve(const double *xyz, const size_t *counts, size_t k,
                                         const plateau_options *options, plateau_mesh *mesh,
                                         plateau_report *report, plateau_error *err)
{
    plateau__cfg cfg;
    plateau_report rep;
    plateau_result rc;
    size_t m = 0, j;

    memset(&rep, 0, sizeof rep);
    rep.loops = k;
    if (report) *report = rep;
    if (mesh) memset(mesh, 0, sizeof *mesh);
    if (!mesh) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            k == 1 ? "plateau_solve needs a mesh to fill"
                                   : "plateau_solve_loops needs a mesh to fill", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (j = 0; j < k; j++) {
        if (counts[j] > (size_t)PLATEAU_INDEX_MAX - m && k > 1) {
            plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1,
                                "the loops have more vertices than plateau_index can count", 0, 0);
            return PLATEAU_ERR_OVERFLOW;
        }
        m += counts[j];
    }
#ifdef PLATEAU_NO_LOOPS
    if (k > 1) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, PLATEAU__CFG_NO_LOOPS, 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
#endif
    rc = plateau__cfg_resolve(options, m, &cfg, err);
    if (rc != PLATEAU_OK) return rc;
    /* several loops run the rounds at full size (no coarse to fine): the
     * accuracy only when asked for */
    if (k > 1 && !(options && options->accuracy > 0.0)) cfg.accuracy = 0.0;
#ifndef PLATEAU_NO_ACCURACY /* else plateau__cfg_resolve refused accuracy > 0 */
    if (cfg.accuracy > 0.0) return plateau__drv_accuracy(xyz, counts, k, m, &cfg, mesh, report, err);
#endif
    rc = plateau__drv_run(xyz, counts, k, m, &cfg, mesh, report, err);
    if (report) report->accuracy_solves = 1;
    return rc;
}

PLATEAU_DEF plateau_result plateau_solve(const double *boundary, size_t m,
                                         const plateau_options *options,
                                         plateau_mesh *mesh, plateau_report *report,
                                         plateau_error *err)
{
    return plateau__drv_solve(boundary, &m, 1, options, mesh, report, err);
}

PLATEAU_DEF plateau_result plateau_solve_loops(const double *xyz, const size_t *loop_counts,
                                               size_t num_loops, const plateau_options *options,
                                               plateau_mesh *mesh, plateau_report *report,
                                               plateau_error *err)
{
    if (!loop_counts || num_loops == 0) {
        plateau_report rep;
        memset(&rep, 0, sizeof rep);
        if (report) *report = rep;
        if (mesh) memset(mesh, 0, sizeof *mesh);
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            !mesh ? "plateau_solve_loops needs a mesh to fill"
                                  : "plateau_solve_loops needs at least one loop count", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    return plateau__drv_solve(xyz, loop_counts, num_loops, options, mesh, report, err);
}
/* ======== END SECTION: the driver ========================================= */

/* ======== SECTION: mesh input and output implementation ================== */
/* Private helpers of this section are named plateau__io_... (and reuse
 * plateau__util_error / plateau__util_ok / plateau__util_finite from the
 * private helpers). */
#if !defined(PLATEAU_FREESTANDING) && !defined(PLATEAU_NO_PARSERS)
#include <stdlib.h> /* strtod */
#include <locale.h> /* localeconv: read numbers with '.' in any locale */

/* Parses one field [s, s + len) as a double.  0: fine; 1: not a number;
 * 2: a number that is not finite. */
static int plateau__io_number(const char *s, size_t len, double *out)
{
    char buf[128];
    char point = '.';
    const struct lconv *lc;
    char *end = NULL;
    size_t i;
    if (len == 0 || len >= sizeof buf) return 1;
    lc = localeconv();
    if (lc && lc->decimal_point && lc->decimal_point[0] && !lc->decimal_point[1])
        point = lc->decimal_point[0];
    for (i = 0; i < len; i++) {
        char c = s[i];
        /* only the characters of C number syntax; ',' never (some locales
         * would read it as a decimal point) */
        if (!((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' ||
              (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '(' || c == ')' ||
              c == '_'))
            return 1;
        buf[i] = (c == '.') ? point : c;
    }
    buf[len] = '\0';
    *out = strtod(buf, &end);
    if (end != buf + len) return 1;
    return plateau__util_finite(*out) ? 0 : 2;
}

/* Appends ': "TEXT"' to the message of err (NULL: nothing): the offending
 * text a parse error quotes, cut to 48 characters ("..." after), control
 * characters shown as '?'. */
static void plateau__io_quote(plateau_error *err, const char *s, size_t len)
{
    size_t k, i, cap;
    if (!err) return;
    k = strlen(err->message);
    cap = sizeof err->message;
    if (k + 4 >= cap) return;
    err->message[k++] = ':';
    err->message[k++] = ' ';
    err->message[k++] = '"';
    for (i = 0; i < len && i < 48 && k + 5 < cap; i++)
        err->message[k++] = (unsigned char)s[i] < 32 || s[i] == 127 ? '?' : s[i];
    if (i < len && k + 5 < cap) {
        err->message[k++] = '.';
        err->message[k++] = '.';
        err->message[k++] = '.';
    }
    err->message[k++] = '"';
    err->message[k] = '\0';
}

/* The fields of the line [start, stop) up to any '#': separated by spaces
 * and tabs, and by one ';', or by one ',' on a line without ';' (CSV as
 * spreadsheets export it).  The first three fields go to fstart / flen;
 * returns how many there are, *extra = 1 when more than three, *empty = 1
 * when a separator follows another or ends the line (or starts it);
 * *end_at is where the scan stopped (stop, or the '#'). */
static int plateau__io_fields(const char *text, size_t start, size_t stop, size_t fstart[3],
                              size_t flen[3], int *extra, int *empty, size_t *end_at)
{
    size_t k;
    char sep = 0;
    int n = 0, after_sep = 0;
    for (k = start; k < stop && text[k] != '#'; k++)
        if (text[k] == ';') sep = ';';
        else if (text[k] == ',' && !sep) sep = ',';
    *extra = *empty = 0;
    k = start;
    while (k < stop) {
        size_t f;
        while (k < stop && (text[k] == ' ' || text[k] == '\t')) k++;
        if (k >= stop || text[k] == '#') break;
        if (sep && text[k] == sep) {
            if (n == 0 || after_sep) *empty = 1;
            after_sep = 1;
            k++;
            continue;
        }
        f = k;
        while (k < stop && text[k] != ' ' && text[k] != '\t' && text[k] != '#' && !(sep && text[k] == sep)) k++;
        if (n < 3) {
            fstart[n] = f;
            flen[n] = k - f;
        } else {
            *extra = 1;
        }
        n++;
        after_sep = 0;
    }
    if (after_sep) *empty = 1;
    *end_at = k;
    return n;
}

/* 1 when the three fields name columns ("x", "Y", "\"z\"", "x_mm"): each
 * starts with a letter or a '"' and none reads as a number ("inf" and
 * "nan" do: a vertex line with them is an error, not a header). */
static int plateau__io_is_header(const char *text, const size_t fstart[3], const size_t flen[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        char c = text[fstart[k]];
        double v;
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '"')) return 0;
        if (plateau__io_number(text + fstart[k], flen[k], &v) != 1) return 0;
    }
    return 1;
}

/* The parser of plateau_parse_boundary and plateau_parse_boundary_lines:
 * every vertex line, nothing dropped.  With where != NULL, *where gets each
 * vertex's 1-based line (allocated with *xyz through allocator), negated
 * for a vertex with a blank line (no field, no '#') between it and the
 * previous vertex: where a new loop may start. */
static plateau_result plateau__io_parse(const char *text, size_t length,
                                        const plateau_allocator *allocator, double **xyz,
                                        size_t *m, long **where, plateau_error *err)
{
    size_t pos = 0, lines = 1, count = 0, i;
    long line = 0, *at = NULL;
    int gap = 0, header = 0;
    double *out = NULL;
    if (xyz) *xyz = NULL;
    if (m) *m = 0;
    if (where) *where = NULL;
    if (!xyz || !m || (!text && length > 0) || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "plateau_parse_boundary: a NULL argument or a bad allocator", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (i = 0; i < length; i++) lines += text[i] == '\n';
    while (pos < length) {
        size_t start = pos, stop, k, end;
        size_t fstart[3] = {0, 0, 0}, flen[3] = {0, 0, 0};
        int nfields, extra = 0, empty = 0;
        double v[3];
        line++;
        while (pos < length && text[pos] != '\n') pos++;
        stop = pos;
        if (pos < length) pos++; /* past the '\n' */
        if (stop > start && text[stop - 1] == '\r') stop--;
        nfields = plateau__io_fields(text, start, stop, fstart, flen, &extra, &empty, &k);
        if (nfields == 0 && !empty) {
            gap |= k >= stop; /* blank, not a comment line */
            continue;
        }
        if (count == 0 && !header && nfields == 3 && !empty && plateau__io_is_header(text, fstart, flen)) {
            header = 1; /* "x,y,z": the columns' names, read once before any vertex */
            continue;
        }
        for (k = start, end = start; k < stop && text[k] != '#'; k++) end = k + 1;
        if (empty || nfields != 3) {
            plateau__util_error(err, PLATEAU_ERR_PARSE, line,
                              empty   ? "line @: an empty field (two separators in a row, or one at the end)"
                              : extra ? "line @: @ fields; expected three numbers \"x y z\""
                                      : "line @: @ field(s); expected three numbers \"x y z\"",
                              line, nfields);
            plateau__io_quote(err, text + start, end - start);
            plateau__free(allocator, out);
            plateau__free(allocator, at);
            return PLATEAU_ERR_PARSE;
        }
        for (k = 0; k < 3; k++) {
            int bad = plateau__io_number(text + fstart[k], flen[k], &v[k]);
            if (bad) {
                plateau__free(allocator, out);
                plateau__free(allocator, at);
                plateau__util_error(err, bad == 2 ? PLATEAU_ERR_NOT_FINITE : PLATEAU_ERR_PARSE, line,
                                    bad == 2 ? "line @: coordinate @ is NaN or infinite"
                                             : "line @: field @ is not a number", line, (long)k + 1);
                plateau__io_quote(err, text + fstart[k], flen[k]);
                return bad == 2 ? PLATEAU_ERR_NOT_FINITE : PLATEAU_ERR_PARSE;
            }
        }
        if (!out) {
            /* a vertex line holds at least "x y z" and a line end: at most
             * length / 6 + 1 vertices, whatever the number of blank lines */
            size_t bytes;
            if (lines > length / 6 + 1) lines = length / 6 + 1;
            bytes = plateau__bytes(lines, 3 * sizeof(double));
            if (bytes == 0) {
                plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the text is too long", 0, 0);
                return PLATEAU_ERR_OVERFLOW;
            }
            out = (double *)plateau__alloc(allocator, bytes);
            if (where && out) {
                /* sizeof(long) <= 3 * sizeof(double): the product fits */
                at = (long *)plateau__alloc(allocator, lines * sizeof(long));
                if (!at) {
                    plateau__free(allocator, out);
                    out = NULL;
                }
            }
            if (!out) {
                plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1,
                                  "out of memory for the boundary vertices", 0, 0);
                return PLATEAU_ERR_OUT_OF_MEMORY;
            }
        }
        for (k = 0; k < 3; k++) out[3 * count + k] = v[k];
        if (at) at[count] = count > 0 && gap ? -line : line;
        gap = 0;
        count++;
    }
    *xyz = out;
    *m = count;
    if (where) *where = at;
    return plateau__util_ok(err);
}

PLATEAU_DEF plateau_result plateau_parse_cables(char *text, size_t length, const plateau_allocator *allocator,
                                                double **tension, size_t *count, plateau_error *err)
{
    size_t pos = 0, lines = 1, n = 0, i;
    long line = 0;
    double *out = NULL;
    int any = 0, pass, header = 0;
    if (tension) *tension = NULL;
    if (count) *count = 0;
    if (!tension || !count || (!text && length > 0) || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_parse_cables: a NULL argument or a bad allocator",
                            0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (i = 0; i < length; i++) lines += text[i] == '\n';
    /* pass 0 finds whether any line has a cable; pass 1 records and blanks */
    for (pass = 0; pass < 2; pass++) {
        pos = 0;
        line = 0;
        n = 0;
        header = 0;
        if (pass == 1) {
            size_t bytes;
            if (!any) return plateau__util_ok(err);
            bytes = plateau__bytes(lines, sizeof(double));
            if (bytes == 0) {
                plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "the text is too long", 0, 0);
                return PLATEAU_ERR_OVERFLOW;
            }
            out = (double *)plateau__alloc(allocator, bytes);
            if (!out) {
                plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the cables", 0, 0);
                return PLATEAU_ERR_OUT_OF_MEMORY;
            }
        }
        while (pos < length) {
            size_t start = pos, stop, k, fs[8], fl[8];
            int nf = 0;
            line++;
            while (pos < length && text[pos] != '\n') pos++;
            stop = pos;
            if (pos < length) pos++;
            for (k = start; k < stop;) {
                size_t f;
                while (k < stop && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r')) k++;
                if (k >= stop || text[k] == '#') break;
                f = k;
                while (k < stop && text[k] != ' ' && text[k] != '\t' && text[k] != '\r' && text[k] != '#') k++;
                if (nf < 8) { fs[nf] = f; fl[nf] = k - f; }
                nf++;
            }
            if (nf == 0) continue;
            if (nf >= 2 && nf <= 8 && fl[nf - 2] == 5 && memcmp(text + fs[nf - 2], "cable", 5) == 0) {
                double t = 0.0;
                int bad = plateau__io_number(text + fs[nf - 1], fl[nf - 1], &t);
                if (bad) {
                    plateau__free(allocator, out);
                    plateau__util_error(err, bad == 2 ? PLATEAU_ERR_NOT_FINITE : PLATEAU_ERR_PARSE, line,
                                        bad == 2 ? "line @: the cable's tension is NaN or infinite"
                                                 : "line @: \"cable\" wants a tension after it", line, 0);
                    plateau__io_quote(err, text + fs[nf - 2], fs[nf - 1] + fl[nf - 1] - fs[nf - 2]);
                    return bad == 2 ? PLATEAU_ERR_NOT_FINITE : PLATEAU_ERR_PARSE;
                }
                any = 1;
                if (pass == 1) {
                    out[n] = t;
                    memset(text + fs[nf - 2], ' ', fs[nf - 1] + fl[nf - 1] - fs[nf - 2]);
                }
            } else if (nf >= 1 && fl[nf - 1] == 5 && memcmp(text + fs[nf - 1], "cable", 5) == 0) {
                plateau__free(allocator, out);
                plateau__util_error(err, PLATEAU_ERR_PARSE, line, "line @: \"cable\" wants a tension after it",
                                    line, 0);
                plateau__io_quote(err, text + fs[0], fs[nf - 1] + fl[nf - 1] - fs[0]);
                return PLATEAU_ERR_PARSE;
            } else {
                /* the header line plateau_parse_boundary skips is no vertex line */
                size_t hs[3], hl[3], hend, hstop = stop > start && text[stop - 1] == '\r' ? stop - 1 : stop;
                int hx, he;
                if (n == 0 && !header && plateau__io_fields(text, start, hstop, hs, hl, &hx, &he, &hend) == 3 &&
                    !he && plateau__io_is_header(text, hs, hl)) {
                    header = 1;
                    continue;
                }
                if (pass == 1) out[n] = 0.0;
            }
            n++;
        }
    }
    *tension = out;
    *count = n;
    return plateau__util_ok(err);
}

static int plateau__io_same_point(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

PLATEAU_DEF plateau_result plateau_parse_boundary(const char *text, size_t length,
                                                  const plateau_allocator *allocator,
                                                  double **xyz, size_t *m,
                                                  plateau_error *err)
{
    plateau_result r = plateau__io_parse(text, length, allocator, xyz, m, NULL, err);
    /* the closing point: the polygon closes by itself */
    if (r == PLATEAU_OK && *m >= 2 && plateau__io_same_point(*xyz, *xyz + 3 * (*m - 1))) (*m)--;
    return r;
}

PLATEAU_DEF void plateau_boundary_lines_free(plateau_boundary_lines *info,
                                             const plateau_allocator *allocator)
{
    if (!info) return;
    plateau__free(allocator, info->lines);
    plateau__free(allocator, info->loop_counts);
    plateau__free(allocator, info->closing_lines);
    info->lines = NULL;
    info->loop_counts = NULL;
    info->closing_lines = NULL;
    info->num_loops = 0;
    info->closing_dropped = 0;
}

PLATEAU_DEF plateau_result plateau_parse_boundary_lines(const char *text, size_t length,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_boundary_lines *info,
                                                        plateau_error *err)
{
    long *at = NULL;
    size_t n, i, w, loop, nloops = 1, bytes;
    plateau_result r;
    if (info) {
        info->lines = NULL;
        info->loop_counts = NULL;
        info->closing_lines = NULL;
        info->num_loops = 0;
        info->closing_dropped = 0;
    }
    if (!info) {
        if (xyz) *xyz = NULL;
        if (m) *m = 0;
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_parse_boundary_lines: info is NULL", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    r = plateau__io_parse(text, length, allocator, xyz, m, &at, err);
    if (r != PLATEAU_OK || *m == 0) return r;
    n = *m;
    for (i = 1; i < n; i++) {
        if (at[i] > 0) continue;
        if (info->split_loops) nloops++;
        else at[i] = -at[i];
    }
    bytes = plateau__bytes(nloops, sizeof(size_t) > sizeof(long) ? sizeof(size_t) : sizeof(long));
    info->loop_counts = bytes ? (size_t *)plateau__alloc(allocator, bytes) : NULL;
    info->closing_lines = bytes ? (long *)plateau__alloc(allocator, bytes) : NULL;
    if (!info->loop_counts || !info->closing_lines) {
        plateau_boundary_lines_free(info, allocator);
        plateau__free(allocator, at);
        plateau__free(allocator, *xyz);
        *xyz = NULL;
        *m = 0;
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1,
                            "out of memory for the boundary's loops", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    /* each loop [i, e) moved down to [first, w), less its closing point */
    for (i = 0, w = 0, loop = 0; loop < nloops; loop++) {
        size_t e = i + 1, first = w, k;
        while (e < n && at[e] > 0) e++;
        at[i] = at[i] < 0 ? -at[i] : at[i];
        for (k = i; k < e; k++, w++) {
            (*xyz)[3 * w] = (*xyz)[3 * k];
            (*xyz)[3 * w + 1] = (*xyz)[3 * k + 1];
            (*xyz)[3 * w + 2] = (*xyz)[3 * k + 2];
            at[w] = at[k];
        }
        info->closing_lines[loop] = 0;
        if (w - first >= 2 && plateau__io_same_point(*xyz + 3 * first, *xyz + 3 * (w - 1))) {
            w--;
            info->closing_lines[loop] = at[w];
            info->closing_dropped++;
        }
        info->loop_counts[loop] = w - first;
        i = e;
    }
    *m = w;
    info->lines = at;
    info->num_loops = nloops;
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_cables_align(double *tension, size_t *count,
                                                const plateau_boundary_lines *info, plateau_error *err)
{
    size_t j, r = 0, w = 0, i, kept = 0;
    if (!tension || !count || !info) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_cables_align: a NULL argument", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (j = 0; j < info->num_loops; j++) kept += info->loop_counts[j];
    if (*count != kept + info->closing_dropped) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_cables_align: the cables and the lines are not of the same text", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    /* first a cable on a dropped closing point, then the move (nothing moved on error) */
    for (j = 0; j < info->num_loops; j++) {
        r += info->loop_counts[j];
        if (info->closing_lines[j] == 0) continue;
        if (tension[r] != 0.0) {
            long line = info->closing_lines[j];
            plateau__util_error(err, PLATEAU_ERR_PARSE, line,
                                "line @: a cable on a closing point (it repeats the loop's first vertex and "
                                "is dropped): put it on the line before",
                                line, 0);
            return PLATEAU_ERR_PARSE;
        }
        r++;
    }
    for (j = 0, r = 0; j < info->num_loops; j++) {
        for (i = 0; i < info->loop_counts[j]; i++) tension[w++] = tension[r++];
        if (info->closing_lines[j] != 0) r++;
    }
    *count = w;
    return plateau__util_ok(err);
}

/* ---- the mesh reader (plateau_parse_mesh): OBJ and OFF ---- */

/* The next field of [*pos, stop) up to a '#' (spaces and tabs separate
 * fields): 1 with *start and *len, or 0 when the line has no more. */
static int plateau__io_token(const char *text, size_t *pos, size_t stop, size_t *start, size_t *len)
{
    size_t k = *pos;
    while (k < stop && (text[k] == ' ' || text[k] == '\t')) k++;
    if (k >= stop || text[k] == '#') {
        *pos = stop;
        return 0;
    }
    *start = k;
    while (k < stop && text[k] != ' ' && text[k] != '\t' && text[k] != '#') k++;
    *len = k - *start;
    *pos = k;
    return 1;
}

/* 1 when [s, s + len) is word. */
static int plateau__io_is(const char *s, size_t len, const char *word)
{
    return strlen(word) == len && memcmp(s, word, len) == 0;
}

/* [s, s + len) as a whole number with an optional '-': 0 with *out, or 1
 * (not one, or beyond 2^53: no index is that large). */
static int plateau__io_whole(const char *s, size_t len, double *out)
{
    size_t i = 0;
    double v = 0.0;
    int neg = len > 0 && s[0] == '-';
    if (neg) i++;
    if (i >= len) return 1;
    for (; i < len; i++) {
        if (s[i] < '0' || s[i] > '9') return 1;
        v = 10.0 * v + (double)(s[i] - '0');
        if (v > 9007199254740992.0) return 1;
    }
    *out = neg ? -v : v;
    return 0;
}

/* The state of the two passes over a mesh text: the first counts and
 * checks what it can, the second (fill) writes the arrays. */
typedef struct plateau__io_mesh {
    const char *text;
    size_t length, start, pos, stop; /* the text; the line being read,
                                        [start, stop), read up to pos */
    long line;
    size_t nv, nt;            /* vertices and triangles so far */
    size_t total_nv;          /* the second pass: the first pass's count */
    int fill;
    double *xyz;
    plateau_index *tri;
    long *lines;
    plateau_error *err;
} plateau__io_mesh;

/* The next line of the text into [t->pos, t->stop) (its "\r\n" left out),
 * counted in t->line; 0 at the end of the text.  A NUL byte is an error
 * (*bad set). */
static int plateau__io_next_line(plateau__io_mesh *t, size_t *next, int *bad)
{
    size_t k = *next;
    if (k >= t->length) return 0;
    t->line++;
    t->start = t->pos = k;
    while (k < t->length && t->text[k] != '\n') {
        if (t->text[k] == '\0') *bad = 1;
        k++;
    }
    t->stop = k > t->pos && t->text[k - 1] == '\r' ? k - 1 : k;
    *next = k < t->length ? k + 1 : k;
    return 1;
}

/* A parse error of line t->line: code, the message fmt (its '@'s take
 * t->line and a), then the quoted text [s, s + len) (s NULL: none). */
static plateau_result plateau__io_mesh_error(plateau__io_mesh *t, plateau_result code, const char *fmt, long a,
                                             const char *s, size_t len)
{
    long v[2];
    v[0] = t->line;
    v[1] = a;
    plateau__util_error_n(t->err, code, t->line, fmt, v, 2);
    if (s) plateau__io_quote(t->err, s, len);
    return code;
}

/* Where the line's text ends: before a '#' and the blanks before it. */
static size_t plateau__io_line_end(const plateau__io_mesh *t)
{
    size_t k, end = t->start;
    for (k = t->start; k < t->stop && t->text[k] != '#'; k++)
        if (t->text[k] != ' ' && t->text[k] != '\t') end = k + 1;
    return end;
}

/* The coordinates of a vertex line from the field after its keyword:
 * three numbers, then at most max_extra more (numbers, left out). */
static plateau_result plateau__io_mesh_vertex(plateau__io_mesh *t, int max_extra)
{
    size_t fs, fl, n = 0;
    double v[3];
    while (plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl)) {
        double x;
        int bad = plateau__io_number(t->text + fs, fl, &x);
        if (bad == 2)
            return plateau__io_mesh_error(t, PLATEAU_ERR_NOT_FINITE, "line @: coordinate @ is NaN or infinite",
                                          (long)n + 1, t->text + fs, fl);
        if (bad || n >= 3 + (size_t)max_extra)
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE,
                                          bad ? "line @: field @ of the vertex is not a number"
                                              : "line @: more than @ numbers on a vertex line",
                                          bad ? (long)n + 1 : 3L + max_extra, t->text + fs, fl);
        if (n < 3) v[n] = x;
        n++;
    }
    if (n < 3)
        return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a vertex wants three numbers \"x y z\", not @",
                                      (long)n, t->text + t->start, plateau__io_line_end(t) - t->start);
    if (t->nv >= (size_t)PLATEAU_INDEX_MAX) {
        plateau__util_error(t->err, PLATEAU_ERR_OVERFLOW, t->line, "line @: more vertices than plateau_index holds",
                            t->line, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    if (t->fill) memcpy(t->xyz + 3 * t->nv, v, sizeof v);
    t->nv++;
    return PLATEAU_OK;
}

/* One corner c of a face: its vertex v (0-based; the file numbers it
 * v + base); the triangles of the fan so far (first corner *first, the one
 * before *prev) get (first, prev, v). */
static plateau_result plateau__io_mesh_corner(plateau__io_mesh *t, size_t c, double v, int base, const char *s,
                                              size_t len, double *first, double *prev)
{
    if (c > 0 && (v == *first || v == *prev))
        return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: the face names vertex @ twice (a degenerate "
                                      "triangle)", (long)v + base, s, len);
    if (c >= 2) {
        if (t->nt >= (size_t)PLATEAU_INDEX_MAX / 3) {
            plateau__util_error(t->err, PLATEAU_ERR_OVERFLOW, t->line,
                                "line @: more triangles than plateau_index holds", t->line, 0);
            return PLATEAU_ERR_OVERFLOW;
        }
        if (t->fill) {
            t->tri[3 * t->nt] = (plateau_index)*first;
            t->tri[3 * t->nt + 1] = (plateau_index)*prev;
            t->tri[3 * t->nt + 2] = (plateau_index)v;
            if (t->lines) t->lines[t->nt] = t->line;
        }
        t->nt++;
    }
    if (c == 0) *first = v;
    *prev = v;
    return PLATEAU_OK;
}

/* An OBJ face from the field after its keyword. */
static plateau_result plateau__io_obj_face(plateau__io_mesh *t)
{
    size_t fs, fl, c = 0;
    double first = -1.0, prev = -1.0;
    plateau_result r;
    while (plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl)) {
        const char *s = t->text + fs;
        size_t k = 0, q;
        double idx, v;
        while (k < fl && s[k] != '/') k++;
        for (q = k; q < fl; q++)
            if (!(s[q] == '/' || s[q] == '-' || (s[q] >= '0' && s[q] <= '9'))) break;
        if (q < fl || plateau__io_whole(s, k, &idx))
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: corner @ is not a vertex index (\"a\", "
                                          "\"a/t\", \"a//n\" or \"a/t/n\")", (long)c + 1, s, fl);
        if (idx == 0.0)
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: vertex index 0 (OBJ counts from 1)", 0, s,
                                          k);
        if (idx < 0.0) {
            v = (double)t->nv + idx;
            if (v < 0.0)
                return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: vertex index reaches before the first "
                                              "vertex (@ vertices come before the line)", (long)t->nv, s, k);
        } else {
            v = idx - 1.0;
            if (v >= (double)PLATEAU_INDEX_MAX)
                return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: vertex index beyond what plateau_index "
                                              "holds", 0, s, k);
            if (t->fill && v >= (double)t->total_nv)
                return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: vertex index beyond the @ vertices of "
                                              "the file", (long)t->total_nv, s, k);
        }
        r = plateau__io_mesh_corner(t, c, v, 1, s, k, &first, &prev);
        if (r != PLATEAU_OK) return r;
        c++;
    }
    if (c < 3)
        return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a face wants at least three corners, not @",
                                      (long)c, t->text + t->start, plateau__io_line_end(t) - t->start);
    return PLATEAU_OK;
}

/* OBJ's statements that hold nothing plateau reads (texture coordinates,
 * normals, groups, lines, points, materials, display attributes), and its
 * free-form geometry, which it cannot read. */
static const char *const plateau__io_obj_skipped[] = {"vt", "vn", "vp", "g", "o", "s", "mg", "l", "p", "usemtl",
                                                      "mtllib", "usemap", "maplib", "bevel", "c_interp",
                                                      "d_interp", "lod", "shadow_obj", "trace_obj", "ctech",
                                                      "stech", NULL};
static const char *const plateau__io_obj_freeform[] = {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
                                                       "parm", "trim", "hole", "scrv", "sp", "end", "con", NULL};

static plateau_result plateau__io_obj(plateau__io_mesh *t)
{
    size_t next = 0, ks, kl;
    int nul = 0;
    while (plateau__io_next_line(t, &next, &nul)) {
        const char *const *w;
        if (nul)
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a NUL byte: not a text file (a binary STL?)",
                                          0, NULL, 0);
        if (!plateau__io_token(t->text, &t->pos, t->stop, &ks, &kl)) continue;
        if (plateau__io_is(t->text + ks, kl, "v")) {
            plateau_result r = plateau__io_mesh_vertex(t, 4);
            if (r != PLATEAU_OK) return r;
            continue;
        }
        if (plateau__io_is(t->text + ks, kl, "f") || plateau__io_is(t->text + ks, kl, "fo")) {
            plateau_result r = plateau__io_obj_face(t);
            if (r != PLATEAU_OK) return r;
            continue;
        }
        for (w = plateau__io_obj_skipped; *w && !plateau__io_is(t->text + ks, kl, *w); w++) continue;
        if (*w) continue;
        for (w = plateau__io_obj_freeform; *w && !plateau__io_is(t->text + ks, kl, *w); w++) continue;
        if (t->line == 1 && (plateau__io_is(t->text + ks, kl, "ply") || plateau__io_is(t->text + ks, kl, "solid")))
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE,
                                          kl == 3 ? "line @: a PLY file: OBJ and OFF meshes are read"
                                                  : "line @: an ASCII STL file: OBJ and OFF meshes are read",
                                          0, t->text + ks, kl);
        return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE,
                                      *w ? "line @: free-form geometry (curves and surfaces) is not read"
                                         : "line @: not an OBJ statement that plateau reads (v, f)",
                                      0, t->text + ks, plateau__io_line_end(t) - ks);
    }
    return PLATEAU_OK;
}

/* 1 when the text's first line with a field starts with an OFF header. */
static int plateau__io_is_off(plateau__io_mesh *t)
{
    size_t next = 0, fs, fl;
    int nul = 0, off = 0;
    long line = t->line;
    while (plateau__io_next_line(t, &next, &nul))
        if (plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl)) {
            off = plateau__io_is(t->text + fs, fl, "OFF") || plateau__io_is(t->text + fs, fl, "COFF") ||
                  plateau__io_is(t->text + fs, fl, "NOFF") || plateau__io_is(t->text + fs, fl, "CNOFF");
            break;
        }
    t->line = line;
    return off;
}

/* OFF: the header, the counts, the vertices, the faces. */
static plateau_result plateau__io_off(plateau__io_mesh *t)
{
    size_t next = 0, fs, fl, i, want[2] = {0, 0}, faces = 0;
    int nul = 0, got = 0, stage = -1; /* -1 the header, 0 the counts, 1 vertices, 2 faces, 3 done */
    while (plateau__io_next_line(t, &next, &nul)) {
        if (nul)
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a NUL byte: not a text file (a binary STL?)",
                                          0, NULL, 0);
        if (!plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl)) continue;
        if (stage < 0) { /* plateau__io_is_off found it; counts may follow on the line */
            stage = 0;
            if (!plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl)) continue;
        }
        if (stage == 0) {
            double c;
            do {
                if (plateau__io_whole(t->text + fs, fl, &c) || c < 0.0 || got >= 3)
                    return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE,
                                                  got >= 3 ? "line @: more than the three counts \"V F E\""
                                                           : "line @: count @ is not a whole number below 2^53",
                                                  (long)got + 1, t->text + fs, fl);
                if (got < 2) want[got] = c > 9.0e15 ? (size_t)-1 : (size_t)c;
                got++;
            } while (plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl));
            if (got < 2)
                return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: the counts \"V F E\" want V and F", 0,
                                              t->text + fs, fl);
            if (want[0] > (size_t)PLATEAU_INDEX_MAX) {
                plateau__util_error(t->err, PLATEAU_ERR_OVERFLOW, t->line,
                                    "line @: more vertices than plateau_index holds", t->line, 0);
                return PLATEAU_ERR_OVERFLOW;
            }
            stage = want[0] ? 1 : want[1] ? 2 : 3;
            continue;
        }
        if (stage == 3)
            return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a line after the last face (the counts say "
                                          "F = @)", (long)want[1], t->text + t->start,
                                          plateau__io_line_end(t) - t->start);
        t->pos = fs;
        if (stage == 1) {
            plateau_result r = plateau__io_mesh_vertex(t, 7); /* a normal, a colour */
            if (r != PLATEAU_OK) return r;
            if (t->nv == want[0]) stage = want[1] ? 2 : 3;
            continue;
        }
        {   /* a face: n, n indices, then perhaps a colour */
            double n, idx, first = -1.0, prev = -1.0;
            plateau_result r;
            plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl);
            if (plateau__io_whole(t->text + fs, fl, &n) || n < 3.0)
                return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: a face starts with its number of "
                                              "corners, 3 or more", 0, t->text + fs, fl);
            for (i = 0; (double)i < n; i++) {
                int bad;
                if (!plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl))
                    return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: the face has @ corners, fewer "
                                                  "than its count", (long)i, t->text + t->start,
                                                  plateau__io_line_end(t) - t->start);
                bad = plateau__io_whole(t->text + fs, fl, &idx) || idx < 0.0;
                if (bad || idx >= (double)want[0])
                    return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE,
                                                  bad ? "line @: corner @ is not a vertex index (0-based)"
                                                      : "line @: vertex index beyond the @ vertices of the file",
                                                  bad ? (long)i + 1 : (long)want[0], t->text + fs, fl);
                r = plateau__io_mesh_corner(t, i, idx, 0, t->text + fs, fl, &first, &prev);
                if (r != PLATEAU_OK) return r;
            }
            while (plateau__io_token(t->text, &t->pos, t->stop, &fs, &fl))
                if (plateau__io_number(t->text + fs, fl, &idx) != 0)
                    return plateau__io_mesh_error(t, PLATEAU_ERR_PARSE, "line @: after the face's corners, a "
                                                  "field that is not a number (a colour)", 0, t->text + fs, fl);
            if (++faces == want[1]) stage = 3;
        }
    }
    if (stage < 3) {
        long v[3];
        v[0] = t->line;
        v[1] = stage == 1 ? (long)t->nv : (long)faces;
        v[2] = stage == 1 ? (long)want[0] : (long)want[1];
        plateau__util_error_n(t->err, PLATEAU_ERR_PARSE, t->line,
                              stage < 1    ? "line @: the OFF text ends before its counts \"V F E\""
                              : stage == 1 ? "line @: the text ends after @ of the @ vertices its counts say"
                                           : "line @: the text ends after @ of the @ faces its counts say",
                              v, 3);
        return PLATEAU_ERR_PARSE;
    }
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_parse_mesh(const char *text, size_t length, const plateau_allocator *allocator,
                                              double **positions, size_t *num_vertices,
                                              plateau_index **triangles, size_t *num_triangles,
                                              long **face_lines, plateau_error *err)
{
    plateau__io_mesh t;
    plateau_result r;
    int off, pass;
    if (positions) *positions = NULL;
    if (num_vertices) *num_vertices = 0;
    if (triangles) *triangles = NULL;
    if (num_triangles) *num_triangles = 0;
    if (face_lines) *face_lines = NULL;
    if (!positions || !num_vertices || !triangles || !num_triangles || (!text && length > 0) ||
        !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "plateau_parse_mesh: a NULL argument or a bad allocator",
                            0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    memset(&t, 0, sizeof t);
    t.text = text;
    t.length = length;
    t.err = err;
    off = plateau__io_is_off(&t);
    for (pass = 0; pass < 2; pass++) {
        t.line = 0;
        t.nv = t.nt = 0;
        r = off ? plateau__io_off(&t) : plateau__io_obj(&t);
        if (r == PLATEAU_OK && pass == 0 && t.nt == 0) {
            plateau__util_error(err, PLATEAU_ERR_PARSE, -1,
                                off ? "no face: the OFF text's counts say 0 faces"
                                    : "no face: a mesh text wants \"f\" lines (and \"v\" lines)", 0, 0);
            r = PLATEAU_ERR_PARSE;
        }
        if (r == PLATEAU_OK && pass == 0) { /* the arrays, for the second pass to fill */
            t.total_nv = t.nv;
            t.fill = 1;
            t.xyz = t.nv ? (double *)plateau__util_array(allocator, t.nv, 3 * sizeof(double)) : NULL;
            t.tri = (plateau_index *)plateau__util_array(allocator, t.nt, 3 * sizeof(plateau_index));
            if (face_lines) t.lines = (long *)plateau__util_array(allocator, t.nt, sizeof(long));
            if ((!t.xyz && t.nv) || !t.tri || (face_lines && !t.lines)) {
                plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the mesh", 0, 0);
                r = PLATEAU_ERR_OUT_OF_MEMORY;
            }
        }
        if (r != PLATEAU_OK) {
            plateau_mesh_arrays_free(t.xyz, t.tri, t.lines, allocator);
            return r;
        }
    }
    *positions = t.xyz;
    *num_vertices = t.nv;
    *triangles = t.tri;
    *num_triangles = t.nt;
    if (face_lines) *face_lines = t.lines;
    return plateau__util_ok(err);
}
#elif !defined(PLATEAU_FREESTANDING) /* PLATEAU_NO_PARSERS: the parsers refuse */
static plateau_result plateau__io_no_parsers(plateau_error *err)
{
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the text parsers are compiled out by PLATEAU_NO_PARSERS",
                        0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

PLATEAU_DEF plateau_result plateau_parse_boundary(const char *text, size_t length,
                                                  const plateau_allocator *allocator,
                                                  double **xyz, size_t *m,
                                                  plateau_error *err)
{
    (void)text, (void)length, (void)allocator;
    if (xyz) *xyz = NULL;
    if (m) *m = 0;
    return plateau__io_no_parsers(err);
}

PLATEAU_DEF plateau_result plateau_parse_cables(char *text, size_t length, const plateau_allocator *allocator,
                                                double **tension, size_t *count, plateau_error *err)
{
    (void)text, (void)length, (void)allocator;
    if (tension) *tension = NULL;
    if (count) *count = 0;
    return plateau__io_no_parsers(err);
}

PLATEAU_DEF plateau_result plateau_parse_boundary_lines(const char *text, size_t length,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_boundary_lines *info,
                                                        plateau_error *err)
{
    (void)text, (void)length, (void)allocator;
    if (xyz) *xyz = NULL;
    if (m) *m = 0;
    plateau_boundary_lines_free(info, allocator);
    return plateau__io_no_parsers(err);
}

PLATEAU_DEF void plateau_boundary_lines_free(plateau_boundary_lines *info,
                                             const plateau_allocator *allocator)
{
    (void)allocator;
    if (!info) return;
    info->lines = NULL; /* nothing was allocated: the parser refused */
    info->loop_counts = NULL;
    info->closing_lines = NULL;
    info->num_loops = info->closing_dropped = 0;
}

PLATEAU_DEF plateau_result plateau_cables_align(double *tension, size_t *count,
                                                const plateau_boundary_lines *info, plateau_error *err)
{
    (void)tension, (void)count, (void)info;
    return plateau__io_no_parsers(err);
}

PLATEAU_DEF plateau_result plateau_parse_mesh(const char *text, size_t length, const plateau_allocator *allocator,
                                              double **positions, size_t *num_vertices,
                                              plateau_index **triangles, size_t *num_triangles,
                                              long **face_lines, plateau_error *err)
{
    (void)text, (void)length, (void)allocator;
    if (positions) *positions = NULL;
    if (num_vertices) *num_vertices = 0;
    if (triangles) *triangles = NULL;
    if (num_triangles) *num_triangles = 0;
    if (face_lines) *face_lines = NULL;
    return plateau__io_no_parsers(err);
}
#endif /* PLATEAU_FREESTANDING, PLATEAU_NO_PARSERS */

PLATEAU_DEF void plateau_boundary_free(double *xyz, const plateau_allocator *allocator)
{
    if (xyz) plateau__free(allocator, xyz);
}

PLATEAU_DEF void plateau_mesh_arrays_free(double *positions, plateau_index *triangles, long *face_lines,
                                          const plateau_allocator *allocator)
{
    if (positions) plateau__free(allocator, positions);
    if (triangles) plateau__free(allocator, triangles);
    if (face_lines) plateau__free(allocator, face_lines);
}

PLATEAU_DEF plateau_result plateau_mesh_vertex_marks(const plateau_mesh *mesh, unsigned char *marks,
                                                     plateau_error *err)
{
    size_t v, e;
    if (!mesh || !marks || !mesh->edges || !mesh->edge_triangles || !mesh->fixed) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_mesh_vertex_marks: no mesh, no adjacency or no marks", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (v = 0; v < mesh->num_vertices; v++) marks[v] = PLATEAU_MARK_INTERIOR;
    for (e = 0; e < mesh->num_edges; e++) {
        int k;
        if (mesh->edge_triangles[2 * e + 1] >= 0) continue;
        for (k = 0; k < 2; k++) {
            size_t w = (size_t)mesh->edges[2 * e + (size_t)k];
            marks[w] = mesh->fixed[w] ? PLATEAU_MARK_BOUNDARY : PLATEAU_MARK_CABLE;
        }
    }
    return plateau__util_ok(err);
}

PLATEAU_DEF void plateau_colormap(double t, double rgb[3])
{
    /* Green (2011), start 0.5, rotations -1.5, hue 1, gamma 1, on the grey
     * levels [0.15, 0.9] */
    double g, a, phi, cp, sp;
    if (!(t > 0.0)) t = 0.0; /* NaN too */
    if (t > 1.0) t = 1.0;
    g = 0.15 + 0.75 * t;
    a = 0.5 * g * (1.0 - g);
    phi = 2.0 * 3.14159265358979323846 * (0.5 / 3.0 - 1.5 * g);
    cp = PLATEAU_COS(phi);
    sp = PLATEAU_SIN(phi);
    rgb[0] = g + a * (-0.14861 * cp + 1.78277 * sp);
    rgb[1] = g + a * (-0.29227 * cp - 0.90649 * sp);
    rgb[2] = g + a * (1.97294 * cp);
}

#ifndef PLATEAU_NO_STDIO
#include <stdio.h>
#include <float.h> /* FLT_MAX: STL's float range */

static plateau_result plateau__io_fail(plateau_error *err, plateau_result code, long index,
                                       const char *what, const char *path)
{
    plateau__util_error(err, code, index, what, 0, 0);
    if (err) {
        size_t k = strlen(err->message);
        snprintf(err->message + k, sizeof err->message - k, " %.100s", path ? path : "(null)");
    }
    return code;
}

/* The checks shared by the writers, done before any file is touched. */
static plateau_result plateau__io_check_mesh(const char *path, const double *positions,
                                             size_t nv, const plateau_index *triangles,
                                             size_t nt, plateau_error *err)
{
    size_t i;
    if (!path || (nv > 0 && !positions) || (nt > 0 && !triangles)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "a NULL path, or a NULL array with a non-zero count", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (i = 0; i < 3 * nv; i++) {
        if (!plateau__util_finite(positions[i])) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)(i / 3),
                              "vertex @ has a NaN or infinite coordinate", (long)(i / 3), 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    }
    for (i = 0; i < 3 * nt; i++) {
        if (triangles[i] < 0 || (size_t)triangles[i] >= nv) {
            plateau__util_error(err, PLATEAU_ERR_INDEX_RANGE, (long)(i / 3),
                              "triangle @ has a vertex index out of range", (long)(i / 3), 0);
            return PLATEAU_ERR_INDEX_RANGE;
        }
    }
    return PLATEAU_OK;
}

/* The writers' files never replace a target with a part of one: the file
 * is written whole to a temporary file beside the target (its path with
 * ".tmp" and a number 0 to 15 appended: the first such name that does not
 * exist), flushed and closed, and only then renamed over the target
 * (rename(), standard C).  On any failure (the temporary cannot be made, a
 * write, the flush or the close fails, the rename fails) the temporary is
 * removed and the target is left as it was; a process killed while writing
 * leaves the temporary, never a truncated target.  POSIX rename replaces
 * the target in one step, so a reader sees the old file or the new one; a
 * symbolic link at the path is itself replaced by the new file (the file
 * it pointed to is left alone: to write through a link, pass the path it
 * resolves to, as the command-line tool does).  Under _WIN32, where
 * rename() refuses an existing target, the target is removed first; if
 * the rename still fails, the new file stays under the temporary name,
 * which the message gives.  Standard C cannot create a file exclusively:
 * a temporary name made by another process between the test and the
 * creation would be written over. */
typedef struct plateau__io_out {
    FILE *f;
    const char *path;
    char tmp[FILENAME_MAX];
} plateau__io_out;

static plateau_result plateau__io_open(plateau__io_out *o, const char *path, plateau_error *err)
{
    size_t len = strlen(path);
    int k;
    o->f = NULL;
    o->path = path;
    if (len + 8 > sizeof o->tmp)
        return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "the path is too long for a temporary file beside it:",
                                path);
    for (k = 0; k < 16; k++) {
        FILE *probe;
        memcpy(o->tmp, path, len);
        o->tmp[len] = '.';
        o->tmp[len + 1] = 't';
        o->tmp[len + 2] = 'm';
        o->tmp[len + 3] = 'p';
        o->tmp[len + 4] = (char)(k < 10 ? '0' + k : 'a' + k - 10);
        o->tmp[len + 5] = '\0';
        probe = fopen(o->tmp, "rb");
        if (probe) { /* taken (a file, or a directory) */
            fclose(probe);
            continue;
        }
        o->f = fopen(o->tmp, "wb");
        if (o->f) return PLATEAU_OK;
        break;
    }
    return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "cannot create a temporary file to write", path);
}

/* Closes the temporary; renames it over the target when everything was
 * written, else removes it (PLATEAU_ERR_IO). */
static plateau_result plateau__io_finish(plateau__io_out *o, int failed, plateau_error *err)
{
    if (fflush(o->f) != 0 || ferror(o->f)) failed = 1;
    if (fclose(o->f) != 0) failed = 1;
    o->f = NULL;
    if (failed) {
        remove(o->tmp);
        return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "could not write (the file is left as it was):",
                                o->path);
    }
    if (rename(o->tmp, o->path) != 0) {
#ifdef _WIN32
        remove(o->path);
        if (rename(o->tmp, o->path) == 0) return plateau__util_ok(err);
        return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "could not rename; the new file is", o->tmp);
#else
        remove(o->tmp);
        return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "could not replace (the file is left as it was):",
                                o->path);
#endif
    }
    return plateau__util_ok(err);
}

static int plateau__io_ext_is(const char *path, const char *ext)
{
    const char *dot = NULL, *p;
    for (p = path; *p; p++) {
        if (*p == '.') dot = p;
        if (*p == '/' || *p == '\\') dot = NULL;
    }
    if (!dot) return 0;
    for (p = dot + 1; *p && *ext; p++, ext++) {
        char c = *p;
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != *ext) return 0;
    }
    return *p == '\0' && *ext == '\0';
}

/* STL's 32-bit floats: the writer below relies on float being IEEE binary32
 * (a compile error otherwise). */
typedef char plateau__io_float_is_32_bits[sizeof(float) == 4 ? 1 : -1];

/* x as 4 little-endian bytes of a binary32 float. */
static void plateau__io_le_float(unsigned char *b, float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    b[0] = (unsigned char)(u & 255u);
    b[1] = (unsigned char)((u >> 8) & 255u);
    b[2] = (unsigned char)((u >> 16) & 255u);
    b[3] = (unsigned char)((u >> 24) & 255u);
}

/* One STL facet: the unit normal of (a, b, c) (0 0 0 if degenerate) and
 * the corners, as floats: v[0..2] the normal, v[3..11] the corners. */
static void plateau__io_stl_facet(const double *positions, const plateau_index *t, float v[12])
{
    const double *a = positions + 3 * (size_t)t[0], *b = positions + 3 * (size_t)t[1],
                 *c = positions + 3 * (size_t)t[2];
    double e1[3], e2[3], n[3], len;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = PLATEAU_SQRT(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (k = 0; k < 3; k++) {
        v[k] = len > 0.0 && plateau__util_finite(len) ? (float)(n[k] / len) : 0.0f;
        v[3 + k] = (float)a[k];
        v[6 + k] = (float)b[k];
        v[9 + k] = (float)c[k];
    }
}

/* The facets of an STL file (binary, or ASCII when ascii); returns
 * non-zero when a write failed. */
static int plateau__io_write_stl(FILE *f, const double *positions, const plateau_index *triangles,
                                 size_t nt, int ascii)
{
    size_t i;
    int failed = 0, k;
    float v[12];
    if (ascii) {
        failed |= fprintf(f, "solid plateau\n") < 0;
        for (i = 0; i < nt && !failed; i++) {
            plateau__io_stl_facet(positions, triangles + 3 * i, v);
            failed |= fprintf(f, "  facet normal %.9g %.9g %.9g\n    outer loop\n", (double)v[0],
                              (double)v[1], (double)v[2]) < 0;
            for (k = 1; k < 4; k++)
                failed |= fprintf(f, "      vertex %.9g %.9g %.9g\n", (double)v[3 * k],
                                  (double)v[3 * k + 1], (double)v[3 * k + 2]) < 0;
            failed |= fprintf(f, "    endloop\n  endfacet\n") < 0;
        }
        if (!failed) failed |= fprintf(f, "endsolid plateau\n") < 0;
    } else {
        unsigned char head[84], rec[50];
        size_t len;
        memset(head, ' ', 80);
        len = strlen("plateau " PLATEAU_VERSION " binary STL");
        memcpy(head, "plateau " PLATEAU_VERSION " binary STL", len < 80 ? len : 80);
        for (k = 0; k < 4; k++) head[80 + k] = (unsigned char)((nt >> (8 * k)) & 255u);
        failed |= fwrite(head, 1, 84, f) != 84;
        rec[48] = rec[49] = 0; /* the attribute byte count */
        for (i = 0; i < nt && !failed; i++) {
            plateau__io_stl_facet(positions, triangles + 3 * i, v);
            for (k = 0; k < 12; k++) plateau__io_le_float(rec + 4 * k, v[k]);
            failed |= fwrite(rec, 1, 50, f) != 50;
        }
    }
    return failed;
}

/* STL's own checks: every coordinate within the float range, and in
 * binary the facet count within its uint32. */
static plateau_result plateau__io_check_stl(const double *positions, size_t nv, size_t nt, int ascii,
                                            plateau_error *err)
{
    size_t i;
    for (i = 0; i < 3 * nv; i++) {
        if (PLATEAU_FABS(positions[i]) > (double)FLT_MAX) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)(i / 3),
                                "vertex @ has a coordinate beyond STL's 32-bit float range", (long)(i / 3), 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    }
    if (!ascii && nt / 65536u / 65536u > 0) { /* nt > 2^32 - 1 */
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1,
                            "binary STL counts at most 4294967295 triangles", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_write_mesh(const char *path, const double *positions,
                                              size_t num_vertices,
                                              const plateau_index *triangles,
                                              size_t num_triangles, plateau_error *err)
{
    return plateau_write_mesh_format(path, positions, num_vertices, triangles, num_triangles,
                                     PLATEAU_MESH_FORMAT_AUTO, err);
}

/* ---- the marked writer (plateau_write_mesh_marked): boundary loops ---- */

/* A triangle's edge: its vertices in the triangle's direction (from, to)
 * and as a key (lo < hi). */
typedef struct plateau__io_edge {
    plateau_index lo, hi, from, to;
} plateau__io_edge;

static int plateau__io_edge_key_cmp(const void *pa, const void *pb)
{
    const plateau__io_edge *a = (const plateau__io_edge *)pa, *b = (const plateau__io_edge *)pb;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    if (a->from != b->from) return a->from < b->from ? -1 : 1;
    return 0;
}

static int plateau__io_edge_from_cmp(const void *pa, const void *pb)
{
    const plateau__io_edge *a = (const plateau__io_edge *)pa, *b = (const plateau__io_edge *)pb;
    if (a->from != b->from) return a->from < b->from ? -1 : 1;
    if (a->to != b->to) return a->to < b->to ? -1 : 1;
    return 0;
}

/* The boundary loops of a triangle list: the vertices of loop j are
 * seq[start[j] .. start[j + 1]), closed[j] 1 when the loop returns to its
 * first vertex (the OBJ polyline repeats it).  All four arrays through
 * the allocator (plateau__io_loops_free). */
typedef struct plateau__io_loops {
    plateau__io_edge *edge;  /* the boundary edges, by their first vertex */
    plateau_index *seq;
    size_t *start;
    unsigned char *closed;
    size_t num_edges, num_loops;
} plateau__io_loops;

static void plateau__io_loops_free(plateau__io_loops *l, const plateau_allocator *a)
{
    plateau__free(a, l->edge);
    plateau__free(a, l->seq);
    plateau__free(a, l->start);
    plateau__free(a, l->closed);
    memset(l, 0, sizeof *l);
}

/* The first edge of l->edge leaving v that is not used yet, or ne. */
static size_t plateau__io_edge_leaving(const plateau__io_loops *l, const unsigned char *used, plateau_index v)
{
    size_t lo = 0, hi = l->num_edges;
    while (lo < hi) { /* the first edge with from >= v */
        size_t mid = lo + (hi - lo) / 2;
        if (l->edge[mid].from < v) lo = mid + 1;
        else hi = mid;
    }
    while (lo < l->num_edges && l->edge[lo].from == v && used[lo]) lo++;
    return lo < l->num_edges && l->edge[lo].from == v ? lo : l->num_edges;
}

/* The edges of one triangle each (sorted by their key, a run of one) and
 * the loops they make, walked from the unused edge of smallest first
 * vertex, each edge used once. */
static plateau_result plateau__io_find_loops(const plateau_index *triangles, size_t nt,
                                             const plateau_allocator *a, plateau__io_loops *l, plateau_error *err)
{
    size_t i, j, n = 0, k = 0, s;
    unsigned char *used;
    memset(l, 0, sizeof *l);
    if (plateau__bytes(nt, 3 * sizeof(plateau__io_edge)) == 0 && nt > 0) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many triangles for the boundary loops", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    l->edge = (plateau__io_edge *)plateau__util_array(a, nt, 3 * sizeof(plateau__io_edge));
    if (!l->edge && nt > 0) goto oom;
    for (i = 0; i < 3 * nt; i++) {
        plateau__io_edge *e = l->edge + i;
        e->from = triangles[i];
        e->to = triangles[i - i % 3 + (i % 3 + 1) % 3];
        e->lo = e->from < e->to ? e->from : e->to;
        e->hi = e->from < e->to ? e->to : e->from;
    }
    if (nt > 0) PLATEAU_QSORT(l->edge, 3 * nt, sizeof *l->edge, plateau__io_edge_key_cmp);
    for (i = 0; i < 3 * nt; i = j) {
        for (j = i + 1; j < 3 * nt && l->edge[j].lo == l->edge[i].lo && l->edge[j].hi == l->edge[i].hi; j++) continue;
        if (j == i + 1) l->edge[n++] = l->edge[i];
    }
    l->num_edges = n;
    if (n > 0) PLATEAU_QSORT(l->edge, n, sizeof *l->edge, plateau__io_edge_from_cmp);
    /* a chain that does not close takes one vertex more than its edges */
    l->seq = (plateau_index *)plateau__util_array(a, n + 1, 2 * sizeof(plateau_index));
    l->start = (size_t *)plateau__util_array(a, n + 2, sizeof(size_t));
    l->closed = (unsigned char *)plateau__util_array(a, n + 1, 2);
    if (!l->seq || !l->start || !l->closed) goto oom;
    used = l->closed + n + 1;
    memset(used, 0, n + 1);
    for (s = 0; s < n; s++) {
        size_t cur = s;
        plateau_index first = l->edge[s].from;
        if (used[s]) continue;
        l->start[l->num_loops] = k;
        l->closed[l->num_loops] = 0;
        for (;;) {
            used[cur] = 1;
            l->seq[k++] = l->edge[cur].from;
            if (l->edge[cur].to == first) {
                l->closed[l->num_loops] = 1;
                break;
            }
            i = plateau__io_edge_leaving(l, used, l->edge[cur].to);
            if (i == n) {
                l->seq[k++] = l->edge[cur].to;
                break;
            }
            cur = i;
        }
        l->num_loops++;
    }
    l->start[l->num_loops] = k;
    return PLATEAU_OK;
oom:
    plateau__io_loops_free(l, a);
    plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the boundary loops", 0, 0);
    return PLATEAU_ERR_OUT_OF_MEMORY;
}

/* OBJ's groups "boundary" (a polyline per loop) and, with marks (NULL:
 * none), "cables" (a polyline per run of cable vertices, from its anchor
 * before to its anchor after); non-zero when a write failed. */
static int plateau__io_write_obj_loops(FILE *f, const plateau__io_loops *l, const unsigned char *marks)
{
    size_t j, i, c;
    int failed = fprintf(f, "g boundary\n") < 0, cables = 0;
    for (j = 0; j < l->num_loops && !failed; j++) {
        const plateau_index *v = l->seq + l->start[j];
        size_t len = l->start[j + 1] - l->start[j];
        failed |= fputc('l', f) == EOF;
        for (i = 0; i < len && !failed; i++) failed |= fprintf(f, " %ld", (long)v[i] + 1) < 0;
        if (l->closed[j] && !failed) failed |= fprintf(f, " %ld", (long)v[0] + 1) < 0;
        failed |= fputc('\n', f) == EOF;
    }
    for (j = 0; marks && j < l->num_loops && !failed; j++) {
        const plateau_index *v = l->seq + l->start[j];
        size_t len = l->start[j + 1] - l->start[j], r = 0;
        int closed = l->closed[j];
        if (closed) { /* start the walk on a vertex that is no cable's */
            while (r < len && marks[v[r]] == PLATEAU_MARK_CABLE) r++;
            if (r == len) { /* cables all round: the loop is the polyline */
                if (!cables++) failed |= fprintf(f, "g cables\n") < 0;
                failed |= fputc('l', f) == EOF;
                for (i = 0; i <= len && !failed; i++) failed |= fprintf(f, " %ld", (long)v[i % len] + 1) < 0;
                failed |= fputc('\n', f) == EOF;
                continue;
            }
        }
        for (i = 0; i < len && !failed; i++) {
            size_t at = (r + i) % len;
            int after_cable = closed ? marks[v[(at + len - 1) % len]] == PLATEAU_MARK_CABLE
                                     : at > 0 && marks[v[at - 1]] == PLATEAU_MARK_CABLE;
            if (marks[v[at]] != PLATEAU_MARK_CABLE || after_cable) continue;
            if (!cables++) failed |= fprintf(f, "g cables\n") < 0;
            failed |= fputc('l', f) == EOF;
            if (closed || at > 0) failed |= fprintf(f, " %ld", (long)v[(at + len - 1) % len] + 1) < 0;
            for (c = 0; c < len && !failed; c++) { /* the run, then its anchor after it */
                size_t q = closed ? (at + c) % len : at + c;
                if (q >= len) break;
                failed |= fprintf(f, " %ld", (long)v[q] + 1) < 0;
                if (marks[v[q]] != PLATEAU_MARK_CABLE) break;
            }
            failed |= fputc('\n', f) == EOF;
        }
    }
    return failed;
}


/* The format fmt asks for at path (AUTO: by the extension): 0 OBJ, 1 PLY,
 * 2 OFF, 3 STL, 4 ASCII STL; -1 with the error. */
static int plateau__io_format(const char *path, plateau_mesh_format fmt, plateau_error *err)
{
    if (fmt == PLATEAU_MESH_FORMAT_AUTO) {
        if (plateau__io_ext_is(path, "obj")) fmt = PLATEAU_MESH_FORMAT_OBJ;
        else if (plateau__io_ext_is(path, "ply")) fmt = PLATEAU_MESH_FORMAT_PLY;
        else if (plateau__io_ext_is(path, "off")) fmt = PLATEAU_MESH_FORMAT_OFF;
        else if (plateau__io_ext_is(path, "stl")) fmt = PLATEAU_MESH_FORMAT_STL;
        else {
            plateau__io_fail(err, PLATEAU_ERR_ARGUMENT, -1, "unknown mesh format (use .obj, .ply, .off or .stl):", path);
            return -1;
        }
    }
    if (fmt < PLATEAU_MESH_FORMAT_OBJ || fmt > PLATEAU_MESH_FORMAT_STL_ASCII) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)fmt, "unknown mesh format @", (long)fmt, 0);
        return -1;
    }
    return (int)fmt - 1;
}

/* The file of an OBJ (format 0), PLY (1) or OFF (2) mesh; with marks
 * (NULL: none) PLY's vertex property "boundary", with loops (NULL: none)
 * OBJ's groups after its faces (plateau_write_mesh_marked).  Non-zero
 * when a write failed. */
static int plateau__io_write_text_mesh(FILE *f, int format, const double *positions, size_t num_vertices,
                                       const plateau_index *triangles, size_t num_triangles,
                                       const unsigned char *marks, const plateau__io_loops *loops)
{
    int failed = 0;
    size_t i;
    if (format == 0) {
        failed |= fprintf(f, "# plateau %s: %lu vertices, %lu triangles\n", PLATEAU_VERSION,
                          (unsigned long)num_vertices, (unsigned long)num_triangles) < 0;
        if (loops)
            failed |= fprintf(f, "# group film: the triangles; group boundary: a polyline per boundary loop%s\n",
                              marks ? "; group cables: a polyline per cable, anchor to anchor" : "") < 0;
    } else if (format == 1) {
        failed |= fprintf(f,
                          "ply\nformat ascii 1.0\ncomment plateau %s\n%s"
                          "element vertex %lu\nproperty double x\nproperty double y\n"
                          "property double z\n%selement face %lu\n"
                          "property list uchar int vertex_indices\nend_header\n",
                          PLATEAU_VERSION,
                          marks ? "comment boundary: 0 interior, 1 boundary, 2 cable vertex\n" : "",
                          (unsigned long)num_vertices, marks ? "property uchar boundary\n" : "",
                          (unsigned long)num_triangles) < 0;
    } else {
        failed |= fprintf(f, "OFF\n%lu %lu 0\n", (unsigned long)num_vertices,
                          (unsigned long)num_triangles) < 0;
    }
    for (i = 0; i < num_vertices && !failed; i++) {
        const double *p = positions + 3 * i;
        if (format == 1 && marks)
            failed |= fprintf(f, "%.17g %.17g %.17g %u\n", p[0], p[1], p[2], (unsigned)marks[i]) < 0;
        else
            failed |= fprintf(f, "%s%.17g %.17g %.17g\n", format == 0 ? "v " : "", p[0], p[1], p[2]) < 0;
    }
    if (format == 0 && loops && !failed) failed |= fprintf(f, "g film\n") < 0;
    for (i = 0; i < num_triangles && !failed; i++) {
        const plateau_index *t = triangles + 3 * i;
        long base = format == 0 ? 1 : 0;
        failed |= fprintf(f, "%s%ld %ld %ld\n", format == 0 ? "f " : "3 ", (long)t[0] + base,
                          (long)t[1] + base, (long)t[2] + base) < 0;
    }
    if (format == 0 && loops && !failed) failed |= plateau__io_write_obj_loops(f, loops, marks);
    return failed;
}

PLATEAU_DEF plateau_result plateau_write_mesh_format(const char *path, const double *positions,
                                                     size_t num_vertices,
                                                     const plateau_index *triangles,
                                                     size_t num_triangles,
                                                     plateau_mesh_format fmt,
                                                     plateau_error *err)
{
    int format, failed;
    plateau__io_out out;
    plateau_result r = plateau__io_check_mesh(path, positions, num_vertices, triangles,
                                              num_triangles, err);
    if (r != PLATEAU_OK) return r;
    format = plateau__io_format(path, fmt, err);
    if (format < 0) return PLATEAU_ERR_ARGUMENT;
    if (format >= 3) {
        r = plateau__io_check_stl(positions, num_vertices, num_triangles, format == 4, err);
        if (r != PLATEAU_OK) return r;
    }
    r = plateau__io_open(&out, path, err);
    if (r != PLATEAU_OK) return r;
    if (format >= 3) failed = plateau__io_write_stl(out.f, positions, triangles, num_triangles, format == 4);
    else failed = plateau__io_write_text_mesh(out.f, format, positions, num_vertices, triangles, num_triangles,
                                              NULL, NULL);
    return plateau__io_finish(&out, failed, err);
}

PLATEAU_DEF plateau_result plateau_write_mesh_marked(const char *path, const double *positions,
                                                     size_t num_vertices, const plateau_index *triangles,
                                                     size_t num_triangles, const unsigned char *marks,
                                                     plateau_mesh_format fmt, const plateau_allocator *allocator,
                                                     plateau_error *err)
{
    int format, failed;
    size_t i;
    plateau__io_out out;
    plateau__io_loops loops;
    unsigned char *own = NULL; /* the marks computed when none are given */
    plateau_result r = plateau__io_check_mesh(path, positions, num_vertices, triangles, num_triangles, err);
    if (r != PLATEAU_OK) return r;
    if (!plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the allocator sets only one of its two functions", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (i = 0; marks && i < num_vertices; i++) {
        if (marks[i] > PLATEAU_MARK_CABLE) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)i, "vertex @ has mark @ (0 interior, 1 boundary, "
                                "2 cable vertex)", (long)i, (long)marks[i]);
            return PLATEAU_ERR_ARGUMENT;
        }
    }
    format = plateau__io_format(path, fmt, err);
    if (format < 0) return PLATEAU_ERR_ARGUMENT;
    if (format >= 2) /* OFF and STL have no place for marks */
        return plateau_write_mesh_format(path, positions, num_vertices, triangles, num_triangles, fmt, err);
    memset(&loops, 0, sizeof loops);
    r = plateau__io_find_loops(triangles, num_triangles, allocator, &loops, err);
    if (r == PLATEAU_OK && !marks && format == 1) {
        own = (unsigned char *)plateau__util_array(allocator, num_vertices, 1);
        if (!own && num_vertices > 0) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the marks", 0, 0);
            r = PLATEAU_ERR_OUT_OF_MEMORY;
        } else {
            for (i = 0; i < num_vertices; i++) own[i] = PLATEAU_MARK_INTERIOR;
            for (i = 0; i < loops.start[loops.num_loops]; i++) own[loops.seq[i]] = PLATEAU_MARK_BOUNDARY;
        }
    }
    if (r == PLATEAU_OK) r = plateau__io_open(&out, path, err);
    if (r == PLATEAU_OK) {
        failed = plateau__io_write_text_mesh(out.f, format, positions, num_vertices, triangles, num_triangles,
                                             marks ? marks : own, format == 0 ? &loops : NULL);
        r = plateau__io_finish(&out, failed, err);
    }
    plateau__free(allocator, own);
    plateau__io_loops_free(&loops, allocator);
    return r;
}

/* ---- SVG drawing (PLATEAU_NO_SVG leaves it out) ---- */
#ifndef PLATEAU_NO_SVG
typedef struct plateau__io_depth {
    double depth;
    size_t index;
} plateau__io_depth;

/* far (large depth) first; equal depths in triangle order */
static int plateau__io_depth_cmp(const void *pa, const void *pb)
{
    const plateau__io_depth *a = (const plateau__io_depth *)pa;
    const plateau__io_depth *b = (const plateau__io_depth *)pb;
    if (a->depth > b->depth) return -1;
    if (a->depth < b->depth) return 1;
    return a->index < b->index ? -1 : (a->index > b->index ? 1 : 0);
}

/* v / |v|, first divided by its largest component so that the squares
 * neither overflow nor underflow; a zero or non-finite v is left as it is. */
static void plateau__io_normalize(double v[3])
{
    double mx = PLATEAU_FABS(v[0]), l;
    if (PLATEAU_FABS(v[1]) > mx) mx = PLATEAU_FABS(v[1]);
    if (PLATEAU_FABS(v[2]) > mx) mx = PLATEAU_FABS(v[2]);
    if (!(mx > 0.0) || !plateau__util_finite(mx)) return;
    v[0] /= mx;
    v[1] /= mx;
    v[2] /= mx;
    l = PLATEAU_SQRT(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0.0) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }
}


/* Vertex v of the picture in units of cs (a power of two): exact, so a mesh
 * scaled by a power of two gives the same file, and no projection, edge or
 * cross product overflows near DBL_MAX. */
static void plateau__io_point(const double *positions, plateau_index v, double cs, double q[3])
{
    const double *p = positions + 3 * (size_t)v;
    q[0] = p[0] / cs;
    q[1] = p[1] / cs;
    q[2] = p[2] / cs;
}

/* The projection of the SVG writers: an orthographic view along fwd, the
 * screen axes right = fwd x (+z, or +y when looking along z) and
 * up = right x fwd, coordinates in units of cs, fitted so that the longer
 * side of the picture is 1000 units with a 3 % margin. */
typedef struct plateau__io_view {
    double fwd[3], right[3], up[3], light[3];
    double cs, lo[2], scale, width, height, margin;
} plateau__io_view;

/* The view of view_dir (NULL: (-1, -1, -1)) fitted to the vertices the
 * triangles use (checked, in range); 0 for a zero or non-finite view_dir. */
static int plateau__io_view_fit(const double *positions, const plateau_index *triangles,
                                size_t num_triangles, const double *view_dir,
                                plateau__io_view *v)
{
    double *fwd = v->fwd, *up = v->up, *right = v->right, ext = 0.0;
    size_t i;
    int k;
    if (view_dir) {
        for (k = 0; k < 3; k++) fwd[k] = view_dir[k];
    } else {
        fwd[0] = fwd[1] = fwd[2] = -1.0;
    }
    for (k = 0; k < 3; k++) {
        if (!plateau__util_finite(fwd[k])) fwd[0] = fwd[1] = fwd[2] = 0.0;
    }
    plateau__io_normalize(fwd);
    if (fwd[0] == 0.0 && fwd[1] == 0.0 && fwd[2] == 0.0) return 0;
    /* screen axes: right = fwd x up_world, up = right x fwd */
    up[0] = 0.0;
    up[1] = PLATEAU_FABS(fwd[2]) > 0.99 ? 1.0 : 0.0;
    up[2] = PLATEAU_FABS(fwd[2]) > 0.99 ? 0.0 : 1.0;
    plateau__util_cross(fwd, up, right);
    plateau__io_normalize(right);
    plateau__util_cross(right, fwd, up);
    plateau__io_normalize(up);
    for (k = 0; k < 3; k++) v->light[k] = -fwd[k] + 0.6 * up[k] - 0.4 * right[k];
    plateau__io_normalize(v->light);

    /* the coordinate unit cs: the power of two at or above the largest
     * coordinate the triangles use (2^1023 at most) */
    v->cs = 1.0;
    for (i = 0; i < 3 * num_triangles; i++)
        for (k = 0; k < 3; k++)
            if (PLATEAU_FABS(positions[3 * (size_t)triangles[i] + (size_t)k]) > ext)
                ext = PLATEAU_FABS(positions[3 * (size_t)triangles[i] + (size_t)k]);
    if (ext > 0.0) v->cs = plateau__util_pow2_at_least(ext);
    /* the picture's extent, from the vertices the triangles use */
    v->lo[0] = v->lo[1] = 0.0;
    {
        double hi[2] = { 0.0, 0.0 };
        for (i = 0; i < 3 * num_triangles; i++) {
            double p[3];
            double x, y;
            plateau__io_point(positions, triangles[i], v->cs, p);
            x = p[0] * right[0] + p[1] * right[1] + p[2] * right[2];
            y = -(p[0] * up[0] + p[1] * up[1] + p[2] * up[2]);
            if (i == 0 || x < v->lo[0]) v->lo[0] = x;
            if (i == 0 || x > hi[0]) hi[0] = x;
            if (i == 0 || y < v->lo[1]) v->lo[1] = y;
            if (i == 0 || y > hi[1]) hi[1] = y;
        }
        v->width = hi[0] - v->lo[0];
        v->height = hi[1] - v->lo[1];
    }
    v->scale = v->width > v->height ? v->width : v->height;
    v->scale = v->scale > 0.0 && plateau__util_finite(1000.0 / v->scale) ? 1000.0 / v->scale : 1.0;
    v->width *= v->scale;
    v->height *= v->scale;
    v->margin = 0.03 * (v->width > v->height ? v->width : v->height) + 1.0;
    return 1;
}

/* Screen position of p (a point in units of cs). */
static void plateau__io_screen(const plateau__io_view *v, const double p[3], double *x, double *y)
{
    *x = (p[0] * v->right[0] + p[1] * v->right[1] + p[2] * v->right[2] - v->lo[0]) * v->scale;
    *y = (-(p[0] * v->up[0] + p[1] * v->up[1] + p[2] * v->up[2]) - v->lo[1]) * v->scale;
}

/* The painter's order: *order (through allocator; NULL when there is no
 * triangle) gets the triangles far to near by the depth of their centroid,
 * ties in triangle order. */
static plateau_result plateau__io_depth_order(const double *positions,
                                              const plateau_index *triangles,
                                              size_t num_triangles, const plateau__io_view *v,
                                              const plateau_allocator *allocator,
                                              plateau__io_depth **order, plateau_error *err)
{
    size_t i, bytes;
    int k;
    *order = NULL;
    if (num_triangles == 0) return PLATEAU_OK;
    bytes = plateau__bytes(num_triangles, sizeof(plateau__io_depth));
    if (bytes == 0) {
        plateau__util_error(err, PLATEAU_ERR_OVERFLOW, -1, "too many triangles", 0, 0);
        return PLATEAU_ERR_OVERFLOW;
    }
    *order = (plateau__io_depth *)plateau__alloc(allocator, bytes);
    if (!*order) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory for the SVG", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (i = 0; i < num_triangles; i++) {
        double d = 0.0;
        for (k = 0; k < 3; k++) {
            double p[3];
            plateau__io_point(positions, triangles[3 * i + (size_t)k], v->cs, p);
            d += p[0] * v->fwd[0] + p[1] * v->fwd[1] + p[2] * v->fwd[2];
        }
        (*order)[i].depth = d / 3.0;
        (*order)[i].index = i;
    }
    PLATEAU_QSORT(*order, num_triangles, sizeof **order, plateau__io_depth_cmp);
    return PLATEAU_OK;
}

/* What every drawing sets up after its mesh is checked: the allocator
 * checked, the view along view_dir fitted (*v) and the painter's order
 * of the triangles (*order, the caller frees it). */
static plateau_result plateau__io_svg_view(const double *positions, const plateau_index *triangles,
                                           size_t num_triangles, const double *view_dir,
                                           const plateau_allocator *allocator, plateau__io_view *v,
                                           plateau__io_depth **order, plateau_error *err)
{
    if (!plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "the allocator sets only one of its two functions", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (!plateau__io_view_fit(positions, triangles, num_triangles, view_dir, v)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "the view direction is zero or not finite",
                          0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    return plateau__io_depth_order(positions, triangles, num_triangles, v, allocator, order, err);
}

PLATEAU_DEF plateau_result plateau_write_svg(const char *path, const double *positions,
                                             size_t num_vertices,
                                             const plateau_index *triangles,
                                             size_t num_triangles, const double *view_dir,
                                             const plateau_allocator *allocator,
                                             plateau_error *err)
{
    plateau__io_view v;
    double width, height;
    plateau__io_depth *order = NULL;
    size_t i;
    int k, failed = 0;
    FILE *f;
    plateau__io_out out;
    plateau_result r = plateau__io_check_mesh(path, positions, num_vertices, triangles,
                                              num_triangles, err);
    if (r != PLATEAU_OK) return r;
    r = plateau__io_svg_view(positions, triangles, num_triangles, view_dir, allocator, &v, &order, err);
    if (r != PLATEAU_OK) return r;
    width = v.width;
    height = v.height;

    r = plateau__io_open(&out, path, err);
    if (r != PLATEAU_OK) {
        plateau__free(allocator, order);
        return r;
    }
    f = out.f;
    failed |= fprintf(f,
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
                      "viewBox=\"%.3f %.3f %.3f %.3f\" width=\"%.0f\" height=\"%.0f\">\n"
                      "<g stroke=\"#1e1e1e\" stroke-width=\"%.3f\" stroke-linejoin=\"round\">\n",
                      -v.margin, -v.margin, width + 2.0 * v.margin, height + 2.0 * v.margin,
                      width + 2.0 * v.margin, height + 2.0 * v.margin,
                      0.0015 * (width > height ? width : height) + 0.1) < 0;
    for (i = 0; i < num_triangles && !failed; i++) {
        const plateau_index *t = triangles + 3 * order[i].index;
        double a[3], b[3], c[3];
        double e1[3], e2[3], nrm[3], shade, xs[3], ys[3];
        int rgb[3];
        plateau__io_point(positions, t[0], v.cs, a);
        plateau__io_point(positions, t[1], v.cs, b);
        plateau__io_point(positions, t[2], v.cs, c);
        for (k = 0; k < 3; k++) {
            e1[k] = b[k] - a[k];
            e2[k] = c[k] - a[k];
        }
        /* directions only: the cross product of a tiny triangle does not
         * underflow */
        plateau__io_normalize(e1);
        plateau__io_normalize(e2);
        plateau__util_cross(e1, e2, nrm);
        plateau__io_normalize(nrm);
        shade = PLATEAU_FABS(nrm[0] * v.light[0] + nrm[1] * v.light[1] + nrm[2] * v.light[2]);
        if (!plateau__util_finite(shade)) shade = 0.0; /* never a NaN into the (int) below */
        shade = 0.25 + 0.75 * shade;
        rgb[0] = (int)(shade * 110.0 + 0.5);
        rgb[1] = (int)(shade * 170.0 + 0.5);
        rgb[2] = (int)(shade * 235.0 + 0.5);
        for (k = 0; k < 3; k++) {
            double p[3];
            plateau__io_point(positions, t[k], v.cs, p);
            plateau__io_screen(&v, p, &xs[k], &ys[k]);
        }
        failed |= fprintf(f,
                          "<polygon points=\"%.3f,%.3f %.3f,%.3f %.3f,%.3f\" "
                          "fill=\"#%02x%02x%02x\"/>\n",
                          xs[0], ys[0], xs[1], ys[1], xs[2], ys[2], rgb[0], rgb[1], rgb[2]) < 0;
    }
    if (!failed) failed |= fprintf(f, "</g>\n</svg>\n") < 0;
    plateau__free(allocator, order);
    return plateau__io_finish(&out, failed, err);
}

/* The checks of the coloured writer beyond those of plateau_write_svg;
 * *lo, *hi get the colour range. */
static plateau_result plateau__io_check_colors(size_t num_vertices, size_t num_triangles,
                                               const plateau_svg_colors *c, double *lo,
                                               double *hi, plateau_error *err)
{
    size_t i, want;
    if (!c || !c->values) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "no colors or no values to colour by", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    want = c->per_vertex ? num_vertices : num_triangles;
    if (c->num_values != want) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)c->num_values,
                          c->per_vertex ? "@ values for @ vertices" : "@ values for @ triangles",
                          (long)c->num_values, (long)want);
        return PLATEAU_ERR_ARGUMENT;
    }
    if (c->num_marked_edges > 0 && !c->marked_edges) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "marked_edges is NULL with a non-zero count",
                          0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (i = 0; i < want; i++) {
        if (!plateau__util_finite(c->values[i])) {
            plateau__util_error(err, PLATEAU_ERR_NOT_FINITE, (long)i, "value @ is NaN or infinite",
                              (long)i, 0);
            return PLATEAU_ERR_NOT_FINITE;
        }
    }
    for (i = 0; i < 2 * c->num_marked_edges; i++) {
        if (c->marked_edges[i] < 0 || (size_t)c->marked_edges[i] >= num_vertices) {
            plateau__util_error(err, PLATEAU_ERR_INDEX_RANGE, (long)(i / 2),
                              "marked edge @ has a vertex index out of range", (long)(i / 2), 0);
            return PLATEAU_ERR_INDEX_RANGE;
        }
    }
    if (!plateau__util_finite(c->range_min) || !plateau__util_finite(c->range_max) ||
        c->range_min > c->range_max) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "the colour range is not finite or its minimum exceeds its maximum", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    *lo = c->range_min;
    *hi = c->range_max;
    if (c->range_min == 0.0 && c->range_max == 0.0) {
        for (i = 0; i < want; i++) {
            if (i == 0 || c->values[i] < *lo) *lo = c->values[i];
            if (i == 0 || c->values[i] > *hi) *hi = c->values[i];
        }
    }
    return PLATEAU_OK;
}

/* The colour of value x on the range [lo, hi] as "#rrggbb" into hex (8 bytes). */
static void plateau__io_color_hex(double x, double lo, double hi, char hex[8])
{
    static const char digits[] = "0123456789abcdef";
    double rgb[3];
    int k;
    plateau_colormap(hi > lo ? (x - lo) / (hi - lo) : 0.5, rgb);
    hex[0] = '#';
    for (k = 0; k < 3; k++) {
        int c = (int)(rgb[k] * 255.0 + 0.5);
        if (c < 0) c = 0;
        if (c > 255) c = 255;
        hex[1 + 2 * k] = digits[c >> 4];
        hex[2 + 2 * k] = digits[c & 15];
    }
    hex[7] = '\0';
}

/* s into an XML text node or attribute: & < > " escaped. */
static int plateau__io_xml_text(FILE *f, const char *s)
{
    int failed = 0;
    for (; *s && !failed; s++) {
        switch (*s) {
        case '&': failed = fputs("&amp;", f) < 0; break;
        case '<': failed = fputs("&lt;", f) < 0; break;
        case '>': failed = fputs("&gt;", f) < 0; break;
        case '"': failed = fputs("&quot;", f) < 0; break;
        default: failed = fputc(*s, f) == EOF; break;
        }
    }
    return failed;
}

/* The body of the coloured writer, checks done; returns non-zero when a
 * write failed. */
static int plateau__io_write_colored(FILE *f, const double *positions,
                                     const plateau_index *triangles, size_t num_triangles,
                                     const plateau_svg_colors *c, const plateau__io_view *v,
                                     const plateau__io_depth *order, double lo, double hi)
{
    const double bar_h = 400.0, bar_w = 50.0, font = 36.0;
    double w = v->width, h = v->height, m = v->margin, side = w > h ? w : h;
    double lx = w + m, legend_w = 0.0, total_h = h;
    size_t i;
    int k, failed = 0;
    char hex[8];
    if (!c->no_legend) {
        size_t title_len = c->title ? strlen(c->title) : 0;
        legend_w = 2.0 * bar_w + 12.0 + 9.0 * 0.6 * font;
        if (0.6 * font * (double)title_len > legend_w) legend_w = 0.6 * font * (double)title_len;
        if (legend_w > 1200.0) legend_w = 1200.0;
        if (total_h < bar_h + 2.5 * font + 20.0) total_h = bar_h + 2.5 * font + 20.0;
    }
    failed |= fprintf(f,
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
                      "viewBox=\"%.1f %.1f %.1f %.1f\" width=\"%.0f\" height=\"%.0f\">\n"
                      "<g stroke=\"#555555\" stroke-width=\"%.2f\" stroke-linejoin=\"round\">\n",
                      -m, -m, w + legend_w + 2.0 * m, total_h + 2.0 * m, w + legend_w + 2.0 * m,
                      total_h + 2.0 * m, 0.001 * side + 0.1) < 0;
    for (i = 0; i < num_triangles && !failed; i++) {
        const plateau_index *t = triangles + 3 * order[i].index;
        double xs[3], ys[3];
        for (k = 0; k < 3; k++) {
            double p[3];
            plateau__io_point(positions, t[k], v->cs, p);
            plateau__io_screen(v, p, &xs[k], &ys[k]);
        }
        if (!c->per_vertex) {
            plateau__io_color_hex(c->values[order[i].index], lo, hi, hex);
            failed |= fprintf(f, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\"/>\n",
                              xs[0], ys[0], xs[1], ys[1], xs[2], ys[2], hex) < 0;
            continue;
        }
        /* the barycentric cells (paper II.B, Fig. 2): corner k, the
         * midpoints of its two edges and the centroid, stroked in their own
         * colour so that no seam shows between the three */
        {
            double gx = (xs[0] + xs[1] + xs[2]) / 3.0, gy = (ys[0] + ys[1] + ys[2]) / 3.0;
            for (k = 0; k < 3 && !failed; k++) {
                int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                plateau__io_color_hex(c->values[t[k]], lo, hi, hex);
                failed |= fprintf(f,
                                  "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f\" "
                                  "fill=\"%s\" stroke=\"%s\"/>\n",
                                  xs[k], ys[k], 0.5 * (xs[k] + xs[k1]), 0.5 * (ys[k] + ys[k1]), gx,
                                  gy, 0.5 * (xs[k] + xs[k2]), 0.5 * (ys[k] + ys[k2]), hex, hex) < 0;
            }
            if (!failed)
                failed |= fprintf(f, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"none\"/>\n",
                                  xs[0], ys[0], xs[1], ys[1], xs[2], ys[2]) < 0;
        }
    }
    if (!failed) failed |= fprintf(f, "</g>\n") < 0;
    if (c->num_marked_edges > 0 && !failed) {
        int pass;
        for (pass = 0; pass < 2 && !failed; pass++) {
            failed |= fprintf(f, "<g stroke=\"%s\" stroke-width=\"%.2f\" stroke-linecap=\"round\">\n",
                              pass ? "#ffd21f" : "#000000", (pass ? 0.006 : 0.012) * side + 0.5) < 0;
            for (i = 0; i < c->num_marked_edges && !failed; i++) {
                double p[3], x0, y0, x1, y1;
                plateau__io_point(positions, c->marked_edges[2 * i], v->cs, p);
                plateau__io_screen(v, p, &x0, &y0);
                plateau__io_point(positions, c->marked_edges[2 * i + 1], v->cs, p);
                plateau__io_screen(v, p, &x1, &y1);
                failed |= fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                                  x0, y0, x1, y1) < 0;
            }
            if (!failed) failed |= fprintf(f, "</g>\n") < 0;
        }
    }
    if (!c->no_legend && !failed) {
        double bx = lx + 0.5 * bar_w, by = 1.4 * font, step = bar_h / 64.0;
        failed |= fprintf(f,
                          "<g class=\"plateau-legend\" font-family=\"sans-serif\" "
                          "font-size=\"%.0f\" fill=\"#222222\">\n",
                          font) < 0;
        if (c->title && !failed) {
            failed |= fprintf(f, "<text class=\"plateau-legend-title\" x=\"%.1f\" y=\"%.1f\">", lx,
                              font) < 0;
            if (!failed) failed |= plateau__io_xml_text(f, c->title);
            if (!failed) failed |= fprintf(f, "</text>\n") < 0;
        }
        for (k = 0; k < 64 && !failed; k++) {
            /* step k from the top: the map's value at the step's middle;
             * each overlaps the next by a unit, so no seam shows */
            plateau__io_color_hex(hi - (hi - lo) * (k + 0.5) / 64.0, lo, hi, hex);
            failed |= fprintf(f, "<rect x=\"%.1f\" y=\"%.2f\" width=\"%.1f\" height=\"%.2f\" fill=\"%s\"/>\n",
                              bx, by + step * k, bar_w, k < 63 ? step + 1.0 : step, hex) < 0;
        }
        if (!failed)
            failed |= fprintf(f,
                              "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" "
                              "fill=\"none\" stroke=\"#222222\" stroke-width=\"2\"/>\n"
                              "<text class=\"plateau-legend-max\" data-value=\"%.17g\" x=\"%.1f\" "
                              "y=\"%.1f\">%.3g</text>\n"
                              "<text class=\"plateau-legend-min\" data-value=\"%.17g\" x=\"%.1f\" "
                              "y=\"%.1f\">%.3g</text>\n</g>\n",
                              bx, by, bar_w, bar_h, hi, bx + bar_w + 12.0, by + 0.35 * font, hi, lo,
                              bx + bar_w + 12.0, by + bar_h + 0.35 * font, lo) < 0;
    }
    if (!failed) failed |= fprintf(f, "</svg>\n") < 0;
    return failed;
}

/* Every check of the coloured writers, the view and the painter's order. */
static plateau_result plateau__io_colored_setup(const double *positions, size_t num_vertices,
                                                const plateau_index *triangles,
                                                size_t num_triangles,
                                                const plateau_svg_colors *colors,
                                                const plateau_allocator *allocator,
                                                plateau__io_view *v, plateau__io_depth **order,
                                                double *lo, double *hi, plateau_error *err)
{
    plateau_result r = plateau__io_check_mesh("", positions, num_vertices, triangles,
                                              num_triangles, err);
    *order = NULL;
    if (r != PLATEAU_OK) return r;
    r = plateau__io_check_colors(num_vertices, num_triangles, colors, lo, hi, err);
    if (r != PLATEAU_OK) return r;
    return plateau__io_svg_view(positions, triangles, num_triangles, colors->view_dir, allocator, v, order, err);
}

/* The coloured drawing to stream, or (stream NULL) to the file at path:
 * the set-up, the file opened, the drawing, its errors. */
static plateau_result plateau__io_colored(FILE *stream, const char *path, const double *positions,
                                          size_t num_vertices, const plateau_index *triangles,
                                          size_t num_triangles, const plateau_svg_colors *colors,
                                          const plateau_allocator *allocator, plateau_error *err)
{
    plateau__io_view v;
    plateau__io_depth *order = NULL;
    double lo = 0.0, hi = 0.0;
    int failed;
    plateau__io_out out;
    plateau_result r = plateau__io_colored_setup(positions, num_vertices, triangles, num_triangles, colors,
                                                 allocator, &v, &order, &lo, &hi, err);
    if (r != PLATEAU_OK) return r;
    out.f = stream;
    if (!stream) {
        r = plateau__io_open(&out, path, err);
        if (r != PLATEAU_OK) {
            plateau__free(allocator, order);
            return r;
        }
    }
    failed = plateau__io_write_colored(out.f, positions, triangles, num_triangles, colors, &v, order, lo, hi);
    plateau__free(allocator, order);
    if (!stream) return plateau__io_finish(&out, failed, err);
    if (failed || ferror(stream)) {
        plateau__util_error(err, PLATEAU_ERR_IO, -1, "could not write the SVG to the stream", 0, 0);
        return PLATEAU_ERR_IO;
    }
    return plateau__util_ok(err);
}

PLATEAU_DEF plateau_result plateau_write_svg_colored_stream(FILE *stream,
                                                            const double *positions,
                                                            size_t num_vertices,
                                                            const plateau_index *triangles,
                                                            size_t num_triangles,
                                                            const plateau_svg_colors *colors,
                                                            const plateau_allocator *allocator,
                                                            plateau_error *err)
{
    if (!stream) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "a NULL stream", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    return plateau__io_colored(stream, NULL, positions, num_vertices, triangles, num_triangles, colors, allocator,
                               err);
}

PLATEAU_DEF plateau_result plateau_write_svg_colored(const char *path, const double *positions,
                                                     size_t num_vertices,
                                                     const plateau_index *triangles,
                                                     size_t num_triangles,
                                                     const plateau_svg_colors *colors,
                                                     const plateau_allocator *allocator,
                                                     plateau_error *err)
{
    if (!path) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "a NULL path", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    return plateau__io_colored(NULL, path, positions, num_vertices, triangles, num_triangles, colors, allocator,
                               err);
}

#else /* PLATEAU_NO_SVG: the drawings refuse, naming the macro */
static plateau_result plateau__io_no_svg(plateau_error *err)
{
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "SVG drawing is compiled out by PLATEAU_NO_SVG", 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

PLATEAU_DEF plateau_result plateau_write_svg(const char *path, const double *positions,
                                             size_t num_vertices,
                                             const plateau_index *triangles,
                                             size_t num_triangles, const double *view_dir,
                                             const plateau_allocator *allocator,
                                             plateau_error *err)
{
    (void)path, (void)positions, (void)num_vertices, (void)triangles, (void)num_triangles;
    (void)view_dir, (void)allocator;
    return plateau__io_no_svg(err);
}

PLATEAU_DEF plateau_result plateau_write_svg_colored_stream(FILE *stream,
                                                            const double *positions,
                                                            size_t num_vertices,
                                                            const plateau_index *triangles,
                                                            size_t num_triangles,
                                                            const plateau_svg_colors *colors,
                                                            const plateau_allocator *allocator,
                                                            plateau_error *err)
{
    (void)stream, (void)positions, (void)num_vertices, (void)triangles, (void)num_triangles;
    (void)colors, (void)allocator;
    return plateau__io_no_svg(err);
}

PLATEAU_DEF plateau_result plateau_write_svg_colored(const char *path, const double *positions,
                                                     size_t num_vertices,
                                                     const plateau_index *triangles,
                                                     size_t num_triangles,
                                                     const plateau_svg_colors *colors,
                                                     const plateau_allocator *allocator,
                                                     plateau_error *err)
{
    (void)path, (void)positions, (void)num_vertices, (void)triangles, (void)num_triangles;
    (void)colors, (void)allocator;
    return plateau__io_no_svg(err);
}
#endif /* PLATEAU_NO_SVG */

#ifndef PLATEAU_NO_PARSERS
/* The whole of stream, at most max_bytes (0: the default cap) bytes, into
 * *buf_out (through allocator; NULL when empty) and *size_out: the
 * readers' one loop.  Errors as plateau_read_boundary_stream's, nothing
 * held. */
static plateau_result plateau__io_slurp(FILE *stream, size_t max_bytes, const plateau_allocator *allocator,
                                        char **buf_out, size_t *size_out, plateau_error *err)
{
    char *buf = NULL;
    size_t size = 0, cap = 0, i, limit;
    int failed = 0;
    *buf_out = NULL;
    *size_out = 0;
    limit = max_bytes ? max_bytes : (size_t)PLATEAU_DEFAULT_MAX_INPUT_BYTES;
    /* read at most limit + 1 bytes: one more than the cap proves the input
     * too large without holding more of it */
    for (;;) {
        size_t got, want;
        if (size == cap) {
            size_t ncap = cap ? 2 * cap : 65536;
            char *nbuf;
            if (ncap <= cap) { failed = 2; break; }
            if (limit < (size_t)-1 && ncap > limit + 1) ncap = limit + 1;
            if (ncap <= cap) { failed = 4; break; }
            nbuf = (char *)plateau__alloc(allocator, ncap);
            if (!nbuf) { failed = 3; break; }
            for (i = 0; i < size; i++) nbuf[i] = buf[i];
            plateau__free(allocator, buf);
            buf = nbuf;
            cap = ncap;
        }
        want = cap - size;
        got = fread(buf + size, 1, want, stream);
        size += got;
        if (size > limit) { failed = 4; break; }
        if (got == 0) {
            if (ferror(stream)) failed = 1;
            break;
        }
    }
    if (failed) {
        plateau__free(allocator, buf);
        if (failed == 3) {
            plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory reading the input", 0, 0);
            return PLATEAU_ERR_OUT_OF_MEMORY;
        }
        if (failed == 4) {
            if (err) {
                err->code = PLATEAU_ERR_INPUT_TOO_LARGE;
                err->index = -1;
                err->index2 = -1;
                snprintf(err->message, sizeof err->message,
                         "the input is larger than the limit of %lu bytes",
                         (unsigned long)limit);
            }
            return PLATEAU_ERR_INPUT_TOO_LARGE;
        }
        plateau__util_error(err, failed == 2 ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_IO, -1,
                          "cannot read the input", 0, 0);
        return failed == 2 ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_IO;
    }
    *buf_out = buf;
    *size_out = size;
    return PLATEAU_OK;
}

PLATEAU_DEF plateau_result plateau_read_boundary_stream(FILE *stream, size_t max_bytes,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_error *err)
{
    char *buf = NULL;
    size_t size = 0;
    plateau_result r;
    if (xyz) *xyz = NULL;
    if (m) *m = 0;
    if (!stream || !xyz || !m || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "plateau_read_boundary_stream: a NULL argument or a bad allocator", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    r = plateau__io_slurp(stream, max_bytes, allocator, &buf, &size, err);
    if (r != PLATEAU_OK) return r;
    r = plateau_parse_boundary(buf, size, allocator, xyz, m, err);
    plateau__free(allocator, buf);
    return r;
}

PLATEAU_DEF plateau_result plateau_read_boundary_file(const char *path,
                                                      const plateau_allocator *allocator,
                                                      double **xyz, size_t *m,
                                                      plateau_error *err)
{
    FILE *f;
    plateau_result r;
    if (xyz) *xyz = NULL;
    if (m) *m = 0;
    if (!path || !xyz || !m || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                          "plateau_read_boundary_file: a NULL argument or a bad allocator", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    f = fopen(path, "rb");
    if (!f) return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "cannot open", path);
    r = plateau_read_boundary_stream(f, 0, allocator, xyz, m, err);
    fclose(f);
    if (r == PLATEAU_ERR_IO || r == PLATEAU_ERR_OVERFLOW)
        return plateau__io_fail(err, r, -1, "cannot read", path);
    return r;
}

PLATEAU_DEF plateau_result plateau_read_mesh_file(const char *path, const plateau_allocator *allocator,
                                                  double **positions, size_t *num_vertices,
                                                  plateau_index **triangles, size_t *num_triangles,
                                                  plateau_error *err)
{
    FILE *f;
    char *buf = NULL;
    size_t size = 0;
    plateau_result r;
    if (positions) *positions = NULL;
    if (num_vertices) *num_vertices = 0;
    if (triangles) *triangles = NULL;
    if (num_triangles) *num_triangles = 0;
    if (!path || !positions || !num_vertices || !triangles || !num_triangles || !plateau__allocator_valid(allocator)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "plateau_read_mesh_file: a NULL argument or a bad allocator", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    f = fopen(path, "rb");
    if (!f) return plateau__io_fail(err, PLATEAU_ERR_IO, -1, "cannot open", path);
    r = plateau__io_slurp(f, 0, allocator, &buf, &size, err);
    fclose(f);
    if (r == PLATEAU_ERR_IO || r == PLATEAU_ERR_OVERFLOW) return plateau__io_fail(err, r, -1, "cannot read", path);
    if (r != PLATEAU_OK) return r;
    r = plateau_parse_mesh(buf, size, allocator, positions, num_vertices, triangles, num_triangles, NULL, err);
    plateau__free(allocator, buf);
    return r;
}
#else /* PLATEAU_NO_PARSERS */
PLATEAU_DEF plateau_result plateau_read_boundary_stream(FILE *stream, size_t max_bytes,
                                                        const plateau_allocator *allocator,
                                                        double **xyz, size_t *m,
                                                        plateau_error *err)
{
    (void)stream, (void)max_bytes;
    return plateau_parse_boundary(NULL, 0, allocator, xyz, m, err);
}

PLATEAU_DEF plateau_result plateau_read_boundary_file(const char *path,
                                                      const plateau_allocator *allocator,
                                                      double **xyz, size_t *m,
                                                      plateau_error *err)
{
    (void)path;
    return plateau_parse_boundary(NULL, 0, allocator, xyz, m, err);
}

PLATEAU_DEF plateau_result plateau_read_mesh_file(const char *path, const plateau_allocator *allocator,
                                                  double **positions, size_t *num_vertices,
                                                  plateau_index **triangles, size_t *num_triangles,
                                                  plateau_error *err)
{
    (void)path;
    return plateau_parse_mesh(NULL, 0, allocator, positions, num_vertices, triangles, num_triangles, NULL, err);
}
#endif /* PLATEAU_NO_PARSERS */
#endif /* PLATEAU_NO_STDIO */
/* ======== END SECTION: mesh input and output ============================= */

/* ======== SECTION: cutting patterns (plateau__pat_) ======================= */
/* CUTTING PATTERNS in the manual: the film cut by a family of planes
 * (exact plane sections of its triangles), each panel flattened by the
 * least-squares conformal map (Levy, Petitjean, Ray and Maillot 2002) and
 * then the local / global strain minimisation of Liu, Zhang, Xu, Gotsman
 * and Gortler 2008 (as-rigid-as-possible), turned to its least width
 * (rotating calipers on its convex hull), compensated and reported. */
#ifndef PLATEAU_NO_PATTERNS

/* The film while it is cut: a growing triangle soup. */
typedef struct plateau__pat_soup {
    const plateau_allocator *al;
    double *xyz;
    size_t nv, cap_v;
    plateau_index *tri;
    size_t nt, cap_t;
    double *g;
    size_t cap_g;
    int nv_overflow; /* more vertices than plateau_index holds */
} plateau__pat_soup;

/* One seam plane: g(x) = n.x - c; for the axis family only its half
 * h.x - hc >= 0 cuts. */
typedef struct plateau__pat_plane {
    double n[3], c, h[3], hc;
    int half;
} plateau__pat_plane;

/* The family, resolved: unit direction d, the axis point p and the frame
 * e1, e2 normal to d; the planes' start and spacing. */
typedef struct plateau__pat_family {
    int axis;
    double d[3], p[3], e1[3], e2[3];
    double s0, span; /* parallel: s = d.x from s0 over span; axis: theta from s0 over span */
    int closed;      /* axis: the film goes round the axis */
    double tol;      /* a vertex this close to a plane is on it */
    double *G;       /* parallel: the width function (PLATEAU__PAT_BINS + 1
                        values; NULL: even spacing) */
    double reach;    /* parallel: span; axis: the largest distance from the axis */
} plateau__pat_family;

typedef struct plateau__pat_key {
    plateau_index a, b;
} plateau__pat_key;

static int plateau__pat_key_cmp(const void *pa, const void *pb)
{
    const plateau__pat_key *a = (const plateau__pat_key *)pa, *b = (const plateau__pat_key *)pb;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    if (a->b != b->b) return a->b < b->b ? -1 : 1;
    return 0;
}

/* Grows *p (count *cap of size bytes each) to hold need, doubling; 0 when
 * out of memory (or on overflow), *p unchanged then. */
static int plateau__pat_grow(const plateau_allocator *al, void **p, size_t *cap, size_t need, size_t size)
{
    size_t nc = *cap ? *cap : 64;
    void *q;
    if (need <= *cap) return 1;
    while (nc < need) {
        if (nc > ((size_t)-1) / 4 / size) return 0;
        nc *= 2;
    }
    q = plateau__util_array(al, nc, size);
    if (!q) return 0;
    if (*cap) memcpy(q, *p, *cap * size);
    plateau__free(al, *p);
    *p = q;
    *cap = nc;
    return 1;
}

static void plateau__pat_soup_free(plateau__pat_soup *s)
{
    plateau__free(s->al, s->xyz);
    plateau__free(s->al, s->tri);
    plateau__free(s->al, s->g);
    s->xyz = s->g = NULL;
    s->tri = NULL;
    s->nv = s->nt = s->cap_v = s->cap_t = s->cap_g = 0;
}

static int plateau__pat_sign(double g, double tol)
{
    return g > tol ? 1 : (g < -tol ? -1 : 0);
}

static size_t plateau__pat_find(const plateau__pat_key *k, size_t n, plateau_index a, plateau_index b)
{
    size_t lo = 0, hi = n;
    plateau__pat_key q;
    q.a = a < b ? a : b;
    q.b = a < b ? b : a;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        int c = plateau__pat_key_cmp(&k[mid], &q);
        if (c == 0) return mid;
        if (c < 0) lo = mid + 1;
        else hi = mid;
    }
    return (size_t)-1;
}

/* The point where edge (a, b) meets the plane, computed from the edge's
 * smaller index so that both triangles of the edge get it bit for bit. */
static void plateau__pat_cut_point(const plateau__pat_soup *s, plateau_index a, plateau_index b, double *out)
{
    plateau_index lo = a < b ? a : b, hi = a < b ? b : a;
    const double *x = s->xyz + 3 * (size_t)lo, *y = s->xyz + 3 * (size_t)hi;
    double t = s->g[lo] / (s->g[lo] - s->g[hi]);
    int c;
    for (c = 0; c < 3; c++) out[c] = x[c] + t * (y[c] - x[c]);
}

/* Whether edge (a, b) is cut: its ends strictly on both sides, and for a
 * half-plane the crossing on its side. */
static int plateau__pat_edge_cut(const plateau__pat_soup *s, const plateau__pat_plane *pl, plateau_index a,
                                 plateau_index b, double tol)
{
    double q[3];
    if (plateau__pat_sign(s->g[a], tol) * plateau__pat_sign(s->g[b], tol) >= 0) return 0;
    if (!pl->half) return 1;
    plateau__pat_cut_point(s, a, b, q);
    return plateau__util_dot(pl->h, q) - pl->hc >= 0.0;
}

static int plateau__pat_add_tri(plateau__pat_soup *s, size_t at, plateau_index a, plateau_index b, plateau_index c)
{
    if (at == s->nt) {
        if (!plateau__pat_grow(s->al, (void **)&s->tri, &s->cap_t, s->nt + 1, 3 * sizeof(plateau_index)))
            return 0;
        s->nt++;
    }
    s->tri[3 * at] = a;
    s->tri[3 * at + 1] = b;
    s->tri[3 * at + 2] = c;
    return 1;
}

/* Replaces triangle t by its pieces on both sides of the plane, given the
 * new vertex of each of its cut edges (-1: not cut; cut[k] on the edge
 * (v_k, v_(k+1))): one cut edge, the triangle from the cut point to the
 * opposite corner; two, the lone corner's triangle and the quad beside it
 * split by its shorter diagonal.  Keeps the orientation. */
static int plateau__pat_split_tri(plateau__pat_soup *s, size_t t, const plateau_index cut[3])
{
    plateau_index v[3];
    int k, ncut = 0, i;
    for (k = 0; k < 3; k++) {
        v[k] = s->tri[3 * t + (size_t)k];
        ncut += cut[k] >= 0;
    }
    if (ncut == 1) {
        for (k = 0; cut[k] < 0; k++) continue;
        return plateau__pat_add_tri(s, t, v[k], cut[k], v[(k + 2) % 3]) &&
               plateau__pat_add_tri(s, s->nt, cut[k], v[(k + 1) % 3], v[(k + 2) % 3]);
    }
    /* the lone corner i: the edges (i, i+1) and (i+2, i) are cut */
    for (i = 0; i < 3 && !(cut[i] >= 0 && cut[(i + 2) % 3] >= 0); i++) continue;
    {
        plateau_index p = cut[i], q = cut[(i + 2) % 3], j = v[(i + 1) % 3], l = v[(i + 2) % 3];
        double d1[3], d2[3];
        plateau__util_sub(s->xyz + 3 * (size_t)p, s->xyz + 3 * (size_t)l, d1);
        plateau__util_sub(s->xyz + 3 * (size_t)j, s->xyz + 3 * (size_t)q, d2);
        if (!plateau__pat_add_tri(s, t, v[i], p, q)) return 0;
        if (plateau__util_dot(d1, d1) <= plateau__util_dot(d2, d2))
            return plateau__pat_add_tri(s, s->nt, p, j, l) && plateau__pat_add_tri(s, s->nt, p, l, q);
        return plateau__pat_add_tri(s, s->nt, p, j, q) && plateau__pat_add_tri(s, s->nt, j, l, q);
    }
}

/* Cuts the soup by one plane: every edge with ends strictly on both sides
 * (beyond tol) gets one new vertex on the plane, shared by its two
 * triangles, and each triangle with a cut edge is split.  A vertex within
 * tol of the plane counts as on it: the seam passes through it and no
 * sliver triangle is made.  0 when out of memory. */
static int plateau__pat_cut(plateau__pat_soup *s, const plateau__pat_plane *pl, double tol)
{
    plateau__pat_key *keys = NULL;
    size_t nk = 0, cap_k = 0, i, nt0 = s->nt, nu = 0, nv0 = s->nv;
    int k, ok = 1;
    if (!plateau__pat_grow(s->al, (void **)&s->g, &s->cap_g, s->nv, sizeof(double))) return 0;
    for (i = 0; i < s->nv; i++) s->g[i] = plateau__util_dot(pl->n, s->xyz + 3 * i) - pl->c;
    for (i = 0; i < nt0 && ok; i++)
        for (k = 0; k < 3 && ok; k++) {
            plateau_index a = s->tri[3 * i + (size_t)k], b = s->tri[3 * i + (size_t)(k + 1) % 3];
            if (!plateau__pat_edge_cut(s, pl, a, b, tol)) continue;
            ok = plateau__pat_grow(s->al, (void **)&keys, &cap_k, nk + 1, sizeof *keys);
            if (!ok) break;
            keys[nk].a = a < b ? a : b;
            keys[nk++].b = a < b ? b : a;
        }
    if (ok && nk > 0) {
        PLATEAU_QSORT(keys, nk, sizeof *keys, plateau__pat_key_cmp);
        for (i = 0; i < nk; i++)
            if (nu == 0 || plateau__pat_key_cmp(&keys[nu - 1], &keys[i]) != 0) keys[nu++] = keys[i];
        if ((size_t)PLATEAU_INDEX_MAX - nv0 <= nu) s->nv_overflow = 1;
        ok = !s->nv_overflow &&
             plateau__pat_grow(s->al, (void **)&s->xyz, &s->cap_v, nv0 + nu, 3 * sizeof(double));
        for (i = 0; i < nu && ok; i++) plateau__pat_cut_point(s, keys[i].a, keys[i].b, s->xyz + 3 * (nv0 + i));
        if (ok) s->nv = nv0 + nu;
        for (i = 0; i < nt0 && ok; i++) {
            plateau_index cut[3];
            int any = 0;
            for (k = 0; k < 3; k++) {
                size_t f = plateau__pat_find(keys, nu, s->tri[3 * i + (size_t)k], s->tri[3 * i + (size_t)(k + 1) % 3]);
                cut[k] = f == (size_t)-1 ? -1 : (plateau_index)(nv0 + f);
                any |= cut[k] >= 0;
            }
            if (any) ok = plateau__pat_split_tri(s, i, cut);
        }
    }
    plateau__free(s->al, keys);
    return ok;
}

/* The cotangent of each triangle's corner angles on the film (3 per
 * triangle) and each triangle's corners in a plane frame of its own (6
 * per triangle: (0, 0), (|e1|, 0), the third by its projection). */
static void plateau__pat_local(const plateau_mesh *pm, double *cot, double *loc)
{
    size_t t;
    int k;
    for (t = 0; t < pm->num_triangles; t++) {
        const double *p[3];
        double e1[3], e2[3], l1, x2;
        for (k = 0; k < 3; k++) p[k] = pm->positions + 3 * (size_t)pm->triangles[3 * t + (size_t)k];
        for (k = 0; k < 3; k++) {
            double a[3], b[3], cr[3], s;
            plateau__util_sub(p[(k + 1) % 3], p[k], a);
            plateau__util_sub(p[(k + 2) % 3], p[k], b);
            plateau__util_cross(a, b, cr);
            s = plateau__util_norm(cr);
            cot[3 * t + (size_t)k] = s > 0.0 ? plateau__util_dot(a, b) / s : 0.0;
        }
        plateau__util_sub(p[1], p[0], e1);
        plateau__util_sub(p[2], p[0], e2);
        l1 = plateau__util_norm(e1);
        x2 = l1 > 0.0 ? plateau__util_dot(e1, e2) / l1 : 0.0;
        loc[6 * t] = loc[6 * t + 1] = loc[6 * t + 3] = 0.0;
        loc[6 * t + 2] = l1;
        loc[6 * t + 4] = x2;
        x2 = plateau__util_dot(e2, e2) - x2 * x2;
        loc[6 * t + 5] = x2 > 0.0 ? PLATEAU_SQRT(x2) : 0.0;
    }
}

/* The cotangent weight of each edge, w_e = (cot alpha + cot beta) / 2 over
 * the corners opposite it: the Dirichlet energy of a piecewise linear map
 * u is 1/2 sum_e w_e |u_a - u_b|^2 (Pinkall and Polthier 1993). */
static void plateau__pat_weights(const plateau_mesh *pm, const double *cot, double *w)
{
    size_t e, t;
    int k;
    for (e = 0; e < pm->num_edges; e++) w[e] = 0.0;
    for (t = 0; t < pm->num_triangles; t++)
        for (k = 0; k < 3; k++) /* edge (v_k, v_k+1) faces corner k + 2 */
            w[pm->triangle_edges[3 * t + (size_t)k]] += 0.5 * cot[3 * t + (size_t)(k + 2) % 3];
}

/* The sparse Cholesky of the system on the free vertices of pm (block
 * unknowns per vertex) whose blocks the caller writes in the order of
 * plateau__solve_sparse_pattern; the objects through pm's allocator. */
typedef struct plateau__pat_sys {
    plateau__solve_sparse sp;
    void *pmem;
    double *vals, *rhs;
    size_t n;
    plateau_index *node; /* mesh vertex -> free index, -1 when fixed */
    plateau_lm_sparse_symbolic *sym;
    plateau_lm_sparse_factor *fac;
} plateau__pat_sys;

static void plateau__pat_sys_free(plateau__pat_sys *y, const plateau_allocator *al)
{
    plateau_lm_sparse_factor_free(y->fac);
    plateau_lm_sparse_symbolic_free(y->sym);
    plateau__free(al, y->pmem);
    plateau__free(al, y->vals);
    plateau__free(al, y->rhs);
    plateau__free(al, y->node);
    memset(y, 0, sizeof *y);
}

static plateau_result plateau__pat_sys_new(const plateau_mesh *pm, int block, int nrhs, plateau__pat_sys *y)
{
    const plateau_allocator *al = &pm->allocator;
    double *xy = NULL;
    size_t v, k = 0;
    memset(y, 0, sizeof *y);
    for (v = 0; v < pm->num_vertices; v++) y->n += !pm->fixed[v];
    y->pmem = plateau__solve_sparse_pattern(pm, y->n, &y->sp, &xy);
    y->node = (plateau_index *)plateau__util_array(al, pm->num_vertices, sizeof(plateau_index));
    if (y->pmem) y->vals = (double *)plateau__util_array(al, (size_t)y->sp.row_start[y->n], (size_t)(block * block) * sizeof(double));
    y->rhs = (double *)plateau__util_array(al, y->n, (size_t)(block * nrhs) * sizeof(double));
    if (!y->pmem || !y->node || !y->vals || !y->rhs) return PLATEAU_ERR_OUT_OF_MEMORY;
    for (v = 0; v < pm->num_vertices; v++) y->node[v] = pm->fixed[v] ? -1 : (plateau_index)k++;
    if (plateau__solve_cholesky_new(&y->sp, y->n, block, xy, al, &y->sym, &y->fac) != PLATEAU_LM_OK)
        return PLATEAU_ERR_OUT_OF_MEMORY;
    return PLATEAU_OK;
}

/* Factorises and solves; a matrix that is not positive definite (a panel
 * whose triangles are degenerate) is PLATEAU_ERR_PATTERN. */
static plateau_result plateau__pat_sys_solve(plateau__pat_sys *y, int factor, int nrhs, size_t ldb)
{
    plateau_lm_result lrc = PLATEAU_LM_OK;
    size_t i;
    if (factor) lrc = plateau_lm_sparse_factorize(y->fac, y->vals, 0.0);
    if (lrc == PLATEAU_LM_OK) lrc = plateau_lm_sparse_solve(y->fac, (size_t)nrhs, y->rhs, ldb);
    if (lrc == PLATEAU_LM_ERR_OUT_OF_MEMORY) return PLATEAU_ERR_OUT_OF_MEMORY;
    for (i = 0; i < (size_t)nrhs * ldb && lrc == PLATEAU_LM_OK; i++)
        if (!plateau__util_finite(y->rhs[i])) lrc = PLATEAU_LM_ERR_NOT_FINITE_RESIDUAL;
    return lrc == PLATEAU_LM_OK ? PLATEAU_OK : PLATEAU_ERR_PATTERN;
}

/* The other end of edge ed from v. */
static plateau_index plateau__pat_other(const plateau_mesh *pm, size_t ed, size_t v)
{
    return pm->edges[2 * ed] == (plateau_index)v ? pm->edges[2 * ed + 1] : pm->edges[2 * ed];
}

/* The least-squares conformal map (Levy et al. 2002) in the form of
 * Desbrun, Meyer and Alliez 2002: minimise E_D(u) - A(u), the Dirichlet
 * energy 1/2 sum_e w_e |u_a - u_b|^2 less the signed flat area (one half
 * of u_a x u_b over the boundary edges a -> b), which is >= 0 and zero
 * exactly for conformal maps keeping the orientation; two vertices pinned
 * (the fixed ones of pm, their uv given).  The system, blocks of 2 (u, v)
 * per vertex: L (x) I minus the Hessian of A, whose block (a, b) is
 * [[0, -1/2], [1/2, 0]] for a boundary edge run a -> b. */
static plateau_result plateau__pat_lscm(const plateau_mesh *pm, const double *w, double *uv)
{
    plateau__pat_sys y;
    size_t v, e, k = 0, q;
    plateau_result r = plateau__pat_sys_new(pm, 2, 1, &y);
    for (v = 0; v < pm->num_vertices && r == PLATEAU_OK; v++) {
        double *d, *rh;
        if (pm->fixed[v]) continue;
        q = (size_t)y.sp.row_start[k];
        d = y.vals + 4 * q++;
        rh = y.rhs + 2 * k++;
        d[0] = d[1] = d[2] = d[3] = rh[0] = rh[1] = 0.0;
        for (e = pm->vertex_edge_start[v]; e < pm->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)pm->vertex_edges[e];
            plateau_index o = plateau__pat_other(pm, ed, v);
            int fwd = pm->edges[2 * ed] == (plateau_index)v; /* edge_triangles[2ed] runs edges[2ed] -> ... */
            double b[4], s = 0.0;
            if (pm->edge_triangles[2 * ed + (size_t)!fwd] >= 0) s -= 0.5; /* a triangle runs v -> o */
            if (pm->edge_triangles[2 * ed + (size_t)fwd] >= 0) s += 0.5;  /* a triangle runs o -> v */
            b[0] = b[3] = -w[ed];
            b[1] = s;
            b[2] = -s;
            d[0] += w[ed];
            d[3] += w[ed];
            if (pm->fixed[o]) {
                rh[0] -= b[0] * uv[2 * (size_t)o] + b[1] * uv[2 * (size_t)o + 1];
                rh[1] -= b[2] * uv[2 * (size_t)o] + b[3] * uv[2 * (size_t)o + 1];
            } else {
                memcpy(y.vals + 4 * q++, b, sizeof b);
            }
        }
    }
    if (r == PLATEAU_OK) r = plateau__pat_sys_solve(&y, 1, 1, 2 * y.n);
    if (r == PLATEAU_OK)
        for (v = 0; v < pm->num_vertices; v++)
            if (y.node[v] >= 0) {
                uv[2 * v] = y.rhs[2 * (size_t)y.node[v]];
                uv[2 * v + 1] = y.rhs[2 * (size_t)y.node[v] + 1];
            }
    plateau__pat_sys_free(&y, &pm->allocator);
    return r;
}

/* The best rotation (c, s) of triangle t's frame corners onto its flat
 * corners in the cotangent-weighted least squares sense (the local step:
 * the rotation of the polar decomposition of the 2 x 2 covariance S =
 * sum_k cot_k (u_a - u_b)(x_a - x_b)^T, a, b the ends of the edge facing
 * corner k), and that edge sum of the energy 1/2 cot_k |u_a - u_b - R(x_a
 * - x_b)|^2. */
static double plateau__pat_rotation(const plateau_mesh *pm, const double *uv, const double *cot,
                                    const double *loc, size_t t, double *cs)
{
    double S[4] = {0.0, 0.0, 0.0, 0.0}, len, en = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        const double *ua = uv + 2 * (size_t)pm->triangles[3 * t + (size_t)a];
        const double *ub = uv + 2 * (size_t)pm->triangles[3 * t + (size_t)b];
        double du0 = ua[0] - ub[0], du1 = ua[1] - ub[1];
        double dx0 = loc[6 * t + 2 * (size_t)a] - loc[6 * t + 2 * (size_t)b];
        double dx1 = loc[6 * t + 2 * (size_t)a + 1] - loc[6 * t + 2 * (size_t)b + 1];
        double c = cot[3 * t + (size_t)k];
        S[0] += c * du0 * dx0;
        S[1] += c * du0 * dx1;
        S[2] += c * du1 * dx0;
        S[3] += c * du1 * dx1;
    }
    cs[0] = S[0] + S[3];
    cs[1] = S[2] - S[1];
    len = PLATEAU_SQRT(cs[0] * cs[0] + cs[1] * cs[1]);
    if (len > 0.0) {
        cs[0] /= len;
        cs[1] /= len;
    } else {
        cs[0] = 1.0;
        cs[1] = 0.0;
    }
    for (k = 0; k < 3; k++) {
        int a = (k + 1) % 3, b = (k + 2) % 3;
        const double *ua = uv + 2 * (size_t)pm->triangles[3 * t + (size_t)a];
        const double *ub = uv + 2 * (size_t)pm->triangles[3 * t + (size_t)b];
        double dx0 = loc[6 * t + 2 * (size_t)a] - loc[6 * t + 2 * (size_t)b];
        double dx1 = loc[6 * t + 2 * (size_t)a + 1] - loc[6 * t + 2 * (size_t)b + 1];
        double r0 = ua[0] - ub[0] - (cs[0] * dx0 - cs[1] * dx1);
        double r1 = ua[1] - ub[1] - (cs[1] * dx0 + cs[0] * dx1);
        en += 0.5 * cot[3 * t + (size_t)k] * (r0 * r0 + r1 * r1);
    }
    return en;
}

/* The local / global iterations (Liu et al. 2008, ARAP): each triangle's
 * best rotation (the local step), then the flat points that fit the
 * rotated triangles best, L u = b with the cotangent Laplacian L of the
 * film and b_a = sum over a's edges ab of 1/2 cot_k R_t (x_a - x_b) (the
 * global step; one vertex pinned, L factorised once).  Stops when an
 * iteration lowers the energy by less than 1e-7 of it, or the energy is at
 * rounding level (a developable panel: its conformal map is an isometry
 * already), or after max_it iterations. */
#define PLATEAU__PAT_ARAP_TOL 1e-7
static plateau_result plateau__pat_arap(const plateau_mesh *pm, const double *w, const double *cot,
                                        const double *loc, double area, int max_it, double *uv, size_t *its)
{
    plateau__pat_sys y;
    size_t v, e, t, k, q, n;
    double prev = -1.0;
    int it;
    plateau_result r = plateau__pat_sys_new(pm, 1, 2, &y);
    n = y.n;
    for (v = 0, k = 0; v < pm->num_vertices && r == PLATEAU_OK; v++) {
        size_t q0;
        if (pm->fixed[v]) continue;
        q0 = (size_t)y.sp.row_start[k++];
        q = q0 + 1;
        y.vals[q0] = 0.0;
        for (e = pm->vertex_edge_start[v]; e < pm->vertex_edge_start[v + 1]; e++) {
            size_t ed = (size_t)pm->vertex_edges[e];
            y.vals[q0] += w[ed];
            if (!pm->fixed[plateau__pat_other(pm, ed, v)]) y.vals[q++] = -w[ed];
        }
    }
    for (it = 0; it < max_it && r == PLATEAU_OK; it++) {
        double en = 0.0, cs[2];
        for (v = 0; v < 2 * n; v++) y.rhs[v] = 0.0;
        for (t = 0; t < pm->num_triangles; t++) {
            int c;
            en += plateau__pat_rotation(pm, uv, cot, loc, t, cs);
            for (c = 0; c < 3; c++) {
                int a = (c + 1) % 3, b = (c + 2) % 3;
                plateau_index va = pm->triangles[3 * t + (size_t)a], vb = pm->triangles[3 * t + (size_t)b];
                double dx0 = loc[6 * t + 2 * (size_t)a] - loc[6 * t + 2 * (size_t)b];
                double dx1 = loc[6 * t + 2 * (size_t)a + 1] - loc[6 * t + 2 * (size_t)b + 1];
                double h = 0.5 * cot[3 * t + (size_t)c];
                double r0 = h * (cs[0] * dx0 - cs[1] * dx1), r1 = h * (cs[1] * dx0 + cs[0] * dx1);
                if (y.node[va] >= 0) {
                    y.rhs[(size_t)y.node[va]] += r0;
                    y.rhs[n + (size_t)y.node[va]] += r1;
                }
                if (y.node[vb] >= 0) {
                    y.rhs[(size_t)y.node[vb]] -= r0;
                    y.rhs[n + (size_t)y.node[vb]] -= r1;
                }
            }
        }
        if (en <= 1e-24 * area || (prev >= 0.0 && prev - en <= PLATEAU__PAT_ARAP_TOL * prev)) break;
        prev = en;
        for (v = 0; v < pm->num_vertices; v++) /* the pinned vertex's terms */
            if (pm->fixed[v])
                for (e = pm->vertex_edge_start[v]; e < pm->vertex_edge_start[v + 1]; e++) {
                    size_t ed = (size_t)pm->vertex_edges[e];
                    plateau_index o = plateau__pat_other(pm, ed, v);
                    if (y.node[o] < 0) continue;
                    y.rhs[(size_t)y.node[o]] += w[ed] * uv[2 * v];
                    y.rhs[n + (size_t)y.node[o]] += w[ed] * uv[2 * v + 1];
                }
        r = plateau__pat_sys_solve(&y, it == 0, 2, n);
        for (v = 0; v < pm->num_vertices && r == PLATEAU_OK; v++)
            if (y.node[v] >= 0) {
                uv[2 * v] = y.rhs[(size_t)y.node[v]];
                uv[2 * v + 1] = y.rhs[n + (size_t)y.node[v]];
            }
        (*its)++;
    }
    plateau__pat_sys_free(&y, &pm->allocator);
    return r;
}

/* The strain of a flat triangle against its film triangle: F maps the
 * frame corners to the flat ones (F = [u1 - u0, u2 - u0][x1 - x0, x2 -
 * x0]^-1), its singular values s1 >= s2 (s2 < 0 when it turns the
 * triangle over) by the closed form of the 2 x 2 case; the strain is the
 * largest |s - 1|. */
static double plateau__pat_strain(const double *uv, const plateau_index *tri, const double *loc)
{
    double a0 = uv[2 * (size_t)tri[1]] - uv[2 * (size_t)tri[0]], a1 = uv[2 * (size_t)tri[1] + 1] - uv[2 * (size_t)tri[0] + 1];
    double b0 = uv[2 * (size_t)tri[2]] - uv[2 * (size_t)tri[0]], b1 = uv[2 * (size_t)tri[2] + 1] - uv[2 * (size_t)tri[0] + 1];
    double x1 = loc[2], x2 = loc[4], y2 = loc[5], det = x1 * y2, f[4], E, F, G, H, Q, R, s1, s2;
    if (!(det > 0.0)) return 0.0; /* a degenerate film triangle has no strain to measure */
    /* [x1 x2; 0 y2]^-1 = [1/x1, -x2/(x1 y2); 0, 1/y2] */
    f[0] = a0 / x1;
    f[1] = (b0 - a0 * x2 / x1) / y2;
    f[2] = a1 / x1;
    f[3] = (b1 - a1 * x2 / x1) / y2;
    E = 0.5 * (f[0] + f[3]);
    F = 0.5 * (f[0] - f[3]);
    G = 0.5 * (f[2] + f[1]);
    H = 0.5 * (f[2] - f[1]);
    Q = PLATEAU_SQRT(E * E + H * H);
    R = PLATEAU_SQRT(F * F + G * G);
    s1 = Q + R;
    s2 = Q - R;
    return PLATEAU_FABS(s1 - 1.0) > PLATEAU_FABS(s2 - 1.0) ? PLATEAU_FABS(s1 - 1.0) : PLATEAU_FABS(s2 - 1.0);
}

static int plateau__pat_uv_cmp(const void *pa, const void *pb)
{
    const double *a = (const double *)pa, *b = (const double *)pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    if (a[1] != b[1]) return a[1] < b[1] ? -1 : 1;
    return 0;
}

/* Turns the flat points (n of them) so that their least width lies
 * across, v: the least width of a point set is attained with a side of
 * its convex hull on a supporting line (Toussaint's rotating calipers;
 * here each side is tried against every hull point).  The hull by
 * Andrew's monotone chain.  scratch: 4 n + 4 doubles.  Then moves the
 * points to u, v >= 0 with both 0 attained.  Returns the width; *length
 * the extent along u. */
static double plateau__pat_turn(double *uv, size_t n, double *scratch, double *length)
{
    double *pts = scratch, *hull = scratch + 2 * n, bw = -1.0, c = 1.0, s = 0.0, lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0};
    size_t i, h = 0, j, lower;
    memcpy(pts, uv, 2 * n * sizeof(double));
    PLATEAU_QSORT(pts, n, 2 * sizeof(double), plateau__pat_uv_cmp);
#define PLATEAU__PAT_TURN_RIGHT(p)                                                                          \
    ((hull[2 * (h - 1)] - hull[2 * (h - 2)]) * ((p)[1] - hull[2 * (h - 2) + 1]) -                           \
         (hull[2 * (h - 1) + 1] - hull[2 * (h - 2) + 1]) * ((p)[0] - hull[2 * (h - 2)]) <= 0.0)
    for (i = 0; i < n; i++) { /* the lower chain */
        while (h >= 2 && PLATEAU__PAT_TURN_RIGHT(pts + 2 * i)) h--;
        hull[2 * h] = pts[2 * i];
        hull[2 * h + 1] = pts[2 * i + 1];
        h++;
    }
    lower = h + 1;
    for (i = n - 1; i-- > 0;) { /* the upper chain */
        while (h >= lower && PLATEAU__PAT_TURN_RIGHT(pts + 2 * i)) h--;
        hull[2 * h] = pts[2 * i];
        hull[2 * h + 1] = pts[2 * i + 1];
        h++;
    }
#undef PLATEAU__PAT_TURN_RIGHT
    if (h > 1) h--; /* the first point closed the chain */
    for (i = 0; i < h; i++) {
        const double *a = hull + 2 * i, *b = hull + 2 * ((i + 1) % h);
        double dx = b[0] - a[0], dy = b[1] - a[1], len = PLATEAU_SQRT(dx * dx + dy * dy), wd = 0.0;
        if (!(len > 0.0)) continue;
        for (j = 0; j < h; j++) {
            double d = PLATEAU_FABS((hull[2 * j] - a[0]) * dy - (hull[2 * j + 1] - a[1]) * dx) / len;
            if (d > wd) wd = d;
        }
        if (bw < 0.0 || wd < bw) {
            bw = wd;
            c = dx / len;
            s = dy / len;
        }
    }
    for (i = 0; i < n; i++) { /* rotate by -angle of the side: it runs along u */
        double u = uv[2 * i], v = uv[2 * i + 1];
        uv[2 * i] = c * u + s * v;
        uv[2 * i + 1] = -s * u + c * v;
        if (i == 0 || uv[2 * i] < lo[0]) lo[0] = uv[2 * i];
        if (i == 0 || uv[2 * i + 1] < lo[1]) lo[1] = uv[2 * i + 1];
        if (i == 0 || uv[2 * i] > hi[0]) hi[0] = uv[2 * i];
        if (i == 0 || uv[2 * i + 1] > hi[1]) hi[1] = uv[2 * i + 1];
    }
    for (i = 0; i < n; i++) {
        uv[2 * i] -= lo[0];
        uv[2 * i + 1] -= lo[1];
    }
    *length = hi[0] - lo[0];
    return hi[1] - lo[1];
}

/* Flattens panel p (its pattern vertices' xyz and its triangles in
 * pattern vertex numbers already set): the conformal map with the two
 * vertices farthest apart (by two sweeps) pinned at their distance, scaled
 * to the film's area, the local / global iterations from it, the strains,
 * the turn to least width and the compensation. */
static plateau_result plateau__pat_flatten(plateau_pattern *pat, size_t p, const plateau_pattern_options *o,
                                           plateau_error *err)
{
    plateau_pattern_panel *pp = &pat->panels[p];
    const plateau_allocator *al = &pat->allocator;
    size_t nv = pp->num_vertices, nt = pp->num_triangles, i, a = 0, b = 0;
    double *uv = pat->uv + 2 * pp->first_vertex, *cot, *loc, *w = NULL, *scratch, best, sc, af = 0.0;
    plateau_index *lt = (plateau_index *)plateau__util_array(al, nt, 3 * sizeof(plateau_index));
    unsigned char *fixed = (unsigned char *)plateau__util_array(al, nv, 1);
    plateau_mesh pm;
    plateau_result r;
    memset(&pm, 0, sizeof pm);
    cot = (double *)plateau__util_array(al, nt, 9 * sizeof(double));
    scratch = (double *)plateau__util_array(al, nv + 1, 4 * sizeof(double));
    loc = cot ? cot + 3 * nt : NULL;
    r = lt && fixed && cot && scratch ? PLATEAU_OK : PLATEAU_ERR_OUT_OF_MEMORY;
    for (i = 0; i < 3 * nt && r == PLATEAU_OK; i++)
        lt[i] = pat->triangles[3 * pp->first_triangle + i] - (plateau_index)pp->first_vertex;
    for (i = 0; i < nv && r == PLATEAU_OK; i++) fixed[i] = 0;
    if (r == PLATEAU_OK) r = plateau_mesh_create(pat->xyz + 3 * pp->first_vertex, nv, fixed, lt, nt, al, &pm, err);
    if (r == PLATEAU_OK && nv + nt != pm.num_edges + 1) {
        plateau__util_error(err, PLATEAU_ERR_PATTERN, (long)p,
                            "panel @ is no disc (the seams leave a band or a hole in it): choose other seams", (long)p, 0);
        r = PLATEAU_ERR_PATTERN;
    }
    if (r == PLATEAU_OK) w = (double *)plateau__util_array(al, pm.num_edges, sizeof(double));
    if (r == PLATEAU_OK && !w) r = PLATEAU_ERR_OUT_OF_MEMORY;
    if (r == PLATEAU_OK) {
        double d[3];
        for (best = -1.0, i = 0; i < nv; i++) {
            plateau__util_sub(pm.positions + 3 * i, pm.positions, d);
            if (plateau__util_dot(d, d) > best) { best = plateau__util_dot(d, d); a = i; }
        }
        for (best = -1.0, i = 0; i < nv; i++) {
            plateau__util_sub(pm.positions + 3 * i, pm.positions + 3 * a, d);
            if (plateau__util_dot(d, d) > best) { best = plateau__util_dot(d, d); b = i; }
        }
        plateau__pat_local(&pm, cot, loc);
        plateau__pat_weights(&pm, cot, w);
        for (i = 0; i < 2 * nv; i++) uv[i] = 0.0;
        uv[2 * b] = PLATEAU_SQRT(best);
        pm.fixed[a] = pm.fixed[b] = 1;
        r = plateau__pat_lscm(&pm, w, uv);
        if (r == PLATEAU_ERR_PATTERN)
            plateau__util_error(err, r, (long)p, "panel @ could not be flattened (degenerate triangles)", (long)p, 0);
    }
    if (r == PLATEAU_OK) {
        pp->area_3d = 0.0;
        for (i = 0; i < nt; i++) {
            const plateau_index *t = pm.triangles + 3 * i;
            pp->area_3d += 0.5 * loc[6 * i + 2] * loc[6 * i + 5];
            af += 0.5 * ((uv[2 * (size_t)t[1]] - uv[2 * (size_t)t[0]]) * (uv[2 * (size_t)t[2] + 1] - uv[2 * (size_t)t[0] + 1]) -
                         (uv[2 * (size_t)t[2]] - uv[2 * (size_t)t[0]]) * (uv[2 * (size_t)t[1] + 1] - uv[2 * (size_t)t[0] + 1]));
        }
        if (!(af > 0.0) || !(pp->area_3d > 0.0)) {
            plateau__util_error(err, PLATEAU_ERR_PATTERN, (long)p, "panel @ has no area to flatten", (long)p, 0);
            r = PLATEAU_ERR_PATTERN;
        }
    }
    if (r == PLATEAU_OK) {
        sc = PLATEAU_SQRT(pp->area_3d / af); /* the conformal map's scale: the film's area */
        for (i = 0; i < 2 * nv; i++) uv[i] *= sc;
        for (i = 0; i < nv; i++) pm.fixed[i] = i == 0;
        r = plateau__pat_arap(&pm, w, cot, loc, pp->area_3d, o->max_iterations == 0 ? 100 : o->max_iterations, uv,
                              &pat->iterations);
        if (r == PLATEAU_ERR_PATTERN)
            plateau__util_error(err, r, (long)p, "panel @ could not be flattened (degenerate triangles)", (long)p, 0);
    }
    if (r == PLATEAU_OK) {
        pp->max_strain = pp->mean_strain = 0.0;
        for (i = 0; i < nt; i++) {
            double s = plateau__pat_strain(uv, pm.triangles + 3 * i, loc + 6 * i);
            if (s > pp->max_strain) pp->max_strain = s;
            pp->mean_strain += s * 0.5 * loc[6 * i + 2] * loc[6 * i + 5];
        }
        pp->mean_strain /= pp->area_3d;
        pp->width = plateau__pat_turn(uv, nv, scratch, &pp->length) * (1.0 - o->shrink_across);
        pp->length *= 1.0 - o->shrink_along;
        for (i = 0; i < nv; i++) {
            uv[2 * i] *= 1.0 - o->shrink_along;
            uv[2 * i + 1] *= 1.0 - o->shrink_across;
        }
        pp->area_flat = 0.0;
        for (i = 0; i < nt; i++) {
            const plateau_index *t = pm.triangles + 3 * i;
            pp->area_flat += 0.5 * ((uv[2 * (size_t)t[1]] - uv[2 * (size_t)t[0]]) * (uv[2 * (size_t)t[2] + 1] - uv[2 * (size_t)t[0] + 1]) -
                                    (uv[2 * (size_t)t[2]] - uv[2 * (size_t)t[0]]) * (uv[2 * (size_t)t[1] + 1] - uv[2 * (size_t)t[0] + 1]));
        }
    }
    if (r == PLATEAU_ERR_OUT_OF_MEMORY)
        plateau__util_error(err, r, -1, "out of memory while flattening the panels", 0, 0);
    plateau_mesh_free(&pm);
    plateau__free(al, w);
    plateau__free(al, cot);
    plateau__free(al, scratch);
    plateau__free(al, fixed);
    plateau__free(al, lt);
    return r;
}

/* The seam plane j of the family with N panels. */
/* Parallel planes are spaced evenly in the film's width across them, not
 * in s = d.x: where the film runs at an angle to d a step ds of s is a
 * step ds / sin(angle) on the film (the tangential part of d has length
 * sin of the angle between the film's normal and the planes' normal), so
 * G(s) = integral of g, g the largest 1 / |d_t| over the triangles at
 * level s (at most 20), tabulated in PLATEAU__PAT_BINS bins of s; plane j
 * of N lies where G = j G_total / N.  On a half cylinder cut along its
 * axis this gives panels of equal arc width instead of wide panels where
 * the film turns parallel to the planes. */
#define PLATEAU__PAT_BINS 4096
static plateau_result plateau__pat_widths(const plateau_mesh *m0, plateau__pat_family *f)
{
    size_t t, b, B = PLATEAU__PAT_BINS;
    f->G = NULL;
    if (!(f->span > 0.0)) return PLATEAU_OK;
    f->G = (double *)plateau__util_array(&m0->allocator, B + 1, sizeof(double));
    if (!f->G) return PLATEAU_ERR_OUT_OF_MEMORY;
    for (b = 0; b <= B; b++) f->G[b] = 0.0;
    for (t = 0; t < m0->num_triangles; t++) {
        double n[3], dn, g, lo = 0.0, hi = 0.0;
        size_t b0, b1;
        int k;
        plateau_triangle_normal(m0, t, n);
        dn = plateau__util_dot(n, f->d);
        g = 1.0 - dn * dn;
        g = g > 0.0025 ? 1.0 / PLATEAU_SQRT(g) : 20.0;
        for (k = 0; k < 3; k++) {
            double sk = (plateau__util_dot(f->d, m0->positions + 3 * (size_t)m0->triangles[3 * t + (size_t)k]) - f->s0) /
                        f->span * (double)B;
            if (k == 0 || sk < lo) lo = sk;
            if (k == 0 || sk > hi) hi = sk;
        }
        b0 = lo <= 0.0 ? 0 : (size_t)lo;
        b1 = hi >= (double)B ? B - 1 : (size_t)hi;
        for (b = b0 < B ? b0 : B - 1; b <= b1; b++) f->G[b + 1] = g > f->G[b + 1] ? g : f->G[b + 1];
    }
    for (b = 0; b < B; b++) f->G[b + 1] += f->G[b]; /* cumulative, in bins */
    if (!(f->G[B] > 0.0)) {
        plateau__free(&m0->allocator, f->G);
        f->G = NULL;
    }
    return PLATEAU_OK;
}

/* s of the parallel plane j of N (G inverted linearly in its bins). */
static double plateau__pat_level(const plateau__pat_family *f, size_t N, size_t j)
{
    size_t lo = 0, hi = PLATEAU__PAT_BINS;
    double target;
    if (!f->G) return f->s0 + f->span * (double)j / (double)N;
    target = f->G[PLATEAU__PAT_BINS] * (double)j / (double)N;
    while (hi - lo > 1) { /* G[lo] <= target <= G[hi] */
        size_t mid = lo + (hi - lo) / 2;
        if (f->G[mid] <= target) lo = mid;
        else hi = mid;
    }
    return f->s0 + f->span / (double)PLATEAU__PAT_BINS *
                       ((double)lo + (f->G[hi] > f->G[lo] ? (target - f->G[lo]) / (f->G[hi] - f->G[lo]) : 0.0));
}

static void plateau__pat_plane_of(const plateau__pat_family *f, size_t N, size_t j, plateau__pat_plane *pl)
{
    int c;
    memset(pl, 0, sizeof *pl);
    if (!f->axis) {
        memcpy(pl->n, f->d, sizeof pl->n);
        pl->c = plateau__pat_level(f, N, j);
        return;
    }
    {
        double th = f->s0 + (f->closed ? 6.283185307179586 : f->span) * (double)j / (double)N;
        double co = PLATEAU_COS(th), si = PLATEAU_SIN(th);
        for (c = 0; c < 3; c++) { /* the normal points to increasing angle */
            pl->n[c] = -si * f->e1[c] + co * f->e2[c];
            pl->h[c] = co * f->e1[c] + si * f->e2[c];
        }
        pl->c = plateau__util_dot(pl->n, f->p);
        pl->hc = plateau__util_dot(pl->h, f->p);
        pl->half = 1;
    }
}

/* The angle of x about the axis, from e1 towards e2, in (-pi, pi]. */
static double plateau__pat_angle(const plateau__pat_family *f, const double *x)
{
    double d[3];
    plateau__util_sub(x, f->p, d);
    return PLATEAU_ATAN2(plateau__util_dot(d, f->e2), plateau__util_dot(d, f->e1));
}

/* Which of the N intervals between the planes holds point x. */
static size_t plateau__pat_label(const plateau__pat_family *f, size_t N, const double *x)
{
    double rel, step;
    if (!f->axis) { /* G at x's level, over G's total */
        double sb = (plateau__util_dot(f->d, x) - f->s0) / f->span * (double)PLATEAU__PAT_BINS, q;
        size_t b;
        if (!f->G || !(sb > 0.0)) return 0;
        if (sb >= (double)PLATEAU__PAT_BINS) return N - 1;
        b = (size_t)sb;
        q = (f->G[b] + (sb - (double)b) * (f->G[b + 1] - f->G[b])) / f->G[PLATEAU__PAT_BINS] * (double)N;
        return q >= (double)(N - 1) ? N - 1 : (size_t)q;
    } else {
        const double tau = 6.283185307179586;
        rel = plateau__pat_angle(f, x) - f->s0;
        while (rel < 0.0) rel += tau;
        while (rel >= tau) rel -= tau;
        step = (f->closed ? tau : f->span) / (double)N;
        if (!f->closed && rel > f->span) rel = rel > 0.5 * (f->span + tau) ? 0.0 : f->span;
    }
    if (!(step > 0.0) || !(rel > 0.0)) return 0;
    rel /= step;
    return rel >= (double)(N - 1) ? N - 1 : (size_t)rel;
}

/* The film cut by the N - 1 (N: closed about the axis) planes, into cm. */
static plateau_result plateau__pat_cut_film(const plateau_mesh *m0, const plateau__pat_family *f, size_t N,
                                            const plateau_allocator *al, plateau_mesh *cm, plateau_error *err)
{
    plateau__pat_soup s;
    size_t j;
    int ok;
    plateau_result r;
    memset(&s, 0, sizeof s);
    s.al = al;
    ok = plateau__pat_grow(al, (void **)&s.xyz, &s.cap_v, m0->num_vertices, 3 * sizeof(double)) &&
         plateau__pat_grow(al, (void **)&s.tri, &s.cap_t, m0->num_triangles, 3 * sizeof(plateau_index));
    if (ok) {
        memcpy(s.xyz, m0->positions, 3 * m0->num_vertices * sizeof(double));
        memcpy(s.tri, m0->triangles, 3 * m0->num_triangles * sizeof(plateau_index));
        s.nv = m0->num_vertices;
        s.nt = m0->num_triangles;
    }
    for (j = f->axis && f->closed ? 0 : 1; j < N && ok; j++) {
        plateau__pat_plane pl;
        plateau__pat_plane_of(f, N, j, &pl);
        ok = plateau__pat_cut(&s, &pl, f->tol);
    }
    if (!ok) {
        r = s.nv_overflow ? PLATEAU_ERR_OVERFLOW : PLATEAU_ERR_OUT_OF_MEMORY;
        plateau__pat_soup_free(&s);
        plateau__util_error(err, r, -1,
                            r == PLATEAU_ERR_OVERFLOW ? "the cut film has more vertices than plateau_index holds"
                                                      : "out of memory while cutting the film", 0, 0);
        return r;
    }
    r = plateau_mesh_create(s.xyz, s.nv, NULL, s.tri, s.nt, al, cm, err);
    plateau__pat_soup_free(&s);
    return r;
}

static int plateau__pat_pair_cmp(const void *pa, const void *pb)
{
    const size_t *a = (const size_t *)pa, *b = (const size_t *)pb;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return a[1] < b[1] ? -1 : (a[1] > b[1]);
}

/* The panels: the triangles of cm labelled by their interval (by the
 * centroid), each connected set of one label a panel, numbered by their
 * interval and then by their first triangle, so that panels side by side
 * on the film are numbered one after the other.  panel[t] out; returns the
 * count, or (size_t)-1 when out of memory. */
static size_t plateau__pat_panels(const plateau_mesh *cm, const plateau__pat_family *f, size_t N,
                                  const plateau_allocator *al, plateau_index *panel)
{
    size_t nt = cm->num_triangles, t, np = 0, top;
    size_t *lab = (size_t *)plateau__util_array(al, nt, sizeof(size_t));
    plateau_index *stack = (plateau_index *)plateau__util_array(al, nt, sizeof(plateau_index));
    if (!lab || !stack) {
        plateau__free(al, lab);
        plateau__free(al, stack);
        return (size_t)-1;
    }
    for (t = 0; t < nt; t++) {
        double c[3];
        int k, q;
        for (q = 0; q < 3; q++) c[q] = 0.0;
        for (k = 0; k < 3; k++)
            for (q = 0; q < 3; q++) c[q] += cm->positions[3 * (size_t)cm->triangles[3 * t + (size_t)k] + (size_t)q] / 3.0;
        lab[t] = plateau__pat_label(f, N, c);
        panel[t] = -1;
    }
    for (t = 0; t < nt; t++) {
        if (panel[t] >= 0) continue;
        panel[t] = (plateau_index)np;
        stack[0] = (plateau_index)t;
        top = 1;
        while (top > 0) {
            size_t u = (size_t)stack[--top];
            int k;
            for (k = 0; k < 3; k++) {
                plateau_index nb = cm->neighbors[3 * u + (size_t)k];
                if (nb >= 0 && panel[nb] < 0 && lab[nb] == lab[t]) {
                    panel[nb] = (plateau_index)np;
                    stack[top++] = nb;
                }
            }
        }
        np++;
    }
    {   /* renumbered by (interval, first triangle): pairs (label, first) sorted */
        size_t *pair = (size_t *)plateau__util_array(al, np, 3 * sizeof(size_t)), q;
        if (!pair) np = (size_t)-1;
        for (q = 0, t = 0; pair && t < nt; t++)
            if ((size_t)panel[t] == q) {
                pair[3 * q] = lab[t];
                pair[3 * q + 1] = t;
                pair[3 * q + 2] = q;
                q++;
            }
        if (pair) PLATEAU_QSORT(pair, np, 3 * sizeof(size_t), plateau__pat_pair_cmp);
        for (q = 0; pair && q < np; q++) stack[pair[3 * q + 2]] = (plateau_index)q;
        for (t = 0; pair && t < nt; t++) panel[t] = stack[panel[t]];
        plateau__free(al, pair);
    }
    plateau__free(al, lab);
    plateau__free(al, stack);
    return np;
}

/* The pattern vertex of cut-film vertex x in cut triangle t (pos: t's
 * place among the pattern's triangles). */
static plateau_index plateau__pat_corner(const plateau_mesh *cm, const plateau_pattern *pat, const size_t *pos,
                                         plateau_index t, plateau_index x)
{
    int k;
    for (k = 0; k < 2 && cm->triangles[3 * (size_t)t + (size_t)k] != x; k++) continue;
    return pat->triangles[3 * pos[t] + (size_t)k];
}

/* Numbers panel vertices (write 0: count only): each panel's film
 * vertices in the order its triangles first use them.  Returns the count. */
static size_t plateau__pat_number(const plateau_mesh *cm, plateau_pattern *pat, const size_t *ord,
                                  plateau_index *vmap, int write)
{
    size_t p, q, nv = 0;
    int k;
    for (p = 0; p < pat->num_panels; p++) {
        plateau_pattern_panel *pp = &pat->panels[p];
        size_t end = pp->first_triangle + pp->num_triangles;
        pp->first_vertex = nv;
        for (q = pp->first_triangle; q < end; q++)
            for (k = 0; k < 3; k++) {
                plateau_index x = cm->triangles[3 * ord[q] + (size_t)k];
                if (vmap[x] < 0) {
                    if (write) memcpy(pat->xyz + 3 * nv, cm->positions + 3 * (size_t)x, 3 * sizeof(double));
                    vmap[x] = (plateau_index)nv++;
                }
                if (write) pat->triangles[3 * q + (size_t)k] = vmap[x];
            }
        pp->num_vertices = nv - pp->first_vertex;
        for (q = pp->first_triangle; q < end; q++) /* cleared for the next panel */
            for (k = 0; k < 3; k++) vmap[cm->triangles[3 * ord[q] + (size_t)k]] = -1;
    }
    return nv;
}

/* The panels' vertices and triangles: the triangles of each panel in film
 * order (pos[t]: cut triangle t's place), a film vertex on a seam one
 * pattern vertex per panel. */
static plateau_result plateau__pat_assemble(const plateau_mesh *cm, const plateau_index *panel, size_t np,
                                            plateau_pattern *pat, size_t *pos)
{
    const plateau_allocator *al = &pat->allocator;
    size_t nt = cm->num_triangles, t, p, nv;
    plateau_index *vmap = (plateau_index *)plateau__util_array(al, cm->num_vertices, sizeof(plateau_index));
    size_t *start = (size_t *)plateau__util_array(al, np + 1, sizeof(size_t));
    size_t *ord = (size_t *)plateau__util_array(al, nt, sizeof(size_t));
    plateau_result r = PLATEAU_OK;
    pat->panels = (plateau_pattern_panel *)plateau__util_array(al, np, sizeof(plateau_pattern_panel));
    pat->triangles = (plateau_index *)plateau__util_array(al, nt, 3 * sizeof(plateau_index));
    if (!vmap || !start || !ord || !pat->panels || !pat->triangles) r = PLATEAU_ERR_OUT_OF_MEMORY;
    if (r == PLATEAU_OK) {
        memset(pat->panels, 0, np * sizeof *pat->panels);
        pat->num_panels = np;
        pat->num_triangles = nt;
        for (p = 0; p <= np; p++) start[p] = 0;
        for (t = 0; t < nt; t++) start[(size_t)panel[t] + 1]++;
        for (p = 0; p < np; p++) start[p + 1] += start[p];
        for (p = 0; p < np; p++) {
            pat->panels[p].first_triangle = start[p];
            pat->panels[p].num_triangles = start[p + 1] - start[p];
        }
        for (t = 0; t < nt; t++) {
            pos[t] = start[panel[t]]++;
            ord[pos[t]] = t;
        }
        for (t = 0; t < cm->num_vertices; t++) vmap[t] = -1;
        nv = plateau__pat_number(cm, pat, ord, vmap, 0);
        pat->xyz = (double *)plateau__util_array(al, nv, 3 * sizeof(double));
        pat->uv = (double *)plateau__util_array(al, nv, 2 * sizeof(double));
        if (!pat->xyz || !pat->uv || nv > (size_t)PLATEAU_INDEX_MAX) r = PLATEAU_ERR_OUT_OF_MEMORY;
        if (r == PLATEAU_OK) {
            pat->num_vertices = nv;
            plateau__pat_number(cm, pat, ord, vmap, 1);
        }
    }
    plateau__free(al, vmap);
    plateau__free(al, start);
    plateau__free(al, ord);
    return r;
}

/* A seam edge while the seams are gathered: its panels, its film ends
 * (run x -> y by the triangle on the lower panel's side), its edge. */
typedef struct plateau__pat_sedge {
    plateau_index p, q, x, y, e;
} plateau__pat_sedge;

static int plateau__pat_sedge_cmp(const void *pa, const void *pb)
{
    const plateau__pat_sedge *a = (const plateau__pat_sedge *)pa, *b = (const plateau__pat_sedge *)pb;
    if (a->p != b->p) return a->p < b->p ? -1 : 1;
    if (a->q != b->q) return a->q < b->q ? -1 : 1;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    return a->e < b->e ? -1 : (a->e > b->e);
}

/* Orders one seam's edges (sorted by x) into chains: from each edge whose
 * x ends no other edge, then round any closed loop left; out[] the order. */
static void plateau__pat_chain(const plateau__pat_sedge *s, size_t n, unsigned char *used, size_t *out)
{
    size_t i, k = 0, pass;
    for (i = 0; i < n; i++) used[i] = 0;
    for (pass = 0; pass < 2; pass++)
        for (i = 0; i < n; i++) {
            size_t cur = i, j;
            int start = 1;
            if (used[i]) continue;
            if (pass == 0)
                for (j = 0; j < n && start; j++) start = !(s[j].y == s[i].x && !used[j]);
            if (!start) continue;
            while (!used[cur]) {
                used[cur] = 1;
                out[k++] = cur;
                for (j = 0; j < n && (used[j] || s[j].x != s[cur].y); j++) continue;
                if (j == n) break;
                cur = j;
            }
        }
}

static double plateau__pat_dist2d(const double *uv, plateau_index a, plateau_index b)
{
    double du = uv[2 * (size_t)a] - uv[2 * (size_t)b], dv = uv[2 * (size_t)a + 1] - uv[2 * (size_t)b + 1];
    return PLATEAU_SQRT(du * du + dv * dv);
}

/* The seams: the edges of cm between triangles of two panels, grouped by
 * the pair, in chains, with their flat lengths on each side. */
static plateau_result plateau__pat_seams(const plateau_mesh *cm, const plateau_index *panel, const size_t *pos,
                                         plateau_pattern *pat)
{
    const plateau_allocator *al = &pat->allocator;
    size_t e, n = 0, i, g, ns = 0;
    plateau__pat_sedge *s;
    unsigned char *used;
    size_t *ord;
    for (e = 0; e < cm->num_edges; e++) {
        plateau_index t1 = cm->edge_triangles[2 * e], t2 = cm->edge_triangles[2 * e + 1];
        n += t1 >= 0 && t2 >= 0 && panel[t1] != panel[t2];
    }
    s = (plateau__pat_sedge *)plateau__util_array(al, n + 1, sizeof *s);
    used = (unsigned char *)plateau__util_array(al, n + 1, 1);
    ord = (size_t *)plateau__util_array(al, n + 1, sizeof(size_t));
    pat->seam_edges = (plateau_index *)plateau__util_array(al, n + 1, 4 * sizeof(plateau_index));
    if (!s || !used || !ord || !pat->seam_edges) {
        plateau__free(al, s);
        plateau__free(al, used);
        plateau__free(al, ord);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (e = 0, i = 0; e < cm->num_edges; e++) {
        plateau_index t1 = cm->edge_triangles[2 * e], t2 = cm->edge_triangles[2 * e + 1];
        int low;
        if (!(t1 >= 0 && t2 >= 0 && panel[t1] != panel[t2])) continue;
        low = panel[t1] < panel[t2]; /* t1 runs edges[2e] -> edges[2e+1] */
        s[i].p = low ? panel[t1] : panel[t2];
        s[i].q = low ? panel[t2] : panel[t1];
        s[i].x = cm->edges[2 * e + (size_t)!low];
        s[i].y = cm->edges[2 * e + (size_t)low];
        s[i++].e = (plateau_index)e;
    }
    PLATEAU_QSORT(s, n, sizeof *s, plateau__pat_sedge_cmp);
    for (i = 0; i < n; i++) ns += i == 0 || s[i].p != s[i - 1].p || s[i].q != s[i - 1].q;
    pat->seams = (plateau_pattern_seam *)plateau__util_array(al, ns + 1, sizeof(plateau_pattern_seam));
    if (!pat->seams) {
        plateau__free(al, s);
        plateau__free(al, used);
        plateau__free(al, ord);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    pat->num_seams = ns;
    pat->num_seam_edges = n;
    for (i = 0, g = 0; i < n; g++) {
        plateau_pattern_seam *sm = &pat->seams[g];
        size_t j = i, k;
        while (j < n && s[j].p == s[i].p && s[j].q == s[i].q) j++;
        memset(sm, 0, sizeof *sm);
        sm->panels[0] = (size_t)s[i].p;
        sm->panels[1] = (size_t)s[i].q;
        sm->first_edge = i;
        sm->num_edges = j - i;
        plateau__pat_chain(s + i, j - i, used, ord);
        for (k = 0; k < j - i; k++) {
            const plateau__pat_sedge *se = &s[i + ord[k]];
            plateau_index t1 = cm->edge_triangles[2 * (size_t)se->e], t2 = cm->edge_triangles[2 * (size_t)se->e + 1];
            plateau_index tp = panel[t1] == se->p ? t1 : t2, tq = tp == t1 ? t2 : t1;
            plateau_index *q = pat->seam_edges + 4 * (i + k);
            double d[3];
            q[0] = plateau__pat_corner(cm, pat, pos, tp, se->x);
            q[1] = plateau__pat_corner(cm, pat, pos, tp, se->y);
            q[2] = plateau__pat_corner(cm, pat, pos, tq, se->x);
            q[3] = plateau__pat_corner(cm, pat, pos, tq, se->y);
            sm->lengths[0] += plateau__pat_dist2d(pat->uv, q[0], q[1]);
            sm->lengths[1] += plateau__pat_dist2d(pat->uv, q[2], q[3]);
            plateau__util_sub(cm->positions + 3 * (size_t)se->x, cm->positions + 3 * (size_t)se->y, d);
            sm->length_3d += plateau__util_norm(d);
        }
        i = j;
    }
    plateau__free(al, s);
    plateau__free(al, used);
    plateau__free(al, ord);
    return PLATEAU_OK;
}

/* One pattern for N panels of the family: cut, panels, flattening, seams. */
static plateau_result plateau__pat_build(const plateau_mesh *m0, const plateau__pat_family *f, size_t N,
                                         const plateau_pattern_options *o, plateau_pattern *pat, plateau_error *err)
{
    const plateau_allocator *al = &pat->allocator;
    plateau_mesh cm;
    plateau_index *panel = NULL;
    size_t *pos = NULL, np = 0, p;
    double a = 0.0;
    plateau_result r = plateau__pat_cut_film(m0, f, N, al, &cm, err);
    if (r != PLATEAU_OK) return r;
    panel = (plateau_index *)plateau__util_array(al, cm.num_triangles, sizeof(plateau_index));
    pos = (size_t *)plateau__util_array(al, cm.num_triangles, sizeof(size_t));
    if (panel && pos) np = plateau__pat_panels(&cm, f, N, al, panel);
    if (!panel || !pos || np == (size_t)-1) r = PLATEAU_ERR_OUT_OF_MEMORY;
    if (r == PLATEAU_OK) r = plateau__pat_assemble(&cm, panel, np, pat, pos);
    if (r == PLATEAU_ERR_OUT_OF_MEMORY)
        plateau__util_error(err, r, -1, "out of memory while making the panels", 0, 0);
    for (p = 0; p < np && r == PLATEAU_OK; p++) r = plateau__pat_flatten(pat, p, o, err);
    if (r == PLATEAU_OK) {
        r = plateau__pat_seams(&cm, panel, pos, pat);
        if (r != PLATEAU_OK) plateau__util_error(err, r, -1, "out of memory while gathering the seams", 0, 0);
    }
    if (r == PLATEAU_OK) {
        pat->max_strain = pat->mean_strain = 0.0;
        for (p = 0; p < np; p++) {
            if (pat->panels[p].max_strain > pat->max_strain) pat->max_strain = pat->panels[p].max_strain;
            pat->mean_strain += pat->panels[p].mean_strain * pat->panels[p].area_3d;
            a += pat->panels[p].area_3d;
        }
        pat->mean_strain /= a;
        pat->spacing = (f->axis && f->closed ? 6.283185307179586 : f->span) / (double)N;
    }
    plateau__free(al, panel);
    plateau__free(al, pos);
    plateau_mesh_free(&cm);
    return r;
}

/* The family resolved from the options and the film (m0). */
static plateau_result plateau__pat_family_make(const plateau_mesh *m0, const plateau_pattern_options *o,
                                               plateau__pat_family *f, plateau_error *err)
{
    const double tau = 6.283185307179586;
    size_t v, n = 0, i, t;
    double len = plateau__util_norm(o->direction), lo = 0.0, hi = 0.0, gap = -1.0, *ang;
    memset(f, 0, sizeof *f);
    f->axis = o->seams == PLATEAU_SEAMS_AXIS;
    f->tol = 1e-2 * plateau_mean_edge_length(m0);
    if (len > 0.0) {
        for (i = 0; i < 3; i++) f->d[i] = o->direction[i] / len;
        memcpy(f->p, o->point, sizeof f->p);
    } else if (!f->axis) { /* the coordinate axis of the largest extent */
        double ext[3];
        for (i = 0; i < 3; i++) {
            lo = hi = m0->positions[i];
            for (v = 1; v < m0->num_vertices; v++) {
                double x = m0->positions[3 * v + i];
                lo = x < lo ? x : lo;
                hi = x > hi ? x : hi;
            }
            ext[i] = hi - lo;
        }
        i = ext[1] > ext[0] ? 1 : 0;
        i = ext[2] > ext[i] ? 2 : i;
        f->d[i] = 1.0;
    } else { /* the vector area through the area centroid */
        double a = 0.0;
        for (t = 0; t < m0->num_triangles; t++) {
            double nrm[3], at = plateau_triangle_normal(m0, t, nrm);
            for (i = 0; i < 3; i++) {
                int k;
                f->d[i] += at * nrm[i];
                for (k = 0; k < 3; k++)
                    f->p[i] += at / 3.0 * m0->positions[3 * (size_t)m0->triangles[3 * t + (size_t)k] + i];
            }
            a += at;
        }
        len = plateau__util_norm(f->d);
        if (!(len > 1e-12 * a)) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                                "the film has no vector area to take as the axis: give options.direction", 0, 0);
            return PLATEAU_ERR_ARGUMENT;
        }
        for (i = 0; i < 3; i++) {
            f->d[i] /= len;
            f->p[i] /= a;
        }
    }
    if (!f->axis) {
        for (v = 0; v < m0->num_vertices; v++) {
            double s = plateau__util_dot(f->d, m0->positions + 3 * v);
            if (v == 0 || s < lo) lo = s;
            if (v == 0 || s > hi) hi = s;
        }
        f->s0 = lo;
        f->span = f->reach = hi - lo;
        if (plateau__pat_widths(m0, f) == PLATEAU_OK) return PLATEAU_OK;
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory while cutting the film", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    {   /* e1 normal to d (from the coordinate axis least along d), e2 = d x e1 */
        double c[3] = {0.0, 0.0, 0.0};
        i = PLATEAU_FABS(f->d[1]) < PLATEAU_FABS(f->d[0]) ? 1 : 0;
        i = PLATEAU_FABS(f->d[2]) < PLATEAU_FABS(f->d[i]) ? 2 : i;
        c[i] = 1.0;
        plateau__util_cross(f->d, c, f->e1);
        len = plateau__util_norm(f->e1);
        for (i = 0; i < 3; i++) f->e1[i] /= len;
        plateau__util_cross(f->d, f->e1, f->e2);
    }
    ang = (double *)plateau__util_array(&m0->allocator, m0->num_vertices, sizeof(double));
    if (!ang) {
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory while cutting the film", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    for (v = 0; v < m0->num_vertices; v++) {
        double d[3], r2;
        plateau__util_sub(m0->positions + 3 * v, f->p, d);
        r2 = plateau__util_dot(d, f->e1) * plateau__util_dot(d, f->e1) + plateau__util_dot(d, f->e2) * plateau__util_dot(d, f->e2);
        if (PLATEAU_SQRT(r2) > f->reach) f->reach = PLATEAU_SQRT(r2);
        if (PLATEAU_SQRT(r2) > f->tol) ang[n++] = plateau__pat_angle(f, m0->positions + 3 * v);
    }
    if (n == 0) {
        plateau__free(&m0->allocator, ang);
        plateau__util_error(err, PLATEAU_ERR_PATTERN, -1, "the film lies on the seams' axis", 0, 0);
        return PLATEAU_ERR_PATTERN;
    }
    PLATEAU_QSORT(ang, n, sizeof(double), plateau__bnd_double_cmp);
    for (i = 0; i < n; i++) { /* the largest gap between the angles, cyclically */
        double g = i + 1 < n ? ang[i + 1] - ang[i] : ang[0] + tau - ang[i];
        if (g > gap) {
            gap = g;
            f->s0 = i + 1 < n ? ang[i + 1] : ang[0];
        }
    }
    plateau__free(&m0->allocator, ang);
    f->span = tau - gap;
    {   /* closed: an edge crosses the half-plane in the middle of the gap */
        plateau__pat_family h = *f;
        plateau__pat_plane pl;
        h.closed = 1;
        h.s0 = f->s0 - 0.5 * gap;
        plateau__pat_plane_of(&h, 1, 0, &pl);
        for (i = 0; i < m0->num_edges && !f->closed; i++) {
            const double *a = m0->positions + 3 * (size_t)m0->edges[2 * i], *b = m0->positions + 3 * (size_t)m0->edges[2 * i + 1];
            double ga = plateau__util_dot(pl.n, a) - pl.c, gb = plateau__util_dot(pl.n, b) - pl.c, q[3];
            int c;
            if (!((ga > 0.0 && gb < 0.0) || (ga < 0.0 && gb > 0.0))) continue;
            for (c = 0; c < 3; c++) q[c] = a[c] + ga / (ga - gb) * (b[c] - a[c]);
            f->closed = plateau__util_dot(pl.h, q) - pl.hc >= 0.0;
        }
    }
    return PLATEAU_OK;
}

static plateau_result plateau__pat_check(const double *positions, size_t num_vertices, const plateau_index *triangles,
                                         size_t num_triangles, const plateau_pattern_options *o, plateau_error *err)
{
    const char *why = NULL;
    int i;
    if (!o || (!positions && num_vertices > 0) || (!triangles && num_triangles > 0))
        why = "a NULL pointer for the options or the mesh's arrays";
    else if (num_triangles == 0 || num_vertices == 0)
        why = "the mesh is empty: no triangle to cut into panels";
    else if (!(o->width > 0.0) || !plateau__util_finite(o->width))
        why = "the roll width must be a finite number > 0";
    else if (!(o->shrink_along >= 0.0 && o->shrink_along < 0.5) || !(o->shrink_across >= 0.0 && o->shrink_across < 0.5))
        why = "the compensation must lie in [0, 0.5) along and across";
    else if (o->seams != PLATEAU_SEAMS_PARALLEL && o->seams != PLATEAU_SEAMS_AXIS)
        why = "unknown seam family (PLATEAU_SEAMS_PARALLEL or PLATEAU_SEAMS_AXIS)";
    for (i = 0; i < 3 && !why; i++)
        if (!plateau__util_finite(o->direction[i]) || !plateau__util_finite(o->point[i]))
            why = "the seams' direction or point is not finite";
    if (!why) return PLATEAU_OK;
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, why, 0, 0);
    return PLATEAU_ERR_ARGUMENT;
}

PLATEAU_DEF void plateau_pattern_free(plateau_pattern *pattern)
{
    plateau_allocator al;
    if (!pattern) return;
    al = pattern->allocator;
    plateau__free(&al, pattern->panels);
    plateau__free(&al, pattern->seams);
    plateau__free(&al, pattern->xyz);
    plateau__free(&al, pattern->uv);
    plateau__free(&al, pattern->triangles);
    plateau__free(&al, pattern->seam_edges);
    memset(pattern, 0, sizeof *pattern);
}

/* The panel count of the first try: the planes spaced by the width along
 * the film's extent across them (parallel) or round its largest radius
 * (axis); at most PLATEAU__PAT_MAX_PANELS. */
#define PLATEAU__PAT_MAX_PANELS 100000.0
static double plateau__pat_first_count(const plateau__pat_family *f, double width)
{
    double c = (f->axis ? (f->closed ? 6.283185307179586 : f->span) * f->reach
                        : f->G ? f->G[PLATEAU__PAT_BINS] * f->span / (double)PLATEAU__PAT_BINS : f->span) / width;
    c = c < 1.0 ? 1.0 : c;
    return c > PLATEAU__PAT_MAX_PANELS ? c : (double)(size_t)c + ((double)(size_t)c < c);
}

static double plateau__pat_widest(const plateau_pattern *p)
{
    double w = 0.0;
    size_t i;
    for (i = 0; i < p->num_panels; i++) w = p->panels[i].width > w ? p->panels[i].width : w;
    return w;
}

/* Fewer panels while they still fit: from a pattern of N panels whose
 * widest is w <= W, N' = ceil(N w / (0.98 W)) when that is fewer, kept
 * when it fits (at most 4 times).  A first try spaced by the largest
 * radius (gores round a mast, whose panels are narrower towards the
 * axis) is often wider apart than it need be. */
static plateau_result plateau__pat_fewer(const plateau_mesh *m0, const plateau__pat_family *f, double N,
                                         const plateau_pattern_options *o, plateau_pattern *pattern,
                                         plateau_error *err)
{
    int k;
    for (k = 0; k < 4; k++) {
        plateau_pattern q;
        double n2 = N * plateau__pat_widest(pattern) / (0.98 * o->width);
        plateau_result r;
        n2 = (double)(size_t)n2 + ((double)(size_t)n2 < n2);
        if (n2 < 1.0) n2 = 1.0;
        if (n2 >= N) return PLATEAU_OK;
        memset(&q, 0, sizeof q);
        q.allocator = pattern->allocator;
        r = plateau__pat_build(m0, f, (size_t)n2, o, &q, err);
        if (r == PLATEAU_ERR_PATTERN || (r == PLATEAU_OK && plateau__pat_widest(&q) > o->width)) {
            plateau_pattern_free(&q); /* the coarser cut fails or is too wide: the finer stays */
            return PLATEAU_OK;
        }
        if (r != PLATEAU_OK) {
            plateau_pattern_free(&q);
            return r;
        }
        plateau_pattern_free(pattern);
        *pattern = q;
        N = n2;
    }
    return PLATEAU_OK;
}

/* The spacing search: N panels, then (while the widest panel exceeds W)
 * N W_max / W with 2 % to spare, at least one more, until every panel
 * fits; it gives up when three tries in a row narrow the widest panel by
 * less than 2 % (a film the planes cannot cut narrower, e.g. one lying
 * across the planes' normal), or past PLATEAU__PAT_MAX_PANELS panels.
 * Then fewer panels while they fit (plateau__pat_fewer). */
PLATEAU_DEF plateau_result plateau_pattern_make(const double *positions, size_t num_vertices,
                                                const plateau_index *triangles, size_t num_triangles,
                                                const plateau_pattern_options *options,
                                                const plateau_allocator *allocator,
                                                plateau_pattern *pattern, plateau_error *err)
{
    plateau_mesh m0;
    plateau__pat_family f;
    double N, best = -1.0;
    int stall = 0, tries;
    plateau_result r;
    if (!pattern) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1, "a NULL pattern", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    memset(pattern, 0, sizeof *pattern);
#ifdef PLATEAU_LM_NO_SPARSE /* the flattenings solve sparse systems (SWITCHES) */
    plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                        "cutting patterns need the sparse solvers, compiled out by PLATEAU_LM_NO_SPARSE", 0, 0);
    return PLATEAU_ERR_ARGUMENT;
#endif
    r = plateau__pat_check(positions, num_vertices, triangles, num_triangles, options, err);
    if (r != PLATEAU_OK) return r;
    r = plateau_mesh_create(positions, num_vertices, NULL, triangles, num_triangles, allocator, &m0, err);
    if (r != PLATEAU_OK) return r;
    r = plateau__pat_family_make(&m0, options, &f, err);
    N = r == PLATEAU_OK ? plateau__pat_first_count(&f, options->width) : 0.0;
    if (options->panels > 0) N = (double)options->panels;
    for (tries = 0; r == PLATEAU_OK; tries++) {
        double maxw = 0.0;
        size_t p;
        if (N > PLATEAU__PAT_MAX_PANELS || stall >= 3) {
            plateau__util_error(err, PLATEAU_ERR_PATTERN, -1,
                                "no spacing of these seam planes fits every panel within the roll width: "
                                "the film is wider than the roll across them", 0, 0);
            r = PLATEAU_ERR_PATTERN;
            break;
        }
        pattern->allocator = m0.allocator;
        r = plateau__pat_build(&m0, &f, (size_t)N, options, pattern, err);
        if (r != PLATEAU_OK) break;
        for (p = 0; p < pattern->num_panels; p++)
            if (pattern->panels[p].width > maxw) maxw = pattern->panels[p].width;
        if (maxw <= options->width) {
            if (options->panels == 0) r = plateau__pat_fewer(&m0, &f, N, options, pattern, err);
            break;
        }
        plateau_pattern_free(pattern);
        if (options->panels > 0) {
            plateau__util_error(err, PLATEAU_ERR_PATTERN, -1,
                                "a panel is wider than the roll with the number of panels asked", 0, 0);
            r = PLATEAU_ERR_PATTERN;
            break;
        }
        stall = best >= 0.0 && maxw > 0.98 * best ? stall + 1 : 0;
        if (best < 0.0 || maxw < best) best = maxw;
        {
            double next = N * maxw / options->width * 1.02;
            next = next > PLATEAU__PAT_MAX_PANELS ? next : (double)(size_t)next + 1.0;
            N = next > N + 1.0 ? next : N + 1.0;
        }
    }
    if (r == PLATEAU_OK) {
        pattern->roll_width = options->width;
        plateau__util_ok(err);
    } else {
        plateau_pattern_free(pattern);
    }
    plateau__free(&m0.allocator, f.G);
    plateau_mesh_free(&m0);
    return r;
}

/* At most this many marks per seam (a spacing that would make more is
 * refused: the walk is linear in the marks). */
#define PLATEAU__PAT_MAX_MARKS 1e7

/* The marks of seam s (see plateau_pattern_seam_marks), stride numbers
 * each (4: the points on both sides; 8: then the seam's unit direction on
 * both sides); at most cap written, the count returned. */
static size_t plateau__pat_marks(const plateau_pattern *pat, size_t s, double spacing, double *out, size_t cap,
                                 size_t stride)
{
    const plateau_pattern_seam *sm = &pat->seams[s];
    size_t k, n = 0;
    double acc = 0.0, next = 0.0, last = -1.0;
    for (k = 0; k < sm->num_edges; k++) {
        const plateau_index *q = pat->seam_edges + 4 * (sm->first_edge + k);
        double d[3], L, t;
        int end = k + 1 == sm->num_edges || q[1] != pat->seam_edges[4 * (sm->first_edge + k + 1)];
        if (k == 0 || q[0] != pat->seam_edges[4 * (sm->first_edge + k - 1) + 1]) acc = next = 0.0, last = -1.0;
        plateau__util_sub(pat->xyz + 3 * (size_t)q[1], pat->xyz + 3 * (size_t)q[0], d);
        L = plateau__util_norm(d);
        for (;;) {
            int c, j;
            if (next <= acc + L) t = L > 0.0 ? (next - acc) / L : 0.0;
            else if (end && acc + L - last > 1e-9 * (acc + L)) t = 1.0;
            else break;
            if (n < cap)
                for (j = 0; j < 2; j++) {
                    const double *a = pat->uv + 2 * (size_t)q[2 * j], *b = pat->uv + 2 * (size_t)q[2 * j + 1];
                    double du = b[0] - a[0], dv = b[1] - a[1], l = PLATEAU_SQRT(du * du + dv * dv);
                    for (c = 0; c < 2; c++) out[stride * n + 2 * (size_t)j + (size_t)c] = a[c] + t * (b[c] - a[c]);
                    if (stride < 8) continue;
                    out[stride * n + 4 + 2 * (size_t)j] = l > 0.0 ? du / l : 0.0;
                    out[stride * n + 5 + 2 * (size_t)j] = l > 0.0 ? dv / l : 0.0;
                }
            n++;
            last = acc + t * L;
            if (t == 1.0 && next > acc + L) break;
            next = spacing > 0.0 ? next + spacing : 1e300;
        }
        acc += L;
    }
    return n;
}

PLATEAU_DEF plateau_result plateau_pattern_seam_marks(const plateau_pattern *pattern, size_t s, double spacing,
                                                      double *marks, size_t capacity, size_t *count,
                                                      plateau_error *err)
{
    if (!pattern || !count || (!marks && capacity > 0) || s >= pattern->num_seams || !(spacing > 0.0) ||
        pattern->seams[s].length_3d / spacing > PLATEAU__PAT_MAX_MARKS) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "a NULL pointer, a seam out of range, or a spacing not > 0 or below a ten-millionth "
                            "of the seam", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    *count = plateau__pat_marks(pattern, s, spacing, marks, capacity, 4);
    return plateau__util_ok(err);
}

#ifndef PLATEAU_NO_STDIO
/* Where the writers put panel p: its strip of the roll, the strips one
 * above the other with a tenth of the roll width between them. */
static double plateau__pat_strip(const plateau_pattern *pat, size_t p)
{
    return (double)p * 1.1 * pat->roll_width;
}

/* One stroke: an SVG line of class layer (y up: the picture is not
 * mirrored), or a DXF R12 LINE on that layer. */
static int plateau__pat_line(FILE *f, int dxf, const char *layer, double x1, double y1, double x2, double y2, double top)
{
    if (dxf)
        return fprintf(f, "0\nLINE\n8\n%s\n10\n%.10g\n20\n%.10g\n30\n0.0\n11\n%.10g\n21\n%.10g\n31\n0.0\n", layer, x1, y1,
                       x2, y2) < 0;
    return fprintf(f, "<line class=\"%s\" x1=\"%.10g\" y1=\"%.10g\" x2=\"%.10g\" y2=\"%.10g\"/>\n", layer, x1, top - y1,
                   x2, top - y2) < 0;
}

/* Each panel's outline: the edges of its triangles that no other of its
 * triangles shares (pattern vertices are a panel's own). */
static int plateau__pat_outline(FILE *f, int dxf, const plateau_pattern *pat, size_t p, plateau__pat_key *keys,
                                double top)
{
    const plateau_pattern_panel *pp = &pat->panels[p];
    size_t i, n = 3 * pp->num_triangles, j;
    double off = plateau__pat_strip(pat, p);
    int failed = 0;
    for (i = 0; i < n; i++) {
        plateau_index a = pat->triangles[3 * pp->first_triangle + i];
        plateau_index b = pat->triangles[3 * pp->first_triangle + (i / 3) * 3 + (i + 1) % 3];
        keys[i].a = a < b ? a : b;
        keys[i].b = a < b ? b : a;
    }
    PLATEAU_QSORT(keys, n, sizeof *keys, plateau__pat_key_cmp);
    for (i = 0; i < n; i = j) {
        const double *u, *v;
        for (j = i + 1; j < n && plateau__pat_key_cmp(&keys[i], &keys[j]) == 0; j++) continue;
        if (j - i != 1) continue;
        u = pat->uv + 2 * (size_t)keys[i].a;
        v = pat->uv + 2 * (size_t)keys[i].b;
        failed |= plateau__pat_line(f, dxf, dxf ? "OUTLINE" : "outline", u[0], u[1] + off, v[0], v[1] + off, top);
    }
    return failed;
}

/* Where panel p's number goes: the centroid of its triangle nearest its
 * area centroid (inside the panel, also for a crescent). */
static void plateau__pat_centroid(const plateau_pattern *pat, size_t t, double g[2])
{
    int k;
    g[0] = g[1] = 0.0;
    for (k = 0; k < 3; k++) {
        g[0] += pat->uv[2 * (size_t)pat->triangles[3 * t + (size_t)k]] / 3.0;
        g[1] += pat->uv[2 * (size_t)pat->triangles[3 * t + (size_t)k] + 1] / 3.0;
    }
}

static void plateau__pat_label_at(const plateau_pattern *pat, size_t p, double *x, double *y)
{
    const plateau_pattern_panel *pp = &pat->panels[p];
    size_t t, end = pp->first_triangle + pp->num_triangles;
    double c[2] = {0.0, 0.0}, a = 0.0, best = -1.0, g[2];
    for (t = pp->first_triangle; t < end; t++) {
        const double *u0 = pat->uv + 2 * (size_t)pat->triangles[3 * t];
        const double *u1 = pat->uv + 2 * (size_t)pat->triangles[3 * t + 1];
        const double *u2 = pat->uv + 2 * (size_t)pat->triangles[3 * t + 2];
        double at = PLATEAU_FABS((u1[0] - u0[0]) * (u2[1] - u0[1]) - (u2[0] - u0[0]) * (u1[1] - u0[1]));
        plateau__pat_centroid(pat, t, g);
        c[0] += at * g[0];
        c[1] += at * g[1];
        a += at;
    }
    if (a > 0.0) {
        c[0] /= a;
        c[1] /= a;
    }
    *x = c[0];
    *y = c[1];
    for (t = pp->first_triangle; t < end; t++) {
        double d;
        plateau__pat_centroid(pat, t, g);
        d = (g[0] - c[0]) * (g[0] - c[0]) + (g[1] - c[1]) * (g[1] - c[1]);
        if (best < 0.0 || d < best) {
            best = d;
            *x = g[0];
            *y = g[1];
        }
    }
}

/* The panels, their numbers and the seam marks (strokes of a fortieth of
 * the roll width into each panel, at right angles to the seam) as SVG or
 * DXF, into f. */
static int plateau__pat_write(FILE *f, int dxf, const plateau_pattern *pat, double spacing, plateau__pat_key *keys,
                              double *m)
{
    size_t p, s, k, nm;
    double len = 0.0, top, tick = pat->roll_width / 40.0;
    int failed = 0;
    for (p = 0; p < pat->num_panels; p++) len = pat->panels[p].length > len ? pat->panels[p].length : len;
    top = plateau__pat_strip(pat, pat->num_panels) - 0.1 * pat->roll_width;
    if (dxf)
        failed |= fprintf(f, "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n") < 0;
    else {   /* drawn 1000 units on its longer side */
        double w = 1.1 * len, h = top + 0.1 * pat->roll_width, px = 1000.0 / (w > h ? w : h);
        failed |= fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                             "width=\"%.6g\" height=\"%.6g\" viewBox=\"%.10g %.10g %.10g %.10g\">\n"
                             "<style>line{stroke:#000;stroke-width:%.4g} line.marks{stroke:#c00}"
                             " text{font-family:sans-serif;text-anchor:middle}</style>\n",
                          w * px, h * px, -0.05 * len, -0.05 * pat->roll_width, w, h, 1.5 / px) < 0;
    }
    for (p = 0; p < pat->num_panels && !failed; p++) {
        const plateau_pattern_panel *pp = &pat->panels[p];
        double x, y, h = 0.3 * pp->width;
        plateau__pat_label_at(pat, p, &x, &y);
        y += plateau__pat_strip(pat, p);
        if (!dxf) failed |= fprintf(f, "<g class=\"panel\" id=\"panel-%lu\">\n", (unsigned long)p) < 0;
        failed |= plateau__pat_outline(f, dxf, pat, p, keys, top);
        if (dxf)
            failed |= fprintf(f, "0\nTEXT\n8\nTEXT\n10\n%.10g\n20\n%.10g\n30\n0.0\n40\n%.10g\n1\n%lu\n", x, y - 0.5 * h,
                              h, (unsigned long)p) < 0;
        else
            failed |= fprintf(f, "<text class=\"number\" transform=\"translate(%.10g %.10g) scale(%.6g)\" "
                                 "font-size=\"100\">%lu</text>\n</g>\n",
                              x, top - y + 0.35 * h, h / 100.0, (unsigned long)p) < 0; /* a font drawn at 100 */
    }
    for (s = 0; s < pat->num_seams && !failed; s++) {
        nm = plateau__pat_marks(pat, s, spacing, m, (size_t)-1, 8);
        for (k = 0; k < nm && !failed; k++) {
            int j;
            for (j = 0; j < 2; j++) { /* side 0 runs the seam as its triangles do: inside on the left */
                double off = plateau__pat_strip(pat, pat->seams[s].panels[j]), sg = j == 0 ? 1.0 : -1.0;
                const double *q = m + 8 * k;
                double x = q[2 * j], y = q[2 * j + 1] + off;
                failed |= plateau__pat_line(f, dxf, dxf ? "MARKS" : "marks", x, y, x - sg * tick * q[5 + 2 * j],
                                            y + sg * tick * q[4 + 2 * j], top);
            }
        }
    }
    if (dxf) failed |= fprintf(f, "0\nENDSEC\n0\nEOF\n") < 0;
    else failed |= fprintf(f, "</svg>\n") < 0;
    return failed;
}

/* The writers' one path: the checks, the scratch (the outline's edge keys
 * and the marks of the seam with most), then the file through a temporary
 * (plateau__io_open) or the stream. */
static plateau_result plateau__pat_write_to(FILE *stream, const char *path, int dxf, const plateau_pattern *pat,
                                            double spacing, plateau_error *err)
{
    size_t p, s, mt = 0, mm = 0;
    plateau__pat_key *keys;
    double *marks;
    plateau__io_out out;
    int failed;
    plateau_result r;
    if ((!stream && !path) || !pat || pat->num_panels == 0 || !pat->panels || !pat->uv || !pat->triangles ||
        !(pat->roll_width > 0.0) || !plateau__util_finite(spacing)) {
        plateau__util_error(err, PLATEAU_ERR_ARGUMENT, -1,
                            "a NULL path or stream, a pattern without panels, or a mark spacing not finite", 0, 0);
        return PLATEAU_ERR_ARGUMENT;
    }
    for (p = 0; p < pat->num_panels; p++) mt = pat->panels[p].num_triangles > mt ? pat->panels[p].num_triangles : mt;
    for (s = 0; s < pat->num_seams; s++) {
        size_t n;
        if (spacing > 0.0 && pat->seams[s].length_3d / spacing > PLATEAU__PAT_MAX_MARKS) {
            plateau__util_error(err, PLATEAU_ERR_ARGUMENT, (long)s,
                                "the mark spacing would put more than ten million marks on seam @", (long)s, 0);
            return PLATEAU_ERR_ARGUMENT;
        }
        n = plateau__pat_marks(pat, s, spacing, NULL, 0, 8);
        mm = n > mm ? n : mm;
    }
    keys = (plateau__pat_key *)plateau__util_array(&pat->allocator, mt, 3 * sizeof *keys);
    marks = (double *)plateau__util_array(&pat->allocator, mm + 1, 8 * sizeof(double));
    if (!keys || !marks) {
        plateau__free(&pat->allocator, keys);
        plateau__free(&pat->allocator, marks);
        plateau__util_error(err, PLATEAU_ERR_OUT_OF_MEMORY, -1, "out of memory while writing the pattern", 0, 0);
        return PLATEAU_ERR_OUT_OF_MEMORY;
    }
    r = path ? plateau__io_open(&out, path, err) : PLATEAU_OK;
    if (r == PLATEAU_OK) {
        failed = plateau__pat_write(path ? out.f : stream, dxf, pat, spacing, keys, marks);
        if (path) {
            r = plateau__io_finish(&out, failed, err);
        } else if (failed || ferror(stream)) {
            plateau__util_error(err, PLATEAU_ERR_IO, -1, "could not write the pattern to the stream", 0, 0);
            r = PLATEAU_ERR_IO;
        } else {
            r = plateau__util_ok(err);
        }
    }
    plateau__free(&pat->allocator, keys);
    plateau__free(&pat->allocator, marks);
    return r;
}

PLATEAU_DEF plateau_result plateau_pattern_write_svg(const char *path, const plateau_pattern *pattern,
                                                     double mark_spacing, plateau_error *err)
{
#ifdef PLATEAU_NO_SVG
    (void)path, (void)pattern, (void)mark_spacing;
    return plateau__io_no_svg(err);
#else
    if (!path) return plateau__pat_write_to(NULL, NULL, 0, pattern, mark_spacing, err);
    return plateau__pat_write_to(NULL, path, 0, pattern, mark_spacing, err);
#endif
}

PLATEAU_DEF plateau_result plateau_pattern_write_svg_stream(FILE *stream, const plateau_pattern *pattern,
                                                            double mark_spacing, plateau_error *err)
{
#ifdef PLATEAU_NO_SVG
    (void)stream, (void)pattern, (void)mark_spacing;
    return plateau__io_no_svg(err);
#else
    return plateau__pat_write_to(stream, NULL, 0, pattern, mark_spacing, err);
#endif
}

PLATEAU_DEF plateau_result plateau_pattern_write_dxf(const char *path, const plateau_pattern *pattern,
                                                     double mark_spacing, plateau_error *err)
{
    if (!path) return plateau__pat_write_to(NULL, NULL, 1, pattern, mark_spacing, err);
    return plateau__pat_write_to(NULL, path, 1, pattern, mark_spacing, err);
}

PLATEAU_DEF plateau_result plateau_pattern_write_dxf_stream(FILE *stream, const plateau_pattern *pattern,
                                                            double mark_spacing, plateau_error *err)
{
    return plateau__pat_write_to(stream, NULL, 1, pattern, mark_spacing, err);
}
#endif /* PLATEAU_NO_STDIO */
#endif /* PLATEAU_NO_PATTERNS */
/* ======== END SECTION: cutting patterns =================================== */

#if defined(__clang__)
#pragma STDC FP_CONTRACT DEFAULT
#endif
#endif /* PLATEAU_IMPLEMENTATION */

/* HISTORY
 *   0.1.0  first release: the Plateau-Mesh pipeline (boundary check,
 *          best-fit-plane or circle domain, seeded candidate points,
 *          constrained Delaunay triangulation, rounds of solve and 3-D
 *          flips, scale-invariant frame), methods paper, paper-literal and
 *          area, the mesh kernel with exact derivatives of the discrete mean
 *          curvature, OBJ / PLY / OFF / SVG writers and the boundary parser.
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

