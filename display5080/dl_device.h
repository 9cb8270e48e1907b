/* dl_device — the writing interface between the 5081 interpreter (dl_interp)
 * and a frame buffer: the software raster (dl_raster) or OpenGL (dl_gl).
 * The interpreter keeps all display state, rasterises every shape itself
 * (dl_cover) and clips everything to the scissor and the screen, so a device
 * only writes what it is given: disjoint boxes of one colour, and blocks of
 * pixels, each through the logic op and plane mask. Writing is all a device
 * does, so every device shows the same pixels. Coordinates are device pixels,
 * origin lower left, y up. */
#ifndef DL_DEVICE_H
#define DL_DEVICE_H
#include <stddef.h>
#include <stdint.h>
#include "util/diag.h"

typedef struct dl_gc {
    unsigned colour;           /* source index 0..255 (boxes) */
    unsigned op;               /* logic op 1..16 */
    unsigned mask;             /* planes that may be written, 0..255 */
    const char *name;          /* for diagnostics */
    long long offset;          /* element being drawn */
} dl_gc;

/* An inclusive box of pixels. */
typedef struct dl_box {
    int x0, y0, x1, y1;
} dl_box;

/* Each operation returns 0 or a diag status recorded in err. */
typedef struct dl_device {
    /* Writes gc->colour over n disjoint, non-empty boxes inside the screen. */
    int (*boxes)(void *dev, const dl_gc *gc, const dl_box *b, size_t n, diag *err);
    /* Writes w x h source pixels at (x0,y0) (inside the screen, w,h >= 1);
     * rows points at the bottom row and row j+1 is at rows + (j+1)*stride. */
    int (*blt)(void *dev, const dl_gc *gc, int x0, int y0, int w, int h, const uint8_t *rows,
               ptrdiff_t stride, diag *err);
} dl_device;
#endif
