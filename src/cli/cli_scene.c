/* cli_scene — scene deck loading for the CLI (see cli_scene.h). */
#include "cli/cli_scene.h"
#include "util/mem.h"
#include "util/outfile.h"
#include "util/recsrc.h"

int cli_scene_load(const char *path, scene **out, diag *err)
{
    char *data = NULL;
    size_t len = 0;
    recsrc src;
    recsrc_mem mem;
    int st = infile_read_all(path, CLI_SCENE_MAX_BYTES, &data, &len, err);
    if (st)
        return st;
    recsrc_from_memory(&src, &mem, path, data, len);
    st = scene_parse(&src, out, err);
    mem_free(data);
    return st;
}
