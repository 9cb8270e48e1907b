/* cmd_bench — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_bench(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt bench: error: not available in this build\n");
    return CLI_IO;
}
