/* image_png_write — the true-colour and grey PNG encoder: rows filtered
 * (per row the filter with the least sum of magnitudes, libpng's default
 * heuristic) and deflated in bands of IMAGE_PNG_WRITE_BAND rows, the bands
 * on separate threads. Each band starts from the previous band's last 32 KiB
 * of filtered data as its dictionary and ends on a sync flush, so the bands
 * join into one zlib stream (as pigz does) and the file does not depend on
 * the number of threads. */
#ifndef IMAGE_PNG_WRITE_H
#define IMAGE_PNG_WRITE_H
#include <stddef.h>
#include "image/image.h"
#include "util/diag.h"

#define IMAGE_PNG_WRITE_BAND  128   /* rows per deflate band */
#define IMAGE_PNG_WRITE_LEVEL 6     /* zlib level (docs/performance.md) */

/* Encodes img (1 or 3 channels) as a PNG in memory with up to `threads`
 * threads (>= 1) at zlib level `level`: *out (release with mem_free) and
 * *len. 0, or DIAG_IO (out of memory, zlib failure; located at name) with
 * err set; outputs untouched then. */
int image_png_write_mem(const image *img, int threads, int level, const char *name,
                        unsigned char **out, size_t *len, diag *err);
#endif
