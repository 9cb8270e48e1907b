/* image_diff — MSE, PSNR, largest and over-threshold differences (see image_diff.h). */
#include "image/image_diff.h"
#include <math.h>
#include <stdlib.h>

void image_diff(const image *a, const image *b, int threshold, image_diff_stats *out)
{
    size_t i, n = (size_t)a->width * (size_t)a->height, over = 0;
    double se = 0;
    int m = 0;
    for (i = 0; i < n; i++) {
        int k, worst = 0;
        for (k = 0; k < 3; k++) {
            int d = abs((int)a->px[3 * i + k] - (int)b->px[3 * i + k]);
            se += (double)d * d;
            if (d > worst)
                worst = d;
        }
        if (worst > m)
            m = worst;
        over += worst > threshold;
    }
    out->mse = n ? se / (3.0 * (double)n) : 0;
    out->psnr = out->mse > 0 ? 10 * log10(255.0 * 255.0 / out->mse) : HUGE_VAL;
    out->over = n ? (double)over / (double)n : 0;
    out->max = m;
}
