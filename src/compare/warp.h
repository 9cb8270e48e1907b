/* warp — the similarity transform that maps TEST pixel coordinates onto
 * REFERENCE pixel coordinates, and resampling of the test picture into the
 * reference frame. The registration (align) finds the transform; the metrics
 * and the pictures then work on the resampled test.
 *
 * Convention (pixel coordinates as in plane.h, origin at the top-left corner
 * of each picture, x right, y down):
 *   xr = scale * ( cos(a) * xt + sin(a) * yt) + dx
 *   yr = scale * (-sin(a) * xt + cos(a) * yt) + dy
 * scale is reference pixels per test pixel, (dx,dy) is where the test's
 * top-left corner lands in reference pixels, and a positive angle a (degrees)
 * turns the test counter-clockwise as seen on screen. */
#ifndef WARP_H
#define WARP_H
#include "compare/plane.h"

typedef struct warp_params {
    double scale, dx, dy, angle;   /* angle in degrees */
} warp_params;

/* Test (xt,yt) -> reference (*xr,*yr). */
void warp_to_ref(const warp_params *p, double xt, double yt, double *xr, double *yr);
/* Reference (xr,yr) -> test (*xt,*yt); the inverse of warp_to_ref. */
void warp_to_test(const warp_params *p, double xr, double yr, double *xt, double *yt);

/* Resamples the test channels src[0..n-1] (all tw x th) into n new planes of
 * the reference size rw x rh, with bilinear interpolation at each reference
 * pixel centre; when the test is shrunk (scale < 1) it is first low-passed
 * with a Gaussian of sigma 0.5*sqrt(1/scale^2 - 1) test pixels against
 * aliasing (halftone dots, thin lines). *mask gets 1 where the reference
 * pixel centre falls inside the test picture, else 0 (and the channels 0).
 * Returns 0 or -1 (out of memory; nothing allocated then). */
int warp_resample(const warp_params *p, const plane *src, int n, int rw, int rh,
                  plane *dst, plane *mask);
#endif
