/* scene_cur — a cursor over the items of one scene statement, with the
 * checks every statement handler needs: numbers (plain decimal or exponent
 * notation, finite, magnitude at most SCENE_CUR_MAX_ABS), names (a letter,
 * then letters, digits or _ $ # @; at most SCENE_NAME_MAX characters; not a
 * reserved word), keywords (case-insensitive) and the end of the statement.
 * Every error goes to the cursor's diag with the item's record and column and
 * the statement keyword as prefix, e.g. "SPHERE: missing number". Handlers in
 * scene_parse.c and later statement files share it. */
#ifndef SCENE_CUR_H
#define SCENE_CUR_H
#include <stddef.h>
#include "model/scene.h"
#include "scene/scene_lex.h"
#include "util/diag.h"

#define SCENE_CUR_MAX_ABS 1e6      /* largest magnitude of a number */

typedef struct scene_cur {
    const scene_lex_stmt *st;
    size_t pos;               /* next item */
    const char *file;         /* for diagnostics */
    const char *what;         /* statement keyword (canonical), message prefix */
    diag *err;
} scene_cur;

void scene_cur_init(scene_cur *c, const scene_lex_stmt *st, const char *file,
                    const char *what, diag *err);

/* The next item, or NULL at the end of the statement. */
const scene_lex_tok *scene_cur_peek(const scene_cur *c);
int scene_cur_at_end(const scene_cur *c);

/* Case-insensitive comparison of an item with an upper-case keyword. */
int scene_cur_is(const scene_lex_tok *t, const char *keyword);
/* Consumes the next item if it is keyword; returns 1 if it did. */
int scene_cur_accept(scene_cur *c, const char *keyword);
/* 1 if the item is written like a number (starts with a digit, sign or '.'). */
int scene_cur_numeric(const scene_lex_tok *t);
/* 1 if word (upper case) is reserved and cannot be a name. */
int scene_cur_reserved(const char *word);

/* Records "<what>: <message>" at item t (or at the end of the statement when
 * t is NULL) and returns DIAG_INPUT. */
int scene_cur_error(scene_cur *c, const scene_lex_tok *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Reads a number into *v. On error returns DIAG_INPUT: "missing number",
 * "expected a number, found X", "X is not a finite number" (NaN, Inf),
 * "X is out of range (magnitude above 1e6)". *at receives the item (may be
 * NULL) so callers can report range errors at it. */
int scene_cur_number(scene_cur *c, double *v, const scene_lex_tok **at);
/* Reads n numbers into v[0..n-1]. */
int scene_cur_numbers(scene_cur *c, double *v, int n);
/* Reads a whole number in [lo, hi]; label names it in the range message
 * ("<label> must be a whole number from lo to hi"). A range wider than
 * +-1e6 (seeds) replaces the magnitude limit of scene_cur_number. */
int scene_cur_int(scene_cur *c, const char *label, long lo, long hi, long *v);
/* Reads a number in [lo, hi] ("<label> must be between lo and hi"). */
int scene_cur_range(scene_cur *c, const char *label, double lo, double hi, double *v);
/* Reads a name into out (upper-cased, NUL-terminated). */
int scene_cur_name(scene_cur *c, char out[SCENE_NAME_MAX + 1], const scene_lex_tok **at);
/* Reads one of the upper-case keywords words[0..n) (a NULL-terminated
 * list) and sets *index to its position: "expected A, B or C, found X",
 * "missing A, B or C". */
int scene_cur_choice(scene_cur *c, const char *const *words, int *index);
/* Fails with "extra operand X" unless the statement is fully consumed. */
int scene_cur_finish(scene_cur *c);
#endif
