/* render_ops — this numeric mode's entry points for the render driver
 * (render.h): compile, per-thread contexts, and one tile of primary rays. */
#include "trace/trace.h"
#include "util/mem.h"
#include <math.h>

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

/* Pixel centres at (x + (i+1/2)/aa, y + (j+1/2)/aa); the PID is the one seen
 * by the sample nearest the pixel centre. Directions are set up in double
 * and normalised in num. */
static void render_ops_tile(const void *vcs, void *vtc, const render_opts *o,
                            int x0, int y0, int x1, int y1, render_fb *fb, render_stats *st)
{
    const cscene *cs = vcs;
    trace_ctx *tc = vtc;
    double aspect = (double)o->width / o->height;
    int x, y, i, j, k, aa = o->aa, mid = aa / 2;
    tc->rs = (render_stats){0};
    tc->gs = (geom_stats){0};
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++) {
            double sum[3] = {0, 0, 0};
            int pid = -1;
            unsigned char *px = fb->img.px + 3 * ((size_t)y * (size_t)o->width + (size_t)x);
            tc->rays_left = (unsigned long)RENDER_MAX_RAYS_PER_SAMPLE * (unsigned long)(aa * aa);
            for (j = 0; j < aa; j++)
                for (i = 0; i < aa; i++) {
                    double sx = (2 * (x + (i + 0.5) / aa) / o->width - 1) * cs->tan_half * aspect;
                    double sy = (1 - 2 * (y + (j + 0.5) / aa) / o->height) * cs->tan_half;
                    double dd[3], rgb[3];
                    prim_ray r;
                    int p;
                    for (k = 0; k < 3; k++)
                        dd[k] = cs->fwd[k] + sx * cs->right[k] + sy * cs->up[k];
                    r.o = cs->eye_n;
                    r.excl_prim = -1;
                    r.excl_enter = 0;
                    if (vec3_normalize(vec3_from_d(dd), &r.d, NULL))
                        continue;
                    tc->rs.rays_primary++;
                    NS(trace_ray)(cs, tc, &r, 0, 1.0, rgb, &p);
                    for (k = 0; k < 3; k++)
                        sum[k] += rgb[k];
                    if (i == mid && j == mid)
                        pid = p;
                }
            for (k = 0; k < 3; k++)
                px[k] = render_ops_byte(sum[k] / (aa * aa));
            fb->pid[(size_t)y * (size_t)o->width + (size_t)x] = pid;
        }
    st->rays_primary += tc->rs.rays_primary;
    st->rays_shadow += tc->rs.rays_shadow;
    st->rays_reflected += tc->rs.rays_reflected;
    st->rays_refracted += tc->rs.rays_refracted;
    st->pds_lookups += tc->rs.pds_lookups;
    st->prim_tests += tc->gs.prim_tests;
    st->bound_tests += tc->gs.bound_tests;
    st->csg_pruned += tc->gs.pruned;
    st->arena_full += tc->gs.arena_full;
    st->rays_capped += tc->rs.rays_capped;
}

const render_ops NS(render_ops) = {
    NUM_NAME, render_ops_compile, render_ops_free, render_ops_thread_new,
    render_ops_thread_free, render_ops_tile};
