/* cms_warn — non-fatal findings of the tape and deck readers (a broken AWS
 * previous-length chain, standard labels skipped, a count rule applied): the
 * reader goes on, and tells the caller through this hook. */
#ifndef CMS_WARN_H
#define CMS_WARN_H
#include "util/diag.h"

typedef struct cms_warn {
    void (*fn)(void *ctx, const diag *w);   /* w->status is 0; msg says what was seen */
    void *ctx;
} cms_warn;

/* Calls w->fn with a diag at (file, byte offset; offset < 0 = none); a NULL
 * hook or function drops the note. */
void cms_warn_emit(const cms_warn *w, const char *file, long long offset, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Formats a note as "FILE: offset N: warning: TEXT" (or "FILE: warning: TEXT"). */
void cms_warn_format(const diag *w, char *buf, size_t size);
#endif
