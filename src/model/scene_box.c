/* scene_box — the deck-space box of a scene primitive (see scene_box.h). */
#include "model/scene_box.h"
#include <math.h>

/* Coordinate i of the deck-space corner k (bit j: the high end on axis j)
 * of the canonical box l..h scaled by c, under m. */
static double scene_box_corner(const double *m, int i, int k, const double *c, const double *l,
                               const double *h)
{
    double p[3];
    int j;
    for (j = 0; j < 3; j++)
        p[j] = ((k >> j) & 1 ? h[j] : l[j]) * c[j];
    return m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
}

/* Grows the box lo/hi by the deck-space corners of primitive sp's canonical
 * bounding box (bounded kinds only). A coordinate is a rounded sum of three
 * rounded products, one per axis, and grows with each of them: the corner
 * that takes on every axis the end with the smaller product is the least of
 * the eight, the one with the larger products the greatest. Only when one
 * of those is zero, whose sign could differ between corners, are all eight
 * formed in order. */
void scene_prim_grow_box(const scene_prim *sp, double *lo, double *hi)
{
    double c[3], l[3], h[3] = {1, 1, 1};
    int k, i;
    const double *m = sp->world_from_object;
    if (scene_prim_canon_box(sp, c, l))
        return;
    for (i = 0; i < 3; i++) {
        double wl = 0, wh = 0;
        int j;
        for (j = 0; j < 3; j++) {         /* summed as scene_box_corner sums them */
            double a = m[4 * i + j] * (l[j] * c[j]), b = m[4 * i + j] * (h[j] * c[j]);
            wl = j ? wl + (b < a ? b : a) : (b < a ? b : a);
            wh = j ? wh + (b > a ? b : a) : (b > a ? b : a);
        }
        wl += m[4 * i + 3];
        wh += m[4 * i + 3];
        for (k = wl == 0 || wh == 0 ? 0 : 8; k < 8; k++) {
            double w = scene_box_corner(m, i, k, c, l, h);
            if (w < lo[i]) lo[i] = w;
            if (w > hi[i]) hi[i] = w;
        }
        if (wl < lo[i]) lo[i] = wl;
        if (wh > hi[i]) hi[i] = wh;
    }
}

void scene_prim_grow_tight_box(const scene_prim *sp, double *lo, double *hi)
{
    const double *m = sp->world_from_object, *d = sp->shape->dim, k = 1 + 0x1p-40;
    double r0, r1, h;
    int i;
    switch (sp->shape->kind) {
    case PRIM_SPHERE:   r0 = r1 = d[0]; h = 0; break;
    case PRIM_CYLINDER: r0 = r1 = d[0]; h = d[1]; break;
    case PRIM_CONE:     r0 = d[0]; r1 = d[1]; h = d[2]; break;
    default:            scene_prim_grow_box(sp, lo, hi); return;
    }
    for (i = 0; i < 3; i++) {
        const double *a = m + 4 * i;
        /* the disc (or the sphere's ball) about each centre */
        double w = sp->shape->kind == PRIM_SPHERE ? sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
                                           : sqrt(a[0] * a[0] + a[1] * a[1]);
        double c0 = a[3], c1 = a[3] + a[2] * h;
        double l = fmin(c0 - k * r0 * w, c1 - k * r1 * w), u = fmax(c0 + k * r0 * w, c1 + k * r1 * w);
        l -= (fabs(c0) + fabs(c1)) * 0x1p-40;
        u += (fabs(c0) + fabs(c1)) * 0x1p-40;
        if (l < lo[i]) lo[i] = l;
        if (u > hi[i]) hi[i] = u;
    }
}
