/* libload — run-time loading of optional libraries (see libload.h). */
#include "util/libload.h"
#include <dlfcn.h>
#include <string.h>

#define LIBLOAD_MAX_SYMS 32

int libload(const char *const *names, const char *const *syms, libload_fn *fns, size_t n, const char *who,
            const char *hint, diag *err)
{
    libload_fn got[LIBLOAD_MAX_SYMS];
    void *h = NULL;
    const char *why = "no library name";
    size_t i;
    if (n > LIBLOAD_MAX_SYMS)
        return diag_at(err, DIAG_IO, who, 0, 0, "internal: %lu symbols asked for", (unsigned long)n);
    for (i = 0; names[i] && !h; i++)
        if (!(h = dlopen(names[i], RTLD_NOW | RTLD_LOCAL)))
            why = dlerror();
    if (!h)
        return diag_at(err, DIAG_IO, who, 0, 0, "cannot load %s: %s (%s)", names[0] ? names[0] : "?",
                       why ? why : "unknown error", hint);
    for (i = 0; i < n; i++) {
        void *p = dlsym(h, syms[i]);
        if (!p) {
            dlclose(h);
            return diag_at(err, DIAG_IO, who, 0, 0, "%s has no symbol %s", names[0], syms[i]);
        }
        /* object to function pointer: POSIX guarantees the representation */
        memcpy(&got[i], &p, sizeof got[i]);
    }
    memcpy(fns, got, n * sizeof *fns);
    return 0;
}
