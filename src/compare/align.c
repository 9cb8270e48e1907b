/* align — coarse-to-fine registration on edge pyramids (see align.h). */
#include "compare/align.h"
#include "util/dmath.h"
#include "util/mem.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ALIGN_LEVELS 16            /* pyramid levels at most */
#define ALIGN_KEEP 8               /* coarse candidates kept */
#define ALIGN_SPREAD 4             /* best ones also started a scale step either side */
#define ALIGN_COARSE 24.0          /* smaller picture's size at the coarse level */
#define ALIGN_SCALE_STEP 1.06      /* coarse scale step (factor) */
#define ALIGN_ANGLE_STEP 8.0       /* coarse angles: multiples of this within the range */
#define ALIGN_INVALID (-2.0)       /* score of a refused placement */
#define ALIGN_DROP 0.6             /* finer level refused below this share of the score */
#define ALIGN_BORDER 3.0           /* level pixels left out along each picture's border */

/* Edge-map pyramid: lv[k] has 2^-k the resolution of the picture. */
typedef struct align_pyr {
    int n;
    plane lv[ALIGN_LEVELS];
} align_pyr;

typedef struct align_ctx {
    align_pyr r, t;
    int rw, rh, tw, th;
    double ref_blur;
} align_ctx;

typedef struct align_cand {
    warp_params p;
    double score;
    int level;                     /* level of the last refinement, -1 if none */
} align_cand;

/* Running sums of a normalised cross-correlation of pairs (a, b). */
typedef struct align_ncc {
    double sa, sb, saa, sbb, sab, n;
} align_ncc;

static void align_ncc_add(align_ncc *s, double a, double b)
{
    s->sa += a;
    s->sb += b;
    s->saa += a * a;
    s->sbb += b * b;
    s->sab += a * b;
    s->n += 1;
}

/* The NCC of the pairs summed in s, over ncov covered pixels of f2
 * reference pixels each; ALIGN_INVALID when the covered part is under
 * ALIGN_MIN_OVERLAP of area (the smaller picture's), what the border bands
 * leave under ALIGN_MIN_USED, or either side is flat. */
static double align_ncc_score(const align_ncc *s, double ncov, double f2, double area)
{
    double va, vb;
    if (s->n < 4 || ncov * f2 < ALIGN_MIN_OVERLAP * area || s->n * f2 < ALIGN_MIN_USED * area)
        return ALIGN_INVALID;
    va = s->saa - s->sa * s->sa / s->n;
    vb = s->sbb - s->sb * s->sb / s->n;
    if (!(va > 1e-9 * s->n) || !(vb > 1e-9 * s->n))
        return ALIGN_INVALID;
    return (s->sab - s->sa * s->sb / s->n) / sqrt(va * vb);
}

/* Area of the smaller picture (reference, or test scaled into reference
 * pixels) in reference pixels. */
static double align_area(const align_ctx *c, double scale)
{
    double area = (double)c->rw * c->rh, t = scale * scale * c->tw * c->th;
    return t < area ? t : area;
}

/* Bounding box in reference pixels of the test placed by p. */
static void align_bbox(const align_ctx *c, const warp_params *p, double *x0, double *y0, double *x1, double *y1)
{
    int q;
    *x0 = *y0 = 1e300;
    *x1 = *y1 = -1e300;
    for (q = 0; q < 4; q++) {
        double xr, yr;
        warp_to_ref(p, (q & 1) ? c->tw : 0, (q & 2) ? c->th : 0, &xr, &yr);
        *x0 = xr < *x0 ? xr : *x0;
        *x1 = xr > *x1 ? xr : *x1;
        *y0 = yr < *y0 ? yr : *y0;
        *y1 = yr > *y1 ? yr : *y1;
    }
}

/* Test pyramid level whose pixels best match reference level l's at scale. */
static int align_test_level(const align_ctx *c, int l, double scale)
{
    int k = (int)floor(log2(ldexp(1.0, l) / scale) + 0.5);
    return k < 0 ? 0 : k >= c->t.n ? c->t.n - 1 : k;
}

static void align_pyr_free(align_pyr *py)
{
    while (py->n > 0)
        plane_free(&py->lv[--py->n]);
}

/* Builds the blurred gradient-magnitude pyramid of src, down to about 8
 * pixels on the longer side. 0 or -1. */
static int align_pyr_build(const plane *src, align_pyr *py)
{
    plane cur, next;
    py->n = 0;
    if (plane_copy(src, &cur))
        return -1;
    for (;;) {
        if (plane_gradient(&cur, &py->lv[py->n]))
            break;
        py->n++;
        if (plane_blur(&py->lv[py->n - 1], 1.0))
            break;
        if (py->n == ALIGN_LEVELS || (cur.w < 16 && cur.h < 16)) {
            plane_free(&cur);
            return 0;
        }
        if (plane_reduce(&cur, &next))
            break;
        plane_free(&cur);
        cur = next;
    }
    plane_free(&cur);
    align_pyr_free(py);
    return -1;
}

/* Side of the smaller of the two pictures (reference, or the test scaled
 * into reference pixels), in reference pixels: the size that decides how
 * much detail the comparison can use. */
static double align_size(const align_ctx *c, double scale)
{
    double r = c->rw > c->rh ? c->rw : c->rh, t = scale * (c->tw > c->th ? c->tw : c->th);
    return r < t ? r : t;
}

/* Reference pyramid level at which the smaller picture is about `target`
 * pixels across. */
static int align_level(const align_ctx *c, double scale, double target)
{
    int l = (int)floor(log2(align_size(c, scale) / target) + 0.5);
    return l < 0 ? 0 : l >= c->r.n ? c->r.n - 1 : l;
}

/* NCC of the reference edge map at level l with the test edge map pulled
 * back through p, over the reference pixels the test covers, minus the
 * border bands. Returns ALIGN_INVALID when the overlap is under
 * ALIGN_MIN_OVERLAP (or what the bands leave under ALIGN_MIN_USED) of the
 * smaller picture, or either side is flat. */
static double align_eval(const align_ctx *c, const warp_params *p, int l)
{
    const plane *fr = &c->r.lv[l], *ft;
    double f = ldexp(1.0, l), g, a = dmath_rad(p->angle);
    double cs = cos(a) / p->scale, sn = sin(a) / p->scale;
    double minx, maxx, miny, maxy, bt, ncov = 0;
    align_ncc s = {0, 0, 0, 0, 0, 0};
    int k = align_test_level(c, l, p->scale), i, j, i0, i1, j0, j1, br;
    ft = &c->t.lv[k];
    g = ldexp(1.0, k);
    /* Leave out a band along each picture's border: where one picture
     * ends, the other often has an edge of its own (a render against the
     * paper of a scan) that the first cannot show, and keeping it would
     * pull the scale inwards. The overlap rule still counts the band. */
    bt = (ALIGN_BORDER * f + 3.0 * c->ref_blur) / p->scale;
    br = (int)ALIGN_BORDER;
    align_bbox(c, p, &minx, &miny, &maxx, &maxy);
    if (maxx <= 0 || maxy <= 0 || minx >= c->rw || miny >= c->rh)
        return ALIGN_INVALID;
    i0 = minx / f - 1 < 0 ? 0 : (int)(minx / f - 1);
    j0 = miny / f - 1 < 0 ? 0 : (int)(miny / f - 1);
    i1 = maxx / f + 1 > fr->w - 1 ? fr->w - 1 : (int)(maxx / f + 1);
    j1 = maxy / f + 1 > fr->h - 1 ? fr->h - 1 : (int)(maxy / f + 1);
    for (j = j0; j <= j1; j++) {
        double yr = (j + 0.5) * f - p->dy;
        for (i = i0; i <= i1; i++) {
            double xr = (i + 0.5) * f - p->dx;
            double xt = cs * xr - sn * yr, yt = sn * xr + cs * yr;
            if (xt < 0 || yt < 0 || xt >= c->tw || yt >= c->th)
                continue;
            ncov += 1;
            if (xt < bt || yt < bt || xt >= c->tw - bt || yt >= c->th - bt || i < br || j < br ||
                i >= fr->w - br || j >= fr->h - br)
                continue;
            align_ncc_add(&s, PLANE_AT(fr, i, j), plane_sample(ft, xt / g, yt / g));
        }
    }
    return align_ncc_score(&s, ncov, f * f, align_area(c, p->scale));
}

static int align_cand_cmp(const void *a, const void *b)
{
    double x = ((const align_cand *)a)->score, y = ((const align_cand *)b)->score;
    return x > y ? -1 : x < y ? 1 : 0;
}

/* Scores every integer shift (in level-l pixels) of the test edge map m
 * (already scaled and turned into level-l pixels; mk is 0 outside the test,
 * 1 in its border band, 2 elsewhere) over the reference edge map; grid gets
 * the NCC for shift (D,E), D in d0..d0+gw-1 and E in e0..e0+gh-1, or
 * ALIGN_INVALID. Same rules as align_eval. */
static void align_shifts(const align_ctx *c, int l, double area, const plane *m, const plane *mk, int d0,
                         int e0, int gw, int gh, float *grid)
{
    const plane *fr = &c->r.lv[l];
    double f2 = ldexp(1.0, 2 * l);
    int y, br = (int)ALIGN_BORDER;
    for (y = 0; y < gh; y++) {
        int x, u, v;
        for (x = 0; x < gw; x++) {
            int D = d0 + x, E = e0 + y;
            int u0 = -D > 0 ? -D : 0, v0 = -E > 0 ? -E : 0;
            int u1 = fr->w - D < m->w ? fr->w - D : m->w, v1 = fr->h - E < m->h ? fr->h - E : m->h;
            double ncov = 0;
            align_ncc s = {0, 0, 0, 0, 0, 0};
            for (v = v0; v < v1; v++) {
                const float *rb = &PLANE_AT(fr, D + u0, E + v), *mb = &PLANE_AT(m, u0, v), *kb = &PLANE_AT(mk, u0, v);
                int inrow = E + v >= br && E + v < fr->h - br;
                for (u = 0; u < u1 - u0; u++) {
                    if (kb[u] == 0)
                        continue;
                    ncov += 1;
                    if (kb[u] < 2 || !inrow || D + u0 + u < br || D + u0 + u >= fr->w - br)
                        continue;
                    align_ncc_add(&s, rb[u], mb[u]);
                }
            }
            grid[(size_t)y * gw + x] = (float)align_ncc_score(&s, ncov, f2, area);
        }
    }
}

/* The test's edge map resampled into the coarse reference grid for one
 * scale and angle: m holds edge values, mk is 0 outside the test, 1 in its
 * border band, 2 elsewhere; m's pixel (u,v) covers reference pixels from
 * (bx0 + u f, by0 + v f). */
typedef struct align_map {
    warp_params p;                 /* the scale and angle; dx = dy = 0 */
    int l;                         /* reference level */
    double f, bx0, by0;            /* level pixel size, origin */
    int mw, mh;
    plane m, mk;
} align_map;

/* Number of coarse scale steps: log steps of ALIGN_SCALE_STEP over the range. */
static int align_nscales(const align_opts *o)
{
    if (o->scale_max <= o->scale_min)
        return 1;
    return 1 + (int)ceil(log(o->scale_max / o->scale_min) / log(ALIGN_SCALE_STEP));
}

/* The coarse grid's placement si (scale step), ai (angle step), and its map
 * size (no pixels yet). */
static void align_map_init(const align_ctx *c, const align_opts *o, int ns, int si, int ai, align_map *mp)
{
    double x1, y1;
    memset(mp, 0, sizeof *mp);
    mp->p.scale = ns > 1 ? o->scale_min * pow(o->scale_max / o->scale_min, (double)si / (ns - 1)) : o->scale_min;
    mp->p.angle = ai * ALIGN_ANGLE_STEP;
    mp->l = align_level(c, mp->p.scale, ALIGN_COARSE);
    mp->f = ldexp(1.0, mp->l);
    align_bbox(c, &mp->p, &mp->bx0, &mp->by0, &x1, &y1);
    mp->mw = (int)ceil((x1 - mp->bx0) / mp->f);
    mp->mh = (int)ceil((y1 - mp->by0) / mp->f);
    mp->mw = mp->mw < 1 ? 1 : mp->mw;
    mp->mh = mp->mh < 1 ? 1 : mp->mh;
}

/* Pixel pairs align_shifts visits for the map: every shift of an mw x mh
 * map over a W x H level meets W*H*mw*mh pairs in all. */
static double align_map_cost(const align_ctx *c, const align_map *mp)
{
    return (double)c->r.lv[mp->l].w * c->r.lv[mp->l].h * mp->mw * mp->mh;
}

static double align_cost(const align_ctx *c, const align_opts *o)
{
    int ns = align_nscales(o), na = (int)floor(o->max_angle / ALIGN_ANGLE_STEP), si, ai;
    double sum = 0;
    for (si = 0; si < ns; si++)
        for (ai = -na; ai <= na; ai++) {
            align_map mp;
            align_map_init(c, o, ns, si, ai, &mp);
            sum += align_map_cost(c, &mp);
        }
    return sum;
}

/* Samples the test edge map into mp->m and mp->mk. 0 or -1. */
static int align_map_fill(const align_ctx *c, align_map *mp)
{
    int k = align_test_level(c, mp->l, mp->p.scale), u, v;
    const plane *ft = &c->t.lv[k];
    double g = ldexp(1.0, k), bt = (ALIGN_BORDER * mp->f + 3.0 * c->ref_blur) / mp->p.scale;
    if (plane_alloc(&mp->m, mp->mw, mp->mh))
        return -1;
    if (plane_alloc(&mp->mk, mp->mw, mp->mh)) {
        plane_free(&mp->m);
        return -1;
    }
    for (v = 0; v < mp->mh; v++)
        for (u = 0; u < mp->mw; u++) {
            double xt, yt;
            warp_to_test(&mp->p, mp->bx0 + (u + 0.5) * mp->f, mp->by0 + (v + 0.5) * mp->f, &xt, &yt);
            if (xt < 0 || yt < 0 || xt >= c->tw || yt >= c->th)
                continue;
            PLANE_AT(&mp->m, u, v) = plane_sample(ft, xt / g, yt / g);
            /* 2: inside and clear of the border band; 1: in the band */
            PLANE_AT(&mp->mk, u, v) = xt < bt || yt < bt || xt >= c->tw - bt || yt >= c->th - bt ? 1 : 2;
        }
    return 0;
}

/* A growing list of candidates. */
typedef struct align_list {
    align_cand *v;
    size_t n, cap;
} align_list;

/* Appends the local maxima of the shift grid (shift (d0+x, e0+y) at
 * grid[y*gw+x]) as candidates. 0 or -1. */
static int align_maxima(const align_map *mp, const float *grid, int d0, int e0, int gw, int gh, align_list *all)
{
    int x, y;
    for (y = 0; y < gh; y++)
        for (x = 0; x < gw; x++) {
            float val = grid[(size_t)y * gw + x];
            int du, dv, best = val > ALIGN_INVALID;
            for (dv = -1; dv <= 1 && best; dv++)
                for (du = -1; du <= 1 && best; du++)
                    if ((du || dv) && x + du >= 0 && y + dv >= 0 && x + du < gw && y + dv < gh &&
                        grid[(size_t)(y + dv) * gw + x + du] > val)
                        best = 0;
            if (!best)
                continue;
            if (mem_grow((void **)&all->v, &all->cap, all->n + 1, sizeof *all->v))
                return -1;
            all->v[all->n].p = mp->p;
            all->v[all->n].p.dx = (d0 + x) * mp->f + mp->bx0;
            all->v[all->n].p.dy = (e0 + y) * mp->f + mp->by0;
            all->v[all->n].score = val;
            all->n++;
        }
    return 0;
}

/* Scores every shift of one map and adds its local maxima; grid is scratch
 * (*gcap floats, grown as needed). 0 or -1. */
static int align_map_search(const align_ctx *c, align_map *mp, float **grid, size_t *gcap, align_list *all)
{
    /* shift (D,E) puts m's pixel (u,v) on reference pixel (u+D, v+E) */
    int d0 = -mp->mw + 1, e0 = -mp->mh + 1;
    int gw = c->r.lv[mp->l].w + mp->mw - 1, gh = c->r.lv[mp->l].h + mp->mh - 1;
    if ((size_t)gw * (size_t)gh > *gcap) {
        mem_free(*grid);
        *gcap = (size_t)gw * (size_t)gh;
        if (!(*grid = mem_alloc(*gcap * sizeof **grid))) {
            *gcap = 0;
            return -1;
        }
    }
    align_shifts(c, mp->l, align_area(c, mp->p.scale), &mp->m, &mp->mk, d0, e0, gw, gh, *grid);
    return align_maxima(mp, *grid, d0, e0, gw, gh, all);
}

/* Greedy suppression of near-duplicates in all (sorted best first):
 * neighbouring scale, angle and shift steps describe the same placement.
 * Keeps up to ALIGN_KEEP; returns how many. */
static int align_distinct(const align_ctx *c, const align_list *all, align_cand *keep)
{
    size_t t;
    int nkeep = 0;
    for (t = 0; t < all->n && nkeep < ALIGN_KEEP; t++) {
        const align_cand *a = &all->v[t];
        double f = ldexp(1.0, align_level(c, a->p.scale, ALIGN_COARSE));
        int k, dup = 0;
        for (k = 0; k < nkeep && !dup; k++)
            dup = fabs(log(a->p.scale / keep[k].p.scale)) < 2.5 * log(ALIGN_SCALE_STEP) &&
                  fabs(a->p.angle - keep[k].p.angle) < 1.5 * ALIGN_ANGLE_STEP &&
                  fabs(a->p.dx - keep[k].p.dx) < 3 * f && fabs(a->p.dy - keep[k].p.dy) < 3 * f;
        if (!dup)
            keep[nkeep++] = *a;
    }
    return nkeep;
}

/* Exhaustive coarse search; writes up to ALIGN_KEEP distinct candidates,
 * best first, and returns how many (or -1 when out of memory). For each
 * scale and angle the test edge map is resampled once into the coarse
 * reference grid, and every integer shift of it is scored. */
static int align_coarse(const align_ctx *c, const align_opts *o, align_cand *keep)
{
    int ns = align_nscales(o), na = (int)floor(o->max_angle / ALIGN_ANGLE_STEP), si, ai, rc = 0;
    align_list all = {NULL, 0, 0};
    float *grid = NULL;
    size_t gcap = 0;
    for (si = 0; si < ns && !rc; si++)
        for (ai = -na; ai <= na && !rc; ai++) {
            align_map mp;
            align_map_init(c, o, ns, si, ai, &mp);
            rc = align_map_fill(c, &mp) || align_map_search(c, &mp, &grid, &gcap, &all) ? -1 : 0;
            plane_free(&mp.m);
            plane_free(&mp.mk);
        }
    mem_free(grid);
    if (!rc && all.n)
        qsort(all.v, all.n, sizeof *all.v, align_cand_cmp);
    if (!rc)
        rc = align_distinct(c, &all, keep);
    mem_free(all.v);
    return rc;
}

/* Parameters from the search variables x = (log scale, reference position
 * of the test's centre x and y, angle): turning and scaling about the
 * centre keeps the variables nearly independent, so the search converges. */
static warp_params align_from_vars(const align_ctx *c, const double x[4])
{
    warp_params p, q;
    double cx, cy;
    p.scale = exp(x[0]);
    p.angle = x[3];
    p.dx = p.dy = 0;
    warp_to_ref(&p, c->tw / 2.0, c->th / 2.0, &cx, &cy);
    q = p;
    q.dx = x[1] - cx;
    q.dy = x[2] - cy;
    return q;
}

/* Pattern search around cand at level l: steps start at one level pixel of
 * motion (shift, scale at the picture's edge, angle at half its size) and
 * halve until they fall under min_step level pixels. */
static void align_refine(const align_ctx *c, const align_opts *o, align_cand *cand, int l, double min_step)
{
    double f = ldexp(1.0, l), m = align_size(c, cand->p.scale) / f;
    double st[4], x[4];
    int d, evals = 0, nd = o->max_angle > 0 ? 4 : 3;
    st[0] = 1.0 / m;
    st[1] = st[2] = f;
    st[3] = dmath_deg(2.0 / m);
    x[0] = log(cand->p.scale);
    warp_to_ref(&cand->p, c->tw / 2.0, c->th / 2.0, &x[1], &x[2]);
    x[3] = cand->p.angle;
    cand->score = align_eval(c, &cand->p, l);
    while (st[1] >= min_step * f && evals < 400) {
        int improved = 0;
        for (d = 0; d < nd; d++) {
            int sign;
            for (sign = -1; sign <= 1; sign += 2) {
                double y[4], sc;
                warp_params p;
                memcpy(y, x, sizeof y);
                y[d] += sign * st[d];
                if (y[0] < log(o->scale_min))
                    y[0] = log(o->scale_min);
                if (y[0] > log(o->scale_max))
                    y[0] = log(o->scale_max);
                if (y[3] < -o->max_angle)
                    y[3] = -o->max_angle;
                if (y[3] > o->max_angle)
                    y[3] = o->max_angle;
                p = align_from_vars(c, y);
                sc = align_eval(c, &p, l);
                evals++;
                if (sc > cand->score) {
                    memcpy(x, y, sizeof x);
                    cand->p = p;
                    cand->score = sc;
                    improved = 1;
                    break;
                }
            }
        }
        if (!improved)
            for (d = 0; d < 4; d++)
                st[d] *= 0.5;
    }
}

int align_find(const plane *ref, const plane *test, const align_opts *o, align_result *out)
{
    /* sizes of the smaller picture at the refinement levels: all
     * candidates are refined and ranked at the first, the best one at all */
    static const double stages[] = {64, 128, 256, 512};
    align_ctx c;
    align_cand cand[ALIGN_KEEP + 2 * ALIGN_SPREAD];
    double cap;
    int n, s, i, rc = 1;
    memset(&c, 0, sizeof c);
    c.rw = ref->w;
    c.rh = ref->h;
    c.tw = test->w;
    c.th = test->h;
    c.ref_blur = o->ref_blur > 0 ? o->ref_blur : 0;
    if (align_pyr_build(ref, &c.r))
        return -1;
    if (align_pyr_build(test, &c.t)) {
        align_pyr_free(&c.r);
        return -1;
    }
    /* the coarse search's cost grows with the scale range, the angle range
     * and the ratio of the sizes: refused before it starts when over the cap */
    cap = o->max_cost > 0 ? o->max_cost : ALIGN_MAX_COST;
    n = align_cost(&c, o) > cap ? (rc = 2, 0) : align_coarse(&c, o, cand);
    if (n < 0)
        rc = -1;
    /* the scale grid is coarse next to small pictures' detail: start the
     * refinement of the best candidates from the neighbouring scale steps
     * too */
    if (n > 0) {
        int m = n < ALIGN_SPREAD ? n : ALIGN_SPREAD;
        for (i = 0; i < m; i++) {
            cand[n + 2 * i] = cand[n + 2 * i + 1] = cand[i];
            cand[n + 2 * i].p.scale /= ALIGN_SCALE_STEP;
            cand[n + 2 * i + 1].p.scale *= ALIGN_SCALE_STEP;
        }
        n += 2 * m;
    }
    for (i = 0; i < n; i++)
        cand[i].level = -1;
    for (s = 0; n > 0 && s < (int)(sizeof stages / sizeof stages[0]); s++) {
        align_cand prev[ALIGN_KEEP + 2 * ALIGN_SPREAD];
        int changed = 0;
        memcpy(prev, cand, (size_t)n * sizeof cand[0]);
        for (i = 0; i < n; i++) {
            int l = align_level(&c, cand[i].p.scale, stages[s]);
            if (l != cand[i].level) {
                align_refine(&c, o, &cand[i], l, 0.25);
                changed = 1;
            }
            cand[i].level = l;
        }
        qsort(cand, (size_t)n, sizeof cand[0], align_cand_cmp);
        /* A level where the correlation collapses is dominated by detail
         * the other picture lacks (halftone dots, grain): stop at the level
         * before it. */
        if (changed && s > 0 && cand[0].score < ALIGN_DROP * prev[0].score) {
            cand[0] = prev[0];
            break;
        }
        /* Candidates are ranked once, at the first fine level, where each
         * is seen at the same size (about 64 pixels); after that only the
         * best is refined. */
        while (n > 1 && cand[n - 1].score <= ALIGN_INVALID)
            n--;
        n = n > 0 ? 1 : 0;
    }
    if (n > 0 && cand[0].score > ALIGN_INVALID)
        align_refine(&c, o, &cand[0], cand[0].level, 1.0 / 64);
    if (n > 0 && cand[0].score > ALIGN_INVALID) {
        out->p = cand[0].p;
        out->score = cand[0].score;
        rc = 0;
    }
    align_pyr_free(&c.r);
    align_pyr_free(&c.t);
    return rc;
}
