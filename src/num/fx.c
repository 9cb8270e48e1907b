/* fx — out-of-line fixed-point operations (see fx.h for the rules). */
#include "num/fx.h"
#include "num/u128.h"
#include <math.h>

unsigned long fx_overflows;

/* ---- Q16.16 ---------------------------------------------------------- */

/* 1/sqrt(X) in Q1.15 at the centre of [i/256, (i+1)/256), i = 64..255:
 * the starting point of fx16_rsqrt, good to about 2^-8. */
const uint16_t fx_rsqrt_tab[192] = {
    65281, 64781, 64292, 63814, 63347, 62889, 62442, 62004, 61575, 61154, 60742, 60339,
    59943, 59555, 59175, 58801, 58435, 58075, 57722, 57376, 57035, 56700, 56372, 56049,
    55731, 55419, 55112, 54810, 54513, 54221, 53933, 53650, 53371, 53097, 52826, 52560,
    52298, 52040, 51785, 51535, 51288, 51044, 50804, 50567, 50333, 50103, 49876, 49652,
    49430, 49212, 48997, 48784, 48574, 48367, 48163, 47961, 47761, 47564, 47370, 47178,
    46988, 46800, 46615, 46432, 46251, 46072, 45895, 45720, 45547, 45376, 45207, 45040,
    44875, 44711, 44550, 44390, 44232, 44075, 43920, 43767, 43615, 43465, 43316, 43169,
    43024, 42879, 42737, 42595, 42456, 42317, 42180, 42044, 41910, 41776, 41644, 41514,
    41384, 41256, 41129, 41003, 40878, 40754, 40631, 40510, 40390, 40270, 40152, 40035,
    39919, 39803, 39689, 39576, 39464, 39352, 39242, 39133, 39024, 38916, 38810, 38704,
    38599, 38494, 38391, 38289, 38187, 38086, 37986, 37887, 37788, 37690, 37593, 37497,
    37401, 37307, 37213, 37119, 37027, 36935, 36843, 36753, 36663, 36573, 36485, 36397,
    36309, 36222, 36136, 36051, 35966, 35882, 35798, 35715, 35632, 35550, 35469, 35388,
    35307, 35228, 35148, 35070, 34991, 34914, 34837, 34760, 34684, 34608, 34533, 34458,
    34384, 34310, 34237, 34164, 34092, 34020, 33949, 33878, 33807, 33737, 33668, 33599,
    33530, 33461, 33393, 33326, 33259, 33192, 33126, 33060, 32994, 32929, 32864, 32800,
};

fx16 fx16_rsqrt(fx16 a)
{
    uint64_t x, xs, y, lim = (uint64_t)1 << 50;
    int s = 0;
    if (a <= 0) { fx_overflows++; return FX16_MAX; }
    x = (uint64_t)a;
    /* xs = x * 4^s in [2^30, 2^32) */
    xs = x;
    while (xs < ((uint64_t)1 << 30)) { xs <<= 2; s++; }
    y = fx_rsqrt_q30(xs);
    /* 1/sqrt(x) * 2^24 = y * 2^(s - 22) */
    y = (y + ((uint64_t)1 << (21 - s))) >> (22 - s);
    /* round to nearest: (2y-1)^2 x <= 2^50 < (2y+1)^2 x */
    while ((2 * y + 1) * (2 * y + 1) * x <= lim) y++;
    while (y > 1 && (2 * y - 1) * (2 * y - 1) * x > lim) y--;
    return (fx16)y;
}

/* ---- portable 128-bit helpers for Q32.32 ------------------------------ */


static u128 fx_u128_add64(u128 a, uint64_t b)
{
    u128 r;
    r.lo = a.lo + b;
    r.hi = a.hi + (r.lo < a.lo);
    return r;
}

static int fx_u128_ge(u128 a, u128 b) { return a.hi != b.hi ? a.hi > b.hi : a.lo >= b.lo; }

static u128 fx_u128_sub(u128 a, u128 b)
{
    u128 r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo);
    return r;
}

/* Magnitude of a signed 64-bit value as unsigned, defined for INT64_MIN. */
static uint64_t fx_mag64(int64_t a) { return a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a; }

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

fx32 fx32_mul_portable(fx32 a, fx32 b)
{
    u128 p = u128_mul64(fx_mag64(a), fx_mag64(b));
    p = fx_u128_add64(p, (uint64_t)1 << 31);          /* round half away from zero */
    /* result magnitude = p >> 32; it must fit in 64 bits */
    return fx32_signed((p.hi << 32) | (p.lo >> 32), (a < 0) != (b < 0), (p.hi >> 32) != 0);
}

/* Number of leading zero bits of v > 0. */
static int fx_clz64(uint64_t v)
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
static uint64_t fx_div128by64(uint64_t u1, uint64_t u0, uint64_t v, uint64_t *rem)
{
    const uint64_t base = (uint64_t)1 << 32;
    uint64_t vn1, vn0, un32, un21, un10, un1, un0, q1, q0, rhat;
    int s = fx_clz64(v);
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

fx32 fx32_div_portable(fx32 a, fx32 b)
{
    uint64_t ma = fx_mag64(a), mb = fx_mag64(b), q, r;
    int neg = (a < 0) != (b < 0);
    if (b == 0) {
        fx_overflows++;
        return a > 0 ? FX32_MAX : a < 0 ? FX32_MIN : 0;
    }
    /* dividend ma * 2^32 = (ma >> 32) : (ma << 32); the quotient needs more
     * than 64 bits exactly when the high word reaches the divisor */
    if ((ma >> 32) >= mb)
        return fx32_signed(0, neg, 1);
    q = fx_div128by64(ma >> 32, ma << 32, mb, &r);
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
        if (fx_u128_ge(v, sq)) break;
        s--;
    }
    for (;;) {                           /* (s+1)^2 > v */
        sq = u128_mul64(s + 1, s + 1);
        if (!fx_u128_ge(v, sq)) break;
        s++;
    }
    /* round to nearest: v - s^2 > s */
    sq = fx_u128_sub(v, u128_mul64(s, s));
    if (sq.hi != 0 || sq.lo > s) s++;
    return (fx32)s;
}
