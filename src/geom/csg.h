/* csg — the CSG tree compiled for one numeric mode, and ray classification
 * by span lists (Roth 1982).
 *
 * At compile time chains of the same operator are flattened and rebuilt as
 * balanced trees over their operands, ordered by position (a bounding-volume
 * hierarchy), and a difference chain a - b - c - ... becomes a - (b u c u ...).
 * Every bounded node carries a bounding sphere (a division-free test) and,
 * where it is much tighter, a bounding box; a ray that misses them skips the
 * whole subtree, so a slab minus N cylinders costs O(log N) per ray, not
 * O(N). Each rendered object (scene root) is a solid of its own: the
 * objects form a tree of CSG_GROUP nodes, bounded like unions, where the
 * nearest surface of any object wins instead of a span merge.
 * Modal: compiled per numeric mode. */
#ifndef GEOM_CSG_H
#define GEOM_CSG_H
#include "geom/prim.h"
#include "util/arena.h"

#define CSG_MAX_NEST 256     /* operator alternations allowed along a path */
#define CSG_GROUP (CSG_DIFF + 1)   /* compiled only: a set of separate objects */

typedef struct csg_node {
    int op;                  /* CSG_LEAF, CSG_UNION, CSG_INTER, CSG_DIFF, CSG_GROUP */
    int left, right;         /* operator operands (compiled node indices) */
    int prim;                /* leaf: primitive index */
    int bounded;
    vec3 bc;                 /* bounding sphere (world) */
    num br;
    int use_box;             /* the box is much tighter than the sphere */
    vec3 lo, hi;             /* bounding box (world), inside the sphere */
} csg_node;

typedef struct csg {
    csg_node *nodes;
    int nnodes;
    int root;                /* -1: nothing to render */
    size_t peak_spans;       /* span storage one query needs at most */
} csg;

/* The nearest surface crossing along a ray. */
typedef struct csg_hit {
    num t;
    int prim, face;
    int entering;            /* 1: the ray enters the solid there (outward
                                normal faces the ray), 0: it leaves it */
} csg_hit;

/* Builds the compiled tree of sc over the compiled primitives prims.
 * 0 on success; DIAG_INPUT for malformed trees (bad indices, cycles, nesting
 * deeper than CSG_MAX_NEST); DIAG_IO when memory runs out. */
int NS(csg_build)(const scene *sc, const prim *prims, csg *out, diag *err);
void NS(csg_free)(csg *c);
/* Bytes of arena a thread needs for csg_intersect. */
size_t NS(csg_arena_bytes)(const csg *c);

/* Nearest surface crossing with 0 < t <= tmax over all objects. The far end
 * shrinks to every hit found, so objects behind it are skipped by their
 * bounds.
 * At equal parameters a surface the ray enters wins over one it leaves (a
 * touching object shows its contact face), then the lower primitive.
 * Returns 1 and *hit, or 0. Temporaries come from ar (released before
 * returning); counters go to st. */
int NS(csg_intersect)(const csg *c, const prim *prims, const prim_ray *r, num tmax,
                      arena *ar, geom_stats *st, csg_hit *hit);
/* Some surface crossing with 0 < t <= tmax (not always the nearest): for
 * shadow rays through opaque scenes. Returns 1 and *hit, or 0. */
int NS(csg_occluded)(const csg *c, const prim *prims, const prim_ray *r, num tmax,
                     arena *ar, geom_stats *st, csg_hit *hit);
#endif
