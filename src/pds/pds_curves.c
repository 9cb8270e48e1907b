/* pds_curves — regions bounded by closed curves (modal): closed polylines
 * or uniform cubic closed B-splines flattened at the definition's tolerance
 * (pds_curve.c), each compiled to a pds_ring with its strip tree. Curves
 * are tried in definition order and the first one containing the point
 * (boundary included) gives the id, so a curve nested inside another is
 * listed before it. */
#include "pds/pds_kind.h"
#include "pds/pds_num.h"
#include "pds/pds_ring.h"
#include "pds/pds_strip.h"
#include "util/mem.h"

typedef struct curves {
    NS(pds_ring) *rings;        /* the box hierarchy, or */
    NS(pds_strip) *strips;      /* Ballard's strip trees (def strips = 1) */
    int32_t *attr;
    size_t n;
} curves;

static void pds_curves_release(void *impl)
{
    curves *c = impl;
    size_t i;
    if (!c)
        return;
    for (i = 0; i < c->n && c->rings; i++)
        NS(pds_ring_free)(&c->rings[i]);
    for (i = 0; i < c->n && c->strips; i++)
        NS(pds_strip_free)(&c->strips[i]);
    mem_free(c->rings);
    mem_free(c->strips);
    mem_free(c->attr);
    mem_free(c);
}

static int pds_curves_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_curves *d = &def->curves;
    curves *c = mem_calloc(1, sizeof *c);
    size_t i;
    if (!c || !(c->attr = mem_calloc(d->ncurves, sizeof *c->attr)))
        goto oom;
    if (d->strips ? !(c->strips = mem_calloc(d->ncurves, sizeof *c->strips))
                  : !(c->rings = mem_calloc(d->ncurves, sizeof *c->rings)))
        goto oom;
    c->n = d->ncurves;
    for (i = 0; i < d->ncurves; i++) {
        double *pts;
        size_t n;
        int owned, rc = pds_curves_ring(d, i, &pts, &n, &owned);
        if (rc)
            goto oom;       /* -1 cannot happen: the check flattened it already */
        rc = d->strips ? NS(pds_strip_build)(&c->strips[i], pts, n, d->strip_width)
                       : NS(pds_ring_build)(&c->rings[i], pts, n);
        if (owned)
            mem_free(pts);
        if (rc)
            goto oom;
        c->attr[i] = d->curves[i].attr;
    }
    *out = c;
    return 0;
oom:
    pds_curves_release(c);
    return NS(pds_oom)(def, file, err);
}

static int32_t pds_curves_locate(const void *impl, num u, num v, unsigned long *steps)
{
    const curves *c = impl;
    size_t i;
    for (i = 0; i < c->n; i++)
        if (c->strips ? NS(pds_strip_inside)(&c->strips[i], u, v, steps)
                      : NS(pds_ring_inside)(&c->rings[i], u, v, steps))
            return c->attr[i];
    return PDS_NONE;
}

static size_t pds_curves_bytes(const void *impl)
{
    const curves *c = impl;
    size_t s = sizeof *c + c->n * sizeof *c->attr, i;
    for (i = 0; i < c->n; i++)
        s += c->strips ? sizeof *c->strips + NS(pds_strip_bytes)(&c->strips[i])
                       : sizeof *c->rings + (c->rings[i].n + 1) * 2 * sizeof(num) +
                             c->rings[i].nnodes * sizeof *c->rings[i].nodes;
    return s;
}

const NS(pds_kind_ops) NS(pds_curves_ops) = {
    .name = "curves",
    .compile = pds_curves_compile,
    .locate = pds_curves_locate,
    .bytes = pds_curves_bytes,
    .release = pds_curves_release,
};
