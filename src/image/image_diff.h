/* image_diff — the difference between two RGB8 images of one size, as
 * reported by `maprt bench` (a mode against the f64 render) and by the
 * display-list writer (the frame against the 5081's quantised view):
 *   mse  = mean over pixels and channels of (a - b)^2
 *   psnr = 10 log10(255^2 / mse) dB, +infinity when identical
 *   max  = largest channel difference, 0..255
 *   over = fraction of pixels whose largest channel difference exceeds the
 *          threshold (strictly). */
#ifndef IMAGE_DIFF_H
#define IMAGE_DIFF_H
#include "image/image.h"

typedef struct image_diff_stats {
    double mse, psnr, over;
    int max;
} image_diff_stats;

/* a and b: 3 channels, same size (the caller checks). */
void image_diff(const image *a, const image *b, int threshold, image_diff_stats *out);
#endif
