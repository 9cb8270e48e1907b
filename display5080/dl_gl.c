/* dl_gl — shared OpenGL drawing for the GL backends (see dl_gl.h). */
#include "display5080/dl_gl.h"
#include "display5080/dl_logic.h"
#include "display5080/dl_format.h"
#include "util/mem.h"
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
    DL_GL_LOAD(Clear, "glClear");
    DL_GL_LOAD(LogicOp, "glLogicOp");
    DL_GL_LOAD(Color4ub, "glColor4ub");
    DL_GL_LOAD(Begin, "glBegin");
    DL_GL_LOAD(End, "glEnd");
    DL_GL_LOAD(Vertex2i, "glVertex2i");
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
    gl->Clear(GLc_COLOR_BUFFER_BIT);
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

static void dl_gl_pass(dl_gl *g, unsigned glop, unsigned v, const dl_box *b, size_t n)
{
    size_t k;
    g->gl.LogicOp(glop);
    g->gl.Color4ub((unsigned char)v, 0, 0, 255);
    g->gl.Begin(GLc_QUADS);
    for (k = 0; k < n; k++) {
        g->gl.Vertex2i(b[k].x0, b[k].y0);
        g->gl.Vertex2i(b[k].x1 + 1, b[k].y0);
        g->gl.Vertex2i(b[k].x1 + 1, b[k].y1 + 1);
        g->gl.Vertex2i(b[k].x0, b[k].y1 + 1);
    }
    g->gl.End();
}

/* Quads on pixel edges cover exactly the pixels whose centres they hold. */
static int dl_gl_boxes(void *dev, const dl_gc *gc, const dl_box *b, size_t n, diag *err)
{
    dl_gl *g = dev;
    uint8_t clr, set, inv;
    (void)err;
    dl_logic_split(gc->op, (uint8_t)gc->colour, (uint8_t)gc->mask, &clr, &set, &inv);
    if (!inv && (clr | set) == 0xFF) {
        dl_gl_pass(g, GLc_COPY, set, b, n);
        return 0;
    }
    if (clr)
        dl_gl_pass(g, GLc_AND, (uint8_t)~clr, b, n);
    if (set)
        dl_gl_pass(g, GLc_OR, set, b, n);
    if (inv)
        dl_gl_pass(g, GLc_XOR, inv, b, n);
    return 0;
}

static int dl_gl_blt(void *dev, const dl_gc *gc, int x0, int y0, int w, int h,
                     const uint8_t *rows, ptrdiff_t stride, diag *err)
{
    dl_gl *g = dev;
    dl_gl_api *gl = &g->gl;
    size_t n = (size_t)w * (size_t)h, i;
    int copy = gc->op == DL_OP_COPY && gc->mask == 0xFF, j, k;
    gl->WindowPos2i(x0, y0);
    if (copy && stride > 0) {
        gl->PixelStorei(GLc_UNPACK_ROW_LENGTH, (int)stride);
        gl->LogicOp(GLc_COPY);
        gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, rows);
        gl->PixelStorei(GLc_UNPACK_ROW_LENGTH, 0);
        return 0;
    }
    /* Bottom-up rows gathered, or split per pixel into AND, OR and XOR images. */
    if (n * 3 > g->scratch_cap) {
        void *p = g->scratch;
        if (mem_grow(&p, &g->scratch_cap, n * 3, 1))
            return diag_offset(err, DIAG_IO, gc->name, gc->offset, "out of memory for a BLT");
        g->scratch = p;
    }
    for (j = 0; j < h; j++)
        for (k = 0; k < w; k++) {
            uint8_t s = rows[(ptrdiff_t)j * stride + k], clr, set, inv;
            i = (size_t)j * (size_t)w + (size_t)k;
            if (copy) {
                g->scratch[i] = s;
                continue;
            }
            dl_logic_split(gc->op, s, (uint8_t)gc->mask, &clr, &set, &inv);
            g->scratch[i] = (uint8_t)~clr;
            g->scratch[n + i] = set;
            g->scratch[2 * n + i] = inv;
        }
    if (copy) {
        gl->LogicOp(GLc_COPY);
        gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch);
        return 0;
    }
    gl->LogicOp(GLc_AND);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch);
    gl->LogicOp(GLc_OR);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch + n);
    gl->LogicOp(GLc_XOR);
    gl->DrawPixels(w, h, GLc_RED, GLc_UNSIGNED_BYTE, g->scratch + 2 * n);
    return 0;
}

const dl_device dl_gl_device = {.boxes = dl_gl_boxes, .blt = dl_gl_blt};
