/* trace — Algorithm 1 of the paper for one ray: nearest hit, (u,v) of the
 * face, attribute lookup, shadows, shading, and recursion for mirror
 * reflection and refraction. Modal: compiled per numeric mode. */
#ifndef TRACE_TRACE_H
#define TRACE_TRACE_H
#include "trace/cscene.h"
#include "render/render.h"

/* Per-thread state: span arena and counters. */
typedef struct trace_ctx {
    arena ar;
    geom_stats gs;
    render_stats rs;
    unsigned long rays_left;   /* secondary rays the current pixel may still trace */
    cscene_map_memo map;       /* the canonical map the last hit that needed
                                  (u,v) formed */
} trace_ctx;

/* 0, or -1 when memory runs out. */
int NS(trace_ctx_init)(const cscene *cs, trace_ctx *tc);
void NS(trace_ctx_free)(trace_ctx *tc);

/* Algorithm 1, step 3: the attribute of face `face` of primitive pi at the
 * surface point sf (its u, v): the region's attribute from the face's PDS,
 * else the primitive's own. */
const scene_attr *NS(trace_attribute)(const cscene *cs, trace_ctx *tc, int pi, int face,
                                      const geom_surface *sf);

/* Shades ray r (a primary ray: depth 0, weight 1) into rgb (linear, not
 * clamped); *pid receives the primitive hit (-1 for the background). */
void NS(trace_ray)(const cscene *cs, trace_ctx *tc, const prim_ray *r, int depth,
                   double weight, double rgb[3], int *pid);
#endif
