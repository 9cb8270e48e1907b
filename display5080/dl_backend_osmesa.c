/* dl_backend_osmesa — the display list drawn with OpenGL into an OSMesa
 * buffer (Mesa's off-screen renderer). libOSMesa is opened with dlopen when
 * this backend is chosen (util/libload), so other commands never map Mesa; where
 * it is missing (OSMesa left Mesa in 25.1) opening the backend says so.
 * The few OSMesa entry points and constants are spelled out here, so no
 * OSMesa header is needed to build. */
#include "display5080/dl_backend.h"
#include "display5080/dl_gl.h"
#include "util/libload.h"
#include "util/mem.h"
#include <string.h>

#define DL_OSMESA_RGBA 0x1908          /* GL_RGBA */
#define DL_OSMESA_UNSIGNED_BYTE 0x1401 /* GL_UNSIGNED_BYTE */

typedef struct dl_backend_osmesa_api {
    void *(*CreateContextExt)(unsigned, int, int, int, void *);
    unsigned char (*MakeCurrent)(void *, void *, unsigned, int, int);
    void (*DestroyContext)(void *);
    dl_gl_proc (*GetProcAddress)(const char *);
} dl_backend_osmesa_api;

typedef struct dl_backend_osmesa_ctx {
    dl_gl g;                   /* first: the device pointer is a dl_gl too */
    void *ctx;                 /* OSMesaContext */
    uint8_t *buf;              /* RGBA colour buffer */
} dl_backend_osmesa_ctx;

static dl_backend_osmesa_api dl_backend_osmesa_fn;

static int dl_backend_osmesa_load(diag *err)
{
    static const char *const names[] = {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so", NULL};
    static const char *const syms[] = {"OSMesaCreateContextExt", "OSMesaMakeCurrent",
                                       "OSMesaDestroyContext", "OSMesaGetProcAddress"};
    libload_fn f[4];
    if (libload(names, syms, f, 4, "osmesa", "install it, or use --backend png", err))
        return DIAG_IO;
    dl_backend_osmesa_fn.CreateContextExt = (void *(*)(unsigned, int, int, int, void *))f[0];
    dl_backend_osmesa_fn.MakeCurrent = (unsigned char (*)(void *, void *, unsigned, int, int))f[1];
    dl_backend_osmesa_fn.DestroyContext = (void (*)(void *))f[2];
    dl_backend_osmesa_fn.GetProcAddress = (dl_gl_proc (*)(const char *))f[3];
    return 0;
}

static dl_gl_proc dl_backend_osmesa_proc(const char *name) { return dl_backend_osmesa_fn.GetProcAddress(name); }

static void dl_backend_osmesa_close(void *dev)
{
    dl_backend_osmesa_ctx *o = dev;
    if (!o)
        return;
    if (o->ctx) {
        dl_gl_stop(&o->g);
        dl_backend_osmesa_fn.DestroyContext(o->ctx);
    }
    mem_free(o->buf);
    mem_free(o);
}

static int dl_backend_osmesa_open(int width, int height, void **dev, diag *err)
{
    dl_backend_osmesa_ctx *o;
    if (dl_backend_osmesa_load(err))
        return DIAG_IO;
    if (!(o = mem_calloc(1, sizeof *o)))
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "out of memory");
    o->buf = mem_alloc((size_t)width * (size_t)height * 4);
    if (!o->buf) {
        dl_backend_osmesa_close(o);
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "out of memory for a %dx%d buffer", width,
                       height);
    }
    o->ctx = dl_backend_osmesa_fn.CreateContextExt(DL_OSMESA_RGBA, 0, 8, 0, NULL);
    if (!o->ctx) {
        dl_backend_osmesa_close(o);
        return diag_at(err, DIAG_IO, "osmesa", 0, 0, "cannot create an OSMesa context");
    }
    if (!dl_backend_osmesa_fn.MakeCurrent(o->ctx, o->buf, DL_OSMESA_UNSIGNED_BYTE, width, height)) {
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
    .summary = "OpenGL in an OSMesa off-screen buffer (libOSMesa, loaded when chosen)",
    .open = dl_backend_osmesa_open,
    .ops = &dl_gl_device,
    .read = dl_backend_osmesa_read,
    .close = dl_backend_osmesa_close,
};
