/* lightbuf — a light buffer over boxes (see lightbuf.h). */
#include "util/lightbuf.h"
#include "util/dmath.h"
#include "util/mem.h"
#include "util/radix.h"
#include <math.h>
#include <string.h>

/* Slack on the grid's side: a projection is rounded once per quotient
 * (relative 2^-53 on values within 1), far below this. */
#define LIGHTBUF_EPS 1e-9

/* A box's reach on face f, in the face's (u, v): [u0, u1] x [v0, v1], or
 * none (u1 < u0); f -1: on every face, the box is near the light. */
typedef struct lightbuf_rect { double u0, u1, v0, v1; int f; } lightbuf_rect;

/* Face f looks along axis f / 2, towards -1 on it when f is odd; (u, v)
 * are the next two axes over that coordinate's magnitude. */
static const int lightbuf_next[3] = {1, 2, 0};

/* The reach on face f of the box [lo, hi] (relative to the light, lo <= hi)
 * that reaches in front of the face's plane through the light: its
 * corners' projections bound it while the box lies wholly in front (a
 * projection keeps a convex set's hull); a box across that plane may
 * reach the whole face. */
static lightbuf_rect lightbuf_reach(int f, const double lo[3], const double hi[3])
{
    lightbuf_rect r;
    int a = f / 2, b = lightbuf_next[a], c = lightbuf_next[b];
    double wlo = f % 2 ? -hi[a] : lo[a], whi = f % 2 ? -lo[a] : hi[a], e = 1 + LIGHTBUF_EPS;
    r.f = f;
    if (!(wlo > 0)) {
        r.u0 = r.v0 = -e;
        r.u1 = r.v1 = e;
        return r;
    }
    /* x / w grows with x, and with w where x < 0 (shrinks where x > 0);
     * rounding keeps that order, so of the 8 corners' quotients these are
     * the least and greatest, to the bit (a zero's sign is lost below) */
    r.u0 = lo[b] / (lo[b] < 0 ? wlo : whi) - LIGHTBUF_EPS;
    r.u1 = hi[b] / (hi[b] < 0 ? whi : wlo) + LIGHTBUF_EPS;
    r.u0 = r.u0 > -e ? r.u0 : -e;
    r.u1 = r.u1 < e ? r.u1 : e;
    if (r.u1 < r.u0)                   /* wholly off the face, whatever v */
        return r;
    r.v0 = lo[c] / (lo[c] < 0 ? wlo : whi) - LIGHTBUF_EPS;
    r.v1 = hi[c] / (hi[c] < 0 ? whi : wlo) + LIGHTBUF_EPS;
    r.v0 = r.v0 > -e ? r.v0 : -e;
    r.v1 = r.v1 < e ? r.v1 : e;
    if (r.v1 < r.v0)
        r.u1 = r.u0 - 1;
    return r;
}

/* Whether the box [lo, hi] comes within 3 grow of the light on every
 * axis: a ray's points near its closest point to the light may then lie
 * in it whatever their direction. */
static int lightbuf_is_near(const lightbuf *lb, const double lo[3], const double hi[3])
{
    int k, near = 1;
    for (k = 0; k < 3; k++)
        near &= lo[k] - 3 * lb->grow <= lb->at[k] && hi[k] + 3 * lb->grow >= lb->at[k];
    return near;
}

/* The square root of d2, a box's squared distance from the point as the
 * build forms it, as a float no greater than the distance itself: made
 * smaller by 2^-20 of itself, far more than the rounding of d2 and of the
 * root, then rounded down. */
static float lightbuf_down(double d2)
{
    return dmath_f32_round(sqrt(d2) * (1 - 0x1p-20), 0);
}

/* The cells of face r->f that rect r covers: [c[0], c[1]] x [c[2], c[3]].
 * A cell is the floor of a coordinate clamped to [0, n], which truncation
 * gives. */
static void lightbuf_cells(const lightbuf *lb, const lightbuf_rect *r, int c[4])
{
    int f = r->f, n = lb->res[f] - 1;
    double x0 = (r->u0 - lb->u0[f]) * lb->su[f], x1 = (r->u1 - lb->u0[f]) * lb->su[f];
    double y0 = (r->v0 - lb->v0[f]) * lb->sv[f], y1 = (r->v1 - lb->v0[f]) * lb->sv[f];
    c[0] = x0 < 0 ? 0 : x0 >= n ? n : (int)x0;
    c[1] = x1 < 0 ? 0 : x1 >= n ? n : (int)x1;
    c[2] = y0 < 0 ? 0 : y0 >= n ? n : (int)y0;
    c[3] = y1 < 0 ? 0 : y1 >= n ? n : (int)y1;
}

/* Box `box` in the cells c of face f: placed at item[start[cell]++], or
 * with item NULL counted at start[cell + 1]. */
static void lightbuf_cover(lightbuf *lb, int f, const int c[4], int box, int *item)
{
    int *start = lb->start + lb->first[f], x, y;
    for (y = c[2]; y <= c[3]; y++)
        for (x = c[0]; x <= c[1]; x++) {
            if (item)
                item[start[y * lb->res[f] + x]++] = box;
            else
                start[y * lb->res[f] + x + 1]++;
        }
}

/* Room in s for n boxes: one block, carved into rc (6n), key (n), cell
 * (6n) and first (n + 1), in that order, so each part keeps its alignment.
 * 0, or -1 when memory runs out (s then holds nothing). */
static int lightbuf_scratch_room(lightbuf_scratch *s, size_t n)
{
    unsigned char *b;
    if (s->mem && n <= s->cap)
        return 0;
    lightbuf_scratch_free(s);
    if (!(b = mem_alloc(n * (6 * sizeof *s->rc + sizeof *s->key + 6 * sizeof *s->cell + sizeof *s->first)
                        + sizeof *s->first)))
        return -1;
    s->mem = b;
    s->cap = n;
    s->rc = (lightbuf_rect *)(void *)b;
    s->key = (uint64_t *)(void *)(b += 6 * n * sizeof *s->rc);
    s->cell = (int (*)[4])(void *)(b += n * sizeof *s->key);
    s->first = (int *)(void *)(b + 6 * n * sizeof *s->cell);
    return 0;
}

void lightbuf_scratch_free(lightbuf_scratch *s)
{
    mem_free(s->mem);
    memset(s, 0, sizeof *s);
}

int lightbuf_build(lightbuf *lb, const double at[3], const double (*lo)[3], const double (*hi)[3],
                   size_t n, double grow, lightbuf_scratch *s)
{
    lightbuf_rect *rc;
    double ext[6][4];
    size_t i, j, nr = 0, total = 0, cells = 0;
    uint64_t *key;
    radix_ix *order = NULL;
    int *first, (*cell)[4], f, k, status = -1, m[6] = {0, 0, 0, 0, 0, 0};
    memset(lb, 0, sizeof *lb);
    memcpy(lb->at, at, sizeof lb->at);
    lb->grow = grow;
    if (n > LIGHTBUF_BOXES_MAX)            /* scratch: 348 bytes a box */
        return 1;
    if (lightbuf_scratch_room(s, n ? n : 1))
        return -1;
    rc = s->rc;
    first = s->first;
    key = s->key;
    cell = s->cell;
    if (!(lb->far = mem_alloc((n ? n : 1) * sizeof *lb->far)))
        goto done;
    for (f = 0; f < 6; f++) {
        ext[f][0] = ext[f][2] = HUGE_VAL;
        ext[f][1] = ext[f][3] = -HUGE_VAL;
    }
    /* each box's distance from the light, and its reaches, box i's at
     * rc[first[i] .. first[i + 1] - 1]; a box near the light is in no cell
     * but in the near list */
    for (i = 0; i < n; i++) {
        double l[3], h[3], d2 = 0;
        for (k = 0; k < 3; k++) {
            double g = lo[i][k] > at[k] ? lo[i][k] - at[k] : at[k] > hi[i][k] ? at[k] - hi[i][k] : 0;
            d2 += g * g;
        }
        key[i] = radix_key_d(d2);
        lb->far[i] = lightbuf_down(d2);
        first[i] = (int)nr;
        if (lightbuf_is_near(lb, lo[i], hi[i])) {
            rc[nr++].f = -1;
            lb->nnear++;
            continue;
        }
        for (k = 0; k < 3; k++) {
            l[k] = lo[i][k] - grow - at[k];
            h[k] = hi[i][k] + grow - at[k];
        }
        for (f = 0; f < 6; f++) {
            lightbuf_rect *r = &rc[nr];
            if (!(f % 2 ? l[f / 2] < 0 : h[f / 2] > 0))
                continue;              /* wholly behind the face's plane */
            *r = lightbuf_reach(f, l, h);
            if (r->u1 < r->u0)
                continue;
            nr++;
            m[f]++;
            ext[f][0] = r->u0 < ext[f][0] ? r->u0 : ext[f][0];
            ext[f][1] = r->u1 > ext[f][1] ? r->u1 : ext[f][1];
            ext[f][2] = r->v0 < ext[f][2] ? r->v0 : ext[f][2];
            ext[f][3] = r->v1 > ext[f][3] ? r->v1 : ext[f][3];
        }
    }
    first[n] = (int)nr;
    /* the boxes nearest the light first in every cell: a camera ray's
     * far end then shrinks before the farther ones are tested */
    if (!(order = radix_order(key, n)))
        goto done;
    /* per face a grid over what the boxes reach, about two cells a side
     * per square root of the boxes there */
    for (f = 0; f < 6; f++) {
        int res = 0;
        if (m[f]) {
            res = (int)ceil(4 * sqrt((double)m[f]));
            res = res > LIGHTBUF_RES_MAX ? LIGHTBUF_RES_MAX : res;
            lb->u0[f] = ext[f][0];
            lb->v0[f] = ext[f][2];
            lb->su[f] = res / fmax(ext[f][1] - ext[f][0], LIGHTBUF_EPS);
            lb->sv[f] = res / fmax(ext[f][3] - ext[f][2], LIGHTBUF_EPS);
        }
        lb->res[f] = res;
        lb->first[f] = (int)cells;
        cells += (size_t)res * (size_t)res;
    }
    lb->start = mem_calloc(cells + 1, sizeof *lb->start);
    lb->near = mem_alloc((lb->nnear ? (size_t)lb->nnear : 1) * sizeof *lb->near);
    if (!lb->start || !lb->near)
        goto done;
    /* count each cell's boxes, then place them, nearest first */
    for (j = 0; j < nr; j++)
        if (rc[j].f >= 0) {
            lightbuf_cells(lb, &rc[j], cell[j]);
            lightbuf_cover(lb, rc[j].f, cell[j], 0, NULL);
            total += (size_t)(cell[j][1] - cell[j][0] + 1) * (size_t)(cell[j][3] - cell[j][2] + 1);
        }
    status = 1;
    if (total > LIGHTBUF_PER_BOX * (n > LIGHTBUF_BOXES_MIN ? n : LIGHTBUF_BOXES_MIN))
        goto done;
    for (j = 0; j < cells; j++)
        lb->start[j + 1] += lb->start[j];
    lb->item = mem_alloc((total ? total : 1) * sizeof *lb->item);
    status = -1;
    if (!lb->item)
        goto done;
    for (j = 0, k = 0; j < n; j++) {
        for (i = (size_t)first[order[j]]; i < (size_t)first[order[j] + 1]; i++) {
            if (rc[i].f < 0)
                lb->near[k++] = (int)order[j];
            else
                lightbuf_cover(lb, rc[i].f, cell[i], (int)order[j], lb->item);
        }
    }
    /* placing advanced each start to the next cell's: shift back */
    memmove(lb->start + 1, lb->start, cells * sizeof *lb->start);
    lb->start[0] = 0;
    status = 0;
done:
    mem_free(order);
    if (status)
        lightbuf_free(lb);
    return status;
}

void lightbuf_free(lightbuf *lb)
{
    mem_free(lb->start);
    mem_free(lb->item);
    mem_free(lb->far);
    mem_free(lb->near);
    lb->start = lb->item = lb->near = NULL;
    lb->far = NULL;
    lb->nnear = 0;
}
