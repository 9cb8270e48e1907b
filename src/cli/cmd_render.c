/* cmd_render — placeholder until the module lands; replaced by its owner. */
#include "cli/cli.h"

int cmd_render(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "maprt render: error: not available in this build\n");
    return CLI_IO;
}
