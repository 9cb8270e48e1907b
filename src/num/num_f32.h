/* num_f32 — IEEE binary32 mode (see num.h). */
#ifndef NUM_F32_H
#define NUM_F32_H
#include <math.h>
#include <float.h>

typedef float num;
#define NUM_NAME "f32"
#define NUM_IS_FIXED 0
#define NUM_IS_NATIVE 1
#define NUM_ZERO 0.0f
#define NUM_ONE  1.0f
#define NUM_HALF 0.5f
#define NUM_MAX  FLT_MAX
#define NUM_ULP  FLT_EPSILON

static inline num num_add(num a, num b) { return a + b; }
static inline num num_sub(num a, num b) { return a - b; }
static inline num num_neg(num a) { return -a; }
static inline num num_abs(num a) { return fabsf(a); }
static inline num num_mul(num a, num b) { return a * b; }
static inline num num_div(num a, num b) { return a / b; }
static inline num num_sqrt(num a) { return a > 0 ? sqrtf(a) : 0.0f; }
static inline num num_from_d(double x) { return (float)x; }
static inline double num_to_d(num a) { return (double)a; }
static inline num num_from_i(int i) { return (num)i; }
#endif
