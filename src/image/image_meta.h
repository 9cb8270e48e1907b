/* image_meta — a picture's provenance as keyword/value text (what made it:
 * program version, deck and its checksum, numeric mode, size, samples,
 * date), written into PNG files as tEXt chunks and into Netpbm files as
 * '#' comment lines. */
#ifndef IMAGE_META_H
#define IMAGE_META_H
#include <stddef.h>
#include "util/diag.h"

#define IMAGE_META_MAX 16
#define IMAGE_META_KEY 40      /* PNG keywords are 1..79 Latin-1 characters */
#define IMAGE_META_VALUE 320

typedef struct image_meta {
    int n;
    struct {
        char key[IMAGE_META_KEY];
        char value[IMAGE_META_VALUE];
    } kv[IMAGE_META_MAX];
} image_meta;

void image_meta_init(image_meta *m);
/* Adds key = printf(fmt, ...); the value is cut at IMAGE_META_VALUE - 1
 * bytes, and bytes outside printable ASCII become '?'. Ignored when the
 * list is full or the key is not 1..IMAGE_META_KEY-1 printable characters. */
void image_meta_add(image_meta *m, const char *key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The current UTC time, or SOURCE_DATE_EPOCH when that is set (for
 * reproducible output), as RFC 3339 "2026-12-01T18:30:00Z". */
void image_meta_date(char out[32]);
/* Inserts m as tEXt chunks into the encoded PNG png (right after IHDR):
 * *out (mem_free it) and *outlen. DIAG_INPUT if png does not start with IHDR,
 * DIAG_IO when out of memory. */
int image_meta_png(const void *png, size_t len, const image_meta *m, void **out, size_t *outlen,
                   diag *err);
/* m as "# key: value\n" lines into buf (NUL-terminated, cut to cap). */
void image_meta_comments(const image_meta *m, char *buf, size_t cap);
#endif
