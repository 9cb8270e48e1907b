/* cms_file — FSOPEN/FSREAD/FSWRITE/FSCLOSE-like record access (see cms_file.h). */
#include "vm_cms_shim/cms_file.h"
#include "vm_cms_shim/cms_attr.h"
#include "util/mem.h"
#include "util/outfile.h"
#include "util/sha256.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>

struct cms_file {
    int writing;
    cms_file_info info;
    long pos;                 /* records read so far / last record number */
    cms_recs recs;            /* reading */
    outfile out;              /* writing */
    const cms_cp *cp;         /* writing EBCDIC forms */
    int failed;               /* writing: an error occurred, do not commit */
    cms_attr attr;            /* writing: the sidecar to commit (present = 1) */
    char *path;               /* writing: the host path (owned) */
};

/* A text file's records fit a sidecar's RECFM/LRECL (F: every record exactly
 * LRECL columns; V: none longer). */
static int cms_file_attr_fits(const cms_recs *r, char recfm, long lrecl)
{
    size_t i;
    for (i = 0; i < r->count; i++) {
        size_t len, k, cols = 0;
        const char *s = cms_recs_at(r, i, &len);
        for (k = 0; k < len; k++)
            cols += ((unsigned char)s[k] & 0xC0) != 0x80;
        if ((long)cols > lrecl || (recfm == 'F' && (long)cols != lrecl))
            return 0;
    }
    return 1;
}

static void cms_file_info_from_name(cms_file_info *info, const cms_name *n)
{
    memset(info, 0, sizeof *info);
    snprintf(info->label, sizeof info->label, "%s", n->label);
    info->is_fileid = n->is_fileid;
    info->id = n->id;
}

int cms_file_open_read(cms_file **f, const cms_disks *d, const char *arg,
                       const cms_decode_opts *o, diag *err)
{
    cms_name n;
    cms_file *r;
    cms_attr attr;
    char *data = NULL;
    size_t len = 0;
    int rc;
    if ((rc = cms_name_input(d, arg, &n, err)))
        return rc;
    if (!(r = mem_calloc(1, sizeof *r))) {
        cms_name_free(&n);
        return diag_at(err, DIAG_IO, arg, 0, 0, "out of memory");
    }
    cms_file_info_from_name(&r->info, &n);
    if ((rc = infile_read_all(n.path, (size_t)CMS_FILE_MAX_BYTES, &data, &len, err)) != 0) {
        if (n.is_fileid)   /* name the fileid, not the host path */
            snprintf(err->file, sizeof err->file, "%s", n.label);
        cms_name_free(&n);
        mem_free(r);
        return rc;
    }
    {
        sha256 h;                 /* the bytes decoded, for a picture's provenance */
        sha256_init(&h);
        if (len)
            sha256_update(&h, data, len);
        sha256_hex(&h, r->info.sha256);
    }
    rc = cms_attr_read(n.path, &attr, err);
    cms_name_free(&n);
    if (!rc && attr.present && attr.binary) {
        if (!attr.recfm || !attr.lrecl)
            rc = diag_at(err, DIAG_INPUT, r->info.label, 0, 0,
                         "binary file: its attribute file names no recfm and lrecl");
        else
            rc = cms_recs_from_stream((const unsigned char *)data, len, attr.recfm, attr.lrecl, -1,
                                      CMS_CP_AUTO, 1, r->info.label, &r->recs, err);
    } else if (!rc) {
        rc = cms_recs_decode((const unsigned char *)data, len, o, r->info.label, &r->recs, err);
        if (!rc && attr.present && attr.recfm && attr.lrecl &&
            cms_file_attr_fits(&r->recs, attr.recfm, attr.lrecl)) {
            r->recs.recfm = attr.recfm;
            r->recs.lrecl = attr.lrecl;
        }
    }
    mem_free(data);
    if (rc) {
        mem_free(r);
        return rc;
    }
    r->info.binary = r->recs.binary;
    if (attr.present && attr.num)
        r->info.id.num = attr.num;
    snprintf(r->info.date, sizeof r->info.date, "%s", attr.date);
    r->info.recfm = r->recs.recfm;
    r->info.lrecl = r->recs.lrecl;
    r->info.records = (long)r->recs.count;
    r->info.form = r->recs.form;
    r->info.cp = r->recs.cp;
    r->info.has_header = r->recs.has_header;
    r->info.header = r->recs.header;
    *f = r;
    return 0;
}

int cms_file_read(cms_file *f, long recno, const char **rec, size_t *len)
{
    long i = recno > 0 ? recno : f->pos + 1;
    if (f->writing || i < 1 || (unsigned long)i > f->recs.count)
        return CMS_RC_EOF;
    *rec = cms_recs_at(&f->recs, (size_t)i - 1, len);
    f->pos = i;
    return 0;
}

long cms_file_recno(const cms_file *f) { return f->pos; }

void cms_file_state(const cms_file *f, cms_file_info *info)
{
    *info = f->info;
    if (f->writing)
        info->records = f->pos;
}

int cms_file_open_write(cms_file **f, const cms_disks *d, const char *arg, char recfm,
                        long lrecl, const cms_write_opts *o, diag *err)
{
    cms_form form = o && o->form != CMS_FORM_AUTO ? o->form : CMS_FORM_TEXT;
    cms_cp_id cp = o && o->cp != CMS_CP_AUTO ? o->cp : CMS_CP_1047;
    cms_name n;
    cms_file *w;
    int rc;
    if (recfm != 'F' && recfm != 'V')
        return diag_at(err, DIAG_USAGE, arg, 0, 0, "RECFM must be F or V");
    if (lrecl < 1 || lrecl > CMS_LRECL_MAX)
        return diag_at(err, DIAG_USAGE, arg, 0, 0, "LRECL %ld is outside 1..%d", lrecl, CMS_LRECL_MAX);
    if (form == CMS_FORM_RDW)
        return diag_at(err, DIAG_USAGE, arg, 0, 0, "RDW streams are read, not written");
    if ((rc = cms_name_output(d, arg, &n, err)))
        return rc;
    if (!(w = mem_calloc(1, sizeof *w))) {
        cms_name_free(&n);
        return diag_at(err, DIAG_IO, arg, 0, 0, "out of memory");
    }
    cms_file_info_from_name(&w->info, &n);
    w->writing = 1;
    w->info.recfm = recfm;
    w->info.lrecl = lrecl;
    w->info.form = form;
    w->info.cp = (form == CMS_FORM_EBCDIC || form == CMS_FORM_VSTREAM) ? cp : CMS_CP_AUTO;
    w->info.binary = o && o->binary;
    if (w->info.binary && form != CMS_FORM_EBCDIC && form != CMS_FORM_VSTREAM) {
        cms_name_free(&n);
        mem_free(w);
        return diag_at(err, DIAG_USAGE, arg, 0, 0, "a binary file is written as ebcdic, "
                       "vstream or a tape (aws, het), not as %s", cms_form_name(form));
    }
    if (w->info.binary || (o && o->num && o->num != '1')) {
        w->attr.present = 1;
        w->attr.binary = w->info.binary;
        w->attr.recfm = recfm;
        w->attr.lrecl = lrecl;
        w->attr.num = o && o->num ? o->num : 0;
        snprintf(w->attr.date, sizeof w->attr.date, "%s", o && o->date ? o->date : "");
    }
    if (w->info.cp != CMS_CP_AUTO && (rc = cms_cp_get(cp, &w->cp, err))) {
        cms_name_free(&n);
        mem_free(w);
        return rc;
    }
    if (!(w->path = mem_strdup(n.path))) {
        cms_name_free(&n);
        mem_free(w);
        return diag_at(err, DIAG_IO, arg, 0, 0, "out of memory");
    }
    rc = outfile_open(&w->out, n.path, err);
    cms_name_free(&n);
    if (rc) {
        mem_free(w->path);
        mem_free(w);
        return rc;
    }
    if (form == CMS_FORM_PUNCH) {
        const cms_fileid *h = o && o->header ? o->header : (w->info.is_fileid ? &w->info.id : NULL);
        if (h) {
            w->info.has_header = 1;
            w->info.header = *h;
            cms_recs_punch_header(h, outfile_sink, &w->out);
        }
    }
    *f = w;
    return 0;
}

int cms_file_write(cms_file *f, const char *rec, size_t len, diag *err)
{
    int rc;
    if (!f->writing)
        return diag_at(err, DIAG_USAGE, f->info.label, 0, 0, "file is open for reading");
    if (f->info.binary)
        rc = cms_recs_encode_binary(f->info.form, f->info.recfm, f->info.lrecl, rec, len,
                                    outfile_sink, &f->out, f->info.label, f->pos + 1, err);
    else
        rc = cms_recs_encode_record(f->info.form, f->info.recfm, f->info.lrecl, f->cp, rec, len,
                                    outfile_sink, &f->out, f->info.label, f->pos + 1, err);
    if (rc) {
        f->failed = 1;
        return rc;
    }
    f->pos++;
    return 0;
}

void cms_file_put_raw(cms_file *f, const void *data, size_t len)
{
    if (f->writing)
        outfile_sink(&f->out, data, len);
}

int cms_file_close(cms_file *f, diag *err)
{
    int rc = 0;
    if (!f)
        return 0;
    if (f->writing) {
        if (f->failed) {
            outfile_abort(&f->out);
            rc = diag_at(err, DIAG_INPUT, f->info.label, 0, 0, "not written: a record was rejected");
        } else if ((rc = outfile_commit(&f->out, err)) != 0) {
            if (f->info.is_fileid)
                snprintf(err->file, sizeof err->file, "%s", f->info.label);
        } else if (f->attr.present) {
            rc = cms_attr_write(f->path, &f->attr, err);
        } else {
            char *a = cms_attr_path(f->path);
            if (a && remove(a) != 0 && errno != ENOENT)
                rc = diag_at(err, DIAG_IO, a, 0, 0, "cannot remove the stale attribute file: %s",
                             strerror(errno));
            mem_free(a);
        }
    } else {
        cms_recs_free(&f->recs);
    }
    mem_free(f->path);
    mem_free(f);
    return rc;
}

void cms_file_abort(cms_file *f)
{
    if (!f)
        return;
    if (f->writing)
        outfile_abort(&f->out);
    else
        cms_recs_free(&f->recs);
    mem_free(f->path);
    mem_free(f);
}

typedef struct file_mem {
    unsigned char *p;
    size_t n, cap;
    int failed;
} file_mem;

static void cms_file_mem_sink(void *ctx, const void *data, size_t len)
{
    file_mem *m = ctx;
    if (m->failed || !len)
        return;
    if (m->n + len > (size_t)CMS_FILE_MAX_BYTES || mem_grow((void **)&m->p, &m->cap, m->n + len, 1)) {
        m->failed = 1;
        return;
    }
    memcpy(m->p + m->n, data, len);
    m->n += len;
}

int cms_file_stream(const cms_file *f, cms_cp_id cp_id, unsigned char **data, size_t *len,
                    diag *err)
{
    cms_form form = f->info.recfm == 'F' ? CMS_FORM_EBCDIC : CMS_FORM_VSTREAM;
    const cms_cp *cp = NULL;
    file_mem m;
    size_t i;
    int rc;
    if (f->writing)
        return diag_at(err, DIAG_USAGE, f->info.label, 0, 0, "file is open for writing");
    if (!f->recs.binary &&
        (rc = cms_cp_get(cp_id != CMS_CP_AUTO ? cp_id : CMS_CP_1047, &cp, err)))
        return rc;
    memset(&m, 0, sizeof m);
    for (i = 0; i < f->recs.count; i++) {
        size_t n;
        const char *rec = cms_recs_at(&f->recs, i, &n);
        rc = f->recs.binary
             ? cms_recs_encode_binary(form, f->info.recfm, f->info.lrecl, rec, n, cms_file_mem_sink, &m,
                                      f->info.label, (long)i + 1, err)
             : cms_recs_encode_record(form, f->info.recfm, f->info.lrecl, cp, rec, n, cms_file_mem_sink,
                                      &m, f->info.label, (long)i + 1, err);
        if (rc) {
            mem_free(m.p);
            return rc;
        }
    }
    if (m.failed) {
        mem_free(m.p);
        return diag_at(err, DIAG_IO, f->info.label, 0, 0, "out of memory");
    }
    *data = m.p;
    *len = m.n;
    return 0;
}

int cms_file_stat(const cms_disks *d, const char *arg, const cms_decode_opts *o,
                  cms_file_info *info, diag *err)
{
    cms_file *f;
    int rc = cms_file_open_read(&f, d, arg, o, err);
    if (rc)
        return rc;
    *info = f->info;
    cms_file_abort(f);
    return 0;
}

int cms_file_erase(const cms_disks *d, const char *arg, diag *err)
{
    cms_name n;
    int rc = cms_name_input(d, arg, &n, err);
    if (rc)
        return rc;
    if (remove(n.path) != 0) {
        int e = errno;
        if (e == ENOENT) {
            diag_at(err, DIAG_INPUT, n.label, 0, 0, "file not found (RC 28)");
            err->rc = CMS_RC_NOTFOUND;
            rc = DIAG_INPUT;
        } else {
            rc = diag_at(err, DIAG_IO, n.label, 0, 0, "cannot erase: %s", strerror(e));
        }
    }
    cms_name_free(&n);
    return rc;
}
