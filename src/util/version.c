/* version — the version string (see version.h). */
#include "util/version.h"

#ifndef MAPRT_REV
#define MAPRT_REV ""
#endif

const char *version_string(void)
{
    return MAPRT_REV[0] ? MAPRT_VERSION " (git " MAPRT_REV ")" : MAPRT_VERSION;
}
