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

/* Indices into the keys: 32 bits, which halve what a sort moves and
 * holds (docs/performance.md, run AU); RADIX_MAX keys at most. */
typedef uint32_t radix_ix;
#define RADIX_MAX ((size_t)UINT32_MAX)

/* The stable order of the n keys: element i of the result is the index
 * of the i-th smallest key, equal keys in index order. The caller sorts its
 * own elements by it, copying each whole with its type's size known, and
 * frees it with mem_free; NULL when memory runs out or n > RADIX_MAX. */
radix_ix *radix_order(const uint64_t *keys, size_t n);

/* The inverse of radix_order: element i of the result is the position of
 * key i in that order. A caller that can form its elements again in index
 * order stores each straight at its place, where sorting by radix_order
 * needs the elements once unsorted and once sorted. mem_free; NULL when
 * memory runs out or n > RADIX_MAX. */
radix_ix *radix_rank(const uint64_t *keys, size_t n);

/* The two in caller memory: buf holds radix_bytes(n) bytes (0: n is too
 * large), aligned for radix_ix, and the result is its first n entries, not
 * to be freed. A caller with several sorts and temporaries of its own
 * then faults their pages in once (docs/performance.md, run AH). */
size_t radix_bytes(size_t n);
radix_ix *radix_order_in(const uint64_t *keys, size_t n, void *buf);
radix_ix *radix_rank_in(const uint64_t *keys, size_t n, void *buf);
#endif
