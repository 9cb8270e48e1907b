/* arena — a bump allocator over one fixed block, for per-ray temporaries.
 * The renderer gives each thread one arena sized at scene-compile time (the
 * CSG evaluator knows its peak need), so tracing a ray never calls malloc.
 * Allocation is stack-like: arena_mark / arena_release free everything
 * allocated after the mark. */
#ifndef ARENA_H
#define ARENA_H
#include <stddef.h>

#define ARENA_ALIGN 16

typedef struct arena {
    unsigned char *base;
    size_t size, top;
} arena;

/* Allocates the block (through mem_alloc); 0 or -1 when memory runs out. */
int arena_init(arena *a, size_t size);
void arena_free(arena *a);

/* size bytes aligned to ARENA_ALIGN, or NULL when the block is exhausted. */
static inline void *arena_alloc(arena *a, size_t size)
{
    size_t need = (size + (ARENA_ALIGN - 1)) & ~(size_t)(ARENA_ALIGN - 1);
    void *p;
    if (need < size || need > a->size - a->top)
        return NULL;
    p = a->base + a->top;
    a->top += need;
    return p;
}
static inline size_t arena_mark(const arena *a) { return a->top; }
static inline void arena_release(arena *a, size_t mark) { a->top = mark; }
#endif
