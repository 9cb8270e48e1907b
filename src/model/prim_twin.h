/* prim_twin — scene primitives that differ only in where they are: an
 * index of a scene's primitives by kind, dimensions and the linear part of
 * world_from_object, bit for bit. A grid of copies of one part holds few
 * distinct primitives many times over, and the scene compiler takes from
 * the first of each set of twins everything it derives from those alone
 * (the canonical map, its inverse, the plane normals, the bounding radius:
 * prim_compile; docs/performance.md, run AC). */
#ifndef MODEL_PRIM_TWIN_H
#define MODEL_PRIM_TWIN_H
#include <stddef.h>
#include <stdint.h>
#include "model/scene.h"

#define PRIM_TWIN_NONE UINT32_MAX

/* An entry: the index of the first primitive of its set of twins (or
 * PRIM_TWIN_NONE while empty), a value its user keeps with it, and the low
 * bits of its hash: a probe that meets another set's entry tells it apart
 * by those, without reading that primitive (scattered through the scene's
 * primitives where few are twins), and the table grows without reading
 * any. */
typedef struct prim_twin_entry {
    double note;
    uint32_t index;
    uint32_t hash;
} prim_twin_entry;

typedef struct prim_twin {
    prim_twin_entry *e;        /* NULL once closed */
    size_t mask;               /* entries - 1, a power of two less one */
    size_t used;               /* entries filled, at most half of them */
    size_t looked, met;        /* lookups, and those that found a twin */
} prim_twin;

/* The index closes where twins are rare: once PRIM_TWIN_TRIAL primitives
 * have been looked up and fewer than one in PRIM_TWIN_RARE of them found
 * a twin, it frees its table and every later lookup answers NULL. The
 * rest are then compiled on their own, to the same bits (a twin hands on
 * only what the same kind, dimensions and linear part give). Open, the
 * table of 10,000 distinct parts grows to 2 MiB and each lookup misses
 * the cache: 5 to 9 % of the load (docs/performance.md, run AS). A deck
 * whose copies all come after that many distinct primitives compiles
 * those copies on their own too: more work, the same picture. */
#define PRIM_TWIN_TRIAL 4096
#define PRIM_TWIN_RARE 16

/* 1 when a and b are twins: kind, dimensions and the linear part of
 * world_from_object alike bit for bit. */
int prim_twin_same(const scene_prim *a, const scene_prim *b);
/* A hash of exactly the bits prim_twin_same compares. */
uint64_t prim_twin_hash(const scene_prim *sp);

/* An empty index. It grows with the sets of twins entered, not with the
 * primitives looked up: a grid of 10,000 copies of one part holds a few
 * sets, in a table that stays in the L1 cache (docs/performance.md, run
 * AH). 0, or -1 when memory runs out. */
int prim_twin_init(prim_twin *t);
void prim_twin_free(prim_twin *t);

/* The entry of sp among primitives of prims: an earlier primitive's, whose
 * kind, dimensions and linear part are sp's bit for bit, or the empty one
 * where sp belongs, which prim_twin_add fills to enter sp; NULL once the
 * index has closed. Each answered lookup is counted towards closing. */
prim_twin_entry *prim_twin_at(prim_twin *t, const scene_prim *prims, const scene_prim *sp);

/* Enters primitive `index` of prims with its note in e, the empty entry
 * prim_twin_at gave for it; an index of PRIM_TWIN_NONE or more is not
 * entered (it has no twins). The table doubles once it is half full, which
 * moves every entry: no entry pointer outlives this call. 0, or -1 when
 * memory runs out (the index is then unchanged but for e). */
int prim_twin_add(prim_twin *t, const scene_prim *prims, prim_twin_entry *e, size_t index, double note);
#endif
