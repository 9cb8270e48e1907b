/* cli_scene — reads and parses a scene deck for the render and bench
 * subcommands. Today SCENE is a host path read whole and split into lines;
 * the CMS shim (fileids, --disk mappings, EBCDIC decks) replaces the reading
 * here, at this one place. */
#ifndef CLI_SCENE_H
#define CLI_SCENE_H
#include "scene/scene.h"

#define CLI_SCENE_MAX_BYTES ((size_t)64 << 20)   /* larger decks are refused */

/* 0 and *out (scene_free it), or a diag status with err filled. */
int cli_scene_load(const char *path, scene **out, diag *err);
#endif
