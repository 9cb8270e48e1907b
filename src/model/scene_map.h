/* scene_map — a named planar division structure of the scene (PDS
 * statement): its definition in double precision (pds_def.h), which the
 * per-mode scene compilers turn into lookup structures, and where the deck
 * defined it. FACE binds one to a face of a primitive through
 * scene_shape.face_map. */
#ifndef SCENE_MAP_H
#define SCENE_MAP_H
#include "model/pds_def.h"
#include "model/scene.h"

typedef struct scene_map {
    char name[SCENE_NAME_MAX + 1];
    pds_def def;
    scene_loc loc;
} scene_map;
#endif
