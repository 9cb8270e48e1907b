/* dl_gl — shared OpenGL drawing for the GL backends (see dl_gl.h). */
#include "display5080/dl_gl.h"
#include "util/dmath.h"
#include "display5080/dl_logic.h"
#include "display5080/dl_format.h"
#include "util/mem.h"
#include <math.h>
#include <string.h>

/* GL constants used here (values fixed by the GL specification), spelled
 * out so that this file builds where no GL headers are installed. */
enum {
    GLc_PROJECTION = 0x1701, GLc_MODELVIEW = 0x1700, GLc_DITHER = 0x0BD0,
    GLc_BLEND = 0x0BE2, GLc_MULTISAMPLE = 0x809D, GLc_SCISSOR_TEST = 0x0C11,
    GLc_COLOR_LOGIC_OP = 0x0BF2, GLc_STENCIL_TEST = 0x0B90, GLc_LINE_SMOOTH = 0x0B20,
    GLc_POINT_SMOOTH = 0x0B10, GLc_POLYGON_SMOOTH = 0x0B41,
    GLc_COLOR_BUFFER_BIT = 0x4000, GLc_STENCIL_BUFFER_BIT = 0x0400,
    GLc_COPY = 0x1503, GLc_AND = 0x1501, GLc_OR = 0x1507, GLc_XOR = 0x1506,
    GLc_ALWAYS = 0x0207, GLc_EQUAL = 0x0202, GLc_KEEP = 0x1E00, GLc_REPLACE = 0x1E01,
    GLc_INVERT = 0x150A, GLc_POINTS = 0, GLc_LINES = 1, GLc_LINE_LOOP = 2,
    GLc_LINE_STRIP = 3, GLc_TRIANGLE_FAN = 6, GLc_QUADS = 7,
    GLc_UNPACK_ALIGNMENT = 0x0CF5, GLc_PACK_ALIGNMENT = 0x0D05,
    GLc_UNPACK_ROW_LENGTH = 0x0CF2, GLc_RED = 0x1903, GLc_UNSIGNED_BYTE = 0x1401,
    GLc_FRAMEBUFFER = 0x8D40, GLc_RENDERBUFFER = 0x8D41, GLc_RGBA8 = 0x8058,
    GLc_DEPTH24_STENCIL8 = 0x88F0, GLc_COLOR_ATTACHMENT0 = 0x8CE0,
    GLc_DEPTH_STENCIL_ATTACHMENT = 0x821A, GLc_FRAMEBUFFER_COMPLETE = 0x8CD5,
    GLc_RENDERER = 0x1F01
};

#define DL_GL_LOAD(field, sym)                                                    \
    do {                                                                          \
        dl_gl_proc p_ = get(sym);                                                 \
        if (!p_)                                                                  \
            return diag_at(err, DIAG_IO, who, 0, 0, "OpenGL entry point %s is missing", sym); \
        memcpy(&g->gl.field, &p_, sizeof p_);                                     \
    } while (0)

int dl_gl_load(dl_gl *g, dl_gl_getproc get, int fbo, const char *who, diag *err)
{
    memset(g, 0, sizeof *g);
    DL_GL_LOAD(Viewport, "glViewport");
    DL_GL_LOAD(MatrixMode, "glMatrixMode");
    DL_GL_LOAD(LoadIdentity, "glLoadIdentity");
    DL_GL_LOAD(Ortho, "glOrtho");
    DL_GL_LOAD(Enable, "glEnable");
    DL_GL_LOAD(Disable, "glDisable");
    DL_GL_LOAD(ClearColor, "glClearColor");
    DL_GL_LOAD(ClearStencil, "glClearStencil");
    DL_GL_LOAD(Clear, "glClear");
    DL_GL_LOAD(Scissor, "glScissor");
    DL_GL_LOAD(LogicOp, "glLogicOp");
    DL_GL_LOAD(ColorMask, "glColorMask");
    DL_GL_LOAD(StencilFunc, "glStencilFunc");
    DL_GL_LOAD(StencilOp, "glStencilOp");
    DL_GL_LOAD(StencilMask, "glStencilMask");
    DL_GL_LOAD(Color4ub, "glColor4ub");
    DL_GL_LOAD(Begin, "glBegin");
    DL_GL_LOAD(End, "glEnd");
    DL_GL_LOAD(Vertex2i, "glVertex2i");
    DL_GL_LOAD(Vertex2d, "glVertex2d");
    DL_GL_LOAD(PixelStorei, "glPixelStorei");
    DL_GL_LOAD(WindowPos2i, "glWindowPos2i");
    DL_GL_LOAD(DrawPixels, "glDrawPixels");
    DL_GL_LOAD(ReadPixels, "glReadPixels");
    DL_GL_LOAD(Finish, "glFinish");
    DL_GL_LOAD(GetError, "glGetError");
    DL_GL_LOAD(GetString, "glGetString");
    if (fbo) {
        DL_GL_LOAD(GenFramebuffers, "glGenFramebuffers");
        DL_GL_LOAD(BindFramebuffer, "glBindFramebuffer");
        DL_GL_LOAD(DeleteFramebuffers, "glDeleteFramebuffers");
        DL_GL_LOAD(GenRenderbuffers, "glGenRenderbuffers");
        DL_GL_LOAD(BindRenderbuffer, "glBindRenderbuffer");
        DL_GL_LOAD(DeleteRenderbuffers, "glDeleteRenderbuffers");
        DL_GL_LOAD(RenderbufferStorage, "glRenderbufferStorage");
        DL_GL_LOAD(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
        DL_GL_LOAD(CheckFramebufferStatus, "glCheckFramebufferStatus");
    }
    return 0;
}

int dl_gl_start(dl_gl *g, int width, int height, int fbo, const char *who, diag *err)
{
    dl_gl_api *gl = &g->gl;
    g->width = width;
    g->height = height;
    if (fbo) {
        gl->GenFramebuffers(1, &g->fbo);
        gl->BindFramebuffer(GLc_FRAMEBUFFER, g->fbo);
        gl->GenRenderbuffers(2, g->rb);
        gl->BindRenderbuffer(GLc_RENDERBUFFER, g->rb[0]);
        gl->RenderbufferStorage(GLc_RENDERBUFFER, GLc_RGBA8, width, height);
        gl->FramebufferRenderbuffer(GLc_FRAMEBUFFER, GLc_COLOR_ATTACHMENT0, GLc_RENDERBUFFER, g->rb[0]);
        gl->BindRenderbuffer(GLc_RENDERBUFFER, g->rb[1]);
        gl->RenderbufferStorage(GLc_RENDERBUFFER, GLc_DEPTH24_STENCIL8, width, height);
        gl->FramebufferRenderbuffer(GLc_FRAMEBUFFER, GLc_DEPTH_STENCIL_ATTACHMENT, GLc_RENDERBUFFER,
                                    g->rb[1]);
        if (gl->CheckFramebufferStatus(GLc_FRAMEBUFFER) != GLc_FRAMEBUFFER_COMPLETE)
            return diag_at(err, DIAG_IO, who, 0, 0, "cannot create a %dx%d framebuffer object",
                           width, height);
    }
    gl->Viewport(0, 0, width, height);
    gl->MatrixMode(GLc_PROJECTION);
    gl->LoadIdentity();
    gl->Ortho(0, width, 0, height, -1, 1);
    gl->MatrixMode(GLc_MODELVIEW);
    gl->LoadIdentity();
    gl->Disable(GLc_DITHER);
    gl->Disable(GLc_BLEND);
    gl->Disable(GLc_MULTISAMPLE);
    gl->Disable(GLc_LINE_SMOOTH);
    gl->Disable(GLc_POINT_SMOOTH);
    gl->Disable(GLc_POLYGON_SMOOTH);
    gl->Disable(GLc_SCISSOR_TEST);
    gl->ClearColor(0, 0, 0, 0);
    gl->ClearStencil(0);
    gl->StencilMask(0xFF);
    gl->Clear(GLc_COLOR_BUFFER_BIT | GLc_STENCIL_BUFFER_BIT);
    gl->Enable(GLc_SCISSOR_TEST);
    gl->Enable(GLc_COLOR_LOGIC_OP);
    gl->PixelStorei(GLc_UNPACK_ALIGNMENT, 1);
    gl->PixelStorei(GLc_PACK_ALIGNMENT, 1);
    if (gl->GetError())
        return diag_at(err, DIAG_IO, who, 0, 0, "OpenGL set-up failed");
    return 0;
}

int dl_gl_read(dl_gl *g, uint8_t *px, const char *who, diag *err)
{
    unsigned e;
    g->gl.Disable(GLc_SCISSOR_TEST);
    g->gl.ReadPixels(0, 0, g->width, g->height, GLc_RED, GLc_UNSIGNED_BYTE, px);
    g->gl.Finish();
    if ((e = g->gl.GetError()) != 0)
        return diag_at(err, DIAG_IO, who, 0, 0, "OpenGL error 0x%04X while drawing", e);
    return 0;
}

void dl_gl_stop(dl_gl *g)
{
    /* Drawing still in flight when a list is refused part-way must end
     * before the context goes: OSMesa's destroy crashes otherwise. */
    if (g->gl.Finish)
        g->gl.Finish();
    if (g->fbo) {
        g->gl.BindFramebuffer(GLc_FRAMEBUFFER, 0);
        g->gl.DeleteFramebuffers(1, &g->fbo);
        g->gl.DeleteRenderbuffers(2, g->rb);
        g->fbo = 0;
    }
    mem_free(g->scratch);
    g->scratch = NULL;
    g->scratch_cap = 0;
}

static void dl_gl_scissor(dl_gl *g, const dl_gc *gc)
{
    g->gl.Scissor(gc->cx0, gc->cy0, gc->cx1 - gc->cx0 + 1, gc->cy1 - gc->cy0 + 1);
}

static void dl_gl_quad(dl_gl *g, int x0, int y0, int x1, int y1)
{
    g->gl.Begin(GLc_QUADS);
    g->gl.Vertex2i(x0, y0);
    g->gl.Vertex2i(x1 + 1, y0);
    g->gl.Vertex2i(x1 + 1, y1 + 1);
    g->gl.Vertex2i(x0, y1 + 1);
    g->gl.End();
}

static void dl_gl_pass(dl_gl *g, unsigned glop, unsigned v, int x0, int y0, int x1, int y1)
{
    g->gl.LogicOp(glop);
    g->gl.Color4ub((unsigned char)v, 0, 0, 255);
    dl_gl_quad(g, x0, y0, x1, y1);
}

/* Writes gc->colour with gc->op and gc->mask over the rectangle (pixels
 * outside the stencil coverage are already masked off by the caller). */
static void dl_gl_paint(dl_gl *g, const dl_gc *gc, int x0, int y0, int x1, int y1)
{
    uint8_t clr, set, inv;
    dl_logic_split(gc->op, (uint8_t)gc->colour, (uint8_t)gc->mask, &clr, &set, &inv);
    if (!inv && (clr | set) == 0xFF) {
        dl_gl_pass(g, GLc_COPY, set, x0, y0, x1, y1);
        return;
    }
    if (clr)
        dl_gl_pass(g, GLc_AND, (uint8_t)~clr, x0, y0, x1, y1);
    if (set)
        dl_gl_pass(g, GLc_OR, set, x0, y0, x1, y1);
    if (inv)
        dl_gl_pass(g, GLc_XOR, inv, x0, y0, x1, y1);
}

static int dl_gl_rect(void *dev, const dl_gc *gc, int x0, int y0, int x1, int y1, diag *err)
{
    dl_gl *g = dev;
    (void)err;
    if (x0 < gc->cx0) x0 = gc->cx0;
    if (y0 < gc->cy0) y0 = gc->cy0;
    if (x1 > gc->cx1) x1 = gc->cx1;
    if (y1 > gc->cy1) y1 = gc->cy1;
    if (x1 < x0 || y1 < y0)
        return 0;
    dl_gl_scissor(g, gc);
    dl_gl_paint(g, gc, x0, y0, x1, y1);
    return 0;
}

static int dl_gl_blt(void *dev, const dl_gc *gc, int x0, int y0, int w, int h,
                     const uint8_t *rows, size_t stride, diag *err)
{
    dl_gl *g = dev;
    dl_gl_api *gl = &g->gl;
    size_t n = (size_t)w * (size_t)h, i;
    int j, k;
    dl_gl_scissor(g, gc);
    gl->WindowPos2i(x0, y0);
    if (gc->op == DL_OP_COPY && gc->mask == 0xFF) {
        gl->PixelStorei(GLc_UNPACK_ROW_LENGTH, (int)stride);
        gl->LogicOp(GLc_COPY);
        gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, rows);
        gl->PixelStorei(GLc_UNPACK_ROW_LENGTH, 0);
        return 0;
    }
    /* Per-pixel split into AND, OR and XOR images. */
    if (n * 3 > g->scratch_cap) {
        void *p = g->scratch;
        if (mem_grow(&p, &g->scratch_cap, n * 3, 1))
            return diag_at(err, DIAG_IO, gc->name, 0, 0, "out of memory for a BLT");
        g->scratch = p;
    }
    for (j = 0; j < h; j++)
        for (k = 0; k < w; k++) {
            uint8_t clr, set, inv;
            i = (size_t)j * (size_t)w + (size_t)k;
            dl_logic_split(gc->op, rows[(size_t)j * stride + (size_t)k], (uint8_t)gc->mask,
                           &clr, &set, &inv);
            g->scratch[i] = (uint8_t)~clr;
            g->scratch[n + i] = set;
            g->scratch[2 * n + i] = inv;
        }
    gl->LogicOp(GLc_AND);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch);
    gl->LogicOp(GLc_OR);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch + n);
    gl->LogicOp(GLc_XOR);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch + 2 * n);
    return 0;
}

/* Stencil coverage: begin (mode REPLACE or INVERT) and finish (write once
 * through the stencil, then clear it inside the clip). */
static void dl_gl_cover_begin(dl_gl *g, const dl_gc *gc, unsigned mode)
{
    dl_gl_api *gl = &g->gl;
    dl_gl_scissor(g, gc);
    gl->Enable(GLc_STENCIL_TEST);
    gl->ColorMask(0, 0, 0, 0);
    gl->StencilMask(1);
    gl->StencilFunc(GLc_ALWAYS, 1, 1);
    gl->StencilOp(GLc_KEEP, GLc_KEEP, mode);
}

static void dl_gl_cover_end(dl_gl *g, const dl_gc *gc)
{
    dl_gl_api *gl = &g->gl;
    gl->ColorMask(1, 1, 1, 1);
    gl->StencilFunc(GLc_EQUAL, 1, 1);
    gl->StencilOp(GLc_KEEP, GLc_KEEP, GLc_KEEP);
    dl_gl_paint(g, gc, gc->cx0, gc->cy0, gc->cx1, gc->cy1);
    gl->Clear(GLc_STENCIL_BUFFER_BIT);
    gl->Disable(GLc_STENCIL_TEST);
}

static void dl_gl_vertex(dl_gl *g, double x, double y) { g->gl.Vertex2d(x + 0.5, y + 0.5); }

static int dl_gl_lines(void *dev, const dl_gc *gc, const int *xy, size_t n, int strip, diag *err)
{
    dl_gl *g = dev;
    size_t i;
    (void)err;
    dl_gl_cover_begin(g, gc, GLc_REPLACE);
    g->gl.Begin(strip ? GLc_LINE_STRIP : GLc_LINES);
    for (i = 0; i < n; i++)
        dl_gl_vertex(g, xy[2 * i], xy[2 * i + 1]);
    g->gl.End();
    g->gl.Begin(GLc_POINTS);   /* GL lines leave out their last pixel */
    for (i = 0; i < n; i++)
        dl_gl_vertex(g, xy[2 * i], xy[2 * i + 1]);
    g->gl.End();
    dl_gl_cover_end(g, gc);
    return 0;
}

static int dl_gl_polygon(void *dev, const dl_gc *gc, const int *xy, size_t n, diag *err)
{
    dl_gl *g = dev;
    size_t i;
    (void)err;
    dl_gl_cover_begin(g, gc, GLc_INVERT);
    g->gl.Begin(GLc_TRIANGLE_FAN);
    for (i = 0; i < n; i++)
        dl_gl_vertex(g, xy[2 * i], xy[2 * i + 1]);
    g->gl.End();
    dl_gl_cover_end(g, gc);
    return 0;
}

static int dl_gl_circle(void *dev, const dl_gc *gc, int cx, int cy, unsigned r, int fill,
                        diag *err)
{
    dl_gl *g = dev;
    /* A regular polygon whose sides stay within 0.1 pixel of the circle. */
    double rad = fill ? r + 0.5 : r, step;
    int k, n;
    (void)err;
    n = rad < 1 ? 4 : (int)ceil(DMATH_PI / acos(1 - 0.1 / (rad + 0.1)));
    if (n < 8) n = 8;
    if (n > 4096) n = 4096;
    step = 2 * DMATH_PI / n;
    dl_gl_cover_begin(g, gc, GLc_REPLACE);
    g->gl.Begin(fill ? GLc_TRIANGLE_FAN : GLc_LINE_LOOP);
    for (k = 0; k < n; k++)
        dl_gl_vertex(g, cx + rad * cos(k * step), cy + rad * sin(k * step));
    g->gl.End();
    if (!fill) {
        g->gl.Begin(GLc_POINTS);
        dl_gl_vertex(g, cx + (double)r, cy);
        g->gl.End();
    }
    dl_gl_cover_end(g, gc);
    return 0;
}

const dl_device dl_gl_device = {dl_gl_rect, dl_gl_blt, dl_gl_lines, dl_gl_polygon, dl_gl_circle};
