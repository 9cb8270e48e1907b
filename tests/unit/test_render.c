/* test_render — the render driver and Algorithm 1 end to end: golden
 * images, ray counts, thread-count independence, scale independence of the
 * normalised scene, mode lookup and an allocation-failure sweep. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include "image/image_png.h"
#include "tracer_test.h"
#include "util/mem.h"
#include "util/outfile.h"

static scene *render_load(const char *path)
{
    size_t len;
    char *text = test_read_file(path, &len), *z;
    scene *sc;
    assert_non_null(text);
    z = mem_alloc(len + 1);
    assert_non_null(z);
    memcpy(z, text, len);
    z[len] = 0;
    mem_free(text);
    sc = tt_parse(z);
    mem_free(z);
    assert_non_null(sc);
    return sc;
}

static void test_render_goldens(void **state)
{
    static const char *const scenes[] = {"fig1", "csg", "coincident"};
    static const char *const modes[] = {"q16", "f64"};
    size_t s, m;
    (void)state;
    for (s = 0; s < 3; s++)
        for (m = 0; m < 2; m++) {
            char path[256];
            scene *sc;
            image gold;
            render_fb fb;
            render_stats st;
            render_opts o = tt_render_opts(128, 128, 1);
            diag err;
            long bad;
            snprintf(path, sizeof path, "scenes/%s.scene", scenes[s]);
            sc = render_load(path);
            diag_init(&err);
            snprintf(path, sizeof path, "tests/golden/%s-%s.png", scenes[s], modes[m]);
            assert_int_equal(image_read_png(path, 3, &gold, &err), 0);
            assert_int_equal(render_scene(sc, render_ops_find(modes[m], RENDER_ISA_AUTO), &o, &fb, &st, &err), 0);
            bad = tt_image_over(&fb.img, &gold, 2);
            printf("# %s: %ld of %d pixels differ by more than 2/255\n", path, bad, 128 * 128);
            assert_true(bad <= 128 * 128 / 200);
            image_free(&gold);
            render_fb_free(&fb);
            scene_free(sc);
        }
}

/* An attribute with neither diffuse nor specular term casts no shadow rays
 * (counted in shadow_skipped) and shows exactly its ambient colour; faces
 * without PDS, texture or bump skip (u,v). The lit floor still casts them. */
static void test_render_unlit_attribute_skips_shadow_rays(void **state)
{
    static const char deck[] =
        "EYE 0 -6 2\nLOOKAT 0 0 0.5\nUP 0 0 1\nFOV 40\nAMBIENT 0.4 0.4 0.4\n"
        "LIGHT 3 -4 6\nLIGHT -3 -4 6\n"
        "ATTR GLOW COLOR 0.5 0.25 1 DIFFUSE 0 SPECULAR 0\nATTR FLOOR COLOR 0.6 0.6 0.6\n"
        "SPHERE BALL 1 ATTR GLOW TRANSLATE 0 0 1\nHALFSPACE GROUND ATTR FLOOR\n"
        "OBJECT BALL\nOBJECT GROUND\n";
    const char *modes[] = {"q16", "f64"};
    int m;
    (void)state;
    for (m = 0; m < 2; m++) {
        scene *sc = tt_parse(deck);
        render_fb fb;
        render_stats st;
        render_opts o = tt_render_opts(64, 48, 1);
        diag err;
        long ball = 0, hits = 0, i;
        assert_non_null(sc);
        diag_init(&err);
        assert_int_equal(render_scene(sc, render_ops_find(modes[m], RENDER_ISA_AUTO), &o, &fb, &st, &err), 0);
        for (i = 0; i < 64 * 48; i++) {
            hits += fb.pid[i] >= 0;
            if (fb.pid[i] == 0) {
                const unsigned char *px = fb.img.px + 3 * i;
                ball++;
                assert_true(px[0] == 51 && px[1] == 26 && px[2] == 102);
            }
        }
        printf("# %s: %ld sphere pixels, %llu shadow rays skipped, %llu traced, %llu (u,v) skipped\n",
               modes[m], ball, st.shadow_skipped, st.rays_shadow, st.uv_skipped);
        assert_true(ball > 100);
        assert_true(st.shadow_skipped == 2ull * (unsigned long long)ball);
        assert_true(st.rays_shadow > 0);
        assert_true(st.uv_skipped == (unsigned long long)hits);   /* no face needs (u,v) */
        render_fb_free(&fb);
        scene_free(sc);
    }
}

/* fig1 at 3x3 samples on one thread and two: the same counts, picture and
 * PIDs; and with render_opts.skip_pid, no PIDs and the same picture. */
static void test_render_counts_and_threads(void **state)
{
    scene *sc = render_load("scenes/fig1.scene");
    render_fb a, b;
    render_stats sa, sb;
    render_opts o = tt_render_opts(70, 50, 1);
    diag err;
    int i;
    (void)state;
    diag_init(&err);
    o.aa = 3;
    assert_int_equal(render_scene(sc, &q16_render_ops, &o, &a, &sa, &err), 0);
    o.threads = 2;
    assert_int_equal(render_scene(sc, &q16_render_ops, &o, &b, &sb, &err), 0);
    assert_true(sa.rays_primary == 70ull * 50 * 9);
    assert_true(sa.rays_shadow > 0 && sa.rays_reflected > 0);
    assert_true(sa.rays_shadow == sb.rays_shadow && sa.rays_reflected == sb.rays_reflected);
    assert_true(sa.fx_overflows == 0);
    assert_int_equal(tt_image_over(&a.img, &b.img, 0), 0);
    for (i = 0; i < 70 * 50; i++) {
        assert_int_equal(a.pid[i], b.pid[i]);
        assert_true(a.pid[i] >= -1 && a.pid[i] < (int)sc->nprims);
    }
    render_fb_free(&b);
    /* without PIDs: none allocated, the same picture and counts */
    o.skip_pid = 1;
    assert_int_equal(render_scene(sc, &q16_render_ops, &o, &b, &sb, &err), 0);
    assert_null(b.pid);
    assert_int_equal(tt_image_over(&a.img, &b.img, 0), 0);
    assert_true(sa.rays_shadow == sb.rays_shadow && sa.rays_reflected == sb.rays_reflected);
    render_fb_free(&a);
    render_fb_free(&b);
    scene_free(sc);
}

/* The gold mirror disc on fig1's top faces up, so it can only mirror what
 * stands above the can behind it (docs/fig1.md): the green ball. A disc
 * pixel whose colour does not change when the background does sees an
 * object; the ball's edge crosses the disc, so some pixels must see it and
 * some the background. Measured at 256x256: 210 of 360 see the ball. */
static void test_render_fig1_gold_disc_mirrors_the_ball(void **state)
{
    scene *sc = render_load("scenes/fig1.scene");
    render_fb a, b;
    render_stats st;
    render_opts o = tt_render_opts(256, 256, 2);
    diag err;
    int i, gold = -1, disc = 0, sees = 0;
    size_t k;
    (void)state;
    diag_init(&err);
    for (k = 0; k < sc->nattrs; k++)
        if (strcmp(sc->attrs[k].name, "DOTGOLD") == 0)
            gold = (int)k;
    assert_true(gold >= 0);
    o.ids = 1;
    assert_int_equal(render_scene(sc, &f64_render_ops, &o, &a, &st, &err), 0);
    sc->background[0] = 0.9;
    sc->background[1] = 0.1;
    sc->background[2] = 0.9;
    o.ids = 0;
    assert_int_equal(render_scene(sc, &f64_render_ops, &o, &b, &st, &err), 0);
    for (i = 0; i < 256 * 256; i++) {
        int c, moved = 0;
        if (a.ids.px[i].region != gold)
            continue;
        disc++;
        for (c = 0; c < 3; c++)
            if (abs((int)a.img.px[3 * i + c] - (int)b.img.px[3 * i + c]) > 2)
                moved = 1;
        sees += !moved;
    }
    printf("# fig1 gold disc: %d pixels, %d see an object\n", disc, sees);
    assert_true(disc > 200);
    assert_true(sees >= disc / 3 && sees <= disc * 9 / 10);
    render_fb_free(&a);
    render_fb_free(&b);
    scene_free(sc);
}

/* Scales every position of the scene model by f (a scene built in C). */
static void render_scale_scene(scene *sc, double f)
{
    size_t i;
    int k;
    for (i = 0; i < sc->nprims; i++)
        for (k = 0; k < 12; k++)
            sc->prims[i].world_from_object[k] *= f;
    for (k = 0; k < 3; k++) {
        sc->view.eye[k] *= f;
        sc->view.look[k] *= f;
    }
    for (i = 0; i < sc->nlights; i++)
        for (k = 0; k < 3; k++)
            sc->lights[i].pos[k] *= f;
}

/* Uniform scales 1e-4 .. 1e6 of the whole scene change at most 0.1% of the
 * pixels by more than 8/255 (anchor target; no absolute epsilons). */
static void test_render_scale_independent(void **state)
{
    static const double scales[] = {1e-4, 1e-2, 1e3, 1e6};
    const render_ops *modes[2] = {&q16_render_ops, &f64_render_ops};
    size_t i, m;
    (void)state;
    for (m = 0; m < 2; m++) {
        scene *sc = render_load("scenes/csg.scene");
        render_fb ref;
        render_stats st;
        render_opts o = tt_render_opts(96, 96, 1);
        diag err;
        diag_init(&err);
        assert_int_equal(render_scene(sc, modes[m], &o, &ref, &st, &err), 0);
        scene_free(sc);
        for (i = 0; i < sizeof scales / sizeof scales[0]; i++) {
            render_fb fb;
            long bad;
            sc = render_load("scenes/csg.scene");
            render_scale_scene(sc, scales[i]);
            assert_int_equal(render_scene(sc, modes[m], &o, &fb, &st, &err), 0);
            bad = tt_image_over(&fb.img, &ref.img, 8);
            printf("# %s scale %g: %ld pixels differ by more than 8/255\n", modes[m]->name, scales[i], bad);
            assert_true(bad <= 96 * 96 / 1000);
            render_fb_free(&fb);
            scene_free(sc);
        }
        render_fb_free(&ref);
    }
}

/* Refraction and mirror recursion: q16 and f64 agree on a glass scene. */
static void test_render_glass_modes_agree(void **state)
{
    scene *sc = render_load("bench/glass.scene");
    render_fb a, b;
    render_stats sa, sb;
    render_opts o = tt_render_opts(96, 72, 1);
    diag err;
    long bad;
    (void)state;
    diag_init(&err);
    assert_int_equal(render_scene(sc, &q16_render_ops, &o, &a, &sa, &err), 0);
    assert_int_equal(render_scene(sc, &f64_render_ops, &o, &b, &sb, &err), 0);
    bad = tt_image_over(&a.img, &b.img, 8);
    printf("# glass: %llu refracted, %llu reflected rays; %ld pixels differ by more than 8/255\n",
           sa.rays_refracted, sa.rays_reflected, bad);
    assert_true(sa.rays_refracted > 1000 && sb.rays_refracted > 1000);
    assert_true(bad <= 96 * 72 / 100);
    assert_true(sa.fx_overflows == 0);
    render_fb_free(&a);
    render_fb_free(&b);
    scene_free(sc);
}

static void test_render_mode_lookup(void **state)
{
    const char *names[] = {"q16", "q32", "f32", "f64", "hfp32", "hfp64"};
    size_t k;
    (void)state;
    assert_ptr_equal(render_ops_find("q16", RENDER_ISA_BASELINE), &q16_render_ops);
    assert_ptr_equal(render_ops_find("F64", RENDER_ISA_BASELINE), &f64_render_ops);
    for (k = 0; k < sizeof names / sizeof names[0]; k++) {
        const render_ops *b = render_ops_find(names[k], RENDER_ISA_BASELINE);
        const render_ops *a = render_ops_find(names[k], RENDER_ISA_AUTO);
        assert_string_equal(b->name, names[k]);
        assert_string_equal(a->name, names[k]);
        assert_string_equal(b->isa, "baseline");
        /* auto: the baseline, or a build of its own for x86-64-v3 */
        if (strcmp(a->isa, "baseline")) {
            assert_string_equal(a->isa, "x86-64-v3");
            assert_ptr_not_equal(a, b);
        } else {
            assert_ptr_equal(a, b);
        }
    }
    assert_null(render_ops_find("f16", RENDER_ISA_AUTO));
    assert_null(render_ops_find(NULL, RENDER_ISA_AUTO));
}

static void test_render_bad_view(void **state)
{
    scene *sc = render_load("scenes/fig1.scene");
    render_fb fb;
    render_stats st;
    render_opts o = tt_render_opts(8, 8, 1);
    diag err;
    char buf[256];
    (void)state;
    memcpy(sc->view.look, sc->view.eye, sizeof sc->view.eye);
    diag_init(&err);
    assert_int_equal(render_scene(sc, &f32_render_ops, &o, &fb, &st, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_string_equal(buf, "test.scene: error: view: eye and look coincide");
    scene_free(sc);
}

/* Fails each allocation of compile and render setup in turn: each must end
 * in a clean DIAG_IO (leaks show under make asan-test). Two objects, and
 * 82 (csg81: twins, light buffers and their shared scratch). */
static void test_render_oom_sweep(void **state)
{
    static const char *const decks[2] = {"scenes/csg.scene", "bench/peers/csg81.scene"};
    int i;
    (void)state;
    for (i = 0; i < 2; i++) {
        scene *sc = render_load(decks[i]);
        render_opts o = tt_render_opts(40, 30, 2);
        long n;
        for (n = 0; n < 1000; n++) {
            render_fb fb;
            render_stats st;
            diag err;
            int rc;
            diag_init(&err);
            mem_fail_after(n);
            rc = render_scene(sc, &q16_render_ops, &o, &fb, &st, &err);
            mem_fail_after(-1);
            if (rc == 0) {
                render_fb_free(&fb);
                break;
            }
            assert_int_equal(rc, DIAG_IO);
        }
        printf("# render setup of %s: %ld allocations failed in turn\n", decks[i], n);
        assert_true(n > 5 && n < 1000);
        scene_free(sc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_render_goldens),
        cmocka_unit_test(test_render_counts_and_threads),
        cmocka_unit_test(test_render_fig1_gold_disc_mirrors_the_ball),
        cmocka_unit_test(test_render_unlit_attribute_skips_shadow_rays),
        cmocka_unit_test(test_render_scale_independent),
        cmocka_unit_test(test_render_glass_modes_agree),
        cmocka_unit_test(test_render_mode_lookup),
        cmocka_unit_test(test_render_bad_view),
        cmocka_unit_test(test_render_oom_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
