/* scene_lex — card images to statements (see scene_lex.h). */
#include "scene/scene_lex.h"
#include <string.h>

void scene_lex_init(scene_lex *lx, const recsrc *src)
{
    lx->src = src;
    lx->recno = 0;
}

static int scene_lex_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* Appends the items of one card (already cut to its significant columns)
 * to st. Sets *cont when the card's last item is a lone `-`, which is then
 * not kept. Returns 0 or DIAG_INPUT. */
static int scene_lex_card(scene_lex *lx, const char *rec, size_t n,
                          scene_lex_stmt *st, int *cont, diag *err)
{
    size_t i = 0, first = st->ntok;
    *cont = 0;
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)rec[i];
        if (c != '\t' && (c < 0x20 || c > 0x7e))
            return diag_at(err, DIAG_INPUT, lx->src->name, lx->recno, (long)i + 1,
                           "invalid character X'%02X'", c);
    }
    i = 0;
    while (i < n) {
        size_t start;
        scene_lex_tok *t;
        while (i < n && scene_lex_blank(rec[i]))
            i++;
        if (i >= n)
            break;
        start = i;
        while (i < n && !scene_lex_blank(rec[i]))
            i++;
        if (st->ntok >= SCENE_LEX_MAX_ITEMS)
            return diag_at(err, DIAG_INPUT, lx->src->name, lx->recno, (long)start + 1,
                           "statement has more than %d items", SCENE_LEX_MAX_ITEMS);
        t = &st->tok[st->ntok++];
        t->line = lx->recno;
        t->col = (long)start + 1;
        t->len = i - start;
        memcpy(t->text, rec + start, t->len);
        t->text[t->len] = '\0';
    }
    if (st->ntok > first && strcmp(st->tok[st->ntok - 1].text, "-") == 0) {
        *cont = 1;
        st->ntok--;
    }
    return 0;
}

int scene_lex_next(scene_lex *lx, scene_lex_stmt *st, diag *err)
{
    int cont = 0;
    long cont_line = 0, cont_col = 0;
    st->ntok = 0;
    st->end_line = st->end_col = 0;
    for (;;) {
        const char *rec;
        size_t len;
        int r = lx->src->next(lx->src->ctx, &rec, &len, err);
        if (r < 0) {
            if (!err->status)
                diag_at(err, DIAG_IO, lx->src->name, lx->recno + 1, 0, "read error");
            return -1;
        }
        if (r == 0) {
            if (cont) {
                diag_at(err, DIAG_INPUT, lx->src->name, cont_line, cont_col,
                        "continued statement has no continuation card");
                return -1;
            }
            return 0;
        }
        lx->recno++;
        if (len > SCENE_LEX_COLUMNS)
            len = SCENE_LEX_COLUMNS;
        if (len > 0 && rec[0] == '*')
            continue;
        {
            size_t before = st->ntok;
            int more;
            if (scene_lex_card(lx, rec, len, st, &more, err))
                return -1;
            if (st->ntok == before && !more) {
                /* a blank card ends a deck section; after a `-` it would
                 * silently join two statements, so it is refused there */
                if (cont) {
                    diag_at(err, DIAG_INPUT, lx->src->name, cont_line, cont_col,
                            "continued statement has no continuation card");
                    return -1;
                }
                continue;
            }
            if (more) {
                /* the dropped `-` item is still in the array */
                cont = 1;
                cont_line = st->tok[st->ntok].line;
                cont_col = st->tok[st->ntok].col;
                continue;
            }
            if (st->ntok > 0) {
                const scene_lex_tok *last = &st->tok[st->ntok - 1];
                st->end_line = last->line;
                st->end_col = last->col + (long)last->len;
                return 1;
            }
        }
    }
}
