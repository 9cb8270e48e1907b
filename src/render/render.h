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
#include "num/hfp.h"
#include "render/idmap.h"

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
    unsigned long long hfp_exc[HFP_EXC_N];   /* hfp modes: exceptions by kind (hfp.h) */
    unsigned long long prim_tests, bound_tests, csg_pruned, arena_full;
    /* primary rays whose first possible surface lies beyond the mode's
     * range (docs/numerics.md): they show the background */
    unsigned long long range_cut;
    /* work the scene did not need: hits whose (u,v) was not evaluated (no
     * PDS, texture or bump on the face), shadow rays not traced (the
     * attribute has no diffuse or specular term) */
    unsigned long long uv_skipped, shadow_skipped;
    unsigned long long rays_capped;   /* secondary rays not traced: the pixel's ray cap was spent */
    /* the compiled scene: its objects, and those traced through an earlier
     * object's tree moved by a translation or a turn (instances,
     * model/scene_inst.h); the scene's, the same in every part of a split
     * render */
    unsigned long long objects, inst_moved, inst_turned;
    double time_compile_s, time_render_s;
} render_stats;

/* Where a render stands, for a progress display. */
typedef struct render_progress {
    long tiles_done, tiles;
    /* The share of the work done, 0..1: finished tiles weighted by their
     * cost, measured before the render by timing a few one-sample pixels of
     * each tile, so that it grows linearly in time (a tile of sky costs
     * less than one of glass). */
    double fraction;
    double elapsed_s;         /* since render_scene began (compile included) */
    unsigned long long rays;  /* rays traced so far, of every kind */
} render_progress;

typedef struct render_opts {
    int width, height;        /* image size; 0 = the scene view's size */
    int threads;              /* worker threads, >= 1 */
    int aa;                   /* NxN samples per pixel, 1..RENDER_MAX_AA */
    /* Pixels [x0,x1) x [y0,y1) of the image to render (a region of a
     * larger job, e.g. one rank's share); all 0 = the whole image. Pixels
     * outside it are left 0 in the framebuffer (pid 0 too). */
    int region[4];
    int ids;                  /* also fill render_fb.ids */
    /* Leave render_fb.pid NULL: no output reads it (a picture file only).
     * The array is 4 bytes a pixel, more than the picture's 3, and writing
     * it faults in its pages (docs/performance.md, run N). */
    int skip_pid;
    /* Called (serialised) after each finished tile; may be NULL (and then
     * no tile costs are measured). */
    void (*progress)(void *ctx, const render_progress *p);
    void *progress_ctx;
} render_opts;

typedef struct render_fb {
    image img;                /* RGB8, top row first */
    int32_t *pid;             /* width*height primitive ids, -1 = background
                                 (NULL with render_opts.skip_pid) */
    idmap ids;                /* with render_opts.ids: primitive, face, region
                                 and distance of the centre sample's hit */
} render_fb;

/* One numeric mode's implementation (q16_render_ops, ...). Opaque compiled
 * scenes and per-thread contexts; render_tile fills pixels [x0,x1)x[y0,y1)
 * of fb and adds to st. */
typedef struct render_ops {
    const char *name;
    const char *isa;          /* the code it was compiled for: "baseline" or
                                 "x86-64-v3" (Makefile, ISA_V3) */
    int (*compile)(const scene *sc, void **cs, diag *err);
    /* Sets st's objects, inst_moved and inst_turned to the compiled
     * scene's. */
    void (*counts)(const void *cs, render_stats *st);
    void (*free)(void *cs);
    int (*thread_new)(const void *cs, void **tc);     /* 0, or -1 out of memory */
    void (*thread_free)(void *tc);
    void (*render_tile)(const void *cs, void *tc, const render_opts *o,
                        int x0, int y0, int x1, int y1, render_fb *fb, render_stats *st);
    /* The region (attribute index) face `face` of primitive prim shows at
     * (u,v), by the mode's PDS lookup. */
    int (*region)(const void *cs, void *tc, int prim, int face, double u, double v);
} render_ops;

extern const render_ops q16_render_ops, q32_render_ops, f32_render_ops, f64_render_ops,
    hfp32_render_ops, hfp64_render_ops;

/* Which build of a mode render_ops_find gives: the fastest this processor
 * runs (x86-64-v3 where the binary holds it and the processor has AVX2,
 * BMI2 and FMA), or the baseline. Both draw the same pictures. */
typedef enum render_isa { RENDER_ISA_AUTO, RENDER_ISA_BASELINE } render_isa;

/* The ops table for "q16", "q32", "f32", "f64", "hfp32" or "hfp64"; NULL for
 * anything else. */
const render_ops *render_ops_find(const char *name, render_isa isa);

/* Checks a region (x0 y0 x1 y1) against a width x height image: 0 when
 * 0 <= x0 < x1 <= width and 0 <= y0 < y1 <= height, or all four are 0. */
int render_region_check(const int region[4], int width, int height);

/* Renders sc in mode ops into *fb (allocated here, the whole image even when
 * o->region asks for part of it; release with render_fb_free). st receives the counters and timings. 0 on success, else
 * the diag status (DIAG_INPUT for scene problems found at compile time,
 * DIAG_USAGE for bad options, DIAG_IO for memory). *fb is untouched then. */
int render_scene(const scene *sc, const render_ops *ops, const render_opts *o,
                 render_fb *fb, render_stats *st, diag *err);
void render_fb_free(render_fb *fb);
/* Adds b's counters (not its times) to a; of the scene's counts (objects,
 * inst_moved, inst_turned) a keeps the larger, so that the parts of one
 * render report them once. */
void render_stats_add(render_stats *a, const render_stats *b);
/* Prints the counters as key=value lines (the --stats format). */
void render_stats_print(FILE *f, const render_stats *st);
#endif
