/* image_png_write — banded, threaded PNG encoding (see image_png_write.h).
 * Format: PNG (ISO/IEC 15948, RFC 2083): signature, IHDR, sRGB, IDAT, IEND;
 * the IDAT data is one zlib stream (RFC 1950) of raw deflate bands (RFC
 * 1951) each ended by an empty stored block (as a sync flush ends it), the
 * last by the final block, followed by the Adler-32 of all filtered bytes. */
#include "image/image_png_write.h"
#include "util/mem.h"
#include <omp.h>
#include <stdint.h>
#include <string.h>
#include <libdeflate.h>
#include <zlib.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

typedef struct image_png_write_band {
    unsigned char *buf;
    size_t len, cap;
    uint32_t adler;            /* Adler-32 of this band's filtered bytes */
    size_t raw;                /* filtered bytes in this band */
    int failed;
} image_png_write_band;

/* The Paeth predictor of x from its left (a), upper (b) and upper-left
 * (c) neighbours (PNG specification, 9.4), in bytes so that the loops
 * vectorise 16 to a register: with pa = |b - c| and pb = |a - c|, the
 * third distance pc = |a + b - 2c| is pa + pb (no smaller than either)
 * when a and b lie on one side of c, else |pa - pb|. */
static inline unsigned char image_png_write_paeth(unsigned char a, unsigned char b, unsigned char c)
{
    unsigned char pa = (unsigned char)(b > c ? b - c : c - b), pb = (unsigned char)(a > c ? a - c : c - a);
    unsigned char pc = (unsigned char)(pa > pb ? pa - pb : pb - pa);
    int one_side = (a >= c) == (b >= c);
    return (pa <= pb) & (one_side | (pa <= pc)) ? a : (one_side | (pb <= pc)) ? b : c;
}

/* (a + b) / 2 rounded down, in bytes. */
static inline unsigned char image_png_write_avg(unsigned char a, unsigned char b)
{
    return (unsigned char)((a & b) + ((a ^ b) >> 1));
}

/* |v| of a filtered byte read as signed: the smaller of v and -v mod 256. */
static inline unsigned image_png_write_mag(unsigned char v)
{
    unsigned char w = (unsigned char)-v;
    return v < w ? v : w;
}

#if defined(__SSE2__)
/* image_png_write_paeth on 16 bytes: pa = |b - c|, pb = |a - c| and
 * pc = |pa - pb| by saturating differences, the comparisons of unsigned
 * bytes by their minima and maxima. */
static inline __m128i image_png_write_paeth16(__m128i a, __m128i b, __m128i c)
{
    __m128i pa = _mm_or_si128(_mm_subs_epu8(b, c), _mm_subs_epu8(c, b));
    __m128i pb = _mm_or_si128(_mm_subs_epu8(a, c), _mm_subs_epu8(c, a));
    __m128i pc = _mm_or_si128(_mm_subs_epu8(pa, pb), _mm_subs_epu8(pb, pa));
    __m128i a_ge = _mm_cmpeq_epi8(_mm_max_epu8(a, c), a), b_ge = _mm_cmpeq_epi8(_mm_max_epu8(b, c), b);
    __m128i one_side = _mm_cmpeq_epi8(a_ge, b_ge);
    __m128i pa_le_pb = _mm_cmpeq_epi8(_mm_min_epu8(pa, pb), pa);
    __m128i pa_le_pc = _mm_cmpeq_epi8(_mm_min_epu8(pa, pc), pa);
    __m128i pb_le_pc = _mm_cmpeq_epi8(_mm_min_epu8(pb, pc), pb);
    __m128i take_a = _mm_and_si128(pa_le_pb, _mm_or_si128(one_side, pa_le_pc));
    __m128i take_b = _mm_or_si128(one_side, pb_le_pc);
    __m128i bc = _mm_or_si128(_mm_and_si128(take_b, b), _mm_andnot_si128(take_b, c));
    return _mm_or_si128(_mm_and_si128(take_a, a), _mm_andnot_si128(take_a, bc));
}

/* The five filters' sums of magnitudes over bytes [i, n) of the row, 16
 * at a time, from i >= k (bpp) while 16 remain; returns where it stopped.
 * The same bytes as the scalar loop below: Paeth and the floor average
 * as in image_png_write_paeth and _avg, the magnitude min(v, -v), and
 * each 16 magnitudes summed by psadbw against zero into two 64-bit lanes
 * (GCC 12 at -O2 widens them to 32 bits a byte at a time instead, 60 %
 * of the filter's instructions). */
static size_t image_png_write_sums16(const unsigned char *cur, const unsigned char *prev, size_t i,
                                     size_t n, size_t k, unsigned sum[5])
{
    const __m128i zero = _mm_setzero_si128(), one = _mm_set1_epi8(1);
    __m128i acc[5];
    int f;
    for (f = 0; f < 5; f++)
        acc[f] = zero;
    for (; i + 16 <= n; i += 16) {
        __m128i x = _mm_loadu_si128((const __m128i *)(cur + i));
        __m128i a = _mm_loadu_si128((const __m128i *)(cur + i - k));
        __m128i b = _mm_loadu_si128((const __m128i *)(prev + i));
        __m128i c = _mm_loadu_si128((const __m128i *)(prev + i - k));
        /* floor((a + b) / 2): pavgb rounds up, minus the odd bit */
        __m128i avg = _mm_sub_epi8(_mm_avg_epu8(a, b), _mm_and_si128(_mm_xor_si128(a, b), one));
        __m128i pred = image_png_write_paeth16(a, b, c);
        __m128i v[5];
        v[0] = x;
        v[1] = _mm_sub_epi8(x, a);
        v[2] = _mm_sub_epi8(x, b);
        v[3] = _mm_sub_epi8(x, avg);
        v[4] = _mm_sub_epi8(x, pred);
        for (f = 0; f < 5; f++) {
            __m128i m = _mm_min_epu8(v[f], _mm_sub_epi8(zero, v[f]));
            acc[f] = _mm_add_epi64(acc[f], _mm_sad_epu8(m, zero));
        }
    }
    for (f = 0; f < 5; f++)
        sum[f] += (unsigned)(_mm_cvtsi128_si32(acc[f]) + _mm_cvtsi128_si32(_mm_unpackhi_epi64(acc[f], acc[f])));
    return i;
}
#endif

/* Filters row cur (n bytes, bpp per pixel; prev is a row of zeros for the
 * first row) into out[0..n]: type byte, then the bytes of the filter (0
 * none, 1 sub, 2 up, 3 average, 4 Paeth) whose outputs, read as signed,
 * have the least sum of magnitudes (libpng's heuristic). The first pixel,
 * whose left neighbours are zero, is done apart so that the loops over
 * the rest have no branch on the position. The sums are 32-bit (a row has
 * at most 3 * IMAGE_MAX_SIDE bytes of at most 128), four to a vector. */
static void image_png_write_filter(const unsigned char *cur, const unsigned char *prev, size_t n,
                                   int bpp, unsigned char *out)
{
    unsigned sum[5] = {0, 0, 0, 0, 0};
    size_t i, k = (size_t)bpp < n ? (size_t)bpp : n;
    int f, best = 0;
    for (i = 0; i < k; i++) {
        unsigned char x = cur[i], b = prev[i];
        sum[0] += image_png_write_mag(x);
        sum[1] += image_png_write_mag(x);
        sum[2] += image_png_write_mag((unsigned char)(x - b));
        sum[3] += image_png_write_mag((unsigned char)(x - (b >> 1)));
        sum[4] += image_png_write_mag((unsigned char)(x - image_png_write_paeth(0, b, 0)));
    }
#if defined(__SSE2__)
    i = image_png_write_sums16(cur, prev, i, n, k, sum);
#endif
    for (; i < n; i++) {
        unsigned char x = cur[i], a = cur[i - k], b = prev[i], c = prev[i - k];
        sum[0] += image_png_write_mag(x);
        sum[1] += image_png_write_mag((unsigned char)(x - a));
        sum[2] += image_png_write_mag((unsigned char)(x - b));
        sum[3] += image_png_write_mag((unsigned char)(x - image_png_write_avg(a, b)));
        sum[4] += image_png_write_mag((unsigned char)(x - image_png_write_paeth(a, b, c)));
    }
    for (f = 1; f < 5; f++)
        if (sum[f] < sum[best])
            best = f;
    out[0] = (unsigned char)best;
    out++;
    switch (best) {
    case 0:
        memcpy(out, cur, n);
        break;
    case 1:
        memcpy(out, cur, k);
        for (i = k; i < n; i++)
            out[i] = (unsigned char)(cur[i] - cur[i - k]);
        break;
    case 2:
        for (i = 0; i < n; i++)
            out[i] = (unsigned char)(cur[i] - prev[i]);
        break;
    case 3:
        for (i = 0; i < k; i++)
            out[i] = (unsigned char)(cur[i] - (prev[i] >> 1));
        for (; i < n; i++)
            out[i] = (unsigned char)(cur[i] - image_png_write_avg(cur[i - k], prev[i]));
        break;
    default:
        for (i = 0; i < k; i++)
            out[i] = (unsigned char)(cur[i] - image_png_write_paeth(0, prev[i], 0));
#if defined(__SSE2__)
        for (; i + 16 <= n; i += 16) {
            __m128i p = image_png_write_paeth16(_mm_loadu_si128((const __m128i *)(cur + i - k)),
                                                _mm_loadu_si128((const __m128i *)(prev + i)),
                                                _mm_loadu_si128((const __m128i *)(prev + i - k)));
            _mm_storeu_si128((__m128i *)(out + i),
                             _mm_sub_epi8(_mm_loadu_si128((const __m128i *)(cur + i)), p));
        }
#endif
        for (; i < n; i++)
            out[i] = (unsigned char)(cur[i] - image_png_write_paeth(cur[i - k], prev[i], prev[i - k]));
        break;
    }
}

/* Makes the raw deflate stream buf[0, *len) continue where it ends: its
 * final block's BFINAL bit cleared and an empty stored block appended, the
 * bytes zlib's Z_SYNC_FLUSH ends a stream with, so that the next band's
 * stream can follow it byte for byte. buf has room for 5 more bytes. The
 * bit positions come from zlib's inflate run block by block (Z_BLOCK: on
 * each return after an end-of-block code data_type holds 128, plus 64
 * after the final block's, and the count of unused bits of the last byte
 * read), which also checks the stream. 0, or -1 if it is not one complete
 * deflate stream. */
static int image_png_write_continue(unsigned char *buf, size_t *len)
{
    unsigned char sink[16384];
    unsigned long hdr = 0, end = 0;
    z_stream z;
    int rc;
    memset(&z, 0, sizeof z);
    if (inflateInit2(&z, -15) != Z_OK)
        return -1;
    z.next_in = buf;
    z.avail_in = (uInt)*len;
    for (;;) {
        z.next_out = sink;
        z.avail_out = sizeof sink;
        rc = inflate(&z, Z_BLOCK);
        if (rc != Z_OK)         /* an error, or no progress: cut short */
            break;
        if (z.data_type & 128) {
            unsigned long at = z.total_in * 8 - (unsigned long)(z.data_type & 7);
            if (z.data_type & 64) {
                end = at;       /* just past the final block */
                break;
            }
            hdr = at;           /* where the next block's header starts */
        }
    }
    inflateEnd(&z);
    if (rc != Z_OK || (end + 7) / 8 != *len)
        return -1;
    buf[hdr / 8] &= (unsigned char)~(1u << (hdr % 8));
    if (end % 8)                /* the bits past the end: zero, as the stored
                                   block's 3 header bits (BFINAL 0, BTYPE 00) */
        buf[end / 8] &= (unsigned char)((1u << (end % 8)) - 1);
    end = (end + 3 + 7) / 8;    /* the header, then to a byte boundary */
    if (end > *len)
        buf[*len] = 0;
    memcpy(buf + end, "\0\0\377\377", 4);   /* LEN 0, NLEN ~0 */
    *len = end + 4;
    return 0;
}

/* What a thread reuses from band to band: the compressor, a row of zeros
 * (the row above the first) and the filtered rows of one band. */
typedef struct image_png_write_work {
    struct libdeflate_compressor *c;
    unsigned char *zero, *rows;
} image_png_write_work;

static void image_png_write_work_init(image_png_write_work *w, const image *img, int level)
{
    size_t n = (size_t)img->width * (size_t)img->channels;
    w->c = libdeflate_alloc_compressor(level);
    w->zero = mem_calloc(1, n);
    w->rows = mem_alloc((size_t)IMAGE_PNG_WRITE_BAND * (n + 1));
}

static void image_png_write_work_free(image_png_write_work *w)
{
    libdeflate_free_compressor(w->c);
    mem_free(w->zero);
    mem_free(w->rows);
}

/* Deflates rows [y0, y1) of img into b (raw deflate, libdeflate at the
 * level w's compressor was made for): a stream of its own, made to
 * continue (see above) unless it is the last. */
static void image_png_write_band_run(const image *img, image_png_write_work *w, int y0, int y1, int last,
                                     image_png_write_band *b)
{
    size_t n = (size_t)img->width * (size_t)img->channels, rb = n + 1, y;
    b->raw = (size_t)(y1 - y0) * rb;
    if (w->c && w->zero && w->rows) {
        b->cap = libdeflate_deflate_compress_bound(w->c, b->raw) + 5;
        b->buf = mem_alloc(b->cap);
    }
    if (!b->buf) {
        b->failed = 1;
        return;
    }
    for (y = (size_t)y0; y < (size_t)y1; y++)
        image_png_write_filter(img->px + y * n, y ? img->px + (y - 1) * n : w->zero, n, img->channels,
                               w->rows + (y - (size_t)y0) * rb);
    b->adler = libdeflate_adler32(1, w->rows, b->raw);
    b->len = libdeflate_deflate_compress(w->c, w->rows, b->raw, b->buf, b->cap - 5);
    b->failed = b->len == 0 || (!last && image_png_write_continue(b->buf, &b->len));
}

static unsigned char *image_png_write_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
    return p + 4;
}

/* Writes one chunk (length, type, data, CRC) at p; returns the end. */
static unsigned char *image_png_write_chunk(unsigned char *p, const char *type, const unsigned char *data,
                                            size_t len)
{
    uLong crc;
    p = image_png_write_u32(p, (uint32_t)len);
    memcpy(p, type, 4);
    if (len)
        memmove(p + 4, data, len);
    crc = crc32(0L, p, (uInt)(4 + len));
    return image_png_write_u32(p + 4 + len, (uint32_t)crc);
}

int image_png_write_mem(const image *img, int threads, int level, const char *name,
                        unsigned char **out, size_t *len, diag *err)
{
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    int nb = (img->height + IMAGE_PNG_WRITE_BAND - 1) / IMAGE_PNG_WRITE_BAND, i, failed = 0;
    image_png_write_band *bands = mem_calloc((size_t)nb, sizeof *bands);
    unsigned char ihdr[13], *png, *p;
    size_t zlen = 2 + 4, total;
    uLong adler;
    if (!bands)
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory encoding a PNG");
    if (threads < 1)
        threads = 1;
#pragma omp parallel num_threads(threads)
    {
        image_png_write_work w;
        image_png_write_work_init(&w, img, level);
#pragma omp for schedule(dynamic, 1)
        for (i = 0; i < nb; i++) {
            int y0 = i * IMAGE_PNG_WRITE_BAND, y1 = y0 + IMAGE_PNG_WRITE_BAND;
            image_png_write_band_run(img, &w, y0, y1 < img->height ? y1 : img->height, i == nb - 1, &bands[i]);
        }
        image_png_write_work_free(&w);
    }
    adler = adler32(0L, Z_NULL, 0);
    for (i = 0; i < nb; i++) {
        failed |= bands[i].failed;
        zlen += bands[i].len;
        adler = adler32_combine(adler, bands[i].adler, (z_off_t)bands[i].raw);
    }
    /* one IDAT per band: the first also holds the zlib header, the last the
     * Adler-32 trailer; 8 + 25 + 13 + 12 + 12 bytes of fixed chunks */
    total = sizeof sig + 25 + 13 + 12 + zlen + 12 * (size_t)nb;
    png = failed ? NULL : mem_alloc(total);
    if (!png) {
        for (i = 0; i < nb; i++)
            mem_free(bands[i].buf);
        mem_free(bands);
        return diag_at(err, DIAG_IO, name, 0, 0, failed ? "PNG deflate failed" : "out of memory encoding a PNG");
    }
    memcpy(png, sig, sizeof sig);
    image_png_write_u32(ihdr, (uint32_t)img->width);
    image_png_write_u32(ihdr + 4, (uint32_t)img->height);
    ihdr[8] = 8;                                     /* bit depth */
    ihdr[9] = img->channels == 1 ? 0 : 2;            /* grey or truecolour */
    ihdr[10] = ihdr[11] = ihdr[12] = 0;              /* deflate, adaptive filters, no interlace */
    p = image_png_write_chunk(png + sizeof sig, "IHDR", ihdr, sizeof ihdr);
    p = image_png_write_chunk(p, "sRGB", (const unsigned char *)"\0", 1);   /* perceptual, as libpng */
    for (i = 0; i < nb; i++) {
        /* assemble the chunk data in place after the 8-byte chunk header */
        unsigned char *d = p + 8, *q = d;
        if (i == 0) {
            *q++ = 0x78;                             /* deflate, 32 KiB window */
            *q++ = level <= 1 ? 0x01 : level <= 5 ? 0x5e : level == 6 ? 0x9c : 0xda;
        }
        memcpy(q, bands[i].buf, bands[i].len);
        q += bands[i].len;
        if (i == nb - 1)
            q = image_png_write_u32(q, (uint32_t)adler);
        p = image_png_write_chunk(p, "IDAT", d, (size_t)(q - d));
        mem_free(bands[i].buf);
    }
    p = image_png_write_chunk(p, "IEND", NULL, 0);
    mem_free(bands);
    *out = png;
    *len = (size_t)(p - png);
    return 0;
}
