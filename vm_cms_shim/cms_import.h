/* cms_import — unpacks an interchange file from a CMS system into a disk
 * directory: an AWS tape image (CMS TAPE DUMP or VMFPLC2 files) or a punch
 * deck with :READ cards (ASCII or EBCDIC). Each CMS file becomes a host text
 * file fn.ft (F records padded to LRECL, so RECFM F survives), written
 * through cms_file (committed on close). The `maprt cms import` engine. */
#ifndef CMS_IMPORT_H
#define CMS_IMPORT_H
#include "vm_cms_shim/cms_file.h"

#define CMS_IMPORT_MAX_BYTES (256L << 20)    /* largest tape image or deck */

typedef enum cms_import_kind { CMS_IMPORT_AUTO = 0, CMS_IMPORT_TAPE, CMS_IMPORT_PUNCH } cms_import_kind;

typedef struct cms_import_opts {
    cms_import_kind kind;     /* AUTO: a tape when the AWS header fits */
    cms_form form;            /* punch decks: AUTO, PUNCH (ASCII) or EBCDIC */
    cms_cp_id cp;             /* AUTO: per file from the bytes, else 1047 */
    char disk;                /* target mode letter, 'A'..'Z' (0 = 'A') */
} cms_import_opts;

/* What was imported, one call per file (after it is committed). */
typedef struct cms_import_item {
    cms_fileid id;            /* as stored (disk letter = target) */
    char recfm;
    long lrecl, records;
    const char *source;       /* "tape dump", "vmfplc2", "punch" */
    cms_cp_id cp;
} cms_import_item;

/* Imports host file path. report may be NULL. Returns 0 or a DIAG status
 * (first error; files already committed stay). *nfiles (may be NULL) gets the
 * number imported. */
int cms_import(const cms_disks *d, const char *path, const cms_import_opts *o,
               void (*report)(void *ctx, const cms_import_item *item), void *ctx,
               long *nfiles, diag *err);
#endif
