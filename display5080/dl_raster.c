/* dl_raster — software 5081 frame buffer and drawing (see dl_raster.h). */
#include "display5080/dl_raster.h"
#include "display5080/dl_logic.h"
#include "util/mem.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int dl_raster_init(dl_raster *r, int width, int height, diag *err)
{
    memset(r, 0, sizeof *r);
    r->px = mem_calloc((size_t)width * (size_t)height, 1);
    if (!r->px)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory for a %dx%d frame buffer", width,
                       height);
    r->width = width;
    r->height = height;
    return 0;
}

void dl_raster_free(dl_raster *r)
{
    mem_free(r->px);
    mem_free(r->stamp);
    mem_free(r->xs);
    memset(r, 0, sizeof *r);
}

static void dl_raster_put(dl_raster *r, const dl_gc *gc, int x, int y, uint8_t s)
{
    uint8_t *p;
    if (x < gc->cx0 || x > gc->cx1 || y < gc->cy0 || y > gc->cy1)
        return;
    p = r->px + (size_t)y * (size_t)r->width + (size_t)x;
    *p = dl_logic_apply(gc->op, s, *p, (uint8_t)gc->mask);
}

/* Like dl_raster_put, but at most once per element (stamp marks). */
static void dl_raster_put_once(dl_raster *r, const dl_gc *gc, int x, int y)
{
    size_t i;
    if (x < gc->cx0 || x > gc->cx1 || y < gc->cy0 || y > gc->cy1)
        return;
    i = (size_t)y * (size_t)r->width + (size_t)x;
    if (r->stamp[i] == r->epoch)
        return;
    r->stamp[i] = r->epoch;
    r->px[i] = dl_logic_apply(gc->op, (uint8_t)gc->colour, r->px[i], (uint8_t)gc->mask);
}

/* Starts a new element for dl_raster_put_once. */
static int dl_raster_new_epoch(dl_raster *r, diag *err)
{
    size_t n = (size_t)r->width * (size_t)r->height;
    if (!r->stamp) {
        r->stamp = mem_calloc(n, 1);
        if (!r->stamp)
            return diag_at(err, DIAG_IO, "", 0, 0, "out of memory for line marks");
        r->epoch = 0;
    }
    if (++r->epoch == 0) {
        memset(r->stamp, 0, n);
        r->epoch = 1;
    }
    return 0;
}

static int dl_raster_rect(void *dev, const dl_gc *gc, int x0, int y0, int x1, int y1, diag *err)
{
    dl_raster *r = dev;
    int x, y;
    (void)err;
    if (x0 < gc->cx0) x0 = gc->cx0;
    if (y0 < gc->cy0) y0 = gc->cy0;
    if (x1 > gc->cx1) x1 = gc->cx1;
    if (y1 > gc->cy1) y1 = gc->cy1;
    if (x1 < x0 || y1 < y0)
        return 0;
    for (y = y0; y <= y1; y++) {
        uint8_t *p = r->px + (size_t)y * (size_t)r->width;
        for (x = x0; x <= x1; x++)
            p[x] = dl_logic_apply(gc->op, (uint8_t)gc->colour, p[x], (uint8_t)gc->mask);
    }
    return 0;
}

static int dl_raster_blt(void *dev, const dl_gc *gc, int x0, int y0, int w, int h,
                         const uint8_t *rows, size_t stride, diag *err)
{
    dl_raster *r = dev;
    int i, j;
    (void)err;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++)
            dl_raster_put(r, gc, x0 + i, y0 + j, rows[(size_t)j * stride + (size_t)i]);
    return 0;
}

/* Bresenham from (x0,y0) to (x1,y1), both ends included. */
static int dl_raster_segment(dl_raster *r, const dl_gc *gc, int x0, int y0, int x1, int y1,
                             diag *err)
{
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, e = dx + dy;
    (void)err;
    for (;;) {
        int e2 = 2 * e;
        dl_raster_put_once(r, gc, x0, y0);
        if (x0 == x1 && y0 == y1)
            break;
        if (e2 >= dy) {
            e += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y0 += sy;
        }
    }
    return 0;
}

static int dl_raster_lines(void *dev, const dl_gc *gc, const int *xy, size_t n, int strip,
                           diag *err)
{
    dl_raster *r = dev;
    size_t i;
    if (dl_raster_new_epoch(r, err))
        return DIAG_IO;
    for (i = 0; i + 1 < n; i += strip ? 1 : 2)
        if (dl_raster_segment(r, gc, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3], err))
            return DIAG_INPUT;
    return 0;
}

static int dl_raster_int_cmp(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Ceiling of n / d for d > 0. */
static long long dl_ceil_div(long long n, long long d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); }

static int dl_raster_polygon(void *dev, const dl_gc *gc, const int *xy, size_t n, diag *err)
{
    dl_raster *r = dev;
    int ymin = 32767, ymax = -32768, y;
    size_t i;
    void *xs = r->xs;
    for (i = 0; i < n; i++) {
        if (xy[2 * i + 1] < ymin) ymin = xy[2 * i + 1];
        if (xy[2 * i + 1] > ymax) ymax = xy[2 * i + 1];
    }
    if (ymin < gc->cy0) ymin = gc->cy0;
    if (ymax > gc->cy1) ymax = gc->cy1;
    if (n > r->xs_cap && mem_grow(&xs, &r->xs_cap, n, sizeof(int)))
        return diag_at(err, DIAG_IO, gc->name, 0, 0, "out of memory for polygon edges");
    r->xs = xs;
    for (y = ymin; y <= ymax; y++) {
        size_t k = 0, m;
        for (i = 0; i < n; i++) {
            size_t j = (i + 1) % n;
            long long xa = xy[2 * i], ya = xy[2 * i + 1], xb = xy[2 * j], yb = xy[2 * j + 1];
            if (ya == yb)
                continue;
            if (ya > yb) {
                long long t = xa; xa = xb; xb = t;
                t = ya; ya = yb; yb = t;
            }
            if (y < ya || y >= yb)
                continue;
            /* first pixel centre at or right of the crossing */
            r->xs[k++] = (int)(xa + dl_ceil_div((y - ya) * (xb - xa), yb - ya));
        }
        qsort(r->xs, k, sizeof(int), dl_raster_int_cmp);
        for (m = 0; m + 1 < k; m += 2) {
            int x0 = r->xs[m], x1 = r->xs[m + 1] - 1;
            if (x1 >= x0 && dl_raster_rect(r, gc, x0, y, x1, y, err))
                return DIAG_INPUT;
        }
    }
    return 0;
}

/* floor(sqrt(v)) exactly. */
static long long dl_isqrt(long long v)
{
    long long s = (long long)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    return s;
}

static int dl_raster_circle(void *dev, const dl_gc *gc, int cx, int cy, unsigned rad, int fill,
                            diag *err)
{
    dl_raster *r = dev;
    long long rr = (long long)rad * rad;
    if (fill) {
        long long dy, lo = (long long)gc->cy0 - cy, hi = (long long)gc->cy1 - cy;
        if (lo < -(long long)rad) lo = -(long long)rad;
        if (hi > (long long)rad) hi = (long long)rad;
        for (dy = lo; dy <= hi; dy++) {
            long long hw = dl_isqrt(rr - dy * dy), x0 = cx - hw, x1 = cx + hw;
            if (x0 < gc->cx0) x0 = gc->cx0;
            if (x1 > gc->cx1) x1 = gc->cx1;
            if (x1 >= x0 && dl_raster_rect(r, gc, (int)x0, (int)(cy + dy), (int)x1,
                                           (int)(cy + dy), err))
                return DIAG_INPUT;
        }
        return 0;
    } else {
        /* Midpoint circle over one octant, mirrored; each pixel once. */
        long long x = 0, y = rad, d = 1 - (long long)rad;
        if (dl_raster_new_epoch(r, err))
            return DIAG_IO;
        while (x <= y) {
            long long px[8][2] = {{x, y}, {-x, y}, {x, -y}, {-x, -y},
                                  {y, x}, {-y, x}, {y, -x}, {-y, -x}};
            int k;
            for (k = 0; k < 8; k++) {
                long long X = cx + px[k][0], Y = cy + px[k][1];
                if (X >= gc->cx0 && X <= gc->cx1 && Y >= gc->cy0 && Y <= gc->cy1)
                    dl_raster_put_once(r, gc, (int)X, (int)Y);
            }
            x++;
            if (d < 0) {
                d += 2 * x + 1;
            } else {
                y--;
                d += 2 * (x - y) + 1;
            }
        }
        return 0;
    }
}

const dl_device dl_raster_device = {
    dl_raster_rect, dl_raster_blt, dl_raster_lines, dl_raster_polygon, dl_raster_circle,
};
