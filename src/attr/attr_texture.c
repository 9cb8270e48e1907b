/* attr_texture — texture image lookup (see attr_texture.h). */
#include "attr/attr_texture.h"
#include <math.h>
#include "model/pds_region.h"

/* Position x in [0, n) of a wrapped coordinate, split into the lower texel
 * index and the fraction towards the next one. Texel centres sit at
 * (i + 1/2) / n. */
static void attr_texture_axis(double x, int n, int *i0, int *i1, double *f)
{
    double p;
    if (!isfinite(x))
        x = 0;
    p = (x - floor(x)) * n - 0.5;
    *i0 = (int)floor(p);
    *f = p - *i0;
    if (*i0 < 0)
        *i0 += n;
    if (*i0 >= n)
        *i0 -= n;
    *i1 = *i0 + 1 < n ? *i0 + 1 : 0;
}

void attr_texture_sample(const image *im, const double repeat[2], double u, double v, double rgb[3])
{
    int x0, x1, y0, y1, k;
    double fx, fy;
    attr_texture_axis(u * repeat[0], im->width, &x0, &x1, &fx);
    /* v runs up; image rows run down */
    attr_texture_axis(1.0 - v * repeat[1], im->height, &y0, &y1, &fy);
    for (k = 0; k < 3; k++) {
        const uint8_t *px = im->px;
        size_t w = (size_t)im->width;
        double a = px[3 * ((size_t)y0 * w + (size_t)x0) + k], b = px[3 * ((size_t)y0 * w + (size_t)x1) + k];
        double c = px[3 * ((size_t)y1 * w + (size_t)x0) + k], d = px[3 * ((size_t)y1 * w + (size_t)x1) + k];
        rgb[k] = ((a + (b - a) * fx) * (1 - fy) + (c + (d - c) * fx) * fy) / 255.0;
    }
}

void attr_texture_rgb(const scene_texture *t, double u, double v, double rgb[3])
{
    attr_texture_sample(&t->img, t->repeat, u, v, rgb);
}

void attr_texture_rgb_at(const scene_texture *t, const pds_def *map, double u, double v, double rgb[3])
{
    pds_region r;
    if (t->local && map) {
        pds_region_at(map, u, v, &r);
        u = r.frame[0];
        v = r.frame[1];
    }
    attr_texture_sample(&t->img, t->repeat, u, v, rgb);
}
