/* attr_texture — the colour of a texture image at face parameters (u,v)
 * (Algorithm 1, step 5: the texture attribute). Mode-independent: shading
 * runs in double in every numeric mode. */
#ifndef ATTR_TEXTURE_H
#define ATTR_TEXTURE_H
#include "model/pds_def.h"
#include "model/scene.h"

/* Bilinear sample of t at (u,v) in [0,1]^2 (u to the right along the image's
 * rows, v up from its bottom row), tiled repeat[] times and wrapping at the
 * edges so that tiled copies join without a seam; rgb in 0..1. Non-finite
 * (u,v) count as 0. */
void attr_texture_rgb(const scene_texture *t, double u, double v, double rgb[3]);

/* The same for a face whose PDS is map (NULL: none): a LOCAL texture is
 * sampled at the point's position in its region's own frame, so the image
 * fills each region (pds_region.h). */
void attr_texture_rgb_at(const scene_texture *t, const pds_def *map, double u, double v, double rgb[3]);

/* The bilinear, wrapping sample of image im (RGB) behind both, tiled
 * repeat[] times. */
void attr_texture_sample(const image *im, const double repeat[2], double u, double v, double rgb[3]);
#endif
