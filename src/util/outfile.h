/* outfile — an output file committed on close. Bytes go to a temporary file
 * beside the target ("<path>.tmp-<pid>-<n>"); outfile_commit renames it over
 * the target, outfile_abort removes it, so a failed run never leaves a
 * half-written file under the real name. Host paths only: the CMS shim
 * resolves fileids to host paths first. */
#ifndef OUTFILE_H
#define OUTFILE_H
#include <stddef.h>
#include <stdio.h>
#include "util/diag.h"

typedef struct outfile {
    FILE *f;
    char *path;      /* final name */
    char *tmp;       /* temporary name */
    int failed;      /* a write failed: commit will refuse */
} outfile;

int outfile_open(outfile *of, const char *path, diag *err);           /* 0 or DIAG_IO */
int outfile_write(outfile *of, const void *data, size_t len, diag *err);
int outfile_commit(outfile *of, diag *err);   /* flush, close, rename; 0 or DIAG_IO */
void outfile_abort(outfile *of);              /* close and remove; safe to repeat */
/* Writes a whole buffer to path through open/write/commit. */
int outfile_write_all(const char *path, const void *data, size_t len, diag *err);
/* A writer callback (stb style) that appends to an outfile: ctx is the outfile;
 * errors are remembered and reported by outfile_commit. */
void outfile_sink(void *ctx, const void *data, size_t len);
/* Reads a whole host file, refusing files larger than max bytes.
 * On success *data (mem_free it) and *len are set; else err names the file:
 * DIAG_INPUT when it does not exist or is too large, DIAG_IO otherwise. */
int infile_read_all(const char *path, size_t max, char **data, size_t *len, diag *err);
#endif
