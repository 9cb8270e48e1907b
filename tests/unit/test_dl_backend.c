/* test_dl_backend — the three backends (png, osmesa, egl) on the same lists:
 * the asymmetric red-on-blue "F" through each backend and the PNG writer
 * (catches flips and channel swaps), exact agreement of the GL backends with
 * the software raster for pixel and fill elements, and the documented bound
 * for lines, circles and polygons (every differing pixel lies within one
 * pixel of a pixel the other backend set), and one drawing budget: a list
 * drawn within its budget draws the same pixels everywhere, and a budget one
 * step short is refused by every backend with the same located error. GL
 * cases skip, with the reason,
 * where no context can be created. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "image/image_png.h"
#include "display5080/dl_encode.h"
#include "display5080/dl_image.h"
#include "display5080/dl_render.h"
#include "util/libload.h"
#include "util/mem.h"
#include "support.h"

/* Leaks inside Mesa (OSMesa, the EGL driver, llvmpipe's LLVM) are not
 * maprt's: the sanitizer build ignores them, and still checks everything
 * maprt allocates. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libOSMesa.so\nleak:libEGL_mesa.so\nleak:swrast_dri.so\nleak:libLLVM\n"
           "leak:libglapi.so\n";
}

/* Skips the test (printing why) when backend b cannot start here. */
static int usable(const dl_backend *b)
{
    void *dev;
    diag err;
    diag_init(&err);
    if (b->open(4, 4, &dev, &err)) {
        char buf[600];
        diag_format(&err, buf, sizeof buf);
        /* tests/run.sh lists the "# skipped:" lines; CI allows none */
        print_message("# skipped: %s backend: %s (Debian: %s)\n", b->name, buf,
                      !strcmp(b->name, "osmesa") ? "libosmesa6-dev libgl1-mesa-dri"
                                                 : "libegl-dev libegl-mesa0 libgl1-mesa-dri");
        return 0;
    }
    b->close(dev);
    return 1;
}

static void encode(dl_encoder *enc, uint8_t **buf, size_t *len)
{
    diag err;
    diag_init(&err);
    dl_encode_simple(enc, DL_END);
    assert_int_equal(dl_encode_finish(enc, "t", buf, len, &err), 0);
}

static void draw(const dl_backend *b, const uint8_t *buf, size_t len, dl_frame *f)
{
    diag err;
    diag_init(&err);
    if (dl_render(buf, len, "t", b, NULL, f, &err)) {
        char msg[600];
        diag_format(&err, msg, sizeof msg);
        fail_msg("%s: %s", b->name, msg);
    }
}

/* ---- the "F" ------------------------------------------------------------- */

#define FW 20
#define FH 24

/* Is image pixel (x, row) (top-down) part of the F? Written in image terms. */
static int in_f(int x, int row)
{
    if (x >= 4 && x <= 6 && row >= 4 && row <= 19) return 1;    /* stem */
    if (x >= 4 && x <= 15 && row >= 4 && row <= 6) return 1;    /* top bar */
    if (x >= 4 && x <= 11 && row >= 11 && row <= 12) return 1;  /* middle bar */
    return 0;
}

static void f_image(const dl_backend *b)
{
    dl_encoder enc;
    uint32_t cols[2] = {0x0000FF, 0xFF0000};   /* 0 blue, 1 red */
    uint8_t *buf;
    size_t len;
    dl_frame f;
    image img;
    char path[80];
    diag err;
    int x, row, pal;
    if (!usable(b)) {
        skip();
        return;
    }
    dl_encode_init(&enc, FW, FH, 0);
    dl_encode_colours(&enc, 0, cols, 2);
    dl_encode_word(&enc, DL_CLEAR, 0);
    dl_encode_word(&enc, DL_INTERIOR_COLOUR, 1);
    /* device coordinates: y up, so image row r is device y = FH-1-r */
    dl_encode_rect(&enc, DL_FILL_RECT, 4, FH - 1 - 19, 6, FH - 1 - 4);
    dl_encode_rect(&enc, DL_FILL_RECT, 4, FH - 1 - 6, 15, FH - 1 - 4);
    dl_encode_rect(&enc, DL_FILL_RECT, 4, FH - 1 - 12, 11, FH - 1 - 11);
    encode(&enc, &buf, &len);
    draw(b, buf, len, &f);
    for (pal = 0; pal <= 1; pal++) {
        snprintf(path, sizeof path, "/tmp/test_dl_backend_%ld_%s.png", (long)getpid(), b->name);
        diag_init(&err);
        assert_int_equal(dl_frame_write_png(path, &f, !pal, &err), 0);
        assert_int_equal(image_read_png(path, 3, &img, &err), 0);
        remove(path);
        assert_int_equal(img.width, FW);
        assert_int_equal(img.height, FH);
        for (row = 0; row < FH; row++)
            for (x = 0; x < FW; x++) {
                const uint8_t *p = img.px + 3 * ((size_t)row * FW + x);
                if (in_f(x, row))
                    assert_memory_equal(p, "\xFF\x00\x00", 3);
                else
                    assert_memory_equal(p, "\x00\x00\xFF", 3);
            }
        image_free(&img);
    }
    dl_frame_free(&f);
    mem_free(buf);
}

static void test_dl_backend_f_image_png(void **state) { (void)state; f_image(&dl_backend_png); }
static void test_dl_backend_f_image_osmesa(void **state) { (void)state; f_image(&dl_backend_osmesa); }
static void test_dl_backend_f_image_egl(void **state) { (void)state; f_image(&dl_backend_egl); }

/* ---- exact agreement for pixel and fill elements ------------------------ */

static int rnd(uint64_t *s, int lo, int hi) { return lo + (int)(test_rand(s) % (uint64_t)(hi - lo + 1)); }

static void fills_exact(const dl_backend *b, const char *test)
{
    uint64_t seed = test_seed(test);
    int t;
    if (!usable(b)) {
        skip();
        return;
    }
    for (t = 0; t < 6; t++) {
        dl_encoder enc;
        uint8_t *buf, pix[40 * 30];
        size_t len, i;
        dl_frame ref, got;
        int k, w = 61, h = 47;
        dl_encode_init(&enc, w, h, 0);
        dl_encode_word(&enc, DL_CLEAR, (unsigned)rnd(&seed, 0, 255));
        for (k = 0; k < 60; k++) {
            int x0 = rnd(&seed, -10, w + 5), y0 = rnd(&seed, -10, h + 5);
            int x1 = x0 + rnd(&seed, 0, 30), y1 = y0 + rnd(&seed, 0, 30);
            switch (rnd(&seed, 0, 7)) {
            case 0: dl_encode_word(&enc, DL_LOGIC_OP, (unsigned)rnd(&seed, 1, 16)); break;
            case 1: dl_encode_plane_mask(&enc, (unsigned)rnd(&seed, 0, 255)); break;
            case 2: dl_encode_rect(&enc, DL_SCISSOR, x0, y0, x1, y1); break;
            case 3: dl_encode_word(&enc, DL_INTERIOR_COLOUR, (unsigned)rnd(&seed, 0, 255)); break;
            case 4: dl_encode_rect(&enc, DL_FILL_RECT, x0, y0, x1, y1); break;
            case 5: {
                unsigned runs[16];
                int n = rnd(&seed, 1, 8), j;
                for (j = 0; j < n; j++) {
                    runs[2 * j] = (unsigned)rnd(&seed, 0, 9);
                    runs[2 * j + 1] = (unsigned)rnd(&seed, 0, 255);
                }
                dl_encode_run_row(&enc, y0, x0, runs, (size_t)n);
                break;
            }
            case 6: {
                int bw = rnd(&seed, 1, 40), bh = rnd(&seed, 1, 30);
                for (i = 0; i < sizeof pix; i++)
                    pix[i] = (uint8_t)test_rand(&seed);
                dl_encode_blt(&enc, x0, y0, bw, bh, (unsigned)rnd(&seed, 1, 16), pix, 40);
                break;
            }
            default: dl_encode_word(&enc, DL_CLEAR, (unsigned)rnd(&seed, 0, 255)); break;
            }
        }
        encode(&enc, &buf, &len);
        draw(&dl_backend_png, buf, len, &ref);
        draw(b, buf, len, &got);
        for (i = 0; i < (size_t)w * h; i++)
            if (ref.px[i] != got.px[i])
                fail_msg("%s: pixel %zu,%zu is 0x%02X, software raster 0x%02X", b->name,
                         i % (size_t)w, i / (size_t)w, got.px[i], ref.px[i]);
        dl_frame_free(&ref);
        dl_frame_free(&got);
        mem_free(buf);
    }
}

static void test_dl_backend_osmesa_fills_exact(void **state)
{
    (void)state;
    fills_exact(&dl_backend_osmesa, "test_dl_backend_osmesa_fills_exact");
}

static void test_dl_backend_egl_fills_exact(void **state)
{
    (void)state;
    fills_exact(&dl_backend_egl, "test_dl_backend_egl_fills_exact");
}

/* ---- every shape, text and style: exact --------------------------------- */

/* Appends one random drawing element of the given kind (and the state it
 * needs), as a list the driver could send; xor forces xor on elements that
 * carry their own logic op. */
static void shape(dl_encoder *enc, uint64_t *seed, int kind, int xor)
{
    int xy[16], k, n;
    for (k = 0; k < 16; k++)
        xy[k] = rnd(seed, -4, 67);
    switch (kind) {
    case 0: dl_encode_points(enc, DL_POLYLINE, xy, 5); break;
    case 1: dl_encode_points(enc, DL_SEGMENTS, xy, 8); break;
    case 2:
        dl_encode_circle(enc, rnd(seed, 0, 1) ? DL_FILL_CIRCLE : DL_CIRCLE, xy[0], xy[1],
                         (unsigned)rnd(seed, 0, 40));
        break;
    case 3:
        dl_encode_word(enc, DL_EDGE_FLAG, (unsigned)rnd(seed, 1, 2));
        dl_encode_word(enc, DL_EDGE_COLOUR, (unsigned)rnd(seed, 0, 255));
        dl_encode_simple(enc, DL_BEGIN_POLYGON);
        dl_encode_points(enc, DL_POLYLINE, xy, (size_t)rnd(seed, 3, 8));
        dl_encode_simple(enc, DL_END_POLYGON);
        break;
    case 4: {   /* text: size, angle, code page */
        uint8_t str[12];
        n = rnd(seed, 1, 12);
        for (k = 0; k < n; k++)
            str[k] = (uint8_t)rnd(seed, 0x40, 0xF9);
        dl_encode_word(enc, DL_CHAR_HEIGHT, (unsigned)rnd(seed, 1, 30));
        dl_encode_begin(enc, DL_CHAR_UP);
        dl_encode_s16(enc, rnd(seed, -5, 5));
        dl_encode_s16(enc, rnd(seed, 1, 5) * (rnd(seed, 0, 1) ? 1 : -1));
        dl_encode_end(enc);
        dl_encode_word(enc, DL_TEXT_COLOUR, (unsigned)rnd(seed, 0, 255));
        dl_encode_text(enc, rnd(seed, -10, 40), rnd(seed, -10, 50), str, (size_t)n);
        break;
    }
    case 5: {   /* styled, wide lines */
        static const unsigned types[3] = {DL_LINE_SOLID, DL_LINE_USER, DL_LINE_USER_CONT};
        dl_encode_begin(enc, DL_USER_LINE_STYLE);
        dl_encode_u16(enc, (unsigned)rnd(seed, 0, 0xFFFF));
        dl_encode_u16(enc, (unsigned)rnd(seed, 0, 3));
        dl_encode_end(enc);
        dl_encode_word(enc, DL_LINE_TYPE, types[rnd(seed, 0, 2)]);
        dl_encode_word(enc, DL_LINE_WIDTH, (unsigned)rnd(seed, 1, 6));
        dl_encode_points(enc, rnd(seed, 0, 1) ? DL_POLYLINE : DL_SEGMENTS, xy, 4);
        dl_encode_points(enc, DL_POLYLINE, xy + 8, 3);
        break;
    }
    default: {  /* colour expansion, top row first, packed */
        int bw = 8 * rnd(seed, 1, 4), bh = rnd(seed, 1, 20);
        dl_encode_begin(enc, DL_BLT_EXPAND);
        dl_encode_s16(enc, xy[0]);
        dl_encode_s16(enc, xy[1]);
        dl_encode_s16(enc, xy[0] + bw - 1);
        dl_encode_s16(enc, xy[1] + bh - 1);
        dl_encode_u16(enc, (unsigned)rnd(seed, 0, 255));
        k = rnd(seed, 1, 16);
        dl_encode_u16(enc, xor ? DL_OP_XOR : (unsigned)k);
        for (k = 0; k < bw / 8 * bh; k++) {
            uint8_t v = (uint8_t)test_rand(seed);
            dl_encode_bytes(enc, &v, 1);
        }
        dl_encode_end(enc);
        break;
    }
    }
}

#define DL_TEST_KINDS 7

static void shapes_exact(const dl_backend *b, const char *test)
{
    static const char *const names[DL_TEST_KINDS] = {
        "polylines", "segments", "circles", "polygons", "text", "styled lines", "bit blocks"};
    uint64_t seed = test_seed(test);
    int t, kind;
    long total[DL_TEST_KINDS] = {0};
    if (!usable(b)) {
        skip();
        return;
    }
    for (kind = 0; kind < DL_TEST_KINDS; kind++)
        for (t = 0; t < 12; t++) {
            dl_encoder enc;
            uint8_t *buf;
            size_t len, i;
            dl_frame ref, got;
            int w = 64, h = 64, j, twice;
            uint64_t s2 = seed;
            for (twice = 0; twice <= 1; twice++) {
                dl_encode_init(&enc, w, h, 0);
                if (twice) {
                    dl_encode_word(&enc, DL_LOGIC_OP, DL_OP_XOR);
                } else {
                    dl_encode_word(&enc, DL_LOGIC_OP, (unsigned)rnd(&seed, 1, 16));
                    dl_encode_plane_mask(&enc, (unsigned)rnd(&seed, 0, 255));
                    dl_encode_word(&enc, DL_LINE_COLOUR, (unsigned)rnd(&seed, 0, 255));
                    dl_encode_word(&enc, DL_INTERIOR_COLOUR, (unsigned)rnd(&seed, 0, 255));
                }
                for (j = 0; j <= twice; j++) {
                    uint64_t s3 = s2;
                    shape(&enc, &s3, kind, twice);
                    if (j == twice)
                        s2 = s3;
                }
                encode(&enc, &buf, &len);
                draw(&dl_backend_png, buf, len, &ref);
                draw(b, buf, len, &got);
                for (i = 0; i < (size_t)w * h; i++) {
                    if (got.px[i] != ref.px[i])
                        fail_msg("%s: %s case %d%s: pixel %zu,%zu is 0x%02X, software raster "
                                 "0x%02X", b->name, names[kind], t, twice ? " (xor twice)" : "",
                                 i % (size_t)w, i / (size_t)w, got.px[i], ref.px[i]);
                    if (twice && got.px[i])   /* xor twice restores the screen: each pixel written once */
                        fail_msg("%s: %s case %d: pixel %zu,%zu left by xor twice", b->name,
                                 names[kind], t, i % (size_t)w, i / (size_t)w);
                    else
                        total[kind] += ref.px[i] != 0;
                }
                dl_frame_free(&ref);
                dl_frame_free(&got);
                mem_free(buf);
            }
            seed = s2;
        }
    for (kind = 0; kind < DL_TEST_KINDS; kind++)
        assert_true(total[kind] > 100);   /* the cases drew something */
    print_message("%s: identical to the software raster: polylines %ld, segments %ld, circles "
                  "%ld, polygons %ld, text %ld, styled lines %ld, bit blocks %ld set pixels\n",
                  b->name, total[0], total[1], total[2], total[3], total[4], total[5], total[6]);
}

static void test_dl_backend_osmesa_shapes_exact(void **state)
{
    (void)state;
    shapes_exact(&dl_backend_osmesa, "test_dl_backend_osmesa_shapes_exact");
}

static void test_dl_backend_egl_shapes_exact(void **state)
{
    (void)state;
    shapes_exact(&dl_backend_egl, "test_dl_backend_egl_shapes_exact");
}

/* ---- what maprt writes: an encoded frame with a wireframe ---------------- */

static void written_exact(const dl_backend *b, const char *test)
{
    uint64_t seed = test_seed(test);
    image img;
    dl_image_polyline pl[3];
    dl_image_opts o;
    int xy[3][12], k, j;
    uint8_t *buf;
    size_t len, i;
    dl_frame ref, got;
    diag err;
    if (!usable(b)) {
        skip();
        return;
    }
    diag_init(&err);
    assert_int_equal(image_alloc(&img, 97, 61, 3, "t", &err), 0);
    for (i = 0; i < (size_t)97 * 61 * 3; i++)   /* smooth bands and noise: runs and blocks */
        img.px[i] = (uint8_t)(i % 3 == 0 ? (i / 300) * 20 : test_rand(&seed) % 4 ? 40 : test_rand(&seed));
    for (k = 0; k < 3; k++) {
        for (j = 0; j < 12; j++)
            xy[k][j] = rnd(&seed, -5, 100);
        pl[k].n = 6;
        pl[k].xy = xy[k];
        pl[k].r = (uint8_t)(k * 100);
        pl[k].g = 255;
        pl[k].b = (uint8_t)(k * 50);
    }
    memset(&o, 0, sizeof o);
    o.polylines = pl;
    o.npolylines = 3;
    for (k = 0; k <= 1; k++) {
        o.dither = k;
        assert_int_equal(dl_image_encode(&img, &o, &buf, &len, NULL, &err), 0);
        draw(&dl_backend_png, buf, len, &ref);
        draw(b, buf, len, &got);
        assert_memory_equal(got.px, ref.px, (size_t)97 * 61);
        dl_frame_free(&ref);
        dl_frame_free(&got);
        mem_free(buf);
    }
    image_free(&img);
}

static void test_dl_backend_osmesa_written_exact(void **state)
{
    (void)state;
    written_exact(&dl_backend_osmesa, "test_dl_backend_osmesa_written_exact");
}

static void test_dl_backend_egl_written_exact(void **state)
{
    (void)state;
    written_exact(&dl_backend_egl, "test_dl_backend_egl_written_exact");
}

/* ---- one drawing budget ------------------------------------------------- */

/* Draws with a budget: 0 or the status, with the message in msg. */
static int draw_limited(const dl_backend *b, const uint8_t *buf, size_t len,
                        unsigned long long limit, dl_frame *f, char *msg, size_t cap)
{
    dl_render_opts ro;
    diag err;
    int rc;
    memset(&ro, 0, sizeof ro);
    ro.work_limit = limit;
    diag_init(&err);
    rc = dl_render(buf, len, "t", b, &ro, f, &err);
    diag_format(&err, msg, cap);
    return rc;
}

/* Random lists of every kind with a clear, fills and a block: drawn with
 * exactly the budget the software raster spent, b gives its pixels; with any
 * smaller budget b refuses it exactly as the software raster does. */
static void budget_same(const dl_backend *b, const char *test)
{
    uint64_t seed = test_seed(test);
    int t, kind;
    if (!usable(b)) {
        skip();
        return;
    }
    for (t = 0; t < 6; t++) {
        dl_encoder enc;
        uint8_t *buf, rows[40 * 30];
        size_t len, i;
        dl_frame ref, got;
        char want[600], msg[600];
        unsigned long long w, cuts[3];
        int c;
        dl_encode_init(&enc, 64, 64, 0);
        dl_encode_word(&enc, DL_CLEAR, (unsigned)rnd(&seed, 0, 255));
        for (kind = 0; kind < DL_TEST_KINDS; kind++)
            shape(&enc, &seed, kind, 0);
        dl_encode_word(&enc, DL_INTERIOR_COLOUR, (unsigned)rnd(&seed, 0, 255));
        dl_encode_rect(&enc, DL_FILL_RECT, rnd(&seed, -10, 30), rnd(&seed, -10, 30),
                       rnd(&seed, 30, 80), rnd(&seed, 30, 80));
        for (i = 0; i < sizeof rows; i++)
            rows[i] = (uint8_t)test_rand(&seed);
        dl_encode_blt(&enc, rnd(&seed, -10, 40), rnd(&seed, -10, 40), 40, 30,
                      (unsigned)rnd(&seed, 1, 16), rows, 40);
        shape(&enc, &seed, (int)(t % DL_TEST_KINDS), 0);
        encode(&enc, &buf, &len);
        draw(&dl_backend_png, buf, len, &ref);
        w = ref.work;
        assert_true(w > 64 * 64);   /* the clear alone costs the frame */
        assert_int_equal(draw_limited(b, buf, len, w, &got, msg, sizeof msg), 0);
        assert_int_equal(got.work, w);
        assert_memory_equal(got.px, ref.px, (size_t)64 * 64);
        dl_frame_free(&got);
        cuts[0] = w - 1;
        cuts[1] = 1 + test_rand(&seed) % (w - 1);
        cuts[2] = 64 * 64 - 1;   /* the clear does not fit */
        for (c = 0; c < 3; c++) {
            assert_int_equal(draw_limited(&dl_backend_png, buf, len, cuts[c], &got, want,
                                          sizeof want), DIAG_INPUT);
            assert_non_null(strstr(want, "error: drawing work limit of"));
            assert_int_equal(draw_limited(b, buf, len, cuts[c], &got, msg, sizeof msg), DIAG_INPUT);
            assert_string_equal(msg, want);
        }
        assert_non_null(strstr(want, "t: offset 16: error:"));   /* the clear, first element */
        dl_frame_free(&ref);
        mem_free(buf);
    }
}

static void test_dl_backend_png_budget(void **state)
{
    (void)state;
    budget_same(&dl_backend_png, "test_dl_backend_png_budget");
}

static void test_dl_backend_osmesa_budget(void **state)
{
    (void)state;
    budget_same(&dl_backend_osmesa, "test_dl_backend_osmesa_budget");
}

static void test_dl_backend_egl_budget(void **state)
{
    (void)state;
    budget_same(&dl_backend_egl, "test_dl_backend_egl_budget");
}

static void test_dl_backend_find(void **state)
{
    (void)state;
    assert_ptr_equal(dl_backend_find("png"), &dl_backend_png);
    assert_ptr_equal(dl_backend_find("osmesa"), &dl_backend_osmesa);
    assert_ptr_equal(dl_backend_find("egl"), &dl_backend_egl);
    assert_null(dl_backend_find("x11"));
}

/* A missing GL library or symbol is a clear DIAG_IO naming it, and leaves
 * the table untouched; a present one fills it. */
static void test_dl_backend_missing_library_is_reported(void **state)
{
    static const char *const none[] = {"libmaprt-no-such-gl.so.0", NULL};
    static const char *const libc[] = {"libc.so.6", NULL};
    static const char *const bad[] = {"maprt_no_such_symbol"};
    static const char *const good[] = {"strlen"};
    libload_fn f[1] = {NULL};
    diag err;
    (void)state;
    diag_init(&err);
    assert_int_equal(libload(none, good, f, 1, "osmesa", "install it", &err), DIAG_IO);
    assert_non_null(strstr(err.msg, "cannot load libmaprt-no-such-gl.so.0"));
    assert_non_null(strstr(err.msg, "(install it)"));
    assert_null(f[0]);
    diag_init(&err);
    assert_int_equal(libload(libc, bad, f, 1, "egl", "install it", &err), DIAG_IO);
    assert_non_null(strstr(err.msg, "no symbol maprt_no_such_symbol"));
    assert_null(f[0]);
    diag_init(&err);
    assert_int_equal(libload(libc, good, f, 1, "egl", "install it", &err), 0);
    assert_non_null(f[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dl_backend_find),
        cmocka_unit_test(test_dl_backend_missing_library_is_reported),
        cmocka_unit_test(test_dl_backend_f_image_png),
        cmocka_unit_test(test_dl_backend_f_image_osmesa),
        cmocka_unit_test(test_dl_backend_f_image_egl),
        cmocka_unit_test(test_dl_backend_osmesa_fills_exact),
        cmocka_unit_test(test_dl_backend_egl_fills_exact),
        cmocka_unit_test(test_dl_backend_osmesa_shapes_exact),
        cmocka_unit_test(test_dl_backend_egl_shapes_exact),
        cmocka_unit_test(test_dl_backend_osmesa_written_exact),
        cmocka_unit_test(test_dl_backend_egl_written_exact),
        cmocka_unit_test(test_dl_backend_png_budget),
        cmocka_unit_test(test_dl_backend_osmesa_budget),
        cmocka_unit_test(test_dl_backend_egl_budget),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
