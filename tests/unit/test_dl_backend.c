/* test_dl_backend — the three backends (png, osmesa, egl) on the same lists:
 * the asymmetric red-on-blue "F" through each backend and the PNG writer
 * (catches flips and channel swaps), exact agreement of the GL backends with
 * the software raster for pixel and fill elements, and the documented bound
 * for lines, circles and polygons (every differing pixel lies within one
 * pixel of a pixel the other backend set). GL cases skip, with the reason,
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
#include "display5080/dl_render.h"
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
            case 1: dl_encode_word(&enc, DL_PLANE_MASK, (unsigned)rnd(&seed, 0, 255)); break;
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

/* ---- lines, circles, polygons: within one pixel ------------------------- */

/* Pixels set in a but not b with no set pixel of b among their 8 neighbours. */
static int far_x, far_y;   /* the last such pixel, for the failure message */

static long far_pixels(const dl_frame *a, const dl_frame *b)
{
    long n = 0;
    int x, y, dx, dy;
    for (y = 0; y < a->height; y++)
        for (x = 0; x < a->width; x++) {
            int near = 0;
            if (!a->px[(size_t)y * a->width + x] || b->px[(size_t)y * a->width + x])
                continue;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    int X = x + dx, Y = y + dy;
                    if (X >= 0 && Y >= 0 && X < a->width && Y < a->height &&
                        b->px[(size_t)Y * a->width + X])
                        near = 1;
                }
            if (!near) {
                n++;
                far_x = x;
                far_y = y;
            }
        }
    return n;
}

static void shapes_near(const dl_backend *b, const char *test)
{
    uint64_t seed = test_seed(test);
    int t, kind;
    long differ[4] = {0, 0, 0, 0}, total[4] = {0, 0, 0, 0};
    if (!usable(b)) {
        skip();
        return;
    }
    for (kind = 0; kind < 4; kind++)
        for (t = 0; t < 12; t++) {
            dl_encoder enc;
            uint8_t *buf;
            size_t len, i;
            dl_frame ref, got;
            int w = 64, h = 64, xy[16], j, twice;
            for (twice = 0; twice <= 1; twice++) {
                uint64_t s2 = seed;
                dl_encode_init(&enc, w, h, 0);
                if (twice)
                    dl_encode_word(&enc, DL_LOGIC_OP, DL_OP_XOR);
                for (j = 0; j <= twice; j++) {
                    int k;
                    seed = s2;
                    for (k = 0; k < 16; k++)
                        xy[k] = rnd(&seed, -4, 67);
                    switch (kind) {
                    case 0: dl_encode_points(&enc, DL_POLYLINE, xy, 5); break;
                    case 1: dl_encode_points(&enc, DL_SEGMENTS, xy, 8); break;
                    case 2:
                        dl_encode_circle(&enc, t & 1 ? DL_FILL_CIRCLE : DL_CIRCLE, xy[0], xy[1],
                                         (unsigned)rnd(&seed, 0, 40));
                        break;
                    default:
                        dl_encode_simple(&enc, DL_BEGIN_POLYGON);
                        dl_encode_points(&enc, DL_POLYLINE, xy, (size_t)rnd(&seed, 3, 8));
                        dl_encode_simple(&enc, DL_END_POLYGON);
                        break;
                    }
                }
                encode(&enc, &buf, &len);
                draw(&dl_backend_png, buf, len, &ref);
                draw(b, buf, len, &got);
                if (twice) {
                    /* xor twice restores the screen: each pixel written once */
                    for (i = 0; i < (size_t)w * h; i++)
                        assert_int_equal(got.px[i], 0);
                } else {
                    long fa = far_pixels(&got, &ref), fb = far_pixels(&ref, &got);
                    if (fa || fb)
                        fail_msg("%s: kind %d case %d: %ld/%ld pixels more than one pixel away, "
                                 "e.g. %d,%d (points %d,%d %d,%d %d,%d ...)", b->name, kind, t,
                                 fa, fb, far_x, far_y, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5]);
                    for (i = 0; i < (size_t)w * h; i++) {
                        differ[kind] += got.px[i] != ref.px[i];
                        total[kind] += ref.px[i] != 0;
                    }
                }
                dl_frame_free(&ref);
                dl_frame_free(&got);
                mem_free(buf);
            }
        }
    print_message("%s: pixels differing from the software raster (none by more than one pixel): "
                  "polylines %ld/%ld, segments %ld/%ld, circles %ld/%ld, polygons %ld/%ld\n",
                  b->name, differ[0], total[0], differ[1], total[1], differ[2], total[2],
                  differ[3], total[3]);
}

static void test_dl_backend_osmesa_shapes_within_one_pixel(void **state)
{
    (void)state;
    shapes_near(&dl_backend_osmesa, "test_dl_backend_osmesa_shapes_within_one_pixel");
}

static void test_dl_backend_egl_shapes_within_one_pixel(void **state)
{
    (void)state;
    shapes_near(&dl_backend_egl, "test_dl_backend_egl_shapes_within_one_pixel");
}

static void test_dl_backend_find(void **state)
{
    (void)state;
    assert_ptr_equal(dl_backend_find("png"), &dl_backend_png);
    assert_ptr_equal(dl_backend_find("osmesa"), &dl_backend_osmesa);
    assert_ptr_equal(dl_backend_find("egl"), &dl_backend_egl);
    assert_null(dl_backend_find("x11"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dl_backend_find),
        cmocka_unit_test(test_dl_backend_f_image_png),
        cmocka_unit_test(test_dl_backend_f_image_osmesa),
        cmocka_unit_test(test_dl_backend_f_image_egl),
        cmocka_unit_test(test_dl_backend_osmesa_fills_exact),
        cmocka_unit_test(test_dl_backend_egl_fills_exact),
        cmocka_unit_test(test_dl_backend_osmesa_shapes_within_one_pixel),
        cmocka_unit_test(test_dl_backend_egl_shapes_within_one_pixel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
