/* scene_inst — objects that are copies of an earlier object moved by one
 * rigid motion (see scene_inst.h). */
#include "model/scene_inst.h"
#include "model/prim_twin.h"
#include "model/scene_box.h"
#include "util/dmath.h"
#include "util/mem.h"
#include "util/radix.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

/* One step of an object's tree in preorder: the operator, and for a leaf
 * its primitive's place among the object's (index - first). */
typedef struct si_step { int op, off; } si_step;

typedef struct si_obj {
    size_t seq;          /* its steps: steps[seq .. seq + nseq - 1] */
    int nseq, first, count;
    int usable;          /* a tree of bounded primitives of its own */
    int half;            /* it holds a half-space */
    int master;          /* the object it copies, or -1 */
    int meets;           /* its box comes within gap of another's */
    int turned;          /* turned: the motion from its master is
                            p -> rot[i] p + c (si_ctx); else p -> p + c */
    int inv_state;       /* as a master: 0 inv[i] not formed, 1 formed,
                            -1 its first primitive's linear part
                            singular */
    uint64_t hash;
    double c[3];
    double size;         /* its first primitive's linear part's squared
                            Frobenius norm, which a rotation keeps */
    double lo[3], hi[3]; /* its box; lo[0] > hi[0]: none */
} si_obj;

typedef struct si_ctx {
    const scene *sc;
    si_obj *o;
    si_step *steps;
    size_t nsteps, cap;
    int *owner;          /* per primitive: the object using it, -1 none,
                            -2 more than one */
    int *stk;
    size_t scap;
    double (*rot)[9];    /* per object, formed once one is turned: its
                            rotation from its master */
    double (*inv)[9];    /* per object as a master, likewise: its first
                            primitive's linear part's inverse */
} si_ctx;

/* Earlier objects of an object's hash it is compared with at most: past
 * that (many objects alike in all but their primitives' places) it is
 * neither an instance nor a master, so n objects cost O(n). */
#define SI_TRIES 8

/* Relative difference of si_obj.size beyond which two objects are not
 * copies: a rotation orthonormal within SCENE_INST_ORTHO and the
 * tolerance of the placement change it by orders of magnitude less. */
#define SI_SIZE_TOL 1e-6

static uint64_t si_mix(uint64_t h, uint64_t w) { return (h ^ w) * 0x100000001b3u; }

/* Records object i's steps, hash, primitives and usability. -1 when memory
 * runs out; 1 when the scene's trees hold more steps than nodes (a node
 * shared or a cycle, which the CSG compiler refuses): nothing is sought. */
static int si_walk(si_ctx *x, int i)
{
    const scene *sc = x->sc;
    si_obj *o = &x->o[i];
    size_t top = 0, k;
    int lo = INT32_MAX, hi = -1;
    uint64_t h = 0xcbf29ce484222325u;
    o->seq = x->nsteps;
    o->usable = 1;
    o->master = -1;
    o->lo[0] = 1;
    o->hi[0] = 0;
    if (mem_grow((void **)&x->stk, &x->scap, 1, sizeof *x->stk))
        return -1;
    x->stk[top++] = sc->roots[i];
    while (top) {
        int n = x->stk[--top];
        const scene_node *nd;
        si_step *st;
        if (n < 0 || (size_t)n >= sc->nnodes)
            return 1;
        if (x->nsteps >= sc->nnodes || mem_grow((void **)&x->steps, &x->cap, x->nsteps + 1, sizeof *x->steps))
            return x->nsteps >= sc->nnodes ? 1 : -1;
        nd = &sc->nodes[n];
        st = &x->steps[x->nsteps++];
        st->op = nd->op;
        st->off = nd->op == CSG_LEAF ? nd->prim : 0;
        h = si_mix(h, (uint64_t)nd->op);
        if (nd->op == CSG_LEAF) {
            if (nd->prim < 0 || (size_t)nd->prim >= sc->nprims)
                return 1;
            lo = nd->prim < lo ? nd->prim : lo;
            hi = nd->prim > hi ? nd->prim : hi;
            o->half |= sc->prims[nd->prim].shape->kind == PRIM_HALFSPACE;
            x->owner[nd->prim] = x->owner[nd->prim] == -1 ? i : -2;
            continue;
        }
        if (mem_grow((void **)&x->stk, &x->scap, top + 2, sizeof *x->stk))
            return -1;
        x->stk[top++] = nd->right;
        x->stk[top++] = nd->left;
    }
    o->nseq = (int)(x->nsteps - o->seq);
    o->first = lo;
    o->count = 0;
    /* the hash: the operators, the leaves' places, kinds and dimensions,
     * which a rigid motion keeps (objects alike in those but not in the
     * rest cost SI_TRIES comparisons at most) */
    for (k = o->seq; k < x->nsteps; k++)
        if (x->steps[k].op == CSG_LEAF) {
            const scene_prim *sp = &sc->prims[x->steps[k].off];
            uint64_t w[3];
            memcpy(w, sp->shape->dim, sizeof w);
            x->steps[k].off -= lo;
            h = si_mix(si_mix(h, (uint64_t)x->steps[k].off), (uint64_t)sp->shape->kind);
            if (!o->count++) {
                const double *m = sp->world_from_object;
                int j;
                h = si_mix(si_mix(si_mix(h, w[0]), w[1]), w[2]);
                for (j = 0, o->size = 0; j < 12; j++)
                    o->size += j % 4 == 3 ? 0 : m[j] * m[j];
            }
        }
    o->usable &= !o->half && o->count > 0 && hi - lo + 1 == o->count;
    o->hash = h;
    return 0;
}

/* The rotation r (row-major) that carries primitive a, the first of
 * master m, onto b (r = B A^-1, A and B the linear parts of their
 * world_from_object; A^-1 formed once per master): 0, or -1 when there is
 * none within SCENE_INST_ORTHO (a singular A, a scale, a shear, a
 * reflection). */
static int si_rotation(si_obj *m, double minv[9], const scene_prim *a, const scene_prim *b, double r[9])
{
    const double *ma = a->world_from_object, *mb = b->world_from_object, *inv = minv;
    double det;
    int i, j, k;
    if (!m->inv_state) {
        double la[9] = {ma[0], ma[1], ma[2], ma[4], ma[5], ma[6], ma[8], ma[9], ma[10]};
        m->inv_state = dmath_m3_inverse(la, minv) ? -1 : 1;
    }
    if (m->inv_state < 0)
        return -1;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            r[3 * i + j] = mb[4 * i] * inv[j] + mb[4 * i + 1] * inv[3 + j] + mb[4 * i + 2] * inv[6 + j];
    for (i = 0; i < 3; i++)       /* r^T r = I */
        for (j = 0; j < 3; j++) {
            double g = 0;
            for (k = 0; k < 3; k++)
                g += r[3 * k + i] * r[3 * k + j];
            if (!(fabs(g - (i == j)) <= SCENE_INST_ORTHO))
                return -1;
        }
    det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) + r[2] * (r[3] * r[7] - r[4] * r[6]);
    return det > 0 ? 0 : -1;
}

/* 1 when primitive a moved by rot and c lands on primitive b within tol:
 * on every row of world_from_object the difference of the translation
 * plus those of the linear part, each times the reach x of the solid
 * along its axis (its canonical box's), at most tol; so no point of the
 * solid moves farther than tol on any axis. */
static int si_lands(const scene_prim *a, const scene_prim *b, const double rot[9], const double c[3], double tol)
{
    const double *ma = a->world_from_object, *mb = b->world_from_object;
    double x[3], l[3];
    int i, j;
    if (scene_prim_canon_box(a, x, l))
        return 0;
    for (i = 0; i < 3; i++) {
        const double *ri = rot + 3 * i;
        double e = fabs(ri[0] * ma[3] + ri[1] * ma[7] + ri[2] * ma[11] + c[i] - mb[4 * i + 3]);
        for (j = 0; j < 3; j++)
            e += fabs(ri[0] * ma[j] + ri[1] * ma[4 + j] + ri[2] * ma[8 + j] - mb[4 * i + j]) * x[j];
        if (!(e <= tol))
            return 0;
    }
    return 1;
}

/* 1 when twins a and b lie apart by c within tol on every axis: si_lands
 * with the identity, whose linear parts twins have alike. */
static int si_moved(const scene_prim *a, const scene_prim *b, const double c[3], double tol)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!(fabs(b->world_from_object[4 * j + 3] - a->world_from_object[4 * j + 3] - c[j]) <= tol))
            return 0;
    return 1;
}

/* 1 when object i copies object m (scene_inst.h), with the motion from m
 * to i in i->c, i->turned and x->rot[i]; -1 when memory runs out. The
 * first primitives decide the motion: twins, the identity and the
 * difference of their translations; otherwise the rotation between their
 * linear parts, and the translation that then carries the one's origin
 * onto the other's. */
static int si_same(si_ctx *x, si_obj *m, si_obj *i, double tol)
{
    static const double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const scene *sc = x->sc;
    const si_step *a = x->steps + m->seq, *b = x->steps + i->seq;
    const double *rot = id;
    size_t n = sc->nroots;
    int k, j, leaf = 0;
    /* objects of one tree at different scales: told apart at once
     * (a copy's size is its master's to within far less) */
    if (!(fabs(i->size - m->size) <= SI_SIZE_TOL * m->size))
        return 0;
    if (m->nseq != i->nseq || m->count != i->count || memcmp(a, b, (size_t)m->nseq * sizeof *a))
        return 0;
    for (k = 0; k < m->nseq; k++) {
        const scene_prim *pm, *pi;
        if (a[k].op != CSG_LEAF)
            continue;
        pm = &sc->prims[m->first + a[k].off];
        pi = &sc->prims[i->first + a[k].off];
        if (!scene_shape_alike(pm->shape, pi->shape))
            return 0;
        if (!leaf++) {
            const double *mm = pm->world_from_object, *mi = pi->world_from_object;
            if ((i->turned = !prim_twin_same(pm, pi))) {
                if (!x->rot && (!(x->rot = mem_alloc(n * sizeof *x->rot)) || !(x->inv = mem_alloc(n * sizeof *x->inv))))
                    return -1;
                rot = x->rot[i - x->o];
                if (si_rotation(m, x->inv[m - x->o], pm, pi, x->rot[i - x->o]))
                    return 0;
            }
            for (j = 0; j < 3; j++)
                i->c[j] = mi[4 * j + 3] - (rot[3 * j] * mm[3] + rot[3 * j + 1] * mm[7] + rot[3 * j + 2] * mm[11]);
            if (!(isfinite(i->c[0]) && isfinite(i->c[1]) && isfinite(i->c[2])))
                return 0;
        }
        if (i->turned ? !si_lands(pm, pi, rot, i->c, tol) : !prim_twin_same(pm, pi) || !si_moved(pm, pi, i->c, tol))
            return 0;
    }
    return leaf;
}

/* Object o's box, as the CSG compiler bounds its tree: a leaf by its
 * primitive's box, a union by the union of its operands' boxes, an
 * intersection by their intersection, a difference by its left operand's;
 * for an object with a half-space (unbounded or cut by a plane), the union
 * of its bounded primitives' boxes, where every surface of it off its
 * planes lies (si_planes keeps instances off those).
 * Its steps are read backwards, so each operator finds its left operand's
 * box on top of the stack and its right one's below (stk: room for nseq
 * boxes). A first pass forwards marks the leaves the result depends on
 * (need: room for 2 nseq + 1), none under a difference's right operand:
 * the others' boxes are not formed (a part's bores: three of its five).
 * An empty box (lo[0] > hi[0]) holds nothing. */
static void si_box(const si_ctx *x, si_obj *o, double (*stk)[6], unsigned char *need)
{
    const si_step *s = x->steps + o->seq;
    unsigned char *pend = need + o->nseq;   /* the operands to come, in
                                               preorder: left on top */
    int k, j, top = 0, np = 0;
    if (o->half) {
        for (j = 0; j < 3; j++) {
            o->lo[j] = HUGE_VAL;
            o->hi[j] = -HUGE_VAL;
        }
        for (k = 0; k < o->nseq; k++)
            if (s[k].op == CSG_LEAF)
                scene_prim_grow_tight_box(&x->sc->prims[o->first + s[k].off], o->lo, o->hi);
        return;                   /* none: lo[0] > hi[0] */
    }
    pend[np++] = 1;
    for (k = 0; k < o->nseq; k++) {
        need[k] = pend[--np];
        if (s[k].op != CSG_LEAF) {
            pend[np++] = need[k] && s[k].op != CSG_DIFF;
            pend[np++] = need[k];
        }
    }
    for (k = o->nseq; k-- > 0;) {
        double *b;
        if (s[k].op == CSG_LEAF) {
            b = stk[top++];
            for (j = 0; j < 3; j++) {
                b[j] = HUGE_VAL;
                b[3 + j] = -HUGE_VAL;
            }
            if (need[k])
                scene_prim_grow_tight_box(&x->sc->prims[o->first + s[k].off], b, b + 3);
            continue;
        }
        b = stk[top - 1];         /* the left operand's, then the result */
        top--;
        for (j = 0; j < 3 && s[k].op != CSG_DIFF; j++) {
            const double *r = stk[top - 1];
            if (s[k].op == CSG_UNION) {
                b[j] = b[j] < r[j] ? b[j] : r[j];
                b[3 + j] = b[3 + j] > r[3 + j] ? b[3 + j] : r[3 + j];
            } else {
                b[j] = b[j] > r[j] ? b[j] : r[j];
                b[3 + j] = b[3 + j] < r[3 + j] ? b[3 + j] : r[3 + j];
            }
        }
        memcpy(stk[top - 1], b, 6 * sizeof *b);
    }
    for (j = 0; j < 3; j++) {
        o->lo[j] = stk[0][j];
        o->hi[j] = stk[0][3 + j];
        if (!(o->lo[j] <= o->hi[j]))
            o->lo[0] = HUGE_VAL;  /* empty */
    }
}

/* 1 when boxes a and b come within gap of each other on every axis. */
static int si_near(const si_obj *a, const si_obj *b, double gap)
{
    int k;
    for (k = 0; k < 3; k++)
        if (!(a->lo[k] <= b->hi[k] + gap && b->lo[k] <= a->hi[k] + gap))
            return 0;
    return 1;
}

/* The cells of side h from the corner z that box o, grown by gap,
 * reaches: c[0..2] to c[3..5]. 0, or 1 when they are more than
 * SI_CELLS_MAX (or the box is not finite). */
#define SI_CELLS_MAX 64
static int si_cells(const si_obj *o, const double z[3], double h, double gap, long c[6])
{
    double n = 1;
    int k;
    for (k = 0; k < 3; k++) {
        double a = floor((o->lo[k] - gap - z[k]) / h), b = floor((o->hi[k] + gap - z[k]) / h);
        if (!(a >= 0 && b >= a && b < 1e9))
            return 1;
        c[k] = (long)a;
        c[3 + k] = (long)b;
        n *= b - a + 1;
    }
    return n > SI_CELLS_MAX;
}

static size_t si_cell_hash(long x, long y, long z, size_t mask)
{
    uint64_t h = (uint64_t)x * 0x9e3779b97f4a7c15u ^ (uint64_t)y * 0xc2b2ae3d27d4eb4fu ^ (uint64_t)z * 0x165667b19e3779f9u;
    return (size_t)(h ^ (h >> 29)) & mask;
}

/* Marks the candidates whose boxes come within gap of another object's.
 * The boxes go into the cells of a grid (side: their median largest
 * extent) by a hash of the cell, and the boxes that share a bucket are
 * compared; a box over more than SI_CELLS_MAX cells is compared with
 * every candidate. 0; 1 when that would compare more than SI_PAIRS pairs
 * an object (boxes piled on one another: none is then an instance); -1
 * when memory runs out. */
#define SI_PAIRS 64
static int si_apart(si_ctx *x, size_t n, double gap)
{
    size_t i, j, m = 0, nbig = 0, regs = 0, mask = 15, pairs = 0, budget = SI_PAIRS * n + 4096;
    double z[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, h, *ext = mem_alloc((n ? n : 1) * sizeof *ext);
    size_t *start = NULL, *item = NULL, *big = mem_alloc((n ? n : 1) * sizeof *big);
    long c[6], a, b, e;
    int status = -1;
    if (!ext || !big)
        goto done;
    for (i = 0; i < n; i++) {
        const si_obj *o = &x->o[i];
        int k;
        if (!(o->lo[0] <= o->hi[0]))
            continue;
        ext[m] = 0;
        for (k = 0; k < 3; k++) {
            z[k] = o->lo[k] < z[k] ? o->lo[k] : z[k];
            ext[m] = o->hi[k] - o->lo[k] > ext[m] ? o->hi[k] - o->lo[k] : ext[m];
        }
        m++;
    }
    status = 0;
    if (m < 2)
        goto done;
    {   /* the median extent */
        uint64_t *key = mem_alloc(m * sizeof *key);
        radix_ix *ord;
        if (!key)
            goto fail;
        for (j = 0; j < m; j++)
            key[j] = radix_key_d(ext[j]);
        ord = radix_order(key, m);
        mem_free(key);
        if (!ord)
            goto fail;
        h = 2 * ext[ord[m / 2]] + 4 * gap;
        mem_free(ord);
    }
    for (j = 0; j < 3; j++)
        z[j] -= 2 * gap;
    if (!(h > 0) || !isfinite(h))
        h = 1;
    /* count the registrations, then size the buckets */
    for (i = 0; i < n; i++) {
        const si_obj *o = &x->o[i];
        if (!(o->lo[0] <= o->hi[0]))
            continue;
        if (si_cells(o, z, h, gap, c)) {
            big[nbig++] = i;
            continue;
        }
        regs += (size_t)((c[3] - c[0] + 1) * (c[4] - c[1] + 1) * (c[5] - c[2] + 1));
    }
    while (mask < 2 * regs)
        mask = 2 * mask + 1;
    status = -1;
    if (!(start = mem_calloc(mask + 2, sizeof *start)) || !(item = mem_alloc((regs ? regs : 1) * sizeof *item)))
        goto done;
    for (int pass = 0; pass < 2; pass++) {
        for (i = 0; i < n; i++) {
            const si_obj *o = &x->o[i];
            if (!(o->lo[0] <= o->hi[0]) || si_cells(o, z, h, gap, c))
                continue;
            for (a = c[0]; a <= c[3]; a++)
                for (b = c[1]; b <= c[4]; b++)
                    for (e = c[2]; e <= c[5]; e++) {
                        size_t k = si_cell_hash(a, b, e, mask);
                        if (pass == 0)
                            start[k + 1]++;
                        else
                            item[start[k]++] = i;
                    }
        }
        if (pass == 0)
            for (j = 0; j <= mask; j++)
                start[j + 1] += start[j];
    }
    /* placing advanced each start to the next bucket's: bucket k now
     * holds item[start[k - 1] .. start[k] - 1] (start[-1] = 0) */
    status = 1;
    for (j = 0; j <= mask; j++) {
        size_t s0 = j ? start[j - 1] : 0, s1 = start[j], p, q;
        for (p = s0; p < s1; p++)
            for (q = p + 1; q < s1; q++) {
                si_obj *u = &x->o[item[p]], *v = &x->o[item[q]];
                if (++pairs > budget)
                    goto done;
                if ((u->master >= 0 || v->master >= 0) && item[p] != item[q] && si_near(u, v, gap))
                    u->meets = v->meets = 1;
            }
    }
    for (j = 0; j < nbig; j++)
        for (i = 0; i < n; i++) {
            si_obj *u = &x->o[big[j]], *v = &x->o[i];
            if (v->master < 0 && u->master < 0)
                continue;
            if (++pairs > budget)
                goto done;
            if (big[j] != i && v->lo[0] <= v->hi[0] && si_near(u, v, gap))
                u->meets = v->meets = 1;
        }
    status = 0;
    goto done;
fail:
    status = -1;
done:
    mem_free(ext);
    mem_free(big);
    mem_free(start);
    mem_free(item);
    return status;
}

/* Planar faces of object o whose planes are within SI_FACE_SIN (the sine
 * of the angle between them) of being parallel to the plane n p = d
 * (|n| = len) and whose primitives' boxes come within gap of it: 1 when
 * there is one (a face that could lie in the plane, where the two
 * surfaces' order along a ray would rest on rounding over a whole area),
 * else 0. A face crossing the plane at a wider angle meets it along a
 * line, where a copy's rounding moves the crossing by a hairline. */
#define SI_FACE_SIN (1.0 / 16)
static int si_faces_near(const si_ctx *x, const si_obj *o, const double n[3], double d, double len, double gap)
{
    const si_step *s = x->steps + o->seq;
    int k, a, j;
    for (k = 0; k < o->nseq; k++) {
        const scene_prim *sp;
        const double *m;
        double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        double blo = 0, bhi = 0;
        int near = 0;
        if (s[k].op != CSG_LEAF)
            continue;
        sp = &x->sc->prims[o->first + s[k].off];
        if (sp->shape->kind == PRIM_SPHERE)
            continue;             /* no planar face */
        m = sp->world_from_object;
        /* a face's normal on axis a lies along the cross product of the
         * linear part's other two columns (the block has faces on every
         * axis, the caps on z alone) */
        for (a = sp->shape->kind == PRIM_BLOCK ? 0 : 2; a < 3 && !near; a++) {
            double u[3], v[3], f[3], cr[3];
            for (j = 0; j < 3; j++) {
                u[j] = m[4 * j + (a + 1) % 3];
                v[j] = m[4 * j + (a + 2) % 3];
            }
            dmath_cross3(u, v, f);
            dmath_cross3(f, n, cr);
            near = !(sqrt(dmath_norm2_3(cr)) >= SI_FACE_SIN * sqrt(dmath_norm2_3(f)) * len);
        }
        if (!near)
            continue;
        scene_prim_grow_tight_box(sp, lo, hi);
        for (j = 0; j < 3; j++) {
            blo += n[j] * (n[j] >= 0 ? lo[j] : hi[j]);
            bhi += n[j] * (n[j] >= 0 ? hi[j] : lo[j]);
        }
        if (!(blo > d + gap * len || bhi < d - gap * len))
            return 1;
    }
    return 0;
}

/* Marks the candidates whose boxes come within gap of the plane of a
 * half-space (its points p with (ainv p)_z = (ainv t)_z, ainv the inverse
 * of its linear part, t its translation) and that have a face which could
 * lie in that plane (si_faces_near). 0, or 1 when a half-space's linear
 * part is singular (the compiler refuses it). */
static int si_planes(si_ctx *x, size_t n, double gap)
{
    const scene *sc = x->sc;
    size_t p, i;
    for (p = 0; p < sc->nprims; p++) {
        const double *m = sc->prims[p].world_from_object;
        double a[9] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]}, inv[9], nn[3], d, len;
        int k;
        if (sc->prims[p].shape->kind != PRIM_HALFSPACE)
            continue;
        if (dmath_m3_inverse(a, inv))
            return 1;
        for (k = 0; k < 3; k++)
            nn[k] = inv[6 + k];
        d = nn[0] * m[3] + nn[1] * m[7] + nn[2] * m[11];
        len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
        for (i = 0; i < n; i++) {
            si_obj *o = &x->o[i];
            double lo = 0, hi = 0;
            if (o->master < 0 || o->meets)
                continue;
            for (k = 0; k < 3; k++) {
                lo += nn[k] * (nn[k] >= 0 ? o->lo[k] : o->hi[k]);
                hi += nn[k] * (nn[k] >= 0 ? o->hi[k] : o->lo[k]);
            }
            if (!(lo > d + gap * len || hi < d - gap * len) && si_faces_near(x, o, nn, d, len, gap))
                o->meets = 1;
        }
    }
    return 0;
}

int scene_inst_find(const scene *sc, double tol, double gap, scene_inst **out)
{
    si_ctx x;
    size_t n = sc->nroots, i, cap = 16, found = 0, nturn = 0, maxseq = 0;
    scene_inst_turn *turn;
    double (*box)[6] = NULL;
    unsigned char *need = NULL;
    int *table = NULL, status = -1, r;
    *out = NULL;
    if (n < 2 || n > INT32_MAX / 4 || sc->nprims > INT32_MAX)
        return 0;
    memset(&x, 0, sizeof x);
    x.sc = sc;
    while (cap < 2 * n)
        cap *= 2;
    x.o = mem_calloc(n, sizeof *x.o);
    x.owner = mem_alloc((sc->nprims ? sc->nprims : 1) * sizeof *x.owner);
    table = mem_alloc(cap * sizeof *table);
    if (!x.o || !x.owner || !table)
        goto done;
    for (i = 0; i < sc->nprims; i++)
        x.owner[i] = -1;
    for (i = 0; i < cap; i++)
        table[i] = -1;
    for (i = 0; i < n; i++)
        if ((r = si_walk(&x, (int)i)))
            goto stop;
    /* the first object of each tree is its master; a later one alike
     * copies it */
    for (i = 0; i < n; i++) {
        si_obj *o = &x.o[i];
        const si_step *s = x.steps + o->seq;
        size_t h, k;
        int tries;
        for (k = 0; o->usable && k < (size_t)o->nseq; k++)
            o->usable &= s[k].op != CSG_LEAF || x.owner[o->first + s[k].off] == (int)i;
        if (!o->usable)
            continue;
        for (h = (size_t)o->hash & (cap - 1), tries = 0; table[h] >= 0; h = (h + 1) & (cap - 1))
            if (x.o[table[h]].hash == o->hash) {
                if (++tries > SI_TRIES || (r = si_same(&x, &x.o[table[h]], o, tol)) > 0)
                    break;
                if (r < 0)
                    goto stop;
            }
        if (table[h] < 0)
            table[h] = (int)i;
        else if (tries <= SI_TRIES)
            o->master = table[h];
    }
    for (i = 0; i < n; i++) {
        maxseq = (size_t)x.o[i].nseq > maxseq ? (size_t)x.o[i].nseq : maxseq;
        found += x.o[i].master >= 0;
    }
    status = 0;
    if (!found)                   /* no copies: no boxes to compare */
        goto done;
    found = 0;
    status = -1;
    if (!(box = mem_alloc((maxseq ? maxseq : 1) * sizeof *box)) || !(need = mem_alloc(2 * maxseq + 1)))
        goto done;
    for (i = 0; i < n; i++)
        if (x.o[i].master < 0 && x.o[i].nseq)
            si_box(&x, &x.o[i], box, need);
    for (i = 0; i < n; i++) {
        si_obj *o = &x.o[i];
        int k;
        if (o->master < 0)
            continue;
        if (o->turned) {          /* turned: its own */
            si_box(&x, o, box, need);
            continue;
        }
        for (k = 0; k < 3; k++) {
            o->lo[k] = x.o[o->master].lo[k] + o->c[k];
            o->hi[k] = x.o[o->master].hi[k] + o->c[k];
        }
    }
    if ((r = si_apart(&x, n, gap)) || (r = si_planes(&x, n, gap)))
        goto stop;
    for (i = 0; i < n; i++) {
        found += x.o[i].master >= 0 && !x.o[i].meets;
        nturn += x.o[i].master >= 0 && !x.o[i].meets && x.o[i].turned;
    }
    status = 0;
    if (!found)
        goto done;
    /* one block: an entry per root, then the turned ones' motions */
    if (!(*out = mem_alloc(n * sizeof **out + nturn * sizeof(scene_inst_turn)))) {
        status = -1;
        goto done;
    }
    turn = (scene_inst_turn *)(*out + n);
    for (i = 0; i < n; i++) {
        const si_obj *o = &x.o[i];
        scene_inst *e = &(*out)[i];
        e->master = o->master >= 0 && !o->meets ? o->master : -1;
        e->turn = NULL;
        if (e->master < 0)
            continue;
        e->first = o->first;
        e->count = o->count;
        e->dprim = o->first - x.o[o->master].first;
        memcpy(e->shift, o->c, sizeof e->shift);
        if (o->turned) {
            memcpy(turn->rot, x.rot[i], sizeof turn->rot);
            memcpy(turn->lo, o->lo, sizeof turn->lo);
            memcpy(turn->hi, o->hi, sizeof turn->hi);
            e->turn = turn++;
        }
    }
    status = (int)found;
    goto done;
stop:
    status = r < 0 ? -1 : 0;
done:
    mem_free(x.o);
    mem_free(x.owner);
    mem_free(x.steps);
    mem_free(x.stk);
    mem_free(table);
    mem_free(box);
    mem_free(need);
    mem_free(x.rot);
    mem_free(x.inv);
    return status;
}
