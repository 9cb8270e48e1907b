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

static u128 u128_shl1(u128 a)
{
    u128 r;
    r.hi = (a.hi << 1) | (a.lo >> 63);
    r.lo = a.lo << 1;
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

fx32 fx32_div(fx32 a, fx32 b)
{
    uint64_t ma = mag64(a), mb = mag64(b), q = 0;
    u128 n, r = {0, 0}, d;
    int i, neg = (a < 0) != (b < 0);
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX32_MAX : a < 0 ? FX32_MIN : 0;
    }
    /* n = ma << 32 as 128 bits; long division, 96 significant bits. */
    n.hi = ma >> 32;
    n.lo = ma << 32;
    d.hi = 0;
    d.lo = mb;
    for (i = 127; i >= 0; i--) {
        uint64_t bit = i >= 64 ? (n.hi >> (i - 64)) & 1 : (n.lo >> i) & 1;
        r = u128_shl1(r);
        r.lo |= bit;
        if (q >> 63) {                    /* quotient would exceed 64 bits */
            if (u128_ge(r, d)) return fx32_signed(0, neg, 1);
            q <<= 1;
            continue;
        }
        q <<= 1;
        if (u128_ge(r, d)) { r = u128_sub(r, d); q |= 1; }
    }
    /* round to nearest: 2r >= d */
    if (u128_ge(u128_shl1(r), d)) {
        if (q == UINT64_MAX) return fx32_signed(0, neg, 1);
        q++;
    }
    return fx32_signed(q, neg, 0);
}

fx32 fx32_sqrt(fx32 a)
{
    /* sqrt(a * 2^32) over 128 bits, bit by bit; the root is below 2^48. */
    u128 v, res = {0, 0}, bit;
    uint64_t s;
    if (a < 0) { fx_overflows++; return 0; }
    v.hi = (uint64_t)a >> 32;
    v.lo = (uint64_t)a << 32;
    bit.hi = (uint64_t)1 << 62;
    bit.lo = 0;
    while (!u128_ge(v, bit) && (bit.hi | bit.lo)) {
        bit.lo = (bit.lo >> 2) | (bit.hi << 62);
        bit.hi >>= 2;
    }
    while (bit.hi | bit.lo) {
        u128 t = res;
        t.lo += bit.lo; t.hi += bit.hi + (t.lo < bit.lo);
        /* res >>= 1 */
        res.lo = (res.lo >> 1) | (res.hi << 63);
        res.hi >>= 1;
        if (u128_ge(v, t)) {
            v = u128_sub(v, t);
            res.lo += bit.lo; res.hi += bit.hi + (res.lo < bit.lo);
        }
        bit.lo = (bit.lo >> 2) | (bit.hi << 62);
        bit.hi >>= 2;
    }
    s = res.lo;                          /* floor root; remainder in v */
    if (v.hi != 0 || v.lo > s) s++;      /* round to nearest */
    return (fx32)s;
}
