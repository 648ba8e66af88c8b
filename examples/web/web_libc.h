/* web_libc.h - the few C library functions plateau needs, written for the
 * freestanding WebAssembly build (examples/web/plateau_wasm.c), where there
 * is no C library at all.  Plain C99 on IEEE-754 binary64 rounded to
 * nearest, so tests can compare it with the host's libm.  Not part of the
 * library.
 *
 *   web_sqrt, web_fabs  the compiler's builtins (WebAssembly has f64.sqrt,
 *                       correctly rounded, and f64.abs)
 *   web_sin, web_cos    reduction to r in [-pi/4, pi/4] by x - k pi/2 with
 *                       pi/2 in three pieces (Cody and Waite: the first two
 *                       have 33 significant bits, so k times them is exact
 *                       for |k| < 2^20), then the Taylor series of sin r to
 *                       r^19 and of cos r to r^18 (the first omitted term is
 *                       below 2^-60 of the result), Horner's rule; cos keeps
 *                       the rounding error of 1 - r^2/2.  About 1 ulp for
 *                       |x| < 2^20 pi/2; beyond that the reduction loses
 *                       accuracy, and above 2^60 the result is NaN (plateau
 *                       calls them on angles in [-2 pi, 2 pi])
 *   web_atan2           |y/x| or |x/y| in [0, 1], then atan t = atan c +
 *                       atan((t - c) / (1 + t c)) with c = i/8 the eighth
 *                       below t (atan c stored as a double pair), the second
 *                       argument in [0, 1/8), its Taylor series to u^21;
 *                       the octant by pi/2 - a and pi - a with pi in two
 *                       parts; IEEE special cases (zeros, infinities, NaN)
 *                       as C99 Annex F.
 *   Measured against glibc 2.36's libm (tests/test_web_libc.c, 3e5 random
 *   arguments each: |x| up to 1000; |y|, |x| from 1e-3 to 1e3): sin within
 *   2 ulp, cos within 1, atan2 within 2.
 *   web_qsort           heap sort in place (no allocation): plateau's
 *                       comparisons are total orders, so the order equals
 *                       the host qsort's
 *   web_snprintf        %s, %.Ns, %d, %ld, %lu, %zu, %g (6 significant
 *                       digits, always d.ddddde+XX: messages only), %%
 * The constants are the doubles nearest to 1/k!, atan(i/8) (and the
 * remainder), pi/2, pi, computed from 80-digit decimal arithmetic. */
#ifndef WEB_LIBC_H
#define WEB_LIBC_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

static double web_fabs(double x)
{
    return __builtin_fabs(x);
}

static double web_sqrt(double x)
{
    return __builtin_sqrt(x);
}

static int web__signbit(double x)
{
    union {
        double d;
        uint64_t u;
    } v;
    v.d = x;
    return (int)(v.u >> 63);
}

/* sin and cos of NaN, an infinity or |x| > 2^60: NaN (beyond 2^60 this
 * reduction means nothing; plateau never gets there) */
static double web__out_of_range(double x)
{
    union {
        double d;
        uint64_t u;
    } v;
    if (x != x) return x;
    v.u = 0x7ff8000000000000ull; /* a quiet NaN */
    return v.d;
}

/* Taylor series of sin r and cos r, |r| <= pi/4 (coefficients 1/k!). */
static double web__sin_kernel(double r)
{
    double w = r * r, p;
    p = -0x1.2f49b46814157p-57;       /* -1/19! */
    p = 0x1.952c77030ad4ap-49 + w * p; /* 1/17! */
    p = -0x1.ae7f3e733b81fp-41 + w * p; /* 1/15! */
    p = 0x1.6124613a86d09p-33 + w * p;  /* 1/13! */
    p = -0x1.ae64567f544e4p-26 + w * p; /* 1/11! */
    p = 0x1.71de3a556c734p-19 + w * p;  /* 1/9! */
    p = -0x1.a01a01a01a01ap-13 + w * p; /* 1/7! */
    p = 0x1.1111111111111p-7 + w * p;   /* 1/5! */
    p = -0x1.5555555555555p-3 + w * p;  /* 1/3! */
    return r + r * w * p;
}

static double web__cos_kernel(double r)
{
    double w = r * r, q, hz, v;
    q = -0x1.6827863b97d97p-53;        /* -1/18! */
    q = 0x1.ae7f3e733b81fp-45 + w * q;  /* 1/16! */
    q = -0x1.93974a8c07c9dp-37 + w * q; /* 1/14! */
    q = 0x1.1eed8eff8d898p-29 + w * q;  /* 1/12! */
    q = -0x1.27e4fb7789f5cp-22 + w * q; /* 1/10! */
    q = 0x1.a01a01a01a01ap-16 + w * q;  /* 1/8! */
    q = -0x1.6c16c16c16c17p-10 + w * q; /* 1/6! */
    q = 0x1.5555555555555p-5 + w * q;   /* 1/4! */
    /* 1 - w/2 + w^2 q, adding back the rounding error of v = 1 - w/2 */
    hz = 0.5 * w;
    v = 1.0 - hz;
    return v + (((1.0 - v) - hz) + w * (w * q));
}

/* x = k pi/2 + r, |r| <= pi/4 (about); returns k mod 4. */
static int web__reduce(double x, double *r)
{
    const double p1 = 0x1.921fb54400000p+0; /* pi/2: 33 bits */
    const double p2 = 0x1.0b4611a600000p-34; /* the next 33 bits */
    const double p3 = 0x1.3198a2e037073p-69; /* the rest, rounded */
    double kd = x * 0x1.45f306dc9c883p-1;   /* x 2/pi */
    int64_t k;
    if (web_fabs(x) <= 0x1.921fb54442d18p-1) { /* |x| <= pi/4 */
        *r = x;
        return 0;
    }
    k = (int64_t)(kd >= 0.0 ? kd + 0.5 : kd - 0.5);
    kd = (double)k;
    *r = ((x - kd * p1) - kd * p2) - kd * p3;
    return (int)(k & 3);
}

static double web_sin(double x)
{
    double r;
    int q;
    if (web_fabs(x) < 0x1p-27) return x; /* x^3/6 is below half an ulp; keeps -0 */
    if (!(web_fabs(x) <= 0x1p60)) return web__out_of_range(x);
    q = web__reduce(x, &r);
    switch (q) {
    case 0: return web__sin_kernel(r);
    case 1: return web__cos_kernel(r);
    case 2: return -web__sin_kernel(r);
    default: return -web__cos_kernel(r);
    }
}

static double web_cos(double x)
{
    double r;
    int q;
    if (!(web_fabs(x) <= 0x1p60)) return web__out_of_range(x);
    q = web__reduce(x, &r);
    switch (q) {
    case 0: return web__cos_kernel(r);
    case 1: return -web__sin_kernel(r);
    case 2: return -web__cos_kernel(r);
    default: return web__sin_kernel(r);
    }
}

/* atan t for 0 <= t <= 1. */
static double web__atan01(double t)
{
    static const double hi[9] = {
        0.0,
        0x1.fd5ba9aac2f6ep-4, 0x1.f5b75f92c80ddp-3, 0x1.6f61941e4def1p-2,
        0x1.dac670561bb4fp-2, 0x1.1e00babdefeb4p-1, 0x1.4978fa3269ee1p-1,
        0x1.700a7c5784634p-1, 0x1.921fb54442d18p-1};
    static const double lo[9] = {
        0.0,
        -0x1.cd37686760c17p-59, 0x1.8ab6e3cf7afbdp-57, -0x1.c63aae6f6e918p-56,
        0x1.a2b7f222f65e2p-56, -0x1.928df287a668fp-58, 0x1.2419a87f2a458p-56,
        -0x1.8c34d25aadef6p-56, 0x1.1a62633145c07p-55};
    int i = (int)(t * 8.0);
    double c = (double)i * 0.125;
    /* t - c is exact (Sterbenz: c <= t <= 2c for i >= 1); 0 <= u < 1/8, so
     * atan c and the series add without cancellation */
    double u = (t - c) / (1.0 + t * c);
    double w = u * u, p;
    p = 1.0 / 21.0;
    p = -1.0 / 19.0 + w * p;
    p = 1.0 / 17.0 + w * p;
    p = -1.0 / 15.0 + w * p;
    p = 1.0 / 13.0 + w * p;
    p = -1.0 / 11.0 + w * p;
    p = 1.0 / 9.0 + w * p;
    p = -1.0 / 7.0 + w * p;
    p = 1.0 / 5.0 + w * p;
    p = -1.0 / 3.0 + w * p;
    return hi[i] + (lo[i] + (u + u * w * p));
}

static double web_atan2(double y, double x)
{
    const double pio2_hi = 0x1.921fb54442d18p+0, pio2_lo = 0x1.1a62633145c07p-54;
    const double pi_hi = 0x1.921fb54442d18p+1, pi_lo = 0x1.1a62633145c07p-53;
    const double big = 1.7976931348623157e308;
    double ax = web_fabs(x), ay = web_fabs(y), a;
    if (x != x || y != y) return x + y;
    if (ay > big && ax > big) {
        a = 0.5 * pio2_hi; /* both infinite: pi/4 (or 3 pi/4 below) */
    } else if (ax > big) {
        a = 0.0;
    } else if (ay > big) {
        a = pio2_hi;
    } else if (ay > ax) { /* pi/2 -+ atan(|x| / |y|) */
        double b = web__atan01(ax / ay);
        a = web__signbit(x) ? pio2_hi + (b + pio2_lo) : pio2_hi - (b - pio2_lo);
        return web__signbit(y) ? -a : a;
    } else if (ax == 0.0) {
        a = 0.0; /* both zero */
    } else {
        a = web__atan01(ay / ax);
    }
    if (web__signbit(x)) a = pi_hi - (a - pi_lo); /* pi - a */
    return web__signbit(y) ? -a : a;
}

/* ---- sorting ---------------------------------------------------------- */
static void web__swap(unsigned char *a, unsigned char *b, size_t size)
{
    while (size--) {
        unsigned char t = *a;
        *a++ = *b;
        *b++ = t;
    }
}

static void web__sift(unsigned char *base, size_t root, size_t count, size_t size,
                      int (*compare)(const void *, const void *))
{
    for (;;) { /* each pass moves root one level down: at most log2(count) */
        size_t child = 2 * root + 1;
        if (child >= count) return;
        if (child + 1 < count && compare(base + child * size, base + (child + 1) * size) < 0)
            child++;
        if (compare(base + root * size, base + child * size) >= 0) return;
        web__swap(base + root * size, base + child * size, size);
        root = child;
    }
}

static void web_qsort(void *items, size_t count, size_t size,
                      int (*compare)(const void *, const void *))
{
    unsigned char *base = (unsigned char *)items;
    size_t i;
    if (count < 2 || size == 0) return;
    for (i = count / 2; i-- > 0;) web__sift(base, i, count, size, compare);
    for (i = count - 1; i > 0; i--) {
        web__swap(base, base + i * size, size);
        web__sift(base, 0, i, size, compare);
    }
}

/* ---- formatting ------------------------------------------------------- */
typedef struct web__out {
    char *buf;
    size_t size, len;
} web__out;

static void web__put(web__out *o, char c)
{
    if (o->len + 1 < o->size) o->buf[o->len] = c;
    o->len++;
}

static void web__put_unsigned(web__out *o, unsigned long long v)
{
    char d[24];
    int n = 0;
    do {
        d[n++] = (char)('0' + (int)(v % 10));
        v /= 10;
    } while (v);
    while (n) web__put(o, d[--n]);
}

static void web__put_signed(web__out *o, long long v)
{
    if (v < 0) {
        web__put(o, '-');
        web__put_unsigned(o, 0ull - (unsigned long long)v);
    } else {
        web__put_unsigned(o, (unsigned long long)v);
    }
}

/* d.ddddde+XX, 6 significant digits (messages only: not correctly rounded) */
static void web__put_double(web__out *o, double x)
{
    int e = 0, i;
    long long m;
    if (x != x) {
        web__put(o, 'n'), web__put(o, 'a'), web__put(o, 'n');
        return;
    }
    if (web__signbit(x)) web__put(o, '-'), x = -x;
    if (x > 1.7976931348623157e308) {
        web__put(o, 'i'), web__put(o, 'n'), web__put(o, 'f');
        return;
    }
    if (x == 0.0) {
        web__put(o, '0');
        return;
    }
    while (x >= 10.0 && e < 400) x /= 10.0, e++;
    while (x < 1.0 && e > -400) x *= 10.0, e--;
    m = (long long)(x * 100000.0 + 0.5);
    if (m >= 1000000) m /= 10, e++;
    web__put(o, (char)('0' + (int)(m / 100000)));
    web__put(o, '.');
    for (i = 10000; i >= 1; i /= 10) web__put(o, (char)('0' + (int)(m / i % 10)));
    web__put(o, 'e');
    web__put(o, e < 0 ? '-' : '+');
    if (e < 0) e = -e;
    if (e < 10) web__put(o, '0');
    web__put_unsigned(o, (unsigned long long)e);
}

static int web_vsnprintf(char *buf, size_t size, const char *fmt, va_list ap)
{
    web__out o;
    o.buf = buf;
    o.size = size;
    o.len = 0;
    while (*fmt) {
        long prec = -1;
        int lng = 0, zu = 0;
        if (*fmt != '%') {
            web__put(&o, *fmt++);
            continue;
        }
        fmt++;
        if (*fmt == '.') {
            prec = 0;
            for (fmt++; *fmt >= '0' && *fmt <= '9'; fmt++) prec = 10 * prec + (*fmt - '0');
        }
        while (*fmt == 'l') lng++, fmt++;
        if (*fmt == 'z') zu = 1, fmt++;
        switch (*fmt) {
        case 's': {
            const char *s = va_arg(ap, const char *);
            if (!s) s = "(null)";
            while (*s && prec != 0) {
                web__put(&o, *s++);
                if (prec > 0) prec--;
            }
            break;
        }
        case 'd':
            if (lng >= 2) web__put_signed(&o, va_arg(ap, long long));
            else if (lng == 1) web__put_signed(&o, va_arg(ap, long));
            else web__put_signed(&o, va_arg(ap, int));
            break;
        case 'u':
            if (zu) web__put_unsigned(&o, va_arg(ap, size_t));
            else if (lng >= 2) web__put_unsigned(&o, va_arg(ap, unsigned long long));
            else if (lng == 1) web__put_unsigned(&o, va_arg(ap, unsigned long));
            else web__put_unsigned(&o, va_arg(ap, unsigned));
            break;
        case 'g': web__put_double(&o, va_arg(ap, double)); break;
        case '%': web__put(&o, '%'); break;
        case '\0': fmt--; break;
        default: web__put(&o, '%'), web__put(&o, *fmt); break;
        }
        fmt++;
    }
    if (size > 0) buf[o.len < size ? o.len : size - 1] = '\0';
    return (int)o.len;
}

static int web_snprintf(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = web_vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

#endif /* WEB_LIBC_H */
