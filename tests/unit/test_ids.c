/* test_ids — `render --ids` against the REAL(16) primary-ray oracle
 * (tests/oracle/ids_oracle.f90) on the shipped decks and the stress decks,
 * in every numeric mode: pixels whose primitive, face or region differs
 * from the oracle's (the oracle's ambiguous pixels not counted), and the
 * hit distance error; the identity map file round trip and its errors. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdlib.h>
#include <unistd.h>
#include "tracer_test.h"
#include "cli/cli_idcheck.h"
#include "util/outfile.h"

static char ids_oracle_path[1024];


static const render_ops *ids_mode(int m)
{
    static const render_ops *const all[4] = {&q16_render_ops, &q32_render_ops, &f32_render_ops,
                                             &f64_render_ops};
    return all[m];
}

/* Mismatch rate limits per mode (fraction of compared pixels). */
static void test_ids_against_oracle(void **state)
{
    static const char *const decks[] = {"scenes/fig1.scene", "scenes/csg.scene", "scenes/coincident.scene",
                                        "scenes/glass.scene", "tests/decks/touching.scene",
                                        "tests/decks/far-eye.scene", "tests/decks/narrow-lens.scene",
                                        "tests/decks/coincident-turned.scene"};
    const int W = 128;
    size_t d;
    int m;
    (void)state;
    if (access(ids_oracle_path, X_OK) != 0) {
        printf("# oracle not found at %s (build it with make test)\n", ids_oracle_path);
        fail();
    }
    for (d = 0; d < sizeof decks / sizeof decks[0]; d++) {
        scene *sc = tt_load(decks[d]);
        idmap orc;
        diag err;
        assert_non_null(sc);
        diag_init(&err);
        if (cli_idcheck_oracle(ids_oracle_path, sc, W, W, &orc, &err))
            diag_print(stderr, &err);
        assert_int_equal(err.status, 0);
        for (m = 0; m < 4; m++) {
            render_opts o = tt_render_opts(W, W, 2);
            render_fb fb;
            render_stats st;
            cli_idcheck_stats cs;
            o.ids = 1;
            assert_int_equal(render_scene(sc, ids_mode(m), &o, &fb, &st, &err), 0);
            cli_idcheck_compare(&fb.ids, &orc, &cs);
            printf("# %s %s: %ld of %ld pixels differ (%ld flagged), hit error median %.3g max %.3g\n",
                   decks[d], ids_mode(m)->name, cs.mismatches, cs.compared, cs.flagged, cs.err_median,
                   cs.err_max);
            assert_true(cs.compared > W * W / 2);
            assert_true(cs.mismatches * 1000 <= cs.compared);
            render_fb_free(&fb);
        }
        idmap_free(&orc);
        scene_free(sc);
    }
}

/* The file round trip, and located errors for bad files. */
static void test_ids_file_round_trip_and_errors(void **state)
{
    char path[] = "/tmp/maprt-ids-test-XXXXXX", buf[512];
    idmap a, b;
    diag err;
    FILE *f;
    int fd, i;
    (void)state;
    diag_init(&err);
    assert_int_equal(idmap_alloc(&a, 5, 3, &err), 0);
    for (i = 0; i < 15; i++) {
        a.px[i].prim = i % 4 - 1;
        a.px[i].face = i % 3;
        a.px[i].region = 100000 + i;
        a.px[i].flags = i & 1;
        a.px[i].t = i ? 1.0 / i : -1;
    }
    fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    assert_int_equal(idmap_write(path, &a, &err), 0);
    assert_int_equal(idmap_read(path, &b, &err), 0);
    assert_int_equal(b.width, 5);
    assert_int_equal(b.height, 3);
    assert_memory_equal(a.px, b.px, 15 * sizeof *a.px);
    idmap_free(&b);
    f = fopen(path, "r+b");
    assert_non_null(f);
    assert_int_equal(ftruncate(fileno(f), 16 + 24 * 14), 0);
    fclose(f);
    assert_int_equal(idmap_read(path, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    printf("# %s\n", buf);
    assert_non_null(strstr(buf, "offset 352: error: identity map of 5x3 pixels needs 376 bytes"));
    f = fopen(path, "wb");
    assert_non_null(f);
    fputs("P6 5 3 255\n", f);
    fclose(f);
    diag_init(&err);
    assert_int_equal(idmap_read(path, &b, &err), DIAG_INPUT);
    diag_format(&err, buf, sizeof buf);
    assert_non_null(strstr(buf, "offset 0: error: not an identity map"));
    idmap_free(&a);
    remove(path);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ids_against_oracle),
        cmocka_unit_test(test_ids_file_round_trip_and_errors),
    };
    const char *slash = argc > 0 ? strrchr(argv[0], '/') : NULL;
    int dirlen = slash ? (int)(slash - argv[0]) : 0;
    snprintf(ids_oracle_path, sizeof ids_oracle_path, "%.*s/../oracle/ids_oracle", dirlen,
             slash ? argv[0] : ".");
    return cmocka_run_group_tests(tests, NULL, NULL);
}
