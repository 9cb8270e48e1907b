/* vec — 3-vectors and 3x3 matrices of `num` for the modal geometry code.
 * Small transparent value types; every operation goes through num_* so the
 * fixed-point modes saturate and count overflows instead of wrapping.
 * Included only by files compiled per numeric mode. */
#ifndef GEOM_VEC_H
#define GEOM_VEC_H
#include "num/num.h"
#include "geom/geom.h"

typedef struct vec3 { num x, y, z; } vec3;
typedef struct mat3 { num m[9]; } mat3;      /* row-major */

static inline vec3 vec3_make(num x, num y, num z) { vec3 v; v.x = x; v.y = y; v.z = z; return v; }
static inline vec3 vec3_from_d(const double *d) { return vec3_make(num_from_d(d[0]), num_from_d(d[1]), num_from_d(d[2])); }
static inline vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(num_add(a.x, b.x), num_add(a.y, b.y), num_add(a.z, b.z)); }
static inline vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(num_sub(a.x, b.x), num_sub(a.y, b.y), num_sub(a.z, b.z)); }
static inline vec3 vec3_neg(vec3 a) { return vec3_make(num_neg(a.x), num_neg(a.y), num_neg(a.z)); }
static inline vec3 vec3_scale(vec3 a, num s) { return vec3_make(num_mul(a.x, s), num_mul(a.y, s), num_mul(a.z, s)); }
static inline vec3 vec3_div(vec3 a, num s) { return vec3_make(num_div(a.x, s), num_div(a.y, s), num_div(a.z, s)); }
/* a + t*d: a point along a ray. */
static inline vec3 vec3_madd(vec3 a, num t, vec3 d) { return vec3_add(a, vec3_scale(d, t)); }
static inline num vec3_dot(vec3 a, vec3 b)
{
    return num_add(num_add(num_mul(a.x, b.x), num_mul(a.y, b.y)), num_mul(a.z, b.z));
}
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
    return vec3_make(num_sub(num_mul(a.y, b.z), num_mul(a.z, b.y)),
                     num_sub(num_mul(a.z, b.x), num_mul(a.x, b.z)),
                     num_sub(num_mul(a.x, b.y), num_mul(a.y, b.x)));
}
static inline num vec3_maxabs(vec3 a) { return num_max(num_abs(a.x), num_max(num_abs(a.y), num_abs(a.z))); }

/* Unit vector along v and its length, without squaring large components:
 * v is first divided by its largest component magnitude, so the sum of
 * squares lies in [1,3]. Returns 0, or -1 (outputs untouched) for v = 0. */
static inline int vec3_normalize(vec3 v, vec3 *unit, num *len)
{
    num m = vec3_maxabs(v), s;
    vec3 w;
    if (m == NUM_ZERO)
        return -1;
    /* one reciprocal instead of three quotients when 1/m is well inside
     * the range (m >= 1/64) */
    w = m >= num_div(NUM_ONE, num_from_i(64)) ? vec3_scale(v, num_div(NUM_ONE, m)) : vec3_div(v, m);
    s = num_sqrt(vec3_dot(w, w));
    if (s == NUM_ZERO)
        return -1;
    *unit = vec3_scale(w, num_div(NUM_ONE, s));      /* s in [1, sqrt 3] */
    if (len)
        *len = num_mul(m, s);
    return 0;
}

static inline vec3 mat3_mul(const mat3 *a, vec3 v)
{
    return vec3_make(num_add(num_add(num_mul(a->m[0], v.x), num_mul(a->m[1], v.y)), num_mul(a->m[2], v.z)),
                     num_add(num_add(num_mul(a->m[3], v.x), num_mul(a->m[4], v.y)), num_mul(a->m[5], v.z)),
                     num_add(num_add(num_mul(a->m[6], v.x), num_mul(a->m[7], v.y)), num_mul(a->m[8], v.z)));
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
static inline num num_div_clamp(num a, num b, num lim)
{
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
}

/* Clips the relative ray interval [*a, *b] (parameters measured from o) to
 * the slab lo <= o + t d <= hi of one axis, with the same clamped quotient
 * as plane faces. 1 when the interval becomes empty. */
static inline int vec3_slab_miss(num lo, num hi, num o, num d, num *a, num *b)
{
    num t0, t1, big = num_from_i(GEOM_TBIG);
    if (d == NUM_ZERO)
        return o < lo || o > hi;
    t0 = num_div_clamp(num_sub(lo, o), d, big);
    t1 = num_div_clamp(num_sub(hi, o), d, big);
    if (d < NUM_ZERO) { num t = t0; t0 = t1; t1 = t; }
    if (t0 > *a) *a = t0;
    if (t1 < *b) *b = t1;
    return *a > *b;
}

/* Bounding-box rejection, after a bounding-sphere test passed with closest
 * parameter tc: 1 when the ray misses the box [lo, hi] for every t in
 * [tmin, tmax]. The origin is first moved to o + tc d, inside the sphere
 * that contains the box, so every difference is at most the sphere's
 * diameter. */
static inline int vec3_box_miss(vec3 lo, vec3 hi, vec3 o, vec3 d, num tc, num tmin, num tmax)
{
    vec3 o1 = vec3_madd(o, tc, d);
    num a = num_sub(tmin, tc), b = num_sub(tmax, tc);
    return vec3_slab_miss(lo.x, hi.x, o1.x, d.x, &a, &b) || vec3_slab_miss(lo.y, hi.y, o1.y, d.y, &a, &b)
        || vec3_slab_miss(lo.z, hi.z, o1.z, d.z, &a, &b);
}

/* Bounding-sphere rejection: 1 when the ray o + t d (d unit) misses the
 * sphere (c, r) for every t in [tmin, tmax]; else 0 and *tc = the parameter of
 * the ray point closest to c. Division-free; the only squares are of
 * quantities already checked to be at most r (docs/numerics.md). */
static inline int vec3_sphere_miss(vec3 c, num r, vec3 o, vec3 d, num tmin, num tmax, num *tc)
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
