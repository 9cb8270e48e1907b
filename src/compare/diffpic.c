/* diffpic — heat map and side-by-side pictures of a comparison (see diffpic.h). */
#include "compare/diffpic.h"
#include <math.h>
#include <string.h>

static uint8_t diffpic_byte(double v) { return (uint8_t)(v <= 0 ? 0 : v >= 255 ? 255 : v + 0.5); }

/* The heat ramp: d in 8-bit units to RGB. */
static void diffpic_ramp(double d, uint8_t rgb[3])
{
    static const double stop[5][3] = {{0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}};
    double t = d / 32.0;
    int k, c;
    if (t >= 4) {
        rgb[0] = rgb[1] = rgb[2] = 255;
        return;
    }
    k = (int)t;
    t -= k;
    for (c = 0; c < 3; c++)
        rgb[c] = diffpic_byte(stop[k][c] + t * (stop[k + 1][c] - stop[k][c]));
}

int diffpic_heat(const plane *ref, const plane *test, int nch, const plane *mask, image *out, diag *err)
{
    image img;
    size_t i, n;
    if (image_alloc(&img, ref[0].w, ref[0].h, 3, "diff picture", err))
        return err->status;
    n = (size_t)img.width * (size_t)img.height;
    for (i = 0; i < n; i++) {
        uint8_t *px = img.px + i * 3;
        double worst = 0;
        int c;
        if (mask && !(mask->v[i] > 0)) {
            px[0] = px[1] = px[2] = 64;
            continue;
        }
        for (c = 0; c < nch; c++) {
            double d = fabs((double)ref[c].v[i] - (double)test[c].v[i]);
            worst = d > worst ? d : worst;
        }
        diffpic_ramp(worst, px);
    }
    *out = img;
    return 0;
}

/* Writes pixel i of the planes (grey or RGB) to px. */
static void diffpic_put(const plane *p, int nch, size_t i, uint8_t *px)
{
    int c;
    for (c = 0; c < 3; c++)
        px[c] = diffpic_byte(p[nch == 3 ? c : 0].v[i]);
}

int diffpic_side_by_side(const plane *ref, const plane *test, int nch, const plane *mask, image *out,
                         diag *err)
{
    image img;
    int w = ref[0].w, h = ref[0].h, x, y;
    if (w > (IMAGE_MAX_SIDE - 2 * DIFFPIC_GAP) / 3)
        return diag_at(err, DIAG_INPUT, "side-by-side picture", 0, 0, "a %d pixel wide reference is too wide for three panels", w);
    if (image_alloc(&img, 3 * w + 2 * DIFFPIC_GAP, h, 3, "side-by-side picture", err))
        return err->status;
    memset(img.px, 255, (size_t)img.width * (size_t)h * 3);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            uint8_t *row = img.px + (size_t)y * img.width * 3;
            int covered = !mask || mask->v[i] > 0;
            int check = ((x / DIFFPIC_CHECK) + (y / DIFFPIC_CHECK)) & 1;
            diffpic_put(ref, nch, i, row + (size_t)x * 3);
            if (covered)
                diffpic_put(test, nch, i, row + (size_t)(w + DIFFPIC_GAP + x) * 3);
            else
                memset(row + (size_t)(w + DIFFPIC_GAP + x) * 3, 128, 3);
            diffpic_put(check && covered ? test : ref, nch, i, row + (size_t)(2 * (w + DIFFPIC_GAP) + x) * 3);
        }
    *out = img;
    return 0;
}
