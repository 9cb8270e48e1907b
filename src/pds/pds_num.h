/* pds_num — exact predicates and grid arithmetic for the PDS lookups, for
 * the current numeric mode (modal: include after num/num.h).
 *
 * Region boundaries are decided with these helpers only, so each mode
 * classifies points exactly against the coordinates it compiled:
 *   pds_num_cell      floor(x * n) clamped to 0..n-1 (exact in every mode)
 *   pds_num_floordiv  floor(x / w) and the remainder in [0, w)
 *   pds_num_orient    side of a line: exact in q16, q32 and f32; in f64
 *                     exact for the double differences of the coordinates
 *   pds_wide          squared distances: in q16 the exact Q32.32 product
 *                     (a Q16.16 square of a distance of 0.01 would keep only
 *                     about 6 bits); in the other modes the mode's number */
#ifndef PDS_NUM_H
#define PDS_NUM_H
#include <math.h>
#include <stdint.h>
#include "num/num.h"

static inline long pds_num_cell(num x, long n)
{
    long c;
    if (!(x > NUM_ZERO))
        return 0;                       /* also NaN in the float modes */
    if (x >= NUM_ONE)
        return n - 1;
#if defined(NUM_MODE_q16)
    c = (long)(((int64_t)x * n) >> 16);
#elif defined(NUM_MODE_q32)
    c = (long)(((uint64_t)x * (uint64_t)n) >> 32);   /* x < 2^32, n <= 2^15 */
#else
    c = (long)(num_to_d(x) * (double)n);             /* exact for f32, hfp32; f64, hfp64 round */
#endif
    return c >= n ? n - 1 : c;
}

static inline long pds_num_floordiv(num x, num w, num *rem)
{
#if NUM_IS_FIXED
    /* Raw integer division: exact quotient and remainder. */
    num q = x / w, r = x % w;
    if (r < 0) {
        r += w;
        q -= 1;
    }
    *rem = r;
    return (long)q;
#else
    num q = num_from_d(floor(num_to_d(x) / num_to_d(w))), r = num_sub(x, num_mul(q, w));
    if (r < NUM_ZERO) { r = num_add(r, w); q = num_sub(q, NUM_ONE); }
    if (r >= w) { r = num_sub(r, w); q = num_add(q, NUM_ONE); }
    *rem = r;
    return (long)num_to_d(q);
#endif
}

#if NUM_IS_FIXED
/* Signed 64x64 -> 128-bit product as an order-preserving key pair
 * (high word with its sign bit flipped, low word). */
static inline void pds_num_mul128(int64_t a, int64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)b : (uint64_t)b;
    uint64_t a0 = ua & 0xffffffffu, a1 = ua >> 32, b0 = ub & 0xffffffffu, b1 = ub >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    uint64_t l = (p00 & 0xffffffffu) | (mid << 32);
    uint64_t h = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    if ((a < 0) != (b < 0)) {          /* two's complement negate */
        l = ~l + 1;
        h = ~h + (l == 0);
    }
    *hi = h ^ ((uint64_t)1 << 63);
    *lo = l;
}
#endif

/* Sign of (bx-ax)*(py-ay) - (by-ay)*(px-ax): which side of the line a->b
 * the point p lies on (+1 left, -1 right, 0 on it). */
static inline int pds_num_orient(num ax, num ay, num bx, num by, num px, num py)
{
#if defined(NUM_MODE_q16)
    /* Differences below 2^24 by the coordinate limits: products exact. */
    int64_t l = ((int64_t)bx - ax) * ((int64_t)py - ay), r = ((int64_t)by - ay) * ((int64_t)px - ax);
    return (l > r) - (l < r);
#elif defined(NUM_MODE_q32)
    /* Differences below 2^40: 128-bit products. */
    uint64_t lh, ll, rh, rl;
    pds_num_mul128(bx - ax, py - ay, &lh, &ll);
    pds_num_mul128(by - ay, px - ax, &rh, &rl);
    if (lh != rh)
        return lh > rh ? 1 : -1;
    return (ll > rl) - (ll < rl);
#else
    /* Kahan's a*b - c*d with fused multiply-adds has relative error below
     * 2 units of rounding, so its sign is the sign of the exact value of the
     * operands. f32, hfp32: the differences are formed exactly in double;
     * f64, hfp64: they are the rounded double differences. */
    double a = num_to_d(bx) - num_to_d(ax), b = num_to_d(py) - num_to_d(ay);
    double c = num_to_d(by) - num_to_d(ay), d = num_to_d(px) - num_to_d(ax);
    double w = c * d, e = fma(-c, d, w), x = fma(a, b, -w) + e;
    return (x > 0) - (x < 0);
#endif
}

#if defined(NUM_MODE_q16)
typedef int64_t pds_wide;
static inline pds_wide pds_wide_sq2(num dx, num dy) { return (int64_t)dx * dx + (int64_t)dy * dy; }
static inline pds_wide pds_wide_from_d(double x) { return (int64_t)floor(x * 4294967296.0 + 0.5); }
static inline pds_wide pds_wide_sub(pds_wide a, pds_wide b) { return a - b; }
#define PDS_WIDE_MAX INT64_MAX
#else
typedef num pds_wide;
static inline pds_wide pds_wide_sq2(num dx, num dy) { return num_add(num_mul(dx, dx), num_mul(dy, dy)); }
static inline pds_wide pds_wide_from_d(double x) { return num_from_d(x); }
static inline pds_wide pds_wide_sub(pds_wide a, pds_wide b) { return num_sub(a, b); }
#define PDS_WIDE_MAX NUM_MAX
#endif

/* Mosaic mortar test: diff <= mortar * sqrt(sep2), with diff = d_i^2 - d_1^2
 * (>= 0 up to rounding) and sep2 the squared distance of the two seeds. In
 * q16 both sides are squared and compared exactly in 128 bits, without a
 * square root. */
static inline int pds_wide_band(pds_wide diff, num mortar, pds_wide sep2)
{
#if defined(NUM_MODE_q16)
    uint64_t lh, ll, rh, rl;
    if (diff <= 0)
        return 1;
    pds_num_mul128(diff, diff, &lh, &ll);
    pds_num_mul128((int64_t)mortar * mortar, sep2, &rh, &rl);
    return lh != rh ? lh < rh : ll <= rl;
#else
    return diff <= num_mul(mortar, num_sqrt(sep2));
#endif
}

/* A squared radius covering d_1 + mortar, where best = d_1^2 and l1 >= d_1
 * (the L1 length of the same offset). q16 uses (d_1 + m)^2 <= best +
 * 2 m l1 + m^2, exact in Q32.32 with no square root; the other modes take
 * the root and add a few units for its rounding. */
static inline pds_wide pds_wide_reach2(pds_wide best, num mortar, num l1)
{
#if defined(NUM_MODE_q16)
    return best + 2 * (int64_t)mortar * l1 + (int64_t)mortar * mortar;
#else
    num r = num_add(num_add(num_sqrt(best), mortar), num_mul(num_from_i(4), NUM_ULP));
    (void)l1;
    return num_mul(r, r);
#endif
}

/* Closed point-in-box test; box = u0 v0 u1 v1. */
static inline int pds_num_in_box(const num *box, num u, num v)
{
    return u >= box[0] && u <= box[2] && v >= box[1] && v <= box[3];
}

/* Grows box to cover box k. */
static inline void pds_num_box_grow(num *box, const num *k)
{
    box[0] = num_min(box[0], k[0]);
    box[1] = num_min(box[1], k[1]);
    box[2] = num_max(box[2], k[2]);
    box[3] = num_max(box[3], k[3]);
}

/* Edge a->b against the point p: 2 if p lies on the closed edge; 1 if the
 * half-line from p towards +u crosses the edge (an endpoint counts as above
 * the line when its v > p's v, so a vertex on the line is counted once);
 * else 0. */
static inline int pds_num_edge(num ax, num ay, num bx, num by, num px, num py)
{
    int s;
    if ((py < ay && py < by) || (py > ay && py > by) || (px > ax && px > bx))
        return 0;
    s = pds_num_orient(ax, ay, bx, by, px, py);
    if (s == 0 && (px >= ax || px >= bx))
        return 2;
    if ((ay > py) != (by > py))
        return by > ay ? s > 0 : s < 0;
    return 0;
}
#endif
