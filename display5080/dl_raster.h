/* dl_raster — the software 5081 frame buffer: width x height 8-bit indices
 * and the reference implementation of every dl_device operation (Bresenham
 * lines with both end points, even-odd polygon fill at pixel centres,
 * midpoint circles, discs by integer square root). Used by the png backend
 * and as the reference the GL backends are tested against. The work budget
 * that turns pathological input into an error is the interpreter's
 * (dl_work.h), the same for every backend. */
#ifndef DL_RASTER_H
#define DL_RASTER_H
#include <stdint.h>
#include "display5080/dl_device.h"

typedef struct dl_raster {
    int width, height;
    uint8_t *px;               /* row y (0 = bottom) at px + y*width */
    uint8_t *stamp;            /* per-pixel "written by this element" marks, lazily allocated */
    uint8_t epoch;
    int *xs;                   /* polygon crossings scratch */
    size_t xs_cap;
} dl_raster;

extern const dl_device dl_raster_device;

/* Creates a zeroed raster; DIAG_IO when memory runs out. */
int dl_raster_init(dl_raster *r, int width, int height, diag *err);
void dl_raster_free(dl_raster *r);
#endif
