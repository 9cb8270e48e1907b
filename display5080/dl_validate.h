/* dl_validate — the validator: a dl_decode visitor that only counts, so a
 * list is checked completely (framing, codes, sizes, ranges, polygon
 * structure, end element) without drawing. Used by `maprt dl validate`. */
#ifndef DL_VALIDATE_H
#define DL_VALIDATE_H
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_decode.h"

typedef struct dl_validate_summary {
    dl_header header;
    unsigned long elements;                    /* including the end element */
    unsigned long count[DL_FORMAT_NCODES];     /* by dl_format_slot */
} dl_validate_summary;

/* Checks buf (opts as for dl_decode, may be NULL); fills *s on success.
 * Returns 0 or DIAG_INPUT with the offset. */
int dl_validate(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
                dl_validate_summary *s, diag *err);
#endif
