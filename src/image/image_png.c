/* image_png — PNG input and output of 8-bit rasters through libpng's
 * simplified API (no setjmp); outputs are committed through outfile. */
#include "image/image_png.h"
#include "image/image_png_write.h"
#include <omp.h>
#include "util/mem.h"
#include "util/outfile.h"
#include <png.h>
#include <string.h>

/* Encodes a prepared png_image to memory: *buf (mem_free it) and *size. */
static int image_png_encode(const char *name, png_image *pi, const void *px, int row_stride,
                            const void *colormap, void **buf, size_t *size, diag *err)
{
    png_alloc_size_t n = 0;
    void *b;
    if (!png_image_write_to_memory(pi, NULL, &n, 0, px, row_stride, colormap))
        return diag_at(err, DIAG_IO, name, 0, 0, "PNG encoding failed: %s", pi->message);
    b = mem_alloc(n);
    if (!b)
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
    if (!png_image_write_to_memory(pi, b, &n, 0, px, row_stride, colormap)) {
        mem_free(b);
        return diag_at(err, DIAG_IO, name, 0, 0, "PNG encoding failed: %s", pi->message);
    }
    *buf = b;
    *size = n;
    return 0;
}

/* Encodes a prepared png_image, then commits it through outfile. */
static int image_png_commit(const char *path, png_image *pi, const void *px, int row_stride,
                            const void *colormap, diag *err)
{
    void *buf = NULL;
    size_t size = 0;
    int rc = image_png_encode(path, pi, px, row_stride, colormap, &buf, &size, err);
    if (rc)
        return rc;
    rc = outfile_write_all(path, buf, size, err);
    mem_free(buf);
    return rc;
}

int image_write_png_mt(const char *path, const image *img, int threads, diag *err)
{
    unsigned char *buf;
    size_t size;
    int rc;
    if (img->channels != 1 && img->channels != 3)
        return diag_at(err, DIAG_USAGE, path, 0, 0, "internal: bad channel count");
    if (image_png_write_mem(img, threads, IMAGE_PNG_WRITE_LEVEL, path, &buf, &size, err))
        return err->status;
    rc = outfile_write_all(path, buf, size, err);
    mem_free(buf);
    return rc;
}

/* To memory through the same threaded encoder (image_png_write.c), for
 * writers that add chunks of their own (image_out: tEXt provenance). */
int image_encode_png(const image *img, void **buf, size_t *size, diag *err)
{
    unsigned char *b;
    if (img->channels != 1 && img->channels != 3)
        return diag_at(err, DIAG_USAGE, "PNG", 0, 0, "internal: bad channel count");
    if (image_png_write_mem(img, omp_get_max_threads(), IMAGE_PNG_WRITE_LEVEL, "PNG", &b, size, err))
        return err->status;
    *buf = b;
    return 0;
}

int image_write_png(const char *path, const image *img, diag *err)
{
    return image_write_png_mt(path, img, omp_get_max_threads(), err);
}

int image_write_png_palette(const char *path, int width, int height, const uint8_t *index,
                            const uint8_t *palette, int ncolors, diag *err)
{
    png_image pi;
    if (ncolors < 1 || ncolors > 256)
        return diag_at(err, DIAG_INPUT, path, 0, 0, "palette of %d colours (1..256 allowed)", ncolors);
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = (png_uint_32)width;
    pi.height = (png_uint_32)height;
    pi.format = PNG_FORMAT_RGB_COLORMAP;
    pi.colormap_entries = (png_uint_32)ncolors;
    return image_png_commit(path, &pi, index, width, palette, err);
}

int image_read_png_memory(const char *name, const void *data, size_t len, int channels,
                          image *out, diag *err)
{
    return image_read_png_memory_limit(name, data, len, channels, NULL, out, err);
}

int image_read_png_memory_limit(const char *name, const void *data, size_t len, int channels,
                                const image_limits *lim, image *out, diag *err)
{
    png_image pi;
    image img;
    void *cmap = NULL;
    int indexed = channels == IMAGE_INDEXED;
    int max_side = lim && lim->max_side > 0 && lim->max_side < IMAGE_MAX_SIDE ? lim->max_side : IMAGE_MAX_SIDE;
    size_t max_px = lim && lim->max_pixels > 0 && lim->max_pixels < IMAGE_MAX_PIXELS ? lim->max_pixels
                                                                                    : IMAGE_MAX_PIXELS;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (channels != 1 && channels != 3 && !indexed)
        return diag_at(err, DIAG_USAGE, name, 0, 0, "internal: bad channel count");
    if (!png_image_begin_read_from_memory(&pi, data, len))
        return diag_at(err, DIAG_INPUT, name, 0, 0, "not a readable PNG: %s", pi.message);
    /* The header alone has been read: refuse a size bomb before any pixel
     * is inflated. */
    if (pi.width > (png_uint_32)max_side || pi.height > (png_uint_32)max_side ||
        (size_t)pi.width * pi.height > max_px) {
        diag_at(err, DIAG_INPUT, name, 0, 0,
                "image size %lux%lu is over the limit of %d per side and %zu pixels",
                (unsigned long)pi.width, (unsigned long)pi.height, max_side, max_px);
        png_image_free(&pi);
        return DIAG_INPUT;
    }
    if (indexed) {
        /* A palette PNG read colour-mapped keeps the file's palette and so
         * its indices; any other PNG gives its grey values. */
        channels = 1;
        if (pi.format & PNG_FORMAT_FLAG_COLORMAP) {
            pi.format = PNG_FORMAT_RGB_COLORMAP;
            cmap = mem_alloc(PNG_IMAGE_COLORMAP_SIZE(pi));
            if (!cmap) {
                png_image_free(&pi);
                return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
            }
        }
    }
    if (image_alloc(&img, (int)pi.width, (int)pi.height, channels, name, err)) {
        png_image_free(&pi);
        mem_free(cmap);
        return err->status;
    }
    pi.format = cmap ? PNG_FORMAT_RGB_COLORMAP : channels == 1 ? PNG_FORMAT_GRAY : PNG_FORMAT_RGB;
    if (!png_image_finish_read(&pi, NULL, img.px, img.width * channels, cmap)) {
        image_free(&img);
        mem_free(cmap);
        return diag_at(err, DIAG_INPUT, name, 0, 0, "corrupt PNG: %s", pi.message);
    }
    mem_free(cmap);
    *out = img;
    return 0;
}

int image_read_png(const char *path, int channels, image *out, diag *err)
{
    return image_read_png_limit(path, channels, NULL, out, err);
}

int image_read_png_limit(const char *path, int channels, const image_limits *lim, image *out, diag *err)
{
    char *data;
    size_t len;
    int rc;
    if (infile_read_all(path, IMAGE_PNG_MAX_BYTES, &data, &len, err))
        return err->status;
    rc = image_read_png_memory_limit(path, data, len, channels, lim, out, err);
    mem_free(data);
    return rc;
}
