/* pnm — reading Netpbm greymaps and pixmaps (P2 P3 P5 P6) into an 8-bit
 * image, and writing binary PPM/PGM (P6/P5) or PAM (P7) for pipelines.
 * Read by compare, whose references are often scans saved as PNM; written
 * by render -o x.ppm / x.pam / - --format.
 * Strict: the header is magic, width, height, maxval (1..65535) separated by
 * whitespace and '#' comments, then exactly one whitespace character before a
 * binary raster; samples above maxval, short rasters and absurd sizes are
 * errors. Samples are rescaled to 0..255 with rounding. Bitmaps (P1, P4) and
 * PAM (P7) are refused with a clear message. */
#ifndef PNM_H
#define PNM_H
#include <stddef.h>
#include "image/image.h"

/* 1 if data starts like a PNM file ('P' and a digit). */
int pnm_sniff(const void *data, size_t len);

typedef struct pnm_info {
    int kind;                 /* 2, 3, 5 or 6 (the digit of the magic) */
    int width, height;        /* 1..IMAGE_MAX_SIDE, product <= IMAGE_MAX_PIXELS */
    unsigned maxval;          /* 1..65535 */
} pnm_info;

/* Checks and reads just the header (magic, size, maxval), so callers can
 * refuse a picture before decoding it. 0 or DIAG_INPUT. */
int pnm_read_header(const char *name, const void *data, size_t len, pnm_info *info, diag *err);

/* Decodes a PNM file held in memory into `out` with `channels` (1 or 3)
 * 8-bit channels: grey is replicated to RGB; RGB becomes grey through the
 * Rec. 601 luma weights (0.299, 0.587, 0.114) on the 8-bit values.
 * name is used in diagnostics: header errors carry LINE:COL, raster errors a
 * byte offset. Returns 0, DIAG_INPUT (bad file) or DIAG_IO (out of memory);
 * out is written only on success (free it with image_free). */
int pnm_read_memory(const char *name, const void *data, size_t len, int channels,
                    image *out, diag *err);

/* The header of img (1 or 3 channels) as binary PGM/PPM (P5/P6, maxval
 * 255) or, with pam, as PAM (P7, TUPLTYPE GRAYSCALE or RGB), into head
 * (cap bytes, PNM_HEAD_MAX more than the comments need): the file is that
 * header, then img->px as it is, so a writer streams the raster from the
 * picture without a copy of it. comments, if not NULL, is inserted after
 * the magic: lines that each start with '#'. Its length, or 0 when head is
 * too small. */
#define PNM_HEAD_MAX 160
size_t pnm_header(const image *img, int pam, const char *comments, char *head, size_t cap);
/* The whole file as pnm_header and the raster describe it, in memory: *buf
 * (mem_free it) and *len; DIAG_IO when out of memory. */
int pnm_encode(const image *img, int pam, const char *comments, void **buf, size_t *len, diag *err);
#endif
