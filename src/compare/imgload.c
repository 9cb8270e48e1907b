/* imgload — PNG, PNM, JPEG or TIFF by content (see imgload.h). */
#include "image/image_png.h"
#include "compare/imgload.h"
#include "image/image_jpeg.h"
#include "image/image_tiff.h"
#include "image/pnm.h"
#include "util/sniff.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <string.h>

static int imgload_too_large(const char *name, unsigned long w, unsigned long h, size_t max_pixels, diag *err)
{
    return diag_at(err, DIAG_INPUT, name, 0, 0, "%lux%lu pixels is over the %zu this command reads; scale it down",
                   w, h, max_pixels);
}

int imgload_memory(const char *name, const void *data, size_t len, size_t max_pixels, image *out, diag *err)
{
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (len == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "empty file (not a PNG, PNM, JPEG or TIFF image)");
    if (len >= 8 && !memcmp(data, png_sig, 8)) {
        image_limits lim;
        lim.max_side = IMAGE_MAX_SIDE;
        lim.max_pixels = max_pixels;
        return image_read_png_memory_limit(name, data, len, 3, &lim, out, err);
    }
    if (pnm_sniff(data, len)) {
        pnm_info info;
        if (pnm_read_header(name, data, len, &info, err))
            return err->status;
        if ((size_t)info.width * (size_t)info.height > max_pixels)
            return imgload_too_large(name, (unsigned long)info.width, (unsigned long)info.height, max_pixels,
                                     err);
        return pnm_read_memory(name, data, len, 3, out, err);
    }
    switch (sniff_data(data, len)) {
    case SNIFF_JPEG:
        return image_read_jpeg_memory(name, data, len, 3, max_pixels, out, err);
    case SNIFF_TIFF:
        return image_read_tiff_memory(name, data, len, 3, max_pixels, out, err);
    default:
        break;
    }
    if (sniff_refuse_data(data, len, name, 0, "a picture (PNG, PNM, JPEG or TIFF)", err))
        return err->status;
    return diag_at(err, DIAG_INPUT, name, 0, 0, "not a PNG, PNM, JPEG or TIFF image");
}

int imgload_read(const char *path, size_t max_pixels, image *out, diag *err)
{
    char *data;
    size_t len;
    int rc;
    /* a missing file, a directory, FIFO or device is bad input (exit 1) */
    if (infile_read_all(path, IMGLOAD_MAX_BYTES, &data, &len, err))
        return err->status;
    rc = imgload_memory(path, data, len, max_pixels, out, err);
    mem_free(data);
    return rc;
}
