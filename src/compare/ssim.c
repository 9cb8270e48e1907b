/* ssim — mean structural similarity with a Gaussian window (see ssim.h). */
#include "compare/ssim.h"
#include "util/mem.h"
#include <math.h>
#include <stdint.h>

#define SSIM_R (SSIM_WINDOW / 2)

/* Horizontal Gaussian filtering of row j: for each window start i, the
 * weighted sums of x, y, x^2, y^2 and xy go to out[5i .. 5i+4]. */
static void ssim_row(const plane *x, const plane *y, int j, const double *k, double *out)
{
    int i, t, ow = x->w - SSIM_WINDOW + 1;
    for (i = 0; i < ow; i++) {
        double *r = out + (size_t)i * 5;
        r[0] = r[1] = r[2] = r[3] = r[4] = 0;
        for (t = 0; t < SSIM_WINDOW; t++) {
            double a = PLANE_AT(x, i + t, j), b = PLANE_AT(y, i + t, j);
            r[0] += k[t] * a;
            r[1] += k[t] * b;
            r[2] += k[t] * a * a;
            r[3] += k[t] * b * b;
            r[4] += k[t] * a * b;
        }
    }
}

int ssim_mean(const plane *x, const plane *y, const plane *mask, double *ssim, long *windows)
{
    double k[SSIM_WINDOW], ksum = 0, c1 = (SSIM_K1 * SSIM_L) * (SSIM_K1 * SSIM_L),
           c2 = (SSIM_K2 * SSIM_L) * (SSIM_K2 * SSIM_L), total = 0;
    int w = x->w, h = x->h, ow = x->w - SSIM_WINDOW + 1, i, j, t, q;
    long count = 0;
    double *rows;       /* ring of 11 rows of 5 horizontally filtered quantities */
    uint32_t *bad = NULL; /* summed-area table of pixels outside the mask */
    if (ow < 1 || h < SSIM_WINDOW)
        return 1;
    for (t = 0; t < SSIM_WINDOW; t++) {
        k[t] = exp(-0.5 * (t - SSIM_R) * (t - SSIM_R) / (SSIM_SIGMA * SSIM_SIGMA));
        ksum += k[t];
    }
    for (t = 0; t < SSIM_WINDOW; t++)
        k[t] /= ksum;
    rows = mem_calloc((size_t)ow * SSIM_WINDOW * 5, sizeof *rows);
    if (!rows)
        return -1;
    if (mask) {
        bad = mem_calloc((size_t)(w + 1) * (size_t)(h + 1), sizeof *bad);
        if (!bad) {
            mem_free(rows);
            return -1;
        }
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++)
                bad[(size_t)(j + 1) * (w + 1) + i + 1] = (PLANE_AT(mask, i, j) > 0 ? 0 : 1) +
                    bad[(size_t)j * (w + 1) + i + 1] + bad[(size_t)(j + 1) * (w + 1) + i] -
                    bad[(size_t)j * (w + 1) + i];
    }
    for (j = 0; j < SSIM_WINDOW - 1; j++)
        ssim_row(x, y, j, k, rows + (size_t)j * ow * 5);
    for (j = 0; j + SSIM_WINDOW <= h; j++) {
        /* the ring holds the filtered rows j .. j+10 */
        ssim_row(x, y, j + SSIM_WINDOW - 1, k, rows + (size_t)((j + SSIM_WINDOW - 1) % SSIM_WINDOW) * ow * 5);
        for (i = 0; i < ow; i++) {
            double m[5] = {0, 0, 0, 0, 0}, vx, vy, cxy;
            if (bad) {
                size_t W = (size_t)w + 1;
                uint32_t nb = bad[(size_t)(j + SSIM_WINDOW) * W + i + SSIM_WINDOW] - bad[(size_t)j * W + i + SSIM_WINDOW] -
                          bad[(size_t)(j + SSIM_WINDOW) * W + i] + bad[(size_t)j * W + i];
                if (nb)
                    continue;
            }
            for (t = 0; t < SSIM_WINDOW; t++) {
                const double *r = rows + ((size_t)((j + t) % SSIM_WINDOW) * ow + i) * 5;
                for (q = 0; q < 5; q++)
                    m[q] += k[t] * r[q];
            }
            vx = m[2] - m[0] * m[0];
            vy = m[3] - m[1] * m[1];
            cxy = m[4] - m[0] * m[1];
            total += (2 * m[0] * m[1] + c1) * (2 * cxy + c2) / ((m[0] * m[0] + m[1] * m[1] + c1) * (vx + vy + c2));
            count++;
        }
    }
    mem_free(rows);
    mem_free(bad);
    if (!count)
        return 1;
    *ssim = total / count;
    *windows = count;
    return 0;
}
