/* cmd_compare — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_compare(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt compare: error: not available in this build\n");
    return CLI_IO;
}
