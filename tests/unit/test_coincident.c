/* test_coincident — coincident faces and equal solids under random rigid
 * motions, in every numeric mode, against an independent classification.
 *
 * Each placement is a deck whose solids share faces or are the same solid
 * built two ways, moved by a random rotation and a translation such as 1/3
 * that no mode represents exactly:
 *   HOLE    a block minus a cylinder whose caps lie on the block's faces;
 *   NESTED  (block minus pocket) minus a cylinder from the pocket floor to
 *           the bottom face;
 *   UNION   three blocks sharing faces, rays also starting inside;
 *   SAME    A - A' for a sphere, a cylinder and a cone, A' being A through
 *           another but equivalent transform (empty solids);
 *   COAXIAL a cylinder minus a longer coaxial cylinder of the same radius
 *           (empty: the sides coincide but are computed in two frames, so
 *           only the regularised span merge makes them one boundary).
 * The truth is computed here in the object frame: analytic spans of
 * axis-aligned boxes, z-aligned cylinders and cones and spheres, boundaries
 * at equal parameters taken as one, membership decided at the midpoints
 * between boundaries. A ray whose first boundary lies within a small window
 * of another (a rim or an edge) is ambiguous and not counted. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "tracer_test.h"

#define CO_PLACEMENTS 1000
#define CO_RAYS 8
#define CO_MAXP 6
#define CO_WINDOW 1e-3          /* deck units: rims and edges nearer are ambiguous */
/* Coincident sides computed in two frames differ by the mode's error over
 * |cos| of the incidence; the regularised merge absorbs the error bound at
 * up to this obliquity (docs/numerics.md). */
#define CO_COAX_COS 0.25

enum { CO_BOX, CO_ZCYL, CO_SPHERE, CO_ZCONE };
enum { CO_HOLE, CO_NESTED, CO_UNION, CO_SAME, CO_COAX, CO_KINDS };
static const char *const co_kind_name[CO_KINDS] = {"hole", "nested", "union", "same", "coaxial"};

/* A primitive in the object frame of the placement. */
typedef struct co_prim {
    int kind;
    double lo[3], hi[3];        /* box bounds; cylinder/cone: z range in [2] */
    double c[3], r, r1;         /* centre (cylinder/cone: axis x, y), radius; cone top radius */
    char name[8];
} co_prim;

typedef struct co_case {
    int kind, np;
    co_prim p[CO_MAXP];
    char deck[4096];
} co_case;

static int co_in_prim(const co_prim *p, const double *q)
{
    double dx = q[0] - p->c[0], dy = q[1] - p->c[1], dz = q[2] - p->c[2], rr;
    switch (p->kind) {
    case CO_BOX:
        return q[0] > p->lo[0] && q[0] < p->hi[0] && q[1] > p->lo[1] && q[1] < p->hi[1]
            && q[2] > p->lo[2] && q[2] < p->hi[2];
    case CO_SPHERE:
        return dx * dx + dy * dy + dz * dz < p->r * p->r;
    default:
        if (!(q[2] > p->lo[2] && q[2] < p->hi[2]))
            return 0;
        rr = p->kind == CO_ZCYL ? p->r
                                : p->r + (p->r1 - p->r) * (q[2] - p->lo[2]) / (p->hi[2] - p->lo[2]);
        return dx * dx + dy * dy < rr * rr;
    }
}

/* Roots of a t^2 + 2 b t + c = 0 appended to t (at most 2). */
static int co_roots(double a, double b, double c, double *t)
{
    double disc = b * b - a * c, h;
    if (a == 0) {
        if (b == 0)
            return 0;
        t[0] = -c / (2 * b);
        return 1;
    }
    if (disc < 0)
        return 0;
    h = sqrt(disc);
    t[0] = (-b - h) / a;
    t[1] = (-b + h) / a;
    return 2;
}

/* |cos| of the angle between unit d and the gradient g. */
static double co_cos(const double *g, const double *d)
{
    double l = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    return l > 0 ? fabs(g[0] * d[0] + g[1] * d[1] + g[2] * d[2]) / l : 0;
}

/* Every parameter where the ray o + t d (d unit) crosses a bounding surface
 * of p (a superset of the span ends is enough: membership decides), with
 * |cos| of the incidence angle there in cs. */
static int co_crossings(const co_prim *p, const double *o, const double *d, double *t, double *cs)
{
    int n = 0, i, m, k;
    double ox = o[0] - p->c[0], oy = o[1] - p->c[1], oz = o[2] - p->c[2], kk = 0, r0 = 0;
    if (p->kind == CO_BOX) {
        for (i = 0; i < 3; i++)
            if (d[i] != 0) {
                cs[n] = cs[n + 1] = fabs(d[i]);
                t[n++] = (p->lo[i] - o[i]) / d[i];
                t[n++] = (p->hi[i] - o[i]) / d[i];
            }
        return n;
    }
    if (p->kind == CO_SPHERE) {
        m = co_roots(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], ox * d[0] + oy * d[1] + oz * d[2],
                     ox * ox + oy * oy + oz * oz - p->r * p->r, t);
    } else {
        if (p->kind == CO_ZCYL) {
            m = co_roots(d[0] * d[0] + d[1] * d[1], ox * d[0] + oy * d[1], ox * ox + oy * oy - p->r * p->r, t);
        } else {
            /* radius R(z) = r + k (z - lo): x^2 + y^2 = R^2 */
            double kd;
            kk = (p->r1 - p->r) / (p->hi[2] - p->lo[2]);
            r0 = p->r + kk * (o[2] - p->lo[2]);
            kd = kk * d[2];
            m = co_roots(d[0] * d[0] + d[1] * d[1] - kd * kd, ox * d[0] + oy * d[1] - r0 * kd,
                         ox * ox + oy * oy - r0 * r0, t);
        }
    }
    for (k = 0; k < m; k++) {
        double g[3];
        g[0] = ox + t[k] * d[0];
        g[1] = oy + t[k] * d[1];
        g[2] = p->kind == CO_SPHERE ? oz + t[k] * d[2] : -kk * (r0 + kk * t[k] * d[2]);
        cs[k] = co_cos(g, d);
    }
    n = m;
    if (p->kind != CO_SPHERE && d[2] != 0) {
        cs[n] = cs[n + 1] = fabs(d[2]);
        t[n++] = (p->lo[2] - o[2]) / d[2];
        t[n++] = (p->hi[2] - o[2]) / d[2];
    }
    return n;
}

/* Membership of the solid of the case at object point q. */
static int co_in(const co_case *c, const double *q)
{
    int in[CO_MAXP], i;
    for (i = 0; i < c->np; i++)
        in[i] = co_in_prim(&c->p[i], q);
    switch (c->kind) {
    case CO_HOLE:   return in[0] && !in[1];
    case CO_NESTED: return in[0] && !in[1] && !in[2];
    case CO_UNION:  return in[0] || in[1] || in[2];
    case CO_COAX:   return in[0] && !in[1];
    default:        return (in[0] && !in[1]) || (in[2] && !in[3]) || (in[4] && !in[5]);
    }
}

static int co_dcmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The first change of membership along o + t d for t in (0, 40]: 1 and *t
 * and the primitives with a boundary exactly there (bit mask), 0 for none,
 * -1 when ambiguous (another boundary within CO_WINDOW of it). */
static int co_truth(const co_case *c, const double *o, const double *d, double *t, unsigned *mask)
{
    double b[CO_MAXP * 6 + 2], q[3];
    int n = 0, i, k, j, prev_in;
    for (i = 0; i < c->np; i++) {
        double tt[6], cs[6];
        int m = co_crossings(&c->p[i], o, d, tt, cs);
        for (k = 0; k < m; k++)
            if (tt[k] > 0 && tt[k] < 40) {
                /* within 3 degrees of grazing a surface the parameter is
                 * ill-conditioned (docs/numerics.md): ambiguous */
                for (j = 0; j < 3; j++)
                    q[j] = o[j] + tt[k] * d[j];
                if (cs[k] < (c->kind == CO_COAX ? CO_COAX_COS : 0.05))
                    return -1;
                b[n++] = tt[k];
            }
    }
    qsort(b, (size_t)n, sizeof *b, co_dcmp);
    for (i = 0, j = 0; i < n; i++)      /* equal parameters: one boundary */
        if (!j || b[i] != b[j - 1])
            b[j++] = b[i];
    n = j;
    b[n] = 41;
    for (k = 0; k < 3; k++)
        q[k] = o[k] + (n ? b[0] / 2 : 1) * d[k];
    prev_in = co_in(c, q);
    for (i = 0; i < n; i++) {
        int now;
        for (k = 0; k < 3; k++)
            q[k] = o[k] + (b[i] + b[i + 1]) / 2 * d[k];
        now = co_in(c, q);
        if (now == prev_in)
            continue;
        if (b[i] < CO_WINDOW || b[i + 1] - b[i] < CO_WINDOW || (i && b[i] - b[i - 1] < CO_WINDOW))
            return -1;
        *t = b[i];
        *mask = 0;
        for (j = 0; j < c->np; j++) {
            double tt[6], cs[6];
            int m = co_crossings(&c->p[j], o, d, tt, cs);
            for (k = 0; k < m; k++)
                if (tt[k] == b[i])
                    *mask |= 1u << j;
        }
        return 1;
    }
    /* membership never changes: also ambiguous when a boundary pair is
     * nearly touching (a grazing sliver) */
    for (i = 1; i < n; i++)
        if (b[i] - b[i - 1] < CO_WINDOW)
            return -1;
    return 0;
}

static double co_u(uint64_t *s, double lo, double hi) { return test_uniform(s, lo, hi); }

static void co_box(co_prim *p, const char *name, double x0, double y0, double z0, double x1, double y1, double z1)
{
    memset(p, 0, sizeof *p);
    p->kind = CO_BOX;
    p->lo[0] = x0; p->lo[1] = y0; p->lo[2] = z0;
    p->hi[0] = x1; p->hi[1] = y1; p->hi[2] = z1;
    snprintf(p->name, sizeof p->name, "%s", name);
}

static void co_zround(co_prim *p, int kind, const char *name, double cx, double cy, double z0, double z1,
                      double r, double r1)
{
    memset(p, 0, sizeof *p);
    p->kind = kind;
    p->c[0] = cx; p->c[1] = cy;
    p->lo[2] = z0; p->hi[2] = z1;
    p->r = r;
    p->r1 = r1;
    snprintf(p->name, sizeof p->name, "%s", name);
}

/* Appends the placement's rigid motion: a random rotation, then a
 * translation by thirds and sevenths. */
static void co_motion(uint64_t *s, char *buf, size_t len)
{
    snprintf(buf, len, "ROTATE AXIS %.17g %.17g %.17g %.17g TRANSLATE %.17g %.17g %.17g",
             co_u(s, -1, 1), co_u(s, -1, 1), co_u(s, 0.05, 1), co_u(s, 0, 360),
             (double)((int)(test_rand(s) % 13) - 6) / 3.0, (double)((int)(test_rand(s) % 13) - 6) / 7.0,
             (double)((int)(test_rand(s) % 13) - 6) / 3.0 + 1.0 / 7.0);
}

/* Rewrites c->deck so that no record is longer than 72 columns (the rest
 * of a card holds sequence numbers): long statements are continued with
 * " -" at a space. */
static void co_wrap(co_case *c)
{
    char out[sizeof c->deck], *w = out;
    const char *r = c->deck;
    int col = 0;
    while (*r) {
        const char *e = r;
        while (*e && *e != ' ' && *e != '\n')
            e++;
        if (col && col + (int)(e - r) > 66) {
            w += sprintf(w, " -\n ");
            col = 1;
        }
        memcpy(w, r, (size_t)(e - r));
        w += e - r;
        col += (int)(e - r);
        if (*e == '\n')
            col = 0;
        if (*e)
            *w++ = *e++, col += col ? 1 : 0;
        r = e;
    }
    *w = 0;
    strcpy(c->deck, out);
}

static void co_build(uint64_t *s, int kind, co_case *c)
{
    char mo[256], *p = c->deck;
    double a = co_u(s, 1.5, 3), b = co_u(s, 1.5, 3), h = co_u(s, 0.3, 1.5);
    memset(c, 0, sizeof *c);
    c->kind = kind;
    co_motion(s, mo, sizeof mo);
    p += sprintf(p, "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n");
    if (kind == CO_HOLE) {
        double r = co_u(s, 0.15, 0.4 * (a < b ? a : b)), cx = co_u(s, r + 0.1, a - r - 0.1),
               cy = co_u(s, r + 0.1, b - r - 0.1);
        c->np = 2;
        co_box(&c->p[0], "P", 0, 0, 0, a, b, h);
        co_zround(&c->p[1], CO_ZCYL, "C", cx, cy, 0, h, r, r);
        sprintf(p, "BLOCK P %.17g %.17g %.17g\nCYLINDER C %.17g %.17g TRANSLATE %.17g %.17g 0\n"
                   "DIFF H P C\nOBJECT H %s\n", a, b, h, r, h, cx, cy, mo);
    } else if (kind == CO_NESTED) {
        double qx0 = co_u(s, 0.1, 0.4 * a), qx1 = co_u(s, 0.6 * a, a - 0.1), qy0 = co_u(s, 0.1, 0.4 * b),
               qy1 = co_u(s, 0.6 * b, b - 0.1), dep = co_u(s, 0.2, 0.7) * h, fl = h - dep;
        double w = qx1 - qx0 < qy1 - qy0 ? qx1 - qx0 : qy1 - qy0, r = co_u(s, 0.1, 0.4) * w;
        double cx = co_u(s, qx0 + r + 0.05, qx1 - r - 0.05), cy = co_u(s, qy0 + r + 0.05, qy1 - r - 0.05);
        c->np = 3;
        co_box(&c->p[0], "P", 0, 0, 0, a, b, h);
        co_box(&c->p[1], "Q", qx0, qy0, fl, qx1, qy1, h);
        co_zround(&c->p[2], CO_ZCYL, "C", cx, cy, 0, fl, r, r);
        sprintf(p, "BLOCK P %.17g %.17g %.17g\nBLOCK Q %.17g %.17g %.17g TRANSLATE %.17g %.17g %.17g\n"
                   "CYLINDER C %.17g %.17g TRANSLATE %.17g %.17g 0\n"
                   "DIFF N1 P Q\nDIFF N2 N1 C\nOBJECT N2 %s\n",
                a, b, h, qx1 - qx0, qy1 - qy0, dep, qx0, qy0, fl, r, fl, cx, cy, mo);
    } else if (kind == CO_UNION) {
        double a2 = co_u(s, 0.5, 2), h2 = co_u(s, 0.3, 1);
        c->np = 3;
        co_box(&c->p[0], "A", 0, 0, 0, a, b, h);
        co_box(&c->p[1], "B", a, 0, 0, a + a2, b, h);
        co_box(&c->p[2], "T", 0, 0, h, a, b, h + h2);
        sprintf(p, "BLOCK A %.17g %.17g %.17g\nBLOCK B %.17g %.17g %.17g TRANSLATE %.17g 0 0\n"
                   "BLOCK T %.17g %.17g %.17g TRANSLATE 0 0 %.17g\nUNION U A B T\nOBJECT U %s\n",
                a, b, h, a2, b, h, a, a, b, h2, h, mo);
    } else if (kind == CO_COAX) {
        double r = co_u(s, 0.3, 1), e = co_u(s, 0.05, 0.5);
        c->np = 2;
        co_zround(&c->p[0], CO_ZCYL, "E", 0, 0, 0, h, r, r);
        co_zround(&c->p[1], CO_ZCYL, "F", 0, 0, -e, h + e, r, r);
        sprintf(p, "CYLINDER E %.17g %.17g\n"
                   "CYLINDER F %.17g %.17g ROTATE Z %.17g TRANSLATE 0 0 %.17g\n"
                   "DIFF D E F\nOBJECT D %s\n",
                r, h, r, h + 2 * e, co_u(s, 0, 360), -e, mo);
    } else {
        /* sphere radius R at (0,0,0); A' scaled from R/k and turned about its
         * centre. Cylinder at x = 4: E' turned over (z -> h - z) and about z.
         * Cone at x = -4: K' turned about z. */
        double R = co_u(s, 0.5, 1.5), k = co_u(s, 0.5, 2), r = co_u(s, 0.3, 1), r0 = co_u(s, 0.2, 1),
               r1 = co_u(s, 0, 1);
        c->np = 6;
        co_zround(&c->p[0], CO_SPHERE, "A", 0, 0, 0, 0, R, R);
        c->p[1] = c->p[0];
        strcpy(c->p[1].name, "A2");
        co_zround(&c->p[2], CO_ZCYL, "E", 4, 0, 0, h, r, r);
        c->p[3] = c->p[2];
        strcpy(c->p[3].name, "E2");
        co_zround(&c->p[4], CO_ZCONE, "K", -4, 0, 0, h, r0, r1);
        c->p[5] = c->p[4];
        strcpy(c->p[5].name, "K2");
        sprintf(p, "SPHERE A %.17g ROTATE AXIS %.17g %.17g %.17g %.17g\n"
                   "SPHERE A2 %.17g SCALE %.17g ROTATE AXIS %.17g %.17g %.17g %.17g\n"
                   "CYLINDER E %.17g %.17g TRANSLATE 4 0 0\n"
                   "CYLINDER E2 %.17g %.17g ROTATE X 180 ROTATE Z %.17g TRANSLATE 4 0 %.17g\n"
                   "CONE K %.17g %.17g %.17g TRANSLATE -4 0 0\n"
                   "CONE K2 %.17g %.17g %.17g ROTATE Z %.17g TRANSLATE -4 0 0\n"
                   "DIFF D1 A A2\nDIFF D2 E E2\nDIFF D3 K K2\nUNION DD D1 D2 D3\nOBJECT DD %s\n",
                R, co_u(s, -1, 1), co_u(s, -1, 1), co_u(s, 0.1, 1), co_u(s, 0, 360), R / k, k, co_u(s, -1, 1),
                co_u(s, -1, 1), co_u(s, 0.1, 1), co_u(s, 0, 360), r, h, r, h, co_u(s, 0, 360), h, r0, r1, h,
                r0, r1, h, co_u(s, 0, 360), mo);
    }
}

/* An object-frame ray aimed at the case's coincident features. */
static void co_ray(uint64_t *s, const co_case *c, int j, double *o, double *d)
{
    double tgt[3], u[3], L = co_u(s, 3, 8), th, ph;
    const co_prim *p = &c->p[c->kind == CO_NESTED ? 2 : c->kind == CO_SAME ? 2 * (j % 3) : 1];
    int i, below = j % 4 == 3;
    if (c->kind == CO_UNION && j % 2 == 0) {
        /* from a point inside A, in any direction */
        const co_prim *a = &c->p[0];
        for (i = 0; i < 3; i++)
            o[i] = co_u(s, a->lo[i] + 0.05, a->hi[i] - 0.05);
        tt_random_dir(s, d);
        return;
    }
    if (c->kind == CO_UNION) {
        /* at the shared faces' edges and across them */
        const co_prim *a = &c->p[0];
        tgt[0] = a->hi[0] + co_u(s, -0.3, 0.3);
        tgt[1] = co_u(s, 0, a->hi[1]);
        tgt[2] = a->hi[2] + co_u(s, -0.3, 0.3);
    } else {
        double rr = (p->kind == CO_ZCONE ? (p->r > p->r1 ? p->r : p->r1) : p->r) * sqrt(co_u(s, 0, 1));
        double a = co_u(s, 0, 6.283185307179586);
        tgt[0] = p->c[0] + 0.98 * rr * cos(a);
        tgt[1] = p->c[1] + 0.98 * rr * sin(a);
        tgt[2] = p->kind == CO_SPHERE ? co_u(s, -0.5, 0.5) * p->r : below ? p->lo[2] : p->hi[2];
        if (j % 5 == 4 && c->kind != CO_SAME) {      /* on the face around the hole */
            tgt[0] = c->p[0].lo[0] + co_u(s, 0, 1) * (c->p[0].hi[0] - c->p[0].lo[0]);
            tgt[1] = c->p[0].lo[1] + co_u(s, 0, 1) * (c->p[0].hi[1] - c->p[0].lo[1]);
        }
    }
    th = co_u(s, 0, 65) * 3.141592653589793 / 180;
    ph = co_u(s, 0, 6.283185307179586);
    u[0] = sin(th) * cos(ph);
    u[1] = sin(th) * sin(ph);
    u[2] = below ? -cos(th) : cos(th);
    for (i = 0; i < 3; i++) {
        o[i] = tgt[i] + L * u[i];
        d[i] = -u[i];
    }
}

/* World ray from an object-frame one through the motion m (rigid). */
static void co_to_world(const double *m, const double *o, const double *d, double *ow, double *dw)
{
    int i;
    for (i = 0; i < 3; i++) {
        ow[i] = m[4 * i] * o[0] + m[4 * i + 1] * o[1] + m[4 * i + 2] * o[2] + m[4 * i + 3];
        dw[i] = m[4 * i] * d[0] + m[4 * i + 1] * d[1] + m[4 * i + 2] * d[2];
    }
}

static void test_coincident_random_placements(void **state)
{
    uint64_t s = test_seed("test_coincident_random_placements");
    long wrong[TT_MODES][CO_KINDS], counted[TT_MODES][CO_KINDS], amb = 0;
    int n, kind, m, j;
    (void)state;
    memset(wrong, 0, sizeof wrong);
    memset(counted, 0, sizeof counted);
    for (n = 0; n < CO_PLACEMENTS; n++)
        for (kind = 0; kind < CO_KINDS; kind++) {
            co_case c;
            scene *sc;
            double o[CO_RAYS][3], d[CO_RAYS][3], tt[CO_RAYS], mo[12];
            unsigned mask[CO_RAYS];
            int truth[CO_RAYS], map[CO_MAXP], i, ref;
            co_build(&s, kind, &c);
            co_wrap(&c);
            sc = tt_parse(c.deck);
            assert_non_null(sc);
            for (i = 0; i < c.np; i++)
                assert_true((map[i] = tt_find_prim(sc, c.p[i].name)) >= 0);
            /* the motion: the world_from_object of a primitive placed at the
             * object origin without a transform of its own */
            ref = map[0];
            if (kind == CO_SAME) {
                /* E is only translated by (4,0,0): undo it */
                memcpy(mo, sc->prims[map[2]].world_from_object, sizeof mo);
                for (i = 0; i < 3; i++)
                    mo[4 * i + 3] -= 4 * mo[4 * i];
            } else {
                memcpy(mo, sc->prims[ref].world_from_object, sizeof mo);
            }
            for (j = 0; j < CO_RAYS; j++) {
                co_ray(&s, &c, j, o[j], d[j]);
                truth[j] = co_truth(&c, o[j], d[j], &tt[j], &mask[j]);
                if (truth[j] < 0)
                    amb++;
            }
            for (m = 0; m < TT_MODES; m++) {
                const probe_ops *ops = tt_mode(m);
                void *cs;
                diag err;
                diag_init(&err);
                assert_int_equal(ops->compile(sc, &cs, &err), 0);
                for (j = 0; j < CO_RAYS; j++) {
                    double ow[3], dw[3];
                    probe_hit h;
                    int got, ok;
                    if (truth[j] < 0)
                        continue;
                    co_to_world(mo, o[j], d[j], ow, dw);
                    got = ops->hit(cs, ow, dw, &h) && h.t < 40;
                    ok = got == truth[j];
                    if (ok && got) {
                        int pi;
                        for (pi = 0; pi < c.np && map[pi] != h.prim; pi++)
                            ;
                        ok = pi < c.np && (mask[j] >> pi & 1) && fabs(h.t - tt[j]) < 1e-2 * (1 + tt[j]);
                    }
                    counted[m][kind]++;
                    if (!ok && wrong[m][kind]++ < 2)
                        printf("# %s %s placement %d ray %d: truth %s t=%.6f, mode %s t=%.6f prim %s\n%s",
                               ops->name, co_kind_name[kind], n, j, truth[j] ? "hit" : "miss",
                               truth[j] ? tt[j] : 0.0, got ? "hit" : "miss", got ? h.t : 0.0,
                               got ? sc->prims[h.prim].shape->name : "-", c.deck);
                }
                ops->free(cs);
            }
            scene_free(sc);
        }
    for (m = 0; m < TT_MODES; m++) {
        long tw = 0;
        printf("# %s:", tt_mode(m)->name);
        for (kind = 0; kind < CO_KINDS; kind++) {
            printf(" %s %ld/%ld", co_kind_name[kind], wrong[m][kind], counted[m][kind]);
            tw += wrong[m][kind];
            assert_true(counted[m][kind] > CO_PLACEMENTS * CO_RAYS / 2);
        }
        printf(" wrong/counted rays over %d placements each\n", CO_PLACEMENTS);
        (void)tw;
    }
    printf("# %ld ambiguous rays not counted\n", amb);
    /* q16 coaxial sides: a direction rounded to 2^-16 errs by up to about
     * 1e-3 normalised units over a probe ray's length, over |cos| more than
     * the bound the merge absorbs; measured, and held under 0.2% */
    for (m = 0; m < TT_MODES; m++)
        for (kind = 0; kind < CO_KINDS; kind++)
            if (m == 0 && kind == CO_COAX)
                assert_true(wrong[m][kind] * 500 <= counted[m][kind]);
            else
                assert_int_equal(wrong[m][kind], 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_coincident_random_placements),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
