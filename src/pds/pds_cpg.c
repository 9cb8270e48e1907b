/* pds_cpg — constructive planar geometry compiled for point location
 * (modal). Data flow: checked pds_def (double) -> flat preorder node array in
 * root (u,v) coordinates -> locate.
 *
 * Compilation bakes every placement into the leaves: an axis-aligned
 * rectangle becomes its box, a polygon of up to 8 edges (or another
 * rectangle) its vertex list, a larger one a pds_ring, an ellipse the affine
 * map that takes it to the unit disk, a nested PDS its own compiled
 * structure and the map into its unit square. Vertex lists and ellipse maps
 * are stored in the node array right after their node. Each node keeps its
 * bounding box; a point outside a node's box is outside the whole subtree.
 *
 * Cost does not depend on the operand order. Chains of one operator are
 * flattened first (UNION(a, UNION(b, c)) is UNION(a, b, c) when the inner
 * node inherits ids; a difference's subtrahends form one union whatever
 * their ids). A union of PDS_CPG_ACCEL_MIN or more operands then gets an
 * index (pds_cpg_index.h: a cell grid listing candidate operands in operand
 * order, and a priority hierarchy where cells overflow), so the first
 * operand in the list that contains the point wins exactly as in a linear
 * scan. The operands of such a union are laid out in memory in the Morton order
 * of their positions (the builder keeps each one's operand position, prio,
 * for the priority rule), so that nearby lookups touch nearby memory
 * whatever the operand order. Priority rules are in docs/pds.md. */
#include "pds/pds_kind.h"
#include <math.h>
#include <string.h>
#include "pds/pds.h"
#include "pds/pds_cpg_index.h"
#include "pds/pds_num.h"
#include "pds/pds_ring.h"
#include "util/mem.h"

enum { K_BOX, K_ELLIPSE, K_POLY, K_RING, K_NESTED, K_UNION, K_INTER, K_DIFF };

#define PDS_CPG_ACCEL_MIN 8      /* operands from which a union is indexed */
#define PDS_CPG_NO_ACCEL UINT32_MAX
#define PDS_CPG_LINE 64          /* cache line bytes the node array is aligned to */

/* A node. An ellipse's map and a small polygon's vertices follow their node
 * in the node array itself (the slots up to `end`), so that the test of a
 * candidate reads adjacent memory, in the same spatial order as the nodes;
 * only the rare large polygons and nested PDSs live in side arrays. */
typedef struct cnode {
    num box[4];          /* closed bounding box; box[0] > box[2] when empty */
    int32_t attr;        /* leaf id, or operator override / PDS_INHERIT */
    uint32_t end;        /* one past the last slot of this subtree (at most
                            4 PDS_MAX_NODES slots: a node and 3 of shape data) */
    uint32_t shape;      /* K_POLY: vertex count; rings, nest index; union:
                            accel or NO_ACCEL */
    uint8_t kind;
} cnode;

/* K_POLY: polygons of at most PDS_RING_LEAF edges, whose strip tree would
 * be a single node with the leaf's box: their n vertices alone (the first
 * not repeated: pds_ring_edges_open). */
#define PDS_CPG_POLY_MAX PDS_RING_LEAF

typedef struct ellipse {
    num m[4];            /* disk_from_root linear part (row-major) */
    num c[2];            /* centre in root coordinates */
} ellipse;

/* A nested PDS: local = m * (root - origin), then the PDS's own lookup. */
typedef struct nested {
    num m[4];
    num origin[2];
    NS(pds) *pds;
} nested;

typedef struct cpg {
    cnode *nodes; size_t nnodes, cap;
    void *block;         /* the compiled node array's allocation (nodes sits
                            in it at a cache-line boundary); NULL while building */
    NS(pds_ring) *rings; size_t nrings, cap_rings;
    nested *nest; size_t nnest, cap_nest;
    NS(pds_cpg_index) *acc; size_t nacc, cap_acc;
} cpg;

/* Operand lists of definition nodes, collected while flattening. */
typedef struct list {
    size_t *v;
    size_t n, cap;
} list;

typedef struct builder {
    const pds_def *def;
    double (*m)[6];      /* root_from_node placements */
    cpg *c;
    uint32_t *prio;      /* by node: operand position in an indexed union
                            (whose memory order is spatial) */
    size_t cap_prio;
} builder;

static void pds_cpg_release(void *impl)
{
    cpg *c = impl;
    size_t i;
    if (!c)
        return;
    for (i = 0; i < c->nrings; i++)
        NS(pds_ring_free)(&c->rings[i]);
    mem_free(c->rings);
    for (i = 0; i < c->nnest; i++)
        NS(pds_free)(c->nest[i].pds);
    mem_free(c->nest);
    for (i = 0; i < c->nacc; i++)
        NS(pds_cpg_index_free)(&c->acc[i]);
    mem_free(c->acc);
    mem_free(c->block ? c->block : c->nodes);
    mem_free(c);
}

static long pds_cpg_push(cpg *c, uint8_t kind, int32_t attr)
{
    cnode *n;
    if (mem_grow((void **)&c->nodes, &c->cap, c->nnodes + 1, sizeof *c->nodes))
        return -1;
    n = &c->nodes[c->nnodes];
    memset(n, 0, sizeof *n);
    n->kind = kind;
    n->attr = attr;
    n->shape = PDS_CPG_NO_ACCEL;
    return (long)c->nnodes++;
}

/* Appends the shape data of the leaf just pushed, as whole slots after it. */
static int pds_cpg_payload(cpg *c, const void *data, size_t bytes)
{
    size_t slots = (bytes + sizeof *c->nodes - 1) / sizeof *c->nodes;
    if (mem_grow((void **)&c->nodes, &c->cap, c->nnodes + slots, sizeof *c->nodes))
        return -1;
    memset(&c->nodes[c->nnodes], 0, slots * sizeof *c->nodes);
    memcpy(&c->nodes[c->nnodes], data, bytes);
    c->nnodes += slots;
    return 0;
}

/* The shape data of leaf n (pds_cpg_payload). */
static const void *pds_cpg_data(const cnode *n) { return n + 1; }

static void pds_cpg_box_set(num box[4], double u0, double v0, double u1, double v1)
{
    box[0] = num_from_d(u0); box[1] = num_from_d(v0);
    box[2] = num_from_d(u1); box[3] = num_from_d(v1);
}

static int pds_cpg_box_empty(const num box[4]) { return box[0] > box[2] || box[1] > box[3]; }

static void pds_cpg_box_clear(num box[4])
{
    box[0] = box[1] = NUM_MAX;
    box[2] = box[3] = num_neg(NUM_MAX);
}

static int pds_cpg_list_add(list *l, size_t x)
{
    if (mem_grow((void **)&l->v, &l->cap, l->n + 1, sizeof *l->v))
        return -1;
    l->v[l->n++] = x;
    return 0;
}

/* Appends the operands of definition node di (an operator `op`), replacing
 * each operand that is itself `op` by its own operands where that cannot
 * change an id: it inherits, or ids do not matter at that place (`ids`
 * is 0 for a difference's subtrahends; for an intersection only the first
 * operand's id counts). Depth is bounded by PDS_MAX_DEPTH. */
static int pds_cpg_flatten(const pds_cpg *d, size_t di, pds_cpg_op op, int ids, list *out)
{
    const pds_cpg_node *n = &d->nodes[di];
    size_t k;
    for (k = 0; k < n->count; k++) {
        size_t kid = d->kids[n->first + k];
        const pds_cpg_node *kn = &d->nodes[kid];
        int kid_ids = ids && (op != PDS_CPG_INTER || (k == 0 && out->n == 0));
        if (kn->op == op && (kn->attr == PDS_INHERIT || !kid_ids)) {
            if (pds_cpg_flatten(d, kid, op, kid_ids, out))
                return -1;
        } else if (pds_cpg_list_add(out, kid)) {
            return -1;
        }
    }
    return 0;
}

static int pds_cpg_emit(builder *b, size_t di);
static int pds_cpg_leaf(builder *b, size_t di);
static int pds_cpg_emit_union(builder *b, const size_t *kids, size_t n, int32_t attr);

/* A K_POLY leaf over the closed polyline pts[2 n] (freed here). */
static int pds_cpg_poly(cpg *c, double *pts, size_t n, int32_t attr)
{
    num *uv = NS(pds_ring_vertices)(pts, n);
    long me = uv ? pds_cpg_push(c, K_POLY, attr) : -1;
    size_t i;
    int rc = -1;
    mem_free(pts);
    if (me >= 0) {
        cnode *nd = &c->nodes[me];
        nd->shape = (uint32_t)n;
        nd->box[0] = nd->box[2] = uv[0];
        nd->box[1] = nd->box[3] = uv[1];
        for (i = 1; i < n; i++) {
            nd->box[0] = num_min(nd->box[0], uv[2 * i]);
            nd->box[2] = num_max(nd->box[2], uv[2 * i]);
            nd->box[1] = num_min(nd->box[1], uv[2 * i + 1]);
            nd->box[3] = num_max(nd->box[3], uv[2 * i + 1]);
        }
        rc = pds_cpg_payload(c, uv, n * 2 * sizeof *uv);
        if (rc == 0)
            c->nodes[me].end = (uint32_t)c->nnodes;
    }
    mem_free(uv);
    return rc;
}

static int pds_cpg_leaf(builder *b, size_t di)
{
    const pds_cpg_node *dn = &b->def->cpg.nodes[di];
    const double *m = b->m[di];
    cpg *c = b->c;
    long me;
    if (dn->op == PDS_CPG_RECT && m[1] == 0 && m[3] == 0) {
        double ua = m[0] * dn->p[0] + m[2], ub = m[0] * dn->p[2] + m[2];
        double va = m[4] * dn->p[1] + m[5], vb = m[4] * dn->p[3] + m[5];
        me = pds_cpg_push(c, K_BOX, dn->attr);
        if (me < 0)
            return -1;
        pds_cpg_box_set(c->nodes[me].box, fmin(ua, ub), fmin(va, vb), fmax(ua, ub), fmax(va, vb));
    } else if (dn->op == PDS_CPG_NESTED) {
        /* The node's unit square, placed by m; store the inverse map. */
        double det = m[0] * m[4] - m[1] * m[3], box[4], pad = 1.0 / 16384;
        nested *ne;
        diag sub_err;
        if (mem_grow((void **)&c->nest, &c->cap_nest, c->nnest + 1, sizeof *c->nest))
            return -1;
        ne = &c->nest[c->nnest];
        diag_init(&sub_err);
        if (NS(pds_compile)(dn->sub, "", &ne->pds, &sub_err))
            return -1;   /* checked already: only memory can run out */
        c->nnest++;
        ne->m[0] = num_from_d(m[4] / det);
        ne->m[1] = num_from_d(-m[1] / det);
        ne->m[2] = num_from_d(-m[3] / det);
        ne->m[3] = num_from_d(m[0] / det);
        ne->origin[0] = num_from_d(m[2]);
        ne->origin[1] = num_from_d(m[5]);
        me = pds_cpg_push(c, K_NESTED, PDS_INHERIT);
        if (me < 0)
            return -1;
        c->nodes[me].shape = (uint32_t)(c->nnest - 1);
        box[0] = fmin(fmin(m[2], m[0] + m[2]), fmin(m[1] + m[2], m[0] + m[1] + m[2]));
        box[2] = fmax(fmax(m[2], m[0] + m[2]), fmax(m[1] + m[2], m[0] + m[1] + m[2]));
        box[1] = fmin(fmin(m[5], m[3] + m[5]), fmin(m[4] + m[5], m[3] + m[4] + m[5]));
        box[3] = fmax(fmax(m[5], m[3] + m[5]), fmax(m[4] + m[5], m[3] + m[4] + m[5]));
        pds_cpg_box_set(c->nodes[me].box, box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad);
    } else if (dn->op == PDS_CPG_ELLIPSE) {
        /* root_from_disk = m * [ru 0 cu; 0 rv cv]; store its inverse. */
        double a = m[0] * dn->p[2], bb = m[1] * dn->p[3], cc = m[3] * dn->p[2], d = m[4] * dn->p[3];
        double cu = m[0] * dn->p[0] + m[1] * dn->p[1] + m[2], cv = m[3] * dn->p[0] + m[4] * dn->p[1] + m[5];
        double det = a * d - bb * cc, eu = hypot(a, bb), ev = hypot(cc, d);
        double pad = 1.0 / 16384;   /* the exact test follows; keep the box conservative */
        ellipse e;
        e.m[0] = num_from_d(d / det);
        e.m[1] = num_from_d(-bb / det);
        e.m[2] = num_from_d(-cc / det);
        e.m[3] = num_from_d(a / det);
        e.c[0] = num_from_d(cu);
        e.c[1] = num_from_d(cv);
        me = pds_cpg_push(c, K_ELLIPSE, dn->attr);
        if (me < 0)
            return -1;
        pds_cpg_box_set(c->nodes[me].box, cu - eu - pad, cv - ev - pad, cu + eu + pad, cv + ev + pad);
        if (pds_cpg_payload(c, &e, sizeof e))
            return -1;
    } else {
        double corners[8], *pts;
        const double *src;
        size_t n, i;
        if (dn->op == PDS_CPG_RECT) {
            corners[0] = dn->p[0]; corners[1] = dn->p[1]; corners[2] = dn->p[2]; corners[3] = dn->p[1];
            corners[4] = dn->p[2]; corners[5] = dn->p[3]; corners[6] = dn->p[0]; corners[7] = dn->p[3];
            src = corners;
            n = 4;
        } else {
            src = b->def->cpg.pts + 2 * dn->first;
            n = dn->count;
        }
        pts = mem_calloc(n, 2 * sizeof *pts);
        if (!pts)
            return -1;
        for (i = 0; i < n; i++) {
            pts[2 * i] = m[0] * src[2 * i] + m[1] * src[2 * i + 1] + m[2];
            pts[2 * i + 1] = m[3] * src[2 * i] + m[4] * src[2 * i + 1] + m[5];
        }
        if (n <= PDS_CPG_POLY_MAX)
            return pds_cpg_poly(c, pts, n, dn->attr);
        if (mem_grow((void **)&c->rings, &c->cap_rings, c->nrings + 1, sizeof *c->rings)) {
            mem_free(pts);
            return -1;
        }
        if (NS(pds_ring_build)(&c->rings[c->nrings], pts, n)) {
            mem_free(pts);
            return -1;
        }
        mem_free(pts);
        c->nrings++;
        me = pds_cpg_push(c, K_RING, dn->attr);
        if (me < 0)
            return -1;
        c->nodes[me].shape = (uint32_t)(c->nrings - 1);
        memcpy(c->nodes[me].box, c->rings[c->nrings - 1].nodes[0].box, sizeof c->nodes[me].box);
    }
    c->nodes[me].end = (uint32_t)c->nnodes;
    return 0;
}

/* ---- the union index --------------------------------------------------- */

/* Indexes the operands of union node me (already emitted). */
static int pds_cpg_accelerate(const builder *b, uint32_t me)
{
    cpg *c = b->c;
    const cnode *u = &c->nodes[me];
    uint32_t *node = NULL, *pos = NULL, j;
    num (*box)[4] = NULL;
    size_t n = 0, npos = 0;
    int rc = -1;
    for (j = me + 1; j < u->end; j = c->nodes[j].end, npos++)
        n += !pds_cpg_box_empty(c->nodes[j].box);
    if (n == 0)
        return 0;      /* no operand can hold a point: the plain loop is exact */
    if (mem_grow((void **)&c->acc, &c->cap_acc, c->nacc + 1, sizeof *c->acc))
        return -1;
    node = mem_calloc(n, sizeof *node);
    pos = mem_calloc(n, sizeof *pos);
    box = mem_calloc(n, sizeof *box);
    if (node && pos && box) {
        size_t i = 0;
        for (j = me + 1; j < u->end; j = c->nodes[j].end)
            if (!pds_cpg_box_empty(c->nodes[j].box)) {
                node[i] = j;
                pos[i] = b->prio[j];
                memcpy(box[i++], c->nodes[j].box, sizeof *box);
            }
        rc = NS(pds_cpg_index_build)(&c->acc[c->nacc], n, node, (const num (*)[4])box, pos, npos, u->box);
    }
    if (rc == 0)
        c->nodes[me].shape = (uint32_t)c->nacc++;
    mem_free(node);
    mem_free(pos);
    mem_free(box);
    return rc;
}

/* ---- emission ---------------------------------------------------------- */

/* A point of definition node di in root coordinates, for ordering:
 * a leaf's centre, an operator's first operand's. */
static void pds_cpg_anchor(const builder *b, size_t di, double *x, double *y)
{
    const pds_cpg *d = &b->def->cpg;
    const pds_cpg_node *n = &d->nodes[di];
    const double *m;
    double lx = 0.5, ly = 0.5;
    while (n->op >= PDS_CPG_UNION) {
        di = d->kids[n->first];
        n = &d->nodes[di];
    }
    m = b->m[di];
    if (n->op == PDS_CPG_RECT) {
        lx = 0.5 * (n->p[0] + n->p[2]);
        ly = 0.5 * (n->p[1] + n->p[3]);
    } else if (n->op == PDS_CPG_ELLIPSE) {
        lx = n->p[0];
        ly = n->p[1];
    } else if (n->op == PDS_CPG_POLYGON) {
        lx = d->pts[2 * n->first];
        ly = d->pts[2 * n->first + 1];
    }
    *x = m[0] * lx + m[1] * ly + m[2];
    *y = m[3] * lx + m[4] * ly + m[5];
}

/* Emits the operands kids[0..n) of an indexed union in the Morton order
 * of their anchors, so that operands near each other in the plane are near
 * each other in memory whatever the operand order; each keeps its operand
 * position in prio, which alone decides priority. */
static int pds_cpg_emit_spatial(builder *b, const size_t *kids, size_t n)
{
    uint32_t *order = mem_calloc(n, sizeof *order);
    double (*xy)[2] = mem_calloc(n, sizeof *xy), lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
    size_t k;
    int rc = -1, a;
    if (!order || !xy)
        goto done;
    for (k = 0; k < n; k++) {
        pds_cpg_anchor(b, kids[k], &xy[k][0], &xy[k][1]);
        for (a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], xy[k][a]);
            hi[a] = fmax(hi[a], xy[k][a]);
        }
    }
    if (NS(pds_cpg_index_morton)((const double (*)[2])xy, n, lo, hi, order))
        goto done;
    for (k = 0; k < n; k++) {
        size_t at = b->c->nnodes;
        if (pds_cpg_emit(b, kids[order[k]]) ||
            mem_grow((void **)&b->prio, &b->cap_prio, at + 1, sizeof *b->prio))
            goto done;
        b->prio[at] = order[k];
    }
    rc = 0;
done:
    mem_free(order);
    mem_free(xy);
    return rc;
}

/* A union node over definition nodes kids[0..n), in that order. */
static int pds_cpg_emit_union(builder *b, const size_t *kids, size_t n, int32_t attr)
{
    cpg *c = b->c;
    long me;
    size_t k;
    uint32_t j;
    if (n == 1 && attr == PDS_INHERIT)
        return pds_cpg_emit(b, kids[0]);
    me = pds_cpg_push(c, K_UNION, attr);
    if (me < 0)
        return -1;
    if (n < PDS_CPG_ACCEL_MIN) {
        for (k = 0; k < n; k++)
            if (pds_cpg_emit(b, kids[k]))
                return -1;
    } else if (pds_cpg_emit_spatial(b, kids, n)) {
        return -1;
    }
    c->nodes[me].end = (uint32_t)c->nnodes;
    pds_cpg_box_clear(c->nodes[me].box);
    for (j = (uint32_t)me + 1; j < c->nnodes; j = c->nodes[j].end)
        if (!pds_cpg_box_empty(c->nodes[j].box))
            pds_num_box_grow(c->nodes[me].box, c->nodes[j].box);
    return n < PDS_CPG_ACCEL_MIN ? 0 : pds_cpg_accelerate(b, (uint32_t)me);
}

static int pds_cpg_emit(builder *b, size_t di)
{
    const pds_cpg *d = &b->def->cpg;
    const pds_cpg_node *dn = &d->nodes[di];
    cpg *c = b->c;
    list ops = { NULL, 0, 0 }, subs = { NULL, 0, 0 };
    long me;
    size_t k, first;
    uint32_t j;
    int rc = -1;
    if (dn->op < PDS_CPG_UNION)
        return pds_cpg_leaf(b, di);
    if (dn->op == PDS_CPG_UNION) {
        if (pds_cpg_flatten(d, di, PDS_CPG_UNION, 1, &ops) == 0)
            rc = pds_cpg_emit_union(b, ops.v, ops.n, dn->attr);
        mem_free(ops.v);
        return rc;
    }
    if (dn->op == PDS_CPG_INTER) {
        if (pds_cpg_flatten(d, di, PDS_CPG_INTER, 1, &ops))
            goto done;
    } else {
        /* DIFF(DIFF(a, b..), c..) = DIFF(a, b.., c..) when the inner one
         * inherits; the subtrahends only need membership: one union. */
        first = di;
        while (d->nodes[first].op == PDS_CPG_DIFF && (first == di || d->nodes[first].attr == PDS_INHERIT)) {
            const pds_cpg_node *fn = &d->nodes[first];
            for (k = 1; k < fn->count; k++) {
                size_t kid = d->kids[fn->first + k];
                if (d->nodes[kid].op == PDS_CPG_UNION ? pds_cpg_flatten(d, kid, PDS_CPG_UNION, 0, &subs)
                                                       : pds_cpg_list_add(&subs, kid))
                    goto done;
            }
            first = d->kids[fn->first];
        }
        if (pds_cpg_list_add(&ops, first))
            goto done;
    }
    me = pds_cpg_push(c, dn->op == PDS_CPG_INTER ? K_INTER : K_DIFF, dn->attr);
    if (me < 0)
        goto done;
    for (k = 0; k < ops.n; k++)
        if (pds_cpg_emit(b, ops.v[k]))
            goto done;
    if (subs.n && pds_cpg_emit_union(b, subs.v, subs.n, PDS_INHERIT))
        goto done;
    {
        cnode *n = &c->nodes[me];
        const cnode *fst = &c->nodes[me + 1];
        n->end = (uint32_t)c->nnodes;
        memcpy(n->box, fst->box, sizeof n->box);
        if (dn->op == PDS_CPG_INTER)
            for (j = fst->end; j < c->nnodes; j = c->nodes[j].end) {
                const cnode *k2 = &c->nodes[j];
                n->box[0] = num_max(n->box[0], k2->box[0]);
                n->box[1] = num_max(n->box[1], k2->box[1]);
                n->box[2] = num_min(n->box[2], k2->box[2]);
                n->box[3] = num_min(n->box[3], k2->box[3]);
            }
    }
    rc = 0;
done:
    mem_free(ops.v);
    mem_free(subs.v);
    return rc;
}

/* Moves the node array to a block of exactly its size, starting at a
 * cache-line boundary: a node (32 bytes in q16) then never straddles two
 * lines. Keeps the growing array if memory runs out. */
static void pds_cpg_settle(cpg *c)
{
    size_t bytes = c->nnodes * sizeof *c->nodes;
    unsigned char *blk = mem_alloc(bytes + PDS_CPG_LINE - 1), *at;
    if (!blk)
        return;
    at = blk + (PDS_CPG_LINE - (uintptr_t)blk % PDS_CPG_LINE) % PDS_CPG_LINE;
    memcpy(at, c->nodes, bytes);
    mem_free(c->nodes);
    c->nodes = (cnode *)(void *)at;
    c->cap = c->nnodes;
    c->block = blk;
}

/* Gives back what mem_grow's doubling left unused: lookups never read it,
 * but it is memory the structure holds. Keeps the block if realloc fails. */
static void pds_cpg_trim(void **p, size_t *cap, size_t n, size_t elem)
{
    void *q;
    if (n == 0 || n >= *cap || !(q = mem_realloc(*p, n * elem)))
        return;
    *p = q;
    *cap = n;
}

static int pds_cpg_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    builder b;
    int *depth;
    cpg *c = mem_calloc(1, sizeof *c);
    size_t nn = def->cpg.nnodes;
    b.def = def;
    b.c = c;
    b.prio = NULL;
    b.cap_prio = 0;
    b.m = mem_calloc(nn, sizeof *b.m);
    depth = mem_calloc(nn, sizeof *depth);
    if (!c || !b.m || !depth)
        goto oom;
    pds_cpg_placements(def, b.m, depth);
    if (pds_cpg_emit(&b, def->cpg.root))
        goto oom;
    pds_cpg_settle(c);
    pds_cpg_trim((void **)&c->rings, &c->cap_rings, c->nrings, sizeof *c->rings);
    pds_cpg_trim((void **)&c->nest, &c->cap_nest, c->nnest, sizeof *c->nest);
    pds_cpg_trim((void **)&c->acc, &c->cap_acc, c->nacc, sizeof *c->acc);
    mem_free(b.m);
    mem_free(b.prio);
    mem_free(depth);
    *out = c;
    return 0;
oom:
    mem_free(b.m);
    mem_free(b.prio);
    mem_free(depth);
    pds_cpg_release(c);
    return NS(pds_oom)(def, file, err);
}

static int pds_cpg_ellipse_in(const ellipse *e, num u, num v)
{
    num du = num_sub(u, e->c[0]), dv = num_sub(v, e->c[1]);
    num x = num_add(num_mul(e->m[0], du), num_mul(e->m[1], dv));
    num y = num_add(num_mul(e->m[2], du), num_mul(e->m[3], dv));
    num two = num_add(NUM_ONE, NUM_ONE);
    if (num_abs(x) > two || num_abs(y) > two)
        return 0;       /* far outside; also keeps the squares in range */
    return num_add(num_mul(x, x), num_mul(y, y)) <= NUM_ONE;
}

/* A nested PDS's region: its closed unit square, minus where it says
 * PDS_NONE (transparent). */
static int pds_cpg_nested_in(const nested *ne, num u, num v, int32_t *attr, unsigned long *steps)
{
    num du = num_sub(u, ne->origin[0]), dv = num_sub(v, ne->origin[1]);
    num x = num_add(num_mul(ne->m[0], du), num_mul(ne->m[1], dv));
    num y = num_add(num_mul(ne->m[2], du), num_mul(ne->m[3], dv));
    int32_t id;
    if (x < NUM_ZERO || x > NUM_ONE || y < NUM_ZERO || y > NUM_ONE)
        return 0;
    id = NS(pds_locate_steps)(ne->pds, x, y, steps);
    if (id == PDS_NONE)
        return 0;
    *attr = id;
    return 1;
}

/* Membership of (u,v) in the subtree at i, whose box has already accepted
 * the point (and been counted in *steps); on success *attr is the winning
 * leaf's id or an operator's override. Rules: docs/pds.md. */
static int pds_cpg_body(const cpg *c, uint32_t i, num u, num v, int32_t *attr, unsigned long *steps);

/* Visits node k: counts it, tests its box, then its shape or operands.
 * Leaf shapes are tested inline: most visits end at a leaf. */
static inline int pds_cpg_visit(const cpg *c, uint32_t k, num u, num v, int32_t *attr, unsigned long *steps)
{
    const cnode *n = &c->nodes[k];
    ++*steps;
    if (!pds_num_in_box(n->box, u, v))
        return 0;
    switch (n->kind) {
    case K_BOX:
        break;
    case K_ELLIPSE:
        if (!pds_cpg_ellipse_in(pds_cpg_data(n), u, v))
            return 0;
        break;
    case K_POLY:
        ++*steps;   /* as the ring's single strip node would count */
        if (!NS(pds_ring_edges_open)(pds_cpg_data(n), n->shape, u, v))
            return 0;
        break;
    case K_RING:
        if (!NS(pds_ring_inside)(&c->rings[n->shape], u, v, steps))
            return 0;
        break;
    case K_NESTED:
        return pds_cpg_nested_in(&c->nest[n->shape], u, v, attr, steps);
    default:
        return pds_cpg_body(c, k, u, v, attr, steps);
    }
    *attr = n->attr;
    return 1;
}

/* The first operand (in operand order) of an indexed union that contains
 * (u,v): the cell's list, or the hierarchy with priority pruning. */
static int pds_cpg_indexed(const cpg *c, const NS(pds_cpg_index) *acc, num u, num v, int32_t *attr,
                           unsigned long *steps)
{
    uint32_t stack[64], best = UINT32_MAX;
    int top = 0;
    if (acc->gn) {
        long cell = pds_cpg_index_cell(acc, 1, v) * acc->gn + pds_cpg_index_cell(acc, 0, u);
        const NS(pds_cpg_cell) *ce = &acc->cells[cell];
        uint32_t s = ce[0].start, e = ce[1].start;
        ++*steps;
        if (e - s <= PDS_CPG_INDEX_SCAN) {
            if (s == e)
                return 0;
            if (pds_cpg_visit(c, ce->first, u, v, attr, steps))
                return 1;
            for (s++; s < e; s++)
                if (pds_cpg_visit(c, acc->ops[s], u, v, attr, steps))
                    return 1;
            return 0;
        }
    }
    stack[top++] = 0;
    while (top > 0) {
        const NS(pds_cpg_bvh) *h = &acc->h[stack[--top]];
        if (h->minp >= best)
            continue;
        if (h->a == PDS_CPG_INDEX_LEAF) {
            int32_t a;
            if (pds_cpg_visit(c, h->b, u, v, &a, steps)) {
                best = h->minp;
                *attr = a;
            }
            continue;
        }
        ++*steps;
        if (!pds_num_in_box(h->box, u, v))
            continue;
        /* Lower positions first: they can end the search early. */
        if (acc->h[h->a].minp < acc->h[h->b].minp) {
            stack[top++] = h->b;
            stack[top++] = h->a;
        } else {
            stack[top++] = h->a;
            stack[top++] = h->b;
        }
    }
    return best != UINT32_MAX;
}

static int pds_cpg_body(const cpg *c, uint32_t i, num u, num v, int32_t *attr, unsigned long *steps)
{
    const cnode *n = &c->nodes[i];
    uint32_t k;
    int32_t dummy;
    if (n->kind == K_UNION) {
        if (n->shape != PDS_CPG_NO_ACCEL) {
            if (!pds_cpg_indexed(c, &c->acc[n->shape], u, v, attr, steps))
                return 0;
        } else {
            for (k = i + 1; k < n->end; k = c->nodes[k].end)
                if (pds_cpg_visit(c, k, u, v, attr, steps))
                    break;
            if (k >= n->end)
                return 0;
        }
    } else {
        k = i + 1;
        if (!pds_cpg_visit(c, k, u, v, attr, steps))
            return 0;
        for (k = c->nodes[k].end; k < n->end; k = c->nodes[k].end)
            if (pds_cpg_visit(c, k, u, v, &dummy, steps) != (n->kind == K_INTER))
                return 0;
    }
    if (n->attr != PDS_INHERIT)
        *attr = n->attr;
    return 1;
}

static int32_t pds_cpg_locate(const void *impl, num u, num v, unsigned long *steps)
{
    int32_t attr = PDS_NONE;
    return pds_cpg_visit(impl, 0, u, v, &attr, steps) ? attr : PDS_NONE;
}

static size_t pds_cpg_bytes(const void *impl)
{
    const cpg *c = impl;
    size_t s = sizeof *c + c->cap * sizeof *c->nodes + (c->block ? PDS_CPG_LINE - 1 : 0) + c->cap_rings * sizeof *c->rings, i;
    for (i = 0; i < c->nrings; i++)
        s += (c->rings[i].n + 1) * 2 * sizeof(num) +
             c->rings[i].nnodes * sizeof *c->rings[i].nodes;
    s += c->cap_nest * sizeof *c->nest;
    for (i = 0; i < c->nnest; i++)
        s += NS(pds_bytes)(c->nest[i].pds);
    s += c->cap_acc * sizeof *c->acc;
    for (i = 0; i < c->nacc; i++)
        s += NS(pds_cpg_index_bytes)(&c->acc[i]);
    return s;
}

const NS(pds_kind_ops) NS(pds_cpg_ops) = {
    .name = "cpg",
    .compile = pds_cpg_compile,
    .locate = pds_cpg_locate,
    .bytes = pds_cpg_bytes,
    .release = pds_cpg_release,
};
