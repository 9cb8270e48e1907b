/* suggest — "did you mean" for a mistyped word: the candidate nearest to it
 * by edit distance (insertions, deletions, substitutions and transpositions,
 * case-insensitive), if near enough to be a likely typo. Used for unknown
 * command-line options and unknown deck keywords. */
#ifndef SUGGEST_H
#define SUGGEST_H
#include <stddef.h>

#define SUGGEST_MAX_LEN 64   /* longer words and candidates are not compared */

typedef struct suggest {
    const char *word;
    const char *best;         /* the nearest candidate so far, or NULL */
    size_t best_len;          /* its length */
    int best_dist;
} suggest;

void suggest_init(suggest *s, const char *word);
/* Offers one candidate (its first n bytes; n = 0 means the whole string). */
void suggest_try(suggest *s, const char *cand, size_t n);
/* The nearest candidate (best_len bytes) within max(1, length/3) edits, else NULL. */
const char *suggest_best(const suggest *s);
/* The case-insensitive distance between a and b (first n bytes of b, 0 = all). */
int suggest_distance(const char *a, const char *b, size_t n);
#endif
