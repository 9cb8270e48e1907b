/* pds_ring — closed polylines with a strip tree (see pds_ring.h). */
#include "pds/pds_ring.h"
#include <math.h>
#include <string.h>
#include "pds/pds_num.h"
#include "util/mem.h"

/* Builds the subtree over vertices i0..i1 at nodes[r->nnodes]; returns its
 * index. Recursion depth is O(log n) because splits stay in the middle half. */
static uint32_t pds_ring_build_node(NS(pds_ring) *r, uint32_t i0, uint32_t i1)
{
    uint32_t idx = (uint32_t)r->nnodes++, i, k;
    NS(pds_ring_node) *nd = &r->nodes[idx];
    nd->i0 = i0;
    nd->i1 = i1;
    nd->box[0] = nd->box[2] = r->uv[2 * i0];
    nd->box[1] = nd->box[3] = r->uv[2 * i0 + 1];
    for (i = i0 + 1; i <= i1; i++) {
        nd->box[0] = num_min(nd->box[0], r->uv[2 * i]);
        nd->box[2] = num_max(nd->box[2], r->uv[2 * i]);
        nd->box[1] = num_min(nd->box[1], r->uv[2 * i + 1]);
        nd->box[3] = num_max(nd->box[3], r->uv[2 * i + 1]);
    }
    nd->left = nd->right = 0;
    if (i1 - i0 <= PDS_RING_LEAF)
        return idx;
    k = NS(pds_ring_split)(r->uv, i0, i1);
    {
        uint32_t left = pds_ring_build_node(r, i0, k), right = pds_ring_build_node(r, k, i1);
        r->nodes[idx].left = left;
        r->nodes[idx].right = right;
    }
    return idx;
}

int NS(pds_ring_build)(NS(pds_ring) *r, const double *pts, size_t n)
{
    memset(r, 0, sizeof *r);
    r->uv = NS(pds_ring_vertices)(pts, n);
    r->nodes = mem_calloc(2 * n + 1, sizeof *r->nodes);
    if (!r->uv || !r->nodes) {
        NS(pds_ring_free)(r);
        return -1;
    }
    r->n = n;
    pds_ring_build_node(r, 0, (uint32_t)n);
    {
        /* 2 n + 1 bounds the node count; keep only what was used, with the
         * vertices in the same block (a CPG holds one ring per polygon
         * leaf: one allocation, one cache line fewer per lookup). */
        size_t nb = r->nnodes * sizeof *r->nodes, ub = (n + 1) * 2 * sizeof *r->uv;
        unsigned char *blk = mem_calloc(1, nb + ub);
        if (blk) {
            memcpy(blk, r->nodes, nb);
            memcpy(blk + nb, r->uv, ub);
            mem_free(r->nodes);
            mem_free(r->uv);
            r->nodes = (NS(pds_ring_node) *)(void *)blk;
            r->uv = (num *)(void *)(blk + nb);
        }
    }
    return 0;
}

void NS(pds_ring_free)(NS(pds_ring) *r)
{
    if (!r->nodes || r->uv != (num *)(void *)(r->nodes + r->nnodes))
        mem_free(r->uv);
    mem_free(r->nodes);
    memset(r, 0, sizeof *r);
}

/* Crossing parity of the chain under node idx: 0 or 1, or 2 when the point
 * lies on the chain. */
static int pds_ring_parity(const NS(pds_ring) *r, uint32_t idx, num u, num v, unsigned long *steps)
{
    const NS(pds_ring_node) *nd = &r->nodes[idx];
    const num *p = r->uv;
    int c, e;
    ++*steps;
    if (v < nd->box[1] || v > nd->box[3] || u > nd->box[2])
        return 0;
    if (u < nd->box[0])   /* every crossing lies right of the point */
        return (p[2 * nd->i0 + 1] > v) != (p[2 * nd->i1 + 1] > v);
    if (!nd->left)
        return NS(pds_ring_edges)(p, nd->i0, nd->i1, u, v);
    c = pds_ring_parity(r, nd->left, u, v, steps);
    if (c == 2)
        return 2;
    e = pds_ring_parity(r, nd->right, u, v, steps);
    return e == 2 ? 2 : c ^ e;
}

int NS(pds_ring_inside)(const NS(pds_ring) *r, num u, num v, unsigned long *steps)
{
    return pds_ring_parity(r, 0, u, v, steps) != 0;
}

num *NS(pds_ring_vertices)(const double *pts, size_t n)
{
    num *uv = mem_calloc(n + 1, 2 * sizeof *uv);
    size_t i;
    if (!uv)
        return NULL;
    for (i = 0; i <= n; i++) {
        uv[2 * i] = num_from_d(pts[2 * (i % n)]);
        uv[2 * i + 1] = num_from_d(pts[2 * (i % n) + 1]);
    }
    return uv;
}

uint32_t NS(pds_ring_split)(const num *uv, uint32_t i0, uint32_t i1)
{
    /* distance from the chord as the cross product (proportional to it) */
    double ax = num_to_d(uv[2 * i0]), ay = num_to_d(uv[2 * i0 + 1]);
    double dx = num_to_d(uv[2 * i1]) - ax, dy = num_to_d(uv[2 * i1 + 1]) - ay, best = -1;
    uint32_t lo = i0 + (i1 - i0) / 4, hi = i1 - (i1 - i0) / 4, i, k;
    if (lo <= i0) lo = i0 + 1;
    if (hi >= i1) hi = i1 - 1;
    k = lo;
    for (i = lo; i <= hi; i++) {
        double px = num_to_d(uv[2 * i]) - ax, py = num_to_d(uv[2 * i + 1]) - ay;
        double dist = (dx == 0 && dy == 0) ? px * px + py * py : fabs(dx * py - dy * px);
        if (dist > best) {
            best = dist;
            k = i;
        }
    }
    return k;
}

int NS(pds_ring_edges)(const num *uv, uint32_t i0, uint32_t i1, num u, num v)
{
    int c = 0, e;
    uint32_t i;
    for (i = i0; i < i1; i++) {
        e = pds_num_edge(uv[2 * i], uv[2 * i + 1], uv[2 * i + 2], uv[2 * i + 3], u, v);
        if (e == 2)
            return 2;
        c ^= e;
    }
    return c;
}

int NS(pds_ring_edges_open)(const num *uv, uint32_t n, num u, num v)
{
    int c = NS(pds_ring_edges)(uv, 0, n - 1, u, v), e;
    if (c == 2)
        return 2;
    e = pds_num_edge(uv[2 * n - 2], uv[2 * n - 1], uv[0], uv[1], u, v);
    return e == 2 ? 2 : c ^ e;
}
