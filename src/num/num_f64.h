/* num_f64 — IEEE binary64 mode (see num.h). */
#ifndef NUM_F64_H
#define NUM_F64_H
#include <math.h>
#include <float.h>

typedef double num;
#define NUM_NAME "f64"
#define NUM_IS_FIXED 0
#define NUM_IS_NATIVE 1
#define NUM_ZERO 0.0
#define NUM_ONE  1.0
#define NUM_HALF 0.5
#define NUM_MAX  DBL_MAX
#define NUM_ULP  DBL_EPSILON

static inline num num_add(num a, num b) { return a + b; }
static inline num num_sub(num a, num b) { return a - b; }
static inline num num_neg(num a) { return -a; }
static inline num num_abs(num a) { return fabs(a); }
static inline num num_mul(num a, num b) { return a * b; }
static inline num num_div(num a, num b) { return a / b; }
static inline num num_sqrt(num a) { return a > 0 ? sqrt(a) : 0.0; }
static inline num num_from_d(double x) { return x; }
static inline double num_to_d(num a) { return a; }
static inline num num_from_i(int i) { return (num)i; }
#endif
