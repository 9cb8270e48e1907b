/* render — ops lookup, tiles over OpenMP threads, counter sums (see render.h). */
#include "render/render.h"
#include "num/fx.h"
#include "num/hfp.h"
#include "util/mem.h"
#include <omp.h>
#include <string.h>
#include <time.h>
#include <strings.h>

#if defined(RENDER_ISA_V3)
extern const render_ops q16_v3_render_ops, q32_v3_render_ops, f32_v3_render_ops, f64_v3_render_ops,
    hfp32_v3_render_ops, hfp64_v3_render_ops;

/* 1 when the processor (and the kernel, for the AVX registers) runs
 * x86-64-v3 code. */
static int render_isa_v3(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("x86-64-v3") != 0;
}
#endif

const render_ops *render_ops_find(const char *name, render_isa isa)
{
    static const render_ops *const all[] = {&q16_render_ops, &q32_render_ops, &f32_render_ops,
                                            &f64_render_ops, &hfp32_render_ops, &hfp64_render_ops};
#if defined(RENDER_ISA_V3)
    static const render_ops *const v3[] = {&q16_v3_render_ops, &q32_v3_render_ops, &f32_v3_render_ops,
                                           &f64_v3_render_ops, &hfp32_v3_render_ops, &hfp64_v3_render_ops};
#endif
    size_t i;
    for (i = 0; name && i < sizeof all / sizeof all[0]; i++)
        if (!strcasecmp(all[i]->name, name)) {
#if defined(RENDER_ISA_V3)
            if (isa == RENDER_ISA_AUTO && render_isa_v3())
                return v3[i];
#endif
            (void)isa;
            return all[i];
        }
    return NULL;
}

void render_fb_free(render_fb *fb)
{
    image_free(&fb->img);
    mem_free(fb->pid);
    fb->pid = NULL;
    idmap_free(&fb->ids);
}

/* Adds this thread's fixed-point overflows and HFP exceptions since the
 * snapshot fx0, hfp0 to st. */
static void render_stats_numeric(render_stats *st, unsigned long fx0, const unsigned long *hfp0)
{
    int k;
    st->fx_overflows += fx_overflows - fx0;
    for (k = 0; k < HFP_EXC_N; k++)
        st->hfp_exc[k] += hfp_exc[k] - hfp0[k];
}

void render_stats_add(render_stats *a, const render_stats *b)
{
    int k;
    a->rays_primary += b->rays_primary;
    a->rays_shadow += b->rays_shadow;
    a->rays_reflected += b->rays_reflected;
    a->rays_refracted += b->rays_refracted;
    a->pds_lookups += b->pds_lookups;
    a->fx_overflows += b->fx_overflows;
    for (k = 0; k < HFP_EXC_N; k++)
        a->hfp_exc[k] += b->hfp_exc[k];
    a->prim_tests += b->prim_tests;
    a->bound_tests += b->bound_tests;
    a->csg_pruned += b->csg_pruned;
    a->arena_full += b->arena_full;
    a->range_cut += b->range_cut;
    a->uv_skipped += b->uv_skipped;
    a->shadow_skipped += b->shadow_skipped;
    a->rays_capped += b->rays_capped;
    a->objects = b->objects > a->objects ? b->objects : a->objects;
    a->inst_moved = b->inst_moved > a->inst_moved ? b->inst_moved : a->inst_moved;
    a->inst_turned = b->inst_turned > a->inst_turned ? b->inst_turned : a->inst_turned;
}

void render_stats_print(FILE *f, const render_stats *st)
{
    int k;
    fprintf(f, "rays.primary=%llu\nrays.shadow=%llu\nrays.reflected=%llu\nrays.refracted=%llu\n"
               "pds.lookups=%llu\nfx.overflows=%llu\ntests.prim=%llu\ntests.bound=%llu\n"
               "csg.pruned=%llu\nskipped.uv=%llu\nskipped.shadow=%llu\n"
               "objects=%llu\ninstances.moved=%llu\ninstances.turned=%llu\n"
               "time.compile_s=%.6f\ntime.render_s=%.6f\n",
            st->rays_primary, st->rays_shadow, st->rays_reflected, st->rays_refracted,
            st->pds_lookups, st->fx_overflows, st->prim_tests, st->bound_tests,
            st->csg_pruned, st->uv_skipped, st->shadow_skipped, st->objects, st->inst_moved,
            st->inst_turned, st->time_compile_s, st->time_render_s);
    for (k = 0; k < HFP_EXC_N; k++)
        fprintf(f, "hfp.%s=%llu\n", hfp_exc_name[k], st->hfp_exc[k]);
    if (st->arena_full)
        fprintf(f, "csg.arena_full=%llu\n", st->arena_full);
    fprintf(f, "range.cut=%llu\n", st->range_cut);
    if (st->rays_capped)
        fprintf(f, "rays.capped=%llu\n", st->rays_capped);
}

int render_region_check(const int region[4], int width, int height)
{
    if (!region[0] && !region[1] && !region[2] && !region[3])
        return 0;
    return region[0] >= 0 && region[0] < region[2] && region[2] <= width &&
           region[1] >= 0 && region[1] < region[3] && region[3] <= height ? 0 : -1;
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
/* Tile k of the ntx-wide grid whose first tile is (tx0, ty0), on the image's
 * 32-pixel grid and clipped to o->region: pixels [r0,r2) x [r1,r3). */
static void render_tile_rect(const render_opts *o, long tx0, long ty0, long ntx, long k, int r[4])
{
    r[0] = (int)(tx0 + k % ntx) * RENDER_TILE;
    r[1] = (int)(ty0 + k / ntx) * RENDER_TILE;
    r[2] = r[0] + RENDER_TILE > o->region[2] ? o->region[2] : r[0] + RENDER_TILE;
    r[3] = r[1] + RENDER_TILE > o->region[3] ? o->region[3] : r[1] + RENDER_TILE;
    if (r[0] < o->region[0])
        r[0] = o->region[0];
    if (r[1] < o->region[1])
        r[1] = o->region[1];
}

static void render_tile_costs(const void *cs, void **tcs, const render_ops *ops, const render_opts *o,
                              long tx0, long ty0, long ntx, long ntiles, int nthreads,
                              render_fb *out, double *cost)
{
    render_opts one = *o;
    double sum = 0, floor_cost;
    long k;
    one.aa = 1;
    one.progress = NULL;
#pragma omp parallel for schedule(dynamic, 4) num_threads(nthreads)
    for (k = 0; k < ntiles; k++) {
        render_stats scratch;
        int r[4], x0, y0, x1, y1, x, y, n = 0;
        double t = render_thread_cpu();
        render_tile_rect(o, tx0, ty0, ntx, k, r);
        x0 = r[0]; y0 = r[1]; x1 = r[2]; y1 = r[3];
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
    unsigned long ov0, hfp0[HFP_EXC_N];
    double t0, tstart = omp_get_wtime(), *cost = NULL, cost_total = 0, cost_done = 0;
    unsigned long long rays_done = 0;
    long tx0, ty0, ntx, nty, ntiles, done = 0;
    int i, status = 0, nthreads;

    memset(&total, 0, sizeof total);
    memset(&out, 0, sizeof out);
    if (!opt.width || !opt.height) {
        opt.width = sc->view.width;
        opt.height = sc->view.height;
    }
    if (opt.width < 1 || opt.height < 1 || opt.width > SCENE_MAX_SIDE || opt.height > SCENE_MAX_SIDE)
        return diag_at(err, DIAG_INPUT, sc->source ? sc->source : "", 0, 0,
                       "image size %dx%d out of range", opt.width, opt.height);
    if (opt.aa < 1 || opt.aa > RENDER_MAX_AA || opt.threads < 1 || opt.threads > RENDER_MAX_THREADS)
        return diag_at(err, DIAG_USAGE, "", 0, 0, "bad anti-aliasing or thread count");
    if (render_region_check(opt.region, opt.width, opt.height))
        return diag_at(err, DIAG_USAGE, "", 0, 0, "region %d,%d,%d,%d is not inside the %dx%d image",
                       opt.region[0], opt.region[1], opt.region[2], opt.region[3], opt.width,
                       opt.height);
    if (!opt.region[2]) {
        opt.region[2] = opt.width;
        opt.region[3] = opt.height;
    }
    nthreads = opt.threads;

    ov0 = fx_overflows;
    memcpy(hfp0, hfp_exc, sizeof hfp0);
    t0 = omp_get_wtime();
    if ((status = ops->compile(sc, &cs, err)) != 0)
        return status;
    total.time_compile_s = omp_get_wtime() - t0;
    ops->counts(cs, &total);
    if ((status = image_alloc(&out.img, opt.width, opt.height, 3, "render", err)) != 0)
        goto done;
    if (!opt.skip_pid)
        out.pid = mem_calloc((size_t)opt.width * (size_t)opt.height, sizeof *out.pid);
    tcs = mem_calloc((size_t)nthreads, sizeof *tcs);
    if ((!out.pid && !opt.skip_pid) || !tcs) {
        status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the framebuffer");
        goto done;
    }
    if (opt.ids && (status = idmap_alloc(&out.ids, opt.width, opt.height, err)))
        goto done;
    for (i = 0; i < nthreads; i++)
        if (ops->thread_new(cs, &tcs[i])) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for thread contexts");
            goto done;
        }
    render_stats_numeric(&total, ov0, hfp0);

    /* Tiles on the image's 32-pixel grid, clipped to the region, so a
     * region render computes exactly the pixels the whole render would. */
    tx0 = opt.region[0] / RENDER_TILE;
    ty0 = opt.region[1] / RENDER_TILE;
    ntx = (opt.region[2] + RENDER_TILE - 1) / RENDER_TILE - tx0;
    nty = (opt.region[3] + RENDER_TILE - 1) / RENDER_TILE - ty0;
    ntiles = ntx * nty;
    if (opt.progress) {
        long k;
        if (!(cost = mem_calloc((size_t)ntiles, sizeof *cost))) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the tile costs");
            goto done;
        }
        render_tile_costs(cs, tcs, ops, &opt, tx0, ty0, ntx, ntiles, nthreads, &out, cost);
        for (k = 0; k < ntiles; k++)
            cost_total += cost[k];
    }
    t0 = omp_get_wtime();
#pragma omp parallel num_threads(nthreads)
    {
        render_stats mine;
        unsigned long before = fx_overflows, hbefore[HFP_EXC_N];
        int me = omp_get_thread_num();
        long k;
        memset(&mine, 0, sizeof mine);
        memcpy(hbefore, hfp_exc, sizeof hbefore);
#pragma omp for schedule(dynamic, 1)
        for (k = 0; k < ntiles; k++) {
            int r[4];
            unsigned long long before_rays = render_rays(&mine);
            render_tile_rect(&opt, tx0, ty0, ntx, k, r);
            ops->render_tile(cs, tcs[me], &opt, r[0], r[1], r[2], r[3], &out, &mine);
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
        render_stats_numeric(&mine, before, hbefore);
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
