/* cmd_dl2png — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_dl2png(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt dl2png: error: not available in this build\n");
    return CLI_IO;
}
