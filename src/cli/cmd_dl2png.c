/* cmd_dl2png — `maprt dl2png IN OUT.png`: draws a DL5080 display list (or a
 * raw MegaPel element stream) on a chosen backend and writes what the 5081
 * would show as a PNG. */
#include "cli/cli.h"
#include "cli/cli_dl.h"
#include "util/sniff.h"
#include "display5080/dl_render.h"
#include "util/cpubind.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <omp.h>
#include <string.h>

#define DL2PNG_MAX_INPUT ((size_t)256 << 20)

static void cmd_dl2png_help(FILE *f)
{
    fprintf(f,
        "usage: maprt dl2png IN.dl5080 OUT.png [--backend png|osmesa|egl] [--truecolor] [--dac 4|8]\n"
        "       maprt dl2png IN.fifo OUT.png --raw [--size WxH] [...]\n"
        "\n"
        "Draws a DL5080 display list as the IBM 5081 display would show it and writes\n"
        "OUT.png (rows top-down; the list's origin is the lower-left corner).\n"
        "\n"
        "  --backend B   png: the software 5081 raster (default); osmesa: OpenGL into\n"
        "                an OSMesa buffer; egl: OpenGL on a surfaceless EGL (Mesa)\n"
        "                context. Every backend writes the same pixels: shapes and\n"
        "                text are rasterised once, the backend writes them.\n"
        "  --truecolor   write 8-bit RGB instead of an 8-bit palette PNG, encoded on\n"
        "                OMP_NUM_THREADS threads (default: one per CPU)\n"
        "  --dac 4|8     show the colour table through a 4-bit DAC (each gun's high\n"
        "                nibble times 17) or an 8-bit one; default: the file's header\n"
        "                flag, 8 for a raw stream\n"
        "  --raw         IN is a raw MegaPel element stream as IBM's X11 driver wrote\n"
        "                it to the adapter's FIFO: no header, no end element, MegaPel\n"
        "                elements only (colour table 0 black, 1 white, rest black)\n"
        "  --size WxH    the raw stream's screen (default 1024x1024, the 5081)\n"
        "\n"
        "Block transfers from adapter memory (0x5012) cannot be drawn from a stream;\n"
        "they are counted and reported as a warning.\n"
        "\n"
        "exit status: 0 ok, 1 malformed display list (the error names the byte offset),\n"
        "2 usage, 3 I/O error or a backend that cannot start here\n");
}

int cmd_dl2png(int argc, char **argv)
{
    const dl_backend *b;
    cli_dl_args a;
    dl_render_opts ro;
    dl_frame frame;
    char *data = NULL;
    size_t len = 0;
    int rc;
    diag err;
    if (cli_wants_help(argc, argv)) {
        cmd_dl2png_help(stdout);
        return CLI_OK;
    }
    if ((rc = cli_dl_parse("dl2png", argc, argv, 1,
                           CLI_DL_DAC | CLI_DL_RAW | CLI_DL_TRUECOLOR | CLI_DL_BACKEND, 2,
                           "IN.dl5080 and OUT.png", &a)))
        return rc;
    if (cli_png_name("dl2png", "OUT", a.file[1]))
        return CLI_USAGE;
    if (!(b = dl_backend_find(a.backend ? a.backend : "png")))
        return cli_usage_error("dl2png", "--backend: '%s' is not png, osmesa or egl", a.backend);
    memset(&ro, 0, sizeof ro);
    ro.dac = a.dac;
    ro.raw = a.raw;
    ro.width = a.width;
    ro.height = a.height;
    diag_init(&err);
    if ((rc = outfile_check(a.file[1], &err)) == 0
        && (a.raw || (rc = sniff_refuse(a.file[0], a.file[0], 1u << SNIFF_DL5080,
                                        "a DL5080 display list", &err)) == 0)
        && (rc = infile_read_all(a.file[0], DL2PNG_MAX_INPUT, &data, &len, &err)) == 0) {
        /* now that the input is known: an output that is the input is refused before drawing */
        if ((rc = outfile_check(a.file[1], &err)) == 0 &&
            (rc = dl_render((const uint8_t *)data, len, a.file[0], b, &ro, &frame, &err)) == 0) {
            if (frame.src_blts)
                fprintf(stderr,
                        "maprt: %s: offset %lld: warning: %lu block transfer%s from adapter "
                        "memory (0x5012) not drawn: a stream does not carry their pixels\n",
                        a.file[0], frame.src_blt_offset, frame.src_blts,
                        frame.src_blts == 1 ? "" : "s");
            /* the RGB encoder's threads: started, each on a CPU, only now,
             * so that no drawing (nor an OpenGL driver's threads) is kept
             * on one CPU */
            if (a.truecolor)
                cpubind_threads(omp_get_max_threads());
            rc = dl_frame_write_png(a.file[1], &frame, a.truecolor, &err);
            dl_frame_free(&frame);
        }
        mem_free(data);
    }
    if (rc)
        diag_print(stderr, &err);
    return rc;
}
