/* diag — first-error records with locations (see diag.h). */
#include "util/diag.h"
#include <stdarg.h>
#include <string.h>

void diag_init(diag *d)
{
    memset(d, 0, sizeof *d);
    d->offset = -1;
}

static void diag_file(diag *d, const char *file)
{
    size_t n = file ? strlen(file) : 0;
    if (n >= sizeof d->file)
        n = sizeof d->file - 1;
    memcpy(d->file, file ? file : "", n);
    d->file[n] = '\0';
}

/* Records the first error: location (line/col or byte offset) and text. */
static int diag_vset(diag *d, int status, const char *file, long line, long col,
                     long long offset, const char *fmt, va_list ap)
{
    if (!d || d->status)
        return status;
    d->status = status;
    diag_file(d, file);
    d->line = line;
    d->col = col;
    d->offset = offset;
    vsnprintf(d->msg, sizeof d->msg, fmt, ap);
    return status;
}

int diag_at(diag *d, int status, const char *file, long line, long col,
            const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    status = diag_vset(d, status, file, line, col, -1, fmt, ap);
    va_end(ap);
    return status;
}

int diag_offset(diag *d, int status, const char *file, long long offset,
                const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    status = diag_vset(d, status, file, 0, 0, offset, fmt, ap);
    va_end(ap);
    return status;
}

static void diag_format_as(const diag *d, const char *kind, char *buf, size_t size)
{
    if (d->offset >= 0)
        snprintf(buf, size, "%s: offset %lld: %s: %s", d->file, d->offset, kind, d->msg);
    else if (d->line > 0 && d->col > 0)
        snprintf(buf, size, "%s:%ld:%ld: %s: %s", d->file, d->line, d->col, kind, d->msg);
    else if (d->line > 0)
        snprintf(buf, size, "%s:%ld: %s: %s", d->file, d->line, kind, d->msg);
    else if (d->file[0])
        snprintf(buf, size, "%s: %s: %s", d->file, kind, d->msg);
    else
        snprintf(buf, size, "%s: %s", kind, d->msg);
}

void diag_format(const diag *d, char *buf, size_t size) { diag_format_as(d, "error", buf, size); }

void diag_print(FILE *f, const diag *d)
{
    char buf[1024];
    diag_format(d, buf, sizeof buf);
    fprintf(f, "maprt: %s\n", buf);
}

void diag_format_warning(const diag *d, char *buf, size_t size) { diag_format_as(d, "warning", buf, size); }

void diag_print_warning(FILE *f, const diag *d)
{
    char buf[1024];
    diag_format_warning(d, buf, sizeof buf);
    fprintf(f, "maprt: %s\n", buf);
}
