/* outfile — outputs committed on close, and bounded whole-file reads. */
#include "util/outfile.h"
#include "util/mem.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static unsigned long outfile_serial;

int outfile_open(outfile *of, const char *path, diag *err)
{
    size_t n = strlen(path);
    struct stat st;
    memset(of, 0, sizeof *of);
    /* The rename would replace a device, FIFO or directory entry (e.g.
     * /dev/null) with a plain file; refuse before writing anything. */
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return diag_at(err, DIAG_IO, path, 0, 0, "not a regular file; refusing to replace it");
    of->path = mem_strdup(path);
    of->tmp = mem_alloc(n + 48);
    if (!of->path || !of->tmp) {
        outfile_abort(of);
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    }
    snprintf(of->tmp, n + 48, "%s.tmp-%ld-%lu", path, (long)getpid(), ++outfile_serial);
    of->f = fopen(of->tmp, "wb");
    if (!of->f) {
        int e = errno;
        outfile_abort(of);
        return diag_at(err, DIAG_IO, path, 0, 0, "cannot create: %s", strerror(e));
    }
    return 0;
}

int outfile_write(outfile *of, const void *data, size_t len, diag *err)
{
    if (of->failed || !of->f || (len && fwrite(data, 1, len, of->f) != len)) {
        of->failed = 1;
        return diag_at(err, DIAG_IO, of->path, 0, 0, "write failed: %s", strerror(errno));
    }
    return 0;
}

void outfile_sink(void *ctx, const void *data, size_t len)
{
    outfile *of = ctx;
    if (!of->failed && (!of->f || fwrite(data, 1, len, of->f) != len))
        of->failed = 1;
}

int outfile_commit(outfile *of, diag *err)
{
    int bad = of->failed || !of->f;
    if (of->f) {
        if (fflush(of->f) != 0)
            bad = 1;
        if (fclose(of->f) != 0)
            bad = 1;
        of->f = NULL;
    }
    if (bad) {
        diag_at(err, DIAG_IO, of->path, 0, 0, "write failed");
        outfile_abort(of);
        return DIAG_IO;
    }
    if (rename(of->tmp, of->path) != 0) {
        int e = errno;
        diag_at(err, DIAG_IO, of->path, 0, 0, "cannot rename into place: %s", strerror(e));
        outfile_abort(of);
        return DIAG_IO;
    }
    mem_free(of->tmp);
    mem_free(of->path);
    of->tmp = of->path = NULL;
    return 0;
}

void outfile_abort(outfile *of)
{
    if (of->f)
        fclose(of->f);
    if (of->tmp)
        remove(of->tmp);
    mem_free(of->tmp);
    mem_free(of->path);
    memset(of, 0, sizeof *of);
}

int outfile_write_all(const char *path, const void *data, size_t len, diag *err)
{
    outfile of;
    if (outfile_open(&of, path, err))
        return DIAG_IO;
    if (outfile_write(&of, data, len, err)) {
        outfile_abort(&of);
        return DIAG_IO;
    }
    return outfile_commit(&of, err);
}

int infile_read_all(const char *path, size_t max, char **data, size_t *len, diag *err)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t n = 0, cap = 0;
    if (!f) /* a name that does not exist is bad input; anything else is I/O */
        return diag_at(err, errno == ENOENT || errno == ENOTDIR ? DIAG_INPUT : DIAG_IO, path, 0, 0,
                       "cannot open: %s", strerror(errno));
    for (;;) {
        size_t got;
        if (n == cap) {
            if (cap >= max + 1 || mem_grow((void **)&buf, &cap, n + 65536, 1)) {
                int over = cap >= max + 1;
                mem_free(buf);
                fclose(f);
                return over ? diag_at(err, DIAG_INPUT, path, 0, 0, "file larger than %zu bytes", max)
                            : diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
            }
        }
        got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (n > max) {
            mem_free(buf);
            fclose(f);
            return diag_at(err, DIAG_INPUT, path, 0, 0, "file larger than %zu bytes", max);
        }
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        mem_free(buf);
        fclose(f);
        return diag_at(err, DIAG_IO, path, 0, 0, "read error");
    }
    fclose(f);
    if (!buf && !(buf = mem_alloc(1)))
        return diag_at(err, DIAG_IO, path, 0, 0, "out of memory");
    *data = buf;
    *len = n;
    return 0;
}
