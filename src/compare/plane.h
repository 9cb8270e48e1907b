/* plane — a single-channel float raster and the filters compare needs:
 * Gaussian blur (plain and masked), 2x pyramid reduction, bilinear sampling,
 * gradient magnitude and conversion from 8-bit images. Values are in 8-bit
 * units (0..255) unless a function says otherwise.
 * Pixel convention shared by all of compare: pixel (i,j) covers the square
 * [i,i+1) x [j,j+1) with x to the right and y down, so its centre is at
 * (i+0.5, j+0.5) and an image of width W spans 0..W. */
#ifndef PLANE_H
#define PLANE_H
#include "image/image.h"

typedef struct plane {
    int w, h;
    float *v;          /* w*h values, rows top to bottom */
} plane;

#define PLANE_AT(p, x, y) ((p)->v[(size_t)(y) * (size_t)(p)->w + (size_t)(x)])

/* Rec. 601 luma weights applied to gamma-encoded 8-bit R'G'B'. */
#define PLANE_LUMA_R 0.299
#define PLANE_LUMA_G 0.587
#define PLANE_LUMA_B 0.114

/* Allocates a zeroed w x h plane (w,h >= 1). 0, or -1 when out of memory. */
int plane_alloc(plane *p, int w, int h);
void plane_free(plane *p);
/* Copies src into a new plane dst. 0 or -1. */
int plane_copy(const plane *src, plane *dst);
/* Extracts channel c (0..channels-1) of img, or its Rec. 601 luma when c < 0
 * (grey images are their own luma), from the rectangle x,y,w,h (inside img). */
int plane_from_image(const image *img, int c, int x, int y, int w, int h, plane *out);
/* Blurs p in place with a separable Gaussian of standard deviation sigma
 * pixels (kernel truncated at 3 sigma, edges clamped). sigma <= 0 is a no-op.
 * 0 or -1. */
int plane_blur(plane *p, double sigma);
/* Blurs p where mask > 0 only, normalising by the blurred mask so values
 * outside the mask do not bleed in; pixels outside the mask are unchanged.
 * mask has p's size. 0 or -1. */
int plane_blur_masked(plane *p, const plane *mask, double sigma);
/* dst = src low-passed with the 6-tap binomial filter [1 5 10 10 5 1]/32 and
 * decimated by 2 (size ceil(w/2) x ceil(h/2)); dst pixel i covers src pixels
 * 2i and 2i+1, so positions scale exactly by 1/2. 0 or -1. */
int plane_reduce(const plane *src, plane *dst);
/* dst = magnitude of the central-difference gradient of src. 0 or -1. */
int plane_gradient(const plane *src, plane *dst);
/* Bilinear sample at continuous position (x,y) in pixel units of p (pixel
 * centres at i+0.5); positions outside are clamped to the border. */
float plane_sample(const plane *p, double x, double y);
#endif
