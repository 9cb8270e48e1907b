/* prim_face — the faces of each primitive kind: their numbers (the index of
 * scene_shape.face_map and of a hit's face), their deck names (FACE
 * statement) and their count. The (u,v) mapping of each face is documented
 * in docs/primitives.md. */
#ifndef MODEL_PRIM_FACE_H
#define MODEL_PRIM_FACE_H
#include "model/scene.h"

enum { PRIM_FACE_NONE = -1 };
enum { PRIM_FACE_SPHERE_SURFACE = 0 };
enum { PRIM_FACE_CYL_SIDE = 0, PRIM_FACE_CYL_TOP = 1, PRIM_FACE_CYL_BOTTOM = 2 };
enum { PRIM_FACE_CONE_SIDE = 0, PRIM_FACE_CONE_TOP = 1, PRIM_FACE_CONE_BOTTOM = 2 };
enum { PRIM_FACE_BLOCK_XMIN = 0, PRIM_FACE_BLOCK_XMAX, PRIM_FACE_BLOCK_YMIN, PRIM_FACE_BLOCK_YMAX,
       PRIM_FACE_BLOCK_ZMIN, PRIM_FACE_BLOCK_ZMAX };
enum { PRIM_FACE_HALFSPACE_PLANE = 0 };

/* Number of faces of a primitive kind, and a face's name ("SIDE", "XMIN",
 * ...; NULL when out of range). */
static inline int prim_face_count(int kind)
{
    static const int n[PRIM_KIND_COUNT] = {1, 3, 6, 3, 1};
    return kind >= 0 && kind < PRIM_KIND_COUNT ? n[kind] : 0;
}
static inline const char *prim_face_name(int kind, int face)
{
    static const char *const names[PRIM_KIND_COUNT][6] = {
        {"SURFACE"}, {"SIDE", "TOP", "BOTTOM"},
        {"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"},
        {"SIDE", "TOP", "BOTTOM"}, {"PLANE"}};
    if (face < 0 || face >= prim_face_count(kind))
        return NULL;
    return names[kind][face];
}
#endif
