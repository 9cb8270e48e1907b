/* dl_lib — a GL library (OSMesa, EGL) opened at run time with dlopen, so a
 * process that never chooses that backend never maps it (Mesa's drivers
 * bring libLLVM, tens of MiB of resident memory). */
#ifndef DL_LIB_H
#define DL_LIB_H
#include <stddef.h>
#include "util/diag.h"

typedef void (*dl_lib_fn)(void);

/* Opens the first loadable library of names (NULL-terminated) and looks up
 * the n symbols syms[] into fns[] (cast each back to its own type before
 * calling). The library stays loaded for the life of the process. 0, or
 * DIAG_IO saying which library could not be opened or which symbol it
 * lacks (who names the backend in the message); fns is untouched then. */
int dl_lib_load(const char *const *names, const char *const *syms, dl_lib_fn *fns, size_t n,
                const char *who, diag *err);
#endif
