/* optics — the directions of Algorithm 1's recursive rays (step 5 (3)):
 * mirror reflection and refraction by Snell's law, in the mode's `num` so
 * that spawned rays keep the mode's precision. Modal. */
#ifndef TRACE_OPTICS_H
#define TRACE_OPTICS_H
#include "geom/vec.h"

/* The mirror direction of unit d about unit normal n: d - 2 (d.n) n,
 * normalised; 0 and *r, or -1 if it degenerates. */
int NS(optics_reflect)(vec3 d, vec3 n, vec3 *r);

/* The refracted direction of unit d through a surface with unit normal n
 * facing d's origin (d.n < 0), for the ratio eta = n_from / n_to of the
 * refractive indices: t = eta d + (eta cos_i - sqrt k) n with
 * k = 1 - eta^2 (1 - cos_i^2). 0 and *t; 1 for total internal reflection
 * (k < 0); -1 if it degenerates. */
int NS(optics_refract)(vec3 d, vec3 n, double eta, vec3 *t);
#endif
