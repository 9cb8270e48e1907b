/* attr_texture — the colour of a texture image at face parameters (u,v)
 * (Algorithm 1, step 5: the texture attribute). Mode-independent: shading
 * runs in double in every numeric mode. */
#ifndef ATTR_TEXTURE_H
#define ATTR_TEXTURE_H
#include "model/scene.h"

/* Bilinear sample of t at (u,v) in [0,1]^2 (u to the right along the image's
 * rows, v up from its bottom row), tiled repeat[] times and wrapping at the
 * edges so that tiled copies join without a seam; rgb in 0..1. Non-finite
 * (u,v) count as 0. */
void attr_texture_rgb(const scene_texture *t, double u, double v, double rgb[3]);
#endif
