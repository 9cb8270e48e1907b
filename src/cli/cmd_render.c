/* cmd_render — `maprt render`: scene deck -> compiled scene for one numeric
 * mode -> tiled render -> PNG (and, later, a DL5080 display list). */
#include "cli/cli.h"
#include "cli/cli_scene.h"
#include "render/render.h"
#include <omp.h>
#include <string.h>

static void render_help(FILE *f)
{
    fprintf(f,
        "usage: maprt render SCENE -o OUT.png [options]\n"
        "\n"
        "Ray-traces the scene deck SCENE (a host file; see docs/scene-format.md)\n"
        "and writes a true-colour PNG.\n"
        "\n"
        "options:\n"
        "  -o, --output OUT.png  write the image here (written to a temporary name and\n"
        "                        renamed when complete)\n"
        "  --dl OUT.dl5080       also write a DL5080 display list (not available in this\n"
        "                        build: exits with status 3)\n"
        "  --numeric MODE        arithmetic of the geometry: q16 (Q16.16 fixed point, the\n"
        "                        default), q32 (Q32.32), f32 or f64 (IEEE binary32/64)\n"
        "  --size WxH            image size in pixels, 1..16384 each (default: the\n"
        "                        deck's SIZE)\n"
        "  --threads N           worker threads, 1..%d (default: OpenMP's count, %d here)\n"
        "  --aa N                N x N samples per pixel, 1..%d (default 1)\n"
        "  --stats               print key=value lines to stdout: numeric rays.primary\n"
        "                        rays.shadow rays.reflected rays.refracted pds.lookups\n"
        "                        fx.overflows tests.prim tests.bound csg.pruned\n"
        "                        time.compile_s time.render_s\n"
        "  -h, --help            show this help\n"
        "\n"
        "A progress bar is drawn on stderr when it is a terminal.\n"
        "exit status: 0 ok, 1 bad scene, 2 usage, 3 I/O or internal failure\n",
        RENDER_MAX_THREADS, omp_get_max_threads(), RENDER_MAX_AA);
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

int cmd_render(int argc, char **argv)
{
    const char *scene_path = NULL, *out_png = NULL, *out_dl = NULL, *mode = "q16", *v;
    const render_ops *ops;
    render_opts o;
    render_stats st;
    render_fb fb;
    scene *sc = NULL;
    diag err;
    long n;
    int i, stats = 0, status;

    if (cli_wants_help(argc, argv)) {
        render_help(stdout);
        return CLI_OK;
    }
    memset(&o, 0, sizeof o);
    o.threads = omp_get_max_threads();
    if (o.threads > RENDER_MAX_THREADS)
        o.threads = RENDER_MAX_THREADS;
    o.aa = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            if (!(out_png = cli_value("render", argc, argv, &i))) return CLI_USAGE;
        } else if (!strcmp(a, "--dl")) {
            if (!(out_dl = cli_value("render", argc, argv, &i))) return CLI_USAGE;
        } else if (!strcmp(a, "--numeric")) {
            if (!(mode = cli_value("render", argc, argv, &i))) return CLI_USAGE;
        } else if (!strcmp(a, "--size")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_size("render", a, v, 16384, &o.width, &o.height))
                return CLI_USAGE;
        } else if (!strcmp(a, "--threads")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_THREADS, &n))
                return CLI_USAGE;
            o.threads = (int)n;
        } else if (!strcmp(a, "--aa")) {
            if (!(v = cli_value("render", argc, argv, &i))
                || cli_long("render", a, v, 1, RENDER_MAX_AA, &n))
                return CLI_USAGE;
            o.aa = (int)n;
        } else if (!strcmp(a, "--stats")) {
            stats = 1;
        } else if (a[0] == '-' && a[1]) {
            return cli_usage_error("render", "unknown option '%s'", a);
        } else if (scene_path) {
            return cli_usage_error("render", "more than one SCENE ('%s', '%s')", scene_path, a);
        } else {
            scene_path = a;
        }
    }
    if (!scene_path)
        return cli_usage_error("render", "no SCENE given");
    if (!out_png && !out_dl)
        return cli_usage_error("render", "no output: give -o OUT.png");
    if (!(ops = render_ops_find(mode)))
        return cli_usage_error("render", "--numeric: '%s' is not q16, q32, f32 or f64", mode);
    if (out_dl) {
        /* The DL5080 writer is called here, once it is part of the build:
         * encode fb (and fb.pid) to out_dl after the render below. */
        fprintf(stderr, "maprt: %s: error: display-list output not available\n", out_dl);
        return CLI_IO;
    }

    diag_init(&err);
    if ((status = cli_scene_load(scene_path, &sc, &err)) != 0) {
        diag_print(stderr, &err);
        return status;
    }
    if (cli_is_tty())
        o.progress = render_progress;
    status = render_scene(sc, ops, &o, &fb, &st, &err);
    if (!status) {
        status = image_write_png(out_png, &fb.img, &err);
        render_fb_free(&fb);
    }
    scene_free(sc);
    if (status) {
        diag_print(stderr, &err);
        return status;
    }
    if (stats) {
        printf("numeric=%s\n", ops->name);
        render_stats_print(stdout, &st);
    }
    return CLI_OK;
}
