/* fx — fixed-point arithmetic of the System/370 kind, and its wider sibling.
 *
 *   fx16: Q16.16 in int32_t, products and quotients through int64_t
 *         (the 3081's fullword registers and even/odd register pairs).
 *   fx32: Q32.32 in int64_t, products and quotients through a portable
 *         128-bit pair of uint64_t (no compiler extensions).
 *
 * Rounding: conversions from double, multiply and divide round to nearest,
 * ties away from zero; square root rounds to nearest. Results outside the
 * representable range saturate to the largest magnitude of the right sign,
 * and every saturation, division by zero, negative square root or NaN input
 * adds one to fx_overflows (per thread; render code sums the threads).
 * No operation here has undefined behaviour for any input. */
#ifndef FX_H
#define FX_H
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

fx16 fx16_from_double(double x);
double fx16_to_double(fx16 a);
fx16 fx16_div(fx16 a, fx16 b);
fx16 fx16_sqrt(fx16 a);

fx32 fx32_from_double(double x);
double fx32_to_double(fx32 a);
fx32 fx32_mul(fx32 a, fx32 b);
fx32 fx32_div(fx32 a, fx32 b);
fx32 fx32_sqrt(fx32 a);

/* Saturates a 64-bit intermediate to Q16.16, counting an overflow. */
static inline fx16 fx16_sat(int64_t v)
{
    if (v > FX16_MAX) { fx_overflows++; return FX16_MAX; }
    if (v < FX16_MIN) { fx_overflows++; return FX16_MIN; }
    return (fx16)v;
}

static inline fx16 fx16_add(fx16 a, fx16 b) { return fx16_sat((int64_t)a + b); }
static inline fx16 fx16_sub(fx16 a, fx16 b) { return fx16_sat((int64_t)a - b); }
static inline fx16 fx16_neg(fx16 a) { return fx16_sat(-(int64_t)a); }
static inline fx16 fx16_abs(fx16 a) { return a < 0 ? fx16_neg(a) : a; }

/* Q16.16 product, rounded to nearest (ties away from zero). |a*b| < 2^62, so
 * the int64_t product and the rounding add cannot overflow. */
static inline fx16 fx16_mul(fx16 a, fx16 b)
{
    int64_t p = (int64_t)a * b;
    int64_t q = p >= 0 ? (p + 32768) / 65536 : -((-p + 32768) / 65536);
    return fx16_sat(q);
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
#endif
