/* render_ops — this numeric mode's entry points for the render driver
 * (render.h): compile, per-thread contexts, and one tile of primary rays. */
#include "trace/trace.h"
#include "util/dmath.h"
#include "util/mem.h"
#include <math.h>
#include <string.h>

static int render_ops_compile(const scene *sc, void **cs, diag *err)
{
    cscene *c;
    int st = NS(cscene_compile)(sc, &c, err);
    if (!st)
        *cs = c;
    return st;
}

static void render_ops_free(void *cs) { NS(cscene_free)(cs); }

static int render_ops_thread_new(const void *cs, void **tc)
{
    trace_ctx *t = mem_alloc(sizeof *t);
    if (!t)
        return -1;
    if (NS(trace_ctx_init)(cs, t)) {
        mem_free(t);
        return -1;
    }
    *tc = t;
    return 0;
}

static void render_ops_thread_free(void *tc)
{
    NS(trace_ctx_free)(tc);
    mem_free(tc);
}

static unsigned char render_ops_byte(double c)
{
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 255;
    return (unsigned char)(c * 255 + 0.5);
}

/* The identity of primary ray r's hit (started t0 from the eye): its
 * primitive, face, region and distance in deck units. */
static void render_ops_ids(const cscene *cs, trace_ctx *tc, const prim_ray *r, double t0, idmap_px *out)
{
    csg_hit h;
    geom_surface sf;
    if (!NS(csg_intersect)(&cs->tree, cs->prims, r, num_from_i(GEOM_TMAX), &tc->ar, &tc->gs, &h))
        return;
    NS(prim_surface)(&cs->prims[h.prim], h.face, vec3_madd(r->o, h.t, r->d), 1, &sf);
    out->prim = h.prim;
    out->face = h.face;
    out->region = (int32_t)(NS(trace_attribute)(cs, tc, h.prim, h.face, &sf) - cs->sc->attrs);
    out->t = (t0 + num_to_d(h.t)) / cs->nm.scale;
}

static int render_ops_region(const void *vcs, void *vtc, int prim, int face, double u, double v)
{
    const cscene *cs = vcs;
    geom_surface sf;
    memset(&sf, 0, sizeof sf);
    sf.u = u;
    sf.v = v;
    if (prim < 0 || (size_t)prim >= cs->nprims)
        return -1;
    return (int)(NS(trace_attribute)(cs, vtc, prim, face, &sf) - cs->sc->attrs);
}

/* One sample: the primary ray along dd (not normalised), its colour added
 * to sum; *p gets the primitive it sees (-1: none), *r and *t0 its last
 * ray and start. */
static void render_ops_sample(const cscene *cs, trace_ctx *tc, const double *dd, double *sum, int *p,
                              prim_ray *r, double *t0)
{
    double u[3], rgb[3], after = 0;
    size_t tries;
    int k, st1;
    *p = -1;
    if (dmath_unit3(dd, u))
        return;
    tc->rs.rays_primary++;
    for (k = 0; k < 3; k++)
        rgb[k] = cs->sc->background[k];
    /* started where a surface can first lie; when nothing is hit in range,
     * again from the next half-space plane */
    for (tries = 0; tries <= cs->nplanes && *p < 0; tries++) {
        if ((st1 = NS(cscene_primary)(cs, u, after, r, t0)) <= 0) {
            tc->rs.range_cut += st1 < 0;
            break;
        }
        NS(trace_ray)(cs, tc, r, 0, 1.0, rgb, p);
        after = *t0 + GEOM_TMAX - 2;
    }
    for (k = 0; k < 3; k++)
        sum[k] += rgb[k];
}

/* Pixel centres at (x + (i+1/2)/aa, y + (j+1/2)/aa); the PID is the one seen
 * by the sample nearest the pixel centre. Directions are set up in double,
 * the ray's start too (cscene_primary), and the direction is normalised in
 * num. A direction fwd + sx right + sy up is summed left to right, so its
 * column part fwd + sx right is formed once per sample column of a strip of
 * at most RENDER_TILE pixels and sy once per sample row. */
static void render_ops_tile(const void *vcs, void *vtc, const render_opts *o,
                            int x0, int y0, int x1, int y1, render_fb *fb, render_stats *st)
{
    const cscene *cs = vcs;
    trace_ctx *tc = vtc;
    double aspect = (double)o->width / o->height;
    double rss = 1.0 / (o->aa * o->aa);
    double col[RENDER_TILE * RENDER_MAX_AA][3], sy[RENDER_MAX_AA], up[3];
    int xs, xe, x, y, i, j, k, aa = o->aa, mid = aa / 2;
    tc->rs = (render_stats){0};
    tc->gs = (geom_stats){0};
    memcpy(up, cs->up, sizeof up);
    for (xs = x0; xs < x1; xs = xe) {
        xe = x1 - xs > RENDER_TILE ? xs + RENDER_TILE : x1;
        for (x = xs; x < xe; x++)
            for (i = 0; i < aa; i++) {
                double sx = (2 * (x + (i + 0.5) / aa) / o->width - 1) * cs->tan_half * aspect;
                double *c = col[(x - xs) * aa + i];
                for (k = 0; k < 3; k++)
                    c[k] = cs->fwd[k] + sx * cs->right[k];
            }
        for (y = y0; y < y1; y++) {
            for (j = 0; j < aa; j++)
                sy[j] = (1 - 2 * (y + (j + 0.5) / aa) / o->height) * cs->tan_half;
            for (x = xs; x < xe; x++) {
                size_t at = (size_t)y * (size_t)o->width + (size_t)x;
                double sum[3] = {0, 0, 0};
                int pid = -1;
                unsigned char *px = fb->img.px + 3 * at;
                tc->rays_left = (unsigned long)RENDER_MAX_RAYS_PER_SAMPLE * (unsigned long)(aa * aa);
                /* samples (i, j) in one loop: a nest of two costs the
                 * pixel a second loop set-up */
                for (i = j = 0; j < aa;) {
                    const double *c = col[(x - xs) * aa + i];
                    double dd[3], t0 = 0;
                    prim_ray r;
                    int p;
                    for (k = 0; k < 3; k++)
                        dd[k] = c[k] + sy[j] * up[k];
                    render_ops_sample(cs, tc, dd, sum, &p, &r, &t0);
                    if (i == mid && j == mid) {
                        pid = p;
                        if (fb->ids.px && p >= 0)
                            render_ops_ids(cs, tc, &r, t0, &fb->ids.px[at]);
                    }
                    if (++i == aa) {
                        i = 0;
                        j++;
                    }
                }
                for (k = 0; k < 3; k++)
                    px[k] = render_ops_byte(sum[k] * rss);
                if (fb->pid)
                    fb->pid[at] = pid;
            }
        }
    }
    st->rays_primary += tc->rs.rays_primary;
    st->rays_shadow += tc->rs.rays_shadow;
    st->rays_reflected += tc->rs.rays_reflected;
    st->rays_refracted += tc->rs.rays_refracted;
    st->pds_lookups += tc->rs.pds_lookups;
    st->uv_skipped += tc->rs.uv_skipped;
    st->shadow_skipped += tc->rs.shadow_skipped;
    st->prim_tests += tc->gs.prim_tests;
    st->bound_tests += tc->gs.bound_tests;
    st->csg_pruned += tc->gs.pruned;
    st->arena_full += tc->gs.arena_full;
    st->range_cut += tc->rs.range_cut;
    st->rays_capped += tc->rs.rays_capped;
}

const render_ops NS(render_ops) = {
    .name = NUM_NAME,
    .compile = render_ops_compile,
    .free = render_ops_free,
    .thread_new = render_ops_thread_new,
    .thread_free = render_ops_thread_free,
    .render_tile = render_ops_tile,
    .region = render_ops_region,
};
