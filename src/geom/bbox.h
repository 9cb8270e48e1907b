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
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* A ray as the box test sees it: its origin and the reciprocals of its
 * direction's components. A zero component gets +-BBOX_RCP_ZERO instead
 * of an infinity, so that a box face through the origin gives t = 0, not
 * 0 * inf = NaN, and every other face an out-of-range parameter of the
 * right sign. */
typedef struct bbox_ray {
    double o[3], rcp[3];
} bbox_ray;

#define BBOX_RCP_ZERO 1e300

/* The reciprocal of direction component d. Tiny components (binary64 can
 * hold them) count as zero: their reciprocals would overflow. */
static inline double bbox_rcp(double d)
{
    return d > 1e-290 || d < -1e-290 ? 1 / d : d < 0 ? -BBOX_RCP_ZERO : BBOX_RCP_ZERO;
}

static inline void bbox_ray_init(bbox_ray *b, const double o[3], const double d[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        b->o[i] = o[i];
        b->rcp[i] = bbox_rcp(d[i]);
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

#if defined(__SSE2__)
/* bbox_miss on a box in registers: x and y in the two lanes of xy, z in
 * the low lane of z (its high lane a copy of x, which changes nothing). */
static inline int bbox_miss_sse(__m128d lxy, __m128d hxy, __m128d lz, __m128d hz, const bbox_ray *r,
                                double tmin, double tmax, double *tin)
{
    __m128d o = _mm_loadu_pd(r->o), rc = _mm_loadu_pd(r->rcp);
    __m128d oz = _mm_set_pd(r->o[0], r->o[2]), rz = _mm_set_pd(r->rcp[0], r->rcp[2]);
    __m128d u = _mm_mul_pd(_mm_sub_pd(lxy, o), rc);
    __m128d v = _mm_mul_pd(_mm_sub_pd(hxy, o), rc);
    __m128d uz = _mm_mul_pd(_mm_sub_pd(lz, oz), rz);
    __m128d vz = _mm_mul_pd(_mm_sub_pd(hz, oz), rz);
    __m128d n = _mm_max_pd(_mm_min_pd(u, v), _mm_min_pd(uz, vz));
    __m128d f = _mm_min_pd(_mm_max_pd(u, v), _mm_max_pd(uz, vz));
    /* tmin and tmax in both lanes (only the low one counts): _mm_set_sd
     * from a register is a zeroing VMOVQ between registers, which
     * valgrind 3.19 does not decode */
    n = _mm_max_sd(_mm_max_sd(n, _mm_unpackhi_pd(n, n)), _mm_set1_pd(tmin));
    f = _mm_min_sd(_mm_min_sd(f, _mm_unpackhi_pd(f, f)), _mm_set1_pd(tmax));
    *tin = _mm_cvtsd_f64(n);
    return _mm_comigt_sd(n, f);
}

/* The x and y of a box corner in binary32, widened (exactly) to binary64. */
static inline __m128d bbox_xy_f(const float *c)
{
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)(const void *)c)));
}
#endif

/* 1 when the ray misses the box [lo, hi] for every parameter in
 * [tmin, tmax]; else 0 and *tin the parameter in [tmin, tmax] where it
 * enters the box (tmin when it starts inside). Branch-free: the three axes
 * are written out (GCC at -O2 keeps a loop over them). */
static inline int bbox_miss(const double lo[3], const double hi[3], const bbox_ray *r,
                            double tmin, double tmax, double *tin)
{
#if defined(__SSE2__)
    return bbox_miss_sse(_mm_loadu_pd(lo), _mm_loadu_pd(hi), _mm_set_pd(lo[0], lo[2]), _mm_set_pd(hi[0], hi[2]), r,
                         tmin, tmax, tin);
#else
    bbox_slab(lo[0], hi[0], r->o[0], r->rcp[0], &tmin, &tmax);
    bbox_slab(lo[1], hi[1], r->o[1], r->rcp[1], &tmin, &tmax);
    bbox_slab(lo[2], hi[2], r->o[2], r->rcp[2], &tmin, &tmax);
    *tin = tmin;
    return tmin > tmax;
#endif
}

/* bbox_miss for a box held in binary32 (a CSG node's), the same test on
 * its exact binary64 values. */
static inline int bbox_miss_f(const float lo[3], const float hi[3], const bbox_ray *r,
                              double tmin, double tmax, double *tin)
{
#if defined(__SSE2__)
    return bbox_miss_sse(bbox_xy_f(lo), bbox_xy_f(hi), _mm_set_pd(lo[0], lo[2]), _mm_set_pd(hi[0], hi[2]), r, tmin,
                         tmax, tin);
#else
    double l[3], h[3];
    int i;
    for (i = 0; i < 3; i++) {
        l[i] = lo[i];
        h[i] = hi[i];
    }
    return bbox_miss(l, h, r, tmin, tmax, tin);
#endif
}

/* A ray prepared for bbox_miss2, once per walk of the object hierarchy:
 * each axis's origin and reciprocal in both lanes of a register where SSE2
 * is there, held in a local the compiler can keep in registers. */
typedef struct bbox_ray2 {
#if defined(__SSE2__)
    __m128d o[3], rc[3];
#else
    double o[3], rcp[3];
#endif
} bbox_ray2;

static inline void bbox_ray2_init(bbox_ray2 *p, const bbox_ray *r)
{
    int a;
    for (a = 0; a < 3; a++) {
#if defined(__SSE2__)
        p->o[a] = _mm_set1_pd(r->o[a]);
        p->rc[a] = _mm_set1_pd(r->rcp[a]);
#else
        p->o[a] = r->o[a];
        p->rcp[a] = r->rcp[a];
#endif
    }
}

/* The test of bbox_miss for two boxes side by side (lo[axis][box]) from
 * parameter 0 to tmax: bit j of the result set when the ray misses box j,
 * else tin[j] its entry parameter. One node of the object hierarchy
 * (util/bvh.h) holds its two children's boxes so, and where SSE2 is there
 * (every x86-64) the two boxes are tested in the two lanes of one register
 * (GCC 12 at -O2 neither pairs the scalar lanes nor avoids branches in
 * their minima). No lane can hold a NaN: the reciprocals are finite and
 * not zero, the differences finite or infinite. */
static inline int bbox_miss2(const double lo[3][2], const double hi[3][2], const bbox_ray2 *r,
                             double tmax, double tin[2])
{
#if defined(__SSE2__)
    __m128d t0 = _mm_setzero_pd(), t1 = _mm_set1_pd(tmax);
    int a;
    for (a = 0; a < 3; a++) {
        __m128d u = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(lo[a]), r->o[a]), r->rc[a]);
        __m128d v = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(hi[a]), r->o[a]), r->rc[a]);
        t0 = _mm_max_pd(t0, _mm_min_pd(u, v));
        t1 = _mm_min_pd(t1, _mm_max_pd(u, v));
    }
    _mm_storeu_pd(tin, t0);
    return _mm_movemask_pd(_mm_cmpgt_pd(t0, t1));
#else
    double t0[2] = {0, 0}, t1[2];
    int a, j;
    t1[0] = t1[1] = tmax;
    for (a = 0; a < 3; a++)
        for (j = 0; j < 2; j++) {
            double u = (lo[a][j] - r->o[a]) * r->rcp[a], v = (hi[a][j] - r->o[a]) * r->rcp[a];
            double tn = u < v ? u : v, tf = u < v ? v : u;
            t0[j] = tn > t0[j] ? tn : t0[j];
            t1[j] = tf < t1[j] ? tf : t1[j];
        }
    tin[0] = t0[0];
    tin[1] = t0[1];
    return (t0[0] > t1[0]) | (t0[1] > t1[1]) << 1;
#endif
}
#endif
