/* cms_import — unpacks an interchange file from a CMS system into a disk
 * directory: an AWS or HET tape image (CMS TAPE DUMP or VMFPLC2 files) or a
 * punch deck with :READ cards (ASCII or EBCDIC). Text files become host
 * text files fn.ft (F records padded to LRECL, so RECFM F survives); binary
 * files (records holding bytes no text has) keep their CMS record stream
 * byte for byte; tape files get an attribute sidecar (cms_attr) with RECFM,
 * LRECL, mode number and date. An import is one transaction: every file is
 * written to a staging directory inside the disk directory first and renamed
 * into place only when all of them decoded, so a failed import leaves the
 * disk as it was. The `maprt cms import` engine. */
#ifndef CMS_IMPORT_H
#define CMS_IMPORT_H
#include "vm_cms_shim/cms_file.h"
#include "vm_cms_shim/cms_warn.h"

#define CMS_IMPORT_MAX_BYTES (256L << 20)    /* largest tape image or deck */

typedef enum cms_import_kind { CMS_IMPORT_AUTO = 0, CMS_IMPORT_TAPE, CMS_IMPORT_PUNCH } cms_import_kind;

/* What happens to a tape file whose records are not text. */
typedef enum cms_binary_policy {
    CMS_BINARY_KEEP = 0,      /* kept byte-exact with a sidecar (default) */
    CMS_BINARY_SKIP,          /* left out, reported */
    CMS_BINARY_FAIL           /* the import fails, naming record and column */
} cms_binary_policy;

typedef struct cms_import_opts {
    cms_import_kind kind;     /* AUTO: a tape when the AWS header fits */
    cms_form form;            /* punch decks: AUTO, PUNCH (ASCII) or EBCDIC */
    cms_cp_id cp;             /* AUTO: per file from the bytes, else 1047 */
    char disk;                /* target mode letter, 'A'..'Z' (0 = 'A') */
    cms_binary_policy binary;
    int replace;              /* existing files of the same name may be replaced */
    const cms_warn *warn;     /* notes from the tape reader (may be NULL) */
} cms_import_opts;

/* What was imported, one call per file, after the whole import committed. */
typedef struct cms_import_item {
    cms_fileid id;            /* as stored (disk letter = target, mode number kept) */
    char recfm;
    long lrecl, records;
    const char *source;       /* "tape dump", "vmfplc2", "punch" */
    cms_cp_id cp;             /* text files read from EBCDIC */
    int binary;               /* 0 text, 1 kept binary, 2 skipped as binary */
    long bin_rec, bin_col;    /* where the first non-text byte is (binary != 0) */
    unsigned bin_byte;
    char date[20];            /* "" if the source has none */
    long holes;               /* null tape blocks filled with zeros */
} cms_import_item;

/* Imports host file path. report may be NULL. Returns 0 or a DIAG status
 * (the first error; nothing is left on the disk). *nfiles (may be NULL) gets
 * the number of files written (skipped ones not counted). Errors include a
 * name used twice in one import (naming both places) and an existing file
 * without o->replace. */
int cms_import(const cms_disks *d, const char *path, const cms_import_opts *o,
               void (*report)(void *ctx, const cms_import_item *item), void *ctx,
               long *nfiles, diag *err);
#endif
