/* test_cms_tape — Hercules AWS tapes (CMS TAPE DUMP, VMFPLC2), punch decks
 * with :READ cards, and `cms import`, against tapes and decks built here
 * byte by byte from the documented layouts. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "test_cms_lib.h"
#include "support.h"
#include "util/mem.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_import.h"
#include "vm_cms_shim/cms_punch.h"
#include "vm_cms_shim/cms_tape.h"

static void expect_diag(const diag *d, const char *text)
{
    char buf[1024];
    diag_format(d, buf, sizeof buf);
    assert_string_equal(buf, text);
}

/* Record i of the test files: "LINE nnnn OF name" and 0-3 stars, so V
 * records differ in length. */
static void rec_text(char *out, size_t size, const char *name, int i)
{
    snprintf(out, size, "LINE %04d OF %s%.*s", i + 1, name, i % 4, "***");
}

/* CMS byte stream of count records: F lrecl (blank padded) or V. */
static void make_stream(tbuf *s, const char *name, char recfm, int lrecl, int count)
{
    int i;
    char t[100];
    for (i = 0; i < count; i++) {
        rec_text(t, sizeof t, name, i);
        if (recfm == 'F')
            tb_ebcdic(s, t, 1047, (size_t)lrecl);
        else {
            tb_be(s, strlen(t), 2);
            tb_ebcdic(s, t, 1047, 0);
        }
    }
}

/* A CMS TAPE DUMP file: data blocks of blk bytes (800 with type blank, 4096
 * with type F/V), a null block after the first data block when nullblk, and
 * the 'N' trailer, short (82 bytes) or padded to 800. */
static void dump_file(tbuf *tape, const char *fn, const char *ft, char recfm, int lrecl,
                      int count, int blk, int nullblk, int short_trailer)
{
    tbuf s = {0}, r = {0}, tr = {0};
    size_t off;
    char fn8[9], ft8[9];
    int type = blk == 800 ? 0x40 : (recfm == 'F' ? 0xC6 : 0xE5);
    make_stream(&s, fn, recfm, lrecl, count);
    for (off = 0; off < s.n; off += (size_t)blk) {
        size_t k = s.n - off < (size_t)blk ? s.n - off : (size_t)blk;
        r.n = 0;
        tb_put(&r, "\x02\xC3\xD4\xE2", 4);
        tb_byte(&r, type);
        tb_put(&r, s.p + off, k);
        tb_fill(&r, 0x00, (size_t)blk - k);
        tb_aws_record(tape, r.p, r.n);
    }
    if (nullblk) {   /* a hole past the records: zeros the records do not reach */
        r.n = 0;
        tb_put(&r, "\x02\xC3\xD4\xE2\xF0", 5);
        tb_fill(&r, 0x00, (size_t)blk);
        tb_aws_record(tape, r.p, r.n);
    }
    tb_put(&tr, "\x02\xC3\xD4\xE2\xD5", 5);
    tb_be(&tr, (unsigned long)count + 1, 2);        /* write pointer */
    tb_be(&tr, 1, 2);                               /* read pointer */
    tb_put(&tr, "\xC1\xF1", 2);                     /* A1 */
    tb_be(&tr, (unsigned long)count, 2);
    tb_be(&tr, 0, 2);
    tb_byte(&tr, recfm == 'F' ? 0xC6 : 0xE5);
    tb_byte(&tr, 0);
    tb_be(&tr, (unsigned long)lrecl, 4);
    tb_be(&tr, (unsigned long)((s.n + 799) / 800), 2);
    tb_put(&tr, "\xF8\xF7\x11\x22\x10\x15", 6);    /* 87, 11/22 10:15 */
    tb_fill(&tr, 0x00, 64 - 24);
    snprintf(fn8, sizeof fn8, "%-8s", fn);
    snprintf(ft8, sizeof ft8, "%-8s", ft);
    tb_ebcdic(&tr, fn8, 1047, 0);
    tb_ebcdic(&tr, ft8, 1047, 0);
    tb_put(&tr, "\xC1\xF1", 2);
    assert_int_equal(tr.n, 5 + 82);
    if (!short_trailer)
        tb_fill(&tr, 0x00, 805 - tr.n);
    tb_aws_record(tape, tr.p, tr.n);
    tb_aws_mark(tape);
    tb_free(&s);
    tb_free(&r);
    tb_free(&tr);
}

/* A VMFPLC2 file: PLCH + FST, PLCD blocks of up to 4000 bytes. aic != 0
 * puts the count in the 32-bit EDF field and 0 in the 16-bit one. */
static void plc_file(tbuf *tape, const char *fn, const char *ft, char recfm, int lrecl,
                     int count, int use_aic)
{
    tbuf s = {0}, r = {0};
    size_t off;
    char fn8[9], ft8[9];
    make_stream(&s, fn, recfm, lrecl, count);
    tb_put(&r, "\x02\xD7\xD3\xC3\xC8", 5);
    snprintf(fn8, sizeof fn8, "%-8s", fn);
    snprintf(ft8, sizeof ft8, "%-8s", ft);
    tb_ebcdic(&r, fn8, 1047, 0);
    tb_ebcdic(&r, ft8, 1047, 0);
    tb_put(&r, "\x11\x22\x10\x15", 4);
    tb_be(&r, (unsigned long)count + 1, 2);
    tb_be(&r, 1, 2);
    tb_put(&r, "\xC2\xF1", 2);                      /* B1 */
    tb_be(&r, use_aic ? 0 : (unsigned long)count, 2);
    tb_be(&r, 0, 2);
    tb_byte(&r, recfm == 'F' ? 0xC6 : 0xE5);
    tb_byte(&r, 0);
    tb_be(&r, (unsigned long)lrecl, 4);
    tb_be(&r, (unsigned long)((s.n + 799) / 800), 2);
    tb_put(&r, "\xF8\xF7", 2);
    tb_be(&r, (unsigned long)(((s.n + 799) / 800) % 5), 4);   /* lastsz */
    tb_be(&r, (unsigned long)(s.n / 4000), 4);                /* numblk */
    tb_be(&r, 0, 4);
    tb_be(&r, 0, 4);
    tb_be(&r, use_aic ? (unsigned long)count : 0, 4);
    tb_fill(&r, 0, 12);
    assert_int_equal(r.n, 5 + 72);
    tb_aws_record(tape, r.p, r.n);
    for (off = 0; off < s.n; off += 4000) {
        size_t k = s.n - off < 4000 ? s.n - off : 4000, padded = (k + 799) / 800 * 800;
        r.n = 0;
        tb_put(&r, "\x02\xD7\xD3\xC3\xC4", 5);
        tb_put(&r, s.p + off, k);
        tb_fill(&r, 0x40, padded - k);
        tb_aws_record(tape, r.p, r.n);
    }
    tb_free(&s);
    tb_free(&r);
}

/* Collects the files a tape yields. */
typedef struct got {
    int n;
    cms_tape_file f[8];
    cms_recs r[8];
} got;

static int collect(void *ctx, const cms_tape_file *f, diag *err)
{
    got *g = ctx;
    char label[40];
    assert_true(g->n < 8);
    g->f[g->n] = *f;
    snprintf(label, sizeof label, "%s", f->id.fn);
    if (cms_recs_from_stream(f->data, f->len, f->recfm, f->lrecl, f->count, CMS_CP_AUTO, 0, label,
                             &g->r[g->n], err))
        return err->status;
    g->n++;
    return 0;
}

static void got_free(got *g)
{
    int i;
    for (i = 0; i < g->n; i++)
        cms_recs_free(&g->r[i]);
}

static void check_file(const got *g, int k, const char *fn, const char *ft, char mode, char recfm,
                       long lrecl, long count)
{
    char t[100];
    long i;
    assert_string_equal(g->f[k].id.fn, fn);
    assert_string_equal(g->f[k].id.ft, ft);
    assert_int_equal(g->f[k].id.mode, mode);
    assert_int_equal(g->f[k].recfm, recfm);
    assert_int_equal(g->f[k].lrecl, lrecl);
    assert_int_equal(g->f[k].count, count);
    assert_int_equal(g->r[k].count, count);
    for (i = 0; i < count; i++) {
        const cms_rec *r = &g->r[k].rec[i];
        rec_text(t, sizeof t, fn, (int)i);
        assert_true(r->len >= strlen(t));
        assert_memory_equal(g->r[k].text + r->off, t, strlen(t));
        assert_int_equal(r->len, recfm == 'F' ? (size_t)lrecl : strlen(t));
    }
}

static void test_cms_tape_dump_both_trailers(void **state)
{
    tbuf t = {0};
    got g;
    diag e;
    long n = 0;
    (void)state;
    t_aws_prev = 0;
    dump_file(&t, "RAY", "DATA", 'F', 80, 25, 800, 1, 0);       /* null block, padded trailer */
    dump_file(&t, "VFILE", "EXEC", 'V', 72, 40, 800, 0, 1);     /* short trailer */
    dump_file(&t, "BIG", "LISTING", 'F', 133, 50, 4096, 1, 1);  /* 4101-byte CMSF blocks */
    tb_aws_mark(&t);
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_true(cms_aws_detect(t.p, t.n));
    assert_int_equal(cms_tape_read(t.p, t.n, "tape.aws", NULL, collect, &g, &n, &e), 0);
    assert_int_equal(n, 3);
    check_file(&g, 0, "RAY", "DATA", 'A', 'F', 80, 25);
    check_file(&g, 1, "VFILE", "EXEC", 'A', 'V', 72, 40);
    check_file(&g, 2, "BIG", "LISTING", 'A', 'F', 133, 50);
    assert_int_equal(g.f[0].kind, CMS_TAPE_DUMP);
    assert_int_equal(g.f[0].len, 4 * 800);                      /* null block: 800 zeros */
    assert_int_equal(g.f[0].holes, 1);
    assert_string_equal(g.f[0].date, "1987-11-22 10:15");
    got_free(&g);
    tb_free(&t);
}

/* TV-6: the 87-byte CMSN trailer from a real tape (cctalk, 2015). */
static void test_cms_tape_real_trailer(void **state)
{
    static const unsigned char tv6[87] = {
        0x02, 0xC3, 0xD4, 0xE2, 0xD5, 0x01, 0x76, 0x00, 0x01, 0xC1, 0xF1, 0x01, 0x75, 0x00, 0x00,
        0xC6, 0x00, 0x00, 0x00, 0x00, 0x50, 0x00, 0x08, 0xF8, 0xF4, 0x12, 0x05, 0x12, 0x31, 0x00,
        0x00, 0x01, 0x3B, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x01, 0x75, 0x01, 0x04, 0x84, 0x12,
        0x05, 0x12, 0x31, 0x21, 0x00, 0x00, 0x00, 0x00, 0xE4, 0xE3, 0xC5, 0x40, 0xE2, 0xC1, 0xE2,
        0xC6, 0xC9, 0xD3, 0xC5, 0x40, 0x00, 0x00, 0x00, 0x00, 0xC3, 0xC8, 0xC5, 0xC3, 0xD2, 0xF1,
        0x40, 0x40, 0xD7, 0xE2, 0xC1, 0xE2, 0x40, 0x40, 0x40, 0x40, 0xC1, 0xF1};
    tbuf t = {0}, s = {0}, r = {0};
    size_t off;
    got g;
    diag e;
    int i;
    char line[81];
    (void)state;
    t_aws_prev = 0;
    for (i = 0; i < 373; i++) {
        snprintf(line, sizeof line, "CHECK1 RECORD %d", i + 1);
        tb_ebcdic(&s, line, 1047, 80);
    }
    for (off = 0; off < s.n; off += 800) {
        size_t k = s.n - off < 800 ? s.n - off : 800;
        r.n = 0;
        tb_put(&r, "\x02\xC3\xD4\xE2\x40", 5);
        tb_put(&r, s.p + off, k);
        tb_fill(&r, 0, 800 - k);
        tb_aws_record(&t, r.p, r.n);
    }
    tb_aws_record(&t, tv6, sizeof tv6);
    tb_aws_mark(&t);
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, t.n, "tv6.aws", NULL, collect, &g, NULL, &e), 0);
    assert_int_equal(g.n, 1);
    assert_string_equal(g.f[0].id.fn, "CHECK1");
    assert_string_equal(g.f[0].id.ft, "PSAS");
    assert_int_equal(g.f[0].id.mode, 'A');
    assert_int_equal(g.f[0].id.num, '1');
    assert_int_equal(g.f[0].recfm, 'F');
    assert_int_equal(g.f[0].lrecl, 80);
    assert_int_equal(g.f[0].count, 373);
    assert_memory_equal(g.r[0].text + g.r[0].rec[372].off, "CHECK1 RECORD 373 ", 18);
    got_free(&g);
    tb_free(&t);
    tb_free(&s);
    tb_free(&r);
}

static void test_cms_tape_vmfplc2(void **state)
{
    tbuf t = {0};
    got g;
    diag e;
    long n = 0;
    (void)state;
    t_aws_prev = 0;
    plc_file(&t, "PLCF", "DATA", 'F', 80, 60, 0);     /* 4000 + 800 bytes */
    plc_file(&t, "PLCV", "SCRIPT", 'V', 100, 7, 1);   /* follows without a tape mark */
    tb_aws_mark(&t);
    plc_file(&t, "LAST", "ONE", 'F', 80, 1, 1);       /* ends at the end of the tape */
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, t.n, "plc.aws", NULL, collect, &g, &n, &e), 0);
    assert_int_equal(n, 3);
    check_file(&g, 0, "PLCF", "DATA", 'B', 'F', 80, 60);
    check_file(&g, 1, "PLCV", "SCRIPT", 'B', 'V', 100, 7);
    check_file(&g, 2, "LAST", "ONE", 'B', 'F', 80, 1);
    assert_int_equal(g.f[0].kind, CMS_TAPE_VMFPLC2);
    got_free(&g);
    tb_free(&t);
}

static char t_warned[1024];

static void t_warn(void *ctx, const diag *w)
{
    (void)ctx;
    cms_warn_format(w, t_warned, sizeof t_warned);
}

static void test_cms_tape_errors(void **state)
{
    tbuf t = {0};
    got g;
    diag e;
    (void)state;
    /* a TAPE DUMP file cut off before its trailer */
    t_aws_prev = 0;
    dump_file(&t, "RAY", "DATA", 'F', 80, 25, 800, 0, 0);
    t.n -= 6 + 805 + 6;                       /* drop the trailer and the tape mark */
    t_aws_prev = 805;
    tb_aws_mark(&t);
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, t.n, "cut.aws", NULL, collect, &g, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "cut.aws: offset 2433: error: tape mark before the CMS tape trailer ('N' block) "
                    "of the file at offset 0");
    /* a damaged previous-length field is a warning, as Hercules' tapemap ignores it */
    t.p[6 + 805 + 2] ^= 1;
    diag_init(&e);
    {
        cms_warn w;
        t_warned[0] = '\0';
        w.fn = t_warn;
        w.ctx = NULL;
        assert_int_equal(cms_tape_read(t.p, t.n, "bad.aws", &w, collect, &g, NULL, &e), DIAG_INPUT);
        expect_diag(&e, "bad.aws: offset 2433: error: tape mark before the CMS tape trailer ('N' "
                        "block) of the file at offset 0");
        assert_non_null(strstr(t_warned, "bad.aws: offset 811: warning: AWS header: previous "
                                         "length 804, but the block before held 805 bytes"));
    }
    /* truncated header, and a block running past the end */
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, 3, "t.aws", NULL, collect, &g, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "t.aws: offset 0: error: truncated AWS block header (3 bytes)");
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, 100, "t.aws", NULL, collect, &g, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "t.aws: offset 0: error: AWS block of 805 bytes runs past the end of the image");
    /* an F file whose blocks hold fewer bytes than the trailer promises */
    t.n = 0;
    t_aws_prev = 0;
    {
        tbuf s = {0};
        dump_file(&s, "RAY", "DATA", 'F', 80, 25, 800, 0, 1);
        s.p[3 * 811 + 6 + 5 + 7] = 99;       /* record count 25 -> 99 (low byte) */
        diag_init(&e);
        memset(&g, 0, sizeof g);
        assert_int_equal(cms_tape_read(s.p, s.n, "n.aws", NULL, collect, &g, NULL, &e), DIAG_INPUT);
        expect_diag(&e, "RAY: error: 99 records of 80 bytes need 7920 bytes, the data holds 2400");
        tb_free(&s);
    }
    tb_free(&t);
}

/* ---- punch decks ------------------------------------------------------- */

typedef struct pgot {
    int n;
    cms_fileid id[4];
    long count[4];
    char first[4][81];
} pgot;

static int pcollect(void *ctx, const cms_fileid *id, const cms_recs *r, long card, diag *err)
{
    pgot *g = ctx;
    (void)err;
    (void)card;
    assert_true(g->n < 4);
    assert_int_equal(r->recfm, 'F');
    assert_int_equal(r->lrecl, 80);
    g->id[g->n] = *id;
    g->count[g->n] = (long)r->count;
    memset(g->first[g->n], 0, 81);
    if (r->count) {
        assert_int_equal(r->rec[0].len, 80);
        memcpy(g->first[g->n], r->text + r->rec[0].off, 80);
    }
    g->n++;
    return 0;
}

static void test_cms_punch_two_files(void **state)
{
    static const char ascii[] =
        "SEPARATOR CARD\n"
        ":READ  FIG1     SCENE    A1 VOL001 11/22/87  10:15\n"
        "EYE 0 -10 4\n"
        "SPHERE S1 1.5\n"
        ":READ  NOTES    TEXT     B2\n"
        "HELLO\r\n";
    tbuf eb = {0};
    pgot g;
    diag e;
    long n = 0;
    char want[81];
    (void)state;
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_punch_split((const unsigned char *)ascii, strlen(ascii), NULL, "p.txt",
                                     pcollect, &g, &n, &e), 0);
    assert_int_equal(n, 3);
    assert_string_equal(g.id[0].fn, "READCARD");
    assert_string_equal(g.id[0].ft, "CMSUT1");
    assert_int_equal(g.count[0], 1);
    assert_string_equal(g.id[1].fn, "FIG1");
    assert_string_equal(g.id[1].ft, "SCENE");
    assert_int_equal(g.count[1], 2);
    snprintf(want, sizeof want, "%-80s", "EYE 0 -10 4");
    assert_string_equal(g.first[1], want);
    assert_string_equal(g.id[2].fn, "NOTES");
    assert_int_equal(g.id[2].mode, 'B');
    assert_int_equal(g.id[2].num, '2');
    snprintf(want, sizeof want, "%-80s", "HELLO");
    assert_string_equal(g.first[2], want);
    /* the same deck punched in EBCDIC mode (037), no separator */
    tb_ebcdic(&eb, ":READ  FIG1     SCENE    A1", 37, 80);
    tb_ebcdic(&eb, "ATTR M COLOR 1 0 0 [SHINY]", 37, 80);
    tb_ebcdic(&eb, ":READ  NOTES    TEXT     B2", 37, 80);
    tb_ebcdic(&eb, "HELLO", 37, 80);
    memset(&g, 0, sizeof g);
    assert_int_equal(cms_punch_split(eb.p, eb.n, NULL, "p.ebc", pcollect, &g, &n, &e), 0);
    assert_int_equal(n, 2);
    assert_string_equal(g.id[0].fn, "FIG1");
    snprintf(want, sizeof want, "%-80s", "ATTR M COLOR 1 0 0 [SHINY]");
    assert_string_equal(g.first[0], want);
    assert_string_equal(g.id[1].ft, "TEXT");
    tb_free(&eb);
}

static void test_cms_punch_rejects_unread_decks(void **state)
{
    tbuf b = {0};
    pgot g;
    diag e;
    (void)state;
    tb_put(&b, "\x02\xC3\xD4\xE2\x40", 5);
    tb_fill(&b, 0x40, 75);
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_punch_split(b.p, b.n, NULL, "dd.ebc", pcollect, &g, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "dd.ebc: offset 0: error: cards starting X'02' CMS: a DISK DUMP deck or raw CMS "
                    "tape blocks; DISK DUMP decks are not read (their card layout is unconfirmed): "
                    "restore it on CMS with DISK LOAD and send the file by PUNCH or TAPE DUMP");
    b.n = 0;
    tb_put(&b, "\x20\xE0\xC9\xD5\xD4\xD9\xF0\xF1", 8);
    tb_fill(&b, 0x40, 72);
    diag_init(&e);
    assert_int_equal(cms_punch_split(b.p, b.n, NULL, "nd.ebc", pcollect, &g, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "nd.ebc: offset 0: error: a NETDATA deck (SENDFILE/TRANSMIT): not read; RECEIVE "
                    "it on CMS and send the file by PUNCH or TAPE DUMP");
    /* a compressed HET block */
    b.n = 0;
    t_aws_prev = 0;
    tb_aws_record(&b, (const unsigned char *)"\x02\xC3\xD4\xE2\x40", 5);
    b.p[4] = 0xA1;
    assert_true(cms_aws_detect(b.p, b.n));
    diag_init(&e);
    assert_int_equal(cms_tape_read(b.p, b.n, "x.het", NULL, collect, NULL, NULL, &e), DIAG_INPUT);
    expect_diag(&e, "x.het: offset 0: error: HET record: zlib data is corrupt");
    tb_free(&b);
}

/* ---- import ------------------------------------------------------------ */

typedef struct report_log {
    char lines[8][80];
    int n;
} report_log;

static void report(void *ctx, const cms_import_item *it)
{
    report_log *l = ctx;
    char t[CMS_FILEID_TEXT_MAX];
    if (l->n < 8)
        snprintf(l->lines[l->n++], 80, "%s %c %ld %ld %s", cms_fileid_format(&it->id, t, sizeof t),
                 it->recfm, it->lrecl, it->records, it->source);
}

static void test_cms_import_tape_to_disk(void **state)
{
    char *dir = t_mkdtemp(), spec[128], tape[256];
    tbuf t = {0};
    cms_disks d;
    cms_file *f;
    cms_file_info info;
    report_log log;
    diag e;
    long n = 0;
    const char *rec;
    size_t len;
    (void)state;
    t_aws_prev = 0;
    dump_file(&t, "RAY", "DATA", 'F', 80, 25, 800, 1, 0);
    dump_file(&t, "VFILE", "EXEC", 'V', 72, 40, 800, 0, 1);
    plc_file(&t, "PLCF", "DATA", 'F', 80, 60, 1);
    tb_aws_mark(&t);
    t_write(dir, "in.aws", t.p, t.n);
    snprintf(tape, sizeof tape, "%s/in.aws", dir);
    cms_disks_init(&d);
    snprintf(spec, sizeof spec, "C=%s", dir);
    diag_init(&e);
    cms_disks_set(&d, spec, &e);
    memset(&log, 0, sizeof log);
    {
        cms_import_opts o;
        memset(&o, 0, sizeof o);
        o.disk = 'C';
        assert_int_equal(cms_import(&d, tape, &o, report, &log, &n, &e), 0);
    }
    assert_int_equal(n, 3);
    assert_string_equal(log.lines[0], "RAY DATA C1 F 80 25 tape dump");
    assert_string_equal(log.lines[1], "VFILE EXEC C1 V 72 40 tape dump");
    assert_string_equal(log.lines[2], "PLCF DATA C1 F 80 60 vmfplc2");
    assert_int_equal(cms_file_open_read(&f, &d, "VFILE EXEC C", NULL, &e), 0);
    cms_file_state(f, &info);
    assert_int_equal(info.records, 40);
    assert_int_equal(info.recfm, 'V');
    assert_int_equal(cms_file_read(f, 40, &rec, &len), 0);
    assert_int_equal(len, strlen("LINE 0040 OF VFILE***"));
    assert_memory_equal(rec, "LINE 0040 OF VFILE***", len);
    cms_file_abort(f);
    assert_int_equal(cms_file_stat(&d, "RAY DATA *", NULL, &info, &e), 0);
    assert_int_equal(info.recfm, 'F');
    assert_int_equal(info.lrecl, 80);
    assert_int_equal(info.records, 25);
    assert_int_equal(t_count_files(dir), 7);   /* the tape, 3 files and their sidecars */
    cms_disks_free(&d);
    tb_free(&t);
    t_rmdir(dir);
}

static void test_cms_oom_sweep_import(void **state)
{
    char *dir = t_mkdtemp(), spec[128], tape[256], deck[256];
    tbuf t = {0};
    long k;
    int which;
    static const char ascii[] = ":READ  A        B        A1\nX\n:READ  C        D        A1\nY\n";
    (void)state;
    t_aws_prev = 0;
    dump_file(&t, "RAY", "DATA", 'F', 80, 25, 800, 1, 0);
    plc_file(&t, "PLCV", "SCRIPT", 'V', 100, 7, 1);
    tb_aws_mark(&t);
    t_write(dir, "in.aws", t.p, t.n);
    t_write(dir, "in.punch", ascii, strlen(ascii));
    snprintf(tape, sizeof tape, "%s/in.aws", dir);
    snprintf(deck, sizeof deck, "%s/in.punch", dir);
    snprintf(spec, sizeof spec, "A=%s", dir);
    for (which = 0; which < 2; which++) {
        for (k = 0; k < 400; k++) {
            cms_disks d;
            diag e;
            int rc;
            mem_fail_after(k);
            cms_disks_init(&d);
            diag_init(&e);
            rc = cms_disks_set(&d, spec, &e);
            if (!rc)
                rc = cms_import(&d, which ? deck : tape, NULL, NULL, NULL, NULL, &e);
            cms_disks_free(&d);
            mem_fail_after(-1);
            if (!rc)
                break;
            if (e.status != DIAG_IO)
                fprintf(stderr, "k=%ld: %s\n", k, e.msg);
            assert_int_equal(e.status, DIAG_IO);
        }
        assert_true(k < 400);
    }
    /* whatever failed left no temporary files: in.aws, in.punch, 4 files and the
     * sidecars of the 2 tape files */
    assert_int_equal(t_count_files(dir), 8);
    tb_free(&t);
    t_rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cms_tape_dump_both_trailers),
        cmocka_unit_test(test_cms_tape_real_trailer),
        cmocka_unit_test(test_cms_tape_vmfplc2),
        cmocka_unit_test(test_cms_tape_errors),
        cmocka_unit_test(test_cms_punch_two_files),
        cmocka_unit_test(test_cms_punch_rejects_unread_decks),
        cmocka_unit_test(test_cms_import_tape_to_disk),
        cmocka_unit_test(test_cms_oom_sweep_import),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
