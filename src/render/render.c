/* render — ops lookup, tiles over OpenMP threads, counter sums (see render.h). */
#include "render/render.h"
#include "num/fx.h"
#include "num/hfp.h"
#include "util/mem.h"
#include <omp.h>
#include <string.h>

const render_ops *render_ops_find(const char *name)
{
    static const render_ops *const all[] = {&q16_render_ops, &q32_render_ops, &f32_render_ops,
                                            &f64_render_ops, &hfp32_render_ops, &hfp64_render_ops};
    size_t i;
    for (i = 0; name && i < sizeof all / sizeof all[0]; i++)
        if (!strcmp(all[i]->name, name))
            return all[i];
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
}

void render_stats_print(FILE *f, const render_stats *st)
{
    int k;
    fprintf(f, "rays.primary=%llu\nrays.shadow=%llu\nrays.reflected=%llu\nrays.refracted=%llu\n"
               "pds.lookups=%llu\nfx.overflows=%llu\ntests.prim=%llu\ntests.bound=%llu\n"
               "csg.pruned=%llu\nskipped.uv=%llu\nskipped.shadow=%llu\n"
               "time.compile_s=%.6f\ntime.render_s=%.6f\n",
            st->rays_primary, st->rays_shadow, st->rays_reflected, st->rays_refracted,
            st->pds_lookups, st->fx_overflows, st->prim_tests, st->bound_tests,
            st->csg_pruned, st->uv_skipped, st->shadow_skipped, st->time_compile_s,
            st->time_render_s);
    for (k = 0; k < HFP_EXC_N; k++)
        fprintf(f, "hfp.%s=%llu\n", hfp_exc_name[k], st->hfp_exc[k]);
    if (st->arena_full)
        fprintf(f, "csg.arena_full=%llu\n", st->arena_full);
    fprintf(f, "range.cut=%llu\n", st->range_cut);
}

int render_region_check(const int region[4], int width, int height)
{
    if (!region[0] && !region[1] && !region[2] && !region[3])
        return 0;
    return region[0] >= 0 && region[0] < region[2] && region[2] <= width &&
           region[1] >= 0 && region[1] < region[3] && region[3] <= height ? 0 : -1;
}

int render_scene(const scene *sc, const render_ops *ops, const render_opts *o,
                 render_fb *fb, render_stats *st, diag *err)
{
    render_opts opt = *o;
    render_fb out;
    render_stats total;
    void *cs = NULL, **tcs = NULL;
    unsigned long ov0, hfp0[HFP_EXC_N];
    double t0;
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
    if ((status = image_alloc(&out.img, opt.width, opt.height, 3, "render", err)) != 0)
        goto done;
    out.pid = mem_calloc((size_t)opt.width * (size_t)opt.height, sizeof *out.pid);
    tcs = mem_calloc((size_t)nthreads, sizeof *tcs);
    if (!out.pid || !tcs) {
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
            int x0 = (int)(tx0 + k % ntx) * RENDER_TILE, y0 = (int)(ty0 + k / ntx) * RENDER_TILE;
            int x1 = x0 + RENDER_TILE > opt.region[2] ? opt.region[2] : x0 + RENDER_TILE;
            int y1 = y0 + RENDER_TILE > opt.region[3] ? opt.region[3] : y0 + RENDER_TILE;
            if (x0 < opt.region[0])
                x0 = opt.region[0];
            if (y0 < opt.region[1])
                y0 = opt.region[1];
            ops->render_tile(cs, tcs[me], &opt, x0, y0, x1, y1, &out, &mine);
            if (opt.progress) {
#pragma omp critical(render_progress)
                {
                    done++;
                    opt.progress(opt.progress_ctx, done, ntiles);
                }
            }
        }
        render_stats_numeric(&mine, before, hbefore);
#pragma omp critical(render_sum)
        render_stats_add(&total, &mine);
    }
    total.time_render_s = omp_get_wtime() - t0;

done:
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
