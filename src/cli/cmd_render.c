/* cmd_render — `maprt render`: scene deck -> compiled scene for one numeric
 * mode -> tiled render -> PNG (and, later, a DL5080 display list). */
#include "image/image_png.h"
#include "cli/cli.h"
#include "cli/cli_scene.h"
#include "render/render.h"
#include "render/outline.h"
#include "display5080/dl_image.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <omp.h>
#include <string.h>

static void render_help(FILE *f)
{
    fprintf(f,
        "usage: maprt render SCENE [-o OUT.png] [--dl OUT.dl5080] [options]\n"
        "\n"
        "Ray-traces the scene deck SCENE (see docs/scene-format.md) and writes a\n"
        "true-colour PNG and/or a DL5080 display list, as the IBM 5081 would show it.\n"
        "SCENE and every output may be a host path or a CMS fileid ('FIG1 SCENE A').\n"
        "Outputs are written to a temporary name and renamed when complete (both or\n"
        "neither); each is checked before the trace: its directory must be writable,\n"
        "and it must not be SCENE, an image SCENE names, or the other output.\n"
        "\n"
        "options:\n"
        "  -o, --output OUT.png  write a true-colour PNG\n"
        "  --dl OUT.dl5080       write a DL5080 display list: the frame quantised to at\n"
        "                        most 256 colours in the DAC's colour space\n"
        "  --dac 4|8             bits per gun of the 5081 colour table (default 4)\n"
        "  --dither              Floyd-Steinberg dithering when quantising (--dl)\n"
        "  --wireframe           add the outlines of the primitives as seen (--dl)\n"
        "  --numeric MODE        arithmetic of the geometry: q16 (Q16.16 fixed point, the\n"
        "                        default), q32 (Q32.32), f32 or f64 (IEEE binary32/64)\n"
        "  --size WxH            image size in pixels, 1..16384 each (default: the\n"
        "                        deck's SIZE; at most 4096 with --dl)\n"
        "  --threads N           worker threads, 1..%d (default: OpenMP's count, %d here)\n"
        "  --aa N                N x N samples per pixel, 1..%d (default 1)\n"
        "  --stats               print key=value lines to stdout: numeric rays.primary\n"
        "                        rays.shadow rays.reflected rays.refracted pds.lookups\n"
        "                        fx.overflows tests.prim tests.bound csg.pruned\n"
        "                        time.compile_s time.render_s (and dl.colours dl.bytes\n"
        "                        dl.psnr with --dl; rays.capped when the cap of %d\n"
        "                        reflected and refracted rays per sample was reached)\n"
        "%s"
        "  -h, --help            show this help\n"
        "\n"
        "A progress bar is drawn on stderr when it is a terminal.\n"
        "exit status: 0 ok, 1 bad scene, 2 usage, 3 I/O or internal failure\n",
        RENDER_MAX_THREADS, omp_get_max_threads(), RENDER_MAX_AA, RENDER_MAX_RAYS_PER_SAMPLE,
        cli_files_help);
}

/* Progress bar on stderr (a terminal), redrawn after every tile. */
static void render_progress(void *ctx, long done, long total)
{
    int width = 40, fill = (int)(done * width / total);
    (void)ctx;
    fprintf(stderr, "\rrender [%.*s%*s] %3ld%%", fill,
            "########################################", width - fill, "", done * 100 / total);
    if (done == total)
        fputc('\n', stderr);
}

/* Outline segments of the rendered primitives as 2-point polylines in
 * device coordinates (lower-left origin) for the display list. */
static int render_wireframe(const render_fb *fb, int **xy, dl_image_polyline **lines,
                            size_t *nlines, diag *err)
{
    outline_seg *segs;
    size_t n, k;
    int w = fb->img.width, h = fb->img.height;
    if (outline_trace(fb->pid, w, h, &segs, &n, err))
        return err->status;
    *xy = mem_calloc(n ? 4 * n : 1, sizeof **xy);
    *lines = mem_calloc(n ? n : 1, sizeof **lines);
    if (!*xy || !*lines) {
        mem_free(segs);
        mem_free(*xy);
        mem_free(*lines);
        return diag_at(err, DIAG_IO, "wireframe", 0, 0, "out of memory");
    }
    for (k = 0; k < n; k++) {
        int *p = *xy + 4 * k;
        p[0] = segs[k].x0;
        p[1] = h - 1 - segs[k].y0;
        p[2] = segs[k].x1;
        p[3] = h - 1 - segs[k].y1;
        (*lines)[k].n = 2;
        (*lines)[k].xy = p;
        (*lines)[k].r = (*lines)[k].g = (*lines)[k].b = 255;
    }
    mem_free(segs);
    *nlines = n;
    return 0;
}

/* Writes the frame as a display list to the host path `path`. */
static int render_write_dl(const char *path, const render_fb *fb, dl_image_opts *dlo,
                           int wireframe, dl_image_stats *dls, diag *err)
{
    int *xy = NULL, st;
    dl_image_polyline *lines = NULL;
    if (wireframe && render_wireframe(fb, &xy, &lines, &dlo->npolylines, err))
        return err->status;
    dlo->polylines = lines;
    st = dl_image_write(path, &fb->img, dlo, dls, err);
    mem_free(xy);
    mem_free(lines);
    return st;
}

int cmd_render(int argc, char **argv)
{
    const char *scene_name = NULL, *out_png = NULL, *out_dl = NULL, *mode = "q16", *v;
    char *png_path = NULL, *dl_path = NULL;
    const char *outs[2];
    const render_ops *ops = NULL;
    render_opts o;
    render_stats st;
    render_fb fb;
    dl_image_opts dlo;
    dl_image_stats dls;
    cli_files files;
    scene *sc = NULL;
    diag err;
    long n;
    int i, stats = 0, wireframe = 0, status = 0, rendered = 0;

    if (cli_wants_help(argc, argv)) {
        render_help(stdout);
        return CLI_OK;
    }
    diag_init(&err);
    if (cli_files_init(&files, &err)) {
        diag_print(stderr, &err);
        cli_files_free(&files);
        return CLI_USAGE;
    }
    memset(&o, 0, sizeof o);
    memset(&dlo, 0, sizeof dlo);
    o.threads = omp_get_max_threads();
    if (o.threads > RENDER_MAX_THREADS)
        o.threads = RENDER_MAX_THREADS;
    o.aa = 1;
    dlo.dac = 4;
    for (i = 1; i < argc && !status; i++) {
        const char *a = argv[i];
        if (cli_files_option(&files, "render", argc, argv, &i, &status))
            continue;
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!(out_png = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--dl")) {
            if (!(out_dl = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--dac")) {
            if (!(v = cli_value("render", argc, argv, &i)) || cli_long("render", a, v, 4, 8, &n)
                || (n != 4 && n != 8))
                status = v ? cli_usage_error("render", "--dac: '%s' is not 4 or 8", v) : CLI_USAGE;
            else
                dlo.dac = (int)n;
        } else if (!strcmp(a, "--dither")) {
            dlo.dither = 1;
        } else if (!strcmp(a, "--wireframe")) {
            wireframe = 1;
        } else if (!strcmp(a, "--numeric")) {
            if (!(mode = cli_value("render", argc, argv, &i))) status = CLI_USAGE;
        } else if (!strcmp(a, "--size")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_size("render", a, v, 16384, &o.width, &o.height))
                status = CLI_USAGE;
        } else if (!strcmp(a, "--threads")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_THREADS, &n))
                status = CLI_USAGE;
            else
                o.threads = (int)n;
        } else if (!strcmp(a, "--aa")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_AA, &n))
                status = CLI_USAGE;
            else
                o.aa = (int)n;
        } else if (!strcmp(a, "--stats")) {
            stats = 1;
        } else if (a[0] == '-' && a[1]) {
            status = cli_usage_error("render", "unknown option '%s'", a);
        } else if (scene_name) {
            status = cli_usage_error("render", "more than one SCENE ('%s', '%s')", scene_name, a);
        } else {
            scene_name = a;
        }
    }
    if (!status && !scene_name)
        status = cli_usage_error("render", "no SCENE given");
    if (!status && !out_png && !out_dl)
        status = cli_usage_error("render", "no output: give -o OUT.png and/or --dl OUT.dl5080");
    if (!status && !(ops = render_ops_find(mode)))
        status = cli_usage_error("render", "--numeric: '%s' is not q16, q32, f32 or f64", mode);
    if (!status && !out_dl && (dlo.dither || wireframe || dlo.dac != 4))
        status = cli_usage_error("render", "--dac, --dither and --wireframe need --dl");
    if (status) {
        cli_files_free(&files);
        return status;
    }

    /* Resolve and check every name before the long work: a bad fileid, a
     * missing or read-only directory, two outputs on one file or an output
     * that is an input (the deck or an image it names) fails fast. */
    if ((out_png && cli_output_path(&files, out_png, &png_path, &err))
        || (out_dl && cli_output_path(&files, out_dl, &dl_path, &err)))
        goto done;
    outs[0] = png_path;
    outs[1] = dl_path;
    if (outfile_check_set(outs, 2, &err) || cli_scene_load(&files, scene_name, &sc, &err)
        || outfile_check_set(outs, 2, &err))
        goto done;
    if (out_dl && ((o.width ? o.width : sc->view.width) > 4096
                   || (o.height ? o.height : sc->view.height) > 4096)) {
        diag_at(&err, DIAG_USAGE, out_dl, 0, 0, "a display list holds at most 4096x4096 pixels");
        goto done;
    }
    if (cli_is_tty())
        o.progress = render_progress;
    if (render_scene(sc, ops, &o, &fb, &st, &err))
        goto done;
    rendered = 1;
    /* both outputs or neither */
    outfile_batch_begin();
    if ((png_path && image_write_png(png_path, &fb.img, &err))
        || (dl_path && render_write_dl(dl_path, &fb, &dlo, wireframe, &dls, &err))
        || outfile_batch_commit(&err)) {
        outfile_batch_abort();
        goto done;
    }
    if (stats) {
        printf("numeric=%s\n", ops->name);
        render_stats_print(stdout, &st);
        if (dl_path)
            printf("dl.colours=%d\ndl.bytes=%lu\ndl.psnr=%.2f\n", dls.colours,
                   (unsigned long)dls.bytes, dls.psnr);
    }
done:
    if (rendered)
        render_fb_free(&fb);
    scene_free(sc);
    mem_free(png_path);
    mem_free(dl_path);
    cli_files_free(&files);
    if (err.status) {
        diag_print(stderr, &err);
        return err.status;
    }
    return CLI_OK;
}
