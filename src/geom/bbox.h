/* bbox — axis-aligned bounding boxes in binary64, and the ray-box test that
 * decides which CSG nodes and objects a ray can reach.
 *
 * The test only culls: it never yields a ray parameter, a face or a hit, so
 * it runs in binary64 whatever the numeric mode and cannot change a picture
 * as long as it keeps every node the mode's own arithmetic could hit. Boxes
 * are padded outwards by CSG_BOX_PAD (csg.c), which is far above both the
 * binary64 rounding of this test (relative 2^-52 on parameters below 2^15)
 * and the distance a mode's rounded surface point can lie from the exact
 * surface (docs/numerics.md, "Culling in binary64"). A ray's origin and
 * direction are the mode's own values converted to binary64 (exactly for
 * q16, f32 and f64).
 * Mode-independent; included by the modal geometry code. */
#ifndef GEOM_BBOX_H
#define GEOM_BBOX_H

/* A ray as the box test sees it: its origin and the reciprocals of its
 * direction's components. A zero component gets +-BBOX_RCP_ZERO instead
 * of an infinity, so that a box face through the origin gives t = 0, not
 * 0 * inf = NaN, and every other face an out-of-range parameter of the
 * right sign. */
typedef struct bbox_ray {
    double o[3], rcp[3];
} bbox_ray;

#define BBOX_RCP_ZERO 1e300

static inline void bbox_ray_init(bbox_ray *b, const double o[3], const double d[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        b->o[i] = o[i];
        /* tiny components (binary64 can hold them) count as zero: their
         * reciprocals would overflow */
        b->rcp[i] = d[i] > 1e-290 || d[i] < -1e-290 ? 1 / d[i] : d[i] < 0 ? -BBOX_RCP_ZERO : BBOX_RCP_ZERO;
    }
}

/* The entry and exit parameters of one axis's slab, as a range clipped
 * into [*tmin, *tmax]: min and max of its two planes' parameters. */
static inline void bbox_slab(double lo, double hi, double o, double rcp, double *tmin, double *tmax)
{
    double t0 = (lo - o) * rcp, t1 = (hi - o) * rcp;
    double tn = t0 < t1 ? t0 : t1, tf = t0 < t1 ? t1 : t0;
    *tmin = tn > *tmin ? tn : *tmin;
    *tmax = tf < *tmax ? tf : *tmax;
}

/* 1 when the ray misses the box [lo, hi] for every parameter in
 * [tmin, tmax]; else 0 and *tin the parameter in [tmin, tmax] where it
 * enters the box (tmin when it starts inside). Branch-free: the three axes
 * are written out (GCC at -O2 keeps a loop over them). */
static inline int bbox_miss(const double lo[3], const double hi[3], const bbox_ray *r,
                            double tmin, double tmax, double *tin)
{
    bbox_slab(lo[0], hi[0], r->o[0], r->rcp[0], &tmin, &tmax);
    bbox_slab(lo[1], hi[1], r->o[1], r->rcp[1], &tmin, &tmax);
    bbox_slab(lo[2], hi[2], r->o[2], r->rcp[2], &tmin, &tmax);
    *tin = tmin;
    return tmin > tmax;
}
#endif
