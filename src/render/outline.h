/* outline — the scene's outlines as seen in a render, for the display-list
 * wireframe. An edge pixel is one whose surface id (primitive and face, or
 * background) differs from its right or lower neighbour; edge pixels are
 * covered by straight segments, vertical runs of two or more pixels first,
 * then horizontal runs, so every edge pixel is drawn exactly once and a
 * straight boundary becomes one segment. Coordinates are pixel positions in
 * the image, origin top-left; both end points are part of the segment. */
#ifndef OUTLINE_H
#define OUTLINE_H
#include <stddef.h>
#include <stdint.h>
#include "util/diag.h"

typedef struct outline_seg {
    int x0, y0, x1, y1;
} outline_seg;

/* Traces the outlines of an id buffer (width*height ids, top row first).
 * On success *segs (mem_free it) holds *nsegs segments; DIAG_IO when memory
 * runs out. */
int outline_trace(const int32_t *id, int width, int height, outline_seg **segs,
                  size_t *nsegs, diag *err);
#endif
