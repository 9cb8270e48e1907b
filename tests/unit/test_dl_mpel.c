/* test_dl_mpel — element streams assembled by hand the way IBM's X11 MegaPel
 * driver (X11R3/R4 server/ddx/ibm/mpel) assembles them, not the way maprt's
 * encoder writes them: the plane mask through the driver's translate table
 * ((~m & 0xFF) << 8, reset 0), logic ops as X GC function + 1 (reset 4),
 * image rows top-first from the upper edge of a rectangle whose y is flipped
 * by 1023 - y (mpelImg.c), colour expansion like the cursor code, dash
 * patterns encoded as mpelDash.c does, raw FIFO contents without a header.
 * Also: the stroke font, the code-page table against iconv, line widths,
 * version 1 lists against version 2, and the decoder's new errors. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <iconv.h>
#include <stdio.h>
#include <string.h>
#include "display5080/dl_decode.h"
#include "display5080/dl_encode.h"
#include "display5080/dl_font.h"
#include "display5080/dl_render.h"
#include "display5080/dl_validate.h"
#include "util/mem.h"
#include "support.h"
#include "unit/dl_test.h"

/* ---- a FIFO as the driver fills it --------------------------------------- */

typedef struct fifo {
    uint8_t b[8192];
    size_t n;
} fifo;

static void w16(fifo *f, unsigned v)
{
    assert_true(f->n + 2 <= sizeof f->b);
    f->b[f->n++] = (uint8_t)(v >> 8);
    f->b[f->n++] = (uint8_t)v;
}

/* mfCmd1Arg / mfCmdNArgs: length (head + arguments), code, words. */
static void cmd(fifo *f, unsigned code, int nwords, ...)
{
    va_list ap;
    int i;
    w16(f, 4 + 2 * (unsigned)nwords);
    w16(f, code);
    va_start(ap, nwords);
    for (i = 0; i < nwords; i++)
        w16(f, (unsigned)va_arg(ap, int) & 0xFFFFu);
    va_end(ap);
}

/* mfCmdVArgs + MPELSendData: the length word counts the fixed part plus the
 * data rounded up to even; the data follow, padded once at the end. */
static void cmd_data(fifo *f, unsigned code, const unsigned *args, int nargs, const uint8_t *d,
                     size_t n)
{
    int i;
    w16(f, (unsigned)(4 + 2 * nargs + n + (n & 1)));
    w16(f, code);
    for (i = 0; i < nargs; i++)
        w16(f, args[i] & 0xFFFFu);
    assert_true(f->n + n + 1 <= sizeof f->b);
    memcpy(f->b + f->n, d, n);
    f->n += n;
    if (n & 1)
        f->b[f->n++] = 0;
}

/* The driver's translate table entry for an X plane mask (mpelALU.c). */
static unsigned xlate(unsigned xmask) { return ((~xmask) & 0xFFu) << 8; }

/* A DL5080 version-2 header in front of a FIFO image and an end element. */
static void as_list(const fifo *raw, fifo *list, int w, int h)
{
    static const uint8_t magic[6] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0};
    memcpy(list->b, magic, 6);
    list->n = 6;
    w16(list, 2);
    w16(list, 1);   /* 8-bit DAC */
    w16(list, (unsigned)w);
    w16(list, (unsigned)h);
    w16(list, 0);
    memcpy(list->b + list->n, raw->b, raw->n);
    list->n += raw->n;
    cmd(list, DL_END, 0);
}

static void draw_raw(const fifo *f, int w, int h, const dl_backend *b, dl_frame *out)
{
    dl_render_opts ro;
    diag err;
    memset(&ro, 0, sizeof ro);
    ro.raw = 1;
    ro.width = w;
    ro.height = h;
    diag_init(&err);
    if (dl_render(f->b, f->n, "fifo", b, &ro, out, &err)) {
        char msg[512];
        diag_format(&err, msg, sizeof msg);
        fail_msg("%s: %s", b->name, msg);
    }
}

/* Validates a raw stream; the formatted diagnostic, or "" when it is valid. */
static const char *raw_msg(const fifo *f, dl_validate_summary *s)
{
    static char msg[512];
    dl_validate_summary t;
    dl_decode_opts d;
    diag err;
    memset(&d, 0, sizeof d);
    d.raw = 1;
    diag_init(&err);
    msg[0] = '\0';
    if (dl_validate(f->b, f->n, "fifo", &d, s ? s : &t, &err))
        diag_format(&err, msg, sizeof msg);
    return msg;
}

static uint8_t at(const dl_frame *f, int x, int y) { return f->px[(size_t)y * f->width + x]; }

/* ---- plane mask and logic ops -------------------------------------------- */

static void test_mpel_plane_mask_as_the_driver_sends_it(void **state)
{
    fifo f;
    dl_frame fr;
    (void)state;
    f.n = 0;
    /* MPELResetPlaneMask() then a fill: every plane is written. */
    cmd(&f, DL_PLANE_MASK, 1, 0);
    cmd(&f, DL_INTERIOR_COLOUR, 1, 0xA5);
    cmd(&f, DL_FILL_RECT, 4, 0, 0, 3, 0);
    /* mpelSetPlaneMask(0x0F): planes 0-3 writable, word 0xF000. */
    assert_int_equal(xlate(0x0F), 0xF000);
    cmd(&f, DL_PLANE_MASK, 1, (int)xlate(0x0F));
    cmd(&f, DL_INTERIOR_COLOUR, 1, 0xFF);
    cmd(&f, DL_FILL_RECT, 4, 0, 1, 3, 1);
    /* mpelSetPlaneMask(0xF0) over the first row with xor (GXxor = 6, sent as 7). */
    cmd(&f, DL_PLANE_MASK, 1, (int)xlate(0xF0));
    cmd(&f, DL_LOGIC_OP, 1, 6 + 1);
    cmd(&f, DL_FILL_RECT, 4, 2, 0, 3, 0);
    /* the glyph code's mpelSetPlaneMask(0xff): back to all planes */
    cmd(&f, DL_PLANE_MASK, 1, (int)xlate(0xFF));
    cmd(&f, DL_LOGIC_OP, 1, 3 + 1);   /* GXcopy */
    cmd(&f, DL_INTERIOR_COLOUR, 1, 0x3C);
    cmd(&f, DL_FILL_RECT, 4, 0, 2, 0, 2);
    draw_raw(&f, 4, 3, &dl_backend_png, &fr);
    assert_int_equal(at(&fr, 0, 0), 0xA5);
    assert_int_equal(at(&fr, 1, 0), 0xA5);
    assert_int_equal(at(&fr, 2, 0), 0xA5 ^ 0xF0);
    assert_int_equal(at(&fr, 0, 1), 0x0F);
    assert_int_equal(at(&fr, 0, 2), 0x3C);
    dl_frame_free(&fr);
}

/* X11's sixteen GC functions by name (X.h order), as the driver passes them:
 * mpelSetALU(a) sends a + 1. */
static unsigned gx(int fn, unsigned s, unsigned d)
{
    switch (fn) {
    case 0: return 0;               /* GXclear */
    case 1: return s & d;           /* GXand */
    case 2: return s & ~d;          /* GXandReverse */
    case 3: return s;               /* GXcopy */
    case 4: return ~s & d;          /* GXandInverted */
    case 5: return d;               /* GXnoop */
    case 6: return s ^ d;           /* GXxor */
    case 7: return s | d;           /* GXor */
    case 8: return ~(s | d);        /* GXnor */
    case 9: return ~s ^ d;          /* GXequiv */
    case 10: return ~d;             /* GXinvert */
    case 11: return s | ~d;         /* GXorReverse */
    case 12: return ~s;             /* GXcopyInverted */
    case 13: return ~s | d;         /* GXorInverted */
    case 14: return ~(s & d);       /* GXnand */
    default: return 0xFF;           /* GXset */
    }
}

static void test_mpel_logic_ops_are_gc_function_plus_one(void **state)
{
    fifo f;
    dl_frame fr;
    int fn;
    (void)state;
    f.n = 0;
    for (fn = 0; fn < 16; fn++) {
        cmd(&f, DL_LOGIC_OP, 1, 3 + 1);
        cmd(&f, DL_INTERIOR_COLOUR, 1, 0x5C);   /* destination */
        cmd(&f, DL_FILL_RECT, 4, fn, 0, fn, 0);
        cmd(&f, DL_LOGIC_OP, 1, fn + 1);
        cmd(&f, DL_INTERIOR_COLOUR, 1, 0x3A);   /* source */
        cmd(&f, DL_FILL_RECT, 4, fn, 0, fn, 0);
    }
    draw_raw(&f, 16, 1, &dl_backend_png, &fr);
    for (fn = 0; fn < 16; fn++)
        assert_int_equal(at(&fr, fn, 0), gx(fn, 0x3A, 0x5C) & 0xFF);
    dl_frame_free(&fr);
}

/* ---- images ------------------------------------------------------------- */

/* mpelDrawColorImage: an X image (rows top-down) at X position (x, y) on a
 * screen of height H goes out as rectangle lleft.y = H - (y + h), uright.y =
 * H - 1 - y, rows copied top row first and packed. */
static void put_image(fifo *f, int H, int x, int y, int w, int h, const uint8_t *rows, int alu)
{
    unsigned args[6];
    args[0] = (unsigned)x;
    args[1] = (unsigned)(H - (y + h));
    args[2] = (unsigned)(x + w - 1);
    args[3] = (unsigned)(H - 1 - y);
    args[4] = 8;
    args[5] = (unsigned)alu + 1;
    cmd_data(f, DL_BLT, args, 6, rows, (size_t)w * (size_t)h);
}

static void test_mpel_blt_rows_top_first_packed(void **state)
{
    static const int sizes[][2] = {{3, 2}, {3, 3}, {1, 1}, {5, 4}, {2, 7}};
    size_t k;
    (void)state;
    for (k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        int w = sizes[k][0], h = sizes[k][1], H = 12, x = 2, y = 3, r, c;
        uint8_t img[64];
        fifo f;
        dl_frame fr;
        for (r = 0; r < w * h; r++)
            img[r] = (uint8_t)(r + 1);
        f.n = 0;
        put_image(&f, H, x, y, w, h, img, 3);
        draw_raw(&f, 10, H, &dl_backend_png, &fr);
        /* X row r (top-down) is device row H-1-(y+r) */
        for (r = 0; r < h; r++)
            for (c = 0; c < w; c++)
                assert_int_equal(at(&fr, x + c, H - 1 - (y + r)), img[r * w + c]);
        assert_int_equal(at(&fr, x - 1, H - 1 - y), 0);
        dl_frame_free(&fr);
    }
}

/* The cursor code: a 16-wide pattern as colour expansion, foreground pass
 * then background pass, both GXcopy + 1, rows top-first, 2 bytes a row. */
static void test_mpel_colour_expansion_like_the_cursor(void **state)
{
    uint8_t fg[2 * 4] = {0x80, 0x01, 0xFF, 0x00, 0x00, 0xFF, 0xAA, 0x55};
    uint8_t bg[2 * 4];
    unsigned args[6];
    fifo f;
    dl_frame fr;
    int H = 8, x = 1, y = 2, r, c, i;
    (void)state;
    for (i = 0; i < 8; i++)
        bg[i] = (uint8_t)~fg[i];
    f.n = 0;
    args[0] = (unsigned)x;
    args[1] = (unsigned)(H - (y + 4));
    args[2] = (unsigned)(x + 16 - 1);
    args[3] = (unsigned)(H - 1 - y);
    args[4] = 7;   /* foreground colour */
    args[5] = 3 + 1;
    cmd_data(&f, DL_BLT_EXPAND, args, 6, fg, sizeof fg);
    args[4] = 9;   /* background colour */
    cmd_data(&f, DL_BLT_EXPAND, args, 6, bg, sizeof bg);
    draw_raw(&f, 20, H, &dl_backend_png, &fr);
    for (r = 0; r < 4; r++)
        for (c = 0; c < 16; c++) {
            int bit = fg[2 * r + c / 8] >> (7 - c % 8) & 1;
            assert_int_equal(at(&fr, x + c, H - 1 - (y + r)), bit ? 7 : 9);
        }
    dl_frame_free(&fr);
}

/* A width that is not whole bytes, and an adapter-memory BLT: refused, and
 * counted but not drawn. */
static void test_mpel_expansion_width_and_src_blt(void **state)
{
    unsigned args[8] = {0, 0, 9, 0, 1, 4};
    uint8_t bits[2] = {0xFF, 0xC0};
    fifo f;
    dl_frame fr;
    (void)state;
    f.n = 0;
    cmd_data(&f, DL_BLT_EXPAND, args, 6, bits, 2);
    assert_string_equal(raw_msg(&f, NULL), "fifo: offset 0: error: blt-expand (0x5019): width 10 is not a "
                             "whole number of bytes");
    /* MPELSrcBLTVPM as mpelDrawColorImage sends it */
    f.n = 0;
    cmd(&f, DL_SRC_BLT, 8, 0x0010, 0x8000, 0, 0, 3, 1, 8, 4);
    cmd(&f, DL_NOOP, 1, 0);
    cmd(&f, DL_SRC_BLT, 8, 0x0010, 0x8000, 0, 0, 3, 1, 8, 4);
    draw_raw(&f, 4, 2, &dl_backend_png, &fr);
    assert_int_equal(fr.src_blts, 2);
    assert_int_equal(fr.src_blt_offset, 0);
    assert_int_equal(at(&fr, 0, 0), 0);
    dl_frame_free(&fr);
}

/* ---- raw streams ---------------------------------------------------------- */

static void test_mpel_raw_stream_rules(void **state)
{
    static const struct {
        int kind;
        const char *want;
    } cases[] = {
        {0, ""},
        {1, "fifo: offset 6: error: load-colours (0x5F00): maprt's own element, not MegaPel's: "
            "not allowed in a raw stream"},
        {2, "fifo: offset 6: error: end (0x5F02): maprt's own element, not MegaPel's: not "
            "allowed in a raw stream"},
        {3, "fifo: offset 10: error: stream ends inside a polygon"},
        {4, "fifo: offset 6: error: truncated element head (2 bytes left)"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fifo f;
        dl_validate_summary s;
        f.n = 0;
        cmd(&f, DL_LINE_TYPE, 1, 1);
        switch (cases[i].kind) {
        case 1: cmd(&f, DL_LOAD_COLOURS, 2, 0, 0); break;
        case 2: cmd(&f, DL_END, 0); break;
        case 3: cmd(&f, DL_BEGIN_POLYGON, 0); break;
        case 4: w16(&f, 4); break;
        }
        assert_string_equal(raw_msg(&f, &s), cases[i].want);
        if (!cases[i].kind) {
            assert_int_equal(s.header.version, 0);
            assert_int_equal(s.header.width, 1024);   /* the 5081 by default */
            assert_int_equal(s.header.height, 1024);
            assert_int_equal(s.header.flags, 0);   /* as given: the CLI's default is 8 */
        }
    }
}

/* The same FIFO contents drawn raw and wrapped in a version 2 header. */
static void test_mpel_raw_equals_wrapped(void **state)
{
    uint8_t img[6] = {1, 2, 3, 4, 5, 6};
    fifo f, l;
    dl_frame a, b;
    diag err;
    (void)state;
    f.n = 0;
    cmd(&f, DL_PLANE_MASK, 1, 0);
    cmd(&f, DL_LINE_COLOUR, 1, 9);
    cmd(&f, DL_POLYLINE, 6, 0, 0, 30, 5, 10, 20);
    put_image(&f, 32, 4, 4, 3, 2, img, 3);
    as_list(&f, &l, 32, 32);
    draw_raw(&f, 32, 32, &dl_backend_png, &a);
    diag_init(&err);
    assert_int_equal(dl_render(l.b, l.n, "l", &dl_backend_png, NULL, &b, &err), 0);
    assert_memory_equal(a.px, b.px, 32 * 32);
    dl_frame_free(&a);
    dl_frame_free(&b);
}

/* ---- version 1 converted on read ----------------------------------------- */

static void test_mpel_version1_converts(void **state)
{
    /* version 1: mask 0x0F in the low byte, rows bottom-first, odd rows padded */
    static const uint8_t v1[] = {
        0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0, 0, 1, 0, 0, 0, 4, 0, 3, 0, 0,
        0, 6, 0x50, 0x61, 0x00, 0x0F,
        0, 24, 0x50, 0x18, 0, 0, 0, 0, 0, 2, 0, 1, 0, 8, 0, 4, 0x14, 0x15, 0x16, 0, 0x11, 0x12, 0x13, 0,
        0, 4, 0x5F, 0x02};
    fifo f, l;
    dl_frame a, b;
    uint8_t top[6] = {0x11, 0x12, 0x13, 0x14, 0x15, 0x16};
    diag err;
    (void)state;
    f.n = 0;
    cmd(&f, DL_PLANE_MASK, 1, (int)xlate(0x0F));
    put_image(&f, 3, 0, 1, 3, 2, top, 3);
    as_list(&f, &l, 4, 3);
    l.b[9] = 0;   /* 4-bit DAC like v1 */
    diag_init(&err);
    assert_int_equal(dl_render(v1, sizeof v1, "v1", &dl_backend_png, NULL, &a, &err), 0);
    assert_int_equal(dl_render(l.b, l.n, "v2", &dl_backend_png, NULL, &b, &err), 0);
    assert_memory_equal(a.px, b.px, 4 * 3);
    assert_int_equal(at(&a, 0, 1), 0x11 & 0x0F);   /* top row 0x11.. at device y 1 */
    assert_int_equal(at(&a, 2, 0), 0x16 & 0x0F);
    dl_frame_free(&a);
    dl_frame_free(&b);
    /* new elements are not version 1 elements */
    {
        static const uint8_t bad[] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0, 0, 1, 0, 0, 0, 4, 0, 3,
                                      0, 0, 0, 6, 0x50, 0x4A, 0, 1, 0, 4, 0x5F, 0x02};
        char msg[256];
        dl_validate_summary s;
        diag_init(&err);
        assert_int_equal(dl_validate(bad, sizeof bad, "v1", NULL, &s, &err), DIAG_INPUT);
        diag_format(&err, msg, sizeof msg);
        assert_string_equal(msg, "v1: offset 16: error: element code 0x504A (text-colour) is not "
                                 "defined in DL5080 version 1");
    }
}

/* ---- polygons -------------------------------------------------------------- */

/* mpelFillSolid: with GXcopy a fill rectangle, with any other op a polygon
 * (interior style 2, edge flag 2) through the same inclusive corners. The
 * driver uses them for the same pixels, so the polygon covers its boundary. */
static void test_mpel_fill_solid_rectangle_equals_polygon(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < 4; k++) {
        static const int r[4][4] = {{2, 3, 5, 4}, {0, 0, 1, 1}, {3, 2, 3, 9}, {1, 6, 12, 6}};
        int H = 12, x = r[k][0], y = r[k][1], w = r[k][2], h = r[k][3];
        fifo a, b;
        dl_frame fa, fb;
        a.n = b.n = 0;
        cmd(&a, DL_LOGIC_OP, 1, 6 + 1);   /* GXxor: the polygon path */
        cmd(&a, DL_INTERIOR_STYLE, 1, 2);
        cmd(&a, DL_INTERIOR_COLOUR, 1, 3);
        cmd(&a, DL_EDGE_FLAG, 1, 2);
        cmd(&a, DL_BEGIN_POLYGON, 0);
        cmd(&a, DL_POLYLINE, 8, x, H - 1 - y, x + w - 1, H - 1 - y, x + w - 1, H - (y + h), x,
            H - (y + h));
        cmd(&a, DL_END_POLYGON, 0);
        cmd(&b, DL_LOGIC_OP, 1, 6 + 1);
        cmd(&b, DL_INTERIOR_COLOUR, 1, 3);
        cmd(&b, DL_FILL_RECT, 4, x, H - (y + h), x + w - 1, H - 1 - y);
        draw_raw(&a, 16, H, &dl_backend_png, &fa);
        draw_raw(&b, 16, H, &dl_backend_png, &fb);
        assert_memory_equal(fa.px, fb.px, 16 * (size_t)H);
        dl_frame_free(&fa);
        dl_frame_free(&fb);
    }
}

static void test_mpel_polygon_closed_even_odd(void **state)
{
    uint64_t seed = test_seed("test_mpel_polygon_closed_even_odd");
    int t;
    (void)state;
    for (t = 0; t < 200; t++) {
        fifo f;
        dl_frame fr;
        int n = 3 + (int)(test_rand(&seed) % 8), xy[22], i, x, y;
        f.n = 0;
        cmd(&f, DL_BEGIN_POLYGON, 0);
        w16(&f, 4 + 4 * (unsigned)n);
        w16(&f, DL_POLYLINE);
        for (i = 0; i < n; i++) {
            xy[2 * i] = (int)(test_rand(&seed) % 60) - 6;
            xy[2 * i + 1] = (int)(test_rand(&seed) % 60) - 6;
            w16(&f, (unsigned)xy[2 * i] & 0xFFFF);
            w16(&f, (unsigned)xy[2 * i + 1] & 0xFFFF);
        }
        cmd(&f, DL_END_POLYGON, 0);
        draw_raw(&f, 48, 48, &dl_backend_png, &fr);
        for (y = 0; y < 48; y++)
            for (x = 0; x < 48; x++) {
                int want = dl_test_inside(xy, n, x, y);
                for (i = 0; i < n && !want; i++)
                    want = dl_test_on_segment(xy[2 * i], xy[2 * i + 1], xy[(2 * i + 2) % (2 * n)],
                                      xy[(2 * i + 3) % (2 * n)], x, y);
                if (at(&fr, x, y) != want)
                    fail_msg("case %d: pixel %d,%d is %d, want %d", t, x, y, at(&fr, x, y), want);
            }
        dl_frame_free(&fr);
    }
}

/* ---- line types and widths ------------------------------------------------ */

/* mpel_do_dashline_gc: dashes {on, off} become mask bits from bit 0, the
 * pattern repeated over 16 bits, factor 0, line type 150. */
static unsigned dash_mask(unsigned on, unsigned off)
{
    unsigned m = 0, off_at = 0, bit;
    m |= ((1u << on) - 1) << off_at;
    off_at += on + off;
    for (bit = off_at; bit < 16; bit++)
        m |= (m & (1u << (bit - off_at))) << off_at;
    return m & 0xFFFF;
}

static void test_mpel_line_styles(void **state)
{
    fifo f;
    dl_frame fr;
    int x;
    (void)state;
    assert_int_equal(dash_mask(4, 4), 0x0F0F);
    assert_int_equal(dash_mask(2, 6), 0x0303);
    /* type 150 continues: two polylines of 10 pixels, pattern 4 on 4 off */
    f.n = 0;
    cmd(&f, DL_USER_LINE_STYLE, 2, (int)dash_mask(4, 4), 0);
    cmd(&f, DL_LINE_TYPE, 1, 150);
    cmd(&f, DL_POLYLINE, 4, 0, 0, 9, 0);
    cmd(&f, DL_POLYLINE, 4, 10, 0, 19, 0);
    /* type 50 restarts each element */
    cmd(&f, DL_LINE_TYPE, 1, 50);
    cmd(&f, DL_POLYLINE, 4, 0, 1, 9, 1);
    cmd(&f, DL_POLYLINE, 4, 10, 1, 19, 1);
    /* a polyline's joint counts once: 3 + 1 + ... along a corner */
    cmd(&f, DL_POLYLINE, 6, 0, 2, 5, 2, 5, 3);
    /* factor 2: each bit two pixels */
    cmd(&f, DL_USER_LINE_STYLE, 2, 0x5555, 2);
    cmd(&f, DL_POLYLINE, 4, 0, 4, 19, 4);
    /* solid again */
    cmd(&f, DL_LINE_TYPE, 1, 1);
    cmd(&f, DL_POLYLINE, 4, 0, 5, 19, 5);
    draw_raw(&f, 20, 6, &dl_backend_png, &fr);
    for (x = 0; x < 20; x++) {
        assert_int_equal(at(&fr, x, 0), (x % 8) < 4);
        assert_int_equal(at(&fr, x, 1), ((x % 10) % 8) < 4);
        assert_int_equal(at(&fr, x, 4), (x / 2) % 2 == 0);
        assert_int_equal(at(&fr, x, 5), 1);
    }
    /* corner: pixels 0..5 on row 2 are positions 0..5, (5,3) is position 6 */
    for (x = 0; x < 6; x++)
        assert_int_equal(at(&fr, x, 2), x < 4);
    assert_int_equal(at(&fr, 5, 3), 0);
    dl_frame_free(&fr);
}

static void test_mpel_line_width(void **state)
{
    static const uint8_t head[] = {0xC4, 0xD3, 0xF5, 0xF0, 0xF8, 0xF0, 0, 2, 0, 0, 0, 32, 0, 32, 0, 0};
    fifo f;
    dl_frame fr;
    diag err;
    int x, y, w;
    (void)state;
    for (w = 1; w <= 4; w++) {
        f.n = 0;
        memcpy(f.b, head, sizeof head);
        f.n = sizeof head;
        cmd(&f, DL_LINE_WIDTH, 1, w);
        cmd(&f, DL_POLYLINE, 4, 10, 10, 20, 10);
        cmd(&f, DL_END, 0);
        diag_init(&err);
        assert_int_equal(dl_render(f.b, f.n, "w", &dl_backend_png, NULL, &fr, &err), 0);
        for (y = 0; y < 32; y++)
            for (x = 0; x < 32; x++) {
                int in = x >= 10 - (w - 1) / 2 && x <= 20 + w / 2 && y >= 10 - (w - 1) / 2 &&
                         y <= 10 + w / 2;
                assert_int_equal(at(&fr, x, y), in);
            }
        dl_frame_free(&fr);
    }
}

/* ---- text ------------------------------------------------------------------ */

/* Draws text bytes at (x,y) with height h and up vector (ux,uy), raw stream. */
static void text(dl_frame *fr, int w, int h, unsigned cp, int height, int ux, int uy, int x,
                 int y, const char *bytes, size_t n)
{
    unsigned args[3];
    fifo f;
    f.n = 0;
    cmd(&f, DL_CODE_PAGE, 1, (int)cp);
    cmd(&f, DL_CHAR_HEIGHT, 1, height);
    cmd(&f, DL_CHAR_UP, 2, ux, uy);
    cmd(&f, DL_TEXT_COLOUR, 1, 5);
    args[0] = (unsigned)x;
    args[1] = (unsigned)y;
    args[2] = (unsigned)n;
    cmd_data(&f, DL_TEXT, args, 3, (const uint8_t *)bytes, n);
    draw_raw(&f, w, h, &dl_backend_png, fr);
}

static void test_mpel_text_glyph_size_and_angle(void **state)
{
    dl_frame a, b, c;
    int x, y, n = 0;
    (void)state;
    /* "I" (EBCDIC 0xC9) at height 6, unit scale: strokes 1030 2026 1636 */
    text(&a, 16, 16, DL_CP_EBCDIC, 6, 0, 1, 4, 3, "\xC9", 1);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            int gx = x - 4, gy = y - 3;
            int want = ((gy == 0 || gy == 6) && gx >= 1 && gx <= 3) || (gx == 2 && gy >= 0 && gy <= 6);
            assert_int_equal(at(&a, x, y), want ? 5 : 0);
            n += want;
        }
    assert_int_equal(n, 11);
    /* the same in code page 819 ('I' = 0x49), and rotated a quarter turn:
     * up (-1,0), the baseline then runs upward */
    text(&b, 16, 16, DL_CP_LATIN1, 6, 0, 1, 4, 3, "I", 1);
    assert_memory_equal(a.px, b.px, 16 * 16);
    text(&c, 16, 16, DL_CP_LATIN1, 6, -1, 0, 10, 2, "I", 1);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            int gx = y - 2, gy = 10 - x;
            int want = ((gy == 0 || gy == 6) && gx >= 1 && gx <= 3) || (gx == 2 && gy >= 0 && gy <= 6);
            assert_int_equal(at(&c, x, y), want ? 5 : 0);
        }
    dl_frame_free(&a);
    dl_frame_free(&b);
    dl_frame_free(&c);
    /* doubled height doubles the glyph; advance is one character height */
    text(&a, 40, 20, DL_CP_LATIN1, 12, 0, 1, 0, 0, "II", 2);
    assert_int_equal(at(&a, 4, 0), 5);
    assert_int_equal(at(&a, 4, 12), 5);
    assert_int_equal(at(&a, 4, 13), 0);
    assert_int_equal(at(&a, 12 + 4, 6), 5);   /* second I's stem */
    assert_int_equal(at(&a, 12 + 5, 6), 0);
    dl_frame_free(&a);
}

/* The code-page 037 table against glibc's IBM037 converter, both ways. */
static void test_mpel_cp037_matches_iconv(void **state)
{
    iconv_t cd = iconv_open("ASCII", "IBM037");
    unsigned b, agree = 0;
    (void)state;
    if (cd == (iconv_t)-1) {
        print_message("skipping: iconv has no IBM037 here\n");
        skip();
        return;
    }
    for (b = 0; b < 256; b++) {
        char in = (char)b, out[8] = {0}, *ip = &in, *op = out;
        size_t il = 1, ol = sizeof out;
        unsigned want = 0;
        iconv(cd, NULL, NULL, NULL, NULL);
        if (iconv(cd, &ip, &il, &op, &ol) != (size_t)-1 && op - out == 1 &&
            (unsigned char)out[0] >= 0x20 && (unsigned char)out[0] <= 0x7E)
            want = (unsigned char)out[0];
        if (dl_font_char(b, DL_CP_EBCDIC) != want)
            fail_msg("byte 0x%02X: table %u, iconv %u", b, dl_font_char(b, DL_CP_EBCDIC), want);
        agree += want != 0;
    }
    iconv_close(cd);
    assert_int_equal(agree, 95);   /* all of printable ASCII */
}

/* Every glyph string is well formed: digit pairs in the 4 x 6 grid. */
static void test_mpel_font_glyphs_well_formed(void **state)
{
    unsigned ch;
    (void)state;
    for (ch = 0; ch < 256; ch++) {
        const char *g = dl_font_glyph(ch);
        size_t run = 0;
        for (; *g; g++) {
            if (*g == ' ') {
                assert_true(run > 0 && run % 2 == 0);
                run = 0;
                continue;
            }
            assert_true(*g >= '0' && *g <= (run % 2 ? '0' + DL_FONT_HEIGHT : '0' + DL_FONT_WIDTH));
            run++;
        }
        assert_true(run % 2 == 0 && (run > 0 || ch == ' '));
    }
}

/* ---- decoder errors of the new elements ----------------------------------- */

static void test_mpel_new_element_errors(void **state)
{
    static const struct {
        unsigned code;
        int n;
        int w[3];
        const char *want;
    } cases[] = {
        {DL_PLANE_MASK, 1, {0x0F0F}, "plane-mask (0x5061): low byte 0x0F is not 0 (the mask is the high byte)"},
        {DL_LINE_TYPE, 1, {2}, "line-type (0x5040): line type 2 is not supported (1 solid, 50 user style, 150 continued user style)"},
        {DL_CHAR_HEIGHT, 1, {0}, "char-height (0x504B): character height 0 is outside 1..1024"},
        {DL_CHAR_UP, 2, {0, 0}, "char-up (0x504C): up vector is zero"},
        {DL_CODE_PAGE, 1, {500}, "code-page (0x5062): code page 500 is not supported (37, 437 or 819)"},
        {DL_INTERIOR_STYLE, 1, {3}, "interior-style (0x5051): interior style 3 is not supported (only 2, solid)"},
        {DL_EDGE_FLAG, 1, {3}, "edge-flag (0x5054): edge flag 3 is outside 1..2"},
        {DL_TEXT_COLOUR, 1, {256}, "text-colour (0x504A): colour index 256 is above 255"},
        {DL_USER_LINE_STYLE, 1, {1}, "user-line-style (0x5066): payload must be a mask and a factor (4 bytes)"},
        {DL_BLT, 3, {0, 0, 0}, "blt (0x5018): payload shorter than rectangle, depth and logic op (12 bytes)"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fifo f;
        char want[300];
        f.n = 0;
        cmd(&f, cases[i].code, cases[i].n, cases[i].w[0], cases[i].w[1], cases[i].w[2]);
        snprintf(want, sizeof want, "fifo: offset 0: error: %s", cases[i].want);
        assert_string_equal(raw_msg(&f, NULL), want);
    }
    {   /* a packed 3x2 BLT, one whose data are short, and a bad pad byte */
        fifo f;
        unsigned args[6] = {0, 0, 2, 1, 8, 4};
        uint8_t px[6] = {1, 2, 3, 4, 5, 6};
        f.n = 0;
        cmd_data(&f, DL_BLT, args, 6, px, 6);
        assert_string_equal(raw_msg(&f, NULL), "");
        f.n = 0;
        cmd_data(&f, DL_BLT, args, 6, px, 4);
        assert_string_equal(raw_msg(&f, NULL), "fifo: offset 0: error: blt (0x5018): 3x2 pixels "
                                               "need 6 bytes, payload has 4");
        args[3] = 0;   /* 3x1: 3 bytes and a pad */
        f.n = 0;
        cmd_data(&f, DL_BLT, args, 6, px, 3);
        f.b[f.n - 1] = 1;
        assert_string_equal(raw_msg(&f, NULL),
                            "fifo: offset 0: error: blt (0x5018): pad byte is not zero");
    }
}

/* ---- round trip of the encoder's elements ---------------------------------- */

typedef struct seen {
    unsigned code[32];
    dl_element e[32];
    int n;
} seen;

static int seen_element(void *ctx, const dl_element *e, diag *err)
{
    seen *s = ctx;
    (void)err;
    if (s->n < 32) {
        s->code[s->n] = e->code;
        s->e[s->n++] = *e;
    }
    return 0;
}

static void test_mpel_encoder_round_trip(void **state)
{
    static const dl_visitor v = {.header = NULL, .element = seen_element};
    uint8_t rows[6] = {1, 2, 3, 4, 5, 6}, *buf;
    dl_encoder enc;
    seen s;
    size_t len;
    diag err;
    (void)state;
    dl_encode_init(&enc, 32, 32, 0);
    dl_encode_plane_mask(&enc, 0x0F);
    dl_encode_blt(&enc, 1, 2, 3, 2, DL_OP_COPY, rows, 3);
    dl_encode_word(&enc, DL_LINE_WIDTH, 3);
    dl_encode_simple(&enc, DL_END);
    diag_init(&err);
    assert_int_equal(dl_encode_finish(&enc, "e", &buf, &len, &err), 0);
    assert_int_equal(buf[7], DL_VERSION);
    memset(&s, 0, sizeof s);
    assert_int_equal(dl_decode(buf, len, "e", NULL, &v, &s, NULL, &err), 0);
    assert_int_equal(s.n, 4);
    assert_int_equal(s.e[0].value, 0xF000);
    assert_int_equal(s.e[0].planes, 0x0F);
    /* the encoder's bottom-up rows come back bottom-up */
    assert_int_equal(s.e[1].data[0], 1);
    assert_int_equal(s.e[1].data[s.e[1].stride], 4);
    assert_int_equal(s.e[1].stride, -3);
    /* and on the wire the top row (4 5 6) comes first, packed, one pad byte */
    assert_memory_equal(buf + 16 + 6 + 16, "\x04\x05\x06\x01\x02\x03", 6);
    assert_int_equal(dl_be16(buf + 16 + 6), 16 + 6);
    assert_int_equal(s.e[2].value, 3);
    mem_free(buf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mpel_plane_mask_as_the_driver_sends_it),
        cmocka_unit_test(test_mpel_logic_ops_are_gc_function_plus_one),
        cmocka_unit_test(test_mpel_blt_rows_top_first_packed),
        cmocka_unit_test(test_mpel_colour_expansion_like_the_cursor),
        cmocka_unit_test(test_mpel_expansion_width_and_src_blt),
        cmocka_unit_test(test_mpel_raw_stream_rules),
        cmocka_unit_test(test_mpel_raw_equals_wrapped),
        cmocka_unit_test(test_mpel_version1_converts),
        cmocka_unit_test(test_mpel_fill_solid_rectangle_equals_polygon),
        cmocka_unit_test(test_mpel_polygon_closed_even_odd),
        cmocka_unit_test(test_mpel_line_styles),
        cmocka_unit_test(test_mpel_line_width),
        cmocka_unit_test(test_mpel_text_glyph_size_and_angle),
        cmocka_unit_test(test_mpel_cp037_matches_iconv),
        cmocka_unit_test(test_mpel_font_glyphs_well_formed),
        cmocka_unit_test(test_mpel_new_element_errors),
        cmocka_unit_test(test_mpel_encoder_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
