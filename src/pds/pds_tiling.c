/* pds_tiling — tilings from a tessellation function (modal).
 *
 * A lookup maps (u,v) to a cell index (i, j, k) and its distance to the
 * cell's edges, in exact fixed-point steps where the mode is fixed point:
 *   SQUARE    cell (i,j) = [i w, (i+1) w) x [j h, (j+1) h)
 *   BRICK     as SQUARE, odd rows j shifted right by offset * w
 *   TRIANGLE  equilateral triangles of side w; rows of height w*sqrt(3)/2
 *             along v; lattice basis (w, 0) and (w/2, h); k = 0 for the
 *             triangle pointing up, 1 for the one pointing down
 *   HEX       pointy-top hexagons: the Voronoi cells of that lattice, found
 *             as the nearest of the three corners of the containing triangle
 * A point within mortar/2 of a cell edge (closed band) gets mortar_attr;
 * otherwise the cell's id follows the rule (docs/pds.md). */
#include "pds/pds_kind.h"
#include <math.h>
#include "pds/pds_num.h"
#include "util/mem.h"

typedef struct tiling {
    int shape;
    num w, h;            /* cell width and height (TRIANGLE/HEX: h = w*sqrt(3)/2) */
    num shift;           /* BRICK odd-row shift */
    num half_w;          /* w / 2 */
    num hm;              /* mortar / 2, 0 = no mortar */
    pds_wide mw;         /* HEX: mortar * w */
    num k_inv3;          /* 1/sqrt(3) */
    num k_2inv3;         /* 2/sqrt(3) */
    num k_half3;         /* sqrt(3)/2 */
    int32_t mortar_attr;
    int rule;
    long step[3];        /* reduced mod n */
    uint32_t seed;
    int32_t *attrs; long n;
} tiling;

static void pds_tiling_release(void *impl)
{
    tiling *t = impl;
    if (t)
        mem_free(t->attrs);
    mem_free(t);
}

static long pds_tiling_mod(long a, long n) { long r = a % n; return r < 0 ? r + n : r; }

static int pds_tiling_compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_tiling *d = &def->tiling;
    tiling *t = mem_calloc(1, sizeof *t);
    size_t i;
    double r3 = sqrt(3.0), h;
    if (!t || !(t->attrs = mem_calloc(d->nattrs, sizeof *t->attrs))) {
        pds_tiling_release(t);
        return NS(pds_oom)(def, file, err);
    }
    for (i = 0; i < d->nattrs; i++)
        t->attrs[i] = d->attrs[i];
    t->n = (long)d->nattrs;
    t->shape = d->shape;
    h = (d->shape == PDS_TILE_SQUARE || d->shape == PDS_TILE_BRICK) ? d->size[1] : d->size[0] * r3 / 2;
    t->w = num_from_d(d->size[0]);
    t->h = num_from_d(h);
    t->half_w = num_from_d(d->size[0] / 2);
    t->shift = num_from_d(d->offset * d->size[0]);
    t->hm = num_from_d(d->mortar / 2);
    t->mw = pds_wide_from_d(d->mortar * d->size[0]);
    t->k_inv3 = num_from_d(1 / r3);
    t->k_2inv3 = num_from_d(2 / r3);
    t->k_half3 = num_from_d(r3 / 2);
    t->mortar_attr = d->mortar_attr;
    t->rule = d->rule;
    for (i = 0; i < 3; i++)
        t->step[i] = pds_tiling_mod(d->step[i], t->n);
    t->seed = d->seed;
    *out = t;
    return 0;
}

/* The cell's id by the assignment rule. */
static int32_t pds_tiling_cell_attr(const tiling *t, long i, long j, long k)
{
    if (t->rule == PDS_RULE_HASH) {
        uint32_t x = (uint32_t)i * 0x9E3779B1u ^ (uint32_t)j * 0x85EBCA77u ^ (uint32_t)k * 0xC2B2AE3Du ^ t->seed;
        x ^= x >> 16; x *= 0x7FEB352Du; x ^= x >> 15; x *= 0x846CA68Bu; x ^= x >> 16;
        return t->attrs[x % (uint32_t)t->n];
    }
    /* Each term is below n^2 <= 2^32: the sum fits in 64 bits. */
    return t->attrs[((int64_t)pds_tiling_mod(i, t->n) * t->step[0] + (int64_t)pds_tiling_mod(j, t->n) * t->step[1] +
                     (int64_t)k * t->step[2]) % t->n];
}

static int32_t pds_tiling_locate(const void *impl, num u, num v, unsigned long *steps)
{
    const tiling *t = impl;
    num lu, lv;
    long i, j;
    ++*steps;
    if (t->shape == PDS_TILE_SQUARE || t->shape == PDS_TILE_BRICK) {
        j = pds_num_floordiv(v, t->h, &lv);
        if (t->shape == PDS_TILE_BRICK && (j & 1))
            u = num_sub(u, t->shift);
        i = pds_num_floordiv(u, t->w, &lu);
        if (t->hm > 0 && (lu <= t->hm || lv <= t->hm || lu >= num_sub(t->w, t->hm) ||
                          lv >= num_sub(t->h, t->hm)))
            return t->mortar_attr;
        return pds_tiling_cell_attr(t, i, j, 0);
    } else {
        /* Lattice coordinates: row j and height lv in it; su = the offset
         * along the row from lattice point (i, j), in u units. */
        num su, s, up;
        long k;
        j = pds_num_floordiv(v, t->h, &lv);
        s = num_sub(num_sub(u, num_mul(num_from_i((int)(j & 1)), t->half_w)), num_mul(lv, t->k_inv3));
        /* j*w/2 taken as (j/2)*w + (j&1)*w/2, exact; (j/2)*w joins i. */
        i = pds_num_floordiv(s, t->w, &su) - j / 2;
        up = num_add(su, num_mul(lv, t->k_2inv3));        /* (fs + ft) * w */
        k = up >= t->w;                                    /* 0: lower, 1: upper triangle */
        if (t->shape == PDS_TILE_TRIANGLE) {
            if (t->hm > 0) {
                num d0, d1, d2;
                if (!k) {
                    d0 = lv;
                    d1 = num_mul(su, t->k_half3);
                    d2 = num_mul(num_sub(t->w, up), t->k_half3);
                } else {
                    d0 = num_sub(t->h, lv);
                    d1 = num_mul(num_sub(t->w, su), t->k_half3);
                    d2 = num_mul(num_sub(up, t->w), t->k_half3);
                }
                if (d0 <= t->hm || d1 <= t->hm || d2 <= t->hm)
                    return t->mortar_attr;
            }
            return pds_tiling_cell_attr(t, i, j, k);
        } else {
            /* Corners of the triangle relative to lattice point (i, j):
             * (0,0) (w,0) (w/2,h) for k = 0; (w,0) (w/2,h) (3w/2,h) for k = 1. */
            num x = num_add(su, num_mul(lv, t->k_inv3)), cx[3], cy[3];
            pds_wide dd[3];
            long ci[3], cj[3];
            int a, best = 0, second;
            cx[0] = k ? t->w : NUM_ZERO;        cy[0] = NUM_ZERO;  ci[0] = k ? i + 1 : i; cj[0] = j;
            cx[1] = k ? t->half_w : t->w;       cy[1] = k ? t->h : NUM_ZERO; ci[1] = k ? i : i + 1; cj[1] = k ? j + 1 : j;
            cx[2] = k ? num_add(t->w, t->half_w) : t->half_w; cy[2] = t->h; ci[2] = k ? i + 1 : i; cj[2] = j + 1;
            for (a = 0; a < 3; a++) {
                dd[a] = pds_wide_sq2(num_sub(x, cx[a]), num_sub(lv, cy[a]));
                if (dd[a] < dd[best])
                    best = a;
            }
            second = best == 0 ? 1 : 0;
            for (a = 0; a < 3; a++)
                if (a != best && dd[a] < dd[second])
                    second = a;
            if (t->hm > 0 && pds_wide_sub(dd[second], dd[best]) <= t->mw)
                return t->mortar_attr;
            /* Lattice point (ci, cj) in axial form: row cj, column ci. */
            return pds_tiling_cell_attr(t, ci[best], cj[best], 0);
        }
    }
}

static size_t pds_tiling_bytes(const void *impl)
{
    const tiling *t = impl;
    return sizeof *t + (size_t)t->n * sizeof *t->attrs;
}

const NS(pds_kind_ops) NS(pds_tiling_ops) = {
    .name = "tiling",
    .compile = pds_tiling_compile,
    .locate = pds_tiling_locate,
    .bytes = pds_tiling_bytes,
    .release = pds_tiling_release,
};
