/* cms_import — tapes and punch decks into a disk directory, as one
 * transaction (see cms_import.h). */
#include "vm_cms_shim/cms_import.h"
#include "vm_cms_shim/cms_attr.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_punch.h"
#include "vm_cms_shim/cms_tape.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define IMPORT_NAME_MAX (2 * CMS_NAME_MAX + 2)
#define IMPORT_MAX_ENTRIES 1000000L      /* directory entries read */

/* A string set with a value per key (open addressing), so that every name
 * check of an import is O(1) and 10,000 files stay linear. */
typedef struct import_map {
    char (*key)[IMPORT_NAME_MAX];
    long *val;
    size_t cap, n;        /* cap: a power of two, at least 2n */
} import_map;

static size_t cms_import_hash(const char *s)
{
    size_t h = 2166136261u;
    while (*s)
        h = (h ^ (unsigned char)*s++) * 16777619u;
    return h;
}

static void cms_import_map_free(import_map *m)
{
    mem_free(m->key);
    mem_free(m->val);
    memset(m, 0, sizeof *m);
}

/* Slot of key: its index when present (*found = 1), else the empty slot. */
static size_t cms_import_map_slot(const import_map *m, const char *key, int *found)
{
    size_t i = cms_import_hash(key) & (m->cap - 1);
    while (m->key[i][0]) {
        if (!strcmp(m->key[i], key)) {
            *found = 1;
            return i;
        }
        i = (i + 1) & (m->cap - 1);
    }
    *found = 0;
    return i;
}

static int cms_import_map_grow(import_map *m)
{
    import_map g;
    size_t i;
    memset(&g, 0, sizeof g);
    g.cap = m->cap ? 2 * m->cap : 64;
    if (!(g.key = mem_calloc(g.cap, sizeof *g.key)) || !(g.val = mem_calloc(g.cap, sizeof *g.val))) {
        cms_import_map_free(&g);
        return -1;
    }
    for (i = 0; i < m->cap; i++)
        if (m->key[i][0]) {
            int f;
            size_t s = cms_import_map_slot(&g, m->key[i], &f);
            memcpy(g.key[s], m->key[i], IMPORT_NAME_MAX);
            g.val[s] = m->val[i];
        }
    g.n = m->n;
    cms_import_map_free(m);
    *m = g;
    return 0;
}

/* Looks key up; returns its value, or -1 after inserting it with val (-2
 * when out of memory). */
static long cms_import_map_put(import_map *m, const char *key, long val)
{
    int found;
    size_t s;
    if ((m->n + 1) * 2 > m->cap && cms_import_map_grow(m))
        return -2;
    s = cms_import_map_slot(m, key, &found);
    if (found)
        return m->val[s];
    snprintf(m->key[s], IMPORT_NAME_MAX, "%s", key);
    m->val[s] = val;
    m->n++;
    return -1;
}

static long cms_import_map_get(const import_map *m, const char *key)
{
    int found;
    size_t s;
    if (!m->cap)
        return -1;
    s = cms_import_map_slot(m, key, &found);
    return found ? m->val[s] : -1;
}

/* One file staged for the commit. */
typedef struct import_file {
    cms_import_item item;
    char host[IMPORT_NAME_MAX];      /* staged name: fn.ft in lower case */
    long long where;                 /* tape offset, or card number (punch) */
    int has_attr;
    long existing;                   /* index into the disk's names, -1 = new */
} import_file;

typedef struct import_ctx {
    const cms_import_opts *o;
    char disk;
    const char *path, *dir;
    char *stage;                     /* staging directory (owned) */
    import_map names;                /* "FN.FT" -> index into files */
    import_file *files;
    size_t nfiles, capfiles;
    int punch;
} import_ctx;

static void cms_import_where(const import_ctx *c, long long w, char *buf, size_t size)
{
    if (c->punch)
        snprintf(buf, size, "%s:%lld", c->path, w);
    else
        snprintf(buf, size, "%s: offset %lld", c->path, w);
}

/* Registers id for this import; a second file of the same name is an error
 * that names both places. */
static int cms_import_claim(import_ctx *c, const cms_fileid *id, long long where, import_file **out,
                        diag *err)
{
    char key[IMPORT_NAME_MAX], a[300], b[300];
    import_file *f;
    long prev;
    snprintf(key, sizeof key, "%s.%s", id->fn, id->ft);
    prev = cms_import_map_put(&c->names, key, (long)c->nfiles);
    if (prev == -2)
        return diag_at(err, DIAG_IO, c->path, 0, 0, "out of memory");
    if (prev >= 0) {
        cms_import_where(c, c->files[prev].where, a, sizeof a);
        cms_import_where(c, where, b, sizeof b);
        return diag_at(err, DIAG_INPUT, c->path, 0, 0,
                       "%s %s occurs twice in one import: at %s and at %s (CMS holds one file "
                       "of a name per disk; rename one on CMS)", id->fn, id->ft, a, b);
    }
    if (mem_grow((void **)&c->files, &c->capfiles, c->nfiles + 1, sizeof *c->files))
        return diag_at(err, DIAG_IO, c->path, 0, 0, "out of memory");
    f = &c->files[c->nfiles++];
    memset(f, 0, sizeof *f);
    f->where = where;
    f->existing = -1;
    f->item.id = *id;
    f->item.id.mode = c->disk;
    {
        size_t k;
        for (k = 0; key[k]; k++)
            f->host[k] = (char)(key[k] >= 'A' && key[k] <= 'Z' ? key[k] - 'A' + 'a' : key[k]);
        f->host[k] = '\0';
    }
    *out = f;
    return 0;
}

/* A file in the staging directory, written in place: the directory is the
 * transaction's own, so no temporary name is needed there. */
typedef struct import_out {
    FILE *f;
    int failed;
} import_out;

static void cms_import_out_sink(void *ctx, const void *data, size_t len)
{
    import_out *o = ctx;
    if (!o->failed && len && fwrite(data, 1, len, o->f) != len)
        o->failed = 1;
}

/* Writes a decoded file into the staging directory, and its sidecar. */
static int cms_import_stage(import_ctx *c, import_file *f, const cms_recs *r, const cms_attr *attr,
                        diag *err)
{
    import_out o;
    char *p = cms_disks_join(c->stage, f->host);
    size_t i;
    int rc = 0;
    long lrecl = r->lrecl > 0 ? r->lrecl : 1;
    if (!p)
        return diag_at(err, DIAG_IO, c->path, 0, 0, "out of memory");
    o.failed = 0;
    if (!(o.f = fopen(p, "wb"))) {
        rc = diag_at(err, DIAG_IO, p, 0, 0, "cannot create: %s", strerror(errno));
        mem_free(p);
        return rc;
    }
    for (i = 0; i < r->count && !rc; i++) {
        size_t len;
        const char *rec = cms_recs_at(r, i, &len);
        if (r->binary)
            rc = cms_recs_encode_binary(r->recfm == 'F' ? CMS_FORM_EBCDIC : CMS_FORM_VSTREAM,
                                        r->recfm, lrecl, rec, len, cms_import_out_sink, &o, c->path,
                                        (long)i + 1, err);
        else
            rc = cms_recs_encode_record(CMS_FORM_TEXT, r->recfm, lrecl, NULL, rec, len,
                                        cms_import_out_sink, &o, c->path, (long)i + 1, err);
    }
    if (fclose(o.f) != 0)
        o.failed = 1;
    if (!rc && o.failed)
        rc = diag_at(err, DIAG_IO, p, 0, 0, "write failed");
    if (!rc && attr) {
        char buf[256], *a = cms_attr_path(p);
        size_t n = cms_attr_format(attr, buf, sizeof buf);
        FILE *af = a ? fopen(a, "wb") : NULL;
        if (!a)
            rc = diag_at(err, DIAG_IO, p, 0, 0, "out of memory");
        else if (!af || fwrite(buf, 1, n, af) != n)
            rc = diag_at(err, DIAG_IO, a, 0, 0, "cannot write the attribute file");
        if (af && fclose(af) != 0 && !rc)
            rc = diag_at(err, DIAG_IO, a, 0, 0, "cannot write the attribute file");
        f->has_attr = 1;      /* also on failure: unstaging removes it */
        mem_free(a);
    }
    mem_free(p);
    f->item.recfm = r->recfm;
    f->item.lrecl = lrecl;
    f->item.records = (long)r->count;
    f->item.cp = r->cp;
    return rc;
}

static int cms_import_tape_file(void *ctx, const cms_tape_file *t, diag *err)
{
    import_ctx *c = ctx;
    import_file *f;
    cms_recs r;
    cms_attr attr;
    char label[300], idt[CMS_FILEID_TEXT_MAX];
    long recno = 0, col = 0;
    unsigned char byte = 0;
    int rc, bin;
    if ((rc = cms_import_claim(c, &t->id, t->offset, &f, err)))
        return rc;
    f->item.source = t->kind == CMS_TAPE_DUMP ? "tape dump" : "vmfplc2";
    f->item.holes = t->holes;
    snprintf(f->item.date, sizeof f->item.date, "%s", t->date);
    snprintf(label, sizeof label, "%s(%s)", c->path, cms_fileid_format(&t->id, idt, sizeof idt));
    bin = cms_recs_stream_control(t->data, t->len, t->recfm, t->lrecl, t->count, &recno, &col,
                                  &byte);
    if (bin) {
        f->item.binary = 1;
        f->item.bin_rec = recno;
        f->item.bin_col = col;
        f->item.bin_byte = byte;
        if (c->o->binary == CMS_BINARY_FAIL) {
            rc = diag_at(err, DIAG_INPUT, label, recno, col,
                         "byte X'%02X' is not text: a binary file, or a text file with a stray "
                         "control byte (--binary keep or skip takes the tape anyway)", byte);
            return rc;
        }
        if (c->o->binary == CMS_BINARY_SKIP) {
            f->item.binary = 2;
            f->item.recfm = t->recfm;
            f->item.lrecl = t->lrecl;
            f->item.records = t->count;
            f->host[0] = '\0';              /* nothing staged */
            return 0;
        }
    }
    if ((rc = cms_recs_from_stream(t->data, t->len, t->recfm, t->lrecl, t->count, c->o->cp, bin,
                                   label, &r, err)))
        return rc;
    memset(&attr, 0, sizeof attr);
    attr.present = 1;
    attr.binary = bin;
    attr.recfm = t->recfm;
    attr.lrecl = t->lrecl;
    attr.num = t->id.num;
    snprintf(attr.date, sizeof attr.date, "%s", t->date);
    rc = cms_import_stage(c, f, &r, &attr, err);
    cms_recs_free(&r);
    return rc;
}

static int cms_import_punch_file(void *ctx, const cms_fileid *id, const cms_recs *r, long card,
                             diag *err)
{
    import_ctx *c = ctx;
    import_file *f;
    cms_attr attr;
    int rc;
    if ((rc = cms_import_claim(c, id, card, &f, err)))
        return rc;
    f->item.source = "punch";
    memset(&attr, 0, sizeof attr);
    attr.present = 1;
    attr.recfm = 'F';
    attr.lrecl = CMS_CARD_COLS;
    attr.num = id->num;
    return cms_import_stage(c, f, r, id->num != '1' ? &attr : NULL, err);
}

/* Upper-cased host names of the disk directory -> index into *names, read
 * once. Only names that can be fileids matter. */
static int cms_import_scan_disk(const char *dir, import_map *m, char ***names, size_t *n, diag *err)
{
    DIR *dh = opendir(dir);
    struct dirent *e;
    size_t cap = 0;
    long seen = 0;
    if (!dh)
        return diag_at(err, DIAG_IO, dir, 0, 0, "cannot read the disk directory: %s",
                       strerror(errno));
    while ((e = readdir(dh)) != NULL && seen++ < IMPORT_MAX_ENTRIES) {
        char key[IMPORT_NAME_MAX];
        size_t k, len = strlen(e->d_name);
        char *copy;
        if (len >= IMPORT_NAME_MAX || !strchr(e->d_name, '.') || e->d_name[0] == '.')
            continue;
        for (k = 0; k <= len; k++) {
            char ch = e->d_name[k];
            key[k] = (char)(ch >= 'a' && ch <= 'z' ? ch - 'a' + 'A' : ch);
        }
        if (mem_grow((void **)names, &cap, *n + 1, sizeof **names) || !(copy = mem_strdup(e->d_name))) {
            closedir(dh);
            return diag_at(err, DIAG_IO, dir, 0, 0, "out of memory");
        }
        (*names)[(*n)++] = copy;       /* the caller frees names[0 .. *n) */
        /* among case variants the byte-wise smallest wins, as cms_disks_find chooses */
        {
            long prev = cms_import_map_put(m, key, (long)*n - 1);
            if (prev == -2) {
                closedir(dh);
                return diag_at(err, DIAG_IO, dir, 0, 0, "out of memory");
            }
            if (prev >= 0 && strcmp(copy, (*names)[prev]) < 0) {
                int f;
                m->val[cms_import_map_slot(m, key, &f)] = (long)*n - 1;
            }
        }
    }
    closedir(dh);
    return 0;
}

/* Removes the staged files and the staging directory; allocates nothing,
 * so that it also cleans up after running out of memory. */
static void cms_import_unstage(import_ctx *c)
{
    char p[4096];
    size_t i;
    if (!c->stage)
        return;
    for (i = 0; i < c->nfiles; i++) {
        int n;
        if (!c->files[i].host[0])
            continue;
        n = snprintf(p, sizeof p, "%s/%s" CMS_ATTR_SUFFIX, c->stage, c->files[i].host);
        if (n < 0 || (size_t)n >= sizeof p)
            continue;
        remove(p);
        p[n - (int)strlen(CMS_ATTR_SUFFIX)] = '\0';
        remove(p);
    }
    rmdir(c->stage);
    mem_free(c->stage);
    c->stage = NULL;
}

static int cms_import_same_file(const struct stat *in, const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && st.st_dev == in->st_dev && st.st_ino == in->st_ino;
}

/* Checks every staged file against the disk, then renames them into place. */
static int cms_import_commit(import_ctx *c, diag *err)
{
    import_map disk;
    char **names = NULL, **paths = NULL, t[CMS_FILEID_TEXT_MAX];
    size_t nnames = 0, i;
    struct stat in;
    int rc, have_in = stat(c->path, &in) == 0;
    memset(&disk, 0, sizeof disk);
    rc = cms_import_scan_disk(c->dir, &disk, &names, &nnames, err);
    /* every check and every path first, so that nothing but rename() runs
     * once files move */
    if (!rc && !(paths = mem_calloc(c->nfiles ? 4 * c->nfiles : 1, sizeof *paths)))
        rc = diag_at(err, DIAG_IO, c->path, 0, 0, "out of memory");
    for (i = 0; i < c->nfiles && !rc; i++) {
        import_file *f = &c->files[i];
        char key[IMPORT_NAME_MAX], **p = paths + 4 * i;
        if (!f->host[0])
            continue;
        snprintf(key, sizeof key, "%s.%s", f->item.id.fn, f->item.id.ft);
        f->existing = cms_import_map_get(&disk, key);
        p[0] = cms_disks_join(c->stage, f->host);
        p[1] = cms_disks_join(c->dir, f->existing >= 0 ? names[f->existing] : f->host);
        p[2] = p[0] ? cms_attr_path(p[0]) : NULL;
        p[3] = p[1] ? cms_attr_path(p[1]) : NULL;
        if (!p[0] || !p[1] || !p[2] || !p[3]) {
            rc = diag_at(err, DIAG_IO, c->path, 0, 0, "out of memory");
            break;
        }
        if (f->existing < 0)
            continue;
        cms_fileid_format(&f->item.id, t, sizeof t);
        if (!c->o->replace)
            rc = diag_at(err, DIAG_INPUT, t, 0, 0, "file exists on disk %c as '%s' (nothing "
                         "imported; --replace replaces existing files)", c->disk,
                         names[f->existing]);
        else if (have_in && cms_import_same_file(&in, p[1]))
            rc = diag_at(err, DIAG_INPUT, t, 0, 0, "would replace the input '%s' itself "
                         "(import onto another disk)", c->path);
    }
    for (i = 0; i < c->nfiles && !rc; i++) {
        import_file *f = &c->files[i];
        char **p = paths + 4 * i;
        if (!f->host[0])
            continue;
        if (rename(p[0], p[1]) != 0)
            rc = diag_at(err, DIAG_IO, p[1], 0, 0, "cannot move the imported file into place: %s "
                         "(%zu of %zu files are in place)", strerror(errno), i, c->nfiles);
        else if (f->has_attr ? rename(p[2], p[3]) != 0 : (remove(p[3]) != 0 && errno != ENOENT))
            rc = diag_at(err, DIAG_IO, p[3], 0, 0, "cannot update the attribute file: %s",
                         strerror(errno));
        else
            f->host[0] = '\0';            /* committed: not staged any more */
    }
    for (i = 0; paths && i < 4 * c->nfiles; i++)
        mem_free(paths[i]);
    mem_free(paths);
    for (i = 0; i < nnames; i++)
        mem_free(names[i]);
    mem_free(names);
    cms_import_map_free(&disk);
    return rc;
}

int cms_import(const cms_disks *d, const char *path, const cms_import_opts *o,
               void (*report)(void *ctx, const cms_import_item *item), void *ctx,
               long *nfiles, diag *err)
{
    static const cms_import_opts defaults;
    import_ctx c;
    char *data = NULL;
    size_t len = 0, i;
    cms_import_kind kind;
    long written = 0;
    int rc;
    memset(&c, 0, sizeof c);
    c.o = o ? o : &defaults;
    c.disk = c.o->disk ? c.o->disk : 'A';
    c.path = path;
    if (c.disk < 'A' || c.disk > 'Z')
        return diag_at(err, DIAG_USAGE, path, 0, 0, "target disk must be a letter A-Z");
    if (!(c.dir = d->dir[c.disk - 'A'])) {
        diag_at(err, DIAG_INPUT, path, 0, 0,
                "disk not accessed (RC 36): no directory for disk %c (use --disk %c=DIR)",
                c.disk, c.disk);
        err->rc = CMS_RC_NOTACCESSED;
        return DIAG_INPUT;
    }
    if ((rc = infile_read_all(path, (size_t)CMS_IMPORT_MAX_BYTES, &data, &len, err)))
        return rc;
    if (!(c.stage = cms_disks_join(c.dir, ".maprt-import-XXXXXX")) || !mkdtemp(c.stage)) {
        rc = diag_at(err, DIAG_IO, c.dir, 0, 0, "cannot create a staging directory: %s",
                     c.stage ? strerror(errno) : "out of memory");
        mem_free(c.stage);
        mem_free(data);
        return rc;
    }
    kind = c.o->kind;
    if (kind == CMS_IMPORT_AUTO)
        kind = cms_aws_detect((const unsigned char *)data, len) ? CMS_IMPORT_TAPE : CMS_IMPORT_PUNCH;
    if (kind == CMS_IMPORT_TAPE) {
        rc = cms_tape_read((const unsigned char *)data, len, path, c.o->warn, cms_import_tape_file, &c,
                           NULL, err);
    } else {
        cms_decode_opts dopt;
        memset(&dopt, 0, sizeof dopt);
        dopt.form = c.o->form;
        dopt.cp = c.o->cp;
        c.punch = 1;
        rc = cms_punch_split((const unsigned char *)data, len, &dopt, path, cms_import_punch_file, &c,
                             NULL, err);
    }
    mem_free(data);
    if (!rc && c.nfiles == 0)
        rc = diag_at(err, DIAG_INPUT, path, 0, 0, "no CMS files found");
    if (!rc)
        rc = cms_import_commit(&c, err);
    cms_import_unstage(&c);
    if (!rc) {
        for (i = 0; i < c.nfiles; i++) {
            if (c.files[i].item.binary != 2)
                written++;
            if (report)
                report(ctx, &c.files[i].item);
        }
        if (nfiles)
            *nfiles = written;
    }
    mem_free(c.files);
    cms_import_map_free(&c.names);
    return rc;
}
