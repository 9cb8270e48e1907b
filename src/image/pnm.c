/* pnm — strict, bounded Netpbm P2/P3/P5/P6 reader (see pnm.h). */
#include "image/pnm.h"
#include "util/mem.h"
#include <stdio.h>
#include <string.h>

/* A cursor over the file that tracks line and column for diagnostics. */
typedef struct pnm_cur {
    const unsigned char *p;
    size_t len, pos;
    long line, col;
    const char *name;
    diag *err;
} pnm_cur;

static int pnm_space(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

static void pnm_advance(pnm_cur *c)
{
    if (c->p[c->pos] == '\n') {
        c->line++;
        c->col = 1;
    } else {
        c->col++;
    }
    c->pos++;
}

/* Skips whitespace and '#' comments (to end of line). */
static void pnm_skip(pnm_cur *c)
{
    while (c->pos < c->len) {
        int ch = c->p[c->pos];
        if (ch == '#') {
            while (c->pos < c->len && c->p[c->pos] != '\n')
                pnm_advance(c);
        } else if (pnm_space(ch)) {
            pnm_advance(c);
        } else {
            break;
        }
    }
}

/* Reads an unsigned decimal number after optional whitespace and comments.
 * Values above `max` are an error naming `what`. */
static int pnm_number(pnm_cur *c, const char *what, unsigned long max, unsigned long *out)
{
    unsigned long v = 0;
    long line, col;
    pnm_skip(c);
    line = c->line;
    col = c->col;
    if (c->pos >= c->len)
        return diag_at(c->err, DIAG_INPUT, c->name, line, col, "file ends before the %s", what);
    if (c->p[c->pos] < '0' || c->p[c->pos] > '9')
        return diag_at(c->err, DIAG_INPUT, c->name, line, col, "expected the %s (a decimal number), found '%c'",
                       what, c->p[c->pos] >= 32 && c->p[c->pos] < 127 ? c->p[c->pos] : '?');
    while (c->pos < c->len && c->p[c->pos] >= '0' && c->p[c->pos] <= '9') {
        if (v <= max)
            v = v * 10 + (unsigned long)(c->p[c->pos] - '0');
        pnm_advance(c);
    }
    if (v > max)
        return diag_at(c->err, DIAG_INPUT, c->name, line, col, "%s is larger than %lu", what, max);
    if (c->pos < c->len && !pnm_space(c->p[c->pos]) && c->p[c->pos] != '#')
        return diag_at(c->err, DIAG_INPUT, c->name, c->line, c->col, "junk after the %s", what);
    *out = v;
    return 0;
}

int pnm_sniff(const void *data, size_t len)
{
    const unsigned char *p = data;
    return len >= 2 && p[0] == 'P' && p[1] >= '1' && p[1] <= '7';
}

/* Converts one decoded pixel (grey or RGB, already 0..255) into out. */
static void pnm_store(uint8_t *dst, int channels, int in_channels, const unsigned v[3])
{
    if (channels == in_channels) {
        dst[0] = (uint8_t)v[0];
        if (channels == 3) {
            dst[1] = (uint8_t)v[1];
            dst[2] = (uint8_t)v[2];
        }
    } else if (channels == 3) {
        dst[0] = dst[1] = dst[2] = (uint8_t)v[0];
    } else {
        /* Rec. 601 luma in 1/1000 units, rounded */
        dst[0] = (uint8_t)((299u * v[0] + 587u * v[1] + 114u * v[2] + 500u) / 1000u);
    }
}

/* Parses the header up to the end of maxval; c is left just after it. */
static int pnm_parse_header(pnm_cur *c, pnm_info *info)
{
    unsigned long w, h, maxval;
    int kind;
    const char *name = c->name;
    diag *err = c->err;
    if (c->len == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "empty file");
    if (!pnm_sniff(c->p, c->len))
        return diag_at(err, DIAG_INPUT, name, 1, 1, "not a PNM file (no P2, P3, P5 or P6 magic)");
    kind = c->p[1] - '0';
    if (kind == 1 || kind == 4)
        return diag_at(err, DIAG_INPUT, name, 1, 1, "PBM bitmaps (P%d) are not supported; use P2, P3, P5 or P6", kind);
    if (kind == 7)
        return diag_at(err, DIAG_INPUT, name, 1, 1, "PAM (P7) is not supported; use P2, P3, P5 or P6");
    pnm_advance(c);
    pnm_advance(c);
    if (c->pos < c->len && !pnm_space(c->p[c->pos]) && c->p[c->pos] != '#')
        return diag_at(err, DIAG_INPUT, name, c->line, c->col, "junk after the magic number");
    if (pnm_number(c, "width", IMAGE_MAX_SIDE, &w) || pnm_number(c, "height", IMAGE_MAX_SIDE, &h) ||
        pnm_number(c, "maxval", 65535, &maxval))
        return err->status;
    if (w == 0 || h == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "image size %lux%lu is empty", w, h);
    if (maxval == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "maxval is 0 (1..65535 allowed)");
    if ((size_t)w * h > IMAGE_MAX_PIXELS)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "image size %lux%lu is over %u pixels", w, h, IMAGE_MAX_PIXELS);
    info->kind = kind;
    info->width = (int)w;
    info->height = (int)h;
    info->maxval = (unsigned)maxval;
    return 0;
}

static void pnm_cur_init(pnm_cur *c, const char *name, const void *data, size_t len, diag *err)
{
    c->p = data;
    c->len = len;
    c->pos = 0;
    c->line = c->col = 1;
    c->name = name;
    c->err = err;
}

int pnm_read_header(const char *name, const void *data, size_t len, pnm_info *info, diag *err)
{
    pnm_cur c;
    pnm_info i;
    pnm_cur_init(&c, name, data, len, err);
    if (pnm_parse_header(&c, &i))
        return err->status;
    *info = i;
    return 0;
}

int pnm_read_memory(const char *name, const void *data, size_t len, int channels,
                    image *out, diag *err)
{
    pnm_cur c;
    pnm_info info = {0};
    unsigned long w, h, maxval;
    int in_ch, binary, bps;
    size_t samples, i;
    image img;
    if (channels != 1 && channels != 3)
        return diag_at(err, DIAG_USAGE, name, 0, 0, "internal: bad channel count");
    pnm_cur_init(&c, name, data, len, err);
    if (pnm_parse_header(&c, &info))
        return err->status;
    w = (unsigned long)info.width;
    h = (unsigned long)info.height;
    maxval = info.maxval;
    in_ch = (info.kind == 3 || info.kind == 6) ? 3 : 1;
    binary = info.kind >= 5;
    samples = (size_t)w * h * (size_t)in_ch;
    bps = maxval > 255 ? 2 : 1;
    if (binary) {
        /* exactly one whitespace character separates maxval from the raster */
        if (c.pos >= c.len)
            return diag_offset(err, DIAG_INPUT, name, (long long)c.pos, "file ends before the raster");
        if (!pnm_space(c.p[c.pos]))
            return diag_at(err, DIAG_INPUT, name, c.line, c.col, "expected one whitespace character before the raster");
        c.pos++;
        if (c.len - c.pos < samples * (size_t)bps)
            return diag_offset(err, DIAG_INPUT, name, (long long)c.len,
                               "raster truncated: %zu bytes present, %zu needed",
                               c.len - c.pos, samples * (size_t)bps);
    } else if (pnm_skip(&c), samples > (c.len - c.pos + 1) / 2) {
        /* every plain sample takes a digit and a separator */
        return diag_at(err, DIAG_INPUT, name, c.line, c.col,
                       "raster truncated: %zu samples cannot fit in %zu bytes", samples, c.len - c.pos);
    }
    if (image_alloc(&img, (int)w, (int)h, channels, name, err))
        return err->status;
    for (i = 0; i < (size_t)w * h; i++) {
        unsigned v[3] = {0, 0, 0};
        int k;
        for (k = 0; k < in_ch; k++) {
            unsigned long s;
            if (binary) {
                s = c.p[c.pos];
                if (bps == 2)
                    s = s << 8 | c.p[c.pos + 1];
                if (s > maxval) {
                    image_free(&img);
                    return diag_offset(err, DIAG_INPUT, name, (long long)c.pos,
                                       "sample %lu is above maxval %lu", s, maxval);
                }
                c.pos += (size_t)bps;
            } else {
                long line, col;
                pnm_skip(&c);
                line = c.line;
                col = c.col;
                if (pnm_number(&c, "sample", 65535, &s)) {
                    image_free(&img);
                    return err->status;
                }
                if (s > maxval) {
                    image_free(&img);
                    return diag_at(err, DIAG_INPUT, name, line, col, "sample %lu is above maxval %lu", s, maxval);
                }
            }
            v[k] = (unsigned)((s * 255u + maxval / 2) / maxval);
        }
        pnm_store(img.px + i * (size_t)channels, channels, in_ch, v);
    }
    *out = img;
    return 0;
}

size_t pnm_header(const image *img, int pam, const char *comments, char *head, size_t cap)
{
    size_t cn = comments ? strlen(comments) : 0;
    int grey = img->channels == 1, n;
    if (cap < 3 + cn + PNM_HEAD_MAX)
        return 0;
    head[0] = 'P';
    head[1] = pam ? '7' : grey ? '5' : '6';
    head[2] = '\n';
    memcpy(head + 3, comments ? comments : "", cn);
    if (pam)
        n = snprintf(head + 3 + cn, PNM_HEAD_MAX, "WIDTH %d\nHEIGHT %d\nDEPTH %d\nMAXVAL 255\n"
                     "TUPLTYPE %s\nENDHDR\n", img->width, img->height, img->channels,
                     grey ? "GRAYSCALE" : "RGB");
    else
        n = snprintf(head + 3 + cn, PNM_HEAD_MAX, "%d %d\n255\n", img->width, img->height);
    return n > 0 && n < PNM_HEAD_MAX ? 3 + cn + (size_t)n : 0;
}

int pnm_encode(const image *img, int pam, const char *comments, void **buf, size_t *len, diag *err)
{
    size_t cap = 3 + (comments ? strlen(comments) : 0) + PNM_HEAD_MAX, hn;
    size_t raster = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
    unsigned char *o;
    if (!(o = mem_alloc(cap + raster)))
        return diag_at(err, DIAG_IO, "PNM", 0, 0, "out of memory");
    if (!(hn = pnm_header(img, pam, comments, (char *)o, cap))) {
        mem_free(o);
        return diag_at(err, DIAG_IO, "PNM", 0, 0, "header too long");
    }
    memcpy(o + hn, img->px, raster);
    *buf = o;
    *len = hn + raster;
    return 0;
}
