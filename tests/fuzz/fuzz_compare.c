/* fuzz_compare — compare's inputs: the bytes are two pictures (PNG or PNM,
 * the first two bytes give the reference's length) and an options byte
 * (register, grey, levels, descreen, crop); both are read under a small
 * pixel limit and measured. Any bytes must give figures or one diagnostic,
 * never a crash, leak or unbounded search. */
#include <stddef.h>
#include <stdint.h>
#include "compare/compare.h"
#include "compare/imgload.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image ref, test;
    compare_opts o;
    compare_result r;
    diag err;
    size_t n;
    unsigned flags;
    if (size < 3)
        return 0;
    flags = data[0];
    n = (size_t)data[1] << 8 | data[2];
    data += 3;
    size -= 3;
    if (n > size)
        n = size;
    diag_init(&err);
    if (imgload_memory("ref", data, n, 4096, &ref, &err))
        return 0;
    diag_init(&err);
    if (imgload_memory("test", data + n, size - n, 4096, &test, &err)) {
        image_free(&ref);
        return 0;
    }
    compare_opts_init(&o);
    /* a cap for sanitizer speed: 2^20 pairs take about a quarter of a
     * second here; the kept corpus reaches 698 of the 700 edges it reaches
     * under 2^22, at a sixth of the time */
    o.align.max_cost = (double)(1 << 20);
    o.do_register = flags & 1;
    o.grey = (flags >> 1) & 1;
    o.levels = (flags >> 2) & 1;
    o.descreen = (flags >> 3) & 1 ? 1.5 : 0;
    if (flags & 16) {
        o.crop = 1;
        o.cx = (int)(flags >> 5);
        o.cy = 1;
        o.cw = 8;
        o.ch = 8;
    }
    if (flags & 128) {   /* a wide registration search (its cost cap applies) */
        o.align.scale_min = 0.01;
        o.align.scale_max = 100;
        o.align.max_angle = 45;
    }
    diag_init(&err);
    if (compare_images("ref", &ref, "test", &test, &o, &r, &err) != 0 && err.status == 0)
        __builtin_trap();
    image_free(&ref);
    image_free(&test);
    return 0;
}
