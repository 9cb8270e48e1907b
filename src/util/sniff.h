/* sniff — what kind of file this is, from its first bytes, so that a
 * command handed the wrong kind can say what it got and which command
 * reads it ("this is a PNG image, not a scene deck; did you mean `maprt
 * compare`?") instead of failing deep in its own parser. Self-contained
 * (magic numbers only), so every layer may call it. */
#ifndef SNIFF_H
#define SNIFF_H
#include <stddef.h>
#include "util/diag.h"

typedef enum sniff_kind {
    SNIFF_UNKNOWN = 0,        /* nothing recognised: let the reader judge */
    SNIFF_TEXT,               /* printable ASCII lines (a deck, perhaps) */
    SNIFF_PNG, SNIFF_JPEG, SNIFF_TIFF, SNIFF_PNM, SNIFF_GIF,
    SNIFF_DL5080,             /* "DL5080" in EBCDIC */
    SNIFF_AWS,                /* a Hercules AWS tape image */
    SNIFF_GZIP, SNIFF_ZIP, SNIFF_PDF, SNIFF_ELF,
    SNIFF_NKINDS
} sniff_kind;

#define SNIFF_BYTES 512        /* bytes looked at */

sniff_kind sniff_data(const void *data, size_t len);
/* The kind of the host file path; SNIFF_UNKNOWN if it cannot be read. */
sniff_kind sniff_file(const char *path);
/* "a PNG image", "a DL5080 display list", ... */
const char *sniff_name(sniff_kind k);
/* The maprt command that reads kind k ("maprt compare"), or NULL. */
const char *sniff_reader(sniff_kind k);
/* For the file path (labelled label in messages) handed to a command that
 * wants `wanted` ("a scene deck") and reads the kinds whose bits are set
 * in accepted (1u << SNIFF_PNG | ...; SNIFF_UNKNOWN is always accepted):
 * 0 if it is acceptable, else DIAG_INPUT with err saying what it is and
 * which command reads it. */
int sniff_refuse(const char *path, const char *label, unsigned accepted, const char *wanted, diag *err);
/* The same for data already read. */
int sniff_refuse_data(const void *data, size_t len, const char *label, unsigned accepted,
                      const char *wanted, diag *err);
#endif
