/* csg — the CSG tree compiled for one numeric mode, and ray classification
 * by span lists (Roth 1982).
 *
 * At compile time chains of the same operator are flattened and rebuilt as
 * balanced trees over their operands, ordered by position (a bounding-volume
 * hierarchy), and a difference chain a - b - c - ... becomes a - (b u c u ...).
 * Every bounded node carries a bounding box, tested in binary64 (bbox.h:
 * culling only), and a leaf also its primitive's bounding sphere, tested in
 * the mode's arithmetic because its closest parameter is where the
 * primitive's solver starts; a ray that misses them skips the whole
 * subtree, so a slab minus N cylinders costs O(log N) per ray, not O(N).
 * Each rendered object (scene root) is a solid of its own: the bounded
 * ones are the items of a hierarchy of boxes (util/bvh.h) walked nearest
 * first, and the nearest surface of any object wins instead of a span
 * merge. A ray that leaves, from its origin, a primitive that holds its
 * whole object (the object's hull) cannot meet that object again and does
 * not classify it.
 * Modal: compiled per numeric mode. */
#ifndef GEOM_CSG_H
#define GEOM_CSG_H
#include "geom/prim.h"
#include "util/arena.h"
#include "util/bvh.h"
#include "util/lightbuf.h"

#define CSG_MAX_NEST 256     /* operator alternations allowed along a path */
/* Bounding boxes are padded outwards by this much (normalised units): far
 * above the rounding of the binary64 box test and of the mode's surface
 * points, whose coordinates stay below 2^14 (docs/numerics.md, "Culling in
 * binary64"): 2^-10, 64 units in q16's last place, or in a floating mode
 * 64 units in the last place of 2^14 where that is more (f32 2^-3, hfp32
 * 1). */
#if NUM_IS_FIXED
#define CSG_BOX_PAD (1.0 / 1024)
#else
#define CSG_BOX_PAD_ULPS (64 * 16384 * num_to_d(NUM_ULP))
#define CSG_BOX_PAD (CSG_BOX_PAD_ULPS > 1.0 / 1024 ? CSG_BOX_PAD_ULPS : 1.0 / 1024)
#endif

/* Half a 64-byte line (csg_build aligns the array): a node's visit reads
 * one line, and an object's nodes take half the lines they took with the
 * box in binary64 (docs/performance.md, run AT). The box is rounded
 * outwards to binary32, which only widens it by a unit in its last place
 * (2^-9 at the 2^14 the normalised world stays below): the test in
 * binary64 still only culls (bbox.h). A leaf's bounding sphere is its
 * primitive's (prim.bc, prim.br). */
typedef struct csg_node {
    float lo[3], hi[3];      /* bounding box (world), padded by CSG_BOX_PAD */
    unsigned left : 27;      /* an operator's left operand (csg_build
                                keeps indices below 2^26) */
    unsigned op : 2;         /* CSG_LEAF, CSG_UNION, CSG_INTER, CSG_DIFF */
    unsigned bounded : 1;
    unsigned same_box : 1;   /* the box is its parent's, whose test over the
                                same parameters stands for its own */
    int right;               /* an operator's right operand; a leaf's
                                primitive index (csg_leaf_prim) */
} csg_node;

typedef char csg_node_is_half_a_line[sizeof(csg_node) == 32 ? 1 : -1];

/* The primitive of leaf nd. */
static inline int csg_leaf_prim(const csg_node *nd) { return nd->right; }

/* Primitives recorded per object that contain it (csg->hull). */
#define CSG_HULL 4

/* Pending subtrees a query keeps on its own stack: a hierarchy less deep
 * than this needs no arena for them. bvh.h keeps the depth below
 * BVH_SAH_DEPTH + log2(n) + 1, so every hierarchy of up to 2^15 objects
 * qualifies; a deeper one keeps them in the query's arena. */
#define CSG_TODO_LOCAL 64

/* The frame change of a turned instance: a point p of the object
 * stands at q p + shift_d (csg_inst) in its master. */
typedef struct csg_turn {
    double q[9];             /* row-major rotation */
    double lo[3], hi[3];     /* the object's own box, padded */
} csg_turn;

/* An object traced through an earlier object's compiled tree (an
 * instance, model/scene_inst.h): the ray carried by turn->q (where
 * turned) and moved by shift meets that tree's primitives where it would
 * meet the object's own, and primitive i of the object (first <= i <
 * first + count) stands where that tree's i - dprim does. count 0: the
 * object's own tree. */
typedef struct csg_inst {
    vec3 shift;              /* in num; |shift| < 2 sqrt(3) GEOM_W */
    double shift_d[3];       /* the same in binary64 */
    int master;              /* while building: the root index copied */
    int first, count, dprim;
    const csg_turn *turn;    /* NULL: translated, the ray only moves; else
                                kept by the caller of csg_build as long as
                                the tree */
} csg_inst;

typedef struct csg {
    const prim *prims;       /* the compiled primitives the leaves name */
    csg_node *nodes;         /* in the block at nodes_mem, from its first
                                64-byte boundary */
    void *nodes_mem;
    int nnodes;
    int *objects;            /* each object's compiled root: the bounded ones
                                (the hierarchy's items) first; an
                                instance's as ~root, its master's (inst[k]
                                moves the ray), so one load tells them */
    int (*hull)[CSG_HULL];   /* per object (as objects[]): up to CSG_HULL
                                primitives that contain the whole object
                                (reached from its root through intersections
                                and left operands of differences), -1 after */
    int nobjects, nbounded;
    double (*olo)[3], (*ohi)[3];
                             /* the bounded objects' boxes (their roots'
                                again), as objects[]: what the hierarchy and
                                the light buffers are built over, and what
                                a buffered query tests of each object in its
                                cell, read from 240 KB arrays at 10,000
                                objects, not from the roots among 3 MB of
                                nodes */
    csg_inst *inst;          /* per object (as objects[]), or NULL where
                                none is an instance */
    int ninst;
    bvh objtree;             /* over objects[0 .. nbounded - 1] */
    size_t peak_spans;       /* span storage one query needs at most */
    int whole;               /* classify each object whole, without
                                csg_diff_first's shortcuts (tests' reference) */
} csg;

/* A child of the object hierarchy (bvh.h) that the traversal will visit
 * if the far end still allows, and where the ray enters its box. */
typedef struct csg_todo { int kid; double tin; } csg_todo;

/* The nearest surface crossing along a ray. */
typedef struct csg_hit {
    num t;
    int prim, face;
    int entering;            /* 1: the ray enters the solid there (outward
                                normal faces the ray), 0: it leaves it */
} csg_hit;

/* Builds the compiled tree of sc over the compiled primitives prims (kept
 * by the tree: the queries read them), compiled into a world of scale
 * `scale` (geom_norm: their boxes come from scene_prim_canon_map). inst: NULL, or per root of sc its
 * csg_inst, master naming an earlier root, itself none, whose tree the
 * root's object is traced through (its own primitives need not be
 * compiled).
 * 0 on success; DIAG_INPUT for malformed trees (bad indices, cycles, nesting
 * deeper than CSG_MAX_NEST); DIAG_IO when memory runs out. */
int NS(csg_build)(const scene *sc, const prim *prims, double scale, const csg_inst *inst, csg *out,
                  diag *err);
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
int NS(csg_intersect)(const csg *c, const prim_ray *r, num tmax, arena *ar, geom_stats *st, csg_hit *hit);
/* Some surface crossing with 0 < t <= tmax (not always the nearest): for
 * shadow rays through opaque scenes. Returns 1 and *hit, or 0. */
int NS(csg_occluded)(const csg *c, const prim_ray *r, num tmax, arena *ar, geom_stats *st, csg_hit *hit);
/* The same for a ray that leaves the point of the light buffer lb (a camera
 * ray from the eye), and for one that goes to it (a shadow ray to a
 * light): lb is over the bounded objects (objects[0 .. nbounded - 1]), and
 * where it answers for the ray (lightbuf_lookup), the objects of the
 * ray's cell are tested instead of the hierarchy's; the answers are the
 * same (docs/numerics.md, "Culling in binary64"). */
int NS(csg_intersect_from)(const csg *c, const lightbuf *lb, const prim_ray *r, num tmax, arena *ar,
                           geom_stats *st, csg_hit *hit);
int NS(csg_occluded_to)(const csg *c, const lightbuf *lb, const prim_ray *r, num tmax, arena *ar, geom_stats *st,
                        csg_hit *hit);
#endif
