/* cms_warn — the warning hook of the readers (see cms_warn.h). */
#include "vm_cms_shim/cms_warn.h"
#include <stdarg.h>
#include <stdio.h>

void cms_warn_emit(const cms_warn *w, const char *file, long long offset, const char *fmt, ...)
{
    diag d;
    va_list ap;
    if (!w || !w->fn)
        return;
    diag_init(&d);
    snprintf(d.file, sizeof d.file, "%s", file ? file : "");
    d.offset = offset;
    va_start(ap, fmt);
    vsnprintf(d.msg, sizeof d.msg, fmt, ap);
    va_end(ap);
    w->fn(w->ctx, &d);
}

void cms_warn_format(const diag *w, char *buf, size_t size)
{
    if (w->offset >= 0)
        snprintf(buf, size, "%s: offset %lld: warning: %s", w->file, w->offset, w->msg);
    else
        snprintf(buf, size, "%s: warning: %s", w->file, w->msg);
}
