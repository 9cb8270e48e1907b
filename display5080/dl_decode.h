/* dl_decode — the one strict DL5080 parser. It checks the header and every
 * element (framing, code, payload size, field ranges, polygon structure, the
 * final end element) and hands each decoded element to a visitor table: the
 * 5081 interpreter (dl_interp), the disassembler (dl_dump) and the validator
 * (dl_validate) all sit behind it, so there is exactly one parser. It also
 * reads a raw MegaPel element stream (no header, no end element, MegaPel
 * codes only: what IBM's driver wrote into the adapter's FIFO) and lists of
 * DL5080 version 1, whose plane mask and BLT rows it converts to the
 * current meaning, so visitors see one semantics.
 * Data flow: DL5080 bytes -> dl_decode -> visitor -> raster / text / summary. */
#ifndef DL_DECODE_H
#define DL_DECODE_H
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_format.h"
#include "util/diag.h"

typedef struct dl_header {
    unsigned version;          /* 1 or DL_VERSION; 0 for a raw MegaPel stream */
    unsigned flags;            /* DL_FLAG_DAC8 or 0 */
    int width, height;         /* 1..DL_MAX_SIDE */
} dl_header;

/* One decoded element. Pointers point into the caller's buffer and are valid
 * only during the visitor call. Which fields are set depends on code:
 *   rect (fill-rect, viewport, scissor, blt, blt-expand, src-blt): x0,y0
 *     lower-left, x1,y1 upper-right
 *   point (text) / centre (circles): x0,y0; radius in value
 *   char-up: x0,y0 the up vector
 *   polyline/segments: count points at data (use dl_element_point)
 *   colours, line type, width, char height, code page, styles, clear: value
 *   logic op: value; plane mask: value = the word as sent, planes = the
 *     planes it lets be written (version 1 lists converted)
 *   user-line-style: value = 16-bit mask (bit 0 first), count = factor
 *   blt: value = bits/pixel, op = logic op, data = the BOTTOM row of the
 *     rectangle, stride = bytes from a row to the one above it (negative for
 *     the top-first rows IBM's driver sends)
 *   blt-expand: value = colour, op, data/stride as blt, 1 bit a pixel, MSB first
 *   src-blt: addr = adapter memory address, value = bits/pixel, op
 *   text: count bytes at data (in the current code page)
 *   load-colours: start, count entries at data (use dl_element_colour)
 *   run-row: x0 = first x, y0 = row, count runs at data (use dl_element_run)
 *   noop: count bytes at data */
typedef struct dl_element {
    unsigned code;
    long long offset;          /* byte offset of the element in the file */
    unsigned length;           /* total element length in bytes */
    int in_polygon;            /* 1 for the polyline between begin and end polygon */
    int x0, y0, x1, y1;
    unsigned value, op, start, count;
    unsigned planes;
    uint32_t addr;
    ptrdiff_t stride;
    const uint8_t *data;
} dl_element;

void dl_element_point(const dl_element *e, unsigned i, int *x, int *y);
uint32_t dl_element_colour(const dl_element *e, unsigned i);   /* 0x00RRGGBB */
void dl_element_run(const dl_element *e, unsigned i, unsigned *count, unsigned *colour);

/* A visitor: both callbacks may be NULL. A callback returns 0 to go on, or a
 * diag status after recording the error in err (it has e->offset for that). */
typedef struct dl_visitor {
    int (*header)(void *ctx, const dl_header *h, diag *err);
    int (*element)(void *ctx, const dl_element *e, diag *err);
} dl_visitor;

typedef struct dl_decode_opts {
    unsigned long max_elements;   /* step limit; 0 = DL_DECODE_MAX_ELEMENTS */
    int raw;                      /* 1: a raw MegaPel element stream */
    int width, height;            /* raw only: the screen; 0 = 1024 (a 5081) */
    unsigned flags;               /* raw only: DL_FLAG_DAC8 or 0 */
} dl_decode_opts;
#define DL_DECODE_MAX_ELEMENTS 16000000ul

/* Decodes buf (len bytes) and visits every element in order. name is used in
 * diagnostics; opts may be NULL. Returns 0, or DIAG_INPUT with err naming the
 * byte offset of the first malformed element (or a visitor's status). If h is
 * not NULL it receives the header on success. */
int dl_decode(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
              const dl_visitor *v, void *ctx, dl_header *h, diag *err);
#endif
