/* mem — allocation hook with fault injection (see mem.h). */
#include "util/mem.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

/* A request for zero bytes gets a valid, distinct pointer (one byte), so
 * that callers need not special-case empty arrays and NULL always means
 * failure. */
void *mem_alloc(size_t size)
{
    if (mem_should_fail())
        return NULL;
    return malloc(size ? size : 1);
}

void *mem_calloc(size_t count, size_t size)
{
    if ((size && count > SIZE_MAX / size) || mem_should_fail())
        return NULL;
    return count && size ? calloc(count, size) : calloc(1, 1);
}

void *mem_realloc(void *p, size_t size)
{
    if (mem_should_fail())
        return NULL;
    return realloc(p, size ? size : 1);
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

int mem_grow(void **p, size_t *cap, size_t need, size_t elem)
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
