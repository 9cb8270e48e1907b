/* cli_mpi — distributed renders over MPI ranks (see cli_mpi.h). */
#include "cli/cli_mpi.h"
#include "render/render_part.h"
#include "util/mem.h"
#include <stdlib.h>
#include <string.h>
#ifdef MAPRT_MPI
#include <mpi.h>
#include <omp.h>
#endif

#ifdef MAPRT_MPI
static int cli_mpi_on, cli_mpi_me, cli_mpi_n = 1;

enum { CLI_MPI_TAG_WORK = 1, CLI_MPI_TAG_STOP = 2, CLI_MPI_TAG_RESULT = 3 };

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

/* Band b: rows [b*RENDER_TILE, ...) of the whole width. */
static void cli_mpi_band(const render_opts *o, int b, int r[4])
{
    r[0] = 0;
    r[1] = b * RENDER_TILE;
    r[2] = o->width;
    r[3] = r[1] + RENDER_TILE < o->height ? r[1] + RENDER_TILE : o->height;
}

/* Renders band b on this rank and encodes it; aborts the job on failure. */
static void cli_mpi_render_band(const scene *sc, const render_ops *ops, const render_opts *o, int b,
                                uint8_t **buf, size_t *len, render_stats *mine)
{
    render_opts bo = *o;
    render_fb fb;
    render_part_info info;
    diag err;
    int st;
    diag_init(&err);
    bo.progress = NULL;
    cli_mpi_band(o, b, bo.region);
    memset(&info, 0, sizeof info);
    if ((st = render_scene(sc, ops, &bo, &fb, &info.stats, &err)) != 0)
        cli_mpi_fail(&err, st);
    info.width = o->width;
    info.height = o->height;
    memcpy(info.region, bo.region, sizeof info.region);
    info.aa = o->aa;
    strncpy(info.mode, ops->name, sizeof info.mode - 1);
    st = render_part_encode(&fb, &info, buf, len, &err);
    render_fb_free(&fb);
    if (st)
        cli_mpi_fail(&err, st);
    render_stats_add(mine, &info.stats);
}

static void cli_mpi_worker(const scene *sc, const render_ops *ops, const render_opts *o,
                           render_stats *st)
{
    for (;;) {
        MPI_Status ms;
        int b;
        uint8_t *buf;
        size_t len;
        MPI_Recv(&b, 1, MPI_INT, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &ms);
        if (ms.MPI_TAG == CLI_MPI_TAG_STOP)
            return;
        cli_mpi_render_band(sc, ops, o, b, &buf, &len, st);
        MPI_Send(buf, (int)len, MPI_BYTE, 0, CLI_MPI_TAG_RESULT, MPI_COMM_WORLD);
        mem_free(buf);
    }
}

/* Places one encoded band into the whole frame; aborts on a malformed one
 * (it came from another rank of the same binary, so that is a fault). */
static void cli_mpi_place(const uint8_t *buf, size_t len, render_fb *fb, uint8_t *covered,
                          render_stats *total, cli_mpi_share *share)
{
    render_part_info info;
    diag err;
    diag_init(&err);
    if (render_part_decode("MPI band", buf, len, &info, &err) ||
        render_part_place("MPI band", buf, &info, fb, covered, &err))
        cli_mpi_fail(&err, DIAG_IO);
    render_stats_add(total, &info.stats);
    if (share) {
        share->bands++;
        share->rays += info.stats.rays_primary + info.stats.rays_shadow +
                       info.stats.rays_reflected + info.stats.rays_refracted;
    }
}

int cli_mpi_render(const scene *sc, const render_ops *ops, const render_opts *o, render_fb *fb,
                   render_stats *st, cli_mpi_share *share, diag *err)
{
    render_opts opt = *o;
    render_stats total;
    render_fb out;
    uint8_t *covered = NULL, *buf = NULL;
    int *outstanding = NULL, nb, next = 0, done = 0, r, status;
    void *cs = NULL;
    double t0;
    if (!cli_mpi_on || cli_mpi_n < 2)
        return render_scene(sc, ops, o, fb, st, err);
    if (!opt.width || !opt.height) {
        opt.width = sc->view.width;
        opt.height = sc->view.height;
    }
    /* Every rank compiles once first and they agree, so a scene refused at
     * compile time fails the same way everywhere, with one message. */
    t0 = MPI_Wtime();
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
    total.time_compile_s = MPI_Wtime() - t0;
    t0 = MPI_Wtime();
    nb = (opt.height + RENDER_TILE - 1) / RENDER_TILE;
    if (cli_mpi_me != 0) {
        cli_mpi_worker(sc, ops, &opt, &total);
        memset(fb, 0, sizeof *fb);
        total.time_render_s = MPI_Wtime() - t0;
        *st = total;
        return 0;
    }
    memset(&out, 0, sizeof out);
    if ((status = image_alloc(&out.img, opt.width, opt.height, 3, "render", err)) != 0)
        cli_mpi_fail(err, status);
    out.pid = mem_calloc((size_t)opt.width * (size_t)opt.height, sizeof *out.pid);
    covered = mem_calloc((size_t)opt.width * (size_t)opt.height, 1);
    outstanding = mem_calloc((size_t)cli_mpi_n, sizeof *outstanding);
    if (!out.pid || !covered || !outstanding) {
        diag_at(err, DIAG_IO, "", 0, 0, "out of memory for the framebuffer");
        cli_mpi_fail(err, DIAG_IO);
    }
    if (share)
        memset(share, 0, (size_t)cli_mpi_n * sizeof *share);
    /* Two bands in flight per worker, so it never waits for rank 0, which
     * renders bands of its own between messages. */
    for (r = 1; r < cli_mpi_n; r++) {
        int k;
        for (k = 0; k < 2 && next < nb; k++, next++, outstanding[r]++)
            MPI_Send(&next, 1, MPI_INT, r, CLI_MPI_TAG_WORK, MPI_COMM_WORLD);
        if (!outstanding[r])
            MPI_Send(&next, 1, MPI_INT, r, CLI_MPI_TAG_STOP, MPI_COMM_WORLD);
    }
    while (done < nb) {
        MPI_Status ms;
        int flag = 0, count;
        size_t len;
        if (next < nb)
            MPI_Iprobe(MPI_ANY_SOURCE, CLI_MPI_TAG_RESULT, MPI_COMM_WORLD, &flag, &ms);
        else
            MPI_Probe(MPI_ANY_SOURCE, CLI_MPI_TAG_RESULT, MPI_COMM_WORLD, &ms), flag = 1;
        if (flag) {
            int src = ms.MPI_SOURCE;
            MPI_Get_count(&ms, MPI_BYTE, &count);
            buf = mem_alloc((size_t)count);
            if (!buf) {
                diag_at(err, DIAG_IO, "", 0, 0, "out of memory for a band");
                cli_mpi_fail(err, DIAG_IO);
            }
            MPI_Recv(buf, count, MPI_BYTE, src, CLI_MPI_TAG_RESULT, MPI_COMM_WORLD, &ms);
            cli_mpi_place(buf, (size_t)count, &out, covered, &total, share ? &share[src] : NULL);
            mem_free(buf);
            outstanding[src]--;
            if (next < nb) {
                MPI_Send(&next, 1, MPI_INT, src, CLI_MPI_TAG_WORK, MPI_COMM_WORLD);
                next++;
                outstanding[src]++;
            } else if (!outstanding[src]) {
                MPI_Send(&next, 1, MPI_INT, src, CLI_MPI_TAG_STOP, MPI_COMM_WORLD);
            }
        } else {
            render_stats mine;
            memset(&mine, 0, sizeof mine);
            cli_mpi_render_band(sc, ops, &opt, next++, &buf, &len, &mine);
            cli_mpi_place(buf, len, &out, covered, &total, share ? &share[0] : NULL);
            mem_free(buf);
        }
        done++;
        if (opt.progress) {
            /* bands finished: a band's cost is not known ahead, so the
             * fraction counts bands (docs/cluster.md) */
            render_progress pr;
            long tiles_per_band = (opt.width + RENDER_TILE - 1) / RENDER_TILE;
            pr.tiles_done = done * tiles_per_band;
            pr.tiles = nb * tiles_per_band;
            pr.fraction = (double)done / nb;
            pr.elapsed_s = MPI_Wtime() - t0;
            pr.rays = total.rays_primary + total.rays_shadow + total.rays_reflected +
                      total.rays_refracted;
            opt.progress(opt.progress_ctx, &pr);
        }
    }
    total.time_render_s = MPI_Wtime() - t0;
    mem_free(covered);
    mem_free(outstanding);
    *fb = out;
    *st = total;
    return 0;
}
#else
int cli_mpi_start(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
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
