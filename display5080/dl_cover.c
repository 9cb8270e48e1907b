/* dl_cover — shape rasterisation into runs (see dl_cover.h). */
#include "display5080/dl_cover.h"
#include "util/mem.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void dl_cover_init(dl_cover *c, dl_work *work)
{
    memset(c, 0, sizeof *c);
    c->work = work;
}

void dl_cover_free(dl_cover *c)
{
    mem_free(c->runs);
    mem_free(c->xs);
    c->runs = NULL;
    c->xs = NULL;
    c->n = c->cap = c->xs_cap = 0;
}

void dl_cover_start(dl_cover *c, int cx0, int cy0, int cx1, int cy1)
{
    c->cx0 = cx0;
    c->cy0 = cy0;
    c->cx1 = cx1;
    c->cy1 = cy1;
    c->n = 0;
}

/* Charges n steps to the budget; 0 once it is exhausted (status set). */
static int dl_cover_charge(dl_cover *c, unsigned long long n)
{
    if (c->status)
        return 0;
    if (!dl_work_charge(c->work, n)) {
        c->status = DIAG_INPUT;
        return 0;
    }
    return 1;
}

void dl_cover_span(dl_cover *c, long long y, long long x0, long long x1)
{
    void *p = c->runs;
    dl_box *b;
    if (c->status || y < c->cy0 || y > c->cy1)
        return;
    if (x0 < c->cx0) x0 = c->cx0;
    if (x1 > c->cx1) x1 = c->cx1;
    if (x1 < x0)
        return;
    if (c->n == c->cap && mem_grow(&p, &c->cap, c->n + 1, sizeof *b)) {
        c->status = DIAG_IO;
        return;
    }
    c->runs = p;
    b = &c->runs[c->n++];
    b->x0 = (int)x0;
    b->x1 = (int)x1;
    b->y0 = b->y1 = (int)y;
}

/* One pixel of a line under the pen: the pattern decides, the brush widens. */
static void dl_cover_dot(dl_cover *c, long long x, long long y, dl_pen *pen)
{
    unsigned bit = (unsigned)((pen->pos / pen->factor) % 16u);
    long long lo = -(long long)((pen->width - 1) / 2), hi = pen->width / 2, k;
    pen->pos++;
    if (!(pen->pattern >> bit & 1u))
        return;
    if (pen->width == 1) {
        dl_cover_span(c, y, x, x);
        return;
    }
    if (!dl_cover_charge(c, pen->width))
        return;
    for (k = lo; k <= hi; k++)
        dl_cover_span(c, y + k, x + lo, x + hi);
}

void dl_cover_line(dl_cover *c, int x0, int y0, int x1, int y1, dl_pen *pen, int skip_first)
{
    long long x = x0, y = y0;
    long long dx = llabs((long long)x1 - x0), dy = -llabs((long long)y1 - y0);
    long long sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, e = dx + dy;
    int first = 1;
    if (!dl_cover_charge(c, (unsigned long long)(dx > -dy ? dx : -dy) + 1))
        return;
    for (;;) {
        long long e2 = 2 * e;
        if (!(first && skip_first))
            dl_cover_dot(c, x, y, pen);
        first = 0;
        if (c->status || (x == x1 && y == y1))
            break;
        if (e2 >= dy) {
            e += dy;
            x += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y += sy;
        }
    }
}

/* floor(sqrt(v)) exactly. */
static long long dl_cover_isqrt(long long v)
{
    long long s = (long long)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    return s;
}

void dl_cover_circle(dl_cover *c, int cx, int cy, unsigned rad, int fill)
{
    long long rr = (long long)rad * rad;
    if (fill) {
        long long dy, lo = (long long)c->cy0 - cy, hi = (long long)c->cy1 - cy;
        if (lo < -(long long)rad) lo = -(long long)rad;
        if (hi > (long long)rad) hi = (long long)rad;
        for (dy = lo; dy <= hi && dl_cover_charge(c, 1); dy++) {
            long long hw = dl_cover_isqrt(rr - dy * dy);
            dl_cover_span(c, cy + dy, cx - hw, cx + hw);
        }
    } else {
        /* Midpoint circle over one octant, mirrored 8 ways. */
        long long x = 0, y = rad, d = 1 - (long long)rad;
        if (!dl_cover_charge(c, rad + 1ull))
            return;
        while (x <= y) {
            const long long px[8][2] = {{x, y}, {-x, y}, {x, -y}, {-x, -y},
                                        {y, x}, {-y, x}, {y, -x}, {-y, -x}};
            int k;
            for (k = 0; k < 8; k++)
                dl_cover_span(c, cy + px[k][1], cx + px[k][0], cx + px[k][0]);
            x++;
            if (d < 0) {
                d += 2 * x + 1;
            } else {
                y--;
                d += 2 * (x - y) + 1;
            }
        }
    }
}

static int dl_cover_int_cmp(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Ceiling of n / d for d > 0. */
static long long dl_cover_ceil_div(long long n, long long d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); }

void dl_cover_polygon(dl_cover *c, const int *xy, size_t n, int closed)
{
    int ymin = 32767, ymax = -32768, y;
    size_t i;
    void *xs = c->xs;
    for (i = 0; i < n; i++) {
        if (xy[2 * i + 1] < ymin) ymin = xy[2 * i + 1];
        if (xy[2 * i + 1] > ymax) ymax = xy[2 * i + 1];
    }
    if (ymin < c->cy0) ymin = c->cy0;
    if (ymax > c->cy1) ymax = c->cy1;
    if (n > c->xs_cap && mem_grow(&xs, &c->xs_cap, n, sizeof(int))) {
        c->status = DIAG_IO;
        return;
    }
    c->xs = xs;
    for (y = ymin; y <= ymax && dl_cover_charge(c, n); y++) {
        size_t k = 0, m;
        for (i = 0; i < n; i++) {
            size_t j = (i + 1) % n;
            long long xa = xy[2 * i], ya = xy[2 * i + 1], xb = xy[2 * j], yb = xy[2 * j + 1];
            if (ya > yb) {
                long long t = xa; xa = xb; xb = t;
                t = ya; ya = yb; yb = t;
            }
            /* closed: pixel centres on the boundary belong to the polygon */
            if (closed && ya == yb && y == ya)
                dl_cover_span(c, y, xa < xb ? xa : xb, xa < xb ? xb : xa);
            if (closed && ya < yb && y >= ya && y <= yb && (y - ya) * (xb - xa) % (yb - ya) == 0)
                dl_cover_span(c, y, xa + (y - ya) * (xb - xa) / (yb - ya),
                              xa + (y - ya) * (xb - xa) / (yb - ya));
            if (ya == yb || y < ya || y >= yb)
                continue;
            /* first pixel centre at or right of the crossing */
            c->xs[k++] = (int)(xa + dl_cover_ceil_div((y - ya) * (xb - xa), yb - ya));
        }
        qsort(c->xs, k, sizeof(int), dl_cover_int_cmp);
        for (m = 0; m + 1 < k; m += 2)
            dl_cover_span(c, y, c->xs[m], (long long)c->xs[m + 1] - 1);
    }
}

static int dl_cover_run_cmp(const void *a, const void *b)
{
    const dl_box *p = a, *q = b;
    if (p->y0 != q->y0)
        return (p->y0 > q->y0) - (p->y0 < q->y0);
    return (p->x0 > q->x0) - (p->x0 < q->x0);
}

size_t dl_cover_finish(dl_cover *c, const dl_box **boxes)
{
    size_t i, m = 0;
    *boxes = c->runs;
    if (c->status || c->n == 0)
        return 0;
    qsort(c->runs, c->n, sizeof *c->runs, dl_cover_run_cmp);
    for (i = 0; i < c->n; i++) {
        dl_box *r = &c->runs[i];
        if (m && c->runs[m - 1].y0 == r->y0 && r->x0 <= c->runs[m - 1].x1 + 1) {
            if (r->x1 > c->runs[m - 1].x1)
                c->runs[m - 1].x1 = r->x1;
        } else {
            c->runs[m++] = *r;
        }
    }
    c->n = m;
    return m;
}
