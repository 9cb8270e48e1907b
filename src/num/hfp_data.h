/* hfp_data — System/370 HFP numbers carried in data (a binary deck field,
 * a tape record written on the 3081): big-endian 4-byte (short) or 8-byte
 * (long) fields, to and from IEEE binary64.
 *
 * Decoding: a short field converts exactly; a long field's 56-bit fraction
 * is rounded to 53 bits, to nearest with ties to even (at most 2^-53
 * relative). Unnormalised fields convert by value; any zero fraction is a
 * zero, of the field's sign.
 * Encoding: a long field is exact; a short field is the long number loaded
 * rounded (LRER: to nearest, ties away from zero; at most 16^-6 / 2 of the
 * leading digit's unit). NaN, infinities, magnitudes above the largest HFP
 * number ((1 - 16^-6) x 16^63 short, (1 - 16^-14) x 16^63 long, about
 * 7.2e75) and nonzero magnitudes below 16^-65 (about 5.4e-79) are refused
 * with DIAG_INPUT: no field is written then. */
#ifndef HFP_DATA_H
#define HFP_DATA_H
#include <stddef.h>
#include "util/diag.h"

/* Field at byte offset off of file (for the message) of width 4 or 8. */
int hfp_data_decode(const unsigned char *p, size_t width, double *out,
                    const char *file, long long off, diag *err);
int hfp_data_encode(double x, size_t width, unsigned char *p, const char *file,
                    long long off, diag *err);
#endif
