/* pds_strip — Ballard's strip trees (see pds_strip.h). */
#include "pds/pds_strip.h"
#include <math.h>
#include <string.h>
#include "pds/pds_num.h"
#include "pds/pds_ring.h"
#include "pds/pds_strip_ops.h"
#include "model/pds_def.h"
#include "util/mem.h"

/* Outward widening of the strip before its corners are rounded to the
 * mode: a few units of the mode at the largest coordinate (64), far above
 * the double error of the projections. The strip is widened by twice that
 * along and across its chord, so that rounding each corner to the mode
 * (half a unit in u and in v) cannot bring any point of the chain outside
 * it, whatever the chord's direction. */
#if NUM_IS_FIXED
#define PDS_STRIP_PAD (4 * num_to_d(NUM_ULP))
#else
#define PDS_STRIP_PAD (256 * num_to_d(NUM_ULP))
#endif

typedef struct strip_build {
    NS(pds_strip) *s;
    double tol;
} strip_build;

/* The strip of vertices i0..i1 into nd: chord direction t (or +u when the
 * chord is a point), extents along t and across it. */
static void pds_strip_fit(const NS(pds_strip) *s, uint32_t i0, uint32_t i1, NS(pds_strip_node) *nd)
{
    const num *p = s->uv;
    double bx = num_to_d(p[2 * i0]), by = num_to_d(p[2 * i0 + 1]);
    double tx = num_to_d(p[2 * i1]) - bx, ty = num_to_d(p[2 * i1 + 1]) - by, l = hypot(tx, ty);
    double s0 = 0, s1 = 0, w0 = 0, w1 = 0, cs[4][2];
    uint32_t i;
    int k;
    if (l > 0) {
        tx /= l;
        ty /= l;
    } else {
        tx = 1;
        ty = 0;
    }
    for (i = i0; i <= i1; i++) {
        double dx = num_to_d(p[2 * i]) - bx, dy = num_to_d(p[2 * i + 1]) - by;
        double a = dx * tx + dy * ty, c = -dx * ty + dy * tx;
        s0 = fmin(s0, a); s1 = fmax(s1, a);
        w0 = fmin(w0, c); w1 = fmax(w1, c);
    }
    nd->w = w1 - w0;
    s0 -= 2 * PDS_STRIP_PAD; s1 += 2 * PDS_STRIP_PAD;
    w0 -= 2 * PDS_STRIP_PAD; w1 += 2 * PDS_STRIP_PAD;
    /* counter-clockwise: (s0,w0) (s1,w0) (s1,w1) (s0,w1) */
    cs[0][0] = s0; cs[0][1] = w0; cs[1][0] = s1; cs[1][1] = w0;
    cs[2][0] = s1; cs[2][1] = w1; cs[3][0] = s0; cs[3][1] = w1;
    for (k = 0; k < 4; k++) {
        double x = bx + cs[k][0] * tx - cs[k][1] * ty, y = by + cs[k][0] * ty + cs[k][1] * tx;
        nd->c[2 * k] = num_from_d(x);
        nd->c[2 * k + 1] = num_from_d(y);
    }
    nd->box[0] = nd->box[2] = nd->c[0];
    nd->box[1] = nd->box[3] = nd->c[1];
    for (k = 1; k < 4; k++) {
        nd->box[0] = num_min(nd->box[0], nd->c[2 * k]);
        nd->box[2] = num_max(nd->box[2], nd->c[2 * k]);
        nd->box[1] = num_min(nd->box[1], nd->c[2 * k + 1]);
        nd->box[3] = num_max(nd->box[3], nd->c[2 * k + 1]);
    }
}

static uint32_t pds_strip_build_node(strip_build *b, uint32_t i0, uint32_t i1)
{
    NS(pds_strip) *s = b->s;
    uint32_t idx = (uint32_t)s->nnodes++, k;
    NS(pds_strip_node) *nd = &s->nodes[idx];
    nd->i0 = i0;
    nd->i1 = i1;
    nd->left = nd->right = 0;
    pds_strip_fit(s, i0, i1, nd);
    if (i1 - i0 <= PDS_STRIP_LEAF || nd->w <= b->tol)
        return idx;
    k = NS(pds_ring_split)(s->uv, i0, i1);
    {
        uint32_t left = pds_strip_build_node(b, i0, k), right = pds_strip_build_node(b, k, i1);
        s->nodes[idx].left = left;
        s->nodes[idx].right = right;
    }
    return idx;
}

int NS(pds_strip_build)(NS(pds_strip) *s, const double *pts, size_t n, double tol)
{
    strip_build b;
    memset(s, 0, sizeof *s);
    s->uv = NS(pds_ring_vertices)(pts, n);
    s->nodes = mem_calloc(2 * n + 1, sizeof *s->nodes);
    if (!s->uv || !s->nodes) {
        NS(pds_strip_free)(s);
        return -1;
    }
    s->n = n;
    b.s = s;
    b.tol = tol;
    pds_strip_build_node(&b, 0, (uint32_t)n);
    {
        NS(pds_strip_node) *fit = mem_calloc(s->nnodes, sizeof *fit);
        if (fit) {
            memcpy(fit, s->nodes, s->nnodes * sizeof *fit);
            mem_free(s->nodes);
            s->nodes = fit;
        }
    }
    return 0;
}

void NS(pds_strip_free)(NS(pds_strip) *s)
{
    mem_free(s->uv);
    mem_free(s->nodes);
    memset(s, 0, sizeof *s);
}

size_t NS(pds_strip_bytes)(const NS(pds_strip) *s)
{
    return (s->n + 1) * 2 * sizeof(num) + s->nnodes * sizeof *s->nodes;
}

/* Does edge a-b meet the half-line from p towards -u (side < 0) or +u
 * (side > 0)? Exact. */
static int pds_strip_edge_meets(num ax, num ay, num bx, num by, num px, num py, int side)
{
    int o;
    if ((ay > py && by > py) || (ay < py && by < py))
        return 0;
    if (ay == py && by == py)
        return side < 0 ? (ax <= px || bx <= px) : (ax >= px || bx >= px);
    if (ay > by) {          /* orient from the lower to the upper end */
        num t = ax; ax = bx; bx = t;
        t = ay; ay = by; by = t;
    }
    o = pds_num_orient(ax, ay, bx, by, px, py);   /* > 0: p left of the crossing */
    return side < 0 ? o <= 0 : o >= 0;
}

/* Does the half-line from (u,v) towards side meet the quad? */
static int pds_strip_quad_meets(const num *c, num u, num v, int side)
{
    int k;
    for (k = 0; k < 4; k++)
        if (pds_strip_edge_meets(c[2 * k], c[2 * k + 1], c[(2 * k + 2) % 8], c[(2 * k + 3) % 8], u, v, side))
            return 1;
    return 0;
}

/* Crossing parity of the chain under node idx: 0 or 1, 2 on the chain. */
static int pds_strip_parity(const NS(pds_strip) *s, uint32_t idx, num u, num v, unsigned long *steps)
{
    const NS(pds_strip_node) *nd = &s->nodes[idx];
    const num *p = s->uv;
    int c, e;
    ++*steps;
    if (v < nd->box[1] || v > nd->box[3] || u > nd->box[2])
        return 0;
    /* The half-line towards -u misses the strip (a point inside the strip
     * would see it leave through an edge): the line meets the strip only
     * right of p, where all the chain's crossings are. */
    if (u < nd->box[0] || !pds_strip_quad_meets(nd->c, u, v, -1))
        return (p[2 * nd->i0 + 1] > v) != (p[2 * nd->i1 + 1] > v);
    if (!nd->left)
        return NS(pds_ring_edges)(p, nd->i0, nd->i1, u, v);
    c = pds_strip_parity(s, nd->left, u, v, steps);
    if (c == 2)
        return 2;
    e = pds_strip_parity(s, nd->right, u, v, steps);
    return e == 2 ? 2 : c ^ e;
}

int NS(pds_strip_inside)(const NS(pds_strip) *s, num u, num v, unsigned long *steps)
{
    return pds_strip_parity(s, 0, u, v, steps) != 0;
}

/* ---- two strip trees ----------------------------------------------------- */

/* Separating-axis test of two convex quads (exact: the axes are the quads'
 * own edges, decided with orientation predicates). 1 if they overlap. */
static int pds_strip_quads_overlap(const num *a, const num *b)
{
    int pass, k, j;
    for (pass = 0; pass < 2; pass++) {
        const num *p = pass ? b : a, *q = pass ? a : b;
        for (k = 0; k < 4; k++) {
            num x0 = p[2 * k], y0 = p[2 * k + 1], x1 = p[(2 * k + 2) % 8], y1 = p[(2 * k + 3) % 8];
            for (j = 0; j < 4; j++)
                if (pds_num_orient(x0, y0, x1, y1, q[2 * j], q[2 * j + 1]) >= 0)
                    break;
            if (j == 4)
                return 0;   /* all of q strictly right of this edge of p */
        }
    }
    return 1;
}

/* Do closed segments a0-a1 and b0-b1 meet? Exact. */
static int pds_strip_segments_meet(const num *a0, const num *a1, const num *b0, const num *b1)
{
    int o1 = pds_num_orient(a0[0], a0[1], a1[0], a1[1], b0[0], b0[1]);
    int o2 = pds_num_orient(a0[0], a0[1], a1[0], a1[1], b1[0], b1[1]);
    int o3 = pds_num_orient(b0[0], b0[1], b1[0], b1[1], a0[0], a0[1]);
    int o4 = pds_num_orient(b0[0], b0[1], b1[0], b1[1], a1[0], a1[1]);
    if (o1 * o2 > 0 || o3 * o4 > 0)
        return 0;
    if (o1 == 0 && o2 == 0) {   /* collinear: overlapping ranges */
        return num_max(num_min(a0[0], a1[0]), num_min(b0[0], b1[0])) <=
                   num_min(num_max(a0[0], a1[0]), num_max(b0[0], b1[0])) &&
               num_max(num_min(a0[1], a1[1]), num_min(b0[1], b1[1])) <=
                   num_min(num_max(a0[1], a1[1]), num_max(b0[1], b1[1]));
    }
    return 1;
}

typedef struct strip_meet {
    const NS(pds_strip) *a, *b;
    uint32_t *pairs;
    size_t max, n;
    unsigned long *steps;
} strip_meet;

static void pds_strip_meet_nodes(strip_meet *m, uint32_t ia, uint32_t ib)
{
    const NS(pds_strip_node) *na = &m->a->nodes[ia], *nb = &m->b->nodes[ib];
    ++*m->steps;
    if (na->box[0] > nb->box[2] || nb->box[0] > na->box[2] || na->box[1] > nb->box[3] ||
        nb->box[1] > na->box[3] || !pds_strip_quads_overlap(na->c, nb->c))
        return;
    if (!na->left && !nb->left) {
        uint32_t i, j;
        for (i = na->i0; i < na->i1; i++)
            for (j = nb->i0; j < nb->i1; j++)
                if (pds_strip_segments_meet(m->a->uv + 2 * i, m->a->uv + 2 * i + 2, m->b->uv + 2 * j,
                                            m->b->uv + 2 * j + 2)) {
                    if (m->n < m->max) {
                        m->pairs[2 * m->n] = i;
                        m->pairs[2 * m->n + 1] = j;
                    }
                    m->n++;
                }
        return;
    }
    /* Ballard: split the wider strip (a leaf cannot be split) */
    if (nb->left == 0 || (na->left && na->w >= nb->w)) {
        pds_strip_meet_nodes(m, na->left, ib);
        pds_strip_meet_nodes(m, na->right, ib);
    } else {
        pds_strip_meet_nodes(m, ia, nb->left);
        pds_strip_meet_nodes(m, ia, nb->right);
    }
}

size_t NS(pds_strip_intersect)(const NS(pds_strip) *a, const NS(pds_strip) *b, uint32_t *pairs,
                               size_t max, unsigned long *steps)
{
    strip_meet m;
    m.a = a;
    m.b = b;
    m.pairs = pairs;
    m.max = max;
    m.n = 0;
    m.steps = steps;
    pds_strip_meet_nodes(&m, 0, 0);
    return m.n;
}

int NS(pds_strip_regions_meet)(const NS(pds_strip) *a, const NS(pds_strip) *b)
{
    unsigned long steps = 0;
    if (NS(pds_strip_intersect)(a, b, NULL, 0, &steps))
        return 1;   /* the boundaries cross or touch */
    /* otherwise one lies inside the other or they are apart */
    return NS(pds_strip_inside)(a, b->uv[0], b->uv[1], &steps) || NS(pds_strip_inside)(b, a->uv[0], a->uv[1], &steps);
}

int NS(pds_strip_in_union)(const NS(pds_strip) *a, const NS(pds_strip) *b, num u, num v)
{
    unsigned long steps = 0;
    return NS(pds_strip_inside)(a, u, v, &steps) || NS(pds_strip_inside)(b, u, v, &steps);
}

int NS(pds_strip_in_inter)(const NS(pds_strip) *a, const NS(pds_strip) *b, num u, num v)
{
    unsigned long steps = 0;
    return NS(pds_strip_inside)(a, u, v, &steps) && NS(pds_strip_inside)(b, u, v, &steps);
}

/* ---- the mode-independent table (pds_strip_ops.h) ------------------------ */

static int pds_strip_of(const pds_def *d, size_t i, NS(pds_strip) *s)
{
    double *pts;
    size_t n;
    int owned, rc = pds_curves_ring(&d->curves, i, &pts, &n, &owned);
    if (rc)
        return -1;
    rc = NS(pds_strip_build)(s, pts, n, d->curves.strip_width);
    if (owned)
        mem_free(pts);
    return rc;
}

static int pds_strip_cross(const pds_def *a, size_t ia, const pds_def *b, size_t ib, double u, double v,
                           size_t *pairs, int *meet, int *in_union, int *in_inter)
{
    NS(pds_strip) sa, sb;
    unsigned long steps = 0;
    num nu = num_from_d(u), nv = num_from_d(v);
    if (pds_strip_of(a, ia, &sa))
        return -1;
    if (pds_strip_of(b, ib, &sb)) {
        NS(pds_strip_free)(&sa);
        return -1;
    }
    *pairs = NS(pds_strip_intersect)(&sa, &sb, NULL, 0, &steps);
    *meet = NS(pds_strip_regions_meet)(&sa, &sb);
    *in_union = NS(pds_strip_in_union)(&sa, &sb, nu, nv);
    *in_inter = NS(pds_strip_in_inter)(&sa, &sb, nu, nv);
    NS(pds_strip_free)(&sa);
    NS(pds_strip_free)(&sb);
    return 0;
}

const pds_strip_ops NS(pds_strip_ops) = {
    .mode = NUM_NAME,
    .cross = pds_strip_cross,
};
