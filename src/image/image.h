/* image — an 8-bit raster (grey or RGB), with no file I/O: the type the
 * scene model (textures), the renderer (framebuffer), the display shim and
 * compare share. Its file formats are image_png.h and pnm.h. */
#ifndef IMAGE_H
#define IMAGE_H
#include <stddef.h>
#include <stdint.h>
#include "util/diag.h"

#define IMAGE_MAX_SIDE 32768          /* larger images are refused */
#define IMAGE_MAX_PIXELS (1u << 28)   /* 268 M pixels */

typedef struct image {
    int width, height;
    int channels;                     /* 1 = grey, 3 = RGB */
    uint8_t *px;                      /* rows top to bottom, tightly packed */
} image;

/* A channel count that asks a reader for one channel of palette indices
 * (image_read_png) rather than colours. */
#define IMAGE_INDEXED 0

/* Allocates a zeroed image; DIAG_INPUT for absurd sizes, DIAG_IO when memory
 * runs out. `what` names the image in the diagnostic. */
int image_alloc(image *img, int width, int height, int channels, const char *what, diag *err);
void image_free(image *img);
#endif
