/* scene_names — the parser's symbol table: names (upper case, at most
 * SCENE_NAME_MAX characters) in separate name spaces (attributes, solids,
 * PDS, ...) mapped to indices, with constant expected lookup time so that
 * decks with many definitions parse in linear time. Used by scene_parse. */
#ifndef SCENE_NAMES_H
#define SCENE_NAMES_H
#include <stddef.h>
#include "model/scene.h"

/* The deck's name spaces; a PDS block's own table holds its CPG nodes and
 * its KEY colours. */
typedef enum scene_names_space {
    SCENE_NAMES_ATTR, SCENE_NAMES_SOLID, SCENE_NAMES_PDS, SCENE_NAMES_TEXTURE,
    SCENE_NAMES_BUMP, SCENE_NAMES_NODE, SCENE_NAMES_COLOUR
} scene_names_space;

typedef struct scene_names_entry {
    char name[SCENE_NAME_MAX + 1];
    int space;                /* scene_names_space; -1 = empty slot */
    int value;
} scene_names_entry;

typedef struct scene_names {
    scene_names_entry *slot;  /* open addressing, linear probing */
    size_t cap, count;
} scene_names;

void scene_names_init(scene_names *t);
void scene_names_free(scene_names *t);
/* The value stored for name in space, or -1. */
int scene_names_find(const scene_names *t, int space, const char *name);
/* Adds a name that is not yet present. Returns 0, or -1 when memory runs
 * out (the table is then unchanged). */
int scene_names_add(scene_names *t, int space, const char *name, int value);
#endif
