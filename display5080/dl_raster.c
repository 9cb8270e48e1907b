/* dl_raster — software 5081 frame buffer (see dl_raster.h). */
#include "display5080/dl_raster.h"
#include "display5080/dl_format.h"
#include "display5080/dl_logic.h"
#include "util/mem.h"
#include <string.h>

int dl_raster_init(dl_raster *r, int width, int height, diag *err)
{
    memset(r, 0, sizeof *r);
    r->px = mem_calloc((size_t)width * (size_t)height, 1);
    if (!r->px)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory for a %dx%d frame buffer", width,
                       height);
    r->width = width;
    r->height = height;
    return 0;
}

void dl_raster_free(dl_raster *r)
{
    mem_free(r->px);
    memset(r, 0, sizeof *r);
}

static int dl_raster_boxes(void *dev, const dl_gc *gc, const dl_box *b, size_t n, diag *err)
{
    dl_raster *r = dev;
    size_t k;
    (void)err;
    for (k = 0; k < n; k++) {
        int x, y;
        for (y = b[k].y0; y <= b[k].y1; y++) {
            uint8_t *p = r->px + (size_t)y * (size_t)r->width;
            if (gc->op == DL_OP_COPY && (gc->mask & 0xFFu) == 0xFFu) {   /* plain copy: a clear */
                memset(p + b[k].x0, (int)(gc->colour & 0xFFu), (size_t)(b[k].x1 - b[k].x0 + 1));
                continue;
            }
            for (x = b[k].x0; x <= b[k].x1; x++)
                p[x] = dl_logic_apply(gc->op, (uint8_t)gc->colour, p[x], (uint8_t)gc->mask);
        }
    }
    return 0;
}

static int dl_raster_blt(void *dev, const dl_gc *gc, int x0, int y0, int w, int h,
                         const uint8_t *rows, ptrdiff_t stride, diag *err)
{
    dl_raster *r = dev;
    int i, j;
    (void)err;
    for (j = 0; j < h; j++) {
        const uint8_t *s = rows + (ptrdiff_t)j * stride;
        uint8_t *p = r->px + (size_t)(y0 + j) * (size_t)r->width + (size_t)x0;
        for (i = 0; i < w; i++)
            p[i] = dl_logic_apply(gc->op, s[i], p[i], (uint8_t)gc->mask);
    }
    return 0;
}

const dl_device dl_raster_device = {.boxes = dl_raster_boxes, .blt = dl_raster_blt};
