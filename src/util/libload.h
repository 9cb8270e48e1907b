/* libload — a shared library opened at run time with dlopen, so a process
 * that never needs it never maps it: the GL libraries of the OSMesa and EGL
 * backends (Mesa's drivers bring libLLVM, tens of MiB of resident memory)
 * and libtiff (eight libraries, libstdc++ among them, whose relocations were
 * 3.9 M of the 4.5 M instructions of a process's start-up). */
#ifndef UTIL_LIBLOAD_H
#define UTIL_LIBLOAD_H
#include <stddef.h>
#include "util/diag.h"

typedef void (*libload_fn)(void);

/* Opens the first loadable library of names (NULL-terminated) and looks up
 * the n symbols syms[] into fns[] (cast each back to its own type before
 * calling). The library stays loaded for the life of the process; opening
 * it again only counts a reference. 0, or DIAG_IO saying which library
 * could not be opened (then hint, e.g. what to install) or which symbol it
 * lacks, with who (the backend or format) as the message's file; fns is
 * untouched then. */
int libload(const char *const *names, const char *const *syms, libload_fn *fns, size_t n, const char *who,
            const char *hint, diag *err);
#endif
