/* main — maprt's entry point: dispatches git-style subcommands. */
#include "cli/cli.h"
#include "cli/cli_mpi.h"
#include "util/outfile.h"
#include "util/suggest.h"
#include "util/version.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct cli_command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} cli_command;

static const cli_command commands[] = {
    {"render",  cmd_render,  "ray-trace a scene deck to PNG and/or a DL5080 display list"},
    {"dl2png",  cmd_dl2png,  "draw a DL5080 display list to PNG (png, osmesa or egl backend)"},
    {"dl",      cmd_dl,      "inspect a DL5080 display list (dump, validate)"},
    {"compare", cmd_compare, "measure a render against a reference image (PSNR, SSIM)"},
    {"bench",   cmd_bench,   "benchmark run time against error across numeric modes"},
    {"cms",     cmd_cms,     "VM/CMS files: import, list, type, export"},
    {"hfp",     cmd_hfp,     "System/370 hexadecimal floating-point numbers to and from IEEE"},
    {"merge",   cmd_merge,   "assemble region files of 'render --region' into the whole image"},
};

static void main_usage(FILE *f)
{
    size_t i;
    fprintf(f, "usage: maprt COMMAND [ARGS...]\n\n"
               "maprt is a CSG ray tracer with multi-attribute primitives (attribute\n"
               "mapping), after Aono's 1987 IBM system, with IBM 5080-style display-list\n"
               "output and a VM/CMS file shim.\n\ncommands:\n");
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n'maprt COMMAND --help' describes each command.\n"
               "Options follow getopt_long conventions: --opt=value or --opt value, '--'\n"
               "ends the options, values such as --numeric Q16 in any case; --version\n"
               "prints the version.\n"
               "exit status: 0 ok, 1 bad input, 2 usage, 3 I/O or internal failure\n");
}

/* Writes out what stdio still holds for stdout: a full disk or /dev/full
 * must not end in exit 0. Returns rc, or CLI_IO when that write fails. */
static int main_flush(int rc)
{
    diag err;
    diag_init(&err);
    if (outfile_close_stdout(&err) && rc == CLI_OK) {
        diag_print(stderr, &err);
        rc = CLI_IO;
    }
    return rc;
}

/* The subcommand's exit status; under mpirun every rank runs it. */
static int main_run(int argc, char **argv)
{
    size_t i;
    if (argc < 2) {
        main_usage(stderr);
        return CLI_USAGE;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help") || !strcmp(argv[1], "help")) {
        main_usage(stdout);
        return main_flush(CLI_OK);
    }
    /* --opt=value, --, --version: once here for every subcommand */
    if (cli_conventions(&argc, &argv)) {
        printf("maprt %s\n", version_string());
        cli_conventions_free();
        return main_flush(CLI_OK);
    }
    if (!argv) {
        fprintf(stderr, "maprt: error: out of memory\n");
        return CLI_IO;
    }
    if (argc < 2) {
        cli_conventions_free();
        main_usage(stderr);
        return CLI_USAGE;
    }
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) {
            int rc;
            outfile_track_inputs();   /* no output of this command replaces one of its inputs */
            rc = commands[i].run(argc - 1, argv + 1);
            cli_conventions_free();
            return main_flush(rc);
        }
    {
        suggest sg;
        suggest_init(&sg, argv[1]);
        for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
            suggest_try(&sg, commands[i].name, 0);
        if (suggest_best(&sg))
            fprintf(stderr, "maprt: error: unknown command '%s' (did you mean %s?)\n", argv[1],
                    suggest_best(&sg));
        else
            fprintf(stderr, "maprt: error: unknown command '%s'\n", argv[1]);
    }
    cli_conventions_free();
    main_usage(stderr);
    return CLI_USAGE;
}

/* Set when main returns. An exit before that was taken by a library:
 * libgomp ends the process with status 1 when it cannot create a thread
 * ("libgomp: Thread creation failed: ..."), which is not bad input. */
static volatile int main_returned;

/* The contract's status for such an exit: an I/O (resource) failure, 3,
 * with the temporaries removed. Left alone under mpirun with several ranks,
 * where MPI_Abort ends the run with the status it was given. */
static void main_at_exit(void)
{
    if (main_returned || cli_mpi_size() > 1)
        return;
    outfile_remove_temporaries();
    fprintf(stderr, "maprt: error: a library ended the run (the line above says why)\n");
    _exit(CLI_IO);
}

int main(int argc, char **argv)
{
    int rc;
    atexit(main_at_exit);
    if (cli_mpi_start(&argc, &argv)) {
        main_returned = 1;
        return CLI_IO;
    }
    rc = main_run(argc, argv);
    cli_mpi_stop();
    main_returned = 1;
    return rc;
}
