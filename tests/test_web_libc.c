/* test_web_libc.c - the C library replacements of the freestanding
 * WebAssembly build (examples/web/web_libc.h) against the host's: sin, cos
 * and atan2 within 2 ulp of libm on random and special arguments (C99 Annex
 * F values at zeros, infinities, NaN), the heap sort equal to qsort on a
 * total order, and the message formatter on every format plateau uses. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../examples/web/web_libc.h"
#include "harness.h"

/* |a - b| in units of the last place of b (b finite) */
static double ulps(double a, double b)
{
    double b_abs = fabs(b), u;
    if (a == b) return 0.0;
    u = nextafter(b_abs, INFINITY) - b_abs;
    return fabs(a - b) / u;
}

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;
static double uniform(void) /* [0, 1), xorshift64 */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * 0x1p-53;
}

static void test_sin_cos(void)
{
    double worst_s = 0.0, worst_c = 0.0;
    int i;
    for (i = 0; i < 300000; i++) {
        /* |x| up to 1, 10, 1000 in turn, and exact multiples of pi/4 nearby */
        double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 10.0 : 1000.0);
        double x = (2.0 * uniform() - 1.0) * scale, u;
        u = ulps(web_sin(x), sin(x));
        if (u > worst_s) worst_s = u;
        u = ulps(web_cos(x), cos(x));
        if (u > worst_c) worst_c = u;
    }
    printf("  sin, cos: at most %.0f and %.0f ulp from libm\n", worst_s, worst_c);
    CHECK(worst_s <= 2.0);
    CHECK(worst_c <= 2.0);
    CHECK(web_sin(0.0) == 0.0 && !signbit(web_sin(0.0)));
    CHECK(web_sin(-0.0) == 0.0 && signbit(web_sin(-0.0)));
    CHECK(web_cos(0.0) == 1.0);
    CHECK(web_sin(1e-300) == 1e-300);
    CHECK(isnan(web_sin(INFINITY)) && isnan(web_cos(-INFINITY)) && isnan(web_sin(NAN)));
    CHECK(isnan(web_sin(1e300)) && isnan(web_cos(-0x1p61)));
    CHECK(ulps(web_cos(3.141592653589793), -1.0) == 0.0);
    CHECK(ulps(web_sin(1.5707963267948966), 1.0) == 0.0);
    /* the builtins: WebAssembly's f64.sqrt and f64.abs, correctly rounded */
    CHECK_NEAR(web_sqrt(2.0), sqrt(2.0), 0.0);
    CHECK(web_fabs(-0.0) == 0.0 && !signbit(web_fabs(-0.0)));
}

static void test_atan2(void)
{
    static const double special[][2] = {
        {0.0, 0.0}, {-0.0, 0.0}, {0.0, -0.0}, {-0.0, -0.0}, {0.0, 1.0}, {-0.0, -1.0},
        {1.0, 0.0}, {-1.0, -0.0}, {1.0, INFINITY}, {1.0, -INFINITY}, {-1.0, -INFINITY},
        {INFINITY, INFINITY}, {INFINITY, -INFINITY}, {-INFINITY, -INFINITY}, {INFINITY, 1.0},
        {-INFINITY, 5.0}, {1e-300, 1e300}, {1e300, 1e-300}, {-1e-300, -1e300}, {1.0, 1.0},
        {-1.0, -1.0}, {3.0, -4.0}};
    double worst = 0.0;
    size_t k;
    int i;
    for (i = 0; i < 300000; i++) {
        double y = (2.0 * uniform() - 1.0) * pow(10.0, (double)(i % 7) - 3.0);
        double x = (2.0 * uniform() - 1.0) * pow(10.0, (double)((i / 7) % 7) - 3.0);
        double u = ulps(web_atan2(y, x), atan2(y, x));
        if (u > worst) worst = u;
    }
    printf("  atan2: at most %.0f ulp from libm\n", worst);
    CHECK(worst <= 2.0);
    for (k = 0; k < sizeof special / sizeof special[0]; k++) {
        double y = special[k][0], x = special[k][1];
        double a = web_atan2(y, x), b = atan2(y, x);
        CHECK_MSG(ulps(a, b) <= 1.0 && signbit(a) == signbit(b), "atan2 special case");
    }
    CHECK(isnan(web_atan2(NAN, 1.0)) && isnan(web_atan2(1.0, NAN)));
}

static int int_cmp(const void *pa, const void *pb)
{
    int a = *(const int *)pa, b = *(const int *)pb;
    return a < b ? -1 : (a > b ? 1 : 0);
}

static void test_sort(void)
{
    int a[2000], b[2000];
    int n, i, same = 1;
    for (n = 0; n <= 2000; n += n < 10 ? 1 : 397) {
        for (i = 0; i < n; i++) a[i] = b[i] = (int)(uniform() * 50.0); /* many ties */
        web_qsort(a, (size_t)n, sizeof(int), int_cmp);
        qsort(b, (size_t)n, sizeof(int), int_cmp);
        for (i = 0; i < n; i++) same &= a[i] == b[i];
    }
    CHECK(same);
}

static void test_format(void)
{
    char buf[200];
    int n = web_snprintf(buf, sizeof buf, "segment %ld %s %ld and %ld; %.5s|%d|%lu|%zu|%%", -12L,
                         "crosses", 3L, 40L, "abcdefgh", -7, 99ul, (size_t)5);
    CHECK(strcmp(buf, "segment -12 crosses 3 and 40; abcde|-7|99|5|%") == 0);
    CHECK_EQ_INT(n, (int)strlen(buf));
    web_snprintf(buf, sizeof buf, "(%g) (%g) (%g) (%g) (%g)", 1.5e-7, -3.0, 0.0, 1e300, 123456.7);
    CHECK(strcmp(buf, "(1.50000e-07) (-3.00000e+00) (0) (1.00000e+300) (1.23457e+05)") == 0);
    n = web_snprintf(buf, 8, "%s", "0123456789"); /* truncated, terminated */
    CHECK(strcmp(buf, "0123456") == 0);
    CHECK_EQ_INT(n, 10);
}

int main(void)
{
    RUN(test_sin_cos);
    RUN(test_atan2);
    RUN(test_sort);
    RUN(test_format);
    return harness_report("test_web_libc");
}
