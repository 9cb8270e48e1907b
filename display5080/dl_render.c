/* dl_render — display list to frame to PNG (see dl_render.h). */
#include "image/image_png.h"
#include "display5080/dl_render.h"
#include "display5080/dl_interp.h"
#include "util/mem.h"
#include <string.h>

typedef struct dl_render_ctx {
    const dl_backend *b;
    const dl_render_opts *opts;
    void *dev;
} dl_render_ctx;

static int dl_render_open(void *octx, int width, int height, const dl_device **ops, void **dev,
                          diag *err)
{
    dl_render_ctx *c = octx;
    int rc = c->b->open(width, height, &c->dev, err);
    if (rc)
        return rc;
    *ops = c->b->ops;
    *dev = c->dev;
    return 0;
}

dl_decode_opts dl_render_decode_opts(const dl_render_opts *opts)
{
    dl_decode_opts d;
    memset(&d, 0, sizeof d);
    if (opts && opts->raw) {
        d.raw = 1;
        d.width = opts->width;
        d.height = opts->height;
        d.flags = opts->dac == 4 ? 0 : DL_FLAG_DAC8;
    }
    return d;
}

int dl_render(const uint8_t *buf, size_t len, const char *name, const dl_backend *b,
              const dl_render_opts *opts, dl_frame *out, diag *err)
{
    dl_render_ctx c;
    dl_interp in;
    dl_frame f;
    dl_decode_opts d = dl_render_decode_opts(opts);
    int rc;
    memset(&c, 0, sizeof c);
    c.b = b;
    c.opts = opts;
    dl_interp_init(&in, name, opts ? opts->dac : 0, opts ? opts->work_limit : 0, dl_render_open,
                   &c);
    rc = dl_decode(buf, len, name, &d, &dl_interp_visitor, &in, NULL, err);
    memset(&f, 0, sizeof f);
    if (!rc) {
        f.width = in.width;
        f.height = in.height;
        f.dac = in.dac;
        f.src_blts = in.src_blts;
        f.src_blt_offset = in.src_blt_offset;
        f.work = in.work.used;
        dl_interp_palette(&in, f.palette);
        f.px = mem_alloc((size_t)f.width * (size_t)f.height);
        if (!f.px)
            rc = diag_at(err, DIAG_IO, name, 0, 0, "out of memory for the frame");
        else if ((rc = b->read(c.dev, f.px, err)))
            mem_free(f.px);
    }
    if (c.dev)
        b->close(c.dev);
    dl_interp_free(&in);
    if (!rc)
        *out = f;
    return rc;
}

void dl_frame_free(dl_frame *f)
{
    mem_free(f->px);
    f->px = NULL;
}

int dl_frame_rgb(const dl_frame *f, image *out, diag *err)
{
    image img;
    int x, y;
    if (image_alloc(&img, f->width, f->height, 3, "frame", err))
        return err->status;
    for (y = 0; y < f->height; y++) {
        const uint8_t *src = f->px + (size_t)(f->height - 1 - y) * (size_t)f->width;
        uint8_t *dst = img.px + (size_t)y * (size_t)f->width * 3;
        for (x = 0; x < f->width; x++)
            memcpy(dst + 3 * x, f->palette + 3 * src[x], 3);
    }
    *out = img;
    return 0;
}

int dl_frame_write_png(const char *path, const dl_frame *f, int truecolor, diag *err)
{
    size_t n = (size_t)f->width * (size_t)f->height, i;
    uint8_t *top;
    int y, used = 0, rc;
    if (truecolor) {
        image img;
        if (dl_frame_rgb(f, &img, err))
            return err->status;
        rc = image_write_png(path, &img, err);
        image_free(&img);
        return rc;
    }
    top = mem_alloc(n);
    if (!top)
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    for (y = 0; y < f->height; y++)
        memcpy(top + (size_t)y * (size_t)f->width,
               f->px + (size_t)(f->height - 1 - y) * (size_t)f->width, (size_t)f->width);
    for (i = 0; i < n; i++)
        if (top[i] >= used)
            used = top[i] + 1;
    rc = image_write_png_palette(path, f->width, f->height, top, f->palette, used, err);
    mem_free(top);
    return rc;
}
