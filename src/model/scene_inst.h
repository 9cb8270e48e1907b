/* scene_inst — objects that are copies of an earlier object moved by one
 * rigid motion (instances): the same tree of operators over primitives of
 * the same kinds and dimensions, each placed as its counterpart is and
 * then turned by one rotation and moved by one translation, and clear of
 * every other object. A ray carried back by that motion meets the earlier
 * object's compiled primitives where it would meet the copy's, so the
 * scene compiler compiles and shares only the first of each set (cscene;
 * docs/numerics.md, "Instances"). Mode-independent, deck units. */
#ifndef MODEL_SCENE_INST_H
#define MODEL_SCENE_INST_H
#include "model/scene.h"

/* A turned copy's motion and box. */
typedef struct scene_inst_turn {
    double rot[9];       /* row-major rotation: a point p of the master
                            stands at rot p + shift in the copy */
    double lo[3], hi[3]; /* the copy's box (as the CSG compiler bounds it) */
} scene_inst_turn;

typedef struct scene_inst {
    int master;          /* the root index of the object copied, or -1:
                            not an instance */
    int first, count;    /* the copy's primitives, first .. first + count - 1,
                            used by this object alone */
    int dprim;           /* first minus the master's first: the copy's
                            primitive i stands where the master's i - dprim
                            does */
    double shift[3];     /* a point p of the master stands at p + shift in
                            the copy, or turned, at turn->rot p + shift */
    const scene_inst_turn *turn;   /* NULL: translated (the primitives are
                            twins, prim_twin, of the master's); else in
                            the block of the entries */
} scene_inst;

/* Finds the instances among sc's objects (its roots), one entry per root
 * into *out (mem_free it). Object i is an instance of an earlier object m
 * (itself none) when:
 *  - their trees are alike, operator for operator; i's primitives are
 *    first .. first + n - 1, bounded, and in no other object; those at
 *    the same place in the two trees have the same kind and dimensions,
 *    and m's lie at i's index less dprim;
 *  - one rotation R (orthonormal within SCENE_INST_ORTHO, determinant
 *    positive) and one translation c carry each of m's primitives onto
 *    i's counterpart to within tol: on every row of world_from_object,
 *    the difference of the translation plus those of the linear part,
 *    each times the solid's reach along that axis (its canonical box), at
 *    most tol, so no point of the solid moves farther than tol on any
 *    axis. Where their first primitives are twins (prim_twin), R is the
 *    identity exactly and every pair must be twins;
 *  - i's box (of its primitives' scene_prim_grow_tight_box, as the CSG
 *    compiler combines them) keeps farther than gap from every other
 *    object's (of their bounded primitives);
 *  - where i's box comes within gap of the plane of a half-space, no
 *    planar face of i is near parallel to that plane (sine of the angle
 *    below 1/16) while its primitive's box comes within gap of it.
 * The number of instances (0: *out NULL, none found or none sought), or -1
 * when memory runs out. *out is one block (mem_free it once). */
#define SCENE_INST_ORTHO (1.0 / 1073741824.0)
int scene_inst_find(const scene *sc, double tol, double gap, scene_inst **out);
#endif
