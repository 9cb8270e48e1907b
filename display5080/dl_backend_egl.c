/* dl_backend_egl — the display list drawn with OpenGL on a surfaceless EGL
 * context (EGL_MESA_platform_surfaceless, no window, no pbuffer) into a
 * framebuffer object. Desktop OpenGL, compatibility profile, through
 * eglBindAPI(EGL_OPENGL_API): the drawing code is dl_gl, shared with the
 * OSMesa backend. This is the GL path for Mesa 25.1 and later. libEGL is
 * opened with dlopen when this backend is chosen (util/libload), so other commands
 * never map Mesa; the EGL types, constants and entry points used are spelled
 * out here, so no EGL header is needed to build. */
#include "display5080/dl_backend.h"
#include "display5080/dl_gl.h"
#include "util/libload.h"
#include "util/mem.h"
#include <stdint.h>
#include <string.h>

/* EGLDisplay, EGLContext, EGLConfig and EGLSurface are opaque pointers;
 * EGLint is 32 bits, EGLBoolean and EGLenum unsigned int (Khronos egl.h). */
#define EGL_NO_DISPLAY ((void *)0)
#define EGL_NO_CONTEXT ((void *)0)
#define EGL_NO_SURFACE ((void *)0)
#define EGL_NO_CONFIG_KHR ((void *)0)
#define EGL_DEFAULT_DISPLAY ((void *)0)
#define EGL_EXTENSIONS 0x3055
#define EGL_OPENGL_API 0x30A2
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD

typedef struct dl_backend_egl_api {
    dl_gl_proc (*GetProcAddress)(const char *);
    const char *(*QueryString)(void *, int32_t);
    int32_t (*GetError)(void);
    unsigned (*Initialize)(void *, int32_t *, int32_t *);
    unsigned (*BindAPI)(unsigned);
    void *(*CreateContext)(void *, void *, void *, const int32_t *);
    unsigned (*MakeCurrent)(void *, void *, void *, void *);
    unsigned (*DestroyContext)(void *, void *);
} dl_backend_egl_api;

static dl_backend_egl_api dl_backend_egl_fn;

static int dl_backend_egl_load(diag *err)
{
    static const char *const names[] = {"libEGL.so.1", "libEGL.so", NULL};
    static const char *const syms[] = {"eglGetProcAddress", "eglQueryString", "eglGetError",
                                       "eglInitialize", "eglBindAPI", "eglCreateContext",
                                       "eglMakeCurrent", "eglDestroyContext"};
    libload_fn f[8];
    if (libload(names, syms, f, 8, "egl", "install it, or use --backend png", err))
        return DIAG_IO;
    dl_backend_egl_fn.GetProcAddress = (dl_gl_proc (*)(const char *))f[0];
    dl_backend_egl_fn.QueryString = (const char *(*)(void *, int32_t))f[1];
    dl_backend_egl_fn.GetError = (int32_t (*)(void))f[2];
    dl_backend_egl_fn.Initialize = (unsigned (*)(void *, int32_t *, int32_t *))f[3];
    dl_backend_egl_fn.BindAPI = (unsigned (*)(unsigned))f[4];
    dl_backend_egl_fn.CreateContext = (void *(*)(void *, void *, void *, const int32_t *))f[5];
    dl_backend_egl_fn.MakeCurrent = (unsigned (*)(void *, void *, void *, void *))f[6];
    dl_backend_egl_fn.DestroyContext = (unsigned (*)(void *, void *))f[7];
    return 0;
}

typedef struct dl_backend_egl_ctx {
    dl_gl g;
    void *dpy;                 /* EGLDisplay */
    void *ctx;                 /* EGLContext */
} dl_backend_egl_ctx;

static dl_gl_proc dl_backend_egl_proc(const char *name) { return dl_backend_egl_fn.GetProcAddress(name); }

static void dl_backend_egl_close(void *dev)
{
    dl_backend_egl_ctx *e = dev;
    if (!e)
        return;
    if (e->ctx != EGL_NO_CONTEXT) {
        dl_gl_stop(&e->g);
        dl_backend_egl_fn.MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        dl_backend_egl_fn.DestroyContext(e->dpy, e->ctx);
    }
    /* The display is not terminated: EGL displays are per-process, and
     * eglTerminate would unload Mesa's driver only to load it again for the
     * next list. It stays initialised until the process ends. */
    mem_free(e);
}

static int dl_backend_egl_fail(dl_backend_egl_ctx *e, const char *what, diag *err)
{
    int32_t code = dl_backend_egl_fn.GetError();
    dl_backend_egl_close(e);
    return diag_at(err, DIAG_IO, "egl", 0, 0, "%s (EGL error 0x%04X)", what, (unsigned)code);
}

static int dl_backend_egl_open(int width, int height, void **dev, diag *err)
{
    void *(*get_display)(unsigned, void *, const int32_t *);
    const char *ext;
    dl_backend_egl_ctx *e;
    dl_gl_proc p;
    int32_t major, minor;
    if (dl_backend_egl_load(err))
        return DIAG_IO;
    ext = dl_backend_egl_fn.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!(e = mem_calloc(1, sizeof *e)))
        return diag_at(err, DIAG_IO, "egl", 0, 0, "out of memory");
    e->dpy = EGL_NO_DISPLAY;
    e->ctx = EGL_NO_CONTEXT;
    if (!ext || !strstr(ext, "EGL_MESA_platform_surfaceless")) {
        dl_backend_egl_close(e);
        return diag_at(err, DIAG_IO, "egl", 0, 0,
                       "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");
    }
    p = dl_backend_egl_fn.GetProcAddress("eglGetPlatformDisplayEXT");
    get_display = (void *(*)(unsigned, void *, const int32_t *))p;
    if (!get_display)
        return dl_backend_egl_fail(e, "eglGetPlatformDisplayEXT is missing", err);
    e->dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (e->dpy == EGL_NO_DISPLAY)
        return dl_backend_egl_fail(e, "no surfaceless EGL display", err);
    if (!dl_backend_egl_fn.Initialize(e->dpy, &major, &minor))
        return dl_backend_egl_fail(e, "cannot initialise the surfaceless EGL display", err);
    ext = dl_backend_egl_fn.QueryString(e->dpy, EGL_EXTENSIONS);
    if (!ext || !strstr(ext, "EGL_KHR_surfaceless_context") || !strstr(ext, "EGL_KHR_no_config_context")) {
        dl_backend_egl_close(e);
        return diag_at(err, DIAG_IO, "egl", 0, 0,
                       "EGL lacks EGL_KHR_surfaceless_context or EGL_KHR_no_config_context");
    }
    if (!dl_backend_egl_fn.BindAPI(EGL_OPENGL_API))
        return dl_backend_egl_fail(e, "EGL cannot bind desktop OpenGL", err);
    e->ctx = dl_backend_egl_fn.CreateContext(e->dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, NULL);
    if (e->ctx == EGL_NO_CONTEXT)
        return dl_backend_egl_fail(e, "cannot create an OpenGL context", err);
    if (!dl_backend_egl_fn.MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx))
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
    .summary = "OpenGL on a surfaceless EGL context (libEGL, loaded when chosen)",
    .open = dl_backend_egl_open,
    .ops = &dl_gl_device,
    .read = dl_backend_egl_read,
    .close = dl_backend_egl_close,
};
