/* test_stress — the stress decks in tests/decks rendered in every numeric
 * mode: touching objects keep their contact faces; far and narrow cameras,
 * far ground planes and thin plates are rendered within a stated error of
 * f64 or refused before rendering; valid decks render without a single
 * fixed-point overflow. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "tracer_test.h"
#include "util/mem.h"

static const render_ops *stress_mode(int m)
{
    static const render_ops *const all[4] = {&q16_render_ops, &q32_render_ops, &f32_render_ops,
                                             &f64_render_ops};
    return all[m];
}


static void stress_render(const scene *sc, const render_ops *ops, int w, render_fb *fb, render_stats *st)
{
    render_opts o = tt_render_opts(w, w, 2);
    diag err;
    diag_init(&err);
    assert_int_equal(render_scene(sc, ops, &o, fb, st, &err), 0);
}

/* Clear blocks resting on the floor, a block standing on one of them: the
 * floor fills the view, so no pixel may show the magenta background
 * through a contact face (green well under red and blue). */
static void test_stress_touching_objects_keep_contact_faces(void **state)
{
    scene *sc = tt_load("tests/decks/touching.scene");
    int m;
    assert_non_null(sc);
    (void)state;
    for (m = 0; m < 4; m++) {
        render_fb fb;
        render_stats st;
        long magenta = 0, i, n;
        stress_render(sc, stress_mode(m), 128, &fb, &st);
        n = (long)fb.img.width * fb.img.height;
        for (i = 0; i < n; i++) {
            const unsigned char *p = fb.img.px + 3 * i;
            if (p[1] < 0.4 * p[0] && p[1] < 0.4 * p[2])
                magenta++;
        }
        printf("# touching %s: %ld of %ld pixels show the background, %llu overflows\n",
               stress_mode(m)->name, magenta, n, st.fx_overflows);
        assert_true(st.rays_refracted > 1000);
        assert_int_equal(magenta, 0);
        assert_int_equal(st.fx_overflows, 0);
        render_fb_free(&fb);
    }
    scene_free(sc);
}



/* An eye 10,000 scene widths away and a 0.1-degree lens: every mode within
 * 0.3% of the pixels (over 8/255) of f64, without an overflow. */
static void test_stress_far_eye_and_narrow_lens(void **state)
{
    static const char *const decks[2] = {"tests/decks/far-eye.scene", "tests/decks/narrow-lens.scene"};
    int d, m;
    (void)state;
    for (d = 0; d < 2; d++) {
        scene *sc = tt_load(decks[d]);
        render_fb ref;
        render_stats st;
        assert_non_null(sc);
        stress_render(sc, &f64_render_ops, 256, &ref, &st);
        assert_int_equal(st.range_cut, 0);
        for (m = 0; m < 3; m++) {
            render_fb fb;
            long over;
            stress_render(sc, stress_mode(m), 256, &fb, &st);
            over = tt_image_over(&fb.img, &ref.img, 8);
            printf("# %s %s: %ld of %d pixels over 8/255 against f64 (%.3f%%), %llu overflows, "
                   "%llu cut\n", decks[d], stress_mode(m)->name, over, 256 * 256,
                   100.0 * over / (256 * 256), st.fx_overflows, st.range_cut);
            assert_true(over * 1000 <= 3 * 256 * 256);
            assert_int_equal(st.fx_overflows, 0);
            assert_int_equal(st.range_cut, 0);
            render_fb_free(&fb);
        }
        render_fb_free(&ref);
        scene_free(sc);
    }
}

/* A floor 1,000 units below a 3-unit scene: q32, f32 and f64 draw it to
 * the horizon (no ray cut); q16 reaches 375 scene widths and counts what
 * lies beyond (the renderer warns); no mode overflows. A floor 20,000
 * below is refused by q16 with the limit named. */
static void test_stress_deep_floor(void **state)
{
    scene *sc = tt_load("tests/decks/deep-floor.scene");
    render_fb fb;
    render_stats st;
    void *cs;
    diag err;
    char buf[512];
    int m;
    size_t i;
    assert_non_null(sc);
    (void)state;
    for (m = 0; m < 4; m++) {
        stress_render(sc, stress_mode(m), 64, &fb, &st);
        printf("# deep floor %s: %llu overflows, %llu of %d primary rays beyond the range\n",
               stress_mode(m)->name, st.fx_overflows, st.range_cut, 64 * 64);
        assert_int_equal(st.fx_overflows, 0);
        if (m == 0)
            assert_true(st.range_cut > 0);
        else
            assert_int_equal(st.range_cut, 0);
        render_fb_free(&fb);
    }
    for (i = 0; i < sc->nprims; i++)
        if (sc->prims[i].shape->kind == PRIM_HALFSPACE)
            sc->prims[i].world_from_object[11] = -20000;
    diag_init(&err);
    assert_int_equal(q16_probe_ops.compile(sc, &cs, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    printf("# %s\n", buf);
    assert_non_null(strstr(buf, "deep-floor.scene:15:1: error: primitive 'GROUND'"));
    assert_non_null(strstr(buf, "beyond the q16 range of 375"));
    for (m = 1; m < 4; m++) {
        stress_render(sc, stress_mode(m), 32, &fb, &st);
        assert_int_equal(st.fx_overflows, 0);
        render_fb_free(&fb);
    }
    scene_free(sc);
}

/* A coin of aspect 5e4: q16 refuses it before rendering, located, with its
 * limit; the other modes render it without an overflow. */
static void test_stress_thin_disc_refused_in_q16(void **state)
{
    scene *sc = tt_load("tests/decks/thin-disc.scene");
    void *cs;
    diag err;
    char buf[512];
    int m;
    assert_non_null(sc);
    (void)state;
    diag_init(&err);
    assert_int_equal(q16_probe_ops.compile(sc, &cs, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    printf("# %s\n", buf);
    assert_non_null(strstr(buf, "thin-disc.scene:9:1: error: primitive 'COIN': aspect ratio 5e+04"));
    assert_non_null(strstr(buf, "q16 limit of 10000"));
    for (m = 1; m < 4; m++) {
        render_fb fb;
        render_stats st;
        stress_render(sc, stress_mode(m), 64, &fb, &st);
        assert_int_equal(st.fx_overflows, 0);
        render_fb_free(&fb);
    }
    scene_free(sc);
}

/* The aspect limit at its edge (q16 1e4, q32 1e8): a stretched cylinder or
 * a turned, squashed sphere 1e-6 under the limit compiles, 1e-6 over it is
 * refused with the ratio named; a sphere of aspect 0.9 of the limit, whose
 * Frobenius bound (1.27 of it) does not clear it, compiles. (Two SCALE
 * items each: a deck number stays within 1e6.) */
static void test_stress_aspect_limit_edge(void **state)
{
    static const struct { const probe_ops *ops; double limit; const char *ratio; } mode[2] = {
        {&q16_probe_ops, 1e4, "aspect ratio 1e+04 is beyond the q16 limit of 10000"},
        {&q32_probe_ops, 1e8, "aspect ratio 1e+08 is beyond the q32 limit of 1e+08"}};
    static const double over[5] = {1 - 1e-6, 1 + 1e-6, 1 - 1e-6, 1 + 1e-6, 0.9};
    int m, k;
    (void)state;
    for (m = 0; m < 2; m++)
        for (k = 0; k < 5; k++) {
            char deck[512], buf[512];
            double a = mode[m].limit * over[k];
            scene *sc;
            void *cs = NULL;
            diag err;
            int st;
            if (k < 2)
                snprintf(deck, sizeof deck, "EYE 3 -4 3\nLOOKAT 0 0 0\nLIGHT 6 -4 9\n"
                         "CYLINDER C 1 1 SCALE 1 1 %.10g SCALE 1 1 %.10g\nOBJECT C\n", sqrt(a), sqrt(a));
            else
                snprintf(deck, sizeof deck, "EYE 3 -4 3\nLOOKAT 0 0 0\nLIGHT 6 -4 9\n"
                         "SPHERE S 1 SCALE 1 1 %.10g SCALE 1 1 %.10g -\n ROTATE AXIS 1 2 3 37\nOBJECT S\n",
                         1 / sqrt(a), 1 / sqrt(a));
            sc = tt_parse(deck);
            assert_non_null(sc);
            diag_init(&err);
            st = mode[m].ops->compile(sc, &cs, &err);
            diag_format(&err, buf, sizeof buf);
            printf("# %s aspect %.7g: %s\n", mode[m].ops->name, a, st ? buf : "compiled");
            if (over[k] > 1) {
                assert_int_equal(st, DIAG_INPUT);
                assert_non_null(strstr(buf, mode[m].ratio));
            } else {
                assert_int_equal(st, 0);
                mode[m].ops->free(cs);
            }
            scene_free(sc);
        }
}

/* Every deck in scenes/ and the valid stress decks, in every mode: zero
 * fixed-point overflows (range cuts are counted, not overflows). */
static void test_stress_no_overflow_on_valid_decks(void **state)
{
    static const char *const decks[] = {
        "scenes/coincident.scene", "scenes/csg.scene", "scenes/fig1.scene", "scenes/foil.scene",
        "scenes/glass.scene", "scenes/granite.scene", "scenes/pds-bspline.scene",
        "scenes/pds-cells.scene", "scenes/pds-cpg.scene", "scenes/pds-pixel.scene",
        "scenes/pds-quadtree.scene", "scenes/pds-striptree.scene", "tests/decks/touching.scene",
        "tests/decks/far-eye.scene", "tests/decks/narrow-lens.scene", "tests/decks/deep-floor.scene",
        "tests/decks/coincident-turned.scene"};
    size_t d;
    int m;
    (void)state;
    for (d = 0; d < sizeof decks / sizeof decks[0]; d++) {
        scene *sc = tt_load(decks[d]);
        assert_non_null(sc);
        for (m = 0; m < 4; m++) {
            render_fb fb;
            render_stats st;
            stress_render(sc, stress_mode(m), 48, &fb, &st);
            if (st.fx_overflows)
                printf("# %s %s: %llu overflows\n", decks[d], stress_mode(m)->name, st.fx_overflows);
            assert_int_equal(st.fx_overflows, 0);
            render_fb_free(&fb);
        }
        scene_free(sc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stress_touching_objects_keep_contact_faces),
        cmocka_unit_test(test_stress_far_eye_and_narrow_lens),
        cmocka_unit_test(test_stress_deep_floor),
        cmocka_unit_test(test_stress_thin_disc_refused_in_q16),
        cmocka_unit_test(test_stress_aspect_limit_edge),
        cmocka_unit_test(test_stress_no_overflow_on_valid_decks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
