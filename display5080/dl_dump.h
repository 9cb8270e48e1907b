/* dl_dump — the disassembler: a dl_decode visitor that lists a display list
 * as text, one element a line with its byte offset, length and code, e.g.
 *     16      8  5F01  clear 0
 * Text elements are shown converted from the current code page (037 via
 * iconv; 437 and 819 in their ASCII range).
 * Used by `maprt dl dump`. Output goes through a writer callback. */
#ifndef DL_DUMP_H
#define DL_DUMP_H
#include <stddef.h>
#include <stdint.h>
#include "display5080/dl_decode.h"
#include "util/diag.h"

typedef void (*dl_dump_write)(void *ctx, const void *data, size_t len);

/* Lists buf (opts as for dl_decode, may be NULL); lines already written stay
 * written when a later element is malformed (the error, with its offset, is
 * returned as DIAG_INPUT). */
int dl_dump(const uint8_t *buf, size_t len, const char *name, const dl_decode_opts *opts,
            dl_dump_write write, void *wctx, diag *err);
#endif
