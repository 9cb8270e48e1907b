/* diffpic — pictures of a comparison for people to look at, made from the
 * reference and the registered test (nch planes of one size, 8-bit units)
 * and the mask of compared pixels:
 *  - the heat map shows, per pixel, the largest channel difference d through
 *    the ramp black (0) -> blue (32) -> red (64) -> yellow (96) -> white
 *    (128 and above); pixels outside the mask are dark grey (64,64,64);
 *  - the side-by-side has three panels separated by 8 white pixels: the
 *    reference, the registered test (uncovered pixels mid grey), and a
 *    checkerboard that alternates the two in squares of DIFFPIC_CHECK
 *    pixels, where any misalignment shows as broken edges. */
#ifndef DIFFPIC_H
#define DIFFPIC_H
#include "compare/plane.h"

#define DIFFPIC_GAP 8
#define DIFFPIC_CHECK 16

/* RGB heat map of |ref - test|. 0, or DIAG_* status in err. */
int diffpic_heat(const plane *ref, const plane *test, int nch, const plane *mask, image *out, diag *err);
/* RGB side-by-side, (3w + 2 gaps) x h. 0, or DIAG_* status in err. */
int diffpic_side_by_side(const plane *ref, const plane *test, int nch, const plane *mask, image *out,
                         diag *err);
#endif
