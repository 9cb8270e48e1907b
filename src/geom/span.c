/* span — set operations on span lists by a sweep over boundaries (see span.h). */
#include "geom/span.h"

/* Result membership for the operator given operand memberships. */
static inline int span_op(int op, int ina, int inb)
{
    switch (op) {
    case CSG_UNION: return ina || inb;
    case CSG_INTER: return ina && inb;
    default:        return ina && !inb;
    }
}

/* A list's cursor is the number p of its ends consumed (0 .. 2n): even,
 * the next end is the entry of span p/2; odd, its exit, and the sweep is
 * inside that span. */
static inline const span_end *span_end_at(const span *l, int p)
{
    return p & 1 ? &l[p >> 1].b : &l[p >> 1].a;
}

/* Consumes every end of list l (n spans) at parameters up to lim, moving
 * the cursor *p; returns the last consumed end (NULL if none). A span of l
 * shorter than the window is entered and left in one step: it vanishes. */
static inline const span_end *span_take(const span *l, int n, int *p, num lim)
{
    const span_end *e = NULL;
    int k = *p;
    /* the first two steps written out: all a list of one span can take,
     * which the compiler then sees (span_merge's one-against-one sweep) */
    if (k < 2 * n && span_end_at(l, k)->t <= lim) {
        e = span_end_at(l, k++);
        if (k < 2 * n && span_end_at(l, k)->t <= lim) {
            e = span_end_at(l, k++);
            while (k < 2 * n && span_end_at(l, k)->t <= lim)
                e = span_end_at(l, k++);
        }
    }
    *p = k;
    return e;
}

/* The sweep, inlined by span_merge for any lengths and, for one span
 * against one (two convex operands, most merges), once per operator:
 * there the lengths and the operator are constants, each take is at most
 * two steps and the membership a fixed expression. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int span_sweep(int op, const span *a, int na, const span *b, int nb, span *out)
{
    int pa = 0, pb = 0, inr = 0, n = 0;
    while (pa < 2 * na || pb < 2 * nb) {
        num t, lim;
        const span_end *ea, *eb, *e;
        int now;
        if (pa >= 2 * na)
            t = span_end_at(b, pb)->t;
        else if (pb >= 2 * nb)
            t = span_end_at(a, pa)->t;
        else
            t = num_min(span_end_at(a, pa)->t, span_end_at(b, pb)->t);
        /* boundaries of the two lists closer than the error bound are one
         * boundary (regularised CSG: no slivers thinner than the bound) */
        lim = span_lim(t);
        ea = span_take(a, na, &pa, lim);
        eb = span_take(b, nb, &pb, lim);
        now = span_op(op, pa & 1, pb & 1);
        if (now == inr)
            continue;
        /* Coincident boundaries: keep the lower primitive id (deterministic,
         * independent of operand order); unbounded ends lose. */
        if (ea && eb)
            e = (eb->prim >= 0 && (ea->prim < 0 || eb->prim < ea->prim)) ? eb : ea;
        else
            e = ea ? ea : eb;
        if (now)
            span_end_copy(&out[n].a, e);
        else
            span_end_copy(&out[n++].b, e);
        inr = now;
    }
    return n;
}

int NS(span_merge)(int op, const span *a, int na, const span *b, int nb, span *out)
{
    if (na == 1 && nb == 1) {     /* the operator a constant too */
        if (op == CSG_UNION)
            return span_sweep(CSG_UNION, a, 1, b, 1, out);
        if (op == CSG_INTER)
            return span_sweep(CSG_INTER, a, 1, b, 1, out);
        return span_sweep(CSG_DIFF, a, 1, b, 1, out);
    }
    return span_sweep(op, a, na, b, nb, out);
}
