/* scene_xform — 4x4 affine transforms of the scene model (row-major, acting
 * on column vectors: p' = M p) and the transform items of the scene language:
 *   TRANSLATE x y z | ROTATE X|Y|Z deg | ROTATE AXIS ax ay az deg |
 *   SCALE s | SCALE sx sy sz | MATRIX m11 m12 m13 m14 m21 ... m34
 * applied in the order written. Used by scene_parse for definitions and uses,
 * and by the expansion that composes world_from_object. */
#ifndef SCENE_XFORM_H
#define SCENE_XFORM_H
#include "scene/scene_cur.h"

/* Largest entry magnitude of a composed transform; beyond it (or for a
 * linear part whose determinant is not clearly non-zero) a transform is
 * rejected as degenerate. */
#define SCENE_XFORM_MAX_ABS 1e12

void scene_xform_identity(double m[16]);
/* out = a * b for affine a and b with finite entries (out may alias a or
 * b); bit for bit the full 4x4 product. out never holds -0, so for any m
 * made by scene_xform_identity or scene_xform_mul, m * I is m itself. */
void scene_xform_mul(double out[16], const double a[16], const double b[16]);
/* 1 if the top three rows of m are exactly the identity's (+0, not -0). */
int scene_xform_is_identity(const double m[16]);
/* 1 if m is finite, within SCENE_XFORM_MAX_ABS, no row of its 3x3 linear
 * part is shorter than 1/SCENE_XFORM_MAX_ABS and that part is invertible
 * (|det| above 1e-12 times the product of its row lengths). */
int scene_xform_ok(const double m[16]);

/* Parses one transform item at the cursor and composes it after m
 * (m = T * m); m is the identity or what earlier calls left in it.
 * Returns 0, -1 when the next item starts no transform (TRANSLATE, ROTATE,
 * SCALE, MATRIX; nothing is consumed), or DIAG_INPUT for errors at the
 * offending item: missing or bad numbers, "ROTATE: expected X, Y, Z or
 * AXIS, found W", "ROTATE: axis must not be zero", "SCALE factor must not
 * be zero", "MATRIX is singular", "transforms give a degenerate or
 * out-of-range matrix". */
int scene_xform_parse(scene_cur *c, double m[16]);
#endif
