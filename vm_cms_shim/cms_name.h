/* cms_name — what a file argument means: a CMS fileid ("FIG1 SCENE A",
 * resolved through the disk map) or a host path (anything with '/', or a
 * single word). The CLI and the renderer call this before opening anything,
 * so input and output names behave alike everywhere. */
#ifndef CMS_NAME_H
#define CMS_NAME_H
#include "util/diag.h"
#include "vm_cms_shim/cms_disk.h"

#define CMS_NAME_LABEL_MAX 256

typedef struct cms_name {
    char *path;                      /* host path (owned) */
    int is_fileid;
    cms_fileid id;                   /* when is_fileid: with the disk found */
    char label[CMS_NAME_LABEL_MAX];  /* for diagnostics: "FIG1 SCENE A1" or the path */
} cms_name;

/* Resolves an existing input file. Errors: CMS RCs 20/24/28/36 (DIAG_INPUT,
 * err->rc set) for fileids, also for blank-separated words without '/' that
 * are no valid fileid and no existing host file ("RAY DATA A9" -> RC 24);
 * host paths are not checked here (opening them reports). Fills *n on
 * success; release with cms_name_free. */
int cms_name_input(const cms_disks *d, const char *arg, cms_name *n, diag *err);

/* Resolves an output name: a fileid goes to its disk directory (an existing
 * file of that name in any case is replaced; else fn.ft in lower case). */
int cms_name_output(const cms_disks *d, const char *arg, cms_name *n, diag *err);

void cms_name_free(cms_name *n);
#endif
