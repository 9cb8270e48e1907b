/* test_util — the allocation hook, first-error diagnostics, the box
 * hierarchy builder, the radix sort and the 3x3 norms (src/util). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "support.h"
#include "util/arena.h"
#include "util/diag.h"
#include "util/dmath.h"
#include "util/mem.h"
#include "util/bvh.h"
#include "util/lightbuf.h"
#include "util/radix.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Zero-byte requests return distinct valid pointers; NULL means failure. */
static void test_util_mem_zero_bytes(void **state)
{
    void *a, *b, *c, *r;
    size_t cap = 0;
    int *arr = NULL;
    (void)state;
    a = mem_alloc(0);
    b = mem_calloc(0, 8);
    c = mem_calloc(8, 0);
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    assert_ptr_not_equal(a, b);
    r = mem_realloc(a, 0);
    assert_non_null(r);
    assert_int_equal(mem_grow((void **)&arr, &cap, 0, sizeof *arr), 0);
    assert_non_null(arr);
    assert_true(cap >= 1);
    mem_free(r);
    mem_free(b);
    mem_free(c);
    mem_free(arr);
}

static void test_util_mem_fail_and_overflow(void **state)
{
    (void)state;
    mem_fail_after(0);
    assert_null(mem_alloc(0));
    assert_null(mem_alloc(16));
    mem_fail_after(-1);
    assert_null(mem_calloc((size_t)-1, 16));
}

/* 1 when the mapping of this process that holds address at carries the
 * huge-page advice ("hg" in its VmFlags, proc(5) smaps), 0 when not, -1
 * when no mapping holds it. */
static int test_util_advised(uintptr_t at)
{
    FILE *f = fopen("/proc/self/smaps", "r");
    char line[512];
    int in = 0, flagged = -1;
    assert_non_null(f);
    while (fgets(line, sizeof line, f)) {
        unsigned long l, h;
        if (sscanf(line, "%lx-%lx ", &l, &h) == 2 && strchr(line, '-') < strchr(line, ' ')) {
            in = at >= (uintptr_t)l && at < (uintptr_t)h;
        } else if (in && !strncmp(line, "VmFlags:", 8)) {
            flagged = strstr(line, " hg") != NULL;
            break;
        }
    }
    fclose(f);
    return flagged;
}

/* A block of at least MEM_HUGE_MIN bytes is asked of malloc padded to
 * whole 2 MiB pages, and the pages it covers are advised for huge pages
 * (mem.h). On Linux with transparent huge
 * pages offered on request ("[madvise]" or "[always]" in
 * /sys/kernel/mm/transparent_hugepage/enabled), a block of 8 MiB from
 * mem_alloc lies in a mapping whose VmFlags (proc(5), smaps) carry "hg",
 * the advice given. */
static void test_util_mem_huge_pages(void **state)
{
    const uintptr_t M = MEM_HUGE_PAGE;
    uintptr_t a = 0;
    size_t n = 0;
    FILE *f;
    char line[512];
    (void)state;
    /* a large block is asked for so that with MEM_HUGE_SLACK bytes it
     * fills whole 2 MiB pages; a small one as it is */
    assert_true(mem_huge_size(MEM_HUGE_MIN - 1) == MEM_HUGE_MIN - 1);
    assert_true(mem_huge_size(MEM_HUGE_MIN) == 2 * M - MEM_HUGE_SLACK);
    assert_true(mem_huge_size(2 * M - MEM_HUGE_SLACK) == 2 * M - MEM_HUGE_SLACK);
    assert_true(mem_huge_size(2 * M - MEM_HUGE_SLACK + 1) == 3 * M - MEM_HUGE_SLACK);
    assert_true(mem_huge_size(SIZE_MAX - 8) == SIZE_MAX - 8);
    /* the pages the block covers, its first and last counted when it
     * reaches them within MEM_HUGE_SLACK bytes (the allocator's header) */
    assert_int_equal(mem_huge_range(3 * M, 2 * M, &a, &n), 1);
    assert_true(a == 3 * M && n == 2 * M);
    assert_int_equal(mem_huge_range(3 * M + 16, 4 * M - 32, &a, &n), 1);   /* a whole mapping */
    assert_true(a == 3 * M && n == 4 * M);
    assert_int_equal(mem_huge_range(3 * M + 16, 4 * M, &a, &n), 1);
    assert_true(a == 3 * M && n == 4 * M);
    assert_int_equal(mem_huge_range(3 * M + MEM_HUGE_SLACK, 2 * M, &a, &n), 1);
    assert_true(a == 4 * M && n == M);
    assert_int_equal(mem_huge_range(3 * M + 64, M + 32, &a, &n), 0);   /* no whole page */
    assert_int_equal(mem_huge_range(3 * M, MEM_HUGE_MIN - 1, &a, &n), 0);
    assert_int_equal(mem_huge_range(UINTPTR_MAX - M, 4 * M, &a, &n), 0);
    assert_int_equal(mem_huge_range(M, SIZE_MAX - M, &a, &n), 0);
    /* mem_align_line: the first 64-byte boundary at or after p */
    assert_true(mem_align_line((void *)(3 * M)) == (void *)(3 * M));
    assert_true(mem_align_line((void *)(3 * M + 1)) == (void *)(3 * M + 64));
    assert_true(mem_align_line((void *)(3 * M + 63)) == (void *)(3 * M + 64));
    assert_true(mem_align_line((void *)(3 * M + 64)) == (void *)(3 * M + 64));
    assert_null(mem_align_line(NULL));
    f = fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f || !fgets(line, sizeof line, f) || (!strstr(line, "[madvise]") && !strstr(line, "[always]"))) {
        if (f)
            fclose(f);
        print_message("# transparent huge pages not offered here: the advice is not checked\n");
        return;
    }
    fclose(f);
    {
        size_t size = 8u << 20, i;
        unsigned char *p = mem_alloc(size), *q;
        assert_non_null(p);
        memset(p, 1, size);
        assert_int_equal(mem_huge_range((uintptr_t)p, size, &a, &n), 1);
        assert_int_equal(test_util_advised(a), 1);
        mem_free(p);
        /* mem_calloc_part: the pages its first `likely` elements fill,
         * and not the rest of the block, which reads as zeros. 40 MiB:
         * above the most glibc's malloc raises its mapping threshold to
         * (32 MiB), so the block is a mapping of its own, not heap memory
         * an earlier block's advice may still cover. */
        size = 40u << 20;
        q = mem_calloc_part(size, 1, 5u << 20);
        assert_non_null(q);
        for (i = 0; i < size; i += 4096)
            assert_int_equal(q[i], 0);
        assert_int_equal(mem_huge_range((uintptr_t)q, 5u << 20, &a, &n), 1);
        assert_true(n >= 2 * M);         /* 5 MiB hold a whole page wherever the mapping starts */
        assert_int_equal(test_util_advised(a), 1);
        assert_int_equal(test_util_advised(a + n - 1), 1);
        assert_int_equal(test_util_advised(a + n), 0);
        assert_int_equal(test_util_advised((uintptr_t)q + size - 1), 0);
        mem_free(q);
    }
}

/* The first error wins; line/col and offset forms format as documented. */
static void test_util_diag_first_error_and_forms(void **state)
{
    diag d;
    char buf[256];
    (void)state;
    diag_init(&d);
    assert_int_equal(diag_at(&d, DIAG_INPUT, "deck", 3, 7, "bad %s", "item"), DIAG_INPUT);
    assert_int_equal(diag_offset(&d, DIAG_IO, "other", 12, "ignored"), DIAG_IO);
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "deck:3:7: error: bad item");
    diag_init(&d);
    diag_offset(&d, DIAG_INPUT, "list.dl", 40, "bad element %d", 2);
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "list.dl: offset 40: error: bad element 2");
    assert_int_equal(d.line, 0);
    diag_init(&d);
    diag_at(&d, DIAG_IO, "f", 0, 0, "gone");
    diag_format(&d, buf, sizeof buf);
    assert_string_equal(buf, "f: error: gone");
}

/* Checks the subtree at child index k: every item under it is within the
 * box the parent holds for it, each item is seen once; returns the depth
 * in nodes. */
static int util_bvh_walk(const bvh *b, int k, const double *plo, const double *phi,
                         double (*lo)[3], double (*hi)[3], int *seen, long *bad)
{
    int j, a, d[2];
    if (k < 0) {
        seen[~k]++;
        for (a = 0; a < 3; a++)
            if (lo[~k][a] < plo[a] || hi[~k][a] > phi[a])
                (*bad)++;
        return 0;
    }
    for (j = 0; j < 2; j++) {
        double clo[3], chi[3];
        for (a = 0; a < 3; a++) {
            clo[a] = b->nodes[k].lo[a][j];
            chi[a] = b->nodes[k].hi[a][j];
            if (clo[a] < plo[a] || chi[a] > phi[a])
                (*bad)++;
        }
        d[j] = util_bvh_walk(b, b->nodes[k].kid[j], clo, chi, lo, hi, seen, bad);
    }
    return 1 + (d[0] > d[1] ? d[0] : d[1]);
}

/* Random boxes, a grid, coincident centres and one item: every item once,
 * each within its parent's box for it, n - 1 nodes, the recorded depth
 * true and below BVH_SAH_DEPTH + log2(n) + 1; a failed allocation leaves
 * nothing built. */
static void test_util_bvh_covers_every_item_once(void **state)
{
    enum { N = 3000 };
    static double lo[N][3], hi[N][3];
    static int seen[N];
    const double inf[3] = {-1e308, -1e308, -1e308}, sup[3] = {1e308, 1e308, 1e308};
    uint64_t s = test_seed("test_util_bvh_covers_every_item_once");
    size_t sizes[] = {1, 2, 3, 17, N}, c;
    int shape, i, a;
    (void)state;
    for (shape = 0; shape < 3; shape++)
        for (c = 0; c < sizeof sizes / sizeof sizes[0]; c++) {
            size_t n = sizes[c];
            bvh b;
            long bad = 0;
            int depth, log2n = 0;
            for (i = 0; i < (int)n; i++)
                for (a = 0; a < 3; a++) {
                    double x = shape == 0 ? test_uniform(&s, -100, 100)
                             : shape == 1 ? (a == 0 ? i % 55 : a == 1 ? i / 55 : 0) * 3.0 : 7;
                    double w = shape == 0 ? test_uniform(&s, 0, 5) : 1;
                    lo[i][a] = x - w;
                    hi[i][a] = x + w;
                }
            assert_int_equal(bvh_build((const double (*)[3])lo, (const double (*)[3])hi, n, &b), 0);
            assert_int_equal(b.nnodes, (int)n - 1);
            memset(seen, 0, sizeof seen);
            depth = util_bvh_walk(&b, b.root, inf, sup, lo, hi, seen, &bad);
            assert_int_equal(bad, 0);
            for (i = 0; i < (int)n; i++)
                assert_int_equal(seen[i], 1);
            assert_int_equal(depth, b.depth);
            while (((size_t)1 << log2n) < n)
                log2n++;
            assert_true(b.depth <= BVH_SAH_DEPTH + log2n + 1);
            if (shape == 1 && n == N)      /* a grid: about balanced */
                assert_true(b.depth <= 2 * log2n);
            bvh_free(&b);
        }
    for (i = 0; i < 3; i++) {
        bvh b;
        memset(&b, 0, sizeof b);
        mem_fail_after(i);
        assert_int_equal(bvh_build((const double (*)[3])lo, (const double (*)[3])hi, 50, &b), -1);
        mem_fail_after(-1);
        assert_null(b.nodes);
    }
}

/* Whether the segment o + t d, t in [0, tmax], meets the box [lo, hi]
 * (slabs in binary64; a zero component tests the origin's coordinate). */
static int util_segment_meets(const double *o, const double *d, double tmax, const double *lo, const double *hi)
{
    double t0 = 0, t1 = tmax;
    int a;
    for (a = 0; a < 3; a++) {
        if (d[a] == 0) {
            if (o[a] < lo[a] || o[a] > hi[a])
                return 0;
        } else {
            double u = (lo[a] - o[a]) / d[a], v = (hi[a] - o[a]) / d[a];
            t0 = fmax(t0, fmin(u, v));
            t1 = fmin(t1, fmax(u, v));
        }
    }
    return t0 <= t1;
}

/* Random boxes (some tiny, some large enough to cross the faces' planes
 * through the light, some around the light itself) and rays that pass the
 * light at up to about the boxes' growth: to the light from anywhere
 * (stopping short of it or past it) and away from it. Where the lookup
 * answers, every box the segment meets is in the cell's list, once, and
 * before the first whose distance from the light (lightbuf.far, ascending
 * and no greater than the box's own) exceeds the ray's reach
 * (lightbuf_ray_far), where csg_nearest stops reading the list; it
 * answers whenever the ray passes within 0.99 of grow / 2 and stops (or
 * starts) within as much of its closest point, and never beyond 1.01 of
 * it. A buffer whose cells would hold too many entries is not built and
 * answers no ray. A failed allocation leaves nothing built. */
static void test_util_lightbuf_lists_every_box_a_ray_meets(void **state)
{
    enum { N = 240, RAYS = 3000 };
    static double lo[N][3], hi[N][3];
    static int listed[N];
    uint64_t s = test_seed("test_util_lightbuf_lists_every_box_a_ray_meets");
    long answered = 0, met = 0, refused = 0, unbuilt = 0, cuts = 0;
    lightbuf_scratch scratch;              /* shared by the builds, as the
                                              scene compiler's; grows with n */
    int trial;
    (void)state;
    memset(&scratch, 0, sizeof scratch);
    for (trial = 0; trial < 24; trial++) {
        size_t n = trial % 4 == 0 ? (trial % 8 ? 60 : 9) : trial % 3 == 0 ? 60 : N;
        double at[3], grow = trial % 2 ? 1.0 / 32 : test_uniform(&s, 0.1, 1.5);
        lightbuf lb;
        int i, a, k, built;
        for (a = 0; a < 3; a++)            /* among the boxes, or off to one side */
            at[a] = test_uniform(&s, -20, 20) + (trial % 4 && a == trial % 3 ? 60 : 0);
        for (i = 0; i < (int)n; i++) {
            /* one large, one around the light, two small ones a growth or
             * so from it, then some tiny ones and ordinary ones */
            int kind = i < 4 ? i : 4 + (int)(test_rand(&s) % 12);
            for (a = 0; a < 3; a++) {
                double c = kind == 0 ? at[a] + test_uniform(&s, -0.1, 0.1)
                           : kind <= 3 && kind >= 2 ? at[a] + test_uniform(&s, -1.5, 1.5) * grow
                                                    : test_uniform(&s, -25, 25);
                double w = kind == 1 ? test_uniform(&s, 5, 30) : kind <= 3 ? test_uniform(&s, 1e-4, 0.2) * grow
                           : kind <= 5 ? test_uniform(&s, 1e-4, 0.05) : test_uniform(&s, 0.1, 3);
                lo[i][a] = c - w;
                hi[i][a] = c + w;
            }
        }
        built = lightbuf_build(&lb, at, (const double (*)[3])lo, (const double (*)[3])hi, n, grow, &scratch);
        assert_true(built == 0 || built == 1);
        unbuilt += built;                  /* too many entries: no buffer */
        for (k = 0; k < RAYS; k++) {
            int toward = k % 2 == 0, m = 0, got, j, cut;
            const int *item = NULL;
            double o[3], d[3], u[3], len = 0, off, tmax, p[3], dd = 0, rd = 0, c2 = 0, ts, gap;
            for (a = 0; a < 3; a++)
                o[a] = test_uniform(&s, -40, 40);
            if (k % 4 != 1 && k % 4 != 3 && k % 8) {   /* past a box's corner, towards the light */
                int b = 4 + (int)(test_rand(&s) % (n - 4)), corner = (int)(test_rand(&s) % 8);
                double back = test_uniform(&s, 0.1, 1);
                for (a = 0; a < 3; a++) {
                    double c = (corner >> a & 1 ? hi[b][a] : lo[b][a]) + test_uniform(&s, -1, 1) * grow;
                    o[a] = c - (at[a] - c) * back;
                }
            }
            for (a = 0; a < 3; a++) {
                u[a] = at[a] - o[a];
                len += u[a] * u[a];
            }
            len = sqrt(len);
            off = test_uniform(&s, k % 3 ? 0.2 : 0, 0.6) * grow;   /* how far the line passes */
            for (a = 0; a < 3; a++)
                p[a] = test_uniform(&s, -1, 1);
            for (a = 0; a < 3; a++)
                d[a] = u[a] / len + off / len * p[a] / sqrt(3.0);
            if (toward) {
                tmax = len + test_uniform(&s, -0.6, 0.3) * grow;
            } else {                                /* from near the light outwards */
                for (a = 0; a < 3; a++) {
                    o[a] = at[a] + test_uniform(&s, -0.4, 0.4) * grow;
                    d[a] = -d[a];
                }
                tmax = test_uniform(&s, 1, 80);
            }
            if (k % 7 == 3)                         /* directions need not be unit */
                for (a = 0; a < 3; a++)
                    d[a] *= test_uniform(&s, 0.25, 4);
            for (a = 0; a < 3; a++) {
                dd += d[a] * d[a];
                rd += (at[a] - o[a]) * d[a];
            }
            ts = rd / dd;
            for (a = 0; a < 3; a++) {
                double q = at[a] - o[a] - ts * d[a];
                c2 += q * q;
            }
            gap = toward ? (tmax - ts) * sqrt(dd) : ts * sqrt(dd);
            got = lightbuf_lookup(&lb, o, d, tmax, toward, &item, &m);
            if (sqrt(c2) <= 0.99 * grow / 2 && gap <= 0.99 * grow / 2)
                assert_int_equal(got, !built);
            if (sqrt(c2) > 1.01 * grow / 2 || gap > 1.01 * grow / 2)
                assert_int_equal(got, 0);
            if (!got) {
                refused++;
                continue;
            }
            answered++;
            /* listed: 1 before the cut lightbuf_ray_far allows, 2 after;
             * the distances ascend and bound each box's own */
            memset(listed, 0, sizeof listed);
            for (j = -lb.nnear, cut = 0; j < m; j++) {
                int b = j < 0 ? lb.near[~j] : item[j];
                assert_true(b >= 0 && b < (int)n);
                assert_int_equal(listed[b], 0);
                if (j >= 0) {
                    double g2 = 0;
                    for (a = 0; a < 3; a++) {
                        double g = lo[b][a] > at[a] ? lo[b][a] - at[a] : at[a] > hi[b][a] ? at[a] - hi[b][a] : 0;
                        g2 += g * g;
                    }
                    assert_true((double)lb.far[b] <= sqrt(g2));
                    assert_true(j == 0 || lb.far[item[j - 1]] <= lb.far[b]);
                    cut |= lb.far[b] > lightbuf_ray_far(&lb, o, d, tmax, toward);
                }
                listed[b] = 1 + cut;
                cuts += cut;
            }
            for (i = 0; i < (int)n; i++)
                if (util_segment_meets(o, d, tmax, lo[i], hi[i])) {
                    met++;
                    if (listed[i] != 1)
                        fail_msg("trial %d ray %d: box %d met (line %.3g from the light, grow %.3g) "
                                 "but %s", trial, k, i, sqrt(c2), grow, listed[i] ? "past the cut" : "not listed");
                }
        }
        lightbuf_free(&lb);
    }
    lightbuf_scratch_free(&scratch);
    print_message("lightbuf: %ld of 24 buffers built, %ld rays answered, %ld refused, %ld boxes met, "
                  "%ld listed past the cut\n", 24 - unbuilt, answered, refused, met, cuts);
    assert_true(unbuilt <= 8 && answered > 20000 && refused > 2000 && met > 20000 && cuts > 1000);
    for (trial = 0; trial < 4; trial++) {
        lightbuf lb;
        double at[3] = {0, 0, 0};
        lightbuf_scratch fresh;
        memset(&fresh, 0, sizeof fresh);
        mem_fail_after(trial);
        assert_int_equal(lightbuf_build(&lb, at, (const double (*)[3])lo, (const double (*)[3])hi, 50, 0.1, &fresh),
                         -1);
        mem_fail_after(-1);
        lightbuf_scratch_free(&fresh);
        assert_null(lb.start);
        assert_null(lb.item);
    }
}

/* An element as prim_share sorts them: a key, then the (primitive, plane)
 * it was stored in, ascending. */
typedef struct util_rec { double key; int prim, k; } util_rec;

/* The order prim_share's comparators give: key, then storage order. */
static int util_rec_cmp(const void *a, const void *b)
{
    const util_rec *x = a, *y = b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    if (x->prim != y->prim)
        return x->prim - y->prim;
    return x->k - y->k;
}

/* radix_order gives exactly qsort's order under util_rec_cmp, and
 * radix_rank each element's place in it: keys drawn
 * from a small pool (many ties; -0 beside +0, negatives, subnormals,
 * infinities, neighbours one ulp apart), from all over the doubles (a
 * pass per digit) and from 1 + j ulp, j < 2048 (one pass), for sizes 0 to
 * 40,000 (the wide digits from 32,768); with all keys equal (no pass) it
 * is the identity. */
static void test_util_radix_order_matches_comparator(void **state)
{
    static const double pool[] = {0.0, -0.0, 1.0, -1.0, 0.5, 1e-310, -1e-310, 3.0e300,
                                  -HUGE_VAL, HUGE_VAL, 1.0000000000000002, 0.9999999999999999,
                                  2.5, -2.5, 1e-9, 1024.0};
    static const size_t sizes[] = {0, 1, 2, 3, 255, 2048, 5000, 40000};
    size_t t, i;
    radix_ix *ord;
    unsigned seed = 12345;
    (void)state;
    for (t = 0; t < 3 * sizeof sizes / sizeof sizes[0]; t++) {
        size_t n = sizes[t / 3];
        util_rec *a = mem_alloc(n * sizeof *a), *b = mem_alloc(n * sizeof *b);
        uint64_t *key = mem_alloc(n * sizeof *key);
        assert_true(a && b && key);
        for (i = 0; i < n; i++) {
            seed = seed * 1103515245u + 12345u;
            if (t % 3 == 0) {
                a[i].key = pool[(seed >> 16) % (sizeof pool / sizeof pool[0])];
            } else if (t % 3 == 2) {
                a[i].key = 1 + (double)(seed >> 21) * DBL_EPSILON;
            } else {
                uint64_t u = (uint64_t)seed << 32 ^ (uint64_t)(seed * 2654435761u) << 7;
                memcpy(&a[i].key, &u, sizeof u);
                if (isnan(a[i].key))              /* NaN has no order */
                    a[i].key = 7;
            }
            a[i].prim = (int)(i / 6);
            a[i].k = (int)(i % 6);
            key[i] = radix_key_d(a[i].key);
        }
        qsort(memcpy(b, a, n * sizeof *a), n, sizeof *b, util_rec_cmp);
        ord = radix_order(key, n);
        assert_non_null(ord);
        for (i = 0; i < n; i++)
            assert_memory_equal(&a[ord[i]], &b[i], sizeof *a);
        mem_free(ord);
        ord = radix_rank(key, n);               /* each element's place */
        assert_non_null(ord);
        for (i = 0; i < n; i++)
            assert_memory_equal(&a[i], &b[ord[i]], sizeof *a);
        mem_free(ord);
        {                                       /* the same in caller memory
                                                   left dirty, used twice */
            void *buf = mem_alloc(radix_bytes(n));
            assert_non_null(buf);
            memset(buf, 0xa5, radix_bytes(n));
            ord = radix_rank_in(key, n, buf);
            for (i = 0; i < n; i++)
                assert_memory_equal(&a[i], &b[ord[i]], sizeof *a);
            ord = radix_order_in(key, n, buf);
            for (i = 0; i < n; i++)
                assert_memory_equal(&a[ord[i]], &b[i], sizeof *a);
            mem_free(buf);
        }
        mem_free(a);
        mem_free(b);
        mem_free(key);
    }
    {
        uint64_t k[300];
        for (i = 0; i < 300; i++)
            k[i] = radix_key_d(2);
        ord = radix_order(k, 300);
        assert_non_null(ord);
        for (i = 0; i < 300; i++)
            assert_int_equal(ord[i], i);
        mem_free(ord);
        k[0] = radix_key_d(3);
        for (t = 0; t < 2; t++) {                 /* out of memory at its allocation */
            mem_fail_after(0);
            ord = t == 0 ? radix_order(k, 300) : radix_rank(k, 300);
            mem_fail_after(-1);
            assert_null(ord);
        }
        assert_int_equal(radix_bytes(SIZE_MAX / 16), 0);   /* too many to count */
#if SIZE_MAX > UINT32_MAX
        assert_int_equal(radix_bytes(RADIX_MAX + (size_t)1), 0);   /* or to index */
        assert_true(radix_bytes(RADIX_MAX) > 0);
        ord = radix_order(k, RADIX_MAX + (size_t)1);      /* refused before any read */
        assert_null(ord);
#endif
    }
}

/* Each of the ARENA_ALIGN largest sizes, which rounding up to a multiple
 * of ARENA_ALIGN would wrap round to 0 (all but the smallest of them), is
 * refused, not made a block of a few bytes and reported made. Smaller
 * sizes reach malloc, whose failure a sanitizer turns into an abort. */
static void test_util_arena_refuses_a_size_that_wraps(void **state)
{
    arena a;
    size_t n;
    (void)state;
    for (n = 0; n < ARENA_ALIGN; n++) {
        assert_int_equal(arena_init(&a, (size_t)-1 - n), -1);
        assert_null(a.base);
        assert_int_equal(a.size, 0);
    }
    assert_int_equal(arena_init(&a, 1), 0);
    assert_int_equal(a.size, ARENA_ALIGN);
    arena_free(&a);
}

/* The computed spectral norm never exceeds the Frobenius norm by more than
 * 1e-14 relative (cscene's aspect check relies on 1e-9): random matrices of
 * random scales, and the worst cases of the closed form (one singular value,
 * two equal largest ones, all equal, nearly singular). */
static void test_util_frobenius_bounds_spectral_norm(void **state)
{
    static const double fixed[][9] = {
        {1, 0, 0, 0, 0, 0, 0, 0, 0},      {1, 2, 3, 2, 4, 6, 3, 6, 9},
        {1, 0, 0, 0, 1, 0, 0, 0, 1e-9},   {1e-9, 0, 0, 0, 1e-9, 0, 0, 0, 1},
        {2, 0, 0, 0, 2, 0, 0, 0, 2},      {0.6, 0.8, 0, -0.8, 0.6, 0, 0, 0, 1e-12},
        {1, 1e-8, 0, 0, 1, 1e-8, 1e-8, 0, 1}, {0, 0, 0, 0, 0, 0, 0, 0, 0}};
    unsigned seed = 99;
    int t, i;
    (void)state;
    for (t = 0; t < 20000; t++) {
        double m[9], f, s;
        if (t < (int)(sizeof fixed / sizeof fixed[0])) {
            memcpy(m, fixed[t], sizeof m);
        } else {
            for (i = 0; i < 9; i++) {
                seed = seed * 1103515245u + 12345u;
                m[i] = ((double)(seed >> 8) / 8388608.0 - 1) * pow(10, (int)(seed % 7) - 3);
            }
            if (t % 3 == 0)                   /* rank one, or two equal rows */
                for (i = 3; i < 9; i++)
                    m[i] = m[i % 3] * (t % 2 ? 1 : (i < 6 ? 0.5 : -2));
        }
        f = dmath_m3_frobenius(m);
        s = dmath_m3_spectral_norm(m);
        assert_true(s <= f * (1 + 1e-14));
        assert_true(s >= f / sqrt(3) * (1 - 1e-9));
    }
}

/* dmath_f32_round against libm: the binary32 next to x on each side (x
 * itself where it is one), checked with nextafterf over random doubles of
 * every binade and sign, the two zeros, subnormals, and values past the
 * largest binary32; a few by their bits. */
static void test_util_f32_round_brackets(void **state)
{
    static const struct { double x; uint32_t down, up; } bits[] = {
        {0.1, 0x3dccccccu, 0x3dcccccdu},   {-0.1, 0xbdcccccdu, 0xbdccccccu},
        {1e-50, 0x00000000u, 0x00000001u}, {-1e-50, 0x80000001u, 0x80000000u},
        {0.0, 0x00000000u, 0x00000000u},   {1e39, 0x7f7fffffu, 0x7f800000u},
    };
    uint64_t seed = 88172645463325252u;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bits / sizeof bits[0]; i++) {
        float d = dmath_f32_round(bits[i].x, 0), u = dmath_f32_round(bits[i].x, 1);
        uint32_t bd, bu;
        memcpy(&bd, &d, sizeof bd);
        memcpy(&bu, &u, sizeof bu);
        assert_int_equal(bd, bits[i].down);
        assert_int_equal(bu, bits[i].up);
    }
    for (i = 0; i < 1000000; i++) {
        double x;
        float d, u, n;
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        x = ldexp((double)(seed >> 11) * 0x1p-53 + 1, (int)(seed % 300) - 160) * (seed & 1024 ? -1 : 1);
        d = dmath_f32_round(x, 0);
        u = dmath_f32_round(x, 1);
        n = (float)x;
        assert_true((double)d <= x && (double)u >= x);
        if ((double)n == x) {
            assert_true(d == n && u == n);
        } else {
            assert_true(nextafterf(d, INFINITY) == u);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_util_mem_zero_bytes),
        cmocka_unit_test(test_util_mem_fail_and_overflow),
        cmocka_unit_test(test_util_mem_huge_pages),
        cmocka_unit_test(test_util_diag_first_error_and_forms),
        cmocka_unit_test(test_util_bvh_covers_every_item_once),
        cmocka_unit_test(test_util_lightbuf_lists_every_box_a_ray_meets),
        cmocka_unit_test(test_util_radix_order_matches_comparator),
        cmocka_unit_test(test_util_arena_refuses_a_size_that_wraps),
        cmocka_unit_test(test_util_frobenius_bounds_spectral_norm),
        cmocka_unit_test(test_util_f32_round_brackets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
