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
#elif defined(NUM_MODE_hfp32)                /* order keys: the images */
#define SPAN_E0 ((num)0x3d800000)           /* 2^-13 = 0.8 x 16^-3 */
#define SPAN_E1 ((num)0x3c800000)           /* 2^-17 */
#elif defined(NUM_MODE_hfp64)
#define SPAN_E0 ((num)0x3810000000000000)   /* 2^-36 = 0.1 x 16^-8 */
#define SPAN_E1 ((num)0x3710000000000000)   /* 2^-40 */
#else
#define SPAN_E0 (1.0 / 68719476736.0)      /* 2^-36 */
#define SPAN_E1 (1.0 / 1099511627776.0)
#endif

static inline num span_eps(num t) { return num_add(SPAN_E0, num_mul(num_abs(t), SPAN_E1)); }
/* The last parameter a sweep step at boundary t takes with it: every end
 * in [t, span_lim(t)] is one boundary (span_merge). */
static inline num span_lim(num t) { return num_add(t, span_eps(t)); }
/* The window about t inside which an end of another operand could join
 * t's sweep step or a step before it: w = 2 eps(t) + E0 (csg_diff_first,
 * docs/numerics.md "Culling in binary64"). */
static inline num span_win(num t) { return num_add(num_add(span_eps(t), span_eps(t)), span_eps(NUM_ZERO)); }

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
