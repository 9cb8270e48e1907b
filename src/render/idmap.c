/* idmap — identity map allocation and the MAPRTID1 file (see idmap.h). */
#include "render/idmap.h"
#include "image/image.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

#define IDMAP_HEAD 16
#define IDMAP_REC 24

int idmap_alloc(idmap *m, int w, int h, diag *err)
{
    size_t i, n;
    if (w < 1 || h < 1 || w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE)
        return diag_at(err, DIAG_IO, "ids", 0, 0, "identity map size %dx%d out of range", w, h);
    n = (size_t)w * (size_t)h;
    if (!(m->px = mem_calloc(n, sizeof *m->px)))
        return diag_at(err, DIAG_IO, "ids", 0, 0, "out of memory for the identity map");
    m->width = w;
    m->height = h;
    for (i = 0; i < n; i++) {
        m->px[i].prim = m->px[i].face = m->px[i].region = -1;
        m->px[i].t = -1;
    }
    return 0;
}

void idmap_free(idmap *m)
{
    mem_free(m->px);
    m->px = NULL;
    m->width = m->height = 0;
}

static void idmap_put32(unsigned char *b, uint32_t v)
{
    int k;
    for (k = 0; k < 4; k++)
        b[k] = (unsigned char)(v >> (8 * k));
}

static uint32_t idmap_get32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

int idmap_write(const char *path, const idmap *m, diag *err)
{
    outfile of;
    unsigned char rec[IDMAP_REC * 64];
    size_t i, n = (size_t)m->width * (size_t)m->height, k = 0;
    if (outfile_open(&of, path, err))
        return err->status;
    memcpy(rec, "MAPRTID1", 8);
    idmap_put32(rec + 8, (uint32_t)m->width);
    idmap_put32(rec + 12, (uint32_t)m->height);
    outfile_write(&of, rec, IDMAP_HEAD, err);
    for (i = 0; i < n; i++) {
        const idmap_px *p = &m->px[i];
        unsigned char *b = rec + IDMAP_REC * k;
        uint64_t bits;
        int j;
        memcpy(&bits, &p->t, sizeof bits);
        idmap_put32(b, (uint32_t)p->prim);
        idmap_put32(b + 4, (uint32_t)p->face);
        idmap_put32(b + 8, (uint32_t)p->region);
        idmap_put32(b + 12, (uint32_t)p->flags);
        for (j = 0; j < 8; j++)
            b[16 + j] = (unsigned char)(bits >> (8 * j));
        if (++k == 64 || i + 1 == n) {
            outfile_write(&of, rec, IDMAP_REC * k, err);
            k = 0;
        }
    }
    if (outfile_commit(&of, err)) {
        outfile_abort(&of);
        return err->status ? err->status : DIAG_IO;
    }
    return 0;
}

int idmap_read_memory(const char *name, const void *data, size_t len, idmap *m, diag *err)
{
    const unsigned char *b = data;
    size_t i, n, need;
    uint32_t w, h;
    idmap out;
    if (len < IDMAP_HEAD || memcmp(b, "MAPRTID1", 8))
        return diag_offset(err, DIAG_INPUT, name, 0, "not an identity map (no MAPRTID1 header)");
    w = idmap_get32(b + 8);
    h = idmap_get32(b + 12);
    if (w < 1 || h < 1 || w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE)
        return diag_offset(err, DIAG_INPUT, name, 8, "identity map size %lux%lu out of range",
                           (unsigned long)w, (unsigned long)h);
    n = (size_t)w * h;
    need = IDMAP_HEAD + IDMAP_REC * n;
    if (len != need)                    /* checked before allocating */
        return diag_offset(err, DIAG_INPUT, name, (long long)(len < need ? len : need),
                           "identity map of %lux%lu pixels needs %lu bytes, the file has %lu",
                           (unsigned long)w, (unsigned long)h, (unsigned long)need, (unsigned long)len);
    if (idmap_alloc(&out, (int)w, (int)h, err))
        return err->status;
    for (i = 0; i < n; i++) {
        const unsigned char *r = b + IDMAP_HEAD + IDMAP_REC * i;
        uint64_t bits = 0;
        int j;
        out.px[i].prim = (int32_t)idmap_get32(r);
        out.px[i].face = (int32_t)idmap_get32(r + 4);
        out.px[i].region = (int32_t)idmap_get32(r + 8);
        out.px[i].flags = (int32_t)idmap_get32(r + 12);
        for (j = 7; j >= 0; j--)
            bits = bits << 8 | r[16 + j];
        memcpy(&out.px[i].t, &bits, sizeof bits);
    }
    *m = out;
    return 0;
}

int idmap_read(const char *path, idmap *m, diag *err)
{
    char *data;
    size_t len;
    int st;
    if (infile_read_all(path, (size_t)IDMAP_HEAD + (size_t)IDMAP_REC * 16384 * 16384, &data, &len, err))
        return err->status;
    st = idmap_read_memory(path, data, len, m, err);
    mem_free(data);
    return st;
}
