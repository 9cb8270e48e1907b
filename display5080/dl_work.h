/* dl_work — the drawing budget of a display list, counted by the
 * interpreter (dl_interp) before each device call, so the png, osmesa and
 * egl backends refuse the same lists at the same element: a list whose
 * drawing would take more than the limit in pixel steps is bad input (its
 * byte offset named), not hours of GL time. The cost of a primitive is what
 * the software raster does for it: the clipped area of a rectangle or a
 * clear (the screen's initial clear included), the area of a pixel block,
 * max(|dx|,|dy|)+1 per line segment (unclipped: Bresenham walks it all),
 * rows times (vertices + clipped width) for a polygon, rows times clipped
 * width for a disc, 8 (r+1) for a circle. */
#ifndef DL_WORK_H
#define DL_WORK_H
#include <stddef.h>
#include "display5080/dl_device.h"

#define DL_WORK_LIMIT (1ull << 30)   /* pixel steps per list */

typedef struct dl_work {
    unsigned long long used, limit;
} dl_work;

/* limit 0 means DL_WORK_LIMIT. */
void dl_work_init(dl_work *w, unsigned long long limit);
/* Adds n steps; DIAG_INPUT at the element (name, offset) that goes over. */
int dl_work_charge(dl_work *w, unsigned long long n, const char *name, long long offset, diag *err);

/* Costs of the device operations (dl_device.h) under clip gc. */
unsigned long long dl_work_rect(const dl_gc *gc, int x0, int y0, int x1, int y1);
unsigned long long dl_work_lines(const int *xy, size_t n, int strip);
unsigned long long dl_work_polygon(const dl_gc *gc, const int *xy, size_t n);
unsigned long long dl_work_circle(const dl_gc *gc, int cy, unsigned r, int fill);
#endif
