/* metrics — MSE, PSNR and the fraction of pixels over a threshold (see metrics.h). */
#include "compare/metrics.h"
#include <math.h>

int metrics_compute(const plane *ref, const plane *test, int nch, const plane *mask, double threshold,
                    metrics *out)
{
    size_t i, n = (size_t)ref[0].w * (size_t)ref[0].h;
    double sum = 0;
    long pixels = 0, over = 0;
    int c;
    for (i = 0; i < n; i++) {
        double worst = 0;
        if (mask && !(mask->v[i] > 0))
            continue;
        for (c = 0; c < nch; c++) {
            double d = (double)ref[c].v[i] - (double)test[c].v[i];
            sum += d * d;
            if (fabs(d) > worst)
                worst = fabs(d);
        }
        pixels++;
        over += worst > threshold;
    }
    if (!pixels)
        return 1;
    out->pixels = pixels;
    out->mse = sum / ((double)pixels * nch);
    out->psnr = out->mse > 0 ? 10.0 * log10(255.0 * 255.0 / out->mse) : HUGE_VAL;
    out->pixels_over = (double)over / (double)pixels;
    return 0;
}
