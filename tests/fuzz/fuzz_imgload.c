/* fuzz_imgload — the JPEG and TIFF readers (libjpeg-turbo, libtiff, behind
 * imgload's dispatch) and the file-kind sniffer on arbitrary bytes: a
 * status, never a crash, leak, or allocation beyond the pixel limit. */
#include <stddef.h>
#include <stdint.h>
#include "image/image_jpeg.h"
#include "image/image_tiff.h"
#include "util/sniff.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image img;
    diag err;
    int channels = size > 0 && (data[size - 1] & 1) ? 1 : 3;
    diag_init(&err);
    if (image_read_jpeg_memory("fuzz", data, size, channels, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    diag_init(&err);
    if (image_read_tiff_memory("fuzz", data, size, channels, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    diag_init(&err);
    (void)sniff_refuse_data(data, size, "fuzz", 1u << SNIFF_TEXT, "a deck", &err);
    return 0;
}
