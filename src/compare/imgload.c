/* imgload — PNG, PNM, JPEG or TIFF by content (see imgload.h). */
#include "image/image_png.h"
#include "compare/imgload.h"
#include "image/image_jpeg.h"
#include "image/image_tiff.h"
#include "image/pnm.h"
#include "util/sniff.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <errno.h>
#include <string.h>
#include <sys/stat.h>

static int imgload_too_large(const char *name, unsigned long w, unsigned long h, size_t max_pixels, diag *err)
{
    return diag_at(err, DIAG_INPUT, name, 0, 0, "%lux%lu pixels is over the %zu this command reads; scale it down",
                   w, h, max_pixels);
}

int imgload_memory(const char *name, const void *data, size_t len, size_t max_pixels, image *out, diag *err)
{
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const unsigned char *p = data;
    if (len == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "empty file (not a PNG, PNM, JPEG or TIFF image)");
    if (len >= 8 && !memcmp(data, png_sig, 8)) {
        /* the size is in the IHDR chunk, which must come first; anything
         * else is left for libpng to report */
        if (len >= 24 && !memcmp(p + 12, "IHDR", 4)) {
            unsigned long w = (unsigned long)p[16] << 24 | (unsigned long)p[17] << 16 | (unsigned long)p[18] << 8 | p[19];
            unsigned long h = (unsigned long)p[20] << 24 | (unsigned long)p[21] << 16 | (unsigned long)p[22] << 8 | p[23];
            if (w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE || (size_t)w * h > max_pixels)
                return imgload_too_large(name, w, h, max_pixels, err);
        }
        return image_read_png_memory(name, data, len, 3, out, err);
    }
    if (pnm_sniff(data, len)) {
        pnm_info info;
        if (pnm_read_header(name, data, len, &info, err))
            return err->status;
        if ((size_t)info.width * (size_t)info.height > max_pixels)
            return imgload_too_large(name, (unsigned long)info.width, (unsigned long)info.height, max_pixels, err);
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
    struct stat st;
    /* a missing or wrong input is bad input (exit 1), not an I/O failure */
    if (stat(path, &st) != 0)
        return diag_at(err, errno == ENOENT || errno == ENOTDIR ? DIAG_INPUT : DIAG_IO, path, 0, 0,
                       "cannot open: %s", strerror(errno));
    if (S_ISDIR(st.st_mode))
        return diag_at(err, DIAG_INPUT, path, 0, 0, "is a directory, not a picture");
    if (infile_read_all(path, IMGLOAD_MAX_BYTES, &data, &len, err))
        return err->status;
    rc = imgload_memory(path, data, len, max_pixels, out, err);
    mem_free(data);
    return rc;
}
