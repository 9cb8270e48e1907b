/* cms_disk — mode letters to host directories, fileids to host files. */
#include "vm_cms_shim/cms_disk.h"
#include "util/mem.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define CMS_DISK_MAX_ENTRIES 100000   /* directory entries looked at per listing */

void cms_disks_init(cms_disks *d)
{
    memset(d, 0, sizeof *d);
    d->dir[0] = mem_strdup(".");   /* NULL on OOM: A then reads as not accessed */
}

void cms_disks_free(cms_disks *d)
{
    int i;
    for (i = 0; i < CMS_DISK_COUNT; i++)
        mem_free(d->dir[i]);
    memset(d, 0, sizeof *d);
}

static int cms_disk_put(cms_disks *d, int i, const char *dir, diag *err)
{
    char *copy = mem_strdup(dir);
    if (!copy)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    mem_free(d->dir[i]);
    d->dir[i] = copy;
    return 0;
}

int cms_disks_from_env(cms_disks *d, diag *err)
{
    char name[] = "MAPRT_DISK_A";
    int i;
    for (i = 0; i < CMS_DISK_COUNT; i++) {
        const char *v;
        name[11] = (char)('A' + i);
        v = getenv(name);
        if (v && *v && cms_disk_put(d, i, v, err))
            return DIAG_IO;
    }
    return 0;
}

int cms_disks_set(cms_disks *d, const char *spec, diag *err)
{
    char l = spec[0];
    if (l >= 'a' && l <= 'z')
        l = (char)(l - 'a' + 'A');
    if (!(l >= 'A' && l <= 'Z') || spec[1] != '=' || !spec[2])
        return diag_at(err, DIAG_USAGE, "", 0, 0,
                       "--disk '%s': expected LETTER=DIRECTORY, e.g. A=scenes", spec);
    return cms_disk_put(d, l - 'A', spec + 2, err);
}

char *cms_disks_join(const char *dir, const char *name)
{
    size_t a = strlen(dir), b = strlen(name);
    char *p = mem_alloc(a + b + 2);
    if (p) {
        memcpy(p, dir, a);
        p[a] = '/';
        memcpy(p + a + 1, name, b + 1);
    }
    return p;
}

static int cms_disk_not_accessed(const cms_fileid *id, char letter, const char *dir, diag *err)
{
    char t[CMS_FILEID_TEXT_MAX];
    cms_fileid_format(id, t, sizeof t);
    if (dir)
        diag_at(err, DIAG_INPUT, t, 0, 0,
                "disk not accessed (RC 36): cannot read directory '%s' of disk %c", dir, letter);
    else
        diag_at(err, DIAG_INPUT, t, 0, 0,
                "disk not accessed (RC 36): no directory for disk %c (use --disk %c=DIR or MAPRT_DISK_%c)",
                letter, letter, letter);
    err->rc = CMS_RC_NOTACCESSED;
    return DIAG_INPUT;
}

/* Looks for "fn.ft" (any case) in dir. Returns 1 and sets *name (new string)
 * if found, 0 if not, -1 if the directory cannot be read, -2 out of memory.
 * Among several case variants the byte-wise smallest name wins, so the choice
 * does not depend on directory order. */
static int cms_disk_lookup(const char *dir, const cms_fileid *id, char **name)
{
    char want[2 * CMS_NAME_MAX + 2];
    char *best = NULL;
    struct dirent *e;
    long seen = 0;
    DIR *dh = opendir(dir);
    if (!dh)
        return -1;
    snprintf(want, sizeof want, "%s.%s", id->fn, id->ft);
    while ((e = readdir(dh)) != NULL && seen++ < CMS_DISK_MAX_ENTRIES) {
        if (strcasecmp(e->d_name, want) != 0)
            continue;
        if (!best || strcmp(e->d_name, best) < 0) {
            char *c = mem_strdup(e->d_name);
            if (!c) {
                mem_free(best);
                closedir(dh);
                return -2;
            }
            mem_free(best);
            best = c;
        }
    }
    closedir(dh);
    if (!best)
        return 0;
    *name = best;
    return 1;
}

/* Resolves id on one disk: 0 with *found 1 (and *path set) or 0 (not
 * there), else DIAG_INPUT (disk not accessed) or DIAG_IO. A disk that is not
 * accessed counts as "not there" when quiet_missing_dir (a '*' search). */
static int cms_disk_find_on(const cms_disks *d, int i, const cms_fileid *id, char **path,
                        int quiet_missing_dir, int *found, diag *err)
{
    char *name = NULL, *p;
    int r;
    *found = 0;
    if (!d->dir[i])
        return quiet_missing_dir ? 0 : cms_disk_not_accessed(id, (char)('A' + i), NULL, err);
    r = cms_disk_lookup(d->dir[i], id, &name);
    if (r == -1)
        return quiet_missing_dir ? 0 : cms_disk_not_accessed(id, (char)('A' + i), d->dir[i], err);
    if (r == -2)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    if (r == 0)
        return 0;
    p = cms_disks_join(d->dir[i], name);
    mem_free(name);
    if (!p)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    *path = p;
    *found = 1;
    return 0;
}

int cms_disks_find(const cms_disks *d, const cms_fileid *id, char **path,
                   cms_fileid *found, diag *err)
{
    char t[CMS_FILEID_TEXT_MAX];
    cms_fileid r = *id;
    int i, lo, hi, any = 0;
    if (id->mode == '*') {
        lo = 0;
        hi = CMS_DISK_COUNT - 1;
    } else {
        lo = hi = id->mode - 'A';
    }
    for (i = lo; i <= hi; i++) {
        int hit, rc = cms_disk_find_on(d, i, id, path, id->mode == '*', &hit, err);
        if (rc)
            return rc;
        if (d->dir[i])
            any = 1;
        if (hit) {
            r.mode = (char)('A' + i);
            if (found)
                *found = r;
            return 0;
        }
    }
    if (!any)
        return cms_disk_not_accessed(id, '*', NULL, err);
    diag_at(err, DIAG_INPUT, cms_fileid_format(id, t, sizeof t), 0, 0,
            "file not found (RC 28)");
    err->rc = CMS_RC_NOTFOUND;
    return DIAG_INPUT;
}

int cms_disks_output_path(const cms_disks *d, const cms_fileid *id, char **path, diag *err)
{
    char name[2 * CMS_NAME_MAX + 2], t[CMS_FILEID_TEXT_MAX];
    size_t k;
    int i, r, found;
    if (id->mode == '*') {
        diag_at(err, DIAG_INPUT, cms_fileid_format(id, t, sizeof t), 0, 0,
                "invalid filemode (RC 24): an output file needs a disk letter, not '*'");
        err->rc = CMS_RC_BADMODE;
        return DIAG_INPUT;
    }
    i = id->mode - 'A';
    if ((r = cms_disk_find_on(d, i, id, path, 0, &found, err)) != 0)
        return r;
    if (found)
        return 0;
    snprintf(name, sizeof name, "%s.%s", id->fn, id->ft);
    for (k = 0; name[k]; k++)
        if (name[k] >= 'A' && name[k] <= 'Z')
            name[k] = (char)(name[k] - 'A' + 'a');
    if (!(*path = cms_disks_join(d->dir[i], name)))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    return 0;
}

static int cms_disk_name_cmp(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Reads "fn.ft" host names into a fileid on disk letter; 0 if not one. */
static int cms_disk_host_fileid(const char *name, char letter, cms_fileid *id)
{
    const char *dot = strchr(name, '.');
    char fn[CMS_NAME_MAX + 1], ft[CMS_NAME_MAX + 1], fm[3];
    diag d;
    size_t a, b;
    if (!dot || strchr(dot + 1, '.'))
        return 0;
    a = (size_t)(dot - name);
    b = strlen(dot + 1);
    if (a == 0 || a > CMS_NAME_MAX || b == 0 || b > CMS_NAME_MAX)
        return 0;
    memset(fn, ' ', sizeof fn);
    memset(ft, ' ', sizeof ft);
    memcpy(fn, name, a);
    memcpy(ft, dot + 1, b);
    fm[0] = letter;
    fm[1] = '1';
    fm[2] = '\0';
    diag_init(&d);
    return cms_fileid_from_fields(fn, ft, fm, id, &d) == 0;
}

int cms_disks_list(const cms_disks *d, char letter,
                   int (*fn)(void *ctx, const char *path, const cms_fileid *id),
                   void *ctx, diag *err)
{
    char **names = NULL;
    size_t n = 0, cap = 0, i;
    struct dirent *e;
    cms_fileid id;
    DIR *dh;
    int rc = 0;
    memset(&id, 0, sizeof id);
    id.mode = letter;
    id.num = '1';
    strcpy(id.fn, "*");
    strcpy(id.ft, "*");
    if (letter < 'A' || letter > 'Z' || !d->dir[letter - 'A'])
        return cms_disk_not_accessed(&id, letter, NULL, err);
    if (!(dh = opendir(d->dir[letter - 'A'])))
        return cms_disk_not_accessed(&id, letter, d->dir[letter - 'A'], err);
    while ((e = readdir(dh)) != NULL && n < CMS_DISK_MAX_ENTRIES) {
        cms_fileid fid;
        char *c;
        if (!cms_disk_host_fileid(e->d_name, letter, &fid))
            continue;
        if (mem_grow((void **)&names, &cap, n + 1, sizeof *names) || !(c = mem_strdup(e->d_name))) {
            rc = diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
            break;
        }
        names[n++] = c;
    }
    closedir(dh);
    if (!rc && n)
        qsort(names, n, sizeof *names, cms_disk_name_cmp);
    for (i = 0; i < n && !rc; i++) {
        char *p = cms_disks_join(d->dir[letter - 'A'], names[i]);
        if (!p) {
            rc = diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
            break;
        }
        cms_disk_host_fileid(names[i], letter, &id);
        rc = fn(ctx, p, &id);
        mem_free(p);
    }
    for (i = 0; i < n; i++)
        mem_free(names[i]);
    mem_free(names);
    return rc;
}
