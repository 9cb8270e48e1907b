/* optics — the directions of Algorithm 1's recursive rays (step 5 (3)):
 * mirror reflection and refraction by Snell's law, in the mode's `num` so
 * that spawned rays keep the mode's precision. Modal. */
#ifndef TRACE_OPTICS_H
#define TRACE_OPTICS_H
#include "geom/vec.h"

/* The mirror direction of unit d about unit normal n: d - 2 (d.n) n,
 * normalised; 0 and *r, or -1 if it degenerates. */
VEC_HOT int optics_reflect_dir(vec3 d, vec3 n, vec3 *r)
{
    num two_dn = num_mul(num_from_i(2), vec3_dot(d, n));
    return vec3_unit_near(vec3_sub(d, vec3_scale(n, two_dn)), r) ? -1 : 0;
}
/* The same, inline in q16: out of line it stored the direction's three
 * 32-bit components one by one, and the caller read them back two at a
 * time, a load that waits until both stores retire (docs/performance.md,
 * run AE). In the other modes the call is cheaper than the inline code
 * (f64: 1.5 to 5 % on whole renders). */
#if defined(NUM_MODE_q16)
VEC_HOT int NS(optics_reflect)(vec3 d, vec3 n, vec3 *r) { return optics_reflect_dir(d, n, r); }
#else
int NS(optics_reflect)(vec3 d, vec3 n, vec3 *r);
#endif

/* The refracted direction of unit d through a surface with unit normal n
 * facing d's origin (d.n < 0), for the ratio eta = n_from / n_to of the
 * refractive indices: t = eta d + (eta cos_i - sqrt k) n with
 * k = 1 - eta^2 (1 - cos_i^2). 0 and *t; 1 for total internal reflection
 * (k < 0); -1 if it degenerates. */
int NS(optics_refract)(vec3 d, vec3 n, double eta, vec3 *t);
#endif
