/* cms_name — fileid-or-path arguments to host paths (see cms_name.h). */
#include "vm_cms_shim/cms_name.h"
#include "util/mem.h"
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int cms_name_path(const char *arg, cms_name *n, diag *err)
{
    memset(n, 0, sizeof *n);
    if (!(n->path = mem_strdup(arg)))
        return diag_at(err, DIAG_IO, arg, 0, 0, "out of memory");
    snprintf(n->label, sizeof n->label, "%s", arg);
    return 0;
}

/* Fills n for a resolved fileid (path owned by n from here on). */
static int cms_name_fileid(cms_name *n, char *path, const cms_fileid *id)
{
    memset(n, 0, sizeof *n);
    n->path = path;
    n->is_fileid = 1;
    n->id = *id;
    cms_fileid_format(id, n->label, sizeof n->label);
    return 0;
}

int cms_name_input(const cms_disks *d, const char *arg, cms_name *n, diag *err)
{
    cms_fileid id, found;
    char *path = NULL;
    int rc;
    if (!cms_fileid_is_fileid(arg)) {
        /* "RAY DATA A9": meant as a fileid unless such a host file exists */
        if (!strchr(arg, '/') && strchr(arg, ' ') && access(arg, F_OK) != 0) {
            cms_fileid_parse(arg, &id, err);
            return DIAG_INPUT;
        }
        return cms_name_path(arg, n, err);
    }
    cms_fileid_parse(arg, &id, err);
    if ((rc = cms_disks_find(d, &id, &path, &found, err)))
        return rc;
    return cms_name_fileid(n, path, &found);
}

int cms_name_output(const cms_disks *d, const char *arg, cms_name *n, diag *err)
{
    cms_fileid id;
    char *path = NULL;
    int rc;
    if (!cms_fileid_is_fileid(arg))
        return cms_name_path(arg, n, err);
    cms_fileid_parse(arg, &id, err);
    if ((rc = cms_disks_output_path(d, &id, &path, err)))
        return rc;
    return cms_name_fileid(n, path, &id);
}

void cms_name_free(cms_name *n)
{
    mem_free(n->path);
    n->path = NULL;
}
