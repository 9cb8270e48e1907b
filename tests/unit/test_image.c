/* test_image — PNG round trips, the encoder's filter choice against a
 * scalar reference, image_diff figures, committed outputs and
 * bounded reads (src/image, src/util/outfile). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>
#include <zlib.h>
#include "image/image_png.h"
#include "image/image_png_write.h"
#include "image/image_diff.h"
#include "util/mem.h"
#include "util/outfile.h"
#include "support.h"

static char dir[64];

static int setup(void **state)
{
    (void)state;
    strcpy(dir, "/tmp/maprt-test-image-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static void test_image_png_round_trip_rgb_and_grey(void **state)
{
    uint64_t s = test_seed("test_image_png_round_trip_rgb_and_grey");
    char path[128];
    int ch;
    (void)state;
    for (ch = 1; ch <= 3; ch += 2) {
        image a, b;
        diag err;
        size_t i;
        diag_init(&err);
        assert_int_equal(image_alloc(&a, 37, 19, ch, "a", &err), 0);
        for (i = 0; i < (size_t)37 * 19 * ch; i++)
            a.px[i] = (uint8_t)test_rand(&s);
        snprintf(path, sizeof path, "%s/rt%d.png", dir, ch);
        assert_int_equal(image_write_png(path, &a, &err), 0);
        assert_int_equal(image_read_png(path, ch, &b, &err), 0);
        assert_int_equal(b.width, 37);
        assert_int_equal(b.height, 19);
        assert_memory_equal(a.px, b.px, (size_t)37 * 19 * ch);
        image_free(&a);
        image_free(&b);
    }
}

static void test_image_palette_png_reads_back_as_colours(void **state)
{
    const uint8_t palette[6] = {255, 0, 0, 0, 0, 255};
    const uint8_t index[4] = {0, 1, 1, 0};
    char path[128];
    image b;
    diag err;
    (void)state;
    diag_init(&err);
    snprintf(path, sizeof path, "%s/pal.png", dir);
    assert_int_equal(image_write_png_palette(path, 2, 2, index, palette, 2, &err), 0);
    assert_int_equal(image_read_png(path, 3, &b, &err), 0);
    assert_memory_equal(b.px, "\xff\x00\x00\x00\x00\xff\x00\x00\xff\xff\x00\x00", 12);
    image_free(&b);
    assert_int_equal(image_write_png_palette(path, 2, 2, index, palette, 0, &err), DIAG_INPUT);
    assert_string_equal(err.msg, "palette of 0 colours (1..256 allowed)");
}

/* IMAGE_INDEXED keeps a palette PNG's own indices, even where the palette
 * repeats a colour or is in no order, and gives another PNG's grey values. */
static void test_image_palette_indices_kept(void **state)
{
    uint8_t palette[3 * 200], index[20 * 10];
    const uint8_t grey[6] = {0, 7, 200, 255, 1, 2};
    char path[128];
    image b;
    diag err;
    size_t i;
    (void)state;
    diag_init(&err);
    for (i = 0; i < 200; i++) {              /* colours repeat every 7 entries */
        palette[3 * i] = (uint8_t)(i % 7 * 30);
        palette[3 * i + 1] = (uint8_t)(255 - i % 7 * 30);
        palette[3 * i + 2] = 9;
    }
    for (i = 0; i < sizeof index; i++)
        index[i] = (uint8_t)((i * 37 + 11) % 200);
    snprintf(path, sizeof path, "%s/idx.png", dir);
    assert_int_equal(image_write_png_palette(path, 20, 10, index, palette, 200, &err), 0);
    assert_int_equal(image_read_png(path, IMAGE_INDEXED, &b, &err), 0);
    assert_int_equal(b.channels, 1);
    assert_memory_equal(b.px, index, sizeof index);
    image_free(&b);
    b.width = 3;
    b.height = 2;
    b.channels = 1;
    b.px = (uint8_t *)grey;
    assert_int_equal(image_write_png(path, &b, &err), 0);
    assert_int_equal(image_read_png(path, IMAGE_INDEXED, &b, &err), 0);
    assert_memory_equal(b.px, grey, 6);
    image_free(&b);
}

static void test_image_bad_inputs_are_reported(void **state)
{
    char path[128], buf[600];
    image b;
    diag err;
    (void)state;
    snprintf(path, sizeof path, "%s/none.png", dir);
    diag_init(&err);
    assert_int_equal(image_read_png(path, 3, &b, &err), DIAG_INPUT);
    snprintf(buf, sizeof buf, "%s: error: cannot open: No such file or directory", path);
    {
        char got[1024];
        diag_format(&err, got, sizeof got);
        assert_string_equal(got, buf);
    }
    diag_init(&err);
    assert_int_equal(image_read_png_memory("x.png", "not a png at all", 16, 3, &b, &err), DIAG_INPUT);
    assert_non_null(strstr(err.msg, "not a readable PNG"));
    diag_init(&err);
    assert_int_equal(image_alloc(&b, 0, 5, 3, "z", &err), DIAG_INPUT);
    assert_string_equal(err.msg, "image size 0x5 is outside 1..32768 per side");
    diag_init(&err);
    assert_int_equal(image_alloc(&b, 32768, 32768, 3, "z", &err), DIAG_INPUT);
}

static void test_image_diff_matches_direct_formula(void **state)
{
    uint64_t s = test_seed("test_image_diff_matches_direct_formula");
    image a, b;
    image_diff_stats d;
    diag err;
    size_t i, n = 64 * 48;
    long double se = 0;
    int maxd = 0, over = 0;
    (void)state;
    diag_init(&err);
    assert_int_equal(image_alloc(&a, 64, 48, 3, "a", &err), 0);
    assert_int_equal(image_alloc(&b, 64, 48, 3, "b", &err), 0);
    image_diff(&a, &b, 2, &d);
    assert_true(isinf(d.psnr) && d.mse == 0 && d.max == 0 && d.over == 0);
    for (i = 0; i < 3 * n; i++) {
        a.px[i] = (uint8_t)test_rand(&s);
        b.px[i] = (uint8_t)(a.px[i] + (int)(test_rand(&s) % 7) - 3);
    }
    for (i = 0; i < n; i++) {
        int k, w = 0;
        for (k = 0; k < 3; k++) {
            int dd = a.px[3 * i + k] - b.px[3 * i + k];
            dd = dd < 0 ? -dd : dd;
            se += (long double)dd * dd;
            w = dd > w ? dd : w;
        }
        maxd = w > maxd ? w : maxd;
        over += w > 2;
    }
    image_diff(&a, &b, 2, &d);
    assert_true(fabs(d.mse - (double)(se / (3.0L * n))) < 1e-12);
    assert_true(fabs(d.psnr - 10 * log10(65025.0 / (double)(se / (3.0L * n)))) < 1e-9);
    assert_int_equal(d.max, maxd);
    assert_true(fabs(d.over - (double)over / n) < 1e-15);
    image_free(&a);
    image_free(&b);
}

static void test_image_outfile_commits_only_on_success(void **state)
{
    char sub[96], path[128];
    outfile of;
    diag err;
    char *data;
    size_t len;
    (void)state;
    snprintf(sub, sizeof sub, "%s/commit", dir);
    assert_int_equal(mkdir(sub, 0700), 0);
    snprintf(path, sizeof path, "%s/out.bin", sub);
    diag_init(&err);
    assert_int_equal(outfile_open(&of, path, &err), 0);
    assert_int_equal(outfile_write(&of, "abc", 3, &err), 0);
    assert_int_equal(access(path, F_OK), -1);          /* not there before commit */
    outfile_abort(&of);
    assert_int_equal(test_dir_entries(sub), 0);                /* abort leaves nothing */
    assert_int_equal(outfile_write_all(path, "hello", 5, &err), 0);
    assert_int_equal(test_dir_entries(sub), 1);
    assert_int_equal(infile_read_all(path, 5, &data, &len, &err), 0);
    assert_int_equal(len, 5);
    assert_memory_equal(data, "hello", 5);
    mem_free(data);
    assert_int_equal(infile_read_all(path, 4, &data, &len, &err), DIAG_INPUT);
    assert_string_equal(err.msg, "file larger than 4 bytes");
}

/* The banded encoder: libpng decodes every output to the exact pixels, for
 * smooth, noisy and flat images, band edges included (heights around
 * multiples of IMAGE_PNG_WRITE_BAND, one row, one column), and the file is
 * the same byte for byte on 1 and 3 threads and at every level. */
static void test_image_png_banded_encoder_decodes_exactly(void **state)
{
    static const int sizes[][2] = {{1, 1}, {1, 300}, {257, 1}, {64, 127}, {64, 128}, {33, 129},
                                   {300, 260}, {97, 385}};
    uint64_t s = test_seed("test_image_png_banded_encoder_decodes_exactly");
    size_t k;
    (void)state;
    for (k = 0; k < sizeof sizes / sizeof sizes[0] * 3; k++) {
        int w = sizes[k / 3][0], h = sizes[k / 3][1], ch = k % 2 ? 1 : 3, kind = (int)(k % 3), lv;
        image img, back;
        diag err;
        size_t i;
        diag_init(&err);
        assert_int_equal(image_alloc(&img, w, h, ch, "t", &err), 0);
        for (i = 0; i < (size_t)w * h * ch; i++) {
            size_t x = i / ch % w, y = i / ch / w;
            img.px[i] = kind == 0 ? (unsigned char)(x * 3 + y * 5 + i % ch * 40)
                      : kind == 1 ? (unsigned char)test_rand(&s) : (unsigned char)(y > (size_t)h / 2 ? 200 : 7);
        }
        for (lv = 1; lv <= 9; lv += 4) {
            unsigned char *a, *b;
            size_t na, nb;
            assert_int_equal(image_png_write_mem(&img, 1, lv, "t", &a, &na, &err), 0);
            assert_int_equal(image_png_write_mem(&img, 3, lv, "t", &b, &nb, &err), 0);
            assert_true(na == nb && !memcmp(a, b, na));
            assert_int_equal(image_read_png_memory("t", a, na, ch, &back, &err), 0);
            assert_int_equal(back.width, w);
            assert_int_equal(back.height, h);
            assert_memory_equal(back.px, img.px, (size_t)w * h * ch);
            image_free(&back);
            mem_free(a);
            mem_free(b);
        }
        image_free(&img);
    }
}

/* The filter libpng's heuristic picks for one row, and its bytes: the
 * plain scalar definitions of PNG 9.2-9.4, the reference for the
 * encoder's vector code. */
static int ref_filter(const unsigned char *cur, const unsigned char *prev, size_t n, size_t bpp,
                      unsigned char out[5][1024])
{
    unsigned long sum[5] = {0, 0, 0, 0, 0};
    size_t i;
    int f, best = 0;
    for (i = 0; i < n; i++) {
        int a = i >= bpp ? cur[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
        int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
        int pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        out[0][i] = cur[i];
        out[1][i] = (unsigned char)(cur[i] - a);
        out[2][i] = (unsigned char)(cur[i] - b);
        out[3][i] = (unsigned char)(cur[i] - (a + b) / 2);
        out[4][i] = (unsigned char)(cur[i] - pred);
        for (f = 0; f < 5; f++)
            sum[f] += out[f][i] < 128 ? out[f][i] : 256 - out[f][i];
    }
    for (f = 1; f < 5; f++)
        if (sum[f] < sum[best])
            best = f;
    return best;
}

static void test_image_png_filters_match_scalar_reference(void **state)
{
    /* widths around the 16-byte vector steps, RGB and grey; pictures that
     * make every filter win somewhere: noise, gradients, steps, and rows
     * copied with a shift */
    static const int sizes[][2] = {{1, 9}, {5, 8}, {6, 8}, {21, 30}, {100, 40}, {341, 12}};
    uint64_t s = test_seed("test_image_png_filters_match_scalar_reference");
    int used[5] = {0, 0, 0, 0, 0};
    size_t k;
    (void)state;
    for (k = 0; k < sizeof sizes / sizeof sizes[0] * 2; k++) {
        int w = sizes[k / 2][0], h = sizes[k / 2][1], ch = k % 2 ? 1 : 3, y;
        size_t n = (size_t)w * ch, i, off = 8, rawlen = (n + 1) * (size_t)h;
        unsigned char *png, *z = NULL, *raw = mem_alloc(rawlen + 1), ref[5][1024], zero[1024];
        size_t len, zl = 0;
        uLongf got = (uLongf)rawlen + 1;
        image img;
        diag err;
        diag_init(&err);
        assert_non_null(raw);
        memset(zero, 0, sizeof zero);
        assert_int_equal(image_alloc(&img, w, h, ch, "t", &err), 0);
        for (y = 0; y < h; y++)
            for (i = 0; i < n; i++) {
                unsigned char *p = img.px + (size_t)y * n + i;
                switch ((y + (int)(test_rand(&s) % 2)) % 5) {
                case 0: *p = (unsigned char)test_rand(&s); break;
                case 1: *p = (unsigned char)(i * 7 + (size_t)y * 3); break;
                case 2: *p = (unsigned char)(i < n / 2 ? 30 : 220); break;
                case 3: *p = y ? p[-(long)n + (i >= (size_t)ch ? -ch : 0)] : 9; break;
                default: *p = (unsigned char)(i * i / 5 + (size_t)y); break;
                }
            }
        assert_int_equal(image_png_write_mem(&img, 2, 6, "t", &png, &len, &err), 0);
        while (off + 12 <= len) {         /* gather the IDAT chunks' data */
            size_t cl = (size_t)png[off] << 24 | (size_t)png[off + 1] << 16 | (size_t)png[off + 2] << 8 | png[off + 3];
            if (!memcmp(png + off + 4, "IDAT", 4)) {
                z = realloc(z, zl + cl);
                assert_non_null(z);
                memcpy(z + zl, png + off + 8, cl);
                zl += cl;
            }
            off += 12 + cl;
        }
        assert_int_equal(uncompress(raw, &got, z, (uLong)zl), Z_OK);
        assert_int_equal(got, rawlen);
        for (y = 0; y < h; y++) {
            const unsigned char *row = raw + (size_t)y * (n + 1);
            int f = ref_filter(img.px + (size_t)y * n, y ? img.px + (size_t)(y - 1) * n : zero, n, (size_t)ch, ref);
            assert_int_equal(row[0], f);
            assert_memory_equal(row + 1, ref[f], n);
            used[f] = 1;
        }
        free(z);
        mem_free(raw);
        mem_free(png);
        image_free(&img);
    }
    for (k = 0; k < 5; k++)
        assert_true(used[k]);             /* every filter was chosen somewhere */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_image_png_round_trip_rgb_and_grey),
        cmocka_unit_test(test_image_png_banded_encoder_decodes_exactly),
        cmocka_unit_test(test_image_png_filters_match_scalar_reference),
        cmocka_unit_test(test_image_palette_png_reads_back_as_colours),
        cmocka_unit_test(test_image_palette_indices_kept),
        cmocka_unit_test(test_image_bad_inputs_are_reported),
        cmocka_unit_test(test_image_diff_matches_direct_formula),
        cmocka_unit_test(test_image_outfile_commits_only_on_success),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
