/* pds_pixels — pixel-array PDS (modal): one region attribute id per cell of
 * a W x H grid over the unit square, found in O(1). Cell (i,j) covers
 * [i/W, (i+1)/W) x [j/H, (j+1)/H) with u = 1 or v = 1 in the last cell; j
 * counts from v = 0, while the definition lists rows from the top (v = 1). */
#include "pds/pds_kind.h"
#include "pds/pds_num.h"
#include <string.h>
#include "util/mem.h"

typedef struct pixels {
    long w, h;
    int32_t *cells;      /* row j (from v = 0) at cells[j * w] */
} pixels;

static void pds_pixels_release(void *impl)
{
    pixels *p = impl;
    if (p)
        mem_free(p->cells);
    mem_free(p);
}

static int pds_pixels_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_pixels *src = &def->pixels;
    pixels *p = mem_calloc(1, sizeof *p);
    long j;
    if (!p || !(p->cells = mem_calloc(src->ncells, sizeof *p->cells))) {
        pds_pixels_release(p);
        return NS(pds_oom)(def, file, err);
    }
    p->w = src->width;
    p->h = src->height;
    for (j = 0; j < p->h; j++)
        memcpy(p->cells + j * p->w, src->cells + (p->h - 1 - j) * p->w, (size_t)p->w * sizeof *p->cells);
    *out = p;
    return 0;
}

static int32_t pds_pixels_locate(const void *impl, num u, num v, unsigned long *steps)
{
    const pixels *p = impl;
    ++*steps;
    return p->cells[pds_num_cell(v, p->h) * p->w + pds_num_cell(u, p->w)];
}

static size_t pds_pixels_bytes(const void *impl)
{
    const pixels *p = impl;
    return sizeof *p + (size_t)(p->w * p->h) * sizeof *p->cells;
}

const NS(pds_kind_ops) NS(pds_pixels_ops) = {
    .name = "pixels",
    .compile = pds_pixels_compile,
    .locate = pds_pixels_locate,
    .bytes = pds_pixels_bytes,
    .release = pds_pixels_release,
};
