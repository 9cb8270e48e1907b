/* image_out — pictures written in the format their name asks for (see image_out.h). */
#include "image/image_out.h"
#include "image/image_png.h"
#include "image/pnm.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <stdio.h>
#include <string.h>
#include <strings.h>

static const char *const image_out_names[] = { "", "png", "ppm", "pam" };

image_out_format image_out_parse(const char *s)
{
    int f;
    for (f = IMAGE_OUT_PNG; f <= IMAGE_OUT_PAM; f++)
        if (!strcasecmp(s, image_out_names[f]))
            return (image_out_format)f;
    return IMAGE_OUT_NONE;
}

int image_out_choose(const char *name, image_out_format given, image_out_format *out, diag *err)
{
    const char *dot = strrchr(name, '.'), *slash = strrchr(name, '/');
    image_out_format byname;
    if (!strcmp(name, "-")) {
        if (!given)
            return diag_at(err, DIAG_USAGE, "-", 0, 0,
                           "standard output needs --format png, ppm or pam");
        *out = given;
        return 0;
    }
    byname = dot && (!slash || dot > slash) ? image_out_parse(dot + 1) : IMAGE_OUT_NONE;
    if (!byname)
        return diag_at(err, DIAG_USAGE, name, 0, 0,
                       "cannot write this kind of picture: the name must end in .png, .ppm or "
                       ".pam (or give '-' and --format for standard output)");
    if (given && given != byname)
        return diag_at(err, DIAG_USAGE, name, 0, 0, "--format %s contradicts the name's .%s",
                       image_out_names[given], image_out_names[byname]);
    *out = byname;
    return 0;
}

/* Writes the n parts of a file (part k: len[k] bytes at data[k]) to path
 * ("-": standard output). 0, or DIAG_IO. */
static int image_out_parts(const char *path, const void *const *data, const size_t *len, int n, diag *err)
{
    outfile of;
    int k;
    if (!strcmp(path, "-")) {
        for (k = 0; k < n; k++)
            if (fwrite(data[k], 1, len[k], stdout) != len[k])
                return diag_at(err, DIAG_IO, "standard output", 0, 0, "write failed");
        return fflush(stdout) ? diag_at(err, DIAG_IO, "standard output", 0, 0, "write failed") : 0;
    }
    if (outfile_open(&of, path, err))
        return err->status;
    for (k = 0; k < n; k++)
        if (outfile_write(&of, data[k], len[k], err)) {
            outfile_abort(&of);
            return DIAG_IO;
        }
    return outfile_commit(&of, err);
}

int image_out_write(const char *path, image_out_format f, const image *img, const image_meta *m,
                    diag *err)
{
    void *buf = NULL, *tagged = NULL;
    size_t len = 0, tlen = 0;
    int rc;
    if (f == IMAGE_OUT_PNG) {
        rc = image_encode_png(img, &buf, &len, err);
        if (!rc && m && m->n) {
            rc = image_meta_png(buf, len, m, &tagged, &tlen, err);
            mem_free(buf);
            buf = tagged;
            len = tlen;
        }
        if (!rc)
            rc = image_out_parts(path, (const void *const *)&buf, &len, 1, err);
        mem_free(buf);
        return rc;
    } else {
        /* the header, then the raster straight from the picture: no copy
         * of a file as large as the picture itself */
        char comments[IMAGE_META_MAX * (IMAGE_META_KEY + IMAGE_META_VALUE + 8)];
        char head[3 + sizeof comments + PNM_HEAD_MAX];
        const void *part[2];
        size_t plen[2];
        if (m)
            image_meta_comments(m, comments, sizeof comments);
        if (!(plen[0] = pnm_header(img, f == IMAGE_OUT_PAM, m ? comments : NULL, head, sizeof head)))
            return diag_at(err, DIAG_IO, path, 0, 0, "PNM header too long");
        part[0] = head;
        part[1] = img->px;
        plen[1] = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
        return image_out_parts(path, part, plen, 2, err);
    }
}
