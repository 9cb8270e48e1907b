/* test_pds — planar division structures in every numeric mode, against
 * independent double-precision references (seeded random points), plus the
 * exact boundary conventions, CPG priority rules, complexity, error texts
 * and an out-of-memory sweep. Points closer to a region boundary than the
 * mode's resolution are skipped: the reference decides that by probing
 * neighbours at that distance (and closer) and skipping the point if any
 * differs. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "num/fx.h"
#include "pds/pds_modes.h"
#include "pds/pds_strip_ops.h"
#include "model/pds_curve.h"
#include "model/pds_def.h"
#include "model/pds_image.h"
#include "util/mem.h"
#include "support.h"

#define M_PI 3.14159265358979323846

static const pds_mode_ops *const modes[] = {
    &q16_pds_mode_ops, &q32_pds_mode_ops, &f32_pds_mode_ops, &f64_pds_mode_ops,
    &hfp32_pds_mode_ops, &hfp64_pds_mode_ops
};
/* Boundary skip distance per mode (same order): a few units of rounding of
 * coordinates near 1 and of the products the lookups form (hfp32's last
 * digit near 1 is 16 times f32's). */
static const double mode_eps[] = { 4e-4, 1e-7, 3e-5, 1e-9, 5e-4, 1e-9 };
#define NMODES 6

static const scene_loc L0 = { 0, 0 };
static scene_loc at(long line, long col) { scene_loc l; l.line = line; l.col = col; return l; }

typedef int32_t (*ref_fn)(const void *ctx, double u, double v);

static void *compile_or_fail(const pds_mode_ops *m, const pds_def *d)
{
    void *p = NULL;
    diag err;
    char buf[700];
    diag_init(&err);
    if (m->compile(d, "t.deck", &p, &err)) {
        diag_format(&err, buf, sizeof buf);
        fail_msg("%s: compile failed: %s", m->mode, buf);
    }
    return p;
}

/* Compares every mode with ref on n random points; returns the number of
 * points compared (not skipped) in the last mode. */
static int compare_all(const pds_def *d, ref_fn ref, const void *ctx, uint64_t *seed, int n,
                       const char *what)
{
    int mi, i, compared = 0;
    for (mi = 0; mi < NMODES; mi++) {
        void *p = compile_or_fail(modes[mi], d);
        double e = mode_eps[mi];
        compared = 0;
        for (i = 0; i < n; i++) {
            double u = test_uniform(seed, 0, 1), v = test_uniform(seed, 0, 1);
            int32_t want = ref(ctx, u, v), got;
            int k, near = 0;
            for (k = 0; k < 24 && !near; k++) {
                /* Eight directions at e, e/3 and e/9: thin bands are caught too. */
                static const int du[8] = { 1, 1, 0, -1, -1, -1, 0, 1 }, dv[8] = { 0, 1, 1, 1, 0, -1, -1, -1 };
                double r = e / (k < 8 ? 1 : k < 16 ? 3 : 9);
                double pu = u + du[k % 8] * r, pv = v + dv[k % 8] * r;
                if (pu < 0 || pu > 1 || pv < 0 || pv > 1)
                    continue;
                near = ref(ctx, pu, pv) != want;
            }
            if (near)
                continue;
            compared++;
            got = modes[mi]->locate(p, u, v);
            if (got != want)
                fail_msg("%s, mode %s: at (%.17g, %.17g) got %ld, reference %ld", what, modes[mi]->mode,
                         u, v, (long)got, (long)want);
        }
        modes[mi]->free(p);
        if (compared < n * 8 / 10)
            fail_msg("%s, mode %s: only %d of %d points away from boundaries", what, modes[mi]->mode,
                     compared, n);
    }
    return compared;
}

/* ---- CPG reference ----------------------------------------------------- */

static int ref_poly_in(const double *pts, size_t n, double x, double y)
{
    size_t i, j;
    int in = 0;
    for (i = 0, j = n - 1; i < n; j = i++) {
        double xi = pts[2 * i], yi = pts[2 * i + 1], xj = pts[2 * j], yj = pts[2 * j + 1];
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
            in = !in;
    }
    return in;
}

/* References for PDSs nested in CPG leaves (test_pds_cpg_nested_*). */
static const pds_def *nest_def[4];
static ref_fn nest_ref[4];
static const void *nest_ctx[4];

static int32_t ref_nested(const pds_def *sub, double u, double v)
{
    int k;
    for (k = 0; k < 4; k++)
        if (nest_def[k] == sub)
            return nest_ref[k](nest_ctx[k], u, v);
    fail_msg("no reference for a nested PDS");
    return PDS_NONE;
}

/* Membership of parent-frame point (x,y) in definition node i; sets *attr. */
static int ref_cpg_node(const pds_def *d, size_t i, double x, double y, int32_t *attr)
{
    const pds_cpg_node *n = &d->cpg.nodes[i];
    const double *m = n->xf;
    double det = m[0] * m[4] - m[1] * m[3], px = x - m[2], py = y - m[5];
    double lx = (m[4] * px - m[1] * py) / det, ly = (-m[3] * px + m[0] * py) / det;
    int in = 0;
    size_t k;
    int32_t dummy;
    switch (n->op) {
    case PDS_CPG_RECT:
        in = lx >= n->p[0] && lx <= n->p[2] && ly >= n->p[1] && ly <= n->p[3];
        break;
    case PDS_CPG_ELLIPSE: {
        double a = (lx - n->p[0]) / n->p[2], b = (ly - n->p[1]) / n->p[3];
        in = a * a + b * b <= 1;
        break;
    }
    case PDS_CPG_POLYGON:
        in = ref_poly_in(d->cpg.pts + 2 * n->first, n->count, lx, ly);
        break;
    case PDS_CPG_NESTED:
        if (lx >= 0 && lx <= 1 && ly >= 0 && ly <= 1) {
            int32_t id = ref_nested(n->sub, lx, ly);
            if (id != PDS_NONE) {
                *attr = id;
                return 1;
            }
        }
        return 0;
    case PDS_CPG_UNION:
        for (k = 0; k < n->count && !in; k++)
            in = ref_cpg_node(d, d->cpg.kids[n->first + k], lx, ly, attr);
        break;
    case PDS_CPG_INTER:
    case PDS_CPG_DIFF:
        in = ref_cpg_node(d, d->cpg.kids[n->first], lx, ly, attr);
        for (k = 1; k < n->count && in; k++)
            if (ref_cpg_node(d, d->cpg.kids[n->first + k], lx, ly, &dummy) != (n->op == PDS_CPG_INTER))
                in = 0;
        break;
    }
    if (in && (n->op < PDS_CPG_NESTED || n->attr != PDS_INHERIT))
        *attr = n->attr;
    return in;
}

static int32_t ref_cpg(const void *ctx, double u, double v)
{
    const pds_def *d = ctx;
    int32_t a = PDS_NONE;
    return ref_cpg_node(d, d->cpg.root, u, v, &a) ? a : PDS_NONE;
}

static int32_t next_attr;

/* A random leaf: rectangle, ellipse or star-shaped (often non-convex) polygon. */
static size_t random_leaf(pds_def *d, uint64_t *s)
{
    double cu = test_uniform(s, 0.2, 0.8), cv = test_uniform(s, 0.2, 0.8), r = test_uniform(s, 0.08, 0.3);
    long idx;
    switch (test_rand(s) % 3) {
    case 0:
        idx = pds_cpg_rect(d, cu - r, cv - r * test_uniform(s, 0.3, 1), cu + r * test_uniform(s, 0.3, 1), cv + r,
                           next_attr++, L0);
        break;
    case 1:
        idx = pds_cpg_ellipse(d, cu, cv, r, r * test_uniform(s, 0.3, 1.5), next_attr++, L0);
        break;
    default: {
        double pts[2 * 12];
        int n = 3 + (int)(test_rand(s) % 10), k;
        for (k = 0; k < n; k++) {
            double ang = 2 * M_PI * (k + test_uniform(s, 0.05, 0.95)) / n, rr = r * test_uniform(s, 0.3, 1);
            pts[2 * k] = cu + rr * cos(ang);
            pts[2 * k + 1] = cv + rr * sin(ang);
        }
        idx = pds_cpg_polygon(d, pts, (size_t)n, next_attr++, L0);
    }
    }
    assert_true(idx >= 0);
    return (size_t)idx;
}

static void random_placement(pds_def *d, size_t node, uint64_t *s)
{
    switch (test_rand(s) % 5) {
    case 0:
        break;
    case 1:
        pds_cpg_translate(d, node, -0.5, -0.5);
        pds_cpg_rotate(d, node, test_uniform(s, -180, 180));
        pds_cpg_translate(d, node, 0.5, 0.5);
        break;
    case 2:
        pds_cpg_translate(d, node, -0.5, -0.5);
        pds_cpg_scale(d, node, test_uniform(s, 0.6, 1.2), test_uniform(s, 0.6, 1.2));
        pds_cpg_translate(d, node, 0.5, 0.5);
        break;
    case 3:
        pds_cpg_translate(d, node, -0.5, -0.5);
        pds_cpg_shear(d, node, test_uniform(s, -0.4, 0.4), test_uniform(s, -0.4, 0.4));
        pds_cpg_translate(d, node, 0.5, 0.5);
        break;
    default:
        pds_cpg_translate(d, node, test_uniform(s, -0.1, 0.1), test_uniform(s, -0.1, 0.1));
    }
}

static size_t random_tree(pds_def *d, uint64_t *s, int depth)
{
    size_t kids[4], idx;
    int n, k;
    long r;
    if (depth == 0 || test_rand(s) % 4 == 0)
        idx = random_leaf(d, s);
    else {
        static const pds_cpg_op ops[3] = { PDS_CPG_UNION, PDS_CPG_INTER, PDS_CPG_DIFF };
        n = 2 + (int)(test_rand(s) % 3);
        for (k = 0; k < n; k++)
            kids[k] = random_tree(d, s, depth - 1);
        r = pds_cpg_op_node(d, ops[test_rand(s) % 3], kids, (size_t)n,
                            test_rand(s) % 4 == 0 ? next_attr++ : PDS_INHERIT, L0);
        assert_true(r >= 0);
        idx = (size_t)r;
    }
    random_placement(d, idx, s);
    return idx;
}

static void test_pds_cpg_matches_reference(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_matches_reference");
    int t;
    (void)state;
    for (t = 0; t < 40; t++) {
        pds_def d;
        diag err;
        pds_def_init(&d, PDS_CPG, L0);
        next_attr = 0;
        d.cpg.root = random_tree(&d, &s, 3);
        diag_init(&err);
        assert_int_equal(pds_def_check(&d, "t.deck", &err), 0);
        compare_all(&d, ref_cpg, &d, &s, 400, "random CPG");
        pds_def_free(&d);
    }
}

/* Locates (u,v) in every mode and requires `want` from each. */
static void expect_all(const pds_def *d, double u, double v, int32_t want, const char *what)
{
    int mi;
    for (mi = 0; mi < NMODES; mi++) {
        void *p = compile_or_fail(modes[mi], d);
        int32_t got = modes[mi]->locate(p, u, v);
        modes[mi]->free(p);
        if (got != want)
            fail_msg("%s, mode %s: at (%.9g, %.9g) got %ld, want %ld", what, modes[mi]->mode, u, v,
                     (long)got, (long)want);
    }
}

/* Two overlapping rectangles a = [0.125,0.625]^2 (id 1), b = [0.375,0.875]^2 (id 2). */
static void two_rects(pds_def *d, pds_cpg_op op, int32_t op_attr)
{
    size_t k[2];
    pds_def_init(d, PDS_CPG, L0);
    k[0] = (size_t)pds_cpg_rect(d, 0.125, 0.125, 0.625, 0.625, 1, L0);
    k[1] = (size_t)pds_cpg_rect(d, 0.375, 0.375, 0.875, 0.875, 2, L0);
    assert_true(pds_cpg_op_node(d, op, k, 2, op_attr, L0) >= 0);
}

static void test_pds_cpg_priority_rules(void **state)
{
    pds_def d;
    size_t k[3];
    (void)state;
    two_rects(&d, PDS_CPG_UNION, PDS_INHERIT);
    expect_all(&d, 0.5, 0.5, 1, "union overlap: first operand wins");
    expect_all(&d, 0.25, 0.25, 1, "union, a only");
    expect_all(&d, 0.75, 0.75, 2, "union, b only");
    expect_all(&d, 0.95, 0.1, PDS_NONE, "union, neither");
    pds_def_free(&d);
    two_rects(&d, PDS_CPG_INTER, PDS_INHERIT);
    expect_all(&d, 0.5, 0.5, 1, "intersection takes the first operand's id");
    expect_all(&d, 0.25, 0.25, PDS_NONE, "intersection, a only");
    pds_def_free(&d);
    two_rects(&d, PDS_CPG_DIFF, PDS_INHERIT);
    expect_all(&d, 0.25, 0.25, 1, "difference, a only");
    expect_all(&d, 0.5, 0.5, PDS_NONE, "difference, a and b");
    expect_all(&d, 0.75, 0.75, PDS_NONE, "difference, b only");
    pds_def_free(&d);
    two_rects(&d, PDS_CPG_UNION, 7);
    expect_all(&d, 0.75, 0.75, 7, "operator id overrides");
    pds_def_free(&d);
    /* Swapping the operands swaps the winner. */
    pds_def_init(&d, PDS_CPG, L0);
    k[1] = (size_t)pds_cpg_rect(&d, 0.125, 0.125, 0.625, 0.625, 1, L0);
    k[0] = (size_t)pds_cpg_rect(&d, 0.375, 0.375, 0.875, 0.875, 2, L0);
    pds_cpg_op_node(&d, PDS_CPG_UNION, k, 2, PDS_INHERIT, L0);
    expect_all(&d, 0.5, 0.5, 2, "union with operands swapped");
    pds_def_free(&d);
    /* n-ary: UNION(a,b,c): first containing; INTER(a,b,c): all; DIFF(a,b,c): a minus b minus c. */
    pds_def_init(&d, PDS_CPG, L0);
    k[0] = (size_t)pds_cpg_rect(&d, 0, 0, 0.5, 1, 1, L0);
    k[1] = (size_t)pds_cpg_rect(&d, 0.25, 0, 0.75, 1, 2, L0);
    k[2] = (size_t)pds_cpg_rect(&d, 0, 0, 1, 0.5, 3, L0);
    pds_cpg_op_node(&d, PDS_CPG_UNION, k, 3, PDS_INHERIT, L0);
    expect_all(&d, 0.375, 0.25, 1, "3-ary union, all three");
    expect_all(&d, 0.625, 0.25, 2, "3-ary union, b and c");
    expect_all(&d, 0.875, 0.25, 3, "3-ary union, c only");
    expect_all(&d, 0.875, 0.75, PDS_NONE, "3-ary union, none");
    d.cpg.nodes[3].op = PDS_CPG_INTER;
    expect_all(&d, 0.375, 0.25, 1, "3-ary intersection, all three");
    expect_all(&d, 0.375, 0.75, PDS_NONE, "3-ary intersection, a and b only");
    d.cpg.nodes[3].op = PDS_CPG_DIFF;
    expect_all(&d, 0.125, 0.75, 1, "3-ary difference, a only");
    expect_all(&d, 0.375, 0.75, PDS_NONE, "3-ary difference, a and b");
    expect_all(&d, 0.125, 0.25, PDS_NONE, "3-ary difference, a and c");
    pds_def_free(&d);
    /* Nested: UNION(DIFF(a, hole), b): the hole shows b, not a. */
    pds_def_init(&d, PDS_CPG, L0);
    k[0] = (size_t)pds_cpg_rect(&d, 0, 0, 1, 1, 1, L0);
    k[1] = (size_t)pds_cpg_ellipse(&d, 0.5, 0.5, 0.25, 0.25, 9, L0);
    k[0] = (size_t)pds_cpg_op_node(&d, PDS_CPG_DIFF, k, 2, PDS_INHERIT, L0);
    k[1] = (size_t)pds_cpg_rect(&d, 0.375, 0.375, 0.625, 0.625, 2, L0);
    pds_cpg_op_node(&d, PDS_CPG_UNION, k, 2, PDS_INHERIT, L0);
    expect_all(&d, 0.5, 0.5, 2, "nested: hole filled by the second union operand");
    expect_all(&d, 0.7, 0.5, PDS_NONE, "nested: hole outside b");
    expect_all(&d, 0.1, 0.1, 1, "nested: a outside the hole");
    pds_def_free(&d);
}

static void test_pds_cpg_boundaries_closed(void **state)
{
    pds_def d;
    size_t k[2];
    double tri[6] = { 0, 0, 0.5, 0, 0, 0.5 }, u = 1.0 / 65536;
    (void)state;
    pds_def_init(&d, PDS_CPG, L0);
    pds_cpg_rect(&d, 0.25, 0.25, 0.75, 0.5, 1, L0);
    expect_all(&d, 0.25, 0.25, 1, "rectangle corner is inside");
    expect_all(&d, 0.75, 0.375, 1, "rectangle right edge is inside");
    expect_all(&d, 0.5, 0.5, 1, "rectangle top edge is inside");
    expect_all(&d, 0.75 + u, 0.375, PDS_NONE, "one q16 unit right of the edge is outside");
    expect_all(&d, 0.5, 0.25 - u, PDS_NONE, "one q16 unit below the edge is outside");
    pds_def_free(&d);
    /* A rectangle rotated by 90 degrees about (0.5,0.5) stays exact. */
    pds_def_init(&d, PDS_CPG, L0);
    pds_cpg_rect(&d, 0.25, 0.25, 0.75, 0.5, 1, L0);
    pds_cpg_translate(&d, 0, -0.5, -0.5);
    pds_cpg_rotate(&d, 0, 90);
    pds_cpg_translate(&d, 0, 0.5, 0.5);
    expect_all(&d, 0.5, 0.25, 1, "rotated rectangle edge inside");
    expect_all(&d, 0.75, 0.75, 1, "rotated rectangle corner inside");
    expect_all(&d, 0.5 - u, 0.5, PDS_NONE, "rotated rectangle, just outside");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, L0);
    pds_cpg_polygon(&d, tri, 3, 4, L0);
    expect_all(&d, 0.25, 0.25, 4, "point on a diagonal polygon edge is inside");
    expect_all(&d, 0, 0, 4, "polygon vertex is inside");
    expect_all(&d, 0.25 + u, 0.25, PDS_NONE, "one unit beyond the diagonal edge");
    expect_all(&d, 0.125, 0.125, 4, "polygon interior");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, L0);
    pds_cpg_ellipse(&d, 0.5, 0.5, 0.25, 0.125, 5, L0);
    expect_all(&d, 0.75, 0.5, 5, "ellipse end of the u axis is inside");
    expect_all(&d, 0.5, 0.375, 5, "ellipse end of the v axis is inside");
    expect_all(&d, 0.75 + 4 * u, 0.5, PDS_NONE, "just beyond the ellipse");
    pds_def_free(&d);
    /* Difference removes the closed second operand: its edge is outside. */
    two_rects(&d, PDS_CPG_DIFF, PDS_INHERIT);
    expect_all(&d, 0.375, 0.5, PDS_NONE, "difference: b's edge belongs to b");
    expect_all(&d, 0.375 - u, 0.5, 1, "difference: just left of b's edge");
    pds_def_free(&d);
    (void)k;
}

/* Balanced union of an s x s grid of squares: O(log N) node visits. */
static double mean_steps(size_t n_side, const pds_mode_ops *m, uint64_t *s)
{
    pds_def d;
    size_t *kids = mem_calloc(n_side * n_side, sizeof *kids), i, j;
    double cell = 1.0 / (double)n_side, total = 0;
    unsigned long steps = 0;
    void *p;
    int t;
    assert_non_null(kids);
    pds_def_init(&d, PDS_CPG, L0);
    for (j = 0; j < n_side; j++)
        for (i = 0; i < n_side; i++)
            kids[j * n_side + i] = (size_t)pds_cpg_rect(&d, i * cell + cell / 8, j * cell + cell / 8,
                                                        (i + 1) * cell - cell / 8, (j + 1) * cell - cell / 8,
                                                        (int32_t)((i + j) % 3), L0);
    pds_cpg_op_node(&d, PDS_CPG_UNION, kids, n_side * n_side, PDS_INHERIT, L0);
    p = compile_or_fail(m, &d);
    for (t = 0; t < 2000; t++) {
        double u = test_uniform(s, 0, 1), v = test_uniform(s, 0, 1);
        int32_t got = m->locate_steps(p, u, v, &steps);
        double fu = u / cell - floor(u / cell), fv = v / cell - floor(v / cell);
        int inside = fu > 0.135 && fu < 0.865 && fv > 0.135 && fv < 0.865;
        if (inside)
            assert_int_equal(got, (int32_t)(((size_t)(u / cell) + (size_t)(v / cell)) % 3));
        else if (fu < 0.115 || fu > 0.885 || fv < 0.115 || fv > 0.885)
            assert_int_equal(got, PDS_NONE);
    }
    total = (double)steps / 2000;
    m->free(p);
    pds_def_free(&d);
    mem_free(kids);
    return total;
}

static void test_pds_cpg_visits_grow_logarithmically(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_visits_grow_logarithmically");
    static const size_t sides[4] = { 3, 10, 32, 100 };   /* N = 9 .. 10,000 */
    int i, mi;
    (void)state;
    for (mi = 0; mi < NMODES; mi++)
        for (i = 0; i < 4; i++) {
            double n = (double)(sides[i] * sides[i]), steps = mean_steps(sides[i], modes[mi], &s);
            printf("# %s N=%.0f mean node visits %.1f\n", modes[mi]->mode, n, steps);
            assert_true(steps <= 3 * log2(n) + 4);
        }
}

/* The same squares listed in spatial, reverse and shuffled order: the
 * operand order must decide priority only, not the cost. */
static double order_steps(size_t n, int order, const pds_mode_ops *m, uint64_t *s)
{
    pds_def d;
    size_t side = (size_t)ceil(sqrt((double)n)), *kids = mem_calloc(n, sizeof *kids), i;
    double cell = 1.0 / (double)side;
    unsigned long steps = 0;
    void *p;
    int t;
    assert_non_null(kids);
    pds_def_init(&d, PDS_CPG, L0);
    for (i = 0; i < n; i++) {
        size_t x = i % side, y = i / side;
        kids[i] = (size_t)pds_cpg_rect(&d, x * cell + cell / 8, y * cell + cell / 8, (x + 1) * cell - cell / 8,
                                       (y + 1) * cell - cell / 8, (int32_t)(i % 5), L0);
    }
    if (order == 1)
        for (i = 0; i < n / 2; i++) {
            size_t tmp = kids[i];
            kids[i] = kids[n - 1 - i];
            kids[n - 1 - i] = tmp;
        }
    else if (order == 2)
        for (i = n; i-- > 1;) {
            size_t j = (size_t)(test_rand(s) % (i + 1)), tmp = kids[i];
            kids[i] = kids[j];
            kids[j] = tmp;
        }
    pds_cpg_op_node(&d, PDS_CPG_UNION, kids, n, PDS_INHERIT, L0);
    p = compile_or_fail(m, &d);
    for (t = 0; t < 2000; t++)
        m->locate_steps(p, test_uniform(s, 0, 1), test_uniform(s, 0, 1), &steps);
    m->free(p);
    pds_def_free(&d);
    mem_free(kids);
    return (double)steps / 2000;
}

static void test_pds_cpg_visits_independent_of_order(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_visits_independent_of_order");
    static const size_t ns[3] = { 10, 1000, 10000 };
    static const char *const names[3] = { "spatial", "reverse", "shuffled" };
    int o, i, mi;
    (void)state;
    for (mi = 0; mi < NMODES; mi++)
        for (o = 0; o < 3; o++) {
            double v10 = 0;
            for (i = 0; i < 3; i++) {
                double v = order_steps(ns[i], o, modes[mi], &s);
                printf("# %s %s N=%zu mean node visits %.2f\n", modes[mi]->mode, names[o], ns[i], v);
                if (i == 0)
                    v10 = v;
                else
                    assert_true(v <= 3 * v10);
            }
        }
}

/* A plate minus n shuffled holes, and a 64-deep chain of two-operand
 * unions: the subtrahends form one indexed union, the chain one flat
 * union, so both cost about what 10 operands cost. */
static double diff_steps(size_t n, int chain, const pds_mode_ops *m, uint64_t *s)
{
    pds_def d;
    size_t side = (size_t)ceil(sqrt((double)n)), *kids = mem_calloc(n + 1, sizeof *kids), i;
    double cell = 1.0 / (double)side;
    unsigned long steps = 0;
    void *p;
    int t;
    assert_non_null(kids);
    pds_def_init(&d, PDS_CPG, L0);
    kids[0] = (size_t)pds_cpg_rect(&d, 0, 0, 1, 1, 9, L0);
    for (i = 0; i < n; i++) {
        size_t x = i % side, y = i / side;
        kids[i + 1] = (size_t)pds_cpg_ellipse(&d, (x + 0.5) * cell, (y + 0.5) * cell, cell / 3, cell / 3,
                                              (int32_t)(i % 5), L0);
    }
    for (i = n; i-- > 1;) {
        size_t j = 1 + (size_t)(test_rand(s) % i), tmp = kids[i + 1];
        kids[i + 1] = kids[j];
        kids[j] = tmp;
    }
    if (chain) {            /* UNION(k1, UNION(k2, ... UNION(kn, plate))) */
        size_t root = kids[0];
        for (i = n; i >= 1; i--) {
            size_t two[2];
            two[0] = kids[i];
            two[1] = root;
            root = (size_t)pds_cpg_op_node(&d, PDS_CPG_UNION, two, 2, PDS_INHERIT, L0);
        }
    } else {
        pds_cpg_op_node(&d, PDS_CPG_DIFF, kids, n + 1, PDS_INHERIT, L0);
    }
    p = compile_or_fail(m, &d);
    for (t = 0; t < 2000; t++) {
        double u = test_uniform(s, 0, 1), v = test_uniform(s, 0, 1);
        int32_t got = m->locate_steps(p, u, v, &steps);
        if (!chain)
            assert_true(got == PDS_NONE || got == 9);
    }
    m->free(p);
    pds_def_free(&d);
    mem_free(kids);
    return (double)steps / 2000;
}

static void test_pds_cpg_diff_and_chains_flat(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_diff_and_chains_flat");
    int mi;
    (void)state;
    for (mi = 0; mi < NMODES; mi++) {
        double d10 = diff_steps(10, 0, modes[mi], &s), d10k = diff_steps(10000, 0, modes[mi], &s);
        double c10 = diff_steps(10, 1, modes[mi], &s), c63 = diff_steps(63, 1, modes[mi], &s);
        printf("# %s plate minus 10 / 10000 holes: %.2f / %.2f visits; chain of 10 / 63 unions: %.2f / %.2f\n",
               modes[mi]->mode, d10, d10k, c10, c63);
        assert_true(d10k <= 3 * d10);
        assert_true(c63 <= 3 * c10);
    }
}

/* Exact reference in the mode itself: each leaf compiled alone (same
 * placement, so the same rounded shape) answers membership, and the
 * operator rules are applied here by plain recursion over the definition. */
typedef struct brute {
    const pds_def *d;
    const pds_mode_ops *m;
    void **leaf;          /* per definition node; NULL for operators */
} brute;

static int brute_node(const brute *b, size_t i, double u, double v, int32_t *attr)
{
    const pds_cpg_node *n = &b->d->cpg.nodes[i];
    size_t k;
    int in = 0;
    int32_t dummy;
    if (n->op < PDS_CPG_UNION) {
        int32_t id = b->m->locate(b->leaf[i], u, v);
        if (id == PDS_NONE)
            return 0;
        *attr = n->op == PDS_CPG_NESTED ? id : n->attr;
        return 1;
    }
    if (n->op == PDS_CPG_UNION) {
        for (k = 0; k < n->count && !in; k++)
            in = brute_node(b, b->d->cpg.kids[n->first + k], u, v, attr);
    } else {
        in = brute_node(b, b->d->cpg.kids[n->first], u, v, attr);
        for (k = 1; k < n->count && in; k++)
            if (brute_node(b, b->d->cpg.kids[n->first + k], u, v, &dummy) != (n->op == PDS_CPG_INTER))
                in = 0;
    }
    if (in && n->attr != PDS_INHERIT)
        *attr = n->attr;
    return in;
}

static void brute_init(brute *b, const pds_def *d, const pds_mode_ops *m)
{
    double (*pl)[6] = mem_calloc(d->cpg.nnodes, sizeof *pl);
    int *depth = mem_calloc(d->cpg.nnodes, sizeof *depth);
    size_t i;
    assert_true(pl && depth);
    b->d = d;
    b->m = m;
    b->leaf = mem_calloc(d->cpg.nnodes, sizeof *b->leaf);
    assert_non_null(b->leaf);
    pds_cpg_placements(d, pl, depth);
    for (i = 0; i < d->cpg.nnodes; i++) {
        const pds_cpg_node *n = &d->cpg.nodes[i];
        pds_def one;
        long k;
        if (depth[i] < 0 || n->op >= PDS_CPG_UNION)
            continue;
        pds_def_init(&one, PDS_CPG, L0);
        if (n->op == PDS_CPG_RECT)
            k = pds_cpg_rect(&one, n->p[0], n->p[1], n->p[2], n->p[3], 0, L0);
        else if (n->op == PDS_CPG_ELLIPSE)
            k = pds_cpg_ellipse(&one, n->p[0], n->p[1], n->p[2], n->p[3], 0, L0);
        else if (n->op == PDS_CPG_POLYGON)
            k = pds_cpg_polygon(&one, d->cpg.pts + 2 * n->first, n->count, 0, L0);
        else
            k = pds_cpg_nested(&one, n->sub, L0);
        assert_true(k == 0);
        memcpy(one.cpg.nodes[0].xf, pl[i], sizeof pl[i]);
        b->leaf[i] = compile_or_fail(m, &one);
        pds_def_free(&one);
    }
    mem_free(pl);
    mem_free(depth);
}

static void brute_free(brute *b)
{
    size_t i;
    for (i = 0; i < b->d->cpg.nnodes; i++)
        if (b->leaf[i])
            b->m->free(b->leaf[i]);
    mem_free(b->leaf);
}

/* A small leaf near (cu, cv), on the 1/256 grid half the time so that
 * lookups on its edges are exact in every mode. */
static size_t brute_leaf(pds_def *d, uint64_t *s, double cu, double cv, double r)
{
    long idx;
    int32_t id = test_rand(s) % 9 == 0 ? PDS_NONE : next_attr++;
    switch (test_rand(s) % 4) {
    case 0:
        idx = pds_cpg_rect(d, floor((cu - r) * 256) / 256, floor((cv - r) * 256) / 256,
                           ceil((cu + r) * 256) / 256, ceil((cv + r * 0.6) * 256) / 256, id, L0);
        break;
    case 1:
        idx = pds_cpg_rect(d, cu - r, cv - r * 0.5, cu + r * 0.7, cv + r, id, L0);
        break;
    case 2:
        idx = pds_cpg_ellipse(d, cu, cv, r, r * test_uniform(s, 0.4, 1.4), id, L0);
        break;
    default: {
        double pts[10];
        int k;
        for (k = 0; k < 5; k++) {
            double ang = 2 * M_PI * (k + test_uniform(s, 0.1, 0.9)) / 5;
            pts[2 * k] = cu + r * cos(ang);
            pts[2 * k + 1] = cv + r * sin(ang);
        }
        idx = pds_cpg_polygon(d, pts, 5, id, L0);
    }
    }
    assert_true(idx >= 0);
    return (size_t)idx;
}

/* A big union of n leaves in random order; sometimes written as a chain
 * of two-operand unions, some leaves grouped in sub-unions. */
static size_t brute_union(pds_def *d, uint64_t *s, size_t n, double rmax, int32_t attr)
{
    size_t *kids = mem_calloc(n, sizeof *kids), i, root;
    assert_non_null(kids);
    for (i = 0; i < n; i++)
        kids[i] = brute_leaf(d, s, test_uniform(s, 0, 1), test_uniform(s, 0, 1), test_uniform(s, 0.01, rmax));
    if (test_rand(s) % 3 == 0 && n <= 60) {
        root = kids[n - 1];      /* UNION(k0, UNION(k1, ... UNION(kn-2, kn-1))) */
        for (i = n - 1; i-- > 0;) {
            size_t two[2];
            two[0] = kids[i];
            two[1] = root;
            root = (size_t)pds_cpg_op_node(d, PDS_CPG_UNION, two, 2, i == 0 ? attr : PDS_INHERIT, L0);
        }
    } else {
        for (i = 0; i + 4 < n; i += 7)
            if (test_rand(s) % 3 == 0) {
                size_t sub = (size_t)pds_cpg_op_node(d, PDS_CPG_UNION, kids + i, 3,
                                                     test_rand(s) % 3 ? PDS_INHERIT : next_attr++, L0);
                kids[i] = sub;
                memmove(kids + i + 1, kids + i + 3, (n - i - 3) * sizeof *kids);
                n -= 2;
            }
        root = (size_t)pds_cpg_op_node(d, PDS_CPG_UNION, kids, n, attr, L0);
    }
    mem_free(kids);
    return root;
}

static void test_pds_cpg_index_matches_brute_force(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_index_matches_brute_force");
    int t, mi, i, busy[NMODES] = {0};
    (void)state;
    for (t = 0; t < 12; t++) {
        pds_def d;
        diag err;
        size_t top[4];
        pds_def_init(&d, PDS_CPG, L0);
        next_attr = 0;
        /* odd trees: large overlapping leaves, long cell lists (the hierarchy) */
        top[0] = brute_union(&d, &s, 20 + test_rand(&s) % 300, t % 2 ? 0.45 : 0.12, PDS_INHERIT);
        top[1] = brute_union(&d, &s, 10 + test_rand(&s) % 40, 0.12, test_rand(&s) % 2 ? PDS_INHERIT : next_attr++);
        switch (t % 3) {
        case 0:        /* a union of both */
            d.cpg.root = (size_t)pds_cpg_op_node(&d, PDS_CPG_UNION, top, 2, PDS_INHERIT, L0);
            break;
        case 1:        /* the first minus the second and a third union */
            top[2] = brute_union(&d, &s, 30, 0.12, PDS_INHERIT);
            d.cpg.root = (size_t)pds_cpg_op_node(&d, PDS_CPG_DIFF, top, 3, PDS_INHERIT, L0);
            break;
        default:       /* intersection with a chain of intersections */
            top[2] = brute_leaf(&d, &s, 0.5, 0.5, 0.4);
            top[3] = (size_t)pds_cpg_op_node(&d, PDS_CPG_INTER, top + 1, 2, PDS_INHERIT, L0);
            top[1] = top[3];
            d.cpg.root = (size_t)pds_cpg_op_node(&d, PDS_CPG_INTER, top, 2, PDS_INHERIT, L0);
        }
        diag_init(&err);
        assert_int_equal(pds_def_check(&d, "t.deck", &err), 0);
        for (mi = 0; mi < NMODES; mi++) {
            brute b;
            void *p = compile_or_fail(modes[mi], &d);
            int hits = 0;
            brute_init(&b, &d, modes[mi]);
            for (i = 0; i < 3000; i++) {
                /* half the points on the 1/256 grid: on rectangle edges */
                double u = i % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % 257) / 256;
                double v = i % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % 257) / 256;
                int32_t want = PDS_NONE, got = modes[mi]->locate(p, u, v);
                if (!brute_node(&b, d.cpg.root, u, v, &want))
                    want = PDS_NONE;
                if (got != want)
                    fail_msg("tree %d, mode %s: at (%.17g, %.17g) got %ld, brute force %ld", t,
                             modes[mi]->mode, u, v, (long)got, (long)want);
                hits += want != PDS_NONE;
            }
            busy[mi] += hits >= 100;   /* intersections may hold few points */
            brute_free(&b);
            modes[mi]->free(p);
        }
        pds_def_free(&d);
    }
    /* not vacuous: most trees put 100 or more of their points in a region */
    for (mi = 0; mi < NMODES; mi++)
        if (busy[mi] < 8)
            fail_msg("mode %s: only %d of 12 trees hold 100 of their 3000 points", modes[mi]->mode,
                     busy[mi]);
}

/* ---- pixel array and quadtree ------------------------------------------ */

typedef struct grid_ref { int w, h; const int32_t *cells; } grid_ref;
static int32_t ref_grid(const void *ctx, double u, double v);
static int32_t ref_tiling(const void *ctx, double u, double v);
static void expect_error(const pds_def *d, const char *want);

/* Figure 1's side face: a mirror rectangle, a band holding a pixel array
 * (its PDS_NONE cells transparent), and a brick tiling under both whose
 * mortar shows the base attribute. */
static void test_pds_cpg_nested_matches_reference(void **state)
{
    uint64_t s = test_seed("test_pds_cpg_nested_matches_reference");
    int32_t cells[12] = { 20, PDS_NONE, 21, 22, 20, 21, PDS_NONE, 22, 23, 23, 20, PDS_NONE };
    int32_t tiles[2] = { 30, 31 };
    pds_def d, px, tl;
    grid_ref g;
    size_t k[3];
    int rot;
    (void)state;
    pds_def_init(&px, PDS_PIXELS, L0);
    pds_pixels_set(&px.pixels, 4, 3, cells, 12);
    pds_def_init(&tl, PDS_TILING, L0);
    tl.tiling.shape = PDS_TILE_BRICK;
    tl.tiling.size[0] = 0.25;
    tl.tiling.size[1] = 0.125;
    tl.tiling.mortar = 1.0 / 64;
    pds_tiling_attrs(&tl, tiles, 2);
    g.w = 4; g.h = 3; g.cells = cells;
    nest_def[0] = &px; nest_ref[0] = ref_grid; nest_ctx[0] = &g;
    nest_def[1] = &tl; nest_ref[1] = ref_tiling; nest_ctx[1] = &tl.tiling;
    for (rot = 0; rot < 2; rot++) {
        pds_def_init(&d, PDS_CPG, L0);
        k[0] = (size_t)pds_cpg_rect(&d, 0.1, 0.6, 0.4, 0.8, 10, L0);
        k[1] = (size_t)pds_cpg_nested(&d, &px, L0);
        pds_cpg_scale(&d, k[1], 1, 0.2);
        pds_cpg_translate(&d, k[1], 0, 0.3);
        if (rot) {
            pds_cpg_translate(&d, k[1], -0.5, -0.4);
            pds_cpg_rotate(&d, k[1], 20);
            pds_cpg_translate(&d, k[1], 0.5, 0.4);
        }
        k[2] = (size_t)pds_cpg_nested(&d, &tl, L0);
        pds_cpg_op_node(&d, PDS_CPG_UNION, k, 3, PDS_INHERIT, L0);
        compare_all(&d, ref_cpg, &d, &s, 1500, "nested PDS in CPG");
        expect_all(&d, 0.25, 0.7, 10, "the rectangle comes first");
        expect_all(&d, 0.375, 0.75, 10, "rectangle over tiles");
        if (!rot) {
            expect_all(&d, 0.125, 0.4, 20, "band: middle row, first column");
            expect_all(&d, 0.4375, 0.45, 30, "band cell NONE: the tile (1, 3) shows through");
            expect_all(&d, 0.625, 0.0625, 30, "tile (2, 0)");
            expect_all(&d, 0.875, 0.0625, 31, "tile (3, 0)");
            expect_all(&d, 0.25, 0.0625, PDS_NONE, "mortar of the tiling: base attribute");
        }
        pds_def_free(&d);
    }
    pds_def_free(&px);
    pds_def_free(&tl);
}

static void test_pds_cpg_nested_errors(void **state)
{
    pds_def a, b, c, e[6];
    int i;
    (void)state;
    pds_def_init(&a, PDS_CPG, at(20, 1));
    pds_cpg_nested(&a, &a, at(21, 4));
    expect_error(&a, "bad.deck:21:4: error: a PDS cannot contain itself");
    pds_def_free(&a);
    pds_def_init(&a, PDS_CPG, at(20, 1));
    pds_cpg_nested(&a, NULL, at(21, 5));
    expect_error(&a, "bad.deck:21:5: error: nested PDS is not defined");
    pds_def_free(&a);
    /* An error inside the nested PDS is reported at its own location. */
    pds_def_init(&b, PDS_TILING, at(30, 2));
    pds_def_init(&a, PDS_CPG, at(20, 1));
    pds_cpg_nested(&a, &b, at(21, 6));
    expect_error(&a, "bad.deck:30:2: error: tiling needs at least one tile attribute");
    pds_def_free(&a);
    pds_def_free(&b);
    /* a contains b contains a: refused by the depth limit. */
    pds_def_init(&a, PDS_CPG, at(20, 1));
    pds_def_init(&b, PDS_CPG, at(40, 1));
    pds_cpg_nested(&a, &b, at(21, 7));
    pds_cpg_nested(&b, &a, at(41, 7));
    expect_error(&a, "bad.deck:40:1: error: PDS nested more than 4 deep (or containing itself)");
    pds_def_free(&a);
    pds_def_free(&b);
    /* Five levels of honest nesting are too deep, four are fine. */
    pds_def_init(&e[0], PDS_CPG, at(50, 1));
    pds_cpg_rect(&e[0], 0, 0, 1, 1, 1, L0);
    for (i = 1; i < 6; i++) {
        pds_def_init(&e[i], PDS_CPG, at(50 + i, 1));
        pds_cpg_nested(&e[i], &e[i - 1], L0);
    }
    expect_all(&e[4], 0.5, 0.5, 1, "four levels of nesting");
    expect_error(&e[5], "bad.deck:50:1: error: PDS nested more than 4 deep (or containing itself)");
    for (i = 0; i < 6; i++)
        pds_def_free(&e[i]);
    pds_def_init(&c, PDS_CPG, at(20, 1));
    pds_def_init(&b, PDS_PIXELS, at(60, 1));
    pds_cpg_nested(&c, &b, at(21, 8));
    pds_cpg_scale(&c, 0, 1, 0.0001);
    expect_error(&c, "bad.deck:21:8: error: nested PDS is thinner than 1/8192 after its transforms");
    pds_def_free(&c);
    pds_def_init(&c, PDS_CPG, at(20, 1));
    pds_cpg_nested(&c, &b, at(21, 9));
    pds_cpg_scale(&c, 0, 1, 0.0002);
    pds_cpg_rotate(&c, 0, 30);
    expect_error(&c, "bad.deck:21:9: error: nested PDS is more than 4096 times longer than wide after its transforms");
    pds_def_free(&c);
    pds_def_free(&b);
}


static int32_t ref_grid(const void *ctx, double u, double v)
{
    const grid_ref *g = ctx;
    int i = (int)floor(u * g->w), j = (int)floor(v * g->h);
    if (i >= g->w) i = g->w - 1;
    if (j >= g->h) j = g->h - 1;
    return g->cells[(g->h - 1 - j) * g->w + i];   /* rows listed from the top */
}

/* Random blocky grid: blobs of equal ids so a quadtree has work to do. */
static int32_t *random_grid(uint64_t *s, int w, int h)
{
    int32_t *c = mem_calloc((size_t)w * (size_t)h, sizeof *c);
    int i, j, b = 1 + (int)(test_rand(s) % 6);
    assert_non_null(c);
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++)
            c[j * w + i] = (int32_t)(((i >> b) * 7 + (j >> b) * 3 + (test_rand(s) % 16 == 0)) % 5) - 1;
    return c;
}

static void test_pds_pixels_match_reference(void **state)
{
    uint64_t s = test_seed("test_pds_pixels_match_reference");
    static const int sizes[][2] = { { 1, 1 }, { 2, 3 }, { 17, 5 }, { 64, 64 }, { 300, 7 } };
    int t;
    (void)state;
    for (t = 0; t < 5; t++) {
        pds_def d;
        grid_ref g;
        int32_t *cells = random_grid(&s, sizes[t][0], sizes[t][1]);
        pds_def_init(&d, PDS_PIXELS, L0);
        assert_int_equal(pds_pixels_set(&d.pixels, sizes[t][0], sizes[t][1], cells,
                                        (size_t)sizes[t][0] * (size_t)sizes[t][1]), 0);
        g.w = sizes[t][0]; g.h = sizes[t][1]; g.cells = cells;
        compare_all(&d, ref_grid, &g, &s, 500, "pixel array");
        pds_def_free(&d);
        mem_free(cells);
    }
}

static void test_pds_pixels_orientation_and_edges(void **state)
{
    pds_def d;
    int32_t cells[4] = { 10, 11, 12, 13 };   /* top row 10 11, bottom row 12 13 */
    (void)state;
    pds_def_init(&d, PDS_PIXELS, L0);
    pds_pixels_set(&d.pixels, 2, 2, cells, 4);
    expect_all(&d, 0.25, 0.75, 10, "top-left cell");
    expect_all(&d, 0.75, 0.25, 13, "bottom-right cell");
    expect_all(&d, 0.5, 0.5, 11, "cell edges are half-open: (0.5,0.5) is the upper-right cell");
    expect_all(&d, 1, 1, 11, "u = v = 1 falls in the last cell");
    expect_all(&d, 0, 0, 12, "origin is the bottom-left cell");
    expect_all(&d, -3, NAN, 12, "out-of-range and NaN input clamp to 0");
    expect_all(&d, 7, 2, 11, "large input clamps to 1");
    pds_def_free(&d);
}

static void test_pds_quadtree_matches_pixel_array(void **state)
{
    uint64_t s = test_seed("test_pds_quadtree_matches_pixel_array");
    static const int sizes[][2] = { { 1, 1 }, { 5, 3 }, { 64, 64 }, { 100, 37 }, { 256, 256 } };
    int t, mi, k;
    (void)state;
    for (t = 0; t < 5; t++) {
        int w = sizes[t][0], h = sizes[t][1];
        int32_t *cells = random_grid(&s, w, h);
        pds_def dp, dq;
        pds_def_init(&dp, PDS_PIXELS, L0);
        pds_def_init(&dq, PDS_QUADTREE, L0);
        pds_pixels_set(&dp.pixels, w, h, cells, (size_t)w * (size_t)h);
        pds_pixels_set(&dq.quad.pixels, w, h, cells, (size_t)w * (size_t)h);
        dq.quad.from_pixels = 1;
        for (mi = 0; mi < NMODES; mi++) {
            void *pp = compile_or_fail(modes[mi], &dp), *pq = compile_or_fail(modes[mi], &dq);
            double maxdepth = ceil(log2((double)(w > h ? w : h))) + 1;
            for (k = 0; k < 3000; k++) {
                /* Include points exactly on cell edges: both must agree. */
                double u = k % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % (unsigned)(w + 1)) / w;
                double v = k % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % (unsigned)(h + 1)) / h;
                unsigned long steps = 0;
                int32_t a = modes[mi]->locate(pp, u, v), b = modes[mi]->locate_steps(pq, u, v, &steps);
                if (a != b)
                    fail_msg("mode %s %dx%d at (%.17g, %.17g): quadtree %ld, pixels %ld", modes[mi]->mode, w,
                             h, u, v, (long)b, (long)a);
                assert_true((double)steps <= maxdepth + 1);
            }
            modes[mi]->free(pp);
            modes[mi]->free(pq);
        }
        pds_def_free(&dp);
        pds_def_free(&dq);
        mem_free(cells);
    }
}

static void test_pds_quadtree_explicit_order(void **state)
{
    /* Root split: SW = 1, SE = split(5, 6, 7, 8), NW = 3, NE = none. */
    int32_t code[] = { PDS_QT_SPLIT, 1, PDS_QT_SPLIT, 5, 6, 7, 8, 3, PDS_NONE };
    pds_def d;
    (void)state;
    pds_def_init(&d, PDS_QUADTREE, L0);
    pds_quadtree_code(&d, code, sizeof code / sizeof *code);
    expect_all(&d, 0.25, 0.25, 1, "SW");
    expect_all(&d, 0.625, 0.125, 5, "SE.SW");
    expect_all(&d, 0.875, 0.125, 6, "SE.SE");
    expect_all(&d, 0.625, 0.375, 7, "SE.NW");
    expect_all(&d, 0.875, 0.375, 8, "SE.NE");
    expect_all(&d, 0.25, 0.75, 3, "NW");
    expect_all(&d, 0.75, 0.75, PDS_NONE, "NE");
    expect_all(&d, 0.5, 0.5, PDS_NONE, "the centre belongs to NE (half-open cells)");
    pds_def_free(&d);
}


/* Random explicit quadtrees against a recursive double-precision descent. */
typedef struct qt_ref { const int32_t *code; size_t n; } qt_ref;

static int32_t ref_qt_node(const int32_t *code, size_t *pos, double x0, double y0, double size, double u,
                           double v, int32_t *hit)
{
    int32_t c = code[(*pos)++];
    int k;
    if (c != PDS_QT_SPLIT) {
        if (u >= x0 && u < x0 + size && v >= y0 && v < y0 + size)
            *hit = c;
        return 0;
    }
    for (k = 0; k < 4; k++)
        ref_qt_node(code, pos, x0 + (k & 1) * size / 2, y0 + (k >> 1) * size / 2, size / 2, u, v, hit);
    return 0;
}

static int32_t ref_qt(const void *ctx, double u, double v)
{
    const qt_ref *q = ctx;
    size_t pos = 0;
    int32_t hit = -99;
    /* Cells are half-open; u = 1 or v = 1 belong to the last cell. */
    if (u >= 1) u = 1 - 1e-12;
    if (v >= 1) v = 1 - 1e-12;
    ref_qt_node(q->code, &pos, 0, 0, 1, u, v, &hit);
    return hit;
}

static void random_code(uint64_t *s, int32_t *code, size_t *n, int depth)
{
    int k;
    if (depth < 6 && test_rand(s) % 3 != 0) {
        code[(*n)++] = PDS_QT_SPLIT;
        for (k = 0; k < 4; k++)
            random_code(s, code, n, depth + 1);
    } else
        code[(*n)++] = (int32_t)(test_rand(s) % 6) - 1;
}

static void test_pds_quadtree_explicit_matches_reference(void **state)
{
    uint64_t s = test_seed("test_pds_quadtree_explicit_matches_reference");
    static int32_t code[6000];
    int t;
    (void)state;
    for (t = 0; t < 10; t++) {
        pds_def d;
        qt_ref r;
        size_t n = 0;
        random_code(&s, code, &n, 0);
        pds_def_init(&d, PDS_QUADTREE, L0);
        assert_int_equal(pds_quadtree_code(&d, code, n), 0);
        r.code = code;
        r.n = n;
        compare_all(&d, ref_qt, &r, &s, 400, "explicit quadtree");
        pds_def_free(&d);
    }
}

/* Exact tile edges: cells are half-open (an edge belongs to the cell above
 * or to the right), the mortar band is closed. Dyadic values are exact in
 * every mode. */
static void test_pds_tiling_boundaries(void **state)
{
    int32_t attrs[2] = { 1, 2 };
    pds_def d;
    (void)state;
    pds_def_init(&d, PDS_TILING, L0);
    d.tiling.size[0] = d.tiling.size[1] = 0.125;
    pds_tiling_attrs(&d, attrs, 2);     /* checkerboard: (i + j) mod 2 */
    expect_all(&d, 0.25, 0.0625, 1, "u on a tile edge belongs to the right tile (i = 2)");
    expect_all(&d, 0.25 - 1.0 / 65536, 0.0625, 2, "just left of the edge (i = 1)");
    expect_all(&d, 0.0625, 0.125, 2, "v on a tile edge belongs to the tile above (j = 1)");
    d.tiling.mortar = 1.0 / 32;
    d.tiling.mortar_attr = 7;
    expect_all(&d, 0.25 + 1.0 / 64, 0.0625, 7, "the inner edge of the mortar band is mortar");
    expect_all(&d, 0.25 + 1.0 / 64 + 1.0 / 65536, 0.0625, 1, "just inside the tile");
    expect_all(&d, 0.25 - 1.0 / 64, 0.0625, 7, "mortar on the other side of the edge");
    d.tiling.shape = PDS_TILE_BRICK;
    d.tiling.mortar = 0;
    expect_all(&d, 0.0625, 0.1875, 2, "odd rows shift by half a brick: brick (0, 1) starts at u = 0.0625");
    expect_all(&d, 0.0625 - 1.0 / 65536, 0.1875, 1, "just before it lies brick (-1, 1)");
    pds_def_free(&d);
}

/* ---- tilings ------------------------------------------------------------ */

static long lmod(long a, long n) { long r = a % n; return r < 0 ? r + n : r; }

static int32_t ref_rule(const pds_tiling *t, long i, long j, long k)
{
    return t->attrs[lmod(i * t->step[0] + j * t->step[1] + k * t->step[2], (long)t->nattrs)];
}

static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(px - ax - t * dx, py - ay - t * dy);
}

/* Independent tiling reference: rectangles by floor; triangles by testing
 * candidate lattice triangles; hexagons by nearest lattice point over a
 * window of the whole lattice. */
static int32_t ref_tiling(const void *ctx, double u, double v)
{
    const pds_tiling *t = ctx;
    double w = t->size[0], m2 = t->mortar / 2;
    if (t->shape == PDS_TILE_SQUARE || t->shape == PDS_TILE_BRICK) {
        double h = t->size[1];
        long j = (long)floor(v / h), i;
        double lv = v - j * h, uu = u - (t->shape == PDS_TILE_BRICK && (j & 1) ? t->offset * w : 0), lu;
        i = (long)floor(uu / w);
        lu = uu - i * w;
        if (m2 > 0 && (lu <= m2 || lv <= m2 || lu >= w - m2 || lv >= h - m2))
            return t->mortar_attr;
        return ref_rule(t, i, j, 0);
    } else {
        double h = w * sqrt(3) / 2;
        long j0 = (long)floor(v / h), i, j, k;
        if (t->shape == PDS_TILE_TRIANGLE) {
            for (j = j0 - 1; j <= j0 + 1; j++)
                for (i = (long)floor((u - j * w / 2) / w) - 2; i <= (long)floor((u - j * w / 2) / w) + 2; i++)
                    for (k = 0; k < 2; k++) {
                        double x0 = i * w + j * w / 2, y0 = j * h, ax, ay, bx, by, cx, cy, d1, d2, d3;
                        if (!k) { ax = x0; ay = y0; bx = x0 + w; by = y0; cx = x0 + w / 2; cy = y0 + h; }
                        else { ax = x0 + w; ay = y0; bx = x0 + w * 1.5; by = y0 + h; cx = x0 + w / 2; cy = y0 + h; }
                        d1 = (bx - ax) * (v - ay) - (by - ay) * (u - ax);
                        d2 = (cx - bx) * (v - by) - (cy - by) * (u - bx);
                        d3 = (ax - cx) * (v - cy) - (ay - cy) * (u - cx);
                        if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) {
                            if (m2 > 0 && (seg_dist(u, v, ax, ay, bx, by) <= m2 || seg_dist(u, v, bx, by, cx, cy) <= m2 ||
                                           seg_dist(u, v, cx, cy, ax, ay) <= m2))
                                return t->mortar_attr;
                            return ref_rule(t, i, j, k);
                        }
                    }
            return -99;
        } else {
            long bi = 0, bj = 0;
            double best = INFINITY, cu = 0, cv = 0, mind = INFINITY;
            for (j = -2; j <= (long)(1 / h) + 2; j++)
                for (i = -(long)(1 / w) - 3; i <= (long)(1 / w) + 3; i++) {
                    double x = i * w + j * w / 2, y = j * h, dd = (x - u) * (x - u) + (y - v) * (y - v);
                    if (dd < best) { best = dd; bi = i; bj = j; cu = x; cv = y; }
                }
            for (j = bj - 1; j <= bj + 1; j++)
                for (i = bi - 1; i <= bi + 1; i++) {
                    double x = i * w + j * w / 2, y = j * h, sep = hypot(x - cu, y - cv), dd;
                    if (i == bi && j == bj)
                        continue;
                    dd = (x - u) * (x - u) + (y - v) * (y - v);
                    if (sep < 1.01 * w && (dd - best) / (2 * sep) < mind)
                        mind = (dd - best) / (2 * sep);
                }
            if (m2 > 0 && mind <= m2)
                return t->mortar_attr;
            return ref_rule(t, bi, bj, 0);
        }
    }
}

static void test_pds_tiling_matches_reference(void **state)
{
    uint64_t s = test_seed("test_pds_tiling_matches_reference");
    int shape, t;
    int32_t attrs[3] = { 4, 5, 6 };
    (void)state;
    for (shape = PDS_TILE_SQUARE; shape <= PDS_TILE_TRIANGLE; shape++)
        for (t = 0; t < 6; t++) {
            pds_def d;
            char what[160];
            pds_def_init(&d, PDS_TILING, L0);
            d.tiling.shape = (pds_tile_shape)shape;
            /* Sizes on the 2^-16 grid: exact in every mode (the cell index
             * multiplies any rounding of the size). */
            d.tiling.size[0] = floor(test_uniform(&s, 0.03, 0.4) * 65536) / 65536;
            d.tiling.size[1] = floor(test_uniform(&s, 0.03, 0.4) * 65536) / 65536;
            d.tiling.offset = test_uniform(&s, 0, 0.99);
            d.tiling.mortar = t % 2 ? 0.004 + test_uniform(&s, 0, 0.2) * fmin(d.tiling.size[0], d.tiling.size[1]) : 0;
            d.tiling.mortar_attr = 9;
            d.tiling.step[0] = (long)(test_rand(&s) % 7) - 3;
            d.tiling.step[1] = (long)(test_rand(&s) % 7) - 3;
            d.tiling.step[2] = (long)(test_rand(&s) % 3);
            pds_tiling_attrs(&d, attrs, 1 + test_rand(&s) % 3);
            snprintf(what, sizeof what, "tiling shape %d size %.17g %.17g offset %.17g mortar %.17g", shape,
                     d.tiling.size[0], d.tiling.size[1], d.tiling.offset, d.tiling.mortar);
            compare_all(&d, ref_tiling, &d.tiling, &s, 400, what);
            pds_def_free(&d);
        }
}

/* The hash rule: every mode agrees with f64 away from edges, ids from the set. */
static void test_pds_tiling_hash_rule_agrees_across_modes(void **state)
{
    uint64_t s = test_seed("test_pds_tiling_hash_rule_agrees_across_modes");
    int32_t attrs[4] = { 1, 2, 3, 4 };
    pds_def d;
    void *ref;
    int mi, k;
    (void)state;
    pds_def_init(&d, PDS_TILING, L0);
    d.tiling.rule = PDS_RULE_HASH;
    d.tiling.seed = 1234;
    d.tiling.size[0] = d.tiling.size[1] = 0.0625;
    pds_tiling_attrs(&d, attrs, 4);
    ref = compile_or_fail(&f64_pds_mode_ops, &d);
    for (mi = 0; mi < NMODES; mi++) {
        void *p = compile_or_fail(modes[mi], &d);
        int counts[5] = { 0, 0, 0, 0, 0 };
        for (k = 0; k < 2000; k++) {
            double u = (floor(test_uniform(&s, 0, 16)) + 0.5) / 16, v = (floor(test_uniform(&s, 0, 16)) + 0.5) / 16;
            int32_t a = modes[mi]->locate(p, u, v);
            assert_int_equal(a, f64_pds_mode_ops.locate(ref, u, v));
            assert_true(a >= 1 && a <= 4);
            counts[a]++;
        }
        for (k = 1; k <= 4; k++)
            assert_true(counts[k] > 200);   /* the hash spreads over all ids */
        modes[mi]->free(p);
    }
    f64_pds_mode_ops.free(ref);
    pds_def_free(&d);
}

/* ---- mosaic -------------------------------------------------------------- */

static int32_t ref_mosaic(const void *ctx, double u, double v)
{
    const pds_mosaic *m = ctx;
    size_t i, bi = 0;
    double best = INFINITY;
    for (i = 0; i < m->nseeds; i++) {
        double dd = (m->seeds[2 * i] - u) * (m->seeds[2 * i] - u) + (m->seeds[2 * i + 1] - v) * (m->seeds[2 * i + 1] - v);
        if (dd < best) { best = dd; bi = i; }
    }
    if (m->mortar > 0)
        for (i = 0; i < m->nseeds; i++) {
            double dd, sep;
            if (i == bi)
                continue;
            dd = (m->seeds[2 * i] - u) * (m->seeds[2 * i] - u) + (m->seeds[2 * i + 1] - v) * (m->seeds[2 * i + 1] - v);
            sep = hypot(m->seeds[2 * i] - m->seeds[2 * bi], m->seeds[2 * i + 1] - m->seeds[2 * bi + 1]);
            if ((dd - best) / (2 * sep) <= m->mortar / 2)
                return m->mortar_attr;
        }
    return m->attrs[bi];
}

static void test_pds_mosaic_matches_brute_force(void **state)
{
    uint64_t s = test_seed("test_pds_mosaic_matches_brute_force");
    static const int counts[] = { 1, 2, 9, 60, 2000 };
    int t, k;
    (void)state;
    for (t = 0; t < 5; t++)
        for (k = 0; k < 2; k++) {
            pds_def d;
            int i;
            size_t j;
            pds_def_init(&d, PDS_MOSAIC, L0);
            for (i = 0; i < counts[t]; i++) {
                /* Half the sets put most seeds in a tight cluster. */
                int clustered = (t + k) % 2 && i % 8 != 0;
                double cu = clustered ? 0.3 + test_uniform(&s, 0, 0.02) : test_uniform(&s, 0, 1);
                double cv = clustered ? 0.6 + test_uniform(&s, 0, 0.02) : test_uniform(&s, 0, 1);
                /* On the 2^-16 grid, so every mode holds the seeds exactly:
                 * the bisector of two close seeds seen from afar amplifies
                 * any rounding of their positions. */
                cu = floor(cu * 65536) / 65536;
                cv = floor(cv * 65536) / 65536;
                for (j = 0; j < d.mosaic.nseeds; j++)
                    if (d.mosaic.seeds[2 * j] == cu && d.mosaic.seeds[2 * j + 1] == cv)
                        break;
                if (j < d.mosaic.nseeds) {
                    i--;            /* coincides with an earlier seed: draw again */
                    continue;
                }
                if (pds_mosaic_seed(&d, cu, cv, i % 50) < 0)
                    fail_msg("out of memory");
            }
            d.mosaic.mortar = k ? 0.3 / sqrt((double)counts[t] + 1) / 4 : 0;
            d.mosaic.mortar_attr = 77;
            compare_all(&d, ref_mosaic, &d.mosaic, &s, 400, "mosaic");
            pds_def_free(&d);
        }
}

/* ---- curves ----------------------------------------------------------------- */

typedef struct curve_ref { double *pts[4]; size_t n[4]; int32_t attr[4]; size_t ncurves; } curve_ref;

static int32_t ref_curves(const void *ctx, double u, double v)
{
    const curve_ref *c = ctx;
    size_t i;
    for (i = 0; i < c->ncurves; i++)
        if (ref_poly_in(c->pts[i], c->n[i], u, v))
            return c->attr[i];
    return PDS_NONE;
}

static void test_pds_curves_match_reference(void **state)
{
    uint64_t s = test_seed("test_pds_curves_match_reference");
    int t;
    (void)state;
    for (t = 0; t < 12; t++) {
        pds_def d;
        curve_ref r;
        size_t i;
        pds_def_init(&d, PDS_CURVES, L0);
        r.ncurves = 3;
        for (i = 0; i < 3; i++) {
            /* Nested star-shaped curves, inner first; wiggly enough to be non-convex. */
            double pts[2 * 40], cu = 0.5, cv = 0.5, rad = 0.12 * (double)(i + 1);
            int n = 5 + (int)(test_rand(&s) % 35), k, bs = (int)(test_rand(&s) % 2);
            for (k = 0; k < n; k++) {
                double ang = 2 * M_PI * k / n, rr = rad * test_uniform(&s, 0.75, 1.0);
                pts[2 * k] = cu + rr * cos(ang);
                pts[2 * k + 1] = cv + rr * sin(ang);
            }
            assert_true(pds_curve_add(&d, bs, pts, (size_t)n, (int32_t)i + 1, L0) >= 0);
            r.attr[i] = (int32_t)i + 1;
            if (bs)
                assert_int_equal(pds_curve_flatten(pts, (size_t)n, d.curves.tolerance, 4096, PDS_MAX_VERTICES,
                                                   &r.pts[i], &r.n[i]), 0);
            else {
                r.pts[i] = mem_calloc((size_t)n, 2 * sizeof(double));
                memcpy(r.pts[i], pts, (size_t)n * 2 * sizeof(double));
                r.n[i] = (size_t)n;
            }
        }
        compare_all(&d, ref_curves, &r, &s, 600, "curves");
        for (i = 0; i < 3; i++)
            mem_free(r.pts[i]);
        pds_def_free(&d);
    }
}

static void test_pds_curves_bspline_circle(void **state)
{
    /* Control points on a regular 24-gon of radius 0.4: the curve lies
     * between 0.4 * (2 + cos(2 pi/24)) / 3 and 0.4 from the centre. */
    double pts[48], inner = 0.4 * (2 + cos(2 * M_PI / 24)) / 3;
    pds_def d;
    int k;
    uint64_t s = test_seed("test_pds_curves_bspline_circle");
    (void)state;
    for (k = 0; k < 24; k++) {
        pts[2 * k] = 0.5 + 0.4 * cos(2 * M_PI * k / 24);
        pts[2 * k + 1] = 0.5 + 0.4 * sin(2 * M_PI * k / 24);
    }
    pds_def_init(&d, PDS_CURVES, L0);
    pds_curve_add(&d, 1, pts, 24, 3, L0);
    for (k = 0; k < 50; k++) {
        double a = test_uniform(&s, 0, 2 * M_PI), r1 = test_uniform(&s, 0, inner - 0.002),
               r2 = test_uniform(&s, 0.402, 0.5);
        expect_all(&d, 0.5 + r1 * cos(a), 0.5 + r1 * sin(a), 3, "inside the B-spline circle");
        expect_all(&d, 0.5 + r2 * cos(a), 0.5 + r2 * sin(a), PDS_NONE, "outside the B-spline circle");
    }
    pds_def_free(&d);
}

/* The ring's vertices themselves are on the boundary, hence inside. */
static void test_pds_curves_boundary_closed(void **state)
{
    double sq[8] = { 0.25, 0.25, 0.75, 0.25, 0.75, 0.75, 0.25, 0.75 };
    double tri[6] = { 0.125, 0.125, 0.875, 0.5, 0.125, 0.875 };
    pds_def d;
    (void)state;
    pds_def_init(&d, PDS_CURVES, L0);
    pds_curve_add(&d, 0, sq, 4, 1, L0);
    pds_curve_add(&d, 0, tri, 3, 2, L0);
    expect_all(&d, 0.75, 0.5, 1, "on the square's edge");
    expect_all(&d, 0.25, 0.75, 1, "on the square's corner");
    expect_all(&d, 0.1875, 0.15625, 2, "on the triangle's slanted edge");
    expect_all(&d, 0.875, 0.5, 2, "at the triangle's vertex");
    expect_all(&d, 0.5, 0.5, 1, "inside both: the first curve wins");
    expect_all(&d, 0.9, 0.9, PDS_NONE, "outside both");
    pds_def_free(&d);
}


/* The flattened B-spline stays within the tolerance of the true curve:
 * dense samples of each segment (evaluated here from the basis) lie within
 * tol of the polyline. */
static double dist_to_polyline(const double *pts, size_t n, double x, double y)
{
    size_t i;
    double best = INFINITY;
    for (i = 0; i < n; i++) {
        const double *a = pts + 2 * i, *b = pts + 2 * ((i + 1) % n);
        double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((x - a[0]) * dx + (y - a[1]) * dy) / l2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        best = fmin(best, hypot(x - a[0] - t * dx, y - a[1] - t * dy));
    }
    return best;
}

static void test_pds_curve_flatten_within_tolerance(void **state)
{
    uint64_t s = test_seed("test_pds_curve_flatten_within_tolerance");
    int t;
    (void)state;
    for (t = 0; t < 20; t++) {
        double ctl[2 * 12], tol = t % 2 ? 1e-4 : 1e-3, *pts, worst = 0;
        size_t n = 3 + test_rand(&s) % 10, np, i;
        int k;
        for (i = 0; i < n; i++) {
            ctl[2 * i] = test_uniform(&s, 0, 1);
            ctl[2 * i + 1] = test_uniform(&s, 0, 1);
        }
        assert_int_equal(pds_curve_flatten(ctl, n, tol, 4096, PDS_MAX_VERTICES, &pts, &np), 0);
        for (i = 0; i < n; i++)
            for (k = 0; k <= 200; k++) {
                const double *p0 = ctl + 2 * ((i + n - 1) % n), *p1 = ctl + 2 * i;
                const double *p2 = ctl + 2 * ((i + 1) % n), *p3 = ctl + 2 * ((i + 2) % n);
                double u = k / 200.0, a = 1 - u;
                double b0 = a * a * a / 6, b1 = (3 * u * u * u - 6 * u * u + 4) / 6;
                double b2 = (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6, b3 = u * u * u / 6;
                double x = b0 * p0[0] + b1 * p1[0] + b2 * p2[0] + b3 * p3[0];
                double y = b0 * p0[1] + b1 * p1[1] + b2 * p2[1] + b3 * p3[1];
                worst = fmax(worst, dist_to_polyline(pts, np, x, y));
            }
        if (worst > tol)
            fail_msg("curve %d: deviation %g above tolerance %g", t, worst, tol);
        mem_free(pts);
    }
}

/* pds_curve_simple against an all-pairs check on random polygons. */
static int seg_touch_ref(const double *a, const double *b, const double *c, const double *d)
{
    double d1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double d2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    double d3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double d4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

static void test_pds_curve_simple_matches_all_pairs(void **state)
{
    uint64_t s = test_seed("test_pds_curve_simple_matches_all_pairs");
    int t, simple_seen = 0, crossing_seen = 0;
    (void)state;
    for (t = 0; t < 400; t++) {
        double pts[2 * 16];
        size_t n = 3 + test_rand(&s) % 10, i, j, ea, eb;
        int want = 1, got;
        /* Random points (in general position): mostly self-crossing; a
         * sorted-angle star now and then for simple ones. */
        for (i = 0; i < n; i++) {
            double ang = t % 3 ? test_uniform(&s, 0, 2 * M_PI) : 2 * M_PI * (i + test_uniform(&s, 0.1, 0.9)) / n;
            double r = test_uniform(&s, 0.1, 0.5);
            pts[2 * i] = 0.5 + r * cos(ang);
            pts[2 * i + 1] = 0.5 + r * sin(ang);
        }
        for (i = 0; i < n && want; i++)
            for (j = i + 2; j < n && want; j++) {
                if (i == 0 && j == n - 1)
                    continue;   /* adjacent through the closing edge */
                if (seg_touch_ref(pts + 2 * i, pts + 2 * ((i + 1) % n), pts + 2 * j, pts + 2 * ((j + 1) % n)))
                    want = 0;
            }
        got = pds_curve_simple(pts, n, &ea, &eb);
        if (got != want)
            fail_msg("polygon %d with %zu vertices: simple says %d, all pairs %d", t, n, got, want);
        if (!got)
            assert_true(seg_touch_ref(pts + 2 * ea, pts + 2 * ((ea + 1) % n), pts + 2 * eb, pts + 2 * ((eb + 1) % n)));
        simple_seen += want;
        crossing_seen += !want;
    }
    assert_true(simple_seen > 50 && crossing_seen > 50);
}

/* ---- q16 stays in range --------------------------------------------------- */

/* ---- Ballard's strip trees ----------------------------------------------- */

/* A star-shaped closed polyline on the 1/1024 grid (exact in every mode,
 * and degenerate cases such as touching edges occur). */
static size_t strip_poly(uint64_t *s, double *pts, size_t max, double cu, double cv, double r)
{
    size_t n = 5 + (size_t)(test_rand(s) % (max - 5)), k, j;
    for (k = 0; k < n; k++) {
        double a = 2 * M_PI * (k + test_uniform(s, 0.1, 0.9)) / (double)n, rr = r * test_uniform(s, 0.4, 1);
        pts[2 * k] = floor((cu + rr * cos(a)) * 1024) / 1024;
        pts[2 * k + 1] = floor((cv + rr * sin(a)) * 1024) / 1024;
    }
    for (k = 0, j = 0; k < n; k++)      /* drop repeated points */
        if (j == 0 || pts[2 * k] != pts[2 * j - 2] || pts[2 * k + 1] != pts[2 * j - 1]) {
            pts[2 * j] = pts[2 * k];
            pts[2 * j + 1] = pts[2 * k + 1];
            j++;
        }
    if (j > 1 && pts[0] == pts[2 * j - 2] && pts[1] == pts[2 * j - 1])
        j--;
    return j;
}

static int seg_meet_exact(const double *a, const double *b, const double *c, const double *d)
{
    /* dyadic coordinates of 10 bits: these products are exact in double */
    double o1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double o2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    double o3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double o4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    if ((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0) || (o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0))
        return 0;
    if (o1 == 0 && o2 == 0)
        return fmax(fmin(a[0], b[0]), fmin(c[0], d[0])) <= fmin(fmax(a[0], b[0]), fmax(c[0], d[0])) &&
               fmax(fmin(a[1], b[1]), fmin(c[1], d[1])) <= fmin(fmax(a[1], b[1]), fmax(c[1], d[1]));
    return 1;
}

/* Closed-boundary point in polygon, exact for the grid coordinates. */
static int poly_holds(const double *p, size_t n, double x, double y)
{
    size_t i, j;
    int in = 0;
    for (i = 0, j = n - 1; i < n; j = i++) {
        double q[2] = { x, y };
        if (seg_meet_exact(p + 2 * i, p + 2 * j, q, q))
            return 1;
        if ((p[2 * i + 1] > y) != (p[2 * j + 1] > y)) {
            /* lower end l, upper end h: p left of the crossing iff orient(l, h, p) > 0 */
            const double *l = p[2 * i + 1] < p[2 * j + 1] ? p + 2 * i : p + 2 * j;
            const double *h = l == p + 2 * i ? p + 2 * j : p + 2 * i;
            if ((h[0] - l[0]) * (y - l[1]) - (h[1] - l[1]) * (x - l[0]) > 0)
                in = !in;
        }
    }
    return in;
}

/* Strip-tree membership answers exactly what the box hierarchy answers, on
 * random points and on grid points (vertices and edges), in every mode and
 * at two width tolerances. */
static void test_pds_strip_membership_matches_boxes(void **state)
{
    uint64_t s = test_seed("test_pds_strip_membership_matches_boxes");
    static double pts[2 * 400];
    int t, mi, i, tested = 0;
    (void)state;
    for (t = 0; t < 24; t++) {
        pds_def a, b;
        size_t n = strip_poly(&s, pts, t % 2 ? 400 : 40, 0.5, 0.5, 0.45);
        pds_def_init(&a, PDS_CURVES, L0);
        pds_def_init(&b, PDS_CURVES, L0);
        assert_true(pds_curve_add(&a, t % 3 == 0, pts, n, 7, L0) >= 0);
        assert_true(pds_curve_add(&b, t % 3 == 0, pts, n, 7, L0) >= 0);
        b.curves.strips = 1;
        b.curves.strip_width = t % 4 < 2 ? 0 : 0.01;
        for (mi = 0; mi < NMODES; mi++) {
            void *pa, *pb;
            diag err;
            diag_init(&err);
            if (modes[mi]->compile(&a, "t", &pa, &err))
                break;          /* the random polygon is not simple: skip it */
            tested++;
            pb = compile_or_fail(modes[mi], &b);
            for (i = 0; i < 4000; i++) {
                double u = i % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % 1025) / 1024;
                double v = i % 2 ? test_uniform(&s, 0, 1) : (double)(test_rand(&s) % 1025) / 1024;
                if (i % 8 == 2) {       /* on a vertex */
                    size_t k = (size_t)(test_rand(&s) % n);
                    u = pts[2 * k];
                    v = pts[2 * k + 1];
                }
                if (modes[mi]->locate(pa, u, v) != modes[mi]->locate(pb, u, v))
                    fail_msg("polygon %d, mode %s: boxes and strips differ at (%.17g, %.17g)", t,
                             modes[mi]->mode, u, v);
            }
            modes[mi]->free(pa);
            modes[mi]->free(pb);
        }
        pds_def_free(&a);
        pds_def_free(&b);
    }
    assert_true(tested >= 20 * NMODES);
}

/* Ballard's intersection of two strip trees finds exactly the meeting edge
 * pairs a brute-force all-pairs test finds; the regions meet iff the
 * boundaries meet or one holds a vertex of the other; union and
 * intersection membership follow the two regions. Every mode. */
static void test_pds_strip_intersection_brute_force(void **state)
{
    static const pds_strip_ops *const sops[NMODES] = {
        &q16_pds_strip_ops, &q32_pds_strip_ops, &f32_pds_strip_ops, &f64_pds_strip_ops,
        &hfp32_pds_strip_ops, &hfp64_pds_strip_ops };
    uint64_t s = test_seed("test_pds_strip_intersection_brute_force");
    static double pa[2 * 300], pb[2 * 300];
    int t, mi, crossing = 0, apart = 0, nested = 0;
    (void)state;
    for (t = 0; t < 60; t++) {
        pds_def a, b;
        /* t % 3: 0 overlapping, 1 apart (opposite corners), 2 a small one at the other's centre */
        double ca = t % 3 == 1 ? 0.25 : test_uniform(&s, 0.4, 0.6), cb = t % 3 == 1 ? 0.75 : t % 3 == 2 ? ca
                                                                                    : test_uniform(&s, 0.3, 0.7);
        size_t na = strip_poly(&s, pa, 300, ca, ca, t % 3 == 1 ? 0.2 : 0.3);
        size_t nb = strip_poly(&s, pb, 300, cb, cb, t % 3 == 0 ? 0.25 : t % 3 == 1 ? 0.2 : 0.05);
        size_t i, j, want = 0;
        int want_meet;
        double u = test_uniform(&s, 0, 1), v = test_uniform(&s, 0, 1);
        for (i = 0; i < na; i++)
            for (j = 0; j < nb; j++)
                want += (size_t)seg_meet_exact(pa + 2 * i, pa + 2 * ((i + 1) % na), pb + 2 * j, pb + 2 * ((j + 1) % nb));
        want_meet = want > 0 || poly_holds(pa, na, pb[0], pb[1]) || poly_holds(pb, nb, pa[0], pa[1]);
        crossing += want > 0;
        apart += !want_meet;
        nested += want == 0 && want_meet;
        pds_def_init(&a, PDS_CURVES, L0);
        pds_def_init(&b, PDS_CURVES, L0);
        pds_curve_add(&a, 0, pa, na, 1, L0);
        pds_curve_add(&b, 0, pb, nb, 2, L0);
        a.curves.strip_width = t % 2 ? 0.02 : 0;
        for (mi = 0; mi < NMODES; mi++) {
            size_t got;
            int meet, in_u, in_i;
            assert_int_equal(sops[mi]->cross(&a, 0, &b, 0, u, v, &got, &meet, &in_u, &in_i), 0);
            if (got != want || meet != want_meet)
                fail_msg("pair %d, mode %s: %zu meeting edge pairs (brute force %zu), meet %d (%d)", t,
                         sops[mi]->mode, got, want, meet, want_meet);
            if (mode_eps[mi] < 1e-3) {     /* (u,v) off the grid: rounding matters only in q16 */
                int ia = poly_holds(pa, na, u, v), ib = poly_holds(pb, nb, u, v);
                assert_int_equal(in_u, ia || ib);
                assert_int_equal(in_i, ia && ib);
            }
        }
        pds_def_free(&a);
        pds_def_free(&b);
    }
    /* the random pairs cover all three cases */
    assert_true(crossing > 5 && apart > 5 && nested > 5);
}

static void test_pds_q16_counts_no_overflow(void **state)
{
    uint64_t s = test_seed("test_pds_q16_counts_no_overflow");
    unsigned long before = fx_overflows;
    pds_def d;
    void *p;
    int k;
    size_t kids[3];
    (void)state;
    /* Thin, far-off and large shapes at the documented limits. */
    pds_def_init(&d, PDS_CPG, L0);
    kids[0] = (size_t)pds_cpg_ellipse(&d, 0.5, 0.5, 0.45, 0.45 / 3000, 1, L0);
    pds_cpg_translate(&d, kids[0], -0.5, -0.5);
    pds_cpg_rotate(&d, kids[0], 33);
    pds_cpg_translate(&d, kids[0], 0.5, 0.5);
    kids[1] = (size_t)pds_cpg_ellipse(&d, 0.5, 0.5, 63, 63, 2, L0);
    kids[2] = (size_t)pds_cpg_rect(&d, -60, -60, 60, 60, 3, L0);
    pds_cpg_rotate(&d, kids[2], 1);
    pds_cpg_op_node(&d, PDS_CPG_UNION, kids, 3, PDS_INHERIT, L0);
    p = compile_or_fail(&q16_pds_mode_ops, &d);
    for (k = 0; k < 100000; k++)
        q16_pds_mode_ops.locate(p, test_uniform(&s, -0.5, 1.5), test_uniform(&s, -0.5, 1.5));
    q16_pds_mode_ops.free(p);
    pds_def_free(&d);
    /* A nested PDS on a thin rotated band, at the aspect limit. */
    {
        pds_def sub;
        int32_t cells[2] = { 1, 2 };
        pds_def_init(&sub, PDS_PIXELS, L0);
        pds_pixels_set(&sub.pixels, 2, 1, cells, 2);
        pds_def_init(&d, PDS_CPG, L0);
        pds_cpg_nested(&d, &sub, L0);
        pds_cpg_scale(&d, 0, 1, 1.0 / 4000);
        pds_cpg_rotate(&d, 0, 37);
        pds_cpg_translate(&d, 0, 0.1, 0.1);
        p = compile_or_fail(&q16_pds_mode_ops, &d);
        for (k = 0; k < 100000; k++)
            q16_pds_mode_ops.locate(p, test_uniform(&s, -0.5, 1.5), test_uniform(&s, -0.5, 1.5));
        q16_pds_mode_ops.free(p);
        pds_def_free(&d);
        pds_def_free(&sub);
    }
    assert_true(fx_overflows == before);
}

/* ---- error texts ----------------------------------------------------------- */

static void expect_error(const pds_def *d, const char *want)
{
    diag err;
    char buf[700];
    int mi;
    diag_init(&err);
    assert_int_equal(pds_def_check(d, "bad.deck", &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    if (strcmp(buf, want) != 0)
        fail_msg("error text\n  got:  %s\n  want: %s", buf, want);
    for (mi = 0; mi < NMODES; mi++) {
        void *p = NULL;
        diag_init(&err);
        assert_int_equal(modes[mi]->compile(d, "bad.deck", &p, &err), DIAG_INPUT);
        assert_null(p);
    }
}

static void test_pds_errors_exact_text(void **state)
{
    pds_def d;
    double two[4] = { 0, 0, 1, 1 }, flat[6] = { 0, 0, 0.5, 0.5, 1, 1 };
    double bow[8] = { 0, 0, 1, 1, 1, 0, 0, 0.5 }, dup[8] = { 0, 0, 1, 0, 1, 0, 0, 1 };
    double eight[2 * 6] = { 0.2, 0.2, 0.8, 0.8, 0.8, 0.2, 0.2, 0.8, 0.5, 0.9, 0.5, 0.1 };
    int32_t cells[3] = { 1, 2, 3 }, badcell[4] = { 1, 2, 70000, 3 };
    int32_t code_short[3] = { PDS_QT_SPLIT, 1, 2 }, code_long[3] = { 4, 5, 6 };
    size_t k[2];
    (void)state;
    pds_def_init(&d, PDS_CPG, at(3, 1));
    expect_error(&d, "bad.deck:3:1: error: CPG defines no regions");
    pds_cpg_polygon(&d, two, 2, 1, at(4, 10));
    expect_error(&d, "bad.deck:4:10: error: polygon needs at least 3 vertices, got 2");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_polygon(&d, NULL, 0, 1, at(4, 11));
    expect_error(&d, "bad.deck:4:11: error: polygon needs at least 3 vertices, got 0");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_polygon(&d, flat, 3, 1, at(5, 7));
    expect_error(&d, "bad.deck:5:7: error: polygon encloses no area");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_polygon(&d, bow, 4, 1, at(6, 2));
    expect_error(&d, "bad.deck:6:2: error: polygon edges 1 and 3 cross or touch (it must be simple)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_polygon(&d, dup, 4, 1, at(6, 3));
    expect_error(&d, "bad.deck:6:3: error: polygon points 2 and 3 coincide");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_ellipse(&d, 0.5, 0.5, 0, 0.25, 1, at(7, 4));
    expect_error(&d, "bad.deck:7:4: error: ellipse is empty (radii 0 and 0.25 must be positive)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_ellipse(&d, 0.5, 0.5, 0.25, NAN, 1, at(7, 5));
    expect_error(&d, "bad.deck:7:5: error: ellipse has a non-finite value");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_ellipse(&d, 0.5, 0.5, 0.25, 0.00001, 1, at(7, 6));
    expect_error(&d, "bad.deck:7:6: error: ellipse is thinner than 1/8192 after its transforms");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_ellipse(&d, 0.5, 0.5, 0.6, 0.00013, 1, at(7, 7));
    expect_error(&d, "bad.deck:7:7: error: ellipse is more than 4096 times longer than wide after its transforms");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_rect(&d, 0.5, 0.1, 0.5, 0.9, 1, at(8, 1));
    expect_error(&d, "bad.deck:8:1: error: rectangle is empty (it needs u0 < u1 and v0 < v1)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_rect(&d, 0.1, 0.1, 0.5, 0.9, 1, at(8, 2));
    pds_cpg_scale(&d, 0, 1, 0);
    expect_error(&d, "bad.deck:8:2: error: rectangle transform is singular (it flattens the region)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_rect(&d, 0.1, 0.1, 0.5, 0.9, 1, at(8, 3));
    pds_cpg_scale(&d, 0, 200, 1);
    expect_error(&d, "bad.deck:8:3: error: rectangle reaches beyond -64..64 after its transforms");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_rect(&d, 0.1, 0.1, 0.5, 0.9, 65536, at(8, 4));
    expect_error(&d, "bad.deck:8:4: error: region attribute id 65536 is out of range (0..65535 or none)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    k[0] = (size_t)pds_cpg_rect(&d, 0.1, 0.1, 0.5, 0.9, 1, at(8, 5));
    k[1] = k[0];
    pds_cpg_op_node(&d, PDS_CPG_UNION, k, 2, PDS_INHERIT, at(9, 1));
    expect_error(&d, "bad.deck:9:1: error: union operand 2 is already an operand elsewhere (CPG must be a tree)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    k[0] = 1;
    pds_cpg_op_node(&d, PDS_CPG_DIFF, k, 1, PDS_INHERIT, at(9, 2));
    expect_error(&d, "bad.deck:9:2: error: difference operand 1 is not defined before it");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CPG, at(3, 1));
    pds_cpg_op_node(&d, PDS_CPG_INTER, k, 0, PDS_INHERIT, at(9, 3));
    expect_error(&d, "bad.deck:9:3: error: intersection needs at least one operand");
    pds_def_free(&d);

    pds_def_init(&d, PDS_PIXELS, at(10, 1));
    pds_pixels_set(&d.pixels, 2, 2, cells, 3);
    expect_error(&d, "bad.deck:10:1: error: pixel array is 2 x 2 (4 cells) but 3 values were given");
    pds_pixels_set(&d.pixels, 2, 2, badcell, 4);
    expect_error(&d, "bad.deck:10:1: error: pixel array value 70000 at column 1, row 2 is not a region attribute id");
    pds_pixels_set(&d.pixels, 0, 2, cells, 0);
    expect_error(&d, "bad.deck:10:1: error: pixel array size 0 x 2 is out of range (1..32768 per side)");
    pds_def_free(&d);

    pds_def_init(&d, PDS_TILING, at(11, 1));
    expect_error(&d, "bad.deck:11:1: error: tiling needs at least one tile attribute");
    pds_tiling_attrs(&d, cells, 2);
    d.tiling.size[0] = 0;
    expect_error(&d, "bad.deck:11:1: error: tile size 0 is out of range (1/8192..1)");
    d.tiling.size[0] = 0.25;
    d.tiling.mortar = 0.125;
    expect_error(&d, "bad.deck:11:1: error: mortar width 0.125 must be at least 0 and below half the tile size");
    pds_def_free(&d);

    pds_def_init(&d, PDS_MOSAIC, at(12, 1));
    expect_error(&d, "bad.deck:12:1: error: mosaic needs at least one seed");
    pds_mosaic_seed(&d, 0.5, 0.5, 1);
    pds_mosaic_seed(&d, 0.25, 0.5, 1);
    pds_mosaic_seed(&d, 0.5, 0.5, 2);
    expect_error(&d, "bad.deck:12:1: error: mosaic seeds 1 and 3 coincide");
    d.mosaic.seeds[4] = 1.5;
    expect_error(&d, "bad.deck:12:1: error: mosaic seed 3 lies outside the unit square");
    pds_def_free(&d);

    pds_def_init(&d, PDS_QUADTREE, at(13, 1));
    pds_quadtree_code(&d, code_short, 3);
    expect_error(&d, "bad.deck:13:1: error: quadtree code ends before the tree is complete (2 more values needed)");
    pds_quadtree_code(&d, code_long, 3);
    expect_error(&d, "bad.deck:13:1: error: quadtree code has 2 values after the tree is complete");
    pds_def_free(&d);

    pds_def_init(&d, PDS_CURVES, at(14, 1));
    expect_error(&d, "bad.deck:14:1: error: curve PDS defines no curves");
    pds_curve_add(&d, 1, eight, 6, 1, at(15, 9));
    expect_error(&d, "bad.deck:15:9: error: B-spline curve intersects itself near (0.487, 0.533)");
    pds_def_free(&d);
    pds_def_init(&d, PDS_CURVES, at(14, 1));
    pds_curve_add(&d, 0, bow, 4, 1, at(16, 2));
    expect_error(&d, "bad.deck:16:2: error: curve edges 1 and 3 cross or touch (it must be simple)");
    pds_def_free(&d);
    {
        /* A comb: every edge spans the same u range, the worst case for the
         * sweep; refused quickly instead of taking quadratic time. */
        static double comb[2 * 20000];
        int i;
        for (i = 0; i < 10000; i++) {
            comb[4 * i] = i % 2 ? 0.9 : 0.1;
            comb[4 * i + 1] = i / 10000.0;
            comb[4 * i + 2] = i % 2 ? 0.1 : 0.9;
            comb[4 * i + 3] = (i + 0.5) / 10000.0;
        }
        comb[0] = 0.0;
        pds_def_init(&d, PDS_CURVES, at(14, 1));
        pds_curve_add(&d, 0, comb, 20000, 1, at(17, 1));
        {
            diag err;
            char buf[700];
            diag_init(&err);
            assert_int_equal(pds_def_check(&d, "bad.deck", &err), DIAG_INPUT);
            diag_format(&err, buf, sizeof buf);
            assert_string_equal(buf, "bad.deck:17:1: error: curve is too intricate to check for "
                                     "self-intersection (more than 10000000 edge pairs)");
        }
        pds_def_free(&d);
    }
    pds_def_init(&d, PDS_CURVES, at(14, 1));
    pds_curve_add(&d, 1, two, 2, 1, at(16, 3));
    expect_error(&d, "bad.deck:16:3: error: B-spline curve needs at least 3 points, got 2");
    pds_def_free(&d);
}

/* ---- images ---------------------------------------------------------------- */

static void test_pds_image_to_pixels(void **state)
{
    uint8_t grey[6] = { 0, 1, 2, 2, 1, 0 }, rgb[6] = { 255, 0, 0, 0, 0, 255 };
    uint8_t map_rgb[6] = { 0, 0, 255, 255, 0, 0 };
    int32_t table[3] = { 7, 8, 9 }, map_attr[2] = { 20, 21 };
    image img;
    pds_image_map map;
    pds_pixels px;
    diag err;
    char buf[700];
    (void)state;
    memset(&px, 0, sizeof px);
    memset(&map, 0, sizeof map);
    img.width = 3; img.height = 2; img.channels = 1; img.px = grey;
    diag_init(&err);
    assert_int_equal(pds_image_to_pixels(&img, NULL, &px, "i.deck", at(2, 5), &err), 0);
    assert_int_equal(px.cells[2], 2);
    map.index_attr = table; map.nindex = 3;
    assert_int_equal(pds_image_to_pixels(&img, &map, &px, "i.deck", at(2, 5), &err), 0);
    assert_int_equal(px.cells[3], 9);
    map.nindex = 2;
    assert_int_equal(pds_image_to_pixels(&img, &map, &px, "i.deck", at(2, 5), &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "i.deck:2:5: error: pixel (2, 0) has index 2 but the index table has 2 entries");
    img.width = 2; img.height = 1; img.channels = 3; img.px = rgb;
    map.rgb = map_rgb; map.rgb_attr = map_attr; map.nrgb = 2;
    diag_init(&err);
    assert_int_equal(pds_image_to_pixels(&img, &map, &px, "i.deck", at(2, 5), &err), 0);
    assert_int_equal(px.cells[0], 21);
    assert_int_equal(px.cells[1], 20);
    map.nrgb = 1;
    assert_int_equal(pds_image_to_pixels(&img, &map, &px, "i.deck", at(2, 5), &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "i.deck:2:5: error: pixel (0, 0) has colour #ff0000, which the colour map does not list");
    mem_free(px.cells);
}

/* ---- out of memory ----------------------------------------------------------- */

/* Builds a definition of each kind; -1 when a builder ran out of memory. */
static int build_kind(pds_def *d, int kind)
{
    double tri[6] = { 0.1, 0.1, 0.9, 0.2, 0.3, 0.8 }, sq[8] = { 0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8 };
    int32_t cells[16] = { 1, 1, 2, 2, 1, 1, 2, 2, 3, 3, 3, 4, 3, 3, 5, 6 }, attrs[2] = { 1, 2 };
    size_t k[3];
    long r;
    pds_def_init(d, (pds_kind)kind, L0);
    switch (kind) {
    case PDS_CPG:
        if ((r = pds_cpg_polygon(d, tri, 3, 1, L0)) < 0) return -1;
        k[0] = (size_t)r;
        if ((r = pds_cpg_ellipse(d, 0.5, 0.5, 0.2, 0.1, 2, L0)) < 0) return -1;
        k[1] = (size_t)r;
        if ((r = pds_cpg_rect(d, 0.1, 0.1, 0.3, 0.3, 3, L0)) < 0) return -1;
        k[2] = (size_t)r;
        pds_cpg_rotate(d, k[2], 10);
        if ((r = pds_cpg_op_node(d, PDS_CPG_UNION, k, 3, PDS_INHERIT, L0)) < 0) return -1;
        return 0;
    case PDS_PIXELS:
        return pds_pixels_set(&d->pixels, 4, 4, cells, 16);
    case PDS_TILING:
        d->tiling.shape = PDS_TILE_HEX;
        d->tiling.mortar = 0.01;
        return pds_tiling_attrs(d, attrs, 2);
    case PDS_MOSAIC:
        if (pds_mosaic_seed(d, 0.2, 0.3, 1) < 0 || pds_mosaic_seed(d, 0.7, 0.6, 2) < 0) return -1;
        d->mosaic.mortar = 0.01;
        return 0;
    case PDS_QUADTREE:
        d->quad.from_pixels = 1;
        return pds_pixels_set(&d->quad.pixels, 4, 4, cells, 16);
    default:
        if (pds_curve_add(d, 1, sq, 4, 1, L0) < 0 || pds_curve_add(d, 0, tri, 3, 2, L0) < 0) return -1;
        return 0;
    }
}

static void test_pds_oom_sweep(void **state)
{
    int kind, mi;
    (void)state;
    for (kind = 0; kind < PDS_KIND_COUNT; kind++)
        for (mi = 0; mi < NMODES; mi++) {
            long n;
            for (n = 0;; n++) {
                pds_def d;
                void *p = NULL;
                diag err;
                int rc, built;
                diag_init(&err);
                mem_fail_after(n);
                built = build_kind(&d, kind);
                rc = built ? -1 : modes[mi]->compile(&d, "oom.deck", &p, &err);
                mem_fail_after(-1);
                if (rc == 0) {
                    assert_int_equal(modes[mi]->locate(p, 0.5, 0.5), modes[mi]->locate(p, 0.5, 0.5));
                    modes[mi]->free(p);
                    pds_def_free(&d);
                    break;
                }
                if (rc > 0)
                    assert_int_equal(rc, DIAG_IO);
                assert_null(p);
                pds_def_free(&d);
                assert_true(n < 10000);
            }
        }
    /* A CPG holding a nested tiling: the nested compile fails cleanly too. */
    for (mi = 0; mi < NMODES; mi++) {
        pds_def sub;
        long n;
        assert_int_equal(build_kind(&sub, PDS_TILING), 0);
        for (n = 0;; n++) {
            pds_def d;
            void *p = NULL;
            diag err;
            int rc = -1;
            diag_init(&err);
            mem_fail_after(n);
            pds_def_init(&d, PDS_CPG, L0);
            if (pds_cpg_nested(&d, &sub, L0) >= 0)
                rc = modes[mi]->compile(&d, "oom.deck", &p, &err);
            mem_fail_after(-1);
            if (rc == 0) {
                assert_int_equal(modes[mi]->locate(p, 0.5, 0.5), modes[mi]->locate(p, 0.5, 0.5));
                modes[mi]->free(p);
                pds_def_free(&d);
                break;
            }
            if (rc > 0)
                assert_int_equal(rc, DIAG_IO);
            assert_null(p);
            pds_def_free(&d);
        }
        pds_def_free(&sub);
    }
}

/* pds_image_to_pixels under failing allocations: a clean DIAG_IO and the
 * pixel array left as it was. */
static void test_pds_image_oom_sweep(void **state)
{
    uint8_t rgb[6] = { 255, 0, 0, 0, 0, 255 }, map_rgb[6] = { 0, 0, 255, 255, 0, 0 };
    int32_t map_attr[2] = { 20, 21 };
    image img;
    pds_image_map map;
    long n;
    (void)state;
    memset(&map, 0, sizeof map);
    img.width = 2; img.height = 1; img.channels = 3; img.px = rgb;
    map.rgb = map_rgb; map.rgb_attr = map_attr; map.nrgb = 2;
    for (n = 0;; n++) {
        pds_pixels px;
        diag err;
        int rc;
        memset(&px, 0, sizeof px);
        diag_init(&err);
        mem_fail_after(n);
        rc = pds_image_to_pixels(&img, &map, &px, "i.deck", L0, &err);
        mem_fail_after(-1);
        if (rc == 0) {
            assert_int_equal(px.cells[0], 21);
            mem_free(px.cells);
            break;
        }
        assert_int_equal(rc, DIAG_IO);
        assert_null(px.cells);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pds_cpg_matches_reference),
        cmocka_unit_test(test_pds_cpg_priority_rules),
        cmocka_unit_test(test_pds_cpg_boundaries_closed),
        cmocka_unit_test(test_pds_cpg_visits_grow_logarithmically),
        cmocka_unit_test(test_pds_cpg_visits_independent_of_order),
        cmocka_unit_test(test_pds_cpg_diff_and_chains_flat),
        cmocka_unit_test(test_pds_cpg_index_matches_brute_force),
        cmocka_unit_test(test_pds_cpg_nested_matches_reference),
        cmocka_unit_test(test_pds_cpg_nested_errors),
        cmocka_unit_test(test_pds_pixels_match_reference),
        cmocka_unit_test(test_pds_pixels_orientation_and_edges),
        cmocka_unit_test(test_pds_quadtree_matches_pixel_array),
        cmocka_unit_test(test_pds_quadtree_explicit_order),
        cmocka_unit_test(test_pds_quadtree_explicit_matches_reference),
        cmocka_unit_test(test_pds_tiling_boundaries),
        cmocka_unit_test(test_pds_tiling_matches_reference),
        cmocka_unit_test(test_pds_tiling_hash_rule_agrees_across_modes),
        cmocka_unit_test(test_pds_mosaic_matches_brute_force),
        cmocka_unit_test(test_pds_curves_match_reference),
        cmocka_unit_test(test_pds_curves_bspline_circle),
        cmocka_unit_test(test_pds_curve_flatten_within_tolerance),
        cmocka_unit_test(test_pds_curve_simple_matches_all_pairs),
        cmocka_unit_test(test_pds_curves_boundary_closed),
        cmocka_unit_test(test_pds_strip_membership_matches_boxes),
        cmocka_unit_test(test_pds_strip_intersection_brute_force),
        cmocka_unit_test(test_pds_q16_counts_no_overflow),
        cmocka_unit_test(test_pds_errors_exact_text),
        cmocka_unit_test(test_pds_image_to_pixels),
        cmocka_unit_test(test_pds_oom_sweep),
        cmocka_unit_test(test_pds_image_oom_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
