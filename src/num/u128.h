/* u128 — an unsigned 128-bit value as two 64-bit halves, and the exact
 * 64 x 64 -> 128-bit product, in portable C99 (no compiler extension). The
 * Q32.32 fallback (fx.c) and the HFP long products (hfp.c) share it. */
#ifndef NUM_U128_H
#define NUM_U128_H
#include <stdint.h>

typedef struct u128 { uint64_t hi, lo; } u128;

static inline u128 u128_mul64(uint64_t a, uint64_t b)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    u128 r;
    r.lo = (p00 & 0xffffffffu) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}
#endif
