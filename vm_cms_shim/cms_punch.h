/* cms_punch — splits a punched deck into CMS files the way READCARD * *
 * does: every :READ control card starts a new file named by its columns
 * 8-15, 17-24 and 26-27; cards before the first :READ card go to READCARD
 * CMSUT1 A1. Accepts Hercules ASCII punch output (lines, trailing blanks
 * stripped; restored to F 80) and EBCDIC-mode punch output (80-byte cards).
 * Used by `maprt cms import`. */
#ifndef CMS_PUNCH_H
#define CMS_PUNCH_H
#include "vm_cms_shim/cms_recs.h"

#define CMS_PUNCH_MAX_FILES 10000

/* Calls fn(ctx, id, recs, card, err) for each file of the deck (buf, n
 * bytes) in order; card is the number of its :READ card (or 1); recs is F 80
 * and is freed after the call. o->form may be AUTO,
 * PUNCH/TEXT (ASCII lines) or EBCDIC; o->cp applies to EBCDIC decks. Returns
 * 0, fn's non-zero return, or a DIAG status (errors located by card). */
int cms_punch_split(const unsigned char *buf, size_t n, const cms_decode_opts *o,
                    const char *name,
                    int (*fn)(void *ctx, const cms_fileid *id, const cms_recs *recs, long card,
                              diag *err),
                    void *ctx, long *nfiles, diag *err);
#endif
