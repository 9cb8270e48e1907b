/* pds_quadtree — region quadtree PDS (modal). The tree partitions a W x H
 * cell grid (W = H = 2^depth for an explicit tree); a lookup converts (u,v)
 * to a cell exactly as the pixel array does, then descends one level per
 * step, so it costs O(depth). Built from a pixel array, a node becomes a
 * leaf as soon as its cells share one id (Samet's region quadtree); an odd
 * range splits with the larger half first, and a range one cell wide only
 * splits the other way (its empty quadrants are never reached). */
#include "pds/pds_kind.h"
#include <string.h>
#include "pds/pds_num.h"
#include "util/mem.h"

typedef struct qnode {
    int32_t v;           /* >= -1: leaf id; <= -2: children at -v - 2 .. +3 */
    uint16_t xm, ym;     /* split cell: SW/SE by ix < xm, lower/upper by iy < ym */
} qnode;

typedef struct quadtree {
    long w, h;
    qnode *nodes; size_t nnodes, cap;
    const int32_t *grid; /* build-time only: cells from v = 0 */
    const int32_t *code; size_t pos;
} quadtree;

static void pds_quadtree_release(void *impl)
{
    quadtree *q = impl;
    if (q)
        mem_free(q->nodes);
    mem_free(q);
}

/* Reserves four consecutive child nodes; returns the first index or -1. */
static long pds_quadtree_children(quadtree *q)
{
    size_t base = q->nnodes;
    if (mem_grow((void **)&q->nodes, &q->cap, base + 4, sizeof *q->nodes))
        return -1;
    memset(q->nodes + base, 0, 4 * sizeof *q->nodes);
    q->nnodes += 4;
    return (long)base;
}

static int pds_quadtree_build_grid(quadtree *q, size_t idx, long x0, long x1, long y0, long y1)
{
    long x, y, xm, ym, base;
    int32_t first;
    if (x0 >= x1 || y0 >= y1) {
        q->nodes[idx].v = PDS_NONE;
        return 0;
    }
    first = q->grid[y0 * q->w + x0];
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++)
            if (q->grid[y * q->w + x] != first)
                goto split;
    q->nodes[idx].v = first;
    return 0;
split:
    xm = x1 - x0 == 1 ? x1 : x0 + (x1 - x0 + 1) / 2;
    ym = y1 - y0 == 1 ? y1 : y0 + (y1 - y0 + 1) / 2;
    base = pds_quadtree_children(q);
    if (base < 0)
        return -1;
    q->nodes[idx].v = (int32_t)(-base - 2);
    q->nodes[idx].xm = (uint16_t)xm;
    q->nodes[idx].ym = (uint16_t)ym;
    return pds_quadtree_build_grid(q, (size_t)base, x0, xm, y0, ym) || pds_quadtree_build_grid(q, (size_t)base + 1, xm, x1, y0, ym) ||
           pds_quadtree_build_grid(q, (size_t)base + 2, x0, xm, ym, y1) || pds_quadtree_build_grid(q, (size_t)base + 3, xm, x1, ym, y1);
}

static int pds_quadtree_build_code(quadtree *q, size_t idx, long x0, long y0, long size)
{
    int32_t c = q->code[q->pos++];
    long base, half = size / 2, k;
    if (c != PDS_QT_SPLIT) {
        q->nodes[idx].v = c;
        return 0;
    }
    base = pds_quadtree_children(q);
    if (base < 0)
        return -1;
    q->nodes[idx].v = (int32_t)(-base - 2);
    q->nodes[idx].xm = (uint16_t)(x0 + half);
    q->nodes[idx].ym = (uint16_t)(y0 + half);
    for (k = 0; k < 4; k++)
        if (pds_quadtree_build_code(q, (size_t)base + (size_t)k, x0 + (k & 1) * half, y0 + (k >> 1) * half, half))
            return -1;
    return 0;
}

static int pds_quadtree_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_quadtree *src = &def->quad;
    quadtree *q = mem_calloc(1, sizeof *q);
    int32_t *grid = NULL;
    int rc;
    if (!q || mem_grow((void **)&q->nodes, &q->cap, 1, sizeof *q->nodes))
        goto oom;
    q->nnodes = 1;
    q->nodes[0].v = PDS_NONE;
    if (src->from_pixels) {
        long j;
        q->w = src->pixels.width;
        q->h = src->pixels.height;
        grid = mem_calloc(src->pixels.ncells, sizeof *grid);
        if (!grid)
            goto oom;
        for (j = 0; j < q->h; j++)
            memcpy(grid + j * q->w, src->pixels.cells + (q->h - 1 - j) * q->w, (size_t)q->w * sizeof *grid);
        q->grid = grid;
        rc = pds_quadtree_build_grid(q, 0, 0, q->w, 0, q->h);
        mem_free(grid);
        q->grid = NULL;
    } else {
        /* Depth of the explicit tree fixes the grid: 2^depth cells a side. */
        size_t i;
        int depth = 0, d = 0, maxd = 0;
        unsigned char need[PDS_QT_MAX_DEPTH + 2];
        for (i = 0; i < src->ncode; i++) {
            if (src->code[i] == PDS_QT_SPLIT) {
                need[++d] = 4;
                if (d > maxd)
                    maxd = d;
                continue;
            }
            while (d > 0 && --need[d] == 0)
                d--;
        }
        depth = maxd;
        q->w = q->h = 1L << depth;
        q->code = src->code;
        rc = pds_quadtree_build_code(q, 0, 0, 0, q->w);
        q->code = NULL;
    }
    if (rc)
        goto oom;
    *out = q;
    return 0;
oom:
    pds_quadtree_release(q);
    return NS(pds_oom)(def, file, err);
}

static int32_t pds_quadtree_locate(const void *impl, num u, num v, unsigned long *steps)
{
    const quadtree *q = impl;
    long ix = pds_num_cell(u, q->w), iy = pds_num_cell(v, q->h);
    const qnode *n = q->nodes;
    ++*steps;
    while (n->v <= -2) {
        const qnode *kids = q->nodes + (-(long)n->v - 2);
        n = kids + (ix >= n->xm) + 2 * (iy >= n->ym);
        ++*steps;
    }
    return n->v;
}

static size_t pds_quadtree_bytes(const void *impl)
{
    const quadtree *q = impl;
    return sizeof *q + q->cap * sizeof *q->nodes;
}

const NS(pds_kind_ops) NS(pds_quadtree_ops) = {
    .name = "quadtree",
    .compile = pds_quadtree_compile,
    .locate = pds_quadtree_locate,
    .bytes = pds_quadtree_bytes,
    .release = pds_quadtree_release,
};
