/* prim — the five primitives compiled for one numeric mode, and their
 * ray intersection (one entry/exit span per ray: all five are convex) and
 * surface evaluation (normal, (u,v), dP/du, dP/dv per face).
 *
 * Every primitive is stored as a canonical unit solid (sphere radius 1;
 * cylinder radius 1, z in [0,1]; block [0,1]^3; cone radius a at z=0 and
 * a+k at z=1 with max radius 1; half-space z <= 0) placed by an affine map
 * into the normalised world. Planar faces are world-space planes rounded to
 * `num` once, so coincident faces of different primitives give bit-identical
 * ray parameters. Curved faces are solved in the canonical frame after the
 * ray origin has been moved next to the primitive (docs/numerics.md).
 * Modal: compiled per numeric mode. */
#ifndef GEOM_PRIM_H
#define GEOM_PRIM_H
#include "geom/geom.h"
#include "geom/span.h"
#include "geom/vec.h"
#include "geom/bbox.h"

/* A ray in the normalised world. d is a unit vector. A ray spawned from a
 * surface names the primitive it left (excl_prim, -1 for none) and whether it
 * went into that primitive (excl_enter): that primitive's surface at the
 * origin is then never reported again (no epsilon offsets). */
typedef struct ray {
    vec3 o, d;
    bbox_ray b;        /* o and d in binary64 for the culling tests (prim_ray_set) */
    int excl_prim;
    int excl_enter;
} prim_ray;

/* Sets every field of r from o and d and their binary64 copies od, dd
 * (vec3_to_d of o and d, which a caller may have at hand). */
static inline void prim_ray_set_d(prim_ray *r, vec3 o, vec3 d, const double *od, const double *dd,
                                  int excl_prim, int excl_enter)
{
    r->o = o;
    r->d = d;
    bbox_ray_init(&r->b, od, dd);
    r->excl_prim = excl_prim;
    r->excl_enter = excl_enter;
}

/* Sets every field of r, the culling tests' binary64 copy included. */
static inline void prim_ray_set(prim_ray *r, vec3 o, vec3 d, int excl_prim, int excl_enter)
{
    double od[3], dd[3];
    vec3_to_d(o, od);
    vec3_to_d(d, dd);
    prim_ray_set_d(r, o, d, od, dd, excl_prim, excl_enter);
}

/* A planar face: plane k of a primitive is face prim_plane_face(kind, k).
 * In binary64 the layout is that of double[4], so the planes in double
 * (prim.pl_d) are the same storage (PRIM_PL_SHARED) and the clip derives
 * the face; in the other modes the plane holds it (prim.c, prim_clip_face). */
#if defined(NUM_MODE_f64)
#define PRIM_PL_SHARED 1
#else
#define PRIM_PL_SHARED 0
#endif

typedef struct prim_plane {
    vec3 n;            /* outward unit normal, world */
    num d;             /* plane n.p = d; inside n.p <= d */
#if !PRIM_PL_SHARED
    int face;          /* prim_plane_face of its index, read by the clip */
#endif
} prim_plane;

#if PRIM_PL_SHARED
typedef char prim_plane_is_4_doubles[sizeof(prim_plane) == 4 * sizeof(double) ? 1 : -1];
#endif

/* The linear part of a primitive's placement in binary64: the inverse
 * ainv_d of its canonical map (world_from_canonical), which every hit
 * reads. The map itself is formed again from the scene primitive where it
 * is read (scene_prim_canon_map: the compile, a hit's tangents, each
 * thread keeping the last it formed, trace/cscene.h): kept, it made
 * 10,000 distinct parts' compile 3.6 MB larger (docs/performance.md,
 * run AV). Twins (a kind, dimensions and linear part alike bit for bit:
 * model/prim_twin.h) share one. */
typedef struct prim_lin {
    double ainv_d[9];
} prim_lin;

/* A primitive's placement in binary64: its linear part and its origin
 * org_d, read by surface evaluation and the compile, kept apart from what
 * every intersection reads. */
typedef struct prim_frame {
    const prim_lin *lin;
    double org_d[3];
} prim_frame;

typedef struct prim {
    int kind, id, attr;
    int bounded;       /* 0 for the half-space */
    vec3 bc;           /* bounding sphere centre and radius (world) */
    num br;
    prim_plane *pl;    /* nplanes planes, in storage the caller provides
                          (prim_compile): a sphere needs none, a block six */
    vec3 org;          /* canonical origin in the world */
    mat3 minv_s;       /* canonical_from_world (linear part) times smin */
    num smin;          /* 1 / frobenius norm of canonical_from_world */
    num inv_smin;      /* its reciprocal (the frobenius norm) */
    num cone_a, cone_k;/* cone radius at canonical z: a + k z */
    int nplanes;
    unsigned fast;     /* exact shortcuts: bits 3k..3k+2 how pl[k]'s dot
                          products are formed (k < 6), bits 24..31 minv_s's
                          nonzero column per row (prim_cols) */
    prim_frame *fr;    /* the placement in double, for surface evaluation
                          (storage the caller provides, as for pl) */
    double (*pl_d)[4]; /* planes in double (n, d), in pl's order (storage
                          as pl, in binary64 pl itself); n is also the
                          face's shading normal */
} prim;

/* Two planes, or two placements of one canonical solid, that agree within
 * this much in the normalised world (unit normals, offsets, transforms) are
 * taken to be the same: far above double rounding (about 1e-14 here), far
 * below any resolution a mode could use to tell them apart. */
#define PRIM_SAME_TOL (1.0 / 1073741824.0)

/* The number of planar faces of a primitive of kind `kind` (0 for an
 * unknown kind): the room prim_compile needs in pl and pl_d. */
static inline int prim_nplanes(int kind)
{
    return kind == PRIM_BLOCK ? 6 : kind == PRIM_CYLINDER || kind == PRIM_CONE ? 2
           : kind == PRIM_HALFSPACE ? 1 : 0;
}

/* The index in pl of the plane of face `face` of a primitive of kind
 * `kind`, or -1 for a curved or unknown face: the planes are stored in
 * face order, after the curved side of a cylinder or cone. */
static inline int prim_face_plane(int kind, int face)
{
    static const signed char k[PRIM_KIND_COUNT][6] = {
        {-1, -1, -1, -1, -1, -1}, {-1, 0, 1, -1, -1, -1}, {0, 1, 2, 3, 4, 5},
        {-1, 0, 1, -1, -1, -1}, {0, -1, -1, -1, -1, -1}};
    return kind >= 0 && kind < PRIM_KIND_COUNT && face >= 0 && face < 6 ? k[kind][face] : -1;
}

/* The face of plane k of a primitive of kind `kind` (prim_face_plane's
 * inverse): k, after the curved side of a cylinder or a cone, the two odd
 * kinds (checked below), so one AND and one add in the plane clip. */
typedef char prim_odd_kinds_curved[PRIM_CYLINDER % 2 && PRIM_CONE % 2 && !(PRIM_SPHERE % 2)
                                   && !(PRIM_BLOCK % 2) && !(PRIM_HALFSPACE % 2) ? 1 : -1];
static inline int prim_plane_face(int kind, int k)
{
    return k + (kind & 1);
}

/* Compiles scene primitive sp (index id) under the normalisation nm, its
 * planes into pl and pl_d (prim_nplanes(sp->kind) entries each; in
 * binary64 (PRIM_PL_SHARED) pl_d must be pl itself) and its
 * placement into fr, all kept by out; *radius receives its bounding
 * radius. twin: NULL, or a primitive compiled before (and not yet shared)
 * from a scene primitive of sp's kind, dimensions and linear part, bit for
 * bit (model/prim_twin.h), with *radius the radius that compile gave:
 * what depends on those alone is then taken from it, with the values the
 * compile would form, and the twin's linear part is shared. Without a
 * twin the linear part is formed in lin, which out then keeps. 0 on
 * success; DIAG_INPUT (located at sp->loc in file) for bad dimensions,
 * non-finite or singular transforms, or a primitive outside the range. */
int NS(prim_compile)(const scene_prim *sp, int id, const geom_norm *nm, prim_plane *pl,
                     double (*pl_d)[4], prim_frame *fr, prim_lin *lin, const prim *twin, double *radius,
                     prim *out, const char *file, diag *err);

/* Gives coincident geometry of the compiled primitives one representation
 * (docs/numerics.md, "Coincident surfaces"): every plane equal within
 * PRIM_SAME_TOL to an earlier one, in either orientation, becomes that
 * plane or its exact negation, and a sphere, cylinder or cone that is the
 * same point set as an earlier primitive of its kind (the same solid placed
 * through an equivalent transform) shares that primitive's curved-face data.
 * Intersected with one ray they then give bit-identical parameters. 0, or
 * DIAG_IO when memory runs out. */
int NS(prim_share)(prim *prims, const scene_prim *sps, double scale, size_t n, diag *err);

/* The bounding box of p in the world (lo, hi), a its canonical map
 * (scene_prim_canon_map); zeros for the half-space. */
void NS(prim_box)(const prim *p, const double a[9], double lo[3], double hi[3]);

/* Intersects r with p; the bounding test rejects p when it lies wholly
 * outside the parameters [tmin, tmax] (the span itself is not clipped).
 * Returns 1 and the span (entry and exit; ends at +-GEOM_TBIG are unbounded
 * and carry PRIM_FACE_NONE) or 0 when the ray misses, *out then undefined
 * (the span is built in place: see prim_side). */
int NS(prim_intersect)(const prim *p, const prim_ray *r, num tmin, num tmax, span *out);
/* prim_intersect_tc past its exclusion test. */
int NS(prim_intersect_spans)(const prim *p, const prim_ray *r, num tc, span *out);
/* The same after the caller has tested p's bounding sphere (bc, br) itself
 * and found the ray's closest parameter tc (0 for the unbounded half-space):
 * a CSG leaf's bound is then tested once. Inline, so that the frequent
 * early return (every primitive a spawned ray leaves) costs no call. */
static inline int NS(prim_intersect_tc)(const prim *p, const prim_ray *r, num tc, span *out)
{
    /* The ray starts on this convex primitive's surface: leaving it, the
     * primitive is behind (nothing to solve); entering it, the span starts
     * at the origin (prim_intersect_spans). */
    if (r->excl_prim == p->id && !r->excl_enter)
        return 0;
    return NS(prim_intersect_spans)(p, r, tc, out);
}

/* Surface data of face `face` of p at world point pt (a hit point). With
 * map NULL only p and n are written ((u,v), dP/du and dP/dv are left as
 * they were): no trigonometry, and a planar face only copies its stored
 * normal. Else map is p's canonical map (scene_prim_canon_map), which
 * carries the tangents into the world. */
void NS(prim_surface)(const prim *p, int face, vec3 pt, const double *map, geom_surface *out);
/* The stored outward unit normal of face `face` of p when the face is
 * planar (the normal prim_surface gives anywhere on it), else NULL. */
const double *NS(prim_face_normal)(const prim *p, int face);
#endif
