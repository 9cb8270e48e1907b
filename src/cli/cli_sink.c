/* cli_sink — writing a rendered frame as a DL5080 display list (render and
 * merge share it; see cli_sink.h). */
#include "cli/cli_sink.h"
#include "render/outline.h"
#include "cli/cli.h"
#include "util/mem.h"
#include <string.h>
#include "util/version.h"

/* Outline segments of the rendered primitives as 2-point polylines in
 * device coordinates (lower-left origin) for the display list. */
static int cli_sink_wireframe(const render_fb *fb, int **xy, dl_image_polyline **lines,
                            size_t *nlines, diag *err)
{
    outline_seg *segs;
    size_t n, k;
    int w = fb->img.width, h = fb->img.height;
    if (outline_trace(fb->pid, w, h, &segs, &n, err))
        return err->status;
    *xy = mem_calloc(4 * n, sizeof **xy);
    *lines = mem_calloc(n, sizeof **lines);
    if (!*xy || !*lines) {
        mem_free(segs);
        mem_free(*xy);
        mem_free(*lines);
        return diag_at(err, DIAG_IO, "wireframe", 0, 0, "out of memory");
    }
    for (k = 0; k < n; k++) {
        int *p = *xy + 4 * k;
        p[0] = segs[k].x0;
        p[1] = h - 1 - segs[k].y0;
        p[2] = segs[k].x1;
        p[3] = h - 1 - segs[k].y1;
        (*lines)[k].n = 2;
        (*lines)[k].xy = p;
        (*lines)[k].r = (*lines)[k].g = (*lines)[k].b = 255;
    }
    mem_free(segs);
    *nlines = n;
    return 0;
}

/* Writes the frame as a display list to the host path `path`. */
int cli_sink_dl(const char *path, const render_fb *fb, dl_image_opts *dlo, int wireframe,
                 dl_image_stats *dls, diag *err)
{
    int *xy = NULL, st;
    dl_image_polyline *lines = NULL;
    if (wireframe && cli_sink_wireframe(fb, &xy, &lines, &dlo->npolylines, err))
        return err->status;
    dlo->polylines = lines;
    st = dl_image_write(path, &fb->img, dlo, dls, err);
    mem_free(xy);
    mem_free(lines);
    return st;
}

void cli_sink_provenance(const char *deck, const char *deck_sha256, const char *mode, int aa,
                         const render_fb *fb, image_meta *m)
{
    char date[32];
    image_meta_date(date);
    image_meta_init(m);
    image_meta_add(m, "Software", "maprt %s", version_string());
    image_meta_add(m, "Creation Time", "%s", date);
    if (deck) {
        image_meta_add(m, "maprt:deck", "%s", deck);
        image_meta_add(m, "maprt:deck-sha256", "%s", deck_sha256);
    }
    image_meta_add(m, "maprt:numeric", "%s", mode);
    image_meta_add(m, "maprt:size", "%dx%d", fb->img.width, fb->img.height);
    image_meta_add(m, "maprt:aa", "%d", aa);
}

int cli_sink_dl_option(const char *cmd, int argc, char **argv, int *i, dl_image_opts *dlo,
                       int *wireframe, int *status)
{
    const char *a = argv[*i], *v;
    long n;
    if (!strcmp(a, "--dac")) {
        if (!(v = cli_value(cmd, argc, argv, i)) || cli_long(cmd, a, v, 4, 8, &n) || (n != 4 && n != 8))
            *status = v ? cli_usage_error(cmd, "--dac: '%s' is not 4 or 8", v) : CLI_USAGE;
        else
            dlo->dac = (int)n;
    } else if (!strcmp(a, "--dither")) {
        dlo->dither = 1;
    } else if (!strcmp(a, "--wireframe")) {
        *wireframe = 1;
    } else {
        return 0;
    }
    return 1;
}
