/* cmd_hfp — `maprt hfp`: System/370 hexadecimal floating-point numbers to
 * and from IEEE binary64, for checking numbers carried in HFP form (a binary
 * deck field, a 3081 tape record) by hand. The conversions are hfp_data's. */
#include "cli/cli.h"
#include "num/hfp_data.h"
#include <ctype.h>
#include <stdint.h>
#include <string.h>

static void cmd_hfp_help(FILE *f)
{
    fprintf(f,
        "usage: maprt hfp decode HEX...\n"
        "       maprt hfp encode short|long NUMBER...\n"
        "\n"
        "Converts System/370 hexadecimal floating-point (HFP) numbers, as a binary\n"
        "deck or a 3081 tape holds them, to and from IEEE binary64 (docs/numerics.md).\n"
        "\n"
        "  decode HEX...   each HEX is a register image of 8 (short) or 16 (long)\n"
        "                  hex digits, e.g. C276A000; prints its value with 17\n"
        "                  significant digits (short: exact; long: rounded to the\n"
        "                  nearest double, ties to even)\n"
        "  encode short|long NUMBER...\n"
        "                  prints each decimal NUMBER's image in hex (long: exact;\n"
        "                  short: rounded to nearest, ties away from zero, as LRER)\n"
        "  -h, --help      show this help\n"
        "\n"
        "exit status: 0 ok, 1 a NUMBER outside the HFP range (about 5.4e-79 to\n"
        "7.2e75 in magnitude), 2 usage (a malformed HEX or NUMBER)\n");
}

/* Parses 8 or 16 hex digits into a big-endian field; its width, or 0. */
static size_t cmd_hfp_parse_hex(const char *s, unsigned char *field)
{
    size_t n = strlen(s), i;
    if (n != 8 && n != 16)
        return 0;
    for (i = 0; i < n; i++) {
        int c = (unsigned char)s[i], v;
        if (!isxdigit(c))
            return 0;
        v = isdigit(c) ? c - '0' : tolower(c) - 'a' + 10;
        if (i % 2 == 0)
            field[i / 2] = (unsigned char)(v << 4);
        else
            field[i / 2] |= (unsigned char)v;
    }
    return n / 2;
}

static int cmd_hfp_decode_args(int argc, char **argv)
{
    int i;
    for (i = 2; i < argc; i++) {
        unsigned char field[8];
        size_t w = cmd_hfp_parse_hex(argv[i], field);
        double x;
        diag err;
        diag_init(&err);
        if (!w)
            return cli_usage_error("hfp", "'%s' is not 8 or 16 hex digits", argv[i]);
        if (hfp_data_decode(field, w, &x, argv[i], -1, &err)) {
            diag_print(stderr, &err);
            return CLI_INPUT;
        }
        printf("%.17g\n", x);
    }
    return CLI_OK;
}

static int cmd_hfp_encode_args(int argc, char **argv)
{
    size_t w, j;
    int i;
    if (argc < 3 || (strcmp(argv[2], "short") && strcmp(argv[2], "long")))
        return cli_usage_error("hfp", "encode needs 'short' or 'long'");
    w = strcmp(argv[2], "short") ? 8 : 4;
    for (i = 3; i < argc; i++) {
        unsigned char field[8];
        double x;
        diag err;
        diag_init(&err);
        if (cli_double("hfp", "NUMBER", argv[i], &x))
            return CLI_USAGE;
        if (hfp_data_encode(x, w, field, argv[i], -1, &err)) {
            diag_print(stderr, &err);
            return CLI_INPUT;
        }
        for (j = 0; j < w; j++)
            printf("%02X", field[j]);
        printf("\n");
    }
    return CLI_OK;
}

int cmd_hfp(int argc, char **argv)
{
    if (cli_wants_help(argc, argv)) {
        cmd_hfp_help(stdout);
        return CLI_OK;
    }
    if (argc >= 2 && !strcmp(argv[1], "decode"))
        return cmd_hfp_decode_args(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "encode"))
        return cmd_hfp_encode_args(argc, argv);
    return cli_usage_error("hfp", "expected 'decode' or 'encode'");
}
