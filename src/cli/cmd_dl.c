/* cmd_dl — `maprt dl dump|validate|encode`: list a DL5080 display list (or a
 * raw MegaPel element stream) one element a line, check one, or turn any PNG
 * into one. */
#include "cli/cli.h"
#include "cli/cli_dl.h"
#include "util/sniff.h"
#include "display5080/dl_dump.h"
#include "display5080/dl_image.h"
#include "display5080/dl_render.h"
#include "display5080/dl_validate.h"
#include "image/image_png.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

#define DL_CLI_MAX_INPUT ((size_t)256 << 20)

static void cmd_dl_help(FILE *f)
{
    fprintf(f,
        "usage: maprt dl dump FILE.dl5080 [--raw [--size WxH] [--dac 4|8]]\n"
        "       maprt dl validate FILE.dl5080 [--raw [--size WxH] [--dac 4|8]]\n"
        "       maprt dl encode IN.png OUT.dl5080 [--dither] [--dac 4|8] [--stats]\n"
        "\n"
        "dump      lists the display list on stdout, one element a line: byte offset,\n"
        "          length, code, name and arguments (text converted from its code page)\n"
        "validate  checks the whole list without drawing and prints a summary\n"
        "  --raw       FILE is a raw MegaPel element stream (IBM's driver's FIFO\n"
        "              contents): no header, no end element, MegaPel elements only\n"
        "  --size WxH  the raw stream's screen (default 1024x1024, the 5081);\n"
        "              --dac the raw stream's DAC (default 8)\n"
        "encode    turns a PNG (at most 4096x4096; alpha composited over black) into a\n"
        "          display list, as `maprt render --dl` does with a rendered frame:\n"
        "          at most 256 colours chosen by median cut in the DAC's space, rows\n"
        "          as run-length runs or pixel blocks, whichever is smaller\n"
        "  --dither    Floyd-Steinberg error diffusion when mapping to the table\n"
        "  --dac 4|8   choose colours for a 4-bit DAC (4096 colours, default) or 8-bit\n"
        "  --stats     print colours=, bytes=, psnr= (dB, PNG vs the 5081's view),\n"
        "              run_rows= and blt_rows= lines on stdout\n"
        "\n"
        "exit status: 0 ok, 1 malformed input (the error names the byte offset), 2 usage,\n"
        "3 I/O error\n");
}

static void cmd_dl_stdout(void *ctx, const void *data, size_t len)
{
    (void)ctx;
    fwrite(data, 1, len, stdout);
}

/* A raw MegaPel stream has no header to recognise, so only a DL5080 list is
 * sniffed. */
static int cmd_dl_read(const char *path, int raw, char **data, size_t *len, diag *err)
{
    if (!raw && sniff_refuse(path, path, 1u << SNIFF_DL5080, "a DL5080 display list", err))
        return err->status;
    return infile_read_all(path, DL_CLI_MAX_INPUT, data, len, err);
}

/* The decoder options of dump and validate: a raw stream, its screen and DAC
 * as dl2png reads them. */
static dl_decode_opts cmd_dl_decode_opts(const cli_dl_args *a)
{
    dl_render_opts ro;
    memset(&ro, 0, sizeof ro);
    ro.raw = a->raw;
    ro.width = a->width;
    ro.height = a->height;
    ro.dac = a->dac;
    return dl_render_decode_opts(&ro);
}

static int cmd_dl_dump(const cli_dl_args *a)
{
    dl_decode_opts d = cmd_dl_decode_opts(a);
    char *data;
    size_t len;
    diag err;
    int rc;
    diag_init(&err);
    if ((rc = cmd_dl_read(a->file[0], a->raw, &data, &len, &err)) == 0) {
        rc = dl_dump((const uint8_t *)data, len, a->file[0], &d, cmd_dl_stdout, NULL, &err);
        mem_free(data);
    }
    fflush(stdout);
    if (rc)
        diag_print(stderr, &err);
    return rc;
}

static int cmd_dl_validate(const cli_dl_args *a)
{
    dl_decode_opts d = cmd_dl_decode_opts(a);
    dl_validate_summary s;
    char *data;
    size_t len;
    diag err;
    int rc, i;
    diag_init(&err);
    if ((rc = cmd_dl_read(a->file[0], a->raw, &data, &len, &err)) == 0) {
        rc = dl_validate((const uint8_t *)data, len, a->file[0], &d, &s, &err);
        mem_free(data);
    }
    if (rc) {
        diag_print(stderr, &err);
        return rc;
    }
    if (s.header.version)
        printf("%s: valid DL5080 version %u, ", a->file[0], s.header.version);
    else
        printf("%s: valid raw MegaPel stream, ", a->file[0]);
    printf("%dx%d, %d-bit DAC, %zu bytes, %lu elements:", s.header.width, s.header.height,
           s.header.flags & DL_FLAG_DAC8 ? 8 : 4, len, s.elements);
    for (i = 0; i < DL_FORMAT_NCODES; i++)
        if (s.count[i])
            printf(" %s=%lu", dl_format_codes[i].name, s.count[i]);
    printf("\n");
    return 0;
}

static int cmd_dl_encode(const cli_dl_args *a)
{
    dl_image_opts o;
    dl_image_stats st;
    image_limits lim;
    image img;
    diag err;
    int rc;
    memset(&o, 0, sizeof o);
    o.dac = a->dac ? a->dac : 4;
    o.dither = a->dither;
    diag_init(&err);
    lim.max_side = DL_MAX_SIDE;
    lim.max_pixels = (size_t)DL_MAX_SIDE * DL_MAX_SIDE;
    /* the size is refused from the PNG header; the output is checked before
     * reading (its directory) and after (not the input) */
    if ((rc = sniff_refuse(a->file[0], a->file[0], 1u << SNIFF_PNG, "a PNG image", &err)) == 0
        && (rc = outfile_check(a->file[1], &err)) == 0
        && (rc = image_read_png_limit(a->file[0], 3, &lim, &img, &err)) == 0) {
        if ((rc = outfile_check(a->file[1], &err)) == 0)
            rc = dl_image_write(a->file[1], &img, &o, &st, &err);
        image_free(&img);
    }
    if (rc) {
        diag_print(stderr, &err);
        return rc;
    }
    if (a->stats)
        printf("colours=%d\nbytes=%zu\npsnr=%.3f\nrun_rows=%zu\nblt_rows=%zu\n", st.colours,
               st.bytes, st.psnr, st.run_rows, st.blt_rows);
    return 0;
}

int cmd_dl(int argc, char **argv)
{
    cli_dl_args a;
    int rc;
    if (cli_wants_help(argc, argv)) {
        cmd_dl_help(stdout);
        return CLI_OK;
    }
    if (argc < 2)
        return cli_usage_error("dl", "needs a subcommand: dump, validate or encode");
    if (!strcmp(argv[1], "encode")) {
        if ((rc = cli_dl_parse("dl", argc, argv, 2, CLI_DL_DITHER | CLI_DL_DAC | CLI_DL_STATS, 2,
                               "IN.png and OUT.dl5080", &a)))
            return rc;
        return cmd_dl_encode(&a);
    }
    if (strcmp(argv[1], "dump") && strcmp(argv[1], "validate"))
        return cli_usage_error("dl", "unknown subcommand '%s' (dump, validate, encode)", argv[1]);
    if ((rc = cli_dl_parse("dl", argc, argv, 2, CLI_DL_RAW | CLI_DL_DAC, 1, "one FILE.dl5080",
                           &a)))
        return rc;
    if (a.dac && !a.raw)   /* a DL5080 header names its DAC; dump and validate do not draw */
        return cli_usage_error("dl", "%s: --dac applies only to a --raw stream", argv[1]);
    return !strcmp(argv[1], "dump") ? cmd_dl_dump(&a) : cmd_dl_validate(&a);
}
