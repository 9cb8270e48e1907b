/* arena — fixed-block bump allocator (see arena.h). */
#include "util/arena.h"
#include "util/mem.h"

int arena_init(arena *a, size_t size)
{
    a->base = NULL;
    a->size = a->top = 0;
    if (size > (size_t)-1 - ARENA_ALIGN)    /* the rounding below would wrap */
        return -1;
    size = (size + (ARENA_ALIGN - 1)) & ~(size_t)(ARENA_ALIGN - 1);
    a->base = mem_alloc(size ? size : ARENA_ALIGN);
    if (!a->base)
        return -1;
    a->size = size ? size : ARENA_ALIGN;
    a->top = 0;
    return 0;
}

void arena_free(arena *a)
{
    mem_free(a->base);
    a->base = NULL;
    a->size = a->top = 0;
}
