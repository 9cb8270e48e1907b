/* cms_tape — CMS TAPE DUMP and VMFPLC2 files out of and into AWS/HET images
 * (see cms_tape.h). */
#include "vm_cms_shim/cms_tape.h"
#include "vm_cms_shim/cms_cp.h"
#include "vm_cms_shim/cms_recs.h"
#include "util/mem.h"
#include <stdio.h>
#include <string.h>
#include <time.h>

#define TAPE_HDR 5
#define TAPE_AT 11                   /* record offset to its data: AWS header + TAPE_HDR */
#define TAPE_TRAILER_MIN 82          /* trailer bytes after the header */
#define TAPE_BLOCK 800               /* CMS TAPE DUMP data block (VM/370) */
#define TAPE_BLOCK_BIG 4096          /* later levels ('F'/'V' blocks) */
#define PLC_FST 72
#define PLC_BLOCK 4000               /* VMFPLC2 data block, 5 x 800 */
#define TAPE_LABEL 80

static const unsigned char tape_hdr_cms[4] = {0x02, 0xC3, 0xD4, 0xE2};      /* X'02' CMS */
static const unsigned char tape_hdr_plch[5] = {0x02, 0xD7, 0xD3, 0xC3, 0xC8};
static const unsigned char tape_hdr_plcd[5] = {0x02, 0xD7, 0xD3, 0xC3, 0xC4};

static unsigned long cms_tape_be(const unsigned char *p, int n)
{
    unsigned long v = 0;
    while (n--)
        v = (v << 8) | *p++;
    return v;
}

static void cms_tape_put_be(unsigned char *p, unsigned long v, int n)
{
    while (n--) {
        p[n] = (unsigned char)(v & 0xFF);
        v >>= 8;
    }
}

/* File being collected. */
typedef struct tape_state {
    cms_tape_kind kind;           /* 0 = none */
    unsigned char *data;
    size_t len, cap;
    long long offset;
    size_t block;                 /* TAPE DUMP data block size of this file */
    long long short_at;           /* offset of a short data block, -1 = none */
    long holes;
    cms_tape_file plc;            /* VMFPLC2: from the header */
    long nfiles;
    int in_labels;                /* the current tape file held labels */
    const char *name;
    const cms_warn *warn;
    cms_tape_fn fn;
    void *ctx;
} tape_state;

static int cms_tape_append(tape_state *t, const unsigned char *p, size_t n, long long off, diag *err)
{
    if (t->len + n > (size_t)CMS_FILE_MAX_BYTES)
        return diag_offset(err, DIAG_INPUT, t->name, off, "file larger than %ld bytes",
                           CMS_FILE_MAX_BYTES);
    if (n && mem_grow((void **)&t->data, &t->cap, t->len + n, 1))
        return diag_offset(err, DIAG_IO, t->name, off, "out of memory");
    if (n && p)
        memcpy(t->data + t->len, p, n);
    else if (n)
        memset(t->data + t->len, 0, n);
    t->len += n;
    return 0;
}

/* Directory-entry name fields (EBCDIC) to a fileid. */
static int cms_tape_fileid(const unsigned char *fn, const unsigned char *ft, const unsigned char *fm,
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

static int cms_tape_recfm(unsigned char b, char *recfm, const char *name, long long off, diag *err)
{
    if (b == 0xC6)
        *recfm = 'F';
    else if (b == 0xE5)
        *recfm = 'V';
    else
        return diag_offset(err, DIAG_INPUT, name, off, "RECFM byte X'%02X' is neither F nor V", b);
    return 0;
}

/* One decimal-coded byte (X'84' = 84), or -1 if it is not two BCD digits. */
static int cms_tape_dcb(unsigned char b)
{
    return (b >> 4) > 9 || (b & 15) > 9 ? -1 : (b >> 4) * 10 + (b & 15);
}

/* The date a directory entry records: the EDF date YYMMDDhhmmss (adt) when
 * set, else the short FST's year (2 EBCDIC digits) and MMDDhhmm; century 20
 * when flag X'08' is on. Leaves "" when the fields are not a date. */
static void cms_tape_date(const unsigned char *adt, const unsigned char *year,
                      const unsigned char *mdhm, unsigned flags, char out[20])
{
    int v[6], i, cc = (flags & 0x08) ? 20 : 19, yy;
    static const unsigned char none[6];
    char t[64];
    out[0] = '\0';
    if (adt && memcmp(adt, none, 6) != 0) {
        for (i = 0; i < 6; i++)
            if ((v[i] = cms_tape_dcb(adt[i])) < 0)
                return;
        if (v[1] < 1 || v[1] > 12 || v[2] < 1 || v[2] > 31 || v[3] > 23 || v[4] > 59 || v[5] > 59)
            return;
        if (!(flags & 0x08) && v[0] < 70)   /* VM/370 wrote 2022 as 22, with no flag */
            cc = 20;
        snprintf(t, sizeof t, "%02d%02d-%02d-%02d %02d:%02d:%02d", cc, v[0], v[1], v[2], v[3],
                 v[4], v[5]);
        memcpy(out, t, 20);
        out[19] = '\0';
        return;
    }
    if (year[0] < 0xF0 || year[0] > 0xF9 || year[1] < 0xF0 || year[1] > 0xF9)
        return;
    for (i = 0; i < 4; i++)
        if ((v[i] = cms_tape_dcb(mdhm[i])) < 0)
            return;
    if (v[0] < 1 || v[0] > 12 || v[1] < 1 || v[1] > 31 || v[2] > 23 || v[3] > 59)
        return;
    yy = (year[0] - 0xF0) * 10 + (year[1] - 0xF0);
    if (!(flags & 0x08) && yy < 70)
        cc = 20;
    snprintf(t, sizeof t, "%02d%d%d-%02d-%02d %02d:%02d", cc, year[0] - 0xF0, year[1] - 0xF0,
             v[0], v[1], v[2], v[3]);
    memcpy(out, t, 17);
    out[16] = '\0';
}

static int cms_tape_emit(tape_state *t, cms_tape_file *f, diag *err)
{
    int rc;
    if (t->nfiles >= CMS_TAPE_MAX_FILES)
        return diag_offset(err, DIAG_INPUT, t->name, f->offset, "more than %d files on the tape",
                           CMS_TAPE_MAX_FILES);
    f->data = t->data ? t->data : (const unsigned char *)"";
    f->len = t->len;
    f->offset = t->offset;
    f->holes = t->holes;
    t->nfiles++;
    rc = t->fn(t->ctx, f, err);
    t->len = 0;
    t->kind = 0;
    t->holes = 0;
    t->short_at = -1;
    return rc;
}

/* CMS TAPE DUMP trailer: p points after the 5-byte header, n bytes. */
static int cms_tape_dump_trailer(tape_state *t, const unsigned char *p, size_t n, long long off,
                             diag *err)
{
    cms_tape_file f;
    unsigned long c16, c32;
    int rc;
    memset(&f, 0, sizeof f);
    if (n < TAPE_TRAILER_MIN)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "CMS tape trailer of %zu bytes is shorter than %d", n, TAPE_TRAILER_MIN);
    f.kind = CMS_TAPE_DUMP;
    if ((rc = cms_tape_recfm(p[10], &f.recfm, t->name, off + TAPE_AT + 10, err)) ||
        (rc = cms_tape_fileid(p + 64, p + 72, p + 80, &f.id, t->name, off + TAPE_AT + 64, err)))
        return rc;
    f.lrecl = (long)cms_tape_be(p + 12, 4);
    if (f.lrecl < 1 || f.lrecl > CMS_LRECL_MAX)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_AT + 12,
                           "LRECL %lu is outside 1..%d", cms_tape_be(p + 12, 4), CMS_LRECL_MAX);
    c16 = cms_tape_be(p + 6, 2);
    c32 = cms_tape_be(p + 32, 4);
    if (c32 && (c32 & 0xFFFFUL) == c16 && c32 <= 0x7FFFFFFFUL) {
        f.count = (long)c32;
    } else {
        f.count = (long)c16;
        if (c32 && c32 != c16)
            cms_warn_emit(t->warn, t->name, off + TAPE_AT + 32,
                          "trailer: the 32-bit field %lu does not extend the 16-bit record "
                          "count %lu (a VM/370 trailer has no 32-bit count); %lu records used",
                          c32, c16, c16);
    }
    cms_tape_date(p + 38, p + 18, p + 20, p[11], f.date);
    if (t->kind == 0)
        t->offset = off;
    return cms_tape_emit(t, &f, err);
}

/* VMFPLC2 header: the FST. */
static int cms_tape_plc_header(tape_state *t, const unsigned char *p, size_t n, long long off,
                           diag *err)
{
    cms_tape_file *f = &t->plc;
    unsigned long aic;
    int rc;
    memset(f, 0, sizeof *f);
    if (n < PLC_FST)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "VMFPLC2 header of %zu bytes is shorter than the %d-byte FST", n, PLC_FST);
    f->kind = CMS_TAPE_VMFPLC2;
    if ((rc = cms_tape_recfm(p[30], &f->recfm, t->name, off + TAPE_AT + 30, err)) ||
        (rc = cms_tape_fileid(p, p + 8, p + 24, &f->id, t->name, off + TAPE_AT, err)))
        return rc;
    f->lrecl = (long)cms_tape_be(p + 32, 4);
    if (f->lrecl < 1 || f->lrecl > CMS_LRECL_MAX)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_AT + 32,
                           "LRECL %lu is outside 1..%d", cms_tape_be(p + 32, 4), CMS_LRECL_MAX);
    aic = cms_tape_be(p + 56, 4);
    if (aic > 0x7FFFFFFFUL)
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_AT + 56,
                           "record count %lu is too large", aic);
    f->count = aic ? (long)aic : (long)cms_tape_be(p + 26, 2);
    cms_tape_date(p + 62, p + 38, p + 16, p[31], f->date);
    t->kind = CMS_TAPE_VMFPLC2;
    t->len = 0;
    t->offset = off;
    return 0;
}

/* Ends a VMFPLC2 file in progress (at a header, tape mark or end). */
static int cms_tape_plc_finish(tape_state *t, diag *err)
{
    if (t->kind != CMS_TAPE_VMFPLC2)
        return 0;
    return cms_tape_emit(t, &t->plc, err);
}

static int cms_tape_dump_open_check(tape_state *t, long long off, const char *what, diag *err)
{
    if (t->kind == CMS_TAPE_DUMP)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "%s before the CMS tape trailer ('N' block) of the file at offset %lld",
                           what, t->offset);
    return 0;
}

/* 1 if r is an 80-byte IBM standard label (VOL1, HDRn, EOFn, EOVn, UHLn, UTLn). */
static int cms_tape_is_label(const unsigned char *r, size_t n)
{
    static const unsigned char ids[6][3] = {
        {0xE5, 0xD6, 0xD3}, {0xC8, 0xC4, 0xD9}, {0xC5, 0xD6, 0xC6},   /* VOL HDR EOF */
        {0xC5, 0xD6, 0xE5}, {0xE4, 0xC8, 0xD3}, {0xE4, 0xE3, 0xD3}};  /* EOV UHL UTL */
    int i;
    if (n != TAPE_LABEL || r[3] < 0xF1 || r[3] > 0xF9)
        return 0;
    for (i = 0; i < 6; i++)
        if (memcmp(r, ids[i], 3) == 0)
            return 1;
    return 0;
}

static void cms_tape_label_note(tape_state *t, const unsigned char *r, long long off)
{
    const cms_cp *cp;
    char text[TAPE_LABEL + 1];
    diag e;
    int i;
    diag_init(&e);
    if (cms_cp_get(CMS_CP_1047, &cp, &e))
        return;
    for (i = 0; i < 17; i++) {   /* the label id and its first fields: volser / dsname */
        unsigned char c = cp->to_latin1[r[i]];
        text[i] = c >= 0x20 && c < 0x7F ? (char)c : '.';
    }
    while (i && text[i - 1] == ' ')
        i--;
    text[i] = '\0';
    cms_warn_emit(t->warn, t->name, off, "standard label skipped: %s", text);
}

static int cms_tape_dump_block(tape_state *t, unsigned char type, const unsigned char *p, size_t pn,
                           long long off, diag *err)
{
    size_t want = type == 0x40 ? TAPE_BLOCK : TAPE_BLOCK_BIG;
    if (type == 0xF0)                                   /* '0': null block */
        want = t->kind == CMS_TAPE_DUMP ? t->block : TAPE_BLOCK;
    if (t->kind == 0) {
        t->kind = CMS_TAPE_DUMP;
        t->offset = off;
        t->len = 0;
        t->holes = 0;
        t->short_at = -1;
        t->block = want;
    } else if (type != 0xF0 && want != t->block) {
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "CMS tape data block of type X'%02X' (%zu bytes) in a file of "
                           "%zu-byte blocks", type, want, t->block);
    }
    if (t->short_at >= 0)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "data block after the short block at offset %lld (only the last "
                           "block of a file may be short)", t->short_at);
    if (type == 0xF0) {
        /* a hole of a sparse file: its block of zeros is part of the data */
        t->holes++;
        return cms_tape_append(t, NULL, t->block, off, err);
    }
    if (pn == 0 || pn > want)
        return diag_offset(err, DIAG_INPUT, t->name, off,
                           "CMS tape data block of %zu bytes (expected 1..%zu)", pn, want);
    if (pn < want)
        t->short_at = off;
    return cms_tape_append(t, p, pn, off, err);
}

static int cms_tape_record(tape_state *t, const unsigned char *r, size_t n, long long off, diag *err)
{
    int rc;
    if (t->kind == 0 && (t->in_labels || cms_tape_is_label(r, n))) {
        if (!t->in_labels || r[0] == 0xE5)
            cms_tape_label_note(t, r, off);
        t->in_labels = 1;
        return 0;
    }
    if (n >= TAPE_HDR && memcmp(r, tape_hdr_cms, 4) == 0) {
        const unsigned char *p = r + TAPE_HDR;
        size_t pn = n - TAPE_HDR;
        unsigned char type = r[4];
        if ((rc = cms_tape_plc_finish(t, err)))
            return rc;
        if (type == 0xD5)                                   /* 'N' */
            return cms_tape_dump_trailer(t, p, pn, off, err);
        if (type == 0x40 || type == 0xC6 || type == 0xE5 || type == 0xF0)
            return cms_tape_dump_block(t, type, p, pn, off, err);
        return diag_offset(err, DIAG_INPUT, t->name, off + TAPE_AT - 1,
                           "unknown CMS tape block type X'%02X'", type);
    }
    if (n >= TAPE_HDR && memcmp(r, tape_hdr_plch, 5) == 0) {
        if ((rc = cms_tape_dump_open_check(t, off, "VMFPLC2 header", err)) ||
            (rc = cms_tape_plc_finish(t, err)))
            return rc;
        return cms_tape_plc_header(t, r + TAPE_HDR, n - TAPE_HDR, off, err);
    }
    if (n >= TAPE_HDR && memcmp(r, tape_hdr_plcd, 5) == 0) {
        if (t->kind != CMS_TAPE_VMFPLC2)
            return diag_offset(err, DIAG_INPUT, t->name, off, "VMFPLC2 data block without a header");
        if (n - TAPE_HDR > PLC_BLOCK)
            return diag_offset(err, DIAG_INPUT, t->name, off,
                               "VMFPLC2 data block of %zu bytes (at most %d)", n - TAPE_HDR,
                               PLC_BLOCK);
        return cms_tape_append(t, r + TAPE_HDR, n - TAPE_HDR, off, err);
    }
    return diag_offset(err, DIAG_INPUT, t->name, off,
                       "tape record of %zu bytes is neither CMS TAPE DUMP nor VMFPLC2 "
                       "(starts %02X %02X %02X %02X)", n, r[0], n > 1 ? r[1] : 0,
                       n > 2 ? r[2] : 0, n > 3 ? r[3] : 0);
}

int cms_tape_read(const unsigned char *buf, size_t n, const char *name, const cms_warn *warn,
                  cms_tape_fn fn, void *ctx, long *nfiles, diag *err)
{
    tape_state t;
    cms_aws a;
    int rc = 0;
    memset(&t, 0, sizeof t);
    t.name = name;
    t.warn = warn;
    t.fn = fn;
    t.ctx = ctx;
    t.short_at = -1;
    cms_aws_init(&a, buf, n, name, warn);
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
            if ((rc = cms_tape_record(&t, r, len, off, err)))
                break;
            continue;
        }
        t.in_labels = 0;
        if ((rc = cms_tape_dump_open_check(&t, at, k == CMS_AWS_MARK ? "tape mark" : "end of tape",
                                       err)) ||
            (rc = cms_tape_plc_finish(&t, err)) || k == CMS_AWS_END)
            break;
    }
    cms_aws_free(&a);
    mem_free(t.data);
    if (!rc && nfiles)
        *nfiles = t.nfiles;
    return rc;
}

/* ---- writing ------------------------------------------------------------ */

void cms_tape_writer_init(cms_tape_writer *t, cms_tape_kind kind, cms_aws_comp comp,
                          cms_aws_sink sink, void *ctx)
{
    memset(t, 0, sizeof *t);
    t->kind = kind;
    cms_aws_writer_init(&t->aws, sink, ctx, comp, 0);
}

void cms_tape_writer_end(cms_tape_writer *t)
{
    cms_aws_put_mark(&t->aws);
    cms_aws_put_mark(&t->aws);
    cms_aws_writer_free(&t->aws);
}

/* EBCDIC of an ASCII fileid field, blank-padded to n. */
static int cms_tape_put_name(unsigned char *p, const char *s, size_t n, diag *err)
{
    const cms_cp *cp;
    size_t i, k = strlen(s);
    int rc;
    if ((rc = cms_cp_get(CMS_CP_1047, &cp, err)))
        return rc;
    for (i = 0; i < n; i++)
        p[i] = i < k ? cp->from_latin1[(unsigned char)s[i]] : 0x40;
    return 0;
}

static unsigned char cms_tape_to_dcb(int v) { return (unsigned char)(((v / 10) << 4) | (v % 10)); }

/* Date fields of a directory entry from "YYYY-MM-DD HH:MM[:SS]" (or now);
 * the EDF date (adt, may be NULL) only when the seconds are known. */
static void cms_tape_put_date(const char *date, unsigned char *adt, unsigned char *year,
                          unsigned char *mdhm, unsigned char *flags)
{
    int y, mo, d, h, mi, s = 0, k = date ? sscanf(date, "%4d-%2d-%2d %2d:%2d:%2d", &y, &mo, &d,
                                                  &h, &mi, &s) : 0;
    if (k == 5)
        adt = NULL;        /* a date without seconds stays one (the short FST date) */
    if (k < 5) {
        time_t now = time(NULL);
        struct tm tm;
        gmtime_r(&now, &tm);
        y = tm.tm_year + 1900;
        mo = tm.tm_mon + 1;
        d = tm.tm_mday;
        h = tm.tm_hour;
        mi = tm.tm_min;
        s = tm.tm_sec;
    }
    if (y >= 2000)
        *flags |= 0x08;
    year[0] = (unsigned char)(0xF0 + (y % 100) / 10);
    year[1] = (unsigned char)(0xF0 + y % 10);
    mdhm[0] = cms_tape_to_dcb(mo);
    mdhm[1] = cms_tape_to_dcb(d);
    mdhm[2] = cms_tape_to_dcb(h);
    mdhm[3] = cms_tape_to_dcb(mi);
    if (adt) {
        adt[0] = cms_tape_to_dcb(y % 100);
        adt[1] = cms_tape_to_dcb(mo);
        adt[2] = cms_tape_to_dcb(d);
        adt[3] = cms_tape_to_dcb(h);
        adt[4] = cms_tape_to_dcb(mi);
        adt[5] = cms_tape_to_dcb(s);
    }
}

int cms_tape_write_file(cms_tape_writer *t, const cms_tape_file *f, diag *err)
{
    unsigned char blk[TAPE_HDR + PLC_BLOCK];
    unsigned char fm[3];
    size_t nblocks = (f->len + TAPE_BLOCK - 1) / TAPE_BLOCK, pos;
    unsigned long count = (unsigned long)f->count;
    int rc;
    if (f->count < 1 || f->len == 0)
        return diag_at(err, DIAG_USAGE, "", 0, 0, "CMS holds no empty files");
    if (f->recfm != 'F' && f->recfm != 'V')
        return diag_at(err, DIAG_USAGE, "", 0, 0, "RECFM must be F or V");
    if (nblocks > 0xFFFF && t->kind == CMS_TAPE_DUMP)
        return diag_at(err, DIAG_USAGE, "", 0, 0, "file of %zu 800-byte blocks: more than a "
                       "TAPE DUMP trailer counts", nblocks);
    fm[0] = (unsigned char)f->id.mode;
    fm[1] = (unsigned char)f->id.num;
    fm[2] = '\0';
    memset(blk, 0, sizeof blk);
    if (t->kind == CMS_TAPE_VMFPLC2) {
        unsigned char *p = blk + TAPE_HDR;
        size_t full = f->len / PLC_BLOCK, last = f->len % PLC_BLOCK;
        memcpy(blk, tape_hdr_plch, TAPE_HDR);
        if ((rc = cms_tape_put_name(p, f->id.fn, 8, err)) || (rc = cms_tape_put_name(p + 8, f->id.ft, 8, err)) ||
            (rc = cms_tape_put_name(p + 24, (const char *)fm, 2, err)))
            return rc;
        cms_tape_put_be(p + 20, (count & 0xFFFF) + 1, 2);      /* write pointer */
        cms_tape_put_be(p + 22, 1, 2);                          /* read pointer */
        cms_tape_put_be(p + 26, count & 0xFFFF, 2);
        p[30] = f->recfm == 'F' ? 0xC6 : 0xE5;
        cms_tape_put_be(p + 32, (unsigned long)f->lrecl, 4);
        cms_tape_put_be(p + 36, nblocks & 0xFFFF, 2);
        cms_tape_put_date(f->date, p + 62, p + 38, p + 16, p + 31);
        cms_tape_put_be(p + 40, (unsigned long)((last + TAPE_BLOCK - 1) / TAPE_BLOCK), 4);
        cms_tape_put_be(p + 44, (unsigned long)full, 4);
        cms_tape_put_be(p + 52, (unsigned long)nblocks, 4);
        cms_tape_put_be(p + 56, count, 4);
        if ((rc = cms_aws_put(&t->aws, blk, TAPE_HDR + PLC_FST, err)))
            return rc;
        memcpy(blk, tape_hdr_plcd, TAPE_HDR);
        for (pos = 0; pos < f->len; pos += PLC_BLOCK) {
            size_t k = f->len - pos < PLC_BLOCK ? f->len - pos : PLC_BLOCK;
            size_t padded = (k + TAPE_BLOCK - 1) / TAPE_BLOCK * TAPE_BLOCK;
            memcpy(blk + TAPE_HDR, f->data + pos, k);
            memset(blk + TAPE_HDR + k, 0, padded - k);
            if ((rc = cms_aws_put(&t->aws, blk, TAPE_HDR + padded, err)))
                return rc;
        }
        return 0;
    }
    memcpy(blk, tape_hdr_cms, 4);
    blk[4] = 0x40;
    for (pos = 0; pos < f->len; pos += TAPE_BLOCK) {
        size_t k = f->len - pos < TAPE_BLOCK ? f->len - pos : TAPE_BLOCK;
        memcpy(blk + TAPE_HDR, f->data + pos, k);
        memset(blk + TAPE_HDR + k, 0, TAPE_BLOCK - k);
        if ((rc = cms_aws_put(&t->aws, blk, TAPE_HDR + TAPE_BLOCK, err)))
            return rc;
    }
    {
        unsigned char *p = blk + TAPE_HDR;
        memset(p, 0, TAPE_BLOCK);
        blk[4] = 0xD5;                                     /* 'N' */
        cms_tape_put_be(p, (count & 0xFFFF) + 1, 2);
        cms_tape_put_be(p + 2, 1, 2);
        if ((rc = cms_tape_put_name(p + 4, (const char *)fm, 2, err)) ||
            (rc = cms_tape_put_name(p + 64, f->id.fn, 8, err)) ||
            (rc = cms_tape_put_name(p + 72, f->id.ft, 8, err)) ||
            (rc = cms_tape_put_name(p + 80, (const char *)fm, 2, err)))
            return rc;
        cms_tape_put_be(p + 6, count & 0xFFFF, 2);
        p[10] = f->recfm == 'F' ? 0xC6 : 0xE5;
        cms_tape_put_be(p + 12, (unsigned long)f->lrecl, 4);
        cms_tape_put_be(p + 16, nblocks, 2);
        cms_tape_put_date(f->date, NULL, p + 18, p + 20, p + 11);
        cms_tape_put_be(p + 32, count, 4);                     /* the count beyond 65,535 */
        return cms_aws_put(&t->aws, blk, TAPE_HDR + TAPE_BLOCK, err);
    }
}
