/* cli_progress — the render progress line on stderr: share done, a bar,
 * elapsed time, ETA and rays/s, fitted to the terminal's width and redrawn
 * in place at most ten times a second; where stderr is not a terminal
 * (forced with --progress) a plain line every two seconds, with the tiles done. The share comes
 * from the renderer, weighted by measured tile cost so that it is linear in
 * time; the ETA is elapsed * (1 - share) / share. */
#ifndef CLI_PROGRESS_H
#define CLI_PROGRESS_H
#include "render/render.h"

typedef struct cli_progress {
    int tty;                  /* redraw in place */
    int width;                /* columns available */
    double last;              /* elapsed_s of the last line drawn, -1 none */
    double elapsed_s;         /* as last reported */
    unsigned long long rays;
} cli_progress;

void cli_progress_init(cli_progress *p);
/* The render_opts.progress callback (ctx is the cli_progress). */
void cli_progress_update(void *ctx, const render_progress *pr);
/* Formats seconds as "12.3 s", "4:05" or "1:02:03" into buf. */
void cli_progress_time(double s, char *buf, size_t cap);
/* Formats a rate as "950 rays/s", "12.3 krays/s", "2.31 Mrays/s". */
void cli_progress_rate(double rays_per_s, char *buf, size_t cap);
#endif
