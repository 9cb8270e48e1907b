/* cms_disk — the minidisk map: which host directory each CMS mode letter
 * stands for, and the lookup of fileids in those directories. Sits between the
 * fileid parser and the record reader/writer: a fileid becomes a host path
 * here. `fn ft fm` lives in DIR/fn.ft (lower case for new files; existing host
 * files match case-insensitively). */
#ifndef CMS_DISK_H
#define CMS_DISK_H
#include "util/diag.h"
#include "vm_cms_shim/cms_fileid.h"

#define CMS_DISK_COUNT 26

typedef struct cms_disks {
    char *dir[CMS_DISK_COUNT];   /* owned copies; NULL = not accessed */
} cms_disks;

/* An empty map with A accessed as the current directory ("."). */
void cms_disks_init(cms_disks *d);
void cms_disks_free(cms_disks *d);

/* Applies MAPRT_DISK_A .. MAPRT_DISK_Z from the environment (an empty value
 * is ignored). Returns 0 or DIAG_IO (out of memory). */
int cms_disks_from_env(cms_disks *d, diag *err);

/* Applies one "--disk" argument "L=DIR" (letter case-insensitive, DIR not
 * empty). Returns 0, DIAG_USAGE for a malformed spec, or DIAG_IO. Later calls
 * override earlier ones and the environment. */
int cms_disks_set(cms_disks *d, const char *spec, diag *err);

/* Finds an existing file. For mode '*' the accessed disks are searched A..Z
 * and the first hit wins; *found gets the fileid with that disk's letter.
 * On success *path is a new host path (mem_free it). Errors (DIAG_INPUT with
 * err->rc): CMS_RC_NOTFOUND, CMS_RC_NOTACCESSED (disk not in the map or its
 * directory cannot be read). */
int cms_disks_find(const cms_disks *d, const cms_fileid *id, char **path,
                   cms_fileid *found, diag *err);

/* Host path for writing id (mode must be a letter): an existing file of that
 * name (any case) is reused, else DIR/fn.ft in lower case. Errors as above
 * (CMS_RC_NOTACCESSED; CMS_RC_BADMODE for mode '*'). */
int cms_disks_output_path(const cms_disks *d, const cms_fileid *id, char **path, diag *err);

/* dir "/" name as a new string (mem_free it); NULL when out of memory. */
char *cms_disks_join(const char *dir, const char *name);

/* Calls fn(ctx, host_name, id) for every host file in disk `letter` whose name
 * is a valid "fn.ft" fileid, in byte order of the host names; stops at the
 * first non-zero return and returns it. Errors: CMS_RC_NOTACCESSED. */
int cms_disks_list(const cms_disks *d, char letter,
                   int (*fn)(void *ctx, const char *path, const cms_fileid *id),
                   void *ctx, diag *err);
#endif
