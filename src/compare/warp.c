/* warp — similarity transform and resampling into the reference frame (see warp.h). */
#include "compare/warp.h"
#include "util/dmath.h"
#include <math.h>


void warp_to_ref(const warp_params *p, double xt, double yt, double *xr, double *yr)
{
    double a = dmath_rad(p->angle), c = cos(a), s = sin(a);
    *xr = p->scale * (c * xt + s * yt) + p->dx;
    *yr = p->scale * (-s * xt + c * yt) + p->dy;
}

void warp_to_test(const warp_params *p, double xr, double yr, double *xt, double *yt)
{
    double a = dmath_rad(p->angle), c = cos(a), s = sin(a);
    double u = (xr - p->dx) / p->scale, v = (yr - p->dy) / p->scale;
    *xt = c * u - s * v;
    *yt = s * u + c * v;
}

int warp_resample(const warp_params *p, const plane *src, int n, int rw, int rh,
                  plane *dst, plane *mask)
{
    int k, i, j, done = 0;
    plane m;
    double sigma = p->scale < 1 ? 0.5 * sqrt(1.0 / (p->scale * p->scale) - 1.0) : 0;
    if (plane_alloc(&m, rw, rh))
        return -1;
    for (k = 0; k < n; k++) {
        plane tmp;
        if (plane_copy(&src[k], &tmp))
            goto fail;
        if (plane_blur(&tmp, sigma) || plane_alloc(&dst[k], rw, rh)) {
            plane_free(&tmp);
            goto fail;
        }
        done++;
        for (j = 0; j < rh; j++)
            for (i = 0; i < rw; i++) {
                double xt, yt;
                warp_to_test(p, i + 0.5, j + 0.5, &xt, &yt);
                if (xt >= 0 && yt >= 0 && xt < tmp.w && yt < tmp.h) {
                    PLANE_AT(&dst[k], i, j) = plane_sample(&tmp, xt, yt);
                    PLANE_AT(&m, i, j) = 1;
                }
            }
        plane_free(&tmp);
    }
    *mask = m;
    return 0;
fail:
    while (done > 0)
        plane_free(&dst[--done]);
    plane_free(&m);
    return -1;
}
