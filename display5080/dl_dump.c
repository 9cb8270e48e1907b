/* dl_dump — display list disassembler (see dl_dump.h). */
#include "display5080/dl_dump.h"
#include "display5080/dl_decode.h"
#include "util/mem.h"
#include <iconv.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

typedef struct dl_dump_ctx {
    dl_dump_write write;
    void *wctx;
    char *line;                /* one growing line buffer */
    size_t len, cap;
    int oom;
    iconv_t cd;
    unsigned code_page;        /* as set by the list, for text */
} dl_dump_ctx;

static void dl_dump_add(dl_dump_ctx *c, const char *fmt, ...)
{
    va_list ap;
    void *p = c->line;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0 || c->oom)
        return;
    if (mem_grow(&p, &c->cap, c->len + (size_t)n + 1, 1)) {
        c->oom = 1;
        return;
    }
    c->line = p;
    va_start(ap, fmt);
    vsnprintf(c->line + c->len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    c->len += (size_t)n;
}

static void dl_dump_flush(dl_dump_ctx *c)
{
    dl_dump_add(c, "\n");
    if (!c->oom)
        c->write(c->wctx, c->line, c->len);
    c->len = 0;
}

static int dl_dump_header(void *ctx, const dl_header *h, diag *err)
{
    dl_dump_ctx *c = ctx;
    (void)err;
    if (h->version == 0)
        dl_dump_add(c, "%7d %6d  ----  raw MegaPel stream dac=%d size=%dx%d", 0, 0,
                    h->flags & DL_FLAG_DAC8 ? 8 : 4, h->width, h->height);
    else
        dl_dump_add(c, "%7d %6d  ----  header version=%u flags=0x%04X dac=%d size=%dx%d", 0,
                    DL_HEADER_SIZE, h->version, h->flags, h->flags & DL_FLAG_DAC8 ? 8 : 4,
                    h->width, h->height);
    dl_dump_flush(c);
    return 0;
}

static void dl_dump_text(dl_dump_ctx *c, const dl_element *e)
{
    unsigned i;
    dl_dump_add(c, " \"");
    for (i = 0; i < e->count; i++) {
        char in = (char)e->data[i], out[8] = {0}, *ip = &in, *op = out;
        size_t il = 1, ol = sizeof out - 1;
        unsigned char ch;
        if (c->code_page != DL_CP_EBCDIC) {
            out[0] = (char)e->data[i];
        } else if (c->cd == (iconv_t)-1 || iconv(c->cd, &ip, &il, &op, &ol) == (size_t)-1 ||
                   op - out != 1) {
            dl_dump_add(c, "\\x%02X", e->data[i]);
            continue;
        }
        ch = (unsigned char)out[0];
        if (ch < 0x20 || ch > 0x7E || ch == '"' || ch == '\\')
            dl_dump_add(c, "\\x%02X", ch);
        else
            dl_dump_add(c, "%c", ch);
    }
    dl_dump_add(c, "\"");
}

static int dl_dump_element(void *ctx, const dl_element *e, diag *err)
{
    dl_dump_ctx *c = ctx;
    unsigned i, a, b;
    int x, y;
    dl_dump_add(c, "%7lld %6u  %04X  %s", e->offset, e->length, e->code, dl_format_name(e->code));
    switch (e->code) {
    case DL_POLYLINE: case DL_SEGMENTS:
        dl_dump_add(c, " n=%u", e->count);
        for (i = 0; i < e->count; i++) {
            dl_element_point(e, i, &x, &y);
            dl_dump_add(c, " %d,%d", x, y);
        }
        break;
    case DL_FILL_RECT: case DL_VIEWPORT: case DL_SCISSOR:
        dl_dump_add(c, " %d,%d %d,%d", e->x0, e->y0, e->x1, e->y1);
        break;
    case DL_FILL_CIRCLE: case DL_CIRCLE:
        dl_dump_add(c, " %d,%d r=%u", e->x0, e->y0, e->value);
        break;
    case DL_TEXT:
        dl_dump_add(c, " %d,%d n=%u", e->x0, e->y0, e->count);
        dl_dump_text(c, e);
        break;
    case DL_BLT:
        dl_dump_add(c, " %d,%d %d,%d bpp=%u op=%u (%dx%d pixels)", e->x0, e->y0, e->x1, e->y1,
                    e->value, e->op, e->x1 - e->x0 + 1, e->y1 - e->y0 + 1);
        break;
    case DL_BLT_EXPAND:
        dl_dump_add(c, " %d,%d %d,%d colour=%u op=%u (%dx%d bits)", e->x0, e->y0, e->x1, e->y1,
                    e->value, e->op, e->x1 - e->x0 + 1, e->y1 - e->y0 + 1);
        break;
    case DL_SRC_BLT:
        dl_dump_add(c, " addr=0x%08lX %d,%d %d,%d bpp=%u op=%u (pixels in adapter memory)",
                    (unsigned long)e->addr, e->x0, e->y0, e->x1, e->y1, e->value, e->op);
        break;
    case DL_CHAR_UP:
        dl_dump_add(c, " %d,%d", e->x0, e->y0);
        break;
    case DL_USER_LINE_STYLE:
        dl_dump_add(c, " mask=0x%04X factor=%u", e->value, e->count);
        break;
    case DL_CODE_PAGE:
        c->code_page = e->value;
        dl_dump_add(c, " %u", e->value);
        break;
    case DL_NOOP:
        dl_dump_add(c, " %u bytes", e->count);
        break;
    case DL_PLANE_MASK:
        dl_dump_add(c, " 0x%04X (writes planes 0x%02X)", e->value, e->planes);
        break;
    case DL_LINE_TYPE: case DL_LINE_COLOUR: case DL_INTERIOR_COLOUR: case DL_LOGIC_OP:
    case DL_CLEAR: case DL_TEXT_COLOUR: case DL_CHAR_HEIGHT: case DL_INTERIOR_STYLE:
    case DL_EDGE_FLAG: case DL_EDGE_COLOUR: case DL_LINE_WIDTH:
        dl_dump_add(c, " %u", e->value);
        break;
    case DL_LOAD_COLOURS:
        dl_dump_add(c, " start=%u n=%u", e->start, e->count);
        for (i = 0; i < e->count; i++)
            dl_dump_add(c, " #%06lX", (unsigned long)dl_element_colour(e, i));
        break;
    case DL_RUN_ROW:
        dl_dump_add(c, " y=%d x0=%d n=%u", e->y0, e->x0, e->count);
        for (i = 0; i < e->count; i++) {
            dl_element_run(e, i, &a, &b);
            dl_dump_add(c, " %ux%u", a, b);
        }
        break;
    default:
        break;
    }
    dl_dump_flush(c);
    if (c->oom)
        return diag_offset(err, DIAG_IO, "dump", e->offset, "out of memory");
    return 0;
}

int dl_dump(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
            dl_dump_write write, void *wctx, diag *err)
{
    static const dl_visitor v = {.header = dl_dump_header, .element = dl_dump_element};
    dl_dump_ctx c;
    int rc;
    memset(&c, 0, sizeof c);
    c.write = write;
    c.wctx = wctx;
    c.cd = iconv_open("ASCII", "IBM037");
    c.code_page = DL_CP_EBCDIC;
    rc = dl_decode(buf, len, name, opts, &v, &c, NULL, err);
    if (c.cd != (iconv_t)-1)
        iconv_close(c.cd);
    mem_free(c.line);
    return rc;
}
