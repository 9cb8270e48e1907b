/* image_tiff — reading TIFF files (scanners' lossless format) into an
 * 8-bit RGB or grey image through libtiff, whatever their bit depth,
 * photometric interpretation or compression (libtiff's RGBA reader; alpha
 * is composited over black). Built only where pkg-config finds libtiff-4
 * (mk/image.mk); elsewhere it refuses, naming the package. First image of
 * the file only. */
#ifndef IMAGE_TIFF_H
#define IMAGE_TIFF_H
#include <stddef.h>
#include "image/image.h"

int image_tiff_available(void);
/* As image_read_jpeg_memory: size checked from the header before decoding. */
int image_read_tiff_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err);
#endif
