/* prim — compile, intersect and evaluate the five primitives (see prim.h,
 * docs/primitives.md for the face mappings, docs/numerics.md for ranges). */
#include "geom/prim.h"
#include "model/scene_box.h"
#include "util/dmath.h"
#include "util/arena.h"
#include "util/mem.h"
#include "util/radix.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- compile (double precision) ------------------------------------- */

/* How prim_clip_planes forms a plane's n.d and n.o (prim->fast, 3 bits a
 * plane): two dot products; the previous plane's, negated, when n is
 * exactly its normal negated (the opposite faces of a block, a cylinder's
 * or cone's two caps); or the ray's own component when n is exactly a
 * coordinate axis: every mode forms 1 * c + 0 * c' + 0 * c'' exactly (up
 * to the sign of a zero). */
enum { PRIM_DOT_FULL, PRIM_DOT_FLIP, PRIM_DOT_X, PRIM_DOT_Y, PRIM_DOT_Z,
       PRIM_DOT_NX, PRIM_DOT_NY, PRIM_DOT_NZ };

static inline int prim_dot_code(const prim *p, int i)
{
    const vec3 *a = &p->pl[i].n, *b;
    num z = NUM_ZERO, one = NUM_ONE, mone = num_neg(NUM_ONE);
    if (i > 0) {
        b = &p->pl[i - 1].n;
        if (a->x == num_neg(b->x) && a->y == num_neg(b->y) && a->z == num_neg(b->z))
            return PRIM_DOT_FLIP;
    }
    if (a->y == z && a->z == z && (a->x == one || a->x == mone))
        return a->x == one ? PRIM_DOT_X : PRIM_DOT_NX;
    if (a->x == z && a->z == z && (a->y == one || a->y == mone))
        return a->y == one ? PRIM_DOT_Y : PRIM_DOT_NY;
    if (a->x == z && a->y == z && (a->z == one || a->z == mone))
        return a->z == one ? PRIM_DOT_Z : PRIM_DOT_NZ;
    return PRIM_DOT_FULL;
}

/* Rounds plane i of p from its double form to num. */
static void prim_round_nd(prim *p, int i)
{
    p->pl[i].n = vec3_from_d(p->pl_d[i]);
    p->pl[i].d = num_from_d(p->pl_d[i][3]);
}

/* Rounds plane i of p again (prim_share replaced it); then sets how the
 * clip forms its dot products and the next plane's, which may refer to it. */
static void prim_round_plane(prim *p, int i)
{
    int k;
    prim_round_nd(p, i);
    for (k = i; k <= i + 1 && k < p->nplanes; k++)
        p->fast = (p->fast & ~(7u << 3 * k)) | (unsigned)prim_dot_code(p, k) << 3 * k;
}

/* 1 when the n doubles at x are all finite: x * 0 is a zero for a finite
 * x and NaN for an infinity or NaN, so one comparison tests the sum. */
static int prim_finite(const double *x, int n)
{
    double z = 0;
    int i;
    for (i = 0; i < n; i++)
        z += x[i] * 0;
    return z == 0;
}

/* For prim->fast's top byte: PRIM_COLS | row i's column in bits 2i, 2i + 1
 * when each row of m has a single nonzero entry (a primitive placed without
 * rotation, or turned by right angles: the rounded cosines of 90 degrees
 * are zeros), else 0. */
#define PRIM_COLS 64u
static unsigned prim_cols(const mat3 *m)
{
    unsigned cols = PRIM_COLS;
    int i, j, nz;
    for (i = 0; i < 3; i++) {
        for (nz = 0, j = 0; j < 3; j++)
            if (m->m[3 * i + j] != NUM_ZERO) {
                nz++;
                cols |= (unsigned)j << 2 * i;
            }
        if (nz != 1)
            return 0;
    }
    return cols;
}

static int prim_fail(diag *err, const char *file, const scene_prim *sp, const char *what)
{
    return diag_at(err, DIAG_INPUT, file, sp->shape->loc.line, sp->shape->loc.col,
                   "primitive '%s': %s", sp->shape->name, what);
}

/* Canonical planes per kind: outward normal and a point; in face order
 * (plane k is face prim_plane_face(kind, k), as prim_face_plane assumes):
 * the block's XMIN..ZMAX, the caps' TOP and BOTTOM, the half-space's PLANE. */
typedef struct prim_cplane { double n[3], p[3]; } prim_cplane;

static const prim_cplane prim_block_planes[6] = {
    {{-1, 0, 0}, {0, 0, 0}}, {{1, 0, 0}, {1, 0, 0}}, {{0, -1, 0}, {0, 0, 0}},
    {{0, 1, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 0, 0}}, {{0, 0, 1}, {0, 0, 1}}};
static const prim_cplane prim_cap_planes[2] = {{{0, 0, 1}, {0, 0, 1}}, {{0, 0, -1}, {0, 0, 0}}};
static const prim_cplane prim_half_plane[1] = {{{0, 0, 1}, {0, 0, 0}}};

/* What prim_compile derives from p's kind, dimensions (cc, lo, hi: the
 * canonical box's centre and corners) and the linear part a of the
 * placement (canonical -> normalised world) alone: into lin its inverse
 * (p's frame then points at it), into p minv_s with its scale and the
 * shortcuts of its columns and the plane normals (pl_d[k][0..2]), and into
 * *r the bounding radius. */
static int prim_compile_linear(prim *p, prim_lin *lin, const scene_prim *sp, const double *a,
                               const double *cc, const double *lo, const double *hi,
                               const prim_cplane *cp, double *r, const char *file, diag *err)
{
    double frob = 0;
    int i, j;
    if (dmath_m3_inverse(a, lin->ainv_d))
        return prim_fail(err, file, sp, "transform is singular");
    p->fr->lin = lin;
    for (i = 0; i < 9; i++)
        frob += lin->ainv_d[i] * lin->ainv_d[i];
    frob = sqrt(frob);
    for (i = 0; i < 9; i++)
        p->minv_s.m[i] = num_from_d(lin->ainv_d[i] / frob);
    p->fast = prim_cols(&p->minv_s) << 24;
    p->smin = num_from_d(1.0 / frob);
    p->inv_smin = num_from_d(frob);
    if (p->bounded && (p->smin == NUM_ZERO || num_to_d(p->inv_smin) < frob * (1 - 1e-3)))
        return prim_fail(err, file, sp, "too small for the numeric range");
    *r = 0;
    if (sp->shape->kind == PRIM_SPHERE) {
        *r = dmath_m3_spectral_norm(a);
    } else if (p->bounded) {
        int k;
        /* lo and hi lie evenly about cc, so corner 7 - k is corner k negated
         * and its image as long to the bit: four corners give the radius */
        for (k = 0; k < 4; k++) {
            double corner[3], w[3], len;
            for (i = 0; i < 3; i++)
                corner[i] = ((k >> i) & 1 ? hi[i] : lo[i]) - cc[i];
            dmath_m3_mul_v(a, corner, w);
            len = dmath_len3(w);
            if (len > *r)
                *r = len;
        }
    }
    for (i = 0; i < p->nplanes; i++) {
        double len;
        dmath_m3_tmul_v(lin->ainv_d, cp[i].n, p->pl_d[i]);
        len = dmath_len3(p->pl_d[i]);
        for (j = 0; j < 3; j++)
            p->pl_d[i][j] /= len;
    }
    return 0;
}

/* prim_compile_linear's results taken from twin, compiled before from a
 * primitive of the same kind, dimensions and linear part (prim_twin): the
 * same operations on the same numbers, so the same values; its linear part
 * itself is shared. */
static void prim_compile_twin(prim *p, const prim *twin)
{
    int i;
    p->fr->lin = twin->fr->lin;
    p->minv_s = twin->minv_s;
    p->fast = twin->fast & ~0xffffffu;
    p->smin = twin->smin;
    p->inv_smin = twin->inv_smin;
    for (i = 0; i < p->nplanes; i++)
        memcpy(p->pl_d[i], twin->pl_d[i], 3 * sizeof p->pl_d[i][0]);
}

int NS(prim_compile)(const scene_prim *sp, int id, const geom_norm *nm, prim_plane *pl,
                     double (*pl_d)[4], prim_frame *fr, prim_lin *lin, const prim *twin, double *radius,
                     prim *out, const char *file, diag *err)
{
    prim p;
    double c[3] = {1, 1, 1}, cc[3] = {0, 0, 0}, lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    double r = 0, bc[3], a[9];
    const prim_cplane *cp = NULL;
    int i, j, ncp = 0, st;
    const double *d = sp->shape->dim, *m = sp->world_from_object;

    memset(&p, 0, sizeof p);
    if (!prim_finite(m, 12))
        return prim_fail(err, file, sp, "transform is not finite");
    if (!prim_finite(d, 3))
        return prim_fail(err, file, sp, "dimension is not finite");
    p.kind = sp->shape->kind;
    p.pl = pl;
    p.pl_d = pl_d;
    p.fr = fr;                  /* every field written below on success */
    p.id = id;
    p.attr = sp->attr;
    p.bounded = 1;
    switch (sp->shape->kind) {
    case PRIM_SPHERE:
        if (!(d[0] > 0)) return prim_fail(err, file, sp, "sphere radius must be positive");
        break;
    case PRIM_CYLINDER:
        if (!(d[0] > 0) || !(d[1] > 0))
            return prim_fail(err, file, sp, "cylinder radius and height must be positive");
        cc[2] = 0.5;
        cp = prim_cap_planes;
        ncp = 2;
        break;
    case PRIM_BLOCK:
        if (!(d[0] > 0) || !(d[1] > 0) || !(d[2] > 0))
            return prim_fail(err, file, sp, "block sizes must be positive");
        cc[0] = cc[1] = cc[2] = 0.5;
        cp = prim_block_planes;
        ncp = 6;
        break;
    case PRIM_CONE: {
        double rm = d[0] > d[1] ? d[0] : d[1];
        if (!(d[0] >= 0) || !(d[1] >= 0) || !(rm > 0) || !(d[2] > 0))
            return prim_fail(err, file, sp, "cone radii must be >= 0 (one > 0) and height > 0");
        cc[2] = 0.5;
        p.cone_a = num_from_d(d[0] / rm);
        p.cone_k = num_from_d(d[1] / rm - d[0] / rm);
        cp = prim_cap_planes;
        ncp = 2;
        break;
    }
    case PRIM_HALFSPACE:
        p.bounded = 0;
        cp = prim_half_plane;
        ncp = 1;
        break;
    default:
        return prim_fail(err, file, sp, "unknown primitive kind");
    }
    if (p.bounded)                /* the canonical box: model/scene_box.h */
        (void)scene_prim_canon_box(sp, c, lo);
    scene_canon_map(m, nm->scale, c, a);  /* scene_prim_canon_map's */
    p.nplanes = ncp;
    if (twin) {
        prim_compile_twin(&p, twin);
        r = *radius;
    } else if ((st = prim_compile_linear(&p, lin, sp, a, cc, lo, hi, cp, &r, file, err))) {
        return st;
    }
    for (i = 0; i < 3; i++)
        p.fr->org_d[i] = nm->scale * m[4 * i + 3] + nm->off[i];
    p.org = vec3_from_d(p.fr->org_d);

    /* bounding sphere */
    dmath_m3_mul_v(a, cc, bc);
    for (i = 0; i < 3; i++)
        bc[i] += p.fr->org_d[i];
    if (p.bounded) {
        for (i = 0; i < 3; i++)
            if (fabs(bc[i]) + r > 4 * GEOM_W)
                return prim_fail(err, file, sp, "outside the normalised scene (internal)");
        p.bc = vec3_from_d(bc);
        p.br = num_from_d(r * (1 + 1e-6) + 1.0 / 16384);
    }

    /* planar faces as world planes in double, rounded once (prim_share may
     * replace them by a coincident plane of another primitive) */
    for (i = 0; i < ncp; i++) {
        double pt[3];
        dmath_m3_mul_v(a, cp[i].p, pt);
        for (j = 0; j < 3; j++)
            pt[j] += p.fr->org_d[j];
        p.pl_d[i][3] = dmath_dot3(p.pl_d[i], pt);
#if !PRIM_PL_SHARED
        p.pl[i].face = prim_plane_face(p.kind, i);
#endif
        prim_round_nd(&p, i);
    }
    /* each code once all the planes it may refer to are rounded */
    for (i = 0; i < ncp; i++)
        p.fast |= (unsigned)prim_dot_code(&p, i) << 3 * i;
    *radius = r;
    *out = p;
    return 0;
}

/* Exact box: ellipsoid extents for the sphere, the two end discs for
 * cylinder and cone, the corners for the block. Computed when asked rather
 * than stored: only the CSG compile needs it. */
void NS(prim_box)(const prim *p, const double a[9], double lo_out[3], double hi_out[3])
{
    int i, k, kind = p->kind;
    if (!p->bounded) {
        memset(lo_out, 0, 3 * sizeof *lo_out);
        memset(hi_out, 0, 3 * sizeof *hi_out);
        return;
    }
    for (i = 0; i < 3; i++) {
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        if (kind == PRIM_SPHERE) {
            double h = sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]);
            lo = -h;
            hi = h;
        } else if (kind == PRIM_BLOCK) {
            for (k = 0; k < 8; k++) {
                double v = (k & 1 ? a[3 * i] : 0) + (k & 2 ? a[3 * i + 1] : 0) + (k & 4 ? a[3 * i + 2] : 0);
                if (v < lo) lo = v;
                if (v > hi) hi = v;
            }
        } else {
            double ra = kind == PRIM_CONE ? num_to_d(p->cone_a) : 1;
            double rb = kind == PRIM_CONE ? ra + num_to_d(p->cone_k) : 1;
            double h = sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1]);
            lo = -ra * h;
            hi = ra * h;
            if (a[3 * i + 2] - rb * h < lo) lo = a[3 * i + 2] - rb * h;
            if (a[3 * i + 2] + rb * h > hi) hi = a[3 * i + 2] + rb * h;
        }
        lo_out[i] = p->fr->org_d[i] + lo;
        hi_out[i] = p->fr->org_d[i] + hi;
    }
}

/* ---- one representation for coincident geometry --------------------- */

/* A plane in the sweep: its key and whose it is. The planes are read
 * where they lie (prim_pref_plane), not copied with their keys: on the
 * 10,000-object deck the scan misses the cache once per plane either way,
 * and a copy sorted through radix_order needed the planes twice (unsorted
 * and sorted, 6 MB each) where 2 MB now hold the sorted references. */
typedef struct prim_pref { double key; int prim, k; } prim_pref;

static double *prim_pref_plane(prim *prims, const prim_pref *e) { return prims[e->prim].pl_d[e->k]; }

/* The orientation (+1, -1) in which plane q equals plane r within
 * PRIM_SAME_TOL, or 0. */
static int prim_plane_same(const double *q, const double *r)
{
    int s, j;
    for (s = 1; s >= -1; s -= 2) {
        for (j = 0; j < 4 && fabs(q[j] - s * r[j]) <= PRIM_SAME_TOL; j++)
            ;
        if (j == 4)
            return s;
    }
    return 0;
}

/* 1 when b (its canonical map bm) is the same point set as a: b's
 * canonical solid maps onto a's by a symmetry of the canonical solid (any
 * rotation or reflection for the sphere; a rotation or reflection about z
 * for cylinder and cone, and for the cylinder also the flip z -> 1 - z). */
static int prim_same_solid(const prim *a, const prim *b, const double *bm)
{
    double s[9], w[3], t[3], e = PRIM_SAME_TOL;
    int i, j, k;
    if (a->kind != b->kind || !a->bounded || a->kind == PRIM_BLOCK
        || a->cone_a != b->cone_a || a->cone_k != b->cone_k)
        return 0;
    if (a->kind != PRIM_SPHERE) {           /* the axes first: s's third column,
                                               (0, 0, +-1) below, tells most
                                               pairs through one point apart */
        for (i = 0; i < 3; i++) {
            s[3 * i + 2] = 0;
            for (k = 0; k < 3; k++)
                s[3 * i + 2] += a->fr->lin->ainv_d[3 * i + k] * bm[3 * k + 2];
        }
        if (fabs(s[2]) > e || fabs(s[5]) > e || fabs(fabs(s[8]) - 1) > e)
            return 0;
    }
    for (i = 0; i < 3; i++)                 /* s = a^-1 b, t = a^-1 (org_b - org_a) */
        for (j = 0; j < 3; j++) {
            s[3 * i + j] = 0;
            for (k = 0; k < 3; k++)
                s[3 * i + j] += a->fr->lin->ainv_d[3 * i + k] * bm[3 * k + j];
        }
    dmath_sub3(b->fr->org_d, a->fr->org_d, w);
    dmath_m3_mul_v(a->fr->lin->ainv_d, w, t);
    for (i = 0; i < 3; i++)                 /* s orthogonal: s s^T = I */
        for (j = 0; j < 3; j++) {
            double dot = s[3 * i] * s[3 * j] + s[3 * i + 1] * s[3 * j + 1] + s[3 * i + 2] * s[3 * j + 2];
            if (fabs(dot - (i == j)) > e)
                return 0;
        }
    if (a->kind == PRIM_SPHERE)
        return fabs(t[0]) <= e && fabs(t[1]) <= e && fabs(t[2]) <= e;
    if (fabs(s[2]) > e || fabs(s[5]) > e || fabs(s[6]) > e || fabs(s[7]) > e
        || fabs(t[0]) > e || fabs(t[1]) > e)
        return 0;
    if (fabs(s[8] - 1) <= e)
        return fabs(t[2]) <= e;
    return a->kind == PRIM_CYLINDER && fabs(s[8] + 1) <= e && fabs(t[2] - 1) <= e;
}

/* A curved solid's sort key: the canonical point every symmetry
 * prim_same_solid allows keeps fixed (the sphere's centre, the middle of
 * the cylinder's or cone's axis) in the world, projected on a direction
 * w no grid of placements lines up with; and how far two keys of the same
 * solid can lie apart: prim_same_solid bounds the canonical offsets by 1.5
 * PRIM_SAME_TOL, which row k of the map stretches by at most its L1 norm,
 * below sqrt(3) times its L2 norm, weighted by |w_k|. */
typedef struct prim_skey {
    double key, win;
    size_t i;
    num cone_a, cone_k;
    float ax[3];       /* the axis, a unit vector; zeros: not compared */
    int kind;
} prim_skey;

/* The world axis (the third column of its map m) of cylinder or cone a as a unit
 * vector, or zeros for a sphere and for a solid so much wider than long
 * (largest radius column R over length L 2^20 or more) that the axes of two
 * placements of it prim_same_solid takes for one could lie far apart.
 * Elsewhere its test (third column of a^-1 b within PRIM_SAME_TOL of
 * (0, 0, +-1), formed with a relative rounding of about (R / L) 2^-52, at
 * most 2^-32) leaves the two axes within an angle whose sine is 2 R / L
 * times 2^-30 plus that rounding, below 2^-8: axes more than 60 degrees
 * apart tell solids apart (prim_skey_alike). */
static void prim_skey_axis(const prim *a, const double *m, float ax[3])
{
    double l = sqrt(m[2] * m[2] + m[5] * m[5] + m[8] * m[8]);
    double r0 = sqrt(m[0] * m[0] + m[3] * m[3] + m[6] * m[6]);
    double r1 = sqrt(m[1] * m[1] + m[4] * m[4] + m[7] * m[7]);
    int k;
    for (k = 0; k < 3; k++)
        ax[k] = 0;
    if (a->kind == PRIM_SPHERE || !(l > 0) || !((r0 > r1 ? r0 : r1) < 1048576.0 * l))
        return;
    for (k = 0; k < 3; k++)
        ax[k] = (float)(m[3 * k + 2] / l);
}

/* What prim_same_solid compares first, from the sweep's own records:
 * neighbours by key that differ here (a sphere and the cylinders through
 * its centre, or three bores through one point along three axes) are told
 * apart without reading either primitive. |cos| >= 1/2 between the axes,
 * or an axis not given (zeros: the test then holds). */
static int prim_skey_alike(const prim_skey *a, const prim_skey *b)
{
    float c = a->ax[0] * b->ax[0] + a->ax[1] * b->ax[1] + a->ax[2] * b->ax[2];
    float na = a->ax[0] * a->ax[0] + a->ax[1] * a->ax[1] + a->ax[2] * a->ax[2];
    float nb = b->ax[0] * b->ax[0] + b->ax[1] * b->ax[1] + b->ax[2] * b->ax[2];
    return a->kind == b->kind && a->cone_a == b->cone_a && a->cone_k == b->cone_k && c * c >= 0.25f * na * nb;
}

/* 1 when the solids of records a and b are the same (prim_skey_alike,
 * then prim_same_solid); bm holds b's canonical map once formed, bm[0]
 * NaN before: most solids meet no candidate alike and never need it. */
static int prim_skey_same(const prim *prims, const scene_prim *sps, double scale, const prim_skey *a,
                          const prim_skey *b, double *bm)
{
    if (!prim_skey_alike(a, b))
        return 0;
    if (isnan(bm[0]))
        scene_prim_canon_map(&sps[b->i], scale, bm);
    return prim_same_solid(&prims[a->i], &prims[b->i], bm);
}

/* The bytes of scratch prim_share works in for np planes, m curved solids
 * and n primitives, the larger of its two phases' needs (each part rounded
 * up to ARENA_ALIGN): the planes' references and the order that sorts
 * them, then the solids' records, their matches, keys and order.
 * One block for both: the second phase reuses the pages the first one
 * faulted in (docs/performance.md, run AH). 0 when that overflows. */
static size_t prim_share_bytes(size_t np, size_t m, size_t n)
{
    size_t rp = radix_bytes(np), rm = radix_bytes(m), a = ARENA_ALIGN, planes, solids;
    if (!rp || !rm || np > SIZE_MAX / 64 || m > SIZE_MAX / 256 || n > SIZE_MAX / 16)
        return 0;
    planes = rp + (np ? np : 1) * sizeof(prim_pref) + 2 * a;
    solids = n * sizeof(long) + m * sizeof(prim_skey) + rm + m * sizeof(uint64_t) + 4 * a;
    return planes > solids ? planes : solids;
}

/* Identical curved solids (m of the n primitives): the later one
 * intersects through the earliest matching one's data (its own frame
 * still gives (u,v)). Candidates come from a sweep over the sorted keys,
 * so n solids cost O(n log n) plus the pairs whose keys lie within the
 * window, not n^2 / 2 comparisons; of a run of equal keys (copies piled
 * at one place) only the earlier solids up to the first match.
 * Works in ar (prim_share_bytes). */
static void prim_share_solids(prim *prims, const scene_prim *sps, double scale, size_t n, size_t m, arena *ar)
{
    prim_skey *sk = arena_alloc(ar, m * sizeof *sk);
    long *match = arena_alloc(ar, n * sizeof *match);
    void *rb = arena_alloc(ar, radix_bytes(m));
    uint64_t *sort = arena_alloc(ar, m * sizeof *sort);
    size_t i, p, q, r0, r1;
    radix_ix *ord;
    m = 0;
    for (i = 0; i < n; i++) {
        const prim *a = &prims[i];
        static const double w[3] = {1, 0.7548776662466927, 0.5698402909980532};
        double cz = a->kind == PRIM_SPHERE ? 0 : 0.5, key = 0, win = 0, am[9];
        int k;
        match[i] = -1;
        if (!a->bounded || a->kind == PRIM_BLOCK)
            continue;
        scene_prim_canon_map(&sps[i], scale, am);
        for (k = 0; k < 3; k++) {
            const double *row = am + 3 * k;
            key += w[k] * (a->fr->org_d[k] + row[2] * cz);
            win += w[k] * sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]);
        }
        sk[m].key = key;
        sk[m].win = 4 * PRIM_SAME_TOL * win + 1e-12 * (fabs(key) + 1);
        sk[m].kind = a->kind;
        sk[m].cone_a = a->cone_a;
        sk[m].cone_k = a->cone_k;
        prim_skey_axis(a, am, sk[m].ax);
        sort[m] = radix_key_d(key);
        sk[m++].i = i;
    }
    /* by key, ties in index order: the records moved along each cycle of
     * the order in place (a sorted copy made the scratch's peak, run AT),
     * each place marked done by pointing at itself */
    ord = radix_order_in(sort, m, rb);
    for (p = 0; p < m; p++) {
        prim_skey t;
        if (ord[p] == p)
            continue;
        t = sk[p];
        for (q = p;;) {
            size_t from = ord[q];
            ord[q] = (radix_ix)q;
            if (from == p) {
                sk[q] = t;
                break;
            }
            sk[q] = sk[from];
            q = from;
        }
    }
    for (p = 0, r0 = r1 = 0; p < m; p++) {
        size_t bi = sk[p].i;
        double bm[9];
        bm[0] = NAN;          /* formed for the first candidate alike */
        if (p == r1) {            /* the run of keys equal to p's: [r0, r1) */
            r0 = p;
            for (r1 = p + 1; r1 < m && sk[r1].key == sk[p].key; r1++)
                ;
        }
        /* in the run the indices ascend: the first match is its earliest
         * (copies piled at one place cost one comparison each, not one
         * per earlier copy) */
        for (q = r0; q < p; q++)
            if (prim_skey_same(prims, sps, scale, &sk[q], &sk[p], bm)) {
                match[bi] = (long)sk[q].i;
                break;
            }
        /* the window's other keys, whatever their indices */
        for (q = r0; q-- > 0 && sk[p].key - sk[q].key <= 2 * sk[p].win;)
            if (sk[q].i < bi && (match[bi] < 0 || sk[q].i < (size_t)match[bi])
                && prim_skey_same(prims, sps, scale, &sk[q], &sk[p], bm))
                match[bi] = (long)sk[q].i;
        for (q = r1; q < m && sk[q].key - sk[p].key <= 2 * sk[p].win; q++)
            if (sk[q].i < bi && (match[bi] < 0 || sk[q].i < (size_t)match[bi])
                && prim_skey_same(prims, sps, scale, &sk[q], &sk[p], bm))
                match[bi] = (long)sk[q].i;
    }
    for (i = 0; i < n; i++)           /* in index order: an earlier copy is final */
        if (match[i] >= 0) {
            prim *b = &prims[i];
            const prim *a = &prims[match[i]];
            b->bc = a->bc;
            b->br = a->br;
            b->org = a->org;
            b->minv_s = a->minv_s;
            b->fast = (b->fast & 0xffffffu) | (a->fast & ~0xffffffu);
            b->smin = a->smin;
            b->inv_smin = a->inv_smin;
        }
}

int NS(prim_share)(prim *prims, const scene_prim *sps, double scale, size_t n, diag *err)
{
    prim_pref *pr;
    uint64_t *sort;
    arena ar;
    void *rb;
    size_t np = 0, m = 0, i, j, mark, bytes;
    radix_ix *rank;
    int k;
    for (i = 0; i < n; i++) {
        np += (size_t)prims[i].nplanes;
        m += prims[i].bounded && prims[i].kind != PRIM_BLOCK;
    }
    bytes = prim_share_bytes(np, m < 2 ? 0 : m, n);
    if (!bytes || arena_init(&ar, bytes))
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
    rb = arena_alloc(&ar, radix_bytes(np));
    mark = arena_mark(&ar);
    sort = arena_alloc(&ar, (np ? np : 1) * sizeof *sort);     /* every entry written below */
    np = 0;
    for (i = 0; i < n; i++)
        for (k = 0; k < prims[i].nplanes; k++)
            sort[np++] = radix_key_d(fabs(prims[i].pl_d[k][3]));
    /* planes sorted by |offset|, ties in (primitive, plane) order, each
     * stored straight at its place; each takes the nearest earlier plane
     * of another primitive that it equals within the tolerance, and that
     * one already holds its group's single representation */
    rank = radix_rank_in(sort, np, rb);
    arena_release(&ar, mark);           /* the keys: pr takes their place */
    pr = arena_alloc(&ar, (np ? np : 1) * sizeof *pr);
    np = 0;
    for (i = 0; i < n; i++)
        for (k = 0; k < prims[i].nplanes; k++) {
            prim_pref *e = &pr[rank[np++]];
            e->key = fabs(prims[i].pl_d[k][3]);
            e->prim = (int)i;
            e->k = k;
        }
    for (i = 0; i < np; i++) {
        double w[4];
        for (j = i; j-- > 0 && pr[i].key - pr[j].key <= PRIM_SAME_TOL;) {
            double *q = prim_pref_plane(prims, &pr[i]);
            const double *r = prim_pref_plane(prims, &pr[j]);
            int s;
            if (pr[j].prim == pr[i].prim || !(s = prim_plane_same(q, r)))
                continue;
            for (k = 0; k < 4; k++)
                w[k] = s * r[k];
            if (memcmp(q, w, sizeof w)) {   /* else already that plane, bit
                                               for bit: nothing to round */
                memcpy(q, w, sizeof w);
                prim_round_plane(&prims[pr[i].prim], pr[i].k);
            }
            break;
        }
    }
    arena_release(&ar, 0);
    if (m >= 2)
        prim_share_solids(prims, sps, scale, n, m, &ar);
    arena_free(&ar);
    return 0;
}

/* ---- intersection (num) -------------------------------------------- */

/* What the clip records for plane k (pl) as it goes, and the face that
 * makes at its end: the plane's own face where it holds one (the clip's
 * instructions as before the planes in double were shared); in binary64
 * the index, turned into the face for the two ends that win (+0.3 to 0.6 %
 * instructions in f64 renders, tools/icount.sh). */
#if PRIM_PL_SHARED
static inline int prim_clip_face(const prim_plane *pl, int k) { (void)pl; return k; }
static inline int prim_clip_face_end(int kind, int f) { return prim_plane_face(kind, f); }
#else
static inline int prim_clip_face(const prim_plane *pl, int k) { (void)k; return pl->face; }
static inline int prim_clip_face_end(int kind, int f) { (void)kind; return f; }
#endif

/* Intersects the span s with the half-spaces of p's planes. 0 if empty.
 * The entry and exit candidates are kept as fractions (positive
 * denominators) and compared by cross products, so only the two winners
 * are divided; an entry at or beyond the exit ends the test early. The dot
 * products n.d and n.o are formed as p->fast says: the shortcuts give the
 * values of the dot products themselves (every mode rounds symmetrically)
 * up to the sign of a zero, which no step below can see (zeros compare
 * equal and a zero numerator divides to NUM_ZERO), and in q16 up to
 * saturation, which n.o cannot reach (|o| < 16,100, docs/numerics.md). */
static int prim_clip_planes(const prim *p, const prim_ray *r, span *s)
{
    const num big = num_from_i(GEOM_TBIG);
    num an = NUM_ZERO, ad = NUM_ZERO, bn = NUM_ZERO, bd = NUM_ZERO, dn = NUM_ZERO, on = NUM_ZERO, t;
    int af = PRIM_FACE_NONE, bf = PRIM_FACE_NONE, k;
    unsigned code = p->fast;
    for (k = 0; k < p->nplanes; k++, code >>= 3) {
        const prim_plane *pl = &p->pl[k];
        num den, nm;
        switch (code & 7) {          /* all eight codes: no range check */
        case PRIM_DOT_FLIP: dn = num_neg(dn); on = num_neg(on); break;
        case PRIM_DOT_X: dn = r->d.x; on = r->o.x; break;
        case PRIM_DOT_Y: dn = r->d.y; on = r->o.y; break;
        case PRIM_DOT_Z: dn = r->d.z; on = r->o.z; break;
        case PRIM_DOT_NX: dn = num_neg(r->d.x); on = num_neg(r->o.x); break;
        case PRIM_DOT_NY: dn = num_neg(r->d.y); on = num_neg(r->o.y); break;
        case PRIM_DOT_NZ: dn = num_neg(r->d.z); on = num_neg(r->o.z); break;
        default: /* PRIM_DOT_FULL */ dn = vec3_dot(pl->n, r->d); on = vec3_dot(pl->n, r->o); break;
        }
        den = dn;
        nm = num_sub(pl->d, on);
        if (den == NUM_ZERO) {
            if (nm < NUM_ZERO)
                return 0;
            continue;
        }
        /* entry against exit only when one of them moved: the pair as it
         * stood has passed (or both were unset) */
        if (den < NUM_ZERO) {
            nm = num_neg(nm);
            den = num_neg(den);
            if (ad == NUM_ZERO || num_frac_gt(nm, den, an, ad)) {
                an = nm; ad = den; af = prim_clip_face(pl, k);
                if (bd != NUM_ZERO && !num_frac_gt(bn, bd, an, ad))
                    return 0;
            }
        } else if (bd == NUM_ZERO || num_frac_gt(bn, bd, nm, den)) {
            bn = nm; bd = den; bf = prim_clip_face(pl, k);
            if (ad != NUM_ZERO && !num_frac_gt(bn, bd, an, ad))
                return 0;
        }
    }
    if (ad != NUM_ZERO && (t = num_div_clamp(an, ad, big)) > s->a.t) {
        s->a.t = t;
        s->a.face = prim_clip_face_end(p->kind, af);
    }
    if (bd != NUM_ZERO && (t = num_div_clamp(bn, bd, big)) < s->b.t) {
        s->b.t = t;
        s->b.face = prim_clip_face_end(p->kind, bf);
    }
    return s->a.t < s->b.t;
}

/* minv_s v. q16: where each row of minv_s has a single nonzero entry
 * (prim_cols), that entry's rounded product alone: mat3_mul's sum of it and
 * two zero products, without them. */
VEC_HOT vec3 prim_map(const prim *p, vec3 v)
{
#if defined(NUM_MODE_q16)
    unsigned cols = p->fast >> 24;
    if (cols) {
        const num *m = p->minv_s.m;
        unsigned c0 = cols & 3, c1 = cols >> 2 & 3, c2 = cols >> 4 & 3;
        num c[3];
        c[0] = v.x; c[1] = v.y; c[2] = v.z;
        return vec3_make(num_mul(m[c0], c[c0]), num_mul(m[3 + c1], c[c1]), num_mul(m[6 + c2], c[c2]));
    }
#endif
    return mat3_mul(&p->minv_s, v);
}

/* Local interval [s0,s1] of the curved face, with flags saying whether each
 * end is a real surface point (1) or the clamp (0). Up to two pieces. */
typedef struct prim_piece { num s0, s1; int f0, f1; } prim_piece;

/* Solves the curved face of a sphere, cylinder or cone in the canonical
 * frame and intersects the result with s (world parameters). tc is the
 * parameter of the ray point closest to the bounding-sphere centre; the
 * origin is moved there first and then to the point closest to the
 * canonical centre, so every squared quantity is O(1) (docs/numerics.md).
 * Out of line: the plane clip before it (all a block needs, and where most
 * misses end) then keeps a smaller frame. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int prim_side(const prim *p, const prim_ray *r, num tc, span *s)
{
    vec3 ol = vec3_scale(prim_map(p, vec3_madd_sub(r->o, tc, r->d, p->org)), p->inv_smin);
    vec3 du, cl, rel;
    num L, rL, ratio, sh, lim, two = num_from_i(2), one = NUM_ONE;
    prim_piece pc[2];
    int npc = 1, k, side = p->kind == PRIM_SPHERE ? PRIM_FACE_SPHERE_SURFACE : PRIM_FACE_CYL_SIDE;

    if (vec3_unit(prim_map(p, r->d), &du, p->kind == PRIM_SPHERE ? NULL : &L, &rL))
        return 0;
    ratio = num_mul(p->smin, rL);      /* world parameter per local one */
    cl = vec3_make(NUM_ZERO, NUM_ZERO, p->kind == PRIM_SPHERE ? NUM_ZERO : NUM_HALF);
    sh = vec3_dot(vec3_sub(cl, ol), du);
    rel = vec3_madd_sub(ol, sh, du, cl);
    if (vec3_maxabs(rel) > two)
        return 0;
    /* the bound of the roots, br / ratio = br |minv_s d| / smin (a sphere's
     * roots are within 1 and need none) */
    lim = one;
    if (p->kind != PRIM_SPHERE) {
        lim = num_add(num_mul_clamp(num_mul(p->br, L), p->inv_smin, num_from_i(GEOM_TBIG)), num_abs(sh));
        if (lim < one)
            lim = one;
    }
    pc[0].f0 = pc[0].f1 = 1;

    if (p->kind == PRIM_SPHERE) {
        num disc = num_sub(one, vec3_dot(rel, rel)), h;
        if (disc < NUM_ZERO)
            return 0;
        h = num_sqrt(disc);
        pc[0].s0 = num_neg(h);
        pc[0].s1 = h;
    } else if (p->kind == PRIM_CYLINDER) {
        vec3 e, r2 = vec3_make(rel.x, rel.y, NUM_ZERO), perp;
        num a, b2, disc, h;
        if (vec3_normalize(vec3_make(du.x, du.y, NUM_ZERO), &e, &a)) {
            if (num_add(num_mul(rel.x, rel.x), num_mul(rel.y, rel.y)) > one)
                return 0;
            pc[0].s0 = num_neg(lim);
            pc[0].s1 = lim;
            pc[0].f0 = pc[0].f1 = 0;
        } else {
            b2 = vec3_dot(r2, e);
            perp = vec3_madd_sub(r2, num_neg(b2), e, vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
            if (vec3_maxabs(perp) > one)
                return 0;
            disc = num_sub(one, vec3_dot(perp, perp));
            if (disc < NUM_ZERO)
                return 0;
            h = num_sqrt(disc);
            pc[0].s0 = num_div_clamp(num_sub(num_neg(b2), h), a, lim);
            pc[0].s1 = num_div_clamp(num_add(num_neg(b2), h), a, lim);
        }
    } else {
        /* cone: x^2 + y^2 = R^2, R = a + k z; with X = rel + s du (about the
         * centre z = 1/2): f(s) = A s^2 + 2 B s + C, inside where f <= 0. */
        num kd = num_mul(p->cone_k, du.z);
        num r0 = num_add(p->cone_a, num_mul(p->cone_k, num_add(NUM_HALF, rel.z)));
        num A = num_sub(num_add(num_mul(du.x, du.x), num_mul(du.y, du.y)), num_mul(kd, kd));
        num B = num_sub(num_add(num_mul(rel.x, du.x), num_mul(rel.y, du.y)), num_mul(r0, kd));
        num C = num_sub(num_add(num_mul(rel.x, rel.x), num_mul(rel.y, rel.y)), num_mul(r0, r0));
        num disc, h, q, x0, x1;
        if (A == NUM_ZERO) {
            if (B == NUM_ZERO) {
                if (C > NUM_ZERO)
                    return 0;
                pc[0].s0 = num_neg(lim); pc[0].s1 = lim; pc[0].f0 = pc[0].f1 = 0;
            } else {
                num sr = num_div_clamp(num_neg(C), num_add(B, B), lim);
                if (B > NUM_ZERO) { pc[0].s0 = num_neg(lim); pc[0].f0 = 0; pc[0].s1 = sr; }
                else { pc[0].s0 = sr; pc[0].s1 = lim; pc[0].f1 = 0; }
            }
        } else {
            disc = num_sub(num_mul(B, B), num_mul(A, C));
            if (disc < NUM_ZERO) {
                if (A > NUM_ZERO)
                    return 0;
                pc[0].s0 = num_neg(lim); pc[0].s1 = lim; pc[0].f0 = pc[0].f1 = 0;
            } else {
                h = num_sqrt(disc);
                q = B >= NUM_ZERO ? num_neg(num_add(B, h)) : num_sub(h, B);
                if (q == NUM_ZERO) {
                    x0 = x1 = NUM_ZERO;
                } else {
                    x0 = num_div_clamp(q, A, lim);
                    x1 = num_div_clamp(C, q, lim);
                }
                if (x0 > x1) { num t = x0; x0 = x1; x1 = t; }
                if (A > NUM_ZERO) {
                    pc[0].s0 = x0; pc[0].s1 = x1;
                } else {
                    pc[0].s0 = num_neg(lim); pc[0].f0 = 0; pc[0].s1 = x0;
                    pc[1].s0 = x1; pc[1].s1 = lim; pc[1].f0 = 1; pc[1].f1 = 0;
                    npc = 2;
                }
            }
        }
    }
    /* the ends are kept apart, not as a copy of *s: a struct copy would
     * load in one piece what was stored field by field, and the store
     * would not forward (a stall of some 15 cycles a test) */
    for (k = 0; k < npc; k++) {
        num t0 = num_add(tc, num_mul(num_add(sh, pc[k].s0), ratio));
        num t1 = num_add(tc, num_mul(num_add(sh, pc[k].s1), ratio));
        num at = s->a.t, bt = s->b.t;
        int af = s->a.face, bf = s->b.face;
        if (t0 > at) { at = t0; af = pc[k].f0 ? side : PRIM_FACE_NONE; }
        if (t1 < bt) { bt = t1; bf = pc[k].f1 ? side : PRIM_FACE_NONE; }
        if (at < bt) {
            s->a.t = at; s->a.face = af;
            s->b.t = bt; s->b.face = bf;
            return 1;
        }
    }
    return 0;
}

int NS(prim_intersect_spans)(const prim *p, const prim_ray *r, num tc, span *out)
{
    const num big = num_from_i(GEOM_TBIG);
    /* built in *out itself (see prim_side): on a miss *out is undefined */
    out->a.t = num_neg(big);
    out->b.t = big;
    out->a.prim = out->b.prim = p->id;
    out->a.face = out->b.face = PRIM_FACE_NONE;
    if (!prim_clip_planes(p, r, out))
        return 0;
    if ((p->kind == PRIM_SPHERE || p->kind == PRIM_CYLINDER || p->kind == PRIM_CONE)
        && !prim_side(p, r, tc, out))
        return 0;
    if (r->excl_prim == p->id) {
        if (out->b.t <= NUM_ZERO)
            return 0;
        out->a.t = NUM_ZERO;
    }
    return 1;
}

int NS(prim_intersect)(const prim *p, const prim_ray *r, num tmin, num tmax, span *out)
{
    num tc = NUM_ZERO;
    /* The bound only rejects: span ends always come from faces, so a
     * rounding difference between bound and face cannot hide a face. */
    if (p->bounded && vec3_sphere_miss(p->bc, p->br, r->o, r->d, tmin, tmax, &tc))
        return 0;
    return NS(prim_intersect_tc)(p, r, tc, out);
}

/* ---- surface evaluation (double) ----------------------------------- */

static double prim_clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

/* prim_face_normal, inlined into prim_surface */
static inline const double *prim_flat_normal(const prim *p, int face)
{
    static const double none[3];   /* a face number the kind has no plane for */
    int k;
    if (p->kind == PRIM_SPHERE || (p->kind != PRIM_BLOCK && p->kind != PRIM_HALFSPACE
                                   && face == PRIM_FACE_CYL_SIDE))
        return NULL;
    k = prim_face_plane(p->kind, face >= 0 && face < 6 ? face : 0);
    return k >= 0 ? p->pl_d[k] : none;
}

const double *NS(prim_face_normal)(const prim *p, int face)
{
    return prim_flat_normal(p, face);
}

void NS(prim_surface)(const prim *p, int face, vec3 pt, const double *map, geom_surface *out)
{
    double w[3], l[3], nl[3] = {0, 0, 0}, du[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
    double u = 0, v = 0, rho = 0, th = 0, ct = 1, st = 0, len;
    const double *fn;
    int i;
    vec3_to_d(pt, w);
    for (i = 0; i < 3; i++)
        out->p[i] = w[i];
    if (!map && (fn = prim_flat_normal(p, face)) != NULL) {
        /* a planar face: its normal is stored, nothing else is asked for */
        for (i = 0; i < 3; i++)
            out->n[i] = fn[i];
        return;
    }
    for (i = 0; i < 3; i++)
        w[i] -= p->fr->org_d[i];
    dmath_m3_mul_v(p->fr->lin->ainv_d, w, l);
    /* the sphere's normal alone needs no angle */
    if (map || p->kind != PRIM_SPHERE) {
        rho = sqrt(l[0] * l[0] + l[1] * l[1]);
        if (rho > 0) {
            ct = l[0] / rho;
            st = l[1] / rho;
        }
    }
    if (map) {
        th = atan2(l[1], l[0]);
        if (th < 0)
            th += 2 * DMATH_PI;
    }
    switch (p->kind) {
    case PRIM_SPHERE:
        u = th / (2 * DMATH_PI);
        v = map ? 0.5 + atan2(l[2], rho) / DMATH_PI : 0;
        nl[0] = l[0]; nl[1] = l[1]; nl[2] = l[2];
        du[0] = -2 * DMATH_PI * l[1]; du[1] = 2 * DMATH_PI * l[0];
        dv[0] = -DMATH_PI * l[2] * ct; dv[1] = -DMATH_PI * l[2] * st; dv[2] = DMATH_PI * rho;
        break;
    case PRIM_CYLINDER:
    case PRIM_CONE: {
        double a = num_to_d(p->cone_a), k = num_to_d(p->cone_k), rf;
        if (p->kind == PRIM_CYLINDER) { a = 1; k = 0; }
        if (face == PRIM_FACE_CYL_SIDE) {
            u = th / (2 * DMATH_PI);
            v = l[2];
            nl[0] = ct; nl[1] = st; nl[2] = -k;
            du[0] = -2 * DMATH_PI * l[1]; du[1] = 2 * DMATH_PI * l[0];
            dv[0] = k * ct; dv[1] = k * st; dv[2] = 1;
        } else {
            rf = face == PRIM_FACE_CYL_TOP ? a + k : a;
            if (rf <= 0) {
                u = v = 0.5;
            } else if (face == PRIM_FACE_CYL_TOP) {
                u = (l[0] / rf + 1) / 2; v = (l[1] / rf + 1) / 2;
            } else {
                u = (1 - l[0] / rf) / 2; v = (l[1] / rf + 1) / 2;
            }
            du[0] = face == PRIM_FACE_CYL_TOP ? 2 * rf : -2 * rf;
            dv[1] = 2 * rf;
        }
        break;
    }
    case PRIM_BLOCK:
        switch (face) {
        case PRIM_FACE_BLOCK_XMIN: u = 1 - l[1]; v = l[2]; du[1] = -1; dv[2] = 1; break;
        case PRIM_FACE_BLOCK_XMAX: u = l[1]; v = l[2]; du[1] = 1; dv[2] = 1; break;
        case PRIM_FACE_BLOCK_YMIN: u = l[0]; v = l[2]; du[0] = 1; dv[2] = 1; break;
        case PRIM_FACE_BLOCK_YMAX: u = 1 - l[0]; v = l[2]; du[0] = -1; dv[2] = 1; break;
        case PRIM_FACE_BLOCK_ZMIN: u = 1 - l[0]; v = l[1]; du[0] = -1; dv[1] = 1; break;
        default:              u = l[0]; v = l[1]; du[0] = 1; dv[1] = 1; break;
        }
        break;
    default: /* half-space: unit tiles of the object frame */
        u = l[0] - floor(l[0]);
        v = l[1] - floor(l[1]);
        du[0] = 1; dv[1] = 1;
        break;
    }
    if (map) {
        out->u = prim_clamp01(u);
        out->v = prim_clamp01(v);
        dmath_m3_mul_v(map, du, out->dpdu);
        dmath_m3_mul_v(map, dv, out->dpdv);
    }
    if ((fn = prim_flat_normal(p, face)) != NULL) {
        for (i = 0; i < 3; i++)
            out->n[i] = fn[i];
    } else {
        dmath_m3_tmul_v(p->fr->lin->ainv_d, nl, out->n);
        len = dmath_len3(out->n);
        if (len > 0)
            for (i = 0; i < 3; i++)
                out->n[i] /= len;
    }
}
