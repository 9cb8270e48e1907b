/* pds_mosaic — Voronoi mosaic of seed points (modal). A point belongs to
 * the nearest seed (ties: the lower seed number); it is mortar when it lies
 * within mortar/2 of the bisector with some other seed, i.e. when
 * d_i^2 - d_1^2 <= mortar * |s_i - s_1| for a seed i other than the nearest.
 *
 * Seeds are kept in an implicit 2-d tree: the seed at the middle of each
 * index range splits it (u at even depths, v at odd), smaller coordinates to
 * the left. A lookup descends towards the point and opens the far side only
 * when the splitting line is not farther than the best distance so far, so
 * clustered seeds cost O(log n) as well as spread ones. The mortar test then
 * visits the seeds within d_1 + mortar, since only they can own a bisector
 * inside the band (d_i - d_1 <= mortar is necessary). */
#include "pds/pds_kind.h"
#include <math.h>
#include "pds/pds_num.h"
#include "util/mem.h"

#define KD_LEAF 6          /* ranges this short are scanned */

typedef struct seed {
    num u, v;
    int32_t attr;          /* region attribute id */
    uint32_t order;        /* definition number, for ties */
} seed;

typedef struct mosaic {
    seed *s;               /* seeds in tree order */
    size_t n;
    num mortar;
    int32_t mortar_attr;
} mosaic;

static void pds_mosaic_release(void *impl)
{
    mosaic *m = impl;
    if (!m)
        return;
    mem_free(m->s);
    mem_free(m);
}

static void pds_mosaic_swap(mosaic *m, size_t a, size_t b)
{
    seed t = m->s[a];
    m->s[a] = m->s[b];
    m->s[b] = t;
}

static num pds_mosaic_key(const seed *s, int axis) { return axis ? s->v : s->u; }

/* Quickselect: puts the k-th smallest key (u or v) at k, smaller-or-equal
 * keys before it and larger-or-equal after. Median-of-three pivots. */
static void pds_mosaic_select_k(mosaic *m, size_t lo, size_t hi, size_t k, int axis)
{
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2, i, store;
        num a = pds_mosaic_key(&m->s[lo], axis), b = pds_mosaic_key(&m->s[mid], axis), c = pds_mosaic_key(&m->s[hi - 1], axis), pivot;
        size_t p = (a < b) == (b < c) ? mid : (b < a) == (a < c) ? lo : hi - 1;
        pds_mosaic_swap(m, p, hi - 1);
        pivot = pds_mosaic_key(&m->s[hi - 1], axis);
        for (i = store = lo; i < hi - 1; i++)
            if (pds_mosaic_key(&m->s[i], axis) < pivot)
                pds_mosaic_swap(m, i, store++);
        pds_mosaic_swap(m, store, hi - 1);
        if (k == store)
            return;
        if (k < store)
            hi = store;
        else
            lo = store + 1;
    }
}

static void pds_mosaic_build(mosaic *m, size_t lo, size_t hi, int depth)
{
    size_t mid;
    if (hi - lo <= KD_LEAF)
        return;
    mid = lo + (hi - lo) / 2;
    pds_mosaic_select_k(m, lo, hi, mid, depth & 1);
    pds_mosaic_build(m, lo, mid, depth + 1);
    pds_mosaic_build(m, mid + 1, hi, depth + 1);
}

static int pds_mosaic_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_mosaic *d = &def->mosaic;
    mosaic *m = mem_calloc(1, sizeof *m);
    size_t i, n = d->nseeds;
    if (!m)
        goto oom;
    m->n = n;
    m->s = mem_calloc(n, sizeof *m->s);
    if (!m->s)
        goto oom;
    for (i = 0; i < n; i++) {
        m->s[i].u = num_from_d(d->seeds[2 * i]);
        m->s[i].v = num_from_d(d->seeds[2 * i + 1]);
        m->s[i].attr = d->attrs[i];
        m->s[i].order = (uint32_t)i;
    }
    pds_mosaic_build(m, 0, n, 0);
    m->mortar = num_from_d(d->mortar);
    m->mortar_attr = d->mortar_attr;
    *out = m;
    return 0;
oom:
    pds_mosaic_release(m);
    return NS(pds_oom)(def, file, err);
}

typedef struct query {
    const mosaic *m;
    num u, v;
    pds_wide best;         /* squared distance of the nearest so far */
    size_t bi;             /* its index */
    pds_wide reach2;       /* mortar pass: squared search radius */
    unsigned long steps;
} query;

static void pds_mosaic_consider(query *q, size_t i)
{
    const seed *s = &q->m->s[i];
    pds_wide dd = pds_wide_sq2(num_sub(s->u, q->u), num_sub(s->v, q->v));
    q->steps++;
    if (dd < q->best || (dd == q->best && s->order < q->m->s[q->bi].order)) {
        q->best = dd;
        q->bi = i;
    }
}

static void pds_mosaic_nearest(query *q, size_t lo, size_t hi, int depth)
{
    size_t mid, i;
    num diff;
    if (hi - lo <= KD_LEAF) {
        for (i = lo; i < hi; i++)
            pds_mosaic_consider(q, i);
        return;
    }
    mid = lo + (hi - lo) / 2;
    pds_mosaic_consider(q, mid);
    diff = num_sub(depth & 1 ? q->v : q->u, pds_mosaic_key(&q->m->s[mid], depth & 1));
    if (diff < NUM_ZERO) {
        pds_mosaic_nearest(q, lo, mid, depth + 1);
        if (pds_wide_sq2(diff, NUM_ZERO) <= q->best)   /* ties may lie across */
            pds_mosaic_nearest(q, mid + 1, hi, depth + 1);
    } else {
        pds_mosaic_nearest(q, mid + 1, hi, depth + 1);
        if (pds_wide_sq2(diff, NUM_ZERO) <= q->best)
            pds_mosaic_nearest(q, lo, mid, depth + 1);
    }
}

/* 1 if a seed within the search radius puts the point in the mortar band. */
static int pds_mosaic_in_band(query *q, size_t i)
{
    const seed *s = &q->m->s[i], *b = &q->m->s[q->bi];
    pds_wide dd;
    if (i == q->bi)
        return 0;
    q->steps++;
    dd = pds_wide_sq2(num_sub(s->u, q->u), num_sub(s->v, q->v));
    if (dd > q->reach2)
        return 0;
    return pds_wide_band(pds_wide_sub(dd, q->best), q->m->mortar, pds_wide_sq2(num_sub(s->u, b->u), num_sub(s->v, b->v)));
}

static int pds_mosaic_band(query *q, size_t lo, size_t hi, int depth)
{
    size_t mid, i;
    num diff;
    if (hi - lo <= KD_LEAF) {
        for (i = lo; i < hi; i++)
            if (pds_mosaic_in_band(q, i))
                return 1;
        return 0;
    }
    mid = lo + (hi - lo) / 2;
    if (pds_mosaic_in_band(q, mid))
        return 1;
    diff = num_sub(depth & 1 ? q->v : q->u, pds_mosaic_key(&q->m->s[mid], depth & 1));
    if (diff <= NUM_ZERO || pds_wide_sq2(diff, NUM_ZERO) <= q->reach2)
        if (pds_mosaic_band(q, lo, mid, depth + 1))
            return 1;
    if (diff >= NUM_ZERO || pds_wide_sq2(diff, NUM_ZERO) <= q->reach2)
        if (pds_mosaic_band(q, mid + 1, hi, depth + 1))
            return 1;
    return 0;
}

static int32_t pds_mosaic_locate(const void *impl, num u, num v, unsigned long *steps)
{
    const mosaic *m = impl;
    query q;
    q.m = m;
    q.u = u;
    q.v = v;
    q.best = PDS_WIDE_MAX;
    q.bi = 0;
    q.steps = 0;
    pds_mosaic_nearest(&q, 0, m->n, 0);
    if (m->mortar > NUM_ZERO) {
        const seed *b = &m->s[q.bi];
        q.reach2 = pds_wide_reach2(q.best, m->mortar, num_add(num_abs(num_sub(b->u, u)), num_abs(num_sub(b->v, v))));
        if (pds_mosaic_band(&q, 0, m->n, 0)) {
            *steps += q.steps;
            return m->mortar_attr;
        }
    }
    *steps += q.steps;
    return m->s[q.bi].attr;
}

static size_t pds_mosaic_bytes(const void *impl)
{
    const mosaic *m = impl;
    return sizeof *m + m->n * sizeof *m->s;
}

const NS(pds_kind_ops) NS(pds_mosaic_ops) = {
    .name = "mosaic",
    .compile = pds_mosaic_compile,
    .locate = pds_mosaic_locate,
    .bytes = pds_mosaic_bytes,
    .release = pds_mosaic_release,
};
