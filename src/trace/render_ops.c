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
    /* the per-sample quotients as products (exact for aa a power of two) */
    double sxk = 2.0 / o->width * cs->tan_half * aspect, syk = 2.0 / o->height * cs->tan_half;
    double raa = 1.0 / o->aa, rss = 1.0 / (o->aa * o->aa);
    int x, y, i, j, k, aa = o->aa, mid = aa / 2;
    tc->rs = (render_stats){0};
    tc->gs = (geom_stats){0};
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++) {
            double sum[3] = {0, 0, 0};
            int pid = -1;
            unsigned char *px = fb->img.px + 3 * ((size_t)y * (size_t)o->width + (size_t)x);
            for (j = 0; j < aa; j++)
                for (i = 0; i < aa; i++) {
                    double sx = (x + (i + 0.5) * raa) * sxk - cs->tan_half * aspect;
                    double sy = cs->tan_half - (y + (j + 0.5) * raa) * syk;
                    double rgb[3];
                    prim_ray r;
                    vec3 dir;
                    int p;
                    /* component by component: an array would be stored in
                     * 8-byte pieces and read back in 16 (a stalled load) */
                    dir = vec3_make(num_from_d(cs->fwd[0] + sx * cs->right[0] + sy * cs->up[0]),
                                    num_from_d(cs->fwd[1] + sx * cs->right[1] + sy * cs->up[1]),
                                    num_from_d(cs->fwd[2] + sx * cs->right[2] + sy * cs->up[2]));
                    if (vec3_normalize(dir, &dir, NULL))
                        continue;
                    prim_ray_set(&r, cs->eye_n, dir, -1, 0);
                    tc->rs.rays_primary++;
                    NS(trace_ray)(cs, tc, &r, 0, 1.0, rgb, &p);
                    for (k = 0; k < 3; k++)
                        sum[k] += rgb[k];
                    if (i == mid && j == mid)
                        pid = p;
                }
            for (k = 0; k < 3; k++)
                px[k] = render_ops_byte(sum[k] * rss);
            fb->pid[(size_t)y * (size_t)o->width + (size_t)x] = pid;
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
}

const render_ops NS(render_ops) = {
    NUM_NAME, render_ops_compile, render_ops_free, render_ops_thread_new,
    render_ops_thread_free, render_ops_tile};
