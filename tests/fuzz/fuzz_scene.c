/* fuzz_scene — libFuzzer target for the scene parser: any bytes, read as a
 * deck of lines, must give a scene or one diagnostic, never a crash, leak or
 * unbounded allocation. Seeds: the decks in scenes/. */
#include <stddef.h>
#include <stdint.h>
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    diag_init(&err);
    recsrc_from_memory(&src, &m, "fuzz.scene", (const char *)data, size);
    if (scene_parse(&src, &s, &err) == 0) {
        size_t i;
        /* every node index the tree holds must be in range */
        for (i = 0; i < s->nnodes; i++) {
            const scene_node *n = &s->nodes[i];
            if (n->op == CSG_LEAF ? (n->prim < 0 || (size_t)n->prim >= s->nprims)
                                  : (n->left < 0 || (size_t)n->left >= i ||
                                     n->right < 0 || (size_t)n->right >= i))
                __builtin_trap();
        }
        for (i = 0; i < s->nroots; i++)
            if (s->roots[i] < 0 || (size_t)s->roots[i] >= s->nnodes)
                __builtin_trap();
        for (i = 0; i < s->nprims; i++)
            if (s->prims[i].attr < 0 || (size_t)s->prims[i].attr >= s->nattrs)
                __builtin_trap();
        scene_free(s);
    } else if (s != NULL || err.status == 0) {
        __builtin_trap();
    }
    return 0;
}
