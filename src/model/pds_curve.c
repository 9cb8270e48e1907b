/* pds_curve — B-spline flattening and polyline simplicity (see pds_curve.h). */
#include "model/pds_curve.h"
#include <math.h>
#include <stdlib.h>
#include "util/mem.h"

/* Samples of segment i (control points i-1..i+2, indices mod n): the k of
 * pds_curve.h's bound, from the larger norm of the two second differences. */
static size_t pds_curve_samples(const double *ctl, size_t n, size_t i, double tol,
                                size_t max_per_seg)
{
    const double *p0 = ctl + 2 * ((i + n - 1) % n), *p1 = ctl + 2 * i;
    const double *p2 = ctl + 2 * ((i + 1) % n), *p3 = ctl + 2 * ((i + 2) % n);
    double m0 = hypot(p0[0] - 2 * p1[0] + p2[0], p0[1] - 2 * p1[1] + p2[1]);
    double m1 = hypot(p1[0] - 2 * p2[0] + p3[0], p1[1] - 2 * p2[1] + p3[1]);
    double m = m0 > m1 ? m0 : m1, kd = ceil(sqrt(m / (8 * tol)));
    return kd < 1 ? 1 : kd > (double)max_per_seg ? max_per_seg : (size_t)kd;
}

int pds_curve_flatten(const double *ctl, size_t n, double tol, size_t max_per_seg,
                      size_t max_total, double **out, size_t *nout)
{
    size_t i, total = 0, pos = 0;
    double *pts;
    /* First pass: sample counts, so the allocation is exact and bounded. */
    for (i = 0; i < n; i++) {
        size_t k = pds_curve_samples(ctl, n, i, tol, max_per_seg);
        if (k > max_total - total)
            return -1;
        total += k;
    }
    pts = mem_calloc(total, 2 * sizeof *pts);
    if (!pts)
        return -2;
    for (i = 0; i < n; i++) {
        const double *p0 = ctl + 2 * ((i + n - 1) % n), *p1 = ctl + 2 * i;
        const double *p2 = ctl + 2 * ((i + 1) % n), *p3 = ctl + 2 * ((i + 2) % n);
        size_t k = pds_curve_samples(ctl, n, i, tol, max_per_seg), s;
        for (s = 0; s < k; s++) {
            /* Uniform cubic B-spline basis at t (segment start included,
             * end excluded: the next segment starts there). */
            double t = (double)s / (double)k, t2 = t * t, t3 = t2 * t;
            double b0 = (1 - 3 * t + 3 * t2 - t3) / 6, b1 = (4 - 6 * t2 + 3 * t3) / 6;
            double b2 = (1 + 3 * t + 3 * t2 - 3 * t3) / 6, b3 = t3 / 6;
            pts[2 * pos] = b0 * p0[0] + b1 * p1[0] + b2 * p2[0] + b3 * p3[0];
            pts[2 * pos + 1] = b0 * p0[1] + b1 * p1[1] + b2 * p2[1] + b3 * p3[1];
            pos++;
        }
    }
    *out = pts;
    *nout = total;
    return 0;
}

double pds_curve_area2(const double *pts, size_t n)
{
    double a = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        const double *p = pts + 2 * i, *q = pts + 2 * ((i + 1) % n);
        a += p[0] * q[1] - q[0] * p[1];
    }
    return a;
}

static double pds_curve_orient(const double *a, const double *b, const double *c)
{
    double d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

/* c lies within the bounding box of segment ab (used when collinear). */
static int pds_curve_within(const double *a, const double *b, const double *c)
{
    return fmin(a[0], b[0]) <= c[0] && c[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= c[1] && c[1] <= fmax(a[1], b[1]);
}

/* Closed segments ab and cd share at least one point. */
static int pds_curve_touch(const double *a, const double *b, const double *c, const double *d)
{
    double o1 = pds_curve_orient(a, b, c), o2 = pds_curve_orient(a, b, d);
    double o3 = pds_curve_orient(c, d, a), o4 = pds_curve_orient(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1;
    return (o1 == 0 && pds_curve_within(a, b, c)) || (o2 == 0 && pds_curve_within(a, b, d)) ||
           (o3 == 0 && pds_curve_within(c, d, a)) || (o4 == 0 && pds_curve_within(c, d, b));
}

typedef struct edge_key { double lo; size_t i; } edge_key;

static int pds_curve_edge_cmp(const void *a, const void *b)
{
    const edge_key *x = a, *y = b;
    if (x->lo != y->lo)
        return x->lo < y->lo ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

static void pds_curve_report(size_t a, size_t b, size_t *ea, size_t *eb)
{
    *ea = a < b ? a : b;
    *eb = a < b ? b : a;
}

int pds_curve_simple(const double *pts, size_t n, size_t *ea, size_t *eb)
{
    edge_key *keys;
    size_t *active, nactive = 0, k, i;
    unsigned long budget = PDS_CURVE_PAIR_BUDGET;
    /* Adjacent edges meet at their shared vertex; they must not fold back. */
    for (i = 0; i < n; i++) {
        const double *a = pts + 2 * i, *b = pts + 2 * ((i + 1) % n), *c = pts + 2 * ((i + 2) % n);
        if (pds_curve_orient(a, b, c) == 0 &&
            (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]) > 0) {
            pds_curve_report(i, (i + 1) % n, ea, eb);
            return 0;
        }
    }
    keys = mem_calloc(n, sizeof *keys);
    active = mem_calloc(n, sizeof *active);
    if (!keys || !active) {
        mem_free(keys);
        mem_free(active);
        return -2;
    }
    for (i = 0; i < n; i++) {
        keys[i].lo = fmin(pts[2 * i], pts[2 * ((i + 1) % n)]);
        keys[i].i = i;
    }
    qsort(keys, n, sizeof *keys, pds_curve_edge_cmp);
    for (k = 0; k < n; k++) {
        size_t e = keys[k].i, j, kept = 0;
        const double *a = pts + 2 * e, *b = pts + 2 * ((e + 1) % n);
        if (nactive > budget) {
            mem_free(keys);
            mem_free(active);
            return -3;
        }
        budget -= nactive;
        for (j = 0; j < nactive; j++) {
            size_t f = active[j];
            const double *c = pts + 2 * f, *d = pts + 2 * ((f + 1) % n);
            if (fmax(c[0], d[0]) < keys[k].lo)
                continue;                        /* left of the sweep: retire */
            active[kept++] = f;
            if ((f + 1) % n == e || (e + 1) % n == f)
                continue;                        /* adjacent: checked above */
            if (pds_curve_touch(a, b, c, d)) {
                pds_curve_report(e, f, ea, eb);
                mem_free(keys);
                mem_free(active);
                return 0;
            }
        }
        nactive = kept;
        active[nactive++] = e;
    }
    mem_free(keys);
    mem_free(active);
    return 1;
}
