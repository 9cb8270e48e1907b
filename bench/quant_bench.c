/* quant_bench — the 5081 colour table: maprt's median cut (dl_quant)
 * against libimagequant on the same RGB picture, both choosing at most 256
 * colours of the 4096 a 4-bit DAC shows, with and without dithering. Each
 * result is the picture as the 5081 would show it (palette entries snapped
 * to the DAC's levels, every pixel mapped to its table entry) measured
 * against the original with compare (PSNR on R,G,B and SSIM on luma).
 * Usage: quant_bench IN.png   (`make quant-bench QUANT_IN=...`) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <libimagequant.h>
#include "compare/compare.h"
#include "display5080/dl_quant.h"
#include "image/image_png.h"
#include "util/mem.h"

static void quant_bench_report(const char *what, const image *ref, const image *shown)
{
    compare_opts o;
    compare_result r;
    diag err;
    diag_init(&err);
    compare_opts_init(&o);
    if (compare_images("original", ref, what, shown, &o, &r, &err)) {
        diag_print(stderr, &err);
        exit(3);
    }
    {
        /* false colour: the hue error on the near-grey pixels, as the mean
         * |shift| of (R-G, B-G) where the original's guns differ by < 24 */
        size_t i, n = (size_t)ref->width * (size_t)ref->height, grey = 0;
        double shift = 0;
        for (i = 0; i < n; i++) {
            const uint8_t *a = ref->px + 3 * i, *b = shown->px + 3 * i;
            int mx = a[0] > a[1] ? (a[0] > a[2] ? a[0] : a[2]) : (a[1] > a[2] ? a[1] : a[2]);
            int mn = a[0] < a[1] ? (a[0] < a[2] ? a[0] : a[2]) : (a[1] < a[2] ? a[1] : a[2]);
            if (mx - mn < 24) {
                double d1 = (double)((b[0] - b[1]) - (a[0] - a[1])), d2 = (double)((b[2] - b[1]) - (a[2] - a[1]));
                shift += sqrt(d1 * d1 + d2 * d2);
                grey++;
            }
        }
        printf("%-34s psnr=%.3f ssim=%.5f grey_hue_shift=%.2f (%zu near-grey pixels)\n", what, r.psnr, r.ssim,
               grey ? shift / (double)grey : 0, grey);
    }
}

/* The 5081's view of a table and indices. */
static void quant_bench_show(const image *rgb, const uint32_t *table, const uint8_t *index, image *out)
{
    diag err;
    size_t i, n = (size_t)rgb->width * (size_t)rgb->height;
    diag_init(&err);
    if (image_alloc(out, rgb->width, rgb->height, 3, "shown", &err))
        exit(3);
    for (i = 0; i < n; i++) {
        uint32_t c = table[index[i]];
        out->px[3 * i] = (uint8_t)(c >> 16);
        out->px[3 * i + 1] = (uint8_t)(c >> 8);
        out->px[3 * i + 2] = (uint8_t)c;
    }
}

static void quant_bench_median(const image *rgb, int dither)
{
    dl_quant_opts qo;
    dl_quant q;
    image shown;
    diag err;
    char what[64];
    memset(&qo, 0, sizeof qo);
    qo.dac = 4;
    qo.dither = dither;
    diag_init(&err);
    if (dl_quant_image(rgb, &qo, &q, &err)) {
        diag_print(stderr, &err);
        exit(3);
    }
    quant_bench_show(rgb, q.table, q.index, &shown);
    snprintf(what, sizeof what, "median-cut%s (%d colours)", dither ? "+FS" : "", q.ncolours);
    quant_bench_report(what, rgb, &shown);
    image_free(&shown);
    dl_quant_free(&q);
}

static void quant_bench_liq(const image *rgb, double dither, int posterize)
{
    size_t i, n = (size_t)rgb->width * (size_t)rgb->height;
    unsigned char *rgba = malloc(4 * n), *idx = malloc(n);
    liq_attr *a = liq_attr_create();
    liq_image *li;
    liq_result *res = NULL;
    const liq_palette *pal;
    uint32_t table[256];
    image shown;
    char what[64];
    for (i = 0; i < n; i++) {
        memcpy(rgba + 4 * i, rgb->px + 3 * i, 3);
        rgba[4 * i + 3] = 255;
    }
    liq_set_max_colors(a, 256);
    liq_set_speed(a, 1);
    if (posterize)
        liq_set_min_posterization(a, 4);  /* 16 levels a gun, as the DAC */
    liq_set_quality(a, 0, 100);
    li = liq_image_create_rgba(a, rgba, rgb->width, rgb->height, 0);
    if (!li || liq_image_quantize(li, a, &res) != LIQ_OK) {
        fprintf(stderr, "quant_bench: libimagequant failed\n");
        exit(3);
    }
    liq_set_dithering_level(res, (float)dither);
    liq_write_remapped_image(res, li, idx, n);
    pal = liq_get_palette(res);
    for (i = 0; i < pal->count; i++)
        table[i] = (uint32_t)dl_quant_gun(pal->entries[i].r, 4) << 16
                   | (uint32_t)dl_quant_gun(pal->entries[i].g, 4) << 8 | dl_quant_gun(pal->entries[i].b, 4);
    quant_bench_show(rgb, table, idx, &shown);
    snprintf(what, sizeof what, "libimagequant%s%s (%u colours)", posterize ? "/p4" : "", dither > 0 ? "+dither" : "",
             pal->count);
    quant_bench_report(what, rgb, &shown);
    image_free(&shown);
    liq_result_destroy(res);
    liq_image_destroy(li);
    liq_attr_destroy(a);
    free(rgba);
    free(idx);
}

int main(int argc, char **argv)
{
    image rgb;
    diag err;
    diag_init(&err);
    if (argc != 2) {
        fprintf(stderr, "usage: quant_bench IN.png\n");
        return 2;
    }
    if (image_read_png(argv[1], 3, &rgb, &err)) {
        diag_print(stderr, &err);
        return 1;
    }
    printf("%s: %dx%d, 256 of the 4096 colours of a 4-bit DAC\n", argv[1], rgb.width, rgb.height);
    quant_bench_median(&rgb, 0);
    quant_bench_liq(&rgb, 0, 0);
    quant_bench_liq(&rgb, 0, 1);
    quant_bench_median(&rgb, 1);
    quant_bench_liq(&rgb, 1.0, 0);
    quant_bench_liq(&rgb, 1.0, 1);
    image_free(&rgb);
    return 0;
}
