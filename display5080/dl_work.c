/* dl_work — drawing costs and the budget (see dl_work.h). */
#include "display5080/dl_work.h"

void dl_work_init(dl_work *w, unsigned long long limit)
{
    w->used = 0;
    w->limit = limit ? limit : DL_WORK_LIMIT;
}

int dl_work_charge(dl_work *w, unsigned long long n, const char *name, long long offset, diag *err)
{
    w->used += n;
    if (w->used > w->limit || w->used < n)
        return diag_offset(err, DIAG_INPUT, name, offset, "drawing work limit of %llu pixel steps exceeded",
                           w->limit);
    return 0;
}

/* Length of [a,b] within [lo,hi]; 0 if they do not meet. */
static unsigned long long dl_work_span(long long a, long long b, long long lo, long long hi)
{
    if (a < lo)
        a = lo;
    if (b > hi)
        b = hi;
    return b >= a ? (unsigned long long)(b - a + 1) : 0;
}

unsigned long long dl_work_rect(const dl_gc *gc, int x0, int y0, int x1, int y1)
{
    return dl_work_span(x0, x1, gc->cx0, gc->cx1) * dl_work_span(y0, y1, gc->cy0, gc->cy1);
}

unsigned long long dl_work_lines(const int *xy, size_t n, int strip)
{
    unsigned long long sum = 0;
    size_t i;
    for (i = 0; i + 1 < n; i += strip ? 1 : 2) {
        long long dx = (long long)xy[2 * i + 2] - xy[2 * i], dy = (long long)xy[2 * i + 3] - xy[2 * i + 1];
        dx = dx < 0 ? -dx : dx;
        dy = dy < 0 ? -dy : dy;
        sum += (unsigned long long)(dx > dy ? dx : dy) + 1;
    }
    return sum;
}

unsigned long long dl_work_polygon(const dl_gc *gc, const int *xy, size_t n)
{
    long long ymin = 32767, ymax = -32768;
    size_t i;
    for (i = 0; i < n; i++) {
        if (xy[2 * i + 1] < ymin) ymin = xy[2 * i + 1];
        if (xy[2 * i + 1] > ymax) ymax = xy[2 * i + 1];
    }
    return dl_work_span(ymin, ymax, gc->cy0, gc->cy1) * (n + (unsigned long long)(gc->cx1 - gc->cx0 + 1));
}

unsigned long long dl_work_circle(const dl_gc *gc, int cy, unsigned r, int fill)
{
    unsigned long long w = 2ull * r + 1, cw = (unsigned long long)(gc->cx1 - gc->cx0 + 1);
    if (!fill)
        return 8ull * (r + 1ull);
    return dl_work_span((long long)cy - r, (long long)cy + r, gc->cy0, gc->cy1) * (w < cw ? w : cw);
}
