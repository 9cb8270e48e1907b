/* pds_strip_ops — the mode-independent door to Ballard's strip-tree
 * operations on two curves of CURVES definitions (for tests, benches and
 * tools; pds_strip.h is the modal interface). One table per mode. */
#ifndef PDS_STRIP_OPS_H
#define PDS_STRIP_OPS_H
#include <stddef.h>
#include "model/pds_def.h"

typedef struct pds_strip_ops {
    const char *mode;
    /* Curve ia of a against curve ib of b (checked definitions), strip
     * trees built to each definition's strip_width: *pairs = the number of
     * edge pairs that meet, *meet = whether the regions they bound share a
     * point, *in_union / *in_inter = membership of (u,v) in their union and
     * intersection. 0, or -1 when memory runs out. */
    int (*cross)(const pds_def *a, size_t ia, const pds_def *b, size_t ib, double u, double v,
                 size_t *pairs, int *meet, int *in_union, int *in_inter);
} pds_strip_ops;

extern const pds_strip_ops q16_pds_strip_ops, q32_pds_strip_ops, f32_pds_strip_ops, f64_pds_strip_ops,
    hfp32_pds_strip_ops, hfp64_pds_strip_ops;
#endif
