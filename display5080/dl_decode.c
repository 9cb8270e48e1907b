/* dl_decode — strict DL5080 and raw MegaPel parsing into visitor calls (see
 * dl_decode.h). Every size is checked against the bytes actually present
 * before it is used; nothing is allocated, so no count can cause an
 * allocation. */
#include "display5080/dl_decode.h"
#include <string.h>

void dl_element_point(const dl_element *e, unsigned i, int *x, int *y)
{
    *x = dl_bes16(e->data + 4 * (size_t)i);
    *y = dl_bes16(e->data + 4 * (size_t)i + 2);
}

uint32_t dl_element_colour(const dl_element *e, unsigned i) { return dl_be32(e->data + 4 * (size_t)i); }

void dl_element_run(const dl_element *e, unsigned i, unsigned *count, unsigned *colour)
{
    *count = dl_be16(e->data + 4 * (size_t)i);
    *colour = dl_be16(e->data + 4 * (size_t)i + 2);
}

typedef struct dl_cursor {
    const char *name;
    unsigned version;          /* 0 raw, 1 or 2 */
    dl_element *e;
    const uint8_t *p;          /* payload */
    size_t n;                  /* payload bytes */
    diag *err;
} dl_cursor;

static int dl_decode_bad(dl_cursor *c, const char *what)
{
    return diag_offset(c->err, DIAG_INPUT, c->name, c->e->offset, "%s (0x%04X): %s",
                       dl_format_name(c->e->code), c->e->code, what);
}

/* Lower-left and upper-right corners at p; the corners must be ordered. */
static int dl_decode_rect(dl_cursor *c, const uint8_t *p)
{
    dl_element *e = c->e;
    e->x0 = dl_bes16(p);
    e->y0 = dl_bes16(p + 2);
    e->x1 = dl_bes16(p + 4);
    e->y1 = dl_bes16(p + 6);
    if (e->x1 < e->x0 || e->y1 < e->y0)
        return dl_decode_bad(c, "upper-right corner is left of or below the lower-left corner");
    return 0;
}

static int dl_decode_index(dl_cursor *c, unsigned v)
{
    char msg[64];
    if (v > 255) {
        snprintf(msg, sizeof msg, "colour index %u is above 255", v);
        return dl_decode_bad(c, msg);
    }
    return 0;
}

static int dl_decode_op(dl_cursor *c, unsigned op)
{
    char msg[64];
    if (op < 1 || op > 16) {
        snprintf(msg, sizeof msg, "logic op %u is outside 1..16", op);
        return dl_decode_bad(c, msg);
    }
    return 0;
}

/* A single u16 argument. */
static int dl_decode_word(dl_cursor *c)
{
    if (c->n != 2)
        return dl_decode_bad(c, "payload must be one 16-bit word");
    c->e->value = dl_be16(c->p);
    return 0;
}

/* A single u16 argument in [lo, hi]. */
static int dl_decode_ranged(dl_cursor *c, const char *what, unsigned lo, unsigned hi)
{
    char msg[96];
    if (dl_decode_word(c))
        return DIAG_INPUT;
    if (c->e->value < lo || c->e->value > hi) {
        snprintf(msg, sizeof msg, "%s %u is outside %u..%u", what, c->e->value, lo, hi);
        return dl_decode_bad(c, msg);
    }
    return 0;
}

/* Inline data of `want` bytes after `head` payload bytes: the element pads
 * only at its end, with one zero byte when want is odd. */
static int dl_decode_inline(dl_cursor *c, size_t head, unsigned long long want, const char *what)
{
    char msg[128];
    unsigned long long have = c->n - head;
    if (have != want + (want & 1u)) {
        snprintf(msg, sizeof msg, "%s need %llu bytes, payload has %llu", what, want, have);
        return dl_decode_bad(c, msg);
    }
    if ((want & 1u) && c->p[c->n - 1])
        return dl_decode_bad(c, "pad byte is not zero");
    return 0;
}

/* The fixed part shared by both inline BLTs: rectangle, a word (bits/pixel
 * or colour), logic op; *w and *h receive the rectangle's size. */
static int dl_decode_blt_head(dl_cursor *c, const char *what, unsigned long long *w,
                              unsigned long long *h)
{
    dl_element *e = c->e;
    char msg[96];
    if (c->n < 12) {
        snprintf(msg, sizeof msg, "payload shorter than rectangle, %s and logic op (12 bytes)", what);
        return dl_decode_bad(c, msg);
    }
    if (dl_decode_rect(c, c->p))
        return DIAG_INPUT;
    e->value = dl_be16(c->p + 8);
    e->op = dl_be16(c->p + 10);
    *w = (unsigned long long)(e->x1 - e->x0) + 1;
    *h = (unsigned long long)(e->y1 - e->y0) + 1;
    return dl_decode_op(c, e->op);
}

/* BLT immediate: version 2 and raw streams carry the rows top-first from the
 * rectangle's upper edge, packed (mpelImg.c); version 1 carried them
 * bottom-first with every odd row padded, and is read as it was written. */
static int dl_decode_blt(dl_cursor *c)
{
    dl_element *e = c->e;
    unsigned long long w, h;
    char msg[128];
    if (dl_decode_blt_head(c, "depth", &w, &h))
        return DIAG_INPUT;
    if (e->value != DL_BLT_BPP) {
        snprintf(msg, sizeof msg, "%u bits per pixel (only 8 is defined)", e->value);
        return dl_decode_bad(c, msg);
    }
    if (c->version == DL_VERSION_1) {
        unsigned long long row = w + (w & 1u);
        if (c->n - 12 != h * row) {
            snprintf(msg, sizeof msg, "%llux%llu pixels need %llu bytes, payload has %zu", w, h,
                     h * row, c->n - 12);
            return dl_decode_bad(c, msg);
        }
        e->data = c->p + 12;
        e->stride = (ptrdiff_t)row;
        return 0;
    }
    snprintf(msg, sizeof msg, "%llux%llu pixels", w, h);
    if (dl_decode_inline(c, 12, w * h, msg))
        return DIAG_INPUT;
    e->data = c->p + 12 + (size_t)((h - 1) * w);
    e->stride = -(ptrdiff_t)w;
    return 0;
}

/* BLT immediate with colour expansion: 1 bit a pixel, MSB first, rows
 * top-first and packed; the rectangle is a whole number of bytes wide
 * (mpelCursor.c, mpelMono.c). */
static int dl_decode_blt_expand(dl_cursor *c)
{
    dl_element *e = c->e;
    unsigned long long w, h;
    char msg[128];
    if (dl_decode_blt_head(c, "colour", &w, &h) || dl_decode_index(c, e->value))
        return DIAG_INPUT;
    if (w % 8) {
        snprintf(msg, sizeof msg, "width %llu is not a whole number of bytes", w);
        return dl_decode_bad(c, msg);
    }
    snprintf(msg, sizeof msg, "%llux%llu bits", w, h);
    if (dl_decode_inline(c, 12, w / 8 * h, msg))
        return DIAG_INPUT;
    e->data = c->p + 12 + (size_t)((h - 1) * (w / 8));
    e->stride = -(ptrdiff_t)(w / 8);
    return 0;
}

static int dl_decode_payload(dl_cursor *c)
{
    dl_element *e = c->e;
    const uint8_t *p = c->p;
    size_t n = c->n, i;
    char msg[96];
    switch (e->code) {
    case DL_POLYLINE:
        if (n % 4 || n < 8)
            return dl_decode_bad(c, "payload is not n points of 4 bytes with n >= 2");
        e->count = (unsigned)(n / 4);
        e->data = p;
        return 0;
    case DL_SEGMENTS:
        if (n % 8 || n < 8)
            return dl_decode_bad(c, "payload is not k >= 1 pairs of 4-byte points");
        e->count = (unsigned)(n / 4);
        e->data = p;
        return 0;
    case DL_FILL_RECT: case DL_VIEWPORT: case DL_SCISSOR:
        if (n != 8)
            return dl_decode_bad(c, "payload must be two points (8 bytes)");
        return dl_decode_rect(c, p);
    case DL_FILL_CIRCLE: case DL_CIRCLE:
        if (n != 6)
            return dl_decode_bad(c, "payload must be a centre and a radius (6 bytes)");
        e->x0 = dl_bes16(p);
        e->y0 = dl_bes16(p + 2);
        e->value = dl_be16(p + 4);
        return 0;
    case DL_BEGIN_POLYGON: case DL_END_POLYGON: case DL_END:
        return n ? dl_decode_bad(c, "element takes no payload") : 0;
    case DL_TEXT:
        if (n < 6)
            return dl_decode_bad(c, "payload shorter than point and count (6 bytes)");
        e->x0 = dl_bes16(p);
        e->y0 = dl_bes16(p + 2);
        e->count = dl_be16(p + 4);
        e->data = p + 6;
        if (n != 6 + (size_t)e->count + (e->count & 1u)) {
            snprintf(msg, sizeof msg, "%u text bytes do not match a payload of %zu bytes",
                     e->count, n);
            return dl_decode_bad(c, msg);
        }
        if ((e->count & 1u) && p[n - 1])
            return dl_decode_bad(c, "pad byte is not zero");
        return 0;
    case DL_SRC_BLT:
        if (n != 16)
            return dl_decode_bad(c, "payload must be address, rectangle, depth and logic op (16 bytes)");
        e->addr = dl_be32(p);
        if (dl_decode_rect(c, p + 4))
            return DIAG_INPUT;
        e->value = dl_be16(p + 12);
        e->op = dl_be16(p + 14);
        if (e->value != DL_BLT_BPP) {
            snprintf(msg, sizeof msg, "%u bits per pixel (only 8 is defined)", e->value);
            return dl_decode_bad(c, msg);
        }
        return dl_decode_op(c, e->op);
    case DL_BLT:
        return dl_decode_blt(c);
    case DL_BLT_EXPAND:
        return dl_decode_blt_expand(c);
    case DL_NOOP:
        e->count = (unsigned)n;
        e->data = p;
        return 0;
    case DL_LINE_TYPE:
        if (dl_decode_word(c))
            return DIAG_INPUT;
        if (e->value != DL_LINE_SOLID && (c->version == DL_VERSION_1 ||
                                          (e->value != DL_LINE_USER && e->value != DL_LINE_USER_CONT))) {
            snprintf(msg, sizeof msg, "line type %u is not supported (%s)", e->value,
                     c->version == DL_VERSION_1 ? "version 1 has only 1, solid"
                                                : "1 solid, 50 user style, 150 continued user style");
            return dl_decode_bad(c, msg);
        }
        return 0;
    case DL_LINE_COLOUR: case DL_INTERIOR_COLOUR: case DL_TEXT_COLOUR: case DL_EDGE_COLOUR:
    case DL_CLEAR:
        return dl_decode_word(c) ? DIAG_INPUT : dl_decode_index(c, e->value);
    case DL_CHAR_HEIGHT:
        return dl_decode_ranged(c, "character height", 1, DL_MAX_CHAR_HEIGHT);
    case DL_LINE_WIDTH:
        return dl_decode_ranged(c, "line width", 1, DL_MAX_LINE_WIDTH);
    case DL_CHAR_UP:
        if (n != 4)
            return dl_decode_bad(c, "payload must be an up vector (4 bytes)");
        e->x0 = dl_bes16(p);
        e->y0 = dl_bes16(p + 2);
        if (!e->x0 && !e->y0)
            return dl_decode_bad(c, "up vector is zero");
        return 0;
    case DL_INTERIOR_STYLE:
        if (dl_decode_word(c))
            return DIAG_INPUT;
        if (e->value != DL_INTERIOR_SOLID) {
            snprintf(msg, sizeof msg, "interior style %u is not supported (only 2, solid)", e->value);
            return dl_decode_bad(c, msg);
        }
        return 0;
    case DL_EDGE_FLAG:
        return dl_decode_ranged(c, "edge flag", DL_EDGE_ON, DL_EDGE_OFF);
    case DL_CODE_PAGE:
        if (dl_decode_word(c))
            return DIAG_INPUT;
        if (e->value != DL_CP_EBCDIC && e->value != DL_CP_PC && e->value != DL_CP_LATIN1) {
            snprintf(msg, sizeof msg, "code page %u is not supported (37, 437 or 819)", e->value);
            return dl_decode_bad(c, msg);
        }
        return 0;
    case DL_USER_LINE_STYLE:
        if (n != 4)
            return dl_decode_bad(c, "payload must be a mask and a factor (4 bytes)");
        e->value = dl_be16(p);
        e->count = dl_be16(p + 2);
        return 0;
    case DL_LOGIC_OP:
        return dl_decode_word(c) ? DIAG_INPUT : dl_decode_op(c, e->value);
    case DL_PLANE_MASK:
        if (dl_decode_word(c))
            return DIAG_INPUT;
        if (c->version == DL_VERSION_1) {
            e->planes = e->value & 0xFFu;   /* version 1: low byte, 1 = writable */
            return 0;
        }
        if (e->value & 0xFFu) {
            snprintf(msg, sizeof msg, "low byte 0x%02X is not 0 (the mask is the high byte)",
                     e->value & 0xFFu);
            return dl_decode_bad(c, msg);
        }
        e->planes = dl_format_mask_planes(e->value);
        return 0;
    case DL_LOAD_COLOURS:
        if (n < 4)
            return dl_decode_bad(c, "payload shorter than start and count (4 bytes)");
        e->start = dl_be16(p);
        e->count = dl_be16(p + 2);
        e->data = p + 4;
        if (n != 4 + 4 * (size_t)e->count) {
            snprintf(msg, sizeof msg, "%u colours do not match a payload of %zu bytes",
                     e->count, n);
            return dl_decode_bad(c, msg);
        }
        if (e->start + e->count > DL_COLOURS) {
            snprintf(msg, sizeof msg, "entries %u..%u run past the 256-entry table", e->start,
                     e->start + e->count - 1);
            return dl_decode_bad(c, msg);
        }
        for (i = 0; i < e->count; i++)
            if (p[4 + 4 * i]) {
                snprintf(msg, sizeof msg, "colour %zu is not of the form 0x00RRGGBB", i);
                return dl_decode_bad(c, msg);
            }
        return 0;
    case DL_RUN_ROW:
        if (n < 6)
            return dl_decode_bad(c, "payload shorter than y, x0 and run count (6 bytes)");
        e->y0 = dl_bes16(p);
        e->x0 = dl_bes16(p + 2);
        e->count = dl_be16(p + 4);
        e->data = p + 6;
        if (n != 6 + 4 * (size_t)e->count) {
            snprintf(msg, sizeof msg, "%u runs do not match a payload of %zu bytes", e->count, n);
            return dl_decode_bad(c, msg);
        }
        for (i = 0; i < e->count; i++)
            if (dl_decode_index(c, dl_be16(e->data + 4 * i + 2)))
                return DIAG_INPUT;
        return 0;
    default:
        return diag_offset(c->err, DIAG_INPUT, c->name, e->offset, "unknown element code 0x%04X",
                           e->code);
    }
}

/* Is the code allowed here: known, in this version, MegaPel's in a raw stream? */
static int dl_decode_known(dl_cursor *c)
{
    dl_element *e = c->e;
    int slot = dl_format_slot(e->code);
    if (slot < 0)
        return diag_offset(c->err, DIAG_INPUT, c->name, e->offset, "unknown element code 0x%04X",
                           e->code);
    if (c->version == 0 && dl_format_codes[slot].own)
        return dl_decode_bad(c, "maprt's own element, not MegaPel's: not allowed in a raw stream");
    if (c->version && dl_format_codes[slot].since > c->version)
        return diag_offset(c->err, DIAG_INPUT, c->name, e->offset,
                           "element code 0x%04X (%s) is not defined in DL5080 version %u", e->code,
                           dl_format_codes[slot].name, c->version);
    return 0;
}

static int dl_decode_header(const uint8_t *buf, size_t len, const char *name, dl_header *h,
                            diag *err)
{
    unsigned reserved;
    if (len < DL_HEADER_SIZE)
        return diag_offset(err, DIAG_INPUT, name, 0,
                           "file of %zu bytes is shorter than the 16-byte header", len);
    if (memcmp(buf, dl_magic, sizeof dl_magic))
        return diag_offset(err, DIAG_INPUT, name, 0,
                           "not a DL5080 file (bad magic; a raw MegaPel stream needs --raw)");
    h->version = dl_be16(buf + 6);
    h->flags = dl_be16(buf + 8);
    h->width = (int)dl_be16(buf + 10);
    h->height = (int)dl_be16(buf + 12);
    reserved = dl_be16(buf + 14);
    if (h->version != DL_VERSION && h->version != DL_VERSION_1)
        return diag_offset(err, DIAG_INPUT, name, 6, "unsupported version %u (expected 1 or %d)",
                           h->version, DL_VERSION);
    if (h->flags & ~DL_FLAG_DAC8)
        return diag_offset(err, DIAG_INPUT, name, 8, "unknown flag bits 0x%04X",
                           h->flags & ~DL_FLAG_DAC8);
    if (h->width < 1 || h->width > DL_MAX_SIDE)
        return diag_offset(err, DIAG_INPUT, name, 10, "width %d is outside 1..%d", h->width,
                           DL_MAX_SIDE);
    if (h->height < 1 || h->height > DL_MAX_SIDE)
        return diag_offset(err, DIAG_INPUT, name, 12, "height %d is outside 1..%d", h->height,
                           DL_MAX_SIDE);
    if (reserved)
        return diag_offset(err, DIAG_INPUT, name, 14, "reserved header word is 0x%04X, not 0",
                           reserved);
    return 0;
}

/* The header a raw stream stands for; 0 or DIAG_INPUT for a bad size. */
static int dl_decode_raw_header(const dl_decode_opts *o, const char *name, dl_header *h, diag *err)
{
    h->version = 0;
    h->flags = o->flags & DL_FLAG_DAC8;
    h->width = o->width ? o->width : DL_RAW_SIDE;
    h->height = o->height ? o->height : DL_RAW_SIDE;
    if (h->width < 1 || h->width > DL_MAX_SIDE || h->height < 1 || h->height > DL_MAX_SIDE)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "raw screen %dx%d is outside 1..%d", h->width,
                       h->height, DL_MAX_SIDE);
    return 0;
}

int dl_decode(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
              const dl_visitor *v, void *ctx, dl_header *hout, diag *err)
{
    dl_header h;
    dl_element e;
    dl_cursor c;
    int raw = opts && opts->raw;
    size_t off = raw ? 0 : DL_HEADER_SIZE;
    unsigned long steps = 0, limit = opts && opts->max_elements ? opts->max_elements
                                                               : DL_DECODE_MAX_ELEMENTS;
    int polygon = 0;   /* 0 outside, 1 after begin, 2 after its polyline */
    int rc;
    if ((rc = raw ? dl_decode_raw_header(opts, name, &h, err)
                  : dl_decode_header(buf, len, name, &h, err)))
        return rc;
    if (v && v->header && (rc = v->header(ctx, &h, err)))
        return rc;
    for (;;) {
        size_t left = len - off;
        unsigned elen;
        if (left == 0) {
            if (raw && polygon)
                return diag_offset(err, DIAG_INPUT, name, (long long)off,
                                   "stream ends inside a polygon");
            if (raw)
                break;   /* a raw stream ends where its bytes do */
            return diag_offset(err, DIAG_INPUT, name, (long long)off,
                               "missing end element (0x5F02)");
        }
        if (left < 4)
            return diag_offset(err, DIAG_INPUT, name, (long long)off,
                               "truncated element head (%zu bytes left)", left);
        if (++steps > limit)
            return diag_offset(err, DIAG_INPUT, name, (long long)off,
                               "step limit of %lu elements reached", limit);
        memset(&e, 0, sizeof e);
        elen = dl_be16(buf + off);
        e.code = dl_be16(buf + off + 2);
        e.offset = (long long)off;
        e.length = elen;
        if (elen < 4)
            return diag_offset(err, DIAG_INPUT, name, e.offset, "element length %u is below 4", elen);
        if (elen & 1u)
            return diag_offset(err, DIAG_INPUT, name, e.offset, "element length %u is odd", elen);
        if (elen > left)
            return diag_offset(err, DIAG_INPUT, name, e.offset,
                               "element length %u runs past the end of the file (%zu bytes left)",
                               elen, left);
        c.name = name;
        c.version = h.version;
        c.e = &e;
        c.p = buf + off + 4;
        c.n = elen - 4u;
        c.err = err;
        if ((rc = dl_decode_known(&c)) || (rc = dl_decode_payload(&c)))
            return rc;
        /* A polygon is exactly: begin, one polyline, end. */
        if (polygon == 1 && e.code != DL_POLYLINE)
            return dl_decode_bad(&c, "expected the polygon's boundary polyline after begin-polygon");
        if (polygon == 2 && e.code != DL_END_POLYGON)
            return dl_decode_bad(&c, "expected end-polygon after the boundary polyline");
        if (e.code == DL_END_POLYGON && polygon != 2)
            return dl_decode_bad(&c, "end-polygon without begin-polygon and boundary");
        e.in_polygon = polygon == 1;
        if (e.code == DL_BEGIN_POLYGON)
            polygon = 1;
        else if (polygon == 1)
            polygon = 2;
        else if (e.code == DL_END_POLYGON)
            polygon = 0;
        if (e.code == DL_END && off + elen != len)
            return diag_offset(err, DIAG_INPUT, name, (long long)(off + elen),
                               "%zu bytes after the end element", len - off - elen);
        if (v && v->element && (rc = v->element(ctx, &e, err)))
            return rc;
        if (e.code == DL_END)
            break;
        off += elen;
    }
    if (hout)
        *hout = h;
    return 0;
}
