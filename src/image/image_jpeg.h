/* image_jpeg — reading JPEG files (scans of the paper's figures usually
 * are) into an 8-bit RGB or grey image through libjpeg-turbo. Built only
 * where pkg-config finds libjpeg (mk/image.mk); elsewhere it refuses,
 * naming the package. */
#ifndef IMAGE_JPEG_H
#define IMAGE_JPEG_H
#include <stddef.h>
#include "image/image.h"

/* 1 if this maprt reads JPEG. */
int image_jpeg_available(void);
/* Decodes the JPEG data (len bytes; name labels diagnostics) into out with
 * `channels` (1 or 3) channels. The size is checked against max_pixels
 * from the header, before any allocation. 0, DIAG_INPUT (corrupt, CMYK,
 * too large, or no JPEG support built in) or DIAG_IO (out of memory). */
int image_read_jpeg_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err);
#endif
