/* test_dl — DL5080 decoding, encoding, disassembly, validation, the logic-op
 * rule, the software raster and the 5081 interpreter. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "display5080/dl_decode.h"
#include "display5080/dl_dump.h"
#include "display5080/dl_encode.h"
#include "display5080/dl_logic.h"
#include "display5080/dl_raster.h"
#include "display5080/dl_render.h"
#include "display5080/dl_validate.h"
#include "util/mem.h"
#include "support.h"
#include "unit/dl_test.h"

/* ---- helpers ------------------------------------------------------------ */

typedef struct bytes {
    uint8_t b[4096];
    size_t n;
} bytes;

static void put16(bytes *s, unsigned v)
{
    s->b[s->n++] = (uint8_t)(v >> 8);
    s->b[s->n++] = (uint8_t)v;
}

static void header_version(bytes *s, unsigned w, unsigned h, unsigned version)
{
    static const uint8_t magic[6] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0};
    memcpy(s->b, magic, 6);
    s->n = 6;
    put16(s, version);
    put16(s, 0);
    put16(s, w);
    put16(s, h);
    put16(s, 0);
}

/* A version 1 header: the tests that use it check that old lists still
 * decode and draw as they were written. */
static void header(bytes *s, unsigned w, unsigned h) { header_version(s, w, h, 1); }
/* The current version. */
static void header2(bytes *s, unsigned w, unsigned h) { header_version(s, w, h, 2); }

/* Appends an element from a list of 16-bit words (count words after code). */
static void elem(bytes *s, unsigned code, int nwords, ...)
{
    va_list ap;
    int i;
    put16(s, 4 + 2 * (unsigned)nwords);
    put16(s, code);
    va_start(ap, nwords);
    for (i = 0; i < nwords; i++)
        put16(s, (unsigned)va_arg(ap, int) & 0xFFFFu);
    va_end(ap);
}

static void end(bytes *s) { elem(s, DL_END, 0); }

/* Decodes and returns the formatted diagnostic ("" when it decoded). */
static const char *decode_msg(const bytes *s)
{
    static char buf[1024];
    dl_validate_summary sum;
    diag err;
    diag_init(&err);
    buf[0] = '\0';
    if (dl_validate(s->b, s->n, "t.dl", NULL, &sum, &err))
        diag_format(&err, buf, sizeof buf);
    return buf;
}

/* Renders with the software backend. */
static int render(const bytes *s, dl_frame *f, diag *err)
{
    diag_init(err);
    return dl_render(s->b, s->n, "t.dl", &dl_backend_png, NULL, f, err);
}

static uint8_t px(const dl_frame *f, int x, int y) { return f->px[(size_t)y * f->width + x]; }

/* ---- decoding ----------------------------------------------------------- */

static void test_dl_decode_header_and_every_element(void **state)
{
    bytes s;
    dl_validate_summary sum;
    diag err;
    int i;
    (void)state;
    header(&s, 64, 32);
    s.b[9] = 1;   /* 8-bit DAC */
    elem(&s, DL_LOAD_COLOURS, 6, 0, 2, 0x0012, 0x3456, 0x00AB, 0xCDEF);
    elem(&s, DL_CLEAR, 1, 0);
    elem(&s, DL_POLYLINE, 6, 0, 0, 10, 0, 10, 10);
    elem(&s, DL_SEGMENTS, 8, 0, 0, 1, 1, 5, 5, 6, 6);
    elem(&s, DL_FILL_RECT, 4, 1, 1, 3, 3);
    elem(&s, DL_FILL_CIRCLE, 3, 20, 20, 4);
    elem(&s, DL_CIRCLE, 3, 20, 20, 6);
    elem(&s, DL_BEGIN_POLYGON, 0);
    elem(&s, DL_POLYLINE, 6, 30, 1, 40, 1, 35, 10);
    elem(&s, DL_END_POLYGON, 0);
    elem(&s, DL_TEXT, 5, 2, 2, 3, 0xC1C2, 0xC300);   /* "ABC" in EBCDIC */
    elem(&s, DL_VIEWPORT, 4, 0, 0, 63, 31);
    elem(&s, DL_SCISSOR, 4, 0, 0, 63, 31);
    elem(&s, DL_BLT, 10, 50, 20, 52, 21, 8, 4, 0x0102, 0x0300, 0x0405, 0x0600);
    elem(&s, DL_NOOP, 2, 0x1234, 0x5678);
    elem(&s, DL_LINE_TYPE, 1, 1);
    elem(&s, DL_LINE_COLOUR, 1, 1);
    elem(&s, DL_INTERIOR_COLOUR, 1, 255);
    elem(&s, DL_LOGIC_OP, 1, 7);
    elem(&s, DL_PLANE_MASK, 1, 0x01F0);
    elem(&s, DL_RUN_ROW, 7, 5, 2, 2, 3, 1, 4, 0);
    end(&s);
    diag_init(&err);
    assert_string_equal(decode_msg(&s), "");
    assert_int_equal(dl_validate(s.b, s.n, "t.dl", NULL, &sum, &err), 0);
    assert_int_equal(sum.header.width, 64);
    assert_int_equal(sum.header.height, 32);
    assert_int_equal(sum.header.flags, DL_FLAG_DAC8);
    assert_int_equal(sum.elements, 22);
    for (i = 0; i < DL_FORMAT_NCODES; i++)   /* every version 1 code */
        assert_int_equal(sum.count[i], dl_format_codes[i].since > 1 ? 0
                                       : dl_format_codes[i].code == DL_POLYLINE ? 2 : 1);
}

static void test_dl_decode_malformed_errors_name_offsets(void **state)
{
    static const struct {
        int kind;
        const char *want;
    } cases[] = {
        {0, "t.dl: offset 0: error: file of 10 bytes is shorter than the 16-byte header"},
        {1, "t.dl: offset 0: error: not a DL5080 file (bad magic; a raw MegaPel stream needs --raw)"},
        {2, "t.dl: offset 6: error: unsupported version 3 (expected 1 or 2)"},
        {3, "t.dl: offset 8: error: unknown flag bits 0x0002"},
        {4, "t.dl: offset 10: error: width 0 is outside 1..4096"},
        {5, "t.dl: offset 12: error: height 4097 is outside 1..4096"},
        {6, "t.dl: offset 14: error: reserved header word is 0x0001, not 0"},
        {7, "t.dl: offset 16: error: missing end element (0x5F02)"},
        {8, "t.dl: offset 20: error: truncated element head (2 bytes left)"},
        {9, "t.dl: offset 16: error: element length 2 is below 4"},
        {10, "t.dl: offset 16: error: element length 7 is odd"},
        {11, "t.dl: offset 16: error: element length 40 runs past the end of the file (8 bytes left)"},
        {12, "t.dl: offset 16: error: unknown element code 0x5001"},
        {13, "t.dl: offset 16: error: polyline (0x5000): payload is not n points of 4 bytes with n >= 2"},
        {14, "t.dl: offset 16: error: segments (0x5003): payload is not k >= 1 pairs of 4-byte points"},
        {15, "t.dl: offset 16: error: fill-rect (0x5004): payload must be two points (8 bytes)"},
        {16, "t.dl: offset 16: error: scissor (0x5017): upper-right corner is left of or below the lower-left corner"},
        {17, "t.dl: offset 16: error: circle (0x5006): payload must be a centre and a radius (6 bytes)"},
        {18, "t.dl: offset 16: error: line-colour (0x5042): colour index 256 is above 255"},
        {19, "t.dl: offset 16: error: line-type (0x5040): line type 2 is not supported (version 1 has only 1, solid)"},
        {20, "t.dl: offset 16: error: logic-op (0x5060): logic op 17 is outside 1..16"},
        {21, "t.dl: offset 16: error: blt (0x5018): 4 bits per pixel (only 8 is defined)"},
        {22, "t.dl: offset 16: error: blt (0x5018): 3x1 pixels need 4 bytes, payload has 2"},
        {23, "t.dl: offset 16: error: load-colours (0x5F00): entries 255..256 run past the 256-entry table"},
        {24, "t.dl: offset 16: error: load-colours (0x5F00): colour 0 is not of the form 0x00RRGGBB"},
        {25, "t.dl: offset 16: error: text (0x500D): 5 text bytes do not match a payload of 10 bytes"},
        {26, "t.dl: offset 16: error: text (0x500D): pad byte is not zero"},
        {27, "t.dl: offset 16: error: run-row (0x5F03): 2 runs do not match a payload of 10 bytes"},
        {28, "t.dl: offset 20: error: fill-rect (0x5004): expected the polygon's boundary polyline after begin-polygon"},
        {29, "t.dl: offset 16: error: end-polygon (0x500B): end-polygon without begin-polygon and boundary"},
        {30, "t.dl: offset 40: error: end (0x5F02): expected end-polygon after the boundary polyline"},
        {31, "t.dl: offset 20: error: 2 bytes after the end element"},
        {32, "t.dl: offset 16: error: end (0x5F02): element takes no payload"},
        {33, "t.dl: offset 16: error: clear (0x5F01): payload must be one 16-bit word"},
        {34, "t.dl: offset 16: error: logic-op (0x5060): logic op 0 is outside 1..16"},
        {35, "t.dl: offset 16: error: run-row (0x5F03): colour index 300 is above 255"},
        {36, "t.dl: offset 40: error: polyline (0x5000): expected end-polygon after the boundary polyline"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        bytes s;
        header(&s, 16, 16);
        switch (cases[i].kind) {
        case 0: s.n = 10; break;
        case 1: s.b[0] = 'D'; end(&s); break;
        case 2: s.b[7] = 3; end(&s); break;
        case 3: s.b[9] = 2; end(&s); break;
        case 4: s.b[10] = s.b[11] = 0; end(&s); break;
        case 5: s.b[12] = 0x10; s.b[13] = 0x01; end(&s); break;
        case 6: s.b[15] = 1; end(&s); break;
        case 7: break;
        case 8: elem(&s, DL_NOOP, 0); s.b[s.n++] = 0; s.b[s.n++] = 8; break;
        case 9: put16(&s, 2); put16(&s, DL_END); break;
        case 10: put16(&s, 7); put16(&s, DL_NOOP); put16(&s, 0); put16(&s, 0); break;
        case 11: put16(&s, 40); put16(&s, DL_NOOP); end(&s); break;
        case 12: elem(&s, 0x5001, 2, 1, 1); end(&s); break;
        case 13: elem(&s, DL_POLYLINE, 2, 1, 1); end(&s); break;
        case 14: elem(&s, DL_SEGMENTS, 6, 1, 1, 2, 2, 3, 3); end(&s); break;
        case 15: elem(&s, DL_FILL_RECT, 3, 1, 1, 2); end(&s); break;
        case 16: elem(&s, DL_SCISSOR, 4, 5, 5, 4, 9); end(&s); break;
        case 17: elem(&s, DL_CIRCLE, 2, 5, 5); end(&s); break;
        case 18: elem(&s, DL_LINE_COLOUR, 1, 256); end(&s); break;
        case 19: elem(&s, DL_LINE_TYPE, 1, 2); end(&s); break;
        case 20: elem(&s, DL_LOGIC_OP, 1, 17); end(&s); break;
        case 21: elem(&s, DL_BLT, 6, 0, 0, 2, 0, 4, 4); end(&s); break;
        case 22: elem(&s, DL_BLT, 7, 0, 0, 2, 0, 8, 4, 0); end(&s); break;
        case 23: elem(&s, DL_LOAD_COLOURS, 6, 255, 2, 0, 0, 0, 0); end(&s); break;
        case 24: elem(&s, DL_LOAD_COLOURS, 4, 0, 1, 0x0100, 0); end(&s); break;
        case 25: elem(&s, DL_TEXT, 5, 0, 0, 5, 0xC1C1, 0xC1C1); end(&s); break;
        case 26: elem(&s, DL_TEXT, 5, 0, 0, 3, 0xC1C1, 0xC101); end(&s); break;
        case 27: elem(&s, DL_RUN_ROW, 5, 0, 0, 2, 1, 1); end(&s); break;
        case 28: elem(&s, DL_BEGIN_POLYGON, 0); elem(&s, DL_FILL_RECT, 4, 0, 0, 1, 1); end(&s); break;
        case 29: elem(&s, DL_END_POLYGON, 0); end(&s); break;
        case 30: elem(&s, DL_BEGIN_POLYGON, 0); elem(&s, DL_POLYLINE, 8, 0, 0, 5, 0, 5, 5, 0, 5); end(&s); break;
        case 31: end(&s); put16(&s, 0); break;
        case 32: elem(&s, DL_END, 1, 0); break;
        case 33: elem(&s, DL_CLEAR, 2, 0, 0); end(&s); break;
        case 34: elem(&s, DL_LOGIC_OP, 1, 0); end(&s); break;
        case 35: elem(&s, DL_RUN_ROW, 5, 0, 0, 1, 1, 300); end(&s); break;
        case 36: elem(&s, DL_BEGIN_POLYGON, 0); elem(&s, DL_POLYLINE, 8, 0, 0, 5, 0, 5, 5, 0, 5);
                 elem(&s, DL_POLYLINE, 4, 0, 0, 1, 1); end(&s); break;
        }
        if (strcmp(decode_msg(&s), cases[i].want)) {
            print_error("case %d:\n got: %s\nwant: %s\n", cases[i].kind, decode_msg(&s), cases[i].want);
            fail();
        }
    }
}

static void test_dl_decode_step_limit(void **state)
{
    bytes s;
    dl_decode_opts o = {.max_elements = 3};
    diag err;
    char buf[256];
    (void)state;
    header(&s, 8, 8);
    elem(&s, DL_NOOP, 0);
    elem(&s, DL_NOOP, 0);
    elem(&s, DL_NOOP, 0);
    end(&s);
    diag_init(&err);
    assert_int_equal(dl_decode(s.b, s.n, "t.dl", &o, NULL, NULL, NULL, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "t.dl: offset 28: error: step limit of 3 elements reached");
}

/* Every truncation of a valid list is an error, never a crash. */
static void test_dl_decode_every_truncation_fails(void **state)
{
    bytes s, t;
    size_t n;
    (void)state;
    header(&s, 8, 8);
    elem(&s, DL_LOAD_COLOURS, 4, 0, 1, 0x00FF, 0x0000);
    elem(&s, DL_POLYLINE, 4, 0, 0, 7, 7);
    elem(&s, DL_BLT, 8, 0, 0, 0, 1, 8, 4, 0x0100, 0x0100);
    end(&s);
    assert_string_equal(decode_msg(&s), "");
    for (n = 0; n < s.n; n++) {
        memcpy(&t, &s, sizeof t);
        t.n = n;
        assert_true(decode_msg(&t)[0] != '\0');
    }
}

/* ---- encoder ------------------------------------------------------------ */

static void test_dl_encode_matches_hand_bytes(void **state)
{
    bytes s;
    dl_encoder enc;
    uint8_t *out;
    size_t len;
    diag err;
    int pts[4] = {-1, 2, 300, -400};
    uint32_t cols[2] = {0x123456, 0xABCDEF};
    uint8_t rows[4] = {1, 2, 3, 9};
    unsigned runs[4] = {3, 1, 4, 0};
    const uint8_t text[3] = {0xC1, 0xC2, 0xC3};
    (void)state;
    header2(&s, 640, 480);
    elem(&s, DL_LOAD_COLOURS, 6, 0, 2, 0x0012, 0x3456, 0x00AB, 0xCDEF);
    elem(&s, DL_POLYLINE, 4, -1, 2, 300, -400);
    elem(&s, DL_FILL_RECT, 4, 1, 2, 3, 4);
    elem(&s, DL_CIRCLE, 3, 5, 6, 7);
    elem(&s, DL_TEXT, 5, 2, 3, 3, 0xC1C2, 0xC300);
    elem(&s, DL_BLT, 8, 10, 20, 12, 20, 8, 4, 0x0102, 0x0300);
    elem(&s, DL_RUN_ROW, 7, 7, 8, 2, 3, 1, 4, 0);
    elem(&s, DL_CLEAR, 1, 3);
    end(&s);
    dl_encode_init(&enc, 640, 480, 0);
    dl_encode_colours(&enc, 0, cols, 2);
    dl_encode_points(&enc, DL_POLYLINE, pts, 2);
    dl_encode_rect(&enc, DL_FILL_RECT, 1, 2, 3, 4);
    dl_encode_circle(&enc, DL_CIRCLE, 5, 6, 7);
    dl_encode_text(&enc, 2, 3, text, 3);
    dl_encode_blt(&enc, 10, 20, 3, 1, 4, rows, 4);
    dl_encode_run_row(&enc, 7, 8, runs, 2);
    dl_encode_word(&enc, DL_CLEAR, 3);
    dl_encode_simple(&enc, DL_END);
    diag_init(&err);
    assert_int_equal(dl_encode_finish(&enc, "e", &out, &len, &err), 0);
    assert_int_equal(len, s.n);
    assert_memory_equal(out, s.b, len);
    assert_int_equal(dl_encode_blt_size(3, 1), 16 + 4);
    assert_int_equal(dl_encode_run_row_size(2), 18);
    mem_free(out);
}

static void test_dl_encode_rejects_out_of_range(void **state)
{
    dl_encoder enc;
    uint8_t *out;
    size_t len;
    diag err;
    char buf[256];
    int pts[4] = {0, 0, 40000, 0};
    (void)state;
    dl_encode_init(&enc, 16, 16, 0);
    dl_encode_points(&enc, DL_POLYLINE, pts, 2);
    diag_init(&err);
    assert_int_equal(dl_encode_finish(&enc, "e", &out, &len, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "e: error: DL5080 encoding: coordinate 40000 is outside -32768..32767");
    {
        static int many[2 * 16400];
        dl_encode_init(&enc, 16, 16, 0);
        dl_encode_points(&enc, DL_POLYLINE, many, 16400);   /* 65604 bytes */
        diag_init(&err);
        assert_int_equal(dl_encode_finish(&enc, "e", &out, &len, &err), DIAG_INPUT);
        diag_format(&err, buf, sizeof buf);
        assert_string_equal(buf, "e: error: DL5080 encoding: element 0x5000 of 65604 bytes exceeds 65534 bytes");
    }
}

/* ---- disassembler ------------------------------------------------------- */

typedef struct sink {
    char buf[4096];
    size_t n;
} sink;

static void sink_write(void *ctx, const void *data, size_t len)
{
    sink *k = ctx;
    assert_true(k->n + len < sizeof k->buf);
    memcpy(k->buf + k->n, data, len);
    k->n += len;
    k->buf[k->n] = '\0';
}

static void test_dl_dump_exact_listing(void **state)
{
    bytes s;
    sink k;
    diag err;
    (void)state;
    header(&s, 32, 16);
    elem(&s, DL_LOAD_COLOURS, 4, 2, 1, 0x00A7, 0x0010);
    elem(&s, DL_POLYLINE, 4, -1, 2, 3, 4);
    elem(&s, DL_TEXT, 5, 2, 3, 3, 0xC1C2, 0xC300);
    elem(&s, DL_BLT, 8, 10, 2, 12, 2, 8, 4, 0x0102, 0x0300);
    elem(&s, DL_RUN_ROW, 5, 7, 8, 1, 3, 1);
    elem(&s, DL_PLANE_MASK, 1, 0x01F0);
    end(&s);
    memset(&k, 0, sizeof k);
    diag_init(&err);
    assert_int_equal(dl_dump(s.b, s.n, "t.dl", NULL, sink_write, &k, &err), 0);
    assert_string_equal(k.buf,
        "      0     16  ----  header version=1 flags=0x0000 dac=4 size=32x16\n"
        "     16     12  5F00  load-colours start=2 n=1 #A70010\n"
        "     28     12  5000  polyline n=2 -1,2 3,4\n"
        "     40     14  500D  text 2,3 n=3 \"ABC\"\n"
        "     54     20  5018  blt 10,2 12,2 bpp=8 op=4 (3x1 pixels)\n"
        "     74     14  5F03  run-row y=7 x0=8 n=1 3x1\n"
        "     88      6  5061  plane-mask 0x01F0 (writes planes 0xF0)\n"
        "     94      4  5F02  end\n");
}

/* ---- logic ops ---------------------------------------------------------- */

/* X11 GC functions written out (independent of the truth-table decoding). */
static uint8_t x11(unsigned op, unsigned s, unsigned d)
{
    unsigned r;
    switch (op - 1) {
    case 0: r = 0; break;
    case 1: r = s & d; break;
    case 2: r = s & ~d; break;
    case 3: r = s; break;
    case 4: r = ~s & d; break;
    case 5: r = d; break;
    case 6: r = s ^ d; break;
    case 7: r = s | d; break;
    case 8: r = ~(s | d); break;
    case 9: r = ~s ^ d; break;
    case 10: r = ~d; break;
    case 11: r = s | ~d; break;
    case 12: r = ~s; break;
    case 13: r = ~s | d; break;
    case 14: r = ~(s & d); break;
    default: r = 0xFF; break;
    }
    return (uint8_t)r;
}

static void test_dl_logic_ops_match_x11_and_split(void **state)
{
    uint64_t seed = test_seed("test_dl_logic_ops_match_x11_and_split");
    unsigned op, s, d;
    int i;
    (void)state;
    for (op = 1; op <= 16; op++)
        for (s = 0; s < 256; s++)
            for (d = 0; d < 256; d++)
                assert_int_equal(dl_logic_apply(op, (uint8_t)s, (uint8_t)d, 0xFF), x11(op, s, d));
    for (i = 0; i < 200000; i++) {
        unsigned m = (unsigned)(test_rand(&seed) & 0xFF);
        uint8_t clr, set, inv, want;
        op = 1 + (unsigned)(test_rand(&seed) % 16);
        s = (unsigned)(test_rand(&seed) & 0xFF);
        d = (unsigned)(test_rand(&seed) & 0xFF);
        want = (uint8_t)((x11(op, s, d) & m) | (d & ~m));
        assert_int_equal(dl_logic_apply(op, (uint8_t)s, (uint8_t)d, (uint8_t)m), want);
        dl_logic_split(op, (uint8_t)s, (uint8_t)m, &clr, &set, &inv);
        assert_int_equal((uint8_t)(((d & ~clr) | set) ^ inv), want);
        assert_int_equal(clr & set, 0);
        assert_int_equal((clr | set | inv) & ~m, 0);
    }
}

/* ---- raster and interpreter -------------------------------------------- */

static void test_dl_raster_lines_are_bresenham(void **state)
{
    uint64_t seed = test_seed("test_dl_raster_lines_are_bresenham");
    int t;
    (void)state;
    for (t = 0; t < 300; t++) {
        bytes s;
        dl_frame f;
        diag err;
        int x0 = (int)(test_rand(&seed) % 64), y0 = (int)(test_rand(&seed) % 64);
        int x1 = (int)(test_rand(&seed) % 64), y1 = (int)(test_rand(&seed) % 64);
        int dx = abs(x1 - x0), dy = abs(y1 - y0), n = 0, x, y;
        header(&s, 64, 64);
        elem(&s, DL_POLYLINE, 4, x0, y0, x1, y1);
        end(&s);
        assert_int_equal(render(&s, &f, &err), 0);
        assert_int_equal(px(&f, x0, y0), 1);
        assert_int_equal(px(&f, x1, y1), 1);
        for (y = 0; y < 64; y++)
            for (x = 0; x < 64; x++) {
                double dist;
                if (!px(&f, x, y))
                    continue;
                n++;
                /* distance along the minor axis from the ideal line is <= 1/2 */
                if (dx >= dy)
                    dist = dx ? fabs(y0 + (double)(y1 - y0) * (x - x0) / (x1 - x0) - y) : 0;
                else
                    dist = fabs(x0 + (double)(x1 - x0) * (y - y0) / (y1 - y0) - x);
                assert_true(dist <= 0.5 + 1e-9);
            }
        assert_int_equal(n, (dx > dy ? dx : dy) + 1);
        dl_frame_free(&f);
    }
}

static void test_dl_raster_polygon_even_odd(void **state)
{
    uint64_t seed = test_seed("test_dl_raster_polygon_even_odd");
    int t;
    (void)state;
    for (t = 0; t < 200; t++) {
        bytes s;
        dl_frame f;
        diag err;
        int n = 3 + (int)(test_rand(&seed) % 8), xy[22], i, x, y;
        header(&s, 48, 48);
        elem(&s, DL_BEGIN_POLYGON, 0);
        put16(&s, 4 + 4 * (unsigned)n);
        put16(&s, DL_POLYLINE);
        for (i = 0; i < n; i++) {
            xy[2 * i] = (int)(test_rand(&seed) % 60) - 6;
            xy[2 * i + 1] = (int)(test_rand(&seed) % 60) - 6;
            put16(&s, (unsigned)xy[2 * i] & 0xFFFF);
            put16(&s, (unsigned)xy[2 * i + 1] & 0xFFFF);
        }
        elem(&s, DL_END_POLYGON, 0);
        end(&s);
        assert_int_equal(render(&s, &f, &err), 0);
        for (y = 0; y < 48; y++)
            for (x = 0; x < 48; x++)
                assert_int_equal(px(&f, x, y), dl_test_inside(xy, n, x, y));
        dl_frame_free(&f);
    }
}

static void test_dl_raster_circles(void **state)
{
    bytes s;
    dl_frame f;
    diag err;
    int x, y, r;
    (void)state;
    for (r = 0; r < 20; r++) {
        header(&s, 64, 64);
        elem(&s, DL_FILL_CIRCLE, 3, 30, 31, r);
        elem(&s, DL_LOGIC_OP, 1, DL_OP_XOR);
        elem(&s, DL_LINE_COLOUR, 1, 2);
        elem(&s, DL_CIRCLE, 3, 30, 31, r);
        elem(&s, DL_CIRCLE, 3, 30, 31, r);   /* xor twice: no trace, so each pixel once */
        end(&s);
        assert_int_equal(render(&s, &f, &err), 0);
        for (y = 0; y < 64; y++)
            for (x = 0; x < 64; x++)
                assert_int_equal(px(&f, x, y), (x - 30) * (x - 30) + (y - 31) * (y - 31) <= r * r);
        dl_frame_free(&f);
        /* the outline: 8-way symmetric, each pixel within half a pixel of r */
        header(&s, 64, 64);
        elem(&s, DL_CIRCLE, 3, 30, 31, r);
        end(&s);
        assert_int_equal(render(&s, &f, &err), 0);
        for (y = 0; y < 64; y++)
            for (x = 0; x < 64; x++) {
                int dx = x - 30, dy = y - 31;
                if (!px(&f, x, y))
                    continue;
                assert_true(fabs(sqrt((double)(dx * dx + dy * dy)) - r) <= 0.5 + 1e-9);
                assert_int_equal(px(&f, 30 - dx, 31 + dy), 1);
                assert_int_equal(px(&f, 30 + dy, 31 + dx), 1);
            }
        assert_int_equal(px(&f, 30 + r, 31), 1);
        assert_int_equal(px(&f, 30, 31 - r), 1);
        dl_frame_free(&f);
    }
}

static void test_dl_interp_state_scissor_mask_ops(void **state)
{
    bytes s;
    dl_frame f;
    diag err;
    int x, y;
    (void)state;
    header(&s, 16, 8);
    elem(&s, DL_CLEAR, 1, 0x0F);                  /* whole screen */
    elem(&s, DL_SCISSOR, 4, 2, 1, 5, 3);
    elem(&s, DL_INTERIOR_COLOUR, 1, 0xF3);
    elem(&s, DL_FILL_RECT, 4, -100, -100, 100, 100);   /* clipped to the scissor */
    elem(&s, DL_SCISSOR, 4, 0, 0, 15, 7);
    elem(&s, DL_PLANE_MASK, 1, 0x3C);
    elem(&s, DL_LOGIC_OP, 1, DL_OP_XOR);
    elem(&s, DL_FILL_RECT, 4, 4, 0, 4, 7);
    elem(&s, DL_PLANE_MASK, 1, 0xFF);
    elem(&s, DL_LOGIC_OP, 1, 4);
    elem(&s, DL_VIEWPORT, 4, 3, 3, 3, 3);           /* no effect on device drawing */
    elem(&s, DL_BLT, 8, 10, 5, 11, 6, 8, 2, 0x0102, 0x0304);   /* op 2 = and */
    elem(&s, DL_RUN_ROW, 7, 7, 13, 2, 2, 9, 5, 8);    /* runs past the right edge */
    end(&s);
    assert_int_equal(render(&s, &f, &err), 0);
    for (y = 0; y < 8; y++)
        for (x = 0; x < 16; x++) {
            unsigned want = 0x0F;
            if (x >= 2 && x <= 5 && y >= 1 && y <= 3)
                want = 0xF3;
            if (x == 4)
                want = (want & ~0x3Cu) | ((want ^ 0xF3) & 0x3C);
            if (y == 5 && (x == 10 || x == 11))
                want = 0x0F & (x == 10 ? 1 : 2);           /* bottom row first */
            if (y == 6 && (x == 10 || x == 11))
                want = 0x0F & (x == 10 ? 3 : 4);
            if (y == 7 && x >= 13)
                want = x < 15 ? 9 : 8;
            if (px(&f, x, y) != want) {
                print_error("pixel %d,%d = 0x%02X, want 0x%02X\n", x, y, px(&f, x, y), want);
                fail();
            }
        }
    dl_frame_free(&f);
}

static void test_dl_interp_palette_and_dac(void **state)
{
    bytes s;
    dl_frame f;
    dl_render_opts ro = {.dac = 0};
    diag err;
    (void)state;
    header(&s, 4, 4);
    elem(&s, DL_LOAD_COLOURS, 4, 3, 1, 0x00A7, 0x1FF0);
    end(&s);
    assert_int_equal(render(&s, &f, &err), 0);
    assert_int_equal(f.dac, 4);
    assert_memory_equal(f.palette, "\x00\x00\x00\xFF\xFF\xFF\x00\x00\x00\xAA\x11\xFF", 12);
    dl_frame_free(&f);
    s.b[9] = 1;   /* 8-bit DAC flag */
    assert_int_equal(render(&s, &f, &err), 0);
    assert_int_equal(f.dac, 8);
    assert_memory_equal(f.palette + 9, "\xA7\x1F\xF0", 3);
    dl_frame_free(&f);
    ro.dac = 4;   /* forced */
    diag_init(&err);
    assert_int_equal(dl_render(s.b, s.n, "t.dl", &dl_backend_png, &ro, &f, &err), 0);
    assert_memory_equal(f.palette + 9, "\xAA\x11\xFF", 3);
    dl_frame_free(&f);
}

static void test_dl_interp_work_limit(void **state)
{
    bytes s;
    dl_frame f;
    dl_render_opts ro = {.work_limit = 1000};
    diag err;
    char buf[256];
    (void)state;
    header(&s, 16, 16);
    elem(&s, DL_POLYLINE, 4, -30000, -30000, 30000, 30000);
    end(&s);
    diag_init(&err);
    assert_int_equal(dl_render(s.b, s.n, "t.dl", &dl_backend_png, &ro, &f, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "t.dl: offset 16: error: drawing work limit of 1000 pixel steps exceeded");
    /* Clears and fills cost their pixels, counted by hand: three clears of
     * 16x16 and a 4x4 fill are 3*256 + 16 = 784 steps. */
    header(&s, 16, 16);
    elem(&s, DL_CLEAR, 1, 1);
    elem(&s, DL_CLEAR, 1, 2);
    elem(&s, DL_CLEAR, 1, 3);
    elem(&s, DL_FILL_RECT, 4, 2, 2, 5, 5);   /* offset 16 + 3*6 */
    end(&s);
    ro.work_limit = 784;
    diag_init(&err);
    assert_int_equal(dl_render(s.b, s.n, "t.dl", &dl_backend_png, &ro, &f, &err), 0);
    assert_int_equal(f.work, 784);
    assert_int_equal(px(&f, 2, 2), 1);
    assert_int_equal(px(&f, 6, 6), 3);
    dl_frame_free(&f);
    ro.work_limit = 783;
    diag_init(&err);
    assert_int_equal(dl_render(s.b, s.n, "t.dl", &dl_backend_png, &ro, &f, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "t.dl: offset 34: error: drawing work limit of 783 pixel steps exceeded");
    ro.work_limit = 767;   /* the third clear no longer fits */
    diag_init(&err);
    assert_int_equal(dl_render(s.b, s.n, "t.dl", &dl_backend_png, &ro, &f, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "t.dl: offset 28: error: drawing work limit of 767 pixel steps exceeded");
}

/* Fails each allocation in turn: a clean error, never a crash (leaks are
 * caught by the sanitizer build). */
static void test_dl_oom_sweep(void **state)
{
    bytes s;
    long n;
    int done = 0;
    (void)state;
    header(&s, 32, 32);
    elem(&s, DL_POLYLINE, 6, 0, 0, 31, 31, 0, 31);
    elem(&s, DL_CIRCLE, 3, 10, 10, 5);
    elem(&s, DL_BEGIN_POLYGON, 0);
    elem(&s, DL_POLYLINE, 6, 0, 0, 20, 0, 10, 20);
    elem(&s, DL_END_POLYGON, 0);
    end(&s);
    for (n = 0; !done && n < 100; n++) {
        dl_frame f;
        sink k;
        diag err;
        int rc;
        diag_init(&err);
        mem_fail_after(n);
        rc = dl_render(s.b, s.n, "t.dl", &dl_backend_png, NULL, &f, &err);
        mem_fail_after(-1);
        if (rc == 0) {
            dl_frame_free(&f);
            done = 1;
        } else {
            assert_int_equal(rc, DIAG_IO);
        }
        memset(&k, 0, sizeof k);
        diag_init(&err);
        mem_fail_after(n);
        rc = dl_dump(s.b, s.n, "t.dl", NULL, sink_write, &k, &err);
        mem_fail_after(-1);
        assert_true(rc == 0 || rc == DIAG_IO);
    }
    assert_true(done);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dl_decode_header_and_every_element),
        cmocka_unit_test(test_dl_decode_malformed_errors_name_offsets),
        cmocka_unit_test(test_dl_decode_step_limit),
        cmocka_unit_test(test_dl_decode_every_truncation_fails),
        cmocka_unit_test(test_dl_encode_matches_hand_bytes),
        cmocka_unit_test(test_dl_encode_rejects_out_of_range),
        cmocka_unit_test(test_dl_dump_exact_listing),
        cmocka_unit_test(test_dl_logic_ops_match_x11_and_split),
        cmocka_unit_test(test_dl_raster_lines_are_bresenham),
        cmocka_unit_test(test_dl_raster_polygon_even_odd),
        cmocka_unit_test(test_dl_raster_circles),
        cmocka_unit_test(test_dl_interp_state_scissor_mask_ops),
        cmocka_unit_test(test_dl_interp_palette_and_dac),
        cmocka_unit_test(test_dl_interp_work_limit),
        cmocka_unit_test(test_dl_oom_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
