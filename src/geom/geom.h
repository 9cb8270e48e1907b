/* geom — mode-independent geometry definitions shared by the per-mode
 * geometry code (src/geom), the tracer (src/trace) and their callers:
 * the scene normalisation and the
 * double-precision surface record handed to shading and attribute lookup.
 * Face mappings are documented in docs/primitives.md. */
#ifndef GEOM_H
#define GEOM_H
#include "model/prim_face.h"

/* Normalised world: the bounded part of the scene and the eye are scaled
 * and translated into the cube [-GEOM_W, GEOM_W]^3 (see docs/numerics.md).
 * Hits farther than GEOM_TMAX from a ray origin are ignored; GEOM_TBIG
 * stands for an infinite ray parameter. */
#define GEOM_W     16.0
#define GEOM_TMAX  4096
#define GEOM_TBIG  16384
#define GEOM_LIGHT_MAX 1024.0   /* lights farther from the centre are pulled in */

/* p_normalised = scale * p_deck + off. Distances scale by `scale`. */
typedef struct geom_norm {
    double scale;
    double off[3];
} geom_norm;

/* A point on a primitive's face, in normalised world coordinates:
 * n is the primitive's own outward unit normal (not yet oriented for a CSG
 * difference), (u,v) in [0,1]^2 the face parameters, dpdu/dpdv the partial
 * derivatives of the position (normalised units per unit of u or v). */
typedef struct geom_surface {
    double p[3], n[3];
    double u, v;
    double dpdu[3], dpdv[3];
} geom_surface;

/* Counters kept per thread and summed by the renderer. */
typedef struct geom_stats {
    unsigned long long prim_tests;    /* ray-primitive intersection tests */
    unsigned long long bound_tests;   /* bounding-sphere tests of CSG nodes */
    unsigned long long pruned;        /* CSG subtrees skipped by their bound */
    unsigned long long arena_full;    /* span storage exhausted (never expected) */
} geom_stats;
#endif
