/* fuzz_render — libFuzzer target for scene compilation and rendering: any
 * deck the parser accepts must compile and render (8x8, q16 and f64) or be
 * refused with a diagnostic, never crash, hang or leak. Seeds: the decks in
 * scenes/ and bench/. */
#include <stddef.h>
#include <stdint.h>
#include "scene/scene_parse.h"
#include "render/render.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const render_ops *const modes[2] = {&q16_render_ops, &f64_render_ops};
    recsrc src;
    recsrc_mem m;
    scene *s = NULL;
    diag err;
    int i;
    diag_init(&err);
    recsrc_from_memory(&src, &m, "fuzz.scene", (const char *)data, size);
    if (scene_parse(&src, &s, &err) != 0)
        return 0;
    for (i = 0; i < 2; i++) {
        render_opts o = {.width = 8, .height = 8, .threads = 1, .aa = 1};
        render_fb fb;
        render_stats st;
        diag_init(&err);
        if (render_scene(s, modes[i], &o, &fb, &st, &err) == 0)
            render_fb_free(&fb);
        else if (err.status == 0)
            __builtin_trap();
    }
    scene_free(s);
    return 0;
}
