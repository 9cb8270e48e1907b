/* pds_cpg_index — the index of one CPG union of many operands (modal; built
 * by pds_cpg, read by its lookup).
 *
 *   - a cell grid over the union's box (clipped to the unit square): per
 *     cell, the operands whose boxes meet it, in operand order. The cell of
 *     a coordinate is a monotone function of it (pds_cpg_index_cell), so a
 *     box and every point in it agree on the cells, and the first listed
 *     operand that contains the point wins. A cell keeps a copy of its
 *     list's first entry: most lookups are decided by it, and then read the
 *     cell and the operand, not the list as well;
 *   - where some cell lists more than PDS_CPG_INDEX_SCAN operands (heavy
 *     overlap), a bounding hierarchy over the operands, built in space
 *     (Morton order of the box centres, halved recursively), each node
 *     keeping the lowest operand position below it: a lookup keeps the best
 *     (lowest) position found so far and skips every subtree that cannot
 *     beat it, so the result is the linear scan's first operand that
 *     contains the point.
 * Operands are named by their node index in the CPG's node array. */
#ifndef PDS_CPG_INDEX_H
#define PDS_CPG_INDEX_H
#include <stddef.h>
#include <stdint.h>
#include "num/num.h"

#define PDS_CPG_INDEX_SCAN 24          /* longer cell lists use the hierarchy */
#define PDS_CPG_INDEX_LEAF UINT32_MAX  /* bvh.a of a leaf */

/* Hierarchy node: box of the operands below, the lowest of their operand
 * positions, children a, b, or a == PDS_CPG_INDEX_LEAF and b the operand. */
typedef struct NS(pds_cpg_bvh) {
    num box[4];
    uint32_t minp, a, b;
} NS(pds_cpg_bvh);

/* A cell: where its list starts in ops (the next cell's start ends it) and
 * a copy of the list's first entry (unused when the list is empty). */
typedef struct NS(pds_cpg_cell) {
    uint32_t start, first;
} NS(pds_cpg_cell);

typedef struct NS(pds_cpg_index) {
    NS(pds_cpg_bvh) *h;        /* 2 n - 1 nodes, root first; NULL: none */
    size_t nh;
    NS(pds_cpg_cell) *cells;   /* gn * gn + 1; NULL: no cell grid */
    uint32_t *ops;             /* operands per cell, in operand order */
    size_t nops;
    double g0[2], gs[2];       /* cell of x = floor((x - g0) * gs), clamped */
    long gn;                   /* cells a side; 0: hierarchy only */
} NS(pds_cpg_index);

/* Indexes the n operands node[i] with boxes box[i] (none empty) and
 * distinct operand positions pos[i] < npos, listed in memory order, of a
 * union whose box is ubox. 0, or -1 out of memory (then *x is zeroed). */
int NS(pds_cpg_index_build)(NS(pds_cpg_index) *x, size_t n, const uint32_t *node, const num (*box)[4],
                            const uint32_t *pos, size_t npos, const num ubox[4]);
void NS(pds_cpg_index_free)(NS(pds_cpg_index) *x);
size_t NS(pds_cpg_index_bytes)(const NS(pds_cpg_index) *x);

/* Morton order of the n points xy[i] scaled from [lo, hi] to 16 bits a
 * side (ties: lower i first): order[k] is the k-th point. 0, or -1 out of
 * memory. Also used to lay out a union's operands in memory. */
int NS(pds_cpg_index_morton)(const double (*xy)[2], size_t n, const double lo[2], const double hi[2],
                             uint32_t *order);

/* Cell of coordinate v on one axis: a monotone function of v. */
static inline long pds_cpg_index_cell(const NS(pds_cpg_index) *x, int axis, num v)
{
    double t = (num_to_d(v) - x->g0[axis]) * x->gs[axis];
    if (!(t > 0))
        return 0;
    return t >= (double)x->gn ? x->gn - 1 : (long)t;
}
#endif
