/* test_compare — registration, metrics, pictures, PNM reading and error
 * paths of `maprt compare`, against independent computations on synthetic
 * pictures (see test_compare_synth.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "compare/compare.h"
#include "compare/diffpic.h"
#include "compare/ssim.h"
#include "compare/imgload.h"
#ifdef IMAGE_HAVE_JPEG
#include <jpeglib.h>
#endif
#include "image/image_tiff.h"
#include "image/pnm.h"
#include "util/mem.h"
#include "test_compare_synth.h"

/* The largest distance, in reference pixels, between where two transforms
 * put the corners of a w x h test picture. */
static double corner_error(const warp_params *a, const warp_params *b, int w, int h)
{
    double worst = 0;
    int q;
    for (q = 0; q < 4; q++) {
        double x1, y1, x2, y2, d;
        warp_to_ref(a, (q & 1) ? w : 0, (q & 2) ? h : 0, &x1, &y1);
        warp_to_ref(b, (q & 1) ? w : 0, (q & 2) ? h : 0, &x2, &y2);
        d = hypot(x1 - x2, y1 - y2);
        worst = d > worst ? d : worst;
    }
    return worst;
}

static void test_compare_warp_inverse(void **state)
{
    uint64_t s = test_seed("test_compare_warp_inverse");
    int i;
    (void)state;
    for (i = 0; i < 1000; i++) {
        warp_params p;
        double xt = test_uniform(&s, -500, 500), yt = test_uniform(&s, -500, 500), xr, yr, x2, y2;
        p.scale = exp(test_uniform(&s, -2, 2));
        p.dx = test_uniform(&s, -100, 100);
        p.dy = test_uniform(&s, -100, 100);
        p.angle = test_uniform(&s, -45, 45);
        warp_to_ref(&p, xt, yt, &xr, &yr);
        warp_to_test(&p, xr, yr, &x2, &y2);
        assert_true(fabs(x2 - xt) < 1e-9 && fabs(y2 - yt) < 1e-9);
    }
    /* the documented direction: a positive angle turns the test's x axis
     * towards the top of the reference (counter-clockwise on screen) */
    {
        warp_params p = {2.0, 10.0, 20.0, 90.0};
        double xr, yr;
        warp_to_ref(&p, 1.0, 0.0, &xr, &yr);
        assert_true(fabs(xr - 10.0) < 1e-12 && fabs(yr - 18.0) < 1e-12);
    }
}

/* The acceptance test: a grey, scaled, shifted, turned, blurred,
 * noisy scan with paper margins registers within 1 pixel and 1 percent. */
static void test_compare_register_recovers_scan(void **state)
{
    uint64_t s = test_seed("test_compare_register_recovers_scan");
    image render;
    int k;
    (void)state;
    assert_int_equal(synth_render(0, 160, &render), 0);
    for (k = 0; k < 3; k++) {
        warp_params truth;
        image scan;
        compare_opts o;
        compare_result r;
        diag err;
        int w, h;
        truth.scale = test_uniform(&s, 0.8, 1.4);
        truth.angle = test_uniform(&s, 0, 1) < 0.5 ? -1.0 : 1.0;
        truth.dx = test_uniform(&s, 8, 40);
        truth.dy = test_uniform(&s, 8, 40);
        w = (int)(truth.scale * 160 + truth.dx + test_uniform(&s, 8, 40));
        h = (int)(truth.scale * 160 + truth.dy + test_uniform(&s, 8, 40));
        assert_int_equal(synth_scan(0, 160, &truth, w, h, 12.0, &s, &scan), 0);
        compare_opts_init(&o);
        o.do_register = 1;
        o.grey = 1;
        diag_init(&err);
        assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
        printf("# truth scale %.4f dx %.2f dy %.2f angle %.1f; found %.4f %.2f %.2f %.3f (corner error %.3f px)\n",
               truth.scale, truth.dx, truth.dy, truth.angle, r.p.scale, r.p.dx, r.p.dy, r.p.angle,
               corner_error(&truth, &r.p, 160, 160));
        assert_true(r.registered);
        assert_true(fabs(r.p.scale / truth.scale - 1) < 0.01);
        assert_true(fabs(r.p.dx - truth.dx) < 1.0 && fabs(r.p.dy - truth.dy) < 1.0);
        assert_true(corner_error(&truth, &r.p, 160, 160) < 1.0);
        assert_true(fabs(r.p.angle - truth.angle) < 0.25);
        image_free(&scan);
    }
    image_free(&render);
}

/* Seeded random placements over a wider range of scales and angles. */
static void test_compare_register_random_placements(void **state)
{
    uint64_t s = test_seed("test_compare_register_random_placements");
    image render;
    int k;
    (void)state;
    assert_int_equal(synth_render(0, 160, &render), 0);
    for (k = 0; k < 6; k++) {
        warp_params truth;
        image scan;
        compare_opts o;
        compare_result r;
        diag err;
        int w, h;
        truth.scale = exp(test_uniform(&s, log(0.5), log(2.0)));
        truth.angle = test_uniform(&s, -4, 4);
        truth.dx = test_uniform(&s, 5, 40);
        truth.dy = test_uniform(&s, 5, 40);
        w = (int)(truth.scale * 160 + truth.dx + test_uniform(&s, 5, 40));
        h = (int)(truth.scale * 160 + truth.dy + test_uniform(&s, 5, 40));
        assert_int_equal(synth_scan(0, 160, &truth, w, h, 10.0, &s, &scan), 0);
        compare_opts_init(&o);
        o.do_register = 1;
        o.grey = 1;
        diag_init(&err);
        assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
        printf("# truth %.4f %.2f %.2f %.2f; found %.4f %.2f %.2f %.2f (corner error %.3f px)\n", truth.scale,
               truth.dx, truth.dy, truth.angle, r.p.scale, r.p.dx, r.p.dy, r.p.angle,
               corner_error(&truth, &r.p, 160, 160));
        assert_true(fabs(r.p.scale / truth.scale - 1) < 0.01);
        assert_true(corner_error(&truth, &r.p, 160, 160) < 1.0);
        image_free(&scan);
    }
    image_free(&render);
}

/* With --crop the transform is relative to the crop's corner. */
static void test_compare_register_crop_offsets(void **state)
{
    uint64_t s = test_seed("test_compare_register_crop_offsets");
    image render, scan;
    warp_params truth = {1.2, 30.0, 26.0, -1.0}, want = {1.2, 18.0, 19.0, -1.0};
    compare_opts o;
    compare_result r;
    diag err;
    (void)state;
    assert_int_equal(synth_render(0, 120, &render), 0);
    assert_int_equal(synth_scan(0, 120, &truth, 200, 190, 8.0, &s, &scan), 0);
    compare_opts_init(&o);
    o.do_register = 1;
    o.grey = 1;
    o.crop = 1;
    o.cx = 12;
    o.cy = 7;
    o.cw = 180;
    o.ch = 176;
    diag_init(&err);
    assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
    assert_int_equal(r.width, 180);
    assert_int_equal(r.height, 176);
    assert_true(corner_error(&want, &r.p, 120, 120) < 1.0);
    image_free(&render);
    image_free(&scan);
}

/* A halftoned print (binary dots on a 45-degree screen repeating every 10
 * pixels along its axes) still registers within a pixel and a percent once
 * descreened with sigma 0.4 x the period. */
static void test_compare_register_halftone_scan(void **state)
{
    uint64_t s = test_seed("test_compare_register_halftone_scan");
    image render, scan;
    warp_params truth = {1.37, 25.0, 18.0, 1.0};
    compare_opts o;
    compare_result r;
    diag err;
    (void)state;
    assert_int_equal(synth_render(0, 160, &render), 0);
    assert_int_equal(synth_scan(0, 160, &truth, 270, 260, 8.0, &s, &scan), 0);
    synth_halftone(&scan, 5.0);
    compare_opts_init(&o);
    o.do_register = 1;
    o.grey = 1;
    o.descreen = 4.0;
    diag_init(&err);
    assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
    printf("# found %.4f %.2f %.2f %.3f (corner error %.3f px), ssim %.3f, score %.3f\n", r.p.scale, r.p.dx, r.p.dy,
           r.p.angle, corner_error(&truth, &r.p, 160, 160), r.ssim, r.register_score);
    assert_true(fabs(r.p.scale / truth.scale - 1) < 0.01);
    assert_true(corner_error(&truth, &r.p, 160, 160) < 1.0);
    image_free(&render);
    image_free(&scan);
}

/* The same scan scores far higher against its own scene than against a
 * different one. */
static void test_compare_ssim_separates_scenes(void **state)
{
    uint64_t s = test_seed("test_compare_ssim_separates_scenes");
    image same, other, scan;
    warp_params truth = {1.15, 17.0, 23.0, -1.0};
    compare_opts o;
    compare_result a, b;
    diag err;
    (void)state;
    assert_int_equal(synth_render(0, 160, &same), 0);
    assert_int_equal(synth_render(1, 160, &other), 0);
    assert_int_equal(synth_scan(0, 160, &truth, 220, 215, 12.0, &s, &scan), 0);
    compare_opts_init(&o);
    o.do_register = 1;
    o.grey = 1;
    o.descreen = 1.5;   /* as docs/compare.md advises for scans */
    diag_init(&err);
    assert_int_equal(compare_images("scan", &scan, "same", &same, &o, &a, &err), 0);
    assert_int_equal(compare_images("scan", &scan, "other", &other, &o, &b, &err), 0);
    printf("# same scene: ssim %.4f psnr %.2f score %.3f; other scene: ssim %.4f psnr %.2f score %.3f\n",
           a.ssim, a.psnr, a.register_score, b.ssim, b.psnr, b.register_score);
    assert_true(a.ssim > 0.85);
    assert_true(a.ssim > b.ssim + 0.25);
    assert_true(a.register_score > b.register_score + 0.15);
    /* and so does the other scene put exactly where the figure is */
    {
        plane rl, tl, wt, mask;
        double ssim;
        long windows;
        assert_int_equal(plane_from_image(&scan, -1, 0, 0, scan.width, scan.height, &rl), 0);
        assert_int_equal(plane_from_image(&other, -1, 0, 0, 160, 160, &tl), 0);
        assert_int_equal(warp_resample(&truth, &tl, 1, scan.width, scan.height, &wt, &mask), 0);
        assert_int_equal(plane_blur_masked(&rl, &mask, 1.5), 0);
        assert_int_equal(plane_blur_masked(&wt, &mask, 1.5), 0);
        assert_int_equal(ssim_mean(&rl, &wt, &mask, &ssim, &windows), 0);
        printf("# other scene at the figure's place: ssim %.4f\n", ssim);
        assert_true(a.ssim > ssim + 0.25);
        plane_free(&rl);
        plane_free(&tl);
        plane_free(&wt);
        plane_free(&mask);
    }
    image_free(&same);
    image_free(&other);
    image_free(&scan);
}

/* Fills an image with seeded noise, so every pixel differs. */
static void random_image(image *img, int w, int h, int ch, uint64_t *s)
{
    size_t i;
    diag err;
    diag_init(&err);
    assert_int_equal(image_alloc(img, w, h, ch, "random", &err), 0);
    for (i = 0; i < (size_t)w * h * ch; i++)
        img->px[i] = (uint8_t)(test_rand(s) >> 56);
}

/* PSNR and pixels_over on aligned pairs agree with a direct computation. */
static void test_compare_psnr_matches_direct(void **state)
{
    uint64_t s = test_seed("test_compare_psnr_matches_direct");
    int k;
    (void)state;
    for (k = 0; k < 4; k++) {
        image a, b;
        compare_opts o;
        compare_result r;
        diag err;
        long double se = 0;
        long over = 0;
        size_t i, n = 37 * 29;
        int grey = k & 1;
        double thr = k < 2 ? 8 : 40;
        random_image(&a, 37, 29, 3, &s);
        random_image(&b, 37, 29, 3, &s);
        for (i = 0; i < n * 3; i++) /* make b a noisy copy of a */
            if (test_rand(&s) & 1)
                b.px[i] = a.px[i];
        for (i = 0; i < n; i++) {
            long double worst = 0;
            int c;
            if (grey) {
                long double ya = 0.299L * a.px[3 * i] + 0.587L * a.px[3 * i + 1] + 0.114L * a.px[3 * i + 2];
                long double yb = 0.299L * b.px[3 * i] + 0.587L * b.px[3 * i + 1] + 0.114L * b.px[3 * i + 2];
                se += (ya - yb) * (ya - yb);
                worst = fabsl(ya - yb);
            } else {
                for (c = 0; c < 3; c++) {
                    long double d = (long double)a.px[3 * i + c] - b.px[3 * i + c];
                    se += d * d;
                    worst = fabsl(d) > worst ? fabsl(d) : worst;
                }
            }
            over += worst > thr;
        }
        compare_opts_init(&o);
        o.grey = grey;
        o.threshold = thr;
        diag_init(&err);
        assert_int_equal(compare_images("a", &a, "b", &b, &o, &r, &err), 0);
        {
            long double mse = se / (n * (grey ? 1 : 3));
            double psnr = (double)(10.0L * log10l(255.0L * 255.0L / mse));
            assert_int_equal(r.pixels, (long)n);
            assert_int_equal(r.channels, grey ? 1 : 3);
            assert_true(fabs(r.psnr - psnr) < (grey ? 1e-4 : 1e-9));
            assert_true(fabs(r.pixels_over - (double)over / n) < 1e-12);
        }
        image_free(&a);
        image_free(&b);
    }
}

static void test_compare_identical_is_perfect(void **state)
{
    uint64_t s = test_seed("test_compare_identical_is_perfect");
    image a;
    compare_opts o;
    compare_result r;
    diag err;
    (void)state;
    random_image(&a, 30, 20, 3, &s);
    compare_opts_init(&o);
    diag_init(&err);
    assert_int_equal(compare_images("a", &a, "a", &a, &o, &r, &err), 0);
    assert_true(isinf(r.psnr) && r.mse == 0 && r.pixels_over == 0);
    assert_true(fabs(r.ssim - 1) < 1e-9);
    assert_int_equal(r.ssim_windows, 20L * 10);
    image_free(&a);
}

/* SSIM against a direct evaluation of the formula at every window. */
static void test_compare_ssim_matches_formula(void **state)
{
    uint64_t s = test_seed("test_compare_ssim_matches_formula");
    plane x, y;
    double got, want = 0, g[11], gs = 0;
    long windows;
    int i, j, u, v, n = 0;
    (void)state;
    assert_int_equal(plane_alloc(&x, 23, 17), 0);
    assert_int_equal(plane_alloc(&y, 23, 17), 0);
    for (i = 0; i < 23 * 17; i++) {
        x.v[i] = (float)(test_rand(&s) >> 56);
        y.v[i] = (float)(0.5 * x.v[i] + (test_rand(&s) >> 57));
    }
    for (u = 0; u < 11; u++)
        gs += g[u] = exp(-(u - 5) * (u - 5) / (2 * 1.5 * 1.5));
    for (j = 0; j + 11 <= 17; j++)
        for (i = 0; i + 11 <= 23; i++) {
            long double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0, c1 = 6.5025L, c2 = 58.5225L;
            for (v = 0; v < 11; v++)
                for (u = 0; u < 11; u++) {
                    long double wgt = g[u] * g[v] / (gs * gs), a = PLANE_AT(&x, i + u, j + v), b = PLANE_AT(&y, i + u, j + v);
                    mx += wgt * a;
                    my += wgt * b;
                }
            for (v = 0; v < 11; v++)
                for (u = 0; u < 11; u++) {
                    long double wgt = g[u] * g[v] / (gs * gs), a = PLANE_AT(&x, i + u, j + v) - mx,
                                b = PLANE_AT(&y, i + u, j + v) - my;
                    sxx += wgt * a * a;
                    syy += wgt * b * b;
                    sxy += wgt * a * b;
                }
            want += (double)((2 * mx * my + c1) * (2 * sxy + c2) / ((mx * mx + my * my + c1) * (sxx + syy + c2)));
            n++;
        }
    want /= n;
    assert_int_equal(ssim_mean(&x, &y, NULL, &got, &windows), 0);
    assert_int_equal(windows, n);
    assert_true(fabs(got - want) < 1e-9);
    /* a mask with one hole removes exactly the windows that cover it */
    {
        plane m;
        assert_int_equal(plane_alloc(&m, 23, 17), 0);
        for (i = 0; i < 23 * 17; i++)
            m.v[i] = 1;
        PLANE_AT(&m, 0, 0) = 0;
        assert_int_equal(ssim_mean(&x, &y, &m, &got, &windows), 0);
        assert_int_equal(windows, n - 1);
        plane_free(&m);
    }
    plane_free(&x);
    plane_free(&y);
}

/* --levels undoes a fade: a faded copy scores like the original. */
static void test_compare_levels_undo_fade(void **state)
{
    image a, b;
    compare_opts o;
    compare_result r;
    diag err;
    size_t i;
    (void)state;
    assert_int_equal(synth_render(0, 64, &a), 0);
    assert_int_equal(synth_render(0, 64, &b), 0);
    for (i = 0; i < (size_t)64 * 64 * 3; i++)
        b.px[i] = (uint8_t)(a.px[i] / 2 + 100);
    compare_opts_init(&o);
    diag_init(&err);
    assert_int_equal(compare_images("a", &a, "b", &b, &o, &r, &err), 0);
    assert_true(r.psnr < 20);
    o.levels = 1;
    assert_int_equal(compare_images("a", &a, "b", &b, &o, &r, &err), 0);
    assert_true(r.psnr > 45);
    assert_true(fabs(r.gain[0] - 2) < 0.02 && fabs(r.offset[0] + 200) < 2);
    image_free(&a);
    image_free(&b);
}

static void test_compare_heat_ramp(void **state)
{
    plane r, t, m;
    image out;
    diag err;
    static const float diffs[5] = {0, 32, 64, 96, 200};
    static const uint8_t want[6][3] = {{0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}, {64, 64, 64}};
    int i;
    (void)state;
    assert_int_equal(plane_alloc(&r, 6, 1), 0);
    assert_int_equal(plane_alloc(&t, 6, 1), 0);
    assert_int_equal(plane_alloc(&m, 6, 1), 0);
    for (i = 0; i < 6; i++) {
        r.v[i] = 10;
        t.v[i] = i < 5 ? 10 + diffs[i] : 99;
        m.v[i] = i < 5;
    }
    diag_init(&err);
    assert_int_equal(diffpic_heat(&r, &t, 1, &m, &out, &err), 0);
    for (i = 0; i < 6; i++)
        assert_memory_equal(out.px + 3 * i, want[i], 3);
    image_free(&out);
    plane_free(&r);
    plane_free(&t);
    plane_free(&m);
}

static void test_compare_pnm_formats(void **state)
{
    static const char p2[] = "P2\n# a comment\n3 2\n# another\n1000\n0 500 1000\n1000 0 1\n";
    static const char p3[] = "P3 2 1 255 255 0 0   0 0 255\n";
    static const unsigned char p5[] = {'P', '5', ' ', '2', ' ', '1', ' ', '6', '5', '5', '3', '5', '\n', 0xff, 0xff, 0x80, 0x00};
    static const unsigned char p6[] = {'P', '6', '\n', '1', ' ', '1', '\n', '2', '5', '5', '\n', 10, 20, 30};
    image img;
    diag err;
    (void)state;
    diag_init(&err);
    assert_int_equal(pnm_read_memory("p2", p2, sizeof p2 - 1, 1, &img, &err), 0);
    assert_int_equal(img.width, 3);
    assert_int_equal(img.height, 2);
    assert_memory_equal(img.px, "\x00\x80\xff\xff\x00\x00", 6);
    image_free(&img);
    assert_int_equal(pnm_read_memory("p3", p3, sizeof p3 - 1, 3, &img, &err), 0);
    assert_memory_equal(img.px, "\xff\x00\x00\x00\x00\xff", 6);
    image_free(&img);
    assert_int_equal(pnm_read_memory("p3", p3, sizeof p3 - 1, 1, &img, &err), 0);
    assert_int_equal(img.px[0], 76);  /* 0.299 * 255 */
    assert_int_equal(img.px[1], 29);  /* 0.114 * 255 */
    image_free(&img);
    assert_int_equal(pnm_read_memory("p5", p5, sizeof p5, 3, &img, &err), 0);
    assert_memory_equal(img.px, "\xff\xff\xff\x80\x80\x80", 6);
    image_free(&img);
    assert_int_equal(pnm_read_memory("p6", p6, sizeof p6, 3, &img, &err), 0);
    assert_memory_equal(img.px, "\x0a\x14\x1e", 3);
    image_free(&img);
    assert_int_equal(err.status, 0);
}

/* Every bad PNM gets its own exact diagnostic. */
static void test_compare_pnm_errors(void **state)
{
    static const struct {
        const char *data;
        size_t len;
        const char *want;
    } cases[] = {
        {"", 0, "f: error: empty file"},
        {"GIF89a", 6, "f:1:1: error: not a PNM file (no P2, P3, P5 or P6 magic)"},
        {"P1\n1 1\n0\n", 9, "f:1:1: error: PBM bitmaps (P1) are not supported; use P2, P3, P5 or P6"},
        {"P7\n", 3, "f:1:1: error: PAM (P7) is not supported; use P2, P3, P5 or P6"},
        {"P2x 1 1 255 0", 13, "f:1:3: error: junk after the magic number"},
        {"P2\n0 4\n255\n", 11, "f: error: image size 0x4 is empty"},
        {"P2\n2 2\n0\n", 9, "f: error: maxval is 0 (1..65535 allowed)"},
        {"P2\n2 2\n65536\n", 13, "f:3:1: error: maxval is larger than 65535"},
        {"P2\n99999 2\n255\n", 15, "f:2:1: error: width is larger than 32768"},
        {"P2\n2 -2\n255\n", 12, "f:2:3: error: expected the height (a decimal number), found '-'"},
        {"P2\n2 2", 6, "f:2:4: error: file ends before the maxval"},
        {"P2\n2 2\n255\n1 2 3 300\n", 21, "f:4:7: error: sample 300 is above maxval 255"},
        {"P2\n2 2\n255\n1 2 3\n", 17, "f:4:1: error: raster truncated: 4 samples cannot fit in 6 bytes"},
        {"P2\n2 2\n255\n1 2 3     \n", 22, "f:5:1: error: file ends before the sample"},
        {"P2\n2 2\n255\n1 2 3x4\n", 19, "f:4:6: error: junk after the sample"},
        {"P2\n16000 16000\n255\n1 2\n", 23, "f:4:1: error: raster truncated: 256000000 samples cannot fit in 4 bytes"},
        {"P2\n30000 30000\n255\n1 2\n", 23, "f: error: image size 30000x30000 is over 268435456 pixels"},
        {"P5\n2 2\n255\n\x01\x02\x03", 14, "f: offset 14: error: raster truncated: 3 bytes present, 4 needed"},
        {"P5\n1 1\n15\n\x10", 11, "f: offset 10: error: sample 16 is above maxval 15"},
        {"P6\n1 1\n255", 10, "f: offset 10: error: file ends before the raster"},
        {"P5\n1 1\n255#c\n\x01", 14, "f:3:4: error: expected one whitespace character before the raster"},
    };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        image img;
        diag err;
        char buf[600];
        diag_init(&err);
        assert_int_equal(pnm_read_memory("f", cases[k].data, cases[k].len, 3, &img, &err), DIAG_INPUT);
        diag_format(&err, buf, sizeof buf);
        if (strcmp(buf, cases[k].want))
            printf("# case %zu: got '%s'\n", k, buf);
        assert_string_equal(buf, cases[k].want);
    }
}

/* Bad pictures and impossible requests give exact, located messages. */
static void test_compare_input_errors(void **state)
{
    image a, b;
    compare_opts o;
    compare_result r;
    diag err;
    char buf[600];
    static const char junk[] = "hello, world";
    (void)state;
    assert_int_equal(synth_render(0, 40, &a), 0);
    assert_int_equal(synth_render(0, 30, &b), 0);
    compare_opts_init(&o);
    diag_init(&err);
    assert_int_equal(compare_images("ref.png", &a, "test.png", &b, &o, &r, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "test.png: error: size 30x30 differs from the reference's 40x40; use --register "
                             "to compare pictures of different sizes");
    o.crop = 1;
    o.cx = 30;
    o.cy = 0;
    o.cw = 11;
    o.ch = 10;
    diag_init(&err);
    assert_int_equal(compare_images("ref.png", &a, "test.png", &b, &o, &r, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "ref.png: error: crop 30,0,11,10 is not inside the 40x40 reference");
    o.cx = 0;
    o.cw = 10;
    diag_init(&err);
    assert_int_equal(compare_images("ref.png", &a, "test.png", &b, &o, &r, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "test.png: error: size 30x30 differs from the reference's 10x10 (after cropping); "
                             "use --register to compare pictures of different sizes");
    o.crop = 0;
    {
        image c, d;
        assert_int_equal(synth_render(0, 8, &c), 0);
        assert_int_equal(synth_render(0, 8, &d), 0);
        diag_init(&err);
        assert_int_equal(compare_images("ref.png", &c, "test.png", &d, &o, &r, &err), DIAG_INPUT);
        diag_format(&err, buf, sizeof buf);
        assert_string_equal(buf, "test.png: error: the compared area has no 11x11 patch for SSIM (8x8 reference frame)");
        image_free(&c);
        image_free(&d);
    }
    diag_init(&err);
    assert_int_equal(imgload_memory("x.png", junk, sizeof junk - 1, 1000, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "x.png: error: this is a text file, not a picture (PNG, PNM, JPEG or TIFF); "
                             "did you mean `maprt render`?");
    diag_init(&err);
    assert_int_equal(imgload_memory("x.bin", "\001\002\003", 3, 1000, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "x.bin: error: not a PNG, PNM, JPEG or TIFF image");
    diag_init(&err);
    assert_int_equal(imgload_memory("x.png", "\x89PNG\r\n\x1a\n\0\0", 10, 1000, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_true(!strncmp(buf, "x.png: error: not a readable PNG", 32));
    diag_init(&err);
    assert_int_equal(imgload_read("/nonexistent/ref.png", 1000, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "/nonexistent/ref.png: error: cannot open: No such file or directory");
    /* too large for the limit: refused from the header */
    {
        static const char big[] = "P5 40 30 255\n";
        /* a real 256x200 PNG, from libpng */
        static unsigned char grey[256 * 200], png[4096];
        png_image pi;
        png_alloc_size_t plen = sizeof png;
        memset(&pi, 0, sizeof pi);
        pi.version = PNG_IMAGE_VERSION;
        pi.width = 256;
        pi.height = 200;
        pi.format = PNG_FORMAT_GRAY;
        assert_true(png_image_write_to_memory(&pi, png, &plen, 0, grey, 256, NULL));
        diag_init(&err);
        assert_int_equal(imgload_memory("big.pgm", big, sizeof big - 1, 1000, &b, &err), DIAG_INPUT);
        diag_format(&err, buf, sizeof buf);
        assert_string_equal(buf, "big.pgm: error: 40x30 pixels is over the 1000 this command reads; scale it down");
        diag_init(&err);
        assert_int_equal(imgload_memory("big.png", png, plen, 50000, &b, &err), DIAG_INPUT);
        diag_format(&err, buf, sizeof buf);
        assert_string_equal(buf, "big.png: error: image size 256x200 is over the limit of 32768 per side and 50000 pixels");
    }
    image_free(&a);
    image_free(&b);
}

/* A little-endian TIFF of one IFD whose strip or tile holds 16 zero bytes:
 * tags[] are (tag, type 3 or 4, value) triples in ascending tag order, and
 * the offset tag (273 or 324) gets the data's offset. */
static size_t tiff_build(unsigned char *b, const unsigned long (*tags)[3], int n)
{
    size_t data = 8 + 2 + 12 * (size_t)n + 4, p = 0;
    int i, k;
    memcpy(b, "II*\0\x08\0\0\0", 8);
    p = 8;
    b[p++] = (unsigned char)n;
    b[p++] = 0;
    for (i = 0; i < n; i++) {
        unsigned long v = tags[i][0] == 273 || tags[i][0] == 324 ? data : tags[i][2];
        unsigned char f[12] = {0};
        f[0] = (unsigned char)tags[i][0];
        f[1] = (unsigned char)(tags[i][0] >> 8);
        f[2] = (unsigned char)tags[i][1];
        f[4] = 1;
        for (k = 0; k < (tags[i][1] == 3 ? 2 : 4); k++)
            f[8 + k] = (unsigned char)(v >> (8 * k));
        memcpy(b + p, f, 12);
        p += 12;
    }
    memset(b + p, 0, 4 + 16);
    return p + 4 + 16;
}

/* A TIFF header can describe buffers far larger than its file (65535
 * samples a pixel, 32768x32768 tiles of a 16x16 picture): the reader
 * refuses the layout, by name, before libtiff allocates, and still reads a
 * small one of the same form. */
static void test_compare_tiff_layout_limits(void **state)
{
    static const unsigned long samples[][3] = {
        {256, 4, 16384}, {257, 4, 1}, {258, 3, 8}, {259, 3, 8}, {262, 3, 1},
        {273, 4, 0}, {277, 3, 65535}, {278, 4, 1}, {279, 4, 16}, {284, 3, 1}};
    static const unsigned long tiles[][3] = {
        {256, 4, 16}, {257, 4, 16}, {258, 3, 8}, {259, 3, 32773}, {262, 3, 1}, {277, 3, 1},
        {284, 3, 1}, {322, 4, 32768}, {323, 4, 32768}, {324, 4, 0}, {325, 4, 16}};
    unsigned long small[11][3];
    unsigned char b[256];
    image img;
    diag err;
    char buf[300];
    size_t n;
    (void)state;
    if (!image_tiff_available())
        skip();
    n = tiff_build(b, samples, 10);
    diag_init(&err);
    assert_int_equal(imgload_memory("s.tif", b, n, (size_t)1 << 20, &img, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "s.tif: error: TIFF: 65535 samples of 8 bits a pixel is over the 128 bits this "
                             "command reads");
    n = tiff_build(b, tiles, 11);
    diag_init(&err);
    assert_int_equal(imgload_memory("t.tif", b, n, (size_t)1 << 20, &img, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "t.tif: error: TIFF: 32768x32768 tiles for a 16x16 picture are over 1048576 pixels");
    /* the same picture in 16x16 tiles: PackBits of zero bytes */
    memcpy(small, tiles, sizeof small);
    small[7][2] = small[8][2] = 16;
    n = tiff_build(b, (const unsigned long (*)[3])small, 11);
    diag_init(&err);
    assert_int_equal(imgload_memory("t.tif", b, n, (size_t)1 << 20, &img, &err), 0);
    assert_int_equal(img.width, 16);
    assert_int_equal(img.height, 16);
    image_free(&img);
}

#ifdef IMAGE_HAVE_JPEG
/* A progressive 64x64 JPEG from libjpeg with its last scan repeated `extra`
 * times before the end marker (a valid file, which libjpeg warns of and
 * reads), written to out (room for cap bytes); returns its length. */
static size_t jpeg_repeated_scans(unsigned char *out, size_t cap, int extra)
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr e;
    unsigned char *buf = NULL, row[64 * 3];
    unsigned long len = 0;
    size_t i, last = 0, n = 0;
    int k;
    c.err = jpeg_std_error(&e);
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, &buf, &len);
    c.image_width = c.image_height = 64;
    c.input_components = 3;
    c.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_simple_progression(&c);
    jpeg_start_compress(&c, TRUE);
    for (i = 0; i < 64; i++) {
        for (k = 0; k < 64 * 3; k++)
            row[k] = (unsigned char)(i * 4 + (size_t)k);
        {
            JSAMPROW r = row;
            jpeg_write_scanlines(&c, &r, 1);
        }
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    /* the last start-of-scan marker: its scan runs to the end marker */
    for (i = 0; i + 1 < len; i++)
        if (buf[i] == 0xff && buf[i + 1] == 0xda)
            last = i;
    assert_true(last > 0 && buf[len - 2] == 0xff && buf[len - 1] == 0xd9);
    assert_true(len + (size_t)extra * (len - 2 - last) <= cap);
    memcpy(out, buf, len - 2);
    n = len - 2;
    for (k = 0; k < extra; k++, n += len - 2 - last)
        memcpy(out + n, buf + last, len - 2 - last);
    out[n++] = 0xff;
    out[n++] = 0xd9;
    free(buf);
    return n;
}
#endif

/* A progressive JPEG of more than 500 scans is refused by name; one of
 * 10 + 400 is read. */
static void test_compare_jpeg_scan_limit(void **state)
{
#ifdef IMAGE_HAVE_JPEG
    static unsigned char b[1 << 20];
    image img;
    diag err;
    char buf[300];
    size_t n;
    (void)state;
    n = jpeg_repeated_scans(b, sizeof b, 400);
    diag_init(&err);
    assert_int_equal(imgload_memory("ok.jpg", b, n, (size_t)1 << 20, &img, &err), 0);
    assert_int_equal(img.width, 64);
    image_free(&img);
    n = jpeg_repeated_scans(b, sizeof b, 600);
    diag_init(&err);
    assert_int_equal(imgload_memory("scans.jpg", b, n, (size_t)1 << 20, &img, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "scans.jpg: error: JPEG: more than 500 scans (a progressive JPEG has about 10)");
#else
    (void)state;
    skip();
#endif
}

/* Fails each allocation of a registered comparison with both pictures in
 * turn: every failure is a clean DIAG_IO, and the run after succeeds. */
static void test_compare_oom_sweep(void **state)
{
    uint64_t s = test_seed("test_compare_oom_sweep");
    image render, scan;
    warp_params truth = {1.1, 6.0, 5.0, 1.0};
    compare_opts o;
    compare_result r;
    diag err;
    char diffp[64], sbsp[64];
    long n, total;
    (void)state;
    assert_int_equal(synth_render(0, 48, &render), 0);
    assert_int_equal(synth_scan(0, 48, &truth, 64, 62, 6.0, &s, &scan), 0);
    snprintf(diffp, sizeof diffp, "/tmp/test_compare_%ld_diff.png", (long)getpid());
    snprintf(sbsp, sizeof sbsp, "/tmp/test_compare_%ld_sbs.png", (long)getpid());
    compare_opts_init(&o);
    o.do_register = 1;
    o.align.scale_min = 0.9;
    o.align.scale_max = 1.3;
    o.levels = 1;
    o.descreen = 0.7;
    o.diff_path = diffp;
    o.sbs_path = sbsp;
    mem_fail_after(-1);
    mem_fail_after(1L << 40);
    diag_init(&err);
    assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
    total = mem_alloc_count();
    printf("# %ld allocations\n", total);
    for (n = 0; n < total; n++) {
        mem_fail_after(n);
        diag_init(&err);
        assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), DIAG_IO);
    }
    mem_fail_after(-1);
    diag_init(&err);
    assert_int_equal(compare_images("scan", &scan, "render", &render, &o, &r, &err), 0);
    unlink(diffp);
    unlink(sbsp);
    image_free(&render);
    image_free(&scan);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_compare_warp_inverse),
        cmocka_unit_test(test_compare_register_recovers_scan),
        cmocka_unit_test(test_compare_register_random_placements),
        cmocka_unit_test(test_compare_register_crop_offsets),
        cmocka_unit_test(test_compare_register_halftone_scan),
        cmocka_unit_test(test_compare_ssim_separates_scenes),
        cmocka_unit_test(test_compare_psnr_matches_direct),
        cmocka_unit_test(test_compare_identical_is_perfect),
        cmocka_unit_test(test_compare_ssim_matches_formula),
        cmocka_unit_test(test_compare_levels_undo_fade),
        cmocka_unit_test(test_compare_heat_ramp),
        cmocka_unit_test(test_compare_pnm_formats),
        cmocka_unit_test(test_compare_pnm_errors),
        cmocka_unit_test(test_compare_input_errors),
        cmocka_unit_test(test_compare_tiff_layout_limits),
        cmocka_unit_test(test_compare_jpeg_scan_limit),
        cmocka_unit_test(test_compare_oom_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
