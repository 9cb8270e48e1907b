/* ssim — the structural similarity index of Wang, Bovik, Sheikh and
 * Simoncelli (IEEE TIP 2004) between two single-channel pictures of the
 * same size (compare passes luminance, 0..255):
 *   SSIM(x,y) = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))
 * with local statistics weighted by an 11x11 circular-symmetric Gaussian
 * window of standard deviation 1.5 (normalised to sum 1), C1 = (K1 L)^2,
 * C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, L = 255. The result is the mean of
 * the SSIM map over every window that lies wholly inside the picture and
 * inside the mask (no padding, no automatic downsampling). */
#ifndef SSIM_H
#define SSIM_H
#include "compare/plane.h"

#define SSIM_K1 0.01
#define SSIM_K2 0.03
#define SSIM_L 255.0
#define SSIM_WINDOW 11
#define SSIM_SIGMA 1.5

/* Mean SSIM of x and y (same size) over windows wholly inside mask (NULL:
 * the whole picture). Returns 0 with *ssim and *windows set; 1 when no
 * window fits; -1 when out of memory. */
int ssim_mean(const plane *x, const plane *y, const plane *mask, double *ssim, long *windows);
#endif
