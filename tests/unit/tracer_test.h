/* tracer_test — helpers shared by the tracer's test binaries (test_prim,
 * test_csg, test_render, test_oracle): decks parsed from text, random
 * similarity transforms, an independent point classification in double. */
#ifndef TRACER_TEST_H
#define TRACER_TEST_H
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene/scene_parse.h"
#include "cli/cli_scene.h"
#include "trace/probe.h"
#include "render/render.h"
#include "util/recsrc.h"
#include "support.h"

/* The numeric modes the property tests run in, by index 0..TT_MODES-1. */
#define TT_MODES 6
static inline const probe_ops *tt_mode(int i)
{
    static const probe_ops *const all[TT_MODES] = {&q16_probe_ops, &q32_probe_ops, &f32_probe_ops,
                                                   &f64_probe_ops, &hfp32_probe_ops, &hfp64_probe_ops};
    return all[i];
}

/* Parses a deck given as text; fails the test on error. */
static inline scene *tt_parse(const char *text)
{
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    diag_init(&err);
    recsrc_from_memory(&src, &m, "test.scene", text, strlen(text));
    if (scene_parse(&src, &s, &err)) {
        char buf[1024];
        diag_format(&err, buf, sizeof buf);
        fprintf(stderr, "deck did not parse: %s\n", buf);
        return NULL;
    }
    return s;
}

/* Reads a deck file as the CLI does (images beside it); fails the test on
 * error. */
static inline scene *tt_load(const char *path)
{
    cli_files f;
    scene *sc = NULL;
    diag err;
    diag_init(&err);
    if (cli_files_init(&f, &err) == 0) {
        if (cli_scene_load(&f, path, &sc, &err))
            diag_print(stderr, &err);
        cli_files_free(&f);
    }
    return sc;
}

/* Render options: w x h pixels, one sample each, on `threads` threads. */
static inline render_opts tt_render_opts(int w, int h, int threads)
{
    render_opts o;
    memset(&o, 0, sizeof o);
    o.width = w;
    o.height = h;
    o.threads = threads;
    o.aa = 1;
    return o;
}

/* Index of the primitive named name in sc, -1 if none. */
static inline int tt_find_prim(const scene *sc, const char *name)
{
    size_t i;
    for (i = 0; i < sc->nprims; i++)
        if (!strcmp(sc->prims[i].shape->name, name))
            return (int)i;
    return -1;
}

/* Pixels of two images where some channel differs by more than tol;
 * LONG_MAX when their sizes differ. */
static inline long tt_image_over(const image *a, const image *b, int tol)
{
    long n = 0;
    size_t i, k;
    if (a->width != b->width || a->height != b->height)
        return LONG_MAX;
    for (i = 0; i < (size_t)a->width * (size_t)a->height; i++) {
        int big = 0;
        for (k = 0; k < 3; k++)
            if (abs((int)a->px[3 * i + k] - (int)b->px[3 * i + k]) > tol)
                big = 1;
        n += big;
    }
    return n;
}

/* Object coordinates of world point p for primitive sp (double inverse). */
static inline void tt_to_object(const scene_prim *sp, const double *p, double *q)
{
    const double *m = sp->world_from_object;
    double a[9] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]}, c[9], det, w[3];
    int i;
    c[0] = a[4] * a[8] - a[5] * a[7]; c[1] = a[2] * a[7] - a[1] * a[8]; c[2] = a[1] * a[5] - a[2] * a[4];
    c[3] = a[5] * a[6] - a[3] * a[8]; c[4] = a[0] * a[8] - a[2] * a[6]; c[5] = a[2] * a[3] - a[0] * a[5];
    c[6] = a[3] * a[7] - a[4] * a[6]; c[7] = a[1] * a[6] - a[0] * a[7]; c[8] = a[0] * a[4] - a[1] * a[3];
    det = a[0] * c[0] + a[1] * c[3] + a[2] * c[6];
    w[0] = p[0] - m[3]; w[1] = p[1] - m[7]; w[2] = p[2] - m[11];
    for (i = 0; i < 3; i++)
        q[i] = (c[3 * i] * w[0] + c[3 * i + 1] * w[1] + c[3 * i + 2] * w[2]) / det;
}

/* Signed "distance" of object point q to primitive sp (negative inside),
 * exact for planes and spheres, a Lipschitz-1 bound for cylinder/cone sides
 * (cone: measured horizontally). */
static inline double tt_sdf(const scene_prim *sp, const double *q)
{
    const double *d = sp->shape->dim;
    double r = sqrt(q[0] * q[0] + q[1] * q[1]), f;
    switch (sp->shape->kind) {
    case PRIM_SPHERE: return sqrt(r * r + q[2] * q[2]) - d[0];
    case PRIM_CYLINDER:
        f = r - d[0];
        if (-q[2] > f) f = -q[2];
        if (q[2] - d[1] > f) f = q[2] - d[1];
        return f;
    case PRIM_CONE:
        f = r - (d[0] + (d[1] - d[0]) * q[2] / d[2]);
        f /= sqrt(1 + ((d[1] - d[0]) / d[2]) * ((d[1] - d[0]) / d[2]));
        if (-q[2] > f) f = -q[2];
        if (q[2] - d[2] > f) f = q[2] - d[2];
        return f;
    case PRIM_BLOCK: {
        int i;
        f = -q[0];
        for (i = 0; i < 3; i++) {
            if (-q[i] > f) f = -q[i];
            if (q[i] - d[i] > f) f = q[i] - d[i];
        }
        return f;
    }
    default: return q[2];
    }
}

/* A random rotation/uniform scale/translation tail for a deck, scale in
 * [0.5, 2], translation in [-2, 2]^3. */
static inline void tt_random_tail(uint64_t *s, char *buf, size_t len)
{
    snprintf(buf, len, "-\n  ROTATE AXIS %.6f %.6f %.6f %.4f -\n  SCALE %.5f TRANSLATE %.5f %.5f %.5f",
             test_uniform(s, -1, 1), test_uniform(s, -1, 1), test_uniform(s, 0.1, 1),
             test_uniform(s, 0, 360), test_uniform(s, 0.5, 2), test_uniform(s, -2, 2),
             test_uniform(s, -2, 2), test_uniform(s, -2, 2));
}

/* Uniform random unit vector. */
static inline void tt_random_dir(uint64_t *s, double *d)
{
    double l;
    do {
        d[0] = test_uniform(s, -1, 1);
        d[1] = test_uniform(s, -1, 1);
        d[2] = test_uniform(s, -1, 1);
        l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (l < 0.1 || l > 1);
    d[0] /= l; d[1] /= l; d[2] /= l;
}
#endif
