/* prim_twin — scene primitives that differ only in where they are (see
 * prim_twin.h). Open addressing with linear probing, at most half full. */
#include "model/prim_twin.h"
#include "util/mem.h"
#include <stdint.h>
#include <string.h>

/* The words compared: the dimensions, then the linear part of the row-major
 * 3x4 world_from_object (its translation column left out). */
static const int prim_twin_lin[9] = {0, 1, 2, 4, 5, 6, 8, 9, 10};

int prim_twin_same(const scene_prim *a, const scene_prim *b)
{
    int k;
    if (!scene_shape_alike(a->shape, b->shape))
        return 0;
    for (k = 0; k < 9; k++)
        if (memcmp(&a->world_from_object[prim_twin_lin[k]], &b->world_from_object[prim_twin_lin[k]],
                   sizeof(double)))
            return 0;
    return 1;
}

/* A hash of exactly the bits prim_twin_same compares (FNV-1a over 64-bit
 * words, then a final mix of the high bits into the low ones). */
uint64_t prim_twin_hash(const scene_prim *sp)
{
    uint64_t h = 0xcbf29ce484222325u ^ (uint64_t)sp->shape->kind, w;
    int k;
    for (k = 0; k < 12; k++) {
        const double *v = k < 3 ? &sp->shape->dim[k] : &sp->world_from_object[prim_twin_lin[k - 3]];
        memcpy(&w, v, sizeof w);
        h = (h ^ w) * 0x100000001b3u;
    }
    h ^= h >> 32;
    h *= 0xd6e8feb86659fd93u;
    return h ^ (h >> 32);
}

/* A table of cap entries (a power of two), all empty. */
static prim_twin_entry *prim_twin_table(size_t cap)
{
    prim_twin_entry *e;
    size_t i;
    if (cap > SIZE_MAX / sizeof *e || !(e = mem_alloc(cap * sizeof *e)))
        return NULL;
    for (i = 0; i < cap; i++)
        e[i].index = PRIM_TWIN_NONE;
    return e;
}

int prim_twin_init(prim_twin *t)
{
    t->mask = 15;
    t->used = t->looked = t->met = 0;
    return (t->e = prim_twin_table(t->mask + 1)) ? 0 : -1;
}

void prim_twin_free(prim_twin *t)
{
    mem_free(t->e);
    t->e = NULL;
}

prim_twin_entry *prim_twin_at(prim_twin *t, const scene_prim *prims, const scene_prim *sp)
{
    uint64_t h;
    size_t i;
    if (t->e && t->looked >= PRIM_TWIN_TRIAL && t->met < t->looked / PRIM_TWIN_RARE)
        prim_twin_free(t);
    if (!t->e)
        return NULL;
    h = prim_twin_hash(sp);
    i = (size_t)h & t->mask;
    while (t->e[i].index != PRIM_TWIN_NONE
           && (t->e[i].hash != (uint32_t)h || !prim_twin_same(&prims[t->e[i].index], sp)))
        i = (i + 1) & t->mask;
    t->looked++;
    t->met += t->e[i].index != PRIM_TWIN_NONE;
    return &t->e[i];
}

int prim_twin_add(prim_twin *t, const scene_prim *prims, prim_twin_entry *e, size_t index, double note)
{
    prim_twin_entry *old = t->e, *grown;
    size_t cap = t->mask + 1, i;
    if (index >= PRIM_TWIN_NONE)
        return 0;
    e->index = (uint32_t)index;
    e->hash = (uint32_t)prim_twin_hash(&prims[index]);
    e->note = note;
    if (++t->used <= cap / 2)
        return 0;
    /* the stored bits place each entry in a table of up to 2^32 */
    if (cap > SIZE_MAX / 2 || cap > ((size_t)1 << 31) || !(grown = prim_twin_table(2 * cap))) {
        e->index = PRIM_TWIN_NONE;
        t->used--;
        return -1;
    }
    t->e = grown;
    t->mask = 2 * cap - 1;
    for (i = 0; i < cap; i++)
        if (old[i].index != PRIM_TWIN_NONE) {
            size_t j = old[i].hash & t->mask;
            while (t->e[j].index != PRIM_TWIN_NONE)
                j = (j + 1) & t->mask;
            t->e[j] = old[i];
        }
    mem_free(old);
    return 0;
}
