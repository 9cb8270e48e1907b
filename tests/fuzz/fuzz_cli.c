/* fuzz_cli — the command line: the bytes are NUL-separated arguments for
 * render, dl2png, dl, compare or cms (bench, which runs gnuplot, is left
 * out), run in a private directory holding a tiny deck, a PNG, a display
 * list and a CMS file. Every argument vector must end in a status, never a
 * crash or leak. To keep runs bounded and the machine safe, vectors naming a
 * path outside the directory ('/' or '..') or the size options (--size, --aa,
 * --threads: bounded, but up to hours at their limits) are skipped, and so is
 * --register: its search takes up to 0.5 s a vector here (ten times a whole
 * vector without it) and fuzz_compare runs it on its own inputs. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <unistd.h>
#include "cli/cli.h"
#include "util/outfile.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_ARGS 24

static const char fuzz_deck[] = "SIZE 4 4\nEYE 0 -5 0\nLOOKAT 0 0 0\nLIGHT 0 -5 5\n"
                                "ATTR R COLOR 1 0 0 MIRROR 0.5\nSPHERE S 1 ATTR R\nOBJECT S\n";
/* a 4x4 grey PNG, and the display list `maprt dl encode` makes of it */
static const unsigned char fuzz_png[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00, 0x8c, 0x9a, 0xc1,
    0xa2, 0x00, 0x00, 0x00, 0x0e, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0xf8, 0x0f, 0x84,
    0xa8, 0x04, 0x00, 0x4b, 0xc8, 0x07, 0xf9, 0x6b, 0xde, 0x2f, 0x7c, 0x00, 0x00, 0x00, 0x00, 0x49,
    0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
static const unsigned char fuzz_dl[] = {
    0xc4, 0xd3, 0xf5, 0xf0, 0xf8, 0xf0, 0x00, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00, 0x04, 0x00, 0x00,
    0x00, 0x10, 0x5f, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff,
    0x00, 0x06, 0x5f, 0x01, 0x00, 0x00, 0x00, 0x14, 0x50, 0x18, 0x00, 0x01, 0x00, 0x00, 0x00, 0x03,
    0x00, 0x00, 0x00, 0x08, 0x00, 0x04, 0x01, 0x00, 0x01, 0x00, 0x00, 0x14, 0x50, 0x18, 0x00, 0x01,
    0x00, 0x01, 0x00, 0x03, 0x00, 0x01, 0x00, 0x08, 0x00, 0x04, 0x01, 0x00, 0x01, 0x00, 0x00, 0x14,
    0x50, 0x18, 0x00, 0x01, 0x00, 0x02, 0x00, 0x03, 0x00, 0x02, 0x00, 0x08, 0x00, 0x04, 0x01, 0x00,
    0x01, 0x00, 0x00, 0x14, 0x50, 0x18, 0x00, 0x01, 0x00, 0x03, 0x00, 0x03, 0x00, 0x03, 0x00, 0x08,
    0x00, 0x04, 0x01, 0x00, 0x01, 0x00, 0x00, 0x04, 0x5f, 0x02,
};
static char fuzz_dir[64];

static void fuzz_put(const char *name, const void *data, size_t len)
{
    FILE *f = fopen(name, "wb");
    if (!f || fwrite(data, 1, len, f) != len || fclose(f) != 0)
        abort();
}

/* Removes every file in the private directory. */
static void fuzz_empty(void)
{
    DIR *d = opendir(fuzz_dir);
    struct dirent *e;
    char path[sizeof fuzz_dir + 256];
    if (!d)
        abort();
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")
            && (size_t)snprintf(path, sizeof path, "%s/%s", fuzz_dir, e->d_name) < sizeof path)
            unlink(path);
    closedir(d);
}

/* At exit: the private directory goes too (a crash leaves it, with what
 * the crashing vector made). */
static void fuzz_leave(void)
{
    fuzz_empty();
    if (chdir("/") == 0)
        rmdir(fuzz_dir);
}

/* Restores the directory to its fixtures: every file a run made is removed. */
static void fuzz_reset(void)
{
    fuzz_empty();
    fuzz_put("d.scene", fuzz_deck, sizeof fuzz_deck - 1);
    fuzz_put("a.png", fuzz_png, sizeof fuzz_png);
    fuzz_put("a.dl", fuzz_dl, sizeof fuzz_dl);
    fuzz_put("c.text", "HELLO\nWORLD\n", 12);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    char L;
    (void)argc;
    (void)argv;
    strcpy(fuzz_dir, "/tmp/maprt-fuzz-cli-XXXXXX");
    if (!mkdtemp(fuzz_dir) || chdir(fuzz_dir) != 0 || atexit(fuzz_leave) != 0)
        abort();
    for (L = 'A'; L <= 'Z'; L++) {
        char v[] = "MAPRT_DISK_X";
        v[11] = L;
        unsetenv(v);
    }
    if (!freopen("/dev/null", "w", stdout))
        abort();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const struct { const char *name; int (*run)(int, char **); } cmds[] = {
        {"render", cmd_render}, {"dl2png", cmd_dl2png}, {"dl", cmd_dl}, {"compare", cmd_compare},
        {"cms", cmd_cms}};
    char buf[1024], *argv[FUZZ_ARGS + 1];
    int argc = 0, i;
    size_t k, n = size < sizeof buf - 1 ? size : sizeof buf - 1;
    memcpy(buf, data, n);
    buf[n] = '\0';
    for (k = 0; k <= n && argc < FUZZ_ARGS; k++) {
        argv[argc++] = buf + k;
        k += strlen(buf + k);
    }
    argv[argc] = NULL;
    for (i = 0; i < argc; i++)
        if (strchr(argv[i], '/') || strstr(argv[i], "..") || !strcmp(argv[i], "--size") ||
            !strcmp(argv[i], "--aa") || !strcmp(argv[i], "--threads") || !strcmp(argv[i], "--register"))
            return 0;
    for (i = 0; i < (int)(sizeof cmds / sizeof cmds[0]); i++)
        if (!strcmp(argv[0], cmds[i].name)) {
            int rc;
            fuzz_reset();
            outfile_track_inputs();
            rc = cmds[i].run(argc, argv);
            if (rc < 0 || rc > 3)
                __builtin_trap();
            fflush(stdout);
            break;
        }
    return 0;
}
