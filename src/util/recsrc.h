/* recsrc — a source of records (text lines or card images) for the parsers.
 * The core never opens files: the CMS shim or a test hands the parser a recsrc.
 * Records are byte strings in the host character set (ASCII), without line
 * ends; recno is the 1-based record number used in diagnostics. */
#ifndef RECSRC_H
#define RECSRC_H
#include <stddef.h>
#include "util/diag.h"

typedef struct recsrc {
    /* Returns 1 and sets *rec and *len (valid until the next call) for a record,
     * 0 at end of input, or a diag_status (>1 never; use -1) after filling
     * err on a read error. */
    int (*next)(void *ctx, const char **rec, size_t *len, diag *err);
    void *ctx;
    const char *name;   /* file name or fileid for diagnostics */
    size_t records;     /* records in all where known before the first is
                           read (a deck decoded whole), else 0: a reader
                           may size its arrays by it, never trust it */
} recsrc;

/* Line reader over a memory buffer: splits at LF, drops a CR before it; the
 * buffer must outlive the recsrc. */
typedef struct recsrc_mem {
    const char *buf;
    size_t len, pos;
} recsrc_mem;

void recsrc_from_memory(recsrc *src, recsrc_mem *state, const char *name,
                        const char *buf, size_t len);
#endif
