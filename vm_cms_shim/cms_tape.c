/* cms_tape — CMS TAPE DUMP and VMFPLC2 files out of AWS images (see cms_tape.h). */
#include "vm_cms_shim/cms_tape.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_cp.h"
#include "vm_cms_shim/cms_recs.h"
#include "util/mem.h"
#include <string.h>

#define TAPE_HDR 5
#define TAPE_TRAILER_MIN 82          /* trailer bytes after the header */
#define PLC_FST 72

static const unsigned char hdr_cms[4] = {0x02, 0xC3, 0xD4, 0xE2};      /* X'02' CMS */
static const unsigned char hdr_plch[5] = {0x02, 0xD7, 0xD3, 0xC3, 0xC8};
static const unsigned char hdr_plcd[5] = {0x02, 0xD7, 0xD3, 0xC3, 0xC4};

static unsigned long be(const unsigned char *p, int n)
{
    unsigned long v = 0;
    while (n--)
        v = (v << 8) | *p++;
    return v;
}

/* File being collected. */
typedef struct tape_state {
    cms_tape_kind kind;           /* 0 = none */
    unsigned char *data;
    size_t len, cap;
    long long offset;
    cms_tape_file plc;            /* VMFPLC2: from the header */
    long nfiles;
    const char *name;
    cms_tape_fn fn;
    void *ctx;
} tape_state;

static int tape_append(tape_state *t, const unsigned char *p, size_t n, long long off, diag *err)
{
    if (t->len + n > (size_t)CMS_FILE_MAX_BYTES)
        return diag_offset(err, DIAG_INPUT, t->name, off, "file larger than %ld bytes",
                           CMS_FILE_MAX_BYTES);
    if (n && mem_grow((void **)&t->data, &t->cap, t->len + n, 1))
        return diag_offset(err, DIAG_IO, t->name, off, "out of memory");
    if (n)
        memcpy(t->data + t->len, p, n);
    t->len += n;
    return 0;
}

/* Directory-entry name fields (EBCDIC) to a fileid. */
static int tape_fileid(const unsigned char *fn, const unsigned char *ft, const unsigned char *fm,
                       cms_fileid *id, const char *name, long long off, diag *err)
{
    const cms_cp *cp;
    char a[8], b[8], c[2];
    int i, rc;
    diag sub;
    if ((rc = cms_cp_get(CMS_CP_1047, &cp, err)))   /* fileid characters are the same in 037 */
        return rc;
    for (i = 0; i < 8; i++) {
        a[i] = (char)cp->to_latin1[fn[i]];
        b[i] = (char)cp->to_latin1[ft[i]];
    }
    c[0] = (char)cp->to_latin1[fm[0]];
    c[1] = (char)cp->to_latin1[fm[1]];
    diag_init(&sub);
    if (cms_fileid_from_fields(a, b, c, id, &sub)) {
        diag_offset(err, DIAG_INPUT, name, off, "directory entry: %s", sub.msg);
        err->rc = sub.rc;
        return DIAG_INPUT;
    }
    return 0;
}

static int tape_recfm(unsigned char b, char *recfm, const char *name, long long off, diag *err)
{
    if (b == 0xC6)
        *recfm = 'F';
    else if (b == 0xE5)
        *recfm = 'V';
    else
        return diag_offset(err, DIAG_INPUT, name, off, "RECFM byte X'%02X' is neither F nor V", b);
    return 0;
}

static int tape_emit(tape_state *t, cms_tape_file *f, diag *err)
{
    int rc;
    if (t->nfiles >= CMS_TAPE_MAX_FILES)
        return diag_offset(err, DIAG_INPUT, t->name, f->offset, "more than %d files on the tape",
                           CMS_TAPE_MAX_FILES);
    f->data = t->data ? t->data : (const unsigned char *)"";
    f->len = t->len;
    f->offset = t->offset;
    t->nfiles++;
    rc = t->fn(t->ctx, f, err);
    t->len = 0;
    t->kind = 0;
    return rc;
}

/* CMS TAPE DUMP trailer: p points after the 5-byte header, n bytes. */
static int dump_trailer(tape_state *t, const unsigned char *p, size_t n, long long off, diag *err)
{
    cms_tape_file f;
    int rc;
    memset(&f, 0, sizeof f);
    if (n < TAPE_TRAILER_MIN)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "CMS tape trailer of %zu bytes is shorter than %d", n, TAPE_TRAILER_MIN);
    f.kind = CMS_TAPE_DUMP;
    if ((rc = tape_recfm(p[10], &f.recfm, t->name, off + TAPE_HDR + 10, err)) ||
        (rc = tape_fileid(p + 64, p + 72, p + 80, &f.id, t->name, off + TAPE_HDR + 64, err)))
        return rc;
    f.lrecl = (long)be(p + 12, 4);
    f.count = (long)be(p + 6, 2);
    if (f.lrecl < 1 || f.lrecl > CMS_LRECL_MAX)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_HDR + 12,
                           "LRECL %lu is outside 1..%d", be(p + 12, 4), CMS_LRECL_MAX);
    if (t->kind == 0)
        t->offset = off;
    return tape_emit(t, &f, err);
}

/* VMFPLC2 header: the FST. */
static int plc_header(tape_state *t, const unsigned char *p, size_t n, long long off, diag *err)
{
    cms_tape_file *f = &t->plc;
    unsigned long aic;
    int rc;
    memset(f, 0, sizeof *f);
    if (n < PLC_FST)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "VMFPLC2 header of %zu bytes is shorter than the %d-byte FST", n, PLC_FST);
    f->kind = CMS_TAPE_VMFPLC2;
    if ((rc = tape_recfm(p[30], &f->recfm, t->name, off + TAPE_HDR + 30, err)) ||
        (rc = tape_fileid(p, p + 8, p + 24, &f->id, t->name, off + TAPE_HDR, err)))
        return rc;
    f->lrecl = (long)be(p + 32, 4);
    if (f->lrecl < 1 || f->lrecl > CMS_LRECL_MAX)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_HDR + 32,
                           "LRECL %lu is outside 1..%d", be(p + 32, 4), CMS_LRECL_MAX);
    aic = be(p + 56, 4);
    if (aic > 0x7FFFFFFFUL)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_HDR + 56,
                           "record count %lu is too large", aic);
    f->count = aic ? (long)aic : (long)be(p + 26, 2);
    t->kind = CMS_TAPE_VMFPLC2;
    t->len = 0;
    t->offset = off;
    return 0;
}

/* Ends a VMFPLC2 file in progress (at a header, tape mark or end). */
static int plc_finish(tape_state *t, diag *err)
{
    if (t->kind != CMS_TAPE_VMFPLC2)
        return 0;
    return tape_emit(t, &t->plc, err);
}

static int dump_open_check(tape_state *t, long long off, const char *what, diag *err)
{
    if (t->kind == CMS_TAPE_DUMP)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "%s before the CMS tape trailer ('N' block) of the file at offset %lld",
                           what, t->offset);
    return 0;
}

static int tape_record(tape_state *t, const unsigned char *r, size_t n, long long off, diag *err)
{
    int rc;
    if (n >= TAPE_HDR && memcmp(r, hdr_cms, 4) == 0) {
        const unsigned char *p = r + TAPE_HDR;
        size_t pn = n - TAPE_HDR;
        unsigned char type = r[4];
        if ((rc = plc_finish(t, err)))
            return rc;
        if (type == 0xD5)                                   /* 'N' */
            return dump_trailer(t, p, pn, off, err);
        if (type == 0x40 || type == 0xC6 || type == 0xE5 || type == 0xF0) {
            size_t want = type == 0x40 ? 800 : type == 0xF0 ? pn : 4096;
            if (type == 0xF0 && pn != 800 && pn != 4096)
                want = 800;
            if (pn != want)
                return diag_offset(err, DIAG_INPUT, t->name, off,
                                   "CMS tape data block of %zu bytes (expected %zu)", pn, want);
            if (t->kind == 0) {
                t->kind = CMS_TAPE_DUMP;
                t->offset = off;
                t->len = 0;
            }
            if (type == 0xF0)                               /* '0': null block */
                return 0;
            return tape_append(t, p, pn, off, err);
        }
        return diag_offset(err, DIAG_INPUT, t->name, off + 4,
                           "unknown CMS tape block type X'%02X'", type);
    }
    if (n >= TAPE_HDR && memcmp(r, hdr_plch, 5) == 0) {
        if ((rc = dump_open_check(t, off, "VMFPLC2 header", err)) || (rc = plc_finish(t, err)))
            return rc;
        return plc_header(t, r + TAPE_HDR, n - TAPE_HDR, off, err);
    }
    if (n >= TAPE_HDR && memcmp(r, hdr_plcd, 5) == 0) {
        if (t->kind != CMS_TAPE_VMFPLC2)
            return diag_offset(err, DIAG_INPUT, t->name, off, "VMFPLC2 data block without a header");
        if (n - TAPE_HDR > 4000)
            return diag_offset(err, DIAG_INPUT, t->name, off,
                               "VMFPLC2 data block of %zu bytes (at most 4000)", n - TAPE_HDR);
        return tape_append(t, r + TAPE_HDR, n - TAPE_HDR, off, err);
    }
    return diag_offset(err, DIAG_INPUT, t->name, off,
                       "tape record of %zu bytes is neither CMS TAPE DUMP nor VMFPLC2 "
                       "(starts %02X %02X %02X %02X)", n, r[0], n > 1 ? r[1] : 0,
                       n > 2 ? r[2] : 0, n > 3 ? r[3] : 0);
}

int cms_tape_read(const unsigned char *buf, size_t n, const char *name, cms_tape_fn fn,
                  void *ctx, long *nfiles, diag *err)
{
    tape_state t;
    cms_aws a;
    int rc = 0;
    memset(&t, 0, sizeof t);
    t.name = name;
    t.fn = fn;
    t.ctx = ctx;
    cms_aws_init(&a, buf, n, name);
    for (;;) {
        const unsigned char *r;
        size_t len;
        long long off, at = (long long)a.pos;
        int k = cms_aws_next(&a, &r, &len, &off, err);
        if (k < 0) {
            rc = err->status;
            break;
        }
        if (k == CMS_AWS_RECORD) {
            if ((rc = tape_record(&t, r, len, off, err)))
                break;
            continue;
        }
        if ((rc = dump_open_check(&t, at, k == CMS_AWS_MARK ? "tape mark" : "end of tape", err)) ||
            (rc = plc_finish(&t, err)) || k == CMS_AWS_END)
            break;
    }
    cms_aws_free(&a);
    mem_free(t.data);
    if (!rc && nfiles)
        *nfiles = t.nfiles;
    return rc;
}
