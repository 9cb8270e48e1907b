/* dl_render — a DL5080 display list drawn to a frame: decode, interpret on a
 * chosen backend, read the indices back, and keep the colour table as the
 * DAC shows it. Frames become palette or true-colour PNGs here too.
 * Data flow: DL5080 bytes -> dl_render (dl_decode + dl_interp + backend)
 *            -> dl_frame -> PNG. */
#ifndef DL_RENDER_H
#define DL_RENDER_H
#include <stdint.h>
#include "display5080/dl_backend.h"
#include "display5080/dl_decode.h"
#include "image/image.h"

typedef struct dl_frame {
    int width, height;
    int dac;                   /* 4 or 8 */
    uint8_t *px;               /* width*height indices, bottom row first */
    uint8_t palette[768];      /* colour table as shown */
    unsigned long src_blts;    /* 0x5012 elements not drawn: their pixels are in adapter memory */
    long long src_blt_offset;  /* byte offset of the first */
    unsigned long long work;   /* drawing budget spent, in pixel steps (dl_work) */
} dl_frame;

typedef struct dl_render_opts {
    int dac;                   /* 0 = the file's header flag (raw: 8), else 4 or 8 */
    unsigned long long work_limit;   /* drawing budget in pixel steps; 0 = default */
    int raw;                   /* 1: buf is a raw MegaPel element stream */
    int width, height;         /* raw only: the screen; 0 = 1024 */
} dl_render_opts;

/* Draws buf (len bytes, named name in diagnostics) with backend b into *out
 * (free with dl_frame_free). Returns 0, DIAG_INPUT for a bad list (err names
 * the byte offset) or DIAG_IO when the backend fails. opts may be NULL. */
/* The decoder options opts stands for (raw stream, screen, DAC). */
dl_decode_opts dl_render_decode_opts(const dl_render_opts *opts);
int dl_render(const uint8_t *buf, size_t len, const char *name, const dl_backend *b,
              const dl_render_opts *opts, dl_frame *out, diag *err);
void dl_frame_free(dl_frame *f);
/* The frame as the display shows it: RGB, top row first. */
int dl_frame_rgb(const dl_frame *f, image *out, diag *err);
/* Writes an 8-bit palette PNG (palette trimmed to the highest index used) or,
 * with truecolor, an RGB PNG; committed on close. */
int dl_frame_write_png(const char *path, const dl_frame *f, int truecolor, diag *err);
#endif
