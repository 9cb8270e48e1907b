/* scene — the scene model, in double precision, exactly as the scene deck
 * describes it. The deck parser (src/scene) builds it, analysis and the
 * per-mode compilers read it; it is never modified after parsing.
 *
 * Geometry conventions (documented in docs/primitives.md):
 *   - right-handed world, any orientation; the camera's UP picks "up".
 *   - each primitive lives in a canonical object frame, z is its axis:
 *       SPHERE    radius dim[0], centre at the origin
 *       CYLINDER  radius dim[0], z from 0 to dim[1] (height), capped
 *       BLOCK     [0,dim[0]] x [0,dim[1]] x [0,dim[2]]
 *       CONE      radius dim[0] at z=0, dim[1] at z=dim[2] (height), capped
 *       HALFSPACE z <= 0 (the solid below the xy-plane)
 *   - world_from_object is the top three rows of a 4x4 affine matrix (the
 *     fourth is 0 0 0 1), row-major, acting on column vectors (p_world =
 *     M * p_object), composed from the deck's transforms.
 * All arrays are owned by the scene and released by scene_free. */
#ifndef MODEL_SCENE_H
#define MODEL_SCENE_H
#include <stddef.h>
#include <string.h>
#include "util/diag.h"
#include "image/image.h"

#define SCENE_NAME_MAX 16     /* significant characters of a name */
#define SCENE_MAX_FACES 6
#define SCENE_MAX_LIGHTS 64   /* lights in a scene (parser and renderer) */
#define SCENE_MAX_SIDE 16384  /* image width or height a deck (SIZE) or a command
                                 line may ask for; the renderer checks it too */

typedef enum prim_kind {
    PRIM_SPHERE, PRIM_CYLINDER, PRIM_BLOCK, PRIM_CONE, PRIM_HALFSPACE,
    PRIM_KIND_COUNT
} prim_kind;

/* Where a definition came from, for diagnostics at render time. */
typedef struct scene_loc {
    long line, col;           /* record number and column in scene->source */
} scene_loc;

/* A plain attribute: one colour and one optical model for a whole surface. */
/* Shading models of an optical attribute (MODEL in ATTR; src/trace/shade.h). */
typedef enum shade_model {
    SHADE_PHONG, SHADE_LAMBERT, SHADE_BLINN, SHADE_MIRROR, SHADE_TRANSPARENT, SHADE_MODEL_COUNT
} shade_model;

typedef struct scene_attr {
    char name[SCENE_NAME_MAX + 1];
    shade_model model;        /* default SHADE_PHONG */
    double color[3];          /* linear 0..1 */
    double ambient;           /* ka, fraction of the scene ambient reflected */
    double diffuse;           /* kd */
    double specular;          /* ks (Phong highlight) */
    double exponent;          /* Phong exponent */
    double mirror;            /* kr, mirror reflectance 0..1 */
    double transmit;          /* kt, transmittance 0..1 */
    double ior;               /* index of refraction (used when kt > 0) */
    int texture;              /* index into textures: colour image over the
                                 face replacing color, -1 = none */
    int bump;                 /* index into bumps, -1 = none */
    scene_loc loc;
} scene_attr;

/* A colour image laid over a face's (u,v) square (TEXTURE statement):
 * u runs along the image's rows left to right, v from its bottom row up;
 * repeat[] copies of it across u and v. */
typedef struct scene_texture {
    char name[SCENE_NAME_MAX + 1];
    image img;                /* RGB, 8 bits per channel */
    double repeat[2];
    int local;                /* 1: in the region's own frame (pds_region.h) */
    scene_loc loc;
} scene_texture;

/* Bump patterns: a height field h(u,v) in [-1,1] scaled by the amplitude
 * (src/attr/attr_bump.c defines each). */
typedef enum bump_pattern {
    BUMP_WAVES,               /* sin 2pi(fu u + fv v): parallel ridges */
    BUMP_BUMPS,               /* sin 2pi fu u * sin 2pi fv v: egg crate */
    BUMP_DIMPLES,             /* a spherical dimple in each of fu x fv cells */
    BUMP_NOISE,               /* gradient noise with fu x fv lattice cells */
    BUMP_GROOVES,             /* grooves of `width` along the region boundaries of
                                 the face's PDS (pds_region.h), depth = amplitude */
    BUMP_IMAGE,               /* grey level of an image: 2 grey - 1, tiled fu x fv */
    BUMP_PATTERN_COUNT
} bump_pattern;

/* A bump attribute (BUMP statement): the surface is displaced along its
 * normal by amplitude * h(u,v) (deck length units) for shading only. */
typedef struct scene_bump {
    char name[SCENE_NAME_MAX + 1];
    bump_pattern pattern;
    double amplitude;         /* deck units, non-zero */
    double freq[2];           /* cycles or cells across u and v */
    unsigned seed;            /* BUMP_NOISE: lattice hash seed */
    double width;             /* BUMP_GROOVES: groove width, face (u,v) units */
    image img;                /* BUMP_IMAGE: the height image (RGB, grey used) */
    int local;                /* 1: pattern in the region's own frame */
    scene_loc loc;
} scene_bump;

/* What a primitive statement defines, the same for every placement of it:
 * kept once per placed definition (scene.shapes), not once per placement
 * (10,000 objects of five primitives: 4 MB less, docs/performance.md,
 * run AU). */
typedef struct scene_shape {
    prim_kind kind;
    double dim[3];                    /* see the table above */
    int face_map[SCENE_MAX_FACES];    /* per face: the planar division
                                         structure bound by FACE (index into
                                         maps), -1 = the plain attr only */
    char name[SCENE_NAME_MAX + 1];    /* the deck's name for it */
    scene_loc loc;
} scene_shape;

/* 1 when two shapes have the same kind and dimensions, bit for bit (one
 * shape, shared by placements of one definition, at once). */
static inline int scene_shape_alike(const scene_shape *a, const scene_shape *b)
{
    return a == b || (a->kind == b->kind && !memcmp(a->dim, b->dim, sizeof a->dim));
}

typedef struct scene_prim {
    const scene_shape *shape;         /* its definition, in scene.shapes */
    int attr;                         /* index into attrs (plain attribute) */
    double world_from_object[12];     /* row-major 3x4 affine: 10,000
                                         objects' primitives keep 1.6 MB
                                         less than the full 4x4 */
} scene_prim;

typedef enum csg_op { CSG_LEAF, CSG_UNION, CSG_INTER, CSG_DIFF } csg_op;

/* CSG tree node: a leaf names a primitive; an operator node names its two
 * operands, left first (operand order matters for DIFF). */
typedef struct scene_node {
    csg_op op;
    int left, right;          /* node indices, operators only */
    int prim;                 /* prim index, leaves only */
} scene_node;

typedef struct scene_light {
    double pos[3];
    double color[3];
    double intensity;
    scene_loc loc;
} scene_light;

typedef struct scene_view {
    double eye[3], look[3], up[3];
    double fov_deg;           /* vertical field of view, degrees */
    int width, height;        /* default image size (overridden by --size) */
} scene_view;

typedef struct scene {
    char *source;             /* file name or fileid the deck came from */
    scene_view view;
    double ambient[3];        /* ambient light colour */
    double background[3];
    int max_depth;            /* reflection/refraction recursion limit */

    scene_attr *attrs;   size_t nattrs;
    scene_prim *prims;   size_t nprims;
    scene_shape **shapes; size_t nshapes; /* each allocated on its own, so
                                             that prims may point at it */
    scene_node *nodes;   size_t nnodes;
    int *roots;          size_t nroots;   /* rendered objects, each a solid of its own */
    scene_light *lights; size_t nlights;
    /* Attribute mapping: planar division structures (scene_map.h; each one
     * allocated on its own so that nested PDS references stay valid),
     * texture images and bump patterns. */
    struct scene_map **maps;       size_t nmaps;
    scene_texture *textures;       size_t ntextures;
    scene_bump *bumps;             size_t nbumps;
} scene;

/* Frees s and every array it owns; NULL is allowed. */
void scene_free(scene *s);
#endif
