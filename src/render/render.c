/* render — ops lookup, tiles over OpenMP threads, counter sums (see render.h). */
#include "render/render.h"
#include "num/fx.h"
#include "util/mem.h"
#include <omp.h>
#include <string.h>
#include <time.h>
#include <strings.h>

const render_ops *render_ops_find(const char *name)
{
    static const render_ops *const all[] = {&q16_render_ops, &q32_render_ops,
                                            &f32_render_ops, &f64_render_ops};
    size_t i;
    for (i = 0; name && i < sizeof all / sizeof all[0]; i++)
        if (!strcasecmp(all[i]->name, name))
            return all[i];
    return NULL;
}

void render_fb_free(render_fb *fb)
{
    image_free(&fb->img);
    mem_free(fb->pid);
    fb->pid = NULL;
}

static void render_stats_add(render_stats *a, const render_stats *b)
{
    a->rays_primary += b->rays_primary;
    a->rays_shadow += b->rays_shadow;
    a->rays_reflected += b->rays_reflected;
    a->rays_refracted += b->rays_refracted;
    a->pds_lookups += b->pds_lookups;
    a->fx_overflows += b->fx_overflows;
    a->prim_tests += b->prim_tests;
    a->bound_tests += b->bound_tests;
    a->csg_pruned += b->csg_pruned;
    a->arena_full += b->arena_full;
}

void render_stats_print(FILE *f, const render_stats *st)
{
    fprintf(f, "rays.primary=%llu\nrays.shadow=%llu\nrays.reflected=%llu\nrays.refracted=%llu\n"
               "pds.lookups=%llu\nfx.overflows=%llu\ntests.prim=%llu\ntests.bound=%llu\n"
               "csg.pruned=%llu\ntime.compile_s=%.6f\ntime.render_s=%.6f\n",
            st->rays_primary, st->rays_shadow, st->rays_reflected, st->rays_refracted,
            st->pds_lookups, st->fx_overflows, st->prim_tests, st->bound_tests,
            st->csg_pruned, st->time_compile_s, st->time_render_s);
    if (st->arena_full)
        fprintf(f, "csg.arena_full=%llu\n", st->arena_full);
}

static unsigned long long render_rays(const render_stats *st)
{
    return st->rays_primary + st->rays_shadow + st->rays_reflected + st->rays_refracted;
}

/* CPU seconds of the calling thread: unlike wall time, not inflated when
 * the thread is descheduled on a loaded machine. */
static double render_thread_cpu(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return omp_get_wtime();
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Estimates each tile's cost for a progress display that is linear in
 * time: times (in thread CPU time) a 4x4 grid of one-sample pixels in the tile (about 1/64 of
 * its pixels at --aa 1) and scales by the tile's pixel count. The pixels
 * are drawn into the framebuffer, which the render then overwrites. */
static void render_tile_costs(const void *cs, void **tcs, const render_ops *ops, const render_opts *o,
                              long ntx, long ntiles, int nthreads, render_fb *out, double *cost)
{
    render_opts one = *o;
    double sum = 0, floor_cost;
    long k;
    one.aa = 1;
    one.progress = NULL;
#pragma omp parallel for schedule(dynamic, 4) num_threads(nthreads)
    for (k = 0; k < ntiles; k++) {
        render_stats scratch;
        int x0 = (int)(k % ntx) * RENDER_TILE, y0 = (int)(k / ntx) * RENDER_TILE;
        int x1 = x0 + RENDER_TILE > o->width ? o->width : x0 + RENDER_TILE;
        int y1 = y0 + RENDER_TILE > o->height ? o->height : y0 + RENDER_TILE;
        int x, y, n = 0;
        double t = render_thread_cpu();
        memset(&scratch, 0, sizeof scratch);
        for (y = y0 + RENDER_TILE / 8; y < y1; y += RENDER_TILE / 4)
            for (x = x0 + RENDER_TILE / 8; x < x1; x += RENDER_TILE / 4, n++)
                ops->render_tile(cs, tcs[omp_get_thread_num()], &one, x, y, x + 1, y + 1, out, &scratch);
        if (!n) {   /* a sliver of a tile at the edge */
            ops->render_tile(cs, tcs[omp_get_thread_num()], &one, x0, y0, x0 + 1, y0 + 1, out, &scratch);
            n = 1;
        }
        cost[k] = (render_thread_cpu() - t) / n * (double)((x1 - x0) * (y1 - y0));
    }
    for (k = 0; k < ntiles; k++)
        sum += cost[k];
    /* no tile is free: a floor keeps timer noise from zeroing one */
    floor_cost = sum > 0 ? 0.02 * sum / (double)ntiles : 1;
    for (k = 0; k < ntiles; k++)
        cost[k] += floor_cost;
}

int render_scene(const scene *sc, const render_ops *ops, const render_opts *o,
                 render_fb *fb, render_stats *st, diag *err)
{
    render_opts opt = *o;
    render_fb out;
    render_stats total;
    void *cs = NULL, **tcs = NULL;
    unsigned long ov0;
    double t0, tstart = omp_get_wtime(), *cost = NULL, cost_total = 0, cost_done = 0;
    unsigned long long rays_done = 0;
    long ntx, nty, ntiles, done = 0;
    int i, status = 0, nthreads;

    memset(&total, 0, sizeof total);
    memset(&out, 0, sizeof out);
    if (!opt.width || !opt.height) {
        opt.width = sc->view.width;
        opt.height = sc->view.height;
    }
    if (opt.width < 1 || opt.height < 1 || opt.width > IMAGE_MAX_SIDE || opt.height > IMAGE_MAX_SIDE)
        return diag_at(err, DIAG_INPUT, sc->source ? sc->source : "", 0, 0,
                       "image size %dx%d out of range", opt.width, opt.height);
    if (opt.aa < 1 || opt.aa > RENDER_MAX_AA || opt.threads < 1 || opt.threads > RENDER_MAX_THREADS)
        return diag_at(err, DIAG_USAGE, "", 0, 0, "bad anti-aliasing or thread count");
    nthreads = opt.threads;

    ov0 = fx_overflows;
    t0 = omp_get_wtime();
    if ((status = ops->compile(sc, &cs, err)) != 0)
        return status;
    total.time_compile_s = omp_get_wtime() - t0;
    if ((status = image_alloc(&out.img, opt.width, opt.height, 3, "render", err)) != 0)
        goto done;
    out.pid = mem_calloc((size_t)opt.width * (size_t)opt.height, sizeof *out.pid);
    tcs = mem_calloc((size_t)nthreads, sizeof *tcs);
    if (!out.pid || !tcs) {
        status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the framebuffer");
        goto done;
    }
    for (i = 0; i < nthreads; i++)
        if (ops->thread_new(cs, &tcs[i])) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for thread contexts");
            goto done;
        }
    total.fx_overflows += fx_overflows - ov0;

    ntx = (opt.width + RENDER_TILE - 1) / RENDER_TILE;
    nty = (opt.height + RENDER_TILE - 1) / RENDER_TILE;
    ntiles = ntx * nty;
    if (opt.progress) {
        long k;
        if (!(cost = mem_calloc((size_t)ntiles, sizeof *cost))) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the tile costs");
            goto done;
        }
        render_tile_costs(cs, tcs, ops, &opt, ntx, ntiles, nthreads, &out, cost);
        for (k = 0; k < ntiles; k++)
            cost_total += cost[k];
    }
    t0 = omp_get_wtime();
#pragma omp parallel num_threads(nthreads)
    {
        render_stats mine;
        unsigned long before = fx_overflows;
        int me = omp_get_thread_num();
        long k;
        memset(&mine, 0, sizeof mine);
#pragma omp for schedule(dynamic, 1)
        for (k = 0; k < ntiles; k++) {
            int x0 = (int)(k % ntx) * RENDER_TILE, y0 = (int)(k / ntx) * RENDER_TILE;
            int x1 = x0 + RENDER_TILE > opt.width ? opt.width : x0 + RENDER_TILE;
            int y1 = y0 + RENDER_TILE > opt.height ? opt.height : y0 + RENDER_TILE;
            unsigned long long before_rays = render_rays(&mine);
            ops->render_tile(cs, tcs[me], &opt, x0, y0, x1, y1, &out, &mine);
            if (opt.progress) {
#pragma omp critical(render_progress)
                {
                    render_progress pr;
                    done++;
                    cost_done += cost[k];
                    rays_done += render_rays(&mine) - before_rays;
                    pr.tiles_done = done;
                    pr.tiles = ntiles;
                    pr.fraction = done == ntiles ? 1.0 : cost_done / cost_total;
                    pr.elapsed_s = omp_get_wtime() - tstart;
                    pr.rays = rays_done;
                    opt.progress(opt.progress_ctx, &pr);
                }
            }
        }
        mine.fx_overflows += fx_overflows - before;
#pragma omp critical(render_sum)
        render_stats_add(&total, &mine);
    }
    total.time_render_s = omp_get_wtime() - t0;

done:
    mem_free(cost);
    if (tcs) {
        for (i = 0; i < nthreads; i++)
            if (tcs[i])
                ops->thread_free(tcs[i]);
        mem_free(tcs);
    }
    ops->free(cs);
    if (status) {
        render_fb_free(&out);
        return status;
    }
    *fb = out;
    *st = total;
    return 0;
}
