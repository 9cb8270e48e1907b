/* pds_cpg_index — cell grid and priority hierarchy of a CPG union (see
 * pds_cpg_index.h). */
#include "pds/pds_cpg_index.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pds/pds_num.h"
#include "util/mem.h"

#define PDS_CPG_INDEX_GRID_MAX 512   /* cells a side */

/* Spreads the low 16 bits of x to the even bits (Morton interleave). */
static uint32_t pds_cpg_index_spread(uint32_t x)
{
    x &= 0xffff;
    x = (x | (x << 8)) & 0x00ff00ffu;
    x = (x | (x << 4)) & 0x0f0f0f0fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
}

typedef struct pds_cpg_index_keyed { uint32_t key, i; } pds_cpg_index_keyed;

static int pds_cpg_index_keyed_cmp(const void *pa, const void *pb)
{
    const pds_cpg_index_keyed *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return a->i < b->i ? -1 : a->i > b->i;
}

int NS(pds_cpg_index_morton)(const double (*xy)[2], size_t n, const double lo[2], const double hi[2],
                             uint32_t *order)
{
    pds_cpg_index_keyed *ks = mem_calloc(n ? n : 1, sizeof *ks);
    size_t k;
    int a;
    if (!ks)
        return -1;
    for (k = 0; k < n; k++) {
        uint32_t q[2];
        for (a = 0; a < 2; a++)
            q[a] = hi[a] > lo[a] ? (uint32_t)fmin(fmax((xy[k][a] - lo[a]) / (hi[a] - lo[a]) * 65535, 0), 65535) : 0;
        ks[k].key = pds_cpg_index_spread(q[0]) | pds_cpg_index_spread(q[1]) << 1;
        ks[k].i = (uint32_t)k;
    }
    qsort(ks, n, sizeof *ks, pds_cpg_index_keyed_cmp);
    for (k = 0; k < n; k++)
        order[k] = ks[k].i;
    mem_free(ks);
    return 0;
}

/* The hierarchy over operands ord[0..n) (indices into node, box, pos; in
 * Morton order), at x->h[x->nh]; returns its root. */
static uint32_t pds_cpg_index_bvh(NS(pds_cpg_index) *x, const uint32_t *ord, size_t n, const uint32_t *node,
                                  const num (*box)[4], const uint32_t *pos)
{
    uint32_t me = (uint32_t)x->nh++;
    NS(pds_cpg_bvh) *h = &x->h[me];
    if (n == 1) {
        memcpy(h->box, box[ord[0]], sizeof h->box);
        h->minp = pos[ord[0]];
        h->a = PDS_CPG_INDEX_LEAF;
        h->b = node[ord[0]];
    } else {
        uint32_t l = pds_cpg_index_bvh(x, ord, n / 2, node, box, pos);
        uint32_t r = pds_cpg_index_bvh(x, ord + n / 2, n - n / 2, node, box, pos);
        h = &x->h[me];
        memcpy(h->box, x->h[l].box, sizeof h->box);
        pds_num_box_grow(h->box, x->h[r].box);
        h->minp = x->h[l].minp < x->h[r].minp ? x->h[l].minp : x->h[r].minp;
        h->a = l;
        h->b = r;
    }
    return me;
}

/* Cell grid with gn cells a side over operands ord[0..n) (indices into
 * node and box, in operand order); 1 when the entries would exceed the
 * budget (the caller tries a coarser grid), -1 out of memory. */
static int pds_cpg_index_grid(NS(pds_cpg_index) *x, const uint32_t *ord, size_t n, const uint32_t *node,
                              const num (*box)[4], const num ubox[4], long gn)
{
    size_t total = 0, i, budget = 8 * n + (size_t)(gn * gn);
    long cx, cy, x0, x1, y0, y1, a;
    uint32_t *fill, *start;
    for (a = 0; a < 2; a++) {
        double lo = fmax(0, num_to_d(ubox[a])), hi = fmin(1, num_to_d(ubox[a + 2]));
        x->g0[a] = lo;
        x->gs[a] = hi > lo ? (double)gn / (hi - lo) : 0;
    }
    x->gn = gn;
    for (i = 0; i < n; i++) {
        const num *b = box[ord[i]];
        total += (size_t)(pds_cpg_index_cell(x, 0, b[2]) - pds_cpg_index_cell(x, 0, b[0]) + 1) *
                 (size_t)(pds_cpg_index_cell(x, 1, b[3]) - pds_cpg_index_cell(x, 1, b[1]) + 1);
        if (total > budget)
            return 1;
    }
    start = mem_calloc((size_t)(gn * gn + 1), sizeof *start);
    x->cells = mem_calloc((size_t)(gn * gn + 1), sizeof *x->cells);
    x->ops = mem_calloc(total ? total : 1, sizeof *x->ops);
    fill = mem_calloc((size_t)(gn * gn), sizeof *fill);
    if (!start || !x->cells || !x->ops || !fill) {
        mem_free(start);
        mem_free(fill);
        return -1;
    }
    for (i = 0; i < n; i++) {
        const num *b = box[ord[i]];
        x0 = pds_cpg_index_cell(x, 0, b[0]); x1 = pds_cpg_index_cell(x, 0, b[2]);
        y0 = pds_cpg_index_cell(x, 1, b[1]); y1 = pds_cpg_index_cell(x, 1, b[3]);
        for (cy = y0; cy <= y1; cy++)
            for (cx = x0; cx <= x1; cx++)
                start[cy * gn + cx + 1]++;
    }
    for (i = 0; i < (size_t)(gn * gn); i++)
        start[i + 1] += start[i];
    for (i = 0; i < n; i++) {       /* in operand order: lists come out ascending */
        const num *b = box[ord[i]];
        x0 = pds_cpg_index_cell(x, 0, b[0]); x1 = pds_cpg_index_cell(x, 0, b[2]);
        y0 = pds_cpg_index_cell(x, 1, b[1]); y1 = pds_cpg_index_cell(x, 1, b[3]);
        for (cy = y0; cy <= y1; cy++)
            for (cx = x0; cx <= x1; cx++) {
                long cell = cy * gn + cx;
                x->ops[start[cell] + fill[cell]++] = node[ord[i]];
            }
    }
    for (i = 0; i <= (size_t)(gn * gn); i++) {
        x->cells[i].start = start[i];
        x->cells[i].first = start[i] < total ? x->ops[start[i]] : 0;
    }
    x->nops = total;
    mem_free(start);
    mem_free(fill);
    return 0;
}

int NS(pds_cpg_index_build)(NS(pds_cpg_index) *x, size_t n, const uint32_t *node, const num (*box)[4],
                            const uint32_t *pos, size_t npos, const num ubox[4])
{
    uint32_t *ord = mem_calloc(n, sizeof *ord), *by = mem_calloc(npos, sizeof *by), longest = 0;
    double (*xy)[2] = mem_calloc(n, sizeof *xy), lo[2], hi[2];
    size_t i, w;
    long gn;
    int rc = -1;
    memset(x, 0, sizeof *x);
    if (!ord || !by || !xy)
        goto done;
    /* the cell lists are filled in operand order */
    for (i = 0; i < npos; i++)
        by[i] = UINT32_MAX;
    for (i = 0; i < n; i++)
        by[pos[i]] = (uint32_t)i;
    for (i = 0, w = 0; i < npos; i++)
        if (by[i] != UINT32_MAX)
            ord[w++] = by[i];
    for (gn = (long)ceil(sqrt((double)n)); gn > PDS_CPG_INDEX_GRID_MAX; gn /= 2)
        ;
    for (; gn >= 2; gn /= 2) {
        int g = pds_cpg_index_grid(x, ord, n, node, box, ubox, gn);
        if (g < 0)
            goto done;
        if (g == 0)
            break;
    }
    if (gn < 2)
        x->gn = 0;
    /* The hierarchy, unless every cell is short enough to scan (it would
     * never be read, and a lookup touches less memory without it). */
    for (i = 0; x->gn && i < (size_t)(x->gn * x->gn); i++)
        if (x->cells[i + 1].start - x->cells[i].start > longest)
            longest = x->cells[i + 1].start - x->cells[i].start;
    if (!x->gn || longest > PDS_CPG_INDEX_SCAN) {
        for (i = 0; i < n; i++) {
            xy[i][0] = 0.5 * (num_to_d(box[i][0]) + num_to_d(box[i][2]));
            xy[i][1] = 0.5 * (num_to_d(box[i][1]) + num_to_d(box[i][3]));
        }
        lo[0] = num_to_d(ubox[0]); lo[1] = num_to_d(ubox[1]);
        hi[0] = num_to_d(ubox[2]); hi[1] = num_to_d(ubox[3]);
        if (!(x->h = mem_calloc(2 * n - 1, sizeof *x->h)) || NS(pds_cpg_index_morton)((const double (*)[2])xy, n, lo, hi, ord))
            goto done;
        pds_cpg_index_bvh(x, ord, n, node, box, pos);
    }
    rc = 0;
done:
    if (rc)
        NS(pds_cpg_index_free)(x);
    mem_free(ord);
    mem_free(by);
    mem_free(xy);
    return rc;
}

void NS(pds_cpg_index_free)(NS(pds_cpg_index) *x)
{
    mem_free(x->h);
    mem_free(x->cells);
    mem_free(x->ops);
    memset(x, 0, sizeof *x);
}

size_t NS(pds_cpg_index_bytes)(const NS(pds_cpg_index) *x)
{
    return x->nh * sizeof *x->h +
           (x->gn ? (size_t)(x->gn * x->gn + 1) * sizeof *x->cells + x->nops * sizeof *x->ops : 0);
}
