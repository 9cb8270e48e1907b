/* vec — 3-vectors and 3x3 matrices of `num` for the modal geometry code.
 * Small transparent value types; every operation goes through num_* so the
 * fixed-point modes saturate and count overflows instead of wrapping
 * (except q16's bounding-sphere test, whose exact 64-bit intermediates
 * cannot overflow: see vec3_sphere_miss).
 * Included only by files compiled per numeric mode. */
#ifndef GEOM_VEC_H
#define GEOM_VEC_H
#include "num/num.h"
#include "geom/geom.h"

/* The per-ray helpers below are small but called from several places; GCC
 * and Clang would otherwise keep some out of line on the hot path. */
#if defined(__GNUC__)
#define VEC_HOT static inline __attribute__((always_inline))
#else
#define VEC_HOT static inline
#endif

typedef struct vec3 { num x, y, z; } vec3;
typedef struct mat3 { num m[9]; } mat3;      /* row-major */

static inline vec3 vec3_make(num x, num y, num z) { vec3 v; v.x = x; v.y = y; v.z = z; return v; }
static inline vec3 vec3_from_d(const double *d) { return vec3_make(num_from_d(d[0]), num_from_d(d[1]), num_from_d(d[2])); }
VEC_HOT vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(num_add(a.x, b.x), num_add(a.y, b.y), num_add(a.z, b.z)); }
VEC_HOT vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(num_sub(a.x, b.x), num_sub(a.y, b.y), num_sub(a.z, b.z)); }
static inline vec3 vec3_neg(vec3 a) { return vec3_make(num_neg(a.x), num_neg(a.y), num_neg(a.z)); }
VEC_HOT vec3 vec3_scale(vec3 a, num s) { return vec3_make(num_mul(a.x, s), num_mul(a.y, s), num_mul(a.z, s)); }
static inline vec3 vec3_div(vec3 a, num s) { return vec3_make(num_div(a.x, s), num_div(a.y, s), num_div(a.z, s)); }
/* a + t*d: a point along a ray. */
VEC_HOT vec3 vec3_madd(vec3 a, num t, vec3 d) { return vec3_add(a, vec3_scale(d, t)); }
/* q16: the three Q32 products summed at 2^-34 resolution (each below 2^62,
 * so a quarter of each sums below 2^62; truncated toward zero, so a dot
 * with -b is exactly minus the dot with b) and rounded once to Q16: one
 * saturation check instead of five, and one rounding instead of three.
 * Other modes: term by term. */
VEC_HOT num vec3_dot(vec3 a, vec3 b)
{
#if defined(NUM_MODE_q16)
    int64_t s = (int64_t)a.x * b.x / 4 + (int64_t)a.y * b.y / 4 + (int64_t)a.z * b.z / 4;
    return fx16_sat(fx_shr_round(s, 14));
#else
    return num_add(num_add(num_mul(a.x, b.x), num_mul(a.y, b.y)), num_mul(a.z, b.z));
#endif
}
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return vec3_make(num_sub(num_mul(a.y, b.z), num_mul(a.z, b.y)),
                     num_sub(num_mul(a.z, b.x), num_mul(a.x, b.z)),
                     num_sub(num_mul(a.x, b.y), num_mul(a.y, b.x)));
}
static inline num vec3_maxabs(vec3 a) { return num_max(num_abs(a.x), num_max(num_abs(a.y), num_abs(a.z))); }

/* Unit vector along v, its length and the reciprocal of its length (each
 * output may be NULL). Returns 0, or -1 (outputs untouched) for v = 0.
 * Nothing overflows and nothing is divided:
 *   q16: the sum of squares S of v's raw components is formed exactly
 *        (each square below 2^62, the sum below 3 2^62 in 64 unsigned
 *        bits) and shifted by an even count 2j so that its top bit lies at
 *        bit 30 or 31 (exact when shifting left, the bits below 2^30
 *        dropped when shifting right); fx_rsqrt_q30 gives the reciprocal
 *        square root of that (2^-29 relative), so each unit component is
 *        v_i/sqrt(S) rounded once, within 0.5 + 2^-13 units of 2^-16 of
 *        its exact value, and the length and its reciprocal within 0.5
 *        units plus 2^-29 of the value (test_vec_unit_exact).
 *   f32/f64: one square root and one reciprocal when the largest component
 *        is in [2^-30, 2^30] (no overflow or underflow), else v is first
 *        divided by it.
 *   q32: v is divided by its largest component, a square root and a
 *        reciprocal (native 128-bit divides where the compiler has them). */
VEC_HOT int vec3_unit(vec3 v, vec3 *unit, num *len, num *rlen)
{
#if defined(NUM_MODE_q16)
    uint64_t ss = (uint64_t)((int64_t)v.x * v.x) + (uint64_t)((int64_t)v.y * v.y)
                  + (uint64_t)((int64_t)v.z * v.z), xs, y;
    int t = 63, j;
    if (ss == 0)
        return -1;
#if defined(__GNUC__)
    t = 63 - __builtin_clzll(ss);                       /* ss's top bit */
#else
    while (!(ss >> t))
        t--;
#endif
    j = (t + 34) / 2 - 32;                              /* floor((t - 30) / 2), -15 to 16 */
    xs = j >= 0 ? ss >> 2 * j : ss << -2 * j;           /* in [2^30, 2^32) */
    y = fx_rsqrt_q30(xs);                               /* 2^(46 + j) / sqrt(S), Q.30 */
    if (unit)
        *unit = vec3_make((num)fx_shr_round(v.x * (int64_t)y, 30 + j),
                          (num)fx_shr_round(v.y * (int64_t)y, 30 + j),
                          (num)fx_shr_round(v.z * (int64_t)y, 30 + j));
    if (len)      /* sqrt(S) = xs y 2^(j - 46), xs y below 2^63 */
        *len = fx16_sat(fx_shr_round((int64_t)(xs * y >> 1), 45 - j));
    if (rlen) {   /* 2^32 / sqrt(S) = y 2^(-14 - j) in Q16.16 */
        int sh = 14 + j;
        *rlen = sh > 0 ? fx16_sat(fx_shr_round((int64_t)y, sh)) : fx16_sat((int64_t)y << -sh);
    }
    return 0;
#else
    num m = vec3_maxabs(v);
    if (m == NUM_ZERO)
        return -1;
    {
        num s, inv;
        vec3 w = v;
#if NUM_IS_FIXED
        const int direct = 0;
#else
        const int direct = m >= num_from_d(9.313225746154785e-10) && m <= num_from_d(1073741824.0);
#endif
        if (!direct)
            w = vec3_div(v, m);
        s = num_sqrt(vec3_dot(w, w));
        if (s == NUM_ZERO)
            return -1;
        inv = num_div(NUM_ONE, s);
        if (unit)
            *unit = vec3_scale(w, inv);
        if (len)
            *len = direct ? s : num_mul(m, s);
        if (rlen)
            *rlen = direct ? inv : num_div(inv, m);
        return 0;
    }
#endif
}

static inline int vec3_normalize(vec3 v, vec3 *unit, num *len) { return vec3_unit(v, unit, len, NULL); }

/* Unit vector along v where |v| is close to 1 (a mirror or refracted
 * direction formed from unit vectors); -1 for v = 0, as vec3_unit.
 * q16: with x = |v|^2 - 1 within 2^-10 (|v|^2 summed exactly), 1/|v| is
 * the series 1 - x/2 + 3x^2/8 of (1 + x)^-1/2 in Q.32, which leaves out
 * less than 5/16 |x|^3 <= 2^-31.6 and rounds below 2^-31; each component is
 * then rounded once: within 0.50003 units of its exact value (vec3_unit's
 * table and Newton step: 0.50006), with three multiplies where the table
 * needs seven in a chain (docs/numerics.md). Else, and in every other mode,
 * vec3_unit. */
VEC_HOT int vec3_unit_near(vec3 v, vec3 *unit)
{
#if defined(NUM_MODE_q16)
    int64_t s = (int64_t)v.x * v.x + (int64_t)v.y * v.y + (int64_t)v.z * v.z, x = s - ((int64_t)1 << 32);
    if (x >= -((int64_t)1 << 22) && x <= ((int64_t)1 << 22)) {
        int64_t y = ((int64_t)1 << 32) - x / 2 + (3 * (x * x >> 16) >> 19);     /* Q.32 */
        *unit = vec3_make((num)fx_shr_round(v.x * y, 32), (num)fx_shr_round(v.y * y, 32),
                          (num)fx_shr_round(v.z * y, 32));
        return 0;
    }
#endif
    return vec3_unit(v, unit, NULL, NULL);
}

/* a + t*d - c: a point along a ray, measured from c. q16: each component
 * summed in 64 bits from the rounded product and saturated once, the value
 * of vec3_sub(vec3_madd(a, t, d), c) unless a + t*d leaves the range
 * (prim_side's uses: docs/numerics.md). */
VEC_HOT vec3 vec3_madd_sub(vec3 a, num t, vec3 d, vec3 c)
{
#if defined(NUM_MODE_q16)
    return vec3_make(fx16_sat((int64_t)a.x + fx16_mul_wide(d.x, t) - c.x),
                     fx16_sat((int64_t)a.y + fx16_mul_wide(d.y, t) - c.y),
                     fx16_sat((int64_t)a.z + fx16_mul_wide(d.z, t) - c.z));
#else
    return vec3_sub(vec3_madd(a, t, d), c);
#endif
}

/* q16: each row's three rounded products summed in 64 bits and saturated
 * once: the chained saturating form's value unless one of its partial sums
 * leaves the range while the row does not. With rows of norm at most 1
 * (minv_s, the only matrix multiplied) every partial sum is at most |v| by
 * Cauchy-Schwarz, so that needs |v| >= 32768, beyond every vector prim_side
 * maps (docs/numerics.md). */
VEC_HOT vec3 mat3_mul(const mat3 *a, vec3 v)
{
#if defined(NUM_MODE_q16)
    return vec3_make(fx16_sat(fx16_mul_wide(a->m[0], v.x) + fx16_mul_wide(a->m[1], v.y) + fx16_mul_wide(a->m[2], v.z)),
                     fx16_sat(fx16_mul_wide(a->m[3], v.x) + fx16_mul_wide(a->m[4], v.y) + fx16_mul_wide(a->m[5], v.z)),
                     fx16_sat(fx16_mul_wide(a->m[6], v.x) + fx16_mul_wide(a->m[7], v.y) + fx16_mul_wide(a->m[8], v.z)));
#else
    return vec3_make(num_add(num_add(num_mul(a->m[0], v.x), num_mul(a->m[1], v.y)), num_mul(a->m[2], v.z)),
                     num_add(num_add(num_mul(a->m[3], v.x), num_mul(a->m[4], v.y)), num_mul(a->m[5], v.z)),
                     num_add(num_add(num_mul(a->m[6], v.x), num_mul(a->m[7], v.y)), num_mul(a->m[8], v.z)));
#endif
}
/* transpose(a) * v */
static inline vec3 mat3_tmul(const mat3 *a, vec3 v)
{
    return vec3_make(num_add(num_add(num_mul(a->m[0], v.x), num_mul(a->m[3], v.y)), num_mul(a->m[6], v.z)),
                     num_add(num_add(num_mul(a->m[1], v.x), num_mul(a->m[4], v.y)), num_mul(a->m[7], v.z)),
                     num_add(num_add(num_mul(a->m[2], v.x), num_mul(a->m[5], v.y)), num_mul(a->m[8], v.z)));
}
static inline void vec3_to_d(vec3 v, double *d) { d[0] = num_to_d(v.x); d[1] = num_to_d(v.y); d[2] = num_to_d(v.z); }

/* a/b clamped to [-lim, lim] without overflowing: |a/b| >= lim (or b = 0)
 * yields +-lim with the quotient's sign; 0/0 is 0. lim must be >= 1. */
VEC_HOT num num_div_clamp(num a, num b, num lim)
{
#if defined(NUM_MODE_q16)
    return fx16_div_clamp(a, b, lim);
#else
    num aa = num_abs(a), ab = num_abs(b);
    int neg = (a < NUM_ZERO) != (b < NUM_ZERO);
    if (aa == NUM_ZERO)
        return NUM_ZERO;
    if (ab == NUM_ZERO || (ab < NUM_ONE && aa >= num_mul(ab, lim)))
        return neg ? num_neg(lim) : lim;
    {
        num q = num_div(a, b);
        if (q > lim) return lim;
        if (q < num_neg(lim)) return num_neg(lim);
        return q;
    }
#endif
}

/* a*b clamped to [-lim, lim] (lim > 0) without saturating: a product
 * beyond lim gives +-lim and counts no overflow. */
static inline num num_mul_clamp(num a, num b, num lim)
{
#if defined(NUM_MODE_q16)
    int64_t p = (int64_t)a * b, l = (int64_t)lim << 16;
    if (p >= l) return lim;
    if (p <= -l) return -lim;
    return fx16_mul(a, b);
#elif NUM_IS_FIXED
    num ab = num_abs(b);
    if (ab > NUM_ONE && num_abs(a) >= num_div(lim, ab))
        return (a < NUM_ZERO) != (b < NUM_ZERO) ? num_neg(lim) : lim;
    {
        num t = num_mul(a, b);
        return t > lim ? lim : t < num_neg(lim) ? num_neg(lim) : t;
    }
#else
    num t = num_mul(a, b);
    return t > lim ? lim : t < num_neg(lim) ? num_neg(lim) : t;
#endif
}

/* n1/d1 > n2/d2 for d1, d2 > 0: exact in q16 (64-bit cross products) and in
 * q32 where the compiler has 128-bit integers; else on the rounded
 * quotients (what the divide would give). */
static inline int num_frac_gt(num n1, num d1, num n2, num d2)
{
#if defined(NUM_MODE_q16)
    return (int64_t)n1 * d2 > (int64_t)n2 * d1;
#elif NUM_IS_FIXED && defined(FX_HAVE_INT128)
    return (fx_i128)n1 * d2 > (fx_i128)n2 * d1;
#elif NUM_IS_FIXED
    return num_div(n1, d1) > num_div(n2, d2);
#else
    return num_mul(n1, d2) > num_mul(n2, d1);
#endif
}

/* Bounding-sphere rejection: 1 when the ray o + t d (d unit) misses the
 * sphere (c, r) for every t in [tmin, tmax]; else 0 and *tc = the parameter of
 * the ray point closest to c. Division-free; the only squares are of
 * quantities already checked to be at most r (docs/numerics.md). */
#if defined(NUM_MODE_q16)
/* q16: the same test on exact 64-bit intermediates. Differences of Q16.16
 * values stay below 2^33 and products with a unit component below 2^49, so
 * the dot product is summed exactly and rounded once; squares of
 * components at most r are below 2^62, so |q|^2 is summed exactly in
 * unsigned 64 bits and compared with r^2 without rounding. Nothing can
 * overflow and nothing needs a saturation check. */
VEC_HOT int vec3_sphere_miss(vec3 c, num r, vec3 o, vec3 d, num tmin, num tmax, num *tc)
{
    int64_t ox = (int64_t)c.x - o.x, oy = (int64_t)c.y - o.y, oz = (int64_t)c.z - o.z;
    int64_t t = fx_shr_round(ox * d.x + oy * d.y + oz * d.z, 16), qx, qy, qz;
    if (t + r < tmin || t - r > tmax)
        return 1;
    qx = ox - fx_shr_round(d.x * t, 16);
    qy = oy - fx_shr_round(d.y * t, 16);
    qz = oz - fx_shr_round(d.z * t, 16);
    if (qx > r || qx < -(int64_t)r || qy > r || qy < -(int64_t)r || qz > r || qz < -(int64_t)r
        || (uint64_t)(qx * qx) + (uint64_t)(qy * qy) + (uint64_t)(qz * qz) > (uint64_t)((int64_t)r * r))
        return 1;
    *tc = fx16_sat(t);
    return 0;
}
#else
VEC_HOT int vec3_sphere_miss(vec3 c, num r, vec3 o, vec3 d, num tmin, num tmax, num *tc)
{
    vec3 oc = vec3_sub(c, o), q;
    num t = vec3_dot(oc, d);
    if (num_add(t, r) < tmin || num_sub(t, r) > tmax)
        return 1;
    q = vec3_madd(oc, num_neg(t), d);
    if (vec3_maxabs(q) > r || vec3_dot(q, q) > num_mul(r, r))
        return 1;
    *tc = t;
    return 0;
}
#endif
#endif
