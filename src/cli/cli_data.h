/* cli_data — where maprt finds the scenes it ships, so that `maprt render
 * fig1 -o fig1.png` works from any directory: a name that is neither a host
 * file nor a CMS fileid is looked up as NAME.scene in $MAPRT_SCENES (a
 * colon-separated list), then PREFIX/share/maprt/scenes (`make install`),
 * then the scenes/ directory of the source tree maprt was built in. */
#ifndef CLI_DATA_H
#define CLI_DATA_H
#include <stdio.h>

/* The path of the shipped scene `name` ("fig1" or "fig1.scene"): 1 and
 * *path (mem_free it); 0 when there is none (or no memory). */
int cli_data_scene(const char *name, char **path);
/* Lists the shipped scenes of each search directory that has any, one a
 * line: name, then the deck's title (its first comment card); a name is
 * taken from the first directory that has it. 0, or CLI_IO. */
int cli_data_list(FILE *f);
#endif
