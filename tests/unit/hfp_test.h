/* hfp_test — random HFP operands for the tests of src/num/hfp.c (test_hfp,
 * test_hfp_hercules): register images of nd = 6 (short) or 14 (long)
 * fraction digits in a uint64_t. */
#ifndef HFP_TEST_H
#define HFP_TEST_H
#include <stdint.h>
#include <stdlib.h>
#include "support.h"

/* A normalised number (or, rarely, a true zero) with characteristics
 * bunched near 64 and at both ends of the range, and fractions that are
 * random, all ones, or a leading digit with few other bits. */
static inline uint64_t hfp_test_image(uint64_t *st, int nd)
{
    uint64_t r = test_rand(st), f = test_rand(st), fmask = ((uint64_t)1 << (4 * nd)) - 1;
    int c, fb = 4 * nd;
    if ((r & 63) == 0)
        return 0;
    switch ((r >> 6) & 7) {
    case 5: c = (int)((r >> 9) % 128); break;
    case 6: c = (int)((r >> 9) % 4); break;
    case 7: c = 124 + (int)((r >> 9) % 4); break;
    default: c = 60 + (int)((r >> 9) % 9); break;
    }
    switch ((r >> 16) & 7) {
    case 4: f = fmask; break;
    case 5: f = ((uint64_t)1 << (fb - 4)) | (f & 1); break;
    case 6: f &= ~(((uint64_t)1 << ((r >> 20) % (uint64_t)fb)) - 1); break;
    default: break;
    }
    f &= fmask;
    if (!(f >> (fb - 4)))
        f |= (uint64_t)(1 + (r >> 24) % 15) << (fb - 4);
    return ((uint64_t)((r >> 30) & 1) << (fb + 7)) | ((uint64_t)c << fb) | f;
}

/* A second operand: often a near neighbour of the first (cancellation,
 * guard-digit and carry cases), else independent. */
static inline uint64_t hfp_test_second(uint64_t *st, uint64_t a, int nd)
{
    uint64_t r = test_rand(st), b;
    int fb = 4 * nd, c;
    switch (r & 7) {
    case 0:
        return a;
    case 1:
        return a ^ ((uint64_t)1 << (fb + 7));
    case 2:
    case 3:
        if (!a)
            return hfp_test_image(st, nd);
        b = a ^ (test_rand(st) & (((uint64_t)1 << ((r >> 3) % (uint64_t)fb)) - 1));
        c = (int)(a >> fb & 0x7f) - (int)((r >> 10) % (uint64_t)(nd + 3));
        if (c < 0)
            c = 0;
        b = (b & ~((uint64_t)0x7f << fb)) | ((uint64_t)c << fb);
        if ((r >> 16) & 1)
            b ^= (uint64_t)1 << (fb + 7);
        if (!((b >> (fb - 4)) & 0xf))           /* keep it normalised */
            b |= (uint64_t)1 << (fb - 4);
        return b;
    default:
        return hfp_test_image(st, nd);
    }
}

/* The count from environment variable var, else dflt. */
static inline long hfp_test_count(const char *var, long dflt)
{
    const char *s = getenv(var);
    long n = s ? strtol(s, NULL, 10) : dflt;
    return n > 0 ? n : dflt;
}
#endif
