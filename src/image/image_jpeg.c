/* image_jpeg — JPEG input through libjpeg(-turbo) (see image_jpeg.h). */
#include "image/image_jpeg.h"

#ifdef IMAGE_HAVE_JPEG
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <jpeglib.h>

int image_jpeg_available(void) { return 1; }

/* libjpeg reports errors through error_exit, which must not return: it
 * jumps back to image_read_jpeg_memory with the message kept. */
typedef struct image_jpeg_err {
    struct jpeg_error_mgr mgr;
    jmp_buf jump;
    char msg[JMSG_LENGTH_MAX];
} image_jpeg_err;

static void image_jpeg_exit(j_common_ptr cinfo)
{
    image_jpeg_err *e = (image_jpeg_err *)cinfo->err;
    e->mgr.format_message(cinfo, e->msg);
    longjmp(e->jump, 1);
}

static void image_jpeg_quiet(j_common_ptr cinfo, int level) { (void)cinfo; (void)level; }

/* A progressive file may repeat scans without end: each can be 12 bytes
 * (an end-of-band run covers a whole component) and costs a pass over
 * every block: a 1000x1000 grey picture with one scan repeated 80,000
 * times, 966 KB, took 9.5 s to read, against 0.1 s for the picture alone.
 * A real file has about 10 (libjpeg's own progressive script has 10), so more
 * than IMAGE_JPEG_MAX_SCANS is refused, as libjpeg-turbo's djpeg -maxscans
 * and TurboJPEG's scan limit let callers do. libjpeg calls the progress
 * monitor between rows while it reads the scans. */
#define IMAGE_JPEG_MAX_SCANS 500

static void image_jpeg_progress(j_common_ptr cinfo)
{
    j_decompress_ptr d = (j_decompress_ptr)cinfo;
    image_jpeg_err *e = (image_jpeg_err *)cinfo->err;
    if (cinfo->is_decompressor && d->input_scan_number > IMAGE_JPEG_MAX_SCANS) {
        snprintf(e->msg, sizeof e->msg, "more than %d scans (a progressive JPEG has about 10)",
                 IMAGE_JPEG_MAX_SCANS);
        longjmp(e->jump, 1);
    }
}

int image_read_jpeg_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err)
{
    struct jpeg_decompress_struct ci;
    struct jpeg_progress_mgr prog;
    image_jpeg_err je;
    image img;
    volatile int have = 0;
    int st;
    memset(&img, 0, sizeof img);
    ci.err = jpeg_std_error(&je.mgr);
    je.mgr.error_exit = image_jpeg_exit;
    je.mgr.emit_message = image_jpeg_quiet;
    if (setjmp(je.jump)) {
        if (have)
            image_free(&img);
        jpeg_destroy_decompress(&ci);
        return diag_at(err, DIAG_INPUT, name, 0, 0, "JPEG: %s", je.msg);
    }
    jpeg_create_decompress(&ci);
    memset(&prog, 0, sizeof prog);
    prog.progress_monitor = image_jpeg_progress;
    ci.progress = &prog;
    jpeg_mem_src(&ci, (const unsigned char *)data, (unsigned long)len);
    jpeg_read_header(&ci, TRUE);
    if (ci.jpeg_color_space == JCS_CMYK || ci.jpeg_color_space == JCS_YCCK) {
        jpeg_destroy_decompress(&ci);
        return diag_at(err, DIAG_INPUT, name, 0, 0, "JPEG: CMYK pictures are not read; save it as RGB");
    }
    if (ci.image_width > IMAGE_MAX_SIDE || ci.image_height > IMAGE_MAX_SIDE
        || (size_t)ci.image_width * ci.image_height > max_pixels) {
        st = diag_at(err, DIAG_INPUT, name, 0, 0, "%ux%u pixels is over the %zu this command reads; scale it down",
                     (unsigned)ci.image_width, (unsigned)ci.image_height, max_pixels);
        jpeg_destroy_decompress(&ci);
        return st;
    }
    ci.out_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&ci);
    if ((st = image_alloc(&img, (int)ci.output_width, (int)ci.output_height, channels, name, err)) != 0) {
        jpeg_destroy_decompress(&ci);
        return st;
    }
    have = 1;
    while (ci.output_scanline < ci.output_height) {
        JSAMPROW row = img.px + (size_t)ci.output_scanline * (size_t)img.width * (size_t)channels;
        jpeg_read_scanlines(&ci, &row, 1);
    }
    jpeg_finish_decompress(&ci);
    jpeg_destroy_decompress(&ci);
    *out = img;
    return 0;
}

#else

int image_jpeg_available(void) { return 0; }

int image_read_jpeg_memory(const char *name, const void *data, size_t len, int channels,
                           size_t max_pixels, image *out, diag *err)
{
    (void)data; (void)len; (void)channels; (void)max_pixels; (void)out;
    return diag_at(err, DIAG_INPUT, name, 0, 0,
                   "a JPEG image, and this maprt was built without JPEG support "
                   "(apt-get install -y libjpeg62-turbo-dev, then rebuild)");
}
#endif
