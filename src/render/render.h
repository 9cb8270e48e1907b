/* render — the mode-independent rendering driver. It picks a numeric mode's
 * ops table by name, has that mode compile the scene model, splits the image
 * into tiles rendered by worker threads, and sums the per-thread counters.
 * Output: an RGB8 framebuffer plus the primitive id (PID) seen at each pixel.
 * Data flow: scene (double) -> ops->compile -> tiles -> render_fb -> sinks. */
#ifndef RENDER_H
#define RENDER_H
#include <stdint.h>
#include "model/scene.h"
#include "image/image.h"
#include "util/diag.h"

#define RENDER_TILE 32        /* tile side in pixels */
#define RENDER_MAX_AA 16      /* samples per pixel side */
#define RENDER_MAX_THREADS 256
/* Secondary (reflected and refracted) rays a pixel may trace, per sample:
 * with the energy rule (DIFFUSE + MIRROR + TRANSMIT <= 1) and the weight
 * cut, real decks stay far below it (scenes/glass.scene: under 20). */
#define RENDER_MAX_RAYS_PER_SAMPLE 1024

typedef struct render_stats {
    unsigned long long rays_primary, rays_shadow, rays_reflected, rays_refracted;
    unsigned long long pds_lookups, fx_overflows;
    unsigned long long prim_tests, bound_tests, csg_pruned, arena_full;
    unsigned long long rays_capped;   /* secondary rays not traced: the pixel's ray cap was spent */
    double time_compile_s, time_render_s;
} render_stats;

typedef struct render_opts {
    int width, height;        /* image size; 0 = the scene view's size */
    int threads;              /* worker threads, >= 1 */
    int aa;                   /* NxN samples per pixel, 1..RENDER_MAX_AA */
    /* Called (serialised) after each finished tile; may be NULL. */
    void (*progress)(void *ctx, long done, long total);
    void *progress_ctx;
} render_opts;

typedef struct render_fb {
    image img;                /* RGB8, top row first */
    int32_t *pid;             /* width*height primitive ids, -1 = background */
} render_fb;

/* One numeric mode's implementation (q16_render_ops, ...). Opaque compiled
 * scenes and per-thread contexts; render_tile fills pixels [x0,x1)x[y0,y1)
 * of fb and adds to st. */
typedef struct render_ops {
    const char *name;
    int (*compile)(const scene *sc, void **cs, diag *err);
    void (*free)(void *cs);
    int (*thread_new)(const void *cs, void **tc);     /* 0, or -1 out of memory */
    void (*thread_free)(void *tc);
    void (*render_tile)(const void *cs, void *tc, const render_opts *o,
                        int x0, int y0, int x1, int y1, render_fb *fb, render_stats *st);
} render_ops;

extern const render_ops q16_render_ops, q32_render_ops, f32_render_ops, f64_render_ops;

/* The ops table for "q16", "q32", "f32" or "f64"; NULL for anything else. */
const render_ops *render_ops_find(const char *name);

/* Renders sc in mode ops into *fb (allocated here; release with
 * render_fb_free). st receives the counters and timings. 0 on success, else
 * the diag status (DIAG_INPUT for scene problems found at compile time,
 * DIAG_USAGE for bad options, DIAG_IO for memory). *fb is untouched then. */
int render_scene(const scene *sc, const render_ops *ops, const render_opts *o,
                 render_fb *fb, render_stats *st, diag *err);
void render_fb_free(render_fb *fb);
/* Prints the counters as key=value lines (the --stats format). */
void render_stats_print(FILE *f, const render_stats *st);
#endif
