/* compare — measures a TEST picture (e.g. a maprt render) against a
 * REFERENCE picture (e.g. a scan of the paper's Figure 1). The data flow:
 *   read both (imgload) -> crop the reference -> [register the test onto the
 *   reference (align) and resample it into the reference frame (warp)]
 *   -> [descreen both] -> [match the test's levels] -> metrics (PSNR,
 *   pixels over threshold) on RGB or luma, SSIM on luma -> pictures
 *   (diffpic). All figures are in the (cropped) reference's pixel frame. */
#ifndef COMPARE_H
#define COMPARE_H
#include "compare/align.h"

#define COMPARE_MAX_READ_PIXELS ((size_t)64 << 20)  /* per file read */
#define COMPARE_MAX_PIXELS (16u << 20)   /* per picture after cropping */
#define COMPARE_THRESHOLD_DEFAULT 8.0
#define COMPARE_DESCREEN_MAX 50.0

typedef struct compare_opts {
    int do_register;           /* find the transform; else sizes must match */
    align_opts align;          /* search ranges for the registration */
    int grey;                  /* compare luma only (else R, G, B) */
    int levels;                /* fit test levels to the reference per channel */
    double descreen;           /* Gaussian sigma in reference pixels, 0 = off */
    double threshold;          /* for pixels_over, 8-bit units */
    int crop;                  /* crop the reference to cx,cy,cw,ch */
    int cx, cy, cw, ch;
    const char *diff_path;     /* heat map PNG, or NULL */
    const char *sbs_path;      /* side-by-side PNG, or NULL */
} compare_opts;

typedef struct compare_result {
    int width, height;         /* the compared frame (cropped reference) */
    int channels;              /* 3 (R,G,B) or 1 (luma) for psnr and pixels_over */
    long pixels;               /* pixels compared */
    double overlap;            /* pixels / (width * height) */
    double mse, psnr, ssim, pixels_over;
    long ssim_windows;
    int registered;
    warp_params p;             /* when registered */
    double register_score;     /* edge-map NCC of the registration */
    double gain[3], offset[3]; /* when levels: test' = gain * test + offset */
} compare_result;

/* Below these a pair very likely shows two different things (figures
 * measured on renders of the shipped scenes against each other, in
 * docs/compare.md): the registration's edge correlation, and SSIM. */
#define COMPARE_MATCH_MIN_SCORE 0.78
#define COMPARE_MATCH_MIN_SSIM 0.30

/* 1 when r says the two pictures do not show the same thing, with the
 * reason ("register_score 0.45 < 0.78") in why; 0 otherwise. */
int compare_mismatch(const compare_result *r, char *why, size_t cap);

/* Sets the documented defaults. */
void compare_opts_init(compare_opts *o);

/* Compares two decoded pictures (names for diagnostics). Returns 0 with *out
 * filled, else a DIAG_* status with err set: DIAG_INPUT for pictures that
 * cannot be compared (sizes differ without registration, crop outside the
 * reference, too large, too small for SSIM, no registration found), DIAG_IO
 * for memory or output-file failures. */
int compare_images(const char *ref_name, const image *ref, const char *test_name, const image *test,
                   const compare_opts *o, compare_result *out, diag *err);
/* Reads both files (PNG or PNM) and compares them. */
int compare_files(const char *ref_path, const char *test_path, const compare_opts *o, compare_result *out,
                  diag *err);
#endif
