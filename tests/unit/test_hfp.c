/* test_hfp — System/370 hexadecimal floating point (src/num/hfp.c) against
 * (1) vectors derived by hand from the Principles of Operation rules, the
 * derivation beside each, and (2) a second implementation written here in
 * a different way, on seeded random operands.
 *
 * The reference works on exact values, not on digit shifts: a number is
 * m * 2^e in 128-bit integers, and every result is "the exact value (of
 * the operation the PoO defines), normalised in base 16 and truncated to
 * nd digits", found from the bit length of m. Quotients come from one
 * 128-bit division, square roots from a long double estimate corrected
 * with exact squares, the two load-rounded operations and the IEEE
 * conversions from long double arithmetic. hfp.c instead shifts hex digits
 * and develops quotients and roots one bit per step in 64-bit words.
 *
 * MAPRT_HFP_N sets the random operands per operation (default 100000);
 * `MAPRT_HFP_N=1000000 build/tests/test_hfp` is the full check
 * (docs/numerics.md). MAPRT_SEED replays a run. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "num/hfp.h"
#include "num/hfp_data.h"
#include "support.h"
#include "hfp_test.h"

__extension__ typedef unsigned __int128 ref_u128;
__extension__ typedef __int128 ref_i128;

/* ---- the reference ------------------------------------------------------- */

typedef struct ref_val {
    int s;          /* sign */
    ref_u128 m;     /* |value| = m * 2^e */
    int e;
} ref_val;

static int ref_floordiv4(int n) { return n >= 0 ? n / 4 : -((-n + 3) / 4); }

static int ref_bitlen(ref_u128 m)
{
    int n = 0;
    while (m) {
        m >>= 1;
        n++;
    }
    return n;
}

static ref_val ref_decode(uint64_t a, int nd)
{
    ref_val v;
    int fb = 4 * nd, c = (int)(a >> fb) & 0x7f;
    v.s = (int)(a >> (fb + 7)) & 1;
    v.m = a & (((uint64_t)1 << fb) - 1);
    v.e = 4 * (c - 64) - fb;
    return v;
}

static uint64_t ref_max(int s, int nd)
{
    return ((uint64_t)s << (4 * nd + 7)) | (((uint64_t)1 << (4 * nd + 7)) - 1);
}

/* The nd-digit HFP number of the exact nonzero value v (or of any value in
 * [m, m+1) * 2^e, which truncates the same): 16^(X-1) <= |v| < 16^X, the
 * fraction floor(|v| / 16^(X-nd)) (or nearest, if round), characteristic
 * X + 64. */
static uint64_t ref_hex(ref_val v, int nd, int round, unsigned long *exc)
{
    int len = ref_bitlen(v.m), x = -ref_floordiv4(-(len + v.e)), sh = 4 * x - 4 * nd - v.e;
    uint64_t f = (uint64_t)(sh >= 0 ? v.m >> sh : v.m << -sh);
    /* Rounding to nearest: the first bit below the last digit. The callers
     * that round (square root) never have a value exactly halfway. */
    if (round && sh > 0 && (uint64_t)(v.m >> (sh - 1)) & 1) {
        if (++f >> (4 * nd)) {
            f >>= 4;
            x++;
        }
    }
    if (x + 64 > 127) {
        exc[HFP_EXC_OVERFLOW]++;
        return ref_max(v.s, nd);
    }
    if (x + 64 < 0) {
        exc[HFP_EXC_UNDERFLOW]++;
        return 0;
    }
    return ((uint64_t)v.s << (4 * nd + 7)) | ((uint64_t)(x + 64) << (4 * nd)) | f;
}

/* Add: in units of the guard digit of the larger characteristic, the
 * operand of larger characteristic is exact and the other is truncated
 * toward zero; their exact sum is then normalised and truncated. */
static uint64_t ref_add(uint64_t a, uint64_t b, int negb, int nd, unsigned long *exc)
{
    ref_val x = ref_decode(a, nd), y = ref_decode(b, nd), r;
    int ge = (x.e > y.e ? x.e : y.e) - 4;
    ref_i128 sx, sy, sum;
    ref_u128 mx = x.e - ge >= 0 ? x.m << (x.e - ge) : (ge - x.e >= 128 ? 0 : x.m >> (ge - x.e));
    ref_u128 my = y.e - ge >= 0 ? y.m << (y.e - ge) : (ge - y.e >= 128 ? 0 : y.m >> (ge - y.e));
    y.s ^= negb;
    sx = x.s ? -(ref_i128)mx : (ref_i128)mx;
    sy = y.s ? -(ref_i128)my : (ref_i128)my;
    sum = sx + sy;
    if (sum == 0) {
        exc[HFP_EXC_SIGNIFICANCE]++;
        return 0;
    }
    r.s = sum < 0;
    r.m = (ref_u128)(sum < 0 ? -sum : sum);
    r.e = ge;
    return ref_hex(r, nd, 0, exc);
}

/* Exact value order; every zero fraction is equal to every other. */
static int ref_cmp(uint64_t a, uint64_t b, int nd)
{
    ref_val x = ref_decode(a, nd), y = ref_decode(b, nd);
    int sx = x.m ? (x.s ? -1 : 1) : 0, sy = y.m ? (y.s ? -1 : 1) : 0, mag, lx, ly;
    if (sx != sy)
        return sx < sy ? -1 : 1;
    if (!sx)
        return 0;
    lx = ref_bitlen(x.m) + x.e;
    ly = ref_bitlen(y.m) + y.e;
    if (lx != ly)
        mag = lx > ly ? 1 : -1;
    else {
        ref_u128 ax = x.e >= y.e ? x.m << (x.e - y.e) : x.m, ay = y.e > x.e ? y.m << (y.e - x.e) : y.m;
        mag = ax == ay ? 0 : ax > ay ? 1 : -1;
    }
    return sx * mag;
}

/* Multiply: the exact product, normalised and truncated to 14 digits. */
static uint64_t ref_mul(uint64_t a, uint64_t b, int nd, unsigned long *exc)
{
    ref_val x = ref_decode(a, nd), y = ref_decode(b, nd), r;
    if (!x.m || !y.m)
        return 0;
    r.s = x.s ^ y.s;
    r.m = x.m * y.m;
    r.e = x.e + y.e;
    return ref_hex(r, 14, 0, exc);
}

/* Divide: floor(mx * 2^64 / my) carries more than enough quotient bits. */
static uint64_t ref_div(uint64_t a, uint64_t b, int nd, unsigned long *exc)
{
    ref_val x = ref_decode(a, nd), y = ref_decode(b, nd), r;
    r.s = x.s ^ y.s;
    if (!y.m) {
        exc[HFP_EXC_DIVIDE]++;
        return x.m ? ref_max(r.s, nd) : 0;
    }
    if (!x.m)
        return 0;
    r.m = (x.m << 64) / y.m;
    r.e = x.e - y.e - 64;
    return ref_hex(r, nd, 0, exc);
}

/* Square root, rounded to nearest: the radicand scaled to about 2^124 with
 * an even exponent; a long double root, made exactly floor(sqrt) with
 * integer squares, then rounded at the last digit. */
static uint64_t ref_sqrt(uint64_t a, int nd, unsigned long *exc)
{
    ref_val x = ref_decode(a, nd), r;
    ref_u128 n, q;
    int k;
    if (!x.m)
        return 0;
    if (x.s) {
        exc[HFP_EXC_SQRT]++;
        return 0;
    }
    if (x.e & 1) {
        x.m <<= 1;
        x.e -= 1;
    }
    k = (124 - ref_bitlen(x.m)) / 2;
    n = x.m << (2 * k);
    q = (ref_u128)sqrtl((long double)n);
    while (q * q > n)
        q--;
    while ((q + 1) * (q + 1) <= n)
        q++;
    r.s = 0;
    r.m = q;
    r.e = (x.e - 2 * k) / 2;
    return ref_hex(r, nd, 1, exc);
}

static uint64_t ref_halve(uint64_t a, int nd, unsigned long *exc)
{
    ref_val x = ref_decode(a, nd);
    if (!x.m)
        return 0;
    x.e -= 1;
    return ref_hex(x, nd, 0, exc);
}

/* LRER in long double: |fraction| / 2^32 + 1/2, floored, is exact. */
static uint64_t ref_lrer(uint64_t a, unsigned long *exc)
{
    int s = (int)(a >> 63), c = (int)(a >> 56) & 0x7f;
    long double f = floorl(ldexpl((long double)(a & 0x00ffffffffffffffu), -32) + 0.5L);
    if (f == 16777216.0L) {
        f = 1048576.0L;
        if (++c > 127) {
            exc[HFP_EXC_OVERFLOW]++;
            return ref_max(s, 6);
        }
    }
    return ((uint64_t)s << 31) | ((uint64_t)c << 24) | (uint64_t)f;
}

/* LRDR on the 28-digit extended fraction in 128 bits. */
static uint64_t ref_lrdr(uint64_t hi, uint64_t lo, unsigned long *exc)
{
    int s = (int)(hi >> 63), c = (int)(hi >> 56) & 0x7f;
    ref_u128 full = ((ref_u128)(hi & 0x00ffffffffffffffu) << 56) | (lo & 0x00ffffffffffffffu);
    uint64_t f = (uint64_t)((full + ((ref_u128)1 << 55)) >> 56);
    if (f >> 56) {
        f >>= 4;
        if (++c > 127) {
            exc[HFP_EXC_OVERFLOW]++;
            return ref_max(s, 14);
        }
    }
    return ((uint64_t)s << 63) | ((uint64_t)c << 56) | f;
}

static long double ref_value(uint64_t a, int nd)
{
    ref_val v = ref_decode(a, nd);
    long double x = ldexpl((long double)(uint64_t)v.m, v.e);
    return v.s ? -x : x;
}

static uint64_t ref_from_i32(int32_t i, int nd, unsigned long *exc)
{
    ref_val v;
    if (!i)
        return 0;
    v.s = i < 0;
    v.m = (ref_u128)(i < 0 ? -(int64_t)i : (int64_t)i);
    v.e = 0;
    return ref_hex(v, nd, 0, exc);
}

static int32_t ref_to_i32(uint64_t a, int nd, unsigned long *exc)
{
    long double t = truncl(ref_value(a, nd));
    if (t > 2147483647.0L || t < -2147483648.0L) {
        exc[HFP_EXC_CONVERT]++;
        return t > 0 ? INT32_MAX : INT32_MIN;
    }
    return (int32_t)t;
}

static uint64_t ref_long_from_double(double d, unsigned long *exc)
{
    ref_val v;
    int k;
    double m = frexp(fabs(d), &k);
    if (d == 0)
        return 0;
    v.s = signbit(d) != 0;
    v.m = (ref_u128)(uint64_t)ldexp(m, 53);
    v.e = k - 53;
    return ref_hex(v, 14, 0, exc);
}

/* Nearest short number, ties away from zero, in long double; values below
 * 16^-65 underflow (they do as long numbers already). */
static uint64_t ref_short_from_double(double d, unsigned long *exc)
{
    long double a = fabsl((long double)d), f;
    int s = signbit(d) != 0, k, x;
    if (d == 0)
        return 0;
    frexpl(a, &k);
    x = -ref_floordiv4(-k);                 /* 16^(x-1) <= a < 16^x */
    if (x + 64 < 0) {
        exc[HFP_EXC_UNDERFLOW]++;
        return 0;
    }
    f = floorl(ldexpl(a, 24 - 4 * x) + 0.5L);
    if (f == 16777216.0L) {
        f = 1048576.0L;
        x++;
    }
    if (x + 64 > 127) {
        exc[HFP_EXC_OVERFLOW]++;
        return ref_max(s, 6);
    }
    return ((uint64_t)s << 31) | ((uint64_t)(x + 64) << 24) | (uint64_t)f;
}

static long hfp_n(void) { return hfp_test_count("MAPRT_HFP_N", 100000); }

/* ---- checks -------------------------------------------------------------- */

static int exc_same(const unsigned long *before, const unsigned long *want)
{
    int k;
    for (k = 0; k < HFP_EXC_N; k++)
        if (hfp_exc[k] - before[k] != want[k])
            return 0;
    return 1;
}

enum op { OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_SQRT, OP_HALVE, OP_CMP, OP_ROUND, OP_FROM_I, OP_TO_I,
          OP_FROM_D, OP_TO_D, OP_N };
static const char *const op_name[2][OP_N] = {
    {"AE", "SE", "ME", "DE", "SQE", "HER", "CE/key", "LRER", "from_i32", "to_i32", "from_double", "to_double"},
    {"AD", "SD", "MD", "DD", "SQD", "HDR", "CD/key", "LRDR", "from_i32", "to_i32", "from_double", "to_double"},
};

/* One random case of op in format nd (6 or 14): 1 if hfp.c and the
 * reference agree on the result and on every exception count. */
static int check_one(uint64_t *st, enum op op, int nd, uint64_t *shown_a, uint64_t *shown_b)
{
    unsigned long before[HFP_EXC_N], want[HFP_EXC_N] = {0};
    uint64_t a = hfp_test_image(st, nd), b = hfp_test_second(st, a, nd), got = 0, ref = 0;
    int lng = nd == 14;
    double d;
    int32_t i;
    memcpy(before, hfp_exc, sizeof before);
    *shown_a = a;
    *shown_b = b;
    switch (op) {
    case OP_ADD:
        got = lng ? hfp_ad(a, b) : hfp_ae((hfp_short)a, (hfp_short)b);
        ref = ref_add(a, b, 0, nd, want);
        break;
    case OP_SUB:
        got = lng ? hfp_sd(a, b) : hfp_se((hfp_short)a, (hfp_short)b);
        ref = ref_add(a, b, 1, nd, want);
        break;
    case OP_MUL:
        got = lng ? hfp_md(a, b) : hfp_me((hfp_short)a, (hfp_short)b);
        ref = ref_mul(a, b, nd, want);
        break;
    case OP_DIV:
        if ((test_rand(st) & 63) == 0)
            b = 0;
        *shown_b = b;
        got = lng ? hfp_dd(a, b) : hfp_de((hfp_short)a, (hfp_short)b);
        ref = ref_div(a, b, nd, want);
        break;
    case OP_SQRT:
        got = lng ? hfp_sqd(a) : hfp_sqe((hfp_short)a);
        ref = ref_sqrt(a, nd, want);
        break;
    case OP_HALVE:
        got = lng ? hfp_hdr(a) : hfp_her((hfp_short)a);
        ref = ref_halve(a, nd, want);
        break;
    case OP_CMP: {
        /* CE/CD as defined (a subtraction with guard digit), and the order
         * of the keys num_hfp32.h/num_hfp64.h compare with <, against the
         * exact order of the values. */
        int c = lng ? hfp_cd(a, b) : hfp_ce((hfp_short)a, (hfp_short)b), r = ref_cmp(a, b, nd);
        int64_t ka = (a >> (4 * nd + 7)) ? -(int64_t)(a & (((uint64_t)1 << (4 * nd + 7)) - 1)) : (int64_t)a;
        int64_t kb = (b >> (4 * nd + 7)) ? -(int64_t)(b & (((uint64_t)1 << (4 * nd + 7)) - 1)) : (int64_t)b;
        got = (uint64_t)(c + 1) * 3 + (uint64_t)((ka > kb) - (ka < kb) + 1);
        ref = (uint64_t)(r + 1) * 4;
        break;
    }
    case OP_ROUND:
        if (lng) {
            got = hfp_lrdr(a, b);
            ref = ref_lrdr(a, b, want);
        } else {
            a = hfp_test_image(st, 14);
            *shown_a = a;
            got = hfp_lrer(a);
            ref = ref_lrer(a, want);
        }
        break;
    case OP_FROM_I:
        i = (int32_t)(uint32_t)(test_rand(st) >> (test_rand(st) % 33));
        *shown_a = (uint64_t)(uint32_t)i;
        got = lng ? hfp_long_from_i32(i) : hfp_short_from_i32(i);
        ref = ref_from_i32(i, nd, want);
        break;
    case OP_TO_I:
        if ((test_rand(st) & 1)) {         /* characteristics where integers live */
            a = (a & ~((uint64_t)0x7f << (4 * nd))) | ((uint64_t)(64 + test_rand(st) % 10) << (4 * nd));
            *shown_a = a;
        }
        got = (uint64_t)(uint32_t)(lng ? hfp_long_to_i32(a) : hfp_short_to_i32((hfp_short)a));
        ref = (uint64_t)(uint32_t)ref_to_i32(a, nd, want);
        break;
    case OP_FROM_D: {
        uint64_t bits = test_rand(st);
        if (bits & 1)                       /* exponents of the HFP range and a little beyond */
            bits = (bits & 0x800fffffffffffffu) | ((uint64_t)(1023 - 270 + test_rand(st) % 530) << 52);
        memcpy(&d, &bits, sizeof d);
        if (d != d || isinf(d))
            d = 1.5;
        *shown_a = bits;
        got = lng ? hfp_long_from_double(d) : hfp_short_from_double(d);
        ref = lng ? ref_long_from_double(d, want) : ref_short_from_double(d, want);
        break;
    }
    case OP_TO_D:
        d = lng ? hfp_long_to_double(a) : hfp_short_to_double((hfp_short)a);
        memcpy(&got, &d, sizeof got);
        d = (double)ref_value(a, nd);
        memcpy(&ref, &d, sizeof ref);
        break;
    default:
        break;
    }
    return got == ref && exc_same(before, want);
}

static void check_random(const char *test, int nd)
{
    uint64_t s = test_seed(test);
    long n = hfp_n(), k, bad[OP_N] = {0};
    int op, total = 0;
    if (!test_long_double_ok()) {
        printf("# %s: SKIPPED, long double arithmetic has fewer than 64 bits here "
               "(the reference needs 64; valgrind emulates 53)\n", test);
        return;
    }
    for (op = 0; op < OP_N; op++) {
        for (k = 0; k < n; k++) {
            uint64_t a, b;
            if (!check_one(&s, (enum op)op, nd, &a, &b)) {
                if (bad[op]++ < 3)
                    printf("# %s %s mismatch: a=%016llx b=%016llx\n", test, op_name[nd == 14][op],
                           (unsigned long long)a, (unsigned long long)b);
            }
        }
        printf("# %s %-11s %ld random operands, %ld mismatches\n", nd == 14 ? "long " : "short",
               op_name[nd == 14][op], n, bad[op]);
        total += bad[op] != 0;
    }
    assert_int_equal(total, 0);
}

static void test_hfp_short_random(void **state)
{
    (void)state;
    check_random("test_hfp_short_random", 6);
}

static void test_hfp_long_random(void **state)
{
    (void)state;
    check_random("test_hfp_long_random", 14);
}

/* ---- vectors derived by hand from the PoO rules -------------------------- */

/* Evaluates expr with the exception counters watched: the result must be
 * want, with exactly one count of kind exc (or none for -1). */
static void vec_check(const char *what, uint64_t got, uint64_t want, int exc, const unsigned long *before)
{
    int k;
    if (got != want)
        fail_msg("%s: got %016llx, want %016llx", what, (unsigned long long)got, (unsigned long long)want);
    for (k = 0; k < HFP_EXC_N; k++) {
        unsigned long d = hfp_exc[k] - before[k];
        if (d != (unsigned long)(k == exc))
            fail_msg("%s: exception %s counted %lu times", what, hfp_exc_name[k], d);
    }
}
#define EV(expr, want, exc) do { \
        uint64_t got_; \
        memcpy(before, hfp_exc, sizeof before); \
        got_ = (uint64_t)(expr); \
        vec_check(#expr, got_, want, exc, before); \
    } while (0)

static void test_hfp_vectors(void **state)
{
    unsigned long before[HFP_EXC_N];
    (void)state;
    {
            /* 1 + 1: equal characteristics, fractions 100000 + 100000 = 200000. */
            EV(hfp_ae(0x41100000, 0x41100000), 0x41200000, -1);
            /* 8 + 8: 800000 + 800000 = 1000000 carries: the fraction moves
             * right one digit (100000) and the characteristic goes to 42. */
            EV(hfp_ae(0x41800000, 0x41800000), 0x42100000, -1);
            /* The guard digit: 1 - 0.FFFFFF. The smaller operand moves right
             * one digit, 0FFFFF with F kept in the guard: 100000.0 -
             * 0FFFFF.F = 000000.1; normalising shifts six digits left, the
             * guard digit first: 100000, characteristic 41 - 6 = 3B. The
             * exact 16^-6; without the guard digit it would be 16^-5. */
            EV(hfp_se(0x41100000, 0x40FFFFFF), 0x3B100000, -1);
            /* Digits beyond the guard are lost: 1 + 0.100001 x 16^-1 aligns
             * the second two digits right: 001000, guard 0, the final 1
             * lost. Sum 101000. */
            EV(hfp_ae(0x41100000, 0x3F100001), 0x41101000, -1);
            /* x - x: zero fraction, a significance exception; with the mask
             * off the result is a true zero. */
            EV(hfp_se(0x41100000, 0x41100000), 0x00000000, HFP_EXC_SIGNIFICANCE);
            /* 1 - 2: the larger magnitude gives the sign: C1100000. */
            EV(hfp_se(0x41100000, 0x41200000), 0xC1100000, -1);
            /* Largest + largest: FFFFFF + FFFFFF carries, characteristic 128:
             * exponent overflow, fixed up to the largest number. */
            EV(hfp_ae(0x7FFFFFFF, 0x7FFFFFFF), 0x7FFFFFFF, HFP_EXC_OVERFLOW);
            /* 100001 - 100000 = 000001 at characteristic 00: normalising
             * needs five left shifts, characteristic -5: underflow, true zero. */
            EV(hfp_se(0x00100001, 0x00100000), 0x00000000, HFP_EXC_UNDERFLOW);
            /* 2 x 3: 200000 x 300000 = 060000000000 (12 digits), one leading
             * zero: shift left, characteristic 41 + 41 - 40 - 1 = 41. The
             * long product keeps all 14 digits: 4160000000000000. */
            EV(hfp_me(0x41200000, 0x41300000), 0x4160000000000000u, -1);
            /* FFFFFF^2 = FFFFFE000001 exactly, no leading zero: the long
             * product 42FFFFFE00000100; its leading word 42FFFFFE truncates. */
            EV(hfp_me(0x41FFFFFF, 0x41FFFFFF), 0x42FFFFFE00000100u, -1);
            EV(hfp_me_short(0x41FFFFFF, 0x41FFFFFF), 0x42FFFFFE, -1);
            /* 1/3: dividend fraction below the divisor's, quotient
             * floor(2^24/3) = 555555, characteristic 41 - 41 + 40. */
            EV(hfp_de(0x41100000, 0x41300000), 0x40555555, -1);
            /* 2/3 = 0.AAAAAA|AA...: truncated to AAAAAA (rounding would give
             * AAAAAB). */
            EV(hfp_de(0x41200000, 0x41300000), 0x40AAAAAA, -1);
            /* 3/2: dividend fraction >= divisor's, so one digit right and
             * characteristic + 1: 0.18 x 16^1 = 1.5. */
            EV(hfp_de(0x41300000, 0x41200000), 0x41180000, -1);
            /* Division by a zero fraction: divide exception. */
            EV(hfp_de(0x41100000, 0x00000000), 0x7FFFFFFF, HFP_EXC_DIVIDE);
            EV(hfp_de(0xC1100000, 0x00000000), 0xFFFFFFFF, HFP_EXC_DIVIDE);
            EV(hfp_de(0x00000000, 0x00000000), 0x00000000, HFP_EXC_DIVIDE);
            /* sqrt 4: 0.4 x 16^1, odd exponent: sqrt(0.4/16) x 16^1 = 0.2 x
             * 16^1 = 2. */
            EV(hfp_sqe(0x41400000), 0x41200000, -1);
            /* sqrt 3 = 1.BB67AE|8584CAA73B...: the short root rounds up at
             * the 8 (411BB67B), the long one keeps ...CAA at the 7. */
            EV(hfp_sqe(0x41300000), 0x411BB67B, -1);
            /* sqrt(16^-2): exponent -1, odd: sqrt(0.1/16) x 16^0 = 0.1: 40100000. */
            EV(hfp_sqe(0x3F100000), 0x40100000, -1);
            EV(hfp_sqe(0xC1100000), 0x00000000, HFP_EXC_SQRT);
            /* Halve 1: 100000 >> 1 = 080000 with a leading zero digit:
             * normalised to 800000 at characteristic 40. */
            EV(hfp_her(0x41100000), 0x40800000, -1);
            /* Halve 3: 300000 >> 1 = 180000, already normalised. */
            EV(hfp_her(0x41300000), 0x41180000, -1);
            /* Halve FFFFFF: 7FFFFF, the bit shifted out lost with the guard. */
            EV(hfp_her(0x41FFFFFF), 0x417FFFFF, -1);
            /* Halve 000001 (unnormalised): the bit goes to the guard digit and
             * normalisation brings it back: 800000, characteristic 41 - 6. */
            EV(hfp_her(0x41000001), 0x3B800000, -1);
            /* Halve the smallest normalised number: characteristic -1. */
            EV(hfp_her(0x00100000), 0x00000000, HFP_EXC_UNDERFLOW);
            /* LRER: add one at bit 32 (the leftmost dropped bit) and truncate.
             * Bit 32 clear: no change; set: +1; FFFFFF + 1 carries: fraction
             * right one digit, characteristic + 1; at 7F that overflows. */
            EV(hfp_lrer(0x4110000070000000u), 0x41100000, -1);
            EV(hfp_lrer(0x4110000080000000u), 0x41100001, -1);
            EV(hfp_lrer(0x41FFFFFF80000000u), 0x42100000, -1);
            EV(hfp_lrer(0x7FFFFFFF80000000u), 0x7FFFFFFF, HFP_EXC_OVERFLOW);
            /* LRDR: the leftmost bit of the low part's fraction (bit 8). */
            EV(hfp_lrdr(0x4110000000000000u, 0x3380000000000000u), 0x4110000000000001u, -1);
            EV(hfp_lrdr(0x4110000000000000u, 0x337FFFFFFFFFFFFFu), 0x4110000000000000u, -1);
            /* MD: (1 - 16^-14)^2 = 1 - 2 x 16^-14 + 16^-28: fraction
             * FFFFFFFFFFFFFE|00000000000001, truncated. */
            EV(hfp_md(0x40FFFFFFFFFFFFFFu, 0x40FFFFFFFFFFFFFFu), 0x40FFFFFFFFFFFFFEu, -1);
            EV(hfp_sqd(0x4130000000000000u), 0x411BB67AE8584CAAu, -1);
            /* 1/3 long: floor(2^56 / 3) = 55555555555555. */
            EV(hfp_dd(0x4110000000000000u, 0x4130000000000000u), 0x4055555555555555u, -1);
            /* AD carry: 8 + 8, 80000000000000 + 80000000000000 carries: 16. */
            EV(hfp_ad(0x4180000000000000u, 0x4180000000000000u), 0x4210000000000000u, -1);
            /* AD guard digit: 1 - (1 - 16^-14) = 16^-14: 0x33100000000000. */
            EV(hfp_sd(0x4110000000000000u, 0x40FFFFFFFFFFFFFFu), 0x3310000000000000u, -1);
            /* Integers: X'4E000000 nnnnnnnn' normalised. 1 = 0.1 x 16^1;
             * -2^31 = -0.8 x 16^8; 2^31 - 1 = 7FFFFFFF: its short form keeps
             * six digits, 487FFFFF (truncated). */
            EV(hfp_long_from_i32(1), 0x4110000000000000u, -1);
            EV(hfp_long_from_i32(INT32_MIN), 0xC880000000000000u, -1);
            EV(hfp_short_from_i32(INT32_MAX), 0x487FFFFF, -1);
            /* -118.625 (the usual HFP example, -0.76A x 16^2) to integer:
             * truncation toward zero. */
            EV((uint32_t)hfp_short_to_i32(0xC276A000), (uint32_t)-118, -1);
            EV((uint32_t)hfp_short_to_i32(0x487FFFFF), 0x7FFFFF00u, -1);
            EV((uint32_t)hfp_short_to_i32(0x48800000), 0x7FFFFFFFu, HFP_EXC_CONVERT);
            EV((uint32_t)hfp_short_to_i32(0xC8800000), 0x80000000u, -1);
            /* 0.1 = 1.999999999999A p-4 as a double: 0.1999999999999A x 16^0
             * exactly as a long number; short: 199999|9999999A rounds up
             * (bit 32 set) to 4019999A, the familiar short 0.1. */
            EV(hfp_long_from_double(0.1), 0x401999999999999Au, -1);
            EV(hfp_short_from_double(0.1), 0x4019999A, -1);
            EV(hfp_short_from_double(-118.625), 0xC276A000, -1);
            EV(hfp_short_from_double(1e76), 0x7FFFFFFF, HFP_EXC_OVERFLOW);
            EV(hfp_short_from_double(-1e-80), 0x00000000, HFP_EXC_UNDERFLOW);
            EV(hfp_long_from_double(NAN), 0x00000000, HFP_EXC_CONVERT);
    }
    /* Compare: "numbers with zero fraction compare equal"; 1 > 0.FFFFFF. */
    assert_int_equal(hfp_ce(0x00000000, 0x80000000), 0);
    assert_int_equal(hfp_ce(0x41100000, 0x40FFFFFF), 1);
    assert_int_equal(hfp_cd(0xC110000000000000u, 0x4110000000000000u), -1);
    /* The range ends: (1 - 16^-6) x 16^63 and 16^-65. */
    assert_true(hfp_short_to_double(0x7FFFFFFF) == ldexp(1.0 - ldexp(1.0, -24), 252));
    assert_true(hfp_short_to_double(0x00100000) == ldexp(1.0, -260));
    /* Long to double, 56 bits to 53: 80000000000004 drops 100 (binary), a tie,
     * to even (8.0); 8000000000000C also ties, and rounds up to even. */
    assert_true(hfp_long_to_double(0x4180000000000004u) == 8.0);
    assert_true(hfp_long_to_double(0x418000000000000Cu) == 8.0 + ldexp(2.0, -49));
}

/* ---- fields in data ------------------------------------------------------ */

static void test_hfp_data_fields(void **state)
{
    static const unsigned char m118[4] = {0xC2, 0x76, 0xA0, 0x00}, one[8] = {0x41, 0x10};
    static const unsigned char tenth4[4] = {0x40, 0x19, 0x99, 0x9A};
    static const unsigned char tenth8[8] = {0x40, 0x19, 0x99, 0x99, 0x99, 0x99, 0x99, 0x9A};
    unsigned char b[8];
    double x;
    diag err;
    char msg[600];
    (void)state;
    diag_init(&err);
    assert_int_equal(hfp_data_decode(m118, 4, &x, "f", 0, &err), 0);
    assert_true(x == -118.625);
    assert_int_equal(hfp_data_decode(one, 8, &x, "f", 0, &err), 0);
    assert_true(x == 1.0);
    assert_int_equal(hfp_data_encode(0.1, 4, b, "f", 0, &err), 0);
    assert_memory_equal(b, tenth4, 4);
    assert_int_equal(hfp_data_encode(0.1, 8, b, "f", 0, &err), 0);
    assert_memory_equal(b, tenth8, 8);
    /* Refusals name the limit and the offset and write nothing. */
    memset(b, 0x55, sizeof b);
    assert_int_equal(hfp_data_encode(1e76, 4, b, "deck.bin", 12, &err), DIAG_INPUT);
    diag_format(&err, msg, sizeof msg);
    assert_non_null(strstr(msg, "deck.bin: offset 12"));
    assert_non_null(strstr(msg, "7.2e75"));
    assert_int_equal(b[0], 0x55);
    diag_init(&err);
    assert_int_equal(hfp_data_encode(-1e-80, 8, b, "f", 0, &err), DIAG_INPUT);
    diag_init(&err);
    assert_int_equal(hfp_data_encode(NAN, 8, b, "f", 0, &err), DIAG_INPUT);
    diag_init(&err);
    assert_int_equal(hfp_data_decode(b, 5, &x, "f", 3, &err), DIAG_INPUT);
    assert_int_equal(b[0], 0x55);
}

/* Round trips on random values: doubles through long fields are exact;
 * short fields through doubles are exact; doubles through short fields
 * land within half a unit of the sixth digit; long fields through doubles
 * within half a unit of the 53rd bit. */
static void test_hfp_data_round_trips(void **state)
{
    uint64_t s = test_seed("test_hfp_data_round_trips");
    long n = hfp_n(), k;
    diag err;
    (void)state;
    if (!test_long_double_ok()) {
        printf("# test_hfp_data_round_trips: SKIPPED, long double has fewer than 64 bits here\n");
        return;
    }
    diag_init(&err);
    for (k = 0; k < n; k++) {
        unsigned char b[8];
        double x = ldexp(test_uniform(&s, -1, 1), (int)(test_rand(&s) % 480) - 240), y;
        uint64_t img = hfp_test_image(&s, 14), back;
        int e, i;
        if (x == 0)
            continue;
        assert_int_equal(hfp_data_encode(x, 8, b, "f", 0, &err), 0);
        assert_int_equal(hfp_data_decode(b, 8, &y, "f", 0, &err), 0);
        assert_true(x == y);
        assert_int_equal(hfp_data_encode(x, 4, b, "f", 0, &err), 0);
        assert_int_equal(hfp_data_decode(b, 4, &y, "f", 0, &err), 0);
        frexp(x, &e);
        e = -ref_floordiv4(-e);                 /* 16^(e-1) <= |x| < 16^e */
        assert_true(fabsl((long double)x - y) <= ldexpl(1.0L, 4 * e - 25));
        assert_int_equal(hfp_data_encode(y, 4, b, "f", 0, &err), 0);
        back = (uint64_t)b[0] << 24 | (uint64_t)b[1] << 16 | (uint64_t)b[2] << 8 | b[3];
        assert_true(back == hfp_short_from_double(y));
        for (i = 0; i < 8; i++)
            b[i] = (unsigned char)(img >> (56 - 8 * i));
        assert_int_equal(hfp_data_decode(b, 8, &y, "f", 0, &err), 0);
        if (img)
            assert_true(fabsl(ref_value(img, 14) - y) <= ldexpl(fabsl(ref_value(img, 14)), -53));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hfp_vectors),
        cmocka_unit_test(test_hfp_short_random),
        cmocka_unit_test(test_hfp_long_random),
        cmocka_unit_test(test_hfp_data_fields),
        cmocka_unit_test(test_hfp_data_round_trips),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
