/* scene_names — hashed name table (see scene_names.h). */
#include "scene/scene_names.h"
#include <string.h>
#include "util/mem.h"

void scene_names_init(scene_names *t)
{
    t->slot = NULL;
    t->cap = t->count = 0;
}

void scene_names_free(scene_names *t)
{
    mem_free(t->slot);
    scene_names_init(t);
}

/* FNV-1a over the name and its space. */
static size_t scene_names_hash(int space, const char *name)
{
    unsigned long h = 2166136261UL ^ (unsigned long)space;
    for (; *name; name++)
        h = ((h ^ (unsigned char)*name) * 16777619UL) & 0xffffffffUL;
    return (size_t)h;
}

static scene_names_entry *scene_names_probe(scene_names_entry *slot, size_t cap,
                                            int space, const char *name)
{
    size_t i = scene_names_hash(space, name) & (cap - 1);
    while (slot[i].space >= 0 &&
           (slot[i].space != space || strcmp(slot[i].name, name) != 0))
        i = (i + 1) & (cap - 1);
    return &slot[i];
}

int scene_names_find(const scene_names *t, int space, const char *name)
{
    const scene_names_entry *e;
    if (!t->cap)
        return -1;
    e = scene_names_probe(t->slot, t->cap, space, name);
    return e->space >= 0 ? e->value : -1;
}

int scene_names_add(scene_names *t, int space, const char *name, int value)
{
    scene_names_entry *e;
    if (2 * (t->count + 1) > t->cap) {   /* keep the load at most 1/2 */
        size_t ncap = t->cap ? t->cap * 2 : 64, i;
        scene_names_entry *ns;
        if (ncap > ((size_t)-1) / sizeof *ns)
            return -1;
        ns = mem_alloc(ncap * sizeof *ns);
        if (!ns)
            return -1;
        for (i = 0; i < ncap; i++)
            ns[i].space = -1;
        for (i = 0; i < t->cap; i++)
            if (t->slot[i].space >= 0)
                *scene_names_probe(ns, ncap, t->slot[i].space, t->slot[i].name) = t->slot[i];
        mem_free(t->slot);
        t->slot = ns;
        t->cap = ncap;
    }
    e = scene_names_probe(t->slot, t->cap, space, name);
    strncpy(e->name, name, SCENE_NAME_MAX);
    e->name[SCENE_NAME_MAX] = '\0';
    e->space = space;
    e->value = value;
    t->count++;
    return 0;
}
