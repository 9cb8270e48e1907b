/* attr_bump — bump attributes: a height field over a face's (u,v) and the
 * shading normal it implies (Blinn 1978), for Algorithm 1, step 5 (1).
 * Mode-independent: shading runs in double in every numeric mode. */
#ifndef ATTR_BUMP_H
#define ATTR_BUMP_H
#include "geom/geom.h"
#include "model/pds_def.h"
#include "model/scene.h"

/* Height of pattern b at (u,v), in [-1, 1] (before the amplitude). */
double attr_bump_height(const scene_bump *b, double u, double v);

/* The perturbed unit normal of surface point sf when it is displaced along
 * its normal by amplitude * scale * h(u,v) (scale: normalised units per deck
 * unit). Derivatives of h come from central differences in (u,v); the
 * surface's own tangents dpdu, dpdv give the frame, so the bumps follow the
 * face's mapping. The result stays on the outside of the surface (its dot
 * product with sf->n is at least ATTR_BUMP_MIN_COS); where the tangent frame
 * degenerates (a cap's centre, a sphere's pole) sf->n is returned unchanged. */
#define ATTR_BUMP_MIN_COS 0.05
void attr_bump_normal(const scene_bump *b, double scale, const geom_surface *sf, double n[3]);

/* The same on a face whose PDS is map (NULL: none): GROOVES follow the
 * region boundaries of map (flat without one) and LOCAL patterns are laid in
 * each region's own frame (pds_region.h). */
void attr_bump_normal_at(const scene_bump *b, const pds_def *map, double scale, const geom_surface *sf, double n[3]);
#endif
