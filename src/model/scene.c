/* scene — releasing a parsed scene (the model is in scene.h; scene_parse.c
 * builds it). */
#include "model/scene.h"
#include "model/scene_map.h"
#include "util/mem.h"

/* Frees s and every array it owns; NULL is allowed. */
void scene_free(scene *s)
{
    size_t i;
    if (!s)
        return;
    for (i = 0; i < s->nmaps; i++) {
        pds_def_free(&s->maps[i]->def);
        mem_free(s->maps[i]);
    }
    for (i = 0; i < s->ntextures; i++)
        image_free(&s->textures[i].img);
    for (i = 0; i < s->nbumps; i++)
        image_free(&s->bumps[i].img);
    mem_free(s->source);
    mem_free(s->attrs);
    mem_free(s->prims);
    for (i = 0; i < s->nshapes; i++)
        mem_free(s->shapes[i]);
    mem_free(s->shapes);
    mem_free(s->nodes);
    mem_free(s->roots);
    mem_free(s->lights);
    mem_free(s->maps);
    mem_free(s->textures);
    mem_free(s->bumps);
    mem_free(s);
}
