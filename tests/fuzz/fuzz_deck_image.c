/* fuzz_deck_image — images named by a deck: the input bytes are the PNG file
 * that a fixed deck reads as a TEXTURE, as a colour PIXELS IMAGE with KEY
 * lines and as an indexed one with an INDEX line, through the same limits
 * the command line applies (SCENE_IMAGE_MAX_PIXELS, from the header). Any
 * bytes must give a scene or one located diagnostic. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "image/image_png.h"
#include "scene/scene_parse.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct fuzz_file {
    const uint8_t *data;
    size_t size;
} fuzz_file;

static int fuzz_image(void *ctx, const char *name, int channels, image *out, diag *err)
{
    const fuzz_file *f = ctx;
    /* a smaller limit than the command line's keeps each run fast; the
     * limit is checked the same way */
    image_limits lim = {4096, (size_t)1 << 18};
    return image_read_png_memory_limit(name, f->data, f->size, channels, &lim, out, err);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char deck[] =
        "ATTR A COLOR 1 0 0\nATTR B COLOR 0 1 0\n"
        "TEXTURE T IMAGE t.png REPEAT 2 1\nATTR C COLOR 1 1 1 TEXTURE T\n"
        "PDS P PIXELS IMAGE p.png\nKEY #000000 A\nKEY #FFFFFF B\nEND\n"
        "PDS Q PIXELS IMAGE q.png\nINDEX NONE A B\nEND\n"
        "PDS R QUADTREE IMAGE r.png\nINDEX A B\nEND\n"
        "SPHERE S 1 ATTR C\nFACE S 0 P\nOBJECT S\n";
    static const char *const decks[4] = {"TEXTURE T IMAGE t.png\n", "PDS P PIXELS IMAGE p.png\nINDEX A\nEND\n",
                                         "PDS P PIXELS IMAGE p.png\nKEY #FF0000 NONE\nEND\n", deck};
    fuzz_file f;
    scene_loader ld;
    int k;
    f.data = data;
    f.size = size;
    ld.image = fuzz_image;
    ld.ctx = &f;
    for (k = 0; k < 4; k++) {
        recsrc src;
        recsrc_mem m;
        scene *s = NULL;
        diag err;
        diag_init(&err);
        recsrc_from_memory(&src, &m, "fuzz.scene", decks[k], strlen(decks[k]));
        if (scene_parse_with(&src, &ld, &s, &err) == 0)
            scene_free(s);
        else if (s != NULL || err.status == 0)
            __builtin_trap();
    }
    return 0;
}
