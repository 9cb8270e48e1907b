/* scene_lex — card images to statements (see scene_lex.h). */
#include "scene/scene_lex.h"
#include <stdio.h>
#include <string.h>

void scene_lex_init(scene_lex *lx, const recsrc *src)
{
    lx->src = src;
    lx->recno = 0;
    lx->warn = NULL;
    lx->warn_ctx = NULL;
}

static int scene_lex_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* 1 when columns 73-80 of the card are a sequence number: all eight
 * punched, letters and digits only (a deck tag then a number, as CMS SERIAL
 * and scenes/cardseq.sh write it), ending in a digit. */
static int scene_lex_seqno(const char *rec, size_t n)
{
    size_t i;
    if (n < 80)
        return 0;
    for (i = 72; i < 80; i++) {
        unsigned char c = (unsigned char)rec[i];
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')))
            return 0;
    }
    return rec[79] >= '0' && rec[79] <= '9';
}

/* Columns 73-80 are not part of the statement, so an item running from
 * column 72 into 73 would be cut there. That is an error (at the item's
 * column) unless 73-80 hold a sequence number, which may just follow an
 * item that ends in column 72: then a warning. Returns 0 or DIAG_INPUT. */
static int scene_lex_col72(scene_lex *lx, const char *rec, size_t n, diag *err)
{
    size_t start = 71, end = 72;
    char item[81];
    diag w;
    if (n <= 72 || rec[0] == '*' || scene_lex_blank(rec[71]) || scene_lex_blank(rec[72]))
        return 0;
    while (start > 0 && !scene_lex_blank(rec[start - 1]))
        start--;
    if (scene_lex_seqno(rec, n)) {
        if (!lx->warn)
            return 0;
        diag_init(&w);
        diag_at(&w, DIAG_INPUT, lx->src->name, lx->recno, (long)start + 1,
                "item '%.*s' ends in column 72, against the sequence number '%.8s' in "
                "columns 73-80; if it was meant to be longer it has been cut (columns "
                "73-80 are not read)", (int)(72 - start), rec + start, rec + 72);
        w.status = 0;
        lx->warn(lx->warn_ctx, &w);
        return 0;
    }
    while (end < n && end < 80 && !scene_lex_blank(rec[end]))
        end++;
    snprintf(item, sizeof item, "%.*s", (int)(end - start), rec + start);
    return diag_at(err, DIAG_INPUT, lx->src->name, lx->recno, (long)start + 1,
                   "item '%s' runs past column 72 and would be cut to '%.*s' (columns "
                   "73-80 are the sequence field, not read); end it by column 72, or end "
                   "the card with ' -' and go on on the next card",
                   item, (int)(72 - start), rec + start);
}

/* 1 for a character that is part of an item: printable ASCII but blank. */
static int scene_lex_item(char c)
{
    return (unsigned char)c - 0x21u < 0x5eu;
}

/* The error for the first character of rec[from..n) outside printable
 * ASCII and tab, if there is one (DIAG_INPUT); 0 otherwise. */
static int scene_lex_bad(scene_lex *lx, const char *rec, size_t from, size_t n, diag *err)
{
    size_t i;
    for (i = from; i < n; i++)
        if (!scene_lex_item(rec[i]) && !scene_lex_blank(rec[i]))
            return diag_at(err, DIAG_INPUT, lx->src->name, lx->recno, (long)i + 1,
                           "invalid character X'%02X'", (unsigned char)rec[i]);
    return 0;
}

/* Appends the items of one card (already cut to its significant columns)
 * to st. Sets *cont when the card's last item is a lone `-`, which is then
 * not kept. Returns 0 or DIAG_INPUT, with st as it was. One pass finds the
 * items and the first character outside printable ASCII and tab, which is
 * reported before anything else the card holds. */
static int scene_lex_card(scene_lex *lx, const char *rec, size_t n,
                          scene_lex_stmt *st, int *cont, diag *err)
{
    char card[SCENE_LEX_COLUMNS + 1];     /* ends in NUL, which no item holds */
    size_t i = 0, first = st->ntok;
    *cont = 0;
    memcpy(card, rec, n);
    card[n] = '\0';
    for (;;) {
        size_t start;
        scene_lex_tok *t;
        while (scene_lex_blank(card[i]))
            i++;
        start = i;
        while (scene_lex_item(card[i]))
            i++;
        if (i < n && !scene_lex_blank(card[i])) {
            st->ntok = first;
            return scene_lex_bad(lx, card, i, n, err);
        }
        if (i == start)
            break;                        /* the end of the card */
        if (st->ntok >= SCENE_LEX_MAX_ITEMS) {
            st->ntok = first;
            if (scene_lex_bad(lx, card, i, n, err))
                return DIAG_INPUT;
            return diag_at(err, DIAG_INPUT, lx->src->name, lx->recno, (long)start + 1,
                           "statement has more than %d items", SCENE_LEX_MAX_ITEMS);
        }
        t = &st->tok[st->ntok++];
        t->line = lx->recno;
        t->col = (long)start + 1;
        t->len = i - start;
        memcpy(t->text, card + start, t->len);
        t->text[t->len] = '\0';
    }
    if (st->ntok > first && st->tok[st->ntok - 1].len == 1 && st->tok[st->ntok - 1].text[0] == '-') {
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
        if (scene_lex_col72(lx, rec, len, err))
            return -1;
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
