/* fuzz_png — the PNG reader (libpng's simplified API behind
 * image_read_png_memory_limit) on arbitrary bytes, in the three ways maprt
 * reads PNGs: RGB (textures, compare, dl encode), grey and palette indices
 * (PIXELS IMAGE), each under a 1 Mpixel limit checked from the header. It
 * must return a status, never crash, leak, or decode past the limit. */
#include <stddef.h>
#include <stdint.h>
#include "image/image_png.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const int channels[3] = {3, 1, IMAGE_INDEXED};
    image_limits lim = {1024, (size_t)1 << 20};
    int i;
    for (i = 0; i < 3; i++) {
        image img;
        diag err;
        diag_init(&err);
        if (image_read_png_memory_limit("fuzz.png", data, size, channels[i], &lim, &img, &err) == 0) {
            if ((size_t)img.width * (size_t)img.height > lim.max_pixels || img.width > lim.max_side)
                __builtin_trap();
            image_free(&img);
        } else if (err.status == 0) {
            __builtin_trap();
        }
    }
    return 0;
}
