/* render_part — a rendered region as bytes (see render_part.h). */
#include "render/render_part.h"
#include "util/mem.h"
#include <string.h>

static const char render_part_magic[8] = {'M', 'A', 'P', 'R', 'T', 'P', 'T', '3'};

/* Every field of render_stats is in the layout: one that is added there
 * without a place here stops the build. */
typedef char render_part_in_step[sizeof(render_stats) == 8 * RENDER_PART_COUNTERS + 2 * sizeof(double)
                                 ? 1 : -1];

static void render_part_put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24); p[1] = (uint8_t)(v >> 16); p[2] = (uint8_t)(v >> 8); p[3] = (uint8_t)v;
}

static void render_part_put64(uint8_t *p, uint64_t v)
{
    render_part_put32(p, (uint32_t)(v >> 32));
    render_part_put32(p + 4, (uint32_t)v);
}

static uint32_t render_part_get32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static uint64_t render_part_get64(const uint8_t *p)
{
    return (uint64_t)render_part_get32(p) << 32 | render_part_get32(p + 4);
}

/* The counters in the order of the layout: the named ones, then the HFP
 * exceptions. */
#define RENDER_PART_NAMED (RENDER_PART_COUNTERS - HFP_EXC_N)
static unsigned long long *render_part_counter(render_stats *s, int i)
{
    unsigned long long *const c[RENDER_PART_NAMED] = {
        &s->rays_primary, &s->rays_shadow, &s->rays_reflected, &s->rays_refracted,
        &s->pds_lookups, &s->fx_overflows, &s->prim_tests, &s->bound_tests,
        &s->csg_pruned, &s->arena_full, &s->range_cut, &s->uv_skipped, &s->shadow_skipped,
        &s->rays_capped, &s->objects, &s->inst_moved, &s->inst_turned};
    return i < RENDER_PART_NAMED ? c[i] : &s->hfp_exc[i - RENDER_PART_NAMED];
}

size_t render_part_bytes(const int region[4], int ids)
{
    size_t n = (size_t)(region[2] - region[0]) * (size_t)(region[3] - region[1]);
    return RENDER_PART_HEADER + (RENDER_PART_PX + (ids ? RENDER_PART_ID_PX : 0)) * n;
}

/* One identity map record at p (the layout of the header comment). */
static void render_part_put_id(uint8_t *p, const idmap_px *id)
{
    uint64_t bits;
    memcpy(&bits, &id->t, 8);
    render_part_put32(p, (uint32_t)id->prim);
    render_part_put32(p + 4, (uint32_t)id->face);
    render_part_put32(p + 8, (uint32_t)id->region);
    render_part_put32(p + 12, (uint32_t)id->flags);
    render_part_put64(p + 16, bits);
}

static void render_part_get_id(const uint8_t *p, idmap_px *id)
{
    uint64_t bits = render_part_get64(p + 16);
    id->prim = (int32_t)render_part_get32(p);
    id->face = (int32_t)render_part_get32(p + 4);
    id->region = (int32_t)render_part_get32(p + 8);
    id->flags = (int32_t)render_part_get32(p + 12);
    memcpy(&id->t, &bits, 8);
}

int render_part_encode(const render_fb *fb, const render_part_info *info, uint8_t **out,
                       size_t *len, diag *err)
{
    const int *r = info->region;
    size_t n = render_part_bytes(r, info->ids), w = (size_t)(r[2] - r[0]), h = (size_t)(r[3] - r[1]);
    size_t y, x;
    render_stats st = info->stats;
    uint8_t *b = mem_alloc(n), *px, *ids, *idm;
    uint64_t bits;
    int i;
    if (!b)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory for a %zux%zu region", w, h);
    memset(b, 0, RENDER_PART_HEADER);
    memcpy(b, render_part_magic, 8);
    render_part_put32(b + 8, (uint32_t)info->width);
    render_part_put32(b + 12, (uint32_t)info->height);
    for (i = 0; i < 4; i++)
        render_part_put32(b + 16 + 4 * i, (uint32_t)r[i]);
    render_part_put32(b + 32, (uint32_t)info->aa);
    memcpy(b + 36, info->mode, strnlen(info->mode, 8));
    render_part_put32(b + 44, info->ids ? RENDER_PART_IDS : 0);
    for (i = 0; i < RENDER_PART_COUNTERS; i++)
        render_part_put64(b + 48 + 8 * i, *render_part_counter(&st, i));
    memcpy(&bits, &st.time_compile_s, 8);
    render_part_put64(b + RENDER_PART_HEADER - 16, bits);
    memcpy(&bits, &st.time_render_s, 8);
    render_part_put64(b + RENDER_PART_HEADER - 8, bits);
    px = b + RENDER_PART_HEADER;
    ids = px + 3 * w * h;
    idm = ids + 4 * w * h;
    for (y = 0; y < h; y++) {
        size_t row = (size_t)(r[1] + (int)y) * (size_t)info->width + (size_t)r[0];
        memcpy(px + 3 * w * y, fb->img.px + 3 * row, 3 * w);
        for (x = 0; x < w; x++) {
            render_part_put32(ids + 4 * (w * y + x), (uint32_t)fb->pid[row + x]);
            if (info->ids)
                render_part_put_id(idm + RENDER_PART_ID_PX * (w * y + x), &fb->ids.px[row + x]);
        }
    }
    *out = b;
    *len = n;
    return 0;
}

int render_part_decode(const char *name, const uint8_t *buf, size_t len, render_part_info *info,
                       diag *err)
{
    render_part_info in;
    uint64_t bits;
    int i;
    memset(&in, 0, sizeof in);
    /* an older format's header places fields elsewhere: named, not misread */
    if (len >= 8 && !memcmp(buf, render_part_magic, 7) && buf[7] >= '1' && buf[7] < render_part_magic[7])
        return diag_offset(err, DIAG_INPUT, name, 0, "a region file of format %c (%.8s, made by an "
                           "older maprt); this maprt reads format %c (%.8s): render the part again",
                           buf[7], (const char *)buf, render_part_magic[7], render_part_magic);
    if (len < RENDER_PART_HEADER)
        return diag_offset(err, DIAG_INPUT, name, (long long)len,
                           "a region file has a %d-byte header; this one ends first",
                           RENDER_PART_HEADER);
    if (memcmp(buf, render_part_magic, 8))
        return diag_offset(err, DIAG_INPUT, name, 0, "not a maprt region file (magic %.8s)",
                           render_part_magic);
    if (render_part_get32(buf + 8) < 1 || render_part_get32(buf + 8) > SCENE_MAX_SIDE ||
        render_part_get32(buf + 12) < 1 || render_part_get32(buf + 12) > SCENE_MAX_SIDE)
        return diag_offset(err, DIAG_INPUT, name, 8, "image size %lux%lu is outside 1..%d",
                           (unsigned long)render_part_get32(buf + 8),
                           (unsigned long)render_part_get32(buf + 12), SCENE_MAX_SIDE);
    in.width = (int)render_part_get32(buf + 8);
    in.height = (int)render_part_get32(buf + 12);
    for (i = 0; i < 4; i++) {
        uint32_t v = render_part_get32(buf + 16 + 4 * i);
        if (v > SCENE_MAX_SIDE)
            return diag_offset(err, DIAG_INPUT, name, 16 + 4 * i, "region coordinate %lu is "
                               "outside the image", (unsigned long)v);
        in.region[i] = (int)v;
    }
    if (render_region_check(in.region, in.width, in.height) || !in.region[2])
        return diag_offset(err, DIAG_INPUT, name, 16, "region %d,%d,%d,%d is not inside the %dx%d "
                           "image", in.region[0], in.region[1], in.region[2], in.region[3],
                           in.width, in.height);
    in.aa = (int)render_part_get32(buf + 32);
    if (in.aa < 1 || in.aa > RENDER_MAX_AA)
        return diag_offset(err, DIAG_INPUT, name, 32, "samples per side %d is outside 1..%d",
                           in.aa, RENDER_MAX_AA);
    memcpy(in.mode, buf + 36, 8);
    for (i = 0; i < 8 && in.mode[i]; i++)
        if (in.mode[i] < 'a' || in.mode[i] > 'z') {
            if (in.mode[i] >= '0' && in.mode[i] <= '9')
                continue;
            return diag_offset(err, DIAG_INPUT, name, 36 + i, "numeric mode name is not "
                               "lower-case letters and digits");
        }
    if (!in.mode[0])
        return diag_offset(err, DIAG_INPUT, name, 36, "numeric mode name is empty");
    if (render_part_get32(buf + 44) & ~(uint32_t)RENDER_PART_IDS)
        return diag_offset(err, DIAG_INPUT, name, 44, "contents word 0x%lx has bits other than "
                           "the identity map's (0x%x)", (unsigned long)render_part_get32(buf + 44),
                           RENDER_PART_IDS);
    in.ids = (render_part_get32(buf + 44) & RENDER_PART_IDS) != 0;
    for (i = 0; i < RENDER_PART_COUNTERS; i++)
        *render_part_counter(&in.stats, i) = render_part_get64(buf + 48 + 8 * i);
    bits = render_part_get64(buf + RENDER_PART_HEADER - 16);
    memcpy(&in.stats.time_compile_s, &bits, 8);
    bits = render_part_get64(buf + RENDER_PART_HEADER - 8);
    memcpy(&in.stats.time_render_s, &bits, 8);
    if (len != render_part_bytes(in.region, in.ids))
        return diag_offset(err, DIAG_INPUT, name,
                           (long long)(len < render_part_bytes(in.region, in.ids)
                                       ? len : render_part_bytes(in.region, in.ids)),
                           "region %d,%d,%d,%d needs %zu bytes%s; the file has %zu", in.region[0],
                           in.region[1], in.region[2], in.region[3],
                           render_part_bytes(in.region, in.ids),
                           in.ids ? " with its identity map" : "", len);
    *info = in;
    return 0;
}

int render_part_place(const char *name, const uint8_t *buf, const render_part_info *info,
                      render_fb *fb, uint8_t *covered, diag *err)
{
    const int *r = info->region;
    size_t w = (size_t)(r[2] - r[0]), h = (size_t)(r[3] - r[1]), x, y;
    const uint8_t *px = buf + RENDER_PART_HEADER, *ids = px + 3 * w * h, *idm = ids + 4 * w * h;
    for (y = 0; y < h; y++) {
        size_t row = (size_t)(r[1] + (int)y) * (size_t)info->width + (size_t)r[0];
        for (x = 0; x < w; x++)
            if (covered[row + x])
                return diag_at(err, DIAG_INPUT, name, 0, 0, "pixel %zu,%zu is in two regions",
                               (size_t)r[0] + x, (size_t)r[1] + y);
        memset(covered + row, 1, w);
        memcpy(fb->img.px + 3 * row, px + 3 * w * y, 3 * w);
        for (x = 0; x < w; x++) {
            fb->pid[row + x] = (int32_t)render_part_get32(ids + 4 * (w * y + x));
            if (info->ids)
                render_part_get_id(idm + RENDER_PART_ID_PX * (w * y + x), &fb->ids.px[row + x]);
        }
    }
    return 0;
}
