/* lm_bounded.h - bounded and linearly constrained least-squares test
 * problems for tests/test_lm_fit.c and bench/bench_lm.c: Hock and
 * Schittkowski 1 and 21, Hatfield B and C (CUTE) and the combustion of
 * propane (Meintjes and Morgan) in a box; and, with linear constraints,
 * Schittkowski 235, Boggs and Tolle 7 and Hock and Schittkowski 52 in the
 * modified forms levmar's demo (lmdemo.c) states: HS235 and BT7 with two
 * or three equalities and bounds, HS52 #1 with three equalities and a box,
 * HS52 #2 with three inequalities.  As residuals with analytic Jacobians,
 * their constraints, starts and published solutions (definitions from Hock
 * and Schittkowski, "Test examples for nonlinear programming codes", 1981,
 * Schittkowski, "More test examples for nonlinear programming codes", 1987,
 * Boggs and Tolle, "A strategy for global convergence in a sequential
 * quadratic programming algorithm", 1989, and the CUTE collection;
 * written here).  The published minimum f* of the constrained four is the
 * sum of squares at their published minimiser. */
#ifndef PLATEAU_TEST_LM_BOUNDED_H
#define PLATEAU_TEST_LM_BOUNDED_H

#include <math.h>
#include <stddef.h>


/* combustion of propane (Meintjes and Morgan 1990, the reduced 5-variable
 * system): its constants */
#define CMB_R 10.0
#define CMB_R5 0.193
#define CMB_R6 (0.002597 / 6.324555320336759)
#define CMB_R7 (0.003448 / 6.324555320336759)
#define CMB_R8 (0.00001799 / 40.0)
#define CMB_R9 (0.0002155 / 6.324555320336759)
#define CMB_R10 (0.00003846 / 40.0)

static void box_eval(int id, const double *x, double *f, double *J)
{
    size_t i;
    switch (id) {
    case 1: /* HS01: 100 (x2 - x1^2)^2 + (1 - x1)^2, x2 >= -1.5 */
        f[0] = 10.0 * (x[1] - x[0] * x[0]);
        f[1] = 1.0 - x[0];
        if (J) { J[0] = -20.0 * x[0]; J[1] = 10.0; J[2] = -1.0; J[3] = 0.0; }
        break;
    case 21: /* HS21 without its linear inequality: 0.01 x1^2 + x2^2, 2 <= x1 <= 50, |x2| <= 50 */
        f[0] = 0.1 * x[0];
        f[1] = x[1];
        if (J) { J[0] = 0.1; J[1] = 0.0; J[2] = 0.0; J[3] = 1.0; }
        break;
    case 2: /* Hatfield B: x1 - 1, x_{i-1} - sqrt(x_i); x >= 0, x2 <= 0.8 */
    case 3: /* Hatfield C: x1 - 1, x_{i-1} - sqrt(x_i), x4 - 1; 0 <= x <= 10 */
        f[0] = x[0] - 1.0;
        for (i = 1; i < 4; i++) f[i] = x[i - 1] - sqrt(x[i]);
        if (id == 3) f[3] = x[3] - 1.0;
        if (J) {
            for (i = 0; i < 16; i++) J[i] = 0.0;
            J[0] = 1.0;
            for (i = 1; i < 4; i++) { J[i * 4 + i - 1] = 1.0; J[i * 4 + i] = -0.5 / sqrt(x[i]); }
            if (id == 3) { J[3 * 4 + 2] = 0.0; J[3 * 4 + 3] = 1.0; }
        }
        break;
    case 235: /* modified HS235: 0.01 (x1 - 1)^2 + (x2 - x1^2)^2 */
        f[0] = 0.1 * (x[0] - 1.0);
        f[1] = x[1] - x[0] * x[0];
        if (J) { J[0] = 0.1; J[1] = 0.0; J[2] = 0.0; J[3] = -2.0 * x[0]; J[4] = 1.0; J[5] = 0.0; }
        break;
    case 7: { /* modified BT7: five copies of r = 100 (x2 - x1^2)^2 + (x1 - 1)^2 */
        double q = x[1] - x[0] * x[0], r = 100.0 * q * q + (x[0] - 1.0) * (x[0] - 1.0);
        for (i = 0; i < 5; i++) {
            f[i] = r;
            if (J) {
                J[5 * i] = -400.0 * q * x[0] + 2.0 * (x[0] - 1.0);
                J[5 * i + 1] = 200.0 * q;
                J[5 * i + 2] = J[5 * i + 3] = J[5 * i + 4] = 0.0;
            }
        }
    } break;
    case 52: /* modified HS52 #1: 4 x1 - x2, x2 + x3 - 2, x4 - 1, x5 - 1 */
    case 53: /* modified HS52 #2: the same and x1 - 0.5 */
        f[0] = 4.0 * x[0] - x[1];
        f[1] = x[1] + x[2] - 2.0;
        f[2] = x[3] - 1.0;
        f[3] = x[4] - 1.0;
        if (id == 53) f[4] = x[0] - 0.5;
        if (J) {
            for (i = 0; i < (id == 53 ? 25u : 20u); i++) J[i] = 0.0;
            J[0] = 4.0; J[1] = -1.0; J[6] = 1.0; J[7] = 1.0; J[13] = 1.0; J[19] = 1.0;
            if (id == 53) J[20] = 1.0;
        }
        break;
    default: { /* 5: combustion of propane, x >= 1e-4 */
        double x1 = x[0], x2 = x[1], x3 = x[2], x4 = x[3], x5 = x[4];
        f[0] = x1 * x2 + x1 - 3.0 * x5;
        f[1] = 2.0 * x1 * x2 + x1 + 2.0 * CMB_R10 * x2 * x2 + x2 * x3 * x3 + CMB_R7 * x2 * x3 +
               CMB_R9 * x2 * x4 + CMB_R8 * x2 - CMB_R * x5;
        f[2] = 2.0 * x2 * x3 * x3 + CMB_R7 * x2 * x3 + 2.0 * CMB_R5 * x3 * x3 + CMB_R6 * x3 - 8.0 * x5;
        f[3] = CMB_R9 * x2 * x4 + 2.0 * x4 * x4 - 4.0 * CMB_R * x5;
        f[4] = x1 * x2 + x1 + CMB_R10 * x2 * x2 + x2 * x3 * x3 + CMB_R7 * x2 * x3 + CMB_R9 * x2 * x4 +
               CMB_R8 * x2 + CMB_R5 * x3 * x3 + CMB_R6 * x3 + x4 * x4 - 1.0;
        if (J) {
            double r0[5] = {x2 + 1.0, x1, 0.0, 0.0, -3.0};
            double r1[5] = {2.0 * x2 + 1.0, 2.0 * x1 + 4.0 * CMB_R10 * x2 + x3 * x3 + CMB_R7 * x3 + CMB_R9 * x4 + CMB_R8,
                            2.0 * x2 * x3 + CMB_R7 * x2, CMB_R9 * x2, -CMB_R};
            double r2[5] = {0.0, 2.0 * x3 * x3 + CMB_R7 * x3,
                            4.0 * x2 * x3 + CMB_R7 * x2 + 4.0 * CMB_R5 * x3 + CMB_R6, 0.0, -8.0};
            double r3[5] = {0.0, CMB_R9 * x4, 0.0, CMB_R9 * x2 + 4.0 * x4, -4.0 * CMB_R};
            double r4[5] = {x2 + 1.0, x1 + 2.0 * CMB_R10 * x2 + x3 * x3 + CMB_R7 * x3 + CMB_R9 * x4 + CMB_R8,
                            2.0 * x2 * x3 + CMB_R7 * x2 + 2.0 * CMB_R5 * x3 + CMB_R6, CMB_R9 * x2 + 2.0 * x4, 0.0};
            for (i = 0; i < 5; i++) {
                J[i] = r0[i]; J[5 + i] = r1[i]; J[10 + i] = r2[i]; J[15 + i] = r3[i]; J[20 + i] = r4[i];
            }
        }
    } break;
    }
}

static const double bnd_lo1[2] = {-HUGE_VAL, -1.5}, bnd_lo21[2] = {2.0, -50.0}, bnd_up21[2] = {50.0, 50.0};
static const double bnd_lo2[4] = {0, 0, 0, 0}, bnd_up2[4] = {HUGE_VAL, 0.8, HUGE_VAL, HUGE_VAL};
static const double bnd_up3[4] = {10, 10, 10, 10};
static const double bnd_lo5[5] = {1e-4, 1e-4, 1e-4, 1e-4, 1e-4}, bnd_up5[5] = {100, 100, 100, 100, 100};
static const double bnd_s1[2] = {-2.0, 1.0}, bnd_s21[2] = {10.0, -1.0}, bnd_s2[4] = {0.1, 0.1, 0.1, 0.1};
static const double bnd_s3[4] = {0.9, 0.9, 0.9, 0.9}, bnd_s5[5] = {10, 10, 0.05, 50.5, 0.05};
static const double bnd_x1[2] = {1, 1}, bnd_x21[2] = {2, 0}, bnd_x2[4] = {0.947214, 0.8, 0.64, 0.4096};
static const double bnd_x3[4] = {1, 1, 1, 1}, bnd_x5[5] = {0.0031141, 34.598, 0.065042, 0.85938, 0.036951};
/* the constrained four: modified HS235, x1 + x3 = -1, x2 - 4 x3 = 0,
 * 0.1 <= x2 <= 2.9, x3 >= 0.7; modified BT7, x1 + x2 - x3 = 1,
 * x1 + x2 - x4 = 0, x1 + x5 = 0.5, x1 <= 0.7, x5 >= -0.3; modified HS52 #1,
 * x1 + 3 x2 = 0, x3 + x4 - 2 x5 = 0, x2 - x5 = 0, -0.09 <= x1,
 * 0 <= x2 <= 0.3, x3 <= 0.25, -0.2 <= x4 <= 0.3, 0 <= x5 <= 0.3; modified
 * HS52 #2, x1 + 3 x2 >= -1, x3 + x4 - 2 x5 >= -2, x5 - x2 >= -7 */
static const double bnd_a235[6] = {1, 0, 1, 0, 1, -4}, bnd_b235[2] = {-1, 0};
static const double bnd_lo235[3] = {-HUGE_VAL, 0.1, 0.7}, bnd_up235[3] = {HUGE_VAL, 2.9, HUGE_VAL};
static const double bnd_s235[3] = {-2, 3, 1}, bnd_x235[3] = {-1.725, 2.9, 0.725};
static const double bnd_a7[15] = {1, 1, -1, 0, 0, 1, 1, 0, -1, 0, 1, 0, 0, 0, 1}, bnd_b7[3] = {1, 0, 0.5};
static const double bnd_lo7[5] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -0.3};
static const double bnd_up7[5] = {0.7, HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL};
static const double bnd_s7[5] = {-2, 1, 1, 1, 1}, bnd_x7[5] = {0.7, 0.49, 0.19, 1.19, -0.2};
static const double bnd_a52[15] = {1, 3, 0, 0, 0, 0, 0, 1, 1, -2, 0, 1, 0, 0, -1}, bnd_b52[3] = {0, 0, 0};
static const double bnd_lo52[5] = {-0.09, 0.0, -HUGE_VAL, -0.2, 0.0};
static const double bnd_up52[5] = {HUGE_VAL, 0.3, 0.25, 0.3, 0.3};
static const double bnd_s52[5] = {2, 2, 2, 2, 2}, bnd_x52[5] = {-0.09, 0.03, 0.25, -0.19, 0.03};
static const double bnd_c53[15] = {1, 3, 0, 0, 0, 0, 0, 1, 1, -2, 0, -1, 0, 0, 1}, bnd_d53[3] = {-1, -2, -7};
static const double bnd_x53[5] = {0.5, 2, 0, 1, 1};
typedef struct bounded_case {
    int id;
    const char *name;
    size_t m, n;
    const double *lo, *up, *x0, *xs;
    double fstar;          /* published minimum of sum f_i^2 */
    size_t ne;             /* equalities A x = b (a, b), 0 for none */
    const double *a, *b;
    size_t ni;             /* inequalities C x >= d (c, d), 0 for none */
    const double *c, *d;
} bounded_case;
static const bounded_case bounded_cases[] = {
    {1, "HS1", 2, 2, bnd_lo1, NULL, bnd_s1, bnd_x1, 0.0, 0, NULL, NULL, 0, NULL, NULL},
    {21, "HS21", 2, 2, bnd_lo21, bnd_up21, bnd_s21, bnd_x21, 0.04, 0, NULL, NULL, 0, NULL, NULL},
    {2, "hatfldb", 4, 4, bnd_lo2, bnd_up2, bnd_s2, bnd_x2, 5.57281e-3, 0, NULL, NULL, 0, NULL, NULL},
    {3, "hatfldc", 4, 4, bnd_lo2, bnd_up3, bnd_s3, bnd_x3, 0.0, 0, NULL, NULL, 0, NULL, NULL},
    {5, "combustion", 5, 5, bnd_lo5, bnd_up5, bnd_s5, bnd_x5, 0.0, 0, NULL, NULL, 0, NULL, NULL},
    {235, "HS235 mod", 2, 3, bnd_lo235, bnd_up235, bnd_s235, bnd_x235, 0.079975390625,
     2, bnd_a235, bnd_b235, 0, NULL, NULL},
    {7, "BT7 mod", 5, 5, bnd_lo7, bnd_up7, bnd_s7, bnd_x7, 0.0405, 3, bnd_a7, bnd_b7, 0, NULL, NULL},
    {52, "HS52 mod 1", 4, 5, bnd_lo52, bnd_up52, bnd_s52, bnd_x52, 5.4675, 3, bnd_a52, bnd_b52, 0,
     NULL, NULL},
    {53, "HS52 mod 2", 5, 5, NULL, NULL, bnd_s52, bnd_x53, 0.0, 0, NULL, NULL, 3, bnd_c53, bnd_d53},
};
#define BOUNDED_COUNT (sizeof bounded_cases / sizeof bounded_cases[0])

#endif /* PLATEAU_TEST_LM_BOUNDED_H */
