/* fuzz_pnm — the PNM reader (and the PNG/PNM dispatch in imgload) on
 * arbitrary bytes: it must return a status, never crash, leak or allocate
 * more than the input can describe. */
#include <stddef.h>
#include <stdint.h>
#include "compare/imgload.h"
#include "image/pnm.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image img;
    diag err;
    int channels = size > 0 && (data[size - 1] & 1) ? 1 : 3;
    diag_init(&err);
    if (pnm_read_memory("fuzz", data, size, channels, &img, &err) == 0)
        image_free(&img);
    diag_init(&err);
    if (imgload_memory("fuzz", data, size, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    return 0;
}
