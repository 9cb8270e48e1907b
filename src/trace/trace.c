/* trace — Algorithm 1 (see trace.h), its steps in the paper's order.
 * Geometry (hits, spawned rays, the PDS lookup) runs in the mode's `num`;
 * colours, (u,v) and shading normals are doubles (the mode changes where
 * surfaces and regions are, not how light is summed). */
#include "trace/trace.h"
#include "util/dmath.h"
#include "attr/attr_bump.h"
#include "attr/attr_texture.h"
#include "trace/optics.h"
#include "trace/shade.h"
#include <math.h>
#include <string.h>

/* Rays whose contribution falls below half an 8-bit step are not traced. */
#define TRACE_MIN_WEIGHT (1.0 / 512)

int NS(trace_ctx_init)(const cscene *cs, trace_ctx *tc)
{
    memset(tc, 0, sizeof *tc);
    return arena_init(&tc->ar, NS(csg_arena_bytes)(&cs->tree));
}

void NS(trace_ctx_free)(trace_ctx *tc) { arena_free(&tc->ar); }

/* Algorithm 1, step 3: the attribute of face entry f at the surface point
 * sf. The PDS bound to the face (FACE statement) names the region's
 * attribute; where it has no region (PDS_NONE), or the face has no PDS, the
 * primitive's plain attribute applies. */
static inline const scene_attr *trace_face_attribute(const cscene *cs, trace_ctx *tc,
                                                     const cscene_face *f, const geom_surface *sf)
{
    if (f->map) {
        int32_t id = NS(pds_locate)(f->map, num_from_d(sf->u), num_from_d(sf->v));
        tc->rs.pds_lookups++;
        if (id >= 0 && (size_t)id < cs->sc->nattrs)
            return &cs->sc->attrs[id];
    }
    return f->plain;
}

const scene_attr *NS(trace_attribute)(const cscene *cs, trace_ctx *tc, int pi, int face,
                                         const geom_surface *sf)
{
    return trace_face_attribute(cs, tc, cscene_face_at(cs, pi, face), sf);
}

/* Evaluates the surface of hit h (on face entry f) at p, (u,v) only where
 * needed (counted when not). Without (u,v) the trace reads only the
 * normal: a planar face's is copied from its plane and sf->p is not set. */
static inline void trace_surface(const cscene *cs, trace_ctx *tc, const cscene_face *f, const csg_hit *h, vec3 p,
                          geom_surface *sf)
{
    if (!f->need_uv) {
        tc->rs.uv_skipped++;
        if (f->flat_k >= 0) {
            const csg_inst *in;
            memcpy(sf->n, cscene_prim_of(cs, h->prim, &in)->pl_d[f->flat_k], sizeof sf->n);
            if (in && in->turn)
                NS(cscene_inst_back)(in, sf->n);
            return;
        }
    }
    NS(cscene_surface)(cs, h->prim, h->face, p, f->need_uv, &tc->map, sf);
}

/* Spawns a ray from surface point p of primitive pi (outward normal n_prim,
 * double) along unit direction d: the ray excludes that primitive's surface
 * and knows whether it goes into the primitive. */
static inline void trace_spawn(prim_ray *r, vec3 p, vec3 d, int pi, const double *n_prim)
{
    double pd[3], dd[3];
    vec3_to_d(p, pd);
    vec3_to_d(d, dd);
    prim_ray_set_d(r, p, d, pd, dd, pi, dmath_dot3(n_prim, dd) < 0);
}

/* Step 4: the fraction of the light at distance dist along unit l (ld in
 * double) from p on primitive pi that arrives through a scene with
 * transparent attributes: each transparent surface on the way
 * (transmittance kt of its attribute at the crossing) passes kt of it,
 * without bending the shadow ray; an opaque one stops it. `enter`: l goes
 * into pi (its outward normal and l point apart). */
static double trace_light_through(const cscene *cs, trace_ctx *tc, vec3 p, vec3 l, const double *ld,
                                  num dist, int pi, int enter)
{
    double pass = 1;
    int k;
    for (k = 0; k <= cs->max_depth; k++) {
        prim_ray s;
        csg_hit h;
        geom_surface sf;
        const scene_attr *at;
        const cscene_face *fc;
        double pd[3];
        vec3_to_d(p, pd);
        prim_ray_set_d(&s, p, l, pd, ld, pi, enter);
        tc->rs.rays_shadow++;
        if (!NS(csg_intersect)(&cs->tree, &s, dist, &tc->ar, &tc->gs, &h))
            return pass;
        p = vec3_madd(p, h.t, l);
        dist = num_sub(dist, h.t);
        fc = cscene_face_at(cs, h.prim, h.face);
        trace_surface(cs, tc, fc, &h, p, &sf);
        at = trace_face_attribute(cs, tc, fc, &sf);
        pass *= at->transmit;
        if (pass <= TRACE_MIN_WEIGHT)
            return 0;
        pi = h.prim;
        enter = dmath_dot3(sf.n, ld) < 0;
    }
    return 0;
}

/* Step 4: the fraction of the light that arrives, as trace_light_through;
 * where no attribute transmits, any surface on the way will do (the caller's
 * light test has the dot product that gives `enter`). pd is p in double,
 * formed once for all the lights. */
static double trace_light_passes(const cscene *cs, trace_ctx *tc, vec3 p, const double *pd, vec3 l,
                                 const double *ld, num dist, int pi, int enter, size_t li)
{
    prim_ray s;
    csg_hit h;
    if (cs->transparent)
        return trace_light_through(cs, tc, p, l, ld, dist, pi, enter);
    prim_ray_set_d(&s, p, l, pd, ld, pi, enter);
    tc->rs.rays_shadow++;
    if (cs->lbuf && cs->lbuf[li].start)
        return NS(csg_occluded_to)(&cs->tree, &cs->lbuf[li], &s, dist, &tc->ar, &tc->gs, &h) ? 0 : 1;
    return NS(csg_occluded)(&cs->tree, &s, dist, &tc->ar, &tc->gs, &h) ? 0 : 1;
}

/* Takes one secondary ray from the pixel's cap; 0 (counted) when spent. */
static int trace_budget(trace_ctx *tc)
{
    if (tc->rays_left == 0) {
        tc->rs.rays_capped++;
        return 0;
    }
    tc->rays_left--;
    return 1;
}

/* Step 5 (3), the recursive part: the weights of the mirror and refracted
 * rays of ray r's hit h at p (primitive normal n_prim, shading normal ns
 * facing the viewer), each ray traced from step 1 and added to c. `inside`
 * (r travelled inside the solid and leaves it here) selects the refraction
 * ratio. */
static void trace_secondary(const cscene *cs, trace_ctx *tc, const prim_ray *r, const csg_hit *h, vec3 p,
                            const double *n_prim, const double *ns, const scene_attr *at,
                            const double *color, int depth, double weight, double c[3])
{
    double d[3], refl, trans, tint[3];
    int i, inside = !h->entering;
    vec3 nsn = vec3_from_d(ns);
    vec3_to_d(r->d, d);
    NS(shade_weights)(at, color, -dmath_dot3(d, ns), inside ? at->ior : 1.0 / at->ior, &refl, &trans, tint);
    if (trans > 0 && weight * trans > TRACE_MIN_WEIGHT) {
        vec3 td;
        int tir = at->ior > 0 ? NS(optics_refract)(r->d, nsn, inside ? at->ior : 1.0 / at->ior, &td) : 1;
        if (tir > 0) {
            refl += trans;                   /* total internal reflection */
        } else if (tir == 0 && trace_budget(tc)) {
            prim_ray tr;
            double tc3[3];
            trace_spawn(&tr, p, td, h->prim, n_prim);
            tc->rs.rays_refracted++;
            NS(trace_ray)(cs, tc, &tr, depth + 1, weight * trans, tc3, NULL);
            for (i = 0; i < 3; i++)
                c[i] += trans * tc3[i];
        }
    }
    if (refl > 0 && weight * refl > TRACE_MIN_WEIGHT) {
        vec3 rd;
        prim_ray rr;
        double rc[3];
        if (!NS(optics_reflect)(r->d, nsn, &rd) && trace_budget(tc)) {
            trace_spawn(&rr, p, rd, h->prim, n_prim);
            tc->rs.rays_reflected++;
            NS(trace_ray)(cs, tc, &rr, depth + 1, weight * refl, rc, NULL);
            for (i = 0; i < 3; i++)
                c[i] += refl * tint[i] * rc[i];
        }
    }
}

void NS(trace_ray)(const cscene *cs, trace_ctx *tc, const prim_ray *r, int depth,
                   double weight, double rgb[3], int *pid)
{
    const scene *sc = cs->sc;
    const scene_attr *at;
    const cscene_face *fc;
    geom_surface sf;
    csg_hit h;
    vec3 p;
    double d[3], pd[3], ns[3], dn, c[3], tex[3], pass[SCENE_MAX_LIGHTS];
    const double *color;
    double ldir[SCENE_MAX_LIGHTS][3];        /* unit direction to each light */
    size_t li;
    int i, far, lit;

    /* Step 1: nearest hit and its primitive (PID), else the background. */
    if (!(depth == 0 && cs->eyebuf.start
              ? NS(csg_intersect_from)(&cs->tree, &cs->eyebuf, r, num_from_i(GEOM_TMAX), &tc->ar, &tc->gs, &h)
              : NS(csg_intersect)(&cs->tree, r, num_from_i(GEOM_TMAX), &tc->ar, &tc->gs, &h))) {
        /* copied whole, as the colour is at the end: stored element by
         * element, it was read back by the caller's wider loads, which
         * wait until the stores retire (docs/performance.md, run AE) */
        memcpy(rgb, sc->background, sizeof c);
        if (pid)
            *pid = -1;
        return;
    }
    if (pid)
        *pid = h.prim;
    p = vec3_madd(r->o, h.t, r->d);
    /* Step 2: (x,y,z) -> face parameters (u,v) and the tangent frame. */
    fc = cscene_face_at(cs, h.prim, h.face);
    trace_surface(cs, tc, fc, &h, p, &sf);
    /* Step 3: the region of (u,v) in the face's PDS and its attribute. */
    at = trace_face_attribute(cs, tc, fc, &sf);

    /* The ray meets the surface from the side d points away from. The
     * solid's outward normal may be the primitive's flipped one where a
     * difference exposes a subtracted solid. */
    vec3_to_d(r->d, d);
    dn = dmath_dot3(d, sf.n);
    /* No ray is spawned from beyond GEOM_TMAX (only a half-space reaches
     * there): ray origins then stay inside the range argued in
     * docs/numerics.md, and nothing out there can cast a visible shadow. */
    far = vec3_maxabs(p) > num_from_i(GEOM_TMAX);

    /* Step 4: shadows, per light: the fraction of it that reaches p. Lights
     * behind the (unbumped) surface do not reach it. An attribute with no
     * diffuse and no specular term uses no light: no shadow ray then. */
    lit = at->diffuse > 0 || at->specular > 0;
    if (!lit) {
        tc->rs.shadow_skipped += cs->nlights;
        for (li = 0; li < cs->nlights; li++)
            pass[li] = 0;
    } else {
        vec3_to_d(p, pd);         /* read by the shadow rays (!far) */
    }
    for (li = 0; lit && li < cs->nlights; li++) {
        vec3 l;
        num dist;
        double *ld = ldir[li], ln;
        pass[li] = 0;
        if (vec3_normalize(vec3_sub(cs->lights[li].pos, p), &l, &dist))
            continue;
        vec3_to_d(l, ld);
        ln = dmath_dot3(sf.n, ld);
        if (ln * dn >= 0)
            continue;
        pass[li] = far ? 1 : trace_light_passes(cs, tc, p, pd, l, ld, dist, h.prim, ln < 0, li);
    }

    /* Step 5 (1): the bump attribute perturbs the normal; the shading normal
     * ns faces the viewer. */
    if (at->bump >= 0)
        attr_bump_normal_at(&sc->bumps[at->bump], fc->def, cs->nm.scale, &sf, ns);
    else
        memcpy(ns, sf.n, sizeof ns);
    if (dn > 0)
        for (i = 0; i < 3; i++)
            ns[i] = -ns[i];
    /* Step 5 (2): the texture attribute gives the colour. */
    color = at->color;
    if (at->texture >= 0) {
        attr_texture_rgb_at(&sc->textures[at->texture], fc->def, sf.u, sf.v, tex);
        color = tex;
    }

    /* Step 5 (3): the optical attribute's shading model (shade.c). */
    NS(shade_local)(cs, at, color, ns, d, (const double (*)[3])ldir, pass, c);

    /* ... and recursion from step 1 for transmission and mirror reflection:
     * none from beyond GEOM_TMAX, at the depth limit, or where no ray can
     * have a weight. */
    if (!far && depth < cs->max_depth && shade_spawns(at))
        trace_secondary(cs, tc, r, &h, p, sf.n, ns, at, color, depth, weight, c);
    memcpy(rgb, c, sizeof c);
}
