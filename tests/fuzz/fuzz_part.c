/* fuzz_part — the region-file decoder of `maprt merge` and of MPI bands
 * (render_part) on arbitrary bytes: a status, never a crash or a read past
 * the input; a part that decodes is placed into a framebuffer of its size
 * (with the identity map when the part carries one) only when that is small
 * (the decoder itself allocates nothing), then placed again, which must be
 * refused as an overlap. */
#include <stddef.h>
#include <stdint.h>
#include "render/render_part.h"
#include "util/mem.h"
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    render_part_info info;
    render_fb fb;
    uint8_t *covered;
    diag err;
    size_t n;
    diag_init(&err);
    if (render_part_decode("fuzz", data, size, &info, &err))
        return 0;
    n = (size_t)info.width * (size_t)info.height;
    if (n > ((size_t)1 << 20))
        return 0;
    diag_init(&err);
    memset(&fb, 0, sizeof fb);
    if (image_alloc(&fb.img, info.width, info.height, 3, "fuzz", &err))
        return 0;
    fb.pid = mem_calloc(n, sizeof *fb.pid);
    covered = mem_calloc(n, 1);
    if (fb.pid && covered && (!info.ids || !idmap_alloc(&fb.ids, info.width, info.height, &err))
        && !render_part_place("fuzz", data, &info, &fb, covered, &err)
        && !render_part_place("fuzz", data, &info, &fb, covered, &err))
        abort();   /* every pixel placed twice must be refused */
    mem_free(covered);
    render_fb_free(&fb);
    return 0;
}
