/* span — in/out intervals of a solid along a ray, and their set operations
 * (Roth 1982). A span [a.t, b.t) is half-open: a ray point at parameter t is
 * inside when a.t <= t < b.t. Exactly coincident boundaries of different
 * solids therefore cancel in a difference and merge in a union. Each end
 * names the primitive and face it lies on, so the nearest hit can be shaded.
 * Modal: compiled per numeric mode. */
#ifndef GEOM_SPAN_H
#define GEOM_SPAN_H
#include "num/num.h"
#include "model/scene.h"

typedef struct span_end {
    num t;
    int prim;          /* primitive index, -1 for an unbounded end */
    int face;          /* face id (geom.h), PRIM_FACE_NONE for an unbounded end */
} span_end;

typedef struct span {
    span_end a, b;     /* entry and exit; a.t < b.t */
} span;

/* *d = *s field by field. The tests store an end's fields one by one; a
 * struct copy soon after loads them as one wider piece, which no single
 * store can forward: the load waits until the stores retire (some 15
 * cycles a copy on a hot path). */
static inline void span_end_copy(span_end *d, const span_end *s)
{
    d->t = s->t;
    d->prim = s->prim;
    d->face = s->face;
}

/* Combines the sorted, disjoint, non-touching span lists a (na spans) and b
 * (nb spans) by op (CSG_UNION, CSG_INTER or CSG_DIFF = a minus b) into out,
 * which must hold na + nb spans; returns the number written. The result is
 * sorted, disjoint and non-touching. Regularised: boundaries within the
 * mode's error bound of the earliest pending one (docs/numerics.md) are
 * taken as one boundary, so no span thinner than the bound is created or
 * kept. Of coincident boundaries the end of the lower-numbered primitive
 * is kept, so the result does not depend on the order of union operands. */
int NS(span_merge)(int op, const span *a, int na, const span *b, int nb, span *out);
#endif
