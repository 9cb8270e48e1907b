/* test_cms_het — HET containers (zlib, bzip2, chunked records), the tape
 * writer read back, the layouts of real tapes (32-bit record counts, short
 * last blocks, standard labels), single-byte punch decks, and the import
 * transaction (name clashes, --replace, binary files). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "test_cms_lib.h"
#include "support.h"
#include "util/mem.h"
#include "vm_cms_shim/cms_attr.h"
#include "vm_cms_shim/cms_aws.h"
#include "vm_cms_shim/cms_import.h"
#include "vm_cms_shim/cms_tape.h"
#include <zlib.h>

static void sink_tb(void *ctx, const void *d, size_t n) { tb_put(ctx, d, n); }

static char t_notes[2048];

static void t_note(void *ctx, const diag *w)
{
    size_t k = strlen(t_notes);
    (void)ctx;
    cms_warn_format(w, t_notes + k, sizeof t_notes - k - 1);
    strcat(t_notes, "\n");
}

/* Records written with each compression and a small chunk size come back
 * whole; the chunk headers carry the compression on every chunk. */
static void test_cms_het_round_trip(void **state)
{
    static const cms_aws_comp comps[3] = {CMS_AWS_PLAIN, CMS_AWS_ZLIB, CMS_AWS_BZIP2};
    unsigned char big[10000];
    int c, i;
    (void)state;
    for (i = 0; i < (int)sizeof big; i++)
        big[i] = (unsigned char)(i % 7 == 0 ? i * 31 : 0x40);   /* compressible, not trivial */
    for (c = 0; c < (cms_aws_have_bzip2() ? 3 : 2); c++) {
        tbuf t = {0};
        cms_aws_writer w;
        cms_aws a;
        const unsigned char *rec;
        size_t len;
        long long off;
        diag e;
        cms_aws_writer_init(&w, sink_tb, &t, comps[c], 4096);
        assert_int_equal(cms_aws_put(&w, big, sizeof big, &e), 0);
        assert_int_equal(cms_aws_put(&w, "\x02\xC3\xD4\xE2\x40", 5, &e), 0);
        cms_aws_put_mark(&w);
        cms_aws_writer_free(&w);
        /* first chunk: start of record, the method in flags1 */
        assert_int_equal(t.p[4] & 0x80, 0x80);
        assert_int_equal(t.p[4] & 0x03, (int)comps[c]);
        if (comps[c] == CMS_AWS_PLAIN)   /* 10000 bytes in chunks of 4096: 3 chunks */
            assert_int_equal(t.p[4], 0x80);
        assert_true(cms_aws_detect(t.p, t.n));
        cms_aws_init(&a, t.p, t.n, "t.het", NULL);
        diag_init(&e);
        assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), CMS_AWS_RECORD);
        assert_int_equal(len, sizeof big);
        assert_memory_equal(rec, big, sizeof big);
        assert_int_equal(off, 0);
        assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), CMS_AWS_RECORD);
        assert_int_equal(len, 5);
        assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), CMS_AWS_MARK);
        assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), CMS_AWS_END);
        assert_int_equal(a.chain_breaks, 0);
        cms_aws_free(&a);
        tb_free(&t);
    }
}

/* Corrupt and hostile HET records are errors with their offsets. */
static void test_cms_het_errors(void **state)
{
    tbuf t = {0};
    cms_aws a;
    const unsigned char *rec;
    size_t len;
    long long off;
    diag e;
    unsigned char *zeros, *z;
    uLongf zn;
    (void)state;
    /* zlib data that inflates past the 2 MiB record limit */
    zeros = calloc(3u << 20, 1);
    zn = compressBound(3u << 20);
    z = malloc(zn);
    assert_non_null(zeros);
    assert_non_null(z);
    assert_int_equal(compress2(z, &zn, zeros, 3u << 20, 9), Z_OK);
    assert_true(zn < 65535);
    t_aws_prev = 0;
    tb_aws_record(&t, z, zn);
    t.p[4] |= 0x01;
    cms_aws_init(&a, t.p, t.n, "bomb.het", NULL);
    diag_init(&e);
    assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), -1);
    assert_string_equal(e.msg, "HET record: zlib data inflates past the 2 MiB record limit, or is "
                               "cut short");
    cms_aws_free(&a);
    /* bzip2 flag on bytes that are no bzip2 stream */
    t.p[4] = (unsigned char)((t.p[4] & ~0x03) | 0x02);
    cms_aws_init(&a, t.p, t.n, "bad.het", NULL);
    diag_init(&e);
    assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), -1);
    assert_string_equal(e.msg, cms_aws_have_bzip2()
                        ? "HET record: bzip2 data is corrupt or cut short"
                        : "HET record is compressed with bzip2, and this maprt was built without "
                          "libbz2 (apt-get install libbz2-dev, then rebuild)");
    assert_int_equal(e.offset, 0);
    cms_aws_free(&a);
    /* chunks of one record that disagree on the compression */
    t.n = 0;
    t_aws_prev = 0;
    tb_aws_record(&t, (const unsigned char *)"ABCD", 4);
    tb_aws_record(&t, (const unsigned char *)"EFGH", 4);
    t.p[4] = 0x81;            /* start, zlib, no end */
    t.p[10 + 4] = 0x20;       /* end, plain */
    cms_aws_init(&a, t.p, t.n, "mix.het", NULL);
    diag_init(&e);
    assert_int_equal(cms_aws_next(&a, &rec, &len, &off, &e), -1);
    assert_string_equal(e.msg, "HET chunk compression differs from the record's first chunk");
    assert_int_equal(e.offset, 10);
    cms_aws_free(&a);
    free(zeros);
    free(z);
    tb_free(&t);
}

typedef struct tape_got {
    int n;
    cms_tape_file f[4];
    unsigned char *data[4];
} tape_got;

static int tape_collect(void *ctx, const cms_tape_file *f, diag *err)
{
    tape_got *g = ctx;
    (void)err;
    assert_true(g->n < 4);
    g->f[g->n] = *f;
    g->data[g->n] = malloc(f->len ? f->len : 1);
    memcpy(g->data[g->n], f->data, f->len);
    g->f[g->n].data = g->data[g->n];
    g->n++;
    return 0;
}

static void tape_got_free(tape_got *g)
{
    int i;
    for (i = 0; i < g->n; i++)
        free(g->data[i]);
}

/* A tape file description for the writer. */
static void t_tape_file(cms_tape_file *f, const char *fn, const char *ft, char num, char recfm,
                        long lrecl, long count, const unsigned char *data, size_t len)
{
    memset(f, 0, sizeof *f);
    strcpy(f->id.fn, fn);
    strcpy(f->id.ft, ft);
    f->id.mode = 'A';
    f->id.num = num;
    f->recfm = recfm;
    f->lrecl = lrecl;
    f->count = count;
    f->data = data;
    f->len = len;
}

/* A file of 70,000 one-byte records: the TAPE DUMP trailer's 16-bit count
 * holds 4,464, the 32-bit count 70,000, and the 32-bit count wins; both
 * formats and both containers carry it. */
static void test_cms_tape_write_read_counts(void **state)
{
    static const cms_tape_kind kinds[2] = {CMS_TAPE_DUMP, CMS_TAPE_VMFPLC2};
    unsigned char *stream = malloc(70000);
    int k, comp;
    (void)state;
    memset(stream, 0xC1, 70000);
    for (k = 0; k < 2; k++)
        for (comp = 0; comp < 3; comp++) {
            tbuf t = {0};
            cms_tape_writer w;
            cms_tape_file f;
            tape_got g;
            diag e;
            memset(&g, 0, sizeof g);
            t_tape_file(&f, "MANY", "DATA", '2', 'F', 1, 70000, stream, 70000);
            strcpy(f.date, "1985-03-04 05:06:07");
            cms_tape_writer_init(&w, kinds[k], (cms_aws_comp)comp, sink_tb, &t);
            diag_init(&e);
            assert_int_equal(cms_tape_write_file(&w, &f, &e), 0);
            cms_tape_writer_end(&w);
            assert_int_equal(cms_tape_read(t.p, t.n, "many.tape", NULL, tape_collect, &g, NULL, &e), 0);
            assert_int_equal(g.n, 1);
            assert_int_equal(g.f[0].kind, kinds[k]);
            assert_int_equal(g.f[0].count, 70000);
            assert_int_equal(g.f[0].id.num, '2');
            assert_true(g.f[0].len >= 70000);
            assert_memory_equal(g.f[0].data, stream, 70000);
            /* TAPE DUMP keeps the short date (no seconds); VMFPLC2 the EDF date */
            assert_string_equal(g.f[0].date, kinds[k] == CMS_TAPE_DUMP ? "1985-03-04 05:06"
                                                                        : "1985-03-04 05:06:07");
            tape_got_free(&g);
            tb_free(&t);
        }
    free(stream);
}

/* A trailer whose 32-bit field does not extend the 16-bit count (VM/370
 * trailers carry no such count): the 16-bit count is used, with a note. */
static void test_cms_tape_count_rule(void **state)
{
    tbuf t = {0};
    cms_tape_writer w;
    cms_tape_file f;
    tape_got g;
    cms_warn wn;
    diag e;
    size_t tr;
    (void)state;
    memset(&g, 0, sizeof g);
    t_tape_file(&f, "A", "B", '1', 'F', 80, 3, (const unsigned char *)calloc(240, 1), 240);
    cms_tape_writer_init(&w, CMS_TAPE_DUMP, CMS_AWS_PLAIN, sink_tb, &t);
    diag_init(&e);
    assert_int_equal(cms_tape_write_file(&w, &f, &e), 0);
    cms_tape_writer_end(&w);
    tr = 6 + 805 + 6 + 5;                    /* the trailer's data */
    t.p[tr + 35] = 0x77;                     /* 32-bit field 0x00000077: not 3 */
    wn.fn = t_note;
    wn.ctx = NULL;
    t_notes[0] = '\0';
    assert_int_equal(cms_tape_read(t.p, t.n, "c.aws", &wn, tape_collect, &g, NULL, &e), 0);
    assert_int_equal(g.f[0].count, 3);
    assert_non_null(strstr(t_notes, "c.aws: offset 854: warning: trailer: the 32-bit field 119 "
                                    "does not extend the 16-bit record count 3"));
    tape_got_free(&g);
    free((void *)f.data);
    tb_free(&t);
}

/* Real-tape layouts: a short last data block (as other tape writers make),
 * standard labels before the CMS file (skipped with a note), a short block
 * that is not the last (refused). */
static void test_cms_tape_real_layouts(void **state)
{
    tbuf t = {0}, r = {0};
    tape_got g;
    cms_warn wn;
    diag e;
    int i;
    (void)state;
    t_aws_prev = 0;
    tb_ebcdic(&r, "VOL1TAPE01", 1047, 80);
    tb_aws_record(&t, r.p, r.n);
    r.n = 0;
    tb_ebcdic(&r, "HDR1CMS.FILES", 1047, 80);
    tb_aws_record(&t, r.p, r.n);
    tb_aws_mark(&t);
    /* 3 records of 80 = 240 bytes in one short block */
    r.n = 0;
    tb_put(&r, "\x02\xC3\xD4\xE2\x40", 5);
    for (i = 0; i < 3; i++)
        tb_ebcdic(&r, "SHORT BLOCK RECORD", 1047, 80);
    tb_aws_record(&t, r.p, r.n);
    r.n = 0;
    tb_put(&r, "\x02\xC3\xD4\xE2\xD5", 5);
    tb_be(&r, 4, 2);
    tb_be(&r, 1, 2);
    tb_put(&r, "\xC1\xF1", 2);
    tb_be(&r, 3, 2);
    tb_be(&r, 0, 2);
    tb_byte(&r, 0xC6);
    tb_byte(&r, 0);
    tb_be(&r, 80, 4);
    tb_fill(&r, 0, 64 - 16);
    tb_ebcdic(&r, "SHORT   ", 1047, 0);
    tb_ebcdic(&r, "DATA    ", 1047, 0);
    tb_put(&r, "\xC1\xF1", 2);
    tb_aws_record(&t, r.p, r.n);
    tb_aws_mark(&t);
    memset(&g, 0, sizeof g);
    wn.fn = t_note;
    wn.ctx = NULL;
    t_notes[0] = '\0';
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, t.n, "sl.aws", &wn, tape_collect, &g, NULL, &e), 0);
    assert_int_equal(g.n, 1);
    assert_string_equal(g.f[0].id.fn, "SHORT");
    assert_int_equal(g.f[0].len, 240);
    assert_int_equal(g.f[0].count, 3);
    assert_non_null(strstr(t_notes, "sl.aws: offset 0: warning: standard label skipped: VOL1TAPE01"));
    tape_got_free(&g);
    /* the same short block followed by a full one */
    t.n = 0;
    t_aws_prev = 0;
    r.n = 0;
    tb_put(&r, "\x02\xC3\xD4\xE2\x40", 5);
    tb_fill(&r, 0x40, 240);
    tb_aws_record(&t, r.p, r.n);
    tb_fill(&r, 0x40, 560);
    tb_aws_record(&t, r.p, r.n);
    memset(&g, 0, sizeof g);
    diag_init(&e);
    assert_int_equal(cms_tape_read(t.p, t.n, "s2.aws", NULL, tape_collect, &g, NULL, &e), DIAG_INPUT);
    assert_string_equal(e.msg, "data block after the short block at offset 0 (only the last block "
                               "of a file may be short)");
    assert_int_equal(e.offset, 251);
    tb_free(&t);
    tb_free(&r);
}

/* Hercules' ASCII punch writes one byte per column (ISO 8859-1 for the
 * 819/1047 table): an 80-column card with a cent sign and CRLF is 82 bytes
 * and reads as one 80-column record. */
static void test_cms_punch_single_byte(void **state)
{
    char line[83];
    cms_recs r;
    diag e;
    size_t len;
    const char *rec;
    (void)state;
    memset(line, 'X', 80);
    line[10] = (char)0xA2;     /* cent sign */
    line[79] = (char)0xAC;     /* not sign */
    line[80] = '\r';
    line[81] = '\n';
    diag_init(&e);
    assert_int_equal(cms_recs_decode((const unsigned char *)line, 82, NULL, "p.txt", &r, &e), 0);
    assert_int_equal(r.count, 1);
    assert_int_equal(r.recfm, 'F');
    assert_int_equal(r.lrecl, 80);
    rec = cms_recs_at(&r, 0, &len);
    assert_int_equal(len, 82);                 /* two UTF-8 sequences of 2 bytes */
    assert_memory_equal(rec + 10, "\xC2\xA2", 2);
    assert_memory_equal(rec + 80, "\xC2\xAC", 2);
    cms_recs_free(&r);
}

static void t_report(void *ctx, const cms_import_item *it)
{
    (void)it;
    (*(int *)ctx)++;
}

/* One import is one transaction: a name used twice fails naming both places
 * and leaves nothing; an existing file needs replace; binary files keep
 * their bytes and get a sidecar. */
static void test_cms_import_transaction(void **state)
{
    char *dir = t_mkdtemp(), spec[300], tape[300], path[400];
    static const char deck[] = ":READ  ONE      DATA     A1\nX\n:READ  TWO      DATA     A1\nY\n"
                               ":READ  ONE      DATA     A2\nZ\n";
    cms_disks d;
    cms_import_opts o;
    cms_attr attr;
    diag e;
    long n = 0;
    int reports = 0;
    tbuf t = {0};
    cms_tape_writer w;
    cms_tape_file f;
    unsigned char bin[16] = {0x00, 0x01, 0x02, 0xC1, 0xFF, 0x40, 0x15, 0x25,
                             0x00, 0x00, 0x00, 0x00, 0xDE, 0xAD, 0xBE, 0xEF};
    (void)state;
    snprintf(spec, sizeof spec, "A=%s", dir);
    cms_disks_init(&d);
    diag_init(&e);
    assert_int_equal(cms_disks_set(&d, spec, &e), 0);
    t_write(dir, "in.punch", deck, strlen(deck));
    snprintf(tape, sizeof tape, "%s/in.punch", dir);
    memset(&o, 0, sizeof o);
    assert_int_equal(cms_import(&d, tape, &o, t_report, &reports, &n, &e), DIAG_INPUT);
    assert_non_null(strstr(e.msg, "ONE DATA occurs twice in one import: at "));
    assert_non_null(strstr(e.msg, "in.punch:1 and at "));
    assert_non_null(strstr(e.msg, "in.punch:5"));
    assert_int_equal(reports, 0);
    assert_int_equal(t_count_files(dir), 1);        /* only the deck: nothing imported */
    /* a binary V file on a tape: kept byte for byte, mode number 3 */
    {
        static unsigned char s[2 + 16 + 2 + 4];
        s[0] = 0;
        s[1] = 16;
        memcpy(s + 2, bin, 16);
        s[18] = 0;
        s[19] = 4;
        memcpy(s + 20, bin + 12, 4);
        t_tape_file(&f, "PROG", "MODULE", '3', 'V', 16, 2, s, sizeof s);
        cms_tape_writer_init(&w, CMS_TAPE_VMFPLC2, cms_aws_have_bzip2() ? CMS_AWS_BZIP2 : CMS_AWS_ZLIB,
                             sink_tb, &t);
        assert_int_equal(cms_tape_write_file(&w, &f, &e), 0);
        cms_tape_writer_end(&w);
        t_write(dir, "in.het", t.p, t.n);
        snprintf(tape, sizeof tape, "%s/in.het", dir);
        diag_init(&e);
        assert_int_equal(cms_import(&d, tape, &o, NULL, NULL, &n, &e), 0);
        assert_int_equal(n, 1);
        {
            FILE *fh;
            unsigned char got[64];
            size_t k;
            snprintf(path, sizeof path, "%s/prog.module", dir);
            fh = fopen(path, "rb");
            assert_non_null(fh);
            k = fread(got, 1, sizeof got, fh);
            fclose(fh);
            assert_int_equal(k, sizeof s);
            assert_memory_equal(got, s, sizeof s);
        }
        assert_int_equal(cms_attr_read(path, &attr, &e), 0);
        assert_int_equal(attr.present, 1);
        assert_int_equal(attr.binary, 1);
        assert_int_equal(attr.recfm, 'V');
        assert_int_equal(attr.lrecl, 16);
        assert_int_equal(attr.num, '3');
    }
    /* again: the file exists, refused without replace, accepted with it */
    diag_init(&e);
    assert_int_equal(cms_import(&d, tape, &o, NULL, NULL, &n, &e), DIAG_INPUT);
    assert_non_null(strstr(e.msg, "file exists on disk A as 'prog.module'"));
    o.replace = 1;
    diag_init(&e);
    assert_int_equal(cms_import(&d, tape, &o, NULL, NULL, &n, &e), 0);
    /* --binary fail names record 1, column 1 */
    o.binary = CMS_BINARY_FAIL;
    diag_init(&e);
    assert_int_equal(cms_import(&d, tape, &o, NULL, NULL, &n, &e), DIAG_INPUT);
    assert_int_equal(e.line, 1);
    assert_int_equal(e.col, 1);
    assert_int_equal(t_count_files(dir), 4);   /* deck, tape, the file, its sidecar */
    cms_disks_free(&d);
    tb_free(&t);
    t_rmdir(dir);
}

/* Sidecar text: accepted as formatted, errors placed by line and column. */
static void test_cms_attr_parse(void **state)
{
    static const char good[] = "maprt-cms-attributes 1\nform binary\nrecfm V\nlrecl 80\nmode 2\n"
                               "date 2022-01-07 19:57:00\n";
    cms_attr a;
    char buf[256];
    diag e;
    (void)state;
    diag_init(&e);
    assert_int_equal(cms_attr_parse(good, strlen(good), "x.cms", &a, &e), 0);
    assert_int_equal(a.binary, 1);
    assert_int_equal(a.recfm, 'V');
    assert_int_equal(a.lrecl, 80);
    assert_int_equal(a.num, '2');
    assert_string_equal(a.date, "2022-01-07 19:57:00");
    assert_int_equal(cms_attr_format(&a, buf, sizeof buf), strlen(good));
    assert_string_equal(buf, good);
    assert_int_equal(cms_attr_parse("maprt-cms-attributes 1\nlrecl 0\n", 31, "y.cms", &a, &e),
                     DIAG_INPUT);
    assert_int_equal(e.line, 2);
    assert_int_equal(e.col, 7);
    assert_string_equal(e.msg, "lrecl must be 1..65535");
    diag_init(&e);
    assert_int_equal(cms_attr_parse("recfm F\n", 8, "z.cms", &a, &e), DIAG_INPUT);
    assert_int_equal(e.line, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cms_het_round_trip),
        cmocka_unit_test(test_cms_het_errors),
        cmocka_unit_test(test_cms_tape_write_read_counts),
        cmocka_unit_test(test_cms_tape_count_rule),
        cmocka_unit_test(test_cms_tape_real_layouts),
        cmocka_unit_test(test_cms_punch_single_byte),
        cmocka_unit_test(test_cms_import_transaction),
        cmocka_unit_test(test_cms_attr_parse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
