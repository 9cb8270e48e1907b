/* scene_box — the box in deck units that holds a bounded scene primitive:
 * its canonical bounding box under world_from_object, each coordinate the
 * least and greatest of the eight corners as formed in double. Read by the
 * normalisation (cscene) and by the search for translated copies
 * (scene_inst). */
#ifndef MODEL_SCENE_BOX_H
#define MODEL_SCENE_BOX_H
#include "model/scene.h"

/* Grows lo/hi to hold primitive sp (bounded kinds only; a half-space
 * leaves them as they are). */
void scene_prim_grow_box(const scene_prim *sp, double *lo, double *hi);
#endif
