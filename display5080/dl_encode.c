/* dl_encode — in-memory DL5080 writer (see dl_encode.h). */
#include "display5080/dl_encode.h"
#include "util/mem.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define DL_NO_ELEMENT ((size_t)-1)

static void dl_encode_fail(dl_encoder *enc, int status, const char *fmt, ...)
{
    va_list ap;
    if (enc->status)
        return;
    enc->status = status;
    va_start(ap, fmt);
    vsnprintf(enc->msg, sizeof enc->msg, fmt, ap);
    va_end(ap);
}

static void dl_encode_put(dl_encoder *enc, const void *p, size_t n)
{
    void *buf = enc->buf;
    if (enc->status || n == 0)
        return;
    if (n > (size_t)-1 - enc->len || mem_grow(&buf, &enc->cap, enc->len + n, 1)) {
        dl_encode_fail(enc, DIAG_IO, "out of memory");
        return;
    }
    enc->buf = buf;
    memcpy(enc->buf + enc->len, p, n);
    enc->len += n;
}

void dl_encode_init(dl_encoder *enc, int width, int height, unsigned flags)
{
    uint8_t h[DL_HEADER_SIZE] = {0};
    memset(enc, 0, sizeof *enc);
    enc->open = DL_NO_ELEMENT;
    memcpy(h, dl_magic, sizeof dl_magic);
    h[7] = DL_VERSION;
    h[8] = (uint8_t)(flags >> 8);
    h[9] = (uint8_t)flags;
    h[10] = (uint8_t)(width >> 8);
    h[11] = (uint8_t)width;
    h[12] = (uint8_t)(height >> 8);
    h[13] = (uint8_t)height;
    if (width < 1 || width > DL_MAX_SIDE || height < 1 || height > DL_MAX_SIDE)
        dl_encode_fail(enc, DIAG_INPUT, "size %dx%d is outside 1..%d", width, height, DL_MAX_SIDE);
    dl_encode_put(enc, h, sizeof h);
}

void dl_encode_free(dl_encoder *enc)
{
    mem_free(enc->buf);
    enc->buf = NULL;
    enc->len = enc->cap = 0;
}

void dl_encode_begin(dl_encoder *enc, unsigned code)
{
    uint8_t head[4] = {0, 0, (uint8_t)(code >> 8), (uint8_t)code};
    if (enc->open != DL_NO_ELEMENT)
        dl_encode_fail(enc, DIAG_INPUT, "element 0x%04X opened inside another", code);
    enc->open = enc->len;
    dl_encode_put(enc, head, 4);
}

void dl_encode_u16(dl_encoder *enc, unsigned v)
{
    uint8_t b[2] = {(uint8_t)(v >> 8), (uint8_t)v};
    if (v > 0xFFFFu)
        dl_encode_fail(enc, DIAG_INPUT, "value %u does not fit 16 bits", v);
    dl_encode_put(enc, b, 2);
}

void dl_encode_s16(dl_encoder *enc, long v)
{
    if (v < -32768 || v > 32767) {
        dl_encode_fail(enc, DIAG_INPUT, "coordinate %ld is outside -32768..32767", v);
        return;
    }
    dl_encode_u16(enc, (unsigned)(v & 0xFFFF));
}

void dl_encode_u32(dl_encoder *enc, uint32_t v)
{
    uint8_t b[4] = {(uint8_t)(v >> 24), (uint8_t)(v >> 16), (uint8_t)(v >> 8), (uint8_t)v};
    dl_encode_put(enc, b, 4);
}

void dl_encode_bytes(dl_encoder *enc, const void *p, size_t n) { dl_encode_put(enc, p, n); }

void dl_encode_end(dl_encoder *enc)
{
    size_t n;
    if (enc->status || enc->open == DL_NO_ELEMENT) {
        enc->open = DL_NO_ELEMENT;
        return;
    }
    if ((enc->len - enc->open) & 1u) {
        uint8_t z = 0;
        dl_encode_put(enc, &z, 1);
    }
    n = enc->len - enc->open;
    if (!enc->status && n > DL_MAX_ELEMENT)
        dl_encode_fail(enc, DIAG_INPUT, "element 0x%04X of %zu bytes exceeds %d bytes",
                       dl_be16(enc->buf + enc->open + 2), n, DL_MAX_ELEMENT);
    if (!enc->status) {
        enc->buf[enc->open] = (uint8_t)(n >> 8);
        enc->buf[enc->open + 1] = (uint8_t)n;
    }
    enc->open = DL_NO_ELEMENT;
}

void dl_encode_simple(dl_encoder *enc, unsigned code)
{
    dl_encode_begin(enc, code);
    dl_encode_end(enc);
}

void dl_encode_word(dl_encoder *enc, unsigned code, unsigned v)
{
    dl_encode_begin(enc, code);
    dl_encode_u16(enc, v);
    dl_encode_end(enc);
}

void dl_encode_points(dl_encoder *enc, unsigned code, const int *xy, size_t n)
{
    size_t i;
    dl_encode_begin(enc, code);
    for (i = 0; i < 2 * n; i++)
        dl_encode_s16(enc, xy[i]);
    dl_encode_end(enc);
}

void dl_encode_rect(dl_encoder *enc, unsigned code, int x0, int y0, int x1, int y1)
{
    dl_encode_begin(enc, code);
    dl_encode_s16(enc, x0);
    dl_encode_s16(enc, y0);
    dl_encode_s16(enc, x1);
    dl_encode_s16(enc, y1);
    dl_encode_end(enc);
}

void dl_encode_circle(dl_encoder *enc, unsigned code, int cx, int cy, unsigned r)
{
    dl_encode_begin(enc, code);
    dl_encode_s16(enc, cx);
    dl_encode_s16(enc, cy);
    dl_encode_u16(enc, r);
    dl_encode_end(enc);
}

void dl_encode_text(dl_encoder *enc, int x, int y, const uint8_t *ebcdic, size_t n)
{
    dl_encode_begin(enc, DL_TEXT);
    dl_encode_s16(enc, x);
    dl_encode_s16(enc, y);
    dl_encode_u16(enc, n > 0xFFFFu ? 0x10000u : (unsigned)n);
    dl_encode_bytes(enc, ebcdic, n);
    dl_encode_end(enc);
}

void dl_encode_colours(dl_encoder *enc, unsigned start, const uint32_t *rgb, size_t n)
{
    size_t i;
    dl_encode_begin(enc, DL_LOAD_COLOURS);
    dl_encode_u16(enc, start);
    dl_encode_u16(enc, n > 0xFFFFu ? 0x10000u : (unsigned)n);
    for (i = 0; i < n; i++)
        dl_encode_u32(enc, rgb[i] & 0xFFFFFFu);
    dl_encode_end(enc);
}

void dl_encode_blt(dl_encoder *enc, int x0, int y0, int w, int h, unsigned op,
                   const uint8_t *rows, size_t stride)
{
    int r;
    if (w < 1 || h < 1) {
        dl_encode_fail(enc, DIAG_INPUT, "empty BLT of %dx%d pixels", w, h);
        return;
    }
    dl_encode_begin(enc, DL_BLT);
    dl_encode_s16(enc, x0);
    dl_encode_s16(enc, y0);
    dl_encode_s16(enc, (long)x0 + w - 1);
    dl_encode_s16(enc, (long)y0 + h - 1);
    dl_encode_u16(enc, DL_BLT_BPP);
    dl_encode_u16(enc, op);
    /* top row first, rows packed; dl_encode_end pads the element once */
    for (r = h - 1; r >= 0 && !enc->status; r--)
        dl_encode_bytes(enc, rows + (size_t)r * stride, (size_t)w);
    dl_encode_end(enc);
}

void dl_encode_plane_mask(dl_encoder *enc, unsigned writable)
{
    dl_encode_word(enc, DL_PLANE_MASK, dl_format_mask_word(writable));
}

void dl_encode_run_row(dl_encoder *enc, int y, int x0, const unsigned *runs, size_t n)
{
    size_t i;
    dl_encode_begin(enc, DL_RUN_ROW);
    dl_encode_s16(enc, y);
    dl_encode_s16(enc, x0);
    dl_encode_u16(enc, n > 0xFFFFu ? 0x10000u : (unsigned)n);
    for (i = 0; i < 2 * n; i++)
        dl_encode_u16(enc, runs[i]);
    dl_encode_end(enc);
}

size_t dl_encode_run_row_size(size_t runs) { return 10 + 4 * runs; }

size_t dl_encode_blt_size(int w, int h)
{
    size_t n = (size_t)w * (size_t)h;
    return 16 + n + (n & 1);
}

int dl_encode_finish(dl_encoder *enc, const char *name, uint8_t **out, size_t *len, diag *err)
{
    if (!enc->status && enc->open != DL_NO_ELEMENT)
        dl_encode_fail(enc, DIAG_INPUT, "element left open");
    if (enc->status) {
        int st = enc->status;
        dl_encode_free(enc);
        return diag_at(err, st, name, 0, 0, "DL5080 encoding: %s", enc->msg);
    }
    *out = enc->buf;
    *len = enc->len;
    enc->buf = NULL;
    enc->len = enc->cap = 0;
    return 0;
}
