/* dl_interp — the 5081 display model (see dl_interp.h). Defaults at the start
 * of a list: colour table 0 = black, 1 = white, rest black; polyline and
 * interior colour 1; logic op 4 (copy); plane mask 0xFF; scissor and viewport
 * the whole screen. */
#include "display5080/dl_interp.h"
#include "util/mem.h"
#include <string.h>

void dl_interp_init(dl_interp *in, const char *name, int force_dac, dl_interp_open_fn open,
                    void *octx)
{
    memset(in, 0, sizeof *in);
    in->name = name;
    in->force_dac = force_dac;
    in->open = open;
    in->octx = octx;
    dl_work_init(&in->work, 0);
}

void dl_interp_free(dl_interp *in)
{
    mem_free(in->pts);
    mem_free(in->poly);
    in->pts = in->poly = NULL;
    in->pts_cap = in->poly_cap = 0;
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
    in->dac = in->force_dac ? in->force_dac : (h->flags & DL_FLAG_DAC8) ? 8 : 4;
    memset(in->lut, 0, sizeof in->lut);
    in->lut[1] = 0xFFFFFFu;
    in->line_colour = in->interior_colour = 1;
    in->op = DL_OP_COPY;
    in->mask = 0xFF;
    in->sx0 = in->vx0 = 0;
    in->sy0 = in->vy0 = 0;
    in->sx1 = in->vx1 = h->width - 1;
    in->sy1 = in->vy1 = h->height - 1;
    /* every backend clears its new screen: that is work too */
    if (dl_work_charge(&in->work, (unsigned long long)h->width * (unsigned)h->height, in->name, 0, err))
        return DIAG_INPUT;
    return in->open(in->octx, h->width, h->height, &in->ops, &in->dev, err);
}

/* Graphics context for the current element; 0 if the clip is empty. */
static int dl_interp_gc(const dl_interp *in, const dl_element *e, unsigned colour, dl_gc *gc)
{
    gc->colour = colour;
    gc->op = in->op;
    gc->mask = in->mask & 0xFFu;
    gc->cx0 = in->sx0 > 0 ? in->sx0 : 0;
    gc->cy0 = in->sy0 > 0 ? in->sy0 : 0;
    gc->cx1 = in->sx1 < in->width - 1 ? in->sx1 : in->width - 1;
    gc->cy1 = in->sy1 < in->height - 1 ? in->sy1 : in->height - 1;
    gc->name = in->name;
    gc->offset = e->offset;
    return gc->cx0 <= gc->cx1 && gc->cy0 <= gc->cy1;
}

/* Copies the element's points into *dst as ints. */
static int dl_interp_points(dl_interp *in, const dl_element *e, int **dst, size_t *cap, diag *err)
{
    void *p = *dst;
    unsigned i;
    if (2u * (size_t)e->count > *cap && mem_grow(&p, cap, 2u * (size_t)e->count, sizeof(int)))
        return diag_at(err, DIAG_IO, in->name, 0, 0, "out of memory for %u points", e->count);
    *dst = p;
    for (i = 0; i < e->count; i++)
        dl_element_point(e, i, &(*dst)[2 * i], &(*dst)[2 * i + 1]);
    return 0;
}

static int dl_interp_charge(dl_interp *in, const dl_element *e, unsigned long long n, diag *err)
{
    return dl_work_charge(&in->work, n, in->name, e->offset, err);
}

static int dl_interp_runs(dl_interp *in, const dl_element *e, diag *err)
{
    long long x = e->x0;
    unsigned i, count, colour;
    dl_gc gc;
    for (i = 0; i < e->count; i++) {
        dl_element_run(e, i, &count, &colour);
        if (!dl_interp_gc(in, e, colour, &gc))
            return 0;
        if (count && x <= gc.cx1 && x + count - 1 >= gc.cx0 && e->y0 >= gc.cy0 && e->y0 <= gc.cy1) {
            long long a = x < gc.cx0 ? gc.cx0 : x, b = x + count - 1 > gc.cx1 ? gc.cx1 : x + count - 1;
            int rc = dl_interp_charge(in, e, dl_work_rect(&gc, (int)a, e->y0, (int)b, e->y0), err);
            if (!rc)
                rc = in->ops->rect(in->dev, &gc, (int)a, e->y0, (int)b, e->y0, err);
            if (rc)
                return rc;
        }
        x += count;
    }
    return 0;
}

static int dl_interp_element(void *ctx, const dl_element *e, diag *err)
{
    dl_interp *in = ctx;
    dl_gc gc;
    switch (e->code) {
    case DL_POLYLINE:
        if (e->in_polygon) {
            in->poly_n = e->count;
            return dl_interp_points(in, e, &in->poly, &in->poly_cap, err);
        }
        /* fall through */
    case DL_SEGMENTS:
        if (!dl_interp_gc(in, e, in->line_colour, &gc))
            return 0;
        if (dl_interp_points(in, e, &in->pts, &in->pts_cap, err))
            return DIAG_IO;
        if (dl_interp_charge(in, e, dl_work_lines(in->pts, e->count, e->code == DL_POLYLINE), err))
            return DIAG_INPUT;
        return in->ops->lines(in->dev, &gc, in->pts, e->count, e->code == DL_POLYLINE, err);
    case DL_FILL_RECT:
        if (!dl_interp_gc(in, e, in->interior_colour, &gc))
            return 0;
        if (dl_interp_charge(in, e, dl_work_rect(&gc, e->x0, e->y0, e->x1, e->y1), err))
            return DIAG_INPUT;
        return in->ops->rect(in->dev, &gc, e->x0, e->y0, e->x1, e->y1, err);
    case DL_FILL_CIRCLE: case DL_CIRCLE: {
        int fill = e->code == DL_FILL_CIRCLE;
        if (!dl_interp_gc(in, e, fill ? in->interior_colour : in->line_colour, &gc))
            return 0;
        if (dl_interp_charge(in, e, dl_work_circle(&gc, e->y0, e->value, fill), err))
            return DIAG_INPUT;
        return in->ops->circle(in->dev, &gc, e->x0, e->y0, e->value, fill, err);
    }
    case DL_END_POLYGON:
        if (!dl_interp_gc(in, e, in->interior_colour, &gc))
            return 0;
        if (dl_interp_charge(in, e, dl_work_polygon(&gc, in->poly, in->poly_n), err))
            return DIAG_INPUT;
        return in->ops->polygon(in->dev, &gc, in->poly, in->poly_n, err);
    case DL_VIEWPORT:
        in->vx0 = e->x0; in->vy0 = e->y0; in->vx1 = e->x1; in->vy1 = e->y1;
        return 0;
    case DL_SCISSOR:
        in->sx0 = e->x0; in->sy0 = e->y0; in->sx1 = e->x1; in->sy1 = e->y1;
        return 0;
    case DL_BLT:
        if (!dl_interp_gc(in, e, 0, &gc))
            return 0;
        gc.op = e->op;
        if (dl_interp_charge(in, e, (unsigned long long)(e->x1 - e->x0 + 1) * (unsigned)(e->y1 - e->y0 + 1), err))
            return DIAG_INPUT;
        return in->ops->blt(in->dev, &gc, e->x0, e->y0, e->x1 - e->x0 + 1, e->y1 - e->y0 + 1,
                            e->data, e->stride, err);
    case DL_LINE_COLOUR:
        in->line_colour = e->value;
        return 0;
    case DL_INTERIOR_COLOUR:
        in->interior_colour = e->value;
        return 0;
    case DL_LOGIC_OP:
        in->op = e->value;
        return 0;
    case DL_PLANE_MASK:
        in->mask = e->value & 0xFFu;
        return 0;
    case DL_LOAD_COLOURS: {
        unsigned i;
        for (i = 0; i < e->count; i++)
            in->lut[e->start + i] = dl_element_colour(e, i);
        return 0;
    }
    case DL_CLEAR:
        if (!dl_interp_gc(in, e, e->value, &gc))
            return 0;
        if (dl_interp_charge(in, e, dl_work_rect(&gc, 0, 0, in->width - 1, in->height - 1), err))
            return DIAG_INPUT;
        return in->ops->rect(in->dev, &gc, 0, 0, in->width - 1, in->height - 1, err);
    case DL_RUN_ROW:
        return dl_interp_runs(in, e, err);
    default:   /* begin-polygon, text (not drawn), noop, line type, end */
        return 0;
    }
}

const dl_visitor dl_interp_visitor = {dl_interp_header, dl_interp_element};
