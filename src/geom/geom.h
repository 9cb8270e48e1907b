/* geom — mode-independent geometry definitions shared by the per-mode
 * geometry code (src/geom), the tracer (src/trace) and their callers:
 * face numbering per primitive kind, the scene normalisation, and the
 * double-precision surface record handed to shading and attribute lookup.
 * Face mappings are documented in docs/primitives.md. */
#ifndef GEOM_H
#define GEOM_H
#include "scene/scene.h"

/* Normalised world: the bounded part of the scene and the eye are scaled
 * and translated into the cube [-GEOM_W, GEOM_W]^3 (see docs/numerics.md).
 * Hits farther than GEOM_TMAX from a ray origin are ignored; GEOM_TBIG
 * stands for an infinite ray parameter. */
#define GEOM_W     16.0
#define GEOM_TMAX  4096
#define GEOM_TBIG  16384
#define GEOM_LIGHT_MAX 1024.0   /* lights farther from the centre are pulled in */

enum { GEOM_FACE_NONE = -1 };
enum { GEOM_FACE_SPHERE_SURFACE = 0 };
enum { GEOM_FACE_CYL_SIDE = 0, GEOM_FACE_CYL_TOP = 1, GEOM_FACE_CYL_BOTTOM = 2 };
enum { GEOM_FACE_CONE_SIDE = 0, GEOM_FACE_CONE_TOP = 1, GEOM_FACE_CONE_BOTTOM = 2 };
enum { GEOM_FACE_BLOCK_XMIN = 0, GEOM_FACE_BLOCK_XMAX, GEOM_FACE_BLOCK_YMIN, GEOM_FACE_BLOCK_YMAX,
       GEOM_FACE_BLOCK_ZMIN, GEOM_FACE_BLOCK_ZMAX };
enum { GEOM_FACE_HALFSPACE_PLANE = 0 };

/* Number of faces of a primitive kind, and a face's name ("SIDE", "XMIN",
 * ...; NULL when out of range). */
static inline int geom_face_count(int kind)
{
    static const int n[PRIM_KIND_COUNT] = {1, 3, 6, 3, 1};
    return kind >= 0 && kind < PRIM_KIND_COUNT ? n[kind] : 0;
}
static inline const char *geom_face_name(int kind, int face)
{
    static const char *const names[PRIM_KIND_COUNT][6] = {
        {"SURFACE"}, {"SIDE", "TOP", "BOTTOM"},
        {"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"},
        {"SIDE", "TOP", "BOTTOM"}, {"PLANE"}};
    if (face < 0 || face >= geom_face_count(kind))
        return NULL;
    return names[kind][face];
}

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
