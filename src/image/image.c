/* image — 8-bit rasters: allocation and release (PNG I/O is image_png.c). */
#include "image/image.h"
#include "util/mem.h"

int image_alloc(image *img, int width, int height, int channels, const char *what, diag *err)
{
    size_t n;
    if (width < 1 || height < 1 || width > IMAGE_MAX_SIDE || height > IMAGE_MAX_SIDE ||
        (size_t)width * (size_t)height > IMAGE_MAX_PIXELS || (channels != 1 && channels != 3))
        return diag_at(err, DIAG_INPUT, what, 0, 0, "image size %dx%d is outside 1..%d per side",
                       width, height, IMAGE_MAX_SIDE);
    n = (size_t)width * (size_t)height * (size_t)channels;
    img->px = mem_calloc(n, 1);
    if (!img->px)
        return diag_at(err, DIAG_IO, what, 0, 0, "out of memory for a %dx%d image", width, height);
    img->width = width;
    img->height = height;
    img->channels = channels;
    return 0;
}

void image_free(image *img)
{
    mem_free(img->px);
    img->px = NULL;
    img->width = img->height = 0;
}
