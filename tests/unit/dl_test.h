/* dl_test — oracles shared by the display-list tests, written from the
 * geometry, not from display5080's code. */
#ifndef DL_TEST_H
#define DL_TEST_H

/* Even-odd by ray crossing (pnpoly): exact off the boundary; on it, a centre
 * on a left edge is inside and edges are half-open in y. */
static inline int dl_test_inside(const int *xy, int n, double x, double y)
{
    int i, j, c = 0;
    for (i = 0, j = n - 1; i < n; j = i++) {
        double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
        if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi))
            c = !c;
    }
    return c;
}

/* Point (x,y) on the segment a-b, exactly. */
static inline int dl_test_on_segment(long ax, long ay, long bx, long by, long x, long y)
{
    if ((bx - ax) * (y - ay) != (by - ay) * (x - ax))
        return 0;
    return x >= (ax < bx ? ax : bx) && x <= (ax < bx ? bx : ax) && y >= (ay < by ? ay : by) &&
           y <= (ay < by ? by : ay);
}
#endif
