/* pds_modes — the mode-independent door to the compiled PDS: one table per
 * numeric mode (q16_pds_mode_ops, ...), for code that is not itself modal
 * (tests, benches, the CLI, the scene compiler's mode dispatch). Coordinates
 * cross the table as double and are rounded with the mode's num_from_d. */
#ifndef PDS_MODES_H
#define PDS_MODES_H
#include <stddef.h>
#include <stdint.h>
#include "model/pds_def.h"
#include "util/diag.h"

typedef struct pds_mode_ops {
    const char *mode;                         /* "q16" "q32" "f32" "f64" "hfp32" "hfp64" */
    int (*compile)(const pds_def *def, const char *file, void **out, diag *err);
    void (*free)(void *pds);
    int32_t (*locate)(const void *pds, double u, double v);
    int32_t (*locate_steps)(const void *pds, double u, double v, unsigned long *steps);
    size_t (*bytes)(const void *pds);
    /* Locates n points uv[2*i], uv[2*i+1] into out[i], reps times over
     * (the points are converted once, before the loops, so a bench times the
     * lookups alone); returns how many ids differ from PDS_NONE. */
    size_t (*locate_many)(const void *pds, const double *uv, size_t n, unsigned reps, int32_t *out);
} pds_mode_ops;

extern const pds_mode_ops q16_pds_mode_ops, q32_pds_mode_ops, f32_pds_mode_ops, f64_pds_mode_ops,
    hfp32_pds_mode_ops, hfp64_pds_mode_ops;
#endif
