/* cli_mpi — distributed renders and benchmark sweeps over MPI ranks (see
 * cli_mpi.h). */
#include "cli/cli_mpi.h"
#include "render/render_part.h"
#include "util/mem.h"
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef MAPRT_MPI
#include <mpi.h>
#include <pthread.h>
#endif

/* The farm on one rank: every cell in order, each taken when it is done. */
static int cli_mpi_farm_local(const cli_mpi_farm *f, diag *err)
{
    int c, st = 0;
    for (c = 0; c < f->cells && !st; c++) {
        uint8_t *buf = NULL;
        size_t len = 0;
        if ((st = f->run(f->ctx, c, &buf, &len, err)) == 0)
            st = f->take(f->ctx, c, 0, buf, len, err);
        mem_free(buf);
    }
    return st;
}

#ifdef MAPRT_MPI
static int cli_mpi_on, cli_mpi_me, cli_mpi_n = 1;

/* A cell number goes out with WORK; STOP ends a rank's farm; a result comes
 * back as META (cell, status, length, and the diag's line, column and
 * offset) then DATA (the result, or the diag's file and text when the cell
 * failed). */
enum { CLI_MPI_TAG_WORK = 1, CLI_MPI_TAG_STOP = 2, CLI_MPI_TAG_META = 3, CLI_MPI_TAG_DATA = 4 };
enum { CLI_MPI_META_CELL, CLI_MPI_META_STATUS, CLI_MPI_META_LEN, CLI_MPI_META_LINE,
       CLI_MPI_META_COL, CLI_MPI_META_OFFSET, CLI_MPI_META_N };

int cli_mpi_start(int *argc, char ***argv)
{
    int provided;
    /* Only under a launcher: a plain run must not pay for (or depend on)
     * MPI's start-up. */
    if (!getenv("OMPI_COMM_WORLD_SIZE") && !getenv("PMIX_RANK") && !getenv("PMI_RANK"))
        return 0;
    /* Threads render, only the main thread talks to other ranks. */
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "maprt: error: MPI did not start\n");
        return -1;
    }
    cli_mpi_on = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &cli_mpi_me);
    MPI_Comm_size(MPI_COMM_WORLD, &cli_mpi_n);
    if (cli_mpi_n > CLI_MPI_MAX_RANKS) {
        if (cli_mpi_me == 0)
            fprintf(stderr, "maprt: error: %d MPI ranks; at most %d are supported\n", cli_mpi_n,
                    CLI_MPI_MAX_RANKS);
        MPI_Finalize();
        cli_mpi_on = 0;
        return -1;
    }
    return 0;
}

void cli_mpi_stop(void)
{
    if (cli_mpi_on)
        MPI_Finalize();
    cli_mpi_on = 0;
}

int cli_mpi_rank(void) { return cli_mpi_me; }
int cli_mpi_size(void) { return cli_mpi_n; }

void cli_mpi_fail(const diag *d, int status)
{
    char buf[1024];
    if (!cli_mpi_on || cli_mpi_n < 2)
        return;
    diag_format(d, buf, sizeof buf);
    fprintf(stderr, "maprt: rank %d: %s\n", cli_mpi_me, buf);
    fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status);
}

int cli_mpi_agree(int status, int *root)
{
    int worst = status, r0 = status;
    if (cli_mpi_on && cli_mpi_n > 1) {
        MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        MPI_Bcast(&r0, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }
    if (root)
        *root = r0;
    return worst;
}

/* What a render's bands share: the job, this rank's own counters, and on
 * rank 0 the whole frame being assembled. */
typedef struct cli_mpi_bands {
    const scene *sc;
    const render_ops *ops;
    const render_opts *o;     /* the whole image's size filled in */
    render_stats mine;        /* the bands this rank rendered */
    render_fb *out;           /* rank 0: the frame, its coverage, the sums */
    uint8_t *covered;
    render_stats *total;
    cli_mpi_share *share;
    long done;
    double t0;
} cli_mpi_bands;

/* Band b: rows [b*RENDER_TILE, ...) of the whole width. */
static void cli_mpi_band(const render_opts *o, int b, int r[4])
{
    r[0] = 0;
    r[1] = b * RENDER_TILE;
    r[2] = o->width;
    r[3] = r[1] + RENDER_TILE < o->height ? r[1] + RENDER_TILE : o->height;
}

/* Renders band b on this rank and encodes it (with the identity map when
 * the render asks for one). */
static int cli_mpi_band_run(void *ctx, int b, uint8_t **buf, size_t *len, diag *err)
{
    cli_mpi_bands *j = ctx;
    render_opts bo = *j->o;
    render_fb fb;
    render_part_info info;
    int st;
    bo.progress = NULL;
    cli_mpi_band(j->o, b, bo.region);
    memset(&info, 0, sizeof info);
    if ((st = render_scene(j->sc, j->ops, &bo, &fb, &info.stats, err)) != 0)
        return st;
    info.width = bo.width;
    info.height = bo.height;
    memcpy(info.region, bo.region, sizeof info.region);
    info.aa = bo.aa;
    info.ids = bo.ids;
    strncpy(info.mode, j->ops->name, sizeof info.mode - 1);
    st = render_part_encode(&fb, &info, buf, len, err);
    render_fb_free(&fb);
    if (!st)
        render_stats_add(&j->mine, &info.stats);
    return st;
}

/* Rank 0: places one band into the whole frame, adds its counters to the
 * sums and to the share of the rank that rendered it, shows progress. */
static int cli_mpi_band_take(void *ctx, int b, int rank, const uint8_t *buf, size_t len, diag *err)
{
    cli_mpi_bands *j = ctx;
    render_part_info info;
    int st;
    (void)b;
    if ((st = render_part_decode("MPI band", buf, len, &info, err)) != 0
        || (st = render_part_place("MPI band", buf, &info, j->out, j->covered, err)) != 0)
        return st;
    render_stats_add(j->total, &info.stats);
    if (j->share) {
        j->share[rank].bands++;
        j->share[rank].rays += info.stats.rays_primary + info.stats.rays_shadow +
                               info.stats.rays_reflected + info.stats.rays_refracted;
    }
    j->done++;
    if (j->o->progress) {
        /* bands finished: a band's cost is not known ahead, so the fraction
         * counts bands (docs/cluster.md) */
        render_progress pr;
        long nb = (j->o->height + RENDER_TILE - 1) / RENDER_TILE;
        long tiles_per_band = (j->o->width + RENDER_TILE - 1) / RENDER_TILE;
        pr.tiles_done = j->done * tiles_per_band;
        pr.tiles = nb * tiles_per_band;
        pr.fraction = (double)j->done / nb;
        pr.elapsed_s = MPI_Wtime() - j->t0;
        pr.rays = j->total->rays_primary + j->total->rays_shadow + j->total->rays_reflected +
                  j->total->rays_refracted;
        j->o->progress(j->o->progress_ctx, &pr);
    }
    return 0;
}

/* Waiting without spinning: Open MPI's blocking calls poll the CPU, which
 * on an oversubscribed node takes the core from a rank that renders (with
 * blocking calls two ranks on two cores cost 60% more CPU than one and ran
 * slower). A nap grows from 16 us to 1 ms, a rank that waits wakes at most
 * a thousand times a second. */
static void cli_mpi_nap(long *us)
{
    struct timespec ts;
    ts.tv_sec = 0;
    ts.tv_nsec = *us * 1000;
    nanosleep(&ts, NULL);
    if (*us < 1000)
        *us *= 2;
}

static void cli_mpi_probe(int src, int tag, MPI_Status *ms)
{
    long us = 16;
    int flag = 0;
    for (MPI_Iprobe(src, tag, MPI_COMM_WORLD, &flag, ms); !flag;
         MPI_Iprobe(src, tag, MPI_COMM_WORLD, &flag, ms))
        cli_mpi_nap(&us);
}

/* A result on its way to rank 0: sent without blocking, so that the rank
 * renders its next cell before rank 0 has received the last. */
typedef struct cli_mpi_out {
    long long meta[CLI_MPI_META_N];
    char text[sizeof ((diag *)0)->file + sizeof ((diag *)0)->msg];
    uint8_t *buf;             /* the result (mem_alloc'd), NULL when text goes */
    MPI_Request req[2];
    int busy;
} cli_mpi_out;

/* Waits until the result in flight has left, and frees it. */
static void cli_mpi_out_done(cli_mpi_out *o)
{
    long us = 16;
    int flag = 0;
    if (!o->busy)
        return;
    for (MPI_Testall(2, o->req, &flag, MPI_STATUSES_IGNORE); !flag;
         MPI_Testall(2, o->req, &flag, MPI_STATUSES_IGNORE))
        cli_mpi_nap(&us);
    mem_free(o->buf);
    o->buf = NULL;
    o->busy = 0;
}

/* A rank other than 0: runs the cells rank 0 sends until told to stop, and
 * sends back each result, or the diag of a cell that failed. */
static void cli_mpi_farm_worker(const cli_mpi_farm *f)
{
    cli_mpi_out out;
    memset(&out, 0, sizeof out);
    for (;;) {
        MPI_Status ms;
        uint8_t *buf = NULL;
        const void *data;
        size_t len = 0;
        diag err;
        int c, st;
        cli_mpi_probe(0, MPI_ANY_TAG, &ms);
        MPI_Recv(&c, 1, MPI_INT, 0, ms.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (ms.MPI_TAG == CLI_MPI_TAG_STOP)
            break;
        diag_init(&err);
        st = f->run(f->ctx, c, &buf, &len, &err);
        if (!st && len > INT_MAX)
            st = diag_at(&err, DIAG_IO, "", 0, 0, "a result of %zu bytes is too large to send", len);
        cli_mpi_out_done(&out);
        if (st) {
            size_t nf = strlen(err.file) + 1;
            mem_free(buf);
            memcpy(out.text, err.file, nf);
            memcpy(out.text + nf, err.msg, strlen(err.msg) + 1);
            data = out.text;
            len = nf + strlen(err.msg) + 1;
        } else {
            out.buf = buf;
            data = buf;
        }
        out.meta[CLI_MPI_META_CELL] = c;
        out.meta[CLI_MPI_META_STATUS] = st;
        out.meta[CLI_MPI_META_LEN] = (long long)len;
        out.meta[CLI_MPI_META_LINE] = err.line;
        out.meta[CLI_MPI_META_COL] = err.col;
        out.meta[CLI_MPI_META_OFFSET] = err.offset;
        MPI_Isend(out.meta, CLI_MPI_META_N, MPI_LONG_LONG, 0, CLI_MPI_TAG_META, MPI_COMM_WORLD,
                  &out.req[0]);
        MPI_Isend((void *)data, (int)len, MPI_BYTE, 0, CLI_MPI_TAG_DATA, MPI_COMM_WORLD, &out.req[1]);
        out.busy = 1;
    }
    cli_mpi_out_done(&out);
}

/* Rank 0: receives one result from src and takes it, or records its
 * failure in *failed and *err (the first failure only). */
static void cli_mpi_farm_recv(const cli_mpi_farm *f, int src, int *failed, diag *err)
{
    long long meta[CLI_MPI_META_N];
    uint8_t *buf;
    int len, st;
    MPI_Recv(meta, CLI_MPI_META_N, MPI_LONG_LONG, src, CLI_MPI_TAG_META, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    len = (int)meta[CLI_MPI_META_LEN];
    if (!(buf = mem_alloc(len > 0 ? (size_t)len : 1))) {
        diag_at(err, DIAG_IO, "", 0, 0, "out of memory for a result of %d bytes from rank %d",
                len, src);
        cli_mpi_fail(err, DIAG_IO);
    }
    MPI_Recv(buf, len, MPI_BYTE, src, CLI_MPI_TAG_DATA, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    st = (int)meta[CLI_MPI_META_STATUS];
    if (!st) {
        /* taken even after a failure, as one process would have taken the
         * cells before the one that failed */
        st = f->take(f->ctx, (int)meta[CLI_MPI_META_CELL], src, buf, (size_t)len, err);
        if (!*failed)
            *failed = st;
    } else if (!*failed) {     /* only the first failure is reported */
        const char *file = (const char *)buf, *msg = file + strlen(file) + 1;
        if (meta[CLI_MPI_META_OFFSET] >= 0)
            diag_offset(err, st, file, meta[CLI_MPI_META_OFFSET], "%s (on MPI rank %d)", msg, src);
        else
            diag_at(err, st, file, (long)meta[CLI_MPI_META_LINE], (long)meta[CLI_MPI_META_COL],
                    "%s (on MPI rank %d)", msg, src);
        *failed = st;
    }
    mem_free(buf);
}

/* Rank 0's own cell, run on a thread of its own so that the main thread
 * keeps answering the other ranks however long the cell takes (a bench
 * cell in hfp32 can take fifty times one in f64). Only the main thread
 * calls MPI (MPI_THREAD_FUNNELED) and take; the cell's thread only runs. */
typedef struct cli_mpi_local {
    const cli_mpi_farm *f;
    int cell, status, busy, done;
    uint8_t *buf;
    size_t len;
    diag err;
    pthread_t thread;
    pthread_mutex_t lock;
} cli_mpi_local;

static void *cli_mpi_local_main(void *arg)
{
    cli_mpi_local *l = arg;
    int st = l->f->run(l->f->ctx, l->cell, &l->buf, &l->len, &l->err);
    pthread_mutex_lock(&l->lock);
    l->status = st;
    l->done = 1;
    pthread_mutex_unlock(&l->lock);
    return NULL;
}

/* Starts cell c on the thread; 0, or -1 when no thread could start (then
 * the caller runs it itself). */
static int cli_mpi_local_start(cli_mpi_local *l, int c)
{
    l->cell = c;
    l->buf = NULL;
    l->len = 0;
    l->status = l->done = 0;
    diag_init(&l->err);
    if (pthread_create(&l->thread, NULL, cli_mpi_local_main, l))
        return -1;
    l->busy = 1;
    return 0;
}

/* When the thread's cell is done: joins it and takes the result (or records
 * its failure in *failed and *err, unless one is recorded). 1 if it was. */
static int cli_mpi_local_finish(cli_mpi_local *l, int *failed, diag *err)
{
    int done, st;
    pthread_mutex_lock(&l->lock);
    done = l->done;
    pthread_mutex_unlock(&l->lock);
    if (!l->busy || !done)
        return 0;
    pthread_join(l->thread, NULL);
    l->busy = 0;
    st = l->status ? l->status : l->f->take(l->f->ctx, l->cell, 0, l->buf, l->len, err);
    if (l->status && !*failed)
        *err = l->err;
    if (!*failed)
        *failed = st;
    mem_free(l->buf);
    return 1;
}

int cli_mpi_farm_run(const cli_mpi_farm *f, diag *err)
{
    cli_mpi_local local;
    int *outstanding, next = 0, inflight = 0, failed = 0, r;
    long us = 16;
    if (!cli_mpi_on || cli_mpi_n < 2)
        return cli_mpi_farm_local(f, err);
    if (cli_mpi_me != 0) {
        cli_mpi_farm_worker(f);
        return 0;
    }
    if (!(outstanding = mem_calloc((size_t)cli_mpi_n, sizeof *outstanding))) {
        diag_at(err, DIAG_IO, "", 0, 0, "out of memory for %d ranks", cli_mpi_n);
        cli_mpi_fail(err, DIAG_IO);
    }
    memset(&local, 0, sizeof local);
    local.f = f;
    pthread_mutex_init(&local.lock, NULL);
    for (r = 1; r < cli_mpi_n; r++) {
        for (; outstanding[r] < 2 && next < f->cells; next++, outstanding[r]++, inflight++)
            MPI_Send(&next, 1, MPI_INT, r, CLI_MPI_TAG_WORK, MPI_COMM_WORLD);
        if (!outstanding[r])
            MPI_Send(&next, 1, MPI_INT, r, CLI_MPI_TAG_STOP, MPI_COMM_WORLD);
    }
    while (inflight || local.busy || (!failed && next < f->cells)) {
        MPI_Status ms;
        int flag = 0;
        if (!local.busy && !failed && next < f->cells) {
            if (cli_mpi_local_start(&local, next) == 0) {
                next++;
            } else {
                /* no thread: the cell runs here, the others wait */
                uint8_t *buf = NULL;
                size_t len = 0;
                int c = next++;
                if ((failed = f->run(f->ctx, c, &buf, &len, err)) == 0)
                    failed = f->take(f->ctx, c, 0, buf, len, err);
                mem_free(buf);
            }
            continue;
        }
        if (inflight)
            MPI_Iprobe(MPI_ANY_SOURCE, CLI_MPI_TAG_META, MPI_COMM_WORLD, &flag, &ms);
        if (flag) {
            int src = ms.MPI_SOURCE;
            cli_mpi_farm_recv(f, src, &failed, err);
            outstanding[src]--;
            inflight--;
            if (!failed && next < f->cells) {
                MPI_Send(&next, 1, MPI_INT, src, CLI_MPI_TAG_WORK, MPI_COMM_WORLD);
                next++;
                outstanding[src]++;
                inflight++;
            } else if (!outstanding[src]) {
                MPI_Send(&next, 1, MPI_INT, src, CLI_MPI_TAG_STOP, MPI_COMM_WORLD);
            }
            us = 16;
        } else if (cli_mpi_local_finish(&local, &failed, err)) {
            us = 16;
        } else {
            cli_mpi_nap(&us);
        }
    }
    pthread_mutex_destroy(&local.lock);
    mem_free(outstanding);
    return failed;
}

int cli_mpi_render(const scene *sc, const render_ops *ops, const render_opts *o, render_fb *fb,
                   render_stats *st, cli_mpi_share *share, diag *err)
{
    render_opts opt = *o;
    render_stats total;
    render_fb out;
    cli_mpi_bands job;
    cli_mpi_farm farm;
    void *cs = NULL;
    int status;
    if (!cli_mpi_on || cli_mpi_n < 2)
        return render_scene(sc, ops, o, fb, st, err);
    opt.skip_pid = 0;                 /* the bands carry their PIDs to rank 0 */
    if (!opt.width || !opt.height) {
        opt.width = sc->view.width;
        opt.height = sc->view.height;
    }
    /* Every rank compiles once first and they agree, so a scene refused at
     * compile time fails the same way everywhere, with one message. */
    memset(&job, 0, sizeof job);
    job.t0 = MPI_Wtime();
    status = opt.region[2] ? diag_at(err, DIAG_USAGE, "", 0, 0, "--region is for single-process "
                                     "renders; under mpirun the ranks share the whole image")
                           : ops->compile(sc, &cs, err);
    if (cs)
        ops->free(cs);
    if ((status = cli_mpi_agree(status, NULL)) != 0) {
        if (!err->status)
            diag_at(err, status, sc->source ? sc->source : "", 0, 0,
                    "another rank could not compile the scene");
        return status;
    }
    memset(&total, 0, sizeof total);
    memset(&out, 0, sizeof out);
    total.time_compile_s = MPI_Wtime() - job.t0;
    job.t0 = MPI_Wtime();
    job.sc = sc;
    job.ops = ops;
    job.o = &opt;
    if (cli_mpi_me == 0) {
        if ((status = image_alloc(&out.img, opt.width, opt.height, 3, "render", err)) != 0
            || (opt.ids && (status = idmap_alloc(&out.ids, opt.width, opt.height, err)) != 0))
            cli_mpi_fail(err, status);
        out.pid = mem_calloc((size_t)opt.width * (size_t)opt.height, sizeof *out.pid);
        job.covered = mem_calloc((size_t)opt.width * (size_t)opt.height, 1);
        if (!out.pid || !job.covered) {
            diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the framebuffer");
            cli_mpi_fail(err, DIAG_IO);
        }
        if (share)
            memset(share, 0, (size_t)cli_mpi_n * sizeof *share);
        job.out = &out;
        job.total = &total;
        job.share = share;
    }
    memset(&farm, 0, sizeof farm);
    farm.cells = (opt.height + RENDER_TILE - 1) / RENDER_TILE;
    farm.run = cli_mpi_band_run;
    farm.take = cli_mpi_band_take;
    farm.ctx = &job;
    status = cli_mpi_farm_run(&farm, err);
    mem_free(job.covered);
    if ((status = cli_mpi_agree(status, NULL)) != 0) {
        render_fb_free(&out);
        if (!err->status)
            diag_at(err, status, sc->source ? sc->source : "", 0, 0,
                    "another rank could not render its bands");
        return status;
    }
    if (cli_mpi_me != 0) {
        job.mine.time_compile_s = total.time_compile_s;
        total = job.mine;
        total.time_render_s = MPI_Wtime() - job.t0;
        memset(fb, 0, sizeof *fb);
    } else {
        total.time_render_s = MPI_Wtime() - job.t0;
        *fb = out;
    }
    *st = total;
    return 0;
}
#else
/* A launcher's world size (Open MPI, PMI), or 1. */
static long cli_mpi_launched_ranks(void)
{
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"};
    size_t i;
    for (i = 0; i < sizeof vars / sizeof vars[0]; i++) {
        const char *v = getenv(vars[i]);
        long n = v ? strtol(v, NULL, 10) : 0;
        if (n > 1)
            return n;
    }
    return 1;
}

/* Started as one of several ranks, this build would have each rank do the
 * whole job and write the same files: it refuses and names the one that
 * shares the work. */
int cli_mpi_start(int *argc, char ***argv)
{
    long n = cli_mpi_launched_ranks();
    (void)argc;
    (void)argv;
    if (n > 1) {
        fprintf(stderr, "maprt: error: started as one of %ld MPI ranks, but this maprt is built without MPI; "
                        "run maprt-mpi under mpirun (docs/cluster.md)\n", n);
        return -1;
    }
    return 0;
}
void cli_mpi_stop(void) {}
int cli_mpi_rank(void) { return 0; }
int cli_mpi_size(void) { return 1; }
void cli_mpi_fail(const diag *d, int status)
{
    (void)d;
    (void)status;
}
int cli_mpi_agree(int status, int *root)
{
    if (root)
        *root = status;
    return status;
}
int cli_mpi_farm_run(const cli_mpi_farm *f, diag *err) { return cli_mpi_farm_local(f, err); }
int cli_mpi_render(const scene *sc, const render_ops *ops, const render_opts *o, render_fb *fb,
                   render_stats *st, cli_mpi_share *share, diag *err)
{
    (void)share;
    return render_scene(sc, ops, o, fb, st, err);
}
#endif

void cli_mpi_print_shares(FILE *f, const cli_mpi_share *share, int n)
{
    int r;
    fprintf(f, "mpi.ranks=%d\n", n);
    for (r = 0; share && r < n; r++)
        fprintf(f, "mpi.rank%d.bands=%ld\nmpi.rank%d.rays=%llu\n", r, share[r].bands, r,
                share[r].rays);
}
