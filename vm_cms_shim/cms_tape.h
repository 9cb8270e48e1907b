/* cms_tape — CMS files on Hercules AWS/HET tapes, in the two formats CMS writes:
 *   CMS TAPE DUMP (VM/370): records X'02' "CMS" + type + data; type blank =
 *     800 data bytes, 'F'/'V' = 4096 data bytes (later levels), '0' = null
 *     block (a hole of zeros in a sparse file), 'N' = trailer with the file's
 *     directory entry (RECFM at 10, LRECL at 12, 16-bit record count at 6,
 *     32-bit count at 32, fn/ft/fm at 64/72/80), padded to 800 bytes or short
 *     (82 bytes after the header). A data block shorter than the others is
 *     accepted as the file's last.
 *   VMFPLC2: X'02' "PLCH" + 72-byte FST first, then X'02' "PLCD" data blocks
 *     of up to 4000 bytes; the file ends at the next header, a tape mark or
 *     the end of the tape.
 * Record counts: VMFPLC2 takes the 32-bit EDF count when non-zero, else the
 * 16-bit one (as Hercules' vmfplc2 reads it). TAPE DUMP takes the 32-bit
 * count when it is non-zero and its low 16 bits equal the 16-bit count (a
 * VM/SP file of more than 65,535 records keeps the low half there; a VM/370
 * trailer has no 32-bit field, and what its bytes hold is then not a count),
 * else the 16-bit count; a disagreement is reported through the warning hook.
 * Tape files of 80-byte standard labels (VOL1, HDR1.., EOF1.., EOV1..,
 * UHL/UTL) are skipped with a note.
 * The data is the CMS byte stream of the file (cms_recs_from_stream decodes
 * it). Files are handed to a callback one at a time, so memory stays bounded
 * by the largest file (CMS_FILE_MAX_BYTES). The writer side produces both
 * formats (cms_tape_writer). */
#ifndef CMS_TAPE_H
#define CMS_TAPE_H
#include <stddef.h>
#include "util/diag.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_fileid.h"
#include "vm_cms_shim/cms_warn.h"

#define CMS_TAPE_MAX_FILES 100000

typedef enum cms_tape_kind { CMS_TAPE_DUMP = 1, CMS_TAPE_VMFPLC2 = 2 } cms_tape_kind;

typedef struct cms_tape_file {
    cms_tape_kind kind;
    cms_fileid id;                /* as recorded on the tape, mode number included */
    char recfm;                   /* 'F' or 'V' */
    long lrecl;
    long count;                   /* records */
    char date[20];                /* "YYYY-MM-DD HH:MM[:SS]" last written, "" if unknown */
    const unsigned char *data;    /* CMS byte stream (valid during the callback) */
    size_t len;
    long long offset;             /* byte offset of the file's first block */
    long holes;                   /* null blocks filled with zeros */
} cms_tape_file;

typedef int (*cms_tape_fn)(void *ctx, const cms_tape_file *f, diag *err);

/* Decodes an AWS or HET image (buf, n bytes; name labels diagnostics with
 * byte offsets) and calls fn for each file in tape order; a non-zero return
 * from fn stops the scan and is returned. Notes go to warn (may be NULL).
 * Returns 0, or DIAG_INPUT for a malformed tape, DIAG_IO when out of memory.
 * *nfiles (may be NULL) gets the number of files handed over. */
int cms_tape_read(const unsigned char *buf, size_t n, const char *name, const cms_warn *warn,
                  cms_tape_fn fn, void *ctx, long *nfiles, diag *err);

/* ---- writing ------------------------------------------------------------ */

typedef struct cms_tape_writer {
    cms_aws_writer aws;
    cms_tape_kind kind;
} cms_tape_writer;

/* A tape of kind DUMP or VMFPLC2 in container comp (PLAIN = AWS, else HET). */
void cms_tape_writer_init(cms_tape_writer *t, cms_tape_kind kind, cms_aws_comp comp,
                          cms_aws_sink sink, void *ctx);
/* Writes one file: f->id (fn ft fm with mode number), recfm, lrecl, count,
 * date ("" = none) and the CMS byte stream f->data/f->len (F: count*lrecl
 * bytes; V: count 2-byte-length records). Returns 0 or DIAG_USAGE for
 * values the format cannot hold, DIAG_IO. */
int cms_tape_write_file(cms_tape_writer *t, const cms_tape_file *f, diag *err);
/* Ends the tape: two tape marks (the end-of-volume convention Hercules'
 * utilities stop at), and releases the writer. */
void cms_tape_writer_end(cms_tape_writer *t);
#endif
