/* cmd_bench — `maprt bench`: renders each scene in each numeric mode N
 * times and reports, per scene and mode, the median render time, rays/s,
 * the error against the scene's f64 render (PSNR) and, with --oracle,
 * against the REAL(16) oracle's identity map (pixels whose primitive, face
 * or region differs; hit distance error). Output: a table on stdout,
 * optional CSV and a Pareto chart drawn by gnuplot. gnuplot is run
 * without a shell and sees numbers and labels of a fixed alphabet only:
 * scenes are named S1, S2, ... in the chart (the table and the CSV say
 * which is which), and the PNG comes back on its standard output.
 * Each (scene, mode) is a cell of cli_mpi's farm: under mpirun the cells
 * spread over the ranks, each timed where it ran, and rank 0 prints and
 * writes the rows in the order one process would. */
#include "cli/cli.h"
#include "cli/cli_scene.h"
#include "image/image_diff.h"
#include "cli/cli_idcheck.h"
#include "cli/cli_mpi.h"
#include "render/render.h"
#include "util/cpubind.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#define BENCH_MAX_MODES 6
#define BENCH_MAX_RUNS 99

typedef struct bench_row {
    const char *scene, *mode;
    int scene_no, threads, runs, has_ids, rank;   /* rank: the MPI rank that ran it */
    double seconds, rays_per_s, psnr, pct_over2;
    double id_pct, err_median, err_max;
    long id_compared, id_flagged, id_mismatch;
    unsigned long long rays, overflows, range_cut, hfp_exc;
} bench_row;

static void cmd_bench_help(FILE *f)
{
    fprintf(f,
        "usage: maprt bench SCENE... [options]\n"
        "\n"
        "Renders every SCENE in every numeric mode N times and prints per scene and\n"
        "mode: the median wall-clock render seconds of the N runs, rays/s (all rays:\n"
        "primary, shadow, reflected, refracted), the error against the same scene\n"
        "rendered in f64 (PSNR in dB, inf when identical, and the %% of pixels where\n"
        "a channel differs by more than 2/255), the fixed-point overflows and primary\n"
        "rays beyond the mode's range, and with --oracle the pixels whose primitive,\n"
        "face or region differs from the REAL(16) oracle's (its ambiguous pixels not\n"
        "counted) and the hit distance error against it, median and largest, in deck\n"
        "units (docs/idmap.md).\n"
        "\n"
        "options:\n"
        "  --size WxH        image size, 1..%d each (default: each deck's SIZE)\n"
        "  --modes LIST      comma-separated modes out of q16,q32,f32,f64,hfp32,hfp64\n"
        "                    (default: all)\n"
        "  --runs N          timed renders per scene and mode, 1..%d (default 3)\n"
        "  --threads N       worker threads, 1..%d (default: OpenMP's count, %d here);\n"
        "                    as many as the CPUs are kept on one CPU each (as render)\n"
        "  --oracle PATH     the ids_oracle executable (make builds build/oracle/ids_oracle)\n"
        "  --csv OUT.csv     also write the rows as CSV with a header line; its last\n"
        "                    column, rank, is the MPI rank that ran the row (0 in a\n"
        "                    single process)\n"
        "  --plot OUT.png    Pareto chart with gnuplot: median seconds against the %% of\n"
        "                    pixels that differ from the oracle (needs --oracle; else\n"
        "                    against the %% over 2/255 from f64), both axes logarithmic;\n"
        "                    scenes are labelled S1, S2, ... in the order given\n"
        "                    (an error, exit 3, when gnuplot is not installed)\n"
        "  -h, --help        show this help\n"
        "\n"
        "Timings depend on machine load; the median of N runs damps the noise.\n"
        "They are of the tracer's x86-64-v3 build where the processor runs it\n"
        "('maprt render --isa'); the f64 reference is rendered by the baseline.\n"
        "Under 'mpirun -n N maprt-mpi bench' the (scene, mode) cells are handed\n"
        "out to the ranks, each rank renders its cells' N runs with --threads\n"
        "threads, and rank 0 prints and writes the rows in the order above; the\n"
        "outputs are written all or none, and none when a cell or a rank fails.\n"
        "exit status: 0 ok, 1 bad scene, 2 usage, 3 I/O or internal failure\n",
        SCENE_MAX_SIDE, BENCH_MAX_RUNS, RENDER_MAX_THREADS, omp_get_max_threads());
}

/* Writes s as one CSV field (RFC 4180: quoted, quotes doubled). */
static int cmd_bench_csv_field(outfile *of, const char *s, diag *err)
{
    char buf[2];
    if (!strpbrk(s, ",\"\r\n"))
        return outfile_write(of, s, strlen(s), err);
    outfile_write(of, "\"", 1, err);
    for (; *s; s++) {
        buf[0] = *s;
        if (*s == '"')
            outfile_write(of, "\"", 1, err);
        outfile_write(of, buf, 1, err);
    }
    return outfile_write(of, "\"", 1, err);
}

/* Writes the rows as CSV with a header line, committed on close. */
static int cmd_bench_csv(const char *path, const bench_row *rows, int n)
{
    outfile of;
    diag err;
    char line[768];
    int i;
    diag_init(&err);
    if (outfile_open(&of, path, &err))
        goto fail;
    snprintf(line, sizeof line, "scene,label,mode,threads,runs,seconds_median,rays,rays_per_s,psnr_db,"
                                "pct_pixels_over_2,fx_overflows,range_cut,hfp_exceptions,id_compared,id_flagged,"
                                "id_mismatch,id_mismatch_pct,hit_err_median,hit_err_max,rank\n");
    outfile_write(&of, line, strlen(line), &err);
    for (i = 0; i < n; i++) {
        const bench_row *r = &rows[i];
        cmd_bench_csv_field(&of, r->scene, &err);
        snprintf(line, sizeof line, ",S%d,%s,%d,%d,%.6f,%llu,%.0f,%.3f,%.4f,%llu,%llu,%llu",
                 r->scene_no, r->mode, r->threads, r->runs, r->seconds, r->rays, r->rays_per_s,
                 r->psnr, r->pct_over2, r->overflows, r->range_cut, r->hfp_exc);
        outfile_write(&of, line, strlen(line), &err);
        if (r->has_ids)
            snprintf(line, sizeof line, ",%ld,%ld,%ld,%.4f,%.3g,%.3g,%d\n", r->id_compared,
                     r->id_flagged, r->id_mismatch, r->id_pct, r->err_median, r->err_max, r->rank);
        else
            snprintf(line, sizeof line, ",,,,,,,%d\n", r->rank);
        outfile_write(&of, line, strlen(line), &err);
    }
    if (outfile_commit(&of, &err))
        goto fail;
    return CLI_OK;
fail:
    outfile_abort(&of);
    diag_print(stderr, &err);
    return CLI_IO;
}

/* The chart's y value of a row: % of pixels off, floored at a tenth of one
 * pixel so that a perfect run stays on the logarithmic axis. */
static double cmd_bench_y(const bench_row *r, int ids)
{
    double floor_pct = 10.0 / (r->id_compared > 0 ? (double)r->id_compared : 1e6);
    double y = ids ? r->id_pct : r->pct_over2;
    return y > floor_pct ? y : floor_pct;
}

/* The gnuplot script: fixed text, numbers, and labels "S<n> <mode>". */
static void cmd_bench_script(FILE *gp, const bench_row *rows, int n, int ids)
{
    int i;
    fprintf(gp, "set terminal pngcairo size 1000,700 noenhanced font ',11'\n"
                "set logscale xy\nset grid xtics ytics mxtics mytics\n"
                "set format x '%%g'\nset format y '%%g'\n"
                "set xlabel 'median render seconds (log)'\n"
                "set ylabel \"%s\\n(log; none drawn at 0.1 pixel)\"\n"
                "set title 'maprt bench: time against error, per scene (S1, S2, ...) and mode'\n"
                "set key outside right top\nset offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1\n"
                "$d << EOD\n",
            ids ? "% of pixels whose primitive, face or region\\ndiffers from the REAL(16) oracle"
                : "% of pixels over 2/255 from f64");
    for (i = 0; i < n; i++)
        fprintf(gp, "%.9g %.9g S%d_%s %d\n", rows[i].seconds > 0 ? rows[i].seconds : 1e-6,
                cmd_bench_y(&rows[i], ids), rows[i].scene_no, rows[i].mode,
                !strcmp(rows[i].mode, "q16") ? 0 : !strcmp(rows[i].mode, "q32") ? 1
                : !strcmp(rows[i].mode, "f32") ? 2 : 3);
    /* one colour per mode; labels alternate above and below the point so
     * that neighbours (f32 and f64 are often close) stay apart */
    fprintf(gp, "EOD\nplot for [m=0:3] $d using ($4==m ? $1 : NaN):2 with points pt 7 ps 1.5 "
                "title word('q16 q32 f32 f64', m+1), \\\n"
                "     $d using 1:2:3 every 2 with labels offset 0,1.2 notitle, \\\n"
                "     $d using 1:2:3 every 2::1 with labels offset 0,-1.2 notitle\n");
}

/* Runs gnuplot (found on PATH, no shell) with the chart script on its
 * standard input and its standard output into the PNG, committed only when
 * gnuplot succeeds. CLI_OK or CLI_IO. */
static int cmd_bench_plot(const char *out, const bench_row *rows, int n, int ids)
{
    outfile of;
    diag err;
    int fds[2], status = -1;
    pid_t pid;
    FILE *gp;
    diag_init(&err);
    if (outfile_open(&of, out, &err)) {
        diag_print(stderr, &err);
        return CLI_IO;
    }
    fflush(of.f);
    if (pipe(fds) != 0) {
        outfile_abort(&of);
        fprintf(stderr, "maprt: %s: error: cannot run gnuplot\n", out);
        return CLI_IO;
    }
    pid = fork();
    if (pid == 0) {
        char *argv[2];
        argv[0] = (char *)"gnuplot";
        argv[1] = NULL;
        close(fds[1]);
        if (dup2(fds[0], 0) < 0 || dup2(fileno(of.f), 1) < 0)
            _exit(126);
        execvp("gnuplot", argv);
        _exit(127);
    }
    close(fds[0]);
    if (pid < 0 || !(gp = fdopen(fds[1], "w"))) {
        if (pid < 0)
            close(fds[1]);
        outfile_abort(&of);
        fprintf(stderr, "maprt: %s: error: cannot run gnuplot\n", out);
        return CLI_IO;
    }
    cmd_bench_script(gp, rows, n, ids);
    fclose(gp);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || ftell(of.f) < 0
        || fseek(of.f, 0, SEEK_END) != 0 || ftell(of.f) == 0 || outfile_commit(&of, &err)) {
        outfile_abort(&of);
        fprintf(stderr, "maprt: %s: error: gnuplot failed%s\n", out,
                WIFEXITED(status) && WEXITSTATUS(status) == 127 ? " (is it installed?)" : "");
        return CLI_IO;
    }
    return CLI_OK;
}

/* Parses "q16,f64" into ops tables; 0 or CLI_USAGE. */
static int cmd_bench_modes(const char *s, const render_ops **ops, int *n)
{
    char buf[64], *tok, *save = NULL;
    int k;
    if (strlen(s) >= sizeof buf)
        return cli_usage_error("bench", "--modes: '%s' is too long", s);
    strcpy(buf, s);
    *n = 0;
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        const render_ops *o = render_ops_find(tok, RENDER_ISA_AUTO);
        if (!o)
            return cli_usage_error("bench", "--modes: '%s' is not q16, q32, f32, f64, hfp32 or hfp64",
                                   tok);
        for (k = 0; k < *n; k++)
            if (ops[k] == o)
                return cli_usage_error("bench", "--modes: '%s' given twice", tok);
        ops[(*n)++] = o;
    }
    if (!*n)
        return cli_usage_error("bench", "--modes: empty list");
    return 0;
}

static int cmd_bench_dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* One scene in one mode: `runs` timed renders (the median time), the
 * image against ref, and with an oracle map the identity map against it. */
static int cmd_bench_one(const scene *sc, const render_ops *ops, const render_opts *o, int runs,
                     const render_fb *ref, const idmap *orc, bench_row *r, diag *err)
{
    double t[BENCH_MAX_RUNS];
    render_fb fb;
    render_stats st;
    image_diff_stats d;
    int k;
    for (k = 0; k < runs; k++) {
        if (render_scene(sc, ops, o, &fb, &st, err))
            return err->status;
        t[k] = st.time_render_s;
        if (k + 1 < runs)
            render_fb_free(&fb);
    }
    qsort(t, (size_t)runs, sizeof *t, cmd_bench_dcmp);
    r->seconds = runs % 2 ? t[runs / 2] : (t[runs / 2 - 1] + t[runs / 2]) / 2;
    r->rays = st.rays_primary + st.rays_shadow + st.rays_reflected + st.rays_refracted;
    r->rays_per_s = r->seconds > 0 ? (double)r->rays / r->seconds : 0;
    r->overflows = st.fx_overflows;
    r->range_cut = st.range_cut;
    r->hfp_exc = 0;           /* exponent overflow and underflow, divide, sqrt, conversion */
    for (k = 0; k < HFP_EXC_N; k++)
        if (k != HFP_EXC_SIGNIFICANCE)
            r->hfp_exc += st.hfp_exc[k];
    image_diff(&fb.img, &ref->img, 2, &d);
    r->psnr = d.psnr;
    r->pct_over2 = 100.0 * d.over;
    render_fb_free(&fb);
    if (orc) {
        render_opts oi = *o;
        cli_idcheck_stats cs;
        oi.ids = 1;
        if (render_scene(sc, ops, &oi, &fb, &st, err))
            return err->status;
        cli_idcheck_compare(&fb.ids, orc, &cs);
        render_fb_free(&fb);
        r->has_ids = 1;
        r->id_compared = cs.compared;
        r->id_flagged = cs.flagged;
        r->id_mismatch = cs.mismatches;
        r->id_pct = cs.compared ? 100.0 * cs.mismatches / cs.compared : 0;
        r->err_median = cs.err_median;
        r->err_max = cs.err_max;
    }
    return 0;
}

/* The sweep: scenes x modes cells. Each rank keeps the scene of its latest
 * cell with its f64 reference and oracle map; cells go out in order, so a
 * rank meets each scene at most once. */
typedef struct bench_sweep {
    const char **scenes, *oracle;
    const render_ops **modes;
    int nmodes, runs, cells;
    const render_opts *o;
    int cur;                  /* the scene loaded, -1 none */
    scene *sc;
    render_fb ref;
    idmap orc;
    int have_orc;
    bench_row *rows;          /* rank 0: every row, filled as taken */
    char *taken;
    int printed;              /* rows printed so far, in order */
} bench_sweep;

static void cmd_bench_unload(bench_sweep *w)
{
    if (w->cur < 0)
        return;
    idmap_free(&w->orc);
    render_fb_free(&w->ref);
    scene_free(w->sc);
    w->sc = NULL;
    w->have_orc = 0;
    w->cur = -1;
}

/* Loads scene s, renders its f64 reference and runs the oracle on it. */
static int cmd_bench_load(bench_sweep *w, int s, diag *err)
{
    render_stats st;
    cli_files files;
    int status;
    if (w->cur == s)
        return 0;
    cmd_bench_unload(w);
    memset(&w->orc, 0, sizeof w->orc);
    status = cli_files_init(&files, err);
    if (!status)
        status = cli_scene_load(&files, w->scenes[s], &w->sc, err);
    cli_files_free(&files);
    if (status)
        return status;
    if ((status = render_scene(w->sc, &f64_render_ops, w->o, &w->ref, &st, err)) != 0) {
        scene_free(w->sc);
        w->sc = NULL;
        return status;
    }
    w->cur = s;
    if (w->oracle) {
        if ((status = cli_idcheck_oracle(w->oracle, w->sc, w->ref.img.width, w->ref.img.height,
                                         &w->orc, err)) != 0) {
            cmd_bench_unload(w);
            return status;
        }
        w->have_orc = 1;
    }
    return 0;
}

/* A row's measured fields as text for rank 0: hexadecimal floating point,
 * so that every double arrives exactly. */
#define BENCH_ROW_FMT "%a %a %a %a %a %a %a %ld %ld %ld %llu %llu %llu %llu %d"
#define BENCH_ROW_FIELDS 15

/* Runs cell c (scene c / nmodes, mode c % nmodes) on this rank. */
static int cmd_bench_run(void *ctx, int c, uint8_t **out, size_t *len, diag *err)
{
    bench_sweep *w = ctx;
    bench_row r;
    char line[512];
    int status, n;
    memset(&r, 0, sizeof r);
    if ((status = cmd_bench_load(w, c / w->nmodes, err)) != 0
        || (status = cmd_bench_one(w->sc, w->modes[c % w->nmodes], w->o, w->runs, &w->ref,
                                   w->have_orc ? &w->orc : NULL, &r, err)) != 0)
        return status;
    n = snprintf(line, sizeof line, BENCH_ROW_FMT, r.seconds, r.rays_per_s, r.psnr, r.pct_over2,
                 r.id_pct, r.err_median, r.err_max, r.id_compared, r.id_flagged, r.id_mismatch,
                 r.rays, r.overflows, r.range_cut, r.hfp_exc, r.has_ids);
    if (n < 0 || (size_t)n >= sizeof line || !(*out = mem_alloc((size_t)n)))
        return diag_at(err, DIAG_IO, "", 0, 0, "cannot encode a bench row");
    memcpy(*out, line, (size_t)n);
    *len = (size_t)n;
    return 0;
}

static void cmd_bench_print(const bench_row *r)
{
    printf("S%-2d %-24s %-5s %3d %9.4f %11.0f %8.2f %8.4f ", r->scene_no, r->scene, r->mode,
           r->threads, r->seconds, r->rays_per_s, r->psnr, r->pct_over2);
    if (r->has_ids)
        printf("%9.4f %5ld %9.2g %9.2g", r->id_pct, r->id_flagged, r->err_median, r->err_max);
    else
        printf("%9s %5s %9s %9s", "-", "-", "-", "-");
    printf(" %9llu %7llu\n", r->overflows, r->hfp_exc);
    if (r->range_cut)
        printf("    %llu primary rays beyond the %s range (shown as background)\n", r->range_cut,
               r->mode);
    fflush(stdout);
}

/* Rank 0: decodes cell c's row as run on `rank` and prints the rows that
 * are now complete in order. */
static int cmd_bench_take(void *ctx, int c, int rank, const uint8_t *buf, size_t len, diag *err)
{
    bench_sweep *w = ctx;
    bench_row *r = &w->rows[c];
    char line[512];
    int used = -1;
    if (len >= sizeof line)
        return diag_at(err, DIAG_IO, "", 0, 0, "a bench row of %zu bytes from rank %d", len, rank);
    memcpy(line, buf, len);
    line[len] = '\0';
    if (sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %ld %ld %ld %llu %llu %llu %llu %d%n",
               &r->seconds, &r->rays_per_s, &r->psnr, &r->pct_over2, &r->id_pct, &r->err_median,
               &r->err_max, &r->id_compared, &r->id_flagged, &r->id_mismatch, &r->rays,
               &r->overflows, &r->range_cut, &r->hfp_exc, &r->has_ids, &used) != BENCH_ROW_FIELDS
        || used != (int)len)
        return diag_at(err, DIAG_IO, "", 0, 0, "a malformed bench row from rank %d", rank);
    r->scene = w->scenes[c / w->nmodes];
    r->scene_no = c / w->nmodes + 1;
    r->mode = w->modes[c % w->nmodes]->name;
    r->threads = w->o->threads;
    r->runs = w->runs;
    r->rank = rank;
    w->taken[c] = 1;
    while (w->printed < w->cells && w->taken[w->printed])
        cmd_bench_print(&w->rows[w->printed++]);
    return 0;
}

int cmd_bench(int argc, char **argv)
{
    const render_ops *modes[BENCH_MAX_MODES];
    const char *csv = NULL, *plot = NULL, *oracle = NULL, *v, **scenes;
    const char *outs[2];
    bench_sweep w;
    cli_mpi_farm farm;
    bench_row *rows;
    render_opts o;
    diag err;
    int nmodes = 0, nscenes = 0, runs = 3, i, status = CLI_OK;
    long n;

    if (cli_wants_help(argc, argv)) {
        cmd_bench_help(stdout);
        return CLI_OK;
    }
    memset(&o, 0, sizeof o);
    o.aa = 1;
    o.threads = omp_get_max_threads();
    if (o.threads > RENDER_MAX_THREADS)
        o.threads = RENDER_MAX_THREADS;
    cmd_bench_modes("q16,q32,f32,f64,hfp32,hfp64", modes, &nmodes);
    scenes = mem_alloc(sizeof *scenes * (size_t)argc);
    rows = mem_calloc((size_t)argc * BENCH_MAX_MODES, sizeof *rows);
    memset(&w, 0, sizeof w);
    w.taken = mem_calloc((size_t)argc * BENCH_MAX_MODES, 1);
    if (!scenes || !rows || !w.taken) {
        mem_free(scenes);
        mem_free(rows);
        mem_free(w.taken);
        fprintf(stderr, "maprt bench: error: out of memory\n");
        return CLI_IO;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--size")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cli_size("bench", a, v, SCENE_MAX_SIDE, &o.width, &o.height))
                goto usage;
        } else if (!strcmp(a, "--modes")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cmd_bench_modes(v, modes, &nmodes))
                goto usage;
        } else if (!strcmp(a, "--threads")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cli_long("bench", a, v, 1, RENDER_MAX_THREADS, &n))
                goto usage;
            o.threads = (int)n;
        } else if (!strcmp(a, "--runs")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cli_long("bench", a, v, 1, BENCH_MAX_RUNS, &n))
                goto usage;
            runs = (int)n;
        } else if (!strcmp(a, "--oracle")) {
            if (!(oracle = cli_value("bench", argc, argv, &i)))
                goto usage;
        } else if (!strcmp(a, "--csv")) {
            if (!(csv = cli_value("bench", argc, argv, &i)))
                goto usage;
        } else if (!strcmp(a, "--plot")) {
            if (!(plot = cli_value("bench", argc, argv, &i)))
                goto usage;
        } else if (a[0] == '-' && a[1]) {
            cli_unknown_option("bench", a, cmd_bench_help);
            goto usage;
        } else {
            scenes[nscenes++] = a;
        }
    }
    if (!nscenes) {
        cli_usage_error("bench", "no SCENE given");
        goto usage;
    }
    cpubind_threads(o.threads);
    /* The outputs are checked before the sweep, by the rank that writes
     * them; every rank stops when they are refused. */
    diag_init(&err);
    outs[0] = csv;
    outs[1] = plot;
    status = cli_mpi_rank() == 0 ? outfile_check_set(outs, 2, &err) : 0;
    if ((status = cli_mpi_agree(status, NULL)) != 0) {
        if (err.status)
            diag_print(stderr, &err);
        goto done;
    }
    if (cli_mpi_rank() == 0)
        printf("%-3s %-24s %-5s %3s %9s %11s %8s %8s %9s %5s %9s %9s %9s %7s\n", "", "scene",
               "mode", "thr", "median_s", "rays/s", "psnr_db", "%>2/255", "%id_diff", "flag",
               "err_med", "err_max", "overflows", "hfp_exc");
    w.scenes = scenes;
    w.oracle = oracle;
    w.modes = modes;
    w.nmodes = nmodes;
    w.runs = runs;
    w.cells = nscenes * nmodes;
    w.o = &o;
    w.cur = -1;
    w.rows = rows;
    memset(&farm, 0, sizeof farm);
    farm.cells = w.cells;
    farm.run = cmd_bench_run;
    farm.take = cmd_bench_take;
    farm.ctx = &w;
    status = cli_mpi_farm_run(&farm, &err);
    cmd_bench_unload(&w);
    if (status)
        diag_print(stderr, &err);     /* rank 0 only: the others return 0 */
    if ((status = cli_mpi_agree(status, NULL)) != 0 || cli_mpi_rank() != 0)
        goto done;
    /* every output or none */
    outfile_batch_begin();
    if ((csv && (status = cmd_bench_csv(csv, rows, w.cells)) != 0)
        || (plot && (status = cmd_bench_plot(plot, rows, w.cells, oracle != NULL)) != 0)
        || (status = outfile_batch_commit(&err)) != 0) {
        if (err.status)
            diag_print(stderr, &err);
        outfile_batch_abort();
    }
done:
    mem_free(scenes);
    mem_free(rows);
    mem_free(w.taken);
    return status;
usage:
    mem_free(scenes);
    mem_free(rows);
    mem_free(w.taken);
    return CLI_USAGE;
}
