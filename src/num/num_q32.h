/* num_q32 — Q32.32 mode (see num.h, fx.h). */
#ifndef NUM_Q32_H
#define NUM_Q32_H
#include "num/fx.h"

typedef fx32 num;
#define NUM_NAME "q32"
#define NUM_IS_FIXED 1
#define NUM_IS_NATIVE 0
#define NUM_ZERO ((num)0)
#define NUM_ONE  FX32_ONE
#define NUM_HALF ((num)1 << 31)
#define NUM_MAX  FX32_MAX
#define NUM_ULP  ((num)1)

static inline num num_add(num a, num b) { return fx32_add(a, b); }
static inline num num_sub(num a, num b) { return fx32_sub(a, b); }
static inline num num_neg(num a) { return fx32_neg(a); }
static inline num num_abs(num a) { return fx32_abs(a); }
static inline num num_mul(num a, num b) { return fx32_mul(a, b); }
static inline num num_div(num a, num b) { return fx32_div(a, b); }
static inline num num_sqrt(num a) { return fx32_sqrt(a); }
static inline num num_from_d(double x) { return fx32_from_double(x); }
static inline double num_to_d(num a) { return fx32_to_double(a); }
static inline num num_from_i(int i)
{
    if (i > INT32_MAX || i < INT32_MIN) { fx_overflows++; return i > 0 ? FX32_MAX : FX32_MIN; }
    return (num)((uint64_t)(int64_t)i << 32);
}
#endif
