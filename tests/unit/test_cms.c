/* test_cms — the CMS shim's fileids, disks, code pages, record forms, record
 * file API and scene-deck recsrc, against vectors built here (EBCDIC by a
 * hand-written chart, see test_cms_lib.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "test_cms_lib.h"
#include "support.h"
#include "util/mem.h"
#include "vm_cms_shim/cms_deck.h"
#include "util/sha256.h"
#include "vm_cms_shim/cms_file.h"

/* The Figure 1 deck used throughout: card text (columns 1-72) and its
 * sequence field (73-80). Brackets and the caret are where 037 and 1047
 * differ. */
static const char *const fig1[] = {
    "* FIGURE 1 [AONO 1987]: CSG WITH MULTI-ATTRIBUTE PRIMITIVES",
    "EYE 0 -10 4",
    "LOOKAT 0 0 0",
    "LIGHT 5 -5 10",
    "ATTR RED COLOR 1 0 0 EXPONENT 2^3",
    "SPHERE S1 1.5 ATTR RED",
    "* [END]",
};
#define FIG1_N (sizeof fig1 / sizeof fig1[0])

/* The 80-column card image of fig1[i] (blank-padded, sequence number). */
static void fig1_card(size_t i, char card[81])
{
    snprintf(card, 81, "%-72sFIG%05u", fig1[i], (unsigned)(10 * (i + 1)));
}

static void fig1_ebcdic(tbuf *b, int cp)
{
    size_t i;
    char card[81];
    for (i = 0; i < FIG1_N; i++) {
        fig1_card(i, card);
        tb_ebcdic(b, card, cp, 80);
    }
}

static void expect_diag(const diag *d, const char *text)
{
    char buf[1024];
    diag_format(d, buf, sizeof buf);
    assert_string_equal(buf, text);
}

/* ---- fileids ------------------------------------------------------------ */

static void test_cms_fileid_table(void **state)
{
    static const struct { const char *in; int rc; const char *out; } t[] = {
        {"RAY DATA A1", 0, "RAY DATA A1"},
        {"ray data", 0, "RAY DATA A1"},
        {"RAY DATA B", 0, "RAY DATA B1"},
        {"  fig1   scene  a  ", 0, "FIG1 SCENE A1"},
        {"RAY DATA *", 0, "RAY DATA *"},
        {"$#@+-:_ X9 Z6", 0, "$#@+-:_ X9 Z6"},
        {"A B c0", 0, "A B C0"},
        {"RAYTRACER DATA", 20, NULL},
        {"RAY.DATA", 20, NULL},
        {"RAY DATA.X A", 20, NULL},
        {"RAY", 20, NULL},
        {"A B C D", 20, NULL},
        {"", 20, NULL},
        {"RAY DATA A7", 24, NULL},
        {"RAY DATA 1", 24, NULL},
        {"RAY DATA AB", 24, NULL},
        {"RAY DATA A12", 24, NULL},
        {"RAY D%TA", 20, NULL},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        cms_fileid id;
        diag d;
        char txt[CMS_FILEID_TEXT_MAX];
        int rc;
        diag_init(&d);
        rc = cms_fileid_parse(t[i].in, &id, &d);
        if (rc != t[i].rc)
            fail_msg("'%s': rc %d, expected %d", t[i].in, rc, t[i].rc);
        if (rc == 0)
            assert_string_equal(cms_fileid_format(&id, txt, sizeof txt), t[i].out);
        else {
            assert_int_equal(d.status, DIAG_INPUT);
            assert_int_equal(d.rc, t[i].rc);
        }
    }
}

static void test_cms_fileid_messages(void **state)
{
    cms_fileid id;
    diag d;
    (void)state;
    diag_init(&d);
    cms_fileid_parse("RAYTRACER DATA", &id, &d);
    expect_diag(&d, "RAYTRACER DATA: error: invalid character in fileid (RC 20): filename "
                    "'RAYTRACER' must be 1-8 characters");
    diag_init(&d);
    cms_fileid_parse("RAY.DATA X", &id, &d);
    expect_diag(&d, "RAY.DATA X: error: invalid character in fileid (RC 20): '.' in filename 'RAY.DATA'");
    diag_init(&d);
    cms_fileid_parse("RAY DATA A7", &id, &d);
    expect_diag(&d, "RAY DATA A7: error: invalid filemode (RC 24): 'A7' is not a letter A-Z "
                    "with an optional number 0-6");
}

static void test_cms_fileid_or_path(void **state)
{
    (void)state;
    assert_true(cms_fileid_is_fileid("FIG1 SCENE A"));
    assert_true(cms_fileid_is_fileid("fig1 scene"));
    assert_true(cms_fileid_is_fileid("FIG1 PNG A"));
    assert_false(cms_fileid_is_fileid("fig1.scene"));
    assert_false(cms_fileid_is_fileid("scenes/fig1 scene"));
    assert_false(cms_fileid_is_fileid("FIG1"));
    assert_false(cms_fileid_is_fileid("my scene.txt"));
    assert_false(cms_fileid_is_fileid("A B C D"));
    assert_false(cms_fileid_is_fileid("FIG1 SCENE A9"));
}

/* ---- disks -------------------------------------------------------------- */

static void test_cms_disk_lookup_rcs(void **state)
{
    char *dir = t_mkdtemp(), *path = NULL, spec[128];
    cms_disks d;
    cms_fileid id, found;
    diag e;
    (void)state;
    t_write(dir, "Fig1.Scene", "X\n", 2);
    cms_disks_init(&d);
    snprintf(spec, sizeof spec, "c=%s", dir);
    diag_init(&e);
    assert_int_equal(cms_disks_set(&d, spec, &e), 0);
    /* case-insensitive match on disk C */
    cms_fileid_parse("fig1 scene c", &id, &e);
    assert_int_equal(cms_disks_find(&d, &id, &path, &found, &e), 0);
    assert_non_null(strstr(path, "/Fig1.Scene"));
    mem_free(path);
    /* '*' searches A..Z: A (".") does not hold it, C does */
    cms_fileid_parse("FIG1 SCENE *", &id, &e);
    assert_int_equal(cms_disks_find(&d, &id, &path, &found, &e), 0);
    assert_int_equal(found.mode, 'C');
    mem_free(path);
    /* RC 28 and RC 36 */
    cms_fileid_parse("NOPE DATA C", &id, &e);
    assert_int_equal(cms_disks_find(&d, &id, &path, &found, &e), DIAG_INPUT);
    assert_int_equal(e.rc, 28);
    expect_diag(&e, "NOPE DATA C1: error: file not found (RC 28)");
    diag_init(&e);
    cms_fileid_parse("FIG1 SCENE Q", &id, &e);
    assert_int_equal(cms_disks_find(&d, &id, &path, &found, &e), DIAG_INPUT);
    assert_int_equal(e.rc, 36);
    expect_diag(&e, "FIG1 SCENE Q1: error: disk not accessed (RC 36): no directory for disk Q "
                    "(use --disk Q=DIR or MAPRT_DISK_Q)");
    /* output names: existing file reused, new file in lower case */
    cms_fileid_parse("FIG1 PNG C", &id, &e);
    assert_int_equal(cms_disks_output_path(&d, &id, &path, &e), 0);
    assert_non_null(strstr(path, "/fig1.png"));
    mem_free(path);
    diag_init(&e);
    assert_int_equal(cms_disks_set(&d, "AB", &e), DIAG_USAGE);
    cms_disks_free(&d);
    t_rmdir(dir);
}

static void test_cms_disk_env(void **state)
{
    cms_disks d;
    diag e;
    (void)state;
    setenv("MAPRT_DISK_K", "/some/where", 1);
    cms_disks_init(&d);
    diag_init(&e);
    assert_int_equal(cms_disks_from_env(&d, &e), 0);
    assert_string_equal(d.dir['K' - 'A'], "/some/where");
    assert_string_equal(d.dir[0], ".");
    assert_int_equal(cms_disks_set(&d, "k=/else", &e), 0);   /* option overrides */
    assert_string_equal(d.dir['K' - 'A'], "/else");
    cms_disks_free(&d);
    unsetenv("MAPRT_DISK_K");
}

/* ---- code pages ---------------------------------------------------------- */

static void test_cms_cp_six_differences(void **state)
{
    /* research table: EBCDIC byte, Latin-1 in 037, Latin-1 in 1047 */
    static const unsigned char diff[6][3] = {
        {0x5F, 0xAC, '^'}, {0xAD, 0xDD, '['}, {0xB0, '^', 0xAC},
        {0xBA, '[', 0xDD}, {0xBB, ']', 0xA8}, {0xBD, 0xA8, ']'}};
    const cms_cp *a, *b;
    diag e;
    int i, k, ndiff = 0;
    (void)state;
    diag_init(&e);
    assert_int_equal(cms_cp_get(CMS_CP_037, &a, &e), 0);
    assert_int_equal(cms_cp_get(CMS_CP_1047, &b, &e), 0);
    for (i = 0; i < 256; i++) {
        if (a->to_latin1[i] != b->to_latin1[i]) {
            int hit = 0;
            for (k = 0; k < 6; k++)
                if (diff[k][0] == i) {
                    assert_int_equal(a->to_latin1[i], diff[k][1]);
                    assert_int_equal(b->to_latin1[i], diff[k][2]);
                    hit = 1;
                }
            assert_true(hit);
            ndiff++;
        }
        if (i >= 0x40 && i != 0xFF) {   /* the hand chart agrees on its characters */
            int c = a->to_latin1[i];
            if (c < 0x80 && t_ebcdic(c, 37) >= 0)
                assert_int_equal(t_ebcdic(c, 37), i);
            c = b->to_latin1[i];
            if (c < 0x80 && t_ebcdic(c, 1047) >= 0)
                assert_int_equal(t_ebcdic(c, 1047), i);
        }
        assert_int_equal(a->from_latin1[a->to_latin1[i]], i);
    }
    assert_int_equal(ndiff, 6);
}

/* ---- record forms -------------------------------------------------------- */

static void check_fig1(const cms_recs *r)
{
    size_t i;
    char card[81];
    assert_int_equal(r->count, FIG1_N);
    for (i = 0; i < FIG1_N; i++) {
        fig1_card(i, card);
        assert_int_equal(r->rec[i].len, 80);
        assert_memory_equal(r->text + r->rec[i].off, card, 80);
    }
}

static void test_cms_fig1_ebcdic_037_and_1047(void **state)
{
    tbuf b037 = {0}, b1047 = {0};
    cms_recs r;
    cms_decode_opts o;
    diag e;
    (void)state;
    fig1_ebcdic(&b037, 37);
    fig1_ebcdic(&b1047, 1047);
    assert_true(b037.n == 80 * FIG1_N && memcmp(b037.p, b1047.p, b037.n) != 0);
    diag_init(&e);
    assert_int_equal(cms_recs_decode(b037.p, b037.n, NULL, "FIG1 SCENE A1", &r, &e), 0);
    assert_int_equal(r.form, CMS_FORM_EBCDIC);
    assert_int_equal(r.cp, CMS_CP_037);
    assert_int_equal(r.recfm, 'F');
    assert_int_equal(r.lrecl, 80);
    check_fig1(&r);
    cms_recs_free(&r);
    assert_int_equal(cms_recs_decode(b1047.p, b1047.n, NULL, "FIG1 SCENE A1", &r, &e), 0);
    assert_int_equal(r.cp, CMS_CP_1047);
    check_fig1(&r);
    cms_recs_free(&r);
    /* the wrong page shows Y-acute for '[' (X'AD' in 037) */
    memset(&o, 0, sizeof o);
    o.cp = CMS_CP_037;
    assert_int_equal(cms_recs_decode(b1047.p, b1047.n, &o, "X", &r, &e), 0);
    assert_memory_equal(r.text + r.rec[0].off, "* FIGURE 1 \xC3\x9D" "AONO", 15);
    cms_recs_free(&r);
    tb_free(&b037);
    tb_free(&b1047);
}

static void test_cms_cp_ambiguous_needs_option(void **state)
{
    tbuf b = {0};
    cms_recs r;
    cms_decode_opts o;
    diag e;
    (void)state;
    tb_ebcdic(&b, "A [ B", 37, 80);
    tb_ebcdic(&b, "A [ B", 1047, 80);
    diag_init(&e);
    assert_int_equal(cms_recs_decode(b.p, b.n, NULL, "MIXED DECK A1", &r, &e), DIAG_INPUT);
    expect_diag(&e, "MIXED DECK A1: error: the code page cannot be told from the bytes: both 037 "
                    "and 1047 bracket or caret codes occur (choose one with --cp 037 or --cp 1047)");
    memset(&o, 0, sizeof o);
    o.cp = CMS_CP_1047;
    diag_init(&e);
    assert_int_equal(cms_recs_decode(b.p, b.n, &o, "MIXED DECK A1", &r, &e), 0);
    assert_memory_equal(r.text + r.rec[1].off, "A [ B", 5);
    cms_recs_free(&r);
    tb_free(&b);
}

static void test_cms_vstream_vs_rdw(void **state)
{
    static const unsigned char v[] = {0x00, 0x02, 0xC8, 0xC9, 0x00, 0x05, 0xE3, 0xC8, 0xC5, 0xD9, 0xC5};
    static const unsigned char rdw[] = {0x00, 0x06, 0x00, 0x00, 0xC8, 0xC9,
                                        0x00, 0x09, 0x00, 0x00, 0xE3, 0xC8, 0xC5, 0xD9, 0xC5};
    static const unsigned char zero[] = {0x00, 0x02, 0xC8, 0xC9, 0x00, 0x00};
    static const unsigned char trunc[] = {0x00, 0x02, 0xC8, 0xC9, 0x00, 0x05, 0xE3};
    cms_recs r;
    cms_decode_opts o;
    diag e;
    (void)state;
    diag_init(&e);
    assert_int_equal(cms_recs_decode(v, sizeof v, NULL, "V", &r, &e), 0);
    assert_int_equal(r.form, CMS_FORM_VSTREAM);
    assert_int_equal(r.count, 2);
    assert_int_equal(r.recfm, 'V');
    assert_int_equal(r.lrecl, 5);
    assert_memory_equal(r.text + r.rec[0].off, "HI", 2);
    assert_memory_equal(r.text + r.rec[1].off, "THERE", 5);
    cms_recs_free(&r);
    assert_int_equal(cms_recs_decode(rdw, sizeof rdw, NULL, "R", &r, &e), 0);
    assert_int_equal(r.form, CMS_FORM_RDW);
    assert_int_equal(r.count, 2);
    assert_memory_equal(r.text + r.rec[1].off, "THERE", 5);
    cms_recs_free(&r);
    /* forcing the wrong one fails with a located error */
    memset(&o, 0, sizeof o);
    o.form = CMS_FORM_VSTREAM;
    assert_int_equal(cms_recs_decode(rdw, sizeof rdw, &o, "R", &r, &e), DIAG_INPUT);
    expect_diag(&e, "R: offset 2: error: record 1: byte X'00' is not a character of code page 1047");
    o.form = CMS_FORM_RDW;
    diag_init(&e);
    assert_int_equal(cms_recs_decode(v, sizeof v, &o, "V", &r, &e), DIAG_INPUT);
    expect_diag(&e, "V: offset 0: error: record 1: invalid RDW (length 2, flags C8C9)");
    o.form = CMS_FORM_VSTREAM;
    diag_init(&e);
    assert_int_equal(cms_recs_decode(zero, sizeof zero, &o, "V", &r, &e), DIAG_INPUT);
    expect_diag(&e, "V: offset 4: error: record 2: zero-length record (CMS V files have none)");
    diag_init(&e);
    assert_int_equal(cms_recs_decode(trunc, sizeof trunc, &o, "V", &r, &e), DIAG_INPUT);
    expect_diag(&e, "V: offset 4: error: record 2: length 5 runs past the end of the file (1 bytes left)");
    /* undetectable bytes fall back to text and say why when NUL appears */
    diag_init(&e);
    assert_int_equal(cms_recs_decode(trunc, sizeof trunc, NULL, "V", &r, &e), DIAG_INPUT);
    expect_diag(&e, "V:1:1: error: NUL byte: not a text file, nor a valid V or RDW stream "
                    "(choose the form with --read-as)");
}

static void test_cms_text_forms(void **state)
{
    static const char crlf[] = "ABC\r\nDEF\r\n";
    static const char var[] = "ABC\nDE\n\n";
    static const char punch[] = ":READ  FIG1     SCENE    A1 VOL001 11/22/87  10:15\nEYE 0 0 1\n\n";
    cms_recs r;
    diag e;
    char card[81];
    (void)state;
    diag_init(&e);
    assert_int_equal(cms_recs_decode((const unsigned char *)crlf, strlen(crlf), NULL, "T", &r, &e), 0);
    assert_int_equal(r.form, CMS_FORM_TEXT);
    assert_int_equal(r.recfm, 'F');
    assert_int_equal(r.lrecl, 3);
    assert_int_equal(r.count, 2);
    assert_memory_equal(r.text + r.rec[1].off, "DEF", 3);
    cms_recs_free(&r);
    assert_int_equal(cms_recs_decode((const unsigned char *)var, strlen(var), NULL, "T", &r, &e), 0);
    assert_int_equal(r.recfm, 'V');
    assert_int_equal(r.lrecl, 3);
    assert_int_equal(r.count, 3);
    assert_int_equal(r.rec[2].len, 0);
    cms_recs_free(&r);
    assert_int_equal(cms_recs_decode((const unsigned char *)punch, strlen(punch), NULL, "P", &r, &e), 0);
    assert_int_equal(r.form, CMS_FORM_PUNCH);
    assert_true(r.has_header);
    assert_string_equal(r.header.fn, "FIG1");
    assert_string_equal(r.header.ft, "SCENE");
    assert_int_equal(r.recfm, 'F');
    assert_int_equal(r.count, 2);
    snprintf(card, sizeof card, "%-80s", "EYE 0 0 1");
    assert_memory_equal(r.text + r.rec[0].off, card, 80);
    snprintf(card, sizeof card, "%-80s", "");
    assert_memory_equal(r.text + r.rec[1].off, card, 80);
    cms_recs_free(&r);
}

static void test_cms_text_errors(void **state)
{
    static const char two[] = ":READ  A        B        A1\nX\n:READ  C        D        A1\nY\n";
    static const char badhdr[] = ":READ  A.B      B        A1\nX\n";
    char long81[90];
    cms_recs r;
    cms_decode_opts o;
    diag e;
    (void)state;
    diag_init(&e);
    assert_int_equal(cms_recs_decode((const unsigned char *)two, strlen(two), NULL, "D", &r, &e), DIAG_INPUT);
    expect_diag(&e, "D:3:1: error: a second :READ card: this deck holds several files "
                    "(split it with 'maprt cms import')");
    diag_init(&e);
    assert_int_equal(cms_recs_decode((const unsigned char *)badhdr, strlen(badhdr), NULL, "D", &r, &e), DIAG_INPUT);
    expect_diag(&e, "D:1:8: error: :READ card: invalid character in fileid (RC 20): "
                    "'.' in filename 'A.B'");
    memset(long81, 'X', 81);
    long81[81] = '\n';
    memset(&o, 0, sizeof o);
    o.form = CMS_FORM_PUNCH;
    diag_init(&e);
    assert_int_equal(cms_recs_decode((const unsigned char *)long81, 82, &o, "D", &r, &e), DIAG_INPUT);
    expect_diag(&e, "D:1:81: error: card longer than 80 columns");
    /* a partial EBCDIC card and a control byte in a card */
    o.form = CMS_FORM_EBCDIC;
    diag_init(&e);
    {
        unsigned char c[85];
        memset(c, 0xC1, sizeof c);
        assert_int_equal(cms_recs_decode(c, 85, &o, "E", &r, &e), DIAG_INPUT);
        expect_diag(&e, "E: offset 80: error: the deck ends with a partial card of 5 bytes (cards are 80 bytes)");
        c[83] = 0x15;
        diag_init(&e);
        assert_int_equal(cms_recs_decode(c, 80, &o, "E", &r, &e), 0);
        cms_recs_free(&r);
        c[3] = 0x25;
        assert_int_equal(cms_recs_decode(c, 80, &o, "E", &r, &e), DIAG_INPUT);
        expect_diag(&e, "E:1:4: error: byte X'25' is not a character of code page 1047");
    }
}

/* ---- write -> read round trips -------------------------------------------- */

/* Random printable record of 0..maxlen columns, from a charset all forms
 * carry (including 037/1047-sensitive brackets when brackets != 0). */
static size_t rand_record(uint64_t *s, char *out, size_t maxlen, int brackets)
{
    static const char cs[] = "ABCXYZabcxyz0189 .,*()+-=/:$#@";
    size_t n = (size_t)(test_rand(s) % (maxlen + 1)), i;
    for (i = 0; i < n; i++) {
        unsigned k = (unsigned)(test_rand(s) % (sizeof cs - 1 + (brackets ? 3 : 0)));
        out[i] = k < sizeof cs - 1 ? cs[k] : "[]^"[k - (sizeof cs - 1)];
    }
    return n;
}

static void test_cms_roundtrip_every_form(void **state)
{
    static const cms_form forms[] = {CMS_FORM_TEXT, CMS_FORM_EBCDIC, CMS_FORM_VSTREAM, CMS_FORM_PUNCH};
    static const cms_cp_id cps[] = {CMS_CP_037, CMS_CP_1047};
    uint64_t s = test_seed("test_cms_roundtrip_every_form");
    char *dir = t_mkdtemp(), spec[128], recs[20][81];
    size_t lens[20];
    cms_disks d;
    diag e;
    int fi, ci, rf, round;
    (void)state;
    cms_disks_init(&d);
    snprintf(spec, sizeof spec, "A=%s", dir);
    diag_init(&e);
    assert_int_equal(cms_disks_set(&d, spec, &e), 0);
    for (round = 0; round < 6; round++)
        for (fi = 0; fi < 4; fi++)
            for (ci = 0; ci < 2; ci++)
                for (rf = 0; rf < 2; rf++) {
                    char recfm = rf ? 'V' : 'F';
                    long lrecl = 80;
                    int n = 1 + (int)(test_rand(&s) % 20), i;
                    cms_write_opts w;
                    cms_decode_opts o;
                    cms_file *f;
                    cms_file_info info;
                    memset(&w, 0, sizeof w);
                    w.form = forms[fi];
                    w.cp = cps[ci];
                    for (i = 0; i < n; i++)
                        lens[i] = rand_record(&s, recs[i], 80, forms[fi] != CMS_FORM_TEXT);
                    diag_init(&e);
                    assert_int_equal(cms_file_open_write(&f, &d, "RT FILE A", recfm, lrecl, &w, &e), 0);
                    for (i = 0; i < n; i++)
                        assert_int_equal(cms_file_write(f, recs[i], lens[i], &e), 0);
                    assert_int_equal(cms_file_close(f, &e), 0);
                    memset(&o, 0, sizeof o);
                    o.cp = cps[ci];      /* random brackets may mix codes: name the page */
                    o.form = forms[fi] == CMS_FORM_PUNCH ? CMS_FORM_AUTO : forms[fi];
                    if (cms_file_open_read(&f, &d, "rt file a", &o, &e))
                        fail_msg("form %s cp %d recfm %c: %s", cms_form_name(forms[fi]), cps[ci],
                                 recfm, e.msg);
                    cms_file_state(f, &info);
                    assert_int_equal(info.records, n);
                    assert_string_equal(info.label, "RT FILE A1");
                    for (i = 0; i < n; i++) {
                        const char *r;
                        size_t len, want = lens[i];
                        assert_int_equal(cms_file_read(f, 0, &r, &len), 0);
                        assert_int_equal(cms_file_recno(f), i + 1);
                        if (recfm == 'F' || forms[fi] == CMS_FORM_PUNCH || forms[fi] == CMS_FORM_EBCDIC) {
                            /* padded to LRECL with blanks */
                            assert_int_equal(len, 80);
                            assert_memory_equal(r, recs[i], want);
                            while (want < 80)
                                assert_int_equal(r[want++], ' ');
                        } else if (want == 0) {
                            assert_int_equal(len, 1);     /* empty V record written as a blank */
                            assert_int_equal(r[0], ' ');
                        } else {
                            assert_int_equal(len, want);
                            assert_memory_equal(r, recs[i], want);
                        }
                    }
                    assert_int_equal(cms_file_read(f, 0, &(const char *){0}, &(size_t){0}), CMS_RC_EOF);
                    assert_int_equal(cms_file_read(f, n + 1, &(const char *){0}, &(size_t){0}), CMS_RC_EOF);
                    if (n > 1) {          /* RECNO=n positions */
                        const char *r;
                        size_t len;
                        assert_int_equal(cms_file_read(f, 1, &r, &len), 0);
                        assert_int_equal(cms_file_recno(f), 1);
                    }
                    cms_file_abort(f);
                }
    assert_int_equal(cms_file_erase(&d, "RT FILE A", &e), 0);
    assert_int_equal(cms_file_erase(&d, "RT FILE A", &e), DIAG_INPUT);
    assert_int_equal(e.rc, 28);
    assert_int_equal(t_count_files(dir), 0);
    cms_disks_free(&d);
    t_rmdir(dir);
}

static void test_cms_write_limits_and_commit(void **state)
{
    char *dir = t_mkdtemp(), spec[128], path[256];
    cms_disks d;
    cms_file *f;
    diag e;
    struct stat st;
    (void)state;
    cms_disks_init(&d);
    snprintf(spec, sizeof spec, "A=%s", dir);
    diag_init(&e);
    cms_disks_set(&d, spec, &e);
    snprintf(path, sizeof path, "%s/out.data", dir);
    assert_int_equal(cms_file_open_write(&f, &d, "OUT DATA A", 'F', 4, NULL, &e), 0);
    assert_int_equal(cms_file_write(f, "ABCD", 4, &e), 0);
    assert_int_equal(stat(path, &st), -1);            /* nothing under the real name yet */
    assert_int_equal(cms_file_write(f, "ABCDE", 5, &e), DIAG_INPUT);
    expect_diag(&e, "OUT DATA A1:2:5: error: record of 5 bytes is longer than LRECL 4");
    diag_init(&e);
    assert_int_equal(cms_file_close(f, &e), DIAG_INPUT);   /* a rejected record: not committed */
    assert_int_equal(stat(path, &st), -1);
    assert_int_equal(t_count_files(dir), 0);
    assert_int_equal(cms_file_open_write(&f, &d, "OUT DATA A", 'V', 10, NULL, &e), 0);
    cms_file_abort(f);
    assert_int_equal(t_count_files(dir), 0);
    diag_init(&e);
    assert_int_equal(cms_file_open_write(&f, &d, "OUT DATA *", 'V', 10, NULL, &e), DIAG_INPUT);
    assert_int_equal(e.rc, 24);
    diag_init(&e);
    assert_int_equal(cms_file_open_write(&f, &d, "OUT DATA A", 'V', 0, NULL, &e), DIAG_USAGE);
    cms_disks_free(&d);
    t_rmdir(dir);
}

/* ---- the renderer's entry points ----------------------------------------- */

static void test_cms_deck_recsrc_names_fileid(void **state)
{
    char *dir = t_mkdtemp(), spec[128], card[81];
    tbuf b = {0};
    cms_disks d;
    cms_deck *dk;
    recsrc src;
    const char *rec;
    size_t len;
    diag e;
    int n = 0;
    cms_file_info info;
    (void)state;
    fig1_ebcdic(&b, 1047);
    t_write(dir, "FIG1.SCENE", b.p, b.n);
    cms_disks_init(&d);
    snprintf(spec, sizeof spec, "A=%s", dir);
    diag_init(&e);
    cms_disks_set(&d, spec, &e);
    assert_int_equal(cms_deck_open(&dk, &src, &d, "FIG1 SCENE A", NULL, &e), 0);
    assert_string_equal(src.name, "FIG1 SCENE A1");
    cms_deck_state(dk, &info);
    assert_int_equal(info.form, CMS_FORM_EBCDIC);
    /* the checksum is of the bytes read: the card images, not their text,
     * and still theirs after the file changes (a picture's provenance) */
    {
        sha256 h;
        char hex[65];
        sha256_init(&h);
        sha256_update(&h, b.p, b.n);
        sha256_hex(&h, hex);
        assert_string_equal(info.sha256, hex);
        t_write(dir, "FIG1.SCENE", "changed", 7);
        cms_deck_state(dk, &info);
        assert_string_equal(info.sha256, hex);
    }
    while (src.next(src.ctx, &rec, &len, &e) == 1) {
        fig1_card((size_t)n, card);
        assert_int_equal(len, 80);
        assert_memory_equal(rec, card, 80);
        n++;
    }
    assert_int_equal(n, FIG1_N);
    cms_deck_close(dk);
    /* the missing file: RC 28, exit status 1 (DIAG_INPUT) */
    diag_init(&e);
    assert_int_equal(cms_deck_open(&dk, &src, &d, "FIG2 SCENE A", NULL, &e), DIAG_INPUT);
    assert_int_equal(e.rc, 28);
    expect_diag(&e, "FIG2 SCENE A1: error: file not found (RC 28)");
    /* a host path goes straight to the host; missing is bad input (exit 1) */
    diag_init(&e);
    assert_int_equal(cms_deck_open(&dk, &src, &d, "/nonexistent/fig1.scene", NULL, &e), DIAG_INPUT);
    expect_diag(&e, "/nonexistent/fig1.scene: error: cannot open: No such file or directory");
    cms_disks_free(&d);
    tb_free(&b);
    t_rmdir(dir);
}

static void test_cms_name_output(void **state)
{
    cms_disks d;
    cms_name n;
    diag e;
    (void)state;
    cms_disks_init(&d);
    diag_init(&e);
    cms_disks_set(&d, "B=/tmp/out-dir", &e);
    assert_int_equal(cms_name_output(&d, "FIG1 PNG B", &n, &e), DIAG_INPUT);  /* dir missing */
    assert_int_equal(e.rc, 36);
    diag_init(&e);
    assert_int_equal(cms_name_output(&d, "out/fig1.png", &n, &e), 0);
    assert_false(n.is_fileid);
    assert_string_equal(n.path, "out/fig1.png");
    cms_name_free(&n);
    cms_disks_free(&d);
}

/* Every allocation failing in turn: a clean status, never a crash. */
static void test_cms_oom_sweep_records(void **state)
{
    char *dir = t_mkdtemp(), spec[128];
    tbuf b = {0};
    long k;
    (void)state;
    fig1_ebcdic(&b, 37);
    t_write(dir, "fig1.scene", b.p, b.n);
    snprintf(spec, sizeof spec, "A=%s", dir);
    for (k = 0; k < 200; k++) {
        cms_disks d;
        cms_deck *dk;
        cms_file *f;
        recsrc src;
        diag e;
        int rc, rc2 = 0;
        mem_fail_after(k);
        cms_disks_init(&d);
        diag_init(&e);
        rc = cms_disks_set(&d, spec, &e);
        if (!rc && (rc = cms_deck_open(&dk, &src, &d, "FIG1 SCENE A", NULL, &e)) == 0)
            cms_deck_close(dk);
        if (!rc && (rc2 = cms_file_open_write(&f, &d, "NEW FILE A", 'V', 80, NULL, &e)) == 0) {
            rc2 = cms_file_write(f, "X", 1, &e);
            rc2 = rc2 ? (cms_file_abort(f), rc2) : cms_file_close(f, &e);
        }
        cms_disks_free(&d);
        mem_fail_after(-1);
        if (rc || rc2)
            assert_true(e.status == DIAG_IO || e.status == DIAG_INPUT);
        else
            break;
    }
    assert_true(k < 200);
    {
        char p[256];
        snprintf(p, sizeof p, "%s/new.file", dir);
        remove(p);
    }
    assert_int_equal(t_count_files(dir), 1);
    tb_free(&b);
    t_rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cms_fileid_table),
        cmocka_unit_test(test_cms_fileid_messages),
        cmocka_unit_test(test_cms_fileid_or_path),
        cmocka_unit_test(test_cms_disk_lookup_rcs),
        cmocka_unit_test(test_cms_disk_env),
        cmocka_unit_test(test_cms_cp_six_differences),
        cmocka_unit_test(test_cms_fig1_ebcdic_037_and_1047),
        cmocka_unit_test(test_cms_cp_ambiguous_needs_option),
        cmocka_unit_test(test_cms_vstream_vs_rdw),
        cmocka_unit_test(test_cms_text_forms),
        cmocka_unit_test(test_cms_text_errors),
        cmocka_unit_test(test_cms_roundtrip_every_form),
        cmocka_unit_test(test_cms_write_limits_and_commit),
        cmocka_unit_test(test_cms_deck_recsrc_names_fileid),
        cmocka_unit_test(test_cms_name_output),
        cmocka_unit_test(test_cms_oom_sweep_records),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
