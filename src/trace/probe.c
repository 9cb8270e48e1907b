/* probe — geometry queries in deck units for one numeric mode (probe.h). */
#include "trace/probe.h"
#include "util/dmath.h"
#include "trace/optics.h"
#include "trace/cscene.h"
#include "util/mem.h"
#include <math.h>
#include <string.h>

typedef struct probe_cs {
    cscene *cs;
    arena ar;
    int buffered;            /* rays from the eye and to the lights use the
                                scene's light buffers (probe buffers) */
} probe_cs;

static int probe_compile(const scene *sc, void **out, diag *err)
{
    probe_cs *p = mem_calloc(1, sizeof *p);
    int st;
    if (!p)
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    if ((st = NS(cscene_compile)(sc, &p->cs, err)) != 0) {
        mem_free(p);
        return st;
    }
    if (arena_init(&p->ar, NS(csg_arena_bytes)(&p->cs->tree))) {
        NS(cscene_free)(p->cs);
        mem_free(p);
        return diag_at(err, DIAG_IO, "", 0, 0, "out of memory");
    }
    *out = p;
    return 0;
}

static void probe_free(void *v)
{
    probe_cs *p = v;
    if (!p)
        return;
    arena_free(&p->ar);
    NS(cscene_free)(p->cs);
    mem_free(p);
}

/* Deck ray -> normalised-world ray in num; -1 for a zero direction. */
static int probe_ray(const cscene *cs, const double *o, const double *d, prim_ray *r)
{
    double w[3], u[3];
    vec3 dir;
    NS(cscene_to_world)(cs, o, w);
    if (dmath_unit3(d, u) || vec3_normalize(vec3_from_d(u), &dir, NULL))
        return -1;
    prim_ray_set(r, vec3_from_d(w), dir, -1, 0);
    return 0;
}

static int probe_prim_span(const void *v, int pi, const double *o, const double *d,
                           double *t, int *face)
{
    const probe_cs *p = v;
    const cscene *cs = p->cs;
    prim_ray r;
    span s;
    const prim *pr;
    const csg_inst *in;
    if (pi < 0 || (size_t)pi >= cs->nprims || probe_ray(cs, o, d, &r))
        return 0;
    pr = cscene_prim_of(cs, pi, &in);
    if (in && in->turn) {       /* a turned instance's: its master's */
        double od[3], dd[3], o2[3], d2[3];
        int i;
        vec3_to_d(r.o, od);
        vec3_to_d(r.d, dd);
        dmath_m3_mul_v(in->turn->q, od, o2);
        dmath_m3_mul_v(in->turn->q, dd, d2);
        for (i = 0; i < 3; i++)
            o2[i] += in->shift_d[i];
        prim_ray_set(&r, vec3_from_d(o2), vec3_from_d(d2), -1, 0);
    } else if (in) {              /* an instance's: its master's, moved */
        prim_ray_set(&r, vec3_add(r.o, in->shift), r.d, -1, 0);
    }
    if (!NS(prim_intersect)(pr, &r, num_neg(num_from_i(GEOM_TBIG)), num_from_i(GEOM_TMAX), &s))
        return 0;
    t[0] = num_to_d(s.a.t) / cs->nm.scale;
    t[1] = num_to_d(s.b.t) / cs->nm.scale;
    face[0] = s.a.face;
    face[1] = s.b.face;
    return 1;
}

/* Nearest hit of r; fills h (deck units) and the num hit point. lb: as
 * for csg_intersect. The probe owns one arena, so one compiled probe must
 * not be queried from two threads at once. */
static int probe_trace(const probe_cs *pc, const prim_ray *r, const lightbuf *lb, probe_hit *h, vec3 *pn)
{
    const cscene *cs = pc->cs;
    arena *ar = (arena *)&pc->ar;
    geom_stats gs;
    csg_hit ch;
    cscene_map_memo mm = {0};
    double dd[3], dn;
    int i;
    memset(&gs, 0, sizeof gs);
    if (!(lb && lb->start ? NS(csg_intersect_from)(&cs->tree, lb, r, num_from_i(GEOM_TMAX), ar, &gs, &ch)
                          : NS(csg_intersect)(&cs->tree, r, num_from_i(GEOM_TMAX), ar, &gs, &ch)))
        return 0;
    *pn = vec3_madd(r->o, ch.t, r->d);
    NS(cscene_surface)(cs, ch.prim, ch.face, *pn, 1, &mm, &h->sf);
    h->t = num_to_d(ch.t) / cs->nm.scale;
    h->prim = ch.prim;
    h->face = ch.face;
    h->entering = ch.entering;
    vec3_to_d(r->d, dd);
    dn = dd[0] * h->sf.n[0] + dd[1] * h->sf.n[1] + dd[2] * h->sf.n[2];
    for (i = 0; i < 3; i++) {
        h->p[i] = (h->sf.p[i] - cs->nm.off[i]) / cs->nm.scale;
        /* entering: the outward normal faces the ray (dn < 0) */
        h->n_solid[i] = (ch.entering ? dn > 0 : dn < 0) ? -h->sf.n[i] : h->sf.n[i];
    }
    return 1;
}

static int probe_hit_fn(const void *v, const double *o, const double *d, probe_hit *h)
{
    const probe_cs *p = v;
    prim_ray r;
    vec3 pn;
    if (probe_ray(p->cs, o, d, &r))
        return 0;
    return probe_trace(p, &r, p->buffered ? &p->cs->eyebuf : NULL, h, &pn);
}

/* The ray from the nearest hit along d from o, as shading spawns it along
 * d2 (h1 that hit): 0, or -1 when there is none. */
static int probe_spawn(const probe_cs *p, const double *o, const double *d, const double *d2, probe_hit *h1,
                       prim_ray *r2)
{
    prim_ray r;
    vec3 pn, dir;
    double u[3];
    if (probe_ray(p->cs, o, d, &r) || !probe_trace(p, &r, NULL, h1, &pn) || dmath_unit3(d2, u)
        || vec3_normalize(vec3_from_d(u), &dir, NULL))
        return -1;
    prim_ray_set(r2, pn, dir, h1->prim, u[0] * h1->sf.n[0] + u[1] * h1->sf.n[1] + u[2] * h1->sf.n[2] < 0);
    return 0;
}

static int probe_respawn(const void *v, const double *o, const double *d, const double *d2,
                         probe_hit *h1, probe_hit *h2)
{
    const probe_cs *p = v;
    prim_ray r2;
    vec3 pn;
    if (probe_spawn(p, o, d, d2, h1, &r2))
        return -1;
    return probe_trace(p, &r2, NULL, h2, &pn);
}

static int probe_shadow(const void *v, const double *o, const double *d, const double *d2, double tmax)
{
    const probe_cs *p = v;
    const cscene *cs = p->cs;
    prim_ray r2;
    probe_hit h1;
    geom_stats gs;
    csg_hit ch;
    double tm = tmax * cs->nm.scale;
    if (probe_spawn(p, o, d, d2, &h1, &r2))
        return -1;
    memset(&gs, 0, sizeof gs);
    return NS(csg_occluded)(&cs->tree, &r2, num_from_d(tm < GEOM_TMAX ? tm : GEOM_TMAX), (arena *)&p->ar, &gs,
                            &ch);
}

static int probe_light(const void *v, const double *o, const double *d, int li)
{
    const probe_cs *p = v;
    const cscene *cs = p->cs;
    prim_ray r, s;
    probe_hit h;
    geom_stats gs;
    csg_hit ch;
    vec3 pn, l;
    num dist;
    double pd[3], ld[3];
    if (li < 0 || (size_t)li >= cs->nlights || probe_ray(cs, o, d, &r)
        || !probe_trace(p, &r, p->buffered ? &cs->eyebuf : NULL, &h, &pn)
        || vec3_normalize(vec3_sub(cs->lights[li].pos, pn), &l, &dist))
        return -1;
    vec3_to_d(pn, pd);
    vec3_to_d(l, ld);
    prim_ray_set_d(&s, pn, l, pd, ld, h.prim, dmath_dot3(h.sf.n, ld) < 0);
    memset(&gs, 0, sizeof gs);
    if (p->buffered && cs->lbuf && cs->lbuf[li].start)
        return NS(csg_occluded_to)(&cs->tree, &cs->lbuf[li], &s, dist, (arena *)&p->ar, &gs, &ch);
    return NS(csg_occluded)(&cs->tree, &s, dist, (arena *)&p->ar, &gs, &ch);
}

static int probe_buffers(void *v)
{
    probe_cs *p = v;
    size_t i;
    int n = p->cs->eyebuf.start != NULL;
    for (i = 0; p->cs->lbuf && i < p->cs->nlights; i++)
        n += p->cs->lbuf[i].start != NULL;
    p->buffered = 1;
    return n;
}

static int probe_refract(const double *d, const double *n, double eta, double *t)
{
    vec3 tv;
    int r = NS(optics_refract)(vec3_from_d(d), vec3_from_d(n), eta, &tv);
    if (r == 0)
        vec3_to_d(tv, t);
    return r;
}

static void probe_unbox(void *v)
{
    csg *t = &((probe_cs *)v)->cs->tree;
    int i, k, j;
    for (i = 0; i < t->nnodes; i++)
        for (k = 0; k < 3; k++) {
            t->nodes[i].lo[k] = -HUGE_VAL;
            t->nodes[i].hi[k] = HUGE_VAL;
        }
    for (i = 0; i < t->objtree.nnodes; i++)
        for (k = 0; k < 3; k++)
            for (j = 0; j < 2; j++) {
                t->objtree.nodes[i].lo[k][j] = -HUGE_VAL;
                t->objtree.nodes[i].hi[k][j] = HUGE_VAL;
            }
}

static int probe_deepen(void *v)
{
    probe_cs *p = v;
    csg *t = &p->cs->tree;
    int depth = t->objtree.depth;
    if (depth < CSG_TODO_LOCAL)
        t->objtree.depth = CSG_TODO_LOCAL;
    arena_free(&p->ar);                  /* room for the deeper stack */
    return arena_init(&p->ar, NS(csg_arena_bytes)(t)) ? -1 : depth;
}

static void probe_whole(void *v) { ((probe_cs *)v)->cs->tree.whole = 1; }

static int probe_instances(const void *v) { return ((const probe_cs *)v)->cs->tree.ninst; }

const probe_ops NS(probe_ops) = {
    .name = NUM_NAME,
    .compile = probe_compile,
    .free = probe_free,
    .prim_span = probe_prim_span,
    .hit = probe_hit_fn,
    .respawn = probe_respawn,
    .shadow = probe_shadow,
    .refract = probe_refract,
    .unbox = probe_unbox,
    .deepen = probe_deepen,
    .whole = probe_whole,
    .light = probe_light,
    .buffers = probe_buffers,
    .instances = probe_instances,
};
