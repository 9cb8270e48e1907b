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
#include "model/scene.h"

#define PRIM_TWIN_NONE ((size_t)-1)

/* An entry: the index of the first primitive of its set of twins (or
 * PRIM_TWIN_NONE while empty) and a value its user keeps with it. */
typedef struct prim_twin_entry {
    size_t index;
    double note;
} prim_twin_entry;

typedef struct prim_twin {
    prim_twin_entry *e;
    size_t mask;               /* entries - 1, a power of two less one */
} prim_twin;

/* An empty index for up to n primitives. 0, or -1 when n is beyond what
 * can be allocated or memory runs out. */
int prim_twin_init(prim_twin *t, size_t n);
void prim_twin_free(prim_twin *t);

/* The entry of sp among primitives of prims: an earlier primitive's, whose
 * kind, dimensions and linear part are sp's bit for bit, or the empty one
 * where sp belongs, which the caller fills (index, note) to enter sp. At
 * most n primitives may be entered (prim_twin_init). */
prim_twin_entry *prim_twin_at(const prim_twin *t, const scene_prim *prims, const scene_prim *sp);
#endif
