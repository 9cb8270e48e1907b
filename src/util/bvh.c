/* bvh — binned surface-area-heuristic build (see bvh.h). */
#include "util/bvh.h"
#include "util/mem.h"
#include <string.h>

#define BVH_BINS 16

typedef struct bvh_ctx {
    const double (*lo)[3], (*hi)[3];
    int *items;
    double (*cen)[3];        /* box centres */
    bvh_node *nodes;
    int n;
    int depth;
} bvh_ctx;

typedef struct bvh_box { double lo[3], hi[3]; } bvh_box;

static void bvh_box_empty(bvh_box *b)
{
    int k;
    for (k = 0; k < 3; k++) {
        b->lo[k] = 1e308;
        b->hi[k] = -1e308;
    }
}

/* Written as selections, not conditional stores: the compiler then emits
 * min and max instructions (the same values for the finite boxes here). */
static void bvh_box_grow(bvh_box *b, const double *lo, const double *hi)
{
    int k;
    for (k = 0; k < 3; k++) {
        b->lo[k] = lo[k] < b->lo[k] ? lo[k] : b->lo[k];
        b->hi[k] = hi[k] > b->hi[k] ? hi[k] : b->hi[k];
    }
}

/* Half the surface area (the heuristic only compares). */
static double bvh_box_area(const bvh_box *b)
{
    double x = b->hi[0] - b->lo[0], y = b->hi[1] - b->lo[1], z = b->hi[2] - b->lo[2];
    return x < 0 ? 0 : x * y + y * z + z * x;
}

/* Where to split items[first, first + count): the number going left, by
 * the binned surface area heuristic along the axis of largest centre
 * spread; half of them (in their current order) when the centres
 * coincide, no split beats the other, or the tree is already deep. */
static int bvh_split(bvh_ctx *x, int first, int count, int depth)
{
    double clo[3] = {1e308, 1e308, 1e308}, chi[3] = {-1e308, -1e308, -1e308}, scale, best = 0;
    bvh_box bin[BVH_BINS], right[BVH_BINS];
    int nbin[BVH_BINS], axis = 0, i, k, left, best_b = -1;
    for (i = first; i < first + count; i++)
        for (k = 0; k < 3; k++) {
            double c = x->cen[x->items[i]][k];
            clo[k] = c < clo[k] ? c : clo[k];
            chi[k] = c > chi[k] ? c : chi[k];
        }
    for (k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis])
            axis = k;
    if (!(chi[axis] > clo[axis]) || depth >= BVH_SAH_DEPTH)
        return count / 2;
    scale = BVH_BINS / (chi[axis] - clo[axis]);
    if (!(scale < 1e300))                /* a spread too small to bin */
        return count / 2;
    if (count == 2) {   /* what the bins would give, without them: the lower centre first */
        int a = x->items[first], b = x->items[first + 1];
        if (x->cen[b][axis] < x->cen[a][axis]) {
            x->items[first] = b;
            x->items[first + 1] = a;
        }
        return 1;
    }
    for (k = 0; k < BVH_BINS; k++) {
        bvh_box_empty(&bin[k]);
        nbin[k] = 0;
    }
    for (i = first; i < first + count; i++) {
        int it = x->items[i], b = (int)((x->cen[it][axis] - clo[axis]) * scale);
        if (b >= BVH_BINS) b = BVH_BINS - 1;
        nbin[b]++;
        bvh_box_grow(&bin[b], x->lo[it], x->hi[it]);
    }
    right[BVH_BINS - 1] = bin[BVH_BINS - 1];
    for (k = BVH_BINS - 1; k-- > 0;) {
        right[k] = bin[k];
        bvh_box_grow(&right[k], right[k + 1].lo, right[k + 1].hi);
    }
    {
        bvh_box acc;
        int nl = 0;
        bvh_box_empty(&acc);
        for (k = 0; k + 1 < BVH_BINS; k++) {     /* left: bins 0..k */
            double cost;
            nl += nbin[k];
            bvh_box_grow(&acc, bin[k].lo, bin[k].hi);
            if (nl == 0 || nl == count)
                continue;
            cost = bvh_box_area(&acc) * nl + bvh_box_area(&right[k + 1]) * (count - nl);
            if (best_b < 0 || cost < best) {
                best = cost;
                best_b = k;
            }
        }
    }
    if (best_b < 0)
        return count / 2;
    /* partition: bins 0..best_b first */
    left = first;
    for (i = first; i < first + count; i++) {
        int it = x->items[i], b = (int)((x->cen[it][axis] - clo[axis]) * scale);
        if (b >= BVH_BINS) b = BVH_BINS - 1;
        if (b <= best_b) {
            x->items[i] = x->items[left];
            x->items[left++] = it;
        }
    }
    return left - first;
}

/* Builds the subtree over items[first, first + count) at depth (its
 * node's depth from the root, 1 for the root); returns its child index and
 * its box in *box. */
static int bvh_node_build(bvh_ctx *x, int first, int count, int depth, bvh_box *box)
{
    int ni, nl, j, k;
    bvh_box kb[2];
    bvh_node *nd;
    if (count == 1) {
        int it = x->items[first];
        memcpy(box->lo, x->lo[it], sizeof box->lo);
        memcpy(box->hi, x->hi[it], sizeof box->hi);
        if (depth - 1 > x->depth)
            x->depth = depth - 1;
        return ~it;
    }
    ni = x->n++;
    nl = bvh_split(x, first, count, depth);
    nd = &x->nodes[ni];
    nd->kid[0] = bvh_node_build(x, first, nl, depth + 1, &kb[0]);
    nd = &x->nodes[ni];
    nd->kid[1] = bvh_node_build(x, first + nl, count - nl, depth + 1, &kb[1]);
    nd = &x->nodes[ni];
    bvh_box_empty(box);
    for (j = 0; j < 2; j++) {
        for (k = 0; k < 3; k++) {
            nd->lo[k][j] = kb[j].lo[k];
            nd->hi[k][j] = kb[j].hi[k];
        }
        bvh_box_grow(box, kb[j].lo, kb[j].hi);
    }
    return ni;
}

int bvh_build(const double (*lo)[3], const double (*hi)[3], size_t n, bvh *out)
{
    bvh_ctx x;
    bvh_box all;
    size_t i;
    int k;
    memset(&x, 0, sizeof x);
    memset(out, 0, sizeof *out);
    if (n == 0)
        return 0;
    if (n > (size_t)1 << 28)
        return -1;
    x.lo = lo;
    x.hi = hi;
    x.items = mem_calloc(n, sizeof *x.items);
    x.cen = mem_calloc(n, sizeof *x.cen);
    x.nodes = mem_calloc(n > 1 ? n - 1 : 1, sizeof *x.nodes);
    if (!x.items || !x.cen || !x.nodes) {
        mem_free(x.items);
        mem_free(x.cen);
        mem_free(x.nodes);
        return -1;
    }
    for (i = 0; i < n; i++) {
        x.items[i] = (int)i;
        for (k = 0; k < 3; k++)
            x.cen[i][k] = (lo[i][k] + hi[i][k]) / 2;
    }
    out->root = bvh_node_build(&x, 0, (int)n, 1, &all);
    out->nodes = x.nodes;
    out->nnodes = x.n;
    out->depth = x.depth;
    mem_free(x.items);
    mem_free(x.cen);
    return 0;
}

void bvh_free(bvh *b)
{
    mem_free(b->nodes);
    memset(b, 0, sizeof *b);
}
