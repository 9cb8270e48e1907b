/* test_cscene — the scene compiler's normalisation (src/trace/cscene.c):
 * the bounding box it takes from each primitive's extreme corners equals,
 * bit for bit, the box of all eight corners formed one by one. Checked in
 * the f64 build; the normalisation is double in every mode. */
#define NUM_MODE f64
#define NUM_MODE_f64
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "trace/cscene.h"
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
        const double *m = sp->world_from_object, *d = sp->dim;
        double c[3], l[3], h[3] = {1, 1, 1};
        switch (sp->kind) {
        case PRIM_SPHERE:   c[0] = c[1] = c[2] = d[0]; l[0] = l[1] = l[2] = -1; break;
        case PRIM_CYLINDER: c[0] = c[1] = d[0]; c[2] = d[1]; l[0] = l[1] = -1; l[2] = 0; break;
        case PRIM_CONE:     c[0] = c[1] = d[0] > d[1] ? d[0] : d[1]; c[2] = d[2];
                            l[0] = l[1] = -1; l[2] = 0; break;
        case PRIM_BLOCK:    c[0] = d[0]; c[1] = d[1]; c[2] = d[2]; l[0] = l[1] = l[2] = 0; break;
        default: continue;
        }
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

/* 6,000 decks of one to three primitives of every bounded kind, placed by
 * quarter turns (exact zeros in the matrix), other turns, negative and
 * uneven scales and translations that put faces on the deck's planes
 * (boxes touching 0, where corners may differ in the sign of zero): the
 * compiled normalisation equals the one from all eight corners. */
static void test_cscene_box_from_extreme_corners(void **state)
{
    static const char *const kind[4] = {"SPHERE P%d %.3f", "CYLINDER P%d %.3f %.3f",
                                        "CONE P%d %.3f %.3f %.3f", "BLOCK P%d %.3f %.3f %.3f"};
    uint64_t seed = test_seed("test_cscene_box_from_extreme_corners");
    int deck;
    (void)state;
    for (deck = 0; deck < 6000; deck++) {
        char text[2048];
        size_t len = (size_t)snprintf(text, sizeof text, "EYE 30 -40 30\nLOOKAT 0 0 0\nLIGHT 6 -4 9\n");
        int n = 1 + (int)(test_rand(&seed) % 3), i, t;
        scene *sc;
        cscene *cs = NULL;
        geom_norm want;
        diag err;
        for (i = 0; i < n; i++) {
            int k = (int)(test_rand(&seed) % 4);
            double a = 0.125 + cscene_test_num(&seed, 0, 3), b = 0.125 + cscene_test_num(&seed, 0, 3);
            double c = 0.125 + cscene_test_num(&seed, 0, 3);
            len += (size_t)snprintf(text + len, sizeof text - len, kind[k], i, a, k == 2 ? 0.0 : b, c);
            for (t = (int)(test_rand(&seed) % 4); t > 0; t--) {
                uint64_t r = test_rand(&seed) % 5;
                if (r == 0)
                    len += (size_t)snprintf(text + len, sizeof text - len, " -\n ROTATE %c %d",
                                            "XYZ"[test_rand(&seed) % 3], 90 * (int)(test_rand(&seed) % 4));
                else if (r == 1)
                    len += (size_t)snprintf(text + len, sizeof text - len, " -\n ROTATE AXIS %.3f %.3f 1 %.3f",
                                            cscene_test_num(&seed, -2, 2), cscene_test_num(&seed, -2, 2),
                                            cscene_test_num(&seed, -180, 180));
                else if (r == 2)
                    len += (size_t)snprintf(text + len, sizeof text - len, " -\n SCALE %.3f %.3f %.3f",
                                            test_rand(&seed) % 2 ? -1.5 : 0.75, 0.5 + cscene_test_num(&seed, 0, 2),
                                            -0.25 - cscene_test_num(&seed, 0, 2));
                else
                    len += (size_t)snprintf(text + len, sizeof text - len, " -\n TRANSLATE %.3f %.3f %.3f",
                                            cscene_test_num(&seed, -5, 5), cscene_test_num(&seed, -5, 5),
                                            cscene_test_num(&seed, -5, 5));
            }
            len += (size_t)snprintf(text + len, sizeof text - len, "\nOBJECT P%d\n", i);
        }
        assert_true(len < sizeof text);
        sc = tt_parse(text);
        assert_non_null(sc);
        diag_init(&err);
        assert_int_equal(f64_cscene_compile(sc, &cs, &err), 0);
        cscene_test_norm(sc, &want);
        if (memcmp(&cs->nm, &want, sizeof want))
            fail_msg("deck %d: scale %.17g off %.17g %.17g %.17g, all corners give %.17g %.17g "
                     "%.17g %.17g\n%s", deck, cs->nm.scale, cs->nm.off[0], cs->nm.off[1],
                     cs->nm.off[2], want.scale, want.off[0], want.off[1], want.off[2], text);
        f64_cscene_free(cs);
        scene_free(sc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cscene_box_from_extreme_corners),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
