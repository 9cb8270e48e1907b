/* dl_gl — the OpenGL frame-buffer writer shared by the osmesa and egl
 * backends, written once against a table of GL entry points that each
 * backend loads through its own GetProcAddress (so the two GL libraries never
 * clash at link time). The 5081 frame buffer is the red channel of an RGBA8
 * colour buffer: boxes are quads on pixel edges, blocks are glDrawPixels,
 * and every write goes through glLogicOp, op and plane mask being split into
 * at most three exact passes (AND, OR, XOR; see dl_logic_split). Shapes reach
 * it already rasterised and clipped (dl_cover), so GL's own line and polygon
 * rules never decide a pixel.
 * Legacy (compatibility profile) GL 1.4: immediate mode, glWindowPos,
 * glDrawPixels; the EGL backend adds framebuffer objects (GL 3.0). */
#ifndef DL_GL_H
#define DL_GL_H
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_device.h"

typedef void (*dl_gl_proc)(void);
typedef dl_gl_proc (*dl_gl_getproc)(const char *name);

/* GL entry points; GL types are spelled out as C types so this header does
 * not need GL/gl.h (unsigned int = GLenum/GLuint, int = GLint/GLsizei). */
typedef struct dl_gl_api {
    void (*Viewport)(int, int, int, int);
    void (*MatrixMode)(unsigned);
    void (*LoadIdentity)(void);
    void (*Ortho)(double, double, double, double, double, double);
    void (*Enable)(unsigned);
    void (*Disable)(unsigned);
    void (*ClearColor)(float, float, float, float);
    void (*Clear)(unsigned);
    void (*LogicOp)(unsigned);
    void (*Color4ub)(unsigned char, unsigned char, unsigned char, unsigned char);
    void (*Begin)(unsigned);
    void (*End)(void);
    void (*Vertex2i)(int, int);
    void (*PixelStorei)(unsigned, int);
    void (*WindowPos2i)(int, int);
    void (*DrawPixels)(int, int, unsigned, unsigned, const void *);
    void (*ReadPixels)(int, int, int, int, unsigned, unsigned, void *);
    void (*Finish)(void);
    unsigned (*GetError)(void);
    const unsigned char *(*GetString)(unsigned);
    /* framebuffer objects: loaded only with fbo = 1 */
    void (*GenFramebuffers)(int, unsigned *);
    void (*BindFramebuffer)(unsigned, unsigned);
    void (*DeleteFramebuffers)(int, const unsigned *);
    void (*GenRenderbuffers)(int, unsigned *);
    void (*BindRenderbuffer)(unsigned, unsigned);
    void (*DeleteRenderbuffers)(int, const unsigned *);
    void (*RenderbufferStorage)(unsigned, unsigned, int, int);
    void (*FramebufferRenderbuffer)(unsigned, unsigned, unsigned, unsigned);
    unsigned (*CheckFramebufferStatus)(unsigned);
} dl_gl_api;

typedef struct dl_gl {
    dl_gl_api gl;
    int width, height;
    unsigned fbo, rb[2];       /* EGL only */
    uint8_t *scratch;
    size_t scratch_cap;
} dl_gl;

extern const dl_device dl_gl_device;

/* Loads the entry points (with fbo, the framebuffer-object ones too); on a
 * missing one returns DIAG_IO naming it, with `who` (the backend) first. */
int dl_gl_load(dl_gl *g, dl_gl_getproc get, int fbo, const char *who, diag *err);
/* With a current context: creates the FBO if fbo is set, sets up the
 * device-pixel projection and clears the indices to 0. */
int dl_gl_start(dl_gl *g, int width, int height, int fbo, const char *who, diag *err);
/* Reads width*height indices, bottom row first; DIAG_IO on a GL error. */
int dl_gl_read(dl_gl *g, uint8_t *px, const char *who, diag *err);
/* Deletes the FBO (context still current) and frees scratch memory. */
void dl_gl_stop(dl_gl *g);
#endif
