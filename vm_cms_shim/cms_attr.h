/* cms_attr — the attribute sidecar of a host file: what a CMS file carries
 * beyond its bytes (RECFM, LRECL, mode number, date last written, and
 * whether the records are binary). The sidecar of DIR/fn.ft is DIR/fn.ft.cms,
 * a text file of "key value" lines:
 *     maprt-cms-attributes 1
 *     form binary            (or text)
 *     recfm V
 *     lrecl 80
 *     mode 2
 *     date 1984-12-05 12:31:21
 * A binary file's host bytes are its CMS record stream, untranslated: F =
 * the records concatenated (a multiple of LRECL), V = each record led by a
 * 2-byte big-endian length. Listings skip sidecars (their names hold two
 * dots, which no fileid's host name does). */
#ifndef CMS_ATTR_H
#define CMS_ATTR_H
#include <stddef.h>
#include "util/diag.h"

#define CMS_ATTR_SUFFIX ".cms"

typedef struct cms_attr {
    int present;          /* a sidecar was read / is to be written */
    int binary;
    char recfm;           /* 'F', 'V', or 0 = unknown */
    long lrecl;           /* 0 = unknown */
    char num;             /* mode number '0'..'6', 0 = unknown */
    char date[20];        /* "YYYY-MM-DD HH:MM[:SS]", "" = unknown */
} cms_attr;

/* The sidecar path of host file path (mem_free it); NULL when out of memory. */
char *cms_attr_path(const char *path);

/* Reads the sidecar of host file path into *a; a missing sidecar gives
 * a->present = 0 and status 0. Errors: DIAG_INPUT with file:line:col for a
 * malformed sidecar, DIAG_IO. */
int cms_attr_read(const char *path, cms_attr *a, diag *err);

/* Parses sidecar text (data, len bytes; name labels the diagnostics). */
int cms_attr_parse(const char *data, size_t len, const char *name, cms_attr *a, diag *err);

/* Writes the sidecar of path (committed through util/outfile). */
int cms_attr_write(const char *path, const cms_attr *a, diag *err);

/* Formats the sidecar text into buf (at least 160 bytes); returns its length. */
size_t cms_attr_format(const cms_attr *a, char *buf, size_t size);
#endif
