/* pds_ring — a closed polyline compiled for point membership: vertices in
 * the mode's numbers and a strip tree over its edges (modal; used by CPG
 * polygons and by curve-bounded regions).
 *
 * Strip tree: each node covers the chain of edges from vertex i0 to i1 and
 * holds the chain's bounding box. The chain is split at the vertex farthest
 * from the chord i0-i1 (Ballard's rule), restricted to the middle half of the
 * chain so the depth stays O(log n). Membership counts crossings of the
 * half-line from (u,v) towards +u: a subtree whose box misses the line
 * contributes nothing, and one whose box lies wholly right of the point
 * contributes exactly [end vertices on opposite sides of the line], so only
 * nodes whose boxes straddle the point are opened. (Chord-aligned strips
 * as in Ballard's paper were measured slower here; docs/pds.md.) */
#ifndef PDS_RING_H
#define PDS_RING_H
#include <stddef.h>
#include <stdint.h>
#include "num/num.h"

#define PDS_RING_LEAF 8    /* edges per leaf, tested directly */

typedef struct NS(pds_ring_node) {
    num box[4];                 /* u0 v0 u1 v1 of the chain */
    uint32_t i0, i1;            /* vertex range */
    uint32_t left, right;       /* children; left == 0 for a leaf */
} NS(pds_ring_node);

typedef struct NS(pds_ring) {
    num *uv;                    /* n + 1 vertices (the first repeated last) */
    size_t n;
    NS(pds_ring_node) *nodes;   /* nodes[0] is the root */
    size_t nnodes;
} NS(pds_ring);

/* Compiles the closed polyline pts[2*n] (double, rounded with num_from_d).
 * Returns 0, or -1 when memory runs out (then *r is zeroed). */
int NS(pds_ring_build)(NS(pds_ring) *r, const double *pts, size_t n);
void NS(pds_ring_free)(NS(pds_ring) *r);

/* 1 if (u,v) lies inside or on the ring, else 0; adds visited nodes to *steps. */
int NS(pds_ring_inside)(const NS(pds_ring) *r, num u, num v, unsigned long *steps);

/* Chain helpers shared with the strip trees (pds_strip.h), over closed
 * vertex arrays uv of n + 1 points (the first repeated last):
 *   pds_ring_vertices  rounds pts[2*n] into a new such array (NULL: out
 *                      of memory)
 *   pds_ring_split     Ballard's split of the chain i0..i1: the vertex
 *                      farthest from its chord, within the middle half
 *   pds_ring_edges     crossing parity of edges i0..i1 at (u,v): 0 or 1,
 *                      2 when the point lies on one
 *   pds_ring_edges_open  the same over all n edges of a polygon stored as
 *                      its n vertices, the first not repeated last (small
 *                      polygons kept inline by the CPG: one vertex less) */
num *NS(pds_ring_vertices)(const double *pts, size_t n);
uint32_t NS(pds_ring_split)(const num *uv, uint32_t i0, uint32_t i1);
int NS(pds_ring_edges)(const num *uv, uint32_t i0, uint32_t i1, num u, num v);
int NS(pds_ring_edges_open)(const num *uv, uint32_t n, num u, num v);
#endif
