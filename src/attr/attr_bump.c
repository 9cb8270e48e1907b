/* attr_bump — bump patterns and perturbed normals (see attr_bump.h). */
#include "attr/attr_bump.h"
#include "attr/attr_texture.h"
#include "model/pds_region.h"
#include "util/dmath.h"
#include <math.h>
#include <stdint.h>

#define ATTR_BUMP_EPS 1e-4                /* (u,v) step of the differences */
#define ATTR_BUMP_DIMPLE_R 0.4            /* dimple radius, fraction of a cell */

/* Integer lattice hash (a 32-bit mix) for the noise gradients: the same on
 * every platform, unlike rand(). */
static uint32_t attr_bump_hash(int32_t i, int32_t j, uint32_t seed)
{
    uint32_t h = (uint32_t)i * 0x8da6b343u ^ (uint32_t)j * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

/* Gradient noise in about [-1, 1] with a unit lattice. */
static double attr_bump_noise1(double x, double y, uint32_t seed)
{
    double fx = floor(x), fy = floor(y), tx = x - fx, ty = y - fy, g[4];
    double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    int32_t ix, iy;
    int k;
    if (!(fabs(fx) < 1e9 && fabs(fy) < 1e9))
        return 0;
    ix = (int32_t)fx;
    iy = (int32_t)fy;
    for (k = 0; k < 4; k++) {
        int dx = k & 1, dy = k >> 1;
        double a = (attr_bump_hash(ix + dx, iy + dy, seed) >> 8) * (2 * DMATH_PI / 16777216.0);
        g[k] = cos(a) * (tx - dx) + sin(a) * (ty - dy);
    }
    return 1.4142135623730951 * ((g[0] + (g[1] - g[0]) * sx) * (1 - sy) + (g[2] + (g[3] - g[2]) * sx) * sy);
}

double attr_bump_height(const scene_bump *b, double u, double v)
{
    double x = b->freq[0] * u, y = b->freq[1] * v, h;
    switch (b->pattern) {
    case BUMP_WAVES:
        return sin(2 * DMATH_PI * (x + y));
    case BUMP_BUMPS:
        return sin(2 * DMATH_PI * x) * sin(2 * DMATH_PI * y);
    case BUMP_DIMPLES: {
        double cx = x - floor(x) - 0.5, cy = y - floor(y) - 0.5;
        double r2 = ATTR_BUMP_DIMPLE_R * ATTR_BUMP_DIMPLE_R - cx * cx - cy * cy;
        return r2 > 0 ? -sqrt(r2) / ATTR_BUMP_DIMPLE_R : 0;
    }
    case BUMP_IMAGE: {
        double rgb[3], one[2] = { 1, 1 };
        if (!b->img.px)
            return 0;
        attr_texture_sample(&b->img, one, x, y, rgb);
        return 2 * (0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]) - 1;
    }
    case BUMP_NOISE:
        /* three octaves, weights 1, 1/2, 1/4 (sum 1.75) */
        h = attr_bump_noise1(x, y, b->seed) + 0.5 * attr_bump_noise1(2 * x, 2 * y, b->seed + 1)
            + 0.25 * attr_bump_noise1(4 * x, 4 * y, b->seed + 2);
        h /= 1.75;
        return h > 1 ? 1 : h < -1 ? -1 : h;
    default:
        return 0;
    }
}

/* Groove profile across distance e from a region boundary: -1 on the
 * boundary rising as a half cosine to 0 at half the width (both sides of a
 * boundary share the width). */
static double attr_bump_groove(double e, double width)
{
    double half = width / 2;
    if (!(e < half))
        return 0;
    return -0.5 * (1 + cos(DMATH_PI * e / half));
}

/* Height at face point (u,v): GROOVES and LOCAL patterns ask the face's PDS
 * where the point lies in its region. */
static double attr_bump_height_at(const scene_bump *b, const pds_def *map, double u, double v)
{
    pds_region r;
    if (b->pattern == BUMP_GROOVES) {
        if (!map)
            return 0;
        pds_region_at(map, u, v, &r);
        return attr_bump_groove(r.edge, b->width);
    }
    if (b->local && map) {
        pds_region_at(map, u, v, &r);
        u = r.frame[0];
        v = r.frame[1];
    }
    return attr_bump_height(b, u, v);
}

void attr_bump_normal(const scene_bump *b, double scale, const geom_surface *sf, double n[3])
{
    attr_bump_normal_at(b, NULL, scale, sf, n);
}

/* P' = P + H n with H = A s h(u,v); to first order (Blinn's approximation,
 * dropping the derivatives of n) P'_u = P_u + H_u n and P'_v = P_v + H_v n,
 * so N' = P_u x P_v + H_u (n x P_v) + H_v (P_u x n), oriented like n. */
void attr_bump_normal_at(const scene_bump *b, const pds_def *map, double scale, const geom_surface *sf, double n[3])
{
    double n0[3], t1[3], t2[3], len0, len, hu, hv, a, c, sgn;
    int i;
    for (i = 0; i < 3; i++)
        n[i] = sf->n[i];
    dmath_cross3(sf->dpdu, sf->dpdv, n0);
    len0 = sqrt(dmath_dot3(n0, n0));
    if (!(len0 > 1e-12) || !isfinite(len0))
        return;
    sgn = dmath_dot3(n0, sf->n) < 0 ? -1 : 1;
    a = b->amplitude * scale / (2 * ATTR_BUMP_EPS);
    hu = a * (attr_bump_height_at(b, map, sf->u + ATTR_BUMP_EPS, sf->v) - attr_bump_height_at(b, map, sf->u - ATTR_BUMP_EPS, sf->v));
    hv = a * (attr_bump_height_at(b, map, sf->u, sf->v + ATTR_BUMP_EPS) - attr_bump_height_at(b, map, sf->u, sf->v - ATTR_BUMP_EPS));
    dmath_cross3(sf->n, sf->dpdv, t1);
    dmath_cross3(sf->dpdu, sf->n, t2);
    for (i = 0; i < 3; i++)
        n0[i] = sgn * (n0[i] + hu * t1[i] + hv * t2[i]);
    len = sqrt(dmath_dot3(n0, n0));
    if (!(len > 0) || !isfinite(len))
        return;
    for (i = 0; i < 3; i++)
        n0[i] /= len;
    /* Keep the normal on the outside: a too-steep one is turned, within the
     * plane of n and itself, to the steepest allowed angle. */
    c = dmath_dot3(n0, sf->n);
    if (c < ATTR_BUMP_MIN_COS) {
        double t[3], tl, s = sqrt(1 - ATTR_BUMP_MIN_COS * ATTR_BUMP_MIN_COS);
        for (i = 0; i < 3; i++)
            t[i] = n0[i] - c * sf->n[i];
        tl = sqrt(dmath_dot3(t, t));
        if (!(tl > 1e-12))
            return;
        for (i = 0; i < 3; i++)
            n0[i] = ATTR_BUMP_MIN_COS * sf->n[i] + s * t[i] / tl;
    }
    for (i = 0; i < 3; i++)
        n[i] = n0[i];
}
