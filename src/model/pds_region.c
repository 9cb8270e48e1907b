/* pds_region — the region frame and boundary distance (see pds_region.h). */
#include "model/pds_region.h"
#include <math.h>
#include <string.h>
#include "util/dmath.h"

static void pds_region_apply(const double m[6], double x, double y, double *ox, double *oy)
{
    *ox = m[0] * x + m[1] * y + m[2];
    *oy = m[3] * x + m[4] * y + m[5];
}

/* Distance from (px,py) to segment a-b. */
static double pds_region_seg(double ax, double ay, double bx, double by, double px, double py)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t = 0;
    if (l2 > 0)
        t = fmin(1, fmax(0, ((px - ax) * dx + (py - ay) * dy) / l2));
    return hypot(px - ax - t * dx, py - ay - t * dy);
}

/* Crossing parity of the polygon pts[n] at (x,y), closed boundary. */
static int pds_region_poly_in(const double *pts, size_t n, double x, double y)
{
    size_t i, j;
    int in = 0;
    for (i = 0, j = n - 1; i < n; j = i++) {
        double xi = pts[2 * i], yi = pts[2 * i + 1], xj = pts[2 * j], yj = pts[2 * j + 1];
        if (pds_region_seg(xi, yi, xj, yj, x, y) == 0)
            return 1;
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
            in = !in;
    }
    return in;
}

static int pds_region_kind(const pds_def *d, double u, double v, pds_region *r, int depth);

/* Leaf or operator node i of a CPG; m = face_from_node placement (the
 * node's own transform included), (u,v) in face coordinates. */
static int pds_region_cpg(const pds_def *d, size_t i, const double pm[6], double u, double v, pds_region *r,
                          int depth)
{
    const pds_cpg_node *n = &d->cpg.nodes[i];
    double m[6], det, lx, ly, px, py;
    size_t k;
    memcpy(m, n->xf, sizeof m);
    pds_affine_after(m, pm);
    det = m[0] * m[4] - m[1] * m[3];
    if (det == 0)
        return 0;
    px = u - m[2];
    py = v - m[5];
    lx = (m[4] * px - m[1] * py) / det;
    ly = (-m[3] * px + m[0] * py) / det;
    switch (n->op) {
    case PDS_CPG_RECT: {
        double c[8], e = PDS_REGION_FAR;
        int a;
        if (!(lx >= n->p[0] && lx <= n->p[2] && ly >= n->p[1] && ly <= n->p[3]))
            return 0;
        pds_region_apply(m, n->p[0], n->p[1], &c[0], &c[1]);
        pds_region_apply(m, n->p[2], n->p[1], &c[2], &c[3]);
        pds_region_apply(m, n->p[2], n->p[3], &c[4], &c[5]);
        pds_region_apply(m, n->p[0], n->p[3], &c[6], &c[7]);
        for (a = 0; a < 4; a++)
            e = fmin(e, pds_region_seg(c[2 * a], c[2 * a + 1], c[(2 * a + 2) % 8], c[(2 * a + 3) % 8], u, v));
        r->frame[0] = (lx - n->p[0]) / (n->p[2] - n->p[0]);
        r->frame[1] = (ly - n->p[1]) / (n->p[3] - n->p[1]);
        r->edge = e;
        return 1;
    }
    case PDS_CPG_ELLIPSE: {
        double a = (lx - n->p[0]) / n->p[2], b = (ly - n->p[1]) / n->p[3], rho = hypot(a, b), smin, smax;
        if (rho > 1)
            return 0;
        dmath_sv2(m[0] * n->p[2], m[1] * n->p[3], m[3] * n->p[2], m[4] * n->p[3], &smin, &smax);
        r->frame[0] = (a + 1) / 2;
        r->frame[1] = (b + 1) / 2;
        r->edge = (1 - rho) * smin;
        return 1;
    }
    case PDS_CPG_POLYGON: {
        const double *p = d->cpg.pts + 2 * n->first;
        double box[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY }, e = PDS_REGION_FAR;
        size_t j, cnt = n->count;
        if (!pds_region_poly_in(p, cnt, lx, ly))
            return 0;
        for (j = 0; j < cnt; j++) {
            double ax, ay, bx, by;
            box[0] = fmin(box[0], p[2 * j]); box[2] = fmax(box[2], p[2 * j]);
            box[1] = fmin(box[1], p[2 * j + 1]); box[3] = fmax(box[3], p[2 * j + 1]);
            pds_region_apply(m, p[2 * j], p[2 * j + 1], &ax, &ay);
            pds_region_apply(m, p[2 * ((j + 1) % cnt)], p[2 * ((j + 1) % cnt) + 1], &bx, &by);
            e = fmin(e, pds_region_seg(ax, ay, bx, by, u, v));
        }
        r->frame[0] = (lx - box[0]) / (box[2] - box[0]);
        r->frame[1] = (ly - box[1]) / (box[3] - box[1]);
        r->edge = e;
        return 1;
    }
    case PDS_CPG_NESTED: {
        double smin, smax;
        if (!(lx >= 0 && lx <= 1 && ly >= 0 && ly <= 1) || depth >= PDS_MAX_NESTING)
            return 0;
        if (!pds_region_kind(n->sub, lx, ly, r, depth + 1))
            return 0;      /* transparent where the nested PDS has no region */
        dmath_sv2(m[0], m[1], m[3], m[4], &smin, &smax);
        if (r->edge < PDS_REGION_FAR)
            r->edge *= smin;
        return 1;
    }
    case PDS_CPG_UNION:
        for (k = 0; k < n->count; k++)
            if (pds_region_cpg(d, d->cpg.kids[n->first + k], m, u, v, r, depth))
                return 1;
        return 0;
    default: {
        pds_region dummy;
        if (!pds_region_cpg(d, d->cpg.kids[n->first], m, u, v, r, depth))
            return 0;
        for (k = 1; k < n->count; k++)
            if (pds_region_cpg(d, d->cpg.kids[n->first + k], m, u, v, &dummy, depth) != (n->op == PDS_CPG_INTER))
                return 0;
        return 1;
    }
    }
}

/* Square or brick cell frame and side distance. */
static void pds_region_box_cell(double u, double v, double w, double h, double shift, pds_region *r)
{
    double j = floor(v / h), lv = v - j * h, lu, i;
    if (shift != 0 && fmod(fabs(j), 2) == 1)
        u -= shift;
    i = floor(u / w);
    lu = u - i * w;
    r->frame[0] = lu / w;
    r->frame[1] = lv / h;
    r->edge = fmin(fmin(lu, w - lu), fmin(lv, h - lv));
}

static void pds_region_tiling(const pds_tiling *t, double u, double v, pds_region *r)
{
    double w = t->size[0], h = w * sqrt(3.0) / 2, j, lv, s, su, fs, ft;
    if (t->shape == PDS_TILE_SQUARE || t->shape == PDS_TILE_BRICK) {
        pds_region_box_cell(u, v, w, t->size[1], t->shape == PDS_TILE_BRICK ? t->offset * w : 0, r);
        return;
    }
    /* Triangle lattice: (fs, ft) in the basis (w,0), (w/2,h), fractional. */
    j = floor(v / h);
    lv = v - j * h;
    ft = lv / h;
    s = u - j * w / 2 - lv / sqrt(3.0);
    su = s - floor(s / w) * w;
    fs = su / w;
    r->frame[0] = u / w - floor(u / w);
    r->frame[1] = v / h - floor(v / h);
    if (t->shape == PDS_TILE_TRIANGLE) {
        /* distances to the three sides are h times the barycentric weights */
        double a = fs, b = ft, c = 1 - fs - ft;
        if (c < 0) {
            a = 1 - fs; b = 1 - ft; c = fs + ft - 1;
        }
        r->edge = h * fmin(a, fmin(b, c));
    } else {
        /* hexagon: the gap between the nearest and second nearest lattice
         * points' distances, along the bisector */
        double cx[4] = { 0, w, w / 2, 3 * w / 2 }, cy[4] = { 0, 0, h, h }, x = su + lv / sqrt(3.0);
        double d1 = INFINITY, d2 = INFINITY;
        int a;
        for (a = 0; a < 4; a++) {
            double dd = hypot(x - cx[a], lv - cy[a]);
            if (dd < d1) {
                d2 = d1;
                d1 = dd;
            } else if (dd < d2) {
                d2 = dd;
            }
        }
        r->edge = (d2 * d2 - d1 * d1) / (2 * w);
    }
}

static int pds_region_kind(const pds_def *d, double u, double v, pds_region *r, int depth)
{
    static const double identity[6] = { 1, 0, 0, 0, 1, 0 };
    r->frame[0] = u;
    r->frame[1] = v;
    r->edge = PDS_REGION_FAR;
    switch (d->kind) {
    case PDS_CPG:
        if (d->cpg.nnodes == 0)
            return 0;
        if (pds_region_cpg(d, d->cpg.root, identity, u, v, r, depth))
            return 1;
        r->frame[0] = u;
        r->frame[1] = v;
        r->edge = PDS_REGION_FAR;
        return 0;
    case PDS_TILING:
        pds_region_tiling(&d->tiling, u, v, r);
        return 1;
    case PDS_PIXELS:
        if (d->pixels.width > 0 && d->pixels.height > 0)
            pds_region_box_cell(u, v, 1.0 / d->pixels.width, 1.0 / d->pixels.height, 0, r);
        return 1;
    default:
        return 1;
    }
}

int pds_region_at(const pds_def *d, double u, double v, pds_region *r)
{
    return pds_region_kind(d, u, v, r, 0);
}
