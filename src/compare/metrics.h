/* metrics — pixel-difference figures between the reference and the
 * (registered) test, over the pixels of a mask, on 1 (luma) or 3 (R,G,B)
 * channels in 8-bit units:
 *   mse = sum over pixels and channels of (ref - test)^2 / (pixels * channels)
 *   psnr = 10 log10(255^2 / mse) dB (infinite when mse is 0)
 *   pixels_over = fraction of pixels whose largest channel difference
 *                 |ref - test| is strictly above the threshold. */
#ifndef METRICS_H
#define METRICS_H
#include "compare/plane.h"

typedef struct metrics {
    long pixels;        /* pixels compared (inside the mask) */
    double mse, psnr, pixels_over;
} metrics;

/* ref and test hold nch planes of one size; mask NULL means all pixels.
 * Returns 0, or 1 when the mask is empty. */
int metrics_compute(const plane *ref, const plane *test, int nch, const plane *mask, double threshold,
                    metrics *out);
#endif
