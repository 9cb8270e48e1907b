/* cscene — a scene compiled for one numeric mode: the normalisation into the
 * fixed-point range, compiled primitives, the CSG tree, lights and camera.
 * Built from the double-precision scene model, which must outlive it (the
 * attributes, textures and bump patterns are read from it). Modal: compiled
 * per numeric mode. */
#ifndef TRACE_CSCENE_H
#define TRACE_CSCENE_H
#include "util/dmath.h"
#include "util/lightbuf.h"
#include "model/scene_box.h"
#include "geom/csg.h"
#include "pds/pds.h"
#include <string.h>

#define CSCENE_MAX_DEPTH 32   /* recursion limit applied to scene max_depth */
#define CSCENE_MAX_PLANES 64  /* half-spaces a primary ray is advanced over */
#define CSCENE_LBUF_MIN 8      /* bounded objects for a light buffer */
#define CSCENE_LBUF_GROW (1.0 / 32)   /* its boxes' growth, normalised world */

typedef struct cscene_light {
    vec3 pos;                 /* normalised world */
    double rgb[3];            /* colour times intensity */
} cscene_light;

/* What a hit on one face of a primitive looks up, resolved at compile time
 * (cscene_face_at). */
typedef struct cscene_face {
    const scene_attr *plain;  /* the primitive's own attribute */
    const NS(pds) *map;       /* the PDS bound to the face (FACE), or NULL */
    const pds_def *def;       /* its definition, or NULL */
    int need_uv;              /* the hit needs (u,v) and its tangents: the
                                 face has a PDS, or the plain attribute a
                                 texture or a bump */
    int flat_k;               /* the face's plane in prim.pl_d, whose normal
                                 serves when (u,v) is not needed
                                 (prim_face_plane), or -1 */
} cscene_face;

typedef struct cscene {
    const scene *sc;
    geom_norm nm;
    prim *prims;
    size_t nprims;
    /* the primitives' planes (prim.pl, prim.pl_d) in primitive order, as
     * many as each has: a sphere none, a block six */
    prim_plane *prim_pl;
    double (*prim_pl_d)[4];
    prim_frame *prim_fr;
    /* Instances (model/scene_inst.h): per root its csg_inst, and per
     * primitive the root of the instance it belongs to, or -1; both NULL
     * where the scene has none. An instance's primitives are not compiled:
     * its master's stand for them (cscene_prim_of, cscene_surface). */
    csg_inst *root_inst;
    csg_turn *inst_turn;           /* the turned ones' frame changes */
    size_t inst_moved, inst_turned;   /* the instances taken, translated
                                         and turned (render --stats) */
    int *prim_root;
    prim_lin *lins;                /* the distinct linear parts (twins share
                                      one), in order: the frames point
                                      into them */
    void *prim_mem;                /* the one block of prims, prim_pl,
                                      prim_pl_d, prim_fr, face_row and
                                      lins (cscene_prim_room) */
    csg tree;
    cscene_light *lights;
    size_t nlights;
    lightbuf *lbuf;           /* per light, for shadow rays (cscene_lights);
                                 NULL where the hierarchy serves alone */
    lightbuf eyebuf;          /* the same at the eye, for camera rays */
    double eye[3], fwd[3], right[3], up[3], tan_half;   /* camera, normalised */
    /* Primary rays start where something can first be hit (computed in
     * double, see cscene_primary): the sphere of radius bound_r about the
     * centre that holds every bounded primitive (0: none), and the planes
     * of the half-spaces (n, d). orig_max bounds |origin| in this mode;
     * below orig_in2 (a hair under its square) |origin|^2 is certainly
     * within it, without a square root. */
    double bound_r, orig_max, orig_in2;
    double planes[CSCENE_MAX_PLANES][4];
    double plane_gap[CSCENE_MAX_PLANES];   /* d - n.eye per plane */
    size_t nplanes;
    double eye2;              /* |eye|^2 */
    vec3 eye_n;               /* the eye in num, when it is in range */
    int eye_ok;
    int advance;              /* 0: more half-spaces than CSCENE_MAX_PLANES */
    int max_depth;
    /* Attribute mapping: maps[i] is scene map i compiled for this mode, or
     * NULL when no face is bound to it (nothing is compiled that no ray can
     * look up). */
    NS(pds) **maps;
    size_t nmaps;
    /* rows of 1 + SCENE_MAX_FACES entries: entry 0 for a face number
     * outside 0..SCENE_MAX_FACES-1, then one per face. Row
     * a * PRIM_KIND_COUNT + kind serves every primitive of that kind and
     * attribute a with no face bound by FACE, so a large scene keeps a
     * few rows, not one per primitive; each other primitive has a row of
     * its own. face_row[i]: the index in faces of primitive i's row. */
    cscene_face *faces;
    size_t *face_row;
    int transparent;          /* some attribute transmits light: shadow rays
                                 then look up what they cross */
} cscene;

/* The entry of face `face` of primitive pi. */
static inline const cscene_face *cscene_face_at(const cscene *cs, int pi, int face)
{
    size_t k = face >= 0 && face < SCENE_MAX_FACES ? (size_t)face + 1 : 0;
    return &cs->faces[cs->face_row[pi] + k];
}

/* The compiled primitive that stands for primitive pi: its own, or for a
 * primitive of an instance its master's (at the point moved by *in's
 * shift, or carried by its q and shift where it is turned:
 * cscene_surface_inst; *in NULL otherwise). */
static inline const prim *cscene_prim_of(const cscene *cs, int pi, const csg_inst **in)
{
    int r;
    if (!cs->prim_root || (r = cs->prim_root[pi]) < 0) {
        *in = NULL;
        return &cs->prims[pi];
    }
    *in = &cs->root_inst[r];
    return &cs->prims[pi - (*in)->dprim];
}

/* A direction v of a turned instance's master (csg_turn.q) carried back
 * into the instance: q^T v (q is a rotation, its inverse its transpose
 * to within SCENE_INST_ORTHO), in place. */
static inline void NS(cscene_inst_back)(const csg_inst *in, double v[3])
{
    double w[3];
    dmath_m3_tmul_v(in->turn->q, v, w);
    memcpy(v, w, sizeof w);
}

/* The canonical map a thread formed last, and whose: prim is the
 * primitive's index plus one (0, as a zeroed context holds it: none).
 * Consecutive hits that need (u,v) mostly fall on one primitive, which
 * then forms its map once, not once a hit (docs/performance.md, run AW). */
typedef struct cscene_map_memo {
    int prim;
    double a[9];
} cscene_map_memo;

/* Compiled primitive p's canonical map (scene_prim_canon_map), from or
 * into *mm, where need_uv, for prim_surface's tangents; else NULL. */
static inline const double *NS(cscene_map)(const cscene *cs, const prim *p, int need_uv, cscene_map_memo *mm)
{
    if (!need_uv)
        return NULL;
    if (mm->prim != p->id + 1) {
        scene_prim_canon_map(&cs->sc->prims[p->id], cs->nm.scale, mm->a);
        mm->prim = p->id + 1;
    }
    return mm->a;
}

/* prim_surface of primitive pi (any, an instance's included) at pt, the
 * map from or into *mm: an instance's out of line, so that a scene
 * without them pays one test. */
void NS(cscene_surface_inst)(const cscene *cs, int pi, int face, vec3 pt, int need_uv, cscene_map_memo *mm,
                             geom_surface *out);
static inline void NS(cscene_surface)(const cscene *cs, int pi, int face, vec3 pt, int need_uv,
                                      cscene_map_memo *mm, geom_surface *out)
{
    if (cs->prim_root && cs->prim_root[pi] >= 0)
        NS(cscene_surface_inst)(cs, pi, face, pt, need_uv, mm, out);
    else
        NS(prim_surface)(&cs->prims[pi], face, pt, NS(cscene_map)(cs, &cs->prims[pi], need_uv, mm), out);
}

/* Compiles sc. 0 and *out (free with cscene_free), or a diag status:
 * DIAG_INPUT with the location of the offending definition, DIAG_IO when
 * memory runs out. */
int NS(cscene_compile)(const scene *sc, cscene **out, diag *err);
void NS(cscene_free)(cscene *cs);
/* Primary rays are set up CSCENE_BATCH at a time, each array indexed by
 * lane: stored so (structure of arrays), the compiler forms two lanes per
 * instruction, square roots and divisions included, and the long chains
 * of one ray's set-up overlap with the next one's. */
#define CSCENE_BATCH 32
enum { CSCENE_BAD = -2, CSCENE_CUT = -1, CSCENE_NONE = 0, CSCENE_RAY = 1 };
/* 1 where the batch rounds the rays to num for all its lanes at once (q16,
 * whose rounding of a value in range vectorises: fx16_lane_scale and
 * fx16_from_lane);
 * the other non-native modes round in cscene_primary_ray, ray by ray. */
#if defined(NUM_MODE_q16)
#define CSCENE_BATCH_NUM 1
#else
#define CSCENE_BATCH_NUM 0
#endif

typedef struct cscene_batch {
    double d[3][CSCENE_BATCH];     /* in: direction from the eye, any length */
    double u[3][CSCENE_BATCH];     /* d made unit (d / |d|, in double) */
    double t0[CSCENE_BATCH];       /* where the ray starts */
    double o[3][CSCENE_BATCH];     /* that point, eye + t0 u */
    double rcp[3][CSCENE_BATCH];   /* the box test's reciprocals of the
                                      direction (bbox_ray) */
#if CSCENE_BATCH_NUM
    num un[3][CSCENE_BATCH];       /* u and o rounded to num */
    num on[3][CSCENE_BATCH];
#endif
    signed char st[CSCENE_BATCH];  /* CSCENE_RAY: a ray; CSCENE_NONE:
                                      nothing remains to be hit; CSCENE_CUT:
                                      the start lies beyond the mode's range
                                      (the hit could not be represented);
                                      CSCENE_BAD: d is zero or not finite */
} cscene_batch;

/* Sets up the primary rays of lanes 0..n-1 of b (n <= CSCENE_BATCH) from
 * their directions d: each is started at the first parameter t >= after
 * where a surface can lie (the bounding sphere or a half-space plane, less
 * a margin), so that far eyes and narrow lenses keep the accuracy of
 * double. A ray that found nothing is set up again from its t0 onwards. */
void NS(cscene_primary_batch)(const cscene *cs, cscene_batch *b, int n, double after);
/* The ray of lane k of b, whose status is CSCENE_RAY. */
void NS(cscene_primary_ray)(const cscene *cs, const cscene_batch *b, int k, prim_ray *r);
/* Maps a deck point to the normalised world (double). */
void NS(cscene_to_world)(const cscene *cs, const double *deck, double *world);
#endif
