/* radix — a stable sort by 64-bit keys without a comparison callback: a
 * least-significant-digit radix sort, a few instructions per element and
 * byte where qsort calls a comparator about log2(n) times per element.
 * Stable, so elements stored in index order come out as a comparator on
 * (key, then index) would order them. */
#ifndef UTIL_RADIX_H
#define UTIL_RADIX_H
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* A key that orders doubles as < does, -0 and +0 as one value (not NaN). */
static inline uint64_t radix_key_d(double x)
{
    uint64_t u;
    x += 0.0;                               /* -0 becomes +0 */
    memcpy(&u, &x, sizeof u);
    return u >> 63 ? ~u : u | (uint64_t)1 << 63;
}

/* Sorts the n elements of size bytes at base by keys[i], the key of element
 * i, stably. 0, or -1 when memory runs out (then base is unchanged). */
int radix_sort(void *base, size_t n, size_t size, const uint64_t *keys);
#endif
