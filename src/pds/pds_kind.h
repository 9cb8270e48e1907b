/* pds_kind — the per-kind operations table behind the PDS interface
 * (modal; internal to src/pds). Each PDS kind (pds_cpg.c, pds_pixels.c,
 * pds_tiling.c, pds_mosaic.c, pds_quadtree.c, pds_curves.c) fills one table;
 * pds.c dispatches on the definition's kind.
 *   compile  checked definition -> new compiled structure (mem_*), 0 or
 *            DIAG_IO when memory runs out (err filled)
 *   locate   (u,v) in [0,1] -> region attribute id or PDS_NONE; adds the
 *            number of nodes/cells/edges it visited to *steps
 *   bytes    heap bytes held by the compiled structure
 *   release  frees it */
#ifndef PDS_KIND_H
#define PDS_KIND_H
#include <stddef.h>
#include <stdint.h>
#include "num/num.h"
#include "model/pds_def.h"
#include "util/diag.h"

typedef struct NS(pds_kind_ops) {
    const char *name;
    int (*compile)(const pds_def *def, const char *file, void **out, diag *err);
    int32_t (*locate)(const void *impl, num u, num v, unsigned long *steps);
    size_t (*bytes)(const void *impl);
    void (*release)(void *impl);
} NS(pds_kind_ops);

extern const NS(pds_kind_ops) NS(pds_cpg_ops), NS(pds_pixels_ops), NS(pds_tiling_ops),
    NS(pds_mosaic_ops), NS(pds_quadtree_ops), NS(pds_curves_ops);

/* The out-of-memory diagnostic every compiler reports. */
int NS(pds_oom)(const pds_def *def, const char *file, diag *err);
#endif
