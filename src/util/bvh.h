/* bvh — a binary bounding-volume hierarchy over n boxes (binary64), built
 * once per scene by the surface area heuristic, for the traversal that
 * finds which of a scene's objects a ray can meet (geom/csg.c).
 *
 * Each node holds its two children's boxes, axis by axis side by side
 * (lo[axis][child]), so one node fetch tests both children. A child index
 * k >= 0 is a node; k < 0 is the item ~k. Nodes are laid out depth first,
 * a node's first child right after it. */
#ifndef UTIL_BVH_H
#define UTIL_BVH_H
#include <stddef.h>

/* Deepest the tree grows: past this depth the builder splits at the
 * median, so the depth stays below BVH_SAH_DEPTH + log2(n) + 1. */
#define BVH_SAH_DEPTH 48

typedef struct bvh_node {
    double lo[3][2], hi[3][2];
    int kid[2];
} bvh_node;

typedef struct bvh {
    bvh_node *nodes;     /* n - 1 nodes for n >= 2 items, none else */
    int nnodes;
    int root;            /* a child index as above; unused for n = 0 */
    int depth;           /* nodes on the longest root-to-item path */
} bvh;

/* Builds the hierarchy over items 0..n-1 with boxes lo[i], hi[i] (lo <= hi
 * on every axis, finite). 0, or -1 when memory runs out or n exceeds 2^28
 * (out then holds nothing). */
int bvh_build(const double (*lo)[3], const double (*hi)[3], size_t n, bvh *out);
void bvh_free(bvh *b);
#endif
