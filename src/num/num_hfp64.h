/* num_hfp64 — System/370 long hexadecimal floating point (see num.h, hfp.h).
 *
 * A num is an order key of the register image: the image itself for a
 * positive number, the negated magnitude bits for a negative one. Every
 * value the mode produces is normalised or a true zero, and for those the
 * key orders exactly as the values do, so the tracer's <, <= and == are the
 * algebraic comparison COMPARE (CD) makes. Arithmetic is AD, SD, MD, DD and
 * SQD. */
#ifndef NUM_HFP64_H
#define NUM_HFP64_H
#include "num/hfp.h"

typedef int64_t num;
#define NUM_NAME "hfp64"
#define NUM_IS_FIXED 0
#define NUM_IS_NATIVE 0
#define NUM_ZERO ((num)0)
#define NUM_ONE  ((num)0x4110000000000000)     /* 0.1 x 16^1 */
#define NUM_HALF ((num)0x4080000000000000)    /* 0.8 x 16^0 */
#define NUM_MAX  ((num)HFP_LONG_MAX)
#define NUM_ULP  ((num)0x3410000000000000) /* 16^-13: one unit in the last digit of 1 */

static inline num num_hfp_key(hfp_long a)
{
    return (a >> 63) ? -(num)(a & 0x7fffffffffffffffu) : (num)a;
}
static inline hfp_long num_hfp_image(num k)
{
    return k < 0 ? 0x8000000000000000u | (hfp_long)-k : (hfp_long)k;
}

static inline num num_add(num a, num b) { return num_hfp_key(hfp_ad(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_sub(num a, num b) { return num_hfp_key(hfp_sd(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_neg(num a) { return -a; }        /* LCDR: exact */
static inline num num_abs(num a) { return a < 0 ? -a : a; }   /* LPDR */
static inline num num_mul(num a, num b) { return num_hfp_key(hfp_md(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_div(num a, num b) { return num_hfp_key(hfp_dd(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_sqrt(num a) { return num_hfp_key(hfp_sqd(num_hfp_image(a))); }
static inline num num_from_d(double x) { return num_hfp_key(hfp_long_from_double(x)); }
static inline double num_to_d(num a) { return hfp_long_to_double(num_hfp_image(a)); }
static inline num num_from_i(int i) { return num_hfp_key(hfp_long_from_i32(i)); }
#endif
