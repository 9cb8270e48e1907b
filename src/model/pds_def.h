/* pds_def — planar division structure (PDS) definitions, in double precision.
 *
 * A PDS splits a face's unit square [0,1] x [0,1] of (u,v) into regions, each
 * carrying a region attribute id (an index into the scene's attribute table,
 * resolved by the parser). The parser fills one pds_def per PDS statement with
 * the builder functions below; pds_def_check validates it with exact error
 * texts; the per-mode compilers in src/pds (q16_pds_compile etc.) turn it into
 * flat lookup structures. Data flow:
 *     deck -> parser -> pds_def (this file) -> pds_def_check -> <mode>_pds_compile
 *          -> <mode>_pds_locate(u, v) -> region attribute id | PDS_NONE
 * Semantics, conventions and limits are specified in docs/pds.md.
 * All arrays are owned by the pds_def and released by pds_def_free. */
#ifndef PDS_DEF_H
#define PDS_DEF_H
#include <stddef.h>
#include <stdint.h>
#include "model/scene.h"
#include "util/diag.h"

#define PDS_NONE     (-1)     /* "no region": the face's base attribute */
#define PDS_INHERIT  (-2)     /* CPG operator: take the winning operand's id */
#define PDS_QT_SPLIT (-3)     /* explicit quadtree code: an internal node */

/* Limits (docs/pds.md explains each). */
#define PDS_MAX_ATTR        65535    /* largest region attribute id */
#define PDS_COORD_MAX       64.0     /* |coordinate| after transforms */
#define PDS_MAX_NODES       262144   /* CPG nodes */
#define PDS_MAX_DEPTH       64       /* CPG operator nesting */
#define PDS_MAX_VERTICES    65536    /* one polygon or one flattened curve */
#define PDS_MAX_SIDE        32768    /* pixel array side */
#define PDS_MAX_CELLS       (1L << 24) /* pixel array cells */
#define PDS_MAX_SEEDS       (1L << 20) /* mosaic seeds */
#define PDS_QT_MAX_DEPTH    15       /* explicit quadtree levels */
#define PDS_MIN_FEATURE     (1.0 / 8192) /* smallest ellipse radius, tile size */
#define PDS_CURVE_TOLERANCE 1.0e-4   /* default B-spline flattening tolerance */
#define PDS_MAX_NESTING     4        /* PDS inside CPG inside ... */

typedef enum pds_kind {
    PDS_CPG, PDS_PIXELS, PDS_TILING, PDS_MOSAIC, PDS_QUADTREE, PDS_CURVES,
    PDS_KIND_COUNT
} pds_kind;

/* ---- CPG: constructive planar geometry -------------------------------- */
typedef enum pds_cpg_op {
    PDS_CPG_RECT,      /* p = u0 v0 u1 v1 (u0 < u1, v0 < v1) */
    PDS_CPG_ELLIPSE,   /* p = centre u, centre v, radius u, radius v */
    PDS_CPG_POLYGON,   /* vertices pts[2*first .. 2*(first+count)) as u,v */
    PDS_CPG_NESTED,    /* another PDS (sub) over the node's unit square */
    PDS_CPG_UNION,     /* operands kids[first .. first+count), in order */
    PDS_CPG_INTER,
    PDS_CPG_DIFF
} pds_cpg_op;

typedef struct pds_cpg_node {
    pds_cpg_op op;
    double p[4];
    size_t first, count;
    /* Placement in the parent's (u,v) frame, row-major 2x3 affine:
     * parent = [xf0 xf1; xf3 xf4] * local + [xf2; xf5]. Identity by default;
     * the transform helpers below compose onto it. */
    double xf[6];
    int32_t attr;      /* leaf: id >= 0 or PDS_NONE; operator: PDS_INHERIT or id;
                          NESTED: PDS_INHERIT (ids come from sub) */
    const struct pds_def *sub; /* NESTED: not owned; must outlive this def */
    scene_loc loc;
} pds_cpg_node;

typedef struct pds_cpg {
    pds_cpg_node *nodes; size_t nnodes, cap_nodes;
    double *pts;         size_t npts, cap_pts;    /* npts (u,v) pairs */
    size_t *kids;        size_t nkids, cap_kids;
    size_t root;         /* set by the parser; default: the last node added */
} pds_cpg;

/* ---- pixel array ------------------------------------------------------- */
typedef struct pds_pixels {
    int width, height;
    int32_t *cells;      /* ncells ids, row-major, top row (v = 1) first */
    size_t ncells, cap_cells;
} pds_pixels;

/* ---- tiling from a tessellation function ------------------------------- */
typedef enum pds_tile_shape { PDS_TILE_SQUARE, PDS_TILE_BRICK, PDS_TILE_HEX, PDS_TILE_TRIANGLE } pds_tile_shape;
typedef enum pds_tile_rule {
    PDS_RULE_CYCLE,    /* attrs[(i*step[0] + j*step[1] + k*step[2]) mod n] */
    PDS_RULE_HASH      /* attrs[hash(i, j, k, seed) mod n] */
} pds_tile_rule;

typedef struct pds_tiling {
    pds_tile_shape shape;
    double size[2];      /* tile width, height (HEX, TRIANGLE: size[0] only) */
    double offset;       /* BRICK: shift of odd rows, fraction of the width */
    double mortar;       /* grout band width (0 = none), centred on edges */
    int32_t mortar_attr;
    pds_tile_rule rule;
    long step[3];
    uint32_t seed;
    int32_t *attrs; size_t nattrs, cap_attrs;
} pds_tiling;

/* ---- mosaic: Voronoi cells of seed points ------------------------------ */
typedef struct pds_mosaic {
    double *seeds;  size_t nseeds, cap_seeds;   /* (u,v) pairs */
    int32_t *attrs; size_t cap_attrs;           /* one per seed */
    double mortar;
    int32_t mortar_attr;
} pds_mosaic;

/* ---- region quadtree --------------------------------------------------- */
typedef struct pds_quadtree {
    int from_pixels;     /* 1: built from `pixels`; 0: explicit `code` */
    pds_pixels pixels;
    /* Explicit form, preorder: an id (>= 0 or PDS_NONE) is a leaf; PDS_QT_SPLIT
     * is an internal node followed by its children SW, SE, NW, NE. */
    int32_t *code; size_t ncode, cap_code;
} pds_quadtree;

/* ---- curve-bounded regions --------------------------------------------- */
typedef struct pds_curve {
    int bspline;         /* 1: uniform cubic closed B-spline control points;
                            0: closed polyline vertices */
    size_t first, count; /* points pts[2*first ..) */
    int32_t attr;
    scene_loc loc;
} pds_curve;

typedef struct pds_curves {
    pds_curve *curves; size_t ncurves, cap_curves;
    double *pts;       size_t npts, cap_pts;
    double tolerance;  /* B-spline flattening tolerance, (u,v) units */
    int strips;        /* 1: Ballard's strip trees (pds_strip.h) answer membership;
                          0: the box hierarchy of pds_ring.h */
    double strip_width;/* strips: width tolerance of the tree (0: to the leaves) */
} pds_curves;

typedef struct pds_def {
    pds_kind kind;
    scene_loc loc;       /* the PDS statement, for whole-PDS errors */
    pds_cpg cpg;
    pds_pixels pixels;
    pds_tiling tiling;
    pds_mosaic mosaic;
    pds_quadtree quad;
    pds_curves curves;
} pds_def;

/* Initialises an empty definition of the given kind with defaults (tiling:
 * square 0.25, no mortar, cycle rule step 1 1 0; curve tolerance
 * PDS_CURVE_TOLERANCE; mortar ids PDS_NONE). No allocation. */
void pds_def_init(pds_def *d, pds_kind kind, scene_loc loc);
void pds_def_free(pds_def *d);

/* Builders. Each returns the new node/curve index (>= 0), or -1 when memory
 * runs out (the definition is then unchanged and still freeable). */
long pds_cpg_rect(pds_def *d, double u0, double v0, double u1, double v1, int32_t attr, scene_loc loc);
long pds_cpg_ellipse(pds_def *d, double cu, double cv, double ru, double rv, int32_t attr, scene_loc loc);
long pds_cpg_polygon(pds_def *d, const double *uv, size_t nvert, int32_t attr, scene_loc loc);
long pds_cpg_op_node(pds_def *d, pds_cpg_op op, const size_t *operands, size_t n, int32_t attr, scene_loc loc);
/* A leaf holding another PDS: its region is the node's unit square
 * [0,1] x [0,1] (placed by the node's transforms, edges included) wherever
 * sub gives an id other than PDS_NONE; where sub gives PDS_NONE the leaf is
 * transparent (later union operands show through). sub is not copied. */
long pds_cpg_nested(pds_def *d, const pds_def *sub, scene_loc loc);
/* Placement: composes the transform after the node's current one. */
void pds_cpg_translate(pds_def *d, size_t node, double du, double dv);
void pds_cpg_rotate(pds_def *d, size_t node, double degrees);        /* counter-clockwise about (0,0) */
void pds_cpg_scale(pds_def *d, size_t node, double su, double sv);
void pds_cpg_shear(pds_def *d, size_t node, double shu, double shv); /* u += shu*v, then v += shv*u */
/* m = t * m for 2x3 affines (t applied after m). */
void pds_affine_after(double m[6], const double t[6]);

int pds_pixels_set(pds_pixels *px, int width, int height, const int32_t *cells, size_t ncells);
int pds_tiling_attrs(pds_def *d, const int32_t *attrs, size_t n);
long pds_mosaic_seed(pds_def *d, double u, double v, int32_t attr);
int pds_quadtree_code(pds_def *d, const int32_t *code, size_t n);
long pds_curve_add(pds_def *d, int bspline, const double *uv, size_t npts, int32_t attr, scene_loc loc);

/* Validates a definition. Returns 0, or DIAG_INPUT with the first error at
 * the offending element's location in `file` (texts listed in docs/pds.md),
 * or DIAG_IO if memory ran out during the check. */
int pds_def_check(const pds_def *d, const char *file, diag *err);

/* For the compilers (definitions already checked):
 * pds_cpg_placements fills m[i] = root_from_node placement and depth[i]
 * (-1 for nodes not under the root), for arrays of nnodes entries.
 * pds_curves_ring gives curve i as a closed polyline: *pts points into the
 * definition (*owned = 0) or is a new flattened B-spline (*owned = 1, caller
 * mem_frees); returns 0, -1 too many points, -2 out of memory. */
void pds_cpg_placements(const pds_def *d, double (*m)[6], int *depth);
int pds_curves_ring(const pds_curves *c, size_t i, double **pts, size_t *n, int *owned);

#endif
