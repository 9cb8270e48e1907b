/* cmd_dl — `maprt dl dump|validate|encode`: list a DL5080 display list one
 * element a line, check one, or turn any PNG into one. */
#include "cli/cli.h"
#include "display5080/dl_dump.h"
#include "display5080/dl_image.h"
#include "display5080/dl_validate.h"
#include "image/image_png.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

#define DL_CLI_MAX_INPUT ((size_t)256 << 20)

static void dl_help(FILE *f)
{
    fprintf(f,
        "usage: maprt dl dump FILE.dl5080\n"
        "       maprt dl validate FILE.dl5080\n"
        "       maprt dl encode IN.png OUT.dl5080 [--dither] [--dac 4|8] [--stats]\n"
        "\n"
        "dump      lists the display list on stdout, one element a line: byte offset,\n"
        "          length, code, name and arguments (text converted from EBCDIC)\n"
        "validate  checks the whole list without drawing and prints a summary\n"
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

static void dl_stdout(void *ctx, const void *data, size_t len)
{
    (void)ctx;
    fwrite(data, 1, len, stdout);
}

static int dl_read(const char *path, char **data, size_t *len, diag *err)
{
    return infile_read_all(path, DL_CLI_MAX_INPUT, data, len, err);
}

static int dl_cmd_dump(const char *path)
{
    char *data;
    size_t len;
    diag err;
    int rc;
    diag_init(&err);
    if ((rc = dl_read(path, &data, &len, &err)) == 0) {
        rc = dl_dump((const uint8_t *)data, len, path, dl_stdout, NULL, &err);
        mem_free(data);
    }
    fflush(stdout);
    if (rc)
        diag_print(stderr, &err);
    return rc;
}

static int dl_cmd_validate(const char *path)
{
    dl_validate_summary s;
    char *data;
    size_t len;
    diag err;
    int rc, i;
    diag_init(&err);
    if ((rc = dl_read(path, &data, &len, &err)) == 0) {
        rc = dl_validate((const uint8_t *)data, len, path, &s, &err);
        mem_free(data);
    }
    if (rc) {
        diag_print(stderr, &err);
        return rc;
    }
    printf("%s: valid DL5080, %dx%d, %d-bit DAC, %zu bytes, %lu elements:", path,
           s.header.width, s.header.height, s.header.flags & DL_FLAG_DAC8 ? 8 : 4, len,
           s.elements);
    for (i = 0; i < DL_FORMAT_NCODES; i++)
        if (s.count[i])
            printf(" %s=%lu", dl_format_name(dl_format_codes[i]), s.count[i]);
    printf("\n");
    return 0;
}

static int dl_cmd_encode(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    dl_image_opts o;
    dl_image_stats st;
    image_limits lim;
    image img;
    diag err;
    int i, stats = 0, rc;
    memset(&o, 0, sizeof o);
    o.dac = 4;
    for (i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--dither")) {
            o.dither = 1;
        } else if (!strcmp(argv[i], "--stats")) {
            stats = 1;
        } else if (!strcmp(argv[i], "--dac")) {
            const char *v = cli_value("dl", argc, argv, &i);
            if (!v)
                return CLI_USAGE;
            if (strcmp(v, "4") && strcmp(v, "8"))
                return cli_usage_error("dl", "--dac: '%s' is not 4 or 8", v);
            o.dac = v[0] - '0';
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_usage_error("dl", "unknown option '%s'", argv[i]);
        } else if (!in) {
            in = argv[i];
        } else if (!out) {
            out = argv[i];
        } else {
            return cli_usage_error("dl", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!in || !out)
        return cli_usage_error("dl", "encode needs IN.png and OUT.dl5080");
    diag_init(&err);
    lim.max_side = DL_MAX_SIDE;
    lim.max_pixels = (size_t)DL_MAX_SIDE * DL_MAX_SIDE;
    /* the size is refused from the PNG header; the output is checked before
     * reading (its directory) and after (not the input) */
    if ((rc = outfile_check(out, &err)) == 0 && (rc = image_read_png_limit(in, 3, &lim, &img, &err)) == 0) {
        if ((rc = outfile_check(out, &err)) == 0)
            rc = dl_image_write(out, &img, &o, &st, &err);
        image_free(&img);
    }
    if (rc) {
        diag_print(stderr, &err);
        return rc;
    }
    if (stats)
        printf("colours=%d\nbytes=%zu\npsnr=%.3f\nrun_rows=%zu\nblt_rows=%zu\n", st.colours,
               st.bytes, st.psnr, st.run_rows, st.blt_rows);
    return 0;
}

int cmd_dl(int argc, char **argv)
{
    if (cli_wants_help(argc, argv)) {
        dl_help(stdout);
        return CLI_OK;
    }
    if (argc < 2)
        return cli_usage_error("dl", "needs a subcommand: dump, validate or encode");
    if (!strcmp(argv[1], "encode"))
        return dl_cmd_encode(argc, argv);
    if (strcmp(argv[1], "dump") && strcmp(argv[1], "validate"))
        return cli_usage_error("dl", "unknown subcommand '%s' (dump, validate, encode)", argv[1]);
    if (argc != 3)
        return cli_usage_error("dl", "%s needs exactly one FILE.dl5080", argv[1]);
    return !strcmp(argv[1], "dump") ? dl_cmd_dump(argv[2]) : dl_cmd_validate(argv[2]);
}
