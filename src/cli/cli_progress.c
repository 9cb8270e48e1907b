/* cli_progress — the render progress line (see cli_progress.h). */
#include "cli/cli_progress.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

void cli_progress_init(cli_progress *p)
{
    struct winsize ws;
    const char *cols = getenv("COLUMNS");
    memset(p, 0, sizeof *p);
    p->tty = isatty(2);
    p->width = 80;
    if (p->tty && ioctl(2, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0)
        p->width = ws.ws_col;
    else if (cols && atoi(cols) > 0)
        p->width = atoi(cols);
    if (p->width > 200)
        p->width = 200;
    p->last = -1;
}

void cli_progress_time(double s, char *buf, size_t cap)
{
    long t = (long)(s + 0.5);
    if (s < 60)
        snprintf(buf, cap, "%.1f s", s);
    else if (t < 3600)
        snprintf(buf, cap, "%ld:%02ld", t / 60, t % 60);
    else
        snprintf(buf, cap, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
}

void cli_progress_rate(double r, char *buf, size_t cap)
{
    if (r >= 1e6)
        snprintf(buf, cap, "%.2f Mrays/s", r / 1e6);
    else if (r >= 1e3)
        snprintf(buf, cap, "%.1f krays/s", r / 1e3);
    else
        snprintf(buf, cap, "%.0f rays/s", r);
}

void cli_progress_update(void *ctx, const render_progress *pr)
{
    cli_progress *p = ctx;
    char el[24], eta[24], rate[32], tail[128], line[256];
    int done = pr->tiles_done == pr->tiles, pct = (int)(pr->fraction * 100);
    int room, bar, fill, n;
    p->elapsed_s = pr->elapsed_s;
    p->rays = pr->rays;
    if (!done && p->last >= 0 && pr->elapsed_s - p->last < (p->tty ? 0.1 : 2.0))
        return;
    p->last = pr->elapsed_s;
    cli_progress_time(pr->elapsed_s, el, sizeof el);
    if (pr->fraction > 0.005 && !done)
        cli_progress_time(pr->elapsed_s * (1 - pr->fraction) / pr->fraction, eta, sizeof eta);
    else
        snprintf(eta, sizeof eta, done ? "0 s" : "?");
    cli_progress_rate(pr->elapsed_s > 0 ? (double)pr->rays / pr->elapsed_s : 0, rate, sizeof rate);
    if (!p->tty) {
        fprintf(stderr, "render %3d%%  %s elapsed  ETA %s  %s  (tiles %ld/%ld)\n", pct, el, eta, rate,
                pr->tiles_done, pr->tiles);
        return;
    }
    /* the longest tail that fits with a bar of at least 10 columns */
    room = p->width - 1 - 12;   /* "render 100% " */
    n = snprintf(tail, sizeof tail, " %s elapsed, ETA %s, %s", el, eta, rate);
    if (n > room - 12)
        n = snprintf(tail, sizeof tail, " %s, ETA %s", el, eta);
    if (n > room - 12)
        n = snprintf(tail, sizeof tail, " ETA %s", eta);
    if (n > room - 3)
        n = tail[0] = 0;
    bar = room - n - 2;
    if (bar > 50)
        bar = 50;
    if (bar < 1) {
        snprintf(line, sizeof line, "render %3d%%%s", pct, tail);
    } else {
        fill = (int)(pr->fraction * bar + 0.5);
        snprintf(line, sizeof line, "render %3d%% [%.*s%*s]%s", pct, fill,
                 "##################################################", bar - fill, "", tail);
    }
    fprintf(stderr, "\r%s\033[K", line);
    if (done)
        fputc('\n', stderr);
    fflush(stderr);
}
