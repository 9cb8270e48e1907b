/* cscene — scene analysis and per-mode compilation (see cscene.h). */
#include "trace/cscene.h"
#include "util/dmath.h"
#include "model/prim_twin.h"
#include "model/scene_box.h"
#include "model/scene_inst.h"
#include "model/scene_map.h"
#include "util/mem.h"
#include <float.h>
#include <math.h>
#include <string.h>


static const char *cscene_file(const scene *sc) { return sc->source ? sc->source : ""; }

static int cscene_finite3(const double *v) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

void NS(cscene_to_world)(const cscene *cs, const double *deck, double *world)
{
    int i;
    for (i = 0; i < 3; i++)
        world[i] = cs->nm.scale * deck[i] + cs->nm.off[i];
}

void NS(cscene_surface_inst)(const cscene *cs, int pi, int face, vec3 pt, int need_uv, cscene_map_memo *mm,
                             geom_surface *out)
{
    const csg_inst *in;
    const prim *p = cscene_prim_of(cs, pi, &in);
    double w[3], m[3];
    int i;
    if (!in->turn) {
        NS(prim_surface)(p, face, vec3_add(pt, in->shift), NS(cscene_map)(cs, p, need_uv, mm), out);
        vec3_to_d(pt, out->p);    /* the point itself, not its master's */
        return;
    }
    /* turned: the point carried into the master's frame (rounded to num
     * once), the master's normal and tangents carried back */
    vec3_to_d(pt, w);
    for (i = 0; i < 3; i++)
        m[i] = dmath_dot3(in->turn->q + 3 * i, w) + in->shift_d[i];
    NS(prim_surface)(p, face, vec3_from_d(m), NS(cscene_map)(cs, p, need_uv, mm), out);
    memcpy(out->p, w, sizeof w);
    NS(cscene_inst_back)(in, out->n);
    NS(cscene_inst_back)(in, out->dpdu);
    NS(cscene_inst_back)(in, out->dpdv);
}

/* Normalisation: the bounded primitives are mapped into the cube
 * [-GEOM_W, GEOM_W]^3 by one uniform scale and a translation
 * (docs/numerics.md); the eye may lie anywhere, primary rays start near the
 * scene (cscene_primary). Only half-spaces: the eye and the look point set
 * the box. */
static int cscene_normalise(const scene *sc, geom_norm *nm, diag *err)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double half = 0;
    size_t i;
    int j, any = 0;
    for (i = 0; i < sc->nprims; i++)
        if (sc->prims[i].shape->kind != PRIM_HALFSPACE) {
            scene_prim_grow_box(&sc->prims[i], lo, hi);
            any = 1;
        }
    for (j = 0; j < 3 && !any; j++) {
        if (sc->view.eye[j] < lo[j]) lo[j] = sc->view.eye[j];
        if (sc->view.eye[j] > hi[j]) hi[j] = sc->view.eye[j];
        if (sc->view.look[j] < lo[j]) lo[j] = sc->view.look[j];
        if (sc->view.look[j] > hi[j]) hi[j] = sc->view.look[j];
    }
    for (j = 0; j < 3; j++) {
        if (!isfinite(lo[j]) || !isfinite(hi[j]) || !isfinite(hi[j] - lo[j]))
            return diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0,
                           "scene extent is not finite");
        if ((hi[j] - lo[j]) / 2 > half)
            half = (hi[j] - lo[j]) / 2;
    }
    if (!(half > 0) || !isfinite(GEOM_W / half)) {
        double m = 0;
        for (j = 0; j < 3; j++)
            if (fabs(lo[j]) > m) m = fabs(lo[j]);
        half = m > 0 ? m * 1e-6 : 1.0;
    }
    nm->scale = GEOM_W / half;
    for (j = 0; j < 3; j++)
        nm->off[j] = -nm->scale * (lo[j] + hi[j]) / 2;
    return 0;
}

/* Compiles every scene map that some primitive face is bound to: bound
 * through the shapes, each of which some primitive points at, in the order
 * the primitives first name them. */
static int cscene_maps(const scene *sc, cscene *cs, diag *err)
{
    size_t i;
    int f, st;
    if (!sc->nmaps)
        return 0;
    cs->maps = mem_calloc(sc->nmaps, sizeof *cs->maps);
    if (!cs->maps)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
    cs->nmaps = sc->nmaps;
    for (i = 0; i < sc->nshapes; i++)
        for (f = 0; f < SCENE_MAX_FACES; f++) {
            const scene_shape *sh = sc->shapes[i];
            int m = sh->face_map[f];
            if (m < 0)
                continue;
            if ((size_t)m >= sc->nmaps)
                return diag_at(err, DIAG_INPUT, cscene_file(sc), sh->loc.line, sh->loc.col,
                               "primitive '%s': map index out of range", sh->name);
            if (!cs->maps[m] &&
                (st = NS(pds_compile)(&sc->maps[m]->def, cscene_file(sc), &cs->maps[m], err)))
                return st;
        }
    return 0;
}

/* One row of the face table: what the faces of a primitive of kind `kind`
 * and attribute attr look up under the face bindings fmap (NULL: none). */
static void cscene_face_row(const scene *sc, const cscene *cs, int kind, int attr, const int *fmap,
                            cscene_face *row)
{
    int f;
    for (f = -1; f < SCENE_MAX_FACES; f++) {
        cscene_face *e = &row[f + 1];
        int m = fmap && f >= 0 ? fmap[f] : -1;
        e->plain = &sc->attrs[attr];
        e->map = m >= 0 ? cs->maps[m] : NULL;
        e->def = m >= 0 ? &sc->maps[m]->def : NULL;
        e->need_uv = m >= 0 || e->plain->texture >= 0 || e->plain->bump >= 0;
        e->flat_k = prim_face_plane(kind, f);
    }
}

/* 1 when primitive sp has a face bound by FACE. */
static int cscene_face_bound(const scene_prim *sp)
{
    int f;
    for (f = 0; f < SCENE_MAX_FACES; f++)
        if (sp->shape->face_map[f] >= 0)
            return 1;
    return 0;
}

/* A face_row entry that cscene_faces replaces by a row of the primitive's
 * own (a face bound by FACE). */
#define CSCENE_ROW_OWN ((size_t)-1)

/* Primitive sp's entry in face_row as the primitive compile leaves it: the
 * shared row of its kind and attribute, or CSCENE_ROW_OWN. Set while the
 * compile reads sp, not in a pass of its own: at 10,000 objects a pass
 * over the parsed primitives' face bindings was 40 % of the compile's
 * own cycles (docs/performance.md, run AG). */
static size_t cscene_face_row_of(const scene_prim *sp)
{
    size_t kind = (size_t)sp->shape->kind;
    return cscene_face_bound(sp) ? CSCENE_ROW_OWN : ((size_t)sp->attr * PRIM_KIND_COUNT + kind) * (SCENE_MAX_FACES + 1);
}

/* The face table (cscene_face_at), after the maps and primitives are
 * compiled (every kind is known, and face_row set by cscene_face_row_of;
 * nown of its entries CSCENE_ROW_OWN). */
static int cscene_faces(const scene *sc, cscene *cs, size_t nown, diag *err)
{
    const size_t row = SCENE_MAX_FACES + 1, nshared = sc->nattrs * PRIM_KIND_COUNT;
    size_t i, nrows = nshared + nown;
    cs->faces = mem_calloc(nrows ? nrows : 1, row * sizeof *cs->faces);
    if (!cs->faces)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
    for (i = 0; i < nshared; i++)
        cscene_face_row(sc, cs, (int)(i % PRIM_KIND_COUNT), (int)(i / PRIM_KIND_COUNT), NULL,
                        &cs->faces[i * row]);
    nrows = nshared;
    for (i = 0; i < sc->nprims; i++) {
        const scene_prim *sp = &sc->prims[i];
        if (cs->face_row[i] != CSCENE_ROW_OWN)
            continue;
        cs->face_row[i] = nrows++ * row;
        cscene_face_row(sc, cs, sp->shape->kind, sp->attr, sp->shape->face_map, &cs->faces[cs->face_row[i]]);
    }
    return 0;
}

/* Largest |origin| of a primary ray and largest |offset| of a half-space
 * plane, in normalised units: with hit points at most GEOM_TMAX further,
 * every plane and sphere test stays in range (docs/numerics.md, q16:
 * 16384 + 12000 + 4096 < 32768). Largest aspect ratio of a curved
 * primitive (measured: q16 overflows from 2.5e4, q32 from 1e10); 0 for no
 * limit. */
#if defined(NUM_MODE_q16)
#define CSCENE_ORIG_MAX 12000.0
#define CSCENE_ASPECT_MAX 1e4
#elif defined(NUM_MODE_q32)
#define CSCENE_ORIG_MAX 268435456.0
#define CSCENE_ASPECT_MAX 1e8
#else
#define CSCENE_ORIG_MAX 268435456.0
#define CSCENE_ASPECT_MAX 0.0
#endif
#define CSCENE_PLANE_MAX (CSCENE_ORIG_MAX + 4096 + 288)

/* Range checks and the data primary rays are started from: the sphere that
 * holds the bounded primitives and the half-space planes. A curved
 * primitive too thin for the mode, or a half-space plane the eye could see
 * beyond the mode's range, is refused (located, the limit named); a
 * half-space plane beyond the range that the eye is inside is moved to the
 * range's end, which changes nothing a ray can reach. */
static int cscene_ranges(const scene *sc, cscene *cs, diag *err)
{
    size_t i;
    int bounded = 0;
    cs->orig_max = CSCENE_ORIG_MAX;
    cs->orig_in2 = CSCENE_ORIG_MAX * CSCENE_ORIG_MAX * (1 - 0x1p-40);
    cs->nplanes = 0;
    cs->advance = 1;
    for (i = 0; i < cs->nprims; i++) {
        prim *p = &cs->prims[i];
        const scene_prim *sp = &sc->prims[i];
        if (cs->prim_root && cs->prim_root[i] >= 0)
            continue;             /* its master's is checked */
        if (p->bounded) {
            double aspect = 0, a[9];
            bounded = 1;
            /* the Frobenius norms' product is never below the aspect by
             * more than rounding (dmath_m3_frobenius): a primitive it keeps
             * 1e-9 under the limit needs no eigenvalues */
            if (CSCENE_ASPECT_MAX > 0 && p->kind != PRIM_BLOCK)
                scene_prim_canon_map(sp, cs->nm.scale, a);
            if (CSCENE_ASPECT_MAX > 0 && p->kind != PRIM_BLOCK
                && dmath_m3_frobenius(a) * dmath_m3_frobenius(p->fr->lin->ainv_d) > CSCENE_ASPECT_MAX * (1 - 1e-9)
                && (aspect = dmath_m3_spectral_norm(a) * dmath_m3_spectral_norm(p->fr->lin->ainv_d))
                       > CSCENE_ASPECT_MAX)
                return diag_at(err, DIAG_INPUT, cscene_file(sc), sp->shape->loc.line, sp->shape->loc.col,
                               "primitive '%s': aspect ratio %.3g is beyond the %s limit of %g "
                               "(docs/numerics.md); use --numeric q32 or f64",
                               sp->shape->name, aspect, NUM_NAME, CSCENE_ASPECT_MAX);
            continue;
        }
        if (fabs(p->pl_d[0][3]) > CSCENE_PLANE_MAX) {
            if (dmath_dot3(p->pl_d[0], cs->eye) > p->pl_d[0][3])
                return diag_at(err, DIAG_INPUT, cscene_file(sc), sp->shape->loc.line, sp->shape->loc.col,
                               "primitive '%s': the half-space's plane lies %.3g scene widths from "
                               "the scene, beyond the %s range of %.0f (docs/numerics.md); use "
                               "--numeric q32 or f64", sp->shape->name, fabs(p->pl_d[0][3]) / (2 * GEOM_W),
                               NUM_NAME, CSCENE_ORIG_MAX / (2 * GEOM_W));
        }
        if (cs->nplanes < CSCENE_MAX_PLANES)   /* as placed, before the move */
            memcpy(cs->planes[cs->nplanes++], p->pl_d[0], sizeof cs->planes[0]);
        else
            cs->advance = 0;
        if (fabs(p->pl_d[0][3]) > CSCENE_PLANE_MAX)   /* in binary64 pl_d too */
            p->pl[0].d = num_from_d(p->pl_d[0][3] > 0 ? CSCENE_PLANE_MAX : -CSCENE_PLANE_MAX);
    }
    /* the cube [-GEOM_W, GEOM_W]^3 holds every bounded primitive's box */
    cs->bound_r = bounded ? GEOM_W * sqrt(3.0) * (1 + 1e-9) : 0;
    for (i = 0; i < cs->nplanes; i++)
        cs->plane_gap[i] = cs->planes[i][3] - dmath_dot3(cs->planes[i], cs->eye);
    cs->eye2 = dmath_norm2_3(cs->eye);
    cs->eye_ok = sqrt(cs->eye2) <= cs->orig_max;
    if (cs->eye_ok)
        cs->eye_n = vec3_from_d(cs->eye);
    return 0;
}

void NS(cscene_primary_batch)(const cscene *cs, cscene_batch *b, int n, double after)
{
    const double margin = 1, r2 = cs->bound_r * cs->bound_r;
    size_t k;
    double norm2[CSCENE_BATCH];
    int m;
    /* the loops run over lanes, branch-free within, so that they vectorise;
     * a lane's arithmetic is the same operations in the same order as one
     * ray's would be */
    for (m = 0; m < n; m++) {
        double x = b->d[0][m], y = b->d[1][m], z = b->d[2][m], l = sqrt(x * x + y * y + z * z);
        b->u[0][m] = x / l;
        b->u[1][m] = y / l;
        b->u[2][m] = z / l;
        b->st[m] = l > 0 && l <= DBL_MAX ? CSCENE_RAY : CSCENE_BAD;
    }
    if (!cs->advance) {
        for (m = 0; m < n; m++)
            b->t0[m] = after > 0 ? HUGE_VAL : margin;
    } else if (cs->bound_r > 0 && after <= 0 && cs->eye2 <= r2) {
        for (m = 0; m < n; m++)
            b->t0[m] = 0;                    /* the eye is inside the sphere */
    } else if (cs->bound_r > 0 && after <= 0) {
        for (m = 0; m < n; m++) {
            double tc = -(cs->eye[0] * b->u[0][m] + cs->eye[1] * b->u[1][m] + cs->eye[2] * b->u[2][m]);
            double h2 = r2 - (cs->eye2 - tc * tc), t = tc - sqrt(h2);
            b->t0[m] = ((h2 >= 0) & (tc > 0)) ? t : HUGE_VAL;
        }
    } else {
        for (m = 0; m < n; m++)
            b->t0[m] = HUGE_VAL;
    }
    for (k = 0; cs->advance && k < cs->nplanes; k++) {
        const double *pl = cs->planes[k], gap = cs->plane_gap[k];
        for (m = 0; m < n; m++) {
            double den = pl[0] * b->u[0][m] + pl[1] * b->u[1][m] + pl[2] * b->u[2][m], th = gap / den;
            b->t0[m] = ((den != 0) & (th > after) & (th < b->t0[m])) ? th : b->t0[m];
        }
    }
    for (m = 0; m < n; m++)
        b->st[m] = b->st[m] == CSCENE_BAD ? CSCENE_BAD : b->t0[m] == HUGE_VAL ? CSCENE_NONE : CSCENE_RAY;
    for (m = 0; m < n; m++) {
        double t = b->t0[m], x, y, z, n2;
        t = t - margin > after ? t - margin : after;
        x = cs->eye[0] + t * b->u[0][m];
        y = cs->eye[1] + t * b->u[1][m];
        z = cs->eye[2] + t * b->u[2][m];
        n2 = x * x + y * y + z * z;
        b->t0[m] = t;
        b->o[0][m] = x;
        b->o[1][m] = y;
        b->o[2][m] = z;
        norm2[m] = n2;
    }
    /* a start at the eye is in range (eye_ok); elsewhere only one that may
     * lie beyond the range takes a square root */
    for (m = 0; m < n; m++)
        if (norm2[m] >= cs->orig_in2 && b->st[m] == CSCENE_RAY && !(b->t0[m] == 0 && cs->eye_ok)
            && sqrt(norm2[m]) > cs->orig_max)
            b->st[m] = CSCENE_CUT;
#if NUM_IS_NATIVE
    {   /* the box test's reciprocals of the direction as the ray holds it
         * (num, converted back to binary64); other modes convert in
         * cscene_primary_ray, once */
        int i;
        for (i = 0; i < 3; i++)
            for (m = 0; m < n; m++)
                b->rcp[i][m] = bbox_rcp(num_to_d(num_from_d(b->u[i][m])));
    }
#elif CSCENE_BATCH_NUM
    {   /* the rays rounded to num, and the reciprocals from that: |u| <= 1,
         * and |o| <= CSCENE_ORIG_MAX < 2^15 in the lanes that become rays
         * (CSCENE_RAY), where num_from_d would give the same values (no
         * lane saturates); the other lanes' values are never read */
        double s[2][3][CSCENE_BATCH];
        int i;
        for (i = 0; i < 3; i++)
            for (m = 0; m < n; m++) {
                s[0][i][m] = fx16_lane_scale(b->u[i][m]);
                s[1][i][m] = fx16_lane_scale(b->o[i][m]);
            }
        for (i = 0; i < 3; i++)
            for (m = 0; m < n; m++) {
                num q = fx16_from_lane(s[0][i][m]);
                b->un[i][m] = q;
                b->on[i][m] = fx16_from_lane(s[1][i][m]);
                b->rcp[i][m] = bbox_rcp(num_to_d(q));
            }
    }
#endif
}

void NS(cscene_primary_ray)(const cscene *cs, const cscene_batch *b, int k, prim_ray *r)
{
    int i;
    /* u is a unit vector in double: rounding each component keeps it unit
     * to the mode's resolution, as a normalisation in num would */
#if CSCENE_BATCH_NUM
    r->d = vec3_make(b->un[0][k], b->un[1][k], b->un[2][k]);
    r->o = b->t0[k] == 0 && cs->eye_ok ? cs->eye_n : vec3_make(b->on[0][k], b->on[1][k], b->on[2][k]);
    for (i = 0; i < 3; i++)
        r->b.rcp[i] = b->rcp[i][k];
#else
    double d[3];
    r->d = vec3_make(num_from_d(b->u[0][k]), num_from_d(b->u[1][k]), num_from_d(b->u[2][k]));
    r->o = b->t0[k] == 0 && cs->eye_ok ? cs->eye_n
           : vec3_make(num_from_d(b->o[0][k]), num_from_d(b->o[1][k]), num_from_d(b->o[2][k]));
    vec3_to_d(r->d, d);
    for (i = 0; i < 3; i++)
        r->b.rcp[i] = NUM_IS_NATIVE ? b->rcp[i][k] : bbox_rcp(d[i]);
#endif
    vec3_to_d(r->o, r->b.o);
    r->excl_prim = -1;
    r->excl_enter = 0;
}

/* A light buffer per light and one at the eye over the bounded objects'
 * boxes, where there are enough objects for a hierarchy walk to cost more
 * than a lookup (CSCENE_LBUF_MIN). Boxes are grown by CSCENE_LBUF_GROW: a
 * ray whose line passes farther from its light or eye (a far surface
 * point or a far eye in a coarse mode) walks the hierarchy instead
 * (lightbuf_lookup). */
static int cscene_lights(cscene *cs, diag *err)
{
    const csg *t = &cs->tree;
    lightbuf_scratch scratch;
    size_t i;
    int status = 0;
    if (t->nbounded < CSCENE_LBUF_MIN)
        return 0;
    memset(&scratch, 0, sizeof scratch);
    cs->lbuf = mem_calloc(cs->nlights ? cs->nlights : 1, sizeof *cs->lbuf);
    if (!cs->lbuf)
        status = DIAG_IO;
    for (i = 0; !status && i <= cs->nlights; i++) {
        double at[3];
        if (i < cs->nlights)
            vec3_to_d(cs->lights[i].pos, at);
        if (lightbuf_build(i < cs->nlights ? &cs->lbuf[i] : &cs->eyebuf, i < cs->nlights ? at : cs->eye,
                           (const double (*)[3])t->olo, (const double (*)[3])t->ohi, (size_t)t->nbounded,
                           CSCENE_LBUF_GROW, &scratch) < 0)
            status = DIAG_IO;
    }
    lightbuf_scratch_free(&scratch);
    return status ? diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene") : 0;
}

/* The offset of an array of count elements of size bytes at *at, which
 * moves past it to the next 64-byte boundary; SIZE_MAX, there and on,
 * once the sizes overflow. */
static size_t cscene_carve(size_t *at, size_t count, size_t size)
{
    size_t start = *at;
    if (start == SIZE_MAX || (size && count > (SIZE_MAX - 2 * MEM_LINE - start) / size))
        return *at = SIZE_MAX;
    *at = (start + count * size + MEM_LINE - 1) & ~(size_t)(MEM_LINE - 1);
    return start;
}

/* The compiled primitives' arrays in one block (cscene.prim_mem), each
 * from a 64-byte boundary: n primitives, npl planes (in num and, apart
 * from them outside binary64, in double), n frames, n face rows, and
 * room for n linear parts, last, so that the room twins leave unused is
 * never touched. A large block is rounded up to whole huge pages once,
 * where five arrays were each (docs/performance.md, run AT); room is
 * mem_calloc, or mem_calloc_sparse where instances leave most of it
 * unwritten. 0, or -1 when memory runs out or the sizes overflow. */
static int cscene_prim_room(cscene *cs, size_t n, size_t npl, void *(*room)(size_t, size_t))
{
    size_t at = 0, o_pl, o_pl_d, o_fr, o_row, o_lin;
    unsigned char *b;
    (void)cscene_carve(&at, n, sizeof *cs->prims);
    o_pl = cscene_carve(&at, npl, sizeof *cs->prim_pl);
    o_pl_d = PRIM_PL_SHARED ? o_pl : cscene_carve(&at, npl, sizeof *cs->prim_pl_d);
    o_fr = cscene_carve(&at, n, sizeof *cs->prim_fr);
    o_row = cscene_carve(&at, n, sizeof *cs->face_row);
    o_lin = cscene_carve(&at, n, sizeof *cs->lins);
    if (at == SIZE_MAX || !(cs->prim_mem = room(1, at + MEM_LINE)))
        return -1;
    b = mem_align_line(cs->prim_mem);
    cs->prims = (prim *)(void *)b;
    cs->prim_pl = (prim_plane *)(void *)(b + o_pl);
    cs->prim_pl_d = (double (*)[4])(void *)(b + o_pl_d);
    cs->prim_fr = (prim_frame *)(void *)(b + o_fr);
    cs->face_row = (size_t *)(void *)(b + o_row);
    cs->lins = (prim_lin *)(void *)(b + o_lin);
    return 0;
}

/* The objects traced as translated or turned copies of an earlier one
 * (model/scene_inst.h): found in deck units to within PRIM_SAME_TOL, kept
 * farther than 2^-10 normalised units (CSCENE_INST_GAP) from every other
 * object; a translated copy's shift rounded to num once, so that the ray
 * and the object's box move by the same vector; a turned copy's frame
 * change by cscene_turned. Their primitives are then not compiled; *nprims
 * says how many they are. Fewer than CSCENE_INST_MIN instances are not
 * taken: the load they would save is less than what moving the rays
 * costs the render (docs/performance.md, run AO). */
#define CSCENE_INST_MIN 1024
#define CSCENE_INST_GAP (1.0 / 1024)

/* The frame change of a turned instance e into *in and *tu: in the normalised
 * world (scale s, offset f) a point p of the object stands at
 * q p + shift in its master, q = rot^-1 and shift = f - q (f + s c).
 * Its box is its own, padded by twice CSG_BOX_PAD: once as every box is,
 * once for the carried ray's offset (csg_object_turned), which is kept
 * under a quarter of the gap between objects: an object whose box
 * diagonal would allow more is not taken (1). */
static int cscene_turned(const cscene *cs, const scene_inst *e, csg_inst *in, csg_turn *tu)
{
    const double s = cs->nm.scale, *f = cs->nm.off;
    double a[3], diag = 0, unit = NUM_IS_FIXED ? num_to_d(NUM_ULP) : 2 * GEOM_W * num_to_d(NUM_ULP);
    int j;
    if (dmath_m3_inverse(e->turn->rot, tu->q))
        return 1;
    for (j = 0; j < 3; j++) {
        tu->lo[j] = s * e->turn->lo[j] + f[j] - 2 * CSG_BOX_PAD;
        tu->hi[j] = s * e->turn->hi[j] + f[j] + 2 * CSG_BOX_PAD;
        diag += s * (e->turn->hi[j] - e->turn->lo[j]) * s * (e->turn->hi[j] - e->turn->lo[j]);
        a[j] = f[j] + s * e->shift[j];
    }
    if (!((1 + sqrt(diag)) * sqrt(3.0) / 2 * unit <= CSCENE_INST_GAP / 4))
        return 1;
    for (j = 0; j < 3; j++)
        in->shift_d[j] = f[j] - dmath_dot3(tu->q + 3 * j, a);
    in->shift = vec3_from_d(in->shift_d);
    return 0;
}

static int cscene_instances(const scene *sc, cscene *cs, size_t *nprims, diag *err)
{
    scene_inst *si = NULL;
    size_t i, nturn = 0;
    int n = scene_inst_find(sc, PRIM_SAME_TOL / cs->nm.scale, CSCENE_INST_GAP / cs->nm.scale, &si), j;
    *nprims = 0;
    if (n < CSCENE_INST_MIN) {
        mem_free(si);
        return n < 0 ? diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene") : 0;
    }
    for (i = 0; i < sc->nroots; i++)
        nturn += si[i].master >= 0 && si[i].turn;
    cs->root_inst = mem_calloc(sc->nroots, sizeof *cs->root_inst);
    cs->prim_root = mem_alloc(sc->nprims * sizeof *cs->prim_root);
    cs->inst_turn = mem_alloc((nturn ? nturn : 1) * sizeof *cs->inst_turn);
    if (!cs->root_inst || !cs->prim_root || !cs->inst_turn) {
        mem_free(si);
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
    }
    for (i = 0; i < sc->nprims; i++)
        cs->prim_root[i] = -1;
    nturn = 0;
    for (i = 0; i < sc->nroots; i++) {
        csg_inst *in = &cs->root_inst[i];
        double d[3];
        if (si[i].master < 0)
            continue;
        if (si[i].turn) {
            csg_turn *tu = &cs->inst_turn[nturn];
            if (cscene_turned(cs, &si[i], in, tu))
                continue;         /* too large for the mode: its own */
            in->turn = tu;
            nturn++;
        } else {
            for (j = 0; j < 3; j++)
                d[j] = -si[i].shift[j] * cs->nm.scale;
            in->shift = vec3_from_d(d);
            vec3_to_d(in->shift, in->shift_d);
            cs->inst_moved++;
        }
        in->master = si[i].master;
        in->first = si[i].first;
        in->count = si[i].count;
        in->dprim = si[i].dprim;
        for (j = 0; j < in->count; j++)
            cs->prim_root[in->first + j] = (int)i;
        *nprims += (size_t)in->count;
    }
    cs->inst_turned = nturn;
    mem_free(si);
    return 0;
}

int NS(cscene_compile)(const scene *sc, cscene **out, diag *err)
{
    cscene *cs;
    const scene_view *v = &sc->view;
    double fwd[3], d[3];
    size_t i, npl = 0, nlin = 0, nown = 0, ninst = 0;
    prim_twin tw = {NULL, 0, 0, 0, 0};
    int status = DIAG_IO;

    if (!cscene_finite3(v->eye) || !cscene_finite3(v->look) || !cscene_finite3(v->up)
        || !(v->fov_deg > 0 && v->fov_deg < 180))
        return diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0,
                       "view: eye, look and up must be finite and fov in (0,180) degrees");
    cs = mem_calloc(1, sizeof *cs);
    if (!cs)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
    cs->sc = sc;
    if ((status = cscene_normalise(sc, &cs->nm, err)) != 0)
        goto fail;
    status = DIAG_INPUT;
    for (i = 0; i < 3; i++)
        d[i] = v->look[i] - v->eye[i];
    if (dmath_unit3(d, fwd)) {
        diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0, "view: eye and look coincide");
        goto fail;
    }
    memcpy(cs->fwd, fwd, sizeof fwd);
    d[0] = fwd[1] * v->up[2] - fwd[2] * v->up[1];
    d[1] = fwd[2] * v->up[0] - fwd[0] * v->up[2];
    d[2] = fwd[0] * v->up[1] - fwd[1] * v->up[0];
    if (dmath_unit3(d, cs->right)) {
        diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0, "view: up is parallel to the view direction");
        goto fail;
    }
    cs->up[0] = cs->right[1] * fwd[2] - cs->right[2] * fwd[1];
    cs->up[1] = cs->right[2] * fwd[0] - cs->right[0] * fwd[2];
    cs->up[2] = cs->right[0] * fwd[1] - cs->right[1] * fwd[0];
    cs->tan_half = tan(dmath_rad(v->fov_deg / 2));
    NS(cscene_to_world)(cs, v->eye, cs->eye);
    if (!cscene_finite3(cs->eye)) {
        diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0, "view: the eye is too far from the scene");
        goto fail;
    }
    cs->max_depth = sc->max_depth < 0 ? 0 : sc->max_depth > CSCENE_MAX_DEPTH ? CSCENE_MAX_DEPTH
                                                                          : sc->max_depth;
    status = DIAG_IO;
    for (i = 0; i < sc->nprims; i++)
        npl += (size_t)prim_nplanes(sc->prims[i].shape->kind);
    if ((status = cscene_instances(sc, cs, &ninst, err)))
        goto fail;
    status = DIAG_IO;
    if (sc->nprims) {
        /* where instances leave most primitives uncompiled, their arrays
         * are mostly never written: small pages (mem_calloc_sparse) */
        if (cscene_prim_room(cs, sc->nprims, npl, 2 * ninst > sc->nprims ? mem_calloc_sparse : mem_calloc)) {
            diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
            goto fail;
        }
    }
    cs->nprims = sc->nprims;
    if (prim_twin_init(&tw)) {
        diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
        goto fail;
    }
    /* each primitive with the linear results of its first twin, if any */
    for (i = 0, npl = 0; i < sc->nprims; i++) {
        const scene_prim *sp = &sc->prims[i];
        prim_twin_entry *e;
        int known;
        double radius;
        if (sp->attr < 0 || (size_t)sp->attr >= sc->nattrs) {
            status = diag_at(err, DIAG_INPUT, cscene_file(sc), sp->shape->loc.line, sp->shape->loc.col,
                             "primitive '%s': attribute index out of range", sp->shape->name);
            goto fail;
        }
        if (cs->prim_root && cs->prim_root[i] >= 0) {   /* traced as its master's */
            cs->face_row[i] = cscene_face_row_of(sp);
            nown += cs->face_row[i] == CSCENE_ROW_OWN;
            npl += (size_t)prim_nplanes(sp->shape->kind);
            continue;
        }
        e = prim_twin_at(&tw, sc->prims, sp);
        known = e && e->index != PRIM_TWIN_NONE;
        radius = known ? e->note : 0;
        if ((status = NS(prim_compile)(sp, (int)i, &cs->nm, cs->prim_pl + npl, cs->prim_pl_d + npl, cs->prim_fr + i,
                                       known ? NULL : cs->lins + nlin, known ? &cs->prims[e->index] : NULL, &radius,
                                       &cs->prims[i], cscene_file(sc), err)))
            goto fail;
        if (!known) {
            if (e && prim_twin_add(&tw, sc->prims, e, i, radius)) {
                status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
                goto fail;
            }
            nlin++;
        }
        cs->face_row[i] = cscene_face_row_of(sp);
        nown += cs->face_row[i] == CSCENE_ROW_OWN;
        npl += (size_t)prim_nplanes(sp->shape->kind);
    }
    prim_twin_free(&tw);
    if ((status = NS(prim_share)(cs->prims, sc->prims, cs->nm.scale, cs->nprims, err))
        || (status = cscene_ranges(sc, cs, err)))
        goto fail;
    for (i = 0; i < sc->nattrs; i++) {
        const scene_attr *a = &sc->attrs[i];
        if (a->texture >= (int)sc->ntextures || a->bump >= (int)sc->nbumps ||
            (a->texture >= 0 && !sc->textures[a->texture].img.px)) {
            status = diag_at(err, DIAG_INPUT, cscene_file(sc), a->loc.line, a->loc.col,
                             "attribute '%s': texture or bump index out of range", a->name);
            goto fail;
        }
        if (a->transmit > 0)
            cs->transparent = 1;
    }
    if (sc->nlights > SCENE_MAX_LIGHTS) {
        status = diag_at(err, DIAG_INPUT, cscene_file(sc), 0, 0, "more than %d lights",
                         SCENE_MAX_LIGHTS);
        goto fail;
    }
    if (sc->nlights) {
        cs->lights = mem_calloc(sc->nlights, sizeof *cs->lights);
        if (!cs->lights) {
            status = diag_at(err, DIAG_IO, "", 0, 0, "out of memory compiling the scene");
            goto fail;
        }
    }
    cs->nlights = sc->nlights;
    for (i = 0; i < sc->nlights; i++) {
        const scene_light *l = &sc->lights[i];
        double w[3], len;
        int j;
        if (!cscene_finite3(l->pos) || !cscene_finite3(l->color) || !isfinite(l->intensity)) {
            status = diag_at(err, DIAG_INPUT, cscene_file(sc), l->loc.line, l->loc.col,
                             "light is not finite");
            goto fail;
        }
        NS(cscene_to_world)(cs, l->pos, w);
        len = dmath_len3(w);
        if (len > GEOM_LIGHT_MAX)           /* far lights keep their direction */
            for (j = 0; j < 3; j++)
                w[j] *= GEOM_LIGHT_MAX / len;
        cs->lights[i].pos = vec3_from_d(w);
        for (j = 0; j < 3; j++)
            cs->lights[i].rgb[j] = l->color[j] * l->intensity;
    }
    if ((status = NS(csg_build)(sc, cs->prims, cs->nm.scale, cs->root_inst, &cs->tree, err)) ||
        (status = cscene_lights(cs, err)) ||
        (status = cscene_maps(sc, cs, err)) || (status = cscene_faces(sc, cs, nown, err)))
        goto fail;
    *out = cs;
    return 0;
fail:
    prim_twin_free(&tw);
    NS(cscene_free)(cs);
    return status ? status : DIAG_IO;
}

void NS(cscene_free)(cscene *cs)
{
    size_t i;
    if (!cs)
        return;
    for (i = 0; i < cs->nmaps; i++)
        NS(pds_free)(cs->maps[i]);
    mem_free(cs->maps);
    mem_free(cs->faces);
    NS(csg_free)(&cs->tree);
    mem_free(cs->prim_mem);
    mem_free(cs->prim_root);
    mem_free(cs->root_inst);
    mem_free(cs->inst_turn);
    for (i = 0; cs->lbuf && i < cs->nlights; i++)
        lightbuf_free(&cs->lbuf[i]);
    mem_free(cs->lbuf);
    lightbuf_free(&cs->eyebuf);
    mem_free(cs->lights);
    mem_free(cs);
}
