/* image_tiff — TIFF input through libtiff (see image_tiff.h), which is
 * opened when the first TIFF is read (util/libload): a process that reads
 * none never maps it or the libraries it brings. */
#include "image/image_tiff.h"

#ifdef IMAGE_HAVE_TIFF
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <tiffio.h>
#include "util/libload.h"
#include "util/mem.h"

int image_tiff_available(void) { return 1; }

/* The libtiff entry points used here, with their prototypes from tiffio.h. */
typedef struct image_tiff_lib {
    TIFFOpenOptions *(*OpenOptionsAlloc)(void);
    void (*OpenOptionsFree)(TIFFOpenOptions *);
    void (*OpenOptionsSetErrorHandlerExtR)(TIFFOpenOptions *, TIFFErrorHandlerExtR, void *);
    void (*OpenOptionsSetWarningHandlerExtR)(TIFFOpenOptions *, TIFFErrorHandlerExtR, void *);
    void (*OpenOptionsSetMaxSingleMemAlloc)(TIFFOpenOptions *, tmsize_t);
    TIFF *(*ClientOpenExt)(const char *, const char *, thandle_t, TIFFReadWriteProc, TIFFReadWriteProc,
                           TIFFSeekProc, TIFFCloseProc, TIFFSizeProc, TIFFMapFileProc, TIFFUnmapFileProc,
                           TIFFOpenOptions *);
    int (*GetField)(TIFF *, uint32_t, ...);
    int (*ReadRGBAImageOriented)(TIFF *, uint32_t, uint32_t, uint32_t *, int, int);
    void (*Close)(TIFF *);
} image_tiff_lib;

/* Each read looks the entry points up again: after the first, dlopen only
 * counts a reference and nine lookups cost microseconds, and no state is
 * shared between threads. */
static int image_tiff_load(image_tiff_lib *t, const char *name, diag *err)
{
    static const char *const names[] = {IMAGE_TIFF_SONAME, NULL};
    static const char *const syms[] = {"TIFFOpenOptionsAlloc", "TIFFOpenOptionsFree",
                                       "TIFFOpenOptionsSetErrorHandlerExtR",
                                       "TIFFOpenOptionsSetWarningHandlerExtR",
                                       "TIFFOpenOptionsSetMaxSingleMemAlloc", "TIFFClientOpenExt",
                                       "TIFFGetField", "TIFFReadRGBAImageOriented", "TIFFClose"};
    libload_fn f[9];
    /* the table's types checked against tiffio.h (a conditional needs
     * compatible pointer types); sizeof does not evaluate
     * its operand, so nothing here links libtiff */
    (void)sizeof(1 ? t->OpenOptionsAlloc : TIFFOpenOptionsAlloc);
    (void)sizeof(1 ? t->OpenOptionsFree : TIFFOpenOptionsFree);
    (void)sizeof(1 ? t->OpenOptionsSetErrorHandlerExtR : TIFFOpenOptionsSetErrorHandlerExtR);
    (void)sizeof(1 ? t->OpenOptionsSetWarningHandlerExtR : TIFFOpenOptionsSetWarningHandlerExtR);
    (void)sizeof(1 ? t->OpenOptionsSetMaxSingleMemAlloc : TIFFOpenOptionsSetMaxSingleMemAlloc);
    (void)sizeof(1 ? t->ClientOpenExt : TIFFClientOpenExt);
    (void)sizeof(1 ? t->GetField : TIFFGetField);
    (void)sizeof(1 ? t->ReadRGBAImageOriented : TIFFReadRGBAImageOriented);
    (void)sizeof(1 ? t->Close : TIFFClose);
    if (libload(names, syms, f, 9, name, "reading a TIFF needs it: apt-get install -y libtiff6", err))
        return DIAG_IO;
    t->OpenOptionsAlloc = (TIFFOpenOptions * (*)(void)) f[0];
    t->OpenOptionsFree = (void (*)(TIFFOpenOptions *))f[1];
    t->OpenOptionsSetErrorHandlerExtR = (void (*)(TIFFOpenOptions *, TIFFErrorHandlerExtR, void *))f[2];
    t->OpenOptionsSetWarningHandlerExtR = (void (*)(TIFFOpenOptions *, TIFFErrorHandlerExtR, void *))f[3];
    t->OpenOptionsSetMaxSingleMemAlloc = (void (*)(TIFFOpenOptions *, tmsize_t))f[4];
    t->ClientOpenExt = (TIFF * (*)(const char *, const char *, thandle_t, TIFFReadWriteProc, TIFFReadWriteProc,
                                   TIFFSeekProc, TIFFCloseProc, TIFFSizeProc, TIFFMapFileProc,
                                   TIFFUnmapFileProc, TIFFOpenOptions *)) f[5];
    t->GetField = (int (*)(TIFF *, uint32_t, ...))f[6];
    t->ReadRGBAImageOriented = (int (*)(TIFF *, uint32_t, uint32_t, uint32_t *, int, int))f[7];
    t->Close = (void (*)(TIFF *))f[8];
    return 0;
}

/* A read-only TIFF stream over memory, and the first error libtiff reports. */
typedef struct image_tiff_mem {
    const unsigned char *p;
    toff_t len, pos;
    char msg[256];
} image_tiff_mem;

static tmsize_t image_tiff_read(thandle_t h, void *buf, tmsize_t n)
{
    image_tiff_mem *m = (image_tiff_mem *)h;
    toff_t left = m->pos < m->len ? m->len - m->pos : 0;
    if (n < 0)
        return 0;
    if ((toff_t)n > left)
        n = (tmsize_t)left;
    memcpy(buf, m->p + m->pos, (size_t)n);
    m->pos += (toff_t)n;
    return n;
}

static tmsize_t image_tiff_write(thandle_t h, void *buf, tmsize_t n) { (void)h; (void)buf; (void)n; return 0; }

static toff_t image_tiff_seek(thandle_t h, toff_t off, int whence)
{
    image_tiff_mem *m = (image_tiff_mem *)h;
    toff_t base = whence == SEEK_CUR ? m->pos : whence == SEEK_END ? m->len : 0;
    m->pos = base + off;
    return m->pos;
}

static int image_tiff_close(thandle_t h) { (void)h; return 0; }
static toff_t image_tiff_size(thandle_t h) { return ((image_tiff_mem *)h)->len; }

static int image_tiff_map(thandle_t h, void **base, toff_t *size)
{
    image_tiff_mem *m = (image_tiff_mem *)h;
    *base = (void *)m->p;
    *size = m->len;
    return 1;
}

static void image_tiff_unmap(thandle_t h, void *base, toff_t size) { (void)h; (void)base; (void)size; }

static int image_tiff_on_error(TIFF *tif, void *user, const char *module, const char *fmt, va_list ap)
{
    image_tiff_mem *m = user;
    (void)tif;
    (void)module;
    if (!m->msg[0])
        vsnprintf(m->msg, sizeof m->msg, fmt, ap);
    return 1;
}

static int image_tiff_on_warning(TIFF *tif, void *user, const char *module, const char *fmt, va_list ap)
{
    (void)tif; (void)user; (void)module; (void)fmt; (void)ap;
    return 1;
}

/* What libtiff may allocate at once: its strip and tile buffers are sized
 * from the header's samples and tile sides, not from the file, so a
 * 162-byte file could ask for gigabytes. The cap allows a strip or tile of
 * IMAGE_TIFF_MAX_BYTES_PER_PIXEL bytes per pixel over max_pixels, and
 * IMAGE_TIFF_MIN_CAP for tiles larger than a small image. */
#define IMAGE_TIFF_MAX_BYTES_PER_PIXEL 16u        /* RGBA of 32-bit samples */
#define IMAGE_TIFF_MIN_CAP ((size_t)64 << 20)
#define IMAGE_TIFF_MIN_TILE_PIXELS ((size_t)1 << 20)

static size_t image_tiff_cap(size_t max_pixels)
{
    size_t px = max_pixels < IMAGE_MAX_PIXELS ? max_pixels : IMAGE_MAX_PIXELS;
    return IMAGE_TIFF_MIN_CAP + px * IMAGE_TIFF_MAX_BYTES_PER_PIXEL;
}

/* The header's layout against what a picture of w x h needs: at most
 * IMAGE_TIFF_MAX_BYTES_PER_PIXEL bytes a pixel, and tiles no larger than
 * the picture or IMAGE_TIFF_MIN_TILE_PIXELS, whichever is more. */
static int image_tiff_check_layout(const image_tiff_lib *t, TIFF *tif, const char *name, uint32_t w,
                                   uint32_t h, diag *err)
{
    uint16_t spp = 1, bps = 1;
    uint32_t tw = 0, th = 0;
    size_t tile_max = (size_t)w * h > IMAGE_TIFF_MIN_TILE_PIXELS ? (size_t)w * h : IMAGE_TIFF_MIN_TILE_PIXELS;
    t->GetField(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
    t->GetField(tif, TIFFTAG_BITSPERSAMPLE, &bps);
    if ((unsigned long)spp * bps > 8ul * IMAGE_TIFF_MAX_BYTES_PER_PIXEL)
        return diag_at(err, DIAG_INPUT, name, 0, 0,
                       "TIFF: %u samples of %u bits a pixel is over the %u bits this command reads",
                       (unsigned)spp, (unsigned)bps, 8u * IMAGE_TIFF_MAX_BYTES_PER_PIXEL);
    if (t->GetField(tif, TIFFTAG_TILEWIDTH, &tw) && t->GetField(tif, TIFFTAG_TILELENGTH, &th) &&
        (size_t)tw * th > tile_max)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "TIFF: %ux%u tiles for a %ux%u picture are over %lu pixels",
                       (unsigned)tw, (unsigned)th, (unsigned)w, (unsigned)h, (unsigned long)tile_max);
    return 0;
}

int image_read_tiff_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err)
{
    image_tiff_lib t;
    image_tiff_mem m;
    TIFFOpenOptions *opts;
    TIFF *tif;
    uint32_t w = 0, h = 0, *rgba;
    image img;
    size_t i, n;
    int st;
    if (image_tiff_load(&t, name, err))
        return DIAG_IO;
    memset(&m, 0, sizeof m);
    m.p = data;
    m.len = (toff_t)len;
    if (!(opts = t.OpenOptionsAlloc()))
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
    t.OpenOptionsSetErrorHandlerExtR(opts, image_tiff_on_error, &m);
    t.OpenOptionsSetWarningHandlerExtR(opts, image_tiff_on_warning, &m);
    t.OpenOptionsSetMaxSingleMemAlloc(opts, (tmsize_t)image_tiff_cap(max_pixels));
    tif = t.ClientOpenExt(name, "rm", (thandle_t)&m, image_tiff_read, image_tiff_write, image_tiff_seek,
                            image_tiff_close, image_tiff_size, image_tiff_map, image_tiff_unmap, opts);
    t.OpenOptionsFree(opts);
    if (!tif)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "TIFF: %s", m.msg[0] ? m.msg : "cannot be read");
    t.GetField(tif, TIFFTAG_IMAGEWIDTH, &w);
    t.GetField(tif, TIFFTAG_IMAGELENGTH, &h);
    if (w < 1 || h < 1 || w > IMAGE_MAX_SIDE || h > IMAGE_MAX_SIDE || (size_t)w * h > max_pixels) {
        t.Close(tif);
        return diag_at(err, DIAG_INPUT, name, 0, 0, "%ux%u pixels is %s; scale it down", (unsigned)w,
                       (unsigned)h, w && h ? "over what this command reads" : "no picture");
    }
    if ((st = image_tiff_check_layout(&t, tif, name, w, h, err)) != 0) {
        t.Close(tif);
        return st;
    }
    n = (size_t)w * h;
    if (!(rgba = mem_alloc(n * sizeof *rgba))) {
        t.Close(tif);
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory for %ux%u pixels", (unsigned)w, (unsigned)h);
    }
    if (!t.ReadRGBAImageOriented(tif, w, h, rgba, ORIENTATION_TOPLEFT, 0)) {
        st = diag_at(err, DIAG_INPUT, name, 0, 0, "TIFF: %s", m.msg[0] ? m.msg : "cannot decode the picture");
        mem_free(rgba);
        t.Close(tif);
        return st;
    }
    t.Close(tif);
    if ((st = image_alloc(&img, (int)w, (int)h, channels, name, err)) != 0) {
        mem_free(rgba);
        return st;
    }
    for (i = 0; i < n; i++) {
        /* libtiff's RGBA is premultiplied: over black it is the colour as is */
        unsigned r = TIFFGetR(rgba[i]), g = TIFFGetG(rgba[i]), b = TIFFGetB(rgba[i]);
        if (channels == 1) {
            img.px[i] = (uint8_t)((299 * r + 587 * g + 114 * b + 500) / 1000);
        } else {
            img.px[3 * i] = (uint8_t)r;
            img.px[3 * i + 1] = (uint8_t)g;
            img.px[3 * i + 2] = (uint8_t)b;
        }
    }
    mem_free(rgba);
    *out = img;
    return 0;
}

#else

int image_tiff_available(void) { return 0; }

int image_read_tiff_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err)
{
    (void)data; (void)len; (void)channels; (void)max_pixels; (void)out;
    return diag_at(err, DIAG_INPUT, name, 0, 0,
                   "a TIFF image, and this maprt was built without TIFF support "
                   "(apt-get install -y libtiff-dev, then rebuild)");
}
#endif
