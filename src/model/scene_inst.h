/* scene_inst — objects that are translated copies of an earlier object
 * (instances): the same tree of operators over primitives that are twins
 * (prim_twin) one for one, all moved by one translation, and clear of
 * every other object. A ray moved by the opposite translation meets the
 * earlier object's compiled primitives where it would meet the copy's, so
 * the scene compiler compiles and shares only the first of each set
 * (cscene; docs/numerics.md, "Instances"). Mode-independent, deck units. */
#ifndef MODEL_SCENE_INST_H
#define MODEL_SCENE_INST_H
#include "model/scene.h"

typedef struct scene_inst {
    int master;          /* the root index of the object copied, or -1:
                            not an instance */
    int first, count;    /* the copy's primitives, first .. first + count - 1,
                            used by this object alone */
    int dprim;           /* first minus the master's first: the copy's
                            primitive i stands where the master's i - dprim
                            does */
    double shift[3];     /* the copy's placement minus the master's */
} scene_inst;

/* Finds the instances among sc's objects (its roots), one entry per root
 * into *out (mem_free it). Object i is an instance of an earlier object m
 * (itself none) when:
 *  - their trees are alike, operator for operator; i's primitives are
 *    first .. first + n - 1, bounded, and in no other object; those at
 *    the same place in the two trees are twins and m's lie i's at the same
 *    index less dprim; and their translations (world_from_object's last
 *    column) differ by one vector within tol on every axis;
 *  - i's box (of its primitives' scene_prim_grow_box) keeps farther than
 *    gap from every other object's (of their bounded primitives) and from
 *    the plane of every half-space.
 * The number of instances (0: *out NULL, none found or none sought), or -1
 * when memory runs out. */
int scene_inst_find(const scene *sc, double tol, double gap, scene_inst **out);
#endif
