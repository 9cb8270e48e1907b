/* hfp — System/370 hexadecimal floating point (see hfp.h for the model and
 * docs/numerics.md for the rules and their sources).
 *
 * One digit-serial implementation serves both formats: nd is the number of
 * fraction digits (6 short, 14 long) and a number travels as a uint64_t
 * register image of 1 + 7 + 4*nd bits. Long products and the radicands of
 * long square roots need 112 bits: a pair of uint64_t. */
#include "num/hfp.h"
#include "num/u128.h"
#include <math.h>

unsigned long hfp_exc[HFP_EXC_N];

const char *const hfp_exc_name[HFP_EXC_N] = {
    [HFP_EXC_OVERFLOW] = "overflows",
    [HFP_EXC_UNDERFLOW] = "underflows",
    [HFP_EXC_SIGNIFICANCE] = "significance",
    [HFP_EXC_DIVIDE] = "divides",
    [HFP_EXC_SQRT] = "sqrt_negative",
    [HFP_EXC_CONVERT] = "conversions",
};

#define HFP_SHORT 6
#define HFP_LONG 14

/* Unpacked operand: sign, characteristic (an int, so that intermediate
 * values below 0 or above 127 can be held), fraction. */
typedef struct hfp_num {
    int s, c;
    uint64_t f;
} hfp_num;

typedef u128 hfp_pair;      /* long products and radicands: 112 bits */

static hfp_num hfp_unpack(uint64_t a, int nd)
{
    hfp_num u;
    int fb = 4 * nd;
    u.s = (int)(a >> (fb + 7)) & 1;
    u.c = (int)(a >> fb) & 0x7f;
    u.f = a & (((uint64_t)1 << fb) - 1);
    return u;
}

static uint64_t hfp_max(int s, int nd)
{
    int fb = 4 * nd;
    return ((uint64_t)s << (fb + 7)) | (((uint64_t)1 << (fb + 7)) - 1);
}

/* The final result of fraction f (nd digits, normalised, or zero) and
 * characteristic c: exponent overflow and underflow are decided here. */
static uint64_t hfp_finish(int s, int c, uint64_t f, int nd)
{
    int fb = 4 * nd;
    if (f == 0)
        return 0;
    if (c > 127) {
        hfp_exc[HFP_EXC_OVERFLOW]++;
        return hfp_max(s, nd);
    }
    if (c < 0) {
        hfp_exc[HFP_EXC_UNDERFLOW]++;
        return 0;
    }
    return ((uint64_t)s << (fb + 7)) | ((uint64_t)c << fb) | f;
}

/* Prenormalisation for multiply, divide and square root: leading zero
 * digits out, characteristic down (possibly below 0). f is nonzero. */
static void hfp_prenorm(hfp_num *u, int nd)
{
    uint64_t top = (uint64_t)0xf << (4 * nd - 4);
    while (!(u->f & top)) {
        u->f <<= 4;
        u->c--;
    }
}

/* ---- add, subtract, compare ---------------------------------------------- */

/* The aligned intermediate sum of a and b (b's sign inverted if negb): the
 * fraction of the operand with the smaller characteristic is shifted right
 * by the difference, keeping one guard digit; digits beyond the guard are
 * lost. Returns the magnitude with 4*nd+4 bits plus a possible carry, and
 * its sign and characteristic. */
static uint64_t hfp_align_sum(uint64_t a, uint64_t b, int negb, int nd, int *s, int *c)
{
    hfp_num x = hfp_unpack(a, nd), y = hfp_unpack(b, nd), t;
    uint64_t fx, fy;
    int d;
    y.s ^= negb;
    if (x.c < y.c) {
        t = x;
        x = y;
        y = t;
    }
    d = x.c - y.c;
    fx = x.f << 4;
    fy = d > nd ? 0 : (y.f << 4) >> (4 * d);
    *c = x.c;
    if (x.s == y.s) {
        *s = x.s;
        return fx + fy;
    }
    *s = fx >= fy ? x.s : y.s;
    return fx >= fy ? fx - fy : fy - fx;
}

static uint64_t hfp_add(uint64_t a, uint64_t b, int negb, int nd)
{
    int s, c, fb = 4 * nd;
    uint64_t f = hfp_align_sum(a, b, negb, nd, &s, &c);
    if (f >> (fb + 4)) {                /* carry: one digit right */
        f >>= 4;
        c++;
    }
    if (f == 0) {
        hfp_exc[HFP_EXC_SIGNIFICANCE]++;
        return 0;
    }
    while (!(f >> fb)) {                /* normalise; the guard digit moves in */
        f <<= 4;
        c--;
    }
    return hfp_finish(s, c, f >> 4, nd);
}

/* Compare: the normalised subtraction, difference discarded, no exceptions. */
static int hfp_cmp(uint64_t a, uint64_t b, int nd)
{
    int s, c;
    uint64_t f = hfp_align_sum(a, b, 1, nd, &s, &c);
    return f == 0 ? 0 : s ? -1 : 1;
}

/* ---- multiply ------------------------------------------------------------ */

/* The normalised product of nd-digit operands as a long number: for nd = 6
 * the exact 12-digit product (ME), for nd = 14 truncated to 14 digits (MD). */
static uint64_t hfp_mul(uint64_t a, uint64_t b, int nd)
{
    hfp_num x = hfp_unpack(a, nd), y = hfp_unpack(b, nd);
    hfp_pair p;
    int s = x.s ^ y.s, c;
    if (!x.f || !y.f)
        return 0;
    hfp_prenorm(&x, nd);
    hfp_prenorm(&y, nd);
    c = x.c + y.c - 64;
    p = u128_mul64(x.f, y.f);
    if (nd == HFP_SHORT) {              /* 48-bit product in p.lo */
        if (!(p.lo >> 44)) {
            p.lo <<= 4;
            c--;
        }
        return hfp_finish(s, c, p.lo << 8, HFP_LONG);
    }
    if (!(p.hi >> 44)) {                /* 112-bit product */
        p.hi = (p.hi << 4) | (p.lo >> 60);
        p.lo <<= 4;
        c--;
    }
    return hfp_finish(s, c, (p.hi << 8) | (p.lo >> 56), HFP_LONG);
}

/* ---- divide -------------------------------------------------------------- */

static uint64_t hfp_div(uint64_t a, uint64_t b, int nd)
{
    hfp_num x = hfp_unpack(a, nd), y = hfp_unpack(b, nd);
    int s = x.s ^ y.s, c, k, i, fb = 4 * nd;
    uint64_t q, r;
    if (!y.f) {
        hfp_exc[HFP_EXC_DIVIDE]++;
        return x.f ? hfp_max(s, nd) : 0;
    }
    if (!x.f)
        return 0;
    hfp_prenorm(&x, nd);
    hfp_prenorm(&y, nd);
    c = x.c - y.c + 64;
    k = fb;
    if (x.f >= y.f) {                   /* quotient >= 1: one digit right */
        c++;
        k = fb - 4;
    }
    /* floor(x.f * 2^k / y.f), one quotient bit per step. */
    q = x.f / y.f;
    r = x.f % y.f;
    for (i = 0; i < k; i++) {
        r <<= 1;
        q <<= 1;
        if (r >= y.f) {
            r -= y.f;
            q |= 1;
        }
    }
    return hfp_finish(s, c, q, nd);
}

/* ---- square root, halve -------------------------------------------------- */

/* floor(sqrt(n)) for n < 2^(2*bits), bits <= 56: two radicand bits per
 * step; *rem = n - root^2. */
static uint64_t hfp_isqrt(hfp_pair n, int bits, uint64_t *rem)
{
    uint64_t q = 0, r = 0, t;
    int i;
    for (i = bits - 1; i >= 0; i--) {
        int at = 2 * i;
        uint64_t two = at >= 64 ? (n.hi >> (at - 64)) & 3 : (n.lo >> at) & 3;
        r = (r << 2) | two;
        t = (q << 2) | 1;
        q <<= 1;
        if (r >= t) {
            r -= t;
            q |= 1;
        }
    }
    *rem = r;
    return q;
}

/* Square root, rounded to nearest (as Hercules executes SQER/SQDR; see
 * docs/numerics.md): value f * 16^e with e even is sqrt(f) * 16^(e/2); with
 * e odd it is sqrt(f/16) * 16^((e+1)/2). Either fraction lies in [1/16, 1),
 * so the root is normalised and cannot overflow or underflow. The radicand
 * n is an integer, so the root is never halfway between two fractions: it
 * rounds up when n - q^2 > q. Rounding up never carries: q + 1 < 2^(4*nd). */
static uint64_t hfp_sqrt(uint64_t a, int nd)
{
    hfp_num x = hfp_unpack(a, nd);
    int fb = 4 * nd, e, sh;
    uint64_t q, rem;
    hfp_pair n;
    if (!x.f)
        return 0;
    if (x.s) {
        hfp_exc[HFP_EXC_SQRT]++;
        return 0;
    }
    hfp_prenorm(&x, nd);
    e = x.c - 64;
    sh = e % 2 ? fb - 4 : fb;
    n.hi = x.f >> (64 - sh);            /* sh is 20 or more */
    n.lo = x.f << sh;
    q = hfp_isqrt(n, fb, &rem);
    if (rem > q)
        q++;
    return hfp_finish(0, 64 + (e % 2 ? (e + 1) / 2 : e / 2), q, nd);
}

/* Halve: the fraction moves right one bit, the bit shifted out kept in the
 * guard digit; then normalised (GA22-7000: "the normalized quotient"). */
static uint64_t hfp_halve(uint64_t a, int nd)
{
    hfp_num x = hfp_unpack(a, nd);
    int fb = 4 * nd, c = x.c;
    uint64_t f = (x.f << 4) >> 1;
    if (!f)
        return 0;
    while (!(f >> fb)) {
        f <<= 4;
        c--;
    }
    return hfp_finish(x.s, c, f >> 4, nd);
}

/* ---- the instructions ---------------------------------------------------- */

hfp_short hfp_ae(hfp_short a, hfp_short b) { return (hfp_short)hfp_add(a, b, 0, HFP_SHORT); }
hfp_short hfp_se(hfp_short a, hfp_short b) { return (hfp_short)hfp_add(a, b, 1, HFP_SHORT); }
hfp_long hfp_me(hfp_short a, hfp_short b) { return hfp_mul(a, b, HFP_SHORT); }
hfp_short hfp_de(hfp_short a, hfp_short b) { return (hfp_short)hfp_div(a, b, HFP_SHORT); }
hfp_short hfp_sqe(hfp_short a) { return (hfp_short)hfp_sqrt(a, HFP_SHORT); }
hfp_short hfp_her(hfp_short a) { return (hfp_short)hfp_halve(a, HFP_SHORT); }
int hfp_ce(hfp_short a, hfp_short b) { return hfp_cmp(a, b, HFP_SHORT); }

hfp_long hfp_ad(hfp_long a, hfp_long b) { return hfp_add(a, b, 0, HFP_LONG); }
hfp_long hfp_sd(hfp_long a, hfp_long b) { return hfp_add(a, b, 1, HFP_LONG); }
hfp_long hfp_md(hfp_long a, hfp_long b) { return hfp_mul(a, b, HFP_LONG); }
hfp_long hfp_dd(hfp_long a, hfp_long b) { return hfp_div(a, b, HFP_LONG); }
hfp_long hfp_sqd(hfp_long a) { return hfp_sqrt(a, HFP_LONG); }
hfp_long hfp_hdr(hfp_long a) { return hfp_halve(a, HFP_LONG); }
int hfp_cd(hfp_long a, hfp_long b) { return hfp_cmp(a, b, HFP_LONG); }

/* Load rounded: add one at the leftmost dropped bit and truncate; a carry
 * out of the fraction shifts it right one digit. No normalisation; only
 * exponent overflow can occur. */
static uint64_t hfp_round(int s, int c, uint64_t f, int round_bit, int nd)
{
    int fb = 4 * nd;
    if (round_bit && ++f >> fb) {
        f >>= 4;
        if (++c > 127) {
            hfp_exc[HFP_EXC_OVERFLOW]++;
            return hfp_max(s, nd);
        }
    }
    return ((uint64_t)s << (fb + 7)) | ((uint64_t)c << fb) | f;
}

hfp_short hfp_lrer(hfp_long a)
{
    hfp_num x = hfp_unpack(a, HFP_LONG);
    return (hfp_short)hfp_round(x.s, x.c, x.f >> 32, (int)(x.f >> 31) & 1, HFP_SHORT);
}

hfp_long hfp_lrdr(hfp_long hi, hfp_long lo)
{
    hfp_num x = hfp_unpack(hi, HFP_LONG);
    return hfp_round(x.s, x.c, x.f, (int)(lo >> 55) & 1, HFP_LONG);
}

/* ---- integers ------------------------------------------------------------ */

hfp_long hfp_long_from_i32(int32_t i)
{
    uint64_t f = i < 0 ? (uint64_t)0 - (uint64_t)(int64_t)i : (uint64_t)i;
    int c = 64 + 14;                    /* X'4E': the integer in the low 8 digits */
    if (!f)
        return 0;
    while (!(f >> 52)) {
        f <<= 4;
        c--;
    }
    return ((uint64_t)(i < 0) << 63) | ((uint64_t)c << 56) | f;
}

hfp_short hfp_short_from_i32(int32_t i) { return (hfp_short)(hfp_long_from_i32(i) >> 32); }

int32_t hfp_long_to_i32(hfp_long a)
{
    hfp_num x = hfp_unpack(a, HFP_LONG);
    int e = x.c - 64;
    uint64_t m;
    if (!x.f || e <= 0)
        return 0;
    m = e > 8 ? (uint64_t)1 << 40 : x.f >> (56 - 4 * e);
    if (x.s) {
        if (m > (uint64_t)1 << 31) {
            hfp_exc[HFP_EXC_CONVERT]++;
            return INT32_MIN;
        }
        return m == (uint64_t)1 << 31 ? INT32_MIN : -(int32_t)m;
    }
    if (m > INT32_MAX) {
        hfp_exc[HFP_EXC_CONVERT]++;
        return INT32_MAX;
    }
    return (int32_t)m;
}

int32_t hfp_short_to_i32(hfp_short a) { return hfp_long_to_i32((hfp_long)a << 32); }

/* ---- IEEE binary64 ------------------------------------------------------- */

hfp_long hfp_long_from_double(double x)
{
    int s = signbit(x) ? 1 : 0, k, e;
    uint64_t m;
    if (x != x) {
        hfp_exc[HFP_EXC_CONVERT]++;
        return 0;
    }
    if (x == 0)
        return 0;
    if (isinf(x)) {
        hfp_exc[HFP_EXC_OVERFLOW]++;
        return hfp_max(s, HFP_LONG);
    }
    /* |x| = m * 2^(k-53) with m < 2^53; 16^(e-1) <= |x| < 16^e. */
    m = (uint64_t)ldexp(frexp(fabs(x), &k), 53);
    e = k >= 0 ? (k + 3) / 4 : -((-k) / 4);
    return hfp_finish(s, e + 64, m << (k + 3 - 4 * e), HFP_LONG);
}

hfp_short hfp_short_from_double(double x)
{
    hfp_long l = hfp_long_from_double(x);
    if ((l & HFP_LONG_MAX) == HFP_LONG_MAX)     /* overflowed already: no double count */
        return (hfp_short)(l >> 32);
    return hfp_lrer(l);
}

double hfp_short_to_double(hfp_short a)
{
    hfp_num x = hfp_unpack(a, HFP_SHORT);
    double v = ldexp((double)x.f, 4 * (x.c - 64) - 24);
    return x.s ? -v : v;
}

double hfp_long_to_double(hfp_long a)
{
    hfp_num x = hfp_unpack(a, HFP_LONG);
    int drop = 0;
    uint64_t f = x.f, rem, half;
    double v;
    while (f >> (53 + drop))
        drop++;
    if (drop) {                         /* to 53 bits, nearest, ties to even */
        rem = f & (((uint64_t)1 << drop) - 1);
        half = (uint64_t)1 << (drop - 1);
        f >>= drop;
        if (rem > half || (rem == half && (f & 1)))
            f++;
    }
    v = ldexp((double)f, 4 * (x.c - 64) - 56 + drop);
    return x.s ? -v : v;
}
