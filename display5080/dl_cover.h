/* dl_cover — the pixels one element covers, computed once on the CPU for
 * every backend: Bresenham lines (both end points) with MegaPel line styles
 * and a square brush for wide lines, midpoint circle outlines, discs, and
 * even-odd polygons sampled at pixel centres. Pixels are collected as
 * horizontal runs clipped to the element's clip rectangle; dl_cover_finish
 * merges them into disjoint runs, so an element writes each pixel once
 * however often its strokes cross. Each step is charged to the list's
 * drawing budget (dl_work) first, so pathological input becomes an error.
 * Data flow: dl_interp -> dl_cover -> dl_box runs -> dl_device. */
#ifndef DL_COVER_H
#define DL_COVER_H
#include <stddef.h>
#include "display5080/dl_device.h"
#include "display5080/dl_work.h"

/* How a line is drawn: brush width, 16-bit pattern (bit 0 first, 1 = drawn;
 * 0xFFFF solid), pixels per pattern bit, and the pattern position reached. */
typedef struct dl_pen {
    unsigned width;
    unsigned pattern;
    unsigned factor;
    unsigned long long pos;
} dl_pen;

typedef struct dl_cover {
    int cx0, cy0, cx1, cy1;    /* clip, inclusive */
    dl_box *runs;
    size_t n, cap;
    int *xs;                   /* polygon crossings */
    size_t xs_cap;
    dl_work *work;             /* the list's budget (not owned) */
    int status;                /* sticky: 0, DIAG_INPUT (budget spent) or DIAG_IO (memory) */
} dl_cover;

/* Steps are charged to work. */
void dl_cover_init(dl_cover *c, dl_work *work);
void dl_cover_free(dl_cover *c);
/* Starts an element with an empty set clipped to the inclusive rectangle. */
void dl_cover_start(dl_cover *c, int cx0, int cy0, int cx1, int cy1);
/* Adds pixels x0..x1 of row y (clipped). */
void dl_cover_span(dl_cover *c, long long y, long long x0, long long x1);
/* Adds a line from (x0,y0) to (x1,y1); with skip_first its first pixel is
 * neither drawn nor counted in the pattern (a polyline's joint). */
void dl_cover_line(dl_cover *c, int x0, int y0, int x1, int y1, dl_pen *pen, int skip_first);
/* Adds a circle outline or a filled disc of radius r. */
void dl_cover_circle(dl_cover *c, int cx, int cy, unsigned r, int fill);
/* Adds the even-odd interior of a closed polygon of n vertices xy[2n],
 * sampled at pixel centres (vertex (x,y) = centre of pixel (x,y)); centres
 * on the boundary count when `closed` (MegaPel), else only those on left
 * edges, with edges half-open in y (DL5080 version 1). */
void dl_cover_polygon(dl_cover *c, const int *xy, size_t n, int closed);
/* Sorts and merges the runs; *boxes receives them (valid until the next
 * start). Returns the count, or 0 with c->status set on failure. */
size_t dl_cover_finish(dl_cover *c, const dl_box **boxes);
#endif
