/* image_png — PNG input and output of 8-bit rasters: reading and palette
 * output through libpng's simplified API, grey and RGB output through the
 * threaded encoder image_png_write. Shared by the renderer (true-colour output), the display
 * shim (palette output) and compare (reading references). */
#ifndef IMAGE_PNG_H
#define IMAGE_PNG_H
#include <stddef.h>
#include <stdint.h>
#include "image/image.h"
#include "util/diag.h"

/* Writes img as an 8-bit grey or RGB PNG, committed on close, encoded on
 * up to `threads` threads (image_png_write); image_write_png uses OpenMP's
 * default count. */
int image_write_png_mt(const char *path, const image *img, int threads, diag *err);
int image_write_png(const char *path, const image *img, diag *err);
/* Encodes img the same way into memory: *buf (mem_free it) and *size. */
int image_encode_png(const image *img, void **buf, size_t *size, diag *err);
/* Writes an 8-bit palette PNG: index has width*height entries (top row
 * first); palette holds ncolors RGB triples (1..256). */
int image_write_png_palette(const char *path, int width, int height, const uint8_t *index,
                            const uint8_t *palette, int ncolors, diag *err);
/* Reads any PNG, converted to `channels` (1 or 3) 8-bit channels; alpha is
 * composited over black. With channels IMAGE_INDEXED the result has one
 * channel holding a palette PNG's palette indices, or another PNG's grey
 * values. Refuses files over 1 GiB and sizes over the IMAGE_MAX_ limits,
 * from the header. */
int image_read_png(const char *path, int channels, image *out, diag *err);
/* The same from memory (name is used in diagnostics). */
int image_read_png_memory(const char *name, const void *data, size_t len, int channels,
                          image *out, diag *err);

#define IMAGE_PNG_MAX_BYTES ((size_t)1 << 30)
/* Size limits a reader checks from the PNG header, before any pixel is
 * decoded; 0 (or over the IMAGE_MAX_ limits) means the IMAGE_MAX_ limits. */
typedef struct image_limits {
    int max_side;
    size_t max_pixels;
} image_limits;
/* image_read_png and image_read_png_memory with limits (NULL: the defaults). */
int image_read_png_limit(const char *path, int channels, const image_limits *lim, image *out, diag *err);
int image_read_png_memory_limit(const char *name, const void *data, size_t len, int channels,
                                const image_limits *lim, image *out, diag *err);
#endif
