/* cmd_cms — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_cms(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt cms: error: not available in this build\n");
    return CLI_IO;
}
