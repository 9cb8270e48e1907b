/* version — maprt's version, printed by --version and written into the
 * provenance of every picture (PNG tEXt, PNM comments). */
#ifndef VERSION_H
#define VERSION_H

#define MAPRT_VERSION "0.9.0"

/* "0.9.0", or "0.9.0 (git 1a2b3c4)" when built from a git checkout (the
 * Makefile passes the revision to version.c alone). */
const char *version_string(void);
#endif
