/* num_hfp32 — System/370 short hexadecimal floating point (see num.h, hfp.h).
 *
 * A num is an order key of the register image: the image itself for a
 * positive number, the negated magnitude bits for a negative one. Every
 * value the mode produces is normalised or a true zero, and for those the
 * key orders exactly as the values do, so the tracer's <, <= and == are the
 * algebraic comparison COMPARE (CE) makes. Arithmetic is AE, SE, ME (the
 * leading word of the long product), DE and SQE. */
#ifndef NUM_HFP32_H
#define NUM_HFP32_H
#include "num/hfp.h"

typedef int32_t num;
#define NUM_NAME "hfp32"
#define NUM_IS_FIXED 0
#define NUM_IS_NATIVE 0
#define NUM_ZERO ((num)0)
#define NUM_ONE  ((num)0x41100000)     /* 0.1 x 16^1 */
#define NUM_HALF ((num)0x40800000)     /* 0.8 x 16^0 */
#define NUM_MAX  ((num)HFP_SHORT_MAX)
#define NUM_ULP  ((num)0x3c100000)     /* 16^-5: one unit in the last digit of 1 */

static inline num num_hfp_key(hfp_short a)
{
    return (a >> 31) ? -(num)(a & 0x7fffffffu) : (num)a;
}
static inline hfp_short num_hfp_image(num k)
{
    return k < 0 ? 0x80000000u | (hfp_short)-k : (hfp_short)k;
}

static inline num num_add(num a, num b) { return num_hfp_key(hfp_ae(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_sub(num a, num b) { return num_hfp_key(hfp_se(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_neg(num a) { return -a; }        /* LCER: exact */
static inline num num_abs(num a) { return a < 0 ? -a : a; }   /* LPER */
static inline num num_mul(num a, num b) { return num_hfp_key(hfp_me_short(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_div(num a, num b) { return num_hfp_key(hfp_de(num_hfp_image(a), num_hfp_image(b))); }
static inline num num_sqrt(num a) { return num_hfp_key(hfp_sqe(num_hfp_image(a))); }
static inline num num_from_d(double x) { return num_hfp_key(hfp_short_from_double(x)); }
static inline double num_to_d(num a) { return hfp_short_to_double(num_hfp_image(a)); }
static inline num num_from_i(int i) { return num_hfp_key(hfp_short_from_i32(i)); }
#endif
