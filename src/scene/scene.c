/* scene — releasing a parsed scene (the model is in scene.h; scene_parse.c
 * builds it). */
#include "scene/scene.h"
#include "util/mem.h"

/* Frees s and every array it owns; NULL is allowed. */
void scene_free(scene *s)
{
    if (!s)
        return;
    mem_free(s->source);
    mem_free(s->attrs);
    mem_free(s->prims);
    mem_free(s->nodes);
    mem_free(s->roots);
    mem_free(s->lights);
    mem_free(s->maps);
    mem_free(s);
}
