/* mem — the one allocation hook. Every heap allocation in maprt goes through
 * these functions so that tests can fail the Nth allocation (mem_fail_after)
 * and check that each caller reports the failure instead of crashing. */
#ifndef MEM_H
#define MEM_H
#include <stddef.h>
#include <stdint.h>

/* NULL means failure only: a request for zero bytes returns a valid pointer
 * that mem_free releases. */
void *mem_alloc(size_t size);                 /* NULL on failure */
void *mem_calloc(size_t count, size_t size);  /* NULL on failure or overflow of count*size */
void *mem_realloc(void *p, size_t size);      /* NULL on failure; p untouched */
/* As mem_calloc, for an array of which few elements may ever be written:
 * without the huge-page advice below, a write faults in 4 KiB, not 2 MiB
 * (the compiled scene's per-primitive arrays where instances leave most
 * of them unwritten). */
void *mem_calloc_sparse(size_t count, size_t size);
/* As mem_calloc, for an array of which about the first `likely` elements
 * are written (a bound on the count that is twice what most inputs
 * need): the advice covers the huge pages those elements fill, and the
 * rest faults in 4 KiB pages as it is written, so that a huge page is not
 * cleared for the few elements that spill into it (the CSG compile's
 * nodes, docs/performance.md, run AV). */
void *mem_calloc_part(size_t count, size_t size, size_t likely);
void  mem_free(void *p);
char *mem_strdup(const char *s);

/* Grows *p (an array of *cap elements of elem bytes) to hold at least need
 * elements (at least one, so that *p is allocated even for need 0), doubling;
 * returns 0 on success, -1 on overflow or failure (then *p
 * and *cap are unchanged). Inline, as most calls find the room there:
 * appending one element at a time then costs a compare, not a call. */
int mem_grow_realloc(void **p, size_t *cap, size_t need, size_t elem);
static inline int mem_grow(void **p, size_t *cap, size_t need, size_t elem)
{
    return need && need <= *cap ? 0 : mem_grow_realloc(p, cap, need, elem);
}

/* The first 64-byte boundary (a cache line) at or after p, NULL for NULL:
 * an array whose elements are read a line at a time is allocated one
 * element (of at least 64 bytes) longer and used from there, the block
 * still freed as allocated. */
#define MEM_LINE ((uintptr_t)64)
static inline void *mem_align_line(void *p)
{
    return p ? (void *)(((uintptr_t)p + MEM_LINE - 1) & ~(MEM_LINE - 1)) : NULL;
}

/* Blocks of MEM_HUGE_MIN bytes or more are advised for transparent huge
 * pages where Linux offers them (mem.c says why). mem_huge_size gives the
 * bytes asked of malloc for a block of size bytes: for a large block, the
 * next size that with MEM_HUGE_SLACK bytes of header fills a whole number
 * of 2 MiB pages. mem_huge_range gives the range advised for a block of
 * size bytes at address p, as 1 and *start, *len (0 when there is none):
 * the 2 MiB pages the block covers, a page counted when the block starts
 * less than MEM_HUGE_SLACK bytes past its start or ends less than that
 * before its end. */
#define MEM_HUGE_PAGE ((uintptr_t)2 << 20)
#define MEM_HUGE_MIN ((size_t)2 << 20)
#define MEM_HUGE_SLACK ((uintptr_t)32)
size_t mem_huge_size(size_t size);
int mem_huge_range(uintptr_t p, size_t size, uintptr_t *start, size_t *len);

/* Test hook: allocations succeed n more times, then fail; n < 0 disables.
 * mem_alloc_count() is the number of successful allocations so far. */
void mem_fail_after(long n);
long mem_alloc_count(void);
#endif
