/* cli_dl — the options shared by `maprt dl` and `maprt dl2png`: one parser
 * for positional files and the display-list flags, each command naming the
 * flags it takes. */
#ifndef CLI_DL_H
#define CLI_DL_H

enum {
    CLI_DL_DAC = 1,            /* --dac 4|8 */
    CLI_DL_RAW = 2,            /* --raw [--size WxH] */
    CLI_DL_DITHER = 4,         /* --dither */
    CLI_DL_STATS = 8,          /* --stats */
    CLI_DL_TRUECOLOR = 16,     /* --truecolor */
    CLI_DL_BACKEND = 32        /* --backend NAME */
};

typedef struct cli_dl_args {
    const char *file[2];       /* positional arguments in order */
    int dac;                   /* 0 = not given, else 4 or 8 */
    int raw, width, height;    /* --raw and --size (0 = not given) */
    int dither, stats, truecolor;
    const char *backend;       /* NULL = not given */
} cli_dl_args;

/* Parses argv[first..] for command cmd, accepting the flags in `allowed` and
 * exactly nfiles positional arguments (described by `files` in the usage
 * message). 0, or CLI_USAGE after a message. */
int cli_dl_parse(const char *cmd, int argc, char **argv, int first, unsigned allowed, int nfiles,
                 const char *files, cli_dl_args *out);
#endif
