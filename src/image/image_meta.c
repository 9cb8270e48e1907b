/* image_meta — provenance text for pictures (see image_meta.h). */
#include "image/image_meta.h"
#include "util/mem.h"
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void image_meta_init(image_meta *m) { m->n = 0; }

void image_meta_add(image_meta *m, const char *key, const char *fmt, ...)
{
    va_list ap;
    size_t i, k = strlen(key);
    char *v;
    if (m->n >= IMAGE_META_MAX || k < 1 || k >= IMAGE_META_KEY)
        return;
    for (i = 0; i < k; i++)
        if (key[i] < 0x20 || key[i] > 0x7e)
            return;
    memcpy(m->kv[m->n].key, key, k + 1);
    v = m->kv[m->n].value;
    va_start(ap, fmt);
    vsnprintf(v, IMAGE_META_VALUE, fmt, ap);
    va_end(ap);
    for (i = 0; v[i]; i++)
        if ((unsigned char)v[i] < 0x20 || (unsigned char)v[i] > 0x7e)
            v[i] = '?';
    m->n++;
}

void image_meta_date(char out[32])
{
    const char *sde = getenv("SOURCE_DATE_EPOCH");
    time_t t = time(NULL);
    struct tm tm;
    if (sde && *sde) {
        char *end;
        long long v = strtoll(sde, &end, 10);
        if (!*end && v >= 0)
            t = (time_t)v;
    }
    if (!gmtime_r(&t, &tm) || !strftime(out, 32, "%Y-%m-%dT%H:%M:%SZ", &tm))
        strcpy(out, "unknown");
}

/* CRC-32 of the PNG specification (ISO 3309 polynomial, reflected). */
static uint32_t image_meta_crc(uint32_t crc, const unsigned char *p, size_t n)
{
    size_t i;
    int b;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= p[i];
        for (b = 0; b < 8; b++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void image_meta_be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

int image_meta_png(const void *png, size_t len, const image_meta *m, void **out, size_t *outlen,
                   diag *err)
{
    /* after IHDR, before IDAT, so that readers that stop at the pixels
     * (libpng's png_read_info) see them too */
    static const unsigned char ihdr[16] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',
                                           0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    const unsigned char *in = png;
    size_t extra = 0, at = 8 + 12 + 13, pos;
    unsigned char *o;
    int i;
    if (len < at + 12 || memcmp(in, ihdr, sizeof ihdr) != 0)
        return diag_at(err, DIAG_INPUT, "PNG", 0, 0, "the encoded PNG does not start with IHDR");
    for (i = 0; i < m->n; i++)
        extra += 12 + strlen(m->kv[i].key) + 1 + strlen(m->kv[i].value);
    if (!(o = mem_alloc(len + extra)))
        return diag_at(err, DIAG_IO, "PNG", 0, 0, "out of memory");
    memcpy(o, in, at);
    pos = at;
    for (i = 0; i < m->n; i++) {
        size_t k = strlen(m->kv[i].key), v = strlen(m->kv[i].value), n = k + 1 + v;
        image_meta_be32(o + pos, (uint32_t)n);
        memcpy(o + pos + 4, "tEXt", 4);
        memcpy(o + pos + 8, m->kv[i].key, k + 1);      /* keyword, NUL separator */
        memcpy(o + pos + 8 + k + 1, m->kv[i].value, v);
        image_meta_be32(o + pos + 8 + n, image_meta_crc(0, o + pos + 4, n + 4));
        pos += 12 + n;
    }
    memcpy(o + pos, in + at, len - at);
    *out = o;
    *outlen = pos + len - at;
    return 0;
}

void image_meta_comments(const image_meta *m, char *buf, size_t cap)
{
    size_t pos = 0;
    int i;
    if (!cap)
        return;
    buf[0] = '\0';
    for (i = 0; i < m->n && pos < cap; i++) {
        int w = snprintf(buf + pos, cap - pos, "# %s: %s\n", m->kv[i].key, m->kv[i].value);
        if (w < 0 || (size_t)w >= cap - pos) {
            buf[pos] = '\0';    /* a comment cut in half is not kept */
            break;
        }
        pos += (size_t)w;
    }
}
