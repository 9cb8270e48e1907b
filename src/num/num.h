/* num — the number type the tracer is written against.
 *
 * Files in the modal directories (src/geom, src/pds, src/trace) are compiled
 * once per numeric mode with -DNUM_MODE=<mode> -DNUM_MODE_<mode>; this header
 * then provides, for that mode:
 *   num                          the scalar type: <, == etc. compare values;
 *                                arithmetic goes through num_* only (in the
 *                                hfp modes a num is an order key, not a value)
 *   NUM_ZERO NUM_ONE NUM_HALF NUM_MAX NUM_ULP   constants (NUM_ULP: smallest
 *                                positive step; 1/65536 in q16)
 *   num_add sub neg abs mul div sqrt min max   arithmetic (fixed point
 *                                saturates and counts overflows, see fx.h)
 *   num_from_d(double) num_to_d(num) num_from_i(int)   conversions
 *   NUM_IS_FIXED                 1 for q16/q32, 0 for f32/f64/hfp32/hfp64
 *   NUM_IS_NATIVE                1 for f32/f64 (a num is the machine's own
 *                                binary float: a conversion from double is
 *                                one instruction, which a loop can vectorise)
 *   NUM_NAME                     "q16" | "q32" | "f32" | "f64" | "hfp32" | "hfp64"
 *   NS(name)                     mode-prefixed symbol: NS(trace) -> q16_trace
 *                                (q16_v3_trace in the x86-64-v3 build of the
 *                                mode, -DNUM_ISA_V3: see the Makefile)
 *   NUM_ISA_NAME                 "baseline" | "x86-64-v3"
 * Mode-independent code reaches modal code only through per-mode ops tables
 * (e.g. q16_render_ops), never by including this header. */
#ifndef NUM_H
#define NUM_H

#define NUM_NS_2(m, x) m##_##x
#define NUM_NS_1(m, x) NUM_NS_2(m, x)
#if defined(NUM_ISA_V3)
#define NS(x) NUM_NS_1(NUM_NS_1(NUM_MODE, v3), x)
#define NUM_ISA_NAME "x86-64-v3"
#else
#define NS(x) NUM_NS_1(NUM_MODE, x)
#define NUM_ISA_NAME "baseline"
#endif

#if defined(NUM_MODE_q16)
#include "num/num_q16.h"
#elif defined(NUM_MODE_q32)
#include "num/num_q32.h"
#elif defined(NUM_MODE_f32)
#include "num/num_f32.h"
#elif defined(NUM_MODE_f64)
#include "num/num_f64.h"
#elif defined(NUM_MODE_hfp32)
#include "num/num_hfp32.h"
#elif defined(NUM_MODE_hfp64)
#include "num/num_hfp64.h"
#else
#error "num.h: compile with -DNUM_MODE=<q16|q32|f32|f64|hfp32|hfp64> -DNUM_MODE_<mode>"
#endif

static inline num num_min(num a, num b) { return a < b ? a : b; }
static inline num num_max(num a, num b) { return a > b ? a : b; }
#endif
