/* suggest — nearest-candidate search for "did you mean" (see suggest.h). */
#include "util/suggest.h"
#include <ctype.h>
#include <string.h>

int suggest_distance(const char *a, const char *b, size_t n)
{
    /* optimal string alignment distance over three rolling rows */
    int rows[3][SUGGEST_MAX_LEN + 1];
    size_t la = strlen(a), lb = n ? n : strlen(b), i, j;
    if (la > SUGGEST_MAX_LEN || lb > SUGGEST_MAX_LEN)
        return SUGGEST_MAX_LEN + 1;
    for (j = 0; j <= lb; j++)
        rows[0][j] = (int)j;
    for (i = 1; i <= la; i++) {
        int *cur = rows[i % 3], *prev = rows[(i + 2) % 3], *prev2 = rows[(i + 1) % 3];
        cur[0] = (int)i;
        for (j = 1; j <= lb; j++) {
            int ca = tolower((unsigned char)a[i - 1]), cb = tolower((unsigned char)b[j - 1]);
            int d = prev[j - 1] + (ca != cb);
            if (prev[j] + 1 < d)
                d = prev[j] + 1;
            if (cur[j - 1] + 1 < d)
                d = cur[j - 1] + 1;
            if (i > 1 && j > 1 && ca == tolower((unsigned char)b[j - 2])
                && tolower((unsigned char)a[i - 2]) == cb && prev2[j - 2] + 1 < d)
                d = prev2[j - 2] + 1;
            cur[j] = d;
        }
    }
    return rows[la % 3][lb];
}

void suggest_init(suggest *s, const char *word)
{
    s->word = word;
    s->best = NULL;
    s->best_len = 0;
    s->best_dist = SUGGEST_MAX_LEN + 1;
}

void suggest_try(suggest *s, const char *cand, size_t n)
{
    int d = suggest_distance(s->word, cand, n);
    if (d < s->best_dist) {
        s->best = cand;
        s->best_len = n ? n : strlen(cand);
        s->best_dist = d;
    }
}

const char *suggest_best(const suggest *s)
{
    int limit = (int)strlen(s->word) / 3;
    if (limit < 1)
        limit = 1;
    return s->best && s->best_dist <= limit ? s->best : NULL;
}
