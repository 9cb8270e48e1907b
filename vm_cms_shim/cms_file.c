/* cms_file — FSOPEN/FSREAD/FSWRITE/FSCLOSE-like record access (see cms_file.h). */
#include "vm_cms_shim/cms_file.h"
#include "util/mem.h"
#include "util/outfile.h"
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
};

static void info_from_name(cms_file_info *info, const cms_name *n)
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
    char *data = NULL;
    size_t len = 0;
    int rc;
    if ((rc = cms_name_input(d, arg, &n, err)))
        return rc;
    if (!(r = mem_calloc(1, sizeof *r))) {
        cms_name_free(&n);
        return diag_at(err, DIAG_IO, arg, 0, 0, "out of memory");
    }
    info_from_name(&r->info, &n);
    if ((rc = infile_read_all(n.path, (size_t)CMS_FILE_MAX_BYTES, &data, &len, err)) != 0) {
        if (n.is_fileid)   /* name the fileid, not the host path */
            snprintf(err->file, sizeof err->file, "%s", n.label);
        cms_name_free(&n);
        mem_free(r);
        return rc;
    }
    cms_name_free(&n);
    rc = cms_recs_decode((const unsigned char *)data, len, o, r->info.label, &r->recs, err);
    mem_free(data);
    if (rc) {
        mem_free(r);
        return rc;
    }
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
    info_from_name(&w->info, &n);
    w->writing = 1;
    w->info.recfm = recfm;
    w->info.lrecl = lrecl;
    w->info.form = form;
    w->info.cp = (form == CMS_FORM_EBCDIC || form == CMS_FORM_VSTREAM) ? cp : CMS_CP_AUTO;
    if (w->info.cp != CMS_CP_AUTO && (rc = cms_cp_get(cp, &w->cp, err))) {
        cms_name_free(&n);
        mem_free(w);
        return rc;
    }
    rc = outfile_open(&w->out, n.path, err);
    cms_name_free(&n);
    if (rc) {
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
    rc = cms_recs_encode_record(f->info.form, f->info.recfm, f->info.lrecl, f->cp, rec, len,
                                outfile_sink, &f->out, f->info.label, f->pos + 1, err);
    if (rc) {
        f->failed = 1;
        return rc;
    }
    f->pos++;
    return 0;
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
        } else if ((rc = outfile_commit(&f->out, err)) != 0 && f->info.is_fileid) {
            snprintf(err->file, sizeof err->file, "%s", f->info.label);
        }
    } else {
        cms_recs_free(&f->recs);
    }
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
    mem_free(f);
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
