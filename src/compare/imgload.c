/* imgload — PNG or PNM by content (see imgload.h). */
#include "compare/imgload.h"
#include "image/pnm.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <errno.h>
#include <string.h>
#include <sys/stat.h>

int imgload_memory(const char *name, const void *data, size_t len, image *out, diag *err)
{
    static const unsigned char png_sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (len == 0)
        return diag_at(err, DIAG_INPUT, name, 0, 0, "empty file (not a PNG or PNM image)");
    if (len >= 8 && !memcmp(data, png_sig, 8))
        return image_read_png_memory(name, data, len, 3, out, err);
    if (pnm_sniff(data, len))
        return pnm_read_memory(name, data, len, 3, out, err);
    return diag_at(err, DIAG_INPUT, name, 0, 0, "not a PNG or PNM image");
}

int imgload_read(const char *path, image *out, diag *err)
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
    rc = imgload_memory(path, data, len, out, err);
    mem_free(data);
    return rc;
}
