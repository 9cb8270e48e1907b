/* test_cscene — what the scene compiler measures in double from each
 * primitive's corners, against all eight formed one by one, bit for bit:
 * the box the normalisation is taken from (src/trace/cscene.c) and the
 * bounding sphere's radius (src/geom/prim.c); and where primary rays
 * start. Checked in the f64 build; all of it is double in every mode. */
#define NUM_MODE f64
#define NUM_MODE_f64
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "geom/prim.h"
#include "model/prim_twin.h"
#include "model/scene_box.h"
#include "trace/cscene.h"
#include "util/dmath.h"
#include "tracer_test.h"

/* The box of the eight corners of every bounded primitive, each corner
 * formed and compared in turn, and the normalisation taken from it. */
static void cscene_test_norm(const scene *sc, geom_norm *nm)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double half = 0;
    size_t n;
    int i, j, k;
    for (n = 0; n < sc->nprims; n++) {
        const scene_prim *sp = &sc->prims[n];
        const double *m = sp->world_from_object;
        double c[3], l[3], h[3] = {1, 1, 1};
        if (scene_prim_canon_box(sp, c, l))
            continue;
        for (k = 0; k < 8; k++) {
            double p[3], w;
            for (i = 0; i < 3; i++)
                p[i] = ((k >> i) & 1 ? h[i] : l[i]) * c[i];
            for (i = 0; i < 3; i++) {
                w = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
                if (w < lo[i]) lo[i] = w;
                if (w > hi[i]) hi[i] = w;
            }
        }
    }
    for (j = 0; j < 3; j++)
        if ((hi[j] - lo[j]) / 2 > half)
            half = (hi[j] - lo[j]) / 2;
    if (!(half > 0) || !isfinite(GEOM_W / half)) {
        double mx = 0;
        for (j = 0; j < 3; j++)
            if (fabs(lo[j]) > mx) mx = fabs(lo[j]);
        half = mx > 0 ? mx * 1e-6 : 1.0;
    }
    nm->scale = GEOM_W / half;
    for (j = 0; j < 3; j++)
        nm->off[j] = -nm->scale * (lo[j] + hi[j]) / 2;
}

/* A random number for a deck: a few digits, sometimes exactly 0 or 1. */
static double cscene_test_num(uint64_t *seed, double lo, double hi)
{
    uint64_t r = test_rand(seed) % 8;
    if (r == 0)
        return 0;
    if (r == 1)
        return 1;
    return floor(test_uniform(seed, lo, hi) * 1000) / 1000;
}

/* A deck of one to three primitives of the bounded kinds, placed by quarter
 * turns (exact zeros in the matrix), other turns, negative and uneven
 * scales and translations that put faces on the deck's planes (boxes
 * touching 0, where corners may differ in the sign of zero). */
static scene *cscene_test_deck(uint64_t *seed, char *text, size_t size)
{
    static const char *const kind[4] = {"SPHERE P%d %.3f", "CYLINDER P%d %.3f %.3f",
                                        "CONE P%d %.3f %.3f %.3f", "BLOCK P%d %.3f %.3f %.3f"};
    size_t len = (size_t)snprintf(text, size, "EYE 30 -40 30\nLOOKAT 0 0 0\nLIGHT 6 -4 9\n");
    int n = 1 + (int)(test_rand(seed) % 3), i, t;
    for (i = 0; i < n; i++) {
        int k = (int)(test_rand(seed) % 4);
        double a = 0.125 + cscene_test_num(seed, 0, 3), b = 0.125 + cscene_test_num(seed, 0, 3);
        double c = 0.125 + cscene_test_num(seed, 0, 3);
        len += (size_t)snprintf(text + len, size - len, kind[k], i, a, k == 2 ? 0.0 : b, c);
        for (t = (int)(test_rand(seed) % 4); t > 0; t--) {
            uint64_t r = test_rand(seed) % 5;
            if (r == 0)
                len += (size_t)snprintf(text + len, size - len, " -\n ROTATE %c %d",
                                        "XYZ"[test_rand(seed) % 3], 90 * (int)(test_rand(seed) % 4));
            else if (r == 1)
                len += (size_t)snprintf(text + len, size - len, " -\n ROTATE AXIS %.3f %.3f 1 %.3f",
                                        cscene_test_num(seed, -2, 2), cscene_test_num(seed, -2, 2),
                                        cscene_test_num(seed, -180, 180));
            else if (r == 2)
                len += (size_t)snprintf(text + len, size - len, " -\n SCALE %.3f %.3f %.3f",
                                        test_rand(seed) % 2 ? -1.5 : 0.75, 0.5 + cscene_test_num(seed, 0, 2),
                                        -0.25 - cscene_test_num(seed, 0, 2));
            else
                len += (size_t)snprintf(text + len, size - len, " -\n TRANSLATE %.3f %.3f %.3f",
                                        cscene_test_num(seed, -5, 5), cscene_test_num(seed, -5, 5),
                                        cscene_test_num(seed, -5, 5));
        }
        len += (size_t)snprintf(text + len, size - len, "\nOBJECT P%d\n", i);
    }
    assert_true(len < size);
    return tt_parse(text);
}

/* sc compiled in f64; fails the test unless it parses and compiles. */
static cscene *cscene_test_compile(scene *sc)
{
    cscene *cs = NULL;
    diag err;
    assert_non_null(sc);
    diag_init(&err);
    assert_int_equal(f64_cscene_compile(sc, &cs, &err), 0);
    return cs;
}

/* 6,000 random decks: the compiled normalisation equals the one from all
 * eight corners. */
static void test_cscene_box_from_extreme_corners(void **state)
{
    uint64_t seed = test_seed("test_cscene_box_from_extreme_corners");
    int deck;
    (void)state;
    for (deck = 0; deck < 6000; deck++) {
        char text[2048];
        scene *sc = cscene_test_deck(&seed, text, sizeof text);
        cscene *cs = cscene_test_compile(sc);
        geom_norm want;
        cscene_test_norm(sc, &want);
        if (memcmp(&cs->nm, &want, sizeof want))
            fail_msg("deck %d: scale %.17g off %.17g %.17g %.17g, all corners give %.17g %.17g "
                     "%.17g %.17g\n%s", deck, cs->nm.scale, cs->nm.off[0], cs->nm.off[1],
                     cs->nm.off[2], want.scale, want.off[0], want.off[1], want.off[2], text);
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

/* A compiled cylinder's, cone's or block's bounding sphere has the radius
 * of its farthest corner of all eight (prim_compile measures four), for the
 * primitives of 6,000 random decks. */
static void test_cscene_bounding_radius_from_all_corners(void **state)
{
    uint64_t seed = test_seed("test_cscene_bounding_radius_from_all_corners");
    int deck;
    (void)state;
    for (deck = 0; deck < 6000; deck++) {
        char text[2048];
        scene *sc = cscene_test_deck(&seed, text, sizeof text);
        cscene *cs = cscene_test_compile(sc);
        diag err;
        size_t n;
        diag_init(&err);
        for (n = 0; n < sc->nprims; n++) {
            const scene_prim *sp = &sc->prims[n];
            double lo[3] = {-1, -1, 0}, cc[3] = {0, 0, 0.5}, r = 0, a[9];
            prim p;
            prim_plane pl[6];
            double pl_d[6][4];
            prim_frame fr;
            prim_lin lin;
            int i, k;
            if (sp->shape->kind == PRIM_SPHERE)
                continue;
            if (sp->shape->kind == PRIM_BLOCK)
                lo[0] = lo[1] = 0, cc[0] = cc[1] = 0.5;
            {
                double radius;
                assert_int_equal(f64_prim_compile(sp, (int)n, &cs->nm, pl, pl_d, &fr, &lin, NULL, &radius, &p, "test", &err), 0);
            }
            scene_prim_canon_map(sp, cs->nm.scale, a);
            for (k = 0; k < 8; k++) {
                double corner[3], w[3], len;
                for (i = 0; i < 3; i++)
                    corner[i] = ((k >> i) & 1 ? 1 : lo[i]) - cc[i];
                dmath_m3_mul_v(a, corner, w);
                len = dmath_len3(w);
                if (len > r)
                    r = len;
            }
            assert_true(p.br == r * (1 + 1e-6) + 1.0 / 16384);
        }
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

/* Every bounded leaf of 2,000 random decks keeps its primitive's box,
 * padded by CSG_BOX_PAD, as the tightest binary32 box around it: each
 * bound on the outer side, and the next binary32 inwards on the inner. */
static void test_cscene_node_boxes_rounded_outwards(void **state)
{
    uint64_t seed = test_seed("test_cscene_node_boxes_rounded_outwards");
    int deck, leaves = 0;
    (void)state;
    for (deck = 0; deck < 2000; deck++) {
        char text[2048];
        scene *sc = cscene_test_deck(&seed, text, sizeof text);
        cscene *cs = cscene_test_compile(sc);
        int k, i;
        for (k = 0; k < cs->tree.nnodes; k++) {
            const csg_node *nd = &cs->tree.nodes[k];
            double lo[3], hi[3], a[9];
            if (nd->op != CSG_LEAF || !nd->bounded)
                continue;
            scene_prim_canon_map(&sc->prims[csg_leaf_prim(nd)], cs->nm.scale, a);
            f64_prim_box(&cs->prims[csg_leaf_prim(nd)], a, lo, hi);
            for (i = 0; i < 3; i++) {
                double l = lo[i] - CSG_BOX_PAD, h = hi[i] + CSG_BOX_PAD;
                if (!(nd->lo[i] <= l && nextafterf(nd->lo[i], INFINITY) > l && nd->hi[i] >= h
                      && nextafterf(nd->hi[i], -INFINITY) < h))
                    fail_msg("deck %d node %d axis %d: [%.9g, %.9g] around [%.17g, %.17g]\n%s", deck, k, i,
                             (double)nd->lo[i], (double)nd->hi[i], l, h, text);
            }
            leaves++;
        }
        f64_cscene_free(cs);
        scene_free(sc);
    }
    assert_true(leaves > 2000);
}

/* The names of the primitives recorded in hull (up to CSG_HULL), sorted
 * and joined: "A,B". */
static void cscene_test_hull_names(const scene *sc, const int *hull, char *out, size_t cap)
{
    const char *names[CSG_HULL];
    int n = 0, i, j;
    for (i = 0; i < CSG_HULL && hull[i] >= 0; i++)
        names[n++] = sc->prims[hull[i]].shape->name;
    for (i = 1; i < n; i++)
        for (j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
            const char *t = names[j];
            names[j] = names[j - 1];
            names[j - 1] = t;
        }
    out[0] = 0;
    for (i = 0; i < n; i++)
        snprintf(out + strlen(out), cap - strlen(out), "%s%s", i ? "," : "", names[i]);
}

/* The primitives csg_build records as holding a whole object (the ones a
 * ray leaving them from its origin cannot find the object behind): both
 * operands of an intersection, a difference's left operand, none of a
 * union's; at most CSG_HULL of a long intersection, all of them from it. */
static void test_cscene_object_hull(void **state)
{
    static const char deck[] =
        "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n"
        "BLOCK A 2 2 2 TRANSLATE -1 -1 -1\nSPHERE B 1.3\nCYLINDER C 0.4 3 TRANSLATE 0 0 -1.5\n"
        "SPHERE D 0.3 TRANSLATE 5 0 0\nSPHERE E 0.3 TRANSLATE 5 1 0\n"
        "SPHERE F 1 TRANSLATE -5 0 0\nSPHERE G 1 TRANSLATE -5 0.1 0\nSPHERE H 1 TRANSLATE -5 0.2 0\n"
        "SPHERE J 1 TRANSLATE -5 0.3 0\nSPHERE K 1 TRANSLATE -5 0.4 0\nSPHERE L 1 TRANSLATE -5 0.5 0\n"
        "INTER I A B\nDIFF P I C\nUNION U D E\nINTER M F G H J K L\nUNION N C P\n"
        "OBJECT P\nOBJECT U\nOBJECT M\nOBJECT N\n";
    static const char *const want[4] = {"A,B", "", NULL, ""};
    scene *sc = tt_parse(deck);
    cscene *cs = NULL;
    diag err;
    int k;
    (void)state;
    assert_non_null(sc);
    diag_init(&err);
    assert_int_equal(f64_cscene_compile(sc, &cs, &err), 0);
    assert_int_equal(cs->tree.nobjects, 4);
    for (k = 0; k < 4; k++) {
        char got[64];
        cscene_test_hull_names(sc, cs->tree.hull[k], got, sizeof got);
        if (want[k]) {
            assert_string_equal(got, want[k]);
        } else {
            int i;
            assert_int_equal((int)strlen(got), 4 * 2 - 1);   /* four names */
            for (i = 0; i < 7; i += 2)
                assert_non_null(strchr("FGHJKL", got[i]));
        }
    }
    f64_cscene_free(cs);
    scene_free(sc);
}


/* A deck of one to four spheres and blocks at random places and turns, and
 * up to two half-spaces at random tilts, seen from a random eye, sometimes
 * among the primitives. */
static scene *cscene_test_view_deck(uint64_t *seed, char *text, size_t size)
{
    int n = 1 + (int)(test_rand(seed) % 4), h = (int)(test_rand(seed) % 3), i;
    double r = test_rand(seed) % 4 ? 40 : 3;
    size_t len = (size_t)snprintf(text, size, "EYE %.3f %.3f %.3f\nLOOKAT 0 0 0\nLIGHT 6 -4 9\n",
                                  test_uniform(seed, -r, r), test_uniform(seed, -r, r), test_uniform(seed, -r, r));
    for (i = 0; i < n + h; i++) {
        if (i >= n)
            len += (size_t)snprintf(text + len, size - len, "HALFSPACE P%d ROTATE AXIS %.3f %.3f 1 %.3f -\n"
                                    " TRANSLATE 0 0 %.3f\n", i, test_uniform(seed, -1, 1),
                                    test_uniform(seed, -1, 1), test_uniform(seed, -180, 180),
                                    test_uniform(seed, -6, -1));
        else if (test_rand(seed) % 2)
            len += (size_t)snprintf(text + len, size - len, "SPHERE P%d %.3f -\n TRANSLATE %.3f %.3f %.3f\n", i,
                                    test_uniform(seed, 0.2, 2), test_uniform(seed, -4, 4),
                                    test_uniform(seed, -4, 4), test_uniform(seed, -4, 4));
        else
            len += (size_t)snprintf(text + len, size - len, "BLOCK P%d %.3f %.3f %.3f -\n ROTATE AXIS %.3f %.3f 1"
                                    " %.3f -\n TRANSLATE %.3f %.3f %.3f\n", i, test_uniform(seed, 0.2, 3),
                                    test_uniform(seed, 0.2, 3), test_uniform(seed, 0.2, 3),
                                    test_uniform(seed, -1, 1), test_uniform(seed, -1, 1),
                                    test_uniform(seed, -180, 180), test_uniform(seed, -4, 4),
                                    test_uniform(seed, -4, 4), test_uniform(seed, -4, 4));
    }
    for (i = 0; i < n + h; i++)
        len += (size_t)snprintf(text + len, size - len, "OBJECT P%d\n", i);
    assert_true(len < size);
    return tt_parse(text);
}

/* Lane m of a and lane k of b hold the same set-up, bit for bit. */
static int cscene_test_same_lane(const cscene_batch *a, int m, const cscene_batch *b, int k)
{
    int i;
    for (i = 0; i < 3; i++)
        if (memcmp(&a->u[i][m], &b->u[i][k], sizeof(double)) || memcmp(&a->o[i][m], &b->o[i][k], sizeof(double))
            || memcmp(&a->rcp[i][m], &b->rcp[i][k], sizeof(double)))
            return 0;
    return a->st[m] == b->st[k] && !memcmp(&a->t0[m], &b->t0[k], sizeof(double));
}

/* The nearest hit along (o, d): 1 and *h, or 0. */
static int cscene_test_hit(const cscene *cs, arena *ar, const double *o, const double *d, csg_hit *h)
{
    prim_ray r;
    geom_stats gs;
    memset(&gs, 0, sizeof gs);
    prim_ray_set(&r, vec3_from_d(o), vec3_from_d(d), -1, 0);
    return f64_csg_intersect(&cs->tree, &r, num_from_i(GEOM_TBIG), ar, &gs, h);
}

/* What the lanes of test_cscene_primary_batch_skips_nothing came to. */
typedef struct cscene_test_counts { long rays, hits, far, none, bad; } cscene_test_counts;

/* Directions for 1 to CSCENE_BATCH lanes of b, mostly towards the scene
 * from cs's eye, at lengths from 10^-3 to 10^3; 1 in 32 zero, 1 in 32 with
 * an infinite and 1 in 32 with a NaN component. Returns their number. */
static int cscene_test_directions(const cscene *cs, uint64_t *seed, cscene_batch *b)
{
    int n = 1 + (int)(test_rand(seed) % CSCENE_BATCH), m, i;
    for (m = 0; m < n; m++) {
        uint64_t kind = test_rand(seed) % 32;
        double len = pow(10, test_uniform(seed, -3, 3));
        for (i = 0; i < 3; i++)
            b->d[i][m] = (test_uniform(seed, -0.6, 0.6) - cs->eye[i] / (1 + dmath_len3(cs->eye))) * len;
        if (kind == 0)
            b->d[0][m] = b->d[1][m] = b->d[2][m] = 0;
        else if (kind == 1)
            b->d[(int)(test_rand(seed) % 3)][m] = HUGE_VAL;
        else if (kind == 2)
            b->d[(int)(test_rand(seed) % 3)][m] = NAN;
    }
    return n;
}

/* Checks lane m of all, set up from after = 0 (see the test below); text
 * names the deck in a failure. */
static void cscene_test_lane(const cscene *cs, arena *ar, const cscene_batch *all, int m, const char *text,
                             cscene_test_counts *c)
{
    cscene_batch one;
    double o[3], u[3], l;
    csg_hit he = {0}, hs = {0};
    int from_eye, from_start, i;
    for (i = 0; i < 3; i++)
        one.d[i][0] = all->d[i][m];
    f64_cscene_primary_batch(cs, &one, 1, 0);
    if (!cscene_test_same_lane(all, m, &one, 0))
        fail_msg("lane %d differs from its batch of one\n%s", m, text);
    l = sqrt(one.d[0][0] * one.d[0][0] + one.d[1][0] * one.d[1][0] + one.d[2][0] * one.d[2][0]);
    if (!(l > 0 && isfinite(l))) {
        assert_int_equal(all->st[m], CSCENE_BAD);
        c->bad++;
        return;
    }
    assert_true(all->st[m] == CSCENE_RAY || all->st[m] == CSCENE_NONE);
    for (i = 0; i < 3; i++)
        u[i] = all->u[i][m];
    assert_true(fabs(dmath_len3(u) - 1) < 1e-15);
    from_eye = cscene_test_hit(cs, ar, cs->eye, u, &he);
    if (all->st[m] == CSCENE_NONE) {
        if (from_eye)
            fail_msg("a ray given no start meets primitive %d at %.17g\n%s", he.prim, num_to_d(he.t), text);
        c->none++;
        return;
    }
    c->rays++;
    assert_true(all->t0[m] >= 0);
    for (i = 0; i < 3; i++) {
        o[i] = cs->eye[i] + all->t0[m] * u[i];
        assert_memory_equal(&o[i], &all->o[i][m], sizeof o[i]);
    }
    from_start = cscene_test_hit(cs, ar, o, u, &hs);
    if (!from_eye && from_start && all->t0[m] + num_to_d(hs.t) > GEOM_TBIG / 2) {
        c->far++;                 /* beyond what a ray from the eye sees */
        return;
    }
    if (from_eye != from_start || (from_eye && (he.prim != hs.prim || he.face != hs.face
        || fabs(all->t0[m] + num_to_d(hs.t) - num_to_d(he.t)) > 1e-9 * (1 + num_to_d(he.t)))))
        fail_msg("from the eye %d (primitive %d face %d t %.17g), from t0 %.17g %d (primitive %d face %d "
                 "t %.17g)\n%s", from_eye, he.prim, he.face, num_to_d(he.t), all->t0[m], from_start, hs.prim,
                 hs.face, num_to_d(hs.t), text);
    c->hits += from_eye;
    f64_cscene_primary_batch(cs, &one, 1, all->t0[m] + 2);
    assert_true(one.st[0] != CSCENE_RAY || one.t0[0] >= all->t0[m] + 2);
}

/* One random deck and view, and 8 batches of directions from its eye. */
static void cscene_test_view(uint64_t *seed, cscene_test_counts *c)
{
    char text[2048];
    scene *sc = cscene_test_view_deck(seed, text, sizeof text);
    cscene *cs = cscene_test_compile(sc);
    arena ar;
    int b, m, n;
    assert_int_equal(arena_init(&ar, f64_csg_arena_bytes(&cs->tree)), 0);
    for (b = 0; b < 8; b++) {
        cscene_batch all;
        n = cscene_test_directions(cs, seed, &all);
        f64_cscene_primary_batch(cs, &all, n, 0);
        for (m = 0; m < n; m++)
            cscene_test_lane(cs, &ar, &all, m, text, c);
    }
    arena_free(&ar);
    f64_cscene_free(cs);
    scene_free(sc);
}

/* Primary rays set up in batches (cscene_primary_batch), for 3,000 random
 * decks and views and 8 batches of 1 to CSCENE_BATCH directions each (some
 * zero, infinite or NaN): every lane is what a batch of that one direction
 * gives, bit for bit, wherever it lies in the batch (the vectorised loops
 * and their scalar ends agree); a direction that is zero or not finite is
 * refused and every other made unit; the start is eye + t0 u with t0 >= 0;
 * and nothing is skipped: the ray from the start meets the surface the ray
 * from the eye meets first (the same primitive and face, at the parameter
 * less t0; a hit farther than GEOM_TBIG / 2 from the eye, which a ray from
 * the eye cannot see, is only counted), and a ray given no start meets
 * nothing. Started again beyond its start (after > 0), a lane starts no
 * sooner. */
static void test_cscene_primary_batch_skips_nothing(void **state)
{
    uint64_t seed = test_seed("test_cscene_primary_batch_skips_nothing");
    cscene_test_counts c = {0, 0, 0, 0, 0};
    int deck;
    (void)state;
    for (deck = 0; deck < 3000; deck++)
        cscene_test_view(&seed, &c);
    printf("primary batch: %ld rays started (%ld hit near, %ld far), %ld given no start, %ld refused\n",
           c.rays, c.hits, c.far, c.none, c.bad);
    assert_true(c.hits > 10000 && c.none > 1000 && c.bad > 1000);
}

/* A half-space the eye is inside whose plane lies beyond the binary64
 * range (2^28 normalised units): the primitive's plane is moved to the
 * range's end, in binary64 in the one storage its planes in double share,
 * while the plane primary rays are started from keeps the placed offset. */
static void test_cscene_far_halfspace_moved(void **state)
{
    scene *sc = tt_parse("EYE 0.0004 -0.0006 0.0003\nLOOKAT 0 0 0\nUP 0 0 1\nLIGHT 0 0 0.001\n"
                         "SPHERE BALL 0.0001\nHALFSPACE CEIL TRANSLATE 0 0 1e6\n"
                         "OBJECT BALL\nOBJECT CEIL\n");
    cscene *cs = cscene_test_compile(sc);
    const prim *p = &cs->prims[1];
    (void)state;
    assert_int_equal(p->kind, PRIM_HALFSPACE);
    assert_ptr_equal((const void *)p->pl_d, (const void *)p->pl);
    assert_true(p->pl[0].d > 2.6e8 && p->pl[0].d < 2.7e8);
    assert_int_equal(cs->nplanes, 1);
    assert_true(cs->planes[0][3] > 1e10);
    assert_true(cs->planes[0][2] == p->pl[0].n.z);
    f64_cscene_free(cs);
    scene_free(sc);
}

/* 1 when the compile gave primitives a and b one set of curved-face data
 * (prim_share): b then intersects through a's placement. */
static int cscene_test_shared(const cscene *cs, const scene *sc, const char *a, const char *b)
{
    const prim *p = &cs->prims[tt_find_prim(sc, a)], *q = &cs->prims[tt_find_prim(sc, b)];
    return !memcmp(&p->org, &q->org, sizeof p->org) && !memcmp(&p->minv_s, &q->minv_s, sizeof p->minv_s);
}

/* 300 random rigid placements of one cluster: a cylinder, the same
 * cylinder turned end for end, the same through its other axis order
 * (three bores through one centre, which are not the same solid), a cone
 * and its copy, a sphere and its turned copy, a disc 1,000 times wider
 * than thick and its turned copy. Every copy shares its original's
 * curved-face data; the bores share nothing with each other. */
static void test_cscene_same_solids_shared(void **state)
{
    uint64_t seed = test_seed("test_cscene_same_solids_shared");
    int n;
    (void)state;
    for (n = 0; n < 300; n++) {
        static const char *const body[][3] = {
            {"CYLINDER", "C1", "1 2 TRANSLATE 0 0 -1"}, {"CYLINDER", "C2", "1 2 ROTATE X 180 TRANSLATE 0 0 1"},
            {"CYLINDER", "BX", "1 2 TRANSLATE 0 0 -1 ROTATE Y 90"},
            {"CYLINDER", "BY", "1 2 TRANSLATE 0 0 -1 ROTATE X 90"},
            {"CONE", "K1", "1 0.5 2"}, {"CONE", "K2", "1 0.5 2 ROTATE Z 77"},
            {"SPHERE", "S1", "1"}, {"SPHERE", "S2", "1 ROTATE AXIS 1 2 3 40"},
            {"CYLINDER", "D1", "10 0.01"},
            {"CYLINDER", "D2", "10 0.01 ROTATE X 180 TRANSLATE 0 0 0.01"}};
        char deck[4096], tail[256];
        size_t len, i;
        scene *sc;
        cscene *cs;
        tt_random_tail(&seed, tail, sizeof tail);
        len = (size_t)snprintf(deck, sizeof deck, "EYE 9 -9 7\nLOOKAT 0 0 0\nLIGHT 0 0 20\n");
        for (i = 0; i < sizeof body / sizeof body[0]; i++)
            len += (size_t)snprintf(deck + len, sizeof deck - len, "%s %s %s %s\nOBJECT %s\n", body[i][0],
                                    body[i][1], body[i][2], tail, body[i][1]);
        assert_true(len < sizeof deck);
        sc = tt_parse(deck);
        cs = cscene_test_compile(sc);
        assert_true(cscene_test_shared(cs, sc, "C1", "C2"));
        assert_true(cscene_test_shared(cs, sc, "K1", "K2"));
        assert_true(cscene_test_shared(cs, sc, "S1", "S2"));
        assert_true(cscene_test_shared(cs, sc, "D1", "D2"));
        assert_false(cscene_test_shared(cs, sc, "C1", "BX"));
        assert_false(cscene_test_shared(cs, sc, "C1", "BY"));
        assert_false(cscene_test_shared(cs, sc, "BX", "BY"));
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

/* The fields of two compiled primitives and their storage that the compile
 * writes, bit for bit (not the pointers). */
static int cscene_test_alike(const prim *a, const prim *b, double ra, double rb)
{
    int k;
    if (a->kind != b->kind || a->id != b->id || a->attr != b->attr || a->bounded != b->bounded
        || a->nplanes != b->nplanes || a->fast != b->fast || memcmp(&a->bc, &b->bc, sizeof a->bc)
        || memcmp(&a->br, &b->br, sizeof a->br) || memcmp(&a->org, &b->org, sizeof a->org)
        || memcmp(&a->minv_s, &b->minv_s, sizeof a->minv_s) || memcmp(&a->smin, &b->smin, sizeof a->smin)
        || memcmp(&a->inv_smin, &b->inv_smin, sizeof a->inv_smin)
        || memcmp(&a->cone_a, &b->cone_a, sizeof a->cone_a) || memcmp(&a->cone_k, &b->cone_k, sizeof a->cone_k)
        || memcmp(a->fr->lin, b->fr->lin, sizeof *a->fr->lin)
        || memcmp(a->fr->org_d, b->fr->org_d, sizeof a->fr->org_d) || memcmp(&ra, &rb, sizeof ra))
        return 0;
    for (k = 0; k < a->nplanes; k++)
        if (memcmp(a->pl_d[k], b->pl_d[k], sizeof a->pl_d[k]) || memcmp(&a->pl[k], &b->pl[k], sizeof a->pl[k]))
            return 0;
    return 1;
}

/* 200 random decks, each a part of every bounded kind under random
 * transforms (every other deck turned by right angles only), placed seven
 * times: four times moved only (twins of the
 * first placement), once turned, once mirrored, once scaled. Every
 * primitive compiled with its first twin's linear results (prim_twin, as
 * the scene compiler does) equals the one compiled on its own, bit for bit,
 * and the twins are found: three of every four moved placements. */
static void test_cscene_twins_compile_alike(void **state)
{
    uint64_t seed = test_seed("test_cscene_twins_compile_alike");
    int deck;
    (void)state;
    for (deck = 0; deck < 200; deck++) {
        static const char *const body[][2] = {
            {"BLOCK", "1 2 0.5"}, {"SPHERE", "0.8"}, {"CYLINDER", "0.4 2.5"}, {"CONE", "0.7 0.2 1.5"}};
        static const char *const place[7] = {"", "", "", "", "ROTATE Z 90", "SCALE -1 1 1", "SCALE 2"};
        char text[8192], tail[256];
        size_t len = 0, n, found = 0;
        scene *sc;
        cscene *cs;
        prim_twin tw;
        prim *ref, *got;
        prim_plane (*pl)[6];
        double (*pld)[6][4], *rad;
        prim_frame *fr;
        prim_lin *lin;
        diag err;
        int i;
        len += (size_t)snprintf(text + len, sizeof text - len, "EYE 30 -40 20\nLOOKAT 0 0 0\nLIGHT 0 0 50\n");
        for (i = 0; i < 4; i++) {
            if (deck % 2)       /* turned by right angles: minv_s's column shortcuts */
                snprintf(tail, sizeof tail, "ROTATE %c 90 SCALE %.4f TRANSLATE %.4f 0 %.4f", "XYZ"[i % 3],
                         test_uniform(&seed, 0.5, 2), test_uniform(&seed, -2, 2), test_uniform(&seed, -2, 2));
            else
                tt_random_tail(&seed, tail, sizeof tail);
            len += (size_t)snprintf(text + len, sizeof text - len, "%s Q%d %s %s\n", body[i][0], i, body[i][1], tail);
        }
        len += (size_t)snprintf(text + len, sizeof text - len, "UNION P Q0 Q1 Q2 Q3\n");
        for (i = 0; i < 7; i++)
            len += (size_t)snprintf(text + len, sizeof text - len, "OBJECT P %s TRANSLATE %.4f %.4f %.4f\n",
                                    place[i], test_uniform(&seed, -9, 9), test_uniform(&seed, -9, 9),
                                    test_uniform(&seed, -9, 9));
        assert_true(len < sizeof text);
        sc = tt_parse(text);
        cs = cscene_test_compile(sc);
        n = sc->nprims;
        ref = test_malloc(2 * n * sizeof *ref);
        got = ref + n;
        pl = test_malloc(2 * n * sizeof *pl);
        pld = test_malloc(2 * n * sizeof *pld);
        fr = test_malloc(2 * n * sizeof *fr);
        lin = test_malloc(2 * n * sizeof *lin);
        rad = test_malloc(2 * n * sizeof *rad);
        assert_int_equal(prim_twin_init(&tw), 0);
        diag_init(&err);
        for (i = 0; i < (int)n; i++) {
            const scene_prim *sp = &sc->prims[i];
            prim_twin_entry *e = prim_twin_at(&tw, sc->prims, sp);
            int known = e->index != PRIM_TWIN_NONE;
            assert_int_equal(f64_prim_compile(sp, i, &cs->nm, pl[i], pld[i], &fr[i], &lin[i], NULL, &rad[i], &ref[i],
                                              "test", &err), 0);
            rad[n + i] = known ? e->note : 0;
            assert_int_equal(f64_prim_compile(sp, i, &cs->nm, pl[n + i], pld[n + i], &fr[n + i], &lin[n + i],
                                              known ? &got[e->index] : NULL, &rad[n + i], &got[i], "test", &err), 0);
            /* a twin shares its first twin's linear part, else has its own */
            assert_true(got[i].fr->lin == (known ? got[e->index].fr->lin : &lin[n + i]));
            if (!known)
                assert_int_equal(prim_twin_add(&tw, sc->prims, e, (size_t)i, rad[n + i]), 0);
            found += (size_t)known;
            assert_true(cscene_test_alike(&ref[i], &got[i], rad[i], rad[n + i]));
        }
        assert_true(found >= 12);
        prim_twin_free(&tw);
        test_free(ref);
        test_free(pl);
        test_free(pld);
        test_free(fr);
        test_free(lin);
        test_free(rad);
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

/* Twins are primitives whose kind, dimensions and linear part agree bit
 * for bit: a zero of the other sign, or the other kind, is none. */
static void test_cscene_twins_bit_for_bit(void **state)
{
    scene_prim p[4];
    scene_shape sh[4];
    prim_twin tw;
    prim_twin_entry *e;
    int i;
    (void)state;
    memset(p, 0, sizeof p);
    memset(sh, 0, sizeof sh);
    for (i = 0; i < 4; i++) {
        sh[i].kind = PRIM_CYLINDER;
        sh[i].dim[0] = 1;
        sh[i].dim[1] = 2;
        p[i].shape = &sh[i];
        p[i].world_from_object[0] = p[i].world_from_object[5] = p[i].world_from_object[10] = 1;
    }
    p[1].world_from_object[3] = 7;         /* moved: a twin */
    p[2].world_from_object[1] = -0.0;      /* the other zero: none */
    sh[3].kind = PRIM_CONE;
    assert_int_equal(prim_twin_init(&tw), 0);
    e = prim_twin_at(&tw, p, &p[0]);
    assert_int_equal(e->index, PRIM_TWIN_NONE);
    assert_int_equal(prim_twin_add(&tw, p, e, 0, 0.5), 0);
    assert_int_equal(prim_twin_at(&tw, p, &p[1])->index, 0);
    assert_int_equal(prim_twin_at(&tw, p, &p[2])->index, PRIM_TWIN_NONE);
    e = prim_twin_at(&tw, p, &p[3]);
    assert_int_equal(e->index, PRIM_TWIN_NONE);
    /* an index the entries cannot hold is not entered (nor read) */
    assert_int_equal(prim_twin_add(&tw, p, e, (size_t)PRIM_TWIN_NONE, 0.25), 0);
    assert_int_equal(prim_twin_at(&tw, p, &p[3])->index, PRIM_TWIN_NONE);
    prim_twin_free(&tw);
}

/* The index grows with the sets entered: after 1,000 sets (the table
 * doubled six times) each set is still found, with its note, and a
 * primitive of none is not. */
static void test_cscene_twins_index_grows(void **state)
{
    enum { N = 1000 };
    scene_prim *p = test_calloc(N + 1, sizeof *p);
    scene_shape *sh = test_calloc(N + 1, sizeof *sh);
    prim_twin tw;
    int i;
    (void)state;
    for (i = 0; i <= N; i++) {
        sh[i].kind = PRIM_SPHERE;
        sh[i].dim[0] = 1 + i / 64.0;
        p[i].shape = &sh[i];
        p[i].world_from_object[0] = p[i].world_from_object[5] = p[i].world_from_object[10] = 1;
    }
    assert_int_equal(prim_twin_init(&tw), 0);
    for (i = 0; i < N; i++) {
        prim_twin_entry *e = prim_twin_at(&tw, p, &p[i]);
        assert_int_equal(e->index, PRIM_TWIN_NONE);
        assert_int_equal(prim_twin_add(&tw, p, e, (size_t)i, i * 0.5), 0);
    }
    assert_true(tw.mask + 1 >= 2 * N && tw.used == N);
    for (i = 0; i < N; i++) {
        const prim_twin_entry *e = prim_twin_at(&tw, p, &p[i]);
        assert_int_equal(e->index, i);
        assert_true(e->note == i * 0.5);
    }
    assert_int_equal(prim_twin_at(&tw, p, &p[N])->index, PRIM_TWIN_NONE);
    prim_twin_free(&tw);
    test_free(p);
    test_free(sh);
}

/* The index closes where twins are rare: PRIM_TWIN_TRIAL distinct
 * primitives are each looked up and entered, and the next lookup answers
 * NULL, its table freed; where one primitive in eight is a twin of the
 * one before it, the index stays open and finds every such twin. */
static void test_cscene_twins_index_closes(void **state)
{
    enum { N = 2 * PRIM_TWIN_TRIAL };
    scene_prim *p = test_calloc(N + 1, sizeof *p);
    scene_shape *sh = test_calloc(N + 1, sizeof *sh);
    prim_twin tw;
    int i, pass;
    (void)state;
    for (pass = 0; pass < 2; pass++) {
        size_t found = 0;
        for (i = 0; i <= N; i++) {
            /* pass 1: primitive 8k + 7 repeats primitive 8k + 6 */
            int v = pass && i % 8 == 7 ? i - 1 : i;
            memset(&p[i], 0, sizeof p[i]);
            sh[i].kind = PRIM_SPHERE;
            sh[i].dim[0] = 1 + v / 1024.0;
            p[i].shape = &sh[i];
            p[i].world_from_object[0] = p[i].world_from_object[5] = p[i].world_from_object[10] = 1;
            p[i].world_from_object[3] = i;
        }
        assert_int_equal(prim_twin_init(&tw), 0);
        for (i = 0; i < N; i++) {
            prim_twin_entry *e = prim_twin_at(&tw, p, &p[i]);
            if (!pass && i >= PRIM_TWIN_TRIAL) {
                assert_null(e);
                assert_null(tw.e);
                continue;
            }
            assert_non_null(e);
            if (e->index != PRIM_TWIN_NONE) {
                assert_int_equal(e->index, i - 1);
                found++;
                continue;
            }
            assert_int_equal(prim_twin_add(&tw, p, e, (size_t)i, 0), 0);
        }
        assert_int_equal(found, pass ? N / 8 : 0);
        prim_twin_free(&tw);
        prim_twin_free(&tw);              /* closed or freed: a no-op */
    }
    test_free(p);
    test_free(sh);
}

/* The compiled tree of object k, pre-order, into out: each operator's
 * letter and each leaf's primitive name. */
static void cscene_test_shape(const cscene *cs, const scene *sc, int ni, char *out, size_t cap)
{
    const csg_node *nd = &cs->tree.nodes[ni];
    size_t len = strlen(out);
    if (nd->op == CSG_LEAF) {
        snprintf(out + len, cap - len, "%s ", sc->prims[csg_leaf_prim(nd)].shape->name);
        return;
    }
    snprintf(out + len, cap - len, "%c(", "LUID"[nd->op]);
    cscene_test_shape(cs, sc, (int)nd->left, out, cap);
    cscene_test_shape(cs, sc, nd->right, out, cap);
    len = strlen(out);
    snprintf(out + len, cap - len, ") ");
}

/* 60 copies of csg81's part (a block meeting a sphere, minus three
 * bores; the centres of each operator's operands coincide) at random
 * turns, scales and places, the block and the sphere written in either
 * order: each compiles to the same tree, its operands in the deck's
 * order but for the sphere, which comes second. Ordered by the rounding
 * of their centres, copies split between the two orders of block and
 * sphere, and only the sphere second takes csg_diff_sphere. */
static void test_cscene_copies_compile_alike(void **state)
{
    uint64_t seed = test_seed("test_cscene_copies_compile_alike");
    static const char *const inter[2] = {"CUBE BALL", "BALL CUBE"};
    static char text[16384];
    int order;
    (void)state;
    for (order = 0; order < 2; order++) {
        size_t len = 0;
        scene *sc;
        cscene *cs;
        char got[256];
        int k;
        len += (size_t)snprintf(text + len, sizeof text - len,
                                "EYE 30 -40 20\nLOOKAT 0 0 0\nLIGHT 0 0 50\n"
                                "BLOCK CUBE 2 2 2 TRANSLATE -1 -1 -1\nSPHERE BALL 1.35\n"
                                "CYLINDER BORE 0.5 3 TRANSLATE 0 0 -1.5\nINTER ROUND %s\n"
                                "DIFF PART ROUND BORE ROTATE Y 90 BORE ROTATE X 90 BORE\n", inter[order]);
        for (k = 0; k < 60; k++)
            len += (size_t)snprintf(text + len, sizeof text - len,
                                    "OBJECT PART SCALE %.9f ROTATE X %.4f ROTATE Y %.4f -\n"
                                    "  ROTATE Z %.4f TRANSLATE %.4f %.4f %.4f\n",
                                    test_uniform(&seed, 0.2, 3), test_uniform(&seed, 0, 360),
                                    test_uniform(&seed, 0, 360), test_uniform(&seed, 0, 360),
                                    test_uniform(&seed, -90, 90), test_uniform(&seed, -90, 90),
                                    test_uniform(&seed, -9, 9));
        assert_true(len < sizeof text);
        sc = tt_parse(text);
        cs = cscene_test_compile(sc);
        assert_int_equal(cs->tree.nobjects, 60);
        assert_int_equal(cs->tree.ninst, 0);
        for (k = 0; k < 60; k++) {
            assert_true(cs->tree.objects[k] >= 0);
            got[0] = 0;
            cscene_test_shape(cs, sc, cs->tree.objects[k], got, sizeof got);
            if (strcmp(got, "D(I(CUBE BALL ) U(BORE U(BORE BORE ) ) ) "))
                fail_msg("%s: object %d compiles to %s", inter[order], k, got);
        }
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

/* A thread's kept map (cscene_map_memo) answers as a map formed afresh:
 * over 500 random decks, the surface at each primitive's bounding centre,
 * asked in a random order of primitives and faces with one memo kept
 * throughout, equals bit for bit the surface asked with an empty memo. */
static void test_cscene_map_memo_as_fresh(void **state)
{
    uint64_t seed = test_seed("test_cscene_map_memo_as_fresh");
    cscene_map_memo kept = {0};
    int deck, k;
    (void)state;
    for (deck = 0; deck < 500; deck++) {
        char text[2048];
        scene *sc = cscene_test_deck(&seed, text, sizeof text);
        cscene *cs = cscene_test_compile(sc);
        memset(&kept, 0, sizeof kept);
        for (k = 0; k < 12; k++) {
            int pi = (int)(test_rand(&seed) % cs->nprims), face = (int)(test_rand(&seed) % 3);
            cscene_map_memo fresh = {0};
            geom_surface a, b;
            memset(&a, 0, sizeof a);
            memset(&b, 0, sizeof b);
            f64_cscene_surface(cs, pi, face, cs->prims[pi].bc, 1, &kept, &a);
            f64_cscene_surface(cs, pi, face, cs->prims[pi].bc, 1, &fresh, &b);
            if (memcmp(&a, &b, sizeof a) || kept.prim != pi + 1)
                fail_msg("deck %d, ask %d: primitive %d face %d differs with the kept map\n%s", deck, k, pi, face,
                         text);
        }
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cscene_box_from_extreme_corners),
        cmocka_unit_test(test_cscene_bounding_radius_from_all_corners),
        cmocka_unit_test(test_cscene_object_hull),
        cmocka_unit_test(test_cscene_primary_batch_skips_nothing),
        cmocka_unit_test(test_cscene_far_halfspace_moved),
        cmocka_unit_test(test_cscene_same_solids_shared),
        cmocka_unit_test(test_cscene_twins_compile_alike),
        cmocka_unit_test(test_cscene_twins_bit_for_bit),
        cmocka_unit_test(test_cscene_twins_index_grows),
        cmocka_unit_test(test_cscene_twins_index_closes),
        cmocka_unit_test(test_cscene_node_boxes_rounded_outwards),
        cmocka_unit_test(test_cscene_copies_compile_alike),
        cmocka_unit_test(test_cscene_map_memo_as_fresh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
