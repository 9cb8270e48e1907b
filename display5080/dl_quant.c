/* dl_quant — median cut and nearest-colour mapping (see dl_quant.h).
 * Colours are keyed in DAC space: 12-bit keys for a 4-bit DAC, 24-bit keys
 * for an 8-bit one; the histogram is the sorted list of distinct keys. */
#include "display5080/dl_quant.h"
#include "util/mem.h"
#include <stdlib.h>
#include <string.h>

typedef struct dl_qentry {
    uint32_t rgb;              /* shown colour 0x00RRGGBB */
    uint32_t count;
} dl_qentry;

uint8_t dl_quant_gun(unsigned v, int dac)
{
    return dac == 4 ? (uint8_t)(((v * 15u + 127u) / 255u) * 17u) : (uint8_t)v;
}

/* The DAC colour shown for rgb. An 8-bit DAC shows it as it is. A 4-bit one
 * has 16 levels a gun: rounding each gun on its own gives the nearest
 * colour, but on a near-grey colour (guns within DL_QUANT_GREY of each
 * other) the three roundings fall at different brightnesses, so a smooth
 * grey-blue gradient comes out in bands of teal and pink. There, of the
 * eight DAC colours around rgb, the one with the least
 *   |e|^2 + 0.4 |c|^2
 * is taken: e the error, c = (eR - eG, eB - eG) its chroma. Less hue error
 * costs brightness error, which SSIM sees: these weights are the least
 * hue penalty that leaves no teal or pink band on fig1's floor, at a PSNR
 * still above libimagequant's and an SSIM 0.004 below it (docs/dl5080.md,
 * "The colour table", has the trade-off). */
#define DL_QUANT_GREY 32
static uint32_t dl_quant_snap(uint32_t rgb, int dac)
{
    int t[3], lo[3], c, k, mx, mn;
    long long best = -1;
    uint32_t out = 0;
    if (dac != 4)
        return rgb & 0xFFFFFFu;
    for (c = 0; c < 3; c++) {
        t[c] = (int)((rgb >> (16 - 8 * c)) & 0xFFu);
        lo[c] = t[c] / 17;
    }
    mx = t[0] > t[1] ? (t[0] > t[2] ? t[0] : t[2]) : (t[1] > t[2] ? t[1] : t[2]);
    mn = t[0] < t[1] ? (t[0] < t[2] ? t[0] : t[2]) : (t[1] < t[2] ? t[1] : t[2]);
    if (mx - mn >= DL_QUANT_GREY)
        return (uint32_t)dl_quant_gun((unsigned)t[0], 4) << 16 | (uint32_t)dl_quant_gun((unsigned)t[1], 4) << 8 |
               dl_quant_gun((unsigned)t[2], 4);
    for (k = 0; k < 8; k++) {
        long long e[3], c1, c2, cost;
        int q[3];
        for (c = 0; c < 3; c++) {
            q[c] = lo[c] + ((k >> c) & 1);
            if (q[c] > 15)
                q[c] = 15;
            e[c] = 17LL * q[c] - t[c];
        }
        c1 = e[0] - e[1];
        c2 = e[2] - e[1];
        /* 5 x (|e|^2 + 0.4 |c|^2), in integers */
        cost = 5 * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) + 2 * (c1 * c1 + c2 * c2);
        if (best < 0 || cost < best) {
            best = cost;
            out = (uint32_t)(17 * q[0]) << 16 | (uint32_t)(17 * q[1]) << 8 | (uint32_t)(17 * q[2]);
        }
    }
    return out;
}

static int dl_quant_u32_cmp(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Entry orders by one channel (qsort has no context argument). */
#define DL_QUANT_CMP(name, shift)                                   \
    static int name(const void *a, const void *b)                   \
    {                                                               \
        unsigned x = (((const dl_qentry *)a)->rgb >> (shift)) & 0xFFu; \
        unsigned y = (((const dl_qentry *)b)->rgb >> (shift)) & 0xFFu; \
        return (x > y) - (x < y);                                   \
    }
DL_QUANT_CMP(dl_quant_cmp_r, 16)
DL_QUANT_CMP(dl_quant_cmp_g, 8)
DL_QUANT_CMP(dl_quant_cmp_b, 0)

static int dl_quant_rgb_cmp(const void *a, const void *b)
{
    return dl_quant_u32_cmp(&((const dl_qentry *)a)->rgb, &((const dl_qentry *)b)->rgb);
}

typedef struct dl_qbox {
    size_t lo, hi;             /* entries [lo, hi) */
    unsigned long long count;
    int axis;                  /* shift of the longest channel */
    unsigned range;
} dl_qbox;

static void dl_quant_measure(const dl_qentry *e, dl_qbox *b)
{
    unsigned mn[3] = {255, 255, 255}, mx[3] = {0, 0, 0}, c;
    size_t i;
    b->count = 0;
    for (i = b->lo; i < b->hi; i++) {
        b->count += e[i].count;
        for (c = 0; c < 3; c++) {
            unsigned v = (e[i].rgb >> (16 - 8 * c)) & 0xFFu;
            if (v < mn[c]) mn[c] = v;
            if (v > mx[c]) mx[c] = v;
        }
    }
    b->range = 0;
    b->axis = 16;
    for (c = 0; c < 3; c++)
        if (mx[c] >= mn[c] && mx[c] - mn[c] > b->range) {
            b->range = mx[c] - mn[c];
            b->axis = 16 - 8 * (int)c;
        }
}

/* Median cut of entries into at most nbox boxes; writes box means to out. */
static int dl_quant_cut(dl_qentry *e, size_t n, int nbox, int dac, uint32_t *out, dl_qbox *box)
{
    int nb = 1, i;
    box[0].lo = 0;
    box[0].hi = n;
    dl_quant_measure(e, &box[0]);
    while (nb < nbox) {
        int best = -1;
        unsigned long long bestp = 0, half, acc = 0;
        size_t k;
        for (i = 0; i < nb; i++) {
            unsigned long long p = box[i].count * box[i].range;
            if (box[i].hi - box[i].lo > 1 && p > bestp) {
                bestp = p;
                best = i;
            }
        }
        if (best < 0)
            break;
        qsort(e + box[best].lo, box[best].hi - box[best].lo, sizeof *e,
              box[best].axis == 16 ? dl_quant_cmp_r : box[best].axis == 8 ? dl_quant_cmp_g
                                                                           : dl_quant_cmp_b);
        half = box[best].count / 2;
        for (k = box[best].lo; k + 1 < box[best].hi; k++) {
            acc += e[k].count;
            if (acc >= half)
                break;
        }
        if (k + 1 >= box[best].hi)   /* the last colour holds over half: cut before it */
            k = box[best].hi - 2;
        box[nb].lo = k + 1;
        box[nb].hi = box[best].hi;
        box[best].hi = k + 1;
        dl_quant_measure(e, &box[best]);
        dl_quant_measure(e, &box[nb]);
        nb++;
    }
    for (i = 0; i < nb; i++) {
        unsigned long long s[3] = {0, 0, 0};
        size_t k;
        unsigned c;
        uint32_t rgb = 0;
        for (k = box[i].lo; k < box[i].hi; k++)
            for (c = 0; c < 3; c++)
                s[c] += (unsigned long long)((e[k].rgb >> (16 - 8 * c)) & 0xFFu) * e[k].count;
        for (c = 0; c < 3; c++)
            rgb |= (uint32_t)((s[c] + box[i].count / 2) / box[i].count) << (16 - 8 * c);
        out[i] = dl_quant_snap(rgb, dac);
    }
    return nb;
}

/* Nearest table entry to (r,g,b) by squared distance; lowest index on ties. */
static int dl_quant_nearest(const uint32_t *t, int n, int r, int g, int b)
{
    int i, best = 0;
    long bd = -1;
    for (i = 0; i < n; i++) {
        long dr = (long)((t[i] >> 16) & 0xFF) - r, dg = (long)((t[i] >> 8) & 0xFF) - g,
             db = (long)(t[i] & 0xFF) - b, d = dr * dr + dg * dg + db * db;
        if (bd < 0 || d < bd) {
            bd = d;
            best = i;
            if (d == 0)
                break;
        }
    }
    return best;
}

static int dl_quant_add(dl_quant *q, uint32_t rgb)
{
    int i;
    for (i = 0; i < q->ncolours; i++)
        if (q->table[i] == rgb)
            return i;
    q->table[q->ncolours] = rgb;
    return q->ncolours++;
}

/* Floyd-Steinberg over the shown colours of the table. */
static void dl_quant_dither(const image *rgb, dl_quant *q, int dac, float *err)
{
    int w = rgb->width, h = rgb->height, x, y, c;
    float *cur = err, *next = err + 3 * (size_t)(w + 2);
    memset(err, 0, sizeof(float) * 6 * (size_t)(w + 2));
    for (y = 0; y < h; y++) {
        const uint8_t *p = rgb->px + (size_t)y * (size_t)w * 3;
        for (x = 0; x < w; x++) {
            float v[3];
            uint32_t s = 0;
            int k;
            for (c = 0; c < 3; c++) {
                v[c] = p[3 * x + c] + cur[3 * (x + 1) + c];
                s |= (uint32_t)(v[c] < 0 ? 0 : v[c] > 255 ? 255 : (int)(v[c] + 0.5f)) << (16 - 8 * c);
            }
            s = dl_quant_snap(s, dac);
            k = dl_quant_nearest(q->table, q->ncolours, (int)(s >> 16), (int)((s >> 8) & 0xFF), (int)(s & 0xFF));
            q->index[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)k;
            for (c = 0; c < 3; c++) {
                float e = v[c] - (float)((q->table[k] >> (16 - 8 * c)) & 0xFFu);
                cur[3 * (x + 2) + c] += e * 7.0f / 16;
                next[3 * x + c] += e * 3.0f / 16;
                next[3 * (x + 1) + c] += e * 5.0f / 16;
                next[3 * (x + 2) + c] += e * 1.0f / 16;
            }
        }
        {
            float *t = cur;
            cur = next;
            next = t;
            memset(next, 0, sizeof(float) * 3 * (size_t)(w + 2));
        }
    }
}

int dl_quant_image(const image *rgb, const dl_quant_opts *opts, dl_quant *q, diag *err)
{
    size_t n = (size_t)rgb->width * (size_t)rgb->height, i, m = 0;
    uint32_t *keys = NULL, table[256];
    dl_qentry *ent = NULL;
    dl_qbox *box = NULL;
    float *ferr = NULL;
    int dac = opts->dac, k, nb;
    if (rgb->channels != 3 || (dac != 4 && dac != 8) || opts->nfixed < 0 || opts->nfixed > 255)
        return diag_at(err, DIAG_INPUT, "quantise", 0, 0,
                       "needs an RGB image, a DAC of 4 or 8 bits and at most 255 fixed colours");
    memset(q, 0, sizeof *q);
    keys = mem_alloc(n * sizeof *keys);
    q->index = mem_alloc(n);
    box = mem_alloc(256 * sizeof *box);
    if (!keys || !q->index || !box)
        goto oom;
    for (i = 0; i < n; i++) {
        const uint8_t *p = rgb->px + 3 * i;
        keys[i] = dl_quant_snap((uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2], dac);
    }
    for (k = 0; k < opts->nfixed; k++)
        q->fixed_index[k] = dl_quant_add(q, dl_quant_snap(opts->fixed[k] & 0xFFFFFFu, dac));
    /* histogram: distinct shown colours with counts */
    {
        uint32_t *sorted = mem_alloc(n * sizeof *sorted);
        if (!sorted)
            goto oom;
        memcpy(sorted, keys, n * sizeof *sorted);
        qsort(sorted, n, sizeof *sorted, dl_quant_u32_cmp);
        for (i = 0; i < n; i++)
            if (i == 0 || sorted[i] != sorted[i - 1])
                m++;
        ent = mem_alloc(m * sizeof *ent);
        if (!ent) {
            mem_free(sorted);
            goto oom;
        }
        m = 0;
        for (i = 0; i < n; i++) {
            if (i == 0 || sorted[i] != sorted[i - 1]) {
                ent[m].rgb = sorted[i];
                ent[m++].count = 0;
            }
            ent[m - 1].count++;
        }
        mem_free(sorted);
    }
    if (m + (size_t)q->ncolours <= 256) {
        for (i = 0; i < m; i++)
            dl_quant_add(q, ent[i].rgb);
    } else {
        nb = dl_quant_cut(ent, m, 256 - q->ncolours, dac, table, box);
        for (k = 0; k < nb; k++)
            dl_quant_add(q, table[k]);
        qsort(ent, m, sizeof *ent, dl_quant_rgb_cmp);   /* the cut reordered it */
    }
    if (opts->dither) {
        ferr = mem_alloc(sizeof(float) * 6 * ((size_t)rgb->width + 2));
        if (!ferr)
            goto oom;
        dl_quant_dither(rgb, q, dac, ferr);
    } else {
        /* map each distinct colour once, then each pixel by binary search */
        uint8_t *map;
        if (!(map = mem_alloc(m)))
            goto oom;
        for (i = 0; i < m; i++)
            map[i] = (uint8_t)dl_quant_nearest(q->table, q->ncolours, (int)(ent[i].rgb >> 16),
                                               (int)((ent[i].rgb >> 8) & 0xFF), (int)(ent[i].rgb & 0xFF));
        for (i = 0; i < n; i++) {
            size_t lo = 0, hi = m;
            while (hi - lo > 1) {
                size_t mid = (lo + hi) / 2;
                if (ent[mid].rgb <= keys[i]) lo = mid; else hi = mid;
            }
            q->index[i] = map[lo];
        }
        mem_free(map);
    }
    mem_free(keys);
    mem_free(ent);
    mem_free(box);
    mem_free(ferr);
    return 0;
oom:
    mem_free(keys);
    mem_free(ent);
    mem_free(box);
    mem_free(ferr);
    dl_quant_free(q);
    return diag_at(err, DIAG_IO, "quantise", 0, 0, "out of memory for a %dx%d image",
                   rgb->width, rgb->height);
}

void dl_quant_free(dl_quant *q)
{
    mem_free(q->index);
    q->index = NULL;
}
