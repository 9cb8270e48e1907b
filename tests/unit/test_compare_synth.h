/* test_compare_synth — synthetic pictures for the compare tests: a "render"
 * (discs, bars, a gradient and a CG-like mark, asymmetric so flips and
 * turns show) and a "scan" of it (grey, scaled, shifted, turned, blurred,
 * noisy, inside paper margins; synth_halftone adds a dot screen), made
 * with an independent forward mapping so the registration has a known
 * answer. */
#ifndef TEST_COMPARE_SYNTH_H
#define TEST_COMPARE_SYNTH_H
#include <math.h>
#include <stdint.h>
#include "image/image.h"
#include "compare/plane.h"
#include "compare/warp.h"
#include "support.h"

/* Colour of scene `which` (0 = the figure, 1 = a different scene) at
 * continuous position (x,y) in a size x size picture; rgb in 0..255. */
static void synth_color(int which, int size, double x, double y, double rgb[3])
{
    double u = x / size, v = y / size, dx, dy;
    rgb[0] = 40 + 60 * u;
    rgb[1] = 50 + 40 * v;
    rgb[2] = 90;
    if (which == 0) {
        dx = u - 0.36; dy = v - 0.40;
        if (dx * dx + dy * dy < 0.22 * 0.22) { rgb[0] = 200; rgb[1] = 180; rgb[2] = 60; }
        dx = u - 0.36; dy = v - 0.40;
        if (dx * dx + dy * dy < 0.12 * 0.12 && !(dx > 0.04 && fabs(dy) < 0.05)) { rgb[0] = 30; rgb[1] = 30; rgb[2] = 160; }
        if (u > 0.66 && u < 0.78 && v > 0.15 && v < 0.85) { rgb[0] = 230; rgb[1] = 40; rgb[2] = 40; }
        if (u > 0.66 && u < 0.92 && v > 0.15 && v < 0.25) { rgb[0] = 230; rgb[1] = 40; rgb[2] = 40; }
        if (u > 0.66 && u < 0.86 && v > 0.45 && v < 0.53) { rgb[0] = 230; rgb[1] = 40; rgb[2] = 40; }
        if (v > 0.74 && v < 0.9 && u > 0.1 && u < 0.55 && fmod(u * 20, 2) < 1) { rgb[0] = 240; rgb[1] = 240; rgb[2] = 240; }
    } else {
        dx = u - 0.7; dy = v - 0.65;
        if (dx * dx + dy * dy < 0.2 * 0.2) { rgb[0] = 60; rgb[1] = 200; rgb[2] = 80; }
        if (u > 0.1 && u < 0.45 && v > 0.1 && v < 0.3) { rgb[0] = 220; rgb[1] = 220; rgb[2] = 30; }
        if (fabs(u - v) < 0.04 && u < 0.5) { rgb[0] = 250; rgb[1] = 250; rgb[2] = 250; }
    }
}

/* A size x size RGB render of scene `which`, 4x4 supersampled. */
static int synth_render(int which, int size, image *out)
{
    int i, j, a, b, c;
    diag d;
    diag_init(&d);
    if (image_alloc(out, size, size, 3, "synth", &d))
        return -1;
    for (j = 0; j < size; j++)
        for (i = 0; i < size; i++) {
            double acc[3] = {0, 0, 0}, rgb[3];
            for (b = 0; b < 4; b++)
                for (a = 0; a < 4; a++) {
                    synth_color(which, size, i + (a + 0.5) / 4, j + (b + 0.5) / 4, rgb);
                    for (c = 0; c < 3; c++)
                        acc[c] += rgb[c] / 16;
                }
            for (c = 0; c < 3; c++)
                out->px[((size_t)j * size + i) * 3 + c] = (uint8_t)(acc[c] + 0.5);
        }
    return 0;
}

/* A grey "scan" (w x h) of scene `which` rendered at size `size`, placed by
 * p (warp.h convention: render pixel -> scan pixel), faded to a contrast of
 * 0.7 on paper tone 235, blurred by sigma 1 (by supersampling a disc of
 * radius ~1.5 px), with uniform noise of +-noise levels. */
static int synth_scan(int which, int size, const warp_params *p, int w, int h, double noise,
                      uint64_t *rng, image *out)
{
    int i, j, a, b;
    diag d;
    diag_init(&d);
    if (image_alloc(out, w, h, 1, "scan", &d))
        return -1;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            double acc = 0, rgb[3];
            int n = 0;
            for (b = -3; b <= 3; b++)
                for (a = -3; a <= 3; a++) {
                    double xs = i + 0.5 + a * 0.5, ys = j + 0.5 + b * 0.5, xt, yt, y;
                    if (a * a + b * b > 10)
                        continue;
                    warp_to_test(p, xs, ys, &xt, &yt);
                    if (xt >= 0 && yt >= 0 && xt < size && yt < size) {
                        synth_color(which, size, xt, yt, rgb);
                        y = PLANE_LUMA_R * rgb[0] + PLANE_LUMA_G * rgb[1] + PLANE_LUMA_B * rgb[2];
                        y = 235 - 0.7 * (255 - y);
                    } else {
                        y = 235;
                    }
                    acc += y;
                    n++;
                }
            acc = acc / n + test_uniform(rng, -noise, noise);
            out->px[(size_t)j * w + i] = (uint8_t)(acc < 0 ? 0 : acc > 255 ? 255 : acc + 0.5);
        }
    return 0;
}

/* Prints a grey scan with a 45-degree dot screen of the given period in
 * pixels: each pixel becomes ink (20) or paper (235), as in a print. */
static void synth_halftone(image *scan, double period)
{
    int x, y;
    double k = 3.14159265358979323846 / (period * 1.4142135623730951);
    for (y = 0; y < scan->height; y++)
        for (x = 0; x < scan->width; x++) {
            uint8_t *p = &scan->px[(size_t)y * scan->width + x];
            double screen = 127.5 + 63.75 * (cos((x + y) * k) + cos((x - y) * k));
            *p = *p > screen ? 235 : 20;
        }
}
#endif
