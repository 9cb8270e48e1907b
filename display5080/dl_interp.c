/* dl_interp — the 5081 display model (see dl_interp.h). State at the start of
 * a list: colour table 0 = black, 1 = white, rest black; polyline, interior,
 * text and edge colour 1; logic op 4 (copy, IBM's reset value); plane mask all
 * planes (IBM's reset word 0); line type 1 (solid), user style 0xFFFF factor
 * 1, width 1; character height 12, up vector (0,1), code page 37; edge flag
 * 2 (no edge); scissor and viewport the whole screen. */
#include "display5080/dl_interp.h"
#include "display5080/dl_font.h"
#include "util/mem.h"
#include <math.h>
#include <string.h>

#define DL_INTERP_CHAR_HEIGHT 12

void dl_interp_init(dl_interp *in, const char *name, int force_dac, unsigned long long work_limit,
                    dl_interp_open_fn open, void *octx)
{
    memset(in, 0, sizeof *in);
    in->name = name;
    in->force_dac = force_dac;
    in->open = open;
    in->octx = octx;
    dl_work_init(&in->work, work_limit);
    dl_cover_init(&in->cover, &in->work);
}

void dl_interp_free(dl_interp *in)
{
    mem_free(in->pts);
    mem_free(in->poly);
    in->pts = in->poly = NULL;
    in->pts_cap = in->poly_cap = 0;
    dl_cover_free(&in->cover);
}

void dl_interp_palette(const dl_interp *in, uint8_t rgb[768])
{
    int i;
    for (i = 0; i < 256; i++) {
        rgb[3 * i] = dl_interp_gun((in->lut[i] >> 16) & 0xFFu, in->dac);
        rgb[3 * i + 1] = dl_interp_gun((in->lut[i] >> 8) & 0xFFu, in->dac);
        rgb[3 * i + 2] = dl_interp_gun(in->lut[i] & 0xFFu, in->dac);
    }
}

static int dl_interp_header(void *ctx, const dl_header *h, diag *err)
{
    dl_interp *in = ctx;
    in->width = h->width;
    in->height = h->height;
    in->version = h->version;
    in->dac = in->force_dac ? in->force_dac : (h->flags & DL_FLAG_DAC8) ? 8 : 4;
    memset(in->lut, 0, sizeof in->lut);
    in->lut[1] = 0xFFFFFFu;
    in->line_colour = in->interior_colour = in->text_colour = in->edge_colour = 1;
    in->op = DL_OP_COPY;
    in->mask = 0xFF;
    in->line_type = DL_LINE_SOLID;
    in->style_mask = 0xFFFF;
    in->style_factor = 1;
    in->line_width = 1;
    in->char_height = DL_INTERP_CHAR_HEIGHT;
    in->up_x = 0;
    in->up_y = 1;
    in->code_page = DL_CP_EBCDIC;
    in->edge_flag = DL_EDGE_OFF;
    in->sx0 = in->vx0 = 0;
    in->sy0 = in->vy0 = 0;
    in->sx1 = in->vx1 = h->width - 1;
    in->sy1 = in->vy1 = h->height - 1;
    return in->open(in->octx, h->width, h->height, &in->ops, &in->dev, err);
}

/* The clip (scissor within the screen) as a box; 0 if it is empty. */
static int dl_interp_clip(const dl_interp *in, dl_box *c)
{
    c->x0 = in->sx0 > 0 ? in->sx0 : 0;
    c->y0 = in->sy0 > 0 ? in->sy0 : 0;
    c->x1 = in->sx1 < in->width - 1 ? in->sx1 : in->width - 1;
    c->y1 = in->sy1 < in->height - 1 ? in->sy1 : in->height - 1;
    return c->x0 <= c->x1 && c->y0 <= c->y1;
}

/* Clips b to the clip; 0 if nothing is left. */
static int dl_interp_clip_box(const dl_interp *in, dl_box *b)
{
    dl_box c;
    if (!dl_interp_clip(in, &c))
        return 0;
    if (b->x0 < c.x0) b->x0 = c.x0;
    if (b->y0 < c.y0) b->y0 = c.y0;
    if (b->x1 > c.x1) b->x1 = c.x1;
    if (b->y1 > c.y1) b->y1 = c.y1;
    return b->x0 <= b->x1 && b->y0 <= b->y1;
}

static void dl_interp_gc(const dl_interp *in, const dl_element *e, unsigned colour, unsigned op,
                         dl_gc *gc)
{
    gc->colour = colour;
    gc->op = op;
    gc->mask = in->mask;
    gc->name = in->name;
    gc->offset = e->offset;
}

/* The located error for a list whose drawing budget is spent. */
static int dl_interp_spent(const dl_interp *in, const dl_element *e, diag *err)
{
    return diag_offset(err, DIAG_INPUT, in->name, e->offset,
                       "drawing work limit of %llu pixel steps exceeded", in->work.limit);
}

/* Charges n boxes' pixels, then hands them to the device. */
static int dl_interp_boxes(dl_interp *in, const dl_element *e, const dl_gc *gc, const dl_box *b,
                           size_t n, diag *err)
{
    unsigned long long px = 0;
    size_t k;
    for (k = 0; k < n; k++)
        px += (unsigned long long)(b[k].x1 - b[k].x0 + 1) * (unsigned)(b[k].y1 - b[k].y0 + 1);
    if (!dl_work_charge(&in->work, px))
        return dl_interp_spent(in, e, err);
    return in->ops->boxes(in->dev, gc, b, n, err);
}

/* Writes one clipped box. */
static int dl_interp_box(dl_interp *in, const dl_element *e, unsigned colour, long long x0,
                         long long y0, long long x1, long long y1, diag *err)
{
    dl_box b;
    dl_gc gc;
    if (x1 < x0 || y1 < y0 || x1 < 0 || y1 < 0 || x0 >= in->width || y0 >= in->height)
        return 0;
    b.x0 = x0 < 0 ? 0 : (int)x0;
    b.y0 = y0 < 0 ? 0 : (int)y0;
    b.x1 = x1 >= in->width ? in->width - 1 : (int)x1;
    b.y1 = y1 >= in->height ? in->height - 1 : (int)y1;
    if (!dl_interp_clip_box(in, &b))
        return 0;
    dl_interp_gc(in, e, colour, in->op, &gc);
    return dl_interp_boxes(in, e, &gc, &b, 1, err);
}

/* Starts collecting the pixels of an element; 0 if the clip is empty. */
static int dl_interp_start(dl_interp *in)
{
    dl_box c;
    if (!dl_interp_clip(in, &c))
        return 0;
    dl_cover_start(&in->cover, c.x0, c.y0, c.x1, c.y1);
    return 1;
}

/* Writes the pixels collected since dl_interp_start. */
static int dl_interp_flush(dl_interp *in, const dl_element *e, unsigned colour, unsigned op,
                           diag *err)
{
    const dl_box *b;
    size_t n = dl_cover_finish(&in->cover, &b);
    dl_gc gc;
    if (in->cover.status == DIAG_INPUT)
        return dl_interp_spent(in, e, err);
    if (in->cover.status)
        return diag_offset(err, DIAG_IO, in->name, e->offset, "out of memory while drawing");
    if (!n)
        return 0;
    dl_interp_gc(in, e, colour, op, &gc);
    return dl_interp_boxes(in, e, &gc, b, n, err);
}

/* Copies the element's points into *dst as ints. */
static int dl_interp_points(dl_interp *in, const dl_element *e, int **dst, size_t *cap, diag *err)
{
    void *p = *dst;
    unsigned i;
    if (2u * (size_t)e->count > *cap && mem_grow(&p, cap, 2u * (size_t)e->count, sizeof(int)))
        return diag_offset(err, DIAG_IO, in->name, e->offset, "out of memory for %u points",
                           e->count);
    *dst = p;
    for (i = 0; i < e->count; i++)
        dl_element_point(e, i, &(*dst)[2 * i], &(*dst)[2 * i + 1]);
    return 0;
}

/* The pen for lines: type 1 solid; 50 the user style from the element's
 * start; 150 the user style continued from the last element drawn with it. */
static dl_pen dl_interp_pen(const dl_interp *in)
{
    dl_pen p;
    p.width = in->line_width;
    p.pattern = in->line_type == DL_LINE_SOLID ? 0xFFFFu : in->style_mask;
    p.factor = in->style_factor ? in->style_factor : 1;
    p.pos = in->line_type == DL_LINE_USER_CONT ? in->style_pos : 0;
    return p;
}

/* Polyline (strip) or segments, or a closed polygon edge (closed). */
static int dl_interp_lines(dl_interp *in, const dl_element *e, const int *xy, size_t n, int strip,
                           int closed, unsigned colour, diag *err)
{
    dl_pen pen = dl_interp_pen(in);
    size_t i;
    if (!dl_interp_start(in))
        return 0;
    if (closed) {
        pen.width = 1;
        pen.pattern = 0xFFFF;
    }
    for (i = 0; i + 1 < n; i += strip ? 1 : 2)
        dl_cover_line(&in->cover, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3], &pen,
                      strip && i > 0);
    if (closed && n > 1)
        dl_cover_line(&in->cover, xy[2 * n - 2], xy[2 * n - 1], xy[0], xy[1], &pen, 1);
    if (!closed && in->line_type == DL_LINE_USER_CONT)
        in->style_pos = pen.pos;
    return dl_interp_flush(in, e, colour, in->op, err);
}

/* A glyph coordinate, rounded, kept well inside int (strokes are short). */
static int dl_interp_round(double v)
{
    v = floor(v + 0.5);
    return v < -1048576.0 ? -1048576 : v > 1048576.0 ? 1048576 : (int)v;
}

/* Text in the stroke font: the point is the lower-left corner of the first
 * character cell; the cell is char_height tall, the baseline runs at right
 * angles clockwise from the up vector. */
static int dl_interp_text(dl_interp *in, const dl_element *e, diag *err)
{
    double len = sqrt((double)in->up_x * in->up_x + (double)in->up_y * in->up_y);
    double ux = in->up_x / len, uy = in->up_y / len, s = in->char_height / (double)DL_FONT_HEIGHT;
    dl_pen pen = {1, 0xFFFF, 1, 0};
    unsigned i;
    if (!dl_interp_start(in))
        return 0;
    for (i = 0; i < e->count && !in->cover.status; i++) {
        const char *g = dl_font_glyph(dl_font_char(e->data[i], in->code_page));
        int px = 0, py = 0, have = 0;
        for (; *g; g++) {
            double gx, gy;
            int x, y;
            if (*g == ' ') {
                have = 0;   /* pen up */
                continue;
            }
            gx = (double)i * DL_FONT_ADVANCE + (g[0] - '0');
            gy = g[1] - '0';
            g++;
            x = e->x0 + dl_interp_round(s * (gx * uy + gy * ux));
            y = e->y0 + dl_interp_round(s * (-gx * ux + gy * uy));
            if (have)
                dl_cover_line(&in->cover, px, py, x, y, &pen, 1);
            else
                dl_cover_line(&in->cover, x, y, x, y, &pen, 0);
            px = x;
            py = y;
            have = 1;
        }
    }
    return dl_interp_flush(in, e, in->text_colour, in->op, err);
}

/* A block of pixels: clipped here, written by the device. */
static int dl_interp_blt(dl_interp *in, const dl_element *e, diag *err)
{
    dl_box b = {e->x0, e->y0, e->x1, e->y1};
    dl_gc gc;
    const uint8_t *rows;
    if (!dl_interp_clip_box(in, &b))
        return 0;
    if (!dl_work_charge(&in->work, (unsigned long long)(b.x1 - b.x0 + 1) * (unsigned)(b.y1 - b.y0 + 1)))
        return dl_interp_spent(in, e, err);
    rows = e->data + (ptrdiff_t)(b.y0 - e->y0) * e->stride + (b.x0 - e->x0);
    dl_interp_gc(in, e, 0, e->op, &gc);
    return in->ops->blt(in->dev, &gc, b.x0, b.y0, b.x1 - b.x0 + 1, b.y1 - b.y0 + 1, rows,
                        e->stride, err);
}

/* Colour expansion: the 1 bits of each row take the colour, 0 bits leave
 * the screen alone (mpelMono.c: "solid foreground and transparent background"). */
static int dl_interp_blt_expand(dl_interp *in, const dl_element *e, diag *err)
{
    long long w = (long long)e->x1 - e->x0 + 1, h = (long long)e->y1 - e->y0 + 1, j, i;
    if (!dl_interp_start(in))
        return 0;
    for (j = 0; j < h; j++) {
        const uint8_t *row = e->data + (ptrdiff_t)j * e->stride;
        for (i = 0; i < w; i++) {
            long long a = i;
            if (!(row[i / 8] >> (7 - i % 8) & 1u))
                continue;
            while (i + 1 < w && (row[(i + 1) / 8] >> (7 - (i + 1) % 8) & 1u))
                i++;
            dl_cover_span(&in->cover, e->y0 + j, e->x0 + a, e->x0 + i);
        }
    }
    return dl_interp_flush(in, e, e->value, e->op, err);
}

static int dl_interp_runs(dl_interp *in, const dl_element *e, diag *err)
{
    long long x = e->x0;
    unsigned i, count, colour;
    for (i = 0; i < e->count; i++) {
        int rc;
        dl_element_run(e, i, &count, &colour);
        if (count && (rc = dl_interp_box(in, e, colour, x, e->y0, x + count - 1, e->y0, err)))
            return rc;
        x += count;
    }
    return 0;
}

static int dl_interp_element(void *ctx, const dl_element *e, diag *err)
{
    dl_interp *in = ctx;
    int rc;
    switch (e->code) {
    case DL_POLYLINE:
        if (e->in_polygon) {
            in->poly_n = e->count;
            return dl_interp_points(in, e, &in->poly, &in->poly_cap, err);
        }
        /* fall through */
    case DL_SEGMENTS:
        if (dl_interp_points(in, e, &in->pts, &in->pts_cap, err))
            return DIAG_IO;
        return dl_interp_lines(in, e, in->pts, e->count, e->code == DL_POLYLINE, 0,
                               in->line_colour, err);
    case DL_FILL_RECT:
        return dl_interp_box(in, e, in->interior_colour, e->x0, e->y0, e->x1, e->y1, err);
    case DL_FILL_CIRCLE: case DL_CIRCLE: {
        int fill = e->code == DL_FILL_CIRCLE;
        if (!dl_interp_start(in))
            return 0;
        dl_cover_circle(&in->cover, e->x0, e->y0, e->value, fill);
        return dl_interp_flush(in, e, fill ? in->interior_colour : in->line_colour, in->op, err);
    }
    case DL_END_POLYGON:
        if (dl_interp_start(in)) {
            dl_cover_polygon(&in->cover, in->poly, in->poly_n, in->version != DL_VERSION_1);
            if ((rc = dl_interp_flush(in, e, in->interior_colour, in->op, err)))
                return rc;
        }
        if (in->edge_flag == DL_EDGE_ON)
            return dl_interp_lines(in, e, in->poly, in->poly_n, 1, 1, in->edge_colour, err);
        return 0;
    case DL_TEXT:
        return dl_interp_text(in, e, err);
    case DL_VIEWPORT:
        in->vx0 = e->x0; in->vy0 = e->y0; in->vx1 = e->x1; in->vy1 = e->y1;
        return 0;
    case DL_SCISSOR:
        in->sx0 = e->x0; in->sy0 = e->y0; in->sx1 = e->x1; in->sy1 = e->y1;
        return 0;
    case DL_BLT:
        return dl_interp_blt(in, e, err);
    case DL_BLT_EXPAND:
        return dl_interp_blt_expand(in, e, err);
    case DL_SRC_BLT:
        /* The pixels are in adapter memory, which a stream does not carry. */
        if (!in->src_blts++)
            in->src_blt_offset = e->offset;
        return 0;
    case DL_LINE_TYPE:
        in->line_type = e->value;
        in->style_pos = 0;
        return 0;
    case DL_USER_LINE_STYLE:
        in->style_mask = e->value;
        in->style_factor = e->count;
        in->style_pos = 0;
        return 0;
    case DL_LINE_WIDTH:
        in->line_width = e->value;
        return 0;
    case DL_LINE_COLOUR:
        in->line_colour = e->value;
        return 0;
    case DL_INTERIOR_COLOUR:
        in->interior_colour = e->value;
        return 0;
    case DL_TEXT_COLOUR:
        in->text_colour = e->value;
        return 0;
    case DL_EDGE_COLOUR:
        in->edge_colour = e->value;
        return 0;
    case DL_EDGE_FLAG:
        in->edge_flag = e->value;
        return 0;
    case DL_CHAR_HEIGHT:
        in->char_height = e->value;
        return 0;
    case DL_CHAR_UP:
        in->up_x = e->x0;
        in->up_y = e->y0;
        return 0;
    case DL_CODE_PAGE:
        in->code_page = e->value;
        return 0;
    case DL_LOGIC_OP:
        in->op = e->value;
        return 0;
    case DL_PLANE_MASK:
        in->mask = e->planes;
        return 0;
    case DL_LOAD_COLOURS: {
        unsigned i;
        for (i = 0; i < e->count; i++)
            in->lut[e->start + i] = dl_element_colour(e, i);
        return 0;
    }
    case DL_CLEAR:
        return dl_interp_box(in, e, e->value, 0, 0, in->width - 1, in->height - 1, err);
    case DL_RUN_ROW:
        return dl_interp_runs(in, e, err);
    default:   /* begin-polygon, interior style (solid only), noop, end */
        return 0;
    }
}

const dl_visitor dl_interp_visitor = {.header = dl_interp_header, .element = dl_interp_element};
