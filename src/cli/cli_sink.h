/* cli_sink — the outputs of a rendered frame shared by render and merge: a
 * DL5080 display list, the frame quantised to the 5081's colour table
 * (dl_image), optionally with the outlines of the primitives as seen
 * (--wireframe, from the pid map). */
#ifndef CLI_SINK_H
#define CLI_SINK_H
#include "cli/cli_scene.h"
#include "display5080/dl_image.h"
#include "image/image_meta.h"
#include "render/render.h"
#include "util/diag.h"

/* The display-list options render and merge share: --dac 4|8, --dither,
 * --wireframe. 1 when argv[*i] is one of them (taken, *i advanced past its
 * value; *status = CLI_USAGE after a message when it is bad), else 0. */
int cli_sink_dl_option(const char *cmd, int argc, char **argv, int *i, dl_image_opts *dlo,
                       int *wireframe, int *status);
/* Writes fb as a display list to the host path `path`; dls receives the
 * colour count, size and PSNR. 0 or the diag status. */
int cli_sink_dl(const char *path, const render_fb *fb, dl_image_opts *dlo, int wireframe,
                 dl_image_stats *dls, diag *err);
/* What made the picture, for its PNG tEXt chunks or PPM/PAM comments:
 * maprt's version, the date (SOURCE_DATE_EPOCH when set), the deck's name
 * and SHA-256 (64 hex digits: render's from the bytes it parsed,
 * cli_scene_load_sum; merge's from the file, cli_file_sha256; neither
 * when deck is NULL), the numeric mode, size and aa. render and merge
 * write the same, so merged parts give the same bytes. */
void cli_sink_provenance(const char *deck, const char *deck_sha256, const char *mode, int aa,
                         const render_fb *fb, image_meta *m);
#endif
