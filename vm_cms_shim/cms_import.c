/* cms_import — tapes and punch decks into a disk directory (see cms_import.h). */
#include "vm_cms_shim/cms_import.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_punch.h"
#include "vm_cms_shim/cms_tape.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

typedef struct import_ctx {
    const cms_disks *d;
    const cms_import_opts *o;
    char disk;
    const char *path;
    void (*report)(void *ctx, const cms_import_item *item);
    void *rctx;
    long files;
} import_ctx;

/* Writes one decoded file as host text on the target disk. */
static int import_write(import_ctx *c, const cms_fileid *src, const cms_recs *r,
                        const char *source, diag *err)
{
    cms_fileid id = *src;
    cms_import_item item;
    cms_file *f;
    char name[CMS_FILEID_TEXT_MAX];
    size_t i;
    int rc;
    long lrecl = r->lrecl > 0 ? r->lrecl : 1;
    id.mode = c->disk;
    cms_fileid_format(&id, name, sizeof name);
    if ((rc = cms_file_open_write(&f, c->d, name, r->recfm, lrecl, NULL, err)))
        return rc;
    for (i = 0; i < r->count; i++) {
        size_t len;
        const char *rec = cms_recs_at(r, i, &len);
        if ((rc = cms_file_write(f, rec, len, err))) {
            cms_file_abort(f);
            return rc;
        }
    }
    if ((rc = cms_file_close(f, err)))
        return rc;
    c->files++;
    if (c->report) {
        memset(&item, 0, sizeof item);
        item.id = id;
        item.recfm = r->recfm;
        item.lrecl = lrecl;
        item.records = (long)r->count;
        item.source = source;
        item.cp = r->cp;
        c->report(c->rctx, &item);
    }
    return 0;
}

static int import_tape_file(void *ctx, const cms_tape_file *f, diag *err)
{
    import_ctx *c = ctx;
    cms_recs r;
    char label[300], idt[CMS_FILEID_TEXT_MAX];
    int rc;
    snprintf(label, sizeof label, "%s(%s)", c->path, cms_fileid_format(&f->id, idt, sizeof idt));
    if ((rc = cms_recs_from_stream(f->data, f->len, f->recfm, f->lrecl, f->count, c->o->cp,
                                   label, &r, err)))
        return rc;
    rc = import_write(c, &f->id, &r, f->kind == CMS_TAPE_DUMP ? "tape dump" : "vmfplc2", err);
    cms_recs_free(&r);
    return rc;
}

static int import_punch_file(void *ctx, const cms_fileid *id, const cms_recs *r, diag *err)
{
    return import_write(ctx, id, r, "punch", err);
}

int cms_import(const cms_disks *d, const char *path, const cms_import_opts *o,
               void (*report)(void *ctx, const cms_import_item *item), void *ctx,
               long *nfiles, diag *err)
{
    static const cms_import_opts defaults;
    import_ctx c;
    char *data = NULL;
    size_t len = 0;
    cms_import_kind kind;
    int rc;
    memset(&c, 0, sizeof c);
    c.d = d;
    c.o = o ? o : &defaults;
    c.disk = c.o->disk ? c.o->disk : 'A';
    c.path = path;
    c.report = report;
    c.rctx = ctx;
    if (c.disk < 'A' || c.disk > 'Z')
        return diag_at(err, DIAG_USAGE, path, 0, 0, "target disk must be a letter A-Z");
    if ((rc = infile_read_all(path, (size_t)CMS_IMPORT_MAX_BYTES, &data, &len, err)))
        return rc;
    kind = c.o->kind;
    if (kind == CMS_IMPORT_AUTO)
        kind = cms_aws_detect((const unsigned char *)data, len) ? CMS_IMPORT_TAPE : CMS_IMPORT_PUNCH;
    if (kind == CMS_IMPORT_TAPE)
        rc = cms_tape_read((const unsigned char *)data, len, path, import_tape_file, &c, NULL, err);
    else {
        cms_decode_opts dopt;
        memset(&dopt, 0, sizeof dopt);
        dopt.form = c.o->form;
        dopt.cp = c.o->cp;
        rc = cms_punch_split((const unsigned char *)data, len, &dopt, path, import_punch_file, &c,
                             NULL, err);
    }
    mem_free(data);
    if (!rc && c.files == 0)
        rc = diag_at(err, DIAG_INPUT, path, 0, 0, "no CMS files found");
    if (nfiles)
        *nfiles = c.files;
    return rc;
}
