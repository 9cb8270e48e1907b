/* image_png_write — the true-colour and grey PNG encoder: rows filtered
 * (per row the filter with the least sum of magnitudes, libpng's default
 * heuristic) and deflated in bands of IMAGE_PNG_WRITE_BAND rows, the bands
 * on separate threads. Each band is compressed on its own by libdeflate
 * (in one call, about twice as fast as zlib's deflate for the same bytes on
 * rendered pictures: docs/performance.md) and made to end on an empty
 * stored block, so the bands join into one zlib stream and the file does
 * not depend on the number of threads. */
#ifndef IMAGE_PNG_WRITE_H
#define IMAGE_PNG_WRITE_H
#include <stddef.h>
#include "image/image.h"
#include "util/diag.h"

#define IMAGE_PNG_WRITE_BAND  128   /* rows per deflate band */
#define IMAGE_PNG_WRITE_LEVEL 6     /* libdeflate level (docs/performance.md) */

/* Encodes img (1 or 3 channels) as a PNG in memory with up to `threads`
 * threads (>= 1) at libdeflate level `level` (1-12): *out (release with
 * mem_free) and *len. 0, or DIAG_IO (out of memory, a deflate failure;
 * located at name) with err set; outputs untouched then. */
int image_png_write_mem(const image *img, int threads, int level, const char *name,
                        unsigned char **out, size_t *len, diag *err);
#endif
