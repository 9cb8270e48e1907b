/* span — set operations on span lists by a sweep over boundaries (see span.h). */
#include "geom/span.h"

/* The mode's error bound on a span end at parameter t (normalised units),
 * eps(t) = E0 (1 + |t|/16): the bound docs/numerics.md states for a ray
 * parameter, in normalised rather than deck units. */
#if defined(NUM_MODE_q16)
#define SPAN_E0 ((num)32)                  /* 2^-11 */
#define SPAN_E1 ((num)2)
#elif defined(NUM_MODE_q32)
#define SPAN_E0 ((num)64)                  /* 2^-26 */
#define SPAN_E1 ((num)4)
#elif defined(NUM_MODE_f32)
#define SPAN_E0 (1.0f / 65536)             /* 2^-16 */
#define SPAN_E1 (1.0f / 1048576)
#else
#define SPAN_E0 (1.0 / 68719476736.0)      /* 2^-36 */
#define SPAN_E1 (1.0 / 1099511627776.0)
#endif

static inline num span_eps(num t) { return num_add(SPAN_E0, num_mul(num_abs(t), SPAN_E1)); }

/* Result membership for the operator given operand memberships. */
static inline int span_op(int op, int ina, int inb)
{
    switch (op) {
    case CSG_UNION: return ina || inb;
    case CSG_INTER: return ina && inb;
    default:        return ina && !inb;
    }
}

/* Parameter of the next boundary of list l at cursor i with state in. */
static inline num span_next_t(const span *l, int i, int in)
{
    return in ? l[i].b.t : l[i].a.t;
}

/* Consumes every boundary of list l at parameters up to lim, updating the
 * cursor and state; returns the last consumed end (NULL if none). A span of
 * l shorter than the window is entered and left in one step: it vanishes. */
static inline const span_end *span_take(const span *l, int n, int *i, int *in, num lim)
{
    const span_end *e = NULL;
    while (*i < n && span_next_t(l, *i, *in) <= lim) {
        if (*in) {
            e = &l[*i].b;
            *in = 0;
            (*i)++;
        } else {
            e = &l[*i].a;
            *in = 1;
        }
    }
    return e;
}

int NS(span_merge)(int op, const span *a, int na, const span *b, int nb, span *out)
{
    int i = 0, j = 0, ina = 0, inb = 0, inr = 0, n = 0;
    while (i < na || j < nb) {
        num t, lim;
        const span_end *ea, *eb, *e;
        int now;
        if (i >= na)
            t = span_next_t(b, j, inb);
        else if (j >= nb)
            t = span_next_t(a, i, ina);
        else
            t = num_min(span_next_t(a, i, ina), span_next_t(b, j, inb));
        /* boundaries of the two lists closer than the error bound are one
         * boundary (regularised CSG: no slivers thinner than the bound) */
        lim = num_add(t, span_eps(t));
        ea = span_take(a, na, &i, &ina, lim);
        eb = span_take(b, nb, &j, &inb, lim);
        now = span_op(op, ina, inb);
        if (now == inr)
            continue;
        /* Coincident boundaries: keep the lower primitive id (deterministic,
         * independent of operand order); unbounded ends lose. */
        if (ea && eb)
            e = (eb->prim >= 0 && (ea->prim < 0 || eb->prim < ea->prim)) ? eb : ea;
        else
            e = ea ? ea : eb;
        if (now)
            out[n].a = *e;
        else
            out[n++].b = *e;
        inr = now;
    }
    return n;
}
