/* imgload — reads a picture for compare from a host file, PNG, PNM
 * (P2 P3 P5 P6), JPEG or TIFF (image_jpeg.h, image_tiff.h: where built with
 * them), recognised by its first bytes, as 8-bit RGB (grey files are
 * replicated into the three channels). Any other kind is named (util/sniff). */
#ifndef IMGLOAD_H
#define IMGLOAD_H
#include "image/image.h"

#define IMGLOAD_MAX_BYTES ((size_t)1 << 30)

/* Pictures over max_pixels are refused from their header, before decoding.
 * 0, DIAG_INPUT (missing file, directory, not a picture, corrupt, too
 * large) or DIAG_IO (unreadable, out of memory); out written only on
 * success. */
int imgload_read(const char *path, size_t max_pixels, image *out, diag *err);
/* The same for a file already in memory; name is used in diagnostics. */
int imgload_memory(const char *name, const void *data, size_t len, size_t max_pixels, image *out, diag *err);
#endif
