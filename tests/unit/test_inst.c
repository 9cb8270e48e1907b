/* test_inst — instances: which objects scene_inst_find takes for
 * translated or turned copies of an earlier one (model/scene_inst.h), and
 * that a scene traced through them answers as the same scene traced
 * object by object, in every mode: nearest hits, rays spawned from their
 * surfaces, shadow rays and single primitives' spans. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "model/scene_inst.h"
#include "util/mem.h"
#include "tracer_test.h"

/* The part of bench/peers/csg81.scene: a block meets a sphere, minus three
 * bores; the bores reach past the block, so its primitives' boxes are
 * wider (6 across) than the part's (2). */
#define INST_HEAD                                                              \
    "EYE     22 -30 20\nLOOKAT  0 0 -1\nUP      0 0 1\nFOV     40\n"          \
    "SIZE    64 48\nAMBIENT 0.12 0.12 0.12\nDEPTH   5\n"                       \
    "LIGHT  60 -50 90  INTENSITY 0.9\n"                                        \
    "ATTR BODY   COLOR 0.30 0.50 0.85  SPECULAR 0.3  EXPONENT 40\n"           \
    "ATTR BORE   COLOR 0.85 0.75 0.30\n"                                       \
    "ATTR FLOOR  COLOR 0.60 0.60 0.60  MIRROR 0.2\n"                           \
    "BLOCK    CUBE  2 2 2        TRANSLATE -1 -1 -1\n"                         \
    "SPHERE   BALL  1.35\n"                                                    \
    "CYLINDER BORE  0.5 3        TRANSLATE 0 0 -1.5\n"                         \
    "INTER    ROUND CUBE BALL\n"                                               \
    "DIFF     PART  ROUND ATTR BODY  BORE ATTR BORE ROTATE Y 90 -\n"          \
    "               BORE ATTR BORE ROTATE X 90  BORE ATTR BORE\n"             \
    "HALFSPACE GROUND  ATTR FLOOR  TRANSLATE 0 0 -1.01\n"

/* The instances of deck head + objects: their count, and *out. */
static int inst_find(const char *objects, scene_inst **out, scene **sc)
{
    char deck[4096];
    snprintf(deck, sizeof deck, "%s%s", INST_HEAD, objects);
    *sc = tt_parse(deck);
    assert_non_null(*sc);
    return scene_inst_find(*sc, 1e-9, 1e-3, out);
}

static void test_inst_translated_copy(void **state)
{
    scene *sc;
    scene_inst *si;
    (void)state;
    /* the copy 2.9 along x: its bores' boxes overlap the first part's, its
     * own box (the block's) keeps 0.9 away */
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART TRANSLATE 2.9 0.1 0\nOBJECT GROUND\n", &si, &sc), 1);
    assert_int_equal(si[0].master, -1);
    assert_int_equal(si[1].master, 0);
    assert_int_equal(si[2].master, -1);
    assert_int_equal(si[1].count, 5);
    assert_int_equal(si[1].dprim, 5);
    assert_int_equal(si[1].first, 5);
    assert_null(si[1].turn);
    assert_true(fabs(si[1].shift[0] - 2.9) < 1e-12 && fabs(si[1].shift[1] - 0.1) < 1e-12
                && fabs(si[1].shift[2]) < 1e-12);
    mem_free(si);
    scene_free(sc);
    /* a third copy takes the first for its master, not the second */
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART TRANSLATE 3.3 0 0\nOBJECT PART TRANSLATE 6.6 0 0\n",
                               &si, &sc), 2);
    assert_int_equal(si[2].master, 0);
    assert_int_equal(si[2].dprim, 10);
    mem_free(si);
    scene_free(sc);
}

/* A turned copy: the rotation and translation that carry the first part
 * onto it; a copy through the floor at an angle is one too. */
static void test_inst_turned_copy(void **state)
{
    static const double rz90[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    scene *sc;
    scene_inst *si;
    int k;
    (void)state;
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART ROTATE Z 90 TRANSLATE 5 0 0\n", &si, &sc), 1);
    assert_int_equal(si[1].master, 0);
    assert_non_null(si[1].turn);
    for (k = 0; k < 9; k++)
        assert_true(fabs(si[1].turn->rot[k] - rz90[k]) < 1e-12);
    assert_true(fabs(si[1].shift[0] - 5) < 1e-12 && fabs(si[1].shift[1]) < 1e-12 && fabs(si[1].shift[2]) < 1e-12);
    /* its box: the block's turned, met with the ball's (not the ball's
     * box of corners, sqrt(3) times wider) */
    assert_true(fabs(si[1].turn->lo[0] - 4) < 1e-9 && fabs(si[1].turn->hi[0] - 6) < 1e-9);
    mem_free(si);
    /* a primitive's linear part off by 5e-10 (the bore reaches 3 along
     * its axis: 1.5e-9, beyond tol), then by 2e-10 (6e-10, within) */
    sc->prims[7].world_from_object[2] += 5e-10;
    assert_int_equal(scene_inst_find(sc, 1e-9, 1e-3, &si), 0);
    sc->prims[7].world_from_object[2] -= 3e-10;
    assert_int_equal(scene_inst_find(sc, 1e-9, 1e-3, &si), 1);
    mem_free(si);
    scene_free(sc);
    /* through the floor's plane, no face near parallel to it */
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART ROTATE X 30 ROTATE Y 20 TRANSLATE 5 0 -0.5\n"
                               "OBJECT GROUND\n", &si, &sc), 1);
    assert_non_null(si[1].turn);
    mem_free(si);
    scene_free(sc);
    /* turned by a hair: no twins, a rotation all the same */
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART ROTATE Z 1e-14 TRANSLATE 5 0 0\n", &si, &sc), 1);
    assert_non_null(si[1].turn);
    mem_free(si);
    scene_free(sc);
}

static void test_inst_refused(void **state)
{
    static const char *const none[] = {
        /* boxes 0.0005 apart, within the gap of 0.001 */
        "OBJECT PART\nOBJECT PART TRANSLATE 2.0005 0 0\n",
        /* scaled, mirrored: no rotation */
        "OBJECT PART\nOBJECT PART SCALE 2 TRANSLATE 6 0 0\n",
        "OBJECT PART\nOBJECT PART SCALE 1 1 -1 TRANSLATE 6 0 0\n",
        /* the floor's plane through the copy, in the plane of faces of
         * its block, as placed or turned about the plane's normal */
        "OBJECT PART\nOBJECT PART TRANSLATE 5 0 -0.5\nOBJECT GROUND\n",
        "OBJECT PART\nOBJECT PART ROTATE Z 45 TRANSLATE 5 0 -0.5\nOBJECT GROUND\n",
        /* a sphere carved out of the floor's half-space around the copy:
         * that object's box, by its operators, would be empty */
        "DIFF CAVE GROUND BALL TRANSLATE 5 0 0\n"
        "OBJECT PART\nOBJECT PART TRANSLATE 5 0 0.5\nOBJECT CAVE\n",
        /* a half-space in the object itself */
        "OBJECT GROUND\nOBJECT GROUND TRANSLATE 5 0 0\n",
        /* one object only */
        "OBJECT PART\n",
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof none / sizeof none[0]; i++) {
        scene *sc;
        scene_inst *si = (scene_inst *)&si;
        int n = inst_find(none[i], &si, &sc);
        if (n != 0)
            fprintf(stderr, "case %zu: %d instances\n", i, n);
        assert_int_equal(n, 0);
        assert_null(si);
        scene_free(sc);
    }
}

/* A primitive of a copy whose translation strays by more than tol from its
 * object's: no instance; by less: one. */
static void test_inst_translation_tolerance(void **state)
{
    scene *sc;
    scene_inst *si;
    (void)state;
    assert_int_equal(inst_find("OBJECT PART\nOBJECT PART TRANSLATE 5 0 0\n", &si, &sc), 1);
    sc->prims[7].world_from_object[3] += 2e-9;
    mem_free(si);
    assert_int_equal(scene_inst_find(sc, 1e-9, 1e-3, &si), 0);
    sc->prims[7].world_from_object[3] -= 1.5e-9;
    assert_int_equal(scene_inst_find(sc, 1e-9, 1e-3, &si), 1);
    mem_free(si);
    /* a tree that takes in another's (which the compiler refuses): none */
    sc->nodes[sc->roots[1]].left = sc->roots[0];
    assert_int_equal(scene_inst_find(sc, 1e-9, 1e-3, &si), 0);
    scene_free(sc);
}

/* test_oracle's error bounds on a ray parameter t (deck units), by mode
 * (q16 q32 f32 f64 hfp32 hfp64): base (1 + |t| / 10) / |cos|, cos the
 * angle's between the ray and the normal, for a scene about 20 units
 * across; inst_grid's is about 110, so five times that here. */
static const double inst_base[TT_MODES] = {3e-4, 1e-8, 1e-5, 1e-11, 5e-5, 1e-11};

/* 1 when hits a and b of the ray along unit d agree: the same primitive,
 * face and crossing, at parameters within the mode's bound; -1 when a
 * lies within 3 degrees of grazing (ill-conditioned: not counted). */
static int inst_alike(const probe_hit *a, const probe_hit *b, const double *d, double base)
{
    double c = fabs(d[0] * a->n_solid[0] + d[1] * a->n_solid[1] + d[2] * a->n_solid[2]);
    if (c < 0.0523)
        return -1;
    return a->prim == b->prim && a->face == b->face && a->entering == b->entering
           && fabs(a->t - b->t) <= 5 * base * (1 + fabs(a->t) / 10) / c;
}

/* The grid of INST_SIDE x INST_SIDE parts over the floor, 3.3 apart,
 * as placed (turned 0) or each turned about x, y and z by its own angles
 * (turned 1; through the floor, where they reach it). In the reference
 * (ref 1) each part but the first has its bores slid along their axes by
 * a length of its own (k 1e-6, k = 1 .. 1088), so that none is an
 * instance and each is traced as its own: the bores' ends lie outside the
 * part (0.15 away), so the solids are the same. Otherwise every part but
 * the first is an instance, enough for the compiler to take them
 * (CSCENE_INST_MIN). */
#define INST_SIDE 33
static scene *inst_grid(int turned, int ref)
{
    size_t cap = sizeof INST_HEAD + 96 * INST_SIDE * INST_SIDE + 64, n, p;
    char *deck = malloc(cap);
    scene *sc;
    int i, j, k;
    assert_non_null(deck);
    n = (size_t)snprintf(deck, cap, "%s", INST_HEAD);
    for (i = 0; i < INST_SIDE; i++)
        for (j = 0; j < INST_SIDE; j++) {
            k = INST_SIDE * i + j;
            n += (size_t)snprintf(deck + n, cap - n, "OBJECT PART ROTATE X %d ROTATE Y %d ROTATE Z %d -\n"
                                  "  TRANSLATE %.2f %.2f 0\n", turned ? 37 * k % 360 : 0,
                                  turned ? 71 * k % 360 : 0, turned ? 113 * k % 360 : 0,
                                  3.3 * (i - INST_SIDE / 2), 3.3 * (j - INST_SIDE / 2));
        }
    snprintf(deck + n, cap - n, "OBJECT GROUND\n");
    sc = tt_parse(deck);
    free(deck);
    assert_non_null(sc);
    for (p = 5; ref && p < 5 * INST_SIDE * INST_SIDE; p++) {
        double *m = sc->prims[p].world_from_object, dz = 1e-6 * (double)(p / 5);
        if (sc->prims[p].shape->kind != PRIM_CYLINDER)
            continue;
        for (i = 0; i < 3; i++)
            m[4 * i + 3] += dz * m[4 * i + 2];
    }
    return sc;
}

static void inst_traced_alike(int turned, uint64_t seed)
{
    scene *sc[2];
    int m, k;
    for (k = 0; k < 2; k++)
        sc[k] = inst_grid(turned, k);
    for (m = 0; m < TT_MODES; m++) {
        const probe_ops *ops = tt_mode(m);
        void *cs[2];
        diag err;
        uint64_t rng = seed;
        int r, hits = 0, spawned = 0, shadows = 0, odd = 0, rays = 2000;
        for (k = 0; k < 2; k++) {
            diag_init(&err);
            if (ops->compile(sc[k], &cs[k], &err))
                diag_print(stderr, &err);
            assert_int_equal(err.status, 0);
        }
        if (turned)               /* some turned into the floor's plane */
            assert_true(ops->instances(cs[0]) >= 1024);
        else
            assert_int_equal(ops->instances(cs[0]), INST_SIDE * INST_SIDE - 1);
        assert_int_equal(ops->instances(cs[1]), 0);
        for (r = 0; r < rays; r++) {
            double o[3], a[3], d[3], d2[3], len = 0, len2 = 0;
            probe_hit h[2], g[2];
            int f[2], s[2], c, pi, e;
            /* from above the floor near a random part, at a point in its
             * box */
            pi = (int)(test_rand(&rng) % (INST_SIDE * INST_SIDE));
            a[0] = 3.3 * (pi / INST_SIDE - INST_SIDE / 2) + test_uniform(&rng, -1, 1);
            a[1] = 3.3 * (pi % INST_SIDE - INST_SIDE / 2) + test_uniform(&rng, -1, 1);
            a[2] = test_uniform(&rng, -1, 1);
            for (c = 0; c < 2; c++)
                o[c] = a[c] + test_uniform(&rng, -10, 10);
            o[2] = test_uniform(&rng, 1.5, 12);
            for (c = 0; c < 3; c++) {
                d[c] = a[c] - o[c];
                d2[c] = test_uniform(&rng, -1, 1);
                len += d[c] * d[c];
                len2 += d2[c] * d2[c];
            }
            for (c = 0; c < 3; c++) {
                d[c] /= sqrt(len);
                d2[c] /= sqrt(len2);
            }
            for (k = 0; k < 2; k++)
                f[k] = ops->hit(cs[k], o, d, &h[k]);
            if (f[0] != f[1]) {
                odd++;
                continue;
            }
            if (!f[0] || (e = inst_alike(&h[0], &h[1], d, inst_base[m])) < 0)
                continue;
            if (!e) {
                odd++;
                continue;
            }
            hits++;
            /* a ray spawned from the surface hit, either way from it:
             * outward it must not meet that surface again, inward it
             * finds its exit; and a shadow ray the same way */
            for (k = 0; k < 2; k++)
                s[k] = ops->respawn(cs[k], o, d, d2, &h[k], &g[k]);
            if (s[0] != s[1] || (s[0] == 1 && !inst_alike(&g[0], &g[1], d2, inst_base[m]))) {
                odd++;
                continue;
            }
            spawned += s[0] == 1;
            for (k = 0; k < 2; k++)
                s[k] = ops->shadow(cs[k], o, d, d2, 30);
            odd += s[0] != s[1];
            shadows += s[0] == 1;
            /* the span of the primitive hit, alone, from the ray's origin */
            {
                double t[2][2];
                int fc[2][2];
                for (k = 0; k < 2; k++)
                    s[k] = ops->prim_span(cs[k], h[0].prim, o, d, t[k], fc[k]);
                if (s[0] != s[1] || (s[0] && (fc[0][0] != fc[1][0] || fc[0][1] != fc[1][1]
                                              || fabs(t[0][0] - t[1][0]) > 1e-3 * (1 + fabs(t[0][0]))
                                              || fabs(t[0][1] - t[1][1]) > 1e-3 * (1 + fabs(t[0][1])))))
                    odd++;
            }
        }
        fprintf(stderr, "test_inst: %s %-5s %d instances, %d rays, %d hits, %d spawned rays hit, %d shadowed, "
                "%d answered otherwise\n", turned ? "turned" : "placed", ops->name, ops->instances(cs[0]), rays, hits,
                spawned, shadows, odd);
        assert_true(hits > rays / 2 && spawned > hits / 4 && shadows > 0);
        assert_true(odd <= rays / 200);
        for (k = 0; k < 2; k++)
            ops->free(cs[k]);
    }
    for (k = 0; k < 2; k++)
        scene_free(sc[k]);
}

static void test_inst_traced_alike(void **state)
{
    (void)state;
    inst_traced_alike(0, test_seed("test_inst_traced_alike"));
}

static void test_inst_turned_traced_alike(void **state)
{
    (void)state;
    inst_traced_alike(1, test_seed("test_inst_turned_traced_alike"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inst_translated_copy),
        cmocka_unit_test(test_inst_turned_copy),
        cmocka_unit_test(test_inst_refused),
        cmocka_unit_test(test_inst_translation_tolerance),
        cmocka_unit_test(test_inst_traced_alike),
        cmocka_unit_test(test_inst_turned_traced_alike),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
