/* trace — Algorithm 1 (see trace.h). Geometry (hits, spawned rays) runs in
 * the mode's `num`; colours are doubles (the mode changes where surfaces are,
 * not how light is summed). */
#include "trace/trace.h"
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

/* Algorithm 1, steps 2-3: the attribute of face `face` of primitive `pi` at
 * the surface point sf ((u,v) in [0,1]^2, tangent frame dpdu/dpdv, normal).
 * This is the attribute-mapping hook: every face currently yields the
 * primitive's plain attribute; the planar division structure lookup for faces
 * with a binding (scene_prim.face_map[face] >= 0) plugs in here and counts
 * tc->rs.pds_lookups. */
static const scene_attr *trace_attribute(const cscene *cs, trace_ctx *tc, int pi, int face,
                                         const geom_surface *sf)
{
    (void)tc;
    (void)face;
    (void)sf;
    return &cs->sc->attrs[cs->prims[pi].attr];
}

static vec3 trace_vec_d(const double *v) { return vec3_from_d(v); }

/* Spawns a ray from surface point p of primitive pi (outward normal n_prim,
 * double) along unit direction d: the ray excludes that primitive's surface
 * and knows whether it goes into the primitive. */
static void trace_spawn(prim_ray *r, vec3 p, vec3 d, int pi, const double *n_prim)
{
    double dd[3];
    vec3_to_d(d, dd);
    r->o = p;
    r->d = d;
    r->excl_prim = pi;
    r->excl_enter = n_prim[0] * dd[0] + n_prim[1] * dd[1] + n_prim[2] * dd[2] < 0;
}

/* Step 4: 1 when the light at distance dist along unit l from p is blocked. */
static int trace_shadowed(const cscene *cs, trace_ctx *tc, vec3 p, vec3 l, num dist, int pi,
                          const double *n_prim)
{
    prim_ray s;
    csg_hit h;
    trace_spawn(&s, p, l, pi, n_prim);
    tc->rs.rays_shadow++;
    return NS(csg_intersect)(&cs->tree, cs->prims, &s, dist, &tc->ar, &tc->gs, &h);
}

void NS(trace_ray)(const cscene *cs, trace_ctx *tc, const prim_ray *r, int depth,
                   double weight, double rgb[3], int *pid)
{
    const scene *sc = cs->sc;
    const scene_attr *at;
    geom_surface sf;
    csg_hit h;
    vec3 p, nsn;
    double d[3], ns[3], dn, refl, c[3];
    size_t li;
    int i, inside, far;

    /* Step 1: nearest hit, else the background. */
    if (!NS(csg_intersect)(&cs->tree, cs->prims, r, num_from_i(GEOM_TMAX), &tc->ar, &tc->gs, &h)) {
        for (i = 0; i < 3; i++)
            rgb[i] = sc->background[i];
        if (pid)
            *pid = -1;
        return;
    }
    if (pid)
        *pid = h.prim;
    p = vec3_madd(r->o, h.t, r->d);
    /* Step 2: (x,y,z) -> face parameters (u,v) and the tangent frame. */
    NS(prim_surface)(&cs->prims[h.prim], h.face, p, &sf);
    /* Step 3: the attribute of the face at (u,v). */
    at = trace_attribute(cs, tc, h.prim, h.face, &sf);

    /* Shading normal faces the viewer; `inside` says the ray travelled inside
     * the solid (it leaves it here), which selects the refraction ratio. The
     * solid's outward normal may be the primitive's flipped one where a
     * difference exposes a subtracted solid. */
    vec3_to_d(r->d, d);
    dn = d[0] * sf.n[0] + d[1] * sf.n[1] + d[2] * sf.n[2];
    for (i = 0; i < 3; i++)
        ns[i] = dn > 0 ? -sf.n[i] : sf.n[i];
    inside = !h.entering;
    nsn = trace_vec_d(ns);
    /* No ray is spawned from beyond GEOM_TMAX (only a half-space reaches
     * there): ray origins then stay inside the range argued in
     * docs/numerics.md, and nothing out there can cast a visible shadow. */
    far = vec3_maxabs(p) > num_from_i(GEOM_TMAX);
    /* Step 5 (1): a bump attribute would perturb ns here. */

    for (i = 0; i < 3; i++)
        c[i] = at->ambient * at->color[i] * sc->ambient[i];
    /* Step 4: shadows and brightness per light. */
    for (li = 0; li < cs->nlights; li++) {
        vec3 l;
        num dist;
        double ld[3], ndl, spec = 0;
        if (vec3_normalize(vec3_sub(cs->lights[li].pos, p), &l, &dist))
            continue;
        vec3_to_d(l, ld);
        ndl = ns[0] * ld[0] + ns[1] * ld[1] + ns[2] * ld[2];
        if (ndl <= 0)
            continue;
        if (!far && trace_shadowed(cs, tc, p, l, dist, h.prim, sf.n))
            continue;
        if (at->specular > 0) {
            /* Phong: the light reflected about ns against the view direction */
            double rl[3], rv;
            for (i = 0; i < 3; i++)
                rl[i] = 2 * ndl * ns[i] - ld[i];
            rv = -(rl[0] * d[0] + rl[1] * d[1] + rl[2] * d[2]);
            if (rv > 0)
                spec = at->specular * pow(rv, at->exponent);
        }
        for (i = 0; i < 3; i++)
            c[i] += cs->lights[li].rgb[i] * (at->diffuse * ndl * at->color[i] + spec);
    }

    /* Step 5 (3): mirror reflection and transmission recurse from step 1. */
    refl = at->mirror;
    if (far)
        depth = cs->max_depth;
    if (at->transmit > 0 && depth < cs->max_depth && weight * at->transmit > TRACE_MIN_WEIGHT) {
        double eta = inside ? at->ior : 1.0 / at->ior, cosi = -(d[0] * ns[0] + d[1] * ns[1] + d[2] * ns[2]);
        double k = 1 - eta * eta * (1 - cosi * cosi);
        if (k < 0 || !(at->ior > 0)) {
            refl += at->transmit;            /* total internal reflection */
        } else {
            /* t = eta d + (eta cosi - sqrt k) ns, in num */
            num ne = num_from_d(eta), nk = num_sub(num_mul(ne, num_from_d(cosi)), num_sqrt(num_from_d(k)));
            vec3 td;
            prim_ray tr;
            double tc3[3];
            if (!vec3_normalize(vec3_add(vec3_scale(r->d, ne), vec3_scale(nsn, nk)), &td, NULL)) {
                trace_spawn(&tr, p, td, h.prim, sf.n);
                tc->rs.rays_refracted++;
                NS(trace_ray)(cs, tc, &tr, depth + 1, weight * at->transmit, tc3, NULL);
                for (i = 0; i < 3; i++)
                    c[i] += at->transmit * tc3[i];
            }
        }
    }
    if (refl > 0 && depth < cs->max_depth && weight * refl > TRACE_MIN_WEIGHT) {
        /* r = d - 2 (d.ns) ns, in num */
        vec3 rd;
        prim_ray rr;
        double rc[3];
        num two_dn = num_mul(num_from_i(2), vec3_dot(r->d, nsn));
        if (!vec3_normalize(vec3_sub(r->d, vec3_scale(nsn, two_dn)), &rd, NULL)) {
            trace_spawn(&rr, p, rd, h.prim, sf.n);
            tc->rs.rays_reflected++;
            NS(trace_ray)(cs, tc, &rr, depth + 1, weight * refl, rc, NULL);
            for (i = 0; i < 3; i++)
                c[i] += refl * rc[i];
        }
    }
    for (i = 0; i < 3; i++)
        rgb[i] = c[i];
}
