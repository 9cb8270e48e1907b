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
int scene_prim_canon_box(const scene_prim *sp, double c[3], double lo[3]);

/* The linear part of primitive sp's canonical map into a world of scale
 * `scale` (world_from_object's, each column k times c[k] of
 * scene_prim_canon_box, 1 for a half-space): a[3 i + j] = scale m[i][j]
 * c[j], formed in that order (scene_canon_map), so that every reader gets
 * the same bits. The compiled primitive keeps only its inverse: this is
 * formed again where the map itself is read (the compile, a hit's
 * tangents). */
void scene_prim_canon_map(const scene_prim *sp, double scale, double a[9]);

/* The same from the placement m (world_from_object) and the scale c. */
static inline void scene_canon_map(const double *m, double scale, const double c[3], double a[9])
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[3 * i + j] = scale * m[4 * i + j] * c[j];
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
