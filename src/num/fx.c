/* fx — out-of-line fixed-point operations (see fx.h for the rules). */
#include "num/fx.h"
#include <math.h>

unsigned long fx_overflows;

/* ---- Q16.16 ---------------------------------------------------------- */

fx16 fx16_from_double(double x)
{
    double r;
    if (x != x) { fx_overflows++; return 0; }
    r = x * 65536.0;
    if (r >= 2147483647.5) { fx_overflows++; return FX16_MAX; }
    if (r <= -2147483648.5) { fx_overflows++; return FX16_MIN; }
    return (fx16)llround(r);
}

double fx16_to_double(fx16 a) { return (double)a / 65536.0; }

/* Quotient a/b in Q16.16: the dividend a*2^16 fits int64_t exactly. */
fx16 fx16_div(fx16 a, fx16 b)
{
    int64_t n, q, r;
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX16_MAX : a < 0 ? FX16_MIN : 0;
    }
    n = (int64_t)a * 65536;
    q = n / b;
    r = n % b;
    if (r < 0) r = -r;
    if (2 * r >= (b < 0 ? -(int64_t)b : (int64_t)b))
        q += ((n < 0) != (b < 0)) ? -1 : 1;
    return fx16_sat(q);
}

/* Q16.16 square root, rounded to nearest: the integer root of a * 2^16.
 * A binary64 square root of the exact integer (below 2^47, so exactly
 * representable) lands within one of the floor root; the integer checks
 * that follow make s exactly floor(sqrt(v)), so the result does not depend
 * on the floating-point unit. */
fx16 fx16_sqrt(fx16 a)
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

/* ---- portable 128-bit helpers for Q32.32 ------------------------------ */

typedef struct u128 { uint64_t hi, lo; } u128;

static u128 u128_mul64(uint64_t a, uint64_t b)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    u128 r;
    r.lo = (p00 & 0xffffffffu) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

static u128 u128_add64(u128 a, uint64_t b)
{
    u128 r;
    r.lo = a.lo + b;
    r.hi = a.hi + (r.lo < a.lo);
    return r;
}

static int u128_ge(u128 a, u128 b) { return a.hi != b.hi ? a.hi > b.hi : a.lo >= b.lo; }

static u128 u128_sub(u128 a, u128 b)
{
    u128 r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo);
    return r;
}

/* Magnitude of a signed 64-bit value as unsigned, defined for INT64_MIN. */
static uint64_t mag64(int64_t a) { return a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a; }

/* Applies sign and saturates an unsigned magnitude to fx32. */
static fx32 fx32_signed(uint64_t m, int negative, int overflow)
{
    if (overflow || m > (uint64_t)INT64_MAX + negative) {
        fx_overflows++;
        return negative ? FX32_MIN : FX32_MAX;
    }
    if (negative)
        return m == (uint64_t)INT64_MAX + 1 ? FX32_MIN : -(int64_t)m;
    return (int64_t)m;
}

/* ---- Q32.32 ---------------------------------------------------------- */

fx32 fx32_from_double(double x)
{
    double r;
    if (x != x) { fx_overflows++; return 0; }
    r = x * 4294967296.0;
    if (r >= 9223372036854775808.0) { fx_overflows++; return FX32_MAX; }
    if (r < -9223372036854775808.0) { fx_overflows++; return FX32_MIN; }
    return (fx32)llround(r);
}

double fx32_to_double(fx32 a) { return (double)a / 4294967296.0; }

fx32 fx32_mul(fx32 a, fx32 b)
{
    u128 p = u128_mul64(mag64(a), mag64(b));
    p = u128_add64(p, (uint64_t)1 << 31);          /* round half away from zero */
    /* result magnitude = p >> 32; it must fit in 64 bits */
    return fx32_signed((p.hi << 32) | (p.lo >> 32), (a < 0) != (b < 0), (p.hi >> 32) != 0);
}

/* Number of leading zero bits of v > 0. */
static int clz64(uint64_t v)
{
#if defined(__GNUC__)
    return __builtin_clzll(v);
#else
    int n = 0;
    while (!(v >> 63)) { v <<= 1; n++; }
    return n;
#endif
}

/* Divides the 128-bit u1:u0 by v, where u1 < v so the quotient fits in 64
 * bits: schoolbook division in two 32-bit quotient digits after normalising
 * v (Knuth's algorithm D for a two-digit divisor). *rem gets the remainder. */
static uint64_t div128by64(uint64_t u1, uint64_t u0, uint64_t v, uint64_t *rem)
{
    const uint64_t base = (uint64_t)1 << 32;
    uint64_t vn1, vn0, un32, un21, un10, un1, un0, q1, q0, rhat;
    int s = clz64(v);
    v <<= s;
    vn1 = v >> 32;
    vn0 = v & 0xffffffffu;
    un32 = s ? (u1 << s) | (u0 >> (64 - s)) : u1;
    un10 = u0 << s;
    un1 = un10 >> 32;
    un0 = un10 & 0xffffffffu;
    q1 = un32 / vn1;
    rhat = un32 - q1 * vn1;
    while (q1 >= base || q1 * vn0 > base * rhat + un1) {
        q1--;
        rhat += vn1;
        if (rhat >= base) break;
    }
    un21 = un32 * base + un1 - q1 * v;
    q0 = un21 / vn1;
    rhat = un21 - q0 * vn1;
    while (q0 >= base || q0 * vn0 > base * rhat + un0) {
        q0--;
        rhat += vn1;
        if (rhat >= base) break;
    }
    *rem = (un21 * base + un0 - q0 * v) >> s;
    return q1 * base + q0;
}

fx32 fx32_div(fx32 a, fx32 b)
{
    uint64_t ma = mag64(a), mb = mag64(b), q, r;
    int neg = (a < 0) != (b < 0);
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX32_MAX : a < 0 ? FX32_MIN : 0;
    }
    /* dividend ma * 2^32 = (ma >> 32) : (ma << 32); the quotient needs more
     * than 64 bits exactly when the high word reaches the divisor */
    if ((ma >> 32) >= mb)
        return fx32_signed(0, neg, 1);
    q = div128by64(ma >> 32, ma << 32, mb, &r);
    if (r >= mb - r) {                   /* 2r >= mb: round half away from zero */
        if (q == UINT64_MAX) return fx32_signed(0, neg, 1);
        q++;
    }
    return fx32_signed(q, neg, 0);
}

/* Q32.32 square root, rounded to nearest: the integer root of a * 2^32
 * (below 2^95, root below 2^47.5). A binary64 root gives an estimate within
 * a few units; exact 128-bit comparisons then make it floor(sqrt(v)). */
fx32 fx32_sqrt(fx32 a)
{
    u128 v, sq;
    uint64_t s;
    if (a < 0) { fx_overflows++; return 0; }
    v.hi = (uint64_t)a >> 32;
    v.lo = (uint64_t)a << 32;
    s = (uint64_t)sqrt((double)a * 4294967296.0);
    for (;;) {                           /* s*s <= v */
        sq = u128_mul64(s, s);
        if (u128_ge(v, sq)) break;
        s--;
    }
    for (;;) {                           /* (s+1)^2 > v */
        sq = u128_mul64(s + 1, s + 1);
        if (!u128_ge(v, sq)) break;
        s++;
    }
    /* round to nearest: v - s^2 > s */
    sq = u128_sub(v, u128_mul64(s, s));
    if (sq.hi != 0 || sq.lo > s) s++;
    return (fx32)s;
}
