/* pds_mosaic — Voronoi mosaic of seed points (modal). A point belongs to
 * the nearest seed (ties: the lower seed number); it is mortar when it lies
 * within mortar/2 of the bisector with some other seed, i.e. when
 * d_i^2 - d_1^2 <= mortar * |s_i - s_1| for a seed i other than the nearest.
 * Seeds are bucketed in a G x G grid (G ~ sqrt(seeds)); a lookup scans
 * rings of buckets around the point's bucket until no farther bucket can
 * hold a nearer seed (or, with mortar, a seed within d_1 + mortar). */
#include "pds/pds_kind.h"
#include <math.h>
#include "pds/pds_num.h"
#include "util/mem.h"

typedef struct mosaic {
    long g;                  /* grid side */
    num *su, *sv;            /* seeds (sorted by bucket) */
    int32_t *attr;           /* their ids */
    uint32_t *order;         /* their definition numbers, for ties */
    uint32_t *start;         /* bucket b holds seeds start[b] .. start[b+1]-1 */
    num *ring;               /* ring[r] = r * bucket size */
    pds_wide *ring2;         /* ring[r]^2 */
    num mortar;
    int32_t mortar_attr;
    size_t n;
} mosaic;

static void release(void *impl)
{
    mosaic *m = impl;
    if (!m)
        return;
    mem_free(m->su); mem_free(m->sv); mem_free(m->attr); mem_free(m->order);
    mem_free(m->start); mem_free(m->ring); mem_free(m->ring2);
    mem_free(m);
}

static int compile(const pds_def *def, const char *file, void **out, diag *err)
{
    const pds_mosaic *d = &def->mosaic;
    mosaic *m = mem_calloc(1, sizeof *m);
    uint32_t *fill = NULL;
    size_t i, n = d->nseeds;
    long g, r, b;
    if (!m)
        goto oom;
    g = (long)ceil(sqrt((double)n));
    g = g < 1 ? 1 : g > 1024 ? 1024 : g;
    m->g = g;
    m->n = n;
    m->su = mem_calloc(n, sizeof *m->su);
    m->sv = mem_calloc(n, sizeof *m->sv);
    m->attr = mem_calloc(n, sizeof *m->attr);
    m->order = mem_calloc(n, sizeof *m->order);
    m->start = mem_calloc((size_t)(g * g + 1), sizeof *m->start);
    m->ring = mem_calloc((size_t)g + 2, sizeof *m->ring);
    m->ring2 = mem_calloc((size_t)g + 2, sizeof *m->ring2);
    fill = mem_calloc((size_t)(g * g), sizeof *fill);
    if (!m->su || !m->sv || !m->attr || !m->order || !m->start || !m->ring || !m->ring2 || !fill)
        goto oom;
    /* Counting sort of the seeds into buckets, stable in definition order. */
    for (i = 0; i < n; i++) {
        num u = num_from_d(d->seeds[2 * i]), v = num_from_d(d->seeds[2 * i + 1]);
        m->start[pds_num_cell(v, g) * g + pds_num_cell(u, g) + 1]++;
    }
    for (b = 0; b < g * g; b++)
        m->start[b + 1] += m->start[b];
    for (i = 0; i < n; i++) {
        num u = num_from_d(d->seeds[2 * i]), v = num_from_d(d->seeds[2 * i + 1]);
        long cell = pds_num_cell(v, g) * g + pds_num_cell(u, g);
        uint32_t at = m->start[cell] + fill[cell]++;
        m->su[at] = u;
        m->sv[at] = v;
        m->attr[at] = d->attrs[i];
        m->order[at] = (uint32_t)i;
    }
    for (r = 0; r <= g + 1; r++) {
        /* Lower bounds on the distance to seeds r + 1 or more buckets away.
         * Bucket edges fall between representable numbers, so take off two
         * units of the mode's resolution before squaring. */
        double rd = (double)r / (double)g - 2 * num_to_d(NUM_ULP);
        rd = rd > 0 ? rd : 0;
        m->ring[r] = num_from_d(rd);
        m->ring2[r] = pds_wide_from_d(rd * rd);
    }
    m->mortar = num_from_d(d->mortar);
    m->mortar_attr = d->mortar_attr;
    mem_free(fill);
    *out = m;
    return 0;
oom:
    mem_free(fill);
    release(m);
    return NS(pds_oom)(def, file, err);
}

/* Visits every bucket in ring r (Chebyshev distance r) around (cu, cv). */
#define RING_FOR(m, cu, cv, r, ...)                                                   \
    do {                                                                              \
        long y_, x_;                                                                  \
        for (y_ = (cv) - (r); y_ <= (cv) + (r); y_++) {                               \
            long dx_ = (y_ == (cv) - (r) || y_ == (cv) + (r)) ? 1 : 2 * (r);          \
            if (y_ < 0 || y_ >= (m)->g)                                               \
                continue;                                                             \
            for (x_ = (cu) - (r); x_ <= (cu) + (r); x_ += dx_ > 0 ? dx_ : 1) {        \
                uint32_t s_;                                                          \
                if (x_ < 0 || x_ >= (m)->g)                                           \
                    continue;                                                         \
                for (s_ = (m)->start[y_ * (m)->g + x_]; s_ < (m)->start[y_ * (m)->g + x_ + 1]; s_++) { __VA_ARGS__ } \
            }                                                                         \
        }                                                                             \
    } while (0)

static int32_t locate(const void *impl, num u, num v, unsigned long *steps)
{
    const mosaic *m = impl;
    long cu = pds_num_cell(u, m->g), cv = pds_num_cell(v, m->g), r, reach;
    pds_wide best = PDS_WIDE_MAX, reach2;
    num d1;
    uint32_t bi = 0;
    int found = 0;
    for (r = 0; r <= m->g; r++) {
        RING_FOR(m, cu, cv, r, {
            pds_wide dd = pds_wide_sq2(num_sub(m->su[s_], u), num_sub(m->sv[s_], v));
            ++*steps;
            if (!found || dd < best || (dd == best && m->order[s_] < m->order[bi])) {
                best = dd;
                bi = s_;
                found = 1;
            }
        });
        /* Seeds in rings beyond r lie at least r buckets away. */
        if (found && best < m->ring2[r])
            break;
    }
    if (m->mortar == NUM_ZERO)
        return m->attr[bi];
    /* Any seed within d1 + mortar may own a bisector inside the band; the
     * few units of slack cover the rounded square root. Farther seeds are
     * skipped by their squared distance before any square root is taken. */
    d1 = num_add(num_add(pds_wide_sqrt(best), m->mortar), 4 * NUM_ULP);
    reach2 = pds_wide_sq2(d1, NUM_ZERO);
    for (reach = 0; reach <= m->g && m->ring[reach > 0 ? reach - 1 : 0] <= d1; reach++) {
        RING_FOR(m, cu, cv, reach, {
            pds_wide dd = pds_wide_sq2(num_sub(m->su[s_], u), num_sub(m->sv[s_], v));
            ++*steps;
            if (s_ != bi && dd <= reach2) {
                num sep = pds_wide_sqrt(pds_wide_sq2(num_sub(m->su[s_], m->su[bi]), num_sub(m->sv[s_], m->sv[bi])));
                if (dd - best <= pds_wide_mul(m->mortar, sep))
                    return m->mortar_attr;
            }
        });
    }
    return m->attr[bi];
}

static size_t bytes(const void *impl)
{
    const mosaic *m = impl;
    return sizeof *m + m->n * (2 * sizeof(num) + sizeof(int32_t) + sizeof(uint32_t)) +
           (size_t)(m->g * m->g + 1) * sizeof(uint32_t) + (size_t)(m->g + 2) * (sizeof(num) + sizeof(pds_wide));
}

const NS(pds_kind_ops) NS(pds_mosaic_ops) = { "mosaic", compile, locate, bytes, release };
