/* pds_strip — Ballard's strip trees (D. H. Ballard, "Strip trees: a
 * hierarchical representation for curves", CACM 24(5), 1981, 310-321) over
 * a closed polyline, in the mode's numbers (modal).
 *
 * A node covers the chain of edges from vertex i0 to i1 and holds its strip:
 * the rectangle aligned with the chord i0-i1 (an axis-aligned one for the
 * root of a closed curve, whose chord is a point) that encloses the chain,
 * its widths wl + wr across the chord. A node is split at the vertex
 * farthest from its chord (Ballard's rule; within the middle half of the
 * chain, so the depth is O(log n)) until its width is at most the tolerance
 * or it holds PDS_STRIP_LEAF edges or fewer. The strip's corners are widened
 * by a few units of the mode before rounding, so they enclose the rounded
 * chain exactly and every test on them is an exact predicate (pds_num.h).
 *
 * Operations (Ballard, sections 3-5):
 *   pds_strip_inside      point membership of the region the curve bounds:
 *                         crossing parity of the half-line towards +u; a
 *                         strip the line meets only right of the point adds
 *                         [its end vertices lie on opposite sides of the
 *                         line], one it meets only left of the point adds
 *                         nothing; only strips straddling the point are
 *                         opened
 *   pds_strip_intersect   the crossings of two curves: strips that do not
 *                         overlap are pruned, the wider of two overlapping
 *                         strips is split, leaf edges are tested exactly
 *   pds_strip_regions_meet, _in_union, _in_inter: the union and intersection
 *                         of two regions so bounded (membership, and whether
 *                         they overlap at all: their boundaries cross or
 *                         one holds a vertex of the other) */
#ifndef PDS_STRIP_H
#define PDS_STRIP_H
#include <stddef.h>
#include <stdint.h>
#include "num/num.h"

#define PDS_STRIP_LEAF 8      /* edges per leaf, tested directly */

typedef struct NS(pds_strip_node) {
    num c[8];                 /* corners, counter-clockwise (u, v pairs) */
    num box[4];               /* their bounding box */
    double w;                 /* width wl + wr across the chord */
    uint32_t i0, i1;          /* vertex range */
    uint32_t left, right;     /* children; left == 0 for a leaf */
} NS(pds_strip_node);

typedef struct NS(pds_strip) {
    num *uv;                  /* n + 1 vertices (the first repeated last) */
    size_t n;
    NS(pds_strip_node) *nodes;
    size_t nnodes;
} NS(pds_strip);

/* Builds the strip tree of the closed polyline pts[2*n] (double, rounded
 * with num_from_d) down to width tol (0: down to the leaf size). 0, or -1
 * when memory runs out (*s zeroed). */
int NS(pds_strip_build)(NS(pds_strip) *s, const double *pts, size_t n, double tol);
void NS(pds_strip_free)(NS(pds_strip) *s);
size_t NS(pds_strip_bytes)(const NS(pds_strip) *s);

/* 1 if (u,v) lies inside or on the curve, else 0; adds visited nodes. */
int NS(pds_strip_inside)(const NS(pds_strip) *s, num u, num v, unsigned long *steps);

/* Crossings of the curves a and b: returns how many pairs of edges meet
 * (touching counts), stores up to `max` of them as edge index pairs
 * (edge k joins vertices k and k+1) in pairs[2*i], pairs[2*i+1]. Adds the
 * strip pairs compared to *steps. */
size_t NS(pds_strip_intersect)(const NS(pds_strip) *a, const NS(pds_strip) *b, uint32_t *pairs,
                               size_t max, unsigned long *steps);

/* Regions bounded by a and b: whether they share a point, and membership
 * of their union and intersection. */
int NS(pds_strip_regions_meet)(const NS(pds_strip) *a, const NS(pds_strip) *b);
int NS(pds_strip_in_union)(const NS(pds_strip) *a, const NS(pds_strip) *b, num u, num v);
int NS(pds_strip_in_inter)(const NS(pds_strip) *a, const NS(pds_strip) *b, num u, num v);
#endif
