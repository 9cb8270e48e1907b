/* scene_cur — item cursor and operand checks for scene statements
 * (see scene_cur.h). */
#include "scene/scene_cur.h"
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Words of the language that cannot be names, so that an operand list such
 * as "A TRANSLATE 1 0 0 B" has exactly one reading. Sorted (strcmp order)
 * for the binary search. */
static const char *const scene_cur_words[] = {
    "AMBIENT", "AMPLITUDE", "ATTR", "AXIS", "BACKGROUND", "BLINN", "BLOCK",
    "BRICK", "BSPLINE", "BUMP", "BUMPS", "CIRCLE", "CODE", "COLOR", "CONE",
    "CPG", "CURVES", "CYCLE", "CYLINDER", "DEPTH", "DIFF", "DIFFERENCE",
    "DIFFUSE", "DIMPLES", "ELLIPSE", "END", "EXPONENT", "EYE", "FACE", "FOV",
    "FREQUENCY", "GROOVES", "HALFSPACE", "HASH", "HEX", "IMAGE", "INDEX",
    "INF", "INFINITY", "INTENSITY", "INTER", "INTERSECT", "INTERSECTION",
    "IOR", "KEY", "LAMBERT", "LIGHT", "LOCAL", "LOOK", "LOOKAT", "MATRIX",
    "MIRROR", "MODEL", "MORTAR", "MOSAIC", "NAN", "NEST", "NOISE", "NONE",
    "OBJECT", "OFFSET", "PDS", "PHONG", "PIXELS", "POLYGON", "POLYLINE",
    "QUADTREE", "RECT", "REPEAT", "ROOT", "ROTATE", "ROW", "SCALE", "SCATTER",
    "SEED", "SHEAR", "SIZE", "SPECULAR", "SPHERE", "SPLIT", "SQUARE", "STRIPS",
    "TEXTURE", "TILES", "TILING", "TOLERANCE", "TRANSLATE", "TRANSMIT",
    "TRANSPARENT", "TRIANGLE", "UNION", "UP", "WAVES", "WIDTH"
};

/* A binary search whose probes compare first letters before calling
 * strcmp: most probes of a name differ from the word there at once. */
int scene_cur_reserved(const char *word)
{
    size_t lo = 0, hi = sizeof scene_cur_words / sizeof scene_cur_words[0];
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const char *w = scene_cur_words[mid];
        int d = (unsigned char)word[0] - (unsigned char)w[0];
        if (d == 0)
            d = strcmp(word, w);
        if (d == 0)
            return 1;
        if (d < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return 0;
}

void scene_cur_init(scene_cur *c, const scene_lex_stmt *st, const char *file,
                    const char *what, diag *err)
{
    c->st = st;
    c->pos = 1;               /* item 0 is the keyword */
    c->file = file;
    c->what = what;
    c->err = err;
}

const scene_lex_tok *scene_cur_peek(const scene_cur *c)
{
    return c->pos < c->st->ntok ? &c->st->tok[c->pos] : NULL;
}

int scene_cur_at_end(const scene_cur *c)
{
    return c->pos >= c->st->ntok;
}

/* Items are printable ASCII (scene_lex) and the parser runs in the C
 * locale, where toupper changes only a-z; this is that, without the call. */
static unsigned char scene_cur_upper(unsigned char ch)
{
    return ch >= 'a' && ch <= 'z' ? (unsigned char)(ch - 'a' + 'A') : ch;
}

int scene_cur_is(const scene_lex_tok *t, const char *keyword)
{
    size_t i;
    if (!t)
        return 0;
    for (i = 0; i < t->len; i++)
        if (scene_cur_upper((unsigned char)t->text[i]) != (unsigned char)keyword[i])
            return 0;
    return keyword[i] == '\0';
}

int scene_cur_accept(scene_cur *c, const char *keyword)
{
    if (!scene_cur_is(scene_cur_peek(c), keyword))
        return 0;
    c->pos++;
    return 1;
}

int scene_cur_numeric(const scene_lex_tok *t)
{
    char ch = t ? t->text[0] : '\0';
    return isdigit((unsigned char)ch) || ch == '+' || ch == '-' || ch == '.';
}

int scene_cur_error(scene_cur *c, const scene_lex_tok *t, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (t)
        return diag_at(c->err, DIAG_INPUT, c->file, t->line, t->col, "%s: %s", c->what, msg);
    return diag_at(c->err, DIAG_INPUT, c->file, c->st->end_line, c->st->end_col,
                   "%s: %s", c->what, msg);
}

/* 1 if the item spells NaN or infinity the way strtod would accept it. */
static int scene_cur_nonfinite(const scene_lex_tok *t)
{
    scene_lex_tok u;
    if (!isalpha((unsigned char)t->text[t->text[0] == '+' || t->text[0] == '-']))
        return 0;                         /* those are words: not a number's digits */
    u = *t;
    if (u.text[0] == '+' || u.text[0] == '-') {
        memmove(u.text, u.text + 1, u.len);
        u.len--;
    }
    return scene_cur_is(&u, "NAN") || scene_cur_is(&u, "INF") ||
           scene_cur_is(&u, "INFINITY");
}

/* Reads the run of digits at s into *m (times ten per digit, plus it) and
 * counts them in *n; clears *fast when *m would reach 2^53. Returns the
 * end of the run. */
static const char *scene_cur_digits(const char *s, uint64_t *m, int *n, int *fast)
{
    unsigned d;
    for (; (d = (unsigned)(*s - '0')) < 10; s++, ++*n) {
        if (*m >= ((uint64_t)1 << 53) / 10)
            *fast = 0;
        *m = *m * 10 + d;
    }
    return s;
}

/* Reads s, in one pass, as [+-] digits [. digits] [E [+-] digits] with a
 * digit in the mantissa (a leading or trailing '.' is allowed: ".5", "2.").
 * 0 if s is not written so. Else 1 with *v the value when s has no
 * exponent, its digits make an integer below 2^53 and at most 22 are
 * fractional: the integer and the power of ten are then exact doubles, and
 * their quotient, rounded once to nearest, is the correctly rounded value
 * strtod returns (Clinger's fast path, about a tenth of strtod's work);
 * 2 when only strtod can convert it. */
static int scene_cur_scan(const char *s, double *v)
{
#if FLT_EVAL_METHOD == 0
    static const double p10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                   1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    int fast = 1;
#else                                     /* wider evaluation could round twice */
    int fast = 0;
#endif
    uint64_t m = 0;
    int neg = *s == '-', digits = 0, frac = 0;
    if (*s == '+' || *s == '-')
        s++;
    s = scene_cur_digits(s, &m, &digits, &fast);
    if (*s == '.') {
        s = scene_cur_digits(s + 1, &m, &frac, &fast);
        digits += frac;
    }
    if (!digits)
        return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        if ((unsigned)(*s - '0') >= 10)
            return 0;
        while ((unsigned)(*s - '0') < 10)
            s++;
        fast = 0;
    }
    if (*s != '\0')
        return 0;
#if FLT_EVAL_METHOD == 0
    if (fast && frac <= 22) {
        *v = (double)m / p10[frac];
        if (neg)
            *v = -*v;
        return 1;
    }
#endif
    return 2;
}

/* Reads the next item as a number, without a magnitude check (a value
 * too large for a double is infinite); *at receives the item. */
static int scene_cur_value(scene_cur *c, double *v, const scene_lex_tok **at)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    int r;
    *at = t;
    *v = 0;
    if (!t)
        return scene_cur_error(c, NULL, "missing number");
    r = scene_cur_scan(t->text, v);
    if (r == 0) {                         /* NaN and Inf are never a number's syntax */
        if (scene_cur_nonfinite(t))
            return scene_cur_error(c, t, "%s is not a finite number", t->text);
        return scene_cur_error(c, t, "expected a number, found %s", t->text);
    }
    if (r == 2)
        *v = strtod(t->text, NULL);   /* syntax checked: always converts fully */
    c->pos++;
    return 0;
}

static int scene_cur_too_big(scene_cur *c, const scene_lex_tok *t)
{
    return scene_cur_error(c, t, "%s is out of range (magnitude above 1e6)", t->text);
}

int scene_cur_number(scene_cur *c, double *v, const scene_lex_tok **at)
{
    const scene_lex_tok *t;
    double d;
    int r = scene_cur_value(c, &d, &t);
    if (at)
        *at = t;
    if (r)
        return r;
    if (!(fabs(d) <= SCENE_CUR_MAX_ABS)) {
        c->pos--;             /* not consumed, as for the other errors */
        scene_cur_too_big(c, t);
        return DIAG_INPUT;
    }
    *v = d;
    return 0;
}

int scene_cur_numbers(scene_cur *c, double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (scene_cur_number(c, &v[i], NULL))
            return DIAG_INPUT;
    return 0;
}

int scene_cur_int(scene_cur *c, const char *label, long lo, long hi, long *v)
{
    const scene_lex_tok *t;
    double d;
    if (scene_cur_value(c, &d, &t))
        return DIAG_INPUT;
    /* A range wider than 1e6 (seeds) replaces the general magnitude limit. */
    if (!(fabs(d) <= SCENE_CUR_MAX_ABS) && lo >= -SCENE_CUR_MAX_ABS && hi <= SCENE_CUR_MAX_ABS)
        return scene_cur_too_big(c, t);
    if (d != floor(d) || d < (double)lo || d > (double)hi)
        return scene_cur_error(c, t, "%s must be a whole number from %ld to %ld",
                               label, lo, hi);
    *v = (long)d;
    return 0;
}

int scene_cur_range(scene_cur *c, const char *label, double lo, double hi, double *v)
{
    const scene_lex_tok *t;
    double d;
    if (scene_cur_number(c, &d, &t))
        return DIAG_INPUT;
    if (d < lo || d > hi)
        return scene_cur_error(c, t, "%s must be between %g and %g", label, lo, hi);
    *v = d;
    return 0;
}

static int scene_cur_namechar(char ch)
{
    return isalnum((unsigned char)ch) || ch == '_' || ch == '$' || ch == '#' || ch == '@';
}

int scene_cur_name(scene_cur *c, char out[SCENE_NAME_MAX + 1], const scene_lex_tok **at)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    char up[SCENE_LEX_COLUMNS + 1];
    size_t i;
    if (at)
        *at = t;
    if (!t)
        return scene_cur_error(c, NULL, "missing name");
    for (i = 0; i < t->len; i++) {
        if (!scene_cur_namechar(t->text[i]))
            break;
        up[i] = (char)scene_cur_upper((unsigned char)t->text[i]);
    }
    up[i < t->len ? 0 : t->len] = '\0';
    if (i < t->len || !isalpha((unsigned char)t->text[0]))
        return scene_cur_error(c, t, "bad name %s (a letter, then letters, digits or _ $ # @)",
                               t->text);
    if (t->len > SCENE_NAME_MAX)
        return scene_cur_error(c, t, "name %s is longer than %d characters",
                               t->text, SCENE_NAME_MAX);
    if (scene_cur_reserved(up))
        return scene_cur_error(c, t, "%s is a reserved word, not a name", t->text);
    memcpy(out, up, t->len + 1);
    c->pos++;
    return 0;
}

int scene_cur_choice(scene_cur *c, const char *const *words, int *index)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    char list[300] = "";
    size_t len = 0;
    int i, n;
    for (n = 0; words[n]; n++)
        if (scene_cur_is(t, words[n])) {
            *index = n;
            c->pos++;
            return 0;
        }
    for (i = 0; i < n && len < sizeof list; i++)
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
                                i == 0 ? "" : i == n - 1 ? " or " : ", ", words[i]);
    if (!t)
        return scene_cur_error(c, NULL, "missing %s", list);
    return scene_cur_error(c, t, "expected %s, found %s", list, t->text);
}

int scene_cur_finish(scene_cur *c)
{
    const scene_lex_tok *t = scene_cur_peek(c);
    if (t)
        return scene_cur_error(c, t, "extra operand %s", t->text);
    return 0;
}
