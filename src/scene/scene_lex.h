/* scene_lex — card images to statements for the scene parser.
 * Reads records from a recsrc, keeps columns 1-72 (73-80 carry sequence
 * numbers and are ignored; an item running from 72 into 73 is refused, or
 * only warned about when 73-80 hold a sequence number), drops comment cards (`*` in column 1) and blank
 * cards, joins continued cards (a card whose last item is a lone `-`; comment
 * cards may come between, blank cards may not) and
 * splits the result into blank-separated items, each with the record and
 * column it came from. Sits between the record reader and scene_parse. */
#ifndef SCENE_LEX_H
#define SCENE_LEX_H
#include <stddef.h>
#include "util/diag.h"
#include "util/recsrc.h"

#define SCENE_LEX_COLUMNS 72       /* significant columns of a card */
#define SCENE_LEX_MAX_ITEMS 512    /* items in one (continued) statement */

typedef struct scene_lex_tok {
    long line, col;                       /* record number, 1-based column */
    size_t len;
    char text[SCENE_LEX_COLUMNS + 1];     /* as written, NUL-terminated */
} scene_lex_tok;

/* One statement: its items in order; tok[0] is the keyword. */
typedef struct scene_lex_stmt {
    size_t ntok;
    scene_lex_tok tok[SCENE_LEX_MAX_ITEMS];
    long end_line, end_col;   /* just past the last item, for "missing" */
} scene_lex_stmt;

typedef struct scene_lex {
    const recsrc *src;
    long recno;               /* records read so far */
    /* Called with each warning (status 0, location and text); may be NULL. */
    void (*warn)(void *ctx, const diag *w);
    void *warn_ctx;
} scene_lex;

void scene_lex_init(scene_lex *lx, const recsrc *src);

/* warn and warn_ctx start NULL; set them after init to receive warnings. */
/* Reads the next statement into *st. Returns 1 with a statement, 0 at the
 * end of the deck, or -1 with err filled (DIAG_INPUT for the deck's faults,
 * DIAG_IO for a read error of the recsrc). Errors: a character outside printable ASCII,
 * an item that crosses from column 72 into 73 (a warning instead when
 * columns 73-80 hold a sequence number, which may simply follow it),
 * a statement of more than SCENE_LEX_MAX_ITEMS items, a continuation
 * followed by a blank card or the end of the deck. */
int scene_lex_next(scene_lex *lx, scene_lex_stmt *st, diag *err);
#endif
