/* pds — per-mode PDS front: kind dispatch, locate entry points and the
 * mode-independent table (see pds.h, pds_modes.h). */
#include "pds/pds.h"
#include "pds/pds_modes.h"
#include "util/mem.h"

int NS(pds_oom)(const pds_def *def, const char *file, diag *err)
{
    return diag_at(err, DIAG_IO, file, def->loc.line, def->loc.col,
                   "out of memory compiling a planar division structure");
}

static const NS(pds_kind_ops) *pds_kind_ops_of(pds_kind k)
{
    switch (k) {
    case PDS_CPG: return &NS(pds_cpg_ops);
    case PDS_PIXELS: return &NS(pds_pixels_ops);
    case PDS_TILING: return &NS(pds_tiling_ops);
    case PDS_MOSAIC: return &NS(pds_mosaic_ops);
    case PDS_QUADTREE: return &NS(pds_quadtree_ops);
    case PDS_CURVES: return &NS(pds_curves_ops);
    default: return NULL;
    }
}

int NS(pds_compile)(const pds_def *def, const char *file, NS(pds) **out, diag *err)
{
    NS(pds) *p;
    int rc = pds_def_check(def, file, err);
    if (rc)
        return rc;
    p = mem_calloc(1, sizeof *p);
    if (!p)
        return NS(pds_oom)(def, file, err);
    p->kind = def->kind;
    p->ops = pds_kind_ops_of(def->kind);
    rc = p->ops->compile(def, file, &p->impl, err);
    if (rc) {
        mem_free(p);
        return rc;
    }
    *out = p;
    return 0;
}

void NS(pds_free)(NS(pds) *p)
{
    if (!p)
        return;
    p->ops->release(p->impl);
    mem_free(p);
}

int32_t NS(pds_locate_steps)(const NS(pds) *p, num u, num v, unsigned long *steps)
{
    if (!(u > NUM_ZERO)) u = NUM_ZERO;
    if (!(v > NUM_ZERO)) v = NUM_ZERO;
    if (u > NUM_ONE) u = NUM_ONE;
    if (v > NUM_ONE) v = NUM_ONE;
    return p->ops->locate(p->impl, u, v, steps);
}

size_t NS(pds_bytes)(const NS(pds) *p)
{
    return sizeof *p + p->ops->bytes(p->impl);
}

/* ---- the mode-independent table ---------------------------------------- */

static int pds_mode_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    NS(pds) *p = NULL;
    int rc = NS(pds_compile)(def, file, &p, err);
    if (rc == 0)
        *out = p;
    return rc;
}

static void pds_mode_free(void *p) { NS(pds_free)(p); }

static int32_t pds_mode_locate(const void *p, double u, double v)
{
    return NS(pds_locate)(p, num_from_d(u), num_from_d(v));
}

static int32_t pds_mode_locate_steps(const void *p, double u, double v, unsigned long *steps)
{
    return NS(pds_locate_steps)(p, num_from_d(u), num_from_d(v), steps);
}

static size_t pds_mode_bytes(const void *p) { return NS(pds_bytes)(p); }

static size_t pds_mode_locate_many(const void *pds, const double *uv, size_t n, unsigned reps, int32_t *out)
{
    size_t i, hits = 0;
    unsigned r;
    num *q = mem_calloc(n, 2 * sizeof *q);
    if (!q) {
        for (i = 0; i < n; i++)
            if ((out[i] = pds_mode_locate(pds, uv[2 * i], uv[2 * i + 1])) != PDS_NONE)
                hits++;
        return hits;
    }
    for (i = 0; i < 2 * n; i++)
        q[i] = num_from_d(uv[i]);
    for (r = 0; r < reps; r++)
        for (i = 0, hits = 0; i < n; i++)
            if ((out[i] = NS(pds_locate)(pds, q[2 * i], q[2 * i + 1])) != PDS_NONE)
                hits++;
    mem_free(q);
    return hits;
}

const pds_mode_ops NS(pds_mode_ops) = {
    .mode = NUM_NAME,
    .compile = pds_mode_compile,
    .free = pds_mode_free,
    .locate = pds_mode_locate,
    .locate_steps = pds_mode_locate_steps,
    .bytes = pds_mode_bytes,
    .locate_many = pds_mode_locate_many,
};
