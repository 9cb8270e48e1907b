/* align — registration: finds the similarity transform (warp.h convention)
 * that maps the TEST picture onto the REFERENCE picture, robustly enough for
 * scans of prints (grey or faded, halftoned, blurred, noisy, with margins).
 *
 * Method: both luminance pictures become Gaussian pyramids (binomial 2x
 * reduction) of blurred gradient magnitude, an edge map that ignores
 * brightness, contrast and paper tone. The score of a transform is the
 * normalised cross-correlation (NCC) of the two edge maps over the part of
 * the reference the test covers, leaving out a band along each picture's
 * border (3 pixels of the level, plus 3 x ref_blur for the test's band):
 * where one picture ends the other often shows an edge of its own (a
 * render's edge against the paper of a scan) that would pull the scale
 * inwards. A placement must cover at least half of the smaller picture, and
 * the part left after the bands at least a quarter, so a tiny corner match
 * cannot win.
 *  1. Coarse: exhaustive search over scale (log steps of 6 %), angle
 *     (multiples of 8 degrees within the range) and shift (one pixel of the
 *     level where the smaller picture is about 24 pixels across); the 8 best
 *     mutually distinct local maxima are kept.
 *  2. Fine: each candidate (and the best 4 once more from a scale step
 *     either side, as the scale grid is coarse next to small pictures) is
 *     refined by a pattern search in (log scale, position of the test's
 *     centre, angle) at the level where the smaller picture is about 64
 *     pixels across; the best one is then refined at
 *     levels where it is about 128, 256 and 512 pixels across (never finer
 *     than full resolution). If the correlation at a level falls under 0.6
 *     of the previous level's, that level is dominated by detail only one
 *     picture has (halftone dots, grain) and the search stops at the
 *     previous level. A last search there goes down to 1/64 pixel steps.
 *     Test pixels are read from the test pyramid level nearest to the
 *     reference level's pixel size, so the test is never sampled with
 *     aliasing.
 * A direct search was chosen over FFT phase correlation: it needs no extra
 * library, it searches scale and angle directly instead of through a
 * log-polar spectrum (which halftone screens and margins disturb), and the
 * coarse level is small enough that exhaustive search is cheap. */
#ifndef ALIGN_H
#define ALIGN_H
#include "compare/warp.h"

typedef struct align_opts {
    double scale_min, scale_max;   /* reference px per test px; 0 < min <= max */
    double max_angle;              /* degrees, 0..45; angles in [-max, max] */
    double ref_blur;               /* Gaussian sigma already applied to the
                                    * reference (reference px), >= 0; widens the
                                    * band along the test's border */
    double max_cost;               /* coarse search cost cap in pixel pairs;
                                    * 0 = ALIGN_MAX_COST */
} align_opts;

#define ALIGN_SCALE_MIN_DEFAULT 0.25
#define ALIGN_SCALE_MAX_DEFAULT 4.0
#define ALIGN_MAX_ANGLE_DEFAULT 5.0
#define ALIGN_MIN_OVERLAP 0.5      /* of the smaller picture's area */
#define ALIGN_MIN_USED 0.25        /* the same, after the border bands */
/* Cost cap of the coarse search, in pixel pairs compared: the sum over its
 * scales and angles of (coarse reference level area) x (test map area),
 * computed before the search starts. 2^32 pairs take about 10 s on one core
 * of a 2020s machine (docs/compare.md). */
#define ALIGN_MAX_COST 4294967296.0

typedef struct align_result {
    warp_params p;
    double score;                  /* edge-map NCC at the finest level, -1..1 */
} align_result;

/* Registers test onto ref (luminance planes, 8-bit units). Returns 0 and
 * fills *out; 1 when no transform in the search ranges overlaps enough
 * (or a picture has no edges at all); 2 when the search would cost more
 * than its cost cap (o->max_cost, else ALIGN_MAX_COST); -1 when out of memory. */
int align_find(const plane *ref, const plane *test, const align_opts *o, align_result *out);
#endif
