/* fuzz_pnm — the picture readers compare uses on arbitrary bytes: the PNM
 * reader, the JPEG and TIFF readers (libjpeg-turbo, libtiff), imgload's
 * dispatch between them and PNG, and the file-kind sniffer. Each must return
 * a status, never crash, leak or allocate more than the input can describe
 * (seeds: PNM, JPEG and TIFF files). */
#include <stddef.h>
#include <stdint.h>
#include "compare/imgload.h"
#include "image/image_jpeg.h"
#include "image/image_tiff.h"
#include "image/pnm.h"
#include "util/sniff.h"

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
    if (image_read_jpeg_memory("fuzz", data, size, channels, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    diag_init(&err);
    if (image_read_tiff_memory("fuzz", data, size, channels, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    diag_init(&err);
    (void)sniff_refuse_data(data, size, "fuzz", 1u << SNIFF_TEXT, "a deck", &err);
    diag_init(&err);
    if (imgload_memory("fuzz", data, size, (size_t)1 << 20, &img, &err) == 0)
        image_free(&img);
    return 0;
}
