/* dl_backend_osmesa — the display list drawn with OpenGL into an OSMesa
 * buffer (Mesa's off-screen renderer). Compiled only when pkg-config found
 * osmesa (DL_HAVE_OSMESA, see mk/display5080.mk): OSMesa left Mesa in 25.1,
 * so without it the backend exists but says why it cannot start. */
#include "display5080/dl_backend.h"
#include "display5080/dl_gl.h"
#include "util/mem.h"
#include <string.h>

#ifdef DL_HAVE_OSMESA
#include <GL/osmesa.h>

typedef struct dl_backend_osmesa_ctx {
    dl_gl g;                   /* first: the device pointer is a dl_gl too */
    OSMesaContext ctx;
    uint8_t *buf;              /* RGBA colour buffer */
} dl_backend_osmesa_ctx;

static dl_gl_proc dl_backend_osmesa_proc(const char *name)
{
    OSMESAproc p = OSMesaGetProcAddress(name);
    dl_gl_proc q;
    memcpy(&q, &p, sizeof q);
    return q;
}

static void dl_backend_osmesa_close(void *dev)
{
    dl_backend_osmesa_ctx *o = dev;
    if (!o)
        return;
    if (o->ctx) {
        dl_gl_stop(&o->g);
        OSMesaDestroyContext(o->ctx);
    }
    mem_free(o->buf);
    mem_free(o);
}

static int dl_backend_osmesa_open(int width, int height, void **dev, diag *err)
{
    dl_backend_osmesa_ctx *o = mem_calloc(1, sizeof *o);
    if (!o)
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "out of memory");
    o->buf = mem_alloc((size_t)width * (size_t)height * 4);
    if (!o->buf) {
        dl_backend_osmesa_close(o);
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "out of memory for a %dx%d buffer", width,
                       height);
    }
    o->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 8, 0, NULL);
    if (!o->ctx) {
        dl_backend_osmesa_close(o);
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "cannot create an OSMesa context");
    }
    if (!OSMesaMakeCurrent(o->ctx, o->buf, GL_UNSIGNED_BYTE, width, height)) {
        dl_backend_osmesa_close(o);
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "cannot make the OSMesa context current");
    }
    if (dl_gl_load(&o->g, dl_backend_osmesa_proc, 0, "osmesa", err) ||
        dl_gl_start(&o->g, width, height, 0, "osmesa", err)) {
        dl_backend_osmesa_close(o);
        return DIAG_IO;
    }
    *dev = o;
    return 0;
}

static int dl_backend_osmesa_read(void *dev, uint8_t *px, diag *err)
{
    dl_backend_osmesa_ctx *o = dev;
    return dl_gl_read(&o->g, px, "osmesa", err);
}

const dl_backend dl_backend_osmesa = {
    .name = "osmesa",
    .summary = "OpenGL in an OSMesa off-screen buffer",
    .open = dl_backend_osmesa_open,
    .ops = &dl_gl_device,
    .read = dl_backend_osmesa_read,
    .close = dl_backend_osmesa_close,
};

#else

static int dl_backend_osmesa_open(int width, int height, void **dev, diag *err)
{
    (void)width;
    (void)height;
    (void)dev;
    return diag_at(err, DIAG_IO, "osmesa", 0, 0,
                   "this maprt was built without OSMesa (no osmesa.pc; OSMesa left Mesa in 25.1); "
                   "use --backend egl");
}

static int dl_backend_osmesa_read(void *dev, uint8_t *px, diag *err)
{
    (void)dev;
    (void)px;
    return diag_at(err, DIAG_IO, "osmesa", 0, 0, "not available");
}

static void dl_backend_osmesa_close(void *dev) { (void)dev; }

const dl_backend dl_backend_osmesa = {
    .name = "osmesa",
    .summary = "OpenGL in an OSMesa off-screen buffer (not built)",
    .open = dl_backend_osmesa_open,
    .ops = &dl_gl_device,
    .read = dl_backend_osmesa_read,
    .close = dl_backend_osmesa_close,
};
#endif
