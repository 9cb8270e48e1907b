/* fuzz_scene — libFuzzer target for the scene parser: any bytes, read as a
 * deck of lines, must give a scene or one diagnostic, never a crash, leak or
 * unbounded allocation. Images the deck names come from a synthetic loader
 * (a small raster drawn from the name; "x"-prefixed names fail), so the
 * TEXTURE and PIXELS IMAGE paths run too. Seeds: the decks in scenes/ and
 * attribute-mapping decks. */
#include <stddef.h>
#include <stdint.h>
#include "image/image_png.h"
#include "scene/scene_parse.h"
#include "model/scene_map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int fuzz_image(void *ctx, const char *name, int channels, image *out, diag *err)
{
    unsigned h = 2166136261u;
    size_t i, n;
    int r;
    (void)ctx;
    if (name[0] == 'x')
        return diag_at(err, DIAG_INPUT, name, 0, 0, "cannot open");
    for (i = 0; name[i]; i++)
        h = (h ^ (unsigned char)name[i]) * 16777619u;
    if (channels == IMAGE_INDEXED)
        channels = 1;
    r = image_alloc(out, 1 + (int)(h % 5), 1 + (int)(h / 5 % 4), channels, name, err);
    if (r)
        return r;
    n = (size_t)out->width * (size_t)out->height * (size_t)channels;
    for (i = 0; i < n; i++)   /* grey 0..2; colour channels 0 or 255 */
        out->px[i] = (uint8_t)(channels == 1 ? (h >> i % 16) % 3 : ((h >> i % 24) & 1) * 255);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const scene_loader ld = { fuzz_image, NULL, NULL };
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    diag_init(&err);
    recsrc_from_memory(&src, &m, "fuzz.scene", (const char *)data, size);
    if (scene_parse_with(&src, &ld, &s, &err) == 0) {
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
        for (i = 0; i < s->nprims; i++) {
            int f;
            if (s->prims[i].attr < 0 || (size_t)s->prims[i].attr >= s->nattrs)
                __builtin_trap();
            for (f = 0; f < SCENE_MAX_FACES; f++)
                if (s->prims[i].shape->face_map[f] < -1 || s->prims[i].shape->face_map[f] >= (int)s->nmaps)
                    __builtin_trap();
        }
        for (i = 0; i < s->nattrs; i++)
            if (s->attrs[i].texture < -1 || s->attrs[i].texture >= (int)s->ntextures ||
                s->attrs[i].bump < -1 || s->attrs[i].bump >= (int)s->nbumps)
                __builtin_trap();
        /* every definition the scene keeps passes the check again */
        for (i = 0; i < s->nmaps; i++)
            if (pds_def_check(&s->maps[i]->def, "fuzz.scene", &err) != 0)
                __builtin_trap();
        scene_free(s);
    } else if (s != NULL || err.status == 0) {
        __builtin_trap();
    }
    return 0;
}
