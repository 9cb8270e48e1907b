/* dmath — the small double-precision mathematics every module shares: pi,
 * degrees, 3-vectors, 3x3 matrices (row-major), the singular values of a
 * 2x2 matrix and binary32 rounded outwards. Used where the scene model,
 * the per-mode compilers, PDS validation, compare and the display shim
 * need the same formula, so that each is written once. Header-only except
 * the 3x3 inverse and norm (dmath.c). */
#ifndef UTIL_DMATH_H
#define UTIL_DMATH_H
#include <math.h>
#include <stdint.h>
#include <string.h>

#define DMATH_PI 3.14159265358979323846

static inline double dmath_rad(double deg) { return deg * (DMATH_PI / 180.0); }
static inline double dmath_deg(double rad) { return rad * (180.0 / DMATH_PI); }

/* Volume of a sphere of radius r. */
static inline double dmath_sphere_volume(double r) { return 4.0 / 3.0 * DMATH_PI * r * r * r; }

static inline double dmath_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline double dmath_norm2_3(const double *a) { return dmath_dot3(a, a); }
/* The largest |a_i| (no fmax: a library call, for NaN's sake, on hot paths). */
static inline double dmath_maxabs3(const double *a)
{
    double x = fabs(a[0]), y = fabs(a[1]), z = fabs(a[2]), m = x > y ? x : y;
    return m > z ? m : z;
}
static inline double dmath_len3(const double *a) { return sqrt(dmath_dot3(a, a)); }
static inline void dmath_sub3(const double *a, const double *b, double *out)
{
    out[0] = a[0] - b[0]; out[1] = a[1] - b[1]; out[2] = a[2] - b[2];
}
static inline void dmath_cross3(const double *a, const double *b, double *out)
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
    out[0] = x; out[1] = y;
}

/* out = a / |a|; -1 (out untouched) when |a| is zero or not finite. */
static inline int dmath_unit3(const double *a, double *out)
{
    double l = dmath_len3(a);
    if (!(l > 0) || !isfinite(l))
        return -1;
    out[0] = a[0] / l; out[1] = a[1] / l; out[2] = a[2] / l;
    return 0;
}

/* Singular values of the 2x2 matrix [a b; c d]: *smin <= *smax, from the
 * closed form s^2 = (S -+ sqrt(S^2 - 4 det^2)) / 2 with S the squared
 * Frobenius norm (clamped so rounding never takes a root of a negative). */
static inline void dmath_sv2(double a, double b, double c, double d, double *smin, double *smax)
{
    double s2 = a * a + b * b + c * c + d * d, det = fabs(a * d - b * c);
    double r = sqrt(fmax(0, s2 * s2 - 4 * det * det));
    *smin = sqrt(fmax(0, (s2 - r) / 2));
    *smax = sqrt((s2 + r) / 2);
}

/* out = m v and out = m^T v for a row-major 3x3 m (out must not alias v). */
static inline void dmath_m3_mul_v(const double *m, const double *v, double *out)
{
    int i;
    for (i = 0; i < 3; i++)
        out[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
}
static inline void dmath_m3_tmul_v(const double *m, const double *v, double *out)
{
    int i;
    for (i = 0; i < 3; i++)
        out[i] = m[i] * v[0] + m[3 + i] * v[1] + m[6 + i] * v[2];
}
/* Inverse by cofactors; -1 (inv untouched) when m is singular relative to
 * its own scale (|det| tiny against the product of its row norms). */
int dmath_m3_inverse(const double *m, double *inv);
/* Largest singular value of m (closed-form eigenvalue of m^T m). */
double dmath_m3_spectral_norm(const double *m);
/* Frobenius norm of m: never below dmath_m3_spectral_norm(m) by more than
 * rounding (that one computes the largest eigenvalue of m^T m as q + 2p cos
 * phi with p <= q and 3q the trace, the square of this norm), and cheaper:
 * a bound that clears most matrices before the spectral norm is needed. */
static inline double dmath_m3_frobenius(const double *m)
{
    return sqrt(dmath_norm2_3(m) + dmath_norm2_3(m + 3) + dmath_norm2_3(m + 6));
}
/* x in binary32 rounded upwards (up 1) or downwards: the nearest binary32,
 * stepped one unit in the last place (its bits one from zero or towards
 * it; past zero the least subnormal) where it lies on the wrong side of x.
 * Without a branch, as about half the conversions step and a branch on
 * that mispredicts (docs/performance.md, run AW); nextafterf is a call. */
static inline float dmath_f32_round(double x, int up)
{
    float f = (float)x;
    uint32_t b, s, m;
    memcpy(&b, &f, sizeof b);
    m = (uint32_t)0 - (uint32_t)(up ? (double)f < x : (double)f > x);
    s = (b & 0x7fffffffu) == 0 ? (up ? 1u : 0x80000001u) : (b >> 31) != (uint32_t)(up != 0) ? b + 1 : b - 1;
    b = (s & m) | (b & ~m);
    memcpy(&f, &b, sizeof f);
    return f;
}
#endif
