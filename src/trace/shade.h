/* shade — the shading models an optical attribute selects (Algorithm 1,
 * step 5 (3); MODEL in ATTR, docs/scene-format.md). Colours and directions
 * are double in every mode; modal only because src/trace is compiled per
 * mode (symbols <mode>_shade_*).
 *   LAMBERT      ambient + diffuse
 *   PHONG        + ks (R.V)^n, R the light reflected about the normal (default)
 *   BLINN        + ks (N.H)^n, H the half vector of light and view
 *   MIRROR       a perfect mirror tinted by the colour: no local term, the
 *                reflected ray weighted by MIRROR (1 when not given)
 *   TRANSPARENT  Phong highlight, then reflection and refraction weighted by
 *                the dielectric Fresnel reflectance F of IOR: kr + kt F and
 *                kt (1 - F) (TRANSMIT 1 when not given) */
#ifndef TRACE_SHADE_H
#define TRACE_SHADE_H
#include <stddef.h>
#include "model/scene.h"
#include "trace/cscene.h"

/* x^n by repeated squaring when n is a whole number up to 2^20, pow()
 * otherwise. */
double NS(shade_pow)(double x, double n);

/* Unpolarised Fresnel reflectance of a dielectric for cos_i (the cosine
 * between the incident ray and the normal, 0..1) and eta = n_from / n_to;
 * 1 beyond the critical angle. */
double NS(shade_fresnel)(double cos_i, double eta);

/* The local term: ambient, then diffuse and specular per light that
 * reaches the point (pass[l] > 0, unit direction ldir[l]). ns is the
 * shading normal facing the viewer, d the unit ray direction, color the
 * surface colour (texture or attribute); the result goes to c. */
void NS(shade_local)(const cscene *cs, const scene_attr *at, const double color[3], const double ns[3],
                     const double d[3], const double (*ldir)[3], const double *pass, double c[3]);

/* Whether shade_weights can give a recursive ray a positive weight: the
 * attribute reflects (MIRROR) or transmits (TRANSMIT). */
static inline int shade_spawns(const scene_attr *at) { return at->mirror > 0 || at->transmit > 0; }

/* Weights of the recursive rays: *refl for the mirror ray (tint[] its
 * colour filter), *trans for the refracted one; cos_i and eta as above. */
void NS(shade_weights)(const scene_attr *at, const double color[3], double cos_i, double eta, double *refl,
                       double *trans, double tint[3]);
#endif
