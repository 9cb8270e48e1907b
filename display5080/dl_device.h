/* dl_device — the drawing interface between the 5081 interpreter (dl_interp)
 * and a drawing engine: the software raster (dl_raster) or OpenGL (dl_gl).
 * The interpreter keeps all display state (colour table, colours, logic op,
 * plane mask, scissor) and hands each primitive over with a graphics context.
 * Rule shared by every device: one element writes each pixel at most once
 * (so an element drawn twice with xor restores the screen), and nothing
 * outside gc->clip is written. Coordinates are device pixels, origin lower
 * left, y up. */
#ifndef DL_DEVICE_H
#define DL_DEVICE_H
#include <stddef.h>
#include <stdint.h>
#include "util/diag.h"

typedef struct dl_gc {
    unsigned colour;           /* source index 0..255 */
    unsigned op;               /* logic op 1..16 */
    unsigned mask;             /* plane mask 0..255 */
    int cx0, cy0, cx1, cy1;    /* clip: scissor within the screen, inclusive, non-empty */
    const char *name;          /* for diagnostics */
    long long offset;          /* element being drawn */
} dl_gc;

/* Each operation returns 0 or a diag status recorded in err. */
typedef struct dl_device {
    /* Fill the inclusive rectangle with gc->colour. */
    int (*rect)(void *dev, const dl_gc *gc, int x0, int y0, int x1, int y1, diag *err);
    /* Write w x h source pixels (rows bottom-up, stride bytes apart) at
     * (x0,y0) with gc->op and gc->mask (gc->colour unused). */
    int (*blt)(void *dev, const dl_gc *gc, int x0, int y0, int w, int h, const uint8_t *rows,
               size_t stride, diag *err);
    /* n points xy[2n]: a connected polyline (strip = 1) or n/2 separate
     * segments (strip = 0); every segment includes both end points. */
    int (*lines)(void *dev, const dl_gc *gc, const int *xy, size_t n, int strip, diag *err);
    /* Closed polygon of n vertices, filled by the even-odd rule, sampling at
     * pixel centres (a vertex (x,y) is the centre of pixel (x,y)). */
    int (*polygon)(void *dev, const dl_gc *gc, const int *xy, size_t n, diag *err);
    /* Circle of radius r about (cx,cy): outline or filled disc. */
    int (*circle)(void *dev, const dl_gc *gc, int cx, int cy, unsigned r, int fill, diag *err);
} dl_device;
#endif
