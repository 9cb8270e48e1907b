/* dl_image — RGB frame to DL5080 (see dl_image.h). */
#include "display5080/dl_image.h"
#include "display5080/dl_encode.h"
#include "display5080/dl_quant.h"
#include "image/image_diff.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <math.h>
#include <string.h>

#define DL_IMAGE_CHUNK 16382   /* points per polyline element: (65534 - 4) / 4 */

/* One row (device y) of indices: trims the background, then runs or a block. */
static void dl_image_row(dl_encoder *enc, int y, const uint8_t *row, int w, unsigned bg,
                         unsigned *runs, dl_image_stats *st)
{
    int a = 0, b = w - 1, x;
    size_t nr = 0;
    while (a < w && row[a] == bg) a++;
    while (b >= a && row[b] == bg) b--;
    if (a > b)
        return;
    for (x = a; x <= b; x++) {
        if (x == a || row[x] != row[x - 1]) {
            runs[2 * nr] = 0;
            runs[2 * nr + 1] = row[x];
            nr++;
        }
        runs[2 * nr - 2]++;
    }
    if (dl_encode_run_row_size(nr) <= dl_encode_blt_size(b - a + 1, 1)) {
        dl_encode_run_row(enc, y, a, runs, nr);
        st->run_rows++;
    } else {
        dl_encode_blt(enc, a, y, b - a + 1, 1, 4, row + a, (size_t)w);
        st->blt_rows++;
    }
}

int dl_image_encode_indexed(int width, int height, const uint8_t *index, const uint32_t *table,
                            int ncolours, unsigned flags, const dl_image_polyline *lines,
                            const int *line_index, size_t nlines, uint8_t **out, size_t *len,
                            dl_image_stats *stats, diag *err)
{
    dl_encoder enc;
    dl_image_stats st;
    size_t hist[256] = {0}, n = (size_t)width * (size_t)height, i, l;
    unsigned bg = 0, *runs;
    int y;
    memset(&st, 0, sizeof st);
    if (width < 1 || height < 1 || width > DL_MAX_SIDE || height > DL_MAX_SIDE)
        return diag_at(err, DIAG_INPUT, "dl5080", 0, 0, "image size %dx%d is outside 1..%d",
                       width, height, DL_MAX_SIDE);
    if (ncolours < 1 || ncolours > 256)
        return diag_at(err, DIAG_INPUT, "dl5080", 0, 0, "%d colours is outside 1..256", ncolours);
    runs = mem_alloc(2 * sizeof *runs * (size_t)width);
    if (!runs)
        return diag_at(err, DIAG_IO, "dl5080", 0, 0, "out of memory");
    for (i = 0; i < n; i++)
        hist[index[i]]++;
    for (i = 1; i < 256; i++)
        if (hist[i] > hist[bg])
            bg = (unsigned)i;
    dl_encode_init(&enc, width, height, flags);
    dl_encode_colours(&enc, 0, table, (size_t)ncolours);
    dl_encode_word(&enc, DL_CLEAR, bg);
    for (y = 0; y < height && !enc.status; y++)
        dl_image_row(&enc, y, index + (size_t)(height - 1 - y) * (size_t)width, width, bg, runs, &st);
    mem_free(runs);
    for (l = 0; l < nlines && !enc.status; l++) {
        const dl_image_polyline *p = &lines[l];
        size_t start;
        if (p->n == 0)
            continue;
        dl_encode_word(&enc, DL_LINE_COLOUR, (unsigned)line_index[l]);
        if (p->n == 1) {
            int two[4] = {p->xy[0], p->xy[1], p->xy[0], p->xy[1]};
            dl_encode_points(&enc, DL_POLYLINE, two, 2);
            continue;
        }
        for (start = 0; start + 1 < p->n; start += DL_IMAGE_CHUNK - 1) {
            size_t k = p->n - start < DL_IMAGE_CHUNK ? p->n - start : DL_IMAGE_CHUNK;
            dl_encode_points(&enc, DL_POLYLINE, p->xy + 2 * start, k);
        }
    }
    dl_encode_simple(&enc, DL_END);
    if (dl_encode_finish(&enc, "dl5080", out, len, err))
        return err->status;
    st.colours = ncolours;
    st.bytes = *len;
    if (stats)
        *stats = st;
    return 0;
}

/* PSNR of rgb against the quantised frame as the 5081 shows it (1e9 when
 * identical); DIAG_IO when memory runs out. */
static int dl_image_psnr(const image *rgb, const dl_quant *q, double *psnr, diag *err)
{
    size_t n = (size_t)rgb->width * (size_t)rgb->height, i;
    image shown;
    image_diff_stats d;
    int c;
    if (image_alloc(&shown, rgb->width, rgb->height, 3, "display list", err))
        return err->status;
    for (i = 0; i < n; i++) {
        uint32_t t = q->table[q->index[i]];
        for (c = 0; c < 3; c++)
            shown.px[3 * i + c] = (uint8_t)((t >> (16 - 8 * c)) & 0xFFu);
    }
    image_diff(rgb, &shown, 0, &d);
    image_free(&shown);
    *psnr = d.mse > 0 ? d.psnr : 1e9;
    return 0;
}

int dl_image_encode(const image *rgb, const dl_image_opts *opts, uint8_t **out, size_t *len,
                    dl_image_stats *stats, diag *err)
{
    dl_image_opts def;
    dl_quant_opts qo;
    dl_quant q;
    dl_image_stats st;
    uint32_t fixed[256];
    int *line_index = NULL, rc;
    size_t l, k;
    memset(&def, 0, sizeof def);
    if (!opts)
        opts = &def;
    memset(&qo, 0, sizeof qo);
    memset(&st, 0, sizeof st);
    qo.dac = opts->dac ? opts->dac : 4;
    qo.dither = opts->dither;
    if (qo.dac != 4 && qo.dac != 8)
        return diag_at(err, DIAG_INPUT, "dl5080", 0, 0, "DAC of %d bits (4 or 8)", opts->dac);
    if (rgb->channels != 3 || rgb->width > DL_MAX_SIDE || rgb->height > DL_MAX_SIDE)
        return diag_at(err, DIAG_INPUT, "dl5080", 0, 0,
                       "needs an RGB image of at most %dx%d, not %dx%d", DL_MAX_SIDE, DL_MAX_SIDE,
                       rgb->width, rgb->height);
    for (l = 0; l < opts->npolylines; l++) {
        uint32_t c = (uint32_t)opts->polylines[l].r << 16 | (uint32_t)opts->polylines[l].g << 8 |
                     opts->polylines[l].b;
        for (k = 0; k < 2 * opts->polylines[l].n; k++)
            if (opts->polylines[l].xy[k] < -32768 || opts->polylines[l].xy[k] > 32767)
                return diag_at(err, DIAG_INPUT, "dl5080", 0, 0,
                               "polyline %zu: coordinate %d is outside -32768..32767", l,
                               opts->polylines[l].xy[k]);
        for (k = 0; k < (size_t)qo.nfixed && fixed[k] != c; k++)
            ;
        if (k == (size_t)qo.nfixed) {
            if (qo.nfixed == 255)
                return diag_at(err, DIAG_INPUT, "dl5080", 0, 0, "more than 255 wireframe colours");
            fixed[qo.nfixed++] = c;
        }
    }
    qo.fixed = fixed;
    if (opts->npolylines) {
        line_index = mem_alloc(opts->npolylines * sizeof *line_index);
        if (!line_index)
            return diag_at(err, DIAG_IO, "dl5080", 0, 0, "out of memory");
    }
    if ((rc = dl_quant_image(rgb, &qo, &q, err))) {
        mem_free(line_index);
        return rc;
    }
    for (l = 0; l < opts->npolylines; l++) {
        uint32_t c = (uint32_t)opts->polylines[l].r << 16 | (uint32_t)opts->polylines[l].g << 8 |
                     opts->polylines[l].b;
        for (k = 0; fixed[k] != c; k++)
            ;
        line_index[l] = q.fixed_index[k];
    }
    rc = dl_image_encode_indexed(rgb->width, rgb->height, q.index, q.table, q.ncolours,
                                 qo.dac == 8 ? DL_FLAG_DAC8 : 0, opts->polylines, line_index,
                                 opts->npolylines, out, len, &st, err);
    if (!rc && (rc = dl_image_psnr(rgb, &q, &st.psnr, err)) != 0) {
        mem_free(*out);
        *out = NULL;
    }
    dl_quant_free(&q);
    mem_free(line_index);
    if (!rc && stats)
        *stats = st;
    return rc;
}

int dl_image_write(const char *path, const image *rgb, const dl_image_opts *opts,
                   dl_image_stats *stats, diag *err)
{
    uint8_t *buf;
    size_t len;
    diag e2;
    int rc;
    diag_init(&e2);
    if ((rc = dl_image_encode(rgb, opts, &buf, &len, stats, &e2))) {
        diag_at(err, rc, path, 0, 0, "%s", e2.msg);
        return rc;
    }
    rc = outfile_write_all(path, buf, len, err);
    mem_free(buf);
    return rc;
}
