/* fx — fixed-point arithmetic of the System/370 kind, and its wider sibling.
 *
 *   fx16: Q16.16 in int32_t, products and quotients through int64_t
 *         (the 3081's fullword registers and even/odd register pairs).
 *   fx32: Q32.32 in int64_t, products and quotients through 128 bits:
 *         the compiler's unsigned __int128 where it has one (one multiply
 *         or divide instruction pair), else a portable pair of uint64_t.
 *         Both paths give identical results (test_fx compares them).
 *
 * Rounding: conversions from double, multiply and divide round to nearest,
 * ties away from zero; square root rounds to nearest. Results outside the
 * representable range saturate to the largest magnitude of the right sign,
 * and every saturation, division by zero, negative square root or NaN input
 * adds one to fx_overflows (per thread; render code sums the threads).
 * No operation here has undefined behaviour for any input. */
#ifndef FX_H
#define FX_H
#include <math.h>
#include <stdint.h>

extern unsigned long fx_overflows;
#pragma omp threadprivate(fx_overflows)

typedef int32_t fx16;
typedef int64_t fx32;

#define FX16_FRAC 16
#define FX16_ONE  ((fx16)65536)
#define FX16_MAX  INT32_MAX
#define FX16_MIN  INT32_MIN
#define FX32_FRAC 32
#define FX32_ONE  ((fx32)1 << 32)
#define FX32_MAX  INT64_MAX
#define FX32_MIN  INT64_MIN

#if defined(__SIZEOF_INT128__) && !defined(FX_PORTABLE)
#define FX_HAVE_INT128 1
__extension__ typedef unsigned __int128 fx_u128;
__extension__ typedef __int128 fx_i128;
#endif

fx32 fx32_from_double(double x);
fx32 fx32_sqrt(fx32 a);
/* The portable 128-bit paths, always compiled (the reference for the
 * native ones, and what fx32_mul/fx32_div use without __int128). */
fx32 fx32_mul_portable(fx32 a, fx32 b);
fx32 fx32_div_portable(fx32 a, fx32 b);

/* Saturates a 64-bit intermediate to Q16.16, counting an overflow. */
static inline fx16 fx16_sat(int64_t v)
{
    if (v > FX16_MAX) { fx_overflows++; return FX16_MAX; }
    if (v < FX16_MIN) { fx_overflows++; return FX16_MIN; }
    return (fx16)v;
}

/* Round to nearest, ties away from zero, without a call to llround or a
 * branch on the rounding: one test keeps NaN and out-of-range values out;
 * then truncation and its remainder f are exact for |r| < 2^31, and so is
 * 2f, whose truncation is +-1 exactly when |f| >= 1/2. */
static inline fx16 fx16_from_double(double x)
{
    double r = x * 65536.0, f;
    int64_t i;
    if (!(r < 2147483647.5 && r > -2147483648.5)) {
        fx_overflows++;
        return x != x ? 0 : r > 0 ? FX16_MAX : FX16_MIN;
    }
    i = (int64_t)r;
    f = r - (double)i;
    return (fx16)(i + (int64_t)(f + f));
}

/* fx16_from_double of x, in two steps for a loop over many values: with
 * no branch and no counter, each step vectorises. fx16_lane_scale gives
 * r = x * 2^16 where fx16_from_double neither saturates nor counts, else
 * (NaN too) 0; fx16_from_lane then gives fx16_from_double's value by the
 * same steps in 32 bits. Two loops, one for each step: GCC vectorises
 * neither loop that does both. */
static inline double fx16_lane_scale(double x)
{
    double r = x * 65536.0;
    return ((r < 2147483647.5) & (r > -2147483648.5)) ? r : 0.0;
}
static inline fx16 fx16_from_lane(double r)
{
    int32_t i = (int32_t)r;
    double f = r - (double)i;
    return i + (int32_t)(f + f);
}

static inline double fx16_to_double(fx16 a) { return (double)a * (1.0 / 65536.0); }

static inline fx16 fx16_add(fx16 a, fx16 b) { return fx16_sat((int64_t)a + b); }
static inline fx16 fx16_sub(fx16 a, fx16 b) { return fx16_sat((int64_t)a - b); }
static inline fx16 fx16_neg(fx16 a) { return fx16_sat(-(int64_t)a); }
static inline fx16 fx16_abs(fx16 a) { return a < 0 ? fx16_neg(a) : a; }

/* floor(x / 2^k) (0 <= k < 63), without C's implementation-defined shift
 * of a negative value: GCC and Clang make one arithmetic shift of it. */
static inline int64_t fx_sar(int64_t x, int k) { return x < 0 ? ~(~x >> k) : x >> k; }

/* v / 2^k rounded to nearest, ties away from zero (1 <= k <= 62,
 * |v| <= INT64_MAX - 2^(k-1)): floor((v + 2^(k-1) - [v < 0]) / 2^k),
 * which for v < 0 is -floor((-v + 2^(k-1)) / 2^k). No branch on the
 * sign: the signs of direction and normal components are data, and a
 * branch on them is often mispredicted. */
static inline int64_t fx_shr_round(int64_t v, int k)
{
    return fx_sar(v + ((int64_t)1 << (k - 1)) - (v < 0), k);
}

/* Q16.16 product, rounded to nearest (ties away from zero), not saturated:
 * |a*b| < 2^62, so the int64_t product and the rounding add cannot
 * overflow. Sums of these are exact (prim.c, mat3_mul). */
static inline int64_t fx16_mul_wide(fx16 a, fx16 b) { return fx_shr_round((int64_t)a * b, 16); }
static inline fx16 fx16_mul(fx16 a, fx16 b) { return fx16_sat(fx16_mul_wide(a, b)); }

/* Quotient a/b in Q16.16: the dividend a*2^16 fits int64_t exactly. */
static inline fx16 fx16_div(fx16 a, fx16 b)
{
    int64_t n, q, r, mb;
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX16_MAX : a < 0 ? FX16_MIN : 0;
    }
    n = (int64_t)a * 65536;
    q = n / b;
    r = n - q * b;
    if (r < 0) r = -r;
    mb = b < 0 ? -(int64_t)b : (int64_t)b;
    if (2 * r >= mb)
        q += ((n < 0) != (b < 0)) ? -1 : 1;
    return fx16_sat(q);
}

/* Q16.16 square root, rounded to nearest: the integer root of a * 2^16.
 * A binary64 square root of the exact integer (below 2^47, so exactly
 * representable) lands within one of the floor root; the integer checks
 * that follow make s exactly floor(sqrt(v)), so the result does not depend
 * on the floating-point unit. */
static inline fx16 fx16_sqrt(fx16 a)
{
    uint64_t v, s;
    if (a < 0) { fx_overflows++; return 0; }
    v = (uint64_t)a << 16;
    s = (uint64_t)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    if (v - s * s > s) s++;            /* round to nearest */
    return (fx16)s;                    /* s <= 2^23.5: fits */
}

/* 1/sqrt(a) in Q16.16 for a > 0, rounded to nearest: round(2^24/sqrt(raw)).
 * fx_rsqrt_q30 (a table of 385 knots and one Newton step in integers)
 * gives it to well under one unit; an exact integer test then settles the
 * last unit. No divide and no floating point. a <= 0 counts an overflow
 * and gives FX16_MAX. */
fx16 fx16_rsqrt(fx16 a);

extern const uint32_t fx_rsqrt_tab[385];

/* The core of fx16_rsqrt: for xs in [2^30, 2^32) (X = xs/2^32 in [1/4, 1)),
 * 1/sqrt(X) in Q2.30, within 1.35 units (`make check-rsqrt` tries every
 * xs, the unit tests a sample). The chord between the table's two
 * knots around X starts it, 2^-17.4 relative at worst (the curve is convex:
 * the chord lies above it by at most h^2/8 max f'' with h = 2^-9); one
 * Newton step y(3 - X y^2)/2 squares that error. A lookup of the value
 * alone (8 bits) needs two steps: three more multiplies in a chain every
 * unit vector waits for. y^2 and X y^2 keep 30 fraction bits: X y^2 is
 * within 2^-16 of 1, so X y^2 2^62 stays below 2^64. */
static inline uint64_t fx_rsqrt_q30(uint64_t xs)
{
    const uint32_t *k = &fx_rsqrt_tab[(xs >> 23) - 128];
    uint64_t y = k[0] - (((uint64_t)(k[0] - k[1]) * (xs & 0x7fffff)) >> 23), y2, t;
    y2 = (y * y) >> 30;                                     /* Q.30 */
    t = ((uint64_t)3 << 32) - ((xs * y2) >> 30);            /* Q.32 */
    return (y * (t >> 1)) >> 32;                            /* Q.30 */
}


/* a/b rounded to nearest (ties away from zero) and clamped to [-lim, lim],
 * for FX16_ONE <= lim: num_div_clamp of Q16.16 (geom/vec.h), worked on
 * 64-bit magnitudes, so the rounding, the sign and the clamp need one
 * division and no saturation. The values are those of the saturating form
 * (|a| >= |b| lim when |b| < 1, else the quotient, clamped), and so are the
 * overflow counts for lim <= 2^30, except that a or b = FX16_MIN (itself a
 * saturated value) no longer counts a second overflow. */
static inline fx16 fx16_div_clamp(fx16 a, fx16 b, fx16 lim)
{
    int64_t ua = a < 0 ? -(int64_t)a : a, ub = b < 0 ? -(int64_t)b : b, q;
    if (ua == 0)
        return 0;
    if (ub == 0 || (ub < FX16_ONE && ua >= fx_shr_round(ub * lim, 16))) {
        q = lim;
    } else {
        q = ((ua << 17) + ub) / (2 * ub);            /* round(|a| 2^16 / |b|) */
        if (q > lim)
            q = lim;
    }
    return (fx16)((a < 0) != (b < 0) ? -q : q);
}

static inline fx32 fx32_add(fx32 a, fx32 b)
{
    if ((b > 0 && a > FX32_MAX - b) || (b < 0 && a < FX32_MIN - b)) {
        fx_overflows++;
        return b > 0 ? FX32_MAX : FX32_MIN;
    }
    return a + b;
}
static inline fx32 fx32_neg(fx32 a)
{
    if (a == FX32_MIN) { fx_overflows++; return FX32_MAX; }
    return -a;
}
static inline fx32 fx32_sub(fx32 a, fx32 b) { return fx32_add(a, fx32_neg(b)); }
static inline fx32 fx32_abs(fx32 a) { return a < 0 ? fx32_neg(a) : a; }
static inline double fx32_to_double(fx32 a) { return (double)a * (1.0 / 4294967296.0); }

#ifdef FX_HAVE_INT128
/* Magnitude of a signed 64-bit value as unsigned, defined for INT64_MIN. */
static inline uint64_t fx32_mag(int64_t a) { return a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a; }

/* Applies a sign to magnitude m, saturating (and counting) out of range. */
static inline fx32 fx32_sign(uint64_t m, int negative)
{
    if (m > (uint64_t)INT64_MAX + (uint64_t)negative) {
        fx_overflows++;
        return negative ? FX32_MIN : FX32_MAX;
    }
    return negative ? (fx32)((uint64_t)0 - m) : (fx32)m;
}

/* Q32.32 product rounded half away from zero, on one 64x64->128 multiply. */
static inline fx32 fx32_mul(fx32 a, fx32 b)
{
    fx_u128 p = (fx_u128)fx32_mag(a) * fx32_mag(b) + ((fx_u128)1 << 31);
    int neg = (a < 0) != (b < 0);
    if (p >> 96) {
        fx_overflows++;
        return neg ? FX32_MIN : FX32_MAX;
    }
    return fx32_sign((uint64_t)(p >> 32), neg);
}

/* Q32.32 quotient rounded half away from zero, on one 128/64 divide. */
static inline fx32 fx32_div(fx32 a, fx32 b)
{
    uint64_t ma = fx32_mag(a), mb = fx32_mag(b), q, r;
    int neg = (a < 0) != (b < 0);
    fx_u128 n;
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX32_MAX : a < 0 ? FX32_MIN : 0;
    }
    if ((ma >> 32) >= mb) {              /* quotient needs more than 64 bits */
        fx_overflows++;
        return neg ? FX32_MIN : FX32_MAX;
    }
    n = (fx_u128)ma << 32;
    q = (uint64_t)(n / mb);
    r = (uint64_t)(n - (fx_u128)q * mb);
    if (r >= mb - r) {
        if (q == UINT64_MAX) {
            fx_overflows++;
            return neg ? FX32_MIN : FX32_MAX;
        }
        q++;
    }
    return fx32_sign(q, neg);
}
#else
static inline fx32 fx32_mul(fx32 a, fx32 b) { return fx32_mul_portable(a, b); }
static inline fx32 fx32_div(fx32 a, fx32 b) { return fx32_div_portable(a, b); }
#endif
#endif
