/* shade — shading models (see shade.h). */
#include "trace/shade.h"
#include <math.h>
#include "util/dmath.h"

double NS(shade_pow)(double x, double n)
{
    double r = 1;
    unsigned long k;
    if (!(n >= 0 && n <= 1048576 && n == floor(n)))
        return pow(x, n);
    for (k = (unsigned long)n; k; k >>= 1) {
        if (k & 1)
            r *= x;
        x *= x;
    }
    return r;
}

double NS(shade_fresnel)(double cos_i, double eta)
{
    double s2 = eta * eta * (1 - cos_i * cos_i), ct, rs, rp;
    if (cos_i > 1)
        cos_i = 1;
    if (s2 >= 1)
        return 1;
    ct = sqrt(1 - s2);
    rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    rp = (cos_i - eta * ct) / (cos_i + eta * ct);
    return 0.5 * (rs * rs + rp * rp);
}

void NS(shade_local)(const cscene *cs, const scene_attr *at, const double color[3], const double ns[3],
                     const double d[3], const double (*ldir)[3], const double *pass, double c[3])
{
    const scene *sc = cs->sc;
    double acc[3];        /* summed here, not in c: c may alias the inputs,
                             so each sum into c would reload them */
    size_t li;
    int i;
    if (at->model == SHADE_MIRROR) {
        c[0] = c[1] = c[2] = 0;
        return;
    }
    for (i = 0; i < 3; i++)
        acc[i] = at->ambient * color[i] * sc->ambient[i];
    for (li = 0; li < cs->nlights; li++) {
        const double *ld = ldir[li];
        double ndl, spec = 0, x = 0;
        if (pass[li] <= 0)
            continue;
        ndl = dmath_dot3(ns, ld);
        if (ndl <= 0)
            continue;
        if (at->specular > 0 && at->model == SHADE_BLINN) {
            double h[3], hl;
            for (i = 0; i < 3; i++)
                h[i] = ld[i] - d[i];
            hl = sqrt(dmath_dot3(h, h));
            if (hl > 0)
                x = dmath_dot3(ns, h) / hl;
        } else if (at->specular > 0 && at->model != SHADE_LAMBERT) {
            /* Phong: the light reflected about ns against the view direction */
            double rl[3];
            for (i = 0; i < 3; i++)
                rl[i] = 2 * ndl * ns[i] - ld[i];
            x = -dmath_dot3(rl, d);
        }
        if (x > 0)
            spec = at->specular * NS(shade_pow)(x, at->exponent);
        for (i = 0; i < 3; i++)
            acc[i] += pass[li] * cs->lights[li].rgb[i] * (at->diffuse * ndl * color[i] + spec);
    }
    for (i = 0; i < 3; i++)
        c[i] = acc[i];
}

void NS(shade_weights)(const scene_attr *at, const double color[3], double cos_i, double eta, double *refl,
                       double *trans, double tint[3])
{
    int i;
    *refl = at->mirror;
    *trans = at->transmit;
    for (i = 0; i < 3; i++)
        tint[i] = at->model == SHADE_MIRROR ? color[i] : 1;
    if (at->model == SHADE_TRANSPARENT && at->transmit > 0) {
        double f = NS(shade_fresnel)(cos_i < 0 ? 0 : cos_i, eta);
        *refl = at->mirror + at->transmit * f;
        *trans = at->transmit * (1 - f);
    }
}
