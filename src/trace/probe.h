/* probe — a mode-independent window on one mode's geometry, in deck units
 * and doubles, for tests, the Fortran oracle comparison and diagnostics.
 * Rays are given in the deck's coordinates; ray parameters come back in deck
 * units along the unit direction. Each mode provides NS(probe_ops). */
#ifndef TRACE_PROBE_H
#define TRACE_PROBE_H
#include "geom/geom.h"

typedef struct probe_hit {
    double t;                 /* deck units along the unit direction */
    int prim, face;
    int entering;             /* the ray enters the solid at the hit */
    double p[3];              /* hit point, deck coordinates */
    double n_solid[3];        /* outward normal of the CSG solid (flipped where a
                                 difference exposes a subtracted solid) */
    geom_surface sf;          /* normalised-world surface record */
} probe_hit;

typedef struct probe_ops {
    const char *name;
    int (*compile)(const scene *sc, void **cs, diag *err);
    void (*free)(void *cs);
    /* Span of primitive pi along o + t d: 1 and t[2], face[2], or 0 (miss). */
    int (*prim_span)(const void *cs, int pi, const double *o, const double *d,
                     double *t, int *face);
    /* Nearest hit of the whole scene: 1 and *h, or 0. */
    int (*hit)(const void *cs, const double *o, const double *d, probe_hit *h);
    /* Hits along d from o, then spawns a ray from that hit point (kept in the
     * mode's numbers) along d2, as shading does; 1 and *h2 for its nearest
     * hit, 0 when it hits nothing, -1 when the first ray missed. */
    int (*respawn)(const void *cs, const double *o, const double *d, const double *d2,
                   probe_hit *h1, probe_hit *h2);
    /* As respawn, but the ray spawned along d2 asks what a shadow ray asks
     * (csg_occluded): whether anything lies within tmax deck units of the
     * hit. 1 or 0; -1 when the first ray missed. */
    int (*shadow)(const void *cs, const double *o, const double *d, const double *d2, double tmax);
    /* The mode's refraction (optics.h) of unit d at unit normal n for index
     * ratio eta: 0 and t, 1 for total internal reflection, -1 degenerate. */
    int (*refract)(const double *d, const double *n, double eta, double *t);
    /* Makes every bounding box of the compiled scene infinite, so that only
     * the bounding spheres and the primitives decide what a ray meets: for
     * tests that the boxes (binary64 culling) never change a hit. */
    void (*unbox)(void *cs);
    /* Marks the object hierarchy at least CSG_TODO_LOCAL deep, so that
     * queries keep their pending subtrees in the arena, as they do for
     * hierarchies that deep (csg.c): for tests that both stacks agree.
     * Returns the hierarchy's real depth, or -1 when memory runs out. */
    int (*deepen)(void *cs);
    /* Has every object classified whole (its span list, then its first
     * crossing), without the first-crossing shortcuts of csg_diff_first:
     * the reference for tests of those. */
    void (*whole)(void *cs);
    /* The nearest hit along d from o, then the shadow ray to light li as
     * shading casts it (from the hit point, in the mode's numbers, to the
     * light's distance): 1 when something lies on the way, 0 when not, -1
     * when the first ray missed or there is no such light. */
    int (*light)(const void *cs, const double *o, const double *d, int li);
    /* Has the nearest hits of hit and light's first rays ask the eye's
     * light buffer, and light's shadow rays the light's (cscene_lights),
     * where the compile built them: for tests that the buffers never change
     * an answer. Returns how many buffers were built. */
    int (*buffers)(void *cs);
    /* The number of objects traced through an earlier object's compiled
     * primitives (instances, model/scene_inst.h). */
    int (*instances)(const void *cs);
} probe_ops;

extern const probe_ops q16_probe_ops, q32_probe_ops, f32_probe_ops, f64_probe_ops,
    hfp32_probe_ops, hfp64_probe_ops;
#endif
