/* render_part — a rendered region of an image as bytes: what one MPI rank
 * sends back for its tiles, and what `render --part` writes for a batch
 * system's array job, so that `maprt merge` (or rank 0) can assemble the
 * whole framebuffer and write exactly the bytes a single process writes.
 *
 * Layout (docs/cluster.md), all integers big-endian:
 *   0   8  magic "MAPRTPT3" (format 3; the older "MAPRTPT1" and
 *          "MAPRTPT2", without the scene's counts, are refused with a
 *          message)
 *   8   4  image width          12  4  image height
 *   16 16  region x0 y0 x1 y1   (pixels [x0,x1) x [y0,y1))
 *   32  4  samples per pixel side (--aa)
 *   36  8  numeric mode name, NUL-padded ("q16", "f64", ...)
 *   44  4  contents: bit 0 = the identity map follows the ids; others 0
 *   48 184 render_stats: 23 counters (u64: the seventeen of render_stats,
 *          the scene's three counts last, then the six HFP exceptions),
 *          then compile and render seconds as binary64 bit patterns (u64)
 *   248    region pixels, rows top first: RGB8 (3 bytes each), then the
 *          primitive ids (i32 each, -1 = background), then with bit 0 the
 *          identity map records (24 bytes each: primitive, face, region,
 *          flags as i32, distance as a binary64 bit pattern)
 * Pure functions over memory; the caller reads and writes files. */
#ifndef RENDER_PART_H
#define RENDER_PART_H
#include <stddef.h>
#include <stdint.h>
#include "render/render.h"
#include "util/diag.h"

#define RENDER_PART_COUNTERS (17 + HFP_EXC_N)
#define RENDER_PART_HEADER (48 + 8 * RENDER_PART_COUNTERS + 16)
#define RENDER_PART_IDS 1     /* contents bit: the identity map is included */
/* Bytes per pixel: RGB8 and the primitive id, and an identity record. */
#define RENDER_PART_PX 7
#define RENDER_PART_ID_PX 24

typedef struct render_part_info {
    int width, height;        /* the whole image */
    int region[4];            /* x0 y0 x1 y1 */
    int aa;
    char mode[9];             /* NUL-terminated */
    int ids;                  /* the identity map is included (fb->ids) */
    render_stats stats;       /* this region's counters */
} render_part_info;

/* Bytes of the encoding of a region of that size (header included), with
 * or without the identity map. */
size_t render_part_bytes(const int region[4], int ids);
/* Encodes the region info->region of fb (a whole-image framebuffer of
 * info->width x info->height, with fb->ids filled when info->ids) into a
 * new buffer *out of *len bytes (mem_free it). 0, or DIAG_IO when memory
 * runs out. */
int render_part_encode(const render_fb *fb, const render_part_info *info, uint8_t **out,
                       size_t *len, diag *err);
/* Decodes buf (len bytes, named `name` in diagnostics) into *info and the
 * offsets of its pixel data. The header is checked against the limits
 * (SCENE_MAX_SIDE, a region inside the image) and len against the size the
 * header implies before anything else is read. 0, or DIAG_INPUT with the
 * byte offset of the first bad field. */
int render_part_decode(const char *name, const uint8_t *buf, size_t len, render_part_info *info,
                       diag *err);
/* Copies a decoded part's pixels into fb (a whole-image framebuffer of the
 * part's size, with fb->ids allocated when info->ids). covered (width*height bytes, 0 = not yet) marks the pixels
 * placed so far; a pixel placed twice is an error (DIAG_INPUT, naming the
 * part and the pixel). */
int render_part_place(const char *name, const uint8_t *buf, const render_part_info *info,
                      render_fb *fb, uint8_t *covered, diag *err);
#endif
