/* mem — allocation hook with fault injection (see mem.h). */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE 1     /* MADV_HUGEPAGE, which POSIX does not name */
#endif
#include "util/mem.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

static long fail_after = -1;
static long alloc_count;

static int mem_should_fail(void)
{
    int fail = 0;
#pragma omp critical(mem_hook)
    {
        if (fail_after == 0)
            fail = 1;
        else {
            if (fail_after > 0)
                fail_after--;
            alloc_count++;
        }
    }
    return fail;
}

void mem_fail_after(long n) { fail_after = n; alloc_count = 0; }
long mem_alloc_count(void) { return alloc_count; }

/* Large blocks (a deck of 10,000 objects compiles to about 50 MB) are
 * offered to the kernel for transparent huge pages, where it lets a
 * process ask (Linux, `madvise` mode of
 * /sys/kernel/mm/transparent_hugepage/enabled): one fault maps 2 MiB
 * instead of 4 KiB. Each first touch of a page is a fault, which a virtual
 * machine makes dear: the 10,000-object deck took 15,170 of them and 42 ms
 * of system time, and about 9,200 and 28 ms with this advice
 * (docs/performance.md, run I).
 * A huge page needs a 2 MiB-aligned stretch inside one mapping. So a large
 * block is asked for a little larger (mem_huge_size): glibc's malloc then
 * maps a whole number of 2 MiB, which Linux (6.18 here) places on a 2 MiB
 * boundary, and the block with its header fills the mapping. Without that
 * the head and tail of each block, up to 2 MiB each, faulted in 4 KiB
 * pages: the 10,000-object deck, 10,349 faults against 6,794 (run S). The
 * range advised runs from boundary to boundary over the block, reaching
 * past its ends by less than MEM_HUGE_SLACK (the allocator's header);
 * the advice is a hint, and its failure changes nothing. */

size_t mem_huge_size(size_t size)
{
    if (size < MEM_HUGE_MIN || size > SIZE_MAX - 2 * MEM_HUGE_PAGE)
        return size;
    return ((size + MEM_HUGE_SLACK + MEM_HUGE_PAGE - 1) & ~(size_t)(MEM_HUGE_PAGE - 1)) - MEM_HUGE_SLACK;
}

int mem_huge_range(uintptr_t p, size_t size, uintptr_t *start, size_t *len)
{
    uintptr_t a, b, e;
    if (size < MEM_HUGE_MIN || size > UINTPTR_MAX - 2 * MEM_HUGE_PAGE || p > UINTPTR_MAX - 2 * MEM_HUGE_PAGE - size)
        return 0;
    e = p + size;
    a = p & ~(MEM_HUGE_PAGE - 1);
    if (p - a >= MEM_HUGE_SLACK)
        a += MEM_HUGE_PAGE;
    b = (e + MEM_HUGE_SLACK) & ~(MEM_HUGE_PAGE - 1);
    if (b <= a)
        return 0;
    *start = a;
    *len = (size_t)(b - a);
    return 1;
}

#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define MEM_MADV_COLLAPSE 25   /* Linux 6.1's MADV_COLLAPSE, which glibc 2.36 does not name */

/* 1 when the system offers huge pages on advice ("[always]" or
 * "[madvise]" in /sys/kernel/mm/transparent_hugepage/enabled), read once. */
static int mem_thp_offered(void)
{
    static int offered = -1;
    int v;
#pragma omp critical(mem_hook)
    {
        if (offered < 0) {
            FILE *f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
            char line[128];
            offered = f && fgets(line, sizeof line, f) && (strstr(line, "[always]") || strstr(line, "[madvise]"));
            if (f)
                fclose(f);
        }
        v = offered;
    }
    return v;
}
#endif

/* The block's first 2 MiB hold malloc's header, written before the advice
 * and so faulted as a 4 KiB page: later faults there would map 4 KiB
 * pages too. Where the system offers huge pages, MADV_COLLAPSE makes that
 * stretch one huge page at once (the block's start is always written
 * first); a kernel without it refuses, which changes nothing. */
static void *mem_huge(void *p, size_t size)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    uintptr_t a;
    size_t n;
    if (p && mem_huge_range((uintptr_t)p, size, &a, &n)) {
        (void)madvise((void *)a, n, MADV_HUGEPAGE);
        if (a < (uintptr_t)p && mem_thp_offered())
            (void)madvise((void *)a, MEM_HUGE_PAGE, MEM_MADV_COLLAPSE);
    }
#else
    (void)size;
#endif
    return p;
}

/* A request for zero bytes gets a valid, distinct pointer (one byte), so
 * that callers need not special-case empty arrays and NULL always means
 * failure. */
void *mem_alloc(size_t size)
{
    if (mem_should_fail())
        return NULL;
    size = mem_huge_size(size);
    return mem_huge(malloc(size ? size : 1), size);
}

void *mem_calloc(size_t count, size_t size)
{
    return mem_calloc_part(count, size, count);
}

void *mem_calloc_part(size_t count, size_t size, size_t likely)
{
    size_t n;
    if ((size && count > SIZE_MAX / size) || mem_should_fail())
        return NULL;
    n = mem_huge_size(count * size);
    return n ? mem_huge(calloc(1, n), likely < count ? likely * size : n) : calloc(1, 1);
}

void *mem_calloc_sparse(size_t count, size_t size)
{
    if ((size && count > SIZE_MAX / size) || mem_should_fail())
        return NULL;
    return calloc(count && size ? count : 1, count && size ? size : 1);
}

void *mem_realloc(void *p, size_t size)
{
    if (mem_should_fail())
        return NULL;
    size = mem_huge_size(size);
    return mem_huge(realloc(p, size ? size : 1), size);
}

void mem_free(void *p) { free(p); }

char *mem_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = mem_alloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

int mem_grow_realloc(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t ncap = *cap ? *cap : 8;
    void *np;
    if (need == 0)
        need = 1;             /* an empty array is still allocated */
    if (need <= *cap)
        return 0;
    while (ncap < need) {
        if (ncap > SIZE_MAX / 2)
            return -1;
        ncap *= 2;
    }
    if (elem == 0 || ncap > SIZE_MAX / elem)
        return -1;
    np = mem_realloc(*p, ncap * elem);
    if (!np)
        return -1;
    *p = np;
    *cap = ncap;
    return 0;
}
