/* cmd_dl2png — `maprt dl2png IN.dl5080 OUT.png`: draws a DL5080 display list
 * on a chosen backend and writes what the 5081 would show as a PNG. */
#include "cli/cli.h"
#include "display5080/dl_render.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

#define DL2PNG_MAX_INPUT ((size_t)256 << 20)

static void dl2png_help(FILE *f)
{
    fprintf(f,
        "usage: maprt dl2png IN.dl5080 OUT.png [--backend png|osmesa|egl] [--truecolor] [--dac 4|8]\n"
        "\n"
        "Draws a DL5080 display list as the IBM 5081 display would show it and writes\n"
        "OUT.png (rows top-down; the list's origin is the lower-left corner).\n"
        "\n"
        "  --backend B   png: the software 5081 raster (default); osmesa: OpenGL into\n"
        "                an OSMesa buffer; egl: OpenGL on a surfaceless EGL (Mesa)\n"
        "                context. Pixel blocks, runs, rectangles and clears match the\n"
        "                png backend exactly; GL lines, circles and polygons may differ\n"
        "                by one pixel along their edges (see docs/dl5080.md).\n"
        "  --truecolor   write 8-bit RGB instead of an 8-bit palette PNG\n"
        "  --dac 4|8     show the colour table through a 4-bit DAC (each gun's high\n"
        "                nibble times 17) or an 8-bit one; default: the file's header flag\n"
        "\n"
        "exit status: 0 ok, 1 malformed display list (the error names the byte offset),\n"
        "2 usage, 3 I/O error or a backend that cannot start here\n");
}

int cmd_dl2png(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *bname = "png";
    const dl_backend *b;
    dl_render_opts ro;
    dl_frame frame;
    char *data = NULL;
    size_t len = 0;
    int i, truecolor = 0, rc;
    diag err;
    memset(&ro, 0, sizeof ro);
    if (cli_wants_help(argc, argv)) {
        dl2png_help(stdout);
        return CLI_OK;
    }
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--backend")) {
            if (!(bname = cli_value("dl2png", argc, argv, &i)))
                return CLI_USAGE;
        } else if (!strcmp(argv[i], "--truecolor")) {
            truecolor = 1;
        } else if (!strcmp(argv[i], "--dac")) {
            const char *v = cli_value("dl2png", argc, argv, &i);
            if (!v)
                return CLI_USAGE;
            if (strcmp(v, "4") && strcmp(v, "8"))
                return cli_usage_error("dl2png", "--dac: '%s' is not 4 or 8", v);
            ro.dac = v[0] - '0';
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_usage_error("dl2png", "unknown option '%s'", argv[i]);
        } else if (!in) {
            in = argv[i];
        } else if (!out) {
            out = argv[i];
        } else {
            return cli_usage_error("dl2png", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!in || !out)
        return cli_usage_error("dl2png", "needs IN.dl5080 and OUT.png");
    if (!(b = dl_backend_find(bname)))
        return cli_usage_error("dl2png", "--backend: '%s' is not png, osmesa or egl", bname);
    diag_init(&err);
    if ((rc = outfile_check(out, &err)) == 0 &&
        (rc = infile_read_all(in, DL2PNG_MAX_INPUT, &data, &len, &err)) == 0) {
        /* now that the input is known: an output that is the input is refused before drawing */
        if ((rc = outfile_check(out, &err)) == 0 &&
            (rc = dl_render((const uint8_t *)data, len, in, b, &ro, &frame, &err)) == 0) {
            rc = dl_frame_write_png(out, &frame, truecolor, &err);
            dl_frame_free(&frame);
        }
        mem_free(data);
    }
    if (rc)
        diag_print(stderr, &err);
    return rc;
}
