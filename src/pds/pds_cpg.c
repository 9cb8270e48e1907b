/* pds_cpg — constructive planar geometry compiled for point location
 * (modal). Data flow: checked pds_def (double) -> flat preorder node array in
 * root (u,v) coordinates -> locate.
 *
 * Compilation bakes every placement into the leaves: an axis-aligned
 * rectangle becomes its box, any other rectangle or polygon a pds_ring, an
 * ellipse the affine map that takes it to the unit disk, a nested PDS its
 * own compiled structure and the map into its unit square. Each node keeps its
 * bounding box; a point outside a node's box is outside the whole subtree,
 * so a spatially balanced tree is searched in O(log N) node visits. n-ary
 * unions are rebuilt as balanced binary unions with the operand order kept
 * (first-wins is associative), which gives that balance for long operand
 * lists. Priority rules are in docs/pds.md. */
#include "pds/pds_kind.h"
#include <math.h>
#include <string.h>
#include "pds/pds.h"
#include "pds/pds_num.h"
#include "pds/pds_ring.h"
#include "util/mem.h"

enum { K_BOX, K_ELLIPSE, K_RING, K_NESTED, K_UNION, K_INTER, K_DIFF };

typedef struct cnode {
    num box[4];          /* closed bounding box; box[0] > box[2] when empty */
    int32_t attr;        /* leaf id, or operator override / PDS_INHERIT */
    uint32_t end;        /* one past the last node of this subtree */
    uint32_t shape;      /* index into ellipses or rings */
    uint8_t kind;
} cnode;

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
    ellipse *ell; size_t nell, cap_ell;
    NS(pds_ring) *rings; size_t nrings, cap_rings;
    nested *nest; size_t nnest, cap_nest;
} cpg;

typedef struct builder {
    const pds_def *def;
    double (*m)[6];      /* root_from_node placements */
    cpg *c;
} builder;

static void release(void *impl)
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
    mem_free(c->ell);
    mem_free(c->nodes);
    mem_free(c);
}

static long push(cpg *c, uint8_t kind, int32_t attr)
{
    cnode *n;
    if (mem_grow((void **)&c->nodes, &c->cap, c->nnodes + 1, sizeof *c->nodes))
        return -1;
    n = &c->nodes[c->nnodes];
    memset(n, 0, sizeof *n);
    n->kind = kind;
    n->attr = attr;
    return (long)c->nnodes++;
}

static void box_set(num box[4], double u0, double v0, double u1, double v1)
{
    box[0] = num_from_d(u0); box[1] = num_from_d(v0);
    box[2] = num_from_d(u1); box[3] = num_from_d(v1);
}

static int compile_node(builder *b, size_t di);

/* Emits a union of operands kids[lo..hi) of definition node di, balanced. */
static int emit_union(builder *b, const size_t *kids, size_t lo, size_t hi, int32_t attr)
{
    cpg *c = b->c;
    long me;
    size_t k;
    if (hi - lo == 1 && attr == PDS_INHERIT)
        return compile_node(b, kids[lo]);
    me = push(c, K_UNION, attr);
    if (me < 0)
        return -1;
    if (hi - lo <= 2) {
        for (k = lo; k < hi; k++)
            if (compile_node(b, kids[k]))
                return -1;
    } else {
        size_t mid = lo + (hi - lo + 1) / 2;
        if (emit_union(b, kids, lo, mid, PDS_INHERIT) || emit_union(b, kids, mid, hi, PDS_INHERIT))
            return -1;
    }
    {
        cnode *n = &c->nodes[me];
        size_t j;
        n->end = (uint32_t)c->nnodes;
        n->box[0] = n->box[1] = NUM_MAX;
        n->box[2] = n->box[3] = num_neg(NUM_MAX);
        for (j = (size_t)me + 1; j < c->nnodes; j = c->nodes[j].end) {
            const cnode *k2 = &c->nodes[j];
            if (k2->box[0] > k2->box[2])
                continue;
            n->box[0] = num_min(n->box[0], k2->box[0]);
            n->box[1] = num_min(n->box[1], k2->box[1]);
            n->box[2] = num_max(n->box[2], k2->box[2]);
            n->box[3] = num_max(n->box[3], k2->box[3]);
        }
    }
    return 0;
}

static int compile_leaf(builder *b, size_t di)
{
    const pds_cpg_node *dn = &b->def->cpg.nodes[di];
    const double *m = b->m[di];
    cpg *c = b->c;
    long me;
    if (dn->op == PDS_CPG_RECT && m[1] == 0 && m[3] == 0) {
        double ua = m[0] * dn->p[0] + m[2], ub = m[0] * dn->p[2] + m[2];
        double va = m[4] * dn->p[1] + m[5], vb = m[4] * dn->p[3] + m[5];
        me = push(c, K_BOX, dn->attr);
        if (me < 0)
            return -1;
        box_set(c->nodes[me].box, fmin(ua, ub), fmin(va, vb), fmax(ua, ub), fmax(va, vb));
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
        me = push(c, K_NESTED, PDS_INHERIT);
        if (me < 0)
            return -1;
        c->nodes[me].shape = (uint32_t)(c->nnest - 1);
        box[0] = fmin(fmin(m[2], m[0] + m[2]), fmin(m[1] + m[2], m[0] + m[1] + m[2]));
        box[2] = fmax(fmax(m[2], m[0] + m[2]), fmax(m[1] + m[2], m[0] + m[1] + m[2]));
        box[1] = fmin(fmin(m[5], m[3] + m[5]), fmin(m[4] + m[5], m[3] + m[4] + m[5]));
        box[3] = fmax(fmax(m[5], m[3] + m[5]), fmax(m[4] + m[5], m[3] + m[4] + m[5]));
        box_set(c->nodes[me].box, box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad);
    } else if (dn->op == PDS_CPG_ELLIPSE) {
        /* root_from_disk = m * [ru 0 cu; 0 rv cv]; store its inverse. */
        double a = m[0] * dn->p[2], bb = m[1] * dn->p[3], cc = m[3] * dn->p[2], d = m[4] * dn->p[3];
        double cu = m[0] * dn->p[0] + m[1] * dn->p[1] + m[2], cv = m[3] * dn->p[0] + m[4] * dn->p[1] + m[5];
        double det = a * d - bb * cc, eu = hypot(a, bb), ev = hypot(cc, d);
        double pad = 1.0 / 16384;   /* the exact test follows; keep the box conservative */
        ellipse *e;
        if (mem_grow((void **)&c->ell, &c->cap_ell, c->nell + 1, sizeof *c->ell))
            return -1;
        me = push(c, K_ELLIPSE, dn->attr);
        if (me < 0)
            return -1;
        c->nodes[me].shape = (uint32_t)c->nell;
        e = &c->ell[c->nell++];
        e->m[0] = num_from_d(d / det);
        e->m[1] = num_from_d(-bb / det);
        e->m[2] = num_from_d(-cc / det);
        e->m[3] = num_from_d(a / det);
        e->c[0] = num_from_d(cu);
        e->c[1] = num_from_d(cv);
        box_set(c->nodes[me].box, cu - eu - pad, cv - ev - pad, cu + eu + pad, cv + ev + pad);
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
        me = push(c, K_RING, dn->attr);
        if (me < 0)
            return -1;
        c->nodes[me].shape = (uint32_t)(c->nrings - 1);
        memcpy(c->nodes[me].box, c->rings[c->nrings - 1].nodes[0].box, sizeof c->nodes[me].box);
    }
    c->nodes[me].end = (uint32_t)c->nnodes;
    return 0;
}

static int compile_node(builder *b, size_t di)
{
    const pds_cpg *d = &b->def->cpg;
    const pds_cpg_node *dn = &d->nodes[di];
    cpg *c = b->c;
    long me;
    size_t k, j;
    if (dn->op < PDS_CPG_UNION)
        return compile_leaf(b, di);
    if (dn->op == PDS_CPG_UNION)
        return emit_union(b, d->kids + dn->first, 0, dn->count, dn->attr);
    me = push(c, dn->op == PDS_CPG_INTER ? K_INTER : K_DIFF, dn->attr);
    if (me < 0)
        return -1;
    for (k = 0; k < dn->count; k++)
        if (compile_node(b, d->kids[dn->first + k]))
            return -1;
    {
        cnode *n = &c->nodes[me];
        const cnode *first = &c->nodes[me + 1];
        n->end = (uint32_t)c->nnodes;
        memcpy(n->box, first->box, sizeof n->box);
        if (dn->op == PDS_CPG_INTER)
            for (j = first->end; j < c->nnodes; j = c->nodes[j].end) {
                const cnode *k2 = &c->nodes[j];
                n->box[0] = num_max(n->box[0], k2->box[0]);
                n->box[1] = num_max(n->box[1], k2->box[1]);
                n->box[2] = num_min(n->box[2], k2->box[2]);
                n->box[3] = num_min(n->box[3], k2->box[3]);
            }
    }
    return 0;
}

static int compile(const pds_def *def, const char *file, void **out, diag *err)
{
    builder b;
    int *depth;
    cpg *c = mem_calloc(1, sizeof *c);
    size_t nn = def->cpg.nnodes;
    b.def = def;
    b.c = c;
    b.m = mem_calloc(nn, sizeof *b.m);
    depth = mem_calloc(nn, sizeof *depth);
    if (!c || !b.m || !depth)
        goto oom;
    pds_cpg_placements(def, b.m, depth);
    if (compile_node(&b, def->cpg.root))
        goto oom;
    mem_free(b.m);
    mem_free(depth);
    *out = c;
    return 0;
oom:
    mem_free(b.m);
    mem_free(depth);
    release(c);
    return NS(pds_oom)(def, file, err);
}

static int ellipse_in(const ellipse *e, num u, num v)
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
static int nested_in(const nested *ne, num u, num v, int32_t *attr, unsigned long *steps)
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
static int body(const cpg *c, uint32_t i, num u, num v, int32_t *attr, unsigned long *steps);

/* Visits node k: counts it, tests its box, then its shape or operands.
 * Leaf shapes are tested inline: most visits end at a leaf. */
static inline int visit(const cpg *c, uint32_t k, num u, num v, int32_t *attr, unsigned long *steps)
{
    const cnode *n = &c->nodes[k];
    ++*steps;
    if (!pds_num_in_box(n->box, u, v))
        return 0;
    switch (n->kind) {
    case K_BOX:
        break;
    case K_ELLIPSE:
        if (!ellipse_in(&c->ell[n->shape], u, v))
            return 0;
        break;
    case K_RING:
        if (!NS(pds_ring_inside)(&c->rings[n->shape], u, v, steps))
            return 0;
        break;
    case K_NESTED:
        return nested_in(&c->nest[n->shape], u, v, attr, steps);
    default:
        return body(c, k, u, v, attr, steps);
    }
    *attr = n->attr;
    return 1;
}

static int body(const cpg *c, uint32_t i, num u, num v, int32_t *attr, unsigned long *steps)
{
    const cnode *n = &c->nodes[i];
    uint32_t k;
    int32_t dummy;
    if (n->kind == K_UNION) {
        for (k = i + 1; k < n->end; k = c->nodes[k].end)
            if (visit(c, k, u, v, attr, steps))
                break;
        if (k >= n->end)
            return 0;
    } else {
        k = i + 1;
        if (!visit(c, k, u, v, attr, steps))
            return 0;
        for (k = c->nodes[k].end; k < n->end; k = c->nodes[k].end)
            if (visit(c, k, u, v, &dummy, steps) != (n->kind == K_INTER))
                return 0;
    }
    if (n->attr != PDS_INHERIT)
        *attr = n->attr;
    return 1;
}

static int32_t locate(const void *impl, num u, num v, unsigned long *steps)
{
    int32_t attr = PDS_NONE;
    return visit(impl, 0, u, v, &attr, steps) ? attr : PDS_NONE;
}

static size_t bytes(const void *impl)
{
    const cpg *c = impl;
    size_t s = sizeof *c + c->cap * sizeof *c->nodes + c->cap_ell * sizeof *c->ell + c->cap_rings * sizeof *c->rings, i;
    for (i = 0; i < c->nrings; i++)
        s += (c->rings[i].n + 1) * 2 * sizeof(num) +
             c->rings[i].nnodes * sizeof *c->rings[i].nodes;
    s += c->cap_nest * sizeof *c->nest;
    for (i = 0; i < c->nnest; i++)
        s += NS(pds_bytes)(c->nest[i].pds);
    return s;
}

const NS(pds_kind_ops) NS(pds_cpg_ops) = { "cpg", compile, locate, bytes, release };
