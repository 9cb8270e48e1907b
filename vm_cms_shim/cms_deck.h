/* cms_deck — a scene deck opened by name as a recsrc for the scene parser:
 * host path or CMS fileid, any host form (ASCII lines, EBCDIC cards, V
 * stream, punch deck), records yielded as host text in full (columns 73-80
 * included; the parser ignores them). recsrc.name is the fileid ("FIG1 SCENE
 * A1") or the path, so parser diagnostics read "FIG1 SCENE A1:12:5: ...". */
#ifndef CMS_DECK_H
#define CMS_DECK_H
#include "util/recsrc.h"
#include "vm_cms_shim/cms_file.h"

typedef struct cms_deck cms_deck;

/* Opens name (see cms_name) and fills *src; o may be NULL (auto-detect the
 * form and code page). Errors as cms_file_open_read. Release with
 * cms_deck_close after the parser is done with src. */
int cms_deck_open(cms_deck **deck, recsrc *src, const cms_disks *d, const char *name,
                  const cms_decode_opts *o, diag *err);

/* The file's description (form, RECFM, LRECL, record count). */
void cms_deck_state(const cms_deck *deck, cms_file_info *info);

void cms_deck_close(cms_deck *deck);
#endif
