/* cmd_bench — `maprt bench`: renders each scene in each numeric mode and
 * reports run time against error, the error measured against the scene's
 * f64 render (the reference, rendered once per scene in addition to the
 * listed modes). Output: a table on stdout, optional CSV and gnuplot chart. */
#include "cli/cli.h"
#include "cli/cli_scene.h"
#include "image/image_diff.h"
#include "render/render.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define BENCH_MAX_MODES 4

typedef struct bench_row {
    const char *scene, *mode;
    int threads;
    double seconds, rays_per_s, rays_per_s_core, psnr, pct_over2, maxdiff;
    unsigned long long rays, overflows;
} bench_row;

static void bench_help(FILE *f)
{
    fprintf(f,
        "usage: maprt bench SCENE... [options]\n"
        "\n"
        "Renders every SCENE in every numeric mode and prints, per run: wall-clock\n"
        "render seconds, rays/s and rays/s per thread (all rays: primary, shadow,\n"
        "reflected, refracted), and the error against the same scene rendered in\n"
        "f64, which is the reference (rendered once more per scene for that):\n"
        "PSNR in dB (inf when identical), the %% of pixels where some channel differs\n"
        "by more than 2/255, the largest channel difference (0..255), and the\n"
        "fixed-point overflow count.\n"
        "\n"
        "options:\n"
        "  --size WxH        image size, 1..16384 each (default: each deck's SIZE)\n"
        "  --modes LIST      comma-separated modes out of q16,q32,f32,f64 (default: all)\n"
        "  --threads N       worker threads, 1..%d (default: OpenMP's count, %d here)\n"
        "  --csv OUT.csv     also write the rows as CSV with a header line\n"
        "  --plot OUT.png    chart seconds against max difference with gnuplot\n"
        "                    (an error, exit 3, when gnuplot is not installed)\n"
        "  -h, --help        show this help\n"
        "\n"
        "Timings depend on machine load; repeat runs to judge the noise.\n"
        "exit status: 0 ok, 1 bad scene, 2 usage, 3 I/O or internal failure\n",
        RENDER_MAX_THREADS, omp_get_max_threads());
}

/* 1 when an executable gnuplot is on PATH. */
static int bench_has_gnuplot(void)
{
    const char *path = getenv("PATH");
    char buf[4096];
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t len = end ? (size_t)(end - path) : strlen(path);
        if (len && len < sizeof buf - 10) {
            memcpy(buf, path, len);
            strcpy(buf + len, "/gnuplot");
            if (access(buf, X_OK) == 0)
                return 1;
        }
        path = end ? end + 1 : NULL;
    }
    return 0;
}

/* Charts seconds against max difference, one labelled point per run, by
 * piping a script with inline data to gnuplot. The PNG is written under a
 * temporary name and renamed when gnuplot succeeds. CLI_OK or CLI_IO. */
static int bench_plot(const char *out, const bench_row *rows, int n)
{
    FILE *gp;
    char *tmp;
    int i, rc;
    size_t len = strlen(out) + 16;
    if (!bench_has_gnuplot()) {
        fprintf(stderr, "maprt: %s: error: --plot needs gnuplot, which is not installed\n", out);
        return CLI_IO;
    }
    if (!(tmp = mem_alloc(len)))
        return CLI_IO;
    snprintf(tmp, len, "%s.tmp-%ld", out, (long)getpid());
    if (!(gp = popen("gnuplot", "w"))) {
        mem_free(tmp);
        fprintf(stderr, "maprt: %s: error: cannot run gnuplot\n", out);
        return CLI_IO;
    }
    fprintf(gp, "set terminal png size 800,600\nset output '%s'\n"
                "set xlabel 'render seconds'\nset ylabel 'max channel difference vs f64 (0..255)'\n"
                "set title 'maprt bench: run time against error'\nset key outside\n"
                "$d << EOD\n", tmp);
    for (i = 0; i < n; i++)
        fprintf(gp, "\"%s/%s\" %.6f %.0f\n", rows[i].scene, rows[i].mode, rows[i].seconds, rows[i].maxdiff);
    fprintf(gp, "EOD\nplot $d using 2:3:1 with labels point pt 7 offset 1,1 notitle\n");
    rc = pclose(gp);
    if (rc != 0 || rename(tmp, out) != 0) {
        remove(tmp);
        mem_free(tmp);
        fprintf(stderr, "maprt: %s: error: gnuplot failed\n", out);
        return CLI_IO;
    }
    mem_free(tmp);
    return CLI_OK;
}

/* Writes the rows as CSV with a header line, committed on close. */
static int bench_csv(const char *path, const bench_row *rows, int n)
{
    outfile of;
    diag err;
    char line[512];
    int i;
    diag_init(&err);
    if (outfile_open(&of, path, &err))
        goto fail;
    snprintf(line, sizeof line, "scene,mode,threads,seconds,rays,rays_per_s,rays_per_s_core,"
                                "psnr_db,pct_pixels_over_2,max_abs_diff,fx_overflows\n");
    outfile_write(&of, line, strlen(line), &err);
    for (i = 0; i < n; i++) {
        snprintf(line, sizeof line, "%s,%s,%d,%.6f,%llu,%.0f,%.0f,%.3f,%.4f,%.0f,%llu\n",
                 rows[i].scene, rows[i].mode, rows[i].threads, rows[i].seconds, rows[i].rays,
                 rows[i].rays_per_s, rows[i].rays_per_s_core, rows[i].psnr, rows[i].pct_over2,
                 rows[i].maxdiff, rows[i].overflows);
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

/* Parses "q16,f64" into ops tables; 0 or CLI_USAGE. */
static int bench_modes(const char *s, const render_ops **ops, int *n)
{
    char buf[64], *tok, *save = NULL;
    int k;
    if (strlen(s) >= sizeof buf)
        return cli_usage_error("bench", "--modes: '%s' is too long", s);
    strcpy(buf, s);
    *n = 0;
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        const render_ops *o = render_ops_find(tok);
        if (!o)
            return cli_usage_error("bench", "--modes: '%s' is not q16, q32, f32 or f64", tok);
        for (k = 0; k < *n; k++)
            if (ops[k] == o)
                return cli_usage_error("bench", "--modes: '%s' given twice", tok);
        ops[(*n)++] = o;
    }
    if (!*n)
        return cli_usage_error("bench", "--modes: empty list");
    return 0;
}

int cmd_bench(int argc, char **argv)
{
    const render_ops *modes[BENCH_MAX_MODES];
    const char *csv = NULL, *plot = NULL, *v, **scenes;
    bench_row *rows;
    render_opts o;
    int nmodes = 0, nscenes = 0, nrows = 0, i, s, m, status = CLI_OK;
    long n;

    if (cli_wants_help(argc, argv)) {
        bench_help(stdout);
        return CLI_OK;
    }
    memset(&o, 0, sizeof o);
    o.aa = 1;
    o.threads = omp_get_max_threads();
    if (o.threads > RENDER_MAX_THREADS)
        o.threads = RENDER_MAX_THREADS;
    bench_modes("q16,q32,f32,f64", modes, &nmodes);
    scenes = mem_alloc(sizeof *scenes * (size_t)argc);
    rows = mem_alloc(sizeof *rows * (size_t)argc * BENCH_MAX_MODES);
    if (!scenes || !rows) {
        mem_free(scenes);
        mem_free(rows);
        fprintf(stderr, "maprt bench: error: out of memory\n");
        return CLI_IO;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--size")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cli_size("bench", a, v, 16384, &o.width, &o.height))
                goto usage;
        } else if (!strcmp(a, "--modes")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || bench_modes(v, modes, &nmodes))
                goto usage;
        } else if (!strcmp(a, "--threads")) {
            if (!(v = cli_value("bench", argc, argv, &i)) || cli_long("bench", a, v, 1, RENDER_MAX_THREADS, &n))
                goto usage;
            o.threads = (int)n;
        } else if (!strcmp(a, "--csv")) {
            if (!(csv = cli_value("bench", argc, argv, &i)))
                goto usage;
        } else if (!strcmp(a, "--plot")) {
            if (!(plot = cli_value("bench", argc, argv, &i)))
                goto usage;
        } else if (a[0] == '-' && a[1]) {
            cli_unknown_option("bench", a, bench_help);
            goto usage;
        } else {
            scenes[nscenes++] = a;
        }
    }
    if (!nscenes) {
        cli_usage_error("bench", "no SCENE given");
        goto usage;
    }
    printf("%-28s %-4s %3s %9s %12s %12s %8s %8s %4s %9s\n", "scene", "mode", "thr", "seconds",
           "rays/s", "rays/s/core", "psnr_db", "%>2/255", "max", "overflows");
    for (s = 0; s < nscenes && status == CLI_OK; s++) {
        scene *sc = NULL;
        render_fb ref, fb;
        render_stats st;
        cli_files files;
        diag err;
        diag_init(&err);
        status = cli_files_init(&files, &err);
        if (!status)
            status = cli_scene_load(&files, scenes[s], &sc, &err);
        cli_files_free(&files);
        if (status != 0
            || (status = render_scene(sc, &f64_render_ops, &o, &ref, &st, &err)) != 0) {
            diag_print(stderr, &err);
            scene_free(sc);
            break;
        }
        for (m = 0; m < nmodes; m++) {
            bench_row *r = &rows[nrows];
            image_diff_stats d;
            if ((status = render_scene(sc, modes[m], &o, &fb, &st, &err)) != 0) {
                diag_print(stderr, &err);
                break;
            }
            r->scene = scenes[s];
            r->mode = modes[m]->name;
            r->threads = o.threads;
            r->seconds = st.time_render_s;
            r->rays = st.rays_primary + st.rays_shadow + st.rays_reflected + st.rays_refracted;
            r->rays_per_s = r->seconds > 0 ? (double)r->rays / r->seconds : 0;
            r->rays_per_s_core = r->rays_per_s / o.threads;
            r->overflows = st.fx_overflows;
            image_diff(&fb.img, &ref.img, 2, &d);
            r->psnr = d.psnr;
            r->pct_over2 = 100.0 * d.over;
            r->maxdiff = d.max;
            render_fb_free(&fb);
            printf("%-28s %-4s %3d %9.4f %12.0f %12.0f %8.2f %8.4f %4.0f %9llu\n", r->scene, r->mode,
                   r->threads, r->seconds, r->rays_per_s, r->rays_per_s_core, r->psnr, r->pct_over2,
                   r->maxdiff, r->overflows);
            fflush(stdout);
            nrows++;
        }
        render_fb_free(&ref);
        scene_free(sc);
    }
    if (status == CLI_OK && csv)
        status = bench_csv(csv, rows, nrows);
    if (status == CLI_OK && plot)
        status = bench_plot(plot, rows, nrows);
    mem_free(scenes);
    mem_free(rows);
    return status;
usage:
    mem_free(scenes);
    mem_free(rows);
    return CLI_USAGE;
}
