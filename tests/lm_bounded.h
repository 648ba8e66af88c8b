/* lm_bounded.h - bounded least-squares test problems for tests/test_lm_fit.c
 * and bench/bench_lm.c: Hock and Schittkowski 1 and 21, Hatfield B and C
 * (CUTE) and the combustion of propane (Meintjes and Morgan), as residuals
 * with analytic Jacobians, their boxes, starts and published solutions
 * (definitions from Hock and Schittkowski, "Test examples for nonlinear
 * programming codes", 1981, and the CUTE collection; written here). */
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
typedef struct bounded_case {
    int id; size_t n; const double *lo, *up, *x0, *xs; double fstar;
} bounded_case;
static const bounded_case bounded_cases[] = {
    {1, 2, bnd_lo1, NULL, bnd_s1, bnd_x1, 0.0},  {21, 2, bnd_lo21, bnd_up21, bnd_s21, bnd_x21, 0.04},
    {2, 4, bnd_lo2, bnd_up2, bnd_s2, bnd_x2, 5.57281e-3}, {3, 4, bnd_lo2, bnd_up3, bnd_s3, bnd_x3, 0.0},
    {5, 5, bnd_lo5, bnd_up5, bnd_s5, bnd_x5, 0.0},
};
#define BOUNDED_COUNT (sizeof bounded_cases / sizeof bounded_cases[0])

#endif /* PLATEAU_TEST_LM_BOUNDED_H */
