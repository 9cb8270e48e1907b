/* dl_raster — the software 5081 frame buffer: width x height 8-bit indices,
 * written box by box and block by block through the logic op and plane
 * mask. The png backend, and the reference the GL backends are tested
 * against. It writes what it is given: the interpreter has charged every
 * operation to the list's drawing budget (dl_work) before issuing it. */
#ifndef DL_RASTER_H
#define DL_RASTER_H
#include <stdint.h>
#include "display5080/dl_device.h"

typedef struct dl_raster {
    int width, height;
    uint8_t *px;               /* row y (0 = bottom) at px + y*width */
} dl_raster;

extern const dl_device dl_raster_device;

/* Creates a zeroed raster; DIAG_IO when memory runs out. */
int dl_raster_init(dl_raster *r, int width, int height, diag *err);
void dl_raster_free(dl_raster *r);
#endif
