/* cmd_dl — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_dl(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt dl: error: not available in this build\n");
    return CLI_IO;
}
