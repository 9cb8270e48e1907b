/* pds — the planar division structure interface for one numeric mode
 * (modal: include after compiling with -DNUM_MODE=<m>; symbols are
 * <m>_pds_*). The renderer's attribute mapping (Algorithm 1, step 3) calls
 *     id = NS(pds_locate)(pds, u, v);
 * with the hit point's face parameters and uses id as the region attribute
 * (PDS_NONE: keep the face's base attribute).
 *
 *   definitions (scene/pds_def.h, double)
 *     -> NS(pds_compile) -> NS(pds) (flat arrays, read-only, thread-safe)
 *     -> NS(pds_locate)(u, v) -> region attribute id | PDS_NONE
 *
 * Mode-independent callers (the CLI, tests, the scene compiler's dispatch)
 * use the per-mode tables of pds_modes.h instead of this header. */
#ifndef PDS_H
#define PDS_H
#include <stddef.h>
#include <stdint.h>
#include "num/num.h"
#include "model/pds_def.h"
#include "util/diag.h"
#include "pds/pds_kind.h"

typedef struct NS(pds) {
    pds_kind kind;
    const NS(pds_kind_ops) *ops;
    void *impl;
} NS(pds);

/* Validates def (pds_def_check) and compiles it for this mode. Coordinates
 * are rounded once with num_from_d, the same rounding used for the (u,v)
 * of a lookup, so a point given exactly on a boundary is classified by the
 * documented convention in every mode. Returns 0 and sets *out (free with
 * NS(pds_free)); DIAG_INPUT for a malformed definition, DIAG_IO when memory
 * runs out; *out is untouched on error. `file` names the deck in messages. */
int NS(pds_compile)(const pds_def *def, const char *file, NS(pds) **out, diag *err);
void NS(pds_free)(NS(pds) *p);

/* Region attribute id at (u,v), or PDS_NONE. Coordinates are clamped to
 * [0,1] first (NaN counts as 0), so any input is safe. Thread-safe. */
static inline int32_t NS(pds_locate)(const NS(pds) *p, num u, num v)
{
    unsigned long steps = 0;
    if (!(u > NUM_ZERO)) u = NUM_ZERO;
    if (!(v > NUM_ZERO)) v = NUM_ZERO;
    if (u > NUM_ONE) u = NUM_ONE;
    if (v > NUM_ONE) v = NUM_ONE;
    return p->ops->locate(p->impl, u, v, &steps);
}

/* The same, adding to *steps the nodes, cells or edges visited (for the
 * complexity tests and --stats). */
int32_t NS(pds_locate_steps)(const NS(pds) *p, num u, num v, unsigned long *steps);

/* Heap bytes held by the compiled structure. */
size_t NS(pds_bytes)(const NS(pds) *p);
#endif
