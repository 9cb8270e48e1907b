/* pds_def — PDS definitions: builders, placement algebra and validation
 * (see pds_def.h; the error texts are listed in docs/pds.md). */
#include "model/pds_def.h"
#include "util/dmath.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/pds_curve.h"
#include "util/mem.h"

static const double identity[6] = { 1, 0, 0, 0, 1, 0 };

void pds_def_init(pds_def *d, pds_kind kind, scene_loc loc)
{
    memset(d, 0, sizeof *d);
    d->kind = kind;
    d->loc = loc;
    d->tiling.shape = PDS_TILE_SQUARE;
    d->tiling.size[0] = d->tiling.size[1] = 0.25;
    d->tiling.offset = 0.5;
    d->tiling.mortar_attr = PDS_NONE;
    d->tiling.rule = PDS_RULE_CYCLE;
    d->tiling.step[0] = d->tiling.step[1] = 1;
    d->mosaic.mortar_attr = PDS_NONE;
    d->curves.tolerance = PDS_CURVE_TOLERANCE;
}

void pds_def_free(pds_def *d)
{
    mem_free(d->cpg.nodes);
    mem_free(d->cpg.pts);
    mem_free(d->cpg.kids);
    mem_free(d->pixels.cells);
    mem_free(d->tiling.attrs);
    mem_free(d->mosaic.seeds);
    mem_free(d->mosaic.attrs);
    mem_free(d->quad.pixels.cells);
    mem_free(d->quad.code);
    mem_free(d->curves.curves);
    mem_free(d->curves.pts);
    memset(d, 0, sizeof *d);
}

/* Appends one node, growing the array; -1 on failure. */
static long pds_def_cpg_push(pds_def *d, pds_cpg_op op, int32_t attr, scene_loc loc)
{
    pds_cpg *c = &d->cpg;
    pds_cpg_node *n;
    if (mem_grow((void **)&c->nodes, &c->cap_nodes, c->nnodes + 1, sizeof *c->nodes))
        return -1;
    n = &c->nodes[c->nnodes];
    memset(n, 0, sizeof *n);
    n->op = op;
    n->attr = attr;
    n->loc = loc;
    memcpy(n->xf, identity, sizeof identity);
    c->root = c->nnodes;
    return (long)c->nnodes++;
}

long pds_cpg_rect(pds_def *d, double u0, double v0, double u1, double v1, int32_t attr, scene_loc loc)
{
    long i = pds_def_cpg_push(d, PDS_CPG_RECT, attr, loc);
    if (i >= 0) {
        double *p = d->cpg.nodes[i].p;
        p[0] = u0; p[1] = v0; p[2] = u1; p[3] = v1;
    }
    return i;
}

long pds_cpg_ellipse(pds_def *d, double cu, double cv, double ru, double rv, int32_t attr, scene_loc loc)
{
    long i = pds_def_cpg_push(d, PDS_CPG_ELLIPSE, attr, loc);
    if (i >= 0) {
        double *p = d->cpg.nodes[i].p;
        p[0] = cu; p[1] = cv; p[2] = ru; p[3] = rv;
    }
    return i;
}

long pds_cpg_polygon(pds_def *d, const double *uv, size_t nvert, int32_t attr, scene_loc loc)
{
    pds_cpg *c = &d->cpg;
    long i;
    if (nvert > PDS_MAX_VERTICES * 4UL ||
        mem_grow((void **)&c->pts, &c->cap_pts, c->npts + nvert, 2 * sizeof *c->pts))
        return -1;
    i = pds_def_cpg_push(d, PDS_CPG_POLYGON, attr, loc);
    if (i < 0)
        return -1;
    if (nvert)
        memcpy(c->pts + 2 * c->npts, uv, nvert * 2 * sizeof *uv);
    c->nodes[i].first = c->npts;
    c->nodes[i].count = nvert;
    c->npts += nvert;
    return i;
}

long pds_cpg_nested(pds_def *d, const pds_def *sub, scene_loc loc)
{
    long i = pds_def_cpg_push(d, PDS_CPG_NESTED, PDS_INHERIT, loc);
    if (i >= 0)
        d->cpg.nodes[i].sub = sub;
    return i;
}

long pds_cpg_op_node(pds_def *d, pds_cpg_op op, const size_t *operands, size_t n, int32_t attr, scene_loc loc)
{
    pds_cpg *c = &d->cpg;
    long i;
    if (n > PDS_MAX_NODES * 4UL ||
        mem_grow((void **)&c->kids, &c->cap_kids, c->nkids + n, sizeof *c->kids))
        return -1;
    i = pds_def_cpg_push(d, op, attr, loc);
    if (i < 0)
        return -1;
    if (n)
        memcpy(c->kids + c->nkids, operands, n * sizeof *operands);
    c->nodes[i].first = c->nkids;
    c->nodes[i].count = n;
    c->nkids += n;
    return i;
}

void pds_affine_after(double m[6], const double t[6])
{
    double r[6];
    r[0] = t[0] * m[0] + t[1] * m[3];
    r[1] = t[0] * m[1] + t[1] * m[4];
    r[2] = t[0] * m[2] + t[1] * m[5] + t[2];
    r[3] = t[3] * m[0] + t[4] * m[3];
    r[4] = t[3] * m[1] + t[4] * m[4];
    r[5] = t[3] * m[2] + t[4] * m[5] + t[5];
    memcpy(m, r, sizeof r);
}

void pds_cpg_translate(pds_def *d, size_t node, double du, double dv)
{
    double t[6] = { 1, 0, 0, 0, 1, 0 };
    t[2] = du; t[5] = dv;
    pds_affine_after(d->cpg.nodes[node].xf, t);
}

void pds_cpg_rotate(pds_def *d, size_t node, double degrees)
{
    /* Exact for multiples of 90 degrees, so rectangles stay axis-aligned. */
    double r = fmod(degrees, 360.0), c, s, t[6];
    if (r < 0)
        r += 360.0;
    if (r == 0) { c = 1; s = 0; }
    else if (r == 90) { c = 0; s = 1; }
    else if (r == 180) { c = -1; s = 0; }
    else if (r == 270) { c = 0; s = -1; }
    else { c = cos(dmath_rad(r)); s = sin(dmath_rad(r)); }
    t[0] = c; t[1] = -s; t[2] = 0; t[3] = s; t[4] = c; t[5] = 0;
    pds_affine_after(d->cpg.nodes[node].xf, t);
}

void pds_cpg_scale(pds_def *d, size_t node, double su, double sv)
{
    double t[6] = { 0, 0, 0, 0, 0, 0 };
    t[0] = su; t[4] = sv;
    pds_affine_after(d->cpg.nodes[node].xf, t);
}

void pds_cpg_shear(pds_def *d, size_t node, double shu, double shv)
{
    double a[6] = { 1, 0, 0, 0, 1, 0 }, b[6] = { 1, 0, 0, 0, 1, 0 };
    a[1] = shu;
    b[3] = shv;
    pds_affine_after(d->cpg.nodes[node].xf, a);
    pds_affine_after(d->cpg.nodes[node].xf, b);
}

int pds_pixels_set(pds_pixels *px, int width, int height, const int32_t *cells, size_t ncells)
{
    if (ncells > (size_t)PDS_MAX_CELLS * 2 ||
        mem_grow((void **)&px->cells, &px->cap_cells, ncells ? ncells : 1, sizeof *cells))
        return -1;
    px->width = width;
    px->height = height;
    if (ncells)
        memcpy(px->cells, cells, ncells * sizeof *cells);
    px->ncells = ncells;
    return 0;
}

int pds_tiling_attrs(pds_def *d, const int32_t *attrs, size_t n)
{
    pds_tiling *t = &d->tiling;
    if (n > 65536 || mem_grow((void **)&t->attrs, &t->cap_attrs, n, sizeof *attrs))
        return -1;
    if (n)
        memcpy(t->attrs, attrs, n * sizeof *attrs);
    t->nattrs = n;
    return 0;
}

long pds_mosaic_seed(pds_def *d, double u, double v, int32_t attr)
{
    pds_mosaic *m = &d->mosaic;
    if (m->nseeds >= (size_t)PDS_MAX_SEEDS * 2 ||
        mem_grow((void **)&m->seeds, &m->cap_seeds, m->nseeds + 1, 2 * sizeof *m->seeds) ||
        mem_grow((void **)&m->attrs, &m->cap_attrs, m->nseeds + 1, sizeof *m->attrs))
        return -1;
    m->seeds[2 * m->nseeds] = u;
    m->seeds[2 * m->nseeds + 1] = v;
    m->attrs[m->nseeds] = attr;
    return (long)m->nseeds++;
}

int pds_quadtree_code(pds_def *d, const int32_t *code, size_t n)
{
    pds_quadtree *q = &d->quad;
    if (n > (size_t)PDS_MAX_CELLS * 2 ||
        mem_grow((void **)&q->code, &q->cap_code, n, sizeof *code))
        return -1;
    if (n)
        memcpy(q->code, code, n * sizeof *code);
    q->ncode = n;
    q->from_pixels = 0;
    return 0;
}

long pds_curve_add(pds_def *d, int bspline, const double *uv, size_t npts, int32_t attr, scene_loc loc)
{
    pds_curves *c = &d->curves;
    pds_curve *k;
    if (npts > PDS_MAX_VERTICES * 4UL ||
        mem_grow((void **)&c->pts, &c->cap_pts, c->npts + npts, 2 * sizeof *c->pts) ||
        mem_grow((void **)&c->curves, &c->cap_curves, c->ncurves + 1, sizeof *c->curves))
        return -1;
    k = &c->curves[c->ncurves];
    k->bspline = bspline;
    k->first = c->npts;
    k->count = npts;
    k->attr = attr;
    k->loc = loc;
    if (npts)
        memcpy(c->pts + 2 * c->npts, uv, npts * 2 * sizeof *uv);
    c->npts += npts;
    return (long)c->ncurves++;
}

/* ---- validation -------------------------------------------------------- */

#define FAIL(loc, ...) diag_at(err, DIAG_INPUT, file, (loc).line, (loc).col, __VA_ARGS__)

static int pds_def_id_ok(int32_t id) { return id == PDS_NONE || (id >= 0 && id <= PDS_MAX_ATTR); }

static int pds_def_finite_all(const double *x, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* Validates a closed polyline shared by polygons and curves: `what` names
 * it in messages; a flattened B-spline reports where it crosses itself
 * instead of edge numbers the deck never mentions. */
static int pds_def_check_ring(const double *pts, size_t n, const char *what, int bspline,
                      const char *file, scene_loc loc, diag *err)
{
    size_t i, ea, eb;
    int r;
    for (i = 0; i < n && !bspline; i++) {
        const double *p = pts + 2 * i, *q = pts + 2 * ((i + 1) % n);
        if (p[0] == q[0] && p[1] == q[1])
            return FAIL(loc, "%s points %zu and %zu coincide", what, i + 1, (i + 1) % n + 1);
    }
    if (pds_curve_area2(pts, n) == 0)
        return FAIL(loc, "%s encloses no area", what);
    r = pds_curve_simple(pts, n, &ea, &eb);
    if (r == -3)
        return FAIL(loc, "%s is too intricate to check for self-intersection (more than %lu edge pairs)",
                    what, PDS_CURVE_PAIR_BUDGET);
    if (r < 0)
        return diag_at(err, DIAG_IO, file, loc.line, loc.col, "out of memory checking a %s", what);
    if (r == 0 && bspline) {
        /* Report where: the crossing of the two flattened edges (or, for
         * overlapping edges, the start of the second). */
        const double *a = pts + 2 * ea, *b = pts + 2 * ((ea + 1) % n);
        const double *c = pts + 2 * eb, *e = pts + 2 * ((eb + 1) % n);
        double den = (b[0] - a[0]) * (e[1] - c[1]) - (b[1] - a[1]) * (e[0] - c[0]);
        double t = den != 0 ? ((c[0] - a[0]) * (e[1] - c[1]) - (c[1] - a[1]) * (e[0] - c[0])) / den : 0;
        double x = den != 0 ? a[0] + t * (b[0] - a[0]) : c[0], y = den != 0 ? a[1] + t * (b[1] - a[1]) : c[1];
        return FAIL(loc, "%s intersects itself near (%.3f, %.3f)", what, x, y);
    }
    if (r == 0)
        return FAIL(loc, "%s edges %zu and %zu cross or touch (it must be simple)", what, ea + 1, eb + 1);
    return 0;
}

/* Root-from-node placements and nesting depths for every node reachable
 * from the root (others get depth -1). Operands precede their operators
 * (checked before this runs), so one pass in decreasing index order visits
 * each parent before its operands. */
void pds_cpg_placements(const pds_def *d, double (*m)[6], int *depth)
{
    const pds_cpg *c = &d->cpg;
    size_t i, k;
    for (i = 0; i < c->nnodes; i++)
        depth[i] = -1;
    memcpy(m[c->root], c->nodes[c->root].xf, sizeof m[0]);
    depth[c->root] = 0;
    for (i = c->root + 1; i-- > 0;) {
        const pds_cpg_node *n = &c->nodes[i];
        if (depth[i] < 0 || n->op < PDS_CPG_UNION)
            continue;
        for (k = 0; k < n->count; k++) {
            size_t kid = c->kids[n->first + k];
            memcpy(m[kid], c->nodes[kid].xf, sizeof m[0]);
            pds_affine_after(m[kid], m[i]);
            depth[kid] = depth[i] + 1;
        }
    }
}

/* Bounding box (u0,v0,u1,v1) of leaf `n` placed by `m`. */
static void pds_def_leaf_box(const pds_def *d, const pds_cpg_node *n, const double m[6], double box[4])
{
    double pts4[8];
    const double *pts;
    size_t cnt, i;
    if (n->op == PDS_CPG_ELLIPSE) {
        double eu = hypot(m[0] * n->p[2], m[1] * n->p[3]), ev = hypot(m[3] * n->p[2], m[4] * n->p[3]);
        double cu = m[0] * n->p[0] + m[1] * n->p[1] + m[2], cv = m[3] * n->p[0] + m[4] * n->p[1] + m[5];
        box[0] = cu - eu; box[1] = cv - ev; box[2] = cu + eu; box[3] = cv + ev;
        return;
    }
    if (n->op == PDS_CPG_RECT) {
        pts4[0] = n->p[0]; pts4[1] = n->p[1]; pts4[2] = n->p[2]; pts4[3] = n->p[1];
        pts4[4] = n->p[2]; pts4[5] = n->p[3]; pts4[6] = n->p[0]; pts4[7] = n->p[3];
        pts = pts4; cnt = 4;
    } else if (n->op == PDS_CPG_NESTED) {
        static const double unit[8] = { 0, 0, 1, 0, 1, 1, 0, 1 };
        pts = unit; cnt = 4;
    } else {
        pts = d->cpg.pts + 2 * n->first; cnt = n->count;
    }
    box[0] = box[1] = INFINITY; box[2] = box[3] = -INFINITY;
    for (i = 0; i < cnt; i++) {
        double u = m[0] * pts[2 * i] + m[1] * pts[2 * i + 1] + m[2];
        double v = m[3] * pts[2 * i] + m[4] * pts[2 * i + 1] + m[5];
        box[0] = fmin(box[0], u); box[1] = fmin(box[1], v);
        box[2] = fmax(box[2], u); box[3] = fmax(box[3], v);
    }
}

static const char *pds_def_op_name(pds_cpg_op op)
{
    static const char *names[] = { "rectangle", "ellipse", "polygon", "nested PDS", "union", "intersection",
                                   "difference" };
    return names[op];
}

static int pds_def_check_nested(const pds_def *sub, const char *file, diag *err, int depth);

static int pds_def_check_cpg(const pds_def *d, const char *file, diag *err, int nest)
{
    const pds_cpg *c = &d->cpg;
    size_t i, k;
    unsigned char *used;
    double (*m)[6];
    int *depth, rc = 0;
    if (c->nnodes == 0)
        return FAIL(d->loc, "CPG defines no regions");
    if (c->nnodes > PDS_MAX_NODES)
        return FAIL(d->loc, "CPG has %zu nodes (limit %d)", c->nnodes, PDS_MAX_NODES);
    if (c->root >= c->nnodes)
        return FAIL(d->loc, "CPG root is not a defined node");
    for (i = 0; i < c->nnodes; i++) {
        const pds_cpg_node *n = &c->nodes[i];
        double det = n->xf[0] * n->xf[4] - n->xf[1] * n->xf[3];
        if (!pds_def_finite_all(n->xf, 6))
            return FAIL(n->loc, "%s transform has a non-finite value", pds_def_op_name(n->op));
        if (det == 0 || !isfinite(det))
            return FAIL(n->loc, "%s transform is singular (it flattens the region)", pds_def_op_name(n->op));
        if (!pds_def_id_ok(n->attr) && !(n->op >= PDS_CPG_NESTED && n->attr == PDS_INHERIT))
            return FAIL(n->loc, "region attribute id %ld is out of range (0..%d or none)",
                        (long)n->attr, PDS_MAX_ATTR);
        switch (n->op) {
        case PDS_CPG_RECT:
            if (!pds_def_finite_all(n->p, 4))
                return FAIL(n->loc, "rectangle has a non-finite coordinate");
            if (!(n->p[0] < n->p[2] && n->p[1] < n->p[3]))
                return FAIL(n->loc, "rectangle is empty (it needs u0 < u1 and v0 < v1)");
            break;
        case PDS_CPG_ELLIPSE:
            if (!pds_def_finite_all(n->p, 4))
                return FAIL(n->loc, "ellipse has a non-finite value");
            if (!(n->p[2] > 0 && n->p[3] > 0))
                return FAIL(n->loc, "ellipse is empty (radii %g and %g must be positive)", n->p[2], n->p[3]);
            break;
        case PDS_CPG_POLYGON:
            if (n->first > c->npts || n->count > c->npts - n->first)
                return FAIL(n->loc, "polygon vertices are not defined");
            if (n->count < 3)
                return FAIL(n->loc, "polygon needs at least 3 vertices, got %zu", n->count);
            if (n->count > PDS_MAX_VERTICES)
                return FAIL(n->loc, "polygon has %zu vertices (limit %d)", n->count, PDS_MAX_VERTICES);
            if (!pds_def_finite_all(c->pts + 2 * n->first, 2 * n->count))
                return FAIL(n->loc, "polygon has a non-finite coordinate");
            rc = pds_def_check_ring(c->pts + 2 * n->first, n->count, "polygon", 0, file, n->loc, err);
            if (rc)
                return rc;
            break;
        case PDS_CPG_NESTED:
            if (!n->sub)
                return FAIL(n->loc, "nested PDS is not defined");
            if (n->sub == d)
                return FAIL(n->loc, "a PDS cannot contain itself");
            break;
        default:
            if (n->count == 0)
                return FAIL(n->loc, "%s needs at least one operand", pds_def_op_name(n->op));
            if (n->first > c->nkids || n->count > c->nkids - n->first)
                return FAIL(n->loc, "%s operands are not defined", pds_def_op_name(n->op));
            for (k = 0; k < n->count; k++)
                if (c->kids[n->first + k] >= i)
                    return FAIL(n->loc, "%s operand %zu is not defined before it",
                                pds_def_op_name(n->op), k + 1);
        }
    }
    used = mem_calloc(c->nnodes, 1);
    m = mem_calloc(c->nnodes, sizeof *m);
    depth = mem_calloc(c->nnodes, sizeof *depth);
    if (!used || !m || !depth) {
        rc = diag_at(err, DIAG_IO, file, d->loc.line, d->loc.col, "out of memory checking a CPG");
        goto done;
    }
    for (i = 0; i < c->nnodes && !rc; i++) {
        const pds_cpg_node *n = &c->nodes[i];
        if (n->op < PDS_CPG_UNION)
            continue;
        for (k = 0; k < n->count; k++) {
            size_t kid = c->kids[n->first + k];
            if (used[kid]) {
                rc = FAIL(n->loc, "%s operand %zu is already an operand elsewhere (CPG must be a tree)",
                          pds_def_op_name(n->op), k + 1);
                break;
            }
            used[kid] = 1;
        }
    }
    if (rc)
        goto done;
    pds_cpg_placements(d, m, depth);
    for (i = 0; i < c->nnodes; i++) {
        const pds_cpg_node *n = &c->nodes[i];
        double box[4];
        if (depth[i] < 0)
            continue;
        if (depth[i] > PDS_MAX_DEPTH) {
            rc = FAIL(n->loc, "CPG is nested deeper than %d levels", PDS_MAX_DEPTH);
            goto done;
        }
        if (n->op >= PDS_CPG_UNION)
            continue;
        pds_def_leaf_box(d, n, m[i], box);
        if (!(box[0] >= -PDS_COORD_MAX && box[1] >= -PDS_COORD_MAX &&
              box[2] <= PDS_COORD_MAX && box[3] <= PDS_COORD_MAX)) {
            rc = FAIL(n->loc, "%s reaches beyond -%g..%g after its transforms", pds_def_op_name(n->op),
                      PDS_COORD_MAX, PDS_COORD_MAX);
            goto done;
        }
        if (n->op == PDS_CPG_NESTED) {
            /* Its unit square must stay wide enough for the inverse map to
             * keep its coefficients small; then check the PDS it holds. */
            double smin, smax;
            dmath_sv2(m[i][0], m[i][1], m[i][3], m[i][4], &smin, &smax);
            if (smin < PDS_MIN_FEATURE) {
                rc = FAIL(n->loc, "nested PDS is thinner than 1/8192 after its transforms");
                goto done;
            }
            if (smax > 4096 * smin) {
                rc = FAIL(n->loc, "nested PDS is more than 4096 times longer than wide after its transforms");
                goto done;
            }
            rc = pds_def_check_nested(n->sub, file, err, nest + 1);
            if (rc)
                goto done;
        }
        if (n->op == PDS_CPG_ELLIPSE) {
            /* Smallest semi-axis: the smaller singular value of the 2x2
             * linear part of root_from_disk. */
            double smin, smax;
            dmath_sv2(m[i][0] * n->p[2], m[i][1] * n->p[3], m[i][3] * n->p[2], m[i][4] * n->p[3],
                      &smin, &smax);
            if (smin < PDS_MIN_FEATURE) {
                rc = FAIL(n->loc, "ellipse is thinner than 1/8192 after its transforms");
                goto done;
            }
            if (smax > 4096 * smin) {
                rc = FAIL(n->loc, "ellipse is more than 4096 times longer than wide after its transforms");
                goto done;
            }
        }
    }
done:
    mem_free(used);
    mem_free(m);
    mem_free(depth);
    return rc;
}

static int pds_def_check_pixels(const pds_pixels *px, const char *what, const char *file,
                                scene_loc loc, diag *err)
{
    size_t i, n;
    if (px->width < 1 || px->height < 1 || px->width > PDS_MAX_SIDE || px->height > PDS_MAX_SIDE)
        return FAIL(loc, "%s size %d x %d is out of range (1..%d per side)", what, px->width,
                    px->height, PDS_MAX_SIDE);
    n = (size_t)px->width * (size_t)px->height;
    if (n > (size_t)PDS_MAX_CELLS)
        return FAIL(loc, "%s has %zu cells (limit %ld)", what, n, PDS_MAX_CELLS);
    if (px->ncells != n)
        return FAIL(loc, "%s is %d x %d (%zu cells) but %zu values were given", what, px->width,
                    px->height, n, px->ncells);
    for (i = 0; i < n; i++)
        if (!pds_def_id_ok(px->cells[i]))
            return FAIL(loc, "%s value %ld at column %zu, row %zu is not a region attribute id",
                        what, (long)px->cells[i], i % (size_t)px->width + 1, i / (size_t)px->width + 1);
    return 0;
}

static int pds_def_check_tiling(const pds_def *d, const char *file, diag *err)
{
    const pds_tiling *t = &d->tiling;
    size_t i;
    int two = t->shape == PDS_TILE_SQUARE || t->shape == PDS_TILE_BRICK;
    double smin = two ? fmin(t->size[0], t->size[1]) : t->size[0];
    if ((unsigned)t->shape > PDS_TILE_TRIANGLE || (unsigned)t->rule > PDS_RULE_HASH)
        return FAIL(d->loc, "unknown tile shape or rule");
    for (i = 0; i < (two ? 2u : 1u); i++)
        if (!(t->size[i] >= PDS_MIN_FEATURE && t->size[i] <= 1))
            return FAIL(d->loc, "tile size %g is out of range (1/8192..1)", t->size[i]);
    if (!(t->mortar >= 0 && t->mortar < smin / 2))
        return FAIL(d->loc, "mortar width %g must be at least 0 and below half the tile size", t->mortar);
    if (!(t->offset >= 0 && t->offset < 1))
        return FAIL(d->loc, "brick offset %g must be in 0..1 (exclusive)", t->offset);
    if (t->nattrs == 0)
        return FAIL(d->loc, "tiling needs at least one tile attribute");
    for (i = 0; i < t->nattrs; i++)
        if (!pds_def_id_ok(t->attrs[i]))
            return FAIL(d->loc, "region attribute id %ld is out of range (0..%d or none)",
                        (long)t->attrs[i], PDS_MAX_ATTR);
    if (!pds_def_id_ok(t->mortar_attr))
        return FAIL(d->loc, "region attribute id %ld is out of range (0..%d or none)",
                    (long)t->mortar_attr, PDS_MAX_ATTR);
    return 0;
}

typedef struct seed_key { double u, v; size_t i; } seed_key;

static int pds_def_seed_cmp(const void *a, const void *b)
{
    const seed_key *x = a, *y = b;
    if (x->u != y->u)
        return x->u < y->u ? -1 : 1;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

static int pds_def_check_mosaic(const pds_def *d, const char *file, diag *err)
{
    const pds_mosaic *m = &d->mosaic;
    seed_key *keys;
    size_t i;
    int rc = 0;
    if (m->nseeds == 0)
        return FAIL(d->loc, "mosaic needs at least one seed");
    if (m->nseeds > (size_t)PDS_MAX_SEEDS)
        return FAIL(d->loc, "mosaic has %zu seeds (limit %ld)", m->nseeds, PDS_MAX_SEEDS);
    if (!(m->mortar >= 0 && m->mortar <= 0.25))
        return FAIL(d->loc, "mortar width %g must be in 0..0.25", m->mortar);
    if (!pds_def_id_ok(m->mortar_attr))
        return FAIL(d->loc, "region attribute id %ld is out of range (0..%d or none)",
                    (long)m->mortar_attr, PDS_MAX_ATTR);
    for (i = 0; i < m->nseeds; i++) {
        double u = m->seeds[2 * i], v = m->seeds[2 * i + 1];
        if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
            return FAIL(d->loc, "mosaic seed %zu lies outside the unit square", i + 1);
        if (!pds_def_id_ok(m->attrs[i]))
            return FAIL(d->loc, "region attribute id %ld is out of range (0..%d or none)",
                        (long)m->attrs[i], PDS_MAX_ATTR);
    }
    keys = mem_calloc(m->nseeds, sizeof *keys);
    if (!keys)
        return diag_at(err, DIAG_IO, file, d->loc.line, d->loc.col, "out of memory checking a mosaic");
    for (i = 0; i < m->nseeds; i++) {
        keys[i].u = m->seeds[2 * i];
        keys[i].v = m->seeds[2 * i + 1];
        keys[i].i = i;
    }
    qsort(keys, m->nseeds, sizeof *keys, pds_def_seed_cmp);
    for (i = 1; i < m->nseeds; i++)
        if (keys[i].u == keys[i - 1].u && keys[i].v == keys[i - 1].v) {
            rc = FAIL(d->loc, "mosaic seeds %zu and %zu coincide", keys[i - 1].i + 1, keys[i].i + 1);
            break;
        }
    mem_free(keys);
    return rc;
}

static int pds_def_check_quadtree(const pds_def *d, const char *file, diag *err)
{
    const pds_quadtree *q = &d->quad;
    size_t i, pending = 1;
    /* need[k]: children still expected at depth k along the current path. */
    unsigned char need[PDS_QT_MAX_DEPTH + 2];
    int depth = 0;
    if (q->from_pixels)
        return pds_def_check_pixels(&q->pixels, "quadtree pixel array", file, d->loc, err);
    memset(need, 0, sizeof need);
    for (i = 0; i < q->ncode; i++) {
        int32_t c = q->code[i];
        if (pending == 0)
            return FAIL(d->loc, "quadtree code has %zu values after the tree is complete", q->ncode - i);
        if (c != PDS_QT_SPLIT && !pds_def_id_ok(c))
            return FAIL(d->loc, "quadtree value %ld is neither a region attribute id nor a split", (long)c);
        if (c == PDS_QT_SPLIT) {
            if (depth >= PDS_QT_MAX_DEPTH)
                return FAIL(d->loc, "quadtree is deeper than %d levels", PDS_QT_MAX_DEPTH);
            need[++depth] = 4;
            pending += 3;
            continue;
        }
        pending--;
        while (depth > 0 && --need[depth] == 0)
            depth--;
    }
    if (pending)
        return FAIL(d->loc, "quadtree code ends before the tree is complete (%zu more values needed)", pending);
    return 0;
}

/* Flattened ring of curve k in *pts (owned by caller iff *owned). */
static int pds_def_curve_ring(const pds_curves *c, const pds_curve *k, double **pts, size_t *n, int *owned)
{
    if (!k->bspline) {
        *pts = c->pts + 2 * k->first;
        *n = k->count;
        *owned = 0;
        return 0;
    }
    *owned = 1;
    return pds_curve_flatten(c->pts + 2 * k->first, k->count, c->tolerance, 4096,
                             PDS_MAX_VERTICES, pts, n);
}

int pds_curves_ring(const pds_curves *c, size_t i, double **pts, size_t *n, int *owned)
{
    return pds_def_curve_ring(c, &c->curves[i], pts, n, owned);
}

static int pds_def_check_curves(const pds_def *d, const char *file, diag *err)
{
    const pds_curves *c = &d->curves;
    size_t i, j;
    if (c->ncurves == 0)
        return FAIL(d->loc, "curve PDS defines no curves");
    if (!(c->tolerance >= 1e-6 && c->tolerance <= 0.01))
        return FAIL(d->loc, "curve tolerance %g is out of range (1e-06..0.01)", c->tolerance);
    for (i = 0; i < c->ncurves; i++) {
        const pds_curve *k = &c->curves[i];
        const char *what = k->bspline ? "B-spline curve" : "curve";
        double *pts;
        size_t n;
        int owned, rc;
        if (k->first > c->npts || k->count > c->npts - k->first)
            return FAIL(k->loc, "%s points are not defined", what);
        if (k->count < 3)
            return FAIL(k->loc, "%s needs at least 3 points, got %zu", what, k->count);
        if (k->count > PDS_MAX_VERTICES)
            return FAIL(k->loc, "%s has %zu points (limit %d)", what, k->count, PDS_MAX_VERTICES);
        if (!pds_def_id_ok(k->attr))
            return FAIL(k->loc, "region attribute id %ld is out of range (0..%d or none)",
                        (long)k->attr, PDS_MAX_ATTR);
        for (j = 0; j < k->count; j++) {
            double u = c->pts[2 * (k->first + j)], v = c->pts[2 * (k->first + j) + 1];
            if (!(fabs(u) <= PDS_COORD_MAX && fabs(v) <= PDS_COORD_MAX))
                return FAIL(k->loc, "%s point %zu is not a number in -%g..%g", what, j + 1,
                            PDS_COORD_MAX, PDS_COORD_MAX);
        }
        rc = pds_def_curve_ring(c, k, &pts, &n, &owned);
        if (rc == -1)
            return FAIL(k->loc, "%s flattens to more than %d points at tolerance %g", what,
                        PDS_MAX_VERTICES, c->tolerance);
        if (rc)
            return diag_at(err, DIAG_IO, file, k->loc.line, k->loc.col, "out of memory checking a curve");
        rc = pds_def_check_ring(pts, n, what, k->bspline, file, k->loc, err);
        if (owned)
            mem_free(pts);
        if (rc)
            return rc;
    }
    return 0;
}

static int pds_def_check_def(const pds_def *d, const char *file, diag *err, int nest);

/* A PDS held by a CPG leaf at nesting depth `depth`; deeper than
 * PDS_MAX_NESTING (which also catches cycles) is refused. */
static int pds_def_check_nested(const pds_def *sub, const char *file, diag *err, int depth)
{
    if (depth > PDS_MAX_NESTING)
        return FAIL(sub->loc, "PDS nested more than %d deep (or containing itself)", PDS_MAX_NESTING);
    return pds_def_check_def(sub, file, err, depth);
}

int pds_def_check(const pds_def *d, const char *file, diag *err)
{
    return pds_def_check_def(d, file, err, 0);
}

static int pds_def_check_def(const pds_def *d, const char *file, diag *err, int nest)
{
    switch (d->kind) {
    case PDS_CPG: return pds_def_check_cpg(d, file, err, nest);
    case PDS_PIXELS: return pds_def_check_pixels(&d->pixels, "pixel array", file, d->loc, err);
    case PDS_TILING: return pds_def_check_tiling(d, file, err);
    case PDS_MOSAIC: return pds_def_check_mosaic(d, file, err);
    case PDS_QUADTREE: return pds_def_check_quadtree(d, file, err);
    case PDS_CURVES: return pds_def_check_curves(d, file, err);
    default: return FAIL(d->loc, "unknown PDS kind");
    }
}
