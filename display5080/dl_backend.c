/* dl_backend — the backend list and the software (png) backend. */
#include "display5080/dl_backend.h"
#include "display5080/dl_raster.h"
#include "util/mem.h"
#include <string.h>
#include <strings.h>

static int dl_backend_png_open(int width, int height, void **dev, diag *err)
{
    dl_raster *r = mem_alloc(sizeof *r);
    if (!r)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    if (dl_raster_init(r, width, height, err)) {
        mem_free(r);
        return DIAG_IO;
    }
    *dev = r;
    return 0;
}

static int dl_backend_png_read(void *dev, uint8_t *px, diag *err)
{
    dl_raster *r = dev;
    (void)err;
    memcpy(px, r->px, (size_t)r->width * (size_t)r->height);
    return 0;
}

static void dl_backend_png_close(void *dev)
{
    if (dev) {
        dl_raster_free(dev);
        mem_free(dev);
    }
}

const dl_backend dl_backend_png = {
    .name = "png",
    .summary = "software 5081 raster (the reference)",
    .open = dl_backend_png_open,
    .ops = &dl_raster_device,
    .read = dl_backend_png_read,
    .close = dl_backend_png_close,
};

const dl_backend *dl_backend_find(const char *name)
{
    static const dl_backend *const all[] = {&dl_backend_png, &dl_backend_osmesa, &dl_backend_egl};
    size_t i;
    for (i = 0; i < sizeof all / sizeof all[0]; i++)
        if (!strcasecmp(all[i]->name, name))
            return all[i];
    return NULL;
}
