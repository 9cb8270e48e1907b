/* render — ops lookup, tiles over OpenMP threads, counter sums (see render.h). */
#include "render/render.h"
#include "num/fx.h"
#include "util/mem.h"
#include <errno.h>
#include <omp.h>
#include <pthread.h>
#include <string.h>

const render_ops *render_ops_find(const char *name)
{
    static const render_ops *const all[] = {&q16_render_ops, &q32_render_ops,
                                            &f32_render_ops, &f64_render_ops};
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
    a->rays_capped += b->rays_capped;
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
    if (st->rays_capped)
        fprintf(f, "rays.capped=%llu\n", st->rays_capped);
}

/* The tile loop's shared state: workers take the next tile under the lock. */
typedef struct render_job {
    const render_ops *ops;
    const render_opts *opt;
    void *cs;
    render_fb *out;
    long ntx, ntiles, next, done;
    pthread_mutex_t lock;
} render_job;

typedef struct render_worker {
    render_job *job;
    void *tc;
    render_stats st;
    pthread_t id;
} render_worker;

static void *render_worker_run(void *arg)
{
    render_worker *w = arg;
    render_job *j = w->job;
    const render_opts *o = j->opt;
    unsigned long before = fx_overflows;
    for (;;) {
        long k;
        int x0, y0, x1, y1;
        pthread_mutex_lock(&j->lock);
        k = j->next < j->ntiles ? j->next++ : -1;
        pthread_mutex_unlock(&j->lock);
        if (k < 0)
            break;
        x0 = (int)(k % j->ntx) * RENDER_TILE;
        y0 = (int)(k / j->ntx) * RENDER_TILE;
        x1 = x0 + RENDER_TILE > o->width ? o->width : x0 + RENDER_TILE;
        y1 = y0 + RENDER_TILE > o->height ? o->height : y0 + RENDER_TILE;
        j->ops->render_tile(j->cs, w->tc, o, x0, y0, x1, y1, j->out, &w->st);
        if (o->progress) {
            pthread_mutex_lock(&j->lock);
            j->done++;
            o->progress(o->progress_ctx, j->done, j->ntiles);
            pthread_mutex_unlock(&j->lock);
        }
    }
    w->st.fx_overflows += fx_overflows - before;   /* fx_overflows is per thread */
    return NULL;
}

/* Runs the tiles on nthreads threads (the calling one among them). A thread
 * that cannot be created is an error (DIAG_IO), reported after the threads
 * already started have finished. */
static int render_tiles(render_job *job, render_worker *w, int nthreads, diag *err)
{
    int i, started, rc = 0;
    for (started = 1; started < nthreads; started++)
        if ((rc = pthread_create(&w[started].id, NULL, render_worker_run, &w[started])) != 0)
            break;
    if (rc) {   /* stop the others at their next tile */
        pthread_mutex_lock(&job->lock);
        job->next = job->ntiles;
        pthread_mutex_unlock(&job->lock);
    } else {
        render_worker_run(&w[0]);
    }
    for (i = 1; i < started; i++)
        pthread_join(w[i].id, NULL);
    if (rc)
        return diag_at(err, DIAG_IO, "", 0, 0, "cannot create render thread %d of %d: %s", started + 1,
                       nthreads, strerror(rc));
    return 0;
}

int render_scene(const scene *sc, const render_ops *ops, const render_opts *o,
                 render_fb *fb, render_stats *st, diag *err)
{
    render_opts opt = *o;
    render_fb out;
    render_stats total;
    render_job job;
    render_worker *w = NULL;
    void *cs = NULL;
    unsigned long ov0;
    double t0;
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
    w = mem_calloc((size_t)nthreads, sizeof *w);
    if (!out.pid || !w) {
        status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the framebuffer");
        goto done;
    }
    memset(&job, 0, sizeof job);
    for (i = 0; i < nthreads; i++) {
        w[i].job = &job;
        if (ops->thread_new(cs, &w[i].tc)) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory for thread contexts");
            goto done;
        }
    }
    total.fx_overflows += fx_overflows - ov0;

    job.ops = ops;
    job.opt = &opt;
    job.cs = cs;
    job.out = &out;
    job.ntx = (opt.width + RENDER_TILE - 1) / RENDER_TILE;
    job.ntiles = job.ntx * ((opt.height + RENDER_TILE - 1) / RENDER_TILE);
    if ((errno = pthread_mutex_init(&job.lock, NULL)) != 0) {
        status = diag_at(err, DIAG_IO, "", 0, 0, "cannot create a lock: %s", strerror(errno));
        goto done;
    }
    t0 = omp_get_wtime();
    status = render_tiles(&job, w, nthreads, err);
    pthread_mutex_destroy(&job.lock);
    total.time_render_s = omp_get_wtime() - t0;
    for (i = 0; i < nthreads; i++)
        render_stats_add(&total, &w[i].st);

done:
    if (w) {
        for (i = 0; i < nthreads; i++)
            if (w[i].tc)
                ops->thread_free(w[i].tc);
        mem_free(w);
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
