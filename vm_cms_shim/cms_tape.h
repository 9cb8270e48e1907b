/* cms_tape — CMS files on Hercules AWS tapes, in the two formats CMS writes:
 *   CMS TAPE DUMP (VM/370): records X'02' "CMS" + type + data; type blank =
 *     800 data bytes, 'F'/'V' = 4096 data bytes (later levels), '0' = null
 *     block (skipped), 'N' = trailer with the file's directory entry (RECFM at
 *     10, LRECL at 12, record count at 6, fn/ft/fm at 64/72/80), padded to
 *     800 bytes or short (82 bytes after the header); both are accepted.
 *   VMFPLC2: X'02' "PLCH" + 72-byte FST first, then X'02' "PLCD" data blocks
 *     of up to 4000 bytes; the file ends at the next header, a tape mark or
 *     the end of the tape. Record count: the 32-bit EDF count when non-zero,
 *     else the 16-bit one (as Hercules' vmfplc2 reads it).
 * The data is the CMS byte stream of the file (cms_recs_from_stream decodes
 * it). Files are handed to a callback one at a time, so memory stays bounded
 * by the largest file (CMS_FILE_MAX_BYTES). */
#ifndef CMS_TAPE_H
#define CMS_TAPE_H
#include <stddef.h>
#include "util/diag.h"
#include "vm_cms_shim/cms_fileid.h"

#define CMS_TAPE_MAX_FILES 10000

typedef enum cms_tape_kind { CMS_TAPE_DUMP = 1, CMS_TAPE_VMFPLC2 = 2 } cms_tape_kind;

typedef struct cms_tape_file {
    cms_tape_kind kind;
    cms_fileid id;                /* as recorded on the tape */
    char recfm;                   /* 'F' or 'V' */
    long lrecl;
    long count;                   /* records */
    const unsigned char *data;    /* CMS byte stream (valid during the callback) */
    size_t len;
    long long offset;             /* byte offset of the file's first block */
} cms_tape_file;

typedef int (*cms_tape_fn)(void *ctx, const cms_tape_file *f, diag *err);

/* Decodes an AWS image (buf, n bytes; name labels diagnostics with byte
 * offsets) and calls fn for each file in tape order; a non-zero return from fn
 * stops the scan and is returned. Returns 0, or DIAG_INPUT for a malformed
 * tape, DIAG_IO when out of memory. *nfiles (may be NULL) gets the number of
 * files handed over. */
int cms_tape_read(const unsigned char *buf, size_t n, const char *name, cms_tape_fn fn,
                  void *ctx, long *nfiles, diag *err);
#endif
