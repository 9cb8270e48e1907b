/* dl_image — an RGB frame as a DL5080 display list: the renderer's way to the
 * 5081. Quantises to at most 256 colours in the DAC's space (dl_quant), loads
 * the colour table, clears to the most common colour, writes each remaining
 * row as run-length runs (0x5F03) or a pixel block (0x5018), whichever is
 * smaller, adds optional wireframe polylines, and ends the list.
 * Data flow: render framebuffer -> dl_image_write -> outfile -> .dl5080. */
#ifndef DL_IMAGE_H
#define DL_IMAGE_H
#include <stddef.h>
#include <stdint.h>
#include "image/image.h"
#include "util/diag.h"

/* A wireframe outline in device coordinates (lower-left origin, y up):
 * n points at xy[0..2n-1], each coordinate within -32768..32767. */
typedef struct dl_image_polyline {
    size_t n;
    const int *xy;
    uint8_t r, g, b;           /* its colour; reserved exactly in the table */
} dl_image_polyline;

typedef struct dl_image_opts {
    int dac;                   /* 4 (default when 0) or 8 */
    int dither;                /* Floyd-Steinberg */
    const dl_image_polyline *polylines;
    size_t npolylines;         /* their distinct colours must number at most 255 */
} dl_image_opts;

typedef struct dl_image_stats {
    int colours;               /* colour table entries loaded */
    size_t bytes;              /* display list size */
    double psnr;               /* dB, RGB input vs the frame as the 5081 shows it
                                  (before wireframe); 1e9 when identical */
    size_t run_rows, blt_rows; /* rows written each way */
} dl_image_stats;

/* Writes rgb (3 channels, top row first, at most 4096 a side) to path as a
 * DL5080 file, committed on close. opts and stats may be NULL. Returns 0,
 * DIAG_INPUT (bad size, coordinates or options) or DIAG_IO. */
int dl_image_write(const char *path, const image *rgb, const dl_image_opts *opts,
                   dl_image_stats *stats, diag *err);
/* The same into memory: *out (mem_free it) and *len on success. */
int dl_image_encode(const image *rgb, const dl_image_opts *opts, uint8_t **out, size_t *len,
                    dl_image_stats *stats, diag *err);
/* Encodes an already indexed frame: index (width*height, top row first) over
 * table (ncolours entries 0x00RRGGBB), flags DL_FLAG_DAC8 or 0; lines are
 * drawn in colour line_index[i]. Drawn back, the list reproduces index
 * exactly (under the lines). stats->psnr is set to 0 here. */
int dl_image_encode_indexed(int width, int height, const uint8_t *index, const uint32_t *table,
                            int ncolours, unsigned flags, const dl_image_polyline *lines,
                            const int *line_index, size_t nlines, uint8_t **out, size_t *len,
                            dl_image_stats *stats, diag *err);
#endif
