/* csg — tree compilation (flatten, balance, bound) and span-list
 * classification along a ray (see csg.h). */
#include "geom/csg.h"
#include "model/scene_box.h"
#include "util/dmath.h"
#include "util/mem.h"
#include "util/bvh.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- build ----------------------------------------------------------- */

/* A node's bounds in double while building; nspans and peak bound the
 * span storage its classification needs. */
typedef struct csg_bound { double c[3], r, lo[3], hi[3]; int bounded; size_t nspans, peak; } csg_bound;

typedef struct csg_ctx {
    const scene *sc;
    const prim *prims;
    double scale;            /* the world's (geom_norm) */
    csg_node *nodes;
    csg_bound *bd;           /* double bounds of the current object's
                                compiled nodes: node i's is bd[i - b0] (no
                                parent reads a bound of another object) */
    size_t bdcap;
    int n, cap, b0;
    /* scratch kept across objects, so compiling one allocates nothing: the
     * operand lists of the nodes being compiled, one above the other
     * (lst[0 .. ltop - 1]), csg_gather's stack and csg_balance's keys */
    int *lst, *stk;
    struct csg_key *keys;
    size_t lcap, scap, kcap, ltop;
    diag *err;
} csg_ctx;

typedef struct csg_key { double key; int idx; } csg_key;

/* Operand lists up to this long are sorted by insertion: most are two or
 * three operands, where qsort's calls cost more than the sort. */
#define CSG_SORT_SHORT 16

static int csg_key_cmp(const void *a, const void *b)
{
    double x = ((const csg_key *)a)->key, y = ((const csg_key *)b)->key;
    if (x < y) return -1;
    if (x > y) return 1;
    return ((const csg_key *)a)->idx - ((const csg_key *)b)->idx;
}

static int csg_err(csg_ctx *x, int status, const char *what)
{
    return diag_at(x->err, status, x->sc->source ? x->sc->source : "", 0, 0, "%s", what);
}

/* The node's box: its bound's box padded outwards by CSG_BOX_PAD, then
 * rounded outwards to binary32. */
static void csg_set_box(csg_node *nd, const csg_bound *b)
{
    int i;
    for (i = 0; i < 3; i++) {
        nd->lo[i] = dmath_f32_round(b->lo[i] - CSG_BOX_PAD, 0);
        nd->hi[i] = dmath_f32_round(b->hi[i] + CSG_BOX_PAD, 1);
    }
}

/* Marks child kid when its box is exactly parent's (a difference's left
 * operand always; an intersection's operand that lies within the other). */
static void csg_mark_same(const csg_node *parent, csg_node *kid)
{
    kid->same_box = kid->bounded && !memcmp(kid->lo, parent->lo, sizeof kid->lo)
                    && !memcmp(kid->hi, parent->hi, sizeof kid->hi);
}

/* Appends a compiled node; its bound follows from the children. Returns the
 * node index or -1 (error recorded). */
static int csg_add(csg_ctx *x, int op, int l, int r, int pi)
{
    csg_node *nd;
    csg_bound *b;
    if (x->n >= x->cap) {
        csg_err(x, DIAG_INPUT, "CSG tree has a cycle or shares subtrees too often");
        return -1;
    }
    if (mem_grow((void **)&x->bd, &x->bdcap, (size_t)(x->n - x->b0) + 1, sizeof *x->bd)) {
        csg_err(x, DIAG_IO, "out of memory compiling the CSG tree");
        return -1;
    }
    nd = &x->nodes[x->n];
    b = &x->bd[x->n - x->b0];
    memset(nd, 0, sizeof *nd);
    memset(b, 0, sizeof *b);
    nd->op = (unsigned)op;
    nd->left = op == CSG_LEAF ? 0 : (unsigned)l;
    nd->right = op == CSG_LEAF ? pi : r;
    if (op == CSG_LEAF) {
        const prim *p = &x->prims[pi];
        double a[9];
        b->bounded = p->bounded;
        vec3_to_d(p->bc, b->c);
        b->r = num_to_d(p->br);
        scene_prim_canon_map(&x->sc->prims[pi], x->scale, a);
        NS(prim_box)(p, a, b->lo, b->hi);
        b->nspans = 1;
        b->peak = 1;
    } else {
        const csg_bound *bl = &x->bd[l - x->b0], *br = &x->bd[r - x->b0];
        size_t a = bl->peak, c = bl->nspans + br->peak, e = 2 * (bl->nspans + br->nspans);
        b->nspans = bl->nspans + br->nspans;
        b->peak = a > c ? (a > e ? a : e) : (c > e ? c : e);
        if (op == CSG_DIFF) {
            size_t ns = b->nspans, pk = b->peak;
            *b = *bl;
            b->nspans = ns;
            b->peak = pk;
        } else if (op == CSG_INTER) {
            const csg_bound *s = !bl->bounded ? br : !br->bounded ? bl : bl->r <= br->r ? bl : br;
            size_t ns = b->nspans, pk = b->peak;
            int i;
            *b = *s;
            b->nspans = ns;
            b->peak = pk;
            if (bl->bounded && br->bounded)         /* the boxes intersect */
                for (i = 0; i < 3; i++) {
                    b->lo[i] = bl->lo[i] > br->lo[i] ? bl->lo[i] : br->lo[i];
                    b->hi[i] = bl->hi[i] < br->hi[i] ? bl->hi[i] : br->hi[i];
                    if (b->hi[i] < b->lo[i])
                        b->hi[i] = b->lo[i];
                }
        } else if (bl->bounded && br->bounded) {
            double d[3], dist, R;
            int i;
            for (i = 0; i < 3; i++)
                d[i] = br->c[i] - bl->c[i];
            dist = dmath_len3(d);
            b->bounded = 1;
            for (i = 0; i < 3; i++) {
                b->lo[i] = bl->lo[i] < br->lo[i] ? bl->lo[i] : br->lo[i];
                b->hi[i] = bl->hi[i] > br->hi[i] ? bl->hi[i] : br->hi[i];
            }
            if (dist + br->r <= bl->r) {
                memcpy(b->c, bl->c, sizeof b->c); b->r = bl->r;
            } else if (dist + bl->r <= br->r) {
                memcpy(b->c, br->c, sizeof b->c); b->r = br->r;
            } else {
                R = (dist + bl->r + br->r) / 2;
                for (i = 0; i < 3; i++)
                    b->c[i] = bl->c[i] + (R - bl->r) / dist * d[i];
                b->r = R * (1 + 1e-9);
            }
        }
    }
    nd->bounded = (unsigned char)b->bounded;
    if (b->bounded) {
        csg_set_box(nd, b);
        /* a child with this very box needs no test of its own where it is
         * asked for the parameters the parent was: the left operand of
         * every operator, both operands of a union (csg_eval_in) */
        if (op != CSG_LEAF)
            csg_mark_same(nd, &x->nodes[l]);
        if (op == CSG_UNION)
            csg_mark_same(nd, &x->nodes[r]);
    }
    return x->n++;
}

/* 1 when compiled node ni is a sphere's leaf. */
static int csg_is_sphere(const csg_ctx *x, int ni)
{
    const csg_node *nd = &x->nodes[ni];
    return nd->op == CSG_LEAF && x->prims[csg_leaf_prim(nd)].kind == PRIM_SPHERE;
}

/* Balanced tree of operator op over the compiled nodes items[0..n-1]:
 * bounded operands are split at the median of their centres along the axis
 * of largest spread; unbounded ones are chained on top. Operands whose
 * centres agree within PRIM_SAME_TOL on every axis (a block and the sphere
 * that rounds it, bores through one point) are split in the deck's order:
 * sorted, they would follow the rounding of their placement, and copies of
 * one part would compile to different trees wherever they stood (10,000
 * turned copies of csg81's part split 5,346 to 4,654 between the two orders
 * of its block and sphere, docs/performance.md, run AZ). */
static int csg_balance(csg_ctx *x, int *items, int n, int op, csg_key *keys)
{
    int nb = 0, i, j, l, r, axis = 0;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    if (n == 1)
        return items[0];
    for (i = 0; i < n; i++)
        if (x->bd[items[i] - x->b0].bounded) {
            int t = items[nb]; items[nb] = items[i]; items[i] = t; nb++;
        }
    if (nb < n) {
        int acc = nb ? csg_balance(x, items, nb, op, keys) : items[0];
        for (i = nb ? nb : 1; i < n && acc >= 0; i++)
            acc = csg_add(x, op, acc, items[i], -1);
        return acc;
    }
    for (i = 0; i < n; i++)
        for (j = 0; j < 3; j++) {
            double c = x->bd[items[i] - x->b0].c[j];
            if (c < lo[j]) lo[j] = c;
            if (c > hi[j]) hi[j] = c;
        }
    for (j = 1; j < 3; j++)
        if (hi[j] - lo[j] > hi[axis] - lo[axis])
            axis = j;
    if (hi[axis] - lo[axis] > PRIM_SAME_TOL) {
        for (i = 0; i < n; i++) {
            keys[i].key = x->bd[items[i] - x->b0].c[axis];
            keys[i].idx = items[i];
        }
        if (n <= CSG_SORT_SHORT)             /* the same order, without calls */
            for (i = 1; i < n; i++) {
                csg_key k = keys[i];
                for (j = i; j > 0 && csg_key_cmp(&k, &keys[j - 1]) < 0; j--)
                    keys[j] = keys[j - 1];
                keys[j] = k;
            }
        else
            qsort(keys, (size_t)n, sizeof *keys, csg_key_cmp);
        for (i = 0; i < n; i++)
            items[i] = keys[i].idx;
    }
    /* a sphere meeting one other operand goes second, where
     * csg_diff_first looks for it: the sweep gives an intersection the
     * same spans in either order (span.c) */
    if (op == CSG_INTER && n == 2 && csg_is_sphere(x, items[0]) && !csg_is_sphere(x, items[1])) {
        int t = items[0];
        items[0] = items[1];
        items[1] = t;
    }
    l = csg_balance(x, items, n / 2, op, keys);
    if (l < 0)
        return -1;
    r = csg_balance(x, items + n / 2, n - n / 2, op, keys);
    if (r < 0)
        return -1;
    return csg_add(x, op, l, r, -1);
}

static int csg_compile_node(csg_ctx *x, int sn, int depth);

/* Appends the operands of a chain of op (scene node sn) to x->lst (scene
 * node indices) from x->ltop on, following only nodes with the same op;
 * list holds the operands gathered before (from index base on). */
static int csg_gather(csg_ctx *x, int sn, int op, size_t base)
{
    size_t top = 0;
    if (mem_grow((void **)&x->stk, &x->scap, 1, sizeof *x->stk))
        return csg_err(x, DIAG_IO, "out of memory compiling the CSG tree");
    x->stk[top++] = sn;
    while (top > 0) {
        int k = x->stk[--top];
        const scene_node *nd;
        if (k < 0 || (size_t)k >= x->sc->nnodes)
            return csg_err(x, DIAG_INPUT, "CSG node index out of range");
        nd = &x->sc->nodes[k];
        if ((int)nd->op == op && op != CSG_LEAF) {
            if (x->ltop - base + top + 2 > (size_t)x->cap)
                return csg_err(x, DIAG_INPUT, "CSG tree has a cycle or shares subtrees too often");
            if (mem_grow((void **)&x->stk, &x->scap, top + 2, sizeof *x->stk))
                return csg_err(x, DIAG_IO, "out of memory compiling the CSG tree");
            x->stk[top++] = nd->right;
            x->stk[top++] = nd->left;
        } else {
            if (mem_grow((void **)&x->lst, &x->lcap, x->ltop + 1, sizeof *x->lst))
                return csg_err(x, DIAG_IO, "out of memory compiling the CSG tree");
            x->lst[x->ltop++] = k;
        }
    }
    return 0;
}

/* Compiles the operands (scene nodes) x->lst[base ..] up to x->ltop, each
 * replaced by its compiled index, and balances them under op. */
static int csg_compile_list(csg_ctx *x, size_t base, int op, int depth)
{
    int i, n = (int)(x->ltop - base);
    if (mem_grow((void **)&x->keys, &x->kcap, (size_t)n, sizeof *x->keys)) {
        csg_err(x, DIAG_IO, "out of memory compiling the CSG tree");
        return -1;
    }
    for (i = 0; i < n; i++) {
        /* the operand's own list goes above ours (x->lst may move) */
        int r = csg_compile_node(x, x->lst[base + (size_t)i], depth + 1);
        if (r < 0)
            return -1;
        x->lst[base + (size_t)i] = r;
    }
    return csg_balance(x, x->lst + base, n, op, x->keys);
}

/* Compiles scene node sn; returns the compiled index or -1 (error set). */
static int csg_compile_node(csg_ctx *x, int sn, int depth)
{
    const scene_node *nd;
    size_t base = x->ltop;
    int res = -1;
    if (sn < 0 || (size_t)sn >= x->sc->nnodes) {
        csg_err(x, DIAG_INPUT, "CSG node index out of range");
        return -1;
    }
    if (depth > CSG_MAX_NEST) {
        csg_err(x, DIAG_INPUT, "CSG operators nested too deeply");
        return -1;
    }
    nd = &x->sc->nodes[sn];
    switch (nd->op) {
    case CSG_LEAF:
        if (nd->prim < 0 || (size_t)nd->prim >= x->sc->nprims) {
            csg_err(x, DIAG_INPUT, "CSG leaf names a primitive out of range");
            return -1;
        }
        return csg_add(x, CSG_LEAF, -1, -1, nd->prim);
    case CSG_UNION:
    case CSG_INTER:
        if (!csg_gather(x, sn, nd->op, base))
            res = csg_compile_list(x, base, nd->op, depth);
        break;
    case CSG_DIFF: {
        int b = sn, steps = 0;
        /* a - b - c ... = a - (b u c u ...) */
        while (b >= 0 && (size_t)b < x->sc->nnodes && x->sc->nodes[b].op == CSG_DIFF) {
            if (++steps > x->cap) {
                csg_err(x, DIAG_INPUT, "CSG tree has a cycle or shares subtrees too often");
                break;
            }
            if (csg_gather(x, x->sc->nodes[b].right, CSG_UNION, base))
                break;
            b = x->sc->nodes[b].left;
        }
        if (x->err->status)
            break;
        b = csg_compile_node(x, b, depth + 1);
        if (b < 0)
            break;
        res = csg_compile_list(x, base, CSG_UNION, depth);
        if (res >= 0)
            res = csg_add(x, CSG_DIFF, b, res, -1);
        break;
    }
    default:
        csg_err(x, DIAG_INPUT, "CSG node has an unknown operator");
        break;
    }
    x->ltop = base;
    return res;
}

/* Records in hull the primitives that contain compiled node ni's solid:
 * an intersection lies in both operands, a difference in its left one;
 * a union in neither alone. */
static void csg_hull(const csg_node *nodes, int ni, int hull[CSG_HULL])
{
    const csg_node *nd = &nodes[ni];
    int k;
    for (;;) {
        for (k = 0; k < CSG_HULL && hull[k] >= 0; k++)
            ;
        if (k == CSG_HULL)
            return;               /* full: the rest goes unrecorded */
        if (nd->op == CSG_LEAF) {
            hull[k] = csg_leaf_prim(nd);
            return;
        }
        if (nd->op == CSG_UNION)
            return;
        if (nd->op == CSG_INTER)
            csg_hull(nodes, nd->right, hull);
        nd = &nodes[nd->left];
    }
}

int NS(csg_build)(const scene *sc, const prim *prims, double scale, const csg_inst *inst, csg *out,
                  diag *err)
{
    csg_ctx x;
    int *obj = NULL, *src = NULL, *croot = NULL, nb = 0, nu = 0, k;
    int (*hull)[CSG_HULL] = NULL;
    double (*lo)[3] = NULL, (*hi)[3] = NULL;
    size_t cap, i, peak = 0;
    memset(&x, 0, sizeof x);
    memset(out, 0, sizeof *out);
    out->prims = prims;
    x.sc = sc;
    x.prims = prims;
    x.scale = scale;
    x.err = err;
    /* Every scene node yields at most one compiled leaf or operator per
     * operand, so 2 * (nodes + roots) + 2 bounds a tree; more means sharing
     * or a cycle. */
    cap = 2 * (sc->nnodes + sc->nroots) + 2;
    if (cap > (size_t)1 << 26)
        return csg_err(&x, DIAG_INPUT, "CSG tree too large");
    x.cap = (int)cap;
    /* and a line to align; most trees compile to as many nodes as the
     * scene's */
    out->nodes_mem = mem_calloc_part(cap + MEM_LINE / sizeof *x.nodes, sizeof *x.nodes,
                                     sc->nnodes + sc->nroots + MEM_LINE / sizeof *x.nodes);
    x.nodes = mem_align_line(out->nodes_mem);
    obj = mem_calloc(sc->nroots + 1, sizeof *obj);
    hull = mem_calloc(sc->nroots + 1, sizeof *hull);
    lo = mem_calloc(sc->nroots + 1, sizeof *lo);
    hi = mem_calloc(sc->nroots + 1, sizeof *hi);
    src = mem_calloc(sc->nroots + 1, sizeof *src);
    croot = mem_calloc(sc->nroots + 1, sizeof *croot);
    if (!x.nodes || !obj || !hull || !lo || !hi || !src || !croot) {
        csg_err(&x, DIAG_IO, "out of memory compiling the CSG tree");
        goto fail;
    }
    /* each object compiled on its own; the bounded ones first (the
     * hierarchy's items), the unbounded ones after them */
    for (i = 0; i < sc->nroots; i++) {
        int r;
        const csg_inst *in = inst && inst[i].count ? &inst[i] : NULL;
        if (in) {                 /* the master's tree, moved */
            r = croot[in->master];
            for (k = 0; k < 3; k++) {
                lo[nb][k] = in->turn ? in->turn->lo[k] : x.nodes[r].lo[k] - in->shift_d[k];
                hi[nb][k] = in->turn ? in->turn->hi[k] : x.nodes[r].hi[k] - in->shift_d[k];
            }
            memmove(obj + nb + 1, obj + nb, (size_t)nu * sizeof *obj);
            memmove(src + nb + 1, src + nb, (size_t)nu * sizeof *src);
            src[nb] = (int)i;
            obj[nb++] = croot[i] = r;
            out->ninst++;
            continue;
        }
        x.b0 = x.n;
        if ((r = csg_compile_node(&x, sc->roots[i], 1)) < 0)
            goto fail;
        croot[i] = r;
        if (x.bd[r - x.b0].peak > peak)
            peak = x.bd[r - x.b0].peak;
        if (x.nodes[r].bounded) {
            memmove(obj + nb + 1, obj + nb, (size_t)nu * sizeof *obj);
            memmove(src + nb + 1, src + nb, (size_t)nu * sizeof *src);
            for (k = 0; k < 3; k++) {
                lo[nb][k] = x.nodes[r].lo[k];
                hi[nb][k] = x.nodes[r].hi[k];
            }
            src[nb] = (int)i;
            obj[nb++] = r;
        } else {
            src[nb + nu] = (int)i;
            obj[nb + nu++] = r;
        }
    }
    if (out->ninst) {
        if (!(out->inst = mem_calloc((size_t)(nb + nu), sizeof *out->inst))) {
            csg_err(&x, DIAG_IO, "out of memory compiling the CSG tree");
            goto fail;
        }
        for (k = 0; k < nb + nu; k++)
            if (inst[src[k]].count)
                out->inst[k] = inst[src[k]];
    }
    if (bvh_build((const double (*)[3])lo, (const double (*)[3])hi, (size_t)nb, &out->objtree)) {
        csg_err(&x, DIAG_IO, "out of memory compiling the CSG tree");
        goto fail;
    }
    for (k = 0; k < nb + nu; k++) {
        memset(hull[k], -1, sizeof hull[k]);
        csg_hull(x.nodes, obj[k], hull[k]);
        if (out->inst && out->inst[k].count)
            obj[k] = ~obj[k];     /* an instance's: its master's root */
    }
    out->nodes = x.nodes;
    out->nnodes = x.n;
    out->objects = obj;
    out->hull = hull;
    out->nobjects = nb + nu;
    out->nbounded = nb;
    out->peak_spans = peak;
    out->olo = lo;
    out->ohi = hi;
    mem_free(x.bd);
    mem_free(x.lst);
    mem_free(x.stk);
    mem_free(x.keys);
    mem_free(src);
    mem_free(croot);
    return 0;
fail:
    mem_free(out->nodes_mem);
    out->nodes_mem = NULL;
    mem_free(x.bd);
    mem_free(x.lst);
    mem_free(x.stk);
    mem_free(x.keys);
    mem_free(obj);
    mem_free(hull);
    mem_free(lo);
    mem_free(hi);
    mem_free(src);
    mem_free(croot);
    mem_free(out->inst);
    out->inst = NULL;
    out->ninst = 0;
    return err->status ? err->status : DIAG_IO;
}

void NS(csg_free)(csg *c)
{
    mem_free(c->nodes_mem);
    mem_free(c->objects);
    mem_free(c->hull);
    mem_free(c->olo);
    mem_free(c->ohi);
    mem_free(c->inst);
    bvh_free(&c->objtree);
    memset(c, 0, sizeof *c);
}

size_t NS(csg_arena_bytes)(const csg *c)
{
    /* each live list may waste up to ARENA_ALIGN bytes of padding; the
     * traversal's pending subtrees come first */
    return c->peak_spans * (sizeof(span) + ARENA_ALIGN) + (size_t)(c->objtree.depth + 1) * sizeof(csg_todo)
           + 5 * ARENA_ALIGN;
}

/* ---- classification ------------------------------------------------ */

typedef struct csg_query {
    const csg *c;
    const prim *prims;
    const prim_ray *r;
    num tmax;
    double tmax_d;           /* tmax in binary64, for the culling tests */
    int any;                 /* any hit will do (an occlusion test) */
    const lightbuf *lb;      /* the buffer of the light the ray goes to
                                (any) or of the eye it leaves, or NULL */
    arena *ar;
    geom_stats *st;
} csg_query;

/* The bounds test of node nd for parameters in [lo, hi]: 1 when the ray
 * misses them. Else 0 and *tc the parameter closest to a leaf's bounding
 * sphere centre (what its primitive test continues from; 0 for other
 * nodes). The box is tested first, in binary64 (culling only), unless the
 * parent's test over the same parameters stands for it (alike and
 * nd->same_box); a leaf's sphere then in the mode's arithmetic, for tc. */
VEC_HOT int csg_bounds_miss(csg_query *q, const csg_node *nd, num lo, num hi, int alike, num *tc)
{
    int box = !(alike && nd->same_box);
    double tin;
    *tc = NUM_ZERO;
    if (!nd->bounded || (!box && nd->op != CSG_LEAF))
        return 0;
    q->st->bound_tests++;
    if ((box && bbox_miss_f(nd->lo, nd->hi, &q->r->b, num_to_d(lo), num_to_d(hi), &tin))
        || (nd->op == CSG_LEAF
            && vec3_sphere_miss(q->prims[csg_leaf_prim(nd)].bc, q->prims[csg_leaf_prim(nd)].br, q->r->o, q->r->d,
                                lo, hi, tc))) {
        q->st->pruned++;
        return 1;
    }
    return 0;
}

static int csg_eval_in(csg_query *q, int ni, num lo, num hi, int tested, span **out);
VEC_HOT int csg_eval(csg_query *q, int ni, num lo, num hi, int alike, span **out);

/* The rest of csg_eval_in once ni's left operand has given the nl spans
 * at l (nl > 0, or any nl for a union), the arena at mark on entry to it. */
VEC_HOT int csg_eval_right(csg_query *q, const csg_node *nd, span *l, int nl, num lo, num hi, int tested,
                         size_t mark, span **out)
{
    span *r = NULL, *tmp, *dst;
    int nr, n;
    num rlo = lo, rhi = hi;
    if (nd->op != CSG_UNION) {
        rlo = num_max(lo, l[0].a.t);
        rhi = num_min(hi, l[nl - 1].b.t);
    }
    nr = csg_eval(q, nd->right, rlo, rhi, tested && nd->op == CSG_UNION, &r);
    if (nr == 0 && nd->op == CSG_INTER) {
        arena_release(q->ar, mark);
        return 0;
    }
    /* An operand met alone (a union or difference with nothing) is swept
     * too: what the sweep keeps of it must not depend on whether the other
     * operand, or its bounds, meet the ray somewhere else. One span longer
     * than a sweep step comes through unchanged. */
    if (nr == 0 || nl == 0) {
        span *one = nr ? r : l;
        int k = nr ? nr : nl;
        if (k == 0)
            return 0;
        if (k == 1 && one->b.t > span_lim(one->a.t)) {
            *out = one;
            return 1;
        }
    }
    if (!(tmp = arena_alloc(q->ar, (size_t)(nl + nr) * sizeof *tmp))) {
        q->st->arena_full++;
        arena_release(q->ar, mark);
        return 0;
    }
    n = NS(span_merge)(nd->op, l, nl, r, nr, tmp);
    arena_release(q->ar, mark);
    if (n == 0)
        return 0;
    dst = arena_alloc(q->ar, (size_t)n * sizeof *dst);   /* at mark: dst <= tmp */
    if (n <= 2) {                 /* most merges: forward copies, no call */
        dst[0] = tmp[0];
        if (n == 2)
            dst[1] = tmp[1];
    } else {
        memmove(dst, tmp, (size_t)n * sizeof *dst);
    }
    *out = dst;
    return n;
}

/* Span list of the operator node ni along the ray, whose bounds test
 * passed, placed at the arena top on entry (nothing is left allocated
 * when it returns 0). Only parameters in [lo, hi] can matter to
 * the caller, so subtrees whose bounds lie outside are skipped; the right
 * operand of a difference or intersection only matters where the left one
 * has spans, which narrows [lo, hi] further. tested: ni's box passed over
 * [lo, hi] itself (not only over a wider range), so that children with
 * the same box need not test it again. */
static int csg_eval_in(csg_query *q, int ni, num lo, num hi, int tested, span **out)
{
    const csg_node *nd = &q->c->nodes[ni];
    size_t mark = arena_mark(q->ar);
    span *l = NULL;
    int nl = csg_eval(q, nd->left, lo, hi, tested, &l);
    if (nl == 0 && nd->op != CSG_UNION) {
        q->st->pruned++;          /* the right operand cannot matter */
        return 0;
    }
    return csg_eval_right(q, nd, l, nl, lo, hi, tested, mark, out);
}

/* The span list of node ni after its own bounds test (see csg_eval_in);
 * alike: asked for its parent's parameters. A leaf's one span is found
 * here, inline in its parent's classification: no call per leaf. */
VEC_HOT int csg_eval(csg_query *q, int ni, num lo, num hi, int alike, span **out)
{
    const csg_node *nd = &q->c->nodes[ni];
    span *dst;
    size_t mark;
    num tc;
    if (csg_bounds_miss(q, nd, lo, hi, alike, &tc))
        return 0;
    if (nd->op != CSG_LEAF)
        return csg_eval_in(q, ni, lo, hi, 1, out);
    q->st->prim_tests++;
    /* the span is written in place: a copy of it would load whole what
     * the test stored field by field (see prim_side) */
    mark = arena_mark(q->ar);
    if (!(dst = arena_alloc(q->ar, sizeof *dst))) {
        q->st->arena_full++;
        return 0;
    }
    if (!NS(prim_intersect_tc)(&q->prims[csg_leaf_prim(nd)], q->r, tc, dst)) {
        arena_release(q->ar, mark);
        return 0;
    }
    *out = dst;
    return 1;
}

/* The first surface crossing of one object's span list s[0..n-1] with
 * 0 < t <= tmax: 1 and *h, or 0. */
static int csg_first(const span *s, int n, num tmax, csg_hit *h)
{
    int i, k;
    for (i = 0; i < n; i++) {
        const span_end *e[2];
        e[0] = &s[i].a;
        e[1] = &s[i].b;
        for (k = 0; k < 2; k++) {
            if (e[k]->t <= NUM_ZERO || e[k]->face == PRIM_FACE_NONE)
                continue;
            if (e[k]->t > tmax)
                return 0;
            h->t = e[k]->t;
            h->prim = e[k]->prim;
            h->face = e[k]->face;
            h->entering = k == 0;
            return 1;
        }
    }
    return 0;
}

/* The ray in a primitive's canonical frame, in binary64, for the
 * canonical tests (csg_deep_in_sphere, csg_leaf_clear): the point c0 =
 * ainv (o + t0 d - org) on the exact placement, and g = ainv d, its move
 * per unit of t. */
typedef struct csg_canon { double c0[3], g[3], glen; num t0; } csg_canon;

VEC_HOT void csg_canon_point(const csg_query *q, const prim *p, double td, double *d, double *c)
{
    const prim_frame *fr = p->fr;
    double v[3];
    int i;
    vec3_to_d(q->r->d, d);
    for (i = 0; i < 3; i++)
        v[i] = q->r->b.o[i] + td * d[i] - fr->org_d[i];
    dmath_m3_mul_v(fr->lin->ainv_d, v, c);
}

static void csg_canon_at(const csg_query *q, const prim *p, num t0, csg_canon *k)
{
    double d[3];
    csg_canon_point(q, p, num_to_d(t0), d, k->c0);
    dmath_m3_mul_v(p->fr->lin->ainv_d, d, k->g);
    k->glen = dmath_len3(k->g);
    k->t0 = t0;
}

/* How far, in canonical units, a point of the ray at |t| <= tm must lie
 * from primitive p's exact surface for the canonical tests: e, 2^8 units
 * of the mode's rounding scaled by the canonical map's norm and the
 * magnitudes the solver forms (the bounding radius, and in a floating
 * mode the origin and t), which bounds how far the mode's surface points
 * lie from the exact surface; then at least 1/64, and at least 2w glen
 * (w = 2 eps + E0, span_win, at tm: csg_win2 is 2w; glen = |g|, or a
 * bound of it) beyond it (docs/numerics.md, "Culling in binary64"). */
static double csg_win2(double tm) { return 2 * (3 * num_to_d(SPAN_E0) + 2 * tm * num_to_d(SPAN_E1)); }

static double csg_canon_slack(const csg_query *q, const prim *p, double tm, double glen)
{
    double scale = 1 + num_to_d(p->br), e, need = csg_win2(tm) * glen;
    if (!NUM_IS_FIXED)
        scale += tm + dmath_maxabs3(q->r->b.o);
    e = 256 * num_to_d(NUM_ULP) * num_to_d(p->inv_smin) * scale;
    return e + (need > 1.0 / 64 ? need : 1.0 / 64);
}

/* 1 when the ray's stretch from k->t0 to t1 lies so deep inside the
 * sphere p that no end of the mode's span of p (prim_side) lies within w
 * of it (csg_diff_sphere). With |c| = rho at either end, every point of
 * the ray within (1 - rho) / |g| of it is inside the unit sphere, which
 * holds the points between (it is convex). Asked of that: 1 - rho at
 * least the slack (csg_canon_slack; its 1/64 keeps the chord's
 * half-length above 0.176, which bounds how much a rounding of the
 * discriminant moves a root). */
static int csg_deep_in_sphere(const csg_query *q, const prim *p, const csg_canon *k, num t1)
{
    double t0 = num_to_d(k->t0), dt = num_to_d(t1) - t0, a = fabs(t0), b = fabs(t0 + dt), tm = a > b ? a : b;
    double m = 1 - csg_canon_slack(q, p, tm, k->glen), c1[3];
    int i;
    if (!(m > 0) || dmath_norm2_3(k->c0) > m * m)
        return 0;
    for (i = 0; i < 3; i++)
        c1[i] = k->c0[i] + dt * k->g[i];
    return dmath_norm2_3(c1) <= m * m;
}

/* 1 when the canonical point c lies farther than m outside the canonical
 * solid of a sphere, cylinder or block (kind): the unit sphere, the
 * cylinder x^2 + y^2 <= 1, 0 <= z <= 1, the cube [0, 1]^3 (by a
 * coordinate beyond it, or by the radius). */
static int csg_canon_outside(int kind, const double *c, double m)
{
    double r = 1 + m;
    if (kind == PRIM_SPHERE)
        return c[0] * c[0] + c[1] * c[1] + c[2] * c[2] > r * r;
    if (kind == PRIM_BLOCK && (c[0] < -m || c[0] > r || c[1] < -m || c[1] > r))
        return 1;
    if (kind == PRIM_CYLINDER && c[0] * c[0] + c[1] * c[1] > r * r)
        return 1;
    return c[2] < -m || c[2] > r;
}

/* 1 when no span of the sphere, cylinder or block p (as
 * prim_intersect_spans finds it) meets the window [lo, hi] (of half-width
 * span_win of its middle, csg_diff_rest) because the middle lies outside
 * the exact solid by the slack (csg_canon_slack): every point of the
 * mode's span lies within e of the exact solid (its ends do, and the
 * solid is convex), every point of the window farther. The box misses
 * less where the solid is turned or round: a window at a block's face
 * beside a bore, in the bore's box but not in the bore. Outside by 1/64
 * is asked first (the least slack), |g| only where its bound inv_smin
 * sqrt(3) |d|max could decide the slack. */
static int csg_leaf_clear(const csg_query *q, const prim *p, num lo, num hi)
{
    double a = fabs(num_to_d(lo)), b = fabs(num_to_d(hi)), tm = a > b ? a : b, d[3], c[3], g[3], glen;
    if (p->kind != PRIM_SPHERE && p->kind != PRIM_CYLINDER && p->kind != PRIM_BLOCK)
        return 0;
    csg_canon_point(q, p, 0.5 * (num_to_d(lo) + num_to_d(hi)), d, c);
    if (!csg_canon_outside(p->kind, c, 1.0 / 64))
        return 0;
    glen = 1.7320508075688773 * num_to_d(p->inv_smin) * dmath_maxabs3(d);
    if (csg_win2(tm) * glen > 1.0 / 64) {
        dmath_m3_mul_v(p->fr->lin->ainv_d, d, g);
        glen = dmath_len3(g);
    }
    return csg_canon_outside(p->kind, c, csg_canon_slack(q, p, tm, glen));
}

/* 1 when node ni has no span that meets [lo, hi] (a window around a
 * difference's entry or exit, csg_diff_rest): a node whose bounds the ray
 * misses there; a sphere, cylinder or block the window lies clearly
 * outside of (csg_leaf_clear); a union both of whose operands are clear;
 * an intersection or difference whose left operand is (its spans lie
 * within the left one's). No primitive is tested. */
static int csg_bounds_clear(csg_query *q, int ni, num lo, num hi)
{
    const csg_node *nd = &q->c->nodes[ni];
    num tc;
    if (csg_bounds_miss(q, nd, lo, hi, 0, &tc))
        return 1;
    if (nd->op == CSG_LEAF)
        return csg_leaf_clear(q, &q->prims[csg_leaf_prim(nd)], lo, hi);
    if (!csg_bounds_clear(q, nd->left, lo, hi))
        return 0;
    return nd->op != CSG_UNION || csg_bounds_clear(q, nd->right, lo, hi);
}

/* 1 when the first span of l starts at *a0 > *w on a face and outlasts
 * a0's sweep step; *w = span_win(*a0). */
VEC_HOT int csg_entry_window(const span *l, num *a0, num *w)
{
    *a0 = l[0].a.t;
    *w = span_win(*a0);
    return *a0 > *w && l[0].a.face != PRIM_FACE_NONE && l[0].b.t > span_lim(*a0);
}

/* 1 when the first span of list l (nl spans) ends at *b0, on a face,
 * beyond its window *w = span_win(*b0) and at or below tmax, after its
 * entry's sweep step and before the step of the next span's entry. */
VEC_HOT int csg_exit_window(const span *l, int nl, num tmax, num *b0, num *w)
{
    *b0 = l[0].b.t;
    *w = span_win(*b0);
    return *b0 > *w && *b0 <= tmax && l[0].b.face != PRIM_FACE_NONE && *b0 > span_lim(l[0].a.t)
           && (nl == 1 || l[1].a.t > span_lim(*b0));
}

/* For an occlusion query (some crossing will do), where A's list l has an
 * exit window at b0 (csg_exit_window) and B's bounds keep clear of
 * [b0 - w, b0 + w]: in span_merge's sweep the step that takes b0 then
 * takes no end of B and no other end of A, and before it the sweep is
 * inside A and outside B (a span of B reaching that step would meet the
 * window). So A - B has a span ending at b0, and csg_first of its list
 * finds a crossing at or before b0: that exit is one, *h, and B is not
 * classified (as for the entry, csg_diff_first; docs/numerics.md, the
 * fifth skip). */
static int csg_exit_hit(const span *l, csg_hit *h)
{
    h->t = l[0].b.t;
    h->prim = l[0].b.prim;
    h->face = l[0].b.face;
    h->entering = 0;
    return 1;
}

/* The first crossing of the difference A - B at nd (an object's root)
 * given A's span list l (nl > 0, at the arena's mark): A's first entry
 * where B's bounds keep clear of it (csg_diff_first), else that of the
 * whole difference; for an occlusion query also A's first exit where they
 * keep clear of that (csg_exit_hit). */
VEC_HOT int csg_diff_rest(csg_query *q, const csg_node *nd, span *l, int nl, int tested, size_t mark,
                       csg_hit *h)
{
    span *s = NULL;
    num a0, b0, w;
    int n;
    if (csg_entry_window(l, &a0, &w) && csg_bounds_clear(q, nd->right, num_sub(a0, w), num_add(a0, w)))
        return csg_first(l, nl, q->tmax, h);
    if (q->any && csg_exit_window(l, nl, q->tmax, &b0, &w)
        && csg_bounds_clear(q, nd->right, num_sub(b0, w), num_add(b0, w)))
        return csg_exit_hit(l, h);
    n = csg_eval_right(q, nd, l, nl, NUM_ZERO, q->tmax, tested, mark, &s);
    return n > 0 && csg_first(s, n, q->tmax, h);
}

/* csg_diff_first where A = X n S, S the sphere leaf sp (A's right operand,
 * the ray not leaving it). X is classified first, as classifying A would
 * begin. From s0 = max(x0, -span_win(0)) on, x0 X's first entry, A's list
 * is X's as far as S holds the ray deep (csg_deep_in_sphere): no end of S
 * lies within w of that stretch, so the steps of A's sweep there hold X's
 * ends alone, and the steps before s0 reach no t > 0 (before x0 both are
 * empty). So where S holds s0 deep: A's first entry as csg_diff_first
 * takes it; else the first crossing of X - B if S holds the ray deep from
 * s0 to it; else none if X - B has none and S holds the ray deep from s0
 * to X's exit (or q->tmax, if nearer). Else S is classified, and A - B. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int csg_diff_sphere(csg_query *q, const csg_node *nd, const csg_node *a, const prim *sp,
                           int tested, csg_hit *h)
{
    size_t mark = arena_mark(q->ar), mark2;
    span *l = NULL, *s = NULL;
    int nl, n, hit;
    num tc;
    csg_canon k;
    if (csg_bounds_miss(q, a, NUM_ZERO, q->tmax, tested, &tc))
        return 0;
    if ((nl = csg_eval(q, a->left, NUM_ZERO, q->tmax, 1, &l)) == 0) {
        q->st->pruned++;          /* S and B cannot matter */
        return 0;
    }
    csg_canon_at(q, sp, num_max(l[0].a.t, num_neg(span_win(NUM_ZERO))), &k);
    if (csg_deep_in_sphere(q, sp, &k, k.t0)) {
        num a0, b0, w;
        if (csg_entry_window(l, &a0, &w) && csg_bounds_clear(q, nd->right, num_sub(a0, w), num_add(a0, w)))
            return csg_first(l, nl, q->tmax, h);
        /* an occlusion query: X's first exit, where S holds the ray deep
         * up to it (A's list is X's there: its step at b0 takes X's end
         * alone) */
        if (q->any && csg_exit_window(l, nl, q->tmax, &b0, &w) && csg_deep_in_sphere(q, sp, &k, b0)
            && csg_bounds_clear(q, nd->right, num_sub(b0, w), num_add(b0, w)))
            return csg_exit_hit(l, h);
        mark2 = arena_mark(q->ar);  /* X - B above X's list */
        n = csg_eval_right(q, nd, l, nl, NUM_ZERO, q->tmax, tested, mark2, &s);
        hit = n > 0 && csg_first(s, n, q->tmax, h);
        if (csg_deep_in_sphere(q, sp, &k, hit ? h->t : num_min(l[nl - 1].b.t, q->tmax)))
            return hit;
        arena_release(q->ar, mark2);
    }
    if ((nl = csg_eval_right(q, a, l, nl, NUM_ZERO, q->tmax, 1, mark, &l)) == 0)
        return 0;
    return csg_diff_rest(q, nd, l, nl, tested, mark, h);
}

/* The first crossing (0 < t <= q->tmax) of the difference A - B at node
 * ni (an object's root, tested as for csg_eval_in), as csg_first of its
 * span list gives it, into *h: 1, or 0 when there is none. Where A's first
 * span starts at a0 > w on a face and outlasts a0's sweep step, and B's
 * bounds alone show that B has no span within w = 2 eps(a0) + E0 of a0
 * (csg_bounds_clear), that list starts with A's entry at a0: in
 * span_merge's sweep the steps before a0 - w end before a0, no end of B
 * joins a0's step, and a0 lies outside B. B is then not classified over
 * the rest of A. An A that is X n S with S a sphere: csg_diff_sphere.
 * Else the whole difference, as csg_eval_in. */
static int csg_diff_first(csg_query *q, int ni, int tested, csg_hit *h)
{
    const csg_node *nd = &q->c->nodes[ni], *a = &q->c->nodes[nd->left];
    size_t mark = arena_mark(q->ar);
    span *l = NULL;
    int nl;
    if (a->op == CSG_INTER) {
        const csg_node *sp = &q->c->nodes[a->right];
        if (sp->op == CSG_LEAF && q->prims[csg_leaf_prim(sp)].kind == PRIM_SPHERE
            && q->r->excl_prim != csg_leaf_prim(sp))
            return csg_diff_sphere(q, nd, a, &q->prims[csg_leaf_prim(sp)], tested, h);
    }
    if ((nl = csg_eval(q, nd->left, NUM_ZERO, q->tmax, tested, &l)) == 0) {
        q->st->pruned++;          /* B cannot matter */
        return 0;
    }
    return csg_diff_rest(q, nd, l, nl, tested, mark, h);
}

/* The first crossing (0 < t <= q->tmax) of object k, rooted at the
 * operator node ni, into *h: 1, or 0 when there is none. tested: as for
 * csg_object. Out of line, so that csg_object (every query's floor and
 * one-primitive objects) stays small enough to inline. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int csg_object_tree(csg_query *q, int k, int ni, int tested, csg_hit *h)
{
    const int *hull = q->c->hull[k];
    int leaves = q->r->excl_enter ? -1 : q->r->excl_prim;   /* from its origin */
    size_t mark;
    span *s = NULL;
    int n, hit;
    /* A ray that leaves a convex primitive holding the whole object is
     * outside it for every t > 0: its span list would be empty (that
     * primitive's test gives none, and the intersections and differences
     * above it then give none), so it is not built. */
    if (leaves >= 0 && (hull[0] == leaves || hull[1] == leaves || hull[2] == leaves
                        || hull[3] == leaves))
        return 0;
    mark = arena_mark(q->ar);
    if (q->c->nodes[ni].op == CSG_DIFF && !q->c->whole) {
        hit = csg_diff_first(q, ni, tested, h);
    } else {
        n = csg_eval_in(q, ni, NUM_ZERO, q->tmax, tested, &s);
        hit = n > 0 && csg_first(s, n, q->tmax, h);
    }
    arena_release(q->ar, mark);
    return hit;
}

/* The first crossing below q->tmax of object k (rooted at node ni, a CSG
 * subtree), whose box the ray meets, into *h: 1, or 0 when there is none.
 * An object of one primitive first tests its bounding sphere, which gives
 * the primitive test its start. tested: the object's box passed over
 * [0, q->tmax] as it is now. Forced inline: left to itself GCC keeps it
 * out of line in q16, a call per object tested (+2 % of the sphere
 * scene's instructions). */
VEC_HOT int csg_object_hit(csg_query *q, int k, int ni, int tested, csg_hit *h)
{
    const csg_node *nd = &q->c->nodes[ni];
    num tc = NUM_ZERO;
    if (nd->op == CSG_LEAF) {     /* one primitive: one span, no arena */
        span s;
        const prim *p = &q->prims[csg_leaf_prim(nd)];
        if (nd->bounded && vec3_sphere_miss(p->bc, p->br, q->r->o, q->r->d, NUM_ZERO, q->tmax, &tc)) {
            q->st->pruned++;
            return 0;
        }
        q->st->prim_tests++;
        return NS(prim_intersect_tc)(p, q->r, tc, &s) && csg_first(&s, 1, q->tmax, h);
    }
    return csg_object_tree(q, k, ni, tested, h);
}

/* csg_object_hit of a turned instance (q->c->inst[k], model/scene_inst.h):
 * the ray carried into its master's frame, from a start t0 on it: where
 * it enters the object's box (0 from a surface of the object, which the
 * exclusion needs at the origin). The start q (o + t0 d) + shift and the
 * direction q d are each rounded to num once; parameters past t0 are
 * kept (a rigid motion keeps lengths), so the hit's is t0 plus the
 * master's. Starting at the box keeps the rounding of the direction,
 * multiplied by the parameter, within the object's size: the ray found
 * is off the exact one by at most (1 + L) sqrt(3) / 2 units in num's last
 * place, L the box's diagonal (docs/numerics.md, "Instances"). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int csg_object_turned(csg_query *q, int k, int ni, csg_hit *h)
{
    const csg_inst *in = &q->c->inst[k];
    const prim_ray *r0 = q->r;
    prim_ray r;
    num tmax = q->tmax, t0 = NUM_ZERO;
    double tmax_d = q->tmax_d, d[3], p[3], o2[3], d2[3], tin, t0d;
    int hit, i, own = r0->excl_prim >= in->first && r0->excl_prim - in->first < in->count;
    if (!own) {
        if (bbox_miss(in->turn->lo, in->turn->hi, &r0->b, 0, tmax_d, &tin))
            return 0;
        t0 = num_from_d(tin);
        t0 = t0 < NUM_ZERO ? NUM_ZERO : t0 < tmax ? t0 : tmax;
    }
    t0d = num_to_d(t0);
    vec3_to_d(r0->d, d);
    for (i = 0; i < 3; i++)
        p[i] = r0->b.o[i] + t0d * d[i];
    dmath_m3_mul_v(in->turn->q, p, o2);
    dmath_m3_mul_v(in->turn->q, d, d2);
    for (i = 0; i < 3; i++)
        o2[i] += in->shift_d[i];
    r.o = vec3_from_d(o2);
    r.d = vec3_from_d(d2);
    vec3_to_d(r.o, o2);
    vec3_to_d(r.d, d2);
    prim_ray_set_d(&r, r.o, r.d, o2, d2, own ? r0->excl_prim - in->dprim : -1, r0->excl_enter);
    q->r = &r;
    q->tmax = num_sub(tmax, t0);
    q->tmax_d = num_to_d(q->tmax);
    hit = csg_object_hit(q, k, ni, 0, h);
    q->r = r0;
    q->tmax = tmax;
    q->tmax_d = tmax_d;
    if (!hit)
        return 0;
    h->t = num_add(h->t, t0);
    h->prim += in->dprim;
    return !(tmax < h->t);        /* rounding in a floating mode */
}

/* csg_object_hit of an instance (q->c->inst[k]): the ray moved by its
 * shift, which keeps every parameter, meets its master's tree; the
 * primitive it leaves, if the instance's, named as the master's, and the
 * primitive hit named as the instance's. Out of line: every object of a
 * scene without instances takes the test above alone. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int csg_object_inst(csg_query *q, int k, int ni, int tested, csg_hit *h)
{
    const csg_inst *in = &q->c->inst[k];
    const prim_ray *r0 = q->r;
    prim_ray r = *r0;
    int hit;
    if (in->turn)
        return csg_object_turned(q, k, ni, h);
    r.o = vec3_add(r.o, in->shift);
    vec3_to_d(r.o, r.b.o);
    r.excl_prim = r.excl_prim >= in->first && r.excl_prim - in->first < in->count ? r.excl_prim - in->dprim : -1;
    q->r = &r;
    hit = csg_object_hit(q, k, ni, tested, h);
    q->r = r0;
    if (hit)
        h->prim += in->dprim;
    return hit;
}

/* The nearest hit below q->tmax of object k, whose box the ray meets: a
 * hit found replaces *best (see csg_intersect for ties) and becomes the
 * far end. Forced inline, as csg_object_hit. */
VEC_HOT void csg_object(csg_query *q, int k, int tested, csg_hit *best, int *found)
{
    csg_hit h;
    int ni = q->c->objects[k];
    int hit = ni >= 0 ? csg_object_hit(q, k, ni, tested, &h) : csg_object_inst(q, k, ~ni, tested, &h);
    if (hit && (!*found || h.t < best->t
                || (h.t == best->t && (h.entering > best->entering
                                       || (h.entering == best->entering && h.prim < best->prim))))) {
        best->t = h.t;            /* field by field: see prim_side */
        best->prim = h.prim;
        best->face = h.face;
        best->entering = h.entering;
        *found = 1;
        q->tmax = h.t;
        q->tmax_d = num_to_d(h.t);
    }
}

/* The nearest hit below q->tmax among the objects (see csg_intersect).
 * The unbounded ones (a floor) are tried first: their hits only shrink the
 * far end. Then the hierarchy: at each node both children's boxes are
 * tested, the nearer child (by its box's entry parameter) is visited at
 * once and the other kept in todo[] (objtree.depth entries at most), to
 * be skipped without another test when a hit nearer than its entry has
 * been found by then. Returns 1 to stop (an occlusion test found a hit). */
VEC_HOT int csg_nearest(csg_query *q, csg_todo *todo, csg_hit *best, int *found)
{
    const csg *c = q->c;
    const bvh_node *nodes = c->objtree.nodes;
    size_t n = 0;
    double tin[2];
    int k = c->objtree.root, fresh = 1;   /* k's box passed over [0, q->tmax] */
    bbox_ray2 rb;
    for (k = c->nbounded; k < c->nobjects; k++) {
        csg_object(q, k, 0, best, found);
        if (q->any && *found)
            return 1;
    }
    if (c->nbounded == 0)
        return 0;
    k = c->objtree.root;
    if (k < 0) {                  /* one bounded object: its own box */
        const csg_node *nd = &c->nodes[c->objects[~k]];
        q->st->bound_tests++;
        if (bbox_miss_f(nd->lo, nd->hi, &q->r->b, 0, q->tmax_d, &tin[0])) {
            q->st->pruned++;
            return 0;
        }
    } else {
        bbox_ray2_init(&rb, &q->r->b);
        /* with a buffer (of the light the ray goes to, or the eye it
         * leaves), a ray that meets the root's boxes tests its cell's
         * objects instead of walking (where the buffer answers for it) */
        if (q->lb && q->lb->start) {
            const int *item;
            double d[3], reach;
            int m, i;
            q->st->bound_tests += 2;
            if (bbox_miss2(nodes[k].lo, nodes[k].hi, &rb, q->tmax_d, tin) == 3) {
                q->st->pruned += 2;
                return 0;
            }
            vec3_to_d(q->r->d, d);
            if (lightbuf_lookup(q->lb, q->r->b.o, d, q->tmax_d, q->any, &item, &m)) {
                /* the cell's boxes come nearest the point first: from the
                 * first one beyond the ray's reach on, none holds a point
                 * of it (a hit's point lies in its object's box) */
                reach = lightbuf_ray_far(q->lb, q->r->b.o, d, q->tmax_d, q->any);
                for (i = -q->lb->nnear; i < m; i++) {   /* the near list, then the cell */
                    int ob = i < 0 ? q->lb->near[~i] : item[i];
                    double tmax_d = q->tmax_d;
                    if (i >= 0 && q->lb->far[ob] > reach) {
                        q->st->pruned += m - i;
                        break;
                    }
                    q->st->bound_tests++;
                    if (bbox_miss(c->olo[ob], c->ohi[ob], &q->r->b, 0, q->tmax_d, &tin[0])) {
                        q->st->pruned++;
                        continue;
                    }
                    csg_object(q, ob, 1, best, found);
                    if (q->any && *found)
                        return 1;
                    if (q->tmax_d < tmax_d)             /* a hit: the reach shrinks */
                        reach = lightbuf_ray_far(q->lb, q->r->b.o, d, q->tmax_d, q->any);
                }
                return 0;
            }
        }
    }
    for (;;) {
        if (k >= 0) {
            const bvh_node *nd = &nodes[k];
            int miss = bbox_miss2(nd->lo, nd->hi, &rb, q->tmax_d, tin);
            q->st->bound_tests += 2;
            if (!miss) {
                int first = tin[1] < tin[0];
                todo[n].kid = nd->kid[!first];
                todo[n++].tin = tin[!first];
                k = nd->kid[first];
                fresh = 1;
                continue;
            }
            q->st->pruned += 1 + (miss == 3);
            if (miss != 3) {
                k = nd->kid[miss == 1];
                fresh = 1;
                continue;
            }
        } else {
            csg_object(q, ~k, fresh, best, found);
            if (q->any && *found)
                return 1;
        }
        do {
            if (n == 0)
                return 0;
            n--;
        } while (todo[n].tin > q->tmax_d);
        k = todo[n].kid;
        fresh = 0;                /* tested over a far end since shrunk */
    }
}

/* One query; inlined into each entry point below, so that the two without
 * a buffer keep the walk they had before buffers (a scene with few
 * objects has none). */
VEC_HOT int csg_query_run(const csg *c, const prim_ray *r, num tmax, int any, const lightbuf *lb, arena *ar,
                          geom_stats *st, csg_hit *hit)
{
    csg_query q;
    int found = 0;
    size_t mark;
    csg_todo *todo, local[CSG_TODO_LOCAL];   /* the pending subtrees of most
                                                 hierarchies: no arena */
    if (c->nobjects == 0)
        return 0;
    q.c = c;
    q.prims = c->prims;
    q.r = r;
    q.tmax = tmax;
    q.tmax_d = num_to_d(tmax);
    q.any = any;
    q.lb = lb;
    q.ar = ar;
    q.st = st;
    mark = arena_mark(ar);
    if (c->objtree.depth < CSG_TODO_LOCAL) {
        todo = local;
    } else if (!(todo = arena_alloc(ar, (size_t)(c->objtree.depth + 1) * sizeof *todo))) {
        st->arena_full++;
        return 0;
    }
    csg_nearest(&q, todo, hit, &found);
    arena_release(ar, mark);
    return found;
}

int NS(csg_intersect)(const csg *c, const prim_ray *r, num tmax, arena *ar, geom_stats *st, csg_hit *hit)
{
    return csg_query_run(c, r, tmax, 0, NULL, ar, st, hit);
}

int NS(csg_occluded)(const csg *c, const prim_ray *r, num tmax, arena *ar, geom_stats *st, csg_hit *hit)
{
    return csg_query_run(c, r, tmax, 1, NULL, ar, st, hit);
}

int NS(csg_intersect_from)(const csg *c, const lightbuf *lb, const prim_ray *r, num tmax, arena *ar,
                           geom_stats *st, csg_hit *hit)
{
    return csg_query_run(c, r, tmax, 0, lb, ar, st, hit);
}

int NS(csg_occluded_to)(const csg *c, const lightbuf *lb, const prim_ray *r, num tmax, arena *ar, geom_stats *st,
                        csg_hit *hit)
{
    return csg_query_run(c, r, tmax, 1, lb, ar, st, hit);
}
