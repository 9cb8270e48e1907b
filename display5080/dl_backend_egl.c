/* dl_backend_egl — the display list drawn with OpenGL on a surfaceless EGL
 * context (EGL_MESA_platform_surfaceless, no window, no pbuffer) into a
 * framebuffer object. Desktop OpenGL, compatibility profile, through
 * eglBindAPI(EGL_OPENGL_API): the drawing code is dl_gl, shared with the
 * OSMesa backend. This is the GL path for Mesa 25.1 and later. Compiled only
 * when pkg-config found egl (DL_HAVE_EGL). */
#include "display5080/dl_backend.h"
#include "display5080/dl_gl.h"
#include "util/mem.h"
#include <string.h>

#ifdef DL_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>

typedef struct dl_backend_egl_ctx {
    dl_gl g;
    EGLDisplay dpy;
    EGLContext ctx;
} dl_backend_egl_ctx;

static dl_gl_proc dl_backend_egl_proc(const char *name)
{
    __eglMustCastToProperFunctionPointerType p = eglGetProcAddress(name);
    dl_gl_proc q;
    memcpy(&q, &p, sizeof q);
    return q;
}

static void dl_backend_egl_close(void *dev)
{
    dl_backend_egl_ctx *e = dev;
    if (!e)
        return;
    if (e->ctx != EGL_NO_CONTEXT) {
        dl_gl_stop(&e->g);
        eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(e->dpy, e->ctx);
    }
    /* The display is not terminated: EGL displays are per-process, and
     * eglTerminate would unload Mesa's driver only to load it again for the
     * next list. It stays initialised until the process ends. */
    mem_free(e);
}

static int dl_backend_egl_fail(dl_backend_egl_ctx *e, const char *what, diag *err)
{
    EGLint code = eglGetError();
    dl_backend_egl_close(e);
    return diag_at(err, DIAG_IO, "egl", 0, 0, "%s (EGL error 0x%04X)", what, (unsigned)code);
}

static int dl_backend_egl_open(int width, int height, void **dev, diag *err)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display;
    const char *ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    dl_backend_egl_ctx *e = mem_calloc(1, sizeof *e);
    __eglMustCastToProperFunctionPointerType p;
    EGLint major, minor;
    if (!e)
        return diag_at(err, DIAG_IO, "egl", 0, 0, "out of memory");
    e->dpy = EGL_NO_DISPLAY;
    e->ctx = EGL_NO_CONTEXT;
    if (!ext || !strstr(ext, "EGL_MESA_platform_surfaceless")) {
        dl_backend_egl_close(e);
        return diag_at(err, DIAG_IO, "egl", 0, 0,
                       "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");
    }
    p = eglGetProcAddress("eglGetPlatformDisplayEXT");
    memcpy(&get_display, &p, sizeof p);
    if (!get_display)
        return dl_backend_egl_fail(e, "eglGetPlatformDisplayEXT is missing", err);
    e->dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (e->dpy == EGL_NO_DISPLAY)
        return dl_backend_egl_fail(e, "no surfaceless EGL display", err);
    if (!eglInitialize(e->dpy, &major, &minor))
        return dl_backend_egl_fail(e, "cannot initialise the surfaceless EGL display", err);
    ext = eglQueryString(e->dpy, EGL_EXTENSIONS);
    if (!ext || !strstr(ext, "EGL_KHR_surfaceless_context") || !strstr(ext, "EGL_KHR_no_config_context")) {
        dl_backend_egl_close(e);
        return diag_at(err, DIAG_IO, "egl", 0, 0,
                       "EGL lacks EGL_KHR_surfaceless_context or EGL_KHR_no_config_context");
    }
    if (!eglBindAPI(EGL_OPENGL_API))
        return dl_backend_egl_fail(e, "EGL cannot bind desktop OpenGL", err);
    e->ctx = eglCreateContext(e->dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, NULL);
    if (e->ctx == EGL_NO_CONTEXT)
        return dl_backend_egl_fail(e, "cannot create an OpenGL context", err);
    if (!eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx))
        return dl_backend_egl_fail(e, "cannot make the context current without a surface", err);
    if (dl_gl_load(&e->g, dl_backend_egl_proc, 1, "egl", err) ||
        dl_gl_start(&e->g, width, height, 1, "egl", err)) {
        dl_backend_egl_close(e);
        return DIAG_IO;
    }
    *dev = e;
    return 0;
}

static int dl_backend_egl_read(void *dev, uint8_t *px, diag *err)
{
    dl_backend_egl_ctx *e = dev;
    return dl_gl_read(&e->g, px, "egl", err);
}

const dl_backend dl_backend_egl = {
    .name = "egl",
    .summary = "OpenGL on a surfaceless EGL context (Mesa)",
    .open = dl_backend_egl_open,
    .ops = &dl_gl_device,
    .read = dl_backend_egl_read,
    .close = dl_backend_egl_close,
};

#else

static int dl_backend_egl_open(int width, int height, void **dev, diag *err)
{
    (void)width;
    (void)height;
    (void)dev;
    return diag_at(err, DIAG_IO, "egl", 0, 0, "this maprt was built without EGL (no egl.pc)");
}

static int dl_backend_egl_read(void *dev, uint8_t *px, diag *err)
{
    (void)dev;
    (void)px;
    return diag_at(err, DIAG_IO, "egl", 0, 0, "not available");
}

static void dl_backend_egl_close(void *dev) { (void)dev; }

const dl_backend dl_backend_egl = {
    .name = "egl",
    .summary = "OpenGL on a surfaceless EGL context (not built)",
    .open = dl_backend_egl_open,
    .ops = &dl_gl_device,
    .read = dl_backend_egl_read,
    .close = dl_backend_egl_close,
};
#endif
