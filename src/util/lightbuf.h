/* lightbuf — for one point (a light, or the eye), the boxes a ray to or
 * from it can meet, looked up by the direction of the ray as seen from
 * the point (a light buffer, after Haines and Greenberg, "The Light
 * Buffer", IEEE CG&A 6(9), 1986).
 *
 * The directions from the point are split among the six faces of a cube
 * around it; each face holds a grid of cells over the part of it that
 * some box covers, and each cell the boxes whose projection from the
 * point reaches it. The boxes are grown by `grow` first, so a ray whose
 * line passes within grow / 2 of the point, and that stays on one side
 * of its closest point L' to it but for grow / 2, meets no box outside its
 * cell's list: a point x of the ray on that side lies in a box B only if
 * x + (point - L') lies in B grown by |point - L'|, in the ray's direction
 * as seen from the point. A box within 3 grow of the point is in no cell
 * but in the list `near`, which every lookup's caller tests too
 * (docs/numerics.md, "Culling in binary64").
 * Binary64 throughout; mode-independent. */
#ifndef UTIL_LIGHTBUF_H
#define UTIL_LIGHTBUF_H
#include <stddef.h>
#include <math.h>
#include <stdint.h>

typedef struct lightbuf {
    double at[3];            /* the light */
    double grow;             /* how far each box was grown */
    double u0[6], v0[6], su[6], sv[6];   /* per face: the grid's corner and
                                            cells per unit */
    int res[6];              /* cells a side per face; 0: none covered */
    int first[6];            /* the face's first cell in start[] */
    int *start;              /* cell c's items are item[start[c] ..
                                start[c + 1] - 1] */
    int *item;
    float *far;              /* per box: its distance from the point,
                                rounded down. A cell lists its boxes
                                nearest first, so a ray that comes no
                                farther from the point than lightbuf_ray_far
                                says meets none from the first one farther
                                on */
    int *near;               /* the boxes near the light, which every
                                direction can meet: nnear of them */
    int nnear;
} lightbuf;

/* Cells a side at most, and entries in all at most a box, counted over no
 * fewer than LIGHTBUF_BOXES_MIN boxes (beyond that the buffer is not built
 * and the caller walks its hierarchy). */
#define LIGHTBUF_RES_MAX 64
#define LIGHTBUF_PER_BOX 64
#define LIGHTBUF_BOXES_MIN 1024
#define LIGHTBUF_BOXES_MAX ((size_t)1 << 20)   /* boxes a buffer is built over */

/* What a build works in and leaves, for the next build to reuse: the
 * buffers of several points over the same boxes (a scene's lights and its
 * eye) then fault in their scratch once, not once each (docs/performance.md,
 * run AH). Zeroed before the first build; lightbuf_scratch_free after the
 * last. */
typedef struct lightbuf_scratch {
    void *mem;               /* one block for the arrays below */
    size_t cap;              /* boxes it has room for */
    struct lightbuf_rect *rc;/* the boxes' reaches, 6 a box at most */
    int *first;              /* box i's reaches: rc[first[i] .. first[i + 1] - 1] */
    uint64_t *key;           /* the boxes' distances, for their order */
    int (*cell)[4];          /* each reach's cells */
} lightbuf_scratch;

/* Builds the buffer of the light at `at` over the finite boxes lo[i] <=
 * hi[i] (i < n), each grown by grow > 0, working in *s. 0; 1 when there
 * are more than LIGHTBUF_BOXES_MAX boxes or the cells would hold more
 * entries than the limit above (nothing built); -1 when memory runs out. */
int lightbuf_build(lightbuf *lb, const double at[3], const double (*lo)[3], const double (*hi)[3],
                   size_t n, double grow, lightbuf_scratch *s);
void lightbuf_free(lightbuf *lb);
void lightbuf_scratch_free(lightbuf_scratch *s);

/* The boxes (indices, nearest the point first) besides lb->near whose
 * grown projections reach the direction the ray from o along d (not zero)
 * takes, seen from the point, over parameters [0, tmax]: 1 and *items, *n. `toward`: the ray goes to
 * the light (a shadow ray, seen there as -d), and must stop before its
 * closest point to it or within grow / 2 of it (a distance); else it
 * leaves (a camera ray from an eye there, seen as +d) and must start after
 * that point or within grow / 2 of it. Either way its line passes within
 * grow / 2 of the light, |(at - o) x d| <= grow / 2 |d|; else 0 (the list
 * would not be complete).
 * The cell is found with one division; its rounding, like the build's, is
 * far inside the grid's slack. Inline: one call per ray. */
static inline int lightbuf_lookup(const lightbuf *lb, const double o[3], const double d[3], double tmax,
                                  int toward, const int **items, int *n)
{
    double r0 = lb->at[0] - o[0], r1 = lb->at[1] - o[1], r2 = lb->at[2] - o[2];
    double c0 = r1 * d[2] - r2 * d[1], c1 = r2 * d[0] - r0 * d[2], c2 = r0 * d[1] - r1 * d[0];
    double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], h = 0.5 * lb->grow, rd, g, w, x, y;
    double a0 = d[0] < 0 ? -d[0] : d[0], a1 = d[1] < 0 ? -d[1] : d[1], a2 = d[2] < 0 ? -d[2] : d[2];
    int a, f, res;
    size_t cell;
    rd = r0 * d[0] + r1 * d[1] + r2 * d[2];
    g = toward ? tmax * dd - rd : rd;    /* |d|^2 times the parameter past (or
                                            before) the closest point */
    if (!lb->start || !(dd > 0) || !(c0 * c0 + c1 * c1 + c2 * c2 <= h * h * dd)
        || !(g <= 0 || g * g <= h * h * dd))
        return 0;
    a = a0 >= a1 ? (a0 >= a2 ? 0 : 2) : (a1 >= a2 ? 1 : 2);
    f = 2 * a + ((d[a] > 0) == (toward != 0));    /* the face the ray is seen on */
    res = lb->res[f];
    *items = lb->item;
    *n = 0;
    if (res == 0)
        return 1;
    w = (toward ? -1 : 1) / (a == 0 ? a0 : a == 1 ? a1 : a2);
    x = (d[a == 2 ? 0 : a + 1] * w - lb->u0[f]) * lb->su[f];
    y = (d[a == 0 ? 2 : a - 1] * w - lb->v0[f]) * lb->sv[f];
    if (!(x >= 0 && x <= res && y >= 0 && y <= res))
        return 1;
    cell = (size_t)lb->first[f] + (size_t)((int)y < res ? (int)y : res - 1) * (size_t)res
           + (size_t)((int)x < res ? (int)x : res - 1);
    *items = lb->item + lb->start[cell];
    *n = lb->start[cell + 1] - lb->start[cell];
    return 1;
}

/* How far from the point any point of the ray from o along d over
 * parameters [0, tmax] lies at most, a little more (relative 2^-30, far
 * above the rounding here): |o - point| + tmax |d| for a ray leaving it,
 * and for one going to it (`toward`) the larger of its ends' distances,
 * a segment's distance from a point being convex. A box in the ray's list
 * whose distance (lightbuf.far) is greater holds no point of the ray:
 * neither it nor any listed after it needs testing. */
static inline double lightbuf_ray_far(const lightbuf *lb, const double o[3], const double d[3], double tmax,
                                    int toward)
{
    double r0 = 0, r1 = 0, dd = 0, reach;
    int k;
    for (k = 0; k < 3; k++) {
        double a = o[k] - lb->at[k], b = a + tmax * d[k];
        r0 += a * a;
        r1 += b * b;
        dd += d[k] * d[k];
    }
    reach = toward ? sqrt(r0 > r1 ? r0 : r1) : sqrt(r0) + tmax * sqrt(dd);
    return reach * (1 + 0x1p-30);
}
#endif
