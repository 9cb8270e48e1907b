/* render_ops — this numeric mode's entry points for the render driver
 * (render.h): compile, per-thread contexts, and one tile of primary rays. */
#include "trace/trace.h"
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

static void render_ops_counts(const void *vcs, render_stats *st)
{
    const cscene *cs = vcs;
    st->objects = cs->sc->nroots;
    st->inst_moved = cs->inst_moved;
    st->inst_turned = cs->inst_turned;
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

/* Pixel at gets the mean sum * rss of its samples (sum is cleared for the
 * next) and the PID pid. */
static void render_ops_pixel(render_fb *fb, size_t at, double *sum, double rss, int pid)
{
    unsigned char *px = fb->img.px + 3 * at;
    int k;
    for (k = 0; k < 3; k++) {
        px[k] = render_ops_byte(sum[k] * rss);
        sum[k] = 0;
    }
    if (fb->pid)
        fb->pid[at] = pid;
}

/* The identity of primary ray r's hit (started t0 from the eye): its
 * primitive, face, region and distance in deck units. */
static void render_ops_ids(const cscene *cs, trace_ctx *tc, const prim_ray *r, double t0, idmap_px *out)
{
    csg_hit h;
    geom_surface sf;
    if (!(cs->eyebuf.start ? NS(csg_intersect_from)(&cs->tree, &cs->eyebuf, r, num_from_i(GEOM_TMAX), &tc->ar,
                                                    &tc->gs, &h)
                           : NS(csg_intersect)(&cs->tree, r, num_from_i(GEOM_TMAX), &tc->ar, &tc->gs, &h)))
        return;
    NS(cscene_surface)(cs, h.prim, h.face, vec3_madd(r->o, h.t, r->d), 1, &tc->map, &sf);
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

/* One sample: the primary ray of lane m of b, its colour added to sum;
 * *p gets the primitive it sees (-1: none), *r and *t0 its last ray and
 * start. A ray that finds nothing is started again beyond the next
 * half-space plane (one lane set up on its own). */
static void render_ops_sample(const cscene *cs, trace_ctx *tc, const cscene_batch *b, int m, double *sum,
                              int *p, prim_ray *r, double *t0)
{
    double rgb[3];
    size_t tries = 0;
    int k, st1 = b->st[m];
    cscene_batch one;
    *p = -1;
    if (st1 == CSCENE_BAD)
        return;
    tc->rs.rays_primary++;
    for (k = 0; k < 3; k++)
        rgb[k] = cs->sc->background[k];
    for (;;) {
        if (st1 <= 0) {
            tc->rs.range_cut += st1 == CSCENE_CUT;
            break;
        }
        NS(cscene_primary_ray)(cs, b, m, r);
        *t0 = b->t0[m];
        NS(trace_ray)(cs, tc, r, 0, 1.0, rgb, p);
        if (*p >= 0 || ++tries > cs->nplanes)
            break;
        for (k = 0; k < 3; k++)
            one.d[k][0] = b->d[k][m];
        NS(cscene_primary_batch)(cs, &one, 1, *t0 + GEOM_TMAX - 2);
        b = &one;
        m = 0;
        st1 = one.st[0];
    }
    for (k = 0; k < 3; k++)
        sum[k] += rgb[k];
}

/* Pixel centres at (x + (i+1/2)/aa, y + (j+1/2)/aa); the PID is the one seen
 * by the sample nearest the pixel centre. Directions are set up in double,
 * the ray's start too (cscene_primary_batch), and the direction is
 * normalised there. A direction fwd + sx right + sy up is summed left to
 * right, so its column part fwd + sx right is formed once per sample column
 * of a strip of at most RENDER_TILE pixels and sy once per sample row. The
 * samples of one row of the strip, pixel by pixel and within a pixel row
 * by row, are set up CSCENE_BATCH at a time, then traced in that order. */
static void render_ops_tile(const void *vcs, void *vtc, const render_opts *o,
                            int x0, int y0, int x1, int y1, render_fb *fb, render_stats *st)
{
    const cscene *cs = vcs;
    trace_ctx *tc = vtc;
    double aspect = (double)o->width / o->height;
    double rss = 1.0 / (o->aa * o->aa);
    double col[RENDER_TILE * RENDER_MAX_AA][3], sy[RENDER_MAX_AA], up[3];
    int xs, xe, x, y, i, j, k, aa = o->aa, per = aa * aa, centre = aa / 2 * (aa + 1);
    unsigned long rays_per_pixel = (unsigned long)RENDER_MAX_RAYS_PER_SAMPLE * (unsigned long)per;
    cscene_batch b;
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
            /* (x, j, i): the next sample to set up; xt and s (the sample in
             * its pixel, row by row) the next to trace */
            int xt = xs, s = 0, pid = -1;
            double sum[3] = {0, 0, 0};
            for (j = 0; j < aa; j++)
                sy[j] = (1 - 2 * (y + (j + 0.5) / aa) / o->height) * cs->tan_half;
            x = xs;
            i = j = 0;
            while (xt < xe) {
                int n, m;
                /* one sample a pixel needs no counters */
                for (n = 0; aa == 1 && n < CSCENE_BATCH && x < xe; n++, x++)
                    for (k = 0; k < 3; k++)
                        b.d[k][n] = col[x - xs][k] + sy[0] * up[k];
                for (; n < CSCENE_BATCH && x < xe; n++) {
                    const double *c = col[(x - xs) * aa + i];
                    for (k = 0; k < 3; k++)
                        b.d[k][n] = c[k] + sy[j] * up[k];
                    if (++i == aa) {
                        i = 0;
                        if (++j == aa) {
                            j = 0;
                            x++;
                        }
                    }
                }
                NS(cscene_primary_batch)(cs, &b, n, 0);
                for (m = 0; m < n; m++) {
                    size_t at = (size_t)y * (size_t)o->width + (size_t)xt;
                    double t0 = 0;
                    prim_ray r;
                    int p;
                    if (s == 0)
                        tc->rays_left = rays_per_pixel;
                    render_ops_sample(cs, tc, &b, m, sum, &p, &r, &t0);
                    if (s == centre) {
                        pid = p;
                        if (fb->ids.px && p >= 0)
                            render_ops_ids(cs, tc, &r, t0, &fb->ids.px[at]);
                    }
                    if (++s < per)
                        continue;
                    s = 0;
                    render_ops_pixel(fb, at, sum, rss, pid);
                    pid = -1;
                    xt++;
                }
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
    .isa = NUM_ISA_NAME,
    .compile = render_ops_compile,
    .counts = render_ops_counts,
    .free = render_ops_free,
    .thread_new = render_ops_thread_new,
    .thread_free = render_ops_thread_free,
    .render_tile = render_ops_tile,
    .region = render_ops_region,
};
