/* scene_box — the box in deck units that holds a bounded scene primitive:
 * its canonical bounding box under world_from_object, each coordinate the
 * least and greatest of the eight corners as formed in double; the
 * canonical box it is the image of, and the canonical map itself. Read by
 * the normalisation (cscene), the search for copies (scene_inst) and the
 * compile (geom/prim.h, geom/csg.h), and by a hit's tangents. */
#ifndef MODEL_SCENE_BOX_H
#define MODEL_SCENE_BOX_H
#include "model/scene.h"

/* The canonical bounding box of primitive sp, scaled per axis: from
 * lo[k] c[k] to c[k] on axis k (the sphere's [-r, r]^3, the cylinder's
 * and the cone's [-R, R]^2 x [0, h], R the cone's larger radius, the
 * block's [0, a] x [0, b] x [0, c]). 0, or -1 for a half-space or an
 * unknown kind (c and lo then untouched). The one table of these boxes:
 * the primitive compile, the deck-space box below and its test read it. */
static inline int scene_prim_canon_box(const scene_prim *sp, double c[3], double lo[3])
{
    const double *d = sp->shape->dim;
    switch (sp->shape->kind) {
    case PRIM_SPHERE:   c[0] = c[1] = c[2] = d[0]; lo[0] = lo[1] = lo[2] = -1; return 0;
    case PRIM_CYLINDER: c[0] = c[1] = d[0]; c[2] = d[1]; lo[0] = lo[1] = -1; lo[2] = 0; return 0;
    case PRIM_CONE:     c[0] = c[1] = d[0] > d[1] ? d[0] : d[1]; c[2] = d[2];
                        lo[0] = lo[1] = -1; lo[2] = 0; return 0;
    case PRIM_BLOCK:    c[0] = d[0]; c[1] = d[1]; c[2] = d[2]; lo[0] = lo[1] = lo[2] = 0; return 0;
    default:            return -1;
    }
}

/* The linear part of a canonical map from the placement m
 * (world_from_object) and the canonical scale c into a world of scale
 * `scale`: a[3 i + j] = scale m[i][j] c[j], formed in that order, so that
 * every reader gets the same bits. */
static inline void scene_canon_map(const double *m, double scale, const double c[3], double a[9])
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[3 * i + j] = scale * m[4 * i + j] * c[j];
}

/* Primitive sp's canonical map (c of scene_prim_canon_box, 1 for a
 * half-space). The compiled primitive keeps only its inverse: this is
 * formed again where the map itself is read (the compile, a hit's
 * tangents). Inline, as the canonical box: the compile forms it some
 * three times a primitive. */
static inline void scene_prim_canon_map(const scene_prim *sp, double scale, double a[9])
{
    double c[3] = {1, 1, 1}, lo[3];
    (void)scene_prim_canon_box(sp, c, lo);
    scene_canon_map(sp->world_from_object, scale, c, a);
}

/* Grows lo/hi to hold primitive sp (bounded kinds only; a half-space
 * leaves them as they are). */
void scene_prim_grow_box(const scene_prim *sp, double *lo, double *hi);

/* The same, tighter for a turned curved solid: a sphere's box is its
 * centre plus and minus its radius times each row's length of the linear
 * part, a cylinder's and a cone's that of their two cap discs (a
 * turned sphere's box of corners reaches up to sqrt(3) times as far);
 * enlarged by 2^-40 of itself against rounding. For the search for
 * copies (scene_inst), which needs boxes apart. */
void scene_prim_grow_tight_box(const scene_prim *sp, double *lo, double *hi);
#endif
