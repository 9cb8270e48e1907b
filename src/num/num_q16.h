/* num_q16 — Q16.16 mode (see num.h, fx.h). The default mode. */
#ifndef NUM_Q16_H
#define NUM_Q16_H
#include "num/fx.h"

typedef fx16 num;
#define NUM_NAME "q16"
#define NUM_IS_FIXED 1
#define NUM_IS_NATIVE 0
#define NUM_ZERO ((num)0)
#define NUM_ONE  FX16_ONE
#define NUM_HALF ((num)32768)
#define NUM_MAX  FX16_MAX
#define NUM_ULP  ((num)1)

static inline num num_add(num a, num b) { return fx16_add(a, b); }
static inline num num_sub(num a, num b) { return fx16_sub(a, b); }
static inline num num_neg(num a) { return fx16_neg(a); }
static inline num num_abs(num a) { return fx16_abs(a); }
static inline num num_mul(num a, num b) { return fx16_mul(a, b); }
static inline num num_div(num a, num b) { return fx16_div(a, b); }
static inline num num_sqrt(num a) { return fx16_sqrt(a); }
static inline num num_from_d(double x) { return fx16_from_double(x); }
static inline double num_to_d(num a) { return fx16_to_double(a); }
static inline num num_from_i(int i) { return fx16_sat((int64_t)i * 65536); }
#endif
