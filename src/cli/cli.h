/* cli — the subcommand table and small option helpers shared by the
 * subcommands. Exit codes: 0 ok, 1 bad input, 2 usage, 3 I/O or internal. */
#ifndef CLI_H
#define CLI_H
#include <stdio.h>

enum { CLI_OK = 0, CLI_INPUT = 1, CLI_USAGE = 2, CLI_IO = 3,
       CLI_MISMATCH = 4 /* compare: measured, but the pair does not match */ };

/* Each subcommand: argv[0] is the subcommand name. */
int cmd_render(int argc, char **argv);
int cmd_dl2png(int argc, char **argv);
int cmd_dl(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_cms(int argc, char **argv);
int cmd_hfp(int argc, char **argv);
int cmd_merge(int argc, char **argv);

/* Prints "maprt CMD: error: TEXT" and a hint to use --help; returns CLI_USAGE. */
int cli_usage_error(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The usage error for an unknown option opt of cmd, naming the option of
 * cmd's --help text (written by help) nearest to it: "unknown option
 * '--szie' (did you mean --size?)". Returns CLI_USAGE. */
int cli_unknown_option(const char *cmd, const char *opt, void (*help)(FILE *f));
/* getopt_long conventions for every subcommand, applied once in main before
 * the subcommand parses argv[1..]: "--opt=value" becomes "--opt" "value";
 * "--" ends the options (it is dropped, and a later argument that begins
 * with '-' is passed as "./-..." so that it reads as a file); returns 1 if
 * --version was given before any "--". *argv is replaced by a new array,
 * released by cli_conventions_free; NULL argv on out of memory. */
int cli_conventions(int *argc, char ***argv);
void cli_conventions_free(void);
/* The value of option argv[*i] (the next argument); advances *i. NULL (after
 * a usage error message) if missing. */
const char *cli_value(const char *cmd, int argc, char **argv, int *i);
/* Parses a whole decimal integer in [lo,hi]; 0 ok, else CLI_USAGE after a message. */
int cli_long(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out);
/* Parses a finite decimal number; 0 ok, else CLI_USAGE after a message. */
int cli_double(const char *cmd, const char *opt, const char *s, double *out);
/* Parses "WxH" with 1 <= W,H <= max; 0 ok, else CLI_USAGE after a message. */
int cli_size(const char *cmd, const char *opt, const char *s, int max, int *w, int *h);
/* Parses a region "X0,Y0,X1,Y1" (pixels [X0,X1) x [Y0,Y1), whole numbers
 * 0..max with X0 < X1 and Y0 < Y1); 0 ok, else CLI_USAGE after a message. */
int cli_region(const char *cmd, const char *opt, const char *s, int max, int r[4]);
/* 0 if name ends in .png (any case); else a usage error saying so, before
 * the work (CLI_USAGE). For outputs that are always PNG. */
int cli_png_name(const char *cmd, const char *opt, const char *name);
/* 1 if argv contains -h or --help. */
int cli_wants_help(int argc, char **argv);
/* 1 when stderr is a terminal (progress bars go there only then). */
int cli_is_tty(void);
#endif
